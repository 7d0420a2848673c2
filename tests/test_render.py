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
    pid = server.proc.pid
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
        doc = _ask(proc, {"op": "render", "dir": str(letters), "seed": 0})
        assert doc["ok"], doc
        _image(doc, "goal")
        environ = open(f"/proc/{proc.pid}/environ", "rb").read().split(b"\0")
        assert b"RPG_WARM_GL=0" in environ, "the server should have re-executed without the warm context"
        time.sleep(0.1)
        assert _threads(proc.pid) == 1
    finally:
        proc.kill()
        proc.wait()
