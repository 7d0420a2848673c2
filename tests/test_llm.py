"""The litellm front end, with litellm's mocked responses only: no test touches a network."""

import json
import os
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from rpg import cli
from rpg.compiler import compile_instruction, load_artifact
from rpg.schema.builtin import parse
from rpg.schema.llm import (
    LLMClient,
    ModelOutputError,
    ProviderError,
    ReplayError,
    llm_parse,
    load_record,
)

MODEL = "openai/gpt-4o-mini"
ROOT_LIBRARY = __import__("pathlib").Path(__file__).resolve().parents[1] / "library"


def schema_json(instruction: str) -> str:
    """A correct answer, as a model would write it."""
    return parse(instruction).model_dump_json(indent=1)


def test_model_answer_becomes_a_valid_artifact_with_its_record(tmp_path):
    text = "Put the green cube on top of the yellow cube"
    client = LLMClient(MODEL, mock_responses=[schema_json(text)])
    result = compile_instruction("Balance the verdant block upon the golden one", tmp_path, llm=client)
    assert result.valid, result.log
    _, doc = load_artifact(result.path)
    assert doc["provenance"]["backend"] == "litellm" and doc["provenance"]["model"] == MODEL
    assert doc["schema"]["instruction"] == "Balance the verdant block upon the golden one"
    header, exchanges = load_record(result.path)
    assert header["instruction"] == "Balance the verdant block upon the golden one"
    assert len(exchanges) == 1 and exchanges[0]["request"]["messages"][1]["content"] == header["instruction"]
    assert "TaskSchema" in exchanges[0]["request"]["messages"][0]["content"]


def test_validation_errors_are_fed_back_then_retried(tmp_path):
    good = schema_json("Stack the red block on top of the blue block")
    bad = json.loads(good)
    del bad["goal_layout"]
    client = LLMClient(MODEL, mock_responses=["I think you want a tower.", json.dumps(bad), good])
    schema = llm_parse("Stack the red block on top of the blue block", client)
    assert schema.goal_predicate().describe().startswith("stack")
    assert len(client.records) == 3
    feedback = client.records[2]["request"]["messages"][-1]["content"]
    assert "goal_layout" in feedback and "not a valid answer" in feedback
    with pytest.raises(ModelOutputError, match="4 tries"):
        llm_parse("x", LLMClient(MODEL, mock_responses=["{}"] * 4))


def test_provider_errors_are_provider_errors():
    with pytest.raises(ProviderError, match="RateLimit"):
        llm_parse("Stack two blocks", LLMClient(MODEL, mock_responses=["litellm.RateLimitError"]))


def test_replay_recompiles_offline_to_the_same_artifact(tmp_path):
    client = LLMClient(MODEL, mock_responses=[schema_json("Align 4 cubic blocks in a single straight horizontal line.")])
    first = compile_instruction("line up four blocks please", tmp_path / "a", llm=client)
    again = compile_instruction("", tmp_path / "b", replay=first.path)
    assert again.valid and again.content_hash == first.content_hash
    tampered = tmp_path / "rec.jsonl"
    lines = (first.path / "llm_log.jsonl").read_text().splitlines()
    tampered.write_text(lines[0].replace("line up", "stack up") + "\n" + lines[1] + "\n")
    with pytest.raises(ReplayError, match="does not match"):
        compile_instruction("", tmp_path / "c", replay=tampered)


def test_cli_model_exit_codes_and_replay(tmp_path, monkeypatch):
    runner = CliRunner()
    answers = {"ok": [schema_json("Place the red block behind the yellow block")],
               "down": ["litellm.InternalServerError"], "junk": ["no json"] * 4}
    for case, responses in answers.items():
        monkeypatch.setattr(cli, "make_llm_client", lambda model, r=responses: LLMClient(model, mock_responses=list(r)))
        res = runner.invoke(cli.app, ["compile", "put red behind yellow", "--model", MODEL, "-o", str(tmp_path / case), "--json"])
        if case == "ok":
            assert res.exit_code == 0, res.output
            path = json.loads(res.stdout)["path"]
        elif case == "down":
            assert res.exit_code == 3 and "provider" in res.output
            assert not (tmp_path / case).exists() or not any((tmp_path / case).iterdir())
        else:
            assert res.exit_code == 1 and "no valid schema answer" in res.output
    env = {**os.environ, "OPENAI_API_KEY": ""}
    proc = subprocess.run([sys.executable, "-m", "rpg.cli", "compile", "", "--replay", path, "-o", str(tmp_path / "r"), "--json"],
                          capture_output=True, text=True, env=env)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["content_hash"] == load_artifact(path)[1]["content_hash"]


def test_builtin_first_asks_the_model_only_for_what_the_parser_cannot_read(tmp_path):
    client = LLMClient(MODEL, mock_responses=[])
    r = compile_instruction("Stack the green block on top of the blue block", tmp_path, llm=client, builtin_first=True)
    assert r.valid and not client.records and not (r.path / "llm_log.jsonl").exists()
    client = LLMClient(MODEL, mock_responses=[schema_json("Stack the green block on top of the blue block")])
    r = compile_instruction("Perch the verdant cube atop its azure sibling", tmp_path / "m", llm=client, builtin_first=True)
    assert r.valid and len(client.records) == 1


def test_litellm_is_not_imported_by_a_builtin_compile(tmp_path):
    code = ("import sys; from rpg.compiler import compile_instruction; "
            f"compile_instruction('Stack two blocks on top of each other.', {str(tmp_path)!r}); "
            "print('litellm' in sys.modules)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.stdout.strip() == "False", proc.stderr


def test_model_steering_is_recorded_and_replays(tmp_path):
    from rpg.steer import Family, create_family, steer

    base = compile_instruction("Place a blue cube on top of a red cube on the table", tmp_path, name="fam")
    fam = create_family(base.path)
    route = json.dumps({"intent": "extend", "reference": 0, "parameters": {"add": "green on top"}})
    new = schema_json("Build a tower from bottom to top: red, blue, green")
    client = LLMClient(MODEL, mock_responses=[json.dumps({"intent": "extend", "reference": 7}), route, new])
    r = steer(fam.path, "crown it with something verdant", llm=client)
    assert (r.intent, r.reference, r.version, r.valid) == ("extend", 0, 1, True)
    snap = Family(fam.path).load().get(1)
    assert snap.parameters == {"add": "green on top"} and snap.intent == "extend"
    header, exchanges = load_record(fam.version_dir(1))
    assert header["command"] == "steer" and [e["purpose"] for e in exchanges] == ["route", "route", "schema"]
    assert "reference must be a version id" in exchanges[1]["request"]["messages"][-1]["content"]
    # replay on a copy of the family before the edit reproduces the same version offline
    other = compile_instruction("Place a blue cube on top of a red cube on the table", tmp_path / "o", name="fam")
    fam2 = create_family(other.path)
    again = steer(fam2.path, None, replay=fam.version_dir(1))
    assert again.valid and Family(fam2.path).load().get(1).content_hash == snap.content_hash


def test_cli_steer_with_a_model(tmp_path, monkeypatch):
    from rpg.steer import create_family

    base = compile_instruction("Place a blue cube on top of a red cube on the table", tmp_path, name="fam")
    create_family(base.path)
    runner = CliRunner()
    monkeypatch.setattr(cli, "make_llm_client", lambda model: LLMClient(model, mock_responses=["litellm.RateLimitError"]))
    res = runner.invoke(cli.app, ["steer", str(base.path), "add a green block", "--model", MODEL])
    assert res.exit_code == 3 and "provider" in res.output
    fresh = [json.dumps({"intent": "fresh", "reference": None}), schema_json("Place the red block behind the yellow block")]
    monkeypatch.setattr(cli, "make_llm_client", lambda model: LLMClient(model, mock_responses=fresh))
    res = runner.invoke(cli.app, ["steer", str(base.path), "something else: red behind yellow", "--model", MODEL, "--json"])
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    assert doc["intent"] == "fresh" and doc["reference"] is None and doc["version"] == "v1"


def test_llm_codegen_is_grounded_and_its_failures_go_to_fix_agents(tmp_path):
    from rpg.codegen import generate

    text = "Stack the green block on top of the blue block"
    good = generate(parse(text))
    bad_goal = good.goal_state_code.replace("(0.55, 0.0, 0.97", "(0.55, 0.2, 0.97", 1)  # green no longer on blue
    assert bad_goal != good.goal_state_code
    answers = [schema_json(text),
               json.dumps({"code": "import os\n", "goal_state_code": good.goal_state_code}),  # refused before running
               json.dumps({"code": good.code, "goal_state_code": bad_goal}),
               json.dumps({"code": good.code, "goal_state_code": good.goal_state_code})]
    client = LLMClient(MODEL, mock_responses=answers)
    r = compile_instruction(text, tmp_path, llm=client, codegen="llm", library=ROOT_LIBRARY)
    assert r.valid, r.log
    purposes = [x["purpose"] for x in client.records]
    assert purposes[0] == "schema" and purposes[1:3] == ["codegen", "codegen"] and purposes[3].startswith("repair:")
    first = client.records[1]["request"]["messages"][0]["content"]
    assert "BlockTask.goal" in first and "Common errors" in first and first.count("### Reference task") == 3
    assert "stack" in first.split("### Reference task")[1].split("\n")[0]  # retrieved by tags: a stacking task first
    assert "import of 'os' is not allowed" in client.records[2]["request"]["messages"][-1]["content"]
    fix = client.records[3]["request"]["messages"][-1]["content"]
    assert "SuccessCheckFixAgent" in fix and "attempt 1 failed gate goal_state" in fix
    assert any("repair attempt 1: SuccessCheckFixAgent" in line for line in r.log)
    assert len(load_record(r.path)[1]) == 4
    with pytest.raises(ValueError, match="needs a model"):
        compile_instruction(text, tmp_path / "x", codegen="llm")


def test_a_schema_that_drops_a_named_count_goes_back_to_the_model():
    text = "Stack three blue blocks on top of the red block"
    short = schema_json("Stack the blue block on top of the red block")  # one blue, not three
    client = LLMClient(MODEL, mock_responses=[short, schema_json(text)])
    schema = llm_parse(text, client)
    assert sorted(a.color for a in schema.assets) == ["blue", "blue", "blue", "red"]
    feedback = client.records[1]["request"]["messages"][-1]["content"]
    assert "3 blue" in feedback and "does not match the instruction" in feedback
    dropped = schema_json("Stack the blue block on top of the red block")
    with pytest.raises(ModelOutputError, match="green"):  # a named colour missing from every answer
        llm_parse("Stack the blue block on the red block, then the green block on top",
                  LLMClient(MODEL, mock_responses=[dropped] * 4))
