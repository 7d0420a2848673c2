"""Steering: intents, references, lineage, loops, asset compatibility, sessions, CLI."""

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from rpg.errors import BadInput
from rpg.schema.builtin import parse
from rpg.steer import Family, SteerError, create_family, is_family, steer
from rpg.steer.edits import apply_ops, interpret
from rpg.steer.session import goal_tower
from rpg.steer.spec import Item, TaskSpec, extract, render
from tests.helpers import compiled


@pytest.fixture(autouse=True)
def _no_snapshots(monkeypatch):
    """The steering tests judge edits, not pictures: their versions are built without initial.png and goal.png
    (``RPG_SNAPSHOTS=0``, a fifth of a second of software rendering each; test_compile checks both ways)."""
    monkeypatch.setenv("RPG_SNAPSHOTS", "0")

ROOT = Path(__file__).resolve().parents[1]
SEEDS = ROOT.parent / "shared" / "seed-cases.yaml"
RPG = [sys.executable, "-m", "rpg.cli"]


def rpg(*args):
    return subprocess.run([*RPG, *args], capture_output=True, text=True, env={**os.environ, "COLUMNS": "200"})


def sessions():
    if not SEEDS.exists():
        return []
    return yaml.safe_load(SEEDS.read_text())["benchmark_sessions"]


# -- the paper's ten benchmark sessions --------------------------------------------


@pytest.mark.parametrize("session", sessions(), ids=lambda s: s["name"])
def test_benchmark_session_in_the_library_has_expected_intents_and_references(session):
    """Each benchmark session's family in the task library has one version per step, each
    with the step's words, intent and reference (``current``: the version before it).  The
    library is what the sessions regenerate to: examples/ holds these sessions (the test
    below) and CI's ``rpg build library/manifest.yaml --check`` reruns every one of them
    and fails on any byte that differs, so the sessions are not run a second time here."""
    fam = ROOT / "library" / session["name"]
    versions = Family(fam).load().versions
    assert len(versions) == len(session["steps"])
    for k, (v, want) in enumerate(zip(versions, session["steps"], strict=True)):
        assert v.version_id == k and v.description == want.get("edit", want.get("instruction"))
        if "expected_intent" in want:
            assert v.intent == want["expected_intent"], (session["name"], k)
        ref = want.get("expected_reference")
        if ref is not None:
            assert v.reference == (k - 1 if ref == "current" else int(ref.removeprefix("v"))), (session["name"], k)
    assert all(r["ok"] for r in Family(fam).verify())


def test_examples_hold_the_ten_benchmark_sessions():
    names = sorted(p.stem for p in (ROOT / "examples").glob("*.yaml"))
    assert len(names) == 10
    if SEEDS.exists():
        assert names == sorted(s["name"] for s in sessions())
        for s in sessions():
            assert yaml.safe_load((ROOT / "examples" / f"{s['name']}.yaml").read_text()) == s


@pytest.fixture()
def evolution(tmp_path):
    """evolution_revert_and_extend, steered through the API."""
    r = compiled("Make a simple 2-block tower with a red block on bottom and blue on top", tmp_path, name="fam")
    fam = create_family(r.path)
    return fam


@pytest.mark.slow
def test_revert_and_extend_then_letters_from_goal_positions(evolution):
    fam = evolution
    assert steer(fam.path, "Add a green block on top").reference == 0
    assert steer(fam.path, "Add a yellow block on top of that").reference == 1
    r = steer(fam.path, "Actually, go back to when it was just red and blue and instead add a purple block")
    assert (r.intent, r.reference, r.version) == ("extend", 0, 3)
    assert goal_tower(fam.version_dir(3)) == ["red", "blue", "purple"]
    r = steer(fam.path, "Now from this simpler version, add letter cubes instead of colored ones")
    assert (r.intent, r.reference) == ("modify", 3)
    tower = goal_tower(fam.version_dir(r.version))
    assert len(tower) == 3 and all(t.startswith("letter ") for t in tower)
    hist = fam.load()
    assert [v.parent for v in hist.versions] == [None, 0, 1, 0, 3]


def test_lineage_catches_edited_code_and_history(evolution, tmp_path):
    fam = evolution
    steer(fam.path, "Add a green block on top")
    assert all(r["ok"] for r in fam.verify())
    assert rpg("verify", str(fam.path)).returncode == 0
    code = fam.version_dir(1) / "code.py"
    original = code.read_text()
    code.write_text(original.replace("'green'", "'yellow'"))
    report = {r["version"]: r for r in fam.verify()}
    assert report[0]["ok"] and not report[1]["ok"]
    assert "content hash" in report[1]["problems"][0]
    proc = rpg("verify", str(fam.path))
    assert proc.returncode == 1 and "ALTERED" in proc.stdout
    code.write_text(original)
    hist_file = fam.path / "family.yaml"
    text = hist_file.read_text()
    hist_file.write_text(text.replace("intent: extend", "intent: tweak"))
    report = {r["version"]: r for r in fam.verify()}
    assert report[0]["ok"] and not report[1]["ok"]
    assert "lineage" in report[1]["problems"][0]


def test_loop_back_reuses_the_earlier_version(evolution):
    fam = evolution
    steer(fam.path, "Add a green block on top")
    r = steer(fam.path, "Remove the top block")
    assert r.reused and r.version == 0 and r.valid
    hist = fam.load()
    assert len(hist.versions) == 2 and hist.head == 0
    assert not (fam.path / "v2").exists()


def test_asset_incompatible_edit_finds_compatible_earlier_version(tmp_path):
    r = compiled("Arrange 4 letter cubes in alphabetical order from left to right", tmp_path, name="fam")
    fam = create_family(r.path)
    blue = steer(fam.path, "Arrange the blocks in order red, yellow, green, blue from left to right")
    assert blue.valid and blue.version == 1
    again = steer(fam.path, "Now sort them alphabetically")
    assert again.reference == 0
    assert any("asset compatibility" in n for n in again.notes)


def test_fresh_edit_has_no_reference(evolution):
    r = steer(evolution.path, "Start over with a new task: place the red block behind the yellow block")
    assert (r.intent, r.reference, r.valid) == ("fresh", None, True)
    snap = evolution.load().get(r.version)
    assert snap.reference is None and snap.parent == 0
    assert not any([snap.preserve_assets, snap.preserve_positions, snap.preserve_goals])


def test_uninterpretable_edit_is_refused_and_family_unchanged(evolution):
    before = (evolution.path / "family.yaml").read_bytes()
    with pytest.raises(SteerError):
        steer(evolution.path, "   ")
    proc = rpg("steer", str(evolution.path), "florp the wizzle")
    assert proc.returncode == 2 and "florp" in proc.stderr and "Traceback" not in proc.stderr
    proc = rpg("steer", str(evolution.path), "go back to when it was just cyan and pink and add a red block")
    assert proc.returncode == 2 and "no earlier version" in proc.stderr
    assert (evolution.path / "family.yaml").read_bytes() == before
    assert sorted(p.name for p in evolution.path.iterdir() if not p.name.startswith(".")) == ["family.yaml", "v0"]


# -- the interpreter on edits beyond the paper's -----------------------------------------


@pytest.mark.parametrize("edit,intent,ops", [
    ("make it 5 blocks tall", "tweak", ["count"]),
    ("Turn it into a circle", "pivot", ["structure"]),
    ("use digit cubes instead of letters", "modify", ["material"]),
    ("paint the top block orange", "tweak", ["recolor"]),
    ("put two more blue cubes on top", "extend", ["add"]),
    ("reverse the order", "modify", ["reverse"]),
    ("make the base 4", "tweak", ["dims"]),
    ("Stack the red block on top of the yellow block", None, []),
])
def test_interpreter_reads_edits_of_the_domain(edit, intent, ops):
    from rpg.steer.edits import intent_of_ops

    plan = interpret(edit)
    assert [o.op for o in plan.ops] == ops
    if intent:
        assert intent_of_ops(plan.ops) == intent
    else:
        assert plan.standalone


@pytest.mark.parametrize("edit,cue", [
    ("go back to version 1 and add a red block", ("version", 1)),
    ("use the original but with 4 blocks", ("original", None)),
    ("undo that", ("previous", None)),
    ("go back to the 3-block version", ("search", None)),
    ("also add a red cube", ("current", None)),
    # an end of a line, no version: it had taken v0 and lost the edits since (steer_stranger13)
    ("add a brown at the start", ("current", None)),
    ("go back to the start", ("original", None)),
    ("back to how it was at the start", ("original", None)),
])
def test_reference_cues(edit, cue):
    plan = interpret(edit)
    assert (plan.cue.kind, plan.cue.version) == cue


def test_ops_apply_to_specs():
    tower = TaskSpec("tower", (Item("red"), Item("blue"), Item("yellow"), Item(label="A")))
    flipped = apply_ops(tower, interpret("Flip the color order of the tower but keep the letter 'A' on top").ops)
    assert [i.phrase() for i in flipped.items] == ["yellow", "blue", "red", "letter 'A'"]
    circle = apply_ops(tower, interpret("turn it into a circle").ops)
    assert circle.structure == "circle" and circle.items == tower.items
    pyramid = extract(parse("Build a pyramid of letter blocks alphabetically with a 3x3 base"))
    bigger = apply_ops(pyramid, interpret("make the base 4").ops)
    assert bigger.dims == (4, 3) and len(bigger.items) == 30
    with pytest.raises(SteerError, match="base"):
        apply_ops(pyramid, interpret("add a red block on top").ops)


def test_every_editable_seed_task_round_trips_through_its_canonical_instruction():
    if not SEEDS.exists():
        pytest.skip("seed cases not present")
    d = yaml.safe_load(SEEDS.read_text())
    texts = [s["steps"][0]["instruction"] for s in d["benchmark_sessions"]]
    texts += [t["instruction"] for k in ("reference_tasks", "training_tasks", "evaluation_tasks") for t in d[k]]
    editable = 0
    for t in texts:
        spec = extract(parse(t))
        if spec is None:
            continue
        editable += 1
        assert extract(parse(render(spec))) == spec, t
    assert editable >= 20


def test_cli_steer_log_show_and_session(tmp_path):
    proc = rpg("session", "run", str(ROOT / "examples" / "progressive_tower.yaml"), "-o", str(tmp_path), "--json")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    doc = json.loads(proc.stdout)
    assert doc["ok"] and [s["intent"] for s in doc["steps"]] == ["base", "extend", "tweak", "extend", "modify", "tweak"]
    fam = doc["family"]
    log = rpg("log", fam)
    assert log.returncode == 0 and "v5" in log.stdout and "(head)" in log.stdout
    shown = json.loads(rpg("show", f"{fam}@v2", "--json").stdout)
    assert shown["intent"] == "tweak" and shown["reference"] == 1
    by_hash = json.loads(rpg("show", f"{fam}@{shown['lineage_hash'][:8]}", "--json").stdout)
    assert by_hash["version_id"] == 2
    assert rpg("show", f"{fam}@v9").returncode == 2
    r = rpg("steer", fam, "Change the base cube to yellow", "--json")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["reused"] is True  # yellow, blue, red, A is v4


def test_edits_beyond_the_paper_on_a_tower(tmp_path):
    r = compiled("Stack the red block on top of the yellow block", tmp_path, name="fam")
    fam = create_family(r.path)
    steps = [
        ("Put a blue block on top", "extend", ["yellow", "red", "blue"]),  # ("make it taller" makes up the colour: refused)
        ("Use green instead of yellow", "tweak", ["green", "red", "blue"]),
        ("Swap the top and bottom blocks", "modify", ["blue", "red", "green"]),
        ("Put a letter B cube at the bottom", "extend", ["letter B", "blue", "red", "green"]),
    ]
    for edit, intent, tower in steps:
        s = steer(fam.path, edit)
        assert (s.intent, s.valid) == (intent, True), (edit, s.notes)
        assert goal_tower(fam.version_dir(s.version)) == tower, edit
    back = steer(fam.path, "Go back to the first version")
    assert back.reused and back.version == 0 and fam.load().head == 0


def test_colour_tweak_on_a_relational_task_and_growing_a_pyramid(tmp_path):
    r = compiled("Place the red block behind the yellow block", tmp_path, name="rel")
    fam = create_family(r.path)
    s = steer(fam.path, "Change red to blue")
    assert (s.intent, s.valid) == ("tweak", True)
    schema = fam.schema(s.version)
    assert sorted(a.color for a in schema.assets) == ["blue", "yellow"]
    assert schema.goal_predicate().describe() == "blue behind yellow"
    p = compiled("Build a pyramid with a base of 3", tmp_path, name="pyr")
    pyr = create_family(p.path)
    g = steer(pyr.path, "Make it bigger")
    assert g.intent == "tweak" and extract(pyr.schema(g.version)).dims == (4, 2)


def test_steering_a_plain_artifact_makes_it_v0_of_a_family(tmp_path):
    r = compiled("Place a blue cube on top of a red cube on the table", tmp_path)
    proc = rpg("steer", str(r.path), "Add a green cube on top", "--json")
    assert proc.returncode == 0, proc.stderr
    doc = json.loads(proc.stdout)
    assert (doc["intent"], doc["reference"], doc["version"]) == ("extend", "v0", "v1")
    hist = Family(r.path).load()
    assert [v.intent for v in hist.versions] == ["base", "extend"]
    assert (r.path / "v0" / "task.yaml").is_file() and not (r.path / "task.yaml").exists()
    assert all(x["ok"] for x in Family(r.path).verify())


@pytest.mark.parametrize("edit,op", [
    ("Reverse the gradient", "reverse"), ("Change the word to DOG", "word"), ("Use four colors", "colors"),
    ("Stack them into a tower instead", "structure"),
])
def test_more_edit_operations(edit, op):
    assert [o.op for o in interpret(edit).ops] == [op]


def test_word_and_gradient_edits_apply_to_lines():
    word = extract(parse("Spell CAT with letter cubes in a line"))
    dog = apply_ops(word, interpret("Change the word to DOG").ops)
    assert render(dog) == "Spell the word 'DOG' using letter cubes arranged in a line from left to right"
    grad = extract(parse("Arrange five blocks in a line from left to right in a color gradient"))
    more = apply_ops(grad, interpret("Add two more blocks").ops)
    assert len(extract(parse(render(more))).items) == 7


@pytest.mark.parametrize("base,edit,expected", [
    ("Stack the red block on top of the yellow block", "Change the colors to a rainbow", "Build a tower from bottom to top: red, orange"),
    ("Stack the red block on top of the yellow block", "Add another red block to the bottom", "Build a tower from bottom to top: red, yellow, red"),
    ("Build a pyramid with a base of 3", "Make the pyramid 3D", "Build a pyramid of red blocks with a 3x3 base"),
    ("Arrange 4 letter cubes in alphabetical order from left to right", "Instead of letters use numbers",
     "Arrange 4 digit cubes in increasing numerical order from left to right"),
])
def test_edit_phrasings_render_the_expected_task(base, edit, expected):
    assert render(apply_ops(extract(parse(base)), interpret(edit).ops)) == expected


def test_a_version_named_by_its_content(tmp_path):
    r = compiled("Build a pyramid of letter blocks alphabetically with a base of 3", tmp_path, name="fam")
    fam = create_family(r.path)
    assert steer(fam.path, "Build a pyramid of blue blocks with a base of 3").version == 1
    s = steer(fam.path, "Take the letter version and make the base 4")
    assert (s.reference, s.intent, s.valid) == (0, "tweak", True)
    assert extract(fam.schema(s.version)).material == "letters"
    plan = interpret("Use the 3-block version but make it blue")
    assert (plan.cue.kind, plan.cue.count, [o.op for o in plan.ops]) == ("search", 3, ["recolor"])


def test_paraphrased_benchmark_edits():
    tower = TaskSpec("tower", (Item("red"), Item("blue"), Item("yellow"), Item(label="A")))
    flipped = apply_ops(tower, interpret("Flip the order of the colors but keep A on top").ops)
    assert [i.phrase() for i in flipped.items] == ["yellow", "blue", "red", "letter 'A'"]
    revert = interpret("Revert to the red and blue tower and add a purple block")
    assert (revert.cue.kind, revert.cue.colors, [o.op for o in revert.ops]) == ("search", ("red", "blue"), ["add"])


def test_edits_of_a_relation_task_change_the_relation(tmp_path):
    """A pairwise-relation task steered in its own terms: "it", "instead", "the other side",
    "swap them"; a relation change of the same cubes is a Modify."""
    fam = compiled("Place the red block behind the yellow block", tmp_path).path
    steps = [("Put it in front instead", "red in front of yellow"),
             ("Move it to the left", "red left of yellow"),
             ("Swap them", "yellow left of red"),
             ("Move it to the other side", "yellow right of red"),
             ("Put the yellow block on top of the red block", "tower bottom to top: red, yellow")]
    for edit, summary in steps:
        r = steer(fam, edit)
        assert r.valid and r.intent == "modify", (edit, r.intent, r.notes)
        assert r.compile.schema.goal_summary == summary, edit
    r = steer(fam, "Put it next to the red block instead")  # "it": the yellow block on top
    assert r.compile.schema.goal_summary == "yellow next to red"
    r = steer(fam, "Add a green block behind it")  # brings in a cube: an Extend
    assert (r.intent, r.valid) == ("extend", True)
    assert r.compile.schema.goal_summary == "yellow next to red; green behind yellow"
    fam2 = compiled("Stack the red block on top of the yellow block", tmp_path / "stack").path
    r = steer(fam2, "Add a blue block to the left of them")
    assert (r.intent, r.valid) == ("extend", True), r.notes
    assert r.compile.schema.goal_summary == "tower bottom to top: yellow, red; blue left of yellow"


def _steer_through(fam, steps):
    """Apply (edit, expected intent, expected goal summary) steps in turn; each must be valid."""
    for edit, intent, summary in steps:
        r = steer(fam, edit)
        assert (r.intent, r.valid) == (intent, True), (edit, r.intent, r.notes)
        assert r.compile.schema.goal_summary == summary, edit


def test_edits_of_a_patch_task(tmp_path):
    """Cubes on one goal patch, steered in its own terms: the patch's colour and shape, the
    number of cubes (Tweak), a named cube added (Extend); the cubes keep their colours."""
    fam = compiled("Place both blocks onto the goal patch", tmp_path).path
    steps = [("Make the patch green", "tweak", "red on green_patch; blue on green_patch"),
             ("Use three blocks", "tweak", "red on green_patch; blue on green_patch; green on green_patch"),
             ("Make the patch long", "tweak", "red on green_long_patch; blue on green_long_patch; green on green_long_patch"),
             ("Add a purple block", "extend",
              "red on green_long_patch; blue on green_long_patch; green on green_long_patch; purple on green_long_patch")]
    _steer_through(fam, steps)


def test_edits_of_a_region_task(tmp_path):
    """Cubes placed in regions of the table, steered in their own terms: another region or
    "swap them" (Modify), a colour (Tweak), a cube added by a region or a cube (Extend)."""
    fam = compiled("Place the red cube in the middle of the table", tmp_path).path
    steps = [("Make it green", "tweak", "green in the center of the workspace"),
             ("Move it to the back left corner instead", "modify", "green in the back left corner of the workspace"),
             ("Add a blue block on the right side of the table", "extend",
              "green in the back left corner of the workspace; blue on the right side of the workspace"),
             ("Swap them", "modify", "green on the right side of the workspace; blue in the back left corner of the workspace"),
             ("Add a yellow block next to the blue one", "extend",
              "green on the right side of the workspace; blue in the back left corner of the workspace; yellow next to blue")]
    _steer_through(fam, steps)
    fam2 = compiled("Move the yellow cube onto the blue target", tmp_path / "patch").path
    r = steer(fam2, "Make the target green")
    assert (r.intent, r.valid, r.compile.schema.goal_summary) == ("tweak", True, "yellow on green_patch")


def test_a_spelled_word_reversed_by_an_edit(tmp_path):
    fam = compiled("Spell CAT with letter cubes", tmp_path).path
    r = steer(fam, "Spell it backwards")
    assert (r.intent, r.valid) == ("modify", True)
    assert r.compile.schema.goal_summary == "the cubes spell 'TAC' left to right in a line"


def test_moving_a_cube_alternating_colours_and_removing_cubes(tmp_path):
    """'Put the blue one at the bottom' moves the cube the tower has (it adds none);
    'alternating' repaints in a pattern; 'remove one block' shrinks by one."""
    fam = compiled("Build a tower from bottom to top: red, green, blue", tmp_path / "t").path
    s = steer(fam, "Put the blue one at the bottom")
    assert (s.intent, s.valid) == ("modify", True)
    assert s.compile.schema.goal_summary == "tower bottom to top: blue, red, green"
    line = compiled("Align 4 cubic blocks in a single straight horizontal line.", tmp_path / "l").path
    s = steer(line, "Use red and blue alternating")
    assert (s.intent, s.valid) == ("tweak", True)
    assert s.compile.schema.goal_summary == "cubes in a line left to right: red_1, blue_1, red_2, blue_2"
    s = steer(line, "Remove one block")
    assert (s.intent, s.valid) == ("tweak", True)
    assert s.compile.schema.goal_summary == "cubes in a line left to right: red_1, blue, red_2"
    s = steer(fam, "Add a yellow block and an orange block on top")
    s = steer(fam, "Remove the top two blocks")  # back to the 3-block tower of v1: reused
    assert s.reused and s.version == 1


def test_reading_direction_tower_of_a_word_and_back_to_a_named_word(tmp_path):
    fam = compiled("Spell the word 'DOG' using semantic cubes arranged in a line", tmp_path).path
    steer(fam, "Change the word to 'CAT'")
    s = steer(fam, "Make it read right to left")
    assert (s.intent, s.valid) == ("modify", True)
    assert s.compile.schema.goal_summary == "the cubes spell 'CAT' right to left in a line"
    s = steer(fam, "Use a tower instead")  # the letters stay
    assert s.compile.schema.goal_summary == "tower bottom to top: letter_c, letter_a, letter_t"
    s = steer(fam, "Go back to DOG")  # a version named by the word it spells
    assert s.reused and s.version == 0


def test_structure_registry_drives_parser_steering_and_edits():
    """Each structure kind names a recognizer the parser runs, states a spec that the
    parser reads back to the same spec, and is what its words name in an edit."""
    from rpg.schema.readers.registry import READERS
    from rpg.schema.structures import STRUCTURE_KINDS, STRUCTURE_WORDS, structure_of_word

    recognizers = set(READERS)
    samples = {
        "tower": TaskSpec("tower", (Item("red"), Item("red"), Item("blue"))),
        "line": TaskSpec("line", (Item("red"), Item("green"), Item("blue"))),
        "pyramid": TaskSpec("pyramid", tuple(Item("yellow") for _ in range(6)), (3, 2)),
        "grid": TaskSpec("grid", (Item("red"), Item("blue"), Item("blue"), Item("red")), (2, 2)),
        "block": TaskSpec("block", tuple(Item("green") for _ in range(8)), (2, 2, 2)),
        "circle": TaskSpec("circle", (Item("red"), Item("blue"), Item("green"), Item("blue"))),
        "piles": TaskSpec("piles", (Item("red"), Item("red"), Item("blue"), Item("blue")), piles_by="color"),
    }
    assert set(samples) == set(STRUCTURE_KINDS)
    for name, kind in STRUCTURE_KINDS.items():
        assert kind.recognizer in recognizers, name
        text = render(samples[name])
        schema = parse(text)
        assert extract(schema) == samples[name], (name, text)
        assert any(isinstance(p, kind.predicate) for p in schema.goal.walk()), name
        for w in kind.words:
            assert structure_of_word(w) == structure_of_word(w + "s") == name
    assert STRUCTURE_WORDS["stack"] == "tower"
    assert interpret("make it a ring").ops[-1].params == {"to": "circle"}


@pytest.mark.parametrize("colors", [["green", "green"], ["green", "red", "green"], ["blue", "blue", "blue", "red"]])
def test_canonical_instructions_never_name_one_cube_twice(colors):
    """Steering a patch task whose cubes share a colour states them counted ("two green
    blocks"), and the parser reads back as many cubes as the task has (issue: "the green
    block and the green block" was merged into one cube)."""
    from rpg.schema.structures import cube_list
    from rpg.steer.relations import rewrite_patch

    ref = parse(f"Place {cube_list(colors, 'a')} onto the blue goal patch")
    assert sorted(a.color for a in ref.assets if a.kind == "colored_cube") == sorted(colors)
    text, intent = rewrite_patch("make the patch yellow", ref)
    assert intent == "tweak" and not any(text.count(f"the {c} block") > 1 for c in colors), text
    got = parse(text)
    assert sorted(a.color for a in got.assets if a.kind == "colored_cube") == sorted(colors)
    assert len(got.goal.conjuncts()) == len(colors)


@pytest.mark.parametrize("text,needle", [
    ("Place the green block and the green block onto the blue goal patch", "twice"),
    ("Put the red block to the left of the red block", "itself"),
])
def test_an_instruction_naming_one_cube_twice_is_refused(text, needle):
    from rpg.schema.builtin import ParseError

    with pytest.raises(ParseError, match=needle):
        parse(text)


@pytest.mark.parametrize("edit,expected", [
    # "the tower you just built" is the current tower: an addition, not a new task (issue 30)
    ("put a yellow block on top of the tower you just built", "Build a tower from bottom to top: red, blue, yellow"),
    ("put a yellow block on top of the existing tower", "Build a tower from bottom to top: red, blue, yellow"),
    ("Now add a green block on top of the blue one", "Build a tower from bottom to top: red, blue, green"),
])
def test_an_edit_that_refers_to_what_exists_adds_to_it(edit, expected):
    plan = interpret(edit)
    assert not plan.standalone
    assert render(apply_ops(extract(parse("Stack the blue block on top of the red block")), plan.ops)) == expected


@pytest.mark.parametrize("edit", ["keep the tower and also put a pink block to its left",
                                  "add a pink block to the left of the tower",
                                  "add a white block next to the tower"])
def test_a_cube_added_beside_a_tower_is_refused_not_stacked(edit):
    """Steering adds cubes to the structure itself; one placed beside it used to be stacked
    on top (silently wrong)."""
    spec = extract(parse("Stack the blue block on top of the red block"))
    with pytest.raises(SteerError, match="beside"):
        apply_ops(spec, interpret(edit).ops)


def test_a_cube_added_to_the_left_of_a_line_starts_it():
    line = extract(parse("Put the red, blue and green blocks in a line from left to right"))
    more = apply_ops(line, interpret("add a yellow block to the left").ops)
    assert [i.color for i in more.items] == ["yellow", "red", "blue", "green"]


def test_an_added_structure_is_refused_not_merged_into_the_first(tmp_path):
    """"add a pyramid of 3 yellow blocks" used to add three cubes to the tower (silently wrong): a structure of its own is no
    operation on the tower (a clause added to the task, which here does not read as the tower and a pyramid)."""
    assert not any(o.op == "add" for o in interpret("also add a pyramid of 3 yellow blocks").ops)
    fam = compiled("Build a tower of red, blue and green blocks", tmp_path, name="fam").path
    with pytest.raises(SteerError):
        steer(fam, "keep the tower, and also add a pyramid of 3 yellow blocks")


def test_keep_names_the_structure_the_edit_builds_on():
    tower = extract(parse("Build a tower of red, blue and green blocks"))
    kept = apply_ops(tower, interpret("keep the tower and add a yellow block").ops)
    assert [i.color for i in kept.items] == ["red", "blue", "green", "yellow"]
    circle = apply_ops(tower, interpret("arrange them in a circle").ops)
    with pytest.raises(SteerError, match="keeps a tower, but the version it builds on is a circle"):
        apply_ops(circle, interpret("keep the tower and add a yellow block").ops)


# -- issue 30, item 6: edits written by others (additions, counts, colours, labels, places, refusals) --

def test_a_copied_base_is_the_base_compiled_there(tmp_path):
    """The steering tests' bases come from :func:`tests.helpers.compiled`, which copies a task
    compiled once per test process: the copy is the task compiled in its place, file for file
    but for the gates' timings, and steers to the same version."""
    from rpg.compiler import compile_instruction

    base = "Stack the red block on top of the yellow block"
    here = compile_instruction(base, tmp_path / "here", name="fam")
    compiled(base, tmp_path / "warm", name="fam")
    copy = compiled(base, tmp_path / "copy", name="fam")
    assert copy.path == tmp_path / "copy" / "fam" and copy.valid and copy.content_hash == here.content_hash
    timing = re.compile(r"duration_s|gate \w+ +PASS|\"created\"|validation\.(json|log):")
    for f in sorted(p.name for p in here.path.iterdir()):
        a, b = (here.path / f).read_bytes(), (copy.path / f).read_bytes()
        if f.endswith(".png") or f == "code.py" or f == "goal_state_code.py":
            assert a == b, f
        else:
            strip = [ln for ln in a.decode().splitlines() if not timing.search(ln)]
            assert strip == [ln for ln in b.decode().splitlines() if not timing.search(ln)], f
    r1, r2 = steer(here.path, "add a green block on top"), steer(copy.path, "add a green block on top")
    assert (r1.intent, r1.valid) == (r2.intent, r2.valid) == ("extend", True)
    assert Family(here.path).schema(r1.version) == Family(copy.path).schema(r2.version)


def _meaning_after(tmp_path, base, edits):
    """Steer ``base`` through ``edits``; the last version's meaning and intent."""
    from rpg.schema.meaning import meaning

    fam = compiled(base, tmp_path, name="fam").path
    r = None
    for e in edits:
        r = steer(fam, e)
        assert r.valid, (e, r.notes)
    return sorted(meaning(Family(fam).schema(r.version))), r.intent


@pytest.mark.parametrize("base,edits,expected,intent", [
    # an addition keeps the rest: a clause of its own joins a relation task
    ("Put the cyan block next to the red block", ["also stack a white block on the cyan one"],
     ["next_to(cyan,red)", "stack(cyan,white)"], "extend"),
    ("Put the cyan block next to the red block", ["also stack a white block on it"],
     ["next_to(cyan,red)", "stack(cyan,white)"], "extend"),
    ("Place the orange block next to the cyan block", ["stack a gray block on the orange one"],
     ["next_to(cyan,orange)", "stack(orange,gray)"], "extend"),
    ("Put the red block on the green patch", ["the yellow block too"], ["on_patch(red,yellow,patch:green)"], "extend"),
    # counts: a number said wins over "shorter"; "just two", "four tall"
    ("Build a tower of 5 yellow blocks", ["can you make it a bit shorter, like 3 blocks"], ["stack(yellow,yellow,yellow)"], "tweak"),
    ("stack 3 cyan cubes", ["actually just two please"], ["stack(cyan,cyan)"], "tweak"),
    ("Build a tower of three blue blocks", ["make it four tall"], ["stack(blue,blue,blue,blue)"], "tweak"),
    # colours of the whole structure, of both cubes, of a role
    # (a line of identical cubes in a sequence: no order, meaning() writes the canonical instruction's "sequence")
    ("Make a row of three purple cubes", ["I'd like the row to be green"], ["line(green,green,green)"], "tweak"),
    ("Stack a red block on a blue block", ["both shoud be white"], ["stack(white,white)"], "tweak"),
    ("Place a blue cube on top of a red cube on the table", ["put a green cube on top of that", "and the bottom one purple"],
     ["stack(purple,blue,green)"], "tweak"),
    # labels and words
    ("Stack the number cubes 1, 2 and 3 with 1 at the bottom", ["swap the 3 for a 7"], ["stack(1,2,7)"], "tweak"),
    ("Spell the word CAT with letter cubes from left to right", ["change it to DOG"],
     ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"], "modify"),
    # taking a cube off, moving the structure to a place on the table, layers
    ("Stack the green block on the red block", ["put a yellow one on top", "take the yellow one off again"], ["stack(red,green)"], "tweak"),
    ("Stack the white block on the black block", ["Move the stack to the back of the table."], ["stack(black,white)@back"], "modify"),
    ("Build a pyramid of 6 green blocks", ["make the bottom layer blue"], ["pyramid(blue,blue,blue|green,green|green)"], "tweak"),
    ("Build a wall of gray blocks, 3 wide and 2 high", ["add a third row on top, in black"],
     ["wall(gray,gray,gray|gray,gray,gray|black,black,black)"], "extend"),
    ("Build a pyramid of six yellow blocks", ["make it a wall instead, 3 wide and 2 high"],
     ["wall(yellow,yellow,yellow,yellow,yellow,yellow)"], "pivot"),
])
def test_edits_written_by_others(tmp_path, base, edits, expected, intent):
    assert _meaning_after(tmp_path, base, edits) == (expected, intent)


@pytest.mark.parametrize("base,edit,needle", [
    # must-refuse edits name their real reason
    ("Stack the blue block on the red block", "rotate the top block by 45 degrees", "action"),
    ("Build a tower of four black blocks", "make the blocks twice as big", "size"),
    ("Build a pyramid of 6 green blocks", "make the blue block on top spin around", "action"),
    ("Put the red cube next to the blue cube", "but they must not touch each other", "negation"),
    # an edit that refers to the task but says no change steering reads is refused, not read as a new task
    ("Put the cyan block next to the red block", "make it nicer", "'nicer'"),
    ("Put the cyan block next to the red block", "put it back where it was", "names no change"),
    ("Build a tower of 3 red blocks", "make it a star shape", "shape the domain does not have"),
    # what cannot be stated exactly is refused naming why
    ("Build a tower of 4 red blocks", "make two of them white", "does not say which"),
    ("Stack a red block on a blue block on a green block", "both should be white", "'both' names two cubes"),
])
def test_edits_that_cannot_be_applied_exactly_are_refused(tmp_path, base, edit, needle):
    fam = compiled(base, tmp_path, name="fam").path
    before = (fam / "family.yaml").read_bytes() if (fam / "family.yaml").exists() else None
    with pytest.raises(SteerError, match=needle):
        steer(fam, edit)
    if before is not None:
        assert (fam / "family.yaml").read_bytes() == before


def test_steering_words_live_in_the_lexicon():
    from rpg.schema import lexicon
    from rpg.steer import edits

    assert edits.ANAPHORA_RE is lexicon.EDIT_ANAPHORA_RE and edits.FRESH_RE is lexicon.EDIT_FRESH_RE
    assert interpret("completely different task now: stack three yellow blocks").fresh
    assert not interpret("Stack the red block on top of the yellow block").ops


@pytest.mark.parametrize("base,edit,expected", [
    ("Build a tower from bottom to top: red, green, blue", "make the top 2 blocks yellow",
     "Build a tower from bottom to top: red, yellow, yellow"),
    # a stack in any order stays in any order
    ("Build a tower of red, green and blue blocks", "make the blue one yellow", "Build a tower: red, green, yellow"),
    ("Build a tower of 3 red blocks", "add one more", "Build a tower from bottom to top: red, red, red, red"),
    ("Build a tower of 3 red blocks", "now a line instead", "Align 3 blocks in a single straight line: red, red, red"),
    ("Put the green block on the red patch", "put a purple block on the patch too",
     "Place the green block and the purple block onto the red goal patch"),
    # "it" of a relation is the cube it moves; sizes said "3 by 3"; a word to spell; a colour "instead"
    ("Place the red block behind the yellow block", "make it blue", "Place the blue block behind the yellow block"),
    ("Make a 2x2 grid of red blocks", "make it 3 by 3", "Make a 3x3 grid of red blocks"),
    ("Spell CAT with letter cubes", "make it spell DOG", "Spell the word 'DOG' using letter cubes arranged in a line from left to right"),
    ("Build a tower of 3 red blocks", "use blue instead", "Build a tower from bottom to top: blue, blue, blue"),
    # a stack in any order with one end said: that end kept, a cube added on top is the top said
    ("Build a tower of 4 blocks with a black block at the bottom", "make the bottom one white",
     "Stack the white block, the red block, the blue block and the green block with the white block at the bottom"),
    ("Build a tower of red, green and blue blocks", "add a yellow block on top",
     "Stack the red block, the green block, the blue block and the yellow block with the yellow block on top"),
    # "it" of a two-cube stack is the stack: a cube beside it stands by its lower cube
    ("Stack the red block on the blue block", "put a green block next to it",
     "Stack the red block on the blue block, then place the green block next to the blue block"),
    # "from the left to the right": the relation after "to"; "instead of on top": the old one
    ("Put the red block to the left of the blue block", "move it from the left side to the right side",
     "Place the red block to the right of the blue block"),
    ("Put the pink block on top of the gray block", "put it next to the gray block instead of on top",
     "Place the pink block next to the gray block"),
    # "2 more", "4 instead of 3", "in blue", the material an edit changes from, a cube moved onto the patch too
    ("Build a tower of 3 green blocks", "can you use 2 more blocks",
     "Build a tower from bottom to top: green, green, green, green, green"),
    ("Build a tower of 3 green blocks", "make it 4 blocks instead of 3", "Build a tower from bottom to top: green, green, green, green"),
    ("Build a tower of 3 green blocks", "I'd like it in blue", "Build a tower from bottom to top: blue, blue, blue"),
    ("Spell the word HI with letter cubes", "change the letters to numbers",
     "Arrange the blocks in order digit '1', digit '2' from left to right"),
    ("Place the blue block on the yellow patch", "now move the red block onto the patch too",
     "Place the blue block and the red block onto the yellow goal patch"),
    ("Build a tower of 3 green blocks", "scratch that, build a line of 3 red blocks", "build a line of 3 red blocks"),
    # "N blocks shorter" is N; a lone capital is a letter cube
    ("Build a tower of 5 yellow blocks", "make it 2 blocks shorter", "Build a tower from bottom to top: yellow, yellow, yellow"),
    ("Stack the letter cubes A, B and C with A at the bottom", "swap A and C",
     "Build a tower from bottom to top: letter 'C', letter 'B', letter 'A'"),
    # an edit opened by "and" keeps the task
    ("Put the red block to the left of the blue block", "and a yellow block on the blue block",
     "Place the red block to the left of the blue block, then place the yellow block on top of the blue block"),
    # a relation's or a patch's cubes made a structure: in no order, since nobody said one
    ("Put the red block to the left of the blue block", "stack them", "Build a tower: red, blue"),
    ("Put the red block and the yellow block on the green patch", "make a row of them instead",
     "Align 2 blocks in a single straight line: red, yellow"),
    # a cube added beside a structure, in a clause of its own: the structure kept
    ("Put the red block on the blue block", "now put a green block on the table to the left of the blue block",
     "Put the red block on the blue block, then put a green block on the table to the left of the blue block"),
    ("Build a pyramid of 6 green blocks", "make the top layer red and the bottom layer blue",
     "Build a pyramid of blue, green and red blocks with a base of 3 with 3 blue blocks at the bottom, 2 green blocks in the "
     "middle and 1 red block on top"),
    ("Stack the red block on the blue block", "put it in the middle of the table",
     "Build a tower in the center of the table from bottom to top: blue, red"),
    ("Make a row of 4 brown blocks", "make two of them white",
     "Align 4 blocks in a single straight line: 2 brown blocks and 2 white blocks"),
    ("Stack the letter cubes A, B and C with A at the bottom", "put a D on top",
     "Build a tower from bottom to top: letter A, letter B, letter C, letter D"),
])
def test_edit_instructions_state_exactly_what_was_asked(base, edit, expected):
    """The canonical instruction an edit gives (parse only: no compile)."""
    from rpg.steer.steering import plan_schema

    class One:
        def schema(self, v):
            return parse(base)

    _, instruction, _ = plan_schema(interpret(edit), One(), 0)
    assert instruction == expected


@pytest.mark.parametrize("base,edit,needle", [
    # an addition on a cube that is not the tower's end, or beside an unordered line's end
    ("Build a tower from bottom to top: red, green, blue", "put a yellow block on top of the red one", "not the top"),
    ("Build a tower of red, green and blue blocks", "make the top one white", "no cube the top place"),
    ("Build a tower of red, green and blue blocks", "put the blue one at the bottom", "no places"),
    # a cube beside a stack's upper cube stands in the air; a second relation between two related cubes contradicts
    ("Stack the red block on the blue block", "add a green block next to the red one", "in the air"),
    ("Put the yellow block in front of the purple block", "stack the yellow block on the purple block too", "contradict"),
    # "the patch" is the task's patch, not a new one of a colour nobody said
    ("Place the blue block on the yellow patch", "put the blue block next to the patch instead", "nobody named"),
    # a distance, and edits that contradict themselves
    ("Put the red block next to the blue block", "move them closer together", "distance"),
    ("Put the red block next to the blue block", "put it on the left and on the right", "contradicts"),
    ("Build a tower of 3 red blocks", "make it taller and shorter", "contradicts"),
    # a number no operation uses; a cube in front of "both" (no one relation)
    ("Stack the yellow block on the green block", "make the tower 3 blocks high using a red block", "'3' has no place|'a red block' 1 times"),
    ("Put the blue block next to the red block", "put a cyan cube in front of both", "cannot add"),
    # a vague degree is no count; a stack in any order with its bottom said takes no second end
    ("Build a tower of 3 red blocks", "make it a bit taller", "vague quantity"),
    ("Build a tower of 4 blocks with a black block at the bottom", "add a red block on top", "one end said"),
    # a cube named as if it were there ("the green block") that the task lacks
    ("Stack the red block on the blue block", "now add a yellow one on top of the green block", "no green cube"),
    ("Build a tower from bottom to top: red, green, blue", "remove the red and the blue block", "'blue' has no place"),
    ("Build a tower of red, green and blue blocks", "make it 2 towers", "names no change"),
    ("Align 3 blocks in a single straight line: red, green, blue", "add a yellow block at the right end", "gives no cube a place"),
    ("Align 3 blocks in a single straight line: red, green, blue", "reverse it", "no order"),
    # a pivot that would change how many cubes there are, a colour left unread
    ("Place 5 blocks in a circle", "make it a square instead", "not made of 5 cubes"),
])
def test_edits_not_applied_exactly_are_refused_before_compiling(base, edit, needle):
    from rpg.steer.steering import plan_schema

    class One:
        def schema(self, v):
            return parse(base)

    with pytest.raises(SteerError, match=needle):
        plan_schema(interpret(edit), One(), 0)


def test_an_addition_to_a_relation_names_its_cube_by_one(tmp_path):
    """"behind the purple one" is the purple block (it was read as the task's subject)."""
    from rpg.steer.relations import rewrite

    text, intent = rewrite("add a brown block behind the purple one", parse("Put the yellow block in front of the purple block"))
    assert intent == "extend" and text.endswith("place the brown block behind the purple block")


def test_an_edit_that_changes_nothing_is_refused(tmp_path):
    """An edit of the current version whose goal comes out as it was was not read as meant."""
    fam = compiled("Build a tower of 3 red blocks", tmp_path, name="fam").path
    before = (fam / "family.yaml").read_bytes() if (fam / "family.yaml").exists() else None
    with pytest.raises(SteerError, match="changes nothing"):
        steer(fam, "make it red")
    if before is not None:
        assert (fam / "family.yaml").read_bytes() == before


@pytest.mark.parametrize("base, edit, colors", [
    ("Line up a yellow, a green and a blue block from left to right", "add a red block at the left end",
     ["red", "yellow", "green", "blue"]),
    ("Line up a yellow, a green and a blue block from right to left", "add a red block at the left end",
     ["yellow", "green", "blue", "red"]),
    ("Line up a yellow, a green and a blue block from left to right", "add a red block at the right end",
     ["yellow", "green", "blue", "red"]),
])
def test_a_cube_added_at_a_named_end_of_a_directed_line_goes_there(base, edit, colors):
    """"add a red block at the left end" of a left-to-right line appended it on the right."""
    assert apply_ops(extract(parse(base)), interpret(edit).ops).colors() == colors


def test_a_line_has_no_end_across_its_direction():
    from rpg.steer.edits import SteerError

    with pytest.raises(SteerError, match="has no front end"):
        apply_ops(extract(parse("Line up a yellow, a green and a blue block from left to right")),
                  interpret("add a red block at the front end").ops)


def _steered(tmp_path, base: str, *edits: str, build_last: bool = False):
    """(intent, meaning) of each edit applied in turn to a compiled base: each but the last built and recorded, the last
    read and checked as ``rpg steer --dry-run`` does (what these tests ask of it; ``build_last`` builds it too, and the
    tests of building, recording and reusing versions build every one)."""
    from rpg.schema.meaning import meaning

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    out = []
    for i, e in enumerate(edits):
        preview = i == len(edits) - 1 and not build_last
        r = steer(fam.path, e, dry_run=preview)
        if preview:
            out.append((r.intent, meaning(r.schema)))
            continue
        assert r.valid, (e, r.notes)
        out.append((r.intent, meaning(fam.schema(r.version))))
    return out


@pytest.mark.parametrize("edit", ["and the blue block in the front right corner", "also the blue block in the front right corner"])
def test_a_cube_the_task_lacks_placed_in_a_region_is_added(tmp_path, edit):
    """It moved the task's red cube to the blue cube's corner (an addition read as a replacement)."""
    assert _steered(tmp_path, "Put the red block in the front left corner", edit) == [
        ("extend", ["in_region(blue,front_right)", "in_region(red,front_left)"])]


def test_the_tower_put_on_a_side_is_placed_there_whole(tmp_path):
    """"put the tower on the left side" compiled the tower's cubes side by side (left_of)."""
    assert _steered(tmp_path, "Put the orange block on top of the cyan block", "put the tower on the left side",
                    "add a pink block on top") == [("modify", ["stack(cyan,orange)@left"]),
                                                   ("extend", ["stack(cyan,orange,pink)@left"])]


def test_the_same_blocks_keep_their_colour_in_a_new_structure(tmp_path):
    """"same blocks, but make two towers of four" of eight orange blocks built red and blue towers."""
    assert _steered(tmp_path, "Arrange eight orange blocks in a circle", "same blocks, but make two towers of four") == [
        ("pivot", ["stack(orange,orange,orange,orange)", "stack(orange,orange,orange,orange)"])]


@pytest.mark.parametrize("base, edit, kind", [
    ("stack the red block on the blue block", "put them in a row", "InLine"),
    ("line up the red, green and blue blocks from left to right", "stack them instead", "UnorderedStack"),
])
def test_a_structure_turned_into_another_has_no_order_nobody_said(tmp_path, base, edit, kind):
    """"put them in a row" of a stack gave a left-to-right line in the stack's order."""
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    r = steer(fam.path, edit)
    goal = fam.schema(r.version).goal_predicate()
    assert r.intent == "pivot" and type(goal).__name__ == kind and getattr(goal, "order", None) is None


@pytest.mark.parametrize("base, edits, want", [
    # two letters swapped, as the parser reads them
    ("build a tower of 3 red blocks", ["pls mkae the tower blue"], ["stack(blue,blue,blue)"]),
    # a correction opened by "no wait," is no negation, and "right next to" no side
    ("Put the white block on top of the blue block", ["no wait, put it right next to the blue block instead of on it"],
     ["next_to(blue,white)"]),
    # a verbless addition; "on top of that" is on top of the task
    ("Stack the letter cube O on the letter cube R", ["put a B on top of the tower you just built", "and a T on top of that"],
     ["stack(R,O,B,T)"]),
    # a count said alone is the structure's count
    ("Arrange five pink cubes in a circle", ["let's go with 7 instead"], ["circle(pink,pink,pink,pink,pink,pink,pink)"]),
    ("stack 2 red cubes", ["three"], ["stack(red,red,red)"]),
    # ... and cubes of one colour on a patch stay that colour (a red cube had been added)
    ("Put 2 blue cubes on the orange patch", ["3 instead"], ["on_patch(blue,blue,blue,patch:orange)"]),
    # "one more row" grows the wall (it had pivoted to a line of four default cubes)
    ("Build a wall of red blocks, 4 wide and 2 high", ["one more row"],
     ["wall(red,red,red,red,red,red,red,red,red,red,red,red)"]),
    # a row of one colour moved: no order of interchangeable cubes is demanded
    ("Put three green blocks in a row", ["move the row to the back of the table"], ["line(green,green,green)@back"]),
    # a place alone, a patch's colour said as "should be", a count after "taller", "side by side" (each was refused)
    ("Place the gray cube on the left side of the table", ["now the right side"], ["in_region(gray,right)"]),
    ("Put the green cube on the red patch", ["no wait, the patch should be blue"], ["on_patch(green,patch:blue)"]),
    ("Build a tower of two orange blocks in the back right corner", ["make it taller, 4 blocks"],
     ["stack(orange,orange,orange,orange)@back_right"]),
    ("Put the white block on the black block", ["put them side by side instead"], ["next_to(black,white)"]),
    # "and now a blue one on top" adds; "that blue one" is the blue cube; "lay them out" puts them (each was refused)
    ("Put the green cube on top of the red cube", ["and now a blue one on top", "no wait, make that blue one white"],
     ["stack(red,green,white)"]),
    ("Put the cyan block on the red block", ["lay them out in a line instead"], ["line(cyan,red)"]),
    # a far relation, a typo'd "add" (both were refused)
    ("Put the blue block next to the orange block", ["actually they should be far apart"], ["far_from(blue,orange)"]),
    ("Make a stack with brown on the bottom and orange on top", ["ad a yelow block on top"], ["stack(brown,orange,yellow)"]),
    # a line stacked "in the same order": first cube at the bottom, or from the end the colour names
    ("Make a row of red, white and blue blocks from left to right",
     ["now stack them instead, in the same order, with red at the bottom"], ["stack(red,white,blue)"]),
    ("Make a row of red, white and blue blocks from left to right", ["stack them in the same order with blue at the bottom"],
     ["stack(blue,white,red)"]),
    # a cube taken off a patch it shares, a cube moved from a patch to a place and from a place to a patch (each refused)
    ("Put the cyan cube and the pink cube on the yellow patch", ["get rid of the pink one"], ["on_patch(cyan,patch:yellow)"]),
    ("Place the black cube on the green patch", ["Move it to the left side of the table instead."], ["in_region(black,left)"]),
    ("put the orange cube in the back left corner", ["put it on a purple patch instead"], ["on_patch(orange,patch:purple)"]),
    # "the blue one" moves the blue cube (the relation had been turned the other way), and both cubes may be said
    ("stack red on blue", ["put that blue one on the left"], ["left_of(blue,red)"]),
    ("Put the green cube to the left of the red cube", ["actually the green one should go in front of the red one"],
     ["in_front_of(green,red)"]),
    # a cube counted from an end (the bottom cube had been painted: silently wrong)
    ("Build a tower of five yellow cubes", ["paint the 2nd one from the bottom red"], ["stack(yellow,red,yellow,yellow,yellow)"]),
    ("Build a tower of red, blue, green and yellow from bottom to top", ["make the 2nd from the top pink"],
     ["stack(red,blue,pink,yellow)"]),
    # a new structure's place said with it (the old corner had been kept: silently wrong)
    ("Stack three blue cubes in the front right corner", ["make it a line along the front instead"], ["line(blue,blue,blue)@front"]),
    # counts said alone in a stranger's words, a casual verb, a cube taken off, a corner without "corner"
    ("Build a tower of five purple blocks", ["actually, three"], ["stack(purple,purple,purple)"]),
    ("Build a tower of 3 green blocks", ["three more"], ["stack(green,green,green,green,green,green)"]),
    ("Put two pink cubes in a row", ["make that seven pink cubes pls"], ["line(pink,pink,pink,pink,pink,pink,pink)"]),
    ("Stack a red cube on a yellow cube", ["and pop a green one on top of that"], ["stack(yellow,red,green)"]),
    ("Build a tower of four blue blocks", ["take one off"], ["stack(blue,blue,blue)"]),
    ("Build a tower of three red cubes in the back left corner", ["move it to the front right"], ["stack(red,red,red)@front_right"]),
    # the two colours exchanged; a plural colour recoloured
    ("Stack a green cube on a yellow cube", ["swap the colours"], ["stack(green,yellow)"]),
    ("Make a row of four cubes from left to right: red, blue, red, blue", ["change the blues to green"],
     ["line[left_to_right](red,green,red,green)"]),
    # additions: a cube "too", a second cube of a colour on the same patch, a kept tower and a clause
    ("Put the white cube on the green patch", ["now the black cube goes on the red patch too"],
     ["on_patch(black,patch:red)", "on_patch(white,patch:green)"]),
    ("Put the green block on the blue patch", ["put a second green block on the same patch"], ["on_patch(green,green,patch:blue)"]),
    ("Stack three green cubes", ["Right, keep the tower, and also put a pink cube on the orange patch"],
     ["on_patch(pink,patch:orange)", "stack(green,green,green)"]),
    # a letter said alone, a new stack of two colours, an opening "fine." and closing "then", "the cube" of one cube
    ("Build a tower of letter cubes with A at the bottom, then B, then C on top", ["put D on top"], ["stack(A,B,C,D)"]),
    ("Stack the white block on the blue block", ["make it blue on white instead"], ["stack(white,blue)"]),
    ("Put the blue cube on the pink patch", ["fine. make the cube white then"], ["on_patch(white,patch:pink)"]),
])
def test_edits_said_in_fewer_or_looser_words(tmp_path, base, edits, want):
    assert _steered(tmp_path, base, *edits)[-1][1] == want


@pytest.mark.parametrize("base, edits, want", [
    ("Put the black block on the yellow patch", ["scrap this and start again: put the green cube between the red cube "
                                                 "and the white cube"], ("fresh", ["between(green;red,white)"])),
    # "the same patch" is the task's one patch; a cube added to a patch keeps the cube already there
    ("Place a red cube on the green patch", ["also a blue cube on the same patch"], ("extend", ["on_patch(blue,red,patch:green)"])),
])
def test_more_edits_said_in_other_words(tmp_path, base, edits, want):
    assert _steered(tmp_path, base, *edits)[-1] == want


@pytest.mark.parametrize("base, edit, want", [
    ("Put the red block next to the blue block and the green block behind the blue block", "get rid of the green block",
     ("tweak", ["next_to(blue,red)"])),
    ("Put the red block on the green patch and the blue block in the back left corner", "take the red one away",
     ("tweak", ["in_region(blue,back_left)"])),
    # an addition opened by "and" keeps the task (it was read as a whole new task, the base dropped)
    ("put the red block on the green patch", "and the blue block in the front right corner",
     ("extend", ["in_region(blue,front_right)", "on_patch(red,patch:green)"])),
    ("Put the red block in the front left corner", "and the blue block on the green patch",
     ("extend", ["in_region(red,front_left)", "on_patch(blue,patch:green)"])),
])
def test_removals_and_additions_of_cubes_among_relations(tmp_path, base, edit, want):
    """Removing a cube from a task of relations takes its relations with it (it was refused: "not a
    structure the builtin steering edits in place")."""
    assert _steered(tmp_path, base, edit) == [want]


@pytest.mark.parametrize("base, edit, match", [
    ("build a tower of 3 red blocks", "no red blocks please", "negation"),  # "no" before a noun is still a negation
    ("Put the red block next to the green block", "wait, can the robot even reach the green block?", "asks a question"),
    ("Put the red block next to the blue block", "remove the blue block", "no goal left"),  # every relation needs it
    ("Put the red block in the front left corner", "also a red block in the front right corner", "cannot add"),
    ("stack the red block on the blue block", "same blocks, but make two towers of four", "keeps the task's 2 cubes"),
    # the colour said for the bottom stands at neither end of the kept order
    ("Make a row of red, white and blue blocks from left to right", "stack them in the same order with white at the bottom",
     "is not at exactly one end"),
    # a comparative and a count that disagree (the tower had shrunk), and one cube of two named by colour (both changed)
    ("build a tower of three green cubes", "make it taller, 2 blocks", "disagree"),
    ("build a tower of two blue blocks and one red block on top", "make that blue one green", "names one of the task's 2 blue"),
    ("stack red, blue and green", "swap the colours", "names two colours"),
    ("Stack a red cube on a yellow cube", "and paint it beige", "palette"),  # a colour, not an action
    # found by the attack: a count from no end, several places at once, the wrong axis, a line's "top" (each had been
    # read silently: from the bottom, the first only, across the axis, at the line's right end)
    ("Build a tower of red, blue and white from bottom to top", "swap the 1st and 2nd from the top", "counted from an end nobody"),
    ("Build a tower of red, blue, green and yellow from bottom to top", "make the second and third from the bottom white",
     "several cubes"),
    ("Build a tower of red, blue, green and yellow from bottom to top", "remove the 2nd from the left", "count from its bottom"),
    ("Make a row of red, blue, green from left to right", "make the 2nd one from the bottom white", "count from its left"),
    ("Make a row of red, blue, green from left to right", "put a yellow one on top", "no top or bottom"),
    ("Put two pink cubes in a row", "make that 3 green cubes", "has no place in the change"),
])
def test_edits_refused_for_their_reason(tmp_path, base, edit, match):
    fam = compiled(base, tmp_path, name="fam").path
    with pytest.raises(SteerError, match=match):
        steer(fam, edit)


def test_a_patch_recoloured_with_another_colour_said_is_not_read_as_the_patch_alone(tmp_path):
    from rpg.errors import BadInput

    fam = compiled("put the red cube on the yellow patch", tmp_path, name="fam").path
    with pytest.raises(BadInput):  # the cube's new colour had been dropped silently
        steer(fam, "the patch should be blue and the cube green")


@pytest.mark.parametrize("base,edit,match", [
    # steer_stranger4 (eighth session): each compiled silently wrong before
    ("Place a red cube in the left half of the table", "and a blue one on the right", "adds none|have no place"),  # red moved
    ("Make a line of three purple cubes", "add two yellow ones at each end", "two places"),  # one end dropped
    # (one cube at each end is read since the sixteenth session: test_edits_said_in_other_words_read_as_their_operation)
    ("Stack blue on red", "swap the red for the yellow one we used before", "earlier turn"),  # no such cube
])
def test_steering_refuses_what_it_would_apply_wrong(tmp_path, base, edit, match):
    r = compiled(base, tmp_path, name="fam")
    fam = create_family(r.path)
    before = (Path(fam.path) / "family.yaml").read_bytes()
    with pytest.raises(SteerError, match=match):
        steer(fam.path, edit)
    assert (Path(fam.path) / "family.yaml").read_bytes() == before  # nothing half-written


@pytest.mark.parametrize("edit, ops", [
    # steer_stranger13's edits said in words the edit reader had not known (each refused)
    ("now five instead of three", [("count", {"count": 5})]),
    ("extend it to spell STOP", [("word", {"word": "STOP"})]),
    ("what if the base was black", [("recolor", {"select": {"position": "bottom"}, "to": {"color": "black"}})]),
    ("same but in yellow", [("recolor", {"select": {"all": True}, "to": {"color": "yellow"}})]),
    ("add a third", [("add", {"items": [], "count": 1, "at": "top"})]),
    # the middle cube replaced (it had been added in the table's centre, the yellow one kept)
    ("use a purple cube in the middle instead of the yellow one",
     [("recolor", {"select": {"color": "yellow"}, "to": {"color": "purple"}})]),
    # steer_stranger14: another word in capitals; a cube at both ends
    ("make it HELLO", [("word", {"word": "HELLO"})]),
    ("BED -> BAD", [("word", {"word": "BAD"})]),
    ("make it RED", [("recolor", {"select": {"all": True}, "to": {"color": "red"}})]),  # a colour, not a word
    ("and add a red at each end", [("add", {"items": [{"color": "red"}], "count": None, "at": "bottom"}),
                                   ("add", {"items": [{"color": "red"}], "count": None, "at": "top"})]),
])
def test_edits_said_in_other_words_read_as_their_operation(edit, ops):
    assert [(o.op, o.params) for o in interpret(edit).ops] == ops


def test_a_cube_put_on_a_patch_the_relation_lacks_is_an_addition(tmp_path):
    """"and the green one on the red patch" of yellow next to green had become green on yellow
    (the patch dropped; steer_stranger13)."""
    assert _steered(tmp_path, "Put the yellow cube next to the green cube", "and the green one on the red patch")[-1] == (
        "extend", ["next_to(green,yellow)", "on_patch(green,patch:red)"])


def test_a_cube_on_a_patch_added_to_a_between_task_lays_out(tmp_path):
    """The cube on the new patch and the middle cube had been laid at one spot; validation failed (exit 1)."""
    assert _steered(tmp_path, "Put the orange cube between the white cube and the black cube",
                    "and put a red cube on the green patch too")[-1] == (
        "extend", ["between(orange;black,white)", "on_patch(red,patch:green)"])


def test_a_cube_added_inside_a_structure_is_refused_not_put_at_the_end():
    """"add another O right after the first one" of GOD had made GODO (steer_stranger14)."""
    with pytest.raises(SteerError, match="inside the structure"):
        interpret("add another O right after the first one")


def test_a_cube_added_left_of_a_cube_in_a_region_is_a_relation_and_a_bare_side_moves_it(tmp_path):
    """"and a pink cube to the left of it" had put pink in the table's left side (steer_stranger14);
    "nah right side" had been refused."""
    assert _steered(tmp_path, "Put the black cube in the center of the table", "and a pink cube to the left of it")[-1] == (
        "extend", ["in_region(black,center)", "left_of(pink,black)"])
    assert _steered(tmp_path / "b", "Place the red cube on the left side of the table", "nah right side")[-1] == (
        "modify", ["in_region(red,right)"])


def test_a_cube_put_onto_a_new_cube_is_not_a_cube_added_on_top():
    """"put it on a yellow one" of blue on green had added yellow on top of blue (steer_stranger8)."""
    plan = interpret("put it on a yellow one then")
    assert not any(o.op == "add" for o in plan.ops)
    plan = interpret("put a yellow one on it")
    assert [o.params["items"] for o in plan.ops if o.op == "add"] == [[{"color": "yellow"}]]


def test_a_label_put_on_a_label_is_not_added_twice():
    """"then put C on A" of A on B had become B, A, C, A (the anchor A added as a cube)."""
    plan = interpret("then put C on A")
    assert all(o.op != "add" or [i.get("label") for i in o.params["items"]] == ["C"] for o in plan.ops)


@pytest.mark.parametrize("base, edits, want", [
    # a misspelt word of the vocabulary, corrected before the edit is read ("ontop", "yelow", "insted")
    ("Put the black cube next to the white cube", ["actually put it ontop of the white one"], ("modify", ["stack(white,black)"])),
    ("Put a red cube, a green cube and a blue cube in a line from left to right", ["and stick a yelow one on the far right end"],
     ("extend", ["line[left_to_right](red,green,blue,yellow)"])),
    ("Build a tower of three blue cubes", ["put a red one at the bottom insted of a blue one"], ("tweak", ["stack(red,blue,blue)"])),
    # "nah" opens a correction; a cube next to a patch put on it
    ("Put the orange cube next to the green patch", ["nah put it ON the patch"], ("modify", ["on_patch(orange,patch:green)"])),
    # a count said as "enough"
    ("Place three white cubes on the black patch", ["just one is enough tbh"], ("tweak", ["on_patch(white,patch:black)"])),
    # a place on the table said alone, or "along" an edge, or by the structure's noun
    ("Build a tower of three orange cubes", ["fine, front of the table then"], ("modify", ["stack(orange,orange,orange)@front"])),
    ("Put a green cube in the front right corner", ["other corner - front left"], ("modify", ["in_region(green,front_left)"])),
    ("Put three blue cubes in a line", ["and put it along the left edge"], ("modify", ["line(blue,blue,blue)@left"])),
    # two related cubes moved together keep their relation
    ("Put the yellow cube to the right of the purple cube", ["move both of them to the back of the table"],
     ("modify", ["in_region(purple,back)", "in_region(yellow,back)", "right_of(yellow,purple)"])),
    # a cube at one end of an ordered line moved to the other end
    ("Put three cubes in a row: purple, orange, cyan from left to right", ["move the purple one to the other end"],
     ("modify", ["line[left_to_right](orange,cyan,purple)"])),
    # a row "of red cubes" added on top of a wall, then its colour corrected ("green not red")
    ("Build a wall of blue cubes, 4 long and 2 high", ["add a third row of red cubes on top", "make that top row green not red"],
     ("tweak", ["wall(blue,blue,blue,blue|blue,blue,blue,blue|green,green,green,green)"])),
])
def test_edits_of_a_stranger_set_said_loosely(tmp_path, base, edits, want):
    """Each was refused (steer_stranger4.yaml's first run)."""
    assert _steered(tmp_path, base, *edits)[-1] == want


@pytest.mark.parametrize("base, edit, match", [
    ("Put three cubes in a row: purple, orange, cyan from left to right", "move the orange one to the other end", "no one end"),
    ("Put the yellow cube to the right of the purple cube", "move it to the back of the table", "not a structure"),
    ("Build a tower of red, blue and green cubes", "move the green one to the other end", "no places"),
])
def test_loose_edits_that_stay_refused(tmp_path, base, edit, match):
    """"The other end" of a cube in the middle; "it" of two related cubes (which one moves?); a cube of an unordered tower."""
    fam = compiled(base, tmp_path, name="fam").path
    with pytest.raises(SteerError, match=match):
        steer(fam, edit)


@pytest.mark.parametrize("base, edits, want", [
    # the roles of a cube between two others said by place (each was refused)
    ("Put the yellow block between the red block and the green block", ["make the middle one purple"],
     ("tweak", ["between(purple;green,red)"])),
    ("Put the pink cube between the two cyan cubes", ["Make the outer two white, if you would."], ("tweak", ["between(pink;white,white)"])),
    # one colour for another, said with an arrow
    ("Put the brown cube in front of the black cube", ["brown -> grey"], ("tweak", ["in_front_of(gray,black)"])),
])
def test_roles_of_a_between_and_a_colour_said_with_an_arrow(tmp_path, base, edits, want):
    assert _steered(tmp_path, base, *edits)[-1] == want


def test_the_outer_two_of_ends_of_two_colours_is_refused(tmp_path):
    fam = compiled("Put the yellow block between the red block and the green block", tmp_path, name="fam").path
    with pytest.raises(SteerError, match="at once"):
        steer(fam, "make the outer two white")


@pytest.mark.parametrize("base, edits, want", [
    # "other way round" had pivoted to a circle of six red cubes ("round"); a cube "in the middle" of a between to a
    # cube in the table's centre (the two others dropped)
    ("Put the red cube to the left of the blue cube", ["other way round"], ("modify", ["left_of(blue,red)"])),
    ("Place the black cube between the red cube and the blue cube", ["use a gray one in the middle instead"],
     ("tweak", ["between(gray;blue,red)"])),
    # an instruction's "but put them" and "at the start" are a correction and a time; an edit's are the change itself
    ("Stack a red block, then a green block, then a blue block, from bottom to top",
     ["keep the colours but lay them out in a row from left to right, the bottom one on the left"],
     ("pivot", ["line[left_to_right](red,green,blue)"])),
    ("Make a line of red, green and blue from left to right", ["add a yellow one at the start"],
     ("extend", ["line[left_to_right](yellow,red,green,blue)"])),
])
def test_edits_a_fifth_stranger_found_read_wrong(tmp_path, base, edits, want):
    assert _steered(tmp_path, base, *edits)[-1] == want


def test_a_whole_task_reading_that_drops_cubes_nobody_said_to_drop_is_refused(tmp_path):
    """"blacks on the left, whites on the right" of a line of six had become one black cube left of one white one:
    refused, by steering ("new task of 2 cubes") or, since colours as plural nouns are read, by the parser (the black
    cubes it names are several, the reading has one)."""
    from rpg.errors import BadInput

    fam = compiled("Make a line of six cubes, three black and three white, in any order", tmp_path, name="fam").path
    with pytest.raises(BadInput, match=r"new task of \d cubes|names several black cubes"):
        steer(fam, "blacks on the left, whites on the right")


@pytest.mark.parametrize("base, edits, want", [
    # an edit going on from the task, or stacking a new cube on one of its cubes, had replaced the task:
    # the cubes below were dropped (stack(red,green) of red on blue), silently
    ("Put the red cube on the blue cube", ["then put the green cube on the red cube"], ("extend", ["stack(blue,red,green)"])),
    ("Put the red cube on the blue cube", ["now put the green cube on the red cube"], ("extend", ["stack(blue,red,green)"])),
    ("Put the A cube on the B cube", ["then put C on A", "actually the other way up"], ("modify", ["stack(C,A,B)"])),
    # a cube moved to another landmark is still a tweak of the task
    ("Put the red cube on the blue cube", ["put the red cube on the yellow cube"], ("tweak", ["stack(yellow,red)"])),
])
def test_an_edit_that_builds_on_the_task_keeps_it(tmp_path, base, edits, want):
    assert _steered(tmp_path, base, *edits)[-1] == want


def test_a_new_word_and_the_letter_it_adds_is_one_change(tmp_path):
    """"make it ROBOTS, add an S" had spelled ROBOTSS (steer_stranger6)."""
    [(_, got)] = _steered(tmp_path, "Place the letter cubes R, O, B, O, T in a row so they spell ROBOT", "make it ROBOTS, add an S")
    assert got[0] == "line[left_to_right](R,O,B,O,T,S)"


def test_a_pivot_to_a_stack_keeps_the_order_it_states(tmp_path):
    """"put them in a stack instead, H on top of I" had stacked H under I (steer_stranger6)."""
    [(_, got)] = _steered(tmp_path, "Arrange the letter cubes H and I in a row so they spell HI",
                          "put them in a stack instead, H on top of I")
    assert got == ["stack(I,H)"]


def test_a_walls_top_row_is_its_top_layer(tmp_path):
    """"the top row should be red" had turned a wall into a line of four (steer_stranger6)."""
    assert _steered(tmp_path, "Make a wall: bottom row two yellow cubes, top row two green cubes", "the top row should be red") \
        == [("tweak", ["wall(yellow,yellow|red,red)"])]


def test_each_row_of_a_wall_made_wider_is_its_width(tmp_path):
    """"make each row three cubes wide" had turned a wall into a line of three (steer_stranger6)."""
    assert _steered(tmp_path, "Make a wall: bottom row two yellow cubes, top row two red cubes", "make each row three cubes wide") \
        == [("tweak", ["wall(yellow,yellow,yellow|red,red,red)"])]


@pytest.mark.parametrize("base,edit,expected", [
    # edits said in fewer words (steer_stranger6): each had been refused
    ("Put three green cubes in a line", "one more", ("extend", ["line(green,green,green,green)"])),
    ("Put the orange cube in the front left corner of the table", "no wait, back right", ("modify", ["in_region(orange,back_right)"])),
    ("Arrange six red cubes in a circle", "all yellow now pls", ("tweak", ["circle(yellow,yellow,yellow,yellow,yellow,yellow)"])),
    ("stack four purple cubes", "taller. six", ("tweak", ["stack(purple,purple,purple,purple,purple,purple)"])),
    ("stack four purple cubes", "Fresh task please, a line of four blue cubes at the back of the table",
     ("fresh", ["line(blue,blue,blue,blue)@back"])),
    ("Put the blue cube on the red patch and the yellow cube on the green patch", "same thing without the yellow cube",
     ("tweak", ["on_patch(blue,patch:red)"])),
    ("line up blue, yellow, red from left to right", "and put that line on the right side of the table",
     ("modify", ["line[left_to_right](blue,yellow,red)@right"])),
])
def test_edits_said_in_fewer_words(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit) == [expected]


@pytest.mark.parametrize("base,edit,expected", [
    # a shape alone keeps the task's cubes (steer_stranger7): "as a row" had become a row of four invented cubes
    ("Stack the green cube on the blue cube", "as a row", ("pivot", ["line(blue,green)"])),
    ("Stack the cubes from bottom to top: yellow, purple, white", "same cubes but as a row", ("pivot", ["line(purple,white,yellow)"])),
    # it had been refused: "make a row" had read as a new row of four cubes nobody named
    ("build a tower of red, blue and green", "same blocks, but make a row", ("pivot", ["line(blue,green,red)"])),
    # a cube added beside a cube on a patch stands beside it (it had been put on the patch too, or laid out 3 cm away)
    ("Put a red cube on the green patch", "plus a purple cube next to the red one",
     ("extend", ["next_to(purple,red)", "on_patch(red,patch:green)"])),
    ("Put the blue cube on the red patch", "with a yellow cube right next to the blue one",
     ("extend", ["next_to(blue,yellow)", "on_patch(blue,patch:red)"])),
])
def test_a_shape_alone_keeps_the_cubes_and_a_cube_beside_a_patch_cube_stands_beside_it(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit) == [expected]


@pytest.mark.parametrize("base,edits,expected", [
    # review comments and casual edits of steer_stranger7, each refused before
    ("Build a tower: red on the bottom, then green, then blue on top", ["green and blue are backwards, swap them"],
     ("modify", ["stack(red,blue,green)"])),
    ("Put the cubes in a line from left to right: orange, purple, pink", ["you've got the orange and the pink backwards"],
     ("modify", ["line[left_to_right](pink,purple,orange)"])),
    ("Line up the red, green and blue cubes from left to right", ["Mirror it."], ("modify", ["line[left_to_right](blue,green,red)"])),
    ("Place a blue cube on top of a red cube", ["throw in a yellow on top"], ("extend", ["stack(red,blue,yellow)"])),
    ("Stack three green cubes", ["make it taller by two"], ("tweak", ["stack(green,green,green,green,green)"])),
    ("Arrange eight red cubes in a circle", ["two fewer"], ("tweak", ["circle(red,red,red,red,red,red)"])),
    ("Stack five yellow cubes", ["Too tall, cut it to three."], ("tweak", ["stack(yellow,yellow,yellow)"])),
    ("Put two white cubes in a line", ["make it twice as long"], ("tweak", ["line(white,white,white,white)"])),
    ("Stack three pink cubes", ["fine, a white cube on top then"], ("extend", ["stack(pink,pink,pink,white)"])),
    ("Put the yellow cube on the blue patch", ["ok then, also a green cube on that patch"], ("extend", ["on_patch(green,yellow,patch:blue)"])),
    ("Put the orange cube in the back left corner", ["and a purple next to it"],
     ("extend", ["in_region(orange,back_left)", "next_to(orange,purple)"])),
    ("Put the green cube to the left of the blue cube", ["ok new thing: put the orange cube on the pink patch"],
     ("fresh", ["on_patch(orange,patch:pink)"])),
    ("Put the green cube between the red cube and the yellow cube", ["the ends are fine but the middle one should be white"],
     ("tweak", ["between(white;red,yellow)"])),
    # a count of one colour taken away takes that many, not every cube of it ("remove one red block" had removed all three)
    ("Put three red cubes and two blue cubes in a line", ["one fewer red"], ("tweak", ["line(blue,blue,red,red)"])),
    ("Put three red cubes and two blue cubes in a line", ["remove one red block"], ("tweak", ["line(blue,blue,red,red)"])),
    # going back more than one version, redoing what was undone, each named by the change from the head
    ("Put a red cube on the green patch", ["patch should be blue", "plus a purple cube next to the red one", "go back two versions"],
     ("modify", ["on_patch(red,patch:green)"])),
    ("Place a blue cube on top of a red cube", ["add a yellow on top", "revert", "nvm, redo"], ("extend", ["stack(red,blue,yellow)"])),
    ("Stack the green cube on the blue cube", ["as a row", "revert to the original"], ("pivot", ["stack(blue,green)"])),
])
def test_review_comments_and_casual_edits(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edit,match", [
    ("Stack four black cubes", "make the blocks twice as big", "size"),  # twice as big stays a size
    ("Stack red, red, blue, red from bottom to top", "remove one red block", "does not say which"),  # its place is judged
    ("Place a blue cube on top of a red cube", "redo", "nothing to redo"),
])
def test_edits_that_stay_refused(tmp_path, base, edit, match):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=match):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger8's silent errors
    ("Put the red cube in front of the blue cube", ["no, on the left of the blue one"], ("modify", ["left_of(red,blue)"])),
    ("Put the blue cube on the red patch", ["make the cube green and the patch yellow"], ("tweak", ["on_patch(green,patch:yellow)"])),
    ("Put the letter cubes O, N, E in a row so they read ONE", ["put a T before it so it says TONE"],
     ("extend", ["line[left_to_right](T,O,N,E)", "reads(T,O,N,E;direction=left_to_right,face=up,text=TONE)"])),
    ("Put the green cube next to the orange cube", ["add a blue one nxt to the orange one as well"],
     ("extend", ["next_to(blue,orange)", "next_to(green,orange)"])),
    ("Place five cubes in a row from left to right: red, orange, yellow, green, blue", ["now as a tower, red at the bottom"],
     ("pivot", ["stack(red,orange,yellow,green,blue)"])),
    # a sorted line of named cubes stays a line of them (a sort had added a judge of their up faces nobody asked for)
    ("Put the digit cubes 4, 2, 3 and 1 in a row, sorted from smallest to largest, left to right",
     ["descending now", "add a 5 and keep it largest first"], ("extend", ["line[left_to_right](5,4,3,2,1)"])),
    ("Put the letter cubes B, C, A in a row from left to right", ["sort them alphabetically"], ("modify", ["line[left_to_right](A,B,C)"])),
])
def test_steer_stranger8_silent_errors_are_read_as_meant(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_cube_made_bigger_stays_a_size(tmp_path):
    fam = Family(create_family(compiled("Stack four yellow cubes", tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="size"):
        steer(fam.path, "can you make the bottom one 2x bigger so the tower is more stable")  # it had made the tower taller


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger9's silent errors
    ("Line up four yellow cubes", ["move the line to the right side of the table", "make two of them red"],
     ("tweak", ["line(red,red,yellow,yellow)@right"])),  # had gained an order nobody said
    ("Stack a cyan cube on an orange cube", ["make the top one white", "ok then v0 but with a black cube on top"],
     ("extend", ["stack(orange,cyan,black)"])),  # had gone back to v0 without the black cube
    ("Stack green, white and red cubes, green at the bottom and red on top",
     ["swap the top and bottom", "now like the first version but with a yellow top"], ("tweak", ["stack(green,white,yellow)"])),
    ("Stack a purple cube on a green cube", ["move it to the left"], ("modify", ["stack(green,purple)@left"])),  # had been left_of
])
def test_steer_stranger9_silent_errors_are_read_as_meant(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_taller_then_an_added_cube_keeps_the_tower(tmp_path):  # steer_stranger10: had recoloured every cube yellow
    assert _steered(tmp_path, "Stack a red cube on a blue cube", "make it taller, add a yellow one on top")[-1] \
        == ("extend", ["stack(blue,red,yellow)"])


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger10's voices: a pair swapped by its place, a sort said end to end, a typo before a count, a verdict
    ("Build a tower: green at the bottom, then yellow, then purple on top", ["swap the first two"],
     ("modify", ["stack(yellow,green,purple)"])),
    ("Put four cubes in a row from left to right: yellow, yellow, blue, blue", ["swap the middle two"],
     ("modify", ["line[left_to_right](yellow,blue,yellow,blue)"])),
    ("Arrange digit cubes 5, 2, 8 and 1 from smallest to largest, left to right", ["largest to smallest instead"],
     ("modify", ["line[left_to_right](8,5,2,1)"])),
    ("Build a tower of five cubes, all orange", ["mkae it shorter, 3"], ("tweak", ["stack(orange,orange,orange)"])),
    ("Put the red cube next to the blue cube", ["I think green would be better than red"], ("tweak", ["next_to(blue,green)"])),
    ("Make a circle of six red cubes", ["bump it to 8"], ("tweak", ["circle(red,red,red,red,red,red,red,red)"])),
    ("Put the orange cube on the green patch", ["try a purple cube instead of the orange", "also put a red cube on that same patch"],
     ("extend", ["on_patch(purple,red,patch:green)"])),
    ("Make a row of red, white and blue cubes, left to right", ["ok then just a green cube at the right end"],
     ("extend", ["line[left_to_right](red,white,blue,green)"])),
    ("Put a red cube in the middle of the table", ["move it to the back"], ("modify", ["in_region(red,back)"])),
])
def test_steer_stranger10_voices(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_two_cubes_named_by_place_in_one_recolour_are_refused(tmp_path):  # the bottom one had been dropped: silently wrong
    fam = Family(create_family(compiled("Stack red, green and blue, bottom to top", tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="several cubes"):
        steer(fam.path, "make the top one and the bottom one blue")


def test_a_version_reference_with_an_unread_change_is_refused(tmp_path):
    fam = Family(create_family(compiled("Stack a cyan cube on an orange cube", tmp_path, name="fam").path).path)
    steer(fam.path, "make the top one white")
    with pytest.raises(SteerError, match="did not read"):
        steer(fam.path, "like v0 but blue on top")  # on top as well, or the top one blue? it had returned to v0 alone


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger9's voices: a correction that denies the old relation, a count against the old one, a review's
    # opening, a notebook's key=value, a polite letter, a word changed "same thing but ..."
    ("Place the yellow cube in front of the purple cube", ["actually it should be behind, not in front"],
     ("modify", ["behind(yellow,purple)"])),
    ("Put three green cubes in a row", ["four instead of three"], ("tweak", ["line(green,green,green,green)"])),
    ("Make a circle of eight cyan cubes", ["too many, use six"], ("tweak", ["circle(cyan,cyan,cyan,cyan,cyan,cyan)"])),
    ("Put five blue cubes in a row", ["n_cubes=3", "region=back"], ("modify", ["line(blue,blue,blue)@back"])),
    ("Stack blue, blue, red, bottom to top", ["+green top", "@center"], ("modify", ["stack(blue,blue,red,green)@center"])),
    ("Put the red cube behind the blue cube", ["rel=left_of"], ("modify", ["left_of(red,blue)"])),
    ("Put three red cubes in a line", ["red -> gray"], ("tweak", ["line(gray,gray,gray)"])),
    ("Spell CAT with letter cubes", ["same thing but DOG"],
     ("modify", ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"])),
    ("Put the blue cube on top of the yellow cube", ["is better if you put also one red cube under the yellow, please"],
     ("extend", ["stack(red,yellow,blue)"])),
    ("Put the red cube on the blue patch and the green cube on the yellow patch",
     ["Hello, thank you so much for this, it looks great. If it isn't too much trouble, could you possibly also put a "
      "purple cube on the blue patch together with the red one? Many thanks in advance."],
     ("extend", ["on_patch(green,patch:yellow)", "on_patch(purple,red,patch:blue)"])),
    ("Put three yellow cubes in a line", ["make every one of those cubes orange instead? No rush at all, thanks."],
     ("tweak", ["line(orange,orange,orange)"])),
])
def test_steer_stranger9_voices(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_relation_named_after_it_is_no_added_cube(tmp_path):  # "one" there is the cube's noun, not a count
    assert _steered(tmp_path, "Put the green block in front of the yellow block", "put it behind the yellow one instead")[-1] \
        == ("modify", ["behind(green,yellow)"])


def test_keep_the_cubes_but_as_a_sized_grid_is_a_pivot(tmp_path):  # the size had been applied to the circle
    assert _steered(tmp_path, "Make a circle of six purple cubes", "keep the cubes, but as a 2x3 grid")[-1] == \
        ("pivot", ["grid(2x3:purple,purple,purple,purple,purple,purple)"])


def test_the_two_leftmost_of_a_left_to_right_row(tmp_path):
    assert _steered(tmp_path, "Put six cubes in a row from left to right: red, red, red, blue, blue, blue",
                    "make the two leftmost ones green", "make the 2 on the right yellow")[-1] == \
        ("tweak", ["line[left_to_right](green,green,red,blue,yellow,yellow)"])


def test_the_leftmost_of_a_row_that_runs_no_way_is_refused(tmp_path):
    fam = Family(create_family(compiled("Put three green cubes in a row", tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="runs no way left to right"):
        steer(fam.path, "make the two leftmost ones red")


def test_an_edit_with_a_run_of_blanks_is_read(tmp_path):  # it had taken minutes
    assert _steered(tmp_path, "Put three green cubes in a row", "make them" + " " * 7000 + "red")[-1] == \
        ("tweak", ["line(red,red,red)"])


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger11's silent errors: a cube brought in without a verb, "a blue one" on a cube of a relation, the cube
    # said with a side in a pivot, a count that goes on with the pattern, "right next to" as next to
    ("Put the red cube in the back left corner", ["now a green one too, in the front right"],
     ("extend", ["in_region(green,front_right)", "in_region(red,back_left)"])),
    ("Put a red cube next to a green cube", ["put a blue one on top of the red"],
     ("extend", ["next_to(green,red)", "stack(red,blue)"])),
    ("Stack a red cube on a green cube", ["make it a row, green on the left"], ("pivot", ["line[left_to_right](green,red)"])),
    ("Build a tower of four cubes alternating black and white, black at the bottom", ["make it six cubes, same pattern"],
     ("tweak", ["stack(black,white,black,white,black,white)"])),
    ("Put the white cube in the center of the table", ["also a brown cube right next to it"],
     ("extend", ["in_region(white,center)", "next_to(brown,white)"])),
])
def test_steer_stranger11_silent_errors_are_read_as_meant(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base, edit", [
    ("Stack a red cube, then a blue cube, then a green cube", "make it four"),
    ("Stack the red block on top of the yellow block", "Double the number of blocks"),
    ("Stack the red block on top of the yellow block", "Make the tower taller"),
    ("Build a tower of red, yellow and blue cubes from bottom to top.", "5 not 3"),
])
def test_a_count_of_cubes_of_several_colours_that_repeat_no_pattern_is_refused(tmp_path, base, edit):
    """The new cubes' colours are unsaid (a colour the task did not use had been made up: a goal stricter than the words;
    issue 30). One colour, a repeating pattern, or a stack in any order of cubes nobody named still grow."""
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="not the new cubes' colours"):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger12's silent errors: two labels added in one edit (the second had been dropped); "blue, not pink"
    # corrects the colour of the cube named (it had recoloured every pink cube as well)
    ("Sort the digit cubes 5, 2 and 8 from smallest to largest, left to right", ["add also a 0 and a 9 please"],
     ("extend", ["line[left_to_right](0,2,5,8,9)"])),
    ("Stack three pink cubes", ["the bottom one should be blue, not pink"], ("tweak", ["stack(blue,pink,pink)"])),
])
def test_steer_stranger12_silent_errors_are_read_as_meant(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger12's voices: a substitution said the other way round, a label arrow, "same thing but ...", the
    # cubes listed in a new order, one cube recoloured while the rest is kept
    ("Put the red cube and the blue cube in a row", ["instead of the red cube use a green one"], ("tweak", ["line(blue,green)"])),
    ("Put the red cube on the blue patch", ["instead of the blue patch use a yellow patch"], ("tweak", ["on_patch(red,patch:yellow)"])),
    ("Spell CAT with letter cubes", ["C -> B"],
     ("tweak", ["line[left_to_right](B,A,T)", "reads(B,A,T;direction=left_to_right,face=up,text=BAT)"])),
    ("Line up an orange, a pink and a purple cube from front to back", ["same thing but left to right"],
     ("modify", ["line[left_to_right](orange,pink,purple)"])),
    ("Stack three red cubes", ["same thing but on the left"], ("modify", ["stack(red,red,red)@left"])),
    ("Put the red, green and blue cubes in a row", ["left to right: blue, red, green"],
     ("modify", ["line[left_to_right](blue,red,green)"])),
    ("Stack the digit cubes 1, 2 and 3", ["from top to bottom: 2, 1, 3"], ("modify", ["stack(3,1,2)"])),
    ("Line up a red, a green and a blue cube from left to right", ["keep everything but the middle one make it purple"],
     ("tweak", ["line[left_to_right](red,purple,blue)"])),
])
def test_steer_stranger12_voices(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("edit,match", [
    ("left to right: blue, red, yellow", "list each of them once"),  # not the task's cubes
    ("bottom to top: red, green, blue", "not how a line runs"),
])
def test_an_order_that_is_not_the_tasks_cubes_along_its_axis_is_refused(tmp_path, edit, match):
    fam = Family(create_family(compiled("Put the red, green and blue cubes in a row", tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=match):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger12's refusals: a two-cube task turned around without saying how, a word said by "let's do", a
    # return to the start, a size that "is enough", one more pair of a pattern
    ("Put the red cube behind the blue cube", ["flip it"], ("modify", ["behind(blue,red)"])),
    ("Put the red cube in the back and the blue cube in the front", ["nah, other way round"],
     ("modify", ["in_region(blue,back)", "in_region(red,front)"])),
    ("Spell DOG with the letter cubes", ["nah, let's do GOD"],
     ("modify", ["line[left_to_right](G,O,D)", "reads(G,O,D;direction=left_to_right,face=up,text=GOD)"])),
    ("Stack four cubes: red at the bottom, then orange, then yellow, then green on top", ["make it blue", "back to how it was at the start"],
     ("tweak", ["stack(red,orange,yellow,green)"])),
    ("Lay out a 2 by 3 grid of yellow cubes", ["2x2 is enough"], ("tweak", ["grid(2x2:yellow,yellow,yellow,yellow)"])),
    ("Put two red cubes and two blue cubes in a row, alternating colours, starting with red on the left", ["one more pair pls"],
     ("extend", ["line[left_to_right](red,blue,red,blue,red,blue)"])),
    ("Stack three red cubes", ["add one more cube at the bottom"], ("extend", ["stack(red,red,red,red)"])),
])
def test_steer_stranger12_turnarounds_and_sizes(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_tower_counted_with_its_colour_keeps_another_cube_apart():  # the blue cube had joined the tower
    from rpg.schema.meaning import meaning

    assert meaning(parse("Build a tower of two red blocks and put the blue block in the back right corner")) == [
        "in_region(blue,back_right)", "stack(red,red)"]


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger15's silent errors: a stack's role said with a row's side (the top cube had gone left), a cube
    # "over the white" (a second white had been added), a tower of digits "smallest on top" (the order had been
    # dropped), a cube added "to finish the rainbow" (the rainbow had recoloured the tower), a cube put under the
    # base (the task's top cube had been dropped), "make it so that the green cube is the lowest one" (every cube
    # had turned green)
    ("Stack purple on top of green", ["turn it into a row, bottom cube on the left"],
     ("pivot", ["line[left_to_right](green,purple)"])),
    ("Stack purple on top of green", ["make it a row with the top one on the right"],
     ("pivot", ["line[left_to_right](green,purple)"])),
    ("Put the white cube on top of the black cube", ["please put also one gray cube more over the white"],
     ("extend", ["stack(black,white,gray)"])),
    ("Arrange the digits 9, 3, 5 and 2 in increasing order from left to right", ["put them in a tower instead, smallest on top"],
     ("pivot", ["stack(9,5,3,2)"])),
    ("Stack the digits 4, 1 and 7 in a tower", ["smallest at the bottom"], ("modify", ["stack(1,4,7)"])),
    ("Stack five cubes in rainbow order with red at the bottom: red, orange, yellow, green, blue",
     ["add purple on top to finish the rainbow"], ("extend", ["stack(red,orange,yellow,green,blue,purple)"])),
    ("Put the red cube on the blue cube", ["now you put the green cube under of the blue cube"],
     ("extend", ["stack(green,blue,red)"])),
    ("Stack the cubes blue, green and orange, blue is at the bottom and orange at the top",
     ["Please make it so that the green cube is the lowest one"], ("modify", ["stack(green,blue,orange)"])),
    ("Stack the cubes blue, green and orange, blue is at the bottom and orange at the top",
     ["make it so that the top one is green"], ("tweak", ["stack(blue,green,green)"])),
])
def test_steer_stranger15_roles_orders_and_additions(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected



@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger15's refusals: two cubes swapped in a task of several relations or places (each takes the
    # other's place; a patch keeps its colour), a cube moved to another patch or off it, a count said as "go down to",
    # a cube recoloured by its role alone, a line piled up from its left end
    ("Put the yellow cube between the red cube and the green cube", ["swap yellow and red"], ("modify", ["between(red;green,yellow)"])),
    ("Put the green cube to the left of the red cube and the red cube to the left of the blue cube", ["swap green and blue"],
     ("modify", ["left_of(blue,red)", "left_of(red,green)"])),
    ("Put the red cube on the green patch and the blue cube on the yellow patch", ["switch them"],
     ("modify", ["on_patch(blue,patch:green)", "on_patch(red,patch:yellow)"])),
    ("Put a purple cube on the left side of the table and a yellow cube on the right side", ["please interchange both of their sides"],
     ("modify", ["in_region(purple,right)", "in_region(yellow,left)"])),
    ("Put the green cube on the blue patch", ["move it to the yellow patch"], ("modify", ["on_patch(green,patch:yellow)"])),
    ("Put the green cube on the blue patch", ["take it off the patch and put it in the middle of the table"],
     ("modify", ["in_region(green,center)"])),
    ("Build a tower of four green cubes", ["make it 6", "hmm too tall, go down to three"], ("tweak", ["stack(green,green,green)"])),
    ("Stack four cubes: black at the bottom, then white, then black, then white on top", ["top one red"],
     ("tweak", ["stack(black,white,black,red)"])),
    ("Put a red, a blue and a yellow cube in a row from left to right", ["wait, pile them up into a tower instead, leftmost one at the bottom"],
     ("pivot", ["stack(red,blue,yellow)"])),
])
def test_steer_stranger15_swaps_moves_and_roles(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_swap_of_a_colour_two_cubes_share_is_refused(tmp_path):
    """Which red cube takes the blue cube's place is not said: no swap is guessed."""
    from rpg.errors import BadInput

    fam = Family(create_family(compiled("Put two red cubes next to each other and the blue cube on the green patch",
                                                   tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, "swap red and blue")


@pytest.mark.parametrize("base,edits,expected", [
    # a tower on a goal patch is edited in place, the patch carried (it was "not a structure the builtin steering edits")
    ("Build a tower of three pink cubes on the orange patch", ["just two high"], ("tweak", ["on_patch(pink,patch:orange)", "stack(pink,pink)"])),
    ("Build a tower of three pink cubes on the orange patch", ["add a red cube on top"],
     ("extend", ["on_patch(pink,patch:orange)", "stack(pink,pink,pink,red)"])),
    ("Stack red, then green, then blue on the white patch", ["reverse it"], ("modify", ["on_patch(blue,patch:white)", "stack(blue,green,red)"])),
    ("Put three blue cubes on the green patch", ["only two"], ("tweak", ["on_patch(blue,blue,patch:green)"])),
])
def test_a_tower_on_a_patch_and_counts_alone(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_tower_on_a_patch_in_any_order_stays_in_any_order(tmp_path):
    fam = Family(create_family(compiled("Build a tower of three cubes on the purple patch.", tmp_path, name="fam").path).path)
    r = steer(fam.path, "make it four")
    assert fam.schema(r.version).goal_summary.startswith("a stack of red, blue, green, yellow in any order")


@pytest.mark.parametrize("base,edits,expected", [
    # a chain of side relations edited as the order it states (it was "not a structure the builtin steering edits")
    ("Put the green cube to the left of the red cube and the red cube to the left of the blue cube", ["reverse the order"],
     ("modify", ["left_of(blue,red)", "left_of(red,green)"])),
    ("Put the green cube to the left of the red cube and the red cube to the left of the blue cube",
     ["now make it front to back instead of left to right"], ("modify", ["in_front_of(green,red)", "in_front_of(red,blue)"])),
    ("Place the yellow cube to the left of the orange cube and the pink cube to the right of the orange cube", ["reverse it"],
     ("modify", ["left_of(orange,yellow)", "left_of(pink,orange)"])),
])
def test_a_chain_of_relations_is_reversed_or_turned(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edits,expected", [
    # a second hostile tester's steering silent errors
    ("Put the red cube to the left of the blue cube", ["make it a tower with blue on top"], ("pivot", ["stack(red,blue)"])),
    ("Build a tower of red, green and blue from bottom to top", ["make the red one blue and the blue one red"],
     ("modify", ["stack(blue,green,red)"])),  # (both had become red)
])
def test_second_attack_steering(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_structure_with_a_role_is_not_read_as_a_recolour(tmp_path):
    """"make it a tower with red on top" of a tower in any order had turned every cube red (then it
    was refused); it is the same cubes with red on top, the rest in any order: a Modify."""
    assert _steered(tmp_path, "Make a tower of red, green and blue in any order", "make it a tower with red on top",
                    build_last=True) == [
        ("modify", ["stack(green,blue,red)"])]
    fam = Family(tmp_path / "fam")
    assert "red on top, the rest in any order" in fam.schema(1).goal_summary


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger16's silent errors (after its first run): "undo x2" went back one step only
    ("Build a tower of four blue cubes", ["make the bottom two red", "add two red cubes on top", "undo x2"],
     ("tweak", ["stack(blue,blue,blue,blue)"])),
])
def test_steer_stranger16_undo_twice(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edit", [
    ("Stack yellow on orange on red", "3 towers like that"),  # (three towers of made-up colours)
    ("Stack the yellow cube on the purple cube and put the orange cube on the green patch", "tower in the back instead"),
])
def test_steer_stranger16_made_up_cubes_are_refused(tmp_path, base, edit):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger17's silent errors (first run)
    ("Build a red tower three cubes tall", ["pls make red tower two more"], ("tweak", ["stack(red,red,red,red,red)"])),  # (two)
    ("Sort the digit cubes 6, 2, 4 from smallest to largest, left to right", ["stack them instead, smallest on top"],
     ("pivot", ["stack(6,4,2)"])),  # (still a line)
    ("put the blue cube to the right of the yellow cube",
     ["also a green cube to the right of the blue one, so it's a row", "make it a tower, same order bottom to top"],
     ("pivot", ["stack(yellow,blue,green)"])),  # (stacked in the order the task named the cubes)
    # terse edits: arrows, s///, n=, <->, "same but", "like before"
    ("Place the black cube on the white patch", ["patch -> cyan"], ("tweak", ["on_patch(black,patch:cyan)"])),
    ("put the brown cube behind the orange cube", ["brown -> cyan, orange -> pink"], ("tweak", ["behind(cyan,pink)"])),
    ("Stack the green cube on the red cube", ["s/green/blue/"], ("tweak", ["stack(red,blue)"])),
    ("Line up four blue cubes from left to right", ["n=6 pls"], ("tweak", ["line[left_to_right](blue,blue,blue,blue,blue,blue)"])),
    ("Build a tower of red, then blue, then green, bottom to top", ["red <-> green"], ("modify", ["stack(green,blue,red)"])),
    ("Place the red cube on the green patch", ["same but with the yellow cube"], ("tweak", ["on_patch(yellow,patch:green)"])),
    ("Put the red cube in front of the green cube", ["put it behind instead", "nah, like before"],
     ("modify", ["in_front_of(red,green)"])),
    # a cube put between two neighbours goes into the structure (it had been refused, or had replaced a row)
    ("Build a tower of three cubes: blue at the bottom, then white, then red on top",
     ["add a black cube between the white one and the blue one"], ("extend", ["stack(blue,black,white,red)"])),
    ("Make a row of red, green and blue from left to right", ["put a yellow cube between the red cube and the green cube"],
     ("extend", ["line[left_to_right](red,yellow,green,blue)"])),
    ("Arrange a red, a green and a blue block in a line from left to right", ["put a yellow block between the red and green ones"],
     ("extend", ["line[left_to_right](red,yellow,green,blue)"])),  # (refused before this session: 'green' had no place)
    ("Put the red cube to the left of the green cube", ["put a yellow cube between the red cube and the green cube"],
     ("extend", ["between(yellow;green,red)", "left_of(red,green)"])),
])
def test_steer_stranger17(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_the_cube_of_a_task_with_several_cubes_is_refused(tmp_path):
    """"make the cube yellow" of a two-cube tower had made both cubes yellow."""
    from rpg.errors import BadInput

    fam = Family(create_family(compiled("Stack the pink cube on the brown cube", tmp_path, name="fam").path).path)
    with pytest.raises(BadInput, match="names one cube"):
        steer(fam.path, "make the cube yellow")


@pytest.mark.parametrize("base,edits,expected", [
    # a hostile tester's steering silent errors (this session's features)
    ("Put the red cube to the left of the green cube and the green cube to the left of the blue cube",
     ["make it a tower, same order top to bottom"], ("pivot", ["stack(blue,green,red)"])),  # (bottom to top before)
    ("Put the red cube to the left of the green cube and the green cube to the left of the blue cube",
     ["make it a tower, leftmost on top"], ("pivot", ["stack(blue,green,red)"])),  # (any order before)
])
def test_chain_to_tower_keeps_the_said_end(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edits,words", [
    ("Make a row of red, green and blue from left to right", ["stack them instead, smallest on top"], "carry no numbers"),
    ("Put the red cube to the left of the green cube and the blue cube to the left of the yellow cube",
     ["make it a tower, same order bottom to top"], "no one order"),
    ("Spell CAT with letter cubes from left to right", ["n=4"], "a count says no letters"),
])
def test_steering_that_would_invent_is_refused(tmp_path, base, edits, words):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    for e in edits[:-1]:
        steer(fam.path, e)
    with pytest.raises(BadInput, match=re.escape(words)):
        steer(fam.path, edits[-1])


@pytest.mark.parametrize("base,edits,expected", [
    # a row's end cube by its side, a cube by its place said with "one in the middle"/"on top"
    ("Make a row of three cubes from left to right: pink, gray, brown", ["make the leftmost one red"],
     ("tweak", ["line[left_to_right](red,gray,brown)"])),
    ("Make a row of three cubes from left to right: pink, gray, brown", ["the one on the left -> red"],
     ("tweak", ["line[left_to_right](red,gray,brown)"])),
    ("Put the blue cube between the red cube and the yellow cube", ["the one in the middle should be black"],
     ("tweak", ["between(black;red,yellow)"])),
])
def test_cubes_by_their_place(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edits,expected", [
    # a second hostile tester's steering silent errors
    ("stack red, green, blue from bottom to top", ["the top one is wrong, it should be orange"],
     ("tweak", ["stack(red,green,orange)"])),  # (every cube had turned orange)
    ("stack red, green, blue from bottom to top", ["put white between green and blue"],
     ("extend", ["stack(red,green,white,blue)"])),  # (the tower had been replaced by a bare relation)
])
def test_second_steering_attack(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edit,words", [
    ("stack red, green, blue from bottom to top", "add a cube on top and one at the bottom", "a second place"),  # (half dropped)
    ("stack red, green, blue from bottom to top", "add a cube on top in the same colour as the base", "same colour as"),
    ("stack red, green, blue from bottom to top", "put a white cube in the middle", "between which two"),  # (on top)
    ("put the red cube on the blue patch and the green cube left of the yellow cube", "get rid of the yellow cube",
     "green would have no goal left"),  # (green had vanished)
    ("put the yellow cube on the white patch and stack the red cube on the green cube", "make the tower a row",
     "parts besides"),  # (yellow pulled into the row, the patch dropped)
])
def test_second_steering_attack_refusals(tmp_path, base, edit, words):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput, match=re.escape(words)):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger18's classes (nineteenth session): a curriculum's label of the variant being made is no reference
    ("Stack a blue cube on a red cube", ["v2: add a green cube on top"], ("extend", ["stack(red,blue,green)"])),
    ("Place the yellow cube on the blue patch", ["level 2 -> also a green cube on the red patch"],
     ("extend", ["on_patch(green,patch:red)", "on_patch(yellow,patch:blue)"])),
    # "like the first one, but ...": the base task, changed; "revert the revert": the change made again
    ("Make a row of four cubes, left to right: purple, pink, red, orange",
     ["remove the last one", "like the first one, but the pink cube should be white"],
     ("tweak", ["line[left_to_right](purple,white,red,orange)"])),
    ("Put the gray cube behind the cyan cube", ["make it in front instead", "revert that", "revert the revert"],
     ("modify", ["in_front_of(gray,cyan)"])),
    # "the cube you added": the one cube the last edit added
    ("Place a cyan cube on the yellow patch", ["add a green cube on top of the cyan one", "the cube you added should be orange"],
     ("tweak", ["on_patch(cyan,patch:yellow)", "stack(cyan,orange)"])),
    # the two cubes on two patches exchanged
    ("Place the orange cube on the green patch and the cyan cube on the pink patch", ["nit: the two cubes should trade patches"],
     ("modify", ["on_patch(cyan,patch:green)", "on_patch(orange,patch:pink)"])),
    # terse and non-native edits
    ("Stack three cubes: white, black, white from bottom to top", ["more one black on top"],
     ("extend", ["stack(white,black,white,black)"])),
    ("Make a row of red, yellow and blue cubes from left to right", ["yellow go to end please"],
     ("modify", ["line[left_to_right](red,blue,yellow)"])),
    ("Build a tower with a blue cube on the bottom, then cyan, then white", ["put it in corner, front right"],
     ("modify", ["stack(blue,cyan,white)@front_right"])),
    ("Make a row of four blue cubes", ["LGTM but the row should be in the back of the table"],
     ("modify", ["line(blue,blue,blue,blue)@back"])),
])
def test_steer_stranger18_classes(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edits,words", [
    # silent errors of steer_stranger18's first run, refused now ("put the pink one on the red patch instead", whose old
    # relation had been kept, is read now: test_instead_exchanges_one_placement_of_a_relational_task)
    ("Place a cyan cube on the yellow patch", ["add a green cube on top of the cyan one",
                                               "the cube you added before that should be brown"], "before the last"),
    ("Place a cyan cube on the yellow patch", ["the cube you added should be brown"], "is the base task"),
])
def test_steer_stranger18_refusals(tmp_path, base, edits, words):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    for e in edits[:-1]:
        assert steer(fam.path, e).valid
    with pytest.raises(BadInput, match=re.escape(words)):
        steer(fam.path, edits[-1])


def test_a_variant_label_keeps_the_edit_as_said(tmp_path):
    """The label is dropped for reading, and the version records the edit as it was said."""
    fam = Family(create_family(compiled("Stack a blue cube on a red cube", tmp_path, name="fam").path).path)
    r = steer(fam.path, "v2: add a green cube on top")
    assert r.valid and fam.load().get(r.version).description == "v2: add a green cube on top"


def test_a_tower_put_on_a_patch_then_the_version_before_the_patch(tmp_path):
    """steer_stranger18 z037: 'put the stack on the white patch' had lost the tower's middle cube (refused), and 'go back to
    the one before the patch' had picked the version with the patch (silently wrong)."""
    got = _steered(tmp_path, "Stack three cubes: orange on the bottom, then green, then purple on top",
                   "put the stack on the white patch", "take the purple off",
                   "go back to the one before the patch, and add a brown cube on top")
    assert got[0] == ("extend", ["on_patch(orange,patch:white)", "stack(orange,green,purple)"])
    assert got[-1][1] == ["stack(orange,green,purple,brown)"]


def test_a_cube_put_between_the_task_s_two_cubes(tmp_path):
    """'put a green cube between them' had found no change to read."""
    got = _steered(tmp_path, "Put the red cube to the left of the blue cube", "put a green cube between them")
    assert got == [("extend", ["between(green;blue,red)", "left_of(red,blue)"])]


def test_an_addition_that_says_the_count_it_makes(tmp_path):
    """'same but four cubes, put a yellow one on the very top' of a tower of three: the four is the count the addition
    makes (it had been refused as a number with no place); a count the addition does not make stays refused."""
    from rpg.errors import BadInput

    got = _steered(tmp_path, "Stack a blue cube on a red cube", "add a green cube on top",
                   "same but four cubes, put a yellow one on the very top")
    assert got[-1] == ("extend", ["stack(red,blue,green,yellow)"])
    fam = Family(create_family(compiled("Stack a blue cube on a red cube", tmp_path, name="fam2").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, "same but five cubes, put a yellow one on the very top")


def test_the_task_s_cubes_restated_in_other_structures_are_a_pivot(tmp_path):
    """"now split it into two towers of two: red under blue, green under yellow", "now the same three in a tower, red at
    the bottom, ...": the task's own cubes in the structures listed (they had been refused: 'names no change')."""
    assert _steered(tmp_path, "Stack a blue cube on a red cube", "add a green cube on top", "add a yellow one on the very top",
                    "now split it into two towers of two: red under blue, green under yellow")[-1] == \
        ("pivot", ["stack(green,yellow)", "stack(red,blue)"])
    assert _steered(tmp_path / "b", "Put the red cube to the left of the blue cube", "put a green cube between them",
                    "now the same three in a tower, red at the bottom, then green, blue on top")[-1] == \
        ("pivot", ["stack(red,green,blue)"])


def test_an_addition_that_keeps_a_cube_where_it_is_adds_only(tmp_path):
    """"also put a pink cube on a blue patch, keep the yellow one where it is": the keeping is what an addition does
    anyway (it had been refused: 'keep' an action)."""
    assert _steered(tmp_path, "Put the yellow cube on the green patch",
                    "also put a pink cube on a blue patch, keep the yellow one where it is") == [
        ("extend", ["on_patch(pink,patch:blue)", "on_patch(yellow,patch:green)"])]


def test_a_question_edit_is_refused_as_a_question():
    from rpg.steer.edits import SteerError, interpret

    with pytest.raises(SteerError, match="asks a question"):
        interpret("wait, which of the two patches is closer to the robot right now?")  # (it had been read as a distance)


@pytest.mark.parametrize("edit, expected", [
    ("swap the two middle ones", "stack(red,yellow,orange,green)"),
    ("the 2 middle ones swap", "stack(red,yellow,orange,green)"),
    ("swap the 2 bottom ones", "stack(orange,red,yellow,green)"),
    ("the green and red trade places", "stack(green,orange,yellow,red)"),
    ("make both ends purple", "stack(purple,orange,yellow,purple)"),
    ("the ends should be white", "stack(white,orange,yellow,white)"),
    ("all of them pink", "stack(pink,pink,pink,pink)"),
    ("change all orange to pink", "stack(red,pink,yellow,green)"),
    ("top one white", "stack(red,orange,yellow,white)"),
])
def test_positional_swaps_ends_and_recolours_said_tersely(tmp_path, edit, expected):
    """Steering written by strangers (steer_stranger17/18, thirtieth session): a pair named by its
    place before the noun, two cubes that "trade places", both ends recoloured, every cube one colour
    and a terse "top one white" had been refused (or, for "change all orange", read without its colour)."""
    assert _steered(tmp_path, "Build a tower of four cubes: red, orange, yellow, green from bottom to top", edit) == [
        (("modify" if "swap" in edit or "trade" in edit else "tweak"), [expected])]


def test_the_rest_staying_a_colour_is_checked_not_applied(tmp_path):
    """"..., the ones in between stay blue" had stopped the recolour before it; it is a check: the
    other cubes must be that colour already, or the edit is refused."""
    assert _steered(tmp_path, "Make a row of six blue cubes from left to right",
                    "ok and make both ends orange, the ones in between stay blue") == [
        ("tweak", ["line[left_to_right](orange,blue,blue,blue,blue,orange)"])]
    with pytest.raises(SteerError, match="other cubes stay pink"):
        _steered(tmp_path / "b", "Make a row of six blue cubes from left to right", "make the first one red, the rest stay pink")
    with pytest.raises(SteerError, match="keep their colour"):
        _steered(tmp_path / "c", "Make a row of six blue cubes from left to right", "add a red one on the left, the rest stay blue")


def test_a_change_after_going_back_is_applied_to_that_version(tmp_path):
    """"compare with the first one, but with the middle cube green", "revert that and add ...":
    the version named, then the change (it had been refused: go back first, change next)."""
    assert _steered(tmp_path, "Put three blue cubes in a row from left to right", "make the left one red",
                    "compare with the first one, but with the middle cube green")[-1] == (
        "tweak", ["line[left_to_right](blue,green,blue)"])
    assert _steered(tmp_path / "b", "Put the yellow cube on the red patch", "move the yellow cube to the green patch",
                    "revert that and add a blue cube on the same patch")[-1] == ("extend", ["on_patch(blue,yellow,patch:red)"])
    assert _steered(tmp_path / "c", "Put the blue cube in the back left corner", "move it to the center",
                    "compare with the first one, but in the front left corner")[-1] == ("modify", ["in_region(blue,front_left)"])


@pytest.mark.parametrize("edit", ["make it one long row", "# next variant: collapse it into one long row"])
def test_one_long_row_is_a_row_of_every_cube(tmp_path, edit):
    """"one long row" had read "one long" as a count: a 3x1 grid of three of a 3x3 grid's nine cubes (silently wrong)."""
    assert _steered(tmp_path, "Arrange four white cubes in a 2x2 grid", edit) == [("pivot", ["line(white,white,white,white)"])]


@pytest.mark.parametrize("base, edit, expected", [
    ("Put the pink cube between the two black cubes", "put the whole thing into a tower, pink in the middle", ["stack(black,pink,black)"]),
    ("Make a pyramid of three pink cubes", "now tower, yellow on top", None),
    ("Stack the letter cubes B, A and T, B at the bottom and T on top", "keep the letters, row instead, reading BAT",
     ["line[left_to_right](B,A,T)", "reads(B,A,T;direction=left_to_right,face=up,text=BAT)"]),
    ("Stack the letter cubes B, A and T, B at the bottom and T on top", "make it a row", ["line(A,B,T)"]),
    # (these two had been refused: the roles unread; the first once with made-up cubes, all white)
    ("Make a row of white, gray and black cubes from front to back", "turn it into a tower, white at the bottom",
     ["stack(white,gray,black)"]),
    ("Put the pink cube between the two purple cubes", "put the whole thing into a tower, pink in the middle", ["stack(purple,pink,purple)"]),
])
def test_a_pivot_reads_the_roles_it_gives_the_task_cubes(tmp_path, base, edit, expected):
    """A pivot with roles ("into a tower, pink in the middle", "row instead, reading BAT") is the
    task's own cubes in the new structure, the roles read by the parser; "make it a row" of a letter
    tower keeps its letters (three made-up letters A, B, C had replaced B, A, T, silently)."""
    steps = [edit] if expected is not None else ["make the top one yellow", edit]
    got = _steered(tmp_path, base, *steps)[-1]
    assert got == ("pivot", expected or ["stack(pink,pink,yellow)"])


def test_a_pivot_of_one_of_two_structures_is_not_read_as_all_cubes(tmp_path):
    """"turn the red row into a pyramid" of a green row and a red row had become one pyramid of all
    six cubes (silently wrong); it is refused."""
    with pytest.raises(SteerError):
        _steered(tmp_path, "Make a row of three green cubes and a row of three red cubes", "turn the red row into a pyramid")


@pytest.mark.parametrize("base, edits, expected", [
    ("Spell CAT with letter cubes from left to right", ["v2: CART"],
     ("extend", ["line[left_to_right](C,A,R,T)", "reads(C,A,R,T;direction=left_to_right,face=up,text=CART)"])),
    ("Spell BED with letter cubes from left to right", ["reverse the letters", "jk put it back, and add an S at the end"],
     ("extend", ["line[left_to_right](B,E,D,S)", "reads(B,E,D,S;direction=left_to_right,face=up,text=BEDS)"])),
    ("Spell DOG with letter cubes, left to right", ["change G to T", "T go to first"],
     ("modify", ["line[left_to_right](T,D,O)", "reads(T,D,O;direction=left_to_right,face=up,text=TDO)"])),
    ("Stack green on orange", ["make it 3 tall with a pink one on top"], ("extend", ["stack(orange,green,pink)"])),
    ("Stack two green cubes", ["make it three", "v3: four, and the top one orange"], ("tweak", ["stack(green,green,green,orange)"])),
    ("Make a row of red, yellow and blue cubes from left to right", ["all row to back side"],
     ("modify", ["line[left_to_right](red,yellow,blue)@back"])),
    ("Put the green cube next to the pink cube", ["add brown also close to green"], ("extend", ["next_to(brown,green)", "next_to(green,pink)"])),
    ("Build a tower with a blue cube on the bottom, then cyan, then white", ["cyan take out"], ("tweak", ["stack(blue,white)"])),
    ("Build a pyramid with three green cubes at the bottom, two white cubes in the middle and a black cube on top",
     ["swap the green and the white layers"], ("modify", ["pyramid(white,white,white|green,green|black)"])),
    # the colours of two layers of different sizes exchanged (it had been refused as a swap of unequal sets)
    ("Build a pyramid with 3 red blocks at the bottom, 2 green in the middle and 1 blue on top",
     ["swap the colours of the top and bottom layers"], ("modify", ["pyramid(blue,blue,blue|green,green|red)"])),
    ("Build a pyramid with three green cubes at the bottom, two white cubes in the middle and a black cube on top",
     ["swap the green and the white layers", "undo the swap"], ("tweak", ["pyramid(green,green,green|white,white|black)"])),
    ("Stack a blue cube on top of a yellow cube on the orange patch", ["swap the two cube colours"],
     ("modify", ["on_patch(blue,patch:orange)", "stack(blue,yellow)"])),
])
def test_terse_edits_of_steer_stranger17_and_18(tmp_path, base, edits, expected):
    """Edits written by strangers that had been refused (or, "undo the swap", read as no change;
    "jk put it back, and add an S", read as an addition to the reversed word: silently wrong)."""
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_bare_command_in_capitals_is_no_word_to_spell(tmp_path):
    """"UNDO" is the command, not a word for the cubes to spell."""
    assert _steered(tmp_path, "Spell SUN using letter cubes from left to right", "make it spell RUN", "UNDO")[-1] == (
        "modify", ["line[left_to_right](S,U,N)", "reads(S,U,N;direction=left_to_right,face=up,text=SUN)"])


def test_every_cube_moved_to_one_region_and_a_layer_recoloured_cube_by_cube(tmp_path):
    """"please change it so both are on the left side" (both cubes there) and "change the bottom layer
    so it goes orange, green, orange" (each cube of it in turn) had been refused ('change' read as an
    action); a list that does not fit the layer is refused."""
    assert _steered(tmp_path, "Put the red cube on the left side of the table and the blue cube on the right side",
                    "please change it so both are on the left side") == [("modify", ["in_region(blue,left)", "in_region(red,left)"])]
    base = "Build a pyramid of six cubes: three orange on the bottom, two yellow in the middle, one red on top"
    assert _steered(tmp_path / "b", base, "please change the bottom layer so it goes orange, green, orange") == [
        ("tweak", ["pyramid(green,orange,orange|yellow,yellow|red)"])]
    with pytest.raises(SteerError, match="2 colours are said for 3 cubes"):
        _steered(tmp_path / "c", base, "make the bottom layer red, blue")


@pytest.mark.parametrize("base, edit, expected", [
    ("Stack red on blue. Stack pink on white.", "one long row", ("pivot", ["line(blue,pink,red,white)"])),
    ("Stack red on blue. Stack pink on white.", "row", ("pivot", ["line(blue,pink,red,white)"])),
    ("Put pink, white and cyan in a row from left to right", "one tower", ("pivot", ["stack(pink,white,cyan)"])),
    ("Build a tower of five blue cubes", "make the 2 top ones white", ("tweak", ["stack(blue,blue,blue,white,white)"])),
])
def test_attack_on_terse_pivots_and_counted_ends(tmp_path, base, edit, expected):
    """A hostile helper's silent errors: a bare structure noun had read as a default task of made-up
    cubes; "the 2 top ones" had recoloured one cube."""
    assert _steered(tmp_path, base, edit) == [expected]


@pytest.mark.parametrize("base, edit, needle", [
    ("Build a tower of five blue cubes", "make all but the ends pink", "by the ones they are not|'all but' is a negation"),  # (all
    # five had been pink; 'all but' is an exclusion the domain refuses as a negation since the forty-third session)
    ("Put red, blue, green and yellow in a row from left to right", "swap the 2 bottom ones", "no bottom two"),  # (a row's left two)
    ("Stack red on blue", "add a green cube on the same patch", "has none"),  # (a gray patch had been made up)
    ("Put red, blue and green in a row from left to right", "stack it instead, D at the bottom", "no such cube"),  # (D dropped)
])
def test_attack_on_selectors_and_roles_is_refused(tmp_path, base, edit, needle):
    with pytest.raises(SteerError, match=needle):
        _steered(tmp_path, base, edit)


def test_a_count_among_a_pivots_roles_is_no_label(tmp_path):
    """Review: a digit among a coloured task's roles ("a tower of 3, pink on top") is a count, not a cube the task lacks."""
    assert _steered(tmp_path, "Make a pyramid of three pink cubes", "make it a tower of 3, pink on top") == [
        ("pivot", ["stack(pink,pink,pink)"])]


def test_bare_colours_added_and_the_count_said_again(tmp_path):
    """"five cubes, add a yellow and an orange at the right end" (colours with no noun, the count the additions reach) and
    "same five but reversed" (the count said again, then the change) were refused; a count the version does not have
    stays refused, and so does an addition that misses the count said."""
    base = "Put three cubes in a row from left to right: red, green, blue"
    assert _steered(tmp_path, base, "five cubes, add a yellow and an orange at the right end, in that order",
                    "same five but reversed") == [
        ("extend", ["line[left_to_right](red,green,blue,yellow,orange)"]),
        ("modify", ["line[left_to_right](orange,yellow,blue,green,red)"])]
    fam = Family(create_family(compiled(base, tmp_path / "b", name="fam").path).path)
    for edit in ("same four but reversed", "six cubes, add a yellow and an orange at the right end"):
        with pytest.raises(SteerError):
            steer(fam.path, edit)


def test_the_letters_stacked_instead(tmp_path):
    """"stack the letters instead, C at the bottom" of a spelled word was refused as changing nothing."""
    assert _steered(tmp_path, "Spell CAT with letter cubes from left to right", "stack the letters instead, C at the bottom") == [
        ("pivot", ["stack(C,A,T)"])]


@pytest.mark.parametrize("base, edit", [
    ("Put three cubes in a row from left to right: red, green, blue", "add a yellow and an orange at the right end, then reverse"),
    ("Put three cubes in a row from left to right: red, green, blue", "add a yellow and an orange at the right end, in reverse order"),
    ("Stack the red cube on the green cube and the blue cube on the red cube", "same five but build a tower of pink, white and cyan"),
    ("Stack the red cube on the green cube and the blue cube on the red cube", "same letters but reversed"),
    ("Spell CAT with letter cubes from left to right", "stack the digits instead, C at the bottom"),
    ("Build a pyramid with three orange cubes on the bottom, two yellow cubes in the middle and a red cube on top", "reversed"),
])
def test_edits_that_say_what_the_version_lacks_are_refused(tmp_path, base, edit):
    """Attacks on this session's edits (a stranger's): each had applied a change the words did not say (a reversal
    dropped, a count or the task's letters the version does not have, a pyramid's layers mixed)."""
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, edit)


@pytest.mark.parametrize("edit", ["go back to round 3", "revert to level 7"])
def test_a_version_numbered_by_the_writers_own_count_is_refused(tmp_path, edit):
    """"go back to round 3" of a family with two versions had been read as one step back (silently another version)."""
    fam = Family(create_family(compiled("Stack the red cube on the blue cube", tmp_path, name="fam").path).path)
    steer(fam.path, "add a green cube on top")
    with pytest.raises(SteerError, match="count of its own"):
        steer(fam.path, edit)


def test_a_rounds_label_with_words_after_its_number_is_dropped(tmp_path):
    """"Round 2 rule change: put a pink cube on top": the label of the variant being made (its '2' had been refused)."""
    assert _steered(tmp_path, "Build a tower of the red, green and blue cubes from bottom to top",
                    "Round 2 rule change: put a pink cube on top.") == [("extend", ["stack(red,green,blue,pink)"])]


@pytest.mark.parametrize("edit", ["switch pink and gray", "swap pink n gray", "swap the pink cube & the gray cube"])
def test_two_cubes_switched_tersely(tmp_path, edit):
    """"switch pink and gray" (read as an action) and texting's "n"/"&" for "and" had been refused."""
    assert _steered(tmp_path, "Build a tower of the pink, gray and white cubes from bottom to top", edit) == [
        ("modify", ["stack(gray,pink,white)"])]


@pytest.mark.parametrize("edit", [
    "The class keeps mixing up pink and white, so make the white cube cyan instead.",  # a reason before "so"
    "For the poster session: make the white cube cyan.",  # a label saying what for
])
def test_a_reason_or_a_label_before_the_change_is_dropped(tmp_path, edit):
    """The reason's colours ("mixing up pink and white") had been read as part of the change (refused), and the label's
    words as an action."""
    assert _steered(tmp_path, "Put the pink cube, the white cube and the gray cube in a row from left to right", edit) == [
        ("tweak", ["line[left_to_right](pink,cyan,gray)"])]


@pytest.mark.parametrize("edit", [
    "Start over: put the black block on the gray patch",  # a fresh start, not a label
    "Put red on top, so make the white cube cyan.",  # a command before "so" is no reason
])
def test_a_label_or_reason_that_may_change_the_edit_is_kept(tmp_path, edit):
    got = _steered_or_refused(tmp_path, "Put the pink cube, the white cube and the gray cube in a row from left to right", edit)
    assert got is None or got[0] == "fresh" or got[1] != ["line[left_to_right](pink,cyan,gray)"]


def _steered_or_refused(tmp_path, base: str, edit: str):
    """(intent, meaning) of ``edit`` applied to a compiled base, or None where it is refused."""
    try:
        return _steered(tmp_path, base, edit)[0]
    except SteerError:
        return None


@pytest.mark.parametrize("edit, expected", [
    ("um, okay, put a red one on top, no wait, a green one", [("extend", ["stack(blue,red,green)"])]),
    ("make it three, no wait, four", [("tweak", ["stack(blue,blue,blue,blue)"])]),
])
def test_a_spoken_self_correction_in_an_edit_wins(tmp_path, edit, expected):
    """"..., no wait, a green one" had been refused (the first value and the correction both read as the change)."""
    base = "Stack the red cube on the blue cube" if "top" in edit else "Build a tower of two blue cubes"
    assert _steered(tmp_path, base, edit) == expected


def test_a_change_said_with_the_ends_it_makes_is_applied(tmp_path):
    """"build it upside down, yellow at the bottom and red on top": the reversal's ends said again (they had been refused
    as values no change read); ends that the change does not make stay refused."""
    base = "Stack three cubes: red at the bottom, then green, then yellow on top."
    assert _steered(tmp_path / "a", base, "Make it harder: build it upside down, yellow at the bottom and red on top.") == [
        ("modify", ["stack(yellow,green,red)"])]
    fam = Family(create_family(compiled(base, tmp_path / "b", name="fam").path).path)
    with pytest.raises(SteerError, match="no place"):
        steer(fam.path, "build it upside down, red at the bottom")


@pytest.mark.parametrize("edit", [
    "It should be upside down, so make the green cube yellow.",  # the "reason" is itself a change
    "The red one must go, so make the green cube yellow.",
    "Flip it: make the green cube yellow.",  # the label is itself a change
    "Mirror version: make the green cube yellow.",
    "Bad example for the worksheet: make the green cube yellow.",
])
def test_a_reason_or_label_that_is_itself_a_change_is_not_dropped(tmp_path, edit):
    """A hostile helper's silent errors against this session's steering (the change in the reason or label had been
    dropped and the recolour alone applied)."""
    got = _steered_or_refused(tmp_path, "Put the red cube, the green cube and the blue cube in a row from left to right", edit)
    assert got is None or got[1] != ["line[left_to_right](red,yellow,blue)"]


@pytest.mark.parametrize("base, edits, expected", [
    # spoken edits: hesitations, fillers between pauses, a count corrected after "no"
    ("Make a tower of three pink cubes.", ["uh, make it five, no, four"], ("tweak", ["stack(pink,pink,pink,pink)"])),
    ("Put four cubes in a row from left to right: red, orange, yellow, green.", ["okay so, reverse that, like, green first"],
     ("modify", ["line[left_to_right](green,yellow,orange,red)"])),
    ("Stack a yellow cube on a blue cube.", ["and uh make the bottom one purple"], ("tweak", ["stack(purple,yellow)"])),
    # a name the edit gives the version it makes ("Round 3:", "Height ablation:"), and a count with the one it replaces
    ("Arrange four yellow cubes in a row.", ["Round two rule change: six cubes in the row instead of four."],
     ("tweak", ["line(yellow,yellow,yellow,yellow,yellow,yellow)"])),
    ("Make a row of three red cubes.", ["6 not 3"], ("tweak", ["line(red,red,red,red,red,red)"])),
    ("Build a tower of four gray cubes.", ["Height ablation: two cubes."], ("tweak", ["stack(gray,gray)"])),
    # a reason said in a sentence of its own, set aside
    ("Stack three cubes: red at the bottom, yellow in the middle, blue on top.",
     ["That's too much for today. Leave out the yellow cube."], ("tweak", ["stack(red,blue)"])),
    # the structure said again with every cube; the same six cubes kept in another structure
    ("Stack two red cubes and put a blue cube on top.",
     ["She's good at this now. Make the tower five cubes: three red and then two blue on top."],
     ("tweak", ["stack(red,red,red,blue,blue)"])),
    ("Arrange six yellow cubes in a row.", ["Round four: same six cubes, but stacked in one tower in the centre of the table."],
     ("pivot", ["stack(yellow,yellow,yellow,yellow,yellow,yellow)@center"])),
    # the cube said first, then "put it"; the structure said to go to a side; a place alone; a digit by its word
    ("Put the blue cube on top of the green cube, and the red cube to the left of the green cube.",
     ["uh, the red cube, put it to the right of the green one instead"], ("modify", ["right_of(red,green)", "stack(green,blue)"])),
    ("Put the cyan cube in the left half and the orange cube in the right half of the table.",
     ["put them in a tower instead, cyan on the bottom", "and, uh, the tower goes on the right side"],
     ("modify", ["stack(cyan,orange)@right"])),
    ("Put a row of three blue cubes at the back of the table.", ["Let's try the row at the front instead."],
     ("modify", ["line(blue,blue,blue)@front"])),
    ("Put the red cube in the back half of the table.", ["actually in front"], ("modify", ["in_region(red,front)"])),
    ("Build a tower of the digit cubes 2, 4 and 6 with 2 at the bottom.", ["add, um, an eight on top"],
     ("extend", ["stack(2,4,6,8)"])),
    # a take named and a message's kind before the change, who asked for it (steer_stranger20's annotator, director and
    # student voices: "Take four:" had been read as a count, "the homework says" as unknown words)
    ("Build a tower: orange on the bottom, blue, then white on top.", ["Take four: remove the blue cube."],
     ("tweak", ["stack(orange,white)"])),
    ("Build a tower: orange on the bottom, blue, then white on top.", ["Correction: add a green cube on top."],
     ("extend", ["stack(orange,blue,white,green)"])),
    ("Build a tower: orange on the bottom, blue, then white on top.", ["the homework says the white cube goes at the bottom"],
     ("modify", ["stack(white,orange,blue)"])),
])
def test_spoken_labelled_and_reasoned_edits_of_steer_stranger19(tmp_path, base, edits, expected):
    """Edits of steer_stranger19 (development material since its classes were reported) that had been refused: a
    hesitation or filler read as a word of the change, a version's own name ("Round 3:") as a count, a reason sentence as
    a quantity, "the red cube, put it ..." as no change, "instead" of one of several relations as one more."""
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base, edits, needle", [
    # "scrap that" and a version named by the session's own count: no fresh task of made-up cubes
    ("Stack the digit cubes 1, 2, 3 and 4 with 1 at the bottom.",
     ["Round two: put them in descending order, 4 at the bottom.", "Scrap that, go back to the round one tower."], "goes back"),
    # a colour the palette lacks (a green cube had been added)
    ("Stack the red cube on the blue cube.", ["Put a gold cube on top as a reward."], "palette"),
    # the count the edit says the task had is checked
    ("Arrange four yellow cubes in a row.", ["six instead of three"], "has 4"),
    # a reason that is a fresh start is no reason
    ("Make a row of four white blocks", ["It's time to start over. Put the cyan block on the red patch."], None),
])
def test_steer_stranger19_edits_that_must_not_compile_silently(tmp_path, base, edits, needle):
    """Silent errors this session's changes exposed or risked: each is refused, or (a fresh start) not read as a reason."""
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    for e in edits[:-1]:
        steer(fam.path, e)
    if needle is None:
        r = steer(fam.path, edits[-1])
        assert r.intent == "fresh" and not any("set aside" in n for n in r.notes)
        return
    with pytest.raises(SteerError, match=needle):
        steer(fam.path, edits[-1])


def test_a_reason_sentence_set_aside_is_reported(tmp_path):
    """The set-aside reason is said in the steer's notes (never silently dropped)."""
    fam = Family(create_family(compiled("Stack three cubes: red at the bottom, yellow in the middle, blue on top.", tmp_path,
                                        name="fam").path).path)
    r = steer(fam.path, "That's too much for today. Leave out the yellow cube.")
    assert any("set aside: \"That's too much for today.\"" in n for n in r.notes)


@pytest.mark.parametrize("base, edits", [
    # a hostile helper's silent errors against this session's spoken, labelled and reasoned edits (each had compiled)
    ("Build a tower of three red cubes on the blue patch.", ["Make the tower four cubes: two red and two blue."]),  # patch lost
    ("Put three red cubes in a row from left to right.", ["Make the row four cubes: red, blue, green, yellow."]),  # order lost
    ("Stack two red cubes and put a blue cube on top.", ["Make the tower five cubes: red, red, blue, blue, and red in the middle."]),
    ("Put three red cubes in a row.", ["make it 2 mm"]),  # millimetres, no hesitation
    ("Spell CAT with letter cubes in a row from left to right.", ["the word is now longer"]),
    ("Stack the red cube on the blue cube.", ["Put a gold coloured cube on top."]),
    ("Stack the red cube on the blue cube.", ["Put a cube of gold on top."]),
    ("Build a tower of three red cubes.", ["Make the top one green. Add one."]),  # the second sentence had been dropped
    ("Build a tower of three red cubes.", ["Make the top one green. The tower goes on the right side."]),
    ("Build a tower of three red cubes.", ["the row goes on the right side"]),  # the tower had been moved
    ("Arrange four yellow cubes in a row.", ["six cubes in the tower instead of four"]),
    ("Stack the red cube on the blue cube.", ["I want the same three in a row instead"]),  # the count said is checked
    ("Put the red cube to the left of the blue cube and the green cube in front of the blue cube.",
     ["put the two on top of the green cube"]),  # "the two" is no digit cube
    ("Spell the word DOG with letter cubes in a row from left to right.",
     ["the word is now DOGS", "same letters as a tower, D at the bottom and S on top."]),  # O and G had been lost
])
def test_attack_on_spoken_and_restated_edits_is_refused(tmp_path, base, edits):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    for e in edits[:-1]:
        steer(fam.path, e)
    with pytest.raises(BadInput):
        steer(fam.path, edits[-1])


@pytest.mark.parametrize("base, edit, expected", [
    ("Spell CAT with letter cubes in a row from left to right.", "spell L O O K instead",
     ["line[left_to_right](L,O,O,K)", "reads(L,O,O,K;direction=left_to_right,face=up,text=LOOK)"]),  # a double letter kept
    ("Spell CAT with letter cubes in a row from left to right.", "the word is now HMM",
     ["line[left_to_right](H,M,M)", "reads(H,M,M;direction=left_to_right,face=up,text=HMM)"]),  # a word, no hesitation
    ("Stack the red cube on the blue cube.", "actually in front", ["stack(blue,red)@front"]),  # the tower moved, not undone
    ("Put the pink cube to the right of the blue cube.", "add orange left of blue", ["left_of(orange,blue)", "right_of(pink,blue)"]),
])
def test_attack_on_spoken_edits_reads_what_was_said(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[0][1] == expected


def test_instead_exchanges_one_placement_of_a_relational_task(tmp_path):
    """"put the pink one on the red patch instead" of a task where pink's one placement is next to the yellow cube: that
    placement exchanged, the rest kept (it had been refused, and before that the old relation kept beside the new one)."""
    assert _steered(tmp_path, "Put a green cube on a yellow cube and a pink cube next to the yellow cube",
                    "put the pink one on the red patch instead") == [("modify", ["on_patch(pink,patch:red)", "stack(yellow,green)"])]


@pytest.mark.parametrize("base, edit", [
    # a second hostile helper's findings against this session's steering (each had compiled silently wrong or crashed)
    ("Build a tower from bottom to top: red, blue, green.", "the wall goes on the right side"),  # KeyError 'wal'
    ("Build a tower from bottom to top: red, blue, green.", "Remove the top one. Remove the bottom one."),  # one removed
    ("Build a tower from bottom to top: red, blue, green.", "Add a pink cube on top. Add a pink cube at the bottom."),
    ("Build a tower from bottom to top: red, blue, green.", "Make the red one green. She's nervous, so far apart."),
    ("Put the red cube on the green patch.", "the row goes at the back"),  # the patch had been dropped, no row there
    ("Stack the letter B cube on the letter A cube.", "make the tower 3 cubes: two red and one blue on top"),  # letters lost
    ("Build a tower of three red cubes.", "make the tower 4 cubes: two red and two blue, in any order"),  # an order made up
])
def test_second_attack_on_this_sessions_steering_is_refused(tmp_path, base, edit):
    from rpg.errors import BadInput

    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


def test_a_wall_named_by_an_edit_of_a_wall_is_moved(tmp_path):
    assert _steered(tmp_path, "Build a wall two cubes high: three green on the bottom and three white on top.",
                    "the wall goes on the right side") == [("modify", ["wall(green,green,green|white,white,white)@right"])]


def test_a_colour_said_twice_before_one_cube_is_one_cube(tmp_path):
    """"add a yellow yellow cube on top": one cube (a stutter before a singular noun; two had been added)."""
    assert _steered(tmp_path, "Build a tower from bottom to top: red, blue, green.", "add a yellow yellow cube on top") == [
        ("extend", ["stack(red,blue,green,yellow)"])]


@pytest.mark.parametrize("base, edit, expected", [
    # cubes picked by their role in the task's relations (the task had been "not a structure the steering edits")
    ("Put the red cube to the left of the green cube, and the green cube to the left of the blue cube.",
     "make the one on the left yellow", ["left_of(green,blue)", "left_of(yellow,green)"]),
    ("Put the yellow cube to the right of the red cube.", "the one on the right should be blue", ["right_of(blue,red)"]),
    ("Put the white cube between the two blue cubes.", "and make the ends gray", ["between(white;gray,gray)"]),
    ("Put the orange cube between the green cube and the purple cube.", "the cube in the middle should be white",
     ["between(white;green,purple)"]),
    # a cube of a patch's colour recoloured alone (the patch had been recoloured with it, silently)
    ("Put the red cube on the red patch and the blue cube to the right of the red cube.", "make the red cube green",
     ["on_patch(green,patch:red)", "right_of(blue,green)"]),
    ("Put the green cube on the green patch.", "make the green cube blue", ["on_patch(blue,patch:green)"]),
])
def test_cubes_of_a_relational_task_recoloured_by_their_role(tmp_path, base, edit, expected):
    """The instruction with the picked cubes' colour words changed, read back and checked to mean only that change."""
    intent, got = _steered(tmp_path, base, edit)[-1]
    assert (intent, sorted(got)) == ("tweak", expected)


@pytest.mark.parametrize("base, edit", [
    # the roles pick no one cube: both cubes of a chain's middle are on the left of someone
    ("Put the red cube to the left of the green cube and the blue cube to the left of the green cube.",
     "make the one on the left yellow"),
])
def test_a_role_that_picks_no_one_cube_is_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, edit)


@pytest.mark.parametrize("base, edits, expected", [
    ("Line up the letter cubes to spell STAR", ["rearrange it to spell RATS", "now stack them in that order, R at the bottom"],
     ("pivot", ["stack(R,A,T,S)"])),
    ("Put the 1, 2 and 3 digit cubes in a row from left to right", ["reverse it", "stack them in that order, 3 at the bottom"],
     ("pivot", ["stack(3,2,1)"])),
    ("Spell BOX with letter cubes", ["stack them, B at the top and X at the bottom"], ("pivot", ["stack(X,O,B)"])),
    ("Spell BOX with letter cubes", ["stack them in that order, X at the top"], ("pivot", ["stack(B,O,X)"])),
])
def test_a_row_stacked_in_its_order_from_a_named_end(tmp_path, base, edits, expected):
    """A row with an order made a tower in that order (it had been "names no change")."""
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base, edit", [
    # the letters listed after the change had been read as every cube relabelled R: a line of R, R, R, R (silently)
    ("Spell RATS with letter cubes in a row from left to right.", "make it a tower, from bottom to top: R, A, T, S"),
    # a middle cube named, or the others' order unsaid
    ("Spell RATS with letter cubes in a row from left to right.", "stack them in that order, A at the bottom"),
    ("Spell RATS with letter cubes in a row from left to right.", "stack them, R at the bottom"),
])
def test_labels_an_edit_leaves_unread_or_an_order_unsaid_are_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, edit)


_T3 = "Build a tower of red, blue and green from bottom to top"
_ROW3 = "a row of red, blue, green from left to right"
_SWAPPED = "Put the red cube on the blue patch and the blue cube on the red patch"


@pytest.mark.parametrize("base,edit,expected", [
    # the thirty-eighth session's steering attack: each had been silently wrong (the neighbour's colour taken for the cube's,
    # the patch recoloured for the cube on it, every cube recoloured, the stack dropped or its order lost)
    (_T3, "the cube under the green one becomes cyan", ("tweak", ["stack(red,cyan,green)"])),
    (_T3, "Correction: the cube on the blue one is orange", ("tweak", ["stack(red,blue,orange)"])),
    ("Build a tower of red, blue, green and yellow from bottom to top", "the cube between the blue and the yellow one is now pink",
     ("tweak", ["stack(red,blue,pink,yellow)"])),
    (_ROW3, "the cube left of the blue one is now yellow", ("tweak", ["line[left_to_right](yellow,blue,green)"])),
    (_ROW3, "the cube next to the green one becomes cyan", ("tweak", ["line[left_to_right](red,cyan,green)"])),
    (_ROW3, "the cube in between is brown", ("tweak", ["line[left_to_right](red,brown,green)"])),
    (_T3, "it should be yellow, not blue", ("tweak", ["stack(red,yellow,green)"])),
    (_ROW3, "blue, not green, is on the right", ("tweak", ["line[left_to_right](red,blue,blue)"])),
    (_SWAPPED, "the cube on the red patch becomes green", ("tweak", ["on_patch(green,patch:red)", "on_patch(red,patch:blue)"])),
    ("Put the red cube on the red patch", "the cube on the red patch is now blue", ("tweak", ["on_patch(blue,patch:red)"])),
    (_SWAPPED, "paint the patch under the red cube yellow", ("tweak", ["on_patch(blue,patch:red)", "on_patch(red,patch:yellow)"])),
    ("Build a tower of red, blue and green from bottom to top on the red patch", "change the red patch to orange",
     ("tweak", ["on_patch(red,patch:orange)", "stack(red,blue,green)"])),
    (_ROW3, "stack them in reverse order of the row", ("pivot", ["stack(green,blue,red)"])),
    (_ROW3, "stack them in the order of the row", ("pivot", ["stack(red,blue,green)"])),
    # steer_stranger20's silent error: the pair stacked in the order said (K had gone on M)
    ("Put the letter cube K to the left of the letter cube M.", "The exercise wants them stacked, M on top of K.",
     ("modify", ["stack(K,M)"])),
    ("Put the red cube left of the blue cube", "stack them, blue on top of red", ("modify", ["stack(red,blue)"])),
])
def test_cubes_picked_by_neighbour_patch_or_correction(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edit,words", [
    (_T3, "the top one is green, not red", "the cube picked is green, not red"),  # the negated colour is checked, not dropped
    (_T3, "make the bottom blue cube pink", "the cube picked is red, not blue"),
    (_T3, "the cube left of the blue one is now yellow", "no cube of a tower stands left of another"),
    ("Build a tower of red, blue, green and yellow from bottom to top", "the cube between the red and the yellow one is pink",
     "2 cubes stand between the two named"),
    (_ROW3, "the cube next to the blue one becomes cyan", "2 cubes stand beside the one named"),
])
def test_cube_picks_that_do_not_hold_are_refused(tmp_path, base, edit, words):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=re.escape(words)):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger21's silent errors (development material from the thirty-eighth session)
    ("Make a pile of two green cubes and two purple cubes.", "The collection should be sorted: one pile for each colour.",
     ("modify", ["piles(green,green,purple,purple;by=color)"])),  # (three red cubes had been made up)
])
def test_a_sort_of_the_task_s_cubes_keeps_them(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edit,words", [
    # each had been read by one relation word or added on top (silently wrong)
    ("Put the M cube and the O cube next to each other.",
     "She wants it to spell MOP, so line up the M, the O and the P from left to right.", "not a structure"),  # (M right of O)
    ("Put the pink cube to the left of the purple cube.", "Line them up with a gray cube: pink, purple, then gray, from left to right.",
     "not a structure"),  # (gray left of pink)
    ("Stack a blue cube on an orange cube in the front right corner.",
     "Add a second piece alongside it: a green cube on a pink cube, in the front left corner.", "names no change"),
])
def test_edits_that_say_more_than_one_relation_or_cube_are_refused(tmp_path, base, edit, words):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=re.escape(words)):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # a change reported as someone's want or words (its words had been refused as unknown, or the want read as an action)
    ("Build a tower with a yellow cube on the bottom, then a red one, then a blue one",
     ["Maya says it needs a purple one on the very top too.", "Now she wants the red one taken out, but everything else can stay."],
     ("tweak", ["stack(yellow,blue,purple)"])),
    ("Arrange a red, an orange and a yellow cube in a row from left to right.", ["He'd like a green cube added at the right end."],
     ("extend", ["line[left_to_right](red,orange,yellow,green)"])),
    ("Put the yellow cube between the red patch and the blue patch.",
     ["The curator asks for the yellow cube to be replaced with a cyan one."], ("tweak", ["between(cyan;patch:blue,patch:red)"])),
    ("Build a tower of red, blue and green from bottom to top", ["the homework says it should be yellow, not blue"],
     ("tweak", ["stack(red,yellow,green)"])),
])
def test_a_change_reported_as_someone_s_want(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected



_FRONT = "Put the red cube in front of the blue cube and the green cube behind the blue cube."


@pytest.mark.parametrize("base,edit,expected", [
    # a second attack on this session's steering: "behind"/"in front of" had been dropped (the anchor recoloured), and a
    # row stacked with a place had stayed a row or lost its corner
    (_FRONT, "The cube behind the red cube becomes yellow", ("tweak", ["behind(green,yellow)", "in_front_of(red,yellow)"])),
    (_FRONT, "The cube behind the blue cube becomes yellow", ("tweak", ["behind(yellow,blue)", "in_front_of(red,blue)"])),
    (_ROW3, "Stack them in reverse order of the row, in the back left corner.", ("pivot", ["stack(green,blue,red)@back_left"])),
    (_ROW3, "stack them in the back left corner", ("pivot", ["stack(red,blue,green)@back_left"])),
    (_T3, "Put them in a row in the order of the tower.", ("pivot", ["line[left_to_right](red,blue,green)"])),
    # steer_stranger16's x030: "add:" before a relation is an addition (the old relation had been dropped)
    ("Place the blue cube behind the green cube.", "add: the red cube is left of the green cube",
     ("extend", ["behind(blue,green)", "left_of(red,green)"])),
    # steer_stranger16's x031: a place said without "the" (the corner had been dropped with the change)
    ("Put red cube on top of yellow cube, and yellow cube on top of blue cube.",
     "Now remove the red one and put tower in back left corner.", ("modify", ["stack(blue,yellow)@back_left"])),
])
def test_second_attack_on_neighbour_picks_and_kept_orders(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edit,words", [
    (_FRONT, "The cube in front of the red cube becomes yellow", "not a structure"),  # no cube stands there
    (_T3, "The cube in front of the blue cube becomes yellow", "picks no cube of a tower by what stands front"),
    (_ROW3, "The cube far from the red cube becomes yellow", "picks no cube of a line by what stands far"),
    ("Put the red, blue and green cubes in a row.", "Stack them in the order of the row.", "no order, so there is none to keep"),
    (_T3, "Stack them in reverse order of the row.", "the version it builds on is a tower"),
    # steer_stranger16's x044: both put in the centre, the stack said with it lost (silently)
    ("Put a green cube in the left half and a red cube in the right half.", "stack them both in the centre, green on top",
     "names no change"),
])
def test_second_attack_refusals(tmp_path, base, edit, words):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=re.escape(words)):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger22 (read at the thirty-ninth session's start): the added cube's colour said after it ("make it cyan"
    # had recoloured the whole tower: silently wrong)
    ("Put the yellow cube to the right of the purple cube.",
     ["Move the yellow one on top of the purple one.", "And a third cube on top, make it cyan."], ("extend", ["stack(purple,yellow,cyan)"])),
    # "scratch that last change": the change taken back (the verb had been refused as an action)
    (_T3, ["Add a yellow cube on top.", "Scratch that last change."], ("tweak", ["stack(red,blue,green)"])),
    # "same three, but as a tower" said by its ends: the cube left over stands between them (a tower of two had been read)
    ("Put the yellow cube to the left of the pink cube, and the pink cube to the left of the cyan cube.",
     ["Variant B: same three, but as a tower, yellow on the bottom and cyan on top."], ("pivot", ["stack(yellow,pink,cyan)"])),
    # "all three in a row instead, brown, green, yellow from left to right": a row (the direction alone had been read, of the
    # chain of relations)
    ("Put the brown cube in front of the green cube and the yellow cube behind the green cube.",
     ["Next setup: all three in a row instead, brown, green, yellow from left to right."],
     ("pivot", ["line[left_to_right](brown,green,yellow)"])),
    # "Next shot: same stack, but in the back left corner": the task's stack moved (a default stack of two had been made)
    ("Stack a red cube on a white cube.", ["Next shot: same stack, but in the back left corner."],
     ("modify", ["stack(white,red)@back_left"])),
    # people's judgement before the change set aside; a cube judged by its colour is the change's "it"
    ("Put the white cube next to the black cube.", ["Also put a gray cube next to the white one.",
                                                     "Testers say three is clutter. Get rid of the black cube."],
     ("tweak", ["next_to(gray,white)"])),
    ("Put the orange cube between the green cube and the purple cube.", ["The orange's too loud. Replace it with a gray one."],
     ("tweak", ["between(gray;green,purple)"])),
    ("Put four black cubes in a row at the front of the table.",
     ["Too dark for the living room. Make all of them white.", "Client changed her mind again. Go back to the black ones."],
     ("tweak", ["line(black,black,black,black)@front"])),
    # a count with the cubes kept listed ("make it two cubes, yellow and green": the count had been taken for a cube)
    ("Build a tower: yellow on the bottom, then green, then blue.", ["Players keep knocking it over. Make it two cubes, yellow and green."],
     ("tweak", ["stack(yellow,green)"])),
    # the middle of a row of one colour in no order: read left to right
    ("Put a row of three white cubes along the back of the table.", ["The homeowner thinks it's too plain. Make the middle one gray."],
     ("tweak", ["line[left_to_right](white,gray,white)@back"])),
    # "between them" of a task of two cubes; "same spot" of cubes in a region; "lose one"
    ("Put the black cube to the right of the white cube.", ["And stick a gray cube in between them."],
     ("extend", ["between(gray;black,white)", "right_of(black,white)"])),
    ("Line up three cyan cubes in a row on the right side of the table.", ["Stack them into a tower instead, same spot.", "Lose one."],
     ("tweak", ["stack(cyan,cyan)@right"])),
])
def test_steer_stranger22_edits_read_as_said(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


@pytest.mark.parametrize("base,edit,words", [
    # steer_stranger22: one cube in two corners (it had been moved to the first), the task's cubes said kept but others read
    ("Put the orange cube in the front left corner and the blue cube in the back right corner.",
     "The blue cube should also be in the front left corner, and stay in the back right one.", "stay"),
    (_FRONT, "All three in a row, blue, yellow, green from left to right.", "keeps the task's cubes"),
    (_T3, "Now all three in a row.", "keeps the task's cubes"),  # (a row of four default cubes had been made)
])
def test_steer_stranger22_refusals(tmp_path, base, edit, words):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match=re.escape(words)):
        steer(fam.path, edit)


_LINE_YGC = "Line up the yellow cube, the green cube and the cyan cube from left to right."
_CORNERS = "Put the red cube in the back right corner and the blue cube in the front left corner."


@pytest.mark.parametrize("base,edit", [
    # a hostile helper's attack on this session's steering: each had compiled silently wrong
    ("Stack the red cube on the blue cube.", "add a red cube on top, make it cyan"),  # which cube is cyan?
    (_LINE_YGC, "same three, but as a tower, cyan on top of yellow"),  # cyan right on yellow: no middle to fill
    (_LINE_YGC, "same three, but as a tower, yellow first and cyan second"),
    (_LINE_YGC, "same three, but as a tower, cyan second from the bottom and yellow on top"),
    (_LINE_YGC, "same three as a tower with yellow directly under cyan"),  # (the green cube had been dropped)
    ("Build a tower from bottom to top: red, green, blue, in the back left corner.",
     "all three in a row instead, blue, green, red from left to right"),  # (the corner had been dropped)
    ("Stack a red cube on a white cube.", "Same row but on the left."),  # a structure the task does not have
    ("Stack a red cube on a white cube.", "same pyramid but on the left"),
    (_CORNERS, "move the red cube to the back left corner and the front left corner"),  # one cube, two places
    ("Build a tower of red, blue and green in the back right corner.", "move it to the front left corner and the back left corner"),
])
def test_thirty_ninth_session_steering_attack_is_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edit,expected", [
    ("Stack the red cube on the blue cube.", "add a cube on top, make them cyan", ("extend", ["stack(cyan,cyan,cyan)"])),
    ("Stack the red cube on the blue cube.", "add two cubes on top, make them cyan", ("extend", ["stack(blue,red,cyan,cyan)"])),
    (_LINE_YGC, "same three as a tower, yellow on the bottom and cyan on top", ("pivot", ["stack(yellow,green,cyan)"])),
    ("Stack a red cube on a white cube.", "Same stack in the back left corner.", ("modify", ["stack(white,red)@back_left"])),
    (_CORNERS, "Move the red cube from the back right corner to the front right corner.",
     ("modify", ["in_region(blue,front_left)", "in_region(red,front_right)"])),
])
def test_thirty_ninth_session_steering_read_as_said(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger22's other classes (read at the thirty-ninth session): new task markers of a trade, a word spelled though
    # it is a known word, a wall's width said "across", "stretch it to five", "the other way round", a patch used instead,
    # the middle cube said again, the original said as "the way it was at the start", the word moved
    ("Build a row of cubes from left to right: red, orange, yellow, green.",
     ["New idea for the back counter, nothing to do with the row: just a tower of three white cubes."],
     ("fresh", ["stack(white,white,white)"])),
    ("Stack three red cubes on the green patch.",
     ["New room, new puzzle: the brown cube in the back right corner and the purple cube in the front left corner."],
     ("fresh", ["in_region(brown,back_right)", "in_region(purple,front_left)"])),
    ("Spell TOY with letter cubes, left to right.", ["Now make it say TOYS."],
     ("extend", ["line[left_to_right](T,O,Y,S)", "reads(T,O,Y,S;direction=left_to_right,face=up,text=TOYS)"])),
    ("Make a wall of blue cubes, three across and two high.", ["Make it four across."],
     ("tweak", ["wall(blue,blue,blue,blue,blue,blue,blue,blue)"])),
    ("Put three pink cubes in a row.", ["Playtest 2: stretch it to five."], ("tweak", ["line(pink,pink,pink,pink,pink)"])),
    ("Put the blue cube on the left side of the table and the green cube on the right side of the table.",
     ["The buyers would rather have them the other way round."], ("modify", ["in_region(blue,right)", "in_region(green,left)"])),
    ("Put the white cube on top of the gray cube, and the gray cube on the blue patch.", ["Use a red patch instead of the blue one."],
     ("tweak", ["on_patch(gray,patch:red)", "stack(gray,white)"])),
    ("Put the gray cube between the red cube and the yellow cube.", ["Fine, a brown cube in the middle then."],
     ("tweak", ["between(brown;red,yellow)"])),
    ("Build a tower of three cubes: blue on the bottom, then yellow, then red on top.",
     ["Swap the yellow one for a green one.", "Put it back the way it was at the start."], ("tweak", ["stack(blue,yellow,red)"])),
    ("Spell HOME with letter cubes from left to right.", ["Put the word along the back of the table."],
     ("modify", ["line[left_to_right](H,O,M,E)@back", "reads(H,O,M,E;direction=left_to_right,face=up,text=HOME)"])),
])
def test_steer_stranger22_trade_edits(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_both_moved_with_a_relation_is_not_read_as_a_move_alone(tmp_path):
    # "next to each other" had been dropped (both put in the centre, silently wrong)
    fam = Family(create_family(compiled("Put the blue cube on the left side of the table and the green cube on the right side of "
                                        "the table.", tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, "Put them both in the center instead, next to each other.")


@pytest.mark.parametrize("base,edit", [
    # a second hostile helper's attack on this session's steering: each had compiled silently wrong
    ("a row of red, green, blue from left to right", "Same row but in the front, reversed."),  # (moved only)
    ("Stack the red cube on the blue cube.", "I don't want them the other way round."),  # (swapped)
    ("Stack the green cube on the yellow cube.", "New idea: same cubes, but side by side."),  # (cubes made up)
    ("Make a wall of gray cubes, three across and two high.", "Make the cube two across on the top row red."),  # (2 wide)
    ("Put the red cube and the blue cube in the back left corner.", "Stack them into a tower instead, same spot."),  # (corner lost)
    ("Put the red cube and the blue cube in the back left corner.", "Stack them into a tower instead."),
    ("Put the red cube to the left of the blue cube.", "Add a green and a yellow cube far apart and a gray cube between the two."),
    (_T3, "Take off one, from the bottom."),  # (the top had gone)
    (_T3, "Mum says blue at the bottom. Add a yellow cube on top."),  # (her want dropped)
    (_T3, "Testers said no green. Add a yellow cube on top."),
    ("Build a tower of red, green and blue from bottom to top", "The green's too dull for the tower. Replace the top with it."),
    ("Put three white cubes in a row.", "Make the middle one gray and the first one black."),  # (a direction made up)
    ("Put the blue cube on the left side of the table and the green cube on the right side of the table.",
     "Put them both in the center, side by side."),
    (_CORNERS, "Move it to the back left corner, and the blue cube to the front."),
    ("Build a tower of three cubes: blue on the bottom, then yellow, then red on top.",
     "The yellow one: change it back to what it was at first."),  # (the whole task had gone back)
    ("Spell CAT with letter cubes from left to right.", "Have the letters on the left side swap."),
    ("Spell CAT with letter cubes from left to right.", "Put the word along the back edge, reading right to left."),
])
def test_thirty_ninth_session_second_attack_is_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


def test_read_right_to_left_is_a_direction_not_a_word(tmp_path):
    assert _steered(tmp_path, "Spell CAT with letter cubes from left to right.", "Make it read RIGHT TO LEFT.")[-1] == (
        "modify", ["line[right_to_left](C,A,T)", "reads(C,A,T;direction=right_to_left,face=up,text=CAT)"])


@pytest.mark.parametrize("base,edits,expected", [
    # steer_stranger22's last classes read this session: the ends of a row of one colour, people who cracked it, the
    # original said as a reset, a want said with "also" and a place, one cube kept
    ("Put four gray cubes in a row.", ["Make the two at the ends red."], ("tweak", ["line[left_to_right](red,gray,gray,red)"])),
    ("Build a tower of red, green, blue and yellow from bottom to top", ["Make both ends white."],
     ("tweak", ["stack(white,green,blue,white)"])),
    ("Stack the cubes labelled 4, 7 and 2 with 4 at the bottom and 2 on top.",
     ["Players cracked it in two minutes. Add a 9 at the bottom.", "Too hard now. Reset the puzzle to the original code."],
     ("tweak", ["stack(4,7,2)"])),
    ("Put the red cube on the blue patch.", ["She'd also like a black cube in front of the red one."],
     ("extend", ["in_front_of(black,red)", "on_patch(red,patch:blue)"])),
    ("Put the red cube on the yellow patch and the blue cube on the yellow patch too.", ["Only the blue cube this time."],
     ("tweak", ["on_patch(blue,patch:yellow)"])),
])
def test_steer_stranger22_last_classes(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_the_ends_of_a_row_of_several_colours_in_no_order_are_refused(tmp_path):
    fam = Family(create_family(compiled("Put the red, blue, green and yellow cubes in a row.", tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="the ends"):
        steer(fam.path, "Make the two at the ends white.")


@pytest.mark.parametrize("base,edit", [
    # a third attack: the ends of a layer or row of a structure (the whole layer had been recoloured, or a removal dropped)
    ("Build a pyramid with three red cubes on the bottom, two green in the middle and a blue on top.",
     "make the two at the ends of the bottom row white"),
    ("Build a wall of white cubes three wide and two high.", "make the two at the ends of the top row red"),
    ("Build a wall of white cubes three wide and two high.", "remove the ends of the top row"),
])
def test_the_ends_of_a_part_of_a_structure_are_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(SteerError, match="ends of a part"):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edit,expected", [
    # "swap X with Y" exchanges the two colours (it had replaced one by the other: every cube white); "swap X for Y" replaces
    ("Put a red, a white, a white and a red cube in a row, in that order.", "swap the red cubes with the white cubes",
     ("modify", ["line[sequence](white,red,red,white)"])),
    (_T3, "swap red for yellow", ("tweak", ["stack(yellow,blue,green)"])),
])
def test_swap_with_exchanges_and_swap_for_replaces(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


_TOWER_RBG = "Stack three cubes: red on the bottom, blue in the middle and green on top."


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger24 (read at the forty-first session): labels and chatter of a voice around the change, a new task said
    # by a voice's words, a change said passively or without its verb, a reversal said by the word it gives, a row of a wall
    ("Put the red cube in the left half of the table.",
     "Beautiful. A new piece now, nothing from before: a pyramid of three cubes, two green on the bottom and a yellow one on top.",
     ("fresh", ["pyramid(green,green|yellow)"])),
    ("Place a black cube far from a white cube.",
     "The study is closed. New protocol, unrelated to the old one: two towers, one of two red cubes and one of two green cubes.",
     ("fresh", ["stack(green,green)", "stack(red,red)"])),
    ("Stack a blue cube on top of a yellow cube.", "Protocol change requested by the sponsor: a red cube is added on top of the blue cube.",
     ("extend", ["stack(yellow,blue,red)"])),
    ("Stack a blue cube on top of a yellow cube.", "feat: also put a purple cube on top", ("extend", ["stack(yellow,blue,purple)"])),
    ("Make a pyramid of six cubes: three red cubes on the bottom, two green cubes in the middle and one blue cube on top.",
     "Per the sponsor, the blue top cube is replaced with a yellow one.", ("tweak", ["pyramid(red,red,red|green,green|yellow)"])),
    ("Put the green cube to the left of the blue cube.", "chat wants a red cube in between them",
     ("extend", ["between(red;blue,green)", "left_of(green,blue)"])),
    (_TOWER_RBG, "Again from the top, but the middle one becomes purple.", ("tweak", ["stack(red,purple,green)"])),
    (_TOWER_RBG, "Cut. The top cube reads wrong on camera, make it black.", ("tweak", ["stack(red,blue,black)"])),
    ("Put four purple cubes in a row.", "Two more purple cubes in the row, please.",
     ("extend", ["line(purple,purple,purple,purple,purple,purple)"])),
    ("Stack three yellow cubes in the front left corner.", "Raise the tower by two more yellow cubes.",
     ("extend", ["stack(yellow,yellow,yellow,yellow,yellow)@front_left"])),
    ("Spell DOG with letter cubes from left to right.", "Reverse it so it reads GOD.",
     ("modify", ["line[left_to_right](G,O,D)", "reads(G,O,D;direction=left_to_right,face=up,text=GOD)"])),
    ("Build a wall two rows high: three red cubes in the bottom row and three yellow cubes in the top row.",
     "feat: add a third row of three blue cubes on top of the wall", ("extend", ["wall(red,red,red|yellow,yellow,yellow|blue,blue,blue)"])),
])
def test_forty_first_session_steering_read_as_said(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edit", [
    # silent classes found at the forty-first session: "it" after a clause that says more of a cube had recoloured every
    # cube; a change clause after another dropped; a cube picked by its place beside a resize applied after it; a reversal
    # whose word is not the old one reversed; a row of another width added to a wall
    (_TOWER_RBG, "The top cube goes on the left, make it black."),
    (_TOWER_RBG, "make the top cube black and add one"),
    (_TOWER_RBG, "Make the top cube black, then make it bigger"),
    ("Spell DOG with letter cubes from left to right.", "Reverse it so it reads CAT."),
    ("Build a wall two rows high: three red cubes in the bottom row and three yellow cubes in the top row.",
     "add a row of two blue cubes on top"),
])
def test_forty_first_session_steering_attack_is_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edits,expected", [
    # silent classes of steer_stranger24 (read at the forty-first session): "a 6 cube" is the digit cube 6 (six cubes had
    # been added); a sorted row of named digits keeps them (1, 2, 3 had been made up)
    ("stack the 4 cube on top of the 2 cube", ("ok put a 6 cube on top",), ("extend", ["stack(2,4,6)"])),
    ("stack the 6 cube on the 4 cube on the 2 cube", ("now make them a row instead, smallest number on the left",),
     ("pivot", ["line[left_to_right](2,4,6)"])),
    ("Build a tower of three red cubes.", ("make it taller and add a yellow one on top",), ("extend", ["stack(red,red,red,yellow)"])),
])
def test_forty_first_session_steering_keeps_the_cubes_said(tmp_path, base, edits, expected):
    assert _steered(tmp_path, base, *edits)[-1] == expected


def test_a_pivot_that_cannot_state_the_task_s_labels_is_refused(tmp_path):
    """A circle of the digit cubes 2, 4 and 6 is said as "3 digit blocks", read back as 1, 2 and 3: refused (it had been
    made of 1, 2, 3, silently)."""
    fam = Family(create_family(compiled("stack the 6 cube on the 4 cube on the 2 cube", tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, "make them a circle instead")


@pytest.mark.parametrize("base,edit", [
    # a hostile helper's silent classes (forty-first session): a passive change after another dropped, "it"/"them" after
    # a part of the task recolouring every cube, a place picked after an addition read before it, counted runs merged, a
    # digit said of several cubes, a plural added as one cube, a row added under a wall put on top
    ("Line up red, blue and green from left to right.", "the leftmost cube gets replaced with a white one and the rightmost gets removed"),
    ("Line up red, blue and green from left to right.", "make the left cube white and the right cube gets removed"),
    (_TOWER_RBG, "the top is too dark, make it white"),
    ("Line up red, blue and green from left to right.", "the ends are too dark, make them white"),
    (_TOWER_RBG, "add a black cube on top then make the top cube white"),
    (_TOWER_RBG, "add two yellow then one white on top"),
    ("Stack the 2 cube on the 1 cube.", "put two 5 cubes on top"),
    (_TOWER_RBG, "Step 2: add white cubes on top"),
    (_TOWER_RBG, "Raise the tower by two cubes"),
])
def test_forty_first_session_steering_helper_attack_is_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


@pytest.mark.parametrize("base,edit", [
    # the session's own rules, attacked by the read steering sets: a label that says an addition ("Add a clue:") had been
    # dropped and the rest read as the whole new task, losing the earlier cubes
    ("Put the black cube on the white patch.", "Add a clue: a red cube to the left of the white patch."),
    ("Stack the blue cube on the orange cube in the front right corner.",
     "Add a second piece alongside it: a green cube on a pink cube, in the front left corner."),
])
def test_a_label_saying_an_addition_never_becomes_a_new_task(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    try:
        r = steer(fam.path, edit)
    except BadInput:
        return
    from rpg.schema.meaning import meaning

    assert r.intent == "extend" and any("patch:white" in a or "orange" in a for a in meaning(fam.schema(r.version)))


def test_back_to_take_one_is_the_first_version(tmp_path):
    from rpg.schema.meaning import meaning

    fam = Family(create_family(compiled("Stack the red cube on the yellow cube.", tmp_path, name="fam").path).path)
    steer(fam.path, "add a blue cube on top")
    steer(fam.path, "make the top one green")
    r = steer(fam.path, "Let's go back to take one.")
    assert meaning(fam.schema(r.version)) == ["stack(yellow,red)"]


_ROW_GCB = "Arrange the blocks in order green, cyan, blue from left to right."
_TOWER_BWY = "Build a tower: brown on the bottom, white in the middle, yellow on top."


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger25 (read at the forty-second session): a new order said with a reorder verb and a direction (the list
    # had had no place in the change read), 'convert' and 'relocate', a passive replacement, "Further,", a tier said by its
    # cube, "top up the tower with ..."
    (_ROW_GCB, "Rearrange them from left to right: blue, green, cyan.", ("modify", ["line[left_to_right](blue,green,cyan)"])),
    (_ROW_GCB, "Now let's put them in traffic-light order from left to right: blue, green, cyan.",
     ("modify", ["line[left_to_right](blue,green,cyan)"])),
    (_ROW_GCB, "Now the order is blue, green, cyan from left to right.", ("modify", ["line[left_to_right](blue,green,cyan)"])),
    (_ROW_GCB, "Convert the line to a tower, green at the bottom and blue at the top.", ("pivot", ["stack(green,cyan,blue)"])),
    (_ROW_GCB, "Further, the green cube shall be replaced by a black cube.", ("tweak", ["line[left_to_right](black,cyan,blue)"])),
    (_TOWER_BWY, "And add one more tier, a red cube right on top, like a cherry.", ("extend", ["stack(brown,white,yellow,red)"])),
    (_TOWER_BWY, "Relocate the stack to the front right corner.", ("modify", ["stack(brown,white,yellow)@front_right"])),
    (_TOWER_BWY, "Top up the tower with one more red cube.", ("extend", ["stack(brown,white,yellow,red)"])),
    ("Stack three pink cubes into a little tower.", "Then just make it a tower of five pink cubes.",
     ("tweak", ["stack(pink,pink,pink,pink,pink)"])),  # its own colour restated with the count
    ("Build a wall: a bottom row of three brown cubes and a top row of three gray cubes.",
     "Swap the rows: gray on the bottom, brown on top.", ("modify", ["wall(gray,gray,gray|brown,brown,brown)"])),
    ("Put the cyan cube next to the orange cube.", "Add one gray cube next to the cyan cube.",
     ("extend", ["next_to(cyan,gray)", "next_to(cyan,orange)"])),
    ("Put the cyan cube next to the orange cube.", "Change the orange cube for a red one.", ("tweak", ["next_to(cyan,red)"])),
    # a verb the lexicon lacks in the caused-motion construction: a move of what the task has, an addition of a new cube
    ("Stack the red cube on the blue cube.", "Now ferry the tower to the back of the table.", ("modify", ["stack(blue,red)@back"])),
    ("Stack the red cube on the blue cube.", "Also park a green cube next to the blue cube.",
     ("extend", ["next_to(blue,green)", "stack(blue,red)"])),
    ("Put the red cube on the orange patch.", "Amended: the orange patch is replaced by a purple patch.",
     ("tweak", ["on_patch(red,patch:purple)"])),
    ("The court orders a row of the letter cubes spelling LAW, read left to right.", "Amended: the row shall spell JAW.",
     ("modify", ["line[left_to_right](J,A,W)", "reads(J,A,W;direction=left_to_right,face=up,text=JAW)"])),
])
def test_forty_second_session_steering_read_as_said(tmp_path, base, edit, expected):
    assert _steered(tmp_path, base, edit)[-1] == expected


@pytest.mark.parametrize("base,edit", [
    # steer_stranger25's two silent edits: a second structure made had replaced the task's ("Make a second heap of three
    # brown cubes" of a pile of four orange cubes); an edit read as the same wall again had been recorded as a change
    ("Pile the four orange cubes up in the middle of the table.",
     "Make a second heap of three brown cubes on the right side of the table."),
    ("Pile the four orange cubes up in the middle of the table.", "Build a second tower of three brown cubes on the right."),
    ("Build a two-row wall along the front: three blue cubes below, three green cubes above.",
     "Extend the wall: a fourth cube in each row, same colours."),
    (_ROW_GCB, "Put them from left to right: blue, red, cyan."),  # a list that is not the row's cubes
    ("Build a wall: a bottom row of three brown cubes and a top row of three gray cubes.",
     "Swap the rows: brown on the bottom, gray on top."),  # a swap restated as the rows it had
    ("Stack a pink cube on a blue cube.", "Make it a tower of five pink cubes."),  # pink is not the tower's one colour
    ("Stack the red cube on the blue cube.", "Melt the tower onto the green patch."),  # a change of the cubes, not a move
])
def test_forty_second_session_steering_silent_classes_refused(tmp_path, base, edit):
    fam = Family(create_family(compiled(base, tmp_path, name="fam").path).path)
    with pytest.raises(BadInput):
        steer(fam.path, edit)


@pytest.mark.parametrize("edit", ["Nobody wants a green cube on top.", "Nobody wants the red cube moved to the back.",
                                  "No one wants a green cube on top."])
def test_forty_third_session_a_negated_asker_is_refused(tmp_path, edit):
    """'Nobody' had been read as a person's name asking for the change (a green cube had been added)."""
    fam = compiled("Stack the red cube on the blue cube.", tmp_path, name="fam").path
    with pytest.raises(BadInput, match="negation"):
        steer(fam, edit)


def test_forty_third_session_a_relation_said_again_instead_keeps_the_rest(tmp_path):
    """steer_stranger26 t016: a standalone edit giving two cubes of the task another relation "instead" exchanges that one
    relation (the orange cube's patch had been lost as a pivot)."""
    got, intent = _meaning_after(tmp_path, "Put the orange cube on the purple patch, and the cyan cube directly behind the "
                                 "orange cube.", ["Revised brief: the cyan cube stands in front of the orange cube instead."])
    assert got == ["in_front_of(cyan,orange)", "on_patch(orange,patch:purple)"] and intent == "modify"


def test_forty_third_session_a_cube_stacked_instead_does_not_replace_the_base_cubes_place(tmp_path):
    """'Put a brown cube on the gray cube instead' of a gray cube in a corner had replaced the corner (the stack's atom names
    its bottom first); the brown cube has no placement to replace, so the edit is refused."""
    fam = compiled("Put the gray cube in the back left corner.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Put a brown cube on the gray cube instead.")


def test_forty_third_session_same_colours_with_a_recolour_is_refused(tmp_path):
    """steer_stranger26 t041: "same colours left to right, red first" had been read as every cube made red."""
    fam = compiled("Stack red, green and blue, bottom to top.", tmp_path, name="fam").path
    with pytest.raises(BadInput, match="keeps the colours"):
        steer(fam, "make it a row instead, same colours left to right, red first")


def test_forty_third_session_keep_everything_but_is_no_exclusion(tmp_path):
    """'keep everything but make it a tower' turns the task ('everything but' before a verb is no 'all but' exclusion, which
    had refused it as a negation)."""
    assert _steered(tmp_path, "Place four yellow cubes in a row", "keep everything but make it a tower") == [
        ("pivot", ["stack(yellow,yellow,yellow,yellow)"])]


def test_forty_third_session_an_additional_cube_never_replaces_the_task(tmp_path):
    """steer_stranger23 y002: "Additional traffic: a pink cube onto the orange patch." had become a new task without the
    green cube (a pivot); an edit that says it adds keeps the task or is refused."""
    fam = compiled("Put the green cube on the orange patch.", tmp_path, name="fam").path
    try:
        r = steer(fam, "Additional traffic: a pink cube onto the orange patch.")
    except BadInput:
        return
    from rpg.schema.meaning import meaning

    assert "green" in " ".join(meaning(Family(fam).schema(r.version)))


@pytest.mark.parametrize("edit", ["It's too tall for the aquarium lid, take one blue off.", "Take off one of the blues.",
                                  "Remove a blue cube."])
def test_forty_fourth_session_one_of_a_run_of_identical_cubes_is_removed(tmp_path, edit):
    """steer_stranger27 r047: "take one blue off" a tower green, green, blue, blue had removed both blue cubes ('one blue'
    without a noun was no count); one of two blue cubes standing together leaves the same tower whichever goes."""
    assert _meaning_after(tmp_path, "Make a tower of four cubes: green, green, blue, blue from the bottom.", [edit]) == (
        ["stack(green,green,blue)"], "tweak")


def test_forty_fourth_session_one_of_identical_cubes_apart_is_not_guessed(tmp_path):
    """Blue cubes that do not stand together: which one goes changes the tower, so the edit is refused."""
    fam = compiled("Make a tower of four cubes: green, blue, green, blue from the bottom.", tmp_path, name="fam").path
    with pytest.raises(BadInput, match="does not say which"):
        steer(fam, "Take one blue off.")


@pytest.mark.parametrize("base,edit,expected", [
    ("Put the purple cube on the orange patch and the pink cube on the orange patch too.", "Move the pink one onto a new green patch.",
     ["on_patch(pink,patch:green)", "on_patch(purple,patch:orange)"]),
    ("Put the red cube left of the blue cube and the green cube on the yellow patch.", "Move the red cube onto the yellow patch.",
     ["on_patch(green,red,patch:yellow)"]),
    ("Put the red cube left of the blue cube and the green cube on the yellow patch.", "Move the green cube onto a new red patch.",
     ["left_of(red,blue)", "on_patch(green,patch:red)"]),
])
def test_forty_fourth_session_a_moved_cube_leaves_its_old_place(tmp_path, base, edit, expected):
    """steer_stranger27 r049: "move the pink one onto a new green patch" of two cubes on one patch had been refused (read as
    one more placement, 'new' unread); moving a cube of the task replaces its one placement, like "instead"."""
    assert _meaning_after(tmp_path, base, [edit]) == (expected, "modify")


def test_forty_fourth_session_the_cube_already_on_the_patch_is_not_added_again(tmp_path):
    """"Put the pink cube on the orange patch" of a task whose pink cube stands there had added a second pink cube."""
    fam = compiled("Put the purple cube on the orange patch and the pink cube on the orange patch too.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Put the pink cube on the orange patch.")


@pytest.mark.parametrize("base,edit,expected", [
    ("Tonight's running session: a row of two orange cubes and one white cube, order doesn't matter.",
     "Put the white one in the middle.", ["line[sequence](orange,white,orange)"]),
    ("Put red, green and blue in a row from left to right.", "Put the red one in the middle.", ["line[left_to_right](green,red,blue)"]),
    ("Put red, green and blue in a row from left to right.", "Move the blue cube to the left end.",
     ["line[left_to_right](blue,red,green)"]),
    ("Stack red, green and blue from the bottom.", "Put the red one in the middle.", ["stack(green,red,blue)"]),
])
def test_forty_fourth_session_a_cube_moved_within_its_row_or_tower(tmp_path, base, edit, expected):
    """steer_stranger27 r058: "put the white one in the middle" of a row had been read as the table's centre and refused; one
    cube of a row or tower moved to its middle or to an end said by side."""
    assert _meaning_after(tmp_path, base, [edit]) == (expected, "modify")


def test_forty_fourth_session_a_middle_that_leaves_the_rest_unsaid_is_refused(tmp_path):
    """A row of three different cubes in no order: the middle said for one leaves the two ends' places unsaid."""
    fam = compiled("Make a row of a red, a green and a blue cube.", tmp_path, name="fam").path
    with pytest.raises(BadInput, match="others' places"):
        steer(fam, "Put the red one in the middle.")


def test_forty_fourth_session_a_letter_swapped_in_a_named_row(tmp_path):
    """steer_stranger27 r011: "swap the C for a B" of the letter cubes C, A and T in a row had been refused (the row was stated
    as up-faces that read a word, which demands more than the task said)."""
    assert _meaning_after(tmp_path, "Put the letter cubes C, A and T in a row from left to right.", ["Swap the C for a B."]) == (
        ["line[left_to_right](B,A,T)"], "tweak")


@pytest.mark.parametrize("edit", ["Gain staging: swap the bottom colour and the top colour.",
                                  "Swap the colours of the bottom and top layers."])
def test_forty_fourth_session_a_pyramids_bottom_and_top_swapped(tmp_path, edit):
    """steer_stranger27 r029: "swap the bottom colour and the top colour" of a pyramid with one colour per layer had been
    refused ('the bottom' read as one cube of a layer of three); said as colours or layers, they are its layers. "Swap the
    bottom cube and the top cube" names one cube of a layer of three, and stays refused (a helper's attack: it had swapped
    the layers)."""
    base = "Build a pyramid of six cubes: three red on the bottom row, two orange in the middle row, one yellow on top."
    assert _meaning_after(tmp_path, base, [edit]) == (["pyramid(yellow,yellow,yellow|orange,orange|red)"], "modify")
    fam = compiled(base, tmp_path / "cube", name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "swap the bottom cube and the top cube")


@pytest.mark.parametrize("base,edit,expected", [
    ("Build a pyramid of three cubes: two black on the bottom and one yellow on top.",
     "Make it a tunnel mouth: add a bottom row of three gray cubes under it.", ["pyramid(gray,gray,gray|black,black|yellow)"]),
    ("Build a pyramid of six red cubes.", "Add a layer of gray cubes at the bottom.", ["pyramid(gray,gray,gray,gray|red,red,red|red,red|red)"]),
    ("Build a wall two layers high, three blue cubes on the bottom layer and three green cubes on top.",
     "Add a layer of red cubes at the bottom.", ["wall(red,red,red|blue,blue,blue|green,green,green)"]),
    # (a forty-first session attack, refused then: the row had gone on top)
    ("Build a wall two rows high: three red cubes in the bottom row and three blue cubes in the top row.",
     "add a row of green cubes underneath", ["wall(green,green,green|red,red,red|blue,blue,blue)"]),
])
def test_forty_fourth_session_a_layer_added_at_the_bottom(tmp_path, base, edit, expected):
    """steer_stranger27 r059: "add a bottom row of three gray cubes under it" of a pyramid had been refused (rows were added on
    top only); a pyramid's base grows by one under its layers, a wall gains a layer under its others."""
    assert _meaning_after(tmp_path, base, [edit]) == (expected, "extend")


def test_forty_fourth_session_a_bottom_layer_that_does_not_fit_is_refused(tmp_path):
    fam = compiled("Build a pyramid of three cubes: two black on the bottom and one yellow on top.", tmp_path, name="fam").path
    with pytest.raises(BadInput, match="does not fit"):
        steer(fam, "Add a layer of four gray cubes at the bottom.")


@pytest.mark.parametrize("edit", ["Stack those six cubes into one tower.", "Scrap the pyramid and stack the cubes into a tower.",
                                  "Stack them into a tower."])
def test_forty_fourth_session_a_pyramid_with_coloured_layers_stacked(tmp_path, edit):
    """steer_stranger27 r005: "stack those six cubes into one tower" had been read as a second structure added, and a pyramid
    whose layers' colours are judged could not be made a tower (its layers were kept); the tower holds its cubes in any order."""
    fam = compiled("Build a pyramid: three brown cubes on the bottom, two gray cubes on them, one white cube on top.", tmp_path,
                   name="fam").path
    r = steer(fam, edit)
    assert r.intent == "pivot"
    goal = Family(fam).schema(r.version).goal_predicate()
    assert type(goal).__name__ == "UnorderedStack" and sorted(o.split("_")[0] for o in goal.objects) == [
        "brown", "brown", "brown", "gray", "gray", "white"]


def test_forty_fourth_session_it_stood_on_a_patch_is_the_structure(tmp_path):
    """steer_stranger27 r028: "stand it on the blue patch" of a tower had been refused ('it' named no cube); of a structure
    task, 'it' is the structure, as "put the tower on a blue patch" reads."""
    assert _meaning_after(tmp_path, "Stack white, gray, black from the bottom up.", ["Stand it on the blue patch."]) == (
        ["on_patch(white,patch:blue)", "stack(white,gray,black)"], "extend")


def test_forty_fourth_session_a_swap_announced_then_said_in_full(tmp_path):
    """steer_stranger27 r009: "Swap them over like switching kegs: white on the green patch, black on the red patch." had been
    refused (the announcement named no change read); the statement after the colon is the edit, a Modify of the same cubes."""
    assert _meaning_after(tmp_path, "Place the white cube on the red patch and the black cube on the green patch.",
                          ["Swap them over like switching kegs: white on the green patch, black on the red patch."]) == (
        ["on_patch(black,patch:red)", "on_patch(white,patch:green)"], "modify")


@pytest.mark.parametrize("base,edit,expected", [
    ("Put a pink cube on top of a white cube.", "Add a second pair: a green cube on a brown cube.",
     ["stack(brown,green)", "stack(white,pink)"]),
    ("Put a pink cube on top of a white cube.", "Also stack a green cube on a brown cube.", ["stack(brown,green)", "stack(white,pink)"]),
    # (refused until the forty-fourth session; both cubes had once gone on top of the tower)
    ("Stack a blue cube on an orange cube", "add a green cube on a pink cube", ["stack(orange,blue)", "stack(pink,green)"]),
])
def test_forty_fourth_session_a_second_stack_added_beside_the_task(tmp_path, base, edit, expected):
    """steer_stranger27 r033: a second two-cube stack added to a task had been refused as a structure steering cannot compose;
    the task's instruction with the clause after it reads both, checked to keep the task and add to it."""
    assert _meaning_after(tmp_path, base, [edit]) == (expected, "extend")


def test_forty_fourth_session_a_second_structure_that_does_not_compose_is_refused(tmp_path):
    fam = compiled("Put a pink cube on top of a white cube.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Add a pyramid of three yellow cubes.")


def test_forty_fourth_session_a_cube_added_after_a_named_end(tmp_path):
    """steer_stranger27 r011: "Set an S after the T, at the right end." had added an S and a second T (silently wrong); the T
    named is the row's own end cube, and a cube 'after' one inside the row is refused."""
    assert _meaning_after(tmp_path, "Put the letter cubes B, A and T in a row from left to right.",
                          ["Set an S after the T, at the right end."]) == (["line[left_to_right](B,A,T,S)"], "extend")
    fam = compiled("Put the letter cubes B, A and T in a row from left to right.", tmp_path / "inside", name="fam").path
    with pytest.raises(BadInput, match="ends only"):
        steer(fam, "Add an S after the A.")


@pytest.mark.parametrize("edit", ["Time permitting: add a blue cube on top.", "Optional: add a blue cube on top."])
def test_forty_fourth_session_an_edit_label_that_conditions_is_not_dropped(tmp_path, edit):
    """"Time permitting: add a blue cube on top." had been applied as if the label were unsaid (the label list that refuses a
    task's conditioning labels was not consulted for an edit's)."""
    fam = compiled("Stack the yellow cube on the green cube.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, edit)


@pytest.mark.parametrize("edit", ["Interleave the samples: purple, yellow, purple, yellow, left to right.",
                                  "Purple, yellow, purple, yellow, from left to right."])
def test_forty_fourth_session_a_new_order_listed_before_its_direction(tmp_path, edit):
    """steer_stranger26 t034: the task's cubes listed in a new order with the direction after the list (and a label before
    it) had been read as no task."""
    assert _meaning_after(tmp_path, "A row of four cubes, purple, purple, yellow, yellow, from left to right.", [edit]) == (
        ["line[left_to_right](purple,yellow,purple,yellow)"], "modify")


def test_forty_fourth_session_a_swap_then_said_after_a_comma_and_a_label(tmp_path):
    """steer_stranger26 t023: "Seating chart changed: swap them, yellow on the red patch and blue on the green patch." had been
    refused; a label that conditions the edit still refuses it."""
    base = "Put the blue cube on the red patch and the yellow cube on the green patch."
    assert _meaning_after(tmp_path, base, ["Seating chart changed: swap them, yellow on the red patch and blue on the green "
                                           "patch."]) == (["on_patch(blue,patch:green)", "on_patch(yellow,patch:red)"], "modify")
    fam = compiled(base, tmp_path / "cond", name="fam").path
    with pytest.raises(BadInput, match="Time permitting"):
        steer(fam, "Time permitting: swap them, yellow on the red patch and blue on the green patch.")


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger27 r043: a voice's chunk after the change, and "two more" cubes of a colour on the task's one patch
    ("Place the yellow cube on the blue patch.", "Add two more yellow cubes to the blue patch, a school of guppies.",
     ["on_patch(yellow,yellow,yellow,patch:blue)"]),
    # r041: a cube put on a cube in a place of the table: the tower stands there
    ("Put the brown cube in the back right corner of the table.", "Hardscape tweak: stack a green cube on it, like moss on driftwood.",
     ["stack(brown,green)@back_right"]),
    # r029: "one more layer" of a pyramid, its cubes said after a comma
    ("Build a pyramid of three cubes: two black on the bottom and one yellow on top.", "Add one more layer underneath, three green cubes.",
     ["pyramid(green,green,green|black,black|yellow)"]),
])
def test_forty_fourth_session_additions_said_in_a_voice(tmp_path, base, edit, expected):
    assert _meaning_after(tmp_path, base, [edit]) == (expected, "extend")


def test_forty_fourth_session_two_more_cubes_one_at_each_end(tmp_path):
    """steer_stranger27 r058: "Lengthen the row with two more orange cubes, one at each end." had been refused ('lengthen',
    then two cubes at two places)."""
    assert _meaning_after(tmp_path, "A row of two orange cubes and one white cube, order doesn't matter.", [
        "Put the white one in the middle.", "Lengthen the row with two more orange cubes, one at each end."]) == (
        ["line[sequence](orange,orange,white,orange,orange)"], "extend")


def test_forty_fourth_session_a_matching_tower_in_another_place(tmp_path):
    """steer_stranger27 r037: "Build a matching tower on the right side, same colours in the same order." had been read as no
    change; the tower is copied there, checked to read back as the tower and its copy (else refused)."""
    assert _meaning_after(tmp_path, "Stack three cubes: blue on the bottom, then yellow, then red.", [
        "Put it on the left side of the table.", "Build a matching tower on the right side, same colours in the same order."]) == (
        ["stack(blue,yellow,red)@left", "stack(blue,yellow,red)@right"], "extend")
    fam = compiled("Stack the red cube on the blue cube in the back left corner.", tmp_path / "same", name="fam").path
    with pytest.raises(BadInput, match="another place"):
        steer(fam, "Build an identical tower in the back left corner.")


def test_forty_fourth_session_an_edits_label_is_not_dropped_as_a_voices(tmp_path):
    """A steering edit's label is its own readers' (the voice chunks dropped from an edit are its closing ones): "Different
    house, different job:" says a fresh start (it had been read as a pivot), "Add a clue:" an addition (the patch's cube had
    been lost, silently)."""
    r = steer(compiled("Put the cyan cube behind the white cube.", tmp_path, name="fam").path,
              "Different house, different job: spell HOME with letter cubes from left to right.")
    assert r.intent == "fresh"
    fam = compiled("Put the black cube on the white patch.", tmp_path / "clue", name="fam").path
    try:
        r = steer(fam, "Add a clue: a red cube to the left of the white patch.")
    except BadInput:
        return
    from rpg.schema.meaning import meaning

    assert "on_patch(black,patch:white)" in meaning(Family(fam).schema(r.version))


@pytest.mark.parametrize("base,edit", [
    # a hostile helper's probes of this session's steering (each had compiled silently wrong)
    ("Stack red, blue, blue and green from the bottom.", "take three blues off"),  # more than there are
    ("Put the red cube on the blue patch and the pink cube on the yellow patch.", "Move the red one onto a new yellow patch"),
    ("Put the letter cubes C, A and T in a row from left to right.", "swap the A for the C"),  # two C cubes
    ("Build a pyramid of six cubes: three red on the bottom, two blue in the middle, one green on top.",
     "swap the bottom cube and the top cube"),  # one cube of a layer of three
    ("Build a wall two rows high: three red cubes in the bottom row and three blue cubes in the top row.",
     "add a row of gray cubes above the bottom row"),  # between the rows, not under them
    ("Build a pyramid of six cubes: three red on the bottom, two blue in the middle, one green on top.",
     "stack those three cubes into one tower"),  # three of six
    ("Build a pyramid of six cubes: three red on the bottom, two blue in the middle, one green on top.",
     "stack them into a tower, red at the bottom"),  # the role had been dropped
    ("Stack red, blue, blue and green from the bottom.", "Swap them over: green at the bottom and red on top."),  # cubes lost
    ("Put the letter cubes C, A and T in a row from left to right.", "add an S after the T, at the left end"),
    ("Put the letter cubes C, A and T in a row from left to right.", "add an S after the T and a B before the C"),
    ("Make a row of a red, a white and a blue cube.", "add a yellow cube after the blue one"),  # a row in no order
    ("Put red, white, blue and green in a row from left to right.", "Wrong order: green, blue, white, red, left to right"),
    ("Put red, white, blue and green in a row from left to right.", "Optionally: add a yellow cube at the right end"),
])
def test_forty_fourth_session_hostile_probes_are_refused(tmp_path, base, edit):
    fam = compiled(base, tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, edit)


@pytest.mark.parametrize("edit", ["swap the C for a B and the A for an O", "swap the C for a B, keeping the order"])
def test_forty_fourth_session_two_letters_replaced_in_a_named_row(tmp_path, edit):
    """Two replacements in one edit had been read as the C and the A exchanged; 'keeping the order' as a reversal."""
    got, _ = _meaning_after(tmp_path, "Put the letter cubes C, A and T in a row from left to right.", [edit])
    assert got == (["line[left_to_right](B,O,T)"] if "O" in edit else ["line[left_to_right](B,A,T)"])


def test_forty_fourth_session_a_pyramid_or_wall_is_not_stood_on_a_patch(tmp_path):
    """'put it on the blue patch' of a pyramid had crashed (a helper's probe); it is refused."""
    fam = compiled("Build a pyramid of six cubes: three red on the bottom, two blue in the middle, one green on top.", tmp_path,
                   name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "put it on the blue patch")


def test_forty_fourth_session_both_ends_of_a_new_tower_said(tmp_path):
    """"Convert the line to a tower, green at the bottom and blue at the top." had made a tower in any order (its roles
    dropped, the meaning notation hiding it); both ends of three cubes leave one order. One end of six stays refused."""
    fam = compiled("Arrange the blocks in order green, cyan, blue from left to right.", tmp_path, name="fam").path
    r = steer(fam, "Convert the line to a tower, green at the bottom and blue at the top.")
    goal = Family(fam).schema(r.version).goal_predicate()
    assert type(goal).__name__ == "Stack" and list(goal.objects) == ["green", "cyan", "blue"]


@pytest.mark.parametrize("edit,expected", [
    ("Put cube 6 on top.", (["stack(9,8,7,6)"], "extend")),
    ("Remove cube 8.", (["stack(9,7)"], "tweak")),
])
def test_forty_fifth_session_a_digit_cube_named_after_its_noun(tmp_path, edit, expected):
    """steer_stranger28 q035: "Put cube 6 on top" of a tower 9, 8, 7 had added six digit cubes, 1 to 6, silently ("cube 6"
    read as a count); a digit after "cube" names the cube."""
    assert _meaning_after(tmp_path, "Cube 7 on cube 8 on cube 9: a little three-tile stack with 9 at the bottom.", [edit]) == expected


def test_forty_fifth_session_a_row_with_an_end_said_keeps_its_end_when_a_cube_is_recoloured(tmp_path):
    """An AnchoredLine (a row free but for its left end) edited in place keeps its end; edits the builtin steering does not
    read for it are refused, never applied to a line in some order."""
    assert _meaning_after(tmp_path, "Make a row of red, green and blue with red at the left end.",
                          ["Swap the red cube for a white one."]) == (["line[left_end](white,blue,green)"], "tweak")
    fam = compiled("Make a row of red, green and blue with red at the left end.", tmp_path / "b", name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Move the row to the back of the table.")


@pytest.mark.parametrize("edit,expected", [
    # steer_stranger28 q038: a tower standing on a patch moved to another (read as an addition it had made a second tower,
    # then been refused); "change the patch to ..." (read as an action)
    ("Move the stack to the yellow patch.", (["on_patch(brown,patch:yellow)", "stack(brown,green)"], "modify")),
    ("Move it to the yellow patch.", (["on_patch(brown,patch:yellow)", "stack(brown,green)"], "modify")),
    ("Change the patch to the yellow patch.", (["on_patch(brown,patch:yellow)", "stack(brown,green)"], "tweak")),
])
def test_forty_fifth_session_a_tower_on_a_patch_moved_to_another(tmp_path, edit, expected):
    assert _meaning_after(tmp_path, "Put the green cube on top of the brown cube, and stand that stack on the cyan patch.",
                          [edit]) == expected


def test_forty_fifth_session_discard_removes_a_cube(tmp_path):
    """steer_stranger28 q016: "Discard the white one" had been read as an action the domain lacks."""
    assert _meaning_after(tmp_path, "Put the red cube on the green patch and the white cube on the red patch.",
                          ["Discard the white one, out of the game entirely."]) == (["on_patch(red,patch:green)"], "tweak")


@pytest.mark.parametrize("edit,expected", [
    ("Throw a third purple into the heap.", ["pile(gray,purple,purple,purple)"]),
    ("Add a red cube to the pile.", ["pile(gray,purple,purple,red)"]),
    ("Remove the gray cube.", ["pile(purple,purple)"]),
])
def test_forty_fifth_session_one_pile_of_several_colours_stays_one_pile(tmp_path, edit, expected):
    """A pile of a gray and two purple cubes had been steered as piles sorted by colour with an outlier each: "add a purple
    cube to the pile" made two piles, each of a gray and a purple cube, silently."""
    assert _meaning_after(tmp_path, "Heap the gray cube and two purple cubes into one pile.", [edit])[0] == expected


def test_forty_fifth_session_one_pile_in_a_region_is_edited_in_place(tmp_path):
    """steer_stranger28 q034: a pile standing at the back was no structure the builtin steering edits (its cubes had not
    been counted as the pile's); a third purple cube thrown in keeps the pile and its place."""
    assert _meaning_after(tmp_path, "Heap the gray cube and two purple cubes into one pile at the back of the table.",
                          ["Throw a third purple into the heap."]) == (["pile(gray,purple,purple,purple)@back"], "extend")


@pytest.mark.parametrize("edit,expected", [
    # steer_stranger28 q043: a new cube put beside the task's one cube had been read as a new task, or as a move of the cube
    # ('land' is 'move'), and the cyan cube's place in the middle lost, silently: an addition
    ("Land the green cube right next to the cyan.", (["in_region(cyan,center)", "next_to(cyan,green)"], "extend")),
    ("Put the green cube next to the cyan.", (["in_region(cyan,center)", "next_to(cyan,green)"], "extend")),
    ("Put the green cube next to the cyan and the red cube on the green.",
     (["in_region(cyan,center)", "next_to(cyan,green)", "stack(green,red)"], "extend")),
    # replacing words still replace, and a move of the task's own cube moves it
    ("Put the green cube next to the cyan instead.", (["next_to(cyan,green)"], "pivot")),
    ("Move the cyan cube to the back.", (["in_region(cyan,back)"], "modify")),
])
def test_forty_fifth_session_a_new_cube_related_to_the_task_is_an_addition(tmp_path, edit, expected):
    assert _meaning_after(tmp_path, "Set the cyan cube down in the middle of the table, my laydown area.", [edit]) == expected


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger28 q058, q047: label cubes related to each other were no structure the builtin steering edits in place
    ("Close-up: cube K in front of cube J.", "Wrong letter, swap the K out for an L.", (["in_front_of(L,J)"], "tweak")),
    ("Close-up: cube K in front of cube J.", "Swap K and J.", (["in_front_of(J,K)"], "modify")),
    ("Put the E between the A and the R.", "Swap E and R.", (["between(R;A,E)"], "modify")),
    ("Put the E between the A and the R.", "Swap the A for a B.", (["between(E;B,R)"], "tweak")),
])
def test_forty_fifth_session_labels_of_related_cubes_exchanged(tmp_path, base, edit, expected):
    assert _meaning_after(tmp_path, base, [edit]) == expected


def test_forty_fifth_session_a_new_label_the_task_has_is_not_exchanged(tmp_path):
    """"Swap the K for a J" of K in front of J would make two J cubes: refused, never two cubes merged."""
    fam = compiled("Close-up: cube K in front of cube J.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Swap the K for a J.")


@pytest.mark.parametrize("base,edit", [
    # a hostile helper's probes (forty-fifth session), each applied silently wrong before its mend
    ("Put the K cube to the left of the E cube and the R cube behind the E cube.", "Swap the K for an L cube on the red patch."),
    ("Put the K cube to the left of the E cube and the R cube behind the E cube.", "Swap E and R, then put K on the red patch."),
    ("Put the K cube to the left of the E cube and the R cube behind the E cube.", "Swap the K for 2 L cubes."),
    ("Heap the gray cube and a red cube into one pile.", "Throw a third red into the heap."),
    ("Build a tower from bottom to top: red, green, blue.", "Put a white cube on the table."),
    ("Stack cube 3, cube 2 and cube 1 from bottom to top.", "Put cube 3 on top."),
])
def test_forty_fifth_session_hostile_edits_refused(tmp_path, base, edit):
    fam = compiled(base, tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, edit)


def test_forty_fifth_session_a_cube_far_from_the_tower_is_no_cube_on_top(tmp_path):
    """"Put a white cube far from the tower" had stacked it on the tower's top, silently."""
    assert _meaning_after(tmp_path, "Build a tower from bottom to top: red, green, blue.", ["Put a white cube far from the tower."])[0] == [
        "far_from(red,white)", "stack(red,green,blue)"]


def test_forty_sixth_session_that_little_tower_is_the_tasks_own(tmp_path):
    """steer_stranger29 p046: "Move that little tower to the back right corner" had been read as a fresh task, a tower of a
    red and a blue cube nobody named (silently wrong); a structure an edit points at is the task's."""
    assert _meaning_after(tmp_path, "Stack the yellow cube on the red cube in the front left corner.",
                          ["Move that little tower to the back right corner."]) == (["stack(red,yellow)@back_right"], "modify")


@pytest.mark.parametrize("edit,expected", [
    # steer_stranger29 p007: "the digit cube 7" had been normalised "the digit digit 7 cube", the material op (digits, the
    # task's own) read as a change: Modify
    ("Add the digit cube 7 on top.", (["stack(1,8,0,7)"], "extend")),
])
def test_forty_sixth_session_a_label_cube_named_after_its_noun_is_added(tmp_path, edit, expected):
    assert _meaning_after(tmp_path, "Stack the digit cubes 1, 8 and 0, 1 at the bottom, then 8, and 0 at the top.",
                          [edit]) == expected


def test_forty_sixth_session_a_letter_cube_named_after_its_noun_is_added(tmp_path):
    assert _meaning_after(tmp_path, "Put the letter cubes A, K and Q in a row from left to right.",
                          ["Add the letter cube T at the right end."]) == (["line[left_to_right](A,K,Q,T)"], "extend")


@pytest.mark.parametrize("edit", ["Take the two cubes off the ends of the row.", "Remove the two cubes at the ends of the row."])
def test_forty_sixth_session_the_cubes_at_both_ends_removed(tmp_path, edit):
    """steer_stranger29 p040: "take ... off the ends" had been refused as an action, "remove the two cubes at the ends" as a
    part of the structure."""
    assert _meaning_after(tmp_path, "Put the purple, blue, green, yellow, orange and red cubes in a row from left to right.",
                          [edit]) == (["line[left_to_right](blue,green,yellow,orange)"], "tweak")


@pytest.mark.parametrize("edit,expected", [
    # steer_stranger29 p015: "the pile goes to the centre instead" had been read as one more placement of a cube, refused
    ("The pile goes to the centre of the table instead.", (["pile(purple,purple,purple,purple,purple)@center"], "modify")),
    ("Now the pile goes in the front left corner.", (["pile(purple,purple,purple,purple,purple)@front_left"], "modify")),
])
def test_forty_sixth_session_the_structure_goes_somewhere_else(tmp_path, edit, expected):
    assert _meaning_after(tmp_path, "Pile five purple cubes in the back right corner.", [edit]) == expected


@pytest.mark.parametrize("edit,expected", [
    # steer_stranger29 p039: the task's structure named before the new one ("turn the pyramid into a tower of the same four
    # cubes, white on top"): the roles had had no place (refused)
    ("Turn the pyramid into a tower of the same four cubes, white on top.", (["stack(green,green,green,white)"], "pivot")),
])
def test_forty_sixth_session_a_structure_turned_into_another_with_a_role(tmp_path, edit, expected):
    assert _meaning_after(tmp_path, "Build a pyramid with three green cubes on the bottom and a white cube on top.", [edit]) == expected


def test_forty_sixth_session_a_role_of_a_pivot_leaves_the_rest_free(tmp_path):
    fam = compiled("Build a pyramid of the red, green and blue cubes.", tmp_path, name="fam").path
    r = steer(fam, "Turn the pyramid into a tower of the same three cubes, red on top.")
    goal = Family(fam).schema(r.version).goal_predicate()
    assert type(goal).__name__ == "AnchoredStack" and goal.top and not goal.bottom


def test_forty_sixth_session_the_other_side_said_by_a_between(tmp_path):
    """steer_stranger29 p026: "on the other side of the pink one, so the pink cube is between the cyan and the yellow": the
    between places the new cube ('the other side' alone stays refused)."""
    assert _meaning_after(tmp_path, "Place the cyan cube next to the pink cube.",
                          ["Add a yellow cube on the other side of the pink one, so the pink cube is between the cyan and the "
                           "yellow."]) == (["between(pink;cyan,yellow)", "next_to(cyan,pink)"], "extend")
    fam = compiled("Place the cyan cube next to the pink cube.", tmp_path / "b", name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Add a yellow cube on the other side of the pink one.")


@pytest.mark.parametrize("base,edit,expected", [
    # steer_stranger29: "lay", "refactor", "redraw" name a new structure of the task's cubes (each had been refused: no
    # change read, or an action); "the same three letters": the task's own count, said again
    ("Stack the letter cubes B, I and D from bottom to top.", "Rebid: lay the same three letters in a row, left to right, spelling BID.",
     "line[left_to_right](B,I,D)"),
    ("Build a pyramid with three gray cubes on the bottom and a black cube on top.", "Refactor it into a row of the same four cubes.",
     "line(black,gray,gray,gray)"),
    ("Put the letter cubes P, A and M in a row from left to right.", "Redraw it as a tower: P at the bottom, then A, then M on top.",
     "stack(P,A,M)"),
])
def test_forty_sixth_session_other_verbs_of_a_new_structure(tmp_path, base, edit, expected):
    atoms, intent = _meaning_after(tmp_path, base, [edit])
    assert expected in atoms and intent == "pivot"


def test_forty_sixth_session_the_same_count_that_is_not_the_tasks_refused(tmp_path):
    fam = compiled("Stack the letter cubes B, I and D from bottom to top.", tmp_path, name="fam").path
    with pytest.raises(BadInput):
        steer(fam, "Lay the same four letters in a row, left to right, spelling BID.")


def test_forty_seventh_session_a_sort_said_by_the_numbers_way_along_the_row(tmp_path):
    # steer_stranger29 (read material): "Sort them so the numbers go up from left to right." had changed nothing; the way
    # must be said with it ("make the numbers go up" alone stays refused: up along which way?)
    assert _steered(tmp_path / "a", "Put the digit cubes 7, 5 and 3 in a row, left to right.",
                    "Sort them so the numbers go up from left to right.") == [("modify", ["line[left_to_right](3,5,7)"])]
    fam = Family(create_family(compiled("Put the digit cubes 7, 5 and 3 in a row, left to right.", tmp_path / "b",
                                        name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, "Make the numbers go up.")


def test_forty_eighth_session_a_swap_with_the_other_cube_exchanges_them(tmp_path):
    # steer_stranger30 (read material): "swap the red cube at the bottom with the yellow cube at the top" had recoloured red
    # yellow (two yellow cubes, red lost, silently); "swap ... with the ..." exchanges, "swap ... with a ..." replaces
    base = "Stack a red cube, then blue, then green, then yellow on top, bottom to top."
    assert _steered(tmp_path / "a", base, "swap the red cube at the bottom with the yellow cube at the top.") == [
        ("modify", ["stack(yellow,blue,green,red)"])]
    assert _steered(tmp_path / "b", base, "swap the red cube with a white one.") == [("tweak", ["stack(white,blue,green,yellow)"])]


def test_forty_eighth_session_a_patch_colour_in_an_edit_recolours_no_cube(tmp_path):
    # steer_stranger30: "make it four green cubes on the white patch" had made the cubes white (and lost two): the colour is
    # the patch's; the edit is refused now, not read as a recolouring
    fam = Family(create_family(compiled("Put two green cubes on the white patch.", tmp_path / "a", name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, "make it four green cubes on the white patch.")


def test_forty_eighth_session_swaps_and_recolourings_a_hostile_helper_tried(tmp_path):
    # "swap X with the one in the middle of the table" had exchanged X with the tower's middle; "make the cubes on the white
    # patch green" had recoloured the patch; "swap X with the new green cube" stays a replacement
    base = "Stack a yellow cube, then blue, then red on top, bottom to top."
    fam = Family(create_family(compiled(base, tmp_path / "a", name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, "swap the red cube with the one in the middle of the table")
    assert _steered(tmp_path / "b", base, "swap the red cube with the new green cube") == [("tweak", ["stack(yellow,blue,green)"])]
    fam = Family(create_family(compiled("Put three red cubes on the white patch.", tmp_path / "c", name="fam").path).path)
    with pytest.raises(SteerError):
        steer(fam.path, "make the cubes on the white patch green")


def _tree(path: Path) -> dict:
    """Every file under ``path`` and its bytes, but the (empty) lock files a reader takes."""
    return {str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*")) if p.is_file() and not p.name.endswith(".lock")}


@pytest.mark.parametrize("base, edits", [
    ("Stack the red cube on the blue cube.", ["add a green cube on top", "make the top cube yellow"]),
    ("Put the red block next to the blue block and the green block behind the blue block", ["get rid of the green block"]),
    ("Build a tower of red, blue and green.", ["now put it on the left side", "swap the red and green cubes"]),
])
def test_a_dry_run_reads_each_edit_as_steer_does_and_writes_nothing(tmp_path, base, edits):
    """``steer(..., dry_run=True)`` (``rpg steer --dry-run``) gives the intent, reference and task that steering records,
    and leaves the family, or the task that is not yet one, byte for byte as it was."""
    from rpg.schema.meaning import meaning

    task = compiled(base, tmp_path, name="fam").path
    before = _tree(tmp_path)
    first = steer(task, edits[0], dry_run=True)
    assert first.version is None and not first.valid and _tree(tmp_path) == before and not is_family(task)
    fam = Family(create_family(task).path)
    for e in edits:
        before = _tree(tmp_path)
        dry = steer(fam.path, e, dry_run=True)
        assert _tree(tmp_path) == before
        r = steer(fam.path, e)
        assert r.valid and (dry.intent, dry.reference, dry.instruction) == (r.intent, r.reference, r.instruction)
        assert meaning(dry.schema) == meaning(fam.schema(r.version))


def test_cli_steer_dry_run_prints_the_version_it_would_record(tmp_path):
    task = compiled("Stack the red cube on the blue cube.", tmp_path, name="fam").path
    before = _tree(tmp_path)
    r = rpg("steer", str(task), "add a green cube on top", "--dry-run", "--json")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert doc["intent"] == "extend" and doc["version"] is None and doc["meaning"] == ["stack(blue,red,green)"]
    assert _tree(tmp_path) == before
    bad = rpg("steer", str(task), "turn it into a spaceship", "--dry-run")
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and _tree(tmp_path) == before


@pytest.mark.parametrize("edit", [
    # a move said with two placements: the region replaces the cube's old one and the relation joins (it had been read as an
    # addition: the cube in two corners, refused as a contradiction)
    "Move the cyan cube to the front left corner, next to the brown one.",
    # "as well" there is the other cube's corner: the cube cannot keep its old one too
    "Move the cyan cube to the front left corner as well, right next to the brown one.",
])
def test_fifty_first_session_a_move_to_a_place_and_beside_a_cube_replaces_its_old_place(tmp_path, edit):
    base = "Place the cyan cube in the back right corner and the brown cube in the front left corner."
    assert _meaning_after(tmp_path, base, [edit]) == (
        ["in_region(brown,front_left)", "in_region(cyan,front_left)", "next_to(brown,cyan)"], "modify")

