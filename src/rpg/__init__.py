"""rpg: compile natural-language instructions into reproducible MuJoCo block tasks."""

import os as _os
import re as _re

# The readers match thousands of patterns built from the lexicon; the standard library keeps only 512 compiled ones, so
# a steering session or a batch compile recompiled most of them on every text (about a third of a steer's time).
if getattr(_re, "_MAXCACHE", 0) < 16384:
    _re._MAXCACHE = 16384

# Headless rendering: EGL first (see rpg.domain.render for the OSMesa fallback).
_os.environ.setdefault("MUJOCO_GL", "egl")

from rpg._version import __version__  # noqa: E402

__all__ = ["__version__"]
