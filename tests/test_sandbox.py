"""Hostile task code: each artifact is rejected by the text gate or contained by the worker
sandbox (restricted execution, audit hook, limits, seccomp, namespaces), with the reason in
validation.log, and nothing outside the sandbox changes (no file created, no secret or
system file leaked, the parent alive, no process left)."""

import json
import os
import shutil
import subprocess
import sys
import threading
import time

import pytest

from rpg.compiler import compile_instruction, revalidate
from rpg.validate.isolation import namespaces_layer, seccomp_layer

SECRET = "sk-rpg-test-secret-7f3a"


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    return compile_instruction("Stack the blue block on top of the red block.", tmp_path_factory.mktemp("base")).path


@pytest.fixture(autouse=True)
def secret_env(monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", SECRET)
    monkeypatch.setenv("RPG_TEST_SECRET", SECRET)
    monkeypatch.setenv("RPG_WORKER_TIMEOUT_S", "6")


def hostile(base, tmp_path, payload: str, where: str = "module", fname: str = "code.py"):
    d = tmp_path / "artifact"
    shutil.copytree(base, d)
    marker = tmp_path / "pwned"
    payload = payload.replace("MARKER", str(marker)).replace("PARENT", str(os.getpid()))
    text = (d / fname).read_text()
    if where == "module":
        text += "\n" + payload + "\n"
    elif where == "class":  # a member of the task class
        body = "\n".join("    " + line for line in payload.splitlines())
        text = text.replace("    def goal(self):\n", body + "\n\n    def goal(self):\n", 1)
    elif where == "goal_class":  # a predicate subclass that goal() returns
        text += "\n" + payload + "\n"
        text = text.replace("return Stack(", "return Always(", 1)
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
    "import numpy as np\nnp.fromfile('/proc/self/environ')",
    "import numpy as np\nnp.lib.format.open_memmap('MARKER', mode='w+', shape=(3,))",
    "global x", "import math as m, os", "import builtins",
    "BlockTask.__init__.__globals__", "from rpg import task_api",
    # module-object reach-through (the attack review's remote code execution)
    "import rpg.task_api\nrpg.validate.child.json.sys.modules",
    "import numpy as np\nnp.matrixlib.defmatrix.sys.modules", "import numpy as np\nnp.ctypeslib",
    "from rpg.task_api import constants", "from numpy import ctypeslib", "from numpy import random",
    "import numpy as np\nnp.random.mtrand", "x = type(1)", "raise SystemExit(0)", "raise KeyboardInterrupt",
    "import numpy as np\nnp.load('/etc/passwd')", "BlockTask.reset._x", "'{0.__class__}'.format(1)",
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
    # past the text gate, stopped by the restricted runtime (guards on attributes, writes, imports)
    ("import numpy as np\nr = np.random\nr.mtrand", "module", "not available"),
    ("import numpy as np\nl = [np]\nl[0].matrixlib.defmatrix", "module", "not available"),
    ("import numpy as np\nnp.ones(3).tofile('MARKER')", "module", "not available"),
    ("Stack.evaluate = None", "module", "may not modify"),
    ("BlockTask.success = None", "module", "may not modify"),
    ("def success(self):\n    return True", "class", "redefines BlockTask.success"),
    ("class Always(Stack):\n    pass", "goal_class", "only rpg.task_api predicates"),
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
    "import ctypes\nrc = ctypes.CDLL(None).system(b'touch MARKER')\nraise RuntimeError(rc)",
    "import mujoco\nspec = mujoco.MjSpec()\nspec.compile()\nspec.to_file('MARKER')",
    "import mujoco\nm = mujoco.MjModel.from_xml_string('<mujoco/>')\nmujoco.mj_saveModel(m, 'MARKER', None)",
    "import os\nos.mkfifo('MARKER')",
    "import os\nos.setxattr('code.py', 'user.x', b'1')\nopen('MARKER', 'w')",
    "import os\nos.kill(PARENT, 9)",
    "import ctypes\nctypes.CDLL(None).kill(PARENT, 9)\nraise RuntimeError('sent')",
    "import os\nif os.fork() == 0:\n    os.setsid()\n    os.execv('/bin/sleep', ['sleep', '4242.5'])",

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
    """Defence in depth: the text gate switched off (ablation: the code runs as plain Python),
    the worker's other layers still hold."""
    d, marker = hostile(base, tmp_path, payload)
    result = revalidate(d, disabled=frozenset({"text"}))
    fail = next((g for g in result.gates if g["status"] == "fail"), None)
    assert fail is None or fail["message"], fail  # what matters is what did not happen:
    text = (d / "validation.log").read_text() + (d / "validation.json").read_text()
    assert SECRET not in text
    assert not marker.exists() and (d / "code.py").exists() and os.path.isdir("/tmp")
    assert json.loads((d / "validation.json").read_text())["valid"] is result.valid
    assert subprocess.run(["pgrep", "-f", "^sleep 4242[.]5"], capture_output=True).returncode == 1, "a process escaped"


needs_namespaces = pytest.mark.skipif(not namespaces_layer().active, reason=f"needs the namespace layer: {namespaces_layer().detail}")
needs_seccomp = pytest.mark.skipif(not seccomp_layer().active, reason=f"needs the seccomp layer: {seccomp_layer().detail}")

READ_SECRETS = """import os
text = ''
for p in sorted(os.listdir('/proc')):
    try:
        text += open('/proc/' + p + '/environ').read()
    except Exception as e:
        text += repr(e)
for f in ('/etc/passwd', '/etc/hostname', '/proc/PARENT/environ', os.path.expanduser('~/.bashrc')):
    try:
        text += open(f).read()
    except Exception as e:
        text += repr(e)
raise RuntimeError(text[:100000])
"""


@needs_namespaces
@pytest.mark.parametrize("disabled", [frozenset(), frozenset({"text"})], ids=["gated", "ablation"])
def test_task_code_sees_no_secret_and_no_system_file(base, tmp_path, disabled):
    """No other process is visible (PID namespace) and /etc is not mounted: neither the
    parent's API key nor /etc/passwd can end up in validation.log."""
    d, _ = hostile(base, tmp_path, READ_SECRETS if disabled else "import math", "module")
    result = revalidate(d, disabled=disabled)
    text = (d / "validation.log").read_text() + (d / "validation.json").read_text()
    assert SECRET not in text and "root:x:0:0" not in text
    if disabled:
        # /etc/passwd is not there at all (namespaces), or not readable (Landlock)
        assert not result.valid and ("FileNotFoundError" in text or "PermissionError" in text)


@needs_seccomp
@pytest.mark.parametrize("payload,reason", [
    ("import ctypes\nlibc = ctypes.CDLL(None)\nwhile True:\n    if libc.fork() < 0:\n        raise RuntimeError('fork refused')",
     "fork refused"),
    # no file can be opened for writing (seccomp, Landlock); where one could, RLIMIT_FSIZE bounds it
    ("f = open('big', 'wb')\nwhile True:\n    f.write(b'x' * 1048576)\n    f.flush()", "Operation not permitted|File too large"),
    ("import sys\nwhile True:\n    sys.stderr.write('x' * 1048576)\n    sys.stderr.flush()", "File too large"),
    ("import sys\nfor i in range(2000):\n    sys.stdout.write('x' * 1048576)\nraise RuntimeError('flooded')", "flooded"),
], ids=["fork-bomb", "file-size-bomb", "stderr-flood", "stdout-flood"])
def test_bombs_and_floods_are_bounded(base, tmp_path, payload, reason):
    d, marker = hostile(base, tmp_path, payload)
    t0 = time.monotonic()
    result = revalidate(d, disabled=frozenset({"text"}))
    assert not result.valid and time.monotonic() - t0 < 30
    fail = next(g for g in result.gates if g["status"] == "fail")
    assert any(r in fail["message"] or r in fail.get("details", {}).get("traceback", "") for r in reason.split("|")), fail


def test_the_worker_runs_with_every_active_layer(base, tmp_path):
    """What ``rpg doctor`` claims is what the process that runs task code has: a seccomp
    filter, its own PID namespace (it is a low PID and sees few processes), no network."""
    probe = ("import os, socket, ctypes\n"
             "seccomp = '2' if ctypes.CDLL(None).prctl(21, 0, 0, 0, 0) != 0 else '0'\n"  # PR_GET_SECCOMP: itself denied
             "try:\n    socket.create_connection(('1.1.1.1', 53), timeout=1)\n    net = 'up'\n"
             "except OSError as e:\n    net = 'down'\n"
             "raise RuntimeError('PROBE seccomp=%s pids=%d net=%s' % (seccomp, os.getpid(), net))")
    d, _ = hostile(base, tmp_path, probe)
    result = revalidate(d, disabled=frozenset({"text"}))
    message = next(g for g in result.gates if g["status"] == "fail")["message"]
    assert "PROBE" in message, message
    fields = dict(kv.split("=") for kv in message.split("PROBE ")[1].split())
    assert fields["net"] == "down"
    if seccomp_layer().active:
        assert fields["seccomp"] == "2"
    if namespaces_layer().active:
        assert int(fields["pids"]) < 10, "the worker should be a low PID of its own PID namespace"


def test_swapping_the_code_during_validation_never_runs_ungated_text(base, tmp_path):
    """Check-then-load race: a writer flips goal_state_code.py between a valid file and one
    the text gate refuses while ``validate`` runs; the worker runs only the text that was
    gated, so each run is VALID or a text-gate failure, never the hostile code running."""
    d = tmp_path / "a"
    shutil.copytree(base, d)
    good = (d / "goal_state_code.py").read_text()
    bad = good + "\nimport os\nraise RuntimeError('UNGATED CODE RAN')\n"
    stop = threading.Event()

    def flip():
        i = 0
        while not stop.is_set():
            tmp = d / f".swap{i % 2}"
            tmp.write_text(bad if i % 2 else good)
            os.replace(tmp, d / "goal_state_code.py")
            i += 1
            time.sleep(0.001)

    writer = threading.Thread(target=flip)
    writer.start()
    outcomes = set()
    try:
        for _ in range(30):
            result = revalidate(d)
            log = (d / "validation.log").read_text()
            assert "UNGATED CODE RAN" not in log
            fail = next((g for g in result.gates if g["status"] == "fail"), None)
            assert fail is None or fail["gate"] == "text", fail
            outcomes.add(fail["gate"] if fail else "valid")
    finally:
        stop.set()
        writer.join()
    assert outcomes, "validate ran"


def test_rpg_validate_as_a_process_survives_and_leaves_nothing(base, tmp_path):
    """The whole CLI under attack: a payload signals rpg, reads secrets and starts a detached
    sleeper; rpg exits 1 (invalid), is not killed, and no process is left behind."""
    payload = ("import ctypes\nlibc = ctypes.CDLL(None)\nlibc.kill(PARENT, 9)\n"
               "import os\nif os.fork() == 0:\n    os.setsid()\n    os.execv('/bin/sleep', ['sleep', '4242.5'])\n"
               + READ_SECRETS)
    d, marker = hostile(base, tmp_path, "pass")
    text = (d / "code.py").read_text().replace("\npass\n", "\n")
    env = {**os.environ, "OPENAI_API_KEY": SECRET}
    rpg = subprocess.Popen([os.path.join(os.path.dirname(sys.executable), "rpg"), "validate", str(d), "--disable", "text"], env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    (d / "code.py").write_text(text + "\n" + payload.replace("PARENT", str(rpg.pid)) + "\n")
    out, err = rpg.communicate(timeout=120)
    assert rpg.returncode == 1, (out, err)  # invalid, not killed by a signal
    everything = out + err + (d / "validation.log").read_bytes() + (d / "validation.json").read_bytes()
    assert SECRET.encode() not in everything and b"root:x:0:0" not in everything
    time.sleep(0.2)
    assert subprocess.run(["pgrep", "-f", "^sleep 4242[.]5"], capture_output=True).returncode == 1, "a process escaped"


def test_corpus_has_at_least_thirty_hostile_artifacts():
    assert len(TEXT_GATE) + len(RUNTIME) + 2 + len(SANDBOX) + 4 >= 60


def test_child_answers_are_schema_checked_data(monkeypatch):
    """What the sandboxed child answers is data checked against a schema: extra keys, wrong
    types, oversized lists and poses that are not 7 finite numbers are refused."""
    from rpg.validate import data as data_mod

    good = {"class": "T", "assets": [{"kind": "colored_cube", "name": "red", "color": "red"},
                                     {"kind": "colored_cube", "name": "blue", "color": "blue"}],
            "goal": {"predicate": "stack", "objects": ["red", "blue"]},
            "goal_poses": {"red": [0.55, 0, 0.97, 1, 0, 0, 0], "blue": [0.55, 0, 1.0105, 1, 0, 0, 0]},
            "rho0": {}, "errors": {}}
    answers = []
    from types import SimpleNamespace

    monkeypatch.setattr(data_mod, "_start", lambda *a, **k: SimpleNamespace(wait=lambda: {"ok": True, "result": answers[-1]}))
    answers.append(good)
    assert data_mod.fetch_task_data({"code.py": "", "goal_state_code.py": ""}).goal.name == "stack"
    for bad, why in [({**good, "verdict": "pass"}, "malformed"), ({**good, "assets": "x"}, "malformed"),
                     ({**good, "goal": {"predicate": "always_true"}}, "unknown predicate"),
                     ({**good, "goal": {"predicate": "stack", "objects": ["red", "ghost"]}}, "objects of the task"),
                     ({**good, "assets": [{"kind": "colored_cube", "name": "red", "color": "red", "size": 5.0}]}, "edge"),
                     ({**good, "assets": [{"kind": "colored_cube", "name": "../x", "color": "red"}]}, "invalid object name"),
                     ({**good, "assets": [{"kind": "colored_cube", "name": f"c{i}", "color": "red"} for i in range(65)]},
                      "malformed")]:
        answers.append(bad)
        with pytest.raises(data_mod.DataError, match=why):
            data_mod.fetch_task_data({"code.py": "", "goal_state_code.py": ""})
    for poses in ({"red": [0.5, 0, 1, 1, 0, 0, 0]}, {"red": [float("nan")] * 7, "blue": [0.5, 0, 1, 1, 0, 0, 0]},
                  {"red": [0.5, 0, 1, 0, 0, 0, 0], "blue": [0.5, 0, 1, 1, 0, 0, 0]}):
        answers.append({**good, "goal_poses": poses})
        got = data_mod.fetch_task_data({"code.py": "", "goal_state_code.py": ""})
        assert got.goal_poses is None and got.goal_error is not None


def test_sandbox_mounts_tmp_before_the_interpreter_and_packages(monkeypatch, tmp_path):
    """bwrap applies mounts in order: an interpreter, a virtual environment or a checkout
    under /tmp (as on CI machines) must be bound after the sandbox's tmpfs /tmp, or the
    server cannot even start."""
    from rpg.validate import isolation

    monkeypatch.setattr(isolation, "_python_roots", lambda: [str(tmp_path / "venv"), "/opt/python"])
    argv = isolation.bwrap_argv({"PATH": "/usr/bin"}, writable=str(tmp_path / "work"))
    tmpfs = argv.index("--tmpfs")
    binds = [i for i, a in enumerate(argv) if a in ("--ro-bind", "--bind") and argv[i + 1] != "/usr"]
    assert binds and all(i > tmpfs for i in binds)
    assert argv[argv.index("--bind") + 1] == str(tmp_path / "work")


def _children_of(pid: int) -> set[int]:
    out = subprocess.run(["pgrep", "-P", str(pid)], capture_output=True, text=True).stdout
    return {int(p) for p in out.split()}


def test_a_prepared_child_serves_one_request_and_an_unused_one_dies_with_rpg(base, tmp_path):
    """prepare() starts the next request's child early; that child answers exactly one request
    (the next request starts its own), and one prepared but never used is gone when rpg exits."""
    from rpg.artifact import task_sources
    from rpg.validate import sandbox

    sources = task_sources(base)
    request = {"op": "data", "sources": sources, "seeds": [0], "draws": 1, "goal_state": False, "restricted": True}
    sandbox.prepare()
    prepared = sandbox._spare.proc.pid
    first = sandbox.ChildRun(request)
    assert first.proc.pid == prepared and sandbox._spare is None
    second = sandbox.ChildRun(request)
    assert second.proc.pid != prepared
    assert first.wait()["ok"] and second.wait()["ok"]
    assert first.proc.returncode == 0 and second.proc.returncode == 0

    code = ("import sys, time\nfrom rpg.validate import sandbox\nsandbox.prepare()\n"
            "print(sandbox._spare.proc.pid, flush=True)\ntime.sleep(0.5)\n")
    script = tmp_path / "prepare_and_exit.py"
    script.write_text(code)
    proc = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    pid = int(proc.stdout.split()[0])
    time.sleep(0.2)
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def test_a_process_forked_after_prepare_neither_takes_nor_holds_the_parents_child(base):
    """A pool worker forked while a child is prepared must not use it, and must not keep its
    request pipe open: the parent's request still ends and is answered."""
    from rpg.artifact import task_sources
    from rpg.validate import sandbox

    sandbox.prepare()
    prepared = sandbox._spare.proc.pid
    pid = os.fork()
    if pid == 0:  # the forked worker: no spare of its own; stays alive while the parent asks
        ok = sandbox._spare is None
        time.sleep(3)
        os._exit(0 if ok else 3)
    try:
        request = {"op": "data", "sources": task_sources(base), "seeds": [0], "draws": 1, "goal_state": False,
                   "restricted": True}
        run = sandbox.ChildRun(request, timeout=2.5)
        assert run.proc.pid == prepared
        assert run.wait()["ok"]
    finally:
        _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
