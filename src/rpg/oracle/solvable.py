"""Oracle episodes and the optional ``solvable`` validation gate (issue "oracle ... and a
``solvable`` gate": a task whose goal is stable but that no robot can build is a bad
evaluation task)."""

from __future__ import annotations

from dataclasses import dataclass

from rpg.domain import constants as C


@dataclass(frozen=True)
class OracleEpisode:
    """One oracle episode.

    Attributes:
        seed: the episode's seed (rho_0 sample).
        success: G held at the end (or the episode ended on success).
        steps: control steps taken.
        reason: why it failed (the oracle's own failure, a fragile-goal note, or the first
            unsatisfied predicate); None on success.
    """

    seed: int
    success: bool
    steps: int
    reason: str | None


def oracle_episode(env, oracle, seed: int) -> OracleEpisode:
    """Run ``oracle`` (an :class:`rpg.oracle.Oracle` of ``env``) for one episode from ``seed``.

    The episode ends on success, at the step limit, or as soon as the oracle reports that it
    gave up (``oracle.failure``): from then on it only holds still with the hand open, and a
    27-cube task would otherwise spend thousands of steps there (the ``solvable`` gate runs
    within the task worker's time limit)."""
    obs, info = env.reset(seed=int(seed))
    oracle.reset(obs)
    done, steps, truncated = False, 0, False
    while not done:
        obs, _, terminated, truncated, info = env.step(oracle.act(obs))
        steps += 1
        done = terminated or truncated or oracle.failure is not None
    if info["success"]:
        return OracleEpisode(int(seed), True, steps, None)
    notes = list(oracle.plan.notes) if oracle.plan else []
    first = "; ".join(info["diagnostics"]["unsatisfied"][:1])
    reason = oracle.failure or ("episode step limit reached" if truncated else "G not reached")
    return OracleEpisode(int(seed), False, steps, "; ".join([*notes, f"{reason}: {first}" if first else reason]))


def solvability(task, seed: int = 0, episodes: int = C.SOLVABLE_SEEDS,
                embodiment: str = C.SOLVABLE_EMBODIMENT, needed: int | None = None) -> dict:
    """The oracle's success on ``episodes`` seeds from ``seed``: the ``solvable`` gate's details.

    Args:
        task: what :class:`rpg.env.BlockTaskEnv` loads (a directory or a
            :class:`rpg.env.loading.TaskCode`).
        needed: stop once this many episodes succeeded, or once so many failed that this many
            can no longer succeed (the gate passes ``SOLVABLE_MIN_SUCCESS``: its verdict is then
            known, and the seeds left would only cost time, most on a pyramid's long episodes);
            None runs every seed (a measurement of the rate, as ``benchmarks/bench_oracle.py``).

    Returns:
        ``{"embodiment", "episodes", "successes", "rate", "failures": [{"seed", "reason"}]}``:
        ``episodes`` counts the episodes run, ``rate`` is successes per episode run.
    """
    from rpg.env import BlockTaskEnv
    from rpg.oracle.planner import Oracle

    env = BlockTaskEnv(task, embodiment=embodiment, cameras=())
    runs: list[OracleEpisode] = []
    try:
        oracle = Oracle(env)
        for k in range(episodes):
            ok = sum(r.success for r in runs)
            if needed is not None and (ok >= needed or ok + episodes - k < needed):
                break
            runs.append(oracle_episode(env, oracle, seed + k))
    finally:
        env.close()
    ok = sum(r.success for r in runs)
    return {"embodiment": embodiment, "episodes": len(runs), "successes": ok, "rate": ok / max(1, len(runs)),
            "failures": [{"seed": r.seed, "reason": r.reason} for r in runs if not r.success]}
