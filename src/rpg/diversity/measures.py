"""Diversity measures over a set of tasks (paper: Results, task diversity; its appendix
checks the trend with other measures).

Semantic measures take unit-length embeddings ``x`` (n, d) (:mod:`rpg.diversity.embeddings`);
the distance between two tasks is the cosine distance ``1 - cos``.  Structural measures take
the tasks' schemas and need no embedding.  All randomness comes from a seeded
``numpy.random.Generator``.
"""

from __future__ import annotations

import math
from collections import Counter

import numpy as np

from rpg.domain import predicates as P
from rpg.schema.model import TaskSchema
from rpg.schema.structures import STRUCTURE_KINDS, extract

POOL_ORDERINGS = 200
"""Random orderings of contributors averaged by :func:`pooled_diversity` (the paper's bands are 95% intervals over orderings)."""

ASSET_CLASSES = ("ColoredCube", "GoalPatch", "SemanticCube")
RELATIONS = ("on", "left_of", "right_of", "in_front_of", "behind", "next_to", "far_from", "between", "on_patch", "in_region")
"""Predicates counted as relations between objects (or an object and a place)."""
GOAL_KINDS = (*STRUCTURE_KINDS, "relations", "patches", "regions", "word", "equation", "temporal", "rotation", "other")
"""What a task builds: a structure kind of the registry, or the kind of goal it states instead."""


def distance_matrix(x: np.ndarray) -> np.ndarray:
    """Cosine distances (n, n) between unit rows of ``x``."""
    return np.clip(1.0 - x @ x.T, 0.0, 2.0)


def mean_pairwise_distance(x: np.ndarray, idx: np.ndarray | None = None, d: np.ndarray | None = None) -> float:
    """Mean cosine distance over all pairs of tasks (rows ``idx`` of ``x``); NaN for fewer than two."""
    d = distance_matrix(x) if d is None else d
    idx = np.arange(len(d)) if idx is None else np.asarray(idx)
    n = len(idx)
    if n < 2:
        return float("nan")
    sub = d[np.ix_(idx, idx)]
    return float(sub[np.triu_indices(n, 1)].mean())


def pooled_diversity(x: np.ndarray, groups: list[str], rng: np.random.Generator,
                     orderings: int = POOL_ORDERINGS) -> list[dict]:
    """Diversity of the tasks of 1..N contributors pooled, over random orderings of contributors.

    Returns:
        One ``{"contributors": k, "mean", "lo", "hi", "tasks"}`` per k = 1..N: the mean over
        orderings of the pooled mean pairwise distance, its 2.5 / 97.5 percentiles (a 95%
        interval) and the mean number of tasks pooled.
    """
    d = distance_matrix(x)
    names = sorted(set(groups))
    members = {g: np.array([i for i, h in enumerate(groups) if h == g]) for g in names}
    out = []
    perms = [rng.permutation(len(names)) for _ in range(orderings)]
    for k in range(1, len(names) + 1):
        vals, sizes = [], []
        for perm in perms:
            idx = np.concatenate([members[names[j]] for j in perm[:k]])
            vals.append(mean_pairwise_distance(x, idx, d))
            sizes.append(len(idx))
        v = np.array(vals)
        v = v[~np.isnan(v)]
        out.append({"contributors": k, "mean": float(v.mean()) if len(v) else float("nan"),
                    "lo": float(np.percentile(v, 2.5)) if len(v) else float("nan"),
                    "hi": float(np.percentile(v, 97.5)) if len(v) else float("nan"),
                    "tasks": float(np.mean(sizes))})
    return out


def cumulative_diversity(x: np.ndarray, groups: list[str]) -> dict[str, list[float]]:
    """Per contributor, the mean pairwise distance of their first m tasks, m = 2..n (in the
    order given): the curve that plateaus when an author repeats themselves."""
    d = distance_matrix(x)
    out = {}
    for g in sorted(set(groups)):
        idx = [i for i, h in enumerate(groups) if h == g]
        out[g] = [mean_pairwise_distance(x, np.array(idx[:m]), d) for m in range(2, len(idx) + 1)]
    return out


def goal_kind(schema: TaskSchema) -> str:
    """What a task builds (one of :data:`GOAL_KINDS`)."""
    spec = extract(schema)
    if spec is not None:
        return spec.structure
    names = {p.name for p in schema.goal.walk()}
    for kind, preds in (("temporal", {"in_order"}), ("equation", {"equation"}), ("word", {"reads"}),
                        ("rotation", {"label_facing", "upright"}), ("patches", {"on_patch"}),
                        ("regions", {"in_region"}), ("relations", set(RELATIONS) | {"stack"})):
        if names & preds:
            return kind
    return "other"


def _entropy(counts: Counter) -> float:
    total = sum(counts.values())
    return float(-sum(c / total * math.log2(c / total) for c in counts.values() if c)) if total else 0.0


def _feature(counts: Counter, possible: tuple[str, ...]) -> dict:
    h = _entropy(counts)
    used = [k for k in possible if counts.get(k)]
    return {"counts": {k: int(counts.get(k, 0)) for k in possible}, "entropy_bits": round(h, 6),
            "normalized_entropy": round(h / math.log2(len(possible)), 6) if len(possible) > 1 else 0.0,
            "coverage": round(len(used) / len(possible), 6)}


def structural_diversity(schemas: list[TaskSchema]) -> dict:
    """Diversity from the schemas alone: for predicate types, asset classes and goal kinds,
    the count of tasks using each value, Shannon entropy (bits) of that distribution, the
    entropy normalised by its maximum, and coverage (share of possible values used); and the
    distribution of the number of relations per task."""
    preds, assets, kinds, rels = Counter(), Counter(), Counter(), Counter()
    for s in schemas:
        names = {p.name for p in s.goal.walk()} - {"and"}
        preds.update(names)
        assets.update(s.assets_used())
        kinds[goal_kind(s)] += 1
        rels[sum(p.name in RELATIONS for p in s.goal.walk())] += 1
    possible_preds = tuple(sorted(set(P.PREDICATES) - {"and"}))
    n = len(schemas)
    return {"tasks": n, "predicate_types": _feature(preds, possible_preds),
            "asset_classes": _feature(assets, ASSET_CLASSES), "goal_kinds": _feature(kinds, GOAL_KINDS),
            "relations_per_task": {"histogram": {str(k): v for k, v in sorted(rels.items())},
                                   "mean": round(sum(k * v for k, v in rels.items()) / n, 6) if n else 0.0}}


def suggestions(structural: dict, k: int = 5) -> dict[str, list[str]]:
    """The goal kinds, predicate types and asset classes the library covers least (unused
    first, then the rarest): what a curator could author next."""
    out = {}
    for key in ("goal_kinds", "predicate_types", "asset_classes"):
        counts = {v: n for v, n in structural[key]["counts"].items() if v != "other"}  # "other" is no kind to author
        out[key] = sorted(counts, key=lambda v: (counts[v], v))[:k]
    return out
