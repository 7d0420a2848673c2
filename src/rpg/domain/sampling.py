"""Initial-state distribution rho_0: seeded sampling of object poses in the workspace.

Everything here draws from a caller-supplied ``numpy.random.Generator``; nothing touches
global random state, so the same seed gives the same initial state, byte for byte.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from rpg.domain import constants as C
from rpg.domain.assets import Asset
from rpg.domain.state import Pose, yaw_quat
from rpg.errors import BadInput


class InfeasibleLayout(BadInput):
    """Raised when objects cannot be placed with the requested separation in the workspace."""


def footprint_radius(asset: Asset) -> float:
    """Radius of the circle that covers an asset's footprint at any yaw, m."""
    sx, sy, _ = asset.extents
    return 0.5 * math.hypot(sx, sy)


def rest_height(asset: Asset, level: int = 0) -> float:
    """Centre height of an upright asset resting on the table (level 0) or on a stack, m."""
    sz = asset.extents[2]
    if not asset.movable:
        return C.TABLE_TOP_Z + sz / 2
    return C.TABLE_TOP_Z + sz / 2 + level * sz + C.SPAWN_CLEARANCE


def sample_footprints(
    rng: np.random.Generator,
    radii: Sequence[float],
    min_separation: float = C.MIN_SEPARATION,
    bounds_x: tuple[float, float] = C.WORKSPACE_X,
    bounds_y: tuple[float, float] = C.WORKSPACE_Y,
    occupied: Sequence[tuple[float, float, float]] = (),
) -> list[tuple[float, float]]:
    """Rejection-sample planar centres (m) for footprints of the given radii.

    Two footprints keep their centres at least ``max(min_separation, r_i + r_j + 1 cm)``
    apart, and away from ``occupied`` discs (x, y, radius).  Centres stay inside the
    bounds shrunk by each radius.

    Crowded scenes, where sequential rejection sampling runs out of tries, fall back to
    :func:`lattice_footprints` (a random subset of a jittered lattice, same spacing rule).

    Raises:
        InfeasibleLayout: the objects do not fit even on the lattice.
    """
    try:
        return _rejection_footprints(rng, radii, min_separation, bounds_x, bounds_y, occupied)
    except InfeasibleLayout:
        return lattice_footprints(rng, radii, min_separation, bounds_x, bounds_y, occupied)


def lattice_footprints(
    rng: np.random.Generator,
    radii: Sequence[float],
    min_separation: float = C.MIN_SEPARATION,
    bounds_x: tuple[float, float] = C.WORKSPACE_X,
    bounds_y: tuple[float, float] = C.WORKSPACE_Y,
    occupied: Sequence[tuple[float, float, float]] = (),
) -> list[tuple[float, float]]:
    """Planar centres (m) on a lattice whose pitch keeps every pair apart as
    :func:`sample_footprints` requires: cells are drawn without replacement and jittered
    within the slack the bounds leave.

    Raises:
        InfeasibleLayout: fewer free lattice cells than objects.
    """
    if not radii:
        return []
    r = max(radii)
    pitch = max(min_separation, 2 * r + 0.01)
    lo = np.array([bounds_x[0] + r, bounds_y[0] + r])
    hi = np.array([bounds_x[1] - r, bounds_y[1] - r])
    counts = np.floor((hi - lo) / pitch).astype(int) + 1
    if np.any(hi < lo):
        raise InfeasibleLayout(f"an object of radius {r:.3f} m does not fit in the workspace")
    # spread the cells over the bounds; each may move by half the spacing beyond the pitch
    step = np.where(counts > 1, (hi - lo) / np.maximum(counts - 1, 1), 0.0)
    half_extra = np.where(counts > 1, (step - pitch) / 2, (hi - lo) / 2)
    start = np.where(counts > 1, lo, (lo + hi) / 2)
    cells = [start + np.array([i, j]) * step for i in range(counts[0]) for j in range(counts[1])]
    cells = [c for c in cells if all(math.hypot(c[0] - px, c[1] - py) >= max(min_separation, r + pr + 0.01)
                                     for px, py, pr in occupied)]
    if len(cells) < len(radii):
        raise InfeasibleLayout(
            f"could not place {len(radii)} objects {min_separation:.2f} m apart in the workspace; "
            "use fewer objects or a smaller separation")
    chosen = rng.choice(len(cells), size=len(radii), replace=False)
    jitter = rng.uniform(-1.0, 1.0, size=(len(radii), 2)) * half_extra
    return [(float(cells[k][0] + dx), float(cells[k][1] + dy)) for k, (dx, dy) in zip(chosen, jitter, strict=True)]


def _rejection_footprints(rng, radii, min_separation, bounds_x, bounds_y, occupied) -> list[tuple[float, float]]:
    placed: list[tuple[float, float, float]] = list(occupied)
    out = []
    for r in radii:
        lo_x, hi_x = bounds_x[0] + r, bounds_x[1] - r
        lo_y, hi_y = bounds_y[0] + r, bounds_y[1] - r
        if lo_x > hi_x or lo_y > hi_y:
            raise InfeasibleLayout(f"an object of radius {r:.3f} m does not fit in the workspace")
        for _ in range(C.MAX_SAMPLING_TRIES):
            x = float(rng.uniform(lo_x, hi_x))
            y = float(rng.uniform(lo_y, hi_y))
            if all(math.hypot(x - px, y - py) >= max(min_separation, r + pr + 0.01) for px, py, pr in placed):
                break
        else:
            raise InfeasibleLayout(
                f"could not place {len(radii)} objects {min_separation:.2f} m apart in the workspace; "
                "use fewer objects or a smaller separation"
            )
        placed.append((x, y, r))
        out.append((x, y))
    return out


def _outside(units: list[list[str]], avoid: Mapping[str, str]):
    """Per unit, a test of a planar centre: outside every region one of its objects avoids."""
    from rpg.domain.predicates import region_boxes

    def test(boxes):
        return lambda xy: not any(x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1 for (x0, x1), (y0, y1) in boxes)

    return [test([box for n in unit if n in avoid for box in region_boxes(avoid[n])]) for unit in units]


def sample_scattered(
    rng: np.random.Generator,
    assets: Sequence[Asset],
    min_separation: float = C.MIN_SEPARATION,
    yaw_range: float = C.DEFAULT_YAW_RANGE,
    structures: Sequence[Sequence[str]] = (),
    fixed: Mapping[str, Pose] | None = None,
    avoid: Mapping[str, str] | None = None,
) -> dict[str, Pose]:
    """Sample a scattered initial state: every asset upright on the table, apart.

    Args:
        rng: the episode's generator.
        assets: all task assets (cubes and patches).
        min_separation: least centre distance between footprints, m.
        yaw_range: yaw is drawn uniformly in [-yaw_range, yaw_range], rad (patches: 0).
        structures: initial stacks, each a list of names bottom to top ("yellow starts
            stacked on red" is ``[["red", "yellow"]]``); a stack takes one footprint.
        fixed: poses that are not sampled (e.g. patches placed by the goal layout).
        avoid: object name -> a workspace region (:data:`constants.REGION_NAMES`) its centre
            must start outside: a cube whose goal is a region never starts in it.  Layouts
            are redrawn until it holds (at most :data:`constants.MAX_REGION_REDRAWS` draws).

    Returns:
        name -> :class:`Pose`, sorted by name.

    Raises:
        InfeasibleLayout: the objects do not fit (or never fit outside their regions).
    """
    fixed = dict(fixed or {})
    by_name = {a.name: a for a in assets}
    stacked = {n for s in structures for n in s}
    units: list[list[str]] = [list(s) for s in structures]
    units += [[a.name] for a in sorted(assets, key=lambda a: a.name)
              if a.name not in stacked and a.name not in fixed]
    occupied = [(p.pos[0], p.pos[1], footprint_radius(by_name[n])) for n, p in sorted(fixed.items())]
    radii = [max(footprint_radius(by_name[n]) for n in unit) for unit in units]
    outside = _outside(units, avoid or {})
    for _ in range(C.MAX_REGION_REDRAWS if avoid else 1):
        centres = sample_footprints(rng, radii, min_separation, occupied=occupied)
        if all(ok(xy) for ok, xy in zip(outside, centres, strict=True)):
            break
    else:
        raise InfeasibleLayout("could not sample a layout with every cube outside its goal region; "
                               "use fewer cubes or smaller regions")
    poses: dict[str, Pose] = dict(fixed)
    for unit, (x, y) in zip(units, centres, strict=True):
        movable = by_name[unit[0]].movable
        yaw = float(rng.uniform(-yaw_range, yaw_range)) if movable and yaw_range > 0 else 0.0
        for level, n in enumerate(unit):
            poses[n] = Pose((x, y, rest_height(by_name[n], level)), yaw_quat(yaw))
    return {n: poses[n] for n in sorted(poses)}
