"""Goal configuration of align_blocks_in_color_gradient_from_left_90ac9e: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'cyan': Pose((0.55, -0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'green': Pose((0.55, -0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'orange': Pose((0.55, 0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red': Pose((0.55, 0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'yellow': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
