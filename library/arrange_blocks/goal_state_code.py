"""Goal configuration of arrange_blocks_in_order_red_yellow_green_1b841b: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue': Pose((0.55, -0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green': Pose((0.55, -0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, 0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'yellow': Pose((0.55, 0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
