"""World state as seen by success predicates: object poses plus what the objects are.

Predicates evaluate a :class:`WorldState`, not a MuJoCo ``MjData``, so they can be tested
on constructed states and evaluated on states read from any simulator.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from rpg.domain import constants as C
from rpg.domain.glyphs import FACE_NORMALS, FACES, GLYPH_UP

IDENTITY_QUAT: tuple[float, float, float, float] = (1.0, 0.0, 0.0, 0.0)

DIRECTIONS: dict[str, tuple[float, float, float]] = {
    "up": (0.0, 0.0, 1.0),
    "down": (0.0, 0.0, -1.0),
    "front": (-1.0, 0.0, 0.0),
    "back": (1.0, 0.0, 0.0),
    "left": (0.0, 1.0, 0.0),
    "right": (0.0, -1.0, 0.0),
}
"""World directions by name.  "front" points toward the robot and the camera (-x)."""

READING_UP: dict[str, tuple[float, float, float]] = {
    "up": (1.0, 0.0, 0.0),
    "down": (1.0, 0.0, 0.0),
    "front": (0.0, 0.0, 1.0),
    "back": (0.0, 0.0, 1.0),
    "left": (0.0, 0.0, 1.0),
    "right": (0.0, 0.0, 1.0),
}
"""Expected glyph up (world) for a face turned toward each direction, as read from the
default camera: a face turned up reads with +x (away from the camera) as its top."""


def quat_to_mat(quat) -> np.ndarray:
    """3x3 rotation matrix of a unit quaternion (w, x, y, z)."""
    w, x, y, z = (float(v) for v in quat)
    n = w * w + x * x + y * y + z * z
    if n < 1e-12 or not np.isfinite(n):
        raise ValueError(f"invalid quaternion {quat!r}")
    s = 2.0 / n
    return np.array(
        [
            [1 - s * (y * y + z * z), s * (x * y - w * z), s * (x * z + w * y)],
            [s * (x * y + w * z), 1 - s * (x * x + z * z), s * (y * z - w * x)],
            [s * (x * z - w * y), s * (y * z + w * x), 1 - s * (x * x + y * y)],
        ]
    )


def yaw_quat(yaw: float) -> tuple[float, float, float, float]:
    """Quaternion (w, x, y, z) of a rotation by ``yaw`` rad about world +z."""
    return (float(np.cos(yaw / 2)), 0.0, 0.0, float(np.sin(yaw / 2)))


def quat_mul(a, b) -> tuple[float, float, float, float]:
    """Hamilton product a * b of two quaternions (w, x, y, z)."""
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    )


@dataclass(frozen=True)
class Pose:
    """Position (m, world frame) and orientation quaternion (w, x, y, z)."""

    pos: tuple[float, float, float]
    quat: tuple[float, float, float, float] = IDENTITY_QUAT

    def to_json(self) -> dict:
        return {"position": [float(v) for v in self.pos], "quaternion": [float(v) for v in self.quat]}


@dataclass(frozen=True)
class ObjectState:
    """One object of a world state.

    Attributes:
        name: object name.
        kind: ``"colored_cube"``, ``"semantic_cube"`` or ``"goal_patch"``.
        pos: centre position, m, world frame, shape (3,).
        quat: orientation (w, x, y, z), shape (4,).
        size: full extents (x, y, z) in the local frame, m.
        color: palette colour name, or None.
        label: primary label of a semantic cube, or None.
        face_labels: local face -> label (None for blank faces).
    """

    name: str
    kind: str
    pos: np.ndarray
    quat: np.ndarray = field(default_factory=lambda: np.array(IDENTITY_QUAT))
    size: tuple[float, float, float] = (C.CUBE_EDGE, C.CUBE_EDGE, C.CUBE_EDGE)
    color: str | None = None
    label: str | None = None
    face_labels: dict[str, str | None] = field(default_factory=dict)

    @property
    def is_cube(self) -> bool:
        return self.kind != "goal_patch"

    @cached_property
    def signature(self) -> tuple:
        """What makes two objects interchangeable in a goal: kind, colour and face labels."""
        return (self.kind, self.color, tuple(sorted((k, v or "") for k, v in self.face_labels.items())))

    @cached_property
    def rotation(self) -> np.ndarray:
        """Local-to-world rotation, shape (3, 3) (computed once: the state is frozen)."""
        return quat_to_mat(self.quat)

    @property
    def half_height(self) -> float:
        """Half of the object's vertical extent in its current orientation, m."""
        R = self.rotation
        return 0.5 * float(np.abs(R[2, :]) @ np.asarray(self.size))

    @property
    def label_type(self) -> str | None:
        from rpg.domain.glyphs import label_type

        return None if self.label is None else label_type(self.label)

    @cached_property
    def face_normals(self) -> np.ndarray:
        """World-frame outward normals of the local faces, shape (3, 6), columns in ``FACES`` order."""
        return self.rotation @ np.array([FACE_NORMALS[f] for f in FACES], dtype=float).T

    def face_normal(self, face: str) -> np.ndarray:
        """World-frame outward normal of a local face (a column of :attr:`face_normals`)."""
        return self.face_normals[:, FACES.index(face)]

    def glyph_up(self, face: str) -> np.ndarray:
        """World-frame up vector of the glyph on a local face."""
        return self.rotation @ np.asarray(GLYPH_UP[face])

    def face_toward(self, direction: str) -> tuple[str, float]:
        """Local face whose normal is closest to a named world direction, and that cosine."""
        cos = np.asarray(DIRECTIONS[direction]) @ self.face_normals
        k = int(np.argmax(cos))  # the first of equal cosines, in FACES order
        return FACES[k], float(cos[k])

    def label_toward(self, direction: str, min_cos: float = C.READABLE_NORMAL_COS) -> str | None:
        """Label on the face turned toward ``direction`` (None if no face is turned that way)."""
        face, cos = self.face_toward(direction)
        if cos < min_cos:
            return None
        return self.face_labels.get(face)

    def readable(self, face: str, direction: str) -> tuple[bool, float, float]:
        """Whether a local face reads upright toward a named direction.

        Returns:
            (readable, normal cosine, glyph-up cosine), judged against
            :data:`~rpg.domain.constants.READABLE_NORMAL_COS` and
            :data:`~rpg.domain.constants.READABLE_UP_COS` (paper, Face Readability).
        """
        ncos = float(self.face_normal(face) @ np.asarray(DIRECTIONS[direction]))
        ucos = float(self.glyph_up(face) @ np.asarray(READING_UP[direction]))
        return (ncos >= C.READABLE_NORMAL_COS and ucos >= C.READABLE_UP_COS, ncos, ucos)

    def attribute(self, key: str) -> str | None:
        """Attribute used for grouping: ``color``, ``label``, ``kind`` or ``label_type``."""
        if key == "type":
            return self.label_type or self.kind
        return getattr(self, key)


@dataclass
class WorldState:
    """Objects by name, optionally with the visibility of their faces from the camera.

    Attributes:
        objects: name -> :class:`ObjectState`.
        visible_faces: optional (name, local face) -> visible from the default camera.  When
            None, every face counts as visible (predicates then judge geometry only).
    """

    objects: dict[str, ObjectState]
    visible_faces: dict[tuple[str, str], bool] | None = None

    def __getitem__(self, name: str) -> ObjectState:
        try:
            return self.objects[name]
        except KeyError:
            raise KeyError(
                f"no object named {name!r}; objects are: {', '.join(sorted(self.objects))}"
            ) from None

    def is_visible(self, name: str, face: str) -> bool:
        if self.visible_faces is None:
            return True
        return self.visible_faces.get((name, face), False)

    def cubes(self) -> list[ObjectState]:
        return [o for _, o in sorted(self.objects.items()) if o.is_cube]
