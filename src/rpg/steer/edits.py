"""The builtin edit interpreter: intent, parameters and reference cues of a steering edit.

Paper, "Controlled Task Modifications" and appendix "Version History Representation".  An
edit is read into

* a :class:`RefCue`: which version it builds on ("go back to when it was just red and
  blue", "version 2", "the letter version"; otherwise the current version);
* a list of :class:`Op` (add cubes, recolor, remove, change material, ordering, reverse,
  dimensions, count, outliers, structure), or a whole task stated anew (``standalone``);
* an intent: Tweak (colours, counts, dimensions), Extend (additions), Modify (material,
  ordering, properties within the structure), Pivot (a different structure) or Fresh
  (explicitly a new, unrelated task).

Deterministic and offline; the same rules for every edit, no per-sentence cases.
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass, field, replace
from functools import lru_cache

from rpg.domain.palette import GRADIENT_ORDER
from rpg.domain.predicates import Reads
from rpg.errors import BadInput
from rpg.schema import lexicon
from rpg.schema.builder import DEFAULT_COLORS
from rpg.schema.lexicon import (
    BARE_ORDER_RE,
    CAUSED_MOTION_RE,
    COLOR_RE,
    COLOURS_KEPT_RE,
    COUNT_WORD_RE,
    COUNTED_RUNS_RE,
    EDIT_ADDITIVE_RE,
    EDIT_ANAPHORA_RE,
    EDIT_BESIDE_RE,
    EDIT_CHANGE_VERB_RE,
    EDIT_CLAUSE_VERBS,
    EDIT_CONTINUES_RE,
    EDIT_COUNT_ALONE_RE,
    EDIT_COUNT_RE,
    EDIT_CUBE_REASON_RE,
    EDIT_EXCLAMATION_HAZARD_RE,
    EDIT_EXCLAMATION_RE,
    EDIT_FRESH_RE,
    EDIT_INEXPRESSIBLE,
    EDIT_INTERJECTION_RE,
    EDIT_LABEL_RE,
    EDIT_LEADING_RE,
    EDIT_MORE_ALONE_RE,
    EDIT_OPENING,
    EDIT_OWN_VERB_RE,
    EDIT_PERSON_REASON_HAZARD_RE,
    EDIT_PERSON_REASON_RE,
    EDIT_REASON_HAZARD_RE,
    EDIT_REASON_JUDGEMENT_RE,
    EDIT_REASON_SENTENCE_RE,
    EDIT_REFERS_RE,
    EDIT_REST_STAYS_RE,
    EDIT_REWRITES,
    EDIT_SAME_COUNT_RE,
    EDIT_SENTENCE_CHANGE_RE,
    EDIT_SHOULD_BE_RE,
    EDIT_SWAP_BOTH_RE,
    EDIT_VAGUE_RE,
    IGNORABLE,
    IGNORABLE_MORE,
    INEXPRESSIBLE,
    INSTRUCTION_ONLY,
    INTENSIFIER_RIGHT_RE,
    NUMBER_WORDS,
    POINTED_STRUCTURE_RE,
    POLITE_CONDITION_RE,
    REF_CHANGE_RE,
    SWAPPED_THEN_SAID_RE,
    TURNING_LABEL_RE,
    TYPOS,
    UNKNOWN_COLOUR,
    VOCAB,
    colour_names,
    edit_label_dropped,
    is_dictionary_word,
    said,
)
from rpg.schema.model import TaskSchema
from rpg.schema.readers.common import item_sequence
from rpg.schema.reading import (
    apply_corrections,
    canon_color,
    drop_voice_chunks,
    moving_verb,
    region_name,
    spoken,
)
from rpg.schema.structures import (
    STRUCTURE_KINDS,
    STRUCTURE_RE,
    pyramid_count,
    sort_labels,
    structure_of_word,
)
from rpg.steer.carried import split
from rpg.steer.spec import Item, TaskSpec

INTENTS = ("tweak", "extend", "modify", "pivot", "fresh")
"""Steering categories, weakest to strongest change."""

PRESERVATION: dict[str, dict[str, bool]] = {
    "tweak": {"preserve_assets": True, "preserve_positions": True, "preserve_goals": True},
    "extend": {"preserve_assets": True, "preserve_positions": True, "preserve_goals": True},
    "modify": {"preserve_assets": False, "preserve_positions": True, "preserve_goals": True},
    "pivot": {"preserve_assets": True, "preserve_positions": False, "preserve_goals": False},
    "fresh": {"preserve_assets": False, "preserve_positions": False, "preserve_goals": False},
}
"""Preservation flags per intent: Tweak and Extend keep the reference's assets, rho_0 and
success predicate apart from the change (directly comparable versions); Modify substitutes
assets within the structure; Pivot keeps the reference's cubes but rewrites the goal;
Fresh keeps nothing."""

OP_INTENT = {
    "add": "extend", "recolor": "tweak", "remove": "tweak", "count": "tweak", "dims": "tweak",
    "material": "modify", "ordering": "modify", "reverse": "modify", "outliers": "modify",
    "relabel": "tweak", "swap": "modify", "word": "modify", "colors": "tweak", "structure": "pivot",
    "move": "modify", "pattern": "tweak", "direction": "modify", "keep": "tweak", "region": "modify", "add_layer": "extend",
    "arrange": "modify", "rest": "tweak",
}
"""The intent each operation implies; an edit's intent is the strongest of its operations."""

LETTERS = [chr(ord("A") + i) for i in range(26)]
DIGITS = [str(d) for d in (1, 2, 3, 4, 5, 6, 7, 8, 9, 0)]


class SteerError(BadInput):
    """An edit that cannot be interpreted or applied; the message says why and what works."""


class SecondStructure(SteerError):
    """An edit that adds a structure of its own ("add a second pair: a green cube on a brown cube"), which no operation on
    the task's structure states: read as a clause added to the task (its instruction, then the clause), kept only when the
    two read together keep the task and add to it."""


@dataclass
class Op:
    """One edit operation with its parameters (recorded in the version history)."""

    op: str
    params: dict = field(default_factory=dict)


@dataclass
class RefCue:
    """What the edit says about the version it builds on."""

    kind: str = "current"  # current | version | original | previous | redo | search | before
    version: int | None = None
    lacks: str | None = None  # ``before``: what the version lacks ("patch", "cube") that later ones gained
    steps: int = 1  # how many versions back ("go back two versions"), for ``previous``
    colors: tuple[str, ...] = ()
    exact: bool = False
    material: str | None = None
    structure: str | None = None
    count: int | None = None
    word: str | None = None
    phrase: str = ""


@dataclass
class EditPlan:
    """An interpreted edit."""

    text: str
    cue: RefCue
    ops: list[Op] = field(default_factory=list)
    standalone: bool = False
    fresh: bool = False
    adds: bool = False  # a clause added to a version named by the cue ("revert that and add ..."), read as an addition
    checks: tuple[tuple[str, object], ...] = ()  # what the edit says the version built on has, checked, not applied:
    # ("count", 5) for "same five but ...", ("material", "letters") for "same letters but ..." (see :func:`check_said`)
    set_aside: tuple[str, ...] = ()  # sentences said as the reason for the change ("That's too much for today."), not read

    def parameters(self) -> dict:
        cue = {k: v for k, v in asdict(self.cue).items() if v not in (None, (), False, "") and not (k == "steps" and v == 1)}
        return {"ops": [asdict(o) for o in self.ops], "reference_cue": cue, "standalone": self.standalone}  # one step back: unsaid


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

TYPO_RE = re.compile(r"(?i)\b(?:" + "|".join(sorted(TYPOS, key=len, reverse=True)) + r")\b")
"""A misspelt word of the vocabulary (:data:`rpg.schema.lexicon.TYPOS`)."""

FRESH_RE = EDIT_FRESH_RE
ANAPHORA_RE = EDIT_ANAPHORA_RE
"""Words that make an edit a change to the current task rather than a whole new one
(:data:`rpg.schema.lexicon.EDIT_ANAPHORA_RE`)."""
CUT_RE = re.compile(r"\band (?:then|instead|now|also|add|put|make|change|use|replace|remove|sort|swap|flip|turn)\b"
                    r"|\binstead\b|\bthen\b|\bbut\b|[;,.]")
MATERIAL_WORDS = (("letters", r"\bletters?\b|\balphabet\b"), ("digits", r"\bnumbers?\b|\bdigits?\b"), ("colors", r"\bcolou?r(?:s|ed)?\b"))
ORDERING_PHRASES = (
    r"\b(?:sort(?:ed)?|order(?:ed)?|arrange[ds]?)?\s*(?:them\s+)?by\s+(?:different\s+|their\s+)?colou?rs?\b",
    r"\bcolou?r\s+(?:order|gradient|sequence)\b", r"\bdifferent\s+colou?rs?\b", r"\balphabetic(?:al)?(?:ly)?\b",
    r"\bnumeric(?:al)?(?:ly)?\b", r"\b(?:each|every)\s+(?:row|layer|level)\b", r"\bcolou?rs?\s+(?:to|into)\s+(?:a\s+)?rainbow\b",
)
LABELLED_RE = r"\b(?:letter|digit|number|label)\s+'?[a-z0-9]'?(?![a-z0-9])"


def normalize_edit(text: str) -> str:
    """Lower-case, quotes unified, number words as digits, a bare capital letter or digit after
    an article read as a labelled cube ("put a D on top", "swap the 3 for a 7"), a word in
    capitals quoted ("change it to DOG"), and typos of known words corrected ("shoud")."""
    t = text.strip()
    t = re.sub(r"\b(?:(letter)\s+(cube|block)\s+([A-Za-z])|(?:digit|number)\s+(cube|block)\s+(\d))\b(?!['\-])(?![x\d\-.,]\d)",
               lambda m: f"letter {m.group(3).upper()} {m.group(2)}" if m.group(1) else f"digit {m.group(5)} {m.group(4)}", t)
    # "the letter cube T", "the digit cube 7": the letter T cube, the digit 7 cube (the label had been read twice, "letter
    # cube letter t", "digit digit 7 cube")
    t = re.sub(r"\b(a|an|the)\s+([A-Z])\b(?!['\-])", r"\1 letter \2", t)
    # a lone capital is a letter cube ("swap A and D"); "A" only where no noun follows it
    t = re.sub(r"(?<![\w'])(?<!letter )([B-HJ-Z])\b(?!['\-])|(?<![\w'])(?<!letter )(A)\b(?=\s*(?:$|[,.;!?]|and\b|or\b|with\b|for\b"
               r"|to\b|on\b|at\b|in\b|instead\b|is\b|should\b|goes\b))",
               lambda m: f"letter {m.group(1) or m.group(2)}", t)
    t = re.sub(r"\b(a|an|the)\s+(\d)\s+(cube|block)\b(?!\s*(?:-|towers?|stacks?|rows?|lines?|pyramids?|walls?|piles?|circles?|grids?"
               r"|columns?|high|tall|wide|long)\b)", r"\1 digit \2 \3", t)  # "put a 6 cube on top": the digit cube 6 (six had been
    # added, silently); "a 3 cube tower" is a count
    t = re.sub(r"(?<!digit )(?<!\d )\b(cube|block)\s+(\d)\b(?![x\d\-.,]\d)(?!\s*(?:blocks?|cubes?|tall|high|wide|long|deep|layers?|levels?|rows?|more|of"
               r"|colou?rs?|times)\b)", r"digit \2 \1", t)  # "put cube 6 on top": the digit cube 6 (six had been added, silently)
    t = re.sub(r"\b(a|an|the)\s+(\d)\b(?![x\d\-])(?!\s*(?:blocks?|cubes?|tall|high|wide|long|deep|layers?|levels?|rows?|"
               r"more|of|colou?rs?|stor\w*|outliers?|times)\b)", r"\1 digit \2", t)
    known = _known_words()
    t = re.sub(r"\b((?i:say|says|spell|spells|spelling|read|reads|reading)\s+)([A-Z]{2,})\b(?!\s+(?i:to)\b)", r"\1'\2'", t)  # "make it say
    # TOYS": a word spelled, though "toys" is a known word (it had been refused as an object)
    t = re.sub(r"(?<!')\b[A-Z]{2,}\b(?!')", lambda m: m.group(0) if m.group(0).lower() in known else f"'{m.group(0)}'", t)
    t = t.lower()
    t = POINTED_STRUCTURE_RE.sub(lambda m: f"the {m.group('n')}", t)  # "that little tower": the task's own
    for pattern, sort in lexicon.ORDER_RANGE_RES[:2]:  # "sort them so the numbers go up from left to right": a sort by the
        # numbers' way, where the way along the structure is said with it (the edit had changed nothing)
        t = pattern.sub(lambda m, sort=sort: sort if lexicon.DIRECTION_SAID_RE.match(
                            re.sub(r"^\s*(?:from\s+(?=left|right))?", "", m.string[m.end():])) else m.group(0),
                        re.sub(r"\bso\s+(?=(?:the\s+)?(?:numbers|digits|values|labels)\s)", "so that ", t))
    t = re.sub(r"[\u2018\u2019\u201c\u201d`\"]", "'", t)
    t = re.sub(r"''+", "'", t)
    t = re.sub(r"\b(\d+)\s*(?:by|\u00d7)\s*(\d+)\b", r"\1x\2", t)
    t = re.sub(rf"\b(?:the|all|both)\s+({COLOR_RE})s\b", r"the \1 blocks", t)  # "change the blues to green"
    # "one" is a count only where a count stands ("one more block", "just one"); "the orange one" is a cube
    t = re.sub(r"\bone\b(?!\s+(?:tall|high|wide|long)\s+(?:rows?|lines?|towers?|stacks?|columns?|walls?|piles?)\b)"  # "one long row": a row
               r"(?=\s+(?:more|fewer|less|blocks?|cubes?|layers?|rows?|levels?|tall|high|wide|long)\b)"
               r"|\b((?:just|only|like|use|with|to|have) )one\b(?!\s+(?:of|at|on|in)\b)", lambda m: (m.group(1) or "") + "1", t)
    for w, n in NUMBER_WORDS.items():
        if w not in ("single", "pair", "couple", "both", "one"):
            t = re.sub(rf"\b{w}\b", str(n), t)
    return " ".join(_corrected(w, known) for w in t.split())


@lru_cache(maxsize=1)
def _known_words() -> frozenset[str]:
    """Words an edit's typo is corrected to: the vocabulary, the ignorable words and the colours."""
    return frozenset(VOCAB | IGNORABLE | IGNORABLE_MORE | set(COLOR_RE.split("|")))


def _corrected(word: str, known: frozenset[str], fuzzy: bool = True) -> str:
    """A typo of a known word corrected ("shoud" -> "should"): only a word of 4 letters or
    more that is no English word, within the parser's own distance; with ``fuzzy`` False, only
    two letters swapped ("mkae" -> "make")."""
    core = word.strip(".,;:!?'")
    if len(core) < 3 or not core.isalpha() or core in known or is_dictionary_word(core):
        return word
    swapped = sorted({core[:i] + core[i + 1] + core[i] + core[i + 2:] for i in range(len(core) - 1)} & known - {core})
    if len(swapped) == 1:  # two letters swapped ("mkae" -> "make"), as the parser reads them
        return word.replace(core, swapped[0])
    if len(core) < 4 or not fuzzy:
        return word
    from rapidfuzz import fuzz, process

    match = process.extractOne(core, sorted(known), scorer=fuzz.ratio, score_cutoff=84)
    return word.replace(core, match[0]) if match else word


def refuse_inexpressible(edit: str, t: str) -> None:
    """Refuse an edit that asks for what the domain cannot express, naming the words and why:
    the parser's classes (:data:`rpg.schema.lexicon.INEXPRESSIBLE`; not ``reference``, whose
    words name versions here) and the edits' own (:data:`~rpg.schema.lexicon.EDIT_INEXPRESSIBLE`).

    Raises:
        SteerError: the edit says one.
    """
    t = re.sub(r"'[a-z0-9]{2,}'", " ", t)  # a quoted word is one spelled ("make it say 'toys'"), no object or action
    vague = EDIT_VAGUE_RE.search(t)
    if vague and not EDIT_COUNT_RE.search(t):  # "make it a bit taller" (a number said, "like 3 blocks", is a count)
        raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": '{vague.group(0)}' is a vague quantity: rpg's counts are "
                         "exact and its relations qualitative; say how many blocks (e.g. \"make it 5 blocks tall\")")
    for m in re.finditer(r"\b([a-z]+)\b(?=(?:[\s-]+colou?red)?\s+(?:cubes?|blocks?|ones?|patch(?:es)?|bricks?)\b)"
                         r"|\b(?:cubes?|blocks?|ones?|bricks?)\s+(?:of|in)\s+([a-z]+)\b", t):
        word = m.group(1) or m.group(2)  # "put a gold cube on top": a colour the palette lacks (it had been dropped, a green cube added)
        if word in colour_names() and not re.fullmatch(COLOR_RE, word) and word not in _known_words():
            raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": '{word}' {UNKNOWN_COLOUR[1]}")
    inherited = (c for c in INEXPRESSIBLE if c[0] != "reference" and c[1] not in INSTRUCTION_ONLY)
    classes = (*EDIT_INEXPRESSIBLE, *inherited)
    # a question first ("which of the two patches is closer to the robot right now?": a question, whatever it asks about)
    for _cls, pattern, why in sorted(classes, key=lambda c: c[0] != "question"):
        m = re.search(pattern, t)
        if m:
            raise SteerError(f"cannot apply the edit \"{edit.strip()[:80]}\": '{said(m)}' {why}")


def _materials(text: str) -> list[str]:
    t = re.sub(r"\bnumber of\b", " ", text)
    for p in ORDERING_PHRASES:
        t = re.sub(p, " ", t)
    t = re.sub(LABELLED_RE, " ", t)
    return [m for m, pat in MATERIAL_WORDS if re.search(pat, t)]


NON_WORDS = frozenset("""go going went back when was were version spelled spelling said read had just only
again previous earlier older one""".split())
"""Words of a back-reference that are not the spelled word it may name ("go back to DOG")."""


def find_reference(t: str) -> RefCue:
    """The reference cue of a normalised edit."""
    m = re.search(r"\b(?:version|v)\s*#?(\d+)\b", t)
    if m:
        return RefCue("version", version=int(m.group(1)), phrase=m.group(0))
    own = re.search(r"\b(?:back|revert\w*|return\w*|go\s+to|restore\w*|like|as\s+in|compared?\s+(?:with|to))\b(?:\s+\w+){0,3}?\s+"
                    r"((?:round|level|iteration|draft|attempt|try|step|stage|variant|rev|revision|take)\s*#?\d+)\b", t)
    if own:  # "go back to round 3": a version numbered by the writer's own count, which the family does not keep (it had
        # been read as one step back)
        raise SteerError(f"'{own.group(1)}' names a version by a count of its own, which rpg does not keep; name it as rpg "
                         "numbers versions (e.g. \"go back to v1\"; `rpg log` lists them)")
    m = re.search(r"\b(?:the original|first version|base (?:task|version)|very first|initial version)\b"
                  r"|\b(?:like|as in|as|back to|compared? (?:with|to)|go back to|revert to|return to)\s+the\s+first\s+(?:one|task|variant|try)\b"
                  r"|\b(?:back|revert|return|restart|from|like|as)\b(?:\s+\w+){0,5}?\s+(?:the beginning|the start)\b", t)
    # ("add a brown one at the start" is an end of the line, no version: "back to how it was at the start" is)
    if m:
        return RefCue("original", phrase=m.group(0))
    redo = re.fullmatch(r"\W*(?:(?:nvm|never\s*mind|ok(?:ay)?|actually|no|hmm+|wait)\W+)*(?:redo(?:\s+(?:that|it|the\s+last\s+"
                        r"(?:change|edit|step)|the\s+change))?|(?:revert|undo)\s+(?:the|that|my)\s+(?:revert|undo))"
                        r"(?:\s+(?:please|pls))?\W*", t)
    if redo:  # "nvm, redo": the change the last undo took back
        return RefCue("redo", phrase=redo.group(0).strip())
    this = re.search(r"\bth(?:is|e current|e latest)\s+(?:[a-z]+\s+)?version\b|\bcurrent\b", t)
    back = re.search(r"\b(?:go(?:ing)? back|back to|revert|return to|undo|earlier|previous|prior|older|used to)\b", t)
    named = re.search(r"\b(?:the|that)\s+((?:[a-z0-9'-]+\s+){1,5}?)(?:version|variant)\b", t)
    if named and not back and not this and (_materials(named.group(1)) or re.search(
            rf"\b(?:{COLOR_RE})\b|{STRUCTURE_RE}|\b\d+[- ](?:blocks?|cubes?)\b", named.group(1))):
        back = named  # "the letter version", "the 3-block version": a version named by its content
    if not back or this:
        return RefCue("current", phrase=this.group(0) if this else "")
    region = t[back.start():] if back is named else t[back.end():]
    cut = CUT_RE.search(region)
    region = region[: cut.start()] if cut else region
    gained = re.search(rf"\bbefore\s+(?:(?:you|we|i)\s+(?:added|put|placed)\s+|adding\s+)?(?:the|a|an)\s+(?:(?P<c>{COLOR_RE})\s+)?"
                       r"(?P<what>patch|cube|block)\b", region)
    if gained and (gained.group("what") == "patch" or gained.group("c")):  # "go back to the one before the patch", "before
        # you added the green cube": the latest version, back from the head, without it
        c = gained.group("c")
        return RefCue("before", colors=(canon_color(c),) if c else (), lacks="patch" if gained.group("what") == "patch" else "cube",
                      phrase=(back.group(0) + region[:gained.end()]).strip())
    many = re.search(rf"\b(\d+|{COUNT_WORD_RE})\s+(?:versions?|steps?|edits?|changes?)(?:\s+(?:back|ago|earlier))?\b|\b(twice)\b"
                     r"|(?<![\w-])[x\u00d7]\s*(\d)\b|\b(\d)\s*[x\u00d7](?![\w-])", region)  # "undo x2", "undo 2x"
    region = region.replace(many.group(0), " ") if many else region  # "go back two versions": how far, not which
    colors = tuple(dict.fromkeys(canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", region)))
    mats = _materials(region)
    s = re.search(STRUCTURE_RE, region)
    n = re.search(r"\b(\d+)[- ](?:blocks?|cubes?)\b", region)
    words = [w.strip("'") for w in re.findall(r"'?\b[a-z]{2,}\b'?", region)]
    spelled = [w for w in words if w not in VOCAB and w not in NON_WORDS and not re.fullmatch(COLOR_RE, w)
               and w not in ("one", "ones")]  # "go back to the black ones": cubes, no word spelled
    cue = RefCue("search", colors=colors, exact=bool(re.search(r"\b(?:just|only)\b", region)),
                 material=mats[0] if len(mats) == 1 else None,
                 structure=structure_of_word(s.group(1)) if s else None,
                 count=int(n.group(1)) if n else None, word=spelled[0].upper() if len(spelled) == 1 else None,
                 phrase=(back.group(0) + region).strip())
    if not (cue.colors or cue.material or cue.structure or cue.count or cue.word):
        steps = 2 if many and many.group(2) else int(many.group(3) or many.group(4)) if many and (many.group(3) or many.group(4)) \
            else int(NUMBER_WORDS.get(many.group(1), many.group(1))) if many else 1
        return RefCue("previous", phrase=back.group(0), steps=steps)  # "go back two versions": that many
    return cue


_PATCH_PHRASE_RE = re.compile(rf"(?:the\s+|an?\s+)?({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat)")
"""A patch named by its colour ("the red patch"): fullmatched by :func:`_selector` and :func:`_relation_pick`."""
_REVERSE_ORDER = r"in\s+(?:the\s+)?(?:reverse|reversed|opposite)\s+order"
"""An order said reversed ("in reverse order", "in the opposite order"): read by ``stack_all`` and :func:`_kept_order`."""

_REL_PICK_RE = re.compile(
    r"(?:the\s+)?(?:cube|block|one)\s+(?:that\s+is\s+|that's\s+|which\s+is\s+|(?:sitting|standing|resting|lying|placed)\s+)?"
    r"(?:(?:right|directly|just|immediately)\s+)?(?P<rel>on\s+top\s+of|on|onto|atop|above|over|under|underneath|below|beneath"
    r"|(?:to\s+the\s+|on\s+the\s+)?left\s+of|(?:to\s+the\s+|on\s+the\s+)?right\s+of|next\s+to|beside|in\s+between|between"
    r"|behind|in\s+front\s+of|far\s+(?:away\s+)?from|near|close\s+to|opposite|across\s+from)"
    r"(?:\s+(?P<of>.+))?")
"""A cube picked by where it stands beside another ("the cube under the green one", "the cube left of the blue one", "the
cube on the red patch", "the cube between the blue and the yellow one"): read by :func:`_selector` (the colour of the
other cube had been taken for the cube's own: silently wrong)."""
_REL_PICKED = {"on top of": "above", "on": "above", "onto": "above", "atop": "above", "above": "above", "over": "above",
               "under": "below", "underneath": "below", "below": "below", "beneath": "below", "next to": "beside",
               "beside": "beside", "in front of": "front", "far from": "far", "far away from": "far", "near": "near",
               "close to": "near", "opposite": "far", "across from": "far"}


def _relation_pick(text: str) -> dict | None:
    """:func:`_selector` of a cube picked by its neighbour (:data:`_REL_PICK_RE`): ``{"next": side, "of": selector}`` (side
    above, below, left, right, beside, front, behind, far or near: :data:`_REL_PICKED`), ``{"between": [selector, selector]}``, ``{"position": "middle"}`` for "the cube in
    between" said alone, ``{"on_patch": colour}``; None when the phrase is no such pick.

    Raises:
        SteerError: the neighbour named is not read."""
    m = _REL_PICK_RE.fullmatch(text)
    if m is None:
        return None
    rel, of = re.sub(r"^(?:to|on)\s+the\s+", "", m.group("rel")), (m.group("of") or "").strip()
    if not of:
        if rel in ("between", "in between"):
            return {"position": "middle"}
        return None
    if rel in ("on", "onto", "atop") and re.match(r"(?:the\s+)?(?:far\s+|very\s+)?(?:left|right|front|back|top|bottom|base|end|table)\b", of):
        return None  # "the one on the left", "the cube on top": a place, not a neighbour
    patch = _PATCH_PHRASE_RE.fullmatch(of)
    if patch and rel in ("on", "onto", "atop", "on top of"):
        return {"on_patch": canon_color(patch.group(1))}
    if rel in ("between", "in between"):
        ends = re.fullmatch(r"(?:the\s+)?(?P<a>.+?)\s+and\s+(?:the\s+)?(?P<b>.+)", of)
        pair = [_selector(ends.group("a")), _selector(ends.group("b"))] if ends else []
        if len(pair) != 2 or not all(pair):
            raise SteerError(f"'{text}' picks a cube between two others the builtin steering does not read; name the two by colour "
                             "(e.g. \"the cube between the red and the green one\"), or use --model")
        return {"between": pair}
    inner = None if re.search(r"\b(?:patch|pad|mat)(?:es|s)?\b", of) else _selector(of)
    if not inner or "patch" in inner or "on_patch" in inner:
        raise SteerError(f"'{text}' picks a cube by a neighbour the builtin steering does not read ('{of}'); name the cube by colour "
                         "or by its place, or use --model")
    return {"next": _REL_PICKED.get(rel, rel.removesuffix(" of")), "of": inner}


def _selector(text: str) -> dict | None:
    """Which cubes a phrase names: a position (of a cube, or of a layer: "the bottom layer"),
    a colour, a label, some of them ("two of them"), that many from an end ("the top 2", "the 2 top
    ones"), both of two, all of them, a cube by its neighbour (:func:`_relation_pick`) or a patch
    ("the red patch": ``{"patch": colour}``).  A colour said with a place ("the bottom red cube")
    is kept as ``"was"``: the cube there must be that colour (:func:`_indices` checks it).

    Raises:
        SteerError: the phrase names cubes by the ones they are not ("all but the ends"), or several
            places at once."""
    text = re.sub(r"(?:\s+(?:is|are|was|now|should|must|becomes?|turns?|gets?|goes))+$", "", text.strip())  # "the cube in between is brown"
    patch = _PATCH_PHRASE_RE.fullmatch(text)
    if patch:
        return {"patch": canon_color(patch.group(1))}
    under = re.fullmatch(rf"(?:the\s+)?(?:goal\s+|target\s+)?(?:patch|pad|mat)\s+(?:that\s+is\s+|that's\s+)?(?:under(?:neath)?|beneath|below|of)\s+"
                         rf"(?:the\s+)?({COLOR_RE})\s+(?:cube|block|one)", text)
    if under:  # "the patch under the red cube": the patch the red cube stands on (the cube had been recoloured)
        return {"patch_of": canon_color(under.group(1))}
    picked = _relation_pick(text)
    if picked is not None:
        return picked
    said = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", text)]
    placed = said and re.search(r"\b(?:left|right|leftmost|rightmost|top|bottom|base|middle|first|last|lowest|highest|second|third"
                                r"|\d+(?:st|nd|rd|th))\b", text)
    # "the right green cube": the cube at that place, which must be green ("green" had picked the cube alone)
    sel = _selector_of(re.sub(rf"\s*\b(?:{COLOR_RE})\b", "", text).strip() if placed else text)
    if sel and said and not {"color", "label"} & set(sel):
        if len(set(said)) > 1:
            raise SteerError(f"'{text}' names one cube by {len(set(said))} colours; say which cube, by its place or its colour")
        if sel.get("all") and not {"both", "single", "uniform"} & set(sel):
            return {"color": said[0]}  # "all the red cubes": every red cube (every cube had been taken)
        return {**sel, "was": said[0]}
    return sel


_UNREAD_PICK_RE = re.compile(r"\b(?:behind|front|far|near|close|beside|next\s+to|left\s+of|right\s+of|under|underneath|below|beneath"
                             r"|above|over|atop|on\s+top\s+of|between|opposite|across|against|touching)\b")
"""Relation words in a phrase that picks a cube: a phrase :func:`_relation_pick` did not read is not read by its first
colour (the neighbour's colour had been taken for the cube's)."""


def _selector_of(text: str) -> dict | None:
    """:func:`_selector` of a phrase that is no patch and picks no cube by its neighbour."""
    other = re.search(r"\b(?:all|every\w*|each|them)\b.*?\b(?:but|except|other\s+than|apart\s+from|besides)\b|\ball\s+(?:the\s+)?other\b"
                      r"|\bbetween\s+the\s+ends\b", text)
    if other:  # "all but the ends", "every cube but the bottom one": every cube had been taken
        raise SteerError(f"'{text}' names cubes by the ones they are not, which the builtin steering does not read; name them by "
                         "colour or place (e.g. \"make the 2nd and 3rd from the bottom pink\" in two edits), or use --model")
    ends = re.search(r"\b(?P<e>top|bottom|first|last|lowest|highest)\s+(?P<n>\d+)\b"  # "the top 2"
                     r"|\b(?P<n2>\d+)\s+(?P<e2>top|bottom|first|last|lowest|highest)(?:\s+(?:ones|cubes|blocks))?\b", text)  # "the 2 top ones"
    if ends:
        end, n = ends.group("e") or ends.group("e2"), ends.group("n") or ends.group("n2")
        return {"end": "bottom" if end in ("bottom", "first", "lowest") else "top", "n": int(n)}
    sides = re.search(r"\b(left|right)(?:most)?\s+(\d+)\b|\b(\d+)\s+(left|right)(?:most)?(?:\s+(?:ones|cubes|blocks))?\b"
                      r"|\b(\d+)\s+(?:(?:ones|cubes|blocks)\s+)?(?:on|at)\s+the\s+(?:far\s+)?(left|right)(?:\s+end)?\b", text)
    if sides:  # "the two leftmost ones", "the left 2", "the 2 on the right": that many from that end of a row
        return {"end": sides.group(1) or sides.group(4) or sides.group(6), "n": int(sides.group(2) or sides.group(3) or sides.group(5))}
    side = re.fullmatch(r"(?:the\s+)?(?:(left|right)most(?:\s+(?:one|cube|block))?|(left|right)(?:-hand)?\s+(?:one|cube|block)"
                        r"|(?:one|cube|block)\s+(?:on|at)\s+the\s+(?:far\s+)?(left|right)(?:\s+end)?)", text)
    if side:  # "the leftmost one", "the one on the left": the one cube at that end of a row
        return {"end": side.group(1) or side.group(2) or side.group(3), "n": 1}
    nth = re.search(r"\b(?:(\d+)(?:st|nd|rd|th)|(second|third|fourth|fifth|sixth))\b(?:\s+(?:one|block|cube))?"
                    r"(?:\s+from\s+the\s+(bottom|top|left|right|front|back))?", text)
    places = re.sub(r"\bfrom\s+the\s+(?:top|bottom|left|right)\b", " ", text)  # "the 2nd from the bottom": one place
    if len(re.findall(r"\b(?:\d+(?:st|nd|rd|th)|first|second|third|fourth|fifth|sixth|last|top|bottom|base|middle|lowest|highest)\b",
                      places)) > 1:  # "the second and third from the bottom", "the top one and the bottom one"
        raise SteerError(f"'{text}' names several cubes by their places; change one cube per edit "
                         "(e.g. \"make the 2nd from the bottom white\")")
    if nth and not (nth.group(1) or nth.group(3)):
        nth = None  # "the second one": the place in the structure's own order (below)
    if nth:  # "the 2nd one from the bottom": a place counted from an end
        k = int(nth.group(1)) if nth.group(1) else ("second", "third", "fourth", "fifth", "sixth").index(nth.group(2)) + 2
        return {"nth": k, "from": nth.group(3)}
    some = re.search(r"\b(\d+)\s+of\s+(?:them|the\s+(?:[a-z]+\s+)?(?:blocks|cubes|ones))\b", text)
    if some:
        return {"some": int(some.group(1))}
    if re.fullmatch(r"(?:the\s+)?(?:(?:two|2)\s+)?(?:ones?\s+|cubes\s+|blocks\s+)?(?:at|on)\s+(?:the|both|either)\s+ends|(?:the\s+)?both\s+ends"
                    r"|(?:the\s+)?(?:two\s+|2\s+)?ends|the\s+(?:two\s+|2\s+)?end\s+(?:ones|cubes|blocks)", text):
        return {"ends": True}  # "the two at the ends", "both ends"
    if re.search(r"\bends?\b", text) and re.search(r"\b(?:of|in|on)\s+the\s+(?:\w+\s+)?(?:row|layer|level|tier|line|column)\b", text):
        raise SteerError(f"'{text}' names the ends of a part of the structure, which the builtin steering does not pick; name the "
                         "cubes by colour or place, one per edit, or use --model")  # (the whole layer had been recoloured)
    if re.fullmatch(r"(?:the\s+)?both(?:\s+(?:of\s+)?(?:them|the\s+(?:blocks|cubes)|blocks|cubes))?", text):
        return {"all": True, "both": True}
    if re.fullmatch(r"(?:the\s+)?(?:cube|block)", text):
        return {"all": True, "single": True}  # "make the cube yellow": the task's one cube
    if re.search(r"\b(?:all|every|everything|each|whole)\b|^(?:the\s+)?(?:blocks|cubes|them|it|they|wall)\b", text) \
            or re.match(r"(?:the\s+)?" + STRUCTURE_RE, text):
        return {"all": True}
    m = re.search(r"\b(base|bottom|first|lowest|top|last|highest|upper|middle|center|centre|second|third)\b", text)
    if m:
        where = {"lowest": "bottom", "base": "bottom", "first": "bottom", "highest": "top", "last": "top",
                 "upper": "top", "centre": "middle", "center": "middle"}.get(m.group(1), m.group(1))
        if re.search(r"\b(?:layers?|levels?|rows?|tiers?|storey|story|floor)\b", text):
            return {"layer": where}
        return {"position": where}
    counted = re.match(rf"(?:(\d+|one|a|an|single)\s+(?:of\s+the\s+)?)({COLOR_RE})(?:\s+(?:blocks?|cubes?|ones?)\b|s?(?=\s*(?:"
                       r"off|away|out|from|$|[,.;!])))", text)
    if counted:  # "one red block", "2 of the blue cubes", "take one blue off", "one of the blues": that many of that
        # colour, not all of them
        k = counted.group(1)
        return {"color": canon_color(counted.group(2)), "count": int(k) if k.isdigit() else 1}
    items = item_sequence(text)
    if items and _UNREAD_PICK_RE.search(text):
        raise SteerError(f"'{text}' picks a cube by where it stands, in words the builtin steering does not read; name the cube "
                         "by its colour or its place, or use --model")
    if items:
        color, label = items[0]
        return {"color": color} if color else {"label": label}
    return None


def _new_item(text: str) -> dict | None:
    items = item_sequence(text)
    if not items:
        return None
    color, label = items[0]
    return {"color": color} if color else {"label": label}


def _region_of(t: str) -> str | None:
    """The region of the table an edit moves the whole structure to ("move the stack to the
    back of the table", "put the whole thing in the back left corner"), or None."""
    from rpg.steer.relations import _edit_region

    m = re.search(r"\b(?:move|put|place|shift|bring|slide|build|set|push|have|make|keep|stack|pile)\s+(?:it|them|everything|the\s+whole\s+thing"
                  r"|(?:both|all)\s+of\s+them|them\s+(?:both|all)"
                  r"|(?:the\s+)?(?:whole\s+|entire\s+)?(?:" + STRUCTURE_RE + r"|wall|blocks|cubes|word|letters|digits|numbers))\s+(?P<where>.*)", t)
    if not m:
        return None
    where = m.group("where")
    if re.search(r"\b(?:word|letters|digits|numbers)\s+$", t[:m.start("where")]) and not re.fullmatch(
            r"(?:on|to|at|in|into|along)\s+the\s+(?:far\s+|very\s+)?(?:front|back|rear|left|right|middle|cent(?:er|re))(?:[\s-]+(?:left|right))?"
            r"(?:\s+(?:side|edge|half|corner|end|part))?(?:\s+of\s+the\s+(?:table|workspace))?\s*[.!]?\s*", where):
        return None  # "put the word along the back of the table": the word moved there, and nothing else said of it
    structure = not re.match(r"(?:it|them)\b", m.group(0).split(None, 1)[1])
    pivot = re.match(r"(?:into\s+)?(?:a|an)\s+(?:[a-z0-9-]+\s+){0,2}?" + STRUCTURE_RE + r"\s+", where)
    if pivot:  # "make it a line along the front": the new structure's place
        where, structure = where[pivot.end():], True
    corner = re.match(r"(?:on|to|at|in|into|toward|towards)\s+the\s+(?:far\s+)?(front|back|rear)[\s-]+(left|right)\b(?!\s+of\b)", where)
    if corner:  # "move it to the front right": a corner of the table, whatever "it" is
        return region_name(corner.group(1), corner.group(2))
    if not re.search(r"\b(?:table|corner|side|edge|half|workspace)\b", where):
        # "put the tower on the left": a side alone, when the structure itself is moved there
        side = re.match(r"(?:on|to|at|in|along)\s+the\s+(?:far\s+)?(left|right|front|back|middle|center|centre)\b(?!\s+(?:of|end)\b)",
                        where)
        return region_name(*((None, side.group(1)) if side.group(1) in ("left", "right", "middle", "center", "centre")
                             else (side.group(1), None))) if side and (structure or side.group(1) in ("front", "back")) else None
        # ("move it to the back" of a structure: the back of the table; "put it on the left" may be a cube to an end)
    return _edit_region(" " + where + " ")


def _adds_a_cube(add: re.Match, t: str) -> bool:
    """Whether a verb's phrase brings in a cube: "add ...", or "put/stack a (new) ..." (not "put it
    on the blue patch", "put the blue block on the red block"; "also put the yellow block on it" is)."""
    if add.group("verb") not in ("add", "append", "include") and not re.search(
            r"\b(?:an?|another|\d+|one(?=\s+(?:[a-z]+\s+)?(?:block|cube)s?\b)|more|some|new|extra)\b", add.group("what")) and not (
            EDIT_ADDITIVE_RE.search(t) and re.fullmatch(rf"\s*the\s+(?:{COLOR_RE})\s+(?:block|cube)\s*", add.group("what"))):
        return False
    if re.search(r"\bpatch", add.group("what") + t[add.end():]):
        return False  # a patch: not a cube of the structure
    if re.search(r"\b(?:on(?:to)?\s+the\s+(?:table|floor|ground)\s*(?:[.;!,]|$)|far\s+(?:from|away)\b|away\s+from\b|apart\b|corner|(?:side|edge|middle|cent(?:er|re)|half)\s+of\s+"
                 r"the\s+(?:table|workspace)|at\s+the\s+(?:front|back|rear)\b(?!\s+end)|on\s+its\s+own|by\s+itself|separate\w*)", t[add.start("what"):]):
        return False  # "put a white cube on the table", "... far from the tower": a place of its own, not the structure's top
        # (it had gone on top of the tower, silently)
    if re.match(rf"\s*(?:it|them|that|this|the\s+(?:(?:{COLOR_RE})\s+)?(?:block|cube|one|tower|stack))\s+(?:on(?:to)?|on\s+top\s+of|under|"
                r"underneath|below|beneath|next\s+to|beside|behind|in\s+front\s+of)\s", add.group("what")):
        return False  # "put it on a yellow one": the cube named is moved onto the new one, which is no cube added on top
    return bool(item_sequence(add.group("what")) or re.search(
        r"\b(?:blocks?|cubes?)\b|^\s*(?:\d+|another|1)\s+more\s*$|^\s*another\s*(?:one\s*)?$", add.group("what")))


def read_ops(t: str) -> list[Op]:
    """The operations of a normalised partial edit (empty when it names none)."""
    t = re.sub(r"\b(?:the|that|this)\s+(?:[a-z0-9'-]+\s+){0,5}?(?:version|variant)\b", " ", t)  # names a version, changes nothing
    ops: list[Op] = []
    substitution = re.search(r"\b(?:instead of|rather than|in place of)\b(.*?)(?=[,;.]|\buse\b|\bwith\b|\bmake\b|\band\b|$)", t) or \
        re.search(r"\b(?:change|turn|switch|convert|replace|swap)\s+(?:all\s+)?(?:the\s+|its\s+|their\s+)?(\w+(?:\s+\w+)?)\s+(?:to|into|with|for|by)\b", t)
    source = _materials(substitution.group(1)) if substitution else []
    mats = [m for m in _materials(t) if m not in source]
    word = re.search(r"\b(?:change|make|turn|set)\s+(?:the\s+)?word\s+(?:to|into)\s+'?([a-z]{2,})'?|\bspell\s+'?([a-z]{2,})'?\s+instead\b"
                     r"|\bso\s+(?:that\s+)?(?:it|they|the\s+(?:word|line|row))\s+(?:says|spells|reads|say|spell|read)\s+'?([a-z]{2,})'?"
                     r"|\b(?:change|make|turn|switch)\s+(?:it|that|this)\s+(?:to\s+|into\s+)?(?:spell\s+)?'([a-z]{2,})'"
                     r"|\b(?:make|have|let)\s+(?:it|them|the\s+(?:line|row|cubes|blocks|letters))\s+(?:spell|say|read)\s+(?:out\s+)?'([a-z]{2,})'"
                     r"|\b(?:make|have|let)\s+(?:it|them|the\s+(?:line|row|cubes|blocks|letters))\s+spell\s+(?:out\s+)?"
                     r"(?!(?:backwards?|it|them|the|from|in|right|left|out)\b)([a-z]{2,})\b", t)
    if word:
        ops.append(Op("word", {"word": next(g for g in word.groups() if g).upper()}))
    ncolors = re.search(r"\b(?:use|with|have|make it|in)\s+(\d+)\s+(?:different\s+)?colou?rs\b", t)
    if ncolors:
        ops.append(Op("colors", {"count": int(ncolors.group(1))}))
    if re.search(r"\boutliers?\b", t):
        m = re.search(r"\b(\d+)\s+outliers?\b", t)
        ops.append(Op("outliers", {"per_pile": int(m.group(1)) if m else 1}))
    reverse = re.search(r"\b(?:flip|reverse|invert|mirror|swap)\b(?![^.;]*\b(?:keep\w*|same|kept|unchanged)\s+(?:the\s+)?order\b)[^.;]*\border\b|\bupside down\b|\breverse(?:d)? order\b|\bother\s+way\s+up\b|"
                        r"\b(?:flip|reverse|invert)\s+(?:it|them|that|this|everything|the\s+(?:whole\s+|entire\s+)?(?:tower|stack|line|row|gradient|sequence|colou?rs|word|letters|digits"
                        r"|numbers|labels|cubes|blocks))\b"
                        r"|\b(?:spell|write|read|arrange|put|place)\s+(?:it|them|the\s+word)\s+backwards?\b", t)
    if reverse:
        keep = re.search(r"\bkeep(?:ing)?\s+(?:the\s+)?(.+?)\s+(?:on top|at the top|in place|where it is|at the bottom|fixed)\b", t)
        kept = None
        if keep:  # "keep the letter 'A' on top", "keep A on top"
            lone = re.fullmatch(r"'?([a-z0-9])'?", keep.group(1).strip())
            kept = _selector(keep.group(1)) or ({"label": lone.group(1).upper()} if lone else None)
        ops.append(Op("reverse", {"colors_only": bool(re.search(r"\bcolou?r order\b|\border of (?:the )?colou?rs\b", t)),
                                  **({"keep": kept} if kept else {})}))
    if re.search(r"\balphabetic(?:al)?(?:ly)?\b", t):
        ops.append(Op("ordering", {"key": "label", "descending": bool(re.search(r"\b(?:reverse|descending|backwards?|z to a)\b", t))}))
    elif re.search(r"\bnumeric(?:al)?(?:ly)?\b|\b(?:increasing|ascending|decreasing|descending) order\b", t):
        ops.append(Op("ordering", {"key": "number", "descending": bool(re.search(r"\b(?:decreasing|descending|reverse)\b", t))}))
    elif ends := re.search(r"\b(?P<v>smallest|largest|biggest|greatest)\s+(?:one\s+|number\s+|digit\s+)?(?P<at>on\s+top|at\s+the\s+top"
                           r"|(?:at|on)\s+the\s+(?:bottom|base)|on\s+the\s+(?:left|right)|at\s+the\s+(?:left|right)(?:\s+end)?)\b", t):
        # "smallest on top", "largest at the bottom": the order of the task's labels, by the end where one of them stands
        low_first = (ends.group("v") == "smallest") == bool(re.search(r"bottom|base|left", ends.group("at")))
        ops.append(Op("ordering", {"key": "auto", "descending": not low_first}))
    elif re.search(r"\b(?:ascending|descending|increasing|decreasing)\b|\b(?:largest|biggest|highest|smallest|lowest)\s+(?:one\s+)?first\b"
                   r"|\b(?:high|low)(?:est)?\s+to\s+(?:low|high)(?:est)?\b"
                   r"|\b(?:largest|biggest|greatest|smallest)\s+to\s+(?:the\s+)?(?:smallest|largest|biggest|greatest)\b", t):
        # "descending now", "largest first", "largest to smallest instead": the order of the task's own labels
        ops.append(Op("ordering", {"key": "auto", "descending": bool(re.search(
            r"\b(?:decreasing|descending|largest|biggest|highest|greatest|high(?:est)?\s+to\s+low)\b"
            r"(?!\s+(?:one\s+)?last\b)", re.sub(r"\b(?:smallest|lowest)\s+to\s+(?:the\s+)?(?:largest|biggest|greatest|highest)\b",
                                                   "ascending", t)))}))
    elif re.search(r"\b(?:sort|order|arrange|group)\w*\s+(?:them\s+|it\s+)?by\s+(?:different\s+|their\s+)?colou?rs?\b|\bcolou?r gradient\b|\brainbow\b|\b(?:each|every)\s+(?:row|layer|level)\b[^.;]*\bdifferent colou?r", t):
        ops.append(Op("ordering", {"key": "color", "descending": False}))
    if mats and not reverse and not ncolors:
        ops.append(Op("material", {"to": mats[0] if len(mats) == 1 else "mixed", **({"from": source[0]} if source else {})}))
    move = re.search(r"\b(?:put|move|place|bring)\s+the\s+(?P<sel>(?:[a-z0-9']+\s+){0,2}?[a-z0-9']+)\s+(?:one|block|cube)?\s*(?:at|to|on)\s+(?:the\s+)?"
                     r"(?:very\s+)?(?P<where>top|bottom|base|start|end|beginning)\b(?!\s+(?:of\s+the\s+table|left|right|corner))", t)
    other = re.search(r"\b(?:put|move|place|bring|shift)\s+the\s+(?P<sel>(?:[a-z0-9']+\s+){0,2}?[a-z0-9']+)\s+(?:one|block|cube)?\s*"
                      r"(?:to|at|on)\s+the\s+(?:other|opposite)\s+end\b", t)
    if other and not move and _selector(other.group("sel")):  # "move the purple one to the other end": of the two ends of its order
        move = other
    region = _region_of(t)
    if region:
        from rpg.steer.relations import places_said

        if len(places_said(t) | {region}) > 1:  # "move it to the front left corner and the back left corner": the first
            raise SteerError(f"the edit puts the task in {len(places_said(t) | {region})} places of the table at once "  # had won
                             f"({', '.join(sorted(places_said(t) | {region}))}); say one place, or use --model")
        ops.append(Op("region", {"region": region}))
    if move and _selector(move.group("sel")) and not region:
        at = "other" if move is other else "bottom" if move.group("where") in ("bottom", "base", "start", "beginning") else "top"
        ops.append(Op("move", {"select": _selector(move.group("sel")), "at": at}))
    pattern = re.search(r"\balternat\w*\b", t)
    pattern_colors = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", t)] if pattern else []
    if len(dict.fromkeys(pattern_colors)) >= 2:
        ops.append(Op("pattern", {"colors": list(dict.fromkeys(pattern_colors))}))
    fewer = re.search(r"\b(?:remove|delete|take away|take off|drop|get rid of)\s+(\d+|an?|one)\s+(?:more\s+)?(?:of the\s+)?(?:blocks?|cubes?)\b"
                      r"|\b(?:remove|delete|take away|take off|drop|get rid of)\s+(1|one)(?=(?:\s*,?\s*please)?\s*[.!]?\s*$)"  # "lose one": one
                      r"|\b(\d+|one)\s+(?:fewer|less)\s+(?:blocks?|cubes?)\b", t)
    more_n = re.search(r"\b(?:use|using|with|have|want|need)\s+(\d+)\s+(?:more|extra|additional)\s+(?:blocks?|cubes?)\b"
                       r"|\bmake\s+(?:[a-z]+\s+){0,3}?(\d+)\s+(?:more|extra|additional)(?:\s+(?:blocks?|cubes?))?(?:\s+(?:high|tall|long))?"
                       r"\s*(?:please|pls)?\s*[.!]?\s*$", t)  # "make red tower two more": two added (it had become two)
    by = re.search(r"\b(\d+)\s+(?:more\s+)?(?:blocks?|cubes?|levels?|layers?)\s+(taller|higher|longer|bigger|shorter|lower|smaller)\b", t)
    if fewer:
        k = next(g for g in fewer.groups() if g)
        ops.append(Op("count", {"delta": -(int(k) if k.isdigit() else 1)}))
    elif more_n:  # "can you use 2 more blocks"
        ops.append(Op("count", {"delta": int(more_n.group(1) or more_n.group(2))}))
    elif by:  # "make it 2 blocks shorter"
        ops.append(Op("count", {"delta": int(by.group(1)) * (1 if by.group(2) in ("taller", "higher", "longer", "bigger") else -1)}))
    layer = re.search(r"\b(?:add|put|build|stack)\s+(?:an?\s+|another\s+|one more\s+|the\s+)?(?:\d+(?:st|nd|rd|th)\s+|second\s+|third\s+"
                      r"|fourth\s+|new\s+|extra\s+)?(?:bottom\s+|lower\s+)?(?:row|layer|level|tier)\b(?P<rest>.*)", t) or \
        re.match(r"\s*(?:and\s+|now\s+|plus\s+)?(?:1\s+more|one\s+more|another|an\s+extra|1\s+extra)\s+(?:row|layer|level|tier)\b"
                 r"(?P<rest>.*)", t)  # "one more row"
    if layer and region is None and not re.search(r"\b(?:blocks?|cubes?)\b", re.sub(  # "put the row on the right side": a move
            rf"(?:^\s*of|,)\s+(?:\d+\s+)?(?:(?:{COLOR_RE})\s+)?(?:blocks|cubes)\b", " ", layer.group("rest"))):  # "a third row of (3) red
        # cubes", "another layer underneath, 3 green cubes"
        rest = layer.group("rest")
        counted = re.match(r"\s*of\s+(\d+)\s", rest) or re.search(r",\s+(\d+)\s+(?:[a-z]+\s+)?(?:blocks|cubes)\b", rest)
        below = re.search(r"\b(?:bottom|under|underneath|below|beneath)\b", layer.group(0))
        if re.search(r"\b(?:base|left|right|front|back|beside|next)\b", rest) or (below and re.search(r"\btop\b", rest)) or (
                below and re.search(r"\b(?:above|over|atop|between)\b|\b(?:row|layer|level|tier|course)s?\b", rest)):
            # ("a row of gray cubes beneath the second row", "... above the bottom row": a place among the others)
            raise SteerError(f"'{layer.group(0).strip()}': the builtin steering adds a row or layer on top or at the bottom only; "
                             "state the whole new task")
        color = re.search(rf"\b({COLOR_RE})\b", rest)
        ops.append(Op("add_layer", {"color": canon_color(color.group(1)) if color else None,
                                    **({"n": int(counted.group(1))} if counted else {}), **({"at": "bottom"} if below else {})}))
    adds = [] if layer or (substitution and mats) or any(o.op in ("move", "pattern") for o in ops) else re.finditer(
        r"\b(?P<verb>add|append|include|put|place|stack|set)\b(?P<what>.*?)(?P<where>\bon top\b|\b(?:at|to|on) (?:the )?(?:very |far )?(?:(?:left|right|front|back) end|top|bottom|base|end|start|beginning)\b|"
        r"\b(?:under|underneath|beneath|below)\b|\bto the (?:left|right|end|start)\b|\bon the (?:left|right)\b"
        r"|\b(?:on(?:to)?|over|above|atop)(?= (?:the|it|them|that)\b)(?! the table\b)"
        r"|\b(?:on(?:to)?|over|above|atop)(?= (?:letter|digit) [a-z0-9]\b)"
        rf"|[;,.]|\band\b(?!\s+an?\s+(?:(?:digit|letter|number)\s+)?(?:[a-z0-9]|{COLOR_RE})\b(?!\s+(?:on|to|at|under|next|beside)\b))|$)", t)  # "add a 0 and a 9"
    add = next((a for a in adds if _adds_a_cube(a, t)), None)
    each_end = re.search(r"\b(?:at|on|to)\s+(?:each|both|either)\s+(?:ends?|sides?)\b", t) if add else None
    one = item_sequence(add.group("what")) if each_end else []
    one_each = each_end and re.search(r"\b(?:one|1)\s+(?:at|on|to)\s+(?:each|both|either)\s+(?:ends?|sides?)\b", t) and re.search(
        r"\b(?:2|two)\s+(?:more\s+)?(?:[a-z]+\s+)?(?:cubes|blocks|ones)\b", add.group("what"))  # "two more orange cubes, one at
    # each end": one at each end
    if each_end and len(one) == 1 and (one_each or not re.search(r"\b(?:\d+|two|three|four|pairs?)\b", add.group("what"))):
        # "add a red at each end": that cube at both ends (one of them had been dropped, then the edit refused)
        item = {"color": one[0][0]} if one[0][0] else {"label": one[0][1]}
        ops += [Op("add", {"items": [item], "count": None, "at": end}) for end in ("bottom", "top")]
    elif add:
        what = add.group("what")
        if each_end:  # "add two yellow ones at each end": not read
            raise SteerError(f"'{each_end.group(0)}' puts cubes at two places in one edit, which the builtin steering "
                             "does not read; add one end per edit (\"add a yellow one on the left end\"), or use --model")
        inside = re.search(r"\b(?:right\s+|just\s+|directly\s+|immediately\s+)?(?:after|before|following)\s+the\s+(?:first|second|third|"
                           r"fourth|fifth|last|middle|other)\s+(?:one|letter|cube|block|digit|number|[a-z0-9])\b", t[add.start():])
        if inside:  # "add another O right after the first one": a place inside the structure (it had gone at the end)
            raise SteerError(f"'{inside.group(0)}' puts the cube inside the structure, which the builtin steering adds only at "
                             "an end; say the whole new order (e.g. \"make it spell GOOD\"), or use --model")
        beside = EDIT_BESIDE_RE.search(what)
        second = re.search(r"\b(?:an?|another|one|\d+|new|second|other)\s+(?:[a-z]+\s+){0,2}?" + STRUCTURE_RE, what)
        piece = re.search(r"\b(?:second|another|separate|new|other)\s+(piece|group|set|pair|unit|station|arrangement)\b", t)
        # "add a green cube on a pink cube": two new cubes stacked on each other, a stack of their own (both had gone on top)
        own = re.search(rf"\ban?\s+(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:on|onto|on\s+top\s+of|atop)\s+an?\s+(?:{COLOR_RE})\b", what)
        kind = second.group(1) if second else piece.group(1) if piece else "stack" if own else None
        if kind:  # "add a pyramid of 3 yellow blocks": a second structure, not cubes of this one
            raise SecondStructure(f"'{add.group(0).strip()}' adds a second structure (a {kind}), which the builtin "
                             "steering cannot compose with the first; state the whole new task in the edit, or use --model")
        after = re.search(rf"\s*\b(?:right\s+|just\s+|directly\s+|immediately\s+)?(?P<r>after|following|before)\s+(?P<sel>the\s+"
                          rf"(?:(?:letter|digit)\s+)?(?:[a-z0-9]|{COLOR_RE})(?:\s+(?:one|block|cube))?)(?![\w'])", what)
        beyond = (what[after.end():] + " " + t[add.end():]) if after else ""  # what the edit says past the cube named
        if after:  # "set an S after the T, at the right end": the T is a cube of the task, not one more
            what = what[:after.start()] + " " + what[after.end():]
        m = re.search(r"\b(\d+)\b", re.sub(LABELLED_RE, " ", what))
        n = int(m.group(1)) if m else 1
        items = [{"color": c} if c else {"label": lab} for c, lab in item_sequence(what)]
        where = add.group("where")
        at = "bottom" if re.search(r"bottom|base|under|beneath|below|start|beginning|left", where) else "top"
        if after:  # next in reading order: at the end the cube said stands at (checked when applied)
            end_said = re.search(r"\b(left|right)\s+end\b|\b(bottom|base|top)\b", where + " " + beyond)
            said_at = None if end_said is None else "bottom" if (end_said.group(1) or end_said.group(2)) in ("left", "bottom", "base") \
                else "top"
            at = "bottom" if after.group("r") == "before" else "top"
            if (said_at and said_at != at) or re.search(r"\b(?:after|before|following)\b|\band\s+(?:an?|one|another|the)\b|,\s*(?:an?|one)\s",
                                                         beyond):
                raise SteerError(f"'{add.group(0).strip()} ...' puts the cube next to one end and says another place or a second "
                                 "cube too; say one cube and one end per edit, or use --model")
        side = beside or re.search(r"\b(left|right)\b", where)
        target = re.match(r"\s*(?:of\s+)?(?P<sel>the\s+[a-z0-9' ]+?(?:one|block|cube)s?\b|the\s+(?:top|bottom)\b|(?:the\s+)?(?:[a-z]+\s+)?letter\s+[a-z]\b"
                          rf"|the\s+(?:[a-z]+\s+)?digit\s+\d\b|the\s+(?:{COLOR_RE})\b)", t[add.end():])
        onto = _selector(after.group("sel")) if after else _selector(target.group("sel")) if target and re.search(r"[a-z]", where) \
            else None
        if re.match(r"(?:on(?:to)?|over|above|atop)$", where.strip()) and onto is None:
            onto = {"all": True} if re.match(r"\s*(?:it|them|that|the\s+(?:tower|stack|top))\b", t[add.end():]) else None
            if onto is None:
                return ops  # "put a yellow block on ...": on nothing this reads
        one = rf"(?:the\s+[a-z0-9' ]+?(?:one|block|cube)|(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:one|block|cube))?)"
        gap = re.match(rf"(?P<what>.*?)\bbetween\s+(?P<a>{one})\s+and\s+(?P<b>{one})(?![\w-])", t[add.end("verb"):])
        inserted = (_selector(gap.group("a")), _selector(gap.group("b"))) if gap else None
        middle = re.search(r"\b(?:in\s+the\s+middle|in\s+between|halfway)\b(?!\s+of\s+the\s+(?:table|workspace))", t[add.end("verb"):])
        if middle and not gap:  # "put a white cube in the middle" of a tower: which gap? (it had gone on top)
            raise SteerError(f"'{middle.group(0)}' puts the cube inside the structure without saying between which two cubes; say it "
                             "(e.g. \"add a white cube between the green one and the blue one\"), or use --model")
        both = re.search(r"\band\s+(?:another(?:\s+one)?|one|a\s+[a-z]+\s+(?:one|cube|block))\s+(?:at|on|under|to)\s+(?:the\s+)?"
                         r"(?:bottom|top|base|left|right|end|start|beginning)\b", t[add.end("verb"):])
        if both:  # "add a cube on top and one at the bottom": two places in one edit (the second had been dropped)
            raise SteerError(f"'{both.group(0).strip()}' adds a cube at a second place in the same edit; add one place per edit, "
                             "or use --model")
        if re.search(r"\bsame\s+colou?r\s+as\b", t[add.end("verb"):]):  # "in the same colour as the base": made up before
            raise SteerError("a cube added 'in the same colour as' another is not read by the builtin steering; name its colour, "
                             "or use --model")
        if inserted and all(inserted):  # "add a black cube between the white one and the blue one": in the gap between them
            what = gap.group("what")
            items = [{"color": c} if c else {"label": lab} for c, lab in item_sequence(what)]
            ops.append(Op("add", {"items": items, "count": None if items else 1, "between": list(inserted)}))
        else:
            ops.append(Op("add", {"items": items * (n if len(items) == 1 else 1) if items else [], "count": n if not items else None,
                                  "at": at, **({"side": side.group(0)} if side else {}),
                                  **({"onto": onto} if onto and not onto.get("all") else {}),
                                  **({"end": where.strip()} if re.search(r"[a-z]", where) and not re.match(r"\s*and\b", where) else {})}))
    kept = re.search(rf"\bkeep(?:ing)?\s+(?:the|this|that|my|your|our)\s+(?:same\s+|existing\s+|current\s+)?{STRUCTURE_RE}", t)
    if kept:  # "keep the tower, and ...": the reference must be that structure
        ops.append(Op("keep", {"structure": structure_of_word(kept.group(1))}))
    swap = re.search(r"\bswap\s+(?:the\s+)?(?P<a>(?:(?!\b(?:for|with|by)\b)[a-z0-9' ])+?)\s+(?:block\s+|cube\s+)?and\s+(?:the\s+)?"
                     r"(?P<b>(?:(?!\b(?:for|with|by)\b)[a-z0-9' ])+?)(?:\s+(?:blocks?|cubes?))?(?:\s*$|[;,.])", t)  # ("swap the c for a b and
    # the a for an o": two replacements, not c and a exchanged)
    swap = swap or re.search(r"\b(?:swap|switch|exchange|trade)\s+(?!out\b)(?:the\s+)?(?P<a>(?:(?!\b(?:for|with|by|and|table|patch"
                             r"|of|new|spare|other|another)\b)[a-z0-9 ])+?)\s+with\s+the\s+(?!new\b|spare\b|other\b|extra\b)"
                             r"(?P<b>(?:(?!\b(?:for|with|by|and|table|patch|of|back)\b)[a-z0-9 ])+?)(?:\s*$|[;,.])", t)  # "swap the red cube at
    # the bottom with the yellow cube at the top": the two exchanged (read as a replacement, the red had become yellow, silently);
    # "swap the red cube with a yellow one" stays a replacement
    pair = re.search(r"\b(?:swap|switch|exchange|flip|trade)\s+(?:the\s+)?(?:places\s+of\s+the\s+)?(first|bottom|lowest|top|last|highest|middle"
                     r"|left|leftmost|right|rightmost)\s+(?:two|2)(?:\s+(?:ones|cubes|blocks|letters|digits))?\b", t)
    if pair and not reverse:  # "swap the first two", "swap the top two", "swap the middle two": a pair by its place
        where = {"lowest": "bottom", "highest": "top", "last": "top", "leftmost": "left", "rightmost": "right"}.get(pair.group(1), pair.group(1))
        ops.append(Op("swap", {"a": {"pair": where, "at": 0, "n": 2}, "b": {"pair": where, "at": 1, "n": 2}}))
        swap = None
    if swap and _selector(swap.group("a")) and _selector(swap.group("b")) and not reverse:
        ops.append(Op("swap", {"a": _selector(swap.group("a")), "b": _selector(swap.group("b")),
                               **({"layers": True} if re.search(r"\bcolou?rs?\b", swap.group(0)) and not re.search(
                                   r"\b(?:cube|block|one)s?\b", swap.group(0)) else {})}))  # ("the bottom colour and the top
        # colour": layers; "the bottom cube and the top cube" names one cube each)
    elif re.search(r"\b(?:swap|switch|exchange|flip)\s+(?:the|their|its)\s+(?:2\s+)?colou?rs\b", t) and not reverse:
        ops.append(Op("swap", {"colors": True}))  # "swap the colours": the structure's two colours exchanged
    recolor_all = re.fullmatch(rf"(?:(?:ok|okay|actually|now|maybe|hmm)\s+)*(?:use\s+|try\s+|with\s+|make\s+it\s+)?(?:an?\s+)?(?P<new>{COLOR_RE})"
                               rf"(?:\s+(?:blocks?|cubes?|ones?))?\s+instead\W*", t)
    if recolor_all:
        ops.append(Op("recolor", {"select": {"all": True, "uniform": True}, "to": {"color": canon_color(recolor_all.group("new"))}}))
    instead = re.search(rf"\b(?:use\s+)?(?:an?\s+|the\s+)?(?P<new>{COLOR_RE})(?:\s+(?:block|cube)s?)?\s+(?:instead of|rather than|in place of)\s+(?:the\s+)?(?P<old>{COLOR_RE})\b", t)
    if instead:
        ops.append(Op("recolor", {"select": {"color": canon_color(instead.group("old"))}, "to": {"color": canon_color(instead.group("new"))}}))
    repl = None if instead or swap else re.search(r"\b(?:replace|substitute|swap)\s+(?:the\s+)?(?P<old>.+?)\s+(?:with|for|by)\s+(?:an?\s+|the\s+)?(?P<new>.+)", t) or \
        re.search(rf"\b(?:change|turn|make|paint|recolou?r|colou?r)\s+(?:the\s+)?(?P<old>.+?)\s+(?:to|into)\s+(?!(?:an?\s+|one\s+)?(?:[a-z]+\s+)?"
                  rf"{STRUCTURE_RE})(?:an?\s+|be\s+)?(?P<new>.+)", t) or \
        re.search(rf"\b(?:make|paint)\s+(?:the\s+)?(?P<old>(?:(?!\band\s+(?:add|put|place|stack|make)\b|\badd\b|\bput\b|\bwith\b"
                  rf"|\ban?\s+{STRUCTURE_RE})[^,;.])+?)\s+(?P<new>(?:{COLOR_RE}))\b(?!\s+(?:cubes?|blocks?|ones?|(?:goal\s+)?patch(?:es)?"
                  r"|pads?|mats?)\b)", t)  # ("make it four green cubes on the white patch": the patch's colour, no recolouring)
    # (the cubes made a colour are said within one clause: "make it taller, add a yellow one" recolours nothing)
    repl = repl or re.search(rf"(?P<old>\b(?:the|both|all|each|every|it|they|them|\d+\s+of)\b[a-z0-9' ]*?)\s+(?:to\s+)?{EDIT_SHOULD_BE_RE}"
                             rf"\s+(?:an?\s+)?(?P<new>(?:{COLOR_RE})\b|(?:letter|digit)\s+[a-z0-9]\b)", t) or \
        re.fullmatch(rf"(?:and\s+|also\s+|now\s+)*(?P<old>(?:the|both)\b[a-z0-9' ]*?)\s+(?P<new>{COLOR_RE})[.!]?", t) or \
        re.search(rf"\b(?:like|want|need|have|make|do|redo|build)\s+(?P<old>it|them|the\s+(?:whole\s+)?\w+)\s+(?:all\s+)?in\s+(?P<new>{COLOR_RE})"
                  r"(?:\s+(?:blocks|cubes|instead|please))*\W*$", t)
    blank = next((o for o in ops if o.op == "add" and not o.params.get("items") and o.params.get("count")), None)
    one_said = r"it|that\s+one|this\s+one|the\s+new\s+(?:one|cube|block)"  # (a pronoun in the added cubes' number)
    if repl and not reverse and blank is not None and add is not None and repl.start() > add.start() and re.fullmatch(
            rf"\s*(?:{one_said})\s*" if blank.params["count"] == 1 else r"\s*(?:them|they|those|these|the\s+new\s+(?:ones|cubes|blocks))\s*",
            repl.group("old")):
        colour = re.match(rf"(?:{COLOR_RE})\b", repl.group("new"))  # "add a third cube on top, make it cyan": the added cube's
        if colour:  # colour (the whole task had been recoloured)
            blank.params.update(items=[{"color": canon_color(colour.group(0))}] * blank.params["count"], count=None)
            repl = None
    coloured = next((o for o in ops if o.op == "add" and o.params.get("items")), None)
    if repl and coloured is not None and add is not None and repl.start() > add.start() \
            and re.fullmatch(rf"\s*(?:{one_said})\s*", repl.group("old")):
        raise SteerError(f"'{repl.group(0).strip()}' after '{add.group(0).strip()}' may recolour the cube added, which the edit "
                         "names by colour already, or the whole task; say the added cube's colour once, or use --model")
    if repl and not reverse and re.search(r"\b(?:cubes|blocks|ones|them)\b", repl.group("old")) and re.search(
            r"\b(?:on|in|at)\s+(?:the\s+)?(?:[a-z]+\s+)?patch", repl.group("old")):  # ("the cube on the red patch" is read)
        raise SteerError(f"'{repl.group('old').strip()}' names cubes by the patch they stand on, which the builtin steering does "
                         "not read for a recolouring; name the cubes by colour (e.g. \"make the red cubes green\"), or use --model")
    if repl and not reverse:
        sel, new = _selector(repl.group("old")), _new_item(repl.group("new"))
        bare = re.fullmatch(r"\s*'?([a-z0-9])'?\s*[.!]?", repl.group("new"))
        if sel and "label" in sel and new is None and bare:  # "change the 3 to 5": a label for a label
            new = {"label": bare.group(1).upper()}
        run = re.match(rf"(?:{COLOR_RE})(?:\s*(?:,\s*(?:and\s+)?|\band\s+)(?:{COLOR_RE})\b)+", t[repl.start("new"):])
        listed = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", run.group(0))] if run and sel and "layer" in sel else []
        if sel and new and len(listed) >= 2:  # "make the bottom layer orange, green, orange": each cube of it
            ops.append(Op("recolor", {"select": sel, "to": {"colors": listed}}))
        elif sel and new:
            ops.append(Op("recolor" if "color" in new else "relabel", {"select": sel, "to": new}))
            first = re.search(rf"\b(?:{COLOR_RE})\b|\b(?:letter|digit)\s+[a-z0-9]\b", t[repl.start("new"):])
            rest = t[repl.start("new") + first.end():] if first else ""
            for more in re.finditer(rf"(?:,|;|\band\b)\s+(?:make\s+|paint\s+|change\s+|turn\s+)?(?P<old>the\s+[a-z0-9' ]+?)\s+"
                                    rf"(?:to\s+|into\s+|should\s+be\s+|be\s+)?(?:an?\s+)?(?P<new>(?:{COLOR_RE})\b|(?:letter|digit)\s+[a-z0-9]\b)", rest):
                sel2, new2 = _selector(more.group("old")), _new_item(more.group("new"))  # "... and the bottom layer blue"
                if sel2 and new2:
                    ops.append(Op("recolor" if "color" in new2 else "relabel", {"select": sel2, "to": new2}))
    rm = re.search(r"\b(?:remove|delete|take away|take off|drop|get rid of)\s+(?:the\s+)?(?P<sel>.+?)(?:[;,.]|\band\b|$)", t)
    rm = rm or re.search(r"\b(?:take|lift|pull)\s+(?:the\s+)?(?P<sel>[a-z0-9' ]+?)\s+(?:off|away|out)\b", t)
    top_n = re.search(r"\b(?:remove|delete|take away|take off|drop|get rid of)\s+(?:the\s+)?(?:top|last)\s+(\d+)\s+(?:blocks?|cubes?)\b", t)
    if top_n:  # "remove the top two blocks": the structure shrinks from its end
        ops.append(Op("count", {"delta": -int(top_n.group(1))}))
    elif rm and _selector(rm.group("sel")):
        ops.append(Op("remove", {"select": _selector(rm.group("sel"))}))
    arranged = ARRANGED_RE.search(t)
    if arranged and not any(o.op in ("ordering", "reverse", "pattern", "add", "remove", "recolor") for o in ops):
        # "left to right: blue, red, green": the task's cubes in that order
        listed = re.findall(rf"\b(?:{COLOR_RE})\b|\b\d\b", arranged.group("list") or arranged.group("list2"))
        ops.append(Op("arrange", {"items": [{"label": x} if x.isdigit() else {"color": canon_color(x)} for x in listed],
                                  "way": (arranged.group("way") or arranged.group("way2")).replace(" ", "_")}))
    direction = re.search(r"\b(?:read|reads|go|goes|run|runs|order|arrange\w*|spell\w*|from|it)\s+(?:from\s+)?"
                          r"(left to right|right to left|front to back|back to front)\b", t)
    if direction and not any(o.op in ("ordering", "reverse", "arrange") for o in ops):
        ops.append(Op("direction", {"to": direction.group(1).replace(" ", "_")}))
    flat = re.search(r"\b([23])d\b|\b(flat)\b", t)
    if flat:
        ops.append(Op("dims", {"pyramid_dims": 2 if flat.group(2) else int(flat.group(1))}))
    dims = None if flat else re.search(r"\b(\d+)x(\d+)(?:x(\d+))?\b", t)
    base = re.search(r"\bbase\s+(?:of\s+|to\s+|is\s+|to be\s+)?(\d+)\b|\b(\d+)[- ]wide base\b", t)
    if dims:
        ops.append(Op("dims", {"dims": [int(g) for g in dims.groups() if g]}))
    elif base and not flat:
        ops.append(Op("dims", {"base": int(base.group(1) or base.group(2))}))
    count = EDIT_COUNT_RE.search(t)
    if count and not any(o.op in ("add", "dims", "count", "word", "colors", "outliers") for o in ops):
        dim = count.group("dim") or count.group("dim2")
        grow = re.search(r"\b(?:(taller|higher|longer|bigger|larger)|shorter|smaller|lower)\s+to\s+\d", t)
        ops.append(Op("count", {"count": int(count.group("n") or count.group("n1") or count.group("n2")),
                                **({"dim": dim} if dim else {}),
                                **({"grow": 1 if grow.group(1) else -1} if grow else {})}))  # "taller, 4 blocks"
    elif re.search(r"\b(?:double|triple|halve)\b", t) and not any(o.op in ("add", "dims", "remove", "count") for o in ops):
        factor = {"double": 2.0, "triple": 3.0, "halve": 0.5}[re.search(r"\b(double|triple|halve)\b", t).group(1)]
        ops.append(Op("count", {"factor": factor}))
    elif re.search(r"\b(?:taller|higher|longer|bigger|larger)\b", t) and not any(o.op in ("add", "dims", "count") for o in ops):
        ops.append(Op("count", {"delta": 1}))
    elif re.search(r"\b(?:shorter|smaller|lower)\b", t) and not any(o.op in ("remove", "dims", "count") for o in ops):
        ops.append(Op("count", {"delta": -1}))
    shape = re.search(r"\b(?:make|turn|arrange|rearrange|build|form|put|change|reshape|stack|place|line up|lay out|lay|set out|use|do|spell"
                      r"|convert|transform|rebuild|redo|rework|refactor|redraw|recast|reorgani[sz]e)\b[^.;]*?\b(?:into|as|in|to be|to)?\s*(?:an?\s+|one\s+|a\s+single\s+)(?:\d+x\d+(?:x\d+)?\s+|(?:long|tall|single|straight|big)\s+)?"
                      rf"{STRUCTURE_RE}", t)
    stack_all = re.search(r"\b(?:stack|pile)\s+(?:them|all|everything|(?:all\s+)?the\s+(?:blocks|cubes))(?:(?:\s+|\s*,\s*)(?:up|instead|together"
                          r"|on top of each other|on top of one another|" + _REVERSE_ORDER +
                          r"(?:\s+(?:of|to|from)\s+the\s+(?:row|line))?|in\s+the\s+order\s+of\s+the\s+(?:row|line)"
                          r"|(?:in|at|on)\s+the\s+(?:[a-z]+\s+){0,2}?(?:corner|half|side|cent(?:er|re)|middle)))*(?:\W*$|\s*[,;]\s*(?=(?:the\s+)?(?:smallest|largest|biggest|lowest|highest)"
                          r"(?:\s+(?:one|number|digit|letter))?\s+(?:on\s+top|at\s+the\s+(?:top|bottom)|first|last)\W*$))", t) or (
        SAME_ORDER_RE.search(t) and re.search(r"\b(?:stack|pile)\s+(?:them|all|everything)\b", t))  # "stack them, in the same order"
    end_role = rf"(?:\s*,?\s*(?:with\s+)?(?:the\s+)?(?P<end_c>{COLOR_RE})\s+(?:block\s+|cube\s+|one\s+)?(?:at|on)\s+(?:the\s+)?" \
        r"(?P<end_w>bottom|base|top|left|right))?"  # "now as a tower, red at the bottom": the order kept from that end
    bare_shape = re.fullmatch(r"(?:(?:now|ok|okay|actually|then|and|maybe|rather)\s+)*"
                              r"(?:(?:(?:the\s+)?same|keep\s+(?:the\s+)?(?:same\s+)?)\s*(?:blocks|cubes|bricks|colou?rs)\s*,?\s*(?:but\s+)?)?"
                              r"(?:as\s+|in\s+|into\s+)?an?\s+(?:\d+x\d+(?:x\d+)?\s+)?"
                              + STRUCTURE_RE + r"(?:\s+(?:instead|now|please))*" + end_role + r"\W*", t)
    if stack_all is None:  # "stack them with blue at the bottom"
        stack_all = re.fullmatch(r"(?:(?:now|ok|okay|actually|then|and|please)\s+)*(?:stack|pile)\s+(?:them|all|everything|(?:all\s+)?the\s+"
                                 r"(?:blocks|cubes))(?:\s+up)?" + end_role + r"\W*", t)
    ended = next((m for m in (bare_shape, stack_all) if m is not None and "end_c" in m.re.groupindex and m.group("end_c")), None)
    ended_order = {"keep_order": True, "end": (canon_color(ended.group("end_c")), ended.group("end_w"))} if ended else {}
    wall = re.search(r"\b(?:make|turn|build|form|change|rearrange|arrange|reshape|into|as)\b[^.;]*?\ban?\s+wall\b", t)
    wide, high = re.search(r"\b(\d+)\s+(?:blocks?\s+|cubes?\s+)?wide\b", t), re.search(r"\b(\d+)\s+(?:blocks?\s+|cubes?\s+)?(?:high|tall)\b", t)
    if wall and not any(o.op in ("add", "recolor", "relabel", "remove") for o in ops):
        if not (wide and high):
            raise SteerError(f"'{wall.group(0).strip()}': say how wide and how high the wall is (e.g. \"3 wide and 2 high\")")
        ops = [o for o in ops if o.op != "count"]
        ops.append(Op("structure", {"to": "block", "dims": [1, int(wide.group(1)), int(high.group(1))]}))
    elif shape and not any(o.op in ("add", "recolor", "relabel", "remove") for o in ops):
        ops.append(Op("structure", {"to": structure_of_word(shape.group(1)), **_kept_order(t), **_stated_on(t)}))
    elif stack_all and not any(o.op in ("add", "recolor", "relabel", "remove") for o in ops):
        ops.append(Op("structure", {"to": "tower", **_kept_order(t), **_stated_on(t), **ended_order}))  # "stack them": the task's cubes
    elif bare_shape and not any(o.op in ("add", "recolor", "relabel", "remove") for o in ops):
        ops.append(Op("structure", {"to": structure_of_word(bare_shape.group(1)), **ended_order}))  # "now a line instead"
    role = re.search(rf"\b(?:{COLOR_RE}|[a-z0-9])(?:\s+(?:cube|block|one)s?)?\s+(?:is\s+|goes\s+)?(?:at|on|in)\s+(?:the\s+)?(?:very\s+)?"
                     r"(?:bottom|top|base|middle|(?:left|right)(?:\s+end)?)\b(?!\s+of\s+the\s+table)", t)
    if role and any(o.op == "structure" and not o.params.get("end") for o in ops) and re.search(
            r"\b(?:the|those|these)\s+(?:[a-z0-9]+\s+)?(?:cubes|blocks)\b", t):  # (of "make it a tower, blue at the bottom"
        # the steering reads the role with the cubes, :func:`rpg.steer.steering._pivot_with_roles`)
        # "stack the cubes into one tower, red at the bottom": a role the structure read leaves out (the tower had been in
        # any order, silently)
        raise SteerError(f"'{role.group(0)}' gives a cube a place in the new structure, which the change read (the task's cubes "
                         "in a structure, in no order) leaves out; say the whole order (e.g. \"from bottom to top: red, green, "
                         "blue\"), or use --model")
    trail = re.search(rf"(?:,|;|\band\b)\s+(?:make\s+)?(?P<old>the\s+(?:top|bottom|first|last|middle|base|lowest|highest)"
                      rf"(?:\s+(?:one|cube|block|layer|row|level))?)\s+(?:is\s+|should\s+be\s+|to\s+)?(?P<new>{COLOR_RE})\s*[.!]?\s*$", t)
    trailed = _selector(trail.group("old")) if trail and not any(o.op in ("recolor", "relabel", "reverse") for o in ops) else None
    if trailed:  # "make it four, and the top one orange": the count, then the cube at that place that colour
        ops.append(Op("recolor", {"select": trailed, "to": {"color": canon_color(trail.group("new"))}}))
    recolors = [o for o in ops if o.op == "recolor" and set(o.params["select"]) == {"color"} and "color" in o.params["to"]]
    if len(recolors) == 2 and recolors[0].params["select"]["color"] == recolors[1].params["to"]["color"] \
            and recolors[1].params["select"]["color"] == recolors[0].params["to"]["color"]:
        # "make the red one blue and the blue one red": the two exchanged at once (applied in turn, both had become red)
        ops = [o for o in ops if o not in recolors] + [Op("swap", {"a": {"color": recolors[0].params["select"]["color"]},
                                                                   "b": {"color": recolors[1].params["select"]["color"]}})]
    word = next((o.params["word"] for o in ops if o.op == "word"), None)
    if word:  # "make it ROBOTS, add an S": the added letters say how the new word is made, not more letters
        ops = [o for o in ops if not (o.op == "add" and o.params.get("items") and all(
            "label" in i and i["label"].upper() in word for i in o.params["items"]))]
    return ops


SAME_ORDER_RE = re.compile(r"\b(?:in\s+the\s+same\s+order|keep(?:ing)?\s+the\s+(?:same\s+)?order|same\s+order"
                           r"|in\s+the\s+(?:row|line|tower|stack)'s\s+order|in\s+the\s+order\s+of\s+the\s+(?:row|line|tower|stack))\b")
"""A structure turned into another that keeps its cubes' order ("stack them in the same order")."""


def _stated_on(t: str) -> dict:
    """``{"on": [(top, bottom), ...]}`` for each "X on top of Y" a structure edit states between
    its cubes ("put them in a stack instead, H on top of I"), names as written (a colour or a
    label); else ``{}``."""
    pairs = re.findall(rf"\b(?:the\s+)?(?:letter\s+|digit\s+)?((?:{COLOR_RE})|[a-z0-9])(?:\s+(?:block|cube|one))?\s+"
                       rf"(?:on\s+top\s+of|on|above|over|atop)\s+(?:the\s+)?(?:letter\s+|digit\s+)?((?:{COLOR_RE})|[a-z0-9])\b", t)
    return {"on": pairs} if pairs else {}


def _kept_order(t: str) -> dict:
    """``{"keep_order": True}`` and the end a colour is given ("red at the bottom": ``{"end":
    ("red", "bottom")}``) when a structure edit keeps the cubes' order; else ``{}``."""
    if not SAME_ORDER_RE.search(t) and not re.search(rf"\b{_REVERSE_ORDER}\b", t):
        return {}  # ("stack them in reverse order" of a row: its order kept, then reversed; the order had been lost)
    role = re.search(rf"\b({COLOR_RE})\s+(?:block\s+|cube\s+|one\s+)?(?:at|on)\s+(?:the\s+)?(bottom|base|top|left|right)\b", t)
    return {"keep_order": True, **({"end": (canon_color(role.group(1)), role.group(2))} if role else {})}


TASK_NOUN_RE = re.compile(r"\b(?:towers?|stacks?|stacked|lines?|rows?|circles?|circular|rings?|pyramids?|grids?|squares?|"
                          r"piles?|bunch(?:es)?|groups?|spell|word|equation|patch(?:es)?|order|on top of|onto|left|right|"
                          r"behind|front|between|next to|beside|rotate|faces?)\b|\b\d+x\d+\b")
"""A whole task names a structure, a goal or a relation; an edit may name none."""


def looks_standalone(t: str) -> bool:
    """True when a normalised edit reads as a whole task rather than a change to one (an
    addition, "also ...", "and a yellow block on the blue one", keeps the task; an order alone,
    "left to right: blue, red, green", orders the task's cubes)."""
    return not ANAPHORA_RE.search(t) and not EDIT_ADDITIVE_RE.search(t) and not re.match(r"\s*and\b", t) \
        and not EDIT_CONTINUES_RE.match(t) and not BARE_ORDER_RE.match(t) and bool(TASK_NOUN_RE.search(t))


def names_cubes(t: str) -> bool:
    """Whether a normalised edit says which cubes its task has (a colour, a label, a count, letters
    or digits): one that names none ("as a row", "same cubes but as a circle") is the task's own
    cubes in another structure, never a new task of cubes nobody named."""
    return bool(re.search(rf"\b(?:{COLOR_RE}|{COUNT_WORD_RE}|\d+(?:x\d+)*|colou?r(?:s|ed)?|letters?|digits?|numbers?|word|spell\w*)\b|'[a-z]+'", t))


IN_PLACE_MOVE_RE = re.compile(
    r"^\s*(?:(?:now|ok(?:ay)?|so|and|then|actually|just)[\s,]+)*(?:put|move|place|bring|shift|slide)\s+the\s+"
    r"(?P<sel>(?:[a-z0-9']+\s+){0,2}?[a-z0-9']+)\s+(?:one|block|cube)?\s*(?:at|to|on|in|into)\s+the\s+(?:very\s+)?"
    r"(?P<where>middle|centre|center|left\s+end|right\s+end|far\s+left|far\s+right)(?:\s+of\s+the\s+(?:row|line|tower|stack))?"
    r"\s*(?:instead|now|please)?\s*[.!]?\s*$")
"""An edit that moves one cube of a row or tower to its middle or to an end said by side ("put the white one in the
middle", "move the blue cube to the left end"): read by :func:`in_place_move` for a structure task only (of cubes related
one by one, "the middle" is the table's)."""

_IN_PLACE = {"middle": "middle", "centre": "middle", "center": "middle", "left end": "left", "far left": "left",
             "right end": "right", "far right": "right"}


def in_place_move(edit: str) -> Op | None:
    """The ``move`` operation of an edit that puts one cube of the structure in its middle or at its left or right end
    (:data:`IN_PLACE_MOVE_RE`), or None."""
    m = IN_PLACE_MOVE_RE.match(normalize_edit(edit))
    sel = _selector(m.group("sel")) if m else None
    return Op("move", {"select": sel, "at": _IN_PLACE[re.sub(r"\s+", " ", m.group("where"))]}) if sel else None


def intent_of_ops(ops: list[Op], spec: TaskSpec | None = None) -> str:
    """The strongest intent of the operations (a structure op to the reference's own
    structure, or a material op to its own material, changes nothing and does not count)."""
    ops = [o for o in ops if not (spec is not None and o.op == "structure" and o.params["to"] == spec.structure)]
    ops = [o for o in ops if not (spec is not None and o.op == "material" and o.params["to"] == spec.material)]  # "add the
    # digit cube 7" to digit cubes: their material kept
    if spec is not None:  # "add a 5 and keep it largest first": the order it has, kept
        kept = {"auto": "label" if spec.material == "letters" else "number"}
        ops = [o for o in ops if not (o.op == "ordering" and spec.ordering == kept.get(o.params["key"], o.params["key"])
                                      and bool(spec.descending) == o.params.get("descending", False) and len(ops) > 1)]
    old = (spec.word or "".join(it.label or "" for it in spec.items)) if spec is not None else ""
    grown = [o for o in ops if o.op == "word" and old and len(o.params["word"]) > len(old) and _keeps_in_order(old, o.params["word"])]
    if grown and len(grown) == len(ops):  # "make it DOGS", "put a T before it so it says TONE": letters added to the word
        return "extend"
    return max((OP_INTENT[o.op] for o in ops), key=INTENTS.index, default="tweak")


def _keeps_in_order(old: str, new: str) -> bool:
    """Whether ``new`` is ``old`` with letters added anywhere ("CAT" -> "CART", "DOG" -> "DOGS"): a subsequence."""
    rest = iter(new)
    return all(ch in rest for ch in old)


def intent_of_standalone(new: TaskSpec | None, ref: TaskSpec | None) -> str:
    """Tweak, Modify or Pivot for a whole task stated as an edit, compared with its reference."""
    if new is None or ref is None or new.structure != ref.structure:
        return "pivot"
    if (new.material, new.ordering, new.descending, new.layer_colors, new.piles_by, new.outliers, new.word) != \
            (ref.material, ref.ordering, ref.descending, ref.layer_colors, ref.piles_by, ref.outliers, ref.word):
        return "modify"
    return "tweak"


def _caused_motion_in_edit(m: re.Match) -> str:
    """The verb of a caused-motion clause of an edit (:data:`~rpg.schema.lexicon.CAUSED_MOTION_RE`: "ferry the tower to the
    back", "park a green cube next to ...") as "move" of what the task has ("the ...") and "put" of a cube it adds, when
    :func:`~rpg.schema.reading.moving_verb` holds; as said otherwise."""
    if EDIT_OWN_VERB_RE.fullmatch(m.group("v")) or not moving_verb(m.group("v")):
        return m.group(0)  # ("add a yellow block to the left": the steering's own verb, read as itself)
    verb = "move" if re.match(r"(?i)(?:the|both|all)\b", m.string[m.end():]) else "put"
    return f"{m.group('pre')}{verb} "


def interpret(edit: str) -> EditPlan:
    """Read an edit into a plan (reference cue, operations or a whole new task).

    A closing clause saying the other cubes keep their colour ("make both ends orange, the ones in
    between stay blue": :data:`EDIT_REST_STAYS_RE`) becomes a ``rest`` operation that checks it. An
    opening that says the count again ("same five but reversed": :data:`EDIT_SAME_COUNT_RE`) and the task's
    letters or digits named ("same letters but reversed", "stack the letters instead, ...") become
    :attr:`EditPlan.checks`, which :func:`check_said` verifies against the version built on.

    Raises:
        SteerError: empty edit; such a clause beside no recolour.
    """
    edit, aside = reasons_set_aside(edit)
    if aside:  # "That's too much for today. Leave out the yellow cube.": the change read without its reason
        return replace(interpret(edit), set_aside=aside)
    edit, voice = drop_voice_chunks(edit, labels=False)  # "Add two more yellow cubes to the blue patch, a school of guppies.": the voice's
    if voice:  # chunk, inert by the test a task's is held to
        return replace(interpret(edit), set_aside=tuple(voice))
    swapped = SWAPPED_THEN_SAID_RE.match(edit)
    if swapped and swapped.group("label") and EDIT_LABEL_RE.sub(edit_label_dropped, f"{swapped.group('label')}: swap") != "swap":
        swapped = None  # a label that may change the edit ("Time permitting: swap them, ..."): read, or refused, below
    try:
        said = interpret(edit[swapped.end():]) if swapped else None
    except BadInput:  # "swap them, please": no statement after it
        said = None
    if said is not None and said.standalone and not said.fresh and names_cubes(normalize_edit(said.text)):
        # "Swap them over like switching kegs: white on the green patch, black on the red patch.": the exchange said in full
        return replace(said, checks=(*said.checks, ("swapped", True)))
    plan = _interpret_material(edit)
    _refuse_a_sentence_unread(edit, plan)
    _refuse_a_place_before_or_after_resizing(edit, plan)
    kept = COLOURS_KEPT_RE.search(edit)
    if kept and any(o.op == "recolor" for o in plan.ops):  # "make it a row instead, same colours left to right, red first":
        # 'red first' had been read as every cube made red
        raise SteerError(f"'{kept.group(0)}' in the edit \"{edit.strip()[:80]}\" keeps the colours, and the edit reads as a "
                         "change of colour too; say the one change (e.g. \"make it a row, red at the left end\"), or use --model")
    return plan


_CHANGE_CLAUSE_SPLIT = (r"\s*(?:,\s*and\s+(?:then\s+)?|,\s*then\s+|;\s*|\s+and\s+(?:then\s+)?|\s+then\s+)(?=(?:also\s+|please\s+)?"
                        rf"(?:{EDIT_CLAUSE_VERBS})\s)")
"""Where an edit's clauses each begin with a change verb ("make the top cube black and add one"): each is read alone too
(:func:`_refuse_a_sentence_unread`), so that no change said is dropped (the addition had been, silently)."""


_UNREAD_EDIT_SHAPES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"(?i)(?:\band|\bthen|,)\s+the\s+[^,.;!?]{1,40}?\s+(?:is|are|gets?|should\s+be|must\s+be)\s+(?:removed|replaced|moved"
                r"|swapped|taken\s+(?:away|off|out)|deleted|added|painted|recolou?red)\b"),
     "a change said passively after another (\"... and the rightmost gets removed\") is not read beside it"),
    (re.compile(r"(?i)\bthe\s+(?!(?:tower|stack|row|line|pyramid|wall|pile|circle|grid|whole|entire|structure|task|thing|same)\b)"
                r"[a-z ]{1,30}?\s+(?:is|are|looks?|seems?|reads?)\b[^.;!?]*?[,;.]\s*(?:so\s+|just\s+|please\s+)*(?:make|paint|turn"
                r"|colou?r|change|recolou?r)\s+(?:it|them)\b"),
     "'it'/'them' after a clause that names part of the task may be that part or the whole task"),
    (re.compile(r"(?i)^\s*the\s+(?:[a-z]+\s+){0,2}(?:cube|block|one)\b[^.;:!?]*?[,;]\s*(?:so\s+|just\s+|please\s+)*"
                r"(?:make|paint|turn|colou?r|change|recolou?r|swap|replace|remove|move)\s+it\b"),
     "'it' may be the cube the clause before it names or the whole task, and that clause says more than which cube"),
    (re.compile(r"(?i)\b(?:add|put|place|append)\s+(?:" + COUNTED_RUNS_RE.pattern + ")"), "runs of counted cubes in one change (\"two yellow then one white\") are not read one by one"),
    (re.compile(r"(?i)\b(?:\d+|two|three|four|five|six|a\s+couple\s+of)\s+\d\s+(?:cubes|blocks)\b"),
     "one digit is on one cube: several cubes with one label cannot be made"),
    (re.compile(rf"(?i)\b(?:add|put|place|stack)\s+(?:some\s+|more\s+)?(?:{COLOR_RE})\s+(?:cubes|blocks)\b"),
     "cubes of a colour added without their count: how many is not said"),
)
"""Edit shapes the builtin steering does not read whole, each with why: refused rather than applied in part (each had been
read silently wrong: the passive change dropped, every cube recoloured, the runs' counts merged, a run of digits made up,
one cube added for a plural)."""


def _refuse_unread_shapes(edit: str) -> None:
    """Refuse an edit of a shape in :data:`_UNREAD_EDIT_SHAPES`.

    Raises:
        SteerError: naming the shape and the words."""
    for pattern, why in _UNREAD_EDIT_SHAPES:
        m = pattern.search(edit)
        if m:
            raise SteerError(f"in \"{edit.strip()[:80]}\": {why} ('{m.group(0).strip()}'); say each change in an edit of its "
                             "own, naming the cubes, or use --model")


def _refuse_a_place_before_or_after_resizing(edit: str, plan: EditPlan) -> None:
    """Refuse an edit that resizes the structure and picks a cube by its place in it ("Make the top cube black, then make it
    bigger"): the top before the change or after it is not said (the cube added had been recoloured, the old top kept).

    Raises:
        SteerError: a count or size change beside a cube picked by its place."""
    placed = [o for o in plan.ops if isinstance(o.params.get("select"), dict) and o.params["select"].get("position")]
    if not placed or not any(o.op in ("count", "dims", "add") for o in plan.ops):
        return
    clauses = [x for x in re.split(r"(?<=[.!?])\s+|" + _CHANGE_CLAUSE_SPLIT + r"|,\s*(?:and\s+)?(?:then\s+)?", (edit or "").strip())
               if x and x.strip(" .!?")]
    kinds = []
    for clause in clauses:
        try:
            kinds.append({o.op if o.op != "dims" else "count" for o in _interpret_material(clause).ops})
        except BadInput:
            kinds.append(set())
    first = {op: next((k for k, ops in enumerate(kinds) if op in ops), None) for op in ("count", "add")}
    at = min((k for k, ops in enumerate(kinds) if ops & {o.op for o in placed}), default=None)
    # the ops apply resize first, then recolour and the like, then additions: a place said before a resize, or after an
    # addition, would be read against the other structure ("Make the top cube black, then make it bigger"; "add a black
    # cube on top then make the top cube white")
    resized = at is not None and ((first["count"] is not None and at < first["count"]) or (first["add"] is not None and first["add"] < at))
    if resized:
        raise SteerError(f"the edit \"{edit.strip()[:80]}\" resizes the structure and picks the {placed[0].params['select']['position']} "
                         "cube: before or after the change is not said; say each change in an edit of its own, or use --model")


def _refuse_a_sentence_unread(edit: str, plan: EditPlan) -> None:
    """Refuse an edit of several sentences when one of them, read alone, asks for a change that the whole edit's reading
    lacks ("Make the top one green. Add one.": the addition had been dropped, the recolour alone applied).

    Raises:
        SteerError: a sentence's change is not among those read.
    """
    sentences = [x for x in re.split(r"(?<=[.!?])\s+|" + _CHANGE_CLAUSE_SPLIT, (edit or "").strip()) if x and x.strip(" .!?")]
    if len(sentences) < 2 or plan.standalone or plan.fresh:
        return
    read = {o.op for o in plan.ops}
    said = 0  # the changes the sentences ask for one by one ("Remove the top one. Remove the bottom one." asks two)
    for sentence in sentences:
        if len(re.findall(r"[A-Za-z0-9]+", sentence)) < 2 or not EDIT_SENTENCE_CHANGE_RE.search(sentence):
            continue  # "bigger. 4 by 4", "cool. put ...", "thanks": a word alone or chat asks no change of its own
        try:
            alone = _interpret_material(sentence)
        except BadInput as exc:  # "Make the top one green. Add one.": a sentence not read alone is no part of the change read
            raise SteerError(f"the edit \"{edit.strip()[:80]}\" has a sentence that is not read as a change: '{sentence.strip()}' "
                             f"({str(exc).splitlines()[0][:120]}); say one change per edit, or use --model") from None
        said += sum(o.op not in ("count", "dims") for o in alone.ops)  # (a count said twice, "shorter? Just two", is one)
        missing = {o.op for o in alone.ops} - read
        if read & {"add", "remove"}:  # "make it taller and add a yellow one on top": the count the addition changes
            missing -= {"count"}
        unread = not alone.ops and not alone.standalone and not alone.fresh and alone.cue.kind == "current" and bool(read)
        if missing or unread or (alone.standalone and not alone.fresh and read):
            raise SteerError(f"the edit \"{edit.strip()[:80]}\" asks for a change in '{sentence.strip()}' that its reading as one "
                             f"edit lacks ({', '.join(sorted(missing)) or 'a change of its own'}); say one change per edit, or use "
                             "--model")
    if said > sum(o.op not in ("count", "dims") for o in plan.ops):
        raise SteerError(f"the edit \"{edit.strip()[:80]}\" asks for {said} changes in its sentences, and its reading as one edit "
                         f"makes {len(plan.ops)}; say one change per edit, or use --model")


def _interpret_material(edit: str) -> EditPlan:
    """:func:`interpret` past the reasons set aside, with what the edit says the task has as checks (:func:`check_said`):
    its letters or digits ("same letters but ...") and the one structure it names ("the row goes on the right side")."""
    kept = re.search(r"(?i)\bsame\s+(?P<m>letter|digit|number)s?\b", edit or "")
    plan = _interpret_counted(edit)
    word = next((o for o in plan.ops if o.op == "word"), None)
    if word is not None and any(o.op == "reverse" for o in plan.ops):  # "Reverse it so it reads GOD": the word said is the
        # reversal's result (reversing it too had given the word back, "no change"); the old word reversed is checked
        plan = replace(plan, ops=[o for o in plan.ops if o.op != "reverse"], checks=(*plan.checks, ("reversed", word.params["word"])))
    if kept:  # "same letters but reversed": the task's cubes are letters, checked
        plan = replace(plan, checks=(*plan.checks, ("material", _MATERIAL_WORDS[kept.group("m").lower()])))
    nth = re.search(rf"(?i)\ban?\s+(?P<k>second|third|fourth|fifth|sixth)\s+(?P<c>{COLOR_RE})\b", edit or "")
    if nth:  # "throw a third purple into the heap": the task has two purple cubes (checked; of one, two had been made)
        had = {"second": 1, "third": 2, "fourth": 3, "fifth": 4, "sixth": 5}[nth.group("k").lower()]
        plan = replace(plan, checks=(*plan.checks, ("colour count", (canon_color(nth.group("c").lower()), had))))
    of_order = re.search(r"(?i)\border\s+(?:of|as)\s+the\s+(row|line|tower|stack)\b|\bthe\s+(row|line|tower|stack)'s\s+order\b", edit or "")
    if of_order and not plan.standalone and not plan.fresh:  # "stack them in reverse order of the row": the task is that row
        kind = _structure_named(of_order.group(1) or of_order.group(2))  # (of a tower, the tower had been reversed)
        if kind:
            plan = replace(plan, checks=(*plan.checks, ("structure", kind)))
    if not plan.standalone and not plan.fresh and not any(o.op in ("structure", "keep") for o in plan.ops):
        named = re.findall(r"(?i)\bthe\s+(?:whole\s+|entire\s+)?(tower|stack|row|line|pyramid|wall|grid|circle|ring|pile)\b(?!\s+of\b)",
                           f"{edit or ''} {plan.text}")  # (as said and as rewritten: "same row but on the left")
        kinds = sorted({k for w in named if (k := _structure_named(w))})
        if len(kinds) == 1:  # "the row goes on the right side": the task's structure is a row (checked; a tower had been moved)
            plan = replace(plan, checks=(*plan.checks, ("structure", kinds[0])))
    return plan


def _structure_named(word: str) -> str | None:
    """The structure kind a word names ("row" -> "line", "wall" -> "block"), or None for a word of no registered kind."""
    if re.fullmatch(r"(?i)walls?", word):
        return "block"  # a wall is read back as a block of cubes (rpg.schema.structures)
    try:
        return structure_of_word(word)
    except KeyError:
        return None


def reasons_set_aside(edit: str) -> tuple[str, tuple[str, ...]]:
    """``edit`` without the sentences that say why the change is made (:data:`EDIT_REASON_SENTENCE_RE`: "That's too much
    for today.", "She's good at this now."; :data:`EDIT_PERSON_REASON_RE`: "Testers say three is clutter."), and those
    sentences; the edit as it is when no other sentence is left or when such a sentence holds anything that may change the
    edit (:data:`EDIT_REASON_HAZARD_RE`, :data:`EDIT_PERSON_REASON_HAZARD_RE`).  A first sentence that judges one cube by
    its colour (:data:`EDIT_CUBE_REASON_RE`: "The orange's too loud.") before a change that says "it" once: "it" is that
    cube."""
    sentences = [x for x in re.split(r"(?<=[.!?])\s+", (edit or "").strip()) if x]
    if len(sentences) < 2:
        return edit, ()
    cube = EDIT_CUBE_REASON_RE.match(sentences[0])
    later = " ".join(sentences[1:])
    if cube and len(sentences) == 2 and len(re.findall(r"(?i)\bit\b", later)) == 1 and not re.search(
            r"(?i)\b(?:with|for|by|to|into|as|on|onto|under|beside|next\s+to)\s+it\b", later) and not re.search(
            rf"(?i)\b(?:{COLOR_RE})\s+(?:one|cube|block)\b(?!\s*$)|\bthe\s+(?:{COLOR_RE})\b", later.split(" it ")[0]):
        # "The orange's too loud. Replace it with a gray one.": "it" is the cube judged
        return re.sub(r"(?i)\bit\b", f"the {cube.group('c').lower()} one", later, count=1), (sentences[0],)
    reasons = tuple(x for x in sentences if (EDIT_REASON_SENTENCE_RE.match(x) and EDIT_REASON_JUDGEMENT_RE.search(x)
                                             and not EDIT_REASON_HAZARD_RE.search(x.lower()))
                    or (EDIT_EXCLAMATION_RE.match(x) and not EDIT_REASON_HAZARD_RE.search(x.lower())  # "Cut!", "Beautiful."
                        and not EDIT_SENTENCE_CHANGE_RE.search(x) and not EDIT_EXCLAMATION_HAZARD_RE.search(x))
                    or (EDIT_PERSON_REASON_RE.match(x) and not EDIT_PERSON_REASON_HAZARD_RE.search(x.lower())))
    if not reasons or len(reasons) == len(sentences):
        return edit, ()
    return " ".join(x for x in sentences if x not in reasons), reasons


_MATERIAL_WORDS = {"letter": "letters", "digit": "digits", "number": "digits"}
"""The word an edit names the task's labelled cubes by -> their material."""


def check_said(plan: EditPlan, schema: TaskSchema) -> None:
    """Check what the edit says the version it builds on has (:attr:`EditPlan.checks`): its count of cubes, its letters or
    digits, its structure (a wall is read back as a block; a tower of a relational task is its stack).

    Raises:
        SteerError: the version has another count or other cubes.
    """
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    labels = [a.label or "" for a in cubes]
    material = "letters" if labels and all(x.isalpha() for x in labels) else "digits" if labels and all(x.isdigit() for x in labels) \
        else "colors"
    for kind, value in plan.checks:
        if kind == "count" and value != len(cubes):
            raise SteerError(f"the edit says the version it builds on has {value} cubes, but it has {len(cubes)}; name the "
                             "version to build on, or say the change without the count")
        if kind == "structure":
            spec = split(schema)[0]
        if kind == "structure" and spec is not None and spec.structure != value:
            value = "wall" if value == "block" else value
            raise SteerError(f"the edit names the task's {value}, but the version it builds on is a {spec.structure}; name "
                             "the structure the task has, or say the change another way")
        if kind == "structure" and value != "block" and spec is None and not (value == "tower" and any(
                type(p).__name__ == "Stack" for p in schema.goal_predicate().conjuncts())):
            raise SteerError(f"the edit names the task's {value}, but the version it builds on has none ({schema.goal_summary}); "
                             "say the change of its cubes, or state the whole new task")
        if kind == "reversed":
            words = [p.text for p in schema.goal_predicate().walk() if isinstance(p, Reads)]
            if len(words) != 1 or words[0][::-1] != value:
                raise SteerError(f"the edit reverses the word so it reads '{value}', but the version it builds on reads "
                                 f"{' and '.join(repr(w) for w in words) or 'no word'}; say the new word alone (e.g. \"make "
                                 f"it spell {value}\"), or use --model")
        if kind == "colour count" and sum(a.color == value[0] for a in cubes) != value[1]:
            nth = {1: "second", 2: "third", 3: "fourth", 4: "fifth", 5: "sixth"}[value[1]]
            raise SteerError(f"the edit adds a {nth} {value[0]} cube, but the version it builds on has "
                             f"{sum(a.color == value[0] for a in cubes)}; say how many to add (e.g. \"add another {value[0]} cube\")")
        if kind == "material" and value != material:
            raise SteerError(f"the edit names the task's {value}, but the version it builds on has {material}; name the cubes "
                             "the task has")


_TASK_CUBES_COUNTED_RE = re.compile(
    r"(?i)\b(?P<v>stack|put|arrange|pile|line\s+up|place|set|build)\s+(?:all\s+)?(?:those|these|the)\s+(?P<n>\d+|two|three|four|five"
    r"|six|seven|eight|nine|ten)\s+(?:cubes|blocks)\s+(?P<p>into|in|as)\s+(?:one|a|a\s+single|just\s+one)\s+"
    r"(?P<s>tower|stack|row|line|pile|heap|column)(?=\s*(?:instead\s*)?[.!]?\s*$)")
"""The task's cubes counted and put in one structure ("stack those six cubes into one tower"): read as "stack them into a
tower", the count checked (three of six had been read as all six)."""


def _interpret_counted(edit: str) -> EditPlan:
    """:func:`interpret` past the material check: a stack of the task's letters said, the count said again, a closing
    clause that keeps the other cubes' colour."""
    said = re.match(r"(?i)\s*(?:stack|pile)\s+(?:all\s+)?the\s+(?P<m>letter|digit|number)s?(?:\s+cubes)?\b", edit or "")
    if said:  # "stack the letters instead, C at the bottom": the task's cubes are letters, checked
        plan = interpret(edit[:said.start()] + "stack them" + edit[said.end():])
        return replace(plan, checks=(*plan.checks, ("material", _MATERIAL_WORDS[said.group("m").lower()])))
    counted = _TASK_CUBES_COUNTED_RE.search(edit or "")
    if counted:  # "stack those six cubes into one tower": the task's cubes, their count checked against the version built on
        plan = interpret(edit[:counted.start()] + f"{counted.group('v')} them {counted.group('p')} a {counted.group('s')}"
                         + edit[counted.end():])
        return replace(plan, checks=(*plan.checks, ("count", int(NUMBER_WORDS.get(counted.group("n").lower(), counted.group("n"))))))
    same = EDIT_SAME_COUNT_RE.match(edit or "")
    if same:  # "same five but reversed": the count checked against the version built on, the rest read as the change
        count = ("count", int(NUMBER_WORDS.get(same.group("n").lower(), same.group("n"))))
        try:
            plan = interpret(edit[same.end():])
        except BadInput:
            plan = None
        if plan is None or plan.standalone or not plan.ops:  # the whole edit read ("now the same three in a tower"
            plan = _interpret_rested(edit)  # restates the task's cubes), the count checked all the same
        return replace(plan, checks=(*plan.checks, count, ("same", True)))  # (the task's cubes kept: checked of a whole
        # task read, :func:`rpg.steer.steering._same_cubes_kept`)
    alone = EDIT_COUNT_ALONE_RE.fullmatch(edit or "")
    was = alone and (alone.group("was") or alone.group("was2"))
    if was:  # "six cubes in the row instead of four", "6 not 3": the count before checked, the new one applied
        plan = _interpret_rested(edit)
        return replace(plan, checks=(*plan.checks, ("count", int(NUMBER_WORDS.get(was.lower(), was)))))
    return _interpret_rested(edit)


def _interpret_rested(edit: str) -> EditPlan:
    rest = EDIT_REST_STAYS_RE.search(edit or "")
    if rest is None:
        return _interpret(edit)
    plan = _interpret(edit[:rest.start()] + edit[rest.end():])
    if plan.standalone or not plan.ops or not all(o.op in ("recolor", "relabel") for o in plan.ops):
        raise SteerError(f"'{rest.group(0).strip(' ,;.!')}' says which cubes keep their colour, which the builtin steering reads only "
                         "after a change of colour (e.g. \"make the top one red, the rest stay blue\"); or use --model")
    return replace(plan, ops=[*plan.ops, Op("rest", {"color": canon_color(rest.group("c"))})])


def _interpret(edit: str) -> EditPlan:
    if not edit or not edit.strip():
        raise SteerError("the edit is empty; say what to change, e.g. \"add a green block on top\"")
    edit = " ".join(edit.split())  # runs of blanks say nothing, and patterns with optional blanks had taken minutes on them
    edit = spoken(edit) or edit  # "and uh make the bottom one purple", "reverse that, like, green first"
    edit = INTENSIFIER_RIGHT_RE.sub("", EDIT_INTERJECTION_RE.sub("", edit)) or edit  # "no wait, put it right next to ..."
    edit = TYPO_RE.sub(lambda m: TYPOS[m.group(0).lower()], edit)  # "put a yelow one ontop": the words meant
    edit = POLITE_CONDITION_RE.sub(" ", edit).strip() or edit  # "make the outer two white, if you would": no condition
    edit = apply_corrections(edit)  # "put a red one on top, no wait, a green one": the correction wins, as in a task
    # "mkae it shorter, 3": two swapped letters corrected before the rewrites, which look for "make"
    edit = " ".join(_corrected(w, _known_words(), fuzzy=False) if w.islower() else w for w in edit.split())
    for pattern, replacement in EDIT_REWRITES:
        edit = pattern.sub(replacement, edit)
    edit = CAUSED_MOTION_RE.sub(_caused_motion_in_edit, edit)  # "now ferry the tower to the back": move it there
    _refuse_unread_shapes(edit)
    label = re.match(r"\s*([^:.;!?]{2,60}):\s", edit)
    if label and TURNING_LABEL_RE.search(label.group(1)):  # "Mirror version: make ...", "Bad example: ...": the label may be
        raise SteerError(f"the label '{label.group(1).strip()}' may change the edit (a judgement, a turn, a condition or a size) "
                         "that the builtin steering does not read; say the change without it, or use --model")  # the change
    count = EDIT_COUNT_ALONE_RE.fullmatch(edit)
    more = EDIT_MORE_ALONE_RE.fullmatch(edit)
    if count:  # "three", "let's go with 7 instead": the structure's count
        edit = f"use {count.group(1)} {count.group('color') + ' ' if count.group('color') else ''}blocks instead"
    elif more:  # "three more": that many more cubes
        edit = f"add {more.group(1)} more blocks"
    t = normalize_edit(edit)
    cue = find_reference(t)
    fresh = FRESH_RE.search(t) if cue.kind != "redo" else None  # "never mind, redo": the undone change, no new task
    if fresh and re.search(r"\bsame\b", t[fresh.end():]):  # "New idea: same cubes, but side by side": the task's cubes, no new
        fresh = None  # task (cubes of their own had been made up)
    back = re.search(r"\b(?:(?:go|going|come|get|take\s+(?:it|me|us))\s+back\s+to|return\s+to|revert\s+to|restore)\s+(?P<what>[^,.;!?]+)", t)
    if fresh and back and cue.kind in ("original", "version", "previous"):
        fresh = None  # "scrap that, go back to the original tower": that version, no new task
    if fresh and back:  # "scrap that, go back to the round one tower": a version named by what rpg does not keep
        raise SteerError(f"'{back.group(0).strip()}' goes back to a version the builtin steering does not find by "
                         f"'{back.group('what').strip()}'; name it as rpg numbers versions (e.g. \"go back to v0\"; `rpg log` lists "
                         "them), or use --model")
    if fresh:
        return EditPlan(edit, RefCue("none", phrase=fresh.group(0)), standalone=True, fresh=True)
    refuse_inexpressible(edit, t)
    try:
        first_ops = read_ops(t)
    except SteerError:
        first_ops = []
    if any(o.op == "add" and o.params.get("between") for o in first_ops):
        # "put a yellow cube between the red cube and the green cube" of a row: into it (it had become the whole task)
        return EditPlan(edit, cue, first_ops)
    if EDIT_SWAP_BOTH_RE.match(edit):  # "the two cubes should trade patches": the task's two cubes exchanged
        return EditPlan(edit, cue, [])
    if looks_standalone(t) and names_cubes(t):
        from rpg.schema.builtin import ParseError, parse

        try:
            parse(strip_edit_words(edit))
            return EditPlan(edit, cue, standalone=True)
        except (ParseError, ValueError):
            pass  # not a whole task after all: read it as a change
    try:
        ops = read_ops(t)
    except SecondStructure:
        if cue.kind != "current":
            raise
        return EditPlan(edit, cue)  # "add a second pair: a green cube on a brown cube": a clause added to the task
    if not ops and cue.kind != "current" and cue.phrase and (change := REF_CHANGE_RE.search(t, t.find(cue.phrase) + len(cue.phrase))):
        then = _change_after_reference(change.group(0))
        if then is not None:  # "revert that and add a blue cube on the same patch": that version, then the change
            return replace(then, cue=cue)
        raise SteerError(f"'{change.group(0).strip()}' after '{cue.phrase}' asks for a change the builtin steering did not read; "
                         f"go back to it in one edit (\"{cue.phrase}\") and say the change in the next, or use --model")
    if ops or cue.kind != "current":
        return EditPlan(edit, cue, ops)  # no ops with a back-reference: return to that version
    # an edit that refers to the task ("it", "the orange one") or adds to it ("also", "too") is
    # no whole new task: the task's own terms or an addition read it, else it is refused
    return EditPlan(edit, cue, standalone=not (REFERS_RE.search(t) or EDIT_ADDITIVE_RE.search(t) or EDIT_VERB_RE.search(t)
                                               or re.match(r"\s*(?:and|plus)\b", t)  # "and the blue block in the corner"
                                               or EDIT_CONTINUES_RE.match(t)))  # "then put C on A"


def _change_after_reference(said: str) -> EditPlan | None:
    """The change an edit asks for after naming the version it builds on ("compare with the first
    one, but with the middle cube green", "revert that and add a blue cube on the same patch",
    "like v1 but in the front left corner"), read as an edit of its own; None when it names no
    version of its own, reads as a whole new task or as no change."""
    m = re.match(r"(?:but|and)\s+(?:then\s+)?(?P<rest>.+)", said.strip())
    if m is None:
        return None  # "except ...", "with ...": what is kept and what is not is unsaid
    rest = m.group("rest").strip()
    rest = re.sub(rf"^with\s+(the\s+(?:[a-z0-9]+\s+){{0,3}}?(?:one|cube|block|layer|row))\s+(?:in\s+)?((?:{COLOR_RE}))\s*[.!]?$",
                  r"make \1 \2", rest)  # "but with the middle cube green"
    rest = re.sub(r"^(?:in|into|at|on)\s+(?=the\s+(?:front|back|left|right|middle|center|centre)\b)", "move it to ", rest)  # "but in the back"
    try:
        plan = _interpret(rest)
    except SteerError:
        return None
    if plan.cue.kind != "current" or plan.standalone or plan.fresh:
        return None
    if plan.ops:
        return plan
    adds = re.match(r"(?:also\s+)?(?:add|put|place|stack|set)\b", rest)
    return replace(plan, adds=True) if adds else None


REFERS_RE = EDIT_REFERS_RE
EDIT_VERB_RE = EDIT_CHANGE_VERB_RE


def strip_edit_words(edit: str) -> str:
    """The task part of a whole-task edit ("Start over: stack ..." -> "stack ...")."""
    marks = list(FRESH_RE.finditer(edit))
    t = edit
    if marks:
        after = edit[marks[-1].end():].strip(" :,.;-")
        lead = re.match(r"[^:.;!?]{0,40}:\s*(?=\S)", after)  # "unrelated to the old one: two towers ...": the task after its colon
        if lead and not re.search(rf"(?i)\b(?:{COLOR_RE})\b|\d", lead.group(0)):
            after = after[lead.end():]
        t = after if len(after.split()) >= 2 else FRESH_RE.sub(" ", edit)
    for _ in range(3):
        t = EDIT_LEADING_RE.sub("", t.strip())
    return t.strip(" ,:;.") or edit


def addition_clause(edit: str) -> str | None:
    """The clause an addition states ("also stack a white block on the cyan one" -> "stack a
    white block on the cyan block"), or None when it has a pronoun the clause cannot resolve
    ("it", "them")."""
    t = strip_edit_words(edit)
    t = re.sub(r"\b(?:also|too|as well|additionally|in addition)\b", " ", t, flags=re.IGNORECASE)
    t = re.sub(rf"\b((?:{COLOR_RE}))\s+one\b", r"\1 block", t, flags=re.IGNORECASE)
    t = " ".join(t.split()).strip(" ,;.")
    if not t or re.search(r"\b(?:it|them|they|its|their|those|these|that|this|one)\b", t, re.IGNORECASE):
        return None
    return t


# ---------------------------------------------------------------------------
# Applying operations to a spec
# ---------------------------------------------------------------------------


def _material_items(material: str, n: int, colors: list[str]) -> list[Item]:
    """``n`` cubes of a material: letters A.., digits 1..9,0, colours (``colors`` cycled, else
    the default palette), or ``mixed`` (letter, digit, colour in turn)."""
    if material == "letters":
        return [Item(label=LETTERS[i % 26]) for i in range(n)]
    if material == "digits":
        return [Item(label=DIGITS[i % 10]) for i in range(n)]
    if material == "mixed":
        kinds = (lambda k: Item(label=LETTERS[k % 26]), lambda k: Item(label=DIGITS[k % 10]),
                 lambda k: Item(color=DEFAULT_COLORS[k % len(DEFAULT_COLORS)]))
        return [kinds[i % 3](i // 3) for i in range(n)]
    palette = colors or list(DEFAULT_COLORS)
    return [Item(color=palette[i % len(palette)]) for i in range(n)]


def _next_item(spec: TaskSpec) -> Item:
    """A cube that continues the spec's material: the next letter or digit, or an unused colour."""
    labels = [i.label for i in spec.items if i.label]
    if spec.material == "letters" and labels:
        return Item(label=next((c for c in LETTERS if c not in labels), "A"))
    if spec.material == "digits" and labels:
        return Item(label=next((d for d in DIGITS if d not in labels), "1"))
    used = set(spec.colors())
    return Item(color=next((c for c in DEFAULT_COLORS if c not in used), "red"))


def _orders_cubes(spec: TaskSpec) -> bool:
    """Whether the structure's goal gives each cube its place (a tower, a line read in a
    direction): then "two of them" does not say which.  A sequence that holds from either end
    ("in the order red, green, blue") gives no end a cube: nothing to reverse or add at an end."""
    return spec.kind.spells and spec.direction not in (None, "sequence")


def _layer_indices(spec: TaskSpec, where: str) -> list[int]:
    sizes = _layer_sizes(spec)
    k = {"bottom": 0, "top": len(sizes) - 1}.get(where, 1 if where == "middle" and len(sizes) == 3 else
                                                 {"second": 1, "third": 2}.get(where, -1))
    if not 0 <= k < len(sizes):
        raise SteerError(f"a {spec.structure} {len(sizes)} layers high has no {where} layer; name it from the bottom")
    start = sum(sizes[:k])
    return list(range(start, start + sizes[k]))


def _inserted_between(spec: TaskSpec, p: dict, anchors: frozenset[str]) -> TaskSpec:
    """``spec`` with the cube an edit adds between two neighbouring cubes put in the gap between them
    ("add a black cube between the white one and the blue one" of a tower: above the lower of the two).

    Raises:
        SteerError: the structure orders no cubes, the two are not one cube each, or they are not neighbours.
    """
    if not _orders_cubes(spec) or spec.structure not in ("tower", "line"):
        raise SteerError(f"a cube added between two cubes of a {spec.structure} whose goal gives no cube a place cannot be "
                         "judged; say the whole new order, or use --model")
    a, b = (_indices(spec, sel, anchors) for sel in p["between"])
    if len(a) != 1 or len(b) != 1 or abs(a[0] - b[0]) != 1:
        raise SteerError(f"the two cubes the edit puts a cube between are not one cube each standing next to each other in the "
                         f"{spec.structure} ({', '.join(i.phrase() for i in spec.items)}); say the whole new order, or use --model")
    new = [Item(**d) for d in p["items"]]
    if len(new) != 1:
        raise SteerError("name the one cube to put between the two (e.g. \"a black cube\")")
    at = max(a[0], b[0])
    return spec.with_items(list(spec.items[:at]) + new + list(spec.items[at:]))


def _indices(spec: TaskSpec, sel: dict, anchors: frozenset[str] = frozenset()) -> list[int]:
    """The indices of ``spec``'s items a selector (:func:`_selector`) picks: with ``"was"``, each must be of that colour.

    Raises:
        SteerError: the selector picks no cube of the structure, or a cube not of the colour said with it."""
    if "was" in sel:
        idx = _indices(spec, {k: v for k, v in sel.items() if k != "was"}, anchors)
        wrong = sorted({spec.items[i].color or spec.items[i].label or "?" for i in idx} - {sel["was"]})
        if wrong:
            raise SteerError(f"the cube picked is {', '.join(wrong)}, not {sel['was']}; name the cube as the task has it (by its place "
                             "or its colour), or state the whole new task")
        return idx
    if "next" in sel or "between" in sel:
        return _neighbour_indices(spec, sel, anchors)
    if "patch" in sel or "on_patch" in sel or "patch_of" in sel:
        raise SteerError(f"the {spec.structure}'s cubes are not picked by a patch; name the cube by its colour or its place")
    return _indices_of(spec, sel, anchors)


def _removed_indices(spec: TaskSpec, sel: dict, anchors: frozenset[str]) -> list[int]:
    """The indices of the cubes a removal takes: as :func:`_indices`, but ``k`` of a run of identical cubes that stand
    together in a one-line structure ("take one blue off" a tower green, green, blue, blue) are the run's last ``k``, since
    whichever ``k`` go the structure left is the same; cubes of that colour apart (blue, green, blue) stay unnamed."""
    if set(sel) == {"color", "count"} and not spec.kind.layered and _orders_cubes(spec):
        idx = [i for i, it in enumerate(spec.items) if it.color == sel["color"]]
        k = sel["count"]
        if 0 < k < len(idx) and idx == list(range(idx[0], idx[0] + len(idx))) and all(
                spec.items[i] == spec.items[idx[0]] for i in idx):
            return idx[-k:]
    return _indices(spec, sel, anchors)


def _neighbour_indices(spec: TaskSpec, sel: dict, anchors: frozenset[str]) -> list[int]:
    """The one cube a neighbour pick names (:func:`_relation_pick`): in a tower, the cube directly above or below the one
    named; in a row with a left-to-right order, the one directly left or right of it; the one beside it where only one is;
    the one cube between two named.

    Raises:
        SteerError: the structure gives its cubes no such order, the cube named is not one cube, or no one cube stands there."""
    n = len(spec.items)
    tower = spec.structure in ANCHORED_KINDS
    if spec.kind.layered or not _orders_cubes(spec) or (not tower and spec.direction not in ("left_to_right", "right_to_left")):
        raise SteerError(f"a {spec.structure} whose goal gives no cube its place beside another picks no cube by its neighbour; "
                         "name the cube by colour")
    def one(s: dict) -> int:
        idx = _indices(spec, s, anchors)
        if len(idx) != 1:
            raise SteerError(f"the cube a pick stands by must be one cube, and the {spec.structure} has {len(idx)} such; name the "
                             "cube by its place")
        return idx[0]
    if "between" in sel:
        lo, hi = sorted(one(s) for s in sel["between"])
        if hi - lo != 2:
            raise SteerError(f"{max(hi - lo - 1, 0)} cubes stand between the two named; name the cube by colour or place")
        return [lo + 1]
    side = sel["next"]
    if side not in ("above", "below", "left", "right", "beside"):  # "the cube behind the blue one" of a tower or a row
        raise SteerError(f"the builtin steering picks no cube of a {spec.structure} by what stands {side} of another; name the "
                         "cube by colour or place")
    k = one(sel["of"])
    if side in ("above", "below") and not tower or side in ("left", "right") and tower:
        raise SteerError(f"no cube of a {spec.structure} stands {side if side in ('above', 'below') else side + ' of'} another; name "
                         "the cube by colour or place")
    step = {"above": [1], "below": [-1], "beside": [-1, 1]}.get(side) or [1 if (side == "right") == (spec.direction == "left_to_right") else -1]
    picked = [k + d for d in step if 0 <= k + d < n]
    if len(picked) != 1:
        raise SteerError(f"{'no' if not picked else len(picked)} cubes stand {side} the one named; name the cube by colour or place")
    return picked


def _indices_of(spec: TaskSpec, sel: dict, anchors: frozenset[str] = frozenset()) -> list[int]:
    n = len(spec.items)
    if sel.get("position") in anchors and sel["position"] in ("bottom", "top"):
        return [0 if sel["position"] == "bottom" else n - 1]  # the end a stack in any order has its cube at
    if sel.get("both") and n != 2:
        raise SteerError(f"'both' names two cubes, but the {spec.structure} has {n}; say which")
    if sel.get("single") and n != 1:
        raise SteerError(f"'the cube' names one cube, but the {spec.structure} has {n}; say which (e.g. by its colour)")
    if sel.get("uniform") and len(set(spec.colors())) > 1:
        raise SteerError(f"the {spec.structure} has cubes of {len(set(spec.colors()))} colours; say which to change")
    if sel.get("all"):
        return list(range(n))
    if sel.get("ends"):  # "make the two at the ends red": the first and the last of a tower or a line (the same either way)
        if spec.kind.layered or not spec.kind.spells or n < 2 or (not _orders_cubes(spec) and len(set(spec.items)) > 1):
            raise SteerError(f"'the ends' of a {spec.structure} of {n} cubes whose goal gives no cube an end is not a pair the "
                             "builtin steering can name; name the cubes by colour, or say the whole order")
        return [0, n - 1]
    if "pair" in sel:  # one of two neighbouring cubes named by where the pair stands ("the top two", "the middle two")
        if not _orders_cubes(spec) or n < 3:
            raise SteerError(f"the {sel['pair']} two of a {spec.structure} of {n} cubes"
                             + ("" if _orders_cubes(spec) else " whose goal gives no cube a place") + " name no pair; name them by colour")
        if sel["pair"] in ("bottom", "top") and spec.structure not in ANCHORED_KINDS:
            raise SteerError(f"a {spec.structure} has no {sel['pair']} two (its cubes stand side by side); name them by colour or "
                             "by side (e.g. \"the left two\")")
        if sel["pair"] in ("left", "right"):
            if spec.direction not in ("left_to_right", "right_to_left") or spec.structure in ANCHORED_KINDS:
                raise SteerError(f"the {sel['pair']} two of a {spec.structure} whose goal runs no way left to right name no "
                                 "cubes; name them by colour")
            first = (sel["pair"] == "left") == (spec.direction == "left_to_right")
            start = 0 if first else n - 2
        elif sel["pair"] == "middle":
            if n % 2:
                raise SteerError(f"a {spec.structure} of {n} cubes has no middle two; name them by colour")
            start = n // 2 - 1
        else:
            start = 0 if sel["pair"] in ("first", "bottom") else n - 2
        return [start + sel["at"]]
    if sel.get("end") in ("left", "right"):  # an end of a row said by its side: the row's own first or last cubes
        if spec.direction not in ("left_to_right", "right_to_left") or spec.structure in ANCHORED_KINDS:
            raise SteerError(f"the {sel['end']} {sel['n']} of a {spec.structure} whose goal runs no way left to right name no "
                             "cubes; name them by colour")
        first = (sel["end"] == "left") == (spec.direction == "left_to_right")
        sel = {**sel, "end": "bottom" if first else "top"}
    if "end" in sel:
        k = sel["n"]
        if not 0 < k <= n or not _orders_cubes(spec):
            raise SteerError(f"the {sel['end']} {k} of a {spec.structure} of {n} cubes"
                             + ("" if _orders_cubes(spec) else " whose goal gives no cube a place") + " name no cubes; name them by colour")
        return list(range(k)) if sel["end"] == "bottom" else list(range(n - k, n))
    if "some" in sel:
        k = sel["some"]
        if not 0 < k < n or _orders_cubes(spec):
            raise SteerError(f"'{k} of them' does not say which of the {spec.structure}'s {n} cubes"
                             + (" (its goal gives each cube its place)" if _orders_cubes(spec) else "")
                             + "; name them by colour or place (e.g. \"the top two\")")
        same = [i for i, it in enumerate(spec.items) if it == spec.items[-1]]
        if len(same) < n:
            raise SteerError(f"'{k} of them' does not say which of the {spec.structure}'s cubes; name them by colour")
        return list(range(n - k, n))
    if "nth" in sel:
        k, end = sel["nth"], sel["from"]
        along = ("bottom", "top") if spec.structure in ANCHORED_KINDS else ("left", "right")  # the structure's own ends
        if spec.kind.layered or not _orders_cubes(spec) or not 0 < k <= n or end not in along or (
                spec.structure not in ANCHORED_KINDS and spec.direction not in ("left_to_right", "right_to_left")):
            said = f"cube {k} counted from the {end}" if end else f"cube {k} counted from an end nobody named"
            raise SteerError(f"the {said} of a {spec.structure} of {n} cubes"
                             + ("" if _orders_cubes(spec) else " whose goal gives no cube a place")
                             + f" is not a cube the builtin steering can name; count from its {' or '.join(along)} "
                             "(e.g. \"the 2nd from the " + along[0] + "\"), or say the whole order")
        return [k - 1] if end in ("bottom", "left") else [n - k]
    if "layer" in sel and spec.kind.layered:
        return _layer_indices(spec, sel["layer"])
    if "layer" in sel or "position" in sel:
        where = sel.get("layer") or sel["position"]
        if spec.kind.layered:
            idx = _layer_indices(spec, where)
            if len(idx) > 1:
                raise SteerError(f"the {where} layer of the {spec.structure} has {len(idx)} cubes; say the {where} layer, "
                                 "or name the cube by colour")
            return idx
        if not spec.kind.spells or not _orders_cubes(spec):
            raise SteerError(f"a {spec.structure}'s goal gives no cube the {where} place (any order holds); name the cube by colour")
        pos = {"bottom": 0, "top": n - 1, "middle": n // 2 if n % 2 else -1, "second": 1, "third": 2}[where]
        if pos < 0:
            raise SteerError(f"a {spec.structure} of {n} cubes has no one middle cube; name the cube by colour")
        return [pos] if 0 <= pos < n else []
    if "color" in sel:
        idx = [i for i, it in enumerate(spec.items) if it.color == sel["color"]]
        k = sel.get("count")
        if k is not None and k > len(idx):  # "take three blues off" of two blue cubes: more than there are
            raise SteerError(f"'{k} {sel['color']}' asks for {k} {sel['color']} cubes, but the {spec.structure} has {len(idx)}; "
                             "say how many there are, or name them by place")
        if k is not None and k < len(idx):
            if _orders_cubes(spec):
                raise SteerError(f"'{k} {sel['color']}' does not say which of the {spec.structure}'s {len(idx)} {sel['color']} cubes, "
                                 "and its goal gives each cube a place; name it by place (e.g. \"the top one\")")
            return idx[-k:]  # cubes of one colour in a structure that orders none: any k of them
        return idx
    return [i for i, it in enumerate(spec.items) if it.label == sel.get("label")]


def _colors_of(value) -> set[str]:
    if isinstance(value, dict):
        return {v for k, v in value.items() if k in ("color", "was", "patch", "on_patch", "patch_of") and v} | {c for v in value.values() for c in _colors_of(v)}
    if isinstance(value, (list, tuple)):
        return {c for v in value for c in _colors_of(v)} | {v for v in value if isinstance(v, str) and v in _PALETTE_NAMES}
    return set()


_PALETTE_NAMES = frozenset(canon_color(c) for c in COLOR_RE.split("|"))


def _numbers_of(value) -> set[int]:
    if isinstance(value, bool):
        return set()
    if isinstance(value, int):
        return {abs(value)}
    if isinstance(value, float):
        return {int(value)} if value.is_integer() else set()
    if isinstance(value, str):  # a digit cube's label ("bottom to top: 3, 1, 2")
        return {int(value)} if value.isdigit() else set()
    if isinstance(value, dict):
        return {n for v in value.values() for n in _numbers_of(v)} | {len(value["items"])} if "items" in value else \
            {n for v in value.values() for n in _numbers_of(v)}
    if isinstance(value, (list, tuple)):
        return {n for v in value for n in _numbers_of(v)} | {len(value)}
    return set()


def unread_numbers(plan: EditPlan) -> list[str]:
    """Counts the edit says that none of its operations uses ("make the tower 3 blocks high using a red
    block" read as a recolour only); labels ("the digit 3"), sizes ("3x3") and versions are not counts."""
    t = normalize_edit(plan.text)
    if plan.cue.phrase:
        t = t.replace(plan.cue.phrase, " ")
    t = re.sub(r"\b(?:digit|letter|number|version|v)\s+'?\w'?|\b\d+x\d+(?:x\d+)?\b|\b\d+(?:st|nd|rd|th)\b", " ", t)
    t = re.sub(r"\b(?:instead\s+of|rather\s+than|from)\s+(?:the\s+)?\d+\b", " ", t)  # "4 blocks instead of 3": the old count
    if plan.cue.kind != "current":  # "go back to the original two-block tower": a count that names the version
        t = re.sub(r"\b\d+[- ](?:blocks?|cubes?)(?=[- ](?:tall\s+|high\s+)?(?:tower|stack|line|row|pyramid|circle|version|one)\b)", " ", t)
    said = re.findall(r"\b\d+\b", t)
    used = _numbers_of([o.params for o in plan.ops]) | ({plan.cue.count} if plan.cue.count else set())
    return [n for n in dict.fromkeys(said) if int(n) not in used]


def _labels_of(value) -> set[str]:
    """The labels an operation's parameters use: each ``label``, and a ``word`` with each of its letters."""
    if isinstance(value, dict):
        said = {x for k, v in value.items() if k in ("label", "word") and isinstance(v, str) for x in (v, *v)}
        return said | {c for v in value.values() for c in _labels_of(v)}
    if isinstance(value, (list, tuple)):
        return {c for v in value for c in _labels_of(v)}
    return set()


def unread_labels(plan: EditPlan) -> list[str]:
    """Letter labels the edit names that none of its operations (nor its reference cue) uses ("make it a tower, from bottom
    to top: R, A, T, S" read as every cube relabelled R): a part of the edit that was not read.  "I" and "A" said as words
    ("I want", "A tower") are no labels."""
    t = plan.text
    if plan.cue.phrase:
        t = re.sub(re.escape(plan.cue.phrase), " ", t, flags=re.IGNORECASE)
    said = [m.group(0) for m in re.finditer(r"(?<![\w'])[A-Z](?![\w'])", t)
            if not (m.group(0) in "IA" and re.match(r"\s+[a-z]", t[m.end():]))]
    used = _labels_of([o.params for o in plan.ops]) | _labels_of(asdict(plan.cue))
    return [c for c in dict.fromkeys(said) if c not in used]


def unread_colors(plan: EditPlan) -> list[str]:
    """Colours the edit names that none of its operations (nor its reference cue) uses: a
    part of the edit that was not read ("make the top layer red and the bottom one blue" read
    as the first half only)."""
    t = normalize_edit(plan.text)
    if plan.cue.phrase:
        t = t.replace(plan.cue.phrase, " ")
    said = [canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", t)]
    used = _colors_of([o.params for o in plan.ops]) | set(plan.cue.colors)
    return [c for c in dict.fromkeys(said) if c not in used]


def carried_after(spec: TaskSpec, carried, ops: list[Op]):
    """The modifiers (:class:`rpg.steer.carried.Carried`) after the edit: a region it moves
    the structure to; judged layers once it gives a layered structure's layer a colour."""
    ends = set(carried.ends)
    for o in ops:
        if o.op == "add" and spec.direction is None and spec.structure in ANCHORED_KINDS and (o.params.get("end") or o.params.get("onto")):
            ends.add(o.params.get("at") or "top")  # "add a yellow block on top" of a stack in any order: its top said
        if o.op == "remove" and ends:
            gone = set(_indices(spec, o.params["select"], frozenset(ends)))
            ends -= {e for e, i in (("bottom", 0), ("top", len(spec.items) - 1)) if i in gone}
        if o.op == "region":
            carried = replace(carried, region=o.params["region"])
        sel = o.params.get("select") or {}
        if o.op in ("recolor", "relabel") and spec.kind.layered and ("layer" in sel or "position" in sel):
            carried = replace(carried, layers=True)
        if o.op == "structure" and o.params.get("to") in STRUCTURE_KINDS and not STRUCTURE_KINDS[o.params["to"]].layered:
            carried = replace(carried, layers=False)  # "stack them into a tower" of a pyramid with judged layers: none left
    return replace(carried, ends=frozenset(ends))


_ARRANGED_WAY = r"left to right|right to left|front to back|back to front|bottom to top|top to bottom"
_ARRANGED_LIST = rf"(?:{COLOR_RE}|\d)(?:(?:\s*,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+|\s+then\s+|\s+)(?:{COLOR_RE}|\d))+"
ARRANGED_RE = re.compile(EDIT_OPENING + rf"(?:[a-z][a-z' \-]{{0,40}}:\s*)?(?:(?:put|arrange|order|reorder|line|set)\s+"
                         rf"(?:them|it|the\s+(?:cubes|blocks))\s+(?:up\s+)?)?(?:(?:from\s+)?(?P<way>{_ARRANGED_WAY})\s*[:,]?\s*"
                         rf"(?P<list>{_ARRANGED_LIST})|(?P<list2>{_ARRANGED_LIST})\s*,?\s*(?:from\s+)?(?P<way2>{_ARRANGED_WAY}))"
                         r"\s*[.!]?\s*$")
"""An edit that lists the task's cubes in a new order ("left to right: blue, red, green", "from bottom to top: 3, 1, 2",
"Interleave the samples: purple, yellow, purple, yellow, left to right"); the list is the whole order (a label before it
that turns or judges the edit is refused before)."""


def _arranged(spec: TaskSpec, items: list[Item], way: str) -> TaskSpec:
    """``spec`` with its cubes in the order ``items`` lists them, read ``way`` (a line's
    direction, or ``bottom_to_top`` / ``top_to_bottom`` of a tower).

    Raises:
        SteerError: the list is not the task's cubes, or the way is not the structure's axis.
    """
    def key(it: Item) -> tuple[str, str]:
        return (it.color or "", it.label or "")

    if sorted(map(key, items)) != sorted(map(key, spec.items)):
        raise SteerError(f"the order lists {', '.join(i.phrase() for i in items)}; the task's cubes are "
                         f"{', '.join(i.phrase() for i in spec.items)}: list each of them once, or say the change first")
    vertical = way in ("bottom_to_top", "top_to_bottom")
    if vertical != (spec.structure == "tower") or spec.structure not in ("tower", "line"):
        raise SteerError(f"'{way.replace('_', ' ')}' is not how a {spec.structure} runs; say the order along it")
    if way in ("top_to_bottom", "right_to_left", "back_to_front"):
        items = items[::-1]
        way = {"top_to_bottom": "bottom_to_top", "right_to_left": "left_to_right", "back_to_front": "front_to_back"}[way]
    spec = replace(spec.with_items(items), ordering=None, descending=False)
    return spec if vertical else replace(spec, direction=way, axis=None)


def _period(items: list[Item]) -> int | None:
    """The length of the shortest pattern that ``items`` repeat at least twice over
    (black, white, black, white: 2; one cube, or cubes of one colour: 1), or None."""
    return next((p for p in range(1, max(1, len(items) // 2) + 1)
                 if items and all(items[i] == items[i % p] for i in range(len(items)))), None)


def _resize(spec: TaskSpec, n: int) -> TaskSpec:
    """The spec with ``n`` cubes: the first ``n`` kept; cubes added go on with the pattern the
    cubes repeat ("make it six" of black, white, black, white: two more of black, white), else
    with a colour or label the task does not use yet."""
    items = list(spec.items[:n])
    period = _period(items) if all(it.label is None for it in items) else None
    while len(items) < n:
        grow = replace(spec, items=tuple(items))
        items.append(items[len(items) % period] if period else _next_item(grow))
    return spec.with_items(items)


def _layer_sizes(spec: TaskSpec) -> list[int]:
    return spec.kind.layer_sizes(spec)


def _with_layer_colors(spec: TaskSpec) -> TaskSpec:
    sizes = _layer_sizes(spec)
    palette = list(dict.fromkeys(spec.colors())) + [c for c in DEFAULT_COLORS if c not in spec.colors()]
    items = [Item(color=palette[k]) for k, size in enumerate(sizes) for _ in range(size)]
    return replace(spec, items=tuple(items), layer_colors=True, ordering=None, descending=False)


def _in_kept_order(spec: TaskSpec, end: tuple[str, str] | None) -> TaskSpec:
    """A tower or line that keeps the cubes' order of the structure it was made from (first
    cube at the bottom or on the left), read from the other end when ``end`` names the last
    cube's colour for the first end ("in the same order, red at the bottom" of a line whose
    red is on the right).

    Raises:
        SteerError: ``end`` names a colour at neither end, or at both.
    """
    if end is not None:
        color, where = end
        first = where in ("bottom", "base", "left")
        colors = [it.color for it in spec.items]
        at = [i for i in (0, len(colors) - 1) if colors[i] == color]
        if len(at) != 1:
            raise SteerError(f"'{color} at the {where}' does not say which end of the order goes {where}: the {color} cube "
                             "is not at exactly one end; state the whole new task")
        if (at[0] == 0) != first:
            spec = spec.with_items(list(reversed(spec.items)))
    return replace(spec, direction="left_to_right")


def _in_stated_order(spec: TaskSpec, on: list[tuple[str, str]]) -> TaskSpec:
    """A tower whose cubes stand as the edit's "X on top of Y" pairs say, bottom to top.

    Raises:
        SteerError: a pair names a cube the tower has not (or two alike), or the pairs do not
            fix every cube's place.
    """
    def index(name: str) -> int:
        color = canon_color(name) if re.fullmatch(COLOR_RE, name) else None
        at = [i for i, it in enumerate(spec.items) if (color is not None and it.color == color and it.label is None)
              or (color is None and (it.label or "").upper() == name.upper())]
        if len(at) != 1:
            raise SteerError(f"'{name}' does not name one cube of the tower; state the whole new task, or use --model")
        return at[0]
    above = {index(b): index(a) for a, b in on}
    bottoms = [i for i in range(len(spec.items)) if i not in above.values()]
    order = bottoms[:1]
    while order and order[-1] in above:
        order.append(above[order[-1]])
    if len(bottoms) != 1 or sorted(order) != list(range(len(spec.items))):
        raise SteerError("the edit's 'on top of' does not fix every cube's place in the tower; say the whole order "
                         "(e.g. \"bottom to top: red, blue, green\"), or use --model")
    return spec.with_items([spec.items[i] for i in order])


def _fit_structure(spec: TaskSpec, target: str) -> TaskSpec:
    try:
        return STRUCTURE_KINDS[target].fit(spec, _resize)
    except BadInput as exc:
        raise SteerError(f"cannot turn a {spec.structure} into a {target}: {exc}") from None


APPLY_ORDER = ("keep", "region", "structure", "add_layer", "material", "word", "dims", "count", "colors", "remove", "recolor", "relabel", "pattern", "add",
               "move", "swap", "reverse", "ordering", "arrange", "direction", "outliers", "rest")
"""Order in which an edit's operations are applied to the spec."""


ANCHORED_KINDS = ("tower",)
"""Kinds whose cubes in any order may have one end's cube said (:class:`~rpg.domain.predicates.AnchoredStack`)."""

DIM_AXES: dict[str, dict[str, int]] = {
    "block": {"deep": 0, "wide": 1, "long": 1, "tall": 2, "high": 2, "level": 2, "layer": 2, "storey": 2, "story": 2},
    "grid": {"deep": 0, "wide": 1, "long": 1},
    "pyramid": {"wide": 0, "tall": 0, "high": 0, "level": 0, "layer": 0},
}
"""Which dimension of a structure's ``dims`` a side word sets ("four wide", "3 tall")."""

LAYER_AXES: dict[str, int] = {"block": 2, "grid": 0}
"""The dimension another row or layer grows ("add a third row on top")."""


def _layer_added_below(spec: TaskSpec, p: dict) -> TaskSpec:
    """A pyramid or wall with a new bottom layer of one colour under it ("add a bottom row of three gray cubes under it"): a
    pyramid's base grows by one (its new bottom layer one cube wider, or one wider each way in 3D), a wall gains a layer as
    wide as its others; the layers above keep their cubes.

    Raises:
        SteerError: another structure, no colour said, or a count that does not fit the new layer."""
    if spec.structure not in ("pyramid", "block"):
        raise SteerError(f"a {spec.structure} takes no layer below its cubes; state the whole new task")
    if p.get("color") is None:
        raise SteerError("say the colour of the new bottom layer (e.g. \"add a row of gray cubes at the bottom\")")
    if spec.structure == "pyramid":
        base, d = spec.dims
        dims, size = (base + 1, d), (base + 1) ** (d - 1)
    else:
        dims = tuple(spec.dims[:2]) + (spec.dims[2] + 1,)
        size = spec.dims[0] * spec.dims[1]
    if p.get("n") is not None and p["n"] != size:
        raise SteerError(f"a new bottom layer of {p['n']} cubes does not fit under the {spec.structure}, whose new bottom layer "
                         f"holds {size}; state the whole new task, or use --model")
    return replace(spec, dims=dims).with_items([Item(color=p["color"])] * size + list(spec.items))


def _layers_of(spec: TaskSpec) -> list[list[str | None]]:
    out, i = [], 0
    for size in _layer_sizes(spec):
        out.append([it.color or it.label for it in spec.items[i:i + size]])
        i += size
    return out


def _resize_dims(spec: TaskSpec, dims: tuple[int, ...], keep_layers: bool = False) -> TaskSpec:
    """The spec with new dimensions; with judged layers each layer keeps its one colour."""
    if min(dims) < 1:
        raise SteerError(f"a {spec.structure} cannot be {'x'.join(map(str, dims))}")
    new = replace(spec, dims=dims)
    if not keep_layers:
        return _resize(new, spec.kind.cube_count(dims))
    layers, sizes = _layers_of(spec), _layer_sizes(new)
    if len(layers) != len(sizes) or any(len(set(layer)) != 1 for layer in layers):
        raise SteerError(f"the {spec.structure}'s layers cannot keep their colours at {'x'.join(map(str, dims))}; "
                         "state the whole new task")
    return new.with_items([Item(color=layer[0]) for layer, size in zip(layers, sizes, strict=True) for _ in range(size)])


def _no_such_cube(sel, spec: TaskSpec, purpose: str = "") -> SteerError:
    """The refusal of an edit that names a cube the task does not have (``sel``, a selector: "paint the purple cube red" of a
    tower of white, blue and orange): what it names, what the task has, and how to say it."""
    said = sel if not isinstance(sel, dict) else " ".join(
        str(v) for k, v in sorted(sel.items()) if k in ("color", "label", "at", "index") and v is not None) or str(sel)
    has = ", ".join(i.phrase() for i in spec.items)
    return SteerError(f"the task has no {said} cube{' ' + purpose if purpose else ''}: the edit refers to a cube that does not "
                      f"exist (it has {has}); name one of its cubes, or say to add one")


def apply_ops(spec: TaskSpec, ops: list[Op], keep_layers: bool = False, anchors: frozenset[str] = frozenset()) -> TaskSpec:
    """The spec after the edit's operations, in order.

    Operations apply in :data:`APPLY_ORDER` (material before ordering, and so on), whatever
    the order of the words.

    Raises:
        SteerError: an operation does not fit the structure (the message says what would).
    """
    touched: set[int] = set()  # the cubes recoloured, for a "rest" op ("the rest stay blue")
    for o in sorted(ops, key=lambda o: APPLY_ORDER.index(o.op)):
        p = o.params
        if o.op == "rest":
            other = [it for i, it in enumerate(spec.items) if i not in touched]
            if not other or any(it.color != p["color"] for it in other):
                raise SteerError(f"the edit says the other cubes stay {p['color']}, but the {spec.structure}'s other cubes are "
                                 f"{', '.join(it.phrase() for it in other) or 'none'}; say the colour of each cube to change")
        elif o.op == "keep":
            if p["structure"] != spec.structure:
                raise SteerError(f"the edit keeps a {p['structure']}, but the version it builds on is a {spec.structure}; "
                                 "name the version to build on (e.g. \"go back to the tower\"), or state the whole new task")
        elif o.op == "structure" and p.get("dims"):
            dims = tuple(p["dims"])
            spec = _resize(TaskSpec(p["to"], spec.items, dims), STRUCTURE_KINDS[p["to"]].cube_count(dims))
        elif o.op == "structure":
            if p["to"] != spec.structure:
                before = len(spec.items)
                if p.get("keep_order") and not _orders_cubes(spec):  # "stack them in the order of the row" of a row in any
                    raise SteerError(f"the {spec.structure}'s goal gives its cubes no order, so there is none to keep; say the "
                                     "order (e.g. \"from bottom to top: red, green, blue\")")  # order (one had been made up)
                spec = _fit_structure(spec, p["to"])
                if len(spec.items) != before and not any(q.op in ("count", "dims") for q in ops):
                    raise SteerError(f"a {p['to']} is not made of {before} cubes (the nearest has {len(spec.items)}); say its size "
                                     "too, or state the whole new task")
                if p.get("keep_order") and spec.structure in ("tower", "line"):
                    spec = _in_kept_order(spec, p.get("end"))
                if p.get("on") and spec.structure == "tower":
                    spec = _in_stated_order(spec, p["on"])
        elif o.op == "material":
            if p["to"] == spec.material:
                continue
            if spec.kind.grouped:
                spec = replace(spec, piles_by="type" if p["to"] == "mixed" else spec.piles_by)
            spec = spec.with_items(_material_items(p["to"], len(spec.items), []))
            if spec.ordering == "label" and spec.material == "digits":
                spec = replace(spec, ordering="number")
            elif spec.ordering == "number" and spec.material == "letters":
                spec = replace(spec, ordering="label")
            elif spec.ordering in ("label", "number") and spec.material == "colors":
                spec = replace(spec, ordering=None)
            spec = replace(spec, word=None, layer_colors=spec.layer_colors and spec.material == "colors", named=False)
        elif o.op == "ordering":
            key = p["key"] if p["key"] != "auto" else "label" if spec.material == "letters" else "number"
            if spec.kind.grouped:
                spec = replace(spec, piles_by="color" if key == "color" else "type")
                continue
            if key == "color" and spec.kind.layered:
                spec = _with_layer_colors(spec)
                continue
            if key == "color" and spec.kind.rainbow:  # a rainbow: gradient colours in structure order
                spec = spec.with_items([Item(color=GRADIENT_ORDER[i % len(GRADIENT_ORDER)]) for i in range(len(spec.items))])
                continue
            need = {"label": "letters", "number": "digits", "color": "colors"}[key]
            if spec.material == "colors" and p["key"] == "auto" and not any(q.op == "material" for q in ops):
                # "stack them instead, smallest on top" of coloured cubes: they carry no numbers (digit cubes nobody named
                # had replaced them)
                raise SteerError(f"the {spec.structure}'s cubes carry no {'numbers' if need == 'digits' else 'letters'} to sort by; "
                                 f"say the {need} (e.g. \"use the digit cubes 1, 2 and 3\"), or use --model")
            if spec.material != need:  # new cubes nobody named one by one
                spec = replace(spec.with_items(_material_items(need, len(spec.items), spec.colors())), named=False)
            if key == "color" and spec.structure == "line":
                spec = spec.with_items(_material_items("colors", len(spec.items), [c for c in DEFAULT_COLORS]))
            spec = replace(spec, ordering=key, descending=p.get("descending", False), word=None, layer_colors=False,
                           direction=spec.direction or "left_to_right")
        elif o.op == "reverse":
            if spec.kind.layered:
                raise SteerError(f"a {spec.structure}'s cubes stand in layers, which have no one order to reverse; say each "
                                 "layer's colours")
            if spec.kind.spells and not _orders_cubes(spec):
                raise SteerError(f"the {spec.structure}'s goal gives its cubes no order (any order holds), so there is none to "
                                 "reverse; say the order it should have (e.g. \"from left to right: red, green, blue\")")
            keep = set(_indices(spec, p["keep"], anchors)) if p.get("keep") else set()
            idx = [i for i, it in enumerate(spec.items) if i not in keep and (not p.get("colors_only") or it.label is None)]
            items = list(spec.items)
            for i, j in zip(idx, reversed(idx), strict=True):
                items[i] = spec.items[j]
            spec = spec.with_items(items)
            if spec.ordering:
                spec = replace(spec, descending=not spec.descending)
        elif o.op == "add":
            repeated = sorted({it["label"] for it in p.get("items") or [] if it.get("label")} & {i.label for i in spec.items if i.label})
            if repeated:  # "put cube 3 on top" of a tower 1, 2, 3: a second cube labelled 3 (it had been added, silently)
                raise SteerError(f"the task already has a cube labelled {', '.join(repeated)}, and the edit adds another; to move "
                                 f"it, say so (e.g. \"move the {repeated[0]} to the top\"), or name a new label")
            if not spec.kind.sized_by_count:
                raise SteerError(f"cubes cannot be added one by one to a {spec.structure}; change its size instead "
                                 "(e.g. \"make the base 4\")")
            if p.get("between"):
                spec = _inserted_between(spec, p, anchors)
                continue
            if p.get("side") and (spec.structure != "line" or p["side"] not in ("left", "right")):
                raise SteerError(f"a cube added beside a {spec.structure} ({p['side']!r}) is not part of it, which the "
                                 "builtin steering cannot place (it adds cubes to the structure itself); state the "
                                 "whole new task in the edit, or use --model")
            if spec.structure not in ANCHORED_KINDS and re.search(r"\b(?:top|bottom|base|under|underneath|beneath|below|above)\b",
                                                                p.get("end") or ""):
                raise SteerError(f"'{p['end']}': a {spec.structure} has no top or bottom to add a cube at (its cubes stand side by "
                                 "side); say which end (e.g. \"at the right end\"), or state the whole new task")
            anchorable = spec.structure in ANCHORED_KINDS and spec.direction is None and p.get("at") not in anchors
            if p.get("end") and spec.kind.spells and not _orders_cubes(spec) and not anchorable:
                raise SteerError(f"'{p['end']}': the {spec.structure}'s goal gives no cube a place (any order holds), so a cube "
                                 "added there cannot be judged; say the order of the whole line, or state the whole new task")
            if p.get("onto") and spec.kind.spells and not _orders_cubes(spec) and spec.structure not in ANCHORED_KINDS:
                raise SteerError(f"the {spec.structure}'s goal gives its cubes no places (any order holds), so a cube added next to "
                                 "one of them cannot be judged; say the whole order, or state the whole new task")
            if p.get("onto"):
                end = 0 if p.get("at") == "bottom" else len(spec.items) - 1
                idx = _indices(spec, p["onto"], anchors)
                if not idx:
                    raise _no_such_cube(p["onto"], spec, f"to add one {'under' if end == 0 else 'on'}")
                if idx != [end]:
                    raise SteerError(f"the cube {'under' if end == 0 else 'on'} which the edit adds one ({p['onto']}) is not the "
                                     f"{'bottom' if end == 0 else 'top'} of the {spec.structure}; the builtin steering adds cubes at "
                                     "its ends only: say where in the whole structure, or state the whole new task")
            if p.get("side") and spec.kind.spells and not _orders_cubes(spec):
                raise SteerError(f"'{p['side']}': the {spec.structure}'s goal gives no cube a place (any order holds), so a cube "
                                 f"added there cannot be judged; say the order of the whole {spec.structure}, or state the whole new task")
            new = [Item(**d) for d in p["items"]] or []
            grow = spec
            for _ in range(p.get("count") or 0):
                unused = [c for c in GRADIENT_ORDER if c not in grow.colors()]
                period = _period(list(grow.items)) if all(it.label is None for it in grow.items) else None
                # "add one more" to cubes all alike: one more of them; to cubes that repeat a pattern: the pattern goes on
                item = (Item(color=unused[0]) if spec.ordering == "color" and unused else
                        grow.items[len(grow.items) % period] if period and (period == 1 or p.get("at") != "bottom") else _next_item(grow))
                new.append(item)
                grow = grow.with_items(list(grow.items) + [item])
            at = p.get("at")
            side_end = re.search(r"\b(left|right|front|back) end\b", p.get("end") or "")
            if side_end and spec.direction:  # "at the left end" of a line read left to right: its first cube
                first, last = spec.direction.split("_to_")
                if side_end.group(1) not in (first, last):
                    raise SteerError(f"'{p['end']}': the line runs {spec.direction.replace('_', ' ')} and has no "
                                     f"{side_end.group(1)} end")
                at = "bottom" if side_end.group(1) == first else "top"
            items = new + list(spec.items) if at == "bottom" else list(spec.items) + new
            spec = spec.with_items(items)
            if spec.word:  # "add an S at the end": the cubes spell a longer word
                word = "".join(i.label or "" for i in spec.items)
                spec = replace(spec, word=word if word.isalpha() and len(word) == len(spec.items) else None)
        elif o.op == "direction":
            if spec.structure != "line":
                raise SteerError(f"a reading direction applies to a line; this task has a {spec.structure}")
            spec = replace(spec, direction=p["to"], axis=None)
        elif o.op == "move":
            if spec.kind.spells and not _orders_cubes(spec) and p["at"] != "middle":
                raise SteerError(f"the {spec.structure}'s goal gives its cubes no places (any order holds), so one moved to "
                                 f"{'the other end' if p['at'] == 'other' else 'its ' + p['at']} cannot be judged alone; say the order of the whole {spec.structure}")
            idx = _indices(spec, p["select"], anchors)
            if not idx:
                raise _no_such_cube(p["select"], spec, "to move")
            items = list(spec.items)
            at = p["at"]
            if at == "other":  # "to the other end": the end the cube does not stand at
                if idx[0] not in (0, len(items) - 1) or len(items) < 2 or len(idx) > 1:
                    raise SteerError(f"'the other end': {spec.items[idx[0]].phrase()} stands at no one end of the {spec.structure}; "
                                     "say which end it goes to (\"move it to the top\", \"... to the right end\")")
                at = "top" if idx[0] == 0 else "bottom"
            if at in ("left", "right"):  # "to the left end" of a row read left to right (or right to left)
                if spec.structure in ANCHORED_KINDS or spec.direction not in ("left_to_right", "right_to_left"):
                    raise SteerError(f"the {at} end of a {spec.structure} whose goal runs no way left to right is no place of "
                                     "its own; say the whole order from left to right")
                at = "bottom" if (at == "left") == (spec.direction == "left_to_right") else "top"
            if len(idx) > 1:
                raise SteerError(f"the edit moves one cube, but {len(idx)} cubes of the {spec.structure} are picked; name one")
            moved = items.pop(idx[0])
            if at == "middle":  # "put the white one in the middle": the one middle place of an odd row or tower
                if len(spec.items) % 2 == 0:
                    raise SteerError(f"a {spec.structure} of {len(spec.items)} cubes has no one middle place; say the whole order")
                if not _orders_cubes(spec) and len(set(items)) > 1:
                    raise SteerError(f"the {spec.structure}'s goal orders none of its cubes: with {moved.phrase()} in the middle "
                                     "the others' places stay unsaid, which its goal cannot state; say the whole order")
                spec = spec.with_items(items[:len(items) // 2] + [moved] + items[len(items) // 2:])
                if spec.direction is None:  # identical cubes either side: an order that holds from either end
                    spec = replace(spec, direction="sequence")
            else:
                spec = spec.with_items([moved] + items if at == "bottom" else items + [moved])
            if spec.ordering:
                spec = replace(spec, ordering=None)
        elif o.op == "arrange":
            spec = _arranged(spec, [Item(**it) for it in p["items"]], p["way"])
        elif o.op == "pattern":
            if spec.material != "colors":
                spec = spec.with_items(_material_items("colors", len(spec.items), []))
            colors = p["colors"]
            spec = replace(spec.with_items([Item(color=colors[i % len(colors)]) for i in range(len(spec.items))]),
                           layer_colors=False, ordering=None if spec.ordering == "color" else spec.ordering)
            if spec.structure == "line" and spec.direction is None:
                spec = replace(spec, direction="left_to_right")
        elif o.op in ("recolor", "relabel"):
            if p["select"] in ({"position": "middle"}, {"ends": True}) and spec.structure == "line" and spec.direction is None and len(ops) == 1 \
                    and (len(spec.items) % 2 or "ends" in p["select"]) and len(set(spec.items)) == 1:
                # "make the middle one gray" of a row of three white cubes, in no order: its middle place is one from
                # either end, read left to right (white, gray, white reads the same from its other end), the convention
                # six of seven steering annotators wrote (line[sequence] would say no axis; the README tells why not)
                spec = replace(spec, direction="left_to_right")
            idx = _indices(spec, p["select"], anchors)
            if not idx:
                raise _no_such_cube(p["select"], spec)
            items = list(spec.items)
            touched.update(idx)
            colours = p["to"].get("colors")  # a layer's cubes given one colour each, in the order said
            if colours is not None and len(colours) != len(idx):
                raise SteerError(f"{len(colours)} colours are said for {len(idx)} cubes; say one colour per cube")
            made = [Item(color=c) for c in colours] if colours is not None else [Item(**p["to"])] * len(idx)
            if o.op == "relabel" and spec.named and p["to"].get("label") in {it.label for i, it in enumerate(spec.items) if i not in idx}:
                raise SteerError(f"the {spec.structure} already has a {p['to']['label']} cube: '{p['to']['label']}' for another of its "
                                 "cubes makes two; to exchange two cubes say \"swap the A and the C\", or name a label it lacks")
            for i, item in zip(idx, made, strict=True):
                items[i] = item
            spec = replace(spec.with_items(items), layer_colors=False if spec.layer_colors and len(idx) < len(items) else spec.layer_colors)
            if spec.word:  # "change the B to a C": the word spelled is the cubes' now
                spec = replace(spec, word="".join(i.label or "?" for i in spec.items))
        elif o.op == "remove":
            idx = set(_removed_indices(spec, p["select"], anchors))
            if not idx:
                raise _no_such_cube(p["select"], spec)
            spec = spec.with_items([it for i, it in enumerate(spec.items) if i not in idx])
        elif o.op == "dims" and "pyramid_dims" in p:
            if spec.structure != "pyramid":
                raise SteerError(f"only a pyramid is 2D or 3D; this task has a {spec.structure}")
            dims = (spec.dims[0], p["pyramid_dims"])
            spec = _resize(replace(spec, dims=dims), pyramid_count(*dims))
            if spec.layer_colors:
                spec = _with_layer_colors(spec)
        elif o.op == "dims":
            if "base" in p:
                if spec.structure != "pyramid":
                    raise SteerError(f"a {spec.structure} has no base size; name its dimensions instead")
                dims = (p["base"], spec.dims[1])
                spec = _resize(replace(spec, dims=dims), pyramid_count(*dims))
            else:
                d = tuple(p["dims"])
                if spec.structure == "pyramid" and len(d) == 2 and d[0] == d[1]:
                    spec = _resize(replace(spec, dims=(d[0], 3)), pyramid_count(d[0], 3))
                elif spec.structure in ("grid", "block"):
                    structure = "block" if len(d) == 3 else "grid"
                    n = d[0] * d[1] * (d[2] if len(d) == 3 else 1)
                    spec = _resize(replace(spec, structure=structure, dims=d), n)
                else:
                    raise SteerError(f"dimensions {'x'.join(map(str, d))} do not fit a {spec.structure}")
            if spec.layer_colors:
                spec = _with_layer_colors(spec)
        elif o.op == "swap" and p.get("colors"):
            cols = list(dict.fromkeys(c for c in spec.colors() if c))
            if len(cols) != 2 or any(it.label for it in spec.items):
                raise SteerError(f"'swap the colours' names two colours, but the {spec.structure} has {len(cols)}; "
                                 "say which (e.g. \"swap the red and blue cubes\")")
            other = {cols[0]: cols[1], cols[1]: cols[0]}
            spec = spec.with_items([Item(color=other[it.color]) for it in spec.items])
        elif o.op == "swap":
            if spec.kind.layered and p.get("layers"):  # "swap the bottom colour and the top colour" of a pyramid: its layers
                p = {k: ({"layer": v["position"]} if isinstance(v, dict) and set(v) == {"position"} else v) for k, v in p.items()}
            ia, ib = _indices(spec, p["a"], anchors), _indices(spec, p["b"], anchors)
            if not ia or not ib:
                raise _no_such_cube(p["a"] if not ia else p["b"], spec)
            one_each = len({spec.items[i] for i in ia}) == len({spec.items[i] for i in ib}) == 1
            if len(ia) != len(ib) and one_each and spec.kind.layered and set(ia).isdisjoint(ib):
                # "swap the green and the white layers" of a pyramid (3 and 2 cubes): the two layers' colours exchanged
                a, b = spec.items[ia[0]], spec.items[ib[0]]
                spec = spec.with_items([b if i in ia else a if i in ib else it for i, it in enumerate(spec.items)])
                continue
            if len(ia) != len(ib) or (len(ia) > 1 and not one_each):
                raise SteerError(f"cannot swap {p['a']} ({len(ia)} cubes) with {p['b']} ({len(ib)} cubes); name one cube of each")
            items = list(spec.items)
            for i, j in zip(ia, ib, strict=True):
                items[i], items[j] = spec.items[j], spec.items[i]
            spec = spec.with_items(items)
            if spec.ordering:  # "swap A and D" of an alphabetical line: that order no longer holds
                spec = replace(spec, ordering=None)
        elif o.op == "count" and "delta" in p and not spec.kind.sized_by_count:
            dims = spec.kind.grown(spec.dims, p["delta"])
            if min(dims) < 2:
                raise SteerError(f"a {spec.structure} cannot be made smaller than {'x'.join(map(str, spec.dims))}")
            spec = _resize(replace(spec, dims=dims), spec.kind.cube_count(dims))
            if spec.layer_colors:
                spec = _with_layer_colors(spec)
        elif o.op == "count" and p.get("dim") and (not spec.kind.sized_by_count or spec.structure in DIM_AXES):
            axis = DIM_AXES.get(spec.structure, {}).get(re.sub(r"s$", "", p["dim"]))
            if axis is None or not spec.dims:
                raise SteerError(f"'{p['count']} {p['dim']}' does not name a side of a {spec.structure}")
            dims = list(spec.dims)
            dims[axis] = p["count"]
            spec = _resize_dims(spec, tuple(dims), keep_layers)
        elif o.op == "add_layer" and p.get("at") == "bottom":
            spec = _layer_added_below(spec, p)
        elif o.op == "add_layer":
            axis = LAYER_AXES.get(spec.structure)
            if axis is None:
                raise SteerError(f"a {spec.structure} cannot take another row or layer; change its size instead")
            top = _layers_of(spec)[-1] if spec.kind.layered else [i.color for i in spec.items]
            color = p.get("color") or (top[0] if len(set(top)) == 1 else None)
            if color is None:
                raise SteerError("say the colour of the new row (e.g. \"add a row on top, in black\")")
            if not spec.kind.layered and {color} != set(spec.colors()):
                raise SteerError(f"a {spec.structure}'s goal does not say which row a cube stands in, so a row of another "
                                 "colour cannot be judged; state the whole new task")
            dims = list(spec.dims)
            if p.get("n") is not None and p["n"] != len(spec.items) // spec.dims[axis]:
                raise SteerError(f"a new row of {p['n']} cubes does not fit a {spec.structure} whose rows hold "
                                 f"{len(spec.items) // spec.dims[axis]}; state the whole new task, or use --model")
            dims[axis] += 1
            grown = replace(spec, dims=tuple(dims))
            spec = grown.with_items(list(spec.items) + [Item(color=color)] * (len(spec.items) // spec.dims[axis]))
        elif o.op == "count":
            if not spec.kind.sized_by_count:
                raise SteerError(f"the size of a {spec.structure} is set by its dimensions (e.g. \"a 3x3 base\")")
            if spec.word and not any(q.op == "word" for q in ops):  # "n=4" of CAT: which letter? (a made-up one had been added)
                raise SteerError(f"the cubes spell '{spec.word}'; a count says no letters: say the new word (e.g. \"make it "
                                 f"spell {spec.word}S\"), or use --model")
            n = p.get("count") or (round(len(spec.items) * p["factor"]) if "factor" in p else len(spec.items) + p.get("delta", 0))
            if p.get("grow") and (n - len(spec.items)) * p["grow"] <= 0:
                raise SteerError(f"'{'taller' if p['grow'] > 0 else 'shorter'}' and {n} cubes disagree: the "
                                 f"{spec.structure} has {len(spec.items)}; say the count alone")
            colours = [it.color for it in spec.items]
            if n > len(spec.items) and not spec.kind.layered and all(it.label is None for it in spec.items) \
                    and len(set(colours)) > 1 and _period(list(spec.items)) is None and spec.ordering != "color" \
                    and _orders_cubes(spec) and not any(q.op in ("recolor", "pattern", "colors", "material", "word") for q in ops):
                # (a stack in any order is of cubes nobody named: one more of them is as free; "make it 4 high all green",
                # "five tall, alternating red and blue" say the colours)
                # "make it 5" of a red, yellow, blue tower: which colours the new cubes have is unsaid (green and orange had
                # been made up, a goal stricter than the words)
                raise SteerError(f"the {spec.structure} has cubes of {len(set(colours))} colours ({', '.join(colours)}); '{n}' "
                                 "says how many but not the new cubes' colours: say them (e.g. \"add a green and an orange cube "
                                 "on top\"), or use --model")
            spec = _resize(spec, n)
        elif o.op == "word":
            if not spec.kind.spells:
                raise SteerError(f"a {spec.structure} does not spell a word; say e.g. \"spell {p['word']} in a line\"")
            spec = replace(spec.with_items([Item(label=ch) for ch in p["word"]]), word=p["word"], ordering=None,
                           direction=spec.direction or "left_to_right")
        elif o.op == "colors":
            k = p["count"]
            if not 1 <= k <= len(DEFAULT_COLORS):
                raise SteerError(f"between 1 and {len(DEFAULT_COLORS)} colours are available")
            palette = (list(dict.fromkeys(spec.colors())) + [c for c in DEFAULT_COLORS if c not in spec.colors()])[:k]
            if spec.structure == "piles":
                per = max(2, len(spec.items) // max(len(set(spec.colors())), 1))
                spec = replace(spec.with_items([Item(color=c) for c in palette for _ in range(per)]), piles_by="color")
            else:
                spec = spec.with_items([Item(color=palette[i % k]) for i in range(len(spec.items))])
        elif o.op == "region":
            continue  # the structure's place: a modifier (carried_after)
        elif o.op == "outliers":
            if spec.structure != "piles":
                raise SteerError("outliers apply to piles; this task has a " + spec.structure)
            spec = replace(spec, outliers=p["per_pile"])
    if spec.structure in ("line", "tower") and spec.ordering in ("label", "number") and spec.items and all(i.label for i in spec.items):
        # a sorted line or tower of named cubes: its cubes stand in that order ("descending now", "add a 5 and keep it largest
        # first", "put them in a tower instead, smallest on top": a tower's cubes listed bottom first)
        spec = spec.with_items(sort_labels(spec.items, spec.ordering, spec.descending))
    return spec
