"""Success rates with their uncertainty, and run comparisons.

Binomial success over ``n`` episodes: mean ``k/n``, standard error ``sqrt(p(1-p)/n)`` and
the Wilson score interval at 95% (Wilson 1927), which stays inside [0, 1] and is not empty at
0 or n successes (where the standard error is 0).  Two runs are compared per task with the
two-proportion z-test (pooled variance), two-sided.
"""

from __future__ import annotations

import math
from collections import defaultdict

Z95 = 1.959963984540054
"""The standard normal quantile of a two-sided 95% interval."""

SIGNIFICANCE = 0.05
"""p-value below which ``rpg eval compare`` calls a difference real."""


def wilson_interval(successes: int, n: int, z: float = Z95) -> tuple[float, float]:
    """The Wilson score interval (lo, hi) of a success rate; (0, 1) when ``n`` is 0."""
    if n <= 0:
        return 0.0, 1.0
    p = successes / n
    denom = 1.0 + z * z / n
    center = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, center - half), min(1.0, center + half)


def rate(successes: int, n: int) -> dict:
    """``{"n", "successes", "mean", "stderr", "wilson95": [lo, hi]}`` (rounded to 6 places)."""
    p = successes / n if n else 0.0
    lo, hi = wilson_interval(successes, n)
    return {"n": n, "successes": successes, "mean": round(p, 6),
            "stderr": round(math.sqrt(p * (1 - p) / n), 6) if n else 0.0,
            "wilson95": [round(lo, 6), round(hi, 6)]}


def task_key(record: dict) -> str:
    """``family@vN`` for a family version, else the task's name."""
    return f"{record['family']}@v{record['version']}" if record.get("family") else record["task"]


def summarize(records: list[dict], config: dict) -> dict:
    """The ``summary.json`` document of a run's episode records (any order; the result is
    sorted and has no timings, so the same episodes give the same bytes)."""
    groups: dict[str, dict[str, list[bool]]] = defaultdict(lambda: defaultdict(list))
    for r in records:
        ok = bool(r["success"])
        groups["tasks"][task_key(r)].append(ok)
        if r.get("family"):
            groups["families"][r["family"]].append(ok)
            groups["intents"][r.get("intent") or "none"].append(ok)
        groups["splits"][r.get("split") or "none"].append(ok)
        groups["instructions"][r.get("instruction_variant", "canonical")].append(ok)
    out = {"config": {k: config[k] for k in sorted(config)},
           "overall": rate(sum(bool(r["success"]) for r in records), len(records))}
    for name in ("tasks", "families", "intents", "splits", "instructions"):
        out[name] = {k: rate(sum(v), len(v)) for k, v in sorted(groups[name].items())}
    return out


def two_proportion_test(k1: int, n1: int, k2: int, n2: int) -> float:
    """Two-sided p-value of H0: equal success rates (pooled two-proportion z-test); 1.0 when
    either run has no episodes or both rates are 0 or 1."""
    if n1 == 0 or n2 == 0:
        return 1.0
    pooled = (k1 + k2) / (n1 + n2)
    se = math.sqrt(pooled * (1 - pooled) * (1 / n1 + 1 / n2))
    if se == 0.0:
        return 1.0
    z = (k1 / n1 - k2 / n2) / se
    return math.erfc(abs(z) / math.sqrt(2))


def compare_runs(a: dict, b: dict) -> list[dict]:
    """Per-task rows comparing two summaries: ``{"task", "a", "b", "diff", "p_value",
    "significant"}`` (``a``/``b`` None where a run lacks the task), tasks sorted by name."""
    rows = []
    for task in sorted(set(a["tasks"]) | set(b["tasks"])):
        ra, rb = a["tasks"].get(task), b["tasks"].get(task)
        if ra is None or rb is None:
            rows.append({"task": task, "a": ra, "b": rb, "diff": None, "p_value": None, "significant": False})
            continue
        p = two_proportion_test(ra["successes"], ra["n"], rb["successes"], rb["n"])
        rows.append({"task": task, "a": ra, "b": rb, "diff": round(rb["mean"] - ra["mean"], 6),
                     "p_value": round(p, 6), "significant": p < SIGNIFICANCE})
    return rows
