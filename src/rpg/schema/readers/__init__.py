"""The builtin front end's readers, and the parse loop that tries them.

A *reader* reads one kind of instruction (a tower, a line, relations between named cubes, a
temporal order...) into a :class:`~rpg.schema.builder.Builder`.  Each registers itself with
:func:`~rpg.schema.readers.registry.reader` in the module of its family; :func:`parse` tries
them in their registered order and keeps the first reading that accounts for every mention
(:func:`rpg.schema.accounting.unaccounted`).

Modules: :mod:`.registry` (the registry), :mod:`.common` (what several readers read the same
way), and one module per family: :mod:`.places`, :mod:`.structures`, :mod:`.temporal`,
:mod:`.patches`, :mod:`.labels`, :mod:`.relational`, :mod:`.compose` (parts read apart, laid out together),
:mod:`.initial` (a start stated with the goal: rho_0's stacks).
"""

from __future__ import annotations

import itertools
import json
import math
import re
from collections import Counter

from pydantic import ValidationError

from rpg.domain.predicates import (
    MAX_ASSIGNMENTS,
    AnchoredLine,
    AnchoredStack,
    And,
    Behind,
    CentredIn,
    FarFrom,
    InFrontOf,
    InLine,
    InRegion,
    LeftOf,
    OnPatch,
    Reads,
    RightOf,
    Stack,
    StackOnPatch,
    UnorderedStack,
    describe_region,
    region_boxes,
)
from rpg.errors import BadInput
from rpg.schema import citations, lexicon
from rpg.schema.accounting import unaccounted
from rpg.schema.builder import Builder, make_paraphrases
from rpg.schema.model import TaskSchema
from rpg.schema.readers import (  # noqa: F401 (they register)
    compose,
    config,
    initial,
    labels,
    patches,
    places,
    registry,
    relational,
    structures,
    temporal,
)
from rpg.schema.reading import (
    COLOR_RE,
    MAX_INSTRUCTION_CHARS,
    MAX_RAW_CHARS,
    Features,
    Inexpressible,
    ParseError,
    canon_color,
    color_mentions,
    explicit_labels,
    features,
    task_slug,
)
from rpg.schema.structures import STRUCTURE_RE, STRUCTURE_WORDS


def _cube_colours_said(text: str) -> set[str]:
    """The colours ``text`` names cubes by: a colour that names a goal patch names no cube ("stack two blocks on the
    blue patch": any two blocks)."""
    return {c for i, c in color_mentions(text)
            if not re.match(r"\S*\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|tile|area|zone)\b", text[i:])}


def free_unnamed_orders(f: Features, schema: TaskSchema) -> TaskSchema:
    """A stack none of whose cubes the instruction names, gives a role or relates to anything
    else becomes an :class:`~rpg.domain.predicates.UnorderedStack`: "stack two blocks on top
    of each other" says nothing of which goes on top, so G may not demand an order (a policy
    that stacks them the other way has done what it was told).  The summary and paraphrases
    then say "in any order" too, so no instruction the policy is given states an order G
    lacks.  A colour named, an order word (:data:`rpg.schema.lexicon.ORDER_WORDS`), a cube of the stack in
    another part of the goal or in a structure rho_0 starts ("reverse the tower") keeps the order."""
    if lexicon.ORDER_WORDS.search(f.text.lower()):
        return schema
    named = _cube_colours_said(f.text)
    colors = {a.name: a.color for a in schema.assets if a.kind == "colored_cube"}
    goal = schema.goal_predicate()
    parts = goal.children() if isinstance(goal, And) else [goal]
    started = {n for st in schema.initial_state.structures for n in st}  # told apart by where rho_0 puts them

    def placed(q, p) -> bool:
        # a region the stack stands in, or the goal patch its base rests on, relates its base only as the
        # whole stack's place: every cube of a stack stands over the same spot, whichever is at the bottom (a stack
        # of one colour on a patch is left as it is: its cubes trade places anyway, evaluate_goal's assignment)
        return isinstance(q, InRegion) or (type(q) is OnPatch and q.a == p.objects[0]
                                           and len({colors.get(n) for n in p.objects}) > 1)

    def free(p):
        if type(p) is not Stack:
            return p
        elsewhere = {n for q in parts if q is not p and not placed(q, p) for n in q.object_names()}
        if (len(p.objects) > 1 and not set(p.objects) & (elsewhere | started)
                and all(n in colors and colors[n] not in named for n in p.objects)):
            return UnorderedStack(objects=p.objects)
        return p

    new = [free(p) for p in parts]
    for p, q in zip(parts, new, strict=True):  # "a tower of three blocks on the red patch": some cube of it on the patch
        if q is not p:
            new = [StackOnPatch(r.a, r.patch, tuple(sorted(p.objects))) if type(r) is OnPatch and r.a == p.objects[0] else r
                   for r in new]
    return _with_parts(schema, goal, parts, new)


_UNORDERED_FIELDS = {"unordered_stack": ("objects",), "stack_on_patch": ("among",), "next_to": ("a", "b"), "far_from": ("a", "b")}
"""Predicates whose named fields hold their objects as a set (their order says nothing), by predicate name."""

_PLACING = frozenset({"in_region", "left_of", "right_of", "in_front_of", "behind", "on_patch", "between", *_UNORDERED_FIELDS})
"""The predicates :func:`one_colour_for_unnamed` weighs: where cubes go (a structure of colours a reader chose for what
they are, "a colour gradient", is left as read)."""


def _canonical(p) -> str:
    """One conjunct of G as a string that two readings share when they differ only by the order of a set of objects."""
    d = p.to_dict()
    if p.name == "stack_on_patch":
        d.pop("a", None)  # some cube of the stack on the patch: which one is named says nothing
    fields = _UNORDERED_FIELDS.get(p.name, ())
    if len(fields) == 1 and isinstance(d.get(fields[0]), list):
        d[fields[0]] = sorted(d[fields[0]])
    elif len(fields) == 2:
        d[fields[0]], d[fields[1]] = sorted((d[fields[0]], d[fields[1]]))
    return json.dumps(d, sort_keys=True, default=str)


def one_colour_for_unnamed(f: Features, schema: TaskSchema) -> TaskSchema:
    """Cubes the instruction names by no colour, given default colours that differ, take one colour when G would tell
    them apart: "put a cube in the back left corner and a cube in the front left corner" had demanded the red cube
    back left and the blue one front left, a goal stricter than the words (issue 30); of one colour they are
    interchangeable, and G accepts either in either place.  Their colours stay as read where swapping them leaves G as it
    is ("stack two blocks", "both blocks onto the goal patch", "side by side"), where they are in a predicate other
    than a place or a relation (:data:`_PLACING`: "a colour gradient" chose them) or a stack rho_0 starts, where a
    patch of their colour may match them ("its corresponding patch"), where the words say the colours differ, and where
    one colour would give more interchangeable cubes than :data:`~rpg.domain.predicates.MAX_ASSIGNMENTS` covers."""
    if re.search(r"\b(?:different|distinct|other|not\s+the\s+same|unlike)\s+colou?rs?\b|\bcolou?rs?\s+(?:differ|that\s+differ)", f.text):
        return schema  # "..., different colours": their colours are said to differ
    said = _cube_colours_said(f.text)
    patch_colors = {a.color for a in schema.assets if a.kind == "goal_patch"}  # "each object into its corresponding patch": a
    # cube of a patch's colour may be matched to it by colour
    unnamed = [a for a in schema.assets if a.kind == "colored_cube" and a.color and a.color not in said | patch_colors]
    colors = list(dict.fromkeys(a.color for a in unnamed))
    group = [a for a in schema.assets if a.kind == "colored_cube" and a.color in colors]
    if len(colors) < 2 or math.factorial(len(group)) > MAX_ASSIGNMENTS:
        return schema  # (more cubes of one colour than evaluate_goal tries the assignments of: left as read)
    goal = schema.goal_predicate()
    parts = goal.conjuncts()
    names = {a.name for a in unnamed}
    if any(set(p.object_names()) & names and p.name not in _PLACING for p in parts) or schema.initial_state.structures:
        return schema
    before = sorted(_canonical(p) for p in parts)
    for x, y in itertools.combinations(unnamed, 2):
        if x.color == y.color:
            continue
        swapped = sorted(_canonical(p.rename({x.name: y.name, y.name: x.name})) for p in parts)
        if swapped != before:
            break
    else:
        return schema  # no swap of them changes G: their colours demand nothing
    taken = {a.name for a in schema.assets}
    mapping: dict[str, str] = {}
    for a in unnamed:
        if a.color != colors[0]:
            k = 1
            while f"{colors[0]}_{k}" in taken:
                k += 1
            mapping[a.name] = f"{colors[0]}_{k}"
            taken.add(mapping[a.name])
    from rpg.schema.edits import renamed_doc

    doc = renamed_doc(schema, mapping, colors[0])
    doc["goal_summary"] = "; ".join(p.describe() for p in doc["goal"].conjuncts())
    doc["paraphrases"] = make_paraphrases(doc["goal_summary"])
    return TaskSchema.model_validate(doc)


def _with_parts(schema: TaskSchema, goal, parts: list, new: list) -> TaskSchema:
    """``schema`` with the conjuncts ``parts`` of its ``goal`` replaced by ``new``, and the
    summary and paraphrases saying the new goal (``schema`` itself when nothing changed)."""
    if new == parts:
        return schema
    new_goal = And(new) if isinstance(goal, And) else new[0]
    summary = "; ".join(p.describe() for p in new)
    return schema.model_copy(update={"goal": new_goal, "goal_summary": summary,
                                     "paraphrases": make_paraphrases(summary)})


def _listed_roles(text: str) -> dict[str, str] | None:
    """For a stack whose cubes the instruction only lists ("stack the red and blue blocks",
    "... with red on top"): the ends it gives a colour ({"top": "red"}; empty: none), or None
    when it may say more of the order (:data:`rpg.schema.lexicon.CUBE_ORDER_RE`)."""
    roles: dict[str, str] = {}
    for m in lexicon.STACK_ROLE_RE.finditer(text):
        color = m.group("c")
        if color not in lexicon.COLORS:
            return None
        end = "top" if (m.group("end") or m.group("end2")) == "top" else "bottom"
        if roles.get(end, color) != color:
            return None
        roles[end] = color
    rest = lexicon.STACK_FREE_PHRASES.sub(" ", lexicon.STACK_ROLE_RE.sub(" ", text))
    rest = re.sub(r"\bnext\s+to\b", " beside ", rest)  # a relation, not a step ("next, ...")
    if lexicon.ORDER_WORDS.search(rest) or lexicon.CUBE_ORDER_RE.search(rest):
        return None
    return roles


_PLANAR_RELATIONS = (LeftOf, RightOf, InFrontOf, Behind, FarFrom)
"""Relations judged in the table's plane alone (:class:`~rpg.domain.predicates.NextTo` also needs the cubes level): one to
a cube of a stack holds of every cube of it."""


def free_listed_orders(f: Features, schema: TaskSchema) -> TaskSchema:
    """A stack of named cubes that the instruction only lists gets no order from the list:
    "stack the red and blue blocks" or "put the red, blue and green blocks on top of each
    other" say nothing of which goes on top, so G is an
    :class:`~rpg.domain.predicates.UnorderedStack`; "... with red on top" gives red the top and
    the rest no order (:class:`~rpg.domain.predicates.AnchoredStack`).  A stack standing on a
    goal patch then needs some cube of it there (:class:`~rpg.domain.predicates.StackOnPatch`).
    Any word that may order the cubes ("on", "then", "from bottom to top", "in that order")
    keeps the order read (issue 30: a goal may demand nothing the words do not)."""
    roles = _listed_roles(" ".join(f.text.lower().split()))
    if roles is None:
        return schema
    # what names each cube: its colour, or the label of a letter or digit cube ("the letters C, A and T")
    colors = {a.name: a.color if a.kind == "colored_cube" else a.label for a in schema.assets
              if a.kind == "colored_cube" or (a.kind == "semantic_cube" and a.label)}
    named = {c for _, c in color_mentions(f.text)} | set(explicit_labels(f)) | {
        m.upper() for m in re.findall(r"\b(?:letter|number|digit)\s+'?([A-Za-z0-9])'?(?![A-Za-z0-9'])", f.original, re.IGNORECASE)} | {
        # "a tower of the X block and the Y block", "the X and Y blocks": a capital said as a cube's label
        m for m in re.findall(r"(?<![\w'-])([A-Z0-9])(?=(?:\s+and\s+(?:the\s+)?[A-Z0-9])*\s+(?:block|cube)s?\b)", f.original)}
    goal = schema.goal_predicate()
    parts = goal.children() if isinstance(goal, And) else [goal]
    out = list(parts)
    for i, p in enumerate(parts):
        if (type(p) is not Stack or not all(colors.get(n) in named for n in p.objects)
                or len({colors[n] for n in p.objects}) < 2):
            continue  # a stack with a cube nobody named is free_unnamed_orders' and the citations'; one of
            # interchangeable cubes (one colour) has no order to drop
        objs = list(p.objects)
        others = [q for q in parts if q is not p and set(q.object_names()) & set(objs)]
        if not all(isinstance(q, InRegion) or (type(q) is OnPatch and q.a == objs[0])
                   or (isinstance(q, _PLANAR_RELATIONS) and len(set(q.object_names()) & set(objs)) == 1) for q in others):
            continue  # a cube of the stack related to something else by itself: its place is said ("next to it" is
            # judged against the tower's bottom cube, so the order read is kept; a relation in the plane to one cube of it
            # holds of the whole tower, its cubes standing one above another: "put green behind it")
        ends = {end: [n for n in objs if colors[n] == c] for end, c in roles.items()}
        if any(len(v) != 1 for v in ends.values()):
            continue  # a role colour missing from this stack, or shared by two of its cubes
        if "bottom" in ends:
            objs.remove(ends["bottom"][0])
            objs.insert(0, ends["bottom"][0])
        if "top" in ends:
            objs.remove(ends["top"][0])
            objs.append(ends["top"][0])
        if objs != list(p.objects):
            continue  # the goal configuration stacks them otherwise: leave it to the citations
        out[i] = (AnchoredStack(objects=p.objects, bottom="bottom" in ends, top="top" in ends) if ends
                  else UnorderedStack(objects=p.objects))
        for j, q in enumerate(parts):
            if type(q) is OnPatch and q.a == objs[0] and q in others:
                out[j] = StackOnPatch(q.a, q.patch, tuple(sorted(objs)))
    return _with_parts(schema, goal, parts, out)


def any_order_with_ends(f: Features, schema: TaskSchema) -> TaskSchema | None:
    """A reading of a text that leaves a tower's order free ("in any order") and gives an end to one of its cubes, or to
    one each ("Stack A, B and C into one tower. Any order is fine, but A must be at the bottom.", "Tower: purple base,
    then the yellow and the white cubes above it in any order"): its one :class:`~rpg.schema.Stack` made an
    :class:`~rpg.domain.predicates.AnchoredStack` with those ends fixed and the rest free; None where the reading has
    another stack, a cube named for an end is not one of its own or its colour is shared, an end is said twice, or a
    cube of it is related to something else by itself (the order read would be judged)."""
    goal = schema.goal_predicate()
    parts = goal.children() if isinstance(goal, And) else [goal]
    stacks = [p for p in parts if type(p) is Stack]
    if len(stacks) != 1 or any(isinstance(p, (Stack, AnchoredStack, UnorderedStack)) and p is not stacks[0]
                               for q in parts for p in q.walk()):
        return None
    stack = stacks[0]
    names = {a.name: a.color if a.kind == "colored_cube" else a.label for a in schema.assets
             if a.kind == "colored_cube" or (a.kind == "semantic_cube" and a.label)}
    ends: dict[str, str] = {}
    rest = " ".join(part for part in re.split(r"[,;.:!?]", lexicon.TOWER_END_SAID_RE.sub(" ", f.original))
                    if not lexicon.FREE_ORDER_PART_RE.search(part))
    if lexicon.ORDER_BEYOND_ENDS_RE.search(rest):
        return None  # "A at the bottom, then B": more of the order said than its ends (it had been dropped); a part that
        # says the rest is free ("then the yellow and the white cubes above it in any order") says no more
    for m in lexicon.TOWER_END_SAID_RE.finditer(f.original):
        if re.search(rf"(?i)(?:\b(?:{COLOR_RE})|(?-i:\b[A-Z])|\b\d)(?:\s+(?:cube|block))?\s+and\s+(?:the\s+)?$", f.original[:m.start()]):
            return None  # "C and D must be on top": two cubes for one end (D alone had been fixed)
        said = canon_color(m.group("c").lower()) if m.group("c").lower() in lexicon.COLORS or len(m.group("c")) > 1 else m.group("c")
        owners = [n for n in stack.objects if names.get(n) == said]
        end = "top" if (m.group("end") or "").lower() == "top" else "bottom"
        if len(owners) != 1 or ends.get(end, owners[0]) != owners[0]:
            return None
        ends[end] = owners[0]
    if not ends or len(set(ends.values())) != len(ends):
        return None
    others = [q for q in parts if q is not stack and set(q.object_names()) & set(stack.objects)]
    if not all(isinstance(q, InRegion) for q in others):
        return None
    objs = [n for n in stack.objects if n not in ends.values()]
    objs = ([ends["bottom"]] if "bottom" in ends else []) + objs + ([ends["top"]] if "top" in ends else [])
    anchored = AnchoredStack(objects=tuple(objs), bottom="bottom" in ends, top="top" in ends)
    return _with_parts(schema, goal, parts, [anchored if q is stack else q for q in parts])


def pronoun_cubes_made_up(f: Features, schema: TaskSchema) -> ParseError | None:
    """A reading whose cubes of some colour nobody said stand for "them" ("Make a row of them.", "Initially red is on blue.
    Make a row of them."): the pronoun's cubes made up (a row of red, blue, green and yellow, silently), refused; None where
    the text counts or names cubes without a colour ("three cubes ... stack them") or every colour of the task is said."""
    m = lexicon.PRONOUN_CUBES_RE.search(f.text)
    if m is None or re.search(rf"\b(?:\d+|{lexicon.COUNT_WORD_RE}|a|an|another|one|some|the|all)\s+(?:more\s+)?(?:cubes?|blocks?)\b", f.text):
        return None
    said = {c for _, c in color_mentions(f.text)}
    made_up = sorted({a.color for a in schema.assets if a.kind == "colored_cube"} - said)
    if not made_up:
        return None
    return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group('w')}' names no cubes of the task "
                      f"(its {', '.join(made_up)} cubes are made up); name them (e.g. \"make a row of the red and blue blocks\"), "
                      "or use --model")


def line_with_ends(f: Features, schema: TaskSchema) -> TaskSchema | None:
    """A reading of a text that gives a row of three or more cubes, read in no order, a cube at its left or right end and
    says nothing more of its order ("a row of red, green and blue with red at the left end", "Make a row of the orange,
    pink and gray cubes; the gray one must be at the right end"): its one :class:`~rpg.domain.predicates.InLine` made an
    :class:`~rpg.domain.predicates.AnchoredLine` with those ends fixed and the rest free, its goal configuration laid out
    to match; None where the reading has another line, the line runs front to back, any other word gives a cube a place
    in it (:data:`lexicon.LINE_ROLE_RE`) or says more of its order (:data:`lexicon.ORDER_BEYOND_ENDS_RE`), an end is said
    twice, a colour named for an end is not one of its cubes, or a cube of it is related to something else by itself."""
    goal = schema.goal_predicate()
    parts = goal.children() if isinstance(goal, And) else [goal]
    lines = [p for p in parts if isinstance(p, InLine)]
    if len(lines) != 1 or type(lines[0]) is not InLine or lines[0].order or len(lines[0].objects) < 3 \
            or lines[0].axis not in (None, "y"):
        return None
    line = lines[0]
    text = lexicon.FREEDOM_SENTENCE_RE.sub(" ", re.sub(r"\bin\s+any\s+order\b", " ", f.text))
    said = list(lexicon.LINE_END_SAID_RE.finditer(text))
    if not said or any(not any(m.start() <= r.start() and r.end() <= m.end() for m in said)
                       for r in lexicon.LINE_ROLE_RE.finditer(text)):
        return None  # no end said, or another place in the line ("with blue in the middle", "at one end")
    rest = " ".join(part for part in re.split(r"[,;.:!?]", lexicon.LINE_END_SAID_RE.sub(" ", f.text))
                    if not lexicon.FREE_ORDER_PART_RE.search(part))
    if lexicon.ORDER_BEYOND_ENDS_RE.search(rest) or re.search(r"\b(?:left|right)\b", rest):
        return None  # "red at the left end, then blue": more of the order said; another side said elsewhere
    if re.search(r"\b(?:if\s+(?:possible|you\s+can)|ideally|preferably|optionally|maybe|perhaps)\b", f.original.lower()):
        return None  # "with red at the left end if possible": a wish, not read as a constraint
    colours = {a.name: a.color for a in schema.assets if a.kind == "colored_cube"}
    if any(re.search(rf"(?:\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s*,?\s+and\s+(?:the\s+)?|\band\s+the\s+)$", text[:m.start()])
           for m in said):
        return None  # "red and green at the left end": two cubes for one end
    listed = re.search(rf"\b(?:row|line)\s+(?:out\s+)?of\s+(?:the\s+)?(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))*\s*,?\s*(?:and|&)\s+"
                       rf"(?:the\s+)?(?:{COLOR_RE}))\b", text)
    named = Counter(canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", listed.group("l"))) if listed else None
    said_colours: Counter = Counter()
    for m in re.finditer(rf"\b(?:(?P<n>\d+|{lexicon.COUNT_WORD_RE})\s+)?(?P<c>{COLOR_RE})\b", text):
        said_colours[canon_color(m.group("c"))] += lexicon.count_word(m.group("n")) if m.group("n") else 1
    if any(Counter(colours[n] for n in line.objects)[c] > said_colours[c] for c in {colours.get(n) for n in line.objects}) or (
            named is not None and Counter(colours[n] for n in line.objects) != named):
        return None  # cubes of a colour nobody said ("a row of three cubes with yellow at the left end": three yellow), or
        # a cube beyond the row's list ("a row of red, green and blue. The gray one must be at the right end")
    ends: dict[str, str] = {}
    for m in said:
        side = (m.group("side") or m.group("side2") or m.group("most") or m.group("most2")).lower()
        owners = [n for n in line.objects if colours.get(n) == canon_color((m.group("c") or m.group("c2")).lower())]
        if not owners or ends.get(side, owners[0]) != owners[0] or owners[0] in [v for k, v in ends.items() if k != side]:
            return None
        ends[side] = owners[0]
    others = [q for q in parts if q is not line and set(q.object_names()) & set(line.objects)]
    if not all(isinstance(q, (InRegion, CentredIn)) for q in others):
        return None
    objs = ([ends["left"]] if "left" in ends else []) + [n for n in line.objects if n not in ends.values()] + (
        [ends["right"]] if "right" in ends else [])
    anchored = AnchoredLine(objects=tuple(objs), axis="y", left="left" in ends, right="right" in ends)
    slots = sorted((schema.goal_layout[n] for n in line.objects), key=lambda pose: -pose.position[1])  # left to right
    layout = {**schema.goal_layout, **dict(zip(objs, slots, strict=True))}
    read = _with_parts(schema, goal, parts, [anchored if q is line else q for q in parts])
    return read.model_copy(update={"goal_layout": layout})


def disjoint_regions(f: Features, schema: TaskSchema) -> ParseError | None:
    """A reading that puts one cube in two places of the table that do not meet (red in the
    front left corner and in the front right corner), or on two goal patches (which rho_0 lays
    apart): no placement satisfies it."""
    seen: dict[str, list[str]] = {}
    patched: dict[str, list[str]] = {}
    cubes = {a.name for a in schema.assets if a.kind != "goal_patch"}
    tower = {c: c for c in cubes}  # a cube -> the bottom of the tower it stands in (stacked cubes share one place)

    def bottom(c: str) -> str:
        while tower[c] != c:
            c = tower[c]
        return c
    for upper, lower in schema.goal_predicate().support_edges():
        if upper in cubes and lower in cubes and bottom(lower) != bottom(upper):
            tower[bottom(upper)] = bottom(lower)
    for p in schema.goal_predicate().walk():
        if isinstance(p, InRegion):  # "red in the back left corner, yellow in the front right one, red on yellow": the
            # tower would stand in both
            seen.setdefault(bottom(p.a) if p.a in cubes else p.a, []).append(p.region)
        elif type(p) is OnPatch:
            patched.setdefault(p.a, []).append(p.patch)
    for cube, on in sorted(patched.items()):
        if len(set(on)) > 1:
            return Inexpressible("contradiction", [f"{cube} on {' and on '.join(sorted(set(on)))}".replace("_", " ")],
                                 "contradicts itself: one cube cannot stand on two goal patches at the end of the "
                                 "episode; say one patch per cube", f.original)
    for cube, regions in sorted(seen.items()):
        for i, r in enumerate(regions):
            for q in regions[i + 1:]:
                if not any(x0 < x1_ and x0_ < x1 and y0 < y1_ and y0_ < y1
                           for (x0, x1), (y0, y1) in region_boxes(r) for (x0_, x1_), (y0_, y1_) in region_boxes(q)):
                    return ParseError(f"read \"{f.original[:80]}\" as a task that puts {cube} in {describe_region(r)} "
                                      f"and in {describe_region(q)}, which do not meet (a contradiction); say one place per cube "
                                      "(one sentence per structure helps), or use --model")
    return None


def _identifier_label(instruction: str) -> tuple[str, str] | None:
    """(label, text) when ``instruction`` opens with a task's identifier (:data:`lexicon.ID_LABEL_RE`)
    whose every word says nothing the text must (an identifier word, a number or letter, a word of
    the task's kind); None otherwise (then the label is read with the rest, and refused if it says
    what the domain cannot: "Time-limited stacking: ...")."""
    m = lexicon.ID_LABEL_RE.match(instruction)
    fillers = frozenset() if m else lexicon.LABEL_FILLER_WORDS  # "Tower of 3. Base: gray.": a count, no identifier
    if m is None:
        m = lexicon.ID_WORDS_LABEL_RE.match(instruction)  # "Tower variant B: ...", "Demo-day row: ...": words alone
        said = re.findall(r"[A-Za-z]+", m.group("label")) if m else []
        if not any(w.lower() in lexicon.LABEL_JARGON for w in said) or any(len(w) == 1 and w.islower() for w in said) \
                or re.search(r"(?i)\b(?:\d+|one|two|three|four|five|six)[\s-]+(?:[a-z]+[\s-]+)?(?:tower|stack|row|line|pile|wall|pyramid"
                             r"|circle|grid|block|cube)s?\b|\b(?:towers|stacks|rows|lines|piles|walls|pyramids|circles|grids|height|tall|high"
                             r"|ordered|order)\b", m.group("label")):
            return None  # "a: ..." is no letter of a name; "Two-tower variant:", "Baseline, 3 towers:" count (one had been made)
    words = re.findall(r"[a-z]+", re.sub(r"\"[^\"]*\"", " ", m.group("label")).lower())  # a quoted name says nothing
    if not all(w in lexicon.LABEL_JARGON or w in lexicon.LABEL_TASK_KIND_WORDS or w in lexicon.NUMBER_WORDS or len(w) == 1
               or re.fullmatch(r"v|x|st|nd|rd|th", w) or w in fillers
               for w in words):
        return None
    body = m.group("body")
    if re.search(r"(?i)\b(?:them|they|those|these)\b", body) and len(re.findall(r"\d", m.group("label"))) > 1:
        return None  # "digits 9, 4, 7: put them in a row ...": the cubes the body refers to (no identifier)
    if m.groupdict().get("params"):  # "spell-word [word=SUN]: letter cubes in a row": the parameter's words join the text
        key, _, value = (p.strip() for p in m.group("params").partition("="))
        said = lexicon.LABEL_PARAMS.get(key.lower())
        place = config.place_phrase(value) if said == "{place}" else ""
        if said is None or (said == "{place}" and place is None):
            return None
        added = place if said == "{place}" else said.format(value)
        body = f"{body.rstrip(' .')} {added}".strip() if added else body
    return m.group("label"), body


_TOWERS_COUNT_SENTENCE_RE = re.compile(
    r"(?i)(?:^|(?<=[.;:!?])\s+)(?:(?:please\s+)?(?:build|make|stack|create|construct)\s+)?(?P<n>one|two|three|four|five|\d+)\s+"
    r"(?:[a-z]+\s+)?(?:towers?|stacks?)(?:\s+of\s+(?:\d+|two|three|four|five)(?:\s+(?:cubes|blocks))?)?\s*(?:[.:;!]|$)")
"""A sentence that only counts towers ("Build two towers.", "Two towers.", "Build 3 towers of two:"): beside sentences that
say towers one by one, a heading of theirs (:func:`_towers_counted`)."""
_TOWER_SAID_RE = re.compile(r"(?i)(?:\b(?:build|make|stack|create|construct|form)\s+|(?:^\s*|(?<=[.;:!?])\s+)(?:and\s+)?)(?:a|an|another"
                            r"|one|1|the\s+(?:first|second|third|fourth|other|last))\s+(?:[a-z]+\s+)?(?:tower|stack)\b")
"""A tower said on its own ("Build a tower of ...", "Build another tower of ...")."""
_TOWER_NAMED_RE = re.compile(r"(?i)\b(?:(?:tower|stack|column)\s+(?:[A-Z]|[IVX]+|#?\d+|one|two|three|four)|(?:first|second|third|fourth"
                             r"|1st|2nd|3rd|4th|other|next|last)\s+(?:tower|stack|column))\b(?=\s*(?:\([^)]*\)\s*)?,?[^.;:]{0,30}?"
                             r"(?:[:=]|\s[-\u2013\u2014]\s))")
"""A tower named before what it holds ("Tower A: ...", "Tower 2 (top to bottom): ...", "Second tower - ...")."""


def _towers_counted(instruction: str) -> str:
    """``instruction`` with its towers named and listed written one sentence each (:func:`lexicon.named_towers_listed`) and
    a sentence that only counts towers beside towers said one by one dropped when it counts them.

    Raises:
        ParseError: towers named one by one that are not each a list of cubes ("Tower 1: red. Tower 2: blue.", "Tower I -
            red, green"), or a count of towers other than the towers said one by one ("Build two towers. Build a tower of
            red and green."): the towers had been merged into one, or those not said made up of cubes nobody named."""
    heads = list(_TOWER_NAMED_RE.finditer(instruction))
    named = sum(not re.search(r"\b(?:on|onto|atop|under|over|above|below)\b", instruction[h.end():nxt])  # "tower A = pink on
                for h, nxt in zip(heads, [h.start() for h in heads[1:]] + [len(instruction)], strict=False))  # white": a chain
    listed = lexicon.named_towers_listed(instruction)
    if named >= 2 and len(lexicon.NAMED_TOWER_LIST_RE.findall(instruction)) < named:
        raise ParseError(f"\"{instruction[:80]}\" names {named} towers and lists their cubes in a way not read for each: say "
                         "each tower in a sentence of its own (e.g. \"Build a tower of red and green. Build another tower of "
                         "blue and yellow.\"), or use --model")
    counts = list(_TOWERS_COUNT_SENTENCE_RE.finditer(listed))
    said = len(_TOWER_SAID_RE.findall(_TOWERS_COUNT_SENTENCE_RE.sub(" ", listed)))
    if said and counts:  # "Build two towers. Build a tower of red and green. ...": a heading that counts the towers said
        count = counts[0].group("n").lower()
        counted = int(count) if count.isdigit() else lexicon.NUMBER_WORDS[count]
        if len(counts) > 1 or said != counted:
            raise ParseError(f"\"{instruction[:80]}\" counts {counted} towers and says {said} one by one: a tower it does "
                             "not describe would be made up; say each tower (e.g. \"Build a tower of red and green. Build "
                             "another tower of blue and yellow.\"), or use --model")
        listed = (listed[:counts[0].start()] + " " + listed[counts[0].end():]).strip()
    return listed


_TOWERS_HEADING_RE = re.compile(
    r"(?i)^\s*(?:(?:please\s+)?(?:let's\s+)?(?:build|make|stack|create|construct|set\s+up|lay\s+out|line\s+up)\s+"
    r"|(?:we|i)\s+(?:want|need|would\s+like)\s+)?"
    r"(?P<n>two|three|four|[2-4])\s+(?:separate\s+|distinct\s+|independent\s+)?(?:(?P<c>" + COLOR_RE + r")\s+)?(?P<kind>towers|stacks|rows|lines)"
    r"(?:\s+of\s+(?P<h>two|three|four|[2-4])(?:\s+(?:cubes|blocks))?|,?\s+(?P<h2>two|three|four|[2-4])\s+(?:cubes|blocks)\s+each"
    r"|,?\s+each\s+(?P<h3>two|three|four|[2-4])\s+(?:(?:cubes|blocks)\s+)?(?:tall|high|long))?"
    r"(?:\s+each)?(?:\s+at\s+the\s+end)?(?:\s*,\s*(?:friends|folks|everyone|team|please))?"
    r"(?:\s*:\s*|\s*,\s*(?=(?:one|the\s+first|a\s+(?:row|line|tower|stack))\b))(?P<body>.+)$")
"""A heading that counts towers or rows (of one colour: "two gray towers") before a colon, or a comma before the first of
them, and the structures said after it ("Build two towers of two cubes:
yellow on orange in the back left corner, and white on gray in the front right corner.", "We want two separate towers at
the end: pink on purple, and black on white.", "Make two rows: a row of three red blocks and a row of three blue
blocks."): read by :func:`_towers_headed`."""

_HEADED_KINDS: dict[str, type] = {"towers": Stack, "stacks": Stack, "rows": InLine, "lines": InLine}
"""The goal predicate each structure noun of :data:`_TOWERS_HEADING_RE` counts."""


def _towers_headed(instruction: str, framed: bool) -> TaskSchema | None:
    """The task of a heading that counts ``n`` towers or rows (of ``h`` cubes) and the structures said after its colon
    (:data:`_TOWERS_HEADING_RE`): the text after the colon read alone, kept only where it is exactly ``n`` structures of
    that kind (each of ``h`` cubes) and nothing else but their places; None where the heading is not one such (the readers read it whole,
    which had refused "which cubes make each tower is not said" where the chains say it)."""
    m = _TOWERS_HEADING_RE.match(lexicon.rewrite(lexicon.TOWERS_BY_PLACE_REWRITES, instruction))
    if m is None:
        return None
    n, h = lexicon.count_word(m.group("n")), m.group("h") or m.group("h2") or m.group("h3")
    try:
        schema = parse(m.group("body"), _framed=framed)
    except BadInput:
        body = _enumerated_parts(m.group("body"), m.group("kind").lower(), h, m.group("c"))
        if body is None:
            return None
        try:  # "Two towers, each three tall: the first red-blue-green bottom to top, the second all gray"
            schema = parse(body, _framed=framed)
        except BadInput:
            return None
    parts = [p for p in schema.goal_predicate().walk() if not isinstance(p, And)]
    kind = _HEADED_KINDS[m.group("kind").lower()]
    stacks = [p for p in parts if isinstance(p, kind)]
    colour = canon_color(m.group("c")) if m.group("c") else None
    if colour and any(a.color != colour for a in schema.assets if a.kind != "goal_patch"):
        return None  # "Two gray towers: red on blue, and green on yellow": the heading's colour is every cube's, or the
        # text is read whole (the heading's colour had been dropped: a hostile helper's)
    if len(stacks) != n or any(not isinstance(p, (kind, InRegion)) for p in parts) or (
            h and any(len(p.objects) != lexicon.count_word(h) for p in stacks)) or len({o for p in stacks for o in p.objects}) != sum(a.kind != "goal_patch" for a in schema.assets):
        return None
    return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})


def _enumerated_parts(body: str, kind: str, h: str | None, colour: str | None = None) -> str | None:
    """A heading's colon text that counts off its structures (:data:`lexicon.ENUMERATED_PART_RE`: "the first red-blue-green
    bottom to top, the second all gray") said as one sentence per structure of ``kind`` ("A tower of red-blue-green bottom
    to top. A tower of 3 gray cubes."; "all gray", "built from gray cubes" are ``h`` gray cubes where the heading says how
    many each has; a part that says only its place, "one on the left", is ``h`` cubes of the heading's ``colour``); None
    where it does not open with such a word or counts off fewer than two."""
    parts = lexicon.ENUMERATED_PART_RE.split(body.strip().rstrip(".!"))
    if len(parts) < 3 or parts[0].strip():
        return None
    noun = kind.removesuffix("s")
    if colour is not None and not all(lexicon.ENUMERATED_PART_PLACE_RE.fullmatch(p.strip(" ,;")) for p in parts[1:]):
        return None  # a heading's colour beside a part with cubes of its own ("Two gray towers: the first red-blue-green, the
        # second on the left"): which colour is whose is not read
    said = []
    for part in (p.strip(" ,;") for p in parts[1:]):
        part = re.sub(r"^(?:(?:built|made)\s+(?:from|of|out\s+of)|of)\s+", "", part)  # "one built from red cubes"
        if lexicon.ENUMERATED_PART_PLACE_RE.fullmatch(part):  # "Two gray towers, each three cubes tall: one on the left ..."
            if h is None or colour is None:
                return None
            said.append(f"A {noun} of {lexicon.count_word(h)} {colour} cubes {part}.")
            continue
        if not lexicon.ENUMERATED_PART_SPEC_RE.fullmatch(part):
            return None  # anything but cubes, an order and a place ("..., the green one taller", "..., touching"): not read
        uniform = re.fullmatch(rf"(?:all|only)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|ones))?|({COLOR_RE})\s+(?:cubes|blocks|ones)", part)
        if uniform:
            if h is None:
                return None  # "the second all gray": how many is not said
            part = f"{lexicon.count_word(h)} {uniform.group(1) or uniform.group(2)} cubes"
        said.append(f"A {noun} of {part}.")
    return " ".join(said)


def _named_heading(instruction: str, framed: bool) -> TaskSchema | None:
    """The task of a heading that names what its colon's text builds (:data:`lexicon.NAMING_HEADING_RE`: "Let's make a
    little train: four blocks in a row, ...", "Plate it: put ..."): the text after the colon read alone, kept only where
    the heading holds no colour, label, count, structure, place, hazard (:data:`lexicon.VOICE_CHUNK_HAZARD_RE` but its
    "it"/"this", a take-back), no thing known by its order, shape or pose (:data:`lexicon.VOICE_SIMILE_BLOCKER_RE`), no
    one's own thing, and no verb that changes the scene but one that makes (:data:`lexicon.NAMING_HEADING_VERBS_EXEMPT`); None
    otherwise (the readers read the text whole, and refuse the heading's words for what they are)."""
    m = lexicon.NAMING_HEADING_RE.match(instruction)
    if m is None or framed:
        return None
    heading = instruction[:m.start("body")].lower()
    weighed = re.sub(r"\b(?:it|this)\b", " ", heading)
    verb = m.group("verb").lower()
    if "VERB" not in lexicon.parts_of_speech(verb) or ({verb, *lexicon.lemmas(verb)} & lexicon.SCENE_CHANGING_VERBS
                                                      and not {verb, *lexicon.lemmas(verb)} & lexicon.NAMING_HEADING_VERBS_EXEMPT):
        return None
    if re.search(r"\d|\b[A-Z]\b", instruction[:m.start("body")]) or re.search(STRUCTURE_RE, heading, re.IGNORECASE) \
            or lexicon.VOICE_CHUNK_HAZARD_RE.search(weighed) or lexicon.RETRACTION_RE.search(weighed) \
            or lexicon.VOICE_PLACE_HAZARD_RE.search(weighed) or re.search(rf"\b(?:{lexicon.COUNT_WORD_RE})\b", heading) \
            or any(c in heading.split() for c in lexicon.colour_names()) or lexicon.GOAL_THING_RE.search(weighed) \
            or lexicon.VOICE_SIMILE_BLOCKER_RE.search(weighed) or re.search(r"\b(?!let's|it's|that's)[a-z]+'s\b", heading):
        return None  # (a thing known by its order, shape or pose, "like a staircase", "a traffic light", "like a snowman", or
        # someone's, "like the referee's", may say more than the text after the colon: a hostile helper's)
    try:
        schema = parse(m.group("body"), _framed=True)
    except BadInput:
        return None
    return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})


def parse(instruction: str, _framed: bool = False) -> TaskSchema:
    """Read an instruction into a TaskSchema.

    ``_framed`` is set when reading the text a config or an identifier stood for (one frame is
    read, never a frame inside it).

    Raises:
        ParseError: the instruction is empty, too long, has words outside the domain, or
            describes no task the parser knows (message quotes the problem, suggests --model).
        UnknownColorError / UnknownLabelError: an unknown colour or label.
    """
    if len(instruction) > MAX_RAW_CHARS:
        raise ParseError(f"the instruction has {len(instruction)} characters; the limit is {MAX_INSTRUCTION_CHARS}")
    spaced = re.sub(r"[ \t]{2,}", " ", re.sub(r"\n[ \t\n]*\n", "\n", instruction))  # runs of blanks say nothing, and
    if spaced != instruction:  # patterns that begin with optional blanks had taken minutes over thousands of them
        schema = parse(spaced, _framed=_framed)
        return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})
    listed = _towers_counted(instruction)
    shared = re.search(r"\b(?:\d+|two|three|four|five|six|both)\s+(?:[A-Z]|\d)\s+(?:blocks|cubes|bricks)\b", instruction)
    if shared:  # "put two A blocks on the patch", "the 3 3 cubes": a label is one cube's (they had become cubes of colours)
        raise ParseError(f"'{shared.group(0)}' names several cubes with one label: each letter or digit is on one cube; "
                         "name each cube (e.g. \"the A block and the B block\"), or use --model")
    bare = next((m for m in re.finditer(r"(?i)\b(?:cubes|blocks)\s+(?:[A-Z]|\d)\s+and\s+(?:[A-Z]|\d)\b(?!\s+(?:next\s+to|beside)\s+"
                                        r"(?:each\s+other|one\s+another))", instruction)
                 if not re.search(r"(?i)\b(?:letter|digit|number|label(?:l?ed)?)\s*$", instruction[:m.start()])), None)
    kinds = {"letter" if c.isalpha() else "digit" for c in re.findall(r"\b(?:[A-Z]|\d)\b", bare.group(0))} if bare else set()
    if len(kinds) == 1:  # "one tower out of cubes A and B": cube A and cube B, as "cube A" alone is (two coloured cubes
        said = f"{kinds.pop()} {bare.group(0)}"  # had been made up for the labels)
        schema = parse(instruction[:bare.start()] + said + instruction[bare.end():], _framed=_framed)
        return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})
    if bare:  # "put blocks A and 4 on the red patch"
        raise ParseError(f"'{bare.group(0)}' names cubes by labels without saying they are letter or digit cubes; say so "
                         "(e.g. \"the digit cubes 3 and 4\", \"the letter cubes A and B\"), or use --model")
    if listed != instruction:  # "Tower 1: red, green. Tower 2: ...": a tower each (the first name had been read as a label)
        schema = parse(listed, _framed=_framed)
        return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})
    written = None if _framed else config.sentence(instruction)
    if written is not None:  # "structure=line; n=5; colour=green; region=back": the sentence it stands for
        schema = parse(written, _framed=True)
        return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})
    labelled = None if _framed else _identifier_label(instruction)
    if labelled is not None:  # "Task 7 (Stacking-3): the agent must build ...": the text after it
        label, body = labelled
        named = re.sub(r"(?<=\S)\s+[a-z]+\s+\d+\b", " ", label.lower())  # "script, line 12": a line's number (not "Tower 3")
        noun = next((w for w in re.findall(r"[a-z]+", named) if w in STRUCTURE_WORDS), None)
        layered = next((w for w in re.findall(r"[a-z]+", label.lower()) if w in ("wall", "pyramid", "grid")), None)
        if layered and not re.search(STRUCTURE_RE, re.sub(r"(?i)\b(?:rows?|layers?|levels?|tiers?|courses?)\b", " ", body)):
            body = f"{layered}: {body}"  # "build-wall: 2 rows x 3 cubes, all gray": a wall said by its rows (it had been a grid)
        elif noun is not None:
            # "Line-Sort-Colour: red, orange, ...": the structure the label names; "stack-any-4: ..." with its count glued
            # to it (the count had been dropped, a stack of two made up) where the text says none
            glued = re.search(rf"(?i)\b{noun}(?:-[a-z]+)?-(\d+)\b", label)
            counted = glued and not re.search(r"\b\d+\b|\b(?:" + "|".join(lexicon.NUMBER_WORDS) + r")\b", body, re.IGNORECASE)
            if counted:
                body = f"{noun} of {glued.group(1)}: {body}"
            elif not re.search(STRUCTURE_RE, body, re.IGNORECASE):
                body = f"{noun}: {body}"
        schema = parse(body, _framed=True)
        return schema.model_copy(update={"instruction": instruction, "name": task_slug(instruction)})  # as written
    named = _named_heading(instruction, _framed)
    if named is not None:  # "Build it like a layer cake: a brown cube on the bottom, a white cube on that, ...": the body
        return named
    headed = _towers_headed(instruction, _framed)
    if headed is not None:  # "Build two towers of two cubes: yellow on orange in the back left corner, and white on gray ..."
        return headed
    scene = initial.split(instruction)  # "Initially red is on blue. Put ...": rho_0's stacks, then the goal
    if scene is not None and not scene.goal.strip(" ."):
        raise ParseError(f"\"{instruction[:80]}\" says how the cubes start but not where they must end up: a task's goal "
                         "is checked at the end of the episode; add it (e.g. \"... Put the red cube on the table.\")")
    if scene is not None:
        try:
            named = initial.with_start_cubes(scene)  # "Initially yellow is on red. Put both cubes side by side."
            return initial.attach(initial.on_table_goal(scene) or parse(named.goal), scene, instruction)
        except BadInput as exc:  # read as written below, where a reader may read the start itself ("... starts on ...;
            goal_gap = exc       # move it to the table"); a reading as written with no start is refused below
    schema = _read(instruction)
    claimed = initial.START_CLAIM_RE.search(instruction)
    if claimed and not schema.initial_state.structures:  # "starting from a row of red and blue, put red on blue"
        words = re.split(r"\s*[,;:(]\s*", instruction[claimed.start():].strip(" .;!?"))[0][:60]
        raise ParseError(f"\"{instruction[:80]}\": '{words}' says where the cubes start, and rpg reads no start there (rho_0 "
                         "starts only stacks of named cubes, and a goal must say where they end up, e.g. \"Starting from red on "
                         "blue, put red on the table.\"); or use --model")
    if scene is not None and not schema.initial_state.structures:
        # the start's "X is on Y" had become the goal ("Initially yellow is on white. Put both cubes on the table." had
        # compiled to yellow on white: silently wrong): refused as the goal alone is
        raise goal_gap
    return schema


_STACK_COMMAND_RE = re.compile(r"(?:^|[.;!?]\s*|,\s*|\band\s+|\bthen\s+)(?:(?:then|also|now|next)\s+)?stack\b(?!\s+(?:of|on)\b)")


def _stacks_merged(f: Features, schema: TaskSchema) -> ParseError | None:
    """A reading that makes one tower of the cubes of two stacking commands, each naming two cubes or more of its own
    and placing none on another ("Stack red and blue. Stack green and yellow.": a tower of four had been read, its
    order freed, silently): refused, since which cubes form which tower is said but not read."""
    starts = [m.end() for m in _STACK_COMMAND_RE.finditer(f.text)]
    if len(starts) < 2:
        return None
    parts = [f.text[a:b] for a, b in itertools.pairwise([*starts, len(f.text)])]
    own = [set(re.findall(rf"\b(?:{COLOR_RE})\b", p)) for p in parts]
    if sum(len(o) >= 2 and not re.search(r"\b(?:on|onto|atop|upon|above|under|below|it|that|them|top|bottom)\b", p)
           for o, p in zip(own, parts, strict=True)) < 2:
        return None
    towers = [p for p in schema.goal_predicate().walk() if isinstance(p, Stack)]
    colour = {a.name: a.color for a in schema.assets}
    if any(sum(bool(o & {colour.get(n) for n in t.objects}) for o in own if len(o) >= 2) >= 2 for t in towers):
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but each 'stack' there names its own "
                          "cubes; say each tower in a sentence of its own with the word tower (e.g. \"Build a tower of red "
                          "and blue. Build another tower of green and yellow.\"), or use --model")
    return None


def _read(instruction: str) -> TaskSchema:
    """``instruction`` read by the registered readers, the first whose reading accounts for every
    mention winning (see :func:`parse`, which reads frames and a stated start first)."""
    f = features(instruction)
    first_gap: ParseError | None = None
    for entry in registry.ordered():
        b = Builder(f.original)
        b.repairs = []
        if entry.read(f, b):
            try:
                schema = b.schema(task_slug(f.original))
            except ValidationError as exc:  # e.g. "the red block left of the red block"
                reason = str(exc.errors()[0]["msg"]).removeprefix("Value error, ")
                first_gap = first_gap or ParseError(f"read \"{f.original[:80]}\" as a task in which {reason}. "
                                                    "Rephrase (e.g. \"two red blocks\"), or use --model")
                continue
            schema.repairs = b.repairs
            gap = unaccounted(f, schema) or disjoint_regions(f, schema) or pronoun_cubes_made_up(f, schema)
            if gap is not None and (ended := line_with_ends(f, schema)) is not None and unaccounted(f, ended) is None:
                schema, gap = ended, None  # "a row of red, green and blue with red at the left end": that end, the rest free
            if gap is None:
                # reverse accounting: a part of G nobody stated is dropped where a weaker goal
                # exists (a tower's named end kept, the rest free); the rest is recorded as
                # uncited in task.yaml (not refused yet: the citations do not cover every
                # parameter a reader sets, such as a default count). A structure filled up with
                # cubes nobody named makes this reading fail (the next reader may do better)
                try:
                    read = one_colour_for_unnamed(f, citations.enforce(free_listed_orders(f, free_unnamed_orders(f, schema)),
                                                                       refuse=False))
                except citations.UncitedConstraint as exc:
                    gap = ParseError(f"\"{f.original[:80]}\": {exc}; or use --model")
                else:
                    merged = _stacks_merged(f, read)
                    if merged:
                        gap = merged
                    elif not (re.search(r"\bin any order\b", f.text) and any(type(p) is Stack or (isinstance(p, InLine) and p.order)
                                                                              or isinstance(p, Reads) for p in read.goal_predicate().walk())):
                        return read  # ("Spell CAB in a row, in any order", "a rainbow row, in any order": a word's or a
                        # rainbow's order is no free one; they had been read in order, the freedom dropped: a hostile helper's)
                    elif (anchored := any_order_with_ends(f, read)) is not None:
                        return anchored  # "any order is fine, but A must be at the bottom": that end fixed, the rest free
                    # "a tower of red, green and blue, doesn't matter which order, and put yellow to the left of it": the
                    # order said free and the tower read in order (the clause relating it had kept its list's order)
                    gap = ParseError(f"read \"{f.original[:80]}\" as: {read.goal_summary}; but 'in any order' leaves the order "
                                     "free and that task orders its cubes; say the ordered structure in a sentence of its own, or use --model")
            first_gap = first_gap or gap  # a reading that drops a mention: try the next reader
    if first_gap is not None:
        raise first_gap
    action = lexicon.NO_GOAL_RE.search(f.text)
    if action is not None:  # "pick up the orange block": an action, and nowhere for the cube to end
        said = lexicon.NO_GOAL_RE.search(f.original.lower()) or action  # the user's verb ("push"), not its reading
        verb = re.sub(r"\s.*(?:block|cube|box|one).*$", "", said.group(0).strip())  # "push the red block." -> push
        raise ParseError(f"\"{f.original[:80]}\" says no end state: '{verb}' is an action, and a task's goal "
                         "says where cubes end up (on, next to, in a line, on a patch...); say where the cube should go "
                         "(e.g. \"pick up the red block and put it on the blue block\"), or use --model")
    raise ParseError(
        f"could not find a task in \"{f.original[:80]}\": name a structure (tower, line, circle, grid, "
        "pyramid, piles), a relation (on, left of, behind...) or a goal (spell, sort, rotate); "
        "or use --model to let a language model read it"
    )
