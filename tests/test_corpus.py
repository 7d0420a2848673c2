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
        meanings = e["meaning"] if isinstance(e["meaning"], list) else [e["meaning"]]  # a list: readings equally right
        assert e["text"].strip() and meanings and all(m.strip() for m in meanings), e
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
    # all one colour matches either form, with its place too (the place suffix is no object)
    ("pyramid(pink,pink|pink)@center", ["pyramid(pink,pink,pink)@center"], True),
    ("pyramid(pink,pink|pink)@center", ["pyramid(pink,pink,pink)"], False),
    ("pyramid(pink,red|pink)@center", ["pyramid(pink,pink,red)@center"], False),
    # a place said of several cubes at once is one atom per cube
    ("in_region(red,red,left)", ["in_region(red,left)", "in_region(red,left)"], True),
    ("in_region(red,red,left)", ["in_region(red,left)"], False),
    ("in_region(blue,red,left)", ["in_region(red,left)", "in_region(red,left)"], False),
    # a grid written without its size is a grid of those cubes (steer_stranger4's "2x2 square" had not matched)
    ("grid(gray,gray|gray,gray)", ["grid(2x2:gray,gray,gray,gray)"], True),
    ("grid(gray,gray,gray)", ["grid(2x2:gray,gray,gray,gray)"], False),
    ("grid(2x2:brown,brown|white,white)", ["grid(2x2:brown,white|brown,white)"], False),
    ("grid(white,white,white,white)@center", ["grid(2x2:white,white,white,white)@center"], True),  # with its place
    ("grid(white,white,white,white)@center", ["grid(2x2:white,white,white,white)@left"], False),
    # a line read in a reversed direction is the same line written forward (stranger27's annotator wrote it so)
    ("line[left_to_right](blue,red,red)", ["line[right_to_left](red,red,blue)"], True),
    ("line[left_to_right](red,red,blue)", ["line[right_to_left](red,red,blue)"], False),
    ("line[front_to_back](red,green)", ["line[back_to_front](green,red)"], True),
    ("line[front_to_back](red,green)", ["line[left_to_right](red,green)"], False),
    # a relation written with its converse is the same goal (stranger45's annotator wrote "A behind B" as in_front_of(B,A))
    ("in_front_of(blue,red)", ["behind(red,blue)"], True),
    ("behind(red,blue)", ["in_front_of(blue,red)"], True),
    ("right_of(red,blue)", ["left_of(blue,red)"], True),
    ("in_front_of(red,blue)", ["behind(red,blue)"], False),
    ("left_of(red,blue)", ["left_of(blue,red)"], False),
    ("right_of(red,blue); in_front_of(red,blue)", ["left_of(blue,red)", "behind(blue,red)"], True),
    # the two a cube stands between in either order; the one between them is not one of the two
    ("between(white;red,blue)", ["between(white;blue,red)"], True),
    ("between(white;red,blue)", ["between(red;blue,white)"], False),
    # cubes on one patch said at once are one atom per cube
    ("on_patch(red,patch:green); on_patch(blue,patch:green)", ["on_patch(blue,red,patch:green)"], True),
    ("on_patch(red,patch:green)", ["on_patch(blue,red,patch:green)"], False),
    ("on_patch(red,patch:green); on_patch(blue,patch:red)", ["on_patch(blue,red,patch:green)"], False),
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
        if isinstance(e["meaning"], str) and e["meaning"].startswith("none"):
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


# -- steering edits (steer_dev.yaml / steer_unseen.yaml, run_steer.py) ---------------------------------

import run_steer  # noqa: E402


def _step(meaning, category=None, refuse=None):
    s = {"edit": "x", "meaning": meaning}
    if category:
        s["category"] = category
    if refuse:
        s["refuse"] = refuse
    return s


def test_steering_runner_classifies_each_outcome():
    j = run_steer.judge_step
    tower = _step("stack(red,blue,green)", "extend")
    assert j(tower, got=["stack(red,blue,green)"], intent="extend") == ("right", "")
    assert j(_step("stack(red,blue,green)", ["extend", "tweak"]), got=["stack(red,blue,green)"], intent="tweak")[0] == "right"
    assert j(tower, got=["stack(red,blue,green)"], intent="pivot") == ("category wrong", "category wrong: extend read as pivot")
    assert j(tower, got=["stack(green)"], intent="extend", before=["stack(red,blue)"])[1] == \
        "silently wrong: addition applied as a replacement (earlier cubes lost)"
    assert j(tower, got=["stack(red,blue)"], intent="extend", before=["stack(red,blue)"])[1] == \
        "silently wrong: edit had no effect (meaning unchanged)"
    assert j(tower, got=["stack(blue,red,green)"], intent="extend", before=["stack(red,blue)"]) == \
        ("silently wrong", "silently wrong: order or roles")
    assert j(tower, refused="could not parse 'florp' in \"...\"")[0:2] == ("refused wrongly", "refused wrongly: unknown word")
    assert j(tower, error="ValueError (traceback)") == ("error", "error: ValueError (traceback)")
    assert j(tower, refused="could not find a task in ...", family_changed=True)[0] == "error"
    rot = _step("none (rotating is an action)", refuse="action")
    assert j(rot, refused="cannot make a task of \"...\": 'rotate' is an action the domain does not have")[0] == "right"
    assert j(rot, refused="could not parse 'degrees' in \"...\"") == \
        ("refused (must-refuse): other reason", "refused (must-refuse): other reason (unknown word)")
    assert j(rot, got=["stack(red,blue)"], intent="modify") == \
        ("silently wrong", "silently wrong: compiled a must-refuse edit (action)")
    # alternatives and the notation rules: a spelled word's reads atom, identical cubes' order and layers
    assert j(_step(["next_to(blue,yellow)", "next_to(blue,red)"], "extend"), got=["next_to(blue,red)"], intent="extend")[0] == "right"
    assert j(_step("line[left_to_right](C,A,T)", "tweak"), intent="tweak",
             got=["line[left_to_right](C,A,T)", "reads(C,A,T;direction=left_to_right,face=up,text=CAT)"])[0] == "right"
    assert j(_step("line(red,red,red)", "pivot"), got=["line[left_to_right](red,red,red)"], intent="pivot")[0] == "right"
    assert j(_step("line(blue,green,red)", "pivot"), got=["line[left_to_right](red,green,blue)"], intent="pivot")[0] == \
        "silently wrong"  # an order over different cubes is one the edit did not ask for
    assert j(_step("pyramid(red,red,red|red,red|red)", "tweak"), got=["pyramid(red,red,red,red,red,red)"], intent="tweak")[0] == "right"
    assert j(_step("pyramid(blue,blue,blue|green,green|green)", "tweak"), intent="tweak",
             got=["pyramid(blue,blue,blue,green,green,green)"])[0] == "silently wrong"  # layer colours not judged


def test_steering_runner_on_a_few_development_cases():
    """The real steering code on four development cases: every edit gets a verdict that agrees with
    judge_step on what steering did, multi-step cases stop at their first failure, the summary adds up.
    Not a floor on the score."""
    cases = {c["id"]: c for c in run_steer.load_split("dev")}
    chosen = [cases[i] for i in ("s005", "s085", "s105", "s017")]  # tweak, must-refuse, 2 edits, a count edit
    results = run_steer.run_cases(chosen, jobs=1)
    for case, res in zip(chosen, results, strict=True):
        assert res.id == case["id"] and res.outcome in run_steer.ORDER, res
        if res.outcome.startswith("base"):
            continue
        reached = [s for s in res.steps if s.outcome != "not reached"]
        assert reached and all(s.outcome != "not reached" for s in res.steps[:len(reached)])
        first_bad = next((s for s in res.steps if s.outcome not in ("right", "not reached")), None)
        assert res.outcome == (first_bad.outcome if first_bad else "right")
        for spec, st in zip(case["steps"], reached, strict=False):
            if st.got:  # compiled: the verdict is judge_step's on the meaning and intent
                assert st.outcome == run_steer.judge_step(spec, got=st.got, intent=st.intent)[0]
            elif st.outcome != "error":  # refused: a one-line message, never a traceback
                assert st.message and "Traceback" not in st.message
    s = run_steer.summarize(chosen, results)
    assert sum(s["by_case"].values()) == 4
    assert sum(s["by_edit"].values()) == sum(len(c["steps"]) for c in chosen)


def test_steering_unseen_split_is_frozen_and_reported_in_aggregate_only(tmp_path, monkeypatch, capsys):
    frozen = SPLITS["steering"]["unseen"]["sha256"]
    assert hashlib.sha256(run_steer.UNSEEN.read_bytes()).hexdigest() == frozen, \
        "steer_unseen.yaml changed after it was frozen: an edited split is no longer unseen (see splits.yaml)"
    unseen = run_steer.load_split("unseen")
    dev = run_steer.load_split("dev")
    assert len(unseen) + len(dev) == 120 and not {c["id"] for c in unseen} & {c["id"] for c in dev}
    for c in unseen + dev:
        for st in c["steps"]:
            assert run_steer.must_refuse(st) == ("refuse" in st)
            assert st.get("refuse") in (None, *run_steer.STEER_REASON_WORDS), c["id"]
            assert all(k in run_steer.CATEGORIES for k in run_steer.expected_categories(st)), c["id"]
    # the summary the unseen report prints holds no base, edit or expected meaning (results made up here)
    fake = [run_steer.CaseResult(c["id"], "silently wrong", "silently wrong: count",
                                 steps=[run_steer.Step(st["edit"], "silently wrong", "silently wrong: count")
                                        for st in c["steps"]]) for c in unseen]
    run_steer.print_summary("UNSEEN", run_steer.summarize(unseen, fake))
    text = capsys.readouterr().out
    for c in unseen:
        assert c["base"] not in text and c["id"] not in text
        assert all(st["edit"] not in text and str(st["meaning"]) not in text for st in c["steps"])
    edited = tmp_path / "steer_unseen.yaml"
    edited.write_text(run_steer.UNSEEN.read_text() + "# edited\n")
    monkeypatch.setattr(run_steer, "UNSEEN", edited)
    assert run_steer.main(["--split", "unseen"]) == 2
    with pytest.raises(SystemExit):
        run_steer.main(["--split", "unseen", "--show", "wrong"])


def test_a_spelled_words_reading_need_not_be_written_by_the_annotation():
    """A text that spells a word with its cubes is right compiled with the word's reading (``reads``) though its
    annotation writes the line alone (annotators the notation was not shown to); the reading must be of the compiled
    line's cubes, and a text that spells nothing gets no such leeway."""
    spelled = {"text": "Spell DOG from left to right with the letter cubes.", "meaning": "line[left_to_right](D,O,G)"}
    assert run_corpus.classify(spelled)[0] == "correct"
    line = ["line[left_to_right](D,O,G)", "reads(D,O,G;direction=left_to_right,face=up,text=DOG)"]
    assert run_corpus._spelled_reading_unwritten(spelled, line)
    assert not run_corpus._spelled_reading_unwritten({**spelled, "text": "Put D, O and G in a row."}, line)
    assert not run_corpus._spelled_reading_unwritten(spelled, ["line[left_to_right](D,O,G)",
                                                               "reads(G,O,D,A;direction=left_to_right,face=up,text=GODA)"])
    assert not run_corpus._spelled_reading_unwritten({**spelled, "meaning": "line[left_to_right](D,O,G); reads(DOG)"}, line)
