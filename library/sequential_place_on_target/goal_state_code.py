"""Goal configuration of place_each_colored_block_on_matching_colored_12a5e6: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue': Pose((0.55, 0.07, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_patch': Pose((0.55, 0.07, 0.9505), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, -0.07, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_patch': Pose((0.55, -0.07, 0.9505), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
