"""Run the corpus through the builtin front end and print correct / refused / wrong, per split.

Usage: ``.venv/bin/python tests/corpus/run_corpus.py [--split dev|unseen|all] [--show wrong|refused|correct|all|none]``

An instruction is *correct* when the schema pass (parser + feasibility) gives a task whose
meaning (:func:`rpg.schema.meaning.meaning`) matches the corpus entry, *refused* when it
raises ParseError / InfeasibleTask (the message names what it could not place), and *wrong*
when it gives a task that means something else: the outcome this product must never have.

Two splits (``splits.yaml``): the development split (``instructions.yaml``) and the UNSEEN split
(``unseen.yaml``), frozen by source before the parser's output on it was looked at. For the
unseen split the runner checks the file's SHA-256 against ``splits.yaml`` (it refuses to report
when they differ, so a later edit shows) and prints only counts per source and failure
*classes*, never an instruction's text or the parser's message (``--show`` is for the
development split only).

Must-refuse entries (``meaning: none (...)``, with ``refuse: <class>``) are counted apart:
refused for the right reason (the message names the class of problem, not just an unknown
word), refused for another reason, or compiled (a silent error).
"""

from __future__ import annotations

import argparse
import hashlib
import re
import sys
from collections import Counter
from pathlib import Path

import yaml

HERE = Path(__file__).parent
CORPUS = HERE / "instructions.yaml"  # the development split
UNSEEN = HERE / "unseen.yaml"
# Sets written for the project by helpers that had not read rpg (see each file's header): name -> (file, label).
STRANGER_SETS = {
    "stranger": ("stranger.yaml", "STRANGER set (stranger.yaml, development material)"),
    "stranger2": ("stranger2.yaml", "STRANGER set 2 (stranger2.yaml, development material)"),
    "stranger3": ("stranger3.yaml", "STRANGER set 3 (stranger3.yaml, development material)"),
    "stranger4": ("stranger4.yaml", "STRANGER set 4 (stranger4.yaml, HELD OUT: report aggregates only)"),
    "stranger5": ("stranger5.yaml", "STRANGER set 5 (stranger5.yaml, development material)"),
    "stranger6": ("stranger6.yaml", "STRANGER set 6 (stranger6.yaml, development material)"),
    "stranger7": ("stranger7.yaml", "STRANGER set 7 (stranger7.yaml, development material)"),
    "stranger8": ("stranger8.yaml", "STRANGER set 8 (stranger8.yaml, development material)"),
    "stranger9": ("stranger9.yaml", "STRANGER set 9 (stranger9.yaml, development material)"),
    "stranger10": ("stranger10.yaml", "STRANGER set 10 (stranger10.yaml, development material)"),
    "stranger11": ("stranger11.yaml", "STRANGER set 11 (stranger11.yaml, development material)"),
    "stranger12": ("stranger12.yaml", "STRANGER set 12 (stranger12.yaml, development material)"),
    "stranger13": ("stranger13.yaml", "STRANGER set 13 (stranger13.yaml, development material)"),
    "stranger14": ("stranger14.yaml", "STRANGER set 14 (stranger14.yaml, development material)"),
    "stranger15": ("stranger15.yaml", "STRANGER set 15 (stranger15.yaml, HELD OUT: report aggregates only)"),
    "stranger16": ("stranger16.yaml", "STRANGER set 16 (stranger16.yaml, development material)"),
    "stranger17": ("stranger17.yaml", "STRANGER set 17 (stranger17.yaml, development material)"),
    "stranger18": ("stranger18.yaml", "STRANGER set 18 (stranger18.yaml, development material)"),
    "stranger19": ("stranger19.yaml", "STRANGER set 19 (stranger19.yaml, development material)"),
    "stranger20": ("stranger20.yaml", "STRANGER set 20 (stranger20.yaml, development material)"),
    "stranger21": ("stranger21.yaml", "STRANGER set 21 (stranger21.yaml, HELD OUT: report aggregates only)"),
    "stranger22": ("stranger22.yaml", "STRANGER set 22 (stranger22.yaml, development material)"),
    "stranger23": ("stranger23.yaml", "STRANGER set 23 (stranger23.yaml, development material)"),
    "stranger24": ("stranger24.yaml", "STRANGER set 24 (stranger24.yaml, development material, first run at the end of the seventeenth session)"),
    "stranger25": ("stranger25.yaml", "STRANGER set 25 (stranger25.yaml, development material)"),
    "stranger26": ("stranger26.yaml", "STRANGER set 26 (stranger26.yaml, development material, first run at the end of the eighteenth session)"),
    "stranger27": ("stranger27.yaml", "STRANGER set 27 (stranger27.yaml, development material)"),
    "stranger28": ("stranger28.yaml", "STRANGER set 28 (stranger28.yaml, development material, first run at the twentieth session's start)"),
    "stranger29": ("stranger29.yaml", "STRANGER set 29 (stranger29.yaml, development material, read from the twentieth session's middle)"),
    "stranger30": ("stranger30.yaml", "STRANGER set 30 (stranger30.yaml, development material, read from the twenty-first session's start)"),
    "stranger31": ("stranger31.yaml", "STRANGER set 31 (stranger31.yaml, development material, read from the twenty-second session's start)"),
    "stranger32": ("stranger32.yaml", "STRANGER set 32 (stranger32.yaml, development material, read from the twenty-third session's start)"),
    "stranger33": ("stranger33.yaml", "STRANGER set 33 (stranger33.yaml, transfer measure of the twenty-third session's start: aggregates only; a helper reported its failure classes mid-session)"),
    "stranger34": ("stranger34.yaml", "STRANGER set 34 (stranger34.yaml, development material, read from the twenty-fourth session's start)"),
    "stranger35": ("stranger35.yaml", "STRANGER set 35 (stranger35.yaml, transfer measure of the twenty-fourth session; development material, read from the twenty-fifth session's start)"),
    "stranger36": ("stranger36.yaml", "STRANGER set 36 (stranger36.yaml, transfer measure of the twenty-fifth session; development material, read from the twenty-sixth session's start)"),
    "stranger37": ("stranger37.yaml", "STRANGER set 37 (stranger37.yaml, transfer measure of the twenty-sixth session; development material, read from the twenty-seventh session's start)"),
    "stranger38": ("stranger38.yaml", "STRANGER set 38 (stranger38.yaml, transfer measure of the twenty-seventh session; development material from the twenty-eighth)"),
    "stranger39": ("stranger39.yaml", "STRANGER set 39 (stranger39.yaml, transfer measure of the twenty-eighth session; development material from the twenty-ninth)"),
    "stranger40": ("stranger40.yaml", "STRANGER set 40 (stranger40.yaml, transfer measure of the twenty-ninth session; development material from the thirtieth)"),
    "stranger41": ("stranger41.yaml", "STRANGER set 41 (stranger41.yaml, transfer measure of the thirtieth session; development material from the thirty-first)"),
    "stranger42": ("stranger42.yaml", "STRANGER set 42 (stranger42.yaml, transfer measure of the thirty-first session; development material from the thirty-second)"),
    "stranger43": ("stranger43.yaml", "STRANGER set 43 (stranger43.yaml, transfer measure of the thirty-second session: aggregates only; abstract classes reported by a helper mid-session)"),
    "stranger44": ("stranger44.yaml", "STRANGER set 44 (stranger44.yaml, written during the thirty-second session, measured at its end: aggregates only)"),
    "stranger45": ("stranger45.yaml", "STRANGER set 45 (stranger45.yaml, written at the start of the thirty-third session: aggregates only)"),
    "stranger46": ("stranger46.yaml", "STRANGER set 46 (stranger46.yaml, written at the start of the thirty-fourth session: aggregates only)"),
    "stranger47": ("stranger47.yaml", "STRANGER set 47 (stranger47.yaml, written during the thirty-fourth session; development material from the thirty-fifth)"),
    "stranger48": ("stranger48.yaml", "STRANGER set 48 (stranger48.yaml, written at the start of the thirty-fifth session; its classes reported at that session's end: not clean)"),
    "stranger49": ("stranger49.yaml", "STRANGER set 49 (stranger49.yaml, transfer measure of the thirty-sixth session; development material from the thirty-seventh)"),
    "stranger50": ("stranger50.yaml", "STRANGER set 50 (stranger50.yaml, transfer measure of the thirty-seventh session; development material from the thirty-eighth)"),
    "stranger51": ("stranger51.yaml", "STRANGER set 51 (stranger51.yaml, transfer measure of the thirty-eighth session; development material from the thirty-ninth)"),
    "stranger52": ("stranger52.yaml", "STRANGER set 52 (stranger52.yaml, transfer measure of the thirty-ninth session; development material from the fortieth)"),
    "stranger53": ("stranger53.yaml", "STRANGER set 53 (stranger53.yaml, transfer measure of the fortieth session; development material from the forty-first)"),
    "stranger54": ("stranger54.yaml", "STRANGER set 54 (stranger54.yaml, transfer measure of the forty-first session; development material from the forty-second)"),
    "stranger55": ("stranger55.yaml", "STRANGER set 55 (stranger55.yaml, transfer measure of the forty-second session; development material from the forty-third)"),
    "stranger56": ("stranger56.yaml", "STRANGER set 56 (stranger56.yaml, transfer measure of the forty-third session; development material from the forty-fourth)"),
    "stranger57": ("stranger57.yaml", "STRANGER set 57 (stranger57.yaml, transfer measure of the forty-fourth session; development material from the forty-fifth)"),
    "stranger58": ("stranger58.yaml", "STRANGER set 58 (stranger58.yaml, transfer measure of the forty-fifth session; development material from the forty-sixth)"),
    "stranger59": ("stranger59.yaml", "STRANGER set 59 (stranger59.yaml, transfer measure of the forty-sixth session; development material from the forty-seventh)"),
    "stranger60": ("stranger60.yaml", "STRANGER set 60 (stranger60.yaml, transfer measure of the forty-seventh session; development material from the forty-eighth)"),
    "stranger61": ("stranger61.yaml", "STRANGER set 61 (stranger61.yaml, transfer measure of the forty-eighth session; development material from the forty-ninth)"),
    "stranger62": ("stranger62.yaml", "STRANGER set 62 (stranger62.yaml, transfer measure of the forty-ninth session; development material from the fiftieth)"),
    "stranger63": ("stranger63.yaml", "STRANGER set 63 (stranger63.yaml, transfer measure of the fiftieth session; development material from the fifty-first)"),
    "stranger64": ("stranger64.yaml", "STRANGER set 64 (stranger64.yaml, written at the start of the fifty-first session: aggregates only)"),
}
SPLITS = HERE / "splits.yaml"

# What a refusal message must say to be refused "for the right reason", per must-refuse class.
REASON_WORDS = {
    "no_goal": r"no goal|without a goal|goal place|says? (?:where|what)|no end state",
    "question": r"\bquestions?\b",
    "action": r"action|cannot (?:rotate|cut|hide|sweep|turn)|verb",
    "object": r"has no|lacks|no such|does not have|not (?:in|part of) (?:the|this) (?:domain|task|table)|only (?:cubes|blocks)",
    "shape": r"shape|has no|lacks|does not have|only (?:cubes|blocks)",
    "size": r"\bsizes?\b|larger|smaller|all (?:cubes|blocks) are the same",
    "negation": r"negat",
    "quantity": r"quantit|distance|amount|measure",
    "reference": r"refer|earlier|previous|current (?:scene|state)|history|before",
    "condition": r"condition|about time",  # "wait ten seconds, then ...": a goal bounded by time is a condition too
    "time": r"about time|clock|duration",
    "contradiction": r"contradict|cannot (?:both|end in)",
    "colour": r"unknown colou?r|not (?:a|one of the) colou?rs?|colou?r \S+ is not|palette",
}
HELD_OUT = ("unseen", "stranger4", "stranger15", "stranger21")  # read by this runner only; nobody looks at their cases or failures
UNKNOWN_WORD = re.compile(r"^could not parse ")


class SplitFrozenError(RuntimeError):
    """unseen.yaml does not have the SHA-256 that splits.yaml recorded when the split was frozen."""


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def load_split(name: str) -> list[dict]:
    """The entries of one split ('dev' or 'unseen'); the unseen file must match its frozen hash."""
    if name == "dev":
        return yaml.safe_load(CORPUS.read_text())["instructions"]
    if name in STRANGER_SETS:
        path = HERE / STRANGER_SETS[name][0]
        return [{**e, "source": name} for e in yaml.safe_load(path.read_text())["instructions"]]
    splits = yaml.safe_load(SPLITS.read_text())
    want, got = splits["unseen"]["sha256"], sha256(UNSEEN)
    if want != got:
        raise SplitFrozenError(f"unseen.yaml has SHA-256 {got}, splits.yaml froze {want}: the unseen split was edited; "
                               "an edited split is no longer unseen (see splits.yaml)")
    return yaml.safe_load(UNSEEN.read_text())["instructions"]


def classify(entry: dict) -> tuple[str, str]:
    """(outcome, detail) for one corpus entry: outcome is correct, refused or wrong."""
    from rpg.schema.builtin import ParseError, parse
    from rpg.schema.feasibility import InfeasibleTask, check_feasibility
    from rpg.schema.meaning import completions, matches, matches_alternatives, meaning

    try:
        schema = check_feasibility(parse(entry["text"]))
    except (ParseError, InfeasibleTask) as exc:
        return "refused", str(exc).splitlines()[0]
    except Exception as exc:  # a crash is neither a refusal nor a task: count it as wrong
        return "wrong", f"crash: {type(exc).__name__}: {exc}"[:160]
    got = meaning(schema)
    free = entry.get("order") == "any" and "?" not in str(entry["meaning"])  # no end named: the cubes as a set
    readings = [got] + ([_without_spelled_reading(got)] if _spelled_reading_unwritten(entry, got) else [])
    if len(completions(got)) > 1:  # a line free but for an end: right only where the alternatives are its completions
        if not matches_alternatives(list(alternatives(entry)), got):
            return "wrong", "; ".join(got)
    elif not any(matches(_unordered(m), [_unordered(a) for a in g]) if free else matches(m, g)
                 for m in alternatives(entry) for g in readings):
        return "wrong", "; ".join(got)
    if entry.get("order") == "any" and any(type(p).__name__ == "Stack" for p in schema.goal_predicate().walk()):
        return "wrong", "demands what no word says: an order of a stack the words leave free"
    from rpg.schema.citations import REFUSED_WHEN_UNCITED, uncited

    unsaid = [c.line for c in uncited(schema) if c.kind in REFUSED_WHEN_UNCITED]
    if unsaid:  # the meaning notation cannot show it (an order of a stack, a line's axis): G demands it unsaid
        return "wrong", "demands what no word says: " + "; ".join(unsaid)
    return "correct", "; ".join(got)


_SPELL_WORD_RE = re.compile(r"\b(?:spell\w*|reads?|reading)\b", re.IGNORECASE)
_READS_ATOM_RE = re.compile(r"reads\(([^;()]+);")


def _spelled_reading_unwritten(entry: dict, got: list[str]) -> bool:
    """Whether an entry's text spells a word with its cubes ("Spell DOG from left to right with the letter cubes") while
    none of its meanings writes the reading (``reads(...)``: annotators the notation was not shown to wrote the line or
    tower alone), and each reading compiled reads the cubes of a line or tower compiled, in its order or reversed: the
    word's reading is what "spell" says, not a demand beyond the words."""
    if not _SPELL_WORD_RE.search(entry["text"]) or any("reads(" in m for m in alternatives(entry)):
        return False
    structures = [re.sub(r"^\w+(?:\[\w+\])?\(([^()]*)\)(?:@\w+)?$", r"\1", a) for a in got if re.match(r"(?:line|stack)\b", a)]
    reads = [m.group(1) for a in got if (m := _READS_ATOM_RE.match(a))]
    return bool(reads) and all(r in structures or ",".join(reversed(r.split(","))) in structures for r in reads)


def _without_spelled_reading(got: list[str]) -> list[str]:
    """``got`` without its reading atoms (:func:`_spelled_reading_unwritten`)."""
    return [a for a in got if not a.startswith("reads(")]


def _unordered(meaning_text: str) -> str:
    """``meaning_text`` with each stack's cubes sorted: for entries whose words leave the order free."""
    return re.sub(r"\bstack\(([^()]*)\)", lambda m: "stack(" + ",".join(sorted(m.group(1).split(","))) + ")", meaning_text)


def alternatives(entry: dict) -> list[str]:
    """The meanings an entry accepts: one, or a list where more than one reading (or spelling)
    is right (the stranger sets' annotators give lists where the notation's spelling was a guess)."""
    m = entry["meaning"]
    return list(m) if isinstance(m, list) else [m]


def must_refuse(entry: dict) -> bool:
    return alternatives(entry)[0].strip().startswith("none")


def refusal_reason_ok(entry: dict, message: str) -> bool:
    """Whether a refusal of a must-refuse entry names its real reason (not only an unknown word)."""
    words = REASON_WORDS.get(entry.get("refuse", ""), r"(?!)")
    return not UNKNOWN_WORD.search(message) and re.search(words, message, re.IGNORECASE) is not None


def _atoms(text: str) -> list[str]:
    return [a.strip() for a in re.split(r";\s+(?![^()]*\))", text) if a.strip()]


def _objects(atoms: list[str]) -> list[str]:
    """The object descriptors of some atoms (wildcards kept as written)."""
    out = []
    for a in atoms:
        body = a[a.find("(") + 1:a.rfind(")")] if "(" in a else ""
        body = re.sub(r"^\d+x\d+:", "", body)
        out += [t for t in re.split(r"[,;|]", body) if t and "=" not in t]
    return out


def failure_class(entry: dict, outcome: str, detail: str) -> str | None:
    """A failure's class, worded so that it never repeats the instruction or the parser's message."""
    if outcome == "correct":
        return None
    if outcome == "refused":
        if must_refuse(entry):
            return "refused (must-refuse): right reason" if refusal_reason_ok(entry, detail) else \
                "refused (must-refuse): other reason"
        if UNKNOWN_WORD.search(detail):
            return "refused: unknown word"
        if detail.startswith("could not find a task"):
            return "refused: no task found"
        if "contradict" in detail:
            return "refused: read as a contradiction"
        if re.search(r"the most a task holds|do not fit|too many objects|needs \d+ cubes", detail):
            return "refused: size limit"
        if re.search(r"has no place in|read \"", detail):
            return "refused: read, but a mention had no place"
        if re.search(r"reach|feasib|stable|support|collid", detail, re.IGNORECASE):
            return "refused: infeasible"
        return "refused: other"
    if detail.startswith("crash"):
        return "crash"
    if must_refuse(entry):
        return "wrong: compiled a must-refuse text"
    if detail.startswith("demands what no word says"):
        return "wrong: demands what no word says"
    want, got = _atoms(alternatives(entry)[0]), _atoms(detail)
    if any(a.startswith("extra(") for a in got):
        return "wrong: content invented (extra object)"
    heads = sorted(a.split("(")[0] for a in want)
    if heads != sorted(a.split("(")[0] for a in got):
        if len(want) != len(got):
            return "wrong: relation/structure count"
        return "wrong: relation/structure kind"
    if any("@" in a for a in want) != any("@" in a for a in got) or \
            sorted(re.findall(r"@(\w+)", alternatives(entry)[0])) != sorted(re.findall(r"@(\w+)", detail)):
        return "wrong: place lost or changed"
    ow, og = _objects(want), _objects(got)
    if len(ow) != len(og) and not any("*" in o for o in ow):
        return "wrong: count"
    concrete = [o for o in ow if "?" not in o and "*" not in o]
    if not (Counter(concrete) <= Counter(og)):
        return "wrong: colour/label lost or changed"
    if Counter(concrete) == Counter(og) or any("?" in o for o in ow):
        return "wrong: order or roles"
    return "wrong: other"


def _table(title: str, rows: dict[str, Counter], total: Counter) -> None:
    print(f"\n{title}")
    print(f"{'source':18s} {'n':>4s} {'correct':>8s} {'refused':>8s} {'wrong':>6s} {'% correct':>10s}")
    for src, c in sorted(rows.items()):
        n = sum(c[k] for k in ("correct", "refused", "wrong"))
        print(f"{src:18s} {n:4d} {c['correct']:8d} {c['refused']:8d} {c['wrong']:6d} {100 * c['correct'] / n:9.0f}%")
    n = sum(total[k] for k in ("correct", "refused", "wrong"))
    if n:
        print(f"{'total':18s} {n:4d} {total['correct']:8d} {total['refused']:8d} {total['wrong']:6d}"
              f" {100 * total['correct'] / n:9.0f}%")


def run_split(name: str, show: str = "none") -> Counter:
    """Run one split and print its tables; returns outcome counts (plus must-refuse and class counts)."""
    entries = load_split(name)
    if name == "unseen":
        show = "none"  # never print an unseen instruction or message
    counts: Counter = Counter()
    by_source: dict[str, Counter] = {}
    classes: Counter = Counter()
    mr: Counter = Counter()
    plain: Counter = Counter()  # outcomes of the texts the domain can say (issue 30's "plain instructions")
    by_refuse: dict[str, Counter] = {}  # must-refuse class -> verdicts
    for e in entries:
        outcome, detail = classify(e)
        counts[outcome] += 1
        by_source.setdefault(e["source"], Counter())[outcome] += 1
        cls = failure_class(e, outcome, detail)
        if cls:
            classes[cls] += 1
        if not must_refuse(e):
            plain[outcome] += 1
        if must_refuse(e):
            mr["n"] += 1
            if outcome == "refused":
                verdict = "right reason" if refusal_reason_ok(e, detail) else "other reason"
            else:
                verdict = "compiled"
            mr[verdict] += 1
            by_refuse.setdefault(e.get("refuse", "?"), Counter())[verdict] += 1
        if show in (outcome, "all"):
            print(f"[{outcome}] {e['text']}\n    expected: {e['meaning']}\n    got:      {detail[:160]}"
                  + (f"\n    class:    {cls}" if cls else ""))
    label = {"dev": "DEVELOPMENT split (instructions.yaml)", "unseen": "UNSEEN split (unseen.yaml, frozen)",
             **{k: v[1] for k, v in STRANGER_SETS.items()}}[name]
    _table(f"{label}: {len(by_source)} sources", by_source, counts)
    n_plain = sum(plain.values())
    if n_plain:
        print(f"plain instructions (the domain can say them): {n_plain}; right {plain['correct']} "
              f"({100 * plain['correct'] / n_plain:.0f}%), refused {plain['refused']}, silently wrong {plain['wrong']}")
    print(f"must-refuse: {mr['n']} texts; refused for the right reason {mr['right reason']}, "
          f"for another reason {mr['other reason']}, compiled {mr['compiled']}")
    for kind, c in sorted(by_refuse.items()):
        print(f"  must-refuse {kind:14s} {sum(c.values()):3d}: right reason {c['right reason']}, "
              f"other reason {c['other reason']}, compiled {c['compiled']}")
    print("failure classes:" + ("" if classes else " none"))
    for cls, k in sorted(classes.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"  {k:4d}  {cls}")
    counts.update({f"must-refuse {k}": v for k, v in mr.items()})
    counts.update({f"plain {k}": v for k, v in plain.items()})
    counts.update({f"class {k}": v for k, v in classes.items()})
    return counts


def run(show: str = "wrong", split: str = "dev") -> Counter:
    totals: Counter = Counter()
    for name in (["dev", "unseen"] if split == "all" else [split]):
        c = run_split(name, show)
        totals.update({k: v for k, v in c.items() if k in ("correct", "refused", "wrong")})
    if split == "all":
        n = sum(totals.values())
        print(f"\nall splits: {n} instructions, {totals['correct']} correct, {totals['refused']} refused, "
              f"{totals['wrong']} wrong ({100 * totals['correct'] / n:.0f}% correct)")
    return totals


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--split", default="dev", choices=["dev", "unseen", *STRANGER_SETS, "all"])
    ap.add_argument("--show", default=None, choices=["wrong", "refused", "correct", "all", "none"],
                    help="print these development-split instructions (default: wrong); not allowed for --split unseen")
    args = ap.parse_args(argv)
    if args.split in HELD_OUT and args.show not in (None, "none"):
        ap.error(f"--show is for development material: {args.split} is held out and reports aggregates only")
    try:
        counts = run(args.show or "wrong", args.split)
    except SplitFrozenError as exc:
        print(f"refusing to report the unseen split: {exc}", file=sys.stderr)
        return 2
    return 1 if counts["wrong"] else 0


if __name__ == "__main__":
    sys.exit(main())
