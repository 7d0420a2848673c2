"""Gate 1 (text): an allowlist of what task code may say, checked before anything runs.

Task code (``code.py``, ``goal_state_code.py``) may:

- import only ``from rpg.task_api import NAME, ...`` (names of :data:`rpg.task_api.__all__`),
  ``import numpy`` / ``import numpy as np``, ``import math`` and ``from math import NAME``;
- call only the builtins in :data:`SAFE_BUILTINS`;
- use, of numpy, only the names in :data:`NUMPY_API` (and of ``np.random`` / ``np.linalg``
  only :data:`NUMPY_SUBMODULE_API`);
- not name or reach any attribute that starts with ``_``, not hold a string containing
  ``__``, not use ``global``/``nonlocal``.

Everything else is refused with the line and a hint.  The source is then compiled with
RestrictedPython's ``compile_restricted_exec`` (attribute reads and writes become guarded
calls; see :mod:`rpg.validate.restricted`), and the worker executes exactly the bytes that
were checked: it receives the source text, never re-reads it from disk.  This gate is the
first of several layers; the worker process runs under resource limits, an audit hook,
seccomp and, where the kernel allows, in its own namespaces (:mod:`rpg.validate.isolation`).
"""

from __future__ import annotations

import ast
import builtins
from types import CodeType

from rpg.errors import TaskInvalid

SAFE_BUILTINS = frozenset({
    "abs", "all", "any", "bool", "dict", "enumerate", "filter", "float", "frozenset", "int", "isinstance",
    "len", "list", "map", "max", "min", "pow", "range", "reversed", "round", "set", "sorted", "str", "sum",
    "tuple", "zip", "super", "property", "staticmethod", "classmethod", "print", "divmod", "hash",
    "None", "True", "False", "NotImplemented", "ArithmeticError", "AssertionError", "Exception", "IndexError",
    "KeyError", "LookupError", "NotImplementedError", "RuntimeError", "StopIteration", "TypeError",
    "ValueError", "ZeroDivisionError",
})
"""Builtins task code may use (no I/O, no introspection, no code objects)."""

NUMPY_API = frozenset({
    "abs", "absolute", "all", "allclose", "amax", "amin", "any", "arange", "arccos", "arcsin", "arctan",
    "arctan2", "argmax", "argmin", "argsort", "around", "array", "asarray", "ceil", "clip", "column_stack",
    "concatenate", "cos", "cross", "cumsum", "deg2rad", "degrees", "diff", "dot", "e", "exp", "eye",
    "float32", "float64", "floor", "full", "hstack", "hypot", "inf", "int32", "int64", "interp", "isclose",
    "isfinite", "isnan", "linalg", "linspace", "log", "max", "maximum", "mean", "median", "min",
    "minimum", "mod", "nan", "ones", "ones_like", "outer", "pi", "power", "prod", "rad2deg", "radians",
    "random", "repeat", "reshape", "rint", "round", "sign", "sin", "sort", "sqrt", "square", "stack", "std",
    "sum", "tan", "tile", "unique", "vstack", "where", "zeros", "zeros_like",
})
"""Names of numpy task code may use: array construction and arithmetic, no I/O."""

NUMPY_SUBMODULE_API = {
    "random": frozenset({"default_rng", "Generator"}),
    "linalg": frozenset({"norm", "det", "inv", "solve"}),
}
"""Names of ``np.random`` and ``np.linalg`` task code may use."""

MODULES = ("numpy", "math")
"""Modules task code may import besides :mod:`rpg.task_api`."""


class StaticViolation(TaskInvalid, ValueError):
    """Task code failed the text gate; ``kind`` is ``syntax`` or ``api_usage``."""

    def __init__(self, message: str, kind: str = "api_usage", line: int | None = None):
        super().__init__(message)
        self.kind = kind
        self.line = line


def task_api_names() -> frozenset[str]:
    """The names task code may import from :mod:`rpg.task_api` (its ``__all__``, no modules)."""
    import types

    from rpg import task_api

    return frozenset(n for n in task_api.__all__ if not isinstance(getattr(task_api, n), types.ModuleType))


def _module_aliases(tree: ast.Module) -> dict[str, str]:
    """Local names bound to numpy or math by ``import`` statements."""
    out = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                out[alias.asname or alias.name] = alias.name
    return out


class _Gate(ast.NodeVisitor):
    def __init__(self, filename: str, api: frozenset[str], modules: dict[str, str]):
        self.filename = filename
        self.api = api
        self.modules = modules

    def fail(self, node: ast.AST, message: str) -> None:
        line = getattr(node, "lineno", None)
        raise StaticViolation(f"{self.filename}:{line}: {message}", line=line)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            if alias.name not in MODULES:
                self.fail(node, f"import of {alias.name!r} is not allowed: use 'from rpg.task_api import NAME', "
                                "'import numpy as np' or 'import math'")

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        if node.level or node.module not in ("rpg.task_api", "math", "numpy"):
            self.fail(node, f"import from {node.module!r} is not allowed (only rpg.task_api, numpy, math)")
        allowed = {"rpg.task_api": self.api, "numpy": NUMPY_API - {"random", "linalg"},
                   "math": frozenset(n for n in dir(__import__("math")) if not n.startswith("_"))}[node.module]
        for alias in node.names:
            if alias.name not in allowed:
                self.fail(node, f"{alias.name!r} is not part of {node.module}'s API for task code")

    def visit_Name(self, node: ast.Name) -> None:
        if node.id.startswith("_") and node.id != "__name__":
            self.fail(node, f"name {node.id!r} is not allowed in task code (names starting with '_' are private)")
        if hasattr(builtins, node.id) and node.id not in SAFE_BUILTINS and node.id not in self.modules:
            if isinstance(node.ctx, ast.Load):
                self.fail(node, f"builtin {node.id!r} is not allowed in task code")

    def visit_Attribute(self, node: ast.Attribute) -> None:
        if node.attr.startswith("_"):
            self.fail(node, f"attribute {node.attr!r} is not allowed (attributes starting with '_' are private)")
        base = node.value
        if isinstance(base, ast.Name) and self.modules.get(base.id) == "numpy" and node.attr not in NUMPY_API:
            self.fail(node, f"numpy.{node.attr} is not part of the numpy API for task code")
        if (isinstance(base, ast.Attribute) and isinstance(base.value, ast.Name) and self.modules.get(base.value.id) == "numpy"
                and node.attr not in NUMPY_SUBMODULE_API.get(base.attr, ())):
            self.fail(node, f"numpy.{base.attr}.{node.attr} is not part of the numpy API for task code")
        self.generic_visit(node)

    def visit_Constant(self, node: ast.Constant) -> None:
        if isinstance(node.value, str) and "__" in node.value:
            self.fail(node, "strings containing '__' are not allowed in task code")

    def visit_Global(self, node: ast.AST) -> None:
        self.fail(node, "global/nonlocal statements are not allowed in task code")

    visit_Nonlocal = visit_Global


def check_source(source: str, filename: str) -> CodeType:
    """Check ``source`` against the allowlist and compile it restricted.

    Args:
        source: the file's text (the exact text that will run).
        filename: its name, for messages.

    Returns:
        The code object to execute with :func:`rpg.validate.restricted.exec_task_source`.

    Raises:
        StaticViolation: syntax error, a disallowed import, builtin, numpy name, private name
            or attribute, or a construct RestrictedPython refuses.
    """
    from RestrictedPython import compile_restricted_exec

    try:
        tree = ast.parse(source, filename=filename)
    except (SyntaxError, ValueError) as exc:
        line = getattr(exc, "lineno", None)
        raise StaticViolation(f"{filename}:{line}: syntax error: {getattr(exc, 'msg', exc)}", "syntax", line) from None
    _Gate(filename, task_api_names(), _module_aliases(tree)).visit(tree)
    result = compile_restricted_exec(source, filename)
    if result.errors or result.code is None:
        raise StaticViolation(f"{filename}: {result.errors[0] if result.errors else 'cannot be compiled'}")
    return result.code
