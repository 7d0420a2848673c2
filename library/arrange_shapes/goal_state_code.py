"""Goal configuration of place_cubes_in_circular_arrangement: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'red_1': Pose((0.47, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_2': Pose((0.51, -0.069282, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_3': Pose((0.59, -0.069282, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_4': Pose((0.63, -0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_5': Pose((0.59, 0.069282, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_6': Pose((0.51, 0.069282, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
