"""The oracle's goal: where each cube must end, and in which order to put it there.

The compiled task's goal configuration (``goal_state_code.py``) is one arrangement that
satisfies G, at fixed table coordinates.  In an episode the goal patches stand where rho_0
put them and the cubes are scattered, so :func:`plan_goal` adapts it:

- cubes whose goal lies over a goal patch (directly or up a stack) move with that patch;
- a task without patches may be built anywhere: the layout is also tried translated so one
  cube's goal falls where that cube already stands (a stack is built on its bottom cube
  where it lies), and the candidate needing the fewest moves wins;
- every candidate is checked by evaluating G on the planned configuration in a scratch
  copy of the task (no robot, not the episode's state), so a plan always means G.

The order is bottom-up over the goal's support graph, and follows the events of a temporal
goal ("first A, then B").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco
import networkx as nx
import numpy as np

from rpg.domain import constants as C
from rpg.domain.layouts import dense_cubes
from rpg.domain.predicates import InOrder
from rpg.domain.state import Pose
from rpg.env.scripted import cube_yaw
from rpg.errors import TaskInvalid


class OracleError(TaskInvalid):
    """The oracle cannot plan for this task (no goal configuration, or none that satisfies G,
    or an environment it cannot drive); exit code 1 on the command line."""


SUPPORT_XY_TOL = 0.75
"""A goal cube rests on another when their centres are closer than this many cube edges in xy
and it is higher by at least half an edge."""

ROBUSTNESS_SETTLE_STEPS = 500
"""Physics steps the planned goal configuration settles before G is checked again (a goal that
holds only before contacts settle is fragile: a robot cannot reproduce it)."""

DENSE_YAW_TOL = 0.1
"""Yaw error (rad, modulo pi/2) a cube in a dense layout may have."""

DENSE_ANCHOR_ANGLE_TOL = 0.03
"""A dense layout's cube stays where rho_0 put it (the layout is built around it) only when it
is turned less than this (rad) from the layout: a turned cube's corner narrows its neighbours'
gaps."""

WORKSPACE_MARGIN = 0.01
"""How far outside the workspace (m) a translated goal layout may reach."""


@dataclass(frozen=True)
class Target:
    """Where one cube must end: position (3,) m and quaternion (w, x, y, z), world frame.

    ``exact``: the cube's full orientation matters (a semantic goal reads its faces);
    otherwise any orientation that is a symmetry of the cube will do (upright, yaw modulo
    pi/2; in a ``dense`` layout, where a neighbour's face is within C.DENSE_GAP, the yaw too).
    ``supports``: the cubes its goal rests on.
    """

    name: str
    pos: tuple[float, float, float]
    quat: tuple[float, float, float, float]
    size: float
    exact: bool
    supports: tuple[str, ...] = ()
    dense: bool = False


@dataclass
class GoalPlan:
    """The cubes to place, in order, and the offset the layout was moved by (m)."""

    targets: dict[str, Target]
    order: list[str]
    offset: tuple[float, float] = (0.0, 0.0)
    moves: int = 0
    notes: list[str] = field(default_factory=list)


def rot(quat) -> np.ndarray:
    """Rotation matrix (3, 3) of a quaternion (w, x, y, z)."""
    m = np.zeros(9)
    mujoco.mju_quat2Mat(m, np.asarray(quat, float))
    return m.reshape(3, 3)


def up_axis(quat) -> tuple[int, float]:
    """Index and sign of the cube's local axis nearest world +z, and its cosine."""
    z = rot(quat)[2]  # row 2: world z in local coordinates
    k = int(np.argmax(np.abs(z)))
    return k, float(z[k])


def yaw_offset(quat, target_quat) -> float:
    """Yaw (rad) of a cube at ``quat`` from one at ``target_quat`` (w, x, y, z), modulo a
    cube's quarter-turn symmetry: in [-pi/4, pi/4)."""
    return (cube_yaw(quat) - cube_yaw(target_quat) + math.pi / 4) % (math.pi / 2) - math.pi / 4


def pose_matches(target: Target, pos, quat, xy_tol: float = 0.012, z_tol: float = 0.01,
                 angle_tol: float = 0.25, yaw_tol: float = DENSE_YAW_TOL) -> bool:
    """Whether a cube at ``pos``/``quat`` is at ``target`` (tolerances in m and rad; ``yaw_tol``
    for a dense layout's coloured cube)."""
    p = np.asarray(pos, float)
    t = np.asarray(target.pos, float)
    if np.linalg.norm(p[:2] - t[:2]) > xy_tol or abs(p[2] - t[2]) > z_tol:
        return False
    if target.exact:
        r = rot(target.quat).T @ rot(quat)
        tol = min(angle_tol, yaw_tol) if target.dense else angle_tol
        return math.acos(max(-1.0, min(1.0, (np.trace(r) - 1) / 2))) < tol
    _, cos = up_axis(quat)
    if target.dense and abs(yaw_offset(quat, target.quat)) > yaw_tol:
        return False
    return abs(cos) > math.cos(angle_tol)


def semantic_objects(goal) -> set[str]:
    """Objects whose faces a goal reads (their full orientation matters)."""
    return {n for p in goal.walk() if getattr(p, "semantic", False) for n in p.object_names()}


def temporal_events(goal) -> list[list[str]]:
    """Object names of each event of the goal's first temporal (``InOrder``) node, in order."""
    for p in goal.walk():
        if isinstance(p, InOrder):
            return [sorted(e.object_names()) for e in p.events]
    return []


def _supports(poses: dict[str, Pose], sizes: dict[str, float]) -> dict[str, tuple[str, ...]]:
    out = {}
    for a, pa in poses.items():
        under = []
        for b, pb in poses.items():
            if a == b:
                continue
            dxy = math.dist(pa.pos[:2], pb.pos[:2])
            if dxy < SUPPORT_XY_TOL * sizes[b] and pa.pos[2] - pb.pos[2] > 0.5 * sizes[b]:
                under.append(b)
        out[a] = tuple(sorted(under))
    return out


def _order_key(t: Target) -> tuple:
    """Tie-break between cubes free to be placed next: by name, except that a dense layout
    (cubes touching) is filled layer by layer, each layer from the far row (high x) to the
    near one and each row from +y to -y, so that a cube's placed neighbours stand only on its
    +x and +y sides and it can be pushed against them from the free sides."""
    if not t.dense:
        return (0, 0.0, 0.0, 0.0, t.name)
    return (1, round(t.pos[2], 3), round(-t.pos[0], 3), round(-t.pos[1], 3), t.name)


def placement_order(targets: dict[str, Target], events: list[list[str]]) -> list[str]:
    """Cubes in placement order: supports first; a temporal goal's events in their order;
    ties broken by name, and dense layouts layer by layer in a sweep (``_order_key``);
    deterministic.

    Raises:
        OracleError: the constraints form a cycle.
    """
    g = nx.DiGraph()
    g.add_nodes_from(sorted(targets))
    for name, t in targets.items():
        for s in t.supports:
            if s in targets:
                g.add_edge(s, name)
    for before, after in zip(events, events[1:], strict=False):
        for a in before:
            for b in after:
                if a in targets and b in targets and a != b:
                    g.add_edge(a, b)
    try:
        return list(nx.lexicographical_topological_sort(g, key=lambda n: _order_key(targets[n])))
    except nx.NetworkXUnfeasible as exc:
        raise OracleError("the goal's support and temporal order form a cycle") from exc


def _inside_workspace(pos, margin: float = WORKSPACE_MARGIN) -> bool:
    return (C.WORKSPACE_X[0] - margin <= pos[0] <= C.WORKSPACE_X[1] + margin
            and C.WORKSPACE_Y[0] - margin <= pos[1] <= C.WORKSPACE_Y[1] + margin)


def plan_goal(scratch, current: dict[str, Pose], movable: dict[str, float]) -> GoalPlan:
    """Adapt the task's goal configuration to the episode's state.

    Args:
        scratch: a robot-free :class:`rpg.domain.task.Task` (its scene is used to evaluate G
            on candidate configurations; its state is overwritten).
        current: every object's pose now, by name.
        movable: edge length (m) of each movable cube, by name.

    Returns:
        The targets (cubes that must end somewhere else than where they are now, and the
        ones that stay), their order and the chosen offset.

    Raises:
        OracleError: the task has no goal configuration, or no candidate configuration
            satisfies G.
    """
    if scratch.data.goal_poses is None:
        raise OracleError(f"the task has no goal configuration: {scratch.data.goal_error}")
    goal = dict(scratch.data.goal_poses)
    exact = semantic_objects(scratch.goal_predicate)
    patches = [n for n in goal if n not in movable]
    patch_shift = {p: np.subtract(current[p].pos, goal[p].pos)[:2] for p in patches}
    supports = _supports({n: goal[n] for n in movable}, movable)
    dense = dense_cubes(goal, movable)

    def shift_of(name: str, default: np.ndarray) -> np.ndarray:
        """The shift of the patch under ``name``'s goal (or under its bottom support)."""
        bottom = name
        while supports[bottom]:
            bottom = supports[bottom][0]
        for p in patches:
            half = np.asarray(scratch.scene.assets[p].extents[:2]) / 2
            if np.all(np.abs(np.subtract(goal[bottom].pos[:2], goal[p].pos[:2])) <= half + 0.01):
                return patch_shift[p]
        return default

    candidates = [np.zeros(2)]
    if not patches:
        anchors = [n for n in sorted(movable) if not supports[n]]
        if dense:  # a dense layout grows from its first cube (the sweep's corner), which may stay
            anchors = [min((n for n in anchors if n in dense),
                           key=lambda n: (goal[n].pos[2], -goal[n].pos[0], -goal[n].pos[1], n))]
        for n in anchors:
            candidates.append(np.subtract(current[n].pos[:2], goal[n].pos[:2]))

    best = None
    for offset in candidates:
        config, targets = {}, {}
        ok = True
        for n in sorted(movable):
            d = shift_of(n, offset)
            pos = (goal[n].pos[0] + d[0], goal[n].pos[1] + d[1], goal[n].pos[2])
            if not _inside_workspace(pos):
                ok = False
                break
            t = Target(n, pos, tuple(goal[n].quat), movable[n], n in exact, supports[n], n in dense)
            anchor_tol = DENSE_ANCHOR_ANGLE_TOL if n in dense else 0.25
            if pose_matches(t, current[n].pos, current[n].quat, xy_tol=0.004,
                            angle_tol=anchor_tol, yaw_tol=min(anchor_tol, DENSE_YAW_TOL)):
                pos, quat = tuple(current[n].pos), tuple(current[n].quat)
                t = Target(n, pos, quat, movable[n], n in exact, supports[n], n in dense)
            targets[n] = t
            config[n] = Pose(t.pos, t.quat)
        if not ok:
            continue
        for p in patches:
            config[p] = current[p]
        scratch.set_state(config)
        if not scratch.evaluate().satisfied:
            continue
        moves = sum(1 for n, t in targets.items() if not pose_matches(t, current[n].pos, current[n].quat))
        key = (moves, float(np.hypot(*offset)))
        if best is None or key < best[0]:
            best = (key, targets, offset, moves)
    if best is None:
        raise OracleError("no placement of the goal configuration satisfies G in this episode "
                          "(goal patches moved the layout out of the workspace?)")
    _, targets, offset, moves = best
    order = placement_order(targets, temporal_events(scratch.goal_predicate))
    plan = GoalPlan(targets, order, (float(offset[0]), float(offset[1])), moves)
    config = {n: Pose(t.pos, t.quat) for n, t in targets.items()} | {p: current[p] for p in patches}
    scratch.set_state(config)
    scratch.step(ROBUSTNESS_SETTLE_STEPS)
    result = scratch.evaluate()
    if not result.satisfied:
        why = "; ".join(r.reason for r in result.leaves() if not r.satisfied)
        plan.notes.append(f"G fails once the goal configuration has settled for "
                          f"{ROBUSTNESS_SETTLE_STEPS * C.TIMESTEP:.1f} s ({why}): a fragile goal")
    return plan
