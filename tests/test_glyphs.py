"""Glyph orientation, tested by rendering every face of a real semantic cube."""

import mujoco
import numpy as np
import pytest
from PIL import Image

from rpg.domain import constants as C
from rpg.domain.assets import SemanticCube
from rpg.domain.glyphs import FACE_NORMALS, FACES, GLYPH_UP, canonical_label, face_image
from rpg.domain.render import render_image
from rpg.domain.scene import Scene

LABELS = {"+x": "F", "-x": "R", "+y": "G", "-y": "J", "+z": "P", "-z": "L"}  # all asymmetric


def _variants(img: np.ndarray) -> dict[str, np.ndarray]:
    out = {}
    for k in range(4):
        out[f"rot{k * 90}"] = np.rot90(img, k)
        out[f"mirror_rot{k * 90}"] = np.rot90(img[:, ::-1], k)
    return out


def _ncc(a: np.ndarray, b: np.ndarray) -> float:
    a = a - a.mean()
    b = b - b.mean()
    return float((a * b).sum() / (np.linalg.norm(a) * np.linalg.norm(b) + 1e-9))


def _face_camera_scene(face: str):
    """A cube at the origin and a camera outside ``face`` with the glyph's up as image up."""
    scene = Scene([SemanticCube("c", label="A", faces=LABELS)])
    scene.set_pose("c", (0.55, 0.0, 1.2))
    scene.forward()
    n = np.asarray(FACE_NORMALS[face])
    up = np.asarray(GLYPH_UP[face])
    centre = np.array([0.55, 0.0, 1.2])
    pos = centre + 0.14 * n
    fwd = -n
    right = np.cross(fwd, up)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.stack([right, up, -fwd], axis=1).flatten())
    scene.spec.worldbody.add_camera(name="probe", pos=list(pos), quat=list(quat), fovy=20.0)
    scene.model, scene.data = scene.spec.recompile(scene.model, scene.data)
    scene.forward()
    return scene


@pytest.mark.parametrize("face", FACES)
def test_every_face_reads_upright_and_unmirrored(face):
    scene = _face_camera_scene(face)
    img = render_image(scene, 200, 200, camera="probe")
    if img is None:
        pytest.skip("no headless OpenGL")
    gray = img.mean(axis=2)
    # crop the cube face (it fills the centre of the view) and resize to the glyph image
    dark = gray > 60
    rows, cols = np.where(dark)
    crop = gray[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
    crop = np.asarray(Image.fromarray(crop.astype(np.uint8)).resize((64, 64)), float)
    ref = np.frombuffer(face_image(LABELS[face], (242, 242, 242)), np.uint8).reshape(C.GLYPH_TEXTURE_PX, C.GLYPH_TEXTURE_PX, 3)
    ref = np.asarray(Image.fromarray(ref).convert("L").resize((64, 64)), float)
    scores = {k: _ncc(crop, v) for k, v in _variants(ref).items()}
    best = max(scores, key=scores.get)
    assert best == "rot0", f"face {face} renders as {best}: {scores}"
    assert scores["rot0"] > scores["mirror_rot0"] + 0.1


def test_top_face_reads_upright_from_default_camera():
    scene = Scene([SemanticCube("c", label="P")])
    scene.set_pose("c", (*C.WORKSPACE_CENTER, C.TABLE_TOP_Z + C.CUBE_EDGE / 2))
    scene.forward()
    cam = scene.data.cam(C.CAMERA_NAME)
    R = np.array(cam.xmat).reshape(3, 3)
    top = np.array([*C.WORKSPACE_CENTER, C.TABLE_TOP_Z + C.CUBE_EDGE])
    up_world = scene.world_state()["c"].glyph_up("+z")

    def project(p):
        v = R.T @ (p - cam.xpos)
        return np.array([v[0] / -v[2], v[1] / -v[2]])  # image x right, y up

    d = project(top + 0.01 * up_world) - project(top)
    assert d[1] > 0 and abs(d[0]) < 0.2 * d[1], "glyph up must point up in the default camera image"


def test_labels_are_canonical():
    assert canonical_label("a") == "A"
    assert canonical_label("*") == "x"
    assert canonical_label("7") == "7"
    with pytest.raises(ValueError, match="letter A-Z"):
        canonical_label("AB")
