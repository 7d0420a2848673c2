"""Run the development corpus through the builtin front end and print correct / refused / wrong.

Usage: ``.venv/bin/python tests/corpus/run_corpus.py [--show wrong|refused|correct|all]``

An instruction is *correct* when the schema pass (parser + feasibility) gives a task whose
meaning (:func:`rpg.schema.meaning.meaning`) matches the corpus entry, *refused* when it
raises ParseError / InfeasibleTask (the message names what it could not place), and *wrong*
when it gives a task that means something else: the outcome this product must never have.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

import yaml

CORPUS = Path(__file__).with_name("instructions.yaml")


def classify(entry: dict) -> tuple[str, str]:
    """(outcome, detail) for one corpus entry: outcome is correct, refused or wrong."""
    from rpg.schema.builtin import ParseError, parse
    from rpg.schema.feasibility import InfeasibleTask, check_feasibility
    from rpg.schema.meaning import matches, meaning

    try:
        schema = check_feasibility(parse(entry["text"]))
    except (ParseError, InfeasibleTask) as exc:
        return "refused", str(exc).splitlines()[0]
    except Exception as exc:  # a crash is neither a refusal nor a task: count it as wrong
        return "wrong", f"crash: {type(exc).__name__}: {exc}"[:160]
    got = meaning(schema)
    return ("correct" if matches(entry["meaning"], got) else "wrong"), "; ".join(got)


def run(show: str = "wrong") -> Counter:
    doc = yaml.safe_load(CORPUS.read_text())
    counts: Counter = Counter()
    by_source: dict[str, Counter] = {}
    for e in doc["instructions"]:
        outcome, detail = classify(e)
        counts[outcome] += 1
        by_source.setdefault(e["source"], Counter())[outcome] += 1
        if show in (outcome, "all"):
            print(f"[{outcome}] {e['text']}\n    expected: {e['meaning']}\n    got:      {detail[:160]}")
    n = sum(counts.values())
    print(f"\n{'source':16s} {'n':>4s} {'correct':>8s} {'refused':>8s} {'wrong':>6s}")
    for src, c in sorted(by_source.items()):
        print(f"{src:16s} {sum(c.values()):4d} {c['correct']:8d} {c['refused']:8d} {c['wrong']:6d}")
    print(f"{'total':16s} {n:4d} {counts['correct']:8d} {counts['refused']:8d} {counts['wrong']:6d}"
          f"   ({100 * counts['correct'] / n:.0f}% correct)")
    return counts


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--show", default="wrong", choices=["wrong", "refused", "correct", "all", "none"])
    sys.exit(1 if run(ap.parse_args().show)["wrong"] else 0)
