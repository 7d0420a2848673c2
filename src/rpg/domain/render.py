"""Headless PNG snapshots from the default camera through ``mujoco.Renderer``.

The OpenGL backend is EGL first, then OSMesa.  ``rpg`` sets ``MUJOCO_GL=egl`` when it is
imported unless the variable is already set.  Rendering needs the system's EGL (Debian:
``libegl1``, ``libgl1``, ``libgles2``; Mesa works without a GPU) or OSMesa (Debian:
``libosmesa6``).  Where neither loads, :func:`render_snapshot` returns None with a
warning and nothing else fails.
"""

from __future__ import annotations

import logging
import os
import warnings
from pathlib import Path

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.domain.scene import Scene

log = logging.getLogger(__name__)

_BACKEND_FAILED = False


class RenderUnavailable(RuntimeWarning):
    """Warned when no headless OpenGL backend could be loaded; snapshots are skipped."""


def _make_renderer(model: mujoco.MjModel, width: int, height: int) -> mujoco.Renderer | None:
    global _BACKEND_FAILED
    if _BACKEND_FAILED:
        return None
    try:
        return mujoco.Renderer(model, height=height, width=width)
    except Exception as first:  # noqa: BLE001 - any backend failure means: try the next one
        from mujoco.rendering.classic import gl_context

        errors = [f"{gl_context.GLContext.__module__}: {first}"]
        for module in ("mujoco.egl", "mujoco.osmesa"):
            try:
                gl_context.GLContext = __import__(module, fromlist=["GLContext"]).GLContext
                return mujoco.Renderer(model, height=height, width=width)
            except Exception as exc:  # noqa: BLE001
                errors.append(f"{module}: {exc}")
        _BACKEND_FAILED = True
        warnings.warn(
            "snapshots skipped: no headless OpenGL (" + "; ".join(errors) + "). "
            "Install libegl1 (EGL) or libosmesa6 (OSMesa) to get snapshots.",
            RenderUnavailable,
            stacklevel=3,
        )
        return None


def render_image(scene: Scene, width: int = C.SNAPSHOT_SIZE[0], height: int = C.SNAPSHOT_SIZE[1],
                 camera: str = C.CAMERA_NAME) -> np.ndarray | None:
    """RGB image (height, width, 3) uint8 of the scene from ``camera``, or None without OpenGL."""
    renderer = _make_renderer(scene.model, width, height)
    if renderer is None:
        return None
    try:
        scene.forward()
        renderer.update_scene(scene.data, camera=camera)
        return renderer.render().copy()
    finally:
        renderer.close()


def render_snapshot(scene: Scene, path: str | Path, **kwargs) -> Path | None:
    """Write a PNG snapshot of the scene to ``path``; None (and a warning) without OpenGL."""
    with Snapshotter(scene, **kwargs) as snap:
        return snap.save(path)


class _SharedContext:
    """One OpenGL context kept current for the life of a process, so that each model only
    needs a :class:`mujoco.MjrContext` (a few ms) instead of a new context (~50 ms on Mesa
    llvmpipe) plus shader compilation on its first frame (~50 ms)."""

    def __init__(self, width: int, height: int):
        from mujoco.rendering.classic import gl_context

        if gl_context.GLContext is None:
            raise RuntimeError("no OpenGL backend")
        self.width, self.height = width, height
        self.gl = gl_context.GLContext(width, height)
        self.gl.make_current()
        self.owner = os.getpid()
        self.fork_safe = False


_SHARED: _SharedContext | None = None


def warm_shared_context() -> bool:
    """Create this process's shared OpenGL context and render a warm-up scene (a letter
    cube, a coloured cube and a goal patch) so that the renderer's shader variants are
    compiled once.  Called by the fork server before it forks any child: children inherit
    the current, warm context and only build an :class:`mujoco.MjrContext` per task.

    A forked child can only use the context when the renderer started no threads (a child
    has none of its parent's threads; Mesa llvmpipe starts none with ``LP_NUM_THREADS=0``
    and ``MESA_SHADER_CACHE_DISABLE=true``).  :func:`shared_context_fork_safe` says whether
    that holds; children of a process where it does not build their own context.

    Returns:
        True when a warm context now exists; False where no headless OpenGL loads.
    """
    global _SHARED
    from rpg.domain.assets import ColoredCube, GoalPatch, SemanticCube

    try:
        _SHARED = _SharedContext(C.SNAPSHOT_SIZE[0], C.SNAPSHOT_SIZE[1])
        scene = Scene([SemanticCube("warm_letter", label="A"), ColoredCube("warm_cube", color="red"),
                       GoalPatch("warm_patch", color="blue")])
        scene.set_pose("warm_letter", (0.5, -0.05, C.TABLE_TOP_Z + C.CUBE_EDGE / 2))
        scene.set_pose("warm_cube", (0.5, 0.05, C.TABLE_TOP_Z + C.CUBE_EDGE / 2))
        with Snapshotter(scene) as snap:
            snap.image()
        _SHARED.fork_safe = _thread_count() == 1
        return True
    except Exception as exc:  # noqa: BLE001 - no warm context: snapshots make their own as before
        log.debug("no shared OpenGL context: %s", exc)
        _SHARED = None
        return False


def _thread_count() -> int:
    """Native threads of this process (Linux ``/proc``; elsewhere assumed more than one)."""
    try:
        return len(os.listdir("/proc/self/task"))
    except OSError:
        return 2


def shared_context_fork_safe() -> bool:
    """Whether this process has a warm shared context that forked children may use."""
    return _SHARED is not None and _SHARED.fork_safe


class _ModelRenderer:
    """Renders one model in the shared context: the part of :class:`mujoco.Renderer` that
    is per model (MjrContext, MjvScene), without a context of its own."""

    def __init__(self, shared: _SharedContext, model: mujoco.MjModel, width: int, height: int):
        shared.gl.make_current()
        self.model, self.width, self.height = model, width, height
        self.context = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_50.value)
        mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN.value, self.context)
        self.scene = mujoco.MjvScene(model, maxgeom=10_000)
        self.option = mujoco.MjvOption()
        self.camera = mujoco.MjvCamera()

    def update_scene(self, data: mujoco.MjData, camera: str) -> None:
        self.camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
        self.camera.fixedcamid = self.model.camera(camera).id
        mujoco.mjv_updateScene(self.model, data, self.option, None, self.camera,
                               mujoco.mjtCatBit.mjCAT_ALL.value, self.scene)

    def render(self) -> np.ndarray:
        rect = mujoco.MjrRect(0, 0, self.width, self.height)
        buf = np.empty((self.height, self.width, 3), dtype=np.uint8)
        mujoco.mjr_render(rect, self.scene, self.context)
        mujoco.mjr_readPixels(buf, None, rect, self.context)
        return np.flipud(buf)

    def close(self) -> None:
        self.context.free()


class Snapshotter:
    """Several snapshots of one scene through one renderer (one OpenGL context, or the
    process's shared context after :func:`warm_shared_context`).

    Use as a context manager; :meth:`save` writes the scene as it is now.
    """

    def __init__(self, scene: Scene, width: int = C.SNAPSHOT_SIZE[0], height: int = C.SNAPSHOT_SIZE[1],
                 camera: str = C.CAMERA_NAME):
        self.scene, self.camera = scene, camera
        shared = _SHARED if _SHARED is not None and (_SHARED.owner == os.getpid() or _SHARED.fork_safe) else None
        if shared is not None and width <= shared.width and height <= shared.height:
            self.renderer = _ModelRenderer(shared, scene.model, width, height)
        else:
            self.renderer = _make_renderer(scene.model, width, height)

    def __enter__(self) -> Snapshotter:
        return self

    def __exit__(self, *exc) -> None:
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None

    def image(self) -> np.ndarray | None:
        """RGB image (height, width, 3) uint8 of the scene's current state; None without OpenGL."""
        if self.renderer is None:
            return None
        self.scene.forward()
        self.renderer.update_scene(self.scene.data, camera=self.camera)
        return self.renderer.render()

    def png(self) -> bytes | None:
        """The scene's current state as PNG bytes; None without OpenGL."""
        import io

        from PIL import Image

        img = self.image()
        if img is None:
            return None
        buf = io.BytesIO()
        Image.fromarray(img).save(buf, format="PNG", compress_level=1)
        return buf.getvalue()

    def save(self, path: str | Path) -> Path | None:
        """Write a PNG of the scene's current state; None without OpenGL."""
        from PIL import Image

        img = self.image()
        if img is None:
            return None
        path = Path(path)
        Image.fromarray(img).save(path, format="PNG", compress_level=1)
        return path
