"""Demonstrations as a LeRobot dataset, format v3.0 (``rpg demos --format lerobot``, the
default: what lerobot 0.4 and later load), written with pyarrow and PyAV without the
``lerobot`` package.  Episodes are concatenated into chunked files::

    DIR/data/chunk-000/file-000.parquet                    frames of many episodes
    DIR/videos/observation.images.<camera>/chunk-000/file-000.mp4
    DIR/meta/episodes/chunk-000/file-000.parquet           one row per episode
    DIR/meta/tasks.parquet  meta/stats.json  meta/info.json

A data file takes episodes until it reaches ``data_files_size_in_mb``, a video file until it
reaches ``video_files_size_in_mb``; then the next file (``file-001``, and after
``chunks_size`` files the next chunk).  Frame columns: :mod:`rpg.demos.layout`.  A row of the
episodes metadata holds LeRobot's ``episode_index``, ``tasks``, ``length``,
``dataset_from_index`` / ``dataset_to_index`` (the episode's frames in ``index``),
``data/chunk_index`` and ``data/file_index``, per camera ``videos/<key>/chunk_index``,
``file_index``, ``from_timestamp`` and ``to_timestamp`` (where the episode lies in the
video file: its frame t is shown at ``from_timestamp + t / fps``), ``meta/episodes/...``,
the statistics ``stats/<feature>/<min|max|mean|std|count>``, and rpg's provenance:
``task``, ``task_hash``, ``task_name``, ``seed``, ``embodiment``, ``instruction``,
``paraphrase``, ``final_poses`` (JSON), ``object_names`` and ``success``.
``meta/tasks.parquet`` maps each task (the instruction, the index) to its ``task_index``.
``meta/info.json`` also records the robot's meshes in the videos, ``rpg_visual``
(:data:`rpg.demos.layout.VISUAL_KEY`), and the wrist camera's supersampling,
``rpg_wrist_supersample`` (:data:`rpg.demos.layout.SUPERSAMPLE_KEY`).

Crash safety.  A file is only ever replaced whole: written to a temporary name and renamed.
An episode is appended to the current data file and video files by writing each anew (the
old rows or packets, then the episode's; videos are joined without re-encoding,
:func:`rpg.demos.mp4.join`), and it is **committed when its row is in the episodes
metadata** (that file rewritten last, with the new row).  A kill before the commit leaves
data and video files with frames past the last committed episode: :meth:`LeRobotV3Writer.open`
cuts them back (and removes files no committed episode names, and temporary files), then
rewrites ``tasks.parquet``, ``stats.json`` and ``info.json`` from the committed rows, so a
rerun resumes where the last committed episode ended.  ``meta/rpg_attempts.jsonl`` records
every attempt, failed ones too.

Replay reads a dataset as a peer's data (:func:`read_episodes`, :func:`read_episode_actions`):
no symbolic links below the dataset directory, sizes and declared column sizes checked
before reading.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pyarrow.parquet as pq

from rpg.demos import mp4
from rpg.demos.layout import (
    INDEX_FEATURES,
    Layout,
    aggregate_stats,
    check_existing,
    video_key,
)
from rpg.demos.lerobot import _write_json, provenance
from rpg.demos.log import attempted, discard_failed, log_attempt, settle_attempts
from rpg.demos.record import ACTION_NAMES, Episode
from rpg.errors import BadInput, PeerError

CODEBASE_VERSION = "v3.0"
CHUNK_SIZE = 1000
"""Files per chunk directory (LeRobot's ``chunks_size``)."""

DATA_FILE_MB = 100
"""LeRobot's ``data_files_size_in_mb``: a data file takes no more episodes once it is this large."""

VIDEO_FILE_MB = 200
"""LeRobot's ``video_files_size_in_mb``, the same for video files."""

EPISODES_PER_META_FILE = 1000
"""Rows of an episodes metadata file (each commit rewrites the last one)."""

_FILE = "chunk-{chunk_index:03d}/file-{file_index:03d}"
DATA_PATH = "data/" + _FILE + ".parquet"
VIDEO_PATH = "videos/{video_key}/" + _FILE + ".mp4"
EPISODES_PATH = "meta/episodes/" + _FILE + ".parquet"
TASKS_PATH = "meta/tasks.parquet"

_PROVENANCE_TYPES = {"task": pa.string(), "task_hash": pa.string(), "task_name": pa.string(), "seed": pa.int64(),
                     "embodiment": pa.string(), "instruction": pa.string(), "paraphrase": pa.int64(),
                     "final_poses": pa.string(), "object_names": pa.list_(pa.string()), "success": pa.bool_()}




def _replace(tmp: Path, path: Path) -> None:
    """Rename ``tmp`` over ``path`` once its bytes are on disk."""
    with open(tmp, "rb") as fh:
        os.fsync(fh.fileno())
    os.replace(tmp, path)


def _tmp(path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    return path.with_name(f".{path.name}.tmp-{os.getpid()}")


def tasks_table(tasks: list[str]) -> pa.Table:
    """``meta/tasks.parquet``: ``task_index`` by task, the task string as the (pandas) index,
    as LeRobot's ``pd.read_parquet`` reads it."""
    pandas_meta = {
        "index_columns": ["task"], "column_indexes": [{"name": None, "field_name": None, "pandas_type": "unicode",
                                                       "numpy_type": "object", "metadata": {"encoding": "UTF-8"}}],
        "columns": [{"name": "task_index", "field_name": "task_index", "pandas_type": "int64", "numpy_type": "int64",
                     "metadata": None},
                    {"name": "task", "field_name": "task", "pandas_type": "unicode", "numpy_type": "object",
                     "metadata": None}],
        "creator": {"library": "pyarrow", "version": pa.__version__}, "pandas_version": "2.2.0"}
    schema = pa.schema([("task_index", pa.int64()), ("task", pa.string())],
                       metadata={b"pandas": json.dumps(pandas_meta).encode()})
    return pa.Table.from_arrays([pa.array(range(len(tasks)), pa.int64()), pa.array(tasks, pa.string())], schema=schema)


class LeRobotV3Writer:
    """Appends recorded episodes to a LeRobot v3.0 dataset directory (resumable; the interface
    of :class:`rpg.demos.lerobot.LeRobotWriter`).

    Args:
        root: the dataset directory (created).
        layout: what a frame holds (:class:`rpg.demos.layout.Layout`).
        keep_failed: commit failed episodes too (``success`` false) instead of discarding them.
        data_files_size_in_mb, video_files_size_in_mb: file sizes after which the next file starts.
        chunks_size: files per chunk directory.
    """

    version = CODEBASE_VERSION

    def __init__(self, root: str | Path, layout: Layout, keep_failed: bool = False,
                 data_files_size_in_mb: float = DATA_FILE_MB, video_files_size_in_mb: float = VIDEO_FILE_MB,
                 chunks_size: int = CHUNK_SIZE):
        self.root = Path(root)
        self.layout = layout
        self.keep_failed = keep_failed
        self.data_mb = data_files_size_in_mb
        self.video_mb = video_files_size_in_mb
        self.chunks_size = int(chunks_size)
        self.rows: list[dict] = []
        self.tasks: list[str] = []
        self.attempts: list[dict] = []

    @property
    def meta(self) -> Path:
        return self.root / "meta"

    @property
    def episodes(self) -> list[dict]:
        """The committed episodes' metadata rows (``final_poses`` decoded)."""
        return self.rows

    def _where(self, number: int) -> dict:
        """The chunk and file indices of the ``number``-th file (0, 1, ...)."""
        return {"chunk_index": number // self.chunks_size, "file_index": number % self.chunks_size}

    def _number(self, chunk_index, file_index) -> int:
        return int(chunk_index) * self.chunks_size + int(file_index)

    # -- schema ------------------------------------------------------------------------------
    def episodes_schema(self) -> pa.Schema:
        """The schema of the episodes metadata files."""
        i64, f64 = pa.int64(), pa.float64()
        fields = [("episode_index", i64), ("tasks", pa.list_(pa.string())), ("length", i64),
                  ("data/chunk_index", i64), ("data/file_index", i64), ("dataset_from_index", i64),
                  ("dataset_to_index", i64)]
        for cam in self.layout.cameras:
            k = video_key(cam)
            fields += [(f"videos/{k}/chunk_index", i64), (f"videos/{k}/file_index", i64),
                       (f"videos/{k}/from_timestamp", f64), (f"videos/{k}/to_timestamp", f64)]
        fields += [("meta/episodes/chunk_index", i64), ("meta/episodes/file_index", i64)]
        for name in (*(video_key(c) for c in self.layout.cameras), *self.layout.frame_features()):
            image = name.startswith("observation.images.")
            value = pa.list_(pa.list_(pa.list_(f64))) if image else pa.list_(f64)
            fields += [(f"stats/{name}/{s}", value) for s in ("min", "max", "mean", "std")]
            fields.append((f"stats/{name}/count", pa.list_(i64)))
        fields += list(_PROVENANCE_TYPES.items())
        return pa.schema(fields)

    def _episodes_table(self, rows: list[dict]) -> pa.Table:
        schema = self.episodes_schema()
        cols = {f.name: [] for f in schema}
        for row in rows:
            for name in cols:
                v = row[name]
                cols[name].append(json.dumps(v, sort_keys=True) if name == "final_poses" else v)
        return pa.Table.from_pydict(cols, schema=schema)

    # -- opening -------------------------------------------------------------------------------
    def open(self) -> set[tuple[str, int, str]]:
        """Read what a previous run committed, cut back what a kill left past it, and return
        the attempts already made as ``(task_hash, seed, instruction)``.

        Raises:
            BadInput: the directory holds another kind of dataset, another LeRobot version, or
                one of another embodiment, cameras, image size, columns or keyframe interval.
        """

        old = check_existing(self.root, self.layout, CODEBASE_VERSION, "lerobot-v2.1")
        if old is not None:
            if type(old.get("chunks_size")) is int and old["chunks_size"] > 0:
                self.chunks_size = old["chunks_size"]  # the files already written are numbered with it
        elif (self.meta / "episodes.jsonl").is_file():
            raise BadInput(f"{self.root} holds a LeRobot v2.1 dataset; write it with --format lerobot-v2.1 or give a "
                           "new --out directory")
        self.meta.mkdir(parents=True, exist_ok=True)
        for f in sorted(self.root.rglob(".*.tmp-*")):
            if ".staging" not in f.parts:
                f.unlink()
        self.rows = []
        for f in sorted((self.meta / "episodes").glob("chunk-*/file-*.parquet")):
            for row in pq.read_table(f).to_pylist():
                row["final_poses"] = json.loads(row["final_poses"])
                self.rows.append(row)
        for i, row in enumerate(self.rows):
            if row["episode_index"] != i:
                raise BadInput(f"{self.root}: the episodes metadata lists episode {row['episode_index']} at "
                               f"position {i} (changed by hand?); give a new --out directory")
        self._cut_back()
        self.tasks = []
        for row in self.rows:
            if row["tasks"][0] not in self.tasks:
                self.tasks.append(row["tasks"][0])
        self._write_tasks()
        self._write_info()
        self.attempts = settle_attempts(self.meta, self.rows)
        return attempted(self.attempts, self.rows)

    def _cut_back(self) -> None:
        """Make the data and video files hold exactly the committed episodes' frames."""
        last = self.rows[-1] if self.rows else None
        # data files
        keep = self._number(last["data/chunk_index"], last["data/file_index"]) if last else -1
        for f in sorted((self.root / "data").glob("chunk-*/file-*.parquet")):
            n = self._number(f.parent.name[6:], f.stem[5:])
            if n > keep:
                f.unlink()
            elif n == keep:
                rows = sum(r["length"] for r in self.rows
                           if (r["data/chunk_index"], r["data/file_index"]) == (last["data/chunk_index"], last["data/file_index"]))
                if pq.read_metadata(f).num_rows != rows:
                    pf = pq.ParquetFile(f)
                    tmp = _tmp(f)
                    with pq.ParquetWriter(tmp, pf.schema_arrow) as w:
                        for g in range(pf.num_row_groups):
                            t = pf.read_row_group(g)
                            t = t.filter(pc.less(t.column("episode_index"), len(self.rows)))
                            if t.num_rows:
                                w.write_table(t)
                    _replace(tmp, f)
        # video files
        for cam in self.layout.cameras:
            k = video_key(cam)
            keep = self._number(last[f"videos/{k}/chunk_index"], last[f"videos/{k}/file_index"]) if last else -1
            for f in sorted((self.root / "videos" / k).glob("chunk-*/file-*.mp4")):
                n = self._number(f.parent.name[6:], f.stem[5:])
                if n > keep:
                    f.unlink()
                elif n == keep:
                    frames = round(last[f"videos/{k}/to_timestamp"] * self.layout.fps)
                    if mp4.frame_count(f) != frames:
                        tmp = _tmp(f)
                        mp4.join([(f, frames)], tmp)
                        _replace(tmp, f)

    # -- adding ------------------------------------------------------------------------------
    def add(self, ep: Episode) -> int | None:
        """Commit an episode: its frames appended to the current data and video files, then its
        row to the episodes metadata; record any attempt.

        Returns:
            The episode index, or None for a failed episode not kept (its videos are deleted).
        """
        if not self.keep_failed and discard_failed(self.meta, self.attempts, ep):
            return None
        index = len(self.rows)
        last = self.rows[-1] if self.rows else None
        if ep.instruction not in self.tasks:
            self.tasks.append(ep.instruction)
            self._write_tasks()  # a superset of the committed tasks until the commit: harmless
        task_index = self.tasks.index(ep.instruction)
        start = last["dataset_to_index"] if last else 0
        row = {"episode_index": index, "tasks": [ep.instruction], "length": ep.length,
               "dataset_from_index": start, "dataset_to_index": start + ep.length}
        row |= self._append_data(ep, last, index, start, task_index)
        for cam in self.layout.cameras:
            row |= self._append_video(cam, ep, last)
        meta_number = index // EPISODES_PER_META_FILE
        row |= {f"meta/episodes/{k}": v for k, v in self._where(meta_number).items()}
        stats = self.layout.stats(ep, index, start, task_index)
        row |= {f"stats/{name}/{s}": value for name, st in stats.items() for s, value in st.items()}
        row |= provenance(ep)
        path = self.root / EPISODES_PATH.format(**self._where(meta_number))
        rows = [r for r in self.rows if r["episode_index"] // EPISODES_PER_META_FILE == meta_number] + [row]
        tmp = _tmp(path)
        pq.write_table(self._episodes_table(rows), tmp)
        log_attempt(self.meta, self.attempts, ep)  # before the commit (rpg.demos.log)
        _replace(tmp, path)  # the commit
        self.rows.append(row)
        self._write_info()
        return index

    def _append_data(self, ep: Episode, last: dict | None, index: int, start: int, task_index: int) -> dict:
        number = self._number(last["data/chunk_index"], last["data/file_index"]) if last else 0
        path = self.root / DATA_PATH.format(**self._where(number))
        if last and path.stat().st_size >= self.data_mb * 1024**2:
            number += 1
            path = self.root / DATA_PATH.format(**self._where(number))
        table = self.layout.table(ep, index, start, task_index)
        tmp = _tmp(path)
        with pq.ParquetWriter(tmp, table.schema) as w:  # one row group per episode
            if last and path.is_file():
                old = pq.ParquetFile(path)
                for g in range(old.num_row_groups):
                    w.write_table(old.read_row_group(g))
            w.write_table(table)
        _replace(tmp, path)
        return {f"data/{k}": v for k, v in self._where(number).items()}

    def _append_video(self, cam: str, ep: Episode, last: dict | None) -> dict:
        k = video_key(cam)
        src = Path(ep.videos[cam])
        frames = mp4.frame_count(src)
        if frames != ep.length:
            raise ValueError(f"{src} holds {frames} frames for an episode of {ep.length} steps")
        fps = self.layout.fps
        if last:
            number = self._number(last[f"videos/{k}/chunk_index"], last[f"videos/{k}/file_index"])
            path = self.root / VIDEO_PATH.format(video_key=k, **self._where(number))
            before = round(last[f"videos/{k}/to_timestamp"] * fps)
            if path.stat().st_size >= self.video_mb * 1024**2 or mp4.stream_signature(path) != mp4.stream_signature(src):
                number, before = number + 1, 0
        else:
            number, before = 0, 0
        path = self.root / VIDEO_PATH.format(video_key=k, **self._where(number))
        tmp = _tmp(path)
        if before:
            mp4.join([(path, before), (src, None)], tmp)
            src.unlink()
        else:
            os.replace(src, tmp)
        _replace(tmp, path)
        return {f"videos/{k}/{key}": v for key, v in self._where(number).items()} | {
            f"videos/{k}/from_timestamp": before / fps, f"videos/{k}/to_timestamp": (before + ep.length) / fps}

    # -- derived metadata --------------------------------------------------------------------
    def _write_tasks(self) -> None:
        path = self.root / TASKS_PATH
        tmp = _tmp(path)
        pq.write_table(tasks_table(self.tasks), tmp)
        _replace(tmp, path)

    def _write_info(self) -> None:
        n = len(self.rows)
        names = [video_key(c) for c in self.layout.cameras] + list(self.layout.frame_features())
        per_episode = [{name: {s: r[f"stats/{name}/{s}"] for s in ("min", "max", "mean", "std", "count")}
                        for name in names} for r in self.rows]
        _write_json(self.meta / "stats.json", aggregate_stats(per_episode) if per_episode else {})
        _write_json(self.meta / "info.json", {
            "codebase_version": CODEBASE_VERSION, "robot_type": self.layout.robot_type,
            "total_episodes": n, "total_frames": self.rows[-1]["dataset_to_index"] if n else 0,
            "total_tasks": len({r["tasks"][0] for r in self.rows}), "chunks_size": self.chunks_size,
            "data_files_size_in_mb": self.data_mb, "video_files_size_in_mb": self.video_mb,
            "fps": self.layout.fps, "splits": {"train": f"0:{n}"}, "data_path": DATA_PATH,
            "video_path": VIDEO_PATH if self.layout.cameras else None,
            "features": self.layout.features(CODEBASE_VERSION), **self.layout.info_keys(),
        })


# -- reading (replay) ----------------------------------------------------------------------------
MAX_META_BYTES = 256 * 1024**2
"""Largest episodes metadata file replay reads, bytes (a row is a few KB)."""

MAX_DATA_BYTES = 2 * 1024**3
"""Largest data file replay opens, bytes (its footer and two columns are read, not the file)."""

MAX_COLUMN_BYTES = 256 * 1024**2
"""Most bytes the ``episode_index`` and ``action`` columns of a data file may declare uncompressed."""


def is_v3(root: str | Path) -> bool:
    """Whether ``root``'s ``meta/info.json`` declares LeRobot v3.0 (read bounded)."""
    from rpg.demos.lerobot import _peer_file

    root = Path(root)
    if not (root / "meta" / "info.json").is_file():
        return False
    try:
        info = json.loads(_peer_file(root, "meta/info.json", 16 * 1024**2))
    except ValueError:
        raise PeerError(f"{root}/meta/info.json is not JSON") from None
    return isinstance(info, dict) and info.get("codebase_version") == CODEBASE_VERSION


def _peer_parquet(root: Path, rel: str, limit: int):
    """A :class:`pyarrow.parquet.ParquetFile` of ``root/rel``: a regular file of at most
    ``limit`` bytes reached through no symbolic link."""
    here = root
    for part in Path(rel).parts:
        here = here / part
        if here.is_symlink():
            raise PeerError(f"{here} is a symbolic link; replay reads a dataset's own files only")
    if not here.is_file():
        raise PeerError(f"{here} is missing or not a regular file")
    if here.stat().st_size > limit:
        raise PeerError(f"{here} is {here.stat().st_size} bytes, over {limit}")
    try:
        return pq.ParquetFile(here)
    except (pa.ArrowException, OSError, ValueError) as exc:
        raise PeerError(f"{here} is not a parquet file ({' '.join(str(exc).split())[:200]})") from None


def read_episodes(root: str | Path, max_episodes: int = 100_000) -> list[dict]:
    """The committed episode rows of a v3.0 dataset (``final_poses`` decoded), each metadata
    file read only if at most :data:`MAX_META_BYTES`.

    Raises:
        PeerError: a symbolic link, a file too large or not parquet, a row whose
            ``final_poses`` is not JSON, or more than ``max_episodes`` rows.
    """
    root = Path(root)
    out = []
    base = root / "meta" / "episodes"
    if base.is_symlink():
        raise PeerError(f"{base} is a symbolic link; replay reads a dataset's own files only")
    for f in sorted(base.glob("chunk-*/file-*.parquet")):
        pf = _peer_parquet(root, str(f.relative_to(root)), MAX_META_BYTES)
        if len(out) + pf.metadata.num_rows > max_episodes:
            raise PeerError(f"{root}/meta/episodes lists more than {max_episodes} episodes")
        try:
            rows = pf.read().to_pylist()
        except (pa.ArrowException, OSError, ValueError) as exc:
            raise PeerError(f"{f} is not an episodes file ({' '.join(str(exc).split())[:200]})") from None
        for row in rows:
            poses = row.get("final_poses")
            try:
                row["final_poses"] = json.loads(poses) if isinstance(poses, str) else poses
            except ValueError:
                raise PeerError(f"{f}: final_poses of episode {row.get('episode_index')} is not JSON") from None
            out.append(row)
    return out


def read_episode_actions(root: str | Path, row: dict, max_steps: int = 100_000) -> np.ndarray:
    """The recorded actions (T, 7) float32 of the episode a metadata ``row`` describes, read
    from its data file after the file's size (:data:`MAX_DATA_BYTES`), the declared sizes of
    its ``episode_index`` and ``action`` columns (:data:`MAX_COLUMN_BYTES`) and the action
    column's type are checked, and only those two columns.

    Raises:
        PeerError: the row's file indices are not integers, the file is missing, a symbolic
            link, too large or not parquet, or its columns are out of bounds, or the episode
            has not 1 to ``max_steps`` rows.
    """
    root = Path(root)
    chunk, file, index = row.get("data/chunk_index"), row.get("data/file_index"), row.get("episode_index")
    if not all(type(v) is int and 0 <= v < 10**6 for v in (chunk, file, index)):
        raise PeerError(f"{root}: episode {index!r} names no data file (chunk {chunk!r}, file {file!r})")
    rel = DATA_PATH.format(chunk_index=chunk, file_index=file)
    pf = _peer_parquet(root, rel, MAX_DATA_BYTES)
    where = root / rel
    schema = pf.schema_arrow
    field = schema.field("action") if "action" in schema.names else None
    if (field is None or not pa.types.is_fixed_size_list(field.type) or field.type.list_size != len(ACTION_NAMES)
            or not pa.types.is_floating(field.type.value_type) or "episode_index" not in schema.names
            or not pa.types.is_integer(schema.field("episode_index").type)):
        raise PeerError(f"{where}: no action column of {len(ACTION_NAMES)} floats a row, or no integer episode_index")
    meta = pf.metadata
    declared = sum(meta.row_group(i).column(j).total_uncompressed_size
                   for i in range(meta.num_row_groups) for j in range(meta.num_columns)
                   if meta.row_group(i).column(j).path_in_schema.split(".")[0] in ("action", "episode_index"))
    if declared > MAX_COLUMN_BYTES:
        raise PeerError(f"{where}: its action and episode_index columns declare {declared} bytes, over {MAX_COLUMN_BYTES}")
    try:
        table = pf.read(columns=["episode_index", "action"])
    except (pa.ArrowException, OSError, ValueError) as exc:
        raise PeerError(f"{where} is not a data file ({' '.join(str(exc).split())[:200]})") from None
    mask = pc.equal(table.column("episode_index"), index)
    actions = table.filter(mask).column("action").combine_chunks()
    rows = len(actions)
    if not 1 <= rows <= max_steps:
        raise PeerError(f"{where} holds {rows} rows of episode {index}; an episode has 1 to {max_steps} steps")
    values = actions.flatten()
    if actions.null_count or values.null_count:
        raise PeerError(f"{where}: the action column of episode {index} has nulls")
    return values.to_numpy(zero_copy_only=False).astype(np.float32).reshape(rows, len(ACTION_NAMES))


__all__ = ["CODEBASE_VERSION", "INDEX_FEATURES", "LeRobotV3Writer", "is_v3", "read_episode_actions", "read_episodes",
           "tasks_table"]
