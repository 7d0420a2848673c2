"""Compiled tasks as Gymnasium environments with a robot (``rpg/BlockTask-v0``).

Importing this package registers the environment id; see :mod:`rpg.env.core` for the
observation and action conventions.
"""

from __future__ import annotations

import gymnasium as gym

from rpg.env.core import BlockTaskEnv, episode_step_limit
from rpg.env.embodiments import EMBODIMENTS, make_embodiment

ENV_ID = "rpg/BlockTask-v0"

if ENV_ID not in gym.registry:
    gym.register(id=ENV_ID, entry_point="rpg.env.core:BlockTaskEnv", disable_env_checker=False,
                 order_enforce=True)

__all__ = ["ENV_ID", "EMBODIMENTS", "BlockTaskEnv", "episode_step_limit", "make_embodiment"]
