"""Compile benchmark: per-pass and end-to-end time over the paper's instructions, and a fresh-process compile."""

import compileall
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml
from _report import report

import rpg
from rpg.codegen import generate
from rpg.compiler import build
from rpg.schema.builtin import parse
from rpg.schema.feasibility import check_feasibility

# What the `rpg` console script runs, with rpg's bytecode compiled as an installed wheel has it
# (an editable install under PYTHONDONTWRITEBYTECODE would recompile every module each run).
RPG = [sys.executable, "-c", "from rpg.cli import main; main()"]
compileall.compile_dir(str(Path(rpg.__file__).parent), quiet=1)

seeds = Path(__file__).resolve().parents[2] / "shared" / "seed-cases.yaml"
d = yaml.safe_load(seeds.read_text())
instructions = [s["steps"][0]["instruction"] for s in d["benchmark_sessions"]]
instructions += [t["instruction"] for k in ("reference_tasks", "training_tasks", "evaluation_tasks") for t in d[k]]
schema_t, codegen_t, validate_t, e2e_t = [], [], [], []
with tempfile.TemporaryDirectory() as tmp:
    for i, text in enumerate(instructions):
        t0 = time.perf_counter()
        schema = check_feasibility(parse(text))
        t1 = time.perf_counter()
        generate(schema)
        t2 = time.perf_counter()
        build(schema, Path(tmp), name=f"t{i}")
        t3 = time.perf_counter()
        schema_t.append(t1 - t0)
        codegen_t.append(t2 - t1)
        validate_t.append(t3 - t2)
        e2e_t.append(t3 - t0)
    def fresh_compile(isolation: str) -> float:
        """Median of 5 fresh-process compiles with the OS isolation layers on (1) or off (0)."""
        env = {**os.environ, "RPG_ISOLATION": isolation}
        times = []
        for _ in range(5):
            t = time.perf_counter()
            subprocess.run([*RPG, "compile", instructions[0], "-o", tmp], check=True,
                           capture_output=True, env=env)
            times.append(time.perf_counter() - t)
        return statistics.median(times)

    fresh_off = fresh_compile("0")
    fresh = fresh_compile("1")

    def floor_vs_compile(rounds: int = 7) -> tuple[float, float]:
        """Medians of the raw-MuJoCo floor (``../shared/bench/floor_compile.py``: import mujoco,
        a table with three cubes, settle initial and goal layouts 1 s each, render both at
        640x480, write two PNGs) and of ``rpg compile`` of a three-cube stack as a fresh
        process, run alternately in the same loop so both see the same machine."""
        floor = Path(__file__).resolve().parents[2] / "shared" / "bench" / "floor_compile.py"
        fl, rc = [], []
        for _ in range(rounds):
            with tempfile.TemporaryDirectory() as out:
                t = time.perf_counter()
                subprocess.run([sys.executable, str(floor), out], check=True, capture_output=True)
                fl.append(time.perf_counter() - t)
                t = time.perf_counter()
                subprocess.run([*RPG, "compile", "Stack the red block on the green block "
                                "and the yellow block on the red block", "-o", out], check=True, capture_output=True)
                rc.append(time.perf_counter() - t)
        return statistics.median(fl), statistics.median(rc)

    floor_s, compile_s = floor_vs_compile() if (Path(__file__).resolve().parents[2] / "shared").is_dir() else (0.0, 0.0)
report("compile", [
    ("instructions", len(instructions), "", ""),
    ("pass 1 schema (parse + feasibility), median", statistics.median(schema_t) * 1000, "ms", ""),
    ("pass 2 codegen, median", statistics.median(codegen_t) * 1000, "ms", ""),
    ("passes 3-4 validate + repair + artifact, median", statistics.median(validate_t) * 1000, "ms", ""),
    ("end to end in-process, median", statistics.median(e2e_t) * 1000, "ms", "<= 500"),
    ("rpg compile as a fresh process, median of 5 (sandbox: every layer rpg doctor lists)", fresh, "s", "<= 1.5"),
    ("the same without namespaces and seccomp (RPG_ISOLATION=0)", fresh_off, "s", ""),
    ("cost of OS isolation on a fresh compile", (fresh / fresh_off - 1) * 100, "%", "<= 10"),
    ("raw-MuJoCo floor of the same physical work, median of 7", floor_s, "s", ""),
    ("rpg compile of a 3-cube stack, fresh process, same rounds", compile_s, "s", ""),
    ("rpg compile / floor", compile_s / floor_s if floor_s else float("nan"), "x", "<= 2.0"),
])
