"""Compiled tasks as Gymnasium environments with a robot (``rpg/BlockTask-v0``).

Importing this package registers ``rpg/BlockTask-v0`` (any task, by ``task=``) and one id per
task of the default library (``rpg/<task>-v0``, ``rpg/<family>.vN-v0``:
:mod:`rpg.env.registration`, which reads the manifest only); see :mod:`rpg.env.core` for the
observation and action conventions, :mod:`rpg.env.state` for ``reset(options={"state": ...})``
and :mod:`rpg.env.wrappers` for libraries that refuse the instruction's Text space.
"""

from __future__ import annotations

import gymnasium as gym

from rpg.env.core import BlockTaskEnv, episode_step_limit
from rpg.env.embodiments import EMBODIMENTS, make_embodiment
from rpg.env.registration import (
    LIBRARIES,
    env_id,
    make_suite,
    register_default_library,
    register_library,
)

ENV_ID = "rpg/BlockTask-v0"

if ENV_ID not in gym.registry:
    gym.register(id=ENV_ID, entry_point="rpg.env.core:BlockTaskEnv", disable_env_checker=False,
                 order_enforce=True)
if "rpg" not in LIBRARIES:
    register_default_library()

__all__ = ["ENV_ID", "EMBODIMENTS", "LIBRARIES", "BlockTaskEnv", "env_id", "episode_step_limit", "make_embodiment",
           "make_suite", "register_library"]
