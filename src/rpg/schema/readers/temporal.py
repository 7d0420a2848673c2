"""Reader of temporal order: "first put X on Y, then Z on W" (an :class:`InOrder` goal)."""

from __future__ import annotations

from rpg.domain.layouts import (
    stack_layout,
)
from rpg.domain.predicates import (
    InOrder,
    OnPatch,
)
from rpg.schema.builder import Builder
from rpg.schema.readers.common import colors_for
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, features_colors


@reader(order=40)
def recognize_temporal(f: Features, b: Builder) -> bool:
    if not (f.has("first") and f.has("then")) and not f.has("temporal", "sequentially"):
        return False
    if not f.has("patch", "patches", "target", "targets"):
        return False
    order_part = f.text[f.text.find("first") - 20 if "first" in f.text else 0:]
    order = list(dict.fromkeys(c for _, c in features_colors(order_part)))
    if len(order) < 2:
        order = colors_for(2, f)
    centers = b.unit_centers(len(order), 0.14)
    events = []
    for color, (x, y) in zip(order, centers, strict=True):
        cube = b.cube(color)
        patch = b.patch(color)
        b.place_patch(patch, (x, y))
        b.place(stack_layout([cube], (x, y)))
        events.append(OnPatch(cube, patch))
    b.preds.append(InOrder(tuple(events)))
    b.primitives += ["place"]
    b.summary.append("first " + ", then ".join(f"the {c} cube on the {c} patch" for c in order))
    b.min_separation = 0.10
    return True
