"""Geometric visibility and face readability from the default camera.

Paper, appendix "Geometric Visibility and Face Readability": a face is visible if at
least :data:`~rpg.domain.constants.VISIBILITY_MIN_RAYS` of five rays from the camera
(to the face centre and to four points at
:data:`~rpg.domain.constants.VISIBILITY_SAMPLE_FRACTION` of the face's half extent) reach
it unobstructed.  Rays are cast in one ``mujoco.mj_multiRay`` call per face.  Goal
patches (geom group 3) do not block rays.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.domain.assets import CUBE_GEOM_GROUP
from rpg.domain.glyphs import FACE_NORMALS, FACES
from rpg.domain.scene import Scene

_GEOMGROUP = np.array([1 if g == CUBE_GEOM_GROUP else 0 for g in range(6)], dtype=np.uint8)


@dataclass(frozen=True)
class FaceVisibility:
    """Visibility of one cube face.

    Attributes:
        name: object name.
        face: local face (``"+x"``...).
        rays_clear: how many of the 5 rays reached the face.
        visible: ``rays_clear >= VISIBILITY_MIN_RAYS`` and the face turns toward the camera
            (cosine at least ``VISIBILITY_MIN_FACING_COS``).
    """

    name: str
    face: str
    rays_clear: int
    visible: bool


def camera_position(scene: Scene, camera: str = C.CAMERA_NAME) -> np.ndarray:
    """World position of a camera, m, shape (3,)."""
    return np.array(scene.data.cam(camera).xpos)


def face_sample_points(scene: Scene, name: str, face: str) -> tuple[np.ndarray, np.ndarray]:
    """Five sample points (5, 3) on a cube face, world frame, and the face's world normal."""
    data = scene.data.body(name)
    R = np.array(data.xmat).reshape(3, 3)
    center = np.array(data.xpos)
    half = np.asarray(scene.assets[name].extents) / 2
    n_local = np.asarray(FACE_NORMALS[face])
    axis = int(np.argmax(np.abs(n_local)))
    others = [i for i in range(3) if i != axis]
    pts = []
    f = C.VISIBILITY_SAMPLE_FRACTION
    for s0, s1 in ((0, 0), (1, 1), (1, -1), (-1, 1), (-1, -1)):
        p = n_local * half
        p = p.astype(float)
        p[others[0]] = s0 * f * half[others[0]]
        p[others[1]] = s1 * f * half[others[1]]
        pts.append(center + R @ p)
    return np.array(pts), R @ n_local


def face_visibility(scene: Scene, name: str, face: str, camera: str = C.CAMERA_NAME) -> FaceVisibility:
    """Cast the five rays for one face.

    Raises:
        SceneError: unknown object.
    """
    scene._check(name)
    cam = camera_position(scene, camera)
    pts, normal = face_sample_points(scene, name, face)
    vec = pts - cam
    dist_target = np.linalg.norm(vec, axis=1)
    to_cam = cam - pts[0]
    if float(normal @ to_cam) / float(np.linalg.norm(to_cam)) < C.VISIBILITY_MIN_FACING_COS:
        return FaceVisibility(name, face, 0, False)
    dirs = vec / dist_target[:, None]
    geomid = np.full(5, -1, dtype=np.int32)
    dist = np.zeros(5)
    mujoco.mj_multiRay(scene.model, scene.data, cam, dirs.flatten(), _GEOMGROUP, 1, -1,
                       geomid, dist, None, 5, float(np.max(dist_target) + 1.0))
    own = scene.model.geom(name).id
    clear = int(np.sum((geomid == own) & (np.abs(dist - dist_target) <= C.RAY_HIT_TOL)))
    return FaceVisibility(name, face, clear, clear >= C.VISIBILITY_MIN_RAYS)


def visible_faces(scene: Scene, names: list[str] | None = None) -> dict[tuple[str, str], bool]:
    """(object, local face) -> visible, for every face of the given cubes (default: all cubes)."""
    names = names if names is not None else [n for n in scene.names if scene.assets[n].movable]
    out = {}
    for n in names:
        for f in FACES:
            out[(n, f)] = face_visibility(scene, n, f).visible
    return out
