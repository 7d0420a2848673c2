"""Goal configuration of sort_piles_blocks_by_color_into_separated_c95d61: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue_1': Pose((0.526, -0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_2': Pose((0.526, 0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_3': Pose((0.574, -0.024, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green_1': Pose((0.526, -0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green_2': Pose((0.526, -0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green_3': Pose((0.574, -0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_1': Pose((0.526, 0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_2': Pose((0.526, 0.184, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_3': Pose((0.574, 0.136, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
