"""The structure kinds of the domain, in one registry: what each is called, which goal
predicate states it, how its goal layout is built, which recognizer of the builtin parser
reads it, how steering reads it back from a schema (:class:`TaskSpec`), states it as a
canonical instruction, and fits another structure's cubes into it (a Pivot).

The parser (``rpg.schema.builtin``), the steering spec (``rpg.steer.spec``) and the edit
reader (``rpg.steer.edits``) loop over :data:`STRUCTURE_KINDS` instead of naming
structures one by one; adding a structure kind means adding one class here.

A canonical instruction never names one cube twice: cubes alike are counted ("3 red
blocks") or listed as a sequence ("from bottom to top: red, red, blue"), which the parser
reads as separate cubes.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import ClassVar

from rpg.domain import layouts
from rpg.domain.predicates import (
    Grid,
    InCircle,
    InLine,
    LayersUniform,
    Piles,
    Predicate,
    Pyramid,
    Reads,
    SortedBy,
    Stack,
    UnorderedStack,
)
from rpg.errors import BadInput
from rpg.schema.model import TaskSchema


@dataclass(frozen=True)
class Item:
    """One cube: a colour (coloured cube) or a label (semantic cube)."""

    color: str | None = None
    label: str | None = None

    @property
    def material(self) -> str:
        """``colors``, ``letters`` or ``digits``."""
        if self.label is None:
            return "colors"
        return "digits" if self.label.isdigit() else "letters"

    def phrase(self) -> str:
        """How the canonical instruction names the cube: ``red`` or ``letter 'A'``."""
        if self.label is None:
            return str(self.color)
        return f"{'digit' if self.label.isdigit() else 'letter'} '{self.label}'"


@dataclass(frozen=True)
class TaskSpec:
    """A structure task as steering edits it.

    Attributes:
        structure: a name in :data:`STRUCTURE_KINDS`.
        items: the cubes, in structure order (tower: bottom to top; line: reading order;
            pyramid/grid/block: layout order, bottom layer first).
        dims: pyramid ``(base, 2|3)``, grid ``(rows, cols)``, block ``(rows, cols, layers)``.
        ordering: ``label`` (alphabetical), ``number`` (numerical), ``color`` (gradient) or None.
        descending: reverse ordering.
        direction: reading direction of a line (``left_to_right``...); None for a line
            without an order.
        axis: ``y`` (left-right) or ``x`` (front-back) for a line without an order.
        layer_colors: each layer of a pyramid or block is one colour, layers differ.
        piles_by: ``color`` or ``type`` for piles sorted by an attribute; ``one`` for one pile of cubes of several colours.
        outliers: per-pile outliers (piles).
        word: the word a line spells, if any.
        named: a line whose labelled cubes the words name one by one, in order (no sort judged
            apart from it): a sorted line of them is stated by listing them.
    """

    structure: str
    items: tuple[Item, ...]
    dims: tuple[int, ...] = ()
    ordering: str | None = None
    descending: bool = False
    direction: str | None = "left_to_right"
    axis: str | None = None
    layer_colors: bool = False
    piles_by: str | None = None
    outliers: int = 0
    word: str | None = None
    named: bool = False

    @property
    def material(self) -> str:
        """``colors``, ``letters``, ``digits`` or ``mixed``."""
        kinds = {i.material for i in self.items}
        return kinds.pop() if len(kinds) == 1 else "mixed"

    def colors(self) -> list[str]:
        return [i.color for i in self.items if i.color]

    def with_items(self, items) -> TaskSpec:
        return replace(self, items=tuple(items))

    @property
    def kind(self) -> StructureKind:
        return STRUCTURE_KINDS[self.structure]


Resize = Callable[[TaskSpec, int], TaskSpec]
"""Grows or shrinks a spec to ``n`` cubes, choosing new cubes as the edit reader does."""


@dataclass(frozen=True)
class Parts:
    """A goal's conjuncts as the kinds read them: the main predicate first, and the
    modifiers every kind shares (an ordering, uniform layers)."""

    main: Predicate
    kinds: frozenset[type]
    ordering: dict
    layers: bool
    all: tuple[Predicate, ...]


# ---------------------------------------------------------------------------
# phrases shared by the kinds
# ---------------------------------------------------------------------------


def join_words(words: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    if len(words) <= 1:
        return "".join(words)
    return ", ".join(words[:-1]) + " and " + words[-1]


NUMBER_WORDS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def cube_list(colors: list[str], article: str = "the") -> str:
    """Coloured cubes named once each: ``the red block``, ``two green blocks and the red block``.

    Cubes of one colour are counted, never repeated ("the green block and the green block"
    would name one cube twice).
    """
    counts = {c: colors.count(c) for c in dict.fromkeys(colors)}
    return join_words([f"{article} {c} block" if n == 1 else f"{NUMBER_WORDS[n] if n < len(NUMBER_WORDS) else n} {c} blocks"
                       for c, n in counts.items()])


def material_phrase(spec: TaskSpec, noun: str = "blocks") -> str:
    m = spec.material
    if m == "letters":
        return f"letter {noun}"
    if m == "digits":
        return f"digit {noun}"
    colors = list(dict.fromkeys(spec.colors()))
    return f"{join_words(colors)} {noun}" if colors else noun


def ordering_phrase(spec: TaskSpec) -> str:
    text = {"label": "sorted alphabetically", "number": "sorted numerically", "color": "in a color gradient"}.get(
        spec.ordering or "")
    if not text:
        return ""
    return " " + text + (" in reverse order" if spec.descending else "")


def color_sequence(spec: TaskSpec) -> str:
    """``": red, red, blue"`` when coloured cubes are not all alike (the exact sequence)."""
    if spec.material != "colors" or len(set(spec.colors())) <= 1:
        return ""
    return ": " + ", ".join(spec.colors())


def pyramid_count(base: int, dims: int) -> int:
    """Cubes in a pyramid with a ``base`` wide bottom layer, 2D (a wall) or 3D."""
    return sum((base - k) ** (dims - 1) for k in range(base))


# ---------------------------------------------------------------------------
# the kinds
# ---------------------------------------------------------------------------


class StructureKind:
    """One structure kind (template methods; subclasses set the class attributes).

    Attributes:
        name: the kind's name in specs and edits (``tower``).
        words: words that name it in instructions and edits, singular (``stack``, ``column``).
        predicate: the goal predicate that states it.
        layout: the :mod:`rpg.domain.layouts` function that places its cubes.
        recognizer: the builtin parser's recognizer that reads it (``rpg.schema.builtin``).
        min_cubes: the fewest cubes it can have.
        sized_by_count: its size is a number of cubes (cubes can be added one by one);
            otherwise its dimensions set it.
        layered: it has layers (a colour per layer is an ordering of it).
        spells: its cubes can spell a word.
        rainbow: a colour ordering of it recolours its cubes in gradient order.
        grouped: its cubes form groups (piles) that an ordering key sorts them into.
        carriers: goal predicates that carry a mention of the kind's words (mention accounting:
            a tower word is carried by any stacked structure, a row by a line, a sequence or a
            grid's rows).
    """

    name: ClassVar[str]
    words: ClassVar[tuple[str, ...]]
    predicate: ClassVar[type[Predicate]]
    layout: ClassVar[Callable]
    recognizer: ClassVar[str]
    min_cubes: ClassVar[int] = 1
    keeps_ordering: ClassVar[bool] = False
    sized_by_count: ClassVar[bool] = False
    layered: ClassVar[bool] = False
    spells: ClassVar[bool] = False
    rainbow: ClassVar[bool] = False
    grouped: ClassVar[bool] = False
    carriers: ClassVar[tuple[str, ...]] = ()
    described_by: ClassVar[tuple[str, ...]] = ()
    """Further nouns that name the kind where the front end reads a described structure ("a 3
    block tall pillar", "a blue column of 4"): read by :data:`rpg.schema.lexicon.TOWER_NOUNS`,
    not edit words (an edit's "pile" is the piles kind)."""

    def extract(self, parts: Parts, seq: Callable) -> TaskSpec | None:
        """The spec of a goal whose main predicate is this kind's, or None."""
        raise NotImplementedError

    def render(self, spec: TaskSpec) -> str:
        """The canonical instruction: the builtin parser compiles it to the spec's task."""
        raise NotImplementedError

    def fit(self, spec: TaskSpec, resize: Resize) -> TaskSpec:
        """Another structure's cubes arranged as this kind (a Pivot).

        Raises:
            BadInput: too few cubes for this kind.
        """
        if len(spec.items) < self.min_cubes:
            raise BadInput(f"a {self.name} needs at least {NUMBER_WORDS[self.min_cubes]} cubes")
        return TaskSpec(self.name, spec.items, **self._carried(spec))

    def layer_sizes(self, spec: TaskSpec) -> list[int]:
        """Cubes per layer, bottom first (one layer unless the kind is layered)."""
        return [len(spec.items)]

    def grown(self, dims: tuple[int, ...], delta: int) -> tuple[int, ...]:
        """Dimensions one step larger (``delta`` = 1) or smaller (-1): every side."""
        return tuple(x + delta for x in dims)

    def cube_count(self, dims: tuple[int, ...]) -> int:
        """Cubes in a structure of these dimensions."""
        return math.prod(dims)

    def _carried(self, spec: TaskSpec) -> dict:
        return dict(ordering=spec.ordering if self.keeps_ordering else None, descending=spec.descending)


class Tower(StructureKind):
    name, words, predicate, recognizer = "tower", ("tower", "stack"), Stack, "recognize_tower_sequence"
    layout = staticmethod(layouts.stack_layout)
    min_cubes = 2
    sized_by_count = spells = rainbow = True
    carriers = ("stack", "on", "pyramid", "grid")
    described_by = ("column", "pile", "pillar")

    def extract(self, parts, seq):
        if len(parts.kinds) == 1 and parts.kinds <= {Stack, UnorderedStack} and len(parts.all) == 1:
            return TaskSpec("tower", seq(parts.main.objects))  # steered, it is rendered bottom to top
        return None

    def render(self, spec):
        if len(spec.items) < 2:
            raise BadInput("a tower needs at least two cubes")
        return "Build a tower from bottom to top: " + ", ".join(i.phrase() for i in spec.items)

    def fit(self, spec, resize):
        """Another structure's cubes stacked (a Pivot, "stack them instead"): which cube stands
        where is not said, so the tower is in any order (a spelled word keeps its letters' order)."""
        super().fit(spec, resize)
        return TaskSpec("tower", spec.items, direction="left_to_right" if spec.word or spec.ordering else None)


class Line(StructureKind):
    name, words, predicate, recognizer = "line", ("line", "row"), InLine, "recognize_ordered_line"
    layout = staticmethod(layouts.line_layout)
    keeps_ordering = sized_by_count = spells = True
    carriers = ("in_line", "reads", "sorted_by", "equation", "grid")

    def extract(self, parts, seq):
        if not isinstance(parts.main, InLine) or not parts.kinds <= {InLine, SortedBy, Reads}:
            return None
        main, sort = parts.main, next((p for p in parts.all if isinstance(p, SortedBy)), None)
        reads = next((p for p in parts.all if isinstance(p, Reads)), None)
        word = reads.text if reads and reads.text.isalpha() and len(reads.text) >= 2 and not sort else None
        if main.order is None or (main.order == "sequence" and len(set(seq(main.objects))) == 1):
            # an order from either end over identical cubes says nothing: an edit that recolours some starts unordered
            return TaskSpec("line", seq(main.objects), direction=None, axis=main.axis or "y")
        named = not parts.ordering and main.order in ("left_to_right", "right_to_left", "front_to_back", "back_to_front") \
            and all(i.label for i in seq(main.objects))  # labels listed one by one, no sort judged apart
        ordering = _sorted_labels(seq(main.objects)) if named and not reads else parts.ordering  # a word's order is no sort
        return TaskSpec("line", seq(main.objects), direction=main.order, word=word, named=named, **ordering)

    def render(self, spec):
        n = len(spec.items)
        if spec.direction == "sequence" and spec.material == "colors":  # an order from either end
            return f"Arrange {n} blocks in a line in the order {', '.join(spec.colors())}"
        if spec.direction is None or spec.direction == "sequence":
            where = " from front to back" if spec.axis == "x" else ""
            if spec.material == "colors":
                return f"Align {n} blocks in a single straight line{where}: {', '.join(spec.colors())}"
            labels = [i.label for i in spec.items]
            if spec.direction is None and not where and n >= 2 and all(labels):  # the cubes named, none given a place
                what = "letter" if spec.material == "letters" else "digit"  # (they had been made up: "3 letter blocks")
                return f"Put the {what} cubes {', '.join(labels[:-1])} and {labels[-1]} in a row, in any order"
            return f"Align {n} {material_phrase(spec)} in a single straight line{where}"
        d = "from " + spec.direction.replace("_", " ")
        word = "".join(i.label or "" for i in spec.items)
        if spec.word and word.isalpha() and len(word) == n:  # the word follows the cubes (reversed, relabelled...)
            return f"Spell the word '{word}' using letter cubes arranged in a line {d}"
        if spec.ordering == "color":
            reverse = " in reverse order" if spec.descending else ""
            return f"Align {n} blocks in a color gradient {d}{reverse}: {', '.join(spec.colors())}"
        if spec.named and spec.ordering in ("label", "number") and all(i.label for i in spec.items) and _sorted_labels(spec.items):
            what = "letter" if spec.ordering == "label" else "digit"  # the cubes named: a line of them in that order
            labels = [i.label for i in spec.items]
            return f"Put the {what} cubes {', '.join(labels[:-1])} and {labels[-1]} in a row {d}"
        if spec.ordering:
            what = {"label": "letter cubes in alphabetical", "number": "digit cubes in increasing numerical"}[spec.ordering]
            labels = sorted((i.label or "" for i in spec.items), key=lambda x: (x.isdigit() and int(x), x))
            default = [str(k + 1) for k in range(n)] if spec.ordering == "number" else [chr(ord("A") + k) for k in range(n)]
            if all(labels) and labels != default:  # the cubes named ("the digit
                noun, order = what.split(" in ")  # cubes 2, 4 and 6"): a default count had made up 1, 2, 3
                return f"Arrange the {noun} {', '.join(labels[:-1])} and {labels[-1]} in {order} order {d}" + (
                    " in reverse" if spec.descending else "")
            return f"Arrange {n} {what} order {d}" + (" in reverse" if spec.descending else "")
        if spec.named and spec.material in ("letters", "digits") and n >= 3 and all(i.label for i in spec.items) \
                and not spec.ordering:  # cubes named one by one in an order ("the letter cubes C, A and T in a row from
            what = "letter" if spec.material == "letters" else "digit"  # left to right"), no word spelled: so again
            labels = [i.label for i in spec.items]
            return f"Put the {what} cubes {', '.join(labels[:-1])} and {labels[-1]} in a row {d}"
        if spec.material in ("letters", "digits") and n >= 3:
            return f"Arrange cubes so that their up-faces read {', '.join(i.label or '' for i in spec.items)} {d}"
        return f"Arrange the blocks in order {', '.join(i.phrase() for i in spec.items)} {d}"

    def fit(self, spec, resize):
        """Another structure's cubes in a line (a Pivot, "put them in a row"): in an order only
        when the cubes are sorted (letters, digits, a gradient); otherwise which cube stands where
        is not said."""
        carried = self._carried(spec)
        return TaskSpec("line", spec.items, direction="left_to_right" if carried["ordering"] else None, **carried)


class PyramidKind(StructureKind):
    name, words, predicate, recognizer = "pyramid", ("pyramid",), Pyramid, "recognize_pyramid"
    layout = staticmethod(layouts.pyramid_layout)
    keeps_ordering = layered = True
    carriers = ("pyramid",)

    def extract(self, parts, seq):
        # (a pyramid of layers said one by one, "three on the bottom and one on top", is not one a spec states)
        if isinstance(parts.main, Pyramid) and not parts.main.layers and parts.kinds <= {Pyramid, SortedBy, LayersUniform}:
            m = parts.main
            return TaskSpec("pyramid", seq(m.objects), (m.base, m.dims), layer_colors=parts.layers, **parts.ordering)
        return None

    def render(self, spec):
        base, dims = spec.dims
        size = f"with a {base}x{base} base" if dims == 3 else f"with a base of {base}"
        if spec.layer_colors:
            return f"Build a pyramid {size} where each layer is a different color: {join_words(list(dict.fromkeys(spec.colors())))}"
        return f"Build a pyramid of {material_phrase(spec)} {size}" + ordering_phrase(spec)

    def fit(self, spec, resize):
        n = len(spec.items)
        base = next((b for b in range(2, 8) if pyramid_count(b, 2) >= n), None)
        if base is None:
            raise BadInput(f"{n} cubes are too many for a pyramid; remove some first")
        return resize(TaskSpec("pyramid", spec.items, (base, 2), **self._carried(spec)), pyramid_count(base, 2))

    def layer_sizes(self, spec):
        base, dims = spec.dims
        return [(base - k) ** (dims - 1) for k in range(base)]

    def grown(self, dims, delta):
        return (dims[0] + delta, dims[1])  # the base widens; 2D or 3D stays

    def cube_count(self, dims):
        return pyramid_count(*dims)


class GridKind(StructureKind):
    name, words, predicate, recognizer = "grid", ("grid", "square"), Grid, "recognize_grid"
    layout = staticmethod(layouts.grid_layout)
    keeps_ordering = True
    carriers = ("grid", "on_patch")  # "square" also names a square goal patch

    def extract(self, parts, seq):
        m = parts.main
        if isinstance(m, Grid) and m.layers == 1 and parts.kinds <= {Grid, SortedBy, LayersUniform}:
            return TaskSpec("grid", seq(m.objects), (m.rows, m.cols), **parts.ordering)
        return None

    def render(self, spec):
        r, c = spec.dims
        listed = color_sequence(spec)
        return f"Make a {r}x{c} grid of {'blocks' if listed else material_phrase(spec)}" + ordering_phrase(spec) + listed

    def fit(self, spec, resize):
        side = max(2, round(len(spec.items) ** 0.5))
        return resize(TaskSpec("grid", spec.items, (side, side), **self._carried(spec)), side * side)


class Block(StructureKind):
    """A 3D grid of cubes ("a 2x2x2 cube of blocks")."""

    name, words, predicate, recognizer = "block", (), Grid, "recognize_cube_block"
    layout = staticmethod(layouts.grid_layout)
    layered = True
    carriers = ("grid",)

    def extract(self, parts, seq):
        m = parts.main
        if isinstance(m, Grid) and m.layers > 1 and parts.kinds <= {Grid, SortedBy, LayersUniform}:
            return TaskSpec("block", seq(m.objects), (m.rows, m.cols, m.layers), layer_colors=parts.layers,
                            **parts.ordering)
        return None

    def render(self, spec):
        r, c, layers = spec.dims
        if spec.layer_colors:
            return (f"Make a {r}x{c}x{layers} cube of blocks where each layer is a different color: "
                    f"{join_words(list(dict.fromkeys(spec.colors())))}")
        return f"Make a {r}x{c}x{layers} cube of {material_phrase(spec)}" + ordering_phrase(spec)

    def fit(self, spec, resize):
        raise BadInput("name the dimensions of the cube of blocks (e.g. 'make it a 2x2x2 cube')")

    def layer_sizes(self, spec):
        r, c, layers = spec.dims
        return [r * c] * layers


class Circle(StructureKind):
    name, words, predicate, recognizer = "circle", ("circle", "ring"), InCircle, "recognize_circle"
    layout = staticmethod(layouts.circle_layout)
    min_cubes = 3
    sized_by_count = rainbow = True
    carriers = ("in_circle",)

    def extract(self, parts, seq):
        if isinstance(parts.main, InCircle) and parts.kinds <= {InCircle, SortedBy}:
            return TaskSpec("circle", seq(parts.main.objects), **parts.ordering)
        return None

    def render(self, spec):
        listed = color_sequence(spec)
        return f"Place {len(spec.items)} {'blocks' if listed else material_phrase(spec)} in a circle" + listed

    def fit(self, spec, resize):
        super().fit(spec, resize)
        return TaskSpec("circle", spec.items)


class PilesKind(StructureKind):
    name, words, predicate, recognizer = "piles", ("pile",), Piles, "recognize_piles"
    layout = staticmethod(layouts.cluster_layout)
    sized_by_count = grouped = True
    carriers = ("piles",)

    def extract(self, parts, seq):
        m = parts.main
        if not isinstance(m, Piles) or len(parts.all) != 1:
            return None
        if not m.groups:
            return TaskSpec("piles", seq(m.objects), piles_by=m.by or "color")
        groups = [seq(g) for g in m.groups]
        by = "type" if len({i.material for g in groups for i in g}) > 1 else "color"
        if len(groups) == 1 and by == "color" and all(i.color for i in groups[0]) and len({i.color for i in groups[0]}) > 1:
            return TaskSpec("piles", groups[0], piles_by="one")  # one pile of cubes of several colours ("heap the gray cube
            # and two purple cubes into one pile"): one pile still after an edit (it had been read as piles by colour with an
            # outlier each, and a cube added made two piles, silently)

        def key(i: Item) -> str | None:
            return i.material if by == "type" else i.color

        outliers = min(len(g) - max(sum(1 for i in g if key(i) == k) for k in {key(i) for i in g}) for g in groups)
        return TaskSpec("piles", tuple(i for g in groups for i in g), piles_by=by, outliers=outliers)

    def render(self, spec):
        if spec.piles_by == "one" and len({i.color for i in spec.items}) > 1:  # "Put one gray cube and three purple cubes into one pile"
            counts = Counter(i.color for i in spec.items)
            return "Put " + join_words([f"{n} {c} cube{'s' if n > 1 else ''}" for c, n in counts.items()]) + " into one pile"
        tail = f" so that each pile has {spec.outliers} outlier{'s' if spec.outliers > 1 else ''}" if spec.outliers else ""
        if spec.piles_by == "type" or spec.material == "mixed":
            return "Sort letters, numbers and colors mixed into respective piles" + tail
        colors = list(dict.fromkeys(spec.colors()))
        if len(colors) == 1:  # one colour: one pile
            return f"Make a pile of {len(spec.items)} {colors[0]} blocks" + tail
        return f"Sort {len(spec.items)} {join_words(colors)} blocks into piles by color" + tail

    def fit(self, spec, resize):
        return TaskSpec("piles", spec.items, piles_by="type" if spec.material == "mixed" else "one" if spec.piles_by == "one" else "color")


STRUCTURE_KINDS: dict[str, StructureKind] = {k.name: k for k in
                                             (Tower(), Line(), PyramidKind(), GridKind(), Block(), Circle(), PilesKind())}
"""Structure kind name -> kind, in the order :func:`extract` tries them."""

STRUCTURES = tuple(STRUCTURE_KINDS)
"""Names of the structures whose spec steering can edit."""

STRUCTURE_WORDS: dict[str, str] = {w: k.name for k in STRUCTURE_KINDS.values() for w in k.words}
"""A word that names a structure (singular) -> the kind's name."""

STRUCTURE_RE = r"\b(" + "|".join(f"{w}s?" for w in sorted(STRUCTURE_WORDS, key=lambda w: (-len(w), w))) + r")\b"
"""Matches a structure word, singular or plural (group 1)."""


def structure_of_word(word: str) -> str:
    """The kind a structure word names (``stacks`` -> ``tower``).

    Raises:
        KeyError: not a structure word.
    """
    w = word.lower()
    return STRUCTURE_WORDS[w] if w in STRUCTURE_WORDS else STRUCTURE_WORDS[w[:-1]]


def _sorted_labels(items) -> dict:
    """``{"ordering": "number" | "label", "descending": bool}`` when ``items`` are two or more digit or
    letter cubes whose labels stand strictly sorted in their listed order (a line of 4, 3, 2, 1 is
    sorted, descending, by number); else ``{}``."""
    labels = [i.label for i in items]
    if len(labels) < 2 or not all(labels) or len(set(labels)) < len(labels):
        return {}
    if all(lab.isdigit() for lab in labels):
        key, values = "number", [int(lab) for lab in labels]
    elif all(lab.isalpha() for lab in labels):
        key, values = "label", labels
    else:
        return {}
    if values == sorted(values):
        return {"ordering": key, "descending": False}
    if values == sorted(values, reverse=True):
        return {"ordering": key, "descending": True}
    return {}


def sort_labels(items, key: str, descending: bool) -> tuple:
    """``items`` (labelled cubes) in the order a sort by ``key`` puts them: by number when every
    label is a digit and ``key`` is ``number``, else by label (the order :func:`_sorted_labels` reads)."""
    by_number = key == "number" and all(i.label.isdigit() for i in items)
    return tuple(sorted(items, key=(lambda i: int(i.label)) if by_number else (lambda i: i.label), reverse=descending))


def extract(schema: TaskSchema) -> TaskSpec | None:
    """Read a schema back into a TaskSpec; None if its structure is not editable
    (relations between named cubes, goal patches, temporal order, equations)."""
    if any(a.kind == "goal_patch" for a in schema.assets):
        return None
    items = {a.name: Item(color=a.color) if a.kind == "colored_cube" else Item(label=a.label) for a in schema.assets}
    conj = tuple(schema.goal.conjuncts())
    sort = next((p for p in conj if isinstance(p, SortedBy)), None)
    parts = Parts(conj[0], frozenset(type(p) for p in conj),
                  dict(ordering=sort.key, descending=bool(sort.descending)) if sort else {},
                  any(isinstance(p, LayersUniform) for p in conj), conj)

    def seq(names) -> tuple[Item, ...]:
        return tuple(items[n] for n in names)

    for kind in STRUCTURE_KINDS.values():
        spec = kind.extract(parts, seq)
        if spec is not None:
            return spec
    return None


def render(spec: TaskSpec) -> str:
    """The canonical instruction of a spec: the builtin parser compiles it to the spec's task.

    Raises:
        BadInput: the spec cannot be stated (e.g. an empty structure).
    """
    if not spec.items:
        raise BadInput("a task needs at least one cube")
    return spec.kind.render(spec)
