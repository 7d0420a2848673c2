"""Can WordLlama's embeddings read an unknown word as a word of the vocabulary? (issue 30)

The fallback issue 30 asks for: a word outside the lexicon whose embedding is close enough
to a vocabulary word (a threshold set on the development split) is read as that word.  This
script measures whether any threshold does that safely, on the lexicon's own curated data:

- **synonyms** (must be read): every pair of :data:`rpg.schema.lexicon.SYNONYMS` and of
  :data:`rpg.schema.lexicon.PLACEMENT_VERBS` (a verb and the placement it means);
- **contrasts** (must never be read as each other): opposite relation and place words of
  the vocabulary (left/right, above/below, ...) and pairs of colours.

For each threshold it prints how many synonyms the fallback would read and how many
contrasts it would confuse, and, as the fallback would work, whether each synonym's nearest
vocabulary word is its meaning.  Run: ``.venv/bin/python tests/corpus/synonym_threshold.py``.
"""

from __future__ import annotations

import itertools

import numpy as np

from rpg.diversity.embeddings import _wordllama
from rpg.domain.palette import PALETTE
from rpg.schema import lexicon
from rpg.schema.lexicon import COLORS, VOCAB

CONTRASTS = [("left", "right"), ("front", "back"), ("above", "below"), ("top", "bottom"), ("on", "under"),
             ("before", "after"), ("first", "last"), ("ascending", "descending"), ("inside", "outside"),
             ("near", "far"), ("up", "down"), ("behind", "front"), ("over", "under"), ("tallest", "shortest"),
             ("stack", "unstack"), ("increasing", "decreasing"), ("row", "column"), ("horizontal", "vertical")]


def pairs() -> tuple[list[tuple[str, str]], list[tuple[str, str]]]:
    synonyms = sorted({(w, t) for w, t in lexicon.SYNONYMS.items() if not w.endswith("s") or w[:-1] not in lexicon.SYNONYMS}
                      | {(w, t) for w, t in lexicon.PLACEMENT_VERBS.items() if w != t})
    colours = sorted(PALETTE)[:10]
    return synonyms, CONTRASTS + list(itertools.combinations(colours, 2))


def main() -> None:
    wl = _wordllama()
    synonyms, contrasts = pairs()

    def sim(a: str, b: str) -> float:
        e = np.asarray(wl.embed([a, b], norm=True), dtype=np.float64)
        return float(e[0] @ e[1])

    s = np.array([sim(a, b) for a, b in synonyms])
    c = np.array([sim(a, b) for a, b in contrasts])
    print(f"{len(synonyms)} synonym pairs: cosine median {np.median(s):.3f} (min {s.min():.3f}, max {s.max():.3f})")
    print(f"{len(contrasts)} contrast pairs: cosine median {np.median(c):.3f} (max {c.max():.3f}: "
          f"{contrasts[int(c.argmax())]})")
    print("threshold  synonyms read  contrasts confused")
    for t in (0.2, 0.3, 0.4, 0.5, 0.6, 0.7):
        print(f"{t:9.1f}  {int((s >= t).sum()):>6}/{len(s)}  {int((c >= t).sum()):>10}/{len(c)}")
    safe = c.max()
    print(f"above every contrast ({safe:.3f}): {int((s > safe).sum())} of {len(s)} synonyms read")
    vocab = sorted(VOCAB | set(COLORS))
    emb = np.asarray(wl.embed(vocab, norm=True), dtype=np.float64)
    hits = 0
    for word, target in synonyms:
        e = np.asarray(wl.embed([word], norm=True), dtype=np.float64)[0]
        ranked = [vocab[i] for i in np.argsort(-(emb @ e)) if vocab[i] != word]
        hits += ranked[0] == target
    print(f"nearest vocabulary word is the synonym's meaning: {hits} of {len(synonyms)}")


if __name__ == "__main__":
    main()
