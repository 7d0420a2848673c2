"""Scripted steering sessions: an instruction followed by edits, with expectations.

The format is that of ``benchmark_sessions`` in the seed cases::

    name: progressive_tower
    steps:
      - instruction: "Place a blue cube on top of a red cube on the table"
      - edit: "Add a green cube on top of the blue"
        expected_intent: extend          # optional
        expected_reference: current      # optional: current or vN
        expected_final: "tower bottom to top: red, blue, green"   # optional

``expected_final`` of the form ``tower bottom to top: a, b, ...`` (colours, or ``letter X``)
is checked against the settled goal state's object heights; other texts are reported
but not checked.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from rpg import yamlio
from rpg.artifact import ArtifactError, check_name, read_text
from rpg.compiler import compile_instruction
from rpg.errors import BadInput
from rpg.steer.edits import SteerError
from rpg.steer.family import Family, create_family
from rpg.steer.steering import steer


class SessionError(BadInput):
    """A malformed session file."""


@dataclass
class StepResult:
    index: int
    text: str
    ok: bool
    intent: str = "base"
    reference: str | None = None
    version: str | None = None
    problems: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def to_json(self) -> dict:
        return self.__dict__.copy()


def load_session(path: str | Path) -> dict:
    """Read and check a session file.

    Raises:
        SessionError: unreadable, or not ``{name, steps: [{instruction}, {edit, ...}, ...]}``.
    """
    try:
        doc = yamlio.load(read_text(Path(path)))
    except (ArtifactError, yaml.YAMLError) as exc:
        raise SessionError(f"cannot read session {path}: {str(exc).splitlines()[0]}") from None
    steps = doc.get("steps") if isinstance(doc, dict) else None
    if not isinstance(steps, list) or not steps or not isinstance(steps[0], dict) or not isinstance(steps[0].get("instruction"), str):
        raise SessionError(f"{path}: a session needs 'steps', the first with an 'instruction' (text)")
    for i, s in enumerate(steps[1:], 1):
        if not isinstance(s, dict) or not isinstance(s.get("edit"), str):
            raise SessionError(f"{path}: step {i} needs an 'edit' (text)")
    doc.setdefault("name", re.sub(r"[^a-z0-9_]", "_", Path(path).stem.lower()))
    try:
        check_name(doc["name"], "session name")
    except BadInput as exc:
        raise SessionError(f"{path}: {exc}") from None
    return doc


def goal_tower(directory: Path) -> list[str]:
    """Cubes of the settled goal state bottom to top, as ``red`` or ``letter A`` (by height)."""
    from rpg.artifact import task_sources
    from rpg.domain.task import Task
    from rpg.env.loading import task_data
    from rpg.errors import TaskInvalid
    from rpg.validate.verdicts import object_json

    try:
        task = Task(task_data(task_sources(directory), where=str(directory)))
    except TaskInvalid as exc:
        raise SessionError(f"cannot inspect {directory}: {exc}") from None
    task.set_goal_state()
    task.step(50)
    objs = [o for o in object_json(task) if o["kind"] != "goal_patch"]
    return [f"letter {o['label']}" if o["kind"] == "semantic_cube" else o["color"]
            for o in sorted(objs, key=lambda o: o["position"][2])]


def check_final(directory: Path, expected: str) -> list[str]:
    m = re.match(r"\s*tower bottom to top:\s*(.+)$", expected)
    if not m:
        return []
    want = [w.strip().replace("'", "") for w in m.group(1).split(",")]
    got = goal_tower(directory)
    return [] if got == want else [f"goal tower is {', '.join(got)}, expected {', '.join(want)}"]


def run_session(path: str | Path, out_dir: str | Path, seed: int = 0,
                name: str | None = None, enabled: frozenset[str] = frozenset()) -> tuple[Path, list[StepResult]]:
    """Run a session into ``out_dir/<name>/`` (a family); return it and one result per step.

    ``name`` (e.g. the library entry's) overrides the session file's own ``name``;
    ``enabled`` names optional gates every version must pass too (``rpg build``: all).

    Raises:
        SessionError: an unreadable session or an invalid name.
    """
    doc = load_session(path)
    if name is not None:
        doc["name"] = check_name(name, "family name")
    out_dir = Path(out_dir)
    first = doc["steps"][0]
    results: list[StepResult] = []
    compiled = compile_instruction(first["instruction"], out_dir, seed, name=doc["name"], enabled=enabled)
    if not compiled.valid:
        return compiled.path, [StepResult(0, first["instruction"], False, problems=["validation failed after repair"])]
    fam = create_family(compiled.path)
    results.append(StepResult(0, first["instruction"], True, version="v0"))
    for i, step in enumerate(doc["steps"][1:], 1):
        head = fam.load().head
        try:
            r = steer(fam.path, step["edit"], seed, enabled=enabled)
        except (SteerError, ValueError) as exc:
            results.append(StepResult(i, step["edit"], False, problems=[str(exc)]))
            break
        res = StepResult(i, step["edit"], r.valid, r.intent, None if r.reference is None else f"v{r.reference}",
                         None if r.version is None else f"v{r.version}", notes=r.notes)
        if not r.valid:
            res.problems.append("validation failed after repair")
        want_intent = step.get("expected_intent")
        if want_intent and want_intent != r.intent:
            res.problems.append(f"intent {r.intent}, expected {want_intent}")
        want_ref = step.get("expected_reference")
        if want_ref:
            want = head if want_ref == "current" else int(str(want_ref).lstrip("v"))
            if r.reference != want:
                res.problems.append(f"reference {res.reference}, expected {want_ref} (v{want})")
        if step.get("expected_final") and r.version is not None:
            res.problems += check_final(Family(fam.path).version_dir(r.version), step["expected_final"])
        res.ok = res.ok and not res.problems
        results.append(res)
        if not r.valid:
            break
    return fam.path, results
