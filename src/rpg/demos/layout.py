"""What one frame of a LeRobot dataset holds (both format versions): the features of
``meta/info.json``, the parquet schema, an episode's table and its statistics.

Columns, in order (float32 unless said):

- ``observation.state`` (11): :data:`rpg.demos.record.STATE_NAMES` (TCP position, the first
  two columns of its rotation matrix, finger openings): no dimension jumps between frames;
- ``action`` (7): :data:`rpg.demos.record.ACTION_NAMES`;
- optional (``columns``, all by default):

  - ``joint_pos``: ``observation.joint_pos`` (9), :data:`rpg.demos.record.JOINT_NAMES`;
  - ``object_poses``: ``observation.object_poses`` (7 K): K object slots, each position and
    quaternion (w, x, y, z); slot k holds the episode's k-th object in sorted name order
    (its names are the episode's ``object_names``) and unused slots are zero.  The feature
    names are ``<object>.<x|y|z|qw|qx|qy|qz>``: the objects' own names when every task of
    the dataset has the same objects, else ``object_<k>``;
  - ``next``: ``next.reward`` (1), ``next.success`` and ``next.done`` (bool): the
    environment's reward and success after the step, and whether the episode ended there;

- ``timestamp`` (s from the episode's start), ``frame_index``, ``episode_index``, ``index``
  (over the dataset) and ``task_index`` (int64).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pyarrow as pa

from rpg.demos.mp4 import DEFAULT_GOP
from rpg.demos.record import ACTION_NAMES, JOINT_NAMES, POSE_FIELDS, STATE_NAMES, Episode
from rpg.domain import constants as C
from rpg.env.video import VIDEO_CODEC
from rpg.errors import BadInput

COLUMNS = ("joint_pos", "object_poses", "next")
"""The optional column groups (``rpg demos --columns``), all written by default."""

INDEX_FEATURES = ("timestamp", "frame_index", "episode_index", "index", "task_index")

VISUAL_KEY = "rpg_visual"
"""The key of ``meta/info.json`` (both LeRobot versions) that records the robot's meshes in the
videos (``decimated`` or ``stock``; :class:`rpg.env.BlockTaskEnv`'s ``visual``).  lerobot
keeps ``info.json`` as a plain mapping and reads only its own keys, so it loads such a
dataset unchanged (tested with lerobot 0.4).  A dataset written before the key existed has
the decimated meshes."""


SUPERSAMPLE_KEY = "rpg_wrist_supersample"
"""The key of ``meta/info.json`` (both LeRobot versions), next to :data:`VISUAL_KEY`, that
records how the wrist camera's video frames were drawn: ``wrist_supersample`` of
:class:`rpg.env.BlockTaskEnv` (1: at the image size; 2: at twice the size per side and each
2x2 block averaged).  A dataset written before the key existed has 1."""


def recorded_visual(info: dict) -> str:
    """The ``visual`` a LeRobot dataset's ``meta/info.json`` records (``decimated`` if none)."""
    return info.get(VISUAL_KEY, "decimated")


def recorded_wrist_supersample(info: dict) -> int:
    """The ``wrist_supersample`` a LeRobot dataset's ``meta/info.json`` records (1 if none)."""
    return info.get(SUPERSAMPLE_KEY, 1)


def video_key(camera: str) -> str:
    """LeRobot's feature name of a camera's video."""
    return f"observation.images.{camera}"


def check_columns(columns) -> tuple[str, ...]:
    """The optional column groups named, in :data:`COLUMNS` order.

    Raises:
        BadInput: an unknown name.
    """
    columns = tuple(columns)
    unknown = sorted(set(columns) - set(COLUMNS))
    if unknown:
        raise BadInput(f"unknown column group {', '.join(unknown)}; the optional columns are {', '.join(COLUMNS)}")
    return tuple(c for c in COLUMNS if c in columns)


def stats_of(values: np.ndarray) -> dict:
    """LeRobot's statistics of a feature over an episode's frames: per dimension min, max,
    mean and std, and the frame count."""
    v = np.asarray(values, np.float64).reshape(len(values), -1)
    return {"min": v.min(0).tolist(), "max": v.max(0).tolist(), "mean": v.mean(0).tolist(),
            "std": v.std(0).tolist(), "count": [len(v)]}


def aggregate_stats(per_episode: list[dict]) -> dict:
    """The dataset's statistics (``meta/stats.json``) from the episodes': elementwise min and
    max, count-weighted mean, pooled std, total count (LeRobot's ``aggregate_stats``)."""
    out = {}
    for key in sorted({k for s in per_episode for k in s}):
        items = [s[key] for s in per_episode if key in s]
        counts = np.array([float(s["count"][0]) for s in items])
        means = np.array([np.asarray(s["mean"], np.float64) for s in items])
        total = counts.sum()
        w = counts.reshape((-1,) + (1,) * (means.ndim - 1))
        mean = (w * means).sum(0) / total
        var = (w * (np.array([np.asarray(s["std"], np.float64) for s in items]) ** 2 + (means - mean) ** 2)).sum(0) / total
        out[key] = {"min": np.min([np.asarray(s["min"], np.float64) for s in items], 0).tolist(),
                    "max": np.max([np.asarray(s["max"], np.float64) for s in items], 0).tolist(),
                    "mean": mean.tolist(), "std": np.sqrt(np.maximum(var, 0.0)).tolist(), "count": [int(total)]}
    return out


@dataclass(frozen=True)
class Layout:
    """A dataset's frame layout.

    Args:
        robot_type: the embodiment (names ``observation.joint_pos``).
        cameras: cameras recorded as videos.
        image_size: (height, width) of the videos.
        columns: the optional column groups (:data:`COLUMNS`).
        objects: names of the ``observation.object_poses`` slots.
        gop: most frames between keyframes of the videos.
        visual: the robot's meshes in the images, ``decimated`` or ``stock``
            (:class:`rpg.env.BlockTaskEnv`'s ``visual``), recorded as ``meta/info.json``'s
            :data:`VISUAL_KEY`.
        wrist_supersample: the wrist camera's supersampling factor per side (1: off;
            :class:`rpg.env.BlockTaskEnv`'s ``wrist_supersample``), recorded as
            ``meta/info.json``'s :data:`SUPERSAMPLE_KEY`.
    """

    robot_type: str
    cameras: tuple[str, ...]
    image_size: tuple[int, int]
    columns: tuple[str, ...] = COLUMNS
    objects: tuple[str, ...] = ()
    gop: int = DEFAULT_GOP
    visual: str = "decimated"
    wrist_supersample: int = 1

    def info_keys(self) -> dict:
        """rpg's keys of ``meta/info.json``: how the images were drawn."""
        return {VISUAL_KEY: self.visual, SUPERSAMPLE_KEY: self.wrist_supersample}

    @property
    def fps(self) -> int:
        return int(C.CONTROL_HZ)

    def frame_features(self) -> dict:
        """The non-video features, in column order."""
        out = {"observation.state": {"dtype": "float32", "shape": [len(STATE_NAMES)], "names": list(STATE_NAMES)},
               "action": {"dtype": "float32", "shape": [len(ACTION_NAMES)], "names": list(ACTION_NAMES)}}
        if "joint_pos" in self.columns:
            names = JOINT_NAMES.get(self.robot_type) or [f"qpos_{i}" for i in range(9)]
            out["observation.joint_pos"] = {"dtype": "float32", "shape": [len(names)], "names": list(names)}
        if "object_poses" in self.columns:
            names = [f"{o}.{f}" for o in self.objects for f in POSE_FIELDS]
            out["observation.object_poses"] = {"dtype": "float32", "shape": [len(names)], "names": names}
        if "next" in self.columns:
            out["next.reward"] = {"dtype": "float32", "shape": [1], "names": None}
            out["next.success"] = {"dtype": "bool", "shape": [1], "names": None}
            out["next.done"] = {"dtype": "bool", "shape": [1], "names": None}
        for name, dtype in zip(INDEX_FEATURES, ("float32", "int64", "int64", "int64", "int64"), strict=True):
            out[name] = {"dtype": dtype, "shape": [1], "names": None}
        return out

    def video_features(self, version: str) -> dict:
        """The cameras' features; ``version`` ``"v2.1"`` or ``"v3.0"`` (frame rate as a float
        or an integer, as each LeRobot version writes it)."""
        h, w = self.image_size
        fps = float(self.fps) if version == "v2.1" else self.fps
        return {video_key(cam): {
            "dtype": "video", "shape": [h, w, 3], "names": ["height", "width", "channels"],
            "info": {"video.height": h, "video.width": w, "video.codec": "h264", "video.pix_fmt": "yuv420p",
                     "video.is_depth_map": False, "video.fps": fps, "video.channels": 3, "has_audio": False,
                     "video.g": self.gop, "encoder": VIDEO_CODEC}} for cam in self.cameras}

    def features(self, version: str) -> dict:
        """``meta/info.json``'s feature table: the videos, then the frame columns."""
        return {**self.video_features(version), **self.frame_features()}

    def schema(self) -> pa.Schema:
        """The parquet schema of the frames."""
        types = {"float32": pa.float32(), "int64": pa.int64(), "bool": pa.bool_()}
        fields = []
        for name, ft in self.frame_features().items():
            t = types[ft["dtype"]]
            fields.append((name, t if ft["shape"] == [1] else pa.list_(t, ft["shape"][0])))
        return pa.schema(fields)

    def _object_columns(self, ep: Episode) -> np.ndarray:
        slots = len(self.objects)
        if len(ep.object_names) > slots:
            raise BadInput(f"{ep.task_name} has {len(ep.object_names)} objects; this dataset's "
                           f"observation.object_poses holds {slots}; give a new --out directory")
        out = np.zeros((ep.length, 7 * slots), np.float32)
        out[:, : ep.object_poses.shape[1]] = ep.object_poses[: ep.length]
        return out

    def columns_of(self, ep: Episode, index: int, start: int, task_index: int) -> dict[str, np.ndarray]:
        """Episode ``index``'s frame columns as arrays (T rows), its first frame at dataset index ``start``."""
        n = ep.length
        frame = np.arange(n, dtype=np.int64)
        cols = {"observation.state": np.asarray(ep.states, np.float32), "action": np.asarray(ep.actions, np.float32)}
        if "joint_pos" in self.columns:
            cols["observation.joint_pos"] = np.asarray(ep.joint_pos, np.float32)
        if "object_poses" in self.columns:
            cols["observation.object_poses"] = self._object_columns(ep)
        if "next" in self.columns:
            done = np.zeros(n, bool)
            done[-1:] = True
            cols["next.reward"] = np.asarray(ep.rewards, np.float32)
            cols["next.success"] = np.asarray(ep.successes, bool)
            cols["next.done"] = done
        cols["timestamp"] = (frame / self.fps).astype(np.float32)
        cols["frame_index"] = frame
        cols["episode_index"] = np.full(n, index, np.int64)
        cols["index"] = start + frame
        cols["task_index"] = np.full(n, task_index, np.int64)
        return cols

    def table(self, ep: Episode, index: int, start: int, task_index: int) -> pa.Table:
        """Episode ``index``'s frames as a table of :meth:`schema`."""
        cols = self.columns_of(ep, index, start, task_index)
        schema = self.schema()
        arrays = []
        for f in schema:
            v = cols[f.name]
            if pa.types.is_fixed_size_list(f.type):
                arrays.append(pa.FixedSizeListArray.from_arrays(pa.array(v.reshape(-1), f.type.value_type),
                                                                f.type.list_size))
            else:
                arrays.append(pa.array(v, f.type))
        return pa.Table.from_arrays(arrays, schema=schema)

    def stats(self, ep: Episode, index: int, start: int, task_index: int) -> dict:
        """The episode's statistics per feature (LeRobot's ``episodes_stats``), videos included."""
        cols = self.columns_of(ep, index, start, task_index)
        out = {name: stats_of(v) for name, v in cols.items()}
        out |= {video_key(c): ep.image_stats[c] for c in self.cameras}
        return out


def check_existing(root: Path, layout: Layout, version: str, other_format: str) -> dict | None:
    """The ``meta/info.json`` of a LeRobot dataset already in ``root`` (None if there is none),
    checked to be one this writer can append to: format ``version``, the same robot, cameras,
    image size, columns, keyframe interval, meshes (``visual``) and wrist supersampling.

    Raises:
        BadInput: a robomimic dataset, another LeRobot version (``other_format`` is the
            ``--format`` that writes it), or another embodiment, cameras, image size, columns,
            keyframe interval, ``visual`` or ``wrist_supersample``.
    """
    meta = root / "meta"
    if (meta / "rpg_robomimic.json").is_file():
        raise BadInput(f"{root} holds a robomimic (HDF5) dataset; give a new --out directory for --format lerobot")
    info = meta / "info.json"
    if not info.is_file():
        return None
    old = json.loads(info.read_text())
    if old.get("codebase_version") != version:
        raise BadInput(f"{root} holds a LeRobot {old.get('codebase_version')} dataset; write it with "
                       f"--format {other_format} or give a new --out directory")
    new = json.loads(json.dumps(layout.features(version)))
    if old.get("robot_type") != layout.robot_type or old.get("features") != new:
        raise BadInput(f"{root} holds a dataset of another embodiment, cameras, image size, columns "
                       "or keyframe interval; give a new --out directory")
    if recorded_visual(old) != layout.visual:
        raise BadInput(f"{root} holds a dataset recorded with --visual {recorded_visual(old)}; give that "
                       "or a new --out directory")
    if recorded_wrist_supersample(old) != layout.wrist_supersample:
        raise BadInput(f"{root} holds a dataset recorded with --wrist-supersample {recorded_wrist_supersample(old)}; "
                       "give that or a new --out directory")
    return old
