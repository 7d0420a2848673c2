"""Edits of pairwise-relation tasks ("place the red block behind the yellow block").

A relation task has no :class:`~rpg.steer.spec.TaskSpec`; its edits usually speak in
its own terms: "put it in front instead", "move it to the other side", "swap them",
"put the red block on top of it".  :func:`rewrite` reads the reference task's relation
(subject, relation, object) and states the edited task as a whole instruction, which
the builtin parser then compiles like any other.  Paper: Methods, steering (Modify edits
change a relation within the same assets).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from rpg.domain.predicates import (
    PREDICATES,
    Between,
    InRegion,
    OnPatch,
    Predicate,
    Stack,
)
from rpg.errors import BadInput
from rpg.schema.builder import DEFAULT_COLORS
from rpg.schema.lexicon import (
    COLOR_RE,
    COUNT_WORD_RE,
    EDIT_ADDITIVE_RE,
    EDIT_OPENING,
    EDIT_RELATIONS,
    NUMBER_WORDS,
    PAIRWISE_RELATIONS,
    STACK_SIDE_MOVE_RE,
)
from rpg.schema.model import TaskSchema
from rpg.schema.reading import canon_color, region_name
from rpg.schema.structures import cube_list
from rpg.steer.carried import region_phrase
from rpg.steer.edits import SteerError

PHRASES = {name: PREDICATES[name].phrase for name in (*PAIRWISE_RELATIONS, "on")}
"""How a canonical instruction states each relation."""

OPPOSITE = {"left_of": "right_of", "right_of": "left_of", "in_front_of": "behind", "behind": "in_front_of",
            "on": "under", "under": "on"}



ADDS_RE = re.compile(rf"\b(?:add|another|new|extra|more|one more|also)\b|\ban? (?:\w+ )?(?:block|cube)\b|\ban? (?:{COLOR_RE}) one\b")
"""An edit that brings in a cube (an Extend): not a change of the relation."""


NEW_CUBE = rf"\b(?:an?|another|one more|a new|an extra)\s+(?:new\s+|extra\s+)?({COLOR_RE})\s+(?:block|cube|one)\b"
"""A cube an edit brings in, its colour the group ("a green one", "another red block")."""

FLIPPED = (EDIT_OPENING + r"flip\s+(?:it|them|that)\s*$|" + EDIT_OPENING
           + r"(?:(?:do\s+it|have\s+it|make\s+it|put\s+them)\s+)?(?:the\s+)?other\s+way\s+(?:a)?round\s*$")
"""An edit that turns a two-cube task around without naming how ("flip it", "nah, other way
round"): the two cubes trade their roles."""


TABLE_PLACE_RE = re.compile(r"\b(?:of|on|in)\s+the\s+(?:table|workspace)\b|\bcorner\b")
"""A place on the table: an edit that names one moves cubes there, it relates them to no cube."""


def same_assets(a: TaskSchema, b: TaskSchema) -> bool:
    """Whether two tasks use the same cubes and patches (kinds, colours, labels)."""
    def sig(s: TaskSchema) -> list[tuple]:
        return sorted((x.kind, x.color or "", x.label or "") for x in s.assets)

    return sig(a) == sig(b)


@dataclass(frozen=True)
class Relation:
    """The reference task's one relation: ``subject`` REL ``object`` (asset names)."""

    subject: str
    kind: str
    object: str


def relation_of(schema: TaskSchema) -> Relation | None:
    """The single pairwise relation a task is about (a two-cube stack counts as ``on``);
    None when the task has none or several."""
    goal = schema.goal_predicate()
    parts: list[Predicate] = goal.conjuncts()
    kinds = {PREDICATES[name]: name for name in PAIRWISE_RELATIONS}
    found = []
    for p in parts:
        if type(p) in kinds:
            found.append(Relation(p.a, kinds[type(p)], p.b))
        elif isinstance(p, Stack) and len(p.objects) == 2:
            found.append(Relation(p.objects[1], "on", p.objects[0]))
        else:
            return None
    return found[0] if len(found) == 1 else None


def _patches(schema: TaskSchema) -> set[str]:
    return {a.name for a in schema.assets if a.kind == "goal_patch"}


def _phrase(schema: TaskSchema, name: str) -> str:
    asset = next(a for a in schema.assets if a.name == name)
    if asset.kind == "goal_patch":
        return f"the {asset.color} goal patch"
    if asset.kind == "semantic_cube":
        return f"the block with the {'digit' if (asset.label or '').isdigit() else 'letter'} {asset.label}"
    return f"the {asset.color} block"


_STACK_ROLES = {"bottom": "bottom", "lower": "bottom", "lowest": "bottom", "base": "bottom", "top": "top", "upper": "top",
                "uppermost": "top", "highest": "top"}
"""Words naming a cube of a two-cube stack by its role ("the bottom cube on the left")."""


def rewrite(edit: str, schema: TaskSchema) -> tuple[str, str] | None:
    """The whole-task instruction an edit of a relation task means and its intent, or None
    when the edit is not about that relation.

    Reads: a new relation for the same cubes ("put it in front instead", "move the red
    block to the left"), "the other side" / "the opposite side", and "swap them" /
    "switch places" (Modify); and a cube added in relation to one of the two ("add a
    green block next to it", Extend).  "it" is the reference's subject; a relation
    without an object ("in front") is taken relative to the reference's object.
    """
    rel = relation_of(schema)
    t = " " + edit.lower().strip().rstrip(".!") + " "
    if rel is None or TABLE_PLACE_RE.search(t):
        return None  # a place on the table ("move the stack to the back of the table"): not a relation to a cube
    if re.search(r"\bthe\s+(?:whole\s+)?(?:tower|stack|pile|structure)\b|\b(?:everything|all\s+of\s+it|the\s+whole\s+thing)\b", t) \
            and not re.search(r"\b(?:of|to|from|beside|behind|near)\s+(?:it|them|the\s+\w+\s+(?:block|cube|one))\b", t):
        return None  # "put the tower on the left side": a place for the whole structure, not a relation inside it
    if ADDS_RE.search(t):
        return _added(t, schema, rel)
    have = {a.color for a in schema.assets if a.kind == "goal_patch"}
    if any(canon_color(c) not in have for c in re.findall(rf"\b({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat)\b", t)):
        return None  # "and the green one on the red patch": a patch the relation does not have, so no change of it
    subject, obj = rel.subject, rel.object
    side = STACK_SIDE_MOVE_RE.fullmatch(t) if rel.kind == "on" and obj not in _patches(schema) else None
    if side:  # "move it to the left" of a two-cube stack: the stack to that side of the table
        where = region_phrase(region_name(None, side.group("side")))
        return (f"Stack {_phrase(schema, subject)} on {_phrase(schema, obj)}, then place {_phrase(schema, subject)} {where}, "
                f"then place {_phrase(schema, obj)} {where}"), "modify"
    if re.search(r"\b(?:swap|switch|exchange|trade)\b.*\b(?:them|places|positions|roles|blocks|cubes|the two)\b"
                 r"|^\s*(?:\w+\s+){0,2}?reverse\s+the\s+order\s*$|" + FLIPPED, t):  # "other way round", "flip it"
        subject, obj = obj, subject
        kind = rel.kind
    elif re.search(r"\b(?:other|opposite)\s+side\b", t):
        kind = OPPOSITE.get(rel.kind)
        if kind is None:
            return None
    else:
        kind = _edit_relation(t)
        named = [w for w in re.findall(r"\bthe (\w+) (?:block|cube|one)\b", t)  # "put the blue one on the left": blue moves
                 if w not in _STACK_ROLES]  # ("the top one": a cube by its role, read below)
        cube_of = {(a.color or a.label or "").lower(): a.name for a in schema.assets if a.kind != "goal_patch"}
        stacked = re.search(r"\b(?:the\s+)?(?:letter\s+|digit\s+)?([a-z0-9]+)\s+(?:cube\s+|block\s+|one\s+)?(?:is\s+|goes\s+|sits\s+)?"
                            r"(?:on\s+top\s+of|on|onto|atop|above|over)\s+(?:the\s+)?(?:letter\s+|digit\s+)?([a-z0-9]+)\b", t) \
            if kind == "on" and not re.search(r"\b(?:too|also|as\s+well)\b", t) else None
        if stacked and cube_of.get(stacked.group(1)) and {cube_of.get(stacked.group(1)), cube_of.get(stacked.group(2))} == {subject, obj}:
            # "The exercise wants them stacked, M on top of K." of K left of M: M on K (K had gone on M: the pair's order)
            subject, obj = cube_of[stacked.group(1)], cube_of[stacked.group(2)]
            if (subject, kind) == (rel.subject, rel.kind):
                return None
            return f"Stack {_phrase(schema, subject)} on {_phrase(schema, obj)}", "modify"
        if re.search(r"\b(?:stack|pile)\s+(?:them|all|everything|the\s+(?:blocks|cubes))\b", t) and not named:
            return None  # "stack them": which on which is not said (the structure edit reads it)
        by_color = {a.color: a.name for a in schema.assets if a.kind == "colored_cube"}
        pair = [by_color.get(c) for c in named] if len(named) == 2 else None
        if pair and set(pair) == {subject, obj} and not re.search(r"\b(?:too|also|as\s+well)\b", t):  # both said
            subject, obj = pair
            named = []
        if kind is None or len(named) > 1 or (named and named[0] not in by_color):
            return None  # no relation, or cubes of its own: a whole task, not an edit of this one

        side = re.search(rf"\b({COLOR_RE})\s+(?:one\s+|block\s+|cube\s+)?(?:on|to|at|in)\s+(?:the\s+)?(?:left|right|front|back)\b", t)
        role = re.search(rf"\b({'|'.join(_STACK_ROLES)})\s+(?:one|block|cube)\s+(?:goes\s+|is\s+)?"
                         r"(?:on|to|at|in)\s+(?:the\s+)?(?:left|right|front|back)\b", t) if rel.kind == "on" and not named else None
        end = re.search(rf"\b({COLOR_RE})\s+(?:one\s+|block\s+|cube\s+)?(?:is\s+|goes\s+)?(on\s+top|at\s+the\s+top|at\s+the\s+bottom"
                        r"|on\s+the\s+bottom|at\s+the\s+base)\b", t) if kind == "on" and not named else None
        if end and by_color.get(canon_color(end.group(1))) in (subject, obj) and obj not in _patches(schema):
            # "make it a tower with blue on top" of red left of blue: blue is the one on top (red had gone on top)
            said = by_color[canon_color(end.group(1))]
            other = obj if said == subject else subject
            subject, obj = (said, other) if "top" in end.group(2) else (other, said)
        elif role and obj not in _patches(schema):
            # "turn it into a row, bottom cube on the left": the cube of that role in the stack is the one placed there
            moved = obj if _STACK_ROLES[role.group(1)] == "bottom" else subject
            subject, obj = moved, (obj if moved == subject else subject)
            side = role
        elif side and not named and by_color.get(canon_color(side.group(1))) in (subject, obj):
            # "make it a row, green on the left": the cube said with the side is the one placed there
            moved = by_color[canon_color(side.group(1))]
            subject, obj = moved, (obj if moved == subject else subject)
            named = []
        pronoun = re.search(r"\b(?:it|them)\b", t) if not side else None
        anchor = named and re.search(rf"\b(?:of|to|behind|beside|near|under|above|below|on|onto|from|than)\s+the\s+{named[0]}\s+"
                                     r"(?:block|cube|one)\b", t)  # "on the left of the blue one": blue stays where it is
        if named and not pronoun and not anchor and by_color[named[0]] == obj:  # "move the yellow block behind": the subject now
            subject, obj = obj, subject
        if (subject, kind) == (rel.subject, rel.kind):
            return None
    if kind == "under":
        subject, obj, kind = obj, subject, "on"
    patches = _patches(schema)
    if subject in patches:
        return None  # "swap them" of a cube by a patch: a patch is placed by the task, not moved
    if obj in patches and kind == "on":  # "put it on the patch": a cube on a patch lies on it
        return f"Place {_phrase(schema, subject)} on {_phrase(schema, obj)}", "modify"
    return f"Place {_phrase(schema, subject)} {PHRASES[kind]} {_phrase(schema, obj)}", "modify"


def between_roles(edit: str, schema: TaskSchema) -> str:
    """An edit of a task whose goal is one cube between two others, with its roles said by colour:
    "the middle one" is the cube between, "the outer two" / "the ends" the two it lies between
    ("make the outer two white" of a pink cube between two cyan ones: "make the cyan ones white").
    Returns ``edit`` unchanged for any other task or edit.

    Raises:
        SteerError: "the outer two" of ends of two colours (one recolour cannot name both).
    """
    parts = schema.goal_predicate().conjuncts()
    if len(parts) != 1 or not isinstance(parts[0], Between):
        return edit
    color = {a.name: a.color for a in schema.assets if a.kind == "colored_cube"}
    p = parts[0]
    if None in (color.get(p.a), color.get(p.b), color.get(p.c)):
        return edit
    edit = re.sub(r"(?i)\bthe\s+(?:middle|central|center|centre|inner)\s+(?:one|block|cube)\b", f"the {color[p.a]} one", edit)
    edit = re.sub(rf"(?i)^\s*(?:(?:now|ok|okay|actually|rather|fine|then)\s*,?\s+)*(?:(?:use|put|place|have)\s+)?an?\s+({COLOR_RE})\s+(?:one|block|cube)\s+"
                  r"(?:in\s+the\s+middle|in\s+between|between\s+them)(?:\s+(?:instead|then))?\s*[.!]?\s*$",
                  lambda m: f"make the {color[p.a]} one {m.group(1)}", edit)  # "use a gray one in the middle instead", "Fine, a brown cube in the middle then."
    ends = re.search(r"(?i)\bthe\s+(?:(?:two\s+|2\s+)?(?:outer|outside|end)\s+(?:two|2|ones|blocks|cubes)|(?:two\s+)?ends|end\s+ones)\b"
                     r"|\bboth\s+ends\b", edit)
    if ends:
        if color[p.b] != color[p.c]:
            raise SteerError(f"'{ends.group(0)}' names the {color[p.b]} and the {color[p.c]} cube at once; change one per edit "
                             f"(\"make the {color[p.b]} one ...\")")
        edit = edit[:ends.start()] + f"the {color[p.b]} ones" + edit[ends.end():]
    return edit


def rewrite_moved(edit: str, schema: TaskSchema) -> tuple[str, str] | None:
    """"Move both of them to the back of the table" of a relation task: the relation kept, both
    cubes in that region (Modify).  Only for an edit that names both ("both", "them", "the pair",
    "everything"); "move it to the back" of two related cubes does not say which moves.  Returns
    the whole-task instruction and intent, or None."""
    rel = relation_of(schema)
    t = " " + edit.lower().strip().rstrip(".!") + " "
    if rel is None or not re.search(r"\b(?:both|them|they|pair|everything|all\s+of\s+it|whole\s+thing)\b", t):
        return None
    region = _edit_region(t)
    kinds = {a.name: a.kind for a in schema.assets}
    if region is None or "goal_patch" in (kinds[rel.subject], kinds[rel.object]):
        return None
    subject, obj = _phrase(schema, rel.subject), _phrase(schema, rel.object)
    first = f"Stack {subject} on {obj}" if rel.kind == "on" else f"Place {subject} {PHRASES[rel.kind]} {obj}"
    return f"{first}, then place {subject} {region_phrase(region)}, then place {obj} {region_phrase(region)}", "modify"


def _edit_relation(t: str) -> str | None:
    """The one relation an edit names (:data:`EDIT_RELATIONS`); with two ("from the left to the
    right"), the one after "from ... to", else None (which is not said)."""
    t = re.sub(r"\b(?:instead\s+of|rather\s+than|in\s+place\s+of)\b[^,;.]*", " ", t)  # "... instead of on top": the old one
    found = {}
    for pattern, k in EDIT_RELATIONS:
        m = re.search(pattern, t)
        if m and k not in found and not any(m.start() < e and s < m.end() for s, e in found.values()):
            found[k] = m.span()
    if len(found) <= 1:
        return next(iter(found), None)
    dest = re.search(r"\bfrom\b.*?\bto\b", t)
    after = [k for k, (start, _) in found.items() if dest and start >= dest.end() - 2]
    return after[0] if len(after) == 1 else None


def _added(t: str, schema: TaskSchema, rel: Relation) -> tuple[str, str] | None:
    """"Add a green block next to it": the reference's relation, then the new cube's."""
    m = re.search(NEW_CUBE + r"(.*)", t)
    if m is None:
        return None
    color, rest = canon_color(m.group(1)), m.group(2)
    if any(a.color == color for a in schema.assets):
        return None  # a second cube of a colour the task has: left to the whole-task reading
    kind = next((k for pattern, k in EDIT_RELATIONS if re.search(pattern, rest)), None)
    if kind is None or re.search(r"\b(?:both|each|all)\b", rest):
        return None  # "in front of both": a relation to two cubes at once is no one relation
    by_color = {a.color: a.name for a in schema.assets if a.kind == "colored_cube"}
    named = re.findall(rf"\bthe ({COLOR_RE})(?: (?:block|cube|one))?\b", rest)  # "on top of the red": the red cube
    if named:
        if named[0] not in by_color:
            return None
        target = by_color[named[0]]
    else:  # "it" of a two-cube stack is the stack, whose cube on the table is its lower one
        target = rel.object if rel.kind == "on" else rel.subject
    if rel.kind == "on" and target == rel.subject and kind != "on":
        raise SteerError(f"{_phrase(schema, rel.subject)} stands on {_phrase(schema, rel.object)}: a cube {PHRASES[kind]} it "
                         "would stand in the air; say where it goes relative to the stack's lower cube")
    first = (f"Place {_phrase(schema, rel.subject)} {PHRASES[rel.kind]} {_phrase(schema, rel.object)}"
             if rel.kind != "on" else f"Stack {_phrase(schema, rel.subject)} on {_phrase(schema, rel.object)}")
    if kind == "under" or (kind == "on" and rel.kind == "on"):
        return None  # growing a tower is the tower's own edit (its spec)
    return f"{first}, then place the {color} block {PHRASES[kind]} {_phrase(schema, target)}", "extend"


def _patch_task(schema: TaskSchema) -> tuple[list[str], str, str] | None:
    """(cube colours, patch colour, patch shape) of a task that puts coloured cubes on one
    goal patch; None for any other task."""
    goal = schema.goal_predicate()
    parts = goal.conjuncts()
    patches = [a for a in schema.assets if a.kind == "goal_patch"]
    if len(patches) != 1 or not parts or not all(isinstance(p, OnPatch) for p in parts):
        return None
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    if any(a.kind != "colored_cube" for a in cubes) or {p.a for p in parts} != {a.name for a in cubes}:
        return None
    return [a.color for a in cubes], patches[0].color, patches[0].shape


def rewrite_patch(edit: str, schema: TaskSchema) -> tuple[str, str] | None:
    """Edits of a cubes-on-a-patch task in its own terms: the patch's colour ("make the
    patch green") or shape ("make the patch long"), the number of cubes ("use three
    blocks", Tweak) or a named cube added ("add a yellow block", Extend).  Returns the
    whole-task instruction and the intent, or None."""
    task = _patch_task(schema)
    if task is None:
        return None
    colors, pcolor, shape = task
    t = " " + edit.lower().strip().rstrip(".!") + " "
    region = _edit_region(t)
    off = re.sub(r"\b(?:take|get|move|lift)\s+it\s+off\s+(?:of\s+)?the\s+(?:(?:goal|target)\s+)?patch\s+(?:and\s+)?", " ", t)
    if (region is not None and len(colors) == 1 and re.search(r"\b(?:move|put|place|shift|slide|bring|it)\b", off)
            and not re.search(r"\bpatch\b|\b(?:add|another|also|too)\b", off)):
        # "move it to the left side of the table instead", "take it off the patch and put it in the middle of the table"
        return f"Place the {colors[0]} block {region_phrase(region)}", "modify"
    moved = re.fullmatch(rf"\s*(?:(?:now|ok(?:ay)?|actually|and|then|just|hmm|nah|please)\s*,?\s+)*(?:move|put|place|shift|slide|bring|push)\s+"
                         rf"(?:it|the\s+(?:(?P<c>{COLOR_RE})\s+)?(?:cube|block|one))\s+(?:over\s+)?(?:to|onto|on|into)\s+(?:the|a)\s+"
                         rf"({COLOR_RE})\s+(?:goal\s+|target\s+)?patch\s*(?:instead|please)?\s*", t)
    if moved and moved.group("c") and canon_color(moved.group("c")) not in colors:
        return None  # "put the green cube on the yellow patch" of a red cube: another cube (the red one had been moved)
    if moved and len(colors) == 1 and canon_color(moved.group(2)) != pcolor:  # "move it to the yellow patch": that patch instead
        return f"Place the {colors[0]} block on the {canon_color(moved.group(2))} goal patch", "modify"
    intent = None
    t = re.sub(r"\btarget\b(?!\s+patch)", "patch", t)  # "make the target green"
    recolor = re.search(rf"\bpatch\b[^.;]*?\b(?:to|into|be|is)?\s*({COLOR_RE})\b|\b({COLOR_RE})\s+(?:goal\s+|target\s+)?patch\b", t)
    should = re.search(rf"\bpatch\s+(?:should|must|needs?\s+to|has\s+to|ought\s+to)\s+be\s+({COLOR_RE})\b", t)  # "the patch should be blue"
    if should or (recolor and re.search(r"\b(?:make|change|turn|use|paint|color|colour|switch)\b", t)):
        new = canon_color(should.group(1) if should else recolor.group(1) or recolor.group(2))
        said = {canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", t)}
        if should and not said <= {new, pcolor}:
            return None  # "the red patch should be green" of a yellow patch, "... and the cube green": more than the patch
        cube = re.search(rf"\b(?:cube|block|one)\s+(?:to\s+|into\s+|be\s+)?({COLOR_RE})\b(?!\s+(?:goal\s+)?patch)", t)
        if not said <= {new, pcolor} | set(colors):  # "make the cube green and the patch yellow": the cube's colour too
            if cube is None or len(colors) != 1 or not said <= {new, pcolor, canon_color(cube.group(1))} | set(colors):
                return None
            colors = [canon_color(cube.group(1))]
        if new != pcolor:
            pcolor, intent = new, "tweak"
    if re.search(r"\blong(?:er)?\b", t) and shape != "long":
        shape, intent = "long", "tweak"
    elif re.search(r"\b(?:square|short(?:er)?|small(?:er)?)\b", t) and shape != "square":
        shape, intent = "square", "tweak"
    count = re.search(rf"\b(\d+|{COUNT_WORD_RE})\s+(?:blocks|cubes)\b", t)  # "use one blocks instead": a count said alone
    added = re.search(rf"\badd\s+(?:an?|another|one more)\s+({COLOR_RE})\s+(?:block|cube)\b(?=\s*(?:(?:on|onto|to|in)\s+(?:the\s+"
                      rf"(?:(?:{COLOR_RE})\s+)?(?:goal\s+)?patch|it)\s*)?(?:too|as\s+well)?\s*$)", t) or \
        re.fullmatch(rf"\s*(?:and\s+|now\s+|also\s+)*(?:put\s+|place\s+)?(?:the|a|an)\s+({COLOR_RE})\s+(?:block|cube|one)\s+"
                     rf"(?:(?:on|onto|in)\s+(?:the\s+(?:{COLOR_RE}\s+)?(?:goal\s+)?patch|it)\s+)?(?:too|as well)\s*", t) or \
        re.fullmatch(rf"\s*(?:and\s+|now\s+)*(?:also\s+)?(?:put|place|move|bring|slide|push)\s+(?:the|a|an)\s+({COLOR_RE})\s+(?:block|cube|one)\s+"
                     rf"(?:on|onto|in)\s+(?:the\s+(?:{pcolor}\s+)?(?:goal\s+)?patch|it)\s*(?:too|as well)?\s*", t)
    more = re.fullmatch(rf"\s*(?:and\s+|now\s+|also\s+)*(?:add|put|place|bring)\s+(\d+|{COUNT_WORD_RE})\s+more\s+({COLOR_RE})\s+(?:blocks|cubes)"
                        rf"(?:\s+(?:on|onto|to|in)\s+(?:the\s+(?:{pcolor}\s+)?(?:goal\s+)?patch|it))?\s*(?:too|as\s+well)?\s*", t)
    if more:  # "add two more yellow cubes to the blue patch": that many more of the colour on the task's one patch
        k = NUMBER_WORDS.get(more.group(1)) or int(more.group(1))
        return f"Place {cube_list(colors + [canon_color(more.group(2))] * k)} onto the {pcolor}{' long' if shape == 'long' else ''} goal patch", "extend"
    if count:
        n = NUMBER_WORDS.get(count.group(1)) or int(count.group(1))
        if not 1 <= n <= 6:
            return None
        # cubes of one colour stay one colour ("2 blue cubes on the patch", "3 instead"); else new colours
        spare = [colors[0]] * n if len(set(colors)) == 1 else [c for c in DEFAULT_COLORS if c not in colors]
        colors, intent = (colors + spare)[:n] if n > len(colors) else colors[:n], "tweak"
    elif added:
        said = next(g for g in added.groups() if g)
        if canon_color(said) in colors and re.search(rf"\bthe\s+{re.escape(said)}\b", t) and not EDIT_ADDITIVE_RE.search(t):
            return None  # "put the pink cube on the orange patch" of a task whose pink cube stands there: that cube, not one more
        colors, intent = colors + [canon_color(said)], "extend"
    if intent is None:
        return None
    return f"Place {cube_list(colors)} onto the {pcolor}{' long' if shape == 'long' else ''} goal patch", intent


EDIT_REGION_RE = re.compile(
    r"\b(?:to|in|at|into|toward|towards|on|along)\s+the\s+(?:(?P<fb>front|back|rear|far|near)[\s-]+)?"
    r"(?P<lr>left|right|middle|center|centre)?(?:[\s-]*(?:hand\s+)?(?P<part>side|corner|half|edge|end|part))?\b")


_PLACE_SAID_RE = re.compile(r"(?<!from )(?<!of )\bthe\s+(?:far\s+)?(?P<fb>front|back|rear)(?:[\s-]+(?P<lr>left|right))?(?:\s+(?:corner|side|half|edge)"
                            r"|\s+(?=one\b)|(?=\s*(?:[.,;!]|$|and\b|of\s+the\s+(?:table|workspace)\b)))|(?<!from )(?<!of )\bthe\s+(?P<lr2>left|right)"
                            r"(?:\s+(?:side|half|edge)\b|(?=\s*(?:[.,;!]|$|and\b|of\s+the\s+(?:table|workspace)\b)))")
"""A place of the table said in an edit ("the back left corner", "the left side", "the back right one", "the back of the
table"), not one it leaves ("from the back left corner"): :func:`places_said`."""


def places_said(t: str) -> set[str]:
    """The places of the table an edit names as where something goes (:data:`_PLACE_SAID_RE`): more than one for one cube or
    one structure is two places at once ("move the red cube to the back left corner and the front left corner")."""
    return {region_name(m.group("fb"), m.group("lr") or m.group("lr2")) for m in _PLACE_SAID_RE.finditer(t.lower())}


def _edit_region(t: str) -> str | None:
    """The workspace region an edit names ("to the back left corner", "to the left side")."""
    for m in EDIT_REGION_RE.finditer(t):
        fb, lr = m.group("fb"), m.group("lr")
        if not (fb or lr) or (fb and not lr and not m.group("part") and not re.match(r"\s*of the (?:table|workspace)", t[m.end():])):
            continue
        if lr and not fb and not m.group("part") and re.match(r"\s*of\s+(?:it|them|that|this|the\s+(?!table\b|workspace\b)\w+)", t[m.end():]):
            continue  # "to the left of it": a relation to a cube, no side of the table
        return region_name(fb, lr)
    return None


def rewrite_region(edit: str, schema: TaskSchema) -> tuple[str, str] | None:
    """Edits of a task that puts coloured cubes in regions of the table ("place the red
    cube in the middle of the table"), in its own terms: another region ("move it to the
    back left corner", Modify), "swap them" (Modify), another colour for a one-cube task
    ("make it green", Tweak), or a cube added by a region or next to a cube ("add a blue
    block next to it", Extend).  Returns the whole-task instruction and intent, or None."""
    goal = schema.goal_predicate()
    parts = goal.conjuncts()
    if not parts or not all(isinstance(p, InRegion) for p in parts):
        return None
    assets = {a.name: a for a in schema.assets}
    if any(assets[p.a].kind != "colored_cube" for p in parts) or len({p.a for p in parts}) != len(parts):
        return None
    placed = [(assets[p.a].color, p.region) for p in parts]
    if len({c for c, _ in placed}) != len(placed):
        return None  # two cubes of one colour cannot be told apart by name in an edit or a clause
    t = " " + edit.lower().strip().rstrip(".!") + " "
    region = _edit_region(t)
    bare = re.fullmatch(r"\s*(?:(?:now|ok(?:ay)?|actually|rather|no|nah|wait|sorry|hmm)[\s,]+)*(?:the\s+)?((?:far\s+)?(?:front|back|rear|left|right"
                        r"|middle|center|centre)[a-z\s-]*?)(?:\s+(?:instead|please|now|then))*\s*", t)
    if region is None and bare:  # "now the right side", "nah right side": the place alone
        region = _edit_region(f" to the {bare.group(1)} ")
    added = re.search(rf"\b(?:add|put|place)\s+(?:an?|another|one more)\s+({COLOR_RE})\s+(?:block|cube)\b(.*)", t) or (
        EDIT_ADDITIVE_RE.search(t) and re.search(NEW_CUBE + r"(.*\b(?:front|back|rear|corner|half|side|edge|center|centre|middle"
                                                 r"|table|workspace)\b.*)", t))
    # "now a green one too, in the front right": a cube the edit brings in, as well, at a place of the table (a bare
    # "on the right" may be the red cube's right: left to the checks below)
    named = [canon_color(c) for c in re.findall(rf"\bthe ({COLOR_RE}) (?:block|cube|one)\b", t)]
    colors = [c for c, _ in placed]
    extra = ""
    if added:
        color, rest = canon_color(added.group(1)), added.group(2)
        if color in colors:
            return None
        where = _edit_region(rest)
        rel = next((k for pattern, k in EDIT_RELATIONS if re.search(pattern, rest)), None)
        if where:
            placed.append((color, where))
        elif rel in PHRASES and rel != "on":
            target = next((c for c in named if c in colors), colors[0]) if (named or len(colors) == 1) else None
            if target is None:
                return None
            extra = f", then place the {color} block {PHRASES[rel]} the {target} block"
        else:
            return None
        intent = "extend"
    elif re.search(r"\b(?:swap|switch|exchange|trade)\b|^\s*reverse\s+the\s+order\s*$|" + FLIPPED, t) and len(placed) == 2:
        placed = [(placed[0][0], placed[1][1]), (placed[1][0], placed[0][1])]
        intent = "modify"
    elif region is not None and named and not set(named) & set(colors):  # a cube the task does not have
        if len(set(named)) != 1 or not (EDIT_ADDITIVE_RE.search(t) or re.match(r"\s*and\b", t)):
            return None  # "put the blue block in the corner": instead of the red one, or as well? (read elsewhere)
        placed.append((named[0], region))  # "and the blue block in the front right corner": one more cube
        intent = "extend"
    elif (onto := re.search(rf"\b(?:on|onto)\s+(?:an?|the)\s+({COLOR_RE})\s+(?:goal\s+)?patch\b", t)) and len(placed) == 1 \
            and not EDIT_ADDITIVE_RE.search(t) and not re.match(r"\s*and\b", t) \
            and not set(named) - {placed[0][0]}:  # "put it on a purple patch instead": from a place on the table to a patch
        return f"Place the {placed[0][0]} block on the {canon_color(onto.group(1))} goal patch", "modify"
    elif region is not None:
        if re.search(rf"\b(?:an?|another|one\s+more)\s+(?:(?:{COLOR_RE})\s+)?(?:block|cube)\b", t):
            return None  # "also a red block in the front right corner": one more cube, not this one moved
        if re.search(r"\b(?:next\s+to|beside|each\s+other|one\s+another|apart|touch\w*|together|left\s+of|right\s+of|behind"
                     r"|in\s+front|on\s+top|under\w*|below|above|between|stack\w*|row|line|tower|side\s+by\s+side|adjacent|contact"
                     r"|first|last|order\w*|close|near\w*|far)\b", t) and re.search(r"\b(?:both|them|all|they)\b", t):
            return None  # "put them both in the center, next to each other": a relation too (it had been dropped)
        which = [i for i, (c, _) in enumerate(placed) if c in named] or ([0] if len(placed) == 1 else [])
        if not named and len(placed) > 1 and re.search(r"\b(?:both|them|all|everything|each\s+of\s+them)\b", t) \
                and any(r != region for _, r in placed):  # "move both to the left side": every cube of the task there
            return ", then ".join(f"place the {c} block {region_phrase(region)}" for c, _ in placed).capitalize(), "modify"
        if len(which) != 1 or placed[which[0]][1] == region or len(places_said(t) | {region}) > 1:
            return None  # (one cube "also in the front left corner, and stay in the back right one" had been moved)
        placed[which[0]] = (placed[which[0]][0], region)
        intent = "modify"
    else:
        recolor = re.search(rf"\b(?:make|turn|change|paint|color|colour)\b.*\b({COLOR_RE})\b", t)
        if not recolor or len(placed) != 1 or canon_color(recolor.group(1)) == placed[0][0]:
            return None
        placed, intent = [(canon_color(recolor.group(1)), placed[0][1])], "tweak"
    clauses = [f"place the {c} block {region_phrase(r)}" for c, r in placed]
    text = ", then ".join(clauses) + extra
    return text[0].upper() + text[1:], intent


def _clause(schema: TaskSchema, p: Predicate) -> str | None:
    """One conjunct of a relational task as a clause the parser reads back, or None."""
    patches = {a.name: a.color or "gray" for a in schema.assets if a.kind == "goal_patch"}
    if p.name in PHRASES and hasattr(p, "b"):
        return f"place {_phrase(schema, p.a)} {PHRASES[p.name]} {_phrase(schema, p.b)}"
    if isinstance(p, InRegion):
        return f"place {_phrase(schema, p.a)} {region_phrase(p.region)}"
    if type(p) is OnPatch and p.patch in patches:
        return f"place {_phrase(schema, p.a)} on the {patches[p.patch]} patch"
    return None


def remove_cubes(edit: str, schema: TaskSchema, colors: list[str], parse) -> tuple[str, TaskSchema] | None:
    """A relational task (relations, regions, patches) with the cubes of ``colors`` taken away
    ("get rid of the green block"): every conjunct about them is dropped, the rest kept and
    stated again.  None when the task is not made of such conjuncts.

    Raises:
        SteerError: a colour names no one cube of the task, or nothing would be left.
    """
    from rpg.schema.meaning import meaning

    parts = schema.goal_predicate().conjuncts()
    cubes = [a for a in schema.assets if a.kind == "colored_cube" and a.color in colors]
    if sorted({a.color for a in cubes}) != sorted(set(colors)) or len(cubes) != len(set(colors)):
        raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": each colour it removes must name one cube of the "
                         "task; name the cube to remove")
    gone = {a.name for a in cubes}
    kept = [p for p in parts if not set(p.object_names()) & gone]
    patches = {a.name for a in schema.assets if a.kind == "goal_patch"}  # (a patch left with no cube is dropped)
    stranded = sorted({n for p in parts if set(p.object_names()) & gone for n in p.object_names()}
                      - gone - patches - {n for p in kept for n in p.object_names()})
    if stranded:  # "get rid of the yellow cube" of "green left of yellow": green would be left with no goal (it had vanished)
        raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": without the {', '.join(sorted(set(colors)))} cube, "
                         f"{', '.join(stranded)} would have no goal left; say what becomes of it, or state the whole new task")
    clauses = [_clause(schema, p) for p in kept]
    if any(c is None for c in clauses) or len(kept) == len(parts):
        return None
    if not clauses:
        raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": without the {', '.join(sorted(set(colors)))} cube "
                         "the task has no goal left; state the whole new task in the edit")
    text = ", then ".join(clauses)
    text = text[0].upper() + text[1:]
    try:
        new = parse(text)
    except BadInput as exc:
        raise SteerError(str(exc).splitlines()[0]) from None
    names = {a.color for a in cubes}
    want = []
    for atom in meaning(schema):
        grouped = re.fullmatch(r"on_patch\((.*),(patch:\w+)\)", atom)  # "on_patch(cyan,pink,patch:yellow)": one atom per patch
        if grouped:
            left = [c for c in grouped.group(1).split(",") if c not in names]
            want += [f"on_patch({','.join(left)},{grouped.group(2)})"] if left else []
        elif not set(re.findall(r"[a-z]+", atom)) & names:
            want.append(atom)
    want.sort()
    if sorted(meaning(new)) != want:
        return None
    return text, new


def per_cube(atoms: list[str]) -> list[str]:
    """Meaning atoms with the cubes of one patch split apart (``on_patch(blue,red,patch:green)``
    is ``on_patch(blue,patch:green)`` and ``on_patch(red,patch:green)``), so that a cube added
    to a task's patch keeps the atom of the cube already there."""
    out = []
    for a in atoms:
        m = re.fullmatch(r"on_patch\(([^()]*),(patch:[^(),]+)\)(@\w+)?", a)
        out += ([f"on_patch({c},{m.group(2)}){m.group(3) or ''}" for c in m.group(1).split(",")] if m else [a])
    return out


def _conjunct_clause(schema: TaskSchema, p: Predicate) -> str | None:
    """A conjunct as a clause the parser reads back (:func:`_clause`), a two-cube stack among them ("place the blue
    block on top of the green block"); None for any other."""
    if isinstance(p, Stack) and len(p.objects) == 2:
        return f"place {_phrase(schema, p.objects[1])} on top of {_phrase(schema, p.objects[0])}"
    return _clause(schema, p)


def replaced_placement(clause: str, schema: TaskSchema, parse) -> tuple[str, TaskSchema] | None:
    """A relational task with the placement of one cube said again "instead" (``clause``, "put the red cube to the right of
    the green cube" of "... and the red cube to the left of the green cube"): the task's instruction written anew, clause by
    clause, with that cube's one old placement (the atom relating the same two things, or else its one placement of the
    same kind: its patch, its region) replaced by the new one, and the schema it reads as; None unless the clause reads as
    one placement, exactly one old atom is replaced, every other conjunct has a clause, and the new task's meaning is the
    old one with that one atom exchanged (checked, so nothing else is lost or added)."""
    from collections import Counter

    from rpg.schema.meaning import meaning

    try:
        said = meaning(parse(clause))
    except (BadInput, ValueError):
        return None
    old = per_cube(meaning(schema))  # cubes on one patch one atom each, so one of them can move
    said = per_cube(said)
    if not said or any(a in old for a in said):
        return None
    replaced: list[str] = []
    for new in said:
        pair = re.fullmatch(r"[a-z_]+(?:\[[^\]]*\])?\(([^(),;|]+),([^(),;|]+)\)", new)
        if pair is None:
            return None
        kind = new.split("(")[0]
        same_pair = [a for a in old if (m := re.fullmatch(r"[a-z_]+(?:\[[^\]]*\])?\(([^(),;|]+),([^(),;|]+)\)(?:@\w+)?", a))
                     and {m.group(1), m.group(2)} == {pair.group(1), pair.group(2)}]
        same_kind = [a for a in old if a.startswith(f"{kind}({pair.group(1)},")] if kind in ("on_patch", "in_region") else []
        mover = pair.group(2) if kind == "stack" else pair.group(1)  # a stack's atom names its bottom first: the cube put on
        # it is the one placed ("a brown cube on the gray cube instead" had replaced the gray cube's corner)
        subject = [a for a in old if (m := re.fullmatch(r"(?:left_of|right_of|in_front_of|behind|next_to|far_from|near|on_patch"
                                                        r"|in_region)\(([^(),;|]+),[^();|]+\)(?:@\w+)?", a)) and m.group(1) == mover]
        # else the one placement the cube has of its own ("the black one on a blue patch instead" of "black far from white");
        # a clause of several placements ("move the cyan cube to the front left corner, next to the brown one") replaces
        # only an atom of the same pair or the same kind, and adds the others
        found = same_pair or same_kind or (subject if len(said) == 1 else [])
        if len(found) > 1:
            return None
        replaced += found
    if len(replaced) != 1:
        return None
    if len(said) > 1:  # one cube moved: its one place replaced, every other atom a relation of that cube to another (two
        # cubes moved in one clause had kept the second cube's old place beside its new one)
        place = re.fullmatch(r"(?:on_patch|in_region)\(([^(),;|]+),[^();|]+\)(?:@\w+)?", replaced[0])
        if place is None:
            return None
        mover = place.group(1)
        for a in said:
            kind, args = a.split("(", 1)
            if kind in ("on_patch", "in_region") and not args.startswith(f"{mover},"):
                return None  # another cube's place
            if mover not in re.findall(r"[^(),;|]+", args):
                return None  # a relation of two other cubes
    goal = schema.goal_predicate().conjuncts()
    clauses = [_conjunct_clause(schema, p) for p in goal]
    if any(c is None for c in clauses) or len(clauses) != len(old):
        return None
    kept = []
    for c in clauses:
        try:
            alone = meaning(parse(c))
        except (BadInput, ValueError):
            return None
        if per_cube(alone) != [replaced[0]]:
            kept.append(c)
    if len(kept) != len(clauses) - 1:
        return None
    text = ", then ".join([*kept, clause])
    text = text[0].upper() + text[1:]
    try:
        made = parse(text)
    except (BadInput, ValueError):
        return None
    if Counter(per_cube(meaning(made))) != Counter(old) - Counter(replaced) + Counter(said):
        return None
    return text, made

