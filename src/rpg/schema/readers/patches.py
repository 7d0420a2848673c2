"""Readers of goal patches: a cube per matching patch, a stack on each patch."""

from __future__ import annotations

import re

from rpg.domain.layouts import (
    stack_layout,
)
from rpg.domain.predicates import (
    OnPatch,
)
from rpg.schema.builder import DEFAULT_PATCH_COLOR, Builder
from rpg.schema.lexicon import COLOR_RE
from rpg.schema.readers.common import colors_for, patch_spots, stated_count
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, ParseError, canon_color


@reader(order=60)
def recognize_matching_patches(f: Features, b: Builder) -> bool:
    """Each cube on the goal patch of its own colour ("place each block on the patch of the
    same color", "put the red and blue blocks on their matching patches")."""
    if not f.has("patch", "patches", "target", "targets") or f.has("stack", "stacks", "tower", "towers", "first"):
        return False
    if not re.search(r"\b(?:same colou?r|matching|its colou?r|their colou?r|respective|own colou?r|corresponding)\b", f.text):
        return False
    colors = list(dict.fromkeys(f.color_list()))
    n = max(stated_count(f, default=None) or 0, len(colors)) or 2  # the colours named are the cubes, no more
    colors = colors_for(n, f, prefer=colors)
    centers = b.unit_centers(len(colors), 0.14)
    for color, (x, y) in zip(colors, centers, strict=True):
        cube, patch = b.cube(color), b.patch(color)
        b.place_patch(patch, (x, y))
        b.place(stack_layout([cube], (x, y)))
        b.preds.append(OnPatch(cube, patch))
    b.primitives += ["place"]
    b.summary.append("each cube on the patch of its colour: " + ", ".join(colors))
    b.min_separation = 0.10
    return True


EACH_PATCH_RE = re.compile(
    r"\b(?:a|one|(?P<k>\d+))\s+(?:(?P<color>" + COLOR_RE + r")\s+)?(?:block|cube|box)e?s?\s+(?:on|onto|in|into|to)\s+"
    r"(?:each|every)\s+(?:one\s+)?(?:of\s+the\s+)?(?:(?P<n>\d+)\s+)?(?:(?P<pcolor>" + COLOR_RE + r")\s+)?"
    r"(?:goal\s+|target\s+)?(?:patch|patches|target|targets)\b"
    r"|\b(?:one|1)\s+(?:(?P<color2>" + COLOR_RE + r")\s+)?(?:block|cube)\s+per\s+(?:goal\s+|target\s+)?patch\b")


@reader(order=50)
def recognize_each_patch(f: Features, b: Builder) -> bool:
    """One cube on each of several goal patches ("place a block on each of the three goal
    patches", "one cube per patch").  The cubes share a colour, so any cube may take any
    patch."""
    m = EACH_PATCH_RE.search(f.text)
    if not m:
        return False
    per = int(m.group("k")) if m.group("k") else 1  # "two blocks on each patch"
    named = set(re.findall(rf"\b({COLOR_RE})\s+(?:goal\s+|target\s+)?patch\b", f.text))
    if not m.group("n") and not m.group("pcolor") and len(named) >= 2:
        # "one cube on each patch: red on the red patch, blue on the blue patch": said twice, as a count and patch by patch
        raise ParseError(f"\"{f.original[:80]}\" says a cube for each patch and names the patches one by one as well; "
                         "say each cube's patch once (e.g. \"put the red cube on the red patch and the blue cube on the blue "
                         "patch\"), or use --model")
    n = int(m.group("n")) if m.group("n") else stated_count(f, "patch|patche|target", default=None)
    if n is None:  # "put one cube on each patch": how many patches? (3 had been made up)
        raise ParseError(f"\"{f.original[:80]}\" puts cubes on each patch but does not say how many patches there are; "
                         "say it (e.g. \"a cube on each of the three patches\"), or use --model")
    if not 2 <= n <= 6:
        raise ParseError(f"cubes on each of {n} patches: use 2 to 6 patches")
    color = canon_color(m.group("color") or m.group("color2") or "red")
    pcolor = canon_color(m.group("pcolor")) if m.group("pcolor") else DEFAULT_PATCH_COLOR
    centers = b.unit_centers(n, 0.14 if per == 1 else 0.16)
    cubes = []
    for x, y in centers:
        patch = b.patch(pcolor)
        b.place_patch(patch, (x, y))
        for spot in patch_spots((x, y), "square", per):
            cube = b.cube(color)
            b.place(stack_layout([cube], spot))
            b.preds.append(OnPatch(cube, patch))
            cubes.append(cube)
    b.primitives += ["place"]
    what = "one cube" if per == 1 else f"{per} cubes"
    b.summary.append(f"{what} on each of the {n} goal patches ({', '.join(cubes)}, any cube on any patch)")
    b.min_separation = 0.10
    return True
