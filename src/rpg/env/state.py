"""Saving and restoring an environment's state: ``env.get_state()`` and
``env.reset(options={"state": ...})``.

A state is one of:

- a **MuJoCo state row**, float (S,): ``mj_getState`` of the scene with one of
  :data:`STATE_SPECS`, told apart by its length:

  - :data:`ENV_STATE` (``mjSTATE_INTEGRATION``: time, qpos, qvel, mocap poses, actuator
    commands, solver warm start...), what :meth:`rpg.env.BlockTaskEnv.get_state` returns:
    restoring it and replaying the same actions reproduces the episode exactly;
  - :data:`RECORDED_STATE` (``mjSTATE_FULLPHYSICS``: time, qpos, qvel, mocap poses; no
    actuator commands), what ``rpg demos --format hdf5`` records per step in robomimic's
    ``states`` (:data:`rpg.demos.record.SIM_STATE`).  The floating gripper's target is a
    mocap body, so it is in the row and a replay reproduces the recording (measured: next
    states within 1e-8).  The Panda's joint targets are actuator commands, not physics:
    they are estimated from its joints and velocities
    (:meth:`rpg.env.embodiments.panda.Panda.hold_targets`), and a step after the restore
    differs from the recorded one by that estimate's error (measured on ``stack_blocks``:
    up to 0.003 rad or m in a coordinate of the next state, median 0.0003; the episode ends
    the same way).  For exact Panda replays keep :meth:`~rpg.env.BlockTaskEnv.get_state`'s
    rows;

- an **observation dict**, what a LeRobot dataset records per step with ``--columns
  joint_pos,object_poses``: ``{"qpos": (9,), "object_poses": (N, 7) or (7 N,), "qvel":
  optional}``, laid out as the observation's ``qpos`` (the robot's joints:
  ``rpg.demos.record.JOINT_NAMES``), ``object_poses`` (position m and quaternion w, x, y, z
  per object, objects in ``env.unwrapped.object_names`` order) and ``qvel`` (the robot's;
  absent: at rest).  Objects are set at rest and time at 0; the robot's actuators hold its
  pose.  Velocities of objects are not recorded there, so a replay from such a state is
  approximate.

Restoring recomputes the derived quantities the environment reads between steps (TCP pose,
contacts) where ``mj_step`` left them: at the pose one physics step before (``mj_step``
computes them before it integrates, so an observation after a step reads the TCP one 2 ms
physics step behind qpos).  With them computed at qpos instead, a replay's first step
differed from the recording by up to 3 mm.

The episode restarts: ``elapsed_steps`` 0, the full step budget, a temporal goal's order
monitor fresh (the events before the restored state are not part of any state).  A state in
which G already holds is accepted (``info["success"]`` says so).
"""

from __future__ import annotations

from collections.abc import Mapping

import mujoco
import numpy as np

ENV_STATE = mujoco.mjtState.mjSTATE_INTEGRATION
"""What :meth:`rpg.env.BlockTaskEnv.get_state` returns: everything MuJoCo integrates from."""

RECORDED_STATE = mujoco.mjtState.mjSTATE_FULLPHYSICS
"""What ``rpg demos`` records per step (robomimic's ``states``): the physics without actuator
commands or warm start."""

STATE_SPECS = (ENV_STATE, RECORDED_STATE)
"""The ``mj_getState`` layouts a state row may have."""

DICT_KEYS = ("qpos", "qvel", "object_poses")
"""Keys of an observation-dict state (``qvel`` optional)."""

QUAT_TOL = 1e-3
"""How far from 1 a quaternion's norm may be in a restored state (float32 rounding is ~1e-7):
further means the values are not a pose of this scene."""


def capture(env) -> np.ndarray:
    """``env``'s current state, float64 (S,): ``mj_getState`` with :data:`ENV_STATE`."""
    out = np.empty(mujoco.mj_stateSize(env.model, ENV_STATE))
    mujoco.mj_getState(env.model, env.data, out, ENV_STATE)
    return out


def _quat_slices(model: mujoco.MjModel) -> list[tuple[str, int]]:
    """(joint name, qpos address of its quaternion) for every free and ball joint."""
    out = []
    for j in range(model.njnt):
        kind = model.jnt_type[j]
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            out.append((model.joint(j).name, int(model.jnt_qposadr[j]) + 3))
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            out.append((model.joint(j).name, int(model.jnt_qposadr[j])))
    return out


def _check_quats(where: str, quats: list[tuple[str, np.ndarray]]) -> None:
    for name, q in quats:
        norm = float(np.linalg.norm(q))
        if abs(norm - 1.0) > QUAT_TOL:
            raise ValueError(f"{where}: the quaternion of {name!r} has norm {norm:.6g}, not 1; the values are "
                             "not a pose of this scene (a state of another task or embodiment, or shifted columns?)")


def _finite(where: str, values: np.ndarray) -> np.ndarray:
    if not np.all(np.isfinite(values)):
        raise ValueError(f"{where} holds non-finite values (NaN or inf) at index {int(np.argmin(np.isfinite(values)))}")
    return values


def _array(where: str, value) -> np.ndarray:
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{where} must be numbers, not {type(value).__name__}") from None
    return _finite(where, a)


def _row_spec(env, row: np.ndarray) -> mujoco.mjtState:
    sizes = {int(mujoco.mj_stateSize(env.model, s)): s for s in reversed(STATE_SPECS)}
    if row.ndim != 1 or row.size not in sizes:
        want = " or ".join(f"{n} ({sizes[n].name})" for n in sorted(sizes))
        raise ValueError(f"state row has shape {row.shape}; this environment's ({env.source.name}, {env.robot.NAME}) "
                         f"MuJoCo state has {want} values: was it recorded with another task or embodiment? "
                         "(a dict state needs keys qpos and object_poses)")
    return sizes[row.size]


def _restore_row(env, row: np.ndarray) -> None:
    model, data = env.model, env.data
    spec = _row_spec(env, row)
    scratch = mujoco.MjData(model)  # checked before anything of env changes
    mujoco.mj_setState(model, scratch, row, spec)
    _check_quats("state", [(n, scratch.qpos[a:a + 4]) for n, a in _quat_slices(model)]
                 + [(f"mocap body {k}", scratch.mocap_quat[k]) for k in range(model.nmocap)])
    mujoco.mj_resetData(model, data)
    mujoco.mj_setState(model, data, row, spec)
    env.robot.hold_targets()
    if spec == ENV_STATE:
        data.ctrl[:] = scratch.ctrl  # the recorded commands, not the held pose
    _stale_kinematics(model, data, keep_warmstart=spec == ENV_STATE)


def _stale_kinematics(model: mujoco.MjModel, data: mujoco.MjData, keep_warmstart: bool) -> None:
    """Derived quantities as ``mj_step`` leaves them: computed at qpos one physics step
    before (semi-implicit Euler and the implicit integrators advance qpos by
    ``timestep * qvel`` with the new qvel, so that pose is qpos integrated by ``-timestep``);
    without a recorded warm start, the solver's is that state's acceleration."""
    if model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4:
        mujoco.mj_forward(model, data)
        return
    qpos, warm = data.qpos.copy(), data.qacc_warmstart.copy()
    mujoco.mj_integratePos(model, data.qpos, data.qvel, -model.opt.timestep)
    mujoco.mj_forward(model, data)
    data.qpos[:] = qpos
    data.qacc_warmstart[:] = warm if keep_warmstart else data.qacc


def _restore_dict(env, state: Mapping) -> None:
    model, data, robot = env.model, env.data, env.robot
    unknown = sorted(map(str, set(state) - set(DICT_KEYS)))
    if unknown:
        raise ValueError(f"state has unknown key(s) {', '.join(map(repr, unknown))}; a dict state has "
                         f"{', '.join(DICT_KEYS)} (qvel optional)")
    missing = [k for k in ("qpos", "object_poses") if k not in state]
    if missing:
        raise ValueError(f"state has no {' and no '.join(missing)}: a dict state needs the robot's qpos "
                         "(as observation['qpos']) and every object's pose (as observation['object_poses'])")
    qi, vi = robot.state_index()
    qpos = _array("state['qpos']", state["qpos"]).reshape(-1)
    if qpos.shape != qi.shape:
        raise ValueError(f"state['qpos'] has {qpos.size} values; {robot.NAME}'s qpos has {qi.size} "
                         "(observation['qpos']: the robot's joints, not the whole scene's)")
    qvel = None
    if state.get("qvel") is not None:
        qvel = _array("state['qvel']", state["qvel"]).reshape(-1)
        if qvel.shape != vi.shape:
            raise ValueError(f"state['qvel'] has {qvel.size} values; {robot.NAME}'s qvel has {vi.size}")
    names = env.object_names
    poses = _array("state['object_poses']", state["object_poses"])
    if poses.size != 7 * len(names) or poses.ndim not in (1, 2) or (poses.ndim == 2 and poses.shape[1] != 7):
        raise ValueError(f"state['object_poses'] has shape {poses.shape}; {env.source.name} has {len(names)} "
                         f"objects ({', '.join(names)}): give ({len(names)}, 7) or ({7 * len(names)},), position "
                         "and quaternion (w, x, y, z) each, in that order")
    poses = poses.reshape(len(names), 7)
    scratch = mujoco.MjData(model)
    scratch.qpos[qi] = qpos
    _check_quats("state['qpos']", [(n, scratch.qpos[a:a + 4]) for n, a in _quat_slices(model) if a in set(qi)])
    _check_quats("state['object_poses']", list(zip(names, poses[:, 3:], strict=True)))
    mujoco.mj_normalizeQuat(model, scratch.qpos)
    mujoco.mj_resetData(model, data)
    robot.set_robot_state(scratch.qpos[qi], qvel)
    for name, row in zip(names, poses, strict=True):
        env.scene.set_pose(name, row[:3], row[3:])  # normalizes the quaternion
    mujoco.mj_forward(model, data)


def restore(env, state) -> None:
    """Set ``env``'s simulation to ``state`` (see the module docstring for the forms).

    Nothing of ``env`` changes when the state is refused.

    Raises:
        ValueError: a state of the wrong type, length or shape, with unknown or missing
            keys, non-finite values or quaternions that are not unit (the message names
            the problem and what this environment expects).
    """
    if isinstance(state, Mapping):
        _restore_dict(env, state)
    elif isinstance(state, (str, bytes)) or state is None:
        raise ValueError(f"state must be a MuJoCo state row (env.get_state(), robomimic's states[t]) or a dict "
                         f"with {', '.join(DICT_KEYS)}, not {type(state).__name__}")
    else:
        _restore_row(env, _array("state", state))
