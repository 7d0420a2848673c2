"""Real MuJoCo scenes: visibility, stability, determinism, state I/O."""

import json

import mujoco
import numpy as np
import pytest

from rpg.domain import constants as C
from rpg.domain.assets import ColoredCube, GoalPatch, SemanticCube
from rpg.domain.glyphs import FACES
from rpg.domain.layouts import grid_layout, line_layout, pyramid_layout, stack_layout
from rpg.domain.sampling import InfeasibleLayout, sample_scattered
from rpg.domain.scene import Scene, SceneError, drift_report
from rpg.domain.visibility import face_visibility, visible_faces
from tests.helpers import scene_with


def _model_bytes(model):
    buf = np.zeros(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buf)
    return buf.tobytes()


def _assets():
    return [ColoredCube("red", color="red"), ColoredCube("blue", color="blue"),
            SemanticCube("a", label="A"), GoalPatch("patch", color="green", shape="long")]


def test_physics_options_are_global():
    m = Scene(_assets()).model
    assert m.opt.timestep == C.TIMESTEP
    assert m.opt.cone == mujoco.mjtCone.mjCONE_ELLIPTIC
    assert m.opt.impratio == C.IMPRATIO
    assert m.opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    assert m.opt.solver == mujoco.mjtSolver.mjSOL_NEWTON
    assert np.allclose(m.geom("red").solref, C.CONTACT_SOLREF)
    assert m.geom("patch").contype == 0 and m.geom("patch").conaffinity == 0


def test_scene_build_is_deterministic():
    assert _model_bytes(Scene(_assets()).model) == _model_bytes(Scene(_assets()).model)


def test_initial_state_sampling_is_deterministic_and_separated():
    assets = _assets()
    a = sample_scattered(np.random.default_rng(7), assets)
    b = sample_scattered(np.random.default_rng(7), assets)
    c = sample_scattered(np.random.default_rng(8), assets)
    assert a == b and a != c
    xy = [np.array(p.pos[:2]) for n, p in a.items() if n != "patch"]
    assert min(np.linalg.norm(p - q) for i, p in enumerate(xy) for q in xy[i + 1:]) >= C.MIN_SEPARATION
    for p in a.values():
        assert C.WORKSPACE_X[0] <= p.pos[0] <= C.WORKSPACE_X[1]
        assert C.WORKSPACE_Y[0] <= p.pos[1] <= C.WORKSPACE_Y[1]
    s1, s2 = Scene(assets), Scene(assets)
    s1.set_poses(a)
    s2.set_poses(b)
    assert s1.data.qpos.tobytes() == s2.data.qpos.tobytes()


def test_initial_structure_and_infeasible_layout():
    assets = [ColoredCube("red", color="red"), ColoredCube("yellow", color="yellow")]
    poses = sample_scattered(np.random.default_rng(0), assets, structures=[["red", "yellow"]])
    assert poses["yellow"].pos[2] > poses["red"].pos[2] + 0.9 * C.CUBE_EDGE
    many = [ColoredCube(f"c{i}", color="red") for i in range(60)]
    with pytest.raises(InfeasibleLayout, match="could not place"):
        sample_scattered(np.random.default_rng(0), many, min_separation=0.1)


def test_cubes_with_a_goal_region_start_outside_it():
    from rpg.domain.predicates import region_bounds

    assets = [ColoredCube("red", color="red"), ColoredCube("blue", color="blue"), ColoredCube("green", color="green")]
    avoid = {"red": "center", "blue": "left"}
    seen = {"red": [], "blue": []}
    for seed in range(60):
        poses = sample_scattered(np.random.default_rng(seed), assets, avoid=avoid)
        assert poses == sample_scattered(np.random.default_rng(seed), assets, avoid=avoid)
        for name, region in avoid.items():
            (x0, x1), (y0, y1) = region_bounds(region)
            x, y = poses[name].pos[:2]
            assert not (x0 <= x <= x1 and y0 <= y <= y1), (seed, name)
            seen[name].append(y)
    plain = [sample_scattered(np.random.default_rng(s), assets)["blue"].pos[1] for s in range(60)]
    assert max(plain) > region_bounds("left")[1][0], "without avoid the left third is sampled (the test would be vacuous)"
    with pytest.raises(InfeasibleLayout, match="outside its goal region"):
        sample_scattered(np.random.default_rng(0), assets[:2], avoid={"red": "left", "blue": "left"}, min_separation=0.40)


def test_state_json_round_trip_and_errors():
    s = Scene(_assets())
    s.set_poses(sample_scattered(np.random.default_rng(3), list(s.assets.values())))
    doc = s.to_json()
    t = Scene(_assets())
    t.load_json(doc)
    assert t.to_json() == doc
    with pytest.raises(SceneError, match="no object named"):
        t.load_json(json.dumps({"objects": {"ghost": {"position": [0, 0, 1]}}}))
    with pytest.raises(SceneError, match="must be"):
        t.load_json(json.dumps({"objects": {"red": {"position": ["a", 0, 1]}}}))
    with pytest.raises(SceneError, match="not finite"):
        t.set_pose("red", (float("nan"), 0, 1))
    with pytest.raises(SceneError, match="duplicate"):
        Scene([ColoredCube("x"), ColoredCube("x")])


def _stable(scene, steps=100):
    before = scene.poses()
    scene.settle(steps)
    report = drift_report(before, scene.poses())
    return max(r["drift"] for r in report.values()), max(r["drop"] for r in report.values())


@pytest.mark.parametrize("layout", ["tower3", "pyramid_9_4_1", "block_3x3x3"])
def test_structures_are_stable(layout):
    if layout == "tower3":
        poses = stack_layout(["c0", "c1", "c2"], (0.55, 0.0))
    elif layout == "pyramid_9_4_1":
        poses = pyramid_layout([f"c{i}" for i in range(14)], base=3, dims=3)
    else:
        poses = grid_layout([f"c{i}" for i in range(27)], 3, 3, 3)
    drift, drop = _stable(scene_with(poses))
    assert drift < C.MAX_DRIFT and drop < C.MAX_DROP


def test_unsupported_cube_falls_and_is_caught():
    poses = {"c0": stack_layout(["c0"], (0.55, 0.0))["c0"]}
    poses["c1"] = type(poses["c0"])((0.55 + 0.035, 0.0, poses["c0"].pos[2] + C.CUBE_EDGE))
    drift, drop = _stable(scene_with(poses), 300)
    assert drop > C.MAX_DROP


def test_visibility_in_a_stack():
    s = scene_with(stack_layout(["b", "m", "t"], (0.55, 0.0)), {"b": "A", "m": "B", "t": "C"})
    assert face_visibility(s, "t", "+z").visible
    assert not face_visibility(s, "m", "+z").visible  # covered by t
    assert not face_visibility(s, "b", "+z").visible
    for n in ("b", "m", "t"):
        assert face_visibility(s, n, "-x").visible  # faces toward the robot and camera
        assert not face_visibility(s, n, "+x").visible  # faces away


def test_visibility_in_a_line():
    names = ["l0", "l1", "l2", "l3"]
    s = scene_with(line_layout(names, spacing=C.CUBE_EDGE + 0.0005), dict(zip(names, "ABCD", strict=True)))
    for n in names:
        assert face_visibility(s, n, "+z").visible
    assert not face_visibility(s, "l1", "+y").visible  # touching l0
    assert not face_visibility(s, "l1", "-y").visible  # touching l2


def test_visibility_in_a_3x3_pyramid():
    names = [f"p{i}" for i in range(14)]
    s = scene_with(pyramid_layout(names, base=3, dims=3), {n: "A" for n in names})
    assert face_visibility(s, "p13", "+z").visible  # apex
    assert not face_visibility(s, "p4", "+z").visible  # centre of the base, under the middle layer
    front_row = ["p0", "p1", "p2"]
    for n in front_row:
        assert face_visibility(s, n, "-x").visible
    assert not face_visibility(s, "p4", "-x").visible  # behind the front row


def test_all_faces_cast_together_see_what_each_face_cast_alone_sees():
    """visible_faces casts the rays of every face turned to the camera in one call: the same verdicts, face by
    face, as casting each face alone, in a 14-cube pyramid where faces hide one another."""
    names = [f"p{i}" for i in range(14)]
    s = scene_with(pyramid_layout(names, base=3, dims=3), {n: "A" for n in names})
    together = visible_faces(s)
    alone = {(n, f): face_visibility(s, n, f).visible for n in names for f in FACES}
    assert together == alone
    assert 0 < sum(together.values()) < len(together) / 2  # some faces seen, most hidden or turned away
    assert together[("p13", "+z")] and not together[("p4", "+z")]
