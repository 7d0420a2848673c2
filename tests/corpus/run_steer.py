"""Run the steering cases through ``rpg steer`` and print right / refused / silently wrong, per split.

Usage: ``.venv/bin/python tests/corpus/run_steer.py [--split dev|unseen] [--show wrong|refused|right|all|none]
[--jobs N] [--ids s003,s021]``

A case (``steer_dev.yaml`` / ``steer_unseen.yaml``) is a base instruction and one to three edits.
For each case the base is compiled into a fresh temporary directory (``compile_instruction``) and
made a family; each edit is applied with :func:`rpg.steer.steer`, the Python entry point that
``rpg steer`` calls (same arguments, builtin front end). The meaning
(:func:`rpg.schema.meaning.meaning`) of the version the edit leaves at the family's head is
compared with the expected one (:func:`rpg.schema.meaning.matches`), and the intent it was
classified as with the expected category. An edit's outcome is one of

- ``right``: compiled, the expected meaning and a category the case allows; for a must-refuse
  edit (``meaning: none (...)``), refused for its real reason (the message names the class, as
  in ``run_corpus.py``) with the family left as it was;
- ``category wrong``: the expected meaning, another category;
- ``refused wrongly``: an edit the domain can express was refused (exit 2);
- ``refused (must-refuse): other reason``: a must-refuse edit refused, but not for its reason;
- ``silently wrong``: a new version was recorded whose meaning differs (or a must-refuse edit
  compiled): what the product must never do;
- ``error``: exit 1 (validation failed after repair), a traceback, or a refused edit that changed
  the family: bugs.

A case is right when all its edits are; otherwise it takes the class of its first edit that is
not right, and the edits after it are ``not reached`` (they would build on a wrong version). The
base must compile to ``base_meaning`` first; a base refused or compiled wrong is its own class
(``base: ...``), a failure of the parser rather than of steering, and the case is not steered.

Three notation rules, where :func:`~rpg.schema.meaning.meaning` writes one thing two ways (they
change no verdict on what a task demands): a ``reads(...)`` atom (a word spelled by letter cubes
in a direction) is dropped when a line or stack atom lists the same cubes in that direction, as
it restates that atom's order (the corpus notation writes a spelled word
``line[left_to_right](C,A,T)``); a line of identical cubes is unordered whatever its direction
(``line[left_to_right](x,x,x)`` = ``line(x,x,x)``); and a pyramid or wall of identical cubes may
be written without its layers (``pyramid(x,x,x|x,x|x)`` = ``pyramid(x,x,x,x,x,x)``), because
meaning() lists layers only when their colours are judged.

The UNSEEN split (``steer_unseen.yaml``) was written and split off before the runner or the
steering code was run on any case. Its SHA-256 is frozen in ``splits.yaml`` (``steering:``); the
runner refuses to report it (exit 2) when the file differs, and for it prints only counts and
failure classes, never an edit, a base, an expected meaning or a message (``--show`` and
``--ids`` are for the development split only).

Cases run in parallel in at most 2 worker processes (``--jobs``); each in its own temporary
directory, so nothing is left behind.
"""

from __future__ import annotations

import argparse
import hashlib
import multiprocessing
import re
import sys
import tempfile
import time
import traceback
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path

import yaml

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))
from run_corpus import REASON_WORDS, UNKNOWN_WORD, failure_class  # noqa: E402

# Development sets: name -> (file, label). The stranger sets were written by helpers that had not read rpg.
DEVELOPMENT = {
    "dev": ("steer_dev.yaml", "DEVELOPMENT steering split (steer_dev.yaml)"),
    "stranger": ("steer_stranger.yaml", "STRANGER steering set (steer_stranger.yaml, development material)"),
    "stranger2": ("steer_stranger2.yaml", "STRANGER steering set 2 (steer_stranger2.yaml, development material)"),
    "stranger3": ("steer_stranger3.yaml", "STRANGER steering set 3 (steer_stranger3.yaml, development material)"),
    "stranger4": ("steer_stranger4.yaml", "STRANGER steering set 4 (steer_stranger4.yaml, development material)"),
    "stranger5": ("steer_stranger5.yaml", "STRANGER steering set 5 (steer_stranger5.yaml, development material)"),
    "stranger6": ("steer_stranger6.yaml", "STRANGER steering set 6 (steer_stranger6.yaml, development material)"),
    "stranger7": ("steer_stranger7.yaml", "STRANGER steering set 7 (steer_stranger7.yaml, development material)"),
    "stranger8": ("steer_stranger8.yaml", "STRANGER steering set 8 (steer_stranger8.yaml, development material)"),
    "stranger9": ("steer_stranger9.yaml", "STRANGER steering set 9 (steer_stranger9.yaml, development material)"),
    "stranger10": ("steer_stranger10.yaml", "STRANGER steering set 10 (steer_stranger10.yaml, development material)"),
    "stranger11": ("steer_stranger11.yaml", "STRANGER steering set 11 (steer_stranger11.yaml, development material)"),
    "stranger12": ("steer_stranger12.yaml", "STRANGER steering set 12 (steer_stranger12.yaml, development material)"),
    "stranger13": ("steer_stranger13.yaml", "STRANGER steering set 13 (steer_stranger13.yaml, development material)"),
    "stranger14": ("steer_stranger14.yaml", "STRANGER steering set 14 (steer_stranger14.yaml, development material)"),
    "stranger15": ("steer_stranger15.yaml", "STRANGER steering set 15 (steer_stranger15.yaml, development material)"),
    "stranger16": ("steer_stranger16.yaml", "STRANGER steering set 16 (steer_stranger16.yaml, development material, first run at the end of the seventeenth session)"),
    "stranger17": ("steer_stranger17.yaml", "STRANGER steering set 17 (steer_stranger17.yaml, development material)"),
    "stranger18": ("steer_stranger18.yaml", "STRANGER steering set 18 (steer_stranger18.yaml, development material)"),
    "stranger19": ("steer_stranger19.yaml", "STRANGER steering set 19 (steer_stranger19.yaml, transfer measure of the thirty-first session; development material from the thirty-sixth)"),
    "stranger20": ("steer_stranger20.yaml", "STRANGER steering set 20 (steer_stranger20.yaml, transfer measure of the thirty-sixth session; development material from the thirty-seventh)"),
    "stranger21": ("steer_stranger21.yaml", "STRANGER steering set 21 (steer_stranger21.yaml, transfer measure of the thirty-seventh session; development material from the thirty-eighth)"),
    "stranger22": ("steer_stranger22.yaml", "STRANGER steering set 22 (steer_stranger22.yaml, transfer measure of the thirty-eighth session; development material from the thirty-ninth)"),
    "stranger23": ("steer_stranger23.yaml", "STRANGER steering set 23 (steer_stranger23.yaml, transfer measure of the thirty-ninth session; development material from the fortieth)"),
    "stranger24": ("steer_stranger24.yaml", "STRANGER steering set 24 (steer_stranger24.yaml, transfer measure of the fortieth session; development material from the forty-first)"),
    "stranger25": ("steer_stranger25.yaml", "STRANGER steering set 25 (steer_stranger25.yaml, transfer measure of the forty-first session; development material from the forty-second)"),
    "stranger26": ("steer_stranger26.yaml", "STRANGER steering set 26 (steer_stranger26.yaml, transfer measure of the forty-second session; development material from the forty-third)"),
    "stranger27": ("steer_stranger27.yaml", "STRANGER steering set 27 (steer_stranger27.yaml, transfer measure of the forty-third session; development material from the forty-fourth)"),
    "stranger28": ("steer_stranger28.yaml", "STRANGER steering set 28 (steer_stranger28.yaml, transfer measure of the forty-fourth session; development material from the forty-fifth)"),
    "stranger29": ("steer_stranger29.yaml", "STRANGER steering set 29 (steer_stranger29.yaml, transfer measure of the forty-fifth session; development material from the forty-sixth)"),
    "stranger30": ("steer_stranger30.yaml", "STRANGER steering set 30 (steer_stranger30.yaml, transfer measure of the forty-seventh session; development material from the forty-eighth)"),
    "stranger31": ("steer_stranger31.yaml", "STRANGER steering set 31 (steer_stranger31.yaml, written at the start of the forty-seventh session: aggregates only)"),
    "stranger32": ("steer_stranger32.yaml", "STRANGER steering set 32 (steer_stranger32.yaml, transfer measure of the forty-eighth session; development material from the forty-ninth)"),
    "stranger33": ("steer_stranger33.yaml", "STRANGER steering set 33 (steer_stranger33.yaml, written at the start of the forty-ninth session: aggregates only)"),
    "stranger34": ("steer_stranger34.yaml", "STRANGER steering set 34 (steer_stranger34.yaml, written at the start of the fiftieth session: aggregates only)"),
    "stranger35": ("steer_stranger35.yaml", "STRANGER steering set 35 (steer_stranger35.yaml, written at the start of the fifty-first session: aggregates only)"),
}
UNSEEN = HERE / "steer_unseen.yaml"
SPLITS = HERE / "splits.yaml"
CATEGORIES = ("tweak", "extend", "modify", "pivot", "fresh")
MAX_JOBS = 2

# run_corpus's reason words, with the ways a steering refusal names an edit's reason; a version or
# object the family does not have is a reference to something that does not exist.
STEER_REASON_WORDS = dict(REASON_WORDS)
STEER_REASON_WORDS["reference"] = (REASON_WORDS["reference"]
                                   + r"|no (?:such )?version|no earlier version|there is no|does not exist|"
                                     r"(?:has|have) no \w+ (?:block|cube)|not (?:in|part of) the (?:task|tower|family)|"
                                     r"has versions v\d")
STEER_REASON_WORDS["quantity"] = REASON_WORDS["quantity"] + r"|no count|how many|as many"

RIGHT = "right"
ORDER = ["right", "category wrong", "refused wrongly", "refused (must-refuse): other reason", "silently wrong",
         "error", "base: refused", "base: wrong", "base: error"]


class SplitFrozenError(RuntimeError):
    """steer_unseen.yaml does not have the SHA-256 that splits.yaml recorded when it was frozen."""


@dataclass
class Step:
    """What one edit did."""

    edit: str
    outcome: str = "not reached"  # one of ORDER, or "not reached"
    failure: str = ""  # a failure class, worded without the case's text
    intent: str = ""
    got: list[str] = field(default_factory=list)
    message: str = ""  # a refusal's or error's first line


@dataclass
class CaseResult:
    id: str
    outcome: str  # "right" or the first failing edit's (or the base's) outcome
    failure: str = ""
    base_got: list[str] = field(default_factory=list)
    base_message: str = ""
    steps: list[Step] = field(default_factory=list)
    seconds: float = 0.0


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def load_split(name: str) -> list[dict]:
    """The cases of one split ('dev' or 'unseen'); the unseen file must match its frozen hash."""
    if name in DEVELOPMENT:
        return yaml.safe_load((HERE / DEVELOPMENT[name][0]).read_text())["cases"]
    want, got = yaml.safe_load(SPLITS.read_text())["steering"]["unseen"]["sha256"], sha256(UNSEEN)
    if want != got:
        raise SplitFrozenError(f"steer_unseen.yaml has SHA-256 {got}, splits.yaml froze {want}: the unseen steering "
                               "split was edited; an edited split is no longer unseen (see splits.yaml)")
    return yaml.safe_load(UNSEEN.read_text())["cases"]


# -- judging ---------------------------------------------------------------------------


def must_refuse(step: dict) -> bool:
    m = step["meaning"]
    return isinstance(m, str) and m.strip().startswith("none")


def expected_meanings(step_or_case: dict, key: str = "meaning") -> list[str]:
    m = step_or_case[key]
    return list(m) if isinstance(m, list) else [m]


def expected_categories(step: dict) -> list[str]:
    c = step.get("category")
    return list(c) if isinstance(c, list) else ([c] if c else [])


def _body(atom: str) -> tuple[str, str]:
    head, _, rest = atom.partition("(")
    return head, rest[:-1] if rest.endswith(")") else rest


def _same_cubes_line(atom: str) -> str:
    """``line[d](x,x,x)`` -> ``line(x,x,x)``: an order over identical cubes says nothing."""
    head, body = _body(atom)
    if head.startswith("line[") and len(set(body.split(","))) == 1:
        return f"line({body})"
    return atom


def _flat_layers(atom: str) -> str:
    """``pyramid(x,x,x|x,x|x)`` -> ``pyramid(x,x,x,x,x,x)``: meaning() lists the layers of a pyramid or
    wall only when a layer's colours are judged, so one of identical cubes is written flat."""
    head, body = _body(atom)
    cubes = re.split(r"[,|]", body)
    if head in ("pyramid", "wall") and "|" in body and len(set(cubes)) == 1 and "?" not in body and "*" not in body:
        return f"{head}({','.join(cubes)})"
    return atom


def _grid_size(atom: str) -> str:
    """``grid[2x2](x,x|x,x)`` -> ``grid(2x2:x,x,x,x)``: a grid's size as meaning() writes it (the
    stranger sets guessed the size in brackets and the rows after '|')."""
    m = re.fullmatch(r"grid\[(\d+x\d+)\]\((.*)\)(@.*)?", atom)
    return f"grid({m.group(1)}:{m.group(2).replace('|', ',')}){m.group(3) or ''}" if m else atom


def _variants(expected: str) -> list[str]:
    atoms = [a.strip() for a in re.split(r";\s+(?![^()]*\))", expected) if a.strip()]
    flat = "; ".join(_grid_size(_flat_layers(_same_cubes_line(a))) for a in atoms)
    return [expected] if flat == "; ".join(atoms) else [expected, flat]


def normalise(got: list[str]) -> list[str]:
    """Drop a ``reads`` atom that restates the order of a line or stack atom over the same cubes;
    write an ordered line of identical cubes as an unordered one."""
    keep = []
    for a in got:
        a = _same_cubes_line(a)
        head, body = _body(a)
        if head == "reads":
            objs, _, args = body.partition(";")
            kv = dict(p.split("=", 1) for p in args.split(",") if "=" in p)
            d = kv.get("direction", "left_to_right")
            same = {f"line[{d}]({objs})"}
            if d == "bottom_to_top":
                same.add(f"stack({objs})")
            elif d == "top_to_bottom":
                same.add(f"stack({','.join(reversed(objs.split(',')))})")
            if any(b.split("@")[0] in same for b in got if b is not a):
                continue
        keep.append(a)
    return keep


def meaning_ok(expected: dict, got: list[str], key: str = "meaning") -> bool:
    from rpg.schema.meaning import completions, matches, matches_alternatives

    norm = normalise(got)
    if len(completions(norm)) > 1:  # a line free but for an end: right only where the alternatives are its completions
        return matches_alternatives([v for m in expected_meanings(expected, key) for v in _variants(m)], norm)
    return any(matches(v, norm) for m in expected_meanings(expected, key) for v in _variants(m))


def refusal_reason_ok(step: dict, message: str) -> bool:
    """Whether a refusal of a must-refuse edit names its real reason (not only an unknown word)."""
    words = STEER_REASON_WORDS.get(step.get("refuse", ""), r"(?!)")
    return not UNKNOWN_WORD.search(message) and re.search(words, message, re.IGNORECASE) is not None


def _objects(atoms: list[str]) -> Counter:
    out: Counter = Counter()
    for a in atoms:
        _, body = _body(re.sub(r"@\w+$", "", a))
        body = re.sub(r"^\d+x\d+:", "", body.split(";")[0] if a.startswith("reads") else body)
        out.update(t for t in re.split(r"[,;|]", body) if t and "=" not in t and "?" not in t and "*" not in t)
    return out


def wrong_class(step: dict, got: list[str], before: list[str] | None) -> str:
    """The class of a silently wrong edit, worded so that it never repeats the case's text."""
    norm = normalise(got)
    if before is not None and sorted(norm) == sorted(normalise(before)):
        return "silently wrong: edit had no effect (meaning unchanged)"
    want = expected_meanings(step)[0]
    if "extend" in expected_categories(step) and before is not None:
        if not (_objects(normalise(before)) <= _objects(norm)):
            return "silently wrong: addition applied as a replacement (earlier cubes lost)"
    base = failure_class({"meaning": want}, "wrong", "; ".join(norm))
    return "silently " + (base or "wrong: other")


# What a refusal message says, by the templates of rpg's parser and steering messages (most specific first).
REFUSAL_KINDS = [
    (UNKNOWN_WORD.pattern, "unknown word"),
    (r"refers to something|picks a cube by", "a reference to the task not resolved ('it', 'them', ...)"),
    (r"is an action the domain does not have", "the edit's verb read as an action"),
    (r"is a negation", "read as a negation"),
    (r"names an object the domain does not have", "read as an object the domain lacks"),
    (r"^could not find a task", "edit not read (no task found)"),
    (r"the family has versions|no earlier version", "version reference not resolved"),
    (r"has no cube matching", "the cube the edit names not found in the task"),
    (r"adds a second structure", "a second structure not supported"),
    (r"cannot turn a", "this change of structure not supported"),
    (r"the edit keeps a", "'keep' names another structure"),
    (r"added one by one|added beside", "an addition to this structure not supported"),
    (r"not a structure the builtin steering edits in place", "this task kind not editable in place"),
    (r"do not fit|smaller than|no base size|set by its dimensions|the most a task holds|too many|exceed",
     "size or count not supported"),
    (r"contradict", "read as a contradiction"),
    (r"reach|feasib|stable|support|collid", "infeasible"),
    (r'^read "', "read, but a mention had no place"),
    (r"^cannot make a task of", "read as out of domain (other)"),
]


def refusal_kind(message: str) -> str:
    """A refusal's kind, worded so that it never repeats the case's text or the message."""
    return next((kind for pat, kind in REFUSAL_KINDS if re.search(pat, message, re.IGNORECASE)), "other")


def judge_step(step: dict, *, refused: str | None = None, error: str | None = None, got: list[str] | None = None,
               intent: str = "", before: list[str] | None = None, family_changed: bool = False) -> tuple[str, str]:
    """(outcome, failure class) of one edit, from what steering did: refused with a message, an error,
    or a new version with meaning ``got`` and ``intent`` (``before``: the meaning it was applied to)."""
    if error is not None:
        return "error", f"error: {error}"
    if refused is not None:
        if family_changed:
            return "error", "error: a refused edit changed the family"
        if must_refuse(step):
            if refusal_reason_ok(step, refused):
                return RIGHT, ""
            return "refused (must-refuse): other reason", f"refused (must-refuse): other reason ({refusal_kind(refused)})"
        return "refused wrongly", "refused wrongly: " + refusal_kind(refused)
    assert got is not None
    if must_refuse(step):
        return "silently wrong", f"silently wrong: compiled a must-refuse edit ({step.get('refuse', '?')})"
    if not meaning_ok(step, got):
        return "silently wrong", wrong_class(step, got, before)
    cats = expected_categories(step)
    if cats and intent not in cats:
        return "category wrong", f"category wrong: {'/'.join(cats)} read as {intent or 'none'}"
    return RIGHT, ""


# -- running ---------------------------------------------------------------------------


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip()
    return text.splitlines()[0] if text else type(exc).__name__


def _is_refusal(exc: BaseException) -> bool:
    """Whether the CLI would end on it with exit 2 and one line (not exit 1, 3, 4 or a traceback)."""
    from rpg.errors import EXIT_BAD_INPUT, RpgError

    if isinstance(exc, RpgError):
        return exc.exit_code == EXIT_BAD_INPUT
    return isinstance(exc, ValueError)  # the CLI reports any ValueError as bad input (exit 2)


def run_case(case: dict) -> CaseResult:
    """Compile the base in a temporary directory, apply the edits in turn, judge each."""
    from rpg.compiler import compile_instruction
    from rpg.schema.meaning import meaning
    from rpg.steer import Family, create_family, steer

    t0 = time.monotonic()
    res = CaseResult(case["id"], "right", steps=[Step(s["edit"]) for s in case["steps"]])
    with tempfile.TemporaryDirectory(prefix="rpg-steer-") as tmp:
        try:
            base = compile_instruction(case["base"], Path(tmp), name="fam")
        except Exception as exc:  # noqa: BLE001 - a refusal or a crash of the base, both reported
            refused = _is_refusal(exc)
            res.outcome = "base: refused" if refused else "base: error"
            res.failure = res.outcome if refused else f"base: error: {type(exc).__name__}"
            res.base_message = _first_line(exc) if refused else traceback.format_exc(limit=-3)
            res.seconds = time.monotonic() - t0
            return res
        res.base_got = meaning(base.schema)
        if not base.valid:
            res.outcome, res.failure = "base: error", "base: error: exit 1 (validation failed)"
        elif not meaning_ok(case, res.base_got, "base_meaning"):
            res.outcome, res.failure = "base: wrong", "base: wrong"
        if res.outcome != RIGHT:
            res.seconds = time.monotonic() - t0
            return res
        fam = Family(create_family(base.path).path)
        before = res.base_got
        for spec, step in zip(case["steps"], res.steps, strict=True):
            history = (fam.path / "family.yaml").read_bytes()
            kw: dict = {}
            try:
                r = steer(fam.path, spec["edit"])
            except Exception as exc:  # noqa: BLE001
                if _is_refusal(exc):
                    step.message = _first_line(exc)
                    kw = {"refused": step.message,
                          "family_changed": (fam.path / "family.yaml").read_bytes() != history}
                else:
                    step.message = traceback.format_exc(limit=-3)
                    kw = {"error": f"{type(exc).__name__} (traceback)"}
            else:
                step.intent = r.intent
                if not r.valid:
                    step.message = "; ".join(r.notes)[:300]
                    kw = {"error": "exit 1 (validation failed after repair)", "intent": r.intent}
                else:
                    step.got = meaning(fam.schema(r.version))
                    kw = {"got": step.got, "intent": r.intent, "before": before}
            step.outcome, step.failure = judge_step(spec, **kw)
            if step.outcome != RIGHT:
                if res.outcome == RIGHT:
                    res.outcome, res.failure = step.outcome, step.failure
                if not (must_refuse(spec) and "refused" in kw):
                    break  # the family is not what the next edit expects
            elif step.got:
                before = step.got
    res.seconds = time.monotonic() - t0
    return res


def run_cases(cases: list[dict], jobs: int = MAX_JOBS) -> list[CaseResult]:
    jobs = max(1, min(jobs, MAX_JOBS))
    if jobs == 1 or len(cases) == 1:
        return [run_case(c) for c in cases]
    ctx = multiprocessing.get_context("spawn")
    with ctx.Pool(jobs) as pool:
        return pool.map(run_case, cases, chunksize=1)


# -- reporting -------------------------------------------------------------------------


def _show_case(case: dict, res: CaseResult) -> None:
    print(f"[{res.outcome}] {res.id}  base: {case['base']}")
    print(f"    base expected: {case['base_meaning']}")
    print(f"    base got:      {'; '.join(res.base_got)}" + (f"\n    base message:  {res.base_message[:300]}"
                                                             if res.base_message else ""))
    for spec, step in zip(case["steps"], res.steps, strict=True):
        cat = "/".join(expected_categories(spec)) or "-"
        print(f"  edit: {spec['edit']}\n    outcome: {step.outcome}" + (f" ({step.failure})" if step.failure else ""))
        print(f"    expected: {spec['meaning']}  [{cat}" + (f", refuse: {spec['refuse']}]" if "refuse" in spec else "]"))
        if step.outcome != "not reached":
            print(f"    got:      {'; '.join(step.got) if step.got else '-'}  [{step.intent or '-'}]")
        if step.message:
            print(f"    message:  {step.message[:400]}")


def summarize(cases: list[dict], results: list[CaseResult]) -> dict:
    """Counts per case and per edit, must-refuse accounting and failure classes (no text)."""
    by_case = Counter(r.outcome for r in results)
    by_edit: Counter = Counter()
    classes: Counter = Counter()
    mr: Counter = Counter()
    for case, res in zip(cases, results, strict=True):
        if res.outcome.startswith("base"):
            classes[res.failure] += 1
            by_edit["not reached (base failed)"] += len(case["steps"])
            continue
        for spec, step in zip(case["steps"], res.steps, strict=True):
            by_edit[step.outcome] += 1
            if step.failure:
                classes[step.failure] += 1
            if must_refuse(spec) and step.outcome != "not reached":
                mr["n"] += 1
                mr["right reason" if step.outcome == RIGHT else
                   "compiled" if step.outcome == "silently wrong" else
                   "other reason" if step.outcome.startswith("refused") else "error"] += 1
    n_edits = sum(len(c["steps"]) for c in cases)
    n_must = sum(1 for c in cases for s in c["steps"] if must_refuse(s))
    return {"cases": len(cases), "by_case": by_case, "edits": n_edits, "by_edit": by_edit, "classes": classes,
            "must_refuse": mr, "must_refuse_total": n_must,
            "multi_step_cases": sum(1 for c in cases if len(c["steps"]) > 1)}


def print_summary(label: str, s: dict) -> None:
    n = s["cases"]
    print(f"\n{label}: {n} cases ({s['multi_step_cases']} with 2-3 edits), {s['edits']} edits "
          f"({s['must_refuse_total']} must-refuse)")
    print(f"{'cases':38s} {'n':>4s} {'%':>5s}")
    for k in ORDER:
        if s["by_case"][k] or k in ("right", "silently wrong"):
            print(f"  {k:36s} {s['by_case'][k]:4d} {100 * s['by_case'][k] / n:4.0f}%")
    print(f"edits (stopping at a case's first failure): {s['edits']}")
    for k in ORDER + ["not reached", "not reached (base failed)"]:
        if s["by_edit"][k]:
            print(f"  {k:36s} {s['by_edit'][k]:4d}")
    mr = s["must_refuse"]
    print(f"must-refuse edits reached: {mr['n']}; refused for the right reason {mr['right reason']}, "
          f"for another reason {mr['other reason']}, compiled {mr['compiled']}, error {mr['error']}")
    print("failure classes:" + ("" if s["classes"] else " none"))
    for cls, k in sorted(s["classes"].items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"  {k:4d}  {cls}")


def run(split: str = "dev", show: str = "wrong", jobs: int = MAX_JOBS, ids: list[str] | None = None) -> dict:
    cases = load_split(split)
    if split == "unseen":
        show, ids = "none", None  # never print an unseen case
    if ids:
        cases = [c for c in cases if c["id"] in set(ids)]
    t0 = time.monotonic()
    results = run_cases(cases, jobs)
    if show != "none":
        for case, res in zip(cases, results, strict=True):
            want = {"wrong": res.outcome != RIGHT and "refused" not in res.outcome,
                    "refused": "refused" in res.outcome,
                    "right": res.outcome == RIGHT, "all": True}[show]
            if want:
                _show_case(case, res)
    label = {**{k: v[1] for k, v in DEVELOPMENT.items()},
             "unseen": "UNSEEN steering split (steer_unseen.yaml, frozen)"}[split]
    s = summarize(cases, results)
    print_summary(label, s)
    print(f"runtime: {time.monotonic() - t0:.0f} s with {max(1, min(jobs, MAX_JOBS))} worker(s)")
    s["results"] = [asdict(r) for r in results] if split != "unseen" else []
    return s


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--split", default="dev", choices=[*DEVELOPMENT, "unseen"])
    ap.add_argument("--show", default=None, choices=["wrong", "refused", "right", "all", "none"],
                    help="print these development cases (default: wrong, i.e. every case not right and not refused); "
                         "not allowed for --split unseen")
    ap.add_argument("--jobs", type=int, default=MAX_JOBS, help=f"worker processes (at most {MAX_JOBS})")
    ap.add_argument("--ids", default=None, help="comma-separated case ids (development split only)")
    args = ap.parse_args(argv)
    if args.split == "unseen" and (args.show not in (None, "none") or args.ids):
        ap.error("--show and --ids are for the development split: the unseen split reports aggregates only")
    try:
        s = run(args.split, args.show or "wrong", args.jobs, args.ids.split(",") if args.ids else None)
    except SplitFrozenError as exc:
        print(f"refusing to report the unseen steering split: {exc}", file=sys.stderr)
        return 2
    return 1 if s["by_case"]["silently wrong"] or s["by_case"]["error"] else 0


if __name__ == "__main__":
    sys.exit(main())
