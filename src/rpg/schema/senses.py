"""What a word outside the lexicon most likely is, by its WordLlama embedding (issue 30, item 3).

A word the parser does not know (not in :data:`rpg.schema.lexicon.VOCAB`, not an inflection
or a typo of one) is compared with three curated word lists of :mod:`rpg.schema.lexicon`:

- :data:`~rpg.schema.lexicon.UNKNOWN_KIND_EXEMPLARS`: words of meaning the domain cannot
  express, by class (a size, a quantity, time, an action, an object, a shape...).  An
  unknown word close to one ("enormous", "toppled", "dozen") is refused for that class's
  reason, not as an unknown word.  This only changes why a text is refused.
- :data:`~rpg.schema.lexicon.IGNORABLE` and :data:`~rpg.schema.lexicon.IGNORABLE_MORE`:
  words with no meaning for the goal.  An unknown adverb or adjective (never a noun or a
  verb) close to one of them and clearly farther from every vocabulary word ("swiftly" ~
  "quickly", "wonderful" ~ "great") is dropped like them, and the task's accounting lists it.
- :data:`~rpg.schema.lexicon.VOCAB`: words that carry meaning; a word as close to one of these
  as to a class above is neither refused for that class nor dropped.

Every other word stays unknown and the instruction is refused naming it.  The thresholds
(:data:`~rpg.schema.lexicon.SENSE_MIN_SIMILARITY` and the others) were set on the lexicon's
own lists (leave-one-out: no vocabulary word that carries meaning reads as ignorable) and on
made-up probe words, never on the unseen split;
``tests/corpus/synonym_threshold.py`` shows why no threshold maps a word *to* a vocabulary
word safely (opposites such as left/right are as close as synonyms), so nothing unknown is
ever read as a known word here.

WordLlama (MIT) ships its 256-d ``l2_supercat`` weights and tokenizer in its wheel; it is
loaded offline (``disable_download``), lazily, the first time an unknown word is met.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from rpg.schema import lexicon


@lru_cache(maxsize=1)
def wordllama():
    """The WordLlama model, loaded from its wheel without touching the network (~0.2 s).

    Its loader looks for the tokenizer under ``tokenizer/`` while the wheel has it under
    ``tokenizers/``; ``cache_dir`` set to the package directory finds both files."""
    import wordllama as package
    from wordllama import WordLlama

    return WordLlama.load(cache_dir=Path(package.__file__).parent, disable_download=True)


def _embed(words: list[str]) -> np.ndarray:
    return np.asarray(wordllama().embed(words, norm=True), dtype=np.float64)


@lru_cache(maxsize=1)
def _tables() -> tuple[dict[str, tuple[list[str], np.ndarray]], tuple[list[str], np.ndarray], tuple[list[str], np.ndarray]]:
    ignorable = sorted(lexicon.IGNORABLE | lexicon.IGNORABLE_MORE)
    meaning = sorted((lexicon.VOCAB | set(lexicon.PLACEMENT_VERBS)) - set(ignorable))
    kinds = {k: (list(ws), _embed(list(ws))) for k, ws in sorted(lexicon.UNKNOWN_KIND_EXEMPLARS.items())}
    return kinds, (ignorable, _embed(ignorable)), (meaning, _embed(meaning))


@dataclass(frozen=True)
class Sense:
    """How an unknown word reads.

    Attributes:
        word: the word, lower case.
        kind: ``"ignorable"``, a class of :data:`rpg.schema.lexicon.UNKNOWN_KIND_EXEMPLARS`
            (``"size"``, ``"action"``...), or ``"unknown"``.
        like: the listed word it is closest to (for the message), ``""`` when unknown.
        similarity: cosine similarity of the two embeddings, in [-1, 1].
    """

    word: str
    kind: str
    like: str = ""
    similarity: float = 0.0


@lru_cache(maxsize=4096)
def sense(word: str) -> Sense:
    """How unknown ``word`` reads (see the module docstring for the rules)."""
    kinds, (ign_words, ign), (_, mean) = _tables()
    e = _embed([word])[0]
    s_mean = float((mean @ e).max())
    best = max(((float((x @ e).max()), k, ws[int((x @ e).argmax())]) for k, (ws, x) in kinds.items()))
    agent = any(lemma != best[2] and lemma.startswith(best[2]) and lemma[len(best[2]):] in ("er", "ers", "ist", "ists")
                for lemma in {word, *lexicon.lemmas(word)}) and lexicon.is_dictionary_word(word)
    if best[0] >= lexicon.SENSE_MIN_SIMILARITY and best[0] >= s_mean and not agent:  # ("archers" are no arch: a person
        # named after the thing, whose embedding is close to it)
        return Sense(word, best[1], best[2], best[0])
    s_ign = ign @ e
    pos = lexicon.parts_of_speech(word)
    if (pos and not pos & {"NOUN", "VERB", "PROPN"} and s_ign.max() >= lexicon.IGNORABLE_MIN_SIMILARITY
            and s_ign.max() - s_mean >= lexicon.IGNORABLE_MARGIN):
        return Sense(word, "ignorable", ign_words[int(s_ign.argmax())], float(s_ign.max()))
    return Sense(word, "unknown")


@lru_cache(maxsize=1)
def _motion_tables() -> tuple[np.ndarray, np.ndarray]:
    return _embed(list(lexicon.MOTION_VERB_EXEMPLARS)), _embed(list(lexicon.CHANGE_VERB_EXEMPLARS))


@lru_cache(maxsize=4096)
def moves_a_thing(verb: str) -> bool:
    """Whether unknown ``verb`` reads nearer a verb that moves a thing to a place than one that changes, turns or throws it
    (:data:`rpg.schema.lexicon.MOTION_VERB_EXEMPLARS`, :data:`rpg.schema.lexicon.CHANGE_VERB_EXEMPLARS`; cosine of the
    wordllama embeddings, the nearest exemplar of each): "taxi", "post", "ferry" move; "melt", "glue", "shove" do more."""
    motion, change = _motion_tables()
    e = _embed([verb])[0]
    return float((motion @ e).max()) > float((change @ e).max())
