"""Wrappers for libraries that cannot take the environment's observation as it is.

The instruction is a :class:`gymnasium.spaces.Text` in the observation; Stable-Baselines3,
TorchRL's Gym wrappers and other learners accept only Box / Discrete / MultiDiscrete /
MultiBinary leaves and refuse it.  :class:`NoTextObservation` takes it out::

    import gymnasium as gym
    import rpg.env
    from rpg.env.wrappers import NoTextObservation

    env = NoTextObservation(gym.make("rpg/stack_blocks-v0", cameras=()), index=True)
    venv = gym.make_vec("rpg/stack_blocks-v0", num_envs=4, vectorization_mode="sync",
                        wrappers=[NoTextObservation], cameras=())
"""

from __future__ import annotations

import gymnasium as gym
import numpy as np
from gymnasium import spaces

INSTRUCTION_KEY = "instruction"
"""The observation's Text entry."""

INDEX_KEY = "instruction_index"
"""The observation entry :class:`NoTextObservation` adds with ``index=True``."""


class NoTextObservation(gym.Wrapper, gym.utils.RecordConstructorArgs):
    """The observation without its ``instruction`` Text entry; the text is in
    ``info["instruction"]`` after every ``reset`` and ``step``.

    With ``index=True`` the observation gains ``instruction_index``, a
    :class:`~gymnasium.spaces.Discrete` int64 into the task's instruction list
    ``env.unwrapped.instructions`` (0: as written, 1: the canonical statement of G, 2 + K:
    paraphrase K; two equal texts give the lower index).  The index is the task's own: the
    same number means different texts in different tasks, so a multi-task policy needs the
    text (from ``info``) or the task's id as well.

    Args:
        env: an environment whose observation space is a Dict with an ``instruction`` Text
            entry (``rpg/BlockTask-v0`` or a library id, wrapped or not).
        index: add ``instruction_index`` to the observation.

    Raises:
        ValueError: the observation space is not a Dict with a Text ``instruction`` (the
            wrapper is applied twice, or to another environment).
    """

    def __init__(self, env: gym.Env, index: bool = False):
        gym.utils.RecordConstructorArgs.__init__(self, index=index)  # env.spec records the wrapper
        gym.Wrapper.__init__(self, env)
        space = env.observation_space
        if not isinstance(space, spaces.Dict) or not isinstance(space.spaces.get(INSTRUCTION_KEY), spaces.Text):
            raise ValueError(f"NoTextObservation needs a Dict observation space with a Text {INSTRUCTION_KEY!r} "
                             f"entry, got {space}; apply it once, to an rpg environment")
        self.index = bool(index)
        kept = {k: v for k, v in space.spaces.items() if k != INSTRUCTION_KEY}
        if self.index:
            kept[INDEX_KEY] = spaces.Discrete(len(self._instructions()))
        self.observation_space = spaces.Dict(kept)

    def _instructions(self) -> tuple[str, ...]:
        return tuple(self.env.unwrapped.instructions)

    def _convert(self, obs: dict, info: dict) -> tuple[dict, dict]:
        text = obs[INSTRUCTION_KEY]
        out = {k: v for k, v in obs.items() if k != INSTRUCTION_KEY}
        if self.index:
            out[INDEX_KEY] = np.int64(self._instructions().index(text))
        info = dict(info)
        info[INSTRUCTION_KEY] = text
        return out, info

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        obs, info = self.env.reset(seed=seed, options=options)
        return self._convert(obs, info)

    def step(self, action):
        obs, reward, terminated, truncated, info = self.env.step(action)
        obs, info = self._convert(obs, info)
        return obs, reward, terminated, truncated, info
