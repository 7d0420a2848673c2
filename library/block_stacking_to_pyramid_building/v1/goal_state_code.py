"""Goal configuration of make_letter_pyramid_tower_with_blocks_show_22d7d0: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_a': Pose((0.55, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_b': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_c': Pose((0.55, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_d': Pose((0.55, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_e': Pose((0.55, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_f': Pose((0.55, 0.0, 1.051), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
