"""rpg demos: a LeRobot v2.1 dataset of oracle episodes (schema, videos, provenance), replay,
resuming after kill -9, and the same dataset for any number of jobs."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import av
import numpy as np
import pyarrow.parquet as pq

LIBRARY = Path(__file__).resolve().parents[1] / "library"
STACK = str(LIBRARY / "stack_blocks")


def _rpg(*args, **kw):
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    return subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=600, **kw)


def _lines(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()]


def test_dataset_matches_its_metadata_and_replays(tmp_path):
    out = tmp_path / "ds"
    r = _rpg("demos", STACK, "--out", out, "-n", "2", "--image-size", "64")
    assert r.returncode == 0, r.stderr
    info = json.loads((out / "meta" / "info.json").read_text())
    assert info["codebase_version"] == "v2.1" and info["total_episodes"] == 2 and info["fps"] == 20.0
    episodes = _lines(out / "meta" / "episodes.jsonl")
    assert [e["episode_index"] for e in episodes] == [0, 1]
    assert info["total_frames"] == sum(e["length"] for e in episodes)
    assert _lines(out / "meta" / "tasks.jsonl") == [{"task": "Stack two blocks on top of each other.", "task_index": 0}]
    feats = info["features"]
    for e in episodes:
        assert e["seed"] in (0, 1) and e["embodiment"] == "floating_gripper" and len(e["task_hash"]) == 64
        assert e["tasks"] == [e["instruction"]] and e["paraphrase"] is None
        table = pq.read_table(out / info["data_path"].format(episode_chunk=0, episode_index=e["episode_index"]))
        columns = [k for k, f in feats.items() if f["dtype"] != "video"]
        assert sorted(table.column_names) == sorted(columns)
        assert table.num_rows == e["length"]
        for name in columns:
            values = table.column(name).to_pylist()
            width = feats[name]["shape"][0]
            assert all(len(v) == width for v in values) if isinstance(values[0], list) else width == 1
        assert table.column("index").to_pylist()[0] == sum(x["length"] for x in episodes[: e["episode_index"]])
        actions = np.array(table.column("action").to_pylist())
        assert np.abs(actions).max() <= 1.0 and (actions[:, 6] == 1.0).any()  # the gripper closed at some point
        for key in ("observation.images.agentview", "observation.images.wrist"):
            video = out / info["video_path"].format(episode_chunk=0, video_key=key, episode_index=e["episode_index"])
            with av.open(str(video)) as container:
                frames = [f.to_ndarray(format="rgb24") for f in container.decode(video=0)]
            assert len(frames) == e["length"] and frames[0].shape == (64, 64, 3)
    stats = _lines(out / "meta" / "episodes_stats.jsonl")
    assert len(stats) == 2 and len(stats[0]["stats"]["observation.images.wrist"]["mean"]) == 3
    r = _rpg("demos", "--replay", out)
    assert r.returncode == 0 and "replayed 2 episodes, 0 mismatched" in r.stdout, r.stdout + r.stderr


def test_replay_detects_a_changed_action(tmp_path):
    out = tmp_path / "ds"
    assert _rpg("demos", STACK, "--out", out, "-n", "1", "--cameras", "").returncode == 0
    path = out / "data" / "chunk-000" / "episode_000000.parquet"
    table = pq.read_table(path)
    actions = np.array(table.column("action").to_pylist(), np.float32)
    actions[5:15, 0] = 1.0  # a different trajectory
    import pyarrow as pa

    col = table.schema.get_field_index("action")
    table = table.set_column(col, table.schema.field("action"), pa.array(list(actions), type=table.schema.field("action").type))
    pq.write_table(table, path)
    r = _rpg("demos", "--replay", out)
    assert r.returncode == 1 and "MISMATCH" in r.stdout


def test_a_run_killed_mid_way_resumes_keeping_finished_episodes(tmp_path):
    out = tmp_path / "ds"
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    proc = subprocess.Popen([sys.executable, "-m", "rpg.cli", "demos", STACK, "--out", str(out), "-n", "4",
                             "--image-size", "32"], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log = out / "meta" / "episodes.jsonl"
    deadline = time.time() + 300
    while time.time() < deadline and not (log.is_file() and log.read_text().count("\n") >= 1):
        time.sleep(0.05)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    kept = len(_lines(log))
    assert 1 <= kept < 4
    torn = out / "data" / "chunk-000" / "episode_000009.parquet"  # what a kill during writing leaves
    torn.write_bytes(b"PAR1 torn")
    r = _rpg("demos", STACK, "--out", out, "-n", "4", "--image-size", "32")
    assert r.returncode == 0, r.stderr
    episodes = _lines(log)
    assert [e["episode_index"] for e in episodes] == [0, 1, 2, 3]
    assert sorted(e["seed"] for e in episodes) == [0, 1, 2, 3]
    assert not torn.exists()
    assert len(list((out / "data").rglob("*.parquet"))) == 4
    assert len(list((out / "videos").rglob("*.mp4"))) == 8
    assert _rpg("demos", "--replay", out).returncode == 0


def test_two_jobs_write_the_same_dataset_as_one(tmp_path):
    for jobs in (1, 2):
        r = _rpg("demos", STACK, "--out", tmp_path / f"j{jobs}", "-n", "3", "--cameras", "", "--jobs", jobs)
        assert r.returncode == 0, r.stderr
    one, two = (tmp_path / "j1", tmp_path / "j2")
    assert (one / "meta" / "episodes.jsonl").read_text() == (two / "meta" / "episodes.jsonl").read_text()
    for f in sorted((one / "data").rglob("*.parquet")):
        assert pq.read_table(f).equals(pq.read_table(two / f.relative_to(one)))


def test_bad_input_is_one_line_and_exit_2(tmp_path):
    r = _rpg("demos", STACK, "--out", tmp_path / "x", "--format", "hdf5")
    assert r.returncode == 2 and "not supported" in r.stderr and "Traceback" not in r.stderr
    r = _rpg("demos", "--replay", tmp_path)
    assert r.returncode == 2 and "not a dataset" in r.stderr
    r = _rpg("demos", str(tmp_path / "missing"), "--out", tmp_path / "y")
    assert r.returncode == 2 and "no task" in r.stderr
    assert not (tmp_path / "y").exists() and not (tmp_path / "x").exists()
