"""Headless PNG snapshots from the default camera through ``mujoco.Renderer``.

The OpenGL backend is EGL first, then OSMesa.  ``rpg`` sets ``MUJOCO_GL=egl`` when it is
imported unless the variable is already set.  Rendering needs the system's EGL (Debian:
``libegl1``, ``libgl1``, ``libgles2``; Mesa works without a GPU) or OSMesa (Debian:
``libosmesa6``).  Where neither loads, :func:`render_snapshot` returns None with a
warning and nothing else fails.
"""

from __future__ import annotations

import logging
import threading
import warnings
from pathlib import Path

import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.domain.scene import Scene

log = logging.getLogger(__name__)

_BACKEND_FAILED = False
_WARM_UP: threading.Thread | None = None
"""The thread :func:`warm_up` started; a renderer waits for it (one backend start at a time)."""


class RenderUnavailable(RuntimeWarning):
    """Warned when no headless OpenGL backend could be loaded; snapshots are skipped."""


def _make_renderer(model: mujoco.MjModel, width: int, height: int) -> mujoco.Renderer | None:
    global _BACKEND_FAILED
    if _WARM_UP is not None:
        _WARM_UP.join()
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


def warm_up() -> threading.Thread:
    """Start the OpenGL backend (EGL's display, ~60-90 ms with Mesa) in a background thread.

    Call it before waiting on something else (the validation child): the thread spends its
    time in the driver with the GIL released, and the next :class:`Snapshotter` starts
    faster.  A backend that fails here fails again, with its warning, in the snapshot.
    """

    def start() -> None:
        try:
            from mujoco.rendering.classic import gl_context

            gl_context.GLContext(1, 1).free()
        except Exception:  # noqa: BLE001 - reported by _make_renderer when it matters
            pass

    global _WARM_UP
    thread = threading.Thread(target=start, name="rpg-gl-warm-up", daemon=True)
    thread.start()
    _WARM_UP = thread
    return thread


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


class Snapshotter:
    """Several snapshots of one scene through one renderer (one OpenGL context).

    Use as a context manager; :meth:`save` writes the scene as it is now.
    """

    def __init__(self, scene: Scene, width: int = C.SNAPSHOT_SIZE[0], height: int = C.SNAPSHOT_SIZE[1],
                 camera: str = C.CAMERA_NAME):
        self.scene, self.camera = scene, camera
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
