"""Optional pass 2 by a language model (``--codegen llm``), grounded as in the paper.

Paper, "Code Generation" and appendix "In-Context Examples": the model writes ``code.py``
and ``goal_state_code.py`` from the TaskSchema with three context sources:

* API documentation generated from the docstrings of :mod:`rpg.task_api` (:func:`api_docs`);
* a catalog of common errors (:data:`COMMON_ERRORS`);
* 2-3 reference tasks retrieved from a task library by asset class, reasoning type,
  complexity and action primitive (:func:`retrieve_references`).

Failures are repaired by specialist fix agents (:data:`FIX_AGENTS`, one per failure class)
that receive the failure details and the previously failed attempts as negative examples.
The same gates judge the model's code as the builtin emitter's.
"""

from __future__ import annotations

import inspect
import json
from pathlib import Path

from rpg.codegen.emit import GeneratedCode
from rpg.schema.model import TaskSchema

REFERENCES_PER_PROMPT = 3
"""Reference tasks retrieved for one prompt (paper: 2-3)."""

COMMON_ERRORS: tuple[str, ...] = (
    "Import only with 'from rpg.task_api import NAME', 'import numpy as np' and 'import math'; os, sys, subprocess, "
    "open(), eval/exec, type(), and any name or attribute starting with '_' are rejected.",
    "code.py defines exactly one subclass of BlockTask with assets(), initial_state(rng) and goal().",
    "Every name in goal() must be the name of an asset returned by assets().",
    "initial_state(rng) draws only from rng (a numpy Generator); use sample_scattered for rho_0.",
    "A cube resting on the table has its centre at z = TABLE_TOP_Z + edge / 2 (0.97 m for 4 cm cubes); each stacked level adds edge + 0.0005 m.",
    "Keep every object inside the workspace x in [0.40, 0.70] m, y in [-0.25, 0.25] m, in the initial and the goal state.",
    "goal_state_code.py defines goal_state(task) that calls task.set_state({name: Pose(...)}) with every object.",
    "success() must be false at reset: the initial state must not already satisfy the goal.",
    "Labels that a goal reads must face the camera ('front') or up and stay unoccluded.",
    "Private attributes (names starting with '_') are not part of the task API.",
)
"""Errors seen when models write task code, given to every prompt."""

FIX_AGENTS: dict[str, str] = {
    "syntax": "SyntaxFixAgent", "api_usage": "APIUsageFixAgent", "runtime": "RuntimeFixAgent",
    "success_check": "SuccessCheckFixAgent", "visibility": "SuccessCheckFixAgent",
    "stability": "StructureStabilityFixAgent", "constraint": "StructureStabilityFixAgent",
    "bounds": "GeometricBoundsFixAgent",
}
"""Failure class -> specialist fix agent (paper, appendix "Iterative Repair and Agent Taxonomy")."""


def api_docs() -> str:
    """API documentation of :mod:`rpg.task_api`, generated from its public docstrings."""
    from rpg import task_api

    lines = [(task_api.__doc__ or "").strip(), ""]
    for name in task_api.__all__:
        obj = getattr(task_api, name)
        if inspect.ismodule(obj):
            lines.append(f"{name}: module. {(obj.__doc__ or '').strip().splitlines()[0]}")
            continue
        try:
            sig = str(inspect.signature(obj))
        except (TypeError, ValueError):
            sig = ""
        doc = " ".join((inspect.getdoc(obj) or "").split("\n\n")[0].split())
        lines.append(f"{name}{sig}: {doc}")
        if inspect.isclass(obj) and name == "BlockTask":
            for meth, fn in sorted(vars(obj).items()):
                if not meth.startswith("_") and callable(fn):
                    mdoc = " ".join((inspect.getdoc(fn) or "").split("\n\n")[0].split())
                    lines.append(f"  BlockTask.{meth}{inspect.signature(fn)}: {mdoc}")
    return "\n".join(lines)


def _tags_score(want: dict, have: dict) -> tuple:
    return (len(set(want["asset_class"]) & set(have.get("asset_class", []))),
            want["reasoning"] == have.get("reasoning"),
            want["complexity"] == have.get("complexity"),
            len(set(want["primitives"]) & set(have.get("primitives", []))))


def retrieve_references(schema: TaskSchema, library: str | Path | None, k: int = REFERENCES_PER_PROMPT) -> list[dict]:
    """The ``k`` library tasks closest to the schema by asset class, reasoning type,
    complexity and action primitives (ties by name); each ``{"name", "tags", "code", "goal_state_code"}``.
    Only artifacts whose files match their content hash are shown, their code as hashed
    (read once, no links)."""
    from rpg.artifact import ArtifactError, rehash

    if library is None or not Path(library).is_dir():
        return []
    want = schema.tags()
    found = []
    for d in sorted(Path(library).iterdir()):
        artifact = d if (d / "task.yaml").is_file() else d / "v0"
        if not (artifact / "task.yaml").is_file():
            continue
        try:
            _, doc, sources, digest = rehash(artifact)
        except ArtifactError:
            continue
        if digest != doc.get("content_hash"):
            continue
        tags = doc.get("tags", {})
        found.append((_tags_score(want, tags), d.name, sources, tags))
    found.sort(key=lambda t: (tuple(-x for x in t[0]), t[1]))
    return [{"name": name, "tags": tags, "code": src["code.py"], "goal_state_code": src["goal_state_code.py"]}
            for _, name, src, tags in found[:k]]


def _prompt(schema: TaskSchema, references: list[dict]) -> str:
    refs = "\n\n".join(f"### Reference task {r['name']} (tags {json.dumps(r['tags'], sort_keys=True)})\n"
                       f"code.py:\n{r['code']}\ngoal_state_code.py:\n{r['goal_state_code']}" for r in references)
    errors = "\n".join(f"- {e}" for e in COMMON_ERRORS)
    return (f"You write MuJoCo task code for rpg. Answer with ONE JSON object "
            f'{{"code": "<code.py>", "goal_state_code": "<goal_state_code.py>"}} and nothing else.\n\n'
            f"## API (rpg.task_api)\n{api_docs()}\n\n## Common errors to avoid\n{errors}\n\n{refs}\n\n"
            f"## The task (TaskSchema)\n{schema.model_dump_json()}\n")


def _validated(doc: dict) -> GeneratedCode:
    from rpg.validate.static import StaticViolation, check_source

    code, goal = doc.get("code"), doc.get("goal_state_code")
    if not isinstance(code, str) or not isinstance(goal, str) or not code.strip() or not goal.strip():
        raise ValueError("the answer needs non-empty strings 'code' and 'goal_state_code'")
    try:
        check_source(code, "code.py")
        check_source(goal, "goal_state_code.py")
    except StaticViolation as exc:
        raise ValueError(str(exc)) from None
    return GeneratedCode(code=code if code.endswith("\n") else code + "\n",
                         goal_state_code=goal if goal.endswith("\n") else goal + "\n")


class LLMCoder:
    """Writes and repairs task code with a model; one instance per compilation.

    Args:
        client: an :class:`rpg.schema.llm.LLMClient` (its record includes these exchanges).
        library: the task library to retrieve reference tasks from.
    """

    def __init__(self, client, library: str | Path | None = "library"):
        self.client = client
        self.library = library
        self.attempts: list[dict] = []

    def __call__(self, schema: TaskSchema, failure: dict | None = None) -> GeneratedCode:
        """First call: write the code.  Later calls (``failure`` given): the fix agent for the
        failure's class rewrites it, shown the failure and every earlier failed attempt.

        Raises:
            ProviderError / ModelOutputError: as for the schema front end.
        """
        from rpg.schema.llm import ask_validated

        messages = [{"role": "system", "content": _prompt(schema, retrieve_references(schema, self.library))}]
        purpose = "codegen"
        if failure is None:
            messages.append({"role": "user", "content": "Write the task code."})
        else:
            agent = FIX_AGENTS.get(failure.get("kind", "runtime"), "RuntimeFixAgent")
            purpose = f"repair:{agent}"
            self.attempts.append({"gate": failure.get("gate"), "kind": failure.get("kind"), "message": failure.get("message", "")[:500]})
            history = "\n".join(f"- attempt {i + 1} failed gate {a['gate']} ({a['kind']}): {a['message']}"
                                for i, a in enumerate(self.attempts))
            messages.append({"role": "user", "content":
                             f"You are the {agent}. The previous code failed validation.\n"
                             f"Failure details: {json.dumps(failure, default=str)[:4000]}\n"
                             f"Failed attempts so far (do not repeat these strategies):\n{history}\n"
                             "Return the corrected code."})
        return ask_validated(self.client, messages, purpose, _validated)
