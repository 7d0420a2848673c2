"""``rpg demos``: oracle demonstrations of tasks as a dataset, and their replay.

:func:`collect_demos` runs the oracle over the seeds of every task of a target and keeps the
successful episodes, ``episodes`` per task (seeds 0, 1, ... are tried in order, at most
:data:`MAX_SEED_FACTOR` x ``episodes`` of them).  Episodes run in ``jobs`` processes or as Ray
tasks (``backend="ray"``, :mod:`rpg.parallel`) and are committed by this process in (task,
seed) order, however they finish, so the dataset is the same for any number of jobs and
either backend.
:func:`replay_dataset` re-runs every recorded episode's actions from its seed and checks
that it succeeds again and ends in the recorded state.

A dataset to replay is a peer's data, not a program: the task path recorded in it is never
loaded.  Each episode's task is found by its recorded content hash among the tasks and family
versions of a library the user names (:func:`library_tasks`; ``rpg demos --replay DATASET
--library DIR``), loading it recomputes that hash, and an episode whose hash no task of the
library has is refused before anything is replayed.  The readers check what the dataset
declares before reading it (:mod:`rpg.demos.robomimic`: shapes, dtypes and storage of the
HDF5 datasets; :mod:`rpg.demos.lerobot`: the parquet file's size, row count and columns), and
every episode's provenance (:func:`check_provenance`) against bounds.
"""

from __future__ import annotations

import contextlib
import math
import re
import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rpg.demos.layout import COLUMNS, Layout, check_columns
from rpg.demos.record import Episode, close_cached_env, record_episode
from rpg.errors import BadInput, PeerError

MAX_SEED_FACTOR = 3
"""At most this many times ``episodes`` seeds are tried per task."""

FORMATS = ("lerobot", "lerobot-v2.1", "hdf5")
"""Dataset formats written: LeRobot v3.0 (:mod:`rpg.demos.lerobot3`, the default), LeRobot
v2.1 (:mod:`rpg.demos.lerobot`) and robomimic's HDF5 (:mod:`rpg.demos.robomimic`)."""

REPLAY_POSE_TOL = 1e-6
"""Largest difference (m, or quaternion units) between a replay's final poses and the recorded ones."""

MAX_EPISODE_STEPS = 100_000
"""Most actions a replayed episode may hold (T); the longest step limit of a library task
(:func:`rpg.env.core.episode_step_limit`) is a few thousand."""

MAX_EPISODES = 100_000
"""Most episodes a replayed dataset may hold."""

MAX_TEXT = 10_000
"""Longest recorded instruction, embodiment or task name replay accepts, characters."""

MAX_POSES = 1_000
"""Most bodies in an episode's recorded final poses."""

_HASH = re.compile(r"[0-9a-f]{64}")


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
    gop: int | None = None
    visual: str = "decimated"
    wrist_supersample: int = 1


def _run(job: Job) -> Episode:
    return record_episode(job.task, job.seed, job.embodiment, job.cameras, job.image_size, job.instruction,
                          video_dir=Path(job.staging) / f"{Path(job.task).name}-{job.seed}", frames=job.frames,
                          reuse_env=True, gop=job.gop, visual=job.visual, wrist_supersample=job.wrist_supersample)


def _task_hash(task: str) -> str:
    from rpg.artifact import rehash
    from rpg.env.loading import resolve_target

    return rehash(resolve_target(task))[3]


def object_slots(tasks: list[str]) -> tuple[str, ...]:
    """Names of the ``observation.object_poses`` slots for ``tasks``: their objects' names
    (sorted) when every task has the same objects, else ``object_0`` ... for the largest
    number of objects a task has."""
    from rpg.artifact import load_artifact
    from rpg.env.loading import resolve_target

    names = {tuple(sorted(a.name for a in load_artifact(resolve_target(t))[0].assets)) for t in tasks}
    if len(names) == 1:
        return next(iter(names))
    return tuple(f"object_{k}" for k in range(max(len(n) for n in names)))


def library_path(task: str, target: str | Path) -> str:
    """Where ``task`` lies in its library, as a relative path: relative to the manifest's
    directory when ``target`` is a manifest, else the task directory's name (``FAMILY/vN`` for
    a family's version).  A hint for people; rpg finds tasks by content hash."""
    from rpg.env.loading import resolve_target

    directory = resolve_target(task).resolve()
    base = Path(str(target))
    if base.is_file():
        try:
            return directory.relative_to(base.parent.resolve()).as_posix()
        except ValueError:
            pass
    parts = directory.parts
    return "/".join(parts[-2:]) if len(parts) > 1 and parts[-1].startswith("v") and parts[-1][1:].isdigit() else parts[-1]


def make_writer(fmt: str, out: str | Path, layout: Layout, keep_failed: bool = False, task_paths: dict | None = None,
                **options):
    """The dataset writer of a format (:data:`FORMATS`); how the images were drawn
    (``layout.visual``, ``layout.wrist_supersample``) is recorded by every writer;
    ``options`` go to the LeRobot v3.0 writer (``data_files_size_in_mb``,
    ``video_files_size_in_mb``)."""
    if fmt == "hdf5":
        from rpg.demos.robomimic import RobomimicWriter

        return RobomimicWriter(out, layout.cameras, layout.image_size, layout.robot_type, keep_failed=keep_failed,
                               task_paths=task_paths, visual=layout.visual,
                               wrist_supersample=layout.wrist_supersample)
    if fmt == "lerobot-v2.1":
        from rpg.demos.lerobot import LeRobotWriter

        return LeRobotWriter(out, layout, keep_failed=keep_failed)
    from rpg.demos.lerobot3 import LeRobotV3Writer

    return LeRobotV3Writer(out, layout, keep_failed=keep_failed, **options)


def collect_demos(target: str | Path, out: str | Path, episodes: int = 10, embodiment: str = "panda",
                  fmt: str = "lerobot", jobs: int = 1, cameras: tuple[str, ...] = ("agentview", "wrist"),
                  image_size: tuple[int, int] = (256, 256), instruction: str = "original",
                  progress: Callable[[Episode, int | None], None] | None = None, gop: int | None = None,
                  columns: tuple[str, ...] = COLUMNS, keep_failed: bool = False, backend: str = "local",
                  address: str | None = None, visual: str = "decimated", wrist_supersample: int = 1,
                  **writer_options) -> dict:
    """Record ``episodes`` successful oracle demonstrations per task of ``target`` into ``out``.

    Args:
        gop: most frames between keyframes of the MP4s (default 2, LeRobot's).
        columns: the optional LeRobot column groups (:data:`rpg.demos.layout.COLUMNS`).
        keep_failed: commit failed episodes too (marked ``success`` false; they do not count
            toward ``episodes``).
        backend: ``local`` (``jobs`` spawned processes) or ``ray`` (Ray tasks on a local
            instance with ``jobs`` CPUs, or on the cluster at ``address``).
        visual: the robot's meshes in the images, ``decimated`` (default) or ``stock``
            (:mod:`rpg.env.embodiments.visuals`); recorded in robomimic's ``env_kwargs`` and in
            a LeRobot dataset's ``meta/info.json`` (:data:`rpg.demos.layout.VISUAL_KEY`).
        wrist_supersample: the wrist camera drawn at this many times the image size per side
            and averaged back, 1 (off, the default) or 2 (anti-aliased wrist shadows; on a
            software renderer a large share of the steps/s, README); recorded in
            robomimic's ``env_kwargs`` and in a LeRobot dataset's ``meta/info.json``
            (:data:`rpg.demos.layout.SUPERSAMPLE_KEY`).
        writer_options: for the LeRobot v3.0 writer, ``data_files_size_in_mb`` and
            ``video_files_size_in_mb``.

    Returns:
        A summary: ``{"episodes": committed in total, "attempts": run now, "per_task":
        {task: {"success": n, "attempts": m}}}``.

    Raises:
        BadInput: unknown target, format, column group or visual, a ``wrist_supersample``
            other than 1 or 2, ``episodes`` or ``jobs`` < 1, ``gop`` < 1, or ``out`` holds a
            dataset of another kind (or another ``visual`` or ``wrist_supersample``).
        rpg.parallel.BackendError: an unknown backend, Ray not installed or its cluster
            unreachable (before anything is written).
        rpg.parallel.WorkerLost: a worker died (the episodes committed before are kept).
    """
    from rpg.demos.mp4 import DEFAULT_GOP
    from rpg.parallel import open_backend

    if fmt not in FORMATS:
        raise BadInput(f"format {fmt!r} is not supported; rpg demos writes {', '.join(FORMATS)}")
    if episodes < 1 or jobs < 1:
        raise BadInput("--episodes and --jobs must be at least 1")
    gop = DEFAULT_GOP if gop is None else int(gop)
    if gop < 1:
        raise BadInput("--gop must be at least 1")
    columns = check_columns(columns)
    from rpg.env.embodiments.visuals import VISUALS
    from rpg.env.render import check_wrist_supersample

    if visual not in VISUALS:
        raise BadInput(f"--visual must be one of {', '.join(VISUALS)}, not {visual!r}")
    wrist_supersample = check_wrist_supersample(wrist_supersample)
    tasks = expand_targets(target)
    slots = object_slots(tasks) if "object_poses" in columns and fmt != "hdf5" else ()
    layout = Layout(embodiment, tuple(cameras), tuple(image_size), columns, slots, gop, visual, wrist_supersample)
    paths = {_task_hash(t): library_path(t, target) for t in tasks}
    with open_backend(backend, jobs, address) as runner:
        return _collect(runner, tasks, target, out, episodes, embodiment, fmt, tuple(cameras), tuple(image_size),
                        instruction, progress, gop, layout, paths, keep_failed, writer_options)


def _collect(runner, tasks: list[str], target, out, episodes: int, embodiment: str, fmt: str,
             cameras: tuple[str, ...], image_size: tuple[int, int], instruction: str, progress, gop: int,
             layout: Layout, paths: dict, keep_failed: bool, writer_options: dict) -> dict:
    """The part of :func:`collect_demos` that writes the dataset; ``runner`` an open
    :class:`rpg.parallel.Backend`."""
    writer = make_writer(fmt, out, layout, keep_failed=keep_failed, task_paths=paths, **writer_options)
    writer.open()
    staging = Path(out) / ".staging"
    shutil.rmtree(staging, ignore_errors=True)
    staging.mkdir(parents=True)
    hashes = {t: _task_hash(t) for t in tasks}
    per_task = {}
    ran = 0
    try:
        for task in tasks:
            made = sum(1 for e in writer.episodes if e["task_hash"] == hashes[task] and e.get("success", True))
            # a kill between an episode's commit line and its attempt line leaves it only in episodes
            tried = [a["seed"] for a in (*writer.attempts, *writer.episodes) if a["task_hash"] == hashes[task]]
            seed = max(tried, default=-1) + 1
            last = MAX_SEED_FACTOR * episodes
            while made < episodes and seed < last:
                batch = [Job(task, s, embodiment, cameras, image_size, instruction, str(staging),
                             "hdf5" if fmt == "hdf5" else "mp4", gop, layout.visual, layout.wrist_supersample)
                         for s in range(seed, min(seed + episodes - made, last))]
                seed += len(batch)
                # committed in seed order, however they finish: the same dataset for any --jobs and backend
                with contextlib.closing(runner.imap(_run, batch, ordered=True)) as results:
                    for ep in results:
                        ran += 1
                        index = writer.add(ep)
                        made += index is not None and ep.success
                        if progress:
                            progress(ep, index)
            per_task[task] = {"success": made, "attempts": sum(1 for a in writer.attempts
                                                                if a["task_hash"] == hashes[task])}
    finally:
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
    recorded_success: bool = True

    @property
    def ok(self) -> bool:
        """The replay ends as recorded: the same success (true, or false for a failed
        episode kept with ``--keep-failed``) and the same final poses."""
        return self.success == self.recorded_success and self.max_pose_error <= REPLAY_POSE_TOL


def library_tasks(library: str | Path) -> dict[str, Path]:
    """Content hash -> task directory, for every task and family version directly under
    ``library`` (a directory, or a manifest file: its directory).

    A plain task is indexed by the ``content_hash`` its ``task.yaml`` records, a family's
    versions by the hashes its ``family.yaml`` records (each version in ``vN/``).  This is
    only an index: loading a task recomputes its hash (:func:`replay_actions` refuses a
    mismatch).  Entries that cannot be read are skipped.

    Raises:
        BadInput: ``library`` is not a directory (nor a manifest in one).
    """
    from rpg import yamlio
    from rpg.artifact import ArtifactError, read_text
    from rpg.steer.family import Family, is_family

    root = Path(library)
    if root.is_file() and root.suffix in (".yaml", ".yml"):
        root = root.parent
    if not root.is_dir():
        raise BadInput(f"--library {library} is not a directory of tasks and families")
    out: dict[str, Path] = {}
    for d in sorted(p for p in root.iterdir() if p.is_dir() and not p.is_symlink() and not p.name.startswith(".")):
        try:
            if is_family(d):
                fam = Family(d)
                for v in fam.load().versions:
                    out.setdefault(v.content_hash, fam.version_dir(v.version_id))
            elif (d / "task.yaml").is_file():
                doc = yamlio.load(read_text(d / "task.yaml"))
                if isinstance(doc, dict) and isinstance(doc.get("content_hash"), str):
                    out.setdefault(doc["content_hash"], d)
        except (BadInput, ArtifactError, OSError, ValueError):
            continue
    return out


def check_provenance(doc: object, where: str) -> dict:
    """One episode's provenance as a dataset records it, checked against bounds: ``task_hash``
    (64 hex digits), ``seed`` (an integer in [0, 2**32)), ``embodiment``, ``instruction`` and
    ``task_name`` (strings of at most :data:`MAX_TEXT` characters; ``task_name`` optional),
    ``final_poses`` (at most :data:`MAX_POSES` names, each 7 finite numbers: position, m, and
    quaternion), ``success`` (optional, a boolean).  The recorded ``task`` path is ignored.

    Returns:
        The checked fields (``task_name`` defaults to ``"?"``, ``success`` to true).

    Raises:
        PeerError: a field missing, of another type, or out of bounds (``where`` names the episode).
    """
    if not isinstance(doc, dict):
        raise PeerError(f"{where}: the episode record is not a map")
    h, seed = doc.get("task_hash"), doc.get("seed")
    if not isinstance(h, str) or not _HASH.fullmatch(h):
        raise PeerError(f"{where}: task_hash is not a content hash (64 hex digits)")
    if type(seed) is not int or not 0 <= seed < 2**32:
        raise PeerError(f"{where}: seed is not an integer in [0, 2**32)")
    for key in ("embodiment", "instruction", "task_name"):
        value = doc.get(key, "?" if key == "task_name" else None)
        if not isinstance(value, str) or len(value) > MAX_TEXT:
            raise PeerError(f"{where}: {key} is not a string of at most {MAX_TEXT} characters")
    poses = doc.get("final_poses")
    if (not isinstance(poses, dict) or len(poses) > MAX_POSES
            or not all(isinstance(k, str) and len(k) <= MAX_TEXT and isinstance(v, list) and len(v) == 7
                       and all(type(x) in (int, float) and math.isfinite(x) for x in v) for k, v in poses.items())):
        raise PeerError(f"{where}: final_poses is not a map of at most {MAX_POSES} names to 7 finite numbers")
    success = doc.get("success", True)
    if type(success) not in (bool, np.bool_):
        raise PeerError(f"{where}: success is not a boolean")
    return {"success": bool(success), "task_hash": h, "seed": seed, "embodiment": doc["embodiment"], "instruction": doc["instruction"],
            "task_name": doc.get("task_name", "?"), "final_poses": poses}


def replay_actions(task: str | Path, task_hash: str, seed: int, embodiment: str, instruction: str,
                   actions: np.ndarray, final_poses: dict) -> tuple[bool, float]:
    """Re-run recorded ``actions`` from ``seed`` in the task at ``task`` (a directory rpg
    chose, never one a dataset names); (success, largest final-pose difference).

    Raises:
        BadInput: the task's content hash differs from the recorded one, or the recorded
            instruction is not one of the task's.
    """
    from rpg.env.core import BlockTaskEnv

    env = BlockTaskEnv(task, embodiment=embodiment, control_mode="ee_delta", cameras=())
    try:
        if env.source.content_hash != task_hash:
            raise BadInput(f"{task} has changed since the dataset was recorded (content hash "
                           f"{env.source.content_hash[:12]}, recorded {task_hash[:12]})")
        if instruction not in (env.instruction, env.source.canonical, *env.source.paraphrases):
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


def replay_dataset(root: str | Path, progress: Callable[[ReplayResult], None] | None = None,
                   library: str | Path = "library") -> list[ReplayResult]:
    """Replay every episode of a dataset written by :func:`collect_demos`, each in the task of
    ``library`` with its recorded content hash (:func:`library_tasks`); the task path the
    dataset records is not used.

    Every episode's provenance is read and checked, and its task found, before the first is
    replayed; its actions are read (bounded: at most :data:`MAX_EPISODE_STEPS` by 7 floats)
    just before it is.

    Raises:
        BadInput: not a dataset, ``library`` is not a directory, no task of ``library`` has an
            episode's content hash, or a task changed since recording.
        PeerError: the dataset declares something out of bounds or malformed.
    """
    from rpg.demos import lerobot, lerobot3
    from rpg.demos.robomimic import dataset_file, read_demo_actions, read_demos

    root = Path(root)
    h5 = dataset_file(root)
    if h5 is not None:
        episodes = read_demos(h5, max_episodes=MAX_EPISODES, max_steps=MAX_EPISODE_STEPS)
        where = str(h5)

        def actions_of(number: int) -> np.ndarray:
            return read_demo_actions(h5, number, max_steps=MAX_EPISODE_STEPS)
    elif lerobot3.is_v3(root):
        episodes = lerobot3.read_episodes(root, max_episodes=MAX_EPISODES)
        where = str(root)
        rows = {e.get("episode_index"): e for e in episodes}

        def actions_of(number: int) -> np.ndarray:
            return lerobot3.read_episode_actions(root, rows[number], max_steps=MAX_EPISODE_STEPS)
    elif (root / "meta" / "info.json").is_file():
        episodes = lerobot.read_episodes(root, max_episodes=MAX_EPISODES)
        where = str(root)

        def actions_of(number: int) -> np.ndarray:
            return lerobot.read_episode_actions(root, number, max_steps=MAX_EPISODE_STEPS)
    else:
        raise BadInput(f"{root} is not a dataset written by rpg demos (no meta/info.json or demo.hdf5)")
    index = library_tasks(library)
    plan = []
    for i, ep in enumerate(episodes):
        number = ep.get("episode_index") if isinstance(ep, dict) else None
        if type(number) is not int or number < 0:
            raise PeerError(f"{where}: episode record {i} has no non-negative episode_index")
        prov = check_provenance(ep, f"{where} episode {number}")
        task = index.get(prov["task_hash"])
        if task is None:
            raise BadInput(f"no task in {library} has content hash {prov['task_hash'][:12]} (episode {number} of "
                           f"{where}, recorded as {prov['task_name'][:80]!r}); give the library it was recorded "
                           "from with --library")
        plan.append((number, task, prov))
    out = []
    for number, task, prov in plan:
        ok, err = replay_actions(task, prov["task_hash"], prov["seed"], prov["embodiment"], prov["instruction"],
                                 actions_of(number), prov["final_poses"])
        out.append(ReplayResult(number, ok, err, prov["success"]))
        if progress:
            progress(out[-1])
    return out
