"""The language-model front end: instruction -> TaskSchema through any litellm model.

The model gets a prompt grounded in the domain (frame conventions and numbers from
:mod:`rpg.domain.constants`, the predicate catalog from the predicates' own docstrings, the
TaskSchema JSON Schema, and a worked example built by the builtin parser) and must answer
with one JSON object.  The answer is validated into a :class:`TaskSchema`; validation errors
go back to the model for at most :data:`MAX_SCHEMA_RETRIES` more tries.  The same
feasibility checks and validation gates then judge it as they judge the builtin parser.

Every request and response is recorded (:class:`LLMClient` ``records``; written to the
artifact as ``llm_log.jsonl``), and a record replays offline: ``rpg compile --replay DIR``.
litellm is imported only when a model is actually called.
"""

from __future__ import annotations

import json
import os
import re
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

from pydantic import ValidationError

from rpg._version import __version__
from rpg.artifact import MODEL_RECORD
from rpg.errors import BadInput, ProviderFailure, TaskInvalid
from rpg.schema.model import TaskSchema, json_schema

MAX_SCHEMA_RETRIES = 3
"""Extra tries after the model's first answer fails validation."""

REQUEST_TIMEOUT_S = 120.0
"""Timeout of one model request, s."""

LOG_FILE = MODEL_RECORD
"""The record's name in an artifact (in its content hash and file manifest: :mod:`rpg.artifact`)."""


class ProviderError(ProviderFailure):
    """The model provider failed (network, authentication, rate limit, unknown model).

    Never a task failure: the CLI reports it with exit code 3.
    """


class ModelOutputError(TaskInvalid, ValueError):
    """The model did not produce a valid TaskSchema within the retry budget."""


class ReplayError(BadInput):
    """A replay record is missing, malformed or exhausted."""


@dataclass
class LLMClient:
    """Calls a litellm model, recording every exchange; or replays a record offline.

    Args:
        model: a litellm model name (``openai/gpt-4o``, ``ollama/llama3``, ...).
        mock_responses: canned answers (strings, or exceptions to raise) passed to litellm
            as ``mock_response``, one per call, for tests and dry runs: no network is used.
        replay: recorded exchanges to answer from instead of calling the model.
        completion_kwargs: extra arguments for ``litellm.completion`` (``api_base``...).
    """

    model: str
    mock_responses: list | None = None
    replay: list[dict] | None = None
    completion_kwargs: dict = field(default_factory=dict)
    records: list[dict] = field(default_factory=list)

    def complete(self, messages: list[dict], purpose: str) -> str:
        """The model's answer to ``messages``.

        Raises:
            ProviderError: the provider call failed.
            ReplayError: replaying, and the record has no matching exchange.
        """
        seq = len(self.records)
        if self.replay is not None:
            if seq >= len(self.replay):
                raise ReplayError(f"the replay record has {len(self.replay)} exchanges; call {seq + 1} was asked for")
            rec = self.replay[seq]
            if rec.get("purpose") != purpose or rec.get("request", {}).get("messages") != messages:
                raise ReplayError(f"exchange {seq + 1} of the record does not match this request "
                                  "(the compiler or the instruction changed since it was recorded)")
            self.records.append(rec)
            return rec["response"]
        kwargs = {"model": self.model, "messages": messages, "temperature": 0.0, "timeout": REQUEST_TIMEOUT_S,
                  **self.completion_kwargs}
        if self.mock_responses is not None:
            if seq >= len(self.mock_responses):
                raise ProviderError("no mock response left for this request")
            kwargs["mock_response"] = self.mock_responses[seq]
        import litellm  # lazy: importing litellm costs seconds

        try:
            resp = litellm.completion(**kwargs)
            text = resp.choices[0].message.content or ""
            usage = getattr(resp, "usage", None)
        except Exception as exc:  # noqa: BLE001 - every failure inside the provider call is a provider error
            raise ProviderError(f"model provider error ({self.model}): {type(exc).__name__}: {str(exc).splitlines()[0][:300]}") from None
        self.records.append({
            "seq": seq, "purpose": purpose, "model": self.model,
            "request": {"messages": messages, "temperature": 0.0},
            "response": text,
            "usage": {k: getattr(usage, k, None) for k in ("prompt_tokens", "completion_tokens", "total_tokens")} if usage else {},
        })
        return text

    def log_text(self, instruction: str, command: str = "compile") -> str:
        """The ``llm_log.jsonl`` record: a header line (the command and its input text), then
        one line per exchange."""
        head = {"type": "header", "rpg_version": __version__, "model": self.model, "instruction": instruction,
                "command": command}
        lines = [json.dumps(head, sort_keys=True)] + [json.dumps({"type": "exchange", **r}, sort_keys=True) for r in self.records]
        return "\n".join(lines) + "\n"


def load_record(path: str | Path) -> tuple[dict, list[dict]]:
    """Read ``llm_log.jsonl`` (or the artifact directory holding it): (header, exchanges).

    A record inside a task artifact (a directory with ``task.yaml``) is replayed only if it
    is that artifact's own, unchanged (:func:`rpg.artifact.check_model_record`: its SHA-256
    in task.yaml's file manifest, the content hash intact), so a tampered record is refused
    before anything is built from it.  A record file outside any artifact is replayed as
    given: it is the caller's own.

    Raises:
        ReplayError: missing, malformed, or not the artifact's recorded model record.
    """
    from rpg.artifact import MAX_MANIFEST_FILE, ArtifactError, check_model_record, read_bytes

    p = Path(path)
    if p.is_dir():
        p = p / LOG_FILE
    try:
        data = read_bytes(p, MAX_MANIFEST_FILE)
        if os.path.lexists(p.parent / "task.yaml"):
            check_model_record(p.parent, p.name, data)
        rows = [json.loads(line) for line in data.decode("utf-8").splitlines() if line.strip()]
    except ArtifactError as exc:
        raise ReplayError(str(exc)) from None
    except (OSError, ValueError) as exc:
        raise ReplayError(f"cannot read the model record {p}: {str(exc).splitlines()[0]}") from None
    if not rows or rows[0].get("type") != "header" or "instruction" not in rows[0]:
        raise ReplayError(f"{p} is not an rpg model record (no header line)")
    return rows[0], [r for r in rows[1:] if r.get("type") == "exchange"]


# ---------------------------------------------------------------------------
# The prompt
# ---------------------------------------------------------------------------


def _predicate_catalog() -> str:
    from dataclasses import MISSING, fields

    from rpg.domain.predicates import PREDICATES

    lines = []
    for name, cls in sorted(PREDICATES.items()):
        args = ", ".join(f.name.rstrip("_") + ("" if f.default is MISSING else f"={f.default!r}") for f in fields(cls))
        doc = " ".join((cls.__doc__ or "").split())
        lines.append(f"- {name}({args}): {doc}")
    return "\n".join(lines)


def _example() -> str:
    from rpg.schema.builtin import parse

    return parse("Place a blue cube on top of a red cube on the table").model_dump_json()


def system_prompt() -> str:
    """The grounding the model receives (deterministic for one compiler version)."""
    from rpg.domain import constants as C
    from rpg.domain.palette import PALETTE

    catalog = _predicate_catalog()
    example = _example()
    schema = json.dumps(json_schema(), sort_keys=True)
    z0 = C.TABLE_TOP_Z + C.CUBE_EDGE / 2
    return textwrap.dedent(f"""\
        You turn a robot-manipulation instruction into a TaskSchema for rpg, a MuJoCo block domain.
        Answer with ONE JSON object that validates against the JSON Schema below; no prose.

        Domain (SI units):
        - Cubes of edge {C.CUBE_EDGE} m on a table whose top is at z = {C.TABLE_TOP_Z} m.
        - Workspace: x in [{C.WORKSPACE_X[0]}, {C.WORKSPACE_X[1]}] m, y in [{C.WORKSPACE_Y[0]}, {C.WORKSPACE_Y[1]}] m.
        - Frame: the robot is at the origin looking along +x; left = +y, right = -y,
          in front of = smaller x, behind = larger x; "from left to right" runs +y to -y.
        - Asset kinds: colored_cube (color), semantic_cube (label A-Z, 0-9, + - = x), goal_patch (flat, color, shape square|long).
        - Colors: {", ".join(sorted(PALETTE))}.
        - A cube resting on the table has centre z = {z0:.4f}; each level of a stack adds
          {C.CUBE_EDGE + C.SPAWN_CLEARANCE:.4f} m. Goal patches lie at z = {C.TABLE_TOP_Z + C.PATCH_THICKNESS / 2:.4f}.
        - At most {C.MAX_OBJECTS} objects, 26 distinct letters, 10 distinct digits.

        goal is a predicate tree: {{"predicate": name, ...arguments}}; combine with
        {{"predicate": "and", "children": [...]}}. Predicates:
        """) + catalog + textwrap.dedent("""

        goal_layout gives every asset a pose (position, quaternion w x y z) in which the goal holds
        and the structure is physically stable; initial_state.fixed gives the goal patches' poses.
        paraphrases: at least 3 rewordings of the instruction.

        Example (instruction "Place a blue cube on top of a red cube on the table"):
        """) + example + "\n\nJSON Schema of TaskSchema:\n" + schema + "\n"


def _json_object(text: str) -> dict:
    m = re.search(r"\{.*\}", text, re.DOTALL)
    if not m:
        raise ValueError("the answer holds no JSON object")
    doc = json.loads(m.group(0))
    if not isinstance(doc, dict):
        raise ValueError("the answer is not a JSON object")
    return doc


def _errors(exc: Exception) -> str:
    if isinstance(exc, ValidationError):
        return "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in exc.errors()[:10])
    return str(exc).splitlines()[0][:500]


def ask_validated(client: LLMClient, messages: list[dict], purpose: str, validate, max_retries: int = MAX_SCHEMA_RETRIES):
    """Ask until ``validate(json_object)`` accepts the answer; feed its errors back.

    Raises:
        ProviderError: the provider failed.
        ModelOutputError: no acceptable answer within ``max_retries`` extra tries.
    """
    last = ""
    for _ in range(max_retries + 1):
        answer = client.complete(messages, purpose)
        try:
            return validate(_json_object(answer))
        except (ValueError, ValidationError) as exc:
            last = _errors(exc)
            messages = messages + [
                {"role": "assistant", "content": answer},
                {"role": "user", "content": f"That is not a valid answer: {last}. Answer with the corrected JSON object only."},
            ]
    raise ModelOutputError(f"the model gave no valid {purpose} answer in {max_retries + 1} tries; last error: {last}")


def llm_parse(instruction: str, client: LLMClient, max_retries: int = MAX_SCHEMA_RETRIES) -> TaskSchema:
    """Ask the model for a TaskSchema; feed validation errors back up to ``max_retries`` times.

    Raises:
        ProviderError: the provider failed.
        ModelOutputError: no valid TaskSchema within the budget (message has the last error).
    """
    messages = [{"role": "system", "content": system_prompt()}, {"role": "user", "content": instruction}]

    def validate(doc: dict) -> TaskSchema:
        from rpg.schema.builtin import check_mentions

        doc["instruction"] = instruction
        schema = TaskSchema.model_validate(doc)
        try:
            check_mentions(instruction, schema)  # the same accounting as the builtin parser's
        except ValueError as exc:
            raise ValueError(f"the schema does not match the instruction: {exc}") from None
        return schema

    return ask_validated(client, messages, "schema", validate, max_retries)
