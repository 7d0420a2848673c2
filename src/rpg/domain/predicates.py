"""Goal predicates: the vocabulary success predicates G are written in.

Each predicate is a small immutable object.  ``evaluate(state)`` returns a
:class:`PredicateResult` that says whether it holds and explains why: which objects,
the measured values and the tolerances (in the spirit of BDDL's satisfied / unsatisfied
diagnostics).  Predicates are evaluated on a :class:`~rpg.domain.state.WorldState`, so
they can be tested on constructed states.  All tolerances are named constants in
:mod:`rpg.domain.constants`.

Frame: see :mod:`rpg.domain.constants` ("left" = +y, "in front of" = smaller x).

Indistinguishable objects (same kind, colour and labels) may be swapped by a policy
without changing what the scene means, so :func:`evaluate_goal` accepts any assignment
of interchangeable objects that satisfies the goal.

Every predicate serialises to a plain dict (``to_dict``) and back (:func:`from_dict`), and
its ``repr`` is the Python expression that builds it (used by code generation).
"""

from __future__ import annotations

import ast
import itertools
import math
import re
from collections import Counter
from dataclasses import MISSING, dataclass, field, fields, replace
from typing import Any, ClassVar

import numpy as np

from rpg.domain import constants as C
from rpg.domain.layouts import layered_sites
from rpg.domain.palette import GRADIENT_ORDER
from rpg.domain.state import DIRECTIONS, ObjectState, WorldState

# ---------------------------------------------------------------------------
# Results
# ---------------------------------------------------------------------------


def _clean(value: Any) -> Any:
    if isinstance(value, float | np.floating):
        v = float(value)
        return round(v, 6) if math.isfinite(v) else None
    if isinstance(value, np.ndarray):
        return [_clean(v) for v in value.tolist()]
    if isinstance(value, dict):
        return {str(k): _clean(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_clean(v) for v in value]
    if isinstance(value, np.integer | np.bool_):
        return value.item()
    return value


_FIELD_NAMES: dict[type, tuple[str, ...]] = {}
"""Field names of each predicate class (``dataclasses.fields`` is slow for a per-step call)."""
_QUIET_DEFAULTS: dict[type, dict[str, object]] = {}
"""Default of each ``quiet_defaults`` field of each predicate class (:meth:`Predicate._quiet`)."""


@dataclass
class PredicateResult:
    """Outcome of evaluating one predicate.

    Attributes:
        name: predicate name, e.g. ``"on"``.
        args: the predicate's arguments (object names, parameters).
        satisfied: whether it holds.
        measured: the measured values behind the verdict (m, rad, cosines).
        tolerance: the thresholds it was judged against.
        reason: one line explaining the verdict.
        children: results of sub-predicates (for composites).
    """

    name: str
    args: dict
    satisfied: bool
    measured: dict = field(default_factory=dict)
    tolerance: dict = field(default_factory=dict)
    reason: str = ""
    children: list[PredicateResult] = field(default_factory=list)

    def __bool__(self) -> bool:
        return self.satisfied

    def leaves(self) -> list[PredicateResult]:
        """All leaf results (composites flattened)."""
        if not self.children:
            return [self]
        return [leaf for c in self.children for leaf in c.leaves()]

    @property
    def satisfied_list(self) -> list[PredicateResult]:
        return [r for r in self.leaves() if r.satisfied]

    @property
    def unsatisfied_list(self) -> list[PredicateResult]:
        return [r for r in self.leaves() if not r.satisfied]

    def to_json(self) -> dict:
        doc = {
            "name": self.name,
            "args": _clean(self.args),
            "satisfied": bool(self.satisfied),
            "measured": _clean(self.measured),
            "tolerance": _clean(self.tolerance),
            "reason": self.reason,
        }
        if self.children:
            doc["children"] = [c.to_json() for c in self.children]
        return doc


# ---------------------------------------------------------------------------
# Base classes and registry
# ---------------------------------------------------------------------------

PREDICATES: dict[str, type[Predicate]] = {}
"""Predicate name -> class."""


@dataclass(frozen=True)
class Predicate:
    """Base of all predicates.

    Subclasses set ``name`` and implement ``_evaluate``.  Fields named in ``object_fields``
    hold one object name; fields in ``list_fields`` hold a list of object names.
    """

    name: ClassVar[str] = "predicate"
    object_fields: ClassVar[tuple[str, ...]] = ()
    list_fields: ClassVar[tuple[str, ...]] = ()
    quiet_defaults: ClassVar[tuple[str, ...]] = ()
    """Fields left out of :meth:`args` and :meth:`to_dict` while at their default (added after tasks were written)."""
    semantic: ClassVar[bool] = False
    swap_invariant: ClassVar[bool] = False
    """True when the result cannot change by swapping interchangeable objects (the predicate
    compares positions, signatures or labels, never object identities)."""
    cue: ClassVar[str] = ""
    """Regular expression over the parser's normalised text: words that ask for this
    predicate (reverse accounting, :mod:`rpg.schema.citations`, cites them for its
    ``structure`` constraint when mention accounting did not consume a word for it)."""
    opaque: ClassVar[bool] = False
    """True when the children are not demands of their own (a negation)."""
    phrases: ClassVar[str] = ""
    """Regular expression over the parser's normalised text: how an instruction states this
    relation between the cubes it names ("to the left of", "beside"); the relational reader
    reads these (:data:`rpg.schema.lexicon.REL_PATTERNS`).  Empty for a predicate that is not
    stated as a relation between two cubes."""
    phrase: ClassVar[str] = ""
    """How a canonical instruction states the relation ("to the left of")."""
    loose_phrases: ClassVar[str] = ""
    """Words that speak of this relation without taking an object ("apart", "nearby"): mention
    accounting (:data:`rpg.schema.accounting.RELATION_WORDS`) counts them with ``phrases``."""
    carried_by: ClassVar[tuple[str, ...]] = ()
    """Other goal predicates that can state what this relation's words ask for (a row carries
    "left of", a pyramid "next to"): mention accounting accepts any of them for the words."""

    def __post_init__(self) -> None:
        for f in self.list_fields:
            object.__setattr__(self, f, tuple(getattr(self, f)))
        if hasattr(self, "groups"):
            object.__setattr__(self, "groups", tuple(tuple(g) for g in self.groups))
        if hasattr(self, "events"):
            object.__setattr__(self, "events", tuple(self.events))

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "name" in cls.__dict__:
            PREDICATES[cls.name] = cls

    # -- evaluation ----------------------------------------------------------
    def evaluate(self, state: WorldState) -> PredicateResult:
        """Evaluate on a world state.

        Raises:
            KeyError: the predicate names an object the state lacks (message lists them).
        """
        return self._evaluate(state)

    def _evaluate(self, state: WorldState) -> PredicateResult:
        raise NotImplementedError

    def _result(self, satisfied: bool, reason: str, measured=None, tolerance=None, children=None):
        return PredicateResult(
            self.name, self.args(), bool(satisfied), measured or {}, tolerance or {}, reason,
            children or [],
        )

    # -- structure -----------------------------------------------------------
    def args(self) -> dict:
        names = _FIELD_NAMES.get(type(self))
        if names is None:
            names = _FIELD_NAMES.setdefault(type(self), tuple(f.name for f in fields(self)))
        return {n: getattr(self, n) for n in names if not self._quiet(n)}

    def _quiet(self, name: str) -> bool:
        """Whether field ``name`` is left out of :meth:`args` and :meth:`to_dict`: one of ``quiet_defaults`` at its
        default (a field added later, so the files and hashes of tasks written before it stay as they were)."""
        if name not in self.quiet_defaults:
            return False
        defaults = _QUIET_DEFAULTS.get(type(self))
        if defaults is None:  # args() runs per step: fields() once per class
            defaults = _QUIET_DEFAULTS.setdefault(type(self), {f.name: f.default for f in fields(self) if f.name in self.quiet_defaults})
        return getattr(self, name) == defaults[name]

    def object_names(self) -> list[str]:
        """Every object the predicate mentions, in order of appearance."""
        names: list[str] = []
        for f in self.object_fields:
            names.append(getattr(self, f))
        for f in self.list_fields:
            names.extend(getattr(self, f))
        for child in self.children():
            names.extend(child.object_names())
        return names

    def children(self) -> list[Predicate]:
        return []

    # -- what it demands (reverse accounting, rpg.schema.citations) -----------
    def params(self) -> dict:
        """Arguments other than objects and sub-predicates (an axis, a region, a text)."""
        skip = set(self.object_fields) | set(self.list_fields)
        return {k: v for k, v in self.args().items()
                if k not in skip and (v is None or isinstance(v, str | int | float | bool))}

    def constraints(self) -> list[tuple[str, dict]]:
        """What this predicate demands, part by part, as ``(kind, fields)`` pairs:

        - ``("structure", {"predicate": name, **params})``: the relation or structure itself;
        - ``("count", {"predicate": name, "objects": names})``: how many objects it holds;
        - ``("members", {"objects": names})``: which objects take part (their identity);
        - ``("order", {"relation": r, "pairs": ((x, y), ...)})``: roles or a sequence, each
          pair "x r y" (``on``: x rests on y; a direction: x comes before y);
        - ``("place", {"object": name, "region": r} | {"object": name, "patch": name})``.

        Composites return ``[]`` (their leaves speak for themselves).  Subclasses declare
        their own; this default is a structure over a set of objects.
        """
        if self.children():
            return []
        objs = tuple(dict.fromkeys(self.object_names()))
        out: list[tuple[str, dict]] = [("structure", {"predicate": self.name, **self.params()})]
        if self.list_fields:
            out.append(("count", {"predicate": self.name, "objects": objs}))
        return out + [("members", {"objects": objs})]

    def counts(self) -> set[int]:
        """How many cubes an instruction may count for this predicate: the objects of each list
        field, and each integer argument (a base, a number of rows).  Subclasses add the sizes
        of their parts (a pyramid's layers).  Used by the accounting of numbers said
        (:func:`rpg.schema.accounting.unaccounted`)."""
        out = {len(getattr(self, f)) for f in self.list_fields}
        return out | {v for v in self.params().values() if isinstance(v, int) and not isinstance(v, bool)}

    def relax(self, kind: str, goal: Predicate | None = None) -> Predicate | None:
        """This predicate without its constraint of ``kind`` (accepting every configuration
        it did and those that differ only there), or None when the domain has no such
        predicate (then a constraint of that kind nobody stated makes the compile refuse).
        ``goal`` is the whole goal it is part of."""
        return None

    def map_children(self, fn) -> Predicate:
        """A copy with ``fn`` applied to each child (composites); leaves return themselves."""
        return self

    def walk(self):
        """This predicate and every predicate below it, depth first (yields Predicate)."""
        yield self
        for child in self.children():
            yield from child.walk()

    def conjuncts(self) -> list[Predicate]:
        """The parts that must all hold: an ``and`` flattened (nested ``and`` too), else ``[self]``."""
        return [self]

    def support_edges(self) -> list[tuple[str, str]]:
        """(upper, lower) support relations this predicate asserts; ``"table"`` is ground."""
        return [e for c in self.children() for e in c.support_edges()]

    def semantic_faces(self, state: WorldState) -> list[tuple[str, str]]:
        """(object, world direction) of faces whose labels this predicate reads."""
        return [f for c in self.children() for f in c.semantic_faces(state)]

    def rename(self, mapping: dict[str, str]) -> Predicate:
        """A copy with object names substituted through ``mapping``."""
        changes: dict[str, Any] = {}
        for f in self.object_fields:
            v = getattr(self, f)
            changes[f] = mapping.get(v, v)
        for f in self.list_fields:
            changes[f] = tuple(mapping.get(v, v) for v in getattr(self, f))
        return replace(self, **changes)

    def to_dict(self) -> dict:
        """Plain-data form: ``{"predicate": name, <field>: value, ...}``."""
        doc: dict[str, Any] = {"predicate": self.name}
        for f in fields(self):
            if self._quiet(f.name):
                continue
            v = getattr(self, f.name)
            if isinstance(v, tuple) and v and isinstance(v[0], Predicate):
                doc[f.name] = [c.to_dict() for c in v]
            elif isinstance(v, Predicate):
                doc[f.name] = v.to_dict()
            elif isinstance(v, tuple):
                doc[f.name] = [list(x) if isinstance(x, tuple) else x for x in v]
            else:
                doc[f.name] = v
        return doc

    def __repr__(self) -> str:
        parts = []
        for f in fields(self):
            v = getattr(self, f.name)
            if f.default is not MISSING and v == f.default:
                continue
            parts.append(f"{f.name}={_py(v)}")
        return f"{type(self).__name__}({', '.join(parts)})"

    def describe(self) -> str:
        """Short natural-language description (used for goal summaries)."""
        return repr(self)


def _py(value: Any) -> str:
    if isinstance(value, tuple):
        inner = ", ".join(_py(v) for v in value)
        return f"[{inner}]"
    if isinstance(value, float):
        return repr(round(value, 6))
    return repr(value)


def from_dict(doc: dict) -> Predicate:
    """Build a predicate from its ``to_dict`` form.

    Raises:
        ValueError: unknown predicate name or bad arguments (message lists the known ones).
    """
    if not isinstance(doc, dict) or "predicate" not in doc:
        raise ValueError("a predicate must be a mapping with a 'predicate' key")
    kind = doc["predicate"]
    cls = PREDICATES.get(kind)
    if cls is None:
        raise ValueError(f"unknown predicate {kind!r}; known: {', '.join(sorted(PREDICATES))}")
    kwargs = {}
    names = {f.name for f in fields(cls)} | ({"children"} if cls is And else set())
    for key, value in doc.items():
        if key == "predicate":
            continue
        if key not in names:
            raise ValueError(f"predicate {kind!r} has no argument {key!r}")
        if key in ("children", "events"):
            kwargs[key] = tuple(from_dict(v) for v in value)
        elif key == "child":
            kwargs[key] = from_dict(value)
        elif key == "groups":
            kwargs[key] = tuple(tuple(g) for g in value)
        elif isinstance(value, list):
            kwargs[key] = tuple(value)
        else:
            kwargs[key] = value
    try:
        return cls(**kwargs)
    except TypeError as exc:
        raise ValueError(f"bad arguments for predicate {kind!r}: {exc}") from None


def _planar(o: ObjectState) -> np.ndarray:
    return np.asarray(o.pos[:2], float)


def _signature(o: ObjectState) -> tuple:
    return o.signature


def _table_gap(o: ObjectState) -> float:
    return float(o.pos[2] - C.TABLE_TOP_Z - o.half_height)


# ---------------------------------------------------------------------------
# Support and placement
# ---------------------------------------------------------------------------


@dataclass(frozen=True, repr=False)
class On(Predicate):
    """``a`` rests on top of ``b``: centred within ON_XY_TOL and touching within ON_Z_TOL."""

    a: str
    b: str
    name: ClassVar[str] = "on"
    cue: ClassVar[str] = r"\b(?:stack\w*|tower\w*|pile\w*|on\s+top|onto|atop|upon|on|above|over|under|below|beneath|underneath)\b"
    phrases: ClassVar[str] = r"on top of|onto|on to|atop|above|over(?! to\b| there\b| here\b| near\b| next\b| by\b| beside\b| \d| one\b| two\b| three\b| four\b| five\b| six\b)|on"
    phrase: ClassVar[str] = "on top of"
    reverse_phrases: ClassVar[str] = r"under|underneath|beneath|below"
    """How an instruction states the relation with its cubes swapped ("X under Y": Y on X)."""
    object_fields: ClassVar[tuple[str, ...]] = ("a", "b")

    def _evaluate(self, state):
        a, b = state[self.a], state[self.b]
        dxy = float(np.linalg.norm(_planar(a) - _planar(b)))
        gap = float(a.pos[2] - b.pos[2] - a.half_height - b.half_height)
        ok = dxy <= C.ON_XY_TOL and abs(gap) <= C.ON_Z_TOL
        reason = f"{self.a} {'is' if ok else 'is not'} on {self.b} (offset {dxy * 100:.1f} cm, gap {gap * 1000:.1f} mm)"
        return self._result(ok, reason, {"xy_offset": dxy, "z_gap": gap},
                            {"xy_offset": C.ON_XY_TOL, "z_gap": C.ON_Z_TOL})

    def support_edges(self):
        return [(self.a, self.b)]

    def constraints(self):
        return [("structure", {"predicate": "stack"}), ("members", {"objects": (self.a, self.b)}),
                ("order", {"relation": "on", "pairs": ((self.a, self.b),)})]

    def describe(self):
        return f"{self.a} on {self.b}"


@dataclass(frozen=True, repr=False)
class OnTable(Predicate):
    """``a`` rests directly on the table surface."""

    a: str
    name: ClassVar[str] = "on_table"
    object_fields: ClassVar[tuple[str, ...]] = ("a",)

    def _evaluate(self, state):
        a = state[self.a]
        gap = _table_gap(a)
        ok = abs(gap) <= C.TABLE_Z_TOL
        return self._result(ok, f"{self.a} {'rests' if ok else 'does not rest'} on the table (gap {gap * 1000:.1f} mm)",
                            {"z_gap": gap}, {"z_gap": C.TABLE_Z_TOL})

    def support_edges(self):
        return [(self.a, "table")]

    def constraints(self):
        return [("place", {"object": self.a, "region": "table"})]

    def describe(self):
        return f"{self.a} on the table"


@dataclass(frozen=True, repr=False)
class OnPatch(Predicate):
    """``a`` rests on the table with its centre over goal patch ``patch``."""

    a: str
    patch: str
    name: ClassVar[str] = "on_patch"
    object_fields: ClassVar[tuple[str, ...]] = ("a", "patch")

    def _evaluate(self, state):
        a, p = state[self.a], state[self.patch]
        local = p.rotation.T @ (np.asarray(a.pos) - np.asarray(p.pos))
        half = np.asarray(p.size[:2]) / 2 + C.PATCH_XY_MARGIN
        over = np.abs(local[:2]) - half
        gap = _table_gap(a)
        inside = bool(np.all(over <= 0))
        ok = inside and abs(gap) <= C.TABLE_Z_TOL
        why = "inside" if inside else f"outside by {max(over) * 100:.1f} cm"
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} on {self.patch} ({why}, table gap {gap * 1000:.1f} mm)",
                            {"overhang": float(max(over)), "z_gap": gap},
                            {"overhang": 0.0, "z_gap": C.TABLE_Z_TOL, "margin": C.PATCH_XY_MARGIN})

    def support_edges(self):
        return [(self.a, "table")]

    def constraints(self):
        return [("members", {"objects": (self.a,)}), ("place", {"object": self.a, "patch": self.patch})]

    def relax(self, kind, goal=None):
        """Which cube of a stack rests on the patch, when nobody said: any of them
        (:class:`StackOnPatch`, "stack the blocks on the goal patch")."""
        if kind != "identity" or goal is None:
            return None
        edges = [(u, lo) for u, lo in goal.support_edges() if lo != "table"]
        tower, grew = {self.a}, True
        while grew:
            grew = False
            for u, lo in edges:
                if (u in tower) != (lo in tower):
                    tower |= {u, lo}
                    grew = True
        if len(tower) < 2:
            return None
        return StackOnPatch(self.a, self.patch, tuple(sorted(tower)))

    def describe(self):
        return f"{self.a} on {self.patch}"


@dataclass(frozen=True, repr=False)
class StackOnPatch(OnPatch):
    """The bottom cube of a stack of ``among`` rests on goal patch ``patch``, whichever cube
    that is ("stack the blocks on the goal patch" names none); ``a`` is the one the goal
    configuration puts there (a plan, never a requirement)."""

    among: tuple[str, ...] = ()
    name: ClassVar[str] = "stack_on_patch"
    list_fields: ClassVar[tuple[str, ...]] = ("among",)
    swap_invariant: ClassVar[bool] = True

    def _evaluate(self, state):
        results = [OnPatch(n, self.patch).evaluate(state) for n in self.among]
        ok = any(r.satisfied for r in results)
        return self._result(ok, f"{'a' if ok else 'no'} cube of {', '.join(self.among)} rests on {self.patch}",
                            children=results)

    def object_names(self):
        return list(dict.fromkeys([*self.among, self.a, self.patch]))

    def constraints(self):
        return [("members", {"objects": self.among}), ("place", {"object": self.among, "patch": self.patch})]

    def relax(self, kind, goal=None):
        return None

    def describe(self):
        return f"the stack of {', '.join(self.among)} on {self.patch}"


@dataclass(frozen=True, repr=False)
class Upright(Predicate):
    """The cube's local +z points up (cosine >= UPRIGHT_COS)."""

    a: str
    name: ClassVar[str] = "upright"
    object_fields: ClassVar[tuple[str, ...]] = ("a",)

    def _evaluate(self, state):
        cos = float(state[self.a].rotation[2, 2])
        ok = cos >= C.UPRIGHT_COS
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} upright (cos {cos:.3f})",
                            {"cos": cos}, {"cos": C.UPRIGHT_COS})

    def constraints(self):
        return []  # every cube of every goal stands upright; no word asks it

    def describe(self):
        return f"{self.a} upright"


# ---------------------------------------------------------------------------
# Pairwise spatial relations
# ---------------------------------------------------------------------------


@dataclass(frozen=True, repr=False)
class _Relation(Predicate):
    """``a`` stands on one side of ``b`` along the relation's axis, at least ``RELATION_MIN_GAP`` (m) beyond it, and
    level with it across that axis (within ``RELATION_MAX_OFF_AXIS``), unless ``diagonal``: one of two relations
    between the same cubes along both axes ("to the right of the white block and in front of it": diagonally), where
    each relation leaves the other axis to the other."""

    a: str
    b: str
    diagonal: bool = False
    object_fields: ClassVar[tuple[str, ...]] = ("a", "b")
    quiet_defaults: ClassVar[tuple[str, ...]] = ("diagonal",)
    axis: ClassVar[int] = 1
    sign: ClassVar[float] = 1.0
    words: ClassVar[str] = ""
    converse: ClassVar[str] = ""
    """The relation that holds exactly when this one does with ``a`` and ``b`` swapped (same axis, opposite sign:
    ``left_of(a, b)`` is ``right_of(b, a)``)."""

    def _evaluate(self, state):
        a, b = state[self.a], state[self.b]
        d = np.asarray(a.pos) - np.asarray(b.pos)
        along = float(self.sign * d[self.axis])
        across = float(abs(d[1 - self.axis]))
        ok = along >= C.RELATION_MIN_GAP and (self.diagonal or across <= C.RELATION_MAX_OFF_AXIS)
        return self._result(
            ok,
            f"{self.a} {'is' if ok else 'is not'} {self.words} {self.b} (along {along * 100:.1f} cm, across {across * 100:.1f} cm)",
            {"along": along, "across": across},
            {"min_along": C.RELATION_MIN_GAP} if self.diagonal else {"min_along": C.RELATION_MIN_GAP, "max_across": C.RELATION_MAX_OFF_AXIS},
        )

    def constraints(self):
        return [("structure", {"predicate": self.name}), ("members", {"objects": (self.a, self.b)}),
                ("order", {"relation": self.name, "pairs": ((self.a, self.b),)})]

    def describe(self):
        return f"{self.a} {self.words} {self.b}"  # diagonal: said by the pair's other relation


@dataclass(frozen=True, repr=False)
class LeftOf(_Relation):
    """``a`` is left of ``b`` (larger y), roughly level with it in x."""

    name: ClassVar[str] = "left_of"
    phrases: ClassVar[str] = r"on (?:the )?left(?: hand)? side of|to the left of|on the left of|left of"
    carried_by: ClassVar[tuple[str, ...]] = ("right_of", "in_line", "between", "sorted_by", "reads", "equation")
    phrase: ClassVar[str] = "to the left of"
    cue: ClassVar[str] = r"\bleft\b|\bwest\b"
    axis: ClassVar[int] = 1
    sign: ClassVar[float] = 1.0
    words: ClassVar[str] = "left of"
    converse: ClassVar[str] = "right_of"


@dataclass(frozen=True, repr=False)
class RightOf(_Relation):
    """``a`` is right of ``b`` (smaller y)."""

    name: ClassVar[str] = "right_of"
    phrases: ClassVar[str] = r"on (?:the )?right(?: hand)? side of|to the right of|on the right of|right of"
    carried_by: ClassVar[tuple[str, ...]] = ("left_of", "in_line", "between", "sorted_by", "reads", "equation")
    phrase: ClassVar[str] = "to the right of"
    cue: ClassVar[str] = r"\bright\b|\beast\b"
    axis: ClassVar[int] = 1
    sign: ClassVar[float] = -1.0
    words: ClassVar[str] = "right of"
    converse: ClassVar[str] = "left_of"


@dataclass(frozen=True, repr=False)
class InFrontOf(_Relation):
    """``a`` is in front of ``b``: closer to the robot (smaller x)."""

    name: ClassVar[str] = "in_front_of"
    phrases: ClassVar[str] = r"in front of"
    carried_by: ClassVar[tuple[str, ...]] = ("behind", "in_line", "between")
    phrase: ClassVar[str] = "in front of"
    cue: ClassVar[str] = r"\bfront\b|\bsouth\b"
    axis: ClassVar[int] = 0
    sign: ClassVar[float] = -1.0
    words: ClassVar[str] = "in front of"
    converse: ClassVar[str] = "behind"


@dataclass(frozen=True, repr=False)
class Behind(_Relation):
    """``a`` is behind ``b``: farther from the robot (larger x)."""

    name: ClassVar[str] = "behind"
    phrases: ClassVar[str] = r"behind|in back of|at the back of"
    carried_by: ClassVar[tuple[str, ...]] = ("in_front_of", "in_line", "between")
    phrase: ClassVar[str] = "behind"
    cue: ClassVar[str] = r"\bbehind\b|\bback\b|\bnorth\b"
    axis: ClassVar[int] = 0
    sign: ClassVar[float] = 1.0
    words: ClassVar[str] = "behind"
    converse: ClassVar[str] = "in_front_of"


@dataclass(frozen=True, repr=False)
class NextTo(Predicate):
    """``a`` is beside ``b`` at the same level (their bottom faces within ON_Z_TOL of one
    another: a cube beside a flat goal patch stands on the table as the patch does), centres
    within NEXT_TO_MAX_DIST in the plane (m, world frame)."""

    a: str
    b: str
    name: ClassVar[str] = "next_to"
    phrases: ClassVar[str] = r"next to|beside|adjacent to|alongside|near|close to"
    loose_phrases: ClassVar[str] = r"nearby|adjacent"
    carried_by: ClassVar[tuple[str, ...]] = ("in_line", "grid", "pyramid", "in_region", "on_patch", "between", "left_of",
                                             "right_of", "in_front_of", "behind")
    phrase: ClassVar[str] = "next to"
    cue: ClassVar[str] = r"\b(?:next\s+to|beside|adjacent|near\w*|close|touch\w*|together|side\s+by\s+side|alongside)\b"
    object_fields: ClassVar[tuple[str, ...]] = ("a", "b")

    def _evaluate(self, state):
        a, b = state[self.a], state[self.b]
        dist = float(np.linalg.norm(_planar(a) - _planar(b)))
        dz = float(abs((a.pos[2] - a.size[2] / 2) - (b.pos[2] - b.size[2] / 2)))  # bottom faces
        ok = dist <= C.NEXT_TO_MAX_DIST and dz <= C.ON_Z_TOL
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} next to {self.b} ({dist * 100:.1f} cm apart)",
                            {"distance": dist, "dz": dz}, {"distance": C.NEXT_TO_MAX_DIST, "dz": C.ON_Z_TOL})

    def describe(self):
        return f"{self.a} next to {self.b}"


@dataclass(frozen=True, repr=False)
class FarFrom(Predicate):
    """``a`` and ``b`` are at least FAR_FROM_MIN_DIST apart in the plane."""

    a: str
    b: str
    name: ClassVar[str] = "far_from"
    phrases: ClassVar[str] = r"far (?:away )?from|away from"
    loose_phrases: ClassVar[str] = r"apart"
    phrase: ClassVar[str] = "far from"
    cue: ClassVar[str] = r"\b(?:far|apart|away|distant|separat\w*)\b"
    object_fields: ClassVar[tuple[str, ...]] = ("a", "b")

    def _evaluate(self, state):
        dist = float(np.linalg.norm(_planar(state[self.a]) - _planar(state[self.b])))
        ok = dist >= C.FAR_FROM_MIN_DIST
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} far from {self.b} ({dist * 100:.1f} cm apart)",
                            {"distance": dist}, {"min_distance": C.FAR_FROM_MIN_DIST})

    def describe(self):
        return f"{self.a} far from {self.b}"


def region_bounds(region: str) -> tuple[tuple[float, float], tuple[float, float]]:
    """The ((x_min, x_max), (y_min, y_max)) of a named workspace region, m, world frame.

    Raises:
        ValueError: ``region`` is not one of :data:`constants.REGION_NAMES`.
    """
    if region not in C.REGION_NAMES:
        raise ValueError(f"unknown region {region!r}; known: {', '.join(C.REGION_NAMES)}")
    (x0, x1), (y0, y1) = C.WORKSPACE_X, C.WORKSPACE_Y
    dx, dy = (x1 - x0) / 3, (y1 - y0) / 3
    xs = {"front": (x0, x0 + dx), "back": (x1 - dx, x1), "mid": (x0 + dx, x1 - dx), "any": (x0, x1)}
    ys = {"right": (y0, y0 + dy), "left": (y1 - dy, y1), "mid": (y0 + dy, y1 - dy), "any": (y0, y1)}
    parts = region.split("_")
    fb = next((p for p in parts if p in ("front", "back")), "mid" if region == "center" else "any")
    lr = next((p for p in parts if p in ("left", "right")), "mid" if region == "center" else "any")
    return xs[fb], ys[lr]


def region_boxes(region: str) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The boxes ((x_min, x_max), (y_min, y_max)), m, world frame, whose union is a region:
    one for a name of :data:`constants.REGION_NAMES`, one per member for a group of
    :data:`constants.REGION_GROUPS` ("corner", "edge").

    Raises:
        ValueError: ``region`` is neither a region nor a group.
    """
    if region in C.REGION_GROUPS:
        return [region_bounds(r) for r in C.REGION_GROUPS[region]]
    if region not in C.REGION_NAMES:
        raise ValueError(f"unknown region {region!r}; known: {', '.join((*C.REGION_NAMES, *C.REGION_GROUPS))}")
    return [region_bounds(region)]


def point_in_region(x: float, y: float, region: str) -> bool:
    """Whether the point (x, y), m, world frame, lies in a region or region group (:func:`region_boxes`; edges included).

    Raises:
        ValueError: ``region`` is neither a region nor a group.
    """
    return any(x0 <= x <= x1 and y0 <= y <= y1 for (x0, x1), (y0, y1) in region_boxes(region))


def describe_region(region: str) -> str:
    """How a region or region group is said: "the back left corner", "the left side", "a corner"."""
    where = region.replace("_", " ")
    if region in C.REGION_GROUPS:
        return f"an {where}" if where[0] in "aeiou" else f"a {where}"
    if region in ("left", "right", "front", "back"):
        return f"the {where} side"
    return f"the {where}{' corner' if '_' in region else ''}"


@dataclass(frozen=True, repr=False)
class InRegion(Predicate):
    """``a``'s centre lies in a region of the workspace (constants.REGION_NAMES) or a group (REGION_GROUPS).

    A group holds in any of its members (:func:`region_boxes`): "at the corner" in each of
    the four corners, "at the edge" anywhere but the centre."""

    a: str
    region: str
    name: ClassVar[str] = "in_region"
    object_fields: ClassVar[tuple[str, ...]] = ("a",)

    def __post_init__(self) -> None:
        super().__post_init__()
        region_boxes(self.region)  # raises on an unknown region

    def _evaluate(self, state):
        boxes = region_boxes(self.region)
        x, y = (float(v) for v in state[self.a].pos[:2])
        ok = point_in_region(x, y, self.region)
        spans = "; ".join(f"x {x0:.3f}..{x1:.3f}, y {y0:.3f}..{y1:.3f}" for (x0, x1), (y0, y1) in boxes)
        # a named region keeps its message and tolerance as before groups (validation logs, hashes)
        where = describe_region(self.region) if self.region in C.REGION_GROUPS else f"the {self.region.replace('_', ' ')}"
        tolerance = ({"x": list(boxes[0][0]), "y": list(boxes[0][1])} if len(boxes) == 1
                     else {"boxes": [[list(bx), list(by)] for bx, by in boxes]})
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} in {where} of the workspace "
                                f"(at x {x:.3f}, y {y:.3f}; region {spans})", {"x": x, "y": y}, tolerance)

    def constraints(self):
        return [("members", {"objects": (self.a,)}), ("place", {"object": self.a, "region": self.region})]

    def describe(self):
        where = describe_region(self.region)
        return f"{self.a} {'on' if where.endswith(' side') else 'in'} {where} of the workspace"


@dataclass(frozen=True, repr=False)
class CentredIn(Predicate):
    """The mean of ``objects``' centres (a structure's middle) lies in a region of the workspace
    (constants.REGION_NAMES or REGION_GROUPS), m, world frame: "a circle of four cubes in the
    centre of the table", whose cubes cannot all stand in the centre third (issue 30: the words
    place the structure, not each cube)."""

    objects: tuple[str, ...]
    region: str
    name: ClassVar[str] = "centred_in"
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def __post_init__(self) -> None:
        super().__post_init__()
        region_boxes(self.region)  # raises on an unknown region
        if len(self.objects) < 2:
            raise ValueError("centred_in: a structure of two or more objects (one cube: in_region)")

    def _evaluate(self, state):
        x, y = (float(v) for v in np.mean([state[n].pos[:2] for n in self.objects], axis=0))
        boxes = region_boxes(self.region)
        ok = point_in_region(x, y, self.region)
        return self._result(ok, f"the middle of {', '.join(self.objects)} {'is' if ok else 'is not'} in "
                                f"{describe_region(self.region)} of the workspace (at x {x:.3f}, y {y:.3f})",
                            {"x": x, "y": y}, {"boxes": [[list(bx), list(by)] for bx, by in boxes]})

    def constraints(self):
        return [("members", {"objects": self.objects}), ("place", {"object": self.objects, "region": self.region})]

    def describe(self):
        return f"the middle of {', '.join(self.objects)} in {describe_region(self.region)} of the workspace"


@dataclass(frozen=True, repr=False)
class Between(Predicate):
    """``a`` lies between ``b`` and ``c``: on the segment b-c (within LINE_TOL*2), not at its ends."""

    a: str
    b: str
    c: str
    name: ClassVar[str] = "between"
    phrases: ClassVar[str] = r"between"
    carried_by: ClassVar[tuple[str, ...]] = ("in_line",)
    phrase: ClassVar[str] = "between"
    cue: ClassVar[str] = r"\b(?:between|middle)\b|\b(?:in|at)\s+the\s+cent(?:re|er)\b(?!\s+of\b)"  # "black in the centre" of a line
    object_fields: ClassVar[tuple[str, ...]] = ("a", "b", "c")

    def _evaluate(self, state):
        a, b, c = (_planar(state[n]) for n in (self.a, self.b, self.c))
        seg = c - b
        length = float(np.linalg.norm(seg))
        if length < 1e-9:
            return self._result(False, f"{self.b} and {self.c} coincide", {"length": length})
        t = float((a - b) @ seg / length**2)
        rel = a - b
        off = float(abs(seg[0] * rel[1] - seg[1] * rel[0]) / length)
        ok = 0.0 < t < 1.0 and off <= 2 * C.LINE_TOL
        return self._result(ok, f"{self.a} {'is' if ok else 'is not'} between {self.b} and {self.c} (t={t:.2f}, off {off * 100:.1f} cm)",
                            {"t": t, "off_line": off}, {"t": [0.0, 1.0], "off_line": 2 * C.LINE_TOL})

    def constraints(self):
        return [("structure", {"predicate": self.name}), ("members", {"objects": (self.a, self.b, self.c)}),
                ("order", {"relation": self.name, "pairs": ((self.a, self.b), (self.a, self.c))})]

    def describe(self):
        return f"{self.a} between {self.b} and {self.c}"


# ---------------------------------------------------------------------------
# Structures
# ---------------------------------------------------------------------------

ORDER_KEYS: dict[str, tuple[int, float]] = {
    "left_to_right": (1, -1.0),
    "right_to_left": (1, 1.0),
    "front_to_back": (0, 1.0),
    "back_to_front": (0, -1.0),
    "bottom_to_top": (2, 1.0),
    "top_to_bottom": (2, -1.0),
}
"""Reading direction -> (world axis, sign): objects are ordered by sign * coordinate."""


def order_objects(objs: list[ObjectState], direction: str) -> list[ObjectState]:
    """Objects in reading order along a direction.

    ``"reading"`` orders structures layer by layer from the bottom, each layer front to
    back, each row left to right.

    Raises:
        ValueError: unknown direction.
    """
    if direction == "reading":
        edge = C.CUBE_EDGE
        layers: dict[int, list[ObjectState]] = {}
        for o in objs:  # layer k has its centres at k + 1/2 edges above the table
            layers.setdefault(round((o.pos[2] - C.TABLE_TOP_Z) / edge - 0.5), []).append(o)
        out = []
        for k in sorted(layers):
            rows: list[list[ObjectState]] = []
            for o in sorted(layers[k], key=lambda o: o.pos[0]):  # a row: centres chained < edge/2 apart in x
                if rows and o.pos[0] - rows[-1][-1].pos[0] < edge / 2:
                    rows[-1].append(o)
                else:
                    rows.append([o])
            for row in rows:
                out.extend(sorted(row, key=lambda o: -o.pos[1]))
        return out
    if direction not in ORDER_KEYS:
        raise ValueError(f"unknown direction {direction!r}; use one of {', '.join(ORDER_KEYS)} or 'reading'")
    axis, sign = ORDER_KEYS[direction]
    return sorted(objs, key=lambda o: sign * o.pos[axis])


@dataclass(frozen=True, repr=False)
class Stack(Predicate):
    """A vertical stack, ``objects`` listed bottom to top; the bottom rests on the table.

    Interchangeable objects (same kind, colour, labels) may trade places.
    """

    objects: tuple[str, ...]
    name: ClassVar[str] = "stack"
    cue: ClassVar[str] = r"\b(?:stack\w*|tower\w*|pile\w*|columns?|pillars?|on\s+top|onto|atop|upon|on|above|over|under|below|beneath|underneath|high|tall)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)
    ordered: ClassVar[bool] = True

    def _evaluate(self, state):
        listed = [state[n] for n in self.objects]
        actual = sorted(listed, key=lambda o: o.pos[2])
        children = [OnTable(actual[0].name).evaluate(state)]
        for lower, upper in itertools.pairwise(actual):
            children.append(On(upper.name, lower.name).evaluate(state))
        if not self.ordered:
            ok = all(c.satisfied for c in children)
            return self._result(ok, f"stack of {', '.join(self.objects)} in any order {'holds' if ok else 'fails'}",
                                children=children)
        order_ok = [_signature(x) for x in actual] == [_signature(x) for x in listed]
        children.append(PredicateResult(
            "stack_order", {"expected": list(self.objects)}, order_ok,
            {"bottom_to_top": [o.name for o in actual]}, {},
            "order matches" if order_ok else
            f"order bottom to top is {', '.join(o.name for o in actual)}, expected {', '.join(self.objects)}"))
        ok = all(c.satisfied for c in children)
        return self._result(ok, f"stack {'/'.join(self.objects)} {'holds' if ok else 'fails'}", children=children)

    def support_edges(self):
        edges = [(self.objects[0], "table")]
        edges += [(u, lo) for lo, u in itertools.pairwise(self.objects)]
        return edges

    def constraints(self):
        out = [("structure", {"predicate": "stack"}), ("count", {"predicate": "stack", "objects": self.objects}),
               ("members", {"objects": self.objects})]
        if self.ordered:
            out.append(("order", {"relation": "on", "pairs": tuple((u, lo) for lo, u in itertools.pairwise(self.objects))}))
        return out

    def relax(self, kind, goal=None):
        return UnorderedStack(objects=self.objects) if kind == "order" else None

    def describe(self):
        return "stack (bottom to top) " + ", ".join(self.objects)


@dataclass(frozen=True, repr=False)
class UnorderedStack(Stack):
    """One vertical stack of ``objects`` in any order; the bottom rests on the table.

    What "stack two blocks" or "a tower of three blocks" asks when the instruction names no
    cube: which cube stands where is free (the issue "the front end ... exactly what was
    said": a goal may not demand an order the words do not).  ``objects`` lists one order
    that satisfies it (the goal configuration's), used to plan, never to judge.
    """

    name: ClassVar[str] = "unordered_stack"
    ordered: ClassVar[bool] = False

    def describe(self):
        return "a stack of " + ", ".join(self.objects) + " in any order"


@dataclass(frozen=True, repr=False)
class AnchoredStack(Stack):
    """One vertical stack of ``objects`` in any order but at its ends: with ``bottom`` the
    first object (or one interchangeable with it) rests on the table under all the others,
    with ``top`` the last stands above them all.

    What "a tower of four blocks with the black one at the bottom" asks: the black cube's
    place is said, the other three's is not (a goal may not demand what the words do not;
    the issue "the front end ... exactly what was said").  ``objects`` lists one order that
    satisfies it (the goal configuration's), used to plan; only the ends are judged.
    """

    bottom: bool = False
    top: bool = False
    name: ClassVar[str] = "anchored_stack"
    ordered: ClassVar[bool] = False

    def _evaluate(self, state):
        whole = super()._evaluate(state)
        actual = sorted((state[n] for n in self.objects), key=lambda o: o.pos[2])
        children = list(whole.children)
        for flag, role, index in ((self.bottom, "bottom", 0), (self.top, "top", -1)):
            if flag:
                want = state[self.objects[index]]
                ok = _signature(actual[index]) == _signature(want)
                children.append(PredicateResult(
                    f"stack_{role}", {"expected": want.name}, ok, {role: actual[index].name}, {},
                    f"{actual[index].name} is at the {role}" + ("" if ok else f", expected {want.name}")))
        ok = all(c.satisfied for c in children)
        return self._result(ok, f"{self.describe()} {'holds' if ok else 'fails'}", children=children)

    def constraints(self):
        out = super().constraints()
        if self.bottom:
            out.append(("order", {"relation": "bottom", "pairs": ((self.objects[0], "table"),)}))
        if self.top:
            out.append(("order", {"relation": "top", "pairs": ((self.objects[-1], "top"),)}))
        return out

    def relax(self, kind, goal=None):
        return UnorderedStack(objects=self.objects) if kind == "order" else None

    def describe(self):
        ends = [f"{self.objects[0]} at the bottom"] * self.bottom + [f"{self.objects[-1]} on top"] * self.top
        return "a stack of " + ", ".join(self.objects) + " with " + " and ".join(ends) + ", the rest in any order"


@dataclass(frozen=True, repr=False)
class InLine(Predicate):
    """``objects`` lie in one straight line on the table.

    Args:
        objects: the objects, listed in ``order`` when one is given.
        axis: ``"y"`` for a left-right line, ``"x"`` for a front-back line, None for a
            line in any direction on the table ("line up the blocks" names none; the line is
            then the principal axis of the centres).
        order: optional direction (``"left_to_right"``...) in which the listed objects
            must appear, or ``"sequence"``: in the listed order from one end or the other
            ("in the order red, green, blue" says no direction); interchangeable objects
            may trade places.
    """

    objects: tuple[str, ...]
    axis: str | None = "y"
    order: str | None = None
    name: ClassVar[str] = "in_line"
    cue: ClassVar[str] = r"\b(?:lines?|rows?|align\w*|lined|columns?|side\s+by\s+side|sequence|order\w*|left\s+to\s+right|right\s+to\s+left|spell\w*|word|sort\w*|horizontal\w*|reads?|reading)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def _direction(self, objs) -> np.ndarray:
        """Unit vector (x, y) along the line: the axis, or the centres' principal axis."""
        if self.axis is not None:
            return np.array([0.0, 1.0]) if self.axis == "y" else np.array([1.0, 0.0])
        xy = np.array([o.pos[:2] for o in objs], float)
        if len(xy) < 2:
            return np.array([0.0, 1.0])
        _, _, vt = np.linalg.svd(xy - xy.mean(axis=0), full_matrices=False)
        d = vt[0]
        return d if (d[1], d[0]) >= (0.0, 0.0) else -d  # sign fixed: towards +y (left), else +x

    def _evaluate(self, state):
        objs = [state[n] for n in self.objects]
        d = self._direction(objs)
        xy = np.array([o.pos[:2] for o in objs], float)
        along_c, across_c = xy @ d, xy @ np.array([-d[1], d[0]])
        dev = float(np.max(np.abs(across_c - across_c.mean())))
        gaps = np.array([abs(_table_gap(o)) for o in objs])
        coords = np.sort(along_c)
        spacing = np.diff(coords)
        min_sp = float(spacing.min()) if len(spacing) else 0.0
        max_sp = float(spacing.max()) if len(spacing) else 0.0
        ok = dev <= C.LINE_TOL and gaps.max() <= C.TABLE_Z_TOL and min_sp >= 0.9 * C.CUBE_EDGE and max_sp <= C.LINE_MAX_GAP
        measured = {"max_off_line": dev, "max_table_gap": float(gaps.max()), "min_spacing": min_sp, "max_spacing": max_sp}
        reason = "objects in a line" if ok else "objects not in a straight line on the table"
        if ok and self.order:
            want = [_signature(o) for o in objs]
            if self.order == "sequence":
                got = [objs[i] for i in np.argsort(along_c, kind="stable")]
                sig = [_signature(o) for o in got]
                order_ok = sig in (want, want[::-1])
            else:
                got = order_objects(objs, self.order)
                order_ok = [_signature(o) for o in got] == want
            measured["order"] = [o.name for o in got]
            if not order_ok:
                ok = False
                reason = f"{self.order.replace('_', ' ')} order is {', '.join(o.name for o in got)}"
        return self._result(ok, reason, measured,
                            {"max_off_line": C.LINE_TOL, "max_table_gap": C.TABLE_Z_TOL,
                             "min_spacing": 0.9 * C.CUBE_EDGE, "max_spacing": C.LINE_MAX_GAP})

    def support_edges(self):
        return [(n, "table") for n in self.objects]

    def constraints(self):
        out = [("structure", {"predicate": self.name, "axis": self.axis}),
               ("count", {"predicate": self.name, "objects": self.objects}), ("members", {"objects": self.objects})]
        if self.order:
            out.append(("order", {"relation": self.order, "pairs": tuple(itertools.pairwise(self.objects))}))
        return out

    def relax(self, kind, goal=None):
        return replace(self, order=None) if kind == "order" else None

    def describe(self):
        if self.order == "sequence":
            return "line of " + ", ".join(self.objects) + " in that order from either end"
        how = f" {self.order.replace('_', ' ')}" if self.order else ""
        return f"line{how} of " + ", ".join(self.objects)


@dataclass(frozen=True, repr=False)
class AnchoredLine(InLine):
    """A left-right line of ``objects`` (axis ``"y"``) in any order but at its ends: with
    ``left`` the first object (or one interchangeable with it) stands at the left end, with
    ``right`` the last stands at the right end, left and right as the robot faces the table.

    What "a row of red, green and blue with red at the left end" asks: red's place is said, the
    others' is not (a goal may not demand what the words do not; issue 30, "goals no stricter than
    words").  ``objects`` lists one order that satisfies it (the goal configuration's, left to
    right), used to plan; only the line and its said ends are judged.
    """

    left: bool = False
    right: bool = False
    name: ClassVar[str] = "anchored_line"

    def _evaluate(self, state):
        whole = super()._evaluate(state)
        if not whole.satisfied:
            return whole
        got = order_objects([state[n] for n in self.objects], "left_to_right")
        for flag, end, index in ((self.left, "left", 0), (self.right, "right", -1)):
            want = state[self.objects[index]]
            if flag and _signature(got[index]) != _signature(want):
                return self._result(False, f"{got[index].name} is at the {end} end, expected {want.name}",
                                    {**whole.measured, end: got[index].name}, whole.tolerance)
        return self._result(True, f"{self.describe()} holds", whole.measured, whole.tolerance)

    def constraints(self):
        out = super().constraints()
        if self.left:
            out.append(("order", {"relation": "left_end", "pairs": ((self.objects[0], "left"),)}))
        if self.right:
            out.append(("order", {"relation": "right_end", "pairs": ((self.objects[-1], "right"),)}))
        return out

    def relax(self, kind, goal=None):
        return InLine(objects=self.objects, axis=self.axis) if kind == "order" else None

    def describe(self):
        ends = [f"{self.objects[0]} at the left end"] * self.left + [f"{self.objects[-1]} at the right end"] * self.right
        return "line of " + ", ".join(self.objects) + " with " + " and ".join(ends) + ", the rest in any order"


@dataclass(frozen=True, repr=False)
class InCircle(Predicate):
    """``objects`` (3 or more) stand on the table evenly around a circle."""

    objects: tuple[str, ...]
    name: ClassVar[str] = "in_circle"
    cue: ClassVar[str] = r"\b(?:circle\w*|circular|ring|round)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def _evaluate(self, state):
        objs = [state[n] for n in self.objects]
        if len(objs) < 3:
            return self._result(False, "a circle needs at least 3 objects", {"count": len(objs)})
        xy = np.array([_planar(o) for o in objs])
        center = xy.mean(axis=0)
        r = np.linalg.norm(xy - center, axis=1)
        dev = float(np.max(np.abs(r - r.mean())))
        ang = np.sort(np.arctan2(xy[:, 1] - center[1], xy[:, 0] - center[0]))
        gaps = np.diff(np.concatenate([ang, [ang[0] + 2 * math.pi]]))
        max_gap = float(gaps.max())
        allowed = 1.5 * 2 * math.pi / len(objs)
        table = max(abs(_table_gap(o)) for o in objs)
        ok = dev <= C.CIRCLE_RADIUS_TOL and r.mean() >= C.CIRCLE_MIN_RADIUS and max_gap <= allowed and table <= C.TABLE_Z_TOL
        return self._result(ok, f"objects {'form' if ok else 'do not form'} a circle (radius {r.mean() * 100:.1f} cm, deviation {dev * 100:.1f} cm)",
                            {"radius": float(r.mean()), "radius_deviation": dev, "max_angle_gap": max_gap, "max_table_gap": table},
                            {"radius_deviation": C.CIRCLE_RADIUS_TOL, "min_radius": C.CIRCLE_MIN_RADIUS,
                             "max_angle_gap": allowed, "max_table_gap": C.TABLE_Z_TOL})

    def support_edges(self):
        return [(n, "table") for n in self.objects]

    def describe(self):
        return "circle of " + ", ".join(self.objects)


def _match_sites(objs: list[ObjectState], sites: np.ndarray) -> tuple[bool, float, list[str]]:
    """Match each site to a distinct object within GRID_TOL; return (ok, worst error, unmatched)."""
    names = [o.name for o in objs]
    pos = np.array([o.pos for o in objs], dtype=float).reshape(len(objs), 3)
    free = np.ones(len(objs), dtype=bool)
    worst = 0.0
    missing = []
    for site in sites:
        if not free.any():
            missing.append(str(np.round(site, 3).tolist()))
            continue
        d = np.where(free, np.linalg.norm(pos - site, axis=1), np.inf)
        k = int(np.argmin(d))  # the nearest unmatched object; a tie goes to the first, as objs are ordered
        if d[k] <= C.GRID_TOL:
            worst = max(worst, float(d[k]))
            free[k] = False
        else:
            missing.append(str(np.round(site, 3).tolist()))
    remaining = [n for n, f in zip(names, free, strict=True) if f]
    ok = not missing and not remaining
    return ok, worst, missing + sorted(remaining)


def _bottom_origin(objs: list[ObjectState]) -> tuple[np.ndarray, float]:
    zmin = min(o.pos[2] for o in objs)
    bottom = [o for o in objs if o.pos[2] - zmin < C.CUBE_EDGE / 2]
    origin = np.array([min(o.pos[0] for o in bottom), max(o.pos[1] for o in bottom), zmin])
    return origin, float(np.mean([o.size[2] for o in objs]))


@dataclass(frozen=True, repr=False)
class Grid(Predicate):
    """``objects`` fill a rows x cols x layers lattice of touching cubes on the table.

    Rows run along x (front to back), columns along y (left to right), layers along z.
    Any object may fill any site (use other predicates for per-site properties).
    """

    objects: tuple[str, ...]
    rows: int
    cols: int
    layers: int = 1
    name: ClassVar[str] = "grid"
    cue: ClassVar[str] = r"\b(?:grid|squares?|rectangle\w*|rectangular|array|walls?|layers?|\d+x\d+(?:x\d+)?|rows?|cube|block)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def _evaluate(self, state):
        objs = [state[n] for n in self.objects]
        n = self.rows * self.cols * self.layers
        if len(objs) != n:
            return self._result(False, f"a {self.rows}x{self.cols}x{self.layers} grid needs {n} objects, got {len(objs)}",
                                {"count": len(objs)}, {"count": n})
        origin, pitch = _bottom_origin(objs)
        sites = np.array([origin + [r * pitch, -c * pitch, layer * pitch]
                          for layer in range(self.layers) for r in range(self.rows) for c in range(self.cols)])
        ok, worst, missing = _match_sites(objs, sites)
        table = abs(origin[2] - C.TABLE_TOP_Z - pitch / 2)
        ok = ok and table <= C.TABLE_Z_TOL
        return self._result(ok, f"{self.rows}x{self.cols}x{self.layers} grid {'complete' if ok else 'incomplete'}"
                            + ("" if ok else f" (unfilled or stray: {', '.join(missing[:4])})"),
                            {"worst_site_error": worst, "table_gap": float(table), "unmatched": missing},
                            {"site_error": C.GRID_TOL, "table_gap": C.TABLE_Z_TOL})

    def support_edges(self):
        return [(n, "table") for n in self.objects[: self.rows * self.cols]]

    def describe(self):
        dims = f"{self.rows}x{self.cols}" + (f"x{self.layers}" if self.layers > 1 else "")
        return f"{dims} grid of {len(self.objects)} cubes"


@dataclass(frozen=True, repr=False)
class Pyramid(Predicate):
    """A pyramid of touching cubes with a ``base`` of N.

    ``dims=2``: a wall facing the camera, layers of N, N-1, ... 1 cubes along y, each cube
    resting on the two below it.  ``dims=3``: layers of NxN, (N-1)x(N-1), ... 1, each cube
    resting on the four below it.  ``layers`` (2D only; empty for the steps above): the
    cubes of each layer from the bottom up, ``layers[0] == base``, none wider than the one
    below, each centred over it ("three on the bottom and one on top": ``(3, 1)``, the top
    cube on the middle one; :func:`rpg.domain.layouts.layered_sites`).

    Raises:
        ValueError: ``layers`` given for a 3D pyramid, not starting with ``base``, widening
            upwards or of fewer than two layers.
    """

    objects: tuple[str, ...]
    base: int
    dims: int = 2
    layers: tuple[int, ...] = ()
    name: ClassVar[str] = "pyramid"
    cue: ClassVar[str] = r"\b(?:pyramids?|triangle|triangular)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)
    quiet_defaults: ClassVar[tuple[str, ...]] = ("layers",)  # (pyramids written before it keep their hashes)

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "layers", tuple(self.layers))
        layers = self.layers
        if layers and (self.dims != 2 or len(layers) < 2 or layers[0] != self.base or min(layers) < 1
                       or any(b > a for a, b in itertools.pairwise(layers))):
            raise ValueError(f"a pyramid's layers {list(layers)} must start with its base {self.base}, narrow upwards, "
                             "have two or more layers and stand in 2D")

    def layer_sizes(self) -> list[int]:
        """The cubes of each layer from the bottom up (squared in 3D)."""
        if self.layers:
            return list(self.layers)
        return [(self.base - k) ** (self.dims - 1) for k in range(self.base)]

    def expected_count(self) -> int:
        return sum(self.layer_sizes())

    def counts(self) -> set[int]:
        """The whole, the base and each layer's cubes (N, N-1, ... 1; squared in 3D)."""
        if self.layers:
            return super().counts() | set(self.layers)
        return super().counts() | {m ** (self.dims - 1) for m in range(1, self.base + 1)}

    def _evaluate(self, state):
        objs = [state[n] for n in self.objects]
        n = self.expected_count()
        if len(objs) != n:
            return self._result(False, f"a {self.dims}D pyramid with base {self.base} needs {n} cubes, got {len(objs)}",
                                {"count": len(objs)}, {"count": n})
        origin, p = _bottom_origin(objs)
        if self.layers:  # each layer centred over the one below
            sites = [origin + [0.0, -offset * p, k * p] for k, offset in layered_sites(self.layers)]
        else:
            sites = []
            for k in range(self.base):
                m = self.base - k
                rows = range(m) if self.dims == 3 else range(1)
                for r in rows:
                    for c in range(m):
                        dx = (k / 2 + r) * p if self.dims == 3 else 0.0
                        sites.append(origin + [dx, -(k / 2 + c) * p, k * p])
        ok, worst, missing = _match_sites(objs, np.array(sites))
        table = abs(origin[2] - C.TABLE_TOP_Z - p / 2)
        ok = ok and table <= C.TABLE_Z_TOL
        return self._result(ok, f"{self.dims}D pyramid (base {self.base}) {'complete' if ok else 'incomplete'}"
                            + ("" if ok else f" (unfilled or stray: {', '.join(missing[:4])})"),
                            {"worst_site_error": worst, "table_gap": float(table), "unmatched": missing},
                            {"site_error": C.GRID_TOL, "table_gap": C.TABLE_Z_TOL})

    def support_edges(self):
        return [(n, "table") for n in self.objects[: self.base ** (self.dims - 1)]]

    def describe(self):
        if self.layers:
            return f"2D pyramid with layers of {'-'.join(str(m) for m in self.layers)} cubes from the bottom"
        base = f"{self.base}x{self.base}" if self.dims == 3 else str(self.base)
        return f"{self.dims}D pyramid with a base of {base}"


@dataclass(frozen=True, repr=False)
class Bridge(Pyramid):
    """One cube resting on two that stand side by side under it: a 2D :class:`Pyramid` with
    a base of 2, stated as a relation ("put the yellow block on the red and green blocks").
    ``objects``: the two below, then the one on top (which cube stands where is judged by an
    :class:`InLayers` beside it)."""

    base: int = 2
    dims: int = 2
    name: ClassVar[str] = "bridge"
    cue: ClassVar[str] = r"\b(?:on\s+top\s+of|onto|atop|upon|over|on)\b"

    def __post_init__(self) -> None:
        super().__post_init__()
        if (self.base, self.dims, len(self.objects)) != (2, 2, 3):
            raise ValueError("bridge: three objects (two below, one on top), base 2, dims 2")

    def describe(self):
        return f"{self.objects[2]} resting on both {self.objects[0]} and {self.objects[1]}"


@dataclass(frozen=True, repr=False)
class Piles(Predicate):
    """Objects gathered in separate piles on the table (or in one pile, when ``by`` gives every
    object one value or ``groups`` holds one group: its spread alone is judged).

    Either ``by`` an attribute (``color``, ``label``, ``kind`` or ``type``, where type is
    letter / digit / operator / colored_cube) or with explicit ``groups`` of names.  Each
    pile's members lie within PILE_RADIUS of its centroid; centroids are at least
    PILE_SEPARATION apart.
    """

    objects: tuple[str, ...] = ()
    by: str | None = None
    groups: tuple[tuple[str, ...], ...] = ()
    name: ClassVar[str] = "piles"
    cue: ClassVar[str] = r"\b(?:piles?|groups?|bunch\w*|clusters?|heaps?|sort\w*|separat\w*)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def rename(self, mapping):
        new = super().rename(mapping)
        return replace(new, groups=tuple(tuple(mapping.get(n, n) for n in g) for g in self.groups))

    def object_names(self):
        return list(self.objects) + [n for g in self.groups for n in g]

    def resolve_groups(self, state: WorldState) -> list[list[str]]:
        """The piles to check: by attribute, or the explicit groups matched to the piles on
        the table, where interchangeable cubes (same kind, colour, labels) may trade places."""
        if self.groups:
            return self._match_groups(state)
        buckets: dict[str, list[str]] = {}
        for n in self.objects:
            buckets.setdefault(str(state[n].attribute(self.by or "color")), []).append(n)
        return [buckets[k] for k in sorted(buckets)]

    def _match_groups(self, state: WorldState) -> list[list[str]]:
        names = sorted({n for g in self.groups for n in g})
        xy = np.array([_planar(state[n]) for n in names])
        import networkx as nx  # lazy: only piles with explicit groups need it

        g = nx.Graph()
        g.add_nodes_from(range(len(names)))
        for i, j in itertools.combinations(range(len(names)), 2):
            if np.linalg.norm(xy[i] - xy[j]) <= C.PILE_LINK:
                g.add_edge(i, j)
        clusters = sorted(sorted(names[i] for i in comp) for comp in nx.connected_components(g))

        def content(members):
            return sorted(_signature(state[n]) for n in members)

        wanted = sorted(content(grp) for grp in self.groups)
        if sorted(content(c) for c in clusters) == wanted:
            return clusters
        return [list(grp) for grp in self.groups]

    def _evaluate(self, state):
        groups = self.resolve_groups(state)
        if not groups:
            return self._result(False, "no cubes to pile", {"groups": groups})
        cents = []
        spread = []
        for g in groups:
            xy = np.array([_planar(state[n]) for n in g])
            c = xy.mean(axis=0)
            cents.append(c)
            spread.append(float(np.max(np.linalg.norm(xy - c, axis=1))))
        if len(groups) == 1:  # one pile ("pile the three orange cubes up"): its cubes gathered, no other pile to keep apart
            ok = spread[0] <= C.PILE_RADIUS
            return self._result(ok, f"one pile {'gathered' if ok else 'not gathered'} (spread {spread[0] * 100:.1f} cm)",
                                {"groups": groups, "spread": spread}, {"spread": C.PILE_RADIUS})
        seps = [float(np.linalg.norm(a - b)) for a, b in itertools.combinations(cents, 2)]
        ok = max(spread) <= C.PILE_RADIUS and min(seps) >= C.PILE_SEPARATION
        return self._result(ok, f"{len(groups)} piles {'separated' if ok else 'not separated'} (largest spread {max(spread) * 100:.1f} cm, closest piles {min(seps) * 100:.1f} cm)",
                            {"groups": groups, "spread": spread, "min_separation": min(seps)},
                            {"spread": C.PILE_RADIUS, "min_separation": C.PILE_SEPARATION})

    def support_edges(self):
        return []

    def describe(self):
        if self.groups:
            return "one pile" if len(self.groups) == 1 else f"{len(self.groups)} separate piles"
        return f"piles sorted by {self.by}"


@dataclass(frozen=True, repr=False)
class LayersUniform(Predicate):
    """Within a structure, each layer (or row) along ``axis`` shares one value of ``by``,
    and different layers have different values (e.g. "each row a different color")."""

    objects: tuple[str, ...]
    by: str = "color"
    axis: str = "z"
    name: ClassVar[str] = "layers_uniform"
    cue: ClassVar[str] = r"\b(?:layers?|levels?|tiers?|rows?|each|different|colou?r\w*)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def _evaluate(self, state):
        i = "xyz".index(self.axis)
        levels: dict[int, set] = {}
        for n in self.objects:
            o = state[n]
            levels.setdefault(round(o.pos[i] / C.CUBE_EDGE), set()).add(o.attribute(self.by))
        values = [sorted(map(str, v)) for _, v in sorted(levels.items())]
        uniform = all(len(v) == 1 for v in values)
        distinct = len({v[0] for v in values}) == len(values) if uniform else False
        ok = uniform and distinct
        return self._result(ok, f"each layer along {self.axis} {'has' if ok else 'does not have'} its own {self.by}",
                            {"layers": values})

    def describe(self):
        return f"each layer a different {self.by}"


@dataclass(frozen=True, repr=False)
class InLayers(Predicate):
    """Named cubes stand in the layers said: ``levels[i]`` is the layer of ``objects[i]``
    counted from the table (0: resting on it, 1: one cube edge higher, ...), or -1 where the
    words leave that cube's layer free.

    What "a pyramid with a blue base and a red block on top", "a row of green blocks on top
    of the row of yellow blocks" or "put the yellow block on the red and green blocks" asks
    beyond the shape (:class:`Pyramid`, :class:`Grid` judge only the shape, any cube in any
    site).  Interchangeable cubes (same signature) may trade places: for each layer, the
    cubes said to stand there must be found there, as a multiset of signatures.  A layer is
    the height of a cube's centre above the table top, in cube edges (``CUBE_EDGE``, m),
    rounded.  Source: issue "the front end ... exactly what was said" (a goal judges every
    role the words give, and no other).
    """

    objects: tuple[str, ...]
    levels: tuple[int, ...]
    name: ClassVar[str] = "in_layers"
    cue: ClassVar[str] = r"\b(?:on|onto|upon|atop|on\s+top|top|bottom|base|middle|layers?|levels?|tiers?|rows?|over|above|under|below)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)

    def __post_init__(self) -> None:
        super().__post_init__()
        object.__setattr__(self, "levels", tuple(int(k) for k in self.levels))
        if len(self.levels) != len(self.objects):
            raise ValueError(f"in_layers: {len(self.objects)} objects but {len(self.levels)} levels")

    def layer_of(self, o: ObjectState) -> int:
        """The layer ``o`` stands in: its centre's height above the table top over the cube edge, rounded."""
        return int(round((o.pos[2] - C.TABLE_TOP_Z - o.half_height) / C.CUBE_EDGE))

    def _evaluate(self, state):
        objs = [state[n] for n in self.objects]
        actual: dict[int, Counter] = {}
        for o in objs:
            actual.setdefault(self.layer_of(o), Counter())[_signature(o)] += 1
        wanted: dict[int, Counter] = {}
        for o, k in zip(objs, self.levels, strict=True):
            if k >= 0:
                wanted.setdefault(k, Counter())[_signature(o)] += 1
        missing = {k: sorted(map(str, (want - actual.get(k, Counter())).elements())) for k, want in sorted(wanted.items())}
        missing = {k: v for k, v in missing.items() if v}
        ok = not missing
        where = "; ".join(f"layer {k} lacks {', '.join(v)}" for k, v in missing.items())
        return self._result(ok, f"the named cubes {'stand' if ok else 'do not stand'} in their layers"
                            + ("" if ok else f" ({where})"),
                            {"layers": {k: sorted(map(str, c.elements())) for k, c in sorted(actual.items())}})

    def constraints(self):
        """Each named cube's layer: an order "x on y" over the named cubes of adjacent
        layers (``relation: on``), else ``relation: layer`` with pairs ``(name, "k")``."""
        named = [(n, k) for n, k in zip(self.objects, self.levels, strict=True) if k >= 0]
        by_level: dict[int, list[str]] = {}
        for n, k in named:
            by_level.setdefault(k, []).append(n)
        pairs = tuple((u, lo) for k in sorted(by_level) for u in by_level[k] for lo in by_level.get(k - 1, ()))
        paired = {n for pair in pairs for n in pair}
        out: list[tuple[str, dict]] = [("members", {"objects": tuple(n for n, _ in named)})]
        if pairs:
            out.append(("order", {"relation": "on", "pairs": pairs}))
        alone = tuple((n, str(k)) for n, k in named if n not in paired)
        if alone:
            out.append(("order", {"relation": "layer", "pairs": alone}))
        return out

    def relax(self, kind, goal=None):
        return None

    def describe(self):
        by_level: dict[int, list[str]] = {}
        for n, k in zip(self.objects, self.levels, strict=True):
            if k >= 0:
                by_level.setdefault(k, []).append(n)
        ordinal = ("at the bottom", "second from the bottom", "third from the bottom", "fourth from the bottom")
        return "; ".join(f"{', '.join(v)} " + (ordinal[k] if k < len(ordinal) else f"in layer {k + 1} from the bottom")
                         for k, v in sorted(by_level.items()))


# ---------------------------------------------------------------------------
# Semantic predicates (labels, ordering)
# ---------------------------------------------------------------------------


def _read_sequence(state: WorldState, names, direction: str, face: str) -> tuple[str, list[str]]:
    """Labels shown toward ``face`` in ``direction`` order ("?" where none), and the unreadable objects."""
    labels, unreadable = [], []
    for o in order_objects([state[n] for n in names], direction):
        label, ok = _read_label(state, o, face)
        labels.append(label or "?")
        if not ok:
            unreadable.append(o.name)
    return "".join(labels), unreadable


def _read_label(state: WorldState, o: ObjectState, face_dir: str) -> tuple[str | None, bool]:
    """Label shown toward ``face_dir`` and whether it is readable and visible."""
    face, _ = o.face_toward(face_dir)
    readable, _, _ = o.readable(face, face_dir)
    visible = state.is_visible(o.name, face)
    return o.face_labels.get(face), bool(readable and visible)


@dataclass(frozen=True, repr=False)
class Reads(Predicate):
    """The ``face`` labels of ``objects``, in ``direction`` order, spell ``text``.

    Every label must be readable (upright toward ``face``) and visible.
    """

    objects: tuple[str, ...]
    text: str
    direction: str = "left_to_right"
    face: str = "up"
    name: ClassVar[str] = "reads"
    cue: ClassVar[str] = r"\b(?:spell\w*|words?|reads?|writ\w*|letters?|order\w*|ascending|descending|increasing|decreasing|alphabet\w*|numeric\w*|sort\w*)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)
    semantic: ClassVar[bool] = True

    def _evaluate(self, state):
        got, unreadable = _read_sequence(state, self.objects, self.direction, self.face)
        ok = not unreadable and got.upper() == self.text.replace(" ", "").upper()
        reason = f"reads {got!r}" + ("" if ok else f", expected {self.text!r}") + (f"; unreadable: {', '.join(unreadable)}" if unreadable else "")
        return self._result(ok, reason, {"read": got, "unreadable": unreadable}, {"text": self.text})

    def semantic_faces(self, state):
        return [(n, self.face) for n in self.objects]

    def describe(self):
        return f"reads {self.text!r} {self.direction.replace('_', ' ')}"


_EQ_RE = re.compile(r"^[0-9+\-x=]+$")


def _eval_side(expr: str) -> int | None:
    expr = expr.replace("x", "*")
    if not expr or not re.fullmatch(r"\d+([+\-*]\d+)*", expr):
        return None
    node = ast.parse(expr, mode="eval").body

    def ev(n):
        if isinstance(n, ast.Constant):
            return int(n.value)
        if isinstance(n, ast.BinOp):
            a, b = ev(n.left), ev(n.right)
            if isinstance(n.op, ast.Add):
                return a + b
            if isinstance(n.op, ast.Sub):
                return a - b
            if isinstance(n.op, ast.Mult):
                return a * b
        raise ValueError("bad expression")

    return ev(node)


def equation_holds(text: str) -> bool:
    """Whether a string such as ``"3+4=7"`` is a correct equation (``x`` is times)."""
    if not _EQ_RE.match(text) or text.count("=") != 1:
        return False
    left, right = text.split("=")
    a, b = _eval_side(left), _eval_side(right)
    return a is not None and b is not None and a == b


@dataclass(frozen=True, repr=False)
class Equation(Predicate):
    """The ``face`` labels of ``objects`` in ``direction`` order form a correct equation."""

    objects: tuple[str, ...]
    direction: str = "left_to_right"
    face: str = "up"
    name: ClassVar[str] = "equation"
    cue: ClassVar[str] = r"\b(?:equation|math\w*|sum|addition|subtraction|multiplication|plus|minus|equals|times|correct)\b|="
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)
    semantic: ClassVar[bool] = True

    def _evaluate(self, state):
        got, unreadable = _read_sequence(state, self.objects, self.direction, self.face)
        ok = not unreadable and equation_holds(got)
        return self._result(ok, f"reads {got!r}, {'a correct' if ok else 'not a correct'} equation",
                            {"read": got, "unreadable": unreadable})

    def semantic_faces(self, state):
        return [(n, self.face) for n in self.objects]

    def describe(self):
        return f"correct equation {self.direction.replace('_', ' ')}"


def sort_key(o: ObjectState, key: str, label: str | None) -> float | None:
    """Numeric sort key of an object: ``label`` (alphabetical), ``number``, ``color`` (gradient)."""
    if key == "color":
        return float(GRADIENT_ORDER.index(o.color)) if o.color in GRADIENT_ORDER else None
    if label is None:
        return None
    if key == "number":
        return float(label) if label.isdigit() else None
    if key == "label":
        return float(ord(label)) if label.isalnum() else None
    raise ValueError(f"unknown sort key {key!r}; use 'label', 'number' or 'color'")


@dataclass(frozen=True, repr=False)
class SortedBy(Predicate):
    """``objects`` in ``direction`` order are sorted by ``key``.

    Args:
        key: ``"label"`` (alphabetical), ``"number"`` (numerical) or ``"color"`` (colour
            gradient, :data:`~rpg.domain.palette.GRADIENT_ORDER`).
        direction: reading direction (``"left_to_right"``, ``"reading"``...).
        descending: reverse order.
        strict: require strictly increasing keys.
        face: which face's label is read (labels only); only visible, readable faces
            carry the requirement (paper, Geometric Visibility), at least two must.
    """

    objects: tuple[str, ...]
    key: str = "label"
    direction: str = "left_to_right"
    descending: bool = False
    strict: bool = True
    face: str = "up"
    name: ClassVar[str] = "sorted_by"
    cue: ClassVar[str] = r"\b(?:sort\w*|order\w*|alphabet\w*|ascending|descending|increasing|decreasing|gradient|rainbow|numeric\w*)\b"
    swap_invariant: ClassVar[bool] = True
    list_fields: ClassVar[tuple[str, ...]] = ("objects",)
    semantic: ClassVar[bool] = True

    def _evaluate(self, state):
        objs = order_objects([state[n] for n in self.objects], self.direction)
        keys, seen = [], []
        for o in objs:
            if self.key == "color":
                keys.append(sort_key(o, "color", None))
                seen.append(o.name)
                continue
            label, ok = _read_label(state, o, self.face)
            if ok:
                keys.append(sort_key(o, self.key, label))
                seen.append(o.name)
        if len(keys) < 2 or any(k is None for k in keys):
            return self._result(False, f"fewer than two readable {self.key} keys", {"readable": seen})
        sign = -1 if self.descending else 1
        diffs = [sign * (b - a) for a, b in itertools.pairwise(keys)]
        ok = all(d > 0 for d in diffs) if self.strict else all(d >= 0 for d in diffs)
        return self._result(ok, f"{'sorted' if ok else 'not sorted'} by {self.key} {self.direction.replace('_', ' ')}",
                            {"order": seen, "keys": keys})

    def semantic_faces(self, state):
        return [] if self.key == "color" else [(n, self.face) for n in self.objects]

    def describe(self):
        rev = " descending" if self.descending else ""
        return f"sorted by {self.key}{rev} {self.direction.replace('_', ' ')}"


@dataclass(frozen=True, repr=False)
class LabelFacing(Predicate):
    """Cube ``a`` shows ``label`` toward ``direction`` (``"up"`` or ``"front"``...), upright."""

    a: str
    label: str
    direction: str = "up"
    name: ClassVar[str] = "label_facing"
    cue: ClassVar[str] = r"\b(?:fac\w*|show\w*|up|upward\w*|rotat\w*|turn\w*|flip\w*|visible|camera)\b"
    loose_phrases: ClassVar[str] = (r"(?:faces?|facing|shows?|showing|points?|pointing)\s+(?:(?:its|their)\s+(?:letters?|digits?|labels?)\s+)?"
                                    r"(?:up|upwards?|the\s+camera|the\s+robot|front|forward|toward\s+the\s+(?:robot|camera))"
                                    r"|(?:letter|digit|number|label)s?\s+(?:side\s+|face\s+)?up")
    carried_by: ClassVar[tuple[str, ...]] = ("reads",)
    object_fields: ClassVar[tuple[str, ...]] = ("a",)
    semantic: ClassVar[bool] = True

    def _evaluate(self, state):
        if self.direction not in DIRECTIONS:
            raise ValueError(f"unknown direction {self.direction!r}; use one of {', '.join(DIRECTIONS)}")
        o = state[self.a]
        best = None
        for face, lab in sorted(o.face_labels.items()):
            if lab != self.label:
                continue
            ok, ncos, ucos = o.readable(face, self.direction)
            ok = ok and state.is_visible(o.name, face)
            cand = (ok, ncos, ucos, face)
            if best is None or cand > best:
                best = cand
        if best is None:
            return self._result(False, f"{self.a} has no face labelled {self.label!r}")
        ok, ncos, ucos, face = best
        return self._result(ok, f"{self.a} {'shows' if ok else 'does not show'} {self.label!r} {self.direction} (face {face}, normal cos {ncos:.3f}, up cos {ucos:.3f})",
                            {"face": face, "normal_cos": ncos, "up_cos": ucos},
                            {"normal_cos": C.READABLE_NORMAL_COS, "up_cos": C.READABLE_UP_COS})

    def semantic_faces(self, state):
        return [(self.a, self.direction)]

    def describe(self):
        return f"{self.a} shows {self.label!r} facing {self.direction}"


# ---------------------------------------------------------------------------
# Composites and temporal order
# ---------------------------------------------------------------------------


@dataclass(frozen=True, repr=False)
class And(Predicate):
    """All children hold."""

    children_: tuple[Predicate, ...] = field(default=(), metadata={"alias": "children"})
    name: ClassVar[str] = "and"

    def __init__(self, children=()):
        object.__setattr__(self, "children_", tuple(children))

    def children(self):
        return list(self.children_)

    def conjuncts(self):
        return [c for child in self.children_ for c in child.conjuncts()]

    def args(self):
        return {}

    def to_dict(self):
        return {"predicate": self.name, "children": [c.to_dict() for c in self.children_]}

    def rename(self, mapping):
        return And(tuple(c.rename(mapping) for c in self.children_))

    def map_children(self, fn):
        return And(tuple(fn(c) for c in self.children_))

    def _evaluate(self, state):
        results = [c.evaluate(state) for c in self.children_]
        ok = all(r.satisfied for r in results)
        n_bad = sum(not r.satisfied for r in results)
        return self._result(ok, "all hold" if ok else f"{n_bad} of {len(results)} do not hold", children=results)

    def __repr__(self):
        inner = ",\n        ".join(repr(c) for c in self.children_)
        return f"And([\n        {inner},\n    ])"

    def describe(self):
        return "; ".join(c.describe() for c in self.children_)


@dataclass(frozen=True, repr=False)
class Not(Predicate):
    """The child does not hold."""

    child: Predicate
    name: ClassVar[str] = "not"
    cue: ClassVar[str] = r"\b(?:not|no|never)\b|n't\b"
    opaque: ClassVar[bool] = True

    def children(self):
        return [self.child]

    def args(self):
        return {}

    def support_edges(self):
        return []

    def rename(self, mapping):
        return Not(self.child.rename(mapping))

    def constraints(self):
        return [("structure", {"predicate": self.name, "child": self.child.describe()}),
                ("members", {"objects": tuple(dict.fromkeys(self.child.object_names()))})]

    def _evaluate(self, state):
        r = self.child.evaluate(state)
        return self._result(not r.satisfied, f"not ({r.reason})", children=[r])

    def describe(self):
        return f"not ({self.child.describe()})"


@dataclass(frozen=True, repr=False)
class InOrder(Predicate):
    """Temporal goal: ``events`` become true in the listed order ("first A, then B").

    On a single state it checks that every event holds (the terminal condition); the order
    in which they became true is judged by :class:`TemporalMonitor` over an episode.
    """

    events: tuple[Predicate, ...]
    name: ClassVar[str] = "in_order"

    def children(self):
        return list(self.events)

    def args(self):
        return {"events": [e.describe() for e in self.events]}

    def rename(self, mapping):
        return InOrder(tuple(e.rename(mapping) for e in self.events))

    def map_children(self, fn):
        return InOrder(tuple(fn(e) for e in self.events))

    def constraints(self):
        return [("order", {"relation": "temporal", "events": self.events})]

    def to_dict(self):
        return {"predicate": self.name, "events": [e.to_dict() for e in self.events]}

    def _evaluate(self, state):
        results = [e.evaluate(state) for e in self.events]
        ok = all(r.satisfied for r in results)
        return self._result(ok, "all events hold (order judged by the episode monitor)" if ok else "not all events hold", children=results)

    def monitor(self) -> TemporalMonitor:
        return TemporalMonitor(self)

    def __repr__(self):
        inner = ", ".join(repr(e) for e in self.events)
        return f"InOrder(events=[{inner}])"

    def describe(self):
        return "first " + ", then ".join(e.describe() for e in self.events)


class TemporalMonitor:
    """Tracks when each event of an :class:`InOrder` first holds over an episode.

    Call :meth:`update` with each state (in time order); :meth:`result` says whether the
    events first became true in the required order and all hold at the end.
    """

    def __init__(self, goal: InOrder):
        self.goal = goal
        self.first_true: list[int | None] = [None] * len(goal.events)
        self.steps = 0
        self._last: list[bool] = [False] * len(goal.events)

    def update(self, state: WorldState) -> None:
        for i, e in enumerate(self.goal.events):
            ok = e.evaluate(state).satisfied
            if ok and self.first_true[i] is None:
                self.first_true[i] = self.steps
            self._last[i] = ok
        self.steps += 1

    def result(self) -> PredicateResult:
        firsts = self.first_true
        happened = all(f is not None for f in firsts)
        ordered = happened and all(a < b for a, b in itertools.pairwise(firsts))
        ok = ordered and all(self._last)
        reason = ("events happened in order" if ok else
                  "an event never happened" if not happened else
                  "events happened out of order" if not ordered else "an event no longer holds")
        return PredicateResult("in_order", self.goal.args(), ok, {"first_true_step": firsts, "holds_now": list(self._last)}, {}, reason)


# ---------------------------------------------------------------------------
# Goal evaluation with interchangeable objects
# ---------------------------------------------------------------------------

MAX_ASSIGNMENTS = 5040
"""Most object assignments tried when interchangeable objects could satisfy the goal."""


def _swaps_matter(goal: Predicate, groups: list[list[str]]) -> bool:
    """Whether swapping interchangeable objects can change the goal's result.

    It cannot when every leaf predicate is ``swap_invariant`` and holds either all or none
    of each group of interchangeable objects (a circle of six red cubes: no swap matters;
    two stacks of red cubes: which cube is in which stack does).
    """
    leaves, stack = [], [goal]
    while stack:
        p = stack.pop()
        kids = p.children()
        if kids:
            stack.extend(kids)
        else:
            leaves.append(p)
    for leaf in leaves:
        names = set(leaf.object_names())
        for g in groups:
            inside = names.intersection(g)
            if inside and (not leaf.swap_invariant or len(inside) != len(g)):
                return True
    return False


def evaluate_goal(goal: Predicate, state: WorldState) -> PredicateResult:
    """Evaluate ``goal``, accepting any swap of indistinguishable objects that satisfies it.

    Objects with the same kind, colour and labels are interchangeable: a goal naming
    ``red_1`` and ``red_2`` holds if it holds with the two swapped (when a swap can matter
    at all, see :func:`_swaps_matter`).  At most
    :data:`MAX_ASSIGNMENTS` assignments are tried; the literal result is returned if none
    satisfies the goal.
    """
    result = goal.evaluate(state)
    if result.satisfied:
        return result
    mentioned = sorted(set(goal.object_names()))
    classes: dict[tuple, list[str]] = {}
    for n in mentioned:
        if n in state.objects and state[n].is_cube:
            classes.setdefault(_signature(state[n]), []).append(n)
    groups = [g for g in classes.values() if len(g) > 1]
    if not groups or not _swaps_matter(goal, groups):
        return result
    total = math.prod(math.factorial(len(g)) for g in groups)
    if total > MAX_ASSIGNMENTS:  # checked before any permutation is built: 14 identical cubes have 14! of them
        return result
    for combo in itertools.product(*(itertools.permutations(g) for g in groups)):
        mapping = {}
        for g, perm in zip(groups, combo, strict=True):
            mapping.update(dict(zip(g, perm, strict=True)))
        if all(k == v for k, v in mapping.items()):
            continue
        alt = goal.rename(mapping).evaluate(state)
        if alt.satisfied:
            return alt
    return result
