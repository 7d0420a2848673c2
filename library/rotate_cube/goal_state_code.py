"""Goal configuration of rotate_block_letter_b_faces_up: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_b': Pose((0.55, 0.0, 0.9705), (0.707107, 0.0, 0.707107, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
