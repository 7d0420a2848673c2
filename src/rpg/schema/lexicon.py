"""The builtin front end's lexicon: surface forms of the block domain as data.

Each table maps a surface form to its category's canonical value.  The parser reads
inflected forms through their lemma (``lemminflect``, whose data ships in its wheel:
"built" -> build, "stacked" -> stack, "touching" -> touch), so the tables hold lemmas only.

A word of an instruction is either *known* (a colour, number, label, or a lemma in one of
these tables or in the parser's vocabulary), *ignorable* (:data:`IGNORABLE`: it carries no
meaning for the task and is dropped), or unknown, and then the instruction is refused with the
word named.  Nothing here is a guess: a word is only listed where its reading is certain.

Frame conventions (see :mod:`rpg.domain.constants`): the robot stands at the origin looking
along +x.  Compass words follow a map seen from above with the robot at the bottom edge:
north = away from the robot ("behind", larger x), south = towards it ("in front of"),
east = its right (-y), west = its left (+y).
"""

from __future__ import annotations

from functools import lru_cache

IGNORABLE: frozenset[str] = frozenset("""
please kindly carefully gently slowly quickly neatly precisely directly simply just now okay ok alright
hey hi could would you can i we my your our their robot's go ahead really nicely firmly softly
gingerly cautiously immediately sequentially successively very grasped held
""".split())
"""Fillers, politeness, manner adverbs and possessives: no meaning for the goal (dropped)."""

PLACEMENT_VERBS: dict[str, str] = {
    "put": "place", "place": "place", "set": "place", "move": "place", "push": "place", "slide": "place",
    "bring": "place", "shift": "place", "transfer": "place", "relocate": "place", "sweep": "place",
    "position": "place", "drop": "place", "lay": "place", "add": "place", "pack": "place",
    "build": "build", "make": "build", "create": "build", "construct": "build", "assemble": "build",
    "form": "build", "erect": "build", "stack": "stack", "pile": "stack",
}
"""Verbs that ask for objects to end up somewhere, by lemma -> the parser's verb."""

COMPASS: dict[str, str] = {"north": "back", "south": "front", "east": "right", "west": "left"}
"""Compass words -> table directions (see the frame convention above)."""

COMPASS_CORNERS: dict[str, str] = {"nw": "back_left", "ne": "back_right", "sw": "front_left", "se": "front_right"}
"""Compass abbreviations of corners -> region names (:data:`constants.REGION_NAMES`)."""

COMPASS_RELATIONS: dict[str, str] = {"north": "behind", "south": "in front of", "east": "right of", "west": "left of"}
"""'to the north of X' -> the relation words the parser reads."""

@lru_cache(maxsize=4096)
def lemmas(word: str) -> tuple[str, ...]:
    """Dictionary lemmas of ``word`` for any part of speech (empty if lemminflect does not
    know the word: then it may be a typo)."""
    from lemminflect import getAllLemmas

    found = getAllLemmas(word)
    return tuple(sorted({lemma for forms in found.values() for lemma in forms}))


def is_dictionary_word(word: str) -> bool:
    """Whether ``word`` is an English word lemminflect knows (so not to be typo-corrected)."""
    return bool(lemmas(word))
