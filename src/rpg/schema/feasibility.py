"""Feasibility pre-validation of a TaskSchema before any code exists.

Paper, appendix "Task Proposal Feasibility Reasoning": object and label limits, the goal
layout fits the workspace, towers within reach, rho_0 can be sampled.  Violations get a
structured repair recorded in the schema; what cannot be repaired raises
:class:`InfeasibleTask` before code generation.
"""

from __future__ import annotations

import numpy as np

from rpg.domain import constants as C
from rpg.domain.sampling import InfeasibleLayout, sample_scattered
from rpg.domain.state import Pose
from rpg.errors import BadInput
from rpg.schema.edits import add_repair, layout_extent, move_into_workspace, with_changes
from rpg.schema.model import RepairRecord, TaskSchema


class InfeasibleTask(BadInput):
    """The task cannot be realised in the domain; the message says why and what would work."""


def check_feasibility(schema: TaskSchema) -> TaskSchema:
    """Return the schema, repaired where possible.

    Raises:
        InfeasibleTask: too many objects, a tower out of reach, a layout wider than the
            workspace, or an initial state that cannot be sampled.
    """
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    if len(cubes) > C.MAX_OBJECTS:
        raise InfeasibleTask(f"{len(cubes)} cubes exceed the limit of {C.MAX_OBJECTS}, a quantity no task holds; use fewer cubes")
    top = max(p.position[2] for p in schema.goal_layout.values()) - C.TABLE_TOP_Z
    if top > C.MAX_TOWER_HEIGHT:
        n = int(round(top / C.CUBE_EDGE + 0.5))
        raise InfeasibleTask(
            f"the goal structure rises {top:.2f} m (~{n} cubes) above the table; the reach limit is "
            f"{C.MAX_TOWER_HEIGHT:.2f} m ({int(C.MAX_TOWER_HEIGHT / C.CUBE_EDGE)} cubes); use a shorter tower")
    lo, hi = layout_extent(schema)
    if hi[0] - lo[0] > C.WORKSPACE_X[1] - C.WORKSPACE_X[0] or hi[1] - lo[1] > C.WORKSPACE_Y[1] - C.WORKSPACE_Y[0]:
        raise InfeasibleTask(
            f"the goal layout is {hi[0] - lo[0]:.2f} x {hi[1] - lo[1]:.2f} m; the workspace is "
            f"{C.WORKSPACE_X[1] - C.WORKSPACE_X[0]:.2f} x {C.WORKSPACE_Y[1] - C.WORKSPACE_Y[0]:.2f} m; use fewer cubes")
    moved = move_into_workspace(schema, stage="feasibility")
    if moved is not None:
        schema = moved
    schema = _readable_labels(schema)
    assets = schema.built_assets()
    fixed = {n: Pose(tuple(p.position), tuple(p.quaternion)) for n, p in schema.initial_state.fixed.items()}
    for sep in (schema.initial_state.min_separation, 0.055, C.CUBE_EDGE * 1.2):
        try:
            for seed in range(3):
                sample_scattered(np.random.default_rng(seed), assets, sep, schema.initial_state.yaw_range,
                                 schema.initial_state.structures, fixed)
        except InfeasibleLayout:
            continue
        if sep != schema.initial_state.min_separation:
            init = schema.initial_state.model_copy(update={"min_separation": sep})
            schema = with_changes(schema, initial_state=init.model_dump(),
                           repairs=add_repair(schema, "REDUCE_INITIAL_SEPARATION",
                                           f"{len(assets)} objects need a separation of {sep:.3f} m to fit", "feasibility"))
        return schema
    raise InfeasibleTask(f"{len(cubes)} cubes cannot be scattered in the workspace at reset; use fewer cubes")


def uncovered_faces(schema: TaskSchema) -> dict[str, set[str]]:
    """Per cube, the faces (``up``, ``front``) no other cube covers in the goal layout.

    A cube covers the up face of one whose centre is one level below it and within half
    an edge in the plane; it covers the front face of one one edge nearer the robot (smaller
    x) at the same height.  An analytic estimate before any physics (paper, "Geometric
    Visibility": occluded faces carry no semantic requirement); the visibility gate then
    checks the settled goal state with rays.
    """
    cubes = {a.name: (np.asarray(schema.goal_layout[a.name].position), a.size) for a in schema.assets
             if a.kind != "goal_patch"}
    out = {}
    for n, (p, e) in cubes.items():
        faces = {"up", "front"}
        for m, (q, _) in cubes.items():
            if m == n:
                continue
            d = q - p
            if abs(d[0]) < e / 2 and abs(d[1]) < e / 2 and 0.5 * e < d[2] < 1.5 * e:
                faces.discard("up")
            if -1.5 * e < d[0] < -0.5 * e and abs(d[1]) < e / 2 and abs(d[2]) < e / 2:
                faces.discard("front")
        out[n] = faces
    return out


def _readable_labels(schema: TaskSchema) -> TaskSchema:
    """Label requirements on covered faces: read the other face, or, when neither face can be
    read, drop the semantic requirement and keep the structure (SWITCH_TO_SPATIAL_ONLY)."""
    from rpg.domain.predicates import And, from_dict

    goal = schema.goal_predicate()
    parts = goal.conjuncts()
    faces = uncovered_faces(schema)

    def readable(p, face: str) -> bool:
        seen = [n for n in p.objects if face in faces.get(n, set())]
        return len(seen) >= 2 if p.name == "sorted_by" else len(seen) == len(p.objects)

    kept, repairs = [], []
    for p in parts:
        face = getattr(p, "face", None)
        if not p.semantic or face not in ("up", "front") or readable(p, face):
            kept.append(p)
            continue
        other = "front" if face == "up" else "up"
        if readable(p, other):
            kept.append(from_dict({**p.to_dict(), "face": other}))
            repairs.append(("SWITCH_READABLE_FACE", f"{p.describe()}: the {face} faces are covered in the goal layout; "
                                                    f"the {other} faces are read instead"))
        else:
            repairs.append(("SWITCH_TO_SPATIAL_ONLY", f"{p.describe()}: too few labels can be seen in the goal layout "
                                                      "(up or front); the structure is kept without the label requirement"))
    if not repairs:
        return schema
    if not kept:
        raise InfeasibleTask("no requirement of the task can be checked on visible faces; use fewer or flatter cubes")
    new_goal = kept[0] if len(kept) == 1 else And(kept)
    records = [r.model_dump() for r in schema.repairs]
    records += [RepairRecord(operator=op, stage="feasibility", reason=reason).model_dump() for op, reason in repairs]
    reasoning = "semantic" if any(p.semantic for p in kept) else "spatial"
    return with_changes(schema, goal=new_goal, reasoning=reasoning, repairs=records)
