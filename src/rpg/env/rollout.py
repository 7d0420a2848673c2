"""Episodes and robot snapshots for the command line (``rpg play``, ``rpg render --embodiment``)."""

from __future__ import annotations

import contextlib
import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rpg.env.core import BlockTaskEnv
from rpg.env.embodiments.base import EmbodimentError

BUILTIN_POLICIES = ("oracle", "random", "noop")
"""Policies ``rpg play`` knows by name: the planner of :mod:`rpg.oracle`, uniform random
actions (seeded with the episode's seed), and the zero ``ee_delta`` action with the gripper open."""


@dataclass(frozen=True)
class EpisodeSummary:
    """What ``rpg play`` reports: steps, success, the seed, the instruction and the video."""

    task: str
    embodiment: str
    policy: str
    seed: int
    steps: int
    success: bool
    truncated: bool
    instruction: str
    video: str | None
    frames: int

    def to_json(self) -> dict:
        return dict(self.__dict__)


def _plugin(policy, env: BlockTaskEnv):
    """``act`` for a policy object (``reset(instruction)``, ``act(obs)`` answering one action
    or a chunk (H, action_dim), optional ``bind(env)``): the chunk's actions are executed in
    turn before the policy is asked again."""
    if callable(getattr(policy, "bind", None)):
        policy.bind(env)
    queue: list[np.ndarray] = []
    started = []

    def act(obs):
        if not started:
            policy.reset(env.instruction)
            started.append(True)
        if not queue:
            answer = np.asarray(policy.act(obs), dtype=np.float32)
            queue.extend(answer if answer.ndim == 2 else [answer])
        return queue.pop(0)

    return act


def _policy(name, env: BlockTaskEnv, seed: int):
    if not isinstance(name, str):
        return _plugin(name, env)
    if name == "oracle":
        from rpg.oracle import Oracle

        oracle = Oracle(env)
        return oracle.act  # plans at its first call, after reset
    if name == "random":
        env.action_space.seed(seed)
        return lambda obs: env.action_space.sample()
    if name == "noop":
        zero = np.zeros(env.action_space.shape, np.float32)
        zero[-1] = -1.0
        return lambda obs: zero
    raise EmbodimentError(f"unknown policy {name!r}; built-in policies are {', '.join(BUILTIN_POLICIES)}")


def play(task: str | Path, embodiment: str = "panda", policy="random", seed: int = 0,
         video: str | Path | None = None, max_steps: int | None = None,
         image_size: tuple[int, int] = (256, 256)) -> EpisodeSummary:
    """Run one ``ee_delta`` episode of ``policy`` and write the agentview and wrist images side
    by side to ``video`` (MP4, 20 fps) when given.

    ``policy``: a built-in name (:data:`BUILTIN_POLICIES`) or a policy object as ``rpg eval``
    runs them (``reset``, ``act``, optional ``bind``; :mod:`rpg.eval.policies` loads plug-ins and
    openpi servers).  A policy object is given the camera observations.

    Raises:
        EmbodimentError: unknown embodiment or policy.
        BadInput / ArtifactError / TaskInvalid: the task cannot be loaded.
        ValueError: ``max_steps`` < 1.
    """
    from rpg.env.video import VideoWriter

    if max_steps is not None and max_steps < 1:
        raise ValueError("max_steps must be at least 1")
    cameras = ("agentview", "wrist") if video or not isinstance(policy, str) else ()
    env = BlockTaskEnv(task, embodiment=embodiment, cameras=cameras, image_size=image_size,
                       max_episode_steps=max_steps)
    try:
        act = _policy(policy, env, seed)
        obs, info = env.reset(seed=seed)
        # the video appears only if the episode ends without an error (nothing half-written)
        with VideoWriter(video, env.metadata["render_fps"]) if video else contextlib.nullcontext() as writer:
            def record(o):
                if writer is not None:
                    writer.write(np.concatenate([o["agentview_image"], o["wrist_image"]], axis=1))

            record(obs)
            terminated = truncated = False
            while not (terminated or truncated):
                obs, _, terminated, truncated, info = env.step(act(obs))
                record(obs)
        return EpisodeSummary(task=str(task), embodiment=embodiment, policy=policy if isinstance(policy, str) else type(policy).__name__, seed=seed,
                              steps=info["elapsed_steps"], success=info["success"], truncated=truncated,
                              instruction=env.instruction, video=str(video) if video else None,
                              frames=writer.frames if writer is not None else 0)
    finally:
        env.close()


def robot_snapshots(task: str | Path, embodiment: str, seed: int, out_dir: str | Path,
                    size: tuple[int, int] = (480, 640)) -> dict[str, Path]:
    """Agentview PNGs with the robot at home: ``initial_<embodiment>.png`` (rho_0's sample for
    ``seed``) and ``goal_<embodiment>.png`` (the task's goal state, settled).

    Raises:
        as :func:`play`.
    """
    from PIL import Image

    from rpg.artifact import write_file
    from rpg.domain import constants as C

    env = BlockTaskEnv(task, embodiment=embodiment, cameras=(), image_size=size)
    try:
        env.reset(seed=seed)
        images = {"initial": env.render_camera("agentview")}
        env.set_goal_state()
        env.scene.settle(C.SETTLE_STEPS)
        images["goal"] = env.render_camera("agentview")
    finally:
        env.close()
    out = {}
    for key, img in images.items():
        path = Path(out_dir) / f"{key}_{embodiment}.png"
        buf = io.BytesIO()
        Image.fromarray(img).save(buf, format="PNG")
        write_file(path, buf.getvalue())
        out[key] = path
    return out
