"""The words of an instruction, before any reader sees them: normalisation and features.

:func:`normalize` lower-cases an instruction, refuses what the domain cannot express
(:data:`rpg.schema.lexicon.INEXPRESSIBLE`), writes number words as digits, corrects typos
into the vocabulary (:data:`rpg.schema.lexicon.VOCAB`), drops or classifies unknown words by
their embedding (:mod:`rpg.schema.senses`) and refuses the rest naming them;
:func:`features` gives the readers (:mod:`rpg.schema.readers`) the normalised text with its
colour mentions.  Places on the table are marked (``@region_<name>``) by :func:`mark_regions`.

Frame conventions: see :mod:`rpg.domain.constants`.
"""

from __future__ import annotations

import functools
import itertools
import re
from collections.abc import Callable
from dataclasses import dataclass, field

from rapidfuzz import fuzz, process

from rpg.domain import constants as C
from rpg.domain.palette import COLOR_ALIASES
from rpg.errors import BadInput
from rpg.schema import lexicon, senses
from rpg.schema.builder import DEFAULT_COLORS
from rpg.schema.lexicon import (
    COLOR_RE,
    COLORS,
    COMPASS_CORNER_RE,
    COMPASS_REL_RE,
    COMPASS_SIDE_RE,
    HEIGHT_WORDS,
    NUMBER_WORDS,
    REGION_WORDS,
    TOWER_NOUNS,
    VOCAB,
    names_a_role,
)
from rpg.schema.structures import STRUCTURE_RE


class ParseError(BadInput):
    """The builtin front end cannot read the instruction; the message says which part."""


MAX_INSTRUCTION_CHARS = 2000
"""Longest instruction accepted, characters (after fillers, hesitations and markup are removed)."""

MAX_RAW_CHARS = 4 * MAX_INSTRUCTION_CHARS
"""Longest text read at all, characters: a longer one is refused before any rewriting (a text of
thousands of spoken corrections had taken minutes to rewrite)."""


IGNORABLE_HERE = (lexicon.IGNORABLE | lexicon.IGNORABLE_MORE) - VOCAB
"""Ignorable words (:data:`lexicon.IGNORABLE`) the parser's vocabulary does not use itself."""


def _compass(text: str) -> str:
    """Compass words in the frame of :mod:`rpg.schema.lexicon`: "the NW corner" -> "the back
    left corner", "to the north of" -> "behind", "the east side" -> "the right side"."""
    def corner(m: re.Match) -> str:
        key = re.sub(r"[- ]", "", m.group(1))
        key = {"northwest": "nw", "northeast": "ne", "southwest": "sw", "southeast": "se"}.get(key, key)
        return "the " + lexicon.COMPASS_CORNERS[key].replace("_", " ") + " corner"
    text = COMPASS_CORNER_RE.sub(corner, text)
    text = COMPASS_REL_RE.sub(lambda m: lexicon.COMPASS_RELATIONS[m.group(1)] + (" of" if m.group(1) in ("east", "west") else ""), text)
    text = re.sub(r"\b(left|right) of of\b", r"\1 of", text)
    return COMPASS_SIDE_RE.sub(lambda m: f"the {lexicon.COMPASS[m.group(1)]} {m.group(2)}", text)


@dataclass
class Features:
    text: str
    original: str
    colors: list[tuple[int, str]] = field(default_factory=list)
    quoted: list[str] = field(default_factory=list)

    def has(self, *words: str) -> bool:
        return any(re.search(rf"\b{w}\b", self.text) for w in words)

    def color_list(self) -> list[str]:
        return [c for _, c in self.colors]


def canon_color(word: str) -> str:
    return COLOR_ALIASES.get(word, word)


def _transposition(word: str) -> tuple[str] | None:
    """The one known word that ``word`` (a short typo) becomes by swapping two adjacent
    letters ("teh" -> "the", "rde" -> "red"), as a 1-tuple; None if none or several."""
    found = {word[:i] + word[i + 1] + word[i] + word[i + 2:] for i in range(len(word) - 1)}
    known = sorted(w for w in found if w != word and (w in VOCAB or w in COLORS))
    return (known[0],) if len(known) == 1 else None


class Inexpressible(ParseError):
    """The instruction says something the domain cannot express (a negation, a condition, a
    time, a measured quantity, a size, an object it lacks): :data:`lexicon.INEXPRESSIBLE`.

    The message names every such thing the instruction says, the first with why in full and
    the rest in short ("'rotate' is an action the domain does not have: ...; also '90 degrees'
    is a measured or vague quantity"), so a text that says several is refused for all of them.
    ``reasons`` holds them as (class, words, why); ``kind`` is the first one's class.
    """

    def __init__(self, kind: str, words: list[str], why: str, original: str,
                 also: tuple[tuple[str, list[str], str], ...] = ()):
        def shown(ws):
            return ", ".join(f"'{w}'" for w in ws)
        more = "".join(f"; also {shown(ws)} {w.split(':')[0]}" for _, ws, w in also)
        super().__init__(f"cannot make a task of \"{original[:80]}\": {shown(words)} {why}{more}. Rephrase, or use --model")
        self.kind = kind
        self.reasons = ((kind, list(words), why), *also)

    @classmethod
    def of(cls, reasons: list[tuple[str, list[str], str]], original: str) -> Inexpressible:
        """One refusal naming each of ``reasons`` ((class, words, why), first in full)."""
        merged: dict[str, tuple[str, list[str], str]] = {}
        for kind, words, why in reasons:  # one entry per class; a word inside a phrase already named is not named again
            said = " ".join(w for _, ws, _ in merged.values() for w in ws)
            fresh = [w for w in words if not re.search(rf"(?<![\w-]){re.escape(w)}(?![\w-])", said)]
            if fresh and kind in merged:
                merged[kind][1].extend(fresh)
            elif fresh:
                merged[kind] = (kind, list(fresh), why)
        (kind, words, why), *also = merged.values()
        return cls(kind, words, why, original, tuple(also))


_INEXPRESSIBLE = tuple((kind, re.compile(pattern), why) for kind, pattern, why in lexicon.INEXPRESSIBLE)


_SYNONYM_RE = re.compile(r"\b(?:" + "|".join(sorted(lexicon.SYNONYMS, key=len, reverse=True)) + r")\b")


def _inexpressible(text: str) -> list[tuple[str, list[str], str]]:
    """(class, words, why) for each class of :data:`lexicon.INEXPRESSIBLE` that lower-cased
    ``text`` says, in the table's order (a class listed twice with two reasons gives two)."""
    found = []
    for kind, pattern, why in _INEXPRESSIBLE:
        words = list(dict.fromkeys(lexicon.said(m) for m in pattern.finditer(text)))
        if words:
            found.append((kind, words, why))
    compared = list(dict.fromkeys(m.group(0) for m in lexicon.SIZE_COMPARATIVE_RE.finditer(text)))
    if compared and not lexicon.LABEL_VALUE_RE.search(text):
        found.append(("size", compared, _KIND_WHY["size"]))
    return found


def rearranged(m: re.Match) -> str:
    """Labels listed as they start and as they end (:data:`lexicon.REARRANGED_RE`): "arranged in the order" of the end.

    Raises:
        ParseError: the two lists name different labels (which cubes the task has is then unsaid).
    """
    first, then = (sorted(re.findall(r"[A-Z0-9]", m.group(g))) for g in ("first", "then"))
    if first != then:
        raise ParseError(f"'{m.group(0)}' lists other labels at the end ({', '.join(then)}) than at the start "
                         f"({', '.join(first)}); say the cubes once, in their end order, or use --model")
    return f"arranged in the order {m.group('then')}"


def _framing_sentence(sentence: str) -> bool:
    """Whether a sentence that does not end with "!" is framing (:func:`drop_asides`): a statement or a request to a
    person that names nothing of the task ("Code is linked in the description.", "Go when ready.", "Let me know if
    anything's unclear."): no word of a goal (:data:`lexicon.TASK_CONTENT_RE`, :data:`lexicon.ASIDE_CONTENT_RE`), nothing
    that may change what the task asks (:data:`lexicon.FRAMING_SENTENCE_HAZARD_RE`) nor any other domain refusal than a
    condition or a question (a condition on a person conditions no goal), every word one of the dictionary or a name, no
    adjective or adverb of manner beyond fillers ("Wobbly.", "Loosely." stay), and, when it opens with a verb, one said
    to a person (:data:`lexicon.OPERATOR_VERBS`)."""
    low = sentence.lower()
    unconditioned = re.sub(r"\b(?:if|when)\b", " ", low)  # a condition on a person ("Go when ready.") conditions no goal
    if lexicon.TASK_CONTENT_RE.search(low) or lexicon.ASIDE_CONTENT_RE.search(unconditioned) \
            or lexicon.FRAMING_SENTENCE_HAZARD_RE.search(low):
        return False
    if any(k not in ("condition", "question") for k, _, _ in _inexpressible(low)):
        return False  # a size, an object, an action...: refused for it, not dropped
    words = re.findall(r"[A-Za-z][A-Za-z']*", sentence)
    if not words or any(w.lower() in lexicon.TASK_SCENE_VERBS for w in words):
        return False  # "Unstack.": a verb that changes the scene (it had been dropped as framing, the tower kept)
    for i, w in enumerate(words):
        base = w.lower().removesuffix("'s")
        if not (base in VOCAB or base in lexicon.IDLE_WORDS or lexicon.is_dictionary_word(base) or (i and w[0].isupper())):
            return False  # an unknown word (a capital inside the sentence is a name): the unknown-word rules decide
    for w in words:
        pos = lexicon.parts_of_speech(w.lower())
        if pos & {"ADJ", "ADV"} and not pos & {"NOUN", "VERB"} and w.lower() not in (
                lexicon.IDLE_WORDS | lexicon.CHAT_WORDS | lexicon.FUNCTION_WORDS | {"when", "where", "how", "why", "sorry"}):
            return False  # a manner or a property ("Wobbly.", "Loosely."): the domain may lack it, so it is not dropped
    opening = [w.lower() for w in words if w.lower() not in ("please", "just", "now", "and", "so", "ok", "okay", "also")]
    if opening and "VERB" in lexicon.parts_of_speech(opening[0]) and opening[0] not in lexicon.OPERATOR_VERBS and (
            len(opening) == 1 or opening[1] not in lexicon.AUXILIARY_WORDS):
        return False  # an imperative to the robot ("Demolish.", "Tidy up."): it may change the goal
    return True


def _commentary_sentence(sentence: str) -> bool:
    """Whether a sentence of a text that says its task elsewhere is a voice's commentary (a recipe's "Season to taste.", a
    ship's log's "Calm seas.", a commentator's "The crowd goes wild."), dropped by :func:`drop_asides`: at least two
    words; no word of a goal, count or digit (:data:`lexicon.TASK_CONTENT_RE`, :data:`lexicon.ASIDE_CONTENT_RE`); nothing
    that may change what the task asks (:data:`lexicon.FRAMING_SENTENCE_HAZARD_RE`, a verb of
    :data:`lexicon.SCENE_CHANGING_VERBS`); no domain refusal that may bear on a goal
    (:data:`lexicon.COMMENTARY_BLOCKING_KINDS`).  Unlike :func:`_framing_sentence` its words need not be the
    dictionary's, nor plain: a voice's words are its own, and none of them names a cube."""
    low = sentence.lower()
    words = re.findall(r"[a-z][a-z'\-]*", low)
    if len(words) < 2 or re.search(r"\d", low) or lexicon.TASK_CONTENT_RE.search(low) or lexicon.ASIDE_CONTENT_RE.search(low) \
            or lexicon.FRAMING_SENTENCE_HAZARD_RE.search(low) or lexicon.RETRACTION_RE.search(low) \
           :
        return False
    for w in words:
        for part in w.split("-"):
            base = part.removesuffix("'s")
            if base in lexicon.SCENE_CHANGING_VERBS or any(x in lexicon.SCENE_CHANGING_VERBS for x in lexicon.lemmas(base)):
                return False
            if base in COLORS or base in lexicon.colour_names() or (
                    base not in VOCAB and senses.sense(base).kind in lexicon.COMMENTARY_BLOCKING_KINDS):
                return False
    return not any(k in lexicon.COMMENTARY_BLOCKING_KINDS for k, _, _ in _inexpressible(low))


_VOICE_WORLD_ASIDE_RE = re.compile(r"\b(?:not|no|never)\b")
_OPENING_FILLERS = frozenset({"and", "so", "now", "please", "just", "oh", "well", "then", "go", "come"})
_NOT_VERBS = frozenset({"up", "down", "out", "off", "in", "on", "over", "away", "back", "well", "low", "high"})
"""Words the dictionary also knows as verbs that a voice's sentence holds as particles or adverbs ("Logos up."): no verb."""
_PERSONS_OWN = frozenset({"your", "yer", "ya", "his", "her", "their", "my", "our"})
"""Possessives that make a thing a person's own ("your air gauge", "her mouse")."""
_AUXILIARY_LEMMAS = frozenset({"be", "have", "do", "can", "will", "shall", "may", "might", "must", "would", "could", "should"})


def _voice_sentence(sentence: str) -> bool:
    """Whether a sentence of a text that says its task elsewhere speaks of a voice's own world ("No running on deck!",
    "Headquarters is counting on you.", "Enjoy your stay.", "I'll see you later."), dropped by :func:`drop_asides` like
    commentary (:func:`_commentary_sentence`): a verb of its own, no word of a goal, count, colour, digit or place
    (:data:`lexicon.TASK_CONTENT_RE` but for "on": "on deck"; :data:`lexicon.ASIDE_CONTENT_RE` but for a negation, which is
    then of that world; a condition stays: "If there is room."), no verb that changes a scene
    (:data:`lexicon.SCENE_CHANGING_VERBS` but a person's persisting, :data:`lexicon.VOICE_WORLD_VERBS_EXEMPT`), no
    take-back (:data:`lexicon.RETRACTION_RE`) and nothing that may refer to the task or bear on how it is done
    (:data:`lexicon.VOICE_SENTENCE_HAZARD_RE`); a domain refusal of it may only be a
    negation, an object, an action or a question (those of that world), and a negation needs four words or more (a short
    one, "No tools!", has no world of its own but the task's).  A sentence the speaker tells of themselves
    (:data:`lexicon.NARRATOR_OPENING_RE`: "I'll see you later.") may also hold a step of a sequence
    (:data:`lexicon.NARRATION_FREE_RE`): the speaker's day, not the task's.  An imperative (:func:`_imperative`) is said to
    the one who does the task ("Wipe the whiteboard.", "Pinch lightly.", "Don't proceed.") and stays, unless its verb is
    one of regard (:data:`lexicon.REGARD_VERBS`: "Mind the gap.", "Enjoy your stay.")."""
    low = sentence.lower()
    words = re.findall(r"[a-z][a-z'\-]*", low)
    narrated = lexicon.NARRATOR_OPENING_RE.match(low)  # "I'll be back later.": the speaker's time, not the task's
    weighed = lexicon.NARRATION_FREE_RE.sub(" ", low) if narrated else low
    if not words or re.search(r"\d", low) or lexicon.TASK_CONTENT_RE.search(re.sub(r"\bon\b", " ", low)) \
            or lexicon.GOAL_THING_PREFIX_RE.search(low) \
            or lexicon.ASIDE_CONTENT_RE.search(_VOICE_WORLD_ASIDE_RE.sub(" ", weighed)) \
            or lexicon.VOICE_SENTENCE_HAZARD_RE.search(weighed) or lexicon.RETRACTION_RE.search(low) \
           :
        return False
    if _said_to_the_doer(words):
        return False  # "Wipe the whiteboard.", "Pinch lightly.", "Don't proceed.": said to the one who does the task
    if _VOICE_WORLD_ASIDE_RE.search(low) and len(words) < 4:
        return False  # "No tools!", "No dragging!": a short negation has no world of its own to belong to: the task's
    verb = False
    for w in words:
        for part in w.split("-"):
            base = part.removesuffix("'s")
            lemmas = {base, *lexicon.lemmas(base)}
            if lemmas & lexicon.SCENE_CHANGING_VERBS and not lemmas & lexicon.VOICE_WORLD_VERBS_EXEMPT:
                return False
            if base in COLORS or base in lexicon.colour_names():
                return False
            verb = verb or ("VERB" in lexicon.parts_of_speech(base) and base not in lexicon.IDLE_WORDS
                            and not lemmas & _AUXILIARY_LEMMAS and base not in _NOT_VERBS)
    return verb and all(k in ("negation", "object", "action", "question") for k, _, _ in _inexpressible(weighed))


def _world_statement(sentence: str) -> bool:
    """Whether a sentence (or a clause before ";") of a text that says its task elsewhere is a statement about a third
    party of a voice's world ("Varnish dries at its own pace.", "A good bookbinder never rushes the press.", "Roofing's a
    slow trade.", "Sewing can wait"), dropped by :func:`drop_asides`: a subject of the voice's own (a noun phrase of words
    the parser does not read, none of :data:`lexicon.WORLD_SUBJECT_HAZARD_WORDS`, after a place of that world,
    :data:`lexicon.WORLD_OPENING_PLACE_RE`) followed by a verb said of it, no question, no digit, and once the party's own
    time, manner and negation are set apart (:data:`lexicon.WORLD_STATEMENT_OWN_RE`) nothing that may bear on the task
    (:data:`lexicon.TASK_CONTENT_RE`, :data:`lexicon.VOICE_SENTENCE_HAZARD_RE`, :data:`lexicon.ASIDE_CONTENT_RE`, a take-back,
    a colour, a verb that changes a scene) and no domain refusal but an object, an action, a negation or a time.  Said to
    the one who does the task ("Never rush.", "Go slowly.") a sentence has no subject of its own and stays."""
    low = sentence.lower().strip()
    if low.endswith("?") or re.search(r"\d", low):
        return False
    opening = lexicon.WORLD_OPENING_PLACE_RE.match(low)
    if opening and opening.group("n") not in VOCAB:
        low = low[opening.end():]
    words = re.findall(r"[a-z][a-z'\-]*", low)
    if len(words) < 2 or not _world_subject(words):
        return False
    quantified = words[0] in lexicon.WORLD_SUBJECT_QUANTIFIERS  # "Every hull ...": the subject's quantifier set apart
    subject = "the " + low.split(None, 1)[1] if quantified and len(low.split(None, 1)) > 1 else low
    weighed = lexicon.WORLD_STATEMENT_OWN_RE.sub(" ", subject)
    if lexicon.TASK_CONTENT_RE.search(weighed) or lexicon.GOAL_THING_PREFIX_RE.search(weighed) \
            or lexicon.VOICE_SENTENCE_HAZARD_RE.search(weighed) or lexicon.ASIDE_CONTENT_RE.search(weighed) \
            or lexicon.RETRACTION_RE.search(low):
        return False
    for w in words:
        base = w.removesuffix("'s")
        lemmas = {base, *lexicon.lemmas(base)}
        if base in COLORS or base in lexicon.colour_names() or (
                lemmas & lexicon.SCENE_CHANGING_VERBS and not lemmas & lexicon.VOICE_WORLD_VERBS_EXEMPT):
            return False
    return all(k in ("negation", "object", "action", "time") for k, _, _ in _inexpressible(low))


def _world_subject(words: list[str]) -> bool:
    """Whether ``words`` (lower case) open with a subject of a voice's world and a verb said of it: determiners
    (:data:`lexicon.WORLD_SUBJECT_DETERMINERS`), one to three nouns or adjectives none of which the parser reads, the
    last a noun of none of :data:`lexicon.WORLD_SUBJECT_HAZARD_WORDS`, then "'s" on it, a word of
    :data:`lexicon.WORLD_FINITE_WORDS`, or a verb that agrees with it ("Varnish dries", "stalagmites grow")."""
    i = 0
    while i < len(words) and words[i] in lexicon.WORLD_SUBJECT_DETERMINERS:
        i += 1
    for j in range(i, min(i + 3, len(words))):
        w = words[j]
        head = w.removesuffix("'s")
        pos = lexicon.parts_of_speech(head)
        noun = not pos or bool(pos & {"NOUN", "PROPN"}) or (head.endswith("ing") and "VERB" in pos)  # "luthier", "Sewing"
        if head in VOCAB or head in lexicon.WORLD_SUBJECT_HAZARD_WORDS or not (noun or "ADJ" in pos):
            return False
        if w.endswith("'s") and noun:
            return True  # "Roofing's a slow trade."
        nxt = words[j + 1] if j + 1 < len(words) else ""
        if not noun or not nxt:
            continue
        if nxt in lexicon.WORLD_FINITE_WORDS:
            return True
        verb, forms = lexicon.parts_of_speech(nxt), lexicon.lemmas(nxt)
        plural = head.endswith("s") and head not in lexicon.lemmas(head)
        if "VERB" in verb and nxt not in VOCAB and ((nxt.endswith("s") and nxt not in forms and not plural)
                                                   or (plural and nxt in forms)):
            return True  # "Varnish dries", "the stalagmites grow"
    return False


def _said_to_the_doer(words: list[str]) -> bool:
    """Whether a sentence of ``words`` (lower case) is an imperative said to the one who does the task (:func:`_imperative`;
    "Wipe the whiteboard.", "Use the tongs.", "Don't proceed."), not one of regard (:data:`lexicon.REGARD_VERBS`: "Mind
    the gap.") nor one on a thing of a person's own ("Check your air gauge.": that person's world; no cube is anyone's)."""
    opening = list(itertools.dropwhile(lambda w: w in _OPENING_FILLERS, words))[:3]
    return bool(opening) and _imperative(opening) and not {opening[0], *lexicon.lemmas(opening[0])} & lexicon.REGARD_VERBS \
        and not (len(opening) > 1 and opening[1] in _PERSONS_OWN)


def _imperative(opening: list[str]) -> bool:
    """Whether a sentence opening with ``opening`` (its first words, lower case, fillers dropped) is said to the one who
    does the task: a verb in its base form not followed by a verb of its own ("Pinch lightly.", "Wipe the whiteboard.";
    not "Breakfast is served"), or "don't", "do not", "never", "please" before one."""
    if opening[0] in ("don't", "dont", "never", "please") or opening[:2] == ["do", "not"]:
        return True
    first = opening[0]
    if "VERB" not in lexicon.parts_of_speech(first) or first not in lexicon.lemmas(first):
        return False
    after = opening[1] if len(opening) > 1 else ""
    finite = after in ("is", "are", "was", "were", "will", "has", "have", "had", "can", "must", "should", "may", "might") or (
        "VERB" in lexicon.parts_of_speech(after) and after.endswith(("s", "ed")) and after not in lexicon.lemmas(after))
    return not (finite and "NOUN" in lexicon.parts_of_speech(first))  # "Pool closes at five.": a noun and its verb


def _frame_prefix(words: str) -> bool:
    """Whether the words before a task's imperative frame it for a person (:data:`lexicon.FRAME_PREFIX_RE`): words that
    name the task, address a person or say it is needed (:data:`lexicon.FRAME_NOUN_RE`), nothing of a goal, no hazard
    (:data:`lexicon.FRAME_PREFIX_HAZARD_RE`; names with numbers, "Homework 1", "Project RB-7", are no count), nothing
    the domain refuses (an object: "Use the ruler to ..."), no verb but a frame's (:data:`lexicon.FRAME_VERBS`), and
    every word a dictionary word, a name or a number."""
    low = re.sub(r"\b(?:in|for|during)\s+this\s+(?:experiment|task|episode|run|variant|setting|study|trial|eval(?:uation)?|benchmark"
                 r"|section|lesson|level|round|version|exercise|challenge|test)\b", " ", words.lower())  # "In this experiment,"
    low = re.sub(r"\b(?:[a-z]+[-_]?\d[\w\-]*|\d+[a-z][\w\-]*)\b|\b(?:tasks?|homework|levels?|projects?|sections?|lessons?|exercises?"
                 r"|steps?|parts?|stages?|rounds?|trials?|episodes?|activit(?:y|ies)|challenges?|questions?|q|items?|cards?|tickets?"
                 r"|deliverables?|milestones?|protocols?)\s*#?\d+(?:\.\d+)*[a-z]?\b", " ", low)  # "Homework 1", "Project RB-7": names
    if lexicon.GOAL_THING_RE.search(low) or lexicon.FRAME_PREFIX_HAZARD_RE.search(low) \
            or not lexicon.FRAME_NOUN_RE.search(words.lower()):
        return False
    if _inexpressible(low):
        return False  # an object ("Use the ruler to line up ..."), an action, a time...: refused for it, not dropped
    tokens = re.findall(r"[A-Za-z][A-Za-z'\-]*", words)
    for t in tokens:  # a verb of its own may say what was done or seen ("Do what you did:"): only a frame's verbs
        pos = lexicon.parts_of_speech(t.lower())
        if "VERB" in pos and not pos & {"NOUN", "ADJ", "PROPN"} and t.lower() not in lexicon.FRAME_VERBS:
            return False
    return bool(tokens) and all(
        t.lower().removesuffix("'s") in VOCAB or t.lower() in lexicon.IDLE_WORDS or lexicon.is_dictionary_word(t.lower().removesuffix("'s"))
        or (i and t[0].isupper()) for i, t in enumerate(tokens))


def _evaluation_report(sentence: str) -> bool:
    """Whether a sentence (or a parenthesis) reports on evaluating the task, not the task ("Ranked by success rate over
    100 episodes.", "Best entry so far: 71%.", "fails on roughly 30% of seeds"): it has a word of evaluation
    (:data:`lexicon.EVALUATION_WORD_RE`) and nothing of a goal, requirement or sequence
    (:data:`lexicon.EVALUATION_BLOCKER_RE`), and no word the domain cannot express but a quantity, a size, a negation,
    time, a condition or an action other than a move of cubes (those judge policies here: "never fires", "best",
    "roughly", "over 100 episodes")."""
    low = re.sub(r"\b(?:so|thus)\s+far\b", " ", sentence.lower())  # "Best entry so far: 71%.": a time, not a distance
    if not lexicon.EVALUATION_WORD_RE.search(low) or lexicon.EVALUATION_BLOCKER_RE.search(low):
        return False
    return all(k in ("quantity", "size", "negation", "time", "condition", "question", "action") for k, _, _ in _inexpressible(low))


def _title_heading(sentence: str, rest: str) -> bool:
    """Whether ``sentence`` is a title over the ``rest`` of the text ("Challenge: Wall Builder.", "CHALLENGE 2 - Tower
    Rush."): at most :data:`lexicon.TITLE_MAX_WORDS` words, each capitalised (numbers are its identifier), no word
    that may change the task (:data:`lexicon.FRAMING_SENTENCE_HAZARD_RE`, a structure word aside), and every word of
    the task in it said again in the rest (a title that says more than the text, "Red Tower. Build a tower of three.",
    is no title: its colour would be lost)."""
    words = re.findall(r"[A-Za-z][A-Za-z'\-]*", sentence)
    if not rest.strip() or not words or len(words) > lexicon.TITLE_MAX_WORDS or not all(w[0].isupper() for w in words):
        return False
    low = " ".join(w.lower() for w in words)
    content = {m.group(0) for m in lexicon.TASK_CONTENT_RE.finditer(low)}
    hazards = {m.group(0) for m in lexicon.FRAMING_SENTENCE_HAZARD_RE.finditer(low)} - content
    rest_words = set(re.findall(r"[a-z]+", rest.lower()))
    spelled = {w.lower() for w in words if len(w) > 1 and w.isupper()} if re.search(  # "Spell CAT. Spell DOG.": a word
        r"(?i)\b(?:spell\w*|reads?|word)\b", sentence) else set()  # to spell, no title
    return not hazards and spelled <= rest_words and all(c in rest_words or c.rstrip("s") in rest_words or f"{c}s" in rest_words
                                                         for c in content)


def _address_chunk(chunk: str) -> bool:
    """Whether a chunk at a sentence's edge, set off by a comma, colon or dash, only calls out to a listener or exclaims
    ("Arr matey, ...", "..., recruit!", "Hey team: ..."): at most four words, each an interjection or a noun of address
    (:data:`lexicon.INTERJECTIONS`), a filler (:data:`lexicon.IDLE_WORDS`, :data:`lexicon.CHAT_WORDS`) or "listen up",
    and nothing of a goal, no hazard and nothing the domain refuses."""
    low = chunk.lower().strip(" ,:;!?-\u2013\u2014")
    words = re.findall(r"[a-z][a-z']*", low)
    if not words or len(words) > 4 or re.search(r"\d", low):
        return False
    if lexicon.TASK_CONTENT_RE.search(low) or lexicon.GOAL_THING_RE.search(low) or lexicon.FRAMING_SENTENCE_HAZARD_RE.search(low) \
            or _inexpressible(low):
        return False
    if any(len(w) == 1 for w in words):
        return False  # "..., A.": a letter cube's label, not a call
    low = re.sub(r"\blisten\s+up\b", " hey ", re.sub(r"\bmy\s+(?=\w)|\bdear\s+(?=\w)", " ", low))
    words = re.findall(r"[a-z][a-z']*", low)
    return any(w in lexicon.INTERJECTIONS or w in lexicon.CHAT_WORDS for w in words) and all(
        w in lexicon.INTERJECTIONS or w in lexicon.IDLE_WORDS or w in lexicon.CHAT_WORDS for w in words)


def _without_address(sentence: str) -> str:
    """``sentence`` without the chunks at its start and end that only call out to a listener (:func:`_address_chunk`)."""
    for _ in range(2):
        m = re.match(r"\s*([^,:;\u2013\u2014]{1,40}?)\s*(?:[,:\u2013\u2014]|\s-)\s+(?=\S)", sentence)
        if not (m and _address_chunk(m.group(1))):
            break
        sentence = sentence[m.end():]
    for _ in range(2):
        m = re.search(r"\s*,\s*([^,:;]{1,40}?)\s*(?P<end>[.!?]*)\s*$", sentence)
        if not (m and _address_chunk(m.group(1))):
            break
        asks = re.match(r"\s*(?:how|what|which|where|why|who|whom|whose|when|is|are|was|were|do|does|did|can|will|shall|should"
                        r"|has|have)\b", sentence, re.IGNORECASE)  # a question stays one ("How many ..., sweetie?")
        sentence = sentence[:m.start()] + (m.group("end") if asks else m.group("end").replace("?", "."))  # "..., savvy?": the
        # tag's question mark goes with it
    return sentence


def _restates_relations(low: str, rest: str) -> bool:
    """Whether every word of a simile ``low`` that :data:`lexicon.VOICE_SIMILE_BLOCKER_RE` blocks is a relation the words
    before it (``rest``) already say, by :data:`lexicon.SIMILE_RELATION_WORDS` ("..., like the monitor behind the singer"
    of "put the black cube behind the white cube"; "..., like moss on driftwood" of "stack a green cube on it"): the simile
    pictures that relation and says nothing of its own."""
    said = {lexicon.SIMILE_RELATION_WORDS[w] for w in re.findall(r"[a-z]+", rest.lower()) if w in lexicon.SIMILE_RELATION_WORDS}
    blockers = [m.group(0) for m in lexicon.VOICE_SIMILE_BLOCKER_RE.finditer(low)]
    return bool(blockers) and all(lexicon.SIMILE_RELATION_WORDS.get(w) in said for w in blockers)


def _voice_chunk(chunk: str, label: bool = False, rest: str = "") -> bool:
    """Whether a chunk at a task's edge (:data:`lexicon.VOICE_LABEL_RE`, :data:`lexicon.VOICE_TAIL_RES`) is a voice's
    and says nothing of the task: no hazard (:data:`lexicon.VOICE_CHUNK_HAZARD_RE`: a negation, condition, reference,
    quantifier, size, order, time, pose, shape, the robot or a listener), no take-back (:data:`lexicon.RETRACTION_RE`),
    no label cube's letter or digit, no domain refusal that may bear on a goal (:data:`lexicon.COMMENTARY_BLOCKING_KINDS`,
    a condition).  A simile ("like the foundation stones we uncovered", "steady as a belay") may hold counts and verbs of
    the thing it compares, but no word that begins like a cube, colour, structure, patch or label, no place or relation of
    its own and no thing known by its order, shape, pose or size (:data:`lexicon.VOICE_SIMILE_BLOCKER_RE`: "like a towering
    stack", "like a hat on a head", "like a traffic light" stay); any other chunk ("Site diary, day six", "..., where the
    hive entrance would be") has a word beyond fillers, no word that begins like a goal's word ("towered"), no count, no
    verb that changes a scene, no preposition that may place a cube or name a tool (:data:`lexicon.VOICE_PLACE_HAZARD_RE`),
    and no number but a label's name of a thing ("day six", :data:`lexicon.VOICE_NAME_NUMBER_RE`)."""
    if re.search(r"\b[A-HJ-Z]\b|\b[0-9]\b(?!\s*[a-z]{2})|_", chunk) and not (label and not re.search(r"\b[A-Z]\b|_", chunk)):
        return False  # "..., they go T, O, P": a label cube, not a voice ("day 6" names a day)
    said = low = chunk.lower().strip()
    if label:  # "Lads, quick one", "Snooker lesson one", "Two pots": the task itself, a name, a count of the voice's own things
        def name(m: re.Match) -> str:  # "lesson one", "scene two": a name; "just one", "pick one": a count kept
            word = m.group(0).split()[0]
            return word if "NOUN" in lexicon.parts_of_speech(word) and not lexicon.VOICE_CHUNK_HAZARD_RE.search(word) \
                and word not in lexicon.COUNTING_WORDS else m.group(0)
        def world(m: re.Match) -> str:  # "two pots": the voice's own things; "two copies", "three levels": kept
            noun = m.group(0).split()[-1]
            own = not lexicon.QUANTITY_NOUN_RE.fullmatch(noun) and noun not in VOCAB and noun.removesuffix("s") not in VOCAB
            return noun if own else m.group(0)
        low = lexicon.VOICE_LABEL_WORLD_COUNT_RE.sub(world, lexicon.VOICE_NAME_NUMBER_RE.sub(name, lexicon.VOICE_LABEL_TASK_ONE_RE.sub("task", low)))
    masked = low != said  # (a label so weighed may be one word, or fillers and the task: "Two pots", "Alright, last one")
    words = re.findall(r"[a-z][a-z'\-]*", low)
    if (len(words) < 2 and not masked) or re.search(r"[^\w\s'\-.,#\u2022]", low):
        return False  # "..., textbook!", "..., respectively", "Obj:", "cc @kowalski": a word alone, or a handle, is the other
        # readers' to weigh
    if lexicon.VOICE_CHUNK_HAZARD_RE.search(low) or lexicon.RETRACTION_RE.search(re.sub(r"^the\s+way\b", " ", low)):
        return False
    if any(k in lexicon.COMMENTARY_BLOCKING_KINDS or k == "condition" for k, _, _ in _inexpressible(low)):
        return False
    if lexicon.VOICE_SIMILE_OPENING_RE.match(low) and not label:
        return not lexicon.VOICE_SIMILE_BLOCKER_RE.search(low) or _restates_relations(low, rest)
    if lexicon.VOICE_PLACE_HAZARD_RE.search(low):
        return False  # "..., into the bin", "..., using the tongs": it may place a cube or name a tool
    if all(w in lexicon.IDLE_WORDS or w in lexicon.CHAT_WORDS or w in lexicon.INTERJECTIONS for w in words) and not masked:
        return False  # "..., please?": a filler the readers know (it may matter to how the rest is read)
    named = lexicon.VOICE_NAME_NUMBER_RE.sub(lambda m: m.group(0).split()[0], low) if label else low
    if re.search(r"\d", named) or lexicon.TASK_CONTENT_RE.search(named) or lexicon.GOAL_THING_PREFIX_RE.search(named):
        return False
    for w in words:
        for part in w.split("-"):
            base = part.removesuffix("'s")
            if base in COLORS or base in lexicon.colour_names() or base in lexicon.SCENE_CHANGING_VERBS or any(
                    x in lexicon.SCENE_CHANGING_VERBS for x in lexicon.lemmas(base)):
                return False
    return True


def _absolute_phrases(chunk: str) -> bool:
    """Whether a voice's label or first sentence is made of absolute phrases only ("Helmet on, arc struck", "Mask down,
    torch lit", "Flux is on, joint is prepped"): each a thing of the voice's world (a noun the parser does not read, none of
    :data:`lexicon.WORLD_SUBJECT_HAZARD_WORDS`) and its state, a word of :data:`lexicon.ABSOLUTE_STATE_WORDS` or a past
    participle of a verb that changes no scene (:data:`lexicon.SCENE_CHANGING_VERBS`).  Such a label sets the voice's
    scene and says nothing of the task (:func:`drop_voice_chunks`)."""
    low = chunk.lower().strip(" .")
    if lexicon.VOICE_CHUNK_HAZARD_RE.search(low) or lexicon.RETRACTION_RE.search(low) or any(
            k not in ("object", "action") for k, _, _ in _inexpressible(low)):
        return False  # "Upside down.", "Inverse version:": a pose or a turn of the task
    pieces = re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", low)
    for piece in pieces:
        tokens = piece.split()
        if tokens and tokens[0] in lexicon.WORLD_SUBJECT_DETERMINERS - lexicon.WORLD_SUBJECT_QUANTIFIERS:
            tokens = tokens[1:]  # "the flux is on"
        m = re.fullmatch(r"([a-z][a-z'\-]*)\s+(?:(?:is|are)\s+)?([a-z]+)", " ".join(tokens))
        if m is None:
            return False
        noun, state = m.groups()
        pos = lexicon.parts_of_speech(noun)
        if noun in VOCAB or noun in COLORS or noun in lexicon.colour_names() or noun in lexicon.WORLD_SUBJECT_HAZARD_WORDS \
                or (pos and not pos & {"NOUN", "PROPN"}):
            return False
        if state in lexicon.ABSOLUTE_STATE_WORDS:
            continue
        said = lexicon.parts_of_speech(state)
        participle = state not in VOCAB and (("VERB" in said and state not in lexicon.lemmas(state))  # "struck", "lit"
                                             or (not said and state.endswith("ed")))  # "prepped"
        if not participle or {state, *lexicon.lemmas(state)} & lexicon.SCENE_CHANGING_VERBS:
            return False
    return True


def _label_structure_masked(chunk: str, task: str) -> str:
    """A voice's label ``chunk`` with each structure noun that is the voice's own (:data:`lexicon.LABEL_STRUCTURE_KINDS`)
    written as "thing", for :func:`_voice_chunk` to weigh the rest: one its ``task`` names the same kind of ("Tungsten
    tower: stack a gray cube on a black cube"), or one that qualifies a noun of the voice's world that the parser does
    not read ("Grid reference: ...", "Tower captain speaking: ...") and that names no task ("Pyramid task: ..." names
    its structure).  Any other stays ("Contour lines: build a wall": the label's lines are no wall), and so does a plural
    ("Twin towers": how many).  A label with a count or a spec ("pile-5 [region=back]: ..."), or with another word the
    parser reads or one that may count, order, size or place (:data:`lexicon.LABEL_STRUCTURE_HAZARD_RE`: "Rainbow row",
    "Upper tower"), is left whole."""
    if re.search(rf"\d|\b(?:{lexicon.COUNT_WORD_RE})\b|[\[\]=]", chunk.lower()):
        return chunk  # "pile-5 [region=back]": a count or a spec of the task's own, to be read
    words = re.findall(r"[A-Za-z][A-Za-z'\-]*", chunk)
    if any((w.lower() in VOCAB and w.lower() not in lexicon.VOICE_LABEL_FILLER_WORDS) or lexicon.LABEL_STRUCTURE_HAZARD_RE.fullmatch(w.lower())
           for w in words if w.lower().removesuffix("s") not in lexicon.LABEL_STRUCTURE_KINDS and w.lower() != "table"):
        return chunk  # "Rainbow row", "Twin towers", "Bottom row", "Countdown row": a word that may order, count or place
    out = chunk
    if re.search(r"'s\b|s'(?!\w)", chunk) or lexicon.LABEL_MASK_HAZARD_RE.search(chunk.lower()) or any(
            lexicon.OPENING_ADJUNCT_PERSON_RE.fullmatch(w.lower()) for w in words
            if w.lower() not in VOCAB and w.lower().removesuffix("s") not in lexicon.LABEL_STRUCTURE_KINDS):
        return chunk  # "Opponent's table", "Guest table", "Duplicate table", "Line of others": someone's view, copies, others
    for i, w in enumerate(words):
        kind = lexicon.LABEL_STRUCTURE_KINDS.get(w.lower())
        if w.lower() == "table":  # "Tournament table: ...", "Pause table: ...": the voice's table (no side of it said)
            out = re.sub(r"\btable\b", "thing", out, count=1, flags=re.IGNORECASE)
            continue
        if kind is None:
            continue  # (a plural, "Twin towers", "Parallel rows", says how many: the label stays)
        after = words[i + 1].lower() if i + 1 < len(words) else ""
        idiom = after == "of" and i + 2 < len(words) and not words[i + 2].lower().endswith("s") and not re.fullmatch(
            rf"(?:{COLOR_RE}|cubes?|blocks?|bricks?|one|two|three|four|five|six|seven|eight|nine|ten)", words[i + 2].lower())
        # ("Line of sight check": no line of cubes; "Line of dozens", "Line of reds": how many, which)
        if idiom:
            out = re.sub(rf"\b{re.escape(w)}\b", "thing", out, count=1)
            continue
        qualifies = bool(after) and after.removesuffix("s") not in VOCAB and "NOUN" in lexicon.parts_of_speech(after) \
            and not lexicon.VOICE_CHUNK_HAZARD_RE.search(after) and not lexicon.FRAME_NOUN_RE.fullmatch(after)  # "Pyramid
        # task: bottom layer ...": the label names the task's structure
        said = lexicon.STRUCTURE_KIND_SAID_RES.get(kind)
        if qualifies or (said is not None and said.search(task.lower())):
            out = re.sub(rf"\b{re.escape(w)}\b", "thing", out, count=1)
    return out


def _label_names_structure(chunk: str, task: str) -> str | None:
    """The structure noun that ends a voice's label and names its task's structure ("Method ringers' pyramid: six white
    cubes, three on the bottom layer, ..."): a singular noun of :data:`lexicon.LABEL_STRUCTURE_KINDS` at the label's end,
    the words before it the voice's own (the label with the noun as "thing" inert by :func:`_voice_chunk`, none of
    :data:`lexicon.LABEL_STRUCTURE_HAZARD_RE`, no word the parser reads), and a task that names no structure itself (one
    that does names its own; :func:`_label_structure_masked`).  None otherwise."""
    words = re.findall(r"[A-Za-z][A-Za-z'\-]*", chunk)
    if len(words) < 2 or words[-1].lower() not in lexicon.LABEL_STRUCTURE_KINDS or re.search(STRUCTURE_RE, task.lower()):
        return None
    if re.search(rf"\d|\b(?:{lexicon.COUNT_WORD_RE})\b", chunk.lower()) or any(
            w.lower().rstrip("'") in VOCAB or lexicon.LABEL_STRUCTURE_HAZARD_RE.fullmatch(w.lower()) for w in words[:-1]):
        return None
    masked = re.sub(rf"\b{re.escape(words[-1])}\s*$", "thing", chunk.strip())
    return words[-1].lower() if _voice_chunk(masked, label=True) else None


def _naming_tail(chunk: str) -> bool:
    """Whether a chunk at a sentence's end only names, in a voice's words, what the sentence just did ("..., that's the
    pot", "..., which is my bullpen"): "that's" and one noun of the voice's own that :func:`_voice_chunk` finds inert (no
    goal, place, order, reference, count or colour: "..., that's the goal", "..., that's the red one" stay), and none that
    may call the goal unwanted, a trial, an axis or a part of more (:data:`lexicon.OPENING_ADJUNCT_HAZARD_RE`,
    :data:`lexicon.NAMING_TAIL_HAZARD_RE`: "..., that's the decoy", "..., that's the foundation")."""
    m = lexicon.NAMING_TAIL_RE.fullmatch(chunk.strip())
    return bool(m) and " " not in m.group("n").strip() and not lexicon.OPENING_ADJUNCT_HAZARD_RE.search(m.group("n")) \
        and not lexicon.NAMING_TAIL_HAZARD_RE.search(m.group("n")) and _voice_chunk(f"the {m.group('n')}")


def drop_voice_chunks(text: str, labels: bool = True) -> tuple[str, list[str]]:
    """``text`` without a voice's label before its task ("Site diary, day six: ...", :data:`lexicon.VOICE_LABEL_RE`; or a
    first sentence of up to four words such as "Context 17.") and without the chunks that end its sentences in a voice
    ("..., like a bee's stripes.", "..., steady as a belay.", "... - monochrome is so in right now.",
    (:data:`lexicon.VOICE_TAIL_RES`), each inert (:func:`_voice_chunk`), when what is left of the sentence still names a
    thing of a goal; and the chunks dropped.  A voice's words are its own: a chunk that names a cube, a structure, a
    place, a count or anything that may change the goal stays, to be read or refused.  Without ``labels`` only the
    sentences' closing chunks are weighed (a steering edit's label is its own readers', which may find a fresh start in
    it: "Different house, different job: ...")."""
    dropped: list[str] = []
    label = lexicon.VOICE_LABEL_RE.match(text) if labels else None
    first = re.match(r"\s*(?P<c>[^.!?:;]{2,40})\.\s+(?=\S)", text) if labels else None
    for m in (label, first):
        if m is None:
            continue
        chunk = _label_structure_masked(m.group("c"), text[m.end():]) if m is label else m.group("c")
        if (len(m.group("c").split()) <= (10 if m is label else 4) and _voice_chunk(chunk, label=True)
                or _absolute_phrases(m.group("c"))) and lexicon.GOAL_THING_RE.search(text[m.end():].lower()):
            dropped.append(m.group(0).strip())
            text = text[m.end():]
            break
        noun = _label_names_structure(m.group("c"), text[m.end():]) if m is label else None
        if noun and lexicon.GOAL_THING_RE.search(text[m.end():].lower()):  # "Method ringers' pyramid: six white cubes, ...":
            dropped.append(re.sub(rf"\s*{noun}\s*$", "", m.group("c"), flags=re.IGNORECASE).strip())  # the task's structure kept
            text = f"{noun}: {text[m.end():]}"
            break
    opening = lexicon.VOICE_OPENING_SIMILE_RE.match(text)
    simile = opening.group("c").lower() if opening else ""
    runs = re.search(r"\bfrom\b[^,]*\bto\b", simile) and not lexicon.DIRECTION_SAID_RE.search(text[opening.end():].lower())
    if opening and not runs and not lexicon.OPENING_SIMILE_PLACE_RE.search(simile) \
            and _voice_chunk(opening.group("c"), rest=text[opening.end():]) \
            and lexicon.GOAL_THING_RE.search(re.split(r"(?<=[.!?])\s+", text[opening.end():])[0].lower()):
        dropped.append(opening.group(0).strip())  # "Like laying shingles from the eaves to the ridge, build a tower: ..."
        text = text[opening.end():]
    sentences = []
    for sentence in re.split(r"(?<=[.!?])\s+", text):
        for _ in range(2):  # "..., like climbers on a rope, our high camp."
            tail = next((t for t in (p.search(sentence) for p in lexicon.VOICE_TAIL_RES)
                         if t and (_voice_chunk(t.group("c"), rest=sentence[:t.start()]) or _naming_tail(t.group("c")))), None)
            if not tail or not lexicon.GOAL_THING_RE.search(sentence[:tail.start()].lower()):
                break
            dropped.append(tail.group("c").strip())
            sentence = sentence[:tail.start()] + (tail.group("end") or "")
        sentences.append(sentence)
    return " ".join(sentences), dropped


def _opening_adjunct(prep: str | None, np: str) -> bool:
    """Whether an opening adjunct (:data:`lexicon.OPENING_ADJUNCT_RE`: ``prep`` and its noun phrase ``np``, or a noun
    "aside" where ``prep`` is None) is a voice's occasion that says nothing of the task: one to four words, no digit or
    count, no colour, nothing of a goal (:data:`lexicon.TASK_CONTENT_RE`, :data:`lexicon.GOAL_THING_PREFIX_RE`), no word
    of :data:`lexicon.OPENING_ADJUNCT_HAZARD_RE` (a reference, quantifier, negation, condition, time, order, side, person or
    viewpoint, picture, start state, unwanted or turned state, copies) nor a noun that may name a person
    (:data:`lexicon.OPENING_ADJUNCT_PERSON_RE`), no word the domain refuses but an object or an action of that world.
    "Per" needs a determiner ("Per the manual"; "per guest" is one task for each); "in" a demonstrative or possessive one
    before a frame's noun alone ("In this trial"; "In the bowl" places a cube)."""
    low = np.lower().strip()
    words = low.split()
    prep = (prep or "").lower()
    if not words or len(words) > 4 or re.search(rf"\d|\b(?:{lexicon.COUNT_WORD_RE})\b", low):
        return False
    if lexicon.TASK_CONTENT_RE.search(low) or lexicon.GOAL_THING_PREFIX_RE.search(low) or lexicon.OPENING_ADJUNCT_HAZARD_RE.search(low) \
            or lexicon.FRAMING_SENTENCE_HAZARD_RE.search(low):
        return False
    determined = words[0] in lexicon.OPENING_ADJUNCT_DETERMINERS
    nouns = words[1:] if determined else words
    if not nouns or lexicon.RETRACTION_RE.search(" ".join(nouns)) or any(
            w in COLORS or w in lexicon.colour_names() or w in VOCAB or len(w) == 1 or lexicon.OPENING_ADJUNCT_PERSON_RE.fullmatch(w)
            for w in nouns):
        return False
    if prep == "per" and not determined:
        return False  # "Per guest, ...": a task for each
    if prep == "in" and not (words[0] in ("this", "that", "my", "our") and len(nouns) == 1
                             and lexicon.FRAME_NOUN_RE.fullmatch(nouns[0])):
        return False  # "In the bowl", "In this drawer": a place; "In this reflected setup": a turn of the task
    if any(k not in ("object", "action") for k, _, _ in _inexpressible(low)):
        return False
    return all(senses.sense(w).kind not in _KIND_WHY or senses.sense(w).kind in ("object", "action") for w in nouns)


def _said_to_someone_else(before: str) -> bool:
    """Whether the words ``before`` a turn to the robot (:data:`lexicon.ROBOT_TURN_RE`) are of the speaker's own world
    ("Take one capsule twice daily with food.", "Nurse, keep the field sterile."): four words or more with a thing of that
    world (a word the parser does not read), nothing of a goal or a colour, no take-back, nothing that may turn, count,
    order, place or time the task (:data:`lexicon.ROBOT_TURN_HAZARD_RE`, :data:`lexicon.FRAMING_SENTENCE_HAZARD_RE`) once
    the counts and times of that world's own things are set apart (:data:`lexicon.WORLD_COUNT_RE`: "one capsule", "500
    milligrams", "twice daily"), and no "keep" or "leave" but one said to a person called by name ("Nurse, keep ...")."""
    low = before.lower()
    words = re.findall(r"[a-z][a-z'\-]*", low)
    if len(words) < 4 or lexicon.GOAL_THING_RE.search(low) or lexicon.RETRACTION_RE.search(low) \
            or lexicon.ROBOT_TURN_HAZARD_RE.search(low) or lexicon.QUOTED_TASK_RE.search(before) \
            or lexicon.colour_names() & set(words) or not any(
                w not in VOCAB and (not lexicon.is_dictionary_word(w) or "NOUN" in lexicon.parts_of_speech(w)) for w in words):
        return False
    weighed = lexicon.WORLD_COUNT_RE.sub(" ", low)
    if re.match(r"\s*[a-z]+\s*,", weighed) and re.match(r"\s*[A-Z][a-z]+\s*,", before):  # "Nurse, keep the field sterile."
        weighed = re.sub(r"\b(?:keep|keeps|leave|leaves)\b", " ", weighed)
    return not lexicon.FRAMING_SENTENCE_HAZARD_RE.search(weighed)


def drop_asides(text: str) -> tuple[str, list[str]]:
    """``text`` without its asides, and the asides dropped: exclaimed sentences (:data:`lexicon.EXCLAIMED_SENTENCE_RE`:
    "Put the green block on the purple block. What a tower!") that name nothing of a goal
    (:data:`lexicon.ASIDE_CONTENT_RE`) and nothing the domain cannot express ("Quickly!" stays, to be refused), and
    other sentences that are framing (:func:`_framing_sentence`: "Code is linked in the description."), when a sentence
    of the task is left; the text as it is when nothing else is left.  A task quoted in a report of it
    (:data:`lexicon.QUOTED_TASK_RE`) is the quote alone when the report says nothing of cubes or places.  A sentence's
    opening adjunct of a voice's occasion ("For the keyframes I need ...", "Etymology aside, ...") is dropped where
    :func:`_opening_adjunct` finds it inert."""
    quoted = list(lexicon.QUOTED_TASK_RE.finditer(text))
    if len(quoted) == 1:  # 'give the task "put the cyan cube behind the red cube"': the quote, its report dropped
        rest = text[:quoted[0].start("q")] + text[quoted[0].end("q"):]
        segments = [g for g in re.split(r"(?<=[.!?;])\s+|\s+(?=\d+[.)]\s)|[\"\u201c\u201d]", rest) if g.strip()]
        reported = all(lexicon.QUOTED_TASK_REPORT_RE.match(g.lower()) or _evaluation_report(g) for g in segments)
        if reported and lexicon.GOAL_THING_RE.search(quoted[0].group("q").lower()):
            return quoted[0].group("q").strip(), [rest.strip()]
    dropped: list[str] = []
    turn = lexicon.ROBOT_TURN_RE.search(text)
    if turn and lexicon.GOAL_THING_RE.search(text[turn.end():].lower()) and _said_to_someone_else(text[:turn.start()]):
        dropped.append(text[:turn.end()].strip())  # "Nurse, keep the field sterile. Robot, place ...": said to someone else
        text = text[turn.end():]
    pieces = re.split(r"((?<=[.!?])\s+)", text)  # sentences and the spaces between them, kept as they are
    addressed = "".join(piece if i % 2 else _without_address(piece) for i, piece in enumerate(pieces))
    if addressed != text and lexicon.GOAL_THING_RE.search(addressed.lower()):
        # "Arr matey, put ..., savvy?": the call to a listener (kept where no task is left: "Thanks, that's all for today.")
        dropped.append(text)
        text = addressed
    def conceded(m: re.Match) -> str:  # "It may take a while, but put ...": the task's effort, no constraint of its goal
        dropped.append(m.group(0).strip())
        return ""
    text = lexicon.CONCESSION_OPENING_RE.sub(conceded, text)
    def world_time(m: re.Match) -> str:  # "While the glaze sets, put ...": the speaker's time, which no goal holds
        said = m.group("c").lower()
        if lexicon.GOAL_THING_RE.search(said) or lexicon.TASK_CONTENT_RE.search(said) or lexicon.WORLD_TIME_HAZARD_RE.search(said) \
                or any(c in said for c in lexicon.colour_names()) or _inexpressible(said):
            return m.group(0)
        dropped.append(m.group(0).strip())
        return ""
    timed = lexicon.WORLD_TIME_CLAUSE_RE.sub(world_time, text)
    if timed != text and lexicon.GOAL_THING_RE.search(timed.lower()):
        text = timed
    for _ in range(2):  # "In this experiment, the robot was instructed to place ...": two frames, one after the other
        frame = lexicon.FRAME_PREFIX_RE.match(text)
        if frame is None or not _frame_prefix(frame.group("p")):
            break
        dropped.append(frame.group(0).strip())
        text = text[frame.end():]

    n_before = len(dropped)

    def adjunct(m: re.Match) -> str:  # "For the keyframes I need ...", "Etymology aside, put ...": the voice's occasion
        if not _opening_adjunct(m.group("prep"), m.group("np") or m.group("np2")):
            return m.group(0)
        dropped.append(m.group("a").strip())
        return ""
    adjoined = lexicon.OPENING_ADJUNCT_RE.sub(adjunct, text)
    if adjoined != text and lexicon.GOAL_THING_RE.search(adjoined.lower()):
        text = adjoined
    else:
        del dropped[n_before:]

    def aside(m: re.Match) -> str:
        said = m.group(0)
        if (lexicon.ASIDE_CONTENT_RE.search(said) or _inexpressible(said.lower())) and not _commentary_sentence(said.strip()):
            return said
        dropped.append(said.strip())
        return ""
    kept = re.sub(r"\s{2,}", " ", lexicon.EXCLAIMED_SENTENCE_RE.sub(aside, text)).strip()
    if not re.search(r"[a-z]", kept, re.I):
        return text, []
    def report(m: re.Match) -> str:
        if not _evaluation_report(m.group(1)):
            return m.group(0)
        dropped.append(m.group(0).strip())
        return ""
    reported = re.sub(r"\s{2,}", " ", re.sub(r"\s*\(([^()]{3,200})\)", report, kept)).strip()
    kept = reported if re.search(r"[a-z]", reported, re.I) else kept
    sentences = re.split(r"(?<=[.!?])\s+", kept)
    framing = [s for i, s in enumerate(sentences) if not s.endswith("!") and (
        _framing_sentence(s) or _evaluation_report(s) or _title_heading(s, " ".join(sentences[i + 1:])))]
    task = [s for s in sentences if s not in framing and not _commentary_sentence(s) and not _voice_sentence(s)
            and not _world_statement(s)]
    if task and any(lexicon.GOAL_THING_RE.search(s.lower()) for s in task):  # a voice's commentary around a task said
        framing = [s for s in sentences if s not in task]
    if framing and len(framing) < len(sentences):
        kept = " ".join(s for s in sentences if s not in framing)
        dropped += framing
    def world_clause(m: re.Match) -> str:  # "Sewing can wait; put ...": a statement of the voice's world before the task
        if not _world_statement(m.group("c")) or not lexicon.GOAL_THING_RE.search(m.string[m.end():].lower()):
            return m.group(0)
        dropped.append(m.group(0).strip())
        return ""
    kept = re.sub(r"(?:^|(?<=[.!?]\s))\s*(?P<c>[^.!?;:]{3,80});\s+", world_clause, kept)
    kept, voiced = drop_voice_chunks(kept)
    return kept, dropped + voiced


_LISTED_CUBE = rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:\s+first)?"
_LISTED_AFTER_RE = re.compile(rf"[^.;:!?]*:\s*{_LISTED_CUBE}(?:\s*,\s*(?:and\s+)?(?:then\s+)?{_LISTED_CUBE}|\s+(?:and|then)\s+{_LISTED_CUBE})+"
                              r"(?:\s+(?:at|on)\s+the\s+(?:far\s+)?(?:left|right|front|back)(?:\s+end)?)?\s*(?:[.!]|$)")
"""What follows a pronoun for cubes when it stands for the cubes a colon then lists ("line them up from the right: the black
cube first, then the pink cube, then the cyan cube"): a list of cubes and nothing else (a relation after it, "..., and put
the blue cube next to them", leaves "them" unresolved)."""


def _refuse_unresolved_pronoun(text: str, original: str) -> None:
    """Raise :class:`Inexpressible` (``reference``) when a pronoun standing for cubes ("stack
    them", "unstack that.") has nothing named before it to refer to
    (:data:`lexicon.REFERENCE_PRONOUN_RE`, :data:`lexicon.ANTECEDENT_RE`), or "the other block"
    has no cube set apart before it (:data:`lexicon.OTHER_RE`)."""
    for m in lexicon.REFERENCE_PRONOUN_RE.finditer(text):
        before = text[:m.start()]
        listed_after = _LISTED_AFTER_RE.match(text[m.end():])  # "line them up from the right: the black cube first, then ...":
        if m.group(0) in ("them", "they") and listed_after:  # the cubes the colon lists, a list and nothing else
            continue
        plural = m.group(0) in ("them", "they") and not re.search(r"\b(?:cubes|blocks|bricks|ones|tower|stack|pile|row|line|digits|letters|numbers|labels|both|all)\b", before)
        if not lexicon.ANTECEDENT_RE.search(before) or (  # "put the yellow block on them": one cube named, "them" no others
                plural and len(re.findall(rf"\b(?:{COLOR_RE})\b(?!\s+(?:goal\s+)?patch)|\b[a-z]\s+(?:block|cube)\b|\b\d\s+(?:block|cube)\b",
                                          before)) < 2):
            word = m.group(0)
            raise Inexpressible("reference", [word], "refers to something the instruction has not named (a cube the "
                                "speaker sees, or one from an earlier turn): rpg's cubes are known only by colour "
                                "and label; name them (e.g. \"stack the red and blue blocks\")", original)
    for m in lexicon.DEFINITE_STRUCTURE_RE.finditer(text):
        # "stack the red cube on top of the tower": the verb that places a cube on the structure describes no structure
        before = re.sub(r"\b(?:stack|put|place|set|move|pile)\s+(?:the\s+|a\s+|an\s+)?(?:[a-z]+\s+){0,2}?(?:block|cube)s?\s+"
                        r"(?:on|onto|on\s+top|at\s+the\s+top|next\s+to|beside|behind|near|in\s+front)?\s*$", "", text[:m.start()])
        if not lexicon.STRUCTURE_INTRO_RE.search(before):
            raise Inexpressible("reference", [m.group(0)], f"refers to a {m.group('noun')} the instruction has not "
                                "described (one the speaker sees, or from an earlier turn): describe it (e.g. \"build a "
                                "tower of the red and green blocks, then put the blue block on top of it\")", original)
    demonstrative = lexicon.DEMONSTRATIVE_CUBE_RE.search(text)
    if demonstrative and re.search(rf"\b(?:a|an|one)\s+(?:{COLOR_RE})\s+(?:cube|block|one)\s+on\s+top\b[^.;!?]*$", text[:demonstrative.start()]):
        demonstrative = None  # "add a pink one on top, and a brown one on top of that one": the cube just put on top
    if demonstrative:  # "put green on top of that cube": a cube nobody named by colour or label (a red one had been made up)
        raise Inexpressible("reference", [demonstrative.group("w")], "refers to a cube the instruction names by neither colour "
                            "nor label (one the speaker sees, or one said before without saying which): name it (e.g. \"put "
                            "the green block on top of the blue block\")", original)
    for m in lexicon.PLACE_PICKED_RE.finditer(text):
        before = re.sub(r"\b(?:stack|pile|line|row)\s*$", "", text[:m.start()])  # "stack the top block": a verb
        # "stack the cube closest the robot on ...": nearest to something named after it is where a cube stands now, in
        # any structure (the verb "stack" had passed for a structure described, and "closest" had then become "close")
        measured = re.search(r"\b(?:closest|nearest|farthest|furthest)$", m.group(0)) and re.match(
            r"\s+(?:to\s+|from\s+)?(?:the|a|an|your|my|our|you|me|us|him|her|them|it)\b", text[m.end():])
        if measured or not lexicon.PLACED_PART_INTRO_RE.search(before):
            raise Inexpressible("reference", [m.group(0)], "picks a cube by its place in the current scene, which the "
                                "instruction has not described (where the speaker sees it): name the cube by colour or label, or describe "
                                "the structure it stands in first (e.g. \"build a tower of three blocks and make the "
                                "top block red\")", original)
    order = lexicon.THIS_ORDER_RE.search(text)
    unordered = re.search(r"\b(?:circle|ring|grid|piles?|group|cluster|square)s?\b", text) if order else None
    if unordered:  # "put red, green, blue in a circle in that order": the order had been dropped
        raise ParseError(f"'{order.group(0)}' in \"{original[:80]}\" orders the cubes of a {unordered.group(0)}, which the "
                         "builtin parser reads with no order of its cubes; say the places another way (e.g. a row from left "
                         "to right), or use --model")
    listed = len(color_mentions(text)) + len(re.findall(r"\b(?:letter|digit)\s+\w\b|'\w'|\b\d\b", text)) + sum(
        len(re.findall(r"[A-Z]", m.group(1))) for m in re.finditer(  # "the letters Q, R and S ..., in that order"
            r"\b(?:letters|letter\s+(?:cubes|blocks)|(?:cubes|blocks)\s+(?:labell?ed|marked|lettered|showing)(?=[^.;!?]*\bin\s+that\s+order"
            r"\s*(?:[.;!?]|$)))\s+([A-Z](?:\s*,\s*(?:and\s+)?[A-Z]|\s+and\s+[A-Z])+)\b", original))  # "the cubes labelled M, N
    # and E in that order." (where more follows the order, "... in that order next to the red cube", the red cube had been
    # stacked in E's place)
    if order and listed < 2 and not re.search(r"\b[A-Z]{2,}\b|['\"][A-Za-z0-9]{2,}['\"]", original):  # "spell ABC in that order"
        raise Inexpressible("reference", [order.group(0)], "refers to an order the instruction does not list (one the "
                            "speaker shows): list it (e.g. \"stack the red, green and blue blocks in that order\")", original)
    for m in lexicon.DEICTIC_RE.finditer(text):
        if m.group("d") in ("this", "these") or not lexicon.ANTECEDENT_RE.search(text[:m.start()]):
            raise Inexpressible("reference", [m.group(0)], "refers to cubes in the current scene, which the instruction does "
                                "not describe (ones the speaker sees): rpg's cubes are known only by colour and label; name them "
                                "(e.g. \"put the red block on the blue block\")", original)
    for m in lexicon.OTHER_RE.finditer(text):
        if not lexicon.OTHER_SET_RE.search(text[:m.start()]):
            raise Inexpressible("reference", [m.group(0)], "picks a cube by contrast with one the instruction has not "
                                "set apart (a cube the speaker sees, or one from an earlier turn): name it by colour "
                                "or label (e.g. \"put the red block on the green patch\")", original)
    for m in lexicon.OTHER_PLACE_RE.finditer(text):
        if not re.search(rf"\b{m.group('noun')}", text[:m.start()]):
            raise Inexpressible("reference", [m.group(0)], "picks a place by contrast with one the instruction has not "
                                "named (where a cube stands now, which a task cannot see): name the place (e.g. \"the "
                                "green patch\", \"the left side of the table\")", original)


_RECOLOUR_BEFORE = re.compile(r"\b(?:make|paint|colou?r|turn|change|recolou?r|dye)\b(?:\s+\S+){0,4}?\s+(?:to\s+|into\s+)?$")
"""Words before a colour name the palette lacks that make it a colour ("make it beige", "paint the
top one mauve")."""


def _caused_motion(m: re.Match, dropped: list[tuple[str, str]]) -> str:
    """The verb of a caused-motion clause (:data:`lexicon.CAUSED_MOTION_RE`) as "put" when :func:`moving_verb` holds,
    recorded in ``dropped`` (for the accounting).  The clause as it is otherwise."""
    if not moving_verb(m.group("v")):
        return m.group(0)
    dropped.append((m.group("v"), "a verb of moving a cube to a place, read as 'put'"))
    return f"{m.group('pre')}put "


def moving_verb(verb: str) -> bool:
    """Whether ``verb`` of a caused-motion clause (:data:`lexicon.CAUSED_MOTION_RE`) moves the cube, as "put" would: the
    lexicon lacks it, the dictionary knows it as a verb that moves a thing (:func:`senses.moves_a_thing`), and it is no
    action the domain refuses nor a verb the readers read as itself ("melt the red cube on the patch", "hurl it onto ...":
    more than where it ends)."""
    verb = verb.lower()
    lemmas = {verb, *lexicon.lemmas(verb)}
    return not (verb in VOCAB or verb in lexicon.IDLE_WORDS or "VERB" not in lexicon.parts_of_speech(verb)
                or lemmas & set(lexicon.UNKNOWN_KIND_EXEMPLARS["action"]) or lemmas & lexicon.SCENE_CHANGING_VERBS
                or lexicon.RETRACTION_RE.search(verb) or lexicon.VOICE_CHUNK_HAZARD_RE.search(verb) or _inexpressible(verb)
                or not senses.moves_a_thing(verb))


def _unknown_word_classes(text: str, unknown: list[str]) -> list[tuple[str, str, str]]:
    """(word, class, why) for each unknown word that stands where an object does (a noun
    heading a phrase after a determiner: "insert the peg") and, failing that for a word, where a
    command's verb does ("throw the red block"); words that read as neither are left out."""
    def where(word: str):
        for m in re.finditer(rf"(?<![\w-]){re.escape(word)}(?![\w-])", text):
            yield text[:m.start()], text[m.end():]

    found = []
    for word in unknown:
        if word in lexicon.colour_names() and any(lexicon.COLOUR_NOUN_AFTER.match(after) or lexicon.COLOUR_ROLE_AFTER.match(after) or (
                _RECOLOUR_BEFORE.search(before) and re.match(r"\s*(?:[.,;!?]|$|instead\b|please\b|too\b|then\b)", after))
                or lexicon.PALETTE_LIST_NEAR.search(before) or lexicon.PALETTE_LIST_AFTER.match(after)
                for before, after in where(word)):  # "beige block", "make it beige", "maroon at the bottom", "red, beige"
            found.append((word, *lexicon.UNKNOWN_COLOUR))
            continue
        pos = lexicon.parts_of_speech(word)
        lemma = (lexicon.lemmas(word) or (word,))[0]
        if not (pos and pos <= {"ADJ", "ADV"}) and word != "file" and any(
                _SHAPE_AFTER.match(after) or _SHAPE_BEFORE.search(before) for before, after in where(word)):
            found.append((word, "shape", lexicon.SHAPE_WHY))  # "in an arrow shape", "in the shape of a boat"
        elif "NOUN" in pos and word not in lexicon.NOT_OBJECTS and lemma not in lexicon.NOT_OBJECTS and any(
                _heads_a_phrase(before, after) for before, after in where(word)):
            found.append((word, *lexicon.UNKNOWN_OBJECT))
        elif "VERB" in pos and any(_CLAUSE_START_BEFORE.search(b) for b, _ in where(word)):
            found.append((word, *lexicon.UNKNOWN_ACTION))
    return found


_SHAPE_AFTER = re.compile(r"[\s-]+(?:shape|shaped|formation|outline|silhouette)\b")
_SHAPE_BEFORE = re.compile(r"\b(?:shape|form|outline|silhouette)\s+of\s+(?:an?\s+|the\s+)?$")
"""The words around a word that names a shape the structures lack ("in an arrow shape", "an arrow-shaped layout", "in
the shape of a boat"): refused as a shape, not an object or an unknown word."""
_MODIFIES_AFTER = re.compile(rf"\s+(?:(?:{COLOR_RE}|[a-z\-]+)\s+)?{lexicon.THING_NOUN}\b")
"""What follows a word that describes a cube, a patch or a structure ("hollow square", "the shiny one")."""
_PLACE_BEFORE = re.compile(r"\b(?:in|into|on|onto|at|to|towards?|from|over|under|inside|near|beside|behind|above|below|across|along"
                           r"|up|off)\s+(?:(?:the|a|an|my|your|our|their|its|this|that)\s+)?$")
"""What precedes a word that names a place ("in the air", "onto the shelf", "in case")."""
_PLACED_BEFORE = re.compile(rf"\b(?:{'|'.join(sorted(lexicon.PLACEMENT_VERBS))}|stack)\s+(?:the\s+|a\s+|an\s+)?$")
"""What precedes a word that names what is placed ("put teddy on ...")."""
_LIST_SEPARATOR = r"(?:,|;|/|->|\u2192|=>|>|\+|&|\band\b|\bthen\b)"
_LIST_ITEM_AFTER = re.compile(rf"\s*{_LIST_SEPARATOR}\s*(?:the\s+)?(?:{COLOR_RE})\b")
_LIST_ITEM_BEFORE = re.compile(rf"\b(?:{COLOR_RE})\s*{_LIST_SEPARATOR}\s*$")
"""The separators around a word that stands as an item of a list of colours ("zork -> white -> gray tower",
"red, foo, blue"): an unknown word there is a cube said in words the parser does not know (it had been dropped)."""
_VERB_TAKES_AFTER = re.compile(r"\s+(?:up|down|over|out|off|away|back|around|apart|together|along|\d+"
                               r"|(?:(?:by|on|onto|in|into|to|from|with|under|over|against|between|near|beside|behind|atop)\s+)?"
                               r"(?:(?:the|a|an|this|that|these|those|all|both|each|every|\d+)\s+)?(?:[a-z\-]+\s+){0,2}?"
                               rf"{lexicon.THING_NOUN})\b")
"""What follows a word used as a verb on the cubes: a particle ("zorp down"), or a cube or structure,
maybe after a preposition ("yeet the red cube", "supported by green block")."""


def ignorable_unknown(word: str, text: str) -> bool:
    """Whether an unknown word that no class claimed (not an inflection, a typo, an ignorable sense,
    a colour, an object or an action: :func:`_unknown_word_classes`) is ignored, as issue 30's
    item 3 asks ("other words are ignored and listed in accounting"), rather than refused.

    It is kept unknown (the instruction is refused naming it) when it may change what the task
    asks: a colour name; a word of :data:`lexicon.UNKNOWN_CARRIES_MEANING` (time, condition,
    question, alternative, shape), alone or in a hyphenated word; labels spelled one by one
    ("b-a-d"); a word in a sentence that names
    nothing of the task ("Vice versa.": :func:`_idle_sentence` decides); any word of the dictionary
    (lemminflect knows it: a verb, adjective or adverb may say what to do or how, and a noun an
    object or a reference; ignoring those had compiled held-out texts silently wrong); a word
    describing a cube, patch or structure ("zorp square"); a place ("in the zorp"); what is placed
    ("put teddy on ..."); a word used as a verb on the cubes ("yeet the red cube", "supported by
    the red block"); a word before a particle; an item of a list of colours ("zork, white, gray"); the ending of a
    number ("nd" of "2nd")."""
    parts = {word, word.removesuffix("s"), *word.split("-")}  # "reds": the red cubes; "time-limited"
    if parts & lexicon.UNKNOWN_CARRIES_MEANING or parts & lexicon.colour_names():
        return False
    if re.fullmatch(r"[a-z0-9](?:-[a-z0-9])+", word):
        return False  # "b-a-d", "1-2-3": labels spelled out one by one
    pos = lexicon.parts_of_speech(word)
    if pos:
        return False  # a word of the dictionary: a verb, adjective or adverb may say what to do or how, a noun may name
        # an object or a reference the domain lacks; only names, ids and jargon ("alexa", "wp2", "sanity-check") are ignored
    found = list(re.finditer(rf"(?<![\w-]){re.escape(word)}(?![\w-])", text))
    if not found and re.search(rf"\d{re.escape(word)}\b", text):
        return False  # the ending of a number ("nd" of "2nd"): a position
    for m in found:
        before, after = text[:m.start()], text[m.end():]
        sentence = re.split(r"[.!?;]\s", before)[-1] + re.split(r"[.!?;](?:\s|$)", after)[0]
        if not lexicon.TASK_CONTENT_RE.search(sentence):
            return False  # a sentence of its own ("Vice versa.", "Diagonal please."): the idle-sentence rule decides
        if _MODIFIES_AFTER.match(after) or _PLACE_BEFORE.search(before) or _PLACED_BEFORE.search(before):
            return False
        if _LIST_ITEM_AFTER.match(after) or _LIST_ITEM_BEFORE.search(before):
            return False  # an item of a list of colours ("zork -> white -> gray tower"): a cube, unread
        if _VERB_TAKES_AFTER.match(after):
            return False  # a word used as a verb on the cubes ("yeet the red cube"), or before a particle ("zorp down")
    return True


def _heads_a_phrase(before: str, after: str) -> bool:
    """Whether a word with this text ``before`` and ``after`` it heads a noun phrase: a
    determiner, at most two modifiers (adjectives, colours, hyphenated words), the word, then
    the phrase's end (punctuation, a preposition, a conjunction, a number)."""
    m = _DETERMINER_BEFORE.search(before)
    if m is None or not _PHRASE_END_AFTER.match(after):
        return False
    modifiers = m.group("mods").split()
    return all("-" in w or w in lexicon.COLORS or lexicon.parts_of_speech(w) <= {"ADJ", "ADV"} and lexicon.parts_of_speech(w)
               for w in modifiers)


_DETERMINER_BEFORE = re.compile(r"\b(?:a|an|the|this|that|these|those|its|their|each|every|some|any|your|my|our)\s+"
                                r"(?P<mods>(?:[a-z\-]+\s+){0,2})$")
_PHRASE_END_AFTER = re.compile(r"\s*(?:$|[.,;:!?)(/]|(?:and|or|but|into|onto|on|in|to|with|from|off|at|of|that|which"
                               r"|so|then|down|up|over|under|by|for|near|next|inside|\d+)\b)")
_CLAUSE_START_BEFORE = re.compile(r"(?:^|[.,;:!?]\s*|\b(?:and|then|please|to|must|should)\s+"
                                  r"|\b(?:can|could|would|will)\s+you\s+)$")


_KIND_WHY: dict[str, str] = {**{kind: why for kind, _, why in reversed(lexicon.INEXPRESSIBLE)},
                             "object": lexicon.UNKNOWN_OBJECT[1], "action": lexicon.UNKNOWN_ACTION[1], "shape": lexicon.SHAPE_WHY}
"""Why each class of meaning the domain lacks is refused (the first :data:`lexicon.INEXPRESSIBLE`
entry of a class speaks for it)."""


_CHAIN_REL = r"(?:over|on|onto|upon|atop|above|under|below|beneath|underneath)"
_CHAIN_RUN_ON_RE = re.compile(rf"\b(?P<rel>{_CHAIN_REL})\s+(?:the\s+)?(?P<pair>(?P<a>{COLOR_RE})\s+(?P<b>{COLOR_RE}))"
                              rf"(?:\s+(?:block|cube))?\s+{_CHAIN_REL}\b")
"""Two colours with nothing between them inside a chain of cubes ("yellow over blue purple over
red"): a dropped relation word or a dropped "and"; refused rather than guessed."""


def normalize(instruction: str, strict: bool = True) -> tuple[str, str]:
    """Lower-case, number words to digits, typos corrected.  Returns (text, original).
    See :func:`normalize_words` (which also says the words it dropped)."""
    text, original, _ = normalize_words(instruction, strict)
    return text, original


_COUNTED = rf"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:{COLOR_RE})"
_COUNTED_LIST_RE = re.compile(rf"\b{_COUNTED}(?:\s*(?:,\s*and|,|and|\+|&|plus)\s+{_COUNTED})+\b(?P<noun>\s+(?:blocks?|cubes?|boxes|box))?")


def _counted_list_nouns(text: str) -> str:
    """A list of counted colours with one noun, or none, gets one per item: "2 blue and 2 green
    cubes", "2 red + 2 blue" -> "2 blue cubes and 2 green cubes", "2 red blocks and 2 blue
    blocks" (each count then reaches its own colour)."""
    def each(m: re.Match) -> str:
        noun = (m.group("noun") or " blocks").strip()
        items = re.findall(_COUNTED, m.group(0))
        singular = noun.rstrip("s") if noun != "boxes" else "box"
        parts = [f"{it} {singular if it.split()[0] in ('1', 'one') else noun}" for it in items]
        return ", ".join(parts[:-1]) + " and " + parts[-1]
    return _COUNTED_LIST_RE.sub(each, text)


def _labels_each_a_cube(m: re.Match) -> str:
    """A match of :data:`lexicon.LABELS_AND_NOUN_RE` said with the labels' kind: two cubes one at a time ("the 1 & 9
    cubes" -> "the 1 cube and the 9 cube"), more as the kind's list ("the A, B and C cubes" -> "the letter cubes A, B and
    C", which the list readers read; each said as a cube, a tower's roles had been read against its first cubes alone)."""
    labels = re.findall(r"[A-Z0-9]", m.group("labels"))
    if len(labels) > 2 and (all(x.isalpha() for x in labels) or all(x.isdigit() for x in labels)):
        kind = "letter" if labels[0].isalpha() else "digit"
        return f"{m.group('the')} {kind} {m.group('noun')}s {', '.join(labels[:-1])} and {labels[-1]}"
    cubes = [f"the {label} {m.group('noun')}" for label in labels]
    cubes[0] = m.group("the") + cubes[0][3:]
    return ", ".join(cubes[:-1]) + " and " + cubes[-1]


def _placed_labels_one_by_one(m: re.Match) -> str:
    """A match of :data:`lexicon.LABEL_LIST_PLACED_RE` said one cube at a time ("the letter A block and the letter B
    block"); digits said as "number" are digit cubes."""
    labels = re.findall(r"[A-Z0-9]", m.group("labels"))
    kind = "letter" if all(x.isalpha() for x in labels) else "digit" if all(x.isdigit() for x in labels) else None
    if kind is None or (kind == "letter") != (m.group("kind") == "letter"):
        return m.group(0)  # (letters and digits mixed, or said as the other kind: left to the readers, which refuse)
    cubes = [f"the {kind} {x} block" for x in labels]
    cubes[0] = m.group("the") + cubes[0][3:]
    return ", ".join(cubes[:-1]) + " and " + cubes[-1]


BARE_LABEL_RE = re.compile(r"(\b[Tt]he|(?:\bwith|\bthen|\band|,|(?<=[a-z] )that|:)(?=\s+[A-Z]\b))\s+([A-Z]|\d)\b(?![-'])"
                           r"(?!\s+(?:on\s+top\s+of\s+|next\s+to\s+|beside\s+)?(?:each\s+other|one\s+another|together)\b)(?=\s*(?:[,.;:!?()]|$|\s+(?:on|onto|atop|next|to|left|right|in|at|"
                           r"behind|beside|near|under|underneath|below|above|and|then|between|far|is|goes|should|must|from|into|onto|as|with)\b))")
"""A label cube named by its label alone after "the" (a letter after "with", "then", "and", a comma, or "that" or a colon
where the text names label cubes: "so that A is at the bottom, B ..."), before a
relation word or punctuation ("stack the A on the B", "the 1 on the 2", "with A at the bottom,
then B"): read as "the A block" (a letter or digit cube), never as a count or an article."""


CONFIG_KEYS = {"task": "{}", "goal": "{}", "objective": "{}", "type": "{}", "structure": "{}", "shape": "{}",
               "height": "{} high", "count": "{} cubes", "n": "{} cubes", "num": "{} cubes", "num_cubes": "{} cubes",
               "color": "{}", "colour": "{}", "colors": "{}", "colours": "{}", "objects": "{}", "cubes": "{}",
               "instruction": "{}", "goal_text": "{}", "prompt": "{}", "text": "{}", "language_instruction": "{}",
               "seed": ""}
"""Keys of a task written as a config ({"task": "tower", "height": 3, "color": "cyan"}) -> how
their value reads in a sentence ("tower, 3 high, cyan"; an instruction's text as it is; a seed,
which draws rho_0 and says nothing of the goal, dropped); a key not listed stays as it is (and
an unknown one is refused as a word the parser does not know)."""


def config_fragment(text: str) -> str:
    """A task written as a JSON or Python dict (``{'task': 'tower', 'height': 3}``, lower-cased
    and quoted with ``'``) read as a phrase of its values (:data:`CONFIG_KEYS`); ``object_name``
    words split ("blue_large" is "blue large", which a size word then refuses).  Other text is
    returned as it is.

    Raises:
        ParseError: a dict nested in another, or a list in a list (their meaning is not guessed).
    """
    text = re.sub(r"(?<=[a-z])_(?=[a-z])", " ", text)
    if not re.match(r"\s*\{.*:.*\}\s*$", text):
        return text
    if not re.match(r"\s*\{[^{}]*\}\s*$", text) or "[[" in text:  # one flat dict only
        raise ParseError("a task written as a nested config is not read: write it as a sentence, or as one flat dict "
                         "(e.g. {\"task\": \"tower\", \"height\": 3, \"color\": \"cyan\"})")
    parts = []
    for m in re.finditer(r"'?([a-z][a-z _]*)'?\s*:\s*(\[[^\]]*\]|'[^']*'|[^,}]+)", text):
        key, value = m.group(1).strip().replace(" ", "_"), re.sub(r"[\[\]']", "", m.group(2)).strip()
        parts.append(CONFIG_KEYS[key].format(value) if key in CONFIG_KEYS else f"{key.replace('_', ' ')} {value}")
    return ", ".join(p for p in parts if p) or text


SORT_WORD_RE = re.compile(r"\b(?:alphabetic\w*|numeric\w*|ascending|descending|increasing|decreasing|sorted|(?<!\bin\s)order(?!\s+(?:so|for|that)\b))\b", re.IGNORECASE)
"""Words that sort labels: with them, "read A, B, C, D" stays a listed sequence to sort ("put
them in order so they read A B C" does not sort: the reading gives the order)."""

LABEL_CUBES_SAID_RE = re.compile(rf"{lexicon.MATERIAL_SAID_RE.pattern}|\b(?:letter|digit|number)\s+[A-Z0-9]\b", re.IGNORECASE)
"""Words that say the cubes are letter or digit cubes ("the digit cubes", "letter B")."""

_LABEL_REL = (r"(?:on\s+top\s+of|on(?:to)?|atop|under|underneath|below|above|beneath|next\s+to|beside|behind|in\s+front\s+of"
              r"|(?:to\s+the\s+)?(?:left|right)\s+of)")
LABEL_TOKEN_RE = re.compile(r"(?:\b(?:letter|digit|number)\s+)?(?<![\w'@.])(?P<l>[A-Z]|\d)(?![\w'%]|\.\d)"
                            r"(?!\s*(?:[x\u00d7+\-=*/]|blocks?\b|cubes?\b|times\b))")
"""A letter or digit standing alone ("B", "letter B", "2")."""
_LABEL_BE = (r"(?:(?:is|are|goes|sits|stands|rests|lies|stays|ends\s+up|(?:should|must|shall|will|has\s+to|needs\s+to)\s+"
             r"(?:be|go|sit|stand|rest|end\s+up))\s+)?")
"""What may stand between a label cube and its relation ("B should be on C", "A goes on B")."""
LABEL_BEFORE_RE = re.compile(rf"\s+{_LABEL_BE}{_LABEL_REL}\s+(?:the\s+)?(?:(?:letter|digit|number)\s+)?(?:[A-Z]|\d)(?![\w'])")
LABEL_AFTER_RE = re.compile(rf"\b{_LABEL_REL}\s+(?:the\s+)?$")


def labels_in_relations(text: str, digits: bool) -> str:
    """Letters (and, with ``digits``, digits) standing alone for their cubes on either side of a
    relation ("B on A, C on B", "letter B on letter A", "2 on 1, 3 on 2"): rewritten "the letter
    B block".  Digits only for a text that says its cubes are letter or digit cubes
    (:data:`LABEL_CUBES_SAID_RE`): elsewhere "2 on 1" may be a count."""
    def sub(m: re.Match) -> str:
        if m.group("l").isdigit() and not digits:
            return m.group(0)
        if not (LABEL_BEFORE_RE.match(text, m.end()) or LABEL_AFTER_RE.search(text[:m.start()])):
            return m.group(0)
        return f"the {'letter' if m.group('l').isalpha() else 'digit'} {m.group('l')} block"
    return LABEL_TOKEN_RE.sub(sub, text)


THE_PATCH_RE = re.compile(r"\b(the|that|this|same)\s+(?:goal\s+|target\s+)?patch\b(?!es)")
"""A patch referred to without its colour ("far from that patch"): the one patch named before
it, whose colour it takes; refused when several were named (a second, gray patch had been
invented)."""


LATE_REVERSAL_RE = re.compile(
    r"[.!;]\s+(?P<said>(?:(?:then|actually|now|and|oh|wait|sorry)\s*,?\s+)*(?:reverse(?:d)?(?:\s+(?:it|them|that|the\s+order"
    r"|the\s+(?:tower|stack|row|line|word|sequence)))?|(?:put|arrange|place|stack|set)\s+(?:it|them)\s+in\s+(?:the\s+)?reverse(?:d)?\s+order"
    r"|backwards?|in\s+reverse|the\s+other\s+way\s+(?:round|around)|(?:the\s+)?other\s+way\s+(?:round|around)|vice\s+versa"
    r"|flip(?:ped)?(?:\s+(?:it|them|that))?|mirror(?:ed)?(?:\s+(?:it|them|that))?|(?:in\s+)?(?:the\s+)?opposite\s+order"
    r"|upside[\s-]+down))\s*[.!]?\s*$")
"""A last sentence that only turns around what was said before ("Stack red on blue. Vice versa.",
"Build a tower of red, blue and green. Reverse the order."): refused, not dropped."""


THE_TWO_PATCHES_RE = re.compile(r"(?<=\bbetween\s)\s*(?:the\s+(?:two|2)|both(?:\s+the)?|both\s+of\s+the)\s+(?:goal\s+|target\s+)?patches\b")
"""Two patches referred to together without their colours after "between" ("between the two
patches"): the two named before, when exactly two were (other relations to two patches are not
distributed: "behind the two patches" stays refused)."""


def _idle_sentence(sentence: str, unknown: set[str]) -> bool:
    """Whether a sentence says nothing of the task ("My supervisor wants this for the demo."): at
    least two words, none of them a word of the task (:data:`lexicon.TASK_CONTENT_RE`)
    nor a known word beyond fillers and function words, and every unknown one a noun only (an
    adverb or adjective - "Diagonally.", "Sideways.", "Vice versa." - may change what the task asks)."""
    words = re.findall(r"[a-z][a-z'\-]*|\d+", sentence)
    if len(words) < 2 or lexicon.TASK_CONTENT_RE.search(sentence) or lexicon.FRAMING_SENTENCE_HAZARD_RE.search(sentence):
        return False  # ("Return everything.": it may change the goal)
    for w in words:
        if w in unknown:
            pos = lexicon.parts_of_speech(w)
            if "NOUN" not in pos or pos & {"ADJ", "ADV"}:
                return False
        elif w not in lexicon.IDLE_WORDS:
            return False
    return True


_VERB_FINAL_RE = re.compile(r"(?i)^(?P<body>[^.!?]+?)\s*,?\s*(?:please\s+)?(?P<verb>put|place|set|stack(?:ing)?|make|build|arrange)"
                            r"(?:\s+please)?\s*[.!]?\s*$")
_POSTPOSED_RE = re.compile(r"(?i)^(?:as\s+for\s+)?(?P<np>.+?)(?:'s\s+(?P<part>top|right(?:\s+side)?|left(?:\s+side)?|front|back))?\s+"
                           r"(?P<post>on\s+top\s+of|on|onto|to|in|next\s+to|beside|behind|in\s+front\s+of)$")
_PART_PHRASE = {"top": "on top of", "right": "to the right of", "right side": "to the right of", "left": "to the left of",
                "left side": "to the left of", "front": "in front of", "back": "behind"}


def verb_final(text: str) -> str:
    """An instruction whose verb comes last and whose places are postposed (Japanese, Korean,
    Turkish habits: "The 4 cube, the 2 cube's top on, stacking please.", "As for the green cube,
    the yellow patch on, please put.", "Table's right-front corner, white cube, please put.")
    rewritten verb first ("stack the 4 cube on top of the 2 cube"); other text unchanged."""
    m = _VERB_FINAL_RE.match(text.strip())
    if not m or "," not in m.group("body") or re.search(r"(?i)\b(?:not|n't|never|no)\b", m.group("body")) or re.match(r"(?i)\s*(?:please\s+)?(?:put|place|set|stack|make|build|move|arrange)\b",
                                                         m.group("body")):
        return text
    things, places = [], []
    for chunk in (c.strip() for c in m.group("body").split(",")):
        if not chunk or re.fullmatch(r"(?i)please", chunk):
            continue
        post = _POSTPOSED_RE.match(chunk)
        corner = re.fullmatch(r"(?i)(?:the\s+)?table'?s\s+(?P<where>[\w\s-]+?(?:corner|side|edge|centre|center|middle))", chunk)
        if post and not post.group("part") and re.search(r"(?i)\bof$", post.group("post")):
            return text  # "the black cube on top of": the stranded "of" leaves open which cube is on which
        if post and not re.search(r"(?i)\b(?:each other|one another)$", chunk):
            np = re.sub(r"(?i)^(?!the\b)", "the ", post.group("np"))
            where = _PART_PHRASE[post.group("part").lower()] if post.group("part") else post.group("post")
            places.append(f"{where} {np}")
        elif corner:
            places.append(f"in the {corner.group('where')} of the table")
        else:
            things.append(re.sub(r"(?i)^(\w+)\s+(cubes|blocks)\s+all$", r"all the \1 \2", re.sub(r"^The\b", "the", chunk)))
    if len(places) != 1 or not things:
        return text
    verb = m.group("verb").lower().removesuffix("ing")
    return f"{verb} {' and '.join(things)} {places[0]}."


SORT_ASKED_RE = re.compile(r"(?i)\b(?:sort(?:s|ed|ing)?|ascending|descending|increasing|decreasing|numerical(?:ly)?|alphabetical(?:ly)?"
                           r"|smallest|largest|lowest|highest|biggest|greatest)\b"
                           r"|\b" + lexicon.SORT_END_WORD + lexicon.SORT_END_NOUN + r"\s+(?:is\s+|goes\s+|sits\s+)?"
                           r"(?:on|at|in|first|last)\b")
"""Words that ask for labelled cubes in sorted order ("Sort the digit cubes 4, 9 and 2", "in
ascending order", "smallest at the bottom", "biggest number at the bottom")."""

_LABEL_NOUN = lexicon.SORT_END_NOUN
_VERB = r"\s+(?:(?:is|goes|sits|should\s+be|must\s+be)\s+)?"
_DESC_RE = re.compile(r"(?i)\b(?:descending|decreasing|reverse(?:d)?"
                      r"|(?:largest|biggest|greatest|larger|bigger|greater)" + _LABEL_NOUN + _VERB
                      + r"(?:first|at\s+the\s+(?:bottom|base|front|left|start)|on\s+the\s+(?:left|bottom)|in\s+front)"
                      r"|(?:smallest|smaller)" + _LABEL_NOUN + _VERB
                      + r"(?:last|at\s+the\s+(?:top|back|right|end)|on\s+the\s+right|on\s+top|in\s+the\s+back)"
                      r"|(?:highest|higher)" + _LABEL_NOUN + _VERB + r"(?:first|at\s+the\s+(?:bottom|base)|on\s+the\s+(?:left|bottom))"
                      r"|lowest" + _LABEL_NOUN + _VERB + r"(?:last|on\s+top|at\s+the\s+top|on\s+the\s+right))\b")
"""A sort said to run from the largest label ("descending", "the biggest number at the bottom",
"smallest on top", "the larger number is at the bottom"): the listed labels are put largest first
(bottom, left, front)."""


LABEL_RANGE_RE = re.compile(r"(?P<noun>\b(?i:digits|numbers|letters|cubes|blocks)\s+)(?P<lo>\d|[A-Z])\s+(?i:through|thru|to)\s+"
                            r"(?P<hi>\d|[A-Z])\b(?!\s*[-\u2013])")
"""A run of labels said by its ends after their noun ("the digits 1 through 3", "letters A to D")."""


def _listed_range(m: re.Match) -> str:
    """A label range written as its labels ("1 through 3" -> "1, 2 and 3"); unchanged when it runs down or mixes kinds."""
    lo, hi = m.group("lo"), m.group("hi")
    if lo.isdigit() != hi.isdigit() or not lo < hi:
        return m.group(0)
    run = [chr(c) for c in range(ord(lo), ord(hi) + 1)]
    return m.group("noun") + ", ".join(run[:-1]) + " and " + run[-1]


def sorted_labels(text: str) -> str:
    """``text`` with a listed run of labels put in the sorted order its words ask ("Stack the digit
    cubes 7, 3 and 5 in ascending order" -> "... 3, 5 and 7 ..."; descending, or the smallest
    said at the far end, reversed): the readers read a list first to last (bottom to top, left to
    right, front to back), and a sort word alone had left the listed order, silently.  A text
    that spells or reads a word is left as it is (the word gives the order)."""
    if not SORT_ASKED_RE.search(text) or re.search(r"(?i)\b(?:spell\w*|reads?|word|then)\b", text):
        return text
    text = LABEL_RANGE_RE.sub(_listed_range, text)  # "the digits 1 through 3": listed, to be sorted
    least = "1" if re.search(r"(?i)\b(?:digit|number|letter|label)s?\b", text) else "2"  # "digit cubes 5 and 2": two
    m = re.search(r"(?<![\w-])([A-Z]|\d)((?:\s*,\s*(?:and\s+)?|\s+and\s+|\s+)(?:[A-Z]|\d)){" + least + ",}" + r"(?![\w-])", text)
    if m is None:
        return text
    labels = re.findall(r"[A-Z0-9]", m.group(0))
    if len({lab.isdigit() for lab in labels}) != 1:
        return text  # letters and digits mixed: no one key
    ordered = sorted(labels, key=lambda lab: (int(lab) if lab.isdigit() else lab),
                     reverse=bool(_DESC_RE.search(re.sub(r"(?i)\b(?:very|far)\s+(?=bottom|top|left|right|front|back)", "", text))))
    seps = re.findall(r"(?:\s*,\s*(?:and\s+)?|\s+and\s+|\s+)(?=[A-Z0-9])", m.group(0))
    side = _SORT_END_SIDE_RE.search(text)
    way = ""  # "digits 4, 2 and 7 in a row, largest on the left": the sorted labels run from that side
    if side and not re.search(r"(?i)\b(?:left|right|front|back)\s+to\s+(?:the\s+)?(?:left|right|front|back)\b", text):
        way = {"left": " from left to right", "right": " from left to right",
               "front": " from front to back", "back": " from front to back"}[side.group("side").lower()]
    return (text[:m.start()] + ordered[0] + "".join(s + lab for s, lab in zip(seps, ordered[1:], strict=True)) + way
            + text[m.end():])


_SORT_END_SIDE_RE = re.compile(r"(?i)\b" + lexicon.SORT_END_WORD + _LABEL_NOUN
                               + r"(?:\s+(?:is|goes|sits))?\s+(?:on|at|in)\s+(?:the\s+)?(?:far\s+|very\s+)?(?P<side>left|right|front|back)\b")
"""A sorted line's end said by its largest or smallest label ("largest on the left"): the line
runs along that axis, and the sort (:data:`_DESC_RE`) puts the right label at that end."""


def _unshouted(text: str) -> str:
    """``text`` with its words lower-cased when it is shouted (:data:`lexicon.SHOUTING_MIN_SHARE`):
    single letters stay letter cubes, and a word after "spell", "read" or "word" stays spelled."""
    letters = [c for c in text if c.isalpha()]
    if len(letters) < lexicon.SHOUTING_MIN_LETTERS or sum(c.isupper() for c in letters) < lexicon.SHOUTING_MIN_SHARE * len(letters):
        return text
    return re.sub(r"(?<![\w'])(?<!SPELL )(?<!SPELLS )(?<!READ )(?<!READS )(?<!WORD )([A-Z][A-Z']+)\b", lambda m: m.group(1).lower(), text)


def _word_class(word: str) -> str:
    """A word's class for matching a correction to what it corrects (:data:`lexicon.CORRECTION_WORD_CLASSES`)."""
    low = word.lower()
    if low.isdigit() or low in NUMBER_WORDS:
        return "num"
    if low in lexicon.COLORS:
        return "colour"
    if len(word) >= 2 and word.isupper() and word.isalpha():
        return "CAPS"
    return next((k for k, ws in lexicon.CORRECTION_WORD_CLASSES.items() if low in ws), low)


def _corrected(before: str, fix: str) -> str | None:
    """``before`` with the words ``fix`` corrects replaced by it; None when what it corrects is
    not clear (then the instruction is read, and refused, as written)."""
    fixed = re.findall(r"[\w'-]+", fix)
    counted = re.sub(r"(?i)\b(?:\d+|[a-z]+)\s+of\s+them\b", " ", fix)  # "..., three of them": a count, no reference
    if not fixed or lexicon.REFERENCE_PRONOUN_RE.search(counted.lower()) or re.search(
            r"(?i)\b(?:it|them|one)\b", re.sub(rf"(?i)\b(?:{COLOR_RE})\s+one\b", " ", counted)):  # ("the orange one": its cube)
        return None  # "I mean under it": which cube 'it' is depends on what was replaced
    tokens = list(re.finditer(r"[\w'-]+", before))
    lemma = fixed[0].lower() if fixed[0].lower() not in ("just", "then") else (fixed[1].lower() if len(fixed) > 1 else "")
    if lemma in lexicon.PLACEMENT_VERBS:  # "er no, just put them side by side": a new instruction replaces the sentence
        start = max((m.end() for m in re.finditer(r"[.!?;]\s", before)), default=0)
        return before[:start] + fix
    first = _word_class(fixed[0])
    rel = "|".join(p for p, _ in lexicon.REL_PATTERNS[:-1])
    if (first in ("det", "colour") and re.search(rf"(?i)\b(?:cube|block|one)\b.*?\b(?:{rel})\b.*?\b(?:cube|block|one|patch)\b", fix)) \
            or (len(fixed) >= 3 and first not in ("det", "prep") and re.search(rf"\b(?:{rel})\b", fix.lower())):
        # a relation said again, the verb's object and place both: "Stack red on blue, I mean blue on red", "put the red cube
        # on the blue cube, no, the green cube on the blue cube" (the first cube had been kept under the second)
        verbs = [m for m in tokens if m.group(0).lower() in lexicon.PLACEMENT_VERBS]
        return before[:verbs[-1].end()] + " " + fix if verbs else None
    verb_at = max((i for i, m in enumerate(tokens) if m.group(0).lower() in lexicon.PLACEMENT_VERBS), default=-1)
    if first == "colour" and len(fixed) <= 2 and sum(_word_class(m.group(0)) == "colour" for m in tokens[verb_at + 1:]) >= 2:
        return None  # "stack red on blue, sorry, I mean green": red or blue?
    recent = [k for k in range(len(tokens) - 1, max(len(tokens) - 5, -1), -1) if _word_class(tokens[k].group(0)) == first]
    recent = [k for k in recent if tokens[k].group(0).lower() == fixed[0].lower()] or recent  # "to the left of the, wait, to the right"
    if first in ("det", "prep") and recent and not any(  # "on the orange, no the purple cube": the phrase said last
            tokens[k].group(0).lower() in lexicon.PLACEMENT_VERBS for k in range(recent[0], len(tokens))):
        noun = re.search(r"(?i)\b(patch|pad|mat|cube|block)\w*\s*$", before)
        if fixed[-1].lower() == "one" and noun:  # "on the red patch, no wait, the yellow one": the yellow patch (a cube before)
            fix = re.sub(r"(?i)\bone\s*$", noun.group(1), fix)
        return before[:tokens[recent[0]].start()] + fix
    # the phrase of the same shape said last; else the fix's head phrase, its rest continuing the sentence ("put four
    # cubes, no wait, five cubes in a pile": "five cubes" for "four cubes", then "in a pile")
    heads = [len(fixed)] + [k for k in range(len(fixed) - 1, 1, -1) if _word_class(fixed[k]) == "prep" and before.rstrip()[-1:].isalnum()
                            and not re.search(r"\b(?:to|on|onto|in|into|at|of|the|a|an)$", before.rstrip().lower())]
    for k in heads:
        ends = [i for i, m in enumerate(tokens) if _word_class(m.group(0)) == _word_class(fixed[k - 1])]
        for j in reversed(ends if k == len(fixed) else ends[-1:]):
            starts = [i for i in range(j, max(j - 8, -1), -1) if _word_class(tokens[i].group(0)) == first]
            if starts and (k == len(fixed) or j == len(tokens) - 1):  # (a head phrase only where the sentence broke off)
                return before[:tokens[starts[0]].start()] + fix + before[tokens[j].end():]
    if first == "prep":  # "to the left, er no, to the front": the last place said
        preps = [m for m in tokens if _word_class(m.group(0)) == "prep"]
        return before[:preps[-1].start()] + fix if preps else None
    return None


def _relation_object(phrase: str) -> str | None:
    """The colour or label naming a relation phrase's object ("left of the blue cube" -> "blue"), None if it names none."""
    m = re.search(r"(?i)\b(?:the\s+)?([a-z]+)\s+(?:cube|block|one)$", phrase)
    return m.group(1) if m else None


def _relation_head(phrase: str) -> str:
    """A relation phrase's head word ("to the left of it" -> "left", "far apart" -> "far")."""
    return next((w for w in re.findall(r"[a-z]+", phrase.lower()) if w not in ("to", "the", "in", "of", "top")), "")


def _same_slot(kind: str, pos: str, neg: str) -> bool:
    """Whether the denied alternative ``neg`` stands in the slot of the meant one ``pos``, so that ``pos`` already
    excludes it: for two cubes one on the other, the same two colours; for a relation, the same object (or a pronoun
    for it, or none) and a pair of :data:`lexicon.CONTRAST_EXCLUSIVE`; for places, two that share no part of the table
    (:func:`_places_exclusive`); any two structures or orders exclude each other."""
    if kind == "pair":
        return sorted(re.findall(rf"(?i)\b(?:{COLOR_RE})\b", pos.lower())) == sorted(re.findall(rf"(?i)\b(?:{COLOR_RE})\b", neg.lower()))
    if kind == "place":
        return _places_exclusive(pos, neg)
    if kind == "relation":
        a, b = _relation_object(pos), _relation_object(neg)
        heads = {_relation_head(pos), _relation_head(neg)}
        return (a is None or b is None or a.lower() == b.lower()) and heads in lexicon.CONTRAST_EXCLUSIVE
    return True


def _place_extent(phrase: str) -> tuple[str, frozenset[str], frozenset[str]] | None:
    """A said place as ("patch", {colour}, {}) or ("region", its thirds along x, its thirds along y) of the workspace
    (:data:`rpg.domain.constants.REGION_NAMES`: front/center/back by left/center/right); None when not a place."""
    low = phrase.lower()
    patch = re.search(rf"\b({COLOR_RE})\s+(?:patch|pad|mat)\b", low)
    if patch:
        return "patch", frozenset([canon_color(patch.group(1))]), frozenset()
    words = set(re.findall(r"[a-z]+", low))
    xs = {"front"} if words & {"front", "near"} else {"back"} if words & {"back", "rear", "far"} else set()
    ys = {"left"} if "left" in words else {"right"} if "right" in words else set()
    if words & {"middle", "center", "centre"}:
        xs, ys = xs or {"center"}, ys or {"center"}
    if not xs and not ys:
        return None
    return "region", frozenset(xs or {"front", "center", "back"}), frozenset(ys or {"left", "center", "right"})


def _places_exclusive(pos: str, neg: str) -> bool:
    """Whether a cube in place ``pos`` cannot be in place ``neg``: two patches of different colours, or two regions
    that share no part of the table ("the front right corner" and "the back left corner"; not "the left side" and "the
    back left corner", which overlap)."""
    a, b = _place_extent(pos), _place_extent(neg)
    if a is None or b is None or a[0] != b[0]:
        return False
    if a[0] == "patch":
        return a[1] != b[1]
    return not (a[1] & b[1]) or not (a[2] & b[2])


def drop_contrasts(text: str) -> str:
    """``text`` without the alternatives it denies beside the one it means (:data:`lexicon.CONTRAST_ALTERNATIVES`):
    "Not a row, a stack. Green on the bottom, ..." -> "a stack. Green on the bottom, ...", "not descending, ascending:
    ..." -> "ascending: ...", "red on blue, not blue on red" -> "red on blue", "The goal isn't to stack them. The goal is
    to put ..." -> "The goal is to put ...". The meant alternative excludes the denied one, so the goal is the same;
    a denial of anything else stays (refused as a negation). Applied before orders are read (a denied "descending" had
    been read as the order)."""
    text = lexicon.CONTRAST_SENTENCE_RE.sub("", text)
    for kind, pattern in lexicon.CONTRAST_RES:
        for m in reversed(list(pattern.finditer(text))):
            if not _same_slot(kind, m.group("pos"), m.group("neg")):
                continue
            start, end = (m.start(), m.start("pos")) if m.start("pos") >= m.end("neg") else (m.end("pos"), m.end())
            if end == m.start("pos") and kind in ("relation", "place"):  # "Not left of it, right of it: the pink cube goes ..."
                said = re.match(r"\s*(?:[.:;!]|\s?[-\u2013\u2014]+)\s+(?=\S)", text[m.end("pos"):])
                rest = text[m.end("pos") + said.end():] if said else ""
                if said and re.search(rf"(?i)\b(?:{lexicon.CONTRAST_ALTERNATIVES[kind]})\b", rest.split(".")[0]):
                    end = m.end("pos") + said.end()  # the meant alternative said again in the clause after it: the fragment goes too
                elif said and kind == "place" and re.search(r"(?i)\bthere\b", rest):  # "..., the front right corner: put it there"
                    place = m.group("pos") if re.match(r"(?i)(?:in|at|on|to|into|onto)\s", m.group("pos")) else "in " + m.group("pos")
                    text = text[:m.end("pos") + said.end()] + re.sub(r"(?i)\bthere\b", place, rest, count=1)
                    end = m.end("pos") + said.end()
            text = text[:start] + (" " if start and not text[start - 1].isspace() else "") + text[end:]
    return text.strip()


_OTHER_OF_COLOUR_RE = re.compile(rf"\bthe\s+other\s+(?P<c>{COLOR_RE})\s+(?P<n>cube|block|brick)\b")


def other_of_a_colour(text: str) -> str:
    """"the blue cube, the yellow cube and the other blue cube": "the other blue cube" is set apart by the one blue cube
    said before it (a second cube of that colour): both are written as indefinites ("a blue cube ... a blue cube"),
    which :func:`repeated_indefinites` and the readers count as two.  Left as written where that colour is said
    more than once before, in a start ("initially ..."), or not at all (then "the other" contrasts with a cube the
    speaker sees, refused as a reference)."""
    m = _OTHER_OF_COLOUR_RE.search(text)
    if m is None or re.search(r"\b(?:initially|start\w*|begin\w*|currently|now)\b", text):
        return text
    before = list(re.finditer(rf"\b(?:the|a|an|one)\s+{m.group('c')}\s+(?:cube|block|brick)\b", text[:m.start()]))
    if len(before) != 1 or _OTHER_OF_COLOUR_RE.search(text, m.end()):
        return text
    b = before[0]
    return (text[:b.start()] + f"a {m.group('c')} {m.group('n')}" + text[b.end():m.start()] + f"a {m.group('c')} {m.group('n')}"
            + text[m.end():])


def repeated_indefinites(text: str) -> str:
    """``text`` with each indefinite cube of a colour said again (:data:`lexicon.INDEFINITE_CUBE_RE`) written as
    "another" cube of it: "a red cube on the blue patch and a red cube on the green patch" -> "... and another red cube
    on the green patch" (two cubes; the second had been the first on two patches). Left as written where the colour
    is also said with "the" (which one "the red cube" is would be unclear)."""
    seen: dict[str, int] = {}
    out, last = [], 0
    for m in lexicon.INDEFINITE_CUBE_RE.finditer(text):
        c = m.group("c")
        restated = c in seen and lexicon.RESTATEMENT_RE.search(text, seen[c], m.end())  # "..., i.e. a red cube on ..."
        if c in seen and not restated and not re.search(rf"\bthe\s+{c}\s+(?:cube|block|brick|box|one)\b", text):
            out.append(text[last:m.start()] + m.group("pre") + f"another {c} {m.group('n')}")
            last = m.end()
        seen.setdefault(c, m.end())
    return "".join(out) + text[last:]


def spoken(text: str) -> str:
    """``text`` without what speech adds to a request and says nothing of it: interjections and openings
    (:data:`lexicon.FILLER_RE`: "okay so, ..."), hesitations (:data:`lexicon.DISFLUENCY_RE`: "uh", "um", "mm"; a colour
    said again after one, :data:`lexicon.HESITANT_COLOUR_RE`), a filler between pauses (:data:`lexicon.PAUSE_FILLER_RE`:
    ", like,", ", you know,"), words said twice in a row (:data:`lexicon.STUTTER_RE`; a run with a colour or a number
    stays unless it opens with an article: "blue blue" may be two cubes), and a comma put before a correction spoken
    without a pause (:data:`lexicon.SPOKEN_CORRECTION_RE`), for :func:`apply_corrections`.  Used by the parser and by
    steering, whose edits are said the same way ("um, make it five, no, four")."""
    text = lexicon.FILLER_RE.sub("", text).strip()
    text = lexicon.HESITANT_COLOUR_RE.sub(r"\g<det> \g<c>\g<noun>", text)  # "the red, er, orange cube": orange
    text = lexicon.DISFLUENCY_RE.sub(lexicon.dropped_hesitation, text)  # a transcript's "uh", "um"
    text = lexicon.PAUSE_FILLER_RE.sub(",", text)  # "reverse that, like, green first"
    text = re.sub(rf"(?i)\b(a|an|one)\s+({COLOR_RE})\s+\2\s+(cube|block|brick)\b(?!s)", r"\1 \2 \3", text)  # "a yellow yellow cube": one
    text = lexicon.STUTTER_RE.sub(lambda m: m.group(0) if re.search(rf"\b(?:{COLOR_RE}|{lexicon.COUNT_WORD_RE})\b|\d", m.group("run"), re.I)
                                  and not re.match(r"(?i)(?:the|a|an)\s", m.group("run")) else m.group("run"), text)
    return lexicon.SPOKEN_CORRECTION_RE.sub(", ", text)  # "... purple patch no I mean the pink patch"


def apply_corrections(text: str) -> str:
    """``text`` with each self-correction applied ("put the green cube on the yellow patch, sorry,
    the pink patch" -> "... on the pink patch"; :data:`lexicon.SELF_CORRECTION_RE`): the words
    after the correction word, up to the next pause, replace the words of the same shape said
    last before it (same first and last word class), a new command the sentence before it, a new
    relation what the verb before it governs, a list of colours the list said before it ("red,
    green, blue, no wait, red, blue, green").  A correction whose target is not clear is left
    as written (its words are then refused)."""
    colour_list = rf"(?:{COLOR_RE})(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+)(?:{COLOR_RE}))+\b"
    for m in reversed(list(lexicon.SELF_CORRECTION_RE.finditer(text))):
        fix = re.match(r"[^,.;!?\u2013\u2014]+?(?=\s*(?:[,.;!?\u2013\u2014]|\s-\s|$))", text[m.end():])  # (to the next pause or dash)
        before = text[:m.start()].rstrip(" ,;:-\u2013\u2014")
        listed = re.match(rf"(?i)(?:of\s+)?{colour_list}", text[m.end():])
        said = re.search(rf"(?i)(?:\bof\s+)?{colour_list}$", before)
        if listed and said:  # "a row: red, green, blue, no wait, red, blue, green": the list said again (two had been kept)
            again, then = (re.findall(rf"(?i)\b(?:{COLOR_RE})\b", x.group(0)) for x in (listed, said))
            if sorted(again) != sorted(then) and not (listed.group(0).lower().startswith("of") or (len(again) == len(then) >= 3)):
                continue  # "red, blue, sorry, green, and yellow": not the whole list again (its cubes, "of ...", or as
                # many of three or more), so which of the list is corrected is not said (the whole list had been replaced, red dropped, silently): left as written, refused
            text = before[:said.start()] + listed.group(0) + text[m.end() + listed.end():]
            continue
        side = re.fullmatch(r"(?:to|on|at)\s+the\s+(left|right|front|back)", fix.group(0).strip()) if fix else None
        related = re.search(r"(?s:.*)\b(left|right)(\s+of\s+[^,;.]+)$", before) if side else None
        if related and (side.group(1) not in ("left", "right") or re.search(
                r"\b(?:and|in\s+front|behind|on|onto|next|beside|between|under|above|below|near|far)\b", related.group(2))):
            continue  # a relation of another kind, or another cube's, after the side said: which is corrected is not said
        if related:  # "to the left of blue, correction, to the right": the side of the same relation ("to the right" had
            # become a place of the table, the relation dropped)
            text = before[:related.start(1)] + side.group(1) + related.group(2) + text[m.end() + fix.end():]
            continue
        new = _corrected(before, fix.group(0).strip()) if fix and before.strip() else None
        if new is not None:
            rest = text[m.end() + fix.end():]
            if re.fullmatch(r"\d+", fix.group(0).strip()) or fix.group(0).strip().lower() in lexicon.NUMBER_WORDS:  # "stack
                # three, I mean four, red cubes": the count's own noun follows (the comma had cut it off)
                rest = re.sub(r"^\s*(?:,|-|\u2013|\u2014)\s*(?=[a-zA-Z])", " ", rest)
            text = new + rest
    return text


LABEL_ROLE_RE = re.compile(r"(?<![\w.'\-])(?:(?:the\s+)?(?:digit|number|letter)\s+(?P<ll>[a-z0-9])\b|(?P<l>\d|[A-Z]))(?:\s+(?:cube|block))?\s+"
                            r"(?:is\s+|goes\s+|sits\s+|should\s+be\s+|must\s+be\s+)?(?:(?:at|on|in)\s+(?:the\s+)?(?:very\s+)?"
                            r"(?P<r>bottom|base|top|middle)\b|on\s+(?P<t>top)\b|in\s+(?P<b>between)\b|(?P<b2>between)\s+(?:them|those)\b)(?!\s+of\b)")
"""A label cube given its place in a tower ("9 at the bottom", "3 is on top", "2 in between")."""
_ROLE_RANK = {"bottom": 0, "base": 0, "middle": 1, "between": 1, "top": 2}


_LABEL_ITEM = r"(?:(?:the\s+)?(?:digit|number|letter)\s+[a-z0-9]|\d|[A-Z])(?:\s+(?:cube|block))?"
LABEL_TOWER_STEPS_RE = re.compile(
    rf"(?<![\w.'\-])(?P<first>{_LABEL_ITEM}|[a-z])\s+(?:is\s+|goes\s+)?(?:at|on)\s+the\s+(?:very\s+)?(?:bottom|base)\s*,?\s*"
    rf"(?P<rest>(?:and\s+)?then\s+(?:the\s+)?{_LABEL_ITEM}(?:\s*,?\s*(?:and\s+)?then\s+(?:the\s+)?{_LABEL_ITEM})*)"
    r"(?:\s+(?:on\s+top|at\s+the\s+(?:very\s+)?top))?(?=\s*(?:[.;!]|$))")
"""A tower's label cubes said in turn from its base ("7 at the bottom, then 2, then 9", "A at the bottom, then B, then C
on top"; a first letter may be lower-cased there, "a at the bottom, then the letter b block"), to the clause's end (a
place after the last, "then 9 at the bottom", "then 9 in the corner", is not read so): the order from the bottom (the
first label had been lost, or the tower built of coloured cubes)."""


def _label_tower_steps(text: str) -> str:
    """``text`` with a tower's label cubes said in turn from its base (:data:`LABEL_TOWER_STEPS_RE`) written as the order
    from the bottom ("... from bottom to top: digit 7, digit 2, digit 9"), for :func:`_label_tower_roles`'s readers."""
    m = LABEL_TOWER_STEPS_RE.search(text)
    if m is None or not re.search(r"\b(?:stack\w*|towers?|columns?)\b", text[:m.start()]) \
            or re.search(rf"\b(?:{COLOR_RE})\b", text[:m.start()]):
        return text  # ("a tower of blue number blocks: ...": a colour of labelled cubes, read as written)
    items = [m.group("first")] + re.split(r"\s*,?\s*(?:and\s+)?then\s+", m.group("rest"))[1:]
    labels = [re.sub(r"^(?:the\s+)?(?:(?:digit|number|letter)\s+)?|\s+(?:cube|block)$", "", it.strip()) for it in items]
    if re.fullmatch(r"[a-z]", m.group("first")) and not all(lab.isalpha() for lab in labels[1:]):
        return text  # a lower-case letter first (the text is lower-cased but for labels): a letter only among letters
    order = ", ".join(("digit " if lab.isdigit() else "letter ") + lab.lower() for lab in labels)
    head = re.sub(r"\s*[:,]\s*$", "", text[:m.start()])
    return f"{head} from bottom to top: {order}{text[m.end():]}"


def _label_tower_roles(text: str) -> str:
    """A tower's label cubes said by their places ("a two-cube tower: 9 at the bottom, 0 on top",
    "stack the digits so that 1 is at the bottom and 3 is on top, with 2 in between") written as
    the order from the bottom, which the readers read ("... from bottom to top: 9, 0"): the bare
    labels had been dropped and the tower built of coloured cubes (silently wrong).  Left as it is
    where the labels are listed as well; refused unless every role is said once, of two or three
    labels, bottom and top among them.

    Raises:
        ParseError: the roles do not make one order ("0 at the bottom, 1 at the bottom, ...")."""
    if not re.search(r"\b(?:stack\w*|towers?|tiers?|columns?|piles?\s+up)\b", text) or re.search(
            r"\b(?:pyramids?|walls?|grids?|layers?|rows?)\b", text):
        return text  # a layered structure's "3 on the bottom, 2 in the middle" are counts
    found = list(LABEL_ROLE_RE.finditer(text))
    if not found:
        return text
    ranks = [_ROLE_RANK[m.group("r") or m.group("t") or m.group("b") or m.group("b2")] for m in found]
    labels = [(m.group("ll") or m.group("l")).upper() for m in found]
    label_re = r"(?<![\w.])(?:\d|[A-Z])(?![\w.])|\b(?:letter|digit|number)\s+[a-z0-9]\b"
    said = text[:found[0].start()] + " " + text[found[-1].end():]
    if re.search(label_re, said) or len(re.findall(label_re, text[found[0].start():found[-1].end()])) != len(found):
        return text  # the labels are listed as well ("the digit cubes 1, 2, 3 and 4 ..., 4 at the bottom", "A at the
        # bottom, then B, then C on top"): read there
    if len(found) < 2:
        return text  # one label with a place: a relation or a role the readers read ("stack 3 on the red cube")
    big = re.search(r"\b\d\d+\b", text[found[0].start():found[-1].end()])
    if big:  # "3 at the bottom, 12 in the middle and 1 on top": no digit cube (a 2 had been made up between 3 and 1)
        raise ParseError(f"'{big.group(0)}' in \"{text[:80]}\" is given a place in the tower, but digit cubes carry 0-9; "
                         "name each cube of the tower, or use --model")
    if re.search(rf"\b(?:{COLOR_RE})\b", text[found[0].start():found[-1].end()]):
        return text  # a coloured cube given a place among them ("3 at the bottom, red in the middle and 1 on top"): read
        # as written (it had been dropped)
    if len(found) > 3 or len(set(ranks)) != len(ranks) or {0, 2} - set(ranks) or len(set(labels)) != len(found):
        raise ParseError(f"the labelled cubes of \"{text[:80]}\" are given places in the tower that do not make one order "
                         "(each label once, one at the bottom and one on top); say the order from the bottom (e.g. \"stack "
                         "the digit cubes 1, 2 and 3 from bottom to top\"), or use --model")  # read as coloured cubes before
    order = ", ".join(("digit " if lab.isdigit() else "letter ") + lab.lower()
                      for _, lab in sorted(zip(ranks, labels, strict=True), key=lambda x: x[0]))
    head = re.sub(r"(?:\s*[:,]|\s+(?:so\s+that|such\s+that|with|where))\s*$", "", text[:found[0].start()])
    return f"{head} from bottom to top: {order}" + re.sub(r"^[\s,;]*(?:and\s+)?(?=[.!]|$)", "", text[found[-1].end():])




def normalize_words(instruction: str, strict: bool = True) -> tuple[str, str, list[tuple[str, str]]]:
    """Lower-case, number words to digits, typos corrected.  Returns (text, original, dropped):
    ``dropped`` lists the unknown words read as ignorable (:mod:`rpg.schema.senses`), each with
    the ignorable word it reads like.

    Args:
        strict: refuse words the parser does not know (``False``: keep them, for reading the
            mentions of an instruction a language model reads).

    Raises:
        ParseError: empty, too long, or (strict) containing words the parser does not know.
    """
    text, original, dropped = _normalized(instruction, strict)
    return text, original, list(dropped)


@functools.lru_cache(maxsize=4096)
def _normalized(instruction: str, strict: bool) -> tuple[str, str, tuple[tuple[str, str], ...]]:
    """:func:`normalize_words`, remembered: a text is normalized once however many readers, citations and checks of
    one compile, steering session or paraphrase check ask for it (a parse alone had normalized one text up to 4.5 times
    on average over its distinct texts; checking that the corpus's paraphrases state their goals took a quarter of the
    time with this, measured 2026-11-26).  A refusal is not remembered (it is raised again)."""
    text, original, dropped = _normalize_words(instruction, strict)
    return text, original, tuple(dropped)


LABEL_LIST_PLURAL_RE = re.compile(r"(\bthe\s+[A-Z]\b(?:\s*,\s*the\s+[A-Z]\b)*\s*,?\s*(?:and|or)\s+the\s+[A-Z])\s+(block|cube|brick)s\b")
"""Label cubes listed each with "the" and one plural noun after the last ("the B, the A and the T blocks"): the noun is
the last cube's, singular (the plural had hidden its label, and the cube was dropped, silently)."""


def _normalize_words(instruction: str, strict: bool) -> tuple[str, str, list[tuple[str, str]]]:
    original = instruction.strip()
    if len(original) > MAX_RAW_CHARS:
        raise ParseError(f"the instruction has {len(original)} characters; the limit is {MAX_INSTRUCTION_CHARS}")
    for pattern, written in lexicon.MARKUP_RES:  # "the **blue** patch", "## Goal", "`red`"
        original = pattern.sub(written, original).strip()
    original = lexicon.EMOJI_RE.sub(" ", original).strip()
    original = lexicon.ORDINAL_ABBREVIATION_RE.sub(lambda m: lexicon.ORDINAL_ABBREVIATIONS[m.group(1).lower()], original)
    original = LABEL_LIST_PLURAL_RE.sub(r"\1 \2", original)  # "the B, the A and the T blocks": T is one cube (it had been dropped)
    original = lexicon.SAYS_RE.sub(r"\1reads", original)  # "the tower says H, A, T"
    original = lexicon.DEMONSTRATIVE_STRUCTURE_RE.sub(r"\g<p> the \g<n>", original)  # "on top of that tower"
    original = lexicon.REST_ANY_ORDER_RE.sub("the others in any order", original)  # "the rest in whatever order"
    original = lexicon.HYPHENED_DIRECTION_RE.sub(r"\1 to \2", original)
    original = lexicon.rewrite(lexicon.DIAGONAL_SIDE_REWRITES, original)  # "diagonally behind X, off to its right"
    original = lexicon.DIAGONAL_PLACE_RE.sub(lexicon.diagonal_place, original)  # "to the front-right of the red cube"
    original = lexicon.ROBOT_DIRECTION_RE.sub(lexicon.robot_direction, original)  # "a column ... away from the robot"
    original = lexicon.LINE_UP_DIRECTION_RE.sub(lexicon.line_up_direction, original)  # "line up ... going away from the robot"
    original = lexicon.hyphened_chains(original)  # "a red-on-yellow tower", "a 1-on-2 tower", "a three-block ..."
    original = lexicon.ARROW_DIRECTION_RE.sub(lexicon.arrow_direction, original)  # "l->r", "bottom -> top"
    original = lexicon.named_towers_listed(original)  # "Tower A: orange, purple. Tower B: cyan, brown, red."
    original = lexicon.STRUCTURE_NAME_RE.sub(r"\1", original)  # "Tower A: ...", "tower B is pink on gray"
    original = lexicon.MEASURE_WORD_RE.sub(lambda m: f"{m.group(1)} {(m.group('c') or '') + ' ' if m.group('c') else ''}"
                                           f"{'cubes' if m.group('n').lower().startswith('c') else 'blocks'}", original)
    original = lexicon.GLUED_COUNT_RE.sub(lambda m: f"{m.group(1)}{m.group(2).replace('-', ' ')} {m.group(3)}", original)
    if lexicon.LETTER_SIGNATURE_RE.search(original):  # "Hi Sam, ... Thanks, Priya": a signed message
        original = lexicon.LETTER_GREETING_RE.sub("", lexicon.LETTER_SIGNATURE_RE.sub("", original)).strip() or original
    original = _unshouted(original)
    original = lexicon.rewrite(lexicon.ROW_SAID_BY_ORDER_REWRITES, original)  # "Left to right: red, green, blue."
    original = lexicon.bare_tower_roles(original)  # "Top: red. Middle: green. Bottom: blue."
    for pattern, written in lexicon.LEGAL_RES:  # "the aforementioned green cube", "(hereinafter 'the Cube')"
        original = pattern.sub(written, original)
    for pattern in lexicon.GRADING_FRAME_RES:  # "Q3. (4 points) ...", "full marks if ...; zero otherwise"
        original = pattern.sub("", original).strip()
    original = lexicon.rewrite(lexicon.REPORTED_REQUEST_REWRITES, original)  # "Trial 12 asks for the cube to be moved to ..."
    original = lexicon.DISCOURSE_OPENING_RE.sub("", original)  # "Anyway, pop the yellow cube on ..."
    original, asides = drop_asides(original)  # "Put the green block on the purple block. What a tower!"
    original = lexicon.DAYS_TASK_RE.sub("the ", original)  # "Today's exercise is a tower of ...": the exercise
    original = lexicon.SWAP_HEADING_RE.sub("", original)  # "Swap places: the yellow cube goes on the cyan patch and ..."
    needs = lexicon.NEEDS_MORE_RE.search(original)
    if needs and strict and not lexicon.GOAL_THING_RE.search(needs.group(0).lower()):
        raise ParseError(f"'{needs.group(0).strip()}' in \"{original[:80]}\" says the task needs something it does not name as "
                         "cubes; say which cube goes where (e.g. \"put a green cube on top\"), or use --model")
    original = lexicon.taken_down_as_unstack(original)  # "Take down the tower.": an undoing (a tower had been built)
    original = lexicon.start_stack_source(original)  # "There is a stack of blue on red. Move blue from the stack onto ..."
    original = lexicon.start_and_goal_said_tersely(original)  # "1. Start: green on brown. 2. Goal: green on table"
    original = lexicon.TEXTED_TO_RE.sub(lambda m: f"{m.group(1) or m.group(2)} to ", spoken(original))  # texting's "2" for "to"
    original = lexicon.TEXTED_YOU_RE.sub("you", original)  # "can u build ...": texting's "u"
    original = lexicon.SPELLED_ALOUD_RE.sub(lambda m: m.group("letters") if m.group("word").upper() == "".join(
        m.group("letters").split()) else m.group(0), original)  # "D O G dog"
    original = lexicon.SAY_LETTERS_RE.sub("to spell ", original)  # "the letter cubes to say D O G"
    echo = lexicon.SPOKEN_ECHO_RE.search(original)
    if echo and re.search(rf"(?i)\b{echo.group('rel')}\b", original[:echo.start()]):  # "... yeah behind it": said again
        original = original[:echo.start()]
    original = apply_corrections(original)  # "..., sorry, the pink patch": the correction wins
    original = drop_contrasts(original)  # "Not a row, a stack.": the denied alternative excludes nothing more
    original = lexicon.tower_ends_said(original)  # "red (bottom), blue, yellow (top)"
    left = lexicon.END_LEFT_IN_PARENTHESES_RE.search(original)
    if left:  # "red, blue (bottom), yellow", "red (bottom), blue, yellow (bottom)": an end on a middle cube, or one end twice
        raise ParseError(f"'{left.group(0)}' in \"{original[:80]}\" gives a cube an end of the tower that its place in the list does "
                         "not have (or both ends one side); say the tower from bottom to top, or use --model")  # "red (bottom), blue, yellow (top)"
    original = verb_final(original)  # "The 4 cube, the 2 cube's top on, stacking please.": the verb said first
    for pattern, full in lexicon.ORDER_RANGE_RES:  # "small to big": a sort by its two ends
        original = pattern.sub(full, original)
    original = sorted_labels(original)  # "Stack the digit cubes 7, 3 and 5 in ascending order": listed sorted
    if re.search(r"\b(?:[A-Z]|\d)\s+(?:at|on|in)\s+(?:the\s+)?(?:bottom|top|base|middle)\b", original):
        # "stack the digits 1 to 3, 1 at the bottom": the run listed, so the role reads against every cube (the middle
        # digit had been dropped)
        original = LABEL_RANGE_RE.sub(_listed_range, original)
    original = lexicon.LABELS_AND_NOUN_RE.sub(_labels_each_a_cube, original)  # "the 1 & 9 cubes", "the A, B and C cubes"
    original = lexicon.LABEL_LIST_PLACED_RE.sub(_placed_labels_one_by_one, original)  # "the letter cubes A and B on the white patch"
    original = lexicon.DIGIT_WORDS_RE.sub(lambda m: m.group("noun") + lexicon.DIGIT_WORD_RE.sub(
        lambda w: str(lexicon.DIGIT_WORDS.index(w.group(0).lower())), m.group("list")), original)
    if not original:
        raise ParseError("the instruction is empty; describe a task, e.g. \"stack the red block on the blue block\"")
    if len(original) > MAX_INSTRUCTION_CHARS:
        raise ParseError(f"the instruction has {len(original)} characters; the limit is {MAX_INSTRUCTION_CHARS}")
    original = lexicon.rewrite(lexicon.READ_FROM_REWRITES, original)
    original = lexicon.COUNTED_STRUCTURE_RE.sub(r"\1-\2 ", original)  # "the 3 cube tower"
    original = lexicon.LABELS_BETWEEN_RE.sub(lambda m: f"between the {m.group('kind').lower()} {m.group('a').upper()} cube and "
                                             f"the {m.group('kind').lower()} {m.group('b').upper()} cube", original)
    original = lexicon.REARRANGED_RE.sub(rearranged, original)  # "5, 2, 8 rearranged so they go 2, 5, 8"
    # "so that they read 1 2 3", "reads A, B, C": the labels read as one word ("read 123")
    if not SORT_WORD_RE.search(original):  # "... read A, B, C, D in alphabetical order": a sort, read as one
        original = re.sub(r"\b((?:read|spell|show)(?:s|ing)?)\s+((?:[A-Z0-9](?:\s*,\s*(?:and\s+)?|\s+and\s+|\s*-\s*|\s+))+[A-Z0-9])"
                          r"(?![\w'])", lambda m: f"{m.group(1)} {re.sub(r'[^A-Z0-9]', '', m.group(2))}", original)
    # "the cube with the M", "the block with the 4 on it": the cube labelled so
    labelled = lexicon.rewrite(lexicon.LABEL_NOUN_REWRITES, original)
    listed = re.search(r"\b[A-Z0-9](?:\s*,\s*(?:and\s+)?[A-Z0-9]\b|\s+and\s+[A-Z0-9]\b)", original)  # "T, O, P": a list
    labels_named = len(set(re.findall(r"(?<![\w'])[A-Z](?![\w'])", original))) >= 2 or re.search(
        r"(?i)\b(?:letter|digit|number|label)(?:ed|s)?\b", original)  # ("so that A is on top" of coloured cubes: no label)
    spelled_word = re.search(r"(?i)\b(?:spell\w*|reads?|word)\b", original)  # ("Spell HI so that H is on the left": a letter)
    labelled = BARE_LABEL_RE.sub(lambda m: m.group(0) if (listed and m.group(1).lower() != "the") or (
                                     m.group(1).lower() in ("that", ":") and (not labels_named or spelled_word)) else
                                 f"{m.group(1)} {'' if m.group(1).lower() == 'the' else 'the '}{m.group(2)} block",
                                 labelled)  # "stack the A on the B", "with A at the bottom, then B": label cubes; after "that" or
    # a colon only where the text names label cubes ("so that A is at the bottom, B in the middle and C on top")
    # "stack B on A, C on B", "STACK 2 on 1, 3 on 2 (digit cubes)", "stack letter B on letter A"
    labelled = labels_in_relations(labelled, digits=bool(LABEL_CUBES_SAID_RE.search(original)) or any(
        p.search(original) and p.search(original).group("l").isdigit() for p in lexicon.LABEL_CUBE_SAID_RES) or (
        # ("Use block 9 and block 5 only: stack 9 on 5": digit cubes said by their mark; 9 had gone under 5)
        # "Stack 2 on 1 and 4 on 3.": digits on both sides of two relations, with no cube counted anywhere, name digit
        # cubes ("stack 2 on 1" alone stays refused: two cubes on one?)
        len(re.findall(r"\b\d\s+(?:on|onto|on\s+top\s+of)\s+\d\b", original)) >= 2
        and not re.search(r"(?i)\b(?:blocks?|cubes?|bricks?|boxes|towers?|stacks?\s+of|high|tall|levels?|rows?|layers?)\b", original)))
    lone = re.findall(r"\b\d\s+(?:on|onto|on\s+top\s+of)\s+\d\b", labelled)
    if len(lone) == 1 and strict and not re.search(r"(?i)\b(?:blocks?|cubes?|bricks?|boxes|digits?|numbers?|numbered|labell?ed)\b",
                                                   original):
        # "Stack 1 on 2.": the digit cubes 1 and 2, or one cube on two? (it had been read as two cubes in any order)
        raise ParseError(f"'{lone[0]}' in \"{original[:80]}\" may name digit cubes or count cubes; say which (e.g. \"stack the "
                         "digit cube 1 on the digit cube 2\" or \"stack one cube on two cubes\"), or use --model")
    labelled = lexicon.rewrite(lexicon.LABEL_ARTICLE_REWRITES, labelled)
    text = labelled.lower()
    text = re.sub(r"[\u2018\u2019\u201c\u201d`]", "'", text)
    text = text.replace('"', "'")
    text = config_fragment(text)
    def _restated(m: re.Match) -> str:
        said = re.sub(r"\s+the\s+[a-z]+\s+(?:cube|block|one)$", "", m.group("said")).replace("to the ", "").removesuffix(" of")
        neg = m.group("neg").replace("to the ", "").removesuffix(" of").replace("underneath", "under")
        obj = re.search(r"\bthe\s+([a-z]+)\s+(?:cube|block|one)$", m.group("said"))
        other = re.search(r"\bthe\s+([a-z]+)\s+(?:cube|block|one)\s*$", m.group(0))
        if other and obj and other.group(1) != obj.group(1):
            return m.group(0)  # "right of the blue cube, not left of the green cube": another cube, another constraint
        return m.group("said") if any({said, neg} == {a, b} for a, b in lexicon.OPPOSITE_RELATIONS) else m.group(0)
    text = lexicon.OPPOSITE_NEGATED_RE.sub(_restated, text)  # "in front of the grey cube, not behind it": said again
    text = lexicon.OTHER_WAY_DENIED_RE.sub("", text)  # "..., not the other way round": said again
    effectors = [(m.group("what"), "the effector or robot that does it") for m in lexicon.EFFECTOR_RE.finditer(text)]
    effectors += [(said, "a sentence that names nothing of the task") for said in asides]
    text = lexicon.EFFECTOR_RE.sub(" ", text).strip()
    text = lexicon.rewrite(lexicon.OUTCOME_VERB_REWRITES, text)
    for pattern, written in lexicon.FREE_PHRASE_REWRITES:  # "Colours of the cubes are not specified.", "thats it"
        text = pattern.sub(written, text).strip()
    text = lexicon.NOT_IMPORTANT_RE.sub(r"\1 unimportant", text)  # "the colours are not important": no negation
    text = lexicon.FREE_PAIR_RE.sub("colours do not matter, in any order", text)
    text = lexicon.ANY_ORDER_RE.sub(" in any order", text)  # before "doesn't" is refused as a negation
    text = re.sub(r"(\s+(?:at|in|on|along|across|toward|towards)\s+the\s+(?:[a-z-]+\s+){1,3}?of\s+the\s+(?:table|workspace))\s+in\s+any\s+order\b",
                  r" in any order\1", text)  # "... in a row at the back of the table, in any order": the place ends the clause
    text = lexicon.HARMLESS_NEGATION_RE.sub("", text)
    for m in lexicon.FREE_CHOICE_RE.finditer(text):  # "put the red cube left of the blue cube. colours don't matter"
        rest = text[:m.start()] + text[m.end():]
        others = re.search(rf"\b(?:other|remaining|middle)\s+(?:\d+|{lexicon.COUNT_WORD_RE})\b|\brest\b|\bothers\s*:", m.group(0))
        if others and not re.search(rf"\b(?:\d+|{lexicon.COUNT_WORD_RE})\b", rest):
            # "a tower: red bottom, blue top, other two don't matter": the count lives only in those words (two cubes had
            # been built, the other two dropped with them)
            raise ParseError(f"'{m.group(0).strip(' ,;')}' counts the other cubes, but \"{original[:80]}\" does not say how many "
                             "cubes the task has; say it (e.g. \"a tower of four cubes, red at the bottom, blue on top\"), or use --model")
        unnamed = re.search(rf"\b(?:\d+|{lexicon.COUNT_WORD_RE}|some|other|remaining)\s+(?:more\s+)?(?:cubes|blocks|ones)\b(?!\s+of\b)"
                            rf"|\b(?:a|an|any|one)\s+(?:cube|block)\b"
                            rf"|\b(?:tower|stack|row|line|pile)\s+of\s+(?:\d+|{lexicon.COUNT_WORD_RE})\b(?!\s+(?:{COLOR_RE})\b)", re.sub(rf"\b(?:\d+|{lexicon.COUNT_WORD_RE})\s+(?:{COLOR_RE})\b", " ", rest))
        coloured = re.search(rf"\b(?:{COLOR_RE})\s+(?:tower|stack|row|line|pile|pyramid|wall|circle|grid)\b", rest)
        if re.search(r"colou?r", m.group(0)) and re.search(rf"\b(?:{COLOR_RE})\b", rest) and (not unnamed or coloured):
            # ("a red tower of three cubes. Colours ... not specified": the colour before the structure is every cube's)
            # (with cubes nobody names by colour, "any colours" is theirs: "put two cubes on the purple cube, any colours")
            raise Inexpressible("contradiction", [m.group(0).strip(" ,;(\u2013\u2014-")], "leaves the colours free, but the "
                                "instruction names its cubes by colour, which is how the goal tells them apart; say one of "
                                "the two", original)
    text, freed = lexicon.FREE_CHOICE_RE.subn("", text)
    if freed:  # "Stack three cubes; the colours do not matter but the top one must be white": what the 'but' kept
        text = re.sub(r"([;,])?\s*\bbut\s+(?=(?:the|a|an)\s)", lambda m: (m.group(1) or ",") + " ", text, count=1)
    for pattern, written in lexicon.CHAT_TURN_RES:  # "[10:32] alice: stack blue on green [10:33] bob: ok on it"
        text = pattern.sub(written, text)
    text = re.sub(r"^[\s.]+", "", text)
    for pattern in lexicon.TASK_FRAME_RES:  # "In this task the agent must ...", "The episode is successful if ..."
        text = pattern.sub("", text).strip()
    text = lexicon.SMALL_TALK_RE.sub(" ", text)
    text = lexicon.HEADER_RE.sub("", text)
    dash = lexicon.DASH_LABEL_RE.match(text)
    if dash and re.findall(r"[a-z]+", dash.group("label"))[:1] and re.findall(r"[a-z]+", dash.group("label"))[0] in lexicon.DASH_LABEL_WORDS \
            and not lexicon.TASK_CONTENT_RE.search(re.sub(r"\d+", "", dash.group("label"))) and not _inexpressible(dash.group("label")):
        effectors.append((dash.group("label").strip(), "a heading before its dash"))  # "new task -> ...", "todo - ..."
        text = text[dash.end():]
    labels = [m for m in lexicon.LABEL_RE.finditer(text)
              if len(re.findall(r"[a-z]+", m.group("label"))) <= lexicon.LABEL_MAX_WORDS
              and not lexicon.TASK_CONTENT_RE.search(re.sub(r"(?<=[a-z])\s+#?\d+(?=\s|$)|\b(?:just\s+|only\s+)?one\s+(?:task|relation|goal|"
                                                            r"thing|check|condition|episode|run|trial)\b", "",
                                                            m.group("label")))  # "item 2", "just one task"
              and not _inexpressible(m.group("label")) and not lexicon.TURNING_LABEL_RE.search(m.group("label"))
              and not re.fullmatch(r"\s*(?:next|then|second|third|fourth|fifth|2nd|3rd|4th|5th|after\s+that|afterwards|middle|mid"
                                   r"|upper|lower)\s*", m.group("label"))  # "Base: red. Next: white. Top: green.": a role
              and not lexicon.START_WORD_RE.search(m.group("label"))]  # "Let me describe the start: ...": the start, not a label
    for m in reversed(labels):  # "Obj: red on blue.", "Checklist: ...": a label that names nothing of the task
        text = text[:m.start("label")] + text[m.end():]
    effectors += [(m.group("label").strip(), "a label before its colon") for m in labels]
    text = lexicon.ADDRESS_RE.sub("", text)
    text = " ".join(s for s in re.split(r"(?<=[.!?])\s+", text)  # "Good job!", "Yay!": sentences that only cheer
                    if not set(re.findall(r"[a-z']+", s.lower())) <= lexicon.CHAT_WORDS) or text
    asked_by = effectors + [(m.group("who"), "who asks for the task") for m in lexicon.SOMEONE_WANTS_RE.finditer(text)]
    text = lexicon.SOMEONE_WANTS_RE.sub("i want", text)
    asked_by += [(m.group("who") or m.group("pronoun"), "who said the task") for m in lexicon.SOMEONE_SAID_RE.finditer(text)]
    text = lexicon.SOMEONE_SAID_RE.sub("", text)
    text = lexicon.rewrite(lexicon.GOAL_FRAME_REWRITES, text)
    text = lexicon.rewrite(lexicon.HEADING_SENTENCE_REWRITES, text)
    if re.search(r"\bpyramids?\b", text):  # "pyramid: an orange and a pink cube side by side, and a white cube resting on both"
        text = re.sub(rf"(?P<base>(?:(?:an?|one|the|2)\s+)?(?:{COLOR_RE})\s+(?:and\s+(?:an?\s+|the\s+)?(?:{COLOR_RE})\s+)?(?:cubes?|blocks?)"
                      rf"|2\s+(?:{COLOR_RE})\s+(?:cubes|blocks))\s+(?:next\s+to\s+each\s+other|side\s+by\s+side|on\s+the\s+table)\s*,?\s*(?:and\s+|with\s+)?"
                      rf"(?P<top>(?:an?|one|the|1)\s+(?:{COLOR_RE})\s+(?:cube|block))\s+(?:(?:resting|sitting|balanced|placed|lying)\s+)?"
                      r"on\s+(?:top\s+of\s+)?(?:both(?:\s+of\s+them)?|2|them|the\s+2|the\s+pair)\b",
                      r"\g<base> on the bottom and \g<top> on top", text)
    text = lexicon.rewrite(lexicon.PLACEMENT_WISH_REWRITES, text)
    text = lexicon.POLITE_CONDITION_RE.sub(" ", text)
    text = lexicon.PREAMBLE_RE.sub("", text).strip()
    asked_by += [(m.group("what"), "what the task is for") for m in lexicon.PURPOSE_RE.finditer(text)]
    text = lexicon.PURPOSE_RE.sub("", text)
    text = lexicon.STEP_MARKER_RE.sub("", text)
    text = lexicon.ARROW_COLOUR_RE.sub(r"the \1 cube in the ", text)
    text = lexicon.ARROW_RE.sub(r"\1 in the ", text)
    text = lexicon.ARROW_PATCH_RE.sub(r"put the \1 cube on the ", text)
    spelled = ({w.lower() for w in re.findall(r"\b[A-Z]{2,}\b", original)} - lexicon.CAPS_NEVER_SPELLED) | {  # "spell BOOK": a word
        w.lower() for w in re.findall(r"(?i:\b(?:spell(?:s|ing)?|reads?|word)\s+(?:the\s+word\s+)?)([A-Z]{2,})\b", original)}
    text = lexicon.ROBOT_VIEWPOINT_RE.sub("", text)  # "From the robot's point of view, ...": rpg's own frame
    text = lexicon.FRONT_GLOSS_RE.sub(r"\g<r>", text)  # "at the front of the table, near the robot": the front once
    text = lexicon.means_said(text)  # "clear X by putting Y ...": put Y
    text = lexicon.FINDING_IS_TAKING_RE.sub("take ", text)  # "find the A, B and T blocks and spell ...": taking them
    text = lexicon.CAUSED_MOTION_RE.sub(lambda m: _caused_motion(m, asked_by), text)  # "taxi the yellow cube to the back ..."
    text = bottom_up_roles(ordinal_roles(text))  # "the first cube is white, the second black, ...": listed (before "the
    # first cube" is refused)
    refused = [(kind, ws, why) for kind, ws, why in _inexpressible(text)
               if not all(w in spelled for w in ws)]  # refused below, with what the unknown words say as well
    text = lexicon.FRAMING_RE.sub("", text)
    text = lexicon.CLOSING_RE.sub("", text)
    text = lexicon.EPISODE_END_RE.sub("", text)
    text = lexicon.EVAL_LOGISTICS_RE.sub("", text).strip()
    text = lexicon.rewrite(lexicon.ROBOT_SUBJECT_REWRITES, text)
    for pattern, full in lexicon.CONTRACTIONS:
        text = re.sub(pattern, full, text)
    text = lexicon.BLK_RE.sub(lambda m: "black" if m.group("black") is not None else m.group("arrowed") + "black"
                              if m.group("arrowed") is not None else "block" + m.group("block"), text)
    text = _SYNONYM_RE.sub(lambda m: lexicon.SYNONYMS[m.group(0)], text)
    text = lexicon.ONE_IN_EACH_RE.sub(lambda m: f"a {m.group('s')[:-1]} of {m.group('n')} {m.group('a')} cubes and a "
                                      f"{m.group('s')[:-1]} of {m.group('n')} {m.group('b')} cubes", text)  # "reds in one, ..."
    text = lexicon.COLOUR_PLURAL_RE.sub(r"the \1 ones", text)  # "reds at the bottom"
    text = lexicon.TEXTURED_RE.sub(lambda m: f"the {m.group('c')} block" if m.group("c") in COLORS else m.group(0), text)
    text = lexicon.rewrite(lexicon.NOTATION_REWRITES, text)
    text = repeated_indefinites(other_of_a_colour(text))  # "a grey cube on the blue patch and a grey cube on the red patch": two cubes
    if re.search(r"\b(?:walls?|towers?|stacks?)\b", text):  # "yellow down, cyan up", "down row gray gray gray"
        text = lexicon.rewrite(lexicon.UP_DOWN_ROLE_REWRITES, text)
    if re.search(r"\bpyramids?\b", text):  # "Pyramid: bottom row orange, orange, orange; middle row pink, pink; top row cyan."
        text = lexicon.PYRAMID_ROW_RE.sub(r"\1 layer", text)  # a pyramid's rows are its layers
    if re.search(r"\b(?:walls?|pyramids?)\b", text):  # "a pyramid, bottom layer blue blue blue, then red red, then yellow"
        text = layers_said_in_turn(text)
    if re.search(r"\bwalls?\b", text):  # "a two-layer wall with blue on the bottom, three cubes per layer"
        text = lexicon.rewrite(lexicon.WALL_ROW_REWRITES, text)
        text = lexicon.WALL_LAYER_ROLE_RE.sub(lambda m: f"{m.group('where')} layer {m.group('c')}", text)
        text = lexicon.PER_LAYER_RE.sub(_per_layer, text)
    text = _label_tower_roles(_label_tower_steps(text))
    text = lexicon.rewrite(lexicon.WORD_ORDER_REWRITES, text)
    unread = re.search(rf"\bso\s+(?:that\s+)?the\s+(?:tower|stack)\s+(?:is|reads|has|becomes|looks|goes|ends)\b[^.;]*\b(?:{COLOR_RE})\b[^.;]*", text)
    if unread and not lexicon.RESTATED_TOWER_RE.search(text):
        # "put two gray blocks on top so the tower is brown, gray, gray", "... at the bottom so the tower is ...": the
        # tower restated in a way only "put a <colour> cube on top, so the tower reads ..." is read (its cubes had been
        # counted twice)
        raise ParseError(f"'{unread.group(0).strip()}' in \"{original[:80]}\" says the tower again after what is done to it; "
                         "say the tower once, from bottom to top (e.g. \"a tower of brown, green, gray from the bottom\"), or "
                         "use --model")
    restated = lexicon.RESTATED_TOWER_RE.search(text)
    if restated:  # "put a gray block on top so the tower is green, gray, brown": its top is not the cube put there
        raise ParseError(f"'{restated.group(0)}' in \"{original[:80]}\" restates a tower whose top is not the "
                         f"{restated.group('c')} cube put on top; say the tower once, from bottom to top, or use --model")
    two_colours = re.search(rf"\b(?:the|a|an)\s+((?:{COLOR_RE})\s+(?:{COLOR_RE}))\s+(?:block|cube|one)\b(?!s)", text)
    if two_colours and len(set(two_colours.group(1).split())) == 2:  # "put the blue green cube on ...": one cube, two colours
        raise ParseError(f"'{two_colours.group(0)}' in \"{original[:80]}\" names one cube by two colours; say which colour it "
                         "is, or list the cubes (\"the blue and the green cube\"), or use --model")
    text = lexicon.rewrite(lexicon.LOOSE_PHRASE_REWRITES, text)
    text = lexicon.COUNT_THEN_LIST_RE.sub(lexicon.count_then_list, text)  # "three cubes (red, green and blue)": those three
    text = lexicon.COUNTED_RUNS_RE.sub(lexicon.counted_runs_listed, text)  # "3 blue cubes and then 3 white cubes": each cube
    if re.search(r"\b(?:walls?|pyramids?|layers?|\d+x\d+x\d+)\b", text):  # "3 yellow blocks second from the bottom" of a wall:
        text = lexicon.LAYER_FROM_BOTTOM_RE.sub(r"\g<cubes> in the \g<k> layer", text)  # that layer (it had been dropped)
        text = lexicon.layers_said_relatively(text)  # "two white cubes above them", "three blue below, three green above"
    # "... on the green patch and the blue block on the same patch": the one patch named before
    for m in reversed(list(re.finditer(r"\bthe\s+same\s+(?:goal\s+)?(?:patch|pad|mat|tile|area)\b", text))):
        before = {c for c in re.findall(rf"\b({COLOR_RE})\s+(?:goal\s+)?(?:patch|pad|mat|tile|area)\b", text[:m.start()])}
        if len(before) == 1:
            text = text[:m.start()] + f"the {before.pop()} patch" + text[m.end():]
    if re.search(r"\b(?:stack\w*|towers?|columns?)\b", text) and not re.search(r"\b(?:rows?|lines?|line\s+up|circles?|rings?)\b", text):
        # "a tower of red, green and blue, starting with blue", "..., yellow first": the tower's bottom (a fourth cube had
        # been made up; "yellow first" had been dropped as the list's own first, and the list's order freed)
        text = lexicon.TOWER_FIRST_RE.sub(lambda m: f", with the {m.group('c') or m.group('c2')} cube at the bottom", text)
    if re.search(r"\b(?:rows?|lines?|line\s+up|stack\w*|towers?)\b", text):  # "a row of red, blue and green, red first, from left to right"
        said_first = re.search(rf"\s*,\s*(?:with\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s+first\b(?=\s*(?:[,.;!]|$))", text)
        listed_first = re.search(rf"\b({COLOR_RE})\b", text)
        if said_first and listed_first and said_first.start() > listed_first.end():
            if said_first.group(1) != listed_first.group(1):  # another cube first than the list's: which order holds?
                raise ParseError(f"'{said_first.group(1)} first' in \"{original[:80]}\" puts first a cube the list does not "
                                 "start with; say the order once, or use --model")
            text = text[:said_first.start()] + text[said_first.end():]  # said again: the list's first (it had been a 4th cube)
    chained = tower_chain(text)
    if chained == text:
        _refuse_unclear_chain(text, original)
    text = chained
    text = lexicon.rewrite(lexicon.TOP_DOWN_REWRITES, text)
    # "Make a tower. Top: red. Middle: green. Bottom: blue.": each role's cube, whatever order the roles are said in (the
    # colours had been read as a list from the bottom, red at the bottom)
    if re.search(r"\b(?:towers?|stacks?|stacked)\b", text):  # "The cube at the top is orange", "Middle cube must be white."
        text = _role_sentences(text)
    ends = [m.group(1) for m in re.finditer(r"\b(bottom|base|top)\s*[:=]", text)]
    if ends in (["bottom", "top"], ["base", "top"]):
        # "Base: red. Next: white. Top: green.", "Base: red. Second: white. Third: blue. Top: green.": the cubes between
        # the ends in turn (the labels "Next:" had been dropped as headings, the tower's middle with them)
        ordinals = re.findall(r"\b(second|third|fourth|fifth)\s*[:=]", text)
        if ordinals == ["second", "third", "fourth", "fifth"][:len(ordinals)]:
            text = re.sub(rf"\b(?:next|then|after\s+that|second|third|fourth|fifth)\s*[:=]\s*(?=(?:{COLOR_RE})\b)", "then ", text)
    said = list(re.finditer(rf"(?<!\bto\s)\b(top|upper|middle|mid|lower|bottom|base|second|third|fourth|fifth)\s*[:=]\s*"
                            rf"({COLOR_RE})\b(?!\s*,\s*(?:{COLOR_RE}))", text))
    same = {"base": "bottom", "mid": "middle"}
    roles = {same.get(m.group(1), m.group(1)): m.group(2) for m in said}
    if said and re.search(r"\b(?:towers?|stacks?|stacked)\b", text) and set(roles) == {"middle"} and len(said) == 1:
        # "Tower of 3. Middle cube must be white.": that cube in the middle, the others free
        text = text[:said[0].start()] + f"with {roles['middle']} in the middle" + text[said[0].end():]
    elif said and re.search(r"\b(?:towers?|stacks?|stacked)\b", text):
        between = re.fullmatch(rf"\s*(?:(?:cube|block|one)\s*)?[.,;]?\s*((?:(?:and\s+)?then\s+(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s*[.,;]?\s*)+)",
                               text[said[0].end():said[-1].start()])
        after = text[said[-1].end():]
        if re.search(r"\b(?:then|next)\b", after) and said[-1].group(1) == "top":
            # "Base: red. Top: green. Next: white.": a cube said after the top, whose place the roles do not give
            raise ParseError(f"\"{original[:80]}\" says a cube after the tower's top; say the tower from bottom to top once "
                             "(e.g. \"Base: red. Next: white. Top: green.\"), or use --model")
        if len(said) == 2 and between and [same.get(m.group(1), m.group(1)) for m in said] == ["bottom", "top"]:
            # "Bottom: brown. Then orange, then yellow. Top: white.": the cubes said between the ends, in order
            middle = re.findall(rf"\b(?:{COLOR_RE})\b", between.group(1))
            text = text[:said[0].start()] + "from bottom to top: " + ", ".join([roles["bottom"], *middle, roles["top"]]) + text[said[-1].end():]
        else:
            at = {m.start() for m in said}
            stray = next((m for m in re.finditer(rf"\b([a-z0-9]+)\s*[:=]\s*(?:{COLOR_RE})\b", text[said[0].start():said[-1].end()])
                          if m.start() + said[0].start() not in at), None)
            if stray is None:  # "Next: any": no colour read
                stray = re.search(r"\b(?:then|next)\b[^.;]*", text[said[0].end():said[-1].start()])
            if stray:  # "Top: black. Next: yellow. Base: blue.": a cube between the roles with no place they give
                raise ParseError(f"'{stray.group(0)}' in \"{original[:80]}\" names a cube between the tower's roles with no place "
                                 "among them; say the tower from bottom to top (e.g. \"Base: blue. Next: yellow. Top: black.\"), "
                                 "or use --model")
            orders = (("bottom", "top"), ("bottom", "middle", "top"), ("bottom", "lower", "upper", "top"))
            order = next((o for o in orders if set(o) == set(roles)), None)
            if order is None or len(said) != len(roles):  # "top=orange, middle=white" (no bottom), "second=white": which order?
                raise ParseError(f"the roles said in \"{original[:80]}\" ({', '.join(m.group(0) for m in said)}) do not give every cube "
                                 "of the tower one place; say top and bottom (and middle), or list the order (e.g. \"from bottom to "
                                 "top: black, white, orange\"), or use --model")
            rest = text[said[-1].end():]
            other = re.search(rf"\b[a-z]+\s*[:=]\s*(?:{COLOR_RE})\b", rest)
            if other:  # "top=orange, middle=white, bottom=black, extra=red": a cube of no place (it had gone on top)
                raise ParseError(f"'{other.group(0)}' in \"{original[:80]}\" names a cube with no place in the tower its roles "
                                 "say; say where it goes, or use --model")
            n = rf"(\d+|{lexicon.COUNT_WORD_RE})"  # number words are not yet digits here
            count = re.search(rf"\b(?:towers?|stacks?)\s+of\s+{n}\b|\b{n}[\s-]+(?:blocks?|cubes?)?[\s-]*(?:tall|high)\b", text)
            if order == ("bottom", "top") and count and _count(count.group(1) or count.group(2)) > 2:
                # "Tower of 3. Base: gray. Top: yellow.": the ends given, the cubes between them free
                text = text[:said[0].start()] + f"with {roles['bottom']} at the bottom and {roles['top']} on top" + rest
            else:
                text = text[:said[0].start()] + "from bottom to top: " + ", ".join(roles[r] for r in order) + rest
    if not re.search(r"\b(?:pyramids?|walls?)\b", text) or re.search(r"\b(?:towers?|stack\w*|columns?)\b", text):  # a pyramid's
        # "the base is blue, blue, green" is its bottom layer (a tower "by the wall" keeps its list from the top)
        text = lexicon.rewrite(lexicon.TOP_LIST_REWRITES, text)
    if re.search(r"\b(?:rows?|lines?|line\s+up)\b", text):
        text = lexicon.rewrite(lexicon.ROW_ROLE_REWRITES, text)
        # "the first is white, the last is black, and the two in the middle are gray": read before "last" is refused
        text = _ROLE_CLAUSES_RE.sub(lambda m: _role_clauses(m) if re.search(r"\b(?:first|last)\b", m.group(0)) else m.group(0), text)
    text = lexicon.END_ROLE_WORD_RE.sub(lambda m: f" with the {m.group('c')} cube "
                                        + ("at the bottom" if m.group("w") in ("lowest", "bottommost") else "on top"), text)
    lone = lexicon.LONE_ORDINAL_ROLE_RE.search(text)
    if lone and strict and not re.search(r"\b(?:last|final|middle)\b", text) \
            and (len(re.findall(r"\b(?:first|second|third|fourth|fifth|sixth)\b", text)) == 1 or not re.search(r"\bfirst\b", text)):  # "stack three cubes; the third is red": counted
        # from which end? (the rank had been dropped; with a last, a middle or other ranks said, the role readers read or refuse
        # it, naming it)
        raise ParseError(f"'{lone.group(0)}' in \"{original[:80]}\" gives a cube a place by its rank, and the rest of the structure "
                         "is not said in that order; say the whole order (e.g. \"from bottom to top: blue, green, red\") or the "
                         "end it stands at (\"with red on top\"), or use --model")
    inner = lexicon.INNER_POSITION_RE.search(text)
    if inner:
        raise ParseError(f"'{inner.group('c')} {inner.group('w')}' in \"{original[:80]}\" places a cube inside the structure by its "
                         "rank from an end, which the builtin parser reads only as part of the whole order said role by role; "
                         "list the whole order (e.g. \"from bottom to top: blue, red, green\"), or use --model")
    for pattern, written in lexicon.PLACE_REWRITES:  # patches, pairs, the table's centre and sides
        text = pattern.sub(written, text)
    text = lexicon.REGION_ANTECEDENT_RE.sub(  # "the red cube in the center and the blue cube to its left": left of red
        lambda m: (m.group(0)[:m.start("pro") - m.start()]
                   + (f"to the {m.group('side')} of the {m.group('c')} cube" if m.group("side") else f"the {m.group('c')} cube")),
        text)
    centred = re.search(r"\bcent(?:er|r)ed\b", text)
    if centred:  # "a centered stack of red, blue and green", "..., centered": centred where? (it was dropped)
        raise ParseError(f"'centered' in \"{original[:80]}\" does not say where the centre is for the builtin parser; say "
                         "\"in the center of the table\" after the structure (e.g. \"build a tower of red and blue in the "
                         "center of the table\"), or use --model")
    text = lexicon.rewrite(lexicon.FAR_APART_REWRITES, text)
    text = _compass(text)
    text = lexicon.rewrite(lexicon.RELATION_SIDE_REWRITES, text)
    text = lexicon.POSTURE_RE.sub("", text)
    text = _counted_list_nouns(text)
    text = lexicon.rewrite(lexicon.EDGE_AND_EACH_REWRITES, text)
    # "on the left side and the blue block on the right side of the table": each side the table's
    for part in ("side", "half", "edge"):  # "... to the left half of the table and the white cube to the right half"
        # "on the left side and ... on the right side": the table's two sides (both said, neither of a cube)
        bare = {m.group(1) for m in re.finditer(rf"\bthe\s+(left|right|front|back)\s+{part}\b(?!\s+of\b)", text)}
        if re.search(rf"\b{part}s?\s+of\s+the\s+(?:table|workspace)\b", text) or bare in ({"left", "right"}, {"front", "back"}):
            text = re.sub(rf"\b(on|at|to|in|into|near|along)\s+the\s+(left|right|front|back)\s+{part}\b(?!\s+of\b)",
                          rf"\1 the \2 {part} of the table", text)
    # "put the red cube at the front and the blue cube at the back": two cubes, each at one of two opposite sides
    said = rf"\b((?:the|a)\s+(?:{COLOR_RE})\s+(?:cube|block)\s+(?:at|on|to|in)\s+the)\s+(left|right|front|back)(?![\w-])(?!\s+(?:of|side|half|edge|end|corner|part|left|right)\b)"
    if {m.group(2) for m in re.finditer(said, text)} == {"front", "back"} and len(re.findall(said, text)) == 2:
        # (bare "on the left ... on the right" stays a relation between the two cubes, the weaker reading)
        text = re.sub(said, r"\1 \2 of the table", text)
    # "with yellow as the base": a cube of that colour at that end (read as a tower of yellow cubes)
    # "with red on top": a cube at that end, the one already named when its colour was ("a red cube, ... with red on top")
    text = re.sub(rf"\bwith\s+({COLOR_RE})\s+(as|at|on)\s+(the\s+)?(base|bottom|top)\b(?!\s+(?:layer|row|level|tier|course|floor)s?\b)",
                  _end_cube, text)  # ("with red on the bottom layer": the whole layer, read by the pyramid's reader)
    text = lexicon.LAYER_SYNONYM_RE.sub(lambda m: "bottom " if m.group("low") else "top ", text)
    # "the green one goes in between" (a middle left unnamed): in the middle
    if re.search(r"\b(?:stack|stacked|tower|towers|stacks)\b", text):
        text = lexicon.rewrite(lexicon.TOWER_BETWEEN_REWRITES, text)
        text = lexicon.rewrite(lexicon.TOWER_MORE_REWRITES, text)
    text = lexicon.rewrite(lexicon.PATCH_CENTRE_AND_START_REWRITES, text)
    first = re.search(rf"\b(?:{COLOR_RE})\b", text)  # "... starting with red on the left": red first, left to right
    text = lexicon.END_SIDE_RE.sub(lambda m: f"{m.group('verb')} with {m.group('c')} from {lexicon.END_SIDE_DIRECTION[m.group('side')]}"
                                   if first and first.group(0) == m.group("c") else m.group(0), text)
    text = lexicon.START_SIDE_RE.sub(lambda m: f"from {lexicon.END_SIDE_DIRECTION[m.group('side')]}", text)
    text = lexicon.PILE_ON_RE.sub("stack ", text)
    text = lexicon.TOTAL_RE.sub(lambda m: f"{m.group(1)} {m.group(2) or 'blocks'}" if m.group(1) else "", text)
    text = lexicon.rewrite(lexicon.LANDMARK_REWRITES, text)
    if re.search(r"\b(?:line|lines|row|rows|order|sort\w*|spell\w*|reads?|ascending|descending|increasing|decreasing)\b", text):
        # "in increasing order from left", "spell it from the right": the reading direction, its far end unsaid
        text = lexicon.rewrite(lexicon.READING_END_REWRITES, text)
    text = lexicon.rewrite(lexicon.PLEASE_REWRITES, text)
    text = " ".join(w for w in re.split(r"(?<=\S)\s+(?=\S)", text)
                    if re.sub(r"[.,;:!?]+$", "", w) not in IGNORABLE_HERE)
    text = re.sub(r"\s+([.,;:!?])", r"\1", text)
    unknown = []
    caps = set(spelled)
    caps |= {q.lower() for q in re.findall(r"'([A-Za-z]+)'", text)}
    words = re.findall(r"[a-z][a-z\-]*|\d+x\d+(?:x\d+)?|\d+|'[^']*'|[+=*]", text)
    fixed = {}
    for w in words:
        if w.startswith("'") or w[0].isdigit() or w in "+=*" or w in NUMBER_WORDS or w in COLORS:
            continue
        base = w[:-1] if w.endswith("s") and w[:-1] in VOCAB else w
        if base in VOCAB or len(w) == 1 or w in caps:
            continue
        if "-" in w and all(p in VOCAB or p in COLORS or p in NUMBER_WORDS for p in w.split("-") if p):
            continue
        lemma = next((x for x in lexicon.lemmas(w) if x in VOCAB or x in lexicon.PLACEMENT_VERBS), None)
        if lemma is None and w.startswith("un"):  # "unstacking" -> unstack (lemminflect knows only "stacking")
            lemma = next((f"un{x}" for x in lexicon.lemmas(w[2:]) if f"un{x}" in VOCAB), None)
        if lemma is not None:  # an inflection of a known word: "built" -> build, "constructs" -> build
            fixed[w] = lemma if lemma in VOCAB else lexicon.PLACEMENT_VERBS[lemma]
            continue
        slot = re.search(rf"(?<![\w-]){re.escape(w)}\s+(?:cubes?|blocks?|bricks?|patch(?:es)?|ones?|goal\s+patch)\b"
                         rf"|(?<![\w-]){re.escape(w)}\s*,\s*(?:{COLOR_RE})\b|\b(?:{COLOR_RE})\s*,\s*{re.escape(w)}(?![\w-])", text)
        if slot and len(w) >= 3:  # "the wite cube", "cian, blue": a colour's slot, so a colour or nothing ("write", "can" before)
            match = _transposition(w) or process.extractOne(w, COLORS, scorer=fuzz.ratio, score_cutoff=72)
            match = match if match and match[0] in COLORS else None
        else:
            match = _transposition(w) or (process.extractOne(w, list(VOCAB) + COLORS, scorer=fuzz.ratio, score_cutoff=84)
                                           if len(w) >= 4 else None)  # "purpel", "rigth": two letters swapped
        if match and lexicon.is_dictionary_word(w) and not w.startswith(match[0]):
            match = None  # a real word is never "corrected" into another ("bring" is not "ring"); "vertically" -> "vertical"
        if match and match[0] in lexicon.PLACE_WORDS and w.startswith(match[0]) and w[len(match[0]):] not in ("", "s", "es", "ly", "ed", "d", "ing"):
            match = None  # nor a word that only begins with a place word ("righto" is not "right": a place had been read)
        if match and w.endswith(match[0]) and w[:len(w) - len(match[0])] in ("un", "dis", "non", "re", "de", "mis"):
            match = None  # nor stripped of a prefix that changes it ("unstacking" is not "stacking", "restack" not "stack")
        if match:
            fixed[w] = match[0]
        else:
            unknown.append(w)
    dropped = list(asked_by)
    named = {w for _, ws, _ in refused for w in ws}
    for w in dict.fromkeys(unknown):
        read = senses.sense(w)
        if read.kind in _KIND_WHY and strict:
            if w not in named:
                like = f" ('{w}' reads like '{read.like}')" if read.like != w else ""
                refused.append((read.kind, [w], _KIND_WHY[read.kind] + like))
            dropped.append((w, read.like))  # refused for its class: no longer an unknown word
        elif read.kind == "ignorable" and not re.search(rf"(?<![\w-]){re.escape(w)}\s+(?:(?:{COLOR_RE})\s+)?(?:blocks?|cubes?|ones?"
                                                        rf"|boxes|box|patch(?:es)?|{COLOR_RE})\b", text):
            dropped.append((w, read.like))  # never one that describes a cube ("the swift block")
    if dropped:
        gone = {w for w, _ in dropped}
        unknown = [w for w in unknown if w not in gone]
        text = " ".join(w for w in text.split(" ") if re.sub(r"[.,;:!?]+$", "", w) not in gone)
    if unknown and strict:  # a sentence that says nothing of the task ("My supervisor wants this for the demo."): dropped
        sentences = re.split(r"(?<=[.!?;])\s+", text)
        idle = [t for t in sentences if _idle_sentence(t, set(unknown))]
        if idle and len(idle) < len(sentences):
            gone = {w for t in idle for w in re.findall(r"[a-z][a-z\-]*", t)}
            dropped += [(w, "a sentence with nothing of the task") for w in dict.fromkeys(unknown) if w in gone]
            unknown = [w for w in unknown if w not in gone]
            text = " ".join(t for t in sentences if t not in idle)
    if unknown and strict:
        refused += [(kind, [w], why) for w, kind, why in _unknown_word_classes(text, list(dict.fromkeys(unknown)))
                    if w not in named]
    if unknown and not refused:  # issue 30, item 3: other words are ignored and listed in accounting
        gone = {w for w in unknown if ignorable_unknown(w, text)}
        tokens = re.findall(r"[a-z][a-z\-]*", text)
        if 3 * sum(t in gone for t in tokens) > len(tokens):
            gone = set()  # a third of the text or more unread: nothing is ignored, the words are named instead
        if gone:
            dropped += [(w, "a word outside the lexicon") for w in dict.fromkeys(unknown) if w in gone]
            unknown = [w for w in unknown if w not in gone]
            text = " ".join(w for w in text.split(" ") if re.sub(r"[.,;:!?]+$", "", w) not in gone)
    idle = lexicon.IDLE_REQUEST_RE.search(original.lower())
    if idle and strict and not lexicon.GOAL_WORD_RE.search(original.lower()) and not color_mentions(text) \
            and not re.search(r"\b\d\b|\b[A-Z]\b", original):  # "Just look at the blocks for a moment.", "Hello robot."
        raise Inexpressible("no_goal", [idle.group(0)], "asks nothing of the cubes, so there is no goal: a task's goal "
                            "says where cubes end up; say where a cube should go (e.g. \"put the red block on the blue "
                            "patch\")", original)
    if refused:
        raise Inexpressible.of(refused, original)
    if unknown and strict:
        shown = ", ".join(f"'{w}'" for w in dict.fromkeys(unknown))
        raise ParseError(
            f"could not parse {shown} in \"{original[:80]}\"; the builtin parser reads the block domain "
            "(colors, letters, digits, stacks, lines, circles, grids, pyramids, piles, patches, relations). "
            "Rephrase, or use --model to let a language model read it"
        )
    _refuse_unresolved_pronoun(text, original)
    same = re.search(r"\bthe\s+same\s+(?:goal\s+)?patch\b", text)
    if same and not re.search(rf"\b(?:{COLOR_RE})\s+(?:goal\s+)?patch\b", text[:same.start()]):
        # "... and the green cube on the same patch": the same as which? (a patch of a colour nobody said had been made up)
        raise ParseError(f"'{same.group(0)}' in \"{original[:80]}\" refers to a patch the instruction has not named before it; "
                         "name the patch's colour (e.g. \"on the blue patch\"), or use --model")
    run_on = _CHAIN_RUN_ON_RE.search(text)
    if run_on:  # "orange over yellow over blue purple over red": blue over purple, or a bluish purple?
        raise ParseError(f"'{run_on.group('pair')}' in \"{original[:80]}\" names two colours with nothing between them "
                         f"inside a chain of cubes: say '{run_on.group('a')} {run_on.group('rel')} {run_on.group('b')}' "
                         f"or '{run_on.group('a')} and {run_on.group('b')}', or use --model")
    for w, r in fixed.items():
        text = re.sub(rf"\b{re.escape(w)}\b", r, text)
    for m in re.finditer(r"\b(?:the|a|an)\s+([a-z]{2,})\s+(?:cube|block|brick)\b", text):
        w = m.group(1)  # "put the pick cube on the white cube": a cube set apart by a word that is no colour, among coloured ones
        if strict and w in VOCAB and w not in COLORS and w not in lexicon.CUBE_MODIFIERS and w not in NUMBER_WORDS \
                and w not in lexicon.IGNORABLE | lexicon.IGNORABLE_MORE \
                and re.search(rf"\b(?:{COLOR_RE})\s+(?:cube|block|brick)\b", text):  # ("the wooden block": a filler, no colour said)
            raise ParseError(f"'{m.group(0)}' in \"{original[:80]}\": '{w}' stands where a cube's colour or label does, but is "
                             "neither; name the colour (e.g. \"the white cube\"), or use --model")
    text = lexicon.rewrite(lexicon.STRUCTURE_NOUN_REWRITES, text)
    text = lexicon.ANOTHER_STRUCTURE_RE.sub(lexicon.another_structure, text)  # "a tower of ... and another one of ..."
    # a map's "top left corner" is the far one (the robot at the bottom edge; lexicon's compass)
    gapped = re.search(rf"\b(?:in\s+front\s+of|behind|(?:to\s+the\s+)?(?:left|right)\s+of|next\s+to|beside|on\s+top\s+of|onto|under"
                       rf"|near|far\s+from)\s+and\s+(?:the\s+)?(?:{COLOR_RE})\b", text)
    if gapped:  # "red in front of and green to the right of the blue cube": the first relation's cube said only at the end
        raise ParseError(f"'{gapped.group(0)}' in \"{original[:80]}\" leaves a relation without its cube until the end of a "
                         "second one; say each relation with its cube (e.g. \"the red cube in front of the blue cube and the "
                         "green cube to the right of the blue cube\"), or use --model")
    diagonal = re.search(r"\b(?:top|bottom|upper|lower|front|back|rear)[\s-]+(?:left|right)\s+(?:side\s+)?of\s+"
                         r"(?!(?:the\s+)?(?:table|workspace)\b)(?:the\s+)?[a-z]+", text)
    if diagonal:  # "to the top left of the blue block": two relations at once, or a corner of the cube?
        raise ParseError(f"'{diagonal.group(0)}' names a diagonal of a cube, which rpg's relations do not have (each holds "
                         "along one axis): say one relation (\"left of\", \"behind\")")
    text = lexicon.rewrite(lexicon.MAP_WORD_REWRITES, text)
    if not re.search(r"\b(?:towers?|stacks?|stacked|stacking|piles?|columns?|pyramids?|walls?|on\s+top|layers?|levels?)\b", text):
        # "move all the red blocks to the bottom", with no tower to have a bottom: the near side of the map, the front
        text = lexicon.rewrite(lexicon.MAP_TOP_REWRITES, text)
    text = lexicon.rewrite(lexicon.LABEL_CUBE_REWRITES, text)
    for m in reversed(list(lexicon.BOTH_OF_THEM_RE.finditer(text))):  # "... far from both of them": the cubes before
        named = [c for c in dict.fromkeys(re.findall(rf"\b({COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?patch)", text[:m.start()]))
                 if c != (m.group("c") or m.group("c2"))]
        if len(named) < 2 or (len(named) > 2 and not re.search(r"\ball\b", m.group(0))):
            raise ParseError(f"'{m.group(0)}' in \"{original[:80]}\" does not say which cubes ({len(named)} other colours are "
                             "named before it); name them (e.g. \"far from the red and the blue blocks\")")
        text = text[:m.start()] + " and ".join(f"{m.group('subj')} {m.group('rel')} the {c} block" for c in named) + text[m.end():]
    for m in reversed(list(THE_PATCH_RE.finditer(text))):  # "... far from that patch": the one patch named before
        before = list(dict.fromkeys(re.findall(rf"\b({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|square|area)\b",
                                               text[:m.start()])))
        if len(before) > 1:
            raise ParseError(f"'{m.group(0)}' in \"{original[:80]}\" does not say which patch ({', '.join(before)} are "
                             "named before it); say its colour (e.g. \"the green patch\")")
        if before:
            text = f"{text[:m.start()]}{m.group(1)} {before[0]} patch{text[m.end():]}"
    late = LATE_REVERSAL_RE.search(text)
    if late:  # "Stack red on blue. Vice versa.": a later sentence takes back the order said before
        raise ParseError(f"'{late.group('said').strip()}' in \"{original[:80]}\" turns around what the sentence before it "
                         "said; say the final order once (e.g. \"stack blue on red\"), or use --model")
    for m in re.finditer(r"\b(?:the\s+(?:two|2)|both(?:\s+(?:of\s+)?the)?)\s+(?:goal\s+|target\s+)?patches\b", text):
        if not re.search(r"\bbetween\s+$", text[:m.start()]) and re.search(
                rf"\b(?:{COLOR_RE})\s+(?:goal\s+|target\s+)?patch\b", text[:m.start()]):
            raise ParseError(f"'{m.group(0)}' in \"{original[:80]}\" relates a cube to two patches at once; say one "
                             "patch (e.g. \"behind the green patch\"), or use --model")
    for m in reversed(list(THE_TWO_PATCHES_RE.finditer(text))):  # "between the two patches": the two named before
        before = list(dict.fromkeys(re.findall(rf"\b({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|square|area)\b",
                                               text[:m.start()])))
        if len(before) == 2:
            text = f"{text[:m.start()]}the {before[0]} patch and the {before[1]} patch{text[m.end():]}"
    for m in reversed(list(lexicon.BETWEEN_THEM_RE.finditer(text))):  # "red left of blue ... a green cube between them"
        said = re.findall(rf"\b({COLOR_RE})\s+(?:cube|block|one)\b(?!\s+patch)", text[:m.start()])
        before = list(dict.fromkeys(said[:-1]))  # the cube said last is the one put between them
        if len(before) == 2 and said[-1] not in before:  # the two cubes named before it (with more, which two is not
            # said: left as it is, refused)
            text = f"{text[:m.start()]}between the {before[0]} cube and the {before[1]} cube{text[m.end():]}"
    for pattern, written_out in lexicon.DISTRIBUTED_RELATIONS:
        text = pattern.sub(written_out, text)
    text = lexicon.COLOUR_GROUP_NOUN_RE.sub(r"the 2 \g<c> blocks", text)  # "the orange pair": the 2 orange blocks
    text = lexicon.COMPOUND_NUMBER_RE.sub(lexicon.compound_number, lexicon.LARGE_NUMBER_RE.sub("", text))
    for w, n in NUMBER_WORDS.items():
        text = re.sub(rf"\b{w}\b", str(n), text)
    many = re.search(r"\b(\d+)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b", text)
    if many and int(many.group(1)) > C.MAX_OBJECTS:  # "a tower of one thousand cubes"
        raise Inexpressible("quantity", [many.group(0)], f"asks for {many.group(1)} cubes, a quantity no task holds (at most "
                            f"{C.MAX_OBJECTS} cubes); use fewer cubes", original)
    bare = lexicon.BARE_NUMBERS_RE.search(text)
    if bare and not LABEL_CUBES_SAID_RE.search(original) and not re.search(r"(?i)\b(?:label\w*|numbered|digits?|numbers?)\b", original):  # "put 5 and 8 in a row": four coloured cubes had been made
        raise ParseError(f"'{bare.group('nums')}' in \"{original[:80]}\" may count cubes or name digit cubes; say which "
                         "(e.g. \"the digit cubes 5 and 8\" or \"5 red cubes\"), or use --model")
    text = lexicon.rewrite(lexicon.SPELLING_REWRITES, text)
    text = lexicon.COUNT_BREAKDOWN_RE.sub(_count_breakdown, text)  # "4 cubes on the yellow patch: 2 red and 2 blue"
    text = lexicon.WHICH_PLACE_RE.sub(r"\g<cube>, and \g<cube> is \g<place>", text)  # "..., which should be in the center"
    text = lexicon.COLOUR_SPOT_RE.sub(r"\1 patch", text)  # "the yellow spot": a goal patch
    # "put the red and green cubes on the blue cube": the blue cube at the bottom, the two above in any order (red had
    # been demanded under green)
    text = lexicon.PAIR_ON_CUBE_RE.sub(r"stack the \g<a>, \g<b> and \g<c> blocks with the \g<c> block at the bottom", text)
    text = lexicon.ONE_ON_ANOTHER_RE.sub("stack 2 blocks", text)  # "put one cube on top of another": two, either on top
    if re.search(r"\b(?:towers?|stacks?|stacked|columns?)\b", text):  # "the 3 in the middle are gray": all 3 (a row reads it)
        text = lexicon.MIDDLE_GROUP_COLOUR_RE.sub(r"\g<head> \g<n> \g<c>", text)
    return " ".join(_structure_phrases(" ".join(text.split())).split()), original, dropped


def _count_breakdown(m: re.Match) -> str:
    """Cubes counted, then said by colour after a colon (:data:`lexicon.COUNT_BREAKDOWN_RE`): the groups in the count's
    place when they add up to it ("4 cubes on the yellow patch: 2 red and 2 blue" -> "2 red cubes and 2 blue cubes on the
    yellow patch"; the groups had been read as more cubes); as written otherwise (refused by the accounting)."""
    groups = re.findall(rf"(\d+)\s+({COLOR_RE})", m.group("groups"))
    if sum(int(n) for n, _ in groups) != int(m.group("n")):
        return m.group(0)
    noun = m.group("noun")
    return " and ".join(f"{n} {c} {noun}" for n, c in groups) + m.group("rest")


_GROUP = rf"(?P<n{{i}}>\d+)\s+(?P<c{{i}}>{COLOR_RE})(?:\s+(?:blocks|cubes))?"


_LIST2 = rf"(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+"
"""A list of two or more colours ("red, red, red", "red and blue")."""


@dataclass(frozen=True)
class Rewrite:
    """One rewrite of :data:`STRUCTURE_PHRASES`: ``pattern`` replaced by ``replacement`` (a
    template or a function of the match), only in a text that describes a tower when
    ``tower_only`` (a pyramid's or a wall's "base" is a layer, not one cube)."""

    pattern: re.Pattern
    replacement: str | Callable[[re.Match], str]
    tower_only: bool = False


_TOWER_TEXT_RE = re.compile(rf"\b(?:stack|stacked|{TOWER_NOUNS})\b")
_OTHER_STRUCTURE_RE = re.compile(r"\b(?:pyramid|wall|grid|square|row|line|circle|ring)s?\b")


_ROLES = {"below": 0, "beneath": 0, "underneath": 0, "under": 0, "bottom": 0, "lowest": 0, "base": 0,
          "middle": 1, "between": 1, "centre": 1, "center": 1,
          "above": 2, "over": 2, "top": 2, "highest": 2, "topmost": 2}
"""A role said before its cube in a tower ("below red, in the middle blue, above green") ->
its rank from the table (bottom 0, middle 1, top 2)."""
_ROLE_FIRST = (r"(?:at\s+the\s+|on\s+the\s+|in\s+the\s+|in\s+|on\s+)?(?P<r{i}>" + "|".join(_ROLES) + r")\s*(?:is\s+|:\s*|-\s*)?"
               rf"(?:the\s+)?(?P<c{{i}}>{COLOR_RE})(?:\s+(?:block|cube|one))?\b")


def _roles_first(m: re.Match) -> str:
    """"below red, in the middle blue, above green" -> "from bottom to top: red, blue, green"
    (two or three roles, each rank once); the words as they were otherwise."""
    said = [(_ROLES[m.group(f"r{i}")], m.group(f"c{i}")) for i in (1, 2, 3) if m.group(f"r{i}")]
    ranks = [r for r, _ in said]
    if len(set(ranks)) != len(ranks) or not {0, 2} <= set(ranks):
        return m.group(0)
    return "from bottom to top: " + ", ".join(c for _, c in sorted(said))


_ROLE_SENTENCE_RE = re.compile(
    rf"\b(?:the\s+)?(?:(?:cube|block|one)\s+(?:at|on)\s+the\s+(?:very\s+)?(?P<r1>top|bottom|base)|(?P<r2>top|bottom|middle|base)\s+(?:cube|block|one))"
    rf"\s+(?:is|must\s+be|should\s+be|has\s+to\s+be|will\s+be)\s+(?:the\s+|a\s+|an\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\b"
    rf"(?!\s+(?:or|and)\s+(?:the\s+)?(?:{COLOR_RE}))")
"""A tower's end or middle cube said as a sentence ("The cube at the top is orange", "Middle cube must be white"):
read as "top: orange" (:func:`normalize_words`'s roles)."""
_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth")
_ORDINAL_WORD = {"1st": "first", "2nd": "second", "3rd": "third", "4th": "fourth", "5th": "fifth", "6th": "sixth"}
_ORDINAL_ITEM_RE = re.compile(
    r"\bthe\s+(?P<o>first|second|third|fourth|fifth|sixth|1st|2nd|3rd|4th|5th|6th|last|final)"
    r"(?:\s+(?:cube|block|one))?(?:\s+of\s+the\s+(?P<s>tower|stack|row|line))?(?:\s*\((?P<p>[^()]{1,40})\))?"
    r"(?:\s+(?:is|should\s+be|must\s+be|will\s+be))?\s+(?:the\s+|a\s+)?(?P<c>" + COLOR_RE + r")(?:\s+(?:cube|block|one))?(?:\s+again)?\b")
_ORDINAL_SEP_RE = re.compile(r"\s*(?:,\s*(?:and\s+)?|;\s*|\s+and\s+)")
_COUNTING_FROM_RE = re.compile(r"\s*,?\s*(?:counting|counted|going)\s+from\s+the\s+(bottom|top|left|right)(?:\s+up|\s+down)?\b")


def bottom_up_roles(text: str) -> str:
    """A tower said cube by cube from its bottom (:data:`lexicon.BOTTOM_UP_ROLES_RE`: "the bottom cube should be grey, the
    second one black, the third one white and the top one red") -> "build a tower from bottom to top: gray, black, white,
    red" ("from bottom to top: ..." where a tower was said before).  Left as written unless the ordinals count on from
    "second" without a gap (then "the third one" is refused as a cube picked by an order nobody defined)."""
    m = lexicon.BOTTOM_UP_ROLES_RE.search(text)
    if m is None or re.search(r"\b(?:towers|stacks|columns|piles?|rows?|lines?|pyramids?|walls?|circles?|rings?|grids?)\b", text):
        return text  # another structure, or several towers: which one "the bottom cube" is of is not said
    ordinals = re.findall(r"\b(second|third|fourth|fifth|sixth|next)\b", m.group("mid"))
    if not m.group("mid") or re.search(r"\b(?:between|middle|rest|others?|remaining|second|third|fourth|next|\d+|tower|stack|top|above|over|upon|onto"
                                       r"|on|under|below|beneath|bottom|add\w*)\b",
                                       text[m.end():]):
        return text  # no cube between its ends said (other rules read the two ends), or more said after it
    if any(o not in (w, "next") for o, w in zip(ordinals, _ORDINALS[1:], strict=False)):
        return text
    colours = [m.group("c1"), *re.findall(rf"\b(?:{COLOR_RE})\b", m.group("mid")), m.group("cn")]
    said = re.search(r"\b(?:tower|stack|column|pile)\b", text[:m.start()])
    return f"{text[:m.start()]}{'' if said else 'build a tower '}from bottom to top: {', '.join(colours)}{text[m.end():]}"


def ordinal_roles(text: str) -> str:
    """A tower or row said cube by cube by ordinals ("the first cube is white, the second black, the third white, the
    last black"; "the first block of the tower (the bottom one) is purple, the second is pink and the third is purple
    again"; "row of three, left to right: the first block is white, the second is black, ...") -> its colours listed in
    that order ("white, black, white, black"), with the direction the words give: a tower's first cube is its bottom
    unless "counting from the top" or "(the top one)" says otherwise; a row's direction must be said ("left to right")
    and is kept where it is.  Left as written unless the ordinals run first, second, ... with no gap (a last one may
    end the run) and one structure is said; a row with no direction is left (and refused)."""
    items, end = [], None
    for m in _ORDINAL_ITEM_RE.finditer(text):
        if items and not _ORDINAL_SEP_RE.fullmatch(text[end:m.start()]):
            break
        items.append(m)
        end = m.end()
    if len(items) < 2:
        return text
    said = [_ORDINAL_WORD.get(m.group("o"), m.group("o")) for m in items]
    last = said[-1] in ("last", "final")
    tail = _COUNTING_FROM_RE.sub("", text[items[-1].end():])
    if said[:len(said) - last] != list(_ORDINALS[:len(said) - last]) or (last and len(said) < 3) or re.search(
            r"\b(?:middle|between|rest|others?|remaining|second|third|fourth|fifth|last|next|final|penultimate|top|bottom)\b", tail) \
            or re.search(r"\bthe\s+(?:top|topmost|bottom|lowest|highest)\b", _COUNTING_FROM_RE.sub("", re.sub(r"\([^()]*\)", "", text))):
        return text  # (a gap, "the first ..., the last ..." with the cubes between said otherwise: other rules read it)
    nouns = set(re.findall(r"\b(tower|stack|row|line|column)s?\b", text))
    tower = nouns <= {"tower", "stack", "column"} and bool(nouns)
    if len(nouns) != 1 and not (tower and len(nouns) == 2 and nouns <= {"tower", "stack"}):
        return text  # no structure, or two: which one the ordinals count is not said
    counting = _COUNTING_FROM_RE.search(text)
    ends = {e for e in [*re.findall(r"\b(bottom|top|left|right|front|back)\b", items[0].group("p") or ""),
                        counting.group(1) if counting else None] if e}
    direction = re.search(r"\b(left|right|front|back)\s+to\s+(?:the\s+)?(?:left|right|front|back)\b", text)
    if len(ends) > 1 or (tower and ends - {"bottom", "top"}) or (not tower and (not direction or ends - {direction.group(1)})):
        return text  # the first cube's end said twice apart, a tower counted from a side, a row's first end not said or
        # not the end its direction starts from: left as written (refused)
    top_down = ends == {"top"}
    colors = [m.group("c") for m in items]
    listed = ", ".join(colors)
    if tower:
        listed = f"from {'top to bottom' if top_down else 'bottom to top'}: {listed}"
    head = text[:items[0].start()]
    if items[0].group("s") and not re.search(r"\b(?:tower|stack|row|line|column)s?\b", head):
        head = f"{head}the {items[0].group('s')} "  # "the first block of the tower ... is purple": the tower said there
        if not tower:
            listed = f"in a row: {listed}"
    out = f"{head}{listed}{text[items[-1].end():]}"
    return _COUNTING_FROM_RE.sub("", out)


def _role_sentences(text: str) -> str:
    """A tower's two ends, or its middle alone, each said as a sentence (:data:`_ROLE_SENTENCE_RE`) -> "top: orange"
    and "bottom: purple" (or "middle: white"), which the roles of :func:`normalize_words` read; left as written when
    other cubes are placed too ("the two in between are green", "the second from the bottom"), which other rules read."""
    said = [(m.group("r1") or m.group("r2")).replace("base", "bottom") for m in _ROLE_SENTENCE_RE.finditer(text)]
    if sorted(said) == ["bottom", "top"]:
        others = r"\b(?:between|rest|second|third|middle|others?)\b"
    elif said == ["middle"]:
        others = r"\b(?:top|bottom|base|topmost|between|second|third)\b"
    else:
        return text
    out = _ROLE_SENTENCE_RE.sub(lambda m: f"{(m.group('r1') or m.group('r2')).replace('base', 'bottom')}: {m.group('c')}", text)
    return text if re.search(others, out) else out


_CHAIN_CUBE = rf"(?:{COLOR_RE}|(?:letter\s+[a-z]|digit\s+\d)(?=\s+(?:cube|block)\b))"
"""One cube of a tower said cube by cube (:func:`tower_chain`): a colour, or a label cube as the text is read ("the digit 5
block": the block marked 5)."""
_CHAIN_REF = rf"(?:the\s+)?(?P<{{g}}>{_CHAIN_CUBE})(?:\s+(?:cube|block|one))?"
_CHAIN_ROLES = (
    ("above", r"(?:(?:directly|right|just|immediately)\s+)?(?:on|onto|on\s+top\s+of|above|over|atop|upon)\s+(?:it|that|this)(?:\s+one)?"),
    ("below", r"(?:(?:directly|right|just|immediately)\s+)?(?:below|under|underneath|beneath)\s+(?:it|that|this)(?:\s+one)?"),
    ("on", r"(?:(?:directly|right|just|immediately)\s+)?(?:on|onto|on\s+top\s+of|atop|upon)\s+" + _CHAIN_REF.format(g="on_ref")
     + r"|(?:directly|right|just|immediately)\s+(?:above|over)\s+" + _CHAIN_REF.format(g="on_ref2")),
    ("under", r"(?:directly|right|just|immediately)\s+(?:below|under|underneath|beneath)\s+" + _CHAIN_REF.format(g="under_ref")),
    ("higher", r"(?:above|over|higher\s+than)\s+" + _CHAIN_REF.format(g="higher_ref")),
    ("lower", r"(?:below|under|underneath|beneath|lower\s+than)\s+" + _CHAIN_REF.format(g="lower_ref")),
    ("bottom", r"down|(?:at|on|in)\s+the\s+(?:very\s+)?(?:bottom|base)|as\s+the\s+(?:base|bottom)|(?:at|on)\s+the\s+table|first"),
    ("top", r"(?:at|on)\s+the\s+(?:very\s+)?top|on\s+top|as\s+the\s+top"),
    ("middle", r"in\s+the\s+middle"),
)
"""Where one cube of a tower said cube by cube goes (:func:`tower_chain`): on or under the cube said before (or the first
cube said: "it"), on or under a cube named ("directly above the blue one"), anywhere above or below one ("above blue"),
at an end, or in the middle."""
_CHAIN_ITEM_RE = re.compile(
    rf"(?:(?:first(?:ly)?,?|then|and|also|next|finally|lastly|after\s+that,?|afterwards,?)\s+)*(?:(?:put|place|set|stack|add|leave|lay)\s+)?(?:(?:a|an|the|another|1|(?:the\s+)?(?P<n>\d+|two|three|four|five|six|both))\s+)?"
    rf"(?P<c>{_CHAIN_CUBE})(?:\s+(?:blocks?|cubes?|bricks?|ones?))?\s+(?:(?:is|are|goes|go|sits|sit|should\s+be|must\s+be|comes|stands)\s+)?"
    rf"(?:(?:stacked|placed|resting|sitting|standing)\s+)?"
    r"(?P<role>" + "|".join(f"(?P<{k}>{r})" for k, r in _CHAIN_ROLES) + r")")
_CHAIN_SEP_RE = re.compile(r"\s*(?:,\s*(?:and\s+)?(?:then\s+|with\s+)?|;\s*|\s+and\s+(?:then\s+)?|\s+then\s+|\s+with\s+)")
_CHAIN_HEAD_RE = re.compile(
    rf"(?:(?:please|now|puzzle\s*:)\s+)*(?:(?:make|build|create|form|construct|stack|assemble|(?:i|we)\s+(?:want|need)"
    rf"|(?:i|we)\s+would\s+like)\s+(?:a|an|1)\s+(?P<noun>{TOWER_NOUNS})"
    rf"(?:\s+(?:of|from|with|out\s+of|using)\s+(?:(?P<count>\d+|{lexicon.COUNT_WORD_RE})(?:\s+(?:blocks|cubes|bricks))?"
    rf"|(?:the\s+)?(?P<set>(?:{COLOR_RE})(?:\s*,\s*(?:{COLOR_RE}))*\s*,?\s+and\s+(?:{COLOR_RE}))\s+(?:cubes|blocks|bricks)"
    rf"(?P<where>\s+on\s+the\s+(?:{COLOR_RE})\s+(?:goal\s+)?patch)?))?"
    r"|(?:stack|arrange|order)\s+(?:the|these|all\s+the)\s+(?:cubes|blocks)"
    # a tower declared: "the tower should be: red at the bottom, blue above it, ..." (another reader had put every cube
    # "above it"/"above that" above the first one, and ordered the rest at will, silently)
    rf"|(?:a|an|one)\s+(?:{TOWER_NOUNS})(?=\s*:)"  # "a tower: red at the bottom, ..." (a goal's frame dropped before it)
    rf"|^\s*(?:a|an|one)\s+(?:{TOWER_NOUNS})(?=\s+with\b|\s*,\s*(?:{COLOR_RE})\b)"  # "A tower with blue at the bottom, green
    # above it, ...", "A tower, blue at the base and ...": a text that is the tower
    rf"|the\s+(?:final\s+|finished\s+|goal\s+|target\s+)?(?:{TOWER_NOUNS})\s+(?:should|must|will|has\s+to|needs\s+to)\s+(?:be|look\s+like)"
    rf"|(?:it|this|the\s+(?:goal|result|final\s+state|end\s+state|target))\s+(?:should\s+be|must\s+be|is)\s+(?:a|an|one)\s+(?:{TOWER_NOUNS}))"
    r"\s*(?:with|so\s+that|such\s+that|where|in\s+which|:|,|-|(?<=\bbe)(?=\s))\s*")
_CHAIN_RELATIVE = {"on": +1, "under": -1, "higher": +1, "lower": -1}
"""A role by a cube named -> the side of it the cube stands (+1 above)."""


def _count(word: str) -> int:
    """A count said in digits or a number word ("3", "three", "both"): :func:`lexicon.count_word`."""
    return lexicon.count_word(word)


_AFTER_IT_RE = re.compile(r"\b(?:above|over|on|onto|atop|upon|on\s+top\s+of|below|under|beneath|underneath)\s+(?:it|that|this)\b")
_TOPPED_THEN_PLACED_RE = re.compile(
    rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:goes|sits|is|stands|comes)\s+)?(?:on|at)\s+(?:the\s+)?(?:very\s+)?top\s*,\s*"
    r"(?:and\s+)?(?:next|left|right|behind|in|on|at|near|far|close|beside|between|by|away|toward|towards|along|opposite"
    r"|touching)\b")


def _refuse_unclear_chain(text: str, original: str) -> None:
    """Refuse a chain :func:`tower_chain` did not take whole that other readers would read silently wrong.

    Raises:
        ParseError: two cubes placed in turn on "it"/"that" in one sentence with more said around them ("the tower: red
            at the bottom, blue above it, green above that, on the patch": another reader had put each above the first
            cube and ordered them at will); a cube on top of a chain with a place said after it ("put red on blue, then
            green on top, next to yellow": of the cube or the tower? the top had been dropped, the place given to the cube).
    """
    said_after = max((_AFTER_IT_RE.findall(sentence) for sentence in re.split(r"[.!?;]", text)), key=len)
    if len(said_after) >= 2:
        raise ParseError(f"\"{original[:80]}\" places cubes in turn on the one said before "
                         f"({', '.join(repr(w) for w in said_after[:2])}) with more said around them; say the tower from "
                         "bottom to top in a sentence of its own (e.g. \"build a tower from bottom to top: red, blue, green\"), "
                         "or use --model")
    topped = _TOPPED_THEN_PLACED_RE.search(text)
    if topped and re.search(rf"\b(?:on|onto|upon|atop)\s+(?:the\s+)?(?:{COLOR_RE})\b", text[:topped.start()]):
        raise ParseError(f"\"{original[:80]}\" puts a cube on top and says a place after it ('{topped.group(0)}'): of that "
                         "cube or of the whole tower? Say the place in a sentence of its own (e.g. \"... Put the tower next to "
                         "the yellow block.\"), or use --model")


def tower_chain(text: str) -> str:
    """A tower said cube by cube, each cube's place by an end, by the cube said before or by a cube named ("put a green
    cube down, a white cube on it, and another green cube on top of that"; "a stack of 3 cubes with the red one in the
    middle, a blue one below it and a green one above it"; "a tower of the red, blue and yellow cubes so that red is
    directly above blue and yellow is at the very bottom") -> "build a tower from bottom to top: ...".  "it" may stand
    for the cube said just before or the first cube said: the text is rewritten only when every reading that places
    each cube once gives one order (and the tower's count or listed cubes, if said, are the cubes placed), and the
    whole text is the tower (nothing else said); otherwise it is returned as it is."""
    body = text.strip().rstrip(".!").strip()
    head = _CHAIN_HEAD_RE.match(body)
    rest = body[head.end():] if head else body
    items, pos = [], 0
    while pos < len(rest):
        m = _CHAIN_ITEM_RE.match(rest, pos)
        if m is None:
            return text
        if not m.group("n") and re.search(r"\b(?:blocks|cubes|bricks|ones)\b", m.group(0)):
            return text  # "the red cubes at the bottom": how many is not said (one had been taken)
        role = next(k for k, _ in _CHAIN_ROLES if m.group(k))
        ref = next((m.group(g) for g in ("on_ref", "on_ref2", "under_ref", "higher_ref", "lower_ref") if m.group(g)), None)
        if any(c == m.group("c") for c, _, _, _ in items) and not re.match(r"(?:(?:then|and|also|next|finally|lastly|after\s+that,?"
                                                                            r"|afterwards,?)\s+)*(?:(?:put|place|set|stack|add|leave|lay)\s+)?"
                                                                            r"(?:another|an?|1)\s", m.group(0)):
            return text  # "the green cube" said again: the same cube in two places
        if role in ("above", "below") and re.search(r"\bit\s*$", m.group(0)) and items and items[-1][3]:
            return text  # "red on the blue block, then green on it": red or blue? (not said)
        items.append((m.group("c"), _count(m.group("n") or "1"), role, ref))
        pos = m.end()
        sep = _CHAIN_SEP_RE.match(rest, pos)
        if pos < len(rest) and sep is None:
            return text
        pos = sep.end() if sep else pos
    roles = {r for _, _, r, _ in items}  # a bottom, a middle and a top said: a tower's, whatever names it
    if not items or not (head or roles & {"above", "below"} or roles >= {"bottom", "middle", "top"}) \
            or (len(items) < 2 and not (head and head.group("set"))):
        return text
    if any(n > 1 and role not in ("above", "bottom") for _, n, role, _ in items):
        return text
    listed = re.findall(rf"\b(?:{COLOR_RE})\b", head.group("set")) if head and head.group("set") else None
    if listed is not None:  # the cubes listed; each said one a different one of them
        said = [c for c, n, _, _ in items for _ in range(n)]
        if len(set(listed)) != len(listed) or len(set(said)) != len(said) or not set(said) <= set(listed):
            return text
        cubes = [(c, next((role for ic, _, role, _ in items if ic == c), None), 0) for c in listed]
        refs = {c: r for c, _, _, r in items}
        previous = {c: items[i - 1][0] for i, (c, _, _, _) in enumerate(items) if i}
        first = items[0][0]
    else:
        cubes = [(c, role if j == 0 else ("above" if role in ("above", "bottom") else role), j) for c, n, role, _ in items for j in range(n)]
        refs = {k: r for k, (c, n, role, r) in enumerate(x for x in items for _ in range(x[1]))}
        said = {c for c, _, _ in cubes}
        cubes += [(r, None, 0) for r in dict.fromkeys(r for r in refs.values() if r and r not in said)]  # "pink on the orange cube"
        previous, first = None, None
    total = len(cubes)
    if (head and head.group("count") and _count(head.group("count")) != total) or total > 6:
        return text
    colour_at = {c: k for k, (c, _, _) in enumerate(cubes)}
    if any(r is not None and (r not in colour_at or list(c for c, _, _ in cubes).count(r) != 1) for r in refs.values()):
        return text  # a cube named that the tower does not have once
    orders = set()
    for to_first in (False, True):  # "it": the cube said just before, or the first cube said
        for perm in itertools.permutations(range(total)):
            at = {k: perm.index(k) for k in range(total)}  # cube k stands at height at[k]
            ok = True
            for k, (c, role, j) in enumerate(cubes):
                if role is None:
                    continue
                if listed is not None:
                    ref = colour_at.get(refs.get(c)) if refs.get(c) else (colour_at[first] if to_first else colour_at.get(previous.get(c)))
                    pronoun_ok = c in previous
                else:
                    ref = colour_at[refs[k]] if refs.get(k) else (None if k == 0 else k - 1 if j or not to_first else 0)
                    pronoun_ok = k > 0
                if role in ("higher", "lower"):
                    side = _CHAIN_RELATIVE[role]
                    if ref is None or (at[k] - at[ref]) * side <= 0:
                        ok = False
                        break
                    continue
                want = {"bottom": 0, "top": total - 1, "middle": total // 2 if total % 2 else None,
                        "above": at[ref] + 1 if pronoun_ok and ref is not None else None,
                        "below": at[ref] - 1 if pronoun_ok and ref is not None else None,
                        "on": at[ref] + 1 if ref is not None else None, "under": at[ref] - 1 if ref is not None else None}[role]
                if want is None or at[k] != want:
                    ok = False
                    break
            if ok:
                orders.add(tuple(cubes[k][0] for k in perm))
    if len(orders) != 1:
        return text
    where = head.group("where") if head and head.group("set") else None
    return "build a tower from bottom to top: " + ", ".join(orders.pop()) + (f",{where}" if where else "") + "."


_LAYER_LIST = rf"(?:{COLOR_RE})(?:(?:\s*,\s*|\s+)(?:{COLOR_RE}))*"
_THEN_LAYERS_RE = re.compile(rf"\b(?:bottom|base|lowest|first)\s+(?P<noun>layer|row|level|tier|course)\s*:?\s*(?:of\s+)?(?P<l0>{_LAYER_LIST})"
                             + "".join(rf"(?:\s*,?\s*(?:and\s+)?then\s+(?P<l{i}>{_LAYER_LIST}))" + ("" if i == 1 else "?") for i in (1, 2, 3))
                             + r"(?=\s*(?:[,.;!]|$))")
_BASE_OF_ONES_RE = re.compile(rf"\bbase\s+of\s+(?P<list>(?:a|an)\s+(?:{COLOR_RE})\s+and\s+)(?:a|an)\s+(?P<last>{COLOR_RE})\s+(?:block|cube)\b"
                              rf"(?!\s*,?\s*(?:and\s+)?(?:a|an|the)\s+(?:{COLOR_RE})\s+(?:block|cube|one)\b)")
"""A base of two single cubes with one noun ("a base of a cyan and a brown block"); three or more are left to the
layer readers (a third cube said after them had been moved to the top)."""
_LAYER_NAMES = {2: ("bottom", "top"), 3: ("bottom", "middle", "top"), 4: ("bottom", "second", "third", "top")}


def layers_said_in_turn(text: str) -> str:
    """A pyramid's or wall's layers listed from the bottom with "then" ("bottom layer blue blue blue, then red red,
    then yellow") -> each layer named ("bottom layer blue blue blue, middle layer red red, top layer yellow"); a base
    of single cubes with one noun at the end ("a base of a cyan and a brown block") -> each with its own ("a base of a
    cyan block and a brown block").  Other text is returned as it is."""
    def named(m: re.Match) -> str:
        layers = [m.group(f"l{i}") for i in range(4) if m.group(f"l{i}")]
        return ", ".join(f"{role} {m.group('noun')} {layer}" for role, layer in zip(_LAYER_NAMES[len(layers)], layers, strict=True))

    def ones(m: re.Match) -> str:
        colours = re.findall(rf"\b(?:{COLOR_RE})\b", m.group("list")) + [m.group("last")]
        said = [f"a {c} block" for c in colours]
        return "base of " + ", ".join(said[:-1]) + " and " + said[-1]
    return _BASE_OF_ONES_RE.sub(ones, _THEN_LAYERS_RE.sub(named, text))


_END_WORDS = {"bottom": "bottom", "lowest": "bottom", "lower": "bottom", "bottommost": "bottom", "top": "top", "highest": "top",
              "upper": "top", "topmost": "top", "left": "left", "leftmost": "left", "right": "right", "rightmost": "right",
              "first": "first", "last": "last"}
_ROLE_BE = r"(?:(?:is|are|being|should\s+be|must\s+be|has\s+to\s+be|will\s+be)\s+)?"
"""The verb of a role clause, or none ("the leftmost cube should be black, the rightmost brown")."""
_ROLE_NOUN = r"(?:\s+(?:one|ones|1|blocks?|cubes?|layers?|levels?|floors?|tiers?))?"
"""The noun of a role ("the bottom one", "bottom layer", "the middle two cubes"), or none ("bottom purple")."""


def _role_clause(named: bool) -> str:
    """One role clause: an end ("the bottom one is blue", "top layer yellow"), the middle ("the middle one yellow",
    "middle two layer both white", "the 2 in between are green"); with ``named`` groups end, n and c."""
    g = (lambda name: f"?P<{name}>") if named else (lambda name: "?:")
    return (rf"(?:the\s+)?(?:({g('end')}{'|'.join(_END_WORDS)}){_ROLE_NOUN}|({g('n')}\d+|{lexicon.COUNT_WORD_RE})\s+(?:in\s+between|in\s+the\s+middle"
            rf"|between\s+them)|middle(?:\s+({g('mn')}\d+){_ROLE_NOUN}(?:\s+(?:both|all|\d+))?|{_ROLE_NOUN})|({g('nm')}\d+)\s+middle"
            rf"{_ROLE_NOUN})\s+{_ROLE_BE}({g('c')}{COLOR_RE})\b")


_ROLE_CLAUSE_RE = re.compile(_role_clause(named=True))
_ROLE_CLAUSES_RE = re.compile(rf"\s*[;:,]?\s*(?:with\s+)?{_role_clause(False)}(?:\s*,?\s*(?:and\s+)?{_role_clause(False)}){{2}}")


def _role_clauses(m: re.Match) -> str:
    """"the bottom one is blue, the top one is red and the two in between are green" -> ": from bottom to top: blue,
    green, green, red" (each end once, the middle counted, in any order: "bottom layer purple, top layer yellow,
    middle two layer both white"; "the leftmost is red, the rightmost ..." of a row, left to right); the words as
    they were otherwise."""
    ends: dict[str, str] = {}
    middle: list[str] = []
    for r in _ROLE_CLAUSE_RE.finditer(m.group(0)):
        if r.group("end"):
            if _END_WORDS[r.group("end")] in ends:
                return m.group(0)
            ends[_END_WORDS[r.group("end")]] = r.group("c")
        else:  # "the middle one yellow": one cube between the ends; "the 2 in between", "middle two": that many
            n = r.group("n") or r.group("mn") or r.group("nm") or "1"
            middle += [r.group("c")] * int(lexicon.NUMBER_WORDS.get(n, n))
    axis = next((pair for pair in (("bottom", "top"), ("left", "right"), ("first", "last")) if set(ends) == set(pair)), None)
    if axis is None or not middle:
        return m.group(0)
    if axis == ("first", "last"):  # "the first is white, the last is black": in the direction said, where one is
        return ": " + ", ".join([ends["first"], *middle, ends["last"]]) if lexicon.DIRECTION_SAID_RE.search(m.string) else m.group(0)
    if axis == ("bottom", "top") and re.search(r"\b(?:walls?|pyramids?|grids?|layers|rows|levels|tiers|courses|wide)\b", m.string):
        # a wall's or pyramid's layers ("a wall of three rows: bottom red, middle green, top blue"): each a whole layer's
        # colour (the three had been read as one listed row and the other layers given colours nobody said)
        return m.group(0) if len(middle) != 1 else f": bottom row {ends['bottom']}, middle row {middle[0]}, top row {ends['top']}"
    return f": from {axis[0]} to {axis[1]}: " + ", ".join([ends[axis[0]], *middle, ends[axis[1]]])


_LINE_END = (r"(?:the\s+|an?\s+|1\s+)?(?P<{g}>" + COLOR_RE + r")(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+|sits\s+|stands\s+)?"
             r"(?:(?:on|at|to)\s+the\s+(?:far|very|extreme)\s+(?P<{g}s>left|right)(?:\s+end)?|(?:on|at)\s+the\s+(?P<{g}e>left|right)\s+end"
             r"|(?P<{g}m>left|right)most)")
_LINE_MIDDLE = (r"(?:(?P<n>\d+|" + lexicon.COUNT_WORD_RE + r"|an?|the)\s+)?(?:(?P<m>" + COLOR_RE + r")\b)?(?:\s*\b(?P<noun>cubes?|blocks?|ones?))?"
                r"(?<=\w)\s+(?:in\s+between|between\s+them|in\s+the\s+middle)")
_LINE_ROLES_RE = re.compile(rf"(?:\s*[:;,]\s*|\s+with\s+){_LINE_END.format(g='a')}\s*,?\s+(?:and\s+)?(?:with\s+)?"
                            rf"{_LINE_END.format(g='b')}\s*,?\s+(?:and\s+)?(?:with\s+)?{_LINE_MIDDLE}\b")


def _line_roles(m: re.Match) -> str:
    """"a line of blocks: purple on the far left, cyan on the far right, and two gray blocks in between" -> ": from left to
    right: purple, gray, gray, cyan" (each end once, the middle counted; only of a row or a line: the words as they were
    otherwise, where "the far left" may be the table's)."""
    sides = {k: next(m.group(f"{k}{x}") for x in ("s", "e", "m") if m.group(f"{k}{x}")) for k in ("a", "b")}
    if {sides["a"], sides["b"]} != {"left", "right"} or not re.search(r"\b(?:rows?|lines?|line\s+up|lined)\b", m.string):
        return m.group(0)
    if not m.group("m") and not m.group("noun"):
        return m.group(0)
    if not m.group("n") and (m.group("noun") or "").endswith("s"):
        raise ParseError(f"\"{m.string[:80]}\" puts cubes between the row's ends without saying how many; say the count "
                         "(e.g. \"two gray blocks in between\"), or use --model")  # (a plural had become one cube)
    n = m.group("n") or "1"
    n = 1 if n in ("a", "an", "the") else int(lexicon.NUMBER_WORDS.get(n, n))
    left, right = (m.group("a"), m.group("b")) if sides["a"] == "left" else (m.group("b"), m.group("a"))
    named = {canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.string)}
    middle = m.group("m") or next(c for c in DEFAULT_COLORS if c not in named)  # "two blocks in between": any cubes, one
    return ": from left to right: " + ", ".join([left] + [middle] * n + [right])  # colour so that any of them may stand there


_ROW_END_NAMED_RE = re.compile(
    rf"\b(?P<row>(?:row|line)\s+of\s+(?P<n>\d+)\s+(?:cubes|blocks)|(?P<n2>\d+)\s+(?:cubes|blocks)\s+in\s+(?:a|one)\s+(?:row|line))"
    rf"(?:\s*[,;:]\s*(?:and\s+)?|\s+with\s+)(?:(?:the\s+)?(?:far\s+)?(?P<e>left|right)(?:\s+(?:1|one|block|cube))?\s+"
    rf"(?:is\s+|being\s+|(?:should|must)\s+be\s+)?(?:an?\s+)?(?P<c>{COLOR_RE})(?:\s+(?:1|one|block|cube))?"
    rf"|(?:a|an|the)\s+(?P<c2>{COLOR_RE})\s+(?:block|cube|1|one)\s+(?:on|at)\s+the\s+(?:far\s+)?(?P<e2>left|right)(?:\s+end)?)"
    r"(?=\s*(?:[.;!]|$))")
"""A row of a count with only one end's cube named ("arrange four blocks in a row, the leftmost one cyan", "a row of four
blocks with a cyan block on the far left"): read as that row from left to right, the other cubes of one colour that no
word names, so that any of them may stand in any other place (the end's cube had been counted as the whole row: refused)."""


def _row_end_named(m: re.Match) -> str:
    n = int(m.group("n") or m.group("n2"))
    if n < 2:
        return m.group(0)
    end, color = (m.group("e"), m.group("c")) if m.group("c") else (m.group("e2"), m.group("c2"))
    named = {canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.string)}
    other = next(c for c in DEFAULT_COLORS if c not in named)
    cubes = [color] + [other] * (n - 1) if end == "left" else [other] * (n - 1) + [color]
    return f"{m.group('row')}: from left to right: " + ", ".join(cubes)


_SIDE_OF_MIDDLE = rf"(?:the\s+|an?\s+)?(?P<{{c}}>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+)?(?:on|to)\s+(?:its|the)\s+(?P<{{s}}>left|right)(?:\s+of\s+it)?"
_MIDDLE_AND_SIDES_RE = re.compile(
    rf"\b(?P<row>(?:row|line)(?:\s+of\s+3(?:\s+(?:cubes|blocks))?)?)(?:\s*[,:]\s*|\s+with\s+)(?:the\s+|an?\s+)?(?P<m>{COLOR_RE})(?:\s+(?:cube|block|one))?"
    rf"\s+(?:is\s+)?in\s+the\s+(?:middle|center|centre)\s*,?\s+(?:and\s+|with\s+)?{_SIDE_OF_MIDDLE.format(c='a', s='sa')}\s*,?\s+(?:and\s+)?"
    rf"{_SIDE_OF_MIDDLE.format(c='b', s='sb')}(?=\s*(?:[.;!]|$))")
"""A row of three said by its middle and each side of it ("a row of three with the blue cube in the middle, red on its left
and green on its right"): read as that row from left to right (it had found no task)."""


def _middle_and_sides(m: re.Match) -> str:
    if {m.group("sa"), m.group("sb")} != {"left", "right"}:
        return m.group(0)
    left, right = (m.group("a"), m.group("b")) if m.group("sa") == "left" else (m.group("b"), m.group("a"))
    return f"{m.group('row')}: from left to right: {left}, {m.group('m')}, {right}"


_ONE_CUBE_IN_TOWER_RE = re.compile(
    rf"\b(?P<s>tower|stack|column|row|line|circle|ring)\s+(?:of|(?:should|must|will)\s+be|is)\s+(?P<n>\d+)\s+(?:blocks|cubes)(?:\s+(?:tall|high|long))?\s*,?\s+"
    rf"(?:with\s+(?:a|an|1)\s+(?P<c>{COLOR_RE})\s+(?:block|cube|one)\s+in\s+it|(?:with\s+)?(?:(?:exactly|just|only)\s+)?(?P<k>\d+)\s+of\s+(?:them|which)\s+"
    rf"(?:is\s+|are\s+|being\s+)?(?P<c2>{COLOR_RE}))"
    rf"(?:\s*,?\s*(?:and\s+)?the\s+(?:others|rest|other\s+(?:\d+\s+)?(?:cubes|blocks|ones))\s+(?:are\s+|all\s+|being\s+)*(?P<o>{COLOR_RE}))?"
    rf"(?:\s*,?\s+and\s+(?:a|an|the|1)\s+(?P<e>{COLOR_RE})\s+(?:block|cube|one)\s+(?:(?P<top>on\s+top|at\s+the\s+top)|at\s+the\s+(?:bottom|base)))?"
    r"(?=\s*(?:[.;!]|$))")
"""A tower, row or circle of a count with some cubes of a colour somewhere in it ("the stack should be three blocks tall
with a purple block somewhere in it", "a row of four cubes, two of them purple", "..., one of them purple, the others
red"): those cubes and the others of the colour said or of one colour no word names, in any order (it had found no task,
or made every cube purple)."""


def _one_cube_in_tower(m: re.Match) -> str:
    n, k = int(m.group("n")), int(m.group("k") or 1)
    if n < 2 or k >= n:
        return m.group(0)  # "four cubes, four of them purple": as written (the accounting refuses a count that disagrees)
    named = {canon_color(c) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.string)}
    other = m.group("o") or next(c for c in DEFAULT_COLORS if c not in named)
    color = m.group("c") or m.group("c2")
    if m.group("e"):  # "... and a green block on top": that end said, the rest in any order
        if n - k < 2 or m.group("s") not in ("tower", "stack", "column"):
            return m.group(0)
        end = "on top" if m.group("top") else "at the bottom"
        return (f"{m.group('s')} of {k} {color} blocks, {n - k - 1} {other} blocks and 1 {m.group('e')} block, "
                f"with the {m.group('e')} block {end}, in any order")
    return f"{m.group('s')} of {k} {color} blocks and {n - k} {other} blocks, in any order"


_MIDDLE_OF_ODD_ROW_RE = re.compile(
    rf"\b(?P<s>row|line)\s+of\s+(?P<n>\d+)\s+(?:cubes|blocks)\s*,?\s+(?:with\s+)?(?:the\s+|an?\s+)?(?P<m>{COLOR_RE})(?:\s+(?:cube|block|one))?"
    rf"\s+(?:exactly\s+|right\s+|dead\s+)?in\s+the\s+(?:middle|center|centre)\s*,?\s+and\s+(?:the\s+)?(?:others|rest|other\s+(?:\d+\s+)?"
    rf"(?:cubes|blocks|ones))\s+(?:are\s+|all\s+|being\s+)*(?P<o>{COLOR_RE})\b")
"""A row of an odd count with one cube in its middle and the others one colour ("a row of five cubes with the black cube
exactly in the middle and the others white"): read as that row from left to right."""


def _middle_of_odd_row(m: re.Match) -> str:
    n = int(m.group("n"))
    if n % 2 == 0 or n < 3:
        return m.group(0)  # an even row has no middle cube
    side = [m.group("o")] * (n // 2)
    return f"{m.group('s')} from left to right: " + ", ".join(side + [m.group("m")] + side)


STRUCTURE_PHRASES: tuple[Rewrite, ...] = tuple(Rewrite(*r) for r in (
    # "spell HAT along the back edge, left to right": the reading direction said last goes before the place (the place
    # had been dropped, refused)
    (re.compile(r"\b(spell\s+\S+)\s+((?:on|at|along|in)\s+the\s+(?:front|back|left|right|middle|cent(?:er|re))(?:\s+(?:edge|side|half|part))?"
                r"(?:\s+of\s+the\s+table)?)\s*,?\s*((?:from\s+)?(?:left|right|front|back)\s+to\s+(?:right|left|front|back))(?=\s*(?:[.!;]|$))"),
     r"\1 \3 \2"),
    # "a line: purple on the far left, cyan on the far right, and two gray blocks in between": the ends and the middle
    (_LINE_ROLES_RE, _line_roles),
    (_MIDDLE_OF_ODD_ROW_RE, _middle_of_odd_row),
    (_ROW_END_NAMED_RE, _row_end_named),
    (_MIDDLE_AND_SIDES_RE, _middle_and_sides),
    # "a row of three cubes, one blue on each side of the red one": the sides' colour, then the middle (a green cube had
    # been made up, the order dropped)
    (re.compile(rf"\b(?P<row>(?:row|line)(?:\s+of\s+3(?:\s+(?:cubes|blocks))?)?)\s*(?:[,:]\s*|\s+with\s+)(?:a|an|1)\s+(?P<e>{COLOR_RE})"
                rf"(?:\s+(?:cube|block|one))?\s+on\s+(?:each|either|both)\s+sides?\s+of\s+the\s+(?P<m>{COLOR_RE})\s+(?:cube|block|one)\b"),
     r"\g<row>: from left to right: \g<e>, \g<m>, \g<e>"),
    (_ONE_CUBE_IN_TOWER_RE, _one_cube_in_tower),
    # "stack four cubes; the bottom one is blue, the top one is red and the two in between are green": every cube
    # (the middle's count had reached one cube, the other made up)
    (_ROLE_CLAUSES_RE, _role_clauses),
    # "a line of five: an orange cube in the middle, two brown cubes on each side": the middle, the sides counted (the
    # middle cube had been refused as a place the row does not order)
    # ("a row of five cubes with a black cube in the middle and two white cubes on each side of it": the same)
    (re.compile(rf"\b(?P<row>(?:row|line)\s+of\s+(?P<n>\d+)(?:\s+(?:cubes|blocks))?)(?:\s*[:,]\s*|\s+with\s+)(?:an?\s+|the\s+|1\s+)?(?P<m>{COLOR_RE})"
                rf"(?:\s+(?:cube|block|one))?\s+in\s+the\s+(?:middle|center|centre)\s*,?\s+(?:and\s+|with\s+)*(?P<k>\d+)\s+(?P<e>{COLOR_RE})"
                r"(?:\s+(?:cubes|blocks|ones))?\s+(?:at|on)\s+(?:each|both|either)\s+(?:ends?|sides?)(?:\s+of\s+(?:it|them))?\b"),
     lambda m: (f"{m.group('row')}: from left to right: " + ", ".join([m.group("e")] * int(m.group("k")) + [m.group("m")]
                                                                 + [m.group("e")] * int(m.group("k"))))
     if 2 * int(m.group("k")) + 1 == int(m.group("n")) else m.group(0)),
    # "a row of five: a red cube at each end and three white cubes between them": the ends, the middle counted
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(?:a|an|1|one)\s+({COLOR_RE})\s+(?:cube|block)\s+(?:at|on)\s+(?:each|both|either)\s+ends?\s+"
                rf"and\s+(\d+)\s+({COLOR_RE})\s+(?:cubes|blocks)\s+(?:in\s+)?between(?:\s+(?:them|those))?\b"),
     lambda m: ": from left to right: " + ", ".join([m.group(1)] + [m.group(3)] * int(m.group(2)) + [m.group(1)])),
    # "a row of three: green at each end and red in the middle", "..., red in the middle, green on both ends": the two
    # ends one colour, the middle another (the roles had been dropped: a made-up cube in a row of any order)
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(?:an?\s+|the\s+)?(?P<e>{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?\s+(?:at|on)\s+"
                rf"(?:each|both|either|the\s+two|2)\s+ends?\s*,?\s+(?:and\s+)?(?:an?\s+|the\s+)?(?P<m>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                r"\s+(?:in\s+the\s+(?:middle|center|centre)|in\s+between|between\s+them)\b"),
     r": from left to right: \g<e>, \g<m>, \g<e>"),
    # "put a red cube at each end of a row of three, with a blue cube in between": the ends said before the row
    (re.compile(rf"\b(?:put|place|set)\s+(?:an?\s+|1\s+)?(?P<e>{COLOR_RE})\s+(?:cube|block)\s+(?:at|on)\s+(?:each|both|either)\s+ends?\s+"
                rf"of\s+a\s+(?P<s>row|line)\s+of\s+3\s*,?\s+(?:with|and)\s+(?:put\s+)?(?:an?\s+|the\s+|1\s+)?(?P<m>{COLOR_RE})"
                r"(?:\s+(?:cube|block|one))?\s+(?:in\s+between|between\s+them|in\s+the\s+(?:middle|center|centre))\b"),
     r"make a \g<s> from left to right: \g<e>, \g<m>, \g<e>"),
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(?:an?\s+|the\s+)?(?P<m>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+in\s+the\s+(?:middle|center"
                rf"|centre)\s*,?\s+(?:and\s+)?(?:an?\s+|the\s+|1\s+)?(?P<e>{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?\s+(?:at|on)\s+"
                r"(?:each|both|either|the\s+two|2)\s+(?:ends?|sides?(?:\s+of\s+(?:it|them))?)\b"),
     r": from left to right: \g<e>, \g<m>, \g<e>"),
    # "the black cube goes in the middle of a row of three, with a white block on each side of it": the middle said first
    (re.compile(rf"\b(?:the\s+|an?\s+)?(?P<m>{COLOR_RE})\s+(?:cube|block)\s+(?:goes\s+|is\s+|sits\s+|stands\s+|(?:should|must)\s+be\s+)?"
                r"in\s+the\s+(?:middle|center|centre)\s+of\s+a\s+(?P<s>row|line)\s+of\s+3\s*,?\s+(?:with\s+)?(?:an?|1|one)\s+"
                rf"(?P<e>{COLOR_RE})\s+(?:cube|block)\s+(?:at|on)\s+(?:each|both|either)\s+(?:ends?|sides?)(?:\s+of\s+(?:it|them))?\b"),
     r"make a \g<s> from left to right: \g<e>, \g<m>, \g<e>"),
    # "build a stack of two blue cubes and put the green cube on top", "stack 2 blue cubes with a green one on top", "I'd
    # like a tower of two green cubes with an orange cube on top": the counted cubes, then the one on top (the count had
    # reached only one of them)
    (re.compile(rf"\b(?:(?:(?:build|make|create|form)\s+)?a\s+(?:{TOWER_NOUNS})\s+of|stack)\s+(?:the\s+)?(\d+)\s+({COLOR_RE})\s+(?:blocks|cubes|bricks)"
                r"\s*,?\s+(?:and|with|then)\s+(?:then\s+)?(?:(?:put|place|add|stack|set)\s+)?(?:a|an|the|1)\s+"
                rf"({COLOR_RE})\s+(?:block|cube|brick|one)\s+(?:on\s+top|at\s+the\s+top)(?:\s+of\s+(?:it|them|the\s+(?:stack|tower)))?\b"
                r"(?!\s+of\b)"),  # "... and the pink block on top of each other": no order said; "... on top of the table": elsewhere
     lambda m: "build a tower from bottom to top: " + ", ".join([m.group(2)] * int(m.group(1)) + [m.group(3)]), True),
    # "set a cyan cube on top of two stacked red cubes", "... of two red cubes stacked together", "... under two stacked red
    # cubes", "Goal: the cyan cube on top of two stacked red cubes", "a tower with ...": the counted cubes a tower with that
    # cube on top of it or under it (one of them had been dropped: silently a tower of two)
    (re.compile(rf"(?:\b(?:build|make|create|form)\s+a\s+(?:{TOWER_NOUNS})(?:\s+with\s+|\s*:\s*)|\b(?:set|put|place|stack|add|slide)\s+|(?<![\w\s])\s*|^)"
                rf"(?:(?:a|an|the|1)\s+)?({COLOR_RE})(?:\s+(?:block|cube|brick))?\s+"
                r"(?:(?:is|goes|sits|stands|rests|(?:should|must|will)\s+(?:be|sit|stand|end\s+up)|ends\s+up)\s+)?"
                r"(?:(?P<on>on\s+top\s+of|onto|on|atop)|under(?:neath)?|beneath|below)\s+"
                rf"(?:the\s+)?(\d+)\s+(?:stacked\s+({COLOR_RE})\s+(?:blocks|cubes|bricks)|({COLOR_RE})\s+(?:blocks|cubes|bricks)\s+stacked"
                r"(?:\s+(?:together|up|on\s+(?:top\s+of\s+)?each\s+other|one\s+on\s+(?:top\s+of\s+)?the\s+other))?)\b"
                r"(?!\s*,?\s*(?:and|plus|with|as\s+well\s+as)\b)"  # "... and a blue cube": more cubes, of which tower unsaid
                r"(?P<next>\s*[,;]\s*(?=(?:the|an?)\s))?"),  # "..., the green cube on top of two stacked blue cubes": another
     lambda m: "build a tower from bottom to top: " + ", ".join(  # tower, in a sentence of its own
         [m.group(4) or m.group(5)] * int(m.group(3)) + [m.group(1)] if m.group("on") else [m.group(1)] + [m.group(4) or m.group(5)] * int(m.group(3)))
     + (". " if m.group("next") else ""),
     True),
    # "six cubes in one tower: two red at the bottom, two green in the middle, two blue at the top": three counted groups
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|ones))?\s+(?:at|on|in)\s+the\s+(?:bottom|base)"
                rf"\s*,?\s+(?:and\s+)?(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|ones))?\s+in\s+the\s+(?:middle|center|centre)\s*,?\s+(?:and\s+)?"
                rf"(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|ones))?\s+(?:on\s+top|at\s+the\s+top)\b"),
     lambda m: ": from bottom to top: " + ", ".join([m.group(2)] * int(m.group(1)) + [m.group(4)] * int(m.group(3))
                                                    + [m.group(6)] * int(m.group(5))), True),
    # "tower of three: the top and bottom are both white, the middle one brown": both ends one colour (it had read
    # white, white, brown)
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(?:the\s+)?(?:top\s+and\s+(?:the\s+)?bottom|bottom\s+and\s+(?:the\s+)?top)(?:\s+(?:ones|cubes|blocks))?"
                rf"\s+(?:are\s+|being\s+)?(?:both\s+|2\s+)?({COLOR_RE})\s*,?\s+(?:and\s+)?(?:with\s+)?(?:the\s+)?(?:middle|center|centre)"
                rf"(?:\s+(?:one|1|cube|block))?\s+(?:is\s+|being\s+)?({COLOR_RE})\b"),
     r": from bottom to top: \1, \2, \1", True),
    # "make tower of 3 cubes, white is bottom": a colour given an end with "is"; "tower: red/white/orange, red bottom":
    # a terse end at the clause's close (it had been read as a fourth cube, a second red)
    (re.compile(rf"(?<=[,:;]\s)({COLOR_RE})\s+is\s+(bottom|top|base)\b(?!\s+of\b)"), r"\1 at the \2", True),
    (re.compile(rf"(?<=[,:;]\s)({COLOR_RE})\s+(bottom|top|base)(?=\s*(?:[.,;!)]|$))"), r"\1 at the \2", True),
    # "a tower of four: two green at the bottom and two pink on top": the counted colours from the bottom
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|bricks|ones))?\s+(?:at|on|in)\s+the\s+(?:bottom|base)"
                rf"\s*,?\s+(?:and\s+)?(?:then\s+)?(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|bricks|ones))?\s+(?:on\s+top(?:\s+of\s+them)?"
                r"|at\s+the\s+top|above(?:\s+them)?)\b"),
     lambda m: ": from bottom to top: " + ", ".join([m.group(2)] * int(m.group(1)) + [m.group(4)] * int(m.group(3))), True),
    (re.compile(rf"(?:\s*[:,]\s*|\s+with\s+)(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|bricks|ones))?\s+(?:on\s+top|at\s+the\s+top)"
                rf"\s*,?\s+(?:and\s+)?(\d+)\s+({COLOR_RE})(?:\s+(?:cubes|blocks|bricks|ones))?\s+(?:at|on|in)\s+the\s+(?:bottom|base)"
                r"(?:\s+(?:below|under)\s+them)?\b"),
     lambda m: ": from bottom to top: " + ", ".join([m.group(4)] * int(m.group(3)) + [m.group(2)] * int(m.group(1))), True),
    # "stack the cubes, red at the bottom: red, orange, yellow": the list restates the bottom cube (it had been counted twice)
    (re.compile(rf"(?:\s*,?\s*with\s+|\s*,\s*)(?:(?:a|an|the)\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+the\s+"
                rf"(?:bottom|base)\s*:\s*(?P=c)\b"),
     r" from bottom to top: \g<c>", True),
    # "a wall of two layers: red, red, red below, yellow, yellow, yellow above": each list a layer (the places had been
    # dropped: the colours in any layer)
    (re.compile(rf"(?P<lead>\s*[:,;]\s*)(?P<low>{_LIST2})\s+(?:below|beneath|underneath|(?:at|on)\s+the\s+bottom)\s*[,;]?\s*(?:and\s+)?"
                rf"(?P<high>{_LIST2})\s+(?:above|on\s+top|at\s+the\s+top)\b"),
     r"\g<lead>bottom layer \g<low>; top layer \g<high>"),
    # "put two cubes on top of the purple cube": a tower on it of cubes nobody named (the count had reached one cube)
    (re.compile(rf"\b(?:(?:put|place|stack|set|add)\s+)?([2-5])\s+(?:other\s+|more\s+)?(?:cubes|blocks)(?:\s+of\s+any\s+colou?rs?)?\s+"
                r"(?:(?:go|sit|stand|are|(?:must|should|will|have\s+to)\s+(?:go|be|sit|stand|end\s+up))\s+)?(?:on\s+top\s+of|on|onto|atop)\s+"
                rf"the\s+({COLOR_RE})\s+(?:cube|block)\b"),
     lambda m: f"build a tower of {int(m.group(1)) + 1} cubes with the {m.group(2)} cube at the bottom"),
    # "put one yellow cube on each of the two blue cubes": a two-cube tower on each of them
    (re.compile(rf"\b(?:put|place|set|stack|add)\s+(?:a|an|1)\s+({COLOR_RE})\s+(?:cube|block|brick)\s+(?:on\s+top\s+of|on|onto|atop)\s+"
                rf"(?:each|every)\s+(?:one\s+)?of\s+(?:the\s+)?(\d+)\s+({COLOR_RE})\s+(?:cubes|blocks|bricks)\b"),
     lambda m: f"build {m.group(2)} stacks: " + " and ".join([f"{m.group(1)} on {m.group(3)}"] * int(m.group(2)))),
    # "a tower of five cubes with a red cube at the bottom and four yellow cubes above it": the one, then the counted
    (re.compile(rf"(?:\s+with\s+|\s*:\s*)(?:a|an|the|1)\s+({COLOR_RE})\s+(?:block|cube|brick)\s+(?:at|on)\s+the\s+(?:bottom|base)"
                rf"\s*,?\s+and\s+(\d+)\s+({COLOR_RE})\s+(?:blocks|cubes|bricks)\s+(?:above\s+it|on\s+top(?:\s+of\s+it)?)\b"),
     lambda m: " from bottom to top: " + ", ".join([m.group(1)] + [m.group(3)] * int(m.group(2))), True),
    # "make one tower with the cubes red, white and blue": one tower is a tower (its "1" had been read as the cube count)
    (re.compile(rf"\b(make|build|create|form|construct|stack)\s+1\s+({TOWER_NOUNS})\b(?!\s+(?:and|,))"), r"\1 a \2"),
    # "below red, in the middle blue, above green": each role said before its cube, read from the bottom
    (re.compile(rf"\b{_ROLE_FIRST.format(i=1)}\s*[,;]?\s*(?:and\s+)?{_ROLE_FIRST.format(i=2)}"
                rf"(?:\s*[,;]?\s*(?:and\s+)?{_ROLE_FIRST.format(i=3)})?(?![\w\s]*\b(?:of|on)\b)"), _roles_first, True),
    # "a 4-high white stack", "a 3 block tall cyan tower", "a four-story tower": the count and
    # the colour are the whole tower's ("a green 3-high tower" too)
    (re.compile(rf"\b(a|an|one|1|the)\s+({COLOR_RE})\s+(\d+)\s+{HEIGHT_WORDS}\s+({TOWER_NOUNS})\b"), r"\1 \4 of \3 \2 blocks"),
    (re.compile(rf"\b(a|an|one|1|the)\s+(\d+)\s+{HEIGHT_WORDS}\s+(?:({COLOR_RE})\s+)?({TOWER_NOUNS})\b"
                rf"(?!\s+of\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:on|onto|atop|over|under|below|beneath)\b)"),
     r"\1 \4 of \2 \3 blocks"),  # (not "a 3 block tower of red on yellow": its chain is not the count's colour)
    # "two 3-high towers of green blocks": towers of that height each
    (re.compile(rf"\b(\d+)\s+(\d+)\s+{HEIGHT_WORDS}\s+({TOWER_NOUNS})s\b(?:\s+of\s+({COLOR_RE})\s+(?:blocks|cubes|bricks))?"),
     r"\1 \3s of \2 \4 blocks"),
    # "a tower with 4 levels", "a tower of 5 floors": a tower of that many cubes (the levels had been dropped: two cubes)
    (re.compile(rf"\b({TOWER_NOUNS})\s+(?:with|of|having)\s+(\d+)\s+(?:levels?|layers?|floors?|stor(?:ies|eys)|tiers?)\b"),
     r"\1 of \2 blocks"),
    # "a grid of 2 rows, 3 cubes each", "3 rows and 4 columns": a grid of that many rows of that many cubes
    (re.compile(r"\b(\d+)\s+rows\s*(?:,|with|of|and)?\s*(\d+)\s+(?:cubes|blocks)\s+(?:each|per\s+row|in\s+each(?:\s+row)?)\b"),
     r"\1 rows of \2"),
    (re.compile(r"\b(\d+)\s+rows\s+(?:and|by|x|,)\s*(\d+)\s+columns\b"), r"\1x\2"),
    (re.compile(r"\b(\d+)\s+columns\s+(?:and|by|x|,)\s*(\d+)\s+rows\b"), r"\2x\1"),
    # "a tower of height 4", "a tower with a height of 3 cubes": a tower of that many cubes
    (re.compile(rf"\b({TOWER_NOUNS})\s+(?:of|with)\s+(?:a\s+)?height\s+(?:of\s+)?(\d+)(?:\s+(?:blocks?|cubes?|levels?|layers?))?\b"),
     r"\1 of \2 blocks"),
    # "a tower of gray cubes, 3 high", "stack red cubes 4 tall": the height after the colour is the tower's count (it had
    # been dropped: a tower of two)
    (re.compile(rf"\b({TOWER_NOUNS})\s+of\s+({COLOR_RE})\s+(?:blocks|cubes|bricks)\s*,?\s+(\d+)\s+(?:(?:(?:blocks?|cubes?|levels?|"
                r"stor(?:ies|eys)|tiers?|layers?)\s+)?(?:high|tall)|levels|stor(?:ies|eys)|tiers|layers|floors)\b"), r"\1 of \3 \2 blocks"),
    # "a row of gray cubes, 3 long": the length after the colour is the row's count (a row of four had been made)
    (re.compile(rf"\b(row|line)\s+of\s+({COLOR_RE})\s+(?:blocks|cubes|bricks)\s*,?\s+(\d+)\s+(?:(?:blocks?|cubes?)\s+)?(?:long|across)\b"),
     r"\1 of \3 \2 blocks"),
    (re.compile(rf"\b(stack|pile)\s+(?:the\s+)?({COLOR_RE})\s+(?:blocks|cubes|bricks)\s*,?\s+(\d+)\s+(?:(?:blocks?|cubes?|levels?)\s+)?"
                r"(?:high|tall)\b"), r"\1 \3 \2 blocks"),
    # "a tower 3 blocks high"
    (re.compile(rf"\b({TOWER_NOUNS})\s*,?\s+(\d+)\s+(?:(?:blocks?|cubes?|levels?|stor(?:ies|eys)|tiers?|layers?)\s+)?(?:high|tall)\b"),
     r"\1 of \2 blocks"),
    # "a 4-high tower of yellow blocks", "a tower of height 4 made only of green cubes": the colour
    # after the noun is the whole tower's too
    (re.compile(rf"\b({TOWER_NOUNS})\s+of\s+(\d+)\s+(?:blocks|cubes)\s+(?:(?:made|built)\s+)?(?:(?:only|entirely|solely|just|all|purely)\s+)?"
                rf"(?:out\s+)?of\s+({COLOR_RE})(?:\s+(?:blocks|cubes|bricks))?\b(?!\s*(?:,|and\b|&|then\b)\s*(?:the\s+)?(?:{COLOR_RE})\b)"),
     r"\1 of \2 \3 blocks"),  # (not before a list: "a 3-cube tower of red, green and blue" is one cube of each)
    # "a tower with 5 cubes", "tall tower, six cubes, all of them red", "a tower out of 4 cubes": a tower of that many
    (re.compile(rf"\b({TOWER_NOUNS})\s*(?:,|with|using|from|out\s+of|made\s+(?:of|from|with|out\s+of)|having|containing|consisting\s+of)"
                r"\s+(\d+)\s+(blocks|cubes|bricks)\b"), r"\1 of \2 \3"),
    # "a tower, 3 blocks high, all green", "..., every cube red", "a tower 3 high, green": every cube of it
    (re.compile(rf"\b({TOWER_NOUNS})\s+of\s+(\d+)\s+(?:blocks|cubes)\s*,?\s+(?:all|each|every)(?:\s+(?:one|1|block|cube))?(?:\s+of\s+them)?\s+"
                rf"(?:(?:are|is|being|in)\s+)?({COLOR_RE})\b(?!\s+(?:blocks?|cubes?|patch))(?!\s*,?\s*(?:but|except|save|apart|other|and|plus)\b)"),
     r"\1 of \2 \3 blocks"),
    (re.compile(rf"\b({TOWER_NOUNS})\s+of\s+(\d+)\s+(?:blocks|cubes)\s*,\s*({COLOR_RE})(?=\s*[.!]?\s*$)"), r"\1 of \2 \3 blocks"),
    # "stack the red, green and blue blocks, green in the middle": a role said after a comma (the
    # middle had been read as the table's centre and a fourth cube made)
    (re.compile(rf"\s*,\s*(?:and\s+)?(?:the\s+)?({COLOR_RE})\s+(?:block\s+|cube\s+|one\s+)?(?:(?:is|goes|sits)\s+)?"
                r"(in\s+the\s+middle|on\s+top|(?:at|in)\s+the\s+(?:bottom|top|base))\b(?!\s+of\b)"),
     lambda m: m.group(0) if re.search(rf"\b{m.group(1)}\s*$", m.string[:m.start()])  # "black, black on top": one more
     else f" with {m.group(1)} {m.group(2)}", True),
    # "a tower of four with a red base and a blue top": that cube at that end (a tower only: a
    # pyramid's or a wall's base is a layer)
    (re.compile(rf"\bwith\s+(?:a|an)\s+({COLOR_RE})\s+(top|base|bottom)\b(?!\s+(?:of|layer|row|level|tier))"
                rf"(?:\s+and\s+(?:a|an)\s+({COLOR_RE})\s+(top|base|bottom)\b(?!\s+(?:of|layer|row|level|tier)))?"),
     lambda m: "with " + " and ".join(f"a {c} block at the {'top' if e == 'top' else 'bottom'}"
                                      for c, e in ((m.group(1), m.group(2)), (m.group(3), m.group(4))) if c), True),
    # "a pyramid of three, two black on the bottom ...": the count is the structure's cubes
    (re.compile(rf"\b(pyramid|wall|row|line|circle|ring|{TOWER_NOUNS})\s+of\s+(\d+)(?=\s*(?:[,.;:!]|$|with\b))"), r"\1 of \2 blocks"),
    # "a blue tower of 3 blocks"
    (re.compile(rf"\b(a|an|one|1|the)\s+({COLOR_RE})\s+({TOWER_NOUNS})\s+of\s+(\d+)(?:\s+(?:blocks|cubes))?\b"),
     r"\1 \3 of \4 \2 blocks"),
    # "two towers: one of 2 pink blocks and one of 2 brown": a tower per group
    (re.compile(r"\b\d+\s+(tower|stack|column|pile)s\s*[:,;\-]?\s*(?:one|1)\s+(?=of\s+\d)"), r"1 \1 "),
    (re.compile(rf"\b(?:one|1)\s+({TOWER_NOUNS})\s+of\s+{_GROUP.format(i=1)}\s*,?\s+and\s+(?:one|1|another|the\s+other)"
                rf"(?:\s+{TOWER_NOUNS})?\s+of\s+{_GROUP.format(i=2)}"),
     r"a \1 of \g<n1> \g<c1> blocks and a \1 of \g<n2> \g<c2> blocks"),
    # the cube first, its place in the tower after: "the white cube should be at the top of a three block tower whose
    # bottom cube is gray" is the tower with a white block on top (the white cube had gone into the tower's middle)
    (re.compile(rf"^(?:the\s+)?({COLOR_RE})\s+(?:block|cube)\s+(?:should|must|has\s+to|needs\s+to|will)\s+(?:be|end\s+up|sit)\s+"
                rf"(?:at|on)\s+the\s+(top|bottom)\s+of\s+((?:a|an|one)\s+(?:{TOWER_NOUNS})\s+of\s+\d+\s+(?:blocks|cubes)\b[^.;!?]*)"),
     lambda m: f"build {m.group(3)}{' and' if ' with ' in m.group(3) else ' with'} a {m.group(1)} block "
               f"{'on top' if m.group(2) == 'top' else 'at the bottom'}"),
    # roles said as a clause: "where the yellow one is at the top" is "with the yellow block at the top" (not "is on
    # top of the orange cube": a relation, its cube below said)
    (re.compile(rf"\s*,?\s+(?:where|in\s+which|so\s+that|such\s+that)\s+the\s+({COLOR_RE})\s+(block|cube)\s+"
                rf"(?:is|sits|stands|goes|should\s+be|must\s+be|ends\s+up)\s+(at|on)\s+(?:the\s+)?(top|bottom|base)\b(?!\s+of\b)"),
     r" with the \1 \2 at the \4"),
    # "The green cube must be the bottom one", "..., and the red cube is the top one": a cube given an end (it had been
    # put at the other end)
    (re.compile(rf"(?:\s*[,.;]\s*(?:and\s+)?|\s+(?:with|where|and|in\s+which)\s+)the\s+({COLOR_RE})\s+(?:block|cube|one)\s+"
                r"(?:is|(?:should|must|will|has\s+to|needs\s+to)\s+be)\s+the\s+(?:(top|topmost|highest|uppermost)|bottom|base|lowest|bottommost)"
                r"(?:\s+(?:one|1|block|cube))?\b"),
     lambda m: m.group(0) if len(re.findall(rf"\b{m.group(1)}\b", m.string)) > 1
     else f" with a {m.group(1)} block {'on top' if m.group(2) else 'at the bottom'}"),  # (a colour listed too: left as said)
    # roles: "the top one is white", "the bottom block black", ". The top one is red", "and make the top block red"
    (re.compile(rf"(?:\s*[,.;]\s*(?:and\s+)?|\s+(?:with|where|and|in\s+which)\s+)(?:make\s+(?:sure\s+)?(?:that\s+)?)?the\s+(?:top|topmost|uppermost|highest)"
                rf"(?P<noun>\s+(?:block|cube|one|1))?\s+(?:is\s+|being\s+|(?:should|must|will|has\s+to|needs\s+to)\s+be\s+)?(?P<c>{COLOR_RE})"
                rf"(?P<noun2>\s+(?:block|cube|one|1))?\b"), lambda m: _layer_or_end_cube(m, "on top")),
    (re.compile(rf"(?:\s*[,.;]\s*(?:and\s+)?|\s+(?:with|where|and|in\s+which)\s+)(?:make\s+(?:sure\s+)?(?:that\s+)?)?the\s+(?:bottom|lowest|base|bottommost)"
                rf"(?P<noun>\s+(?:block|cube|one|1))?\s+(?:is\s+|being\s+|(?:should|must|will|has\s+to|needs\s+to)\s+be\s+)?(?P<c>{COLOR_RE})"
                rf"(?P<noun2>\s+(?:block|cube|one|1))?\b"), lambda m: _layer_or_end_cube(m, "at the bottom")),
    # "..., with one cube in between": a middle cube of a colour no word names (it had been dropped: a tower of two)
    (re.compile(r"\b(?:with\s+)?(?:1|a|an)\s+(?:other\s+|more\s+)?(?:cube|block)\s+in\s+the\s+middle\b"),
     lambda m: "with a " + next(c for c in DEFAULT_COLORS if not re.search(rf"\b{c}\b", m.string)) + " block in the middle", True),
    # "... and the middle block is blue": the middle cube's colour (it had been dropped: a tower of two)
    (re.compile(rf"(?:\s*[,.;:]\s*(?:and\s+)?|\s+(?:with|where|and|in\s+which)\s+)(?:make\s+(?:sure\s+)?(?:that\s+)?)?(?:the\s+|(?<=[,;:]\s))(?:middle|center|centre)"
                rf"(?:\s+(?:block|cube|one|1))?\s+(?:is\s+|being\s+|(?:should|must|will|has\s+to|needs\s+to)\s+be\s+)?(?P<c>{COLOR_RE})"
                rf"(?:\s+(?:block|cube|one|1))?\b(?!\s+(?:and|or)\s+(?:{COLOR_RE})\b)"), lambda m: _middle_cube(m), True),
))
"""Ways of describing a tower, rewritten to the form the readers take ("a tower of N <colour>
blocks"): a count or colour before the structure noun is the whole structure's, a group
after "one of" is one tower's, "the top one is white" is the top cube's colour."""


def _middle_cube(m: re.Match) -> str:
    """"... and the middle block is blue" -> " with a blue block in the middle"; said without its article ("build 3-stack,
    middle must be yellow") only where nothing else of the tower is said (another colour, an end, "all": those words
    had been read as more cubes in some order, red at the bottom for "top must be red")."""
    color = m.group("c")
    if not re.search(r"\bthe\s+(?:middle|center|centre)\b", m.group(0)) and (
            {c for c in re.findall(rf"\b({COLOR_RE})\b", m.string)} != {color}
            or re.search(r"\b(?:top|topmost|bottom|base|lowest|highest|all|every|each|first|last|second|third)\b", m.string)):
        return m.group(0)
    return f" with a {color} block in the middle"


def _layer_or_end_cube(m: re.Match, where: str) -> str:
    """"the top one is white" -> " with a white block on top" (``where``); in a pyramid or wall "the base is red" names
    no cube, so it is the whole layer's colour (left as said, which the layer roles read: one red cube had been made)."""
    if not m.group("noun") and not m.group("noun2") and re.search(r"\b(?:pyramid|wall)s?\b", m.string):
        return m.group(0)
    return f" with a {m.group('c')} block {where}"


def _structure_phrases(text: str) -> str:
    tower = bool(_TOWER_TEXT_RE.search(text)) and not _OTHER_STRUCTURE_RE.search(text)
    for rule in STRUCTURE_PHRASES:
        if tower or not rule.tower_only:
            text = rule.pattern.sub(rule.replacement, text)  # an unmatched group (no colour) expands to ""
    return text


def color_mentions(text: str) -> list[tuple[int, str]]:
    """(offset, palette colour) of each colour word of normalised text that names an object
    (not "color order" / "color gradient")."""
    return [(m.start(), canon_color(m.group(0))) for m in re.finditer(rf"\b({COLOR_RE})\b", text)
            if not re.match(r"\s+(order|gradient|sort)", text[m.end():])]


def features(instruction: str) -> Features:
    text, original = normalize(instruction)
    f = Features(text, original)
    f.colors = color_mentions(text)
    f.quoted = re.findall(r"['\u2018\u2019\u201c\u201d\"]([^'\u2018\u2019\u201c\u201d\"]+)['\u2018\u2019\u201c\u201d\"]", original)
    return f


def task_slug(text: str) -> str:
    drop = {"a", "an", "the", "can", "you", "please", "so", "that", "of", "this", "it", "its", "is"}
    words = [w for w in re.findall(r"[a-z0-9]+", text.lower()) if w not in drop]
    slug = ("_".join(words[:7]) or "task").lstrip("0123456789_") or "task"
    if len(words) > 7:
        import hashlib

        slug += "_" + hashlib.sha256(text.strip().encode()).hexdigest()[:6]
    return slug


def features_colors(text: str) -> list[tuple[int, str]]:
    return [(m.start(), canon_color(m.group(0))) for m in re.finditer(rf"\b({COLOR_RE})\b", text)]


def explicit_labels(f: Features) -> list[str]:
    """Labels listed ("A, B, C, D"), given as a range ("A to E", "digits 1 to 5"), or listed each
    as a cube ("the A, the B and the C")."""
    m = re.search(r"\b([A-Z0-9])((?:\s*,\s*(?:and\s+)?[A-Z0-9]|\s+and\s+[A-Z0-9]){2,})\b", f.original)
    m = m if m and "," in m.group(2) else None  # "1, 2, 3 and 4", "A, B, and C"; "A and B and C" is the next rule's
    if not m and f.has("letter", "letters", "number", "numbers", "digit", "digits", "label", "labels", "faces"):
        m = re.search(r"\b([A-Z0-9])((?:(?:\s*,\s*|\s+and\s+|\s*,\s*and\s+)[A-Z0-9]){1,})\b", f.original)
    if not m and f.has("letter", "letters", "number", "numbers", "digit", "digits", "label", "labels"):
        m = re.search(r"(?<![\w-])([A-Z0-9])((?:\s+[A-Z0-9]){2,})(?![\w-])", f.original)  # "digit cubes 4 2 1 3"
    if not m and (SORT_ASKED_RE.search(f.text) or f.has("line", "row", "spell", "stack", "tower")):
        m = re.search(r"(?<![\w-])([A-Z])((?:\s+[A-Z]){2,})(?![\w-])", f.original)  # "line up A B C": capitals are letters
        # (bare digits stay unread: "line 1 2 3" may be a count as well as the digit cubes)
    if m:
        labels = [m.group(1)] + re.findall(r"[A-Z0-9]", m.group(2))
        for other in re.finditer(r"(?<![\w'-])([A-Z0-9])((?:\s*,\s*(?:and\s+)?[A-Z0-9]|\s+and\s+[A-Z0-9]){1,})(?![\w'-])", f.original):
            again = [other.group(1)] + re.findall(r"[A-Z0-9]", other.group(2))
            if sorted(again) == sorted(labels) and again != labels:  # "the A, B and C cubes in a row: C, A, B" (the second
                # order had been dropped)
                raise ParseError(f"\"{f.original[:80]}\" lists the cubes in two different orders ({', '.join(labels)}; "
                                 f"{', '.join(again)}); say the order once (e.g. \"from left to right: {', '.join(again)}\"), or use --model")
        return labels
    r = re.search(r"\b([A-Z]|\d)\s+(?:down\s+|up\s+)?(?:to|through|thru)\s+([A-Z]|\d)\b", f.original)
    if not r and f.has("letter", "letters", "number", "numbers", "digit", "digits", "label", "labels"):
        r = re.search(r"(?<![\w-])([A-Z]|\d)\s*[-\u2013]\s*([A-Z]|\d)\b(?!\s*[-\u2013])", f.original)  # "the digit cubes 0-4"
    if r and r.group(1).isdigit() == r.group(2).isdigit():
        lo, hi = ord(r.group(1)), ord(r.group(2))
        if lo < hi:
            return [chr(c) for c in range(lo, hi + 1)]
        if lo > hi and f.has("letter", "letters", "number", "numbers", "digit", "digits", "label", "labels"):
            return [chr(c) for c in range(lo, hi - 1, -1)]  # "from 9 down to 5"
    listed = re.search(r"\b(?:letter|digit|number)\s+'?([a-z0-9])'?\s+(?:block|cube)"
                       r"((?:(?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:the\s+)?(?:letter|digit|number)\s+'?[a-z0-9]'?\s+(?:block|cube))+)",
                       f.text)
    before = re.sub(r"\bthe\s+$", "", f.text[:listed.start()]) if listed else ""
    if listed and not lexicon.OBJECT_PREPOSITION_BEFORE.search(before):
        # "line up the A, the B and the C": label cubes listed each with its noun (not "between the 2 and the 4")
        return [x.upper() for x in [listed.group(1), *re.findall(r"(?:letter|digit|number)\s+'?([a-z0-9])'?", listed.group(2))]]
    return []


REGION_RE = re.compile(
    r"(?:\b(?:in|at|on|to|into|onto|toward|towards|near|along|by)\s+the\s+|(?:^|(?<=[,;:(.]\s)|(?<=[,;:(]))(?:the\s+)?)"
    r"(?:(?P<far>very|far)\s+(?=(?:front|back|rear|left|right)))?"
    r"(?:(?P<fb>front|back|rear)(?:(?:\s*-\s*|\s+)(?P<lr>left|right|middle|center|centre))?"
    r"|(?P<lr2>left|right|middle|center|centre))"
    r"(?P<part>(?:\s*-?\s*(?:hand\s+)?(?:side|corner|half|part|edge|end|area|region|zone))?)"
    r"(?P<tail>\s+of\s+(?:the\s+)?(?:table|workspace))?(?!\s*of\b)")
"""A place on the table after a preposition ("in the back left corner", "on the right side of
the table"), or said bare at the start of a text or a list item ("Spec: tower of three, back-left
corner; line of three, front of the table"), where :func:`mark_regions` marks it only with a
corner, an edge or "of the table" (a bare "left" stays relative)."""


REGION_GROUP_RE = re.compile(
    r"\b(?:in|at|on|to|into|onto|toward|towards|near|by)\s+(?:the|a|an|any|one)\s+(?P<g>corner|edge)"
    r"(?:\s+of\s+the\s+(?:table|workspace))?(?!\s*of\b)(?![\w-])")
"""A place said without saying which ("at the corner of the table", "near an edge"): a region
group of :data:`constants.REGION_GROUPS`, any of whose members will do."""


CORNER_PAIR_RE = re.compile(
    r"\b(?P<prep>in|at|on|to|into|onto)\s+(?:(?:each|both|either)\s+of\s+)?the\s+(?P<a>(?:front|back|rear|far)\s+(?:left|right))"
    r"(?:\s+corner)?\s+and\s+(?:the\s+)?(?P<b>(?:front|back|rear|far)\s+(?:left|right))\s+corners\b"
    r"(?:\s+of\s+the\s+(?:table|workspace))?")
"""Two corners said with one noun ("in the front left and front right corners"): marked as
two places, each with its own preposition, for :func:`mark_regions`."""


def region_name(front_back: str | None, left_right: str | None) -> str | None:
    """The region (:data:`constants.REGION_NAMES`) that a front/back word and a
    left/right/centre word name together ("back", "left" -> ``back_left``; "front",
    "middle" -> ``front``); None when both are missing."""
    fb = REGION_WORDS.get(front_back, front_back)
    lr = REGION_WORDS.get(left_right, left_right)
    if lr == "center" and fb:
        lr = None
    return "_".join(p for p in (fb, lr) if p) or None


_RELATIVE_RE = re.compile(r"\b(?:left|right|front|behind|back|next|beside|between|near|around|by|close|far|it|its|them|"
                          r"their|that|this|one|each|other|then|and\s+(?:the|a|an)\b)\b|@region_|[,;:]")


def _side_part_ok(m: re.Match) -> bool:
    """Whether a side is said bare ("on the left") or as a side of cubes the text names by colour
    ("a line of 3 cyan cubes on the left side"): the side of unnamed cubes stays unread."""
    part = re.sub(r"[\s-]+", " ", m.group("part")).strip()
    return part == "" or (part in ("side", "hand side", "half")
                          and re.search(rf"\b(?:{COLOR_RE})\b", m.string[:m.start()]) is not None)


def _side_ends_text(m: re.Match) -> bool:
    """Whether a place match is a bare side said or put to ("on the left", "to the right side") that ends the text (a role
    or the centre is read elsewhere): what :func:`_table_side` and :func:`_cubes_side` both ask."""
    return (_side_part_ok(m) and m.group(0).split()[0] in ("on", "to", "at", "in")
            and (m.group("lr") or m.group("lr2")) not in ("middle", "center", "centre")
            and re.fullmatch(r"\s*[.!]?\s*", m.string[m.end():]) is not None)


def _table_side(m: re.Match) -> bool:
    """Whether a bare side ("on the left") ends a text that names nothing else it could be the
    side of ("put two green cubes on the left", "stack the red block on the blue block on the
    right"): then it is the table's side.  Anything else that could anchor it (another
    relation, a second clause, a pronoun) leaves it relative (and the text refused)."""
    return (_side_ends_text(m)
            and _RELATIVE_RE.search(_COLOUR_LIST_COMMA_RE.sub(r"\1 ", m.string[:m.start()])) is None  # (a list's commas: no clause)
            and not names_a_role(m.string[:m.start()], m.string))  # "line up yellow and blue with blue on the left"


_COLOUR_LIST_COMMA_RE = re.compile(rf"\b(?<![\w-])((?:{COLOR_RE}))\s*,\s*(?=(?:the\s+)?(?:{COLOR_RE})\b)")
"""A comma between two colours of a list ("the orange, cyan and white cubes"): no second clause a bare side could belong to."""


_CLAUSE_SIDE_BEFORE = re.compile(rf"(?:^|[.;:]\s*|\b(?:and|then)\s+)(?:(?:put|place|set|move|leave|keep)\s+)?(?:the\s+|a\s+|an\s+)?"
                                 rf"(?:{COLOR_RE})\s+(?:block|cube|box|one)(?:\s+(?:goes|go|is|sits|stands|moves|ends\s+up|(?:must|should)"
                                 r"\s+(?:be|go|end\s+up)))?\s*$")  # ("and the red cube goes to the back")
_CLAUSE_SIDE_AFTER = re.compile(rf"\s*,?\s+(?:and|then)\s+(?:(?:put|place|set|move)\s+)?(?:the\s+|a\s+|an\s+)(?:{COLOR_RE})\s+"
                                r"(?:block|cube|box|one)\b(?!\s+(?:is\s+|goes\s+)?(?:on|to|at|in)\s+the\s+(?:far\s+|very\s+)?"
                                r"(?:left|right|front|back|rear|middle|center|centre)\b(?!\s+of\b))")
"""(the next clause relates its cube to another, rather than naming the other side: "red on the left and blue on the
right" are the two sides of one relation)"""


_CUBE_SAID = rf"(?:the\s+|a\s+|an\s+)?(?:{COLOR_RE})\s+(?:block|cube|box|one)"
_CUBES_SIDE_BEFORE = re.compile(rf"^\s*(?:(?:put|place|set|move|leave|keep)\s+)?(?:(?:both|2|all)\s+)?{_CUBE_SAID}(?:\s*,\s*{_CUBE_SAID})*"
                                rf"\s*,?\s+and\s+{_CUBE_SAID}(?:\s+(?:both|all|2))?(?:\s+(?:go|goes|are|sit|stand|end\s+up|belong"
                                r"|(?:must|should|can)\s+(?:be|go|end\s+up)))?(?:\s+(?:both|all|2))?\s*$")
"""Cubes listed as the subject of one place ("the white cube and the black cube both go", "put the red cube and the blue
cube"; "both" normalised to "2"), the whole text before a bare side that ends it: the side is the table's (it had been read
as relative to the first cube, and the text refused; after another sentence, "Make a tower of red and blue. The green cube and
the yellow cube go on the right.", the side may be the tower's, and stays relative)."""


def _cubes_side(m: re.Match) -> bool:
    """Whether a bare side ends a text after cubes listed as the subject of one place ("The white cube and the black cube
    both go to the right side."): the side has no cube of its own clause to be relative to, so it is the table's."""
    return _side_ends_text(m) and _CUBES_SIDE_BEFORE.search(m.string[:m.start()]) is not None


def _clause_side(m: re.Match) -> bool:
    """Whether a bare side ends a clause that places one cube, another cube's clause following
    ("put the red cube in the back and the green cube in front of it"), or a front or back ends
    the text's last such clause ("stack pink on brown, ..., and move the gray cube to the front"):
    the side has nothing in its own clause to be relative to, so it is the table's."""
    last = (m.group("fb") is not None and m.group("lr") is None  # "..., and move the gray cube to the front.": a last clause's
            and re.fullmatch(r"\s*[.!]?\s*", m.string[m.end():]) is not None)  # front or back has no cube to be relative to
    return (_side_part_ok(m) and m.group(0).split()[0] in ("on", "to", "at", "in")
            and _CLAUSE_SIDE_BEFORE.search(m.string[:m.start()]) is not None
            and (last or _CLAUSE_SIDE_AFTER.match(m.string[m.end():]) is not None))


_HEADING_RE = re.compile(r"\s*(?:(?:build|make|put|place|set\s+up)\s+)?(?:(?:a|an|the)\s+)?(?:[\w-]+\s+){0,3}?"
                         rf"{lexicon.STRUCTURE_NOUN}\s*")


def _heading_side(m: re.Match) -> bool:
    """Whether a bare side names where a structure stands, said as a heading before a colon
    ("Pyramid at the back: four purple cubes at the bottom, ...")."""
    return (m.group("part") == "" and m.group(0).split()[0] in ("on", "at", "in")
            and _HEADING_RE.fullmatch(m.string[:m.start()]) is not None
            and re.match(r"\s*:", m.string[m.end():]) is not None)


NEW_STRUCTURE_BEFORE_RE = re.compile(
    r"(?:^\s*line\s+up\s+(?:the\s+)?(?:(?:\d+|[a-z]+)(?:\s*,\s*|\s+and\s+|\s+))+(?:cubes|blocks)\s*$)|"  # "line up the cyan, pink and brown cubes"
    r"(?:(?:^|[,;:.]\s*)(?:(?:a|an|1|\d+)\s+)?|\b(?:and|then|build|make|set\s+up|put|place|create|form|in|into)\s+(?:a|an|1|\d+)\s+)"
    r"(?:(?!the\b|that\b|this\b|its\b|their\b)[\w-]+\s+){0,2}?"
    rf"{lexicon.STRUCTURE_NOUN}s?"
    r"(?:\s+of\s+(?:\d+\s+)?(?:[a-z]+\s+)?(?:cubes|blocks))?\s*$")
"""A structure being described just before a bare side ("a line of 4 gray cubes at the front")."""


_NEW_PILE_BEFORE_RE = re.compile(r"\b(?:a|an|1|one)\s+(?:[\w-]+\s+)?(?:pile|heap)\s+of\s+(?:any\s+)?(?:\d+|[a-z]+)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\s*$"
                                 r"|^\s*(?:pile|heap)\s+(?:up\s+)?(?:any\s+)?\d+\s+(?:[a-z]+\s+)?(?:cubes|blocks)\s*(?:,\s*any\s+colou?rs?\s*,\s*)?$")
"""A pile being described just before a bare side ("make a pile of four cubes on the right side", "Pile four cubes, any
colours, on the right side", "a pile of any four cubes on the right side"); :data:`NEW_STRUCTURE_BEFORE_RE` leaves piles out (a pile may be one the speaker sees)."""


def _structure_side(m: re.Match) -> bool:
    """Whether a bare side ("at the front", "on the left") says where a structure the text is
    describing stands ("set up a line of 4 gray cubes at the front and a circle of 5 orange cubes
    at the back"): a new structure has no sides of its own to be relative to."""
    described = NEW_STRUCTURE_BEFORE_RE.search(m.string[:m.start()]) is not None or _NEW_PILE_BEFORE_RE.search(
        m.string[:m.start()]) is not None  # "a row of three cubes on the left side", "a pile of four cubes on the right side":
    # the side of a structure being described is the table's, its cubes named by colour or not
    part_ok = _side_part_ok(m) or (described and re.sub(r"[\s-]+", " ", m.group("part")).strip() in ("side", "hand side", "half"))
    if not (part_ok and m.group(0).split()[0] in ("on", "at", "in", "to")
            and (m.group("fb") or m.group("lr2")) in ("front", "back", "rear", "left", "right") and not m.group("lr")
            and not names_a_role(m.string[:m.start()], m.string)):
        return False
    before = m.string[:m.start()]
    # "a line of 4 gray cubes at the front"; "a wall: 3 red on the bottom, 3 blue on top, at the back" (its last words)
    return described or (
        re.search(r",\s*$", before) is not None and re.fullmatch(r"\s*[.!]?\s*", m.string[m.end():]) is not None
        and re.match(r"\s*(?:(?:build|make|create|set\s+up|form)\s+)?(?:a|an|1)\s+(?:[\w-]+\s+){0,2}?"
                     rf"{lexicon.STRUCTURE_NOUN}\b", before) is not None
        and len(re.findall(rf"\b{lexicon.STRUCTURE_NOUN}s?\b", before)) == 1)


def _group_side(m: re.Match) -> bool:
    """Whether a bare side is where a group just said stands ("the grey cube left of the black
    cube, both in the back"): two cubes together have no one side to be relative to."""
    return (m.group(0).split()[0] in ("on", "at", "in", "to")
            and not names_a_role(m.string[:m.start()], m.string)
            and lexicon.GROUP_SUBJECT_RE.search(m.string[:m.start()]) is not None)


def _per_layer(m: re.Match) -> str:
    """"3 cubes per layer" -> "3 wide"; "4 cyan cubes per row" -> "4 wide, all cyan"."""
    n = m.group("n1") or m.group("n2") or m.group("n3")
    wide = f"{NUMBER_WORDS.get(n, n)} wide"
    if m.group("noun") or m.group("noun3"):  # "3 layers, 2 cubes each", "2 rows, each row 3 cubes": the layers, then each one's width
        sep = m.group("sep") if m.group("noun") else m.group("sep3")
        return f"{m.group('noun') or m.group('noun3')}{sep.rstrip().removesuffix('with').removesuffix('of').rstrip() or ''} {wide}"
    return f"{wide}, all {m.group('c')}" if m.group("c") else wide


def _end_cube(m: re.Match) -> str:
    """"with red on top" -> "with a red block on top", or "the red block" when a red cube was named before."""
    article = "the" if re.search(rf"\b{m.group(1)}\b", m.string[:m.start()]) else "a"
    return f"with {article} {m.group(1)} block {m.group(2)} {m.group(3) or ''}{m.group(4)}"


def mark_regions(text: str) -> str:
    """Replace places on the table ("in the middle of the table", "at the back left corner",
    "on the right side of the workspace") with ``@region_<name>`` tokens (names as in
    :data:`constants.REGION_NAMES`, or a group of :data:`constants.REGION_GROUPS`: "at the
    corner").  A bare side ("on the left") stays: it is relative."""
    def sub(m: re.Match) -> str:
        corner = "corner" in m.group("part")
        edge = "edge" in m.group("part")  # "near the front edge": a side of the table, not of a cube
        edge = edge or bool(re.search(r"area|region|zone|half", m.group("part")))  # "in the back region", "in the front half": of
        # the table, too (a cube has no halves)
        word = m.group("lr") or m.group("lr2")
        bare_center = (word in ("center", "centre", "middle") and m.group(0).split()[0] in ("in", "at", "to", "into")  # "in the center"
                       and not names_a_role(m.string[:m.start()], m.string)
                       and not (word == "middle" and lexicon.TOP_ROLE_SAID_RE.search(m.string)  # "red on top, green in the
                                and lexicon.BOTTOM_ROLE_SAID_RE.search(m.string)))  # middle, blue on the bottom": the tower's
        two_sides = bool(m.group("fb")) and m.group("lr") in ("left", "right")  # "at the front right": a corner of the table
        if not (m.group("tail") or corner or edge or bare_center or two_sides or _table_side(m) or _heading_side(m)
                or _structure_side(m) or _group_side(m) or _clause_side(m) or _cubes_side(m)):
            return m.group(0)
        fb = m.group("fb") or ("far" if m.group("far") == "far" and corner else None)  # "the far left corner"
        if corner and not (fb and word in ("left", "right")):  # "the right corner": back right or front right?
            raise ParseError(f"'{m.group(0).strip()}' names no one corner: a corner of the table is front or back and "
                             "left or right (e.g. 'the back right corner')")
        return f" @region_{region_name(fb, word)} "
    text = CORNER_PAIR_RE.sub(lambda m: f"{m.group('prep')} the {m.group('a')} corner and {m.group('prep')} the "
                              f"{m.group('b')} corner", text)  # "each of": the reader reads it in the text
    half = re.search(r"\bcorners?\s+(?:at|in|on|towards?|of|to)\s+the\s+(?:back|front|rear|left|right)\b(?!\s+(?:left|right|hand|back|front))", text)
    if half:  # "in the corner at the back": the back edge had been read, the corner dropped
        raise ParseError(f"'{half.group(0).strip()}' names no one corner: a corner of the table is front or back and "
                         "left or right (e.g. 'the back right corner')")
    text = REGION_RE.sub(sub, text)
    return " ".join(REGION_GROUP_RE.sub(lambda m: f" @region_{m.group('g')} ", text).split())
