"""Task library: manifest, parallel build (process pool and Ray), --check, retrieval tags."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from rpg.compiler import load_artifact
from rpg.library import load_manifest

ROOT = Path(__file__).resolve().parents[1]
RPG = [sys.executable, "-m", "rpg.cli"]
MINI = """# a small library
entries:
- name: stack_blocks
  instruction: Stack two blocks on top of each other.
- name: place_left
  instruction: Place the red block on the left side of the yellow block
- name: tower
  session: tower.yaml
"""
SESSION = """name: tower
steps:
- instruction: Place a blue cube on top of a red cube on the table
- edit: Add a green cube on top of the blue
  expected_intent: extend
  expected_reference: current
  expected_final: "tower bottom to top: red, blue, green"
"""


def rpg(*args):
    return subprocess.run([*RPG, *args], capture_output=True, text=True, env={**os.environ, "COLUMNS": "200"})


@pytest.fixture()
def mini(tmp_path):
    (tmp_path / "manifest.yaml").write_text(MINI)
    (tmp_path / "tower.yaml").write_text(SESSION)
    return tmp_path / "manifest.yaml"


def test_build_records_hashes_and_check_catches_a_change(mini, tmp_path, snapshots_on):
    r = rpg("build", str(mini), "--jobs", "2", "--json", str(tmp_path / "report.json"))
    assert r.returncode == 0, r.stdout + r.stderr
    m = load_manifest(mini)
    assert all(e.content_hash and len(e.content_hash) == 64 for e in m.entries)
    assert mini.read_text().startswith("# a small library")
    report = json.loads((tmp_path / "report.json").read_text())
    assert {e["name"]: e["status"] for e in report["entries"]} == {"stack_blocks": "valid", "place_left": "valid", "tower": "valid"}
    assert (tmp_path / "tower" / "family.yaml").is_file() and (tmp_path / "tower" / "v1" / "goal.png").is_file()
    _, doc = load_artifact(tmp_path / "stack_blocks")
    assert doc["content_hash"] == m.entries[0].content_hash
    assert set(doc["tags"]) == {"asset_class", "reasoning", "complexity", "primitives"}
    before = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*") if p.is_file()}
    ok = rpg("build", str(mini), "--check")
    assert ok.returncode == 0, ok.stdout
    assert {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*") if p.is_file() and p.name != "report.json"} == \
        {p: t for p, t in before.items() if p.name != "report.json"}
    text = mini.read_text().replace(m.entries[1].content_hash, "f" * 64)
    mini.write_text(text)
    bad = rpg("build", str(mini), "--check")
    assert bad.returncode == 1 and "changed place_left" in bad.stdout


def _mtimes(root: Path) -> dict:
    return {p: p.stat().st_mtime_ns for p in root.rglob("*") if p.is_file() and p.suffix != ".json" and p.name != "manifest.yaml"}


def test_rebuild_leaves_unchanged_entries_alone_and_restores_altered_ones(mini, tmp_path):
    assert rpg("build", str(mini)).returncode == 0
    built = _mtimes(tmp_path)
    assert rpg("build", str(mini), "--jobs", "2", "--json", str(tmp_path / "r1.json")).returncode == 0
    assert _mtimes(tmp_path) == built, "an unchanged entry's files (logs with timings, snapshots) were rewritten"
    assert not any(e["written"] for e in json.loads((tmp_path / "r1.json").read_text())["entries"])

    code = tmp_path / "stack_blocks" / "code.py"
    pristine = code.read_text()
    code.write_text(pristine + "\n# edited by hand\n")
    history = tmp_path / "tower" / "v1" / "goal_state_code.py"
    history.write_text(history.read_text() + "\n# edited by hand\n")
    r = rpg("build", str(mini), "--json", str(tmp_path / "r2.json"))
    assert r.returncode == 0, r.stdout + r.stderr
    written = {e["name"]: e["written"] for e in json.loads((tmp_path / "r2.json").read_text())["entries"]}
    assert written == {"stack_blocks": True, "place_left": False, "tower": True}
    assert code.read_text() == pristine and "edited" not in history.read_text()
    assert not list(tmp_path.glob(".rpg-build-*")) and not list(tmp_path.glob(".trash-*"))

    assert rpg("build", str(mini), "--force", "--json", str(tmp_path / "r3.json")).returncode == 0
    assert all(e["written"] for e in json.loads((tmp_path / "r3.json").read_text())["entries"])


def test_bad_manifests_exit_2(tmp_path):
    f = tmp_path / "m.yaml"
    for text in ("entries: [{name: x}]", "entries: [{name: Bad Name, instruction: stack two blocks}]", "nope: 1", ": :"):
        f.write_text(text)
        r = rpg("build", str(f))
        assert r.returncode == 2 and "manifest" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.slow
def test_ray_backend_builds_the_same_hashes(mini, tmp_path):
    pytest.importorskip("ray")
    assert rpg("build", str(mini), "--jobs", "2").returncode == 0
    local = {e.name: e.content_hash for e in load_manifest(mini).entries}
    r = rpg("build", str(mini), "--backend", "ray", "--jobs", "2", "--check")
    assert r.returncode == 0, r.stdout + r.stderr
    assert {e.name: e.content_hash for e in load_manifest(mini).entries} == local


def test_repository_library_holds_every_manifest_entry_with_tags():
    m = load_manifest(ROOT / "library" / "manifest.yaml")
    assert len(m.entries) == 42 and all(e.content_hash for e in m.entries)
    for e in m.entries:
        d = ROOT / "library" / e.name
        if e.kind == "task":
            _, doc = load_artifact(d)
            assert doc["content_hash"] == e.content_hash and doc["tags"]["reasoning"] in ("spatial", "semantic")
        else:
            from rpg.steer.family import Family

            assert Family(d).load().digest() == e.content_hash
            assert (ROOT / "library" / e.session).resolve().parent == ROOT / "examples"


def test_every_library_task_records_its_mention_accounting():
    """task.yaml says which words produced which part of the goal; in the committed
    library every mention of every instruction (steering's canonical ones included) has a part."""

    tasks = sorted((Path(__file__).resolve().parents[1] / "library").rglob("task.yaml"))
    assert len(tasks) >= 40
    kinds, empty = set(), 0
    for t in tasks:
        record = yaml.safe_load(t.read_text())["accounting"]
        assert isinstance(record, list) and all(r["kind"] != "unaccounted" for r in record), t
        kinds |= {r["kind"] for r in record}
        empty += not record  # "Place cubes in a circular arrangement" names no colour, count or structure word
    assert {"color", "count", "structure", "relation"} <= kinds and empty <= 3
