"""Goal configuration of build_pyramid_letter_blocks_alphabetically_with_3x3_5ddf99: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_a': Pose((0.5095, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_b': Pose((0.5095, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_c': Pose((0.5095, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_d': Pose((0.55, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_e': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_f': Pose((0.55, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_g': Pose((0.5905, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_h': Pose((0.5905, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_i': Pose((0.5905, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_j': Pose((0.52975, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_k': Pose((0.52975, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_l': Pose((0.57025, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_m': Pose((0.57025, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'letter_n': Pose((0.55, 0.0, 1.051), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
