"""Steering: versioned task families, edits classified into intents, lineage hashes.

Python API::

    from rpg.steer import steer, Family
    steer("out/place_blue_cube", "Add a green cube on top")
    Family("out/place_blue_cube").verify()
"""

from rpg.steer.edits import SteerError
from rpg.steer.family import Family, FamilyError, TaskSnapshot, create_family, is_family
from rpg.steer.steering import SteerResult, steer

__all__ = ["Family", "FamilyError", "SteerError", "SteerResult", "TaskSnapshot", "create_family", "is_family", "steer"]
