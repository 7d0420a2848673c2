"""Deterministic repair operators for the builtin backend.

A failing gate's result carries a failure class (syntax, api_usage, runtime,
success_check, stability, bounds, constraint, visibility).  :func:`route` picks the
operator for that class; each operator maps a TaskSchema to a repaired TaskSchema (or
None when it has nothing to offer), and the code is regenerated from the result.
Paper, appendix "Iterative Repair and Agent Taxonomy".
"""

from __future__ import annotations

from collections.abc import Callable

from rpg.domain import constants as C
from rpg.domain.predicates import And, Predicate, Stack, from_dict
from rpg.schema.edits import add_repair, move_into_workspace, with_changes
from rpg.schema.model import TaskSchema

__all__ = ["OPERATORS", "move_into_workspace", "route"]

Operator = Callable[[TaskSchema, dict], TaskSchema | None]


def regenerate_code(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Syntax / API / runtime failures in hand-edited or model code: re-emit from the schema."""
    return with_changes(schema, repairs=add_repair(schema, "REGENERATE_CODE", failure.get("message", "")[:200]))


def restack_layout(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Unstable goal: rebuild the goal poses of every stack from its support chain
    (each cube centred on the one below, touching), and reset every cube upright."""
    goal = schema.goal_predicate()
    layout = {n: p.model_dump() for n, p in schema.goal_layout.items()}
    changed = False
    for p in goal.walk():
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
    return with_changes(schema, goal_layout=layout, repairs=add_repair(schema, "RESTACK_SUPPORT_CHAIN", failure.get("message", "")[:200]))


def reorder_support_chain(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """Cyclic or ungrounded support: drop the support predicates that close a cycle."""
    goal = schema.goal_predicate()
    children = goal.conjuncts()
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
    return with_changes(schema, goal=new_goal,
                 repairs=add_repair(schema, "REORDER_SUPPORT_CHAIN", f"removed conflicting relation(s): {'; '.join(dropped)}"))


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
    return with_changes(schema, goal=new, repairs=add_repair(schema, "SWITCH_READABLE_FACE", failure.get("message", "")[:200]))


def widen_separation(schema: TaskSchema, failure: dict) -> TaskSchema | None:
    """G already true at reset: spread rho_0 (larger minimum separation) so the start differs from the goal."""
    init = schema.initial_state
    if init.min_separation >= 0.12:
        return None
    new = init.model_copy(update={"min_separation": round(init.min_separation + 0.02, 3)})
    return with_changes(schema, initial_state=new.model_dump(),
                 repairs=add_repair(schema, "WIDEN_INITIAL_SEPARATION", failure.get("message", "")[:200]))


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
