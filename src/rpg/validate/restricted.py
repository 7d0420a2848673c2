"""Runs task code compiled by the text gate with guarded builtins, imports and attributes.

RestrictedPython (:func:`RestrictedPython.compile_restricted_exec`, called by
:func:`rpg.validate.static.check_source`) rewrites attribute reads into ``_getattr_(obj,
name)``, attribute and item writes into ``_write_(obj)``, iteration into ``_getiter_``;
this module supplies those guards:

- reading an attribute that starts with ``_`` or whose value is a module (other than
  ``numpy.random`` / ``numpy.linalg``) is refused, so no module object is ever reachable
  from task code (``np.matrixlib.defmatrix.sys`` and the like);
- writing is allowed on the task's own objects (instances of classes the task code
  defines, builtin containers, numpy arrays), never on modules, on imported classes or on
  instances of the domain's classes (task code cannot patch a predicate to pass);
- ``__import__`` gives only :mod:`rpg.task_api` names, numpy and math.

Task code is only one layer's business here: the process that runs it is isolated too.
"""

from __future__ import annotations

import operator
import types
from types import CodeType

from RestrictedPython.Guards import guarded_iter_unpack_sequence, guarded_unpack_sequence

from rpg.validate.static import (
    NUMPY_API,
    NUMPY_SUBMODULE_API,
    SAFE_BUILTINS,
    StaticViolation,
    check_source,
    task_api_names,
)

NATIVE_BRIDGES = frozenset({"ctypes", "cffi", "ctypeslib", "format", "format_map", "tofile", "dump", "dumps",
                            "data", "base", "view", "getfield", "setfield", "frombuffer", "from_dlpack"})
"""Attribute names refused whatever the object: numpy's ways to native memory and files (a
bit generator's ``ctypes``/``cffi`` function pointers, ``tofile``/``dump``, raw buffers and
views) and ``str.format``, whose fields read attributes with the real ``getattr``."""


class RestrictedAccess(PermissionError):
    """Task code reached for something outside its API (raised at run time)."""


_INPLACE = {"+=": operator.iadd, "-=": operator.isub, "*=": operator.imul, "/=": operator.itruediv,
            "//=": operator.ifloordiv, "%=": operator.imod, "**=": operator.ipow, "@=": operator.imatmul,
            "&=": operator.iand, "|=": operator.ior, "^=": operator.ixor, "<<=": operator.ilshift,
            ">>=": operator.irshift}


def _allowed_modules() -> dict[types.ModuleType, frozenset[str]]:
    import math

    import numpy as np

    return {np: NUMPY_API, np.random: NUMPY_SUBMODULE_API["random"], np.linalg: NUMPY_SUBMODULE_API["linalg"],
            math: frozenset(n for n in dir(math) if not n.startswith("_"))}


class _Guards:
    """The guard functions of one task-code module."""

    def __init__(self, module_name: str):
        self.module_name = module_name
        self.modules = _allowed_modules()
        self.api = task_api_names()

    def getattr_(self, obj, name: str, *default):
        if not isinstance(name, str) or name.startswith("_") or name in NATIVE_BRIDGES:
            raise RestrictedAccess(f"attribute {name!r} is not available to task code")
        if isinstance(obj, types.ModuleType):
            allowed = self.modules.get(obj)
            if allowed is None or name not in allowed:
                raise RestrictedAccess(f"{getattr(obj, '__name__', 'module')}.{name} is not available to task code")
        value = getattr(obj, name, *default)
        if isinstance(value, types.ModuleType) and value not in self.modules:
            raise RestrictedAccess(f"attribute {name!r} is a module; task code cannot reach modules")
        return value

    def own(self, obj) -> bool:
        cls = obj if isinstance(obj, type) else type(obj)
        return cls.__module__ == self.module_name

    def write_(self, obj):
        import numpy as np

        if isinstance(obj, list | dict | set | np.ndarray) or self.own(obj):
            return obj
        raise RestrictedAccess(f"task code may not modify {type(obj).__name__} objects it did not create")

    def import_(self, name, globals=None, locals=None, fromlist=(), level=0):
        import math

        import numpy as np

        if level:
            raise RestrictedAccess("relative imports are not available to task code")
        if name == "rpg.task_api" and fromlist and set(fromlist) <= self.api:
            from rpg import task_api

            return task_api
        if name in ("numpy", "math"):
            module = np if name == "numpy" else math
            if all(f in self.modules[module] and f not in ("random", "linalg") for f in fromlist or ()):
                return module
        raise RestrictedAccess(f"import of {name!r} ({', '.join(fromlist or ()) or 'module'}) is not available to task code")

    def inplace(self, op: str, x, y):
        if op not in _INPLACE:
            raise RestrictedAccess(f"operator {op!r} is not available to task code")
        return _INPLACE[op](x, y)


class _Printer:
    """RestrictedPython's print collector: task code may print; output is discarded."""

    def __init__(self, _getattr_=None):
        self.parts: list[str] = []

    def write(self, text: str) -> None:
        if sum(map(len, self.parts)) < 65536:
            self.parts.append(text)

    def __call__(self) -> str:
        return "".join(self.parts)

    def _call_print(self, *objects, **kwargs) -> None:
        kwargs.pop("file", None)
        print(*objects, file=self, **kwargs)


def task_globals(module_name: str) -> dict:
    """The global namespace task code runs in: guarded builtins, imports and attribute access."""
    import builtins

    g = _Guards(module_name)
    safe = {n: getattr(builtins, n) for n in SAFE_BUILTINS}
    safe["__build_class__"] = builtins.__build_class__
    safe["__import__"] = g.import_
    return {
        "__builtins__": safe, "__name__": module_name, "__metaclass__": type,
        "_getattr_": g.getattr_, "_write_": g.write_, "_getitem_": operator.getitem, "_getiter_": iter,
        "_iter_unpack_sequence_": guarded_iter_unpack_sequence, "_unpack_sequence_": guarded_unpack_sequence,
        "_inplacevar_": g.inplace, "_print_": _Printer, "_apply_": lambda f, *a, **kw: f(*a, **kw),
    }


def exec_task_source(source: str, filename: str, module_name: str, code: CodeType | None = None,
                     restricted: bool = True) -> types.SimpleNamespace:
    """Check ``source`` with the text gate and run it in a restricted namespace.

    Args:
        source: the text of ``code.py`` or ``goal_state_code.py``.
        filename: its name, for messages.
        module_name: the ``__name__`` task classes get (their instances are the task's own).
        code: the code object :func:`check_source` returned for this very source, if known.
        restricted: False only for the text gate's ablation (``rpg validate --disable
            text``): the code then runs as plain Python, held by the process's isolation.

    Returns:
        The module's namespace as attributes.

    Raises:
        StaticViolation: the source fails the text gate.
        Exception: whatever task code raises while it runs (data for the gate results).
    """
    if not restricted:  # the text gate's ablation (``--disable text``): the OS layers alone hold the code
        namespace = {"__name__": module_name}
        exec(compile(source, filename, "exec"), namespace)  # noqa: S102 - isolated process, by explicit request
        return types.SimpleNamespace(**{k: v for k, v in namespace.items() if not k.startswith("__")})
    if code is None:
        code = check_source(source, filename)
    namespace = task_globals(module_name)
    exec(code, namespace)  # noqa: S102 - restricted code object, guarded namespace, isolated process
    return types.SimpleNamespace(**{k: v for k, v in namespace.items() if not k.startswith("_")})


__all__ = ["RestrictedAccess", "StaticViolation", "exec_task_source", "task_globals"]
