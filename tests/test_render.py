"""Snapshots are drawn by rpg's own process from the task's data: the sandboxed child that
runs task code has no simulator and no renderer.  The environment's cameras (issue 32): the
decimated robot meshes leave the physics as it is and look like the stock ones, agentview
frames the arm and the workspace, no acne on the table, filtered wrist shadows."""

import io
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from rpg.compiler import compile_instruction


@pytest.fixture(scope="module")
def letters(tmp_path_factory):
    return compile_instruction("Spell CAB with letter blocks in a row", tmp_path_factory.mktemp("cab")).path


def _png(path) -> np.ndarray:
    if not path.is_file():
        pytest.skip("no headless OpenGL on this machine")
    return np.asarray(Image.open(io.BytesIO(path.read_bytes())).convert("RGB")).astype(int)


def test_rpg_render_redraws_the_compiled_snapshots(letters, tmp_path):
    before = {k: _png(letters / f"{k}.png") for k in ("initial", "goal")}
    for k in before:
        (letters / f"{k}.png").unlink()
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "render", str(letters)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    for key, a in before.items():
        b = _png(letters / f"{key}.png")
        assert a.shape == b.shape == (480, 640, 3)
        assert a.std() > 5, "blank image"
        assert np.abs(a - b).mean() < 0.05, key
    assert np.abs(before["initial"] - before["goal"]).mean() > 0.5  # two different states


def test_the_child_that_runs_task_code_imports_no_simulator(letters):
    """The sandboxed child answers with data only: it must not even import MuJoCo or an
    OpenGL binding (what it cannot load it cannot misuse)."""
    code = ("import sys, json; from rpg.validate import child; from rpg.artifact import task_sources;"
            f"out = child.handle({{'op': 'data', 'sources': task_sources({str(letters)!r}), 'seeds': [0]}});"
            "assert json.loads(out)['ok'], out;"
            "bad = sorted(m for m in sys.modules if m.split('.')[0] in ('mujoco', 'OpenGL', 'PIL', 'gymnasium'));"
            "print(bad)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


# -- environment cameras (issue 32): decimated meshes, framing, shadows -----------------------

STACK = Path(__file__).resolve().parents[1] / "library" / "stack_blocks"
EMBODIMENTS = ("floating_gripper", "panda")


def _camera_env(embodiment: str, **kw):
    from rpg.env import BlockTaskEnv

    kw.setdefault("cameras", ())
    return BlockTaskEnv(STACK, embodiment=embodiment, **kw)


def _segmentation(env, camera: str = "agentview") -> np.ndarray:
    """Per pixel: the geom id the camera sees (-1: none), through MuJoCo's segmentation render."""
    import mujoco

    try:
        r = mujoco.Renderer(env.model, *env.image_size)
    except Exception as exc:  # noqa: BLE001
        pytest.skip(f"no headless OpenGL on this machine: {exc}")
    try:
        r.enable_segmentation_rendering()
        r.update_scene(env.data, camera)
        seg = r.render()
    finally:
        r.close()
    return np.where(seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM), seg[..., 0], -1)


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_decimated_visual_meshes_leave_the_physics_as_it_is(embodiment):
    """Only visual geoms change: the same actions give bit-identical states with either mesh
    set, and masses, inertias and every collision geom are the stock ones."""
    envs = [_camera_env(embodiment, visual=v) for v in ("stock", "decimated")]
    stock, dec = (e.model for e in envs)
    assert np.array_equal(stock.body_mass, dec.body_mass) and np.array_equal(stock.body_inertia, dec.body_inertia)

    def collision(m):
        g = np.flatnonzero((m.geom_contype != 0) | (m.geom_conaffinity != 0))
        return [m.geom_type[g], m.geom_size[g], m.geom_pos[g], m.geom_quat[g], m.geom_friction[g], m.geom_bodyid[g]]

    for a, b in zip(collision(stock), collision(dec), strict=True):
        assert np.array_equal(a, b)
    assert dec.nmeshvert < stock.nmeshvert / 3  # collision meshes stay; visual ones shrink
    for e in envs:
        e.reset(seed=4)
    rng = np.random.default_rng(4)
    for _ in range(40):
        a = rng.uniform(-1, 1, envs[0].action_space.shape).astype(np.float32)
        for e in envs:
            e.step(a)
        assert np.array_equal(envs[0].data.qpos, envs[1].data.qpos)
        assert np.array_equal(envs[0].data.qvel, envs[1].data.qvel)


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_decimated_images_look_like_the_stock_ones(embodiment):
    """SSIM of each camera's 256x256 image, decimated against stock meshes, >= 0.95 (issue 32)
    along a few steps of motion."""
    metrics = pytest.importorskip("skimage.metrics")
    envs = [_camera_env(embodiment, visual=v, cameras=("agentview", "wrist"), image_size=(256, 256))
            for v in ("stock", "decimated")]
    try:
        obs = [e.reset(seed=1)[0] for e in envs]
    except Exception as exc:  # noqa: BLE001
        if "OpenGL" in str(exc) or "EGL" in str(exc):
            pytest.skip(f"no headless OpenGL on this machine: {exc}")
        raise
    rng = np.random.default_rng(1)
    for k in range(3):
        for cam in ("agentview", "wrist"):
            a, b = (o[f"{cam}_image"] for o in obs)
            assert a.std() > 5
            ssim = metrics.structural_similarity(a, b, channel_axis=2, data_range=255)
            assert ssim >= 0.95, (cam, k, ssim)
        act = (0.5 * rng.uniform(-1, 1, envs[0].action_space.shape)).astype(np.float32)
        for _ in range(6):
            obs = [e.step(act)[0] for e in envs]


def test_shipped_decimated_meshes_are_a_fresh_build():
    """The shipped meshes are what ``python -m rpg.env.embodiments.visuals`` builds from the
    vendored Menagerie meshes (deterministic), with the manifest's library version."""
    pytest.importorskip("fast_simplification")
    import json
    from importlib.metadata import version

    from rpg.env.embodiments import visuals

    manifest = json.loads(visuals.MANIFEST.read_text())
    have = f"fast-simplification {version('fast-simplification')}"
    if manifest["library"] != have:
        pytest.skip(f"the meshes were built with {manifest['library']}, this is {have}")
    assert visuals.check() == []
    groups = visuals.all_groups()
    assert {m["output"] for m in manifest["meshes"]} == {g.output for g in groups}


def test_unknown_visual_is_refused():
    from rpg.env.embodiments import EmbodimentError

    with pytest.raises(EmbodimentError, match="visual"):
        _camera_env("panda", visual="fancy")


def test_agentview_shows_the_arm_and_the_workspace():
    """The framing cannot regress unseen (issue 32: agentview showed only the hand): at home the
    Panda's arm links beyond the hand cover >= 2% of the image, the hand lies inside the image,
    the table >= 40%, and the workspace's corners project into it."""
    import mujoco

    from rpg.domain import constants as C

    env = _camera_env("panda", image_size=(128, 128))
    env.reset(seed=0)
    m, d = env.model, env.data
    seg = _segmentation(env)
    body = np.where(seg >= 0, m.geom_bodyid[np.maximum(seg, 0)], -1)
    arm = np.isin(body, [m.body(f"robot/link{i}").id for i in range(1, 7)])
    hand = np.isin(body, [m.body(f"robot/{b}").id for b in ("hand", "left_finger", "right_finger")])
    assert 0.02 <= arm.mean() <= 0.25, arm.mean()
    rows, cols = np.nonzero(hand)
    assert len(rows) and rows.min() > 0 and cols.min() > 0 and rows.max() < 127 and cols.max() < 127
    assert (seg == m.geom("table").id).mean() >= 0.4
    cam = m.camera("agentview").id
    mujoco.mj_forward(m, d)
    R, p = d.cam_xmat[cam].reshape(3, 3), d.cam_xpos[cam]
    f = 64 / np.tan(np.radians(m.cam_fovy[cam]) / 2)
    for x in C.WORKSPACE_X:
        for y in C.WORKSPACE_Y:
            v = R.T @ (np.array([x, y, C.TABLE_TOP_Z]) - p)
            u, w = 64 + f * v[0] / -v[2], 64 - f * v[1] / -v[2]
            assert 4 < u < 124 and 4 < w < 124, (x, y, u, w)


def _isolated_dark_pixels(img: np.ndarray, mask: np.ndarray) -> int:
    """Pixels in ``mask`` darker than all 8 neighbours by > 24 (sum of RGB): acne's dots."""
    g = img.astype(int).sum(axis=2)
    c = g[1:-1, 1:-1]
    h, w = g.shape
    neighbours = np.stack([g[1 + dy:h - 1 + dy, 1 + dx:w - 1 + dx]
                           for dy in (-1, 0, 1) for dx in (-1, 0, 1) if dy or dx])
    return int(((c < neighbours.min(axis=0) - 24) & mask[1:-1, 1:-1]).sum())


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_no_moire_of_dots_on_the_table(embodiment):
    """The table casts no shadow in the environment's cameras, so it cannot shadow itself: no
    dots of acne on it (MuJoCo's own renderer of the same scene shows dozens)."""
    import mujoco

    env = _camera_env(embodiment, image_size=(256, 256))
    env.reset(seed=0)
    table = _segmentation(env) == env.model.geom("table").id
    ours = env.render_camera("agentview")
    r = mujoco.Renderer(env.model, 256, 256)
    r.update_scene(env.data, "agentview")
    plain = r.render()
    r.close()
    assert _isolated_dark_pixels(plain, table) > 10  # the artefact this guards against is there
    assert _isolated_dark_pixels(ours, table) == 0


def test_wrist_shadows_are_filtered():
    """The wrist camera reads the shadow map with linear filtering: where a shadow map's texel
    covers several pixels (the hand low, off the light's axis) the shadow's edge follows a
    smooth contour instead of texel-sized stairs; only pixels on shadow edges change."""
    from scipy import ndimage

    from rpg.domain import constants as C

    env = _camera_env("panda", control_mode="ee_abs", image_size=(256, 256))
    env.reset(seed=0)
    for _ in range(30):
        env.step(np.array([0.45, -0.2, C.TABLE_TOP_Z + 0.09, np.pi, 0, 0, -1], np.float32))
    renderer_soft = env.render_camera("wrist")
    hard = env._renderer.image(env.data, "robot/wrist", soft_shadows=False).astype(int)
    soft = env._renderer.image(env.data, "robot/wrist", soft_shadows=True).astype(int)
    assert np.array_equal(renderer_soft, soft)
    diff = np.abs(soft - hard).sum(axis=2)
    assert 0.002 < (diff > 20).mean() < 0.05, (diff > 20).mean()
    g = hard.sum(axis=2)
    edges = (ndimage.maximum_filter(g, 3) - ndimage.minimum_filter(g, 3)) > 20
    assert not ((diff > 20) & ~ndimage.binary_dilation(edges, iterations=2)).any()  # shadow edges move, nothing else


def _shadow_factor(env) -> np.ndarray:
    """Per pixel of the wrist image: 1 lit by the shadow-casting light, 0 in its shadow, NaN
    where that light adds too little to tell (the image as is, without shadows, and without
    the light)."""
    import mujoco

    renderer, model = env._renderer_for("wrist"), env.model
    on = env.render_camera("wrist")
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = False
    off = env.render_camera("wrist")
    renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = True
    key = next(i for i in range(model.nlight) if model.light_castshadow[i])
    model.light_active[key] = 0
    dark = env.render_camera("wrist")
    model.light_active[key] = 1
    luma = [img.astype(float) @ np.array([0.299, 0.587, 0.114]) for img in (on, off, dark)]
    light = luma[1] - luma[2]
    return np.clip((luma[0] - luma[2]) / np.where(light >= 24, light, np.nan), 0, 1)


def test_a_supersampled_wrist_camera_gives_shadow_edges_a_ramp():
    """``wrist_supersample=2``: the wrist image is the rounded mean of each 2x2 block of the
    image drawn at twice the size (the shadow map sized for that size), so a shadow's edge gets
    pixels between lit and shadowed; drawn at the image size it has next to none (neither
    linear filtering nor a larger shadow map gives a ramp: the filtered depth is compared, on
    Mesa's llvmpipe and on an NVIDIA driver alike; benchmarks/bench_wrist_shadow.py)."""
    from rpg.domain import constants as C
    from rpg.env import BlockTaskEnv
    from rpg.env.embodiments.base import EmbodimentError
    from rpg.env.render import CameraRenderer

    factors, images = {}, {}
    for k in (1, 2):
        env = _camera_env("panda", control_mode="ee_abs", cameras=("wrist",), image_size=(128, 128),
                          wrist_supersample=k)
        try:
            env.reset(seed=0)
            for _ in range(30):
                env.step(np.array([0.45, -0.2, C.TABLE_TOP_Z + 0.09, np.pi, 0, 0, -1], np.float32))
            images[k] = env.render_camera("wrist")
            factors[k] = _shadow_factor(env)
            if k == 2:
                assert env._wrist_renderer._mjr_context.shadowSize == 1024  # 4 texels per pixel drawn (256)
                big = CameraRenderer(env.model, 256, 256)
                try:
                    drawn = big.image(env.data, "robot/wrist", soft_shadows=True).astype(np.uint16)
                finally:
                    big.close()
                mean = (drawn[0::2, 0::2] + drawn[1::2, 0::2] + drawn[0::2, 1::2] + drawn[1::2, 1::2] + 2) // 4
                assert np.array_equal(images[2], mean.astype(np.uint8))
        finally:
            env.close()
    ramp = {k: int(((f > 0.15) & (f < 0.85)).sum()) for k, f in factors.items()}
    assert ramp[1] <= 10 and ramp[2] >= 40 and ramp[2] >= 5 * max(ramp[1], 1), ramp
    assert images[1].shape == images[2].shape == (128, 128, 3)
    with pytest.raises(EmbodimentError, match="wrist_supersample"):
        BlockTaskEnv(STACK, embodiment="panda", cameras=("wrist",), wrist_supersample=5)


def test_a_supersampled_wrist_camera_leaves_the_other_cameras_images_as_they_were():
    """``wrist_supersample=2`` gives the wrist camera a renderer of its own, with the larger
    shadow map (MuJoCo sizes it when a context is made): agentview's images, over steps of a
    moving arm, are byte for byte those of an environment without supersampling, its shadow
    map the image's (96x96: 512 texels, the wrist's 1024), and the model's visual settings are
    left as they were."""
    from rpg.domain import constants as C

    images, sizes = {}, {}
    for k in (1, 2):
        env = _camera_env("panda", control_mode="ee_abs", cameras=("wrist", "agentview"), image_size=(96, 96),
                          wrist_supersample=k)
        vis = env.model.vis
        before = (vis.global_.offwidth, vis.global_.offheight, vis.quality.shadowsize)
        try:
            obs, _ = env.reset(seed=0)
            frames = [obs]
            for _ in range(6):
                frames.append(env.step(np.array([0.45, -0.2, C.TABLE_TOP_Z + 0.09, np.pi, 0, 0, -1], np.float32))[0])
            images[k] = [(f["agentview_image"], f["wrist_image"]) for f in frames]
            sizes[k] = (env._renderer._mjr_context.shadowSize,
                        env._wrist_renderer and env._wrist_renderer._mjr_context.shadowSize)
            assert (vis.global_.offwidth, vis.global_.offheight, vis.quality.shadowsize) == before
        finally:
            env.close()
    assert sizes == {1: (512, None), 2: (512, 1024)}
    for (agent1, _), (agent2, _) in zip(images[1], images[2], strict=True):
        assert np.array_equal(agent1, agent2)
    assert any(not np.array_equal(w1, w2) for (_, w1), (_, w2) in zip(images[1], images[2], strict=True))
