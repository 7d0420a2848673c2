"""TaskSchema: the typed representation pass 1 produces and pass 2 consumes.

Its JSON Schema is exported to ``schemas/task.schema.json`` (``rpg schema`` rewrites it; a
test keeps the two in sync).  A schema fully determines a task
T = (assets, rho_0, G, instruction, paraphrases) together with a goal layout that
realises G.
"""

from __future__ import annotations

import json
from dataclasses import MISSING, fields
from typing import Annotated, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    PlainSerializer,
    PlainValidator,
    WithJsonSchema,
    field_validator,
    model_validator,
)

from rpg.domain import constants as C
from rpg.domain.assets import ColoredCube, GoalPatch, SemanticCube
from rpg.domain.predicates import PREDICATES, And, Predicate, from_dict
from rpg.domain.state import Pose

_JSON_TYPES = {"str": {"type": "string"}, "int": {"type": "integer"}, "float": {"type": "number"},
               "bool": {"type": "boolean"}, "str | None": {"type": ["string", "null"]},
               "tuple[str, ...]": {"type": "array", "items": {"type": "string"}},
               "tuple[tuple[str, ...], ...]": {"type": "array", "items": {"type": "array", "items": {"type": "string"}}},
               "Predicate": {"$ref": "#/$defs/Goal"},
               "tuple[Predicate, ...]": {"type": "array", "items": {"$ref": "#/$defs/Goal"}}}


def goal_json_schema() -> dict:
    """JSON Schema of a goal predicate tree: one alternative per registered predicate, with
    its argument names and types (from the predicate dataclasses, so it cannot drift)."""
    alternatives = []
    for name, cls in sorted(PREDICATES.items()):
        props: dict = {"predicate": {"const": name}}
        required = ["predicate"]
        for f in fields(cls):
            key = "children" if cls is And else f.name
            props[key] = dict(_JSON_TYPES.get(str(f.type), {}))
            if f.default is MISSING and f.default_factory is MISSING or cls is And:
                required.append(key)
        alternatives.append({"type": "object", "title": name, "description": (cls.__doc__ or "").split("\n")[0],
                             "properties": props, "required": required, "additionalProperties": False})
    return {"oneOf": alternatives}


def _goal(value) -> Predicate:
    if isinstance(value, Predicate):
        return value
    return from_dict(value)  # ValueError names the unknown predicate or argument


GoalTree = Annotated[
    Predicate,
    PlainValidator(_goal),
    PlainSerializer(lambda p: p.to_dict(), return_type=dict),
    WithJsonSchema({"type": "object"}),  # json_schema() points it at $defs/Goal
]
"""A goal predicate tree: a :class:`rpg.domain.predicates.Predicate` in Python, its
``to_dict`` form (``{"predicate": name, ...arguments}``) in YAML and JSON."""


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
    goal: GoalTree = Field(description="Success predicate G as a predicate tree (rpg.domain.predicates).")
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
        for p in self.goal.walk():
            refs = p.object_names() if not p.children() else []
            twice = sorted({n for n in refs if refs.count(n) > 1})
            if twice:
                raise ValueError(f"the goal relates {twice[0]} to itself ({p.describe()}); name two different objects")
        parts = self.goal.conjuncts()
        if len(set(parts)) != len(parts):
            same = next(q for k, q in enumerate(parts) if q in parts[:k])
            raise ValueError(f"the goal states '{same.describe()}' twice; a repeated object needs its own asset")
        unknown = sorted(set(self.goal.object_names()) - set(names))
        if unknown:
            raise ValueError(f"goal names unknown objects {unknown}; assets are {names}")
        missing = sorted(set(names) - set(self.goal_layout))
        if missing:
            raise ValueError(f"goal_layout lacks poses for {missing}")
        for a in self.assets:
            a.build()
        return self

    def goal_predicate(self) -> Predicate:
        """The success predicate G (the same object as :attr:`goal`)."""
        return self.goal

    def built_assets(self):
        return [a.build() for a in self.assets]

    def tags(self) -> dict:
        """Retrieval tags (paper, appendix "In-Context Examples"): asset class, reasoning type
        (semantic or spatial), complexity (atomic: one predicate; compositional: a
        conjunction; hierarchical: staged sub-goals in temporal order) and action primitives."""
        from rpg.domain.predicates import InOrder

        temporal = any(isinstance(p, InOrder) for p in self.goal.walk())
        complexity = "hierarchical" if temporal else "compositional" if isinstance(self.goal, And) else "atomic"
        return {"asset_class": self.assets_used(), "reasoning": self.reasoning, "complexity": complexity,
                "primitives": list(self.primitives)}

    def assets_used(self) -> list[str]:
        """Asset class names used, e.g. ``["ColoredCube", "SemanticCube"]``."""
        return sorted({type(a.build()).__name__ for a in self.assets})


def json_schema() -> dict:
    """The JSON Schema of :class:`TaskSchema`, the goal tree included (``$defs/Goal``)."""
    doc = TaskSchema.model_json_schema()
    doc["properties"]["goal"] = {"$ref": "#/$defs/Goal", "description": doc["properties"]["goal"].get("description", "")}
    doc.setdefault("$defs", {})["Goal"] = goal_json_schema()
    return doc


def export_json_schema() -> str:
    """The JSON Schema of :class:`TaskSchema`, as written to ``schemas/task.schema.json``."""
    return json.dumps(json_schema(), indent=2, sort_keys=True) + "\n"
