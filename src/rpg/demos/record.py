"""One oracle episode, recorded: what a demonstration dataset stores about it.

:func:`record_episode` runs the oracle (:class:`rpg.oracle.Oracle`) on a task from a seed,
through ``env.step`` only, and returns the per-step observation state and action, the
robomimic low-dimensional observations and MuJoCo states, the camera frames (written to
``video_dir`` while the episode runs, so frames never pile up in memory: MP4 videos, or
HDF5 frame stores for the robomimic format), and what a replay needs to check it: the
task's content hash, the seed, the embodiment, the instruction and the final object poses.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.env.core import BlockTaskEnv
from rpg.oracle import Oracle

STATE_NAMES = ["eef_x", "eef_y", "eef_z", "eef_rot_xx", "eef_rot_yx", "eef_rot_zx", "eef_rot_xy", "eef_rot_yy",
               "eef_rot_zy", "finger_left", "finger_right"]
"""Names of the 11 ``observation.state`` values: the TCP position (m, world frame), its
orientation as the first two columns of its rotation matrix (``eef_rot_<i><j>``: world axis
i's component of the TCP's axis j; the "6D" rotation of Zhou et al. 2019, continuous: no
jump where an axis-angle vector wraps by 2 pi), and the two finger openings (m, 0 closed,
0.04 open).  :func:`dataset_state` computes it from the environment's ``state``."""

ACTION_NAMES = ["dx", "dy", "dz", "droll", "dpitch", "dyaw", "gripper"]
"""Names of the 7 ``ee_delta`` action values (normalised to [-1, 1]; see rpg.env)."""

JOINT_NAMES = {
    "panda": [*(f"joint{i}" for i in range(1, 8)), "finger_joint1", "finger_joint2"],
    "floating_gripper": ["hand_x", "hand_y", "hand_z", "hand_qw", "hand_qx", "hand_qy", "hand_qz",
                         "finger_joint1", "finger_joint2"],
}
"""Names of ``observation.joint_pos`` per embodiment: the environment's ``qpos`` (the Panda's
seven arm joints, rad, and its two finger joints, m; the floating gripper's free joint, the
hand's position m and quaternion w, x, y, z, and its finger joints)."""

POSE_FIELDS = ("x", "y", "z", "qw", "qx", "qy", "qz")
"""An object's pose in ``observation.object_poses``: position (m) and quaternion (w, x, y, z),
as the environment's privileged ``object_poses``."""

LOW_DIM_KEYS = {
    "panda": ("robot0_eef_pos", "robot0_eef_quat", "robot0_gripper_qpos", "robot0_joint_pos", "object"),
    "floating_gripper": ("robot0_eef_pos", "robot0_eef_quat", "robot0_gripper_qpos", "robot0_hand_pos",
                         "robot0_hand_quat", "object"),
}
"""robomimic's names of the low-dimensional observations recorded per step, per embodiment:
TCP position (3, m, world frame); TCP orientation (4, quaternion x, y, z, w: robosuite's
order, its sign kept continuous from step to step); the finger joints (2, m) with
robosuite's PandaGripper signs (``finger_joint1`` in [0, 0.04], ``finger_joint2`` in
[-0.04, 0]: both 0 closed, open at (0.04, -0.04)); the Panda's seven arm joints (rad) as
robosuite's ``robot0_joint_pos``; for the floating gripper, which has no arm joints, its
free joint's pose as ``robot0_hand_pos`` (3, m) and ``robot0_hand_quat`` (4, x, y, z, w);
and every object's position and quaternion (x, y, z, w) in sorted name order (7 per object)."""

SIM_STATE = mujoco.mjtState.mjSTATE_FULLPHYSICS
"""What a recorded MuJoCo state holds (``mj_getState``: time, qpos, qvel, act, ...)."""

FRAME_FORMATS = ("mp4", "hdf5")
"""How camera frames are recorded: MP4 videos (LeRobot) or HDF5 frame stores (robomimic)."""


@dataclass
class Episode:
    """A recorded episode.  ``states`` (T, 11) float32 (:data:`STATE_NAMES`) and ``actions``
    (T, 7) float32: the observation before each step and the action taken; ``joint_pos``
    (T, 9) float32 (:data:`JOINT_NAMES`) and ``object_poses`` (T, 7 N) float32 (the N objects
    of ``object_names``, sorted, :data:`POSE_FIELDS` each) before each step; ``rewards`` (T,)
    and ``successes`` (T,) bool: the environment's reward and ``info["success"]`` after each
    step; ``low_dim``: the embodiment's :data:`LOW_DIM_KEYS` -> (T + 1, d) float64 and
    ``sim_states`` (T + 1, S) float64 (:data:`SIM_STATE`): before each step and after the
    last; ``videos``: camera -> frame file (an MP4 of T frames, or with ``frames="hdf5"`` an
    HDF5 frame store of T + 1); ``image_stats``: camera -> per-channel min/max/mean/std in
    [0, 1] over the first T frames."""

    task: str
    task_hash: str
    task_name: str
    seed: int
    embodiment: str
    instruction: str
    paraphrase: int | None
    success: bool
    states: np.ndarray
    actions: np.ndarray
    final_poses: dict[str, list[float]]
    videos: dict[str, str] = field(default_factory=dict)
    image_stats: dict[str, dict] = field(default_factory=dict)
    failure: str | None = None
    rewards: np.ndarray = field(default_factory=lambda: np.zeros(0))
    successes: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))
    joint_pos: np.ndarray = field(default_factory=lambda: np.zeros((0, 9), np.float32))
    object_names: list[str] = field(default_factory=list)
    object_poses: np.ndarray = field(default_factory=lambda: np.zeros((0, 0), np.float32))
    low_dim: dict[str, np.ndarray] = field(default_factory=dict)
    sim_states: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))

    @property
    def length(self) -> int:
        return int(len(self.actions))


class _ChannelStats:
    """Running per-channel statistics of uint8 images, in [0, 1]."""

    def __init__(self) -> None:
        self.n = 0
        self.sum = np.zeros(3)
        self.sumsq = np.zeros(3)
        self.min = np.full(3, 255)
        self.max = np.zeros(3, int)

    def add(self, img: np.ndarray) -> None:
        px = img.reshape(-1, 3)
        f = px.astype(np.float64)
        self.n += len(px)
        self.sum += f.sum(0)
        self.sumsq += (f * f).sum(0)
        self.min = np.minimum(self.min, px.min(0))
        self.max = np.maximum(self.max, px.max(0))

    def result(self, frames: int) -> dict:
        mean = self.sum / max(self.n, 1)
        std = np.sqrt(np.maximum(self.sumsq / max(self.n, 1) - mean ** 2, 0.0))

        def chw(v):  # LeRobot keeps image stats as (3, 1, 1)
            return [[[float(x)]] for x in v]

        return {"min": chw(self.min / 255.0), "max": chw(self.max / 255.0), "mean": chw(mean / 255.0),
                "std": chw(std / 255.0), "count": [frames]}


def _paraphrase_index(instruction: str) -> int | None:
    head, _, k = instruction.partition(":")
    return int(k) if head == "paraphrase" and k.isdigit() else None


def _xyzw(wxyz) -> list[float]:
    return [float(wxyz[1]), float(wxyz[2]), float(wxyz[3]), float(wxyz[0])]


def rotation_6d(quat_wxyz) -> np.ndarray:
    """The first two columns of the rotation matrix of a unit quaternion (w, x, y, z), (6,):
    ``[R00, R10, R20, R01, R11, R21]`` (continuous in the rotation, unlike axis-angle)."""
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(quat_wxyz, float))
    m = mat.reshape(3, 3)
    return np.concatenate([m[:, 0], m[:, 1]])


def dataset_state(env_state) -> np.ndarray:
    """``observation.state`` (11,) float32 (:data:`STATE_NAMES`) of the environment's
    ``state`` (8,: TCP position, axis-angle, finger openings): what a policy trained on an
    rpg dataset is given at evaluation."""
    from rpg.env.embodiments.base import axis_angle_to_quat

    s = np.asarray(env_state, float)
    return np.concatenate([s[0:3], rotation_6d(axis_angle_to_quat(s[3:6])), s[6:8]]).astype(np.float32)


def _state(env) -> np.ndarray:
    tcp = env.robot.tcp_pose()
    return np.concatenate([tcp.pos, rotation_6d(tcp.quat), env.robot.finger_positions()]).astype(np.float32)


def _low_dim(env, previous: dict | None) -> dict[str, np.ndarray]:
    """The embodiment's :data:`LOW_DIM_KEYS` observations of ``env``'s current state; the TCP
    quaternion's sign follows ``previous`` (the step before's), so it never jumps."""
    tcp = env.robot.tcp_pose()
    quat = np.array(_xyzw(tcp.quat))
    if previous is not None and float(quat @ previous["robot0_eef_quat"]) < 0:
        quat = -quat
    poses = env.scene.poses()
    fingers = env.robot.finger_positions()
    out = {"robot0_eef_pos": np.asarray(tcp.pos, np.float64), "robot0_eef_quat": quat,
           "robot0_gripper_qpos": np.array([fingers[0], -fingers[1]]),  # robosuite's PandaGripper signs
           "object": np.array([v for name in sorted(poses) for v in (*poses[name].pos, *_xyzw(poses[name].quat))])}
    qpos = env.robot.robot_qpos()
    if env.robot.NAME == "floating_gripper":
        out["robot0_hand_pos"] = qpos[0:3].copy()
        out["robot0_hand_quat"] = np.array(_xyzw(qpos[3:7]))
    else:
        out["robot0_joint_pos"] = qpos[:-2].copy()
    return out


def _object_poses(env) -> np.ndarray:
    poses = env.scene.poses()
    return np.array([v for name in sorted(poses) for v in (*poses[name].pos, *poses[name].quat)], np.float32)


def _sim_state(env) -> np.ndarray:
    out = np.empty(mujoco.mj_stateSize(env.model, SIM_STATE))
    mujoco.mj_getState(env.model, env.data, out, SIM_STATE)
    return out


def _frame_sink(frames: str, path: Path, gop: int):
    if frames == "hdf5":
        from rpg.demos.robomimic import FrameStore

        return FrameStore(path.with_suffix(".h5"))
    from rpg.demos.mp4 import EpisodeVideo

    return EpisodeVideo(path, C.CONTROL_HZ, gop)


_CACHED: dict = {}
"""The environment :func:`record_episode` keeps open between episodes with ``reuse_env``
(one: building a Panda scene takes longer than a short episode)."""


def _environment(key: tuple, reuse: bool) -> BlockTaskEnv:
    if reuse:
        if key in _CACHED:
            return _CACHED[key]
        close_cached_env()
    task, embodiment, cameras, image_size, instruction, max_steps, visual, wrist_supersample = key
    env = BlockTaskEnv(task, embodiment=embodiment, control_mode="ee_delta", cameras=cameras,
                       image_size=image_size, instruction=instruction, max_episode_steps=max_steps, visual=visual,
                       wrist_supersample=wrist_supersample)
    if reuse:
        _CACHED[key] = env
    return env


def close_cached_env() -> None:
    """Close the environment kept open by ``record_episode(..., reuse_env=True)``."""
    for env in _CACHED.values():
        env.close()
    _CACHED.clear()


def record_episode(task: str, seed: int, embodiment: str = "floating_gripper",
                   cameras: tuple[str, ...] = ("agentview", "wrist"), image_size: tuple[int, int] = (256, 256),
                   instruction: str = "original", video_dir: str | Path | None = None,
                   max_steps: int | None = None, frames: str = "mp4", reuse_env: bool = False,
                   gop: int | None = None, visual: str = "decimated", wrist_supersample: int = 1) -> Episode:
    """Run the oracle for one episode and record it.

    Args:
        task: task directory, family or ``FAMILY@vN`` (loaded through the environment's checks).
        seed: the episode's seed (rho_0's sample).
        embodiment: ``"panda"`` or ``"floating_gripper"``.
        cameras: cameras to record as videos (``()`` for none).
        image_size: (height, width) of the videos, pixels.
        instruction: ``"original"``, ``"canonical"`` or ``"paraphrase:K"``.
        video_dir: where the videos go (``<camera>.mp4``); required when ``cameras``.
        max_steps: episode step limit (default: the environment's rule).
        frames: ``"mp4"`` (a video of T frames per camera) or ``"hdf5"`` (a frame store of
            T + 1 frames: the observation after the last step too, robomimic's ``next_obs``).
        reuse_env: keep the environment open for the next episode with the same arguments
            (:func:`close_cached_env` closes it); an episode depends only on its seed, so
            this changes nothing but the time.
        gop: most frames between keyframes of the MP4s (default
            :data:`rpg.demos.mp4.DEFAULT_GOP`).
        visual: the robot's meshes in the images, ``"decimated"`` or ``"stock"``
            (:class:`rpg.env.BlockTaskEnv`'s ``visual``).
        wrist_supersample: the wrist camera drawn at this many times the image size per
            side and averaged back (1: off; :class:`rpg.env.BlockTaskEnv`'s
            ``wrist_supersample``).

    Returns:
        The :class:`Episode` (``success`` false when the oracle failed; its videos are then
        still written, the caller keeps or discards them).

    Raises:
        ValueError: an unknown ``frames`` or a ``gop`` below 1.
    """
    from rpg.demos.mp4 import DEFAULT_GOP, encoder_options

    if frames not in FRAME_FORMATS:
        raise ValueError(f"frames must be one of {FRAME_FORMATS}, not {frames!r}")
    gop = DEFAULT_GOP if gop is None else int(gop)
    encoder_options(gop)  # checks it
    env = _environment((str(task), embodiment, tuple(cameras), tuple(image_size), instruction, max_steps, visual,
                        int(wrist_supersample)), reuse_env)
    try:
        oracle = Oracle(env)
        obs, info = env.reset(seed=seed)
        oracle.reset(obs)
        stats = {c: _ChannelStats() for c in cameras}
        states, actions, rewards, successes, joints, objects, low_dim, sims = [], [], [], [], [], [], [], []
        with contextlib.ExitStack() as stack:  # videos are published only if the episode ends cleanly
            writers = {}
            if cameras:
                video_dir = Path(video_dir)
                video_dir.mkdir(parents=True, exist_ok=True)
                writers = {c: stack.enter_context(_frame_sink(frames, video_dir / f"{c}.mp4", gop)) for c in cameras}
            done = False
            while not done:
                for c in cameras:
                    writers[c].write(obs[f"{c}_image"])
                    stats[c].add(obs[f"{c}_image"])
                low_dim.append(_low_dim(env, low_dim[-1] if low_dim else None))
                sims.append(_sim_state(env))
                states.append(_state(env))
                joints.append(np.asarray(obs["qpos"], np.float32))
                objects.append(_object_poses(env))
                action = oracle.act(obs)
                actions.append(np.asarray(action, np.float32))
                obs, reward, terminated, truncated, info = env.step(action)
                rewards.append(reward)
                successes.append(bool(info["success"]))
                done = terminated or truncated
            low_dim.append(_low_dim(env, low_dim[-1]))
            sims.append(_sim_state(env))
            if frames == "hdf5":
                for c in cameras:
                    writers[c].write(obs[f"{c}_image"])
        poses = {n: [*map(float, p.pos), *map(float, p.quat)] for n, p in env.scene.poses().items()}
        names = sorted(poses)
        return Episode(task=str(task), task_hash=env.source.content_hash, task_name=env.source.name, seed=int(seed),
                       embodiment=embodiment, instruction=env.instruction,
                       paraphrase=_paraphrase_index(instruction), success=bool(info["success"]),
                       states=np.array(states, np.float32).reshape(-1, len(STATE_NAMES)),
                       actions=np.array(actions, np.float32).reshape(-1, 7), final_poses=poses,
                       videos={c: str(writers[c].path) for c in cameras},
                       image_stats={c: stats[c].result(len(actions)) for c in cameras},
                       failure=oracle.failure, rewards=np.array(rewards, np.float64),
                       successes=np.array(successes, bool), joint_pos=np.array(joints, np.float32),
                       object_names=names,
                       object_poses=np.array(objects, np.float32).reshape(len(actions), 7 * len(names)),
                       low_dim={k: np.array([d[k] for d in low_dim]) for k in low_dim[0]},
                       sim_states=np.array(sims))
    finally:
        if not reuse_env:
            env.close()
