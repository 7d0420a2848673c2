"""Library benchmark: batch throughput of the whole library with 1 and 2 workers (rpg build
--check, fresh processes), and the peak memory of the largest process in the worker tree.

The machine's speed drifts by several per cent between runs, so the 1- and 2-worker runs
alternate, ``REPEATS`` times each, and the table reports medians (the speed-up is the
ratio of the median times) with the spread of the per-pair ratios."""

import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from _report import report

from rpg.library import load_manifest

REPEATS = 3
manifest = Path(__file__).resolve().parents[1] / "library" / "manifest.yaml"
entries = len(load_manifest(manifest).entries)
seconds: dict[int, list[float]] = {1: [], 2: []}
for _ in range(REPEATS):
    for jobs in (1, 2):
        t = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "rpg.cli", "build", str(manifest), "--check", "--jobs", str(jobs)],
                              capture_output=True, text=True)
        seconds[jobs].append(time.perf_counter() - t)
        if proc.returncode != 0:
            sys.exit(f"rpg build --check -j {jobs} failed:\n{proc.stdout}\n{proc.stderr}")
median = {jobs: statistics.median(s) for jobs, s in seconds.items()}
pairs = [a / b for a, b in zip(seconds[1], seconds[2], strict=True)]
rows = [(f"library ({entries} entries), {jobs} worker(s), median of {REPEATS}", entries / median[jobs], "entries/s", "")
        for jobs in (1, 2)]
rows.append(("speed-up 1 -> 2 workers (ratio of medians)", median[1] / median[2], "x", ">= 1.7"))
rows.append(("speed-up, lowest pair", min(pairs), "x", ""))
rows.append(("speed-up, highest pair", max(pairs), "x", ""))
peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
rows.append(("peak RSS of the largest worker process", peak_kb / 1024, "MiB", ""))
report("library", rows)
