"""TaskSchema: the typed representation pass 1 produces and pass 2 consumes.

Its JSON Schema is exported to ``schemas/task.schema.json`` (``rpg schema`` rewrites it; a
test keeps the two in sync).  A schema fully determines a task
T = (assets, rho_0, G, instruction, paraphrases) together with a goal layout that
realises G.
"""

from __future__ import annotations

import json
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from rpg.domain import constants as C
from rpg.domain.assets import ColoredCube, GoalPatch, SemanticCube
from rpg.domain.predicates import Predicate, from_dict
from rpg.domain.state import Pose


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid")


class AssetSpec(_Model):
    """One object of the task."""

    name: str = Field(description="Unique object name (letters, digits, underscores).")
    kind: Literal["colored_cube", "semantic_cube", "goal_patch"]
    color: str | None = Field(None, description="Palette colour (cubes, patches).")
    label: str | None = Field(None, description="Label of a semantic cube: A-Z, 0-9, + - = x.")
    faces: dict[str, str | None] = Field(default_factory=dict, description="Per-face labels of a semantic cube.")
    size: float = Field(C.CUBE_EDGE, gt=0.01, le=0.1, description="Cube edge, m.")
    shape: Literal["square", "long"] = Field("square", description="Goal patch shape.")

    def build(self):
        """The domain asset this spec describes.

        Raises:
            ValueError: unknown colour or label (message says what is allowed).
        """
        if self.kind == "colored_cube":
            return ColoredCube(self.name, color=self.color or "red", size=self.size)
        if self.kind == "semantic_cube":
            return SemanticCube(self.name, label=self.label or "A", faces=dict(self.faces),
                                color=self.color or "white", size=self.size)
        return GoalPatch(self.name, color=self.color or "gray", shape=self.shape)


class PoseSpec(_Model):
    position: tuple[float, float, float] = Field(description="Centre, m, world frame.")
    quaternion: tuple[float, float, float, float] = Field((1.0, 0.0, 0.0, 0.0), description="(w, x, y, z).")

    @classmethod
    def of(cls, pose: Pose) -> PoseSpec:
        return cls(position=tuple(round(float(v), 6) for v in pose.pos),
                   quaternion=tuple(round(float(v), 6) for v in pose.quat))

    def pose(self) -> Pose:
        return Pose(tuple(self.position), tuple(self.quaternion))


class InitialStateSpec(_Model):
    """The initial-state distribution rho_0."""

    mode: Literal["scattered"] = "scattered"
    min_separation: float = Field(C.MIN_SEPARATION, ge=0.0, le=0.3, description="Least centre distance, m.")
    yaw_range: float = Field(C.DEFAULT_YAW_RANGE, ge=0.0, le=3.1416, description="Half range of yaw, rad.")
    structures: list[list[str]] = Field(default_factory=list, description="Initial stacks, bottom to top.")
    fixed: dict[str, PoseSpec] = Field(default_factory=dict, description="Objects not sampled (goal patches).")
    orientations: dict[str, tuple[float, float, float, float]] = Field(
        default_factory=dict, description="Initial orientation (w, x, y, z) before yaw, per object.")


class Tolerances(_Model):
    """Validation thresholds (paper, Validation Parameters)."""

    settle_steps: int = C.SETTLE_STEPS
    stability_steps: int = C.STABILITY_STEPS
    max_drift: float = C.MAX_DRIFT
    max_drop: float = C.MAX_DROP


class RepairRecord(_Model):
    """A structured repair applied to the schema or the code."""

    operator: str
    stage: Literal["feasibility", "validation"]
    reason: str


class TaskSchema(_Model):
    """Everything that defines a task, before code exists."""

    name: str = Field(description="snake_case task name.")
    instruction: str
    paraphrases: list[str] = Field(min_length=3)
    assets: list[AssetSpec] = Field(min_length=1)
    initial_state: InitialStateSpec = Field(default_factory=InitialStateSpec)
    goal: dict[str, Any] = Field(description="Predicate tree (see rpg.domain.predicates.from_dict).")
    goal_layout: dict[str, PoseSpec] = Field(description="Concrete poses that satisfy the goal.")
    goal_summary: str = Field("", description="Natural-language summary of the success condition.")
    reasoning: Literal["spatial", "semantic"] = "spatial"
    primitives: list[str] = Field(default_factory=list, description="Action primitives: stack, arrange, rotate, place, push.")
    tolerances: Tolerances = Field(default_factory=Tolerances)
    repairs: list[RepairRecord] = Field(default_factory=list)

    @field_validator("name")
    @classmethod
    def _snake(cls, v: str) -> str:
        if not v or not v.replace("_", "").isalnum() or not v[0].isalpha():
            raise ValueError("name must be snake_case letters, digits and underscores")
        return v

    @model_validator(mode="after")
    def _consistent(self) -> TaskSchema:
        names = [a.name for a in self.assets]
        if len(set(names)) != len(names):
            raise ValueError("asset names must be unique")
        goal = self.goal_predicate()
        unknown = sorted(set(goal.object_names()) - set(names))
        if unknown:
            raise ValueError(f"goal names unknown objects {unknown}; assets are {names}")
        missing = sorted(set(names) - set(self.goal_layout))
        if missing:
            raise ValueError(f"goal_layout lacks poses for {missing}")
        for a in self.assets:
            a.build()
        return self

    def goal_predicate(self) -> Predicate:
        return from_dict(self.goal)

    def built_assets(self):
        return [a.build() for a in self.assets]

    def tags(self) -> dict:
        """Retrieval tags (paper, appendix "In-Context Examples"): asset class, reasoning type
        (semantic or spatial), complexity (atomic: one predicate; compositional: a
        conjunction; hierarchical: staged sub-goals in temporal order) and action primitives."""
        from rpg.domain.predicates import And, InOrder

        goal = self.goal_predicate()
        stack, temporal = [goal], False
        while stack:
            p = stack.pop()
            temporal = temporal or isinstance(p, InOrder)
            stack.extend(p.children())
        complexity = "hierarchical" if temporal else "compositional" if isinstance(goal, And) else "atomic"
        return {"asset_class": self.assets_used(), "reasoning": self.reasoning, "complexity": complexity,
                "primitives": list(self.primitives)}

    def assets_used(self) -> list[str]:
        """Asset class names used, e.g. ``["ColoredCube", "SemanticCube"]``."""
        return sorted({type(a.build()).__name__ for a in self.assets})


def export_json_schema() -> str:
    """The JSON Schema of :class:`TaskSchema`, as written to ``schemas/task.schema.json``."""
    return json.dumps(TaskSchema.model_json_schema(), indent=2, sort_keys=True) + "\n"
