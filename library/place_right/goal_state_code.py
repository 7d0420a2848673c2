"""Goal configuration of place_red_block_on_right_side_yellow_db9398: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'red': Pose((0.55, -0.05, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'yellow': Pose((0.55, 0.05, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
