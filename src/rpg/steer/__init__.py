"""Steering: versioned task families, edits classified into intents, lineage hashes.

Python API::

    from rpg.steer import steer, Family
    steer("out/place_blue_cube", "Add a green cube on top")
    Family("out/place_blue_cube").verify()
"""

import importlib

_HOMES = {"SteerError": "rpg.steer.edits", "Family": "rpg.steer.family", "FamilyError": "rpg.steer.family",
          "TaskSnapshot": "rpg.steer.family", "create_family": "rpg.steer.family", "is_family": "rpg.steer.family",
          "SteerResult": "rpg.steer.steering", "steer": "rpg.steer.steering"}
"""Each name of the API -> its module, imported on first use: a family's files (:mod:`rpg.steer.family`, which an
environment or an evaluation reads) do not import the language front end (:mod:`rpg.steer.edits` compiles its
lexicon, most of a second)."""

__all__ = sorted(_HOMES)


def __getattr__(name: str):
    if name in _HOMES:
        return getattr(importlib.import_module(_HOMES[name]), name)
    raise AttributeError(f"module 'rpg.steer' has no attribute {name!r}")
