"""The base class that task code extends: it describes a task and returns data, nothing more.

Generated ``code.py`` subclasses :class:`BlockTask` (exported by :mod:`rpg.task_api`) and
implements three methods; ``goal_state_code.py`` defines ``goal_state(task)``, which calls
``task.set_state({name: Pose, ...})``:

* ``assets()`` -> list of :mod:`rpg.domain.assets` objects,
* ``initial_state(rng)`` -> name -> :class:`~rpg.domain.state.Pose` (one sample of rho_0),
* ``goal()`` -> a :class:`~rpg.domain.predicates.Predicate` (the success predicate G).

This class runs only inside the sandbox (:mod:`rpg.validate.child`) and holds no simulator:
``self.scene`` is a read-only view of the task's assets, and ``set_state`` only records the
poses it is given.  What the child sends back is plain data (assets, poses, the goal as the
predicate registry's dict); the trusted side rebuilds the task from that data with its own
classes (:class:`rpg.domain.task.Task`) and decides every verdict.  Nothing a task class
defines is ever called outside the sandbox.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from rpg.domain import constants as C

TRUSTED_MEMBERS = ("reset", "step", "evaluate", "success", "world_state", "goal_predicate", "set_goal_state",
                   "scratch", "data")
"""Members of the trusted :class:`rpg.domain.task.Task`.  A task class that defines one is
refused: none of them would ever be called (the trusted side decides), and code that looks
as if it decides its own verdict is not a task to publish."""


class AssetView:
    """What ``self.scene`` offers task code: the assets by name, in the order given.

    Attributes:
        assets: name -> asset (read-only mapping).
        names: the asset names, sorted.
    """

    def __init__(self, assets) -> None:
        self.assets = MappingProxyType({a.name: a for a in assets})
        self.names = sorted(self.assets)


class BlockTask:
    """Base class of a task's code: T = (assets, rho_0, G, instruction, paraphrases).

    Class attributes:
        NAME: task name (snake_case).
        INSTRUCTION: the canonical instruction.
        PARAPHRASES: alternative phrasings for robustness testing.
    """

    NAME: str = "task"
    INSTRUCTION: str = ""
    PARAPHRASES: tuple[str, ...] = ()

    def __init__(self) -> None:
        self.scene = AssetView(self.assets())
        self.recorded_state: dict = {}

    def assets(self) -> list:
        """The task's assets."""
        raise NotImplementedError

    def initial_state(self, rng):
        """One sample of rho_0 (every object's pose, by name) drawn from the
        ``numpy.random.Generator`` ``rng``."""
        raise NotImplementedError

    def goal(self):
        """The success predicate G as a predicate tree."""
        raise NotImplementedError

    def set_state(self, poses: Mapping) -> None:
        """Record object poses (what ``goal_state(task)`` calls); later calls override
        earlier ones per object."""
        self.recorded_state.update(dict(poses))

    @staticmethod
    def table_height() -> float:
        """Table top height, m."""
        return C.TABLE_TOP_Z
