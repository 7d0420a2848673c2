"""TaskSpec: the editable form of a task that steering works on.

Steering does not patch code.  It reads the reference version's schema back into a small
:class:`TaskSpec` (structure, cubes in structure order, dimensions, ordering), applies the
edit to that spec, and renders the result as a *canonical instruction* that the builtin
parser compiles like any other instruction.  The new version is therefore exactly the
task a user would get by typing its canonical instruction, which is recorded with it.

The structures with an editable spec, and how each is read back and stated, are the
registry :data:`rpg.schema.structures.STRUCTURE_KINDS`.  Other tasks (relations between
named cubes, goal patches, temporal order, equations) return ``None`` from :func:`extract`;
steering then accepts colour tweaks, the edits :mod:`rpg.steer.relations` reads (one
relation between two cubes, cubes on one patch) and edits that state a whole task.
"""

from rpg.schema.structures import STRUCTURES, Item, TaskSpec, extract, render

__all__ = ["STRUCTURES", "Item", "TaskSpec", "extract", "render"]
