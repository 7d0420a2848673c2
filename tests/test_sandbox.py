"""Hostile task code: each artifact is rejected by the text gate or contained by the worker
sandbox (limits, stripped environment, audit hook), with the reason in validation.log, and
nothing outside the sandbox changes (no file created, no secret leaked, the parent alive)."""

import json
import os
import shutil

import pytest

from rpg.compiler import compile_instruction, revalidate

SECRET = "sk-rpg-test-secret-7f3a"


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    return compile_instruction("Stack two blocks on top of each other.", tmp_path_factory.mktemp("base")).path


@pytest.fixture(autouse=True)
def secret_env(monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", SECRET)
    monkeypatch.setenv("RPG_TEST_SECRET", SECRET)
    monkeypatch.setenv("RPG_WORKER_TIMEOUT_S", "6")


def hostile(base, tmp_path, payload: str, where: str = "module", fname: str = "code.py"):
    d = tmp_path / "artifact"
    shutil.copytree(base, d)
    marker = tmp_path / "pwned"
    payload = payload.replace("MARKER", str(marker))
    text = (d / fname).read_text()
    if where == "module":
        text += "\n" + payload + "\n"
    else:  # inside goal(), which runs when the task is instantiated and evaluated
        body = "\n".join("        " + line for line in payload.splitlines())
        text = text.replace("    def goal(self):\n", "    def goal(self):\n" + body + "\n", 1)
    (d / fname).write_text(text)
    return d, marker


def assert_contained(d, marker):
    assert not marker.exists(), "the task code wrote outside the sandbox"
    log = (d / "validation.log").read_text() + (d / "validation.json").read_text()
    assert SECRET not in log
    assert sorted(p.name for p in d.iterdir()) == sorted(
        ["code.py", "goal_state_code.py", "task.yaml", "validation.log", "validation.json", "initial.png", "goal.png"])


TEXT_GATE = [
    "import os", "import sys", "import subprocess", "import socket", "import importlib", "import ctypes",
    "import pickle", "import shutil", "from os import system", "exec('x = 1')", "eval('1 + 1')",
    "open('MARKER', 'w')", "__import__('os')", "getattr(__builtins__, 'eval')",
    "().__class__.__bases__[0].__subclasses__()", "globals()['__builtins__']", "compile('1', 'f', 'eval')",
    "vars()", "breakpoint()", "x = '__' + 'import__'", "import numpy as np\nnp.save('MARKER', [1])",
    "import numpy as np\nnp.fromfile('/proc/self/environ')", "import numpy as np\nnp.ones(3).tofile('MARKER')",
    "import numpy as np\nnp.lib.format.open_memmap('MARKER', mode='w+', shape=(3,))",
    "global x", "import math as m, os", "import builtins",
    "BlockTask.__init__.__globals__", "from rpg import task_api",
]


@pytest.mark.parametrize("payload", TEXT_GATE)
def test_text_gate_rejects_hostile_code(base, tmp_path, payload):
    d, marker = hostile(base, tmp_path, payload)
    result = revalidate(d)
    assert not result.valid
    assert [g["gate"] for g in result.gates if g["status"] == "fail"] == ["text"]
    assert "FAIL" in (d / "validation.log").read_text() and "text" in (d / "validation.log").read_text()
    assert not marker.exists()


RUNTIME = [
    ("while True:\n    pass", "goal", "limit"),
    ("x = [0] * (10 ** 10)", "module", "MemoryError"),
    ("import numpy as np\nx = np.ones(10 ** 11)", "module", "Memory"),
    ("def f(n):\n    return f(n + 1)\nf(0)", "module", "RecursionError"),
    ("raise SystemExit(0)", "module", "worker"),
    ("raise KeyboardInterrupt", "module", "worker"),
    ("import math\nmath.factorial(10 ** 8)", "module", "limit"),
    ("return 1 / 0", "goal", "ZeroDivisionError"),
]


@pytest.mark.parametrize("payload,where,reason", RUNTIME)
def test_runtime_hostile_code_is_contained(base, tmp_path, payload, where, reason):
    d, marker = hostile(base, tmp_path, payload, where)
    result = revalidate(d)
    assert not result.valid
    fail = next(g for g in result.gates if g["status"] == "fail")
    assert reason in fail["message"] + fail.get("kind", ""), fail
    assert reason in (d / "validation.log").read_text() or fail.get("kind") == reason
    assert_contained(d, marker) if (d / "initial.png").exists() else None
    assert not marker.exists()


@pytest.mark.parametrize("coord", ["float('nan')", "float('inf')"])
def test_nan_and_inf_goal_poses_fail_the_goal_gate(base, tmp_path, coord):
    d = tmp_path / "a"
    shutil.copytree(base, d)
    g = (d / "goal_state_code.py").read_text()
    (d / "goal_state_code.py").write_text(g.replace("Pose((0.55,", f"Pose(({coord},", 1))
    result = revalidate(d)
    assert not result.valid
    assert any(g["status"] == "fail" and g["gate"] in ("goal_state", "bounds") for g in result.gates)


SANDBOX = [
    "import os\nos.system('touch MARKER')",
    "open('MARKER', 'w').write('x')",
    "import subprocess\nsubprocess.run(['touch', 'MARKER'])",
    "import socket\nsocket.socket().connect(('127.0.0.1', 9))",
    "import os\nwhile True:\n    os.fork()",
    "import os\nraise RuntimeError(str(dict(os.environ)))",
    "import numpy as np\nnp.save('MARKER', [1])",
    "import os\nos.rename('code.py', 'MARKER')",
    "import os\nos.kill(os.getppid(), 9)",
    "import shutil\nshutil.rmtree('/tmp')",
]


@pytest.mark.parametrize("payload", SANDBOX)
def test_sandbox_contains_code_that_bypasses_the_text_gate(base, tmp_path, payload):
    """Defence in depth: the text gate switched off (ablation), the worker still holds."""
    d, marker = hostile(base, tmp_path, payload)
    result = revalidate(d, disabled=frozenset({"text"}))
    assert not result.valid
    fail = next(g for g in result.gates if g["status"] == "fail")
    assert any(w in fail["message"] for w in ("sandbox", "RuntimeError", "not allowed")), fail
    text = (d / "validation.log").read_text() + (d / "validation.json").read_text()
    assert SECRET not in text
    assert not marker.exists() and (d / "code.py").exists() and os.path.isdir("/tmp")
    assert json.loads((d / "validation.json").read_text())["valid"] is False


def test_corpus_has_at_least_thirty_hostile_artifacts():
    assert len(TEXT_GATE) + len(RUNTIME) + 2 + len(SANDBOX) >= 30


def test_worker_results_are_schema_checked():
    from rpg.validate.results import checked_validate_result
    from rpg.validate.sandbox import WorkerError

    ok = {"gates": [{"gate": "smoke", "status": "pass", "duration_s": 0.01, "details": {}}]}
    assert checked_validate_result(ok)["gates"][0]["gate"] == "smoke"
    for bad in ({"gates": [{"gate": "smoke", "status": "pass", "duration_s": -1.0}]},
                {"gates": [{"gate": "rm -rf", "status": "pass", "duration_s": 0.0}]},
                {"gates": [], "extra": 1}, "not a dict", {"gates": [{"gate": "smoke", "status": "maybe", "duration_s": 0}]}):
        with pytest.raises(WorkerError, match="malformed"):
            checked_validate_result(bad)
