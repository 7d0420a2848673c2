"""Goal configuration of build_pyramid_digit_blocks_with_3x3_base_e1cc98: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'digit_0_1': Pose((0.5095, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_0_2': Pose((0.5095, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_1': Pose((0.5095, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_2_1': Pose((0.55, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_2_2': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_3': Pose((0.55, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_4': Pose((0.5905, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_5_1': Pose((0.5905, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_5_2': Pose((0.5905, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_6': Pose((0.52975, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'digit_7_1': Pose((0.52975, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'digit_7_2': Pose((0.57025, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'digit_8': Pose((0.57025, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'digit_9': Pose((0.55, 0.0, 1.051), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
