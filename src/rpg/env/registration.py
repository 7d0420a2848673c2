"""Gymnasium ids for the tasks of a library, and suites of them by filter.

    import gymnasium as gym
    import rpg.env                      # registers rpg/<task>-v0 for the default library

    env = gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=())
    ids = rpg.env.make_suite("split=eval")       # ('rpg/stack_on_goal_patch-v0', ...)

Each entry of a library's manifest gets an id in a namespace (``rpg`` for the default
library): a task ``NAME`` is ``NAMESPACE/NAME-v0``; a family ``FAMILY`` is
``NAMESPACE/FAMILY-v0`` (its head, as ``task="library/FAMILY"``) and each of its versions
``NAMESPACE/FAMILY.vN-v0`` (``FAMILY@vN`` elsewhere in rpg: Gymnasium's ids cannot hold
``@``).  The ``-v0`` is the environment's version, not the task's.  Every id makes a
:class:`rpg.env.BlockTaskEnv` with ``task`` set to the entry's absolute path; the other
keyword arguments of ``gym.make`` are the environment's (``embodiment``, ``cameras``,
``image_size``, ``instruction``, ``control_mode``, ``privileged``...).

Registering reads the manifest and the families' ``family.yaml`` only: no task is loaded,
checked or run until ``gym.make`` (measured: ~15 ms for the 42 entries and 26 family
versions of ``library/``).  A task is loaded with every check of :mod:`rpg.env.loading` when
it is made, so an id registered for a task that has since been edited by hand fails then.

The default library, registered when :mod:`rpg.env` is imported: ``$RPG_LIBRARY`` (a
manifest, or a directory holding ``manifest.yaml``) if set, else the checkout's
``library/manifest.yaml`` when rpg runs from its source tree, else none
(:func:`register_library` registers one).  Spawned vector-environment workers import
:mod:`rpg.env` again (``gym.make("rpg.env:rpg/NAME-v0")``), so they see the same default
library; a library registered by hand in another namespace must be registered in the
worker too.
"""

from __future__ import annotations

import os
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import gymnasium as gym

from rpg.errors import BadInput

ENTRY_POINT = "rpg.env.core:BlockTaskEnv"
"""What every library id makes."""

DEFAULT_NAMESPACE = "rpg"
"""The namespace of the default library's ids."""

LIBRARY_ENV_VAR = "RPG_LIBRARY"
"""Environment variable naming the default library (a manifest or its directory)."""

ENV_VERSION = 0
"""The ``-vN`` of every library id: the environment's interface version."""


@dataclass
class RegisteredLibrary:
    """A library registered in a namespace: its manifest, its ids, and which task
    directory each id makes (resolved; a suite maps tasks to ids through it)."""

    manifest: Path
    namespace: str
    ids: tuple[str, ...] = ()
    by_directory: dict[Path, str] = field(default_factory=dict)


LIBRARIES: dict[str, RegisteredLibrary] = {}
"""Namespace -> the library registered in it (one library per namespace)."""


def env_id(namespace: str, name: str, version: int | None = None) -> str:
    """The id of a library entry: ``NAMESPACE/NAME-v0``, or ``NAMESPACE/NAME.vN-v0`` for
    version N of family NAME."""
    base = name if version is None else f"{name}.v{version}"
    return f"{namespace}/{base}-v{ENV_VERSION}"


def _manifest_path(library: str | Path) -> Path:
    path = Path(library).expanduser()
    if path.is_dir():
        path = path / "manifest.yaml"
    if not path.is_file():
        raise BadInput(f"no library manifest at {library}: give a manifest file or the directory that holds "
                       "its manifest.yaml")
    return path.resolve()


def default_library() -> Path | None:
    """The manifest of the default library (see the module docstring), or None.

    Raises:
        BadInput: ``$RPG_LIBRARY`` is set and names no manifest.
    """
    named = os.environ.get(LIBRARY_ENV_VAR)
    if named:
        return _manifest_path(named)
    checkout = Path(__file__).resolve().parents[3] / "library" / "manifest.yaml"
    return checkout if checkout.is_file() else None


def register_library(library: str | Path, namespace: str = DEFAULT_NAMESPACE) -> tuple[str, ...]:
    """Register an id for every task and family version of ``library`` in ``namespace``
    (see the module docstring for the ids); registering the same library again does
    nothing.

    Args:
        library: a manifest (``library/manifest.yaml``) or the directory holding it.
        namespace: the ids' namespace (letters, digits, ``_``, ``-``).

    Returns:
        The ids, in manifest order (a family's head, then its versions).

    Raises:
        BadInput: no manifest there, an unreadable manifest or family history
            (:class:`rpg.library.build.ManifestError`, :class:`rpg.steer.family.FamilyError`),
            or ``namespace`` already holds another library (register it in another
            namespace, e.g. ``namespace="mylib"``).
    """
    import re

    from rpg.library.build import load_manifest
    from rpg.steer.family import Family

    if not re.fullmatch(r"[A-Za-z0-9_-]+", namespace or ""):
        raise BadInput(f"namespace {namespace!r} must be letters, digits, '_' or '-' (Gymnasium's id syntax)")
    manifest = _manifest_path(library)
    have = LIBRARIES.get(namespace)
    if have is not None:
        if have.manifest == manifest:
            return have.ids
        raise BadInput(f"namespace {namespace!r} already holds the library {have.manifest}; register {manifest} "
                       "in another namespace (register_library(..., namespace='mylib'))")
    root = manifest.parent
    entries: list[tuple[str, str, Path | None]] = []  # (id, task target, directory it makes)
    for e in load_manifest(manifest).entries:
        path = root / e.name
        if e.kind == "family":
            fam = Family(path)
            entries.append((env_id(namespace, e.name), str(path), None))
            for v in fam.load().versions:
                entries.append((env_id(namespace, e.name, v.version_id), f"{path}@v{v.version_id}",
                                fam.version_dir(v.version_id)))
        else:
            entries.append((env_id(namespace, e.name), str(path), path))
    taken = [i for i, _, _ in entries if i in gym.registry]
    if taken:
        raise BadInput(f"{taken[0]} is registered already (not by rpg.env.register_library): register {manifest} "
                       "in another namespace")
    lib = RegisteredLibrary(manifest, namespace)
    for i, target, directory in entries:
        gym.register(id=i, entry_point=ENTRY_POINT, kwargs={"task": target}, disable_env_checker=False,
                     order_enforce=True)
        if directory is not None:
            lib.by_directory[directory.resolve()] = i
    lib.ids = tuple(i for i, _, _ in entries)
    LIBRARIES[namespace] = lib
    return lib.ids


def register_default_library() -> tuple[str, ...]:
    """Register the default library (see the module docstring) in :data:`DEFAULT_NAMESPACE`;
    what importing :mod:`rpg.env` does.  A library that cannot be read is reported with a
    warning, not an error (importing :mod:`rpg.env` must not fail on it)."""
    try:
        manifest = default_library()
        return () if manifest is None else register_library(manifest, DEFAULT_NAMESPACE)
    except BadInput as exc:
        warnings.warn(f"rpg.env: the default library's ids are not registered: {exc} (set ${LIBRARY_ENV_VAR} to a "
                      "library manifest, or call rpg.env.register_library)", stacklevel=2)
        return ()


def make_suite(target: str, namespace: str = DEFAULT_NAMESPACE) -> tuple[str, ...]:
    """The ids of the tasks a target selects from the library registered in ``namespace``.

    ``target`` is what ``rpg eval`` accepts (:func:`rpg.eval.runner.eval_tasks` parses it):
    a filter ``KEY=VALUE`` over the library's manifest (``split=eval``, ``split=train``, a
    ``task.yaml`` tag such as ``reasoning=semantic``), the manifest itself (every task and
    every family version), a task or family directory of the library, or ``FAMILY@vN``.
    A family contributes its versions' ids (``NAMESPACE/FAMILY.vN-v0``), as ``rpg eval``
    evaluates every version.

    Returns:
        The ids, in the order ``rpg eval`` runs the tasks; ``gym.make(i, **kwargs)`` makes each.

    Raises:
        BadInput: nothing registered in ``namespace`` (call :func:`register_library`), a
            target ``rpg eval`` refuses (a filter that selects nothing...), or a task that is
            not in the registered library.
    """
    from rpg.eval.runner import eval_tasks

    lib = LIBRARIES.get(namespace)
    if lib is None:
        raise BadInput(f"no library is registered in namespace {namespace!r}: call "
                       f"rpg.env.register_library('library/manifest.yaml', namespace={namespace!r}) "
                       f"(or set ${LIBRARY_ENV_VAR} before importing rpg.env)")
    out = []
    for task in eval_tasks(target, library=lib.manifest):
        i = lib.by_directory.get(Path(task.path).resolve())
        if i is None:
            raise BadInput(f"{task.path} (selected by {target!r}) is not a task of {lib.manifest}, the library "
                           f"registered in namespace {namespace!r}; register its library in another namespace")
        out.append(i)
    return tuple(out)
