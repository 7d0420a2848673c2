"""Library benchmark: batch throughput of the whole library with 1 and 2 workers (rpg build
--check, fresh processes), and the peak memory of the largest process in the worker tree."""

import resource
import subprocess
import sys
import time
from pathlib import Path

from _report import report

from rpg.library import load_manifest

manifest = Path(__file__).resolve().parents[1] / "library" / "manifest.yaml"
entries = len(load_manifest(manifest).entries)
rows, seconds = [], {}
for jobs in (1, 2):
    t = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "build", str(manifest), "--check", "--jobs", str(jobs)],
                          capture_output=True, text=True)
    seconds[jobs] = time.perf_counter() - t
    if proc.returncode != 0:
        sys.exit(f"rpg build --check -j {jobs} failed:\n{proc.stdout}\n{proc.stderr}")
    rows.append((f"library ({entries} entries), {jobs} worker(s)", entries / seconds[jobs], "entries/s", ""))
rows.append(("speed-up 1 -> 2 workers", seconds[1] / seconds[2], "x", ">= 1.7"))
peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
rows.append(("peak RSS of the largest worker process", peak_kb / 1024, "MiB", ""))
report("library", rows)
