"""Readers that compose: an instruction made of parts, each a task of its own read by the whole
front end, laid out together (structures each in its own place; towers listed after a count).

Each part is read by :func:`rpg.schema.readers.parse` (its own clause), so nothing a part says
is dropped or merged; the parts' cubes are renamed apart, and a colour a part leaves open is
given one no other part uses.
"""

from __future__ import annotations

import re

import numpy as np

from rpg.domain import constants as C
from rpg.domain.predicates import (
    AnchoredStack,
    CentredIn,
    InRegion,
    OnPatch,
    Stack,
    StackOnPatch,
    UnorderedStack,
    describe_region,
    region_boxes,
)
from rpg.domain.state import Pose
from rpg.errors import BadInput
from rpg.schema import readers
from rpg.schema.builder import DEFAULT_COLORS, Builder
from rpg.schema.lexicon import COLOR_RE, PAIRWISE_RELATIONS, STRUCTURE_NOUN
from rpg.schema.model import TaskSchema
from rpg.schema.readers.common import REGION_MARGIN, region_spots
from rpg.schema.readers.registry import reader
from rpg.schema.reading import (
    NEW_STRUCTURE_BEFORE_RE,
    Features,
    ParseError,
    canon_color,
    color_mentions,
    mark_regions,
)
from rpg.schema.structures import STRUCTURE_RE

STACK_KINDS = (Stack, UnorderedStack, AnchoredStack)
"""The goal predicates of a part that stands wholly over one spot."""

ANOTHER_RE = re.compile(r"(?:(?:put|place|build|make|stack|set)\s+)?(?:another(?:\s+one)?|a\s+second(?:\s+one)?|1\s+more)")
"""A part that repeats the structure said before it ("... in the front left corner and another
in the front right corner")."""

_JOINER_RE = re.compile(r"^(?:[,.;]\s*)?(?:and\s+)?(?:then\s+)?|\s*(?:[,.;]\s*)?(?:and\s*)?$")
_TRAILING_PREP_RE = re.compile(r"\s+(?:in|at|on)(?:\s+each\s+of)?(?:\s+both)?(?:\s+the)?$")


def _read_parts(texts: list[str]) -> list[TaskSchema] | None:
    """Each text read by the whole front end; None when one cannot be read."""
    try:
        return [readers.parse(t) for t in texts]
    except BadInput:
        return None


def _single_spot(head: TaskSchema) -> bool:
    """Whether a part is cubes over one spot (a stack, one cube) with no place, patch or
    starting structure of its own."""
    cubes = [a for a in head.assets if a.kind != "goal_patch"]
    xy = np.array([head.goal_layout[a.name].position[:2] for a in cubes])
    return (len(cubes) == len(head.assets) and np.ptp(xy, axis=0).max() < 1e-6 and not head.initial_state.structures
            and not any(isinstance(p, InRegion) for p in head.goal_predicate().walk()))


def _open_color(color: str, own: set[str], clash: set[str], taken: set[str], memo: dict[str, str | None]) -> str | None:
    """The colour a part's cube gets beside other parts: its own when the part said it or no
    other part holds it (``clash``), else the first default colour not ``taken`` (the same for
    every cube of that open colour: ``memo``); None when every default colour is taken."""
    if color in own or color not in clash:
        return color
    if color not in memo:
        memo[color] = next((c for c in DEFAULT_COLORS if c not in taken | {m for m in memo.values() if m}), None)
    return memo[color]


def _merge(f: Features, b: Builder, texts: list[str], heads: list[TaskSchema],
           spots: list[tuple[float, float]], regions: list[str | None]) -> None:
    """Add each part's cubes and goal to ``b``: renamed apart, a colour the part left open and
    another part uses replaced by an unused one, its cubes over ``spots[i]`` and its base in
    ``regions[i]`` (when given)."""
    named = {c for _, c in color_mentions(f.text)}
    used: set[str] = set()
    for text, head, spot, region in zip(texts, heads, spots, regions, strict=True):
        cubes = [a for a in head.assets if a.kind != "goal_patch"]
        own = {c for _, c in color_mentions(text)}
        mapping: dict[str, str] = {}
        recolored: dict[str, str | None] = {}
        for a in cubes:
            if a.kind == "colored_cube":
                color = _open_color(a.color, own, used, used | named | {c.color for c in cubes}, recolored)
                if color is None:
                    raise ParseError(f"\"{f.original[:80]}\" leaves more cubes' colours open than there are colours "
                                     "to tell them apart; name the colours, or use --model")
                mapping[a.name] = b.cube(color)
            else:
                mapping[a.name] = b.semantic(a.label, dict(a.faces))
        used |= {a.color for a in b.assets if a.color}
        base = min(cubes, key=lambda a: head.goal_layout[a.name].position[2]).name
        b.place({mapping[a.name]: Pose((*spot, head.goal_layout[a.name].position[2])) for a in cubes})
        b.orientations.update({mapping[n]: q for n, q in head.initial_state.orientations.items()})
        goal = [p.rename(mapping) for p in head.goal_predicate().conjuncts()]
        goal += [InRegion(mapping[base], region)] if region else []
        b.preds += goal
        b.summary += [p.describe() for p in goal]
        b.primitives += list(head.primitives)
        if head.reasoning != "spatial":
            b.reasoning = head.reasoning


def _placed_parts(text: str, each: bool) -> list[tuple[str, str]] | None:
    """(part, region) pairs of marked ``text`` made of parts that each take one ``@region_``
    token, all before or all after their part ("X @A and Y @B", "@A X. @B Y"), a part
    saying "another" standing for the part before it, and so does one left empty where the
    count says so ("2 stacks of 2 blocks @A and @B") or ``each`` ("a stack in each of @A and
    @B"); None when ``text`` is not of that form."""
    pieces = re.split(r"\s*@region_([a-z_]+)\s*", text)
    regions, texts = pieces[1::2], [_JOINER_RE.sub("", t).strip() for t in pieces[0::2]]
    if len(regions) < 2:
        return None
    if not texts[0]:
        heads = texts[1:]  # each place before its part
    elif not texts[-1]:
        heads = texts[:-1]  # each place after its part
    else:
        return None
    plural = re.match(rf"^(.*?)\b{len(regions)}\s+((?:[a-z\-]+\s+)?(?:tower|stack|column|pile|pillar))s\b(.*)$", heads[0])
    if plural and not any(heads[1:]):  # "2 stacks of 2 blocks in the front left and front right corners"
        return [(f"{plural.group(1)}a {plural.group(2)}{plural.group(3)}".strip(), r) for r in regions]
    parts: list[tuple[str, str]] = []
    for head, region in zip(heads, regions, strict=True):
        if not head or ANOTHER_RE.fullmatch(head):
            if not parts or not (head or each):
                return None
            head = parts[-1][0]
        parts.append((_TRAILING_PREP_RE.sub("", head), region))
    return parts


@reader(order=185)
def recognize_structures_in_places(f: Features, b: Builder) -> bool:
    """Structures each put in its own place on the table: "build a stack of two blocks in the
    front left corner and another in the front right corner", "put two stacks of two blocks in
    the front left and front right corners", "in the NW corner stack the red block on the
    blue one; in the SE corner stack the green block on the yellow one".  Each part stands
    wholly over one spot (a stack or one cube: how a wider structure's footprint sits in a
    place is not said) and its base goes in its region."""
    parts = _placed_parts(mark_regions(f.text), each=bool(re.search(r"\b(?:each|both)\b", f.text)))
    heads = _read_parts([t for t, _ in parts]) if parts else None
    if heads is None or not all(_single_spot(h) for h in heads):
        return False
    regions = [r for _, r in parts]
    _merge(f, b, [t for t, _ in parts], heads, [region_spots(r, 1)[0] for r in regions], regions)
    return True


def _fitted(head: TaskSchema, region: str, whole: bool = True) -> dict[str, tuple[float, float, float]] | None:
    """The part's goal poses moved (and, when no predicate of it fixes an axis, turned a
    quarter) so that every cube's centre lies in ``region`` with :data:`REGION_MARGIN` to
    spare (``whole``), or only so that the structure's middle is the region's centre and every
    cube stands in the workspace (not ``whole``); None when it cannot fit."""
    cubes = [a.name for a in head.assets if a.kind != "goal_patch"]
    xyz = np.array([head.goal_layout[n].position for n in cubes], float)
    (x0, x1), (y0, y1) = region_boxes(region)[0]
    centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    if not whole:
        (x0, x1), (y0, y1) = C.WORKSPACE_X, C.WORKSPACE_Y
    free = all(getattr(p, "axis", None) is None and p.name not in PAIRWISE_RELATIONS for p in head.goal_predicate().walk())
    for turn in ((False, True) if free else (False,)):
        xy = xyz[:, :2] - xyz[:, :2].mean(axis=0)
        if turn:
            xy = xy[:, ::-1] * np.array([1.0, -1.0])
        xy = xy + centre
        if (xy[:, 0].min() >= x0 + REGION_MARGIN and xy[:, 0].max() <= x1 - REGION_MARGIN
                and xy[:, 1].min() >= y0 + REGION_MARGIN and xy[:, 1].max() <= y1 - REGION_MARGIN):
            return {n: (float(x), float(y), float(z)) for n, (x, y), z in zip(cubes, xy, xyz[:, 2], strict=True)}
    return None


_WHOLE_NOUN = rf"(?:{STRUCTURE_RE}|\b{STRUCTURE_NOUN}s?\b)"
IN_REGION_PART_RE = re.compile(
    r"^(?P<head>[^@]+?),?\s+@region_(?P<r>[a-z_]+)[\s,.!]*$"
    r"|^@region_(?P<r2>[a-z_]+)\s*,?\s+(?P<head2>[^@]+?)[\s.!]*$"
    r"|^(?P<head3>[^@]+?),?\s+@region_(?P<r3>[a-z_]+)\s*,?\s+(?P<with>(?:with|using|made\s+(?:of|from)|out\s+of)\s+[^@]+?)[\s.!]*$"
    rf"|^(?P<head4>[^@]*?{_WHOLE_NOUN}[^@,:;.]*?)\s+@region_(?P<r4>[a-z_]+)\s*(?P<rest4>[,:;][^@]+?)[\s.!]*$"
    rf"|^(?P<head5>[^@]+?)[\s,.;]+(?:and\s+)?(?:then\s+)?(?:put|place|move|set)\s+(?:it|that|this"
    rf"|(?:the|that|this)\s+(?:whole\s+)?(?:thing|structure|{_WHOLE_NOUN}))\s+"
    r"(?:@region_(?P<r5>[a-z_]+)|on\s+the\s+(?P<r5side>left|right))[\s.!]*$")
"""A part, then the one place it stands in ("three blocks in a line at @region_back"), the
place first ("in @region_left, build a pyramid of 3 blocks"), the place before the part's
"with" or "using" ("stack the red, green and blue blocks @region_center with the blue block on top",
"build a pyramid @region_back_left using 3 green cubes"),
the place said just after the structure's noun ("a tower of 4 blocks @region_center: yellow
at the bottom, ..."), or the structure put there afterwards ("stack pink on white, and put
that tower on the left")."""


def _region_part(m: re.Match) -> tuple[str, str]:
    """(the part's words, the region's name) of an :data:`IN_REGION_PART_RE` match."""
    if m.group("head3"):
        return f"{m.group('head3')} {m.group('with')}", m.group("r3")
    if m.group("head4"):
        return f"{m.group('head4')}{m.group('rest4')}", m.group("r4")
    if m.group("head5"):
        return m.group("head5"), m.group("r5") or m.group("r5side")
    return m.group("head") or m.group("head2"), m.group("r") or m.group("r2")


def _place_of_last_clause(text: str) -> bool:
    """Whether ``text``'s last clause (after a sentence break or "and put/make/..."), where a place is said, names cubes of
    its own, none of them an earlier clause's, and nothing that refers to all of them ("all", "both", "it", "whole"): the
    place is then that clause's structure's alone."""
    clauses = re.split(r"[.;!?]\s+|,?\s\band\s+(?:then\s+)?(?=(?:put|place|make|build|stack|line|arrange|set|lay|form|create)\b)",
                       text.strip())
    if len(clauses) < 2:
        return False
    last, earlier = clauses[-1], " ".join(clauses[:-1])
    own = set(re.findall(rf"\b(?:{COLOR_RE})\b", last))
    before = set(re.findall(rf"\b(?:{COLOR_RE})\b", earlier))
    return bool(own and before and not own & before) and not re.search(
        r"\b(?:all|both|everything|whole|them|it|its|together|each)\b", last)


@reader(order=187)
def recognize_structure_in_region(f: Features, b: Builder) -> bool:
    """A structure wider than one spot (a line, a pyramid, a grid, a circle) standing in one
    place on the table: "put 3 red blocks in a row along the back edge", "a pyramid of 6
    blocks in the back left corner".  The structure is read by the whole front end (its own
    clause, which must name no place, patch or starting structure of its own) and every one
    of its cubes must stand in the place: the place is said of the whole structure.  Its goal
    layout is moved into the region (turned a quarter when its words fix no axis).

    Raises:
        ParseError: the structure does not fit in the region.
    """
    m = IN_REGION_PART_RE.match(mark_regions(f.text))
    part, region = _region_part(m) if m else (None, None)
    caps = set(re.findall(r"\b[A-Z]{2,}\b", f.original))
    if part and caps:  # "spell HAT ... at the back of the table": the word in its capitals again (it had read as 'hat')
        part = re.sub(r"\b[a-z]{2,}\b", lambda w: w.group(0).upper() if w.group(0).upper() in caps else w.group(0), part)
    if part:  # "stack the letter cubes A, B and C ... at the front": the labels in their capitals again (they had read as
        # an article and two words, and the place had been refused)
        part = re.sub(r"\b(letters?(?:\s+(?:cubes|blocks))?|letter\s+)\s*([a-z](?:(?:\s*,\s*(?:and\s+)?|\s+and\s+)[a-z])*)\b(?!')",
                      lambda m: f"{m.group(1).rstrip()} " + re.sub(r"\b[a-z]\b", lambda w: w.group(0).upper(), m.group(2)), part)
    if part and re.search(r"(?:[.;!]|,?\s+then|,?\s*\band)\s+(?:then\s+)?(?:put|place|move|set|add|bring)\s+(?:a|an|one|another|the)\s+"
                          r"(?:[a-z]+\s+)?(?:cube|block)\b(?!\s+(?:on|onto|atop|over|above)\b)"
                          # "..., then put green in the back left corner", "..., then the green one": a bare colour too (the
                          # tower had taken green and gone to the corner whole, silently)
                          rf"|(?:[.;!]|,?\s+then|,?\s*\band)\s+(?:then\s+)?(?:put|place|move|set|add|bring)\s+(?:the\s+)?(?:{COLOR_RE})"
                          r"(?:\s+one)?\s*$"
                          rf"|,?\s+then\s+(?:the\s+|a\s+)?(?:{COLOR_RE})\s+(?:cube|block|one)\s*$", part) or (
            part and len(re.findall(r"\bthen\b", part)) == 1 and re.search(rf",?\s+then\s+(?:the\s+)?(?:{COLOR_RE})\s*$", part)
            and re.search(rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:on|onto|atop|upon)\s+(?:the\s+)?(?:{COLOR_RE})\b", part)):
        return False  # "a tower of ... then put a brown cube in the back left corner": the place is the last cube's (it had
        # joined the tower; "stack four blue cubes into one tower and put a white cube in the front left corner" too)
    if part and _place_of_last_clause(f.text):
        return False  # "Put the red cube on the blue cube. Put the green and yellow cubes in a row on the left.": the place is
        # the last clause's (both had gone to the left, silently)
    heads = _read_parts([part]) if m else None
    if heads is None:
        return False
    head = heads[0]
    said_last = re.search(rf"(?P<w>\S+)\s*,\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:block|cube|one))?\s*$", part)
    if re.search(rf"\bwith\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:block|cube|one))?\s*$", part) or (
            said_last and region == "center" and not re.fullmatch(rf"(?:{COLOR_RE})", said_last.group("w"))
            and re.search(r"\b(?:rows?|lines?|line\s+up)\b", part) and not re.search(r"\b(?:towers?|stacks?|stacked|columns?|piles?)\b", part)):
        return False  # "line up yellow and blue with blue on the left", "two blue and one orange in a row, orange in the
        # centre": the cube's place in the line, not the line's place ("line: red, red, red" at the front is the line's)
    if len(re.findall(rf"\b(?:a|an|one|1|another)\s+(?:[\w-]+\s+){{0,2}}?{_WHOLE_NOUN}", part)) > 1:
        return False  # "a tower of 3 red blocks and a line of 3 blue blocks on the right": the place of the last one only
    if (region not in C.REGION_NAMES or len(head.assets) < 2 or head.initial_state.structures
            or any(a.kind == "goal_patch" for a in head.assets)
            or any(isinstance(p, InRegion) or p.name in (*PAIRWISE_RELATIONS, "between") for p in head.goal_predicate().walk())):
        return False  # relations between cubes are no structure: "red left of blue, in the back" places red (the relational reader)
    poses = _fitted(head, region)
    centred = poses is None and region == "center"
    if centred:  # "a circle of four cubes in the middle of the table": wider than the centre third, so the structure
        # stands with its middle there (every cube in it could not; the words place the structure)
        poses = _fitted(head, region, whole=False)
    if poses is None:
        raise ParseError(f"the structure of \"{f.original[:80]}\" does not fit in {describe_region(region)}; "
                         "use fewer cubes, a larger place, or say the structure's direction")
    b.assets += [a.model_copy() for a in head.assets]
    b._names.update(a.name for a in head.assets)
    b.place({n: Pose(xyz) for n, xyz in poses.items()})
    b.orientations.update(head.initial_state.orientations)
    b.preds += head.goal_predicate().conjuncts() + ([CentredIn(tuple(poses), region)] if centred
                                                     else [InRegion(n, region) for n in poses])
    b.summary += [head.goal_summary, f"its middle in {describe_region(region)}" if centred
                  else f"all of it in {describe_region(region)}"]
    b.primitives += list(head.primitives)
    if head.reasoning != "spatial":
        b.reasoning = head.reasoning
    return True


ON_PATCH_PART_RE = re.compile(rf"^(?!.*\b(?:and|then)\s+(?:then\s+)?(?:put|place|set|move|slide|push|bring|lay)\b)(?P<head>[^@.;!?]+?)\s+"
                              rf"(?:on|onto|on\s+top\s+of|atop)\s+the\s+(?P<c>{COLOR_RE})\s+(?:goal\s+|target\s+)?patch[\s.!]*$")
"""A structure, then the goal patch it all stands on ("make a heap of the three red cubes on the
yellow patch", "line up two blue cubes on the red patch"), in one clause (not "Line up red and green. Put the yellow cube
on the blue patch.", whose patch is the yellow cube's: the row had been put on it)."""


@reader(order=188)
def recognize_structure_on_patch(f: Features, b: Builder) -> bool:
    """A structure of several cubes standing wholly on one goal patch: the structure is read by
    the whole front end (its own clause, which must name no place, patch, relation or starting
    structure of its own), its layout moved over the patch, and every one of its cubes must stand
    on the patch (a tower's base alone is another reader's: "build a tower ... on the yellow patch").

    Raises:
        ParseError: the structure's cubes do not fit on the patch.
    """
    m = ON_PATCH_PART_RE.match(f.text)
    heads = _read_parts([m.group("head")]) if m else None
    if heads is None:
        return False
    head = heads[0]
    cubes = [a.name for a in head.assets if a.kind != "goal_patch"]
    if (len(cubes) < 2 or len(cubes) != len(head.assets) or head.initial_state.structures
            or any(isinstance(p, (InRegion, *STACK_KINDS)) or p.name in (*PAIRWISE_RELATIONS, "between")
                   for p in head.goal_predicate().walk())):
        return False
    xyz = np.array([head.goal_layout[n].position for n in cubes], float)
    half = np.array(C.PATCH_SIZE) / 2 + C.PATCH_XY_MARGIN
    xy = xyz[:, :2] - xyz[:, :2].mean(axis=0)
    if np.any(np.abs(xy) > half):
        raise ParseError(f"the {len(cubes)} cubes of \"{f.original[:80]}\" do not fit on one goal patch "
                         f"({C.PATCH_SIZE[0] * 100:.0f} cm square); use fewer cubes, or use --model")
    patch = b.patch(canon_color(m.group("c")))
    b.assets += [a.model_copy() for a in head.assets]
    b._names.update(a.name for a in head.assets)
    b.place_patch(patch, (0.0, 0.0))
    b.place({n: Pose((float(x), float(y), float(z))) for n, (x, y), z in zip(cubes, xy, xyz[:, 2], strict=True)})
    b.orientations.update(head.initial_state.orientations)
    b.preds += head.goal_predicate().conjuncts() + [OnPatch(n, patch) for n in cubes]
    b.summary += [head.goal_summary, f"all of it on {patch}"]
    b.primitives += list(head.primitives)
    return True


TOWER_ONTO_PATCH_RE = re.compile(
    rf"^(?P<head>[^@]+?)\s*[.;,]\s*(?:and\s+)?(?:then\s+)?(?:put|place|move|set|stand)\s+(?:the\s+(?:whole\s+)?(?:tower|stack)|it)\s+"
    rf"(?:on|onto|on\s+top\s+of)\s+the\s+(?P<c>{COLOR_RE})\s+(?:goal\s+|target\s+)?patch[\s.!]*$")
"""A tower said, then put on a goal patch in a sentence of its own ("Build a tower: orange on the bottom, then green,
then purple on top. Put the tower on the white patch.")."""


@reader(order=189)
def recognize_tower_onto_patch(f: Features, b: Builder) -> bool:
    """One tower read by the whole front end (its own sentence, naming no place, patch or
    start), then put on a goal patch: its bottom cube rests on the patch (whichever cube that
    is when the tower's order is free).  The relational reader had read the tower's "then"
    steps as relations and dropped a cube."""
    m = TOWER_ONTO_PATCH_RE.match(f.text)
    heads = _read_parts([m.group("head")]) if m else None
    if heads is None:
        return False
    head = heads[0]
    goal = head.goal_predicate().conjuncts()
    towers = [p for p in goal if isinstance(p, STACK_KINDS)]
    if (len(towers) != 1 or not _single_spot(head) or set(towers[0].objects) != {a.name for a in head.assets}
            or any(not isinstance(p, STACK_KINDS) and p.name != "in_layers" for p in goal)):
        return False
    patch = b.patch(canon_color(m.group("c")))
    b.assets += [a.model_copy() for a in head.assets]
    b._names.update(a.name for a in head.assets)
    b.place_patch(patch, (0.0, 0.0))
    b.place({n: Pose((0.0, 0.0, float(head.goal_layout[n].position[2]))) for n in towers[0].objects})
    b.orientations.update(head.initial_state.orientations)
    base = towers[0].objects[0]  # whichever cube is at the bottom when the order is free
    b.preds += goal + [StackOnPatch(base, patch, tuple(sorted(towers[0].objects))) if isinstance(towers[0], UnorderedStack)
                       else OnPatch(base, patch)]
    b.summary += [head.goal_summary, f"its bottom cube on {patch}"]
    b.primitives += list(head.primitives)
    return True


LISTED_TOWERS_RE = re.compile(r"\b(?P<k>\d+)\s+(?P<noun>tower|stack|column|pile|pillar)s(?:\s+of\s+(?:blocks|cubes))?\s*(?P<sep>[:;,\-])\s*(?P<body>.+?)\s*[.!]?$")
"""Towers counted, then each said after a colon: "two stacks: white on black, and black on white"."""


@reader(order=95)
def recognize_listed_towers(f: Features, b: Builder) -> bool:
    """Towers counted, then each described in turn ("I want two stacks: white on black, and
    black on white"; "3 towers: red on blue, green on yellow and a stack of two white
    blocks").  Each description is read as a tower of its own, side by side; it must say a
    stack and no place."""
    m = LISTED_TOWERS_RE.search(f.text)
    if m is None or (m.group("sep") == "," and re.search(r"\b(?:high|tall|all|each|every|both)\b", m.group("body"))):
        return False  # "two towers, 3 blocks high, all green": what every tower is, not one tower after another
    k = int(m.group("k"))
    texts = [t.strip() for t in re.split(r"\s*[;,]\s*(?:and\s+)?|\s+and\s+(?=(?:then\s+)?(?:a|an|the|1|one)\b)", m.group("body"))]
    if len(texts) != k:
        texts = [t.strip() for t in re.split(r"\s*[;,]\s*(?:and\s+)?|\s+and\s+", m.group("body"))]
    texts = [re.sub(r"^(?:(?:1|the first|the second|the other|the last)\s+(?:of|with|is)\s+)", "", t) for t in texts]
    if len(texts) != k or not all(texts) or any(re.search(r"\b(?:it|its|them|that|this|those|these)\b", t) for t in texts):
        return False  # "yellow on orange, and white on top of it": a part that refers to another (its "it" had been made up)
    heads = _read_parts([t if re.search(STRUCTURE_RE, t) else f"a {m.group('noun')}: {t}" for t in texts])
    if heads is None or not all(_single_spot(h) and isinstance(h.goal_predicate(), STACK_KINDS) for h in heads):
        return False
    _merge(f, b, texts, heads, b.unit_centers(k, 0.16), [None] * k)
    return True


SORTED_HEADER_RE = re.compile(r"^(?P<head>[^:]*\b(?:sort|sorted|arrange|organize|group|put|place|move)\b[^:]*\bby\s+colou?rs?)"
                              r"\s*:\s*(?P<body>.+)$")
"""A sorting said, then spelled out after a colon: "sort the cubes onto the patches by colour:
red cubes on the red patch, blue cubes on the blue patch"."""


@reader(order=5)
def recognize_spelled_out_sort(f: Features, b: Builder) -> bool:
    """A sort by colour whose details follow a colon: the details are the task, read by the
    whole front end, and must sort by colour (each cube on the patch of its own colour);
    the heading adds nothing more (its "the patches" are the ones the details name)."""
    m = SORTED_HEADER_RE.match(f.text)
    heads = _read_parts([m.group("body")]) if m else None
    if heads is None:
        return False
    head = heads[0]
    colors = {a.name: a.color for a in head.assets}
    onto = [p for p in head.goal_predicate().conjuncts() if p.name == "on_patch"]
    if not onto or len(onto) != len(head.goal_predicate().conjuncts()) or any(
            colors[p.a] != colors[p.patch] for p in onto):
        return False
    b.assets += [a.model_copy() for a in head.assets]
    b._names.update(a.name for a in head.assets)
    b.place({n: p.pose() for n, p in head.goal_layout.items()})
    b.preds += head.goal_predicate().conjuncts()
    b.summary.append(head.goal_summary)
    b.primitives += list(head.primitives)
    b.min_separation = head.initial_state.min_separation
    return True


PART_SPLIT_RE = re.compile(
    r"\s*(?:[.;!]\s+|,?\s+and\s+then\s+|,\s*then\s+|\s+then\s+"
    r"|,?\s+and\s+(?=(?:put|place|build|make|stack|move|set|arrange|line\s+up|create|form|pile|slide|push|bring)\b)"
    rf"|,?\s+and\s+(?=(?:a|an|\d+)\s+(?:[\w-]+\s+){{0,2}}?{STRUCTURE_NOUN}s?\b)"
    rf"|(?:,?\s+and|,)\s+(?=(?:the\s+|all\s+(?:of\s+)?the\s+|every\s+|each\s+)(?:\d+\s+)?(?:{COLOR_RE})\s+(?:blocks?|cubes?)\s+"
    r"(?:(?:go|goes|should\s+go|must\s+go)\s+)?(?:in|on|at|into|to)\s+the\b))")
"""Where one task said after another begins: a new sentence, "then", or "and" before a verb
("make a tower of two blue blocks and put the red block on the left"), before a new structure
("a line of 4 gray cubes at the front and a circle of 5 orange cubes at the back") or before
cubes sent to a place of their own ("put the two green blocks in the back and the two blue
blocks in the front")."""

REFERS_ACROSS_RE = re.compile(
    r"\b(?:there|it|its|them|they|their|those|these|that|this|same|another|other|others|opposite|second|again|too|also"
    r"|as\s+well|one\s+more|more|matching|just\s+as|as\s+(?:long|tall|high|wide|many|big)|each|both|either|rest|remaining"
    r"|ends?|middle|center|centre)\b(?!\s+of\s+the\s+(?:table|workspace)\b)")
"""Words by which one part may speak of another ("stack two blue cubes there", "a row in front of
it", "the same tower with red cubes", "in the middle", "the other three"): a text with any of them
is not read as independent parts (the middle and centre of the table are the table's)."""

BARE_PLACE_RE = re.compile(r"\b(?:to|on|at|in)\s+the\s+(?:left|right|front|back|top)\s*$|\b(?:in\s+front|behind|on\s+top|beside)\s*$")
"""A part ending in a place said without what it is a place of ("... and put the red block on
the left"): beside another part it may be that part's left, so the parts are not read apart."""

PART_CLEARANCE: float = C.MIN_SEPARATION - C.CUBE_EDGE
"""Least gap (m) between the footprints of two parts laid out apart (the clearance rho_0 keeps
between two cubes, :data:`~rpg.domain.constants.MIN_SEPARATION` less one cube edge)."""

PART_GRID_STEP: float = 0.01
"""Step (m) of the grid of centres tried for a part that names no place."""


def _footprint(head: TaskSchema) -> list[tuple[float, float, float, float]]:
    """Boxes (x0, x1, y0, y1), m, of a part's cubes and goal patches in its goal layout."""
    boxes = []
    for a in head.assets:
        x, y = head.goal_layout[a.name].position[:2]
        sx, sy = ((C.LONG_PATCH_SIZE if a.shape == "long" else C.PATCH_SIZE) if a.kind == "goal_patch"
                  else (C.CUBE_EDGE, C.CUBE_EDGE))
        boxes.append((x - sx / 2, x + sx / 2, y - sy / 2, y + sy / 2))
    return boxes


def _overlaps(a: list, b: list) -> bool:
    g = PART_CLEARANCE
    return any(p[0] < q[1] + g and q[0] < p[1] + g and p[2] < q[3] + g and q[2] < p[3] + g for p in a for q in b)


def _part_shifts(heads: list[TaskSchema]) -> list[tuple[float, float]] | None:
    """A shift (dx, dy), m, for each part: none for a part that places itself (a region of the
    table), else the grid centre nearest the workspace's centre where the part's footprint
    stays on the workspace and clear of every part laid out before it.  None when a part
    cannot be laid out (or two that place themselves overlap)."""
    fixed = [any(isinstance(p, InRegion) for p in h.goal_predicate().walk()) for h in heads]
    placed: list = []
    shifts: list[tuple[float, float] | None] = [None] * len(heads)
    for i in sorted(range(len(heads)), key=lambda i: not fixed[i]):  # parts with a place first
        boxes = _footprint(heads[i])
        if fixed[i]:
            if _overlaps(boxes, placed):
                return None
            shifts[i], placed = (0.0, 0.0), placed + boxes
            continue
        cx = (min(b[0] for b in boxes) + max(b[1] for b in boxes)) / 2
        cy = (min(b[2] for b in boxes) + max(b[3] for b in boxes)) / 2
        xs = np.arange(C.WORKSPACE_X[0], C.WORKSPACE_X[1] + 1e-9, PART_GRID_STEP)
        ys = np.arange(C.WORKSPACE_Y[0], C.WORKSPACE_Y[1] + 1e-9, PART_GRID_STEP)
        centre = np.array(C.WORKSPACE_CENTER)
        for x, y in sorted(((float(x), float(y)) for x in xs for y in ys),
                           key=lambda p: (round(float(np.hypot(*(np.array(p) - centre))), 6), p)):
            moved = [(b[0] + x - cx, b[1] + x - cx, b[2] + y - cy, b[3] + y - cy) for b in boxes]
            if (all(C.WORKSPACE_X[0] <= b[0] and b[1] <= C.WORKSPACE_X[1] and C.WORKSPACE_Y[0] <= b[2]
                    and b[3] <= C.WORKSPACE_Y[1] for b in moved) and not _overlaps(moved, placed)):
                shifts[i], placed = (x - cx, y - cy), placed + moved
                break
        else:
            return None
    return shifts


def _said_apart(texts: list[str]) -> bool:
    """Whether no two parts name the same colour (cube or patch) or label: each part's cubes
    are its own, so nothing one part says of a cube can be about another part's."""
    seen: set[str] = set()
    for t in texts:
        own = {c for _, c in color_mentions(t)} | {m.upper() for m in re.findall(r"\b(?:letter|digit)\s+(\w)\b", t)}
        if own & seen:
            return False
        seen |= own
    return True


def _bare_place(part: str) -> bool:
    """Whether a part ends with a side that may be another part's ("put the red block on the
    left": the tower's left, or the table's?); a side said of a structure the part describes
    ("a line of 4 gray cubes at the front") is the table's."""
    m = BARE_PLACE_RE.search(part)
    return m is not None and NEW_STRUCTURE_BEFORE_RE.search(part[:m.start()]) is None


@reader(order=250)
def recognize_independent_parts(f: Features, b: Builder) -> bool:
    """Tasks said one after another that share no cube ("make a tower of two blue blocks and
    put the red block on the left"; "build a row of three green cubes. Put the red cube on
    the yellow patch"): each part is read by the whole front end, its cubes and patches keep
    its layout, and a part that names no place is moved clear of the others.  Tried last: a
    text any other reader takes is not split.  Parts that name a colour in common, refer to
    one another ("next to it") or cannot be laid out apart are not read here."""
    texts = [re.sub(r"^(?:then|next|after\s+that|afterwards)\s*,?\s+", "", t.strip(" ,.;!"))  # "Then stack blue and yellow.":
             for t in PART_SPLIT_RE.split(f.text)]  # the step's "then" orders the parts, not the part's cubes (it had ordered them)
    texts = [t for t in texts if t]
    shared = re.search(r"\s*,?\s*(?:both\s+|each\s+|all\s+)?(?:listed\s+)?(?:from\s+)?(?P<d>bottom\s+to\s+top|top\s+to\s+bottom)$",
                       texts[-1]) if len(texts) > 1 else None
    if shared and sum(bool(re.search(r"\b(?:tower|stack)\b", t)) for t in texts) > 1:  # "a tower of red and green and a
        # tower of blue and yellow, both from bottom to top": every tower's order (the first had been left free, silently)
        texts = [t[:shared.start()] if i == len(texts) - 1 else t for i, t in enumerate(texts)]
        texts = [f"{t}, {shared.group('d')}" if re.search(r"\b(?:tower|stack)\b", t) else t for t in texts]
    verb = re.match(r"(?:please\s+)?((?:put|place|move|set|bring|pile|stack|line\s+up|arrange|gather|group|heap|cluster)\s+)"
                    r"(?=(?:the|all|every|each|both)\b)", texts[0]) if texts else None
    bare = [bool(i and re.match(r"(?:the|all|every|each)\b", t)) for i, t in enumerate(texts)]  # a later part with no verb
    if any(bare) and verb is None and not re.match(r"(?:the|all|every|each)\b", texts[0]):
        return False  # "build a tower of the two green blocks in the back and the two blue blocks in the front": a tower too?
    texts = [f"{verb.group(1)}{t}" if verb and b_ and _bare_place(t) else t for t, b_ in zip(texts, bare, strict=True)]
    # "pile the red cubes on the left and the blue cubes on the right": both piled (only cubes sent to a place of their
    # own: "line up the pink cubes, then the brown ones" is one line or two)
    placed = [_bare_place(t) for t in texts]
    if (len(texts) < 2 or not _said_apart(texts) or any(REFERS_ACROSS_RE.search(t) for t in texts)
            or (any(placed) and not all(placed))):  # a side may be another part's ("a tower, and red on the left"),
        return False  # unless every part is given its own ("two green in the back and two blue in the front": the table's)
    heads = _read_parts(texts)
    if heads is None or any(h.initial_state.structures or any(a.kind == "semantic_cube" for a in h.assets) for h in heads):
        return False  # labels ("the numbers 1 to 3", "the number 2") are not told apart by colour: parts may share a cube
    shifts = _part_shifts(heads)
    if shifts is None:
        return False
    named = {c for _, c in color_mentions(f.text)}
    used: set[str] = set()
    for text, head, (dx, dy) in zip(texts, heads, shifts, strict=True):
        own = {c for _, c in color_mentions(text)}
        mapping: dict[str, str] = {}
        recolored: dict[str, str | None] = {}
        for a in head.assets:
            color = a.color
            if a.kind == "colored_cube":  # a colour the part left open and another part names or holds: another
                color = _open_color(color, own, used | named, used | named | {x.color for x in head.assets}, recolored)
                if color is None:  # more open cubes than colours left to tell them apart
                    return False
            if a.kind == "goal_patch":
                mapping[a.name] = b.patch(color, a.shape)
            elif a.kind == "colored_cube":
                mapping[a.name] = b.cube(color)
            else:
                mapping[a.name] = b.semantic(a.label, dict(a.faces))
            if color:
                used.add(color)
        for a in head.assets:
            x, y, z = head.goal_layout[a.name].position
            b.place({mapping[a.name]: Pose((x + dx, y + dy, z))})
        b.orientations.update({mapping[n]: q for n, q in head.initial_state.orientations.items()})
        goal = [p.rename(mapping) for p in head.goal_predicate().conjuncts()]
        b.preds += goal
        b.summary += [p.describe() for p in goal]
        b.primitives += list(head.primitives)
        if head.reasoning != "spatial":
            b.reasoning = head.reasoning
    return True
