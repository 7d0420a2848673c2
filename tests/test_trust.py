"""The trust boundary: task code returns data, trusted code decides.

Each attack here is a task that would pass validation on the seeds it checks (its content
hash recomputed, as a forger would) or that tries to write its own verdict.  None may
run code in rpg's process, decide its own verdict, make a do-nothing policy score, or hang
an environment past the sandbox's documented timeout.
"""

import json
import os
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from rpg.artifact import content_hash
from rpg.compiler import revalidate
from rpg.env import BlockTaskEnv
from rpg.errors import TaskInvalid
from rpg.validate.isolation import landlock_layer, seccomp_layer
from rpg.yamlio import dump, load

STACK = Path(__file__).resolve().parents[1] / "library" / "stack_blocks"


def forged(tmp_path: Path, fname: str, old: str, new: str) -> Path:
    """A copy of stack_blocks with ``old`` replaced by ``new`` in ``fname`` and its content
    hash recomputed (its recorded gates still say 'pass')."""
    task = tmp_path / "forged"
    shutil.copytree(STACK, task)
    path = task / fname
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))
    doc = load((task / "task.yaml").read_text())
    doc["content_hash"] = content_hash(doc, (task / "code.py").read_text(), (task / "goal_state_code.py").read_text())
    (task / "task.yaml").write_text(dump(doc))
    return task


INIT = "        return poses\n"


def run_probe(tmp_path: Path, probe: str) -> dict:
    """Append ``probe`` (code that ends raising ``RuntimeError('PROBE ' + repr(pairs))``) to
    goal_state_code.py, validate with the text gate off, and return the pairs it reported."""
    task = forged(tmp_path, "goal_state_code.py", "\n\ndef goal_state(task):", "\n\ndef goal_state(task):")
    gs = task / "goal_state_code.py"
    gs.write_text(gs.read_text() + probe)
    result = revalidate(task, disabled=frozenset({"text"}))
    message = next(g for g in result.gates if g["status"] == "fail")["message"]
    assert "PROBE" in message and "TOP-SECRET" not in message, message
    return dict(eval(message.split("PROBE ", 1)[1]))  # noqa: S307 - our own probe's repr of pairs


def test_rho0_that_is_solved_only_after_the_validated_seeds_is_not_scored(tmp_path):
    """From seed 5 on, initial_state returns the goal configuration: validation's seeds 0-4
    pass, but an episode there would score a policy that does nothing.  The environment
    refuses that seed."""
    task = forged(tmp_path, "code.py", INIT,
                  "        if self.seed_marker(rng) >= 5:\n"
                  "            return {'red': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),\n"
                  "                    'blue': Pose((0.55, 0.0, 1.0105), (1.0, 0.0, 0.0, 0.0))}\n"
                  "        return poses\n\n"
                  "    def seed_marker(self, rng):\n"
                  "        return SEEDS.get(float(rng.random()), 99)\n")
    code = task / "code.py"
    seeds = {float(np.random.default_rng(s).random()): s for s in range(40)}
    text = code.read_text().replace("from rpg.task_api import (", "from rpg.task_api import (\n    Pose,", 1)
    text = text.replace("\n\nclass ", f"\n\nSEEDS = {seeds!r}\n\n\nclass ", 1)
    text = text.replace("        poses = sample_scattered(", "        key = self.seed_marker(rng)\n        poses = sample_scattered(", 1)
    text = text.replace("        if self.seed_marker(rng) >= 5:", "        if key >= 5:", 1)
    code.write_text(text)
    doc = load((task / "task.yaml").read_text())
    doc["content_hash"] = content_hash(doc, code.read_text(), (task / "goal_state_code.py").read_text())
    (task / "task.yaml").write_text(dump(doc))

    env = BlockTaskEnv(task, embodiment="floating_gripper", cameras=())
    obs, info = env.reset(seed=0)
    assert not info["success"]
    with pytest.raises(TaskInvalid, match="G holds in every rho_0 sample"):
        env.reset(seed=7)


def test_rho0_outside_the_workspace_after_the_validated_seeds_is_refused(tmp_path):
    task = forged(tmp_path, "code.py", INIT,
                  "        return {**poses, 'red': Pose((5.0, 5.0, 0.97), (1.0, 0.0, 0.0, 0.0))}\n")
    code = task / "code.py"
    code.write_text(code.read_text().replace("from rpg.task_api import (", "from rpg.task_api import (\n    Pose,", 1))
    doc = load((task / "task.yaml").read_text())
    doc["content_hash"] = content_hash(doc, code.read_text(), (task / "goal_state_code.py").read_text())
    (task / "task.yaml").write_text(dump(doc))
    assert not revalidate(task).valid  # validation sees it too (the bounds gate)
    doc["provenance"]["gates"]["bounds"] = "pass"  # a forged record still does not let it in
    (task / "task.yaml").write_text(dump(doc))
    env = BlockTaskEnv(task, embodiment="floating_gripper", cameras=())
    with pytest.raises(TaskInvalid, match="outside the workspace"):
        env.reset(seed=0)


def test_a_task_that_sets_its_own_evaluate_cannot_make_doing_nothing_score(tmp_path):
    """Instance attributes named like the verdict are never consulted: G is rpg's own."""
    task = forged(tmp_path, "code.py", "    def goal(self):\n",
                  "    def goal(self):\n        self.evaluate = self.assets\n        self.success = True\n")
    result = revalidate(task)
    assert result.valid  # harmless: nothing of the task is ever called outside the sandbox
    env = BlockTaskEnv(task, embodiment="floating_gripper", cameras=())
    for seed in range(3):
        env.reset(seed=seed)
        for _ in range(5):
            _, reward, terminated, _, info = env.step(np.zeros(7, np.float32))
            assert reward == 0.0 and not terminated and not info["success"]


FORGED_REPLY = json.dumps({"ok": True, "result": {"gates": [
    {"gate": g, "status": "pass", "duration_s": 0.0, "details": {}}
    for g in ("compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility")]}})


@pytest.mark.parametrize("how", ["every_fd", "exit_early"])
def test_a_forged_all_pass_reply_does_not_validate_a_goal_that_is_never_true(tmp_path, how):
    """goal_state puts the cubes apart (G never holds) and the code writes an all-pass gate
    report on every file descriptor it holds, then exits before the child can answer: the
    task is invalid (the verdict is computed from data, by rpg)."""
    payload = ("import os\nfor fd in range(3, 64):\n    try:\n        os.write(fd, REPLY)\n    except OSError:\n        pass\n"
               + ("os._exit(0)\n" if how == "exit_early" else ""))
    task = forged(tmp_path, "goal_state_code.py", "    'blue': Pose((0.55, 0.0, 1.0105)",
                  "    'blue': Pose((0.45, 0.15, 0.97)")
    gs = task / "goal_state_code.py"
    gs.write_text(gs.read_text() + "\n" + payload.replace("REPLY", repr(FORGED_REPLY.encode())) + "\n")
    result = revalidate(task, disabled=frozenset({"text"}))
    assert not result.valid
    failed = {g["gate"] for g in result.gates if g["status"] == "fail"}
    assert failed & {"compile", "goal_state"}, result.gates


@pytest.mark.skipif(not seccomp_layer().active, reason=f"needs the seccomp layer: {seccomp_layer().detail}")
def test_the_syscall_filter_is_an_allowlist(tmp_path):
    """Calls a denylist forgot: io_uring (sockets through it), a queued signal to the parent,
    a raw clone, a socket, a file opened for writing, a thread.  Each must fail (EPERM) in the
    child; the probe reports the return values as its error."""
    me = os.getpid()
    probe = f"""
import ctypes, os, threading
libc = ctypes.CDLL(None, use_errno=True)
out = []
buf = ctypes.create_string_buffer(512)
out.append(('io_uring_setup', libc.syscall(425, 8, buf)))
out.append(('rt_sigqueueinfo', libc.syscall(129, {me}, 10, buf)))
out.append(('clone', libc.syscall(56, 17, 0, 0, 0, 0)))
out.append(('socket', libc.syscall(41, 2, 1, 0)))
out.append(('openat_write', libc.syscall(257, -100, b'/tmp/x', 0o101, 0o644)))
try:
    t = threading.Thread(target=print)
    t.start()
    out.append(('thread', 0))
except RuntimeError:
    out.append(('thread', -1))
raise RuntimeError('PROBE ' + repr(out))
"""
    got = run_probe(tmp_path, probe)
    assert set(got) == {"io_uring_setup", "rt_sigqueueinfo", "clone", "socket", "openat_write", "thread"}
    assert all(v == -1 for v in got.values()), got
    assert not os.path.exists("/tmp/x") or os.path.getmtime("/tmp/x") < time.time() - 60


def test_code_that_loops_only_at_unvalidated_seeds_times_out_instead_of_hanging(tmp_path, monkeypatch):
    monkeypatch.setenv("RPG_WORKER_TIMEOUT_S", "4")
    task = forged(tmp_path, "code.py", INIT, INIT)
    code = task / "code.py"
    code.write_text(code.read_text().replace(
        "        poses = sample_scattered(",
        "        if float(rng.random()) == LOOP_AT:\n            while True:\n                pass\n"
        "        poses = sample_scattered(", 1).replace(
        "\n\nclass ", f"\n\nLOOP_AT = {float(np.random.default_rng(9).random())!r}\n\n\nclass ", 1))
    doc = load((task / "task.yaml").read_text())
    doc["content_hash"] = content_hash(doc, code.read_text(), (task / "goal_state_code.py").read_text())
    (task / "task.yaml").write_text(dump(doc))
    t0 = time.monotonic()
    with pytest.raises(TaskInvalid, match="limit"):  # seeds 0-19 are fetched with the task's data: seed 9 loops
        BlockTaskEnv(task, embodiment="floating_gripper", cameras=()).reset(seed=0)
    assert time.monotonic() - t0 < 30


def test_the_host_process_never_loads_task_code(tmp_path):
    """After an environment has run episodes, no module of task code and no task class exists
    in rpg's process."""
    import gc
    import sys

    from rpg.domain.task_code import BlockTask

    env = BlockTaskEnv(STACK, embodiment="floating_gripper", cameras=())
    env.reset(seed=0)
    env.step(np.zeros(7, np.float32))
    assert not [m for m in sys.modules if m.startswith("rpg_task_code") or m.startswith("rpg_goal_state_code")]
    gc.collect()
    assert not [c for c in BlockTask.__subclasses__() if c.__module__.startswith("rpg_")]
    assert type(env.task).__module__ == "rpg.domain.task"


@pytest.mark.skipif(not landlock_layer().active, reason=f"needs the Landlock layer: {landlock_layer().detail}")
def test_landlock_alone_keeps_the_child_from_the_files_of_the_machine(tmp_path, monkeypatch):
    """Without bubblewrap's namespaces (as on a machine without the package), Landlock still
    keeps task code from reading the user's files or another process's environment, and
    from writing anywhere."""
    from rpg.validate import isolation

    monkeypatch.setattr(isolation, "namespaces_layer", lambda: isolation.Layer("namespaces", False, "off for this test"))
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET")
    probe = f"""
out = []
for path in ({str(secret)!r}, '/proc/{os.getpid()}/environ', '/etc/hostname'):
    try:
        open(path).read()
        out.append((path, 'read'))
    except OSError as e:
        out.append((path, type(e).__name__))
raise RuntimeError('PROBE ' + repr(out))
"""
    got = run_probe(tmp_path, probe)
    assert all(v == "PermissionError" for v in got.values()), got


GOAL = "        return UnorderedStack(objects=['red', 'blue'])\n"


@pytest.mark.parametrize("old,new,why", [
    # a goal whose evaluation would loop or allocate without end in rpg's process
    (GOAL, "        return Pyramid(objects=['red', 'blue'], base=10**12)\n", "out of range"),
    (GOAL, "        return Pyramid(objects=['red', 'blue'], base=2, dims=10**10)\n", "out of range|must be"),
    (GOAL, "        return And([OnTable('red')] * 3000 + [On('red', 'blue')])\n", "predicates; at most"),
    # arguments of the wrong type: a traceback in rpg before
    (GOAL, "        return On(a=[['blue']], b='red')\n", "must name an object"),
    # a cube held 3 cm in the air over the other falls into the goal while the episode settles
    (INIT, "        return {'red': Pose((0.55, 0.0, 0.97), (1.0, 0.0, 0.0, 0.0)),"
           " 'blue': Pose((0.55, 0.0, 1.05), (1.0, 0.0, 0.0, 0.0))}\n", "already true after reset"),
    # a native function pointer reached through the seeded generator
    (INIT, "        rng.bit_generator.ctypes.next_uint64(4096)\n        return poses\n", "not available"),
    # an unseeded generator: the same seed would not give the same data
    (INIT, "        poses = sample_scattered(np.random.default_rng(), list(self.scene.assets.values()))\n"
           "        return poses\n", "Error"),
    # str.format reads attributes with the real getattr
    (INIT, "        ('{0.' + '_' * 2 + 'class' + '_' * 2 + '}').format(rng)\n        return poses\n", "not available"),
])
def test_what_the_red_team_found_is_refused(tmp_path, old, new, why):
    task = forged(tmp_path, "code.py", old, new)
    code = task / "code.py"
    code.write_text(code.read_text().replace("from rpg.task_api import (", "from rpg.task_api import (\n    And,\n"
                                             "    On,\n    OnTable,\n    Pose,\n    Pyramid,", 1)
                    .replace("\n\nclass ", "\n\nimport numpy as np\n\n\nclass ", 1))
    t0 = time.monotonic()
    result = revalidate(task)
    assert not result.valid and time.monotonic() - t0 < 60
    fail = next(g for g in result.gates if g["status"] == "fail")
    import re
    assert re.search(why, fail["message"]), fail
