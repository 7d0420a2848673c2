"""Goal configuration of arrange_cubes_they_spell_word_cat_from_6b7372: poses (m; quaternion w, x, y, z) that satisfy G."""

from rpg.task_api import Pose

GOAL_POSES = {
    'letter_a': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_c': Pose((0.55, 0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
    'letter_t': Pose((0.55, -0.06, 0.97), (1.0, 0.0, 0.0, 0.0)),
}


def goal_state(task):
    """Put the task's objects in the goal configuration."""
    task.set_state(GOAL_POSES)
