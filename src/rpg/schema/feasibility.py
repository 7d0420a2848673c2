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
from rpg.repair.operators import layout_extent, move_into_workspace
from rpg.schema.model import TaskSchema


class InfeasibleTask(ValueError):
    """The task cannot be realised in the domain; the message says why and what would work."""


def check_feasibility(schema: TaskSchema) -> TaskSchema:
    """Return the schema, repaired where possible.

    Raises:
        InfeasibleTask: too many objects, a tower out of reach, a layout wider than the
            workspace, or an initial state that cannot be sampled.
    """
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    if len(cubes) > C.MAX_OBJECTS:
        raise InfeasibleTask(f"{len(cubes)} cubes exceed the limit of {C.MAX_OBJECTS}; use fewer cubes")
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
            from rpg.repair.operators import _record, _with

            init = schema.initial_state.model_copy(update={"min_separation": sep})
            schema = _with(schema, initial_state=init.model_dump(),
                           repairs=_record(schema, "REDUCE_INITIAL_SEPARATION",
                                           f"{len(assets)} objects need a separation of {sep:.3f} m to fit", "feasibility"))
        return schema
    raise InfeasibleTask(f"{len(cubes)} cubes cannot be scattered in the workspace at reset; use fewer cubes")
