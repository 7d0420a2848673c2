"""Goal configuration of sort_letters_numbers_and_colors_mixed_into_cfb8ab: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue': Pose((0.526, -0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_1': Pose((0.526, -0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_2': Pose((0.526, 0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'digit_3': Pose((0.574, -0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green': Pose((0.574, -0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_a': Pose((0.526, 0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_b': Pose((0.526, 0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_c': Pose((0.574, 0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.526, -0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
