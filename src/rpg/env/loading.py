"""Loading a compiled task into an environment, through the checks ``rpg validate`` makes.

An environment runs task code (``assets()``, ``initial_state(rng)``, ``goal()``), so it
loads an artifact only after:

1. its files are read once, without following links (:func:`rpg.artifact.rehash`);
2. the content hash recomputed from them equals the one ``task.yaml`` records (a hand edit
   since compilation is refused: re-run ``rpg validate`` or recompile);
3. ``task.yaml`` records that every validation gate passed (and every optional gate that ran);
4. the text gate accepts that very text (:func:`rpg.validate.static.check_source`);
5. it is executed restricted (RestrictedPython guards, :mod:`rpg.validate.restricted`),
   and the task class and its goal and assets are checked as the validation worker checks
   them (:func:`rpg.validate.worker.load_task`).

The OS layers of the sandbox (namespaces, seccomp, resource limits) belong to the
short-lived validation worker; an environment lives in the caller's process and does not
have them.  See the README, "Running untrusted task code".
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from rpg.artifact import FILES_CHANGED, ArtifactError, rehash
from rpg.domain.task import BlockTask
from rpg.errors import BadInput, TaskInvalid
from rpg.validate.gates import GATES


@dataclass(frozen=True)
class TaskSource:
    """Where an environment's task came from.

    Attributes:
        directory: the task artifact directory (a family version's ``vN`` for ``FAMILY@vN``).
        target: the target as given.
        content_hash: the artifact's content hash (verified).
        name: the task's name.
        instruction: the canonical instruction.
        paraphrases: its paraphrases (``instruction="paraphrase:K"`` picks one).
    """

    directory: Path | None
    target: str
    content_hash: str
    name: str
    instruction: str
    paraphrases: tuple[str, ...]


@dataclass(frozen=True)
class TaskCode:
    """A task's code held in memory rather than in an artifact directory: what the validation
    worker runs the ``solvable`` gate on, before the artifact exists.  It has no content
    hash and no recorded gates; its text still goes through the text gate and restricted
    loading (steps 4 and 5 of the module docstring).

    Attributes:
        sources: ``code.py`` and ``goal_state_code.py`` text.
        name: the task's name.
        instruction: its canonical instruction.
        paraphrases: its paraphrases.
    """

    sources: Mapping[str, str]
    name: str = "task"
    instruction: str = ""
    paraphrases: tuple[str, ...] = field(default=())


def resolve_target(target: str | Path) -> Path:
    """The artifact directory of a task target: a task directory, a family directory (its
    head), or ``FAMILY@vN`` / ``FAMILY@<hash prefix>``.

    Raises:
        BadInput: no such directory, not a task or family, or an unknown version.
    """
    from rpg.steer.family import Family, is_family

    text = str(target)
    ref = None
    if "@" in text and not Path(text).exists():
        text, _, ref = text.rpartition("@")
    path = Path(text)
    if not path.is_dir():
        raise BadInput(f"no task at {text!r}: give a task directory, a family directory or FAMILY@vN")
    if is_family(path):
        fam = Family(path)
        return fam.version_dir(fam.resolve(ref).version_id)
    if ref is not None:
        raise BadInput(f"{text} is a task, not a family: '@{ref}' names a version of a family only")
    if not (path / "task.yaml").is_file():
        raise BadInput(f"{text} is not a task artifact (no task.yaml) nor a family (no history.yaml)")
    return path


def load_env_task(target: str | Path | TaskCode, robot=None) -> tuple[BlockTask, TaskSource, object]:
    """Check and load a task for an environment (see the module docstring for the checks).

    Args:
        target: a task directory, family directory or ``FAMILY@vN``, or a :class:`TaskCode`.
        robot: the embodiment to add to the task's scene.

    Returns:
        The task instance (scene compiled with the robot), where it came from, and the
        executed ``goal_state_code.py`` (its ``goal_state(task)`` sets the goal configuration).

    Raises:
        BadInput / ArtifactError: unreadable target or files changed since compilation.
        TaskInvalid: the artifact did not pass validation, or its code fails the text gate
            or the loading checks.
    """
    if isinstance(target, TaskCode):
        task, goal_module = _load_checked(dict(target.sources), robot)
        return task, TaskSource(directory=None, target=target.name, content_hash="", name=target.name,
                                instruction=target.instruction, paraphrases=tuple(target.paraphrases)), goal_module
    directory = resolve_target(target)
    schema, doc, sources, digest = rehash(directory)
    if digest != doc.get("content_hash"):
        raise ArtifactError(f"{directory}: {FILES_CHANGED}; run 'rpg validate {directory}' or recompile it")
    gates = (doc.get("provenance") or {}).get("gates") or {}
    failed = sorted({g for g in GATES if gates.get(g) not in ("pass", "skipped")}
                    | {g for g, status in gates.items() if status not in ("pass", "skipped")})
    if failed:
        raise TaskInvalid(f"{directory} did not pass validation (gate {failed[0]}: "
                          f"{gates.get(failed[0], 'not run')}); an environment loads only valid tasks "
                          "(see its validation.log)")
    task, goal_module = _load_checked(sources, robot)
    source = TaskSource(directory=directory, target=str(target), content_hash=digest, name=schema.name,
                        instruction=schema.instruction, paraphrases=tuple(schema.paraphrases))
    return task, source, goal_module


def _load_checked(sources: dict[str, str], robot) -> tuple[BlockTask, object]:
    """Steps 4 and 5 of the module docstring on ``sources``.

    Raises:
        TaskInvalid: the text gate or the loading checks refuse the code.
    """
    from rpg.validate.static import StaticViolation, check_source
    from rpg.validate.worker import GateFailure, load_task

    try:
        for fname, text in sources.items():
            check_source(text, fname)
        return load_task(sources, restricted=True, robot=robot)
    except (StaticViolation, GateFailure) as exc:
        raise TaskInvalid(f"task code rejected: {exc}") from None
