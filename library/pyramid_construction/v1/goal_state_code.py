"""Goal configuration of build_pyramid_blue_blocks_with_3x3_base: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue_1': Pose((0.5095, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_10': Pose((0.52975, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'blue_11': Pose((0.52975, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'blue_12': Pose((0.57025, 0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'blue_13': Pose((0.57025, -0.02025, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'blue_14': Pose((0.55, 0.0, 1.051), (1.0, 0.0, 0.0, 0.0)),
    'blue_2': Pose((0.5095, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_3': Pose((0.5095, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_4': Pose((0.55, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_5': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_6': Pose((0.55, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_7': Pose((0.5905, 0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_8': Pose((0.5905, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_9': Pose((0.5905, -0.0405, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
