"""Demonstrations as a LeRobot dataset, format v2.1 (``rpg demos --format lerobot-v2.1``;
what openpi's and GR00T's older loaders read; the default is v3.0, :mod:`rpg.demos.lerobot3`),
written with pyarrow and PyAV without the ``lerobot`` package::

    DIR/data/chunk-000/episode_000000.parquet      one row per step
    DIR/videos/chunk-000/observation.images.<camera>/episode_000000.mp4
    DIR/meta/info.json  meta/episodes.jsonl  meta/tasks.jsonl  meta/episodes_stats.jsonl

Parquet columns: :mod:`rpg.demos.layout` (``observation.state`` 11, ``action`` 7, the optional
joint positions, object poses and ``next.*`` columns, ``timestamp``, indices).  Each line of
``episodes.jsonl`` carries LeRobot's ``episode_index``, ``tasks`` and ``length`` and rpg's
provenance: ``task`` (where it was loaded from), ``task_hash`` (content hash), ``seed``,
``embodiment``, ``instruction``, ``paraphrase``, ``final_poses``, ``object_names`` (the
object slots' names) and ``success`` (false only for a failed episode kept with
``--keep-failed``).  ``meta/info.json`` also records the robot's meshes in the
videos, ``rpg_visual`` (:data:`rpg.demos.layout.VISUAL_KEY`), and the wrist camera's
supersampling, ``rpg_wrist_supersample`` (:data:`rpg.demos.layout.SUPERSAMPLE_KEY`).

Crash safety: an episode's files are written first (each atomically), then its line is
appended to ``meta/episodes.jsonl``; that line is the commit.  :meth:`LeRobotWriter.open`
removes the files of an episode without a line (torn by a kill), so a run resumes where the
last committed episode ended.  ``meta/rpg_attempts.jsonl`` records every attempt (failed
ones too) so a resumed run does not retry them.

Replay reads a dataset as a peer's data (:func:`read_episodes`, :func:`read_episode_actions`):
no symbolic links below the dataset directory, sizes checked before reading, and an
episode's parquet footer (row count, ``action`` column type and declared size) checked
before its actions are materialised.
"""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

from rpg.demos.layout import Layout, check_existing, video_key
from rpg.demos.log import attempted, discard_failed, log_attempt, settle_attempts
from rpg.demos.record import ACTION_NAMES, Episode
from rpg.errors import PeerError
from rpg.jsonl import append_jsonl, read_jsonl, rewrite_jsonl

CODEBASE_VERSION = "v2.1"
CHUNK_SIZE = 1000
DATA_PATH = "data/chunk-{episode_chunk:03d}/episode_{episode_index:06d}.parquet"
VIDEO_PATH = "videos/chunk-{episode_chunk:03d}/{video_key}/episode_{episode_index:06d}.mp4"

__all__ = ["CODEBASE_VERSION", "LeRobotWriter", "read_episode_actions", "read_episodes", "video_key"]


def _write_json(path: Path, obj) -> None:
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    tmp.write_text(json.dumps(obj, indent=2, sort_keys=True) + "\n")
    os.replace(tmp, path)


def provenance(ep: Episode) -> dict:
    """rpg's record of an episode, as both LeRobot versions store it (``final_poses`` as a map)."""
    return {"task": ep.task, "task_hash": ep.task_hash, "task_name": ep.task_name, "seed": ep.seed,
            "embodiment": ep.embodiment, "instruction": ep.instruction, "paraphrase": ep.paraphrase,
            "final_poses": ep.final_poses, "object_names": list(ep.object_names), "success": bool(ep.success)}


class LeRobotWriter:
    """Appends recorded episodes to a LeRobot v2.1 dataset directory (resumable).

    Args:
        root: the dataset directory (created).
        layout: what a frame holds (:class:`rpg.demos.layout.Layout`).
        keep_failed: commit failed episodes too (``success`` false) instead of discarding them.
    """

    version = CODEBASE_VERSION

    def __init__(self, root: str | Path, layout: Layout, keep_failed: bool = False):
        self.root = Path(root)
        self.layout = layout
        self.keep_failed = keep_failed
        self.episodes: list[dict] = []
        self.tasks: list[str] = []
        self.attempts: list[dict] = []

    @property
    def meta(self) -> Path:
        return self.root / "meta"

    def open(self) -> set[tuple[str, int, str]]:
        """Read what a previous run committed, remove torn episodes' files, and return the
        attempts already made as ``(task_hash, seed, instruction)``.

        Raises:
            BadInput: the directory holds another kind of dataset, another LeRobot version, or
                one of another embodiment, cameras, image size or columns.
        """
        check_existing(self.root, self.layout, CODEBASE_VERSION, "lerobot (v3.0)")
        self.meta.mkdir(parents=True, exist_ok=True)
        self.episodes = read_jsonl(self.meta / "episodes.jsonl")
        self.tasks = [t["task"] for t in read_jsonl(self.meta / "tasks.jsonl")]
        self.attempts = settle_attempts(self.meta, self.episodes)
        n = len(self.episodes)
        for rel in ("data", "videos"):
            for f in sorted((self.root / rel).rglob("episode_*")):
                if int(f.stem.split("_")[1]) >= n:
                    f.unlink()
        for f in sorted(self.root.rglob(".*tmp*")):
            f.unlink()
        stats = read_jsonl(self.meta / "episodes_stats.jsonl")[:n]
        rewrite_jsonl(self.meta / "episodes_stats.jsonl", stats)
        rewrite_jsonl(self.meta / "episodes.jsonl", self.episodes)
        self._write_info()
        return attempted(self.attempts, self.episodes)

    def _path(self, template: str, index: int, **kw) -> Path:
        return self.root / template.format(episode_chunk=index // CHUNK_SIZE, episode_index=index, **kw)

    def add(self, ep: Episode) -> int | None:
        """Commit an episode (its videos are moved in); record any attempt.

        Returns:
            The episode index, or None for a failed episode not kept (its videos are deleted).
        """
        if not self.keep_failed and discard_failed(self.meta, self.attempts, ep):
            return None
        index = len(self.episodes)
        if ep.instruction not in self.tasks:
            self.tasks.append(ep.instruction)
            rewrite_jsonl(self.meta / "tasks.jsonl", [{"task_index": i, "task": t} for i, t in enumerate(self.tasks)])
        task_index = self.tasks.index(ep.instruction)
        start = sum(e["length"] for e in self.episodes)
        table = self.layout.table(ep, index, start, task_index)
        data = self._path(DATA_PATH, index)
        data.parent.mkdir(parents=True, exist_ok=True)
        tmp = data.with_name(f".{data.name}.tmp")
        pq.write_table(table, tmp)
        os.replace(tmp, data)
        for cam in self.layout.cameras:
            dst = self._path(VIDEO_PATH, index, video_key=video_key(cam))
            dst.parent.mkdir(parents=True, exist_ok=True)
            shutil.move(ep.videos[cam], dst)
        stats = self.layout.stats(ep, index, start, task_index)
        append_jsonl(self.meta / "episodes_stats.jsonl", {"episode_index": index, "stats": stats})
        line = {"episode_index": index, "tasks": [ep.instruction], "length": ep.length, **provenance(ep)}
        log_attempt(self.meta, self.attempts, ep)  # before the commit (rpg.demos.log)
        append_jsonl(self.meta / "episodes.jsonl", line)  # the commit
        self.episodes.append(line)
        self._write_info()
        return index

    def _write_info(self) -> None:
        n = len(self.episodes)
        cams = self.layout.cameras
        _write_json(self.meta / "info.json", {
            "codebase_version": CODEBASE_VERSION, "robot_type": self.layout.robot_type,
            "total_episodes": n, "total_frames": sum(e["length"] for e in self.episodes),
            "total_tasks": len(self.tasks), "total_videos": n * len(cams),
            "total_chunks": (n + CHUNK_SIZE - 1) // CHUNK_SIZE if n else 0, "chunks_size": CHUNK_SIZE,
            "fps": float(self.layout.fps), "splits": {"train": f"0:{n}"}, "data_path": DATA_PATH,
            "video_path": VIDEO_PATH if cams else None,
            "features": self.layout.features(CODEBASE_VERSION), **self.layout.info_keys(),
        })


MAX_META_BYTES = 256 * 1024**2
"""Largest ``meta/episodes.jsonl`` replay reads, bytes (a line is ~1 KB)."""

MAX_PARQUET_BYTES = 64 * 1024**2
"""Largest episode parquet file replay reads, and most bytes its ``action`` column may
declare uncompressed (an episode of 100000 steps is ~10 MB), bytes."""


def _peer_file(root: Path, rel: str, limit: int) -> bytes:
    """The bytes of ``root/rel``, a regular file of at most ``limit`` bytes reached through no
    symbolic link below ``root``.

    Raises:
        PeerError: a symbolic link on the way, not a regular file, or too large.
    """
    from rpg.artifact import ArtifactError, read_bytes

    here = root
    for part in Path(rel).parts:
        here = here / part
        if here.is_symlink():
            raise PeerError(f"{here} is a symbolic link; replay reads a dataset's own files only")
    try:
        return read_bytes(here, limit)
    except ArtifactError as exc:
        raise PeerError(str(exc)) from None


def read_episodes(root: str | Path, max_episodes: int = 100_000) -> list[dict]:
    """The committed episode lines of a dataset's ``meta/episodes.jsonl`` (up to a torn last
    line), read only if the file is at most :data:`MAX_META_BYTES`; none when it is missing.

    Raises:
        PeerError: a symbolic link, too large, a line that is not a map, or more than
            ``max_episodes`` lines.
    """
    root = Path(root)
    if not (root / "meta" / "episodes.jsonl").exists():
        return []
    raw = _peer_file(root, "meta/episodes.jsonl", MAX_META_BYTES)
    out = []
    for line in raw.split(b"\n"):
        if not line.strip():
            continue
        try:
            doc = json.loads(line)
        except ValueError:
            break  # a torn last line (jsonl.read_complete)
        if not isinstance(doc, dict):
            raise PeerError(f"{root}/meta/episodes.jsonl: line {len(out) + 1} is not a map")
        out.append(doc)
        if len(out) > max_episodes:
            raise PeerError(f"{root}/meta/episodes.jsonl lists more than {max_episodes} episodes")
    return out


def read_episode_actions(root: str | Path, index: int, max_steps: int = 100_000) -> np.ndarray:
    """The recorded actions (T, 7) float32 of episode ``index``, materialised only after the
    parquet file's size (:data:`MAX_PARQUET_BYTES`), row count (1 <= T <= ``max_steps``) and
    ``action`` column (7 floats a row, no nulls, declared size bounded) are checked.

    Raises:
        PeerError: the file is missing, a symbolic link, too large, not parquet, or its
            rows or ``action`` column are out of bounds.
    """
    root = Path(root)
    rel = DATA_PATH.format(episode_chunk=int(index) // CHUNK_SIZE, episode_index=int(index))
    raw = _peer_file(root, rel, MAX_PARQUET_BYTES)
    where = root / rel
    try:
        pf = pq.ParquetFile(pa.BufferReader(raw))
        meta = pf.metadata
        rows = meta.num_rows
        if not 1 <= rows <= max_steps:
            raise PeerError(f"{where} declares {rows} rows; an episode has 1 to {max_steps} steps")
        field = pf.schema_arrow.field("action") if "action" in pf.schema_arrow.names else None
        if (field is None or not pa.types.is_fixed_size_list(field.type) or field.type.list_size != len(ACTION_NAMES)
                or not pa.types.is_floating(field.type.value_type)):
            raise PeerError(f"{where}: the action column is not {len(ACTION_NAMES)} floats a row")
        chunks = [meta.row_group(i).column(j) for i in range(meta.num_row_groups) for j in range(meta.num_columns)]
        declared = sum(c.total_uncompressed_size for c in chunks
                       if c.path_in_schema == "action" or c.path_in_schema.startswith("action."))
        if declared > MAX_PARQUET_BYTES:
            raise PeerError(f"{where}: the action column declares {declared} bytes, over {MAX_PARQUET_BYTES}")
        actions = pf.read(columns=["action"]).column("action").combine_chunks()
    except PeerError:
        raise
    except (pa.ArrowException, OSError, ValueError, TypeError, KeyError) as exc:
        raise PeerError(f"{where} is not an episode parquet file ({type(exc).__name__}: "
                        f"{' '.join(str(exc).split())[:200]})") from None
    values = actions.flatten()
    if len(actions) != rows or actions.null_count or values.null_count:
        raise PeerError(f"{where}: the action column has {len(actions)} rows for {rows} declared, or nulls")
    values = values.to_numpy(zero_copy_only=False)
    if values.shape != (rows * len(ACTION_NAMES),):
        raise PeerError(f"{where}: the action column holds {values.shape[0]} numbers for {rows} rows")
    return values.astype(np.float32).reshape(rows, len(ACTION_NAMES))
