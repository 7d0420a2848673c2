"""The readers' registry: each reader registers itself, with the order it is tried in.

A reader is ``read(features, builder) -> bool``: True when it has built the task into the
builder, False when the instruction is not of its kind; it raises
:class:`~rpg.schema.reading.ParseError` when the instruction is of its kind but cannot be built.
Readers are tried lowest ``order`` first: specific readings (a cube moved to a region, an
unstacked stack, tower clauses) before general ones (the relational reader last), so a
general reader never takes a sentence a specific one reads exactly.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from rpg.schema.builder import Builder
from rpg.schema.reading import Features


@dataclass(frozen=True)
class Reader:
    """One registered reader: its function's name, its place in the order, the function."""

    name: str
    order: int
    read: Callable[[Features, Builder], bool]


READERS: dict[str, Reader] = {}
"""Every registered reader by name (``recognize_tower_sequence``), as structure kinds name them
(:attr:`rpg.schema.structures.StructureKind.recognizer`)."""


def reader(order: int) -> Callable:
    """Register the decorated function as a reader tried at ``order`` (lower first).

    Raises:
        ValueError: a reader of that name, or another reader at that order, is registered.
    """
    def register(read: Callable[[Features, Builder], bool]) -> Callable[[Features, Builder], bool]:
        clash = next((r.name for r in READERS.values() if r.order == order and r.name != read.__name__), None)
        if read.__name__ in READERS or clash:
            raise ValueError(f"reader {read.__name__!r} at order {order}: "
                             f"{'already registered' if read.__name__ in READERS else f'{clash!r} has that order'}")
        READERS[read.__name__] = Reader(read.__name__, order, read)
        return read
    return register


def ordered() -> tuple[Reader, ...]:
    """The registered readers in the order :func:`rpg.schema.readers.parse` tries them."""
    return tuple(sorted(READERS.values(), key=lambda r: r.order))
