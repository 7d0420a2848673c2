"""Helpers to build real scenes and constructed states in tests."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from rpg.domain import constants as C
from rpg.domain.assets import ColoredCube, SemanticCube
from rpg.domain.scene import Scene
from rpg.domain.state import ObjectState, Pose, WorldState

Z0 = C.TABLE_TOP_Z + C.CUBE_EDGE / 2
E = C.CUBE_EDGE


def cube(name, x, y, z=Z0, color="red", label=None, quat=(1, 0, 0, 0), kind=None):
    faces = {f: label for f in ("+x", "-x", "+y", "-y", "+z", "-z")} if label else {}
    return ObjectState(
        name=name, kind=kind or ("semantic_cube" if label else "colored_cube"),
        pos=np.array([x, y, z], float), quat=np.array(quat, float),
        color=color if not label else "white", label=label, face_labels=faces,
    )


def state(*objs, visible=None):
    return WorldState({o.name: o for o in objs}, visible)


def scene_with(poses: dict[str, Pose], labels: dict[str, str] | None = None) -> Scene:
    labels = labels or {}
    assets = [SemanticCube(n, label=labels[n]) if n in labels else ColoredCube(n, color="red") for n in poses]
    s = Scene(assets)
    s.set_poses(poses)
    return s


def alive(pid: int) -> bool:
    """Whether process ``pid`` exists and is not a zombie (Linux /proc)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"



_COMPILED: dict[tuple, object] = {}


def compiled(instruction: str, out_dir, name: str | None = None):
    """``rpg.compiler.compile_instruction(instruction, out_dir, name=name)`` for tests that
    compile one base task many times (the steering tests): the first call of a test process
    compiles it, later calls copy that valid task directory into ``out_dir``.  A compiled task
    is the same wherever it is written but for its gates' timings (test_steer's
    ``test_a_copied_base_is_the_base_compiled_there`` checks it); an invalid result is never
    reused."""
    import atexit
    import dataclasses
    import os
    import shutil
    import tempfile

    from rpg.compiler import compile_instruction

    key = (instruction, name, os.environ.get("RPG_SNAPSHOTS", ""))  # (with its pictures or without)
    if key not in _COMPILED:
        if not _COMPILED:
            cache = Path(tempfile.mkdtemp(prefix="rpg-test-compiled-"))
            atexit.register(shutil.rmtree, cache, True)
            _COMPILED[("", "", "")] = cache
        r = compile_instruction(instruction, _COMPILED[("", "", "")] / str(len(_COMPILED)), name=name)
        if not r.valid:
            return compile_instruction(instruction, out_dir, name=name)
        _COMPILED[key] = r
    r = _COMPILED[key]
    dest = Path(out_dir) / r.path.name
    shutil.copytree(r.path, dest)
    return dataclasses.replace(r, path=dest)
