"""Reverse accounting: every constraint of a task's goal G cites the words that demand it.

Mention accounting (:mod:`rpg.schema.accounting`) checks one direction: nothing the
instruction says is dropped.  This module checks the other: nothing G demands was left
unsaid.  Each predicate declares what it demands, part by part
(:meth:`rpg.domain.predicates.Predicate.constraints`: the structure or relation itself, how
many cubes it holds, which cubes take part, an order or roles, a place); this module turns
those into :class:`Constraint` objects over what a person calls each object (its colour,
label, or ``patch:<colour>``) and finds, for each, the mention(s) of the instruction that
demand it:

- a **structure** cites the structure or relation word mention accounting consumed for it,
  else a word of the predicate class's ``cue``;
- a **count** cites a count ("3 blocks", "a tower of 3"), or the colours of its cubes when it
  holds every cube of them ("the red blocks");
- an **identity** (which cube: "cube colour: red") cites the colour, label or patch named;
- an **order** (roles or a sequence: "the order red under blue") cites the names of both
  cubes and a word that orders them ("on", "left of", "then", "bottom"...), or a word
  that fixes an order of its own ("rainbow", "alphabetical");
- a **place** cites the place or patch named.

Demands the scene makes anyway are *vacuous* and need no mention: which cubes take part and
how many, when a structure takes every cube of the task ("stack two blocks": there are
two).  The builtin parser (:func:`enforce`) drops a constraint nobody stated where the
predicate has a weaker form that accepts every configuration the words allow
(:meth:`~rpg.domain.predicates.Predicate.relax`: an ordered stack becomes an
:class:`~rpg.domain.predicates.UnorderedStack`, an ordered line an unordered one) and
otherwise refuses, naming the constraint.  ``task.yaml`` records the result under
``citations`` (:func:`citations`).

For the evaluation: :func:`unstated` lists the constraints of G that another text (a
paraphrase, a canonical description) does not state; :func:`canonical_instruction` writes a
text from G that states exactly its constraints; :func:`stating_paraphrases` completes a
task's paraphrases (the compiler calls it before each code generation) so that each states G.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field

from rpg.domain import predicates as P
from rpg.domain.constants import REGION_GROUPS
from rpg.errors import BadInput
from rpg.schema.meaning import descriptor
from rpg.schema.model import TaskSchema

ORDER_CUE = re.compile(
    r"\b(?:on|onto|upon|atop|above|over|under|below|beneath|underneath|top|peak|apex|tip|summit|bottom|base|first|second|third|then|"
    r"last|next|finally|after|before|order\w*|sequence|from|higher|lower|left|right|front|behind|back|between|"
    r"middle|center|centre|rainbow|gradient|alternat\w*|alphabet\w*|sort\w*|ascending|descending|increasing|"
    r"decreasing|reverse\w*|followed|ending|starting|beginning|end|start|begin)\b")
"""Words that give named cubes places in an order or in roles."""

SELF_ORDERING = re.compile(r"\b(?:rainbow|gradient|alternat\w*|alphabet\w*|sort\w*|ascending|descending|"
                           r"increasing|decreasing|reverse\w*|swap\w*|switch\w*|spell\w*|words?|equation|reads?|reading)\b")
"""Words that fix an order of their own, without naming each cube's place ("so they read KATE", "swap them": the start's
order reversed)."""

ROLE_CUES = {
    "bottom": re.compile(r"\b(?:bottom|base|lowest|bottommost|foundation|start\w*|begin\w*)\b"),
    "top": re.compile(r"\b(?:top|topmost|highest|uppermost|peak|apex|tip|summit|end\w*|finish\w*)\b"),
}
"""Words that put a cube at an end of a stack (:class:`~rpg.domain.predicates.AnchoredStack`)."""

LINE_END_CUES = {
    "left_end": re.compile(r"\b(?:left(?:[\s-]+hand)?\s+end|far\s+left|leftmost)\b"),
    "right_end": re.compile(r"\b(?:right(?:[\s-]+hand)?\s+end|far\s+right|rightmost)\b"),
}
"""Words that put a cube at an end of a left-right line (:class:`~rpg.domain.predicates.AnchoredLine`)."""

TEMPORAL_CUE = re.compile(r"\b(?:then|first|after|afterwards|before|finally|next|once|later|second|last)\b")

TABLE_CUE = re.compile(r"\b(?:table|unstack\w*|off|remov\w*|down|ground|floor)\b")

MATCH_CUE = re.compile(r"\b(?:match\w*|same\s+colou?r|corresponding|respective\w*|colou?r-specific|its\s+own)\b")
"""Words that give each cube the patch of its own colour."""

PATCH_CUE = re.compile(r"\b(?:patch\w*|pads?|mats?|markers?|spots?|zones?|areas?|targets?|goals?)\b")


REGION_WORDS = {"left": r"\b(?:left|west)\b", "right": r"\b(?:right|east)\b", "front": r"\b(?:front|south|near)\b",
                "back": r"\b(?:back|behind|rear|far|north)\b", "center": r"\b(?:center|centre|middle)\b",
                "corner": r"\bcorners?\b", "edge": r"\bedges?\b"}
"""A part of a region's name -> words that name it (a side said without "of the table")."""


class UncitedConstraint(BadInput):
    """The goal demands something the instruction does not say, and no weaker goal exists."""


@dataclass(frozen=True)
class Constraint:
    """One demand of G over what a person calls the objects.

    Attributes:
        kind: ``structure``, ``count``, ``identity``, ``order`` or ``place``.
        key: comparable across tasks (descriptors, not object names).
        line: one human-readable line ("the order red under blue", "cube colour: red").
        sentence: a sentence of the canonical instruction that states it.
        leaf: the predicate it comes from (for :meth:`~rpg.domain.predicates.Predicate.relax`).
        names: the objects it concerns.
        vacuous: the scene makes it hold whatever the words (a structure of every cube).
    """

    kind: str
    key: tuple
    line: str
    sentence: str
    leaf: P.Predicate = field(compare=False, repr=False)
    names: tuple[str, ...] = ()
    vacuous: bool = False


# ---------------------------------------------------------------------------
# G -> constraints
# ---------------------------------------------------------------------------


def _phrase(desc: str) -> str:
    """'red' -> 'the red cube', 'A' -> 'the A cube', 'patch:green' -> 'the green patch'."""
    if desc.startswith("patch:"):
        return f"the {desc[6:]} patch"
    return f"the {desc} cube"


def _identity_line(desc: str) -> str:
    if desc.startswith("patch:"):
        return f"goal patch: {desc[6:]}"
    return f"cube label: {desc}" if len(desc) == 1 else f"cube colour: {desc}"


_ORDER_WORDS = {"on": "under", "left_of": "left of", "right_of": "right of", "in_front_of": "in front of",
                "behind": "behind", "between": "between"}


def _normal_form(goal: P.Predicate) -> Counter:
    """G as a multiset of its leaves' constraints, object sets unordered (for swap tests)."""
    def norm(v):
        if isinstance(v, P.Predicate):
            return v.describe()
        if isinstance(v, tuple) and v and all(isinstance(x, str) for x in v):
            return frozenset(v)
        if isinstance(v, tuple):
            return tuple(norm(x) for x in v)
        return v

    out = Counter()
    for leaf in _leaves(goal):
        parts = []
        for kind, fields in leaf.constraints():
            if kind == "order":
                continue  # roles and sequences are order constraints of their own
            items = tuple(sorted((k, norm(v)) for k, v in fields.items()))
            parts.append((kind, items))
        if parts:
            out[frozenset(parts)] += 1
    return out


class _Scene:
    """What the task holds: descriptors and cubes, and which cubes' identities G cares about."""

    def __init__(self, schema: TaskSchema):
        self.desc = {a.name: descriptor(a) for a in schema.assets}
        self.cubes = frozenset(a.name for a in schema.assets if a.kind != "goal_patch")
        self.goal = schema.goal_predicate()
        self._free: dict[str, bool] = {}

    def identity_free(self, desc: str) -> bool:
        """Whether G holds the same after swapping any cube of ``desc`` with any cube of another
        descriptor: then which cube is which does not matter ("both blocks onto the patch")."""
        if desc not in self._free:
            base = _normal_form(self.goal)
            mine = sorted(n for n in self.cubes if self.desc[n] == desc)
            others = sorted(n for n in self.cubes if self.desc[n] != desc)
            self._free[desc] = all(_normal_form(self.goal.rename({x: y, y: x})) == base
                                   for x in mine[:1] for y in others)
        return self._free[desc]

    def d(self, name: str) -> str:
        return self.desc.get(name, name)

    def by_desc(self, desc: str) -> set[str]:
        return {n for n in self.cubes if self.desc[n] == desc}


def _structure(leaf, fields, scene) -> list[Constraint]:
    pred = fields["predicate"]
    params = tuple(sorted((k, v) for k, v in fields.items() if k != "predicate"))
    extra = ", ".join(f"{k} {v}" for k, v in params if v is not None)
    words = pred.replace("_", " ")
    line = f"a {words}" + (f" ({extra})" if extra else "")
    return [Constraint("structure", ("structure", pred, params), line, f"The goal is {line}.", leaf,
                       tuple(leaf.object_names()))]


def _count(leaf, fields, scene) -> list[Constraint]:
    objs = tuple(n for n in fields["objects"] if n in scene.cubes)
    if not objs:
        return []
    n, pred = len(objs), fields["predicate"].replace("_", " ")
    line = f"{n} cubes in the {pred}"
    return [Constraint("count", ("count", fields["predicate"], n), line, f"Use {n} cubes for the {pred}.", leaf, objs,
                       vacuous=set(objs) >= scene.cubes)]


def _members(leaf, fields, scene) -> list[Constraint]:
    objs = tuple(n for n in fields["objects"] if n in scene.cubes)
    out = []
    for desc in dict.fromkeys(scene.d(n) for n in objs):
        out.append(Constraint("identity", ("identity", desc), _identity_line(desc), f"Use {_phrase(desc)}.", leaf,
                              tuple(n for n in objs if scene.d(n) == desc), scene.identity_free(desc)))
    return out


def _order(leaf, fields, scene) -> list[Constraint]:
    rel = fields["relation"]
    if rel == "temporal":
        events = [e.rename(scene.desc).describe() for e in fields["events"]]
        line = "first " + ", then ".join(events)
        return [Constraint("order", ("order", "temporal", tuple(events)), f"the order in time: {line}",
                           line[0].upper() + line[1:] + ".", leaf, tuple(leaf.object_names()))]
    if rel == "layer":  # a cube's layer in a structure, counted from the table
        out = []
        for name, k in fields["pairs"]:
            dx, where = scene.d(name), "on the table" if k == "0" else f"in layer {k} above the table"
            out.append(Constraint("order", ("order", "layer", (dx, k)), f"{dx} {where} in the structure",
                                  f"Put {_phrase(dx)} {where} in the structure.", leaf, (name,)))
        return out
    if rel in LINE_END_CUES:  # an end of a left-right line
        dx, where = scene.d(fields["pairs"][0][0]), rel.replace("_", " ")
        return [Constraint("order", ("order", rel, (dx,)), f"{dx} at the {where} of the line",
                           f"Put {_phrase(dx)} at the {where} of the line.", leaf, (fields["pairs"][0][0],))]
    if rel in ROLE_CUES:  # an end of a stack
        dx = scene.d(fields["pairs"][0][0])
        where = "at the bottom" if rel == "bottom" else "on top"
        return [Constraint("order", ("order", rel, (dx,)), f"{dx} {where} of the stack",
                           f"Put {_phrase(dx)} {where} of the stack.", leaf, (fields["pairs"][0][0],))]
    out = []
    for x, y in fields["pairs"]:
        dx, dy = scene.d(x), scene.d(y)
        if dx == dy:
            continue  # interchangeable cubes: no order between them
        if rel == "on":
            line, sentence = f"the order {dy} under {dx}", f"Put {_phrase(dx)} on top of {_phrase(dy)}."
        elif rel in _ORDER_WORDS:
            words = _ORDER_WORDS[rel]
            line, sentence = f"the order {dx} {words} {dy}", f"Put {_phrase(dx)} {words} {_phrase(dy)}."
        else:
            words = rel.replace("_", " ")
            line, sentence = f"the order {dx} before {dy} ({words})", f"Put {_phrase(dx)} before {_phrase(dy)}, {words}."
        out.append(Constraint("order", ("order", rel, (dx, dy)), line, sentence, leaf, (x, y)))
    return out


def _place(leaf, fields, scene) -> list[Constraint]:
    a = fields["object"]
    where = scene.d(fields["patch"]) if "patch" in fields else fields["region"]
    if isinstance(a, tuple):  # a stack, whichever of its cubes is at the bottom; or a structure's middle (centred_in)
        descs = ", ".join(sorted(scene.d(n) for n in a))
        whole = "middle" if getattr(leaf, "name", "") == "centred_in" else "stack"
        who, subject, names = f"{whole}:{descs}", f"the {whole} of {descs}", a
    else:
        who, subject, names = scene.d(a), _phrase(scene.d(a)), (a,)
    if where == "table":
        line, sentence = f"{subject.removeprefix('the ')} on the table", f"Put {subject} on the table."
    elif where.startswith("patch:"):
        line, sentence = f"{subject.removeprefix('the ')} on {_phrase(where)}", f"Put {subject} on {_phrase(where)}."
    else:
        w = ("an " if where[0] in "aeiou" else "a ") + where if where in REGION_GROUPS else "the " + where.replace("_", " ")
        line = f"{subject.removeprefix('the ')} in {w} of the table"
        sentence = f"Put {subject} in {w} of the table."
    return [Constraint("place", ("place", who, where), line, sentence, leaf, names)]


CONVERTERS: dict[str, Callable] = {"structure": _structure, "count": _count, "members": _members,
                                   "order": _order, "place": _place}
"""Constraint kind declared by a predicate -> its conversion to :class:`Constraint` objects."""


def _leaves(goal: P.Predicate):
    """Every predicate of G whose constraints speak for it (composites, and not below a negation)."""
    yield goal
    if not goal.opaque:
        for c in goal.children():
            yield from _leaves(c)


def goal_constraints(schema: TaskSchema) -> list[Constraint]:
    """The constraints of the task's G, in goal order (vacuous ones included, flagged)."""
    scene = _Scene(schema)
    out = []
    for leaf in _leaves(schema.goal_predicate()):
        for kind, fields in leaf.constraints():
            out.extend(CONVERTERS[kind](leaf, fields, scene))
    return out


# ---------------------------------------------------------------------------
# constraints -> the mentions that demand them
# ---------------------------------------------------------------------------


@dataclass
class _Reading:
    """An instruction as mention accounting read it against a schema."""

    text: str  # normalised, places as @region_ tokens
    record: list[dict]
    scene: _Scene

    def named(self, desc: str) -> str | None:
        """The mention that names a colour, label or patch, or None."""
        if desc.startswith("patch:"):
            color = desc[6:]
            hit = next((r for r in self.record if r["kind"] == "patch" and r["consumed_by"] == f"goal patch {color}"), None)
            return hit["mention"] if hit else None
        hit = next((r for r in self.record if r["kind"] in ("color", "label") and str(r["mention"]) == desc), None)
        return str(hit["mention"]) if hit else None

    def determined(self, desc: str) -> str | None:
        """The mention that picks out cubes of ``desc``: their name, or "the other cube(s)"
        when every cube not named has this descriptor."""
        named = self.named(desc)
        if named:
            return named
        unnamed = {self.scene.d(n) for n in self.scene.cubes if not self.named(self.scene.d(n))}
        return "the other cube(s)" if unnamed == {desc} else None

    def identified(self, desc: str) -> str | None:
        """The mention that fixes which cube of ``desc`` is meant: its name, or "matching
        colour" when a goal patch of that colour is in the task."""
        named = self.named(desc)
        if named:
            return named
        if f"patch:{desc}" in self.scene.desc.values():
            return self.cue(MATCH_CUE)
        return None

    def equal_split(self, n: int) -> bool:
        """Whether G's stacks all hold ``n`` cubes and together every cube of the task."""
        stacks = [p for p in _leaves(self.scene.goal) if isinstance(p, P.Stack)]
        return (len(stacks) > 1 and all(len(p.objects) == n for p in stacks)
                and {o for p in stacks for o in p.objects} >= self.scene.cubes)

    def cue(self, pattern: str | re.Pattern) -> str | None:
        m = re.search(pattern, self.text) if pattern else None
        return m.group(0) if m else None

    def member(self, name: str, other: str) -> str | None:
        """The mention of a structure of G that ``name`` is one of and ``other`` is not ("a
        tower of three blocks to the left of the green block": each cube of the tower is left
        of it), or None."""
        for leaf in _leaves(self.scene.goal):
            if name in leaf.object_names() and other not in leaf.object_names() \
                    and any(k == "structure" for k, _ in leaf.constraints()) \
                    and len(leaf.object_names()) > 1 and not leaf.object_fields:
                hit = next((x["mention"] for x in self.record if x["kind"] == "structure"
                            and str(x["consumed_by"]).split(", ")[0] in
                            {sub.name for sub in type(leaf).__mro__ if "name" in vars(sub)}), None)
                if hit:
                    return hit
        return None


def _cite_structure(c: Constraint, r: _Reading) -> list[str]:
    pred = c.key[1]
    names = {pred} | {sub.name for sub in type(c.leaf).__mro__ if "name" in vars(sub)}
    hits = [x["mention"] for x in r.record if x["kind"] in ("structure", "relation")
            and names & set(str(x["consumed_by"]).split(", "))]
    if hits:
        return hits
    cls = P.PREDICATES.get(pred, type(c.leaf))
    word = r.cue(cls.cue or type(c.leaf).cue)
    return [word] if word else []


def _cite_count(c: Constraint, r: _Reading) -> list[str]:
    n = c.key[2]
    hits = [x["mention"] for x in r.record if x["kind"] == "count" and re.search(rf"(?<!\d){n}(?!\d)", str(x["mention"]))]
    if hits:
        return hits[:1]
    descs = {r.scene.d(x) for x in c.names}
    towers = [x["mention"] for x in r.record if x["kind"] == "towers"]
    if towers and c.key[1] == "stack" and r.equal_split(c.key[2]):  # "make two stacks of red blocks"
        return [f"{towers[0]} (equal heights: a convention, not said)"]
    once = Counter(r.scene.d(x) for x in c.names)
    if all(r.identified(d) for d in descs) and all(r.scene.by_desc(d) <= set(c.names) or once[d] == 1 for d in descs):
        return list(dict.fromkeys(r.identified(d) for d in sorted(descs)))  # "the red blocks": every cube of them
    return []


def _cite_identity(c: Constraint, r: _Reading) -> list[str]:
    hit = r.identified(c.key[1])
    return [hit] if hit else []


def _cite_order(c: Constraint, r: _Reading) -> list[str]:
    rel = c.key[1]
    if rel in ROLE_CUES or rel in LINE_END_CUES:
        who, word = r.determined(c.key[2][0]), r.cue({**ROLE_CUES, **LINE_END_CUES}[rel])
        return [who, word] if who and word else []
    if rel == "layer":
        who, word = r.determined(c.key[2][0]), r.cue(ORDER_CUE)
        return [who, word] if who and word else []
    if rel == "temporal":
        word = r.cue(TEMPORAL_CUE)
        return [word] if word else []
    own = r.cue(SELF_ORDERING)
    if own:
        return [own]
    pair = tuple(c.names)
    who = [r.determined(d) or (r.member(n, pair[1 - i]) if len(pair) == 2 else None)
           for i, (d, n) in enumerate(zip(c.key[2], pair, strict=True))]
    cls = P.PREDICATES.get(rel)
    word = (r.cue(cls.cue) if cls is not None and cls.cue else None) or r.cue(ORDER_CUE)
    if all(who) and word:
        return [*dict.fromkeys(who), word]
    return []


def _cite_place(c: Constraint, r: _Reading) -> list[str]:
    where = c.key[2]
    if where == "table":
        word = r.cue(TABLE_CUE)
        return [word] if word else []
    if where.startswith("patch:"):
        hit = r.named(where) or r.cue(PATCH_CUE)
        return [hit] if hit else []
    hits = [x["mention"] for x in r.record if x["kind"] == "place" and where in re.split(r"[\s,]+", str(x["consumed_by"]))]
    if hits:
        return hits[:1]
    words = [r.cue(REGION_WORDS[part]) for part in where.split("_")]  # "push the red block to the left"
    return [" ".join(words)] if all(words) else []


CITERS: dict[str, Callable[[Constraint, _Reading], list[str]]] = {
    "structure": _cite_structure, "count": _cite_count, "identity": _cite_identity,
    "order": _cite_order, "place": _cite_place}
"""Constraint kind -> the mentions that demand it (empty: none does)."""


def _goal_after_start(text: str) -> list[str]:
    """The goal's words of a text that says a start ("Initially all cubes are scattered on the table. Goal: ...";
    "Initially, the black cube is stacked on the white cube. Put the black cube to the left of ...": the start's
    mentions are the initial-scene reader's, the goal's words after them); empty where it says none."""
    from rpg.schema.readers.initial import split

    try:
        scene = split(text)
    except BadInput:
        return []
    return [scene.goal] if scene is not None and scene.goal else []


def _reading(schema: TaskSchema, text: str) -> _Reading:
    from rpg.schema import lexicon
    from rpg.schema.accounting import UnaccountedMention, check_mentions
    from rpg.schema.reading import mark_regions, normalize

    if schema.initial_state.structures:  # "Currently red is on blue. Put ...": the start read, the goal's words after it
        text = lexicon.SCENE_NOW_OPENING_RE.sub("", text, count=1)
        pattern, written = lexicon.START_COUNTED_TOWER_REWRITE  # "There's a two-block tower, orange under cyan.": as read
        text = pattern.sub(written, text)
    # "Data-collection script, line 12: put ...": the text after a task's identifier, as the parser reads it (its words had
    # been unaccounted, the places left uncited); "Initially all cubes are scattered. Goal: ...": the goal's words
    labelled = (m.group("body") for m in (lexicon.ID_LABEL_RE.match(text), lexicon.ID_WORDS_LABEL_RE.match(text)) if m)
    for said in (text, *labelled, *_goal_after_start(text)):
        try:
            record = check_mentions(said, schema)
            break
        except (UnaccountedMention, BadInput):
            record = []
    said = said if record else text
    try:
        norm = mark_regions(normalize(said, strict=False)[0])
    except BadInput:
        norm = said.lower()
    return _Reading(norm, record, _Scene(schema))


def cite(schema: TaskSchema, text: str | None = None) -> list[tuple[Constraint, list[str]]]:
    """Each constraint of G with the mentions of ``text`` (default: the task's instruction)
    that demand it; distinct constraints only, in goal order."""
    r = _reading(schema, schema.instruction if text is None else text)
    return [(c, CITERS[c.kind](c, r)) for c in _distinct_constraints(schema)]


def _distinct_constraints(schema: TaskSchema) -> list[Constraint]:
    """The distinct constraints of G (by key and vacuity), in goal order."""
    out, seen = [], set()
    for c in goal_constraints(schema):
        if (c.key, c.vacuous) not in seen:
            seen.add((c.key, c.vacuous))
            out.append(c)
    return out


def citations(schema: TaskSchema) -> list[dict]:
    """The ``citations`` record of ``task.yaml``: one ``{constraint, kind, cites}`` per
    constraint of G (``cites``: the mentions that demand it; a vacuous one with none cites
    ``the scene``, an uncited one, possible only for a goal written by a model or by hand,
    cites nothing)."""
    out = []
    for c, cites in cite(schema):
        if c.vacuous and not cites:
            cites = ["the scene"]
        out.append({"constraint": c.line, "kind": c.kind, "cites": cites})
    return out


def uncited(schema: TaskSchema, text: str | None = None) -> list[Constraint]:
    """The constraints of G that no mention of ``text`` (default: the instruction) demands."""
    return [c for c, cites in cite(schema, text) if not cites and not c.vacuous]


def _replace_leaf(goal: P.Predicate, old: P.Predicate, new: P.Predicate) -> P.Predicate:
    if goal is old:
        return new
    return goal.map_children(lambda ch: _replace_leaf(ch, old, new))


def _tied(leaf: P.Predicate, goal: P.Predicate) -> bool:
    """Whether another part of G relates one of ``leaf``'s cubes by itself ("the red block
    next to the tower": the tower's base), so weakening ``leaf`` would change what it names."""
    mine = set(leaf.object_names())
    return any(q is not leaf and mine & set(q.object_names())
               and not (q.swap_invariant and set(q.object_names()) >= mine)
               for q in _leaves(goal) if not q.children())


def _anchor(leaf: P.Predicate, reading: _Reading) -> tuple[P.Predicate, P.Predicate] | None:
    """(leaf, its weakened form) for an ordered stack of some named cubes and some nobody named: named
    cubes that all stand at its ends each keep their end (an anchored stack); named cubes elsewhere keep
    their levels (an unordered stack in layers); the order of the others is dropped. None otherwise."""
    if type(leaf) is not P.Stack or len(leaf.objects) < 3:
        return None
    objs = leaf.objects
    named = [i for i, n in enumerate(objs) if n in reading.scene.cubes and reading.named(reading.scene.d(n))]
    if not named or len(named) == len(objs):
        return None
    if any(0 < i < len(objs) - 1 for i in named):  # "four cubes with the two green ones at the bottom": the named
        # cubes keep their levels, the others stand anywhere above or between them
        levels = tuple(i if i in named else -1 for i in range(len(objs)))
        return leaf, P.And([P.UnorderedStack(objects=objs), P.InLayers(objects=objs, levels=levels)])
    return leaf, P.AnchoredStack(objects=objs, bottom=0 in named, top=len(objs) - 1 in named)


REFUSED_WHEN_UNCITED = frozenset({"order", "place", "count", "structure"})
"""Constraints of G that make the compile refuse when nobody stated them and they cannot be
weakened.  An identity ("cube colour: red") is recorded uncited instead: the scene's cubes are
the task's assets, so a goal over all of them asks nothing a policy could do otherwise."""


def invented_members(schema: TaskSchema) -> str | None:
    """Why a structure of G holds cubes nobody said, or None.

    A structure whose count no word states, whose named cubes are all counted by colour ("a
    wall with 2 white on the bottom and 1 black on top": three cubes said), but which holds
    further cubes of colours nobody said that G tells apart from the named ones: the reader
    filled the structure up to a default size with cubes of its own (content invented, issue
    30's class 6).  A default structure with a role said ("a tower with the blue block in the
    middle") counts nothing, so its other cubes are the domain's default, not an invention.
    """
    r = _reading(schema, schema.instruction)
    counted = {m.group(1) for x in r.record if x["kind"] == "count"
               for m in [re.match(r"\d+ (\S+) cubes$", str(x["consumed_by"]))] if m}
    by_leaf: dict[int, list[tuple[Constraint, list[str]]]] = {}
    for c in goal_constraints(schema):
        by_leaf.setdefault(id(c.leaf), []).append((c, CITERS[c.kind](c, r)))
    for cs in by_leaf.values():
        counts = [(c, cites) for c, cites in cs if c.kind == "count"]
        if not counts or any(cites for _, cites in counts):
            continue
        named = sorted({c.key[1] for c, cites in cs if c.kind == "identity" and cites})
        unsaid = sorted({c.key[1] for c, cites in cs if c.kind == "identity" and not cites and not c.vacuous})
        if named and unsaid and set(named) <= counted:
            c = counts[0][0]
            return (f"the goal it reads holds {c.line}, but the instruction counts only its "
                    f"{' and '.join(named)} cubes: {', '.join(unsaid)} would be cubes nobody asked for; "
                    "say how many cubes the structure has in all")
    return None


def enforce(schema: TaskSchema, refuse: bool = True,
            refuse_kinds: frozenset[str] = REFUSED_WHEN_UNCITED) -> TaskSchema:
    """``schema`` with every constraint nobody stated dropped (the predicate's weaker form).

    A leaf is only weakened when it names no cube the instruction names (weakening it must
    not drop a part that was said: "a tower three high with a yellow block on top" keeps its
    order, whose pairs this module cannot cite one by one).

    Args:
        refuse: raise on a constraint of ``refuse_kinds`` nobody stated that cannot be
            weakened; the others (and all, with ``False``) stay in G (``task.yaml``'s
            ``citations`` then shows them citing nothing).

    Raises:
        UncitedConstraint: a constraint nobody stated whose predicate has no weaker form
            (with ``refuse``), or a structure filled up with cubes nobody named
            (:func:`invented_members`, always); the message names it.
    """
    from rpg.schema.builder import make_paraphrases

    goal, changed = schema.goal_predicate(), False
    for _ in range(32):  # each pass relaxes at least one leaf
        current = schema.model_copy(update={"goal": goal}) if changed else schema
        missing = uncited(current)
        if not missing:
            break
        reading = _reading(current, current.instruction)
        for c in missing:
            leaves = dict.fromkeys(x.leaf for x in goal_constraints(current) if x.key == c.key)
            anchored = next((a for leaf in leaves if c.kind == "order" and (a := _anchor(leaf, reading)) is not None), None)
            if anchored is not None:  # the named cubes keep the ends they were given, the rest are free
                goal, changed = _replace_leaf(goal, *anchored), True
                break
            weaker = next(((leaf, w) for leaf in leaves
                           if (isinstance(leaf, P.AnchoredStack)
                               or not any(reading.named(reading.scene.d(n)) for n in leaf.object_names()
                                          if n in reading.scene.cubes))
                           and not (c.kind == "order" and _tied(leaf, goal))
                           and (w := leaf.relax(c.kind, goal)) is not None), None)
            if weaker is not None:
                goal, changed = _replace_leaf(goal, *weaker), True
                break
            if refuse and c.kind in refuse_kinds:
                raise UncitedConstraint(f"the goal it reads demands {c.line}, which the instruction does not say")
        else:
            break
    invented = invented_members(schema.model_copy(update={"goal": goal}) if changed else schema)
    if invented:  # cubes nobody named have no weaker form: refused whatever ``refuse`` says
        raise UncitedConstraint(invented)
    if not changed:
        return schema
    summary = "; ".join(p.describe() for p in goal.conjuncts())
    return schema.model_copy(update={"goal": goal, "goal_summary": summary, "paraphrases": make_paraphrases(summary)})


# ---------------------------------------------------------------------------
# for the evaluation: does a text state G?
# ---------------------------------------------------------------------------


def _sentences(text: str) -> set[str]:
    return {" ".join(s.lower().split()) for s in re.split(r"(?<=[.!?])\s+", text.strip()) if s.strip()}


def canonical_instruction(schema: TaskSchema) -> str:
    """A text generated from G that states exactly its constraints: one sentence per
    constraint that is not vacuous (a structure always), in goal order."""
    out = []
    for c in _distinct_constraints(schema):  # G alone: no text is read (an environment loads no lexicon)
        if c.vacuous and c.kind != "structure":
            continue
        if c.sentence not in out:
            out.append(c.sentence)
    return " ".join(out)


def _unstated(schema: TaskSchema, text: str) -> list[Constraint]:
    """The constraints of G that ``text`` does not state (see :func:`unstated`)."""
    from rpg.schema.builtin import parse

    stated: set[tuple] = set()
    try:
        other = parse(text)
    except (BadInput, ValueError):
        other = None
    if other is not None:
        stated = {c.key for c, cites in cite(other, text) if cites}
    sentences = _sentences(text)
    return [c for c in goal_constraints(schema)
            if not (c.vacuous or c.key in stated or " ".join(c.sentence.lower().split()) in sentences)]


def unstated(schema: TaskSchema, text: str) -> list[str]:
    """The constraints of the task's G that ``text`` does not state, one line each
    ("the order red under blue", "cube colour: red"); ``[]`` when it states all of G.

    ``text`` is read with the builtin parser and reverse accounting: a constraint of G is
    stated when the task read from ``text`` has the same constraint and a mention of
    ``text`` demands it, or when ``text`` holds the constraint's canonical sentence
    (:func:`canonical_instruction`).  Constraints the scene makes anyway (a structure of
    every cube needs no count) are not asked for.  A text the parser cannot read states
    only the canonical sentences it holds.
    """
    return list(dict.fromkeys(c.line for c in _unstated(schema, text)))


def _plain_names(text: str, schema: TaskSchema) -> str:
    """``text`` with the task's object names ("letter_a", "gray_patch") replaced by what a
    person calls them ("A", "the gray patch")."""
    words = {}
    for a in schema.assets:
        d = descriptor(a)
        words[a.name] = _phrase(d) if d.startswith("patch:") else d
    if not words:
        return text
    pattern = re.compile(r"\b(?:" + "|".join(re.escape(n) for n in sorted(words, key=len, reverse=True)) + r")\b")
    return pattern.sub(lambda m: words[m.group(0)], text)


def stating_paraphrases(schema: TaskSchema) -> tuple[TaskSchema, list[str]]:
    """``schema`` whose paraphrases each state G (:func:`unstated` finds nothing missing),
    and one log line per paraphrase that had to change.

    A paraphrase written from the goal summary (the builtin's) or by a model may use object
    names or leave out part of G; object names become what a person calls the objects and
    the canonical sentences of what is still missing are appended.  A policy sent any
    paraphrase (``rpg eval --instruction paraphrase:K``) is then told all it is scored on.
    The frames of :data:`rpg.schema.builder.PARAPHRASE_FRAMES` are read through.
    """
    from rpg.schema.builder import unframe

    out, log = [], []
    for k, text in enumerate(schema.paraphrases):
        plain = added = _plain_names(text, schema)
        for _ in range(4):  # the parser may read a longer text differently: check it again
            missing = [s for s in dict.fromkeys(c.sentence for c in _unstated(schema, unframe(plain)))
                       if s not in plain]
            if not missing:
                break
            plain = plain.rstrip()
            plain = (plain if plain.endswith((".", "!", "?")) else plain + ".") + " " + " ".join(missing)
        else:
            plain = f"{added.rstrip()} {canonical_instruction(schema)}"
        if plain != text:
            log.append(f"paraphrase {k}: " + ("completed with sentences of what G demands" if plain != added
                                              else "object names replaced by what they are called"))
        out.append(plain)
    if out == list(schema.paraphrases):
        return schema, log
    return schema.model_copy(update={"paraphrases": out}), log
