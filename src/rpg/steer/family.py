"""Task families: versioned task artifacts with git-like lineage.

A family is a directory::

    FAMILY/
      family.yaml      # FamilyHistory: one TaskSnapshot per version, and the head
      v0/ v1/ ...      # each a complete task artifact, as ``rpg compile`` writes it
      .rejected/vN/    # a steered version that failed validation, kept for inspection

Paper, appendix "Version History Representation".  Hashes:

* ``content_hash``: the artifact's hash (task.yaml fields, both code files and the model
  record ``llm_log.jsonl`` when there is one), chained by the lineage hash.
* ``code_hash``: SHA-256 of the version's code files as they are on disk (``code.py``, a
  NUL byte, ``goal_state_code.py``).
* ``task_hash``: SHA-256 of the code generated from the version's schema with its language
  (name, instruction, paraphrases, summary) blanked and its assets in name order, so two
  versions that define the same task share it whatever words produced them; steering uses
  it to detect loops.  (Histories written before it existed kept this hash in
  ``code_hash``; they still verify.)
* ``lineage_hash``: SHA-256 over the content hash, the parent's lineage hash and the
  snapshot's own recorded fields, so a changed file *or* a changed history entry breaks
  the chain from that version on (:meth:`Family.verify`).
* ``files``: SHA-256 of every file of the version (logs, snapshots, model records too),
  checked by :meth:`Family.verify` but not chained (logs carry times; snapshots depend on
  the renderer).  Each version's task.yaml records the same files in its own manifest
  (:func:`rpg.artifact.check_files`), which :meth:`Family.verify` checks too: a changed,
  missing or unexpected file is named.  What is chained, the content hash, covers every
  file anything is built or run from (task.yaml, the code, the model record).
* :meth:`FamilyHistory.digest`: SHA-256 over the family's name, head and every lineage
  hash: the one hash a library manifest records and ``rpg verify --expect`` compares, so
  a dropped newest version, a moved head or a renamed family are caught too.

What a hash chain without a key proves: that the files and the history agree with each
other.  Whoever can write the family can recompute every hash, so a forgery is caught only
against a hash kept elsewhere (``rpg verify --expect HASH`` with the manifest's value).

Writes are atomic (temporary file or directory, then rename) and serialized by a file lock.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import tempfile
import time
from pathlib import Path
from typing import Literal

import yaml
from filelock import FileLock
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from rpg import yamlio
from rpg.artifact import (
    FILES_CHANGED,
    ArtifactError,
    atomic_replace,
    check_files,
    load_artifact,
    read_bytes,
    read_text,
    rehash,
    staging_dir,
    task_sources,
)
from rpg.errors import BadInput
from rpg.schema.model import TaskSchema

HISTORY_FILE = "family.yaml"
LOCK_FILE = ".family.lock"
LOCK_TIMEOUT_S = 600.0
"""Longest wait for another process steering the same family, s."""


class FamilyError(BadInput):
    """A family directory or its history is missing, corrupt or does not verify."""


class TaskSnapshot(BaseModel):
    """One version of a task family (immutable once recorded)."""

    model_config = ConfigDict(extra="forbid")

    version_id: int = Field(ge=0, description="Sequential id, 0 = the base task.")
    description: str = Field(description="What changed: the edit, or the base instruction.")
    instruction: str = Field(description="Canonical instruction the version was compiled from.")
    assets_used: list[str] = Field(description="Asset class names, e.g. ['ColoredCube', 'SemanticCube'].")
    goal_summary: str
    code_hash: str
    content_hash: str
    parent: int | None = Field(description="Version it descends from (its reference; the previous head for Fresh).")
    reference: int | None = Field(description="Version whose task the edit was applied to; None for base and Fresh.")
    intent: Literal["base", "tweak", "extend", "modify", "pivot", "fresh"]
    parameters: dict = Field(default_factory=dict)
    preserve_assets: bool = False
    preserve_positions: bool = False
    preserve_goals: bool = False
    lineage_hash: str = ""
    task_hash: str = Field("", description="Language-blanked task hash (loop detection); hashed when set.")
    files: dict[str, str] = Field(default_factory=dict, description="File name -> SHA-256 (verified, not chained).")
    created: str = Field("", description="UTC time recorded (not hashed).")
    author: str | None = Field(None, description="Who wrote the edit (from the version's task.yaml provenance); "
                                                 "hashed when known, absent when not.")

    def record_digest(self) -> str:
        doc = self.model_dump(exclude={"lineage_hash", "created", "files"} | (set() if self.author else {"author"})
                              | (set() if self.task_hash else {"task_hash"}))
        return hashlib.sha256(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


class FamilyHistory(BaseModel):
    """The history file of a family."""

    model_config = ConfigDict(extra="forbid")

    format: int = 1
    name: str
    head: int = Field(ge=0, description="The current version: the latest one steered to or looped back to.")
    versions: list[TaskSnapshot]

    def digest(self) -> str:
        """SHA-256 over the name, the head and every version's lineage hash, in order."""
        doc = {"name": self.name, "head": self.head, "lineage": [v.lineage_hash for v in self.versions]}
        return hashlib.sha256(json.dumps(doc, sort_keys=True, separators=(",", ":")).encode()).hexdigest()

    def get(self, version_id: int) -> TaskSnapshot:
        for v in self.versions:
            if v.version_id == version_id:
                return v
        raise FamilyError(f"version v{version_id} does not exist; versions are v0..v{len(self.versions) - 1}")


def lineage_hash(snapshot: TaskSnapshot, parent_lineage: str | None) -> str:
    """SHA-256 over the content hash, the parent's lineage hash and the snapshot's fields."""
    payload = f"{snapshot.content_hash}\n{parent_lineage or ''}\n{snapshot.record_digest()}"
    return hashlib.sha256(payload.encode()).hexdigest()


def code_hash(sources: dict[str, str]) -> str:
    """SHA-256 of a version's code files as read (see module doc)."""
    return hashlib.sha256((sources["code.py"] + "\0" + sources["goal_state_code.py"]).encode()).hexdigest()


def file_hashes(directory: Path) -> dict[str, str]:
    """SHA-256 of every regular file of a version directory, by name (links refused).

    Raises:
        ArtifactError: a link or an unreadable file.
    """
    out = {}
    for f in sorted(Path(directory).iterdir()):
        if f.is_symlink() or f.is_dir():
            if f.is_symlink():
                raise ArtifactError(f"{f} is a symbolic link; artifact files must be regular files")
            continue
        if f.name.startswith("."):
            continue
        out[f.name] = hashlib.sha256(read_bytes(f, 256 * 1024**2)).hexdigest()
    return out


def task_hash(schema: TaskSchema) -> str:
    """SHA-256 of the code generated for a schema's task, its language blanked (see module doc)."""
    from rpg.codegen import generate

    bare = schema.model_copy(update={"name": "task", "instruction": "", "paraphrases": ["", "", ""],
                                     "goal_summary": "", "repairs": [],
                                     "assets": sorted(schema.assets, key=lambda a: a.name)})
    code = generate(bare)
    return hashlib.sha256((code.code + "\0" + code.goal_state_code).encode()).hexdigest()


def _now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


def is_family(path: Path) -> bool:
    return (Path(path) / HISTORY_FILE).is_file()


class Family:
    """A family directory: its history, its versions, verification and the write lock."""

    def __init__(self, path: str | Path):
        self.path = Path(path)

    # -- reading ---------------------------------------------------------------
    def load(self) -> FamilyHistory:
        """The history.

        Raises:
            FamilyError: not a family, or a corrupt history file.
        """
        f = self.path / HISTORY_FILE
        if not f.is_file():
            raise FamilyError(f"{self.path} is not a task family ({HISTORY_FILE} is missing); "
                              "create one with 'rpg compile ... --family' or steer a compiled task")
        try:
            hist = FamilyHistory.model_validate(yamlio.load(read_text(f)))
        except (yaml.YAMLError, ValidationError, TypeError, ArtifactError) as exc:
            first = str(exc).splitlines()[0][:200]
            raise FamilyError(f"{f} is corrupt: {first}") from None
        if [v.version_id for v in hist.versions] != list(range(len(hist.versions))) or not hist.versions:
            raise FamilyError(f"{f} is corrupt: version ids must run v0, v1, ... without gaps")
        if hist.head >= len(hist.versions):
            raise FamilyError(f"{f} is corrupt: head v{hist.head} does not exist")
        return hist

    def version_dir(self, version_id: int) -> Path:
        return self.path / f"v{version_id}"

    def schema(self, version_id: int) -> TaskSchema:
        return load_artifact(self.version_dir(version_id))[0]

    def resolve(self, ref: str | None) -> TaskSnapshot:
        """A version by ``v3``, ``3``, ``head`` or a prefix (>= 4 hex digits) of its lineage,
        content or code hash.

        Raises:
            FamilyError: no such version, or an ambiguous prefix.
        """
        hist = self.load()
        if ref in (None, "", "head", "current"):
            return hist.get(hist.head)
        m = re.fullmatch(r"v(\d+)|(\d{1,3})", ref.strip())
        if m:
            return hist.get(int(m.group(1) or m.group(2)))
        pre = ref.strip().lower()
        if len(pre) < 4 or not re.fullmatch(r"[0-9a-f]+", pre):
            raise FamilyError(f"cannot resolve {ref!r}: use v<N> or a hash prefix of at least 4 hex digits")
        found = [v for v in hist.versions if any(h.startswith(pre) for h in (v.lineage_hash, v.content_hash, v.code_hash))]
        if len(found) != 1:
            raise FamilyError(f"hash prefix {ref!r} matches {len(found)} versions; give more digits" if found
                              else f"no version has a hash starting with {ref!r}")
        return found[0]

    # -- writing ---------------------------------------------------------------
    def lock(self) -> FileLock:
        return FileLock(str(self.path / LOCK_FILE), timeout=LOCK_TIMEOUT_S)

    def save(self, hist: FamilyHistory) -> None:
        """Write the history atomically."""
        doc = hist.model_dump()
        for v in doc["versions"]:
            if v.get("author") is None:
                v.pop("author", None)  # histories without authors read as before
        text = yamlio.dump(doc)
        fd, tmp = tempfile.mkstemp(prefix=".family-", suffix=".yaml", dir=self.path)
        with os.fdopen(fd, "w") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, self.path / HISTORY_FILE)

    def remove_orphans(self, hist: FamilyHistory) -> list[str]:
        """Delete version directories the history does not record (left by a killed steer)."""
        known = {f"v{v.version_id}" for v in hist.versions}
        gone = []
        for d in sorted(self.path.iterdir()):
            if d.is_dir() and (re.fullmatch(r"v\d+", d.name) and d.name not in known or d.name.startswith(".tmp-")):
                shutil.rmtree(d, ignore_errors=True)
                gone.append(d.name)
        return gone

    # -- verification ------------------------------------------------------------
    def verify(self) -> list[dict]:
        """Recompute every hash; one entry per version: ``{"version", "ok", "problems"}``.

        Raises:
            FamilyError: the history file itself is missing or corrupt.
        """
        hist = self.load()
        by_id = {v.version_id: v for v in hist.versions}
        out = []
        for v in hist.versions:
            problems = []
            d = self.version_dir(v.version_id)
            try:
                schema, doc, sources, actual = rehash(d)
                if actual != doc.get("content_hash"):
                    problems.append(FILES_CHANGED)
                problems += check_files(d, doc)
                if actual != v.content_hash:
                    problems.append("artifact does not match the content hash recorded in the history")
                if v.task_hash:
                    if code_hash(sources) != v.code_hash:
                        problems.append("code files do not match the recorded code hash")
                    if task_hash(schema) != v.task_hash:
                        problems.append("task schema does not match the recorded task hash")
                elif task_hash(schema) != v.code_hash:  # a history from before task_hash
                    problems.append("task schema does not match the recorded code hash")
                if v.files:
                    current = file_hashes(d)
                    changed = sorted(n for n in set(v.files) | set(current) if v.files.get(n) != current.get(n))
                    if changed:
                        problems.append(f"files changed, added or removed since the version was recorded: {', '.join(changed)}")
            except (ArtifactError, OSError) as exc:
                problems.append(str(exc))
            parent = by_id.get(v.parent) if v.parent is not None else None
            if v.parent is not None and (parent is None or v.parent >= v.version_id):
                problems.append(f"parent v{v.parent} is not an earlier version")
            if lineage_hash(v, parent.lineage_hash if parent else None) != v.lineage_hash:
                problems.append("history entry or lineage altered (lineage hash differs)")
            out.append({"version": v.version_id, "ok": not problems, "problems": problems})
        return out


def verify_target(path: Path, expect: str | None = None) -> dict:
    """Verify a family or a plain task artifact; against ``expect`` (a manifest's hash) too.

    Returns:
        ``{"ok", "kind", "hash", "expected", "problems", "versions"}``: ``hash`` is the
        family's :meth:`FamilyHistory.digest` or the artifact's recomputed content hash.

    Raises:
        FamilyError / ArtifactError: not a family or artifact, or an unreadable history.
    """
    path = Path(path)
    problems: list[str] = []
    if is_family(path):
        fam = Family(path)
        versions = fam.verify()
        digest = fam.load().digest()
        kind = "family"
    else:
        _, doc, _, digest = rehash(path)
        if digest != doc.get("content_hash"):
            problems.append(FILES_CHANGED)
        problems += check_files(path, doc)
        versions, kind = [], "task"
    if expect is not None and digest != expect.strip().lower():
        problems.append(f"hash {digest[:16]}... differs from the expected {expect.strip()[:16]}... "
                        "(the history, head, name or files differ from the trusted copy)")
    ok = not problems and all(v["ok"] for v in versions)
    return {"ok": ok, "kind": kind, "hash": digest, "expected": expect, "problems": problems, "versions": versions}


def snapshot_of(directory: Path, version_id: int, description: str, parent: TaskSnapshot | None,
                reference: int | None, intent: str, parameters: dict, flags: dict[str, bool]) -> TaskSnapshot:
    """The TaskSnapshot of a compiled version directory, with its lineage hash."""
    schema, doc = load_artifact(directory)
    snap = TaskSnapshot(
        version_id=version_id, description=description, instruction=schema.instruction,
        assets_used=schema.assets_used(), goal_summary=schema.goal_summary,
        code_hash=code_hash(task_sources(directory)), task_hash=task_hash(schema), files=file_hashes(directory),
        content_hash=doc["content_hash"], parent=parent.version_id if parent else None, reference=reference,
        intent=intent, parameters=parameters, **flags, created=_now(),
        author=(doc.get("provenance") or {}).get("author"))
    snap.lineage_hash = lineage_hash(snap, parent.lineage_hash if parent else None)
    return snap


def create_family(artifact: str | Path) -> Family:
    """Turn a compiled task artifact into v0 of a new family, in place and atomically.

    Raises:
        ArtifactError: ``artifact`` is not a task artifact.
    """
    artifact = Path(artifact)
    schema, _ = load_artifact(artifact)
    tmp = staging_dir(artifact.parent, f"family-{artifact.name}")
    try:
        shutil.copytree(artifact, tmp / "v0", ignore=shutil.ignore_patterns("__pycache__"))
        snap = snapshot_of(tmp / "v0", 0, schema.instruction, None, None, "base", {}, {})
        fam = Family(tmp)
        fam.save(FamilyHistory(name=artifact.name, head=0, versions=[snap]))
        atomic_replace(tmp, artifact)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
    return Family(artifact)
