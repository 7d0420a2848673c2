"""The development corpus: instructions written by people (tests/corpus/instructions.yaml).

Each entry is compiled through the schema pass and compared with its expected meaning; the
table of correct / refused / wrong is printed (``pytest -s``) and the issue's targets are
asserted: no silently wrong task, at least 90% read right, every refusal says what it could
not place.
"""

from __future__ import annotations

import re
import sys
from collections import Counter
from pathlib import Path

import pytest
import yaml

sys.path.insert(0, str(Path(__file__).parent / "corpus"))
import run_corpus  # noqa: E402

from rpg.schema.meaning import matches  # noqa: E402

DOC = yaml.safe_load(run_corpus.CORPUS.read_text())


def test_every_entry_cites_a_public_source_with_a_licence():
    sources = DOC["sources"]
    assert len(DOC["instructions"]) >= 300
    for key, src in sources.items():
        assert src["repo"] and src["licence"] and src["file"], key
    for e in DOC["instructions"]:
        assert e["source"] in sources, e
        assert e["text"].strip() and e["meaning"].strip(), e
    assert len({e["text"] for e in DOC["instructions"]}) > 250  # template sources repeat few texts


def test_corpus_no_silent_errors_and_90_percent_correct(capsys):
    outcomes = Counter()
    refusals = []
    wrong = []
    for e in DOC["instructions"]:
        outcome, detail = run_corpus.classify(e)
        outcomes[outcome] += 1
        if outcome == "refused":
            refusals.append(detail)
        elif outcome == "wrong":
            wrong.append((e["text"], e["meaning"], detail))
    n = sum(outcomes.values())
    with capsys.disabled():
        print(f"\ncorpus: {n} instructions, {outcomes['correct']} correct, {outcomes['refused']} refused, "
              f"{outcomes['wrong']} wrong")
    assert not wrong, "silently wrong tasks:\n" + "\n".join(f"{t!r}: expected {m}, got {d}" for t, m, d in wrong)
    assert outcomes["correct"] / n >= 0.90
    for msg in refusals:  # a refusal names the word or mention it could not place, and a way out
        assert "'" in msg or '"' in msg, msg
        assert re.search(r"\b(?:[Rr]ephrase|say|name a|use --model)\b", msg), msg


@pytest.mark.parametrize("expected,actual,ok", [
    ("stack(red,blue)", ["stack(red,blue)"], True),
    ("stack(red,blue)", ["stack(blue,red)"], False),
    ("stack(?,?)", ["stack(red,blue)"], True),
    ("on_patch(red*,patch:green)", ["on_patch(red,red,red,patch:green)"], True),
    ("on_patch(red*,patch:green)", ["on_patch(blue,red,patch:green)"], False),
    ("on_patch(?,patch:?)", ["on_patch(red,patch:gray)"], True),
    ("pyramid(red*)", ["pyramid(red,red,red|red,red|red)"], True),
    ("stack(red,blue); stack(red,blue)", ["stack(red,blue)"], False),
    ("stack(red,blue)", ["stack(red,blue)", "extra(green)"], False),
])
def test_meaning_matcher(expected, actual, ok):
    assert matches(expected, actual) is ok
