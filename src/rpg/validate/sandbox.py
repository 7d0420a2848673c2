"""Runs task code in a separate worker process with limits, isolated from the machine.

The worker gets a stripped environment (no API keys or secrets), a temporary working
directory, CPU-time, address-space, file-size, core-file, process and open-file limits, and
a wall-clock timeout; it runs inside the namespaces and under the seccomp filter of
:mod:`rpg.validate.isolation`.  Its output is treated as data: bounded in size and parsed as
JSON.
"""

from __future__ import annotations

import atexit
import json
import os
import select
import shutil
import socket
import subprocess
import sys
import tempfile
import threading

from rpg.errors import TaskInvalid
from rpg.validate.isolation import die_with_parent, wrap

WORKER_TIMEOUT_S = 120.0
"""Wall-clock limit for one worker run, s."""

WORKER_CPU_S = 120
"""CPU-time limit of the worker, s."""

WORKER_ADDRESS_SPACE = 8 * 1024**3
"""Address-space limit of the worker, bytes."""

WORKER_MAX_OUTPUT = 16 * 1024**2
"""Largest worker output accepted, bytes."""

WORKER_FILE_SIZE = 64 * 1024**2
"""Largest file a worker may write (RLIMIT_FSIZE), bytes: bounds its stderr file too."""

WORKER_PROCESSES = 64
"""RLIMIT_NPROC of a worker inside its user namespace (threads count; new processes are
refused by seccomp anyway)."""

_KEEP_ENV = ("PATH", "HOME", "LANG", "LC_ALL", "MUJOCO_GL", "PYTHONPATH", "VIRTUAL_ENV", "LD_LIBRARY_PATH",
             "PYOPENGL_PLATFORM", "EGL_PLATFORM", "TMPDIR", "LP_NUM_THREADS")


FORK_SAFE_GL_ENV = {"LP_NUM_THREADS": "0", "MESA_SHADER_CACHE_DISABLE": "true"}
"""Environment of the fork server: Mesa llvmpipe renders in the calling thread and keeps
no shader-cache thread, so the server stays single-threaded and can fork with a warm
OpenGL context (see :func:`rpg.domain.render.warm_shared_context`)."""


class WorkerError(TaskInvalid, RuntimeError):
    """The worker crashed, timed out or wrote something that is not a result."""


def apply_limits() -> None:  # pragma: no cover - runs in the child
    """Resource limits of a worker process: CPU seconds, address space, file size, no core
    files, open files and, inside a user namespace, processes."""
    import resource

    resource.setrlimit(resource.RLIMIT_CPU, (WORKER_CPU_S, WORKER_CPU_S))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_AS, (WORKER_ADDRESS_SPACE, WORKER_ADDRESS_SPACE))
    resource.setrlimit(resource.RLIMIT_NOFILE, (256, 256))
    resource.setrlimit(resource.RLIMIT_FSIZE, (WORKER_FILE_SIZE, WORKER_FILE_SIZE))
    if os.environ.get("RPG_SANDBOXED") == "1":  # inside a user namespace: counted per namespace
        resource.setrlimit(resource.RLIMIT_NPROC, (WORKER_PROCESSES, WORKER_PROCESSES))


def _worker_env() -> dict[str, str]:
    env = {k: os.environ[k] for k in _KEEP_ENV if k in os.environ}
    env.setdefault("MUJOCO_GL", "egl")
    env["PYTHONHASHSEED"] = "0"
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # task files are rewritten in place; stale .pyc must never be used
    env["OPENBLAS_NUM_THREADS"] = "1"  # no BLAS threads in a process that forks
    return env


def _parse(out: bytes, stderr: bytes = b"", returncode: int | None = None) -> dict:
    if len(out) > WORKER_MAX_OUTPUT:
        raise WorkerError("task code produced more output than allowed")
    try:
        doc = json.loads(out.decode("utf-8", "replace")) if out else None
    except json.JSONDecodeError:
        doc = None
    if not isinstance(doc, dict) or "ok" not in doc:
        tail = stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or [f"exit code {returncode}"]
        raise WorkerError(f"task worker failed: {tail[0][:300]}")
    if doc.get("contained") and not doc["ok"]:
        raise WorkerError(doc["error"])
    return doc


class _ForkServer:
    """A long-lived :mod:`rpg.validate.forkserver` this process talks to: its own child
    (over stdin/stdout), or, given a template's ``address``, a clone of that template (over
    a Unix-socket connection; see :class:`ForkServerTemplate`).

    Raises:
        OSError: the template cannot be reached.
    """

    def __init__(self, address: str | None = None):
        self.owner = os.getpid()
        self.proc = self.sock = self.cwd = None
        if address:
            self.sock = socket.socket(socket.AF_UNIX)
            try:
                self.sock.connect(address)
            except OSError:
                self.sock.close()
                raise
            self.rfile = self.wfile = self.sock.makefile("rwb")
            self.ready = self.sock
        else:
            self.cwd = tempfile.mkdtemp(prefix="rpg-forkserver-")
            env = _server_env()
            self.proc = subprocess.Popen(
                wrap([sys.executable, "-m", "rpg.validate.forkserver"], env), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                stderr=subprocess.DEVNULL, cwd=self.cwd, env=env, preexec_fn=die_with_parent)
            self.wfile, self.rfile = self.proc.stdin, self.proc.stdout
            self.ready = self.rfile

    def alive(self) -> bool:
        if self.owner != os.getpid():
            return False
        return self.proc.poll() is None if self.proc else self.sock.fileno() != -1

    def run(self, request: dict, timeout: float) -> dict:
        payload = json.dumps({**_with_sources(request), "_timeout": timeout}).encode()
        try:
            self.wfile.write(f"{len(payload)}\n".encode() + payload)
            self.wfile.flush()
            ready, _, _ = select.select([self.ready], [], [], timeout + SERVER_GRACE_S)
            if not ready:
                raise OSError("the fork server did not answer")
            n = int(self.rfile.readline())
            return _parse(self.rfile.read(n))
        except (OSError, ValueError) as exc:
            self.close()
            raise _ServerDown(str(exc)) from None

    def close(self) -> None:
        if self.sock is not None:
            self.rfile.close()
            self.sock.close()
        else:
            _stop(self.proc, self.cwd)


class ForkServerTemplate:
    """A fork server that only clones itself: each connection to :attr:`address` gets its
    own fork server, forked from this one after its imports and OpenGL warm-up.

    A process that is about to fork N workers starts one template and has each worker call
    :func:`prestart` with its address: the N workers then share one start-up (~0.7 s of
    imports and shader compilation) instead of paying it N times on the same cores.  Workers
    can connect at once; the template accepts when it is ready.  Use as a context manager.

    Raises:
        OSError: no Unix socket can be made here (the caller then starts servers as usual).
    """

    def __init__(self):
        self.dir = tempfile.mkdtemp(prefix="rpg-forkserver-")  # mode 0700: only this user can connect
        self.address = os.path.join(self.dir, "template.sock")
        listener = socket.socket(socket.AF_UNIX)
        try:
            listener.bind(self.address)
            listener.listen(64)
            env = _server_env()
            self.proc = subprocess.Popen(
                wrap([sys.executable, "-m", "rpg.validate.forkserver", "--listen-fd", str(listener.fileno())], env),
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=self.dir,
                env=env, pass_fds=(listener.fileno(),), preexec_fn=die_with_parent)
        except (OSError, ValueError) as exc:
            shutil.rmtree(self.dir, ignore_errors=True)
            raise OSError(f"cannot start a fork-server template: {exc}") from None
        finally:
            listener.close()

    def close(self) -> None:
        """Stop the template; clones end when their workers close their connections."""
        _stop(self.proc, self.dir)

    def __enter__(self) -> ForkServerTemplate:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _server_env() -> dict[str, str]:
    return {**_worker_env(), **FORK_SAFE_GL_ENV}


def _stop(proc: subprocess.Popen, directory: str) -> None:
    """Kill a server process if it still runs and remove its working directory."""
    if proc.poll() is None:
        proc.kill()
        proc.wait()
    shutil.rmtree(directory, ignore_errors=True)


class _ServerDown(RuntimeError):
    pass


SERVER_GRACE_S = 30.0
"""Extra wait for the fork server beyond a request's own timeout, s."""

_server: _ForkServer | None = None
_server_lock = threading.Lock()


def _close_server() -> None:
    if _server is not None and _server.owner == os.getpid():
        _server.close()


atexit.register(_close_server)


def worker_timeout() -> float:
    """The wall-clock limit of one worker run, s: ``RPG_WORKER_TIMEOUT_S`` or :data:`WORKER_TIMEOUT_S`."""
    try:
        return float(os.environ.get("RPG_WORKER_TIMEOUT_S", WORKER_TIMEOUT_S))
    except ValueError:
        return WORKER_TIMEOUT_S


def forkserver_enabled() -> bool:
    """Whether task code runs in children of a fork server (set ``RPG_FORKSERVER=0`` for a
    whole interpreter per request)."""
    return os.environ.get("RPG_FORKSERVER", "1") != "0" and hasattr(os, "fork")


STALE_SERVER_DIR_S = 6 * 3600.0
"""Age after which a fork server's leftover directory (its rpg killed) is removed, s."""

_swept = False


def _remove_stale_server_dirs() -> None:
    """Once per process: delete this user's ``rpg-forkserver-*`` / ``rpg-worker-*`` temporary
    directories older than :data:`STALE_SERVER_DIR_S` (left behind by a killed ``rpg``)."""
    global _swept
    if _swept:
        return
    _swept = True
    import glob
    import time

    now = time.time()
    for d in glob.glob(os.path.join(tempfile.gettempdir(), "rpg-forkserver-*")) + \
            glob.glob(os.path.join(tempfile.gettempdir(), "rpg-worker-*")):
        try:
            st = os.lstat(d)
            if st.st_uid == os.getuid() and os.path.isdir(d) and not os.path.islink(d) and now - st.st_mtime > STALE_SERVER_DIR_S:
                shutil.rmtree(d, ignore_errors=True)
        except OSError:
            continue


def prestart(template: str | None = None) -> None:
    """Start the fork server now (without waiting for it), so that its imports overlap the
    caller's own start-up; :func:`run_worker` uses it when it is ready.

    Args:
        template: address of a :class:`ForkServerTemplate` to clone instead of starting a
            new server (when it cannot be reached, a new server is started).
    """
    global _server
    if forkserver_enabled():
        _remove_stale_server_dirs()
        with _server_lock:
            if _server is None or not _server.alive():
                try:
                    _server = _ForkServer(template)
                except OSError:
                    _server = _ForkServer()


def run_worker(request: dict, timeout: float | None = None) -> dict:
    """Run one worker request in a fresh, limited, isolated child process and return its parsed result.

    ``request`` names the task code by ``sources`` (file name -> text) or by ``dir`` (an
    artifact directory, read once here with :func:`rpg.artifact.task_sources`).

    Children are forked from a fork server that has imported the domain once (set
    ``RPG_FORKSERVER=0`` to start a whole interpreter per request instead).

    Raises:
        WorkerError: timeout, crash, oversize or malformed output.
        ArtifactError: ``dir`` holds no readable task code.
    """
    global _server
    timeout = worker_timeout() if timeout is None else timeout
    if forkserver_enabled():
        with _server_lock:
            for _ in range(2):
                if _server is None or not _server.alive():
                    _server = _ForkServer()
                try:
                    return _server.run(request, timeout)
                except _ServerDown:
                    _server = None
    return _run_once(request, timeout)


def _with_sources(request: dict) -> dict:
    """``request`` with an artifact ``dir`` replaced by its code's text, read once here: the
    worker gates and runs exactly this text."""
    if "dir" not in request:
        return request
    from rpg.artifact import task_sources

    return {k: v for k, v in request.items() if k != "dir"} | {"sources": task_sources(request["dir"])}


def _run_once(request: dict, timeout: float) -> dict:
    """One whole interpreter for one request; its output goes to files (bounded by
    RLIMIT_FSIZE) of which at most :data:`WORKER_MAX_OUTPUT` bytes are read."""
    with tempfile.TemporaryDirectory(prefix="rpg-worker-") as cwd:
        env = _worker_env()
        out_path, err_path = os.path.join(cwd, ".stdout"), os.path.join(cwd, ".stderr")
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            try:
                proc = subprocess.run(
                    wrap([sys.executable, "-m", "rpg.validate.worker"], env, writable=cwd),
                    input=json.dumps(_with_sources(request)).encode(), stdout=out, stderr=err, timeout=timeout, cwd=cwd, env=env,
                    preexec_fn=_one_shot_child, start_new_session=True,
                )
            except subprocess.TimeoutExpired:
                raise WorkerError(f"task code ran past the {timeout:.0f} s limit") from None
        with open(out_path, "rb") as fh:
            stdout = fh.read(WORKER_MAX_OUTPUT + 1)
        with open(err_path, "rb") as fh:
            fh.seek(max(0, os.path.getsize(err_path) - 4096))
            stderr = fh.read()
    return _parse(stdout, stderr, proc.returncode)


def _one_shot_child() -> None:  # pragma: no cover - runs in the child (bwrap or the worker)
    die_with_parent()
