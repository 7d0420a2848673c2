"""Every verdict on a task, computed by trusted code from the data its code returned.

The sandbox (:mod:`rpg.validate.child`) runs task code and answers with data; this module
rebuilds the task with rpg's own classes (:class:`rpg.domain.task.Task`) and runs the gates
on it in rpg's process, which never ran task code: compile (the data checks), smoke,
nontrivial, constraint, goal_state (settle and stability), bounds, visibility and, when
asked, solvable (the oracle).  A gate result cannot come from the task: the task only
supplies poses, assets and the goal's dict, and G is evaluated with rpg's predicates.
The paper's "Validation and Physical Realizability" names the gates; the numbers are in
:mod:`rpg.domain.constants`.
"""

from __future__ import annotations

import time
from pathlib import Path

from rpg.domain import constants as C
from rpg.domain.layouts import out_of_bounds
from rpg.domain.scene import drift_report
from rpg.domain.task import Task
from rpg.domain.visibility import face_visibility
from rpg.errors import RpgError


class GateFailure(Exception):
    """A gate's failure: its repair kind, message and details (data for the repair pass)."""

    def __init__(self, kind: str, message: str, details: dict | None = None):
        super().__init__(message)
        self.kind = kind
        self.details = details or {}


def _poses_json(task: Task) -> dict:
    return {n: p.to_json() for n, p in task.scene.poses().items()}


def _reaches(succ: dict[str, set[str]], start: str, goal: set[str], skip: tuple[str, str] | None = None) -> bool:
    """Whether a path of one or more edges leads from ``start`` to a node of ``goal``
    (``skip``: an edge left out)."""
    seen, stack = set(), [start]
    while stack:
        node = stack.pop()
        for nxt in sorted(succ.get(node, ())):
            if (node, nxt) == skip or nxt in seen:
                continue
            if nxt in goal:
                return True
            seen.add(nxt)
            stack.append(nxt)
    return False


def constraint_graph(task: Task) -> dict:
    """The support graph of G: no cycle, every chain grounded on the table or a patch.

    The graph is small (one node per asset), so the standard library's ``graphlib`` finds a
    cycle and a depth-first walk answers reachability (networkx cost a compile 80 ms to import).

    Raises:
        GateFailure: a cycle, or a chain that does not end on the table.
    """
    import graphlib

    goal = task.goal_predicate
    edges = sorted(set(goal.support_edges()))
    succ: dict[str, set[str]] = {"table": set()}
    for up, lo in edges:
        succ.setdefault(up, set()).add(lo)
        succ.setdefault(lo, set())
    try:
        graphlib.TopologicalSorter({n: sorted(s) for n, s in sorted(succ.items())}).prepare()
    except graphlib.CycleError as exc:
        cycle = list(reversed(exc.args[1]))
        raise GateFailure("constraint", f"support relations form a cycle: {' -> '.join(cycle)}",
                          {"cycles": [cycle[:-1]], "edges": edges}) from None
    patches = {n for n, a in task.scene.assets.items() if a.kind == "goal_patch"}
    grounds = {"table", *patches}
    ungrounded = sorted(n for n in succ if n not in grounds and succ[n] and not _reaches(succ, n, grounds))
    if ungrounded:
        raise GateFailure("constraint", f"support chain of {', '.join(ungrounded)} does not end at the table", {"edges": edges})
    redundant = [[up, lo] for up, lo in edges if lo != "table" and _reaches(succ, up, {lo}, skip=(up, lo))]
    return {"edges": edges, "redundant": redundant}


def visibility(task: Task) -> dict:
    """Every label G reads is on a face that is visible and upright to the camera.

    Raises:
        GateFailure: an occluded or unreadable face.
    """
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


def _failure(name: str, exc: BaseException, t0: float) -> dict:
    kind = getattr(exc, "kind", None) or "runtime"
    return {"gate": name, "status": "fail", "kind": kind, "message": str(exc)[:2000],
            "duration_s": time.perf_counter() - t0, "details": dict(getattr(exc, "details", {}) or {})}


def run_gates(sources: dict[str, str], seed: int = 0, disabled=frozenset(), enabled=frozenset(),
              tolerances: dict | None = None, snapshots_to: Path | None = None, name: str = "task",
              pending=None) -> list[dict]:
    """The gates after the text gate, in order, on ``sources`` (``code.py`` and
    ``goal_state_code.py`` text).

    Args:
        seed: the first seed of rho_0's samples checked (``NONTRIVIAL_SEEDS`` from it).
        disabled: gate names switched off (``"text"`` also runs the code unrestricted).
        enabled: optional gates to run after the others, when they all passed.
        tolerances: the schema's settle and stability tolerances (steps, m).
        snapshots_to: a directory to write ``initial.png`` and ``goal.png`` into.
        name: the task's name (for the solvable gate's episodes).
        pending: :func:`rpg.validate.data.start_task_data`'s waiter for these sources and
            :func:`rpg.validate.data.gate_seeds`, when the caller started the sandboxed run already.

    Returns:
        ``[{"gate", "status", "kind"?, "message"?, "duration_s", "details"}]``.
    """
    from rpg.validate.data import fetch_task_data, gate_seeds

    tol = {"settle_steps": C.SETTLE_STEPS, "stability_steps": C.STABILITY_STEPS,
           "max_drift": C.MAX_DRIFT, "max_drop": C.MAX_DROP, **(tolerances or {})}
    results: list[dict] = []
    task: Task | None = None

    def gate(gname, fn):
        if gname in disabled:
            results.append({"gate": gname, "status": "skipped", "duration_s": 0.0, "details": {}})
            return True
        t0 = time.perf_counter()
        try:
            details = fn() or {}
        except (GateFailure, RpgError) as exc:
            results.append(_failure(gname, exc, t0))
            return False
        except Exception as exc:  # noqa: BLE001 - rpg's own code on strange but checked data
            results.append(_failure(gname, GateFailure("runtime", f"{type(exc).__name__}: {exc}"), t0))
            return False
        results.append({"gate": gname, "status": "pass", "duration_s": time.perf_counter() - t0, "details": details})
        return True

    def compile_gate():
        nonlocal task
        if snapshots_to is not None:  # OpenGL starts while the child runs
            from rpg.domain.render import warm_up

            warm_up()
        if pending is not None:
            data = pending()
        else:
            data = fetch_task_data(sources, gate_seeds(seed, enabled), restricted="text" not in disabled)
        task = Task(data)
        return {"class": data.class_name, "objects": task.scene.names}

    if "compile" in disabled:
        disabled = frozenset(disabled) - {"compile"}
    if not gate("compile", compile_gate):
        return results

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
            if not truths[-1]:  # and still false once settled, as an episode starts (a cube held in the air falls)
                task.step(C.RESET_SETTLE_STEPS)
                truths[-1] = task.success()
        if truths.count(False) < C.NONTRIVIAL_MIN_FALSE:
            raise GateFailure("success_check", f"success() is already true after reset for {truths.count(True)} of {len(truths)} seeds",
                              {"success_at_reset": truths})
        return {"success_at_reset": truths}

    def settled_goal():
        task.set_goal_state()
        task.step(tol["settle_steps"])

    def goal_state():
        settled_goal()
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
        if movers:
            raise GateFailure("stability", f"goal state is unstable: {', '.join(sorted(movers))} moved",
                              {"moved": movers, "poses": _poses_json(task)})
        if not second.satisfied:
            raise GateFailure("stability", "success() stopped holding during the stability window",
                              {"predicates": second.to_json()})
        return {"max_drift": max((r["drift"] for r in report.values()), default=0.0),
                "max_drop": max((r["drop"] for r in report.values()), default=0.0),
                "predicates": second.to_json()}

    def bounds():
        out = []
        for s in range(C.NONTRIVIAL_SEEDS):
            out += [dict(o, seed=seed + s) for o in out_of_bounds(task.reset(seed + s))]
        settled_goal()
        out += [dict(o, state="goal") for o in out_of_bounds(task.scene.poses())]
        if out:
            raise GateFailure("bounds", f"{len(out)} object position(s) outside the workspace: " +
                              ", ".join(f"{o['object']} at {o['position']}" for o in out[:3]), {"outside": out})
        return {"checked_seeds": C.NONTRIVIAL_SEEDS}

    def visible():
        settled_goal()
        return visibility(task)

    def solvable():
        from rpg.env.loading import PreparedTask
        from rpg.oracle.solvable import solvability

        details = solvability(PreparedTask(task.data, name=name), seed, needed=C.SOLVABLE_MIN_SUCCESS)
        if details["successes"] < C.SOLVABLE_MIN_SUCCESS:
            first = details["failures"][0]
            raise GateFailure("solvability", f"the oracle solved {details['successes']} of {details['episodes']} "
                              f"episodes with the {details['embodiment']} (needs {C.SOLVABLE_MIN_SUCCESS}); "
                              f"seed {first['seed']}: {first['reason']}", details)
        return details

    for gname, fn in (("smoke", smoke), ("nontrivial", nontrivial), ("constraint", lambda: constraint_graph(task)),
                      ("goal_state", goal_state), ("bounds", bounds), ("visibility", visible)):
        if not gate(gname, fn) and gname == "smoke":
            break
    if "solvable" in enabled and all(r["status"] != "fail" for r in results):
        gate("solvable", solvable)
    if snapshots_to is not None:
        write_snapshots(task, seed, Path(snapshots_to), tol["settle_steps"])
    return results


def write_snapshots(task: Task, seed: int, directory: Path, settle_steps: int = C.SETTLE_STEPS) -> dict[str, Path | None]:
    """``initial.png`` (rho_0's sample for ``seed``) and ``goal.png`` (the settled goal
    configuration) in ``directory``, written whole; key -> path, None where the task cannot
    be shown or there is no OpenGL."""
    from rpg.artifact import write_file
    from rpg.domain.render import Snapshotter

    pngs: dict[str, bytes | None] = {"initial": None, "goal": None}
    try:
        with Snapshotter(task.scene) as snap:
            task.reset(seed)
            for key in ("initial", "goal"):
                if key == "goal":
                    task.set_goal_state()
                    task.step(settle_steps)
                pngs[key] = snap.png()
    except Exception:  # noqa: BLE001 - a task that cannot be shown still has its gate results
        pass
    out: dict[str, Path | None] = {}
    for key, png in pngs.items():  # a write that fails (disk full) is the machine's failure: raised
        out[key] = directory / f"{key}.png" if png is not None else None
        if png is not None:
            write_file(out[key], png)
    return out


def object_json(task: Task) -> list[dict]:
    """Every object of the current state: name, kind, colour, label, pose, size, and a
    cube's up and front labels."""
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


def result_block(task: Task) -> dict:
    """G on the current state with every object (``rpg inspect`` and ``rpg check``)."""
    r = task.evaluate()
    return {"objects": object_json(task), "success": r.satisfied,
            "predicates": [leaf.to_json() for leaf in r.leaves()]}
