"""A task as the trusted side runs it: rebuilt from data, with rpg's own classes.

Task code (``code.py``, :mod:`rpg.domain.task_code`) runs only in the sandbox and answers
with data (:mod:`rpg.validate.data` checks it): the assets, samples of rho_0 for requested
seeds, the goal as the predicate registry's dict and the goal configuration's poses.
:class:`TaskData` holds that data rebuilt with the domain's own classes; :class:`Task`
puts it in a MuJoCo scene (with a robot, for an environment) and evaluates G with rpg's
own predicates.  Nothing here calls an object that task code made.

Loading is separate from initialising an episode (as in ManiSkill3): the constructor
builds and compiles the scene once; :meth:`Task.reset` sets rho_0's sample for a seed.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from rpg.domain import constants as C
from rpg.domain.assets import Asset
from rpg.domain.predicates import Predicate, PredicateResult, evaluate_goal
from rpg.domain.scene import Scene
from rpg.domain.state import Pose, WorldState
from rpg.domain.visibility import visible_faces

DrawSource = Callable[[int, int], list[dict[str, Pose]]]
"""``(seed, n) -> the first n samples`` that task code's ``initial_state(rng)`` draws from
``numpy.random.default_rng(seed)``, in order, as checked data."""


@dataclass
class TaskData:
    """What task code returned, checked and rebuilt with the domain's own classes.

    Attributes:
        assets: the task's assets.
        goal: the success predicate G (built by :func:`rpg.domain.predicates.from_dict`).
        goal_poses: the goal configuration (every object's pose, by name); None when
            ``goal_state`` failed (``goal_error`` says why).
        draws: the source of rho_0's samples (see :data:`DrawSource`).
        class_name: the task class's name (for messages).
        goal_error: why there is no goal configuration (an :class:`rpg.errors.RpgError`).
    """

    assets: tuple[Asset, ...]
    goal: Predicate
    goal_poses: dict[str, Pose] | None
    draws: DrawSource
    class_name: str = "task"
    goal_error: Exception | None = None


class Task:
    """A task's scene, rho_0 and G, from :class:`TaskData`.

    Args:
        data: the checked data of the task's code.
        robot: an embodiment (:mod:`rpg.env.embodiments`) to add to the scene; None for
            the block-only scene that validation uses.
    """

    def __init__(self, data: TaskData, robot=None) -> None:
        self.data = data
        self.scene = Scene(data.assets, robot=robot)
        self._goal = data.goal

    # -- episode ---------------------------------------------------------------
    def reset(self, seed: int = 0) -> dict[str, Pose]:
        """Start an episode: set rho_0's sample for ``seed``.

        rho_0 is conditioned on G being false: a sample in which the goal already holds is
        drawn again from the same generator, up to :data:`~rpg.domain.constants.MAX_TRIVIAL_REDRAWS`
        times (so a policy that does nothing scores 0; the non-trivial gate rejects a task
        whose samples keep satisfying G).  When every draw satisfies G, the last one is set.

        Returns:
            The sampled poses, by name.
        """
        poses: dict[str, Pose] = {}
        seen = 0
        for n in (C.INITIAL_DRAWS, C.MAX_TRIVIAL_REDRAWS + 1):
            for poses in self.data.draws(seed, n)[seen:]:
                self.set_state(poses)
                if not self.success():
                    return poses
            seen = n
        return poses

    def set_state(self, poses: Mapping[str, Pose]) -> None:
        """Set object poses, zero velocities and time."""
        self.scene.set_poses(poses)
        self.scene.reset_time()

    def set_goal_state(self) -> None:
        """Put every object in the goal configuration (``goal_state_code.py``'s poses).

        Raises:
            RpgError: the task's ``goal_state`` failed (``TaskData.goal_error``).
        """
        if self.data.goal_poses is None:
            raise self.data.goal_error or ValueError("the task has no goal configuration")
        self.set_state(self.data.goal_poses)

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

    def scratch(self) -> Task:
        """A robot-free copy of this task (for evaluating G on candidate configurations)."""
        return Task(self.data)

    @staticmethod
    def table_height() -> float:
        """Table top height, m."""
        return C.TABLE_TOP_Z
