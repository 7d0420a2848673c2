"""The JSON-lines logs a demonstration dataset keeps (``meta/episodes.jsonl``, ``meta/rpg_attempts.jsonl``
...), shared by the LeRobot and robomimic writers (:mod:`rpg.jsonl`: appended one fsynced line
at a time, a line is a commit; read up to a torn last line; rewritten atomically)."""

from __future__ import annotations

from pathlib import Path

from rpg.demos.record import Episode
from rpg.jsonl import append_jsonl


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
