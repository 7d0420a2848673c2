"""``rpg/BlockTask-v0``: every compiled task as a Gymnasium environment with a robot.

    import gymnasium as gym
    import rpg.env  # registers rpg/BlockTask-v0

    env = gym.make("rpg/BlockTask-v0", task="library/stack_blocks", embodiment="panda",
                   control_mode="ee_delta", cameras=("agentview", "wrist"), image_size=(256, 256))
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

**Task Description.**  The compiled task's instruction (as written; the canonical statement
of G with ``instruction="canonical"``; paraphrase K with ``instruction="paraphrase:K"``), over the task's cubes and goal patches on the table, with a
robot (``embodiment``): ``panda`` (Menagerie Franka Panda on a fixed base) or
``floating_gripper`` (the Franka hand on a mocap weld).

**Randomizations.**  ``reset(seed=s)`` samples the task's initial-state distribution rho_0
with ``numpy.random.default_rng(s)``: the same initial state ``rpg inspect --seed s``,
validation and every other ``rpg`` command use for seed ``s``.  The robot starts at its
home pose (TCP above the front of the workspace, gripper open, pointing down); then
:data:`~rpg.domain.constants.RESET_SETTLE_STEPS` physics steps settle the scene.
``reset()`` without a seed draws one from the environment's generator.
``reset(options={"state": s})`` starts instead from a state ``env.get_state()`` returned or
``rpg demos`` recorded (:mod:`rpg.env.state`): a policy evaluated from a dataset's states.

**Success Conditions.**  ``info["success"]``: the task's success predicate G holds and the
gripper holds no cube (both fingers touching it), as ManiSkill3 defines success.  A temporal
goal ("first A, then B") also needs its events to have first held in that order during the
episode (:class:`~rpg.domain.predicates.TemporalMonitor`, updated every step).  The
episode terminates on success (``terminate_on_success``) and is truncated after
``max_episode_steps = EPISODE_BASE_STEPS + EPISODE_STEPS_PER_CUBE * movable cubes
+ EPISODE_STEPS_PER_PUSH * dense cubes`` control steps (a dense cube's goal touches a neighbour
in its layer: it is pushed into place).  Reward: 1.0 on a successful step, else 0.0 (sparse).

**Control** at :data:`~rpg.domain.constants.CONTROL_HZ` (20 Hz; 25 physics steps of 2 ms).
Actions are float32 and apply to the *measured* TCP pose (not to the last target):

- ``ee_delta`` (7,): ``[dx, dy, dz, droll, dpitch, dyaw, gripper]`` in [-1, 1].  Position
  moves ``EE_DELTA_POS_LIMIT`` (0.05 m) per unit along world axes; rotation is a rotation
  vector of ``EE_DELTA_ROT_LIMIT`` (0.5 rad) per unit about world axes, applied on the left
  of the measured orientation.  As in robosuite and LIBERO.
- ``ee_abs`` (7,): ``[x, y, z, rx, ry, rz, gripper]``: TCP position in the world frame (m)
  and orientation as an axis-angle vector (rad).
- ``joint_pos`` (8,, Panda only): seven joint targets (rad) and the gripper.

``gripper``: -1 open, +1 closed (actuator command ``255 * (1 - g) / 2``; a held cube is
released at ``g <= -0.41``, command >= 180).

**Observations** (a dict; the world frame of :mod:`rpg.domain.constants`):

- ``<camera>_image``: uint8 (H, W, 3) for each of ``cameras`` (``agentview``: over the
  robot's shoulder; ``wrist``: on the hand, looking along the approach axis; ``default``:
  the snapshot camera);
- ``state``: float64 (8,): TCP position (m), TCP orientation as axis-angle (rad), the two
  finger openings (m): LIBERO's ``[eef_pos, eef_axis_angle, gripper_qpos]``;
- ``qpos`` / ``qvel``: float64, the robot's joint positions and velocities (Panda: 7 arm +
  2 fingers, (9,) and (9,); floating gripper: free joint + 2 fingers, (9,) and (8,));
- ``object_poses`` (only with ``privileged=True``): float64 (N, 7), each object's position
  and quaternion (w, x, y, z), objects in sorted name order (``env.unwrapped.object_names``);
- ``instruction``: the instruction text the policy is given.

**info**: ``success``, ``goal_satisfied`` (G alone), ``is_grasped``, ``grasped`` (object
name or ""), ``diagnostics`` (``{"satisfied": [...], "unsatisfied": [...]}``: one line per
leaf predicate, BDDL-style), ``progress`` (the fraction of those leaves that hold, in [0, 1]:
a structure's leaves are its members, e.g. one per cube of a stack, so a tower with 5 of 6
cubes placed scores 5/6; a temporal goal's order counts as one more leaf), ``elapsed_steps``,
``seed``, ``task_hash``, ``instruction``.

``env.spec.max_episode_steps`` is the task's own limit (it depends on the task, so the
registered id has none); the environment truncates the episode itself.
"""

from __future__ import annotations

import string
from collections.abc import Sequence
from pathlib import Path

import gymnasium as gym
import mujoco
import numpy as np
from gymnasium import spaces

from rpg.domain import constants as C
from rpg.domain.layouts import dense_cubes, out_of_bounds
from rpg.domain.predicates import InOrder
from rpg.env.embodiments import make_embodiment
from rpg.env.embodiments.base import PREFIX, EmbodimentError, quat_to_axis_angle
from rpg.env.loading import PreparedTask, TaskSource, load_env_task
from rpg.env.render import SOFT_SHADOW_CAMERAS, SUPERSAMPLE_FACTORS, CameraRenderer
from rpg.errors import TaskInvalid

CAMERAS = ("agentview", "wrist", "default")
"""Cameras an environment can observe."""


def episode_step_limit(n_cubes: int, n_dense: int = 0) -> int:
    """Control steps of an episode of a task with ``n_cubes`` movable cubes, ``n_dense`` of them
    in a dense goal layout (documented rule, :data:`~rpg.domain.constants.EPISODE_STEPS_PER_PUSH`)."""
    return C.EPISODE_BASE_STEPS + C.EPISODE_STEPS_PER_CUBE * max(1, n_cubes) + C.EPISODE_STEPS_PER_PUSH * n_dense


INSTRUCTION_MODES = ("original", "canonical", "paraphrase:K")
"""What ``instruction=`` picks: the instruction as written, the canonical statement of G
(generated from G, it states exactly what G checks), or paraphrase K."""


def _instruction(source: TaskSource, which: str) -> str:
    if which in ("original", "", None):
        return source.instruction
    if which == "canonical":
        return source.canonical or source.instruction
    head, _, k = str(which).partition(":")
    if head != "paraphrase" or not k.isdigit():
        raise EmbodimentError(f"instruction must be 'original', 'canonical' or 'paraphrase:K', not {which!r}")
    if int(k) >= len(source.paraphrases):
        raise EmbodimentError(f"{source.name} has {len(source.paraphrases)} paraphrases; "
                              f"'paraphrase:{k}' does not exist (they count from 0)")
    return source.paraphrases[int(k)]


class BlockTaskEnv(gym.Env):
    """A compiled block-domain task with a robot, as a :class:`gymnasium.Env`.

    Args:
        task: a task directory, family directory (its head) or ``FAMILY@vN``, or a
            :class:`rpg.env.loading.PreparedTask`; loaded through the checks of
            :mod:`rpg.env.loading` (task code runs only in the sandbox; G is rpg's own).
        embodiment: ``"panda"`` or ``"floating_gripper"``.
        control_mode: ``"ee_delta"``, ``"ee_abs"`` or ``"joint_pos"`` (Panda only).
        cameras: camera observations to render (``()`` for state only).
        image_size: (height, width) of camera images, pixels.
        instruction: ``"original"``, ``"canonical"`` or ``"paraphrase:K"`` (:data:`INSTRUCTION_MODES`).
        privileged: add ``object_poses`` to the observation.
        render_mode: None or ``"rgb_array"`` (``render()`` returns the agentview image).
        terminate_on_success: end the episode on the first successful step.
        max_episode_steps: override the task-size rule.
        visual: the robot's meshes in camera images: ``"decimated"`` (merged and simplified:
            the Panda's two 256x256 cameras ~4x faster on Mesa's software renderer) or
            ``"stock"`` (the Menagerie's); the physics is the same
            (:mod:`rpg.env.embodiments.visuals`).
        wrist_supersample: draw the wrist camera at this many times the image size (an
            integer factor per side) and reduce each k x k block of pixels to its mean (1,
            the default: no supersampling; 2: anti-aliased wrist shadow edges, 4x the wrist
            camera's pixels drawn and a 4x larger shadow map for it).  The wrist camera
            then has a renderer and OpenGL context of its own, so the other cameras' images
            are unchanged, byte for byte; it costs a second context's memory and, on a
            software renderer, a large share of the steps/s with cameras (README;
            ``benchmarks/bench_env.py``; :mod:`rpg.env.render`).

    Raises:
        EmbodimentError: unknown embodiment, visual, camera, control mode or instruction, or a
            ``wrist_supersample`` outside 1..4.
        BadInput / ArtifactError / TaskInvalid: the task cannot be loaded (see
            :func:`rpg.env.loading.load_env_task`).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": int(C.CONTROL_HZ)}

    @property
    def spec(self):
        """The registered spec with this task's ``max_episode_steps`` (None outside ``gym.make``)."""
        import dataclasses

        base = self.__dict__.get("_spec")
        if base is None or "max_episode_steps" not in self.__dict__:
            return base
        return dataclasses.replace(base, max_episode_steps=self.max_episode_steps)

    @spec.setter
    def spec(self, value) -> None:
        self.__dict__["_spec"] = value

    def __init__(self, task: str | Path | PreparedTask, embodiment: str = "panda", control_mode: str = "ee_delta",
                 cameras: Sequence[str] = ("agentview", "wrist"), image_size: tuple[int, int] = C.ENV_IMAGE_SIZE,
                 instruction: str = "original", privileged: bool = False, render_mode: str | None = None,
                 terminate_on_success: bool = True, max_episode_steps: int | None = None,
                 visual: str = "decimated", wrist_supersample: int = 1):
        if wrist_supersample not in SUPERSAMPLE_FACTORS:
            raise EmbodimentError(f"wrist_supersample must be one of {', '.join(map(str, SUPERSAMPLE_FACTORS))}, "
                                  f"not {wrist_supersample!r}")
        self.wrist_supersample = int(wrist_supersample)
        self.robot = make_embodiment(embodiment, visual=visual)
        if control_mode not in self.robot.CONTROL_MODES:
            raise EmbodimentError(f"{embodiment} has no control mode {control_mode!r}; "
                                  f"it has {', '.join(self.robot.CONTROL_MODES)}")
        bad = [c for c in cameras if c not in CAMERAS]
        if bad:
            raise EmbodimentError(f"unknown camera {bad[0]!r}; cameras are {', '.join(CAMERAS)}")
        if render_mode not in (None, "rgb_array"):
            raise EmbodimentError(f"render_mode must be None or 'rgb_array', not {render_mode!r}")
        height, width = (int(v) for v in image_size)
        if not (16 <= height <= 2048 and 16 <= width <= 2048):
            raise EmbodimentError(f"image_size must be (height, width) between 16 and 2048 pixels, not {image_size}")
        self.task, self.source = load_env_task(task, robot=self.robot)
        self.scene = self.task.scene
        self.model, self.data = self.scene.model, self.scene.data
        self.control_mode = control_mode
        self.cameras = tuple(cameras)
        self.image_size = (height, width)
        self.instruction = _instruction(self.source, instruction)
        self.privileged = bool(privileged)
        self.render_mode = render_mode
        self.terminate_on_success = bool(terminate_on_success)
        self.object_names = self.scene.names
        edges = {n: a.extents[0] for n, a in self.scene.assets.items() if a.movable}
        self.max_episode_steps = int(max_episode_steps or episode_step_limit(
            len(edges), len(dense_cubes(self.task.data.goal_poses, edges))))
        self._body_names = {self.model.body(n).id: n for n in self.object_names}
        self._renderer = None  # every camera's, but a supersampled wrist camera's
        self._wrist_renderer = None  # the wrist camera's with wrist_supersample > 1
        self._elapsed = 0
        self._seed: int | None = None
        self._monitors: list = []
        self._goal_cache: tuple[np.ndarray, object] | None = None
        self.action_space = self._make_action_space()
        self.observation_space = self._make_observation_space()

    # -- spaces --------------------------------------------------------------------
    def _make_action_space(self) -> spaces.Box:
        if self.control_mode == "ee_delta":
            return spaces.Box(-1.0, 1.0, (7,), np.float32)
        if self.control_mode == "ee_abs":
            low = np.array([C.WORKSPACE_X[0] - 0.2, C.WORKSPACE_Y[0] - 0.2, C.TABLE_TOP_Z, -np.pi, -np.pi, -np.pi, -1.0])
            high = np.array([C.WORKSPACE_X[1] + 0.2, C.WORKSPACE_Y[1] + 0.2, C.TABLE_TOP_Z + C.MAX_TOWER_HEIGHT + 0.2,
                             np.pi, np.pi, np.pi, 1.0])
            return spaces.Box(low.astype(np.float32), high.astype(np.float32), (7,), np.float32)
        low = np.append(self.robot.joint_low, -1.0).astype(np.float32)
        high = np.append(self.robot.joint_high, 1.0).astype(np.float32)
        return spaces.Box(low, high, (8,), np.float32)

    @property
    def instructions(self) -> tuple[str, ...]:
        """The task's instruction texts: as written, the canonical statement of G, then each
        paraphrase (``instruction=`` picks one; the Text space's charset covers them all)."""
        return (self.source.instruction, self.source.canonical or self.source.instruction, *self.source.paraphrases)

    def _make_observation_space(self) -> spaces.Dict:
        h, w = self.image_size
        inf = np.inf
        obs = {f"{c}_image": spaces.Box(0, 255, (h, w, 3), np.uint8) for c in self.cameras}
        obs["state"] = spaces.Box(-inf, inf, (8,), np.float64)
        obs["qpos"] = spaces.Box(-inf, inf, self.robot.robot_qpos().shape, np.float64)
        obs["qvel"] = spaces.Box(-inf, inf, self.robot.robot_qvel().shape, np.float64)
        if self.privileged:
            obs["object_poses"] = spaces.Box(-inf, inf, (len(self.object_names), 7), np.float64)
        texts = self.instructions
        charset = "".join(sorted(set(string.printable) | set("".join(texts))))
        obs["instruction"] = spaces.Text(max_length=max(256, *(len(t) for t in texts)), charset=charset)
        return spaces.Dict(obs)

    # -- episode -------------------------------------------------------------------
    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Start an episode from rho_0's sample for ``seed`` (see the class docstring), or
        with ``options={"state": s}`` from a saved or recorded state ``s``
        (:meth:`get_state`, robomimic's ``states[t]`` of ``rpg demos``, or a dict of the
        observation's ``qpos``/``qvel``/``object_poses``: :mod:`rpg.env.state`); ``seed``
        then only seeds ``np_random`` and ``info["seed"]`` is None unless given.

        Raises:
            ValueError: ``options`` with a key other than ``state``, or a malformed state.
            TaskInvalid: rho_0's sample for ``seed`` breaks the validation gates' rules.
        """
        options = {} if options is None else options
        unknown = sorted(map(str, set(options) - {"state"}))
        if unknown:
            raise ValueError(f"reset options: unknown key(s) {', '.join(map(repr, unknown))}; the only option is "
                             "'state' (a saved or recorded state to start from, see rpg.env.state)")
        if options.get("state") is not None:
            from rpg.env.state import restore

            restore(self, options["state"])  # checks the state before changing anything
            super().reset(seed=seed)
            self._seed = None if seed is None else int(seed)
            return self._start_episode()
        super().reset(seed=seed)
        if seed is None:
            seed = int(self.np_random.integers(0, 2**31 - 1))
        self._seed = int(seed)
        mujoco.mj_resetData(self.model, self.data)
        poses = self.task.reset(self._seed)
        self._check_sample(poses)
        self.robot.home()
        self.scene.forward()
        mujoco.mj_step(self.model, self.data, nstep=C.RESET_SETTLE_STEPS)
        obs, info = self._start_episode()
        if info["goal_satisfied"]:  # e.g. a cube rho_0 held in the air fell into place while settling
            raise TaskInvalid(f"{self.source.name}: G holds once rho_0's sample for seed {self._seed} has settled; "
                              "an episode that starts solved is not scored")
        return obs, info

    def _start_episode(self) -> tuple[dict, dict]:
        """Step count, temporal monitors and G's cache for a new episode from the current state."""
        self._elapsed = 0
        self._monitors = [p.monitor() for p in self.task.goal_predicate.walk() if isinstance(p, InOrder)]
        self._goal_cache = None
        info = self._info()
        return self._observation(), info

    def get_state(self) -> np.ndarray:
        """The simulation's state, float64 (S,): ``mj_getState`` with
        :data:`rpg.env.state.ENV_STATE` (qpos, qvel, mocap poses, actuator commands, warm
        start...); ``reset(options={"state": it})`` restores it exactly (a replay of the
        same actions from it reproduces the episode)."""
        from rpg.env.state import capture

        return capture(self)

    def step(self, action):
        """One control step: the action's targets, then CONTROL_SUBSTEPS physics steps.

        Raises:
            ValueError: an action of the wrong shape or with non-finite values.
        """
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != self.action_space.shape or not np.all(np.isfinite(a)):
            raise ValueError(f"action must be {self.action_space.shape[0]} finite numbers for "
                             f"control_mode={self.control_mode!r}, got shape {np.shape(action)}")
        self.robot.command(self.control_mode, a)
        parts = self.robot.INTERPOLATION_POINTS
        for k in range(parts):
            self.robot.substep(k, parts)
            mujoco.mj_step(self.model, self.data, nstep=C.CONTROL_SUBSTEPS // parts)
        self._elapsed += 1
        info = self._info()
        terminated = bool(info["success"]) and self.terminate_on_success
        truncated = self._elapsed >= self.max_episode_steps and not terminated
        return self._observation(), float(info["success"]), terminated, truncated, info

    def _check_sample(self, poses) -> None:
        """rho_0's sample for this seed, as the validation gates require of it: every object
        in the workspace, and G false (a task solved at reset would score a policy that does
        nothing).

        Raises:
            TaskInvalid: the sample breaks either rule.
        """
        outside = out_of_bounds(poses)
        if outside:
            raise TaskInvalid(f"{self.source.name}: rho_0's sample for seed {self._seed} puts {outside[0]['object']} "
                              f"outside the workspace at {outside[0]['position']}")
        if self.task.success():
            raise TaskInvalid(f"{self.source.name}: G holds in every rho_0 sample drawn for seed {self._seed} "
                              f"({C.MAX_TRIVIAL_REDRAWS + 1} draws); an episode that starts solved is not scored")

    def set_goal_state(self) -> None:
        """Put the objects in the task's goal configuration (``goal_state_code.py``), robot at
        home, velocities zero; no physics step (for snapshots and tests, not for policies)."""
        self.task.set_goal_state()
        self.robot.home()
        self.scene.forward()

    # -- reading -------------------------------------------------------------------
    def _state(self) -> np.ndarray:
        tcp = self.robot.tcp_pose()
        return np.concatenate([tcp.pos, quat_to_axis_angle(tcp.quat), self.robot.finger_positions()])

    def _observation(self) -> dict:
        obs = {}
        for cam in self.cameras:
            obs[f"{cam}_image"] = self.render_camera(cam)
        obs["state"] = self._state()
        obs["qpos"] = self.robot.robot_qpos()
        obs["qvel"] = self.robot.robot_qvel()
        if self.privileged:
            obs["object_poses"] = np.array([[*p.pos, *p.quat] for p in self.scene.poses().values()], dtype=np.float64)
        obs["instruction"] = self.instruction
        return obs

    def _evaluate_goal(self) -> tuple[bool, list[str], list[str]]:
        """G on the current state (:meth:`rpg.domain.task.BlockTask.evaluate`): whether it holds,
        and the reasons of its satisfied and unsatisfied leaf predicates.  G reads only object
        poses, so the last result is reused while no object has moved more than
        :data:`~rpg.domain.constants.GOAL_REEVALUATE_TOL` since it was computed."""
        poses = self.scene.pose_vector()
        cache = self._goal_cache
        if cache is not None and np.max(np.abs(poses - cache[0]), initial=0.0) <= C.GOAL_REEVALUATE_TOL:
            return cache[1]
        try:
            result = self.task.evaluate()
        except (ValueError, TypeError, KeyError, ArithmeticError, IndexError) as exc:
            raise TaskInvalid(f"{self.source.name}: its goal cannot be evaluated on this state: {exc}") from None
        leaves = result.leaves()
        out = (bool(result.satisfied), [r.reason for r in leaves if r.satisfied],
               [r.reason for r in leaves if not r.satisfied])
        self._goal_cache = (poses, out)
        return out

    def _info(self) -> dict:
        satisfied, good, bad = self._evaluate_goal()
        good, bad = list(good), list(bad)
        if self._monitors:  # a temporal goal: its events must have happened in order
            state = self.task.world_state()
            for m in self._monitors:
                m.update(state)
                order = m.result()
                satisfied = satisfied and order.satisfied
                (good if order.satisfied else bad).append(order.reason)
        body = self.robot.grasped_body()
        grasped = self._body_names.get(body, "") if body is not None else ""
        leaves = len(good) + len(bad)
        return {
            "success": bool(satisfied and body is None),
            "goal_satisfied": bool(satisfied),
            "progress": len(good) / leaves if leaves else float(bool(satisfied)),
            "is_grasped": body is not None,
            "grasped": grasped,
            "diagnostics": {"satisfied": good, "unsatisfied": bad},
            "elapsed_steps": self._elapsed,
            "seed": self._seed,
            "task_hash": self.source.content_hash,
            "instruction": self.instruction,
        }

    # -- rendering -----------------------------------------------------------------
    def render_camera(self, camera: str) -> np.ndarray:
        """An image (H, W, 3) uint8 of the current state from ``camera`` (one of CAMERAS), at
        ``image_size``; the first call creates the renderer (one per environment,
        :class:`rpg.env.render.CameraRenderer`; a second one for the wrist camera when
        ``wrist_supersample`` > 1)."""
        return self._renderer_for(camera).image(self.data, PREFIX + camera if camera == "wrist" else camera,
                                                soft_shadows=camera in SOFT_SHADOW_CAMERAS,
                                                supersampled=camera == "wrist")

    def _renderer_for(self, camera: str) -> CameraRenderer:
        """The renderer that draws ``camera``, made on first use: a supersampled wrist camera
        has its own (its shadow map, sized for the larger drawing, is its context's), every
        other camera shares the environment's."""
        if camera not in CAMERAS:
            raise EmbodimentError(f"unknown camera {camera!r}; cameras are {', '.join(CAMERAS)}")
        if camera == "wrist" and self.wrist_supersample > 1:
            if self._wrist_renderer is None:
                self._wrist_renderer = CameraRenderer(self.model, *self.image_size, supersample=self.wrist_supersample)
            return self._wrist_renderer
        if self._renderer is None:
            self._renderer = CameraRenderer(self.model, *self.image_size)
        return self._renderer

    def render(self):
        """The agentview image (H, W, 3) uint8 (``render_mode="rgb_array"``), else None."""
        if self.render_mode != "rgb_array":
            return None
        return self.render_camera("agentview")

    def close(self) -> None:
        for name in ("_renderer", "_wrist_renderer"):
            renderer = getattr(self, name, None)
            if renderer is not None:
                renderer.close()
                setattr(self, name, None)
        super().close()
