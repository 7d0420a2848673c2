"""rpg demos' dataset formats: LeRobot v3.0 (the default) read back file by file against its
documented layout and loaded by the real ``lerobot`` where it is installed, crash safety of
its concatenated files (kill -9, torn writes), the keyframe interval, the orientation in
``observation.state``, the optional columns and --keep-failed, and robomimic's metadata
(rebuilding the environment, train/valid masks, joint fields, finger signs)."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

ROOT = Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "library"
STACK = str(LIBRARY / "stack_blocks")
CAMERAS = ("observation.images.agentview", "observation.images.wrist")
FPS = 20


def _rpg(*args, **kw):
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    return subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, args)], capture_output=True, text=True,
                          env=env, timeout=600, **kw)


def _demos(out: Path, *extra) -> None:
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "--image-size", "32", *extra)
    assert r.returncode == 0, r.stdout + r.stderr


def _rows(root: Path) -> list[dict]:
    return [r for f in sorted((root / "meta" / "episodes").glob("chunk-*/file-*.parquet"))
            for r in pq.read_table(f).to_pylist()]


def _frames(root: Path) -> pa.Table:
    return pa.concat_tables([pq.read_table(f) for f in sorted((root / "data").glob("chunk-*/file-*.parquet"))])


def check_v3_layout(root: Path) -> list[dict]:
    """Read every file of a LeRobot v3.0 dataset and check it against the documented layout;
    the episode rows."""
    from rpg.demos import mp4

    info = json.loads((root / "meta" / "info.json").read_text())
    assert info["codebase_version"] == "v3.0" and info["fps"] == FPS and type(info["fps"]) is int
    assert info["data_path"] == "data/chunk-{chunk_index:03d}/file-{file_index:03d}.parquet"
    feats = info["features"]
    videos = [k for k, f in feats.items() if f["dtype"] == "video"]
    assert info["video_path"] == ("videos/{video_key}/chunk-{chunk_index:03d}/file-{file_index:03d}.mp4" if videos else None)
    assert info["chunks_size"] > 0 and info["data_files_size_in_mb"] > 0 and info["video_files_size_in_mb"] > 0
    rows = _rows(root)
    n = len(rows)
    assert info["total_episodes"] == n and info["splits"] == {"train": f"0:{n}"}
    assert [r["episode_index"] for r in rows] == list(range(n))
    # tasks: the task string is the index, task_index a column (pandas' layout)
    tasks = pq.read_table(root / "meta" / "tasks.parquet")
    assert json.loads(tasks.schema.metadata[b"pandas"])["index_columns"] == ["task"]
    task_index = dict(zip(tasks.column("task").to_pylist(), tasks.column("task_index").to_pylist(), strict=True))
    assert sorted(task_index.values()) == list(range(len(task_index))) == list(range(info["total_tasks"]))
    # episodes: contiguous index ranges, lengths, per-episode stats columns
    start = 0
    for r in rows:
        assert r["dataset_from_index"] == start and r["dataset_to_index"] == start + r["length"] and r["length"] > 0
        start += r["length"]
        assert r["tasks"] == [r["instruction"]] and r["tasks"][0] in task_index
        for name in feats:
            for s in ("min", "max", "mean", "std"):
                assert f"stats/{name}/{s}" in r, name
            assert r[f"stats/{name}/count"] == [r["length"]]
    assert info["total_frames"] == start
    # data: every frame once, in order, columns as the features say
    frames = _frames(root)
    assert sorted(frames.column_names) == sorted(k for k, f in feats.items() if f["dtype"] != "video")
    assert frames.num_rows == start and frames.column("index").to_pylist() == list(range(start))
    for r in rows:
        part = frames.slice(r["dataset_from_index"], r["length"])
        assert set(part.column("episode_index").to_pylist()) == {r["episode_index"]}
        assert part.column("frame_index").to_pylist() == list(range(r["length"]))
        assert np.allclose(part.column("timestamp").to_numpy(), np.arange(r["length"]) / FPS)
        assert set(part.column("task_index").to_pylist()) == {task_index[r["tasks"][0]]}
        data = root / info["data_path"].format(chunk_index=r["data/chunk_index"], file_index=r["data/file_index"])
        assert r["episode_index"] in pq.read_table(data, columns=["episode_index"]).column("episode_index").to_pylist()
        state = np.array(part.column("observation.state").to_pylist())
        assert np.allclose(r["stats/observation.state/min"], state.min(0), atol=1e-6)
        assert np.allclose(r["stats/observation.state/mean"], state.mean(0), atol=1e-5)
    for name, f in feats.items():
        if f["dtype"] != "video" and f["shape"] != [1]:
            assert all(len(v) == f["shape"][0] for v in frames.column(name).to_pylist()), name
    # stats.json: the episodes' stats aggregated
    stats = json.loads((root / "meta" / "stats.json").read_text())
    state = np.array(frames.column("observation.state").to_pylist())
    assert stats["observation.state"]["count"] == [start]
    assert np.allclose(stats["observation.state"]["min"], state.min(0), atol=1e-6)
    assert np.allclose(stats["observation.state"]["mean"], state.mean(0), atol=1e-5)
    assert np.allclose(stats["observation.state"]["std"], state.std(0), atol=1e-5)
    # videos: each file holds its episodes back to back, timestamps without gaps
    for key in videos:
        files: dict[tuple, list[dict]] = {}
        for r in rows:
            files.setdefault((r[f"videos/{key}/chunk_index"], r[f"videos/{key}/file_index"]), []).append(r)
        on_disk = sorted((root / "videos" / key).glob("chunk-*/file-*.mp4"))
        assert len(on_disk) == len(files)
        for (chunk, file), members in files.items():
            path = root / info["video_path"].format(video_key=key, chunk_index=chunk, file_index=file)
            t = 0.0
            for r in members:
                assert r[f"videos/{key}/from_timestamp"] == pytest.approx(t)
                t = r[f"videos/{key}/to_timestamp"]
                assert t == pytest.approx(r[f"videos/{key}/from_timestamp"] + r["length"] / FPS)
            assert mp4.frame_count(path) == round(t * FPS)
    return rows


@pytest.fixture(scope="module")
def datasets(tmp_path_factory) -> dict[str, Path]:
    """The same three floating-gripper episodes (seeds 0-2, 32x32 cameras) as LeRobot v3.0 (the
    default) and v2.1."""
    base = tmp_path_factory.mktemp("datasets")
    _demos(base / "v3", "-n", "3")
    _demos(base / "v21", "-n", "3", "--format", "lerobot-v2.1")
    return {"v3": base / "v3", "v21": base / "v21"}


def test_v3_is_the_documented_layout_and_matches_v21_frame_for_frame(datasets):
    from rpg.demos import mp4

    v3, v21 = datasets["v3"], datasets["v21"]
    rows = check_v3_layout(v3)
    assert len(rows) == 3 and sorted(r["seed"] for r in rows) == [0, 1, 2]
    assert all(r["data/file_index"] == 0 and r["videos/observation.images.wrist/file_index"] == 0 for r in rows)
    old = [json.loads(x) for x in (v21 / "meta" / "episodes.jsonl").read_text().splitlines()]
    frames = _frames(v3)
    info21 = json.loads((v21 / "meta" / "info.json").read_text())
    for r, o in zip(rows, old, strict=True):
        assert (r["seed"], r["length"], r["task_hash"]) == (o["seed"], o["length"], o["task_hash"])
        assert json.loads(r["final_poses"]) == o["final_poses"]
        table21 = pq.read_table(v21 / info21["data_path"].format(episode_chunk=0, episode_index=o["episode_index"]))
        assert frames.slice(r["dataset_from_index"], r["length"]).equals(table21)
        for key in CAMERAS:
            path = v3 / "videos" / key / "chunk-000" / "file-000.mp4"
            own = mp4.read_frames(v21 / info21["video_path"].format(episode_chunk=0, video_key=key,
                                                                    episode_index=o["episode_index"]))
            assert len(own) == r["length"]
            for t in sorted({0, 1, r["length"] // 2, r["length"] - 1}):  # seek as a loader does
                frame, _ = mp4.read_frame_at(path, r[f"videos/{key}/from_timestamp"] + t / FPS)
                assert np.array_equal(frame, own[t]), (key, r["episode_index"], t)
    for key in CAMERAS:  # the concatenated file is the episodes' files back to back, bit for bit
        whole = mp4.read_frames(v3 / "videos" / key / "chunk-000" / "file-000.mp4")
        parts = [f for o in old for f in mp4.read_frames(
            v21 / info21["video_path"].format(episode_chunk=0, video_key=key, episode_index=o["episode_index"]))]
        assert len(whole) == len(parts) and all(np.array_equal(a, b) for a, b in zip(whole, parts, strict=True))
    r = _rpg("demos", "--replay", v3)
    assert r.returncode == 0 and "replayed 3 episodes, 0 mismatched" in r.stdout, r.stdout + r.stderr


@pytest.fixture(scope="module")  # module-scoped: it skips before the datasets fixture is built
def lerobot_python() -> str:
    """An interpreter that imports lerobot: $RPG_LEROBOT_PYTHON, else this one if it can (else skip)."""
    chosen = os.environ.get("RPG_LEROBOT_PYTHON") or sys.executable
    r = subprocess.run([chosen, "-c", "import lerobot.datasets.lerobot_dataset"], capture_output=True, timeout=300)
    if r.returncode:
        pytest.skip("lerobot is not importable here (set RPG_LEROBOT_PYTHON to an interpreter with lerobot 0.4)")
    return chosen


_LOAD = r'''
import json, sys
import numpy as np
import pyarrow.parquet as pq
from lerobot.datasets.lerobot_dataset import LeRobotDataset
root, expect = sys.argv[1], json.load(open(sys.argv[2]))
ds = LeRobotDataset("rpg/stack_blocks", root=root, video_backend="pyav",
                    delta_timestamps={"action": [t / 20 for t in range(4)]})
assert len(ds) == expect["frames"] and ds.num_episodes == expect["episodes"] and ds.fps == 20, (len(ds), ds.num_episodes)
assert ds.meta.info["rpg_visual"] == "decimated"
data = pq.read_table(expect["data"]).to_pydict()
for i in expect["indices"]:
    item = ds[i]
    assert item["task"] == expect["task"], item["task"]
    assert np.allclose(item["observation.state"].numpy(), data["observation.state"][i])
    assert item["action"].shape == (4, 7) and np.allclose(item["action"][0].numpy(), data["action"][i])
    for key, frame in expect["images"][str(i)].items():
        got = (item[key].numpy().transpose(1, 2, 0) * 255).round().astype(np.uint8)
        assert np.array_equal(got, np.array(frame, np.uint8)), (i, key)
print("loaded", len(ds))
'''


def test_the_lerobot_package_loads_a_dataset_written_with_the_defaults(lerobot_python, datasets, tmp_path):
    """lerobot 0.4 (LeRobotDataset, PyAV decoding) reads every checked frame as written.  lerobot
    pins torch < 2.11 and torchvision's video reader, which the project's environment does not
    have: point RPG_LEROBOT_PYTHON at an interpreter that has lerobot."""
    from rpg.demos import mp4

    python = lerobot_python
    root = datasets["v3"]
    rows = _rows(root)
    total = rows[-1]["dataset_to_index"]
    indices = sorted({0, 1, rows[0]["length"] - 1, rows[1]["dataset_from_index"], rows[1]["dataset_from_index"] + 7,
                      total - 1})
    images = {}
    for i in indices:
        r = next(x for x in rows if x["dataset_from_index"] <= i < x["dataset_to_index"])
        t = i - r["dataset_from_index"]
        images[str(i)] = {k: mp4.read_frame_at(root / "videos" / k / "chunk-000" / "file-000.mp4",
                                               r[f"videos/{k}/from_timestamp"] + t / FPS)[0].tolist() for k in CAMERAS}
    expect = {"frames": total, "episodes": len(rows), "task": rows[0]["tasks"][0], "indices": indices,
              "data": str(root / "data" / "chunk-000" / "file-000.parquet"), "images": images}
    (tmp_path / "expect.json").write_text(json.dumps(expect))
    r = subprocess.run([python, "-c", _LOAD, str(root), str(tmp_path / "expect.json")], capture_output=True, text=True,
                       timeout=600, env=dict(os.environ, HF_HUB_OFFLINE="1"))
    assert r.returncode == 0 and f"loaded {total}" in r.stdout, r.stdout[-2000:] + r.stderr[-4000:]


def test_small_files_roll_over_into_new_files_and_chunks(tmp_path):
    from rpg.demos import collect_demos, mp4

    out = tmp_path / "ds"
    summary = collect_demos(STACK, out, episodes=3, embodiment="floating_gripper", image_size=(32, 32),
                            data_files_size_in_mb=1e-6, video_files_size_in_mb=1e-6, chunks_size=2)
    assert summary["episodes"] == 3
    rows = check_v3_layout(out)
    assert [(r["data/chunk_index"], r["data/file_index"]) for r in rows] == [(0, 0), (0, 1), (1, 0)]
    for key in CAMERAS:
        assert [(r[f"videos/{key}/chunk_index"], r[f"videos/{key}/file_index"]) for r in rows] == [(0, 0), (0, 1), (1, 0)]
        assert all(r[f"videos/{key}/from_timestamp"] == 0 for r in rows)
    assert (out / "data" / "chunk-001" / "file-000.parquet").is_file()
    assert mp4.frame_count(out / "videos" / CAMERAS[0] / "chunk-001" / "file-000.mp4") == rows[2]["length"]
    assert json.loads((out / "meta" / "info.json").read_text())["chunks_size"] == 2
    from rpg.demos import replay_dataset

    assert [x.ok for x in replay_dataset(out, library=LIBRARY)] == [True] * 3


def _same_episodes(a: Path, b: Path, n: int) -> None:
    """The first ``n`` episodes of two v3.0 datasets hold the same frames, data and video."""
    from rpg.demos import mp4

    ra, rb = _rows(a)[:n], _rows(b)[:n]
    assert [(r["seed"], r["length"]) for r in ra] == [(r["seed"], r["length"]) for r in rb]
    end = ra[-1]["dataset_to_index"]
    assert _frames(a).slice(0, end).equals(_frames(b).slice(0, end))
    for key in CAMERAS:
        fa = mp4.read_frames(a / "videos" / key / "chunk-000" / "file-000.mp4")[:end]
        fb = mp4.read_frames(b / "videos" / key / "chunk-000" / "file-000.mp4")[:end]
        assert len(fa) == len(fb) == end and all(np.array_equal(x, y) for x, y in zip(fa, fb, strict=True))


def test_a_run_killed_mid_way_resumes_from_its_last_committed_episode(datasets, tmp_path):
    out = tmp_path / "ds"
    args = [sys.executable, "-m", "rpg.cli", "demos", STACK, "--embodiment", "floating_gripper", "--out", str(out),
            "-n", "3", "--image-size", "32"]
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    for delay in (0.0, 0.15):  # right at the first commit, then a little into the second episode's writes
        proc = subprocess.Popen(args, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.time() + 300
        first = out / "meta" / "episodes" / "chunk-000" / "file-000.parquet"
        while time.time() < deadline and proc.poll() is None and not first.is_file():
            time.sleep(0.01)
        time.sleep(delay)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        assert 1 <= len(_rows(out)) <= 3
    r = _rpg(*args[3:])
    assert r.returncode == 0, r.stderr
    rows = check_v3_layout(out)
    assert sorted(r["seed"] for r in rows) == [0, 1, 2]
    assert not list(out.rglob(".*.tmp-*")) and not (out / ".staging").exists()
    _same_episodes(out, datasets["v3"], 3)


def test_frames_past_the_last_commit_are_cut_back_on_open(datasets, tmp_path):
    """What a kill between an episode's data and video writes and its commit leaves: files with
    its frames but no row for it, and a temporary file.  Opening cuts them back; the rerun then
    writes the same dataset as an uninterrupted run."""
    from rpg.demos import mp4
    from rpg.demos.layout import Layout
    from rpg.demos.lerobot3 import LeRobotV3Writer

    out = tmp_path / "ds"
    shutil.copytree(datasets["v3"], out)
    meta = out / "meta" / "episodes" / "chunk-000" / "file-000.parquet"
    pq.write_table(pq.read_table(meta).slice(0, 2), meta)  # episode 2's row never committed
    attempts = out / "meta" / "rpg_attempts.jsonl"  # its attempt was logged (that comes before the commit)
    assert len(attempts.read_text().splitlines()) == 3
    torn = out / "data" / "chunk-000" / ".file-000.parquet.tmp-123"
    torn.write_bytes(b"PAR1 torn")
    rows = _rows(out)
    writer = LeRobotV3Writer(out, Layout("floating_gripper", ("agentview", "wrist"), (32, 32),
                                         objects=("blue", "red")))
    writer.open()
    kept = rows[-1]["dataset_to_index"]
    assert not torn.exists() and pq.read_metadata(out / "data" / "chunk-000" / "file-000.parquet").num_rows == kept
    for key in CAMERAS:
        assert mp4.frame_count(out / "videos" / key / "chunk-000" / "file-000.mp4") == kept
    assert json.loads((out / "meta" / "info.json").read_text())["total_frames"] == kept
    check_v3_layout(out)
    _demos(out, "-n", "3")
    _same_episodes(out, datasets["v3"], 3)
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--format", "lerobot-v2.1")
    assert r.returncode == 2 and "v3.0 dataset" in r.stderr


def test_videos_have_a_keyframe_every_gop_frames(datasets, tmp_path):
    from rpg.demos import mp4

    root = datasets["v3"]
    rows = _rows(root)
    for key in CAMERAS:
        path = root / "videos" / key / "chunk-000" / "file-000.mp4"
        keys = mp4.keyframes(path)
        assert max(np.diff(keys + [mp4.frame_count(path)])) <= 2  # LeRobot's default g=2
        assert {round(r[f"videos/{key}/from_timestamp"] * FPS) for r in rows} <= set(keys)  # episodes start on one
        for t in range(0, rows[0]["length"], 5):
            assert mp4.read_frame_at(path, t / FPS)[1] <= 2  # frames decoded to reach frame t
    out = tmp_path / "gop5"
    _demos(out, "-n", "1", "--gop", "5", "--cameras", "wrist")
    path = out / "videos" / CAMERAS[1] / "chunk-000" / "file-000.mp4"
    gaps = np.diff(mp4.keyframes(path) + [mp4.frame_count(path)])
    assert gaps.max() <= 5 and gaps.max() > 2
    info = json.loads((out / "meta" / "info.json").read_text())
    assert info["features"][CAMERAS[1]]["info"]["video.g"] == 5
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "-n", "1", "--cameras", "wrist",
             "--image-size", "32")  # another keyframe interval into the same dataset: refused
    assert r.returncode == 2 and "keyframe interval" in r.stderr


# -- observation.state -----------------------------------------------------------------------
@pytest.fixture(scope="module")
def panda_episode():
    from rpg.demos.record import record_episode

    ep = record_episode(STACK, 0, "panda", cameras=(), frames="hdf5")
    assert ep.success
    return ep


def _axis_angle(rot6: np.ndarray) -> np.ndarray:
    """The environment's axis-angle orientation of a row of 6D rotations."""
    import mujoco

    from rpg.env.embodiments.base import quat_to_axis_angle

    out = []
    for r in rot6:
        x, y = r[:3], r[3:]
        m = np.stack([x, y, np.cross(x, y)], axis=1)
        q = np.zeros(4)
        mujoco.mju_mat2Quat(q, m.reshape(-1))
        out.append(quat_to_axis_angle(q))
    return np.array(out)


@pytest.mark.parametrize("robot", ["panda", "floating_gripper"])
def test_the_state_has_no_jumps_between_frames(robot, panda_episode, datasets):
    from rpg.demos.record import STATE_NAMES, record_episode

    ep = panda_episode if robot == "panda" else record_episode(STACK, 0, robot, cameras=())
    states = ep.states
    assert states.shape == (ep.length, 11) and len(STATE_NAMES) == 11
    assert np.abs(np.diff(states, axis=0)).max() < 1.0  # rad or m between consecutive frames
    rot = states[:, 3:9]
    assert np.allclose(np.linalg.norm(rot[:, :3], axis=1), 1, atol=1e-5)
    assert np.allclose((rot[:, :3] * rot[:, 3:]).sum(1), 0, atol=1e-5)
    if robot == "floating_gripper":  # the axis-angle it replaces wraps by 2 pi in this very episode
        assert np.abs(np.diff(_axis_angle(rot), axis=0)).max() > 6.0
        info = json.loads((datasets["v3"] / "meta" / "info.json").read_text())
        assert info["features"]["observation.state"]["names"] == STATE_NAMES


def test_the_dataset_state_is_what_a_policy_computes_from_the_environment():
    from rpg.demos.record import dataset_state, record_episode
    from rpg.env import BlockTaskEnv

    ep = record_episode(STACK, 1, "floating_gripper", cameras=(), max_steps=5)
    env = BlockTaskEnv(STACK, embodiment="floating_gripper", cameras=())
    try:
        obs, _ = env.reset(seed=1)
        assert np.allclose(dataset_state(obs["state"]), ep.states[0], atol=1e-6)
        obs, *_ = env.step(ep.actions[0])
        assert np.allclose(dataset_state(obs["state"]), ep.states[1], atol=1e-6)
        assert np.allclose(obs["qpos"], ep.joint_pos[1], atol=1e-6)
    finally:
        env.close()


# -- optional columns, --keep-failed ---------------------------------------------------------------
def test_optional_columns_hold_joints_objects_and_success(datasets, tmp_path):
    info = json.loads((datasets["v3"] / "meta" / "info.json").read_text())
    feats = info["features"]
    assert feats["observation.joint_pos"]["names"][:3] == ["hand_x", "hand_y", "hand_z"]
    assert feats["observation.object_poses"]["names"][:8] == ["blue.x", "blue.y", "blue.z", "blue.qw", "blue.qx",
                                                              "blue.qy", "blue.qz", "red.x"]
    assert feats["next.success"]["dtype"] == feats["next.done"]["dtype"] == "bool"
    frames = _frames(datasets["v3"])
    rows = _rows(datasets["v3"])
    for r in rows:
        part = frames.slice(r["dataset_from_index"], r["length"]).to_pydict()
        done = part["next.done"]
        assert done == [False] * (r["length"] - 1) + [True]
        assert part["next.success"][-1] and not part["next.success"][0] and part["next.reward"][-1] == 1.0
        poses = np.array(part["observation.object_poses"])
        assert np.allclose(np.linalg.norm(poses[:, 3:7], axis=1), 1, atol=1e-5)
        final = json.loads(r["final_poses"])
        assert r["object_names"] == sorted(final)
        assert np.abs(poses[-1, 7:10] - final["red"][:3]).max() < 0.05  # slot 1: red, sorted after blue
        joints = np.array(part["observation.joint_pos"])
        assert np.allclose(joints[:, 7:9], np.array(part["observation.state"])[:, 9:11], atol=1e-6)
    out = tmp_path / "bare"
    _demos(out, "-n", "1", "--cameras", "", "--columns", "")
    names = set(json.loads((out / "meta" / "info.json").read_text())["features"])
    assert names == {"observation.state", "action", "timestamp", "frame_index", "episode_index", "index", "task_index"}
    check_v3_layout(out)


@pytest.mark.parametrize("fmt", ["lerobot", "lerobot-v2.1", "hdf5"])
def test_keep_failed_commits_failed_episodes_marked_and_replayable(fmt, tmp_path):
    from rpg.demos import replay_dataset
    from rpg.demos.collect import make_writer
    from rpg.demos.layout import Layout
    from rpg.demos.record import record_episode

    out = tmp_path / "ds"
    layout = Layout("floating_gripper", ("wrist",), (32, 32), objects=("blue", "red"))
    writer = make_writer(fmt, out, layout, keep_failed=True)
    writer.open()
    frames = "hdf5" if fmt == "hdf5" else "mp4"
    failed = record_episode(STACK, 0, "floating_gripper", ("wrist",), (32, 32), video_dir=tmp_path / "a",
                            max_steps=8, frames=frames)
    good = record_episode(STACK, 1, "floating_gripper", ("wrist",), (32, 32), video_dir=tmp_path / "b", frames=frames)
    assert not failed.success and good.success
    assert writer.add(failed) == 0 and writer.add(good) == 1
    if fmt == "hdf5":
        writer.finalize()
        import h5py

        with h5py.File(out / "demo.hdf5") as f:
            assert f["data/demo_0"].attrs["success"] == 0 and f["data/demo_1"].attrs["success"] == 1
            assert [x.decode() for x in f["mask/failed"][()]] == ["demo_0"]
            assert [x.decode() for x in f["mask/train"][()]] == ["demo_1"]
    else:
        records = _rows(out) if fmt == "lerobot" else [json.loads(x) for x in
                                                        (out / "meta" / "episodes.jsonl").read_text().splitlines()]
        assert [r["success"] for r in records] == [False, True]
        if fmt == "lerobot":
            check_v3_layout(out)
            part = _frames(out).slice(0, failed.length).to_pydict()
            assert not any(part["next.success"]) and part["next.done"][-1]
    results = replay_dataset(out, library=LIBRARY)
    assert [(x.ok, x.success, x.recorded_success) for x in results] == [(True, False, False), (True, True, True)]


# -- robomimic ---------------------------------------------------------------------------------
def test_robomimic_metadata_rebuilds_the_environment_and_splits_train_valid(tmp_path):
    import h5py
    import mujoco

    from rpg.demos.robomimic import make_env_from_metadata
    from rpg.errors import BadInput

    out = tmp_path / "ds"
    _demos(out, "-n", "2", "--cameras", "", "--format", "hdf5")
    with h5py.File(out / "demo.hdf5") as f:
        args = json.loads(f["data"].attrs["env_args"])
        demo = f["data/demo_1"]
        seed, states, actions = int(demo.attrs["seed"]), demo["states"][()], demo["actions"][()]
        final = json.loads(demo.attrs["final_poses"])
        gripper = demo["obs/robot0_gripper_qpos"][()]
        hand = demo["obs/robot0_hand_pos"][()]
        assert "robot0_joint_pos" not in demo["obs"] and demo["obs/robot0_hand_quat"].shape == (len(actions), 4)
        masks = {k: [x.decode() for x in f["mask"][k][()]] for k in f["mask"]}
    kw = args["env_kwargs"]
    assert kw["task"] == "stack_blocks" and len(kw["task_hash"]) == 64 and kw["embodiment"] == "floating_gripper"
    assert masks["train"] == ["demo_0", "demo_1"] and masks["valid"] == [] == masks["failed"]
    assert np.allclose(gripper[0], [0.04, -0.04])  # robosuite's PandaGripper: open at (+0.04, -0.04)
    assert (gripper[:, 0] >= -1e-4).all() and (gripper[:, 1] <= 1e-4).all() and gripper[:, 0].min() < 0.03
    env = make_env_from_metadata(out, library=LIBRARY, demo=1)
    try:
        env.reset(seed=seed)
        now = np.empty(mujoco.mj_stateSize(env.model, mujoco.mjtState.mjSTATE_FULLPHYSICS))
        mujoco.mj_getState(env.model, env.data, now, mujoco.mjtState.mjSTATE_FULLPHYSICS)
        assert np.array_equal(now, states[0])  # the demo's first state, exactly
        assert np.allclose(env.robot.robot_qpos()[:3], hand[0])
        for a in actions:
            *_, info = env.step(a)
        assert info["success"]  # and on to where it ended
        for name, pose in env.scene.poses().items():
            assert np.abs(np.array([*pose.pos, *pose.quat]) - final[name]).max() < 1e-6
    finally:
        env.close()
    other = tmp_path / "lib"
    (other / "block_alignment").parent.mkdir(parents=True)
    shutil.copytree(LIBRARY / "block_alignment", other / "block_alignment")
    with pytest.raises(BadInput, match="no task in .* has content hash"):
        make_env_from_metadata(out, library=other)


def test_robomimic_env_kwargs_rebuild_the_same_visual_cameras_and_image_size(tmp_path):
    """A non-default ``--visual stock``, one camera and a non-default size: ``env_kwargs`` records
    every one, and the rebuilt environment's first observation is the recorded first frame
    byte for byte (the decimated meshes' frame differs)."""
    import h5py

    from rpg.demos.robomimic import ENV_KEYWORDS, make_env_from_metadata
    from rpg.env import BlockTaskEnv

    out = tmp_path / "ds"
    _demos(out, "-n", "1", "--cameras", "agentview", "--image-size", "40", "--format", "hdf5", "--visual", "stock")
    with h5py.File(out / "demo.hdf5") as f:
        kw = json.loads(f["data"].attrs["env_args"])["env_kwargs"]
        seed = int(f["data/demo_0"].attrs["seed"])
        first = f["data/demo_0/obs/agentview_image"][0]
    assert set(ENV_KEYWORDS) <= set(kw)
    assert (kw["visual"], kw["cameras"], kw["image_size"], kw["embodiment"]) == \
        ("stock", ["agentview"], [40, 40], "floating_gripper")
    assert (kw["privileged"], kw["terminate_on_success"], kw["max_episode_steps"]) == (False, True, None)
    env = make_env_from_metadata(out, library=LIBRARY)
    try:
        assert (env.robot.visual, env.cameras, env.image_size) == ("stock", ("agentview",), (40, 40))
        obs, _ = env.reset(seed=seed)
        assert set(k for k in obs if k.endswith("_image")) == {"agentview_image"}
        assert np.array_equal(obs["agentview_image"], first)
    finally:
        env.close()
    decimated = BlockTaskEnv(STACK, embodiment="floating_gripper", cameras=("agentview",), image_size=(40, 40))
    try:
        assert not np.array_equal(decimated.reset(seed=seed)[0]["agentview_image"], first)
    finally:
        decimated.close()
    # resuming with other meshes is refused
    r = _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", out, "--image-size", "40", "--cameras",
             "agentview", "--format", "hdf5", "-n", "2")
    assert r.returncode == 2 and "visual" in r.stderr and "Traceback" not in r.stderr
    r = _rpg("demos", STACK, "--out", tmp_path / "bad", "--format", "hdf5", "--visual", "fine")
    assert r.returncode == 2 and "decimated, stock" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.parametrize("fmt", ["lerobot", "lerobot-v2.1"])
def test_lerobot_info_records_the_visual_and_rebuilds_its_environment(fmt, datasets, tmp_path):
    """``--visual stock`` with a LeRobot format: ``meta/info.json`` records it (``rpg_visual``;
    the defaults' datasets say ``decimated``), an environment built from info.json renders the
    recorded first frame (closer to it than the other meshes' render, the video being lossy),
    and resuming with the other meshes is one line, exit 2."""
    from rpg.demos import mp4
    from rpg.demos.layout import SUPERSAMPLE_KEY, VISUAL_KEY, recorded_visual
    from rpg.env import BlockTaskEnv

    for name in ("v3", "v21"):
        assert json.loads((datasets[name] / "meta" / "info.json").read_text())[VISUAL_KEY] == "decimated"
        assert json.loads((datasets[name] / "meta" / "info.json").read_text())[SUPERSAMPLE_KEY] == 1
    out = tmp_path / "ds"
    args = ("--embodiment", "panda", "-n", "1", "--cameras", "agentview", "--columns", "", "--format", fmt)
    r = _rpg("demos", STACK, "--out", out, "--image-size", "64", *args, "--visual", "stock")
    assert r.returncode == 0, r.stdout + r.stderr
    info = json.loads((out / "meta" / "info.json").read_text())
    assert info[VISUAL_KEY] == recorded_visual(info) == "stock" and info["robot_type"] == "panda"
    if fmt == "lerobot":
        seed = _rows(out)[0]["seed"]
        video = out / "videos" / "observation.images.agentview" / "chunk-000" / "file-000.mp4"
    else:
        seed = json.loads((out / "meta" / "episodes.jsonl").read_text().splitlines()[0])["seed"]
        video = out / "videos" / "chunk-000" / "observation.images.agentview" / "episode_000000.mp4"
    first = mp4.read_frames(video)[0].astype(float)
    errors = {}
    for visual in (recorded_visual(info), "decimated"):
        h, w, _ = info["features"]["observation.images.agentview"]["shape"]
        env = BlockTaskEnv(STACK, embodiment=info["robot_type"], cameras=("agentview",), image_size=(h, w),
                           visual=visual)
        try:
            assert env.robot.visual == visual
            errors[visual] = np.abs(env.reset(seed=seed)[0]["agentview_image"] - first).mean()
        finally:
            env.close()
    assert errors["stock"] < errors["decimated"], errors
    r = _rpg("demos", STACK, "--out", out, "--image-size", "64", *args)
    assert r.returncode == 2 and "--visual stock" in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr


@pytest.mark.parametrize("backend", ["local", "ray"])
def test_robomimic_env_kwargs_rebuild_the_wrist_supersample_of_either_backend(backend, tmp_path):
    """``rpg demos --wrist-supersample 2`` on the process pool and on Ray: the recorded wrist
    frames are those of a supersampled environment (the rebuilt environment's first frame
    equals the recorded one byte for byte; an environment without supersampling draws another),
    ``env_kwargs`` records the factor and :func:`make_env_from_metadata` passes it back; resuming
    without it is one line, exit 2."""
    import h5py

    from rpg.demos.robomimic import make_env_from_metadata
    from rpg.env import BlockTaskEnv

    if backend == "ray":
        pytest.importorskip("ray", reason="Ray is not installed: the ray backend cannot be tested")
    out = tmp_path / "ds"
    args = ("--embodiment", "floating_gripper", "-n", "1", "--cameras", "wrist", "--image-size", "32", "--format", "hdf5",
            "--backend", backend)
    r = _rpg("demos", STACK, "--out", out, *args, "--wrist-supersample", "2")
    assert r.returncode == 0, r.stdout + r.stderr
    with h5py.File(out / "demo.hdf5") as f:
        kw = json.loads(f["data"].attrs["env_args"])["env_kwargs"]
        seed = int(f["data/demo_0"].attrs["seed"])
        first = f["data/demo_0/obs/robot0_eye_in_hand_image"][0]
    assert kw["wrist_supersample"] == 2
    env = make_env_from_metadata(out, library=LIBRARY)
    try:
        assert env.wrist_supersample == 2
        assert np.array_equal(env.reset(seed=seed)[0]["wrist_image"], first)
    finally:
        env.close()
    plain = BlockTaskEnv(STACK, embodiment="floating_gripper", cameras=("wrist",), image_size=(32, 32))
    try:
        assert not np.array_equal(plain.reset(seed=seed)[0]["wrist_image"], first)
    finally:
        plain.close()
    r = _rpg("demos", STACK, "--out", out, *args)
    assert r.returncode == 2 and "wrist_supersample" in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr


@pytest.mark.parametrize("fmt", ["lerobot", "lerobot-v2.1"])
def test_lerobot_info_records_the_wrist_supersample_and_rebuilds_its_environment(fmt, tmp_path):
    """``--wrist-supersample 2`` with a LeRobot format: ``meta/info.json`` records it next to
    ``rpg_visual`` (``rpg_wrist_supersample``), an environment built with the recorded factor
    renders the recorded first wrist frame closer than one without supersampling (the video
    being lossy), and resuming without it is one line, exit 2."""
    from rpg.demos import mp4
    from rpg.demos.layout import SUPERSAMPLE_KEY, VISUAL_KEY, recorded_wrist_supersample
    from rpg.env import BlockTaskEnv

    out = tmp_path / "ds"
    args = ("--embodiment", "floating_gripper", "-n", "1", "--cameras", "wrist", "--columns", "", "--format", fmt)
    r = _rpg("demos", STACK, "--out", out, "--image-size", "64", *args, "--wrist-supersample", "2")
    assert r.returncode == 0, r.stdout + r.stderr
    info = json.loads((out / "meta" / "info.json").read_text())
    assert info[SUPERSAMPLE_KEY] == recorded_wrist_supersample(info) == 2 and info[VISUAL_KEY] == "decimated"
    assert recorded_wrist_supersample({}) == 1  # a dataset from before the key
    if fmt == "lerobot":
        seed = _rows(out)[0]["seed"]
        video = out / "videos" / "observation.images.wrist" / "chunk-000" / "file-000.mp4"
    else:
        seed = json.loads((out / "meta" / "episodes.jsonl").read_text().splitlines()[0])["seed"]
        video = out / "videos" / "chunk-000" / "observation.images.wrist" / "episode_000000.mp4"
    first = mp4.read_frames(video)[0].astype(float)
    errors = {}
    for k in (recorded_wrist_supersample(info), 1):
        env = BlockTaskEnv(STACK, embodiment=info["robot_type"], cameras=("wrist",), image_size=(64, 64),
                           wrist_supersample=k)
        try:
            errors[k] = np.abs(env.reset(seed=seed)[0]["wrist_image"] - first).mean()
        finally:
            env.close()
    assert errors[2] < errors[1], errors
    r = _rpg("demos", STACK, "--out", out, "--image-size", "64", *args)
    assert r.returncode == 2 and "--wrist-supersample 2" in r.stderr and len(r.stderr.strip().splitlines()) == 1, \
        r.stderr


def test_train_valid_split_is_every_tenth_successful_demo_per_task():
    from rpg.demos.robomimic import split_train_valid

    records = [{"episode_index": i, "task_hash": "ab"[i % 2], "success": i != 4} for i in range(45)]
    split = split_train_valid(records)
    assert split["failed"] == ["demo_4"]
    assert sorted(split["train"] + split["valid"] + split["failed"], key=lambda d: int(d[5:])) == \
        [f"demo_{i}" for i in range(45)]
    assert split["valid"] == ["demo_19", "demo_20", "demo_39", "demo_40"]  # the 10th and 20th of each task
    assert split_train_valid(records[:30])["valid"] == ["demo_19", "demo_20"]  # growing keeps the split


def test_panda_robomimic_joint_fields_are_robosuites(panda_episode):
    low = panda_episode.low_dim
    assert sorted(low) == ["object", "robot0_eef_pos", "robot0_eef_quat", "robot0_gripper_qpos", "robot0_joint_pos"]
    assert low["robot0_joint_pos"].shape == (panda_episode.length + 1, 7)
    assert np.allclose(low["robot0_gripper_qpos"][0], [0.04, -0.04], atol=1e-3)
    q = low["robot0_eef_quat"]
    assert (np.sum(q[1:] * q[:-1], axis=1) > 0).all()  # its sign never flips between steps


# -- replay reads a v3.0 dataset as a peer's ---------------------------------------------------------
def test_a_v3_dataset_out_of_bounds_is_refused(datasets, tmp_path):
    from rpg.demos import replay_dataset
    from rpg.demos.lerobot3 import read_episode_actions
    from rpg.errors import PeerError

    out = tmp_path / "ds"
    shutil.copytree(datasets["v3"], out)
    rows = _rows(out)
    assert read_episode_actions(out, rows[1]).shape == (rows[1]["length"], 7)
    with pytest.raises(PeerError, match="an episode has 1 to 10 steps"):
        read_episode_actions(out, rows[1], max_steps=10)
    with pytest.raises(PeerError, match="names no data file"):
        read_episode_actions(out, {**rows[1], "data/file_index": "../x"})
    data = out / "data" / "chunk-000" / "file-000.parquet"
    saved = data.read_bytes()
    pq.write_table(pa.table({"action": pa.array([["a"] * 7] * 3), "episode_index": [0, 0, 0]}), data)
    with pytest.raises(PeerError, match="no action column of 7 floats"):
        read_episode_actions(out, rows[0])
    data.unlink()
    (tmp_path / "elsewhere.parquet").write_bytes(saved)
    data.symlink_to(tmp_path / "elsewhere.parquet")
    with pytest.raises(PeerError, match="is a symbolic link"):
        read_episode_actions(out, rows[0])
    data.unlink()
    data.write_bytes(saved)
    meta = out / "meta" / "episodes" / "chunk-000" / "file-000.parquet"
    table = pq.read_table(meta)
    trap = tmp_path / "trap"  # a recorded task path is never loaded: its code would leave a marker
    shutil.copytree(STACK, trap)
    (trap / "code.py").write_text((trap / "code.py").read_text() + f"\nopen({str(tmp_path / 'LOADED')!r}, 'w')\n")
    col = table.schema.get_field_index("task")
    pq.write_table(table.set_column(col, "task", pa.array([str(trap)] * table.num_rows)), meta)
    assert [x.ok for x in replay_dataset(out, library=LIBRARY)] == [True] * 3
    assert not (tmp_path / "LOADED").exists()
    col = table.schema.get_field_index("seed")
    pq.write_table(table.set_column(col, "seed", pa.array([-1] * table.num_rows)), meta)
    with pytest.raises(PeerError, match="seed is not an integer"):
        replay_dataset(out, library=LIBRARY)
