"""Mention accounting: every count, patch, place and relation an instruction names must be in its task.

The builtin front end reads an instruction with recognizers; a recognizer that reads part
of a sentence could leave a count ("three green blocks") or a place ("in each of the four
corners") out of the task it builds and still produce a valid task that means something
else.  This pass lists the content mentions of the normalised instruction and checks each
against the schema; a mention the schema does not consume makes the compile refuse, with a
message naming it (refuse rather than guess).  :func:`account` also returns the record of
which part of the task consumed each mention; the compiler writes it to ``task.yaml``
under ``accounting``.

Colours and labels are checked by the builtin front end (:func:`unaccounted` and
:func:`check_mentions`, below), which call :func:`account` for the rest.
"""

from __future__ import annotations

import itertools
import re
from collections import Counter
from dataclasses import dataclass
from functools import lru_cache

from rpg.domain import predicates as P
from rpg.errors import BadInput
from rpg.schema import lexicon
from rpg.schema.lexicon import (
    CAPS_JARGON,
    COLOR_RE,
    COLORS,
    COMPASS_CORNER_RE,
    INVENTORY_RE,
    MATERIAL_SAID_RE,
    OBJECT_PREPOSITION_BEFORE,
    PAIRWISE_RELATIONS,
    VOCAB,
    names_a_role,
)
from rpg.schema.model import TaskSchema
from rpg.schema.reading import (
    LABEL_ROLE_RE,
    Features,
    ParseError,
    canon_color,
    color_mentions,
    explicit_labels,
    mark_regions,
    normalize_words,
)
from rpg.schema.structures import STRUCTURE_KINDS, STRUCTURE_RE, structure_of_word

CUBE_NOUNS = r"(?:block|cube|box|piece|object|one)s?"


@dataclass(frozen=True)
class Mention:
    """A content mention: its words, kind (count, patch, place, towers, relation, structure) and what it requires."""

    words: str
    kind: str
    count: int = 0
    color: str | None = None
    region: str | None = None
    predicates: tuple[str, ...] = ()  # relation, structure: the goal predicates that can carry it
    exact: bool = False  # count: said as "only" / "exactly" N, so no more than N either


RELATION_WORDS: tuple[tuple[str, str], ...] = tuple(
    (r"\b(?:" + "|".join(p for p in (P.PREDICATES[name].phrases, P.PREDICATES[name].loose_phrases) if p) + r")\b",
     " ".join((name, *P.PREDICATES[name].carried_by)))
    for name in (*PAIRWISE_RELATIONS, "between", "label_facing"))
"""Relation words (normalised text) -> the goal predicates that can carry them: each relation's
``phrases`` and ``loose_phrases`` with itself and its ``carried_by`` (:mod:`rpg.domain.predicates`)."""


TOGETHER_RE = re.compile(r"\btogether\b")
STACKED_RE = re.compile(r"(?<!\bun)(?<!\bre)\b(?:stacked|stacking)\b(?!\s+(?:blocks?|cubes?|toys?|game|set)\b)")
"""A cube said to be stacked ("I'd like P and T stacked", "stacking the red cube on the blue one"): a tower, or one cube on
another, as the noun "stack" says (a reading as a row had dropped the word); not "stacking blocks", a kind of toy."""
"""Cubes said to go together: some goal predicate must put them side by side, on each other or in one place."""

THE_PATCHES_RE = re.compile(r"(?:\b(?:the|both|all)\s+(?:(?P<n>\d+)\s+)?|\b(?P<n2>\d+)\s+)(?:goal\s+|target\s+)?patches\b")
"""Patches named together without their colours ("the two patches"): the task must have that many."""

WALL_RE = re.compile(r"\bwalls?\b")
"""A wall: a grid one row deep and several layers high (:func:`rpg.schema.readers.structures.recognize_wall`),
carried only by a :class:`~rpg.domain.predicates.Grid`."""


UNDO_RE = re.compile(r"\bunstack(?:s|ed|ing)?\b|\bremov(?:e|es|ed|ing)\b|\boff\b")
"""Words that take a cube off where it starts (project): only a task whose rho_0 starts a
stack (``initial_state.structures``) can mean them."""

MATCHING_RE = re.compile(r"\b(?:matching|corresponding|respective|(?:its|their)\s+(?:own\s+)?colou?r(?:ed)?|same\s+colou?r)"
                         r"(?:\s+\w+){0,3}?\s+(?:goal\s+|target\s+)?(?:patch|patches|target|targets)\b"
                         r"|\b(?:patch|patches)\s+(?:of|with|in)\s+(?:the\s+)?(?:same|its|their|matching)\s+(?:own\s+)?colou?rs?\b")
"""A patch picked by the cube's own colour ("on its matching patch", "the patch of the same
colour"): every cube the task puts on a patch must be on one of its colour."""

SUPERLATIVE_RE = re.compile(
    r"\b(?:make|build|create|form|construct|assemble|erect|stack|pile)\s+(?:up\s+)?(?:me\s+|us\s+)?(?:the|a)\s+"
    r"(?:tallest|highest|biggest|largest|longest|widest|greatest)\b"
    r"|\bas\s+(?:tall|high|big|large|long|wide)\s+as\s+(?:possible|you\s+can|it\s+can|can\s+be)\b")
"""A structure asked for at its largest ("build the tallest tower you can"): as many cubes as
there are, which only a stated count makes a task (project)."""


DIRECTION_RE = re.compile(r"\b(?P<a>left|right|front|back)\s+to\s+(?:the\s+)?(?P<b>left|right|front|back)\b")
"""A direction said ("from left to right", "front to back"): some part of the goal must order
cubes along that axis (a directed line, a reading, a relation of that axis)."""

AXIS_WORD_RE = re.compile(r"\b(?P<a>left|front)\s*-\s*(?:right|back)\b")
"""An axis said ("a left-right line", "front-back"): some part of the goal must lie along it (a
line on that axis, or an order along it)."""

AXIS_ORDERS = {"left": frozenset({"left_to_right", "right_to_left", "left_of", "right_of"}),
               "front": frozenset({"front_to_back", "back_to_front", "in_front_of", "behind"})}
"""An axis (by its first side) -> the order relations (:meth:`Predicate.constraints`) and
reading directions that run along it."""
AXIS_ORDERS["right"], AXIS_ORDERS["back"] = AXIS_ORDERS["left"], AXIS_ORDERS["front"]


PLACE_WORD_RE = re.compile(r"\b(?P<w>left|right|front|back|rear|middle|center|centre|corners?|edges?|sides?|ends?)\b")
"""Words that name a place on the table, a side of a cube or a part of a structure: each one an
instruction says must be read into its task.  Those inside a place, relation, direction, axis or
corner mention are checked there, and :data:`NOT_A_PLACE_RE`'s uses are no place; any other is a
``place word`` mention, consumed only by a part of the goal of its kind
(:func:`_carries_place_word`): "LINE front edge: red, red, red" read as a line anywhere is refused."""

NOT_A_PLACE_RE = re.compile(r"\bends?\s+(?:up\b|(?=(?:on|in|at|next|beside|behind|under|to)\b))|\bright\s+(?=(?:next|beside|by|on|onto|in|into|at|up|there|here|behind|against|"
                            r"under|underneath|below|above|over|between|away|now|atop|alongside|in\s+front)\b|@)"
                            r"|\ball\s+right\b|\bback\s+(?=(?:on|onto|to|into|in|where|down|up|together)\b)"
                            r"|\b(?:put|place|move|set|bring|take|stack)\s+(?:it|them)\s+back\b"
                            r"|\bfrom\s+(?:the\s+)?(?:far\s+)?(?:left|right|front|back|rear|middle|center|centre)(?:\s+(?:side|edge|end|corner))?\b"
                            r"(?!\s+(?:to|of)\b)"
                            r"|\b(?:in|at|by|towards?)\s+the\s+(?:very\s+)?end\b(?!\s+of\b)|\bend\s+(?:result|state|goal|position|"
                            r"configuration|arrangement|scene)\b")
"""Place words used for no place of the goal: "end up", "in the end" and "the end state" (a time),
"right next to" (an intensifier), "all right", "put it back on" (a return), "take it from the
centre" (where a cube starts, which rho_0 draws)."""

EACH_CORNER_RE = re.compile(r"\b(?:each|every|all)\s+(?:of\s+the\s+)?(?:(\d+)\s+)?corners?\b")
"""Every corner of the table ("in each of the 4 corners"): that many corners in the task."""

BARE_PLACE_RE = re.compile(
    r"\b(?:in|at|on|to|into|onto|near|by|along)\s+the\s+(?:very\s+|far\s+)?(?P<side>front|back|rear|left|right|middle|center|centre)"
    r"(?:\s*-?\s*(?:hand\s+)?(?:side|half|part|edge|end|area|region|zone))?\b(?!\s*(?:of\b|-|corner|left|right|middle))")
"""A side of the table named alone ("at the front", "on the left", "in the middle"), not a
relation ("to the left of"): a place the task must use (project)."""

BARE_PLACES = {"front": "front", "back": "back", "rear": "back", "left": "left", "right": "right",
               "middle": "center", "center": "center", "centre": "center"}
"""Side words -> regions (:data:`rpg.domain.constants.REGION_NAMES`)."""


SIDE_RELATIONS = {"left": ("left_of", "right_of"), "right": ("left_of", "right_of"),
                  "front": ("in_front_of", "behind"), "back": ("in_front_of", "behind")}
"""A side named alone can be one end of a relation between cubes ("the red cube on the left and
the blue one on the right"): the goal predicates that consume it then."""


_OPPOSITE = {"left": ("right",), "right": ("left",), "front": ("back",), "back": ("front",)}
"""A side of the table -> the side across from it: a bare side is one end of a relation only
when the other end is said too ("red on the left, blue on the right")."""


LONE_LETTER_RE = re.compile(r"(?<![\w'\-.(])(?<!\b(?i:plan|step|part|type|task|zone|area|spot|mark|site) )(?<!\b(?i:option|marked|letter) )"
                            r"([B-HJ-Z]|A(?=\s*(?:[,;:!?]|\.(?!\w)|$)|\s+(?:on|onto|and|then|to|is|at|in|next|behind|beside|"
                            r"under|below|above|left|right|between|should|must|shall|goes|sits|stays)\b))(?![\w'\-)]|\.\w)(?!\s+(?:[a-z]+\s+)?(?:blocks|cubes|ones)\b)")
"""A capital letter standing alone ("stack B on A", "the C"): a letter cube, which the task must
have ("I" is the speaker; "A" only where it is no article; not an option, a step or a list
marker: "plan B", "(c)", "e.g."; not a number of cubes: "all N blocks")."""


LONE_DIGIT_RE = re.compile(r"(?<![\w'\-.(#:/@$\u00a3\u20ac])(?<!\bseed\s)(\d)(?![\w'\-%/:\u00d7]|[.)]\s*\w|\.\d)(?!\s*(?:[x\u00d7*+=]|by)\b)(?!\s+[A-Za-z])(?!\s*(?:->|=>|\u2192|-+\s|\u2014|\u2013))")
"""A digit standing alone, with no word after it ("line 1 2 3", "stack 2 on 1", "a tower of 3"):
a digit cube or a number of cubes, which the task must have (not a list marker "1." / "2)",
a grid size "3x3" or "3 by 3", an id "T-88", a time "10:32" or a heading "Task 4:", "Task 5 - ...", "level 3 ->")."""


_AFTERTHOUGHT_COUNT_RE = re.compile(r"(?<!\d),\s*(?:(?:no|or|wait|sorry|actually|make\s+(?:it|that|them))\s*,?\s*)*([2-9]|1[0-9])\s*"
                                    r"(?:actually|instead|please|pls|now|rather|really)?\s*(?=[.!?;]|$)")
"""A number said after a comma with no noun of its own ("..., 4 actually", "..., make it 5"): a count the task must have."""


COLOR_LIST_RE = re.compile(rf"\b(?:{COLOR_RE})(?:\s*(?:,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)(?:the\s+)?"
                           rf"(?:{COLOR_RE})\b(?!\s+(?:patch|pad|mat|tile)))+")
"""A list of colours with nothing but separators between them ("white, white, then black, black"):
each colour said is one cube, so the task must have at least as many of each."""


TOWER_END_SAID_RE = re.compile(rf"\b(?P<c>{COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?:(?:is|goes|sits|stays|(?:should|must|will)\s+be|"
                               r"ends\s+up)\s+)?(?:(?P<top>on\s+top|at\s+the\s+(?:very\s+)?top)|(?:at|on)\s+the\s+(?:very\s+)?"
                               r"(?:bottom|base))\b(?!\s+of\b)"
                               rf"|(?<!\bto\s)\b(?:(?P<top2>top)|bottom|base)\s+(?:block|cube)\s*[:=]\s*(?P<c2>{COLOR_RE})\b"
                               rf"|\b(?P<c3>{COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?:is|(?:should|must|will|has\s+to|needs\s+to)\s+be)\s+the\s+"
                               r"(?:(?P<top3>top|topmost|highest|uppermost)|bottom|base|lowest|bottommost)(?:\s+(?:one|1|block|cube))?\b")
"""A cube of one colour given the top or the bottom of a tower ("with the pink cube on top",
"so that red is at the bottom", "top cube: pink"): the goal's ordered tower that holds it must
have it there."""

END_ROLE_SAID_RE = re.compile(rf"\b(?:start|begin|end|finish)(?:s|ing|ed)?\s+with\s+(?:the\s+|a\s+|an\s+)?(?P<c>{COLOR_RE})\b")
"""A cube given the first or last place of a sequence ("ends with red", "starting with the blue
cube"): some order of the goal must hold that cube."""


class UnaccountedMention(BadInput):
    """A mention of the instruction has no place in the task that was read."""


@lru_cache(maxsize=4)
def _count_re(colors: str) -> re.Pattern:
    return re.compile(
        rf"(?<![a-z'@])(?<!letter )(?<!digit )(?<!number )(?<!labeled )(?<!labelled )(?<!label )"
        rf"(?P<n>\d+)\s+(?:(?:more|additional|extra|other|separate|of\s+the|of|identical|same|stacked|piled|loose|spare)\s+)*"
        rf"(?P<colors>(?:(?:{colors})(?:\s*,\s*|\s+and\s+|\s+or\s+))*(?:{colors})\s+)?"
        rf"(?:(?!(?:with|of|on|in|to|for|from|and|or|by|at|the|a|an|than)\b)[a-z\-]+\s+){{0,2}}?{CUBE_NOUNS}\b"
        rf"|(?<![a-z'@])(?P<n3>\d+)\s+(?P<color3>{colors})\b(?!\s+(?:goal\s+)?patch)"
        rf"|\b(?:tower|stack|column|pile|row|line|pillar)\s+of\s+(?:exactly\s+|only\s+|just\s+)?(?P<n2>\d+)\s+(?:(?P<color2>{colors})\b)?"
        rf"|\b(?:pyramid|wall|circle|ring)\s+of\s+(?:exactly\s+|only\s+|just\s+)?(?P<n4>\d+)\s+(?:(?P<color4>{colors})\s+)?{CUBE_NOUNS}\b")


SIZED_KINDS = {"tower": "stack", "stack": "stack", "column": "stack", "pillar": "stack", "row": "line", "line": "line",
               "pyramid": "pyramid", "wall": "wall", "circle": "circle", "ring": "circle"}
"""A structure noun counted ("a pyramid of 5 cubes") -> the meaning atom whose cubes must number that many."""


def mentions(text: str, colors: str, canon) -> list[Mention]:
    """Counts and places named in normalised text (``@region_<name>`` tokens for places).

    Args:
        text: the parser's normalised instruction (numbers as digits, places as tokens).
        colors: regular-expression alternation of colour words.
        canon: maps a colour word to its palette name.
    """
    out: list[Mention] = []
    said: dict[tuple[str, ...], int] = {}  # cubes counted so far, per colour set
    for m in _count_re(colors).finditer(text):
        n = int(m.group("n") or m.group("n2") or m.group("n3") or m.group("n4"))
        listed = (re.findall(rf"\b(?:{colors})\b", m.group("colors") or "")
                  or [c for c in [m.group("color2"), m.group("color3"), m.group("color4")] if c])
        named = tuple(sorted({canon(c) for c in listed}))
        if re.search(r"\b(?:more|additional|extra)\b", m.group(0)):  # "three blue cubes ... three more blue cubes": six
            # ("the green cube ..., then one more green cube": two, the one said before it uncounted; it had been dropped)
            n += said.get(named, 0) or int(bool(listed) and any(re.search(rf"\b{re.escape(c)}\b", text[:m.start()]) for c in listed))
        said[named] = n
        exact = bool(re.search(r"\b(?:only|exactly|just)\s+$", text[:m.start()]))  # "using only two green cubes"
        out.append(Mention(m.group(0).strip(), "count", count=n, color=",".join(named) or None, exact=exact))
    for m in re.finditer(rf"(?:\b(?P<n>\d+)\s+)?\b(?P<c>{colors})\s+(?:goal\s+)?patch(?P<pl>es)?\b", text):
        # "the two green patches": that many patches of the colour ("the red and the blue patch" is two colours)
        many = int(m.group("n")) if m.group("n") else 2 if m.group("pl") else 1
        out.append(Mention(m.group(0), "patch", color=canon(m.group("c")), count=many))
    for m in re.finditer(r"\b(?:a|an|the|some)\s+(?:(?:goal|target)\s+){0,2}patch\b(?!\s+of\s+(?:its|their)\b)", text):
        out.append(Mention(m.group(0), "patch"))  # a patch of no colour: some goal patch must be in the task
    for m in re.finditer(r"@region_([a-z_]+)", text):
        out.append(Mention(m.group(0), "place", region=m.group(1)))
    for m in BARE_PLACE_RE.finditer(text):  # "at the front", "in the middle": a place, unless a face or a role
        before = text[:m.start()]
        if re.search(r"\bfac\w*\s+(?:\w+\s+){0,2}$", before):
            continue
        row_end = m.group("side") in SIDE_RELATIONS and re.match(r"\s+end\s+of\s+(?:a|the)\s+(?:row|line)\b", text[m.end():])
        if not names_a_role(before, text) and not row_end:
            out.append(Mention(m.group(0), "bare place", region=BARE_PLACES[m.group("side")]))
        elif row_end:  # "the red cube at the right end of a row": the row's end, by its own words
            role = re.findall(rf"\b({colors})\b", before)
            out.append(Mention(m.group(0) + " end", "end role", color=canon(role[-1]) if role else None, region=m.group("side")))
        elif m.group("side") in SIDE_RELATIONS:  # "a line of red, green and blue with blue on the right": an end
            said = before[before.rfind("with"):]
            # the cube said last before the side ("..., and blue on the right"; "with 3 on the far left": a label)
            role = re.findall(rf"\b({colors}|\d|[a-z](?=\s+(?:is\s+|as\s+)?$))\b", said)
            out.append(Mention(said.strip() + " " + m.group(0), "end role",
                               color=(role[-1] if re.fullmatch(r"\d|[a-z]", role[-1]) else canon(role[-1])) if role else None,
                               region=m.group("side")))
    for m in re.finditer(rf"(?<!,\s)(?<!and\s)(?<!or\s)\b(?:all\s+(?:of\s+)?(?:the\s+)?|the\s+)(?P<c>{colors})\s+"
                         r"(?:cubes|blocks|ones|bricks|boxes)\b",
                         text):  # "the pink cubes", "all red cubes": several of that colour (a listed "red and blue blocks" is not)
        out.append(Mention(m.group(0), "plural", color=canon(m.group("c"))))
    for m in re.finditer(rf"(?:^|[.;:]\s*)(?P<w>(?P<c>{colors})\s+(?:cubes|blocks|bricks))\s+(?:on|in|at|to|along)\s+the\s+(?:far\s+)?"
                         r"(?:left|right|front|back|rear)\b",
                         text):  # "red cubes on the left, blue cubes on the right": a group said without "the"
        out.append(Mention(m.group("w"), "plural", color=canon(m.group("c"))))
    towers = len(re.findall(r"\b(?:a|an|1|another)\s+(?:[a-z0-9\-]+\s+){0,2}?(?:tower|stack|column|pillar)\b", text))
    towers += len(re.findall(r"\b(?:tower|stack|column|pillar)\s+(?:of|using|with|from)\s+[^.;]*?\band\s+(?:1|another)\b"
                             r"(?!\s+(?:[a-z]+\s+)?(?:block|cube|tower|stack|column|pillar))", text))  # "one tower of red and one of
    # green", "a tower of red, green and one of blue, yellow"
    towers += len(re.findall(r"(?:^|[.;]\s+)(?:tower|stack)\s+(?:from\s+)?(?:bottom|top)\b", text))  # "Tower bottom to top: red,
    # green. Tower bottom to top: ...": a tower each
    described = re.findall(rf"\bthe\s+(?:tower|stack)\s+(?:of|with)\s+(?:the\s+)?({colors})\b", text)
    towers += len(set(described)) if len(set(described)) > 1 else 0  # "the tower of red and green left of the tower of blue"
    if re.search(r"\b(?:on|onto|above|atop|over|under|below|beneath|underneath)\b"
                 r"(?!\s+the\s+(?:far\s+|very\s+)?(?:left|right|front|back|middle|center|centre|table)\b|\s+@region"
                 rf"|\s+top\b(?!\s+of)|\s+(?:the\s+|a\s+)?(?:{colors}|goal)\s+(?:goal\s+)?patch)", text):
        towers = 0  # a stack put on a stack is one tower: leave counting them to the structure's reader (a cube put on a
        # patch, or "on top" of no cube named, puts no stack on a stack: "Build a tower of red and green. Build another
        # tower of blue and yellow. Put the white cube on the white patch." had made one tower of four, silently)
    towers += sum(int(n) for n in re.findall(r"\b(\d+)\s+(?:[a-z\-]+\s+){0,2}?(?:towers|stacks|columns|pillars)\b", text))
    commands = [c for c in re.split(r"(?<=[.;!?])\s+|,?\s+and\s+then\s+|;\s*then\s+", text)
                if re.match(r"\s*(?:please\s+)?(?:then\s+)?stack\s+", c) and len(re.findall(rf"\b(?:{colors})\b", c)) >= 2
                and not re.search(r"\b(?:on|onto|atop|under|over|above|below|beneath)\b", c)]
    if len(commands) > 1:  # "Stack red, green, blue. Stack white, black.": a tower each (one of five had been read, silently)
        towers = max(towers, len(commands))
    if towers > 1:
        out.append(Mention(f"{towers} towers", "towers", count=towers))
    for m in ALL_RELATED_RE.finditer(text):  # "stack red on green and blue on yellow, both left of white"
        out.append(Mention(m.group(0), "all related", color=canon(m.group("c"))))
    for m in ALL_ON_ONE_PATCH_RE.finditer(text):  # "stack red on green and blue on yellow, both on the blue patch"
        out.append(Mention(m.group(0), "all on patch", color=canon(m.group("c")) if m.group("c") else None))
    for kind, (one, many) in STRUCTURES_COUNTED.items():
        # one more for each said to be another ("a row of 3 and another row of 3", "a second circle", "one pile of red and
        # one of blue"), or the number said ("2 circles"), or a verb of its own each ("Pile red and green. Pile blue.")
        more = len(re.findall(rf"\b(?:another|a\s+second|a\s+third|the\s+second|the\s+other)\s+(?:[a-z0-9\-]+\s+){{0,2}}?(?:{one})\b"
                              rf"|\b(?:{one})\s+of\s+[^.;]*?\band\s+(?:1|another)\s+of\b", text))
        numbered = [int(n) for n in re.findall(rf"\b(\d+)\s+(?:[a-z\-]+\s+){{0,2}}?(?:{many})\b", text)]
        verbs = len(re.findall(r"(?:^|[.;:!]\s*|\band\s+)(?:pile|heap)(?:\s+up)?\s+(?!up\b)(?=\S)", text)) if kind == "pile" else 0
        said_of = len(re.findall(rf"\b(?:a|an|1)\s+(?:[a-z0-9\-]+\s+){{0,2}}?(?:{one})\s+(?:of|with|from)\b", text))  # "a row of 3
        # and a row of 3" (normalizing had written "another" as "a"); a structure said again ("a rainbow row! ... in a line")
        # names no cubes of its own
        said = max(1 + more if more else 0, max(numbered, default=0), verbs, said_of)
        if said > 1:
            out.append(Mention(f"{said} {kind}s", "structures", count=said, predicates=(kind,)))
    for words, kinds in RELATION_WORDS:
        m = re.search(words, text)
        if m:
            out.append(Mention(m.group(0), "relation", predicates=tuple(kinds.split())))
    if TOGETHER_RE.search(text):  # "place the red and blue blocks together": side by side, stacked, or in one group
        out.append(Mention("together", "relation", predicates=("next_to", "stack", "on", "on_patch", "in_line", "grid",
                                                               "pyramid", "in_region", "piles")))
    for m in THE_PATCHES_RE.finditer(text):  # "behind the two patches": that many patches, whatever their colours
        out.append(Mention(m.group(0), "patches", count=int(m.group("n") or m.group("n2") or 2)))
    for m in re.finditer(STRUCTURE_RE, text):
        if re.search(r"\b(?:the|that|this|its|their)\s+(?:[a-z]+\s+)?$", text[:m.start()]):
            continue  # "push the pile of red blocks": a reference to cubes, not a structure to build
        out.append(Mention(m.group(0), "structure", predicates=STRUCTURE_KINDS[structure_of_word(m.group(1))].carriers))
    for m in STACKED_RE.finditer(text):  # "I'd like the letters P and T stacked": a tower as surely as "a stack" says one
        out.append(Mention(m.group(0), "structure", predicates=STRUCTURE_KINDS["tower"].carriers))
    for m in WALL_RE.finditer(text):  # a wall is a grid of layers (no structure kind of its own)
        if not re.search(r"\b(?:the|that|this|its|their)\s+(?:[a-z]+\s+)?$", text[:m.start()]):
            out.append(Mention(m.group(0), "structure", predicates=("grid",)))
    for m in UNDO_RE.finditer(text):
        out.append(Mention(m.group(0), "undo"))
    for m in DIRECTION_RE.finditer(text):
        if AXIS_ORDERS[m.group("a")] is AXIS_ORDERS[m.group("b")] and m.group("a") != m.group("b"):
            out.append(Mention(m.group(0), "direction", region=m.group("a")))
    for m in AXIS_WORD_RE.finditer(text):
        out.append(Mention(m.group(0), "axis", region=m.group("a")))
    for m in MATCHING_RE.finditer(text):
        out.append(Mention(m.group(0), "matching"))
    read = [m.span() for r in (BARE_PLACE_RE, DIRECTION_RE, AXIS_WORD_RE, NOT_A_PLACE_RE, EACH_CORNER_RE, *(re.compile(w) for w, _ in RELATION_WORDS))
            for m in r.finditer(text)]
    for m in PLACE_WORD_RE.finditer(text):  # a place word no mention above reads: some part of the goal must carry it
        if not any(a <= m.start() < b for a, b in read):
            out.append(Mention(m.group(0), "place word", region=m.group("w")))
    for m in SUPERLATIVE_RE.finditer(text):
        out.append(Mention(m.group(0), "superlative"))
    for m in lexicon.HEIGHT_SAID_RE.finditer(text):  # "a tower of gray cubes, 3 high": a height no rewrite read
        out.append(Mention(m.group(0), "height", count=int(m.group("n"))))
    for m in lexicon.COUNT_TIMES_RE.finditer(text):  # "circle x5", "blue x3": a count as a multiplier
        out.append(Mention(m.group(0), "times", count=int(m.group("n") or m.group("n2"))))
    for m in lexicon.EXTENT_SAID_RE.finditer(text):  # "a row of gray cubes, 3 long": a length no rewrite read
        out.append(Mention(m.group(0), "times", count=int(m.group("n"))))
    for m in lexicon.GRID_SIZE_SAID_RE.finditer(text):  # "circle x5x2": a grid's size said of something else
        out.append(Mention(m.group(0), "times", count=int(m.group("r")) * int(m.group("c"))))
    each = EACH_CORNER_RE.search(text)
    if each:
        out.append(Mention(each.group(0), "place", count=int(each.group(1) or 4), region="corners"))
    return out


def _ordered_lines(goal: list[P.Predicate], side: str, odd: bool = False) -> set[str]:
    """The ordered lines of ``goal`` that run along ``side``'s axis (:data:`AXIS_ORDERS`), as ``line <direction>``: the
    parts that carry a row's ends said as sides of the table ("at the far left ... at the far right"), and with ``odd``
    (an odd count of cubes) its middle ("in the center")."""
    along = AXIS_ORDERS.get(side, frozenset())
    return {f"line {p.order}" for p in goal if isinstance(p, P.InLine) and p.order in along and (not odd or len(p.objects) % 2)}


def _orders(goal: list[P.Predicate]) -> set[str]:
    """The order relations of ``goal``'s parts (:meth:`Predicate.constraints`' ``order`` kinds:
    ``left_of``, ``on``, a line's ``left_to_right``...) and the directions its readings run in."""
    return ({c[1].get("relation") for p in goal for c in p.constraints() if c[0] == "order"}
            | {getattr(p, "direction", None) for p in goal}) - {None}


def _carries_place_word(word: str, goal: list[P.Predicate], regions: set[str]) -> list[str]:
    """The parts of ``goal`` that can carry a place word said outside any place mention: a
    side (left, right, front, back) a region of that side or an order along its axis; a middle
    a central region, a between or any order (a stack's or layer's middle); a corner a corner
    region; an edge, side or end any region, side relation or ordered line."""
    word = {"rear": "back", "centre": "middle", "center": "middle"}.get(word, word).rstrip("s")  # "corners": a corner
    orders = _orders(goal)
    params = {str(v) for p in goal for v in p.params().values()}
    if word in AXIS_ORDERS:
        return sorted({f"in_region {r}" for r in regions if word in r.split("_")}
                      | orders & AXIS_ORDERS[word] | {f"{word} (a parameter)" for v in params if word in v.split("_")})
    if word == "middle":
        return sorted({f"in_region {r}" for r in regions if r in ("center", "middle")} | orders
                      | {p.name for p in goal if p.name == "between"})
    if word == "corner":
        return sorted(f"in_region {r}" for r in regions if r.count("_") == 1 or r.startswith("corner"))
    return sorted({f"in_region {r}" for r in regions} | orders & (AXIS_ORDERS["left"] | AXIS_ORDERS["front"])
                  | {p.name for p in goal if p.name in ("between", "in_line")}
                  | {f"{p.name} {side} end" for p in goal if isinstance(p, P.AnchoredLine)  # "red at the left end of a row"
                     for side in ("left", "right") if getattr(p, side) and word == "end"})


_ALL_OF_THEM = (r"\b(?:(?:both|all|each|2)(?:\s+(?:of\s+)?(?:them|the\s+(?:towers|stacks)|towers|stacks|tower|stack))?"
                r"|them(?:\s+(?:both|all))?)\s+(?:(?:goes|go|is|are|sits?|stands?|should\s+be|must\s+be)\s+)?")
"""Several towers said at once ("both", "all of them", "each tower goes"; "both" is written "2" by normalizing)."""

ALL_RELATED_RE = re.compile(
    _ALL_OF_THEM + r"(?:(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|behind"
    rf"|next\s+to|beside|far\s+from)\s+(?:the\s+)?(?P<c>{COLOR_RE})\b")
"""Several towers related at once to one cube ("..., both left of white"): every tower of the task read must be (only the
last had been, silently)."""

ALL_ON_ONE_PATCH_RE = re.compile(
    _ALL_OF_THEM + r"(?:on|onto)\s+(?:the\s+)?(?:(?P<c>[a-z]+)\s+)?(?:goal\s+)?patch\b")
"""Several towers put on one patch at once ("..., both on the blue patch", "all on the pink patch", "put them on the white
patch"): every tower of the task read must stand on a patch (only the last tower had been put there, silently)."""


STRUCTURES_COUNTED: dict[str, tuple[str, str]] = {
    "row": ("row|line", "rows|lines"), "circle": ("circle|ring", "circles|rings"), "pyramid": ("pyramid", "pyramids"),
    "pile": ("pile|heap", "piles|heaps"),
}
"""Structures whose number a text says ("a row of 3 and another row of 3", "2 circles", "Pile red. Pile blue."): the
task read must have as many (:func:`_count_structures`; towers are counted apart: :func:`_count_towers`).  Kind -> (the
noun said of one, of several)."""


def _count_structures(goal: list[P.Predicate], kind: str) -> float:
    """How many structures of ``kind`` (a key of :data:`STRUCTURES_COUNTED`) the goal holds; unbounded where a layered
    structure or a grouping may hold them (a wall's or pyramid's rows, piles by colour)."""
    if kind == "row":
        if any(isinstance(p, P.Grid | P.Pyramid | P.InLayers) for p in goal):
            return float("inf")  # "the first row is red, the second blue": a wall's rows
        return sum(isinstance(p, P.InLine) for p in goal)
    if kind == "circle":
        return sum(isinstance(p, P.InCircle) for p in goal)
    if kind == "pyramid":
        return sum(isinstance(p, P.Pyramid) for p in goal)
    piles = [p for p in goal if isinstance(p, P.Piles)]
    return float("inf") if any(p.by for p in piles) else sum(len(p.groups) or 1 for p in piles)


def _count_towers(goal: list[P.Predicate]) -> int:
    """Stacks in the goal: Stack predicates and layered structures, and chains of On over distinct bases."""
    n = sum(isinstance(p, P.Stack | P.Pyramid | P.Grid) for p in goal)  # a layered structure counts as one
    bases = {p.b for p in goal if isinstance(p, P.On)}
    tops = {p.a for p in goal if isinstance(p, P.On)}
    return n + len(bases - tops)


_END_OF = {"left": ("left_to_right", "right_to_left"), "right": ("right_to_left", "left_to_right"),
           "front": ("front_to_back", "back_to_front"), "back": ("back_to_front", "front_to_back")}
"""A side -> (the direction whose first object is at that side, the one whose last is)."""


def _ends_at(goal: list[P.Predicate], side: str, color_of: dict[str, str | None], color: str | None) -> list[str]:
    """The goal predicates that put a cube of ``color`` (any, None) at ``side``: a relation
    with that side (:data:`SIDE_RELATIONS`) over such a cube, or a directed line (or a reading of labels) that ends there with one."""
    first, last = _END_OF[side]
    out = []
    for p in goal:
        names = p.object_names()
        if p.name in SIDE_RELATIONS[side] and (color is None or any(color_of.get(n) == color for n in names)):
            out.append(p.name)
        elif isinstance(p, P.InLine | P.Reads) and (way := getattr(p, "order", None) or getattr(p, "direction", None)) in (first, last):
            end = p.objects[0] if way == first else p.objects[-1]
            if color is None or color_of.get(end) == color:
                out.append(f"{p.name} {way}")
        elif isinstance(p, P.AnchoredLine) and side in ("left", "right") and getattr(p, side):  # "with red at the left end"
            end = p.objects[0] if side == "left" else p.objects[-1]
            if color is None or color_of.get(end) == color:
                out.append(f"{p.name} {side} end")
    return out


ON_TABLE_RE = re.compile(rf"\b(?:(?:put|place|move|set|lay|lower|bring|return)\s+the\s+({COLOR_RE})\s+(?:block|cube|box)\s+"
                         rf"|(?<!starts )(?<!initially )(?:the\s+)?\b({COLOR_RE})(?:\s+(?:block|cube|box))?\s+(?:(?:must|should|will)\s+)?"
                         rf"(?:is|be|goes|go|sits|stays|stay|ends\s+up|end\s+up)\s+|(?<=[.:;]\s)(?:the\s+)?({COLOR_RE})(?:\s+(?:block|cube))?\s+)"
                         r"(?:back\s+|down\s+)*(?:on|onto|to)\s+the\s+table\b")
"""A named cube sent to the table ("move the green cube down onto the table"): the goal may not
stack it on another cube."""


def _objects_of(p: P.Predicate) -> set[str]:
    """The object names one predicate's own fields hold (its string fields and, nested to any
    depth, its list and tuple fields)."""
    def names(v) -> set[str]:
        if isinstance(v, str):
            return {v}
        if isinstance(v, (tuple, list, set, frozenset)):
            return {n for x in v for n in names(x)}
        if isinstance(v, dict):
            return {n for x in (*v.keys(), *v.values()) for n in names(x)}
        return set()
    return {n for k, v in vars(p).items() if not k.startswith("_") for n in names(v)}


def _stacked_on_another(schema: TaskSchema) -> set[str]:
    """The cubes the goal surely puts on top of another cube (every On edge's upper cube, every
    cube of an ordered Stack but its base)."""
    out = set()
    for p in schema.goal_predicate().walk():
        if isinstance(p, P.On):
            out.add(p.a)
        elif type(p) is P.Stack:  # an unordered or anchored stack may have any of its cubes at the base
            out.update(p.objects[1:])
    return out


def _structure_sizes(schema: TaskSchema, kind: str) -> list[int]:
    """How many cubes each tower (``kind`` "stack") or line ("line") of the goal holds, from its
    meaning atoms (:func:`rpg.schema.meaning.meaning`)."""
    from rpg.schema.meaning import meaning

    return sorted(len(re.split(r"[,|]", m.group(1))) for a in meaning(schema)
                  if (m := re.fullmatch(rf"{kind}(?:\[[a-z_]+\])?\(([^;()]*)\)(?:@\w+)?", a)))


def _heights(schema: TaskSchema) -> list[int]:
    """How high each structure of the goal stands, in cubes: a tower's cubes (any :class:`P.Stack`), a
    pyramid's layers (a pyramid with a base of n is n layers high, one of a base under one cube two), a layered
    grid's (a wall's) layers."""
    out = set()
    for p in schema.goal_predicate().walk():
        if isinstance(p, P.Stack):
            out.add(len(p.objects))
        elif isinstance(p, P.Pyramid):
            out.add(len(p.layer_sizes()) if p.dims == 2 else p.base)  # (3 under 1: two high)
        elif isinstance(p, P.Grid) and p.layers > 1:
            out.add(p.layers)
    return sorted(out)


def _group_sizes(schema: TaskSchema) -> set[int]:
    """Every count a multiplier may name: all cubes, the cubes of each colour, each structure's cubes and layers."""
    from rpg.schema.meaning import meaning

    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    out = {len(cubes), *Counter(a.color for a in cubes).values()}
    for a in meaning(schema):
        m = re.fullmatch(r"[a-z_]+(?:\[[a-z_]+\])?\(([^;()]*)\)(?:@[\w:]+)?", a)
        if m:
            parts = m.group(1).split("|")
            out.add(len(re.split(r"[,|]", m.group(1))))
            out.update(len(p.split(",")) for p in parts)
            out.update(Counter(re.split(r"[,|]", m.group(1))).values())
    for p in schema.goal_predicate().walk():  # a wall's width and height, a grid's rows and columns, a pyramid's base
        if isinstance(p, P.Grid):
            out.update((p.rows, p.cols, p.layers, p.rows * p.cols, p.cols * p.layers))
        elif isinstance(p, P.Pyramid):
            out.update((p.base, p.base * p.base))  # "a pyramid with a 3x3 base": a 3D pyramid's base square
    return out


def account(text: str, schema: TaskSchema, colors: str, canon) -> list[dict]:
    """Check every count, patch, place and relation mention of ``text`` against ``schema``.

    Returns:
        The accounting record: one ``{"mention", "kind", "consumed_by"}`` per mention.

    Raises:
        UnaccountedMention: a mention with no place in the task; the message names it.
    """
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    by_color = Counter(a.color for a in cubes if a.color)
    goal = list(schema.goal_predicate().walk())
    regions = {p.region for p in goal if isinstance(p, P.InRegion | P.CentredIn)}
    patches = {a.color or "gray" for a in schema.assets if a.kind == "goal_patch"}
    patch_count = Counter(a.color or "gray" for a in schema.assets if a.kind == "goal_patch")
    record = []
    named = mentions(text, colors, canon)
    for m in named:
        if m.kind == "patch" and m.color is None:
            if not patches:
                raise UnaccountedMention(f"'{m.words}' names a goal patch and the task read has none")
            record.append({"mention": m.words, "kind": "patch", "consumed_by": "goal patch " + ", ".join(sorted(patches))})
        elif m.kind == "patches":
            if sum(patch_count.values()) < m.count:
                raise UnaccountedMention(f"'{m.words}' names {m.count} goal patches but the task read has "
                                         f"{sum(patch_count.values())}")
            record.append({"mention": m.words, "kind": "patch", "consumed_by": "goal patches " + ", ".join(sorted(patches))})
        elif m.kind == "patch":
            if m.color not in patches:
                raise UnaccountedMention(f"the {m.words} has no part in the task read")
            if m.count > patch_count[m.color]:
                raise UnaccountedMention(f"'{m.words}' names {m.count} {m.color} patches but the task read has "
                                         f"{patch_count[m.color]}")
            record.append({"mention": m.words, "kind": "patch", "consumed_by": f"goal patch {m.color}"})
        elif m.kind == "count":
            have = sum(by_color[c] for c in m.color.split(",")) if m.color else len(cubes)
            what = f"{m.color} cubes" if m.color else "cubes"
            if have < m.count or (m.exact and have != m.count):
                raise UnaccountedMention(f"'{m.words}' asks for {'only ' if m.exact else ''}{m.count} {what} but "
                                         f"the task read has {have}")
            sized = re.fullmatch(r"(tower|stack|column|pillar|row|line) of (?:exactly |only |just )?\d+"
                                 r"|(pyramid|wall|circle|ring) of (?:exactly |only |just )?\d+ (?:cubes?|blocks?|bricks?)", m.words)  # (with
            # a colour, "a circle of 3 red and 3 blue blocks", the count is that colour's)
            if sized:  # "a tower of 3 blocks": some tower of exactly 3 (a tower of 4 held 'at least 3'); "a pyramid of 5 cubes"
                sizes = _structure_sizes(schema, SIZED_KINDS[sized.group(1) or sized.group(2)])
                if m.count not in sizes:
                    kind = sized.group(1) or sized.group(2)
                    raise UnaccountedMention(f"'{m.words}' asks for a {kind} of {m.count} but the task read has "
                                             f"{' and '.join(map(str, sizes)) or 'no'} {'cubes in one' if sizes else ''} "
                                             f"{kind}".replace("  ", " "))
            record.append({"mention": m.words, "kind": "count", "consumed_by": f"{have} {what}"})
        elif m.kind == "structure":  # a predicate counts as each registered class it derives from
            used = sorted({c.name for p in goal for c in type(p).__mro__ if "name" in vars(c)} & set(m.predicates))
            if not used and "stack" in m.predicates and schema.initial_state.structures:
                used = ["initial_state.structures"]  # "starting from a stack of red on blue"
            if used == ["grid"] and re.search(r"\b(?:tower|stack|column)s?\b", m.words) and (
                    re.search(r"\b(?:walls?|grids?|squares?|arrays?|\d+x\d+)\b", text)
                    or not any(isinstance(p, P.Grid) and p.layers > 1 for p in goal)):
                used = []  # "a wall 3 wide and 2 high and a red on blue tower": the tower is not the wall (it had been dropped)
            if not used:
                raise UnaccountedMention(f"the {m.words} it names has no part in the task read")
            record.append({"mention": m.words, "kind": "structure", "consumed_by": ", ".join(used)})
        elif m.kind == "relation":
            used = sorted({p.name for p in goal} & set(m.predicates))
            if not used:
                raise UnaccountedMention(f"the relation '{m.words}' has no part in the task read")
            record.append({"mention": m.words, "kind": "relation", "consumed_by": ", ".join(used)})
        elif m.kind == "plural":
            if by_color[m.color] < 2:
                raise UnaccountedMention(f"'{m.words}' names several {m.color} cubes but the task read has "
                                         f"{by_color[m.color]} (say how many, e.g. '3 {m.color} cubes')")
            record.append({"mention": m.words, "kind": "plural", "consumed_by": f"{by_color[m.color]} {m.color} cubes"})
        elif m.kind == "undo":
            if not schema.initial_state.structures:
                raise UnaccountedMention(f"'{m.words}' takes a cube off a stack and the task read starts "
                                         "with none (say which cube starts on which)")
            record.append({"mention": m.words, "kind": "undo", "consumed_by": "initial_state.structures"})
        elif m.kind == "matching":
            color_of = {a.name: a.color for a in schema.assets}
            on = [(n, p.patch) for p in goal for n in ([p.a] if p.name == "on_patch" else
                                                        list(p.among) if p.name == "stack_on_patch" else [])]
            wrong = sorted({f"{n} on {patch}" for n, patch in on if color_of.get(n) != color_of.get(patch)})
            if not on or wrong:
                raise UnaccountedMention(f"'{m.words}' puts each cube on the patch of its own colour but the task read "
                                         f"{'has ' + ', '.join(wrong) if wrong else 'puts no cube on a patch'}")
            record.append({"mention": m.words, "kind": "matching", "consumed_by": ", ".join(f"{n} on {p}" for n, p in on)})
        elif m.kind == "height":
            heights = _heights(schema)
            if m.count not in heights:
                raise UnaccountedMention(f"'{m.words}' asks for a structure {m.count} cubes high but the task read has "
                                         f"{' and '.join(map(str, heights)) or 'none'}{' high' if heights else ''}")
            record.append({"mention": m.words, "kind": "count", "consumed_by": f"a structure {m.count} high"})
        elif m.kind == "times":
            sizes = _group_sizes(schema)
            if m.count not in sizes:
                raise UnaccountedMention(f"'{m.words}' counts {m.count} cubes and the task read has no group of {m.count}")
            record.append({"mention": m.words, "kind": "count", "consumed_by": f"{m.count} cubes"})
        elif m.kind == "superlative":
            if not any(n.kind == "count" for n in named):
                raise UnaccountedMention(f"'{m.words}' asks for as many cubes as there are (a quantity left to the "
                                         "robot) and no count is given (e.g. 'a tower of 5 cubes')")
            record.append({"mention": m.words, "kind": "superlative", "consumed_by": "the count named"})
        elif m.kind == "towers":
            have = _count_towers(goal)
            if have < m.count or (have > m.count and not re.search(r"\b(?:another|more|also|third|fourth|extra)\b", text)):
                # ("build two towers. Tower A: ... Tower B: ...": two more had been made up of cubes nobody named)
                raise UnaccountedMention(f"it names {m.count} towers but the task read has {have}")
            record.append({"mention": m.words, "kind": "towers", "consumed_by": f"{have} stacks"})
        elif m.kind == "all related":
            stacks = [p for p in goal if isinstance(p, P.Stack)]
            ref = {a.name for a in schema.assets if a.color == m.color}  # the cube or patch of that colour
            related = {n for p in goal if not isinstance(p, P.Stack | P.OnPatch | P.And | P.Not) and set(p.object_names()) & ref
                       for n in p.object_names()}
            if len(stacks) > 1 and not all(set(p.objects) & related for p in stacks):
                raise UnaccountedMention(f"'{m.words}' relates every tower to the {m.color} cube but the task read relates "
                                         f"{sum(bool(set(p.objects) & related) for p in stacks)} of {len(stacks)}")
            record.append({"mention": m.words, "kind": "all related", "consumed_by": "every tower related"})
        elif m.kind == "all on patch":
            stacks = [p for p in goal if isinstance(p, P.Stack)]
            colour = {a.name: a.color for a in schema.assets}
            placed = {n for p in goal if isinstance(p, P.OnPatch) and m.color in (None, colour.get(p.patch))
                      for n in ((p.a,) + tuple(getattr(p, "among", ())))}  # on that patch ("both on the white patch")
            if len(stacks) > 1 and not all(set(p.objects) & placed for p in stacks):
                raise UnaccountedMention(f"'{m.words}' puts every tower on a patch but the task read puts "
                                         f"{sum(bool(set(p.objects) & placed) for p in stacks)} of {len(stacks)} there")
            record.append({"mention": m.words, "kind": "all on patch", "consumed_by": "every tower on a patch"})
        elif m.kind == "structures":
            have = _count_structures(goal, m.predicates[0])
            if have < m.count:  # "Make a row of 3 and another row of 3": one row had been made, silently
                raise UnaccountedMention(f"it names {m.count} {m.predicates[0]}s but the task read has {have}")
            record.append({"mention": m.words, "kind": "structures", "consumed_by": f"{have} {m.predicates[0]}s"})
        elif m.kind == "direction":
            along = sorted(_orders(goal) & AXIS_ORDERS[m.region])
            if not along:
                raise UnaccountedMention(f"'{m.words}' says which way the cubes run and the task read orders none "
                                         "that way")
            record.append({"mention": m.words, "kind": "direction", "consumed_by": ", ".join(along)})
        elif m.kind == "axis":
            axis = "y" if m.region == "left" else "x"
            along = sorted(_orders(goal) & AXIS_ORDERS[m.region] | {f"in_line axis {axis}" for p in goal
                                                                     if isinstance(p, P.InLine) and p.axis == axis})
            if not along:
                raise UnaccountedMention(f"'{m.words}' says which way the cubes lie and the task read puts none that way")
            record.append({"mention": m.words, "kind": "axis", "consumed_by": ", ".join(along)})
        elif m.kind == "place word":
            carried = _carries_place_word(m.region, goal, regions) or (
                ["far_from"] if any(isinstance(p, P.FarFrom) for p in goal) and re.search(
                    rf"\bopposite\s+{re.escape(m.words)}\b", text) else [])  # "at opposite corners, far from each other"
            if not carried:
                raise UnaccountedMention(f"the place word '{m.words}' has no part in the task read (a cube picked by where it "
                                         "stands now refers to the current scene, which a task cannot see: name it by "
                                         "colour or label)")
            record.append({"mention": m.words, "kind": "place", "consumed_by": ", ".join(carried)})
        elif m.kind == "end role":
            said_by = {a.name: a.color or (a.label or "").lower() or None for a in schema.assets}
            ends = _ends_at(goal, m.region, said_by, m.color)
            if not ends and m.color and _ends_at(goal, m.region, said_by, None):
                raise UnaccountedMention(f"it contradicts itself: '{m.words}' puts {m.color} at the {m.region} end and the "
                                         "rest of it puts another cube there (say the order once)")
            if not ends:
                raise UnaccountedMention(f"'{m.words}' puts a cube at the {m.region} end and the task read leaves "
                                         "that end free (say the whole order, e.g. 'from left to right: red, green, blue')")
            record.append({"mention": m.words, "kind": "place", "consumed_by": ", ".join(ends)})
        elif m.kind == "bare place":  # a side of the table, or the sides of a relation ("red on the left, blue on the right")
            paired = any(o.kind in ("bare place", "end role") and o.region in _OPPOSITE.get(m.region, ()) for o in named)
            sides = {r for r in regions if m.region in r.split("_")} | {
                name for p in goal for name in SIDE_RELATIONS.get(m.region, ()) if p.name == name and paired} | (
                _ordered_lines(goal, m.region) if paired else set()) | {  # "gray at the far left, ..., green at the far right"
                f"{p.name} {m.region} end" for p in goal if isinstance(p, P.AnchoredLine) and m.region in ("left", "right")
                and getattr(p, m.region) and re.search(rf"\b{m.region}\s+end\b|\bfar\s+{m.region}\b|\b{m.region}most\b", text)}
            if not sides:
                raise UnaccountedMention(f"the place '{m.region}' has no part in the task read")
            record.append({"mention": m.words, "kind": "place", "consumed_by": ", ".join(sorted(sides))})
        elif m.region == "corners":
            corners = sorted(r for r in regions if r.count("_") == 1)
            if len(corners) < m.count:
                raise UnaccountedMention(f"'{m.words}' names {m.count} corners but the task read uses "
                                         f"{len(corners) or 'no'} corner(s)")
            record.append({"mention": m.words, "kind": "place", "consumed_by": "in_region " + ", ".join(corners)})
        else:
            middles = set()
            if m.region == "center":  # the middle of a row whose two ends are said as sides
                ends_said = {o.region for o in named if o.kind in ("bare place", "end role")}
                middles = set().union(*(_ordered_lines(goal, side, odd=True) for side in ("left", "front")
                                        if {side, _OPPOSITE[side][0]} <= ends_said))
            if middles:  # "the pink cube in the center" between the ends said: the middle of a row of an odd count
                record.append({"mention": m.region, "kind": "place", "consumed_by": ", ".join(sorted(middles))})
                continue
            if m.region not in regions:
                place = m.region.replace("_", " ")
                raise UnaccountedMention(f"the place '{place}' has no part in the task read")
            record.append({"mention": m.region.replace("_", " "), "kind": "place", "consumed_by": f"in_region {m.region}"})
    if sum(isinstance(p, P.Stack) for p in goal) > 1 and re.search(r"\b(?:put|place|move|set|slide|push|bring|shift)\s+(?:it|that)\b"
                                                                 r"(?!\s+(?:cube|block))", text):
        # "Stack red on green and blue on yellow, then put it on the white patch": which tower (the first had been moved)
        raise UnaccountedMention("'it' may be either tower; say which (e.g. \"put the tower with the red cube on top on the "
                                 "white patch\")")
    for m in re.finditer(rf"\b(\d+)\s+(?:cubes|blocks)\b[^.:;]{{0,25}}:\s*((?:{colors})(?:\s*,\s*(?:and\s+)?(?:{colors})|\s+and\s+(?:{colors}))+)"
                         r"\s*(?:[.;]|$)", text):  # "stack 2 cubes: red, blue, green": more or fewer listed than counted (the
        listed = re.findall(rf"\b(?:{colors})\b", m.group(2))  # rest had been made up, or the list padded, silently)
        if len(listed) != int(m.group(1)):
            raise UnaccountedMention(f"'{m.group(0).strip()}' counts {m.group(1)} cubes and lists {len(listed)}")
    each = re.search(r"\b(\d+)\s+(?:(?:cubes?|blocks?)\s+)?of\s+each\b(?!\s+(?:tower|stack|pile|row|line|structure))", text)
    if each:  # "a line of red and blue cubes, three of each": each colour said has that many (one of each had been made)
        named = {canon(c) for c in re.findall(rf"\b({colors})\b(?!\s+(?:goal\s+)?patch)", text)}
        short = sorted(c for c in named if by_color.get(c, 0) != int(each.group(1)))
        if named and short:
            raise UnaccountedMention(f"'{each.group(0)}' asks for {each.group(1)} cubes of each colour and the task read has "
                                     f"{by_color.get(short[0], 0)} {short[0]}")
    grids = [p for p in goal if isinstance(p, P.Grid) and p.rows > 1 and p.layers == 1]
    if grids and not any(isinstance(p, P.InLine | P.InLayers) for p in goal) and re.search(r"\b(?:rows|lines)\b", text) \
            and len(re.findall(rf"\b(?:{colors})\b", text)) >= grids[0].rows * grids[0].cols \
            and re.search(r"\bfirst\b[^.]*\bsecond\b|:\s*\S", text):
        # "two rows of three: red green blue, yellow white black": which cubes share a row is said, and a grid judges only
        # its shape (any cube in any site): the rows had been lost, silently
        raise UnaccountedMention("it says which cubes make each row but the task read is a grid that judges only its shape")
    return record


SINGLE_CUBE_RE = re.compile(rf"\b(?:(?P<det>the|a|an|one|another|that|this|your|my)\s+)?(?P<mod>(?:single|same|other|second)\s+)?"
                            rf"(?P<c>{COLOR_RE})\s+(?:block|cube|box|one)\b(?!\s+(?:tower|stack|column|pile|row|line)"
                            rf"|\s+(?:in|at|on|into)\s+(?:each|every)\b)")
"""A colour named as exactly one cube: "the green block", "a red cube", "red block" (a terse
writer's article left out; not "a red cube in each corner")."""

_NOT_SINGLE_BEFORE = re.compile(r"(?:\d+|two|three|four|five|six|seven|eight|nine|ten|each|every|all|some|any|no|more|several|"
                                r"many|few|both|of|those|these)\s+$")
"""Words before a bare "red block" that make it no single cube ("two red block", typo'd plurals)."""


_LIST_GAP = re.compile(r"\s*[,;:]\s*(?:(?:and|then|and\s+then)\s+)?")
"""What stands between two items of a list of cubes ("red block, red block and blue block")."""


def _single_color_bounds(text: str) -> dict[str, int]:
    """Colours that normalised ``text`` names only as single cubes ("the green block", "a red
    cube", "red block"), mapped to how many cubes of that colour the words allow, read in order:
    each indefinite ("a", "another"), each "other"/"second" and each item of a list after a comma
    is one more cube, and a definite mention ("the green block", said any number of times) is one
    cube only when none came before it.  The task must hold exactly that many."""
    colors = Counter(c for _, c in color_mentions(text))
    seen: Counter = Counter()
    allowed: Counter = Counter()
    prev: re.Match | None = None
    for m in SINGLE_CUBE_RE.finditer(text):
        # an item of a list ("red block, red block, blue block"), not a relation's object before a comma
        listed = (prev is not None and _LIST_GAP.fullmatch(text[prev.end():m.start()]) is not None
                  and not OBJECT_PREPOSITION_BEFORE.search(text[:prev.start()]))
        prev = m
        if not m.group("det") and (_NOT_SINGLE_BEFORE.search(text[:m.start()]) or m.group("mod")):
            continue
        c = canon_color(m.group("c"))
        seen[c] += 1
        if (m.group("mod") or "").strip() in ("other", "second") or m.group("det") in ("a", "an", "one", "another") or listed:
            allowed[c] += 1  # one more cube; so is an item of a list ("red block, red block, blue block")
        else:
            allowed[c] = max(allowed[c], 1)
    return {c: allowed[c] for c in sorted(seen) if colors[c] == seen[c]}


MULTIPLIED_RE = re.compile(r"\b(?:each|every|per|both|times|respectively|corners|sides|patches|another|second|more)\b|\ball\s+(?:the\s+)?\d+\b|\b(?:\d+|several)\s+(?:[a-z\-]+\s+){0,2}?"
                           r"(?:towers|stacks|columns|piles|rows|lines|pillars|groups|sets|layers|levels|copies)\b")
"""Words that multiply a count ("2 red blocks on each corner", "two towers of 3 red blocks", "a
column of three in all four corners"):
with any of them a count is not the number of cubes of its colour."""


def _counted_color_bounds(text: str) -> dict[str, int]:
    """Colours that normalised ``text`` names only inside counts of that colour alone ("two red
    ones", "3 green blocks"), mapped to the counts' sum: the task may hold no more cubes of that
    colour.  Empty when a word multiplies a count (:data:`MULTIPLIED_RE`)."""
    if MULTIPLIED_RE.search(text):
        return {}
    colors = Counter(c for _, c in color_mentions(text))
    counted: Counter = Counter()
    mentioned: Counter = Counter()
    for m in mentions(text, COLOR_RE, canon_color):
        if m.kind == "count" and m.color and "," not in m.color:
            counted[m.color] += m.count
            mentioned[m.color] += len(re.findall(rf"\b(?:{COLOR_RE})\b", m.words))
    return {c: n for c, n in sorted(counted.items()) if mentioned[c] == colors[c]}


def account_named(text: str, schema: TaskSchema) -> list[dict]:
    """Colours, then counts, patches, places and relations of normalised ``text`` against
    ``schema`` (:func:`rpg.schema.accounting.account`).

    Returns:
        The accounting record: one ``{"mention", "kind", "consumed_by"}`` per mention, the
        colours first.

    Raises:
        UnaccountedMention: the first mention with no part in the schema.
    """
    placed = set(schema.goal_predicate().object_names()) | {n for s in schema.initial_state.structures for n in s}
    spelled = {p.text.lower() for p in schema.goal_predicate().walk() if isinstance(p, P.Reads)}  # "spell RED": a word
    missing = sorted({c for i, c in color_mentions(text) if not (
        re.match(r"[a-z]+", text[i:]).group(0) in spelled and re.search(r"\b(?:spell\w*|reads?|read\s+as|words?)\s+(?:out\s+)?['\"]?$", text[:i]))}
                     - {a.color for a in schema.assets if a.name in placed or a.kind == "goal_patch"})
    if missing:  # no cube of that colour, or one the goal and rho_0 leave where it falls
        raise UnaccountedMention(f"the {', '.join(missing)} cube(s) it names have no place in that task")
    cubes = Counter(a.color for a in schema.assets if a.kind != "goal_patch" and a.color)
    for color, n in _single_color_bounds(text).items():
        if cubes[color] != n:  # "the red block ... a red block": two; "a red block ... the red block": one
            raise UnaccountedMention(f"it names {'one' if n == 1 else n} {color} cube{'s' if n > 1 else ''} but the task "
                                     f"read has {cubes[color]}")
    for color, n in _counted_color_bounds(text).items():
        if cubes[color] > n:
            raise UnaccountedMention(f"it names {n} {color} cube{'s' if n > 1 else ''} but the task read has {cubes[color]}")
    named = dict.fromkeys(c for _, c in color_mentions(text))
    record = [{"mention": c, "kind": "color",
               "consumed_by": ", ".join(a.name for a in schema.assets if a.color == c)} for c in named]
    record += [{"mention": a.label, "kind": "label", "consumed_by": a.name}
               for a in schema.assets if a.kind == "semantic_cube" and a.label]
    return record + account(mark_regions(text), schema, COLOR_RE, canon_color)


def check_mentions(instruction: str, schema: TaskSchema) -> list[dict]:
    """Check that ``schema`` accounts for the colours, counts, goal patches, places and
    relations that ``instruction`` names, whoever wrote the schema (the builtin parser or a model).

    Returns:
        The accounting record (see :func:`rpg.schema.accounting.account`).

    Raises:
        UnaccountedMention: a named colour, count, patch, place or relation has no part in the schema.
    """
    text, _, dropped = normalize_words(instruction, strict=False)
    return account_named(text, schema) + [
        {"mention": w, "kind": "ignored", "consumed_by": f"nothing: no meaning for the goal (reads like '{like}')"}
        for w, like in dropped]



_PAIR_CARRIERS = {"on": (P.Stack, P.UnorderedStack, P.AnchoredStack), "under": (P.Stack, P.UnorderedStack, P.AnchoredStack)}
"""Goal predicates that carry "on"/"under" between two cubes; every other relation word needs a
pairwise relation or :class:`~rpg.domain.predicates.Between` of the two."""


def _pair_relation_dropped(f: Features, schema: TaskSchema, cubes: list) -> ParseError | None:
    """A ParseError when the instruction says "put the X cube REL the Y cube" of two cubes, each the
    one of its colour, and no goal predicate relates the two: "make a row of red, blue and green and
    put the yellow cube on the blue cube" had become a row of four (the relation dropped)."""
    parts = list(schema.goal_predicate().conjuncts())
    if schema.initial_state.structures:
        return None  # "Initially the red cube is on the blue cube": how the cubes start, not the goal
    bare = [] if re.search(r"\b(?:start\w*|initial\w*|begin\w*)\b", f.text) else lexicon.PAIR_RELATION_BARE_RE.finditer(f.text)
    for m in itertools.chain(lexicon.PAIR_RELATION_RE.finditer(f.text), bare):  # (a start is refused for what it is)
        a, b = canon_color(m.group("a")), canon_color(m.group("b"))
        named = {c: [x.name for x in cubes if x.color == c] for c in (a, b)}
        if a == b or any(len(v) != 1 for v in named.values()):
            continue
        pair = {named[a][0], named[b][0]}
        rel = "on" if m.group("rel").startswith("on") else "under" if m.group("rel") == "under" else "side"
        carriers = _PAIR_CARRIERS.get(rel, (P.Between,))
        held = any(pair <= set(p.object_names()) and (isinstance(p, carriers) or (rel == "side" and len(set(p.object_names())) == 2))
                   for p in parts)
        if not held:
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group(0)}' relates two cubes "
                              "that task does not relate. Rephrase (one sentence per structure helps), or use --model")
    return None


def _sentence_without_content(text: str, schema: TaskSchema, walk: list) -> str | None:
    """The first sentence of normalised ``text`` (when it has more than one) that names nothing a task is made of
    (:data:`lexicon.SENTENCE_CONTENT_RE`: a cube, colour, label, count, patch, place, relation or structure; an order
    word only where the goal, whose predicates are ``walk``, sorts, reads or orders a line), or None.  Such a sentence ("rotate.", "lift it.", "and the opposite.")
    was read by no reader, and what it says may change the task, so the compile refuses rather than drop it (framing
    that names nothing of the task was dropped before: :func:`rpg.schema.reading.drop_asides`)."""
    sentences = [s.strip() for s in re.split(r"(?<=[.!?;])\s+", text) if re.search(r"[a-z0-9]", s)]
    if len(sentences) < 2:
        return None
    # "Sort the digits 1, 2, 3. Ascending.", "Lesson 3: Ordering.": an order word where the goal sorts, reads or orders a line
    ordered = any(isinstance(p, (P.SortedBy, P.Reads)) or (isinstance(p, P.InLine) and p.order) for p in walk)
    labelled = any(a.label for a in schema.assets)
    for s in sentences:
        words = re.findall(r"\S*_\S*|[a-z][a-z'\-]*", s)
        if (lexicon.SENTENCE_CONTENT_RE.search(s) or lexicon.FREEDOM_SENTENCE_RE.search(s) or lexicon.RESTATED_GOAL_RE.match(s)
                or (ordered and lexicon.ORDER_WORDS.search(s)) or (labelled and re.search(r"\b[a-z]\b", s))
                or all(w in lexicon.FUNCTION_WORDS or "_" in w for w in words)):
            continue  # (a sentence of function words alone is what a rewrite left of framing: "that would be")
        return s
    return None


def _unread(f: Features, schema: TaskSchema, said: str, why: str) -> ParseError:
    """The refusal of a reading of ``f`` that leaves the words ``said`` unread: what it read, the words, and ``why``
    (which says how to say it instead)."""
    return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{said}' {why}")


def _follow_up_relation(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A follow-up sentence that is only a relation ("Put the red block left of the blue block. Right of it."): it had
    been read as nothing (:data:`lexicon.SUBJECTLESS_RELATION_RE`)."""
    follow_up = lexicon.SUBJECTLESS_RELATION_RE.search(f.text)
    if follow_up and len(re.findall(r"[.!?;]\s", f.text[:follow_up.start() + 1])) + (follow_up.start() > 0) > 0:
        return ParseError(f"\"{f.original[:80]}\": '{follow_up.group(0).strip()}' says a relation without the cube it is for: "
                          "a correction of what was said before, or one more relation? Say the whole goal once (e.g. \"put the "
                          "red block to the right of the blue block\"), or use --model")
    return None


def _unread_reversal(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A reversal no reader read ("Put the red block on the blue block, reversed."): the order said before had been kept
    (:data:`lexicon.REVERSAL_RE`)."""
    turned = lexicon.REVERSAL_RE.search(f.text) or (
        lexicon.REVERSE_ORDER_RE.search(f.text) if not lexicon.LISTED_REVERSE_ORDER_RE.search(f.text) else None)
    if turned and not schema.initial_state.structures and not any(isinstance(p, (P.SortedBy, P.Reads)) for p in walk):
        return _unread(f, schema, turned.group(0), "turns an order or a "
                       "structure around, and that task reads nothing it turns. Say the final order once (e.g. \"stack the "
                       "blue block on the red block\"), or use --model")
    return None


def _counted_others(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """Cubes counted under or on a named one ("Stack the red block on top of two blocks"): three cubes, not two
    (:data:`lexicon.COUNTED_OTHERS_RE`)."""
    for m in lexicon.COUNTED_OTHERS_RE.finditer(f.text):
        n = int(m.group("n") or m.group("m"))
        if len(cubes) < n + 1:
            return _unread(f, schema, m.group(0), f"counts {n} cubes "
                           f"besides the one they carry or hold, and that task has {len(cubes)} in all. Say the whole "
                           "structure (e.g. \"a tower of three blocks with the red block on top\"), or use --model")
    return None


def _label_end(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A letter cube given a tower's end the reading contradicts ("Spell GO in a tower, with G at the bottom": G had been
    on top; :data:`lexicon.LABEL_END_SAID_RE`)."""
    for m in lexicon.LABEL_END_SAID_RE.finditer(f.text):
        label, end = m.group("l").upper(), -1 if m.group("end") == "top" else 0
        held = [st.objects for st in walk if isinstance(st, P.Stack)
                and any(a.name == n and a.label == label for n in st.objects for a in schema.assets)]
        if held and not any(next((a.label for a in schema.assets if a.name == st[end]), None) == label for st in held):
            return ParseError(f"\"{f.original[:80]}\" contradicts itself: '{m.group(0)}' puts {label} at the "
                              f"{'top' if end else 'bottom'}, and the rest of it reads {schema.goal_summary}. Say the order once "
                              "(e.g. \"a tower of letter cubes, G at the bottom and O on top\"), or use --model")
    return None


def _moved_pronoun(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A moved "it" after a relation between two named cubes ("Put the red cube next to the green cube and then stack it
    on the blue cube": red or green? green had been taken; :data:`lexicon.PRONOUN_MOVED_RE`)."""
    moved = lexicon.PRONOUN_MOVED_RE.search(f.text)
    before = f.text[:moved.start()] if moved else ""
    if moved and moved.group("p") == "it" and len({c for _, c in color_mentions(before)}) > 1 \
            and not re.search(r"[.;!?]\s", before) \
            and re.search(r"\b(?:next\s+to|beside|behind|in\s+front\s+of|left|right|far|near|between)\b", before):
        return ParseError(f"\"{f.original[:80]}\": '{moved.group(0)}' may mean any cube named before it; name the cube (e.g. "
                          "\"stack the red cube on the blue cube\"), or use --model")
    return None


def _piles_said(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """More piles said than the task holds ("in one pile ... in another pile": the piles had been merged;
    :data:`lexicon.PILES_SAID_RE`)."""
    piles = list(lexicon.PILES_SAID_RE.finditer(f.text))
    if not piles:
        return None
    said = max(piles, key=lambda m: int(m.group("n")) if m.group("n") else 2)
    want = int(said.group("n")) if said.group("n") else 2
    have_piles = sum(len(p.groups) for p in walk if isinstance(p, P.Piles))
    if have_piles and have_piles < want:
        return _unread(f, schema, said.group(0), f"says {want} "
                       f"piles and that task has {have_piles}. Say each pile's cubes (e.g. \"a pile of the red and "
                       "green cubes and a pile of the blue cube\"), or use --model")
    return None


def _scene_count(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A whole-scene count the task lacks ("There are four cubes: red, green, blue and yellow. Stack all of them.": a
    fifth had been made up; :data:`lexicon.SCENE_COUNT_RE`)."""
    told = lexicon.SCENE_COUNT_RE.search(f.text)
    n = int(told.group("n") or told.group("n2")) if told else len(cubes)
    if n != len(cubes):
        return _unread(f, schema, told.group(0), f"says the task has "
                       f"{n} cubes and that task has {len(cubes)}. Rephrase, or use --model")
    return None


def _line_roles(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A cube's place in a line of three or more that the task does not order ("Line up the red, blue and yellow cubes
    with blue at one end."; of two cubes each is an end; :data:`lexicon.LINE_ROLE_RE`)."""
    loose = [p for p in walk if type(p) is P.InLine and not p.order and len(p.objects) > 2]  # (an AnchoredLine's ends are read)
    if not loose or any(isinstance(p, P.Between) for p in walk):
        return None
    role = lexicon.LINE_ROLE_RE.search(lexicon.FREEDOM_SENTENCE_RE.sub(" ", re.sub(r"\bin\s+any\s+order\b", " ", f.text)))
    if role:
        return _unread(f, schema, role.group(0), "gives a cube a place "
                       "in the line and that task orders none of it. Say the whole order (e.g. \"from left to right: "
                       "red, green, blue\"), or use --model")
    return None


_ORDERED_LINE_ROLE_RE = re.compile(
    rf"(?:,\s*|\bwith\s+|(?:^|(?<=[.;!]\s))(?=(?:the\s+)?(?:{COLOR_RE}|\d)(?:\s+(?:cube|block|one))?\s+is\s))(?:the\s+)?(?P<c>{COLOR_RE}|\d)"
    r"(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+|sits\s+)?"
    r"(?:(?:on|at)\s+the\s+(?:far\s+)?(?P<side>left|right)(?:\s+end)?(?!\s+(?:side|half|edge|of|corner))|in\s+the\s+(?P<mid>middle|cent(?:er|re))"
    r"|(?:the\s+)?(?P<most>leftmost|rightmost)|(?:the\s+)?(?P<bare>left|right)(?:\s+(?:one|end))?(?=\s*(?:[.;!]|$)))\b"
    # "... The rightmost is orange." ("rightmost" read "right"): the end's cube said after the line
    rf"|(?:^|(?<=[.;!]\s))the\s+(?:(?P<end>left|right)(?:most)?|(?P<mid2>middle|cent(?:er|re)))(?:\s+(?:one|cube|block|end))?\s+(?:is|should\s+be|must\s+be)\s+"
    rf"(?:the\s+)?(?P<c2>{COLOR_RE}|\d)\b(?=[^.;!]*(?:[.;!]|$))")


def _ordered_line_roles(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A cube given an end or the middle of a line the task orders, at another place there ("line up red, blue, green from
    left to right with red in the middle", "a row of red, blue, green from left to right, green on the left": the order
    had won silently), or an ordered line said to be in any order."""
    lines = [p for p in walk if isinstance(p, P.InLine) and p.order in ("left_to_right", "right_to_left") and len(p.objects) > 2]
    if not lines:
        return None
    if re.search(r"\bin\s+any\s+order\b", f.text) and re.search(r"\b(?:left|right)\s+to\s+(?:the\s+)?(?:right|left)\b", f.text):
        return ParseError(f"\"{f.original[:80]}\" contradicts itself: it says an order from one side to the other and 'in any "
                          "order'; say one, or use --model")
    name_of = {a.name: (a.label or a.color) for a in cubes}
    for m in _ORDERED_LINE_ROLE_RE.finditer(f.text):
        c = m.group("c") or m.group("c2")
        said = c if c.isdigit() else canon_color(c)
        for line in lines:
            who = [name_of.get(n) for n in line.objects]
            if said not in who:
                continue
            left = line.order == "left_to_right"
            if m.group("mid") or m.group("mid2"):
                places = [len(who) // 2] if len(who) % 2 else []
            else:
                side = m.group("side") or m.group("bare") or m.group("end") or ("left" if m.group("most") == "leftmost" else "right")
                places = [0 if (side == "left") == left else len(who) - 1]
            if not any(who[i] == said for i in places):
                return ParseError(f"\"{f.original[:80]}\" contradicts itself: '{m.group(0).strip(' ,')}' gives a cube an end or the "
                                  f"middle of the line, and the line's order ({schema.goal_summary}) puts it elsewhere; say the order "
                                  "once, or use --model")
    return None


_A_CUBE_RE = re.compile(r"\b(?:a|an|another)\s+(?:cube|block)\b(?!\s+(?:of|tower|stack|high|tall|wide|long|row|line|each|per)\b|-)")


def _unnamed_merged(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """More cubes said one by one with no colour ("a cube on the red patch and a cube in the back left corner") than the
    task has: two of them had been read as one cube, put in both places."""
    said = len(_A_CUBE_RE.findall(f.text))
    if said > len(cubes):
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but it says {said} cubes one by one and that "
                          f"task has {len(cubes)}: two of them were read as one. Give them colours (e.g. \"a red cube ... and "
                          "a blue cube ...\"), or use --model")
    counted = re.search(rf"\b(?:\d+|{'|'.join(lexicon.NUMBER_WORDS)}|cubes|blocks|bricks|ones|all|each|every|both|pair|towers?|stacks|(?:a|the)\s+stack|rows?"
                        r"|lines?|piles?|walls?|grids?|pyramids?|circles?|rings?|columns?|letters?|digits?|numbers?)\b", f.text)
    own = {canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|area|zone))", f.text)}
    unnamed = [a for a in cubes if not a.label and a.color not in own]
    mentioned = len(re.findall(rf"\b(?:a|an|another|the|one|this|that|other)\s+(?:(?!(?:{COLOR_RE})\b)[a-z]+\s+)?(?:cube|block|one)\b", f.text))
    if not counted and said and len(unnamed) > max(said, mentioned):  # "put a cube on the red patch and stack a block on it"
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but it says {said} cubes without a colour "
                          f"and that task has {len(unnamed)}: a cube nobody said was made up. Give the cubes colours, or use "
                          "--model")
    return None


def _some_of_them(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """"N of them C" (or "the first of them", "at least one of them") left unread ("a row of four cubes, one of them
    purple, from left to right" had made every cube purple): the task must have exactly N cubes of that colour."""
    for m in re.finditer(rf"\b(?P<q>at\s+(?:least|most)\s+|the\s+(?:first|last|second)\s+)?(?P<k>\d+)?\s*of\s+(?:them|which|those)\s+"
                         rf"(?:is\s+|are\s+|being\s+)?(?P<c>{COLOR_RE})\b", f.text):
        if not m.group("q") and not m.group("k"):
            continue  # "all of them orange", "each of them": every cube
        have = sum(a.color == canon_color(m.group("c")) for a in cubes)
        if m.group("q") or have != int(m.group("k")):
            return _unread(f, schema, m.group(0), f"gives {m.group('k') or 'some'} of the cubes a colour and that task has {have} "
                           f"{canon_color(m.group('c'))}. Say each group (e.g. \"a row of one purple and three red cubes, in any "
                           "order\"), or use --model")
    return None


_OTHERS_COLOUR_RE = re.compile(rf"\b(?:the\s+)?(?:others|rest|other\s+(?:\d+\s+)?(?:cubes|blocks|ones))\s+(?:are\s+|all\s+|being\s+|should\s+be\s+|"
                               rf"must\s+be\s+)*(?P<c>{COLOR_RE})\b(?!\s+(?:cube|block|one|patch))")


def _others_colour(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """"The others red" left unread ("the middle block is blue, the others red" had kept red, blue, green): every cube of a
    colour not said elsewhere must be that colour."""
    for m in _OTHERS_COLOUR_RE.finditer(f.text):
        c = canon_color(m.group("c"))
        said = {canon_color(w) for w in re.findall(rf"\b(?:{COLOR_RE})\b", f.text[:m.start()] + " " + f.text[m.end():])}
        if any(a.color not in said | {c} for a in cubes if not a.label) or not any(a.color == c for a in cubes):
            return _unread(f, schema, m.group(0), "gives the other cubes a colour and that task has others of other colours. "
                           "Say each cube (e.g. \"from bottom to top: red, blue, red\"), or use --model")
    return None


def _left_over_alternative(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """An alternative no contrast read ("Instead of putting red next to blue, put green on yellow.": both goals had been
    kept; :data:`lexicon.LEFT_OVER_ALTERNATIVE_RE`); one sentence ending "... instead" (a steering edit's replacement)
    says no other goal."""
    instead = lexicon.LEFT_OVER_ALTERNATIVE_RE.search(f.text)
    if instead and re.fullmatch(r"instead\s*[.!]?\s*", f.text[instead.start():]) and not re.search(r"[.;!?]\s", f.text):
        return None
    if instead:
        return _unread(f, schema, instead.group(0), "sets one goal against "
                       "another, and that task keeps both. Say only the goal that stands, or use --model")
    return None


def _idle_sentence(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A sentence that names nothing the task holds ("Stack the red cube on the blue cube. Rotate.": it had been
    ignored; :func:`_sentence_without_content`)."""
    idle = _sentence_without_content(f.text, schema, walk)
    if idle:
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but the sentence '{idle}' names nothing "
                          "that task holds (no cube, colour, count, place, relation or structure), and its words may change "
                          "what the task asks. Rephrase it as a place for cubes, leave it out, or use --model")
    return None


def _raised_on_table(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A cube said to end on the table (:data:`lexicon.TABLE_SAID_RE`) that the goal stacks on another, every cube of its
    colour ("stack green, yellow, pink from bottom to top, and put a blue block on the table": blue had joined the
    tower; "put red on blue and put red on the table": the table had been dropped; "put it on the table" of a goal that
    stacks cubes and says no tower: which cube is not said)."""
    raised: set[str] = set()
    for p in walk:
        if type(p) is P.On:
            raised.add(p.a)
        elif type(p) is P.Stack or (type(p) is P.AnchoredStack and p.bottom):
            raised.update(p.objects[1:])
    for m in lexicon.TABLE_SAID_RE.finditer(f.text):
        if not m.group("c") and raised and not re.search(r"\b(?:towers?|stacks?|piles?)\b", f.text):
            named, said = raised, "a"  # "the red cube is now on the blue cube; put it on the table": which cube, or a contradiction
        else:
            named = {a.name for a in cubes if m.group("c") and a.color == canon_color(m.group("c"))}
            said = f"the {canon_color(m.group('c'))}" if m.group("c") else ""
        if named and named <= raised:
            return ParseError(f"\"{f.original[:80]}\" puts {said} cube on the table and on another "
                              "cube; a goal is checked once, at the end of the episode: say where it must end up (if it "
                              "starts stacked, say so: \"Initially the red cube is on the blue cube. Put it on the table.\"), "
                              "or use --model")
    return None


_UNDONE_RE = re.compile(rf"\b(?:unstack\w*|dismantl\w*|disassembl\w*|tak(?:e|ing)\s+apart|break\w*\s+(?:up|down))\s+(?:the\s+|a\s+)?(?:(?:tower|stack)\s+(?:of\s+)?)?"
                        rf"(?P<chain>(?:{COLOR_RE})(?:\s+(?:on|on\s+top\s+of|atop|under)\s+(?:the\s+)?(?:{COLOR_RE}))+)")


def _undone_kept(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A tower the words undo ("after unstacking the green-on-yellow tower") that the goal keeps stacked (it had been read as
    a tower to build)."""
    pairs = {(p.a, p.b) for p in walk if type(p) is P.On} | {
        (st.objects[i + 1], st.objects[i]) for st in walk if type(st) is P.Stack for i in range(len(st.objects) - 1)}
    color_of = {a.name: a.color for a in cubes}
    kept = {(color_of.get(a), color_of.get(b)) for a, b in pairs}
    for m in _UNDONE_RE.finditer(f.text):
        said = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.group("chain"))]
        under = " under " in m.group("chain")
        links = list(zip(said, said[1:], strict=False)) if not under else [(b, a) for a, b in zip(said, said[1:], strict=False)]
        if any(link in kept for link in links):
            return ParseError(f"\"{f.original[:80]}\" undoes '{m.group(0)}' and that task keeps it stacked; if it is how the "
                              "cubes start, say so (\"Initially the green cube is on the yellow cube. ...\"), or use --model")
    return None


_WITH_RELATION_RE = re.compile(
    rf"\bwith\s+(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:is|sits|goes|stands|right|directly|just)\s+)*"
    r"(?P<rel>next\s+to|beside|on\s+top\s+of|on|atop|opposite|across\s+from|(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of"
    rf"|behind|under|below|above|over)\s+(?:the\s+)?(?P<b>{COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|square|area)\b)")


def _with_relation(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A relation between two named cubes said inside a structure's "with" clause ("a row of four cubes with red next to
    blue", "a circle of four cubes with red opposite blue"): some goal predicate must relate those two cubes themselves
    (a relation over both, or a tower or ordered row in which they stand side by side); the structure alone had carried
    the words, and the relation was dropped."""
    for m in _WITH_RELATION_RE.finditer(f.text):
        a, b = canon_color(m.group("a")), canon_color(m.group("b"))
        names = {c: {x.name for x in cubes if x.color == c} for c in (a, b)}
        related = False
        for p in walk:
            objs = list(getattr(p, "objects", ()) or p.object_names())
            if (type(p) is P.Stack or isinstance(p, P.InLine)) and getattr(p, "order", "x") is not None:  # (an unordered
                # tower or row puts no two cubes side by side)
                pairs = list(itertools.pairwise(objs))
            elif p.name in (*PAIRWISE_RELATIONS, "on"):
                pairs = [tuple(p.object_names()[:2])]
            else:
                continue
            related = related or any({u, v} & names[a] and {u, v} & names[b] and u != v for u, v in pairs)
        if not related:
            return _unread(f, schema, m.group(0)[len("with "):].strip(), "relates two cubes that the task read does not "
                           "relate to each other. Say the relation in a sentence of its own, or use --model")
    return None


_NOT_A_PATCH = r"(?!\s+(?:goal\s+)?(?:patch|pad|mat|tile|square|area|zone))"
"""After a colour: it is not a goal patch's ("the green patch"), so the colour names a cube."""

_ANOTHER_SAID_RE = re.compile(rf"\b(?:another|a\s+second|a\s+2nd|1\s+more|one\s+more|an\s+extra|an\s+additional)\s+(?P<c>{COLOR_RE})\b"
                              r"(?!\s+(?:goal\s+)?(?:patch|pad|mat|tile|square|area|zone|towers?|stacks?|rows?|lines?|piles?))")
"""A second cube of a colour said before ("stack red on blue, and another red on top"): :func:`_another_said`."""


def _another_said(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """"another red", "a second red", "one more red": the task must have more cubes of that colour than the one said
    before ("stack red on blue, and another red on top" had read one red cube, the second dropped, silently)."""
    for m in _ANOTHER_SAID_RE.finditer(f.text):
        colour = canon_color(m.group("c"))
        before = len(re.findall(rf"\b{colour}\b" + _NOT_A_PATCH, f.text[:m.start()]))
        if before and sum(x.color == colour for x in cubes) < before + 1:  # (none said before: "one more blue block next
            # to the red block" is one blue cube, read so)
            return _unread(f, schema, m.group(0), f"adds a {colour} cube to the one said before and the task read has "
                           f"{sum(x.color == colour for x in cubes)}; say each cube's place (e.g. \"a tower of blue, red, red from "
                           "the bottom\"), or use --model")
    return None


_BETWEEN_SAID_RE = re.compile(rf"\b(?P<a>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:is|goes|sits|stands|should\s+be|must\s+be)\s+)?"
                              rf"(?:(?:right|exactly|directly)\s+)?(?:in\s+)?between\s+(?:the\s+)?(?P<b>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+"
                              rf"and\s+(?:the\s+)?(?P<c>{COLOR_RE})\b" + _NOT_A_PATCH)
"""One cube said between two others by colour ("a row with red between blue and green"): :func:`_between_held`."""


def _between_held(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """"red between blue and green" must hold in the goal: a between of those cubes, or a tower or ordered row in which a
    red cube stands next to a blue one on one side and a green one on the other ("make a row with red between blue and
    green" had become a row of the three in any order, silently)."""
    for m in _BETWEEN_SAID_RE.finditer(f.text):
        a, b, c = (canon_color(m.group(k)) for k in "abc")
        if len({a, b, c}) < 3:
            continue  # one colour twice: which cube is which is the readers' (refused there when not said)
        colour = {x.name: x.color for x in cubes}
        held = any(isinstance(p, P.Between) and colour.get(p.a) == a and {colour.get(p.b), colour.get(p.c)} == {b, c}
                   for p in walk)
        for p in walk:
            if (type(p) is P.Stack or (isinstance(p, P.InLine) and p.order is not None)):
                seq = [colour.get(n) for n in p.objects]
                held = held or any(seq[i] == a and {seq[i - 1], seq[i + 1]} == {b, c} for i in range(1, len(seq) - 1))
        if not held:
            return _unread(f, schema, m.group(0), "puts a cube between two others and the task read does not; say it "
                           "in a sentence of its own (e.g. \"put the red cube between the blue and green cubes\"), or use --model")
    return None


_COLOUR_LIST_RE = re.compile(rf"(?:\bof|:|\bstack|\bline\s+up|\barrange|\bput)\s+(?:the\s+)?(?P<l>(?:{COLOR_RE})(?:(?:\s*,\s*(?:and\s+|then\s+)?"
                             rf"|\s+(?:and|then)\s+)(?:the\s+)?(?:{COLOR_RE}))+)\b(?!\s+(?:goal\s+)?(?:patch|pad|mat))")
"""The colours a structure is said of, listed ("a tower of red, blue and green", "bottom to top: red, green, blue")."""


def _listed_once(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A text that says its cubes as one list of colours, and no count, says how many of each colour there are: "build a
    tower of red, blue and green: red is second from the bottom" had made a fourth, red cube, "stack red, blue and green,
    red over blue" five, silently.  The task read may not have more cubes of a listed colour than the list names (a
    colour said with a count or "another" elsewhere is the other checks'); a list said from its ends against a role of
    its own ("from bottom to top: red, green, blue, with green on top") is a contradiction."""
    lists = list(_COLOUR_LIST_RE.finditer(f.text))
    if len(lists) != 1 or re.search(r"\b(?:\d+|another|more|extra|each|every|both|all|pairs?|again|too|also|copies|"
                                    r"patch\w*|pads?|mats?|rows|lines|towers|stacks|piles|walls|pyramids|layers?|tiers?|levels?)\b",
                                    f.text.replace(lists[0].group(0), " ")):
        return None
    listed = Counter(canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", lists[0].group("l")))
    have = Counter(x.color for x in cubes)
    over = sorted(c for c in listed if have[c] > listed[c])
    if over:
        return _unread(f, schema, lists[0].group(0).lstrip(":").strip(), f"lists {listed[over[0]]} {over[0]} cube(s) and the "
                       f"task read has {have[over[0]]}; say each cube once, in one order (e.g. \"from bottom to top: ...\"), "
                       "or use --model")
    direction = re.search(r"\b(?:from\s+(?:the\s+)?(bottom|top)\s+(?:to|on)|(bottom|top)\s+to)\s+(?:the\s+)?(?:top|bottom)\b", f.text)
    if direction:  # ("from bottom to top of ..." is normalized to "from bottom on top of ...")
        seq = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", lists[0].group("l"))]
        if (direction.group(1) or direction.group(2)) == "top":
            seq.reverse()
        for m in lexicon.STACK_ROLE_RE.finditer(f.text):
            end = "top" if (m.group("end") or m.group("end2")) == "top" else "bottom"
            if m.group("c") in COLORS and canon_color(m.group("c")) != (seq[-1] if end == "top" else seq[0]):
                return ParseError(f"\"{f.original[:80]}\" contradicts itself: the list puts {seq[-1] if end == 'top' else seq[0]} "
                                  f"at the {end} and '{m.group(0).strip(' ,;.')}' puts {canon_color(m.group('c'))} there; say the "
                                  "order once, or use --model")
    return None


_RANK_SAID_RE = re.compile(
    rf"\b(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is|goes|comes|sits|stands|should\s+be|must\s+be|will\s+be)\s+(?:the\s+)?"
    r"(?P<n>first|second|third|fourth|fifth|sixth|1st|2nd|3rd|4th|5th|6th)(?:\s+(?:one|cube|block|in\s+line))?"
    r"(?:\s+from\s+(?:the\s+)?(?P<end>left|right|bottom|top|front|back)(?:\s+to\s+(?:the\s+)?(?:left|right|top|bottom|front|back))?)?\b"
    r"(?!\s*,?\s*(?:and\s+)?then\b)")  # ("gray goes first, then brown on the gray": a sequence, read by the readers)
# ("from the left" is normalized to "from left to right")
"""A cube given its rank in a row or tower ("red is third from the left", "red is second from the bottom"): :func:`_rank_held`."""
_RANKS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "1st": 1, "2nd": 2, "3rd": 3, "4th": 4,
          "5th": 5, "6th": 6}
_FROM_END = {"left": "left_to_right", "right": "right_to_left", "front": "front_to_back", "back": "back_to_front"}
_REVERSED = {"left_to_right": "right_to_left", "right_to_left": "left_to_right", "front_to_back": "back_to_front",
             "back_to_front": "front_to_back"}


def _rank_held(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """"red is third from the left" must hold: an ordered row or a tower of the goal with a cube of that colour at that
    rank counted from that end (a tower from its bottom when no end is said); "make a row of red, green and blue: red is
    third from the left" had put red first, silently."""
    colour = {x.name: x.color for x in cubes}
    directed = re.search(r"\b(?:left|right|front|back|bottom|top)\s+to\s+(?:the\s+)?(?:left|right|front|back|bottom|top)\b",
                         _RANK_SAID_RE.sub(" ", f.text))
    for m in _RANK_SAID_RE.finditer(f.text):
        if not directed:  # "a tower of red, blue and green; green is third": the rank alone orders one cube, and which order
            # the rest have is not said (free_listed_orders had freed the whole tower, the rank lost, silently)
            return _unread(f, schema, m.group(0), "gives a cube a rank, and the order of the others is not said; say the "
                           "whole order (e.g. \"from bottom to top: red, blue, green\"), or use --model")
        c, n, end = canon_color(m.group("c")), _RANKS[m.group("n")], m.group("end")
        held = False
        for p in walk:
            seq = [colour.get(x) for x in getattr(p, "objects", ())]
            if type(p) is P.Stack and end in (None, "bottom", "top"):
                seq = seq[::-1] if end == "top" else seq
            elif isinstance(p, P.InLine) and end in _FROM_END and p.order in (_FROM_END[end], _REVERSED[_FROM_END[end]]):
                seq = seq if p.order == _FROM_END[end] else seq[::-1]
            else:
                continue
            held = held or (len(seq) >= n and seq[n - 1] == c)
        if not held:
            return _unread(f, schema, m.group(0), "gives a cube a rank the task read does not give it; say the whole order "
                           "(e.g. \"from left to right: blue, green, red\"), or use --model")
    return None


def _spelled_word_read(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A word the instruction spells ("Spell GO, then put the red cube next to the G") must be read as one structure of
    its letter cubes (a row or tower holding every letter); the spelling had been dropped and only the relation kept."""
    label = {x.name: x.label for x in cubes}
    for m in re.finditer(r"\b(?i:spell(?:s|ed|ing)?)\s+(?:(?i:the\s+word)\s+|(?i:out)\s+)?([A-Z]{2,})\b", f.original):
        word = Counter(m.group(1))
        if not any(not word - Counter(label.get(n) for n in getattr(p, "objects", ())) for p in walk):
            return _unread(f, schema, m.group(0), "spells a word and the task read lays out no row or tower of its letters; "
                           "say the word in a sentence of its own, or use --model")
    return None


_GROUP_SAID_RE = re.compile(
    r"(?:,\s*|\band\s+)(?:with\s+)?(?P<q>2|all(?:\s+\d)?|\d\s+of\s+them)(?:\s+of\s+them)?(?:\s+(?:cubes|blocks))?\s+"
    r"(?:(?:are|go|should\s+be|must\s+be|end\s+up|sit|stand)\s+)?(?:(?P<prep>at|in|on|near|towards?|along)\s+the\s+(?:far\s+|very\s+)?"
    r"(?P<side>front|back|rear|left|right|center|centre|middle)(?:\s+(?P<side2>left|right))?(?:\s+corner)?\b"
    rf"|(?P<rel>next\s+to|beside|behind|in\s+front\s+of|(?:to\s+the\s+)?left\s+of|(?:to\s+the\s+)?right\s+of|far\s+from|near)\s+(?:the\s+)?"
    rf"(?P<c>{COLOR_RE})\b)")
"""A place or a relation said of a group after the cubes it is of ("..., both at the back", "..., all in the center",
"..., both next to blue"; "both" is "2" once numbers are normalized): :func:`_group_place`."""


def _group_place(f: Features, schema: TaskSchema, cubes: list, walk: list) -> ParseError | None:
    """A place or relation said of "both" or "all" of the cubes before it must hold of that many cubes: "put red on the
    left and blue on the right, both at the back" had put blue alone at the back, "put red between blue and green, all at
    the back" green alone, silently.  Counted: the cubes the goal puts in that part of the table (or relates so to that
    cube); "both" needs two, "all" as many cubes as the sentence names before it."""
    for m in _GROUP_SAID_RE.finditer(f.text):
        sentence = re.split(r"[.;!?]", f.text[:m.start()])[-1]
        named = len(set(re.findall(rf"\b(?:{COLOR_RE})\b", sentence)))
        q = m.group("q")
        if q == "2" and re.search(r"\b(?:two|2)\s+of\s+them\b", f.original, re.IGNORECASE):
            return _unread(f, schema, m.group(0).strip(" ,"), "picks two of the cubes said before without saying which; "
                           "name them (e.g. \"the red and blue cubes at the back\"), or use --model")
        if q == "2" and not re.search(r"\bboth\b", f.original, re.IGNORECASE):
            continue  # "three on the bottom, two in the middle": a count of a layer, not the cubes said before
        need = 2 if q == "2" else int(re.search(r"\d", q).group(0)) if re.search(r"\d", q) else max(named, 2)
        if m.group("rel"):
            colour = canon_color(m.group("c"))
            anchor = {x.name for x in cubes if x.color == colour}
            held = {n for p in walk if p.name in PAIRWISE_RELATIONS and set(p.object_names()) & anchor
                    for n in p.object_names() if n not in anchor}
        else:
            side = {"centre": "center", "middle": "center", "rear": "back"}.get(m.group("side"), m.group("side"))
            region = f"{side}_{m.group('side2')}" if m.group("side2") else side
            names = {x.name for x in cubes}
            held = {p.a for p in walk if isinstance(p, P.InRegion) and p.a in names and (p.region == region or region in p.region.split("_"))}
            held |= {n for p in walk if isinstance(p, P.InRegion) and p.a not in names
                     and (p.region == region or region in p.region.split("_")) for st in walk
                     if isinstance(st, (P.Stack, P.UnorderedStack, P.InLine)) and p.a in st.object_names()
                     for n in st.object_names()}
        if len(held) < need:
            return _unread(f, schema, m.group(0).strip(" ,"), f"says it of {need} cubes and the task read holds it of "
                           f"{len(held)}. Say it of each cube by name (e.g. \"... and the red and blue cubes at the back\"), or use --model")
    return None


WORD_CHECKS = (_follow_up_relation, _unread_reversal, _counted_others, _label_end, _moved_pronoun, _piles_said,
               _scene_count, _line_roles, _left_over_alternative, _idle_sentence, _raised_on_table, _undone_kept,
               _ordered_line_roles, _unnamed_merged, _some_of_them, _others_colour, _with_relation, _group_place,
               _another_said, _between_held, _listed_once, _rank_held,
               _spelled_word_read)
"""Checks that words of the instruction a reading leaves unread do not change what it asks, in order: each takes
(features, schema, its cubes, its goal's predicates) and returns the ParseError to raise, or None
(:func:`unaccounted` runs them; a new check is one function added here)."""


def unaccounted(f: Features, schema: TaskSchema) -> ParseError | None:
    """The first word or mention of the instruction that ``schema`` has no place for, as the
    ParseError to raise; None when every label, colour, count, patch, place and relation is in it."""
    labels = "".join(a.label or "" for a in schema.assets)
    compass = {m.group(1) for m in COMPASS_CORNER_RE.finditer(f.original.lower())}
    caps = [w for w in re.findall(r"\b[A-Z]{2,}\b(?!\s*(?:\([^)]*\))?\s*:)", f.original)  # not a label: "NOTE:", "TODO(x):"
            if w.lower() not in VOCAB and w.lower() not in COLORS and not set(w) <= set(labels)
            and w.lower() not in compass and w.lower() not in CAPS_JARGON]
    if caps:
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but {caps[0]!r} has no place in "
                          "that task. Rephrase (e.g. \"spell the word ...\"), or use --model")
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    have = Counter(a.color for a in cubes)
    ordered = {n for p in schema.goal_predicate().walk() for kind, c in p.constraints() if kind == "order"
               for pair in c.get("pairs", ()) for n in pair}
    for m in END_ROLE_SAID_RE.finditer(f.text):  # "a row of red, blue and green that ends with red": which end is red?
        if not {a.name for a in cubes if a.color == canon_color(m.group("c"))} & ordered:
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group(0)}' gives a cube a "
                              "place at one end and that task orders none of it (say the whole order, e.g. \"from left to "
                              "right: blue, green, red\"), or use --model")
    dropped = _pair_relation_dropped(f, schema, cubes)
    if dropped is not None:
        return dropped
    walk = list(schema.goal_predicate().walk())
    for btw in (p for p in walk if isinstance(p, P.Between)):
        if any({btw.b, btw.c} <= set(st.objects) for st in walk if isinstance(st, (P.Stack, P.UnorderedStack))):
            # "build a tower with green between red and blue": red had gone on blue, green beside them (a row's between)
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{btw.a} between {btw.b} and {btw.c}' "
                              f"cannot hold with {btw.b} and {btw.c} stacked on each other; say the tower from bottom to top "
                              "(e.g. \"from bottom to top: red, green, blue\"), or use --model")
    stacks = [p.objects for p in schema.goal_predicate().walk() if type(p) is P.Stack]
    loose = [p for p in schema.goal_predicate().walk() if isinstance(p, P.Stack) and type(p) is not P.Stack]
    for m in TOWER_END_SAID_RE.finditer(f.text):  # "stack yellow on pink, with the pink cube on top": which is on top?
        colour = canon_color(m.group("c") or m.group("c2") or m.group("c3"))
        named = {a.name for a in cubes if a.color == colour}
        end = -1 if m.group("top") or m.group("top2") or m.group("top3") else 0
        held = [st for st in stacks if named & set(st)]
        unanchored = [p for p in loose if named & set(p.objects) and not (
            getattr(p, "top" if end else "bottom", False) and p.objects[end] in named)]
        if unanchored and not held:  # "a tower of three cubes. The green cube must be the bottom one": the end had been dropped
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group(0)}' puts the {colour} cube "
                              f"at the {'top' if end else 'bottom'} and that task leaves its place in the tower free. Say it as "
                              f"'with the {colour} cube at the {'top' if end else 'bottom'}', or use --model")
        if held and not any(st[end] in named for st in held):
            return ParseError(f"\"{f.original[:80]}\" contradicts itself: '{m.group(0)}' puts the {colour} "
                              f"cube at the {'top' if end else 'bottom'}, and the rest of it reads {schema.goal_summary}. "
                              "Say the order once (e.g. \"from bottom to top: ...\"), or use --model")
    material = MATERIAL_SAID_RE.search(f.text)  # "put 2 letter cubes on the red patch"
    if material and not labels:  # "put 2 letter cubes on the red patch" read as two coloured cubes
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{material.group(0)}' names "
                          "labelled cubes and that task has none. Rephrase (e.g. \"the letter cubes A and B\"), or use --model")
    single = [m.group(1) for m in LONE_LETTER_RE.finditer(f.original) if m.group(1) not in labels]
    if single:  # "put the red block on the C": a letter cube the reading dropped
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but the letter {single[0]!r} has no "
                          "place in that task. Rephrase (e.g. \"the letter C block\"), or use --model")
    named_labels = {m.upper() for m in re.findall(r"\b(?:letter|number|digit)\s+'?([A-Za-z0-9])'?(?![A-Za-z0-9'])",
                                                  f.original, re.IGNORECASE)}
    marked = {m.group("l").upper() for pattern in lexicon.LABEL_CUBE_SAID_RES for m in pattern.finditer(f.original)}  # "the block
    # marked 5", "the 9 block", "block 5": each must have a place (which labels others name is the named ones' to say)
    if f.has("letter", "letters", "number", "numbers", "digit", "digits"):
        named_labels |= set(explicit_labels(f))  # "the numbers 1 to 3 in a row, then ..."
    if named_labels:  # a label said with its layer only where others are named as well ("A and B at the bottom, C on top")
        named_labels |= {lab for pattern in lexicon.LABEL_LAYER_ROLE_RES for m in pattern.finditer(f.original)
                         for lab in re.findall(lexicon.LABEL_TOKEN, m.group("l"))}  # "A and B at the bottom, C on top"
    if (named_labels | marked) - set(labels):
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but the cube labelled "
                          f"{sorted((named_labels | marked) - set(labels))[0]!r} has no place in that task. Rephrase, or use --model")
    spelled = set("".join(re.findall(r"\b[A-Z]{2,}\b|(?<=')[A-Za-z0-9]{2,}(?=')", f.original)).upper())
    sizes = {len(cubes)} | {n for n in have.values() if n > 1} | {
        n for p in schema.goal_predicate().walk() for n in p.counts()} | {len(st) for st in schema.initial_state.structures}
    lone = [m.group(1) for m in LONE_DIGIT_RE.finditer(f.original) if m.group(1) not in labels and int(m.group(1)) not in sizes]
    lone += [m.group("l") for m in LABEL_ROLE_RE.finditer(f.original)  # "9 at the bottom": a digit given a place, no cube
             if m.group("l") and m.group("l").isdigit() and m.group("l") not in labels and int(m.group("l")) not in sizes]
    # "Three orange cubes in a line, four actually.", ", make it five": a count said again after a comma, which no
    # mention holds (it had been dropped)
    lone += [m.group(1) for m in _AFTERTHOUGHT_COUNT_RE.finditer(f.text) if m.group(1) not in labels and int(m.group(1)) not in sizes]
    if lone:  # "line 1 2 3" read as a line of four coloured cubes: a digit no cube and no count of the task carries
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but the number {lone[0]!r} is neither a "
                          "digit cube nor a count of that task. Rephrase (e.g. \"the digit cubes 1, 2 and 3\", \"3 cubes\"), "
                          "or use --model")
    # "2 on 1, 3 on 2 (digit cubes)": labels the reading named ("the digit 2 block", :func:`labels_in_relations`)
    read_as_cubes = {m.upper() for m in re.findall(r"\b(?:letter|digit)\s+([a-z0-9])\s+(?:block|cube)\b", f.text)}
    invented = sorted(set(labels) - named_labels - spelled - read_as_cubes) if named_labels else []
    if invented:  # "the letter cubes A, B, C and D in a circle" read as a circle of six, A to F
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but no word names the cube labelled "
                          f"{invented[0]!r}. Rephrase (say how many cubes), or use --model")
    for m in INVENTORY_RE.finditer(f.text):  # "Ingredients: 2 cubes. Method: build a tower three cubes tall."
        for n, color in re.findall(rf"(\d+)\s+(?:({COLOR_RE})\s+)?(?:cubes?|blocks?)", m.group("groups")):
            has = have[canon_color(color)] if color else len(cubes)
            if int(n) != has:
                return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group('groups')}' says the "
                                  f"task has {n} {color + ' ' if color else ''}cubes and that task has {has}. Rephrase, or use --model")
    start = lexicon.START_SAID_RE.search(f.text)
    if start and not schema.initial_state.structures:
        # "the robot starts with red on blue and must put red on the green patch": the start had been read as the goal
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{start.group(0)}' describes how the "
                          "cubes start and that task reads no start. Say it as 'Start: red on blue. Goal: ...', or use --model")
    ways = {(m.group("a"), m.group("b")) for m in DIRECTION_RE.finditer(f.text) if m.group("a") != m.group("b")}
    directed = [p for p in schema.goal_predicate().walk() if isinstance(p, P.InLine) and getattr(p, "order", None)]
    if any((b, a) in ways for a, b in ways) and len(directed) < 2:
        # "a row ... from left to right, but build it from right to left": which way the row reads is said twice
        return ParseError(f"\"{f.original[:80]}\" says two opposite directions ({', '.join(sorted(f'{a} to {b}' for a, b in ways))}) "
                          "for one arrangement; say the order once, or use --model")
    stacked = _stacked_on_another(schema)
    for m in ON_TABLE_RE.finditer(f.text):  # "move the green cube onto the table": not stacked on another
        color = canon_color(m.group(1) or m.group(2) or m.group(3))
        named = [a.name for a in cubes if a.color == color]
        if named and all(n in stacked for n in named):
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{m.group(0)}' puts the "
                              f"{color} cube on the table and that task stacks it on another. Rephrase, or use --model")
    rel = r"(?:on(?:\s+top\s+of)?|onto|under|behind|(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|next\s+to|beside|near|far\s+from|above|below)"
    for run in COLOR_LIST_RE.finditer(f.text):  # "white, white, then black, black": each colour said is one cube
        if re.match(rf"\s+{rel}\s+(?:the\s+)?(?:{COLOR_RE})\b", f.text[run.end():]) or re.search(rf"\b{rel}\s+(?:the\s+)?$",
                                                                                                    f.text[:run.start()]):
            continue  # "blue on red, red on yellow": the pairs of a chain of relations
        listed = Counter(canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", run.group(0)))
        short = sorted(c for c, n in listed.items() if have[c] < n)
        if short:
            return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but '{run.group(0)}' lists "
                              f"{listed[short[0]]} {short[0]} cubes and that task has {have[short[0]]}. Rephrase, or use --model")
    said = Counter(canon_color(m.group(1)) for m in re.finditer(rf"\b(?:a|an|another)\s+({COLOR_RE})\s+(?:block|cube|brick|box)\b", f.text))
    short = sorted(c for c, n in said.items() if have[c] < n)
    if short:  # "place a pink cube ..., then a pink cube on the cyan one": each "a pink cube" is one more
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but it says 'a {short[0]} "
                          f"block' {said[short[0]]} times and that task has {have[short[0]]}. Rephrase, or use --model")
    walk = list(schema.goal_predicate().walk())
    for check in WORD_CHECKS:
        gap = check(f, schema, cubes, walk)
        if gap is not None:
            return gap
    try:
        account_named(f.text, schema)
    except UnaccountedMention as exc:
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but {exc}. "
                          "Rephrase (one sentence per structure helps), or use --model")
    used = {n for p in schema.goal_predicate().walk() for n in _objects_of(p)} | {
        n for st in schema.initial_state.structures for n in st}
    stray = sorted(a.name for a in schema.assets if a.kind != "goal_patch" and a.name not in used)
    if stray:  # a cube no part of G or rho_0's structures names: the reading made it up
        return ParseError(f"read \"{f.original[:80]}\" as: {schema.goal_summary}; but the task has a cube ({stray[0]}) "
                          "that no part of its goal names. Rephrase, or use --model")
    return None
