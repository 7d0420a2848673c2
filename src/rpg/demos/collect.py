"""``rpg demos``: oracle demonstrations of tasks as a dataset, and their replay.

:func:`collect_demos` runs the oracle over the seeds of every task of a target and keeps the
successful episodes, ``episodes`` per task (seeds 0, 1, ... are tried in order, at most
:data:`MAX_SEED_FACTOR` x ``episodes`` of them).  Episodes run in ``jobs`` processes and are
committed in (task, seed) order, so the dataset is the same for any number of jobs.
:func:`replay_dataset` re-runs every recorded episode's actions from its seed and checks
that it succeeds again and ends in the recorded state.
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing
import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rpg.demos.lerobot import LeRobotWriter, read_episode_actions
from rpg.demos.record import Episode, close_cached_env, record_episode
from rpg.errors import BadInput
from rpg.jsonl import read_jsonl

MAX_SEED_FACTOR = 3
"""At most this many times ``episodes`` seeds are tried per task."""

FORMATS = ("lerobot", "hdf5")
"""Dataset formats written: LeRobot v2.1 (:mod:`rpg.demos.lerobot`) and robomimic's HDF5
(:mod:`rpg.demos.robomimic`)."""

REPLAY_POSE_TOL = 1e-6
"""Largest difference (m, or quaternion units) between a replay's final poses and the recorded ones."""


def expand_targets(target: str | Path) -> list[str]:
    """The task targets a ``rpg demos`` / ``rpg eval`` target names: a task directory, a family
    (its head) or ``FAMILY@vN``, or a library manifest (every entry, in manifest order).

    Raises:
        BadInput: no such target.
    """
    from rpg.env.loading import resolve_target

    path = Path(str(target))
    if path.is_file() and path.suffix in (".yaml", ".yml"):
        from rpg.library.build import load_manifest

        manifest = load_manifest(path)
        return [str(path.parent / e.name) for e in manifest.entries]
    resolve_target(target)  # raises BadInput with the reason
    return [str(target)]


@dataclass(frozen=True)
class Job:
    task: str
    seed: int
    embodiment: str
    cameras: tuple[str, ...]
    image_size: tuple[int, int]
    instruction: str
    staging: str
    frames: str = "mp4"


def _run(job: Job) -> Episode:
    return record_episode(job.task, job.seed, job.embodiment, job.cameras, job.image_size, job.instruction,
                          video_dir=Path(job.staging) / f"{Path(job.task).name}-{job.seed}", frames=job.frames,
                          reuse_env=True)


def _task_hash(task: str) -> str:
    from rpg.artifact import rehash
    from rpg.env.loading import resolve_target

    return rehash(resolve_target(task))[3]


def collect_demos(target: str | Path, out: str | Path, episodes: int = 10, embodiment: str = "floating_gripper",
                  fmt: str = "lerobot", jobs: int = 1, cameras: tuple[str, ...] = ("agentview", "wrist"),
                  image_size: tuple[int, int] = (256, 256), instruction: str = "canonical",
                  progress: Callable[[Episode, int | None], None] | None = None) -> dict:
    """Record ``episodes`` successful oracle demonstrations per task of ``target`` into ``out``.

    Returns:
        A summary: ``{"episodes": committed in total, "attempts": run now, "per_task":
        {task: {"success": n, "attempts": m}}}``.

    Raises:
        BadInput: unknown target or format, ``episodes`` or ``jobs`` < 1, or ``out`` holds a
            dataset of another kind.
    """
    if fmt not in FORMATS:
        raise BadInput(f"format {fmt!r} is not supported; rpg demos writes {', '.join(FORMATS)}")
    if episodes < 1 or jobs < 1:
        raise BadInput("--episodes and --jobs must be at least 1")
    tasks = expand_targets(target)
    if fmt == "hdf5":
        from rpg.demos.robomimic import RobomimicWriter

        writer = RobomimicWriter(out, cameras, image_size, embodiment)
    else:
        writer = LeRobotWriter(out, cameras, image_size, embodiment)
    writer.open()
    staging = Path(out) / ".staging"
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    hashes = {t: _task_hash(t) for t in tasks}
    per_task = {}
    ran = 0
    pool = None
    if jobs > 1:
        from rpg.validate.isolation import die_with_parent

        pool = cf.ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn"),
                                      initializer=die_with_parent)  # no orphans after a kill
    try:
        for task in tasks:
            made = sum(1 for e in writer.episodes if e["task_hash"] == hashes[task])
            # a kill between an episode's commit line and its attempt line leaves it only in episodes
            tried = [a["seed"] for a in (*writer.attempts, *writer.episodes) if a["task_hash"] == hashes[task]]
            seed = max(tried, default=-1) + 1
            last = MAX_SEED_FACTOR * episodes
            while made < episodes and seed < last:
                batch = [Job(task, s, embodiment, tuple(cameras), tuple(image_size), instruction, str(staging),
                             "hdf5" if fmt == "hdf5" else "mp4")
                         for s in range(seed, min(seed + episodes - made, last))]
                seed += len(batch)
                results = pool.map(_run, batch) if pool else map(_run, batch)
                for ep in results:  # committed in seed order: the same dataset for any --jobs
                    ran += 1
                    index = writer.add(ep)
                    made += index is not None
                    if progress:
                        progress(ep, index)
            per_task[task] = {"success": made, "attempts": sum(1 for a in writer.attempts
                                                                if a["task_hash"] == hashes[task])}
    finally:
        if pool:
            pool.shutdown(cancel_futures=True)
        close_cached_env()
        shutil.rmtree(staging, ignore_errors=True)
        if fmt == "hdf5":
            writer.finalize()  # every committed episode, also after an error
    return {"episodes": len(writer.episodes), "attempts": ran, "per_task": per_task}


@dataclass(frozen=True)
class ReplayResult:
    episode_index: int
    success: bool
    max_pose_error: float

    @property
    def ok(self) -> bool:
        return self.success and self.max_pose_error <= REPLAY_POSE_TOL


def replay_actions(task: str, task_hash: str, seed: int, embodiment: str, instruction: str,
                   actions: np.ndarray, final_poses: dict) -> tuple[bool, float]:
    """Re-run recorded ``actions`` from ``seed``; (success, largest final-pose difference).

    Raises:
        BadInput: the task's content hash differs from the recorded one.
    """
    from rpg.env.core import BlockTaskEnv

    env = BlockTaskEnv(task, embodiment=embodiment, control_mode="ee_delta", cameras=())
    try:
        if env.source.content_hash != task_hash:
            raise BadInput(f"{task} has changed since the dataset was recorded (content hash "
                           f"{env.source.content_hash[:12]}, recorded {task_hash[:12]})")
        if instruction != env.instruction and instruction not in env.source.paraphrases:
            raise BadInput(f"the recorded instruction is not one of {task}'s")
        env.reset(seed=seed)
        info = {"success": False}
        for a in actions:
            _, _, term, trunc, info = env.step(a)
            if term or trunc:
                break
        err = 0.0
        for name, pose in env.scene.poses().items():
            rec = final_poses.get(name)
            if rec is None:
                return False, float("inf")
            err = max(err, float(np.max(np.abs(np.array([*pose.pos, *pose.quat]) - np.array(rec)))))
        return bool(info["success"]), err
    finally:
        env.close()


def replay_dataset(root: str | Path, progress: Callable[[ReplayResult], None] | None = None) -> list[ReplayResult]:
    """Replay every episode of a dataset written by :func:`collect_demos`.

    Raises:
        BadInput: not a dataset, or a task changed since recording.
    """
    from rpg.demos.robomimic import dataset_file, read_demos

    root = Path(root)
    out = []
    h5 = dataset_file(root)
    if h5 is not None:
        for demo in read_demos(h5):
            ok, err = replay_actions(demo["task"], demo["task_hash"], demo["seed"], demo["embodiment"],
                                     demo["instruction"], demo["actions"], demo["final_poses"])
            out.append(ReplayResult(demo["episode_index"], ok, err))
            if progress:
                progress(out[-1])
        return out
    if (root / "meta" / "info.json").is_file():
        rows = read_jsonl(root / "meta" / "episodes.jsonl")
        for row in rows:
            actions = read_episode_actions(root, row["episode_index"])
            ok, err = replay_actions(row["task"], row["task_hash"], row["seed"], row["embodiment"],
                                     row["instruction"], actions, row["final_poses"])
            out.append(ReplayResult(row["episode_index"], ok, err))
            if progress:
                progress(out[-1])
        return out
    raise BadInput(f"{root} is not a dataset written by rpg demos (no meta/info.json or demo.hdf5)")
