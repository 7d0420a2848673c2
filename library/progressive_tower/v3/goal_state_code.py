"""Goal configuration of build_tower_from_bottom_to_top_red_0e89c5: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue': Pose((0.55, 0.0, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_a': Pose((0.55, 0.0, 1.0915), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'yellow': Pose((0.55, 0.0, 1.051), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
