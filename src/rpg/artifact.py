"""Task artifacts on disk: reading, writing, hashing and publishing a task directory.

An artifact directory holds ``task.yaml`` (the schema, tags, provenance, mention accounting,
file manifest and content hash), ``code.py``, ``goal_state_code.py``, ``validation.log``,
``validation.json``, ``initial.png``, ``goal.png`` and, for a model's task, its record
``llm_log.jsonl``.  Every pass that reads or writes one goes through this module; it imports
nothing from the compiler or the steering layer.

Two hashes cover the files:

* ``content_hash``: task.yaml's fields, both code files and the model record (what the task
  *is*, and what ``--replay`` rebuilds it from).  Reproducible: the same compile gives the
  same hash, so a library manifest records it and ``rpg verify --expect`` compares it.
* ``files`` in task.yaml (:func:`file_manifest`): the SHA-256 of every other file of the
  directory, snapshots and validation logs included, which ``rpg verify`` checks
  (:func:`check_files`: a changed, missing or unexpected file is named).  It is outside the
  content hash, because snapshots depend on the renderer and logs carry times; nothing is
  built or run from those files, and ``rpg validate`` / ``rpg render`` rewrite them.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import shutil
import stat
import tempfile
import time
from pathlib import Path

from rpg import yamlio
from rpg._version import __version__
from rpg.errors import BadInput
from rpg.schema.model import TaskSchema
from rpg.validate.gates import GATES


class ArtifactError(BadInput):
    """A task artifact is missing, malformed or truncated."""


NAME_PATTERN = r"^[a-z][a-z0-9_]{0,99}$"
"""Every name that becomes a path (task, session, manifest entry): snake_case, at most 100 characters."""


def check_name(name: object, what: str) -> str:
    """``name`` if it is a valid task/family name (:data:`NAME_PATTERN`): one path component,
    no separators, no ``..``.

    Raises:
        BadInput: anything else, with the name and the rule.
    """
    import re

    if not isinstance(name, str) or not re.fullmatch(NAME_PATTERN, name):
        raise BadInput(f"{what} {name!r} is not a valid name: use snake_case letters, digits and underscores "
                       "(it becomes a directory name)")
    return name


MAX_ARTIFACT_FILE = 4 * 1024**2
"""Largest artifact text file read (task.yaml, code files, family.yaml), bytes."""

TASK_CODE_FILES = ("code.py", "goal_state_code.py")
TASK_FILE = "task.yaml"
MODEL_RECORD = "llm_log.jsonl"
"""The model's exchanges (:mod:`rpg.schema.llm`), part of the content hash when present."""
MANIFEST_KEY = "files"
"""task.yaml's file manifest: name -> SHA-256 of every file of the artifact but task.yaml."""
MAX_MANIFEST_FILE = 256 * 1024**2
"""Largest artifact file hashed for the manifest (snapshots included), bytes."""


def read_bytes(path: Path, limit: int = MAX_ARTIFACT_FILE) -> bytes:
    """Read a regular file without following a symbolic link at ``path``.

    Raises:
        ArtifactError: missing, a symlink, not a regular file, or larger than ``limit`` bytes.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC | os.O_NONBLOCK)
    except FileNotFoundError:
        raise ArtifactError(f"{path} is missing") from None
    except OSError as exc:
        if os.path.islink(path):
            raise ArtifactError(f"{path} is a symbolic link; artifact files must be regular files") from None
        raise ArtifactError(f"cannot read {path}: {exc.strerror}") from None
    with os.fdopen(fd, "rb") as fh:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise ArtifactError(f"{path} is not a regular file")
        data = fh.read(limit + 1)
    if len(data) > limit:
        raise ArtifactError(f"{path} is larger than {limit} bytes")
    return data


def read_text(path: Path, limit: int = MAX_ARTIFACT_FILE) -> str:
    """:func:`read_bytes` decoded as UTF-8.

    Raises:
        ArtifactError: as :func:`read_bytes`, or the bytes are not UTF-8.
    """
    try:
        return read_bytes(path, limit).decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ArtifactError(f"{path} is not UTF-8 text (byte {exc.start})") from None


def task_sources(directory: Path) -> dict[str, str]:
    """The text of ``code.py`` and ``goal_state_code.py``, read once: the text the text gate
    checks is the text the worker runs.

    Raises:
        ArtifactError: a file is missing, a link, oversized or not UTF-8.
    """
    return {f: read_text(Path(directory) / f) for f in TASK_CODE_FILES}


FILES_CHANGED = "artifact files changed since they were written (content hash differs from task.yaml)"


def model_record(directory: Path) -> bytes | None:
    """The bytes of the artifact's ``llm_log.jsonl``, or None when it has none.

    Raises:
        ArtifactError: the record is a link, not a regular file or oversized.
    """
    path = Path(directory) / MODEL_RECORD
    return read_bytes(path, MAX_MANIFEST_FILE) if os.path.lexists(path) else None


def rehash(directory: Path) -> tuple[TaskSchema, dict, dict[str, str], str]:
    """An artifact as it is on disk: its schema, task.yaml document, code text (read once)
    and the content hash recomputed from them and the model record, if any (compare with
    ``doc["content_hash"]``).

    Raises:
        ArtifactError: a missing, linked, oversized, non-UTF-8 or malformed file.
    """
    schema, doc = load_artifact(directory)
    sources = task_sources(directory)
    return schema, doc, sources, content_hash(doc, sources["code.py"], sources["goal_state_code.py"],
                                              model_record(directory))


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _scan(directory: Path) -> tuple[dict[str, str], list[str]]:
    """(name -> SHA-256 of every regular file but task.yaml, names of the entries that are
    not regular files: links, directories, devices)."""
    files: dict[str, str] = {}
    odd: list[str] = []
    with os.scandir(directory) as it:
        entries = sorted(it, key=lambda e: e.name)
    for entry in entries:
        if entry.name == TASK_FILE:
            continue
        if entry.is_symlink() or not entry.is_file(follow_symlinks=False):
            odd.append(entry.name)
            continue
        files[entry.name] = _sha256(read_bytes(Path(entry.path), MAX_MANIFEST_FILE))
    return files, odd


def file_manifest(directory: Path) -> dict[str, str]:
    """SHA-256 of every file of an artifact directory except task.yaml, by name.

    Raises:
        ArtifactError: an entry is a link, a directory or another non-regular file, or a
            file is unreadable or larger than :data:`MAX_MANIFEST_FILE`.
    """
    files, odd = _scan(Path(directory))
    if odd:
        raise ArtifactError(f"{Path(directory) / odd[0]} is not a regular file; an artifact holds only files")
    return files


def check_files(directory: Path, doc: dict) -> list[str]:
    """Compare an artifact's files with the manifest its task.yaml ``doc`` records; one
    problem per kind of difference, each naming the files (empty when they agree)."""
    directory = Path(directory)
    recorded = doc.get(MANIFEST_KEY)
    if not isinstance(recorded, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in recorded.items()):
        return [f"{TASK_FILE} records no file manifest ('{MANIFEST_KEY}'), so no file beside it is covered: "
                "recompile, or run 'rpg validate' on a copy you trust to record the files as they are"]
    try:
        current, odd = _scan(directory)
    except (ArtifactError, OSError) as exc:
        return [f"cannot hash the artifact's files: {exc}"]
    problems = []
    changed = sorted(n for n in set(recorded) & set(current) if recorded[n] != current[n])
    missing = sorted(set(recorded) - set(current) - set(odd))
    extra = sorted(set(current) - set(recorded))
    if changed:
        problems.append(f"changed since the artifact was written (SHA-256 differs from {TASK_FILE}'s manifest): {', '.join(changed)}")
    if missing:
        problems.append(f"missing (recorded in {TASK_FILE}'s manifest): {', '.join(missing)}")
    if extra:
        problems.append(f"unexpected files (not in {TASK_FILE}'s manifest): {', '.join(extra)}")
    if odd:
        problems.append(f"not regular files (links or directories; an artifact holds only files): {', '.join(odd)}")
    return problems


def record_files(directory: Path, names: list[str] | None = None) -> None:
    """Re-record files of an artifact in task.yaml's manifest after rpg rewrote them
    (``rpg validate``'s logs, ``rpg render``'s snapshots): only ``names``, or every file
    when ``names`` is None or task.yaml has no manifest yet.  The content hash is unchanged.

    Raises:
        ArtifactError: task.yaml or a named file is missing, linked, oversized or malformed.
    """
    directory = Path(directory)
    doc = yamlio.load(read_text(directory / TASK_FILE))
    if not isinstance(doc, dict):
        raise ArtifactError(f"{directory / TASK_FILE} is malformed: not a mapping")
    recorded = doc.get(MANIFEST_KEY)
    if names is None or not isinstance(recorded, dict):
        files = file_manifest(directory)
    else:
        files = dict(recorded)
        for name in names:
            files[name] = _sha256(read_bytes(directory / name, MAX_MANIFEST_FILE))
    write_file(directory / TASK_FILE, yamlio.dump(_with_manifest(doc, dict(sorted(files.items())))))


def _with_manifest(doc: dict, files: dict[str, str]) -> dict:
    """``doc`` with its manifest set, placed just before the content hash."""
    out = {k: v for k, v in doc.items() if k not in (MANIFEST_KEY, "content_hash")}
    out[MANIFEST_KEY] = files
    if "content_hash" in doc:
        out["content_hash"] = doc["content_hash"]
    return out


def check_model_record(directory: Path, name: str, data: bytes) -> None:
    """Refuse a model record read from an artifact directory unless it is the artifact's own,
    unchanged: ``llm_log.jsonl``, its SHA-256 the one task.yaml's manifest records and the
    content hash (which covers it) intact.  ``data`` is the bytes as read, once.

    Raises:
        ArtifactError: anything else (one line naming the file).
    """
    directory = Path(directory)
    where = directory / name
    _, doc = load_artifact(directory)
    recorded = doc.get(MANIFEST_KEY)
    if name != MODEL_RECORD or not isinstance(recorded, dict) or name not in recorded:
        raise ArtifactError(f"{where} is not the model record in {TASK_FILE}'s file manifest; refusing to replay it")
    if _sha256(data) != recorded[name]:
        raise ArtifactError(f"{where} was changed since the artifact was written (its SHA-256 differs from "
                            f"{TASK_FILE}'s manifest); refusing to replay it")
    sources = task_sources(directory)
    if content_hash(doc, sources["code.py"], sources["goal_state_code.py"], data) != doc.get("content_hash"):
        raise ArtifactError(f"{directory} does not match its content hash ({TASK_FILE}, the code or {name} "
                            "changed since it was written); refusing to replay its model record")


def write_file(path: Path, data: str | bytes) -> None:
    """Write ``path`` through a new file renamed over it: a symbolic link at ``path`` is
    replaced, never written through, and readers never see a half-written file.

    Raises:
        OSError: the directory is not writable or the disk is full (nothing is left behind).
    """
    path = Path(path)
    raw = data.encode() if isinstance(data, str) else data
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def gates_passed(gates: list[dict]) -> bool:
    """Every gate of :data:`~rpg.validate.gates.GATES` passed or was switched off, and every
    other gate that ran (an optional one) passed."""
    ran = {g["gate"]: g["status"] for g in gates}
    return (all(ran.get(name) in ("pass", "skipped") for name in GATES)
            and all(status in ("pass", "skipped") for status in ran.values()))


def content_hash(task_doc: dict, code: str, goal_code: str, record: bytes | None = None) -> str:
    """SHA-256 over the canonical task.yaml fields (not the hash itself, not the file
    manifest), the two code files and the model record's bytes when there is one (an
    artifact without one hashes as before the record was covered)."""
    doc = {k: v for k, v in task_doc.items() if k not in ("content_hash", MANIFEST_KEY)}
    h = hashlib.sha256()
    h.update(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode())
    h.update(b"\0" + code.encode() + b"\0" + goal_code.encode())
    if record is not None:
        h.update(b"\0" + MODEL_RECORD.encode() + b"\0" + _sha256(record).encode())
    return h.hexdigest()


def mention_accounting(schema: TaskSchema, said: str | None = None) -> list[dict]:
    """Which words of the instruction produced which part of the task: one
    ``{"mention", "kind", "consumed_by"}`` per colour, label, count, patch, place, structure
    and relation the instruction names (:func:`rpg.schema.builtin.check_mentions`), and one of
    kind ``ignored`` per word or sentence set aside as naming nothing of the task.  ``said`` is
    the text as the user wrote it, when the task's instruction is what was left of it once
    such sentences were set aside ("Calm seas. Put the red cube on the blue cube."): they are
    accounted for from it.  A mention the task has no part for (a schema edited by hand), or a
    text this accounting cannot read whole though the parser did (a start said before its goal:
    "Initially red is on yellow. Swap them ..."), is recorded with kind ``unaccounted``; it never
    raises."""
    from rpg.schema.accounting import UnaccountedMention
    from rpg.schema.builtin import ParseError, check_mentions

    failure: Exception | None = None
    for text in dict.fromkeys(t for t in (said, schema.instruction) if t):
        try:
            return check_mentions(text, schema)
        except (UnaccountedMention, ParseError) as exc:  # a start said before the goal ("Initially red is on yellow.
            failure = failure or exc  # Swap them ...") is read by the parser, not by this accounting: recorded, no crash
    return [{"mention": schema.instruction[:200], "kind": "unaccounted", "consumed_by": str(failure).splitlines()[0][:300]}]


def set_aside(doc: dict) -> list[tuple[str, str]]:
    """(what, why) for each word or sentence of the user's text that a task document's accounting records as set
    aside (kind ``ignored``: "Calm seas.", "a sentence that names nothing of the task"), in the order said."""
    def why(consumed_by: str) -> str:  # "nothing: no meaning for the goal (reads like 'please')"
        like = re.fullmatch(r"nothing: no meaning for the goal \(reads like '(.*)'\)", consumed_by, re.S)
        if like is None:
            return consumed_by.removeprefix("nothing: ")
        return like.group(1) if " " in like.group(1) else f"reads like '{like.group(1)}'"

    return [(a["mention"], why(a["consumed_by"])) for a in doc.get("accounting", []) if a.get("kind") == "ignored"]


def constraint_citations(schema: TaskSchema) -> list[dict]:
    """Reverse accounting: each constraint of G with the mentions of the instruction that
    demand it (:func:`rpg.schema.citations.citations`)."""
    from rpg.schema.citations import citations

    return citations(schema)


def task_document(schema: TaskSchema, seed: int, backend: str, model: str | None, gates: list[dict],
                  author: str | None = None, said: str | None = None) -> dict:
    """The content of ``task.yaml`` (without its hash): the schema, retrieval tags, the
    mention accounting (:func:`mention_accounting`), the constraints of G with the mentions
    that demand them (:func:`constraint_citations`) and provenance.  ``said``, the text as the
    user wrote it, is recorded (``provenance.said``) where the task's instruction is not all of
    it (sentences set aside as naming nothing of the task), and accounted for."""
    said = said.strip() if said else None
    doc = {
        "schema": json.loads(schema.model_dump_json()),
        "tags": schema.tags(),
        "accounting": mention_accounting(schema, said),
        "citations": constraint_citations(schema),
        "provenance": {
            "instruction": schema.instruction,
            "compiler_version": __version__,
            "backend": backend,
            "model": model,
            "seed": seed,
            "repairs": [r.model_dump() for r in schema.repairs],
            "gates": {g["gate"]: g["status"] for g in gates},
        },
    }
    if author:  # recorded only when known, so a library built without authors keeps its hashes
        doc["provenance"]["author"] = author
    if said and said != schema.instruction:  # recorded only when it differs, so the library keeps its hashes
        doc["provenance"]["said"] = said
    return doc


def write_artifact_files(directory: Path, schema: TaskSchema, seed: int, backend: str, model: str | None,
                         gates: list[dict], log: list[str], author: str | None = None,
                         extra_files: dict[str, str] | None = None, said: str | None = None) -> tuple[str, dict]:
    """Write the ``extra_files`` (name -> text: the model record ``llm_log.jsonl``),
    validation.log and validation.json beside the code, then task.yaml with the manifest of
    every file (written last); return the content hash (it covers the model record) and the
    task document written."""
    directory = Path(directory)
    for fname, text in sorted((extra_files or {}).items()):
        if fname == TASK_FILE or Path(fname).name != fname:
            raise ValueError(f"an extra artifact file must be a plain name other than {TASK_FILE}, not {fname!r}")
        write_file(directory / fname, text)
    _write_logs(directory, log, gates)
    sources = task_sources(directory)
    doc = task_document(schema, seed, backend, model, gates, author, said)
    digest = content_hash(doc, sources["code.py"], sources["goal_state_code.py"], model_record(directory))
    doc[MANIFEST_KEY] = file_manifest(directory)
    doc["content_hash"] = digest
    write_file(directory / TASK_FILE, yamlio.dump(doc))
    return digest, doc


def write_logs(directory: Path, log: list[str], gates: list[dict]) -> None:
    """Rewrite an artifact's ``validation.log`` and ``validation.json`` (``rpg validate``)
    and record them in task.yaml's manifest."""
    _write_logs(directory, log, gates)
    record_files(directory, ["validation.log", "validation.json"])


def _write_logs(directory: Path, log: list[str], gates: list[dict]) -> None:
    """``validation.log`` (one line per gate and repair attempt) and ``validation.json``."""
    write_file(directory / "validation.log", "\n".join(log) + "\n")
    write_file(directory / "validation.json", json.dumps(
        {"created": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "valid": gates_passed(gates), "log": log, "gates": gates},
        indent=2, default=str) + "\n")


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def staging_dir(parent: Path, name: str) -> Path:
    """A new hidden directory ``parent/.tmp-<name>-*`` to write an artifact into before it is
    published with :func:`atomic_replace`; its mode follows the umask like a plain mkdir."""
    tmp = Path(tempfile.mkdtemp(prefix=f".tmp-{name[:40]}-", dir=parent))
    os.chmod(tmp, 0o777 & ~_umask())
    return tmp


LIBRARY_LOCK = ".rpg.lock"
"""Lock file in a library directory: serializes the renames that publish task directories."""


def atomic_replace(tmp: Path, target: Path) -> None:
    """Publish ``tmp`` as ``target`` by rename (the old ``target``, if any, goes to the
    trash first), under the directory's file lock so concurrent writers never interleave."""
    from filelock import FileLock

    target.parent.mkdir(parents=True, exist_ok=True)
    with FileLock(str(target.parent / LIBRARY_LOCK), timeout=600):
        if target.exists():
            trash = target.parent / f".trash-{target.name}-{os.getpid()}"
            os.rename(target, trash)
            os.rename(tmp, target)
            shutil.rmtree(trash, ignore_errors=True)
        else:
            os.rename(tmp, target)


def load_artifact(directory: str | Path) -> tuple[TaskSchema, dict]:
    """Read an artifact's schema and provenance.

    Raises:
        ArtifactError: missing files, malformed YAML or an invalid schema.
    """
    d = Path(directory)
    for fname in ("task.yaml", "code.py", "goal_state_code.py"):
        if not (d / fname).is_file() and not (d / fname).is_symlink():
            raise ArtifactError(f"{d} is not a task artifact: {fname} is missing")
    text = read_text(d / "task.yaml")
    try:
        doc = yamlio.load(text)
        schema = TaskSchema.model_validate(doc["schema"])
    except Exception as exc:  # noqa: BLE001 - any parse problem means a malformed artifact
        raise ArtifactError(f"{d / 'task.yaml'} is malformed: {str(exc).splitlines()[0][:200]}") from None
    return schema, doc
