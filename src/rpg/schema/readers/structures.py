"""Readers of structures: pyramids, blocks, walls, grids, circles, piles, lines and towers.

Each reader builds one structure kind of :mod:`rpg.schema.structures` (its ``recognizer``
names the reader) with the layout of :mod:`rpg.domain.layouts`.
"""

from __future__ import annotations

import itertools
import math
import re
from collections import Counter

from rpg.domain import constants as C
from rpg.domain.layouts import (
    circle_layout,
    circle_radius,
    cluster_layout,
    grid_layout,
    line_layout,
    pyramid_layout,
    stack_layout,
)
from rpg.domain.predicates import (
    Between,
    Bridge,
    Grid,
    InCircle,
    InLayers,
    InLine,
    InRegion,
    LayersUniform,
    Piles,
    Pyramid,
    Reads,
    SortedBy,
    Stack,
    UnorderedStack,
)
from rpg.schema import clauses, lexicon
from rpg.schema.builder import DEFAULT_COLORS, Builder
from rpg.schema.lexicon import (
    COLOR_RE,
    COUNT_WORD_RE,
    CUBE_ORDER_RE,
    LAYER_ORDINALS,
    LAYER_ROLE_RE,
    LAYER_WORDS,
    LISTED_ROW_LAYER,
    LISTED_ROW_RE,
    ORDER_WORDS,
    THIS_ORDER_RE,
    TOWER_NOUNS,
)
from rpg.schema.readers.common import (
    DESCRIBED_TOWER_RE,
    ITEM_RE,
    alternating_colors,
    asks_per_layer,
    colors_for,
    counted_groups,
    directed_line,
    direction_of,
    direction_stated,
    fill_structure,
    item_sequence,
    label_sequence,
    line_axis,
    line_axis_said,
    mark_references,
    material_of,
    ordering_of,
    outlier_count,
    refuse_towers_merged,
    region_spots,
    spectrum_of,
    spelled_word,
    stated_count,
    tower_order,
)
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, ParseError, canon_color, explicit_labels, mark_regions

THEN_LAYER_RE = re.compile(rf"\bthen\s+(?:(?P<n>\d+)\s+)?(?P<c>{COLOR_RE})\b")
"""A layer said after the one below it ("..., then 2 red, then 1 yellow")."""


def layer_roles(f: Features, levels: int) -> dict[tuple[str, int], int | None]:
    """The colours the text gives a layer of a structure ``levels`` layers high ("yellow on
    top", "3 red blocks at the base", "a blue base"): (colour, layer) -> cubes, layer 0 on the
    table, cubes None for the whole layer ("red blocks", "a red base") else how many ("a red
    block": 1, "2 green": 2).  A colour may stand in two layers ("two red cubes in the middle
    and one red cube on top").

    Raises:
        ParseError: one cube given two layers ("the red cube at the bottom and the red cube on
            top"), or "middle" of a structure that has no one middle layer (two layers, or more
            than three).
    """
    out: dict[tuple[str, int], int | None] = {}
    definite: set[str] = set()  # colours said as "the <colour> cube": one cube, so one layer
    for m in LAYER_ROLE_RE.finditer(f.text):
        i = next(k for k in range(5) if m.group(f"c{k}"))
        word = m.group(f"role{i}")
        role = LAYER_WORDS.get(word)
        if role == "middle" and levels != 3:
            raise ParseError(f"'{m.group(0)}': a structure {levels} layers high has no one middle layer; "
                             "say which layer (counted from the bottom)")
        k = LAYER_ORDINALS[word] if role is None else {"bottom": 0, "middle": 1, "top": levels - 1}[role]
        if k >= levels:
            raise ParseError(f"'{m.group(0)}': a structure {levels} layers high has no {word} layer")
        colors = [canon_color(c) for c in re.findall(COLOR_RE, m.group(f"c{i}"))]
        count = m.groupdict().get(f"n{i}") or m.groupdict().get(f"m{i}") or m.groupdict().get(f"k{i}")
        noun = m.groupdict().get(f"noun{i}") or ""
        n = int(count) if count and count.isdigit() and len(colors) == 1 else \
            1 if noun in ("block", "cube", "one") else None
        the = (m.groupdict().get(f"n{i}") == "the" and noun in ("block", "cube")) or (  # "the orange pair" (the 2 orange
            m.groupdict().get(f"n{i}") not in (None, "the", "a", "an", "one") and f.text[:m.start()].endswith("the "))  # blocks)
        repeated = n is None and 1 < len(set(colors)) < len(colors)  # "base orange, gray, orange": each listed cube, counted
        for color in dict.fromkeys(colors) if repeated else colors:
            if repeated:
                n = colors.count(color)
            placed = {lv for c, lv in out if c == color}
            if placed - {k} and (the or color in definite):
                raise ParseError(f"the {color} cube is given two layers in \"{f.original.strip()}\"")
            if the:
                definite.add(color)
            out[(color, k)] = n
    if out and {lv for _, lv in out} == {0}:  # "3 blue at the base then 2 red then 1 yellow": layer by layer
        for k, m in enumerate(THEN_LAYER_RE.finditer(f.text), start=1):
            color = canon_color(m.group("c"))
            if k >= levels or any(c == color for c, _ in out):
                break
            out[(color, k)] = int(m.group("n")) if m.group("n") else None
    return out


ALL_ONE_COLOR_RE = re.compile(rf"\b(?:all|every\s+(?:cube|block|one)|each\s+(?:cube|block|one))\s+(?:of\s+them\s+)?(?:is\s+|are\s+)?"
                              rf"(?P<c>{COLOR_RE})\b(?!\s+(?:(?:cubes?|blocks?|ones?)\s+)?(?:on|at|in|as|for)\b)")
"""A structure's every cube given one colour ("..., all purple", "every cube red"), not a layer's
("all purple cubes at the bottom")."""


def fill_layers(f: Features, b: Builder, sizes: list[int], roles: dict[tuple[str, int], int | None]) -> list[str]:
    """Cubes for a structure of layers ``sizes`` (bottom first) whose layers ``roles``
    (:func:`layer_roles`) names: each named colour in its layer, the other sites filled with
    the colours the text names for no layer (counted groups keep their counts; one colour
    fills them all), else with colours the task does not use.  Returns the names in site
    order (bottom layer first) and appends the :class:`InLayers` that judges the named ones.

    Raises:
        ParseError: more cubes named for a layer than it holds.
    """
    slots: list[list[str | None]] = []
    for k, size in enumerate(sizes):
        here = [(c, n) for (c, lv), n in roles.items() if lv == k]
        whole = [c for c, n in here if n is None]
        counted = sum(n for _, n in here if n is not None)
        share, rest = divmod(size - counted, len(whole)) if whole else (0, 0)
        if counted + len(whole) > size or rest:
            raise ParseError(f"the cubes named for layer {k + 1} from the bottom ({', '.join(c for c, _ in here)}) "
                             f"do not fill its {size} sites; say how many of each")
        cols: list[str | None] = [c for c, n in here if n is not None for _ in range(n)]
        cols += [c for c in whole for _ in range(share)] if whole else [None] * (size - counted)
        slots.append(cols)
    free = sum(c is None for layer in slots for c in layer)
    given = {c for c, _ in roles}
    groups = [(n, c) for n, c in counted_groups(f) if c not in given]
    listed = [c for c in dict.fromkeys(f.color_list()) if c not in given]
    every = ALL_ONE_COLOR_RE.search(f.text)
    if every and re.search(r"\b(?:top|bottom|base|middle|upper|lower|first|second|third)(?:\s+(?:row|layer|level|tier))?\s*$",
                           f.text[:every.start()]):
        every = None  # "top row all purple": a layer's colour (a role), not every cube's
    if every and any(c != canon_color(every.group("c")) for c in given):
        raise ParseError(f"\"{f.original[:80]}\" gives every cube one colour ('{every.group(0)}') and some cubes "
                         "another: a contradiction; say the colours once")
    if every and not listed:  # "four purple cubes at the bottom, then three, ..., all purple"
        listed = [canon_color(every.group("c"))]
    if groups and sum(n for n, _ in groups) == free:
        pool = [c for n, c in groups for _ in range(n)]
    elif len(listed) == 1:
        pool = listed * free
    elif listed:
        pool = [listed[i % len(listed)] for i in range(free)]
    else:
        pool = [c for c in DEFAULT_COLORS if c not in given][:free]
        pool += [pool[-1] if pool else "red"] * (free - len(pool))
    fill = iter(pool)
    names = [b.cube(c if c is not None else next(fill)) for layer in slots for c in layer]
    levels = [k if c is not None else -1 for k, layer in enumerate(slots) for c in layer]
    b.preds.append(InLayers(tuple(names), tuple(levels)))
    b.summary.append(b.preds[-1].describe())
    return names


BRIDGE_RE = re.compile(
    rf"(?:please\s+)?(?:put|place|set|stack|lay|balance|rest)\s+(?:the\s+|a\s+|an\s+|one\s+)?(?P<top>{COLOR_RE})\s+"
    r"(?:block|cube)\s+(?:on\s+top\s+of|on|onto|atop|across|over|upon)\s+(?:both\s+)?(?:the\s+)?"
    rf"(?P<a>{COLOR_RE})\s+and\s+(?:the\s+)?(?P<b>{COLOR_RE})\s+(?:blocks|cubes)\s*[.!]?")
"""One cube put on two others at once ("put the yellow block on the red and green blocks"):
it rests on both, so the two stand side by side under it (a pyramid with a base of 2)."""


@reader(order=25)
def recognize_bridge(f: Features, b: Builder) -> bool:
    """A cube resting on two named cubes at once: a 2D pyramid with a base of 2 whose layers
    are judged (:class:`InLayers`: the two named below, the one named on top)."""
    m = BRIDGE_RE.fullmatch(f.text)
    if m is None:
        return False
    top, a, c = (canon_color(m.group(k)) for k in ("top", "a", "b"))
    names = [b.cube(a), b.cube(c), b.cube(top)]
    b.place(pyramid_layout(names, 2, 2))
    b.preds += [Bridge(tuple(names)), InLayers(tuple(names), (0, 0, 1))]
    b.primitives += ["stack"]
    b.summary.append(f"{names[2]} resting on both {names[0]} and {names[1]}, side by side")
    return True


_ONE_ON_TOP_RE = re.compile(r"\b(?:1|one|a|an|single)\s+(?:[a-z]+\s+){0,2}?(?:(?:cube|block|one)\s+)?(?:(?:is|goes|sits|sitting|placed|resting)\s+)?"
                            r"(?:on\s+(?:the\s+)?top|at\s+the\s+(?:very\s+)?(?:top|apex|peak|tip|summit)|as\s+the\s+(?:top|apex|peak))\b"
                            r"|\b(?:top|upper)\s+(?:layer|level|row|tier)\s*(?::|is|=)?\s*(?:the\s+)?[a-z]+(?:\s+(?:cube|block))?\s*(?:[.;]|$)")
_LAYERS_BETWEEN_SAID_RE = re.compile(r"\b(?:middle|second|2nd|third|3rd|between)\b|\b\d+[\s-]+(?:layers?|levels?|tiers?|rows?|stor(?:y|ey|ies|eys))\b"
                                     r"|\b(?:6|10|15)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b|\bpyramid\s+of\s+(?:6|10|15)\b|\b\d+-\d+-\d+\b"
                                     r"|\bthen\s+\d+\b|\b2\s+[a-z]+")


_BASE_SAID_RE = re.compile(r"\b\d\s+(?!(?:wide|across|long)\b)(?:[a-z]+\s+){0,2}?(?:(?:block|cube)s?\s+)?(?:[a-z]+\s+)?(?:on|at|as|in|forming|form)\s+(?:the\s+)?"
                           r"(?:base|bottom)\b|\b(?:base|bottom)(?:\s+(?:layer|row|level|tier))?\s*(?:is\s+|are\s+|of\s+|:\s*)?(?:\d+\s+(?:[a-z]+\s+)?"
                           rf"(?:cubes|blocks)\s*)?[(:,\-]?\s*(?:the\s+)?(?:{COLOR_RE})\s*(?:,|and\b)")
"""A pyramid's base said as the cubes that stand in it ("three cubes on the bottom", "3 red cubes at the base", "whose
base is three cubes (pink, orange, cyan)", "bottom layer pink, orange, cyan"), not its size ("a base of 3": a pyramid of
that size, whose layers a reader knows)."""


_LAYER_ROLE_SAID_RE = re.compile(r"\b(?:bottom|top|apex|peak|summit|tip|middle|foundation|upper|lower|highest|lowest)\b"
                                 r"|\b(?:on|at|in|as)\s+(?:the\s+)?base\b|\bbase\s+(?:layer|row|level|tier)s?\b"
                                 r"|\b(?:first|second|third|fourth|next|last|each|every|other)\s+(?:layer|row|level|tier)s?\b")
"""A layer of a pyramid given a cube ("B and A on the bottom", "C at the apex", "the top layer", "A goes up top"); a base
said by its size ("with a 3x3 base", "a base of 3") or a count of layers is none.  Refused only with a label, a rank or
an order said as well (layers said by their counts alone, "base is 3 horizontal blocks, two blocks as middle layers and
one block on top", a paper session's, are sizes)."""


def _truncated_layers(f: Features, base: int, dims: int, roles: dict) -> int | None:
    """The number of layers of a pyramid said as its bottom layer and the one above it, each by its count of cubes of each
    colour, and nothing above ("three red cubes on the bottom layer and two white cubes on the layer above them", "three
    red on the bottom and two white on top"): 2, the pyramid those layers make (its peak had been made up in a colour
    nobody said, or the second layer's cubes refused as more than the peak holds).  None where the text says a layer
    between or above them, a peak, a total or a height, or names a colour neither layer holds."""
    if dims != 2 or base < 3 or not roles or any(n is None for n in roles.values()):
        return None
    total = stated_count(f, default=None)  # (a count of one layer's cubes may be read as the total: "three red cubes")
    if total not in (None, base, 2 * base - 1) or _TRUNCATED_BLOCKER_RE.search(f.text):
        return None
    roled = sum(len(_CUBE_NOUN_RE.findall(m.group(0))) for m in LAYER_ROLE_RE.finditer(f.text))
    counted = re.sub(r"\bpyramid\s+(?:of|with)\s+\d+\s+(?:cubes|blocks)\b", " ", f.text)  # "a pyramid of five cubes: ..."
    if len(_CUBE_NOUN_RE.findall(counted)) > roled:
        return None  # "..., and one cube at the very top", "then a single cube": a cube said beyond the two layers
    levels = {level for _, level in roles}
    upper = levels - {0}
    if 0 not in levels or len(upper) != 1 or next(iter(upper)) not in (1, base - 1):
        return None
    per_level = Counter()
    for (_, level), n in roles.items():
        per_level[0 if level == 0 else 1] += n
    if per_level[0] != base or per_level[1] != base - 1:
        return None
    if set(f.color_list()) - {c for c, _ in roles}:
        return None
    return 2


def _place_layered_pyramid(b: Builder, names: list[str], base: int, layers: tuple[int, ...], summary: str) -> None:
    """Place a 2D pyramid of the given ``layers`` (cubes per layer, bottom first; ``names`` in site order) and record its
    goal and summary: the readings of a pyramid said by some of its layers (:func:`_skipped_layers`,
    :func:`_truncated_layers`)."""
    b.place(pyramid_layout(names, base, 2, layers=layers))
    b.preds.insert(0, Pyramid(tuple(names), base=base, dims=2, layers=layers))
    b.primitives += ["stack"]
    b.summary.insert(0, summary)


_TRUNCATED_BLOCKER_RE = re.compile(r"\b(?:middle|third|fourth|peak|apex|summit|tip|crown\w*|capstone|point|topp\w*"
                                   r"|highest|height|tall|high|tier\w*|stor(?:y|ey|ies|eys)|3d|three-d\w*|proper|full|complete|whole"
                                   r"|single|more|another|add\w*|then|finish\w*|ending|ends?|up\s+to\s+you|any|rest|remaining|others?)\b")
"""What keeps a pyramid said by two layers from being read as those two alone (:func:`_truncated_layers`): a layer between
or above them, a peak or a topper, a height, a whole pyramid ("proper", "3D"), a cube
added after them ("then", "one more", "the highest is up to you") (a hostile helper's)."""
_CUBE_NOUN_RE = re.compile(r"\b(?:cubes?|blocks?|bricks?|ones?)\b")
"""A noun for cubes, counted by :func:`_truncated_layers` inside and outside the layers said."""


def _skipped_layers(f: Features, base: int, dims: int, roles: dict) -> bool:
    """Whether a pyramid is said as a base of three or more (its colours or its count) and one cube on top with nothing
    of the layers between ("a pyramid whose base is pink, orange and cyan with a white cube at the apex", "three cubes on
    the bottom and one on top"): the layers said are the pyramid's (:func:`_layered_pyramid`; a middle layer had been made
    up).  A pyramid whose base is not said ("a pyramid with a red cube on top") keeps the default size."""
    levels = {level for _, level in roles}
    two_said = re.sub(r"\b(?:2|two)[\s-]+(?:layers?|levels?|tiers?|stor(?:y|ey|ies|eys))\b", " ", f.text)  # "a two-level pyramid"
    if dims != 2 or base < 3 or _LAYERS_BETWEEN_SAID_RE.search(two_said) or any(0 < level < base - 1 for level in levels):
        return False
    if two_said != f.text:
        return bool(_ONE_ON_TOP_RE.search(f.text))
    ends_said = {0, base - 1} <= levels  # "pink, orange and cyan on the bottom and red on top": both ends' colours
    # a base said by its cubes, not its size ("a base of 3 and 1 red cube on top"), nor unsaid ("a red cube on top")
    base_said = 0 in levels or _BASE_SAID_RE.search(f.text)
    return bool(ends_said or (base_said and _ONE_ON_TOP_RE.search(f.text)))


_BASE_LIST = rf"(?P<list>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+)"
_LISTED_BASE_RE = re.compile(
    rf"\b(?:base|bottom)(?:\s+(?:layer|row|level|tier))?\s*(?:is\s+|are\s+|:\s*|of\s+)?(?:\d+\s+(?:cubes|blocks)\s*)?\(?\s*{_BASE_LIST}"
    r"\s*\)?(?!\s*(?:cubes|blocks|ones|on|at|in|as)\b)"
    rf"|{_BASE_LIST.replace('list', 'list2')}\s+(?:(?:cubes|blocks)\s+)?(?:on|at|as|in|forming|form)\s+(?:the\s+)?(?:bottom|base)\b"
    rf"|\b(?:on|at|as|in)\s+(?:the\s+)?(?:bottom|base)(?:\s+(?:layer|row|level|tier))?\s*(?:\(\s*{_BASE_LIST.replace('list', 'list3')}\s*\)"
    rf"|,\s*{_BASE_LIST.replace('list', 'list4')}\s*,)"  # "three cubes on the bottom, red, green and blue, and ..."
    rf"|{_BASE_LIST.replace('list', 'list5')}\s+(?:(?:cubes|blocks)\s+)?(?:below|under|underneath|beneath)\s+(?:it|them)\b"
    rf"|\bthe\s+(?:bottom|base)(?:\s+(?:layer|row|level|tier))?\s+(?:has|holds|gets|is\s+made\s+of|consists\s+of)\s+"
    rf"{_BASE_LIST.replace('list', 'list6')}")
"""A pyramid's bottom layer said cube by cube ("bottom layer purple, purple, brown", "green, green and orange on the
bottom", "three cubes on the bottom (red, green, blue)"): one cube per colour said."""


_ONE_COLOURED_TOP_RE = re.compile(rf"\b(?:a|an|one|1|single)(?:\s+(?:1|single))?\s+(?P<c>{COLOR_RE})\s+(?:cube|block|one)\s+"
                                  r"(?:on\s+top|at\s+the\s+(?:very\s+)?(?:top|apex|peak|tip|summit))\b")
"""One cube of a colour said on top of a pyramid ("and a single yellow cube on top of them")."""


def listed_base(text: str) -> list[str] | None:
    """The colours of a pyramid's bottom layer said cube by cube (:data:`_LISTED_BASE_RE`), or None."""
    m = _LISTED_BASE_RE.search(text)
    if m is None:
        return None
    said = next(m.group(g) for g in ("list", "list2", "list3", "list4", "list5", "list6") if m.group(g))
    return [canon_color(c) for c in re.findall(COLOR_RE, said)]


def _layered_pyramid(f: Features, b: Builder, base: int, counted: bool) -> list[str]:
    """Cubes of a 2D pyramid of two layers, ``base`` cubes under one on top (:func:`_skipped_layers`): the base's cubes
    as listed or counted, the top's colour if said, any cube nobody names a colour the task does not use; each named
    one judged in its layer (:class:`InLayers`, appended by :func:`fill_layers`).

    Raises:
        ParseError: the base's size said neither by a count (``counted``) nor by its cubes one by one, more than one
            cube named for the top, a colour said more often than the layers hold it ("sitting on the red and green
            cubes"), or a colour said that neither layer holds (which cube is it?).
    """
    roles = layer_roles(f, 2)
    listed = listed_base(f.text)
    tops = {(c, lv): n for (c, lv), n in roles.items() if lv == 1}
    top = _ONE_COLOURED_TOP_RE.search(f.text)
    if not tops and top:  # "and a single yellow cube on top of them"
        tops = {(canon_color(top.group("c")), 1): 1}
    if listed is not None:
        bottom = {(c, 0): listed.count(c) for c in dict.fromkeys(listed)}
    else:
        bottom = {(c, lv): n for (c, lv), n in roles.items() if lv == 0}
    said = sum(n for n in bottom.values() if n is not None)
    if (None in bottom.values() or said not in (0, base)) or (not counted and said != base):
        raise ParseError(f"\"{f.original[:80]}\" names a pyramid's base and one cube on top but not how many cubes of "
                         "each colour the base has; say them (e.g. \"three cubes on the bottom: red, green and blue, and a "
                         "yellow cube on top\"), or use --model")
    if sum(n or 1 for n in tops.values()) > 1:
        raise ParseError(f"\"{f.original[:80]}\" puts more than one cube on top of a pyramid with no layer between; say "
                         "each layer, or use --model")
    placed = {c for c, _ in bottom} | {c for c, _ in tops}
    mentions = len(re.findall(rf"\b(?:{COLOR_RE})\b", f.text))
    if mentions > (len(listed) if listed is not None else len(bottom)) + len(tops):
        # "... and a yellow cube on top, sitting on the red and green cubes": more said of the cubes than the two layers
        raise ParseError(f"\"{f.original[:80]}\" says more of a pyramid's cubes than its two layers (a base and one cube on "
                         "top); say each layer once, or use --model")
    stray = [c for c in dict.fromkeys(f.color_list()) if c not in placed]
    if stray:
        raise ParseError(f"\"{f.original[:80]}\" names {', '.join(stray)} for a pyramid of a base and one cube on top, "
                         "but neither layer as read holds it; say each layer's cubes, or use --model")
    return fill_layers(f, b, [base, 1], {**bottom, **{k: 1 for k in tops}})


def _refuse_made_up_layer_cubes(f: Features, b: Builder) -> None:
    """Refuse a pyramid whose base is said cube by cube (:func:`listed_base`) and that holds more cubes of a colour than
    the text says, every mention of it a single cube ("three cubes on the bottom (red, green, blue) and one yellow cube
    above them", "blue, green and pink on the bottom, red on top, and orange in the middle"): the upper layers' cubes
    would be made up of the colours said (a second green and red had been invented, one orange said had made two); or
    whose layers, said, were not read at all (their order had been dropped)."""
    if listed_base(f.text) is None:
        return
    if not any(isinstance(p, InLayers) for p in b.preds):  # the layers said, none read ("the second layer has ...")
        raise ParseError(f"\"{f.original[:80]}\" says a pyramid layer by layer, and the builtin parser did not read which "
                         "cubes stand in which layer; say them as \"bottom layer ...; middle layer ...; top layer ...\", or use "
                         "--model")
    built = Counter(a.color for a in b.assets if a.kind != "goal_patch")
    unsaid = [c for c in built if not re.search(rf"\b{c}\b", f.text)]
    if unsaid:  # "bottom row orange, orange, orange; middle row pink, pink.": a red top made up
        raise ParseError(f"\"{f.original[:80]}\" lists a pyramid's cubes layer by layer but not all its layers: its "
                         f"{', '.join(unsaid)} cube{'s' if len(unsaid) > 1 else ''} would be made up; say each layer's cubes, "
                         "or use --model")
    for c, n in built.items():
        said = list(re.finditer(rf"\b{c}\b", f.text))
        counted = any(re.search(rf"\b(?:\d+|{COUNT_WORD_RE}|all|every|only)\s+(?:[a-z]+\s+)?$", f.text[:m.start()])
                      or re.match(r"\s+(?:[a-z]+\s+)?(?:cubes|blocks|ones)\b", f.text[m.end():]) for m in said)
        if said and not counted and n > len(said):
            raise ParseError(f"\"{f.original[:80]}\" says {len(said)} {c} cube{'s' if len(said) > 1 else ''} and the pyramid "
                             f"it lists needs {n}: the layers above its base are not all said; say each layer's cubes (e.g. "
                             "\"... two white cubes in the middle and a yellow cube on top\"), or use --model")


def _label_pyramid(f: Features, b: Builder) -> bool:
    """Read a 2D pyramid of label cubes (:data:`lexicon.LABEL_TOKEN`), none coloured: "a pyramid of the letter cubes A, B
    and C" (any cube in any site), "the 5, 6 and 7 cubes into a pyramid with 7 at the top", "A and B on the bottom, C at
    the apex", "the digit cubes 2, 4 and 6 at the base and 8 at the top" (a base of three and one cube on top, the layers
    :func:`_skipped_layers` reads for colours).  The layers said (:data:`lexicon.LABEL_LAYER_ROLE_RES`) are judged by an
    :class:`InLayers`; labels said for no layer fill the one layer that has sites left.  Returns False where the text
    names no label cube or a colour as well (left to the other readers).

    Raises:
        ParseError: letters and digits mixed, a label given two layers, a count said that the labels do not make, the
            labels said for no layer spread over several layers, a layer given more labels than it holds, or a number of
            labels no pyramid has (3, 6 or 10; or a base and one cube on top)."""
    text = f.original
    if re.search(rf"\b(?:{COLOR_RE})\b", f.text) or re.search(r"\b\d+x\d+\b", f.text):
        return False
    tokens = [m for m in re.finditer(lexicon.LABEL_TOKEN, text)
              if not (m.group(0).isdigit() and lexicon.LABEL_COUNT_AFTER_RE.match(text[m.end():]))
              and not (m.group(0) in ("A", "I") and lexicon.LABEL_ARTICLE_AFTER_RE.match(text[m.end():]))]
    labels = list(dict.fromkeys(m.group(0) for m in tokens))
    if len(labels) < 3:
        return False
    if labels[0].isdigit() and not (explicit_labels(f) or f.has("digit", "digits", "number", "numbers", "label", "labels")):
        return False  # "a pyramid 3 2 1": counts, not digit cubes named
    if len({lab.isdigit() for lab in labels}) > 1:
        raise ParseError(f"\"{f.original[:80]}\" mixes letter and digit cubes in a pyramid; say which cubes, or use --model")
    roles: dict[str, str] = {}
    rest = text  # the text but for the layer roles read: whatever else it says of the cubes is no reader's
    for pattern in lexicon.LABEL_LAYER_ROLE_RES:
        for m in pattern.finditer(text):
            layer = lexicon.LAYER_WORDS[m.group("r")]
            for lab in re.findall(lexicon.LABEL_TOKEN, m.group("l")):
                if roles.get(lab, layer) != layer:
                    raise ParseError(f"the cube {lab} is given two layers in \"{f.original[:80]}\"; say each cube's layer "
                                     "once, or use --model")
                roles[lab] = layer
        rest = pattern.sub(" ", rest)
    related = lexicon.LABEL_RELATED_RE.search(rest) or lexicon.LABEL_PYRAMID_UNREAD_RE.search(
        re.sub(r"@region_\w+", " ", mark_regions(rest.lower())))
    if related or ordering_of(f) or lexicon.LABEL_PYRAMID_ORDER_RE.search(f.text):
        # "with 3 on top of 1", "sorted ascending": more than the layers (it had been dropped)
        raise ParseError(f"\"{f.original[:80]}\" says more of a pyramid's label cubes than the layers they stand in "
                         f"({related.group(0) if related else 'an order'}), which the builtin parser does not read; say each "
                         "layer's cubes, or use --model")
    n = len(labels)
    said = stated_count(f, default=None)
    free = [lab for lab in labels if lab not in roles]
    bottom = [lab for lab in labels if roles.get(lab) == "bottom"]
    top = [lab for lab in labels if roles.get(lab) == "top"]
    base = next((k for k in range(2, 5) if k * (k + 1) // 2 == n), None)
    if base is None and not free and len(top) == 1 and len(bottom) == n - 1 >= 3:
        sizes = [n - 1, 1]  # "2, 4 and 6 at the base and 8 at the top": those two layers
    elif base is not None:
        sizes = [base - k for k in range(base)]
    else:
        raise ParseError(f"\"{f.original[:80]}\" names {n} label cubes for a pyramid, and a pyramid of cubes, each layer "
                         "one shorter, has 3, 6 or 10; say its layers (e.g. \"A and B on the bottom, C on top\"), or use --model")
    if said is not None and said != n:
        raise ParseError(f"\"{f.original[:80]}\" says {said} cubes and names {n} label cubes for its pyramid; say each "
                         "cube once, or use --model")
    index = {"bottom": 0, "top": len(sizes) - 1, "middle": 1 if len(sizes) == 3 else None}
    layers: list[list[str]] = [[] for _ in sizes]
    for lab in labels:
        if lab in roles:
            k = index[roles[lab]]
            if k is None:
                raise ParseError(f"the cube {lab} is put in the middle of a pyramid {len(sizes)} layers high, which has no "
                                 "one middle layer; say which layer, or use --model")
            layers[k].append(lab)
    if any(len(layer) > size for layer, size in zip(layers, sizes, strict=True)):
        raise ParseError(f"\"{f.original[:80]}\" gives a pyramid's layer more label cubes than it holds; say each layer's "
                         "cubes, or use --model")
    open_layers = [k for k, size in enumerate(sizes) if len(layers[k]) < size]
    if roles and free and len(open_layers) > 1:
        raise ParseError(f"\"{f.original[:80]}\" says the layers of some of a pyramid's cubes but not of {', '.join(free)}, "
                         "which could stand in more than one layer; say each layer's cubes, or use --model")
    if roles and free:
        layers[open_layers[0]].extend(free)
    ordered = [lab for layer in layers for lab in layer] if roles else labels
    names = [b.semantic(lab) for lab in ordered]
    skipped = tuple(sizes) if len(sizes) == 2 and sizes[0] > 2 else ()
    b.place(pyramid_layout(names, sizes[0], 2, layers=skipped))
    if roles:
        b.preds.append(InLayers(tuple(names), tuple(k for k, layer in enumerate(layers) for _ in layer)))
        b.summary.append(b.preds[-1].describe())
    b.preds.insert(0, Pyramid(tuple(names), base=sizes[0], dims=2, layers=skipped) if skipped
                   else Pyramid(tuple(names), base=sizes[0], dims=2))
    b.primitives += ["stack"]
    b.summary.insert(0, f"a 2D pyramid of the label cubes {', '.join(ordered)} ({' under '.join(map(str, sizes))})")
    return True


@reader(order=100)
def recognize_pyramid(f: Features, b: Builder) -> bool:
    if not f.has("pyramid", "pyramids", "triangle", "triangular"):
        return False
    several = re.search(rf"\b(?:(?:\d+|{COUNT_WORD_RE}|several|some|a\s+(?:pair|couple)\s+of)\s+(?:[a-z]+\s+)?pyramids|pyramids)\b", f.text)
    if several:  # "Build two pyramids: bottom row ...": the builtin parser builds one (one had been built)
        raise ParseError(f"'{several.group(0)}' in \"{f.original[:80]}\" asks for more than one pyramid; the builtin parser "
                         "builds one pyramid a task; say one, or use --model")
    if not f.has("pyramid", "pyramids", "stack", "stacked", "stacking", "tower", "layer", "layers", "level", "levels",
                 "base", "bottom", "top", "on top", "tier", "tiers", "vertical", "upright"):
        raise ParseError(f"'triangle' in \"{f.original[:80]}\" names no one shape: a pyramid (a layer of cubes on a wider "
                         "one) or cubes at the corners of a triangle on the table, which rpg does not build; say which (e.g. \"a pyramid of 3 blocks\"), or use --model")
    if _label_pyramid(f, b):
        return True
    dims_m = re.search(r"\b(\d+)x(\d+)\b", f.text)
    if dims_m:
        base, dims = int(dims_m.group(1)), 3
    else:
        m = re.search(r"(?:base|bottom\s+(?:layer|level|tier))\s+(?:of\s+|is\s+|with\s+|has\s+)?(\d+)", f.text) or re.search(r"(\d+)\s+(?:[a-z]+\s+){0,2}?(?:(?:block|cube)s?\s+)?(?:(?:go|goes|sit|sits|are|stand|must\s+be|should\s+be)\s+)?(?:on|at|as|in)\s+(?:the\s+)?(?:base|bottom)\b", f.text)
        layers = re.search(r"\b(\d+)\s+(?:layers?|levels?|tiers?|stor(?:y|ey|ies|eys))\b", f.text)
        m = m or layers
        total = stated_count(f, default=None)
        from_total = next((k for k in range(2, 8) if k * (k + 1) // 2 == total), None) if total else None
        size = 2 if f.has("small", "little", "tiny", "mini") else 4 if f.has("big", "large", "tall", "huge") else 3
        named = len(set(f.color_list()))  # "the red, green and blue blocks in a triangle": 3 cubes
        from_named = next((k for k in range(2, 8) if k * (k + 1) // 2 == named), None) if named >= 3 else None
        middle = any("middle" in m_.group(0) for m_ in LAYER_ROLE_RE.finditer(f.text))
        said = re.search(r"\bpyramid\s+(?:of|from|using|made\s+of)\s+(\d+)\b(?!\s+(?:[a-z]+\s+)?(?:blocks?|cubes?)\s+(?:on|at|in|as|with)\b)",
                         f.text)
        if said and total == int(said.group(1)) and from_total is None and not m:  # "a pyramid of four": none has four
            raise ParseError(f"a pyramid of {total} cubes: a pyramid of cubes, each layer one shorter, has 3, 6, 10 or 15; "
                             "say one of those, or its base (e.g. \"a pyramid with a base of 3\")")
        listed = listed_base(f.text)  # "bottom layer purple, purple, brown; top layer blue": a base of 3
        base, dims = (int(m.group(1)) if m else (len(listed) if listed and len(listed) >= 2 else None) or from_total
                      or (3 if middle else from_named) or size), 2
    if base < 2:
        raise ParseError("a pyramid needs a base of at least 2")
    n = sum((base - k) ** (dims - 1) for k in range(base))
    if not dims_m and not m and not listed and not from_total and named >= 3 and n > named and from_named is None \
            and not re.search(rf"\b(?:{COLOR_RE})\s+(?:and\s+(?:{COLOR_RE})\s+)?(?:blocks|cubes|bricks|ones)\b", f.text):
        # "a pyramid of red, blue and green with yellow on top": four cubes said one by one, which no pyramid has (a base
        # of 3 had been built, its middle layer of colours nobody named)
        raise ParseError(f"\"{f.original[:80]}\" names {named} cubes for a pyramid, and a pyramid of cubes, each layer "
                         "one shorter, has 3, 6, 10 or 15; say its base (e.g. \"a pyramid with a base of 3\") and which cubes go "
                         "where, or use --model")
    if n > C.MAX_OBJECTS:
        raise ParseError(f"a pyramid with base {base} needs {n} cubes; the most a task holds is {C.MAX_OBJECTS}")
    material = material_of(f)
    order = ordering_of(f)
    sizes = [(base - k) ** (dims - 1) for k in range(base)]
    roles = layer_roles(f, base) if material == "colors" else {}
    if material != "colors" and _LAYER_ROLE_SAID_RE.search(f.text) and re.search(
            r"(?<![\w'])(?-i:[A-Z])(?![\w'])|(?<![\w.])\d(?![\w.])(?!\s+(?:[a-z]+\s+)?(?:blocks?|cubes?|layers?|levels?|rows?|tiers?|high|wide)\b)"
            r"|\b(?:smallest|largest|biggest|highest|lowest|first|last)\b", f.original):
        # "Pyramid of three: the letter cubes B and A on the bottom, the letter C cube at the apex": layers of label cubes,
        # which no reader judges (their layers had been dropped: any cube at the apex passed)
        raise ParseError(f"\"{f.original[:80]}\" puts label cubes in a pyramid's layers, which the builtin parser does not read; "
                         "say the pyramid with coloured cubes, or use --model")
    kept = _truncated_layers(f, base, dims, roles) if material == "colors" else None
    if kept:  # "three red cubes on the bottom layer and two white cubes on the layer above": those two layers, no peak
        sizes = sizes[:kept]
        said = {(c, kept - 1 if level == base - 1 else level): n for (c, level), n in roles.items()}
        _place_layered_pyramid(b, fill_layers(f, b, sizes, said), base, tuple(sizes),
                               f"a 2D pyramid of {' under '.join(map(str, sizes))} cubes, no layer above ({sum(sizes)} cubes)")
        return True
    if material == "colors" and _skipped_layers(f, base, dims, roles):
        # "three cubes on the bottom (red, green, blue) and a yellow cube on top": those two layers, the top cube
        # centred over the base
        _place_layered_pyramid(b, _layered_pyramid(f, b, base, counted=bool(dims_m or m)), base, (base, 1),
                               f"a 2D pyramid of {base} cubes under 1 on top ({base + 1} cubes)")
        return True
    if roles:
        names = fill_layers(f, b, sizes, roles)
        b.place(pyramid_layout(names, base, dims))
        if asks_per_layer(f):
            b.preds.append(LayersUniform(tuple(names), by="color", axis="z"))
            b.summary.append("each layer a different color")
    elif material == "colors" and asks_per_layer(f):
        sizes = [(base - k) ** (dims - 1) for k in range(base)]
        cols = colors_for(base, f, prefer=list(dict.fromkeys(f.color_list())))
        names = [b.cube(cols[k]) for k, size in enumerate(sizes) for _ in range(size)]
        b.place(pyramid_layout(names, base, dims))
        b.preds.append(LayersUniform(tuple(names), by="color", axis="z"))
        b.summary.append("each layer a different color")
    else:
        # a 2D pyramid stands in the plane facing the camera: each layer covers the up faces of
        # the one below, so its labels show on the front faces
        fill_structure(f, b, n, material, order, lambda names: pyramid_layout(names, base, dims),
                        face="front" if dims == 2 else "up")
    names = [a.name for a in b.assets]
    if not roles and material == "colors" and order and order[0] == "color" and len(set(f.color_list())) != 1:
        # "a pyramid of 3-2-1 with rainbow colored ordering": the colours layer by layer, bottom first
        b.preds.append(InLayers(tuple(names), tuple(k for k, size in enumerate(sizes) for _ in range(size))))
        b.summary.append(b.preds[-1].describe())
    _refuse_made_up_layer_cubes(f, b)
    b.preds.insert(0, Pyramid(tuple(names), base=base, dims=dims))
    b.primitives += ["stack"]
    shape = f"{base}x{base}" if dims == 3 else str(base)
    b.summary.insert(0, f"a {dims}D pyramid with a base of {shape} ({n} cubes)")
    return True


@reader(order=110)
def recognize_cube_block(f: Features, b: Builder) -> bool:
    m = re.search(r"\b(\d+)x(\d+)x(\d+)\b", f.text)
    if not m:
        return False
    r, c, layers = (int(g) for g in m.groups())
    _lattice(f, b, r, c, layers, f"a {r}x{c}x{layers} block of {r * c * layers} cubes")
    return True


WALL_DIMS = (3, 2)
"""Width and height of a wall when the instruction gives neither, cubes."""


@reader(order=120)
def recognize_wall(f: Features, b: Builder) -> bool:
    """A wall: one row of cubes ``width`` long (left to right) and ``height`` layers high
    ("a wall three blocks wide and two high", "a 4x2 wall", "a wall of six blocks"), or
    layers listed cube by cube (:func:`listed_layers`)."""
    if not f.has("wall"):
        return False
    rows = listed_layers(f)
    if rows is not None:
        width, height = len(rows[0]), len(rows)
        names = [b.cube(c) for row in rows for c in row]
        levels = tuple(k for k, row in enumerate(rows) for _ in row)
        b.place(grid_layout(names, 1, width, height))
        b.preds += [Grid(tuple(names), 1, width, height), InLayers(tuple(names), levels)]
        b.primitives += ["stack"]
        b.summary += [f"a wall {width} cubes wide and {height} high ({width * height} cubes)", b.preds[-1].describe()]
        return True
    wide = re.search(r"\b(\d+)\s+(?:blocks?\s+|cubes?\s+)?(?:wide|long|across)\b", f.text)
    high = re.search(r"\b(\d+)\s+(?:blocks?\s+|cubes?\s+|layers?\s+|rows?\s+|levels?\s+)?(?:high|tall)\b", f.text) or \
        re.search(r"\b(\d+)\s+(?:layers|rows|levels|tiers|courses)\b(?!\s+of\b)", f.text)  # "a wall with 3 layers"
    dims = re.search(r"\b(\d+)x(\d+)\b", f.text)
    rows = re.search(r"\b(\d+)\s+(?:rows|layers|levels)\s+of\s+(\d+)\b", f.text)  # "two rows of four"
    if rows and not dims:
        dims = re.search(r"(\d+)x(\d+)", f"{rows.group(2)}x{rows.group(1)}")
    if dims and not (wide or high or rows) and int(dims.group(1)) == 2 != int(dims.group(2)) and _only_two_rows_said(f):
        dims = re.search(r"(\d+)x(\d+)", f"{dims.group(2)}x{dims.group(1)}")  # "a 2x3 wall: bottom row orange, top row yellow"
    width = int(wide.group(1)) if wide else (int(dims.group(1)) if dims else None)
    height = int(high.group(1)) if high else (int(dims.group(2)) if dims else None)
    count = re.search(r"\b(\d+)\s+(?:[a-z]+\s+)?(?:blocks|cubes)\b(?!\s+(?:wide|long|across|high|tall))", f.text)
    if rows and count and rows.start() <= count.start() < rows.end():
        count = None  # "2 rows of 4 blocks": the 4 is a row's, not the wall's
    total = int(count.group(1)) if count else None
    rows_said = _counted_layers(f, height or WALL_DIMS[1]) if material_of(f) == "colors" else None
    if width is None and rows_said:  # "bottom row 3 gray blocks, top row 3 brown blocks"
        width, height, total = rows_said[0], height or len(rows_said), sum(rows_said)
    elif rows_said and len(rows_said) > 1:  # "3 wide and 3 high: three red cubes in the bottom row, ...": the rows' counts
        total = sum(rows_said)  # together (the first had been read as the wall's)
    if width is None and height is None:
        height = WALL_DIMS[1]
        width = max(2, total // height) if total else WALL_DIMS[0]
    elif width is None:
        width = max(2, total // height) if total and total > height else WALL_DIMS[0]
    elif height is None:
        height = max(1, total // width) if total and total > width else WALL_DIMS[1]
    if total and total != width * height and (wide or high or dims):
        raise ParseError(f"a wall {width} wide and {height} high has {width * height} cubes, not {total}")
    _lattice(f, b, 1, width, height, f"a wall {width} cubes wide and {height} high ({width * height} cubes)")
    return True


def _only_two_rows_said(f: Features) -> bool:
    """Whether a wall's text gives a bottom row and a top row and no row between them ("bottom row orange, top row
    yellow"): a size "2x3" is then two rows of three (read as two wide and three high, a middle row nobody named had
    been made up)."""
    said = set(re.findall(r"\b(bottom|lower|top|upper|middle|second|third|centre|center)\s+(?:row|layer|level|tier|course)\b", f.text))
    return bool(said & {"bottom", "lower"}) and bool(said & {"top", "upper"}) and not said - {"bottom", "lower", "top", "upper"}


def listed_layers(f: Features) -> list[list[str]] | None:
    """The colours of each layer, bottom first, when the text lists every layer's cubes one by
    one ("a bottom row of blue, green, blue and a top row of green, blue, green"); None when no
    layer is listed so.  Which cube of a layer stands where in it is not judged (the words list
    the layer's cubes; "from left to right" is not said).

    Raises:
        ParseError: a listed layer among layers not listed, two lists for one layer, or
            layers of different lengths (a wall's rows are all one length).
    """
    found = list(LISTED_ROW_RE.finditer(f.text))
    if not any(len(re.findall(COLOR_RE, m.group("cs"))) > 1 for m in found):
        return None  # one colour a layer: a role of the whole layer (layer_roles)
    top = len(found) - 1
    rows: dict[int, list[str]] = {}
    for m in found:
        k = top if m.group("role") in ("top", "upper") else LISTED_ROW_LAYER[m.group("role")]
        if k in rows:
            raise ParseError(f"\"{f.original[:80]}\" lists layer {k + 1} from the bottom twice; list each layer once")
        rows[k] = [canon_color(c) for c in re.findall(COLOR_RE, m.group("cs"))]
    if sorted(rows) != list(range(len(rows))) or len({len(r) for r in rows.values()}) != 1 or len(rows) < 2:
        raise ParseError(f"\"{f.original[:80]}\" lists the cubes of some layers of a wall but not of every layer, or "
                         "layers of different lengths; list every layer from the bottom with as many cubes each")
    return [rows[k] for k in range(len(rows))]


def _counted_layers(f: Features, height: int) -> list[int] | None:
    """The cubes each layer of a wall ``height`` high holds when the text counts every layer's
    cubes by colour and the counts agree ("bottom row 3 gray blocks, top row 3 brown blocks"
    -> [3, 3]); None when a layer is not counted or the layers differ."""
    try:
        roles = layer_roles(f, height)
    except ParseError:
        return None
    per: dict[int, int] = {}
    for (_, layer), n in roles.items():
        if n is None:
            return None
        per[layer] = per.get(layer, 0) + n
    if sorted(per) != list(range(height)) or len(set(per.values())) != 1 or next(iter(per.values())) < 2:
        return None
    return [per[k] for k in range(height)]


def _lattice(f: Features, b: Builder, r: int, c: int, layers: int, what: str) -> None:
    """A rows x cols x layers lattice of touching cubes (a 3D block, a wall)."""
    n = r * c * layers
    if n > C.MAX_OBJECTS:
        raise ParseError(f"{what.split(' (')[0].split(' of ')[0]} needs {n} cubes; the most a task holds is {C.MAX_OBJECTS}")
    if n < 2:
        raise ParseError("a structure of fewer than two cubes: give a larger size")
    per_layer = asks_per_layer(f)
    roles = layer_roles(f, layers) if layers > 1 and material_of(f) == "colors" else {}
    if roles:
        names = fill_layers(f, b, [r * c] * layers, roles)
    elif per_layer:
        cols = colors_for(layers, f, prefer=[c for c in dict.fromkeys(f.color_list())])
        colors = [cols[lay] for lay in range(layers) for _ in range(r * c)]
        names = [b.cube(col) for col in colors]
    else:
        names = fill_structure(f, b, n, material_of(f), ordering_of(f), lambda ns: ns and {})
    b.place(grid_layout(names, r, c, layers))
    b.preds.insert(0, Grid(tuple(names), r, c, layers))
    if per_layer:
        b.preds.append(LayersUniform(tuple(names), by="color", axis="z"))
        b.summary.append("each layer a different color")
    b.primitives += ["stack"]
    b.summary.insert(0, what)


@reader(order=130)
def recognize_grid(f: Features, b: Builder) -> bool:
    m = re.search(r"\b(\d+)x(\d+)\b", f.text)
    rows = re.search(r"\b(\d+)\s+rows\s+of\s+(\d+)\b", f.text)
    if m is None and rows:
        m = re.search(r"(\d+)x(\d+)", f"{rows.group(1)}x{rows.group(2)}")
    if m is None and re.search(r"\b(?:a|the)\s+(?:[a-z]+\s+)?(?:square|grid)\b(?!\s+patch)", f.text) and not f.has("patch", "patches"):
        side = max(2, round(math.sqrt(stated_count(f, default=4))))
        m = re.search(r"(\d+)x(\d+)", f"{side}x{side}")
    if not m or not (rows or f.has("square", "grid", "rectangle", "rectangular", "array", "block", "blocks", "cubes", "arrangement",
                                   "formation")):
        return False
    r, c = int(m.group(1)), int(m.group(2))
    n = r * c
    if n > C.MAX_OBJECTS:
        raise ParseError(f"a {r}x{c} grid needs {n} cubes; the most a task holds is {C.MAX_OBJECTS}")
    rows_said = re.search(r"\b(?:top|bottom|front|back|rear|first|second|third|middle|left|right|near|far|upper|lower)\s+"
                          r"(?:rows?|columns?|lines?|layers?)\b", f.text)
    if rows_said and len(set(f.color_list())) > 1:  # the goal checks a lattice, any cube at any site: the rows' colours
        # would be dropped (a goal weaker than the words)
        raise ParseError(f"'{rows_said.group(0)}' gives a row of the grid its own cubes, and rpg's grid goal checks the "
                         "lattice with any cube at any site; say the grid without row colours, or the rows as lines "
                         "(e.g. \"a row of two green cubes with a row of two orange cubes behind it\"), or use --model")
    names = fill_structure(f, b, n, material_of(f), ordering_of(f), lambda ns: grid_layout(ns, r, c))
    b.preds.insert(0, Grid(tuple(names), r, c))
    b.primitives += ["arrange"]
    b.summary.insert(0, f"a {r}x{c} grid of {n} touching cubes")
    return True


@reader(order=140)
def recognize_circle(f: Features, b: Builder) -> bool:
    corners = re.search(r"\bcorners of (?:a|the) square\b", f.text)
    if not f.has("circle", "circular", "ring", "round", "circles") and not corners:
        return False
    n = stated_count(f, default=None)
    of = re.search(r"\b(?:circle|ring)\s+of\s+(\d+)\b", f.text)  # "a circle of five"
    n = int(of.group(1)) if n is None and of else n
    listed = list(f.color_list())
    one_list = re.search(rf"\b(?:{COLOR_RE})(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:the\s+)?(?:{COLOR_RE})\b)+", f.text)
    if n is None and len(listed) >= 2 and one_list and (len(set(listed)) == len(listed) or len(
            re.findall(rf"\b(?:{COLOR_RE})\b", one_list.group(0))) == len(listed)):
        n = len(listed)  # "the red, green and blue blocks", "red, white, red, white": one cube per colour listed
        if n < 3:
            raise ParseError(f"a circle needs at least 3 cubes and it names {n} ({', '.join(listed)}); say how many "
                             "(e.g. 'a circle of 3 red and 3 blue blocks')")
    labels = explicit_labels(f)
    n = len(labels) if n is None and len(labels) >= 3 else n  # "the letter cubes A, B, C and D": those four
    n = n if n is not None else (4 if corners else 6)
    if n < 3:
        raise ParseError("a circle needs at least 3 cubes")
    if f.has("alternating", "alternate", "alternately", "alternates"):
        # "a circle of six cubes alternating red and white": the circle's goal (InCircle) checks where the cubes stand,
        # not their order round it, so the alternation had been dropped silently (and an odd count cannot alternate)
        raise ParseError("a circle's goal checks that the cubes stand evenly round a circle, not their order round it, so "
                         "alternating colours round a circle cannot be checked; say a row instead (e.g. \"a row of six cubes "
                         "alternating red and white\"), or drop the alternation, or use --model")
    names = fill_structure(f, b, n, material_of(f), None, lambda ns: circle_layout(ns))
    b.preds.insert(0, InCircle(tuple(names)))
    b.primitives += ["arrange"]
    b.summary.insert(0, f"{n} cubes evenly spaced on a circle of radius {circle_radius(n) * 100:.0f} cm")
    return True


PILE_UNSAID_COUNT = 3
"""Cubes of a colour in a pile whose count is not said ("pile up the red cubes", "separate the
blocks into piles by colour"): the piles predicate judges their spread, not their number (project)."""


@reader(order=150)
def recognize_piles(f: Features, b: Builder) -> bool:
    separate = re.search(r"\b(?:separate|split|divide)\b.*\b(?:from|by colou?r|into)\b", f.text) or (
        re.search(r"\bsort\b.*\bby\s+colou?rs?\b", f.text)  # "sort the blocks by colour": like with like
        and not f.has("line", "row", "rows", "align", "aligned", "tower", "stack", "rainbow", "gradient", "hue")
        and not direction_stated(f))
    if not (f.has("pile", "piles", "bunch", "bunches", "group", "groups", "cluster", "clusters", "heap", "heaps")
            or separate):
        return False
    material = material_of(f)
    groups: list[list[str]] = []
    each_said = list(_PILE_OF_RE.finditer(f.text))
    if len(each_said) >= 2:  # "a pile of red and blue and a pile of green": each pile's cubes said (they had merged into one)
        each = re.search(r"\b(\d+)\s+(?:of\s+)?each\b|\beach\s+(?:with\s+|of\s+)?(\d+)\b", f.text)
        lists = [_pile_cubes(m.group("list")) for m in each_said]
        if each and all(len(cs) == 1 for cs in lists):  # "a pile of red cubes and a pile of blue cubes, three each" (one cube
            lists = [cs * int(each.group(1) or each.group(2)) for cs in lists]  # a pile had been made, the count dropped)
        groups = [[b.cube(c) for c in cs] for cs in lists]
        centers = b.unit_centers(len(groups), 0.16)
        b.place(cluster_layout(groups, centers))
        b.preds.append(Piles(groups=tuple(tuple(g) for g in groups)))
        b.summary.append(f"{len(groups)} separate piles: " + "; ".join(", ".join(g) for g in groups))
        b.primitives += ["arrange"]
        b.min_separation = 0.06
        return True
    if material == "mixed" or f.has("type", "types", "kind"):
        labels_l, _ = label_sequence("letters", 3, b, ordered=False)
        labels_d, _ = label_sequence("digits", 3, b, ordered=False)
        groups = [[b.semantic(lab) for lab in labels_l], [b.semantic(lab) for lab in labels_d]]
        if f.colors or f.has("color", "colors", "colour", "colours", "colored", "coloured") or material != "mixed":
            groups.append([b.cube(c) for c in ("red", "blue", "green")])
        by = "type"
    else:
        k = stated_count(f, "pile|bunch|group|cluster|heap", default=None)
        per_color = re.search(r"\b(?:per|for\s+each|of\s+each|for\s+every)\s+colou?r\b", f.text)  # "one pile per colour"
        several = (separate or per_color or f.has("piles", "heaps", "bunches", "clusters", "groups", "each", "per")
                   or re.search(r"\bby\s+colou?rs?\b|\bother\b|\banother\b", f.text))
        if not per_color and (k == 1 or re.search(r"\b(?:a|one|single)\s+(?:single\s+)?(?:pile|heap|bunch|cluster|group)\b", f.text)):
            return _one_pile(f, b)
        if k is None and not several and _one_pile(f, b, strict=False):  # "pile four cubes": one pile of them
            return True
        sized = re.search(r"\b(\d+)\s+(?:separate\s+)?(?:piles|heaps|groups|clusters|bunches)\s*,?\s+(?:each\s+)?(?:of\s+|with\s+)(\d+)\b", f.text)
        if sized and not f.color_list() and not per_color and f.has(*lexicon.DIFFERENT_WORDS):
            raise ParseError(f"\"{f.original[:80]}\" says the cubes differ but names no colour; say the colours, or use --model")
        if sized and len(set(f.color_list())) <= 1 and not per_color:
            # "two piles of three cubes": no colour said, so which cubes share a pile is free; cubes of one colour are
            # interchangeable (evaluate_goal tries their assignments), so any split into piles of three passes (two piles
            # of two, one red and one blue, had been demanded); "three piles, each of two brown cubes": that colour
            one = f.color_list()[0] if f.color_list() else colors_for(1, f)[0]
            groups = [[b.cube(one) for _ in range(int(sized.group(2)))] for _ in range(int(sized.group(1)))]
            b.place(cluster_layout(groups, b.unit_centers(len(groups), 0.16)))
            b.preds.append(Piles(groups=tuple(tuple(g) for g in groups)))
            b.summary.append(f"{len(groups)} separate piles of {sized.group(2)} cubes")
            b.primitives += ["arrange"]
            b.min_separation = 0.06
            return True
        if not f.color_list() and not per_color and not re.search(r"\bcolou?r(?:s|ed)?\b|\bhues?\b|\bmatching\b|\blike\s+with\s+like\b",
                                                                    f.text):
            # "Make two piles.", "Sort the cubes into two piles.": which cubes share a pile is not said (piles by colour,
            # of colours nobody named, had been demanded)
            raise ParseError(f"\"{f.original[:80]}\" asks for {k or 'several'} piles but says neither which cubes go in each "
                             "nor how the cubes are sorted; say it (e.g. \"sort the cubes into piles by colour\", \"a pile of "
                             "red and a pile of blue\"), or use --model")
        # ("1 pile for each colour": the count is per colour, not the piles' number; one red pile had been made; "two piles,
        # one for each colour": two colours, not three)
        colors = list(dict.fromkeys(f.color_list())) or colors_for(((k if k and k > 1 else None) if per_color else k) or 3, f, prefer=[])
        if k is not None and not per_color and f.color_list() and k != len(colors):
            # "put red, blue, green, yellow into two piles": which cubes go together is not said (it had made a pile of
            # three cubes for each colour: twelve cubes, four piles)
            raise ParseError(f"\"{f.original[:80]}\" asks for {k} piles of cubes of {len(colors)} colours; say which cubes go "
                             "in each pile (e.g. \"a pile of red and blue and a pile of green\"), or use --model")
        said: dict[str, list[int]] = {}  # "3 red in one, 2 blue in the other": each colour's own count
        for count, c in re.findall(rf"\b(\d+)\s+({COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?patch)", f.text):
            said.setdefault(canon_color(c), []).append(int(count))
        if said and set(said) == set(colors) and all(len(v) == 1 for v in said.values()):
            groups = [[b.cube(c) for _ in range(said[c][0])] for c in colors]  # (each pile had taken the first count)
        else:
            each = re.search(r"\b(\d+)\s+(?:of\s+)?each\b|\beach\s+(?:with\s+|of\s+)?(\d+)\b", f.text)  # "red, green, blue, 2 each"
            per = stated_count(f, default=None)
            per = int(each.group(1) or each.group(2)) if each else max(2, per // len(colors)) if per else PILE_UNSAID_COUNT
            if sized and int(sized.group(1)) == len(colors):  # "two piles of three blocks, one of red and one of blue": 3 each
                per = int(sized.group(2))
            groups = [[b.cube(c) for _ in range(per)] for c in colors]
        by = "color"
    outliers = outlier_count(f)
    if outliers:
        if any(len(g) <= outliers for g in groups):
            raise ParseError(f"each pile needs more than {outliers} cube(s) to hold {outliers} outlier(s)")
        # the last `outliers` members of each pile move to the next pile
        moved = [g[-outliers:] for g in groups]
        groups = [g[:-outliers] + moved[i - 1] for i, g in enumerate(groups)]
    centers = b.unit_centers(len(groups), 0.16)
    b.place(cluster_layout(groups, centers))
    names = tuple(n for g in groups for n in g)
    what = f"type ({', '.join(['letters', 'digits', 'colors'][:len(groups)])})" if by == "type" else by
    if outliers:
        b.preds.append(Piles(groups=tuple(tuple(g) for g in groups)))
        b.summary.append(f"{len(groups)} separate piles, one per {what}, each with {outliers} outlier(s) from another pile")
    else:
        b.preds.append(Piles(names, by=by))
        b.summary.append(f"{len(groups)} separate piles, one per {what}")
    b.primitives += ["arrange"]
    b.min_separation = 0.06
    return True


_PILE_OF_RE = re.compile(rf"\b(?:a|one|1|another|the\s+other|a\s+second|a\s+third)\s+(?:pile|heap|group|cluster|bunch)\s+of\s+(?:the\s+)?"
                         rf"(?P<list>(?:\d\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+)(?:the\s+)?(?:\d\s+)?"
                         rf"(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?(?!\s+(?:pile|heap|group|cluster|bunch)))*)")
"""One pile's cubes said with it ("a pile of red and blue", "another pile of green", "one pile of the two green cubes"):
each colour one cube, or as many as its count says."""


def _pile_cubes(listed: str) -> list[str]:
    """The colours of one pile's list (:data:`_PILE_OF_RE`), a counted colour as many times as its count."""
    return [canon_color(c) for n, c in re.findall(rf"(?:\b(\d)\s+)?\b({COLOR_RE})\b", listed) for _ in range(int(n or 1))]


def _one_pile(f: Features, b: Builder, strict: bool = True) -> bool:
    """One pile of the cubes the text names ("a pile of four pink cubes", "one heap of the red,
    green and blue blocks"), or of a count of cubes it does not name ("a pile of four cubes": the
    pile judges their spread, never their colours); a colour said without its count is refused.

    Raises:
        ParseError: the pile's cubes are not named by colour (``strict``; else False is returned).
    """
    groups = counted_groups(f)
    colors = [c for i, c in f.colors if not re.match(r"[a-z]*\s+(?:goal\s+|target\s+)?patch", f.text[i:])]  # not a patch's
    n = stated_count(f, default=None)
    if groups:
        cubes = [c for k, c in groups for _ in range(k)]
    elif len(set(colors)) == 1 and (n or re.search(rf"\b(?:the|all)\s+(?:the\s+)?{colors[0]}\s+(?:cubes|blocks|bricks|ones)\b", f.text)):
        cubes = colors[:1] * (n or PILE_UNSAID_COUNT)  # "pile up the red cubes"
    elif len(colors) >= 2 and len(set(colors)) == len(colors) and n in (None, len(colors)):
        cubes = colors
    elif not colors and n and f.has("cubes", "blocks", "bricks", "boxes", "pieces", "objects"):
        cubes = colors_for(n, f, prefer=[])  # "a pile of four cubes": any four, as "stack three blocks" takes any three
    elif not strict:
        return False  # not said as one pile: the piles reader reads it
    else:
        raise ParseError(f"\"{f.original[:80]}\" asks for one pile but does not say which cubes; name them "
                         "(e.g. \"a pile of three red cubes\")")
    if len(cubes) < 2:
        raise ParseError("a pile needs at least two cubes; say how many")
    names = [b.cube(c) for c in cubes]
    b.place(cluster_layout([names], b.unit_centers(1, 0.16)))
    b.preds.append(Piles(tuple(names), by="color") if len(set(cubes)) == 1 else Piles(groups=(tuple(names),)))
    b.summary.append(f"one pile of {len(names)} cubes")
    b.primitives += ["arrange"]
    b.min_separation = 0.06
    return True


_REVERSE_LIST_RE = re.compile(r"\bin\s+(?:the\s+)?(?:reverse(?:d)?|opposite|backwards?)\s+order\b")
"""A list said to be read backwards ("in reverse order"), with no sort key that the ordering reads."""

_END_ROLE_RE = re.compile(rf"\b(?P<c>{COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?:(?:is|goes|sits|stands|being|should\s+be|must\s+be)\s+)?"
                          r"(?:(?:on|at|to|in)\s+the\s+(?:far\s+|very\s+)?(?P<side>left|right|middle|center|centre)(?:\s+(?:end|side))?"
                          r"|(?<=is\s)(?P<side2>left|right)|(?<=[a-z]\s)(?P<side3>left|right)(?=\s*(?:[,.;]|$|\s+and\b)))\b"
                          r"(?!\s+(?:of|half|part|corner|edge)\b)")
"""A cube of a line given its place in it ("with red on the left", "blue on the far right", "green
in the middle", "orange is leftmost", "with yellow leftmost and cyan rightmost": "leftmost" reads "left")."""


_START_END_RE = re.compile(rf"\b(?P<w>start(?:s|ing)?|begin(?:s|ning)?|end(?:s|ing)?|finish(?:es|ing)?)\s+with\s+"
                           rf"(?:the\s+|a\s+|an\s+)?(?P<c>{COLOR_RE})\b")
"""A line's first or last cube ("starts with the black cube and ends with the white one"): its
ends, when the words say which way the line runs."""


_BESIDE_END_RE = re.compile(rf"\b(?P<c>{COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?:(?:is|goes|sits|stands)\s+)?"
                            r"(?:(?:to\s+the\s+|on\s+the\s+)?(?P<side>left|right)\s+of\s+it|to\s+its\s+(?P<side2>left|right)"
                            r"|(?:next\s+to|beside)\s+it)\b")
"""The third cube of a three-cube line said beside the end cube said just before it ("the orange block at the right, the
pink block left of it and the gray block at the far left"): the middle, when the other two hold the ends."""


def _beside_an_end(f: Features, place: dict[str, str], colors: list[str]) -> dict[str, str]:
    """``place`` with the middle of a three-cube line given to the cube said beside an end cube (:data:`_BESIDE_END_RE`),
    when the other two hold both ends and the side said points into the line from the cube "it" stands for.

    Raises:
        ParseError: the side said points out of the line ("the red cube at the left end, the blue cube left of it")."""
    beside = _BESIDE_END_RE.search(f.text)
    if not beside or len(colors) != 3 or {"left", "right"} - set(place) or "middle" in place:
        return place
    c = canon_color(beside.group("c"))
    before = list(_END_ROLE_RE.finditer(f.text[:beside.start()]))
    if c in place.values() or not before:
        return place
    it = canon_color(before[-1].group("c"))
    end = next((side for side, col in place.items() if col == it), None)
    side = beside.group("side") or beside.group("side2")
    if end is None:
        return place
    if side and side == end:
        raise ParseError(f"\"{f.original[:80]}\" puts the {c} cube {side} of the {it} cube at the {end} end of the line: "
                         "no place is there; say each cube's place once, or use --model")
    return {**place, "middle": c}


def _order_by_end_roles(f: Features) -> list[str] | None:
    """The colours of a line of distinct colours from left to right, when its words put cubes at
    its ends and middle so that every place is fixed ("a row of red, green and blue with red on
    the left and blue on the right"); None otherwise (no such roles, or a place left open)."""
    colors = list(dict.fromkeys(f.color_list()))
    if not 2 <= len(colors) <= 3:
        return None
    listed = len(f.color_list()) >= 2 * len(colors) - 1  # the cubes listed, then (most of) them given a place
    said: list[tuple[str, str]] = []  # (place in the line, colour)
    for m in _END_ROLE_RE.finditer(f.text):
        side = m.group("side") or m.group("side2") or m.group("side3")
        said.append(({"center": "middle", "centre": "middle"}.get(side, side), canon_color(m.group("c"))))
    if direction_stated(f) and line_axis_said(f) == "y":  # "from left to right, starts with black and ends with white"
        first, last = ("right", "left") if direction_of(f) == "right_to_left" else ("left", "right")
        said += [(first if m.group("w").startswith(("start", "begin")) else last, canon_color(m.group("c")))
                 for m in _START_END_RE.finditer(f.text)]
    place: dict[str, str] = {}
    for side, c in said:
        if place.get(side, c) != c or c in place.values() and place.get(side) != c:
            raise ParseError(f"\"{f.original[:80]}\" puts two cubes in one place of the line, or one cube in two "
                             "(say each cube's place once: \"red on the left, green in the middle, blue on the right\"), "
                             "or use --model")
        place[side] = c
    place = _beside_an_end(f, place, colors)
    if not ({"left", "right"} & set(place)) or (len(colors) == 2 and "middle" in place):
        return None
    if not listed and set(place.values()) != set(colors):
        return None  # each cube given its place without a list: every one of them must be
    slots = ["left", "middle", "right"] if len(colors) == 3 else ["left", "right"]
    open_slots = [s for s in slots if s not in place]
    rest = [c for c in colors if c not in place.values()]
    if len(open_slots) != len(rest) or len(rest) > 1:
        return None
    place.update(zip(open_slots, rest, strict=True))
    return [place[s] for s in slots]


_DIRECTION_WORDS = r"(?:from\s+)?(?:left to right|right to left|front to back|back to front)"


def _list_the_direction_orders(f: Features, lists: list[re.Match]) -> re.Match | None:
    """The colour list a line's direction orders: with one list, that one; with several (the
    cubes named, then their order: "arrange red, green and blue in a row, from left to right:
    blue, green, red"), the one said next to the direction words.

    Raises:
        ParseError: two lists in different orders and neither next to the direction words.
    """
    if len(lists) < 2:
        return lists[0] if lists else None
    seqs = [tuple(canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.group(1))) for m in lists]
    if len(set(seqs)) == 1:
        return lists[0]
    longest = max(seqs, key=len)
    if all(longest == tuple(q[i % len(q)] for i in range(len(longest))) for q in seqs):
        return lists[seqs.index(longest)]  # "alternating black and white, left to right black, white, black, white": the
        # pair's alternation written out, one order
    after_colon = [m for m in lists if re.search(rf"{_DIRECTION_WORDS}\s*:\s*(?:the\s+)?$", f.text[:m.start()])]
    near = after_colon or [m for m in lists if re.search(rf"{_DIRECTION_WORDS}\s*[:,]?\s*(?:the\s+)?$", f.text[:m.start()])
                           or re.match(rf"\s*,?\s*{_DIRECTION_WORDS}\b", f.text[m.end():])]
    if len(near) == 1:  # "red, green and blue from left to right: blue, green, red": the list after the colon
        return near[0]
    raise ParseError(f"\"{f.original[:80]}\" lists the cubes in two different orders "
                     f"({'; '.join(', '.join(s) for s in seqs[:2])}); say the order once (e.g. \"from left to right: "
                     f"{', '.join(seqs[-1])}\"), or use --model")


_LABEL_END_ROLE_RE = re.compile(r"\b(?P<lab>[A-Z]|\d)\s+(?:(?:cube\s+|block\s+)?(?:is|goes|sits|stands|being)\s+)?(?:on|at|to)\s+the\s+"
                                r"(?:far\s+|very\s+)?(?P<side>left|right)(?:\s+end)?\b(?!\s+(?:of|side|half|corner|edge)\b)")
"""A labelled cube of a line given its end ("..., 8 on the left", "with C at the right end"), read in the original's case
(a lone capital is a letter cube's label, "a" an article)."""


_LABEL_SIDE_OF_RE = re.compile(r"\b(?P<a>[A-Z]|\d)\s+(?:(?:cube|block)\s+)?(?:(?:is|goes|sits|stands)\s+)?(?:(?:on|to)\s+the\s+)?(?P<side>left|right)\s+"
                               r"of\s+(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?P<b>[A-Z]|\d)\b")
"""One labelled cube of a row said left or right of another ("..., 8 on the left of 5")."""


def _labels_by_end_roles(f: Features, labels: list[str]) -> list[str] | None:
    """The labels of a line from left to right when its words give the ends so that every place is fixed (two labels and
    one end said, or three and both ends, or two and one said left or right of the other); None otherwise.

    Raises:
        ParseError: one label said left or right of another in a row of more than two (the row's order is not said).
    """
    side_of = _LABEL_SIDE_OF_RE.search(f.original)
    if side_of and {side_of.group("a"), side_of.group("b")} <= set(labels) and side_of.group("a") != side_of.group("b"):
        if len(labels) != 2:
            raise ParseError(f"'{side_of.group(0)}' in \"{f.original[:80]}\" orders two cubes of a row of {len(labels)} and "
                             "leaves the rest of its order unsaid; say the whole order (e.g. \"from left to right: 8, 5, 3\"), "
                             "or use --model")
        a, b_ = side_of.group("a"), side_of.group("b")
        return [a, b_] if side_of.group("side") == "left" else [b_, a]
    ends: dict[str, str] = {}
    for m in _LABEL_END_ROLE_RE.finditer(f.original):
        lab = m.group("lab").upper()
        if lab not in labels or ends.get(m.group("side"), lab) != lab:
            return None
        ends[m.group("side")] = lab
    if not ends or len(set(ends.values())) != len(ends) or len(labels) > 3 or len(labels) - len(ends) > 1:
        return None
    rest = [lab for lab in labels if lab not in ends.values()]
    if len(ends) == 2:  # both ends said (with a third label, it stands between them)
        return [ends["left"], *rest, ends["right"]]
    return [ends["left"], *rest] if "left" in ends else [*rest, ends["right"]]


@reader(order=160)
def recognize_ordered_line(f: Features, b: Builder) -> bool:
    order = ordering_of(f)
    explicit = re.search(r"\b(?:order(?:ed)?|sequence)\s*(?::\s*|(?:as|like|by)\s+)?((?:(?:" + COLOR_RE
                         + r")\s*,?\s*(?:and\s+|then\s+)?){2,})", f.text)
    labels = explicit_labels(f)
    is_line = f.has("align", "aligned", "line", "row", "arrange", "arranged", "order", "sort", "sorted",
                    "horizontally", "horizontal") or order
    shape = re.search(r"\b(?:in|into|as)\s+(?:a|an|the)\s+([a-z]+)\s+(?:shape|pattern|formation)\b", f.text)
    if shape and shape.group(1) not in ("line", "row", "straight", "linear", "horizontal", "single"):
        return False  # "in a plus shape": a shape the parser does not build
    pairwise = re.search(r"\b(?:left|right) of\b(?!\s+it\b)|\bin front of\b|\bbehind\b", f.text)
    beside_end = re.search(r"\b(?:left|right) of\s+it\b", f.text)  # "..., the pink block left of it and ...": a line's
    # middle only beside an end cube of a line said by its ends (_beside_an_end)
    if not order and not labels and len(f.colors) >= 2 and (pairwise or (beside_end and not _order_by_end_roles(f))):
        return False  # "so that red is left of green": pairwise relations (recognize_relational)
    if not is_line or f.has("stack", "stacks", "tower", "towers", "on top"):
        return False
    if re.search(r"\b(?:under|underneath|beneath|below)\s+(?:the|a|an|it|them)\b", f.text):
        return False  # "a row of green cubes under the red cube": a row lies flat, nothing stands on it (it had been a row of the two)
    if re.search(r"\b(?:bottom[\s-]+(?:to|up\s+to)[\s-]+top|top[\s-]+(?:to|down\s+to)[\s-]+bottom)\b", f.text):
        return False  # "bottom-to-top order blue, yellow, red": a tower's order, never a line's
    direction = direction_of(f)
    item = (rf"(?:{COLOR_RE})(?:\s+(?:blocks?|cubes?))?(?:\s+first)?"  # "the blue block first, then the red block"
            r"(?!\s+(?:(?:is|goes|sits|on|at|in|to)\s+)?(?:the\s+)?(?:far\s+|very\s+)?(?:left|right|middle|center|centre)\b)")
    # (a cube given its place after the list, "..., yellow leftmost and cyan rightmost", is no further item of it)
    by_roles = _order_by_end_roles(f)  # "with red on the left, green in the middle and blue on the right"
    lists = list(re.finditer(rf"\b((?:{item})(?:\s*(?:,\s*and|,|and|then)\s+(?:then\s+)?(?:the\s+|an?\s+)?(?:{item})\b)+)", f.text))
    listed = _list_the_direction_orders(f, lists)
    alternating = alternating_colors(f, 6)
    if listed and re.search(rf"\bthe\s+({COLOR_RE})\s+(?:cube|block)\b.*\bthe\s+\1\s+(?:cube|block)\b", listed.group(0)):
        return False  # "the brown cube, and the brown cube is in the middle": one cube said twice, not two cubes
    if not explicit and not order and listed and not alternating:
        seq = re.findall(rf"\b(?:{COLOR_RE})\b", listed.group(1))
        if re.search(r"\b(?:left to right|right to left|front to back|back to front)\b", f.text) or \
                (len(set(seq)) < len(seq) and not re.search(r"\bin any order\b", f.text)) or THIS_ORDER_RE.search(f.text):
            # "red, blue, red, blue": a repeated colour only makes sense as an order, unless "in any order" frees it
            # ("cyan, cyan, purple, in any order": which cubes, not where); "red, green and blue in that order": said
            explicit = listed
    if alternating and not explicit:
        explicit = re.search(r"(.+)", ", ".join(alternating))
    if by_roles and not explicit and not order and not labels:
        explicit, direction = re.search(r"(.+)", ", ".join(by_roles)), "left_to_right"
    in_order = re.search(r"\bin (?:the )?order\b(.*)", f.text)
    listed_items = item_sequence(in_order.group(1)) if in_order else []
    said_word = re.search(r"\b(?:reads?|read as|shows?|spells?)\s+'?([a-z0-9]{2,}|(?:[a-z0-9](?:\s+|\s*,\s*)){1,9}[a-z0-9])'?(?![a-z0-9])",
                          f.text)  # "reads 123", "reads 1 2 3": said at once or one by one
    said = re.sub(r"[\s,]", "", said_word.group(1)).upper() if said_word else ""
    if in_order and said and all(label for _, label in listed_items) and sorted(said) == sorted(label for _, label in listed_items):
        listed_items = [(None, ch) for ch in said]  # "in the order 3, 1, 2 ... reads 1 2 3": the word read
    if in_order and any(label for _, label in listed_items) and len(listed_items) >= 2:
        names = [b.semantic(label) if label else b.cube(color) for color, label in listed_items]
        b.place(directed_line(names, direction))
        b.preds.append(InLine(tuple(names), axis=line_axis(direction), order=direction))
        b.summary.append(f"cubes in a line {direction.replace('_', ' ')}: {', '.join(names)}")
    elif explicit:
        colors = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", explicit.group(1))]
        if _REVERSE_LIST_RE.search(f.text):  # "line up red, green and blue in reverse order": the list read backwards
            colors = colors[::-1]
        names = [b.cube(c) for c in colors]
        b.place(directed_line(names, direction))
        if direction_stated(f) or by_roles:
            b.preds.append(InLine(tuple(names), axis=line_axis(direction), order=direction))
            b.summary.append(f"cubes in a line {direction.replace('_', ' ')}: {', '.join(names)}")
        else:  # "in the order red, green, blue", "alternating red and blue": from either end, any direction
            b.preds.append(InLine(tuple(names), axis=None, order="sequence"))
            b.summary.append(b.preds[-1].describe())
    elif labels:
        reads = re.search(r"\b(?:reads?|reading|read as|shows?|showing|spells?|spelling)\s+'?([A-Za-z0-9]{2,})'?", f.original,
                          re.IGNORECASE) or said_word
        if reads and sorted(re.sub(r"[\s,]", "", reads.group(1)).upper()) == sorted(labels):  # "the digits 1, 2, 3 so they read 321"
            labels = list(re.sub(r"[\s,]", "", reads.group(1)).upper())
        elif reads and re.fullmatch(r"[A-Z0-9]{2,}", reads.group(1)) and len(reads.group(1)) == len(labels):
            # "the letter cubes T, A and B in a row, reading CAT": the word is not of the cubes listed (TAB had been read)
            raise ParseError(f"\"{f.original[:80]}\" lists the cubes {', '.join(labels)} and asks them to read "
                             f"'{reads.group(1)}'; say the cubes of the word, or use --model")
        elif order:  # the listed labels are the set; the ordering arranges them
            labels = sorted(labels, key=lambda lab: (not lab.isdigit(), lab), reverse=order[1])
        elif _REVERSE_LIST_RE.search(f.text):  # "the digits 7, 3, 5 in a row in reverse order": the list read backwards
            labels = labels[::-1]
        by_ends = None if reads or order else _labels_by_end_roles(f, labels)
        if by_ends:  # "the number cubes 5 and 8 in a row, 8 on the left": each end's cube said
            labels, direction = by_ends, "left_to_right"
        names = [b.semantic(lab) for lab in labels]
        b.place(directed_line(names, direction))
        said_as_word = bool(reads or READ_WORDS_RE.search(f.text))
        if re.search(r"\bin any order\b", f.text) and (said_as_word or reads):  # (the word had been read, the order kept)
            raise ParseError(f"\"{f.original[:80]}\" asks the labels to read (or face up) in a row and leaves their order free; "
                             "say one (e.g. \"... reading CAT from left to right\", or \"... in any order\" alone), or use --model")
        if direction_stated(f) or said_as_word or order or by_ends:
            b.preds.append(InLine(tuple(names), axis=line_axis(direction), order=direction))
        elif re.search(r"\bin any order\b", f.text):  # "the letter cubes B, A and T in a row, any order": which cubes, not where
            b.preds.append(InLine(tuple(names), axis=None, order=None))
        elif lexicon.THIS_ORDER_RE.search(f.text) or lexicon.LISTED_ORDER_SAID_RE.search(f.text) \
                or lexicon.ROW_PLACE_WORD_RE.search(f.text):
            # "the letters Q, R and S in a row, in that order": the listed order from either end, no reading direction said
            b.preds.append(InLine(tuple(names), axis=None, order="sequence"))
        else:  # "put the A and the B in a line", "the 7, 8 and 9 cubes side by side in a row": which cubes, not where (the
            # listed order had been demanded, as no list of colours is: a goal stricter than its words)
            b.preds.append(InLine(tuple(names), axis=None, order=None))
        if said_as_word:  # the labels read as a word: their faces up (not said otherwise)
            b.preds.append(Reads(tuple(names), "".join(labels), direction))
        if order and said_as_word:  # "... so their up-faces read A, B, C, D in alphabetical order": the faces judged;
            # otherwise the directed line of the listed labels, sorted, already fixes each cube's place (a sort by the
            # up faces' labels had been added, demanding faces nobody named)
            b.preds.append(SortedBy(tuple(names), key=order[0] if order[0] != "color" else "label", direction=direction, descending=order[1]))
        b.summary.append(f"up faces read {', '.join(labels)} {direction.replace('_', ' ')}")
    elif order:
        key, desc = order
        spectrum = spectrum_of(f)
        listed = [c for c in dict.fromkeys(f.color_list()) if c in spectrum]
        n = stated_count(f, default=4 if key != "color" else len(listed) if len(listed) >= 2 else 5)
        if key == "color":
            colors = listed or spectrum
            if len(colors) < n:
                colors = spectrum
            colors = sorted(colors[:n], key=spectrum.index, reverse=desc)
            names = [b.cube(c) for c in colors]
            if not direction_stated(f):  # "in rainbow order": the hues in sequence, read from either end
                b.place(directed_line(names, direction))
                b.preds.append(InLine(tuple(names), axis=None, order="sequence"))
                b.summary.append(b.preds[-1].describe())
                b.primitives += ["arrange"]
                return True
        else:
            material = "letters" if key == "label" else "digits"
            labels, strict = label_sequence(material, n, b)
            if desc:
                labels = list(reversed(labels))
            names = [b.semantic(lab) for lab in labels]
        b.place(directed_line(names, direction))
        b.preds.append(InLine(tuple(names), axis=line_axis(direction), order=direction))
        if key != "color":  # a directed line of named hues already fixes each colour's place
            b.preds.append(SortedBy(tuple(names), key=key, direction=direction, descending=desc))
        what = {"label": "alphabetical", "number": "increasing numerical", "color": "color-gradient"}[key]
        b.summary.append(f"{n} cubes in a line in {'reverse ' if desc else ''}{what} order {direction.replace('_', ' ')}")
    else:
        if not f.has("align", "aligned", "line", "lines", "row", "horizontally", "horizontal"):
            return False  # "sort the blocks", "arrange them by colour": no line said, and no order to read it by
        if re.search(r"\b(?:sort|sorted|order|ordered|arrange|arranged|group|grouped)\s+(?:\w+\s+){0,2}?by\s+(?:colou?rs?|hues?)\b", f.text):
            raise ParseError("a line \"sorted by colour\" names no order of the colours; say it (\"red, green, blue "
                             "from left to right\", \"in rainbow order\") or use --model")
        distinct = list(dict.fromkeys(f.color_list()))
        # a list with a colour said twice, freed by "in any order" ("cyan, cyan, purple, in any order"): its cubes
        said = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", listed.group(1))] if listed else []
        said = said if len(set(said)) < len(said) and not alternating else []
        n = stated_count(f, default=len(said) or (len(distinct) if len(distinct) >= 2 else 4))
        material = material_of(f)
        if material == "mixed" or (material != "colors" and f.has("alternating", "alternate", "alternately")):
            raise ParseError("a line mixing letters and digits in a pattern is beyond the builtin parser; "
                             "list the labels (\"arrange A, 1, B, 2 from left to right\") or use --model")
        if material in ("letters", "digits") and not distinct:  # "line up four letter cubes": labels, any order
            labels, _ = label_sequence(material, n, b, ordered=False)
            names = [b.semantic(lab) for lab in labels]
        elif (groups := counted_groups(f)) and sum(k for k, _ in groups) == n:  # "2 red and 2 blue blocks"
            names = [b.cube(c) for k, c in groups for _ in range(k)]
        elif said and len(said) == n:
            names = [b.cube(c) for c in said]
        else:
            role = re.search(rf"\b(?:(?:start|begin|end|finish)(?:s|ing)?\s+with\s+(?:the\s+|a\s+|an\s+)?(?:{COLOR_RE})\b"
                             rf"|\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:first|last)\b)", f.text)
            if len(distinct) == 1 and n > 1 and role:  # "a row of three cubes from left to right, red first": one cube's
                # colour, not the row's (every cube had been made red)
                raise ParseError(f"'{role.group(0)}' in \"{f.original[:80]}\" gives one cube a colour and a place at one end "
                                 "of the row and says nothing of the others' colours; say every cube's colour (e.g. \"red, "
                                 "blue, blue from left to right\"), or use --model")
            names = [b.cube(c) for c in (distinct * n if len(distinct) == 1 else colors_for(n, f))]
        middle = re.search(rf"\b({COLOR_RE})\s+(?:block\s+|cube\s+)?(?:is\s+)?(?:in|at)\s+the\s+(?:middle|center|centre)\b", f.text)
        mid = canon_color(middle.group(1)) if middle else None
        color_of = {a.name: a.color for a in b.assets}
        if mid and n == 3 and [color_of.get(nm) for nm in names].count(mid) == 1:
            # "red, blue and green with blue in the middle", "two blue and one orange in a row, orange in the centre"
            ends = [nm for nm in names if color_of.get(nm) != mid]
            names = [ends[0], next(nm for nm in names if color_of.get(nm) == mid), ends[1]]
            b.preds.append(Between(names[1], names[0], names[2]))
        axis = line_axis_said(f)
        b.place(line_layout(names, axis=axis or "y"))
        alike = len(distinct) == 1 and material not in ("letters", "digits")
        # "a column of three green cubes from front to back": alike cubes in the direction said
        b.preds.insert(0, InLine(tuple(names), axis=axis, order=direction_of(f) if alike and direction_stated(f) else None))
        kind = {"letters": "letter ", "digits": "digit "}.get(material, "") if not distinct else ""
        b.summary.append(f"{n} {kind}cubes in one straight {({'y': 'left-right ', 'x': 'front-back '}).get(axis, '')}line"
                         + (f" with {names[1]} in the middle" if len(b.preds) > 1 else ""))
    _middle_kept(f, b)
    b.primitives += ["arrange"]
    return True


_COMMA_MIDDLE_RE = re.compile(rf",\s*(?:the\s+)?({COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?:is\s+|goes\s+|sits\s+)?(?:in|at)\s+the\s+"
                              r"(?:middle|center|centre)\b(?!\s+of\b)")
"""A cube given a row's middle after a comma ("two blue and one orange in a row, orange in the centre")."""


def _middle_kept(f: Features, b: Builder) -> None:
    """Refuse a row whose middle a comma gives a cube (:data:`_COMMA_MIDDLE_RE`) that the reading does not put there: a
    cube between the others, or the middle of an ordered row of an odd count, of that colour.

    Raises:
        ParseError: the middle said is not the reading's (it had been dropped, or a cube made up for it).
    """
    said = _COMMA_MIDDLE_RE.search(f.text)
    if said is None:
        return
    mid = canon_color(said.group(1))
    color_of = {a.name: a.color for a in b.assets}
    for p in b.preds:
        if isinstance(p, Between) and color_of.get(p.a) == mid:
            return
        if isinstance(p, InLine) and p.order is not None and len(p.objects) % 2 and color_of.get(p.objects[len(p.objects) // 2]) == mid \
                and sum(color_of.get(o) == mid for o in p.objects) == 1:
            return
    raise ParseError(f"'{said.group(0).strip(', ')}' gives a cube the row's middle, and the row read "
                     f"({'; '.join(b.summary) or 'its cubes'}) does not put it there with the others on each side; "
                     "say the whole order (e.g. \"from left to right: blue, orange, blue\"), or use --model")


SEQ_RELATION_RE = re.compile(r"\b(?:on top of|onto|on|atop|above|over|under|underneath|beneath|below|left|right|"
                             r"behind|front|next|beside|between|near|patch|patches)\b")


SEQ_HINT_RE = re.compile(r"\b(?:on|at|as|in)\s+(?:the\s+|its\s+)?(?:very\s+)?(bottom|base|top|middle|center|centre)\b(?!\s+of)")

READ_WORDS_RE = re.compile(r"\b(?:reads?|reading|readable|spell\w*|shows?|showing|display\w*|fac(?:e|es|ing)\s+up|"
                           r"(?:labels?|letters?|digits?|numbers?)\s+(?:up|visible|on\s+top))\b")
"""Words that ask a line of label cubes to read as a word (its labels face up), not only to
stand in an order."""


BARE_END_RE = re.compile(rf"\b(?P<c>{COLOR_RE})\s+(?P<end>top|bottom|base|first|last)\b(?=\s*(?:[,.;]|$))")
"""A tower's end given to a colour with no preposition ("red top, blue bottom"; "..., red first":
the first cube stacked, the bottom; "..., yellow last": the top)."""

BARE_END_WORD = {"first": "bottom", "last": "top"}
"""An end said as a step of stacking (:data:`BARE_END_RE`) -> the end of the tower."""


def may_order_cubes(text: str) -> bool:
    """Whether ``text`` has a word that may order a tower's cubes (:data:`ORDER_WORDS`,
    :data:`CUBE_ORDER_RE` of :mod:`rpg.schema.lexicon`)."""
    return bool(ORDER_WORDS.search(text) or CUBE_ORDER_RE.search(text))


SORTED_TOWER_DEFAULT = 4
"""Cubes in a sorted tower of letters or digits when the instruction gives no count."""


@reader(order=170)
def recognize_sorted_tower(f: Features, b: Builder) -> bool:
    """A tower of letter or digit cubes in sorted order ("stack the number blocks in
    increasing order from bottom to top", "a tower of four letters with A at the bottom";
    with no count, an end's label leaves which labels follow it unsaid: not read).
    The order is bottom to top; labels face every side, so the front reads it."""
    if not f.has("stack", "tower", "stacked") or f.has("towers", "stacks", "patch", "patches", "pyramid", "each other"):
        return False
    material = material_of(f)
    if material not in ("letters", "digits") or explicit_labels(f) or spelled_word(f):
        return False
    if len(set(re.findall(r"\b(?:letter|digit|number)\s+'?([a-z0-9])\b", f.text))) >= 2 or len(set(re.findall(
            r"\b([a-z0-9])\s+(?:(?:is|goes|sits)\s+)?(?:on|at|in)\s+(?:the\s+)?(?:bottom|base|top|middle)\b", f.text))) >= 2 \
            or re.search(r"(?:,|\band)\s+then\s+[a-z0-9]\b", f.text):
        return False  # "with A at the bottom, then B, then C on top", "3 on the bottom ... 1 on top", "1 at the bottom, then 2,
        # then 3": the cubes are named (a fourth had been added to a sorted tower)
    descending = tower_order(f)
    if descending is None:
        return False
    n = stated_count(f, default=None)
    if n is None and re.search(r"\b(?:(?:letter|digit|number)\s+)?[a-z0-9](?:\s+(?:block|cube))?\s+(?:(?:is|goes|sits)\s+)?(?:on|at|in)\s+"
                               r"(?:the\s+)?(?:top|bottom|base)\b", f.text) and not re.search(
            r"\b(?:order\w*|alphabetical\w*|ascending|descending|increasing|decreasing|sorted|sort)\b", f.text):
        return False  # "a tower of letter cubes with A on top": which letters lie under A is not said (B, C, D had been made)
    n = n or SORTED_TOWER_DEFAULT
    labels, strict = label_sequence(material, n, b, ordered=True)
    if descending:
        labels.reverse()
    names = [b.semantic(lab) for lab in labels]
    b.place(stack_layout(names, C.WORKSPACE_CENTER))
    b.preds.append(Stack(tuple(names)))
    b.primitives += ["stack"]
    kind = "letters" if material == "letters" else "digits"
    b.summary.append(f"a tower of {kind} {'descending' if descending else 'ascending'} from bottom to top: " + ", ".join(labels))
    return True


RAINBOW_TOWER = 5
"""Cubes in a rainbow-order tower when the instruction gives no count."""


@reader(order=180)
def recognize_tower_sequence(f: Features, b: Builder) -> bool:
    """One tower given as a sequence of cubes: "a tower from bottom to top: red, blue,
    letter 'A'", "a tower of red, green and blue blocks", "red at the bottom, then green,
    then blue on top", "the letters A, B, C in a tower", "four blocks in rainbow order".
    Listing order is bottom to top unless the text says "top to bottom" or "in the reversed
    order", or marks a cube "on top" / "at the bottom" (a list with no order word at all is
    freed afterwards: :func:`rpg.schema.readers.free_listed_orders`)."""
    implied = re.search(r"\b(?:at|on)\s+the\s+(?:bottom|base)\b", f.text) and re.search(r"\b(?:on\s+top|at\s+the\s+top)\b", f.text) \
        and re.search(r"\bthen\b", f.text)  # "purple on the bottom then pink then white on top": a tower by its ends
    if not (f.has("stack", "tower", "stacked") or implied) or f.has("towers", "stacks", "each other", "patch", "patches", "pyramid"):
        return False
    if "@" in mark_references(f.text) or len(DESCRIBED_TOWER_RE.findall(f.text)) >= 2:  # relations, or several towers
        return False
    listing = [c for c in re.split(r"(?<=[.;!?])\s+", f.text) if re.search(r"\b(?:stack|tower)\b", c)
               and len(re.findall(rf"\b(?:{COLOR_RE})\b", c)) >= 2]
    if len(listing) >= 2:  # "Stack red, green, blue bottom to top. Stack white, black bottom to top.": a tower each (one
        return False  # tower of five had been read, silently)
    text = BARE_END_RE.sub(lambda m: f"{m.group('c')} at the {BARE_END_WORD.get(m.group('end'), m.group('end'))}",
                           f.text)  # "red top, blue bottom", "..., red first"
    text = SEQ_HINT_RE.sub(lambda m: f" <{m.group(1)}> ", text)
    mentions = list(ITEM_RE.finditer(text))
    for a, c in itertools.pairwise(mentions):
        if SEQ_RELATION_RE.search(text[a.end():c.start()]):
            return False
    items: list[tuple[str | None, str | None]] = []
    grouped: list[int] = []  # counts said of one colour ("2 white cubes")
    filled = False
    hints: dict[int, str] = {}
    about_listed: set[int] = set()  # hints about a cube listed before them ("red, blue, green ... with blue at the bottom")
    said = stated_count(f, default=None)
    for k, m in enumerate(mentions):
        item = (None, m.group("label").upper()) if m.group("label") else (canon_color(m.group("color")), None)
        step = k > 0 and re.match(r"\s*,?\s*(?:and\s+)?then\b", text[mentions[k - 1].end():m.start()])
        hint = re.match(r"\s*(?:(?:block|cube)s?\s*)?(?:(?:is|goes|sits|stands|(?:should|must|will)\s+be|ends\s+up)\s+)?"
                        r"<(bottom|base|top|middle|center|centre)>", text[m.end():])  # "so that red is at the bottom"
        if hint and item in items and not step:  # "... with yellow at the bottom": a hint about a listed cube
            # (not a step of a sequence: "red base, then blue, then red, then blue on top" has two blue cubes)
            at = items.index(item) if hint.group(1) != "top" else len(items) - 1 - items[::-1].index(item)
            hints[at] = hint.group(1)  # a colour listed twice: its bottom one is the base, its top one the top
            about_listed.add(at)
            continue
        count = re.search(r"\b(\d+)\s+$", text[max(0, m.start() - 4): m.start()]) if not m.group("label") else None
        if count and 1 < int(count.group(1)) <= 6:
            grouped.append(int(count.group(1)))
        for _ in range(int(count.group(1)) - 1 if count and 1 < int(count.group(1)) <= 6 else 0):
            items.append(item)  # "two blue blocks and one red block on top"
        if hint:
            hints[len(items)] = hint.group(1)
        items.append(item)
    if re.search(r"\bthen\b", f.text) and any(h == "top" and i < len(items) - 1 and i not in about_listed for i, h in hints.items()):
        # "Stack white, then black on top, then brown": a step said to be the top before more steps (black had been put on
        # brown, silently)
        raise ParseError(f"\"{f.original[:80]}\" puts a cube on top and then more cubes after it: which one is the top is "
                         "not clear; list the tower from the bottom (e.g. \"white, then black, then brown on top\"), or use --model")
    first_hint = min(hints) if hints else None
    if first_hint == 0 and not re.search(r"\bthen\b", f.text) and items.count(items[0]) == 2 and not grouped \
            and re.search(rf"\b(?:{TOWER_NOUNS})\s+of\b", text[mentions[0].end():]):
        # "starting with red at the bottom, build a tower of red, blue and green": the role said before the tower names
        # the listed cube (a second red cube had been made)
        again = items.index(items[0], 1)
        hints = {again - 1 if i > again else (again - 1 if i == 0 else i): h for i, h in hints.items()}
        about_listed.add(again - 1)
        items.pop(0)
    if said is not None and said in grouped and not re.search(rf"(?<!the )\b(?:\d+|{COUNT_WORD_RE})[- ](?:cubes?|blocks?)\b",
                                                            f.original.lower()) \
            and not re.search(rf"\b(?:{TOWER_NOUNS})\s+of\s+{said}\b", f.text):  # not "a two-cube tower of ...", "a tower of 2
        # red blocks and put the blue block ..." ("the 4 cube" is a label)
        said = None  # "stack 2 white cubes and a gray cube": the count is the white cubes', not the tower's
    twice = {i: h for i, h in hints.items() if i < len(items) and items.count(items[i]) > 1 and h in ("bottom", "base", "top")}
    at_ends = all(i == (0 if h in ("bottom", "base") else len(items) - 1) for i, h in hints.items())
    if twice and not at_ends:  # "red, blue, red, blue with blue at the bottom": the end that colour is listed at
        if len(hints) > 1:
            raise ParseError(f"in \"{f.original[:80]}\" a colour listed twice is given an end of the tower; say the whole "
                             "order from the bottom (e.g. \"from bottom to top: blue, red, blue, red\")")
        (i, h), = twice.items()
        want = 0 if h in ("bottom", "base") else len(items) - 1
        if items[len(items) - 1 - want] == items[i] and items[want] != items[i]:
            items.reverse()  # listed from the other end
        elif items[want] != items[i]:
            raise ParseError(f"in \"{f.original[:80]}\" the {items[i][0] or items[i][1]} cube given the {h} is at neither "
                             "end of the list; say the whole order from the bottom")
        hints = {want: h}
    if said is not None and len(items) > said and not re.search(r"\bthen\b", f.text):
        return False  # more cubes named than the tower's count: cubes of another part ("... and put the red block ...")
    if said is not None and len(items) > said:  # a sequence longer than its count
        raise ParseError(f"\"{f.original[:80]}\" lists {len(items)} cubes for a tower of {said}; say the count and the "
                         "list once (e.g. \"a tower of 3: red, blue, green\")")
    labels = explicit_labels(f)
    if not items and labels:
        hinted = re.findall(r"\b([A-Z0-9])\s+(?:(?:is|goes|sits|(?:should|must|will)\s+be|ends\s+up)\s+)?(?:on|at|as)\s+"
                            r"(?:the\s+)?(?:very\s+)?(bottom|base|top)\b", f.original)  # "so that T is on top"
        labels = list(labels)
        for lab, _ in hinted:  # "A, B, C and D, D at the bottom": the role names a listed cube again, not a fifth
            if labels.count(lab) > 1:
                del labels[len(labels) - 1 - labels[::-1].index(lab)]
        items = [(None, lab) for lab in labels]
        for lab, where in hinted:
            if (None, lab) in items:
                hints[items.index((None, lab))] = where
    n = stated_count(f, default=None)
    alternating = alternating_colors(f, 4)
    if alternating:
        items, hints = [(c, None) for c in alternating], {}
    if len(items) < 2 and f.has("rainbow", "gradient"):
        n = n or RAINBOW_TOWER
        spectrum = spectrum_of(f)
        items = [(c, None) for c in sorted(spectrum[:n], key=spectrum.index, reverse=f.has("reverse"))]
    elif 2 <= len(items) < (n or 0) and re.search(r"\bthen\b", f.text):  # a sequence shorter than its count
        raise ParseError(f"\"{f.original[:80]}\" lists {len(items)} cubes one after another for a tower of {n}; say every "
                         "cube of the sequence, or the count that it has")
    elif 1 <= len(items) < (n or 0) and hints:  # "three blocks high with a yellow block on top"
        used = {c for c, _ in items}
        items += [(c, None) for c in DEFAULT_COLORS if c not in used][: n - len(items)]
        filled = True  # cubes nobody named: the reverse accounting frees them (:mod:`rpg.schema.citations`)
    elif len(items) == 1 and set(hints.values()) & {"middle", "center", "centre"}:  # "a tower with blue in the middle"
        used = {c for c, _ in items}
        k = (n or 3) - 1
        others = [(c, None) for c in DEFAULT_COLORS if c not in used][:k]
        items = others[:k // 2] + items + others[k // 2:]
        hints = {k // 2: hints[0]}
    if len(items) < 2:
        return False
    levels: list[int] | None = None
    if re.search(r"\btop to bottom\b|\bin\s+(?:the\s+)?revers(?:e|ed)\s+order\b", f.text) and not (
            {"bottom", "base"} & set(hints.values()) or ("top" in hints.values() and len(items) > 2)):
        items.reverse()  # "... in the reversed order": the list read from its end (ends named are kept)
    else:
        role = {i: {"base": "bottom", "center": "middle", "centre": "middle"}.get(h, h) for i, h in hints.items()
                if i < len(items)}
        if len(items) > 2 and sorted(role.items()) == [(0, "top"), (len(items) - 1, "bottom")]:
            items.reverse()  # "1, 2, 3 and 4 ..., 4 at the bottom and 1 on top": the list read from the top
            role = {0: "bottom", len(items) - 1: "top"}
        elif len(items) > 2 and all(label for _, label in items) and role in ({0: "top"}, {len(items) - 1: "bottom"}):
            items.reverse()  # "digit cubes 9, 8, 7 with 9 on top": a label sequence whose first is the top, read from the top
            role = {len(items) - 1 - i: h for i, h in role.items()}
        bottom = [items[i] for i, h in role.items() if h == "bottom"]
        top = [items[i] for i, h in role.items() if h == "top"]
        middle = [items[i] for i, h in role.items() if h == "middle"]
        rest = [it for i, it in enumerate(items) if i not in role]  # by place: a colour may be listed twice
        below = max(0, len(items) // 2 - len(bottom))  # the middle cube at the middle of the whole tower
        listed = items
        items = bottom + rest[:below] + middle + rest[below:] + top
        direction = re.search(r"\b(?:(bottom)\s+(?:to|up\s+to)\s+(?:the\s+)?top|(top)\s+(?:to|down\s+to)\s+(?:the\s+)?bottom|from\s+the\s+(?:(bottom)\s+up"
                              r"|(top)\s+down))\b", f.text)
        if direction and not levels and not filled:  # "from top to bottom: red, blue, green, with red on top": the roles
            said = listed[::-1] if direction.group(2) or direction.group(4) else listed  # must agree with the order said
            at = {"bottom": 0, "top": len(said) - 1, "middle": len(said) // 2}  # (red had been put on top of the list read
            if any(said[at[h]] != listed[i] for i, h in role.items() if h in at and i in about_listed):  # upward: silently wrong)
                raise ParseError(f"\"{f.original[:80]}\" contradicts itself: the order it says ({direction.group(0)}) and "
                                 "the end or middle it gives a cube disagree; say the order once, or use --model")
            items = said if any(i in about_listed for i in role) else items
        if not middle and not filled and items != listed and len(rest) >= 2 and all(lab for _, lab in items) and not may_order_cubes(
                re.sub(r"\b(?:so|such)\s+that\b", " ", SEQ_HINT_RE.sub(" ", f.text))):
            # "stack T, O, P so that O is on top": the role moved a cube the list had elsewhere, so the list is
            # which cubes, not their order: the roles' places fixed, the rest in any order (listed colours are
            # freed the same way by :func:`rpg.schema.readers.free_listed_orders`)
            levels = [i if (i == 0 and bottom) or (i == len(items) - 1 and top) else -1 for i in range(len(items))]
        if middle:  # "a tower of red, blue and green blocks with blue in the middle": the roles, no order
            if len(items) % 2 == 0 or len(middle) > 1:
                raise ParseError(f"a tower of {len(items)} cubes has no one middle cube; say its place from the bottom")
            unhinted = SEQ_HINT_RE.sub(" ", f.text)
            if not (may_order_cubes(unhinted) or len(rest) < 2):
                place = {"bottom": 0, "middle": len(items) // 2, "top": len(items) - 1}
                levels = [-1] * len(items)
                for h, group in (("bottom", bottom), ("middle", middle), ("top", top)):
                    if group:
                        levels[place[h]] = place[h]
    names = [b.semantic(label) if label else b.cube(color) for color, label in items]
    b.place(stack_layout(names, C.WORKSPACE_CENTER))
    if levels is not None:
        b.preds += [UnorderedStack(tuple(names)), InLayers(tuple(names), tuple(levels))]
        b.summary.append("a tower of " + ", ".join(names) + " in any order, with "
                         + InLayers(tuple(names), tuple(levels)).describe())
        b.primitives += ["stack"]
        return True
    b.preds.append(Stack(tuple(names)))
    b.primitives += ["stack"]
    b.summary.append("tower bottom to top: " + ", ".join(names))
    return True


@reader(order=30)
def recognize_tower_clauses(f: Features, b: Builder) -> bool:
    """Towers described placement by placement (:mod:`rpg.schema.clauses`): "place a green
    block on the red block. place two more green blocks on the green block", "3 blue blocks on
    top of the 3 red blocks", "in the NW corner place a column of 3 green blocks", a row of
    cubes on top of a row (a wall)."""
    plan = clauses.read(mark_regions(f.text), COLOR_RE, canon_color)
    if plan is None:
        return False
    if plan.wall:
        layers, width = len(plan.wall), len(plan.wall[0])
        names = [b.cube(col) for layer in plan.wall for col in layer]
        b.place(grid_layout(names, 1, width, layers))
        b.preds.append(Grid(tuple(names), 1, width, layers))
        b.preds.append(InLayers(tuple(names), tuple(k for k, layer in enumerate(plan.wall) for _ in layer)))
        b.primitives += ["stack"]
        b.summary.append(f"a wall {width} cubes wide and {layers} high, layers bottom to top: "
                         + ", ".join(layer[0] for layer in plan.wall))
        b.summary.append(b.preds[-1].describe())
        return True
    refuse_towers_merged(f.text, f.original, len(plan.towers))
    spots: list[tuple[float, float] | None] = []
    unplaced = sum(r is None for r in plan.regions)
    free = iter(b.unit_centers(unplaced, 0.16) if unplaced else [])
    for region in plan.regions:
        spots.append(region_spots(region, 1)[0] if region else next(free))
    made: dict[tuple[int, int], str] = {}  # cubes are created in the order the text names them
    order = plan.order or [[0] * len(t) for t in plan.towers]
    cells = sorted((order[t][i], t, i) for t, tower in enumerate(plan.towers) for i in range(len(tower)))
    for _, t, i in cells:
        made[t, i] = b.cube(plan.towers[t][i])
    for t, (region, xy) in enumerate(zip(plan.regions, spots, strict=True)):
        names = [made[t, i] for i in range(len(plan.towers[t]))]
        b.place(stack_layout(names, xy))
        b.preds.append(Stack(tuple(names)))
        b.summary.append("tower bottom to top: " + ", ".join(names))
        if region:
            b.preds.append(InRegion(names[0], region))
            b.summary.append(f"{names[0]} in the {region.replace('_', ' ')} of the table")
    b.primitives += ["stack"]
    return True
