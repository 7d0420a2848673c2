"""Towers described clause by clause, the way people give building instructions.

Human block-building instructions (e.g. the IGLU corpus) describe a tower as a sequence of
placements, each a group of cubes put on top of or under a cube already named::

    Place a green block on the red block. Place two more green blocks on the green block.
    Add one blue block under the red block. Then add 3 green blocks on top of red block.
    On top of the red block place one blue block then two yellow blocks.
    Place 3 blue blocks on top of the 3 red blocks.                  (three towers of two)
    In the NW corner place a column of 3 green blocks. In the NE corner place ...
    Place a column of 2 yellow blocks in each of the four corners.
    Build a horizontal row of 3 purple blocks on top of the horizontal row of 3 red blocks.

:func:`read` turns such text into a :class:`Plan` (towers bottom to top, their places on the
table, or a wall's layers), or returns None when any part of the text is not a placement it
can read; the caller then tries other readings or refuses.  Counts attach to their group
("three green blocks" is three cubes), and a reference ("the green block", "it", "that", "the
stack") resolves to a cube already placed: the topmost of that colour for "on top of", the
lowest for "under".  Nothing is filled in by default: a text that names no colour for a group
is not read here.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

ABOVE = r"on\s+top\s+of|on|onto|atop|above|over"
BELOW = r"under|underneath|below|beneath"
NOUN = r"(?:blocks?|cubes?|box(?:es)?|ones?)"
CONTAINER = r"(?:stack|tower|column|pillar|pile)"
VERBS = r"place|put|stack|add|build|set|lay|make|create|construct|position|move|drop|pick|take|grab"
FILLER = re.compile(
    rf"\b(?:{VERBS}|on\s+top\s+of\s+(?:it|that)|then|and|also|more|additional|extra|stacked|vertically|it|that|in\s+a\s+stack|"
    rf"to\s+make\s+a\s+(?:stack|tower|column)|making\s+a\s+(?:longer\s+|taller\s+)?(?:stack|tower|pillar|column)|"
    r"on\s+the\s+table|straight\s+up|up|spot|horizontal|horizontally|vertical|vertically|(?:a|the)\s+(?:tower|stack|column)(?=\s*[:,])|the)\b|[.,;:!]")
"""Words a placement clause may carry besides its cubes, relation and reference."""

STACKED = re.compile(r"\b(?:stack|stacks|stacked|tower|towers|column|columns|pillar|vertical|vertically|"
                     r"on\s+top\s+of\s+(?:each\s+other|one\s+another))\b")
"""Words that say a group of cubes named on its own stands one on another."""


@dataclass
class Plan:
    """What the clauses describe.

    Attributes:
        towers: colours bottom to top, one list per tower.
        regions: a region name (:data:`rpg.domain.constants.REGION_NAMES`) per tower, or None.
        wall: for a wall of rows, its layers' colours bottom to top (towers is then empty).
    """

    towers: list[list[str]] = field(default_factory=list)
    regions: list[str | None] = field(default_factory=list)
    wall: list[list[str]] = field(default_factory=list)
    order: list[list[int]] = field(default_factory=list)
    """For each tower's cubes, the order in which the text first names them (empty: tower order)."""


@dataclass
class _Clause:
    items: list[str]
    rel: str | None          # "above", "below" or None
    ref: str | None          # colour, "it" or None
    ref_count: int = 0
    region: str | None = None
    row: int = 0             # items form a row of this many cubes
    ref_row: int = 0
    definite: set[str] = field(default_factory=set)  # colours named as "red" / "the red block"
    start: int = 0           # offset of the clause in the text
    fronted: bool = False    # the reference comes before the cubes ("on top of the red block place ...")


def _num(word: str | None) -> int:
    if word in (None, "a", "an", "one", "another"):
        return 1
    return int(word)


class _Grammar:
    def __init__(self, colors: str, canon):
        c = rf"(?:{colors})"
        self.canon = canon
        group = rf"(?:(?P<q>a|an|one|another|\d+)\s+)?(?:(?:more|additional|extra)\s+)?(?P<c>{c})(?:\s+{NOUN})?"
        self.group = re.compile(group)
        sep = r"(?:\s*,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+then\s+|\s+then\s+|\s+and\s+|\s+followed\s+by\s+|\s+)"
        plain = rf"(?:(?:a|an|one|another|\d+)\s+)?(?:(?:more|additional|extra)\s+)?{c}(?:\s+{NOUN})?"
        items = rf"(?:{plain}(?:{sep}{plain})*)"
        box = rf"(?:a|an|one)\s+{CONTAINER}\s+(?:of|with)\s+(?P<bn>\d+)\s+(?:(?:more|additional|extra)\s+)?(?P<bc>{c})(?:\s+{NOUN})?"
        row = rf"(?:a|an|one)\s+(?:horizontal\s+)?(?:row|line)\s+of\s+(?P<rn>\d+)\s+(?P<rc>{c})(?:\s+{NOUN})?"
        self.items = re.compile(rf"{box}|{row}|(?P<list>{items})")
        bare = re.sub(r"\(\?P<[a-z0-9]+>", "(?:", self.items.pattern)
        ref = (rf"(?:(?:the|a|an)\s+)?(?:(?P<rcount>\d+)\s+)?(?:single\s+|only\s+|first\s+)?(?P<rcol>{c})"
               rf"(?:\s+(?:{NOUN}|{CONTAINER}))?(?:\s+{CONTAINER})?"
               rf"|(?P<rrow>(?:the|a)\s+(?:horizontal\s+)?(?:row|line)\s+of\s+(?:the\s+)?(?P<rrn>\d+)\s+(?P<rrc>{c})(?:\s+{NOUN})?)"
               rf"|(?P<pron>it|that|them|the\s+(?:{CONTAINER}|top))\b")
        rel = rf"(?P<rel>{ABOVE}|{BELOW})"
        region = r"(?:\s*(?P<region>@region_[a-z_]+|(?:in|on|at|to)\s+(?:each|every|all)\s+(?:of\s+the\s+)?(?:\d+\s+)?corners?(?:\s+of\s+the\s+table)?))"
        self.fwd = re.compile(rf"(?P<items>{bare})(?:\s+(?:in\s+a\s+stack|stacked|vertically|vertical))?\s+{rel}\s+(?P<ref>{ref}){region}?")
        self.fronted = re.compile(rf"{rel}\s+(?P<ref>{ref})\s*,?\s*(?:(?:{VERBS})\s+)?(?P<items>{bare})")
        self.alone = re.compile(rf"{region}\s*,?\s*(?:(?:{VERBS})\s+)?(?P<items>{bare})")
        self.alone2 = re.compile(rf"(?P<items>{bare}){region}")
        self.on_top = re.compile(rf"(?:(?<=then\s)|(?<=then,\s))(?:(?:{VERBS})\s+)?(?P<items>{bare})(?!\s+(?:{ABOVE}|{BELOW})\b)"
                                 rf"|(?P<items_top>{bare})\s+on\s+top\b(?!\s+of)")

    def colors_of(self, m: re.Match, key: str = "items") -> tuple[list[str], int, set[str]]:
        """(colours of the group's cubes, row length or 0, colours named without a count or article)."""
        text = m.group(key)
        im = self.items.fullmatch(text)
        if im is None:
            return [], 0, set()
        if im.group("bn"):
            return [self.canon(im.group("bc"))] * int(im.group("bn")), 0, set()
        if im.group("rn"):
            return [self.canon(im.group("rc"))] * int(im.group("rn")), int(im.group("rn")), set()
        out, definite = [], set()
        for g in self.group.finditer(im.group("list")):
            if g.group("q") is None and not re.search(rf"\b(?:more|additional|extra)\s+{g.group('c')}\b", g.group(0)):
                definite.add(self.canon(g.group("c")))
            out += [self.canon(g.group("c"))] * _num(g.group("q"))
        return out, 0, definite


@lru_cache(maxsize=4)
def _grammar(colors: str, canon) -> _Grammar:
    return _Grammar(colors, canon)


def _clauses(text: str, g: _Grammar) -> list[_Clause] | None:
    """The placement clauses of ``text`` in order, or None if any content word is left over."""
    found: list[tuple[int, int, _Clause]] = []
    taken = [False] * len(text)
    for kind, pat in (("fronted", g.fronted), ("fwd", g.fwd), ("alone", g.alone), ("alone", g.alone2),
                      ("top", g.on_top)):
        for m in pat.finditer(text):
            if any(taken[m.start():m.end()]):
                continue
            items, row, definite = g.colors_of(m, "items_top" if m.groupdict().get("items_top") else "items")
            if not items:
                continue
            region = m.groupdict().get("region")
            cl = _Clause(items, None, None, region=region.strip() if region else None, row=row, definite=definite,
                         start=m.start(), fronted=kind == "fronted")
            if kind == "top":  # "then a red block", "add one red block on top": on the top of the tower
                cl.rel, cl.ref = "above", "top"
            elif kind != "alone":
                cl.rel = "below" if re.fullmatch(BELOW, m.group("rel")) else "above"
                if m.group("pron"):  # "on the stack", "on top": the tower's top; "on it": the cube named last
                    cl.ref = "top" if m.group("pron").startswith("the") and cl.rel == "above" else "it"
                elif m.group("rrow"):
                    cl.ref, cl.ref_row = g.canon(m.group("rrc")), int(m.group("rrn"))
                else:
                    cl.ref, cl.ref_count = g.canon(m.group("rcol")), int(m.group("rcount") or 0)
            found.append((m.start(), m.end(), cl))
            for i in range(m.start(), m.end()):
                taken[i] = True
    left = "".join(" " if t else ch for ch, t in zip(text, taken, strict=True))
    if FILLER.sub(" ", left).strip() or not found:
        return None
    return [cl for _, _, cl in sorted(found, key=lambda t: t[0])]


def _corners(region: str | None) -> bool:
    return bool(region) and not region.startswith("@")


def read(text: str, colors: str, canon) -> Plan | None:
    """Read ``text`` (normalised, places as ``@region_<name>`` tokens) as towers built clause
    by clause; None if it is not such a text.

    Args:
        colors: regular-expression alternation of colour words.
        canon: maps a colour word to its palette name.
    """
    clauses = _clauses(text, _grammar(colors, canon))
    if not clauses:
        return None
    if any(cl.row or cl.ref_row for cl in clauses):  # rows on rows: a wall
        if len(clauses) != 1 or not (clauses[0].row and clauses[0].ref_row == clauses[0].row) or clauses[0].rel != "above":
            return None
        cl = clauses[0]
        return Plan(wall=[[cl.ref] * cl.ref_row, cl.items])
    if len(clauses) == 1 and clauses[0].ref_count > 1:  # "3 blue blocks on top of the 3 red blocks"
        cl = clauses[0]
        k = cl.ref_count
        if len(cl.items) % k or cl.rel != "above":
            return None
        per = len(cl.items) // k
        return Plan(towers=[[cl.ref] + cl.items[i * per:(i + 1) * per] for i in range(k)], regions=[None] * k)
    towers: list[list[str]] = []
    keys: list[list[tuple[int, int]]] = []  # where the text names each cube: (clause offset, position)
    regions: list[str | None] = []
    prev_ref: tuple[int, int] | None = None   # (tower, index) of the last clause's reference
    prev_items: tuple[int, int] | None = None  # (tower, index of its top cube)
    for cl in clauses:
        if any(col in tw for tw in towers for col in cl.definite):
            return None  # "put red on blue and blue on red": a cube already placed is moved again
        if cl.rel is None:  # a group standing on its own: a new tower (in a place, or the first)
            if towers and not cl.region:
                return None
            if len(cl.items) > 1 and not STACKED.search(text):
                return None  # "two red blocks in the corner": side by side or stacked is not said
            towers.append(list(cl.items))
            keys.append([(cl.start, k) for k in range(len(cl.items))])
            regions.append(cl.region)
            prev_ref, prev_items = None, (len(towers) - 1, len(cl.items) - 1)
            continue
        if cl.ref in ("it", "top"):
            anchor = prev_ref or prev_items
            if anchor is None:
                return None
            if cl.ref == "top":
                anchor = (anchor[0], len(towers[anchor[0]]) - 1)
            elif cl.rel == "above" and anchor[1] != len(towers[anchor[0]]) - 1:
                return None  # "red on blue, then green on it": on red (the top) or between them? not said
        else:
            hits = [(t, i) for t, tw in enumerate(towers) for i, col in enumerate(tw) if col == cl.ref]
            if not hits:
                if towers and not cl.region:
                    return None
                towers.append([cl.ref])
                keys.append([(cl.start, 0 if cl.fronted else len(cl.items))])
                regions.append(cl.region)
                anchor = (len(towers) - 1, 0)
            else:
                if len({t for t, _ in hits}) > 1:
                    return None  # which tower is meant is not said
                anchor = max(hits, key=lambda h: h[1]) if cl.rel == "above" else min(hits, key=lambda h: h[1])
                t0, i0 = anchor
                if (cl.rel == "above" and i0 + 1 < len(towers[t0]) and len(set(towers[t0])) == len(towers[t0])) or (
                        cl.rel == "below" and i0 > 0):
                    return None  # "red on green. white on green": green has a cube on it already (white had been put
                    # between them, so red was no longer on green: silently against the first clause)
        t, i = anchor
        if cl.region and regions[t] not in (None, cl.region):
            return None
        regions[t] = regions[t] or cl.region
        at = i + 1 if cl.rel == "above" else i
        towers[t][at:at] = cl.items
        keys[t][at:at] = [(cl.start, k + (1 if cl.fronted else 0)) for k in range(len(cl.items))]
        shift = len(cl.items) if cl.rel == "below" else 0
        prev_ref = (t, i + shift)
        prev_items = (t, at + len(cl.items) - 1)
    if any(len(tw) < 2 for tw in towers):
        return None
    if len(towers) == 1 and _corners(regions[0]):  # one tower "in each of the four corners"
        return Plan(towers=[list(towers[0]) for _ in range(4)],
                    regions=["back_left", "back_right", "front_left", "front_right"])
    if any(_corners(r) for r in regions):
        return None
    ranks = {k: r for r, k in enumerate(sorted(k for ks in keys for k in ks))}
    return Plan(towers=towers, regions=[r[len("@region_"):] if r else None for r in regions],
                order=[[ranks[k] for k in ks] for ks in keys])
