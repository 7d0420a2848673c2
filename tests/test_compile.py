"""End to end: compile real instructions, break artifacts per gate, repair, CLI exit codes."""

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from rpg.artifact import task_sources
from rpg.compiler import build, compile_instruction, load_artifact, revalidate
from rpg.domain.predicates import And, On, Reads
from rpg.domain.task import Task
from rpg.env.loading import task_data
from rpg.schema.builtin import ParseError, parse
from rpg.schema.feasibility import InfeasibleTask, check_feasibility
from rpg.schema.model import export_json_schema

ROOT = Path(__file__).resolve().parents[1]
SEEDS = ROOT.parent / "shared" / "seed-cases.yaml"
RPG = [sys.executable, "-m", "rpg.cli"]


def seed_instructions():
    if not SEEDS.exists():
        return []
    d = yaml.safe_load(SEEDS.read_text())
    out = [s["steps"][0]["instruction"] for s in d["benchmark_sessions"]]
    for k in ("reference_tasks", "training_tasks", "evaluation_tasks"):
        for t in d[k]:
            out.append(t["instruction"] + (f"; {t['initial_state']}" if t.get("initial_state") else ""))
    return out


def rpg(*args, cwd=None):
    return subprocess.run([*RPG, *args], capture_output=True, text=True, cwd=cwd, env={**os.environ, "COLUMNS": "200"})


def test_json_schema_file_in_sync():
    assert (ROOT / "schemas" / "task.schema.json").read_text() == export_json_schema()


def test_every_library_schema_validates_against_the_exported_json_schema():
    """The JSON Schema a model is shown (goal tree included) accepts every committed task
    and rejects a goal with an unknown argument, as pydantic does."""
    import jsonschema
    import yaml

    doc = json.loads(export_json_schema())
    tasks = sorted((ROOT / "library").rglob("task.yaml"))
    assert len(tasks) >= 40
    for t in tasks:
        jsonschema.validate(yaml.safe_load(t.read_text())["schema"], doc)
    schema = yaml.safe_load(tasks[0].read_text())["schema"]
    schema["goal"] = {"predicate": "on", "a": "x", "b": "y", "height": 3}
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(schema, doc)


@pytest.mark.slow
@pytest.mark.parametrize("instruction", seed_instructions())
def test_paper_instruction_compiles_and_goal_holds(instruction, tmp_path, snapshots_on):
    result = compile_instruction(instruction, tmp_path)
    assert result.valid, result.log
    assert {g["gate"] for g in result.gates if g["status"] == "pass"} == {
        "text", "compile", "smoke", "nontrivial", "constraint", "goal_state", "bounds", "visibility"}
    for f in ("task.yaml", "code.py", "goal_state_code.py", "validation.log", "validation.json", "initial.png", "goal.png"):
        assert (result.path / f).is_file(), f
    task = Task(task_data(task_sources(result.path)))
    task.set_goal_state()
    task.step(50)
    assert task.success()
    falses = []
    for s in (0, 2):
        task.reset(s)
        falses.append(not task.success())
    assert any(falses)


def test_tower_order_read_from_object_positions(tmp_path):
    r = compile_instruction("Make a simple 2-block tower with a red block on bottom and blue on top", tmp_path)
    proc = rpg("inspect", str(r.path), "--state", "goal", "--json")
    assert proc.returncode == 0, proc.stderr
    objs = json.loads(proc.stdout)["objects"]
    by_height = [o["color"] for o in sorted(objs, key=lambda o: o["position"][2])]
    assert by_height == ["red", "blue"]
    assert abs(objs[0]["position"][0] - objs[1]["position"][0]) < 0.01


@pytest.fixture(scope="module")
def tower(tmp_path_factory):
    return compile_instruction("Place a blue cube on top of a red cube on the table", tmp_path_factory.mktemp("lib")).path


def _broken(tower, tmp_path, fname, old, new):
    d = tmp_path / "broken"
    shutil.copytree(tower, d)
    text = (d / fname).read_text()
    assert old in text
    (d / fname).write_text(text.replace(old, new, 1))
    return d


@pytest.mark.parametrize("fname,old,new,gate", [
    ("code.py", "def goal(self):", "def goal(self)", "text"),
    ("code.py", "from rpg.task_api import (", "import os\nfrom rpg.task_api import (", "text"),
    ("code.py", "return Stack(objects=['red', 'blue'])", "return Stack(objects=['red'])", "nontrivial"),
    ("code.py", "return Stack(objects=['red', 'blue'])", "return And([On(a='red', b='blue'), On(a='blue', b='red')])", "constraint"),
    ("goal_state_code.py", "'blue': Pose((0.55, 0.0, ", "'blue': Pose((0.585, 0.0, ", "goal_state"),
    ("goal_state_code.py", "'blue': Pose((0.55,", "'blue': Pose((0.75,", "goal_state"),
])
def test_each_gate_catches_a_broken_artifact(tower, tmp_path, fname, old, new, gate):
    if "And(" in new:
        (tmp_path / "x").mkdir()
    d = _broken(tower, tmp_path, fname, old, new)
    if "And(" in new:
        (d / "code.py").write_text((d / "code.py").read_text().replace("    Stack,", "    Stack,\n    And,\n    On,"))
    result = revalidate(d)
    assert not result.valid
    failed = [g["gate"] for g in result.gates if g["status"] == "fail"]
    assert failed[0] == gate, result.log
    assert "FAIL" in (d / "validation.log").read_text()
    assert rpg("validate", str(d)).returncode == 1


def test_bounds_gate_catches_object_outside_workspace(tower, tmp_path):
    d = tmp_path / "b"
    shutil.copytree(tower, d)
    g = (d / "goal_state_code.py").read_text()
    (d / "goal_state_code.py").write_text(g.replace("(0.55, 0.0,", "(0.69, 0.0,"))
    (d / "goal_state_code.py").write_text((d / "goal_state_code.py").read_text().replace("(0.69, 0.0,", "(0.745, 0.0,"))
    result = revalidate(d)
    assert [x["gate"] for x in result.gates if x["status"] == "fail"] == ["bounds"], result.log


def test_visibility_gate_catches_occluded_label_and_repair_switches_face(tmp_path):
    schema = parse("Spell the word 'CAT' with cubes stacked in a tower")
    goal = schema.goal_predicate()
    broken = And([c if not isinstance(c, Reads) else Reads(c.objects, c.text, c.direction, "up") for c in goal.children()])
    bad = schema.model_copy(update={"goal": broken})
    result = build(bad, tmp_path, disabled=frozenset())
    assert result.valid, result.log
    assert "SWITCH_READABLE_FACE" in [r.operator for r in result.schema.repairs]
    assert any("FAIL" in line for line in result.log)
    no_repair = build(bad, tmp_path / "noop", disabled=frozenset({"goal_state"}))
    assert no_repair.valid and [r.operator for r in no_repair.schema.repairs] == ["SWITCH_READABLE_FACE"]


def test_repair_moves_layout_into_workspace_and_breaks_cycles(tmp_path):
    schema = parse("Place the red block on the left side of the yellow block")
    shifted = {n: {"position": (p.position[0] + 0.2, p.position[1], p.position[2]), "quaternion": p.quaternion}
               for n, p in schema.goal_layout.items()}
    result = build(schema.model_copy(update={"goal_layout": {n: type(schema.goal_layout[n])(**v) for n, v in shifted.items()}}), tmp_path)
    assert result.valid and result.schema.repairs[-1].operator == "MOVE_INTO_WORKSPACE", result.log
    tower = parse("Place a blue cube on top of a red cube")
    cyclic = And([tower.goal, On("red", "blue")])
    result = build(tower.model_copy(update={"goal": cyclic}), tmp_path / "c")
    assert result.valid and result.schema.repairs[-1].operator == "REORDER_SUPPORT_CHAIN", result.log


def test_unrepairable_task_is_rejected_with_logs(tmp_path):
    schema = parse("Stack the red block on top of the yellow block")
    goal = And([schema.goal, On("yellow", "red")])
    bad = schema.model_copy(update={"goal": goal, "name": "impossible"})
    result = build(bad, tmp_path, disabled=frozenset({"constraint"}))
    assert not result.valid
    assert result.path == tmp_path / ".rejected" / "impossible"
    assert (result.path / "validation.log").read_text().strip().endswith("REJECTED")
    assert not (tmp_path / "impossible").exists()


def test_feasibility_refuses_and_repairs():
    with pytest.raises(InfeasibleTask, match="reach"):
        check_feasibility(parse("Stack 30 red blocks on top of each other"))
    s = check_feasibility(parse("Build a pyramid of digit blocks sorted numerically with a 3x3 base"))
    assert {"REDUCE_LABELS_PRESERVE_GEOMETRY", "SWITCH_ORDERING_PATTERN"} <= {r.operator for r in s.repairs}


@pytest.mark.parametrize("text,needle", [
    ("", "empty"),
    ("   ", "empty"),
    ("florp the wizzle", "'florp'"),
    ("x" * 2100, "limit"),
    ("put red on blue and blue on red", "contradict"),
    ("Stack the chartreuse block on the red block", "chartreuse"),
])
def test_builtin_parser_refuses_clearly(text, needle):
    with pytest.raises(ParseError, match=needle):
        parse(text)


def test_cli_exit_codes_and_messages(tmp_path, snapshots_on):
    assert rpg("--version").stdout.startswith("rpg ")
    assert "Exit codes" in rpg("--help").stdout
    bad = rpg("compile", "florp the wizzle", "-o", str(tmp_path))
    assert bad.returncode == 2 and "florp" in bad.stderr and "Traceback" not in bad.stderr
    assert list(tmp_path.iterdir()) == []
    ok = rpg("compile", "Stack the green block on top of the blue block", "-o", str(tmp_path), "--json")
    assert ok.returncode == 0, ok.stderr
    doc = json.loads(ok.stdout)
    assert doc["valid"] and Path(doc["snapshots"]["goal"]).is_file()
    poses = tmp_path / "poses.json"
    poses.write_text(json.dumps({"ghost": {"position": [0.5, 0, 1]}}))
    r = rpg("check", doc["path"], "--poses", str(poses), "--json")
    assert r.returncode == 2 and "ghost" in r.stderr
    poses.write_text(json.dumps({"blue": {"position": [0.55, 0.0, 0.97]}, "green": {"position": [0.55, 0.0, 1.0105]}}))
    r = rpg("check", doc["path"], "--poses", str(poses), "--settle", "20", "--json")
    assert r.returncode == 0 and json.loads(r.stdout)["success"] is True
    assert rpg("validate", str(tmp_path / "nope")).returncode == 2


def test_sentences_set_aside_are_printed_and_recorded_with_the_text_as_written(tmp_path):
    """A voice's sentences that name nothing of the task are set aside, never silently: ``rpg compile`` prints each
    with why, ``--json`` lists them, and task.yaml records the text as written (``provenance.said``) and each set-aside
    sentence in its accounting; a text with nothing set aside records no ``said`` (the library keeps its hashes)."""
    text = "Calm seas. Put the red cube on the blue cube. Serve with a smile."
    r = rpg("compile", text, "-o", str(tmp_path / "a"))
    assert r.returncode == 0, r.stderr
    lines = [line for line in r.stdout.splitlines() if line.startswith("set aside:")]
    assert lines == ["set aside: 'Calm seas.' (a sentence that names nothing of the task)",
                     "set aside: 'Serve with a smile.' (a sentence that names nothing of the task)"], r.stdout
    r = rpg("compile", text, "-o", str(tmp_path / "b"), "--json")
    doc = json.loads(r.stdout)
    assert [a["said"] for a in doc["set_aside"]] == ["Calm seas.", "Serve with a smile."]
    task = yaml.safe_load((Path(doc["path"]) / "task.yaml").read_text())
    assert task["provenance"]["said"] == text and task["provenance"]["instruction"] == "Put the red cube on the blue cube."
    assert [a["mention"] for a in task["accounting"] if a["kind"] == "ignored"] == ["Calm seas.", "Serve with a smile."]
    plain = rpg("compile", "Put the red cube on the blue cube.", "-o", str(tmp_path / "c"), "--json")
    doc = json.loads(plain.stdout)
    assert doc["set_aside"] == [] and "said" not in yaml.safe_load((Path(doc["path"]) / "task.yaml").read_text())["provenance"]
    assert "set aside" not in rpg("compile", "Put the red cube on the blue cube.", "-o", str(tmp_path / "d")).stdout


def test_same_instruction_same_artifact_across_processes(tmp_path):
    code = ("import sys; from rpg.compiler import compile_instruction; "
            "print(compile_instruction('Align 4 cubic blocks in a single straight horizontal line.', sys.argv[1]).content_hash)")
    a = subprocess.run([sys.executable, "-c", code, str(tmp_path / "a")], capture_output=True, text=True,
                       env={**os.environ, "PYTHONHASHSEED": "1"})
    b = subprocess.run([sys.executable, "-c", code, str(tmp_path / "b")], capture_output=True, text=True,
                       env={**os.environ, "PYTHONHASHSEED": "2"})
    assert a.returncode == 0, a.stderr
    assert a.stdout == b.stdout and len(a.stdout.strip()) == 64
    schema, doc = load_artifact(next(p for p in (tmp_path / "a").iterdir() if not p.name.startswith(".")))
    assert doc["content_hash"] == a.stdout.strip()


@pytest.mark.parametrize("text,summary", [
    ("Stack three blocks: red at the bottom, then green, then blue on top", "tower bottom to top: red, green, blue"),
    ("Build a tower of red, green and blue blocks", "a stack of red, green, blue in any order"),  # a list is no order
    ("Stack the letters A, B, C into a tower with A at the bottom", "tower bottom to top: letter_a, letter_b, letter_c"),
    ("Make a tower of the blue, red and yellow cubes with yellow at the bottom",
     "a stack of yellow, blue, red with yellow at the bottom, the rest in any order"),
    ("Stack four blocks in rainbow order", "tower bottom to top: red, orange, yellow, green"),
    ("Line up the red, green and blue blocks from right to left", "cubes in a line right to left: red, green, blue"),
    ("Place the red cube on the left and the blue cube on the right", "red left of blue"),
    ("Arrange the digits 1 to 5 in ascending order", "up faces read 1, 2, 3, 4, 5 left to right"),
    ("Make a 3 by 3 grid of blocks", "a 3x3 grid of 9 touching cubes"),
    ("Place the red block behind the blue patch", "red behind blue_patch"),
    ("Arrange the numbers 3, 1, 2 in increasing order", "up faces read 1, 2, 3 left to right"),
    ("Sort the letters A, B and C alphabetically from left to right", "up faces read A, B, C left to right"),
    ("Place each block on the patch of the same color", "each cube on the patch of its colour: red, blue"),
    ("Build a tower three blocks high with a yellow block on top",
     "a stack of red, blue, yellow with yellow on top, the rest in any order"),
    ("Spell ROBOT vertically in a tower", "a tower whose front faces read 'ROBOT' from top to bottom"),
    ("Stack the cubes so the letters read ABC from top to bottom", "a tower whose front faces read 'ABC' from top to bottom"),
    ("Put the block with the letter A on top of the block with the letter B", "tower bottom to top: letter_b, letter_a"),
    ("Arrange the blocks in a square", "a 2x2 grid of 4 touching cubes"),
    ("Create a 2 by 2 square out of yellow cubes", "a 2x2 grid of 4 touching cubes"),
    ("Sort the number cubes from smallest to largest", "4 cubes in a line in increasing numerical order left to right"),
    ("Arrange 4 cubes in a row alternating red and white",  # which colour starts, and which way, is not said
     "line of red_1, white_1, red_2, white_2 in that order from either end"),
    ("Build a tower of 5 blocks alternating green and yellow", "tower bottom to top: green_1, yellow_1, green_2, yellow_2, green_3"),
    # references back to a stack the text builds, or to the previous relation's object ("the
    # stack" nobody built or described is refused: test_language.test_a_structure_nobody_described_is_not_invented)
    ("Stack two green blocks and place a red block beside the stack",
     "tower bottom to top: green_1, green_2; red next to green_1"),
    ("Stack the red block on the blue block and the green block next to them", "tower bottom to top: blue, red; green next to blue"),
    ("Place the yellow block to the left of the green block and the red block to the right of it",
     "yellow left of green; red right of green"),
    ("Put the green block behind the blue block and the red block in front of it", "green behind blue; red in front of blue"),
    # a tower listed without its order: a relation in the plane to it holds of any of its cubes, so the order is free
    ("Build a tower of red, green and blue blocks and place the yellow block behind it",
     "a stack of red, green, blue in any order; yellow behind red"),
    ("Put the purple cube behind the tower of red and blue", "a stack of red, blue in any order; purple behind red"),
    ("Put the yellow block on the goal patch and stack the red block on it", "tower bottom to top: yellow, red; yellow on gray_patch"),
    # sorted towers of letters and digits
    ("Stack the number blocks in increasing order from bottom to top", "a tower of digits ascending from bottom to top: 1, 2, 3, 4"),
    ("Stack the blocks from largest number to smallest number going up",
     "a tower of digits descending from bottom to top: 4, 3, 2, 1"),
    ("Stack the letter blocks in alphabetical order with A at the bottom",
     "a tower of letters ascending from bottom to top: A, B, C, D"),
    ("Build a tower of 3 digit cubes with the smallest on top", "a tower of digits descending from bottom to top: 3, 2, 1"),
    # walls, columns, patches, piles, nearness, typos
    ("Build a wall of six blocks, three wide and two high", "a wall 3 cubes wide and 2 high (6 cubes)"),
    ("Build a wall 4 blocks wide and 2 blocks high", "a wall 4 cubes wide and 2 high (8 cubes)"),
    ("Place the blocks in a vertical column", "a stack of red, blue in any order"),
    ("Place a block on each of the three goal patches",
     "one cube on each of the 3 goal patches (red_1, red_2, red_3, any cube on any patch)"),
    ("Separate the red blocks from the blue blocks", "2 separate piles, one per color"),
    ("Put the green block close to the yellow block", "green next to yellow"),
    ("Put teh red block on the blue block", "tower bottom to top: blue, red"),
    ("Build a three-block tower", "a stack of red, blue, green in any order"),
    ("Build a tower of two blue blocks and one red block on top", "tower bottom to top: blue_1, blue_2, red"),
    ("Build a 4-layer pyramid", "a 2D pyramid with a base of 4 (10 cubes)"),
    ("Stack three blocks in a triangle", "a 2D pyramid with a base of 2 (3 cubes)"),  # a flat one is refused:
    # test_language.test_a_triangle_with_nothing_stacked_names_no_one_shape
    ("Use letter cubes to write the word SUN", "the cubes spell 'SUN' left to right in a line"),
    ("Line the digit cubes up from 9 down to 5", "up faces read 9, 8, 7, 6, 5 left to right"),
    ("Place the cube labeled 7 on the red patch", "digit_7 on red_patch"),
    ("Arrange the red, blue and green blocks in a line with blue in the middle",
     "3 cubes in one straight line with blue in the middle"),
    ("Arrange the cubes so the numbers increase from left to right",
     "4 cubes in a line in increasing numerical order left to right"),
    ("Place the red block and the blue block onto the gray goal patch", "red on gray_patch; blue on gray_patch"),
    ("Place the red block onto the long green goal patch", "red on green_long_patch"),
    ("Pick up the red block and place it on the blue block.", "tower bottom to top: blue, red"),
    ("Grab the yellow cube and put it on the green patch.", "yellow on green_patch"),
    ("Place the blocks side by side", "red next to blue"),
    ("Put the red and green blocks on top of each other", "a stack of red, green in any order"),
    ("Place the cubes in two rows of three", "a 2x3 grid of 6 touching cubes"),
    ("Make a small pyramid", "a 2D pyramid with a base of 2 (3 cubes)"),
    ("Put the A block to the left of the B block", "letter_a left of letter_b"),
    ("Place the 3 cube in front of the 7 cube", "digit_3 in front of digit_7"),
    ("Arrange the blocks so that red is left of green and green is left of blue", "red left of green; green left of blue"),
    ("Place the blue cube in between the two red cubes", "blue between red_1 and red_2"),
    ("Starting from a stack of red on blue, unstack them and put the red block to the right of the blue block",
     "red right of blue; initially red is stacked on blue"),
    ("Build a stack of 2 red blocks and a stack of 2 blue blocks",
     "tower bottom to top: red_1, red_2; tower bottom to top: blue_1, blue_2"),
    ("Make a tower of 3 red blocks next to a tower of 3 blue blocks",
     "tower bottom to top: red_1, red_2, red_3; tower bottom to top: blue_1, blue_2, blue_3; red_1 next to blue_1"),
    ("Stack the red blocks on the red patch and the blue blocks on the blue patch",
     "2 towers of 2 cubes, each on the patch of its color"),
    ("Put the green block to the left of the red block and behind the blue block", "green left of red; green behind blue"),
    ("Build a tower with the blue block in the middle", "a tower of red, blue, green in any order, with blue second from the bottom"),
    ("Make a line of digits 1 through 4 from front to back", "up faces read 1, 2, 3, 4 front to back"),
    ("Line up four letter cubes", "4 letter cubes in one straight line"),
    ("Put two blocks on each of the two patches",  # ("on each patch" alone says no count of patches: refused, test_language)
     "2 cubes on each of the 2 goal patches (red_1, red_2, red_3, red_4, any cube on any patch)"),
    ("Move the yellow cube onto the blue target.", "yellow on blue_patch"),
    ("Place the red block in the green goal area.", "red on green_patch"),
    ("Put the blue cube on the red mat.", "blue on red_patch"),
    ("Put three blocks in a column.", "a stack of red, blue, green in any order"),
    ("Arrange the blocks so that 2 + 3 = 5 reads from left to right.",
     "the cubes read a correct equation left to right (e.g. 2+3=5)"),
    ("Create a row of four blocks with colors red, blue, red, blue.",
     "line of red_1, blue_1, red_2, blue_2 in that order from either end"),
    # no colour said: the cubes are of one colour, so which make which stack is free (issue 30: no goal stricter than the words)
    ("Arrange 6 blocks in two stacks of three.", "a stack of red_1, red_2, red_3 in any order; a stack of red_4, red_5, red_6 in any order"),
    ("Build 3 stacks, 2 blocks high.", "a stack of red_1, red_2 in any order; a stack of red_3, red_4 in any order; a stack of red_5, red_6 in any order"),
    ("Separate the letters from the numbers.", "2 separate piles, one per type (letters, digits)"),
    ("Place the red cube in the middle of the table.", "red in the center of the workspace"),
    ("Put the blue block in the far left corner of the table.", "blue in the back left corner of the workspace"),
    ("Put the red block on the left side of the table and the blue one on the right side of the table.",
     "red on the left side of the workspace; blue on the right side of the workspace"),
    ("Place the red block to the left of the blue block, in the back of the table.",
     "red on the back side of the workspace; red left of blue"),
    ("Put the red block on the left and the blue block on the right.", "red left of blue"),  # relative, not a region
    ("Stack the blocks in rainbow order.", "tower bottom to top: red, orange, yellow, green, blue"),
    ("Arrange the digits 1, 2, 3 so that they read 321.", "up faces read 3, 2, 1 left to right"),
    ("Stack two red blocks and two blue blocks alternately.", "tower bottom to top: red_1, blue_1, red_2, blue_2"),
    ("Stack the cubes so that the colors alternate.", "tower bottom to top: red_1, blue_1, red_2, blue_2"),
    ("Build a tower and then place a green block next to it.", "tower bottom to top: red, blue; green next to red"),
    ("Turn the letter cube so that the letter faces the camera.", "the cube shows 'A' facing front, upright"),
    ("Stack the letter A on the letter B.", "tower bottom to top: letter_b, letter_a"),
    ("Put the number 4 to the left of the number 2.", "digit_4 left of digit_2"),
    ("Put the cube with the letter Z on the red patch.", "letter_z on red_patch"),
])
def test_parser_reads_phrasings_beyond_the_paper(text, summary):
    assert parse(text).goal_summary == summary


@pytest.mark.parametrize("text", [
    "Stack two green blocks and place a red block beside the stack",
    "Put the green block behind the blue block and the red block in front of it",
    "Build a wall 4 blocks wide and 2 blocks high",
    "Stack the letter blocks in alphabetical order with A at the bottom",
    "Place a block on each of the three goal patches",
    "Place three blocks onto the goal patch",  # two rows on a square patch
    "Put 7 blocks on the long goal patch",
    "Make a tower of 3 red blocks next to a tower of 3 blue blocks",
    "Starting from a stack of red on blue, unstack them and put the red block to the right of the blue block",
    "Arrange the digits 1 to 4 from front to back",  # laid out along x (it was along y: the order was luck)
    "Stack the red blocks on the red patch and the blue blocks on the blue patch",
    "Place 2 red cubes on each of the 3 blue patches",
    "Lay out 3 x 3 = 9 with cubes",
    "Arrange 6 blocks in two stacks of three",
    "Build a tower of three blocks in the center of the workspace",
    "Move the purple block to the back right corner and the orange block to the front left corner",
    "Place four cubes in the front right corner",
    # readings of the clause reader and the move-to-a-place recognizer (test_language.py)
    "Place a column of 2 yellow blocks in each of the four corners.",
    "push the red block to the right",
    "Build a horizontal row of 3 purple blocks on top of the horizontal row of 3 red blocks.",
    "Add one blue block under the red block. Then add 3 green blocks on top of red block.",
    # a cube beside a cube on a patch: it had been laid out beside where that cube stood before the patch (3 cm off)
    "Put a red cube on the green patch, then a purple cube next to the red block",
    # two cubes next to one: the second had been laid out where the first stood
    "put the green cube next to the orange cube and the blue cube next to the orange cube",
    "put the red cube left of the blue cube and the green cube left of the blue cube",
    # a structure wider than the centre third stands with its middle there (it had been refused as not fitting)
    "Form a circle of four purple cubes in the centre of the table.",
    "build a row of four black blocks in the middle of the table",
])
def test_new_phrasings_compile_to_valid_tasks(text, tmp_path):
    r = compile_instruction(text, tmp_path)
    assert r.valid, [g for g in r.gates if g["status"] == "fail"]


def test_region_tasks_start_outside_their_regions(tmp_path):
    r = compile_instruction("Move the green cube to the left side of the table", tmp_path)
    assert r.valid
    code = (r.path / "code.py").read_text()
    assert "avoid={'green': 'left'}" in code and "starting outside its goal region: green (left)" in code
    nontrivial = next(g for g in r.gates if g["gate"] == "nontrivial")
    assert nontrivial["status"] == "pass"


def test_a_cube_at_the_corner_may_end_in_any_corner(tmp_path):
    from rpg.domain.predicates import region_boxes

    r = compile_instruction("Place the blue block at the corner.", tmp_path)
    assert r.valid, [g for g in r.gates if g["status"] == "fail"]
    code = (r.path / "code.py").read_text()
    assert "InRegion(a='blue', region='corner')" in code and "avoid={'blue': 'corner'}" in code
    doc = yaml.safe_load((r.path / "task.yaml").read_text())
    assert {"constraint": "blue cube in a corner of the table", "kind": "place", "cites": ["corner"]} in doc["citations"]
    task = Task(task_data(task_sources(r.path)))
    for seed in range(8):  # rho_0 starts the cube in no corner, whatever the seed
        x, y = task.reset(seed)["blue"].pos[:2]
        assert not any(x0 <= x <= x1 and y0 <= y <= y1 for (x0, x1), (y0, y1) in region_boxes("corner")), seed
        assert not task.success()
    task.set_goal_state()
    task.step(50)
    assert task.success()


def test_parser_refuses_rather_than_drop_a_named_cube():
    with pytest.raises(ParseError, match="purple"):
        parse("Stack the red block on the blue block and the purple block")
    with pytest.raises(ParseError, match="mixing letters and digits"):
        parse("Make a row of alternating letters and numbers")  # was read as a line of coloured cubes
    with pytest.raises(ParseError, match="does not say which cubes"):  # one pile, of cubes nobody named
        parse("Put all blocks in one pile")
    with pytest.raises(ParseError, match="could not find a task"):
        parse("Arrange the blocks in a plus shape")  # a shape it does not build is refused, not read as a line
    with pytest.raises(ParseError, match="5 cubes do not fit on one square goal patch"):
        parse("Put 5 blocks on the goal patch")
    with pytest.raises(ParseError, match="wall 4 wide and 2 high has 8 cubes, not 6"):
        parse("Build a wall of 6 blocks, 4 wide and 2 high")
    with pytest.raises(ParseError, match="2\\+2=5 is not a correct equation"):
        parse("Arrange the cubes to show 2 + 2 = 5.")
    with pytest.raises(ParseError, match="labelled '1' has no place"):  # it built a tower of 2 and 4 only
        parse("Place the numbers 1 to 3 in a row, then stack the number 4 on top of the number 2")
    with pytest.raises(ParseError, match="8 cubes do not fit in the center"):
        parse("Put 8 blocks in the center of the table")
    schema = parse("Form a straight line of four blue blocks")
    assert [a.color for a in schema.assets] == ["blue"] * 4


def test_feasibility_switches_face_or_to_spatial_only_when_labels_are_covered():
    from rpg.domain.predicates import Grid

    cube = parse("Make a 2x2x2 cube of letter blocks")
    names = tuple(a.name for a in cube.assets)
    hidden = cube.model_copy(update={"goal": And([Grid(names, 2, 2, 2), Reads(names, "ABCDEFGH")])})
    s = check_feasibility(hidden)
    assert [r.operator for r in s.repairs] == ["SWITCH_TO_SPATIAL_ONLY"]
    assert s.goal_predicate().describe() == "2x2x2 grid of 8 cubes" and s.reasoning == "spatial"
    tower = parse("Spell the word 'CAT' with cubes stacked in a tower")
    up = And([c if not isinstance(c, Reads) else Reads(c.objects, c.text, c.direction, "up") for c in tower.goal_predicate().children()])
    s = check_feasibility(tower.model_copy(update={"goal": up}))
    assert [r.operator for r in s.repairs] == ["SWITCH_READABLE_FACE"]
    assert next(c for c in s.goal_predicate().children() if isinstance(c, Reads)).face == "front"


def test_constraint_gate_names_the_cycle_the_ungrounded_chain_and_redundant_edges():
    from types import SimpleNamespace

    from rpg.domain.predicates import OnPatch, OnTable
    from rpg.validate.verdicts import GateFailure, constraint_graph

    kinds = {"red": "cube", "blue": "cube", "green": "cube", "pad": "goal_patch"}
    scene = SimpleNamespace(assets={n: SimpleNamespace(kind=k) for n, k in kinds.items()})

    def gate(*preds):
        return constraint_graph(SimpleNamespace(goal_predicate=And(list(preds)), scene=scene))

    with pytest.raises(GateFailure, match=r"cycle: (red -> blue -> green -> red|blue -> green -> red -> blue"
                                          r"|green -> red -> blue -> green)"):
        gate(On(a="red", b="blue"), On(a="blue", b="green"), On(a="green", b="red"))
    with pytest.raises(GateFailure, match="support chain of blue, red does not end at the table"):
        gate(On(a="red", b="blue"), On(a="blue", b="green"))
    grounded = gate(On(a="red", b="blue"), On(a="blue", b="green"), OnTable(a="green"))
    assert grounded["redundant"] == []
    assert gate(On(a="red", b="blue"), OnPatch(a="blue", patch="pad"))["edges"] == [("blue", "table"), ("red", "blue")]
    assert gate(On(a="red", b="blue"), On(a="blue", b="green"), On(a="red", b="green"),
                OnTable(a="green"))["redundant"] == [["red", "green"]]


def test_a_start_said_before_its_goal_compiles_to_the_end(tmp_path):
    """The parser reads the start ("Initially red is stacked on yellow.") apart from the goal; task.yaml's accounting
    re-read the whole text and refused it after every gate had passed, so `rpg compile` failed on texts the corpus counts
    right (28 of them). The accounting now records what it cannot account for instead."""
    result = compile_instruction("Initially red is stacked on yellow. Swap them so yellow is on red.", tmp_path)
    assert result.valid
    doc = yaml.safe_load((result.path / "task.yaml").read_text())
    assert [a["kind"] for a in doc["accounting"]] == ["unaccounted"]
    assert doc["schema"]["initial_state"]["structures"]


def test_snapshots_can_be_left_out_and_the_task_is_the_same(tmp_path, monkeypatch):
    """``RPG_SNAPSHOTS=0`` builds the task without initial.png and goal.png (a batch job that looks at no pictures): the
    same valid task, the same content hash, its file manifest without the pictures; ``rpg render`` draws them later."""
    monkeypatch.setenv("RPG_SNAPSHOTS", "1")
    drawn = compile_instruction("Stack the red block on the blue block", tmp_path / "drawn", name="t")
    monkeypatch.setenv("RPG_SNAPSHOTS", "0")
    bare = compile_instruction("Stack the red block on the blue block", tmp_path / "bare", name="t")
    assert drawn.valid and bare.valid and bare.content_hash == drawn.content_hash
    assert (drawn.path / "initial.png").is_file() and (drawn.path / "goal.png").is_file()
    assert not (bare.path / "initial.png").exists() and not (bare.path / "goal.png").exists()
    files = yaml.safe_load((bare.path / "task.yaml").read_text())["files"]
    assert not any(name.endswith(".png") for name in files)
    monkeypatch.setenv("RPG_SNAPSHOTS", "1")
    out = subprocess.run([sys.executable, "-m", "rpg.cli", "render", str(bare.path)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert (bare.path / "initial.png").is_file() and (bare.path / "goal.png").is_file()
