"""Each module-level name of the language modules is bound once: a second binding silently replaces the first for every
reader of the module (the forty-eighth session had redefined ``lexicon.LABEL_FILLER_WORDS`` and turned an identifier
label's fillers into another set; the forty-seventh had left a dead ``DIRECTION_SAID_RE``)."""

import ast
from pathlib import Path

import pytest

import rpg.schema

SCHEMA = Path(rpg.schema.__file__).parent
MODULES = sorted([*SCHEMA.glob("*.py"), *SCHEMA.glob("readers/*.py"), *(SCHEMA.parent / "steer").glob("*.py")])


def _bound_twice(source: str) -> list[str]:
    seen: dict[str, int] = {}
    for node in ast.parse(source).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names = [node.name]
        elif isinstance(node, ast.Assign):
            names = [t.id for t in node.targets if isinstance(t, ast.Name)]
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and node.value is not None:
            names = [node.target.id]
        else:
            continue
        for name in names:
            seen[name] = seen.get(name, 0) + 1
    return sorted(n for n, k in seen.items() if k > 1)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_a_module_binds_each_top_level_name_once(path):
    assert _bound_twice(path.read_text()) == []


def test_a_second_binding_is_found():
    assert _bound_twice("A = 1\ndef f():\n    pass\nA = 2\n") == ["A"]
