"""Goal configuration of arrange_cubes_their_up_faces_read_b_2fca1a: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_a': Pose((0.55, 0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_b': Pose((0.55, 0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_c': Pose((0.55, -0.03, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_d': Pose((0.55, -0.09, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
