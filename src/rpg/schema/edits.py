"""Edits of a TaskSchema shared by the feasibility pass and the repair pass.

A schema is immutable in practice: every edit returns a new, re-validated
:class:`~rpg.schema.model.TaskSchema` and records why in ``repairs``.
"""

from __future__ import annotations

import re

import numpy as np

from rpg.domain import constants as C
from rpg.errors import BadInput
from rpg.schema.model import PoseSpec, RepairRecord, TaskSchema


def with_changes(schema: TaskSchema, **changes) -> TaskSchema:
    """A copy of ``schema`` with top-level fields replaced, validated again.

    Raises:
        pydantic.ValidationError: the changed schema is inconsistent.
    """
    doc = schema.model_dump()
    doc.update(changes)
    return TaskSchema.model_validate(doc)


def add_repair(schema: TaskSchema, operator: str, reason: str, stage: str = "validation") -> list[dict]:
    """``schema.repairs`` plus one record, as plain data for :func:`with_changes`."""
    return ([r.model_dump() for r in schema.repairs]
            + [RepairRecord(operator=operator, stage=stage, reason=reason).model_dump()])


def layout_extent(schema: TaskSchema) -> tuple[np.ndarray, np.ndarray]:
    """Min and max corners (x, y) of the goal layout's footprints, m, world frame."""
    pts = []
    for a in schema.assets:
        p = np.asarray(schema.goal_layout[a.name].position[:2])
        half = np.array([a.size / 2, a.size / 2]) if a.kind != "goal_patch" else np.array(a.build().extents[:2]) / 2
        pts += [p - half, p + half]
    pts = np.array(pts)
    return pts.min(axis=0), pts.max(axis=0)


def move_into_workspace(schema: TaskSchema, failure: dict | None = None, stage: str = "validation") -> TaskSchema | None:
    """Translate the whole goal layout (and the fixed goal patches) so its footprint lies
    inside the workspace (:data:`rpg.domain.constants.WORKSPACE_X` / ``WORKSPACE_Y``).

    Returns:
        The moved schema with a MOVE_INTO_WORKSPACE record, or None when the layout already
        fits or is wider than the workspace (nothing to translate into).
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
    return with_changes(schema, goal_layout={n: v.model_dump() for n, v in layout.items()},
                        initial_state=init.model_dump(),
                        repairs=add_repair(schema, "MOVE_INTO_WORKSPACE",
                                           f"shifted the goal layout by {np.round(shift, 3).tolist()} m", stage))


def renamed_doc(schema: TaskSchema, mapping: dict[str, str], color: str) -> dict:
    """``schema`` as a dict whose assets named in ``mapping`` take their new names and ``color``, renamed consistently
    in the goal, the goal layout and rho_0 (structures, fixed poses, orientations); the texts are left to the caller."""
    doc = schema.model_dump()
    for a in doc["assets"]:
        if a["name"] in mapping:
            a["color"], a["name"] = color, mapping[a["name"]]
    doc["goal"] = schema.goal.rename(mapping)
    doc["goal_layout"] = {mapping.get(k, k): v for k, v in doc["goal_layout"].items()}
    init = doc["initial_state"]
    init["structures"] = [[mapping.get(n, n) for n in st] for st in init["structures"]]
    init["fixed"] = {mapping.get(k, k): v for k, v in init["fixed"].items()}
    init["orientations"] = {mapping.get(k, k): v for k, v in init["orientations"].items()}
    return doc


def recolor(schema: TaskSchema, old: str, new: str, merge: bool = False) -> TaskSchema:
    """A colour tweak applied to any task (relations, patches, temporal order): every asset
    of colour ``old`` becomes ``new``, renamed consistently in the goal, layout and rho_0.
    ``merge``: the task may already have objects of colour ``new`` (they become one colour).

    Raises:
        BadInput: the task has nothing of colour ``old``, or (not ``merge``) already uses ``new``.
    """
    names = {a.name for a in schema.assets}
    hits = [a for a in schema.assets if a.color == old]
    if not hits:
        raise BadInput(f"the task has no {old} object; its colours are "
                         f"{', '.join(sorted({a.color for a in schema.assets if a.color}))}")
    if any(a.color == new for a in schema.assets) and not merge:
        raise BadInput(f"the task already has a {new} object; name the object to change more precisely")
    mapping: dict[str, str] = {}
    for a in hits:
        renamed = re.sub(rf"^{re.escape(old)}(?=_|$)", new, a.name)
        mapping[a.name] = renamed if renamed not in names and renamed not in mapping.values() else f"{new}_{a.name}"
    doc = renamed_doc(schema, mapping, new)
    word = re.compile(rf"\b{re.escape(old)}\b")
    for key in ("instruction", "goal_summary"):
        doc[key] = word.sub(new, doc[key])
    doc["paraphrases"] = [word.sub(new, x) for x in doc["paraphrases"]]
    doc["name"] = word.sub(new, doc["name"])
    return TaskSchema.model_validate(doc)
