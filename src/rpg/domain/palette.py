"""Named colour palette of the block domain.

Every colour a task may name has one fixed RGB value (0-1 floats).  The hue order of
:data:`GRADIENT_ORDER` defines what a "color gradient" means: neighbours in that list
are neighbours on the colour wheel, red -> orange -> yellow -> green -> cyan -> blue ->
purple -> pink.
"""

from __future__ import annotations

from rpg.errors import BadInput

PALETTE: dict[str, tuple[float, float, float]] = {
    "red": (0.85, 0.10, 0.10),
    "orange": (0.95, 0.50, 0.05),
    "yellow": (0.95, 0.85, 0.10),
    "green": (0.15, 0.70, 0.20),
    "cyan": (0.10, 0.80, 0.85),
    "blue": (0.12, 0.25, 0.85),
    "purple": (0.50, 0.15, 0.70),
    "pink": (0.95, 0.50, 0.70),
    "white": (0.95, 0.95, 0.95),
    "gray": (0.50, 0.50, 0.50),
    "black": (0.08, 0.08, 0.08),
    "brown": (0.50, 0.30, 0.12),
}
"""Colour name -> RGB in [0, 1]."""

GRADIENT_ORDER: tuple[str, ...] = (
    "red", "orange", "yellow", "green", "cyan", "blue", "purple", "pink",
)
"""Chromatic colours in hue order; a colour gradient follows this order."""

RAINBOW_ORDER: tuple[str, ...] = ("red", "orange", "yellow", "green", "blue", "purple")
"""The colours of a rainbow as people name them (ROYGBV; indigo and violet are both purple
here): "rainbow order" uses these; a rainbow of more cubes continues with :data:`GRADIENT_ORDER`'s
remaining colours (cyan, pink)."""

COLOR_ALIASES: dict[str, str] = {
    "grey": "gray",
    "violet": "purple",
}
"""Other names a user may write for a palette colour: names of the same colour only.  Magenta,
teal and turquoise are other colours than the palette's pink and cyan (far in hue or
lightness), so they are refused like any colour the palette lacks rather than read as a
neighbour (two of three helpers writing instructions for the project expected that of magenta
and teal; four writers of the development stranger sets 9, 16, 18 and 20, of turquoise)."""

DEFAULT_SEMANTIC_COLOR: str = "white"
"""Body colour of a semantic (letter/number) cube; its glyphs are drawn in black."""


class UnknownColorError(BadInput):
    """Raised when a colour is not in :data:`PALETTE`."""


def canonical_color(name: str) -> str:
    """Return the palette name for ``name`` (case-insensitive, aliases resolved).

    Raises:
        UnknownColorError: the colour is not in the palette; the message lists the palette.
    """
    key = name.strip().lower()
    key = COLOR_ALIASES.get(key, key)
    if key not in PALETTE:
        raise UnknownColorError(
            f"unknown color {name!r}; known colors: {', '.join(sorted(PALETTE))}"
        )
    return key


def rgba(name: str, alpha: float = 1.0) -> list[float]:
    """RGBA list (0-1) of a palette colour.

    Raises:
        UnknownColorError: the colour is not in the palette.
    """
    r, g, b = PALETTE[canonical_color(name)]
    return [r, g, b, alpha]


def gradient_rank(name: str) -> int:
    """Position of a colour in :data:`GRADIENT_ORDER`.

    Raises:
        UnknownColorError: the colour is achromatic or unknown and has no place on the gradient.
    """
    key = canonical_color(name)
    if key not in GRADIENT_ORDER:
        raise UnknownColorError(f"color {name!r} has no place in a color gradient")
    return GRADIENT_ORDER.index(key)
