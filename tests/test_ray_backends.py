"""rpg eval and rpg demos on Ray (``--backend ray``, :mod:`rpg.parallel`) against the local
process pool: the same summary and the same dataset bytes for the oracle, resuming after a
kill -9 with nothing counted twice, and one-line errors when Ray cannot be used.  A local Ray
instance only (bound to 127.0.0.1); nothing here touches the network."""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pyarrow.parquet as pq
import pytest
import yaml

from tests.helpers import alive

ROOT = Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "library"
FLOAT = "floating_gripper"
TASKS = ("stack_blocks", "three_block_stack")

pytest.importorskip("ray", reason="Ray is not installed (pip install 'rpg[ray]'): the ray backend cannot be tested")


def _env() -> dict:
    return {**os.environ, "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl"), "LITELLM_LOCAL_MODEL_COST_MAP": "True"}


def _rpg(*args, timeout=600) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, args)], capture_output=True, text=True,
                          env=_env(), cwd=ROOT, timeout=timeout)


def _without_timing(path: Path) -> dict:
    doc = json.loads(path.read_text())
    doc.pop("timing")
    return doc


def _files(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def manifest(tmp_path_factory) -> Path:
    """Two library tasks copied (others may rewrite the library while this runs) with their manifest."""
    base = tmp_path_factory.mktemp("lib")
    doc = yaml.safe_load((LIBRARY / "manifest.yaml").read_text())
    entries = [e for e in doc["entries"] if e["name"] in TASKS]
    assert [e["name"] for e in entries] == list(TASKS)
    for name in TASKS:
        shutil.copytree(LIBRARY / name, base / name)
    (base / "manifest.yaml").write_text(yaml.safe_dump({"entries": entries}, sort_keys=False))
    return base / "manifest.yaml"


def _eval_args(manifest: Path, backend: str, out: Path) -> list:
    return ["eval", manifest, "--policy", "oracle", "-n", "2", "--embodiment", FLOAT, "-j", "2", "--backend", backend,
            "-o", out]


def _demos_args(manifest: Path, backend: str, out: Path) -> list:
    return ["demos", manifest, "--embodiment", FLOAT, "-n", "2", "--cameras", "agentview", "--image-size", "32",
            "-j", "2", "--backend", backend, "--out", out]


@pytest.fixture(scope="module")
def pool(manifest, tmp_path_factory) -> Path:
    """An eval run and a dataset of the two tasks written by the local process pool."""
    base = tmp_path_factory.mktemp("pool")
    for args in (_eval_args(manifest, "local", base / "eval"), _demos_args(manifest, "local", base / "demos")):
        r = _rpg(*args)
        assert r.returncode == 0, r.stderr
    return base


def _episodes(run: Path) -> list[dict]:
    """Everything an eval run records per episode but its wall-clock times, sorted."""
    recs = [json.loads(x) for x in (run / "episodes.jsonl").read_text().splitlines()]
    return sorted(({k: v for k, v in r.items() if k not in ("wall_s", "latency_s")} for r in recs),
                  key=lambda r: (r["task"], r["seed"]))


def test_ray_and_the_pool_give_the_same_summary_and_the_same_dataset_bytes(manifest, pool, tmp_path):
    for args in (_eval_args(manifest, "ray", tmp_path / "eval"), _demos_args(manifest, "ray", tmp_path / "demos")):
        r = _rpg(*args)
        assert r.returncode == 0, r.stderr
        assert "Traceback" not in r.stderr
    summary = _without_timing(pool / "eval" / "summary.json")
    assert summary == _without_timing(tmp_path / "eval" / "summary.json")
    assert summary["overall"]["n"] == 4 and set(summary["tasks"]) == set(TASKS)
    assert _episodes(pool / "eval") == _episodes(tmp_path / "eval")
    a, b = _files(pool / "demos"), _files(tmp_path / "demos")
    assert [k for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k)] == []  # byte for byte: parquet, MP4, metadata
    assert any(k.endswith(".mp4") for k in a) and any(k.startswith("data/") for k in a)


def _descendants(pid: int) -> list[int]:
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        for task in Path(f"/proc/{p}/task").glob("*"):
            try:
                kids = [int(c) for c in (task / "children").read_text().split()]
            except OSError:
                continue
            out += kids
            todo += kids
    return out


def _cmdline(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return ""


@pytest.mark.slow
def test_a_ray_eval_killed_with_sigkill_resumes_and_counts_nothing_twice(manifest, tmp_path):
    run = tmp_path / "run"
    task = manifest.parent / "three_block_stack"
    args = ["eval", task, "--policy", "oracle", "-n", "8", "--embodiment", FLOAT, "-j", "2", "--backend", "ray",
            "-o", run]
    proc = subprocess.Popen([sys.executable, "-m", "rpg.cli", *map(str, args)], cwd=ROOT, env=_env(),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log = run / "episodes.jsonl"
    deadline = time.time() + 300
    while time.time() < deadline and (not log.is_file() or len(log.read_text().splitlines()) < 2):
        time.sleep(0.05)
    ray_processes = _descendants(proc.pid)  # the local Ray instance and its workers
    names = {p: _cmdline(p) for p in ray_processes}
    os.kill(proc.pid, signal.SIGKILL)
    killed = time.time()
    proc.wait()
    kept = log.read_text().splitlines()
    assert 2 <= len(kept) < 8 and ray_processes
    r = _rpg(*args)
    assert r.returncode == 0, r.stderr
    lines = log.read_text().splitlines()
    assert lines[: len(kept)] == kept and len(lines) == 8
    assert sorted(json.loads(x)["seed"] for x in lines) == list(range(8))
    summary = json.loads((run / "summary.json").read_text())
    assert summary["overall"]["n"] == 8 and summary["tasks"]["three_block_stack"]["n"] == 8
    # the kill took Ray with it: its workers within seconds (Ray's idle node agents give up
    # on the dead instance ~40 s later; not waited for here)
    busy = [p for p in ray_processes if "Agent" not in names[p]]
    while time.time() < killed + 60 and any(alive(p) for p in busy):
        time.sleep(0.5)
    assert busy and not [p for p in busy if alive(p)]


@pytest.mark.slow
def test_a_ray_demos_run_killed_with_sigkill_resumes_to_the_pools_dataset(manifest, pool, tmp_path):
    out = tmp_path / "demos"
    args = _demos_args(manifest, "ray", out)
    proc = subprocess.Popen([sys.executable, "-m", "rpg.cli", *map(str, args)], cwd=ROOT, env=_env(),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    first = out / "meta" / "episodes" / "chunk-000" / "file-000.parquet"  # the first committed episode
    deadline = time.time() + 300
    while time.time() < deadline and proc.poll() is None and not first.is_file():
        time.sleep(0.02)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    kept = pq.read_table(first).to_pylist()
    assert 1 <= len(kept) < 4
    r = _rpg(*args)
    assert r.returncode == 0, r.stderr
    done = pq.read_table(first).to_pylist()
    assert done[: len(kept)] == kept
    assert [(row["task_name"], row["seed"]) for row in done] == [(row["task_name"], row["seed"]) for row in
                                                                 pq.read_table(pool / "demos" / first.relative_to(out)).to_pylist()]
    a, b = _files(out), _files(pool / "demos")
    assert [k for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k)] == []  # byte for byte the pool's, unkilled


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _one_line_error(r: subprocess.CompletedProcess, *words: str) -> None:
    assert r.returncode == 2, r.stdout + r.stderr
    lines = [x for x in r.stderr.splitlines() if x.strip()]
    assert len(lines) == 1 and lines[0].startswith("error:") and "Traceback" not in r.stderr, r.stderr
    for w in words:
        assert w in lines[0], lines[0]


@pytest.mark.parametrize("command", ["eval", "demos"])
def test_an_unreachable_address_or_a_bad_backend_is_one_line_and_writes_nothing(command, manifest, tmp_path):
    out = tmp_path / "out"
    task = manifest.parent / "stack_blocks"
    where = ["-o", out] if command == "eval" else ["--out", out]
    base = [command, task, "--embodiment", FLOAT, "-n", "1", *where]
    t0 = time.monotonic()
    _one_line_error(_rpg(*base, "--backend", "ray", "--address", f"127.0.0.1:{_free_port()}"), "cannot reach")
    assert time.monotonic() - t0 < 60  # Ray alone retries an unreachable cluster for minutes
    _one_line_error(_rpg(*base, "--backend", "ray", "--address", "not an address"), "--address")
    _one_line_error(_rpg(*base, "--backend", "dask"), "--backend must be local or ray")
    _one_line_error(_rpg(*base, "--address", "auto"), "--backend ray")
    assert not out.exists()


@pytest.mark.parametrize("command", ["eval", "demos"])
def test_the_ray_backend_without_ray_installed_is_one_line(command, manifest, tmp_path):
    out = tmp_path / "out"
    where = ["-o", out] if command == "eval" else ["--out", out]
    argv = ["rpg", command, str(manifest.parent / "stack_blocks"), "--embodiment", FLOAT, "-n", "1",
            *map(str, where), "--backend", "ray"]
    code = ("import sys; sys.modules['ray'] = None  # import ray raises ImportError\n"
            f"sys.argv = {argv!r}\nfrom rpg.cli import main\nmain()")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=_env(), cwd=ROOT, timeout=300)
    _one_line_error(r, "needs Ray", "pip install")
    assert not out.exists()


def test_work_items_raise_their_own_exceptions_and_come_back_in_order_on_ray():
    from rpg.parallel import open_backend

    with open_backend("ray", 2) as runner:
        assert list(runner.imap(int, ["3", "1", "2"], ordered=True)) == [3, 1, 2]
        assert sorted(runner.imap(int, ["3", "1", "2"])) == [1, 2, 3]
        with pytest.raises(ValueError, match="invalid literal"):
            list(runner.imap(int, ["1", "x"], ordered=True))


@pytest.fixture
def ray_head():
    """A Ray head started on its own (``ray start --head --block``, 2 CPUs, a free port), as a
    cluster's would be: its files in a fresh temporary directory, Ray's token authentication
    with a token of its own (not ~/.ray's), stopped at the end by ending the process group it
    was started in (``ray stop`` would stop every Ray instance of the machine)."""
    import secrets
    import tempfile

    port = _free_port()
    temp = Path(tempfile.mkdtemp(prefix="rpgray", dir="/tmp"))  # short: Ray's sockets live under it
    env = {**_env(), "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": secrets.token_hex(32), "RAY_USAGE_STATS_ENABLED": "0"}
    head = subprocess.Popen([str(Path(sys.executable).parent / "ray"), "start", "--head", "--block", "--port", str(port),
                             "--num-cpus", "2", "--temp-dir", str(temp), "--node-ip-address", "127.0.0.1",
                             "--include-dashboard", "false", "--disable-usage-stats"],
                            cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            start_new_session=True)
    try:
        deadline = time.time() + 120
        while time.time() < deadline and head.poll() is None:
            with socket.socket() as s, contextlib.suppress(OSError):
                s.settimeout(1)
                s.connect(("127.0.0.1", port))
                break
            time.sleep(0.2)
        if head.poll() is not None:
            pytest.fail(f"ray start --head exited {head.returncode}: {head.stderr.read().decode()[-2000:]}")
        yield f"127.0.0.1:{port}", env
    finally:
        head.terminate()  # --block: Ray stops the processes it started
        with contextlib.suppress(subprocess.TimeoutExpired):
            head.wait(30)
        deadline = time.time() + 30
        while time.time() < deadline and _group(head.pid):
            time.sleep(0.5)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(head.pid, signal.SIGKILL)
        head.wait()
        shutil.rmtree(temp, ignore_errors=True)


def _group(pgid: int) -> list[int]:
    """The live processes of process group ``pgid``."""
    out = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        with contextlib.suppress(OSError, ValueError, IndexError):
            fields = stat.read_text().rsplit(")", 1)[1].split()
            if int(fields[2]) == pgid and fields[0] != "Z":
                out.append(int(stat.parent.name))
    return out


@pytest.mark.slow
def test_eval_on_a_ray_head_started_separately_gives_the_pools_summary(ray_head, manifest, tmp_path):
    address, env = ray_head
    task = manifest.parent / "stack_blocks"
    base = ["eval", task, "--policy", "oracle", "-n", "2", "--embodiment", FLOAT, "-j", "2"]
    pool = _rpg(*base, "--backend", "local", "-o", tmp_path / "pool")
    assert pool.returncode == 0, pool.stderr
    r = subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, base), "--backend", "ray", "--address", address,
                        "-o", tmp_path / "ray"], capture_output=True, text=True, env=env, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    assert "Traceback" not in r.stderr
    # without the token the head, which has just taken the same run with it, refuses it: one line that
    # says what is missing.  Ray tries to connect about once a second, 20 times by default; 2 here
    no_token = {k: v for k, v in env.items() if k not in ("RAY_AUTH_MODE", "RAY_AUTH_TOKEN")}
    no_token |= {"RAY_gcs_server_port_wait_time_s": "2", "RAY_NUM_REDIS_GET_RETRIES": "2"}
    r = subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, base), "--backend", "ray", "--address", address,
                        "-o", tmp_path / "refused"], capture_output=True, text=True, env=no_token, cwd=ROOT, timeout=300)
    _one_line_error(r, "could not start the Ray cluster", "RAY_AUTH_MODE=token")
    assert not (tmp_path / "refused" / "episodes.jsonl").exists()
    summary = _without_timing(tmp_path / "pool" / "summary.json")
    assert summary == _without_timing(tmp_path / "ray" / "summary.json")
    assert summary["overall"]["n"] == 2 and set(summary["tasks"]) == {"stack_blocks"}
    assert _episodes(tmp_path / "pool") == _episodes(tmp_path / "ray")


def test_a_local_ray_instance_joins_no_other_cluster(manifest, tmp_path, monkeypatch):
    """Without --address rpg starts a Ray instance of its own: Ray's default had joined the cluster RAY_ADDRESS (or the
    machine's last started one) names, whose workers may run other code (two test runs side by side had written different
    videos). Here RAY_ADDRESS names a port nobody listens on; the run must not try it."""
    monkeypatch.setenv("RAY_ADDRESS", f"127.0.0.1:{_free_port()}")
    out = tmp_path / "out"
    r = _rpg("eval", manifest.parent / "stack_blocks", "--embodiment", FLOAT, "-n", "1", "-o", out, "--backend", "ray",
             "--jobs", "1")
    assert r.returncode == 0, r.stdout + r.stderr
    assert (out / "summary.json").is_file()
