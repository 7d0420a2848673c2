"""Goal configuration of stack_two_towers_blocks_on_color_specific_43976d: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'blue_1': Pose((0.55, -0.08, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'blue_2': Pose((0.55, -0.08, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'blue_patch': Pose((0.55, -0.08, 0.9505), (1.0, 0.0, 0.0, 0.0)),
    'red_1': Pose((0.55, 0.08, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'red_2': Pose((0.55, 0.08, 1.0105), (1.0, 0.0, 0.0, 0.0)),
    'red_patch': Pose((0.55, 0.08, 0.9505), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
