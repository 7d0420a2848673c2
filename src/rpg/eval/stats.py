"""Success rates and progress with their uncertainty, and run comparisons.

Success over ``n`` episodes is binomial: mean ``k/n``, standard error ``sqrt(p(1-p)/n)`` and
the Wilson score interval at 95% (Wilson 1927), which stays inside [0, 1] and is not empty at
0 or n successes (where the standard error is 0).  Progress (the fraction of G's leaves that
hold, :mod:`rpg.env.core`) is a mean with the sample standard error.

Two runs are compared per task (:func:`compare_runs`) with exact tests from ``scipy.stats``:
McNemar's exact test (a two-sided binomial test on the discordant pairs) when both runs ran
the same seeds on the same task content (paired), Fisher's exact test otherwise (unpaired).
The p-values of the tasks are adjusted with Holm's step-down correction (Holm 1979), which
controls the family-wise error rate over the tasks compared; a difference is called real
when its adjusted p is below :data:`SIGNIFICANCE`.  The overall row is the mean over tasks
with its standard error over tasks, as LIBERO reports it.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict

Z95 = 1.959963984540054
"""The standard normal quantile of a two-sided 95% interval."""

SIGNIFICANCE = 0.05
"""Holm-adjusted p-value below which ``rpg eval compare`` calls a difference real."""

MATCHED_SETTINGS = ("embodiment", "control_mode", "cameras", "image_size", "replan", "visual", "wrist_supersample")
"""Settings two runs must share to be compared (``--allow-mismatch`` overrides, and says so)."""

_SETTING_DEFAULTS = {"visual": "decimated", "wrist_supersample": 1}
"""What a summary from before a setting existed ran with."""


def wilson_interval(successes: int, n: int, z: float = Z95) -> tuple[float, float]:
    """The Wilson score interval (lo, hi) of a success rate; (0, 1) when ``n`` is 0."""
    if n <= 0:
        return 0.0, 1.0
    p = successes / n
    denom = 1.0 + z * z / n
    center = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return max(0.0, center - half), min(1.0, center + half)


def _mean_se(values: list[float]) -> tuple[float, float]:
    """Mean and standard error of the mean (0 for fewer than two values)."""
    if not values:
        return 0.0, 0.0
    mean = statistics.fmean(values)
    se = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else 0.0
    return mean, se


def rate(successes: int, n: int, progress: list[float] | None = None, progress_max: list[float] | None = None,
         errors: int = 0) -> dict:
    """``{"n", "successes", "mean", "stderr", "wilson95": [lo, hi], "progress", "progress_stderr",
    "progress_max", "progress_max_stderr", "errors"}`` (rounded to 6 places)."""
    p = successes / n if n else 0.0
    lo, hi = wilson_interval(successes, n)
    pm, pse = _mean_se(progress or [])
    mm, mse = _mean_se(progress_max or [])
    return {"n": n, "successes": successes, "mean": round(p, 6),
            "stderr": round(math.sqrt(p * (1 - p) / n), 6) if n else 0.0,
            "wilson95": [round(lo, 6), round(hi, 6)],
            "progress": round(pm, 6), "progress_stderr": round(pse, 6),
            "progress_max": round(mm, 6), "progress_max_stderr": round(mse, 6), "errors": errors}


def task_key(record: dict) -> str:
    """``family@vN`` for a family version, else the task's name."""
    return f"{record['family']}@v{record['version']}" if record.get("family") else record["task"]


def _percentile(values: list[float], q: float) -> float:
    """The ``q`` quantile (0-1) of ``values`` by linear interpolation (numpy's default)."""
    xs = sorted(values)
    pos = (len(xs) - 1) * q
    lo = math.floor(pos)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (pos - lo)


def _timing(records: list[dict]) -> dict:
    """Per task: policy latency (median and p95 of every ``act`` call, s) and wall time (s)."""
    by_task: dict[str, list[dict]] = defaultdict(list)
    for r in records:
        by_task[task_key(r)].append(r)
    out = {}
    for key, recs in sorted(by_task.items()):
        lat = [x for r in recs for x in r.get("latency_s") or []]
        out[key] = {"calls": len(lat), "latency_median_s": round(_percentile(lat, 0.5), 6) if lat else None,
                    "latency_p95_s": round(_percentile(lat, 0.95), 6) if lat else None,
                    "wall_s": round(sum(float(r.get("wall_s") or 0.0) for r in recs), 3)}
    return out


def summarize(records: list[dict], config: dict) -> dict:
    """The ``summary.json`` document of a run's episode records (any order).

    Everything but ``timing`` is sorted and free of timings, so the same episodes give the
    same bytes; ``timing`` holds policy latency and wall time per task.  ``errors`` lists the
    episodes whose policy failed (counted as failures); ``task_hashes`` the content hash of
    every task (what :func:`compare_runs` checks)."""
    groups: dict[str, dict[str, list[dict]]] = defaultdict(lambda: defaultdict(list))
    for r in records:
        groups["tasks"][task_key(r)].append(r)
        if r.get("family"):
            groups["families"][r["family"]].append(r)
            groups["intents"][r.get("intent") or "none"].append(r)
        groups["splits"][r.get("split") or "none"].append(r)
        groups["instructions"][r.get("instruction_variant", "canonical")].append(r)

    def rate_of(recs: list[dict]) -> dict:
        return rate(sum(bool(r["success"]) for r in recs), len(recs),
                    [float(r.get("progress") or 0.0) for r in recs],
                    [float(r.get("progress_max") or 0.0) for r in recs], sum(bool(r.get("error")) for r in recs))

    out = {"config": {k: config[k] for k in sorted(config)}, "overall": rate_of(records)}
    for name in ("tasks", "families", "intents", "splits", "instructions"):
        out[name] = {k: rate_of(v) for k, v in sorted(groups[name].items())}
    means = [t["mean"] for t in out["tasks"].values()]
    progress = [t["progress"] for t in out["tasks"].values()]
    m, se = _mean_se(means)
    pm, pse = _mean_se(progress)
    out["over_tasks"] = {"tasks": len(means), "mean": round(m, 6), "stderr": round(se, 6),
                         "progress": round(pm, 6), "progress_stderr": round(pse, 6)}
    out["task_hashes"] = {k: sorted({r["task_hash"] for r in v})[0] for k, v in sorted(groups["tasks"].items())}
    out["errors"] = sorted(({"task": task_key(r), "seed": int(r["seed"]), "instruction_variant": r.get("instruction_variant"),
                             "error": r["error"]} for r in records if r.get("error")),
                           key=lambda e: (e["task"], str(e["instruction_variant"]), e["seed"]))
    out["timing"] = _timing(records)
    return out


def fisher_exact(k1: int, n1: int, k2: int, n2: int) -> float:
    """Two-sided p-value of Fisher's exact test of equal success rates (unpaired runs)."""
    from scipy.stats import fisher_exact as fe

    if n1 == 0 or n2 == 0:
        return 1.0
    return float(fe([[k1, n1 - k1], [k2, n2 - k2]], alternative="two-sided").pvalue)


def mcnemar_exact(b: int, c: int) -> float:
    """Two-sided p-value of McNemar's exact test: ``b`` pairs where only A succeeded, ``c``
    where only B did (a binomial test of b against b + c at 1/2); 1.0 without discordant pairs."""
    from scipy.stats import binomtest

    if b + c == 0:
        return 1.0
    return float(binomtest(b, b + c, 0.5, alternative="two-sided").pvalue)


def holm(pvalues: list[float]) -> list[float]:
    """Holm's step-down adjusted p-values (Holm 1979), in the input's order: the i-th smallest
    p is multiplied by (m - i) and the results made monotone, capped at 1."""
    m = len(pvalues)
    order = sorted(range(m), key=lambda i: pvalues[i])
    adjusted = [0.0] * m
    running = 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (m - rank) * pvalues[i]))
        adjusted[i] = running
    return adjusted


def mismatches(a: dict, b: dict) -> list[str]:
    """What keeps two summaries from being compared: a setting of :data:`MATCHED_SETTINGS`,
    or a task both ran whose content differs; one line each."""
    ca, cb = _SETTING_DEFAULTS | a.get("config", {}), _SETTING_DEFAULTS | b.get("config", {})
    out = [f"{k}: {ca.get(k)!r} vs {cb.get(k)!r}" for k in MATCHED_SETTINGS if ca.get(k) != cb.get(k)]
    ha, hb = a.get("task_hashes", {}), b.get("task_hashes", {})
    for task in sorted(set(ha) & set(hb)):
        if ha[task] != hb[task]:
            out.append(f"task {task}: content {ha[task][:12]} vs {hb[task][:12]}")
    return out


def _outcomes(episodes: list[dict]) -> dict[str, dict[tuple, bool]]:
    """task key -> {(instruction variant, seed): success}."""
    out: dict[str, dict[tuple, bool]] = defaultdict(dict)
    for r in episodes:
        out[task_key(r)][(r.get("instruction_variant", "canonical"), int(r["seed"]))] = bool(r["success"])
    return out


def compare_runs(a: dict, b: dict, episodes_a: list[dict] | None = None, episodes_b: list[dict] | None = None) -> dict:
    """Compare two runs' summaries (and their episodes, for the paired test).

    Returns:
        ``{"rows": [{"task", "a", "b", "diff", "progress_diff", "test", "p_value",
        "p_holm", "significant"}], "overall": {"a", "b", "diff"}, "paired_tasks", "unpaired_tasks",
        "correction": "holm", "significance"}``: a task is paired (McNemar) when both runs ran
        it on the same seeds and instructions with the same content, else unpaired (Fisher);
        a task only one run has gets ``None`` fields and no test.
    """
    oa, ob = _outcomes(episodes_a or []), _outcomes(episodes_b or [])
    rows = []
    for task in sorted(set(a["tasks"]) | set(b["tasks"])):
        ra, rb = a["tasks"].get(task), b["tasks"].get(task)
        if ra is None or rb is None:
            rows.append({"task": task, "a": ra, "b": rb, "diff": None, "progress_diff": None, "test": None,
                         "p_value": None, "p_holm": None, "significant": False})
            continue
        ea, eb = oa.get(task, {}), ob.get(task, {})
        same = a.get("task_hashes", {}).get(task) == b.get("task_hashes", {}).get(task)
        if ea and set(ea) == set(eb) and same and len(ea) == ra["n"] == rb["n"]:
            only_a = sum(ea[k] and not eb[k] for k in ea)
            only_b = sum(eb[k] and not ea[k] for k in ea)
            test, p = "mcnemar_exact", mcnemar_exact(only_a, only_b)
        else:
            test, p = "fisher_exact", fisher_exact(ra["successes"], ra["n"], rb["successes"], rb["n"])
        rows.append({"task": task, "a": ra, "b": rb, "diff": round(rb["mean"] - ra["mean"], 6),
                     "progress_diff": round(rb.get("progress", 0.0) - ra.get("progress", 0.0), 6),
                     "test": test, "p_value": round(p, 6), "p_holm": None, "significant": False})
    tested = [r for r in rows if r["p_value"] is not None]
    for r, adj in zip(tested, holm([r["p_value"] for r in tested]), strict=True):
        r["p_holm"] = round(adj, 6)
        r["significant"] = adj < SIGNIFICANCE
    overall = {"a": a.get("over_tasks"), "b": b.get("over_tasks"),
               "diff": round(b["over_tasks"]["mean"] - a["over_tasks"]["mean"], 6)
               if a.get("over_tasks") and b.get("over_tasks") else None}
    return {"rows": rows, "overall": overall, "paired_tasks": sum(r["test"] == "mcnemar_exact" for r in rows),
            "unpaired_tasks": sum(r["test"] == "fisher_exact" for r in rows), "correction": "holm",
            "significance": SIGNIFICANCE}
