"""Deterministic repair operators for the builtin backend.

A failing gate's result carries a failure class (syntax, api_usage, runtime,
success_check, stability, bounds, constraint, visibility).  :func:`route` picks the
operator for that class; each operator maps a TaskSchema to a repaired TaskSchema (or
None when it has nothing to offer), and the code is regenerated from the result.
Paper, appendix "Iterative Repair and Agent Taxonomy".
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from rpg.domain import constants as C
from rpg.domain.predicates import And, Predicate, Stack, from_dict
from rpg.schema.model import PoseSpec, RepairRecord, TaskSchema

Operator = Callable[[TaskSchema, dict], TaskSchema | None]


def _with(schema: TaskSchema, **changes) -> TaskSchema:
    doc = schema.model_dump()
    doc.update(changes)
    return TaskSchema.model_validate(doc)


def _record(schema: TaskSchema, op: str, reason: str, stage: str = "validation") -> list[dict]:
    return [r.model_dump() for r in schema.repairs] + [RepairRecord(operator=op, stage=stage, reason=reason).model_dump()]


def regenerate_code(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Syntax / API / runtime failures in hand-edited or model code: re-emit from the schema."""
    return _with(schema, repairs=_record(schema, "REGENERATE_CODE", failure.get("message", "")[:200]))


def layout_extent(schema: TaskSchema) -> tuple[np.ndarray, np.ndarray]:
    """Min and max corners (x, y) of the goal layout's footprints, m."""
    pts = []
    for a in schema.assets:
        p = np.asarray(schema.goal_layout[a.name].position[:2])
        half = np.array([a.size / 2, a.size / 2]) if a.kind != "goal_patch" else np.array(a.build().extents[:2]) / 2
        pts += [p - half, p + half]
    pts = np.array(pts)
    return pts.min(axis=0), pts.max(axis=0)


def move_into_workspace(schema: TaskSchema, failure: dict | None = None, stage: str = "validation") -> TaskSchema | None:
    """Translate the whole goal layout so its footprint lies inside the workspace.

    Returns None if the layout is wider than the workspace (nothing to translate into).
    """
    lo, hi = layout_extent(schema)
    ws_lo = np.array([C.WORKSPACE_X[0], C.WORKSPACE_Y[0]])
    ws_hi = np.array([C.WORKSPACE_X[1], C.WORKSPACE_Y[1]])
    if np.any(hi - lo > ws_hi - ws_lo):
        return None
    shift = np.maximum(ws_lo - lo, 0) - np.maximum(hi - ws_hi, 0)
    if np.allclose(shift, 0):
        return None
    layout = {}
    for n, p in schema.goal_layout.items():
        x, y, z = p.position
        layout[n] = PoseSpec(position=(round(x + shift[0], 6), round(y + shift[1], 6), z), quaternion=p.quaternion)
    fixed = {n: layout[n] for n in schema.initial_state.fixed}
    init = schema.initial_state.model_copy(update={"fixed": fixed})
    return _with(schema, goal_layout={n: v.model_dump() for n, v in layout.items()}, initial_state=init.model_dump(),
                 repairs=_record(schema, "MOVE_INTO_WORKSPACE", f"shifted the goal layout by {np.round(shift, 3).tolist()} m", stage))


def restack_layout(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Unstable goal: rebuild the goal poses of every stack from its support chain
    (each cube centred on the one below, touching), and reset every cube upright."""
    goal = schema.goal_predicate()
    layout = {n: p.model_dump() for n, p in schema.goal_layout.items()}
    changed = False
    stack = [goal]
    while stack:
        p = stack.pop()
        stack.extend(p.children())
        if isinstance(p, Stack):
            base = schema.goal_layout[p.objects[0]].position
            for level, n in enumerate(p.objects):
                size = next(a.size for a in schema.assets if a.name == n)
                want = (base[0], base[1], round(C.TABLE_TOP_Z + size / 2 + level * (size + C.SPAWN_CLEARANCE), 6))
                if tuple(layout[n]["position"]) != want or tuple(layout[n]["quaternion"]) != (1.0, 0.0, 0.0, 0.0):
                    layout[n] = {"position": want, "quaternion": (1.0, 0.0, 0.0, 0.0)}
                    changed = True
    if not changed:
        return None
    return _with(schema, goal_layout=layout, repairs=_record(schema, "RESTACK_SUPPORT_CHAIN", failure.get("message", "")[:200]))


def reorder_support_chain(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Cyclic or ungrounded support: drop the support predicates that close a cycle."""
    goal = schema.goal_predicate()
    children = goal.children() if isinstance(goal, And) else [goal]
    import networkx as nx

    g = nx.DiGraph()
    kept: list[Predicate] = []
    dropped = []
    for c in children:
        edges = c.support_edges()
        h = g.copy()
        h.add_edges_from(edges)
        if edges and not nx.is_directed_acyclic_graph(h):
            dropped.append(c.describe())
            continue
        g = h
        kept.append(c)
    if not dropped:
        return None
    new_goal = kept[0] if len(kept) == 1 else And(kept)
    return _with(schema, goal=new_goal.to_dict(),
                 repairs=_record(schema, "REORDER_SUPPORT_CHAIN", f"removed conflicting relation(s): {'; '.join(dropped)}"))


def switch_readable_face(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Occluded labels: read them on the other face (up <-> front)."""
    goal = schema.goal_predicate()

    def swap(p: Predicate) -> Predicate:
        d = p.to_dict()
        if "face" in d:
            d["face"] = "front" if d["face"] == "up" else "up"
        if "children" in d:
            d["children"] = [swap(from_dict(c)).to_dict() for c in d["children"]]
        return from_dict(d)

    new = swap(goal)
    if new == goal:
        return None
    return _with(schema, goal=new.to_dict(), repairs=_record(schema, "SWITCH_READABLE_FACE", failure.get("message", "")[:200]))


def widen_separation(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """G already true at reset: spread rho_0 (larger minimum separation) so the start differs from the goal."""
    init = schema.initial_state
    if init.min_separation >= 0.12:
        return None
    new = init.model_copy(update={"min_separation": round(init.min_separation + 0.02, 3)})
    return _with(schema, initial_state=new.model_dump(),
                 repairs=_record(schema, "WIDEN_INITIAL_SEPARATION", failure.get("message", "")[:200]))


OPERATORS: dict[str, tuple[Operator, ...]] = {
    "syntax": (regenerate_code,),
    "api_usage": (regenerate_code,),
    "runtime": (regenerate_code,),
    "success_check": (restack_layout, switch_readable_face),
    "stability": (restack_layout,),
    "bounds": (move_into_workspace,),
    "constraint": (reorder_support_chain,),
    "visibility": (switch_readable_face,),
    "nontrivial": (widen_separation,),
}
"""Failure class -> repair operators, tried in order until one offers a fix."""


def route(failure: dict) -> tuple[str, tuple[Operator, ...]] | None:
    """Pick the operators for a failing gate result (by ``kind``; the non-trivial gate has its own)."""
    kind = "nontrivial" if failure.get("gate") == "nontrivial" else failure.get("kind", "runtime")
    ops = OPERATORS.get(kind)
    return (kind, ops) if ops else None
