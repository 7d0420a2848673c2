"""Backends that run independent work items in parallel, for ``rpg build``, ``rpg eval`` and
``rpg demos``.

:data:`BACKENDS` maps a name to what opens it (:func:`open_backend`):

- ``local``: a process pool on this machine (``jobs`` workers; one job runs in this process).
- ``ray``: Ray tasks (``pip install 'rpg[ray]'``), one CPU each, on a local instance this
  process starts with ``jobs`` CPUs (bound to 127.0.0.1, Ray's token authentication on, shut
  down at the end; a kill -9 of ``rpg`` takes it and its workers with it) or, with
  ``address``, on a running cluster (``auto``, or the head node's ``host:port``), whose
  CPUs decide how many run at once.  A cluster's workers need rpg installed and the paths
  the work names (tasks, the run or dataset directory) at the same place: a shared file
  system.  Each task runs in the caller's working directory, so relative paths mean the same.

A backend's :meth:`Backend.imap` yields the results as the items finish (or, ``ordered``, in
the items' order); only the caller commits them, so what a run writes does not depend on the
backend.  An exception a work item raises reaches the caller as itself.
"""

from __future__ import annotations

import concurrent.futures as cf
import contextlib
import logging
import multiprocessing
import os
import socket
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures.process import BrokenProcessPool
from contextlib import AbstractContextManager

from rpg.errors import EXIT_SYSTEM, BadInput, RpgError

CONNECT_TIMEOUT_S = 5.0
"""How long ``--address`` may take to accept a TCP connection before it is called unreachable, s
(Ray itself retries an unreachable cluster for many minutes)."""


class BackendError(BadInput):
    """A backend that cannot be used (exit code 2): an unknown name, Ray not installed, a
    cluster address that cannot be reached, ``address`` without the ray backend."""


class WorkerLost(RpgError):
    """A worker process or node died while it ran an item (exit code 4, the machine failed);
    what was committed before is kept, and the same command resumes."""

    exit_code = EXIT_SYSTEM


class Backend:
    """Runs a function over work items (:func:`open_backend`)."""

    name = "inline"

    def imap(self, fn: Callable, items: Iterable, ordered: bool = False) -> Iterator:
        """``fn(item)`` for every item: the results as they finish, or with ``ordered`` in the
        items' order.  Items not started when the iteration stops are cancelled.

        Raises:
            Exception: what ``fn`` raised, as itself.
            WorkerLost: a worker died while it ran an item.
        """
        yield from map(fn, items)


class _Pool(Backend):
    name = "local"

    def __init__(self, pool: cf.ProcessPoolExecutor):
        self.pool = pool

    def imap(self, fn, items, ordered=False):
        futures = [self.pool.submit(fn, x) for x in items]
        try:
            for fut in futures if ordered else cf.as_completed(futures):
                try:
                    yield fut.result()
                except BrokenProcessPool as exc:
                    raise WorkerLost(f"a worker process died ({exc}); rerun the same command to resume") from None
        finally:
            for fut in futures:
                fut.cancel()


def _in_dir(fn: Callable, cwd: str, item):
    """Run ``fn(item)`` in ``cwd`` (a Ray task: the caller's working directory)."""
    if os.getcwd() != cwd:
        os.chdir(cwd)
    return fn(item)


class _Ray(Backend):
    name = "ray"

    def __init__(self, ray):
        self.ray = ray
        self.task = ray.remote(num_cpus=1)(_in_dir)

    def _get(self, ref):
        ray = self.ray
        try:
            return ray.get(ref)
        except ray.exceptions.RayTaskError as exc:
            if isinstance(exc.cause, BaseException):
                raise exc.cause from None
            raise WorkerLost(f"a Ray task failed: {' '.join(str(exc).split())[:300]}") from None
        except ray.exceptions.RayError as exc:  # a worker, node or object lost
            raise WorkerLost(f"a Ray worker was lost ({type(exc).__name__}: {' '.join(str(exc).split())[:200]}); "
                             "rerun the same command to resume") from None

    def imap(self, fn, items, ordered=False):
        cwd = os.getcwd()
        name = getattr(getattr(fn, "func", fn), "__name__", "rpg")  # what Ray's tools call the tasks
        task = self.task.options(name=name)
        refs = [task.remote(fn, cwd, x) for x in items]
        pending = list(refs)
        try:
            if ordered:
                for ref in refs:
                    pending.remove(ref)
                    yield self._get(ref)
            while pending:
                done, pending = self.ray.wait(pending, num_returns=1)
                yield self._get(done[0])
        finally:
            for ref in pending:
                with contextlib.suppress(Exception):
                    self.ray.cancel(ref)


@contextlib.contextmanager
def _local(jobs: int, address: str | None = None, initializer: Callable | None = None,
           mp_context: str | None = "spawn") -> Iterator[Backend]:
    if address:
        raise BackendError("--address names a Ray cluster; give it with --backend ray")
    if jobs <= 1:
        yield Backend()
        return
    if initializer is None:
        from rpg.validate.isolation import die_with_parent

        initializer = die_with_parent  # no orphans after a kill -9
    ctx = multiprocessing.get_context(mp_context) if mp_context else None
    with cf.ProcessPoolExecutor(jobs, mp_context=ctx, initializer=initializer) as pool:
        try:
            yield _Pool(pool)
        except BaseException:
            pool.shutdown(wait=True, cancel_futures=True)
            raise


def _check_address(address: str) -> None:
    """Refuse a cluster address that does not accept a TCP connection within
    :data:`CONNECT_TIMEOUT_S` (``auto``: the running cluster Ray finds, as ``ray.init`` would).

    Raises:
        BackendError: a malformed address, no cluster for ``auto``, or no answer.
    """
    text = address.split("://", 1)[1] if "://" in address else address
    try:
        if "://" not in address:
            from ray._private.services import canonicalize_bootstrap_address_or_die

            text = canonicalize_bootstrap_address_or_die(address)
    except (ImportError, AttributeError):  # Ray's internals moved: ray.init says what is wrong
        return
    except (ConnectionError, ValueError) as exc:
        raise BackendError(f"--address {address}: {' '.join(str(exc).split())[:200]}") from None
    host, _, port = text.rpartition(":")
    if not host or not port.isdigit():
        raise BackendError(f"--address {address} is not host:port (or auto)")
    try:
        socket.create_connection((host.strip("[]"), int(port)), timeout=CONNECT_TIMEOUT_S).close()
    except OSError as exc:
        raise BackendError(f"cannot reach a Ray cluster at --address {address} ({host}:{port}: "
                           f"{exc.strerror or type(exc).__name__}); start one with 'ray start --head' or "
                           "leave --address out for a local instance") from None


@contextlib.contextmanager
def _stderr_quiet() -> Iterator[None]:
    """File descriptor 2 sent to /dev/null (native code's log lines too) for the block's duration."""
    import sys

    with contextlib.suppress(Exception):
        sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


@contextlib.contextmanager
def _ray(jobs: int, address: str | None = None, **_) -> Iterator[Backend]:
    try:
        import ray
    except ImportError:
        raise BackendError("the ray backend needs Ray: pip install 'rpg[ray]'") from None
    started = not ray.is_initialized()
    if started:
        quiet = dict(include_dashboard=False, log_to_driver=False, logging_level=logging.ERROR)
        try:
            if address:
                _check_address(address)
                with _stderr_quiet():  # Ray's C++ client logs each failed attempt to connect
                    ray.init(address=address, **quiet)
            else:
                # A local instance: node address 127.0.0.1 and Ray's token authentication on, so
                # what Ray still opens on other interfaces answers only to this session's token.
                if os.environ.get("RAY_AUTH_MODE", "token") != "token":  # Ray's default: a per-session token
                    raise BackendError("a local Ray instance needs RAY_AUTH_MODE=token (Ray's token "
                                       "authentication); unset RAY_AUTH_MODE or pass --address to use a "
                                       "cluster you secured yourself")
                # address "local": a new instance of its own, even where the machine runs another (without it Ray
                # joins RAY_ADDRESS's or the last one started there, whose workers may run other code: two runs of the
                # test suite side by side had written different videos, a user's job could land on someone else's cluster)
                ray.init(address="local", num_cpus=jobs, _node_ip_address="127.0.0.1", **quiet)
        except BackendError:
            raise
        except Exception as exc:  # noqa: BLE001 - Ray's many start-up failures, as one line
            with contextlib.suppress(Exception):
                ray.shutdown()
            where = f"the Ray cluster at --address {address}" if address else "a local Ray instance"
            hint = ""
            if address and os.environ.get("RAY_AUTH_MODE") != "token":
                hint = (" (a cluster with Ray's token authentication needs RAY_AUTH_MODE=token here and its "
                        "token in RAY_AUTH_TOKEN or ~/.ray/auth_token)")
            raise BackendError(f"could not start {where}: {type(exc).__name__}: "
                               f"{' '.join(str(exc).split())[:300]}{hint}") from None
    try:
        yield _Ray(ray)
    finally:
        if started:
            ray.shutdown()


BACKENDS: dict[str, Callable[..., AbstractContextManager[Backend]]] = {"local": _local, "ray": _ray}
"""Backend name -> what opens it: ``(jobs, address, initializer=..., mp_context=...)``."""


def open_backend(name: str, jobs: int, address: str | None = None, initializer: Callable | None = None,
                 mp_context: str | None = "spawn") -> AbstractContextManager[Backend]:
    """The backend ``name`` with ``jobs`` workers, as a context manager (closed at its end).

    ``address``: a Ray cluster (``ray`` only).  ``initializer`` and ``mp_context``: the
    ``local`` pool's worker initializer (default: die with this process) and start method.

    Raises:
        BackendError: an unknown name or ``jobs`` < 1; Ray not installed, or its cluster
            unreachable or not started; ``address`` given to ``local``.
    """
    if name not in BACKENDS:
        raise BackendError(f"--backend must be {' or '.join(BACKENDS)}, not {name!r}")
    if jobs < 1:
        raise BackendError("--jobs must be at least 1")
    return BACKENDS[name](jobs, address, initializer=initializer, mp_context=mp_context)


__all__ = ["BACKENDS", "Backend", "BackendError", "WorkerLost", "open_backend"]
