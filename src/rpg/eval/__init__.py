"""``rpg eval``: run any policy on compiled tasks and families and report success with its
uncertainty (paper, "Evaluating Policies on Training and Generated Generalization Tasks")."""

from rpg.eval.policies import PolicyError, load_policy
from rpg.eval.runner import EvalConfig, run_eval
from rpg.eval.stats import compare_runs, summarize, wilson_interval

__all__ = ["EvalConfig", "PolicyError", "compare_runs", "load_policy", "run_eval", "summarize", "wilson_interval"]
