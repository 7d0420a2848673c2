"""JSON-lines logs that a kill cannot corrupt: each record is one line, appended and fsynced
(the line is the commit), read back up to a torn last line, rewritten atomically.  Used by
``rpg eval`` (``episodes.jsonl``) and ``rpg demos`` (``meta/*.jsonl``)."""

from __future__ import annotations

import json
import os
from pathlib import Path


def read_complete(path: Path) -> tuple[list[dict], int]:
    """The records of the complete lines of ``path`` and the byte length they span: reading
    stops at the first line that is not JSON (a torn last line, from a kill mid-write); blank
    lines are skipped.  ``([], 0)`` when the file does not exist."""
    if not path.is_file():
        return [], 0
    raw = path.read_bytes()
    records, good = [], 0
    for line in raw.split(b"\n"):
        if line.strip():
            try:
                records.append(json.loads(line))
            except ValueError:
                break
        good += len(line) + 1
    return records, min(good, len(raw))


def read_jsonl(path: Path) -> list[dict]:
    """The records of the complete lines of ``path`` (see :func:`read_complete`)."""
    return read_complete(path)[0]


def cut_torn_line(path: Path) -> list[dict]:
    """Read ``path`` and truncate it after its last complete line (before a resumed run
    appends)."""
    records, good = read_complete(path)
    if path.is_file() and good < path.stat().st_size:
        with open(path, "r+b") as fh:
            fh.truncate(good)
    return records


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
