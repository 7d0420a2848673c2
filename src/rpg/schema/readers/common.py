"""Helpers the readers share: counts, colours, orders, mentions, references and spots.

Each helper reads one thing from :class:`~rpg.schema.reading.Features` (a count, a colour list,
an ordering, a direction) or places cubes (spots in a region, on a patch, free on the table),
so every reader that needs it reads it the same way.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass

from rpg.domain import constants as C
from rpg.domain.layouts import (
    line_layout,
)
from rpg.domain.palette import GRADIENT_ORDER, RAINBOW_ORDER
from rpg.domain.predicates import (
    SortedBy,
    region_boxes,
)
from rpg.domain.state import Pose
from rpg.schema import lexicon
from rpg.schema.builder import DEFAULT_COLORS, Builder
from rpg.schema.lexicon import COLOR_RE, REF_PREP, VOCAB
from rpg.schema.model import RepairRecord
from rpg.schema.reading import Features, ParseError, canon_color

COUNTED_GROUPS_RE = re.compile(
    rf"\b(\d+)\s+({COLOR_RE})(?:\s+(?:blocks?|cubes?))?((?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:(?:the\s+)?(?:\d+|an?)|the(?=\s+(?:{COLOR_RE})\s+(?:block|cube)\b))\s+(?:{COLOR_RE})"
    rf"(?:\s+(?:blocks?|cubes?))?)+(?!\s+(?:goal\s+)?patch)")
"""Counted colour groups said together: "2 red blocks and 2 blue blocks", "3 red, 3 green and 3 blue cubes",
"2 cyan cubes and a purple cube" (a later group's "a" is one), "the 2 yellow cubes and the 2 black cubes", "the 2 yellow
cubes and the black cube" (a later group's "the ... cube" is one)."""


def counted_groups(f: Features) -> list[tuple[int, str]]:
    """(count, colour) per group of one coordinated list of counted colour groups ("3 red and 2
    blue blocks" -> [(3, "red"), (2, "blue")]); empty when there is no such list."""
    m = COUNTED_GROUPS_RE.search(f.text)
    if m is None:
        return []
    return [(int(n) if n.isdigit() else 1, canon_color(c)) for n, c in re.findall(rf"\b(\d+|an?|the)\s+({COLOR_RE})\b", m.group(0))]


def stated_count(f: Features, nouns: str = "block|cube|box|piece|object", default: int | None = None) -> int | None:
    """The number of cubes said ("4 blocks"; counted colour groups add up: "2 red and 2 blue
    blocks" is 4), else ``default``."""
    groups = counted_groups(f) if nouns == "block|cube|box|piece|object" else []
    if groups:
        return sum(n for n, _ in groups)
    # (the words between are the noun's modifiers: "3 blue cubes into piles" counts cubes, not piles)
    m = re.search(rf"(?<!digit\s)(?<!number\s)(?<!numeral\s)\b(\d+)\s+(?:(?!(?:into|in|on|onto|cubes?|blocks?)\b)[a-z\-]+\s+){{0,3}}?"
                  rf"(?:{nouns})s?\b", f.text)  # ("the digit 4 cube" is a label, not four cubes: two had been made up, silently)
    if m:
        return int(m.group(1))
    return default


def colors_for(n: int, f: Features, prefer: list[str] | None = None) -> list[str]:
    given = prefer if prefer is not None else list(dict.fromkeys(f.color_list()))
    if len(given) >= n:
        return given[:n]
    rest = [c for c in DEFAULT_COLORS if c not in given]
    return given + rest[: n - len(given)]


def material_of(f: Features) -> str:
    """``letters``, ``digits``, ``mixed`` (letters, digits and colours) or ``colors``."""
    letters = f.has("letter", "letters", "alphabet", "alphabetical", "alphabetically")
    digits = f.has("number", "numbers", "digit", "digits", "numerical", "numerically", "numeric")
    if letters and digits:
        return "mixed"
    if letters or f.has("semantic"):
        return "letters"
    if digits:
        return "digits"
    return "colors"


def label_sequence(kind: str, n: int, b: Builder, ordered: bool = True) -> tuple[list[str], bool]:
    """``n`` labels of a kind (letters A.., digits 1..); repairs when distinct labels run out.

    Returns:
        (labels, strict): strict is False when labels had to repeat.

    Raises:
        ParseError: more labels than the domain has and the geometry cannot be kept.
    """
    pool = [chr(ord("A") + i) for i in range(C.MAX_DISTINCT_LETTERS)] if kind == "letters" else [str(d) for d in range(C.MAX_DISTINCT_DIGITS)]
    if kind == "digits" and n < C.MAX_DISTINCT_DIGITS:
        pool = pool[1:] + pool[:1]
    if n <= len(pool):
        return pool[:n], True
    b.repairs.append(RepairRecord(
        operator="REDUCE_LABELS_PRESERVE_GEOMETRY", stage="feasibility",
        reason=f"{n} cubes but only {len(pool)} distinct {kind}; labels repeat, the structure is kept"))
    if ordered:
        b.repairs.append(RepairRecord(
            operator="SWITCH_ORDERING_PATTERN", stage="feasibility",
            reason="strictly increasing order is impossible with repeated labels; non-decreasing order is required"))
    base = sorted(pool)
    return [base[i * len(base) // n] for i in range(n)], False


INITIAL_RE = re.compile(
    rf"[,;.]?\s*(?:with\s+|where\s+|and\s+)?(?:the\s+)?({COLOR_RE})\s+(?:block\s+|cube\s+)?"
    rf"(?:starts|starting|begins|is initially|initially|starts out)\s+(?:stacked\s+)?(?:on top of|on)\s+"
    rf"(?:the\s+)?({COLOR_RE})(?:\s+block|\s+cube)?"
)


INITIAL_STACK_RE = re.compile(
    rf"\b(?:starting|start|beginning|begin)\s+(?:from|with)\s+(?:a\s+|the\s+)?(?:stack|tower)\s+of\s+(?:the\s+)?"
    rf"({COLOR_RE})\s+(?:block\s+|cube\s+)?(?:on top of|on)\s+(?:the\s+)?({COLOR_RE})(?:\s+block|\s+cube)?"
    rf"(?:\s*,\s*|\s+)(?:then\s+)?(?:(?:unstack|separate|take)\s+(?:them|it|the\s+stack)(?:\s+apart)?\s*(?:,\s*)?(?:and\s+)?(?:then\s+)?)?")


def initial_clause(text: str) -> tuple[int, int, str, str] | None:
    """Find "yellow starts stacked on red" or "starting from a stack of yellow on red,
    unstack them and ...": (start, end, bottom colour, top colour)."""
    m = INITIAL_RE.search(text)
    if m:
        return m.start(), m.end(), canon_color(m.group(2)), canon_color(m.group(1))
    m = INITIAL_STACK_RE.search(text)
    if m:
        return m.start(), m.end(), canon_color(m.group(2)), canon_color(m.group(1))
    return None


def single_label(f: Features) -> str | None:
    m = re.search(r"\b(?:letter|number|digit|label)\s+'?([A-Za-z0-9])'?(?![A-Za-z0-9])", f.original, re.IGNORECASE)
    if m:
        return m.group(1).upper()
    for q in f.quoted:
        if len(q.strip()) == 1:
            return q.strip().upper()
    if re.search(r"\b(?:the|a)\s+(?:letter|digit|number)\s+(?:block|cube)\b", f.text):  # "turn the letter cube"
        return "A" if re.search(r"\bletter\s+(?:block|cube)\b", f.text) else "1"
    return None


def orientation_showing(face: str, direction: str) -> tuple[float, float, float, float]:
    """Quaternion that turns a cube's local ``face`` toward ``direction``, glyph upright."""
    import mujoco
    import numpy as np

    from rpg.domain.glyphs import FACE_NORMALS, GLYPH_UP
    from rpg.domain.state import DIRECTIONS, READING_UP

    n, u = np.array(FACE_NORMALS[face]), np.array(GLYPH_UP[face])
    dn, du = np.array(DIRECTIONS[direction]), np.array(READING_UP[direction])
    local = np.stack([n, u, np.cross(n, u)], axis=1)
    world = np.stack([dn, du, np.cross(dn, du)], axis=1)
    R = world @ local.T
    q = np.zeros(4)
    mujoco.mju_mat2Quat(q, R.flatten())
    return tuple(round(float(v), 9) for v in q)


def direction_of(f: Features, default: str = "left_to_right") -> str:
    if f.has("right to left"):
        return "right_to_left"
    if re.search(r"\bfront to back\b", f.text):
        return "front_to_back"
    if re.search(r"\bback to front\b", f.text):
        return "back_to_front"
    return default


def direction_stated(f: Features) -> bool:
    """Whether the instruction says which way a sequence runs ("from left to right")."""
    return bool(re.search(r"\b(?:left to right|right to left|front to back|back to front)\b", f.text))


def line_axis_said(f: Features) -> str | None:
    """The axis a line's words give: ``"x"`` (front-back: "vertical", "front to back"),
    ``"y"`` (left-right: "horizontal", "left to right", "side by side"), or None when they
    name none ("line up the blocks": any straight line on the table)."""
    if f.has("vertical", "vertically", "front to back", "back to front", "depth", "front-back", "back-front"):
        return "x"
    if f.has("horizontal", "horizontally", "left to right", "right to left", "side by side", "left-right", "sideways"):
        return "y"
    return None


def spelled_word(f: Features) -> str | None:
    for q in f.quoted:
        if re.fullmatch(r"[A-Za-z]{2,}", q.strip()):
            return q.strip().upper()
    m = re.search(r"\b(?:spell|spells|spelling|spelled|spelt)\s+(?:out\s+)?(?:the\s+)?(?:word\s+|name\s+)?'?([A-Za-z]{2,})'?", f.original, re.IGNORECASE)
    if m and (m.group(1).lower() not in VOCAB or m.group(1).isupper()):
        return m.group(1).upper()
    m = re.search(r"\bword\s+'?([A-Za-z]{2,})'?", f.original, re.IGNORECASE)
    if m:
        return m.group(1).upper()
    m = re.search(r"\b(?:read|reads|reading|show|shows|showing|say|says|saying)\s+'?([A-Z]{2,})'?(?![A-Za-z])", f.original)
    if m:
        return m.group(1)
    return None


def ordering_of(f: Features) -> tuple[str, bool] | None:
    """(sort key, descending) asked for, if any."""
    desc = f.has("reverse", "reversed", "descending", "decreasing", "decrease", "decreases", "backwards") or bool(
        re.search(r"\b(?:largest|highest|biggest|greatest)(?: number| digit| value)? to (?:smallest|lowest|least)\b", f.text))
    if f.has("alphabetical", "alphabetically", "alphabet"):
        return "label", desc
    if f.has("numerical", "numerically", "increasing", "ascending", "decreasing", "descending", "numeric",
             "increase", "increases", "decrease", "decreases") or re.search(
            r"\b(?:smallest|lowest|least|largest|highest|biggest|greatest)(?: number| digit| value)? to "
            r"(?:largest|highest|biggest|greatest|smallest|lowest|least)\b", f.text):
        return "number", desc
    if f.has("gradient", "rainbow", "hue"):
        return "color", desc
    return None


def spectrum_of(f: Features) -> list[str]:
    """Colours in hue order: a rainbow's (:data:`palette.RAINBOW_ORDER`, then the rest of the
    gradient) when the text says "rainbow", else :data:`palette.GRADIENT_ORDER`."""
    if f.has("rainbow"):
        return list(RAINBOW_ORDER) + [c for c in GRADIENT_ORDER if c not in RAINBOW_ORDER]
    return list(GRADIENT_ORDER)


def fill_structure(f, b, n, material, order, layout_fn, face="up"):
    """Create n cubes of a material in reading order, lay them out, add ordering predicates."""
    if material in ("letters", "digits"):
        labels, strict = label_sequence(material, n, b, ordered=order is not None)
        if order and order[1]:
            labels = list(reversed(labels))
        names = [b.semantic(lab) for lab in labels]
        b.place(layout_fn(names))
        if order:
            key = "label" if material == "letters" else "number"
            b.preds.append(SortedBy(tuple(names), key=key, direction="reading", descending=order[1], strict=strict, face=face))
            b.summary.append(f"{'letters' if key == 'label' else 'digits'} {'descending' if order[1] else 'ascending'} in reading order ({'front' if face == 'front' else 'visible'} faces)")
        return names
    groups = counted_groups(f)
    if groups and sum(k for k, _ in groups) == n and not order:  # "2 red and 2 blue blocks": each group's count
        names = [b.cube(c) for k, c in groups for _ in range(k)]
        b.place(layout_fn(names))
        return names
    colors = list(dict.fromkeys(f.color_list()))
    if len(f.color_list()) == n and len(colors) > 1 and not (order and order[0] == "color"):
        names = [b.cube(c) for c in f.color_list()]  # one colour named per cube: use them as listed
        b.place(layout_fn(names))
        return names
    if order and order[0] == "color" or f.has("different", "assorted", "various", "mixed", "rainbow"):
        palette = colors or spectrum_of(f)
        cols = [palette[i % len(palette)] for i in range(n)] if len(colors) != 1 else colors * n
    else:
        cols = (colors or ["red"]) * n if len(colors) <= 1 else [colors[i % len(colors)] for i in range(n)]
    names = [b.cube(c) for c in cols[:n]]
    b.place(layout_fn(names))
    return names


def asks_per_layer(f: Features) -> bool:
    """"each layer (row, level) a different color"."""
    return f.has("row", "rows", "layer", "layers", "level", "levels") and f.has("different", "each")


def outlier_count(f: Features) -> int:
    """Outliers per pile asked for ("so each has one outlier"), 0 if none."""
    if not f.has("outlier", "outliers"):
        return 0
    m = re.search(r"\b(\d+)\s+outliers?\b", f.text)
    return int(m.group(1)) if m else 1


def alternating_colors(f: Features, default: int) -> list[str] | None:
    """``n`` colours cycling through the named ones for "alternating red and blue ..."."""
    said = f.color_list()
    colors = list(dict.fromkeys(said))
    if not f.has("alternating", "alternate", "alternately", "alternates") or len(colors) == 1 or material_of(f) != "colors":
        return None
    colors = colors or list(DEFAULT_COLORS[:2])  # "so that the colors alternate"
    counts = [int(c) for c in re.findall(rf"\b(\d+)\s+(?:{COLOR_RE})\s+(?:blocks|cubes)\b", f.text)]
    if len(said) >= 2 * len(colors) and said == [colors[i % len(colors)] for i in range(len(said))]:
        # "alternating colours: red, white, red, white": the cubes listed, not 6
        default = len(said)
    n = sum(counts) if len(counts) >= 2 else max(stated_count(f, default=default), len(colors))  # "two red and two blue"
    end = re.search(rf"\b(?:start(?:ing|s)?|begin(?:ning|s)?)\s+(?:with|from)\s+(?:an?\s+|the\s+)?(?P<first>{COLOR_RE})\b"
                    rf"|\b(?P<c>{COLOR_RE})\s+(?:block\s+|cube\s+|one\s+)?(?:at|on|as)\s+(?:the\s+)?(?P<end>bottom|base|top)\b", f.text)
    for shift in range(len(colors)):  # "..., blue at the bottom", "starting with blue": the cycle that has it there
        cycle = [colors[(i + shift) % len(colors)] for i in range(n)]
        if end is None or (canon_color(end.group("first") or end.group("c"))
                           == cycle[-1 if end.group("end") == "top" else 0]):
            return cycle
    raise ParseError(f"'{end.group(0)}' names a colour the alternation of \"{f.original[:80]}\" does not have at that end; "
                     "say the order from the bottom")


def line_axis(direction: str) -> str:
    """The table axis a line read in ``direction`` runs along: ``x`` front-back, else ``y``."""
    return "x" if direction in ("front_to_back", "back_to_front") else "y"


def directed_line(names: list[str], direction: str) -> dict[str, Pose]:
    """A line layout whose cubes read ``names`` in ``direction`` (left to right, right to
    left, front to back or back to front)."""
    forward = direction in ("left_to_right", "front_to_back")
    return line_layout(names if forward else list(reversed(names)), axis=line_axis(direction))


@dataclass
class Mention:
    start: int
    end: int
    color: str | None
    label: str | None
    count: int
    patch: bool = False
    shape: str = "square"
    each_other: bool = False
    ref: str | None = None
    """``@s`` (the stack/tower the task builds), ``@it`` or ``@them`` (the previous
    relation's object): a reference, resolved by :func:`recognize_relational`."""
    another: bool = False
    """Said as one more of its kind ("another green block", "a second green block"): a cube of
    its own, not the one of that colour named before."""


STRUCTURE_REF_RE = re.compile(
    REF_PREP + r"(?:the|that|this|your)\s+(?:(?:same|new|finished|first|whole)\s+)?(?:stack|tower|pile|structure)\b"
    r"(?:\s+of\s+(?:the\s+)?(?P<colors>(?:(?:" + COLOR_RE + r")(?:\s*,\s*(?:and\s+)?|\s+and\s+|\s+))*(?:"
    + COLOR_RE + r"))(?:\s+(?:blocks|cubes))?\b)?")


PRONOUN_REF_RE = re.compile(REF_PREP + r"(it|them)\b")


REF_TOKEN_RE = re.compile(r"@(?:s|it|them)\b(?:\{[a-z,]*\})?")


def mark_references(text: str) -> str:
    """Mark the objects that refer back: "beside the stack" -> "beside @s", "in front of
    it" -> "in front of @it" (only after a relation word, so "make it" stays as it is).
    A described stack ("behind the tower of red and blue") keeps its colours as
    ``@s{red,blue}``."""
    def structure(m: re.Match) -> str:
        colors = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.group("colors") or "")]
        return f"{m.group(1)} @s" + ("{" + ",".join(colors) + "}" if colors else "")

    text = STRUCTURE_REF_RE.sub(structure, text)
    return PRONOUN_REF_RE.sub(lambda m: f"{m.group(1)} @{m.group(2)}", text)


def structure_colors(text: str) -> list[str]:
    """The colours of a described stack in marked text (``@s{red,blue}``), bottom to top."""
    m = re.search(r"@s\{([a-z,]+)\}", text)
    return m.group(1).split(",") if m else []


MENTION_RE = re.compile(
    r"(?:\b(?P<count>\d+)\s+)?(?:\b(?:the|a|an|another|one)\s+)?(?:long\s+(?=(?:" + COLOR_RE + r")\s+(?:goal\s+|target\s+)?patch))?"
    r"(?:(?P<color>" + COLOR_RE + r")\s+)?"
    r"(?:(?P<pre>long|square|target|goal|designated|color-specific|colored|matching)\s+){0,3}"
    r"(?:(?:letter|number|digit|semantic)\s+'?(?P<label>[a-z0-9])'?\s+(?:semantic\s+)?)?"
    r"(?P<noun>patch(?:es)?|blocks?|cubes?|boxes?)\b"
    r"(?:\s+(?:with|showing|marked|labell?ed)\s+(?:with\s+)?(?:the\s+|an?\s+)?(?:letter|digit|number|label)\s+'?(?P<label2>[a-z0-9])'?(?![a-z0-9])"
    r"|\s+(?:labell?ed|marked)\s+(?:with\s+)?'?(?P<label3>[a-z0-9])'?(?![a-z0-9]))?"
    r"|\b(?P<bare>" + COLOR_RE + r")\b(?!\s+(?:block|cube|box|patch|long|square|goal|target))"
)


ANOTHER_BEFORE_RE = re.compile(r"\b(?:a|the)\s+(?:second|2nd|third|3rd|other)\s+$|\bone\s+more\s+$")
"""Words just before a mention that make it one more cube of its kind ("a second green block",
"one yellow block ... the other yellow block")."""


def mentions_in(text: str) -> list[Mention]:
    out = [Mention(m.start(), m.end(), None, None, 1, ref=m.group(0).split("{")[0]) for m in REF_TOKEN_RE.finditer(text)]
    for m in MENTION_RE.finditer(text):
        if m.group("bare"):
            out.append(Mention(m.start(), m.end(), canon_color(m.group("bare")), None, 1))
            continue
        noun = m.group("noun")
        plural = noun.endswith("s") and not noun.endswith("ss") or noun.endswith("es")
        count = int(m.group("count")) if m.group("count") else (2 if plural else 1)
        pre = m.group(0)
        out.append(Mention(
            m.start(), m.end(), canon_color(m.group("color")) if m.group("color") else None,
            (m.group("label") or m.group("label2") or m.group("label3") or "").upper() or None, count,
            patch=noun.startswith("patch"), shape="long" if "long" in pre else "square",
            another=bool(re.match(r"another\b", pre) or ANOTHER_BEFORE_RE.search(text[:m.start()])),
        ))
    out.sort(key=lambda mn: mn.start)
    for before, mn in itertools.pairwise(out):
        # "the red and blue blocks": the plural is the list's, one cube of each colour (it read two blue)
        if (mn.count == 2 and before.color and not before.patch and before.end <= mn.start and before.count == 1
                and re.fullmatch(r"\s*(?:,\s*and|,|and|&)\s*(?:the\s+)?", text[before.end:mn.start])
                and not re.match(r"\d", text[mn.start:]) and re.fullmatch(COLOR_RE, text[before.start:before.end])):
            mn.count = 1
    return out


DESCRIBED_TOWER_RE = re.compile(rf"\b(?:a|an|one|another)\s+(?:tower|stack)\s+of\s+(\d+)\s+({COLOR_RE})\s+(?:blocks|cubes)\b")


REGION_PITCH = 0.06
"""Centre spacing of cubes placed together in one region of the table, m."""

REGION_MARGIN = 0.005
"""Least distance of a cube's centre inside its region's border in a structure's goal layout,
m: :class:`~rpg.domain.predicates.InRegion` reads the centre, so the witness keeps clear of it."""


def region_table_pose(region: str) -> Pose:
    """A goal pose for one cube resting on the table in ``region`` (world frame, m)."""
    return Pose((*region_spots(region, 1)[0], C.TABLE_TOP_Z + C.CUBE_EDGE / 2))


def region_spots(region: str, n: int) -> list[tuple[float, float]]:
    """``n`` goal positions in a region of the workspace: rows along y about its centre.

    Raises:
        ParseError: the region cannot hold ``n`` cubes.
    """
    (x0, x1), (y0, y1) = region_boxes(region)[0]  # a group ("corner"): its first member holds the witness
    per_row = max(1, min(n, int((y1 - y0 - C.CUBE_EDGE) // REGION_PITCH) + 1))
    rows = -(-n // per_row)
    if (rows - 1) * REGION_PITCH + C.CUBE_EDGE > x1 - x0 + 1e-9:
        raise ParseError(f"{n} cubes do not fit in the {region.replace('_', ' ')} of the table; use fewer or a larger region")
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    return [(cx + (k // per_row - (rows - 1) / 2) * REGION_PITCH,
             cy + (k % per_row - (min(per_row, n - (k // per_row) * per_row) - 1) / 2) * REGION_PITCH) for k in range(n)]


PATCH_PITCH = 1.05 * C.CUBE_EDGE
"""Centre spacing of cubes that share a goal patch in the goal layout, m (5% gap)."""


def patch_spots(center: tuple[float, float], shape: str, n: int) -> list[tuple[float, float]]:
    """Goal positions of ``n`` cubes on one patch: a row along the patch's length while
    they fit, else two rows (a square patch holds 2x2 cubes with their centres inside).

    Raises:
        ParseError: more cubes than the patch holds (the message says to use a long patch).
    """
    px, py = center
    length = C.LONG_PATCH_SIZE[1] if shape == "long" else C.PATCH_SIZE[1]
    per_row = int((length - C.CUBE_EDGE) / C.CUBE_EDGE + 1e-9) + 1  # one row: touching cubes end to end
    rows = 1 if n <= per_row else 2
    if n > 2 * per_row:
        raise ParseError(f"{n} cubes do not fit on one {shape} goal patch (it holds {2 * per_row}); "
                         "use a long patch or fewer cubes")
    cols = -(-n // rows)
    if n == 1:
        return [(px, py)]
    if rows == 1:
        span = min(length - C.CUBE_EDGE, 1.2 * C.CUBE_EDGE * (n - 1))
        return [(px, py + (i / (n - 1) - 0.5) * span) for i in range(n)]
    return [(px + (r - 0.5) * PATCH_PITCH, py + (c - (cols - 1) / 2) * PATCH_PITCH)
            for r in range(rows) for c in range(cols)][:n]


def free_spots(occupied: list[tuple[float, float]], n: int) -> list[tuple[float, float]]:
    cands = [(x, y) for x in (0.55, 0.47, 0.63) for y in (0.0, 0.12, -0.12, 0.2, -0.2, 0.06, -0.06)]
    out = []
    for x, y in cands:
        if all(math.hypot(x - ox, y - oy) >= 0.09 for ox, oy in occupied + out):
            out.append((x, y))
        if len(out) == n:
            break
    if len(out) < n:
        raise ParseError("too many objects to lay out on the table")
    return out


ITEM_RE = re.compile(
    r"\b(?:letter|digit|number|label)\s+'?(?P<label>[a-z0-9])'?(?![a-z0-9])(?:\s+(?:semantic\s+)?(?:cube|block)s?)?"
    r"|\b(?P<color>" + COLOR_RE + r")\b(?:\s+(?:cube|block)s?)?"
)


def item_sequence(text: str) -> list[tuple[str | None, str | None]]:
    """Cubes named in order in ``text``: (colour, None) or (None, label) per mention."""
    out = []
    for m in ITEM_RE.finditer(text):
        if m.group("label"):
            out.append((None, m.group("label").upper()))
        else:
            out.append((canon_color(m.group("color")), None))
    return out


def tower_order(f: Features) -> bool | None:
    """Whether a sorted tower descends from the bottom up (largest at the bottom); None
    when the text gives no order.  Reads "in increasing order", "from largest to smallest
    going up", "with the smallest at the bottom", "A on the bottom", "1 on top"."""
    small = r"(?:smallest|lowest|least|first|a|1|0)"
    large = r"(?:largest|highest|biggest|greatest|last|z|9)"
    where = r"\s+(?:\w+\s+){0,2}?(?:on|at)\s+(?:the\s+)?(?:very\s+)?"
    for pattern, desc in ((small + where + r"(?:bottom|base)\b", False), (large + where + r"(?:bottom|base)\b", True),
                          (small + where + r"top\b", True), (large + where + r"top\b", False)):
        if re.search(r"\b" + pattern, f.text):
            return desc
    order = ordering_of(f)
    if order is None:
        return None
    return order[1] != bool(re.search(r"\btop to bottom\b|\bgoing down\b|\bdownwards?\b", f.text))


def refuse_towers_merged(text: str, original: str, towers: int) -> None:
    """Refuse a reading of ``towers`` towers (one or more) where ``text`` asks for more, each said as one of its own
    (:data:`rpg.schema.lexicon.A_TOWER_RE`: "a red-on-yellow tower and a blue-on-red tower" had become one tower, the red cube shared).

    Raises:
        ParseError: naming both counts.
    """
    said = len(lexicon.A_TOWER_RE.findall(text))
    if said > towers >= 1:
        raise ParseError(f"\"{original[:80]}\" asks for {said} towers, and its cubes make {towers}: a colour said in two "
                         "towers names one cube; give the towers different colours or count the cubes (e.g. \"two red "
                         "cubes\"), or use --model")
