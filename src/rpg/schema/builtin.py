"""The builtin front end: a deterministic, offline semantic parser for the block domain.

It reads the language of the domain (colours, counts in words or digits, quoted words,
letters, digits and operators; relations; structures; orderings; patches; temporal order;
orientation; equations) and builds a :class:`~rpg.schema.model.TaskSchema` through
:class:`~rpg.schema.builder.Builder`.  Words it does not know are refused, quoted, with a
suggestion to use ``--model``; it never guesses silently.

The front end in layers, each importing only the ones before it:

1. :mod:`rpg.schema.lexicon`: every surface form (vocabulary, colours, number words,
   relation and structure words, what the domain cannot express);
2. :mod:`rpg.schema.reading`: normalisation and the features the readers read;
3. :mod:`rpg.schema.accounting`: every mention of the instruction must be in its task;
4. :mod:`rpg.schema.readers`: the readers, registered with their order, and :func:`parse`.

This module is the front end's public face: :func:`parse`, :func:`normalize`,
:func:`check_mentions` and the errors they raise.  Frame conventions: see
:mod:`rpg.domain.constants`.
"""

from __future__ import annotations

from rpg.schema.accounting import check_mentions
from rpg.schema.readers import parse
from rpg.schema.reading import Inexpressible, ParseError, normalize

__all__ = ["Inexpressible", "ParseError", "check_mentions", "normalize", "parse"]
