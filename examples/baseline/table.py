"""The baseline's results table (the paper's form) from `rpg eval` run directories.

    python examples/baseline/table.py build/baseline/runs [-o results.md]

RUNS/<policy>/<set>/summary.json, policy in bc, oracle, random and set in train, steered,
eval. Rows: the training tasks; the steered families per steering intent (base: the
training tasks they start from; tweak, extend, modify, pivot: their edits; all edits); the
library's evaluation split. Cells: success % +- standard error (binomial) and, where the
summary has it, progress % +- standard error (the fraction of the goal's predicates that hold
at the end).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

POLICIES = (("bc", "BC baseline"), ("oracle", "oracle (upper bound)"), ("random", "random (floor)"))
INTENTS = ("base", "tweak", "extend", "modify", "pivot")


def _load(runs: Path, policy: str, which: str) -> tuple[dict | None, list[dict]]:
    d = runs / policy / which
    if not (d / "summary.json").exists():
        return None, []
    records = [json.loads(x) for x in (d / "episodes.jsonl").read_text().splitlines() if x.strip()]
    return json.loads((d / "summary.json").read_text()), records


def _aggregate(records: list[dict]) -> dict:
    """A summary-like cell for records the summary does not group (all steered edits)."""
    n = len(records)
    k = sum(bool(r["success"]) for r in records)
    p = k / n if n else 0.0
    cell = {"n": n, "mean": p, "stderr": math.sqrt(p * (1 - p) / n) if n else 0.0}
    prog = [float(r["progress"]) for r in records if r.get("progress") is not None]
    if prog and len(prog) == n:
        m = sum(prog) / n
        var = sum((x - m) ** 2 for x in prog) / (n - 1) if n > 1 else 0.0
        cell.update(progress=m, progress_stderr=math.sqrt(var / n))
    return cell


def _fmt(cell: dict | None, key: str) -> str:
    if not cell or key not in cell:
        return "-"
    return f"{100 * cell[key]:.0f} ± {100 * cell[key + '_stderr' if key == 'progress' else 'stderr']:.0f}"


def rows(runs: Path) -> list[tuple[str, int, dict]]:
    """(label, tasks, {policy: cell}) per table row."""
    out = []
    for label, which, group, key in (("training tasks", "train", "splits", "train"),):
        cells, ntasks = {}, 0
        for p, _ in POLICIES:
            s, _ = _load(runs, p, which)
            cells[p] = s and s[group].get(key)
            ntasks = max(ntasks, len(s["tasks"]) if s else 0)
        out.append((label, ntasks, cells))
    for intent in (*INTENTS, "all edits"):
        cells, ntasks = {}, 0
        for p, _ in POLICIES:
            s, recs = _load(runs, p, "steered")
            if s is None:
                cells[p] = None
                continue
            if intent == "all edits":
                sel = [r for r in recs if (r.get("intent") or "base") != "base"]
                cells[p] = _aggregate(sel)
            else:
                sel = [r for r in recs if (r.get("intent") or "none") == intent]
                cells[p] = s["intents"].get(intent)
            ntasks = max(ntasks, len({(r.get("family"), r.get("version")) for r in sel}))
        if ntasks:
            out.append((f"steered: {intent}", ntasks, cells))
    cells, ntasks = {}, 0
    for p, _ in POLICIES:
        s, _ = _load(runs, p, "eval")
        cells[p] = s and s["splits"].get("eval")
        ntasks = max(ntasks, len(s["tasks"]) if s else 0)
    if ntasks:
        out.append(("library eval split", ntasks, cells))
    return out


def markdown(runs: Path) -> str:
    table = rows(runs)
    has_progress = any(c and "progress" in c for _, _, cells in table for c in cells.values())
    head = ["tasks", "n"]
    for _, name in POLICIES:
        head.append(f"{name} success %")
        if has_progress:
            head.append(f"{name} progress %")
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for label, ntasks, cells in table:
        n = next((c["n"] for c in cells.values() if c), 0)
        row = [f"{label} ({ntasks})", str(n)]
        for p, _ in POLICIES:
            row.append(_fmt(cells[p], "mean"))
            if has_progress:
                row.append(_fmt(cells[p], "progress"))
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", type=Path)
    ap.add_argument("-o", "--out", type=Path)
    args = ap.parse_args(argv)
    text = markdown(args.runs)
    if args.out:
        args.out.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
