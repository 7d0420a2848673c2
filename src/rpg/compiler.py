"""The compiler: instruction -> schema -> code -> validate -> repair -> task artifact.

Python API::

    from rpg.compiler import compile_instruction
    result = compile_instruction("Stack the red block on the blue block", out_dir="library")
    result.path, result.valid

An artifact directory holds ``task.yaml``, ``code.py``, ``goal_state_code.py``,
``validation.log``, ``validation.json``, ``initial.png`` and ``goal.png``.  It appears whole
or not at all: it is written to a temporary directory and renamed into place.
"""

from __future__ import annotations

import os
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path

from rpg._version import __version__
from rpg.artifact import (
    LIBRARY_LOCK,  # noqa: F401 - part of the compiler's API
    ArtifactError,  # noqa: F401
    atomic_replace,
    content_hash,  # noqa: F401
    gates_passed,
    load_artifact,  # noqa: F401
    rehash,
    set_aside,
    staging_dir,
    task_document,  # noqa: F401
    task_sources,
    write_artifact_files,
    write_logs,
)
from rpg.codegen import generate
from rpg.errors import BadInput
from rpg.repair import route
from rpg.schema.builtin import parse
from rpg.schema.citations import stating_paraphrases
from rpg.schema.feasibility import check_feasibility
from rpg.schema.model import TaskSchema
from rpg.validate.gates import check_gate_names, check_optional_gates
from rpg.validate.static import StaticViolation, check_source

MAX_CYCLES = 5
"""Validate-repair cycles before a task is rejected (paper, Iterative Repair)."""

MAX_ATTEMPTS_PER_OPERATOR = 3
"""Attempts per repair operator (paper, Iterative Repair)."""


@dataclass
class CompileResult:
    """Outcome of one compilation."""

    valid: bool
    path: Path
    schema: TaskSchema
    gates: list[dict]
    log: list[str] = field(default_factory=list)
    content_hash: str = ""
    set_aside: list[tuple[str, str]] = field(default_factory=list)
    """(what, why) for each word or sentence of the user's text set aside as naming nothing of the task
    (:func:`rpg.artifact.set_aside`): recorded in task.yaml's accounting and printed by ``rpg compile``."""

    def to_json(self) -> dict:
        return {"valid": self.valid, "path": str(self.path), "name": self.schema.name,
                "content_hash": self.content_hash, "repairs": [r.model_dump() for r in self.schema.repairs],
                "set_aside": [{"said": what, "why": why} for what, why in self.set_aside],
                "gates": [{"gate": g["gate"], "status": g["status"], **({"message": g["message"]} if "message" in g else {})}
                          for g in self.gates],
                "snapshots": {k: str(self.path / f"{k}.png") for k in ("initial", "goal") if (self.path / f"{k}.png").exists()}}


def validate_files(directory: Path, seed: int = 0, disabled: frozenset[str] = frozenset(),
                   snapshots: bool = False, tolerances: dict | None = None,
                   sources: dict[str, str] | None = None, enabled: frozenset[str] = frozenset(),
                   name: str = "task") -> list[dict]:
    """Run every gate on the code files in ``directory``; return the gate results in order.

    ``sources`` (file name -> text, as read once by :func:`rpg.artifact.task_sources`) is
    what the gates check and the worker runs; read from ``directory`` when not given.
    ``enabled`` names optional gates (:data:`rpg.validate.gates.OPTIONAL_GATES`) to run after
    the others, when they all passed.
    """
    results = []
    try:
        sources = task_sources(directory) if sources is None else sources
    except ArtifactError as exc:
        return [{"gate": "text", "status": "fail", "kind": "api_usage", "message": str(exc), "duration_s": 0.0, "details": {}}]
    if "text" in disabled:
        results.append({"gate": "text", "status": "skipped", "duration_s": 0.0, "details": {}})
    else:
        t0 = time.perf_counter()
        try:
            for fname, text in sources.items():
                check_source(text, fname)
            results.append({"gate": "text", "status": "pass", "duration_s": time.perf_counter() - t0, "details": {}})
        except StaticViolation as exc:
            results.append({"gate": "text", "status": "fail", "kind": exc.kind, "message": str(exc),
                            "duration_s": time.perf_counter() - t0, "details": {"line": exc.line}})
            return results
    from rpg.validate.data import gate_seeds, start_task_data
    from rpg.validate.sandbox import WorkerError

    try:  # the child runs while the simulator side is imported
        pending = start_task_data(sources, gate_seeds(seed, enabled), restricted="text" not in disabled)
    except WorkerError:
        pending = None
    from rpg.validate.verdicts import run_gates

    return results + run_gates(sources, seed, disabled, enabled, tolerances,
                               snapshots_to=Path(directory) if snapshots else None, name=name, pending=pending)


def _isolation_note() -> list[str]:
    """The sandbox layers missing here, said once on stderr and in every validation.log."""
    from rpg.validate.isolation import warn_once

    note = warn_once()
    return [note] if note else []


def first_failure(gates: list[dict]) -> dict | None:
    return next((g for g in gates if g["status"] == "fail"), None)


def _log_line(g: dict) -> str:
    msg = f" - {g['message']}" if g.get("message") else ""
    return f"gate {g['gate']:<11} {g['status'].upper():<7} {g.get('duration_s', 0.0) * 1000:7.1f} ms{msg}"


def snapshots_wanted() -> bool:
    """Whether a build renders ``initial.png`` and ``goal.png``: yes, unless the environment variable ``RPG_SNAPSHOTS`` is
    ``0``, ``off``, ``no`` or ``false`` (a batch job or a test run that looks at no pictures: each costs about a fifth of a
    second of software rendering).  A task without them is whole, as one built on a machine without OpenGL is; ``rpg
    render`` draws them later."""
    return os.environ.get("RPG_SNAPSHOTS", "1").strip().lower() not in ("0", "off", "no", "false")


def build(schema: TaskSchema, out_dir: Path, seed: int = 0, disabled: frozenset[str] = frozenset(),
          backend: str = "builtin", model: str | None = None, name: str | None = None,
          extra_files=None, coder=None, author: str | None = None,
          enabled: frozenset[str] = frozenset(), written: str | None = None) -> CompileResult:
    """Passes 2-4 on a schema: generate, validate, repair; write the artifact atomically.

    ``extra_files`` (name -> text, or a callable returning that once the code exists, e.g.
    the model record ``llm_log.jsonl``) are written into the artifact too, in its file
    manifest (the model record in its content hash too).  ``coder`` (an
    :class:`rpg.codegen.llm.LLMCoder`) writes the code instead of the builtin emitter, and
    its fix agents repair it.  ``author`` (who wrote the task) is recorded in the provenance
    when given.  ``enabled`` names optional gates to run
    (:data:`rpg.validate.gates.OPTIONAL_GATES`).  ``written`` is the text as the user wrote it
    (recorded and accounted for where sentences of it were set aside: :func:`rpg.artifact.task_document`).
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    log: list[str] = [f"rpg {__version__} compile {schema.name!r} (backend {backend}, seed {seed})", *_isolation_note()]
    log += [f"feasibility repair {r.operator}: {r.reason}" for r in schema.repairs if r.stage == "feasibility"]
    attempts: dict[str, int] = {}
    tmp = staging_dir(out_dir, schema.name)
    gates: list[dict] = []
    try:
        failure = None
        for cycle in range(1, MAX_CYCLES + 1):
            schema, said = stating_paraphrases(schema)  # each paraphrase states G (after each repair too)
            log += [f"paraphrases: {line}" for line in said]
            code = generate(schema) if coder is None else coder(schema, failure)
            (tmp / "code.py").write_text(code.code)
            (tmp / "goal_state_code.py").write_text(code.goal_state_code)
            gates = validate_files(tmp, seed, disabled, snapshots=snapshots_wanted(), tolerances=schema.tolerances.model_dump(),
                                   enabled=enabled, name=schema.name)
            log.append(f"cycle {cycle}:")
            log += ["  " + _log_line(g) for g in gates]
            failure = first_failure(gates)
            if failure is None and gates_passed(gates):
                break
            if coder is not None:
                from rpg.codegen.llm import FIX_AGENTS

                if failure is None:
                    break
                agent = FIX_AGENTS.get(failure.get("kind", "runtime"), "RuntimeFixAgent")
                attempts[agent] = attempts.get(agent, 0) + 1
                if attempts[agent] > MAX_ATTEMPTS_PER_OPERATOR:
                    log.append(f"  repair {agent}: attempt budget exhausted")
                    break
                log.append(f"  repair attempt {attempts[agent]}: {agent} ({failure.get('kind')}) -> model rewrite, "
                           f"shown the failure and {len(coder.attempts)} earlier failed attempt(s)")
                continue
            routed = route(failure or {})
            if routed is None:
                break
            kind, ops = routed
            repaired = None
            for op in ops:
                attempts[op.__name__] = attempts.get(op.__name__, 0) + 1
                if attempts[op.__name__] > MAX_ATTEMPTS_PER_OPERATOR:
                    log.append(f"  repair {op.__name__}: attempt budget exhausted")
                    continue
                repaired = op(schema, failure)
                if repaired is None:
                    log.append(f"  repair attempt {attempts[op.__name__]}: {op.__name__} ({kind}) has no fix")
                    continue
                log.append(f"  repair attempt {attempts[op.__name__]}: {op.__name__} ({kind}) -> {repaired.repairs[-1].reason}")
                break
            if repaired is None:
                break
            schema = repaired
        valid = gates_passed(gates)
        log.append("result: VALID" if valid else "result: REJECTED")
        extras = extra_files() if callable(extra_files) else extra_files
        digest, doc = write_artifact_files(tmp, schema, seed, backend, model, gates, log, author, extras, written)
        aside = set_aside(doc)
        slug = name or schema.name
        target = out_dir / slug if valid else out_dir / ".rejected" / slug
        atomic_replace(tmp, target)
        return CompileResult(valid, target, schema, gates, log, digest, aside)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def check_output_dir(out_dir: Path) -> None:
    """Refuse an output path that exists and is not a directory.

    Raises:
        BadInput: ``out_dir`` is a file (or another non-directory).
    """
    if out_dir.exists() and not out_dir.is_dir():
        raise BadInput(f"output {out_dir} exists and is not a directory; give a directory (it is created if missing)")


def check_text(text: str, what: str) -> str:
    """``text`` if it can be written as UTF-8 (no lone surrogates from undecodable bytes).

    Raises:
        BadInput: the text holds bytes that are not UTF-8.
    """
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise BadInput(f"{what} is not valid UTF-8 text") from None
    return text


def compile_instruction(instruction: str, out_dir: str | Path = "out", seed: int = 0,
                        disabled: frozenset[str] = frozenset(), model: str | None = None,
                        name: str | None = None, llm=None, replay: str | Path | None = None,
                        builtin_first: bool = False, codegen: str = "builtin",
                        library: str | Path | None = "library", author: str | None = None,
                        enabled: frozenset[str] = frozenset()) -> CompileResult:
    """Compile an instruction into a task artifact under ``out_dir/<slug>/`` (or ``out_dir/<name>/``).

    Args:
        instruction: the task in plain language (ignored when replaying).
        model: ``None``/``"builtin"`` for the offline parser, or a litellm model name.
        llm: an :class:`rpg.schema.llm.LLMClient` to use instead of a new one (tests, dry runs).
        replay: an artifact directory or ``llm_log.jsonl`` to recompile from, offline.
        builtin_first: with a model, read with the builtin parser first and ask the model
            only for what the builtin parser cannot read.
        codegen: ``builtin`` (the emitter) or ``llm`` (the model writes the code, grounded
            in the API docs, common errors and reference tasks from ``library``).
        author: who wrote the instruction, recorded in ``task.yaml`` provenance (groups
            ``rpg diversity --by author``); None records nothing.
        enabled: optional gates to run too (``{"solvable"}``; see
            :data:`rpg.validate.gates.OPTIONAL_GATES`).

    Raises:
        ParseError: the builtin front end cannot read the instruction.
        InfeasibleTask: the task cannot be realised and cannot be repaired.
        ProviderError: the model provider failed.
        ModelOutputError: the model gave no valid TaskSchema within its retries.
        ReplayError: the replay record is missing, malformed or does not match.
        ValueError: unknown colour or label.
        BadInput: an unknown gate name in ``disabled`` or ``enabled``.
    """
    from rpg.validate.sandbox import prepare

    prepare()  # the validation child starts up while the instruction is read
    from rpg.schema.builtin import ParseError

    disabled = check_gate_names(disabled)
    enabled = check_optional_gates(enabled)
    check_output_dir(Path(out_dir))
    if isinstance(instruction, str):
        check_text(instruction, "the instruction")
    if codegen not in ("builtin", "llm"):
        raise ValueError(f"codegen must be 'builtin' or 'llm', not {codegen!r}")
    if replay is not None:
        from rpg.schema.llm import LLMClient, load_record

        header, exchanges = load_record(replay)
        instruction, model = header["instruction"], header["model"]
        llm = LLMClient(model, replay=exchanges)
    elif llm is None and model not in (None, "builtin"):
        from rpg.schema.llm import LLMClient

        llm = LLMClient(model)
    backend = "builtin"
    if llm is None:
        schema = parse(instruction)
    else:
        from rpg.schema.llm import llm_parse

        schema = None
        if builtin_first:
            try:
                schema = parse(instruction)
            except ParseError:
                schema = None
        if schema is None:
            schema = llm_parse(instruction, llm)
            backend = "litellm"
    schema = check_feasibility(schema)
    coder = None
    if codegen == "llm":
        if llm is None:
            raise ValueError("--codegen llm needs a model: add --model MODEL (any litellm model name)")
        from rpg.codegen.llm import LLMCoder

        coder = LLMCoder(llm, library)

    def extra() -> dict | None:
        return {"llm_log.jsonl": llm.log_text(instruction)} if llm is not None and llm.records else None

    return build(schema, Path(out_dir), seed, frozenset(disabled), backend=backend,
                 model=llm.model if llm is not None else None, name=name, extra_files=extra, coder=coder,
                 author=author, enabled=enabled, written=instruction)


def revalidate(directory: str | Path, disabled: frozenset[str] = frozenset(),
               enabled: frozenset[str] = frozenset()) -> CompileResult:
    """Re-run every gate (and the optional ones in ``enabled``) on an artifact as it is (e.g.
    after a hand edit); rewrite its logs.

    Raises:
        BadInput: an unknown gate name.
    """
    disabled = check_gate_names(disabled)
    enabled = check_optional_gates(enabled)
    d = Path(directory)
    schema, doc, sources, digest = rehash(d)
    seed = int(doc.get("provenance", {}).get("seed", 0))
    gates = validate_files(d, seed, disabled, snapshots=False, tolerances=schema.tolerances.model_dump(), sources=sources,
                           enabled=enabled, name=schema.name)
    log = [f"rpg {__version__} validate {d}", *_isolation_note()] + [_log_line(g) for g in gates]
    valid = gates_passed(gates)
    log.append("result: VALID" if valid else "result: INVALID")
    write_logs(d, log, gates)
    return CompileResult(valid, d, schema, gates, log, digest)
