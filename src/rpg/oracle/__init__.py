"""The oracle: a task-and-motion planner that solves compiled block-domain tasks with a robot
through the environment's public action space (paper: demonstrations for training tasks,
and the upper-bound policy of evaluation)."""

from rpg.oracle.goal import GoalPlan, OracleError, Target, plan_goal
from rpg.oracle.planner import Oracle

__all__ = ["GoalPlan", "Oracle", "OracleError", "Target", "plan_goal"]
