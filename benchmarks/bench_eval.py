"""rpg eval throughput (issue "rpg eval": episodes per second, oracle, floating gripper, no
video, 1 vs 2 jobs; target speed-up >= 1.7x).

    python benchmarks/bench_eval.py [--seeds 20] [--target library/manifest.yaml]
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    from rpg.eval import EvalConfig, run_eval

    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--target", default="split=train")
    args = ap.parse_args()
    rates = {}
    for jobs in (1, 2):
        out = Path(tempfile.mkdtemp(prefix="rpg-bench-eval-"))
        try:
            cfg = EvalConfig(args.target, "oracle", tuple(range(args.seeds)), embodiment="floating_gripper",
                             library=str(ROOT / "library" / "manifest.yaml"))
            t0 = time.perf_counter()
            summary = run_eval(cfg, out / "run", jobs=jobs)
            dt = time.perf_counter() - t0
        finally:
            shutil.rmtree(out, ignore_errors=True)
        n = summary["overall"]["n"]
        rates[jobs] = n / dt
        print(f"rpg eval, oracle, floating gripper, {args.target}: {n} episodes with {jobs} job(s) in {dt:.1f} s "
              f"= {rates[jobs]:.2f} episodes/s (success {summary['overall']['mean']:.2f})")
    print(f"speed-up 2 jobs vs 1: {rates[2] / rates[1]:.2f}x (target >= 1.7x)")


if __name__ == "__main__":
    main()
