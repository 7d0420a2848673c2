"""An initial scene stated with the goal: "Initially the red cube is on the blue cube. Put the
red cube on the green patch.", "Start: a tower of red, green, blue. Goal: reverse it into
blue, green, red.", "The pink cube starts stacked on the grey cube and must end up on the table."

A task is T = (assets, rho_0, G, instruction, paraphrases) (paper Sec. 3): the words that state
how the cubes start become rho_0's stacks (``initial_state.structures``, bottom to top); the rest
is the goal, read by the whole front end (:func:`rpg.schema.readers.parse`), so nothing either
part says is dropped or merged.  The start is read only when every one of its facts is one of
the forms below (a stack, a tower listed with its direction, a cube on the table, the rest
scattered); otherwise the instruction is read as it was written (and refused for its
starting-state words).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from rpg.domain.layouts import stack_layout
from rpg.domain.predicates import OnTable, Stack
from rpg.errors import BadInput
from rpg.schema import lexicon
from rpg.schema.builder import Builder
from rpg.schema.lexicon import COLOR_RE, MARKUP_RES, NUMBER_WORDS
from rpg.schema.model import TaskSchema
from rpg.schema.reading import Inexpressible, ParseError, canon_color, task_slug

_NAME = rf"(?:{COLOR_RE}|(?-i:[A-Z])(?![\w'])|\d(?!\w))"
"""A cube's name in a start: a colour, or a letter or digit cube's label ("block A", "the 3 cube")."""
_CUBE = rf"(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?:block\s+|cube\s+)?(?P<{{g}}>{_NAME})(?:\s+(?:cube|block|one))?"

START_SENTENCE_RE = re.compile(
    r"(?i)^\s*(?:initially|at\s+(?:the\s+)?(?:start|beginning)(?:\s+of\s+the\s+(?:episode|task))?"
    r"|in\s+the\s+(?:initial|starting|start)\s+(?:state|scene|configuration|setup)"
    r"|(?:the\s+)?(?:initial|start(?:ing)?)\s+(?:state|scene|configuration|setup|position)s?\s*(?:is\b|:|-|\u2014)"
    r"|the\s+(?:start|beginning)\s+is\b"
    r"|(?:scene\s+)?init(?:ial)?(?:\s+(?:state|scene|config(?:uration)?))?\s*:"
    r"|(?:setup|start|before|init)\s*:|(?:the\s+)?(?:scene|episode|table|task)\s+(?:starts|begins)\s+(?:with|as)"
    r"|(?:it|the\s+(?:tower|stack|column))\s+(?:starts|begins)\s+(?:out\s+)?as\b"
    r"|(?:it\s+)?(?:starts|begins)\s+(?:out\s+)?with(?=\s+(?:the|a|an|one)\s)|(?:start|begin)\s+(?:out\s+)?with(?=\s+(?:a|an|one|the)\s)"
    r"|there(?:'s|s|\s+is)\s+(?=(?:an?|one)\s+(?:stack|tower|column)\s+(?:of|with)\b)|we\s+start\s+(?:with|from)|(?:the\s+)?(?:(?:letter|digit|number|colou?red)\s+)?(?:cubes|blocks)\s+start(?:\s+out)?(?:\s+as|\s+in|\s*:)?)"
    r"\s*[:,\-\u2014]?\s*")
"""Words that open a statement of the initial scene ("Initially, ...", "At the start, ...",
"Initial state: ...", "Setup: ...", "The scene starts with ...")."""

STARTS_CLAUSE_RE = re.compile(
    rf"(?i)^\s*(?P<fact>{_CUBE.format(g='top')}\s+(?:starts|begins|is\s+initially|starts\s+out|sits\s+initially)\s+"
    rf"(?:stacked\s+|sitting\s+|resting\s+)?(?:on\s+top\s+of|on|atop)\s+{_CUBE.format(g='bottom')})"
    r"\s*(?:,\s*(?:and\s+)?|\s+and\s+|[.;]\s*)(?:then\s+)?(?P<rest>.+)$")
"""A cube said to start on another, then what it must do ("The pink cube starts stacked on the grey
cube and must end up on the table"): the subject is carried into the goal's clause."""

ROBOT_STARTS_RE = re.compile(
    rf"(?i)^\s*(?:the\s+)?(?:robot|arm|agent|policy|episode|scene|task)\s+(?:starts|begins)\s+with\s+(?P<fact>(?:the\s+)?(?:{COLOR_RE})"
    rf"(?:\s+(?:cube|block))?\s+(?:on\s+top\s+of|on|atop)\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)\s*,?\s+(?:and\s+|but\s+)?"
    r"(?:(?:it\s+)?(?:has\s+to|must|should|needs\s+to|is\s+to|is\s+asked\s+to)\s+)(?P<goal>.+)$")
"""A start said as what the robot starts with ("The robot starts with the white cube on the black
cube and has to move the white cube onto the pink patch"): read as "Initially ... . <goal>"."""

FROM_START_RE = re.compile(
    rf"(?i)^\s*(?:(?:from|starting\s+(?:from|with)|beginning\s+(?:from|with))\s+(?:a|the)\s+(?:start|scene|setup|state|configuration)"
    rf"\s+(?:where|in\s+which|with)|given\s+(?:a|the)\s+(?:stack|tower)\s+(?:of|with))\s+(?P<fact>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:(?:sits|is|rests|lies|stands)\s+)?"
    rf"(?:stacked\s+)?(?:on\s+top\s+of|on|atop)\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)\s*[,;]\s*(?:then\s+)?(?P<goal>.+)$")
"""A start said as the scene a goal starts from ("From a start where blue sits on yellow, move the
blue cube onto the red patch"): read as "Initially ... . <goal>" (its tower had been read as the goal)."""

_CHAIN_SAID = rf"(?:the\s+|an?\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:(?:\s+(?:stacked\s+|sitting\s+|resting\s+)?(?:on\s+top\s+of|on|atop)\s+|-on-)(?:the\s+|an?\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)+"
_LISTED_CUBE = rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?"
_LIST_SAID = rf"{_LISTED_CUBE}(?:\s*,\s*(?:and\s+)?{_LISTED_CUBE}|\s+and\s+{_LISTED_CUBE})+"
FROM_STRUCTURE_RE = re.compile(
    rf"(?i)^\s*(?:(?:(?:starting|beginning|start|begin)(?:\s+out)?\s+)?from|(?:starting|beginning|start|begin)(?:\s+out)?\s+with|given)\s*:?\s+"
    rf"(?:(?:(?:a|the)\s+(?:tower|stack|column)\s+(?:of\s+)?)?"
    rf"(?P<fact>{_CHAIN_SAID})|(?:a|the)\s+(?P<fact3>(?:{COLOR_RE})(?:-on-(?:{COLOR_RE}))+)\s+(?:tower|stack|column)"
    rf"|(?P<fact4>(?:a|the)\s+(?:tower|stack|column)\s+of\s+{_LIST_SAID}\s*\(\s*(?:from\s+)?(?:the\s+)?(?:bottom|top)\s+(?:to|up\s+to|down\s+to)"
    r"\s+(?:the\s+)?(?:top|bottom)\s*\)))"
    rf"(?:\s*\((?:the\s+)?(?P<end_c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+(?:the\s+)?(?P<end>bottom|top)\))?\s*(?:[,;:.]|\s+and(?=\s+(?:then\s+)?(?:put|place|move|set|take|stack|unstack|build|make|lay|bring|slide"
    rf"|push|lift|get)\b))\s*(?:then\s+)?(?!\s*(?:and\s+)?(?:with\s+)?(?:the\s+|an?\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:on|atop|under|on\s+top\s+of)\s)(?P<goal>.+)$"
    rf"|^\s*with\s+(?P<fact2>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:stacked|sitting|resting|starting)\s+(?:on\s+top\s+of|on|atop)"
    rf"\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)\s*[,;]\s*(?:then\s+)?(?P<goal2>(?:put|place|move|set|take|bring|stack|unstack|slide"
    r"|push|lift|lay|arrange|line)\b.+)$")
"""A start said as the structure or the state a goal starts from ("from the tower of pink on cyan, put pink next to
the white block", "starting with red on blue, ...", "from a stack of brown, gray, red (bottom to top), ...", "with the
red cube stacked on the blue cube, move ..."): read as
"Initially ... . <goal>" (its tower had been read as part of the goal: silently wrong)."""


START_CLAIM_RE = re.compile(
    rf"(?i)(?:^|[.;!?]\s+)\s*(?:(?:starting|beginning|start|begin)(?:\s+out)?\s+(?:from|with)|given)\s*:?\s+(?:(?:a|an|the|two|three|four|\d+)\s+(?:[\w-]+\s+)?(?:stacks?|towers?|columns?|rows?|lines?|piles?)\b"
    rf"|(?:the\s+|an?\s+)?(?:(?:cube|block|letter|digit|number)\s+)?(?:{COLOR_RE}|(?-i:[A-Z])|\d)(?:\s+(?:cube|block))?\s+(?:stacked\s+|sitting\s+|resting\s+|is\s+)?"
    rf"(?:on\s+top\s+of|on|onto|atop|over|under(?:neath)?|beneath|below|next\s+to|beside|(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|behind|between|in\s+the)\s+"
    rf"|(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+\s+(?:in\s+a\s+(?:row|line|stack|tower|pile)|stacked|lined))")
"""A sentence opened by the scene the goal starts from ("Starting from a stack of red on blue, ...", "starting with
orange stacked on brown"): when :func:`split` reads no start from the text, the parser refuses it (its tower or row had
been read as the goal: silently wrong)."""

UNSTACK_SAID_RE = re.compile(
    rf"(?i)^\s*(?:please\s+)?(?:unstack|dismantle|disassemble|take\s+apart)\s+(?:everything|it\s+all|all\s+of\s+it|the\s+(?:tower|stack))"
    rf"\s*[:,\-\u2014]\s*(?:the\s+(?:tower|stack)\s+is|it\s+is|it's)\s+(?:(?P<fact>{_CHAIN_SAID})|(?P<list>{_LIST_SAID})\s*,?\s*\(?(?P<dir>(?:from\s+)?"
    rf"(?:the\s+)?(?:top|bottom)\s+(?:to|up\s+to|down\s+to)\s+(?:the\s+)?(?:top|bottom)|from\s+(?:the\s+)?(?:top|bottom)\s+(?:up|down))\)?)"
    rf"\s*(?:[.;,]\s*(?:and\s+)?(?P<goal>.+?))?\s*[.!]?$")
"""The undoing said first, the tower it undoes after ("unstack everything: the tower is pink on top of yellow on top of
green, and all of them should end up on the table"): read as "Initially <tower>. <goal>", every cube on the table when
no goal follows (the start's tower had been read as the goal: silently wrong); another goal besides is refused by
:func:`split` (where the undone cubes end is not said)."""


TAKE_FROM_LISTED_RE = re.compile(
    rf"(?i)^\s*(?P<verb>take|remove|lift)\s+the\s+top\s+(?:cube|block|one)\s+(?:off|from)\s+(?:of\s+)?the\s+"
    rf"(?:(?P<s>stack|tower)\s+of\s+(?P<list>{_LIST_SAID})|(?P<hy>(?:{COLOR_RE})(?:-(?:{COLOR_RE}))+)\s+(?P<s2>stack|tower))"
    rf"\s*(?:\(\s*(?:(?P<end_c>{COLOR_RE})\s+(?:is\s+)?(?:at|on)\s+the\s+(?P<end>bottom|top)|(?P<dir>(?:from\s+)?(?:the\s+)?(?:bottom|top)\s+"
    rf"(?:up|down|to\s+(?:the\s+)?(?:top|bottom))))\s*\))(?P<rest>\s*,?\s*(?:and\s+)?(?:then\s+)?(?:put|set|place|lay|leave)\s+it\b.*)$"
    rf"|^\s*(?P<verb2>take|remove|lift)\s+the\s+top\s+(?:cube|block|one)\s+(?:off|from)\s+(?:of\s+)?the\s+"
    rf"(?:(?:stack|tower)\s+of\s+(?P<chain>{_CHAIN_SAID})|(?P<chain2>{_CHAIN_SAID})\s+(?:stack|tower))"
    rf"(?P<rest2>\s*,?\s*(?:and\s+)?(?:then\s+)?(?:put|set|place|lay|leave)\s+it\b.*)$")
"""A cube taken off a stack that the same sentence lists with its order ("take the top cube off the stack of white, gray,
brown (white at the bottom) and put it on the table"): read as "Initially a stack of ... . Take the top cube off and put
it ..." (a list without its order leaves the top cube unsaid: not read here)."""


def _take_from_listed(m: re.Match) -> str:
    if m.group("verb2"):  # "the tower of purple on orange", "the purple on orange tower": the chain says the order
        return f"Initially {m.group('chain') or m.group('chain2')}. {m.group('verb2')} the top cube off{m.group('rest2')}"
    order = f" {m.group('dir')}" if m.group("dir") else f", with {m.group('end_c')} at the {m.group('end')}" if m.group("end") else ""
    listed = m.group("list") or ", ".join(m.group("hy").split("-"))  # "the orange-purple tower (orange at the bottom)"
    return f"Initially a {m.group('s') or m.group('s2')} of {listed}{order}. {m.group('verb')} the top cube off{m.group('rest')}"


def _unstack_said(m: re.Match) -> str:
    fact = m.group("fact") or f"a tower of {m.group('list')} {m.group('dir')}"  # "pink, yellow, green from top to bottom"
    return f"Initially {fact}. {m.group('goal') or 'put all the cubes on the table.'}"


def _from_structure(m: re.Match) -> str:
    fact = (m.group("fact") or m.group("fact2") or m.group("fact3") or m.group("fact4")).replace("-on-", " on ")
    end = m.group("end")  # "(red at the bottom)": kept in the fact when it is not the chain's end (refused there)
    if end and not re.search(rf"(?i)\b{re.escape(m.group('end_c'))}(?:\s+(?:cube|block))?\s*$" if end == "bottom"
                             else rf"(?i)^\s*(?:the\s+)?{re.escape(m.group('end_c'))}\b", fact):
        fact = f"{fact} ({m.group('end_c')} at the {end})"
    return f"Initially {fact}. {m.group('goal') or m.group('goal2')}"


START_STRUCTURE_RE = re.compile(r"(?i)^\s*(?:the\s+)?(?:initial|starting|start|original)\s+(tower|stack|column)\s*(?:is|:|-|\u2014)\s*"
                                r"(?=(?:the\s+)?(?:" + COLOR_RE + r")\b)")
"""A start said as the structure the episode starts with ("The initial tower is red, blue, green from
the bottom up. The goal is ..."): read as "Initially: a tower of ..." (its tower had been read as
the goal, and the goal's cube lost)."""

_UNDONE = r"(?:(?:it|them)(?:\s+all)?|all\s+of\s+(?:it|them)|everything|the\s+(?:whole\s+|entire\s+)?(?:tower|stack))"
"""What an undoing verb undoes ("unstack it", "take them all apart", "dismantle everything", "unstack the (whole) tower")."""

GOAL_OPENER_RE = re.compile(r"(?i)^\s*(?:(?:the\s+)?(?:goal|target|task|objective)\s*(?:is\s*(?:to\s+)?|:|-|\u2014)"
                            r"|then\s*,?|now\s*,?|your\s+task\s*(?:is\s+to|:)|(?:at|in)\s+the\s+end\s*[,:]?|finally\s*,?"
                            rf"|(?:unstack|dismantle|take\s+apart)\s+{_UNDONE}\s*,?\s*so\s+(?:that\s+)?"
                            rf"|take\s+{_UNDONE}\s+apart\s*,?\s*so\s+(?:that\s+)?"
                            r"|success(?!\s+(?:requires|needs|demands)\b)(?:\s+(?:when|if))?\s*:?)\s*")
"""Words that open the goal after the start ("Goal: ...", "Then ...", "The task is to ...")."""

_REL_ON = r"(?:(?:is|sits|lies|rests|stands|starts|begins)\s+(?:initially\s+|out\s+)?)?(?:stacked\s+|placed\s+|sitting\s+|resting\s+)?(?:on\s+top\s+of|on|atop|upon)"
_REL_UNDER = r"(?:is\s+)?(?:under(?:neath)?|below|beneath)"
_TOWER_RE = re.compile(
    rf"(?i)^(?:an?\s+|one\s+)?(?:stack|tower|column)\s+(?:of\s+)?(?P<list>(?:(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?"
    rf"(?:\s*,\s*(?:and\s+)?(?!with\b)|\s+and\s+|\s+then\s+|\s*$|(?=\s*\(|\s+(?:from|bottom|top)|\s*,?\s*with\b)))+)"
    r"\s*\(?\s*(?:from\s+)?(?:the\s+)?(?P<from>bottom|top)?(?:\s+(?:to|up\s+to|down\s+to)\s+(?:the\s+)?(?:top|bottom)|\s+up|\s+down"
    r"|\s+first)?\s*\)?"
    rf"(?:\s*,?\s*with\s+(?:the\s+)?(?P<end_c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+(?:the\s+)?(?P<end>bottom|base|top))?$")
_CHAIN_RE = re.compile(rf"(?i)^{_CUBE.format(g='a')}(?P<links>(?:\s+(?:{_REL_ON}|{_REL_UNDER})\s+(?:the\s+)?(?:(?:letter|digit|number)\s+)?"
                       rf"(?:block\s+|cube\s+)?{_NAME}(?:\s+(?:cube|block|one))?)+)$")
_IDLE_FACT_RE = re.compile(
    rf"(?i)^(?:(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?:block\s+|cube\s+)?(?:{_NAME})(?:\s+(?:cube|block))?|(?:all\s+)?(?:the\s+)?(?:other|remaining)\s+(?:cubes|blocks)"
    r"|the\s+(?:rest|others)|everything(?:\s+else)?|(?:all\s+)?(?:the\s+)?(?:cubes|blocks)|the\s+(?:gripper|hand)(?:\s+is\s+empty)?)"
    r"(?:\s+(?:is|are|lie|lies|sit|sits|starts|start))?(?:\s+(?:on\s+the\s+table|scattered(?:\s+(?:around|randomly|on\s+the\s+table))?"
    r"|loose|apart|separate|elsewhere|(?:lying\s+)?around|at\s+random|randomly\s+placed|empty|open))?$"
    r"|^(?:the\s+)?(?:hand|gripper|arm)\s+(?:is\s+)?empty$|^(?:arm|hand)-?empty$"
    rf"|^(?:the\s+)?(?:block\s+|cube\s+)?(?:{_NAME})(?:\s+(?:cube|block))?\s+is\s+clear$|^clear\s+(?:the\s+)?(?:block\s+)?(?:{_NAME})$")
"""A fact that starts no stack: a cube on the table, the rest scattered, the gripper empty, a
cube with nothing on it ("A is clear", checked against the stacks said)."""


ON_TABLE_GOAL_RE = re.compile(
    rf"(?i)^\s*(?:success\s+(?:requires|needs|means)\s+)?"
    rf"(?:(?:put|place|move|set|lay|take|bring|get|lower|return)\s+)?{_CUBE.format(g='c')}\s+(?:(?:must|should|has\s+to|"
    r"needs\s+to|will|to)\s+)?(?:(?:be|end\s+up|ends\s+up|finish(?:es)?|stay|stays|go|goes|sit|sits|sitting|lie|lies|lying|rest|rests"
    r"|resting|standing|placed|is|back|down"
    rf"|(?:off|from)\s+(?:of\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?(?:\s+and)?)\s+)*(?:on|onto|to)\s+the\s+table\s*[.!]?$")
"""A goal that only sends a cube to the table ("the pink cube must end up on the table", "put
red on the table"): read here, where the start stacks that cube (alone it asks nothing)."""

_LISTED = rf"(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?:block\s+|cube\s+)?{_NAME}(?:\s+(?:cube|block|one))?"
ON_TABLE_LIST_GOAL_RE = re.compile(
    rf"(?i)^\s*(?:(?:put|place|move|set|lay|take|bring|get|lower|return)\s+)?(?:both\s+)?(?P<list>{_LISTED}(?:\s*,\s*{_LISTED})*"
    rf"\s*,?\s+(?:and|&)\s+{_LISTED})(?:\s+(?:cubes|blocks|ones))?\s+(?:(?:must|should|have\s+to|need\s+to|will)\s+)?"
    r"(?:(?:be|end\s+up|finish|stay|go|sit|lie|rest|placed|are|back|down|both|all)\s+)*(?:on|onto|to)\s+the\s+table\s*[.!]?$")
"""A goal that sends several cubes the start stacks to the table, listed ("put the yellow and the cyan blocks down on the
table", "red and blue must end up on the table"): each listed cube on the table."""

_TOWER_IN_RE = re.compile(
    rf"(?i)(?:\ban?\s+|\bone\s+)?\b(?:stack|tower|column)\s+(?:of\s+)?(?:(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?"
    rf"(?:\s*,\s*(?:and\s+)?|\s+and\s+|\s+then\s+)){{1,}}(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?"
    r"(?:\s*\(?\s*(?:from\s+)?(?:the\s+)?(?:bottom|top)(?:\s+(?:to|up\s+to|down\s+to)\s+(?:the\s+)?(?:top|bottom)|\s+up"
    r"|\s+down|\s+first)?\s*\)?)?"
    rf"(?:\s*,?\s*with\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+(?:the\s+)?(?:bottom|base|top)\b)?")
"""A tower listed inside a statement of the start ("a tower of red, green, blue (bottom to top)"):
read whole before the statement is split into its facts at its commas."""


@dataclass(frozen=True)
class InitialScene:
    """How the cubes start, said with the goal.

    Attributes:
        stacks: each initial stack's colours, bottom to top.
        goal: the rest of the instruction (the goal, read by the whole front end).
        kept: stacks of the start (bottom to top) the goal says to leave as they are ("leave the other two as they
            are"): part of the goal.
    """

    stacks: tuple[tuple[str, ...], ...]
    goal: str
    kept: tuple[tuple[str, ...], ...] = ()


_COUNTED_TOWER_RE = re.compile(
    rf"(?i)\b(?:an?\s+|one\s+)?(?:tower|stack)\s+of\s+(?P<n>\d+|two|three|four|five|six)\s+(?:cubes|blocks)\s*[,:]\s*"
    rf"(?P<first>{COLOR_RE})\s+(?:at|on)\s+the\s+(?P<end>bottom|base|top)\s*,\s*(?:then\s+)?"
    rf"(?P<rest>(?:{COLOR_RE})(?:\s*,\s*(?:then\s+)?(?:and\s+)?(?:{COLOR_RE})|\s+(?:and|then)\s+(?:{COLOR_RE}))*)")
"""A start's tower counted, then listed from one end ("a tower of four cubes, white at the bottom,
then gray, black, brown"): read as the tower of those colours from that end, when the count holds."""


def _counted_tower(m: re.Match) -> str:
    colors = [m.group("first")] + re.findall(rf"(?i)\b(?:{COLOR_RE})\b", m.group("rest"))
    n = NUMBER_WORDS.get(m.group("n").lower(), None) or int(m.group("n"))
    if n != len(colors):
        return m.group(0)  # the count does not hold: left as written (and refused)
    return f"a tower of {', '.join(colors)} from the {'top' if m.group('end') == 'top' else 'bottom'} up"


_CHAIN_WITH_TOP_RE = re.compile(
    rf"(?i)\b(?P<a>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:(?:is|sits|rests|stands|lies)\s+)?(?:stacked\s+)?(?:on\s+top\s+of|on|atop|upon)\s+"
    rf"(?:the\s+|an?\s+)?(?P<b>{COLOR_RE})(?:\s+(?:cube|block))?\s+with\s+(?:the\s+|an?\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block))?\s+"
    r"on\s+top\b(?!\s+of\b)")
"""A start's chain with a cube on its top ("red is on blue with green on top"): green on red, the chain's top (the cube
with another "on top" had been taken for blue, the chain's bottom: blue, green, red)."""

_WITH_ON_TOP_RE = re.compile(rf"(?i)(?<!\bon\s)(?<!\bon\sthe\s)(?<!\bon\sa\s)(?<!\batop\s)(?<!\bof\s)(?<!\bof\sthe\s)\b(?:an?\s+|the\s+)?(?P<bottom>{COLOR_RE})(?:\s+(?:cube|block))?\s+with\s+(?:the\s+|an?\s+)?"
                             rf"(?P<top>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:on\s+top(?:\s+of\s+it)?|on\s+it)\b")
"""A start's stack said as a cube with another on top ("blue cube with the white cube on top of it")."""

_ROLE_FACT_RE = re.compile(rf"(?i)(?:^|(?<=[,;]))\s*(?:and\s+)?(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+)?"
                           r"(?:at|on)\s+(?:the\s+)?(?P<end>bottom|base|top)\s*(?=[,;.]|$)")
"""A start's fact that says again which cube is a stack's end ("..., gray at the bottom"): checked
against the stacks said, not a stack of its own."""


_WHICH_ON_RE = re.compile(r"(?i)\s*,?\s*(?:which|that)\s+(?:in\s+turn\s+)?(?:is|sits|rests|stands|lies)\s+(?:itself\s+)?(?:stacked\s+)?"
                          r"(?=(?:on\s+top\s+of|on|atop|upon)\s)")
"""A start's chain said with a relative clause ("the white cube sits on the black cube, which sits on the gray cube"):
its link, read as one chain with the clause before it."""


def _facts(content: str) -> list[tuple[str, ...]] | None:
    """The stacks (bottom to top) a statement of the start says, or None when one of its facts
    is not a form this module reads."""
    stacks: list[tuple[str, ...]] = []
    content = _WHICH_ON_RE.sub(" ", content)  # "white sits on black, which sits on gray": one chain
    content = _COUNTED_TOWER_RE.sub(_counted_tower, content)
    content = _CHAIN_WITH_TOP_RE.sub(r"\g<a> on \g<b> and \g<c> on \g<a>", content)
    content = _WITH_ON_TOP_RE.sub(r"\g<top> on \g<bottom>", content)
    roles = [(m.group("c"), m.group("end")) for m in _ROLE_FACT_RE.finditer(content)]
    content = _ROLE_FACT_RE.sub(" , ", content)
    towers = [m.group(0).strip() for m in _TOWER_IN_RE.finditer(content)]
    content = _TOWER_IN_RE.sub(" , ", content)
    for fact in towers + re.split(r"\s*(?:[,;]\s*(?:and\s+|while\s+)?|\s+and\s+|\s+while\s+)\s*", content.strip(" .:")):
        fact = re.sub(r"(?i)^\s*(?:the|a|one)\s+(?:tower|stack|column)\s+(?:(?:is|was)\s+(?=(?:the\s+)?(?:" + COLOR_RE + r")\b)"
                      r"|of\s+(?=(?:" + COLOR_RE + r")\s+on\b))", "", fact.strip())  # "the tower is red on blue", "a stack of pink on
        # cyan": the chain
        if not fact or _IDLE_FACT_RE.match(fact):
            continue
        tower = _TOWER_RE.match(fact)
        if tower:
            colors = [_canon(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", tower.group("list"), re.I)]
            if len(colors) < 2:
                return None
            if tower.group("end_c"):  # "a tower of blue, green and red with blue at the bottom": the list's end said
                end, at_bottom = _canon(tower.group("end_c").lower()), tower.group("end") != "top"
                if end not in (colors[0], colors[-1]) or tower.group("from"):
                    return None
                colors = colors if (end == colors[0]) == at_bottom else colors[::-1]
            stacks.append(tuple(colors[::-1] if tower.group("from") == "top" else colors))
            continue
        chain = _CHAIN_RE.match(fact)
        if not chain:
            return None
        links = re.findall(rf"(?i)\s+({_REL_ON}|{_REL_UNDER})\s+(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?:block\s+|cube\s+)?"
                           rf"({_NAME})", chain.group("links"))
        under = {bool(re.search(r"(?i)under|below|beneath", rel)) for rel, _ in links}
        if len(under) != 1:
            return None  # "A on B under C": not read
        order = [_canon(chain.group("a"))] + [_canon(c) for _, c in links]
        stacks.append(tuple(order) if under == {True} else tuple(order[::-1]))  # "A under B": A is the bottom
        continue
    merged = _merged(stacks)
    for c, end in roles:  # "black on white on gray, gray at the bottom": said again, checked against the stacks
        if merged is None or not any(t[0 if end in ("bottom", "base") else -1] == _canon(c) and len(t) > 1 for t in merged):
            return None
    clear = [_canon(m.group(1)) for m in re.finditer(rf"(?i)(?:the\s+)?(?:block\s+|cube\s+)?({_NAME})(?:\s+(?:cube|block))?\s+is\s+"
                                                      r"clear\b|\bclear\s+(?:the\s+)?(?:block\s+)?(" + _NAME + r")\b", content)
             if m.group(1)] if merged is not None else []
    if merged is None or any(c in t[:-1] for c in clear for t in merged):
        return None  # "A is clear" of a cube the start stacks something on: a contradiction
    return merged


def _stacks_read(content: str) -> list[tuple[str, ...]] | None:
    """The stacks (bottom to top) a statement of the start says, read by the whole front end as if it were a goal
    ("red cube stacked on a white cube stacked on a black cube", "blue on the bottom, then orange, then white on
    top"), or None unless that reading is only stacks in one order, of cubes each of its own colour or label, and
    accounts for every word (a tower "in any order", a row, a place: no start rpg builds)."""
    # the front end, which calls this module first (imported here, when a start is read)
    from rpg.schema.readers import parse

    content = re.sub(r"(?i)^\s*(?:the|a|one)\s+(tower|stack|column)\s+(?:is|was|has|looks\s+like)\s*:?\s*", r"a \1: ", content)
    try:  # ("the tower is blue on the bottom, ...": the tower the start describes)
        schema = parse(content)
    except BadInput:
        return None
    if schema.initial_state.structures:
        return None  # a start inside the start
    parts = schema.goal_predicate().conjuncts()
    if not parts or any(type(p) is not Stack for p in parts):
        return None
    names = {a.name: (a.label if a.label else a.color) for a in schema.assets}
    stacks = [tuple(names.get(o) for o in p.objects) for p in parts]
    said = [c for st in stacks for c in st]
    return stacks if all(said) and len(said) == len(set(said)) else None


def _canon(name: str) -> str:
    """A colour's palette name, or a label as it is written ("A", "3")."""
    return name if re.fullmatch(r"[A-Z]|\d", name) else canon_color(name.lower())


def _merged(stacks: list[tuple[str, ...]]) -> list[tuple[str, ...]] | None:
    """Stacks said piece by piece ("red on blue, green on red") joined into towers; None when
    a colour would stand in two places (then which cube is which is not said)."""
    towers = [list(s) for s in stacks]
    changed = True
    while changed:
        changed = False
        for a in towers:
            for b in towers:
                if a is not b and a[-1] == b[0]:
                    a.extend(b[1:])
                    towers.remove(b)
                    changed = True
                    break
            if changed:
                break
    colors = [c for t in towers for c in t]
    return [tuple(t) for t in towers] if len(colors) == len(set(colors)) else None


_TAKEN = rf"the\s+(?:{COLOR_RE}|(?-i:[A-Z])|\d)(?:\s+(?:one|cube|block))?"
_TAKE_OFF_RE = re.compile(
    rf"(?i)^\s*(?:then\s+)?(?:(?:take|lift|remove|pick)\s+(?:just\s+|only\s+)?(?:(?P<a>{_TAKEN})\s+off|off\s+(?P<b>{_TAKEN}))"
    rf"|remove\s+(?:just\s+|only\s+)?(?P<c>{_TAKEN})(?!\s+off\b))"
    rf"(?:\s+(?:of\s+)?(?:the\s+)?(?:tower|stack|top|(?P<below>{_TAKEN})))?(?:\s*,?\s*(?:and\s+)?(?:then\s+)?(?:just\s+)?"
    r"(?:set|put|place|lay|leave|drop)\s+it\s+(?:down\s+)?(?:(?P<table>(?:on|onto)\s+the\s+table)"
    r"|(?P<rel>next\s+to|beside|to\s+the\s+(?:left|right)\s+of|in\s+front\s+of|behind)\s+(?P<obj>it\b|" + _TAKEN + r"))"
    r"|(?P<bare>(?=\s*(?:[.!;]|$|,?\s+(?:and\s+)?(?:leave|keep)\s+the\s+(?:rest|others?)\b))))")
"""A cube taken off the start's tower and set on the table or beside a cube ("Take the red one off and set it on the
table", "take off the red cube and put it on the table", "take the orange block off the brown block and set it down next
to it": 'it' the cube it came off), or taken off or removed and set nowhere else ("Take the red cube off.", "Remove just
the top cube and leave the rest as is": on the table): where the cube goes."""


LEAVE_REST_RE = re.compile(
    r"(?i)\s*[;,]?\s*(?:and\s+)?(?:(?:leave|keep)\s+(?:the\s+)?(?:other\s+(?:two|three|four|\d+|ones|cubes|blocks)|rest|others)"
    r"(?:\s+(?:cubes|blocks|of\s+(?:them|the\s+(?:tower|stack))))?|(?:the\s+)?(?:other\s+(?:two|three|four|\d+|ones|cubes|blocks)|rest|others)"
    r"(?:\s+(?:cubes|blocks))?\s+(?:stay|stays|remain|remains)|(?:don't|do\s+not)\s+(?:touch|move)\s+the\s+(?:rest|others"
    r"|other\s+(?:two|three|\d+|ones|cubes|blocks)))(?:\s+(?:as\s+(?:they\s+are|it\s+is|is)|where\s+they\s+are|in\s+place|stacked"
    r"|alone|untouched|standing))?(?=\s*[.!;]?\s*$)")
"""A goal's words that leave the rest of the start's stack as it is ("...; leave the other two as they are", "the rest
stay where they are"): those cubes' stack is part of the goal (:attr:`InitialScene.kept`)."""


UNDO_START_RE = re.compile(rf"(?i)^\s*(?:please\s+)?(?:unstack|dismantle|take\s+apart|disassemble)\s+{_UNDONE}"
                           r"\s*[.!]?\s*$|^\s*take\s+(?:it|the\s+(?:tower|stack))\s+apart\s*[.!]?\s*$")
"""A goal sentence that only undoes the start's stack ("Unstack the tower."): every cube on the table, or, when
another goal sentence follows, what that one says."""


def _taken_off(m: re.Match) -> str:
    cube = m.group("a") or m.group("b") or m.group("c")
    if m.group("table") or m.group("bare") is not None:  # taken off and set nowhere else: on the table, where it can rest
        return f"put {cube} on the table"
    obj = m.group("below") if m.group("obj").lower() == "it" else m.group("obj")
    return f"put {cube} {m.group('rel')} {obj}" if obj else m.group(0)


STARTS_FACT_RE = re.compile(rf"(?i)^\s*{_CUBE.format(g='top')}\s+(?:starts|begins|is\s+initially|starts\s+out|sits\s+initially)\s+"
                            rf"(?:stacked\s+|sitting\s+|resting\s+)?(?:on\s+top\s+of|on|atop)\s+{_CUBE.format(g='bottom')}\s*[.!;]?\s*$")
"""A sentence that only says where a cube starts ("The orange block starts on top of the brown one."), before or after
the goal: a fact of the start."""


_UNSTACK_RE = re.compile(
    rf"(?i)^\s*(?:please\s+)?unstack\s+(?:the\s+)?(?:(?:(?P<an>two|three|four|five|six|[2-6])[\s-](?:block|cube)\s+)?(?:tower|stack)\s+(?:of\s+)?"
    rf"(?P<a>(?:{COLOR_RE})(?:\s+on(?:\s+top\s+of)?\s+(?:{COLOR_RE}))+)"
    rf"|(?P<b>(?:{COLOR_RE})(?:-on-(?:{COLOR_RE}))+)\s+(?:tower|stack)"
    rf"|(?:tower|stack)\s*\(\s*(?P<c>(?:from\s+)?(?:the\s+)?(?:bottom|top)\s+(?:to|up\s+to|down\s+to)\s+(?:the\s+)?(?:top|bottom)\s*:\s*"
    rf"(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+)\s*\)"
    rf"|(?:(?P<dn>two|three|four|five|six|[2-6])[\s-](?:block|cube)\s+)?(?:tower|stack)\s*\(\s*(?P<d>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+\s*,?\s*"
    rf"(?:from\s+)?(?:the\s+)?(?:bottom|top)\s+(?:up|down|to\s+(?:the\s+)?(?:top|bottom)))\s*\))"
    rf"\s*,?\s*(?:so\s+(?:that\s+)?|and\s+(?:then\s+)?)(?P<goal>.+)$")
"""The start said by the verb that undoes it ("Unstack the yellow-on-white tower so both cubes sit on
the table"): the tower named is rho_0's stack, what follows the goal."""


THERE_IS_START_RE = re.compile(
    rf"(?i)^\s*(?:there(?:'s|\s+is)\s+(?:a|an|the)\s+(?:(?:tower|stack)\s+of\s+(?:the\s+|a\s+)?)?(?P<top>{_NAME})(?:\s+(?:cube|block))?\s+"
    r"(?:(?:stacked|sitting|resting|placed)\s+)?"
    rf"|(?:the\s+|an?\s+)?(?P<top2>{_NAME})(?:\s+(?:cube|block))?\s+(?:is\s+(?:currently\s+|now\s+|already\s+)?(?:stacked|sitting|resting|standing"
    r"|lying|placed|set)|is(?=\s+(?:on|atop))|sits|rests|stands|lies)\s+)"
    rf"(?:on\s+top\s+of|on|atop)\s+(?:(?:a|an|the)\s+)?(?P<bottom>{_NAME})(?:\s+(?:cube|block|one))?\s*[.;]\s+"
    r"(?:(?P<verb>(?:then\s+)?(?:put|place|move|take|set|bring|slide|push|lift|remove|unstack))\s+(?P<obj>it\b|the\s+(?P<moved>\w+)"
    r"|(?<=unstack\s)(?:them|both)(?:\s+(?:cubes|blocks))?(?=\s*[.!]?\s*$))"
    rf"|(?=(?:then\s+)?(?:put|place|set|stack|add)\s+(?:a|an|the)\s+{_NAME}\s+(?:cube|block)\s+(?:on\s+top\b(?!\s+of)"
    r"|(?:on\s+top\s+of|onto|on)\s+(?:it\b|the\s+(?:(?P=top)|(?P=top2))(?:\s+(?:cube|block|one))?)\s*[.!]?\s*$)))")
"""A start said as what is there now, one cube on another, before a command that moves the top one ("There is a red cube on
top of the blue cube. Put it on the green patch.", "The red cube is stacked on the blue cube. Take it off ..."): read
as "Initially ..." (the stack had been read as the goal, and "it" as the stack: silently wrong).  Only where the command
moves "it" or the top cube named (moved, the top cube cannot also be the goal's), moves any cube after "there is" (what
is there now), or puts a named cube on top ("A green block sits on a brown block. Put a gray block on top.", "... on top
of the green block", "... on it").  Said after "Currently" or "Right now" (the scene now,
:data:`lexicon.SCENE_NOW_OPENING_RE`) it is the same start; the citations read the goal's words without that opening."""


_ALREADY_START_RE = re.compile(rf"(?i)^\s*(?P<fact>(?:the|a|an)\s+{_NAME}\s+(?:cube|block)\s+(?:is|sits|rests|stands)\s+)already\s+"
                               rf"(?P<rel>(?:stacked\s+)?(?:on\s+top\s+of|on|atop)\s+(?:the|a|an)\s+{_NAME}\s+(?:cube|block))\s*[.;]\s+")
"""A first sentence that says a stack is there "already" ("A cyan cube is already on a pink cube. Add ..."): the start."""

_TOWER_ON_TABLE_START_RE = re.compile(
    rf"(?i)^\s*(?:there(?:'s|\s+is)\s+)?an?\s+(?:tower|stack)\s+of\s+(?:the\s+)?(?P<top>{_NAME})(?:\s+(?:cube|block))?\s+"
    rf"(?:on\s+top\s+of|on)\s+(?:the\s+)?(?P<bottom>{_NAME})(?:\s+(?:cube|block))?\s+(?:stands|is|sits|rests)\s+on\s+the\s+table"
    r"\s*[.;]\s+(?=(?:then\s+)?(?:(?:take|lift|remove|move|pick|get|slide|put|place|set)\s+(?:up\s+)?(?:it|the\s+(?P=top))\b"
    r"|unstack\b))")
"""A first sentence that says a two-cube tower stands on the table before a command that moves its top cube or undoes it
("A tower of red on blue stands on the table. Take the red cube off and ..."): the start (the tower had been read as the
goal and contradicted what follows; before another command, whether the tower stays is unsaid: read as written)."""


_NOW_THEN_UNDONE_RE = re.compile(r"(?i)^\s*(?P<fact>[^.;!?]+)[.;]\s+(?=(?:then\s+|now\s+|please\s+)?(?:unstack|dismantle|disassemble"
                                 r"|take\s+(?:it|them|the\s+(?:whole\s+|entire\s+)?(?:tower|stack))\s+apart|take\s+apart|reverse|flip)\b)")
"""The scene said now, in one sentence, before a command that undoes or reverses it ("Currently the white cube sits on the
black cube, which sits on the gray cube. Unstack the whole tower ..."): a start when every word of that sentence is a
fact of stacks (:func:`_facts`).  Before another command the scene now stays refused (is "red is on blue" kept in the
goal?)."""


_THERE_IS_RE = re.compile(r"(?i)^\s*there(?:'s|\s+is|\s+are|\s+stands)\s+")
"""What says a fact is there now ("there is a tower of ..."), taken off the fact the scene-now reader reads."""


def _there_is_start(m: re.Match) -> str:
    top = m.group("top") or m.group("top2")
    onto_top = m.group("moved") and re.match(rf"(?i)\s+(?:cube|block)\s+(?:on\s+top\s+of|onto|on)\s+(?:it|the\s+{re.escape(top)})"
                                             r"(?:\s+(?:cube|block|one))?\s*[.!]?\s*$", m.string[m.end():])  # the text's last words
    if m.group("moved") and m.group("moved").lower() != top.lower() and not m.group("top") and not onto_top:
        return m.group(0)  # another cube moved: "the red cube is stacked on the blue cube" may be the goal's ("there is"
        # says what is there now, whichever cube moves); put on the top cube, the start's tower topped
    if not m.group("verb"):  # "... Put a gray block on top": the start's tower topped
        return f"Initially the {top} cube is on the {m.group('bottom')} cube. "
    if re.search(r"(?i)unstack$", m.group("verb")) and re.match(r"(?i)(?:them|both|it)\b", m.group("obj")):
        return f"Initially the {top} cube is on the {m.group('bottom')} cube. Unstack it"  # "Currently pink rests on gray.
        # Unstack both.": the start undone, every cube on the table
    obj = f"the {top} cube" if m.group("obj").lower() == "it" else m.group("obj")
    return f"Initially the {top} cube is on the {m.group('bottom')} cube. {m.group('verb')} {obj}"


def split(instruction: str) -> InitialScene | None:
    """The initial scene and the goal of ``instruction``, or None when it states no start this
    module reads (see the module docstring)."""
    instruction = lexicon.INITIALLY_MISSPELT_RE.sub("initially", instruction)
    instruction = lexicon.DEMONSTRATIVE_STRUCTURE_RE.sub(r"\g<p> the \g<n>", instruction)  # "on top of that tower"
    for pattern, written in MARKUP_RES:
        instruction = pattern.sub(written, instruction)
    for pattern, written in lexicon.START_SAID_REWRITES:
        instruction = pattern.sub(written, instruction)
    instruction = re.sub(r"^\s*[A-Za-z][\w\-]*(?:\s+[\w\-]+){0,3}?\s*(?:\([^)]{0,30}\))?\s*:\s*(?=\S)(?=.*\b(?:starts?|initial(?:ly)?)\b)", "",
                         instruction.strip())  # "# goal (unstack): the pink cube starts ...": its label
    instruction = lexicon.tower_ends_said(instruction)  # "red (bottom), blue, yellow (top)"
    instruction = lexicon.taken_down_as_unstack(instruction)  # "take (down) the stack of blue on yellow (down) so ..."
    instruction = lexicon.start_stack_source(instruction)  # "There is a stack of ... . Move the blue cube from the stack ..."
    instruction = lexicon.start_and_goal_said_tersely(instruction)  # "1. Start: green on brown. 2. Goal: green on table"
    instruction = lexicon.means_said(instruction)  # "...; clear the white block by putting the green block on the table"
    instruction = _ALREADY_START_RE.sub(r"Initially \g<fact>\g<rel>. ", instruction.strip())  # "A cyan cube is already on ..."
    instruction = _TOWER_ON_TABLE_START_RE.sub(r"Initially the \g<top> cube is on the \g<bottom> cube. ", instruction.strip())
    instruction = ROBOT_STARTS_RE.sub(r"Initially \g<fact>. \g<goal>", instruction.strip())
    # "Currently the pink cube is on the orange cube. Add ...": the scene now said before a command that moves or tops its
    # top cube is the start (elsewhere "currently" stays refused: which words are the goal's?)
    now = lexicon.SCENE_NOW_OPENING_RE.sub("", instruction.strip(), count=1)
    said_now = _NOW_THEN_UNDONE_RE.match(now) if now != instruction.strip() else None
    started = THERE_IS_START_RE.sub(_there_is_start, now)
    instruction = started if started != now else THERE_IS_START_RE.sub(_there_is_start, instruction.strip())
    there = _THERE_IS_RE.sub("", said_now.group("fact")) if said_now else ""  # "Currently there is a tower of ...": the
    if started == now and said_now and _facts(there):  # tower "Currently white sits on black, which sits on gray. Unstack
        instruction = f"Initially {there}{now[said_now.end('fact'):]}"  # the whole tower ...": stacks said now, every word a
        # fact, then undone
    instruction = FROM_START_RE.sub(r"Initially \g<fact>. \g<goal>", instruction.strip())
    instruction = FROM_STRUCTURE_RE.sub(_from_structure, instruction.strip())
    undone = UNSTACK_SAID_RE.match(instruction.strip())
    opened = re.match(r"(?i)^\s*(?:please\s+)?(?:unstack|dismantle|disassemble|take\s+apart)\s+(?:everything|it\s+all|all\s+of\s+it|the\s+(?:tower|stack))"
                      r"\s*[:,\-\u2014]\s*(?:the\s+(?:tower|stack)\s+is|it\s+is|it's)\s", instruction.strip())
    if opened and not undone:  # "unstack everything: the tower is pink, yellow, green, and ...": which end is the top is
        raise Inexpressible("time", [opened.group(0).strip()[:40]], "describes the tower it undoes without its order: say "  # unsaid
                            "it from the bottom (e.g. \"the tower is pink on yellow on green\" or \"pink, yellow, green from top "
                            "to bottom\")", instruction)
    if undone and undone.group("goal") and not ALL_ON_TABLE_GOAL_RE.match(undone.group("goal")):
        raise Inexpressible("time", [re.split(r"\s*[:,;\-\u2014]\s*", undone.group(0).strip())[0][:40]],
                            "undoes the start's tower and asks another goal besides: where each of the tower's cubes must "
                            "end up is not said; say it (e.g. \"Initially pink is on yellow. Put pink on the table and the "
                            "green cube on the blue cube.\")", instruction)
    instruction = UNSTACK_SAID_RE.sub(_unstack_said, instruction.strip())
    instruction = TAKE_FROM_LISTED_RE.sub(_take_from_listed, instruction.strip())
    instruction = START_STRUCTURE_RE.sub(r"Initially: a \1 of ", instruction.strip())
    unstack = _UNSTACK_RE.match(instruction.strip())
    if unstack:
        listed = unstack.group("c")  # "Unstack the tower (bottom to top: green, yellow, red) so ...": that tower
        said = f"a tower of {listed.split(':')[1].strip()} from the {listed.split(':')[0].split()[-3 if listed.startswith('from') else 0]}" \
            if listed else f"a tower of {unstack.group('d')}" if unstack.group("d") else (unstack.group("a") or unstack.group("b")).replace("-", " ")
        stacks = _facts(said)
        said_count = unstack.group("dn") or unstack.group("an")  # "the 2-block stack of blue on yellow"
        counted = said_count and NUMBER_WORDS.get(said_count.lower(), said_count)
        if stacks and counted and int(counted) != sum(len(st) for st in stacks):
            return None  # "the two-block tower (red, white, black ...)": read as written (refused)
        return InitialScene(tuple(stacks), unstack.group("goal")) if stacks else None
    clause = STARTS_CLAUSE_RE.match(instruction.strip())
    if clause:
        stacks = _facts(clause.group("fact"))
        subject = f"the {clause.group('top')} cube"
        rest = clause.group("rest").strip()
        rest = rest if re.match(r"(?i)(?:put|place|move|take|stack|unstack|dismantle|leave|build|make|set|bring|now|then|goal|the|a|an)\b",
                                rest) else f"{subject} {rest}"  # "... and must end up on the table": the subject carried over
        rest = re.sub(r"(?i)^((?:then\s+)?(?:put|place|move|take|set|bring|slide|push)\s+)it\b", rf"\1{subject}", rest)  # "Put it ..."
        rest = _start_ends_named([f"{clause.group('fact')}.", rest])[1]  # "... Put the gray block on top.": the tower topped
        rest = _TAKE_OFF_RE.sub(_taken_off, rest)  # "... Take it off and put it on the table.": where it goes
        rest = "put all the cubes on the table." if UNDO_START_RE.match(rest) else rest  # "... Unstack it."
        return InitialScene(tuple(stacks), GOAL_OPENER_RE.sub("", rest, count=1)) if stacks else None
    sentences = [s for s in re.split(r"(?<=[.;!?])\s+|\s*(?=\b(?:[Gg]oal|[Tt]arget)\s*:)|\s*,?\s*\band\s+(?=(?:at|in)\s+the\s+end\b)",
                                      instruction.strip()) if s.strip()]
    start, goal = [], []
    if sentences and re.match(r"(?i)\s*(?:the|a)\s+(?:tower|stack|column)\s+is\s+(?:the\s+)?(?:" + COLOR_RE + r")\b", sentences[0]) and any(
            re.match(r"(?i)\s*(?:then\s+)?(?:take|remove|lift|pick|unstack|dismantle|disassemble)\b", t) for t in sentences[1:]):
        sentences[0] = "Initially " + sentences[0]  # "The tower is red on blue. Take the top one off ...": what is there now
    sentences = _start_ends_named(sentences)
    taken = [(m.group("a") or m.group("b") or m.group("c"), m.group("below")) for t in sentences
             for m in _TAKE_OFF_RE.finditer(GOAL_OPENER_RE.sub("", t, count=1))]
    sentences = [_TAKE_OFF_RE.sub(_taken_off, s) for s in sentences]
    for i, s in enumerate(sentences):
        m = START_SENTENCE_RE.match(s)
        if m:  # a start said before the goal or after it ("... next to it. The orange block starts on the brown one.")
            start.append(s[m.end():])
        elif STARTS_FACT_RE.match(s) and not (i and sentences[i - 1].rstrip().endswith(";")):
            start.append(s)  # (after a ';' the relational reader reads it with its goal: "stack red on yellow; yellow starts on red")
        else:
            opened = GOAL_OPENER_RE.sub("", s, count=1)
            opened = GOAL_OPENER_RE.sub("", opened, count=1) if opened != s else opened  # "Goal: take the tower apart so ..."
            goal.append(_TAKE_OFF_RE.sub(_taken_off, opened))  # "Goal: take off the red cube and put it on the table"
    if not start:
        return None
    leave = LEAVE_REST_RE.search(" ".join(goal))
    if leave:  # "take off the red cube ...; leave the other two as they are": the rest of its stack stays stacked
        goal = [" ".join(goal)[:leave.start()] + " ".join(goal)[leave.end():]]
    if goal and UNDO_START_RE.match(goal[0]):
        if len(goal) > 1 and not ALL_ON_TABLE_GOAL_RE.match(" ".join(goal[1:])):
            return None  # "Unstack the tower. Put red on green.": blue's end is not said (read as written, refused)
        goal = goal[1:] or ["put all the cubes on the table."]  # "Unstack the tower.": every cube off the others
    stacks = _start_stacks(start)
    if stacks is None:  # a start this module cannot build: refused, never read as part of the goal
        raise Inexpressible("time", [start[0].strip()[:60]], "states a starting scene rpg does not build: rho_0 starts only "
                            "stacks of named cubes, each cube once, the rest scattered (e.g. \"Initially the red cube is on the "
                            "blue cube. Put ...\"); say only where the cubes must end up", instruction)
    if len(stacks) > 1 and re.search(r"(?i)\b(?:unstack|dismantle|take\s+apart)\s+(?:it|the\s+(?:tower|stack))\b", instruction):
        return None  # "the tower" of a start with two: which one is not said
    for cube, below in taken:  # "take the red cube off the blue cube": it must stand on top, on that cube
        c = _canon(re.sub(r"(?i)^the\s+|\s+(?:one|cube|block)$", "", cube.strip()).strip())
        b_ = _canon(re.sub(r"(?i)^the\s+|\s+(?:one|cube|block)$", "", below.strip()).strip()) if below else None
        if not any(st[-1] == c and len(st) > 1 and (b_ is None or st[-2] == b_) for st in stacks):
            return None
    kept: list[tuple[str, ...]] = []
    if leave:
        moved = {_canon(c) for c in re.findall(rf"(?i)\b(?:put|place|move|set|lay|lift|take|bring)\s+the\s+({COLOR_RE})\b", " ".join(goal))}
        said = re.search(r"(?i)\b(two|three|four|\d+)\b", leave.group(0))
        left = sum(1 for st in stacks for c in st if c not in moved)
        if not moved or (said and NUMBER_WORDS.get(said.group(1).lower(), int(said.group(1)) if said.group(1).isdigit() else 0) != left):
            return None  # no cube moved, or "the other three" of two: read as written (refused)
        for st in stacks:
            rest = tuple(c for c in st if c not in moved)
            if st[:len(rest)] != rest:
                return None  # a cube taken from under another: read as written (refused)
            kept += [rest] if len(rest) > 1 else []
    return InitialScene(tuple(stacks), " ".join(goal).strip(), tuple(kept))


_START_END_RE = re.compile(r"(?i)\bthe\s+(?:(?P<top>top|topmost|uppermost|highest)|(?P<bottom>bottom|bottommost|lowest|base))\s+"
                           r"(?:cube|block|one)\b|\bthe\s+(?:cube|block|one)\s+(?:on\s+(?P<top2>top)|at\s+the\s+(?P<bottom2>bottom))\b(?!\s+of\b)")
"""The goal's words for an end of the start's one stack ("Take the top one off", "the cube at the bottom")."""


def _start_stacks(start: list[str]) -> list[tuple[str, ...]] | None:
    """The stacks (bottom to top) the start's statements say: read as facts (:func:`_facts`), else by the whole front end
    (:func:`_stacks_read`: "red stacked on white stacked on black", "a stack with orange at the bottom and pink on top");
    None when neither reads them."""
    stacks = _facts(" , ".join(start))
    if stacks is None:
        stacks = _stacks_read(" ".join(f.strip().rstrip(".;,") + "." for f in start))
    return stacks


def _start_ends_named(sentences: list[str]) -> list[str]:
    """``sentences`` with the goal's words for an end of the start's stack (:data:`_START_END_RE`) naming its cube, when
    the start says exactly one stack ("Initially red is on blue. Take the top cube off and put it on the table.": the
    red cube; "take it off" of the cube the start is about, :data:`_IT_TAKEN_RE`; "put gray on top", the tower topped,
    :data:`_ON_TOP_RE`); otherwise as they are (which stack's top would be a guess)."""
    start = [s[m.end():] for s in sentences if (m := START_SENTENCE_RE.match(s))] + [s for s in sentences if STARTS_FACT_RE.match(s)]
    stacks = _start_stacks(start) if start else None
    if not stacks or len(stacks) != 1 or len(stacks[0]) < 2:
        return sentences

    def named(m: re.Match) -> str:
        return f"the {stacks[0][-1] if m.group('top') or m.group('top2') else stacks[0][0]} cube"

    def top_ones(m: re.Match) -> str:  # "remove the top two blocks and set them on the table": those cubes to the table
        n = int(NUMBER_WORDS.get(m.group("n").lower(), m.group("n")))
        if not 1 < n < len(stacks[0]):
            return m.group(0)
        return "put " + " and ".join(f"the {c}" for c in stacks[0][-n:]) + " cubes on the table"

    def swapped(m: re.Match) -> str:  # "swap them so the black one ends on top": the start's stack of two reversed
        if len(stacks[0]) != 2 or (m.group("c") and _canon(m.group("c")) != stacks[0][0 if m.group("top") or m.group("d") else 1]) \
                or (m.group("d") and _canon(m.group("d")) != stacks[0][1]):
            return m.group(0)  # a taller stack (which two is not said), or the 'so that' contradicting the swap: as written
        return f"put the {stacks[0][0]} cube on the {stacks[0][1]} cube"

    subject = re.match(rf"(?i)\s*(?:initially,?\s+|at\s+the\s+start,?\s+)?the\s+(?P<c>{_NAME})\b", " ".join(start))
    top_said = subject is not None and _canon(subject.group("c")) == stacks[0][-1]

    def it_taken(m: re.Match) -> str:  # "The blue cube starts on top of the green cube. Take it off ...": the top cube
        return f"{m.group('verb') or 'take'} the {stacks[0][-1]} cube off" if top_said else m.group(0)

    goal_sentences = [s for s in sentences if not (START_SENTENCE_RE.match(s) or STARTS_FACT_RE.match(s))]
    topped = sum(bool(_ON_TOP_RE.search(s)) for s in goal_sentences) == 1 and not any(
        re.search(r"(?i)\bon\s+top\b(?!\s+of\s+(?:the\s+)?(?!tower|stack)\w)", s) for s in goal_sentences if not _ON_TOP_RE.search(s))

    def on_top(m: re.Match) -> str:  # "Initially green is on brown. Put gray on top.": the tower with gray on top (once: "...
        # Put white on top." after it is on gray, whose top the start does not say); gray on green alone had let green
        # leave brown, though "on top" is the tower's top
        onto = m.group("onto") or m.group("onto2") or m.group("onto3")
        if onto and _canon(onto) != stacks[0][-1]:
            return m.group(0)  # on another cube than the start's top: as written
        tower = [*stacks[0], _canon(m.group("new"))]
        if not topped or not all(re.fullmatch(COLOR_RE, c) for c in tower) or len(set(tower)) != len(tower):
            return m.group(0)
        if m.group("restated"):  # "..., so the tower is brown, green, gray": said again, the same tower or refused
            said = [_canon(c) for c in re.findall(rf"(?i)\b(?:{COLOR_RE})\b", m.group("rlist"))]
            way = (m.group("rway") or "").lower()
            if way.startswith("top") or way.startswith("from the top") or way.startswith("from top"):
                said = said[::-1]
            if said != tower:
                raise ParseError(f"'{m.group('restated').strip(' ,')}' is not the tower the start and the cube put on top "
                                 f"make (bottom to top: {', '.join(tower)}); say the tower once, or use --model")
        return "build a tower from bottom to top: " + ", ".join(tower)

    def taken_then_put(m: re.Match) -> str:  # "take the purple cube off and put it on the red patch": put it there
        if _canon(m.group("c")) != stacks[0][-1] or re.search(r"(?i)\bits?\b", m.string[m.end():]):
            return m.group(0)  # (another "it" after: "... off the brown block and set it down next to it", the brown one)
        rest = m.string[m.end():]
        if re.match(r"(?i)\s+(?:down\s+)?(?:in|at|into|to)\s+the\s+(?:[a-z]+\s+){0,2}?(?:half|side|corner|cent(?:er|re)|middle|front|back|left|right"
                    r"|edge)\b(?!\s+of\s+(?:the\s+)?(?!table)\w)", rest):  # a place on the table: taken off, so on the table there
            return f"{m.group('verb')} the {stacks[0][-1]} cube on the table"
        return f"{m.group('verb')} the {stacks[0][-1]} cube"

    return [s if START_SENTENCE_RE.match(s) or STARTS_FACT_RE.match(s) else
            _TAKEN_THEN_PUT_RE.sub(taken_then_put, _ON_TOP_RE.sub(on_top, _START_END_RE.sub(named, _SWAP_START_RE.sub(
                swapped, _TOP_ONES_OFF_RE.sub(top_ones, _IT_TAKEN_RE.sub(it_taken, s))))))
            for s in sentences]


_TAKEN_THEN_PUT_RE = re.compile(
    rf"(?i)^\s*(?:then\s+)?(?:take|lift|remove|pick|move|get|slide)\s+(?:up\s+)?the\s+(?P<c>{_NAME})(?:\s+(?:cube|block|one))?\s+off"
    rf"(?:\s+(?:of\s+)?(?:it|the\s+(?:tower|stack)|the\s+{_NAME}(?:\s+(?:cube|block|one))?))?\s*,?\s*(?:and\s+)?(?:then\s+)?"
    r"(?P<verb>put|place|set|move|lay)\s+it\b")
"""A goal that takes the start's top cube off and puts it somewhere ("take the purple cube off and put it on the red
patch"): the placing alone ("put the purple cube on the red patch"; taking it off is how it gets there), read when the
cube is the start's one stack's top (:func:`_start_ends_named`; "off" had been refused as taking a cube off no stack)."""


_ON_TOP_RE = re.compile(rf"(?i)(?:^\s*(?:then\s+)?(?:put|place|set|stack|add|lay)\s+(?:the\s+|a\s+|an\s+)?(?P<new>{_NAME})"
                        r"(?:\s+(?:cube|block|one))?\s+)(?:on\s+(?:the\s+)?top(?:\s+of\s+(?:it|the\s+(?:tower|stack)"
                        rf"|the\s+(?P<onto>{_NAME})(?:\s+(?:cube|block|one))?))?"
                        rf"|onto\s+(?:it|the\s+(?:tower|stack)|the\s+(?P<onto2>{_NAME})(?:\s+(?:cube|block|one))?)"
                        rf"|on\s+the\s+(?P<onto3>{_NAME})(?:\s+(?:cube|block|one))?)"
                        rf"(?P<restated>\s*,?\s*so\s+(?:that\s+)?(?:the\s+)?(?:tower|stack)\s+(?:reads|is|becomes|goes)\s*:?\s*"
                        rf"(?P<rlist>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+)"
                        r"(?:\s*,?\s+(?P<rway>from\s+(?:the\s+)?(?:bottom|top)(?:\s+(?:up|down|to\s+(?:the\s+)?(?:top|bottom)))?"
                        r"|bottom\s+to\s+top|top\s+to\s+bottom))?)?"
                        r"(?=\s*(?:[.!;,]|$|\bso\b))")
"""A goal that adds a cube on top of the start's one stack ("Put gray on top.", "Put the gray block on top of it.", "Put
the white block on top of the orange block", orange the stack's top): the tower, the start's cubes with it on top
(:func:`_start_ends_named`; a cube named that is not the stack's top leaves the words as they are)."""


_IT_TAKEN_RE = re.compile(r"(?i)^\s*(?:then\s+)?(?:(?P<verb>take|lift|remove|pick)\s+it\s+off\b|(?:unstack|remove)\s+it\b(?=\s*,?\s*(?:and\s+)?(?:then\s+)?(?:put|place|set|move|lay)\s+it\b))")
"""A goal that takes 'it' off the start's one stack ("The blue cube starts on top of the green cube. Take it off and put it
on the table."): the cube the start sentence is about, named when it is the stack's top (:func:`_start_ends_named`)."""


_SWAP_START_RE = re.compile(
    r"(?i)^\s*(?:then\s+)?(?:swap|switch|reverse|flip)\s+(?:them|the\s+two(?:\s+(?:cubes|blocks))?|the\s+(?:cubes|blocks)|their\s+order"
    r"|the\s+(?:tower|stack)|the\s+order)(?:\s*,?\s*so\s+(?:that\s+)?(?:the\s+)?(?P<c>" + _NAME + r")(?:\s+(?:cube|block|one))?\s+"
    r"(?:ends?\s+(?:up\s+)?|is\s+|sits\s+|goes\s+)(?:on\s+(?P<top>top)|at\s+the\s+(?P<bottom>bottom)"
    r"|(?:on|on\s+top\s+of|atop)\s+(?:the\s+)?(?P<d>" + _NAME + r")(?:\s+(?:cube|block|one))?))?\s*[.!]?\s*$")
"""A goal that swaps the start's stack of two ("swap them so the black one ends on top", "swap them so yellow is on
red"): its bottom cube put on its top one; a 'so that' naming the cube that ends on top (or at the bottom, or the two
cubes' order) must agree with the swap."""


_TOP_ONES_OFF_RE = re.compile(
    r"(?i)^\s*(?:then\s+)?(?:remove|take\s+off|take|lift\s+off|lift)\s+the\s+top\s+(?P<n>two|three|2|3)\s+(?:blocks|cubes|ones)(?:\s+off)?"
    r"(?:\s+(?:of\s+)?(?:the\s+)?(?:tower|stack))?(?:\s*,?\s*(?:and\s+)?(?:then\s+)?(?:set|put|place|lay|leave)\s+(?:them|both)\s+(?:down\s+)?"
    r"(?:on|onto)\s+the\s+table)?\s*[.!]?\s*$")
"""A goal that takes the start's one stack's top cubes off ("remove the top two blocks and set them on the table"): those
cubes, named, sent to the table (:data:`ON_TABLE_LIST_GOAL_RE`)."""


ALL_ON_TABLE_GOAL_RE = re.compile(
    rf"(?i)^\s*(?:(?:unstack|dismantle|take\s+apart)\s+{_UNDONE}\s*,?\s*(?:and\s+|so\s+(?:that\s+)?)?"
    rf"|take\s+{_UNDONE}\s+apart\s*,?\s*(?:and\s+|so\s+(?:that\s+)?)?)?"
    r"(?:(?:put|place|set|lay|leave|get)\s+)?(?:both|all|every|each|the)(?:\s+(?:of\s+the\s+)?(?P<n>two|three|four|five|six|\d+))?\s+(?:of\s+)?(?:the\s+)?"
    r"(?:cubes|blocks|cube|block|ones|of\s+them|them)?\s*(?:(?:must|should|have\s+to|need\s+to|will)\s+)?(?:(?:be|end\s+up|ends\s+up"
    r"|sit|sits|sitting|stand|stands|standing|lie|lies|lying|rest|rests|resting|placed|are|is|go|stay)\s+){0,2}"
    r"(?:(?:flat|back|down|separately)\s+)?(?:on|onto)\s+the\s+table\s*[.!]?$")
"""A goal that sends every cube the start stacks to the table ("both cubes sit on the table",
"put all the blocks on the table", "unstack it and leave both cubes on the table"): each cube a stack holds above
another on the table."""


START_CUBES_RE = re.compile(r"(?i)\b(?:both(?:\s+(?:of\s+the\s+)?(?:cubes|blocks))?|the\s+(?:(?:two|three|four|2|3|4)\s+)?(?:cubes|blocks)"
                            r"|all\s+(?:the\s+)?(?:(?:two|three|four|2|3|4)\s+)?(?:cubes|blocks)|(?:two|three|four|2|3|4)\s+(?:cubes|blocks))\b")
"""The goal's words for the cubes the start describes ("both cubes", "the cubes", "all three cubes")."""


def with_start_cubes(scene: InitialScene) -> InitialScene:
    """``scene`` with a goal that names no cube by colour or label, but says "both cubes" / "the
    cubes", naming the start's cubes instead ("Initial state: yellow on red. Goal: both cubes on
    the table, side by side" -> "the yellow cube and the red cube on the table, side by side"):
    those words are the start's cubes (the goal had been read with cubes of its own: silently
    wrong).  ``scene`` itself when the goal names a cube, or says a count the start does not have."""
    cubes = [c for st in scene.stacks for c in st]
    m = START_CUBES_RE.search(scene.goal)
    # (a patch's colour names no cube: "put both cubes on the green patch")
    if m is None or re.search(rf"(?i)\b(?:{COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|area|zone)\b)"
                              r"|\b(?:letter|digit|number)\b|(?-i:(?<![\w'])[A-Z0-9](?![\w']))", scene.goal):  # (a label in capitals:
        # "in a row"'s "a" had kept the goal's own cubes, a red one made up)
        return scene
    said = re.search(r"(?i)\b(two|three|four|2|3|4|both)\b", m.group(0))
    if said and NUMBER_WORDS.get(said.group(1).lower(), int(said.group(1)) if said.group(1).isdigit() else 0) != len(cubes):
        return scene
    each = [f"the {c} cube" for c in cubes]
    named = ", ".join(each[:-1]) + " and " + each[-1] if len(each) > 1 else each[0]
    return InitialScene(scene.stacks, scene.goal[:m.start()] + named + scene.goal[m.end():])


def on_table_goal(scene: InitialScene) -> TaskSchema | None:
    """The task whose goal only sends a cube the start stacks to the table (:data:`ON_TABLE_GOAL_RE`),
    or every such cube (:data:`ALL_ON_TABLE_GOAL_RE`); None when the goal is not of that form or
    the cube starts on the table."""
    every = ALL_ON_TABLE_GOAL_RE.match(scene.goal)
    m = None if every else ON_TABLE_GOAL_RE.match(scene.goal)
    listed = None if every or m else ON_TABLE_LIST_GOAL_RE.match(scene.goal)
    if m is None and every is None and listed is None:
        return None
    said = every.group("n") if every else None
    if said and NUMBER_WORDS.get(said, int(said) if said.isdigit() else 0) != sum(len(st) for st in scene.stacks):
        return None  # "all four cubes on the table" of a start of three: not these cubes
    colors = [c for s in scene.stacks for c in s] if every else [canon_color(m.group("c"))] if m else \
        [_canon(c) for c in re.findall(rf"\b{_NAME}", listed.group("list"))]  # ("all three cubes on the table": the bottom
    # one too, though it starts there: the words demand it at the end; it had been left out)
    if len(set(colors)) != len(colors):
        return None  # a cube listed twice: read as written
    # a listed cube that starts on the table may stay there while the others move (the goal does not hold at the start)
    listed_moves = (listed or every) and all(any(c in s for s in scene.stacks) for c in colors) and any(
        c in s[1:] for s in scene.stacks for c in colors)
    if not listed_moves and (not colors or not all(any(c in s[1:] for s in scene.stacks) for c in colors)):
        return None  # it starts on the table: the goal would hold before anything moved
    b = Builder(scene.goal)
    for c, xy in zip(colors, b.unit_centers(len(colors)), strict=True):
        cube = b.semantic(c) if re.fullmatch(r"[A-Z]|\d", c) else b.cube(c)  # a letter or digit cube by its label
        b.place(stack_layout([cube], xy))
        b.preds.append(OnTable(cube))
        b.summary.append(f"{cube} on the table")
    b.primitives += ["place"]
    return b.schema(task_slug(scene.goal))


def attach(head: TaskSchema, scene: InitialScene, instruction: str) -> TaskSchema:
    """``head`` (the goal, read alone) with rho_0 starting ``scene``'s stacks: each colour is the
    goal's one cube of that colour, or a cube added for the start when the goal has none.

    Raises:
        BadInput: a colour of the start names two cubes of the goal (which one starts there is
            not said).
    """
    b = Builder(instruction)
    b.adopt(head)
    b.repairs, b.min_separation = list(head.repairs), head.initial_state.min_separation
    b.summary = [head.goal_summary]
    spare = iter(b.unit_centers(8, 0.1)[::-1])
    for colors in scene.stacks:
        names = []
        for c in colors:
            label = re.fullmatch(r"[A-Z]|\d", c) is not None
            have = [a.name for a in b.assets if (a.label == c if label else a.kind == "colored_cube" and a.color == c)]
            if len(have) > 1:
                raise BadInput(f"\"{instruction[:80]}\": the start puts a {c} cube in a stack and the goal has "
                               f"{len(have)} {c} cubes; say which one (e.g. by a letter), or use --model")
            if not have:  # a cube only the start names: it starts there, the goal leaves it free
                have = [b.semantic(c) if label else b.cube(c)]
                b.place(stack_layout([have[0]], next(spare)))
            names.append(have[0])
        if any(n in s for s in b.structures for n in names):
            raise BadInput(f"\"{instruction[:80]}\": the start stacks a cube twice; say each stack once, or use --model")
        b.structures.append(names)
        b.summary.append("initially a stack bottom to top: " + ", ".join(names))
    raised = {n for st in b.structures for n in st[1:]}  # cubes that start on another cube
    below = {st[i]: set(st[:i]) for st in b.structures for i in range(len(st))}  # the cubes each starts above
    b.preds = [p for q in b.preds for p in _resting_on(q, raised, below)]
    by_colour = {a.color: a.name for a in b.assets if a.kind == "colored_cube"}
    for m in lexicon.TABLE_SAID_RE.finditer(scene.goal.lower()):  # "..., then put red on the table": red off its start
        name = by_colour.get(canon_color(m.group("c"))) if m.group("c") else None
        if name in raised and not any(type(p) is OnTable and p.a == name for p in b.preds):
            b.preds.append(OnTable(name))
            b.summary.append(f"{name} on the table")
    by_color = {a.label or a.color: a.name for a in b.assets if a.kind != "goal_patch"}
    for colors in scene.kept:  # "leave the other two as they are": their stack is the goal's too
        b.preds.append(Stack(objects=tuple(by_color[c] for c in colors)))
        b.summary.append("left stacked bottom to top: " + ", ".join(by_color[c] for c in colors))
    if b.preds and all(type(p) is Stack and list(p.objects) in b.structures for p in b.preds):
        raise BadInput(f"\"{instruction[:80]}\": the goal is the stack the cubes start in, so it holds before anything moves; "
                       "say where they must end up (e.g. \"... Put the red cube on the table.\"), or use --model")
    return b.schema(task_slug(instruction), paraphrases=list(head.paraphrases))


def _resting_on(p, raised: set[str], below: dict[str, set[str]]) -> list:
    """``p``, or, when it is a stack whose bottom cube starts on another cube, its cubes each on
    the one below: "put C on A" where A starts on B asks C on A, not A moved to the table; unless a
    cube of the stack starts under its bottom ("stack red on yellow; yellow starts on red": yellow
    must come down to the table first)."""
    from rpg.domain.predicates import On, Stack

    if type(p) is Stack and p.objects[0] in raised and not below.get(p.objects[0], set()) & set(p.objects):
        return [On(a, b) for b, a in zip(p.objects, p.objects[1:], strict=False)]
    return [p]
