"""OS isolation of the processes that run task code, from maintained tools.

Layers, outermost first (``rpg doctor`` prints which are active here):

1. **namespaces** (bubblewrap, ``bwrap``: Debian's ``bubblewrap`` package): each child
   that runs task code starts inside new user, PID, network, IPC, UTS and mount
   namespaces.  Its file system is a read-only view of the interpreter, the installed
   packages and the system libraries (``/usr``), with a size-limited tmpfs ``/tmp`` as the
   only writable place; no ``/etc`` beyond the loader cache, no ``/home``, no ``/root``, no
   network, its own ``/proc`` (no other process is visible, so no ``/proc/<pid>/environ``,
   no signals or ptrace outside), and the whole namespace dies with ``rpg``
   (``--die-with-parent``).  Each request is a fresh ``bwrap`` and a fresh child: no
   process outlives its request or serves another.
2. **seccomp** (libseccomp through ``pyseccomp``), in each child that runs task code: an
   allowlist (:data:`ALLOWED_SYSCALLS`), every other system call denied: no new processes
   or threads, no sockets or io_uring, no signals except to itself, no ptrace, no opening
   a file for writing, no changes to resource limits.
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

ALLOWED_SYSCALLS = (
    "read", "readv", "pread64", "write", "writev", "close", "fstat", "newfstatat", "statx", "stat", "lstat",
    "lseek", "fcntl", "dup", "getdents64", "getcwd", "readlink", "readlinkat", "access", "faccessat",
    "faccessat2", "mmap", "munmap", "mprotect", "mremap", "madvise", "brk", "futex", "rt_sigaction",
    "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "clock_gettime", "clock_getres",
    "gettimeofday", "nanosleep", "clock_nanosleep", "sched_yield", "sched_getaffinity", "getpid", "gettid",
    "getuid", "geteuid", "getgid", "getegid", "uname", "sysinfo", "rseq", "set_robust_list", "exit", "exit_group",
)
"""System calls the child that runs task code may make once its filter is loaded; every
other one fails with EPERM (default deny: new processes and threads, io_uring, sockets,
queued and foreign signals, ptrace, namespaces, BPF...).  Its imports are done before the
filter is loaded; what remains is memory, reading what it can see, writing to the file
descriptors it already holds, and the clock.  No ``getrandom``: task code draws only from
the seeded generator it is given (an unseeded one fails), so the same seed gives the same
data in validation and in every episode.  Further allowed with argument checks:
``openat``/``open`` only without write flags, ``ioctl`` only ``TCGETS`` (``isatty``),
``prlimit64`` only to read a limit, ``kill``/``tgkill`` only to this process (``abort``)."""

OPEN_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND
"""Flags an ``open``/``openat`` of the filtered child may not carry (``O_TMPFILE`` needs a
write mode, so it is covered)."""

TCGETS = 0x5401
"""The ``ioctl`` request behind ``isatty`` (Linux)."""


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
        writable: a host directory bound read-write at the same path (the child's work
            directory).
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
    return Layer("seccomp", True, f"libseccomp via pyseccomp: an allowlist of {len(ALLOWED_SYSCALLS) + 6} system calls, "
                                  "default deny (no processes, threads, sockets, io_uring or signals to others)")


# -- Landlock (the kernel's unprivileged access control, Linux >= 5.13) -------------------
_LANDLOCK_CREATE_RULESET, _LANDLOCK_ADD_RULE, _LANDLOCK_RESTRICT_SELF = 444, 445, 446
_LANDLOCK_RULE_PATH_BENEATH = 1
_FS_EXECUTE, _FS_WRITE_FILE, _FS_READ_FILE, _FS_READ_DIR = 1, 2, 4, 8
_FS_RIGHTS_BY_ABI = {1: (1 << 13) - 1, 2: (1 << 14) - 1, 3: (1 << 15) - 1, 5: (1 << 16) - 1}
"""Every file-system right Landlock knows at each ABI version (bits 0-12 at ABI 1; REFER,
TRUNCATE, IOCTL_DEV added at 2, 3, 5): all are handled, so all are denied but those granted."""


def _landlock_abi() -> int:
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    abi = libc.syscall(_LANDLOCK_CREATE_RULESET, None, ctypes.c_size_t(0), ctypes.c_uint32(1))  # ..._VERSION
    return int(abi) if abi > 0 else 0


@functools.lru_cache(maxsize=1)
def landlock_layer() -> Layer:
    """Whether the kernel has Landlock (probed once per process)."""
    if not enabled():
        return Layer("landlock", False, "switched off (RPG_ISOLATION=0)")
    try:
        abi = _landlock_abi()
    except (OSError, AttributeError) as exc:
        return Layer("landlock", False, f"cannot probe Landlock: {exc}")
    if abi < 1:
        return Layer("landlock", False, "the kernel has no Landlock (Linux >= 5.13 with landlock in its LSM list)")
    extra = "; no TCP" if abi >= 4 else ""
    extra += "; no signals or abstract sockets outside" if abi >= 6 else ""
    return Layer("landlock", True, f"ABI {abi}: read-only view of the interpreter and libraries, no file opened for "
                                   f"writing but /dev/null{extra}")


def readable_roots() -> list[str]:
    """What the filtered child may read: the interpreter, the installed packages, the
    system libraries and the loader cache."""
    roots = set(_python_roots()) | {"/usr", "/etc/ld.so.cache"}
    for name in ("lib", "lib64", "lib32", "libx32", "bin"):
        if os.path.isdir(f"/{name}"):
            roots.add(os.path.realpath(f"/{name}"))
    return sorted(r for r in roots if os.path.exists(r))


def install_landlock() -> bool:  # pragma: no cover - runs in the child that runs task code
    """Confine this process with Landlock (irrevocable): read and execute only beneath
    :func:`readable_roots`, write only ``/dev/null``; no TCP (ABI 4), no signals or abstract
    Unix sockets beyond its own domain (ABI 6).  False when the kernel lacks Landlock.

    Raises:
        RuntimeError: Landlock is there but the rules could not be applied (fail closed).
    """
    import ctypes

    if not landlock_layer().active:
        return False
    abi = _landlock_abi()
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    fs = _FS_RIGHTS_BY_ABI[max(a for a in _FS_RIGHTS_BY_ABI if a <= abi)]
    attr = (ctypes.c_uint64 * 3)(fs, 3 if abi >= 4 else 0, 3 if abi >= 6 else 0)
    size = 8 * (1 + (abi >= 4) + (abi >= 6))
    ruleset = libc.syscall(_LANDLOCK_CREATE_RULESET, ctypes.byref(attr), ctypes.c_size_t(size), ctypes.c_uint32(0))
    if ruleset < 0:
        raise RuntimeError(f"sandbox: landlock_create_ruleset failed: {os.strerror(ctypes.get_errno())}")

    class PathBeneath(ctypes.Structure):
        _pack_ = 1
        _fields_ = [("allowed_access", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]

    try:
        read = _FS_EXECUTE | _FS_READ_FILE
        for path, rights in [*((r, read | (0 if os.path.isfile(r) else _FS_READ_DIR)) for r in readable_roots()),
                             (os.devnull, _FS_WRITE_FILE | _FS_READ_FILE)]:
            fd = os.open(path, os.O_PATH | os.O_CLOEXEC)
            try:
                rule = PathBeneath(rights, fd)
                if libc.syscall(_LANDLOCK_ADD_RULE, ruleset, _LANDLOCK_RULE_PATH_BENEATH, ctypes.byref(rule),
                                ctypes.c_uint32(0)) < 0:
                    raise RuntimeError(f"sandbox: landlock_add_rule({path}) failed: {os.strerror(ctypes.get_errno())}")
            finally:
                os.close(fd)
        if libc.prctl(38, 1, 0, 0, 0) != 0:  # PR_SET_NO_NEW_PRIVS
            raise RuntimeError("sandbox: PR_SET_NO_NEW_PRIVS failed")
        if libc.syscall(_LANDLOCK_RESTRICT_SELF, ruleset, ctypes.c_uint32(0)) < 0:
            raise RuntimeError(f"sandbox: landlock_restrict_self failed: {os.strerror(ctypes.get_errno())}")
    finally:
        os.close(ruleset)
    return True


def layers() -> list[Layer]:
    """Every isolation layer and whether it is active here."""
    return [
        Layer("restricted-execution", True, "text-gate allowlist, RestrictedPython guards"),
        Layer("audit-hook", True, "no writes outside the work dir, no subprocesses, sockets or signals"),
        Layer("resource-limits", True, "CPU, address space, file size, open files, processes, no core"),
        seccomp_layer(),
        landlock_layer(),
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

    f = sc.SyscallFilter(defaction=sc.ERRNO(errno.EPERM))
    for name in ALLOWED_SYSCALLS:
        try:
            f.add_rule(sc.ALLOW, name)
        except (OSError, ValueError, RuntimeError):
            continue  # not a system call on this architecture
    f.add_rule(sc.ALLOW, "openat", sc.Arg(2, sc.MASKED_EQ, OPEN_WRITE_FLAGS, 0))
    try:
        f.add_rule(sc.ALLOW, "open", sc.Arg(1, sc.MASKED_EQ, OPEN_WRITE_FLAGS, 0))
    except (OSError, ValueError, RuntimeError):
        pass
    f.add_rule(sc.ALLOW, "ioctl", sc.Arg(1, sc.EQ, TCGETS))
    f.add_rule(sc.ALLOW, "prlimit64", sc.Arg(2, sc.EQ, 0))  # new_limit NULL: read only
    me = os.getpid()
    f.add_rule(sc.ALLOW, "kill", sc.Arg(0, sc.EQ, me))
    f.add_rule(sc.ALLOW, "tgkill", sc.Arg(0, sc.EQ, me))
    f.load()
