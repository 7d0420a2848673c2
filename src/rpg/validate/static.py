"""Gate 1 (text): static checks on task code before anything runs.

Allowed imports: :mod:`rpg.task_api`, numpy, math.  Forbidden: exec/eval/compile/open/
``__import__``/getattr-family calls, any dunder attribute or name (``__class__``,
``__subclasses__``, ``__builtins__``, ``__globals__``...), the modules os, sys,
subprocess, socket, importlib, ctypes, pickle (among others), and file I/O attributes such
as ``np.save``/``np.load``/``tofile`` (:data:`FORBIDDEN_ATTRIBUTES`).
"""

from __future__ import annotations

import ast

from rpg.errors import TaskInvalid

ALLOWED_IMPORTS = frozenset({"rpg.task_api", "numpy", "math"})
FORBIDDEN_NAMES = frozenset({
    "exec", "eval", "compile", "open", "__import__", "getattr", "setattr", "delattr", "globals",
    "locals", "vars", "input", "breakpoint", "memoryview", "help", "exit", "quit", "dir",
    "os", "sys", "subprocess", "socket", "importlib", "ctypes", "pickle", "builtins", "shutil",
    "marshal", "signal", "threading", "multiprocessing", "io", "pathlib",
})
ALLOWED_DUNDERS = frozenset({"__init__", "__name__", "__doc__"})
FORBIDDEN_ATTRIBUTES = frozenset({
    "save", "savez", "savez_compressed", "savetxt", "load", "loadtxt", "genfromtxt", "fromfile", "tofile",
    "memmap", "open_memmap", "ctypeslib", "ctypes", "lib", "DataSource", "f2py", "distutils", "testing",
    "fromregex", "dump", "dumps", "system", "popen", "environ", "getenv", "modules", "builtins",
})
"""Attribute names task code may not use: file I/O and escape hatches of numpy and friends."""


class StaticViolation(TaskInvalid, ValueError):
    """Task code failed the text gate; ``kind`` is ``syntax`` or ``api_usage``."""

    def __init__(self, message: str, kind: str = "api_usage", line: int | None = None):
        super().__init__(message)
        self.kind = kind
        self.line = line


def check_source(source: str, filename: str) -> None:
    """Raise :class:`StaticViolation` on the first problem in ``source``.

    Raises:
        StaticViolation: syntax error, disallowed import, forbidden name or dunder access.
    """
    try:
        tree = ast.parse(source, filename=filename)
    except SyntaxError as exc:
        raise StaticViolation(f"{filename}:{exc.lineno}: syntax error: {exc.msg}", "syntax", exc.lineno) from None
    for node in ast.walk(tree):
        line = getattr(node, "lineno", None)
        where = f"{filename}:{line}"
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name not in ALLOWED_IMPORTS:
                    raise StaticViolation(f"{where}: import of {alias.name!r} is not allowed (only rpg.task_api, numpy, math)", line=line)
        elif isinstance(node, ast.ImportFrom):
            if node.level or node.module not in ALLOWED_IMPORTS:
                raise StaticViolation(f"{where}: import from {node.module!r} is not allowed (only rpg.task_api, numpy, math)", line=line)
        elif isinstance(node, ast.Name):
            if node.id in FORBIDDEN_NAMES:
                raise StaticViolation(f"{where}: use of {node.id!r} is forbidden in task code", line=line)
            if node.id.startswith("__") and node.id not in ALLOWED_DUNDERS:
                raise StaticViolation(f"{where}: dunder name {node.id!r} is forbidden in task code", line=line)
        elif isinstance(node, ast.Attribute):
            if node.attr.startswith("__") and node.attr not in ALLOWED_DUNDERS:
                raise StaticViolation(f"{where}: dunder attribute {node.attr!r} is forbidden in task code", line=line)
            if node.attr in FORBIDDEN_ATTRIBUTES:
                raise StaticViolation(f"{where}: attribute {node.attr!r} (file I/O or an escape hatch) is forbidden in task code", line=line)
            if node.attr.startswith("_") and node.attr not in ("_goal",):
                raise StaticViolation(f"{where}: private attribute {node.attr!r} is not part of the task API", line=line)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and "__" in node.value:
            raise StaticViolation(f"{where}: strings containing '__' are forbidden in task code", line=line)
        elif isinstance(node, ast.Global | ast.Nonlocal):
            raise StaticViolation(f"{where}: global/nonlocal statements are forbidden in task code", line=line)
