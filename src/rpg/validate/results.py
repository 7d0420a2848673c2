"""The worker's answers as the parent accepts them: schema-checked data, never trusted."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from rpg.validate.sandbox import WorkerError


class GateResult(BaseModel):
    """One gate result as the worker reports it; anything else is refused as malformed."""

    model_config = ConfigDict(extra="forbid")

    gate: Literal["compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility", "solvable"]
    status: Literal["pass", "fail", "skipped"]
    kind: Literal["syntax", "api_usage", "runtime", "success_check", "stability", "bounds", "constraint", "visibility",
                  "solvability"] | None = None
    message: str | None = Field(None, max_length=20000)
    duration_s: float = Field(ge=0.0)
    details: dict = Field(default_factory=dict)


class ValidateResult(BaseModel):
    """The worker's answer to a ``validate`` request."""

    model_config = ConfigDict(extra="forbid")

    gates: list[GateResult] = Field(max_length=16)
    snapshots: dict[Literal["initial", "goal"], str | None] | None = None


def checked_validate_result(result: object) -> dict:
    """The worker's validate result, schema-checked.

    Raises:
        WorkerError: it does not match :class:`ValidateResult`.
    """
    try:
        return ValidateResult.model_validate(result).model_dump(exclude_none=True)
    except ValidationError as exc:
        raise WorkerError(f"task worker returned a malformed result: {str(exc).splitlines()[0][:200]}") from None
