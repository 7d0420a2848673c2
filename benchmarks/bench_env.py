"""Environment benchmark: control steps per second of rpg/BlockTask-v0 for each embodiment.

State-only, and the overhead against a raw ``mj_step`` loop of the same model and substeps
(issue 14 targets on a 2-core CPU: state-only >= 300 steps/s for the floating gripper, >= 150
for the Panda; overhead <= 1.5x).

With two 256x256 cameras (agentview + wrist), side by side in this one run (issue 32): the
robot's stock Menagerie meshes (``visual="stock"``) against the decimated ones (the default),
both replaying the same oracle episode (recorded once without cameras: the physics is the
same, so are the states), timed in alternating blocks so that a busy neighbour slows both
alike; the ratio of their control steps/s, and the SSIM of every camera's images (decimated
against stock, the same state; scikit-image) over the episode (target: ratio >= 3 and SSIM
>= 0.95 for the Panda).  The same again with the wrist camera supersampled 2x
(``wrist_supersample=2``), and what the supersampling costs.  The OpenGL renderer is named in the table (Mesa's llvmpipe on a
machine without a GPU; EGL on a GPU where one is lent).

    python benchmarks/bench_env.py [--quick]
"""

import sys
import time
from pathlib import Path

import numpy as np
from _report import report

import rpg  # noqa: F401  (sets MUJOCO_GL=egl before mujoco loads: mujoco is imported after it)
from rpg.domain import constants as C
from rpg.env import BlockTaskEnv

TASK = Path(__file__).resolve().parents[1] / "library" / "stack_blocks"
TARGETS = {"floating_gripper": 300, "panda": 150}
CAMERAS = ("agentview", "wrist")
QUICK = "--quick" in sys.argv
BLOCK = 8 if QUICK else 15
"""Control steps per timed block with cameras."""
ROUNDS = 3 if QUICK else 7
"""Timed blocks per variant (alternating)."""


def control_rate(env: BlockTaskEnv, steps: int, record: list | None = None) -> float:
    """Control steps per second of ``env.step`` under gentle seeded random actions; ``record``
    receives the actuator and mocap targets of every step (for :func:`raw_rate`)."""
    env.reset(seed=0)
    env.action_space.seed(0)
    actions = [env.action_space.sample() * 0.2 for _ in range(steps)]
    data = env.data
    t = time.perf_counter()
    for a in actions:
        env.step(a)
        if record is not None:
            record.append((data.ctrl.copy(), data.mocap_pos.copy(), data.mocap_quat.copy()))
    return steps / (time.perf_counter() - t)


def raw_rate(env: BlockTaskEnv, targets: list) -> float:
    """Control steps per second of a bare ``mj_step`` loop of the same model and substeps that
    replays the environment's recorded targets (the same motion, so the same contacts)."""
    import mujoco

    env.reset(seed=0)
    model, data = env.model, env.data
    t = time.perf_counter()
    for ctrl, mpos, mquat in targets:
        data.ctrl[:] = ctrl
        data.mocap_pos[:] = mpos
        data.mocap_quat[:] = mquat
        mujoco.mj_step(model, data, nstep=C.CONTROL_SUBSTEPS)
    return len(targets) / (time.perf_counter() - t)


def oracle_actions(embodiment: str) -> list[np.ndarray]:
    """The oracle's actions of seed 0's episode, recorded without cameras."""
    from rpg.oracle.planner import Oracle

    env = BlockTaskEnv(TASK, embodiment=embodiment, cameras=())
    env.reset(seed=0)
    oracle = Oracle(env)
    oracle.reset()
    actions = []
    for _ in range(env.max_episode_steps):
        a = oracle.act()
        actions.append(a)
        if env.step(a)[2]:
            break
    env.close()
    return actions


def timed_block(env: BlockTaskEnv, state: np.ndarray, actions: list) -> float:
    """Control steps per second of ``actions`` from ``state`` (``env.get_state()``: restored
    exactly; the reset renders once, after the switch of OpenGL context)."""
    env.reset(options={"state": state})
    t = time.perf_counter()
    for a in actions:
        env.step(a)
    return len(actions) / (time.perf_counter() - t)


VARIANTS = {"stock meshes": {"visual": "stock"}, "decimated meshes": {"visual": "decimated"},
            "stock meshes, wrist 2x": {"visual": "stock", "wrist_supersample": 2},
            "decimated meshes, wrist 2x": {"visual": "decimated", "wrist_supersample": 2}}
"""The environments timed side by side: the meshes, and the wrist camera drawn as is or
supersampled 2x (anti-aliased shadow edges; ``BlockTaskEnv(wrist_supersample=2)``)."""


def cameras_side_by_side(embodiment: str) -> list[tuple]:
    from skimage.metrics import structural_similarity

    actions = oracle_actions(embodiment)
    envs = {v: BlockTaskEnv(TASK, embodiment=embodiment, cameras=CAMERAS, image_size=(256, 256), **kw)
            for v, kw in VARIANTS.items()}
    stock, dec, stock2, dec2 = VARIANTS
    pairs = {"": (stock, dec), ", wrist 2x": (stock2, dec2)}
    # images: all replay the episode; SSIM of each camera's frames (every 4th step), decimated
    # against stock with the same wrist setting
    starts = set(np.linspace(0, max(0, len(actions) - BLOCK), ROUNDS).astype(int).tolist())
    states, ssim = {}, {(c, tag): [] for c in CAMERAS for tag in pairs}
    obs = {v: e.reset(seed=0)[0] for v, e in envs.items()}
    for k, a in enumerate(actions):
        if k in starts:
            states[k] = envs[stock].unwrapped.get_state()
        if k % 4 == 0:
            for c in CAMERAS:
                for tag, (one, other) in pairs.items():
                    ssim[(c, tag)].append(structural_similarity(obs[one][f"{c}_image"], obs[other][f"{c}_image"],
                                                                channel_axis=2, data_range=255))
        obs = {v: e.step(a)[0] for v, e in envs.items()}
    # speed: alternating blocks along the episode (where the arm moves, grasps and places)
    rates = {v: [] for v in envs}
    for i, start in enumerate(sorted(states)):
        for v in (list(envs) if i % 2 == 0 else list(envs)[::-1]):
            rates[v].append(timed_block(envs[v], states[start], actions[start:start + BLOCK]))
    renderer = envs[dec].unwrapped._renderer.renderer_name()
    for e in envs.values():
        e.close()

    def paired(a: str, b: str) -> float:
        return float(np.median(np.array(rates[a]) / np.array(rates[b])))

    rows = [(f"{embodiment}: 2 cameras 256x256, {v}", float(np.median(rates[v])), "steps/s", "")
            for v in envs]
    target = ">= 3" if embodiment == "panda" else ""
    rows += [
        (f"{embodiment}: decimated / stock (same run, paired blocks)", paired(dec, stock), "x", target),
        (f"{embodiment}: decimated / stock, both wrist 2x", paired(dec2, stock2), "x", target),
        (f"{embodiment}: decimated wrist 2x / stock wrist 1x", paired(dec2, stock), "x", ""),
        (f"{embodiment}: cost of the wrist 2x, decimated (1x / 2x steps/s)", paired(dec, dec2), "x", ""),
    ]
    for tag in pairs:
        for c in CAMERAS:
            values = ssim[(c, tag)]
            rows.append((f"{embodiment}: SSIM {c}{tag}, decimated vs stock (min of {len(values)})",
                         float(np.min(values)), "", ">= 0.95" if embodiment == "panda" else ""))
            rows.append((f"{embodiment}: SSIM {c}{tag}, mean", float(np.mean(values)), "", ""))
    rows.append((f"{embodiment}: renderer {renderer}", float(len(actions)), "oracle steps", ""))
    return rows


rows = []
for name, target in TARGETS.items():
    env = BlockTaskEnv(TASK, embodiment=name, cameras=())
    control_rate(env, 20)  # warm up (IK solver, caches)
    # env and raw loops interleaved, so that a noisy neighbour slows both alike
    targets: list = []
    control_rate(env, 100, targets)
    pairs = [(control_rate(env, 100), raw_rate(env, targets)) for _ in range(3 if QUICK else 7)]
    state_only = float(np.median([p[0] for p in pairs]))
    raw = float(np.median([p[1] for p in pairs]))
    overhead = float(np.median([r / e for e, r in pairs]))
    env.close()
    rows += [
        (f"{name}: state-only control steps", state_only, "steps/s", f">= {target}"),
        (f"{name}: raw mj_step loop ({C.CONTROL_SUBSTEPS} substeps)", raw, "steps/s", ""),
        (f"{name}: overhead vs raw physics, state-only", overhead, "x", "<= 1.5"),
    ]
    rows += cameras_side_by_side(name)
report("env", rows)
