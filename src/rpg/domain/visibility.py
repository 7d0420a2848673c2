"""Geometric visibility and face readability from the default camera.

Paper, appendix "Geometric Visibility and Face Readability": a face is visible if at
least :data:`~rpg.domain.constants.VISIBILITY_MIN_RAYS` of five rays from the camera
(to the face centre and to four points at
:data:`~rpg.domain.constants.VISIBILITY_SAMPLE_FRACTION` of the face's half extent) reach
it unobstructed.  Rays are cast in one ``mujoco.mj_multiRay`` call for all faces asked about.  Goal
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


def _unit_samples() -> np.ndarray:
    """(6, 5, 3): each face's five sample points (in :data:`FACES` order) on a cube of half
    extent 1 in its local frame: the face centre, then four at ``VISIBILITY_SAMPLE_FRACTION``
    of the half extent toward the corners."""
    f = C.VISIBILITY_SAMPLE_FRACTION
    out = np.zeros((len(FACES), 5, 3))
    for i, face in enumerate(FACES):
        n_local = np.asarray(FACE_NORMALS[face], dtype=float)
        axis = int(np.argmax(np.abs(n_local)))
        others = [k for k in range(3) if k != axis]
        for j, (s0, s1) in enumerate(((0, 0), (1, 1), (1, -1), (-1, 1), (-1, -1))):
            out[i, j] = n_local
            out[i, j, others[0]] = s0 * f
            out[i, j, others[1]] = s1 * f
    return out


_UNIT_SAMPLES = _unit_samples()
_FACE_INDEX = {face: i for i, face in enumerate(FACES)}
_NORMALS_LOCAL = np.array([FACE_NORMALS[face] for face in FACES], dtype=float)


def _cube_faces(scene: Scene, name: str) -> tuple[np.ndarray, np.ndarray]:
    """Every face's five sample points (6, 5, 3) and outward normal (6, 3) of cube ``name``, world
    frame, in :data:`FACES` order."""
    data = scene.data.body(name)
    R = np.array(data.xmat).reshape(3, 3)
    half = np.asarray(scene.assets[name].extents) / 2
    return np.array(data.xpos) + (_UNIT_SAMPLES * half) @ R.T, _NORMALS_LOCAL @ R.T


def _cast(scene: Scene, faces: list[tuple[str, str]], camera: str) -> list[FaceVisibility]:
    """The visibility of each (object, local face), in order: faces turned away from the camera
    are not visible; the five rays of every other face are cast in one ``mj_multiRay`` call."""
    cam = camera_position(scene, camera)
    geometry = {name: _cube_faces(scene, name) for name in sorted({name for name, _ in faces})}
    pts = np.array([geometry[name][0][_FACE_INDEX[face]] for name, face in faces]).reshape(len(faces), 5, 3)
    normals = np.array([geometry[name][1][_FACE_INDEX[face]] for name, face in faces]).reshape(len(faces), 3)
    to_cam = cam - pts[:, 0]
    cos = np.einsum("ij,ij->i", normals, to_cam) / np.linalg.norm(to_cam, axis=1)
    out: list[FaceVisibility | None] = []
    facing: list[tuple[int, str, np.ndarray]] = []
    for k, (name, face) in enumerate(faces):
        if cos[k] < C.VISIBILITY_MIN_FACING_COS:
            out.append(FaceVisibility(name, face, 0, False))
        else:
            facing.append((k, name, pts[k]))
            out.append(None)
    if facing:
        vec = np.concatenate([pts for _, _, pts in facing]) - cam
        dist_target = np.linalg.norm(vec, axis=1)
        dirs = vec / dist_target[:, None]
        nray = len(dirs)
        geomid = np.full(nray, -1, dtype=np.int32)
        dist = np.zeros(nray)
        mujoco.mj_multiRay(scene.model, scene.data, cam, dirs.flatten(), _GEOMGROUP, 1, -1,
                           geomid, dist, None, nray, float(np.max(dist_target) + 1.0))
        hit = np.abs(dist - dist_target) <= C.RAY_HIT_TOL
        for k, (slot, name, _) in enumerate(facing):
            rays = slice(5 * k, 5 * k + 5)
            clear = int(np.sum((geomid[rays] == scene.model.geom(name).id) & hit[rays]))
            out[slot] = FaceVisibility(name, faces[slot][1], clear, clear >= C.VISIBILITY_MIN_RAYS)
    return out


def face_visibility(scene: Scene, name: str, face: str, camera: str = C.CAMERA_NAME) -> FaceVisibility:
    """Cast the five rays for one face.

    Raises:
        SceneError: unknown object.
    """
    scene._check(name)
    return _cast(scene, [(name, face)], camera)[0]


def visible_faces(scene: Scene, names: list[str] | None = None) -> dict[tuple[str, str], bool]:
    """(object, local face) -> visible, for every face of the given cubes (default: all cubes);
    the rays of all faces turned toward the camera in one ``mj_multiRay`` call."""
    names = names if names is not None else [n for n in scene.names if scene.assets[n].movable]
    return {(v.name, v.face): v.visible for v in _cast(scene, [(n, f) for n in names for f in FACES], C.CAMERA_NAME)}
