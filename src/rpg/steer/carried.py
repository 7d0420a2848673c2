"""What a structure task says beyond its :class:`~rpg.steer.spec.TaskSpec`, carried through an edit.

A tower standing in a region of the table ("stack(black,white)@back") or a pyramid whose
bottom layer must be blue (:class:`~rpg.domain.predicates.InLayers`) is a structure task plus
a modifier.  :func:`split` reads the spec of the structure without the modifier and the
modifier apart (:class:`Carried`); an edit changes either ("move the stack to the back of the
table", "make the bottom layer blue", "the top block should be red"); :func:`render` states
both as one canonical instruction and :func:`check` parses it back and refuses, naming what
is lost, when the parser does not read the same task (refuse rather than guess).
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, replace

from rpg.domain.predicates import (
    AnchoredStack,
    And,
    InLayers,
    InRegion,
    OnPatch,
    Stack,
    StackOnPatch,
    UnorderedStack,
)
from rpg.errors import BadInput
from rpg.schema.model import TaskSchema
from rpg.schema.structures import STRUCTURE_WORDS, Item, TaskSpec, cube_list, extract, join_words
from rpg.schema.structures import render as render_spec

REGION_PHRASES = {"center": "in the center of the table", "left": "on the left side of the table",
                  "right": "on the right side of the table", "front": "at the front of the table",
                  "back": "at the back of the table"}
"""How a canonical instruction states each region (corners: "in the back left corner of the table")."""

LAYER_NAMES = {"bottom": "at the bottom", "middle": "in the middle", "top": "on top"}
"""How a canonical instruction gives a colour a layer (:data:`rpg.schema.lexicon.LAYER_ROLE_RE` reads them)."""


def region_phrase(region: str) -> str:
    return REGION_PHRASES.get(region) or f"in the {region.replace('_', ' ')} corner of the table"


@dataclass(frozen=True)
class Carried:
    """The modifiers of a structure task: the region it stands in, and whether the colours of
    its layers are judged (the spec's items then give each layer's cubes, bottom first)."""

    region: str | None = None
    layers: bool = False
    ends: frozenset[str] = frozenset()
    """The ends ("bottom", "top") of a stack in any order whose cube is said (``AnchoredStack``)."""
    patch: str | None = None
    """The colour of the goal patch a tower stands on (its bottom cube on it: ``OnPatch`` /
    ``StackOnPatch``), or None."""


def split(schema: TaskSchema) -> tuple[TaskSpec | None, Carried]:
    """The structure's spec and its modifiers; (None, Carried()) when the task is no
    structure steering edits (or its modifiers are not one region / one layering).  A stack
    in any order of cubes that differ is a spec with no direction (its cubes have no places)."""
    spec, carried = _split(schema)
    if spec is not None and spec.kind.spells and len(set(spec.items)) > 1 and any(
            isinstance(p, UnorderedStack) for p in schema.goal.conjuncts()):
        spec = replace(spec, direction=None)
    return spec, carried


def _split(schema: TaskSchema) -> tuple[TaskSpec | None, Carried]:
    conj = list(schema.goal.conjuncts())
    if len(conj) == 1 and type(conj[0]) is AnchoredStack and not (conj[0].bottom and conj[0].top):
        assets = {a.name: a for a in schema.assets}
        if any(a.kind == "goal_patch" for a in schema.assets):
            return None, Carried()
        items = tuple(Item(color=assets[n].color) if assets[n].kind == "colored_cube" else Item(label=assets[n].label)
                      for n in conj[0].objects)
        return TaskSpec("tower", items, direction=None), Carried(ends=frozenset({"bottom"} if conj[0].bottom else {"top"}))
    regions = [p for p in conj if isinstance(p, InRegion)]
    layers = [p for p in conj if isinstance(p, InLayers)]
    on_patch = [p for p in conj if isinstance(p, OnPatch)]
    if on_patch:
        return _split_on_patch(schema, conj, on_patch, regions or layers)
    if not regions and not layers:
        return extract(schema), Carried()
    rest = [p for p in conj if not isinstance(p, (InRegion, InLayers))]
    if not rest or len({p.region for p in regions}) > 1 or len(layers) > 1:
        return None, Carried()
    bare = schema.model_copy(update={"goal": rest[0] if len(rest) == 1 else And(rest)})
    spec = extract(bare)
    if spec is None:
        return None, Carried()
    members = {n for p in rest for n in p.object_names()}  # (a pile's cubes are its groups': "one pile ... at the back")
    if any(p.a not in members for p in regions):
        return None, Carried()  # a region of a cube outside the structure: not a modifier of it
    if layers and not spec.kind.layered:
        return None, Carried()
    return spec, Carried(regions[0].region if regions else None, bool(layers))


def _split_on_patch(schema: TaskSchema, conj: list, on_patch: list, other_modifiers: list) -> tuple[TaskSpec | None, Carried]:
    """A tower standing on a goal patch ("Build a tower of three cubes on the purple patch"): the
    tower's spec, and the patch's colour carried (its bottom cube on it, whichever cube that is
    for a stack in any order).  (None, Carried()) for anything else: cubes on patches apart from
    a tower, a tower with a region or layers as well."""
    rest = [p for p in conj if not isinstance(p, OnPatch)]
    if len(on_patch) != 1 or other_modifiers or len(rest) != 1 or not isinstance(rest[0], (Stack, UnorderedStack)):
        return None, Carried()
    tower, p = rest[0], on_patch[0]
    if not (isinstance(p, StackOnPatch) and set(p.among) == set(tower.objects)) and not (
            type(p) is OnPatch and type(tower) is Stack and p.a == tower.objects[0]):
        return None, Carried()
    bare = schema.model_copy(update={"goal": tower, "assets": [a for a in schema.assets if a.name != p.patch]})
    spec = extract(bare)
    color = next((a.color for a in schema.assets if a.name == p.patch), None)
    if spec is None or spec.structure != "tower" or color is None:
        return None, Carried()
    if isinstance(tower, UnorderedStack):
        spec = replace(spec, direction=None)
    return spec, Carried(patch=color)


def layers_of(spec: TaskSpec) -> list[list[str | None]]:
    """The colours (or labels) of each layer, bottom first."""
    out, i = [], 0
    for size in spec.kind.layer_sizes(spec):
        out.append([it.color or it.label for it in spec.items[i:i + size]])
        i += size
    return out


def _layer_clause(spec: TaskSpec) -> str:
    """" with 3 blue blocks at the bottom and 3 green blocks": each colour found in one
    nameable layer only is given it, the others are listed without a layer."""
    layers = layers_of(spec)
    n = len(layers)
    names = {0: "bottom", n - 1: "top"} | ({1: "middle"} if n == 3 else {})
    where = {}
    for k, layer in enumerate(layers):
        for c in layer:
            where.setdefault(c, set()).add(k)
    counts = Counter(it.color for it in spec.items)
    parts = []
    for c in dict.fromkeys(it.color for it in spec.items):
        k = next(iter(where[c])) if len(where[c]) == 1 else None
        role = f" {LAYER_NAMES[names[k]]}" if k in names else ""
        parts.append(f"{counts[c]} {c} block{'s' if counts[c] > 1 else ''}{role}")
    return " with " + join_words(parts)


def _counted(spec: TaskSpec, text: str) -> str | None:
    """The statement with its listed colours counted instead (": brown, brown, white, white" ->
    ": 2 brown blocks and 2 white blocks"), where the listing's order says nothing: the
    structure gives no cube its place, or its cubes are all alike."""
    ordered = spec.kind.spells and spec.direction is not None
    if spec.material != "colors" or (ordered and len(set(spec.items)) > 1):
        return None
    m = re.search(r":\s*([a-z]+(?:,\s*[a-z]+)+)\s*$", text)
    if not m or [c.strip() for c in m.group(1).split(",")] != spec.colors():
        return None
    counts = Counter(spec.colors())
    return text[:m.start()] + ": " + join_words([f"{n} {c} block{'s' if n > 1 else ''}" for c, n in counts.items()])


def _anchored(spec: TaskSpec, carried: Carried) -> str:
    """"Stack the red, green, blue and yellow blocks with the yellow block on top": a stack in
    any order whose one end's cube is said."""
    if len(carried.ends) != 1 or spec.material != "colors":
        raise BadInput("the builtin steering states a stack in any order with one end said, of coloured cubes only")
    end = next(iter(carried.ends))
    cube = spec.items[0 if end == "bottom" else -1].color
    return f"Stack {cube_list(spec.colors())} with the {cube} block {'at the bottom' if end == 'bottom' else 'on top'}"


def _variants(spec: TaskSpec, carried: Carried) -> list[str]:
    if carried.ends:
        return [_anchored(spec, carried)]
    texts = [render_spec(spec)]
    if spec.direction is None:  # no order said: a statement without its direction words
        texts.insert(0, re.sub(r"\s+from (?:bottom to top|top to bottom|left to right|right to left|front to back|back to front)\b",
                            "", texts[0]))
    texts += [c for c in (_counted(spec, t) for t in list(texts)) if c]
    labels = [i.label for i in spec.items]
    if spec.material in ("letters", "digits") and len(labels) >= 2 and all(labels):  # "3 digit blocks" makes up 1, 2, 3: the
        named = f"the {spec.material[:-1]} cubes {', '.join(labels[:-1])} and {labels[-1]}"  # task's own named
        texts += [re.sub(r"\b(?:\d+\s+)?(?:letter|digit)\s+(?:blocks|cubes)\b", named, t, count=1) for t in list(texts)]
    return list(dict.fromkeys(v for text in texts for v in _phrasings(spec, carried, text)))


def _phrasings(spec: TaskSpec, carried: Carried, text: str) -> list[str]:
    if carried.layers:
        if spec.material != "colors":
            raise BadInput("the builtin steering states a layer's cubes by colour only")
        text = text + _layer_clause(spec)
        if f" {LAYER_NAMES['middle']}" in text:  # "3 yellow blocks in the middle" of a wall: said as a layer too (it had
            second = text.replace(f" {LAYER_NAMES['middle']}", " in the second layer")  # been read as the table's centre)
            return list(dict.fromkeys(_phrasings(spec, replace(carried, layers=False), text)
                                      + _phrasings(spec, replace(carried, layers=False), second)))
    bare = re.sub(r"\b(letter|digit) '([A-Z0-9])'", r"\1 \2", text)  # "letter 'D'": the parser reads 'd as "would"
    if not carried.region and not carried.patch:
        return list(dict.fromkeys([text, bare]))
    phrase = region_phrase(carried.region) if carried.region else f"on the {carried.patch} goal patch"
    words = "|".join(sorted(STRUCTURE_WORDS, key=len, reverse=True)) + "|cube|pyramid"
    noun = re.search(rf"\b(?:{words})s?\b", text)
    out = []
    if noun:
        out.append(f"{text[:noun.end()]} {phrase}{text[noun.end():]}")
    out += [f"{text}, {phrase}", f"{text} {phrase}"]
    return list(dict.fromkeys(out + [v.replace(text, bare) for v in out]))


def _layers_exact(spec: TaskSpec, schema: TaskSchema) -> bool:
    """Whether the parsed task's :class:`InLayers` judges exactly the spec's layers: the
    named cubes in their layers, and the cubes it leaves free all alike (so wherever they go,
    each layer holds what the spec says)."""
    inl = next((p for p in schema.goal.conjuncts() if isinstance(p, InLayers)), None)
    if inl is None:
        return False
    by_name = {a.name: a.color or a.label for a in schema.assets}
    judged: dict[int, Counter] = {}
    free: Counter = Counter()
    for name, k in zip(inl.objects, inl.levels, strict=True):
        (judged.setdefault(k, Counter()) if k >= 0 else free)[by_name[name]] += 1
    if len(free) > 1:
        return False
    for k, layer in enumerate(layers_of(spec)):
        rest = Counter(layer) - judged.get(k, Counter())
        if judged.get(k, Counter()) - Counter(layer) or set(rest) - set(free):
            return False
    return True


def _same_statement(got: TaskSpec, spec: TaskSpec) -> bool:
    """Whether the spec read back states the same task: its canonical instruction is the
    spec's (a field the statement does not show, such as a stale word, may differ)."""
    try:  # the labels too, which a statement by count alone does not show ("a circle of 3 digit blocks": 1, 2, 3, where the
        # task's were 2, 4, 6)
        labels = [i.label for i in spec.items if i.label]
        named = len(labels) >= 2 and len(set(labels)) == len(labels)  # cubes each with a label of its own (made up by
        return (got.direction is None) == (spec.direction is None) and render_spec(got) == render_spec(spec) and (  # count
            not named or sorted(i.label or "" for i in got.items) == sorted(i.label or "" for i in spec.items))  # when repeated)
    except (BadInput, ValueError):
        return False


def render(spec: TaskSpec, carried: Carried, parse) -> tuple[str, TaskSchema]:
    """The canonical instruction of a spec and its modifiers, and its parsed schema: the
    first phrasing that the parser reads back as the same structure (same spec, or for
    judged layers the same cubes with each layer judged) with the same modifiers.

    Raises:
        BadInput: no phrasing reads back as the same task (the message says what is lost).
    """
    last = None
    for text in _variants(spec, carried):
        try:
            schema = parse(text)
        except (BadInput, ValueError) as exc:
            last = str(exc).splitlines()[0]
            continue
        got, got_carried = split(schema)
        if got is None or got_carried != carried:
            last = f"the parser reads {text!r} as {schema.goal_summary!r}"
            continue
        if carried.ends:
            end = 0 if "bottom" in carried.ends else -1
            if sorted(map(str, got.items)) == sorted(map(str, spec.items)) and got.items[end] == spec.items[end]:
                return text, schema
        elif carried.layers:
            if (got.structure, got.dims, sorted(map(str, got.items))) == (spec.structure, spec.dims, sorted(map(str, spec.items))) \
                    and _layers_exact(spec, schema):
                return text, schema
        elif got == spec or _same_statement(got, spec) or (got.named and replace(  # a listed line's sort is only inferred
                got, ordering=spec.ordering, descending=spec.descending, named=spec.named) == spec) or (
                len(set(spec.items)) == 1 and replace(got, direction=spec.direction, axis=spec.axis) == spec):
            return text, schema  # read back as stated (an order over identical cubes says nothing)
        last = f"the parser reads {text!r} as {schema.goal_summary!r}"
    what = " and ".join(w for w, on in (("where it stands", carried.region), ("its layers' colours", carried.layers)) if on)
    raise BadInput(f"the edited {spec.structure} cannot be stated exactly{' with ' + what if what else ''} "
                   f"({last}); state the whole new task in the edit, or use --model")
