"""Demonstrations in robomimic's HDF5 layout (``rpg demos --format hdf5``), written with h5py::

    DIR/demo.hdf5
      data/                     attrs: total (steps of all demos), env_args (JSON: env_name,
                                type 2 = a Gym environment, env_kwargs: below)
        demo_<i>/               attrs: num_samples (T), and rpg's provenance: task, task_hash,
                                task_name, seed, embodiment, instruction, paraphrase (-1: none),
                                final_poses (JSON), success (1, or 0 for a failed episode kept
                                with --keep-failed)
          actions               (T, 7) float32, ee_delta actions in [-1, 1]
          rewards               (T,) float64, the environment's reward after each step
          dones                 (T,) int64, 1 at the last step
          states                (T, S) float64, the MuJoCo state before each step
                                (``mj_getState`` with :data:`rpg.demos.record.SIM_STATE`)
          obs/<key>, next_obs/<key>   the observation before / after each step (T rows each)
      mask/train, mask/valid    robomimic's filter keys of a 90/10 split by episode: of each
                                task's successful demos in recording order, every tenth
                                (the 10th, 20th, ...) is in valid, the others in train
      mask/failed               failed demos kept with --keep-failed (in neither split)
      mask/<task_name>          the demos of each task (bytes)

Observation keys: the embodiment's :data:`rpg.demos.record.LOW_DIM_KEYS` (float64: the Panda's
``robot0_joint_pos`` holds its seven arm joints, as robosuite's; the floating gripper has no
arm joints and its free joint's pose is ``robot0_hand_pos`` and ``robot0_hand_quat``;
``robot0_gripper_qpos`` has robosuite's PandaGripper signs, (0.04, -0.04) open) and one uint8
(T, H, W, 3) image per camera (:data:`IMAGE_KEYS`: ``agentview_image``,
``robot0_eye_in_hand_image`` for the wrist camera), gzip-compressed one frame per chunk.  This
is what robomimic's ``SequenceDataset`` loads (``obs``, ``next_obs``, ``actions``, ``rewards``,
``dones``, the ``env_args`` attribute and filter keys).

``env_kwargs`` says how to rebuild the environment: every keyword of
:class:`rpg.env.BlockTaskEnv` the demos were recorded with that shapes what it observes or how
an episode ends (:data:`ENV_KEYWORDS`: ``embodiment``, ``control_mode``, ``cameras``,
``image_size``, ``visual``, ``wrist_supersample``, ``privileged``, ``terminate_on_success``,
``max_episode_steps``; the
instruction is each demo's own), ``tasks`` (every task's content hash -> its path in the library
it was recorded from, a hint), and for a file of one task ``task_hash`` and ``task`` (that
path).  :func:`make_env_from_metadata` rebuilds it, finding the task by its content hash in a
library the caller names (a path recorded in a file is never loaded).

Crash safety: HDF5 files are not safe to append to across a kill, so each committed episode
is first a file of its own, ``DIR/parts/demo_<i>.hdf5`` (written to a temporary name, then
renamed), and its line in ``DIR/meta/episodes.jsonl`` is the commit (``meta/rpg_attempts.jsonl``
records failed attempts too).  :meth:`RobomimicWriter.finalize` gathers the parts and the
demos of an existing ``demo.hdf5`` into a new file, renames it over ``demo.hdf5`` and then
removes the parts; a kill at any point leaves every committed episode in a part or in
``demo.hdf5``, and the next run resumes from there.

Reading for replay (:func:`read_demos`, :func:`read_demo_actions`) treats the file as a
peer's: links must be hard links, provenance attributes scalars of bounded size, and an
``actions`` dataset is checked (float, (T, 7) with T bounded, stored in the file in bounded
chunks) before any of it is read, so an 8 KB file declaring a (10**9, 7) dataset is refused
without allocating.
"""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

import h5py
import numpy as np

from rpg.demos.log import discard_failed, log_attempt, settle_attempts
from rpg.demos.record import Episode
from rpg.errors import BadInput, PeerError
from rpg.jsonl import append_jsonl, read_jsonl, rewrite_jsonl

DATASET_NAME = "demo.hdf5"
"""The robomimic file inside a dataset directory."""

ENV_NAME = "rpg/BlockTask-v0"
"""``env_args["env_name"]``: the Gymnasium id the demos were recorded in."""

GYM_ENV_TYPE = 2
"""``env_args["type"]``: robomimic's ``EnvType.GYM_TYPE``."""

IMAGE_KEYS = {"agentview": "agentview_image", "wrist": "robot0_eye_in_hand_image", "default": "default_image"}
"""robomimic's observation key of each camera's images."""

IMAGE_COMPRESSION = {"compression": "gzip", "compression_opts": 4}
"""h5py filter of image datasets (gzip: readable by every HDF5 library)."""

SETTINGS = "rpg_robomimic.json"
"""``meta/`` file with the dataset's embodiment, cameras and image size (a resumed run must match)."""


class FrameStore:
    """One camera's frames of an episode in an HDF5 file, written as they come: frame k goes
    to ``obs`` and, for k >= 1, to ``next_obs`` (so neither is rewritten when the episode is
    committed).  On close ``obs`` drops its last frame, so both hold T frames for T + 1
    written.  Like :class:`rpg.env.video.VideoWriter`, the file appears only when closed
    without error.

    Raises:
        ValueError: a frame that is not (H, W, 3) uint8-convertible, or of another shape than the first.
    """

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self._tmp = self.path.with_name(f".{self.path.name}.tmp-{os.getpid()}")
        self._file: h5py.File | None = None
        self.frames = 0

    def __enter__(self) -> FrameStore:
        return self

    def write(self, frame: np.ndarray) -> None:
        frame = np.ascontiguousarray(frame, dtype=np.uint8)
        if self._file is None:
            if frame.ndim != 3 or frame.shape[2] != 3:
                raise ValueError(f"frames must be (H, W, 3), got {frame.shape}")
            self._file = h5py.File(self._tmp, "w")
            for name in ("obs", "next_obs"):
                self._file.create_dataset(name, shape=(0, *frame.shape), maxshape=(None, *frame.shape), dtype=np.uint8,
                                          chunks=(1, *frame.shape), **IMAGE_COMPRESSION)
        obs = self._file["obs"]
        if frame.shape != obs.shape[1:]:
            raise ValueError(f"frame shape {frame.shape} differs from the first frame's {obs.shape[1:]}")
        targets = [obs] + ([self._file["next_obs"]] if self.frames else [])
        for ds in targets:
            ds.resize(ds.shape[0] + 1, axis=0)
            ds[-1] = frame
        self.frames += 1

    def __exit__(self, exc_type, *exc) -> None:
        try:
            if self._file is not None:
                if exc_type is None:
                    self._file["obs"].resize(max(self.frames - 1, 0), axis=0)
                self._file.close()
            if exc_type is None and self.frames:
                os.replace(self._tmp, self.path)
        finally:
            self._tmp.unlink(missing_ok=True)


class RobomimicWriter:
    """Appends recorded episodes to a robomimic dataset directory (resumable); the same
    interface as :class:`rpg.demos.lerobot.LeRobotWriter`, plus :meth:`finalize`.

    Args:
        root: the dataset directory (created).
        cameras: cameras recorded as images.
        image_size: (height, width) of the images.
        robot_type: the embodiment.
        visual: the robot's meshes in the images (``decimated`` or ``stock``).
        wrist_supersample: the wrist camera's supersampling factor per side (1: off).
    """

    def __init__(self, root: str | Path, cameras: tuple[str, ...], image_size: tuple[int, int], robot_type: str,
                 keep_failed: bool = False, task_paths: dict[str, str] | None = None, visual: str = "decimated",
                 wrist_supersample: int = 1):
        self.root = Path(root)
        self.visual = visual
        self.wrist_supersample = int(wrist_supersample)
        self.cameras = tuple(cameras)
        self.image_size = tuple(image_size)
        self.robot_type = robot_type
        self.keep_failed = keep_failed
        self.task_paths = dict(task_paths or {})
        self.episodes: list[dict] = []
        self.attempts: list[dict] = []

    @property
    def meta(self) -> Path:
        return self.root / "meta"

    @property
    def parts(self) -> Path:
        return self.root / "parts"

    def _settings(self) -> dict:
        return {"format": "robomimic", "robot_type": self.robot_type, "cameras": list(self.cameras),
                "image_size": list(self.image_size), "visual": self.visual,
                "wrist_supersample": self.wrist_supersample}

    def open(self) -> None:
        """Read what a previous run committed and remove what a kill left half-written.

        Raises:
            BadInput: the directory holds another kind of dataset, or one of another
                embodiment, cameras or image size.
        """
        if (self.meta / "info.json").is_file():
            raise BadInput(f"{self.root} holds a LeRobot dataset; give a new --out directory for --format hdf5")
        settings = self.meta / SETTINGS
        if settings.is_file():
            # a dataset from before ``visual`` or ``wrist_supersample`` was recorded has the defaults
            old = {"visual": "decimated", "wrist_supersample": 1} | json.loads(settings.read_text())
            if old != self._settings():
                changed = sorted(k for k in set(old) | set(self._settings()) if old.get(k) != self._settings().get(k))
                raise BadInput(f"{self.root} holds a dataset of another {', '.join(changed)}; give the same "
                               "settings or a new --out directory")
        elif self.root.is_dir() and any(p.name != ".staging" for p in self.root.iterdir()):
            raise BadInput(f"{self.root} is not empty and holds no rpg robomimic dataset; give a new --out directory")
        self.meta.mkdir(parents=True, exist_ok=True)
        self.parts.mkdir(exist_ok=True)
        settings.write_text(json.dumps(self._settings(), indent=2, sort_keys=True) + "\n")
        self.episodes = read_jsonl(self.meta / "episodes.jsonl")
        n = len(self.episodes)
        for f in sorted(self.parts.glob("demo_*.hdf5")):
            if int(f.stem.split("_")[1]) >= n:  # written, never committed
                f.unlink()
        for f in sorted(self.root.rglob(".*tmp*")):
            f.unlink()
        rewrite_jsonl(self.meta / "episodes.jsonl", self.episodes)
        self.attempts = settle_attempts(self.meta, self.episodes)

    def add(self, ep: Episode) -> int | None:
        """Commit an episode as a part file; record any attempt.

        Returns:
            The episode index, or None for a failed episode not kept (its frame stores are deleted).
        """
        if not self.keep_failed and discard_failed(self.meta, self.attempts, ep):
            return None
        index = len(self.episodes)
        line = {"episode_index": index, "length": ep.length, "task": ep.task, "task_hash": ep.task_hash,
                "task_name": ep.task_name, "seed": ep.seed, "embodiment": ep.embodiment,
                "instruction": ep.instruction, "paraphrase": ep.paraphrase, "final_poses": ep.final_poses,
                "success": bool(ep.success), "task_path": self.task_paths.get(ep.task_hash)}
        part = self.parts / f"demo_{index}.hdf5"
        tmp = part.with_name(f".{part.name}.tmp-{os.getpid()}")
        try:
            with h5py.File(tmp, "w") as f:
                _write_demo(f.create_group("demo"), ep, line)
            os.replace(tmp, part)
        finally:
            tmp.unlink(missing_ok=True)
        for v in ep.videos.values():
            Path(v).unlink(missing_ok=True)
        log_attempt(self.meta, self.attempts, ep)  # before the commit (rpg.demos.log)
        append_jsonl(self.meta / "episodes.jsonl", line)  # the commit
        self.episodes.append(line)
        return index

    def finalize(self) -> Path:
        """Gather every committed episode into ``demo.hdf5`` (a new file renamed over the old
        one), then remove the parts.

        Raises:
            BadInput: a committed episode is in neither a part nor ``demo.hdf5`` (the
                directory was changed by hand).
        """
        target = self.root / DATASET_NAME
        parts = sorted(self.parts.glob("demo_*.hdf5")) if self.parts.is_dir() else []
        if target.is_file() and not parts:
            return target
        tmp = target.with_name(f".{target.name}.tmp-{os.getpid()}")
        old = h5py.File(target, "r") if target.is_file() else None
        try:
            with h5py.File(tmp, "w") as dst:
                data = dst.create_group("data")
                masks: dict[str, list[str]] = {}
                for line in self.episodes:
                    name = f"demo_{line['episode_index']}"
                    part = self.parts / f"{name}.hdf5"
                    if part.is_file():
                        with h5py.File(part, "r") as src:
                            src.copy(src["demo"], data, name=name)
                    elif old is not None and name in old.get("data", {}):
                        old.copy(old["data"][name], data, name=name)
                    else:
                        raise BadInput(f"{self.root}: committed episode {name} is missing (parts/ or {DATASET_NAME} "
                                       "was changed); give a new --out directory")
                    masks.setdefault(line["task_name"], []).append(name)
                data.attrs["total"] = int(sum(e["length"] for e in self.episodes))
                data.attrs["env_args"] = json.dumps(self.env_args(), sort_keys=True)
                split = split_train_valid(self.episodes)
                for key in ("train", "valid", "failed"):
                    if key in masks:
                        raise BadInput(f"a task is named {key!r}, robomimic's name of a filter key; rename it")
                    masks[key] = split[key]
                mask = dst.create_group("mask")
                for name in sorted(masks):
                    mask.create_dataset(name, data=np.array(masks[name], dtype="S"))
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        finally:
            if old is not None:
                old.close()
        os.replace(tmp, target)
        for p in parts:
            p.unlink()
        return target


    def env_args(self) -> dict:
        """robomimic's ``env_args``: the environment and how to rebuild it (module docstring)."""
        tasks = {}
        for e in self.episodes:
            tasks.setdefault(e["task_hash"], e.get("task_path") or self.task_paths.get(e["task_hash"]))
        kwargs = {"embodiment": self.robot_type, "control_mode": "ee_delta", "cameras": list(self.cameras),
                  "image_size": list(self.image_size), "visual": self.visual,
                  "wrist_supersample": self.wrist_supersample, "privileged": False,
                  "terminate_on_success": True, "max_episode_steps": None, "tasks": tasks}
        if len(tasks) == 1:
            (h, p), = tasks.items()
            kwargs |= {"task_hash": h, "task": p}
        return {"env_name": ENV_NAME, "type": GYM_ENV_TYPE, "env_kwargs": kwargs}


ENV_KEYWORDS = ("embodiment", "control_mode", "cameras", "image_size", "visual", "wrist_supersample",
                "privileged", "terminate_on_success", "max_episode_steps")
"""The keywords of :class:`rpg.env.BlockTaskEnv` that ``env_kwargs`` records and
:func:`make_env_from_metadata` passes back (the embodiment is each demo's own, checked against
its provenance; the instruction likewise).  A file from before ``visual``,
``wrist_supersample``, ``privileged``, ``terminate_on_success`` and ``max_episode_steps`` were
recorded gets the environment's defaults, which are what the demos were recorded with."""


VALID_EVERY = 10
"""Of each task's successful demos in recording order, the 10th, 20th, ... are in ``mask/valid``."""


def split_train_valid(episodes: list[dict]) -> dict[str, list[str]]:
    """robomimic's ``train`` / ``valid`` filter keys (and ``failed``) of committed episode
    records (``episode_index``, ``task_hash``, ``success``): per task, its successful demos in
    index order, every :data:`VALID_EVERY`-th in ``valid`` and the rest in ``train`` (a 90/10
    split that a resumed run only extends); failed ones in ``failed``."""
    out: dict[str, list[str]] = {"train": [], "valid": [], "failed": []}
    seen: dict[str, int] = {}
    for e in sorted(episodes, key=lambda e: e["episode_index"]):
        name = f"demo_{e['episode_index']}"
        if not e.get("success", True):
            out["failed"].append(name)
            continue
        k = seen.get(e["task_hash"], 0)
        seen[e["task_hash"]] = k + 1
        out["valid" if k % VALID_EVERY == VALID_EVERY - 1 else "train"].append(name)
    return out


def _write_demo(g: h5py.Group, ep: Episode, line: dict) -> None:
    """One episode into group ``g`` (robomimic's ``data/demo_<i>`` layout)."""
    t = ep.length
    g.attrs["num_samples"] = t
    for key in ("task", "task_hash", "task_name", "seed", "embodiment", "instruction"):
        g.attrs[key] = line[key]
    g.attrs["paraphrase"] = -1 if ep.paraphrase is None else int(ep.paraphrase)
    g.attrs["final_poses"] = json.dumps(ep.final_poses, sort_keys=True)
    g.attrs["success"] = int(bool(ep.success))
    g.create_dataset("actions", data=np.asarray(ep.actions, np.float32))
    g.create_dataset("rewards", data=np.asarray(ep.rewards, np.float64))
    dones = np.zeros(t, np.int64)
    dones[-1:] = 1
    g.create_dataset("dones", data=dones)
    g.create_dataset("states", data=np.asarray(ep.sim_states[:t], np.float64))
    obs, nxt = g.create_group("obs"), g.create_group("next_obs")
    for key in ep.low_dim:
        values = np.asarray(ep.low_dim[key], np.float64)
        obs.create_dataset(key, data=values[:t])
        nxt.create_dataset(key, data=values[1:t + 1])
    for cam, path in sorted(ep.videos.items()):
        with h5py.File(path, "r") as src:  # raw chunk copies: no recompression
            src.copy(src["obs"], obs, name=IMAGE_KEYS[cam])
            src.copy(src["next_obs"], nxt, name=IMAGE_KEYS[cam])


def dataset_file(root: str | Path) -> Path | None:
    """The robomimic file of a dataset directory (or the file itself), None if there is none."""
    root = Path(root)
    if root.is_file() and h5py.is_hdf5(root):
        return root
    f = root / DATASET_NAME
    return f if f.is_file() else None


MAX_ATTR_BYTES = 1024**2
"""Largest provenance attribute replay reads (``final_poses`` is the longest: ~100 bytes a body), bytes."""

MAX_STEPS = 100_000
"""Largest ``max_episode_steps`` :func:`make_env_from_metadata` accepts from ``env_kwargs``."""

MAX_CHUNK_BYTES = 64 * 1024**2
"""Largest HDF5 chunk of an ``actions`` dataset replay reads (a chunk is decompressed whole), bytes."""

_PROVENANCE = ("task_hash", "task_name", "seed", "embodiment", "instruction", "final_poses")
_DEMO = re.compile(r"demo_([0-9]{1,9})")


def _refuse(path, why: str) -> PeerError:
    return PeerError(f"{path} is refused: {why}")


def _hard_child(group: h5py.Group, name: str, path, kind: type):
    """``group[name]`` if it is a hard link to a ``kind`` (a soft or external link could name
    another object or another file)."""
    link = group.get(name, getlink=True)
    if link is None:
        raise _refuse(path, f"{group.name}/{name} is missing")
    if not isinstance(link, h5py.HardLink):
        raise _refuse(path, f"{group.name}/{name} is a {type(link).__name__}, not a hard link")
    obj = group[name]
    if not isinstance(obj, kind):
        raise _refuse(path, f"{group.name}/{name} is not a {kind.__name__}")
    return obj


def _attr(g: h5py.Group, key: str, path):
    """Attribute ``key`` of ``g``, read only once its declared shape (a scalar), dtype (a
    string or an integer) and storage (at most :data:`MAX_ATTR_BYTES`) are checked."""
    if key not in g.attrs:
        raise _refuse(path, f"{g.name} has no attribute {key!r}")
    aid = g.attrs.get_id(key)
    dt = aid.dtype
    is_str = h5py.check_string_dtype(dt) is not None
    if aid.shape not in ((), None) or not (is_str or dt.kind in "iu") or aid.get_storage_size() > MAX_ATTR_BYTES:
        raise _refuse(path, f"attribute {key!r} of {g.name} is not a scalar string or integer of at most "
                            f"{MAX_ATTR_BYTES} bytes")
    value = g.attrs[key]
    if isinstance(value, bytes):
        value = value.decode("utf-8")
    if isinstance(value, np.integer):
        value = int(value)
    if isinstance(value, str) and len(value) > MAX_ATTR_BYTES:
        raise _refuse(path, f"attribute {key!r} of {g.name} is longer than {MAX_ATTR_BYTES} characters")
    return value


def _actions(g: h5py.Group, path, max_steps: int) -> h5py.Dataset:
    """``g/actions``, checked before any of it is read: a float dataset (T, 7) with
    1 <= T <= ``max_steps``, stored in the file itself (not external, not virtual) in chunks of
    at most :data:`MAX_CHUNK_BYTES`."""
    ds = _hard_child(g, "actions", path, h5py.Dataset)
    dt = ds.dtype
    if dt.kind != "f" or dt.fields is not None or dt.subdtype is not None or dt.itemsize > 8:
        raise _refuse(path, f"{ds.name} has dtype {dt}; actions must be float")
    if len(ds.shape) != 2 or ds.shape[1] != 7 or not 1 <= ds.shape[0] <= max_steps:
        raise _refuse(path, f"{ds.name} declares shape {ds.shape}; actions must be (T, 7) with 1 <= T <= {max_steps}")
    if ds.is_virtual or ds.external:
        raise _refuse(path, f"{ds.name} is stored outside the file (virtual or external)")
    if ds.chunks is not None and math.prod(ds.chunks) * dt.itemsize > MAX_CHUNK_BYTES:
        raise _refuse(path, f"{ds.name} declares chunks {ds.chunks}, over {MAX_CHUNK_BYTES} bytes")
    return ds


def _demos(f: h5py.File, path, max_episodes: int) -> list[tuple[int, h5py.Group]]:
    data = _hard_child(f, "data", path, h5py.Group)
    if len(data) > max_episodes:
        raise _refuse(path, f"it holds {len(data)} demos, more than {max_episodes}")
    out = []
    for name in data:
        m = _DEMO.fullmatch(name)
        if m is None:
            raise _refuse(path, f"data/{name[:60]!r} is not named demo_<i>")
        out.append((int(m.group(1)), _hard_child(data, name, path, h5py.Group)))
    return sorted(out, key=lambda x: x[0])


def read_demos(path: str | Path, max_episodes: int = 100_000, max_steps: int = 100_000) -> list[dict]:
    """Every demo of a robomimic file written by rpg: its provenance, in demo order.  Each
    demo's ``actions`` dataset is checked (:func:`read_demo_actions`'s bounds) but not read.

    Returns:
        Dicts with ``episode_index``, ``task_hash``, ``task_name``, ``seed``, ``embodiment``,
        ``instruction`` and ``final_poses`` (JSON-decoded); the recorded ``task`` path is
        not read.

    Raises:
        BadInput: not an HDF5 file.
        PeerError: more than ``max_episodes`` demos, a demo not named ``demo_<i>``, a link
            that is not a hard link, a provenance attribute that is missing or not a scalar
            string or integer of at most :data:`MAX_ATTR_BYTES`, or an ``actions`` dataset
            out of bounds.
    """
    out = []
    try:
        with h5py.File(path, "r") as f:
            for index, g in _demos(f, path, max_episodes):
                _actions(g, path, max_steps)
                doc = {"episode_index": index, **{k: _attr(g, k, path) for k in _PROVENANCE}}
                if "success" in g.attrs:
                    success = _attr(g, "success", path)
                    if success not in (0, 1):
                        raise _refuse(path, f"attribute 'success' of {g.name} is not 0 or 1")
                    doc["success"] = bool(success)
                try:
                    doc["final_poses"] = json.loads(doc["final_poses"])
                except (TypeError, ValueError):
                    raise _refuse(path, f"final_poses of {g.name} is not JSON") from None
                out.append(doc)
    except PeerError:
        raise
    except (KeyError, ValueError, OSError, TypeError) as exc:
        raise BadInput(f"{path} is not a robomimic dataset written by rpg demos ({exc})") from None
    return out


def read_demo_actions(path: str | Path, index: int, max_steps: int = 100_000) -> np.ndarray:
    """The actions (T, 7) float32 of ``data/demo_<index>``, read only after the dataset's
    shape (1 <= T <= ``max_steps``), dtype (float) and storage (in the file, chunks of at
    most :data:`MAX_CHUNK_BYTES`) are checked, so a small file cannot make this allocate more
    than ``max_steps`` x 7 x 8 bytes.

    Raises:
        BadInput: not an HDF5 file.
        PeerError: no such demo, or its actions are out of bounds.
    """
    try:
        with h5py.File(path, "r") as f:
            data = _hard_child(f, "data", path, h5py.Group)
            ds = _actions(_hard_child(data, f"demo_{int(index)}", path, h5py.Group), path, max_steps)
            return np.asarray(ds[()], np.float32)
    except PeerError:
        raise
    except (KeyError, ValueError, OSError, TypeError) as exc:
        raise BadInput(f"{path} is not a robomimic dataset written by rpg demos ({exc})") from None


def read_env_args(path: str | Path) -> dict:
    """The ``env_args`` of a robomimic file written by rpg, read as a peer's (a scalar
    string attribute of at most :data:`MAX_ATTR_BYTES`, a JSON map with a map ``env_kwargs``).

    Raises:
        BadInput: not an HDF5 file.
        PeerError: ``env_args`` missing, too large or malformed.
    """
    try:
        with h5py.File(path, "r") as f:
            text = _attr(_hard_child(f, "data", path, h5py.Group), "env_args", path)
    except PeerError:
        raise
    except (KeyError, ValueError, OSError, TypeError) as exc:
        raise BadInput(f"{path} is not a robomimic dataset written by rpg demos ({exc})") from None
    try:
        args = json.loads(text) if isinstance(text, str) else None
    except ValueError:
        args = None
    if not isinstance(args, dict) or not isinstance(args.get("env_kwargs"), dict):
        raise _refuse(path, "env_args is not a JSON map with env_kwargs")
    return args


def make_env_from_metadata(path: str | Path, library: str | Path, demo: int | None = None, **overrides):
    """The environment a robomimic file's demos were recorded in, rebuilt from its
    ``env_args`` (robomimic's ``EnvUtils.create_env_from_metadata`` for rpg files).

    The task is found by its recorded content hash among the tasks of ``library``
    (:func:`rpg.demos.collect.library_tasks`); the path the file records is never loaded.
    The instruction is the one demo ``demo`` (default: the first) was recorded with.

    Args:
        path: the dataset directory or its ``demo.hdf5``.
        library: the library the demos were recorded from (a directory or its manifest).
        demo: whose task and instruction; required when the file holds demos of several tasks.
        overrides: more keyword arguments of :class:`rpg.env.BlockTaskEnv` (e.g. ``cameras``).

    Returns:
        A :class:`rpg.env.BlockTaskEnv` (its ``reset(seed=...)`` with a demo's recorded seed
        starts that demo's episode).

    Raises:
        BadInput: not an rpg robomimic file, several tasks and no ``demo``, no task of
            ``library`` with the content hash, or the task changed since.
        PeerError: the file's metadata is out of bounds.
    """
    from rpg.demos.collect import check_provenance, library_tasks
    from rpg.env.core import BlockTaskEnv
    from rpg.env.render import SUPERSAMPLE_FACTORS

    h5 = dataset_file(path)
    if h5 is None:
        raise BadInput(f"{path} holds no {DATASET_NAME}")
    kwargs = read_env_args(h5)["env_kwargs"]
    demos = {d["episode_index"]: d for d in read_demos(h5)}
    if demo is None:
        if len(kwargs.get("tasks") or {}) > 1:
            raise BadInput(f"{h5} holds demos of {len(kwargs['tasks'])} tasks; say which demo's environment (demo=)")
        if not demos:
            raise BadInput(f"{h5} holds no demos")
        demo = min(demos)
    if demo not in demos:
        raise BadInput(f"{h5} has no demo_{demo}")
    prov = check_provenance(demos[demo], f"{h5} demo_{demo}")
    task = library_tasks(library).get(prov["task_hash"])
    if task is None:
        raise BadInput(f"no task in {library} has content hash {prov['task_hash'][:12]} (demo_{demo} of {h5}); give "
                       "the library it was recorded from")
    settings = {"embodiment": prov["embodiment"], "control_mode": kwargs.get("control_mode", "ee_delta")}
    for key in ENV_KEYWORDS:
        if key in kwargs and key not in settings:
            value = kwargs[key]
            if key in ("cameras", "image_size"):
                if not isinstance(value, list) or not all(isinstance(v, (str, int)) for v in value):
                    raise _refuse(h5, f"env_kwargs {key} is not a list")
                value = tuple(value)
            elif key == "max_episode_steps":
                if value is not None and (type(value) is not int or not 0 < value <= MAX_STEPS):
                    raise _refuse(h5, f"env_kwargs max_episode_steps is not null or an integer in [1, {MAX_STEPS}]")
            elif key in ("privileged", "terminate_on_success"):
                if type(value) is not bool:
                    raise _refuse(h5, f"env_kwargs {key} is not a boolean")
            elif key == "wrist_supersample":
                if type(value) is not int or value not in SUPERSAMPLE_FACTORS:
                    raise _refuse(h5, f"env_kwargs wrist_supersample is not one of {SUPERSAMPLE_FACTORS}")
            elif not isinstance(value, str):
                raise _refuse(h5, f"env_kwargs {key} is not a string")
            settings[key] = value
    settings |= overrides
    env = BlockTaskEnv(task, **settings)
    if env.source.content_hash != prov["task_hash"]:
        env.close()
        raise BadInput(f"{task} has changed since the demos were recorded")
    src = env.source
    mode = ("canonical" if prov["instruction"] == src.canonical and prov["instruction"] != src.instruction
            else next((f"paraphrase:{k}" for k, p in enumerate(src.paraphrases) if p == prov["instruction"]), "original"))
    if mode != "original":
        env.close()
        env = BlockTaskEnv(task, instruction=mode, **settings)
    return env
