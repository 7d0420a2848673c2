"""Goal configuration of stack_green_block_on_yellow_block_beside_02b1e2: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'green': Pose((0.55, 0.0, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, -0.07, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'yellow': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
