"""rpg eval on real library tasks: built-in, plug-in and remote (openpi websocket) policies,
summary statistics, determinism over job counts, resuming after kill -9, comparison of runs,
and the evaluation page in headless Chromium."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import msgpack
import numpy as np
import pytest
from conftest import CHROMIUM_FLAGS

from rpg.eval import EvalConfig, run_eval, wilson_interval
from rpg.eval.openpi import openpi_observation, packb, unpackb
from rpg.eval.runner import eval_tasks
from rpg.eval.stats import fisher_exact, holm, mcnemar_exact
from tests.helpers import alive

ROOT = Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "library"
FLOAT = "floating_gripper"


def _rpg(*args, cwd=ROOT, timeout=600):
    env = {**os.environ, "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl"), "LITELLM_LOCAL_MODEL_COST_MAP": "True"}
    return subprocess.run([sys.executable, "-m", "rpg.cli", *args], capture_output=True, text=True, env=env,
                          cwd=cwd, timeout=timeout)


def _lines(path: Path) -> list[dict]:
    return [json.loads(x) for x in path.read_text().splitlines() if x.strip()]


def test_wilson_interval_and_exact_tests_match_published_values():
    # Wilson score intervals at 95% (Newcombe 1998, Table I: 0/10 -> 0-0.2775, 81/263 -> 0.2553-0.3662)
    lo, hi = wilson_interval(0, 10)
    assert lo == 0.0 and hi == pytest.approx(0.2775, abs=1e-4)
    lo, hi = wilson_interval(81, 263)
    assert (lo, hi) == (pytest.approx(0.2553, abs=1e-4), pytest.approx(0.3662, abs=1e-4))
    assert fisher_exact(3, 3, 0, 3) == pytest.approx(0.1)  # 2 / C(6, 3), two-sided
    assert fisher_exact(3, 5, 3, 5) == 1.0
    assert mcnemar_exact(5, 0) == pytest.approx(0.0625)  # 2 * 0.5^5
    assert mcnemar_exact(0, 0) == 1.0
    assert holm([0.01, 0.04, 0.03]) == pytest.approx([0.03, 0.06, 0.06])


def _without_timing(path: Path) -> dict:
    doc = json.loads(path.read_text())
    doc.pop("timing")
    return doc


def test_oracle_is_the_upper_bound_noop_scores_zero_and_seeds_give_distinct_initial_states(tmp_path):
    runs = {}
    for policy in ("oracle", "noop", "random"):  # (random runs every episode to the horizon: one seed is enough to bound)
        seeds = (0,) if policy == "random" else tuple(range(2))
        runs[policy] = run_eval(EvalConfig("split=train", policy, seeds, embodiment=FLOAT,
                                           library=str(LIBRARY / "manifest.yaml")), tmp_path / policy)
    tasks = runs["oracle"]["tasks"]
    assert len(tasks) == 10 and set(runs["oracle"]["splits"]) == {"train"}
    assert runs["noop"]["overall"]["successes"] == 0
    assert runs["oracle"]["overall"]["mean"] >= 0.9
    for name in tasks:
        assert runs["oracle"]["tasks"][name]["mean"] >= runs["random"]["tasks"][name]["mean"]
        r = runs["oracle"]["tasks"][name]
        assert r["n"] == 2 and r["wilson95"][0] <= r["mean"] <= r["wilson95"][1]
        assert r["stderr"] == pytest.approx((r["mean"] * (1 - r["mean"]) / 2) ** 0.5, abs=1e-6)
    eps = _lines(tmp_path / "noop" / "episodes.jsonl")
    assert len(eps) == 20
    for name in tasks:  # every seed starts from its own sample of rho_0
        starts = [e["initial_state"] for e in eps if e["task"] == name]
        assert len(set(starts)) == 2, name
    failed = [e for e in eps if not e["success"]]
    assert all(e["unsatisfied"] for e in failed)  # failed predicates are recorded
    assert all(e["instruction"] for e in eps)  # the exact prompt is recorded


def test_summary_is_byte_identical_for_one_and_two_jobs_and_groups_family_versions_by_intent(tmp_path):
    # a family of five versions (base, three extensions, a modification) whose oracle episodes are short
    fam = "evolution_revert_and_extend"
    a = _rpg("eval", f"library/{fam}", "--policy", "oracle", "-n", "2", "--embodiment", FLOAT,
             "-o", str(tmp_path / "a"))
    b = _rpg("eval", f"library/{fam}", "--policy", "oracle", "-n", "2", "--embodiment", FLOAT,
             "-o", str(tmp_path / "b"), "--jobs", "2")
    assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
    assert _without_timing(tmp_path / "a" / "summary.json") == _without_timing(tmp_path / "b" / "summary.json")
    s = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert set(s["tasks"]) == {f"{fam}@v{k}" for k in range(5)}
    assert set(s["intents"]) == {"base", "extend", "modify"}
    assert (s["intents"]["base"]["n"], s["intents"]["extend"]["n"], s["intents"]["modify"]["n"]) == (2, 6, 2)
    assert s["families"][fam]["n"] == 10


def test_a_killed_run_resumes_keeping_finished_episodes(tmp_path):
    run = tmp_path / "run"
    args = [sys.executable, "-m", "rpg.cli", "eval", "library/three_block_stack", "--policy", "oracle",
            "-n", "10", "--embodiment", FLOAT, "-o", str(run)]
    proc = subprocess.Popen(args, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env={**os.environ, "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl")})
    log = run / "episodes.jsonl"
    deadline = time.time() + 120
    while time.time() < deadline and (not log.is_file() or len(log.read_text().splitlines()) < 3):
        time.sleep(0.05)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    kept = log.read_text().splitlines()
    assert 3 <= len(kept) < 10
    with open(log, "a") as fh:  # a line torn by the kill
        fh.write('{"task": "three_block_stack", "seed": 9')
    r = _rpg("eval", "library/three_block_stack", "--policy", "oracle", "-n", "10", "--embodiment", FLOAT, "-o", str(run))
    assert r.returncode == 0, r.stderr
    lines = log.read_text().splitlines()
    assert lines[:len(kept)] == kept and len(lines) == 10
    assert sorted(json.loads(x)["seed"] for x in lines) == list(range(10))
    fresh = _rpg("eval", "library/three_block_stack", "--policy", "oracle", "-n", "10", "--embodiment", FLOAT,
                 "-o", str(tmp_path / "fresh"))
    assert fresh.returncode == 0
    assert _without_timing(run / "summary.json") == _without_timing(tmp_path / "fresh" / "summary.json")
    # the same directory with other settings is refused, not mixed
    r = _rpg("eval", "library/three_block_stack", "--policy", "noop", "-n", "10", "--embodiment", FLOAT, "-o", str(run))
    assert r.returncode == 2 and "other settings (policy)" in r.stderr


def test_a_second_writer_of_the_same_run_is_refused(tmp_path):
    from filelock import FileLock

    run = tmp_path / "run"
    run.mkdir()
    with FileLock(str(run / ".rpg-eval.lock")):  # as a running rpg eval holds it
        r = _rpg("eval", "library/stack_blocks", "--policy", "noop", "-n", "2", "--embodiment", FLOAT, "-o", str(run))
    assert r.returncode == 2 and "another rpg eval is writing" in r.stderr
    assert not (run / "episodes.jsonl").exists()
    r = _rpg("eval", "library/stack_blocks", "--policy", "noop", "-n", "2", "--embodiment", FLOAT, "-o", str(run))
    assert r.returncode == 0, r.stderr  # the lock file alone does not make the directory foreign
    assert len(_lines(run / "episodes.jsonl")) == 2


def test_packed_bytes_follow_openpi_msgpack_numpy():
    """openpi-client's msgpack_numpy packs an array as the map {__ndarray__, data, dtype, shape}
    with bytes keys and a numpy scalar as {__npgeneric__, data, dtype}; the bytes must be the
    same as packing that map by hand with plain msgpack."""
    img = np.arange(12, dtype=np.uint8).reshape(2, 2, 3)
    state = np.array([0.5, -0.25], dtype=np.float64)
    ours = packb({"observation/image": img, "observation/state": state, "prompt": "stack", "k": np.float32(1.5)})
    by_hand = msgpack.packb({
        "observation/image": {b"__ndarray__": True, b"data": img.tobytes(), b"dtype": "|u1", b"shape": (2, 2, 3)},
        "observation/state": {b"__ndarray__": True, b"data": state.tobytes(), b"dtype": "<f8", b"shape": (2,)},
        "prompt": "stack",
        "k": {b"__npgeneric__": True, b"data": 1.5, b"dtype": "<f4"}})
    assert ours == by_hand
    back = unpackb(ours)
    assert np.array_equal(back["observation/image"], img) and back["observation/image"].dtype == np.uint8
    assert back["k"] == np.float32(1.5)
    mapped = openpi_observation({"agentview_image": img, "wrist_image": img, "state": state, "instruction": "x",
                                 "qpos": state})
    assert set(mapped) == {"observation/image", "observation/wrist_image", "observation/state", "prompt"}


def _serve_openpi(policy):
    """An openpi-protocol server for ``policy`` on a free local port (metadata first, then one
    action chunk per observation); returns (url, server)."""
    from websockets.sync.server import serve

    def handler(ws):
        ws.send(packb({"policy": "scripted", "action_dim": 7}))
        for message in ws:
            obs = unpackb(message)
            ours = {"state": obs["observation/state"], "agentview_image": obs["observation/image"]}
            ws.send(packb({"actions": policy.act(ours)}))

    server = serve(handler, "127.0.0.1", 0, compression=None, max_size=None)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return f"ws://127.0.0.1:{server.socket.getsockname()[1]}", server


def test_a_websocket_policy_gives_the_same_results_as_the_same_policy_in_process(tmp_path):
    sys.path.insert(0, str(ROOT / "tests"))
    from eval_policies import Scripted

    url, server = _serve_openpi(Scripted())
    try:
        common = dict(target=str(LIBRARY / "stack_blocks"), seeds=(0, 1), embodiment=FLOAT, replan=2,
                      image_size=(32, 32))
        remote = run_eval(EvalConfig(policy=url, **common), tmp_path / "remote")
        local = run_eval(EvalConfig(policy=str(ROOT / "tests" / "eval_policies.py") + ":Scripted", **common),
                         tmp_path / "local")
    finally:
        server.shutdown()
    keys = ("seed", "success", "steps", "initial_state", "final_state", "unsatisfied", "instruction")
    r = [{k: e[k] for k in keys} for e in _lines(tmp_path / "remote" / "episodes.jsonl")]
    l_ = [{k: e[k] for k in keys} for e in _lines(tmp_path / "local" / "episodes.jsonl")]
    assert r == l_
    assert any(e["final_state"] != e["initial_state"] for e in r) or all(e["steps"] > 1 for e in r)
    assert remote["tasks"] == local["tasks"]


def test_bad_input_is_one_line_and_writes_nothing(tmp_path):
    out = tmp_path / "run"
    for args, msg in (
        (["library/stack_blocks", "--policy", "nosuch:Policy"], "cannot be imported"),
        (["library/stack_blocks", "--policy", "gpt"], "unknown policy"),
        (["library/stack_blocks", "-n", "3", "--seeds", "1,2"], "not both"),
        (["library/stack_blocks", "--seeds", "1,x"], "--seeds takes"),
        (["library/nope"], "no task at"),
        (["reasoning=nonsense", "--library", str(LIBRARY / "manifest.yaml")], "selects no task"),
        (["library/stack_blocks", "--instruction", "paraphrase"], "--instruction must be"),
        (["library/stack_blocks", "--policy", "ws://127.0.0.1:9"], "cannot reach the policy server"),
        (["library/stack_blocks", "--visual", "fine"], "--visual must be one of decimated, stock"),
    ):
        r = _rpg("eval", *args, "-o", str(out))
        assert r.returncode == 2, (args, r.stderr)
        assert msg in r.stderr and "Traceback" not in r.stderr, (args, r.stderr)
        assert not out.exists(), args
    r = _rpg("eval", "compare", str(tmp_path))
    assert r.returncode == 2 and "two run directories" in r.stderr


def test_targets_tag_filters_and_splits():
    manifest = LIBRARY / "manifest.yaml"
    semantic = eval_tasks("reasoning=semantic", manifest)
    assert semantic and all(t.name in {"arrange_letters", "arrange_word", "arrange_numbers", "arrange_equation",
                                       "arrange_shapes", "rotate_cube", "semantic_spelling"} or t.family
                            for t in semantic)
    assert {t.name for t in eval_tasks("split=eval", manifest)} >= {"stack_green_on_blue", "yellow_on_red_unstack_restack"}
    assert len(eval_tasks("split=eval", manifest)) == 12
    one = eval_tasks(str(LIBRARY / "pile_sorting") + "@v1", manifest)
    assert [(t.family, t.version, t.intent) for t in one] == [("pile_sorting", 1, "modify")]


def test_compare_calls_a_large_difference_real(tmp_path):
    for policy in ("oracle", "noop"):
        run_eval(EvalConfig(str(LIBRARY / "stack_blocks"), policy, tuple(range(8)), embodiment=FLOAT), tmp_path / policy)
    r = _rpg("eval", "compare", str(tmp_path / "oracle"), str(tmp_path / "noop"), "--json")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    (row,) = doc["rows"]
    assert row["task"] == "stack_blocks" and row["diff"] == -1.0 and row["significant"]
    assert row["test"] == "mcnemar_exact" and row["p_value"] == pytest.approx(2 * 0.5**8, abs=1e-6)  # same seeds: paired
    assert doc["same_seeds"] and doc["correction"] == "holm" and row["progress_diff"] < 0


def test_compare_on_other_seeds_is_fisher_and_other_settings_are_refused(tmp_path):
    run_eval(EvalConfig(str(LIBRARY / "stack_blocks"), "oracle", (5, 6, 7), embodiment=FLOAT), tmp_path / "a")
    run_eval(EvalConfig(str(LIBRARY / "stack_blocks"), "noop", (0, 1, 2), embodiment=FLOAT), tmp_path / "b")
    r = _rpg("eval", "compare", str(tmp_path / "a"), str(tmp_path / "b"), "--json")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    (row,) = doc["rows"]
    assert row["test"] == "fisher_exact" and row["p_value"] == pytest.approx(0.1) and not row["significant"]
    assert not doc["same_seeds"]
    text = _rpg("eval", "compare", str(tmp_path / "a"), str(tmp_path / "b"))
    assert "different seeds" in text.stdout and "Fisher" in text.stdout
    run_eval(EvalConfig(str(LIBRARY / "stack_blocks"), "noop", (5, 6, 7), embodiment="panda"), tmp_path / "panda")
    r = _rpg("eval", "compare", str(tmp_path / "a"), str(tmp_path / "panda"))
    assert r.returncode == 2 and "embodiment: 'floating_gripper' vs 'panda'" in r.stderr, r.stderr
    r = _rpg("eval", "compare", str(tmp_path / "a"), str(tmp_path / "panda"), "--allow-mismatch")
    assert r.returncode == 0 and "--allow-mismatch" in r.stdout


@pytest.mark.parametrize("backend", ["local"])
def test_visual_reaches_the_environments_of_either_backend(backend, tmp_path):
    """``rpg eval --visual stock`` on the process pool and on Ray: each episode's record reads
    the meshes back from the environment its worker built; run.json and the summary record the
    setting; a run of the default meshes is not compared with it unasked, and resuming the run
    with the other meshes is one line, exit 2."""
    if backend == "ray":
        pytest.importorskip("ray", reason="Ray is not installed: the ray backend cannot be tested")
    args = ["eval", "library/stack_blocks", "--policy", "oracle", "-n", "2", "--embodiment", FLOAT, "--cameras", "wrist",
            "--image-size", "32", "-j", "2", "--backend", backend]
    runs = {"stock": tmp_path / "stock", "decimated": tmp_path / "decimated"}
    for visual, run in runs.items():
        r = _rpg(*args, "--visual", visual, "-o", str(run))
        assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
        assert [e["visual"] for e in _lines(run / "episodes.jsonl")] == [visual, visual]
        assert json.loads((run / "run.json").read_text())["visual"] == visual
        assert json.loads((run / "summary.json").read_text())["config"]["visual"] == visual
    r = _rpg("eval", "compare", str(runs["stock"]), str(runs["decimated"]))
    assert r.returncode == 2 and "visual: 'stock' vs 'decimated'" in r.stderr, r.stderr
    r = _rpg(*args, "-o", str(runs["stock"]))  # the default meshes into the stock run
    assert r.returncode == 2 and "other settings (visual)" in r.stderr and len(r.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("backend", ["local"])
def test_wrist_supersample_reaches_the_environments_of_either_backend(backend, tmp_path):
    """``rpg eval --wrist-supersample 2`` on the process pool and on Ray: each episode's record
    reads the factor back from the environment its worker built; run.json and the summary
    record it; a run without it is not compared with it unasked, and resuming the run without
    it is one line, exit 2."""
    if backend == "ray":
        pytest.importorskip("ray", reason="Ray is not installed: the ray backend cannot be tested")
    args = ["eval", "library/stack_blocks", "--policy", "oracle", "-n", "1", "--embodiment", FLOAT, "--cameras", "wrist",
            "--image-size", "32", "--backend", backend]
    runs = {2: tmp_path / "x2", 1: tmp_path / "x1"}
    for k, run in runs.items():
        r = _rpg(*args, "--wrist-supersample", str(k), "-o", str(run))
        assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
        assert [e["wrist_supersample"] for e in _lines(run / "episodes.jsonl")] == [k]
        assert json.loads((run / "run.json").read_text())["wrist_supersample"] == k
        assert json.loads((run / "summary.json").read_text())["config"]["wrist_supersample"] == k
    r = _rpg("eval", "compare", str(runs[2]), str(runs[1]))
    assert r.returncode == 2 and "wrist_supersample: 2 vs 1" in r.stderr, r.stderr
    r = _rpg("eval", "compare", str(runs[2]), str(runs[1]), "--allow-mismatch")
    assert r.returncode == 0 and "wrist_supersample" in r.stdout, r.stdout + r.stderr
    r = _rpg(*args, "-o", str(runs[2]))  # the default (off) into the supersampled run
    assert r.returncode == 2 and "other settings (wrist_supersample)" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1


def test_visual_and_wrist_supersample_reach_the_environments_of_ray_workers(tmp_path):
    """The two tests above on Ray, in one run (a Ray instance costs seconds to start): each episode's record reads the
    meshes and the wrist factor back from the environment its Ray worker built, and run.json and the summary record
    both."""
    pytest.importorskip("ray", reason="Ray is not installed: the ray backend cannot be tested")
    run = tmp_path / "ray"
    r = _rpg("eval", "library/stack_blocks", "--policy", "oracle", "-n", "2", "--embodiment", FLOAT, "--cameras", "wrist",
             "--image-size", "32", "-j", "2", "--backend", "ray", "--visual", "stock", "--wrist-supersample", "2",
             "-o", str(run))
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
    assert [(e["visual"], e["wrist_supersample"]) for e in _lines(run / "episodes.jsonl")] == [("stock", 2)] * 2
    recorded = json.loads((run / "run.json").read_text())
    assert (recorded["visual"], recorded["wrist_supersample"]) == ("stock", 2)
    config = json.loads((run / "summary.json").read_text())["config"]
    assert (config["visual"], config["wrist_supersample"]) == ("stock", 2)


def test_a_bad_wrist_supersample_is_one_line_exit_2_and_writes_nothing(tmp_path):
    """Only 1 and 2 are taken, by rpg eval and rpg demos alike; anything else (another
    integer, a word, a decimal) is one line and exit 2 before anything is written."""
    for command, value in (("eval", "3"), ("eval", "two"), ("demos", "4"), ("demos", "2.0")):
        out = tmp_path / f"{command}-{value}"
        r = _rpg(command, "library/stack_blocks", "--embodiment", FLOAT, "--wrist-supersample", value,
                 "-o", str(out))
        assert r.returncode == 2, (command, value, r.stderr)
        assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert "--wrist-supersample must be 1 (off) or 2" in r.stderr and value in r.stderr, r.stderr
        assert not out.exists()


def test_a_failing_plugin_keeps_every_episode_and_the_run_goes_on(tmp_path):
    plugin = tmp_path / "flaky.py"
    plugin.write_text(
        "import numpy as np\n"
        "class Flaky:\n"
        "    episodes = 0\n"
        "    def reset(self, instruction):\n"
        "        type(self).episodes += 1\n"
        "    def act(self, obs):\n"
        "        if type(self).episodes == 3:\n"
        "            raise RuntimeError('the model crashed')\n"
        "        return np.zeros(7, np.float32)\n")
    run = tmp_path / "run"
    # no camera observations: the plug-in reads none, and rendering them was most of this test's time
    r = _rpg("eval", "library/stack_blocks", "--policy", f"{plugin}:Flaky", "-n", "5", "--embodiment", FLOAT,
             "--cameras", "", "-o", str(run))
    assert r.returncode == 0, r.stderr
    eps = _lines(run / "episodes.jsonl")
    assert len(eps) == 5 and [e["seed"] for e in eps] == [0, 1, 2, 3, 4]
    (bad,) = [e for e in eps if e["error"]]
    assert bad["seed"] == 2 and "RuntimeError: the model crashed" in bad["error"] and not bad["success"]
    s = json.loads((run / "summary.json").read_text())
    assert s["overall"]["errors"] == 1 and s["errors"][0]["seed"] == 2
    assert "the model crashed" in r.stdout
    fast = _rpg("eval", "library/stack_blocks", "--policy", f"{plugin}:Flaky", "-n", "5", "--embodiment", FLOAT,
                "--cameras", "", "--fail-fast", "-o", str(tmp_path / "fast"))
    assert fast.returncode == 2 and "--fail-fast" in fast.stderr and "Traceback" not in fast.stderr
    assert len(_lines(tmp_path / "fast" / "episodes.jsonl")) == 3


def test_a_plugin_that_hangs_fails_its_episode_at_the_inference_timeout(tmp_path):
    plugin = tmp_path / "slow.py"
    plugin.write_text("import time\nclass Slow:\n    def reset(self, instruction):\n        pass\n"
                      "    def act(self, obs):\n        time.sleep(3600)\n")
    t = time.monotonic()
    r = _rpg("eval", "library/stack_blocks", "--policy", f"{plugin}:Slow", "-n", "2", "--embodiment", FLOAT,
             "--inference-timeout", "1", "-o", str(tmp_path / "run"))
    assert r.returncode == 0, r.stderr
    assert time.monotonic() - t < 60
    eps = _lines(tmp_path / "run" / "episodes.jsonl")
    assert len(eps) == 2 and all("within 1 s (inference timeout)" in e["error"] for e in eps)


def test_a_silent_server_fails_each_episode_within_the_default_timeouts(tmp_path):
    """A server that sends its metadata and then nothing: every episode fails at the inference
    timeout and the run goes on.  The run sets --inference-timeout 2 (at the default, 30 s, it
    waits a minute); that no flag gives a remote policy the default timeouts is checked on the
    CLI's default and on the policy the runner builds from a config left at its defaults."""
    import inspect
    from types import SimpleNamespace

    from websockets.sync.server import serve

    from rpg.cli import eval_cmd
    from rpg.eval import runner
    from rpg.eval.policies import CONNECT_TIMEOUT_S, INFERENCE_TIMEOUT_S

    stop = threading.Event()

    def handler(ws):  # metadata, then silence
        ws.send(packb({"policy": "silent"}))
        stop.wait(600)

    server = serve(handler, "127.0.0.1", 0, compression=None, max_size=None)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"ws://127.0.0.1:{server.socket.getsockname()[1]}"
    try:
        assert inspect.signature(eval_cmd).parameters["inference_timeout"].default == INFERENCE_TIMEOUT_S
        policy = runner._policy_for(EvalConfig("library/stack_blocks", url, (0,)),  # timeouts at their defaults
                                    SimpleNamespace(action_space=SimpleNamespace(shape=(7,))))
        try:
            assert (policy.connect_timeout, policy.inference_timeout) == (CONNECT_TIMEOUT_S, INFERENCE_TIMEOUT_S)
        finally:
            runner._drop_policy(url)
        r = _rpg("eval", "library/stack_blocks", "--policy", url, "-n", "2", "--embodiment", FLOAT,
                 "--inference-timeout", "2", "-o", str(tmp_path / "run"), timeout=300)
    finally:
        stop.set()
        server.shutdown()
    assert r.returncode == 0, r.stderr
    eps = _lines(tmp_path / "run" / "episodes.jsonl")
    assert len(eps) == 2 and all("within 2 s (inference timeout)" in e["error"] for e in eps), eps
    assert all(e["wall_s"] < 2 + CONNECT_TIMEOUT_S for e in eps)  # connecting, then one unanswered call
    assert CONNECT_TIMEOUT_S + INFERENCE_TIMEOUT_S <= 40  # so at the defaults each episode fails within 40 s


def test_a_refused_setting_leaves_the_run_directory_as_it_was(tmp_path):
    run = tmp_path / "run"
    for args, msg in ((["--cameras", "agentview,fisheye"], "unknown camera 'fisheye'"),
                      (["--instruction", "paraphrase:9"], "has 3 paraphrases"),
                      (["--inference-timeout", "0"], "--inference-timeout must be a positive"),
                      (["--control-mode", "torque"], "no control mode 'torque'")):
        r = _rpg("eval", "library/stack_blocks", "--policy", "noop", "-n", "1", "--embodiment", FLOAT, *args, "-o", str(run))
        assert r.returncode == 2 and msg in r.stderr and "Traceback" not in r.stderr, (args, r.stderr)
        assert not run.exists(), args
    r = _rpg("eval", "library/stack_blocks", "--policy", "noop", "-n", "1", "--embodiment", FLOAT, "-o", str(run))
    assert r.returncode == 0, r.stderr
    s = json.loads((run / "summary.json").read_text())
    assert 0.0 <= s["tasks"]["stack_blocks"]["progress"] < 1.0 and "progress_stderr" in s["overall"]
    assert s["timing"]["stack_blocks"]["calls"] > 0 and s["timing"]["stack_blocks"]["latency_p95_s"] is not None


@pytest.mark.slow
def test_the_evaluation_page_loads_in_chromium(chromium, tmp_path):

    run = tmp_path / "run"
    r = _rpg("eval", "library/stack_blocks", "--policy", "random", "-n", "2", "--embodiment", FLOAT, "--video",
             "-o", str(run))
    assert r.returncode == 0, r.stderr
    site = tmp_path / "site"
    r = _rpg("report", str(run), "-o", str(site))
    assert r.returncode == 0, r.stderr
    dom = subprocess.run([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=10000",
                          "--dump-dom", (site / "eval.html").as_uri()], capture_output=True, text=True, timeout=120).stdout
    assert 'id="overall"' in dom and "<table" in dom
    assert len(re.findall(r'<div class="episode" data-success="(true|false)"', dom)) == 2
    assert dom.count("<video") == 2 and all((site / "eval" / v).is_file() for v in re.findall(r'src="eval/([^"]+\.mp4)"', dom))
    assert (site / "eval" / "success.png").stat().st_size > 1000


def test_killing_a_parallel_run_takes_its_workers_with_it(tmp_path):
    run = tmp_path / "run"
    proc = subprocess.Popen([sys.executable, "-m", "rpg.cli", "eval", "library/three_block_stack", "--policy", "oracle",
                             "-n", "40", "--jobs", "2", "--embodiment", FLOAT, "-o", str(run)], cwd=ROOT,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log = run / "episodes.jsonl"
    deadline = time.time() + 120
    while time.time() < deadline and (not log.is_file() or not log.read_text()):
        time.sleep(0.05)
    children = [int(p) for p in Path(f"/proc/{proc.pid}/task/{proc.pid}/children").read_text().split()]
    assert len(children) >= 2  # the pool's workers (and its resource tracker)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    deadline = time.time() + 20
    while time.time() < deadline and any(alive(c) for c in children):
        time.sleep(0.1)
    assert not any(alive(c) for c in children)


def test_a_process_keeps_few_environments_open():
    from rpg.eval import runner

    assert (runner.env_cache_size(True), runner.env_cache_size(False)) == (2, 12)
    assert runner.env_cache_size(True, wrist_supersampled=True) == 1  # a second renderer per environment
    cfg = runner.EvalConfig("x", "noop", (0,), embodiment=FLOAT, cameras=("wrist",), image_size=(32, 32))
    names = ["stack_blocks", "three_block_stack", "align_blocks"]
    envs = [runner._env_for(runner.Unit(runner.EvalTask(str(ROOT / "library" / n), n), "canonical", 0, cfg, "."))[0]
            for n in names]
    try:
        assert len(runner._ENVS) == runner.env_cache_size(True) == 2
        assert [k[0] for k in runner._ENVS] == [str(ROOT / "library" / n) for n in names[1:]]
        assert envs[0].unwrapped.scene is not None and envs[0] not in [e for e, _ in runner._ENVS.values()]
    finally:
        runner.close_workers()


_RSS_CHILD = r"""
import json, sys
import rpg
from rpg.env import BlockTaskEnv

def rss_mb():
    return next(int(x.split()[1]) for x in open("/proc/self/status") if x.startswith("VmRSS:")) / 1024

cameras, tasks, k = json.loads(sys.argv[1])
envs, rss = [], []
for t in tasks:
    envs.append(BlockTaskEnv(t, embodiment="panda", cameras=tuple(cameras), image_size=(224, 224), wrist_supersample=k))
    envs[-1].reset(seed=0)
    rss.append(rss_mb())
print(json.dumps(rss))
"""


@pytest.mark.parametrize(("key", "cameras", "k"), [("state-only", (), 1), ("cameras", ("agentview", "wrist"), 1),
                                               ("cameras, wrist 2x", ("agentview", "wrist"), 2)])
def test_an_open_panda_environment_costs_at_most_the_documented_memory(key, cameras, k):
    """``ENV_MEMORY_MB`` (which sets how many environments a process keeps open) bounds what one
    more open and reset Panda environment adds to a process's resident memory (with the wrist
    camera supersampled: a second renderer and GL context)."""
    from rpg.eval.runner import ENV_MEMORY_MB

    tasks = [str(LIBRARY / n) for n in ("stack_blocks", "three_block_stack", "align_blocks", "arrange_blocks")]
    r = subprocess.run([sys.executable, "-c", _RSS_CHILD, json.dumps([list(cameras), tasks, k])], capture_output=True,
                       text=True, timeout=300, env=dict(os.environ, MUJOCO_GL="egl"))
    assert r.returncode == 0, r.stderr[-2000:]
    rss = json.loads(r.stdout.strip().splitlines()[-1])
    per_env = (rss[-1] - rss[0]) / (len(rss) - 1)
    assert 0 < per_env <= ENV_MEMORY_MB[key], rss


def test_eval_refuses_to_score_a_goal_its_instruction_does_not_state(tmp_path):
    """G demands red under blue; the instruction sent says only "stack two blocks": refused,
    naming the order; --instruction canonical states G and runs; --allow-unstated records it."""
    from rpg.compiler import build
    from rpg.schema.builtin import parse
    from rpg.schema.feasibility import check_feasibility

    schema = check_feasibility(parse("Put the blue block on top of the red block."))
    secret = schema.model_copy(update={"instruction": "Stack two blocks on top of each other."})
    task = build(secret, tmp_path / "lib", name="secret").path
    r = _rpg("eval", str(task), "--policy", "noop", "-n", "1", "--embodiment", FLOAT, "-o", str(tmp_path / "run"))
    assert r.returncode == 2 and "does not state" in r.stderr and "order red under blue" in r.stderr, r.stderr
    assert not (tmp_path / "run").exists()
    r = _rpg("eval", str(task), "--policy", "oracle", "-n", "1", "--embodiment", FLOAT, "--instruction", "canonical",
             "-o", str(tmp_path / "canonical"))
    assert r.returncode == 0, r.stderr
    (ep,) = _lines(tmp_path / "canonical" / "episodes.jsonl")
    assert "red" in ep["instruction"] and "blue" in ep["instruction"] and ep["success"]
    s = json.loads((tmp_path / "canonical" / "summary.json").read_text())
    assert s["instruction_check"] == {"secret canonical": []}
    r = _rpg("eval", str(task), "--policy", "noop", "-n", "1", "--embodiment", FLOAT, "--allow-unstated",
             "-o", str(tmp_path / "allowed"))
    assert r.returncode == 0, r.stderr
    s = json.loads((tmp_path / "allowed" / "summary.json").read_text())
    assert any("order red under blue" in c for c in s["instruction_check"]["secret original"])
