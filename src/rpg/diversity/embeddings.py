"""Sentence embeddings of task instructions, offline.

``wordllama`` (default): WordLlama's 256-d ``l2_supercat`` model, whose weights and tokenizer
ship inside its wheel (MIT).  Its loader looks for the tokenizer under ``tokenizer/`` while
the wheel has it under ``tokenizers/``; a plain load therefore tries to download.  Loading
with ``cache_dir`` set to the package directory and ``disable_download=True`` finds both
files and never touches the network (~0.2 s).  ``tfidf``: scikit-learn TF-IDF over word
uni- and bigrams, fitted on the texts given.  ``st:PATH``: a local sentence-transformers
model directory (the package must be installed by the user; nothing is downloaded).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from rpg.errors import BadInput

METHODS = ("wordllama", "tfidf", "st:PATH")


def _wordllama():
    """The WordLlama model, loaded offline (:func:`rpg.schema.senses.wordllama`)."""
    from rpg.schema.senses import wordllama

    return wordllama()


def embed(texts: list[str], method: str = "wordllama") -> np.ndarray:
    """Unit-length embeddings of ``texts``.

    Args:
        texts: one text per task.
        method: ``wordllama``, ``tfidf`` or ``st:PATH``.

    Returns:
        float64 array (len(texts), d), each row of L2 norm 1 (a zero row stays zero).

    Raises:
        BadInput: unknown method, or a sentence-transformers path that cannot be loaded.
    """
    if not texts:
        return np.zeros((0, 1))
    if method == "wordllama":
        x = np.asarray(_wordllama().embed(list(texts)), dtype=np.float64)
    elif method == "tfidf":
        from sklearn.feature_extraction.text import TfidfVectorizer

        x = TfidfVectorizer(ngram_range=(1, 2), sublinear_tf=True).fit_transform(texts).toarray()
    elif method.startswith("st:"):
        path = Path(method[3:])
        if not path.is_dir():
            raise BadInput(f"{path} is not a sentence-transformers model directory")
        try:
            from sentence_transformers import SentenceTransformer
        except ImportError:
            raise BadInput("--embedding st:PATH needs the sentence-transformers package "
                           "(pip install sentence-transformers)") from None
        x = np.asarray(SentenceTransformer(str(path), local_files_only=True).encode(list(texts)), dtype=np.float64)
    else:
        raise BadInput(f"unknown embedding {method!r}; use one of {', '.join(METHODS)}")
    norms = np.linalg.norm(x, axis=1, keepdims=True)
    return x / np.where(norms > 0, norms, 1.0)
