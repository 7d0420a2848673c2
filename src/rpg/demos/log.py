"""The JSON-lines logs a demonstration dataset keeps (``meta/episodes.jsonl``, ``meta/rpg_attempts.jsonl``
...), shared by the LeRobot and robomimic writers (:mod:`rpg.jsonl`: appended one fsynced line
at a time, a line is a commit; read up to a torn last line; rewritten atomically).

An episode that will be committed has its attempt logged *before* its commit, marked ``kept``:
a kill between the two leaves a kept attempt with no committed episode, which
:func:`settle_attempts` drops when the dataset is reopened (so the rerun records the episode
and its attempt again, in the order an unkilled run writes them).  Logging after the commit
instead would lose the attempt of an episode committed just before a kill.
"""

from __future__ import annotations

from pathlib import Path

from rpg.demos.record import Episode
from rpg.jsonl import append_jsonl, read_jsonl, rewrite_jsonl

ATTEMPTS = "rpg_attempts.jsonl"


def _key(record: dict) -> tuple:
    return record["task_hash"], record["seed"], record["instruction"]


def attempt_record(ep: Episode, kept: bool) -> dict:
    """The ``rpg_attempts.jsonl`` line of an episode, failed or not (a resumed run skips its seed);
    ``kept``: whether the episode is committed to the dataset."""
    return {"task_hash": ep.task_hash, "seed": ep.seed, "instruction": ep.instruction,
            "success": ep.success, "steps": ep.length, "failure": ep.failure, "kept": kept}


def log_attempt(meta: Path, attempts: list[dict], ep: Episode, kept: bool = True) -> None:
    """Append an episode's attempt to ``meta/rpg_attempts.jsonl`` and to ``attempts`` (before the
    commit of a kept episode)."""
    record = attempt_record(ep, kept)
    append_jsonl(meta / ATTEMPTS, record)
    attempts.append(record)


def settle_attempts(meta: Path, committed: list[dict]) -> list[dict]:
    """Read ``meta/rpg_attempts.jsonl`` without the kept attempts whose episode was never committed
    (a kill between the attempt and the commit), rewrite it so, and return its records.

    Args:
        meta: the dataset's ``meta`` directory.
        committed: the committed episodes' rows (``task_hash``, ``seed``, ``instruction``).
    """
    done = {_key(row) for row in committed}
    attempts = [a for a in read_jsonl(meta / ATTEMPTS) if not a.get("kept") or _key(a) in done]
    rewrite_jsonl(meta / ATTEMPTS, attempts)
    return attempts


def attempted(attempts: list[dict], committed: list[dict]) -> set[tuple]:
    """The attempts already made, as ``(task_hash, seed, instruction)``: a resumed run skips them."""
    return {_key(a) for a in attempts} | {_key(row) for row in committed}


def discard_failed(meta: Path, attempts: list[dict], ep: Episode) -> bool:
    """For a failed episode, delete its frame files and log its attempt; whether it failed."""
    if ep.success:
        return False
    for v in ep.videos.values():
        Path(v).unlink(missing_ok=True)
    log_attempt(meta, attempts, ep, kept=False)
    return True
