"""OS isolation of the processes that run task code, from maintained tools.

Layers, outermost first (``rpg doctor`` prints which are active here):

1. **namespaces** (bubblewrap, ``bwrap``: Debian's ``bubblewrap`` package): the fork server
   (and a one-shot worker) starts inside new user, PID, network, IPC, UTS and mount
   namespaces.  Its file system is a read-only view of the interpreter, the installed
   packages and the system libraries (``/usr``), with a size-limited tmpfs ``/tmp`` as the
   only writable place; no ``/etc`` beyond the loader cache, no ``/home``, no ``/root``, no
   network, its own ``/proc`` (no other process is visible, so no ``/proc/<pid>/environ``,
   no signals or ptrace outside), and the whole namespace dies with the request's server
   and with ``rpg`` (``--die-with-parent``).  The server is isolated once and forks each
   request inside, so isolation costs one ``bwrap`` start per server.
2. **seccomp** (libseccomp through ``pyseccomp``), in each child that runs task code:
   no new processes (``fork``, ``vfork``, ``clone`` without ``CLONE_THREAD``, ``clone3``,
   ``execve``), no signals except to itself, no ptrace or cross-process memory access, no
   sockets, no ``mknod``/``mkfifo``, extended attributes, mounts, namespaces, keyrings,
   BPF, perf events, kernel modules, and no raising of resource limits.
3. **resource limits** (:func:`rpg.validate.sandbox.apply_limits`): CPU time, address
   space, file size, open files, processes, no core files; the wall-clock limit is the
   server's.
4. the Python **audit hook** (:mod:`rpg.validate.guard`) and the **restricted execution**
   of the text-gated code (:mod:`rpg.validate.restricted`).

Where the kernel or the machine lacks a layer (no ``bwrap``, user namespaces disabled, no
libseccomp), rpg says so once on stderr and in ``validation.log`` and runs with the layers
it has.  ``RPG_ISOLATION=0`` switches layers 1 and 2 off (for debugging only).
"""

from __future__ import annotations

import errno
import functools
import os
import shutil
import subprocess
import sys
from dataclasses import dataclass

TMPFS_BYTES = 256 * 1024**2
"""Size of the sandbox's writable tmpfs ``/tmp``, bytes."""

DENIED_SYSCALLS = (
    "fork", "vfork", "execve", "execveat", "ptrace", "process_vm_readv", "process_vm_writev", "kcmp",
    "pidfd_open", "pidfd_send_signal", "pidfd_getfd", "socket", "socketpair", "mknod", "mknodat",
    "setxattr", "lsetxattr", "fsetxattr", "removexattr", "lremovexattr", "fremovexattr",
    "mount", "umount2", "pivot_root", "chroot", "unshare", "setns", "keyctl", "add_key", "request_key",
    "bpf", "perf_event_open", "userfaultfd", "init_module", "finit_module", "delete_module", "kexec_load",
    "kexec_file_load", "reboot", "swapon", "swapoff", "setrlimit", "prlimit64", "acct", "quotactl",
    "setuid", "setgid", "setreuid", "setregid", "setresuid", "setresgid", "setgroups", "setsid", "setpgid",
    "ioperm", "iopl", "open_by_handle_at", "name_to_handle_at", "fanotify_init", "move_mount", "fsopen",
    "fsmount", "open_tree",
)
"""System calls a task-code process gets EPERM for (with new processes and foreign signals)."""


@dataclass(frozen=True)
class Layer:
    name: str
    active: bool
    detail: str


def enabled() -> bool:
    return os.environ.get("RPG_ISOLATION", "1") != "0"


def _python_roots() -> list[str]:
    """Directories the interpreter and the installed packages (and rpg itself) live in."""
    import rpg

    roots = {os.path.realpath(sys.base_prefix), os.path.realpath(sys.prefix),
             os.path.realpath(os.path.dirname(os.path.dirname(rpg.__file__)))}
    for p in sys.path:
        if p and os.path.isdir(p):
            roots.add(os.path.realpath(p))
    # keep the outermost directories only
    out: list[str] = []
    for r in sorted(roots, key=len):
        if r == "/" or r.startswith("/usr/"):
            continue
        if not any(r == o or r.startswith(o + os.sep) for o in out):
            out.append(r)
    return sorted(out)


def bwrap_argv(env: dict[str, str], writable: str | None = None) -> list[str]:
    """The bubblewrap prefix that isolates a command (see the module docstring).

    Args:
        env: the complete environment of the sandboxed command.
        writable: a host directory bound read-write at the same path (the one-shot worker's
            work directory); the fork server needs none.
    """
    argv = [shutil.which("bwrap") or "bwrap", "--unshare-user", "--unshare-pid", "--unshare-net", "--unshare-ipc",
            "--unshare-uts", "--unshare-cgroup-try", "--die-with-parent", "--new-session", "--cap-drop", "ALL",
            "--ro-bind", "/usr", "/usr"]
    for name in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):
        path = f"/{name}"
        if os.path.islink(path):
            argv += ["--symlink", os.readlink(path), path]
        elif os.path.isdir(path):
            argv += ["--ro-bind", path, path]
    argv += ["--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache"]
    # mounts apply in order: the tmpfs first, so an interpreter or checkout under /tmp stays visible
    argv += ["--proc", "/proc", "--dev", "/dev", "--size", str(TMPFS_BYTES), "--tmpfs", "/tmp"]
    for root in _python_roots():
        argv += ["--ro-bind", root, root]
    if writable:
        argv += ["--bind", writable, writable]
    argv += ["--chdir", writable or "/tmp", "--clearenv"]
    for k, v in sorted({**env, "RPG_SANDBOXED": "1", "TMPDIR": "/tmp", "HOME": "/tmp"}.items()):
        argv += ["--setenv", k, v]
    return argv + ["--"]


@functools.lru_cache(maxsize=1)
def namespaces_layer() -> Layer:
    """Whether bubblewrap can isolate a process here (probed once per process)."""
    if not enabled():
        return Layer("namespaces", False, "switched off (RPG_ISOLATION=0)")
    if not shutil.which("bwrap"):
        return Layer("namespaces", False, "bubblewrap (bwrap) is not installed; install Debian's 'bubblewrap' package")
    try:
        proc = subprocess.run([*bwrap_argv({"PATH": "/usr/bin"}), "/usr/bin/true"],
                              capture_output=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired) as exc:
        return Layer("namespaces", False, f"bwrap failed: {exc}")
    if proc.returncode != 0:
        why = proc.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or [f"exit {proc.returncode}"]
        return Layer("namespaces", False, f"bwrap cannot create namespaces here: {why[0][:200]}")
    return Layer("namespaces", True, f"bubblewrap {shutil.which('bwrap')}: user, pid, net, ipc, uts, mount")


@functools.lru_cache(maxsize=1)
def seccomp_layer() -> Layer:
    if not enabled():
        return Layer("seccomp", False, "switched off (RPG_ISOLATION=0)")
    try:
        import pyseccomp

        pyseccomp.SyscallFilter(defaction=pyseccomp.ALLOW)
    except Exception as exc:  # noqa: BLE001 - libseccomp missing or unusable: report the layer as absent
        return Layer("seccomp", False, f"libseccomp is not usable: {str(exc)[:200]}")
    return Layer("seccomp", True, f"libseccomp via pyseccomp: {len(DENIED_SYSCALLS)} system calls denied, no new processes")


def layers() -> list[Layer]:
    """Every isolation layer and whether it is active here."""
    return [
        Layer("restricted-execution", True, "text-gate allowlist, RestrictedPython guards"),
        Layer("audit-hook", True, "no writes outside the work dir, no subprocesses, sockets or signals"),
        Layer("resource-limits", True, "CPU, address space, file size, open files, processes, no core"),
        seccomp_layer(),
        namespaces_layer(),
    ]


_warned = False


def missing_layers_note() -> str | None:
    """One line naming the isolation layers that are not active here, or None."""
    missing = [f"{layer.name} ({layer.detail})" for layer in layers() if not layer.active]
    return f"sandbox: running without {'; '.join(missing)}" if missing else None


def warn_once() -> str | None:
    """Print :func:`missing_layers_note` on stderr the first time it is asked for; return it."""
    global _warned
    note = missing_layers_note()
    if note and not _warned:
        _warned = True
        print(f"warning: {note}", file=sys.stderr)
    return note


def wrap(argv: list[str], env: dict[str, str], writable: str | None = None) -> list[str]:
    """``argv`` run inside the namespaces when that layer is active, else ``argv`` itself."""
    return [*bwrap_argv(env, writable), *argv] if namespaces_layer().active else argv


def die_with_parent() -> None:  # pragma: no cover - runs in a child before exec
    """Ask the kernel to SIGKILL this process when its parent dies (``PR_SET_PDEATHSIG``),
    so that kill -9 of ``rpg`` takes its servers and workers with it."""
    import ctypes
    import signal

    try:
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)  # PR_SET_PDEATHSIG = 1
    except (OSError, AttributeError):
        pass


def install_seccomp() -> bool:  # pragma: no cover - runs in the child that runs task code
    """Load the seccomp filter into this process (irrevocable); False when the layer is
    unavailable here (:func:`seccomp_layer`).

    Raises:
        RuntimeError: the layer is available but the filter could not be loaded (the
            request then fails: a sandbox layer never fails open silently).
    """
    if not seccomp_layer().active:
        return False
    try:
        _load_filter()
    except Exception as exc:  # noqa: BLE001 - fail closed with the reason
        raise RuntimeError(f"sandbox: the seccomp filter could not be loaded: {exc}") from None
    return True


def _load_filter() -> None:  # pragma: no cover - runs in the child that runs task code
    import pyseccomp as sc

    f = sc.SyscallFilter(defaction=sc.ALLOW)
    deny = sc.ERRNO(errno.EPERM)
    for name in DENIED_SYSCALLS:
        try:
            f.add_rule(deny, name)
        except (OSError, ValueError, RuntimeError):
            continue  # not a system call on this architecture
    f.add_rule(deny, "clone", sc.Arg(0, sc.MASKED_EQ, 0x00010000, 0))  # clone without CLONE_THREAD: a new process
    f.add_rule(sc.ERRNO(errno.ENOSYS), "clone3")  # arguments in memory: libc falls back to clone
    me = os.getpid()
    for name in ("kill", "tgkill"):
        f.add_rule(deny, name, sc.Arg(0, sc.NE, me))
    f.add_rule(deny, "tkill")
    f.load()
