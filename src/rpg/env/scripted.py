"""A scripted pick-and-place controller that acts only through the public ``ee_delta`` action
space: the building block of demonstrations and tests (and of the oracle planner).

It reads the privileged ``object_poses`` observation for where cubes are, turns each
waypoint (a TCP position, a yaw and a gripper command) into clipped ``ee_delta`` actions
(a proportional step toward the waypoint), and moves to the next waypoint when the TCP is
within tolerance or the waypoint's step budget is spent.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.env.embodiments.base import TcpPose

APPROACH_HEIGHT = 0.10
"""Height of the approach and retreat waypoints above a grasp or place point, m."""

GRIPPER_STEPS = 10
"""Control steps to close or open the gripper (0.5 s at 20 Hz)."""

REACH_TOL = 0.004
"""Position error under which a waypoint counts as reached, m."""

YAW_TOL = 0.04
"""Orientation error under which a waypoint counts as reached, rad."""

HEADING_TILT = 0.5
"""A TCP tilted more than this (rad) from top-down turns the shortest way (see :func:`heading`)."""


@dataclass(frozen=True)
class Waypoint:
    """A TCP target: position (m, world), yaw about world z (rad) of a top-down TCP, gripper
    (-1 open, +1 closed), tolerance (m) and the most control steps to spend on it.

    ``quat`` (w, x, y, z), when given, is the TCP orientation instead of top-down at ``yaw``;
    ``turn_rate`` (rad per control step), when given, caps how fast the TCP turns toward it
    (an arm swinging a held cube fast about the TCP flings it).
    """

    pos: tuple[float, float, float]
    yaw: float
    gripper: float
    tol: float = REACH_TOL
    max_steps: int = 60
    min_steps: int = 0
    quat: tuple[float, float, float, float] | None = None
    turn_rate: float | None = None

    def orientation(self) -> np.ndarray:
        """The target TCP quaternion (4,)."""
        return np.asarray(self.quat, float) if self.quat is not None else top_down_quat(self.yaw)


def cube_yaw(quat) -> float:
    """Yaw (rad) about world z of a cube's horizontal face axes, reduced to [-pi/4, pi/4) (a
    cube's symmetry); for a cube on any face (the local axis nearest vertical is skipped)."""
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(quat, float))
    r = mat.reshape(3, 3)
    up = int(np.argmax(np.abs(r[2])))
    x = r[:, (up + 1) % 3]
    yaw = float(np.arctan2(x[1], x[0]))
    return (yaw + np.pi / 4) % (np.pi / 2) - np.pi / 4


def top_down_quat(yaw: float) -> np.ndarray:
    """TCP orientation pointing down, turned by ``yaw`` about world z (home has yaw 0)."""
    q = np.zeros(4)
    mujoco.mju_mulQuat(q, np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)]), np.array(C.HOME_TCP_QUAT))
    return q


def rotation_error(tcp: TcpPose, target) -> np.ndarray:
    """Rotation vector (3,) rad, world frame, from the TCP's orientation to ``target``: a
    quaternion (4,), or a yaw (rad) of the top-down orientation."""
    target = top_down_quat(target) if np.ndim(target) == 0 else np.asarray(target, float)
    inv = np.zeros(4)
    mujoco.mju_negQuat(inv, tcp.quat)
    err = np.zeros(4)
    mujoco.mju_mulQuat(err, target, inv)
    if err[0] < 0:
        err = -err
    rot = np.zeros(3)
    mujoco.mju_quat2Vel(rot, err, 1.0)
    return rot


def tcp_yaw(quat) -> float:
    """Yaw (rad) of a TCP orientation (4,) about world z from the home orientation, in (-pi, pi]."""
    r = np.zeros(4)
    inv = np.zeros(4)
    mujoco.mju_negQuat(inv, np.array(C.HOME_TCP_QUAT))
    mujoco.mju_mulQuat(r, np.asarray(quat, float), inv)
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, r)
    return float(np.arctan2(mat[3], mat[0]))


def heading(tcp: TcpPose, wp: Waypoint) -> np.ndarray:
    """The orientation (4,) the TCP turns toward this step: ``wp``'s, except that a top-down
    waypoint's yaw more than a quarter turn away is approached in quarter turns through the
    yaws between (not the shortest way, which for a turn of more than pi from home crosses
    the back and runs the Panda's wrist into its joint limit)."""
    if wp.quat is not None or np.linalg.norm(rotation_error(tcp, tcp_yaw(tcp.quat))) > HEADING_TILT:
        return wp.orientation()  # a tilted or sideways hand (a push, a flip) has no yaw to turn from
    now = tcp_yaw(tcp.quat)
    turn = float(np.clip(wp.yaw - now, -np.pi / 2, np.pi / 2))
    return top_down_quat(now + turn)


def delta_action(tcp: TcpPose, wp: Waypoint) -> np.ndarray:
    """The ``ee_delta`` action (7,) float32 that steps the TCP toward ``wp``."""
    dpos = (np.asarray(wp.pos) - tcp.pos) / C.EE_DELTA_POS_LIMIT
    drot = rotation_error(tcp, heading(tcp, wp))
    if wp.turn_rate is not None and np.linalg.norm(drot) > wp.turn_rate:
        drot *= wp.turn_rate / np.linalg.norm(drot)
    drot = drot / C.EE_DELTA_ROT_LIMIT
    return np.clip(np.concatenate([dpos, drot, [wp.gripper]]), -1.0, 1.0).astype(np.float32)


def pick_place_waypoints(grasp: np.ndarray, grasp_yaw: float, place: np.ndarray, place_yaw: float) -> list[Waypoint]:
    """Waypoints that move a cube whose centre is at ``grasp`` to centre ``place`` (m)."""
    up = np.array([0.0, 0.0, APPROACH_HEIGHT])
    travel = max(grasp[2], place[2]) + APPROACH_HEIGHT
    g_hi = (grasp[0], grasp[1], travel)
    p_hi = (place[0], place[1], travel)
    return [
        Waypoint(g_hi, grasp_yaw, -1.0, tol=0.01),
        Waypoint(tuple(grasp), grasp_yaw, -1.0),
        Waypoint(tuple(grasp), grasp_yaw, 1.0, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS),
        Waypoint(tuple(grasp + up), grasp_yaw, 1.0, tol=0.01),
        Waypoint(p_hi, place_yaw, 1.0, tol=0.01),
        Waypoint(tuple(place + np.array([0.0, 0.0, 0.004])), place_yaw, 1.0),
        Waypoint(tuple(place), place_yaw, -1.0, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS),
        Waypoint(tuple(place + up), place_yaw, -1.0, tol=0.01),
    ]


def reached(tcp: TcpPose, wp: Waypoint) -> bool:
    """Whether the TCP is within the waypoint's position and orientation tolerances."""
    return (np.linalg.norm(tcp.pos - np.asarray(wp.pos)) < wp.tol
            and np.linalg.norm(rotation_error(tcp, wp.orientation())) < YAW_TOL)


def waypoint_actions(robot, waypoints: list[Waypoint]) -> Iterator[np.ndarray]:
    """``ee_delta`` actions (7,) that take ``robot``'s TCP through the waypoints, one per control
    step; the caller steps the environment between them (the TCP is measured each time)."""
    for wp in waypoints:
        for k in range(wp.max_steps):
            tcp = robot.tcp_pose()
            if k >= wp.min_steps and reached(tcp, wp):
                break
            yield delta_action(tcp, wp)


def follow(env, waypoints: list[Waypoint]) -> Iterator[tuple]:
    """Step ``env`` (a :class:`rpg.env.BlockTaskEnv` in ``ee_delta`` mode) through the
    waypoints; yields each step's ``(obs, reward, terminated, truncated, info)``."""
    for action in waypoint_actions(env.unwrapped.robot, waypoints):
        out = env.step(action)
        yield out
        if out[2] or out[3]:
            return
