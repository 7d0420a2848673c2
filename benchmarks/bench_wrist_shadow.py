"""Wrist-camera shadow edges (issue 32): is there a ramp of intermediate intensities across a
shadow's edge, and what does supersampling the wrist image cost?

Two steps, so that the second runs on a machine with nothing but ``mujoco`` and ``numpy``
(a GPU machine lent without rpg's dependencies)::

    python benchmarks/bench_wrist_shadow.py export DIR    # rpg: the Panda scene (model.mjb) and
                                                          # states along an oracle episode
    python benchmarks/bench_wrist_shadow.py measure DIR [OUT]   # render-only, rpg's CameraRenderer

``measure`` loads ``src/rpg/env/render.py`` by path (its one rpg import stubbed with the scene's
shadow receivers, recorded by ``export``), so the images are drawn with rpg's own settings.  Per
state and mode (nearest or linear shadow-map filtering, at 1x or supersampled 2x) it draws the
wrist image three times: as is, without shadows, and without the shadow-casting light.  The
shadow factor of a pixel is ``(as is - no light) / (no shadows - no light)`` (1 lit, 0 in
shadow), where the light adds at least 24 levels (luminance).  It counts the pixels in
between (0.15 < f < 0.85: the ramp) and the hard steps (a pixel with f < 0.15 next to one with
f > 0.85), times a wrist image per mode, and writes ``OUT/wrist_shadow.json``,
``OUT/wrist_crops.png`` (per state, the modes side by side, 6x, around the edges with the most
steps) and ``OUT/wrist_full.png``.

On a GPU machine without rpg's dependencies (as lent in issue 32: Python 3.12, numpy, NVIDIA's
EGL vendor library but no libglvnd): the ``mujoco-core`` and ``PyOpenGL`` wheels unpacked onto
``PYTHONPATH`` (``model.mjb`` may be left behind: ``scene.xml`` names the meshes in the work
tree), and glvnd's ``libEGL.so.1``, ``libGLdispatch.so.0`` and ``libOpenGL.so.0`` on
``LD_LIBRARY_PATH``; ``MUJOCO_GL=egl``.
"""

from __future__ import annotations

import importlib.util
import json
import os
import struct
import sys
import time
import types
import zlib
from pathlib import Path

import numpy as np

os.environ.setdefault("MUJOCO_GL", "egl")

ROOT = Path(__file__).resolve().parents[1]
SIZE = 256
STATES = 8
MODES = {"nearest 1x": (False, 1, None), "linear 1x": (True, 1, None), "linear 2x, map 1024": (True, 2, 1024),
         "nearest 2x": (False, 2, None), "linear 2x": (True, 2, None), "linear 1x, map 4096": (True, 1, 4096),
         "linear 2x, map 4096": (True, 2, 4096)}
"""name: (linear shadow filtering, supersampling factor, shadow map side; None: rpg's for the
drawn size, :func:`rpg.env.render.shadow_map_size`: 1024 at 1x, 2048 at 2x)."""
LO, HI, MIN_LIGHT = 0.15, 0.85, 24.0


def export(out: Path) -> None:
    import mujoco

    import rpg  # noqa: F401  (sets MUJOCO_GL before mujoco loads)
    from rpg.domain.scene import SHADOW_RECEIVERS
    from rpg.env import BlockTaskEnv
    from rpg.env.embodiments.base import PREFIX
    from rpg.oracle.planner import Oracle

    out.mkdir(parents=True, exist_ok=True)
    env = BlockTaskEnv(ROOT / "library" / "stack_blocks", embodiment="panda", cameras=())
    env.reset(seed=0)
    oracle = Oracle(env)
    oracle.reset()
    states = []
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    for _ in range(env.max_episode_steps):
        state = np.empty(mujoco.mj_stateSize(env.model, spec))
        mujoco.mj_getState(env.model, env.data, state, spec)
        states.append(state)
        if env.step(oracle.act())[2]:
            break
    picks = np.linspace(0, len(states) - 1, STATES).round().astype(int)
    np.save(out / "states.npy", np.array([states[i] for i in picks]))
    mujoco.mj_saveModel(env.model, str(out / "model.mjb"), None)
    # the same scene as MJCF, meshes relative to DIR (for a machine with another MuJoCo version)
    rel = Path(*[".."] * len(out.resolve().relative_to(ROOT).parts))
    (out / "scene.xml").write_text(env.scene.spec.to_xml().replace(str(ROOT) + "/", rel.as_posix() + "/"))
    (out / "meta.json").write_text(json.dumps({"camera": PREFIX + "wrist", "receivers": list(SHADOW_RECEIVERS),
                                               "steps": picks.tolist(), "episode": len(states)}))
    env.close()
    print(f"wrote {out}: {len(picks)} states of {len(states)}")


def _render_module(receivers: list[str]):
    """rpg.env.render loaded by path, its import of rpg.domain.scene stubbed."""
    for name in ("rpg", "rpg.domain"):
        sys.modules.setdefault(name, types.ModuleType(name))
    scene = types.ModuleType("rpg.domain.scene")
    scene.SHADOW_RECEIVERS = tuple(receivers)
    sys.modules["rpg.domain.scene"] = scene
    spec = importlib.util.spec_from_file_location("rpg_render", ROOT / "src" / "rpg" / "env" / "render.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _png(path: Path, rgb: np.ndarray) -> None:
    h, w, _ = rgb.shape
    raw = b"".join(b"\0" + rgb[y].tobytes() for y in range(h))
    chunk = lambda tag, data: struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))  # noqa: E731
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                     + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def _luma(img: np.ndarray) -> np.ndarray:
    return img.astype(np.float64) @ np.array([0.299, 0.587, 0.114])


def shadow_factor(on: np.ndarray, off: np.ndarray, dark: np.ndarray) -> np.ndarray:
    """Per pixel, 1 lit .. 0 shadowed; NaN where the light adds too little to tell."""
    light = _luma(off) - _luma(dark)
    f = (_luma(on) - _luma(dark)) / np.where(light >= MIN_LIGHT, light, np.nan)
    return np.clip(f, 0.0, 1.0)


def edge_counts(f: np.ndarray) -> tuple[int, int, np.ndarray]:
    """(ramp pixels, hard steps, step map): pixels with LO < f < HI, and neighbour pairs
    (4-connected) that go from f < LO to f > HI directly."""
    ramp = int(np.sum((f > LO) & (f < HI)))
    dark, lit = f < LO, f > HI
    steps = np.zeros(f.shape, bool)
    h = (dark[:, :-1] & lit[:, 1:]) | (lit[:, :-1] & dark[:, 1:])
    v = (dark[:-1] & lit[1:]) | (lit[:-1] & dark[1:])
    steps[:, :-1] |= h
    steps[:-1] |= v
    return ramp, int(h.sum() + v.sum()), steps


def measure(src: Path, out: Path) -> None:
    import mujoco

    meta = json.loads((src / "meta.json").read_text())
    render = _render_module(meta["receivers"])
    model = None
    if (src / "model.mjb").is_file():  # left out where it would not fit a transfer
        try:
            model = mujoco.MjModel.from_binary_path(str(src / "model.mjb"))
        except Exception as exc:  # noqa: BLE001 - another MuJoCo version: compile the MJCF
            print(f"model.mjb: {exc}; compiling scene.xml")
    if model is None:
        model = mujoco.MjModel.from_xml_path(str(src / "scene.xml"))
    data = mujoco.MjData(model)
    states = np.load(src / "states.npy")
    key = next(i for i in range(model.nlight) if model.light_castshadow[i])
    renderers = {}

    def renderer_for(side, k):
        if (side, k) not in renderers:
            sized = render.shadow_map_size
            if side is not None:
                render.shadow_map_size = lambda h, w: side
            renderers[(side, k)] = render.CameraRenderer(model, SIZE, SIZE, supersample=k)
            render.shadow_map_size = sized
        return renderers[(side, k)]

    renderer = renderer_for(None, 1)
    out.mkdir(parents=True, exist_ok=True)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    shadow_flag = mujoco.mjtRndFlag.mjRND_SHADOW
    result = {"renderer": renderer.renderer_name(), "size": SIZE, "states": meta["steps"], "modes": {}}
    images = {}
    for mode, (soft, k, side) in MODES.items():
        renderer = renderer_for(side, k)
        ramps, steps, maps = [], [], []
        for i, state in enumerate(states):
            mujoco.mj_setState(model, data, state, spec)
            mujoco.mj_forward(model, data)
            on = renderer.image(data, meta["camera"], soft_shadows=soft, supersampled=k > 1)
            renderer.scene.flags[shadow_flag] = False  # image() sets the flags it owns; this one stays
            off = renderer.image(data, meta["camera"], soft_shadows=soft, supersampled=k > 1)
            renderer.scene.flags[shadow_flag] = True
            model.light_active[key] = 0
            dark = renderer.image(data, meta["camera"], soft_shadows=soft, supersampled=k > 1)
            model.light_active[key] = 1
            ramp, step, step_map = edge_counts(shadow_factor(on, off, dark))
            ramps.append(ramp)
            steps.append(step)
            maps.append(step_map)
            images[(mode, i)] = on
        # timing: the wrist image alone, as the environment draws it
        mujoco.mj_setState(model, data, states[len(states) // 2], spec)
        mujoco.mj_forward(model, data)
        for _ in range(3):
            renderer.image(data, meta["camera"], soft_shadows=soft, supersampled=k > 1)
        n = 30
        t = time.perf_counter()
        for _ in range(n):
            renderer.image(data, meta["camera"], soft_shadows=soft, supersampled=k > 1)
        ms = (time.perf_counter() - t) / n * 1e3
        result["modes"][mode] = {"shadow_map": int(renderer._mjr_context.shadowSize), "ramp_pixels": ramps,
                                 "hard_steps": steps, "ramp_total": sum(ramps), "steps_total": sum(steps),
                                 "ms_per_wrist_image": round(ms, 3)}
        if mode == "nearest 1x":
            steps_at = maps
    # crops: per state, the 48x48 window with the most hard steps (nearest 1x), the modes side by
    # side in MODES' order, 6x (nearest); one row per state in wrist_crops.png; the states' full
    # linear 1x images in wrist_full.png
    win, zoom, rows = 48, 6, []
    for i in range(len(states)):
        m = steps_at[i].astype(np.int64)
        c = np.cumsum(np.cumsum(np.pad(m, ((1, 0), (1, 0))), 0), 1)
        sums = c[win:, win:] - c[:-win, win:] - c[win:, :-win] + c[:-win, :-win]
        y, x = np.unravel_index(np.argmax(sums), sums.shape)
        tiles = [np.kron(images[(mode, i)][y:y + win, x:x + win], np.ones((zoom, zoom, 1), np.uint8)) for mode in MODES]
        gap = np.full((win * zoom, zoom, 3), 255, np.uint8)
        rows.append(np.concatenate([t for tile in tiles for t in (tile, gap)][:-1], axis=1))
        rows.append(np.full((zoom, rows[-1].shape[1], 3), 255, np.uint8))
    _png(out / "wrist_crops.png", np.concatenate(rows[:-1]))
    _png(out / "wrist_full.png", np.concatenate([images[("linear 1x", i)] for i in range(len(states))], axis=1))
    (out / "wrist_shadow.json").write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    for r in renderers.values():
        r.close()


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("export", "measure"):
        sys.exit("usage: bench_wrist_shadow.py export DIR | measure DIR [OUT]")
    if sys.argv[1] == "export":
        export(Path(sys.argv[2]))
    else:
        measure(Path(sys.argv[2]), Path(sys.argv[3] if len(sys.argv) > 3 else sys.argv[2]))
