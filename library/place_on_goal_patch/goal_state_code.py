"""Goal configuration of place_both_blocks_onto_goal_patch: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue': Pose((0.55, 0.02, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'gray_patch': Pose((0.55, 0.0, 0.9505), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, -0.02, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
