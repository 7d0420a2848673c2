"""Goal configuration of place_both_blue_blocks_onto_goal_patch: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue_1': Pose((0.55, -0.02, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_2': Pose((0.55, 0.02, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'gray_patch': Pose((0.55, 0.0, 0.9505), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
