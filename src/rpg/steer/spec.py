"""TaskSpec: the editable form of a task that steering works on.

Steering does not patch code.  It reads the reference version's schema back into a small
:class:`TaskSpec` (structure, cubes in structure order, dimensions, ordering), applies the
edit to that spec, and renders the result as a *canonical instruction* that the builtin
parser compiles like any other instruction.  The new version is therefore exactly the
task a user would get by typing its canonical instruction, which is recorded with it.

Structures with an editable spec: ``tower``, ``line``, ``pyramid``, ``grid``, ``block``
(3D grid), ``circle`` and ``piles``.  Other tasks (relations between named cubes, goal
patches, temporal order, equations) return ``None`` from :func:`extract`; steering then
accepts colour tweaks, the edits :mod:`rpg.steer.relations` reads (one relation between
two cubes, cubes on one patch) and edits that state a whole task.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

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
)
from rpg.schema.model import TaskSchema

STRUCTURES = ("tower", "line", "pyramid", "grid", "block", "circle", "piles")
"""Structures whose spec steering can edit."""


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
    """A task as steering edits it.

    Attributes:
        structure: one of :data:`STRUCTURES`.
        items: the cubes, in structure order (tower: bottom to top; line: reading order;
            pyramid/grid/block: layout order, bottom layer first).
        dims: pyramid ``(base, 2|3)``, grid ``(rows, cols)``, block ``(rows, cols, layers)``.
        ordering: ``label`` (alphabetical), ``number`` (numerical), ``color`` (gradient) or None.
        descending: reverse ordering.
        direction: reading direction of a line (``left_to_right``...); None for a line
            without an order.
        axis: ``y`` (left-right) or ``x`` (front-back) for a line without an order.
        layer_colors: each layer of a pyramid or block is one colour, layers differ.
        piles_by: ``color`` or ``type`` for piles.
        outliers: per-pile outliers (piles).
        word: the word a line spells, if any.
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

    @property
    def material(self) -> str:
        """``colors``, ``letters``, ``digits`` or ``mixed``."""
        kinds = {i.material for i in self.items}
        return kinds.pop() if len(kinds) == 1 else "mixed"

    def colors(self) -> list[str]:
        return [i.color for i in self.items if i.color]

    def with_items(self, items) -> TaskSpec:
        return replace(self, items=tuple(items))


# ---------------------------------------------------------------------------
# schema -> spec
# ---------------------------------------------------------------------------


def _parts(goal: Predicate) -> list[Predicate]:
    return goal.conjuncts()


def extract(schema: TaskSchema) -> TaskSpec | None:
    """Read a schema back into a TaskSpec; None if its structure is not editable."""
    if any(a.kind == "goal_patch" for a in schema.assets):
        return None
    items = {a.name: Item(color=a.color) if a.kind == "colored_cube" else Item(label=a.label) for a in schema.assets}
    parts = _parts(schema.goal_predicate())
    kinds = {type(p) for p in parts}
    sort = next((p for p in parts if isinstance(p, SortedBy)), None)
    ordering = dict(ordering=sort.key, descending=bool(sort.descending)) if sort else {}
    layers = any(isinstance(p, LayersUniform) for p in parts)
    main = parts[0]

    def seq(names) -> tuple[Item, ...]:
        return tuple(items[n] for n in names)

    if kinds == {Stack} and len(parts) == 1:
        return TaskSpec("tower", seq(main.objects))
    if isinstance(main, Pyramid) and kinds <= {Pyramid, SortedBy, LayersUniform}:
        return TaskSpec("pyramid", seq(main.objects), (main.base, main.dims), layer_colors=layers, **ordering)
    if isinstance(main, Grid) and kinds <= {Grid, SortedBy, LayersUniform}:
        if main.layers > 1:
            return TaskSpec("block", seq(main.objects), (main.rows, main.cols, main.layers), layer_colors=layers, **ordering)
        return TaskSpec("grid", seq(main.objects), (main.rows, main.cols), **ordering)
    if isinstance(main, InCircle) and kinds <= {InCircle, SortedBy}:
        return TaskSpec("circle", seq(main.objects), **ordering)
    if isinstance(main, Piles) and len(parts) == 1:
        if main.groups:
            groups = [seq(g) for g in main.groups]
            by = "type" if len({i.material for g in groups for i in g}) > 1 else "color"

            def key(i: Item) -> str | None:
                return i.material if by == "type" else i.color

            outliers = min(len(g) - max(sum(1 for i in g if key(i) == k) for k in {key(i) for i in g}) for g in groups)
            return TaskSpec("piles", tuple(i for g in groups for i in g), piles_by=by, outliers=outliers)
        return TaskSpec("piles", seq(main.objects), piles_by=main.by or "color")
    if isinstance(main, InLine) and kinds <= {InLine, SortedBy, Reads}:
        reads = next((p for p in parts if isinstance(p, Reads)), None)
        word = reads.text if reads and reads.text.isalpha() and len(reads.text) >= 2 and not sort else None
        if main.order is None:
            return TaskSpec("line", seq(main.objects), direction=None, axis=main.axis or "y")
        return TaskSpec("line", seq(main.objects), direction=main.order, word=word, **ordering)
    return None


# ---------------------------------------------------------------------------
# spec -> canonical instruction
# ---------------------------------------------------------------------------


def _join(words: list[str]) -> str:
    if len(words) <= 1:
        return "".join(words)
    return ", ".join(words[:-1]) + " and " + words[-1]


def _material_phrase(spec: TaskSpec, noun: str = "blocks") -> str:
    m = spec.material
    if m == "letters":
        return f"letter {noun}"
    if m == "digits":
        return f"digit {noun}"
    colors = list(dict.fromkeys(spec.colors()))
    return f"{_join(colors)} {noun}" if colors else noun


def _ordering_phrase(spec: TaskSpec) -> str:
    if spec.ordering == "label":
        text = "sorted alphabetically"
    elif spec.ordering == "number":
        text = "sorted numerically"
    elif spec.ordering == "color":
        text = "in a color gradient"
    else:
        return ""
    return " " + text + (" in reverse order" if spec.descending else "")


def _direction_phrase(direction: str) -> str:
    return "from " + direction.replace("_", " ")


def _color_list(spec: TaskSpec) -> str:
    """``": red, red, blue"`` when coloured cubes are not all alike (the exact sequence)."""
    if spec.material != "colors" or len(set(spec.colors())) <= 1:
        return ""
    return ": " + ", ".join(spec.colors())


def render(spec: TaskSpec) -> str:
    """The canonical instruction of a spec: the builtin parser compiles it to the spec's task.

    Raises:
        ValueError: the spec cannot be stated (e.g. an empty structure).
    """
    if not spec.items:
        raise ValueError("a task needs at least one cube")
    n = len(spec.items)
    s = spec.structure
    if s == "tower":
        if n < 2:
            raise ValueError("a tower needs at least two cubes")
        return "Build a tower from bottom to top: " + ", ".join(i.phrase() for i in spec.items)
    if s == "pyramid":
        base, dims = spec.dims
        size = f"with a {base}x{base} base" if dims == 3 else f"with a base of {base}"
        text = f"Build a pyramid of {_material_phrase(spec)} {size}"
        if spec.layer_colors:
            return f"Build a pyramid {size} where each layer is a different color: {_join(list(dict.fromkeys(spec.colors())))}"
        return text + _ordering_phrase(spec)
    if s == "grid":
        r, c = spec.dims
        listed = _color_list(spec)
        return f"Make a {r}x{c} grid of {'blocks' if listed else _material_phrase(spec)}" + _ordering_phrase(spec) + listed
    if s == "block":
        r, c, layers = spec.dims
        if spec.layer_colors:
            return f"Make a {r}x{c}x{layers} cube of blocks where each layer is a different color: {_join(list(dict.fromkeys(spec.colors())))}"
        return f"Make a {r}x{c}x{layers} cube of {_material_phrase(spec)}" + _ordering_phrase(spec)
    if s == "circle":
        listed = _color_list(spec)
        return f"Place {n} {'blocks' if listed else _material_phrase(spec)} in a circle" + listed
    if s == "piles":
        tail = f" so that each pile has {spec.outliers} outlier{'s' if spec.outliers > 1 else ''}" if spec.outliers else ""
        if spec.piles_by == "type" or spec.material == "mixed":
            return "Sort letters, numbers and colors mixed into respective piles" + tail
        colors = list(dict.fromkeys(spec.colors()))
        return f"Sort {n} {_join(colors)} blocks into piles by color" + tail
    if s == "line":
        if spec.direction is None:
            where = " from front to back" if spec.axis == "x" else ""
            if spec.material == "colors":
                return f"Align {n} blocks in a single straight line{where}: {', '.join(spec.colors())}"
            return f"Align {n} {_material_phrase(spec)} in a single straight line{where}"
        d = _direction_phrase(spec.direction)
        word = "".join(i.label or "" for i in spec.items)
        if spec.word and word.isalpha() and len(word) == n:  # the word follows the cubes (reversed, relabelled...)
            return f"Spell the word '{word}' using letter cubes arranged in a line {d}"
        if spec.ordering == "color":
            reverse = " in reverse order" if spec.descending else ""
            return f"Align {n} blocks in a color gradient {d}{reverse}: {', '.join(spec.colors())}"
        if spec.ordering:
            what = {"label": "letter cubes in alphabetical", "number": "digit cubes in increasing numerical"}[spec.ordering]
            return f"Arrange {n} {what} order {d}" + (" in reverse" if spec.descending else "")
        if spec.material in ("letters", "digits") and n >= 3:
            return f"Arrange cubes so that their up-faces read {', '.join(i.label or '' for i in spec.items)} {d}"
        return f"Arrange the blocks in order {', '.join(i.phrase() for i in spec.items)} {d}"
    raise ValueError(f"cannot state a {s} of {spec.material} as an instruction")
