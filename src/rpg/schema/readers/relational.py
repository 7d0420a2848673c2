"""The relational reader: stacks, patches and pairwise relations between named cubes.

"put the red block on the blue block, and the green block left of it": each clause's
mentions and relation words (:data:`rpg.schema.lexicon.REL_PATTERNS`) are read into a
:class:`RelationalReading`, whose stacks, relations, patches and places are then laid out.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass, field, replace

from rpg.domain import constants as C
from rpg.domain.layouts import (
    stack_layout,
)
from rpg.domain.predicates import (
    PREDICATES,
    Between,
    FarFrom,
    InRegion,
    LeftOf,
    NextTo,
    OnPatch,
    OnTable,
    Stack,
)
from rpg.schema import lexicon
from rpg.schema.builder import DEFAULT_COLORS, DEFAULT_PATCH_COLOR, Builder
from rpg.schema.lexicon import (
    COLOR_RE,
    EACH_OTHER_GAP_RE,
    GROUP_SUBJECT_RE,
    LABEL_SEPARATOR_AFTER,
    PAIRWISE_RELATIONS,
    REL_PATTERNS,
)
from rpg.schema.readers.common import (
    DESCRIBED_TOWER_RE,
    Mention,
    colors_for,
    free_spots,
    initial_clause,
    mark_references,
    mentions_in,
    patch_spots,
    refuse_towers_merged,
    region_spots,
    stated_count,
    structure_colors,
)
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, ParseError, canon_color, features_colors, mark_regions


@dataclass
class RelationalReading:
    """What the relational reader has read of an instruction so far, clause by clause: the
    cubes and patches it names, the stacking edges, relations, patch and region placements,
    and what "it" refers to next."""

    b: Builder
    stackish: bool
    """The instruction asks for a stack ("stack", "tower", "pile up")."""
    objects: dict[tuple, list[str]] = field(default_factory=dict)
    clause: str = ""
    """The clause being read (an unnamed cube takes a colour it does not name for another cube)."""
    patch_names: dict[tuple, str] = field(default_factory=dict)
    on_edges: list[tuple[str, str]] = field(default_factory=list)
    rels: list = field(default_factory=list)
    onpatch: list[tuple[str, str]] = field(default_factory=list)
    bottom_top: dict[str, str] = field(default_factory=dict)
    sides: dict[str, str] = field(default_factory=dict)
    on_structure: list[str] = field(default_factory=list)
    """Cubes put on the stack the task builds ("on top of the stack")."""
    by_structure: list[tuple[str, str]] = field(default_factory=list)
    """(relation, cube) relative to that stack ("beside the tower")."""
    subjects: set[tuple] = field(default_factory=set)
    """(colour, label) of cubes placed by a relation."""
    beside: set[tuple] = field(default_factory=set)
    """(colour, label) of the cubes of :attr:`by_structure`: never cubes of that stack."""
    previous: list[str] = field(default_factory=list)
    """[subject, object] of the last relation: what "it" refers to."""
    last_pair: list[Mention] = field(default_factory=list)
    """The last relation's subject and object mentions."""
    regions: list[tuple[list[Mention], str]] = field(default_factory=list)
    """(subject mentions, region name): places on the table."""
    on_patch_as_stack: list[str] = field(default_factory=list)
    """Cubes a verb of their own puts on a patch read as their stack's ("stack red on blue, then put the
    blue cube on the green patch": the stack stands there): each must be its stack's base."""
    named_on_patch: bool = False
    """A cube of no stack put on a patch in a stacking text ("red stacked on blue, the gray cube on
    the white patch"): the stack itself stays off the patch."""
    fresh: dict[int, int] = field(default_factory=dict)
    """id of a mention said as one more of its colour (:attr:`Mention.another`) -> its cube's index."""
    group: list[Mention] = field(default_factory=list)
    """The cubes a "both" or a relation after "next to each other" refers to: the last pairwise
    relation's two cubes, or the cubes said next to each other (within the current clause)."""
    group_end: int = -1
    group_names: list[str] = field(default_factory=list)  # the cubes of a counted group said "each other" ("the two black cubes")
    """Where in the clause :attr:`group` was said (the end of its last word)."""

    def shared_subjects(self, clause: str, rm: re.Match, ms: list[Mention]) -> list[Mention]:
        """The cubes a relation at ``rm`` applies to together ("X next to Y, both on the white
        patch"; "X and Y next to each other in front of Z"), or [] when it has its own subject."""
        if len(self.group) < 2 or self.group_end < 0 or any(self.group_end <= m.start < rm.start() for m in ms if not m.ref):
            return []
        gap = clause[self.group_end: rm.start()]
        if GROUP_SUBJECT_RE.search(gap) or EACH_OTHER_GAP_RE.fullmatch(gap):
            return list(self.group)
        return []

    def obj(self, mn: Mention, i: int = 0) -> str:
        """The object a mention names: its patch, or its ``i``-th cube (made in the builder on first mention)."""
        if mn.patch:
            if mn.another and mn.color:  # "another green patch": one more patch of that colour
                i = self.fresh.setdefault(id(mn), sum(1 for k in self.patch_names if k[1:3] == (mn.color, mn.shape)))
            key = ("patch", mn.color, mn.shape) + ((i,) if i and (mn.count > 1 or mn.another) and mn.color else ())  # "the two yellow patches"
            if key not in self.patch_names:
                self.patch_names[key] = self.b.patch(mn.color or DEFAULT_PATCH_COLOR, mn.shape)
            return self.patch_names[key]
        key = ("cube", mn.color, mn.label) if (mn.color or mn.label) else ("cube", None, None, i, mn.start)
        lst = self.objects.setdefault(key, [])
        if len(key) == 5:
            i = 0
        elif mn.another and mn.color and not mn.label and i == 0:  # "another green block": one more of that colour
            i = self.fresh.setdefault(id(mn), len(lst))
        while len(lst) <= i:
            lst.append(self.b.semantic(mn.label) if mn.label else self.b.cube(mn.color or _next_default(
                self.b, self.objects, self.clause if mn.count <= 1 and re.search(r"\b(?:a|an|one|another|any)\s+(?:\w+\s+)?$", self.clause[:mn.end].rsplit(" ", 1)[0] + " ")
                else "")))  # ("three cubes: a red one, ...": named after; "put that block": a cube said before)
        return lst[i]

    def read_clause(self, clause: str) -> None:
        """Read one clause's mentions and relation words into the reading."""
        ms = mentions_in(clause)
        self.clause = clause
        related: list[Mention] = []  # the subject of this clause's relation, if it has one
        self.group, self.group_end = [], -1
        self.group_names = []
        # "with a red block on bottom and blue on top"
        for mn in ms:
            tail = clause[mn.end: mn.end + 22]
            if re.match(r"\s+(?:block\s+|cube\s+)?(?:on|at)\s+(?:the\s+)?(?:bottom|base)\b", tail):
                self.bottom_top.setdefault("bottom", self.obj(mn))
            elif re.match(r"\s+(?:block\s+|cube\s+)?(?:on|at)\s+(?:the\s+)?top\b(?!\s+of)", tail):
                self.bottom_top.setdefault("top", self.obj(mn))
        rel_re = "|".join(f"(?P<r{i}>\\b(?:{p})\\b)" for i, (p, _) in enumerate(REL_PATTERNS))
        # a relation word followed by a label's dash or colon is a role ("below - black"), not a relation
        found = [m for m in re.finditer(rel_re, clause) if not LABEL_SEPARATOR_AFTER.match(clause, m.end())]
        for k, rm in enumerate(found):
            kind = _kind_of(rm)
            left = [m for m in ms if m.end <= rm.start() and not m.patch]
            right = [m for m in ms if m.start >= rm.end()]
            if kind == "region":  # resolved once the stacks are known
                prev = found[k - 1].end() if k else None
                objects = [m for m in ms if prev is not None and m.start >= prev][:1]  # the previous relation's object
                if k and _kind_of(found[k - 1]) == "region":  # (a place has none: "... in the back left corner and the cyan
                    objects = []  # block in the front" places the cyan block)
                own = [m for m in left if prev is not None and m.start >= prev and m not in objects and (m.color or m.label)]
                # "red on the green patch and the white cube in the centre": the cube said after the last relation
                group = own[-1:] or related[:1] or (_listed_group(clause, left) if left else [])
                gap = clause[objects[0].end: rm.start()] if objects else ""
                every = re.search(r"\ball\s+(\d+)\b", gap)
                named = list({(m.color, m.label): m for m in reversed(left) if (m.color or m.label) and not m.ref}.values())[::-1]
                if not own and every and int(every.group(1)) != len(named):
                    raise ParseError(f"'{every.group(0)}' counts {every.group(1)} cubes, but {len(named)} are named before it; "
                                     "say which cubes it means")
                if not own and every and len(named) > 2:
                    # "X left of Y and Y left of Z, all three in the front half": every cube named (Y and Z only, before)
                    group = named
                elif not own and objects and self.last_pair and re.search(  # "X right of Y, both at the back": X and Y
                        r"\b(?:2|both|all)\b|\bthem\b", gap):
                    group = list(self.last_pair)
                self.regions.append((group, rm.group(0)[len("region_"):]))
                continue
            after = clause[rm.end():].strip()
            side = re.match(r"(?:the\s+)?(left|right)(?:\s+(?:hand\s+)?side)?\b(?!\s+(?:hand\s+)?(?:side\s+)?of)", after)
            if kind == "on" and side:
                if left:
                    self.sides[side.group(1)] = self.obj(left[-1])
                continue
            if kind == "on" and re.match(r"(?:the\s+)?(?:table|bottom|base|top\b(?!\s+of))", after):
                if left and (left[-1].color or left[-1].label) and not left[-1].ref and re.match(r"(?:the\s+)?table\b", after):
                    self.previous[:] = [self.obj(left[-1])] * 2  # "place a pink cube on the table, put a cyan cube on it"
                continue
            if kind in ("on", "next_to", "far_from") and re.match(r"each other|one another|top of each other|itself", after):
                if left:
                    group = _listed_group(clause, left)
                    if len(group) > 1:  # "the red and green blocks": one cube per colour, as listed
                        names = [self.obj(mn) for mn in group]
                    elif left[-1].count < 2 and any((mn.color, mn.label) != (left[-1].color, left[-1].label)
                                                    for mn in left if mn.color or mn.label):
                        # "red on blue and green on yellow, side by side": which cubes stand side by side is not said
                        # (a second yellow cube had been made up to stand next to the first)
                        raise ParseError(f"'{kind.replace('_', ' ')} each other' after several cubes does not say which of "
                                         "them; name them (e.g. \"put the blue and yellow cubes next to each other\"), or "
                                         "use --model")
                    else:
                        names = [self.obj(left[-1], i) for i in range(max(left[-1].count, 2))]
                        self.group_names = list(names)  # "the two black cubes next to each other and the white cube far from them"
                    if kind == "on":
                        self.on_edges += [(u, lo) for lo, u in itertools.pairwise(names)]
                    elif kind == "next_to" and len(names) > 2 and len(group) > 1:
                        # "put the red, green and blue cubes next to each other": a row, a cluster, each beside each?
                        # (a chain had been read: the middle one made up, the two ends left apart; of one colour, as in
                        # "three blue cubes side by side", any cube may stand in the middle and the chain stays)
                        raise ParseError(f"'next to each other' of {len(names)} cubes does not say how they stand (in a row, "
                                         "which in the middle?); say a row (e.g. \"a row of red, green and blue\") or the pairs, "
                                         "or use --model")
                    elif kind == "far_from":  # "the red and blue cubes far from each other": every two of them
                        self.rels += [FarFrom(a, c) for a, c in itertools.combinations(names, 2)]
                        self.subjects.update((mn.color, mn.label) for mn in group)
                    else:
                        self.rels += [NextTo(a, c) for a, c in itertools.pairwise(names)]
                        self.subjects.update((mn.color, mn.label) for mn in group)
                        if len(group) > 1:
                            self.group, self.group_end = list(group), rm.end()
                continue
            if not left or not right:
                if kind == "on" and self.stackish and right and right[0].patch:
                    self.onpatch.append(("*", self.obj(right[0])))
                continue
            a_m, b_m = left[-1], right[0]
            shared = self.shared_subjects(clause, rm, ms)
            if shared and not b_m.ref and not self.stackish:
                self.relate_group(shared, kind, b_m)
                continue
            carried = False
            if self.last_pair and a_m is self.last_pair[1] and re.fullmatch(r"\s*(?:,\s*(?:and\s+|but\s+)?|and\s+|but\s+|yet\s+)(?:also\s+|but\s+|still\s+|yet\s+)?",
                                                                    clause[a_m.end: rm.start()]):
                a_m, carried = self.last_pair[0], True  # "X left of Y and behind Z", "X in front of Y, close to it": X is
                # behind Z; "X far from Y but near Z": X is near Z (a plain "but" had related Y to Z)
            self.last_pair[:] = [a_m, b_m]
            related[:] = [a_m]
            if a_m.ref:
                continue
            if b_m.ref == "@them" and len(self.group) > 1 and not self.stackish:  # "X left of Y, Z behind them"
                if kind not in _RELATIONS:
                    raise ParseError(f"'{clause[rm.start():b_m.end].strip().replace('@', '')}' puts one cube {kind.replace('_', ' ')} two "
                                     "cubes at once; say which cube it goes with")
                a = self.obj(a_m)
                self.subjects.add((a_m.color, a_m.label))
                self.rels += [_RELATIONS[kind](a, self.obj(mn)) for mn in self.group]
                self.previous[:] = [a, self.obj(self.group[-1])]
                continue
            if b_m.ref == "@them" and len(self.group_names) > 1 and not self.stackish and kind in _RELATIONS:
                a = self.obj(a_m)  # "the two black cubes next to each other and the white cube far from them": each black cube
                self.subjects.add((a_m.color, a_m.label))
                self.rels += [_RELATIONS[kind](a, n) for n in self.group_names]
                self.previous[:] = [a, self.group_names[-1]]
                continue
            if b_m.ref == "@them" and not self.on_edges and self.previous:
                b_m = Mention(b_m.start, b_m.end, None, None, 1, ref="@it")
            elif b_m.ref == "@it" and not self.previous and self.stackish:  # "build a tower ... and put X behind it"
                before = [m for m in ms if m.end <= a_m.start and not m.patch and not m.ref and (m.color or m.label)]
                if before and self.bottom_top.get("bottom") == self.obj(before[-1]):
                    # "cube A at the bottom of a tower, cube M on it, and cube Z on top": on cube A (M had gone on top
                    # of the whole tower, above Z)
                    self.previous[:] = [self.bottom_top["bottom"]] * 2
                elif before and kind == "on" and self.bottom_top.get("top") == self.obj(before[-1]):
                    raise ParseError(f"'{clause[a_m.start:b_m.end].strip().replace('@', '')}' puts a cube on the one said to be "
                                     "on top; say the tower's order once (e.g. \"from bottom to top: ...\"), or use --model")
                else:
                    b_m = Mention(b_m.start, b_m.end, None, None, 1, ref="@s")
            if b_m.ref in ("@s", "@them"):
                if kind == "on":
                    self.on_structure.append(self.obj(a_m))
                elif kind not in ("under", "between"):
                    self.by_structure.append((kind, self.obj(a_m)))
                    self.beside.add((a_m.color, a_m.label))
                self.subjects.add((a_m.color, a_m.label))
                continue
            if b_m.ref == "@it":
                if not self.previous:
                    continue
                # "put the white cube on the gray patch and stack the red cube on it": on the cube that covers the patch
                covered = kind == "on" and any(p == self.previous[1] and a in ("*", self.previous[0]) for a, p in self.onpatch)
                referent = self.previous[0] if covered else self.previous[1]
                a = self.obj(a_m)
                if referent == a and self.previous[0] != a and kind in ("on", "under"):  # "gray underneath red, with the red one resting on it":
                    referent = self.previous[0]  # no cube is related to itself: "it" is the other one of the pair said
                self.subjects.add((a_m.color, a_m.label))
                if referent in self.patch_names.values():  # "red next to the green patch and yellow on it": the patch or red?
                    raise ParseError(f"'{kind.replace('_', ' ')} it' may mean the cube {self.previous[0]} or the patch named "
                                     f"with it; say which (e.g. \"{kind.replace('_', ' ')} the {self.previous[0]} block\")")
                if referent in self.patch_names.values():
                    self.onpatch.append((a, referent))
                elif kind == "on":
                    self.on_edges.append((a, referent))
                elif kind == "under":
                    self.on_edges.append((referent, a))
                elif kind != "between":
                    self.rels.append(_RELATIONS[kind](a, referent))
                self.previous[:] = [a, referent]
                continue
            stacked = {n for edge in self.on_edges for n in edge}
            if kind == "on" and b_m.patch and self.stackish and stacked and (a_m.color or a_m.label) \
                    and self.obj(a_m) not in stacked:
                self.onpatch.append((self.obj(a_m), self.obj(b_m)))  # "red stacked on blue, the gray cube on the patch"
                self.named_on_patch = True
                self.previous[:] = [self.obj(a_m), self.obj(b_m)]
                continue
            if kind == "on" and b_m.patch and self.stackish:
                if (a_m.color or a_m.label) and re.search(r"\b(?:move|put|place|set|bring|slide|push|get|take)\s+(?:the\s+)?$",
                                                          clause[:a_m.start]):
                    self.on_patch_as_stack.append(self.obj(a_m))  # "move the green cube onto ...": checked once the stack is known
                self.onpatch.append(("*", self.obj(b_m)))
                if a_m.color or a_m.label:  # a named cube that "it" may refer to next
                    self.previous[:] = [self.obj(a_m), self.obj(b_m)]
                continue
            if kind == "on" and b_m.patch:
                # "the red block, the blue block and the green block onto ...", not the object of an earlier
                # relation ("red on the blue block and the blue block on the green patch": one blue cube)
                objects = {id(m) for x in found if x.end() <= rm.start()
                           for m in [m for m in ms if m.start >= x.end()][:2 if _kind_of(x) == "between" else 1]}
                # (both objects of a "between": "between the red and yellow cubes, and the red cube on the patch" had put
                # the yellow cube on the patch too)
                # ("X next to Y but on the blue patch": X, the subject carried over; Y had been put on the patch)
                group = [a_m] if carried else _listed_group(clause, left, stop=objects)
                for member in group:
                    for i in range(member.count):
                        self.onpatch.append((self.obj(member, i), self.obj(b_m)))
                self.previous[:] = [self.obj(a_m), self.obj(b_m)]
                continue
            a, c = self.obj(a_m), self.obj(b_m)
            self.previous[:] = [a, c]
            if kind != "on":
                self.subjects.add((a_m.color, a_m.label))
            if kind == "on":
                self.on_edges.append((a, c))
            elif kind == "under":
                self.on_edges.append((c, a))
            elif kind == "between":
                if len(right) < 2 and b_m.count < 2:
                    continue
                self.rels.append(Between(a, c, self.obj(right[1]) if len(right) >= 2 and b_m.count < 2 else self.obj(b_m, 1)))
            else:
                self.rels.append(_RELATIONS[kind](a, c))
            if kind in _RELATIONS and not b_m.patch and (a_m.color or a_m.label) and (b_m.color or b_m.label):
                self.group, self.group_end = [a_m, b_m], b_m.end

    def relate_group(self, group: list[Mention], kind: str, b_m: Mention) -> None:
        """Each cube of ``group`` in relation ``kind`` to ``b_m``'s object ("both on the white patch").

        Raises:
            ParseError: the relation cannot hold for several cubes at once (two cubes on one cube,
                between).
        """
        target = self.obj(b_m)
        if not (kind in _RELATIONS or (kind == "on" and b_m.patch)):
            raise ParseError(f"'{' and '.join(m.color or m.label for m in group)}' cannot all be {kind.replace('_', ' ')} one "
                             "cube; say which cube goes where")
        for mn in group:
            a = self.obj(mn)
            self.subjects.add((mn.color, mn.label))
            if kind == "on":
                self.onpatch.append((a, target))
            else:
                self.rels.append(_RELATIONS[kind](a, target))
        self.previous[:] = [self.obj(group[-1]), target]




STACK_WORD_RE = re.compile(r"\b(?:stack|stacks|stacked|tower|towers|pile up)\b")
"""Words that make a relational text a stacking one."""


@reader(order=200)
def recognize_relational(f: Features, b: Builder) -> bool:
    initial = initial_clause(f.text)
    text = f.text if initial is None else (f.text[: initial[0]] + f.text[initial[1]:]).strip()
    text = mark_regions(mark_references(text))
    if re.search(rf"\b(?:{COLOR_RE})\s+and\s+(?:the\s+)?(?:{COLOR_RE})\s+(?:cubes|blocks)\s+@region_[a-z_]+\s*,\s*(?:(?:to\s+the\s+)?(?:left|right)"
                 r"\s+of|in\s+front\s+of|behind|next\s+to|beside)\b", text):
        raise ParseError("a place and then a relation said of two cubes together (\"the red and green cubes in the front half, "
                         "left of the blue cube\") is beyond the builtin parser: one of them had lost the relation; say it "
                         "for each cube, or use --model")
    stackish = bool(STACK_WORD_RE.search(text))
    if not (stackish or any(re.search(rf"\b(?:{p})\b", text) for p, _ in REL_PATTERNS)):
        return False
    described = list(DESCRIBED_TOWER_RE.finditer(text))
    if len(described) >= 2:  # "a tower of 3 red blocks next to a tower of 3 blue blocks"
        return _described_towers(text, described, b)
    # towers of several stacks: "two towers", "two stacks of red blocks", "stacks on matching patches"
    multi = re.search(r"\b(\d+)\s+(?:[a-z\-]+\s+)?(?:towers|stacks)\b", text)
    patch_count = len({m.group(1) for m in re.finditer(rf"\b({COLOR_RE})\s+(?:goal\s+|target\s+)?patch\b", text)})
    if stackish and patch_count >= 2 and not multi:  # "stack the red blocks on the red patch and the blue ... on the blue patch"
        return _multi_stacks(f, b, patch_count)
    if multi or (stackish and f.has("each stack", "matching", "color-specific", "respective", "patches", "towers", "stacks")):
        return _multi_stacks(f, b, int(multi.group(1)) if multi else 2)
    clauses = re.split(r"\bthen\b|;|,\s*(?:and\s+)?then\b|\.\s", text)
    f = Features(text, f.original, features_colors(text), f.quoted)
    r = RelationalReading(b, stackish)
    for clause in clauses:
        r.read_clause(clause)
    if "bottom" in r.bottom_top and "top" in r.bottom_top:
        below = r.bottom_top["bottom"]  # the top cube goes on the cubes said on the bottom one ("A at the bottom, M on it, Z on top")
        while (above := [u for u, lo in r.on_edges if lo == below]) and len(above) == 1 and above[0] != r.bottom_top["top"]:
            below = above[0]
        r.on_edges.append((r.bottom_top["top"], below))
    if "left" in r.sides and "right" in r.sides and r.sides["left"] != r.sides["right"]:
        r.rels.append(LeftOf(r.sides["left"], r.sides["right"]))
    # a bare "stack N blocks" / "stack blocks on the patch"
    if stackish and not r.on_edges:
        # the cubes of the clauses that say the stack ("move cyan to the corner. stack 2 brown cubes ...": not cyan)
        # ("stack red and blue, and put yellow next to white": the clause after ", and put" is its own, not the stack's: white
        # had been stacked)
        parts = [p for c in clauses for p in lexicon.AND_PLACING_CLAUSE_RE.split(c)]
        said = " . ".join(c for c in parts if STACK_WORD_RE.search(c)) or text
        if sum(m.count for m in mentions_in(said) if not m.patch and not m.ref) < 2:
            said = text  # "place red and green together, then stack green on top": the clause names one of them
        f = Features(said, f.original, features_colors(said), f.quoted)
        ms = [m for m in mentions_in(said) if not m.patch and not m.ref and (m.color, m.label) not in r.subjects]
        if any(m.color or m.label for m in ms) and not re.search(r"\b(?:but|except|besides|other\s+than|apart\s+from)\b", said):
            # "stack the cubes from bottom to top: digit 1, digit 2, digit 3", "a tower of digit blocks ...: the digit 1
            # block, ...": "the cubes" are those listed (a red cube had been made up for it); not "all cubes but the white ones"
            ms = [m for m in ms if m.color or m.label or not re.search(r"\b(?:the|of)\s+(?:(?:digit|number|letter)\s+)?(?:cubes|blocks)$",
                                                                             said[:m.end])]
        n = stated_count(f, default=None) or (max(m.count for m in ms) if ms else 2)
        n = max(n, 2)
        if ms and ms[0].color and all(m.color == ms[0].color for m in ms):
            if stated_count(f, default=None) is None and sum(m.count for m in ms) < n and not re.search(
                    rf"\b(?:{ms[0].color})s\b|\b(?:{ms[0].color})\s+(?:blocks|cubes|ones|towers?|stacks?|columns?)\b"
                    rf"|\b(?:towers?|stacks?|columns?)\s+of\s+(?:{ms[0].color})\b", said):
                return False  # "a tower with red at the bottom": one red cube said, the tower's other cubes nobody named
            names = [r.obj(ms[0], i) for i in range(n)]
        elif len(ms) > n and len({(m.color, m.label) for m in ms}) == len(ms):  # "a tower of red, green and blue"
            names = [r.obj(m) for m in ms]
            if lexicon.TOP_FIRST_RE.search(said):
                names = names[::-1]  # "from top to bottom: digit 1, digit 2, digit 3": listed from the top (read upward, silently)
        elif stated_count(f, default=None) is None and len(ms) > 2 and all(m.count == 1 for m in ms) and all(
                lexicon.LIST_GAP_RE.fullmatch(said[a.end:b.start]) for a, b in itertools.pairwise(ms)) and not any(
                lexicon.ROLE_AFTER_RE.match(said, m.end) for m in ms):  # "a tower of red and white, white on top": a role, no third cube
            # "stack red, red, blue on the green patch": each colour said is a cube, a colour said again another one
            # (the repeated red had been the same cube: a tower of two)
            seen: dict[tuple, int] = {}
            names = []
            for m in ms:
                names.append(r.obj(m, seen.get((m.color, m.label), 0)))
                seen[(m.color, m.label)] = seen.get((m.color, m.label), 0) + 1
        else:
            cube_colors = {m.color for m in mentions_in(said) if not m.patch}  # a patch's colour names no cube of the stack
            named = [c for c in dict.fromkeys(f.color_list()) if (c, None) not in r.subjects and c in cube_colors]
            # not the colours of cubes placed beside it
            # nor of cubes another clause names ("Stack two cubes. Put the red cube next to the blue cube.": that red cube had
            # been stacked too)
            elsewhere = {m.color for m in mentions_in(text) if not m.patch and m.color} - cube_colors
            cols = [c for c in colors_for(n, f, prefer=named) if (c, None) not in r.beside and c not in elsewhere]
            cols += [c for c in DEFAULT_COLORS if c not in cols and (c, None) not in r.subjects and c not in elsewhere][: n - len(cols)]
            if named and any(c not in named for c in cols[:n]):
                return False  # colours nobody named made up for a stack of cubes whose colours are said
            names = [r.obj(Mention(0, 0, c, None, 1)) for c in cols[:n]]
            if named and lexicon.TOP_FIRST_RE.search(said):  # "stack green and blue from top to bottom and put red ...": green on top
                names = names[::-1]  # (it had been put at the bottom)
        r.on_edges += [(u, lo) for lo, u in zip(names, names[1:], strict=False)]
    raised = [a for a in r.on_patch_as_stack if a in {x for x, _ in r.on_edges}]
    if raised:  # "Build a tower of red, blue, green. Move the green cube onto the red patch.": the base had gone there instead
        raise ParseError(f"\"{f.original[:80]}\" puts the {raised[0]} cube on a patch, but it stands on another cube in the "
                         "tower said; say whether the whole tower goes on the patch (\"put the tower on the red patch\") or "
                         "that the tower is how the cubes start (\"Initially: a tower of ... . Move ...\"), or use --model")
    if r.on_structure or r.by_structure:
        _resolve_structure(b, r.objects, r.on_edges, r.rels, r.on_structure, r.by_structure, structure_colors(text))
    placed_in = _resolve_regions(r.regions, r.on_edges, r.obj, stackish, r.previous)
    if not r.on_edges and not r.rels and not r.onpatch and not placed_in:
        return False
    stacked = {n for edge in r.on_edges for n in edge}
    loose = [a for a in dict.fromkeys(r.on_patch_as_stack) if a not in stacked]
    if loose and len(loose) == sum(a == "*" for a, _ in r.onpatch):  # "put the pink cube on the orange patch ... then make a
        spare = iter(loose)  # tower of brown on gray": pink itself goes on the patch (the tower's base had gone there instead)
        r.onpatch = [(next(spare) if a == "*" else a, p) for a, p in r.onpatch]
        r.named_on_patch = True
    if len({p for a, p in r.onpatch if a == "*"}) > 1:
        raise ParseError("one stack cannot stand on several patches; say which cubes go on which patch")
    if any(a == "*" for a, _ in r.onpatch) or (stackish and r.onpatch and not r.named_on_patch):
        target = r.onpatch[0][1]
        r.onpatch = [(a, p) for a, p in r.onpatch if a != "*"]
        chains = _chains(r.on_edges)
        if chains and (chains[0][0], target) not in r.onpatch:  # "red on blue and blue on the green patch": said once
            r.onpatch.append((chains[0][0], target))
    # cubes that are only on patches (place both blocks onto the patch)
    chains = _chains(r.on_edges)
    if chains is None:
        cycle = ", ".join(f"{a} on {b_}" for a, b_ in r.on_edges)
        raise ParseError(f"the stacking relations of \"{f.original[:80]}\" contradict each other ({cycle}: "
                         "something would be on itself); say once which cube goes on which, or use --model")
    r.rels = _diagonal(r.rels)
    _refuse_crossed_relations(f, r.rels, [*r.onpatch, *r.on_edges])
    refuse_towers_merged(f.text, f.original, len([c for c in chains if len(c) > 1]))
    _layout_relational(b, chains, r.rels, r.onpatch, placed_in)
    for ch in chains:
        b.preds.append(Stack(tuple(ch)) if len(ch) > 1 else OnTable(ch[0]))
        if len(ch) > 1:
            b.summary.append("tower bottom to top: " + ", ".join(ch))
    b.preds += r.rels
    for a, region in placed_in:
        b.preds.append(InRegion(a, region))
        b.summary.append(b.preds[-1].describe())
    for a, p in r.onpatch:
        b.preds.append(OnPatch(a, p))
        b.summary.append(f"{a} on {p}")
    b.summary += [rel.describe() for rel in r.rels]
    b.primitives += ["stack"] if any(len(c) > 1 for c in chains) else ["place"]
    if initial is not None:
        by_color = {a.color: a.name for a in b.assets if a.kind == "colored_cube"}
        bottom, top = initial[2], initial[3]
        if bottom not in by_color or top not in by_color:
            raise ParseError(f"the initial state names a {top if top not in by_color else bottom} cube the task does not have")
        b.structures.append([by_color[bottom], by_color[top]])
        b.summary.append(f"initially {top} is stacked on {bottom}")
    return True


def _kind_of(rm: re.Match) -> str:
    """The relation kind a match of the relational pattern names (:data:`REL_PATTERNS`)."""
    return next(REL_PATTERNS[i][1] for i in range(len(REL_PATTERNS)) if rm.group(f"r{i}"))


def _diagonal(rels: list) -> list:
    """The directional relations with two said of one pair of cubes along both axes ("to the right of the white
    block and in front of it") marked ``diagonal``: each leaves the other axis to the other (the pair stands
    diagonally), where one alone keeps the cubes level.  Two along one axis are left for
    :func:`_refuse_crossed_relations`."""
    ways: dict[frozenset, set] = {}
    for q in filter(_directional, rels):
        ways.setdefault(frozenset((q.a, q.b)), set()).add(_way(q))
    slanted = {pair for pair, w in ways.items() if len(w) == 2 and len({axis for axis, _, _ in w}) == 2}
    return [replace(q, diagonal=True) if _directional(q) and frozenset((q.a, q.b)) in slanted else q for q in rels]


def _directional(q) -> bool:
    """Whether ``q`` is a relation along one axis of the table between two cubes (left of, behind ...)."""
    return hasattr(type(q), "axis") and hasattr(type(q), "sign") and q.a != q.b


def _way(q) -> tuple:
    """(axis, the cube before, the cube after) along ``q``'s axis."""
    lo, hi = (q.b, q.a) if q.sign > 0 else (q.a, q.b)
    return type(q).axis, lo, hi


def _refuse_crossed_relations(f: Features, rels: list, touching: list[tuple[str, str]] = ()) -> None:
    """Refuse directional relations no placement satisfies: two on one pair of cubes along
    different axes or opposite ways ("left of the blue block and right of the blue block";
    "behind the red one and to its left": each relation needs the cubes level across its
    axis, ``RELATION_MAX_OFF_AXIS``), or a cycle along one axis (red left of blue, blue left of red);
    and "far from" between objects that touch: next to each other, or one on the other or on a
    patch (``touching``: the (cube, support) pairs of the reading's stacking and patch relations);
    and a directional relation between a cube and the cube or patch it rests on: they stand over one spot ("The red cube is on the blue cube.
    Move the red cube behind the blue cube." had demanded both).

    Raises:
        ParseError: naming the relations that contradict each other.
    """
    import networkx as nx

    directional = list(filter(_directional, rels))
    by_pair: dict[frozenset, set] = {}
    graphs: dict[int, nx.DiGraph] = {}
    for q in directional:
        axis, lo, hi = _way(q)  # along the axis, lo comes before hi
        by_pair.setdefault(frozenset((q.a, q.b)), set()).add((axis, lo, hi))
        graphs.setdefault(axis, nx.DiGraph()).add_edge(lo, hi, rel=q.describe())
    near = {frozenset((q.a, q.b)) for q in rels if isinstance(q, NextTo)}
    on = {frozenset(pair) for pair in touching if "*" not in pair}  # a cube on a patch or on another cube
    far = [q for q in rels if isinstance(q, FarFrom) and frozenset((q.a, q.b)) in near | on]
    if far:
        how = "next to" if frozenset((far[0].a, far[0].b)) in near else "on"
        raise ParseError(f"the relations of \"{f.original[:80]}\" contradict each other ({far[0].describe()}; "
                         f"{far[0].a} {how} {far[0].b}): objects that touch cannot be far apart; say one")
    over = next((q for q in directional if (q.a, q.b) in set(touching) or (q.b, q.a) in set(touching)), None)
    if over is not None:
        raise ParseError(f"the relations of \"{f.original[:80]}\" contradict each other ({over.describe()}, and one stands on "
                         "the other): objects stacked on each other stand over one spot. If one sentence says how the cubes "
                         "start, say it as 'Initially ...' (e.g. \"Initially the red cube is on the blue cube. Move it behind "
                         "the blue cube.\"); else say one relation")
    crossed = next((ways for ways in by_pair.values() if len(ways) > 1 and len({axis for axis, _, _ in ways}) < len(ways)), None)
    cycle = next((c for g in graphs.values() for c in [next(iter(nx.simple_cycles(g)), None)] if c), None)
    if crossed or cycle:
        said = "; ".join(q.describe() for q in directional)
        raise ParseError(f"the relations of \"{f.original[:80]}\" contradict each other ({said}): no placement "
                         "satisfies them all (a relation needs the two cubes level across its direction); "
                         "say one relation per pair of cubes, or use --model")


def _described_towers(text: str, described: list[re.Match], b: Builder) -> bool:
    """Several towers each described by height and colour, side by side or in a stated
    relation to each other ("a tower of 3 red blocks next to a tower of 3 blue blocks",
    "... to the left of ...")."""
    towers = []
    for m in described:
        height = int(m.group(1))
        if height < 2:
            raise ParseError("a tower needs at least two cubes")
        towers.append([b.cube(canon_color(m.group(2))) for _ in range(height)])
    rels = []
    for (m1, t1), (m2, t2) in itertools.pairwise(zip(described, towers, strict=True)):
        between = text[m1.end(): m2.start()]
        kind = next((k for p, k in REL_PATTERNS if k not in ("on", "under", "between") and re.search(rf"\b(?:{p})\b", between)), None)
        if kind is not None and kind not in _RELATIONS:
            raise ParseError(f"cannot read how the towers in \"{text[:80]}\" relate ({kind.replace('_', ' ')}); "
                             "describe each tower and one relation between them, or use --model")
        if kind:
            rels.append(_RELATIONS[kind](t1[0], t2[0]))
    _layout_relational(b, towers, rels, [])
    for t in towers:
        b.preds.append(Stack(tuple(t)))
        b.summary.append("tower bottom to top: " + ", ".join(t))
    b.preds += rels
    b.summary += [r.describe() for r in rels]
    b.primitives += ["stack"]
    return True


def _listed_group(clause: str, left: list[Mention], stop: set[int] = frozenset()) -> list[Mention]:
    """The mentions listed together just before a relation ("the red, the blue and the
    green block", "the red and green blocks"): the last one and those joined to it by
    commas or "and", up to a mention whose ``id`` is in ``stop`` (the object of an earlier relation)."""
    group = [left[-1]]
    for mn in reversed(left[:-1]):
        if mn.ref or id(mn) in stop or not re.fullmatch(r"\s*(?:,\s*and|,|and)\s*(?:the\s+)?", clause[mn.end: group[0].start]):
            break
        group.insert(0, mn)
    return group


_RELATIONS = {name: PREDICATES[name] for name in PAIRWISE_RELATIONS}


def _resolve_regions(regions: list[tuple[list[Mention], str]], on_edges: list, obj, stackish: bool,
                     previous: list[str]) -> list[tuple[str, str]]:
    """(cube, region) for each place on the table: the cubes named before it, or, for "the
    stack" / "it" / a tower of unnamed cubes, the base of the tallest tower."""
    out = []
    for group, region in regions:
        named = [m for m in group if (m.color or m.label) and not m.ref]
        if named:
            single = len(named) == 1
            out += [(obj(m, i), region) for m in named for i in range(m.count if single else 1)]
            continue
        chains = sorted(_chains(on_edges) or [], key=len, reverse=True)
        if group and group[-1].ref in ("@it", "@them") and previous and not stackish:
            out.append((previous[0], region))
        elif chains and len(chains[0]) > 1:
            out.append((chains[0][0], region))
        elif group and not group[-1].ref:
            out += [(obj(group[-1], i), region) for i in range(group[-1].count)]
    return out


def _resolve_structure(b: Builder, objects: dict, on_edges: list, rels: list, on_structure: list[str],
                       by_structure: list[tuple[str, str]], colors: list[str]) -> None:
    """Resolve "the stack" / "the tower": the tallest tower the instruction builds, or,
    when it builds none, the tower it describes ("the tower of red and blue", bottom to
    top), or one it builds without describing ("build a tower and put the red block behind
    it": two cubes of colours it does not use); one described by less than its cubes ("the
    stack of blue blocks") is refused (:class:`ParseError`), and "the stack" nobody built or
    described was refused by the front end as a reference
    (:data:`rpg.schema.lexicon.DEFINITE_STRUCTURE_RE`).  Cubes put "on the stack" go on its top, in order; relations
    "beside the tower" are taken to its base."""
    chains = _chains(on_edges) or []
    subjects = set(on_structure) | {c for _, c in by_structure}
    tall = sorted((ch for ch in chains if len(ch) > 1 and not subjects & set(ch)), key=len, reverse=True)
    if tall:
        tower = tall[0]
    else:
        if len(colors) == 1:  # "on the stack of blue blocks": how many, and of which colours, is not said
            raise ParseError("the stack it refers to is not described cube by cube; say its cubes bottom to top "
                             "(\"the stack of red and blue blocks\") or build it in the instruction, or use --model")
        tower = [b.cube(c) for c in colors]
        while len(tower) < 2:  # "build a tower and put the red block behind it": a tower the text builds
            tower.append(b.cube(_next_default(b, objects)))
        on_edges += [(up, lo) for lo, up in itertools.pairwise(tower)]
    top = tower[-1]
    for cube in on_structure:
        on_edges.append((cube, top))
        top = cube
    for kind, cube in by_structure:
        rels.append(_RELATIONS[kind](cube, tower[0]))


def _next_default(b: Builder, objects: dict, clause: str = "") -> str:
    """The colour of a cube named by no colour: the first default colour no cube has yet and, where there is one, that the
    ``clause`` it is said in names for no other cube ("put a block between the red block and the green block": it had
    been red, a second red cube, and the instruction refused for naming one)."""
    said = {canon_color(w) for w in re.findall(rf"\b(?:{COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?patch)", clause)}  # cubes' colours
    used = {k[1] for k in objects if k[0] == "cube"} | {a.color for a in b.assets}
    return next((c for c in DEFAULT_COLORS if c not in used | said), None) or next(c for c in DEFAULT_COLORS if c not in used)


def _chains(edges: list[tuple[str, str]]) -> list[list[str]] | None:
    """Support chains bottom to top from (upper, lower) edges; None if they contradict."""
    import networkx as nx

    g = nx.DiGraph()
    for up, lo in edges:
        if up == lo:
            return None
        g.add_edge(lo, up)
    if not nx.is_directed_acyclic_graph(g) or any(g.out_degree(n) > 1 or g.in_degree(n) > 1 for n in g):
        return None
    chains = []
    for n in sorted(g.nodes):
        if g.in_degree(n) == 0:
            ch = [n]
            while g.out_degree(ch[-1]):
                ch.append(next(iter(g.successors(ch[-1]))))
            chains.append(ch)
    return chains


def _free_offset(placed: dict[str, tuple[float, float]], anchor: tuple[float, float], offset: tuple[float, float],
                 relation: str, sign: int) -> tuple[float, float]:
    """Where a cube related to ``anchor`` goes: ``anchor`` + ``sign`` * ``offset`` (m, table frame),
    or, when a cube is already there ("the green cube next to the orange one, and a blue one next
    to it too"), the same relation's next free spot: the other sides for next to and far from,
    shifted sideways for left of / right of / in front of / behind (which only constrain one axis)."""
    dx, dy = sign * offset[0], sign * offset[1]
    if relation in ("next_to", "far_from"):
        candidates = [(dx, dy), (-dx, -dy), (dy, dx), (-dy, -dx)]
    elif dx and dy:  # diagonal: farther out the same way
        candidates = [(k * dx, k * dy) for k in (1.0, 1.5, 2.0)]
    else:
        side = C.CUBE_EDGE + 0.02
        candidates = [(dx, dy)] + [(dx + s * side * (dy != 0), dy + s * side * (dx != 0)) for s in (1, -1, 2, -2)]
    for ox, oy in candidates:
        spot = (anchor[0] + ox, anchor[1] + oy)
        if all((spot[0] - x) ** 2 + (spot[1] - y) ** 2 >= (C.CUBE_EDGE + 0.01) ** 2 for x, y in placed.values()):
            return spot
    return (anchor[0] + dx, anchor[1] + dy)


def _layout_relational(b: Builder, chains: list[list[str]], rels: list, onpatch: list[tuple[str, str]],
                       regions: list[tuple[str, str]] = ()) -> None:
    """Place stacks, related cubes and patches so every relation holds; cubes given a
    region of the table go to its centre first (side by side when several share one)."""
    placed: dict[str, tuple[float, float]] = {}
    base_of = {n: ch[0] for ch in chains for n in ch}
    cube_names = [a.name for a in b.assets if a.kind != "goal_patch"]
    for n in [a.name for a in b.assets]:
        base_of.setdefault(n, n)
    by_region: dict[str, list[str]] = {}
    for a, region in regions:
        if base_of[a] not in by_region.setdefault(region, []):
            by_region[region].append(base_of[a])
    for region, members in by_region.items():
        for m, xy in zip(members, region_spots(region, len(members)), strict=True):
            placed[m] = xy
    # cubes on a patch no relation places stand on it before the relations are laid out, so a cube
    # related to one of them ("then a purple cube next to the red block") is placed beside where it ends
    related = {base_of[x] for r in rels for x in (r.a, r.b, getattr(r, "c", None)) if x}
    first = sorted({p for _, p in onpatch} - set(placed) - related)
    early_xy = dict(zip(first, b.unit_centers(len(first), 0.16), strict=True)) if first else {}
    for p, xy in early_xy.items():
        members = list(dict.fromkeys(base_of[a] for a, q in onpatch if q == p))
        shape = next(a.shape for a in b.assets if a.name == p)
        for m, spot in zip(members, patch_spots(xy, shape, len(members)), strict=True):
            placed[m] = spot
    offset = {"left_of": (0.0, 0.10), "right_of": (0.0, -0.10), "in_front_of": (-0.10, 0.0), "behind": (0.10, 0.0),
              "next_to": (0.0, 0.06), "far_from": (0.0, C.FAR_FROM_MIN_DIST + 0.04)}
    cx, cy = C.WORKSPACE_CENTER
    # a cube between two others first, so a side relation between those two ("red left of green, yellow between them")
    # orients the three (the ends had been placed by the side relation and the middle cube elsewhere)
    for r in sorted(rels, key=lambda r: not isinstance(r, Between)):
        a, c = base_of[r.a], base_of[r.b]
        if isinstance(r, Between):
            c2 = base_of[r.c]
            if a not in placed:  # the middle cube and its two neighbours clear of what stands already (a cube on a patch)
                taken = list(placed.values()) + list(early_xy.values())
                placed[a] = next(((x, y) for x in (cx, cx - 0.08, cx + 0.08) for y in (cy, cy + 0.2, cy - 0.2, cy + 0.12, cy - 0.12)
                                  if all(math.hypot(x - ox, y + dy - oy) >= 0.1 for dy in (0.0, 0.08, -0.08) for ox, oy in taken)),
                                 (cx, cy))
            ax, ay = placed[a]
            side = next((s for s in rels if not isinstance(s, Between) and s.name in ("left_of", "right_of", "in_front_of", "behind")
                         and {base_of[s.a], base_of[s.b]} == {c, c2}), None)
            if side is not None:  # its two ends on the axis the side relation says, that way round
                ux, uy = (0.8 * v for v in offset[side.name])
                placed.setdefault(base_of[side.a], (ax + ux, ay + uy))
                placed.setdefault(base_of[side.b], (ax - ux, ay - uy))
            placed.setdefault(c, (ax, ay + 0.08))
            placed.setdefault(c2, (ax, ay - 0.08))
            continue
        dx, dy = offset[r.name]
        if getattr(r, "diagonal", False):  # with the pair's other relation: the offset along both axes
            other = next(q for q in rels if q is not r and getattr(q, "diagonal", False) and {q.a, q.b} == {r.a, r.b})
            ox, oy = offset[other.name]
            dx, dy = (dx + ox, dy + oy) if other.a == r.a else (dx - ox, dy - oy)
        if c not in placed and a not in placed:
            placed[c] = (cx - dx / 2, cy - dy / 2)
        if c in placed and a not in placed:
            placed[a] = _free_offset(placed, placed[c], (dx, dy), r.name, +1)
        elif a in placed and c not in placed:
            placed[c] = _free_offset(placed, placed[a], (dx, dy), r.name, -1)
    all_patches = {a.name for a in b.assets if a.kind == "goal_patch"}
    patches = sorted({p for _, p in onpatch} - set(placed) - set(early_xy))
    patch_xy = {p: placed[p] for p in sorted(all_patches & set(placed))}  # placed by a relation ("behind the patch")
    pc = free_spots(list(placed.values()) + list(early_xy.values()), len(patches)) if patches and early_xy else \
        b.unit_centers(len(patches), 0.16) if patches else []
    patch_xy.update(zip(patches, pc, strict=True))
    for p, xy in sorted({**patch_xy, **early_xy}.items()):
        b.place_patch(p, xy)
    on_patch_by: dict[str, list[str]] = {}
    for a, p in onpatch:
        if p not in early_xy:
            on_patch_by.setdefault(p, []).append(base_of[a])
    for p, members in on_patch_by.items():
        members = list(dict.fromkeys(members))
        px, py = patch_xy[p]
        shape = next(a.shape for a in b.assets if a.name == p)
        for m, xy in zip(members, patch_spots((px, py), shape, len(members)), strict=True):
            placed[m] = xy
    free = [n for n in dict.fromkeys(base_of[n] for n in cube_names) if n not in placed]
    spots = iter(free_spots(list(placed.values()) + list(patch_xy.values()), len(free)))
    for n in free:
        placed[n] = next(spots)
    for ch in chains:
        b.place(stack_layout(ch, placed[ch[0]]))
    for n in cube_names:
        if n not in b.layout:
            b.place(stack_layout([n], placed[base_of[n]]))


_PER_TOWER_RE = re.compile(
    rf"(?:^|[,.;:!\-]|\band\b)\s*(?:and\s+)?(?:1|one|the\s+other(?:\s+1)?|another(?:\s+1)?|the\s+(?:first|second|third|fourth|last)"
    rf"(?:\s+1)?)(?:\s+(?:tower|stack))?\s+(?:(?:is|of|all|made|built|consisting|entirely|solely|purely|just|in|has|with|should\s+be|must\s+be|only)\s+)*"
    rf"(?P<run>(?:{COLOR_RE})(?:\s+(?:{COLOR_RE}))*)(?:\s+(?:blocks?|cubes?|ones?))?(?=\s*(?:[,.;]|\band\b|$))")
"""One tower's colour said after the towers are counted ("2 towers: one is red red, the other one
is blue blue"; "two towers, one red and one blue"): a colour alone colours the whole tower, a
colour said N times is a tower of N cubes of it.  Colours listed after a colon, one group per
tower between "and"s ("2 towers: red, red and blue, blue"), are read the same way."""


def _per_tower_colors(text: str, k: int, height: int) -> list[list[str]] | None:
    """Each of ``k`` towers' cubes when the words give every tower its own colour
    (:data:`_PER_TOWER_RE`), after the towers are counted; None when they do not.

    Raises:
        ParseError: a tower given several colours (its order unsaid).
    """
    counted = re.search(r"\b\d+\s+(?:[a-z\-]+\s+)?(?:towers|stacks)\b", text)
    if not counted:
        return None
    runs = [m.group("run").split() for m in _PER_TOWER_RE.finditer(text[counted.end():])]
    listed = re.fullmatch(rf"\s*:\s*((?:{COLOR_RE})(?:\s*,?\s*(?:{COLOR_RE}))*)((?:\s*(?:;|,?\s+and)\s+(?:{COLOR_RE})"
                          rf"(?:\s*,?\s*(?:{COLOR_RE}))*)+)\s*[.!]?\s*", text[counted.end():])
    if not runs and listed:  # "2 towers: red, red and blue, blue": the groups between "and"s, one per tower
        runs = [re.findall(rf"\b(?:{COLOR_RE})\b", g) for g in re.split(r";|\band\b", listed.group(0))]
    if len(runs) != k:
        return None
    if any(len({canon_color(c) for c in run}) > 1 for run in runs):
        raise ParseError(f"\"{text[:80]}\" gives a tower several colours and not their order; say each tower "
                         "from the bottom (e.g. \"one tower of red on blue\")")
    return [[canon_color(run[0])] * (len(run) if len(run) > 1 else height) for run in runs]


_TOWER_CHAIN_RE = re.compile(rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:\s+(?P<rel>on\s+top\s+of|onto|upon|on|atop|under|beneath|below)\s+(?:the\s+)?"
                             rf"(?:{COLOR_RE})(?:\s+(?:cube|block))?)+")
"""A tower's cubes said as a chain ("red on yellow", "blue under green under red"), in a text that asks for several towers."""


MAX_TOWERS = C.MAX_OBJECTS // 2
"""The most towers one task may ask for: two cubes each, :data:`rpg.domain.constants.MAX_OBJECTS` cubes in all."""


def _multi_stacks(f: Features, b: Builder, k: int) -> bool:
    if not 2 <= k <= MAX_TOWERS:  # "Build 0 towers.", "Build 100 towers." (each had crashed with a traceback)
        raise ParseError(f"\"{f.original[:80]}\" asks for {k} towers: a task here has from 2 to {MAX_TOWERS} towers "
                         f"({C.MAX_OBJECTS} cubes at most); say how many towers and their cubes")
    if re.search(r"\b(?:1|one)\s+of\s+(?:them|which|those)\b", f.text):  # "two towers of four cubes, one of them purple":
        raise ParseError(f"\"{f.original[:80]}\" picks 'one of them' among several towers: which tower or cube is not "  # (every
                         "said; say each tower (e.g. \"one tower of purple cubes and one of red cubes\"), or use --model")  # cube purple)
    if re.search(r"\b(?:different|differing|unequal|varying)\s+(?:heights?|sizes?|lengths?)\b|\bheights?\s+(?:differ|vary)", f.text):
        raise ParseError(f"\"{f.original[:80]}\" asks for towers of different heights without saying each one's; say how many "
                         "cubes each tower has, or use --model")
    colors = list(dict.fromkeys(f.color_list()))
    each = re.search(r"\b(?:towers|stacks)\s+(?:of|with)\s+(\d+)\b|\b(\d+)\s+(?:blocks?|cubes?)\s+(?:high|tall|each)\b", f.text)
    if each and int(each.group(1) or each.group(2)) < 2:  # "four towers of one cube" (it had been four towers of four)
        raise ParseError(f"\"{f.original[:80]}\" asks for towers of one cube: a tower needs two cubes or more; say how many "
                         "cubes each tower has")
    height = int(each.group(1) or each.group(2)) * k if each else stated_count(f, "block|cube", default=None)
    matching = f.has("matching", "same color", "color-specific", "respective", "each stack is the same", "colored goal")
    with_patches = f.has("patch", "patches", "target", "targets")
    if height and height >= 2 * k:
        height = height // k
    height = height if height and height >= 2 else 2
    per_tower = None if with_patches or matching else _per_tower_colors(f.text, k, height)
    counted = re.search(r"\b\d+\s+(?:[a-z\-]+\s+)?(?:towers|stacks)\b", f.text)
    told = len(list(_PER_TOWER_RE.finditer(f.text[counted.end():]))) if counted and not (with_patches or matching) else 0
    if per_tower is None and 0 < told < k:  # "two towers, two cubes each: one made only of red cubes": the other's colour unsaid
        raise ParseError(f"\"{f.original[:80]}\" says the cubes of {told} of its {k} towers; say each tower's (e.g. \"one tower of "
                         "red cubes and one of blue cubes\"), or use --model")
    patch_said = [canon_color(c) for m in re.finditer(rf"\b((?:{COLOR_RE})(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+)(?:{COLOR_RE}))*)\s+"
                                                       r"(?:goal\s+)?patch(?:es)?\b", f.text)
                  for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.group(1))]
    patch_colors: list[str] | None = None
    if with_patches and not matching and patch_said and set(colors) <= set(patch_said) \
            and not re.search(r"\b(?:its|their|own|same|matching)\s+colou?r", f.text) \
            and not re.search(rf"\b(?:{COLOR_RE})\s+(?:cubes?|blocks?|ones?|bricks?)\b", f.text):  # no cube named by colour
        # "two towers of two cubes, one on the white patch and one on the black patch": the patches' colours, not the
        # cubes' (the cubes had been made white and black, a colour no word gave them)
        if len(patch_said) != k:
            raise ParseError(f"\"{f.original[:80]}\" puts {k} towers on {len(patch_said)} patches named; say which tower goes "
                             "on which patch, or use --model")
        patch_colors = patch_said
        stack_colors = [[next(c for c in DEFAULT_COLORS if c not in patch_said)] * height for _ in range(k)]
    elif per_tower:
        stack_colors = per_tower
    elif len(colors) == 1 and not with_patches:
        stack_colors = [[colors[0]] * height for _ in range(k)]
    elif not colors and not with_patches and not matching and each and f.has(*lexicon.DIFFERENT_WORDS):
        # "two towers of three cubes of different colours": which colours is not said (they had been made all red)
        raise ParseError(f"\"{f.original[:80]}\" says the cubes differ but names no colour; say the colours (e.g. \"one tower of "
                         "red cubes and one of blue cubes\"), or use --model")
    elif not colors and not with_patches and not matching and each:
        # "two towers of three cubes": no colour said, so which cubes make which tower is free; cubes of one colour are
        # interchangeable (evaluate_goal tries their assignments), so any two towers of three pass (a red tower and a
        # blue tower had been demanded)
        stack_colors = [[colors_for(1, f)[0]] * height for _ in range(k)]
    else:
        if not (matching or with_patches) and len(colors) > 1 and re.search(
                r"\b(?:1|the\s+other|another|the\s+(?:first|second|third|last))\b(?!\s+(?:of|on|in|to)\b)",
                f.text[f.text.find("tower"):]):  # "two towers, two cubes each: one made only of red cubes and one ...": each
            raise ParseError(f"\"{f.original[:80]}\" says each tower's cubes in words not read for each tower; say "  # tower's
                             "each tower (e.g. \"one tower of two red cubes and one tower of two blue cubes\"), or use --model")  # own
        palette = colors_for(k, f, prefer=colors)
        stack_colors = [[c] * height for c in palette] if (matching or with_patches or len(colors) <= 1) else [
            colors_for(height, f) for _ in range(k)]
        chain = _TOWER_CHAIN_RE.search(f.text)  # "two towers, each red on yellow": every tower yellow under red (the list
        if chain and not (matching or with_patches):  # order had put red at the bottom: silently wrong)
            if len(re.findall(r"\b(?:towers?|stacks?|columns?)\b", f.text)) > 1:  # "two red-on-yellow towers and one yellow
                raise ParseError(f"\"{f.original[:80]}\" names towers of more than one kind around the chain "  # tower"
                                 f"'{chain.group(0)}'; say each tower in a sentence of its own, or use --model")
            said = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", chain.group(0))]
            up = said[::-1] if chain.group("rel") != "under" else said
            if not each and stated_count(f, "block|cube", default=None) is None:
                height = len(said)  # "two towers of red on yellow on blue": as tall as the chain
            if len(set(said)) != len(said) or set(said) != set(colors) or len(said) != height:
                raise ParseError(f"\"{f.original[:80]}\" stacks '{chain.group(0)}' in {k} towers of {height} cubes: which "
                                 "cubes make each tower is not said; say each tower (e.g. \"one tower of red on blue and one "
                                 "of green on yellow\"), or use --model")
            stack_colors = [list(up) for _ in range(k)]
    centers = b.unit_centers(k, 0.16)
    if len(centers) < k or len(stack_colors) != k:  # more towers than the grid or the palette holds ("Build 20 towers.": it had crashed)
        raise ParseError(f"\"{f.original[:80]}\" asks for {k} towers: more than fit the workspace; use fewer towers")
    for i, (cols, xy) in enumerate(zip(stack_colors, centers, strict=True)):
        names = [b.cube(c) for c in cols]
        b.place(stack_layout(names, xy))
        b.preds.append(Stack(tuple(names)))
        if with_patches:
            p = b.patch(patch_colors[i] if patch_colors else cols[0])
            b.place_patch(p, xy)
            b.preds.append(OnPatch(names[0], p))
    b.primitives += ["stack"]
    b.summary.append(f"{k} towers of {height} cubes" + (", each on the patch of its color" if with_patches else ""))
    return True
