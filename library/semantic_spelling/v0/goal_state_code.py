"""Goal configuration of spell_word_robot_using_semantic_cubes_arranged_f5247c: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_b': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_o_1': Pose((0.55, 0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_o_2': Pose((0.55, -0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_r': Pose((0.55, 0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_t': Pose((0.55, -0.12, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
