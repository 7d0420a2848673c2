"""Memory per open environment: the resident-set growth of a process that opens N Panda
environments of different library tasks, as an ``rpg eval`` worker does (issue 32; it sets
:data:`rpg.eval.runner.ENV_PER_PROCESS_MB` and through it ``ENV_CACHE_SIZE``).

Each case runs in a fresh child process (so one case's freed memory does not hide the next
one's): import rpg, open one environment and reset it (one-time costs: MuJoCo, the mesh files,
the GL context when there are cameras), then open and reset N more, reading ``VmRSS`` from
``/proc/self/status`` after each.  The figure per environment is the growth over those N
divided by N.  Cases: the Panda with the decimated meshes (the default) and with the stock
ones, state-only (``rpg eval``'s built-in policies) and with two 224x224 cameras (a learned
policy's default; the first observation renders both); the floating gripper for comparison; the
Panda's two cameras with the wrist camera supersampled 2x (``--wrist-supersample 2``: a second
renderer and GL context per environment).

    python benchmarks/bench_env_memory.py [--n N]
"""

import json
import subprocess
import sys
from pathlib import Path

from _report import report

ROOT = Path(__file__).resolve().parents[1]
TASKS = ["stack_blocks", "three_block_stack", "align_blocks", "arrange_blocks", "block_alignment",
         "arrange_word", "arrange_letters", "circle_test", "arrange_shapes"]
N = int(sys.argv[sys.argv.index("--n") + 1]) if "--n" in sys.argv else 6

CHILD = r"""
import json, sys
import rpg  # sets MUJOCO_GL before mujoco loads
from rpg.env import BlockTaskEnv

def rss_mb():
    for line in open("/proc/self/status"):
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024

embodiment, visual, cameras, tasks, k = json.loads(sys.argv[1])
envs, rss = [], []
for t in tasks:
    env = BlockTaskEnv(t, embodiment=embodiment, cameras=tuple(cameras), image_size=(224, 224), visual=visual,
                       wrist_supersample=k)
    env.reset(seed=0)
    envs.append(env)
    rss.append(rss_mb())
print(json.dumps(rss))
"""


def case(embodiment: str, visual: str, cameras: tuple[str, ...], wrist_supersample: int = 1) -> list[float]:
    tasks = [str(ROOT / "library" / t) for t in TASKS[:N + 1]]
    out = subprocess.run([sys.executable, "-c", CHILD, json.dumps([embodiment, visual, cameras, tasks,
                                                                   wrist_supersample])],
                         capture_output=True, text=True, check=True, cwd=ROOT)
    return json.loads(out.stdout.strip().splitlines()[-1])


rows = []
for embodiment, visual in (("panda", "decimated"), ("panda", "stock"), ("floating_gripper", "decimated")):
    for cameras in ((), ("agentview", "wrist")):
        rss = case(embodiment, visual, cameras)
        label = f"{embodiment}, {visual}, {'2 cameras 224x224' if cameras else 'state-only'}"
        rows.append((f"{label}: per environment (RSS growth over {N} more / {N})", (rss[-1] - rss[0]) / N, "MB", ""))
        rows.append((f"{label}: process with the first environment", rss[0], "MB", ""))
rss = case("panda", "decimated", ("agentview", "wrist"), wrist_supersample=2)
label = "panda, decimated, 2 cameras 224x224, wrist 2x"
rows.append((f"{label}: per environment (RSS growth over {N} more / {N})", (rss[-1] - rss[0]) / N, "MB", ""))
rows.append((f"{label}: process with the first environment", rss[0], "MB", ""))
report("env_memory", rows)
