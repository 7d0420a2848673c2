"""The MuJoCo Menagerie Franka Emika Panda, driven by differential inverse kinematics.

Cartesian actions (``ee_delta``, ``ee_abs``) become joint targets through ``mink``: a
:class:`mink.FrameTask` on the TCP site, a :class:`mink.PostureTask` toward the home pose
(it resolves the arm's redundancy) and :class:`mink.ConfigurationLimit`, solved with
``daqp`` on a separate robot-only model, integrated over one control period.  The arm's
position actuators (Menagerie gains) then track those targets for the control step, with
gravity compensation on every link.  Measured with these settings (issue 14): two 4 cm
cubes stacked 100/100.
"""

from __future__ import annotations

import daqp
import mujoco
import numpy as np

from rpg.domain import constants as C
from rpg.env.embodiments.base import (
    PREFIX,
    Embodiment,
    TcpPose,
    cartesian_target,
    load_robot_spec,
    prepare_hand,
)

ARM_JOINTS = tuple(f"joint{i}" for i in range(1, 8))
"""The arm's seven revolute joints, base to wrist."""

IK_POSTURE_COST = 1e-2
"""Weight of the posture task relative to the TCP task (mink units: per rad)."""

IK_DAMPING = 1e-3
"""Levenberg-Marquardt damping of the IK least squares."""


def _robot_spec(visual: str = "stock") -> mujoco.MjSpec:
    spec = load_robot_spec("panda.xml", visual)
    prepare_hand(spec, C.GRIPPER_GAIN)
    spec.body("link0").pos = list(C.ROBOT_BASE_POS)
    return spec


def _ik_model() -> mujoco.MjModel:
    """The arm alone (7 joints, the hand as a rigid end with its TCP site, no fingers, no
    geoms): what the IK needs, at the same base pose as in the scene."""
    spec = _robot_spec()
    for el in [*spec.actuators, *spec.tendons, *spec.equalities, *spec.excludes]:
        spec.delete(el)
    for finger in ("left_finger", "right_finger"):
        spec.delete(spec.body(finger))
    for el in [*spec.geoms, *spec.meshes]:
        spec.delete(el)
    return spec.compile()


class Panda(Embodiment):
    """Franka Emika Panda (7 joints, Menagerie hand) on a fixed base at
    :data:`~rpg.domain.constants.ROBOT_BASE_POS`.

    Control modes: ``ee_delta``, ``ee_abs`` (through IK) and ``joint_pos`` (7 joint
    targets, rad, plus the gripper).
    """

    NAME = "panda"
    CONTROL_MODES = ("ee_delta", "ee_abs", "joint_pos")
    INTERPOLATION_POINTS = C.JOINT_INTERPOLATION_POINTS

    def __init__(self, visual: str = "decimated") -> None:
        import mink  # (here: the state-only and floating-gripper paths never pay its import, a quarter of a second)

        super().__init__(visual)
        self.ik_model = _ik_model()
        self.configuration = mink.Configuration(self.ik_model)
        self.tcp_task = mink.FrameTask("tcp", "site", position_cost=1.0, orientation_cost=1.0, lm_damping=1e-6)
        self.posture = mink.PostureTask(self.ik_model, cost=IK_POSTURE_COST)
        self.posture.set_target(np.array(C.HOME_QPOS))
        self.limit = mink.ConfigurationLimit(self.ik_model)
        self._no_rows = np.zeros((0, self.ik_model.nv))
        self._bound_sense = np.zeros(self.ik_model.nv, dtype=np.int32)
        self.joint_low = self.ik_model.jnt_range[:7, 0].copy()
        self.joint_high = self.ik_model.jnt_range[:7, 1].copy()
        self._from = self._to = None

    def attach(self, spec: mujoco.MjSpec) -> None:
        frame = spec.worldbody.add_frame()
        spec.attach(_robot_spec(self.visual), prefix=PREFIX, frame=frame)

    def _bind(self) -> None:
        m = self.model
        self.arm_qpos = np.array([m.jnt_qposadr[m.joint(PREFIX + j).id] for j in ARM_JOINTS])
        self.arm_qvel = np.array([m.jnt_dofadr[m.joint(PREFIX + j).id] for j in ARM_JOINTS])
        self.arm_act = np.array([m.actuator(PREFIX + f"actuator{i}").id for i in range(1, 8)])

    def home(self) -> None:
        d = self.data
        d.qpos[self.arm_qpos] = C.HOME_QPOS
        d.qvel[self.arm_qvel] = 0.0
        d.ctrl[self.arm_act] = C.HOME_QPOS
        self._open_gripper()
        self._from = self._to = None

    def robot_qpos(self) -> np.ndarray:
        return np.concatenate([self.data.qpos[self.arm_qpos], self.data.qpos[self.finger_qpos]])

    def robot_qvel(self) -> np.ndarray:
        return np.concatenate([self.data.qvel[self.arm_qvel], self.data.qvel[self.finger_qvel]])

    def state_index(self) -> tuple[np.ndarray, np.ndarray]:
        return np.concatenate([self.arm_qpos, self.finger_qpos]), np.concatenate([self.arm_qvel, self.finger_qvel])

    def hold_targets(self) -> None:
        """The arm's position targets (which the next step interpolates from; a MuJoCo
        physics state does not hold them) estimated from the measured joints q and
        velocities: ``q + (kv + damping) / kp * qdot``, where the actuator's PD force
        ``kp (target - q) - kv qdot`` balances the joint's damping (zero acceleration; gravity
        is compensated).  Measured on an oracle episode of ``stack_blocks``: a replay's next
        state 0.0026 from the recorded one at worst (0.047 with the targets at q)."""
        super().hold_targets()
        m, d = self.model, self.data
        kp = m.actuator_gainprm[self.arm_act, 0]
        kv = -m.actuator_biasprm[self.arm_act, 2]
        damping = m.dof_damping[self.arm_qvel]
        d.ctrl[self.arm_act] = d.qpos[self.arm_qpos] + (kv + damping) / kp * d.qvel[self.arm_qvel]

    def solve_ik(self, target: TcpPose) -> np.ndarray:
        """Joint targets (7,) rad that move the TCP toward ``target`` within one control period.

        The measured joints are clipped into their limits first (contact can push a joint a
        hair past one, which the QP would reject); where the QP has no solution the arm keeps
        its current targets.  mink builds the QP's objective, daqp solves it directly with the
        joint limits as bounds (``mink.solve_ik`` spent half its time re-checking limits and in
        qpsolvers' conversions).
        """
        import mink

        q = np.clip(self.data.qpos[self.arm_qpos], self.joint_low + 1e-6, self.joint_high - 1e-6)
        self.configuration.update(q)
        self.tcp_task.set_target(mink.SE3.from_rotation_and_translation(mink.SO3(target.quat), target.pos))
        dt = 1.0 / C.CONTROL_HZ
        # min 0.5 dq' P dq + q' dq  subject to mink's ConfigurationLimit, which for revolute
        # joints is the box gain * (q_min - q) <= dq <= gain * (q_max - q): daqp takes it as
        # simple bounds (a 14-row inequality matrix built per step cost as much as the rest).
        problem = mink.build_ik(self.configuration, [self.tcp_task, self.posture], dt, IK_DAMPING, [])
        lim = self.limit
        dq, _, exitflag, _ = daqp.solve(problem.P, problem.q, self._no_rows, lim.gain * (lim.upper - q),
                                        lim.gain * (lim.lower - q), self._bound_sense)
        if exitflag < 1:
            return self.data.ctrl[self.arm_act].copy()
        self.configuration.integrate_inplace(dq / dt, dt)
        return self.configuration.q.copy()

    def command(self, mode: str, action: np.ndarray) -> None:
        if mode == "joint_pos":
            q = np.clip(action[:7], self.joint_low, self.joint_high)
        else:
            q = self.solve_ik(cartesian_target(self.tcp_pose(), mode, action))
        self._from, self._to = self.data.ctrl[self.arm_act].copy(), q
        self.data.ctrl[self.gripper_act] = self.gripper_ctrl(action[-1])

    def substep(self, k: int, n: int) -> None:
        """The joint targets move from the last control step's to this one's in ``n`` equal
        increments, as a robot's controller interpolates a 20 Hz policy: a target that jumps
        once per step jerks the hand (the oracle, 4 dense or pile tasks x 5 seeds: 16/20
        episodes with five increments, 10/20 with one jump)."""
        if self._to is None:
            return
        self.data.ctrl[self.arm_act] = self._from + (k + 1) / n * (self._to - self._from)
