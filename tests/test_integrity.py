"""Every file of an artifact is hashed: the model record in the content hash, every file in
task.yaml's manifest; ``rpg verify`` names what changed and ``--replay`` refuses a changed
record.  Models are litellm's mocked responses only: no network."""

import json
import os

import pytest
from typer.testing import CliRunner

from rpg import cli, yamlio
from rpg.artifact import MODEL_RECORD, content_hash, rehash
from rpg.compiler import compile_instruction, revalidate
from rpg.schema.builtin import parse
from rpg.schema.llm import LLMClient, ReplayError, load_record
from rpg.steer import Family, create_family
from rpg.steer.family import verify_target

MODEL = "openai/gpt-4o-mini"
TEXT = "Put the green cube on top of the yellow cube"


def _verify(path, *args):
    res = CliRunner().invoke(cli.app, ["verify", str(path), *args])
    return res.exit_code, res.output


def _model_task(tmp_path):
    client = LLMClient(MODEL, mock_responses=[parse(TEXT).model_dump_json()])
    r = compile_instruction("Balance the verdant block upon the golden one", tmp_path / "out", llm=client)
    assert r.valid, r.log
    return r


def _task_doc(path):
    return yamlio.load((path / "task.yaml").read_text())


def test_every_file_is_in_the_manifest_and_the_record_in_the_content_hash(tmp_path):
    r = _model_task(tmp_path)
    doc = _task_doc(r.path)
    assert set(doc["files"]) == set(os.listdir(r.path)) - {"task.yaml"}
    assert {MODEL_RECORD, "code.py", "goal_state_code.py", "validation.log", "validation.json"} <= set(doc["files"])
    assert list(doc)[-2:] == ["files", "content_hash"]
    _, _, sources, digest = rehash(r.path)
    assert digest == doc["content_hash"] == r.content_hash
    # the record is part of the content hash; the manifest is not (snapshots and logs vary)
    without = content_hash(doc, sources["code.py"], sources["goal_state_code.py"])
    assert without != digest
    assert content_hash({k: v for k, v in doc.items() if k != "files"}, sources["code.py"],
                        sources["goal_state_code.py"], (r.path / MODEL_RECORD).read_bytes()) == digest
    assert verify_target(r.path)["ok"] and _verify(r.path)[0] == 0


def test_a_changed_model_record_fails_verify_and_is_not_replayed(tmp_path):
    r = _model_task(tmp_path)
    trusted = r.content_hash
    log = r.path / MODEL_RECORD
    original = log.read_text()
    rows = [json.loads(line) for line in original.splitlines()]
    rows[1]["response"] = rows[1]["response"].replace('"yellow"', '"purple"')  # the attacker's schema
    log.write_text("".join(json.dumps(row, sort_keys=True) + "\n" for row in rows))
    assert log.read_text() != original

    code, output = _verify(r.path)
    assert code == 1 and MODEL_RECORD in output
    assert _verify(r.path, "--expect", trusted)[0] == 1
    with pytest.raises(ReplayError, match=f"{MODEL_RECORD} was changed.*refusing to replay"):
        compile_instruction("", tmp_path / "again", replay=r.path)
    with pytest.raises(ReplayError, match="refusing to replay"):
        load_record(log)  # the file inside the artifact, named directly
    res = CliRunner().invoke(cli.app, ["compile", "", "--replay", str(r.path), "-o", str(tmp_path / "cli")])
    assert res.exit_code == 2 and "refusing to replay" in res.output
    assert not (tmp_path / "again").exists() or not any((tmp_path / "again").iterdir())

    # the attacker also rewrites the manifest: the content hash (which covers the record) still differs
    doc = _task_doc(r.path)
    doc["files"][MODEL_RECORD] = __import__("hashlib").sha256(log.read_bytes()).hexdigest()
    (r.path / "task.yaml").write_text(yamlio.dump(doc))
    with pytest.raises(ReplayError, match="does not match its content hash"):
        load_record(r.path)
    assert _verify(r.path)[0] == 1
    # ... and the content hash too: only a hash kept elsewhere catches that
    doc["content_hash"] = rehash(r.path)[3]
    (r.path / "task.yaml").write_text(yamlio.dump(doc))
    assert _verify(r.path)[0] == 0
    code, output = _verify(r.path, "--expect", trusted)
    assert code == 1 and "differs from the expected" in output


def test_a_record_outside_any_artifact_replays_as_given(tmp_path):
    r = _model_task(tmp_path)
    loose = tmp_path / "mine.jsonl"
    loose.write_bytes((r.path / MODEL_RECORD).read_bytes())
    again = compile_instruction("", tmp_path / "again", replay=loose)
    assert again.valid and again.content_hash == r.content_hash


def test_changed_added_or_linked_files_are_named(tmp_path):
    r = compile_instruction("Stack the green block on top of the blue block", tmp_path)
    assert r.valid and verify_target(r.path)["ok"]
    victim = "initial.png" if (r.path / "initial.png").exists() else "validation.log"
    with open(r.path / victim, "ab") as fh:
        fh.write(b"\0")
    (r.path / "notes.txt").write_text("hi")
    os.symlink("code.py", r.path / "more.py")
    code, output = _verify(r.path)
    assert code == 1
    flat = " ".join(output.split())
    assert f"manifest): {victim}" in flat and "notes.txt" in flat and "more.py" in flat
    report = verify_target(r.path)
    assert not report["ok"] and len(report["problems"]) == 3
    os.unlink(r.path / "more.py")
    (r.path / "notes.txt").unlink()
    (r.path / "goal_state_code.py").unlink()
    with pytest.raises(Exception, match="goal_state_code.py is missing"):
        verify_target(r.path)


def test_a_family_version_names_the_changed_file(tmp_path):
    r = compile_instruction("Place a blue cube on top of a red cube on the table", tmp_path, name="fam")
    fam = create_family(r.path)
    assert all(v["ok"] for v in fam.verify())
    victim = "initial.png" if (fam.version_dir(0) / "initial.png").exists() else "validation.json"
    with open(fam.version_dir(0) / victim, "ab") as fh:
        fh.write(b"\0")
    (v0,) = Family(fam.path).verify()
    assert not v0["ok"]
    assert any(victim in p and "task.yaml's manifest" in p for p in v0["problems"])
    code, output = _verify(fam.path)
    assert code == 1 and victim in output


def test_an_artifact_without_a_manifest_is_reported_and_validate_records_it(tmp_path):
    r = compile_instruction("Stack the green block on top of the blue block", tmp_path)
    doc = _task_doc(r.path)
    del doc["files"]  # as written before manifests (or stripped by an attacker)
    (r.path / "task.yaml").write_text(yamlio.dump(doc))
    assert rehash(r.path)[3] == r.content_hash  # the manifest is outside the content hash
    report = verify_target(r.path)
    assert not report["ok"] and "no file manifest" in report["problems"][0]
    result = revalidate(r.path)
    assert result.valid and verify_target(r.path)["ok"]
    # revalidating re-records only the logs it rewrote: a file added since stays reported
    (r.path / "extra.bin").write_bytes(b"x")
    revalidate(r.path)
    assert "extra.bin" in " ".join(verify_target(r.path)["problems"])


def test_build_check_counts_a_changed_snapshot_as_a_changed_entry(tmp_path):
    from rpg.library.build import _recorded_hash

    r = compile_instruction("Stack the green block on top of the blue block", tmp_path)
    assert _recorded_hash(r.path) == r.content_hash
    victim = "goal.png" if (r.path / "goal.png").exists() else "validation.json"
    (r.path / victim).write_bytes(b"forged")
    assert rehash(r.path)[3] == r.content_hash and _recorded_hash(r.path) is None
