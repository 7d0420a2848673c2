"""rpg diversity: measures checked against hand-computed values, the offline embedding load
with sockets blocked, synthetic author groups on library tasks, plots and the CLI."""

import json
import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from rpg.diversity import (
    analyze,
    collect,
    mean_pairwise_distance,
    pooled_diversity,
    structural_diversity,
    suggestions,
)
from rpg.diversity.measures import cumulative_diversity, goal_kind
from rpg.schema.builtin import parse

ROOT = Path(__file__).resolve().parents[1]


def test_measures_match_hand_computed_values():
    x = np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 0.0], [math.sqrt(0.5), math.sqrt(0.5)]])
    # pairs: (0,1)=1, (0,2)=0, (0,3)=1-0.7071, (1,2)=1, (1,3)=1-0.7071, (2,3)=1-0.7071
    assert mean_pairwise_distance(x) == pytest.approx((2 + 3 * (1 - math.sqrt(0.5))) / 6)
    assert mean_pairwise_distance(x[:3]) == pytest.approx(2 / 3)
    assert math.isnan(mean_pairwise_distance(x[:1]))
    groups = ["a", "b", "a", "b"]
    pooled = pooled_diversity(x, groups, np.random.default_rng(0), orderings=50)
    # one author: a's two tasks are identical (0.0); b's are 1 - cos 45 deg apart; both authors: all pairs
    assert pooled[0]["contributors"] == 1 and pooled[0]["lo"] == pytest.approx(0.0)
    assert pooled[0]["hi"] == pytest.approx(1 - math.sqrt(0.5))
    assert pooled[1]["mean"] == pooled[1]["lo"] == pooled[1]["hi"] == pytest.approx(mean_pairwise_distance(x))
    assert pooled[1]["tasks"] == 4
    assert cumulative_diversity(x, groups) == {"a": [pytest.approx(0.0)], "b": [pytest.approx(1 - math.sqrt(0.5))]}


def test_structural_diversity_from_schemas_alone():
    schemas = [parse("Stack the red block on the blue block"), parse("Build a tower of 3 green blocks"),
               parse("Arrange 3 blocks in a line from left to right: red, green, blue")]
    kinds = [goal_kind(s) for s in schemas]
    s = structural_diversity(schemas)
    counts = s["goal_kinds"]["counts"]
    assert counts[kinds[0]] + counts[kinds[1]] + counts[kinds[2]] >= 3 and sum(counts.values()) == 3
    assert kinds[1] == "tower" and kinds[2] == "line"
    if kinds[0] == "tower":  # two towers and a line: H = -(2/3 log2 2/3 + 1/3 log2 1/3)
        assert s["goal_kinds"]["entropy_bits"] == pytest.approx(0.918296, abs=1e-6)
    assert s["asset_classes"]["counts"] == {"ColoredCube": 3, "GoalPatch": 0, "SemanticCube": 0}
    assert s["asset_classes"]["coverage"] == pytest.approx(1 / 3) and s["asset_classes"]["entropy_bits"] == 0.0
    assert suggestions(s)["asset_classes"][:2] == ["GoalPatch", "SemanticCube"]


def test_wordllama_loads_offline_with_sockets_blocked():
    code = (
        "import socket\n"
        "def refuse(*a, **k): raise OSError('network access attempted')\n"
        "socket.socket.connect = refuse\nsocket.create_connection = refuse\n"
        "from rpg.diversity.embeddings import embed\n"
        "x = embed(['stack the red block on the blue block', 'spell CAT with letter cubes'])\n"
        "print(x.shape[1], round(float((x * x).sum(axis=1)[0]), 6))\n")
    env = {k: v for k, v in os.environ.items() if not k.startswith(("HF_", "HUGGINGFACE"))}
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.split() == ["256", "1.0"]


def _synthetic_library(tmp_path: Path) -> Path:
    """Library tasks copied into a new manifest with three synthetic authors."""
    manifest = yaml.safe_load((ROOT / "library" / "manifest.yaml").read_text())
    tasks = [e for e in manifest["entries"] if e.get("instruction")][:9]
    lib = tmp_path / "lib"
    lib.mkdir()
    entries = []
    for i, e in enumerate(tasks):
        shutil.copytree(ROOT / "library" / e["name"], lib / e["name"])
        entries.append({**e, "author": ["ada", "bo", "cy"][i % 3]})
    (lib / "manifest.yaml").write_text(yaml.safe_dump({"entries": entries}, sort_keys=False))
    return lib / "manifest.yaml"


def test_library_with_synthetic_authors_writes_summary_and_plots(tmp_path):
    manifest = _synthetic_library(tmp_path)
    records = collect(manifest)
    assert [r.author for r in records] == ["ada", "bo", "cy"] * 3
    a = analyze(manifest, by="author", embedding="tfidf", out_dir=tmp_path / "out", orderings=40)
    b = analyze(manifest, by="author", embedding="tfidf", orderings=40)
    assert a["groups"] == {"ada": 3, "bo": 3, "cy": 3}
    assert [r["contributors"] for r in a["pooled"]] == [1, 2, 3]
    assert a["pooled"][-1]["mean"] == pytest.approx(a["mean_pairwise_distance"])
    assert all(len(v) == 2 for v in a["cumulative"].values())
    assert {k: v for k, v in a.items() if k != "plots"} == b  # deterministic
    for name in ("pooled.png", "cumulative.png", "tsne.png"):
        data = (tmp_path / "out" / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000, name
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["tasks"] == 9


def test_cli_diversity_and_bad_grouping(tmp_path):
    manifest = _synthetic_library(tmp_path)
    rpg = [sys.executable, "-m", "rpg.cli", "diversity", str(manifest)]
    env = {**os.environ, "COLUMNS": "200"}
    ok = subprocess.run([*rpg, "--by", "author", "--embedding", "tfidf", "--suggest", "-o", str(tmp_path / "o")],
                        capture_output=True, text=True, env=env)
    assert ok.returncode == 0, ok.stderr
    assert "least covered goal kinds" in ok.stdout and (tmp_path / "o" / "summary.json").is_file()
    bad = subprocess.run([*rpg, "--by", "colour"], capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and "--by must be" in bad.stderr and "Traceback" not in bad.stderr
    bad = subprocess.run([*rpg, "--embedding", "bert"], capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and "unknown embedding" in bad.stderr
    (tmp_path / "afile").write_text("")
    for cmd in ([*rpg, "-o", str(tmp_path / "afile")],
                [sys.executable, "-m", "rpg.cli", "report", str(manifest.parent), "-o", str(tmp_path / "afile")]):
        bad = subprocess.run(cmd, capture_output=True, text=True, env=env)
        assert bad.returncode == 2 and "is a file" in bad.stderr and "Traceback" not in bad.stderr, bad.stderr


def test_authors_recorded_by_compile_group_a_library_directory(tmp_path):
    """`rpg compile --author` (or RPG_AUTHOR) records the author in task.yaml provenance;
    `rpg diversity DIR --by author` groups by it; without any author nothing is recorded."""
    env = {**os.environ, "COLUMNS": "200", "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_SYSTEM": os.devnull}
    env.pop("RPG_AUTHOR", None)
    lib = tmp_path / "lib"
    runs = [("Stack the red block on the blue block", ["--author", "ada"], {}),
            ("Build a tower of 3 green blocks", [], {"RPG_AUTHOR": "bo"}),
            ("Arrange 3 blocks in a line from left to right: red, green, blue", [], {})]
    for text, args, extra in runs:
        proc = subprocess.run([sys.executable, "-m", "rpg.cli", "compile", text, "-o", str(lib), *args],
                              capture_output=True, text=True, env={**env, **extra}, cwd=tmp_path)
        assert proc.returncode == 0, proc.stderr
    authors = {r.schema.instruction: r.author for r in collect(lib)}
    assert authors == {runs[0][0]: "ada", runs[1][0]: "bo", runs[2][0]: "unknown"}
    docs = [yaml.safe_load(p.read_text()) for p in sorted(lib.rglob("task.yaml"))]
    assert sum("author" in d["provenance"] for d in docs) == 2
    assert analyze(lib, by="author", embedding="tfidf", orderings=10)["groups"] == {"ada": 1, "bo": 1, "unknown": 1}


def test_steer_records_the_author_in_the_family_history(tmp_path):
    """An edit's author goes into the new version's task.yaml and its history entry (and its
    lineage hash); versions without an author keep the history format and hashes they had."""
    from rpg.compiler import compile_instruction
    from rpg.steer import Family, steer

    art = compile_instruction("Build a tower of 3 green blocks", tmp_path).path
    r = steer(art, "make it 4 blocks tall", author="ada")
    assert r.valid
    fam = Family(art)
    hist = fam.load()
    assert [v.author for v in hist.versions] == [None, "ada"]
    text = (art / "family.yaml").read_text()
    assert text.count("author:") == 1
    assert all(v["ok"] for v in fam.verify())
    assert {r.name: r.author for r in collect(tmp_path)} == {f"{art.name}@v0": "unknown", f"{art.name}@v1": "ada"}


def test_a_sentence_transformers_path_that_is_not_a_model_is_bad_input(tmp_path):
    from rpg.diversity.embeddings import embed
    from rpg.errors import BadInput

    with pytest.raises(BadInput, match="not a sentence-transformers model directory"):
        embed(["stack the red block"], f"st:{tmp_path / 'missing'}")
