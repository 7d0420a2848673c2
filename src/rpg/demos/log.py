"""The JSON-lines logs a demonstration dataset keeps (``meta/episodes.jsonl``, ``meta/rpg_attempts.jsonl``
...), shared by the LeRobot and robomimic writers: appended one fsynced line at a time (a line is
a commit), read up to a torn last line, rewritten atomically."""

from __future__ import annotations

import json
import os
from pathlib import Path

from rpg.demos.record import Episode


def read_jsonl(path: Path) -> list[dict]:
    """Complete JSON lines of a file (a torn last line is ignored); [] when it does not exist."""
    if not path.is_file():
        return []
    out = []
    for line in path.read_text().splitlines():
        try:
            out.append(json.loads(line))
        except json.JSONDecodeError:
            break
    return out


def append_jsonl(path: Path, obj: dict) -> None:
    """Append one line and fsync it (the line is on disk when this returns)."""
    with open(path, "a") as fh:
        fh.write(json.dumps(obj, sort_keys=True) + "\n")
        fh.flush()
        os.fsync(fh.fileno())


def rewrite_jsonl(path: Path, rows: list[dict]) -> None:
    """Replace a file with ``rows``, one per line (a temporary file renamed over it)."""
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    tmp.write_text("".join(json.dumps(r, sort_keys=True) + "\n" for r in rows))
    os.replace(tmp, path)


def attempt_record(ep: Episode) -> dict:
    """The ``rpg_attempts.jsonl`` line of an episode, failed or not (a resumed run skips its seed)."""
    return {"task_hash": ep.task_hash, "seed": ep.seed, "instruction": ep.instruction,
            "success": ep.success, "steps": ep.length, "failure": ep.failure}


def log_attempt(meta: Path, attempts: list[dict], ep: Episode) -> None:
    """Append an episode's attempt to ``meta/rpg_attempts.jsonl`` and to ``attempts``."""
    record = attempt_record(ep)
    append_jsonl(meta / "rpg_attempts.jsonl", record)
    attempts.append(record)


def discard_failed(meta: Path, attempts: list[dict], ep: Episode) -> bool:
    """For a failed episode, delete its frame files and log its attempt; whether it failed."""
    if ep.success:
        return False
    for v in ep.videos.values():
        Path(v).unlink(missing_ok=True)
    log_attempt(meta, attempts, ep)
    return True
