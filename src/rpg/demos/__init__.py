"""Oracle demonstrations of compiled tasks as datasets (LeRobot v2.1), and
their replay (``rpg demos``)."""

from rpg.demos.collect import collect_demos, expand_targets, replay_dataset
from rpg.demos.record import Episode, record_episode

__all__ = ["Episode", "collect_demos", "expand_targets", "record_episode", "replay_dataset"]
