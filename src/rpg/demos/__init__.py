"""Oracle demonstrations of compiled tasks as datasets (LeRobot v3.0 by default, LeRobot v2.1,
robomimic's HDF5), and their replay (``rpg demos``)."""

from rpg.demos.collect import collect_demos, expand_targets, replay_dataset
from rpg.demos.record import Episode, dataset_state, record_episode

__all__ = ["Episode", "collect_demos", "dataset_state", "expand_targets", "record_episode", "replay_dataset"]
