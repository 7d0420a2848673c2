"""Pass 2: TaskSchema -> ``code.py`` and ``goal_state_code.py``."""

from rpg.codegen.emit import GeneratedCode, generate

__all__ = ["GeneratedCode", "generate"]
