"""Camera images of an environment: :class:`CameraRenderer`, a ``mujoco.Renderer`` with the
settings issue 32 measured on Mesa's software renderer (llvmpipe, 2 cores).

Per image, with the Panda's meshes (:mod:`rpg.env.embodiments.visuals`) unchanged:

- **Receivers cast no shadow.**  The table and the floor (:data:`rpg.domain.scene.SHADOW_RECEIVERS`)
  are drawn into the shadow map no more (marked as decoration after each scene update; MuJoCo
  skips decoration when it draws the map): nothing stands under them for their shadow to fall
  on, the map then holds only the robot and the cubes, and the table can no longer shadow
  itself: the moire of dots on the far side of the table (shadow acne where the table's own
  depth was compared with itself near the edge of the light's frustum) is gone.
- **A shadow map sized for the image**: :func:`shadow_map_size` (4 texels per pixel drawn,
  1024 for 256x256; MuJoCo's default is 4096, which costs a software renderer ~4x).
- **Smoother wrist shadows**: the wrist camera reads the shadow map with linear filtering
  instead of MuJoCo's nearest texel, so the edge of a shadow it sees up close follows a
  slightly smoother contour.  It is still hard, a pixel lit or shadowed, never between,
  on Mesa's llvmpipe and on an NVIDIA driver (H200, EGL) alike (``benchmarks/bench_wrist_shadow.py``, 8 wrist frames of an oracle episode at 256x256:
  34-49 pixels between the two levels against ~3,500 hard steps on both, with either filter
  and with a 4096 map).  A ramp comes from **supersampling** (``BlockTaskEnv(...,
  wrist_supersample=2)``, off by default: :func:`CameraRenderer.image` with ``supersampled``):
  the wrist image drawn at 2x and each 2x2 block averaged, its shadow map sized for the drawn
  image (2048 at 256x256): ~1,800 ramp pixels and a fifth of the hard steps, on both
  renderers.  MuJoCo reads the shadow map's size (``model.vis.quality.shadowsize``) when a
  rendering context is made, so the supersampled wrist camera has a renderer (and an OpenGL
  context) of its own and the other cameras keep theirs, their images byte for byte those
  without supersampling (tested); what it costs in steps/s is in the README
  (``benchmarks/bench_env.py`` times it).  The other cameras keep the nearest texel: at a
  distance, on the arm's curved surfaces, the filter's wider footprint would need more depth
  bias than MuJoCo applies (acne).
- **No sky where none is seen**: the skybox (a textured cylinder drawn over every pixel) is
  skipped when all four corners of the image see the floor.

Only the cameras an environment observes are drawn, one ``mjv_updateScene`` each.
"""

from __future__ import annotations

import logging
import math

import mujoco
import numpy as np

from rpg.domain.scene import SHADOW_RECEIVERS

log = logging.getLogger(__name__)

SOFT_SHADOW_CAMERAS = ("wrist",)
"""Cameras whose shadows are read with linear (percentage-closer) filtering."""

SUPERSAMPLE_FACTORS = (1, 2, 3, 4)
"""The supersampling factors a camera may be drawn with (1: none)."""

WRIST_SUPERSAMPLE_OPTIONS = (1, 2)
"""What ``rpg eval`` and ``rpg demos`` take as ``--wrist-supersample`` (1: off, the default;
2: the wrist camera drawn at 2x per side, what the README measures); the environment itself
takes :data:`SUPERSAMPLE_FACTORS`."""


def check_wrist_supersample(value: object) -> int:
    """``value`` as a ``--wrist-supersample`` factor (:data:`WRIST_SUPERSAMPLE_OPTIONS`).

    Raises:
        BadInput: anything else (another integer, a string, a boolean), in one line.
    """
    from rpg.errors import BadInput

    if type(value) is not int or value not in WRIST_SUPERSAMPLE_OPTIONS:
        raise BadInput(f"--wrist-supersample must be 1 (off) or 2 (the wrist camera drawn at 2x and averaged), "
                       f"not {value!r}")
    return value


def shadow_map_size(height: int, width: int) -> int:
    """Side of the shadow map for images of ``height`` x ``width`` pixels: 4 texels per
    pixel of the longer side, a power of two in [512, 4096]."""
    side = 4 * max(int(height), int(width))
    return int(min(4096, max(512, 1 << (side - 1).bit_length())))


class CameraRenderer(mujoco.Renderer):
    """Offscreen images (H, W, 3) uint8 of a model's cameras with the settings above.

    Args:
        model: the compiled scene.  Its offscreen buffer size and shadow map size
            (``model.vis``) are set for this renderer's context while it is made, then
            restored: each renderer's context has its own, whatever was made before.
        height, width: image size, pixels.
        supersample: how many times the size :meth:`image` draws a ``supersampled`` camera
            (1..4; the offscreen buffer and the shadow map are sized for it, so a renderer
            with ``supersample`` > 1 draws every camera's shadows from the larger map: give
            the other cameras a renderer of their own, as :class:`rpg.env.BlockTaskEnv` does).
    """

    def __init__(self, model: mujoco.MjModel, height: int, width: int, supersample: int = 1):
        vis = model.vis
        self.supersample = max(1, int(supersample))
        saved = vis.global_.offwidth, vis.global_.offheight, vis.quality.shadowsize
        vis.global_.offwidth = max(vis.global_.offwidth, width * self.supersample)
        vis.global_.offheight = max(vis.global_.offheight, height * self.supersample)
        # 4 texels per pixel drawn: a supersampled camera's pixels are smaller
        vis.quality.shadowsize = shadow_map_size(height * self.supersample, width * self.supersample)
        try:
            super().__init__(model, height=height, width=width)
        finally:  # read by MjrContext when it is made; the next renderer sets its own
            vis.global_.offwidth, vis.global_.offheight, vis.quality.shadowsize = saved
        self._receivers = {model.geom(n).id for n in SHADOW_RECEIVERS if _has_geom(model, n)}
        floor = model.geom("floor") if _has_geom(model, "floor") else None
        # an infinite plane (size 0) has no edge to see past
        self._floor = None if floor is None else (np.array(floor.pos, float), float(floor.size[0]) or math.inf,
                                                  float(floor.size[1]) or math.inf)
        self._soft = False
        self._gl_filters = True

    def image(self, data: mujoco.MjData, camera: str, soft_shadows: bool = False,
              supersampled: bool = False) -> np.ndarray:
        """The image of ``camera`` (a camera name in the model) for the state in ``data``
        (kinematics computed: after ``mj_step`` or ``mj_forward``); ``supersampled``: drawn
        at ``supersample`` times the size and reduced by the mean of each block of pixels."""
        cam_id = self.model.camera(camera).id
        self.update_scene(data, camera=cam_id)
        scene = self.scene
        self._cast_no_shadow(scene)
        scene.flags[mujoco.mjtRndFlag.mjRND_SKYBOX] = self._sky_visible(data, cam_id)
        self._filter_shadows(soft_shadows)
        if supersampled and self.supersample > 1:
            return self._supersampled()
        return self.render()

    def _supersampled(self) -> np.ndarray:
        """The scene drawn at ``supersample`` x the image size into the offscreen buffer, each
        s x s block of pixels averaged (rounded) into one."""
        k, h, w = self.supersample, self.height, self.width
        if self._gl_context:
            self._gl_context.make_current()
        rect = mujoco.MjrRect(0, 0, w * k, h * k)
        mujoco.mjr_render(rect, self.scene, self._mjr_context)
        big = np.empty((h * k, w * k, 3), np.uint8)
        mujoco.mjr_readPixels(big, None, rect, self._mjr_context)
        # strided adds (~1 ms at 512x512; numpy's sum over two axes of a reshape takes ~8 ms)
        total = np.zeros((h, w, 3), np.uint16)  # at most 16 x 255
        for i in range(k):
            for j in range(k):
                total += big[i::k, j::k]
        return np.ascontiguousarray(((total + k * k // 2) // (k * k)).astype(np.uint8)[::-1])  # rows run bottom-up

    def renderer_name(self) -> str:
        """The OpenGL renderer's name (``llvmpipe (LLVM ...)`` for Mesa's software renderer),
        or ``"unknown"``."""
        try:
            from OpenGL import GL

            self._gl_context.make_current()
            return GL.glGetString(GL.GL_RENDERER).decode(errors="replace")
        except Exception:  # noqa: BLE001 - a name for a report, nothing depends on it
            return "unknown"

    def _cast_no_shadow(self, scene: mujoco.MjvScene) -> None:
        """Mark the receivers as decoration in the scene just updated (they come first: they
        are the world body's first geoms)."""
        left = len(self._receivers)
        geom = mujoco.mjtObj.mjOBJ_GEOM
        for i in range(scene.ngeom):
            if not left:
                return
            g = scene.geoms[i]
            if g.objtype == geom and g.objid in self._receivers:
                g.category = mujoco.mjtCatBit.mjCAT_DECOR
                left -= 1

    def _sky_visible(self, data: mujoco.MjData, cam_id: int) -> bool:
        """Whether a ray through a corner of the image misses the floor (then the sky shows)."""
        if self._floor is None:
            return True
        center, hx, hy = self._floor
        pos = data.cam_xpos[cam_id]
        mat = data.cam_xmat[cam_id].reshape(3, 3)
        ty = math.tan(math.radians(self.model.cam_fovy[cam_id]) / 2)
        tx = ty * self.width / self.height
        for sx in (-1.0, 1.0):
            for sy in (-1.0, 1.0):
                ray = mat @ np.array([sx * tx, sy * ty, -1.0])  # a camera looks along its -z
                if ray[2] >= -1e-9:
                    return True
                hit = pos + (center[2] - pos[2]) / ray[2] * ray
                if abs(hit[0] - center[0]) > hx or abs(hit[1] - center[1]) > hy:
                    return True
        return False

    def _filter_shadows(self, soft: bool) -> None:
        """Nearest or linear filtering of the shadow map (an OpenGL texture parameter of
        MuJoCo's context; left as MuJoCo set it where PyOpenGL cannot reach it)."""
        if soft == self._soft or not self._gl_filters:
            return
        try:
            from OpenGL import GL

            self._gl_context.make_current()
            mode = GL.GL_LINEAR if soft else GL.GL_NEAREST
            GL.glActiveTexture(GL.GL_TEXTURE1)
            GL.glBindTexture(GL.GL_TEXTURE_2D, self._mjr_context.shadowTex)
            GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, mode)
            GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, mode)
            GL.glActiveTexture(GL.GL_TEXTURE0)
            self._soft = soft
        except Exception as exc:  # noqa: BLE001 - an OpenGL binding that cannot: keep MuJoCo's filter
            log.warning("shadow-map filtering unavailable (%s); shadows keep MuJoCo's nearest texel", exc)
            self._gl_filters = False


def _has_geom(model: mujoco.MjModel, name: str) -> bool:
    return mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name) >= 0
