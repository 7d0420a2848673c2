"""`make baseline`: demonstrations -> training -> rpg eval (baseline, oracle, random) -> compare -> table.

    python examples/baseline/run.py [--out build/baseline] [--demos 100] [--seeds 1000-1019] [--jobs 2]

1. ``rpg demos`` of every training task of library/manifest.yaml (``split: train``), Panda,
   state only (``--cameras ''``), robomimic HDF5: OUT/demos/<task>/demo.hdf5;
2. ``rpg build`` of the steered families (examples/baseline/steered/, copied to OUT/steered);
3. ``train.py``: OUT/bc.pt;
4. ``rpg eval`` of the baseline, the oracle and random on the training tasks (split=train),
   the steered families (every version, grouped by intent) and the library's evaluation
   split (split=eval), on held-out seeds: OUT/runs/<policy>/<set>/;
5. ``rpg eval compare`` oracle vs baseline and baseline vs random: OUT/compare/*.txt;
6. table.py: OUT/results.md; OUT/cost.json, the wall time of each stage.

Every stage resumes: demos and evaluations continue where a killed run stopped, training is
skipped while OUT/bc.pt exists.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
POLICIES = {"bc": "examples/baseline/policy.py:BCPolicy", "oracle": "oracle", "random": "random"}


def train_tasks(manifest: Path) -> list[str]:
    from rpg.library.build import load_manifest

    return [e.name for e in load_manifest(manifest).entries if e.split == "train"]


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=ROOT / "build" / "baseline")
    ap.add_argument("--demos", type=int, default=100, help="successful demonstrations per training task")
    ap.add_argument("--seeds", default="1000-1019", help="evaluation seeds (held out: demos use 0, 1, ...)")
    ap.add_argument("--steps", type=int, default=4000, help="training steps")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--sets", default="train,steered,eval", help="what to evaluate (comma-separated)")
    args = ap.parse_args(argv)
    os.chdir(ROOT)
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    rpg = str(Path(sys.executable).with_name("rpg"))
    cost_path = out / "cost.json"
    cost = json.loads(cost_path.read_text()) if cost_path.exists() else {}

    def stage(name: str, fn) -> None:
        t0 = time.monotonic()
        print(f"== {name}", flush=True)
        fn()
        cost[name] = round(cost.get(name, 0.0) + time.monotonic() - t0, 1)  # summed over resumed invocations
        cost_path.write_text(json.dumps(cost, indent=2) + "\n")

    def run(cmd: list[str]) -> None:
        print("$ " + " ".join(cmd), flush=True)
        subprocess.run(cmd, check=True)

    def demos() -> None:
        for task in train_tasks(ROOT / "library" / "manifest.yaml"):
            run([rpg, "demos", f"library/{task}", "--format", "hdf5", "--cameras", "", "--embodiment", "panda",
                 "-n", str(args.demos), "-j", str(args.jobs), "-o", str(out / "demos" / task)])

    def steered() -> None:
        dest = out / "steered"
        dest.mkdir(exist_ok=True)
        for f in sorted((HERE / "steered").glob("*.yaml")):
            shutil.copyfile(f, dest / f.name)
        run([rpg, "build", str(dest / "manifest.yaml"), "--jobs", str(args.jobs)])

    def train() -> None:
        if (out / "bc.pt").exists():
            print(f"{out / 'bc.pt'} exists; training skipped (delete it to retrain)")
            return
        run([sys.executable, str(HERE / "train.py"), str(out / "demos"), "-o", str(out / "bc.pt"),
             "--steps", str(args.steps), "--threads", "2"])

    targets = {"train": "split=train", "steered": str(out / "steered" / "manifest.yaml"), "eval": "split=eval"}
    sets = [s for s in args.sets.split(",") if s]

    def evaluate(policy: str, which: str) -> None:
        os.environ["RPG_BC_CHECKPOINT"] = str(out / "bc.pt")
        run([rpg, "eval", targets[which], "--policy", POLICIES[policy], "--embodiment", "panda", "--cameras", "",
             "--seeds", args.seeds, "-j", str(args.jobs), "-o", str(out / "runs" / policy / which)])

    def compare() -> None:
        (out / "compare").mkdir(exist_ok=True)
        for which in sets:
            for a, b in (("oracle", "bc"), ("bc", "random")):
                res = subprocess.run([rpg, "eval", "compare", str(out / "runs" / a / which),
                                      str(out / "runs" / b / which)], capture_output=True, text=True,
                                     env={**os.environ, "COLUMNS": "160"})
                (out / "compare" / f"{which}_{a}_vs_{b}.txt").write_text(res.stdout + res.stderr)
                print(res.stdout[-3000:])

    def table() -> None:
        run([sys.executable, str(HERE / "table.py"), str(out / "runs"), "-o", str(out / "results.md")])

    t_all = time.monotonic()
    stage("demos", demos)
    stage("steered", steered)
    stage("train", train)
    for which in sets:
        for policy in POLICIES:
            stage(f"eval {policy} {which}", lambda p=policy, w=which: evaluate(p, w))
    stage("compare", compare)
    stage("table", table)
    cost["total_this_invocation"] = round(time.monotonic() - t_all, 1)
    cost["cpus"] = os.cpu_count()
    cost_path.write_text(json.dumps(cost, indent=2) + "\n")
    print((out / "results.md").read_text())
    print(f"cost (s): {json.dumps(cost)}")


if __name__ == "__main__":
    main()
