"""Pass 4: repair operators routed by failure class."""

from rpg.repair.operators import OPERATORS, route

__all__ = ["OPERATORS", "route"]
