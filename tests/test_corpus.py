"""The corpus: instructions written by people, in a development and an UNSEEN split (tests/corpus).

Each development entry (instructions.yaml) is compiled through the schema pass and compared
with its expected meaning; the table of correct / refused / wrong is printed (``pytest -s``)
and these are asserted: no silently wrong task, at least 85% read right (a regression floor), every
refusal says what it could not place. The unseen split (unseen.yaml) is only checked to be
the frozen file (its SHA-256 in splits.yaml) and to be reported in aggregate only: its figures
are measured, not asserted, and no test looks at its individual entries' outcomes.
"""

from __future__ import annotations

import hashlib
import io
import re
import sys
from collections import Counter
from contextlib import redirect_stdout
from pathlib import Path

import pytest
import yaml

sys.path.insert(0, str(Path(__file__).parent / "corpus"))
import run_corpus  # noqa: E402

from rpg.schema.meaning import matches  # noqa: E402

DOC = yaml.safe_load(run_corpus.CORPUS.read_text())
SPLITS = yaml.safe_load(run_corpus.SPLITS.read_text())


def test_every_entry_cites_a_public_source_with_a_licence():
    sources = DOC["sources"]
    assert len(DOC["instructions"]) >= 300
    for key, src in sources.items():
        assert src["repo"] and src["licence"] and src["file"], key
    for e in DOC["instructions"]:
        assert e["source"] in sources, e
        assert e["text"].strip() and e["meaning"].strip(), e
    assert len({e["text"] for e in DOC["instructions"]}) > 250  # template sources repeat few texts


def test_corpus_no_silent_errors_and_85_percent_correct(capsys):
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
    plain = sum(1 for e in DOC["instructions"] if "refuse" not in e)
    must = [e for e in DOC["instructions"] if "refuse" in e]
    right = sum(1 for e in must if run_corpus.classify(e)[0] == "refused"
                and run_corpus.refusal_reason_ok(e, run_corpus.classify(e)[1]))
    with capsys.disabled():
        print(f"\ncorpus: {n} instructions, {outcomes['correct']} correct, {outcomes['refused']} refused, "
              f"{outcomes['wrong']} wrong; {outcomes['correct']} of {plain} plain texts correct, "
              f"{right} of {len(must)} must-refuse texts refused for the right reason")
    assert not wrong, "silently wrong tasks:\n" + "\n".join(f"{t!r}: expected {m}, got {d}" for t, m, d in wrong)
    # Regression floors, not the target (90% of unseen text): measured over the texts
    # that have a meaning to compile (a must-refuse text counts as refused in the table, so the
    # share of all texts falls whenever a source brings many of them: 117 of the 188 texts added
    # on 2026-11-22 were must-refuse). 2026-11-22: 466 of 491 plain texts (95%), 34 of 66
    # must-refuse texts refused for the right reason.
    assert outcomes["correct"] / plain >= 0.93
    assert right / len(must) >= 0.5
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
    # a pyramid whose layers the goal does not judge is one list: layers said do not match it
    ("pyramid(green,red|yellow)", ["pyramid(green,red,yellow)"], False),
    ("pyramid(green,red|yellow)", ["pyramid(green,red|yellow)"], True),
    ("pyramid(?,?|?)", ["pyramid(green,red,yellow)"], True),
    ("pyramid(?,?|?)", ["pyramid(green,red,yellow,blue)"], False),
    ("pyramid(red*)", ["pyramid(red,red,red)"], True),
])
def test_meaning_matcher(expected, actual, ok):
    assert matches(expected, actual) is ok


def test_unseen_split_is_the_frozen_file_and_a_third_of_the_corpus():
    assert hashlib.sha256(run_corpus.UNSEEN.read_bytes()).hexdigest() == SPLITS["unseen"]["sha256"], \
        "unseen.yaml changed after it was frozen: an edited split is no longer unseen (see splits.yaml)"
    unseen = yaml.safe_load(run_corpus.UNSEEN.read_text())
    dev_sources, unseen_sources = set(SPLITS["development"]["sources"]), set(SPLITS["unseen"]["sources"])
    assert dev_sources == set(DOC["sources"]) and unseen_sources == set(unseen["sources"])
    assert not dev_sources & unseen_sources  # whole sources only
    assert {e["source"] for e in unseen["instructions"]} == unseen_sources
    for key, src in unseen["sources"].items():
        assert src["repo"] and src["licence"] and src["file"] and src["kind"], key
    n_unseen, n_dev = len(unseen["instructions"]), len(DOC["instructions"])
    assert n_unseen >= 0.30 * (n_unseen + n_dev)
    for e in DOC["instructions"] + unseen["instructions"]:
        if e["meaning"].startswith("none"):
            assert e.get("refuse") in run_corpus.REASON_WORDS, e  # must-refuse entries name their reason class


def test_runner_refuses_an_edited_unseen_file(tmp_path, monkeypatch):
    edited = tmp_path / "unseen.yaml"
    edited.write_text(run_corpus.UNSEEN.read_text() + "# edited\n")
    monkeypatch.setattr(run_corpus, "UNSEEN", edited)
    assert run_corpus.main(["--split", "unseen"]) == 2


def test_runner_reports_the_unseen_split_in_aggregate_only():
    unseen = yaml.safe_load(run_corpus.UNSEEN.read_text())["instructions"]
    out = io.StringIO()
    with redirect_stdout(out):
        run_corpus.main(["--split", "unseen"])
    text = out.getvalue()
    assert "UNSEEN split" in text and "failure classes" in text and "must-refuse" in text
    for e in unseen:  # no instruction text, whole or in part, and no expected meaning
        assert e["text"] not in text and e["text"][:30] not in text and e["meaning"] not in text
    assert not re.search(r"could not|\bread \"|expected:|got:", text)  # no parser message either
    with pytest.raises(SystemExit):
        run_corpus.main(["--split", "unseen", "--show", "wrong"])
