"""Host parsers refuse what their peers send: an openpi policy server (fake, local, in a
thread), robomimic HDF5 and LeRobot datasets replayed by ``rpg demos --replay``, and run
directories copied by ``rpg report``.  Every refusal is one line, quick, and allocates and
writes nothing on the peer's word."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import msgpack
import numpy as np
import pytest
import yaml

from rpg.demos import replay_dataset
from rpg.errors import BadInput, PeerError
from rpg.eval.openpi import ProtocolError, packb, unpackb
from rpg.eval.policies import PolicyServerError, PolicyTimeout, WebsocketPolicy

OBS = {"agentview_image": np.zeros((8, 8, 3), np.uint8), "state": np.zeros(8), "instruction": "x"}


# -- openpi ------------------------------------------------------------------------------
def _serve(answer, metadata=True):
    """A fake openpi server on a free local port: metadata first (unless ``metadata`` is
    False), then ``answer(observation_message)`` per message (None: no answer, ever);
    returns (url, server)."""
    from websockets.sync.server import serve

    stop = threading.Event()

    def handler(ws):
        if metadata:
            ws.send(packb({"policy": "fake"}))
        for message in ws:
            reply = answer(message)
            if reply is None:
                stop.wait(30)  # silent: holds the connection open, never answers
                return
            ws.send(reply)

    server = serve(handler, "127.0.0.1", 0, compression=None, max_size=None)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    server.stop = stop
    return f"ws://127.0.0.1:{server.socket.getsockname()[1]}", server


def _array(dtype: str, shape, data: bytes) -> dict:
    return {b"__ndarray__": True, b"data": data, b"dtype": dtype, b"shape": shape}


def _refused(answer, match: str, timeout: float = 2.0, cls=PolicyServerError, **kw):
    """Run one act() against a server answering with ``answer``; the error it raises."""
    url, server = _serve(answer)
    try:
        policy = WebsocketPolicy(url, connect_timeout=timeout, inference_timeout=timeout, **kw)
        policy.reset("stack")
        t0 = time.monotonic()
        with pytest.raises(cls, match=match) as info:
            policy.act(OBS)
        assert time.monotonic() - t0 < timeout + 2.0
        policy.close()
    finally:
        server.stop.set()
        server.shutdown()
    msg = str(info.value)
    assert "\n" not in msg and url in msg, msg
    assert isinstance(info.value, PeerError)
    return msg


def test_a_fake_server_answering_well_is_decoded():
    chunk = np.linspace(-1, 1, 35, dtype=np.float32).reshape(5, 7)
    seen = []

    def answer(message):
        seen.append(unpackb(message))
        return packb({"actions": chunk, "server_timing": {"infer_ms": np.float64(1.5)}})

    url, server = _serve(answer)
    try:
        policy = WebsocketPolicy(url, connect_timeout=2, inference_timeout=2)
        assert policy.metadata == {"policy": "fake"}
        policy.reset("stack the blocks")
        assert np.array_equal(policy.act(OBS), chunk)
        policy.close()
    finally:
        server.shutdown()
    assert seen[0]["prompt"] == "stack the blocks" and seen[0]["observation/image"].dtype == np.uint8


def test_an_object_dtype_array_is_refused():
    _refused(lambda m: msgpack.packb({"actions": _array("|O", (7,), b"\0" * 56)}), "dtype '|O' is refused")
    for dtype in ("<U7", "|V8", "<M8[s]", "<c16", "f8,f8"):
        _refused(lambda m, d=dtype: msgpack.packb({"actions": _array(d, (7,), b"\0" * 56)}), "is refused")
    structured = {"names": ["a"], "formats": ["O"], "offsets": [0], "itemsize": 8}
    _refused(lambda m: msgpack.packb({"actions": _array(structured, (7,), b"\0" * 56)}), "is refused")


def test_a_huge_declared_shape_with_tiny_data_is_refused_without_allocating():
    msg = _refused(lambda m: msgpack.packb({"actions": _array("<f8", (1 << 40, 7), b"\0" * 150)}),
                   "needs 61572651155456 bytes; the message holds 150")
    assert "(1099511627776, 7)" in msg
    _refused(lambda m: msgpack.packb({"actions": _array("<f4", (-1, 7), b"\0" * 28)}), "non-negative integers")


def test_an_answer_of_the_wrong_shape_is_refused():
    _refused(lambda m: packb({"actions": np.zeros((4, 6), np.float32)}), r"shape \(4, 6\); expected \(7,\) or \(H, 7\)")
    _refused(lambda m: packb({"actions": np.zeros((2000, 7), np.float32)}), "1 <= H <= 1024")
    _refused(lambda m: packb({"actions": np.zeros((0, 7), np.float32)}), "1 <= H <= 1024")
    _refused(lambda m: packb({"actions": np.zeros((2, 3, 7), np.float32)}), "expected")
    _refused(lambda m: packb({"actions": [0.0] * 7}), "not an array")
    _refused(lambda m: packb({"nothing": 1}), "without 'actions'")
    _refused(lambda m: "Traceback (most recent call last):\n  ...\nRuntimeError: out of memory\n",
             "reported an error: RuntimeError: out of memory")


def test_a_message_over_the_size_limit_is_refused():
    _refused(lambda m: packb({"actions": np.zeros((7,), np.float32), "pad": b"x" * 200_000}),
             "over the 100000-byte limit", max_message_bytes=100_000)


def test_a_silent_server_times_out_with_the_inference_timeout():
    msg = _refused(lambda m: None, "inference timeout", timeout=1.0, cls=PolicyTimeout)
    assert "did not answer within 1 s" in msg


def test_a_server_without_metadata_times_out_with_the_connect_timeout():
    from websockets.sync.server import serve

    stop = threading.Event()
    server = serve(lambda ws: stop.wait(30), "127.0.0.1", 0)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"ws://127.0.0.1:{server.socket.getsockname()[1]}"
    try:
        t0 = time.monotonic()
        with pytest.raises(PolicyTimeout, match=r"sent no metadata within 1 s of connecting \(connect timeout\)"):
            WebsocketPolicy(url, connect_timeout=1.0)
        assert time.monotonic() - t0 < 3.0
    finally:
        stop.set()
        server.shutdown()


def test_unpackb_refuses_malformed_messages():
    for raw, match in ((b"\xc1", "not one msgpack document"), ("text", "not bytes"),
                       (b"\xdd\xff\xff\xff\xff", "not one msgpack document"),
                       (msgpack.packb({b"__npgeneric__": True, b"data": 300, b"dtype": "|u1"}), "does not fit"),
                       (msgpack.packb({b"__npgeneric__": True, b"data": "x", b"dtype": "<f8"}), "not a number")):
        with pytest.raises(ProtocolError, match=match):
            unpackb(raw)
    with pytest.raises(ProtocolError, match="over the 10-byte limit"):
        unpackb(packb(np.zeros(4)), max_bytes=10)


# -- rpg demos --replay ------------------------------------------------------------------
ROOT = Path(__file__).resolve().parents[1]
STACK = ROOT / "library" / "stack_blocks"


def _rpg(*args, cwd=ROOT):
    env = dict(os.environ, MUJOCO_GL=os.environ.get("MUJOCO_GL", "egl"), LITELLM_LOCAL_MODEL_COST_MAP="True")
    return subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=600, cwd=cwd)


def _one_line_error(r, code: int = 2) -> str:
    assert r.returncode == code, r.stdout + r.stderr
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
    return r.stderr


@pytest.mark.parametrize("fmt", ["lerobot-v2.1", "hdf5"])  # LeRobot v3.0: tests/test_datasets.py
def test_replay_finds_tasks_by_hash_in_the_library_and_never_loads_the_recorded_path(tmp_path, fmt):
    import h5py

    out = tmp_path / "ds"
    assert _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "", "--format", fmt).returncode == 0
    trap = tmp_path / "trap"  # a task that must never load: its marker would appear
    shutil.copytree(STACK, trap)
    (trap / "code.py").write_text((trap / "code.py").read_text() + f"\nopen({str(tmp_path / 'LOADED')!r}, 'w')\n")
    if fmt == "hdf5":
        with h5py.File(out / "demo.hdf5", "r+") as f:
            f["data/demo_0"].attrs["task"] = str(trap)
    else:
        rows = [json.loads(x) for x in (out / "meta" / "episodes.jsonl").read_text().splitlines()]
        (out / "meta" / "episodes.jsonl").write_text("".join(json.dumps({**r, "task": str(trap)}) + "\n" for r in rows))
    ours = tmp_path / "mine"  # the default --library is library/ under the working directory
    (ours / "library").mkdir(parents=True)
    shutil.copytree(STACK, ours / "library" / "renamed_stack")
    r = _rpg("demos", "--replay", out, cwd=ours)
    assert r.returncode == 0 and "replayed 1 episodes, 0 mismatched" in r.stdout, r.stdout + r.stderr
    results = replay_dataset(out, library=ours / "library")
    assert [x.ok for x in results] == [True]
    assert not (tmp_path / "LOADED").exists()
    other = tmp_path / "other"  # a library without the recorded hash
    (other / "library").mkdir(parents=True)
    shutil.copytree(ROOT / "library" / "block_alignment", other / "library" / "block_alignment")
    err = _one_line_error(_rpg("demos", "--replay", out, cwd=other))
    recorded = yaml.safe_load((STACK / "task.yaml").read_text())["content_hash"]
    assert f"no task in library has content hash {recorded[:12]}" in err and "--library" in err
    with pytest.raises(BadInput, match="no task in .* has content hash"):
        replay_dataset(out, library=other / "library")
    assert not (tmp_path / "LOADED").exists()


def _demo_file(path: Path, actions: dict) -> None:
    """A robomimic file of one demo with good provenance and an ``actions`` dataset made by
    ``h5py.Group.create_dataset(**actions)``."""
    import h5py

    with h5py.File(path, "w") as f:
        g = f.create_group("data/demo_0")
        for k, v in {"task": "/nonexistent", "task_hash": "0" * 64, "task_name": "t", "seed": 0,
                     "embodiment": "floating_gripper", "instruction": "x", "final_poses": "{}"}.items():
            g.attrs[k] = v
        g.create_dataset("actions", **actions)


def test_an_hdf5_file_declaring_a_huge_action_dataset_is_refused_without_reading_it(tmp_path):
    big = tmp_path / "big"
    big.mkdir()
    _demo_file(big / "demo.hdf5", {"shape": (10**9, 7), "dtype": "f8", "chunks": (1024, 7)})
    assert (big / "demo.hdf5").stat().st_size < 16 * 1024  # nothing written: 56 GB declared
    t0 = time.monotonic()
    with pytest.raises(PeerError, match=r"declares shape \(1000000000, 7\); actions must be \(T, 7\)"):
        replay_dataset(big, library=ROOT / "library")
    assert time.monotonic() - t0 < 5
    assert "declares shape (1000000000, 7)" in _one_line_error(_rpg("demos", "--replay", big))
    for name, actions, match in (
            ("chunk", {"shape": (10, 7), "maxshape": (None, 7), "dtype": "f8", "chunks": (2**24, 7)}, "declares chunks"),
            ("dtype", {"data": np.zeros((10, 7), np.int64)}, "actions must be float"),
            ("shape", {"data": np.zeros((10, 6), np.float32)}, r"actions must be \(T, 7\)"),
            ("external", {"shape": (10, 7), "dtype": "f8", "external": [(str(tmp_path / "x"), 0, 560)]},
             "stored outside the file")):
        (tmp_path / name).mkdir()
        _demo_file(tmp_path / name / "demo.hdf5", actions)
        with pytest.raises(PeerError, match=match):
            replay_dataset(tmp_path / name, library=ROOT / "library")


def test_a_lerobot_dataset_out_of_bounds_is_refused(tmp_path):
    import pyarrow as pa
    import pyarrow.parquet as pq

    from rpg.demos.lerobot import read_episode_actions, read_episodes

    out = tmp_path / "ds"
    assert _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "",
                "--format", "lerobot-v2.1").returncode == 0
    data = out / "data" / "chunk-000" / "episode_000000.parquet"
    good = read_episode_actions(out, 0)
    assert good.shape[1] == 7 and good.dtype == np.float32
    with pytest.raises(PeerError, match=f"declares {len(good)} rows; an episode has 1 to 10 steps"):
        read_episode_actions(out, 0, max_steps=10)
    saved = data.read_bytes()
    pq.write_table(pa.table({"action": pa.array([["a"] * 7] * 3)}), data)
    with pytest.raises(PeerError, match="the action column is not 7 floats a row"):
        read_episode_actions(out, 0)
    data.unlink()
    (tmp_path / "elsewhere.parquet").write_bytes(saved)
    data.symlink_to(tmp_path / "elsewhere.parquet")
    with pytest.raises(PeerError, match="is a symbolic link"):
        read_episode_actions(out, 0)
    meta = out / "meta" / "episodes.jsonl"
    line = json.loads(meta.read_text().splitlines()[0])
    for bad, match in (({"seed": "0"}, "seed is not an integer"), ({"task_hash": "../x"}, "not a content hash"),
                       ({"final_poses": {"red": [0.0] * 7000}}, "final_poses is not a map")):
        meta.write_text(json.dumps({**line, **bad}) + "\n")
        with pytest.raises(PeerError, match=match):
            replay_dataset(out, library=ROOT / "library")
    meta.write_text("[1, 2]\n")
    with pytest.raises(PeerError, match="is not a map"):
        read_episodes(out)


# -- rpg report --eval ---------------------------------------------------------------------
@pytest.fixture(scope="module")
def run_dir(tmp_path_factory):
    """A finished oracle run of one episode with its video."""
    from rpg.eval import EvalConfig, run_eval

    run = tmp_path_factory.mktemp("eval") / "run"
    run_eval(EvalConfig(target=str(STACK), policy="oracle", seeds=(0,), embodiment="floating_gripper", video=True), run)
    return run


def _with_video(run_dir: Path, tmp_path: Path, video: str) -> Path:
    """A copy of ``run_dir`` whose episode names ``video``."""
    run = tmp_path / "run"
    shutil.copytree(run_dir, run, symlinks=True)
    rows = [json.loads(x) for x in (run / "episodes.jsonl").read_text().splitlines()]
    (run / "episodes.jsonl").write_text("".join(json.dumps({**r, "video": video}) + "\n" for r in rows))
    return run


def test_report_copies_a_runs_own_video(run_dir, tmp_path):
    from rpg.eval.report import write_eval_report

    video = json.loads((run_dir / "episodes.jsonl").read_text().splitlines()[0])["video"]
    page = write_eval_report(run_dir, tmp_path / "site")
    assert (tmp_path / "site" / "eval" / video).read_bytes() == (run_dir / video).read_bytes()
    assert video in page.read_text()


@pytest.mark.parametrize("case", ["symlinked_file", "symlinked_dir", "dotdot", "absolute", "symlinked_summary"])
def test_report_refuses_a_symlink_or_a_path_outside_the_run_in_one_line_writing_nothing(run_dir, tmp_path, case):
    from rpg.eval.report import write_eval_report
    from rpg.library.report import write_report

    secret = tmp_path / "secret.mp4"
    secret.write_bytes(b"not yours")
    video = json.loads((run_dir / "episodes.jsonl").read_text().splitlines()[0])["video"]
    if case == "symlinked_file":
        run = _with_video(run_dir, tmp_path, video)
        (run / video).unlink()
        (run / video).symlink_to(secret)
        match = "is a symbolic link"
    elif case == "symlinked_dir":
        run = _with_video(run_dir, tmp_path, video)
        elsewhere = tmp_path / "elsewhere"
        shutil.move(run / Path(video).parent, elsewhere)
        (run / Path(video).parent).symlink_to(elsewhere)
        match = "is a symbolic link"
    elif case == "dotdot":
        run = _with_video(run_dir, tmp_path, "../secret.mp4")
        match = "not a plain path inside the run directory"
    elif case == "absolute":
        run = _with_video(run_dir, tmp_path, str(secret))
        match = "not a plain path inside the run directory"
    else:
        run = _with_video(run_dir, tmp_path, video)
        (tmp_path / "summary.json").write_bytes((run / "summary.json").read_bytes())
        (run / "summary.json").unlink()
        (run / "summary.json").symlink_to(tmp_path / "summary.json")
        match = "symbolic link or not a regular file"
    site = tmp_path / "site"
    with pytest.raises(PeerError, match=match):
        write_eval_report(run, site)
    with pytest.raises(PeerError, match=match):
        write_report(ROOT / "library", site, runs=[run])
    assert not site.exists()
    err = _one_line_error(_rpg("report", run, "-o", site))
    assert "error:" in err and not site.exists()
    assert secret.read_bytes() == b"not yours"
