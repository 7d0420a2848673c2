"""Runs task code in a fresh, limited, isolated process per request, and reads back data.

Each request has its own child (:mod:`rpg.validate.child`), started for it or, with
:func:`prepare`, started ahead so that its start-up overlaps the caller's work: a stripped environment (no
API keys or secrets), its own temporary working directory, CPU-time, address-space,
file-size, core-file, process and open-file limits, a wall-clock timeout, and the
namespaces and seccomp filter of :mod:`rpg.validate.isolation`.  No process serves two
requests, so no child can see, answer for or weaken another request's child.  Its output
is read from a file bounded by RLIMIT_FSIZE, at most :data:`WORKER_MAX_OUTPUT` bytes, and
parsed as JSON; the caller checks it against a schema (:mod:`rpg.validate.data`).
"""

from __future__ import annotations

import atexit
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

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

_KEEP_ENV = ("PATH", "HOME", "LANG", "LC_ALL", "PYTHONPATH", "VIRTUAL_ENV", "LD_LIBRARY_PATH", "TMPDIR")


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
    env["PYTHONHASHSEED"] = "0"
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # task files are rewritten in place; stale .pyc must never be used
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env[var] = "1"  # no threads: the seccomp allowlist has no clone
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
    return doc


def worker_timeout() -> float:
    """The wall-clock limit of one sandboxed run, s: ``RPG_WORKER_TIMEOUT_S`` or :data:`WORKER_TIMEOUT_S`."""
    try:
        return float(os.environ.get("RPG_WORKER_TIMEOUT_S", WORKER_TIMEOUT_S))
    except ValueError:
        return WORKER_TIMEOUT_S


class _Child:
    """A started child of :mod:`rpg.validate.child`, in its own temporary working directory,
    waiting for its one request on stdin (it reads the request before it applies its limits
    and filters, so nothing of the task runs before then)."""

    def __init__(self):
        self._owner = os.getpid()  # a forked copy of this object never removes the directory
        self._dir = cwd = tempfile.mkdtemp(prefix="rpg-worker-")
        env = _worker_env()
        self.out_path, self.err_path = os.path.join(cwd, ".stdout"), os.path.join(cwd, ".stderr")
        try:
            with open(self.out_path, "wb") as out, open(self.err_path, "wb") as err:
                self.proc = subprocess.Popen(
                    wrap([sys.executable, "-I", "-m", "rpg.validate.child"], env, writable=cwd),
                    stdin=subprocess.PIPE, stdout=out, stderr=err, cwd=cwd, env=env,
                    preexec_fn=die_with_parent, start_new_session=True)
        except OSError as exc:
            self.cleanup()
            raise WorkerError(f"cannot start the sandboxed child: {exc}") from None

    def send(self, payload: bytes) -> None:
        """Write the request and close stdin (the child starts on end of file)."""
        try:
            self.proc.stdin.write(payload)
            self.proc.stdin.close()
        except OSError:  # the child died before reading: its exit code and stderr say why
            pass

    def discard(self) -> None:
        """Kill the child (if it still runs) and remove its directory."""
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait()
        if self.proc.stdin and not self.proc.stdin.closed:
            self.proc.stdin.close()
        self.cleanup()

    def cleanup(self) -> None:
        """Remove the child's directory (only in the process that made it)."""
        if os.getpid() == self._owner:
            shutil.rmtree(self._dir, ignore_errors=True)


_spare: _Child | None = None
_spare_lock = threading.Lock()


def prepare() -> None:
    """Start the next request's child now, so that its start-up (the interpreter, its
    imports, the namespaces) overlaps the caller's own work; :class:`ChildRun` uses it for
    its request.  Still one child per request: a prepared child serves exactly one.  An
    unused one is killed at exit.  A child that cannot start is left for the request to
    report."""
    global _spare
    with _spare_lock:
        if _spare is not None and _spare.proc.poll() is None:
            return
        try:
            _spare = _Child()
        except WorkerError:
            _spare = None


def _take() -> _Child:
    """The prepared child if it still waits, else a new one."""
    global _spare
    with _spare_lock:
        child, _spare = _spare, None
    if child is not None and child.proc.poll() is None:
        return child
    if child is not None:
        child.discard()
    return _Child()


def _forget_spare_after_fork() -> None:
    """In a forked process: the parent's prepared child is not ours to use, and our copy of its
    request pipe would keep it from ever seeing the end of its request."""
    global _spare, _spare_lock
    child, _spare, _spare_lock = _spare, None, threading.Lock()
    if child is not None and child.proc.stdin is not None:
        child.proc.stdin.close()


os.register_at_fork(after_in_child=_forget_spare_after_fork)


@atexit.register
def _discard_spare() -> None:
    global _spare
    with _spare_lock:
        child, _spare = _spare, None
    if child is not None:
        child.discard()


class ChildRun:
    """One request's child, started and not yet waited for (so the caller can work while it
    runs).  Use :meth:`wait` exactly once.  The child is the one :func:`prepare` started, if
    it still waits, or a new one.

    Raises:
        WorkerError: the child could not be started.
    """

    def __init__(self, request: dict, timeout: float | None = None):
        self.timeout = worker_timeout() if timeout is None else timeout
        payload = json.dumps(request).encode()
        self._child = _take()
        self.proc = self._child.proc
        self.started = time.monotonic()
        self._child.send(payload)

    def wait(self) -> dict:
        """The child's parsed JSON document.

        Raises:
            WorkerError: timeout (the child is killed), crash, oversize or malformed output.
        """
        try:
            try:
                self.proc.wait(timeout=max(0.0, self.timeout - (time.monotonic() - self.started)))
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
                raise WorkerError(f"task code ran past the {self.timeout:.0f} s limit") from None
            with open(self._child.out_path, "rb") as fh:
                stdout = fh.read(WORKER_MAX_OUTPUT + 1)
            with open(self._child.err_path, "rb") as fh:
                fh.seek(max(0, os.path.getsize(self._child.err_path) - 4096))
                stderr = fh.read()
            return _parse(stdout, stderr, self.proc.returncode)
        finally:
            self._child.cleanup()


def run_child(request: dict, timeout: float | None = None) -> dict:
    """Run one request in a fresh, limited, isolated child process and return its parsed
    JSON document (see :mod:`rpg.validate.child`; the caller schema-checks it).

    Raises:
        WorkerError: timeout, crash, oversize or malformed output.
    """
    return ChildRun(request, timeout).wait()
