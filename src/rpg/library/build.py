"""``rpg build``: (re)generate a task library from its manifest, in parallel.

A manifest (``library/manifest.yaml``) lists entries; each is a task (an instruction) or
a family (a session file, run as ``rpg session run`` does), with a seed and the content
hash it must regenerate to (for a family: the lineage hash of its last version, which
chains every version's content hash).  Entries are built in a temporary directory; with
``check`` their hashes are compared with the manifest's, otherwise the changed ones are
moved into the manifest's directory (see :func:`build_library`).

Backends (:mod:`rpg.parallel`): ``local`` (a process pool; each worker process imports the
compiler once and starts a fresh sandboxed child per task-code run, :mod:`rpg.validate.sandbox`)
and ``ray`` (the same work as Ray tasks, on a running cluster with ``address="auto"`` or a
local one; ``pip install rpg[ray]``).
"""

from __future__ import annotations

import json
import os
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from rpg import yamlio
from rpg.errors import BadInput


class ManifestError(BadInput):
    """A manifest that cannot be read; the message says what is wrong."""


class Entry(BaseModel):
    """One library entry."""

    model_config = ConfigDict(extra="forbid")

    name: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    instruction: str | None = None
    session: str | None = Field(None, description="Session YAML, relative to the manifest.")
    seed: int = 0
    author: str | None = Field(None, description="Who wrote the entry (groups `rpg diversity --by author`).")
    content_hash: str | None = None
    split: str | None = Field(None, pattern=r"^[a-z][a-z0-9_-]*$", description=(
        "Evaluation split (e.g. train / eval, the paper's training and generalization tasks); "
        "`rpg eval` groups by it and selects it with split=NAME."))
    waive: dict[str, str] = Field(default_factory=dict, description=(
        "Optional gates this entry is built without, each with the reason (e.g. solvable: the "
        "oracle lacks the primitive); shown by `rpg build` and the gallery."))

    @model_validator(mode="after")
    def _one_source(self) -> Entry:
        if (self.instruction is None) == (self.session is None):
            raise ValueError(f"entry {self.name!r} needs exactly one of 'instruction' or 'session'")
        from rpg.validate.gates import OPTIONAL_GATES

        unknown = sorted(set(self.waive) - set(OPTIONAL_GATES))
        if unknown:
            raise ValueError(f"entry {self.name!r} waives {unknown[0]!r}, which is not an optional gate "
                             f"({', '.join(OPTIONAL_GATES)})")
        if any(not str(why).strip() for why in self.waive.values()):
            raise ValueError(f"entry {self.name!r}: a waived gate needs its reason")
        return self

    @property
    def gates(self) -> frozenset[str]:
        """The optional gates this entry is built with: all but the waived ones."""
        from rpg.validate.gates import OPTIONAL_GATES

        return frozenset(g for g in OPTIONAL_GATES if g not in self.waive)

    @property
    def kind(self) -> str:
        return "family" if self.session else "task"


class Manifest(BaseModel):
    """``manifest.yaml``: the entries of a library."""

    model_config = ConfigDict(extra="forbid")

    entries: list[Entry]

    @model_validator(mode="after")
    def _unique(self) -> Manifest:
        names = [e.name for e in self.entries]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise ValueError(f"duplicate entry names: {', '.join(dup)}")
        return self


def load_manifest(path: str | Path) -> Manifest:
    """Read and check a manifest.

    Raises:
        ManifestError: unreadable YAML or entries that do not validate.
    """
    try:
        return Manifest.model_validate(yamlio.load(Path(path).read_text()))
    except ValidationError as exc:
        where = "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in exc.errors()[:3])
        raise ManifestError(f"manifest {path} is invalid: {where}") from None
    except (OSError, yaml.YAMLError, TypeError) as exc:
        raise ManifestError(f"cannot read manifest {path}: {str(exc).splitlines()[0][:300]}") from None


def save_manifest(path: str | Path, manifest: Manifest, header: str = "") -> None:
    """Write the manifest atomically."""
    path = Path(path)
    doc = manifest.model_dump(exclude_none=True)
    for entry in doc["entries"]:
        if not entry.get("waive"):
            entry.pop("waive", None)
    text = header + yamlio.dump(doc, width=120)
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    tmp.write_text(text)
    os.replace(tmp, path)


def build_entry(entry: dict, out_dir: str, base_dir: str) -> dict:
    """Build one entry into ``out_dir`` with every optional gate on but those the entry waives
    (a library task must be solvable by the oracle); a JSON-ready report (never raises)."""
    from rpg.artifact import load_artifact
    from rpg.compiler import compile_instruction

    e = Entry.model_validate(entry)
    t0 = time.perf_counter()
    report: dict = {"name": e.name, "kind": e.kind, "expected": e.content_hash, "waived": dict(e.waive)}
    try:
        if e.kind == "task":
            r = compile_instruction(e.instruction, out_dir, e.seed, name=e.name, author=e.author, enabled=e.gates)
            report.update(status="valid" if r.valid else "rejected", content_hash=r.content_hash,
                          repairs=[x.operator for x in r.schema.repairs],
                          gates={g["gate"]: g["status"] for g in r.gates}, path=str(r.path))
        else:
            from rpg.steer.family import Family
            from rpg.steer.session import run_session

            fam, steps = run_session(Path(base_dir) / e.session, out_dir, e.seed, name=e.name, enabled=e.gates)
            hist = Family(fam).load()
            repairs = []
            for v in hist.versions:
                repairs += [x.operator for x in load_artifact(Family(fam).version_dir(v.version_id))[0].repairs]
            ok = all(s.ok for s in steps)
            report.update(status="valid" if ok else "rejected", content_hash=hist.digest(),
                          repairs=repairs, versions=len(hist.versions), path=str(fam),
                          problems=[p for s in steps for p in s.problems])
    except Exception as exc:  # noqa: BLE001 - one entry's failure is reported, the batch goes on
        report.update(status="error", content_hash=None, error=f"{type(exc).__name__}: {exc}")
    report["duration_s"] = round(time.perf_counter() - t0, 3)
    report["changed"] = bool(e.content_hash) and report.get("content_hash") != e.content_hash
    return report


def _start_worker() -> None:
    """Pool-worker initializer: this worker dies with the build (kill -9 of ``rpg build``
    leaves no worker behind) and imports the compiler once."""
    from rpg.validate.isolation import die_with_parent

    die_with_parent()
    import rpg.compiler  # noqa: F401
    import rpg.steer.session  # noqa: F401


def _recorded_seconds(entry_dir: Path) -> float:
    """Seconds the gates of an entry's last build took, from its ``validation.json`` files
    (each version's, for a family); 0.0 where none is readable."""
    total = 0.0
    for f in sorted(entry_dir.glob("**/validation.json")):
        try:
            gates = json.loads(f.read_text()).get("gates", [])
            total += sum(float(g.get("duration_s", 0.0)) for g in gates if isinstance(g, dict))
        except (OSError, ValueError, AttributeError, TypeError):
            continue
    return total


def _longest_first(entries: list[dict], base: Path) -> list[dict]:
    """The entries longest first, so that no long entry starts last and holds the build up
    alone: by the seconds their last build recorded, then families (several compiles each)
    before single tasks, then the manifest's order."""
    return sorted(entries, key=lambda e: (-_recorded_seconds(base / e["name"]), e.get("session") is None))


def _built(entries: list[dict], out_dir: str, base_dir: str, jobs: int, backend: str,
           address: str | None) -> Iterator[dict]:
    """Each entry's report, as it is built (:func:`rpg.parallel.open_backend`: one job builds in
    this process; a pool's forked workers inherit the compiler imported here)."""
    from functools import partial

    from rpg.parallel import open_backend

    if jobs > 1:
        import rpg.compiler  # noqa: F401 - imported once here, inherited by the forked workers
        import rpg.steer.session  # noqa: F401
    with open_backend(backend, jobs, address, initializer=_start_worker, mp_context=None) as runner:
        order = _longest_first(entries, Path(base_dir))
        yield from runner.imap(partial(build_entry, out_dir=out_dir, base_dir=base_dir), order)


STALE_TEMPORARY_S = 6 * 3600.0
"""Age after which a build's leftover temporary directory (its process killed) is removed, s."""


def remove_stale_temporaries(base: Path, max_age_s: float = STALE_TEMPORARY_S) -> list[str]:
    """Delete ``.rpg-build-*``, ``.tmp-*`` and ``.trash-*`` directories in ``base`` (left by
    killed builds) that are older than ``max_age_s``; their names."""
    import shutil

    gone = []
    now = time.time()
    for d in sorted(base.glob(".rpg-build-*")) + sorted(base.glob(".tmp-*")) + sorted(base.glob(".trash-*")):
        try:
            if d.is_dir() and not d.is_symlink() and now - d.stat().st_mtime > max_age_s:
                shutil.rmtree(d, ignore_errors=True)
                gone.append(d.name)
        except OSError:
            continue
    return gone


def build_library(manifest_path: str | Path, jobs: int = 1, backend: Literal["local", "ray"] = "local",
                  check: bool = False, address: str | None = None,
                  progress: Callable[[dict], None] | None = None, force: bool = False) -> tuple[list[dict], float]:
    """Build (or, with ``check``, regenerate and compare) every entry; (reports, seconds).

    Entries are built in a temporary directory.  Without ``check``, each built entry is then
    published beside the manifest (one atomic rename) unless the library already holds it
    with the same hash, recomputed from its files: an unchanged entry keeps its files, so a
    rebuild after a compiler change touches, in git, only what changed (``force`` rewrites
    them all, e.g. to refresh snapshots after a renderer change).  Rejected tasks go to
    ``.rejected/``.  The manifest's hashes are updated to what was built.  With ``check``
    nothing in the library changes, and each committed entry is hashed from its files too
    (``library_hash``): an entry edited in place is ``changed`` even when it regenerates
    to the manifest's hash.  Each report says whether the entry was ``written``.

    Raises:
        ManifestError: an unreadable manifest.
        rpg.parallel.BackendError: an unknown or unavailable backend (Ray not installed, its
            cluster unreachable).
    """
    manifest_path = Path(manifest_path)
    manifest = load_manifest(manifest_path)
    base = manifest_path.resolve().parent
    if not check:
        remove_stale_temporaries(base)
    entries = [e.model_dump() for e in manifest.entries]
    t0 = time.perf_counter()
    # In place, the build directory sits in the library so that publishing is a rename.
    with tempfile.TemporaryDirectory(prefix=".rpg-build-", dir=None if check else base) as tmp:
        runner = _built(entries, tmp, str(base), jobs, backend, address)
        reports = []
        for rep in runner:
            if not check:
                _publish(rep, Path(tmp), base, force)
            reports.append(rep)
            if progress:
                progress(rep)
    order = {e["name"]: i for i, e in enumerate(entries)}
    reports.sort(key=lambda r: order[r["name"]])
    if check:  # the committed library itself must still be what the manifest says
        for rep in reports:
            rep["library_hash"] = _recorded_hash(base / rep["name"])
            if rep.get("expected") and rep["library_hash"] != rep["expected"]:
                rep["changed"] = True
                rep.setdefault("problems", []).append(
                    "the committed library entry differs from the manifest (files edited, or hashes no longer match)")
    if not check:
        by_name = {r["name"]: r for r in reports}
        for e in manifest.entries:
            if by_name[e.name]["status"] == "valid":
                e.content_hash = by_name[e.name]["content_hash"]
        save_manifest(manifest_path, manifest, _header(manifest_path))
    return reports, time.perf_counter() - t0


def _publish(report: dict, tmp: Path, base: Path, force: bool) -> None:
    """Move one built entry from ``tmp`` into the library ``base`` unless the library holds
    it unchanged; sets ``report["written"]`` and points ``report["path"]`` at the library."""
    from rpg.artifact import atomic_replace

    report["written"] = False
    if not report.get("path"):
        return
    rel = Path(report["path"]).relative_to(tmp)
    if rel.parts != (report["name"],) and rel.parts != (".rejected", report["name"]):
        raise ManifestError(f"entry {report['name']!r} was built at {rel}, outside its own directory")
    target = base / rel
    report["path"] = str(target)
    if report["status"] == "valid" and not force and _recorded_hash(target) == report["content_hash"]:
        return
    atomic_replace(tmp / rel, target)
    report["written"] = True


def _recorded_hash(path: Path) -> str | None:
    """The hash of the task artifact or family at ``path``, recomputed from its files; None
    when there is none or its files no longer match their recorded hashes (the content hash
    or the file manifest)."""
    from rpg.artifact import ArtifactError, check_files, rehash
    from rpg.steer.family import Family, is_family

    try:
        if is_family(path):
            family = Family(path)
            intact = all(v["ok"] for v in family.verify())
            return family.load().digest() if intact else None
        _, doc, _, digest = rehash(path)
        return digest if digest == doc.get("content_hash") and not check_files(path, doc) else None
    except (ArtifactError, OSError, ValueError, KeyError, IndexError):
        return None


def _header(path: Path) -> str:
    lines = []
    for line in path.read_text().splitlines():
        if not line.startswith("#"):
            break
        lines.append(line)
    return "\n".join(lines) + "\n" if lines else ""
