"""The validation gates, in the order they run (paper, "Validation and Physical Realizability")."""

GATES = ("text", "compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility")
"""Gate names: text (static checks), compile (import and instantiate), smoke (reset, 10 zero-action
steps), nontrivial (G false at reset), constraint (support graph), goal_state (settle, G holds and
stays stable), bounds (workspace), visibility (labels visible and readable)."""


def check_gate_names(names) -> frozenset[str]:
    """``names`` as a frozenset if every one is a gate (a typo would silently run every gate).

    Raises:
        BadInput: a name that is not in :data:`GATES`.
    """
    from rpg.errors import BadInput

    unknown = sorted(set(names) - set(GATES))
    if unknown:
        raise BadInput(f"--disable {unknown[0]!r} is not a gate; gates: {', '.join(GATES)}")
    return frozenset(names)
