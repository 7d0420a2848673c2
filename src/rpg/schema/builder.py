"""Assembles a TaskSchema from parsed intent: objects, goal predicates and a goal layout.

The builtin front end decides *what* the task is; this module turns that into concrete
assets with unique names, a predicate tree, a goal layout that satisfies it, and rho_0.
Documented defaults fill what an instruction leaves open (:data:`DEFAULT_COLORS`, ...).
"""

from __future__ import annotations

import re
from collections import Counter

from rpg.domain import constants as C
from rpg.domain.layouts import spread_centers
from rpg.domain.predicates import And, Predicate
from rpg.domain.state import Pose
from rpg.schema.model import AssetSpec, InitialStateSpec, PoseSpec, TaskSchema

DEFAULT_COLORS: tuple[str, ...] = ("red", "blue", "green", "yellow", "orange", "purple", "cyan", "pink", "brown", "white", "gray", "black")
"""Colours given, in this order, to cubes whose colour the instruction leaves open."""

DEFAULT_PATCH_COLOR = "gray"
"""Colour of a goal patch whose colour the instruction leaves open."""

LABEL_NAMES = {"+": "plus", "-": "minus", "=": "equals", "x": "times"}


class Builder:
    """Accumulates objects, predicates and goal poses for one task."""

    def __init__(self, instruction: str):
        self.instruction = instruction
        self.assets: list[AssetSpec] = []
        self.preds: list[Predicate] = []
        self.layout: dict[str, Pose] = {}
        self.structures: list[list[str]] = []
        self.orientations: dict[str, tuple[float, float, float, float]] = {}
        self.reasoning = "spatial"
        self.primitives: list[str] = []
        self.summary: list[str] = []
        self.min_separation = C.MIN_SEPARATION
        self.repairs: list = []
        self._names: Counter = Counter()

    def adopt(self, head: TaskSchema) -> None:
        """Take ``head``'s task into this empty builder (its cubes and patches, goal poses, goal
        parts, rho_0's stacks and orientations, reasoning and primitives), to compose more onto it:
        a part read alone, then placed relative to a cube (:mod:`rpg.schema.readers.places`) or
        given a start (:mod:`rpg.schema.readers.initial`)."""
        for a in head.assets:
            self._names[a.name] += 1
            self.assets.append(a.model_copy())
        self.place({n: p.pose() for n, p in head.goal_layout.items()})
        self.preds = list(head.goal.conjuncts())
        self.structures = [list(x) for x in head.initial_state.structures]
        self.orientations = dict(head.initial_state.orientations)
        self.reasoning, self.primitives = head.reasoning, list(head.primitives)

    # -- objects ---------------------------------------------------------------
    def _unique(self, base: str) -> str:
        base = re.sub(r"[^a-z0-9_]", "_", base.lower())
        self._names[base] += 1
        return base if self._names[base] == 1 else f"{base}_{self._names[base]}"

    def cube(self, color: str) -> str:
        name = self._unique(color)
        self.assets.append(AssetSpec(name=name, kind="colored_cube", color=color))
        return name

    def semantic(self, label: str, faces: dict | None = None) -> str:
        kind = "letter" if label.isalpha() and label != "x" else ("digit" if label.isdigit() else "op")
        name = self._unique(f"{kind}_{LABEL_NAMES.get(label, label)}")
        self.assets.append(AssetSpec(name=name, kind="semantic_cube", label=label, faces=faces or {}))
        self.reasoning = "semantic"
        return name

    def patch(self, color: str, shape: str = "square") -> str:
        name = self._unique(f"{color}_patch" if shape == "square" else f"{color}_long_patch")
        self.assets.append(AssetSpec(name=name, kind="goal_patch", color=color, shape=shape))
        return name

    def finalize_names(self) -> None:
        """Rename ``red`` to ``red_1`` where a ``red_2`` exists, so names read consistently."""
        rename = {}
        for base, n in self._names.items():
            if n > 1:
                rename[base] = f"{base}_1"
        if not rename:
            return
        for a in self.assets:
            if a.name in rename:
                a.name = rename[a.name]
        self.preds = [p.rename(rename) for p in self.preds]
        self.layout = {rename.get(k, k): v for k, v in self.layout.items()}
        self.structures = [[rename.get(n, n) for n in s] for s in self.structures]
        self.orientations = {rename.get(k, k): v for k, v in self.orientations.items()}
        pattern = re.compile(r"\b(" + "|".join(map(re.escape, rename)) + r")\b(?!_)")
        self.summary = [pattern.sub(lambda m: rename[m.group(1)], s) for s in self.summary]

    # -- layout ----------------------------------------------------------------
    def place(self, poses: dict[str, Pose]) -> None:
        self.layout.update(poses)

    def place_patch(self, name: str, xy: tuple[float, float]) -> None:
        """Put goal patch ``name`` on the table with its centre at ``xy`` (m, world frame)."""
        self.place({name: Pose((xy[0], xy[1], C.TABLE_TOP_Z + C.PATCH_THICKNESS / 2))})

    def unit_centers(self, count: int, spacing: float = 0.12) -> list[tuple[float, float]]:
        return spread_centers(count, spacing)

    # -- result ----------------------------------------------------------------
    def schema(self, name: str, paraphrases: list[str] | None = None) -> TaskSchema:
        self.finalize_names()
        preds: list = []
        for p in self.preds:  # "green left of yellow, so yellow is right of green": one relation said twice, kept once
            conv = getattr(p, "converse", "")
            if not (conv and any(q.name == conv and q.object_names() == p.object_names()[::-1] for q in preds)):
                preds.append(p)
        goal = preds[0] if len(preds) == 1 else And(preds)
        patches = {a.name for a in self.assets if a.kind == "goal_patch"}
        summary = "; ".join(self.summary) or goal.describe()
        return TaskSchema(
            name=name,
            instruction=self.instruction,
            paraphrases=paraphrases or make_paraphrases(summary),
            assets=self.assets,
            initial_state=InitialStateSpec(
                min_separation=self.min_separation,
                structures=self.structures,
                fixed={n: PoseSpec.of(self.layout[n]) for n in sorted(patches)},
                orientations=self.orientations,
            ),
            goal=goal,
            goal_layout={n: PoseSpec.of(self.layout[n]) for n in sorted(self.layout)},
            goal_summary=summary,
            reasoning=self.reasoning,
            primitives=sorted(set(self.primitives)),
        )


PARAPHRASE_FRAMES = ("Goal: ", "Arrange the cubes so that the final scene shows ")
"""The frames :func:`make_paraphrases` puts around a goal summary (they state nothing more)."""


def make_paraphrases(summary: str) -> list[str]:
    """Three deterministic paraphrases of a goal summary: itself and inside each frame of
    :data:`PARAPHRASE_FRAMES`."""
    s = summary.strip().rstrip(".")
    low = s[0].lower() + s[1:] if s else s
    return [f"{s[0].upper() + s[1:]}.", *(f"{frame}{low}." for frame in PARAPHRASE_FRAMES)]


def unframe(text: str) -> str:
    """``text`` without a leading frame of :data:`PARAPHRASE_FRAMES` (the summary inside it)."""
    for frame in PARAPHRASE_FRAMES:
        if text.startswith(frame):
            rest = text[len(frame):]
            return rest[:1].upper() + rest[1:]
    return text
