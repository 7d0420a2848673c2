"""The validation gates, in the order they run (paper, "Validation and Physical Realizability")."""

GATES = ("text", "compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility")
"""Gate names: text (static checks), compile (import and instantiate), smoke (reset, 10 zero-action
steps), nontrivial (G false at reset), constraint (support graph), goal_state (settle, G holds and
stays stable), bounds (workspace), visibility (labels visible and readable).  Every valid task
passed these; an environment loads nothing else."""

OPTIONAL_GATES = ("solvable",)
"""Gates that run only when asked for (``--gate NAME``; ``rpg build`` asks for all of them):
solvable (the oracle, :class:`rpg.oracle.Oracle`, drives the floating gripper to success in at
least :data:`~rpg.domain.constants.SOLVABLE_MIN_SUCCESS` of
:data:`~rpg.domain.constants.SOLVABLE_SEEDS` episodes).  A task on which one ran must pass it
too; its result (the oracle's success rate) is in ``validation.json``."""


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


def check_optional_gates(names) -> frozenset[str]:
    """``names`` as a frozenset if every one is an optional gate (``--gate NAME``).

    Raises:
        BadInput: a name that is not in :data:`OPTIONAL_GATES`.
    """
    from rpg.errors import BadInput

    unknown = sorted(set(names) - set(OPTIONAL_GATES))
    if unknown:
        hint = " (it always runs)" if unknown[0] in GATES else ""
        raise BadInput(f"--gate {unknown[0]!r} is not an optional gate{hint}; optional gates: {', '.join(OPTIONAL_GATES)}")
    return frozenset(names)
