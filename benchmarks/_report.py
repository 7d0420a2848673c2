"""Shared output of the benchmarks: a printed table and a JSON file under benchmarks/out/."""

import json
from pathlib import Path

from rich.console import Console
from rich.table import Table

OUT = Path(__file__).resolve().parent / "out"


def report(name: str, rows: list[tuple[str, float, str, str]]) -> None:
    """rows: (metric, value, unit, target); printed and written to benchmarks/out/<name>.json."""
    table = Table(title=name)
    for col in ("metric", "value", "unit", "target"):
        table.add_column(col)
    for metric, value, unit, target in rows:
        table.add_row(metric, f"{value:.3g}", unit, target)
    Console().print(table)
    OUT.mkdir(exist_ok=True)
    (OUT / f"{name}.json").write_text(json.dumps(
        [{"metric": m, "value": v, "unit": u, "target": t} for m, v, u, t in rows], indent=2) + "\n")
