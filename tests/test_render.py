"""Snapshots through the fork server's warm, shared OpenGL context: the same pixels as a
fresh ``mujoco.Renderer``, a server that stays single-threaded (it forks), and the
fallback when the renderer starts threads after all."""

import base64
import io
import json
import os
import subprocess
import sys
import time

import numpy as np
import pytest
from PIL import Image

from rpg.artifact import task_sources
from rpg.compiler import compile_instruction
from rpg.validate import sandbox
from rpg.validate.sandbox import FORK_SAFE_GL_ENV, run_worker


@pytest.fixture(scope="module")
def letters(tmp_path_factory):
    return compile_instruction("Spell CAB with letter blocks in a row", tmp_path_factory.mktemp("cab")).path


def _image(result: dict, key: str) -> np.ndarray:
    png = result["result"]["snapshots"][key]
    if png is None:
        pytest.skip("no headless OpenGL on this machine")
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(png))).convert("RGB")).astype(int)


def _threads(pid: int) -> int:
    return len(os.listdir(f"/proc/{pid}/task"))


def _ask(proc: subprocess.Popen, request: dict) -> dict:
    payload = json.dumps({**request, "_timeout": 60}).encode()
    proc.stdin.write(f"{len(payload)}\n".encode() + payload)
    proc.stdin.flush()
    n = int(proc.stdout.readline())
    return json.loads(proc.stdout.read(n))


def test_shared_context_renders_what_a_fresh_renderer_renders(letters, monkeypatch):
    warm = run_worker({"op": "render", "dir": str(letters), "seed": 3})
    assert warm["ok"], warm
    monkeypatch.setenv("RPG_FORKSERVER", "0")  # one interpreter per request: its own mujoco.Renderer
    fresh = run_worker({"op": "render", "dir": str(letters), "seed": 3})
    assert fresh["ok"], fresh
    for key in ("initial", "goal"):
        a, b = _image(warm, key), _image(fresh, key)
        assert a.shape == b.shape == (480, 640, 3)
        assert a.std() > 5, "blank image"
        assert np.abs(a - b).mean() < 0.05, key
    assert np.abs(_image(warm, "initial") - _image(warm, "goal")).mean() > 0.5  # two different states


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs Linux /proc")
def test_fork_server_keeps_a_warm_context_and_one_thread(letters):
    sandbox.prestart()
    assert run_worker({"op": "render", "dir": str(letters), "seed": 0})["ok"]
    server = sandbox._server
    pid = _python_server(server.proc.pid)
    assert _threads(pid) == 1
    environ = open(f"/proc/{pid}/environ", "rb").read().split(b"\0")
    assert b"RPG_WARM_GL=0" not in environ  # no fallback was needed here
    maps = open(f"/proc/{pid}/maps").read()
    assert any(driver in maps for driver in ("_dri.so", "libgallium", "libnvidia-eglcore")), \
        "the server should hold an initialized OpenGL driver (the warm context)"


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs Linux /proc")
def test_fork_server_drops_the_warm_context_when_the_renderer_starts_threads(letters, tmp_path):
    env = {k: v for k, v in sandbox._worker_env().items() if k not in FORK_SAFE_GL_ENV}
    env["LP_NUM_THREADS"] = "2"  # llvmpipe rasterizer threads: forking with them is unsafe
    proc = subprocess.Popen([sys.executable, "-m", "rpg.validate.forkserver"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, cwd=tmp_path, env=env)
    try:
        doc = _ask(proc, {"op": "render", "sources": task_sources(letters), "seed": 0})
        assert doc["ok"], doc
        _image(doc, "goal")
        environ = open(f"/proc/{proc.pid}/environ", "rb").read().split(b"\0")
        assert b"RPG_WARM_GL=0" in environ, "the server should have re-executed without the warm context"
        time.sleep(0.1)
        assert _threads(proc.pid) == 1
    finally:
        proc.kill()
        proc.wait()


def _python_server(pid: int) -> int:
    """The fork server's own process: ``pid`` itself, or, when the server runs inside
    bubblewrap's namespaces, the descendant of ``pid`` that runs the server."""
    todo = [pid]
    while todo:
        p = todo.pop(0)
        cmd = open(f"/proc/{p}/cmdline", "rb").read().split(b"\0")
        if b"rpg.validate.forkserver" in cmd and b"bwrap" not in os.path.basename(cmd[0]):
            return p
        todo += _children(p)
    raise AssertionError(f"no fork server under {pid}")


def _children(pid: int) -> list[int]:
    kids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = open(f"/proc/{entry}/stat").read()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                kids.append(int(entry))
    return sorted(kids)


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs Linux /proc")
def test_template_gives_each_worker_a_warm_clone_of_one_server(letters):
    reference = run_worker({"op": "render", "dir": str(letters), "seed": 2})
    with sandbox.ForkServerTemplate() as template:
        clients = [sandbox._ForkServer(template.address) for _ in range(2)]
        try:
            docs = [c.run({"op": "render", "dir": str(letters), "seed": 2}, 60) for c in clients]
            server = _python_server(template.proc.pid)
            clones = _children(server)
            assert len(clones) == 2, "one clone per connection, forked by the template"
            for pid in clones:
                assert _threads(pid) == 1
                assert b"RPG_WARM_GL=0" not in open(f"/proc/{pid}/environ", "rb").read().split(b"\0")
                maps = open(f"/proc/{pid}/maps").read()
                assert any(d in maps for d in ("_dri.so", "libgallium", "libnvidia-eglcore")), "clone has no warm context"
            for doc in docs:
                assert doc["ok"], doc
                for key in ("initial", "goal"):
                    assert np.abs(_image(doc, key) - _image(reference, key)).mean() < 0.05
            clients[0].close()  # a worker that goes away ends its clone
            deadline = time.monotonic() + 10
            while len(_children(server)) > 1 and time.monotonic() < deadline:
                time.sleep(0.05)
            left = _children(server)
            assert len(left) == 1 and left[0] in clones
            assert clients[1].run({"op": "render", "dir": str(letters), "seed": 2}, 60)["ok"]
        finally:
            for c in clients:
                c.close()
    assert template.proc.poll() is not None and not os.path.exists(template.dir)


def test_unreachable_template_falls_back_to_an_own_server(letters, tmp_path, monkeypatch):
    monkeypatch.setattr(sandbox, "_server", None)
    sandbox.prestart(str(tmp_path / "no-such.sock"))
    try:
        assert sandbox._server.proc is not None  # started its own server instead
        assert run_worker({"op": "render", "dir": str(letters), "seed": 0})["ok"]
    finally:
        sandbox._server.close()
