"""Readers of places: a cube moved to a region, an unstacked stack, a structure beside a cube."""

from __future__ import annotations

import re

import numpy as np

from rpg.domain import constants as C
from rpg.domain.layouts import (
    stack_layout,
)
from rpg.domain.predicates import (
    And,
    Behind,
    InFrontOf,
    InRegion,
    LeftOf,
    NextTo,
    OnTable,
    RightOf,
    Stack,
)
from rpg.domain.state import Pose
from rpg.errors import BadInput
from rpg.schema import readers
from rpg.schema.builder import DEFAULT_COLORS, Builder
from rpg.schema.edits import recolor
from rpg.schema.lexicon import COLOR_RE
from rpg.schema.readers.common import region_table_pose
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, ParseError, canon_color, color_mentions, region_name
from rpg.schema.structures import STRUCTURE_RE

MOVE_TO_REGION_RE = re.compile(
    rf"(?:go\s+)?(?:place|put|move|push|slide|sweep|shift|bring|set|drop)\s+(?:(?P<p>left|right)\s+)?the\s+(?P<c>{COLOR_RE})\s+"
    r"(?:block|cube|box)(?:\s+(?:to|into|onto|on|in|at)\s+the\s+(?:far\s+|very\s+)?(?:(?P<fb>front|back|rear)\s+)?(?P<d>left|right|center|centre|middle|front|back)"
    r"(?:\s+(?:hand\s+)?(?:side|half|part|edge|end|area|region|zone|corner))?(?:\s+of\s+the\s+(?:table|workspace))?)?\s*[.!]?")


@reader(order=10)
def recognize_move_to_region(f: Features, b: Builder) -> bool:
    """One cube moved to a place on the table, said without a second object: "push the red
    block to the left", "slide right the blue block", "move the green block to the center",
    "place the green block in the middle".
    The goal is the cube in that region (:data:`constants.REGION_NAMES`); rho_0 starts it
    outside (the emitter derives that from G)."""
    m = MOVE_TO_REGION_RE.fullmatch(f.text)
    if not m or bool(m.group("p")) == bool(m.group("d")):
        return False
    word = m.group("p") or m.group("d")
    fb = m.group("fb") or (word if word in ("front", "back") else None)
    region = region_name(fb, None if word in ("front", "back") else word)
    color = canon_color(m.group("c"))
    name = b.cube(color)
    b.place({name: region_table_pose(region)})
    b.preds.append(InRegion(name, region))
    b.primitives += ["push" if re.match(r"(?:go\s+)?(?:push|slide|sweep)", f.text) else "place"]
    b.summary.append(b.preds[-1].describe())
    return True


EACH_CORNER_RE = re.compile(
    rf"(?:place|put|set|move|position)\s+(?:(?P<one>a|an|1)\s+(?:(?P<c>{COLOR_RE})\s+)?(?:block|cube|box)"
    rf"|(?P<n>4)\s+(?:(?P<c4>{COLOR_RE})\s+)?(?:blocks|cubes|boxes),?\s+(?:1|one))"
    r"\s+(?:in|at|on|into)\s+(?:each|every)\s+(?:1\s+)?(?:of\s+the\s+(?:4\s+)?)?corners?(?:\s+of\s+the\s+(?:table|workspace))?\s*[.!]?")
"""One cube in each corner of the table: "put a red block in each corner", "place 4 cubes, one
in each corner", "put a cube in each of the four corners" (no colour said: four cubes of one colour)."""


@reader(order=11)
def recognize_cube_in_each_corner(f: Features, b: Builder) -> bool:
    """A cube in each of the table's four corners (:data:`rpg.domain.constants.REGION_GROUPS`
    ``corner``).  The cubes are of the colour said, or of one colour when none is said: cubes
    of one colour are interchangeable, so G accepts any cube in any corner, as the words do."""
    m = EACH_CORNER_RE.fullmatch(f.text)
    if not m:
        return False
    color = canon_color(m.group("c") or m.group("c4") or DEFAULT_COLORS[0])
    for region in C.REGION_GROUPS["corner"]:
        name = b.cube(color)
        b.place({name: region_table_pose(region)})
        b.preds.append(InRegion(name, region))
        b.summary.append(b.preds[-1].describe())
    b.primitives += ["place"]
    return True


STRUCTURE_BY_CUBE_RE = re.compile(
    rf"(?P<head>.+?)\s+(?P<rel>(?:to\s+the\s+)?left\s+of|(?:to\s+the\s+)?right\s+of|in\s+front\s+of|behind|next\s+to|beside)"
    rf"\s+the\s+(?P<c>{COLOR_RE})\s+(?:block|cube)(?:\s+on\s+the\s+table)?\s*[.!]?")
"""A structure placed relative to one named cube: "build a tower of 3 green blocks to the left of the red block"."""


_SIDE = {"left": (LeftOf, 1, -1.0), "right": (RightOf, 1, 1.0), "front": (InFrontOf, 0, 1.0), "behind": (Behind, 0, -1.0)}
"""Relation word -> (predicate, axis, side of the structure the reference cube goes to: +1 larger coordinate)."""


@reader(order=190)
def recognize_structure_by_cube(f: Features, b: Builder) -> bool:
    """A structure stated on its own, then placed relative to a cube the structure does not
    contain ("a tower of three green blocks to the left of the red block", "put 3 blue
    blocks in a line behind the yellow block").  The structure is read by the whole parser
    (its own clause); every cube of it must stand in the relation to the reference cube
    (next to: a tower's base beside it).  Clauses compose: nothing of either part is
    dropped or merged."""
    m = STRUCTURE_BY_CUBE_RE.fullmatch(f.text)
    if m is None or not re.search(STRUCTURE_RE, m.group("head")) or re.search(
            r"\b(?:left|right|front|behind|back|next|beside|between|near|around|@region_[a-z_]+)\b", m.group("head")):
        return False
    try:
        head = readers.parse(m.group("head"))  # the clause read by the whole front end
    except BadInput:
        return False
    ref_color = canon_color(m.group("c"))
    if any(a.kind == "goal_patch" for a in head.assets) or ref_color in {c for _, c in color_mentions(m.group("head"))}:
        return False  # the reference would be one of the structure's own cubes
    if any(a.color == ref_color for a in head.assets):  # an open colour the parser chose: give it a spare one
        used = {a.color for a in head.assets}
        head = recolor(head, ref_color, next(c for c in DEFAULT_COLORS if c not in used))
    cubes = [a for a in head.assets if a.kind != "goal_patch"]
    xy = np.array([head.goal_layout[a.name].position[:2] for a in cubes])
    rel = m.group("rel")
    word = next((w for w in ("left", "right", "front", "behind") if w in rel), "next")
    gap = C.CUBE_EDGE + 0.03
    if word == "next":
        if np.ptp(xy, axis=0).max() > 1e-6:
            return False  # "a line next to the red block": which of its cubes is not said
        ref_xy = (xy[0][0], xy[0][1] - gap)
        base = min(cubes, key=lambda a: head.goal_layout[a.name].position[2]).name
        rels = [NextTo(base, "@ref")]
        # next_to names one cube of the stack (its base), so the stack's order is the one read
        # ("stack the red and blue blocks next to the green block": red at the base); its summary
        # must not say "in any order" (a next_to of any cube of a stack is not in the domain yet)
        parts = [Stack(p.objects) if isinstance(p, Stack) else p for p in head.goal.conjuncts()]
        if parts != head.goal.conjuncts():
            head = head.model_copy(update={"goal": And(parts) if len(parts) > 1 else parts[0],
                                           "goal_summary": "; ".join(p.describe() for p in parts)})
    else:
        cls, axis, side = _SIDE[word]
        ref_xy = xy.mean(axis=0)
        ref_xy[axis] = (xy[:, axis].max() + gap) if side > 0 else (xy[:, axis].min() - gap)
        if np.abs(xy[:, 1 - axis] - ref_xy[1 - axis]).max() > C.RELATION_MAX_OFF_AXIS - 0.02:
            return False  # a structure too wide to stand wholly on one side of one cube
        rels = [cls(a.name, "@ref") for a in cubes]
    b.adopt(head)
    ref = b.cube(ref_color)
    b.place({ref: Pose((float(ref_xy[0]), float(ref_xy[1]), C.TABLE_TOP_Z + C.CUBE_EDGE / 2))})
    b.preds.extend(r.rename({"@ref": ref}) for r in rels)
    b.primitives.append("place")
    b.summary = [head.goal_summary, f"{rels[0].a} {rel.removeprefix('to the ')} {ref}" if word == "next"
                 else f"every cube of it {rel.removeprefix('to the ')} {ref}"]
    return True


UNSTACK_RE = re.compile(
    rf"(?:unstack|take|remove)\s+the\s+(?P<top>{COLOR_RE})\s+(?:block|cube|box)\s+"
    rf"(?:off|from)\s+(?:of\s+)?(?:on\s+)?(?:the\s+)?(?:top\s+of\s+)?the\s+(?P<bottom>{COLOR_RE})\s+(?:block|cube|box)"
    r"(?:\s*,?\s*(?:and\s+)?(?:then\s+)?(?:put|place|set|lay)\s+it\s+(?:down\s+)?on\s+the\s+table)?\s*[.!]?"
    rf"|(?:initially\s*,?\s*|at\s+the\s+start\s*,?\s*)?the\s+(?P<top2>{COLOR_RE})\s+(?:block|cube|box)\s+"
    r"(?:is|starts|begins)\s+(?:currently\s+|initially\s+|out\s+)?(?:on|upon|atop)\s+(?:top\s+of\s+)?"
    rf"the\s+(?P<bottom2>{COLOR_RE})\s+(?:block|cube|box)\s*[.;,]\s*(?:and\s+)?(?:then\s+)?(?:move|put|place|set|take|bring|lower)\s+"
    r"(?:it|the\s+(?P=top2)\s+(?:block|cube|box))\s+(?:down\s+)?(?:off\s+(?:of\s+)?(?:it|the\s+(?P=bottom2)\s+(?:block|cube|box))"
    r"\s*,?\s*(?:and\s+)?(?:put\s+it\s+|place\s+it\s+)?)?(?:on|onto|to)\s+the\s+table\s*[.!]?")
"""One cube taken off another: "unstack the blue block from on top of the red block", "take
the blue block off the red block (and put it on the table)", "the blue cube is on the red cube.
Move it onto the table." (a start stated, then the move).  Not "pick up" or "lift": those
end with the cube in the hand, which no task ends with."""


@reader(order=20)
def recognize_unstack(f: Features, b: Builder) -> bool:
    """A cube taken off the cube it starts stacked on: rho_0 starts the stack (bottom, top),
    G is the top cube on the table (so no longer on the other)."""
    m = UNSTACK_RE.fullmatch(f.text)
    if not m:
        return False
    bottom = canon_color(m.group("bottom") or m.group("bottom2"))
    top = canon_color(m.group("top") or m.group("top2"))
    low, high = b.cube(bottom), b.cube(top)
    (x0, y0), (x1, y1) = b.unit_centers(2, 0.12)
    b.place(stack_layout([low], (x0, y0)) | stack_layout([high], (x1, y1)))
    b.structures.append([low, high])
    b.preds.append(OnTable(high))
    b.primitives += ["place"]
    b.summary += [f"initially {high} is stacked on {low}", f"{high} on the table"]
    return True


REVERSE_TOWER_RE = re.compile(
    r"(?:reverse|invert|flip|turn)\s+(?:the\s+)?(?:order\s+of\s+(?:the\s+)?)?(?:blocks?\s+in\s+the\s+)?(?P<noun>tower|stack)"
    r"(?:\s+of\s+(?P<n>\d+)\s+(?:blocks|cubes))?(?:\s+(?:upside\s+down|over|around))?"
    r"(?:\s*,?\s*(?:so\s+that\s+)?(?:the\s+)?(?:top|bottom)\s+(?:block|cube|one)\s+(?:ends\s+up|is|goes)\s+"
    r"(?:at\s+the\s+|on\s+)?(?:bottom|top))?\s*[.!]?")
"""A tower turned upside down as a whole: "reverse the tower", "invert the stack of 3 blocks",
"flip the tower over"."""


@reader(order=22)
def recognize_reverse_tower(f: Features, b: Builder) -> bool:
    """A tower rho_0 starts, rebuilt in the reverse order ("reverse the tower", "invert the
    stack of 4 blocks").  Its cubes are told apart by where they start, so G is the stack of
    the same cubes top to bottom; how many: the count said, else three
    (:data:`rpg.schema.builder.DEFAULT_COLORS` gives their colours, none of which the words
    name)."""
    if re.match(r"(?:reverse|flip|turn)\s+the\s+(?:[a-z0-9]+\s+){0,4}?(?:tower|stack)\b", f.text) and color_mentions(f.text):
        raise ParseError(f"\"{f.original[:80]}\" turns over a tower it does not describe: say the order it starts in "
                         "(\"starting from a stack of red on blue, ...\") and where each cube ends, or use --model")
    m = REVERSE_TOWER_RE.fullmatch(f.text)
    if not m or color_mentions(f.text):
        return False
    n = int(m.group("n") or 3)
    if n < 2:
        return False
    names = [b.cube(c) for c in DEFAULT_COLORS[:n]]
    spot = b.unit_centers(2, 0.14)[1]  # the goal tower beside where rho_0's may stand
    b.place(stack_layout(names[::-1], spot))
    b.structures.append(names)
    b.preds.append(Stack(tuple(names[::-1])))
    b.primitives += ["stack"]
    b.summary += [f"initially a tower bottom to top: {', '.join(names)}",
                  f"the same tower reversed, bottom to top: {', '.join(names[::-1])}"]
    return True
