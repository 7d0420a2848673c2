"""Goal configuration of arrange_cubes_into_correct_single_digit_math_714381: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'digit_3': Pose((0.55, 0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_4': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_7': Pose((0.55, -0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'op_equals': Pose((0.55, -0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'op_plus': Pose((0.55, 0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
