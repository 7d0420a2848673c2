"""The validation gates, in the order they run (paper, "Validation and Physical Realizability")."""

GATES = ("text", "compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility")
"""Gate names: text (static checks), compile (import and instantiate), smoke (reset, 10 zero-action
steps), nontrivial (G false at reset), constraint (support graph), goal_state (settle, G holds and
stays stable), bounds (workspace), visibility (labels visible and readable)."""
