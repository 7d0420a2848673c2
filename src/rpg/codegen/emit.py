"""The builtin code generator: an emitter over the TaskSchema IR, deterministic to the byte.

The task class is assembled from the schema's parts (assets, rho_0, predicate tree, goal
layout); predicates emit themselves through their ``repr``, which is the Python expression
that rebuilds them.  Only :mod:`rpg.task_api`, numpy and math are imported.

Text from outside the compiler (the instruction, paraphrases, a model's goal summary, names
and labels in a model's schema) reaches the source only as a ``repr`` literal: the
instruction is the class attribute ``INSTRUCTION``, never docstring or comment text.  The
docstrings hold generated text only (the snake_case name, fixed sentences, the numbers of
rho_0 and each goal predicate's ``describe()``), and even that passes :func:`doc_text`,
which keeps only characters that cannot end or escape a triple-quoted string.
"""

from __future__ import annotations

import re
import string
import textwrap
from dataclasses import dataclass

from rpg._version import __version__
from rpg.domain.predicates import Predicate
from rpg.schema.model import AssetSpec, TaskSchema


@dataclass(frozen=True)
class GeneratedCode:
    """The two generated files, as text."""

    code: str
    goal_state_code: str


DOC_CHARS = frozenset(string.ascii_letters + string.digits + " !#$%&'()*+,-./:;<=>?@[]^_`{|}~")
"""The characters :func:`doc_text` keeps: printable ASCII without the double quote and the
backslash, so no run of them can close a triple-quoted string, start an escape or a line."""


def doc_text(text: str) -> str:
    """``text`` made safe inside a triple-quoted docstring: every character outside
    :data:`DOC_CHARS` (quotes, backslashes, line breaks of any kind, NUL, non-ASCII) becomes ``?``."""
    return "".join(c if c in DOC_CHARS else "?" for c in str(text))


def class_name(task_name: str) -> str:
    """CamelCase class name of a snake_case task name (ASCII letters and digits only)."""
    camel = re.sub(r"[^0-9A-Za-z]", "", "".join(p.capitalize() for p in task_name.split("_") if p))[:60]
    return ("" if camel[:1].isalpha() else "Generated") + camel + "Task"


def _asset_expr(a: AssetSpec) -> str:
    if a.kind == "colored_cube":
        return f"ColoredCube({a.name!r}, color={a.color!r})"
    if a.kind == "semantic_cube":
        faces = f", faces={dict(sorted(a.faces.items()))!r}" if a.faces else ""
        return f"SemanticCube({a.name!r}, label={a.label!r}{faces})"
    shape = ", shape='long'" if a.shape == "long" else ""
    return f"GoalPatch({a.name!r}, color={a.color!r}{shape})"


def _goal_lines(goal: Predicate) -> list[str]:
    from rpg.domain.predicates import And

    if isinstance(goal, And):
        return ["return And(["] + [f"    {c!r}," for c in goal.children()] + ["])"]
    return [f"return {goal!r}"]


def _describe_goal(goal: Predicate) -> list[str]:
    return [f"- {doc_text(p.describe())}" for p in goal.conjuncts()]


def _imports(schema: TaskSchema, goal: Predicate) -> list[str]:
    names = {"BlockTask", "sample_scattered"}
    names |= {{"colored_cube": "ColoredCube", "semantic_cube": "SemanticCube", "goal_patch": "GoalPatch"}[a.kind]
              for a in schema.assets}
    names |= {type(p).__name__ for p in goal.walk()}
    if schema.initial_state.fixed or schema.initial_state.orientations:
        names.add("Pose")
    if schema.initial_state.orientations:
        names.add("quat_mul")
    return sorted(names)


def _goal_regions(goal: Predicate) -> dict[str, str]:
    """Object -> region for each ``InRegion`` the goal asserts (not under ``Not``): rho_0
    keeps those objects out of their regions, or G could hold at reset by chance."""
    from rpg.domain.predicates import InRegion

    out: dict[str, str] = {}
    for p in reversed(goal.conjuncts()):
        if isinstance(p, InRegion):
            out.setdefault(p.a, p.region)
    return dict(sorted(out.items()))


def _fmt(v: float) -> str:
    return repr(round(float(v), 6))


def _pose_expr(spec) -> str:
    pos = ", ".join(_fmt(v) for v in spec.position)
    quat = ", ".join(_fmt(v) for v in spec.quaternion)
    return f"Pose(({pos}), ({quat}))"


def generate(schema: TaskSchema) -> GeneratedCode:
    """Emit ``code.py`` and ``goal_state_code.py`` for a schema (deterministic)."""
    goal = schema.goal_predicate()
    init = schema.initial_state
    cls = class_name(schema.name)
    imports = _imports(schema, goal)
    rand = [
        f"- cube positions uniform in the workspace, centres at least {init.min_separation:.3f} m apart",
        f"- cube yaw uniform in [-{init.yaw_range:.3f}, {init.yaw_range:.3f}] rad",
    ]
    if init.structures:
        rand.append("- initial stacks (bottom to top): " + "; ".join(", ".join(s) for s in init.structures))
    if init.fixed:
        rand.append("- fixed (not sampled): " + ", ".join(sorted(init.fixed)))
    if init.orientations:
        rand.append("- initial orientation before yaw: " + ", ".join(sorted(init.orientations)))
    avoid = _goal_regions(goal)
    if avoid:
        rand.append("- starting outside its goal region: " + ", ".join(f"{n} ({r.replace('_', ' ')})" for n, r in avoid.items()))
    conditions = _describe_goal(goal)
    doc = "\n".join([
        f'"""{doc_text(schema.name)}: generated by rpg {doc_text(__version__)} from its TaskSchema (task.yaml).',
        "",
        "Task Description:",
        "    the class attribute INSTRUCTION (verbatim; PARAPHRASES are rewordings of it).",
        "",
        "Randomizations:",
        *("    " + doc_text(r) for r in rand),
        "",
        "Success Conditions:",
        *("    " + line for line in conditions),
        '"""',
    ])
    lines = [doc, "", "from rpg.task_api import (", *(f"    {n}," for n in imports), ")", "", ""]
    summary = textwrap.shorten("; ".join(c.removeprefix("- ") for c in conditions), 90, placeholder=" ...")
    lines += [f"class {cls}(BlockTask):", f'    """Success: {summary}"""', ""]
    lines += [f"    NAME = {schema.name!r}", f"    INSTRUCTION = {schema.instruction!r}", "    PARAPHRASES = ("]
    lines += [f"        {p!r}," for p in schema.paraphrases] + ["    )", ""]
    lines += ["    def assets(self):", "        return ["]
    lines += [f"            {_asset_expr(a)}," for a in schema.assets] + ["        ]", ""]
    lines += ["    def initial_state(self, rng):"]
    fixed = "{" + ", ".join(f"{n!r}: {_pose_expr(p)}" for n, p in sorted(init.fixed.items())) + "}"
    lines += ["        poses = sample_scattered(", "            rng,", "            list(self.scene.assets.values()),",
              f"            min_separation={_fmt(init.min_separation)},", f"            yaw_range={_fmt(init.yaw_range)},",
              f"            structures={[list(s) for s in init.structures]!r},", f"            fixed={fixed},",
              *([f"            avoid={avoid!r},"] if avoid else []), "        )"]
    for name, q in sorted(init.orientations.items()):
        qs = ", ".join(_fmt(v) for v in q)
        lines += [f"        poses[{name!r}] = Pose(poses[{name!r}].pos, quat_mul(poses[{name!r}].quat, ({qs})))"]
    lines += ["        return poses", "", "    def goal(self):"]
    lines += ["        " + ln for ln in _goal_lines(goal)]
    code = "\n".join(lines) + "\n"

    gdoc = f'"""Goal configuration of {doc_text(schema.name)}: poses (m; quaternion w, x, y, z) that satisfy G."""'
    glines = [gdoc, "", "from rpg.task_api import Pose", "", "GOAL_POSES = {"]
    glines += [f"    {n!r}: {_pose_expr(p)}," for n, p in sorted(schema.goal_layout.items())]
    glines += ["}", "", "", "def goal_state(task):", '    """Put the task\'s objects in the goal configuration."""',
               "    task.set_state(GOAL_POSES)", ""]
    return GeneratedCode(code=code, goal_state_code="\n".join(glines))
