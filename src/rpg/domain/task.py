"""The fixed task interface that every generated ``code.py`` extends.

Loading is separate from initialising an episode (as in ManiSkill3): the constructor
builds and compiles the scene once; :meth:`BlockTask.reset` samples an initial state
from rho_0 with a seeded ``numpy.random.Generator`` and sets it.

A task subclass documents itself in three parts (Task Description, Randomizations,
Success Conditions) and implements three methods:

* ``assets()`` -> list of :mod:`rpg.domain.assets` objects,
* ``initial_state(rng)`` -> name -> :class:`~rpg.domain.state.Pose`,
* ``goal()`` -> a :class:`~rpg.domain.predicates.Predicate` (the success predicate G).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from rpg.domain import constants as C
from rpg.domain.assets import Asset
from rpg.domain.predicates import Predicate, PredicateResult, evaluate_goal
from rpg.domain.scene import Scene
from rpg.domain.state import Pose, WorldState
from rpg.domain.visibility import visible_faces


class BlockTask:
    """Base class of block-domain tasks: T = (assets, rho_0, G, instruction, paraphrases).

    Class attributes:
        NAME: task name (snake_case).
        INSTRUCTION: the canonical instruction.
        PARAPHRASES: alternative phrasings for robustness testing.
    """

    NAME: str = "task"
    INSTRUCTION: str = ""
    PARAPHRASES: tuple[str, ...] = ()

    def __init__(self, robot=None) -> None:
        """Build and compile the scene once.

        Args:
            robot: an embodiment (:mod:`rpg.env.embodiments`) to add to the scene; None for
                the block-only scene that validation uses.
        """
        self.scene = Scene(self.assets(), robot=robot)
        self._goal = self.goal()

    # -- to implement ----------------------------------------------------------
    def assets(self) -> list[Asset]:
        """The task's assets."""
        raise NotImplementedError

    def initial_state(self, rng: np.random.Generator) -> dict[str, Pose]:
        """Sample one initial state from rho_0 (all objects) with ``rng``."""
        raise NotImplementedError

    def goal(self) -> Predicate:
        """The success predicate G as a predicate tree."""
        raise NotImplementedError

    # -- episode ---------------------------------------------------------------
    def reset(self, seed: int = 0) -> dict[str, Pose]:
        """Start an episode: sample rho_0 with ``numpy.random.default_rng(seed)`` and set it.

        rho_0 is conditioned on G being false: a sample in which the goal already holds is
        drawn again from the same generator, up to :data:`~rpg.domain.constants.MAX_TRIVIAL_REDRAWS`
        times (so a policy that does nothing scores 0; the non-trivial gate rejects a task
        whose samples keep satisfying G).

        Returns:
            The sampled poses, by name.
        """
        rng = np.random.default_rng(seed)
        for _ in range(C.MAX_TRIVIAL_REDRAWS + 1):
            poses = self.initial_state(rng)
            self.set_state(poses)
            if not self.success():
                break
        return poses

    def set_state(self, poses: Mapping[str, Pose]) -> None:
        """Set object poses, zero velocities and time."""
        self.scene.set_poses(poses)
        self.scene.reset_time()

    def step(self, steps: int = 1) -> None:
        """Advance the physics under zero action."""
        self.scene.settle(steps)

    def world_state(self) -> WorldState:
        """Current state, with face visibility when the goal reads labels."""
        vis = visible_faces(self.scene) if self._needs_visibility() else None
        return self.scene.world_state(vis)

    def _needs_visibility(self) -> bool:
        return any(p.semantic for p in self._goal.walk())

    def evaluate(self) -> PredicateResult:
        """Evaluate G on the current state, with per-predicate diagnostics."""
        return evaluate_goal(self._goal, self.world_state())

    def success(self) -> bool:
        """Whether G holds in the current state."""
        return self.evaluate().satisfied

    @property
    def goal_predicate(self) -> Predicate:
        return self._goal

    @staticmethod
    def table_height() -> float:
        """Table top height, m."""
        return C.TABLE_TOP_Z
