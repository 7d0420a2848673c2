"""Loading a compiled task into an environment: task code runs only in the sandbox.

An environment never imports or calls task code.  It loads an artifact after:

1. its files are read once, without following links (:func:`rpg.artifact.rehash`);
2. the content hash recomputed from them equals the one ``task.yaml`` records (a hand edit
   since compilation is refused: re-run ``rpg validate`` or recompile);
3. ``task.yaml`` records that every validation gate passed (and every optional gate that ran);
4. the text gate accepts that very text (:func:`rpg.validate.static.check_source`);
5. the sandbox runs it and returns data (:func:`rpg.validate.data.fetch_task_data`: assets,
   the goal as the predicate registry's dict, the goal configuration, rho_0's samples per
   seed, fetched and cached as episodes ask for them), which rpg rebuilds with its own
   classes into a :class:`rpg.domain.task.Task`.  G is always rpg's own predicates.

Steps 1-3 say the artifact is the one that was validated; step 5 makes that matter less:
whatever the code does, it does in the sandbox, and what comes back is checked data.  See
the README, "Running untrusted task code".
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from rpg.artifact import FILES_CHANGED, ArtifactError, rehash
from rpg.domain.task import Task, TaskData
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
        instruction: the instruction as written (``instruction="original"``).
        paraphrases: its paraphrases (``instruction="paraphrase:K"`` picks one).
        canonical: a text generated from G that states exactly what G checks
            (``instruction="canonical"``; :func:`rpg.schema.citations.canonical_instruction`).
    """

    directory: Path | None
    target: str
    content_hash: str
    name: str
    instruction: str
    paraphrases: tuple[str, ...]
    canonical: str = ""


@dataclass(frozen=True)
class PreparedTask:
    """A task's checked data held in memory rather than in an artifact directory: what the
    ``solvable`` gate runs the oracle on, before the artifact exists (no content hash, no
    recorded gates).

    Attributes:
        data: the task code's checked data (:func:`rpg.validate.data.fetch_task_data`).
        name: the task's name.
        instruction: its canonical instruction.
        paraphrases: its paraphrases.
    """

    data: TaskData
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


def load_env_task(target: str | Path | PreparedTask, robot=None) -> tuple[Task, TaskSource]:
    """Check and load a task for an environment (see the module docstring for the checks).

    Args:
        target: a task directory, family directory or ``FAMILY@vN``, or a :class:`PreparedTask`.
        robot: the embodiment to add to the task's scene.

    Returns:
        The task (scene compiled with the robot) and where it came from.

    Raises:
        BadInput / ArtifactError: unreadable target or files changed since compilation.
        TaskInvalid: the artifact did not pass validation, or its code fails the text gate,
            fails in the sandbox or returns data that does not check.
    """
    if isinstance(target, PreparedTask):
        return Task(target.data, robot=robot), TaskSource(
            directory=None, target=target.name, content_hash="", name=target.name,
            instruction=target.instruction, paraphrases=tuple(target.paraphrases), canonical=target.instruction)
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
    task = Task(task_data(sources, where=str(directory)), robot=robot)
    from rpg.schema.citations import canonical_instruction

    source = TaskSource(directory=directory, target=str(target), content_hash=digest, name=schema.name,
                        instruction=schema.instruction, paraphrases=tuple(schema.paraphrases),
                        canonical=canonical_instruction(schema))
    return task, source


def task_data(sources: dict[str, str], where: str = "task") -> TaskData:
    """Steps 4 and 5 of the module docstring on ``sources``: the text gate, then the task
    code's data from the sandbox.

    Raises:
        TaskInvalid: the text gate refuses the code, or the sandbox run fails or returns
            data that does not check (its goal configuration too).
    """
    from rpg.validate.data import PREFETCH_SEEDS, fetch_task_data
    from rpg.validate.static import StaticViolation, check_source

    try:
        for fname, text in sources.items():
            check_source(text, fname)
    except StaticViolation as exc:
        raise TaskInvalid(f"{where}: task code rejected: {exc}") from None
    data = fetch_task_data(sources, range(PREFETCH_SEEDS))  # the first episodes' rho_0 in the same sandboxed run
    if data.goal_poses is None:
        raise TaskInvalid(f"{where}: {data.goal_error}")
    return data
