"""Robots for :mod:`rpg.env`: one interface (:class:`~rpg.env.embodiments.base.Embodiment`),
two embodiments (``panda``, ``floating_gripper``)."""

from __future__ import annotations

from rpg.env.embodiments.base import CONTROL_MODES, Embodiment, EmbodimentError

EMBODIMENTS = ("panda", "floating_gripper")
"""Embodiment names, for ``embodiment=`` and ``--embodiment``."""


def make_embodiment(name: str) -> Embodiment:
    """A new embodiment by name.

    Raises:
        EmbodimentError: unknown name.
    """
    if name == "panda":
        from rpg.env.embodiments.panda import Panda

        return Panda()
    if name == "floating_gripper":
        from rpg.env.embodiments.floating import FloatingGripper

        return FloatingGripper()
    raise EmbodimentError(f"unknown embodiment {name!r}; embodiments are {', '.join(EMBODIMENTS)}")


__all__ = ["CONTROL_MODES", "EMBODIMENTS", "Embodiment", "EmbodimentError", "make_embodiment"]
