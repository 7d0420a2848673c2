"""A Python audit hook for worker processes that run task code.

Installed (irrevocably) in each worker child before task code is imported.  It refuses:
file writes, renames and deletions outside the worker's temporary directory; sockets;
subprocesses, ``os.system``, ``exec*``/``spawn*``, ``fork``; signals to other processes;
changes to the environment.  It is the innermost of the sandbox's layers and sees only
Python-level calls; native calls are held by the seccomp filter and the namespaces of
:mod:`rpg.validate.isolation` (the text gate and restricted execution come first).
"""

from __future__ import annotations

import os
import sys

WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC

BLOCKED_EVENTS = frozenset({
    "subprocess.Popen", "os.system", "os.fork", "os.forkpty", "os.kill", "os.killpg", "pty.spawn",
    "os.putenv", "os.unsetenv", "os.startfile", "os.setuid", "os.setgid", "webbrowser.open",
})
"""Audit events refused outright."""

PATH_EVENTS = frozenset({
    "os.remove", "os.unlink", "os.rmdir", "os.mkdir", "os.rename", "os.replace", "os.symlink", "os.link",
    "os.truncate", "os.chmod", "os.chown", "os.utime", "shutil.rmtree", "shutil.move", "shutil.copyfile",
})
"""Audit events allowed only on paths inside the sandbox directory."""


class SandboxViolation(PermissionError):
    """Task code tried something the sandbox refuses."""


def _inside(path, root: str) -> bool:
    if isinstance(path, int):
        return True  # an already-open descriptor
    try:
        p = os.path.realpath(os.fsdecode(path))
    except (TypeError, ValueError):
        return False
    return p == root or p.startswith(root + os.sep)


def install(root: str) -> None:
    """Install the hook; writes are allowed only under ``root`` (the worker's temporary dir)."""
    root = os.path.realpath(root)

    def hook(event: str, args: tuple) -> None:
        if event == "open":
            path, mode, flags = (tuple(args) + (None, None, 0))[:3]
            writing = (isinstance(mode, str) and any(c in mode for c in "wax+")) or bool((flags or 0) & WRITE_FLAGS)
            if writing and path is not None and not _inside(path, root):
                raise SandboxViolation(f"sandbox: writing {path!r} outside the worker directory is not allowed")
        elif event in BLOCKED_EVENTS or event.startswith(("socket.", "os.exec", "os.spawn", "os.posix_spawn")):
            raise SandboxViolation(f"sandbox: {event} is not allowed in task code")
        elif event in PATH_EVENTS:
            for a in args[:2]:
                if isinstance(a, str | bytes | os.PathLike) and not _inside(a, root):
                    raise SandboxViolation(f"sandbox: {event} on {a!r} outside the worker directory is not allowed")

    sys.addaudithook(hook)
