"""Environment benchmark: control steps per second of rpg/BlockTask-v0 for each embodiment,
state-only and with two 256x256 cameras, and the overhead against a raw ``mj_step`` loop of
the same model and substeps (issue 14 targets on a 2-core CPU: state-only >= 300 steps/s for
the floating gripper, >= 150 for the Panda; overhead <= 1.5x)."""

import time
from pathlib import Path

import mujoco
import numpy as np
from _report import report

import rpg  # noqa: F401  (sets MUJOCO_GL=egl before mujoco loads)
from rpg.domain import constants as C
from rpg.env import BlockTaskEnv

TASK = Path(__file__).resolve().parents[1] / "library" / "stack_blocks"
TARGETS = {"floating_gripper": 300, "panda": 150}


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
    env.reset(seed=0)
    model, data = env.model, env.data
    t = time.perf_counter()
    for ctrl, mpos, mquat in targets:
        data.ctrl[:] = ctrl
        data.mocap_pos[:] = mpos
        data.mocap_quat[:] = mquat
        mujoco.mj_step(model, data, nstep=C.CONTROL_SUBSTEPS)
    return len(targets) / (time.perf_counter() - t)


rows = []
for name, target in TARGETS.items():
    env = BlockTaskEnv(TASK, embodiment=name, cameras=())
    control_rate(env, 20)  # warm up (IK solver, caches)
    # env and raw loops interleaved, so that a noisy neighbour slows both alike
    targets: list = []
    control_rate(env, 100, targets)
    pairs = [(control_rate(env, 100), raw_rate(env, targets)) for _ in range(7)]
    state_only = float(np.median([p[0] for p in pairs]))
    raw = float(np.median([p[1] for p in pairs]))
    overhead = float(np.median([r / e for e, r in pairs]))
    env.close()
    cams = BlockTaskEnv(TASK, embodiment=name, cameras=("agentview", "wrist"), image_size=(256, 256))
    control_rate(cams, 3)
    with_cameras = control_rate(cams, 30)
    cams.close()
    rows += [
        (f"{name}: state-only control steps", state_only, "steps/s", f">= {target}"),
        (f"{name}: 2 cameras 256x256 control steps", with_cameras, "steps/s", ""),
        (f"{name}: raw mj_step loop ({C.CONTROL_SUBSTEPS} substeps)", raw, "steps/s", ""),
        (f"{name}: overhead vs raw physics, state-only", overhead, "x", "<= 1.5"),
    ]
report("env", rows)
