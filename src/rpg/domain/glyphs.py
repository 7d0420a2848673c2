"""Glyph textures for semantic cubes, drawn with Pillow's bundled font.

A semantic cube carries one label per face.  The six face images are packed into one
MuJoCo cube texture (faces stacked vertically in MuJoCo's order +x, -x, +y, -y, +z, -z).
MuJoCo maps each stored face with its own in-plane rotation; :data:`FACE_ROTATIONS`
undoes it so that every glyph reads upright and unmirrored seen from outside its face
with the cube's local "glyph up" (:data:`GLYPH_UP`) pointing up in the image.  The
rotations were measured by rendering marker images (see tests/test_glyphs.py, which
checks every face by rendering).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from rpg.domain.constants import GLYPH_TEXTURE_PX
from rpg.errors import BadInput

FACES: tuple[str, ...] = ("+x", "-x", "+y", "-y", "+z", "-z")
"""Local face names of a cube, in MuJoCo's cube-texture order."""

FACE_NORMALS: dict[str, tuple[float, float, float]] = {
    "+x": (1.0, 0.0, 0.0), "-x": (-1.0, 0.0, 0.0),
    "+y": (0.0, 1.0, 0.0), "-y": (0.0, -1.0, 0.0),
    "+z": (0.0, 0.0, 1.0), "-z": (0.0, 0.0, -1.0),
}
"""Outward normal of each face in the cube's local frame."""

GLYPH_UP: dict[str, tuple[float, float, float]] = {
    "+x": (0.0, 0.0, 1.0), "-x": (0.0, 0.0, 1.0),
    "+y": (0.0, 0.0, 1.0), "-y": (0.0, 0.0, 1.0),
    "+z": (1.0, 0.0, 0.0), "-z": (1.0, 0.0, 0.0),
}
"""Up direction of each face's glyph in the cube's local frame.

Side faces read with local +z up; the top and bottom faces read with local +x up, so the
top face of an unrotated cube reads upright from the default camera (which looks along +x).
"""

FACE_ROTATIONS: dict[str, int] = {"+x": 1, "-x": -1, "+y": 2, "-y": 0, "+z": -1, "-z": 1}
"""Quarter turns (``numpy.rot90`` k) applied to an upright face image before packing."""

OPERATORS: tuple[str, ...] = ("+", "-", "=", "x")
"""Operator labels.  Lower-case ``x`` is the multiplication sign; upper-case ``X`` is a letter."""

_DRAWN: dict[str, str] = {"x": "\u00d7", "-": "\u2212"}


class UnknownLabelError(BadInput):
    """Raised for a label that is not a letter A-Z, a digit 0-9 or an operator."""


def canonical_label(label: str) -> str:
    """Normalise a label: letters upper-case, ``*``/``×`` -> ``x``.

    Raises:
        UnknownLabelError: not a letter, digit or one of ``+ - = x``.
    """
    text = str(label).strip()
    if text in ("*", "\u00d7", "x"):
        return "x"
    if len(text) == 1 and text.isascii() and (text.isalpha() or text.isdigit()):
        return text.upper()
    if text in OPERATORS:
        return text
    raise UnknownLabelError(
        f"unknown label {label!r}; a label is a letter A-Z, a digit 0-9 or one of + - = x"
    )


def label_type(label: str) -> str:
    """``"letter"``, ``"digit"`` or ``"operator"`` for a canonical label."""
    if label in OPERATORS:
        return "operator"
    return "digit" if label.isdigit() else "letter"


@lru_cache(maxsize=256)
def face_image(label: str, background: tuple[int, int, int], px: int = GLYPH_TEXTURE_PX) -> bytes:
    """Upright RGB image (px x px, row-major bytes) of one glyph on a background.

    The glyph is black, centred, drawn with Pillow's bundled FreeType font (no system font).
    A bar under the glyph marks its baseline so that 6/9 and M/W stay distinguishable.
    """
    from PIL import (  # only where a texture is drawn: the sandboxed child draws none
        Image,
        ImageDraw,
        ImageFont,
    )

    img = Image.new("RGB", (px, px), background)
    draw = ImageDraw.Draw(img)
    font = ImageFont.load_default(size=int(px * 0.62))
    text = _DRAWN.get(label, label)
    left, top, right, bottom = draw.textbbox((0, 0), text, font=font)
    x = (px - (right - left)) / 2 - left
    y = (px - (bottom - top)) / 2 - top - px * 0.04
    draw.text((x, y), text, fill=(0, 0, 0), font=font)
    if label in ("6", "9", "M", "W", "N", "Z", "H", "I", "O", "S", "X", "0", "8"):
        bar_y = int(px * 0.86)
        draw.rectangle([px * 0.3, bar_y, px * 0.7, bar_y + max(2, px // 32)], fill=(0, 0, 0))
    return img.tobytes()


def cube_texture(
    labels: dict[str, str | None], background: tuple[int, int, int], px: int = GLYPH_TEXTURE_PX
) -> bytes:
    """Bytes of a MuJoCo cube texture (width px, height 6*px, RGB) for per-face labels.

    Args:
        labels: local face name (see :data:`FACES`) -> canonical label, or None for a blank face.
        background: body colour as 0-255 RGB.
        px: side of one face image, pixels.
    """
    blank = np.full((px, px, 3), background, dtype=np.uint8)
    tiles = []
    for face in FACES:
        label = labels.get(face)
        if label is None:
            tile = blank
        else:
            tile = np.frombuffer(face_image(label, background, px), np.uint8).reshape(px, px, 3)
        tiles.append(np.rot90(tile, FACE_ROTATIONS[face]))
    return np.ascontiguousarray(np.concatenate(tiles, axis=0)).tobytes()
