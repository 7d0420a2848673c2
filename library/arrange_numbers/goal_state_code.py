"""Goal configuration of arrange_cubes_in_strictly_increasing_numerical_order: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'digit_1': Pose((0.55, 0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_2': Pose((0.55, 0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_3': Pose((0.55, -0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_4': Pose((0.55, -0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
