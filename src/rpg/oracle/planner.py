"""The oracle: a task-and-motion planner for the block domain that acts through ``env.step``.

:class:`Oracle` is a policy (``reset(obs)``, ``act(obs)``) with privileged access to the
environment's state.  Each time it needs to decide, it reads where the cubes are, picks the
next action of the plan, and turns it into waypoints that the scripted controller
(:mod:`rpg.env.scripted`) follows with ``ee_delta`` actions:

1. the goal: :func:`rpg.oracle.goal.plan_goal` (targets, bottom-up / temporal order);
2. for the first cube in order that is not at its target:
   - a cube lying on it is moved to a free spot first (unstacking an initial stack);
   - a cube standing where it must go is moved to a free spot;
   - a semantic cube whose goal face is not up is flipped (a regrasp on the table: grasp
     across the axis to turn about, lift, turn the hand 90 degrees, put down), once or twice;
   - then it is picked and placed, with a grasp yaw that respects the cube's symmetry
     (coloured cubes modulo pi/2; semantic cubes turned to their exact yaw) and a finger
     axis chosen away from neighbours, opening only as wide as the neighbours allow; the
     held cube is aimed where it sits in the fingers now (it slides along the pads), and the
     hand settles just above the placement's layer before its last, straight descent;
   - in a dense layout (touching cubes: grids, pyramids), filled layer by layer from the
     far row, where a finger would not fit beside a placed neighbour the cube is released
     ``shift`` beside its goal and pushed in by the closed fingers, tilted so that their
     tips lead low on its face (:meth:`Oracle._push`); the gaps it was released with are
     closed by pushes against the neighbours placed before it, and loose cubes in the
     fingers' way are moved off first;
3. after every move the state is read again (verification): a cube that did not land, or a
   neighbour that was knocked, is simply not at its target and is handled again, up to
   :data:`MAX_ATTEMPTS` times per cube.

Its actions are a valid demonstration: nothing but ``env.step`` changes the state.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field, replace

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.domain.state import Pose, yaw_quat
from rpg.env.embodiments.base import mat_to_quat
from rpg.env.scripted import (
    GRIPPER_STEPS,
    Waypoint,
    cube_yaw,
    delta_action,
    top_down_quat,
    waypoint_actions,
)
from rpg.oracle.goal import (
    DENSE_YAW_TOL,
    GoalPlan,
    OracleError,
    Target,
    plan_goal,
    pose_matches,
    rot,
    up_axis,
    yaw_offset,
)

MAX_ATTEMPTS = 3
"""Most pick-and-place attempts per cube before the oracle gives up."""

CLEARANCE = 0.035
"""Height (m) the held cube's bottom keeps above the tallest cube while travelling."""

TRAVEL_MIN = 0.10
"""Lowest travel height of the TCP above the table, m."""

PLACE_DROP = 0.003
"""A cube is released this far (m) above its resting height."""

FLIP_HEIGHT = 0.14
"""TCP height above the table (m) at which the hand turns a cube over."""

FLIP_DROP = 0.012
"""A flipped cube is released this far (m) above the table (the tilted fingers must clear it)."""

FLIP_AIM_MAX = math.radians(90.0)
"""Largest angle (rad) from +x (away from the robot) of the direction a flipped cube's face
points as the hand swings it up: the hand swings from the robot's side or sideways, never
toward the robot (the Panda's IK lost the TCP by 5-70 cm there)."""

FLIP_TILT = math.radians(45.0)
"""How far (rad) the hand's approach tilts from top-down, away from the face that comes up,
when it grasps a cube to flip (it ends tilted 90 degrees minus that the other way), unless
FLIP_FORWARD_MAX asks for another split."""

FLIP_FORWARD_MAX = math.radians(35.0)
"""Largest tilt (rad) of the hand's approach forward (+x, away from the robot) in a flip: the
Panda's sixth joint reaches its limit ~45 degrees forward at x = 0.56 m, less farther out."""

FLIP_SPOT = (0.52, 0.0)
"""Where on the table (m, xy) a flip puts a cube down, when free: the Panda's wrist swings a
cube over in every direction there (x 0.46-0.60 m; farther out it lost the TCP)."""

FLIP_YAW_TOL = 0.05
"""A flip whose result is within this angle (rad) of a target's orientation ends there."""

FLIP_TURN_RATE = 0.1
"""Fastest turn (rad per control step) of the hand that swings a held cube over: the Panda's
arm, asked for the action space's fastest turn (EE_DELTA_ROT_LIMIT), swung its TCP 17 cm off
the point it turns about and flung the cube."""

FLIP_BACK_OFF = 0.10
"""How far (m) the tilted hand backs off a flipped cube, along its approach, before it rises."""

FINGER_REACH = 0.03
"""How far (m) a finger reaches beyond the face of a 4 cm cube it holds, with the small opening
that releases it (the finger's collision box, measured on the Menagerie hand)."""

FINGER_REACH_OPEN = 0.048
"""How far (m) a fully open finger reaches beyond the face of a 4 cm cube."""

FINGER_HALF_WIDTH = 0.0105
"""Half the width (m) of a finger across its opening axis (collision box)."""

PUSHER_HALF_THICKNESS = 0.0096
"""How far (m) the tilted, closed fingers' face leads the TCP along a push made across the
finger axis, low on the pushed cube (see PUSH_TILT)."""

PUSHER_HALF_SPAN = 0.025
"""Half the span (m) of the closed fingers along their axis, at its widest within a cube's
height above the fingertips (the Menagerie finger mesh widens upward)."""

PUSH_CONTACT_TOL = 0.002
"""How far (m) a neighbour beside the pushed cube may stand proud of the face the pusher stops
at: where the fingers are wider than a cube (2 cm and more above the fingertips) the tilted
pusher trails its leading edge by 2 mm or more (see PUSH_TILT)."""

PUSHER_ROOM = 0.035
"""Room (m) the closed fingers need beside a cube to push it."""

LATERAL_GAP = 0.0025
"""Gap (m) kept to a neighbour across the finger axis when placing (the placement's
precision is ~2 mm); in a dense layout it is then closed by a push (GAP_CLOSE_MIN)."""

PUSH_APPROACH_GAP = 0.008
"""Gap (m) between the pusher's face and the cube where the pusher comes down."""

GAP_CLOSE_MIN = 0.0015
"""A dense layout's cube is pushed against a placed goal neighbour when the gap between their
faces is wider than this (m) ..."""

GAP_CLOSE_LEFT = 0.0005
"""... until this gap (m) is left (the goal layouts' own clearance)."""

DENSE_GAP_CLOSE = 0.008
"""Widest gap (m) the oracle closes by a push (a wider one is a misplacement, placed again)."""

SHIFT_MIN = 0.003
"""A finger short of room by less than this (m) is released in place (FINGER_REACH has that
margin), not beside the goal and pushed."""

PUSH_TILT = math.radians(10.0)
"""Tilt (rad) of the pushing hand about the horizontal axis across the push, fingertips
leading: the Menagerie fingers' faces widen ~2 mm upward, so an upright pusher meets a cube at
its top edge; tilted 10 degrees, the face leads the TCP axis by 9.6 mm 5 mm above the
fingertips, 7.6 mm at 20 mm and 6.1 mm at 35 mm (measured on the collision meshes)."""

HOVER_REACH = 0.07
"""Cubes within this distance (m, xy) of a short low move set its height (see HOVER_CLEARANCE)."""

HOVER_CLEARANCE = 0.022
"""TCP height (m) above the tallest cube near a short low move: the fingertips reach 0.01 m
below the TCP (tilted pusher included), leaving ~1 cm."""

PUSH_TOL = 0.0005
"""How close (m), along the push, the pusher gets to the end of a push (the gaps it closes are
~2 mm)."""

PUSH_LEAD = 0.002
"""How far past the end of a push (m) the pusher is aimed (see :meth:`Oracle._push`)."""

PUSH_STEPS = 40
"""Most control steps of a push stroke."""

PUSH_HEIGHT = 0.015
"""TCP height (m) above a pushed cube's bottom: the tilted, closed fingertips (0.0097 m below
the TCP) clear its support by 5 mm (a pusher grazing the layer below caught its cubes), and the
fingers' faces press the cube's lower half (a push high on the face tips it over)."""

PUSH_OVERSHOOT = 0.0
"""How far (m) past the goal face the pusher's face is driven."""

YAW_LIMIT = math.pi / 2 + 0.35
"""Largest TCP yaw (rad) from the home orientation the oracle asks for (the Panda's wrist)."""

GRIPPER_OPEN = -1.0
GRIPPER_CLOSED = 1.0
GRIPPER_NARROW = -0.5
"""Gripper command that releases a cube while opening only part way (dense layouts)."""

ZONE_RADIUS = 0.15
"""Loose cubes within this distance (m) of a dense layout's next goal are candidates to move
away when they leave no room to place it."""

SUPPORT_MARGIN = 0.01
"""A cube released beside its goal on the layer below (to be pushed into place) keeps its
centre this far (m) inside the footprint of the cubes it rests on."""

DENSE_KEEPOUT = 0.05
"""A cube moved out of the way keeps this much farther (m) from a dense layout's goals than
from other goals: the fingers release cubes beside the layout and push them in."""

PLACE_ABOVE = 0.008
"""Height (m) of the held cube's bottom above the tops of the placement's layer where the hand
settles before the last, straight descent."""

PLACE_SETTLE_TOL = 0.0015
"""How close (m) the TCP comes to its point above a placement (PLACE_ABOVE) before the last
descent, and to the release point before the fingers open: an arm that arrives fast
overshoots by ~6 mm (the Panda) and a held cube came down on a neighbour placed 2.5 mm away
(LATERAL_GAP); after a fast descent the Panda's TCP still lags ~1.5 mm across."""

HELD_OFFSET_MAX = 0.012
"""Largest offset (m, horizontal) of a held cube from the TCP that placing corrects for."""

BUFFER_STEP = 0.02
"""Grid step (m) of candidate spots for cubes moved out of the way."""

NUDGE_REACH = 0.025
"""A dense layout's cube standing upright within this distance (m) of its goal, in its layer,
is pushed there (:meth:`Oracle._nudge`) rather than picked again: a pick from between touching
neighbours knocks them (the Panda), and a knocked cube stands a few mm off."""

NUDGE_MIN = 0.002
"""Smallest offset (m, along a face normal) a nudge corrects."""

NUDGE_MAX = 3
"""Nudges per cube and episode before it is picked and placed again."""


@dataclass(frozen=True)
class Grasp:
    """How a cube is moved: TCP yaws at pick and place (rad), the gripper command that releases
    it, and for dense layouts the shift (m) beside the goal along ``out`` (2,) it is released at
    before being pushed into place."""

    pick_yaw: float
    place_yaw: float
    release: float
    shift: float = 0.0
    out: np.ndarray = field(default_factory=lambda: np.zeros(2))
    pick_open: float = -1.0


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _swing(aim: float, angle: float) -> np.ndarray:
    """Rotation (3, 3) by ``angle`` (rad) about the horizontal axis across world yaw ``aim``
    (rad): a positive angle turns the direction at ``aim`` up (at pi/2 it points up, and a
    top-down approach points along ``aim``)."""
    axis = np.cross((math.cos(aim), math.sin(aim), 0.0), (0.0, 0.0, 1.0))
    q = np.zeros(4)
    mujoco.mju_axisAngle2Quat(q, axis, angle)
    m = np.zeros(9)
    mujoco.mju_quat2Mat(m, q)
    return m.reshape(3, 3)


def _tilted(aim: float, yaw: float, tilt: float) -> tuple[float, float, float, float]:
    """TCP orientation (w, x, y, z): top-down at ``yaw`` (rad), then swung by ``tilt`` (rad)
    across world yaw ``aim`` (a positive tilt points the approach toward ``aim``)."""
    return tuple(mat_to_quat(_swing(aim, tilt) @ rot(top_down_quat(yaw))))


def finger_axis(yaw: float) -> np.ndarray:
    """World direction (2,) along which the fingers open at a top-down TCP yaw."""
    return np.array([math.sin(yaw), -math.cos(yaw)])


class Oracle:
    """The block domain's planner as a policy for a :class:`rpg.env.BlockTaskEnv`.

    Args:
        env: the environment (``ee_delta`` control); the oracle reads its state (privileged).

    Raises:
        OracleError: the environment is not in ``ee_delta`` mode.
    """

    name = "oracle"

    def __init__(self, env):
        self.env = env.unwrapped
        if self.env.control_mode != "ee_delta":
            raise OracleError(f"the oracle acts in ee_delta mode, not {self.env.control_mode!r}")
        self.robot = self.env.robot
        self.task = self.env.task
        self.scene = self.task.scene
        self.sizes = {n: a.extents[0] for n, a in self.scene.assets.items() if a.movable}
        self._scratch = None
        self._gen: Iterator[np.ndarray] | None = None
        self.plan: GoalPlan | None = None
        self.attempts: dict[str, int] = {}
        self.gap_pushes: dict[str, int] = {}
        self.nudges: dict[str, int] = {}
        self.failure: str | None = None

    # -- policy interface -----------------------------------------------------------
    def reset(self, obs=None) -> None:
        """Plan for the episode the environment has just reset to."""
        self.plan, self.failure = None, None
        self.attempts, self.gap_pushes, self.nudges = {}, {}, {}
        self._gen = self._run()

    def act(self, obs=None) -> np.ndarray:
        """The next ``ee_delta`` action (7,) float32; once the plan is done or has failed
        (``failure`` says why), it holds still with the gripper open."""
        if self._gen is None:
            self.reset(obs)
        try:
            return next(self._gen)
        except StopIteration:
            return self._hold()
        except OracleError as exc:  # a primitive found no way (e.g. no grasp): the episode fails, reported
            self.failure = self.failure or str(exc)
            self._gen = iter(())
            return self._hold()

    def _hold(self) -> np.ndarray:
        a = np.zeros(7, np.float32)
        a[6] = GRIPPER_OPEN
        return a

    # -- reading the state ----------------------------------------------------------
    def _scratch_task(self):
        if self._scratch is None:
            self._scratch = self.task.scratch()
        return self._scratch

    def poses(self):
        return self.scene.poses()

    def _at_target(self, name: str, poses=None) -> bool:
        p = (poses or self.poses())[name]
        return pose_matches(self.plan.targets[name], p.pos, p.quat)

    def _done(self, poses) -> set[str]:
        """Cubes at their targets, except a dense layout's cube that stands there before the
        cubes ahead of it in the placement order (by chance, from rho_0, or because one ahead
        was knocked): the sweep has not reached it.  It is a subset of :meth:`_at_targets`;
        such a cube is not moved out of another's way unless no grasp exists without that."""
        done, gap = set(), False
        for n in self.plan.order:
            at = self._at_target(n, poses)
            if self.plan.targets[n].dense:
                at, gap = at and not gap, gap or not at
            if at:
                done.add(n)
        return done

    def _at_targets(self, poses) -> set[str]:
        """Cubes at their targets now, in order or not (``_done`` leaves out a dense layout's
        cubes after a gap; a knocked neighbour makes such a gap, and they must stay)."""
        return {n for n in self.plan.order if self._at_target(n, poses)}

    def _on_top_of(self, name: str, poses) -> list[str]:
        """Cubes resting on ``name`` now (highest first)."""
        base = poses[name]
        size = self.sizes[name]
        out = [n for n in self.sizes if n != name
               and math.dist(poses[n].pos[:2], base.pos[:2]) < 0.8 * size
               and poses[n].pos[2] > base.pos[2] + 0.5 * size]
        return sorted(out, key=lambda n: -poses[n].pos[2])

    def _blocking(self, target: Target, poses) -> list[str]:
        """Cubes standing in ``target``'s place (not its supports, not the cube itself, not a cube
        at its own target: goals do not overlap)."""
        out = []
        for n in sorted(self.sizes):
            if n == target.name or n in target.supports or self._at_target(n, poses):
                continue
            p = poses[n].pos
            reach = 0.5 * (self.sizes[n] + target.size) + 0.004
            if (abs(p[2] - target.pos[2]) < 0.75 * target.size
                    and math.dist(p[:2], target.pos[:2]) < reach * 1.2):
                out.append(n)
        return out

    # -- the plan -------------------------------------------------------------------
    def _run(self) -> Iterator[np.ndarray]:
        poses = self.poses()
        try:
            self.plan = plan_goal(self._scratch_task(), poses, self.sizes)
        except OracleError as exc:
            self.failure = str(exc)
            return
        for _ in range(MAX_ATTEMPTS * (len(self.sizes) + 2) + 4):
            poses = self.poses()
            done = self._done(poses)
            pending = [n for n in self.plan.order if n not in done]
            if not pending:
                yield from self._retreat()
                return
            name = pending[0]
            target = self._placement(self.plan.targets[name], poses)
            above = self._on_top_of(name, poses)
            if above:
                yield from self._move_aside(above[0], poses)
                continue
            if target.dense:  # a cube a few mm off (knocked, short of a push) is pushed back
                tidy = self._nudge(name, target, poses) or self._tidy(name, poses)
                if tidy is not None:
                    yield from tidy
                    continue
            blockers, avoid, grasp = self._blocking(target, poses), (), None
            if not blockers and target.dense:
                try:
                    grasp = self._grasp(name, poses[name].quat, target, poses)
                except OracleError:
                    blockers, avoid = self._zone_blockers(name, target, poses)
            if blockers:
                yield from self._move_aside(blockers[0], poses, avoid=avoid)
                continue
            self.attempts[name] = self.attempts.get(name, 0) + 1
            if self.attempts[name] > MAX_ATTEMPTS:
                self.failure = f"{name} did not reach its target in {MAX_ATTEMPTS} attempts"
                return
            if target.exact and not self._face_up_ok(name, target, poses):
                yield from self._flip(name, target, poses)
                continue
            yield from self._pick_place(name, target, poses, grasp)
        self.failure = self.failure or "the plan did not converge"

    def _placement(self, target: Target, poses) -> Target:
        """``target`` adjusted to where the cubes it is placed against actually stand now, m: in
        a stack, its support; in a dense layout, the mean offset of its supports and of the
        goal neighbours in its layer placed before it (a layout placed a few mm off as a whole
        is built on as it stands: its neighbours' faces are where the pusher stops)."""
        if not target.dense:
            if not target.supports:
                return target
            base = self.plan.targets[target.supports[0]]
            dx = np.subtract(target.pos, base.pos)
            return replace(target, pos=tuple(np.asarray(poses[target.supports[0]].pos) + dx))
        done = self._done(poses)
        beside = [n for n in self.plan.order[:self.plan.order.index(target.name)]
                  if n in done and self._goal_neighbours(n, target)]
        anchors = [*target.supports, *beside]
        if not anchors:
            return target
        off = np.mean([np.subtract(poses[n].pos, self.plan.targets[n].pos) for n in anchors], axis=0)
        if not target.supports:
            off[2] = 0.0
        return replace(target, pos=tuple(np.asarray(target.pos) + off))

    def _goal_neighbours(self, name: str, target: Target) -> bool:
        """Whether ``name``'s goal touches ``target``'s face to face in the same layer."""
        t = self.plan.targets[name]
        dist = math.dist(t.pos[:2], target.pos[:2])
        touching = 0.5 * (t.size + target.size)
        return abs(t.pos[2] - target.pos[2]) < 0.25 * target.size and dist < touching + DENSE_GAP_CLOSE

    # -- primitives -----------------------------------------------------------------
    def _travel_z(self, held: str, *points) -> float:
        tops = [p.pos[2] + 0.5 * self.sizes[n] for n, p in self.poses().items() if n in self.sizes and n != held]
        top = max(tops, default=C.TABLE_TOP_Z)
        z = max(C.TABLE_TOP_Z + TRAVEL_MIN, top + CLEARANCE + self.sizes[held] * 0.5,
                *(pt[2] + 0.06 for pt in points))
        return float(z)

    def _room(self, center, direction: np.ndarray, ignore: set[str], poses) -> float:
        """Gap (m) between a cube at ``center`` (its faces across ``direction``) and its nearest
        neighbour on the ``direction`` side (2,) in the finger's path (neighbours at the same
        height; a turned neighbour reaches farther by its corner)."""
        room = 1.0
        heading = math.atan2(direction[1], direction[0])
        for n, p in poses.items():
            if n not in self.sizes or n in ignore:
                continue
            r = np.subtract(p.pos[:2], center[:2])
            if abs(p.pos[2] - center[2]) > 0.75 * self.sizes[n]:
                continue
            along, lateral = float(r @ direction), abs(float(r[0] * direction[1] - r[1] * direction[0]))
            turn = cube_yaw(p.quat) - heading
            reach = 0.5 * self.sizes[n] * (abs(math.cos(turn)) + abs(math.sin(turn)))
            if along > 0 and lateral < 0.5 * self.sizes[n] + FINGER_HALF_WIDTH:
                room = min(room, along - reach - 0.5 * self.sizes[n])
        return room

    def _grasp(self, name: str, pick_quat, target: Target, poses, place_poses=None) -> Grasp:
        """The grasp that moves ``name`` to ``target``: yaws that respect the cube's symmetry,
        a finger axis away from neighbours, and a place-then-push when the fingers have no room
        on either axis.  ``place_poses`` (default ``poses``) are the cubes the placement must
        clear (a dense layout's planner leaves out loose cubes it will move away).

        Raises:
            OracleError: no grasp within the wrist's yaw range has room.
        """
        place_poses = poses if place_poses is None else place_poses
        psi = cube_yaw(pick_quat)
        delta = 0.0
        if target.exact:
            r = rot(target.quat) @ rot(pick_quat).T
            delta = math.atan2(r[1, 0], r[0, 0])
        best = None
        for k in range(-4, 5):
            g_pick = psi + k * math.pi / 2
            if abs(g_pick) > YAW_LIMIT:
                continue
            if target.exact:
                places = [_wrap(g_pick + delta)]
            else:
                psi_t = cube_yaw(target.quat)
                places = [psi_t + j * math.pi / 2 for j in range(-4, 5)]
            f_pick = finger_axis(g_pick)
            room_pick = min(self._room(poses[name].pos, f_pick, {name}, poses),
                            self._room(poses[name].pos, -f_pick, {name}, poses))
            for g_place in places:
                if abs(g_place) > YAW_LIMIT:
                    continue
                low, out, shift = self._release_side(name, target, finger_axis(g_place), place_poses)
                if not self._place_ok(name, target, out, shift, place_poses):
                    continue
                score = (-10.0 * shift + 0.5 * min(room_pick, 0.05) + min(low, 0.05)
                         - 0.01 * abs(g_place - g_pick) - 0.005 * (abs(g_pick) + abs(g_place))
                         - (5.0 if room_pick < FINGER_REACH else 0.0))  # a finger lands on a neighbour
                if best is None or score > best[0]:
                    release = GRIPPER_OPEN if low - shift > FINGER_REACH_OPEN else GRIPPER_NARROW
                    pick_open = GRIPPER_OPEN if room_pick > FINGER_REACH_OPEN else GRIPPER_NARROW
                    best = (score, Grasp(g_pick, g_place, release, shift, out, pick_open))
        if best is None:
            raise OracleError(f"no grasp of {name} within the wrist's yaw range")
        return best[1]

    def _release_side(self, name: str, target: Target, f: np.ndarray, poses) -> tuple[float, np.ndarray, float]:
        """For fingers along ``f`` (2,) at ``target``: the room (m) on the tighter side, the
        direction ``out`` (2,) away from it, and the shift (m) along ``out`` the cube must be
        released at for the finger on that side to fit (0 when it fits)."""
        ignore = {name, *target.supports}
        plus, minus = self._room(target.pos, f, ignore, poses), self._room(target.pos, -f, ignore, poses)
        low, out = (minus, f) if minus < plus else (plus, -f)
        shift = FINGER_REACH - low if FINGER_REACH - low > SHIFT_MIN else 0.0
        return low, out, shift

    def _place_ok(self, name: str, target: Target, out: np.ndarray, shift: float, poses) -> bool:
        """Whether ``name`` can be released ``shift`` (m) beside ``target`` along ``out`` (2,)
        with the fingers along ``out`` and, when shifted, pushed into place: room for the far
        finger and the pusher, something to rest on, a clear path for the pusher."""
        if shift == 0:
            return True
        ignore = {name, *target.supports}
        return (self._room(target.pos, out, ignore, poses) >= FINGER_REACH + shift + PUSHER_ROOM
                and self._supported(name, target, np.asarray(target.pos[:2]) + shift * out, poses)
                and not self._push_blockers(name, target, out, shift, poses))

    def _work_points(self, target: Target, out: np.ndarray, shift: float) -> list[np.ndarray]:
        """Points (xy, m) the fingers pass over placing ``target`` ``shift`` beside along ``out``
        and pushing it in: a cube moved out of their way must not be put back there."""
        reach = 0.5 * target.size + shift + FINGER_REACH_OPEN + PUSHER_ROOM
        return [np.asarray(target.pos[:2]) + a * out for a in np.arange(0.0, reach + 1e-9, 0.02)]

    def _zone_blockers(self, name: str, target: Target, poses) -> tuple[list[str], list[np.ndarray]]:
        """Loose cubes (not at their goal) in the way of placing ``name`` in a dense layout,
        those without which a grasp exists that does not exist with them, nearest first; and
        the points (xy) that grasp's fingers pass over (what moved cubes must keep clear of).
        Cubes at their own targets stay where they are unless no grasp exists without moving
        them too."""
        done = self._done(poses)
        for keep in (self._at_targets(poses), done):  # cubes at their targets stay, if they can
            settled = {n: p for n, p in poses.items() if n == name or n not in self.sizes or n in keep}
            try:
                grasp = self._grasp(name, poses[name].quat, target, poses, settled)
                break
            except OracleError:
                continue
        else:
            return [], []
        loose = sorted((n for n in poses if n not in settled),
                       key=lambda n: math.dist(poses[n].pos[:2], target.pos[:2]))
        out, f = [], finger_axis(grasp.place_yaw)
        for n in loose:
            if math.dist(poses[n].pos[:2], target.pos[:2]) > ZONE_RADIUS:
                break
            with_n = settled | {n: poses[n]}
            _, o, shift = self._release_side(name, target, f, with_n)
            if not (math.isclose(shift, grasp.shift, abs_tol=1e-3) and self._place_ok(name, target, o, shift, with_n)):
                out.append(n)
        return out, self._work_points(target, grasp.out, grasp.shift)

    def _push_blockers(self, name: str, target: Target, out: np.ndarray, shift: float, poses) -> list[str]:
        """The cubes the closed fingers would touch pushing ``name`` from ``shift`` (m) beside
        ``target`` along ``-out`` (2,), nearest first: the fingers are PUSHER_HALF_SPAN wide across
        the push (wider than a cube near their top), PUSHER_HALF_THICKNESS thick along it."""
        half = 0.5 * self.sizes[name]
        side = np.array([-out[1], out[0]])
        near = half  # the pusher's face at the end of the push, from the target's centre
        far = half + shift + PUSH_APPROACH_GAP + 2 * PUSHER_HALF_THICKNESS
        hit = []
        for n, p in poses.items():
            if n == name or n not in self.sizes or abs(p.pos[2] - target.pos[2]) > 0.75 * self.sizes[n]:
                continue
            r = np.subtract(p.pos[:2], target.pos[:2])
            yaw = cube_yaw(p.quat) - math.atan2(out[1], out[0])
            reach = 0.5 * self.sizes[n] * (abs(math.cos(yaw)) + abs(math.sin(yaw))) - PUSH_CONTACT_TOL
            along, across = float(r @ out), abs(float(r @ side))
            if near - reach < along < far + reach and across < PUSHER_HALF_SPAN + reach:
                hit.append((along, n))
        return [n for _, n in sorted(hit)]

    def _supported(self, name: str, target: Target, xy, poses) -> bool:
        """Whether ``name`` released at ``xy`` (2,) m at ``target``'s height would rest there: on
        the table, or with its centre SUPPORT_MARGIN inside the footprint it shares with the
        cubes whose tops are at its bottom (the layer below; in ``target``'s yaw frame)."""
        half = 0.5 * self.sizes[name]
        bottom = target.pos[2] - half
        if bottom - C.TABLE_TOP_Z < 0.5 * half:
            return True
        yaw = cube_yaw(target.quat)
        axes = np.array([[math.cos(yaw), math.sin(yaw)], [-math.sin(yaw), math.cos(yaw)]])
        centre = axes @ np.asarray(xy, float)
        lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
        for n, p in poses.items():
            if n == name or n not in self.sizes or abs(p.pos[2] + 0.5 * self.sizes[n] - bottom) > 0.006:
                continue
            c = axes @ np.asarray(p.pos[:2], float)
            a, b = np.maximum(c - 0.5 * self.sizes[n], centre - half), np.minimum(c + 0.5 * self.sizes[n], centre + half)
            if np.all(a < b):  # the footprints overlap
                lo, hi = np.minimum(lo, a), np.maximum(hi, b)
        return bool(np.all(centre >= lo + SUPPORT_MARGIN) and np.all(centre <= hi - SUPPORT_MARGIN))

    def _pick_place(self, name: str, target: Target, poses, grasp: Grasp | None = None) -> Iterator[np.ndarray]:
        """Move ``name`` to ``target`` with ``grasp`` (default: the best for the state ``poses``)."""
        src = np.asarray(poses[name].pos, float)
        dst = np.asarray(target.pos, float)
        grasp = grasp or self._grasp(name, poses[name].quat, target, poses)
        g_place, release = grasp.place_yaw, grasp.release
        spot = dst.copy()
        spot[:2] += grasp.shift * grasp.out
        side = np.array([-grasp.out[1], grasp.out[0]]) if grasp.shift > 0 else finger_axis(g_place + math.pi / 2)
        ignore = {name, *target.supports}
        for d in (side, -side):  # keep a gap to neighbours across the finger axis
            room = self._room(dst, d, ignore, poses)
            if room < LATERAL_GAP and self._room(dst, -d, ignore, poses) > 2 * LATERAL_GAP:
                spot[:2] -= d * (LATERAL_GAP - room)
        travel = self._travel_z(name, src, dst)
        yield from self._pick(src, grasp.pick_yaw, travel, opening=grasp.pick_open)
        yield from waypoint_actions(self.robot, [
            Waypoint((spot[0], spot[1], travel), g_place, GRIPPER_CLOSED, tol=0.008, max_steps=80)])
        # the cube may have slid in the fingers on the way: aim the cube, not the TCP
        above = spot + (0.0, 0.0, self.sizes[name] + PLACE_ABOVE)
        yield from waypoint_actions(self.robot, [
            Waypoint(self._held_tcp(name, above), g_place, GRIPPER_CLOSED, tol=0.006),
            Waypoint(self._held_tcp(name, above), g_place, GRIPPER_CLOSED, tol=PLACE_SETTLE_TOL, max_steps=30)])
        tcp = self._held_tcp(name, spot + (0.0, 0.0, PLACE_DROP))
        wps = [
            Waypoint(tcp, g_place, GRIPPER_CLOSED, tol=PLACE_SETTLE_TOL, max_steps=40),
            Waypoint(tcp, g_place, release, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS),
        ]
        if grasp.shift > 0:  # up just clear of the cubes around, then the push
            start = self._push_start(name, dst, grasp.out, grasp.shift)
            hover = self._hover_z(name, spot, spot, start)
            wps.append(Waypoint((spot[0], spot[1], hover), g_place, release, tol=0.006))
            yield from waypoint_actions(self.robot, wps)
            yield from self._push(name, dst, grasp.out, grasp.shift, travel, hover)
        else:
            wps.append(Waypoint((spot[0], spot[1], travel), g_place, release, tol=0.01))
            yield from waypoint_actions(self.robot, wps)

    def _held_tcp(self, name: str, cube_pos: np.ndarray) -> tuple[float, float, float]:
        """The TCP position (m) that brings the held cube ``name``'s centre to ``cube_pos`` (3,),
        from where the cube sits in the fingers now: it slides along the finger pads when the arm
        accelerates (the Panda: ~5 mm across the fingers).  Only an offset within
        HELD_OFFSET_MAX is corrected (a larger one is a cube not held), and the TCP is never
        lowered for a cube that rides high in the fingers (the fingertips would reach lower)."""
        off = np.subtract(self.poses()[name].pos, self.robot.tcp_pose().pos)
        if np.linalg.norm(off[:2]) > HELD_OFFSET_MAX:
            off[:] = 0.0
        off[2] = min(off[2], 0.0)
        return tuple(float(v) for v in np.asarray(cube_pos, float) - off)

    def _open_gap(self, name: str, poses, done: set[str]) -> tuple[np.ndarray, float] | None:
        """A gap (direction (2,) toward the neighbour, width to close in m) between a placed cube
        of a dense layout and a goal neighbour placed before it, or None: released LATERAL_GAP
        apart, the gaps would add up along a row."""
        target = self.plan.targets[name]
        for other in self.plan.order[:self.plan.order.index(name)]:
            t = self.plan.targets[other]
            d = np.subtract(t.pos[:2], target.pos[:2])
            dist = float(np.linalg.norm(d))
            touching = 0.5 * (t.size + target.size)
            if (not t.dense or abs(t.pos[2] - target.pos[2]) > 0.25 * target.size
                    or not touching - 0.002 < dist < touching + DENSE_GAP_CLOSE or other not in done):
                continue
            d = d / dist
            gap = self._room(poses[name].pos, d, {name}, poses)
            if GAP_CLOSE_MIN < gap < DENSE_GAP_CLOSE:
                return d, gap - GAP_CLOSE_LEFT
        return None

    def _tidy(self, before: str, poses) -> Iterator[np.ndarray] | None:
        """The next step closing the open gaps of a dense layout's cubes placed before
        ``before``: a push, or a loose cube moved out of the pusher's way; None when none is left."""
        done = self._done(poses)
        for name in self.plan.order[:self.plan.order.index(before)]:
            if not self.plan.targets[name].dense or name not in done or self.gap_pushes.get(name, 0) >= 2:
                continue
            gap = self._open_gap(name, poses, done)
            if gap is None:
                continue
            d, shift = gap
            here = np.asarray(poses[name].pos, float)
            moved = replace(self.plan.targets[name], pos=(*(here[:2] + shift * d), here[2]), quat=tuple(poses[name].quat))
            blockers = self._push_blockers(name, moved, -d, shift, poses)
            if not blockers:
                self.gap_pushes[name] = self.gap_pushes.get(name, 0) + 1
                return self._push(name, np.asarray(moved.pos), -d, shift, self._travel_z(name, here))
            if not any(self._at_target(b, poses) for b in blockers):
                return self._move_aside(blockers[0], poses, avoid=self._work_points(moved, -d, shift))
        return None

    def _nudge(self, name: str, target: Target, poses) -> Iterator[np.ndarray] | None:
        """A push that moves ``name``, upright in ``target``'s layer and within NUDGE_REACH of
        it, to ``target`` along a face normal: the one of its larger offset, else the other
        (the remaining offset is the next nudge); a cube turned more than DENSE_YAW_TOL is
        pushed even when in place, the pusher's face turning it square.  None when it is
        farther, in place, every such pusher path is blocked, or NUDGE_MAX nudges were spent
        on it."""
        here = np.asarray(poses[name].pos, float)
        if (self.nudges.get(name, 0) >= NUDGE_MAX or abs(here[2] - target.pos[2]) > 0.005
                or abs(up_axis(poses[name].quat)[1]) < 0.95):
            return None
        miss = np.subtract(target.pos[:2], here[:2])
        if np.linalg.norm(miss) > NUDGE_REACH:
            return None
        yaw = cube_yaw(target.quat)
        turned = abs(yaw_offset(poses[name].quat, target.quat)) > DENSE_YAW_TOL
        # a neighbour at its target but standing out a few mm past the line the pusher stops
        # at is pushed back into line, not in the way: it is tested where its target is
        at = self._at_targets(poses)
        lined_up = {n: Pose(self.plan.targets[n].pos, self.plan.targets[n].quat) if n in at else p
                    for n, p in poses.items()}
        normals = [np.array([math.cos(yaw + k * math.pi / 2), math.sin(yaw + k * math.pi / 2)]) for k in range(4)]
        for move in sorted(normals, key=lambda n: -float(miss @ n)):
            shift = float(miss @ move)
            if shift < NUDGE_MIN and not (turned and shift > -NUDGE_MIN):
                break
            shift = max(shift, 0.0)
            dst = np.array([here[0] + shift * move[0], here[1] + shift * move[1], target.pos[2]])
            if self._push_blockers(name, replace(target, pos=tuple(dst)), -move, shift, lined_up):
                continue
            self.nudges[name] = self.nudges.get(name, 0) + 1
            return self._push(name, dst, -move, shift, self._travel_z(name, here))
        return None

    def _push_start(self, name: str, dst: np.ndarray, out: np.ndarray, shift: float) -> np.ndarray:
        """Where (xy, m) the pusher comes down to push ``name`` from ``shift`` beside ``dst``."""
        return np.asarray(dst[:2]) + out * (shift + 0.5 * self.sizes[name] + PUSHER_HALF_THICKNESS + PUSH_APPROACH_GAP)

    def _hover_z(self, name: str, dst, *points) -> float:
        """TCP height (m) at which the open or closed fingertips clear ``name`` standing at
        ``dst`` (3,) and every other cube within HOVER_REACH of the ``points`` (xy): for short
        moves low over a layout."""
        tops = [p.pos[2] + 0.5 * self.sizes[n] for n, p in self.poses().items() if n in self.sizes and n != name
                and min(math.dist(p.pos[:2], pt[:2]) for pt in points) < HOVER_REACH]
        return float(max([dst[2] + 0.5 * self.sizes[name], *tops]) + HOVER_CLEARANCE)

    def _push(self, name: str, dst: np.ndarray, out: np.ndarray, shift: float, travel: float,
              hover: float | None = None) -> Iterator[np.ndarray]:
        """Slide ``name``, standing ``shift`` (m) beside ``dst`` (3,) along ``out`` (2,), to ``dst``
        with the closed fingers held across the push, low on its outer face; the hand comes
        from ``hover`` (m, TCP height; default ``travel``) and leaves at ``travel``."""
        half = 0.5 * self.sizes[name]
        side = np.array([-out[1], out[0]])
        yaw = math.atan2(side[0], -side[1])  # finger_axis(yaw) == side
        if abs(yaw) > YAW_LIMIT:
            yaw = _wrap(yaw + math.pi)
        standoff = half + PUSHER_HALF_THICKNESS
        # from where the cube stands now (a released cube may have slid or turned a little)
        shift = max(shift, float(np.subtract(self.poses()[name].pos[:2], dst[:2]) @ out))
        start = self._push_start(name, dst, out, shift)
        end = dst[:2] + out * (standoff + PUSH_OVERSHOOT)
        hover = travel if hover is None else hover
        z = dst[2] - half + PUSH_HEIGHT
        # tilt the hand about the side axis so the fingertips lead: the fingers' faces widen
        # upward, and a push high on the cube's face tips it over
        tilt = np.array([math.cos(PUSH_TILT / 2), *(math.sin(PUSH_TILT / 2) * np.array([side[0], side[1], 0.0]))])
        q = np.zeros(4)
        mujoco.mju_mulQuat(q, tilt, top_down_quat(yaw))
        q = tuple(q)
        # turn top-down first, then tilt: an arm asked for both at once in one rotation (up to
        # ~180 degrees) swung its wrist into a joint limit and stalled (the Panda)
        yield from waypoint_actions(self.robot, [
            Waypoint((start[0], start[1], hover), yaw, GRIPPER_CLOSED, tol=0.01, max_steps=60),
            Waypoint((start[0], start[1], hover), yaw, GRIPPER_CLOSED, tol=0.008, max_steps=30, quat=q),
            Waypoint((start[0], start[1], z), yaw, GRIPPER_CLOSED, tol=0.003, max_steps=40, quat=q)])
        # the stroke: aim PUSH_LEAD past the end (the cube's friction holds the hand back on its
        # compliant weld or arm) and stop once the TCP is within PUSH_TOL of the end along the push
        aim = Waypoint((end[0] - PUSH_LEAD * out[0], end[1] - PUSH_LEAD * out[1], z), yaw, GRIPPER_CLOSED, quat=q)
        for _ in range(PUSH_STEPS):
            tcp = self.robot.tcp_pose()
            if float(np.subtract(tcp.pos[:2], end) @ out) < PUSH_TOL:
                break
            yield delta_action(tcp, aim)
        # back and up with the fingers closed: opened low beside a layout, a finger reaching
        # ~5 cm along the row knocked the cubes placed there (the Panda, by up to 12 mm); the
        # next primitive opens them at travel height
        yield from waypoint_actions(self.robot, [
            Waypoint((start[0], start[1], z + 0.002), yaw, GRIPPER_CLOSED, tol=0.006, max_steps=20, quat=q),
            Waypoint((start[0], start[1], travel), yaw, GRIPPER_CLOSED, tol=0.01, max_steps=40),
        ])

    def _pick(self, src: np.ndarray, yaw: float, travel: float, quat=None,
              opening: float = GRIPPER_OPEN) -> Iterator[np.ndarray]:
        wps = [
            Waypoint((src[0], src[1], travel), yaw, opening, tol=0.008, max_steps=80),
            Waypoint((src[0], src[1], src[2] + 0.03), yaw, opening, tol=0.006),
            Waypoint(tuple(src), yaw, opening, max_steps=40),
            Waypoint(tuple(src), yaw, GRIPPER_CLOSED, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS),
            Waypoint((src[0], src[1], travel), yaw, GRIPPER_CLOSED, tol=0.01),
        ]
        yield from waypoint_actions(self.robot, wps)

    def _retreat(self) -> Iterator[np.ndarray]:
        tcp = self.robot.tcp_pose().pos
        z = max(tcp[2], C.TABLE_TOP_Z + TRAVEL_MIN)
        yield from waypoint_actions(self.robot, [
            Waypoint((tcp[0], tcp[1], tcp[2]), 0.0, GRIPPER_OPEN, tol=1.0, max_steps=4, min_steps=4),
            Waypoint((tcp[0], tcp[1], z + 0.05), 0.0, GRIPPER_OPEN, tol=0.01, max_steps=30)])

    def _free_spot(self, name: str, poses, keepout: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0),
                   avoid=(), near=None):
        """A free place on the table for ``name`` (m): far from every other cube, every target
        (farther from a dense layout's: DENSE_KEEPOUT) and the points ``avoid`` (xy), nearest to
        ``near`` (xy; default where it is), which is itself a candidate.  ``keepout`` (-x, +x,
        -y, +y) widens what must stay clear around the spot (the tilted hand of a flip)."""
        others = [(np.asarray(p.pos[:2]), 0.0) for n, p in poses.items() if n in self.sizes and n != name]
        others += [(np.asarray(t.pos[:2]), DENSE_KEEPOUT if t.dense else 0.0)
                   for n, t in self.plan.targets.items() if n != name]
        others += [(np.asarray(a[:2], float), 0.0) for a in avoid]
        best = None
        here = np.asarray(poses[name].pos[:2] if near is None else near[:2], float)
        margin = 0.06
        grid = [(x, y) for x in np.arange(C.WORKSPACE_X[0] + 0.02, C.WORKSPACE_X[1] - 0.02 + 1e-9, BUFFER_STEP)
                for y in np.arange(C.WORKSPACE_Y[0] + 0.02, C.WORKSPACE_Y[1] - 0.02 + 1e-9, BUFFER_STEP)]
        for x, y in ([tuple(here)] if near is not None else []) + grid:
            gap = 1.0
            for o, extra in others:  # distance from o to the keep-out box around (x, y)
                dx = max(x - keepout[0] - o[0], o[0] - x - keepout[1], 0.0)
                dy = max(y - keepout[2] - o[1], o[1] - y - keepout[3], 0.0)
                gap = min(gap, math.hypot(dx, dy) - extra)
            key = (min(gap, 0.12) >= margin, min(gap, 0.12), -math.dist((x, y), here))
            if best is None or key > best[0]:
                best = (key, (float(x), float(y)))
        return best[1]

    def _move_aside(self, name: str, poses, avoid=()) -> Iterator[np.ndarray]:
        x, y = self._free_spot(name, poses, avoid=avoid)
        z = C.TABLE_TOP_Z + 0.5 * self.sizes[name]
        q = poses[name].quat
        aside = Target(name, (x, y, z), tuple(q), self.sizes[name], False)
        yield from self._pick_place(name, aside, poses)

    # -- flipping -------------------------------------------------------------------
    def _face_up_ok(self, name: str, target: Target, poses) -> bool:
        want = up_axis(target.quat)
        have = up_axis(poses[name].quat)
        return want[0] == have[0] and np.sign(want[1]) == np.sign(have[1]) and abs(have[1]) > 0.8

    def _flip(self, name: str, target: Target, poses) -> Iterator[np.ndarray]:
        """Turn ``name`` 90 degrees about a horizontal axis toward ``target``'s up face (a face
        that is down comes up in two flips).

        The hand grasps the cube across the turning axis with its approach tilted away from
        the face that must come up (FLIP_TILT), lifts it, turns about the vertical to the
        flip's aim, swings 90 degrees about the finger axis (it ends tilted the other way),
        turns to the target's yaw where the wrist allows (:meth:`_flip_aim`) and puts the cube
        down: at its target when the flip ends at the target's orientation and the spot is
        free, else at a free spot nearest FLIP_SPOT.  Neither tilt nor swing takes the hand
        far from top-down: the Panda's wrist cannot point the hand forward (FLIP_FORWARD_MAX),
        and an earlier flip's swing to a horizontal hand ran its IK 17 cm off the point it
        turns about and flung the cube off the table."""
        r_now = rot(poses[name].quat)
        k, s = up_axis(target.quat)
        n = r_now[:, k] * np.sign(s)  # world direction of the face that must end up
        if n[2] < -0.5:  # face down: the side face nearest sideways comes up first
            n = max((r_now[:, j] * sg for j in range(3) if j != k for sg in (1.0, -1.0)), key=lambda v: abs(v[1]))
        theta = math.atan2(n[1], n[0])
        aim, yaw, tilt, settle, last = self._flip_aim(theta, r_now, target)
        q_pick = _tilted(theta, yaw, -tilt)
        q_turned = _tilted(aim, yaw + _wrap(aim - theta), -tilt)
        q_swung = _tilted(aim, yaw + _wrap(aim - theta), math.pi / 2 - tilt)
        q_put = tuple(mat_to_quat(rot(yaw_quat(settle)) @ rot(q_swung)))
        src = np.asarray(poses[name].pos, float)
        near = target.pos if last else FLIP_SPOT  # a flip that ends at the target's pose puts it there
        x, y = self._free_spot(name, poses, keepout=(0.1, 0.1, 0.1, 0.1), near=near)
        half = 0.5 * self.sizes[name]
        high = C.TABLE_TOP_Z + FLIP_HEIGHT
        low = C.TABLE_TOP_Z + half + FLIP_DROP
        travel = max(self._travel_z(name, src), high)
        back = np.array([x, y, low]) - FLIP_BACK_OFF * (rot(q_put) @ np.array([0.0, 0.0, 1.0]))
        rate = FLIP_TURN_RATE
        yield from waypoint_actions(self.robot, [
            Waypoint((src[0], src[1], travel), yaw, GRIPPER_OPEN, tol=0.008, max_steps=80, quat=q_pick),
            Waypoint((src[0], src[1], src[2] + 0.03), yaw, GRIPPER_OPEN, tol=0.006, quat=q_pick),
            Waypoint(tuple(src), yaw, GRIPPER_OPEN, max_steps=40, quat=q_pick),
            Waypoint(tuple(src), yaw, GRIPPER_CLOSED, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS, quat=q_pick),
            Waypoint((src[0], src[1], travel), yaw, GRIPPER_CLOSED, tol=0.01, quat=q_pick),
            Waypoint((x, y, high), yaw, GRIPPER_CLOSED, tol=0.01, max_steps=80, quat=q_turned, turn_rate=rate),
            Waypoint((x, y, high), yaw, GRIPPER_CLOSED, tol=0.01, max_steps=80, quat=q_swung, turn_rate=rate),
            Waypoint((x, y, high), yaw, GRIPPER_CLOSED, tol=0.01, max_steps=60, quat=q_put, turn_rate=rate),
            Waypoint((x, y, low), yaw, GRIPPER_CLOSED, tol=0.005, max_steps=60, quat=q_put),
            Waypoint((x, y, low), yaw, GRIPPER_OPEN, tol=1.0, max_steps=GRIPPER_STEPS, min_steps=GRIPPER_STEPS, quat=q_put),
            Waypoint(tuple(back), yaw, GRIPPER_OPEN, tol=0.01, max_steps=40, quat=q_put),
            Waypoint((back[0], back[1], high), yaw, GRIPPER_OPEN, tol=0.02, max_steps=40, quat=q_put),
        ])

    def _flip_aim(self, theta: float, r_now: np.ndarray, target: Target) -> tuple[float, float, float, float, bool]:
        """Plan a flip of a cube at orientation ``r_now`` (3, 3) whose face pointing at
        ``theta`` (rad, world yaw) comes up: the aim (rad, world yaw within FLIP_AIM_MAX of +x)
        the face points at when the hand swings it up, the top-down yaw (rad) of the hand that
        grasps it, its tilt (rad) at the grasp, the turn (rad) about the vertical after the
        swing, and whether the cube then ends at ``target``'s orientation (the turn sets its
        yaw).  The hand's yaw stays within the wrist's range and it tilts forward at most
        FLIP_FORWARD_MAX; a flip that ends at the target is preferred (where the wrist cannot
        turn the cube that far, a pick and place sets its yaw after), then the least turning.

        Raises:
            OracleError: no aim keeps the hand within the wrist's range.
        """
        best = None
        for aim in np.linspace(-FLIP_AIM_MAX, FLIP_AIM_MAX, 121):
            turn = _wrap(aim - theta)
            swung = _swing(aim, math.pi / 2) @ rot(yaw_quat(turn)) @ r_now
            err = rot(target.quat) @ swung.T  # a turn about the vertical when the face is up
            # the grasp tilts the approach toward -theta by `tilt`, the swing ends it toward aim
            low = math.pi / 2 - FLIP_FORWARD_MAX / max(math.cos(aim), 1e-9)
            high = FLIP_FORWARD_MAX / max(-math.cos(theta), 1e-9)
            options = [(0.0, False)]  # the swing alone: a pick and place sets the yaw after
            if err[2, 2] > math.cos(FLIP_YAW_TOL):
                options.append((math.atan2(err[1, 0], err[0, 0]), True))
            for settle, last in options:
                yaws = [y for y in (theta + j * math.pi for j in range(-3, 4))
                        if max(abs(y), abs(y + turn), abs(y + turn + settle)) <= YAW_LIMIT]
                key = (not last, abs(turn) + abs(settle))
                if yaws and low <= high and (best is None or key < best[0]):
                    tilt = float(np.clip(FLIP_TILT, low, high))
                    best = (key, float(aim), float(min(yaws, key=abs)), tilt, float(settle), last)
        if best is None:
            raise OracleError(f"no flip of a cube whose face points at yaw {theta:.2f} rad within the wrist's range")
        return best[1:]
