"""rpg demos: a LeRobot v2.1 dataset of oracle episodes (schema, videos, provenance), replay,
resuming after kill -9, and the same dataset for any number of jobs; robomimic's HDF5.
LeRobot v3.0 (the default format) and the frame layout: tests/test_datasets.py."""

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
import pytest

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
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "2", "--image-size", "64",
             "--format", "lerobot-v2.1")
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
    assert _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "",
                "--format", "lerobot-v2.1").returncode == 0
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


def _kill_after_first_episode(args: list[str], out: Path) -> list[dict]:
    """Run ``rpg ARGS``, SIGKILL it once ``out`` has committed an episode; the committed lines."""
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    proc = subprocess.Popen([sys.executable, "-m", "rpg.cli", *args], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log = out / "meta" / "episodes.jsonl"
    deadline = time.time() + 300
    while time.time() < deadline and not (log.is_file() and log.read_text().count("\n") >= 1):
        time.sleep(0.05)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    return _lines(log)


def test_a_run_killed_mid_way_resumes_keeping_finished_episodes(tmp_path):
    out = tmp_path / "ds"
    log = out / "meta" / "episodes.jsonl"
    args = ["demos", STACK, "--embodiment", "floating_gripper", "--out", str(out), "-n", "4", "--image-size", "32",
            "--format", "lerobot-v2.1"]
    kept = len(_kill_after_first_episode(args, out))
    assert 1 <= kept < 4
    torn = out / "data" / "chunk-000" / "episode_000009.parquet"  # what a kill during writing leaves
    torn.write_bytes(b"PAR1 torn")
    r = _rpg(*args)
    assert r.returncode == 0, r.stderr
    episodes = _lines(log)
    assert [e["episode_index"] for e in episodes] == [0, 1, 2, 3]
    assert sorted(e["seed"] for e in episodes) == [0, 1, 2, 3]
    assert not torn.exists()
    assert len(list((out / "data").rglob("*.parquet"))) == 4
    assert len(list((out / "videos").rglob("*.mp4"))) == 8
    assert _rpg("demos", "--replay", out).returncode == 0


def _committed(out: Path) -> list[dict]:
    """The committed episode records of a dataset of any format."""
    if (out / "meta" / "episodes").is_dir():  # LeRobot v3.0
        return [r for f in sorted((out / "meta" / "episodes").rglob("*.parquet")) for r in pq.read_table(f).to_pylist()]
    return _lines(out / "meta" / "episodes.jsonl")


def _uncommit_last(out: Path) -> None:
    """Take back the last episode's commit (its row), leaving its files and its attempt line: what a
    kill between the attempt line and the commit leaves."""
    if (out / "meta" / "episodes").is_dir():  # LeRobot v3.0
        f = sorted((out / "meta" / "episodes").rglob("*.parquet"))[-1]
        t = pq.read_table(f)
        pq.write_table(t.slice(0, t.num_rows - 1), f)
    else:
        f = out / "meta" / "episodes.jsonl"
        f.write_text("".join(f.read_text().splitlines(keepends=True)[:-1]))


@pytest.mark.parametrize("fmt", ["lerobot", "lerobot-v2.1", "hdf5"])
def test_a_kill_between_the_attempt_line_and_the_commit_records_the_episode_as_an_unkilled_run(tmp_path, fmt):
    out = tmp_path / "ds"
    args = ["demos", STACK, "--embodiment", "floating_gripper", "--cameras", "", "--format", fmt]
    assert _rpg(*args, "--out", out, "-n", "3").returncode == 0
    unkilled = (out / "meta" / "rpg_attempts.jsonl").read_text()
    _uncommit_last(out)
    assert sorted(e["seed"] for e in _committed(out)) == [0, 1]
    assert len(_lines(out / "meta" / "rpg_attempts.jsonl")) == 3  # the lost episode's attempt, marked kept
    r = _rpg(*args, "--out", out, "-n", "3")
    assert r.returncode == 0, r.stderr
    assert sorted(e["seed"] for e in _committed(out)) == [0, 1, 2]
    assert (out / "meta" / "rpg_attempts.jsonl").read_text() == unkilled


@pytest.mark.parametrize("fmt", ["lerobot", "lerobot-v2.1"])
def test_two_jobs_write_the_same_dataset_as_one(tmp_path, fmt):
    for jobs in (1, 2):
        r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", tmp_path / f"j{jobs}", "-n", "3",
                 "--cameras", "", "--jobs", jobs, "--format", fmt)
        assert r.returncode == 0, r.stderr
    one, two = (tmp_path / "j1", tmp_path / "j2")
    assert _committed(one) == _committed(two) and len(_committed(one)) == 3
    files = sorted((one / "data").rglob("*.parquet"))
    assert files
    for f in files:
        assert pq.read_table(f).equals(pq.read_table(two / f.relative_to(one)))


def test_bad_input_is_one_line_and_exit_2(tmp_path):
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", tmp_path / "x", "--format", "zarr")
    assert r.returncode == 2 and "not supported" in r.stderr and "Traceback" not in r.stderr
    r = _rpg("demos", "--replay", tmp_path)
    assert r.returncode == 2 and "not a dataset" in r.stderr
    r = _rpg("demos", str(tmp_path / "missing"), "--out", tmp_path / "y")
    assert r.returncode == 2 and "no task" in r.stderr
    assert not (tmp_path / "y").exists() and not (tmp_path / "x").exists()


# -- robomimic HDF5 ----------------------------------------------------------------------
def _read_like_robomimic(path: Path) -> dict:
    """What robomimic's SequenceDataset and FileUtils read from a dataset (robomimic
    docs/datasets/overview.md, "Dataset Structure"): env_args, total, per-demo num_samples,
    obs / next_obs / actions / rewards / dones, filter keys under mask/."""
    import h5py

    with h5py.File(path, "r") as f:
        data = f["data"]
        demos = sorted(data, key=lambda n: int(n[5:]))
        out = {"env_args": json.loads(data.attrs["env_args"]), "total": int(data.attrs["total"]), "demos": {},
               "masks": {k: [d.decode() for d in f["mask"][k][:]] for k in f["mask"]}}
        for name in demos:
            g = data[name]
            out["demos"][name] = {
                "n": int(g.attrs["num_samples"]), "seed": int(g.attrs["seed"]),
                "obs": {k: g["obs"][k][()] for k in g["obs"]}, "next_obs": {k: g["next_obs"][k][()] for k in g["next_obs"]},
                **{k: g[k][()] for k in ("actions", "rewards", "dones", "states")}}
    return out


def test_hdf5_dataset_has_robomimic_layout_and_replays(tmp_path):
    out = tmp_path / "ds"
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "2", "--image-size", "32", "--format", "hdf5")
    assert r.returncode == 0, r.stderr
    assert not list((out / "parts").iterdir())  # gathered into demo.hdf5
    ds = _read_like_robomimic(out / "demo.hdf5")
    assert ds["env_args"]["type"] == 2 and ds["env_args"]["env_name"] == "rpg/BlockTask-v0"
    assert ds["env_args"]["env_kwargs"]["embodiment"] == "floating_gripper"
    assert list(ds["demos"]) == ["demo_0", "demo_1"] and ds["total"] == sum(d["n"] for d in ds["demos"].values())
    assert ds["masks"] == {"stack_two_blocks_on_top_each_other": ["demo_0", "demo_1"], "train": ["demo_0", "demo_1"],
                           "valid": [], "failed": []}
    for d in ds["demos"].values():
        n = d["n"]
        assert d["actions"].shape == (n, 7) and d["actions"].dtype == np.float32 and np.abs(d["actions"]).max() <= 1
        assert d["rewards"].shape == (n,) and d["rewards"][-1] == 1.0 and d["dones"].tolist() == [0] * (n - 1) + [1]
        assert d["states"].shape[0] == n
        assert sorted(d["obs"]) == sorted(d["next_obs"]) == sorted(
            ["agentview_image", "robot0_eye_in_hand_image", "robot0_eef_pos", "robot0_eef_quat",
             "robot0_gripper_qpos", "robot0_hand_pos", "robot0_hand_quat", "object"])  # a free joint: no joint_pos
        assert d["obs"]["agentview_image"].shape == (n, 32, 32, 3) and d["obs"]["agentview_image"].dtype == np.uint8
        for k, v in d["obs"].items():  # next_obs is obs one step later
            assert len(v) == len(d["next_obs"][k]) == n
            assert np.array_equal(v[1:], d["next_obs"][k][:-1]), k
        assert np.allclose(np.linalg.norm(d["obs"]["robot0_eef_quat"], axis=1), 1.0)
        assert d["obs"]["object"].shape == (n, 14)  # two cubes, position + quaternion
    assert not np.array_equal(ds["demos"]["demo_0"]["states"][0], ds["demos"]["demo_1"]["states"][0])
    r = _rpg("demos", "--replay", out / "demo.hdf5")
    assert r.returncode == 0 and "replayed 2 episodes, 0 mismatched" in r.stdout, r.stdout + r.stderr


def test_hdf5_replay_detects_a_changed_action_and_formats_do_not_mix(tmp_path):
    import h5py

    out = tmp_path / "ds"
    assert _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "", "--format", "hdf5").returncode == 0
    with h5py.File(out / "demo.hdf5", "r+") as f:
        f["data/demo_0/actions"][5:15, 0] = 1.0
    r = _rpg("demos", "--replay", out)
    assert r.returncode == 1 and "MISMATCH" in r.stdout
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "")  # a LeRobot run into it
    assert r.returncode == 2 and "robomimic" in r.stderr and not (out / "meta" / "info.json").exists()


def test_hdf5_run_killed_mid_way_resumes_keeping_finished_episodes(tmp_path):
    out = tmp_path / "ds"
    args = ["demos", STACK, "--embodiment", "floating_gripper", "--out", str(out), "-n", "4", "--image-size", "32", "--format", "hdf5"]
    log = out / "meta" / "episodes.jsonl"
    kept = _kill_after_first_episode(args, out)
    assert 1 <= len(kept) < 4 and (out / "parts" / "demo_0.hdf5").is_file()
    torn = out / "parts" / "demo_9.hdf5"  # a part written but never committed
    torn.write_bytes(b"\x89HDF torn")
    r = _rpg(*args)
    assert r.returncode == 0, r.stderr
    assert [e["episode_index"] for e in _lines(log)] == [0, 1, 2, 3] and not torn.exists()
    ds = _read_like_robomimic(out / "demo.hdf5")
    assert sorted(d["seed"] for d in ds["demos"].values()) == [0, 1, 2, 3]
    assert _rpg("demos", "--replay", out).returncode == 0
    r = _rpg(*args[:-2])  # the same directory as LeRobot: refused, nothing written
    assert r.returncode == 2 and not (out / "meta" / "info.json").exists()
