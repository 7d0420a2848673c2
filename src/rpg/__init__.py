"""rpg: compile natural-language instructions into reproducible MuJoCo block tasks."""

import os as _os

# Headless rendering: EGL first (see rpg.domain.render for the OSMesa fallback).
_os.environ.setdefault("MUJOCO_GL", "egl")

from rpg._version import __version__  # noqa: E402

__all__ = ["__version__"]
