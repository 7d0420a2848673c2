"""Runs task code in a separate worker process with limits.

The worker gets a stripped environment (no API keys or secrets), a temporary working
directory, CPU-time, address-space, core-file and open-file limits, and a wall-clock
timeout.  Its output is treated as data: bounded in size and parsed as JSON.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

WORKER_TIMEOUT_S = 120.0
"""Wall-clock limit for one worker run, s."""

WORKER_CPU_S = 120
"""CPU-time limit of the worker, s."""

WORKER_ADDRESS_SPACE = 8 * 1024**3
"""Address-space limit of the worker, bytes."""

WORKER_MAX_OUTPUT = 16 * 1024**2
"""Largest worker output accepted, bytes."""

_KEEP_ENV = ("PATH", "HOME", "LANG", "LC_ALL", "MUJOCO_GL", "PYTHONPATH", "VIRTUAL_ENV", "LD_LIBRARY_PATH",
             "PYOPENGL_PLATFORM", "EGL_PLATFORM", "TMPDIR")


class WorkerError(RuntimeError):
    """The worker crashed, timed out or wrote something that is not a result."""


def _limits() -> None:  # pragma: no cover - runs in the child
    import resource

    resource.setrlimit(resource.RLIMIT_CPU, (WORKER_CPU_S, WORKER_CPU_S))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_AS, (WORKER_ADDRESS_SPACE, WORKER_ADDRESS_SPACE))
    resource.setrlimit(resource.RLIMIT_NOFILE, (256, 256))


def run_worker(request: dict, timeout: float = WORKER_TIMEOUT_S) -> dict:
    """Run one worker request and return its parsed result.

    Raises:
        WorkerError: timeout, crash, oversize or malformed output.
    """
    env = {k: os.environ[k] for k in _KEEP_ENV if k in os.environ}
    env.setdefault("MUJOCO_GL", "egl")
    env["PYTHONHASHSEED"] = "0"
    env["PYTHONDONTWRITEBYTECODE"] = "1"  # task files are rewritten in place; stale .pyc must never be used
    with tempfile.TemporaryDirectory(prefix="rpg-worker-") as cwd:
        try:
            proc = subprocess.run(
                [sys.executable, "-m", "rpg.validate.worker"],
                input=json.dumps(request).encode(), capture_output=True, timeout=timeout, cwd=cwd, env=env,
                preexec_fn=_limits,
            )
        except subprocess.TimeoutExpired:
            raise WorkerError(f"task code ran past the {timeout:.0f} s limit") from None
    out = proc.stdout[:WORKER_MAX_OUTPUT + 1]
    if len(out) > WORKER_MAX_OUTPUT:
        raise WorkerError("task code produced more output than allowed")
    try:
        doc = json.loads(out.decode("utf-8", "replace")) if out else None
    except json.JSONDecodeError:
        doc = None
    if not isinstance(doc, dict) or "ok" not in doc:
        tail = proc.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or [f"exit code {proc.returncode}"]
        raise WorkerError(f"task worker failed: {tail[0][:300]}")
    return doc
