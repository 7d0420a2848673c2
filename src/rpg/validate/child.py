"""The sandboxed child that runs task code and answers with data only.

Run only through :func:`rpg.validate.sandbox.run_child`, one fresh process per request,
inside every layer of :mod:`rpg.validate.isolation`.  It reads one JSON request on stdin and
writes one JSON document to stdout.  It imports no simulator and decides nothing: the
trusted side (:mod:`rpg.validate.data`) checks the reply against a schema, rebuilds the task
from it with its own classes and computes every verdict.

Request::

    {"op": "data", "sources": {"code.py": ..., "goal_state_code.py": ...},
     "seeds": [0, 1, ...], "draws": 3, "goal_state": true, "restricted": true}

Reply (``ok`` false only when the code cannot be loaded at all)::

    {"ok": true, "result": {"class": "...", "assets": [{"kind": ..., "name": ..., ...}],
     "goal": {"predicate": ..., ...}, "goal_poses": {name: [x, y, z, qw, qx, qy, qz]},
     "rho0": {"0": [{name: [...]}, ...]}, "errors": {"initial_state": {...}, "goal_state": {...}}}}
"""

from __future__ import annotations

import json
import os
import sys
import traceback

CHILD_MAX_REQUEST = 64 * 1024**2
"""Largest request the child reads, characters."""

TEMPLATE_MEMBERS = frozenset({"assets", "initial_state", "goal", "NAME", "INSTRUCTION", "PARAPHRASES"})
"""Members of the task base class a task class may define; any other member it defines must
not shadow one of the base class's."""


class LoadError(Exception):
    """The task code cannot be loaded: (kind, message)."""

    def __init__(self, kind: str, message: str):
        super().__init__(message)
        self.kind = kind


def classify(exc: BaseException) -> str:
    """The repair kind of an exception raised by task code."""
    from rpg.validate.restricted import RestrictedAccess
    from rpg.validate.static import StaticViolation

    if isinstance(exc, LoadError):
        return exc.kind
    if isinstance(exc, SyntaxError):
        return "syntax"
    if isinstance(exc, StaticViolation):
        return exc.kind
    if isinstance(exc, RestrictedAccess | ImportError | AttributeError | NameError | TypeError):
        return "api_usage"
    return "runtime"


def _error(exc: BaseException) -> dict:
    return {"kind": classify(exc), "message": f"{type(exc).__name__}: {exc}"[:2000],
            "traceback": traceback.format_exc(limit=6)[-4000:]}


def _pose(p) -> list[float]:
    from rpg.domain.state import Pose

    if isinstance(p, Pose):
        pos, quat = p.pos, p.quat
    else:
        pos, quat = p
    return [float(v) for v in pos] + [float(v) for v in quat]


def _poses(poses) -> dict[str, list[float]]:
    if not isinstance(poses, dict):
        raise TypeError(f"expected a dict of poses by name, got {type(poses).__name__}")
    return {str(k): _pose(v) for k, v in poses.items()}


def load(sources: dict[str, str], restricted: bool = True):
    """Run ``code.py`` and ``goal_state_code.py`` (their text, as gated) and return the one
    task class and the goal-state module.

    Raises:
        LoadError: not exactly one task class, a task class that redefines the base class's
            behaviour, or no ``goal_state(task)``.
        StaticViolation: the text fails the text gate.
    """
    from rpg.domain.task_code import TRUSTED_MEMBERS, BlockTask
    from rpg.validate.restricted import exec_task_source

    mod = exec_task_source(str(sources["code.py"]), "code.py", "rpg_task_code", restricted=restricted)
    goal_mod = exec_task_source(str(sources["goal_state_code.py"]), "goal_state_code.py", "rpg_goal_state_code",
                                restricted=restricted)
    classes = [v for v in vars(mod).values() if isinstance(v, type) and issubclass(v, BlockTask) and v is not BlockTask]
    if len(classes) != 1:
        raise LoadError("api_usage", f"code.py must define exactly one BlockTask subclass, found {len(classes)}")
    shadowed = sorted(n for n in vars(classes[0]) if not n.startswith("__") and n not in TEMPLATE_MEMBERS
                      and (hasattr(BlockTask, n) or n in TRUSTED_MEMBERS))
    if shadowed:
        raise LoadError("api_usage", f"code.py redefines BlockTask.{shadowed[0]}; a task defines only "
                                     f"{', '.join(sorted(TEMPLATE_MEMBERS))} and its own helpers")
    if not callable(getattr(goal_mod, "goal_state", None)):
        raise LoadError("api_usage", "goal_state_code.py must define goal_state(task)")
    return classes[0], goal_mod


def _check_domain_objects(task) -> None:
    """The goal and assets must be the domain's own classes, not task-made subclasses (the
    trusted side rebuilds them from data anyway; a subclass says the code meant something
    else than what would be rebuilt)."""
    for node in task.goal().walk():
        if type(node).__module__ != "rpg.domain.predicates":
            raise LoadError("api_usage", f"goal() returned a {type(node).__name__}: only rpg.task_api predicates may be used")
    for asset in task.scene.assets.values():
        if type(asset).__module__ != "rpg.domain.assets":
            raise LoadError("api_usage", f"assets() returned a {type(asset).__name__}: only rpg.task_api assets may be used")


def data(req: dict) -> dict:
    """Answer a ``data`` request (see the module docstring)."""
    import numpy as np

    cls, goal_mod = load(req["sources"], restricted=bool(req.get("restricted", True)))
    task = cls()
    _check_domain_objects(task)
    assets = [a.to_dict() for a in task.scene.assets.values()]
    out: dict = {"class": cls.__name__, "assets": assets, "goal": task.goal().to_dict(), "rho0": {}, "errors": {}}
    draws = max(1, int(req.get("draws", 1)))
    try:
        for seed in req.get("seeds", ()):
            rng = np.random.default_rng(int(seed))
            out["rho0"][str(int(seed))] = [_poses(task.initial_state(rng)) for _ in range(draws)]
    except Exception as exc:  # noqa: BLE001 - task code may raise anything; reported as data
        out["errors"]["initial_state"] = {**_error(exc), "seed": int(seed)}
    if req.get("goal_state", True):
        try:
            stub = cls()
            goal_mod.goal_state(stub)
            out["goal_poses"] = _poses(stub.recorded_state)
        except Exception as exc:  # noqa: BLE001
            out["errors"]["goal_state"] = _error(exc)
    return out


def handle(req: dict) -> str:
    """Run one request; the JSON document for the parent (errors are data too)."""
    try:
        if req.get("op") != "data":
            raise LoadError("runtime", f"unknown request {req.get('op')!r}")
        doc = {"ok": True, "result": data(req)}
    except Exception as exc:  # noqa: BLE001 - reported to the parent as data
        doc = {"ok": False, **_error(exc)}
    return json.dumps(doc, allow_nan=True)


def main() -> None:
    import numpy.linalg  # noqa: F401 - imported before the filters: numpy opens its libraries at import
    import numpy.random  # noqa: F401

    import rpg.task_api  # noqa: F401
    import rpg.validate.restricted  # noqa: F401
    from rpg.validate.guard import install
    from rpg.validate.isolation import install_landlock, install_seccomp
    from rpg.validate.sandbox import apply_limits

    req = json.loads(sys.stdin.read(CHILD_MAX_REQUEST))
    reply = os.fdopen(os.dup(1), "w")  # the reply channel; what task code prints goes nowhere
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    sys.stdout = open(1, "w", closefd=False)  # noqa: SIM115 - fd 1 now /dev/null
    apply_limits()
    install_landlock()
    install_seccomp()
    install(os.getcwd())
    reply.write(handle(req))
    reply.flush()


if __name__ == "__main__":
    main()
