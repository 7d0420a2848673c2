"""Domain benchmark: scene build+compile (10 cubes), settle overhead vs raw mj_step, one snapshot."""

import time

import mujoco
from _report import report

import rpg  # noqa: F401  (sets MUJOCO_GL=egl before mujoco loads)
from rpg.domain.assets import ColoredCube
from rpg.domain.layouts import grid_layout
from rpg.domain.render import render_image
from rpg.domain.scene import Scene

assets = [ColoredCube(f"c{i}", color="red") for i in range(10)]
t = time.perf_counter()
for _ in range(20):
    scene = Scene(assets)
build_ms = (time.perf_counter() - t) / 20 * 1000
scene.set_poses(grid_layout([f"c{i}" for i in range(9)], 3, 3) | {"c9": ((0.45, 0.2, 0.97), None)})
N = 5000
t = time.perf_counter()
scene.settle(N)
settle = time.perf_counter() - t
t = time.perf_counter()
for _ in range(N):
    mujoco.mj_step(scene.model, scene.data)
raw = time.perf_counter() - t

t = time.perf_counter()
img = render_image(scene)
render_ms = (time.perf_counter() - t) * 1000 if img is not None else float("nan")
report("domain", [
    ("scene build+compile, 10 cubes", build_ms, "ms", ""),
    ("settle loop", N / settle, "steps/s", ""),
    ("raw mj_step loop", N / raw, "steps/s", ""),
    ("settle overhead vs raw mj_step", settle / raw, "x", "<= 1.2"),
    ("640x480 snapshot (new renderer)", render_ms, "ms", ""),
])
