"""The emitter writes outside text only as repr literals: hostile instructions, summaries,
paraphrases, labels and names cannot change the shape of code.py."""

import ast

import pytest

from rpg.codegen import generate
from rpg.codegen.emit import DOC_CHARS, class_name, doc_text
from rpg.domain.predicates import And, Reads
from rpg.schema.builtin import parse

HOSTILE = [
    'It\'s "quoted" and \\backslashed\\',
    'Stack it."""\nimport os\nos.system("id")\n"""',
    "Stack it.'''\nimport os\n'''",
    'end with a quote"',
    'end with a backslash\\',
    "two\nlines\r\nand\rcarriage",
    "nul\x00byte",
    "unicode\u2028line\u2029separators\x85nel\x0bvt\x0cff",
    "# a comment\n    def goal(self):\n        return None",
    "f-string {braces} {{double}} {__import__('os')}",
    '\\N{BULLET} \\x41 \\u0041 """ \' "',
    "\ud800 lone surrogate",
    "",
]


def _shape(source: str) -> tuple:
    """Top-level statement types and, for each class, its members' kinds and names."""
    tree = ast.parse(source)
    out = []
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members = []
            for m in node.body:
                if isinstance(m, ast.Assign):
                    members.append(("assign", tuple(t.id for t in m.targets)))
                elif isinstance(m, ast.FunctionDef):
                    members.append(("def", m.name))
                else:
                    members.append((type(m).__name__, None))
            out.append(("class", node.name, tuple(members)))
        else:
            out.append((type(node).__name__,))
    return tuple(out)


def _attr(source: str, name: str):
    cls = next(n for n in ast.parse(source).body if isinstance(n, ast.ClassDef))
    node = next(m for m in cls.body if isinstance(m, ast.Assign) and m.targets[0].id == name)
    return ast.literal_eval(node.value)


def _docstrings(source: str) -> list[str]:
    tree = ast.parse(source)
    return [ast.get_docstring(n, clean=False) for n in ast.walk(tree)
            if isinstance(n, (ast.Module, ast.ClassDef, ast.FunctionDef)) and ast.get_docstring(n, clean=False)]


@pytest.mark.parametrize("text", HOSTILE)
def test_hostile_instruction_and_summary_stay_literals(text):
    base = parse("Stack the green block on top of the blue block")
    benign = generate(base)
    paraphrases = [text, "x" + text, text + "y"]
    schema = base.model_copy(update={"instruction": text, "goal_summary": text, "paraphrases": paraphrases})
    code = generate(schema)
    for src in (code.code, code.goal_state_code):
        compile(src, "code.py", "exec")
    assert _shape(code.code) == _shape(benign.code)
    assert _shape(code.goal_state_code) == _shape(benign.goal_state_code)
    assert _attr(code.code, "INSTRUCTION") == text
    assert list(_attr(code.code, "PARAPHRASES")) == paraphrases
    # the docstrings do not depend on the instruction or the summary at all
    assert _docstrings(code.code) == _docstrings(benign.code)
    assert code.goal_state_code == benign.goal_state_code
    assert "\x00" not in code.code and "\u2028" not in code.code


@pytest.mark.parametrize("text", HOSTILE)
def test_hostile_text_in_goal_descriptions_and_names(text):
    """describe() can quote model text (Reads.text) and object names: sanitised in docstrings."""
    base = parse("Arrange the letter cubes to spell CAT from left to right")
    benign = generate(base)
    parts = [Reads(objects=p.objects, text=text, direction=p.direction, face=p.face) if isinstance(p, Reads) else p
             for p in base.goal.conjuncts()]
    names = [a.name for a in base.assets]
    init = base.initial_state.model_copy(update={"structures": [[names[0] + text, names[1]]]})
    schema = base.model_copy(update={"goal": And(tuple(parts)), "initial_state": init,
                                     "name": base.name, "goal_summary": text})
    code = generate(schema)
    compile(code.code, "code.py", "exec")
    shape, want = _shape(code.code), _shape(benign.code)
    assert shape == want
    for doc in _docstrings(code.code):
        assert set(doc) <= DOC_CHARS | {"\n"}
    reads = next(n for n in ast.walk(ast.parse(code.code)) if isinstance(n, ast.Call) and getattr(n.func, "id", "") == "Reads")
    assert ast.literal_eval(next(k.value for k in reads.keywords if k.arg == "text")) == text


def test_doc_text_and_class_name():
    assert doc_text('a"""b\\c\nd\u2028e\x00f') == "a???b?c?d?e?f"
    assert doc_text("reads 'CAT' left to right; {x} #1") == "reads 'CAT' left to right; {x} #1"
    assert class_name("stack_two_blocks") == "StackTwoBlocksTask"
    for odd in ("x\u00b2", "\u00e9tude_1", "a\u2028b"):
        name = class_name(odd)
        assert name.isidentifier() and name.isascii(), name
