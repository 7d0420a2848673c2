"""Concrete goal layouts: poses that realise each structure of the domain.

Each function returns name -> :class:`~rpg.domain.state.Pose` with cubes upright, touching
their neighbours (pitch = cube edge + ``gap``), resting on the table or on each other.
Positions are world-frame metres; structures are axis-aligned.  The ordering conventions
match :mod:`rpg.domain.predicates` (left = +y; rows front to back along +x).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from rpg.domain import constants as C
from rpg.domain.state import Pose

LAYOUT_GAP: float = 0.0005
"""Gap between neighbouring cubes in a goal layout, m (keeps contacts clean)."""


def _z(level: int, edge: float = C.CUBE_EDGE) -> float:
    return C.TABLE_TOP_Z + edge / 2 + level * (edge + C.SPAWN_CLEARANCE)


def stack_layout(names: Sequence[str], xy: tuple[float, float], edge: float = C.CUBE_EDGE) -> dict[str, Pose]:
    """A tower at ``xy``; ``names`` bottom to top."""
    return {n: Pose((xy[0], xy[1], _z(i, edge))) for i, n in enumerate(names)}


def line_layout(
    names: Sequence[str],
    center: tuple[float, float] = C.WORKSPACE_CENTER,
    axis: str = "y",
    spacing: float = C.CUBE_EDGE + 0.02,
    edge: float = C.CUBE_EDGE,
) -> dict[str, Pose]:
    """A straight line; ``names`` in reading order (left to right for ``axis="y"``,
    front to back for ``axis="x"``)."""
    n = len(names)
    out = {}
    for i, name in enumerate(names):
        off = (i - (n - 1) / 2) * spacing
        x, y = (center[0], center[1] - off) if axis == "y" else (center[0] + off, center[1])
        out[name] = Pose((x, y, _z(0, edge)))
    return out


def line_extent(count: int, spacing: float = C.CUBE_EDGE + 0.02, edge: float = C.CUBE_EDGE) -> float:
    """Length of a line layout of ``count`` cubes, m."""
    return (count - 1) * spacing + edge


def circle_layout(
    names: Sequence[str], center: tuple[float, float] = C.WORKSPACE_CENTER, radius: float | None = None,
    edge: float = C.CUBE_EDGE,
) -> dict[str, Pose]:
    """Cubes evenly around a circle (first one at the front, counter-clockwise from above).

    The default radius leaves one edge of space between neighbours.
    """
    n = len(names)
    if radius is None:
        radius = circle_radius(n, edge)
    out = {}
    for i, name in enumerate(names):
        a = math.pi + 2 * math.pi * i / n
        out[name] = Pose((center[0] + radius * math.cos(a), center[1] + radius * math.sin(a), _z(0, edge)))
    return out


def circle_radius(count: int, edge: float = C.CUBE_EDGE) -> float:
    """Default radius of a circle of ``count`` cubes: neighbours two edges apart, at least 6 cm."""
    return max(0.06, 2 * edge / (2 * math.sin(math.pi / max(count, 3))))


def grid_layout(
    names: Sequence[str], rows: int, cols: int, layers: int = 1,
    center: tuple[float, float] = C.WORKSPACE_CENTER, edge: float = C.CUBE_EDGE,
) -> dict[str, Pose]:
    """A rows x cols x layers block of touching cubes centred at ``center``.

    ``names`` fill sites layer by layer (bottom first), rows front to back, columns left
    to right.
    """
    p = edge + LAYOUT_GAP
    x0 = center[0] - (rows - 1) * p / 2
    y0 = center[1] + (cols - 1) * p / 2
    out = {}
    i = 0
    for lay in range(layers):
        for r in range(rows):
            for c in range(cols):
                out[names[i]] = Pose((x0 + r * p, y0 - c * p, _z(lay, edge)))
                i += 1
    return out


def pyramid_sites(base: int, dims: int) -> list[tuple[int, int, int]]:
    """(layer, row, column) of every pyramid site in reading order (bottom layer first)."""
    sites = []
    for k in range(base):
        m = base - k
        for r in range(m if dims == 3 else 1):
            for c in range(m):
                sites.append((k, r, c))
    return sites


def layered_sites(layers: Sequence[int]) -> list[tuple[int, float]]:
    """(layer, offset along the base in cube pitches from its left end) of every site of a 2D pyramid whose layers hold
    ``layers`` cubes from the bottom up, each layer centred over the one below ("three on the bottom and one on top":
    ``(3, 1)``, the top cube over the middle one); a pyramid that steps in by one cube a layer is ``(n, n-1, ..., 1)``."""
    base = layers[0]
    return [(k, (base - m) / 2 + c) for k, m in enumerate(layers) for c in range(m)]


def pyramid_layout(
    names: Sequence[str], base: int, dims: int = 2,
    center: tuple[float, float] = C.WORKSPACE_CENTER, edge: float = C.CUBE_EDGE,
    layers: Sequence[int] = (),
) -> dict[str, Pose]:
    """A pyramid with a base of ``base`` (2D wall along y, or 3D with a base x base square).

    ``names`` fill :func:`pyramid_sites` in order: bottom layer first, rows front to back,
    left to right; each upper cube sits over the gap between the cubes below.  ``layers``
    (2D only): the cubes of each layer from the bottom up, each layer centred over the one
    below (:func:`layered_sites`), where they do not step in by one.
    """
    p = edge + LAYOUT_GAP
    x0 = center[0] - ((base - 1) * p / 2 if dims == 3 else 0.0)
    y0 = center[1] + (base - 1) * p / 2
    out = {}
    if layers:
        for name, (k, offset) in zip(names, layered_sites(layers), strict=True):
            out[name] = Pose((x0, y0 - offset * p, _z(k, edge)))
        return out
    for name, (k, r, c) in zip(names, pyramid_sites(base, dims), strict=True):
        dx = (k / 2 + r) * p if dims == 3 else 0.0
        out[name] = Pose((x0 + dx, y0 - (k / 2 + c) * p, _z(k, edge)))
    return out


def cluster_layout(
    groups: Sequence[Sequence[str]], centers: Sequence[tuple[float, float]], edge: float = C.CUBE_EDGE,
) -> dict[str, Pose]:
    """Each group as a compact cluster (2-wide rows) around its centre on the table."""
    out = {}
    p = edge + 0.008
    for group, (cx, cy) in zip(groups, centers, strict=True):
        n = len(group)
        cols = 2 if n > 1 else 1
        rows = math.ceil(n / cols)
        for i, name in enumerate(group):
            r, c = divmod(i, cols)
            out[name] = Pose((cx + (r - (rows - 1) / 2) * p, cy + (c - (cols - 1) / 2) * p, _z(0, edge)))
    return out


def spread_centers(count: int, spacing: float, center: tuple[float, float] = C.WORKSPACE_CENTER) -> list[tuple[float, float]]:
    """``count`` centres spaced ``spacing`` apart, in rows of up to 3 along y (left to right)."""
    per_row = min(count, 3)
    rows = math.ceil(count / per_row)
    out = []
    for i in range(count):
        r, c = divmod(i, per_row)
        in_row = min(per_row, count - r * per_row)
        out.append((center[0] + (r - (rows - 1) / 2) * spacing, center[1] + ((in_row - 1) / 2 - c) * spacing))
    return out


def dense_cubes(poses: dict[str, Pose], edges: dict[str, float], gap: float = C.DENSE_GAP) -> set[str]:
    """Cubes of ``edges`` (name -> edge length, m) that have a neighbour in their layer whose
    face is closer than ``gap`` (m) in ``poses``: no finger fits between them."""
    names = sorted(edges)
    return {n for n in names for m in names if m != n
            and abs(poses[n].pos[2] - poses[m].pos[2]) < 0.5 * edges[n]
            and math.dist(poses[n].pos[:2], poses[m].pos[:2]) < 0.5 * (edges[n] + edges[m]) + gap}


def out_of_bounds(poses) -> list[dict]:
    """Objects whose centre lies outside the workspace (x, y within
    :data:`~rpg.domain.constants.BOUNDS_MARGIN` of it) or below the table top: the bounds
    gate's rule, applied to rho_0's samples and the settled goal configuration.

    Args:
        poses: name -> :class:`~rpg.domain.state.Pose`.

    Returns:
        ``[{"object": name, "position": [x, y, z]}]`` (m, rounded to 0.1 mm), sorted by name.
    """
    out = []
    m = C.BOUNDS_MARGIN
    for n in sorted(poses):
        x, y, z = poses[n].pos
        if not (C.WORKSPACE_X[0] - m <= x <= C.WORKSPACE_X[1] + m and C.WORKSPACE_Y[0] - m <= y <= C.WORKSPACE_Y[1] + m
                and z >= C.TABLE_TOP_Z - m):
            out.append({"object": n, "position": [round(float(v), 4) for v in poses[n].pos]})
    return out
