"""The fork server: a worker process that imports the domain once and forks a fresh child
per request, so each task still runs in its own process without paying interpreter and
MuJoCo start-up each time.

Started only by :mod:`rpg.validate.sandbox`, with the same stripped environment as a
one-shot worker.  Protocol on stdin/stdout (or, for a clone of a template server, on its
Unix-socket connection): a line with the byte length, then that many bytes of JSON; the
request carries ``_timeout`` (s) and the task code's text.  The server itself runs inside
the namespaces of :mod:`rpg.validate.isolation` when they are available.  Each child: new
session, resource limits, the seccomp filter, the audit hook, a fresh temporary working
directory, stdout and stderr away from the protocol channel; it writes its JSON document to
a pipe.  The server enforces the wall-clock limit
(SIGKILL to the child's process group) and the output bound, and answers with a document
even when the child dies.
"""

from __future__ import annotations

import json
import os
import select
import shutil
import signal
import sys
import tempfile
import time

from rpg.validate.sandbox import WORKER_MAX_OUTPUT, apply_limits


def _read_child(fd: int, timeout: float) -> tuple[bytes, str | None]:
    """Everything the child writes to ``fd`` until EOF; (data, problem)."""
    chunks, size = [], 0
    deadline = time.monotonic() + timeout
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return b"", f"task code ran past the {timeout:.0f} s limit"
        ready, _, _ = select.select([fd], [], [], left)
        if not ready:
            continue
        chunk = os.read(fd, 1 << 16)
        if not chunk:
            return b"".join(chunks), None
        size += len(chunk)
        if size > WORKER_MAX_OUTPUT:
            return b"", "task code produced more output than allowed"
        chunks.append(chunk)


def _run_child(req: dict, cwd: str, wfd: int) -> None:  # pragma: no cover - runs in the forked child
    try:
        os.setsid()
        devnull = os.open(os.devnull, os.O_RDWR)
        os.dup2(devnull, 0)
        os.dup2(devnull, 1)
        err = os.open(os.path.join(cwd, ".stderr"), os.O_WRONLY | os.O_CREAT, 0o600)
        os.dup2(err, 2)
        os.chdir(cwd)
        apply_limits()
        from rpg.validate.guard import install
        from rpg.validate.isolation import install_seccomp
        from rpg.validate.worker import handle

        install_seccomp()
        install(cwd)

        data = handle(req).encode()
        view = memoryview(data)
        while view:
            n = os.write(wfd, view)
            view = view[n:]
    finally:
        os._exit(0)


def serve_one(req: dict) -> bytes:
    timeout = float(req.pop("_timeout", 120.0))
    cwd = tempfile.mkdtemp(prefix="rpg-worker-")
    rfd, wfd = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - child
        os.close(rfd)
        _run_child(req, cwd, wfd)
    os.close(wfd)
    try:
        data, problem = _read_child(rfd, timeout)
    finally:
        os.close(rfd)
    if problem:
        try:
            os.killpg(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    _, status = os.waitpid(pid, 0)
    stderr_tail = ""
    try:
        with open(os.path.join(cwd, ".stderr"), "rb") as fh:
            fh.seek(max(0, os.fstat(fh.fileno()).st_size - 2000))
            stderr_tail = fh.read(2000).decode("utf-8", "replace").strip().splitlines()[-1:]
            stderr_tail = stderr_tail[0] if stderr_tail else ""
    except OSError:
        pass
    shutil.rmtree(cwd, ignore_errors=True)
    if problem or not data:
        if not problem:
            sig = os.WTERMSIG(status) if os.WIFSIGNALED(status) else None
            problem = (f"task worker died ({signal.Signals(sig).name})" if sig else
                       f"task worker failed: {stderr_tail or 'exit code ' + str(os.WEXITSTATUS(status))}")
        return json.dumps({"ok": False, "kind": "runtime", "error": problem, "contained": True}).encode()
    return data


WARM_GL_ENV = "RPG_WARM_GL"
"""Set to ``0`` to keep OpenGL out of the fork server (each child then makes its own context)."""


def preload() -> None:
    """Import what every child needs, once: the domain, PIL's PNG codec and the OpenGL
    bindings of the configured backend; then, unless ``RPG_WARM_GL=0``, create the shared
    OpenGL context and compile its shaders (:func:`rpg.domain.render.warm_shared_context`)
    so that a child's two snapshots cost ~95 ms instead of ~250 ms.

    The server must stay single-threaded, since it forks: when the renderer started
    threads after all, the server re-executes itself without the warm context.
    """
    import importlib

    from PIL import Image, PngImagePlugin  # noqa: F401

    import rpg.oracle.planner  # noqa: F401 - environment variables on import, which a child may not)
    import rpg.oracle.solvable  # noqa: F401 - the solvable gate's environment and oracle (gymnasium sets
    import rpg.validate.worker  # noqa: F401
    from rpg.validate.isolation import seccomp_layer

    seccomp_layer()  # loads libseccomp now: a child cannot look for it once its limits are on

    backend = os.environ.get("MUJOCO_GL", "egl")
    if backend in ("egl", "osmesa"):
        try:
            importlib.import_module(f"mujoco.{backend}")
        except Exception:  # noqa: BLE001 - no OpenGL here: children skip snapshots as before
            return
    if os.environ.get(WARM_GL_ENV, "1") == "0":
        return
    from rpg.domain.render import shared_context_fork_safe, warm_shared_context

    if warm_shared_context() and not shared_context_fork_safe():
        os.execve(sys.executable, [sys.executable, "-m", "rpg.validate.forkserver", *sys.argv[1:]],
                  {**os.environ, WARM_GL_ENV: "0"})


def serve(inp, out) -> None:
    """Answer requests from ``inp`` on ``out`` (binary files) until ``inp`` ends."""
    while True:
        header = inp.readline()
        if not header:
            return
        req = json.loads(inp.read(int(header)))
        payload = serve_one(req)
        out.write(f"{len(payload)}\n".encode() + payload)
        out.flush()


def serve_clones(listen_fd: int) -> None:
    """Template mode: accept connections on the listening Unix socket ``listen_fd`` and
    fork, for each, a clone that serves that connection as :func:`serve` serves stdin.

    A clone inherits the preloaded modules and the warm OpenGL context, so N workers get N
    fork servers for the start-up cost of one.  A clone exits when its connection closes.
    """
    import socket

    listener = socket.socket(fileno=listen_fd)
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)  # clones that end are reaped by the kernel
    while True:
        conn, _ = listener.accept()
        pid = os.fork()
        if pid == 0:  # pragma: no cover - runs in the clone
            try:
                signal.signal(signal.SIGCHLD, signal.SIG_DFL)  # serve_one waits for its own children
                listener.close()
                stream = conn.makefile("rwb")
                serve(stream, stream)
            finally:
                os._exit(0)
        conn.close()


def main() -> None:
    preload()
    if sys.argv[1:2] == ["--listen-fd"]:
        serve_clones(int(sys.argv[2]))
    else:
        serve(sys.stdin.buffer, sys.stdout.buffer)


if __name__ == "__main__":
    main()
