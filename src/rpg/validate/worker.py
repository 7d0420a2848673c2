"""The worker process that runs task code (gates 2-8, inspect, check, render).

Run only through :func:`rpg.validate.sandbox.run_worker`; it reads a request as JSON on
stdin and writes one JSON document to stdout.  Requests carry the task code's text, which
passed the text gate in the parent and is gated again here, the very text that then runs
(restricted, see :mod:`rpg.validate.restricted`).  Requests:

``{"op": "validate", "sources": {"code.py": ..., "goal_state_code.py": ...}, "seed": 0, "disabled": [...], "snapshots": true, "tolerances": {...}}``
``{"op": "inspect", "sources": ..., "state": "initial"|"goal", "seed": 0, "settle": 50}``
``{"op": "check", "sources": ..., "poses": {...}, "settle": 0}``
``{"op": "render", "sources": ..., "seed": 0}``
"""

from __future__ import annotations

import base64
import json
import os
import sys
import time
import traceback
from pathlib import Path

import networkx as nx
import numpy as np

from rpg.domain import constants as C
from rpg.domain.render import Snapshotter
from rpg.domain.scene import drift_report
from rpg.domain.task import BlockTask
from rpg.domain.visibility import face_visibility
from rpg.validate.restricted import RestrictedAccess, exec_task_source
from rpg.validate.static import StaticViolation

WORKER_MAX_REQUEST = 64 * 1024**2
"""Largest request a one-shot worker reads, characters."""


class GateFailure(Exception):
    def __init__(self, kind: str, message: str, details: dict | None = None):
        super().__init__(message)
        self.kind = kind
        self.details = details or {}


def _classify(exc: BaseException) -> str:
    if isinstance(exc, SyntaxError):
        return "syntax"
    if isinstance(exc, StaticViolation):
        return exc.kind
    if isinstance(exc, RestrictedAccess):
        return "api_usage"
    if isinstance(exc, ImportError | AttributeError | NameError | TypeError):
        return "api_usage"
    return "runtime"


TEMPLATE_MEMBERS = frozenset({"assets", "initial_state", "goal", "NAME", "INSTRUCTION", "PARAPHRASES"})
"""Members of :class:`BlockTask` a task class may define; any other member it defines must
not shadow one of BlockTask's (a task cannot redefine ``success`` or ``evaluate``)."""


def _check_task_class(cls: type) -> None:
    shadowed = sorted(n for n in vars(cls) if not n.startswith("__") and n not in TEMPLATE_MEMBERS and hasattr(BlockTask, n))
    if shadowed:
        raise GateFailure("api_usage", f"code.py redefines BlockTask.{shadowed[0]}; a task defines only "
                                       f"{', '.join(sorted(TEMPLATE_MEMBERS))} and its own helpers")


def _check_domain_objects(task: BlockTask) -> None:
    """The goal and assets must be the domain's own classes, not task-made subclasses."""
    for node in task.goal_predicate.walk():
        if type(node).__module__ != "rpg.domain.predicates":
            raise GateFailure("api_usage", f"goal() returned a {type(node).__name__}: only rpg.task_api predicates may be used")
    for asset in task.scene.assets.values():
        if type(asset).__module__ != "rpg.domain.assets":
            raise GateFailure("api_usage", f"assets() returned a {type(asset).__name__}: only rpg.task_api assets may be used")


def load_task(sources: dict[str, str], restricted: bool = True, robot=None) -> tuple[BlockTask, object]:
    """Run code.py and goal_state_code.py (their text, as gated) and instantiate the one BlockTask subclass.

    Args:
        sources: file name -> text of ``code.py`` and ``goal_state_code.py``; the text gate
            checks this very text again before it runs (no second read from disk).
        restricted: run it under RestrictedPython's guards (False only for the ablation).
        robot: an embodiment to add to the task's scene (an environment's; None here).

    Raises:
        GateFailure: not exactly one task class, a task class that redefines BlockTask's
            behaviour, foreign predicate or asset classes, or no ``goal_state(task)``.
        StaticViolation: the text fails the text gate.
    """
    mod = exec_task_source(str(sources["code.py"]), "code.py", "rpg_task_code", restricted=restricted)
    goal_mod = exec_task_source(str(sources["goal_state_code.py"]), "goal_state_code.py", "rpg_goal_state_code",
                                restricted=restricted)
    classes = [v for v in vars(mod).values() if isinstance(v, type) and issubclass(v, BlockTask) and v is not BlockTask]
    if len(classes) != 1:
        raise GateFailure("api_usage", f"code.py must define exactly one BlockTask subclass, found {len(classes)}")
    _check_task_class(classes[0])
    if not callable(getattr(goal_mod, "goal_state", None)):
        raise GateFailure("api_usage", "goal_state_code.py must define goal_state(task)")
    task = classes[0](robot=robot)
    _check_domain_objects(task)
    return task, goal_mod


def _poses_json(task: BlockTask) -> dict:
    return {n: p.to_json() for n, p in task.scene.poses().items()}


def _in_bounds(task: BlockTask) -> list[dict]:
    out = []
    m = C.BOUNDS_MARGIN
    for n, p in task.scene.poses().items():
        x, y, z = p.pos
        if not (C.WORKSPACE_X[0] - m <= x <= C.WORKSPACE_X[1] + m and C.WORKSPACE_Y[0] - m <= y <= C.WORKSPACE_Y[1] + m
                and z >= C.TABLE_TOP_Z - m):
            out.append({"object": n, "position": [round(v, 4) for v in p.pos]})
    return out


def _constraint_graph(task: BlockTask) -> dict:
    goal = task.goal_predicate
    edges = sorted(set(goal.support_edges()))
    g = nx.DiGraph()
    g.add_node("table")
    for up, lo in edges:
        g.add_edge(up, lo)
    cycles = [c for c in nx.simple_cycles(g)]
    if cycles:
        raise GateFailure("constraint", f"support relations form a cycle: {' -> '.join(cycles[0] + [cycles[0][0]])}",
                          {"cycles": cycles, "edges": edges})
    patches = {n for n, a in task.scene.assets.items() if a.kind == "goal_patch"}
    ungrounded = sorted(n for n in g.nodes if n not in ("table",) and n not in patches
                        and not any(t in ("table", *patches) for t in nx.descendants(g, n)) and g.out_degree(n) > 0)
    if ungrounded:
        raise GateFailure("constraint", f"support chain of {', '.join(ungrounded)} does not end at the table", {"edges": edges})
    redundant = []
    for up, lo in edges:
        h = g.copy()
        h.remove_edge(up, lo)
        if lo != "table" and nx.has_path(h, up, lo):
            redundant.append([up, lo])
    return {"edges": edges, "redundant": redundant}


def _visibility(task: BlockTask) -> dict:
    state = task.world_state()
    checks = []
    failures = []
    for p in task.goal_predicate.walk():
        if not p.semantic:
            continue
        faces = p.semantic_faces(state)
        visible_count = 0
        for name, direction in faces:
            o = state[name]
            face, _ = o.face_toward(direction)
            vis = face_visibility(task.scene, name, face)
            readable, ncos, ucos = o.readable(face, direction)
            ok = vis.visible and readable
            visible_count += ok
            checks.append({"predicate": p.name, "object": name, "face": face, "direction": direction,
                           "rays_clear": vis.rays_clear, "readable": readable, "visible": vis.visible})
            if not ok and p.name != "sorted_by":
                failures.append(f"{name} face {face} ({direction}) is {'occluded' if not vis.visible else 'not readable'}")
        if p.name == "sorted_by" and faces and visible_count < 2:
            failures.append("fewer than two visible labels carry the sort order")
    if failures:
        raise GateFailure("visibility", "; ".join(failures[:3]), {"faces": checks})
    return {"faces": checks}


def validate(req: dict) -> dict:
    sources = req["sources"]
    disabled = set(req.get("disabled", []))
    seed = int(req.get("seed", 0))
    tol = {"settle_steps": C.SETTLE_STEPS, "stability_steps": C.STABILITY_STEPS,
           "max_drift": C.MAX_DRIFT, "max_drop": C.MAX_DROP, **req.get("tolerances", {})}
    results: list[dict] = []
    task = goal_mod = None

    def gate(name, fn):
        if name in disabled:
            results.append({"gate": name, "status": "skipped", "duration_s": 0.0, "details": {}})
            return True
        t0 = time.perf_counter()
        try:
            details = fn() or {}
            results.append({"gate": name, "status": "pass", "duration_s": time.perf_counter() - t0, "details": details})
            return True
        except GateFailure as exc:
            results.append({"gate": name, "status": "fail", "kind": exc.kind, "message": str(exc),
                            "duration_s": time.perf_counter() - t0, "details": exc.details})
        except Exception as exc:  # noqa: BLE001 - task code may raise anything; report it as data
            results.append({"gate": name, "status": "fail", "kind": _classify(exc), "message": f"{type(exc).__name__}: {exc}",
                            "duration_s": time.perf_counter() - t0,
                            "details": {"traceback": traceback.format_exc(limit=6)[-4000:]}})
        return False

    def compile_gate():
        nonlocal task, goal_mod
        task, goal_mod = load_task(sources, restricted="text" not in disabled)
        return {"class": type(task).__name__, "objects": task.scene.names}

    if not gate("compile", compile_gate):
        return {"gates": results}

    def smoke():
        task.reset(seed)
        task.step(C.SMOKE_STEPS)
        if not task.scene.is_finite():
            raise GateFailure("runtime", "simulation produced NaN or inf within the smoke steps")
        task.evaluate()
        return {"steps": C.SMOKE_STEPS}

    def nontrivial():
        truths = []
        for s in range(C.NONTRIVIAL_SEEDS):
            task.reset(seed + s)
            truths.append(task.success())
        false = truths.count(False)
        if false < C.NONTRIVIAL_MIN_FALSE:
            raise GateFailure("success_check", f"success() is already true after reset for {truths.count(True)} of {len(truths)} seeds",
                              {"success_at_reset": truths})
        return {"success_at_reset": truths}

    def bounds_initial():
        out = []
        for s in range(C.NONTRIVIAL_SEEDS):
            task.reset(seed + s)
            out += [dict(o, seed=seed + s) for o in _in_bounds(task)]
        return out

    goal_info: dict = {}

    def goal_state():
        goal_mod.goal_state(task)
        task.step(tol["settle_steps"])
        if not task.scene.is_finite():
            raise GateFailure("stability", "goal state produced NaN or inf")
        first = task.evaluate()
        settled = task.scene.poses()
        if not first.satisfied:
            raise GateFailure("success_check", "success() is false in the settled goal state: " +
                              "; ".join(r.reason for r in first.unsatisfied_list[:3]),
                              {"predicates": first.to_json(), "poses": _poses_json(task)})
        task.step(tol["stability_steps"])
        report = drift_report(settled, task.scene.poses())
        movers = {n: r for n, r in report.items() if r["drift"] > tol["max_drift"] or r["drop"] > tol["max_drop"]}
        second = task.evaluate()
        goal_info["poses"] = _poses_json(task)
        if movers:
            raise GateFailure("stability", f"goal state is unstable: {', '.join(sorted(movers))} moved",
                              {"moved": movers, "poses": goal_info["poses"]})
        if not second.satisfied:
            raise GateFailure("stability", "success() stopped holding during the stability window",
                              {"predicates": second.to_json()})
        return {"max_drift": max((r["drift"] for r in report.values()), default=0.0),
                "max_drop": max((r["drop"] for r in report.values()), default=0.0),
                "predicates": second.to_json()}

    def bounds():
        out = bounds_initial()
        goal_mod.goal_state(task)
        task.step(tol["settle_steps"])
        out += [dict(o, state="goal") for o in _in_bounds(task)]
        if out:
            raise GateFailure("bounds", f"{len(out)} object position(s) outside the workspace: " +
                              ", ".join(f"{o['object']} at {o['position']}" for o in out[:3]), {"outside": out})
        return {"checked_seeds": C.NONTRIVIAL_SEEDS}

    def visibility():
        goal_mod.goal_state(task)
        task.step(tol["settle_steps"])
        return _visibility(task)

    def solvable():
        from rpg.env.loading import TaskCode
        from rpg.oracle.solvable import solvability

        details = solvability(TaskCode(sources, name=str(req.get("name", "task"))), seed)
        if details["successes"] < C.SOLVABLE_MIN_SUCCESS:
            first = details["failures"][0]
            raise GateFailure("solvability", f"the oracle solved {details['successes']} of {details['episodes']} "
                              f"episodes with the {details['embodiment']} (needs {C.SOLVABLE_MIN_SUCCESS}); "
                              f"seed {first['seed']}: {first['reason']}", details)
        return details

    for name, fn in (("smoke", smoke), ("nontrivial", nontrivial), ("constraint", lambda: _constraint_graph(task)),
                     ("goal_state", goal_state), ("bounds", bounds), ("visibility", visibility)):
        if not gate(name, fn) and name in ("smoke",):
            break
    if "solvable" in req.get("enabled", ()) and all(r["status"] != "fail" for r in results):
        gate("solvable", solvable)
    out = {"gates": results}
    if req.get("snapshots"):
        try:
            out["snapshots"] = _snapshots(task, goal_mod, seed, tol)
        except Exception:  # noqa: BLE001 - a task that cannot be shown still has its gate results
            out["snapshots"] = {}
    return out


def _snapshots(task, goal_mod, seed: int, tol: dict) -> dict[str, str | None]:
    """``initial`` and ``goal`` PNGs as base64 (None without OpenGL).  They are written in
    the worker's own directory and handed to the parent as data: task code never needs
    write access to the artifact."""
    images: dict[str, str | None] = {}
    with Snapshotter(task.scene) as snap:
        task.reset(seed)
        for key in ("initial", "goal"):
            if key == "goal":
                goal_mod.goal_state(task)
                task.step(tol.get("settle_steps", C.SETTLE_STEPS))
            path = snap.save(Path.cwd() / f"{key}.png")
            images[key] = base64.b64encode(path.read_bytes()).decode() if path else None
            if path:
                path.unlink()
    return images


def _object_json(task: BlockTask) -> list[dict]:
    state = task.world_state()
    out = []
    for name in task.scene.names:
        o = state[name]
        asset = task.scene.assets[name]
        entry = {"name": name, "kind": o.kind, "color": o.color, "label": o.label,
                 "position": [round(float(v), 6) for v in o.pos], "quaternion": [round(float(v), 6) for v in o.quat],
                 "size": [float(v) for v in asset.extents]}
        if o.is_cube:
            entry["up_label"] = o.label_toward("up")
            entry["front_label"] = o.label_toward("front")
        out.append(entry)
    return out


def _result_block(task: BlockTask) -> dict:
    r = task.evaluate()
    return {"objects": _object_json(task), "success": r.satisfied,
            "predicates": [leaf.to_json() for leaf in r.leaves()]}


def inspect(req: dict) -> dict:
    task, goal_mod = load_task(req["sources"])
    if req.get("state", "initial") == "goal":
        goal_mod.goal_state(task)
    else:
        task.reset(int(req.get("seed", 0)))
    task.step(int(req.get("settle", C.SETTLE_STEPS)))
    return _result_block(task)


def check(req: dict) -> dict:
    task, _ = load_task(req["sources"])
    task.scene.load_json(json.dumps({"objects": req["poses"]}))
    task.scene.reset_time()
    task.step(int(req.get("settle", 0)))
    return _result_block(task)


def render(req: dict) -> dict:
    task, goal_mod = load_task(req["sources"])
    return {"snapshots": _snapshots(task, goal_mod, int(req.get("seed", 0)), {})}


OPS = {"validate": validate, "inspect": inspect, "check": check, "render": render}


def handle(req: dict) -> str:
    """Run one request; the JSON document for the parent (errors are data too)."""
    try:
        out = OPS[req["op"]](req)
        doc = {"ok": True, "result": out}
    except Exception as exc:  # noqa: BLE001 - reported to the parent as data
        doc = {"ok": False, "kind": _classify(exc), "error": f"{type(exc).__name__}: {exc}",
               "traceback": traceback.format_exc(limit=6)[-4000:]}
    return json.dumps(doc, default=lambda v: float(v) if isinstance(v, np.floating) else str(v))


def main() -> None:
    from rpg.validate.guard import install
    from rpg.validate.isolation import install_seccomp
    from rpg.validate.sandbox import apply_limits

    req = json.loads(sys.stdin.read(WORKER_MAX_REQUEST))
    if "solvable" in req.get("enabled", ()):  # imported before the guard: gymnasium sets environment variables
        import rpg.oracle.planner  # noqa: F401
        import rpg.oracle.solvable  # noqa: F401
    apply_limits()
    install_seccomp()
    install(os.getcwd())
    sys.stdout.write(handle(req))


if __name__ == "__main__":
    main()
