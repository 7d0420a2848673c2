"""The builtin front end's lexicon: surface forms of the block domain as data.

Each table maps a surface form to its category's canonical value.  The parser reads
inflected forms through their lemma (``lemminflect``, whose data ships in its wheel:
"built" -> build, "stacked" -> stack, "touching" -> touch), so the tables hold lemmas only.

A word of an instruction is either *known* (a colour, number, label, or a lemma in one of
these tables or in the parser's vocabulary), *ignorable* (:data:`IGNORABLE`: it carries no
meaning for the task and is dropped), or unknown.  An unknown word is refused with the word
named, unless its embedding reads it as a filler (dropped, and listed in the accounting record)
or as meaning the domain lacks (refused for that reason): :mod:`rpg.schema.senses`, with the
exemplars and thresholds below.  Nothing in the tables is a guess: a word is only listed where
its reading is certain.

Relation words are declared on their predicate classes (``phrases``) and tower nouns on the
tower kind (:mod:`rpg.schema.structures`); the tables here that read them (:data:`REL_PATTERNS`,
:data:`TOWER_NOUNS`) are derived from those registries, so each surface word is written once.

Frame conventions (see :mod:`rpg.domain.constants`): the robot stands at the origin looking
along +x.  Compass words follow a map seen from above with the robot at the bottom edge:
north = away from the robot ("behind", larger x), south = towards it ("in front of"),
east = its right (-y), west = its left (+y).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import lru_cache

from rpg.domain.palette import COLOR_ALIASES, PALETTE
from rpg.domain.predicates import PREDICATES
from rpg.schema.structures import STRUCTURE_KINDS

IGNORABLE: frozenset[str] = frozenset("""
please kindly carefully gently slowly quickly neatly precisely directly simply just now okay ok alright
hey hi could would you can i we my your our their robot's go ahead really nicely firmly softly
gingerly cautiously immediately sequentially successively very grasped held
""".split())
"""Fillers, politeness, manner adverbs and possessives: no meaning for the goal (dropped)."""

IGNORABLE_MORE: frozenset[str] = frozenset("""
nice nicely neat tidy tidily maybe perhaps possibly need needs needed want wants wanted let am
try trying attempt anywhere somewhere flat flatly thanks thank cool great gonna wanna um uh yeah alright
help wood wooden plastic properly securely stably steadily safely accurately completely entirely fully pls plz sure
basically essentially literally honestly yo hello ty thx hiya howdy asap today tonight morning afternoon evening fine
quick quickly haha lol good love exercise cheers tbh imo itself kindly tomorrow tmrw tmr
someone somebody anyone anybody everyone everybody friends guys folks buddy boys girls kids children
task episode eval evaluation benchmark dataset proposal experiment policy policies week weekend
fwiw lowkey ngl btw sim simulator simulation
honey sweetie sweetheart darling dear abeg
""".split())
"""Further words with no meaning for the goal, each checked not to change what a task asks:
the names of what is being written ("new eval task:", "for this experiment": every task
is an evaluation task, checked at the end of its episode), hedges ("maybe"), wishes ("I need", "we'll", "let's"), praise ("nice"), who is addressed ("boys and
girls", "can someone ..."), "anywhere", "lay it
flat" (every cube rests on a face), a cube's material ("the red wooden block": every cube is
the same, and G never reads it). Dropped by :func:`rpg.schema.reading.normalize`; the task's
accounting does not list them (it records the mentions that make a part of the task)."""

CONTRACTIONS: tuple[tuple[str, str], ...] = (
    (r"\blet's\b", "let us"), (r"\b(it|that|there|here|what)'s\b", r"\1 is"), (r"'ll\b", " will"),
    (r"'d\b", " would"), (r"'ve\b", " have"), (r"'re\b", " are"), (r"\bi'm\b", "i am"),
)
"""Contractions written out (negated ones, "don't", are refused first: :data:`INEXPRESSIBLE`)."""

TEXTURED_RE = re.compile(r"\b(?:the\s+)?(?:object|block|cube)\s+with\s+(?:the\s+|a\s+)?(?P<c>[a-z]+)\s+texture\b")
"""A cube named by its texture ("the object with red texture", ClevrSkills): read as the cube
of that colour when the word is a colour (:func:`rpg.schema.reading.normalize`)."""

TYPOS: dict[str, str] = {
    "blu": "blue", "gren": "green", "yelow": "yellow", "purpel": "purple", "cirlce": "circle", "cricle": "circle",
    "towr": "tower", "pyramd": "pyramid", "rite": "right", "da": "the", "teh": "the", "ontop": "on top",
    "insted": "instead", "instaed": "instead", "isntead": "instead", "mak": "make", "midle": "middle", "middel": "middle", "mid": "middle",
    "nxt": "next", "mor": "more", "swtich": "switch", "swich": "switch", "swithc": "switch", "revese": "reverse", "reverce": "reverse",
    "blok": "block", "bloks": "blocks", "rigth": "right", "rihgt": "right", "lefft": "left", "cubs": "cubes",
    "seprate": "separate", "seperate": "separate", "seperately": "separately", "seprately": "separately",
    "initialy": "initially", "intially": "initially", "initally": "initially",
}
"""Misspellings of a word of the vocabulary, each read as that word (curated, never a guess; the
steering corrects an edit's words with this table before reading it)."""

ABBREVIATIONS: dict[str, str] = {
    "btwn": "between", "betw": "between", "nxt": "next", "grn": "green", "ylw": "yellow", "yllw": "yellow",
    "brwn": "brown", "brn": "brown", "wht": "white", "blck": "black", "pnk": "pink", "prpl": "purple", "orng": "orange",
    "gry": "gray", "blu": "blue", "cn": "can", "thx": "thanks", "thnx": "thanks", "abv": "above",
    "frnt": "front", "lft": "left", "rght": "right", "ctr": "center", "cntr": "center", "shall": "must",
}
"""Abbreviations of texting and of specifications ("btwn", "grn", "ylw"; "shall" of a
requirement), each read as its word (curated: an abbreviation with two readings, "blk" for
black or block, is read by :data:`BLK_RE` from the word after it)."""

LABEL_LIST_PLACED_RE = re.compile(
    r"\b(?P<the>[Tt]he)\s+(?P<kind>letter|digit|number)\s+(?:cubes|blocks)\s+(?P<labels>(?:[A-Z]|\d)(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+)"
    r"(?:[A-Z]|\d))+)(?=\s+(?:all\s+|both\s+)?(?:on|onto|in|into|to)\s+(?:the|a)\s+(?:[a-z]+\s+){0,2}(?:patch|corner|side|half|edge"
    r"|middle|cent(?:er|re))\b)")
"""Label cubes listed by their kind and then placed on a patch or in a place of the table ("the letter cubes A and B on the
white patch", "the digit cubes 7 and 8 in the front left corner"): said one cube at a time ("the letter A block and the
letter B block"), as the placement readers read them (the list had been read as two unlabelled cubes and refused)."""

LABELS_AND_NOUN_RE = re.compile(r"\b(?P<the>[Tt]he)\s+(?P<labels>(?:[A-Z]|\d)(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+|\s*&\s*)(?:[A-Z]|\d))+)"
                                r"\s+(?P<noun>cube|block)s\b")
""""the 1 & 9 cubes", "the A and B blocks", "the A, B and C cubes": labelled cubes sharing one noun, read as "the 1
cube and the 9 cube" (:func:`rpg.schema.reading.normalize_words`)."""

BLK_RE = re.compile(r"\bblk(?P<black>s?)\b(?=\s+(?:cubes?|blocks?)\b|\s*(?:->|\u2192|=>|/))|(?<=>)(?P<arrowed>\s?)blk\b"
                    r"|(?<=\s)blk(?P<block>s?)\b")
""""blk": black before a cube's noun ("put blk cube nxt 2 brwn cube") or as an item of a list ("blk -> wht ->
gry tower"), else a block ("gray blk between black & white blks")."""

TEXTED_TO_RE = re.compile(r"(?i)\b(move|moved|put|go|goes|slide|push|bring|it|cube|block|one)\s+2\s+(?=the\b)"
                          r"|\b(next|nxt|close|closer)\s+2\s+(?=\S)")
""""2" for "to" in texting ("move the green cube 2 the back", "nxt 2 the 1 cube"): read as "to"."""

TEXTED_YOU_RE = re.compile(r"(?<![\w'])u(?![\w'])")
"""Texting's lower-case "u" for "you" ("can u build ..."); a capital U is a letter cube."""

REF_CHANGE_RE = re.compile(r"\b(?:but|except|with|and\s+(?:then\s+)?(?:make|add|put|change|use|turn))\s+\w+.*")
"""What follows a version reference and asks for a change ("like v0 but ...", "v1 with ..."): an
edit that names one and no change was read is refused, not taken back to that version alone."""

STACK_SIDE_MOVE_RE = re.compile(
    r"\s*(?:(?:now|ok(?:ay)?|and|then|also)[\s,]+)*(?:move|put|shift|slide|place|push|bring|set)\s+(?:it|this|that)\s+(?:over\s+)?"
    r"(?:to|on|at|in|towards?)\s+the\s+(?:far\s+)?(?P<side>left|right|front|back)(?:\s+(?:side|half))?(?:\s+(?:instead|please|now|a\s+bit))*\s*")
"""An edit that moves "it" to a side with no cube to be the side of ("move it to the left"): of
a two-cube stack, "it" is the stack (its top cube to the left would be a relation "of" a cube)."""

ORDER_RANGE_RES: tuple[tuple[re.Pattern, str], ...] = (
    # "so that the numbers go down from left to right", "the digits increase left to right": a sort said by the numbers'
    # way (it had been dropped: the listed order kept, silently)
    (re.compile(r"(?i)\b(?:so\s+that\s+|such\s+that\s+)?(?:the\s+)?(?:numbers|digits|values|labels)\s+(?:go\s+|run\s+|count\s+)?"
                r"(?:down|decrease|descend|get\s+smaller)\b"), "in decreasing order"),
    (re.compile(r"(?i)\b(?:so\s+that\s+|such\s+that\s+)?(?:the\s+)?(?:numbers|digits|values|labels)\s+(?:go\s+|run\s+|count\s+)?"
                r"(?:up|increase|ascend|get\s+(?:bigger|larger))\b"), "in increasing order"),
    (re.compile(r"(?i)\b(?:from\s+)?(?:small|little|low|least|minor)(?:est|er)?\s+(?:to|->|\u2192)\s+(?:big|large|high|great|major)(?:gest|est|er)?\b"),
     "from smallest to largest"),
    (re.compile(r"(?i)\b(?:from\s+)?(?:big|large|high|great|major)(?:gest|est|er)?\s+(?:to|->|\u2192)\s+(?:small|little|low|least|minor)(?:est|er)?\b"),
     "from largest to smallest"),
)
""""small to big", "high -> low", "from minor to major" (Spanish "de menor a mayor"): a sort said by its two ends,
read as the sort words the readers know ("from smallest to largest"); it had been dropped, leaving the listed order."""

SYNONYMS: dict[str, str] = {
    "brick": "block", "bricks": "blocks", "ground": "table", "floor": "table", "tabletop": "table",
    "course": "row", "courses": "rows",  # a wall's course of bricks is a row ("of course" is a filler: FILLER_RE)
    "desk": "table", "rightmost": "right", "leftmost": "left", "frontmost": "front", "backmost": "back",
    "furthest": "far", "farthest": "far", "lastly": "finally", "afterwards": "then", "afterward": "then",
    "subsequently": "then", "organize": "arrange", "organise": "arrange", "organized": "arranged", "rearrange": "arrange",
    "rearranged": "arranged", "reorder": "arrange", "reorganize": "arrange", "reorganise": "arrange",
    "organised": "arranged", "invert": "reverse", "inverted": "reversed", "upper": "top", "lower": "bottom",
    "uppermost": "top", "lowermost": "bottom", "topmost": "top", "bottommost": "bottom", "upon": "on", "right-hand": "right", "left-hand": "left",
    "stays": "is", "remains": "is", "bot": "robot", "midpoint": "center", "tower's": "tower", "within": "in", "inside": "in", "quadrant": "corner",
    "summit": "top", "apex": "top", "belongs": "goes", "belong": "go", "proceed": "go", "proceeds": "goes", "relocate": "move", "relocated": "moved", "reposition": "move", "repositioned": "moved", "objective": "goal", "aim": "goal", **TYPOS, **ABBREVIATIONS,
}
"""Words read as a word of the vocabulary (curated: a synonym, never a guess). "the ground" is
the table the cubes stand on; "the rightmost corner" is a corner on the right."""

NUMBER_WORDS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "both": 2, "pair": 2, "couple": 2,
    "single": 1, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
    "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90,
    "hundred": 100, "thousand": 1000, "million": 1000000,
}
"""Number words -> their value (written as digits by the parser's and the steering's normalisers)."""

LARGE_NUMBER_RE = re.compile(r"\b(?:a|an|one|1)\s+(?=(?:hundred|thousand|million)\b)")
""""a hundred", "one thousand": the number alone (each word had been written as a number of its own, "1 1000")."""

COMPOUND_NUMBER_RE = re.compile(r"\b(?P<tens>twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)[\s-](?P<ones>one|two|three|four|five|six"
                                r"|seven|eight|nine)\b|\b(?P<n>two|three|four|five|six|seven|eight|nine|ten|\d+)\s+(?P<big>hundred|thousand)\b")
""""sixty-five", "five hundred": one number (they had been read as two, "60 5": a tower of five)."""


def compound_number(m: re.Match) -> str:
    """The value of a :data:`COMPOUND_NUMBER_RE` match, in digits."""
    if m.group("tens"):
        return str(NUMBER_WORDS[m.group("tens")] + NUMBER_WORDS[m.group("ones")])
    n = m.group("n")
    return str((int(n) if n.isdigit() else NUMBER_WORDS[n]) * NUMBER_WORDS[m.group("big")])

DIGIT_WORDS = ("zero", *sorted((w for w, v in NUMBER_WORDS.items() if 1 <= v <= 9 and w not in ("single", "pair", "couple", "both")),
                                key=NUMBER_WORDS.get))
"""The digits' names, each at its digit's index ("zero" at 0 ... "nine" at 9)."""
DIGIT_WORD_RE = re.compile(rf"(?i)\b(?:{'|'.join(DIGIT_WORDS)})\b")
DIGIT_WORDS_RE = re.compile(rf"(?i)(?P<noun>\b(?:numbers?|digits?|numerals?)(?:\s+(?:cubes?|blocks?))?\s+)"
                            rf"(?P<list>(?:{'|'.join(DIGIT_WORDS)})(?:\s*(?:,\s*(?:and\s+)?|\s+and\s+|\s*&\s*|\s+(?:through|thru|to)\s+|\s+)"
                            rf"(?:{'|'.join(DIGIT_WORDS)}))*)\b")
"""Digit cubes named by number words ("stack number four on number two", "the digits one, two and
three"): written as digits before the labels are read (they had been read as two coloured cubes,
and as a line of four)."""

COUNT_WORD_RE = "|".join(w for w in NUMBER_WORDS if w not in ("single", "pair", "couple", "both"))
"""The number words that say a count alone ("three", "just one is enough")."""

COLORS = sorted(set(PALETTE) | set(COLOR_ALIASES), key=len, reverse=True)
COLOR_RE = "|".join(COLORS)

INITIALLY_MISSPELT_RE = re.compile(r"(?i)\b(?:" + "|".join(sorted(w for w, right in TYPOS.items() if right == "initially")) + r")\b")
""":data:`TYPOS`' misspellings of "initially": the parser's words are corrected, but the initial-scene reader
(:func:`rpg.schema.readers.initial.split`) reads the text as written ("initialy the green cube is on top of the red cube.
take the green cube off ..." had been refused: the start read as the goal)."""

INITIALLY_RE = (rf"\binitially\b(?!\s+(?:(?:the\s+)?(?:{COLOR_RE})\s+(?:block\s+|cube\s+)?(?:is\s+|sits\s+|rests\s+|stands\s+|lies\s+)?)?(?:stacked\s+)?"
                rf"(?:on\s+top\s+of|on)\s+(?:the\s+)?(?:{COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?patch))")
""""Initially" of any starting state but one cube stacked on another ("yellow is initially on red",
"initially yellow is stacked on red": the initial states the readers build)."""

CUBE_STARTS_BESIDE_RE = (
    rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:starts?|begins?|started|began|spawns?|originates?)(?:\s+(?:out|off))?\s+"
    r"(?:(?:directly|right|just|exactly)\s+on|at\s+the\s+(?!(?:bottom|top|base|end|(?:left|right|front|back)\s+end)\b)"
    r"|(?:directly\s+|right\s+|just\s+)?(?:behind|in\s+front\s+of|next\s+to|beside|left\s+of|right\s+of|to\s+the\s+(?:left|right)\s+of|between"
    r"|under|underneath|beneath|below|above|near|far\s+from|inside|in\s+the\s+(?:[a-z]+\s+)?(?:corner|region|half|area|zone|middle"
    r"|cent(?:er|re))|on\s+the\s+(?:[a-z]+\s+)?(?:patch|side|edge|half)))"
    rf"|\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:spawns?|originates?)\b")
"""A cube said to start (or spawn) beside, behind or under another, at or in a place of the table, or right on another
("the white cube starts behind the brown cube"): a starting state rpg does not build (only one cube stacked on another); it had been read as the goal, silently,
and a goal said after it dropped."""

START_TIME_RE = (r"^(?!.*\b(?:line|row|sequence|word|spell\w*|order\w*|tower|stack|column|list)\b).*?"
                 r"\b(?P<w>at\s+the\s+(?:beginning|start))\b")
""""At the beginning" in an instruction that orders no cubes: a time (the episode's start), not
an end of a line.  Not read in a steering edit, whose "at the start" is an end of the task's line."""

BUT_CORRECTION_RE = (r"\bbut\s+(?:(?:i|we|you|they|he|she)\s+(?:would\s+|'d\s+)?(?:want|need|prefer|like|wish)|"
                     r"(?:put|place|move|set|stack|have)\s+(?:it|them)\b|(?:actually|instead|rather|on\s+second\s+thoughts?|then\s+again)\b)")
""""..., but put it on the green cube", "..., but actually I want it next to the green one" after a placement: a
correction or an addition, which one is not said ("but actually" had kept both).  Not read in a steering edit, where "but put them in a row" is the change itself."""

ROBOT_ONLY_RE = (r"\b(?:move|bring|return|send|park|put|position|raise|lower|open|close|hover|lift|rotate|extend|retract|reset)\s+"
                 r"(?:the\s+|your\s+|its\s+|the\s+robot's\s+)?(?:robot(?:ic)?\s+)?(?:grippers?|arms?|end[\s-]?effectors?|hands?|wrists?"
                 r"|fingers?|manipulators?|claws?|tool)\b"
                 r"|\b(?:home|rest|ready|neutral|parking)\s+(?:position|pose|configuration|posture)\b|\binitial\s+(?:pose|posture)\b"
                 r"|\binitial\s+(?:position|configuration)\b(?!\s*(?::|-|\u2014|is\b))"  # "Initial configuration: ..." is the cubes' start
                 r"|\bhover(?:s|ed|ing)?\b|\bgo\s+(?:back\s+)?(?:to\s+)?(?:the\s+)?home\b")
"""A motion of the robot alone ("move the gripper back to its home pose", "hover above the green
patch", "open the gripper"): no goal for the cubes (:data:`INEXPRESSIBLE`'s no_goal class)."""

TURNED_OVER_RE = (r"\bupside[\s-]+down\b|\b(?:flip|turn|roll)(?:s|ed|ped|ing|ping)?\s+(?:(?:the|a|an|it|them|that|this)\s+)?"
                  r"(?:[a-z0-9]+\s+){0,3}?over(?=\s*(?:[.,;!?]|$|and\b|then\b|\d|once\b|twice\b|again\b|two\b|three\b))")
"""A cube turned over ("flip the A cube upside down", "turn the red cube over"): a rotation, an
action the domain does not have (:data:`INEXPRESSIBLE`'s action class).  A whole instruction only:
in a steering edit "flip it upside down" reverses the structure's order."""

MOTION_RE = (r"\bback\s+and\s+forth\b|\bto\s+and\s+fro\b|\bin\s+circles\b|\band\s+back\s+again\b"
             r"|\b(?:in|into|through)\s+(?:the\s+)?(?:mid-?\s*)?air\b|\bmid-?air\b|\baloft\b"
             r"|\b(?:above|over)\s+(?:a|the)\s+(?:certain\s+|given\s+|minimum\s+)?height\b"
             r"|\b(?:hold|holds|holding|held|suspend\w*|levitat\w*|dangl\w*)\s+(?:(?:the|a|an|it|them)\s+)?(?:[a-z0-9]+\s+){0,3}?"
             r"(?:above|over|up|aloft)\b"
             r"|\bwithout\s+(?:lifting|picking|dropping|tipping|knocking|grasping|grabbing|letting)\b"
             r"|\b(?:tip|knock|push|topple)(?:s|ed|ped|ing|ping)?\s+(?:(?:the|a|an|it|them|that|this)\s+)?"
             r"(?:[a-z0-9]+\s+){0,3}?over(?=\s*(?:[.,;!?]|$|and\b|then\b|\d|once\b|twice\b|again\b|two\b|three\b))")
"""A motion or a pose off the table ("slide it back and forth", "hold the cube above the patch",
"knock the tower over"): an action the domain
does not have (:data:`INEXPRESSIBLE`'s action class)."""

MOTION_WHY = ("is a motion or a pose off the table, an action the domain does not have: a task's goal says where cubes "
              "end up, each resting upright on the table, a patch or another cube; say that end state")
"""Why :data:`MOTION_RE` and :data:`TURNED_OVER_RE` are refused (one reason for both)."""

INSTRUCTION_ONLY = frozenset({START_TIME_RE, BUT_CORRECTION_RE, TURNED_OVER_RE})
""":data:`INEXPRESSIBLE` patterns that hold for a whole instruction only (see each)."""

VIEWPOINT_RE = (r"\b(?:(?:as\s+)?(?:seen|viewed|looked\s+at)\s+from|looking\s+(?:at\s+(?:the\s+table|it)\s+)?from|from)\s+(?:the\s+)?"
                r"(?:front\s+|overhead\s+|top\s+|side\s+|main\s+)?(?:camera|viewer|observer|spectator|audience|user)(?:'s)?"
                r"(?:\s+(?:point\s+of\s+view|perspective|side|view|position))?\b"
                r"|\bfrom\s+(?:my|your|our)\s+(?:side|point\s+of\s+view|perspective|seat|position|view)\b"
                r"|\b(?:as|when)\s+(?:you|i|we)\s+(?:look\s+at|face|see|view)\b"
                r"|\b(?:to|on)\s+(?:your|my|our)\s+(?:left|right)\b|\b(?:your|my|our)\s+(?:left|right)(?:-hand)?(?:\s+side)?\b"
                r"|\b(?:standing\s+)?where\s+the\s+camera\s+(?:sits|is|stands)\b|\bin\s+the\s+camera(?:'s)?\s+(?:image|view|frame|picture)\b"
                r"|\bthe\s+camera's\s+(?:left|right)\b")
"""Left and right said from a viewer other than the robot ("from the camera", "your left", "as you face the table"):
rpg's left and right are the robot's (its left is +y, :mod:`rpg.domain.constants`); the snapshot camera behind the
robot shares them and the agentview camera across the table mirrors them, so which side a viewer means is not known
(refused, naming the robot's frame; "from the robot's point of view" is read)."""

VIEWPOINT_WHY = ("says left or right from a viewer other than the robot: rpg's left and right are the robot's (the "
                 "snapshot camera behind it shares them, the agentview camera facing it mirrors them), so that viewer's side "
                 "is not known; say it from the robot (e.g. \"on the robot's left\", \"to the left of the blue cube as the "
                 "robot sees it\")")

ROBOT_VIEWPOINT_RE = re.compile(r"(?:^|(?<=[.;:!?]\s))(?:(?:as\s+)?(?:seen|viewed|looked\s+at)\s+from|looking\s+(?:at\s+(?:the\s+table|it)\s+)?"
                                r"from|from)\s+the\s+robot(?:'s)?(?:\s+(?:point\s+of\s+view|perspective|side|view|position|base))?\s*,\s*")
"""A viewpoint that is the robot's ("From the robot's point of view, ...", "Seen from the robot, ..."): rpg's own
frame, dropped before viewpoints are refused."""

FRONT_GLOSS_RE = re.compile(r"\b(?P<r>(?:at|on|in|to|toward|towards)\s+the\s+(?:front|near\s+(?:side|edge))(?:\s+(?:side|edge|half|part))?"
                            r"(?:\s+of\s+the\s+(?:table|workspace))?)\s*,?\s+(?:(?:right\s+)?(?:near|nearest|close\s+to|closest\s+to|by)"
                            r"|(?:(?:the\s+)?(?:side|part|half|edge)\s+)?(?:nearest|closest)(?:\s+to)?)\s+(?:the\s+|our\s+|your\s+)?robot\b")
"""The front said again as the robot's side ("at the front of the table, near the robot", "..., the side nearest the
robot"): one region, its gloss dropped (it had been read as the front twice, refused as a cube repeated)."""

MEANS_CLAUSE_RE = re.compile(r"(?i)\b(?:clear|free|uncover|expose|unblock)\s+(?:the\s+|a\s+)?(?:[a-z]+\s+)?(?:block|cube)\s*,?\s+by\s+"
                             r"(?P<v>putting|placing|moving|setting|taking|lifting|stacking)\b")
"""A goal said with its means ("clear the white block by putting the green block on the table"): the means is the end
state said, read as the command ("put the green block on the table"); the end it serves is what the means makes."""

MEANS_VERBS: dict[str, str] = {"putting": "put", "placing": "place", "moving": "move", "setting": "set", "taking": "take",
                               "lifting": "lift", "stacking": "stack"}
"""The gerund of a means clause (:data:`MEANS_CLAUSE_RE`) -> its imperative."""


def means_said(text: str) -> str:
    """``text`` with a goal said by its means read as the means (:data:`MEANS_CLAUSE_RE`); used on the goal and in the
    start reader alike.  A means that puts a cube on the cube it clears ("clear the white block by putting the green block
    on the white block") is left as written (refused)."""
    def means(m: re.Match) -> str:
        cleared = re.search(rf"(?i)\b({COLOR_RE})\s+(?:block|cube)\s*,?\s+by\b", m.group(0))
        rest = re.match(r"[^.;!?]*", text[m.end():]).group(0)
        if cleared and re.search(rf"(?i)\b(?:on|onto|atop)\s+(?:top\s+of\s+)?(?:the\s+)?{cleared.group(1)}\b", rest):
            return m.group(0)
        return MEANS_VERBS[m.group("v").lower()]
    return MEANS_CLAUSE_RE.sub(means, text)

DAYS_TASK_RE = re.compile(r"(?i)\b(?:today|tonight|this\s+(?:morning|afternoon|evening|week)|tomorrow)'s\s+"
                          r"(?=(?:exercise|task|challenge|goal|job|assignment|activity|drill|puzzle|lesson|warm-up)\b)")
"""A task named by its day ("Today's exercise is a tower of ..."): "the exercise" (the day says nothing of the goal)."""

ROBOT_TURN_RE = re.compile(
    r"(?i)(?:(?<=[.!?;]\s)|(?<=\s-\s)|(?<=\s[\u2013\u2014]\s)|(?<=,\s))(?:(?:and|but|so|then)\s+)?(?:(?:now|ok(?:ay)?|right|alright)\s*,?\s+)?"
    r"(?:(?:and\s+)?(?:as\s+)?for\s+(?:(?:the|our|my)\s+|you,?\s+(?:the\s+)?)robot|(?:hey\s+|ok(?:ay)?\s+|now\s+)?robot"
    r"|(?<=now\s)(?:for\s+)?the\s+(?:cubes|blocks)|(?:on\s*to|back\s+to|as\s+for)\s+the\s+(?:cubes|blocks))\s*[:,\u2013\u2014]\s*(?=\S)"
    r"|(?:(?<=[.!?;]\s)|(?<=,\s))(?:(?:and|but|so)\s+)?(?:meanwhile|in\s+the\s+meantime)\s*[:,\u2013\u2014]?\s+(?=\S)")
"""A turn from a voice's own world to the robot or the cubes in the middle of a text ("Take one capsule twice daily with
food. And for the robot: put ...", "Nurse, keep the field sterile. Robot, place ...", "Dosage double-checked. Now the
cubes: ...", "Closing the incision, three sutures. Meanwhile the yellow cube goes ..."): what comes before it is said to someone else or of the speaker's world, and is dropped by
:func:`rpg.schema.reading.drop_asides` when it names nothing of a goal and takes nothing back
(:data:`ROBOT_TURN_HAZARD_RE`)."""

ROBOT_TURN_HAZARD_RE = re.compile(
    r"\b(?:robot\w*|arm|gripper|task|goal|instructions?|following|below|after\w*|then|next|later|first|before|instead|except|unless"
    r"|opposite|revers\w*|mirror\w*|backwards?|same|other|others|rest|again|also|too|both|them|they|their|these|those|everything"
    r"|anything|nothing|it|its|quick\w*|fast\w*|hurr\w*|rush\w*|slow\w*|careful\w*|gentl\w*|soft\w*|seconds?|minutes?|hours?|time"
    r"|within|timer|soon|immediately|don't|do\s+not|never|no|not|words?|spell\w*|reads?|make|makes|made|build\w*|built|invert\w*"
    r"|vice|versa|like|as|shown|setup|set-up|version|copy|copies|total|high|tall|levels?|half|bigger|smaller|larger|times"
    r"|centred|centered|cent(?:er|re)|spaced|diagonal\w*|vertical\w*|horizontal\w*|sort\w*|shuffl\w*|hue|rainbow|alphabet\w*"
    r"|ascend\w*|descend\w*|upside|sideways|flip\w*|swap\w*|rotat\w*|turn\w*|oops|correction|if|when|whenever|until|till|unless"
    r"|provided|providing|case|long|pause\w*|wait\w*|beforehand|max\w*|min|mins|minimum|limit\w*|spac\w*|cm|mm|inch\w*|secs?"
    r"|routine|procedure|drill|exercise|process|sequence|steps?|pieces?|items?|objects?|things?|stuff|duplicates?|replicas?|jumbo"
    r"|size\w*|north\w*|south\w*|east\w*|west\w*|lean\w*|tilt\w*|style|pattern\w*)\b")
"""What keeps the words before a turn to the robot (:data:`ROBOT_TURN_RE`) from being dropped: the robot or the task
named, a sequence or a pointer to what follows, a reversal, a comparison, a pronoun that may stand for cubes, a manner,
time or negation that may be the robot's ("Make it quick. Robot, ...") (besides the take-backs of :data:`RETRACTION_RE`
and any word of a goal)."""

WORLD_TIME_CLAUSE_RE = re.compile(
    r"(?i)(?:^|(?<=[.!?]\s)|(?<=[,;:]\s))(?:and\s+)?(?:while|whilst|before|after|once)\s+(?P<c>[^,.;:!?()\"]{2,60}?)\s*(?:[,:;]|\s[-\u2013\u2014])\s+(?=\S)")
"""A clause of time about the speaker's world before the task ("While the glaze sets, put ...", "Listen, apprentice, while the
forge heats up: set ...", "While I'm away, please put ..."): dropped by :func:`rpg.schema.reading.drop_asides` where it names
nothing of the task (:data:`WORLD_TIME_HAZARD_RE`), so it can time or condition nothing a goal holds; one that does ("while
the red cube stays on blue", "until it is on the patch", "after that") stays, and is refused for its time."""

WORLD_TIME_HAZARD_RE = re.compile(
    r"\b(?:it|its|itself|they|them|their|this|that|these|those|there|here|one|ones|each|every|all|both|other|others|rest|robot|arm"
    r"|gripper|hand|hands|policy|agent|episode|task|goal|scene|table|timer|clock|seconds?|minutes?|hours?|steps?|moves?|tries|try"
    r"|attempts?|done|finish\w*|complet\w*|ready|start\w*|begin\w*|end\w*|stop\w*|fall\w*|fell|drop\w*|slid\w*|slip\w*|tip\w*"
    r"|topple\w*|collaps\w*|move\w*|moving|stack\w*|plac\w*|put\w*|build\w*|reach\w*|touch\w*|grasp\w*|pick\w*|lift\w*)\b|\d")
"""Words that keep a clause of time (:data:`WORLD_TIME_CLAUSE_RE`) as part of the task: the task's things, references,
the robot, the episode, a measure of time, a step of manipulation."""

CONCESSION_OPENING_RE = re.compile(
    r"(?i)(?:^|(?<=[.!?]\s))(?:it|this|that)\s*(?:(?:'s|is|may|might|could|can|will|would)\s+)?(?:be\s+)?"
    r"(?:take\s+(?:a\s+(?:little\s+)?while|a\s+bit|patience|practice|a\s+few\s+tries)"
    r"|(?:a\s+bit\s+|a\s+little\s+|quite\s+|pretty\s+|rather\s+|very\s+)?(?:tricky|hard|difficult|fiddly|tough|challenging|awkward))"
    r"\s*,?\s+but\s+")
"""A concession of the task's effort before it ("It may take a while, but put ...", "This is a bit tricky, but ..."): no
constraint of the goal ("while" had been refused as a time; "it" as a reference); a time said ("It should take under a
minute, but ...") is no concession and stays."""

OPENING_ADJUNCT_RE = re.compile(
    r"(?i)(?:^|(?<=[.!?]\s))(?P<a>(?P<prep>for|per|in)\s+(?P<np>[a-z][a-z'\-]*(?:\s+[a-z][a-z'\-]*){0,3}?)"
    r"|(?P<np2>[a-z][a-z'\-]*)\s+aside)"
    r"(?:\s*,\s*|\s+(?=(?:i|we)\s+(?:need|want|would\s+like|require)\b|(?:i|we)'d\s+like\b"
    r"|(?:the\s+(?:robot|agent|policy|arm)|you)\s+(?:must|should|will|needs?\s+to|has\s+to|have\s+to)\b))(?=\S)")
"""A sentence's opening adjunct of purpose, source or occasion in a voice's world ("For the keyframes I need a row of
...", "For this mosaic panel I want ...", "Per the thesaurus, ...", "Etymology aside, ...", "In this trial the agent must
..."): dropped by :func:`rpg.schema.reading.drop_asides` where its noun phrase says nothing of the task
(:func:`rpg.schema.reading._opening_adjunct`).  Its unknown words had refused the task."""

OPENING_ADJUNCT_DETERMINERS = frozenset({"the", "this", "that", "these", "those", "my", "our", "your", "his", "her", "their",
                                         "a", "an", "today's"})
"""Determiners an opening adjunct's noun phrase (:data:`OPENING_ADJUNCT_RE`) may begin with."""

OPENING_ADJUNCT_HAZARD_RE = re.compile(
    r"\b(?:it|its|they|them|one|ones|each|every|all|both|either|neither|other|others|rest|remainder|remaining|same|former"
    r"|latter|last|next|previous|first|second|third|final|no|not|none|nothing|never|without|except|case|instead|change|time"
    r"|times|while|moment|now|once|twice|long|later|soon|ever|good|sake|order|way|ways|side|sides|end|ends|middle|top|bottom"
    r"|start|finish|goal|task|episode|table|robot|agent|policy|arm|gripper|hand|hands"
    # a person or a viewpoint whose frame "left" or "in front" may be ("For the viewer, put ... left of ...")
    r"|me|you|us|him|her|everyone|everybody|anyone|someone|people|person|persons|human|humans|man|men|woman|women|child"
    r"|children|kids?|family|guests?|audience|crowd|public|class|team|client|friends?|mom|dad|boss|viewpoint|perspective"
    r"|view|eyes?|camera|cameraman|frame|direction|handedness|chirality|orientation|angle"
    # a picture or document the text leans on ("Per the schematic, build a wall of six cubes")
    r"|schematics?|examples?|templates?|models?|references?|samples?|specs?|specifications?|demonstrations?|demos?"
    r"|diagrams?|drawings?|pictures?|photos?|images?|sketch\w*|plans?|blueprints?|notes?|instructions?|manuals?|guides?"
    r"|charts?|maps?|layouts?|designs?|patterns?|figures?|videos?|recordings?|screenshots?|illustrations?|schemes?|sheets?"
    # a start state ("For the setup I need ...")
    r"|setups?|set-up|precondition\w*|prerequisite\w*|opening|prior|source|starting|initial\w*|beginning|before|current"
    r"|present|state|states|scene|scenes|configuration\w*|arrangement\w*"
    # what is not wanted, or turned ("For the counterexample, ...", "In this reflected setup, ...")
    r"|negation|negative|counter\w*|incorrect|wrong|converse|contrary|antithesis|decoy|trap|mistakes?|errors?|problems?"
    r"|issues?|bugs?|failures?|risks?|danger|fears?|nightmares?|opposite|inverse|reverse\w*|anti\w*|reflect\w*|mirror\w*"
    r"|transpos\w*|flip\w*|invert\w*|rotat\w*|southpaw|antipodal|upside"
    # several of the task ("In this duplicated trial, ...")
    r"|multiple|several|many|twins?|triplets?|quadruplets?|duplicat\w*|double\w*|paired|pairs?|cop(?:y|ies)|replicas?)\b")
"""Words that keep an opening adjunct (:data:`OPENING_ADJUNCT_RE`) as part of the task: a reference or quantifier ("For each
of them", "For the last one"), a negation, a condition ("In that case"), a time ("For a while", "For now"), an order,
side or end ("For the other side"), the task's own things; a person or viewpoint whose frame a relation may be in ("For
the viewer"), a picture or document the task leans on ("Per the schematic"), a start state ("For the setup"), a state
not wanted or turned ("For the counterexample", "In this reflected setup"), copies of the task (a hostile helper's)."""

OPENING_ADJUNCT_PERSON_RE = re.compile(r"[a-z]{3,}(?:er|or|ist|ian|ess|ant|ent)s?")
"""A noun that may name a person ("viewer", "spectator", "mosaicist", "photographer"): an opening adjunct with one is kept
(a relation may be in that person's frame)."""

DISCOURSE_OPENING_RE = re.compile(r"(?i)^\s*(?:(?:so|ok(?:ay)?|well|right)\s*,?\s+)?(?:anyway|anyways|anyhow)\s*,\s+(?=\S)")
"""A text's opening "Anyway," ("Anyway, pop the yellow cube on the green patch."): it turns the talk to the task and says
nothing of its goal (its word had been refused as unknown).  Only at the text's start: inside it, "anyway" may set
aside what was said before, and stays (:data:`RETRACTION_RE`)."""

TURNING_LABEL_RE = re.compile(
    r"(?i)\b(?:(?:bad|wrong|incorrect|counter|anti|non|negative|failed|failing)[\s-]*(?:examples?|demos?|cases?|goals?|answers?|approach\w*)"
    r"|counter-?examples?|non-?goals?|forbid\w*|prohibit\w*|banned|off\s+limits|trap|bait|myth|fake|false|danger\w*|pitfall|mistakes?"
    r"|invers\w*|bizarro|inside[\s-]out|opposite|mirror\w*|revers\w*|backwards?|upside|permitting|allowing|optional|maybe|perhaps"
    r"|jumbo|mini|mega|giant|triple|double|decker|views?|perspective|looking|seen\s+from"
    # (a hostile helper's probes, forty-fourth session: labels that make the edit optional, hypothetical, old or rejected)
    r"|optionally|possibl[ey]|ideal(?:ly)?|extra\s+credit|hypothetic\w*|reject\w*|alternativ\w*|preferabl[ey]"
    r"|nice\s+to\s+have|priority|ignore\w*|avoid\w*|wrong|later|scrapped|conditional\w*|obsolete|deprecated)\b")
"""A label before a colon that judges, turns, conditions or sizes what follows ("Bad example:", "Inverse version:", "Time
permitting:", "Mega version:", "Audience view:"): it is never dropped as a label (it had been, and the task compiled as if
unsaid); the words then refuse."""

FRAMING_SENTENCE_HAZARD_RE = re.compile(
    r"\b(?:not|no|never|none|nothing|nobody|nowhere|neither|nor|without|except|unless|avoid\w*|[a-z]+n't|cannot"
    r"|should|must|shall|need|needs|needed|has\s+to|have\s+to|had\s+to|ought|require\w*|want\w*|expect\w*|make\s+sure"
    r"|then|after|afterwards?|next|finally|later|before|first|second|third|last|again|once|twice|thrice|times|repeat\w*"
    r"|more|less|fewer|most|least|many|much|several|few|only|same|other|another|else|different|instead|rather|vice|versa"
    r"|revers\w*|invert\w*|backwards?|opposite|undo|redo|reset|revert|keep|keeps|kept|stay\w*|remain\w*|leave|leaves|left|alone|still|already"
    r"|upside|sideways|diagonal\w*|mirror\w*|flip\w*|rotat\w*|turn\w*|swap\w*|switch\w*|shuffl\w*|scatter\w*|spread\w*"
    r"|tid(?:y|ied|ies)|clean\w*|clear\w*|knock\w*|toppl\w*|tilt\w*|fac(?:e|es|ed|ing)|vertical\w*|horizontal\w*|straight\w*"
    r"|neat\w*|tight\w*|touch\w*|close|closer|away|apart|together|align\w*|square|round|around|up|down|over|inside|outside"
    r"|second|seconds|minutes?|hours?|fast|faster|quick\w*|slow\w*|within|timer|time|hurry|soon"
    r"|it|its|itself|they|them|their|those|these|everything|something|each|all|both|either|one|ones|everyone"
    r"|same|every|alternat\w*|rainbow|gradient|sort\w*|ascending|descending|increasing|decreasing|alphabetic\w*|order\w*"
    r"|colou?r\w*|shade\w*|size|big|bigger|small|smaller|large|tall|high|low|wide|long|short|jumbo|giant|huge|tiny|mini|oversized"
    r"|beneath|underneath|atop|upon|against|adjacent|across|along|beyond|past|toward|towards|via|through|off|out|flat|lying|lie|lay"
    r"|offset|centred|centered|spaced|evenly|equal\w*|distance|far|near|nearby|by|beside|opposite|corner\w*|edge\w*|diagonal\w*"
    r"|mean|meant|correction|actually|oops|scratch|wait|instead|typo|rather|i\s+mean|return\w*|restor\w*|put|place|move|skip\w*|declin\w*)\b"
    r"|\d")
"""What keeps a sentence that names nothing of the task (no :data:`TASK_CONTENT_RE`, :data:`ASIDE_CONTENT_RE` word)
from being dropped as framing by :func:`rpg.schema.reading.drop_asides`: a negation, a requirement, a step of a
sequence, a repetition or quantity, a reversal or another change of the scene, a manner or pose, time, a pronoun or
quantifier that may stand for cubes, an order, a colour, a size or a number.  Such a sentence may change what the task
asks ("Then reset.", "Nothing else may move.", "Twice.", "Quickly."), so it stays, to be read or refused."""

SCENE_CHANGING_VERBS: frozenset[str] = frozenset("""
mix stir scramble jumble shuffle scatter spread demolish destroy wreck break smash crush dismantle disassemble unstack
topple knock tip tilt hide cover uncover remove throw toss drop spill pour spin rotate turn flip roll return restore
reset undo sweep collect gather separate split divide group combine merge join attach connect insert fill empty lift
raise lower push pull slide shift carry bring take grab hold pick stack pile place put move set arrange build make line
assemble construct form create stand lay rest balance swap switch exchange reverse invert mirror sort order clear clean
tidy keep leave stay remain repeat continue finish start begin complete align centre center space close open shake
""".split())
"""Verbs that, said in a sentence naming no cube, may still change what the scene must become ("Mix well.", "Then
scramble.", "Hide the evidence."): such a sentence is never dropped as commentary
(:func:`rpg.schema.reading.drop_asides`), matched by lemma."""

OPERATOR_SCENE_VERBS: frozenset[str] = frozenset(
    "start begin continue finish complete repeat open close hold stand turn set take make form create keep leave stay remain rest".split())
""":data:`SCENE_CHANGING_VERBS` that a sentence said to a person uses of other things ("Start recording.", "Take a
picture.", "Hold on."): they keep no framing sentence (:func:`rpg.schema.reading._framing_sentence`); the rest do
("Unstack.", "Remove.", "Scatter them.")."""

TASK_SCENE_VERBS: frozenset[str] = SCENE_CHANGING_VERBS - OPERATOR_SCENE_VERBS
"""The :data:`SCENE_CHANGING_VERBS` that keep a framing sentence: all but :data:`OPERATOR_SCENE_VERBS`."""

RETRACTION_RE = re.compile(r"\b(?:kidding|joking|jokes?|jk|ignore\w*|forget|scrap|cancel\w*|disregard\w*|nevermind|never\s+mind|skip\w*|declin\w*"
                           r"|april\s+fools?|fooled|pretend\w*|lie|lying|strike|delete|erase|withdraw\w*|retract\w*|that|this|those|these"
                           r"|false|alarm|mistakes?|wrong|topsy|turvy|whichever|whatever|anything|anyhow|anyway|ways?|arrangement\w*"
                           r"|goes|height|heights|taller|shorter|higher|lower|bigger|smaller|better|worse|best|bonus|extra|credit|points?)\b")
"""Words by which a sentence may take back or point at what was said ("Just kidding.", "Ignore that.", "April fools."):
such a sentence is never dropped as a voice's commentary (:func:`rpg.schema.reading.drop_asides`)."""

COMMENTARY_BLOCKING_KINDS: frozenset[str] = frozenset({"negation", "time", "quantity", "size", "shape", "reference",
                                                       "contradiction", "same_colour", "alternative", "no_goal", "colour"})
""":data:`INEXPRESSIBLE` classes (and the colour class) that keep a sentence naming no cube from being dropped as
commentary: each may bear on the goal ("Never twice.", "Under a golden sky."); an object, an action on no cube, a
condition on a person or a question to one ("Serve with a smile.", "What do you do?") bears on none."""

VOICE_SENTENCE_HAZARD_RE = re.compile(
    r"\b(?:it|its|itself|they|them|their|theirs|those|these|this|that|everything|something|anything|nothing|each|every|all"
    r"|both|either|neither|one|ones|rest|remaining|else|other|others|another|same|different|whole|entire|any|some|none"
    r"|robot\w*|gripper|arm|camera|table|scene|task|goal|episode|state|result|outcome|done|complete\w*|finish\w*|end|ends"
    r"|quick\w*|fast\w*|slow\w*|hurr\w*|rush\w*|seconds?|minutes?|hours?|within|timer|time|soon|immediately|until|till"
    r"|again|once|twice|thrice|times|repeat\w*|more|less|fewer|most|least|many|much|several|few|only|dozen|extra|exactly"
    r"|upside|sideways|diagonal\w*|flip\w*|rotat\w*|turn\w*|tilt\w*|fac(?:e|es|ed|ing)|vertical\w*|horizontal\w*|lean\w*"
    r"|lying|lie|lay|flat|order\w*|sort\w*|revers\w*|backwards?|opposite|mirror\w*|invers\w*|alternat\w*|ascending"
    r"|descending|alphabetic\w*|rainbow|gradient|first|second|third|last|next|previous\w*|earlier|usual|follow\w*|below"
    r"|size|big\w*|small\w*|large\w*|tall\w*|tiny|huge|giant|height|colou?r\w*|shade\w*|hue\w*|shape\w*|form|pattern\w*"
    r"|spiral|triangle\w*|cross|zigzag|diamond|star|heart|arrow|letter|word|spell\w*|example\w*|counter\w*|wrong|incorrect"
    r"|nobody|no-one|anybody|anyone|score\w*|grad(?:e|es|ed|ing)|judg\w*|mark(?:s|ed)?|points?|signal\w*|wait\w*|await\w*"
    r"|bad|mistake\w*|error\w*|view\w*|perspective|north\w*|south\w*|east\w*|west\w*|clockwise|anticlockwise"
    r"|counterclockwise|instead|rather|mean|meant|actually|oops|correction|typo|undo|redo|reset|revert|return\w*"
    r"|restor\w*|swap\w*|switch\w*|exchange\w*|then|after|afterwards?|later|finally|before|must|should|shall|need\w*"
    r"|require\w*|ensure\w*|sure|want\w*|expect\w*|avoid\w*|prevent\w*|without|careful\w*|gentl\w*|neighbo\w*|adjacent"
    r"|touch\w*|contact\w*|collisions?|collid\w*|gaps?|spac\w*|distance\w*|apart|together|away|close\w*|evenly|straight"
    r"|align\w*|offset|askew|crooked|overhang\w*|stagger\w*|perched|precarious\w*|teeter\w*|kiss\w*|nestl\w*|snug\w*"
    r"|wedged|level\w*|neat\w*|tight\w*|centred|centered|roof|lid|cap|crown|topped|fall\w*|fell|wobbl\w*|steady|stabl\w*"
    r"|balanc\w*)\b")
"""What keeps a sentence that names nothing of a goal from being dropped as a voice's own world
(:func:`rpg.schema.reading._voice_sentence`: "No running on deck!", "No late fees today.") though it has a verb of its
own: a pronoun or quantifier that may stand for the cubes or the task, the robot, the table, the task's end, time or
speed, a repetition or quantity, a pose, spacing or contact, an order, a size, a colour, a shape, a judgement of an
example, a viewpoint, a take-back, a change of the scene, a further step ("Then celebrate."), a requirement, a care or
the structure's standing ("Must be neighbours.", "Avoid collisions.", "Needs a roof.", "No wobbling.").  Such a sentence
may bear on the task ("Do it twice.", "Faster!", "Nothing else.", "Then reset."), so it stays, to be read or refused.
Negations, places and persistence ("stay", "keep") are not listed: without one of these words they can only be of the
voice's own world ("No running on deck!", "The lifeguard stays on duty.")."""

WORLD_STATEMENT_OWN_RE = re.compile(r"\b(?:slow\w*|quick\w*|fast\w*|hurr\w*|rush\w*|pace\w*|patien\w*|careful\w*|gentl\w*"
                                    r"|never|not|no|always|its\s+own|can\s+wait)\b")
"""Words of manner and negation that a statement about a third party of a voice's world holds as that party's own
("Varnish dries at its own pace.", "A good bookbinder never rushes the press.", "A luthier chooses tonewood slowly.",
"Sewing can wait"; a party that will not wait, or comes soon, may set the task a time: "The clock never waits."):
weighed out before :data:`VOICE_SENTENCE_HAZARD_RE` in :func:`rpg.schema.reading._world_statement` (said to the one who
does the task, "Go slowly.", "Never rush.", they stay, to be refused)."""

WORLD_SUBJECT_QUANTIFIERS: frozenset[str] = frozenset({"every", "each", "any"})
"""Quantifiers that may open a world statement's subject: they count the world's things, not the cubes."""

WORLD_SUBJECT_DETERMINERS: frozenset[str] = frozenset({"a", "an", "the", "my", "our", "his", "her", "their"}) | WORLD_SUBJECT_QUANTIFIERS
"""Determiners that may open the subject of a statement about a voice's world ("A luthier chooses ...", "The canal is
calm.", "Every stonemason starts with the footing."; a quantifier there counts the world's things, not the cubes)."""

WORLD_SUBJECT_HAZARD_WORDS: frozenset[str] = frozenset("""
task tasks job jobs goal goals work result results outcome outcomes policy policies episode episodes trial trials run runs
robot robots arm arms gripper grippers hand hands camera cameras table tables scene scenes setup layout workspace structure
order sequence arrangement spacing symmetry alignment position positions placement orientation size height number count
speed time timing accuracy precision neatness quality everything nothing anything something rest point answer instruction
instructions rule rules step steps plan way trick secret key idea patience care gentleness caution haste hurry slowness
quickness steadiness balance stability tidiness cleanliness safety bot bots machine machines agent agents controller
controllers claw claws model models android androids cobot cobots manipulator manipulators picker pickers grabber grabbers
team teams player players operator operators clock clocks timer timers buzzer buzzers deadline deadlines stopwatch
stopwatches whistle whistles bell bells alarm alarms
""".split())
"""Subjects that may be the task, the one who does it, its time or a demand on it ("Speed matters.", "Order is key.", "The
bot never rushes.", "The clock never waits."): a sentence
about one of them, or about a manner the task may be asked to have ("Patience is key."), is no statement of a voice's own world (:func:`rpg.schema.reading._world_statement`)."""

WORLD_FINITE_WORDS: frozenset[str] = frozenset("""
is are was were can will may might would could has have had does do did never always often rarely seldom usually
sometimes
""".split())
"""Words that may follow the subject of a statement and make it one ("Sewing can wait.", "A bookbinder never rushes ...")."""

WORLD_OPENING_PLACE_RE = re.compile(r"^(?:[a-z]+\s+)?(?:in|at|on|inside|under|beneath|across|along|through|out\s+on|out\s+in"
                                    r"|up\s+on|down\s+in)\s+(?:the|a|an|my|our|this)\s+(?P<n>[a-z'\-]+)\s*,?\s+")
"""A place of a voice's world before a statement's subject ("Deep in the cavern the stalagmites grow slowly."): read past
when its noun is none of the domain's."""

VOICE_WORLD_VERBS_EXEMPT: frozenset[str] = frozenset({"stay", "remain", "keep", "leave"})
"""Verbs of :data:`SCENE_CHANGING_VERBS` that a sentence of a voice's own world may hold ("The lifeguard stays on duty.",
"The crowd remains seated."): with nothing in the sentence they could act on (:data:`VOICE_SENTENCE_HAZARD_RE`)
they persist a person or a place, not a scene (said to the one who does the task, "Stay low.", they stay refused)."""

NARRATOR_OPENING_RE = re.compile(r"^\W*(?:(?:well|oh|so|and|but|now|meanwhile|anyway|honestly|personally)\s*,?\s+)*"
                                 r"(?:i|we|i'm|i'll|i've|i'd|we're|we'll|we've|we'd|(?:my|our)\s+[a-z'\-]+)\b")
"""A sentence told by the speaker of a voice ("I'll see you later.", "My train leaves soon."): its subject is not the
one who does the task, so a step of a sequence in it orders the speaker's day (:data:`NARRATION_FREE_RE`), when it names
nothing of the task (:func:`rpg.schema.reading._voice_sentence`)."""

NARRATION_FREE_RE = re.compile(r"\b(?:then|after|afterwards?|later|finally|before|meanwhile|soon|while)\b")
"""Words of a sequence in :data:`VOICE_SENTENCE_HAZARD_RE` that a sentence the speaker tells of themselves
(:data:`NARRATOR_OPENING_RE`) may hold: they order the speaker's day, not the task.  A clock time, a wish or a condition
stays ("I need results by noon.", "I want no scratches.", "I'll pay double if you're early.": a hostile helper's)."""

REGARD_VERBS: frozenset[str] = frozenset("""
enjoy mind heed watch love like bless thank thanks remember consider imagine respect trust welcome excuse pardon forgive
believe know hope wish mark note
""".split())
"""Verbs of attention, feeling or courtesy, which act on no thing: an imperative of a voice's own world with one of them
and a thing ("Mind the gap.", "Enjoy the park!") asks nothing of the scene (:func:`rpg.schema.reading._voice_sentence`),
unlike an imperative on a thing ("Wipe the whiteboard.")."""

VOICE_LABEL_RE = re.compile(r"^\s*(?P<c>[^.!?:;()\"]{2,70}?)\s*:\s+(?=\S)")
"""A voice's label before a task, up to the text's first colon ("Site diary, day six: ...", "Runway-ready look: ...",
"Swarm-season tip from the apiary: ..."): dropped by :func:`rpg.schema.reading.drop_voice_chunks` when
:func:`rpg.schema.reading._voice_chunk` finds it inert."""

ABSOLUTE_STATE_WORDS: frozenset[str] = frozenset("on off up down in out ready set lit".split())
"""States a voice's absolute phrase gives a thing of its world ("Helmet on, arc struck:", "Mask down, torch lit:"), besides
a past participle: :func:`rpg.schema.reading._absolute_phrases`."""

VOICE_TAIL_RES: tuple[re.Pattern[str], ...] = (
    re.compile(r"(?P<sep>\s*,\s*|\s+[-\u2013\u2014]+\s+|\s+(?=(?:just\s+)?like\s))"
               r"(?P<c>(?:just\s+)?like\s+[^,;:.!?()]{2,80}|as\s+per\s+[^,;:.!?()]{2,60}|the\s+way\s+[^,;:.!?()]{2,80}"
               r"|(?:as\s+)?[a-z]+\s+as\s+(?:a|an|the|two|three|four|five|six|[a-z]+s)\b[^,;:.!?()]{0,60})(?P<end>[.!?]*)\s*$"),
    re.compile(r"(?P<sep>\s*,\s*|\s+[-\u2013\u2014]+\s+)(?P<c>[^,;:.!?()]{2,60})(?P<end>[.!?]*)\s*$"),
)
"""A chunk at a sentence's end in a voice, tried in turn: a simile ("..., like a bee's stripes.", "... in a row like
climbers on a fixed rope.", "..., steady as a belay.", "..., as per the site plan."), then any chunk set off by a comma
or a dash ("... - monochrome is so in right now.", "..., our high camp."): dropped by
:func:`rpg.schema.reading.drop_voice_chunks` when :func:`rpg.schema.reading._voice_chunk` finds it inert."""

NAMING_TAIL_RE = re.compile(r"(?i)(?:that's|that\s+is|which\s+is|this\s+is)\s+(?:the|my|our|your|his|her|their)\s+"
                            r"(?P<n>[a-z][a-z'\-]*(?:\s+[a-z][a-z'\-]*){0,2})")
"""A chunk at a sentence's end that names what the sentence did ("..., that's the pot"): weighed by
:func:`rpg.schema.reading._naming_tail`."""

NAMING_TAIL_HAZARD_RE = re.compile(r"\b(?:test|tests|control|draft|rehearsal|practice|trial|axis|horizon|diagonal|footing|plinth"
                                   r"|foundation|base|basement|ground|floor|starboard|port|bow|stern|north|south|east|west|maximum|minimum"
                                   r"|limit|max|min|start|finish|end|before|after|target|answer|solution|key)\b")
"""Nouns a closing "that's the ..." may not name without bearing on the task (:func:`rpg.schema.reading._naming_tail`): a
trial or an unfinished state, an axis or a side, a part of something more, a limit, the answer (a hostile helper's)."""

VOICE_OPENING_SIMILE_RE = re.compile(r"^\s*(?P<c>(?:just\s+)?like\s+[^,;:.!?()]{2,80}?)\s*,\s+(?=\S)", re.IGNORECASE)
"""A simile before a task ("Like laying shingles from the eaves to the ridge, build a tower: ..."): dropped by
:func:`rpg.schema.reading.drop_voice_chunks` when :func:`rpg.schema.reading._voice_chunk` finds it inert, as one at a
sentence's end (:data:`VOICE_TAIL_RES`), it names no place or side (:data:`OPENING_SIMILE_PLACE_RE`), and a way it runs
("from the ridge to the eaves") is said again by the task itself (:data:`DIRECTION_SAID_RE`)."""

OPENING_SIMILE_PLACE_RE = re.compile(r"\b(?:middle|cent(?:er|re)|left|right|front|back|corner|edge|side|top|bottom|above|below|under"
                                     r"|over|behind|beside|near|next|between|around)\b")
"""Places and sides that keep an opening simile ("Like an island in the middle, ..."): they may place the task."""

VOICE_SIMILE_OPENING_RE = re.compile(r"^(?:just\s+)?like\s+(?!(?:in|at|on|onto|to|near|next|behind|beside|under|over|above|below|right|left"
                                     r"|just|really|so|this|that|here|there|before|last|always|usual|normal|i|we|you)\b)|^as\s+per\b|^the\s+way\b|^(?:as\s+)?[a-z]+\s+as\b")
"""How a simile chunk of :data:`VOICE_TAIL_RES` opens (its words describe the thing compared: its counts are that
thing's; a place of its own keeps it, :data:`VOICE_SIMILE_BLOCKER_RE`)."""

VOICE_PLACE_HAZARD_RE = re.compile(r"\b(?:up|down|over|off|out|upon|atop|underneath|beneath|their|its|in|into|inside|onto|on|at|to"
                                   r"|toward|towards|near|by|with|using|use|via|under|behind|beside)\b")
"""Words of place, possession or means that keep a label or a chunk that is no simile from being dropped as a voice's:
it may place a cube or name a tool ("..., up high", "..., its top free", "..., into the bin", "..., using the tongs").
A simile's possessives are the compared thing's ("like ducklings following their mother"); its places are refused by
:data:`VOICE_SIMILE_BLOCKER_RE`."""

VOICE_CHUNK_HAZARD_RE = re.compile(
    r"\b(?:vice|versa|invert\w*|not|no|never|none|nothing|nowhere|neither|nor|without|except|unless|[a-z]+n't|cannot|if|when|whenever|case|provided"
    r"|before|after|then|next|later|finally|first|second|third|last|again|once|twice|previous\w*|earlier|usual|same|shown|show"
    r"|picture|image|photo|diagram|sketch|drawing|figure|this|that|these|those|it|them|they|one|ones|each|every|all|both"
    r"|some|any|few|several|many|more|less|fewer|most|least|only|other|another|else|rest|remaining|extra|big|bigger|biggest"
    r"|small|smaller|smallest|large|larger|tall|taller|tallest|short|shorter|high|higher|low|lower|wide|tiny|huge|size|height"
    r"|order\w*|sort\w*|revers\w*|backwards?|alphabetic\w*|ascending|descending|quick\w*|fast|slow\w*|seconds?|minutes?|within"
    r"|until|hurry|upside|sideways|diagonal\w*|apart|together|touch\w*|spaced|evenly|straight|tilt\w*|rotat\w*|turn\w*|flip\w*"
    r"|swap\w*|instead|rather|must|should|need|needs|required?|make\s+sure|keep|stay\w*|remain\w*|leave|still|colou?r\w*|mirror\w*|opposite|alternat\w*|exactly|precisely|away|robot\w*|gripper|arm|camera"
    r"|you|your|me|shape\w*|form|formation|pattern\w*|style|design|layout|arrangement\w*|configuration|spiral|triangle\w*"
    r"|cross|zigzag|diamond|star|heart|arrow|letter|word|spell\w*|read\w*|says?|respectively|apiece|resp"
    r"|initial\w*|init|start\w*|begin\w*|setup|set-up|end|ends|ending|final\w*|goal|target|result|outcome|desired|scene|state"
    r"|config\w*|current\w*|success\w*|episode|done|complete\w*"
    # (a hostile helper's probes, thirty-second session) a label or tail that judges the task, turns it, conditions it,
    # sizes it, takes a viewpoint, a direction, a pose or a spacing, or points at an earlier day
    r"|example\w*|counter\w*|anti|non|incorrect|wrong|bad|forbid\w*|prohibit\w*|ban\w*|limits?|trap|bait|myth|fake|false"
    r"|danger\w*|pitfall|mistake\w*|error\w*|invers\w*|bizarro|inside|opposite|mirror\w*|permit\w*|allow\w*|option\w*|willing"
    r"|maybe|perhaps|weekday\w*|weekend\w*|morning\w*|daily|jumbo|mini\w*|mega|giant|triple|double|decker|view\w*"
    r"|perspective|looking|seen|facing|face|north\w*|south\w*|east\w*|west\w*|upstage|downstage|clockwise|anticlockwise"
    r"|counterclockwise|offset|askew|crooked|overhang\w*|lean\w*|perched|precarious\w*|teeter\w*|kiss\w*|nestl\w*|snug\w*"
    r"|wedged|room|budget|practi[sc]\w*|drill|monday\w*|tuesday\w*|wednesday\w*|thursday\w*|friday\w*|saturday\w*|sunday\w*"
    r"|yesterday|cares?|either|direction|dozen|about|approximately|roughly|around|plan\s+b|version|edition|variant)\b")
"""Words that keep a chunk at a task's edge from being dropped as a voice's (:func:`rpg.schema.reading._voice_chunk`):
a negation, a condition, a step or repetition, a reference to something earlier or shown, a quantifier or pronoun that
may stand for cubes, a size, an order, time, a pose or spacing, a requirement, a direction of its own, a colour word, a
shape, the robot or a listener, and a heading's word for the start or the goal ("Initial scene:", "End state:").
Such a chunk may change what the task asks ("..., if the red one is free", "..., like last time", "..., all of them",
"Upside down: ...", "..., up high"), so it stays, to be read or refused."""

VOICE_SIMILE_BLOCKER_RE = re.compile(
    rf"\b(?:{COLOR_RE}|grey|blocks?|cubes?|bricks?|box|tower|stack|pil|line|row|column|pyramid|wall|grid|circle|ring|patch|pad"
    r"|mat\b|tile|letter|digit|label|table|robot|gripper|goal|task|before|previous|last|earlier|usual|shown|picture|image|photo"
    # a place or relation of its own ("like a hat on a head" of a task that says "next to"), or a thing known by its
    # order, pattern, shape, pose or size ("like a traffic light", "like stairs", "like a toppled domino")
    r"|on\b|onto|atop|upon|over\b|under|beneath|below|above|top\b|bottom|between|beside|behind|next\b|left\b|right\b|front"
    r"|back\b|inside|across|along|near\b|far\b|side\b|edge|traffic|rainbow|flag|chess|checker|stripe|gradient|stair|step|ladder"
    r"|snowman|totem|cake|bridge|arch|podium|plus\b|sign\b|u-turn|domino|topple|sphere|cylinder|pancake|flat\b|tall|short"
    r"|big|small|tiny|huge|giant|mouse|elephant|shadow|roof|hat\b|lid\b|crown|pair\b|twins?\b|dice\b|sandwich"
    r"|filling|slice|layer|pyramid|spiral|cross|triangle|square\b)")
"""Words a simile chunk may not hold: a cube, colour, structure, patch, label or the table is not a compared thing but
the task's own (so "..., like the red tower" stays)."""

SIMILE_RELATION_WORDS: dict[str, str] = {
    "on": "on", "onto": "on", "atop": "on", "upon": "on", "over": "on", "top": "on", "above": "on", "stack": "on",
    "under": "under", "beneath": "under", "below": "under", "bottom": "under",
    "beside": "beside", "next": "beside", "behind": "behind", "front": "front", "left": "left", "right": "right",
    "between": "between", "line": "line", "row": "line",
}
"""Relation and structure words of :data:`VOICE_SIMILE_BLOCKER_RE`, each with the relation it pictures: a simile whose
blocked words all picture relations the task's words already say restates them and is dropped as the voice's
(:func:`rpg.schema.reading._restates_relations`); any other blocked word (a colour, a count, a cube, a size) keeps it."""

VOICE_NAME_NUMBER_RE = re.compile(r"\b[a-z][a-z\-]+\s+(?:(?:number|no\.?)\s*|#)?(?:\d+[a-z]?|one|two|three|four|five|six|seven|eight|nine"
                                  r"|ten)\b(?!\s+[a-z])")
"""A number naming a thing of a voice's label ("day six", "trench 4", "camp two", "Context 17", "sheet number four"):
dropped with the label, "number" too (a number anywhere else in a chunk keeps it, and so does one a noun follows: "two
cubes" counts)."""

EVALUATION_WORD_RE = re.compile(
    r"\b(?:episodes?|seeds?|trials?|rollouts?|success(?:\s+(?:rates?|checks?|criteri(?:on|a)|conditions?|detectors?))?"
    r"|scores?|scored|scoring|leaderboards?|entr(?:y|ies)|baselines?|polic(?:y|ies)|metrics?|benchmarks?|accuracy|percent"
    r"|rank(?:ed|ing|s)?|averaged|evaluat(?:ed|ion|ions)|checkpoints?|submissions?|fires?|fails?|failed|failures?|passes"
    r"|sims?|simulations?|runs?)\b|%")
"""Words of a policy's evaluation, not of its task ("Ranked by success rate over 100 episodes.", "Scores are averaged
over 5 seeds.", "Best entry so far: 71%.", "(fails on roughly 30% of seeds)"): a sentence or parenthesis that has one
and names no cube, colour, structure, place, placement verb or pronoun for cubes (:data:`EVALUATION_BLOCKER_RE`)
reports on evaluating the task, and :func:`rpg.schema.reading.drop_asides` drops and lists it (its numbers count
episodes and seeds, its negations and superlatives judge policies: none is the goal's)."""

_GOAL_THINGS = (r"(?:" + "|".join(COLORS) + r"|grey|blocks?|cubes?|bricks?|box(?:es)?|patch(?:es)?|pads?|mats?|tiles?|squares?"
                r"|towers?|stacks?|stacked|stacking|piles?|lines?|rows?|columns?|pillars?|pyramids?|walls?|grids?|circles?|rings?"
                r"|letters?|digits?|labels?|left|right|front|back|rear|behind|middle|cent(?:er|re)|corners?|edges?|sides?"
                r"|top|bottom|base|next|near|beside|between|far|apart|onto|under|above|below|table)")
"""The words of a goal's things, places and relations (no counts: a report's numbers count episodes and steps);
:data:`_TASK_THINGS` adds the counts and "on"."""

GOAL_THING_RE = re.compile(rf"\b{_GOAL_THINGS}\b")

COUNTING_WORDS = frozenset({"just", "only", "pick", "choose", "select", "take", "use", "need", "want", "get", "keep", "make", "build",
                            "stack", "add", "remove", "put", "place", "exactly", "about", "around", "roughly", "nearly", "almost",
                            "least", "most", "any", "some", "all", "every", "each", "another", "other", "per", "times", "top",
                            "bottom", "number", "no", "step", "steps", "phase", "part", "option", "plan", "variant", "version"})
"""Words before a number that count or pick (or number a step of a plan) rather than name a thing of a voice's world ("just
one", "pick one", "step two"): the number stays in a voice's label, to be weighed (:func:`rpg.schema.reading._voice_chunk`)."""

VOICE_LABEL_TASK_ONE_RE = re.compile(r"\b(?:(?:this|that|a|the|another|my|our)\s+(?:(?:last|final|quick|harder|easier|easy|simple|short|fun"
                                     r"|tricky|new|hard|tough|little|big|nice)\s+)?|(?:last|final|quick|harder|easier|easy|simple|short|fun"
                                     r"|tricky|new|hard|tough|little|big|nice)\s+)one\b(?=\s*(?:$|,|for\b|before\b|today\b|tonight\b|now\b"
                                     r"|then\b))")
""""One" in a voice's label that stands for the task itself ("Lads, quick one: ...", "Alright, last one for today: ...",
"Investors love this one: ..."): set apart before the label is weighed (:func:`rpg.schema.reading._voice_chunk`); "one
cube", "one of them" and "one more" are none."""

VOICE_LABEL_WORLD_COUNT_RE = re.compile(
    rf"\b(?:the\s+|our\s+|my\s+)?(?:\d+|{COUNT_WORD_RE})\s+(?!(?:{_GOAL_THINGS}|more|times?|of|other|others|ones?|each|apiece|in|on|at)\b)"
    r"[a-z][a-z\-]*\b(?!\s+(?:blocks?|cubes?|bricks?|of)\b)")
"""A count of a thing of the speaker's own world in a voice's label ("Two pots: ...", "Blocking for the two leads: ...",
"Eight seat drill: ..."): set apart before the label is weighed; a count of cubes, a structure or a place, "times" and
"more" are none, nor one of :data:`QUANTITY_NOUN_RE`."""

QUANTITY_NOUN_RE = re.compile(
    r"(?:cop(?:y|ies)|duplicates?|replicas?|clones?|pairs?|sets?|groups?|pieces?|parts?|levels?|layers?|stor(?:e?ys?|ies)|floors?"
    r"|tiers?|courses?|colou?rs?|shades?|letters?|digits?|numbers?|units?|items?|objects?|things?|mats?|pads?|tiles?|squares?"
    r"|spots?|places?|positions?|slots?|heights?|rounds?|steps?|moves?|tries|attempts?|versions?|instances?|repeats?"
    r"|repetitions?|turns?|goes|bricks?|boxes|blocks?|cubes?|pillars?|heaps?|piles?|stacks?|towers?|rows?|lines?|columns?"
    r"|walls?|pyramids?|circles?|rings?|grids?|ones?|each|reds?|blues?|greens?|yellows?|whites?|blacks?|pinks?|purples?"
    r"|oranges?|grays?|greys?|browns?|cyans?|dice|die|bits?|chunks?|elements?|members?|pieces?)")
"""Nouns a count before them may hand on to the task (copies, levels, pairs, colours, the cubes under other names): a
voice label's count of one of them stays in the label, to be read or refused (a hostile helper's probes, forty-fifth
session: "Three levels: red on blue." had been read as a tower of two)."""

WORLD_COUNT_RE = re.compile(
    rf"\b(?:\d+|{COUNT_WORD_RE}|a\s+few|another)\s+(?:more\s+)?(?!(?:{_GOAL_THINGS}|more|times?|of|other|others)\b)"
    r"[a-z]+s?\b|\b(?:once|twice|thrice|\d+\s+times)\s+(?:a\s+|per\s+|every\s+)?(?:day|daily|week|weekly|month|monthly|year|night"
    r"|nightly|hour|hourly)\b|\ball\s+(?:good|set|fine)\b")
"""A count or a frequency of a thing of the speaker's own world ("one capsule", "500 milligrams", "one more pint", "twice
daily", "all good"): set apart before the words before a turn to the robot are weighed
(:func:`rpg.schema.reading._said_to_someone_else`); a count of a cube, block or anything of a goal is none."""

GOAL_THING_PREFIX_RE = re.compile(rf"\b{_GOAL_THINGS}")
"""A word that begins like a goal's word ("towered", "stacking", "bluish", and harmlessly "topic"): keeps a chunk of a voice
(:func:`rpg.schema.reading._voice_chunk`), which may be a goal said in a form of its own."""

_TURNED_OR_REPEATED = (r"revers\w*|backwards?|opposite|invers\w*|invert\w*|mirror\w*|swap\w*|flip\w*|upside|sideways|rotat\w*"
                       r"|turn\w*|twice|thrice|times|repeat\w*|again|alternat\w*")
"""Words that turn a task around or say it again, which neither an evaluation report nor a task's frame may hold."""

_HANDLED = r"push\w*|pull\w*|knock\w*|toppl\w*|touch\w*|hold\w*|remov\w*|take"
"""Verbs of handling cubes, which neither an evaluation report nor a task's frame may hold."""

EVALUATION_BLOCKER_RE = re.compile(
    r"\b(?:" + _GOAL_THINGS + "|" + _TURNED_OR_REPEATED + "|" + _HANDLED + r"|put|place|move|set|lay|bring|build|make|arrange|group"
    r"|line|stack|spell\w*|sort\w*|order\w*|reads?|it|its|they|them|their|those|these|must|should|has\s+to|have\s+to|needs?\s+to"
    r"|then|after|afterwards|finally|instead|keep|stay\w*|remain\w*|leave|until|while|during|throw\w*|shak\w*|drop\w*|lift\w*"
    r"|pick\w*|grasp\w*|grab\w*|slid\w*|toss\w*|tip\w*|carr\w*|tid\w*|clean\w*|clear\w*|reset\w*|undo|everything|anything"
    r"|something|nothing|vice|versa|other\s+way|doubl\w*|half|only|except|but|also|plus|taller|shorter|higher|lower|more|less"
    r"|within|cm|mm|inch\w*|degrees?)\b")
"""What keeps a sentence with an evaluation word (:data:`EVALUATION_WORD_RE`) in the task: anything of a goal or a
requirement or sequence that may constrain one ("In every episode the red cube must stay on the patch."), or a
verb that moves cubes."""

FRAME_PREFIX_RE = re.compile(
    r"^(?P<p>[^.;!?\"():]{2,120}?)(?:\s*[,:]\s+|\s+(?:is|was|are|were)\s+to\s+|\s+to\s+)"
    r"(?=(?:please\s+)?(?:put|place|set|move|bring|position|lay|build|make|create|construct|assemble|form|stack|pile|arrange|line"
    r"|spell|sort|align|group|get)\b)")
"""Words before the imperative of a task that frame it for a person ("For the pilot set, line up ...", "Okay sweetie,
the robot's job is to put ...", "The task consists in to place ..."): dropped and listed by
:func:`rpg.schema.reading.drop_asides` when they name nothing of a goal (:data:`GOAL_THING_RE`), hold no word of
:data:`FRAME_PREFIX_HAZARD_RE` and every word is a dictionary word or a name (their unknown words had refused the
task)."""

REPORTED_REQUEST_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Trial 12 of the user study asks for the brown cube to be moved to the center of the table": the request itself,
    # its frame before it (read as a frame, :data:`FRAME_PREFIX_RE`, or refused with the task)
    (re.compile(r"^(?P<who>[^.;:!?\"]{2,80}?)\s+(?:asks|asked|calls|called)\s+for\s+(?P<what>the\s+[^.;:!?]+?)\s+to\s+be\s+"
                r"(?P<verb>moved|placed|put|set|stacked|lined\s+up)\b"),
     lambda m: f"{m.group('who')}, {dict(moved='move', placed='place', put='put', set='set', stacked='stack').get(m.group('verb'), 'line up')} "
               f"{m.group('what')}"),
    # "Between the two black cubes goes the orange cube.", "On top of the blue cube goes the red one": a placement said with
    # its place first (no task had been found); a verb of where a cube is now ("On the patch sits the red cube.") may
    # describe the start, and stays
    (re.compile(r"(?i)(?:^|(?<=[.;:!?]\s))(?P<where>(?:between|on\s+top\s+of|on(?:to)?|behind|in\s+front\s+of|(?:to\s+the\s+|on\s+the\s+)?"
                r"(?:left|right)\s+of|next\s+to|beside|under(?:neath)?|below|beneath|above|atop)\s+the\s+[^.;:!?,]{3,60}?)\s+"
                r"(?:goes|go|belongs|comes|(?:should|must|will|has\s+to)\s+(?:go|be|sit|stand|end\s+up))\s+"
                rf"(?P<what>the\s+(?:{COLOR_RE})\s+(?:cube|block|one))\s*(?P<end>[.!]|$)"),  # (the sentence ends there: a
     # relation after it, "... goes the blue cube on the green cube", had been read of the other cube)
     lambda m: f"Put {m.group('what')} {m.group('where')}{m.group('end')}"),
    # "Between the brown cube and the pink cube, put the white cube.": the place fronted before the verb (the sentence
    # ends with the cube: "..., put the white cube on top" says more and stays as said)
    (re.compile(r"(?i)(?:^|(?<=[.;:!?]\s))(?P<where>(?:between|on\s+top\s+of|on(?:to)?|behind|in\s+front\s+of|(?:to\s+the\s+|on\s+the\s+)?"
                r"(?:left|right)\s+of|next\s+to|beside|under(?:neath)?|below|beneath|above|atop)\s+the\s+[^.;:!?,]{3,60}?)\s*,\s*"
                r"(?:please\s+)?(?P<verb>put|place|set|stand|stack)\s+"
                rf"(?P<what>the\s+(?:{COLOR_RE})\s+(?:cube|block|one))\s*(?P<end>[.!]|$)"),
     lambda m: f"{m.group('verb').capitalize()} {m.group('what')} {m.group('where')}{m.group('end')}"),
)
"""A task reported as what something asks for, or said with its place first (:func:`rpg.schema.reading.normalize_words`,
before the frames are dropped)."""

FRAME_NOUN_RE = re.compile(
    r"\b(?:jobs?|tasks?|goals?|objectives?|assignments?|homework|lessons?|exercises?|experiments?|trials?|study|studies|pilot"
    r"|sets?|variants?|ablations?|evals?|evaluations?|benchmarks?|challenges?|levels?|rounds?|episodes?|sessions?|projects?"
    r"|deliverables?|milestones?|reports?|papers?|sections?|protocols?|recipes?|drills?|activit(?:y|ies)|missions?|quests?"
    r"|sweetie|honey|sweetheart|darling|kiddo|buddy|mate|pal|sir|madam|ma'am|team|folks|guys|everyone|everybody|robot"
    r"|necessary|needed|required|consists?)\b")
"""What makes a task's opening words a frame (:data:`FRAME_PREFIX_RE`): they name the task as a task, an exercise or an
experiment ("For the pilot set,", "the robot's job is to"), address a person ("Okay sweetie,", "Sir,") or say the task
is needed ("Is necessary to"); other opening words are read with the task."""

FRAME_VERBS: frozenset[str] = frozenset("""
is was are were be been being am consists consist instructed asked told want wants wanted need needs needed required
would should must shall will can could may might has have had let lets going gonna wanna
""".split())
"""The only verbs a task's opening frame may have (:func:`rpg.schema.reading._frame_prefix`: "the robot was instructed
to", "the task consists in to"); another verb may say what was done or seen ("Do what you did: ...")."""

FRAME_PREFIX_HAZARD_RE = re.compile(
    r"\b(?:" + _TURNED_OR_REPEATED + "|" + _HANDLED + r"|revers\w*|mirror\w*|opposite|invert\w*|flip\w*|not|no|never|none|nothing|without|except|unless|[a-z]+n't|cannot|if|when"
    r"|whenever|once|until|till|while|after|before|then|first|second|third|next|finally|last|tilt\w*|it|its|itself|them|they"
    r"|their|those|these|each|every|all|both|only|other|another|same|different|more|less|fewer|most|least|many|much|several"
    r"|few|like|unlike|as|instead|rather|else|order\w*|colou?r\w*|size|big|small|large|tall|high|low|wide|long|short"
    r"|quick\w*|slow\w*|fast|time|minutes?|seconds?|hours?|start\w*|begin\w*|initial\w*|keep|stay\w*|leave|remain\w*|undo"
    r"|reset|spell\w*|sort\w*|word|words|letter\w*|digit\w*|number\w*|\d+\s*(?:x|by)\s*\d+|use|uses|used|using|with|via"
    r"|through|holding|wearing|by\s+means"
    r"|pictur\w*|photo\w*|images?|diagram\w*|sketch\w*|draw\w*|figures?|screenshots?|videos?|demo\w*|examples?|cards?|plans?"
    r"|blueprints?|templates?|models?|referenc\w*|memory|remember\w*|recall\w*|original\w*|previous\w*|earlier|yesterday|today"
    r"|usual\w*|shown|show\w*|see|seen|saw|sees|look\w*|follow\w*|according|per|copy\w*|match\w*|mimic\w*|replicat\w*"
    r"|recreat\w*|reproduc\w*|scenes?|setups?|configurations?|arrangements?|layouts?|patterns?|designs?|instructions?|here|there"
    r"|this|that|now|current\w*|already|still|back|return\w*|former\w*|also|too|mostly|almost|partly|part|might|would|could"
    r"|may|wrong\w*|mistak\w*|suppos\w*|allegedly|among|human|person|people|students?|child|children|kids?|participants?"
    r"|subjects?|operators?|users?|teachers?|one|two|three|four|five|six|seven|eight|nine|ten|\d+)\b")
"""What keeps a task's opening words from being framing (:data:`FRAME_PREFIX_RE`): a negation, a condition, time, a
step, a repetition or reversal, a pronoun or quantifier for cubes, a comparison or simile, an order, colour or size,
a change of the scene, a start, what the task spells or sorts, a tool ("Use the ruler to ...": an object the
domain lacks), a picture, scene, time or memory the words may point at ("Following the sketch, ..."), a hedge, a part or
a doubt ("the robot's former job", "mostly", "wrongly instructed"), a person other than the robot, or a count."""

QUOTED_TASK_REPORT_RE = re.compile(
    r"^(?:\s*(?:\d+[.)]|[-*\u2022]|;|,|\.|:|repro(?:duce)?|steps?|str|to|give|run|ran|the|a|task|instruction|prompt|command|reset|sim"
    r"|simulation|env(?:ironment)?|scene|bug|issue|with|using|when|i|we|expected|actual|result|=|:|\(|\))\s*)*$")
"""The words of a bug report around a quoted task ("Repro: 1. reset the sim 2. give the task"): each segment of the text
outside the quote must be these or a report on evaluating (:data:`EVALUATION_WORD_RE`)."""

QUOTED_TASK_RE = re.compile(r"(?i)\b(?:the\s+)?(?:task|instruction|prompt|command)\s*(?:=|:|is|was)?\s*[\"\u201c](?P<q>[^\"\u201d]{8,400})[\"\u201d]")
"""A task quoted inside a report of it ('Repro: 1. reset the sim 2. give the task "put the cyan cube behind the red cube" 3.
the success check never fires'): when the words outside the quote name no cube, colour, structure, place or relation
(:data:`GOAL_THING_RE`), the quote is the task and the rest is dropped and listed
(:func:`rpg.schema.reading.drop_asides`); otherwise the whole text is read (an expected result restated outside the
quote is read with it, and refused where it cannot be)."""

TITLE_MAX_WORDS = 4
"""The most words of a capitalised title over a task ("Challenge: Wall Builder.", "CHALLENGE 2 - Tower Rush."), which
:func:`rpg.schema.reading.drop_asides` drops when the text after it says every word of the task it has."""

OPERATOR_VERBS: frozenset[str] = frozenset("""
go start begin let enjoy have see note check feel ask tell contact email ping thank record film watch relax wait
stand get hold remember find read ship send run press hit launch queue good bye
""".split())
"""Verbs that open a sentence addressed to a person rather than to the robot ("Go when ready.", "Start recording.",
"Let me know if anything's unclear.", "Enjoy."): such an imperative with nothing of the task in it is framing
(:func:`rpg.schema.reading.drop_asides`); an imperative of any other verb ("Tidy up.", "Demolish.") may change the
goal, so it stays."""

AUXILIARY_WORDS: frozenset[str] = frozenset("""
is are was were be been being am has have had do does did will would can could may might shall should must 's
""".split())
"""Words after a sentence's first word that make it a statement, not a command ("Code is linked below.")."""

INEXPRESSIBLE: tuple[tuple[str, str, str], ...] = (
    ("question", r"(?:^|[.!;]\s+)(?:which|what|where|who|whose|why|how\s+many|how\s+much|when)\b[^.!;]*\?"
                 r"|^\s*(?:which|what)\s+(?:of\s+the\s+|one\s+of\s+the\s+)?(?:[a-z]+\s+)?(?:blocks?|cubes?|ones?)\s+(?:is|are|was|were|has|have)\b"
                 r"|^\s*(?:which|what)\s+(?:colou?rs?|labels?|letters?|digits?|numbers?)\s+(?:is|are|was|were|does|do|did)\s+(?:the|a|an|it|this|that)\b"
                 r"|^\s*(?:where|why|how)\s+(?:is|are|was|were|does|do|did)\s+(?:the|a|an)\b"
                 r"|(?:^|[.!;?]\s+)(?:is|are|was|were|does|do|did|has|have|had)\s+(?:the|a|an|there|it|this|that|any|all"
                 r"|every|some|each|these|those)\b[^.!;]*\?"
                 r"|^(?:is|are|does|do)\s+(?:the|a|an|there|any)\s+(?:[a-z0-9]+\s+){0,3}?(?:blocks?|cubes?|boxes|box|tower|stack)\b"
                 r"(?:\s+(?:on|to|in|at|next|behind|under|beside|left|right|stacked|placed|lined))"
                 r"|(?:^|[.!;?]\s+)(?:can|could|will|would|should|may|might)\s+(?:the|a|an|any)\s+[^.!;?]*\bbe\b[^.!;]*\?"
                 r"|(?:^|[.!;?]\s+)(?:can|could|will|would|may|might)\s+(?:the|a|an|any|this|that|these|those|my|our|your)\s+"
                 r"(?![^.!;?]*\b(?:put|place|stack|move|build|make|arrange|set|line|lay|slide|push|bring|spell|sort|form|create)\b)"
                 r"[^.!;?]*\?\s*$"
                 r"|\b(?:tell|show)\s+me\s+(?:how|what|which|where|whether|if|who)\b|\bhow\s+many\b[^.!;]*\?"
                 r"|(?:^|[.!;?,]\s*)(?:can|could|will|would|does|do)\s+(?:the\s+robot|it|the\s+arm)\s+(?:even\s+|actually\s+|really\s+)?"
                 r"(?!put|place|stack|move|build|make|arrange|set|line|lay|slide|push|bring|spell|sort|stand|swap|please|tell|show|give)[a-z]+\b(?=[^.!;]*\?)",
     "asks a question: a task is an instruction whose goal says where cubes end up; ask for the arrangement "
     "instead (e.g. \"put the red block on the blue block\")"),
    ("same_colour", r"\b(?:(?:blocks?|cubes?|bricks?|ones)\s+(?:of|in|with)\s+(?:the\s+)?same\s+colou?r|(?:all|both)\s+(?:of\s+(?:them|the\s+"
                 r"(?:cubes|blocks))\s+)?(?:in\s+)?(?:the\s+)?same\s+colou?r)\b",  # ("group the same coloured blocks": piles by colour)
     "asks that cubes share a colour nobody names: a task's cubes are known by their colours, so say the colour (e.g. "
     "\"stack two red cubes\")"),
    ("alternative", r"(?<!\bmore\s)(?<!\bsir\s)\bor\b(?!\s+(?:so|less|madam)\b)",
     "offers alternatives: a task has one goal, checked at the end of the episode; say one end state (e.g. \"put the red "
     "block on the blue block\")"),
    ("no_goal", ROBOT_ONLY_RE,
     "moves only the robot (its gripper, arm or hand), which leaves no goal for the cubes: a task's goal says where "
     "cubes end up; say where a cube should go (e.g. \"put the red block on the blue patch\")"),
    ("action", MOTION_RE,
     MOTION_WHY),
    ("action", TURNED_OVER_RE,
     MOTION_WHY),
    ("negation", r"\b(?:not|never|without|except|excluding|avoid(?:s|ing)?|neither|nor|none|nowhere|nobody|no-one|noone|no\s+one"
                 r"|ban|bans|banned|blacklist\w*|veto\w*|forbid\w*|prohibit\w*|taboo|cancell?ations?"
                 rf"|(?:all|everything|every\s+[a-z]+)\s+but(?=\s+(?:the|a|an|one|two|three|four|five|{COLOR_RE}|(?-i:[A-Z])\b)))\b|n't\b"
                 # ("keep everything but make it a tower": a turn, no exclusion; "cancel that" takes a change back)
                 r"|\b(?:somewhere|anywhere|everywhere)\s+(?:other|else)\s+than\b|\banywhere\s+but\b"  # "somewhere other than the left half"
                 r"|\b(?:rather\s+than|instead\s+of)\s+(?=(?:(?:to\s+the\s+)?(?:left|right)|in\s+front|behind|next|beside|near|on(?:\s+top)?|onto|between"
                 r"|under|in|at|far(?:\s+away)?|above|below)(?:\s+(?:of|to|from))?\s+(?:the\s+[a-z\-]+(?:\s+[a-z\-]+)?\s+(?:cube|block|one|patch"
                 rf"|corner|side|half|edge|region)\b|(?:the\s+)?(?:{COLOR_RE})\b))"  # (bare colours: "instead of on green")
                 r"|\b(?:anywhere|everywhere|anything|any\s+place)\s+but\b"
                 r"|\b(?:don|doesn|didn|isn|aren|shouldn|mustn|won|wouldn)\s*'?\s*t\b"
                 r"|\bno\s+(?:\w+\s+){0,2}?(?:blocks?|cubes?|boxes|one|other|longer)\b",
     "is a negation: a task's goal says what must hold at the end, and rpg does not check that something is absent; "
     "say what should be true instead"),
    ("condition", r"\b(?:if|unless|whenever|otherwise|provided)\b|\bonly\s+(?:after|once|when|before)\b|\bin\s+case\b(?!\s+of\b)"
                  r"|\b(?:after|once|before)\s+(?:the|it|they|you)\b[^.;]*?\b(?:has|have|had)\s+been\b"
                  r"|(?:^|[.;!]\s*)(?P<w>(?:should|were|had)\s+(?:there\s+be|the|a|an|it|they)\b)[^,.;?]*,",  # "Should there be a letter cube A, ..."
     "makes the goal conditional: a task has one goal, checked at the end of the episode; say the goal for one scene"),
    ("action", r"\b(?:rotat\w*|turn\w*|spin\w*)\b[^.;]*?\b(?P<w>(?:\d+|ninety|forty[- ]five)\s*(?:degrees?|deg|\u00b0))",
     "is a rotation, an action the domain does not have: a task's goal says where cubes end up and which face is up, "
     "not a motion or an angle"),
    ("time", r"\b(?:\d+(?:\.\d+)?\s*(?:seconds?|secs?|s|minutes?|mins?|hours?|hrs?|ms|milliseconds?)(?![\w'])|seconds|minutes?|hours?"
             r"|meanwhile|forever|while|whilst|during)\b"
             # a time of day ("After 5 pm, move ...", "By 10:30, stack ...", "at 3 o'clock": it had compiled, the time dropped)
             r"|\b\d{1,2}(?::\d{2})?\s*(?:a\.?m\.?|p\.?m\.?|o'?\s?clock)(?![\w])|\b(?:at|after|before|by|until|till)\s+\d{1,2}:\d{2}\b"
             r"|\b(?:at|after|before|by|until|till)\s+(?:noon|midnight|midday)\b",
     "is about time (a duration or a time limit, a measured quantity): a task's goal is checked once, at the end of "
     "the episode, with no clock or duration"),
    ("quantity", r"\b(?:\d+(?:\.\d+)?\s*(?:cm|mm)\b|(?:centi|milli)?(?:meters?|metres?)|inch(?:es)?|feet|foot"
                 r"|some(?=\s+(?:of\s+the\s+)?(?:[a-z]+\s+)?(?:blocks|cubes|bricks|boxes)\b)|cms?|few|(?<!\d\s)fewer|most|majority|percent|(?<!left\s)(?<!right\s)(?<!front\s)(?<!back\s)(?<!rear\s)half|halves|several|many|much|enough|plenty|numerous"
                 r"|as\s+(?:high|tall|many|much|far|close|long)\s+as\s+(?:you|it|possible|can)"
                 r"|as\s+far\s+(?:[a-z]+\s+){1,4}?as\s+(?:you|it|possible|can)"
                 r"|(?:hand|finger|thumb|palm)(?:'s|s)?\s+(?:widths?|breadths?|lengths?)|\bgap\s+of\b"
                 r"|(?:over|more\s+than|at\s+least|at\s+most|fewer\s+than|less\s+than|up\s+to|under)\s+"
                 r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?=\s+(?:[a-z]+\s+)?(?:blocks?|cubes?|bricks?|high|tall|levels?)\b))\b",
     "is a measured or vague quantity: rpg's relations are qualitative (next to, left of, far from) and "
     "its counts exact"),
    ("size", r"\b(?:big|bigger|biggest|large|larger|largest|small|smaller|smallest|little|tiny|huge|giant|mini|heavy|heavier"
             r"|heaviest|wider|narrow|thin|thick)\s+(?:(?!(?:number|digit|letter|label)\b)[a-z]+\s+)?(?:blocks?|cubes?|boxes|box|ones?"
             r"|objects?|items?|pieces?|things?)\b"
             r"|\b(?:by|of|in\s+order\s+of)\s+(?:their\s+)?(?:size|weight)\b|\b(?:medium|[a-z]+-)sized\b"
             rf"|\b(?:{COLOR_RE})\s+(?:big|large|small|little|tiny|huge|giant)\b"  # "blue_large" of a config
             # "the cube on the red patch should be big", "it must be heavy": a size said after the cube (it had been dropped)
             r"|\b(?:blocks?|cubes?|boxes|box|ones?|it|they|them|each|both)(?:\s+on\s+the\s+[a-z]+\s+patch)?\s+(?:should|must|has\s+to|have\s+to"
             r"|needs?\s+to|will|is|are|'s)\s+(?:be\s+)?(?:very\s+|really\s+|quite\s+|extra\s+|a\s+bit\s+)?(?:big|bigger|biggest|large|larger"
             r"|largest|small|smaller|smallest|little|tiny|huge|giant|heavy|heavier|light|lighter|wide|wider|narrow|thin|thick)\b"
             rf"(?!\s+(?:{COLOR_RE}|grey|gr[ae]y)\b)",  # ("it is light blue": a colour)
     "asks for a size: every cube is the same size (5 cm), so no cube is bigger or smaller than another"),
    ("reference", r"\bthe\s+(?:very\s+)?(?:first|second|third|fourth|fifth|sixth|last|next|previous|former|latter)"
                  r"(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:first|second|third|fourth|fifth|sixth|last))*"  # ("the first, second
                  # and third cubes": four cubes had been made up)
                  r"\s+(?:(?:[a-z]+\s+)?(?:blocks?|cubes?|bricks?|boxes|box|ones?))\b"
                  # "(the second blue)": a colour said as the cube, picked by an order nobody defined (it had been dropped)
                  rf"|\bthe\s+(?:first|second|third|fourth|fifth|sixth)[\s-]+(?:{COLOR_RE})\b(?=\s*(?:[).,;:!?'\"\u00bb]|$)"
                  r"|[\s-]+(?:and|on|onto|in|into|to|next|beside|behind|under|cube|block)\b)"
                  # "cube one", "block four": a cube numbered in words (the digit cube, or an order nobody defined; a coloured cube
                  # had been made up)
                  r"|\b(?:cube|block)\s+(?:one|two|three|four|five|six|seven|eight|nine|ten|\d{2,})\b(?!\s*(?:[-x\u00d7]|cubes?|blocks?"
                  r"|high|tall|wide|long|deep|layers?|levels?|rows?|more|of)\b)"
                  r"|\b(?:put|place|move|set|slide|push|bring|shift)\s+the\s+(?:first|second|third|fourth|last|other)\s+(?:tower|stack"
                  r"|pile|row|line)\b"  # "Put the second tower on the white patch": which tower (the first had been moved)
                  r"|\beach\s+(?:one\s+|cube\s+|block\s+)?(?:on(?:\s+top\s+of)?|onto|above|atop|under|below|beneath)\s+the\s+"
                  r"(?:first|last|next|following|previous)\b"  # "..., each one on the next" ("on the previous" after a list: dropped)
                  r"|\b(?:you|we|i|it|they|the\s+(?:robot|arm|gripper))\s+(?:just|already|have|had|has)\s+(?:just\s+|already\s+)?"
                  r"(?:moved|placed|picked|grabbed|used|put|touched|held|dropped|took|lifted|released|knocked|pushed)\b"
                  r"|\b(?:that|which)\s+(?:was|were|has\s+been|had\s+been)\s+(?:just\s+|already\s+|last\s+)?(?:moved|placed|picked|put"
                  r"|used|touched|grabbed|held)\b"
                  r"|\b(?:blocks?|cubes?|ones?)\s+(?:that\s+)?(?:you|we|i|it|they)\s+(?:moved|placed|picked|grabbed|used|touched|held|pointed"
                  r"|indicated|mentioned|chose|selected|dropped|took|lifted|released)\b"
                  r"|\b(?:you|we|i)(?:'m|'re|\s+am|\s+are)?\s+(?:just\s+)?(?:pointed|pointing|indicated|indicating)\b"
                  r"|\b(?:you|we|i)(?:'m|'re|\s+am|\s+are)?\s+(?:just\s+)?(?:looking|looked|gazing|gazed|staring|stared|glancing)\s+at\b"
                  r"|\b(?:you|we|i)\s+(?:can\s+)?(?:see|saw|look\s+at|gaze\s+at)\b"
                  r"|\b(?:i|you|we)(?:'m|'re|\s+am|\s+are)\s+(?:holding|touching)\b|\b(?:in|from)\s+(?:my|your|the\s+robot's)\s+(?:hand|gripper)\b"
                  r"|\b(?:again|undo|restore|original(?:ly)?|previous(?:ly)?|remaining|as\s+(?:before|it\s+was|they\s+were))\b"
                  r"|\b(?:as|like)\s+(?:last\s+time|yesterday|the\s+last\s+(?:one|time)|before|earlier|previously|we\s+did|you\s+did)\b"
                  r"|\blast\s+time\b|\b(?:you|we|i)\s+(?:built|made|did|stacked|arranged)\s+(?:it\s+)?(?:before|earlier|yesterday|previously)\b"
                  r"|\bthe\s+same\s+(?:towers?|stacks?|rows?|lines?|structures?|pyramids?|walls?|grids?|circles?|piles?|arrangements?"
                  r"|patterns?|configurations?|layouts?|shapes?|setups?)\s+(?:as\s+|that\s+|which\s+)?(?:you|we|i)\b"
                  r"|(?<!leave\s)(?<!keep\s)\bthe\s+rest\b(?!\s+(?:as\s+(?:it\s+is|is|they\s+are)|where\s+they\s+are|in\s+place|alone|untouched)"
                  r"\s*[.!;]?\s*$)|\bwhere\s+(?:it|they|the\s+(?:[a-z]+\s+){0,2}?(?:blocks?|cubes?|ones?))\s+(?:was|were|used\s+to\s+be|started|began)\b"
                  r"|\bthe\s+same\s+(?:order|sequence|positions?|places?|spots?)\b"
                  # "Two stacks: one with red on blue, the other the same": a copy of one said (its cubes had been made up)
                  r"|\b(?:the\s+other|the\s+second|another)(?:\s+one)?\s+(?:(?:is|with|has|gets|in|of|just)\s+)?(?:exactly\s+)?the\s+same\b"
                  r"|\bwith\s+the\s+same\s+colou?rs?\b|\b(?:stack|tower|row|line|pile)s?\s+(?:of|with|in)\s+the\s+same\s+colou?rs\b"
                  r"|\b(?:blocks?|cubes?|ones?|place|position|spot|patch)\s+(?:that\s+|which\s+)?(?:it|they)\s+(?:was|were|had\s+been|started)\s+(?:on|in|at)\b"
                  r"|\b(?:closest|nearest|farthest|furthest)\s+to\s+(?:you|me|us|the\s+(?:robot|camera|gripper|viewer))\b"
                  r"|\bthe\s+same\s+(?:blocks?|cubes?|ones?|boxes|box|objects?|pieces?)\b"
                  r"|\b(?:blocks?|cubes?|box|ones?)'s\s+(?:current\s+|old\s+)?(?:position|place|spot|location|square)\b"
                  r"|\b(?:current|present)\s+(?:position|place|spot|location)s?\b"
                  r"|\bthe\s+(?:blocks?|cubes?|ones?|box|boxes|objects?)\s+(?:that\s+(?:is|are)\s+|which\s+(?:is|are)\s+)?"
                  r"(?:on|at|in)\s+the\s+(?:far\s+)?(?:left|right|front|back|middle|center|centre)\b"
                  r"(?!\s+(?:of|side|corner|edge|half|part|end|area|region|zone)\b)"
                  r"(?=.*\b(?:on|onto|to|into|next|beside|behind|under|near)\b)"
                  r"|\b(?:put|place|move|set|bring|return)\s+(?:(?!the\s+back\b)[a-z]+\s+){0,3}back\b(?!\s+(?:of|left|right|side|edge|corner|row|half|part|end)\b)"
                  # "the red block that is on the blue block": a cube picked by where it stands now
                  r"|\bthe\s+(?:[a-z]+\s+){0,2}?(?:blocks?|cubes?|box|boxes|bricks?|ones?)\s+(?:that|which)"
                  r"(?:'s|\s+is|\s+are|\s+was|\s+were|\s+sits|\s+lies|\s+stands|\s+rests)?\s+(?:currently\s+|now\s+|still\s+|already\s+)?"
                  r"(?:sitting\s+|lying\s+|resting\s+|standing\s+|placed\s+)?(?:on|in|at|inside|next\s+to|near|beside|under|underneath|below"
                  r"|beneath|behind|in\s+front\s+of|(?:to\s+the\s+)?(?:left|right)\s+of)\b"
                  # "the block that the blue block is on", ", which is next to the blue one,": where cubes stand now
                  r"|\bthe\s+(?:[a-z]+\s+)?(?:block|cube|one)\s+(?:that|which)\s+the\s+(?:[a-z]+\s+)?(?:block|cube|one)\s+"
                  r"(?:is|was|sits|stands|rests|lies)\s+(?:on|in|under|beneath|below|next\s+to|beside|behind|near)\b"
                  r"|,\s*(?:which|that)\s+(?:is|are|was|were)\s+(?:currently\s+|now\s+|already\s+)?(?:next\s+to|beside|near|behind"
                  r"|in\s+front\s+of|(?:to\s+the\s+)?(?:left|right)\s+of)\b"
                  # "the red cube, which is currently on blue, ...": where it stands now (it had been read as the goal)
                  r"|,\s*(?:which|that)\s+(?:is|are|was|were)\s+(?:currently|now|already|still)\s+(?:(?:sitting|lying|resting|standing"
                  r"|stacked|placed)\s+)?(?:on|on\s+top\s+of|under|underneath|in|inside|at)\b"
                  # "the black cube glides from the left of the white cube (to ...)", "take it out from under the white cube":
                  # where a cube starts, not where it ends (the start place had become the goal)
                  r"|\b(?:cubes?|blocks?|ones?)\s+(?:glid|travel|drift|wander|stroll|waltz|sashay|tiptoe|scurr|hop|shimm|mov|slid|go|head"
                  r"|scoot|shift|mak)\w*\s+(?:its\s+way\s+)?(?:out\s+|back\s+|over\s+)?from\b"
                  r"(?!\s+(?:the\s+)?(?:left|right|front|back|top|bottom|near|far)\w*(?:\s+(?:end|side|edge))?(?:\s+of\s+the\s+(?:table|workspace))?\s+"
                  r"(?:to|towards?)\b)"  # ("cubes going from left to right": the line's direction)
                  r"|\bout\s+from\s+(?:under|underneath|beneath|behind|between)\b"
                  # "take the block from the green patch": a cube picked by where it stands now
                  r"|\b(?:take|move|pick|grab|lift|remove|get|bring|slide|push)\s+(?:up\s+)?the\s+(?:[a-z]+\s+){0,2}?(?:blocks?|cubes?|box"
                  r"|boxes|bricks?|ones?)\s+(?:up\s+)?from\s+(?:the\s+|its\s+|their\s+)",
     "picks a cube by its place in an order nobody defined or by what happened earlier: rpg's cubes are known "
     "only by colour and label; name the cube (e.g. \"the red block\"), or say the structure it is part of "
     "(\"the top block of the tower\")"),
    ("reference", r"\b(?:on|onto|to|in|into)\s+(?:(?:two|three|2|3|their|own|different|separate|distinct|individual)\s+)+(?:goal\s+)?patches\b"
                  r"(?!\s*(?:[:,(]|of\s+(?:the\s+)?(?:same|their|its|matching)))"
                  r"|\b(?:on|onto|to|in|into)\s+a\s+(?:different|separate|distinct)\s+(?:goal\s+)?patch\b"  # "each on a different patch"
                  # "Put each cube on its own patch.": cubes nobody named, each on a patch nobody named (a red cube on a grey
                  # patch had been made up; "the green cube on its own patch" is its colour's)
                  r"|\b(?:each|every|all|(?:cubes|blocks))\b[^.;!?]{0,60}?\b(?:on|onto|to|in|into)\s+(?:its|their)\s+own\s+(?:goal\s+)?patch\b"
                  r"(?!\s+(?:of|in|with)\s+(?:the\s+)?(?:same|matching|its|their)\b)",
     "does not say which patch each cube goes on (patches are known by colour): name each one (e.g. \"the red cube on "
     "the red patch and the blue cube on the green patch\")"),
    ("reference", r"\b(?:as\s+)?(?:shown|displayed|depicted|pictured|illustrated|demonstrated)\b"
                  r"|\bthe\s+same\s+(?:[a-z]+\s+)?(?:pyramid|tower|stack|row|line|wall|grid|circle|structure|task|thing|one)\s+as\s+"
                  r"(?:in|before|earlier|last|for|from|at)\b"
                  r"|\b(?:this|that|these|those|the\s+same|the\s+following|the\s+given)\s+(?:arrangement|configuration|layout"
                  r"|pattern|formation|scene|setup|set-up|picture|image|way|design)s?\b"
                  r"|\b(?:picture|image|photo|photograph|diagram|figure|screen|video|illustration|drawing|sketch|screenshot)s?\b"
                  r"|\b(?:from|like|as\s+in|like\s+in|in|of)\s+the\s+(?:(?:last|previous|first|earlier|given)\s+)?(?:example|demo"
                  r"|demonstration|sample|template|reference|model)\b",
     "refers to something shown or seen (a picture, the scene, an arrangement) that a task cannot see: say the "
     "arrangement in words (e.g. \"stack the red block on the blue block\")"),
    ("reference", r"(?:(?<=,)\s*(?:like|the\s+way|as\s+if|as\s+though)|(?:(?<=\bcube)|(?<=\bblock)|(?<=\bcubes)|(?<=\bblocks))\s+like"
                  r"|\b(?:just|exactly)\s+(?:like|as))\s(?!\s*(?:this|so|that|follows|such|well|usual)\b)"
                  rf"(?=[^.;!?]*\b(?:{COLOR_RE}|cubes?|blocks?|ones?|it|them|\d)\b)"
                  r"(?=[^.;!?]*\b(?:on|onto|atop|upon|under|beneath|below|above|behind|front|next|beside|left|right|between|near|top"
                  r"|bottom)\b)",
     "compares to cubes arranged as the instruction does not ask (\"like the green cube on the yellow cube\"): whether that "
     "arrangement is part of the goal is not said; say each placement the goal needs"),
    ("reference", r"\b(?:swap|swapping|swapped|interchange|exchange)\b|\bswitch(?:es|ed|ing)?\s+(?:the\s+)?(?:places|positions|spots)\b",
     "refers to something the instruction has not described: the places the cubes stand in now (the current "
     "scene), which a task's goal cannot see; say where each cube should end (e.g. \"put the red block "
     "left of the yellow block\")"),
    ("reference", r"\b(?:closer|nearer|further|farther)\s+(?:away\s+)?(?:to|from|apart|together)\b"
                  r"|\b(?:a\s+(?:bit|little|tad)|slightly|somewhat|a\s+few\s+(?:cm|centimet(?:er|re)s|inches))\s+(?:more\s+|further\s+|farther\s+)?"
                  r"(?:to\s+the\s+)?(?:left|right|forward|forwards|backward|backwards|back|up|down|closer|nearer|further|farther|away|apart)\b",
     "refers to where the cubes stand now (moved closer, further, a bit to one side): a task's goal says where "
     "they end up, not how far they moved; say the end state (e.g. \"put the red block next to the blue block\")"),
    ("action", r"\b(?:then|and|also|afterwards?|finally|after\s+that)\s*,?\s+(?:please\s+)?(?:tid(?:y|ies|ied|ying)|clean(?:s|ed|ing)?"
               r"|clear(?:s|ed|ing)?)\s+(?:\w+\s+)?(?:up|away)\b|\bput\s+(?:\w+\s+){0,3}?away\b"
               r"|\breset(?:s|ting)?\b|\b(?:stay|stays|remain|remains)\s+put\b",
     "is an action or a keeping the domain does not have (tidying up, putting away, resetting, staying put): a task's goal "
     "says where the cubes end up; say where each should be"),
    ("action", r"\boff\s+(?:of\s+)?the\s+(?:table|table's\s+edge|edge\s+of\s+the\s+table|workspace)\b",
     "is an action the domain does not have: its cubes stay on the table, and a task's goal says where on it they "
     "end up"),
    ("object", r"\b(?:balls?|spheres?|cylinders?|cones?|cups?|mugs?|bottles?|plates?|bowls?|pens?|toys?|books?"
               r"|drawers?|shelf|shelves|baskets?|bins?|trays?|doors?|triangles?\s+(?:block|piece)s?|rods?)\b"
               r"|\b(?:on|onto|in)\s+(?:the|a)\s+(?:balance\s+)?scales?\b",
     "names an object the domain does not have: it has only 5 cm cubes (coloured, optionally labelled) "
     "and flat coloured patches on the table"),
    ("action", r"\bon\s+(?:its|their|one|an?)\s+(?:sides?|edges?|corners?|ends?|points?|tips?)\b|\bon\s+end\b"
               r"|\b(?:tilt\w*|tipped|slanted|askew|angled|diagonally|sideways)\b"
               r"|\b(?:face|faces|facing|pointing|points|showing|shows)\s+(?:down|downwards?|away|backwards?|the\s+(?:table|floor|ground|wall))\b"
               r"|\bface[\s-]+down\b",
     "is a pose the domain does not have: every cube rests flat on one of its faces, upright; a task's goal says where "
     "cubes end up and, for a labelled cube, which face shows up or toward the camera"),
    # "Put the black cube to the left of the white cube, then to its right.": one cube put in one place, then in another
    # with no subject of its own (the first place had been kept)
    ("time", r"\b(?:to\s+the\s+(?:left|right)\s+of|behind|in\s+front\s+of|next\s+to|beside|on(?:\s+top\s+of)?|onto|under|near|far\s+from)"
             r"\s+the\s+[a-z]+\s+(?:cube|block)\s*,?\s*(?:and\s+)?then\s+(?:(?:move\s+|put\s+|slide\s+)?(?:it|them)\s+)?"
             r"(?:to\s+(?:the\s+)?(?:left|right)|to\s+its\s+(?:left|right)|behind|in\s+front|next\s+to|beside|on\s+top|onto|under)\b",
     "puts a cube in one place and then in another: a task's goal is checked once, at the end of the episode; say only "
     "where it must end up"),
    ("time", r"\b(?:used\s+to\s+be|had\s+been|(?:was|were)\s+(?:\w+\s+)?(?:on|in|at|next|beside|behind|under|left|right|stacked|"
             r"placed|lying|sitting|standing|resting))\b|\b(?:originally|beforehand|to\s+begin\s+with|at\s+first"
             r"|in\s+the\s+beginning|in\s+the\s+(?:morning|afternoon|evening)|at\s+(?:night|noon|midnight)|tomorrow|yesterday)\b"
             r"|\b(?:run|episode|trial|attempt)s?\s+after\s+(?:that|this|it)\b|\b(?:second|every|each|other)\s+(?:run|episode|trial)s?\b"
             r"|\b(?:from|starting\s+(?:from|with)|beginning\s+(?:from|with))\s+(?:a|the)\s+(?:start|scene|setup|state|configuration)"
             r"\s+(?:where|in\s+which|with)\b",
     "is about another time than the end of this episode (a past or starting state, a time of day, another run): a "
     "task's goal is checked once, at the end of one episode; say only where the cubes must end up"),
    # "Every morning, line up three yellow cubes.": a schedule ('morning' had been dropped as a filler)
    ("condition", r"\b(?:every|each)\s+(?:single\s+)?(?:morning|afternoon|evening|night|day|week|month|hour|session|shift|monday"
                  r"|tuesday|wednesday|thursday|friday|saturday|sunday|weekday|weekend)s?\b",
     "sets a schedule, a condition on when the task is done again: a task's goal is checked once, at the end of one "
     "episode; say only where the cubes must end up"),
    ("time", START_TIME_RE, "is about another time than the end of this episode (a starting state): a task's goal is checked "
                            "once, at the end of one episode; say only where the cubes must end up"),
    ("time", INITIALLY_RE, "is about the episode's starting state, which rpg builds only as one cube stacked on another "
                           "(\"yellow starts stacked on red\"); say only where the cubes must end up"),
    ("time", CUBE_STARTS_BESIDE_RE, "is about the episode's starting state, which rpg builds only as one cube stacked on "
                                    "another (\"yellow starts stacked on red\"); say only where the cubes must end up"),
    # a hostile helper's (forty-ninth session): a start, a past, a later motion or a stay said around the goal's words,
    # which had been dropped (the goal read alone, or the start read as the goal, or the wrong cube sent to a patch)
    ("time", r"'s\s+(?:starting|initial|start|original)\s+(?:place|position|spot|location)|\b(?:starting|initial|start|original)\s+"
             r"(?:place|position|spot|location)\s+of\b|\bin\s+(?:the|its|their)\s+(?:starting|initial|start|original)\s+(?:place|position"
             r"|spot|location)s?\b|\bset\s*-?\s*up\s+with\b|\bbefore\s+(?:the\s+(?:episode|start|task|run|trial)|we\s+(?:start|begin)|starting|beginning)\b"
             r"|\b(?:cube|block|one)\s*,?\s+(?:starting|beginning)\s+(?:on|behind|next\s+to|beside|under|underneath|beneath|below|above"
             r"|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|left\s+of|right\s+of)\b"
             r"|\b(?:move|take|bring|carry|slide|push|lift|shift|get)\s+the\s+[a-z]+\s+(?:cube|block|one)\s*,?\s+(?:which\s+|that\s+)?"
             r"(?:is\s+|sits\s+|rests\s+|lies\s+|stands\s+|sitting\s+|resting\s+|lying\s+|standing\s+)(?:currently\s+|now\s+|already\s+)?"
             r"(?:on|behind|next\s+to|beside|under|underneath|beneath|below|above|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|left\s+of"
             r"|right\s+of)\b"
             r"|\bfrom\s+(?:behind|beside|next\s+to|under(?:neath)?|beneath|below|in\s+front\s+of)\b"
             r"|\bfor\s+now\b|\bas\s+(?:it|they)\s+(?:is|are)\s+now\b"
             r"|\b(?:is|sits|lies|rests|stands)\s+(?:on|behind|next\s+to|beside|under|in\s+front\s+of|to\s+the\s+\w+\s+of)\b[^.;]{0,60}?"
             r"(?:\bbut|\band|,)\s+(?:it\s+)?(?:should|must|needs?\s+to|has\s+to|belongs|ought)\b"
             r"|\b(?:before|after)\s+(?:going|sitting|being|moving|resting|lying|standing)\b"
             r"|\b(?:used\s+to|(?:is|are|was|were)\s+used\s+to|had\s+to|(?:was|were)\s+going\s+to|would\s+have|could\s+have)\b"
             r"|\bthen\s+(?:move|lift|pick|take|carry|remove|raise|hold|knock|push)\s+(?:it|them|that|this)(?:\s+(?:up|away|off|out|on))?"
             r"\s*(?:[.!;,]|$)|\bthen\s+(?:moves?|carr(?:y|ies)|go(?:es)?|carry)\s+on\b"
             r"|\bfor\s+(?:a|one|just\s+a|only\s+a)\s+(?:second|sec|spell|bit|while|minute|min|jiffy|tick|instant|moment|beat)\b",
     "is about another time than the end of this episode (where a cube starts, was, or goes after): a task's goal is "
     "checked once, at the end of one episode, from a scattered start (rpg builds a start only as one cube stacked on "
     "another); say only where the cubes must end up"),
    # a second hostile helper's (forty-ninth session): a relation after a listed structure (its last cube had taken it),
    # a structure "like" another said by "one", a structure nobody built, an exclusion, a colour nobody named, a digit
    # after a colour, a superlative of distance
    ("reference", rf"\b(?:tower|stack|column|row|line|pile)\s+of\s+(?:the\s+)?(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))*\s*,?\s+(?:and|&)\s+"
                  rf"(?:the\s+)?(?:{COLOR_RE})\s+(?:behind|in\s+front\s+of|left\s+of|right\s+of|to\s+the\s+(?:left|right)\s+of"
                  rf"|next\s+to|beside|near|between)\s+(?:the\s+)?(?:{COLOR_RE})\b"
                  rf"|\bstack\s+(?:the\s+)?(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))*\s*,?\s+(?:and|&)\s+(?:the\s+)?(?:{COLOR_RE})"
                  rf"\s+(?:behind|in\s+front\s+of|left\s+of|right\s+of|to\s+the\s+(?:left|right)\s+of|next\s+to|beside"
                  rf"|near|between)\s+(?:the\s+)?(?:{COLOR_RE})\b",
     "relates a listed structure to a cube, which could be said of its last cube or of the whole structure: say it of the "
     "structure (e.g. \"build a tower of red and blue, and put the tower behind the green cube\")"),
    ("reference", rf"\b(?:on|onto|in|into|next\s+to|beside|behind|near|at\s+the\s+end\s+of)\s+(?:the\s+)?(?:{COLOR_RE})\s+(?:circle|pyramid|wall|grid)\b"
                  r"|\b(?:on|onto|in|into)\s+the\s+(?:circle|pyramid|wall|grid)\s*(?:[.!;,]|$)|\bas\s+(?:tall|high|wide|big)\s+as\b",
     "refers to a structure nobody described (\"the blue circle\", \"as tall as the tower\"): describe each structure with "
     "its cubes (e.g. \"a circle of six blue cubes\")"),
    ("negation", r"\bother\s+than\b|(?<!\bfar\s)\bapart\s+from\b|\banything\s+but\b",
     "excludes something (\"other than\", \"apart from\"): a task's goal says which cubes go where; name them"),
    ("quantity", rf"(?<!\bbe\s)\b(?:{COLOR_RE})\s+and\s+(?:{COLOR_RE})\s+only\b|\b(?:of|in)\s+(?:another|some\s+other|any\s+other)\s+colou?r\b"
                 rf"|\bboth\s+(?:the\s+)?(?:{COLOR_RE})\s+and\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?\s+(?:on|onto|atop|on\s+top\s+of)\b"
                 r"|\bby\s+(?:one|two|three|four|\d+)\s+(?:cubes?|blocks?)\b"
                 rf"|\b(?:{COLOR_RE})\s+(?:one|two|three|four|five)\s+(?:cubes?|blocks?)\s+(?:to\s+the\s+)?(?:left|right|above|below|behind|in\s+front"
                 r"|away|apart)\b",
     "says a colour only, another colour, both cubes on one, or a distance rpg does not read: name each cube and where it "
     "goes"),
    ("action", r"\b(?:likes?|loves?|prefers?|enjoys?|hates?|dislikes?|wants?|wanted|wishes|wished|hopes?|longs?|yearns?)\s+(?:to\s+)?"
               r"(?:be|sit|sitting|rest|resting|stand|standing|lie|lying|stay|staying|go|going)\b",
     "gives a cube a liking or a wish, which a goal does not have: say where the cube must end up"),
    ("quantity", rf"[\u00bc-\u00be\u2150-\u215e]|(?<![\w.])\.\d|\b\d+\.(?=\s+(?:(?:{COLOR_RE})\s+)?(?:cubes?|blocks?)\b)|\d\s*[+*]\s*\d+\s+(?:[a-z]+\s+)?(?:cubes?|blocks?)\b"
                 r"|\b[a-z0-9]+-plus\b|[~\u2248\u2265\u2264<>]\s*\d|\b(?:one|two|three|four|five|six|\d+)\s*/\s*(?:one|two|three|four|five|six"
                 r"|\d+)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b|\d\s*[\u2012-\u2015]\s*\d|\bx\d+\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b|\b\d+e\d+\b|\b0[bx][0-9a-f]+\b"
                 r"|\b(?:cube|block|one|it|them)\s+(?:one|two|three|four|five|\d+)\s+(?:cubes?|blocks?)\s+(?:to\s+the\s+)?(?:left|right|above"
                 r"|below|behind|in\s+front|away|apart|over|further|farther)\b"
                 r"|\b(?:a|one|two|three|four|five|\d+)\s+(?:cube\s+|block\s+)?(?:widths?|lengths?|spaces?)\b"
                 r"|\b(?:far|high|way|well)\s+(?:above|below|over|under)\b",
     "is a count or a distance in a notation rpg does not read (a fraction, a sum, a bound, a number of cube widths): a "
     "task places whole cubes, and its relations are qualitative; say how many cubes and where, in words"),
    ("quantity", rf"\ball\s+(?:{COLOR_RE}|the\s+same(?:\s+colou?r)?)\s+(?:but|except(?:\s+for)?)\s+(?:one|two|three|\d+)\b"
                 r"|\b(?:of|in)\s+(?:two|three|four|five|\d+)\s+colou?rs\b|\bmatching\s+(?:cubes|blocks)\b",
     "says how many colours a group has, or that all but some share one, without saying which cube has which: name each "
     "cube's colour (e.g. \"four red cubes and one blue cube\")"),
    ("contradiction", r"\bactually\b[^.;]{0,15}?\b(?:one|two|three|four|five|six|seven|eight|nine|ten|\d+)(?:\s+(?:cubes?|blocks?))?\s*(?:[.!;,]|$)|\b(?:one|two|three|four"
                      r"|five|six|seven|eight|nine|ten|\d+)\s*,?\s+actually\b|(?:^|[.;!]\s*)make\s+it\s+(?:one|two|three|four|five|six"
                      r"|seven|eight|nine|ten|\d+)\s*[.!]?\s*$",
     "corrects a count said before it: say the one count the task should have"),
    ("shape", r"\bvertical(?:ly)?\s+(?:row|line)\b(?![^.;]*\b(?:front|back)\b)|\b(?:row|line|between|either\s+side|each\s+side)\b[^.;]*\bvertical(?:ly)?\b"
              r"|\babove\s+and\s+below\b",
     "puts a row or a between upright, which rpg does not build: a row lies on the table; cubes one above another are a "
     "tower (say its order from the bottom)"),
    ("contradiction", BUT_CORRECTION_RE,
     "may correct what was said before it or add to it: one of the two end states; say the one the task should have"),
    ("reference", VIEWPOINT_RE, VIEWPOINT_WHY),
    ("reference", r"\band\s+another\s+one\s*(?:[.!;]|$)|\b(?:only|just|any)\s+(?:\d+|one|two|three|four|five|some|a\s+few)\s+of\s+(?:them|those|these)\b"
                  rf"|\b(?:\d+|two|three|four|five|some|a\s+few)\s+of\s+the\s+(?:{'|'.join(COLORS)})(?:\s*,\s*(?:{'|'.join(COLORS)}))*"
                  rf"(?:,?\s+(?:and|or)\s+(?:{'|'.join(COLORS)}))\s+(?:cubes|blocks)\b"
                  r"|\b(?:build|stack)\s+(?:\d+|one|two|three|four|five|some)\s+of\s+(?:them|those|these)\b",
     "picks some of a group described earlier: which ones is not said; describe only what the goal has (e.g. \"build "
     "one tower of two cubes\")"),
    ("reference", rf"\b(?:\d+|one|two|three|four|five|six|a\s+few|some|several|a\s+couple)\s+more\b(?!\s+(?:(?:{'|'.join(COLORS)}|grey)\b"
                  r"|(?:[a-z]+\s+)?(?:cubes?|blocks?|bricks?)\b|than\b))|\b(?:add|stack|put|place|pile|set|build|make|create|do)\s+another(?:\s+one)?\s*(?=on\b|onto\b|next\b|behind\b|beside\b|[.!;,]|$)"
                  r"|\b(?:make|build|do|add)\s+(?:\d+|one|two|three|four|five|another)\s+(?:more\s+)?(?:of\s+)?(?:these|those|this|that|them)\b"
                  # "one more green under the red": more of a colour no cube of which was said before (in its sentence)
                  rf"|^(?:(?!\b(?:{'|'.join(COLORS)}|grey)\b).)*?\b(?:\d+|one|two|three|four|five|a\s+couple|a\s+few|some)\s+more\s+"
                  rf"(?:{'|'.join(COLORS)}|grey)\b(?!\s+(?:cubes?|blocks?|bricks?|ones?)\b)"
                  # "Make another tower just like it.", "an identical pyramid next to it": a copy of a structure said
                  r"|\b(?:another|a\s+second|an\s+identical|a\s+matching|a\s+copy\s+of\s+the)\s+(?:(?:identical|matching|similar|same)\s+)?"
                  r"(?:one|tower|stack|pyramid|row|line|wall|grid|circle|pile|structure)s?\b(?=\s+(?:just\s+|exactly\s+)?(?:like|as|identical"
                  r"|the\s+same|next\s+to\s+(?:it|that|this)|beside\s+(?:it|that|this))\b)"
                  r"|\b(?:make|build|add|create|stack|construct)\s+(?:another|a\s+second|an\s+identical)\s+(?:one|tower|stack|pyramid|row|line|wall"
                  r"|grid|circle|pile|structure)\b(?=\s*[.!;]?\s*$)",
     "asks for more cubes or copies than it names (\"two more\", \"another\", \"three of these\"): which cubes, and "
     "where, is not said; name each cube of the goal (e.g. \"stack the green block on the red block\")"),
    ("condition", r"\b(?:maybe|perhaps|possibly|ideally|preferably|or\s+else)\s+(?:even\s+)?(?:on|onto|in|into|at|next|near|behind|under"
                  r"|beside|to|left|right|in\s+front|far|stacked)\b",
     "hedges between two goals ('maybe on it'): a task has one goal, checked at the end; say the one end state"),
    ("quantity", r"\b(?:times\s+(?:\d+|two|three|four|five)|(?:\d+|" + "|".join(w for w in NUMBER_WORDS if w not in ("single", "pair"))
                 + r"|dozen|several|many|multiple)\s+times|twice|thrice)\b",
     "says how many times: a task is one end state, checked once; say how many cubes or structures it has (e.g. \"two "
     "towers of three gray cubes\")"),
    ("contradiction", r"\bboth\s+(?:at|on)\s+(?:the\s+)?(?:bottom|base|top)\s+and\s+(?:at|on)\s+(?:the\s+)?(?:top|bottom|base)\b",
     "puts one cube at both ends of a tower: a cube stands in one place at the end of the episode; say which end"),
    ("contradiction", rf"\bthe\s+(?P<c>{'|'.join(COLORS)}|grey)\s+(?:cube|block|one)\b[^.;]*?\b(?P<w>the\s+(?:very\s+)?same\s+(?P=c)\s+"
                      r"(?:cube|block|one))\s+(?:is\s+)?(?:also\s+|too\s+)?(?:at|on|in|under|next|beside|behind|left|right|as)\b",
     "gives the cube named before a second place: one cube stands in one place at the end of the episode, so the two "
     "places contradict each other; say one place for it, or say two cubes of that colour"),
    ("shape", rf"\b(?:the|a|an|one|each)\s+(?:{'|'.join(COLORS)}|grey)\s+(?:triangles?|triangular\s+(?:blocks?|pieces?|prisms?)"
              r"|prisms?|wedges?)\b(?!\s+of\b)",
     "names a piece of a shape the domain does not have (a triangle, prism or wedge): it has only 5 cm cubes "
     "(coloured, optionally labelled) and flat coloured patches; a pyramid is built of cubes (e.g. \"a pyramid of 3 "
     "cubes\")"),
    # "Build a round tower.", "a cylindrical stack": a rounded structure of cubes (the word had been dropped, a tower built)
    ("shape", r"\b(?:round(?:ed)?|cylindrical|curved|spherical|conical)\s+(?:towers?|stacks?|piles?|columns?|walls?|pyramids?|blocks?|cubes?)\b",
     "is a shape the domain does not have: its structures are towers, lines, circles, grids, pyramids, walls and piles "
     "of cubes (a circle of cubes is \"cubes in a circle\")"),
    # "Put every cube to the left of the white cube.", "Put every cube on the blue patch.": all the scene's cubes, of a
    # count and colours nobody said (one red cube had been made up)
    ("quantity", rf"\b(?:put|place|move|set|bring|slide)\s+(?:every|each|all(?:\s+(?:of\s+)?the)?|all\s+other)\s+(?:other\s+|remaining\s+)?"
                 rf"(?:cubes?|blocks?)\b(?=\s+(?:to\s+the\s+(?:left|right)\s+of|next\s+to|beside|behind|in\s+front\s+of|near|far\s+from|under"
                 rf"|on\s+top\s+of|on|onto|in|into)\s+the\s+(?:(?:{'|'.join(COLORS)})\s+(?:cube|block|patch|goal\s+patch)|patch)\b"
                 r"(?!\s+(?:of\s+(?:its|their|the\s+same|a\s+matching|matching)|that\s+match|matching|:)))",  # ("on the patch of its
                 # own colour: ...", "on the patch of the same color": each cube's own patch)
     "asks for every cube of the scene, whose count and colours the instruction does not say: name the cubes (e.g. \"put "
     "the red and the green cube on the blue patch\")"),
    # some of a group ("two of the three green cubes", "2 out of 4", "all but one", "every red cube but one"): which cubes
    # is not said (the whole group had been placed, silently)
    ("quantity", r"(?<!\bone\s)(?<!\b1\s)\b(?:[2-9]|two|three|four|five|six|some|most|half)\s+(?:of|out\s+of)\s+(?:the\s+|these\s+|those\s+)?(?:\d+|two|three"
                 r"|four|five|six|seven|eight|nine|ten)\s+(?:[a-z]+\s+)?(?:cubes|blocks|ones)\b|\bof\s+the\s+(?:\d+|two|three|four|five|six)"
                 r"\s+(?:[a-z]+\s+)?(?:cubes|blocks)\s*,\s*(?:\d+|one|two|three|four|five)\b|\ball\s+but\s+(?:\d+|one|two|three|four|five)\b"
                 r"|\b(?:cubes?|blocks?)\s+but\s+(?:\d+|one|two|three|four|five)\b",
     "picks some cubes of a group (\"two of the three\", \"all but one\"): which of them is not said; name the cubes and "
     "their count (e.g. \"put two green cubes on the blue patch and one green cube on the table\")"),
    # a range or an approximate count ("2-3 red cubes", "two to three", "2+", "3 or so", "3 and up", "2/3", "cube * 2"):
    # one number had been taken, silently ("at least" and "up to" were refused already)
    ("quantity", r"\b\d+\s*(?:-|\u2013|to|/)\s*\d+\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b|\b(?:one|two|three|four|five|six)\s*(?:-|to)\s*"
                 r"(?:two|three|four|five|six|seven|eight)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b|\b\d+\s*\+\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b"
                 r"|\b(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:or\s+so|and\s+up|or\s+more|or\s+fewer|or\s+less|ish)\b"
                 r"|\b(?:cube|block)s?\s*[*\u00d7]\s*\d+\b|,?\s*\bplus\s+(?:one|1|two|2|another|a\s+few|some)\b"  # ("3 red cubes, plus one")
                 r"|(?:^|(?<=\s))-\d+\s+(?:[a-z]+\s+)?(?:cubes?|blocks?)\b",
     "gives a range or an approximate count (\"2-3 cubes\", \"3 or so\"): a task has an exact number of cubes; say it"),
    # "one cube of each colour", "two cubes of each colour": cubes of colours nobody named, so how many is not said (one
    # red cube had been made, silently)
    ("quantity", r"\b(?:cubes?|blocks?)\s+(?:of|in)\s+(?:each|every)\s+colou?r\b(?!\s*:)",
     "asks for cubes of every colour without naming the colours: say each colour and its count (e.g. \"one red, one blue "
     "and one green cube on the blue patch\")"),
    # "put the red cube on the blue patch and all other cubes on the green patch": cubes nobody named (made up)
    ("quantity", r"\b(?:all|every|each)\s+(?:the\s+)?other\s+(?:cubes?|blocks?)\b",
     "asks for every other cube of the scene, whose count and colours the instruction does not say: name the cubes"),
    # "Stack 2.5 orange cubes", "one and a half blocks", "half a cube": a count that is not whole (5 cubes had been made of
    # "2.5", silently)
    ("quantity", r"(?<![\d.])\d+[.,]\d+\s*-?\s*(?:[a-z]+\s+){0,2}(?:cubes?|blocks?)\b|\b(?:one|two|three|four|five|\d+)\s+and\s+an?\s+"
                 r"half\s+(?:[a-z]+\s+)?(?:cubes?|blocks?)\b|\b(?:half|a\s+third|a\s+quarter)\s+(?:of\s+)?an?\s+(?:[a-z]+\s+)?(?:cube|block)\b",
     "is a count that is not a whole number (\"2.5 cubes\", \"half a cube\"): a task places whole cubes; say how many"),
    ("quantity", r"\b(?:minus|negative)\s+(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b|\bzero\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b",
     "is a quantity the domain cannot hold (a count below one): a task places whole cubes, one or more; say how many cubes"),
    ("contradiction", r"\b(?:on|onto|on\s+top\s+of|atop|under|below|beneath|next\s+to|beside|left\s+of|right\s+of|behind|in\s+front\s+of)"
                      r"\s+(?:itself|themselves)\b",
     "relates a cube to itself, which contradicts what a relation is: a cube cannot stand on or beside itself; name two cubes"),
    ("time", r"\b(?:which|that|who)\s+(?:starts|begins|is\s+initially|sits\s+initially|started|began)\s+(?:out\s+)?(?:on|in|at|atop|under"
             r"|beneath|below|next|beside|behind|stacked|sitting|resting|standing)\b",
     "states a start inside a clause of the goal, which rpg does not read there: say the start first (e.g. \"Initially "
     "the blue cube is on the green cube. Put the red cube on the blue cube.\")"),
    ("question", r"^\s*(?:(?:hey|hi|so|ok(?:ay)?)\s*,?\s+)?(?:did|have|has|had)\s+(?:you|the\s+robot|it|we|they)\b",
     "asks a question about what was done: a task is an instruction whose goal says where cubes end up; ask for the "
     "arrangement instead (e.g. \"put the red block on the blue block\")"),
    ("size", rf"\b(?:big|bigger|biggest|large|larger|largest|small|smaller|smallest|little|tiny|huge|giant|mini|tall|taller"
             r"|tallest|short|shorter|shortest|wide|wider|widest|narrow|thin|thick|fat|heavy|heavier|heaviest)\s+"
             rf"(?:{'|'.join(COLORS)}|grey)(?=\s*(?:$|[,.;!?]|(?:on|onto|under|below|next|beside|behind|to|in|at|and|one|cube|block|brick)\b))",
     "asks for a size: every cube is the same size (5 cm), so no cube is bigger or smaller than another"),
    # "Hey you in the front left corner, put ...": a listener called by where they stand (the place had become the goal's)
    ("reference", r"^\s*(?:hey|hi|oi|yo)\s*,?\s+(?:you|there)\s+(?:in|at|on|over|by|near)\s+the\s+[^,:;.!?]*",
     "calls someone by where they stand, which refers to the scene now, not to where cubes end up; leave it out or say "
     "where the cubes must go"),
    # "Reversed, stack red, green, blue": an order reversed from one nobody said (the word had been dropped)
    ("reference", r"^\s*(?:reversed|in\s+reverse(?:\s+order)?|backwards|the\s+other\s+way\s+round)\s*[,:;\-\u2014]",
     "refers to an order said before (reversed, backwards): say the order itself (e.g. \"from bottom to top: blue, green, "
     "red\")"),
    # "now red is on blue. put ...", "red is currently on blue": the scene now (it had become part of the goal)
    ("reference", rf"\b(?:right\s+)?now\s*,?\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:is|sits|stands|lies|rests)\b"
                  r"|\b(?:is|are|sits|stands|lies|rests)\s+(?:currently|presently|at\s+the\s+moment)\b|\bcurrently\b"
                  # "Right now there is red on blue. Stack ...": a start no reader took (it had become part of the goal)
                  r"|^\s*(?:(?:right\s+)?now|at\s+the\s+moment|at\s+present)\s*,?\s+there(?:'s|\s+is|\s+are)\b"
                  r"|^\s*there(?:'s|\s+is|\s+are)\s+(?:now|currently|at\s+the\s+moment|at\s+present)\b",
     "describes the scene now (currently, now ... is), which refers to where cubes stand, not where they must end up; "
     "say the start as \"Initially the red cube is on the blue cube.\" and then the goal"),
    # "a 0-block tower of red on yellow": a structure of no cubes (the count had been dropped)
    ("quantity", r"\b(?:0|zero)\s*[- ]\s*(?:blocks?|cubes?)\b(?=\s+(?:tall\s+|high\s+)?(?:tower|stack|column|row|line|wall|pile)\b)",
     "asks for a structure of no cubes: a quantity below one; say how many cubes it has"),
    # "a 9-on-10 tower", "a red-next-to-yellow tower", "two 1-on-2 towers": a chain as one word that no rewrite read
    # (lexicon.hyphened_chains; it had been dropped, a tower of made-up cubes)
    ("object", r"\b[\w]+-(?:on|onto|upon|over|atop|above|under|below|beneath|next-to|beside|left-of|right-of|ontop|on-top-of)-[\w]+\b",
     "names a tower as one hyphenated word, which rpg reads only between two colours or two digits before 'tower' (\"a "
     "red-on-blue tower\", \"a 1-on-2 tower\"): say it in words (e.g. \"the 1 cube on the 2 cube\")"),
    # "make the tower taller": a structure changed against itself (the comparison had been dropped: a tower of two)
    ("reference", r"\b(?:make|build|get|have)\s+(?:the|it|this|that|your|my|our)\s*(?:(?:[\w-]+\s+){0,3}?(?:tower|stack|row|line|pile|wall|pyramid|column)\s+)?"
                  r"(?:a\s+(?:bit|little|lot)\s+|much\s+|even\s+)?(?:taller|shorter|higher|lower|longer|wider|bigger|smaller|larger)\b",
     "compares a structure with how it stands now (taller, longer): a task's goal says where the cubes end up; say the "
     "structure whole (e.g. \"a tower of three cubes: red on blue on green\")"),
    # "a big-on-small tower": sizes said as the tower's cubes (they had been dropped: a tower of two made-up cubes)
    ("size", r"\b(?:big|bigger|biggest|large|larger|largest|small|smaller|smallest|little|tiny|huge)\s*[-\u2013]?\s*(?:on|over|atop|under|below)"
             r"\s*[-\u2013]?\s*(?:the\s+)?(?:big|bigger|biggest|large|larger|largest|small|smaller|smallest|little|tiny|huge)\b",
     "asks for a size: every cube is the same size (5 cm), so no cube is bigger or smaller than another"),
)
"""Meaning the domain cannot express, by class: (class, pattern over the lower-cased text,
why; a group named ``w``, where it matched, holds the words to name).  An instruction that
says one is refused naming the words and why (refuse rather than guess); none of these words
may be dropped as a filler."""

SIZE_COMPARATIVE_RE = re.compile(r"\b(?:largest|smallest|biggest|heaviest|lightest|larger|smaller|bigger|heavier|lighter)\b")
"""A cube compared by size or weight on its own ("from largest at the bottom to smallest", "the
larger of the two"): refused as a size, like :data:`INEXPRESSIBLE`'s "size" class, unless
:data:`LABEL_VALUE_RE` says the comparison is of the cubes' labels."""

LABEL_VALUE_RE = re.compile(r"\b(?:digits?|numbers?|numerals?|numeric\w*|values?|letters?|alphabet\w*)\b|\b\d\b")
"""Words that make "smallest"/"largest" a label's value ("the digits from smallest to largest")."""

NOT_OBJECTS: frozenset[str] = frozenset("""
task tasks objective objectives job aim purpose way ways position positions direction directions orientation
idea step steps thing things kind sort instruction instructions scene setup configuration state arrangement
manner fashion time end result outcome mission challenge game attempt order sequence version variant
copy one side part level
""".split())
"""Nouns that name no object: an unknown word among these is not refused as a missing object
(the parser says it could not read it instead)."""

CUBE_MODIFIERS: frozenset[str] = frozenset("""
letter letters digit digits number numbers numeral word lettered labelled labeled marked numbered coloured colored
top bottom middle centre center left right front back rear base upper lower leftmost rightmost topmost bottommost
uppermost lowest highest first second third fourth fifth sixth last final next other same single only remaining spare
extra new goal target matching respective own whole one another every each both all any empty
""".split())
"""Known words that may stand between an article and a cube or patch noun without being its colour or
label ("the top cube", "the other block", "the goal patch"); any other word of the lexicon there
("the pick cube") stands where a colour does and is refused, not dropped (the cube had taken a
default colour, silently)."""

UNKNOWN_OBJECT = ("object", "names an object the domain does not have: it has only 5 cm cubes (coloured, "
                  "optionally labelled) and flat coloured patches on the table")
"""How an unknown noun is refused when it stands where an object does ("insert the peg", "a
puck"): the noun heads a phrase after a determiner, lemminflect knows it as a noun, and it is not
in :data:`NOT_OBJECTS`."""

UNKNOWN_COLOUR = ("colour", "is a colour the palette does not have: cubes and patches come in "
                  + ", ".join(sorted(PALETTE)) + "; name one of them")
"""How an unknown word is refused when it is a colour's name (:func:`colour_names`: "the mauve
cube") and stands where a cube's or patch's colour does."""


@lru_cache(maxsize=1)
def colour_names() -> frozenset[str]:
    """One-word colour names people use (matplotlib's CSS4 and XKCD colour tables, e.g. "mauve",
    "teal", "crimson"), for telling an unknown colour from an unknown word."""
    import matplotlib.colors as mcolors  # a table of names only; loaded on the refusal path

    names = set(mcolors.CSS4_COLORS) | {n.split(":", 1)[1] for n in mcolors.XKCD_COLORS}
    return frozenset(n for n in names if n.isalpha())

THING_NOUN = ("(?:cubes?|blocks?|bricks?|boxes|box|patch(?:es)?|ones?|shapes?|structures?|walls?|"
              + "|".join(sorted({f"{w}s?" for k in STRUCTURE_KINDS.values() for w in (*k.words, *k.described_by)})) + ")")
"""A noun for a cube, a patch or a structure (plural too), from the structure kinds' own words: what
a word outside the lexicon may describe or act on (:func:`rpg.schema.reading.ignorable_unknown`)."""

UNKNOWN_CARRIES_MEANING: frozenset[str] = frozenset("""
time times week weeks day days month months year years weekend deadline timer clock monday tuesday wednesday thursday
friday saturday sunday once whichever whatever wherever whoever case why whether either else outline perimeter border
frame hollow silhouette rerun redo orientation pose angle count counts counting counted whose whom upside
""".split())
"""Words outside the lexicon that carry meaning a task cannot hold (a time, a condition - "once",
"whichever", "in case" -, a question, an alternative, a shape, a repeat of something done
before): never ignored as an unknown word (:func:`rpg.schema.reading.ignorable_unknown`).  Since
no dictionary word is ignored alone, this list decides for the parts of a hyphenated word
("time-limited") and for spellings the dictionary lacks."""

UNKNOWN_ACTION = ("action", "is an action the domain does not have: a task's goal says where cubes end up "
                  "(stacked, in a line, next to or on something, on a patch); say where the cubes should end")
"""How an unknown verb is refused when it stands where a command's verb does (first word of a
clause: "throw the red block", "then shake it")."""

CAUSED_MOTION_RE = re.compile(
    r"(?i)(?P<pre>(?:^|[.;:!?]\s+|,\s+(?:and\s+)?(?:then\s+)?|\band\s+(?:then\s+)?|\bthen\s+|\bplease\s+|\blet's\s+|\bnow\s+|\bjust\s+"
    r"|\balso\s+)\s*)(?P<v>[a-z]+)\s+"
    r"(?=(?:the|a|an|both|all\s+the|\d+|one|two|three|four)\s+(?:[a-z0-9]+\s+){0,2}?(?:cubes?|blocks?|tower|stack|row|line|pile|wall|pyramid)\s+"
    r"(?:(?:all\s+the\s+way|right|straight|over|gently|carefully)\s+)?"
    r"(?:onto|on\s+top\s+of|on|into|in\s+the\s+(?:(?:far|back|front)\s+)?(?:left|right|front|back|center|centre|middle)|next\s+to|beside"
    r"|behind|in\s+front\s+of|between|under|underneath|atop|to\s+the\s+(?:left|right)\s+of"
    r"|to\s+the\s+(?:(?:far|back|front|near)\s+)?(?:left|right|front|back|center|centre|middle)\b|to\s+the\s+[a-z]+\s+(?:patch|corner)"
    r"|at\s+the\s+(?:(?:far|back|front)\s+)?(?:left|right|front|back|center|centre|middle))\b)")
"""A verb the lexicon lacks in the caused-motion construction, verb + cube + where it goes ("taxi the yellow cube to the back
left corner", "post the red cube to the front right corner", "hang the red cube on the blue patch"): the construction
says the cube is moved there, whatever the verb's manner, so it reads as "put" (:func:`rpg.schema.reading.normalize_words`;
it had been refused as an action).  Not a verb of :data:`UNKNOWN_KIND_EXEMPLARS`' actions (a turn, a throw, a spill:
what they do to the cube is more than where it ends), nor one of :data:`SCENE_CHANGING_VERBS` (read as themselves)."""

MOTION_VERB_EXEMPLARS: tuple[str, ...] = tuple(
    "move carry slide push drag bring deliver transport shift place drop set put take lay lift send".split())
CHANGE_VERB_EXEMPLARS: tuple[str, ...] = tuple(
    "melt paint burn crush break cut glue wash freeze bend rotate spin flip throw toss hurl shake twist destroy dissolve colour "
    "juggle bounce".split())
"""Verbs that move a thing to a place, and verbs that change, turn or throw it: an unknown verb of a caused-motion clause
(:data:`CAUSED_MOTION_RE`) is read as "put" only when it is nearer the first (:func:`rpg.schema.senses.moves_a_thing`)."""

UNKNOWN_KIND_EXEMPLARS: dict[str, tuple[str, ...]] = {
    "size": tuple("big small large tiny huge giant heavy thin thick wide narrow size sized massive miniature".split()),
    "quantity": tuple("few many several half most dozen plenty amount distance centimeter inch meter degrees maximum "
                      "minimum percent".split()),
    "time": tuple("second minute hour until later soon wait duration moment forever".split()),
    "negation": tuple("not never without except avoid none nothing".split()),
    "condition": tuple("if unless whenever otherwise".split()),
    "action": tuple("rotate spin throw flip roll shake topple knock pour cut open close twist wipe sweep toss".split()),
    "object": tuple("ball cup mug bottle bowl plate peg nut rope disk cylinder sphere container drawer shelf basket "
                    "tray".split()),
    "shape": tuple("triangle star heart hexagon oval arch staircase spiral smiley prism wedge".split()),
    "reference": tuple("previous earlier original former latter remaining".split()),
}
"""Words of meaning the domain cannot express, by class (:data:`INEXPRESSIBLE`,
:data:`UNKNOWN_OBJECT`, :data:`UNKNOWN_ACTION`, :data:`SHAPE_WHY`): an unknown word whose
embedding is close to one of them is refused for that class (:mod:`rpg.schema.senses`)."""

SHAPE_WHY = ("names a shape the domain does not build: its structures are towers, lines, circles, grids, walls, "
             "pyramids, bridges and piles of 5 cm cubes")
"""Why a shape the domain lacks is refused (:data:`UNKNOWN_KIND_EXEMPLARS`)."""

SENSE_MIN_SIMILARITY: float = 0.5
"""Least cosine similarity (WordLlama, 256-d) of an unknown word to a word of
:data:`UNKNOWN_KIND_EXEMPLARS` for it to be refused for that class; it must also be at least
its similarity to every vocabulary word.  At 0.5, "enormous" (0.60 to "huge"), "toppled" (0.74
to "topple") and "dozen" are classed; "gigantic" (0.34) and "kick" (0.24) stay unknown words
(project, set on the lexicon's own lists and made-up probe words, 2026-11-23)."""

IGNORABLE_MIN_SIMILARITY: float = 0.45
"""Least cosine similarity of an unknown adverb or adjective to an :data:`IGNORABLE` word for
it to be dropped like one ("swiftly" 0.60 to "quickly", "wonderful" 0.64 to "great")."""

IGNORABLE_MARGIN: float = 0.1
"""How much closer to an ignorable word than to every vocabulary word such a word must be.
With :data:`IGNORABLE_MIN_SIMILARITY`, leaving each vocabulary word out in turn, only "goes",
"robot" and "sequential" would read as ignorable (none changes a goal), and none of 70
made-up spatial, structural and reference words tried ("diagonally", "sideways", "staggered",
"stairs", "upside", "remaining") does; "stairs" comes to 0.53 of "stably" (shared subwords),
which is why nouns and verbs are never dropped (project, measured 2026-11-23)."""

REFERENCE_PRONOUN_RE = re.compile(
    r"\b(it|them|they)\b(?!\s*(?:is|was|will|would|should|must|has)\b)"
    r"|\b(that|this|those|these)\b(?=\s*(?:[.,;!?]|$)|\s+(?:on|onto|to|in|into|next|beside|behind|under|from|off|up"
    r"|down|back|over|at|left|right|and)\b)")
"""A pronoun standing for cubes ("stack them", "unstack that.", "put it on the red block").  It
must refer to something the instruction named before it (:data:`ANTECEDENT_RE`); without one it
refers to what the speaker sees or did earlier, which a task cannot know."""

DEICTIC_RE = re.compile(r"\b(?P<d>this|these|that|those)\s+(?:(?:\d+|two|three|four|five|six)\s+)?"
                        r"(?:blocks?|cubes?|ones?|boxes|box|bricks?|objects?|items?|pieces?)\b")
""""This block", "these cubes", "those two blocks": cubes picked by pointing at them in a scene.
"this"/"these" always point (a cube the speaker sees); "that"/"those" may instead refer back to
a cube named before (:data:`ANTECEDENT_RE`). A colour said ("this red block") names the cube,
and the phrase does not match."""

THIS_ORDER_RE = re.compile(r"\b(?:this|that|the\s+following|the\s+given)\s+(?:order|sequence)\b")
""""In this order", "in that order": an order the instruction must list (two or more colours or
labels, before or after); with none it is one the speaker shows, which a task cannot know."""

LISTED_ORDER_SAID_RE = re.compile(r"\b(?:in\s+order|in\s+(?:a\s+|this\s+|that\s+|the\s+)?(?:exact\s+)?sequence|sequential\w*|successive\w*"
                                  r"|one\s+after\s+(?:the\s+)?(?:other|another)|consecutive(?:ly)?|in\s+turn|respectively)\b")
"""Words that keep a listed row's order with no direction said ("the digits 1, 2 and 3 in a row, in order"), as
:data:`THIS_ORDER_RE` does."""

ROW_PLACE_WORD_RE = re.compile(r"\b(?:then|first|last|next(?!\s+to\b)|number\s+line|middle|cent(?:er|re)|between|order\w*|exact\w*|left\w*|right\w*|ends?"
                               r"|before|after|follow\w*|precede\w*)\b")
"""Words that may place a listed label cube in its row ("3, then 1, then 2", "with 1 in the middle", "Y at the centre"):
a row of listed labels that says any keeps the listed order (its roles are no reader's; an unordered row had dropped them)."""

OTHER_RE = re.compile(r"\bthe\s+other\s+(?:[a-z]+\s+)?(?:blocks?|cubes?|ones?|bricks?|boxes|box)\b")
""""The other block": it picks a cube by contrast with one the instruction set apart before it
("put one red block on the patch and the other one next to it", :data:`OTHER_SET_RE`); without
that it means a cube the speaker sees, which a task cannot know."""

OTHER_PLACE_RE = re.compile(r"\bthe\s+other\s+(?:[a-z]+\s+)?(?P<noun>patch|pad|mat|side|corner|end|spot|place|location|area|half)(?:e?s)?\b")
""""The other patch", "the other side": a place picked by contrast; it needs the same kind of
place said before it ("put red on the green patch and blue on the other patch"), otherwise it
contrasts with one the speaker sees (where a cube stands now)."""

ENUMERATED_PART_RE = re.compile(r"(?i)(?:^|\s*[,;]\s*(?:and\s+)?|\s+and\s+)(?:the\s+(?:first|second|third|fourth)(?:\s+one)?|one|the\s+other"
                                r"(?:\s+one)?|another)\s*(?:(?:is|of|has|:|-)\s+)?(?=\S)")
"""A word that counts off one structure of several a heading announces ("Two towers, each three tall: the first ..., the
second ..."; "one ..., the other ..."): split on by :func:`rpg.schema.readers._enumerated_parts`."""

ENUMERATED_PART_PLACE_RE = re.compile(r"(?i)(?:at|on|in)\s+the\s+(?:front|back|left|right|center|centre|middle)(?:\s+side)?"
                                      r"(?:\s+of\s+the\s+table)?")
"""One structure counted off after a heading by its place alone ("two gray towers, each three cubes tall: one on the left
side of the table and one in the centre"): the heading's cubes there (:func:`rpg.schema.readers._enumerated_parts`)."""

_PART_CUBE = rf"(?:{COLOR_RE}|grey|[a-z0-9])"
ENUMERATED_PART_SPEC_RE = re.compile(
    rf"(?:(?:\d+|{COUNT_WORD_RE})\s+)?(?:(?:all|only)\s+)?{_PART_CUBE}(?:(?:\s*[,\-]\s*|\s+and\s+|\s+then\s+|\s+)(?:then\s+)?{_PART_CUBE})*"
    r"(?:\s+(?:cubes|blocks|ones))?(?:\s+(?:from\s+)?(?:(?:the\s+)?bottom\s+(?:to\s+(?:the\s+)?top|up)|(?:the\s+)?top\s+(?:to\s+(?:the\s+)?bottom|down)"
    r"|left\s+to\s+right|right\s+to\s+left))?(?:\s+(?:at|on|in)\s+the\s+(?:front|back|left|right|center|centre|middle)"
    r"(?:\s+(?:of\s+the\s+table|side))?)?", re.IGNORECASE)
"""What one structure counted off after a heading may say (:data:`ENUMERATED_PART_RE`): its cubes (a count, colours or
labels), an order said without a comma, and a place of the table; anything else ("..., the green one taller", "...,
touching", "..., left to right" after a comma, which may be every structure's) leaves the text to the other readers."""

REST_ANY_ORDER_RE = re.compile(r"(?i)\bthe\s+rest(?:\s+of\s+(?:them|the\s+(?:cubes|blocks)))?\s+(?:(?:can|may|could)\s+)?"
                               r"(?:(?:go|be|are|stand|sit)\s+)?(?:in\s+(?:any|whatever|whichever|either)\s+order\b"
                               r"|(?:however|wherever|as)\s+you\s+(?:like|want|wish|please|prefer)\b)"
                               r"|\b(?:the\s+)?order\s+of\s+the\s+(?:others|rest|other\s+(?:two|three|four|five|[2-5]|ones|cubes|blocks)"
                               r"|remaining\s+(?:two|three|four|five|[2-5]|ones|cubes|blocks))(?:\s+(?:cubes|blocks|ones))?\s+"
                               r"(?:is\s+(?:free|open|unimportant|irrelevant|up\s+to\s+you|your\s+(?:choice|call)|not\s+important)"
                               r"|(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter|is\s*n[o']?t\s+important)\b")
"""The cubes given no place, left in any order ("with the black cube on top; the rest in whatever order", "the rest however
you like", "The order of the other two is free."): written "the others in any order" (it had been refused as a reference to
cubes nobody named, or over "free")."""

STRUCTURE_ADJECTIVES = r"little|small|tiny|short|tall|big|large|new|finished|completed|neat|lone|single"
"""Words that may stand between "the"/"that" and a structure one sees ("that little tower", "the small stack")."""

POINTED_STRUCTURE_RE = re.compile(r"\b(?:this|that|the)\s+(?:" + STRUCTURE_ADJECTIVES + r")?\s*"
                                  r"(?P<n>tower|stack|pile|structure|pyramid|wall|row|line|column|circle|ring|grid)\b")
"""A structure an edit points at ("move that little tower", "the small stack"): the task's own, written "the tower" by
:func:`rpg.steer.edits.normalize_edit` (the words had been read as a fresh task, a tower of two made-up cubes)."""

DEMONSTRATIVE_STRUCTURE_RE = re.compile(r"(?i)\b(?P<p>on|onto|upon|to|into|beside|behind|near|of|from|off|put|place|move|set|slide|push|shift"
                                        r"|bring|carry|relocate|transfer|position)\s+(?:this|that)\s+(?:(?:" + STRUCTURE_ADJECTIVES + r")\s+)?"
                                        r"(?P<n>tower|stack|pile|structure|pyramid|wall|row|line|column)\b(?!\s+of\b)")
"""A structure named by a demonstrative after a preposition ("put a cyan cube on top of that tower"): the definite one,
written "the tower" (it had missed :data:`DEFINITE_STRUCTURE_RE`'s check and made a tower of two made-up cubes, silently)."""

DEMONSTRATIVE_CUBE_RE = re.compile(r"\b(?:on|onto|upon|atop|top\s+of|next\s+to|beside|behind|in\s+front\s+of|left\s+of|right\s+of|under"
                                   r"|underneath|below|beneath|above|over|near|by|of|to|from|off"
                                   r")\s+(?P<w>(?:this|that)\s+(?:cube|block|one))\b(?!\s*(?:'s|,?\s+(?:which|that|the)\b))")
"""A cube named by a demonstrative alone ("put green on top of that cube"): the scene's cube, or one said before without
saying which (a hostile helper's probe: a red cube had been made up for it, silently); refused as a reference."""

DEFINITE_STRUCTURE_RE = re.compile(
    r"\b(?:on|onto|upon|to|into|next\s+to|beside|behind|in\s+front\s+of|near|left\s+of|right\s+of|top\s+of|from|off|of"
    r"|put|place|move|set|slide|push|shift|bring|carry|relocate|transfer|position)"
    r"\s+the\s+(?:(?:existing|current|whole|entire|" + STRUCTURE_ADJECTIVES + r")\s+)?"
    r"(?P<noun>tower|stack|pile|structure|pyramid|wall|row|line|column|circle|ring|grid)\b(?!\s+of\b)")
"""A structure an instruction places something in relation to ("put the blue block on top of
the stack") or moves ("put the tower centrally"): it must have been described before it
(:data:`STRUCTURE_INTRO_RE`); otherwise it is one the speaker sees, which a task cannot know."""

STRUCTURE_INTRO_RE = re.compile(
    r"\b(?:a|an|one|\d+|the)\s+(?:[a-z0-9\-]+\s+){0,3}(?:towers?|stacks?|piles?|structures?|pyramids?|walls?|rows?|lines?"
    r"|columns?|circles?|rings?|grids?)\s+(?:of|with|from|using|made)\b|\b(?:a|an|one|\d+)\s+(?:[a-z0-9\-]+\s+){0,3}"
    r"(?:towers?|stacks?|piles?|structures?|pyramids?|walls?|rows?|lines?|columns?|circles?|rings?|grids?)\b"
    r"|\b(?:stack|build|make|pile|form|create|construct|arrange|line\s+up)\b"
    r"|\b(?:on|onto|atop|on\s+top\s+of)\s+(?:the|a|an)\s+(?:[a-z]+\s+)?(?:block|cube)\b"
    rf"|\b(?:{COLOR_RE})\s+(?:on|onto|atop|on\s+top\s+of)\s+(?:the\s+)?(?:{COLOR_RE})\b")
"""What describes a structure before "the stack" refers to it (:data:`DEFINITE_STRUCTURE_RE`):
one introduced ("a tower of three blocks", "build ...") or a cube put on another ("black on white")."""

PLACE_PICKED_RE = re.compile(
    r"\bthe\s+(?:top|bottom|topmost|uppermost|highest|lowest|bottommost|middle|center|centre|left|right|front|back"
    r"|closest|nearest|farthest|furthest|near|far)\s+(?:blocks?|cubes?|ones?|boxes|box)\b"
    r"(?!\s+(?:stacks?|towers?|piles?|lines?|rows?|columns?)\b)"  # "the highest block stack": a structure
    r"|\b(?:blocks?|cubes?|ones?)\s+(?:that\s+is\s+|which\s+is\s+|that's\s+)?(?:closest|nearest|farthest|furthest)\b")  # "the cube nearest the robot"
""""The top block", "the left one", "the nearest cube": a cube picked by its place.  It must be a
place in a structure described before it (:data:`PLACED_PART_INTRO_RE`: "build a tower of three
and make the top block red"); otherwise it is a place in the scene the speaker sees, which a task
cannot know.  ("rightmost" reads as "right" first: :data:`SYNONYMS`.)"""

PLACED_PART_INTRO_RE = re.compile(r"\b(?:towers?|stacks?|piles?|lines?|rows?|columns?|pyramids?|walls?|structures?|grids?"
                                  r"|circles?|rings?)\b")
"""What describes a structure whose cubes :data:`PLACE_PICKED_RE` can pick by place."""

OTHER_SET_RE = re.compile(r"\b(?:one|two|both|each|either)\b")
"""What sets a cube apart before "the other" (:data:`OTHER_RE`)."""

EPISODE_END_RE = re.compile(r"\s*,?\s*\b(?:at|by)\s+the\s+(?:very\s+)?end\s+of\s+(?:the|this|each|every|an?)\s+(?:episode|task|trial|run"
                            r"|rollout|evaluation|eval)\b|\s*,?\s*\b(?:when|once)\s+the\s+(?:episode|task|trial|run|rollout)\s+(?:ends|is\s+over)\b"
                            r"|\s*,?\s*\bat\s+(?:episode|task|trial)\s+end\b")
"""When the goal is checked, said ("The gray cube should be far from the black cube at the end of
the episode."): a goal is always checked at the episode's end, so the words add nothing (dropped)."""

TAKE_DOWN_RE = re.compile(r"(?i)\b(?:take|tear|pull|knock|bring)\s+down\s+(?=(?:the|this|that)\s+(?:(?:\d+|two|three|four)[\s-]+(?:block|cube)\s+)?"
                          r"(?:tower|stack)\b)|\bbreak\s+up\s+(?=(?:the|this|that)\s+(?:tower|stack)\b)")
"""Verbs that undo a tower said another way ("Take down the stack of blue on yellow so both end up on the table"): read as
"unstack" (the tower had been built instead)."""

TAKE_DOWN_AFTER_RE = re.compile(rf"(?i)\b(?:take|tear|pull|knock|bring)\s+(the\s+(?:(?:\d+|two|three|four)[\s-]+(?:block|cube)\s+)?(?:tower|stack)"
                                rf"(?:\s+of\s+(?:{COLOR_RE})(?:\s+on(?:\s+top\s+of)?\s+(?:{COLOR_RE}))+)?)\s+down\b")
"""The same with the particle after the tower ("Take the stack of blue on yellow down so ..."): "unstack <the tower>"."""


def taken_down_as_unstack(text: str) -> str:
    """``text`` with a tower's undoing said as taking it down (:data:`TAKE_DOWN_RE`, :data:`TAKE_DOWN_AFTER_RE`) said as
    "unstack" ("Take the stack of blue on yellow down so ..." -> "unstack the stack of blue on yellow so ...")."""
    return TAKE_DOWN_AFTER_RE.sub(r"unstack \1", TAKE_DOWN_RE.sub("unstack ", text))


FROM_START_STACK_RE = re.compile(
    r"(?i)^(?=\s*(?:there(?:'s|\s+is)|currently|right\s+now)\b[^.;!?]*\b(?:stack|tower|on|atop)\b[^.;!?]*[.;])"
    r"(?P<before>[^.;!?]*[.;][^.!?]*?\b(?:cube|block|it))\s+from\s+(?:the|that|this)\s+(?:stack|tower)\b"
    r"(?=\s+(?:on|onto|to|into|in|next|beside|behind)\b)")
"""A cube moved "from the stack" after a first sentence that says the stack there now ("There is a stack of blue on red.
Move the blue cube from the stack onto the yellow patch."): that start's stack, which the words before said; the source
dropped by :func:`start_stack_source` (it had been refused as a cube picked by where it stands; said with no start before
it, it stays refused)."""


TABLE_NO_ARTICLE_RE = re.compile(r"(?i)\b(on|onto|to|off|from|across)\s+table\b")
"""A terse "green on table", "put it to table": the table (an article dropped; the start and goal readers look for "the
table")."""

NUMBERED_START_GOAL_RE = re.compile(r"(?i)(?:^|(?<=[.;]\s))\s*\d\s*[.)]\s+(?=(?:start|goal|initial(?:ly)?|final|end|target)\b)")
"""A start and a goal numbered as steps ("1. Start: ... 2. Goal: ..."): the numbers dropped, the labels read."""


def start_and_goal_said_tersely(text: str) -> str:
    """``text`` with the table's article said (:data:`TABLE_NO_ARTICLE_RE`) and a numbered start and goal unnumbered
    (:data:`NUMBERED_START_GOAL_RE`)."""
    return NUMBERED_START_GOAL_RE.sub("", TABLE_NO_ARTICLE_RE.sub(r"\1 the table", text)).strip()


def start_stack_source(text: str) -> str:
    """``text`` without "from the stack" where it is the start said in its first sentence (:data:`FROM_START_STACK_RE`):
    only where that sentence says a stack of two named cubes (no patch) and names the cube moved ("it" is its top)."""
    def dropped(m: re.Match) -> str:
        first = re.split(r"[.;]", m.group("before"), maxsplit=1)[0].lower()
        said = re.findall(rf"\b(?:{COLOR_RE})\b", first)
        moved = re.search(rf"\b({COLOR_RE})\s+(?:cube|block)$|\bit$", m.group("before").lower())
        stack = re.search(r"\b(?:stack|tower|on\s+top\s+of|atop|on)\b", first) and not re.search(r"\b(?:patch|table)", first)
        if len(said) != 2 or len(set(said)) != 2 or not stack or not moved or (moved.group(1) and moved.group(1) not in said):
            return m.group(0)
        return m.group("before")
    return FROM_START_STACK_RE.sub(dropped, text, count=1)


NEEDS_MORE_RE = re.compile(r"(?i)(?:^|(?<=[.!?;]\s))(?:it\s+|this\s+|the\s+(?:tower|stack|row|line|pyramid|wall)\s+)?(?:needs|must\s+have"
                           r"|should\s+have|requires|wants|is\s+missing|lacks)\s+(?:a|an|some|more|another|its|one)\s+[a-z]+(?:\s+[a-z]+)?\s*[.!]?(?=\s|$)")
"""A sentence that says the task needs something more ("Needs a roof.", "Must have a hat.", "The tower needs a
foundation."): a cube or a structure nobody named, which the builtin parser does not read (the sentence had been dropped
as idle: a roof is another cube on top)."""


PYRAMID_ROW_RE = re.compile(r"\b(bottom|middle|top|lower|upper|base|second|third|first)\s+rows?\b")
"""A pyramid's layer called a row ("bottom row orange, orange, orange; middle row pink, pink; top row cyan"): its layer."""


SCENE_NOW_OPENING_RE = re.compile(r"(?i)^\s*(?:currently|right\s+now|at\s+the\s+moment|at\s+present)\s*,?\s+")
"""The opening of a text that says the scene now ("Currently the pink cube is on the orange cube. Add ..."): a start
where the initial-scene reader reads one there (:func:`rpg.schema.readers.initial.split`), refused elsewhere."""


SWAP_HEADING_RE = re.compile(
    rf"(?i)^\s*(?:swap|switch|exchange)\s+(?:places|positions|spots)\s*:\s*(?=(?:the\s+)?(?P<a>{COLOR_RE})\s+(?:cube|block)\s+"
    rf"(?:goes|moves|must\s+go|should\s+go)\s+(?:on|onto|to)\s+the\s+(?P<b>{COLOR_RE})\s+patch\s*,?\s+and\s+(?:the\s+)?(?P=b)\s+(?:cube|block)\s+"
    rf"(?:goes|moves|must\s+go|should\s+go)\s+(?:on|onto|to)\s+the\s+(?P=a)\s+patch\s*[.!]?\s*$)")
"""A heading "Swap places:" over a text that says each cube's end place ("Swap places: the yellow cube goes on the cyan
patch and the cyan cube goes on the yellow patch"): the swap is said by those places, so the heading is dropped (a swap
said alone refers to where the cubes stand now, refused)."""


FRAMING_RE = re.compile(
    r"^(?:(?:ok(?:ay)?|so|alright|right)\s*,?\s+)*(?:(?:so\s+)?here(?:'s|\s+is)\s+what\s+(?:i|we)\s+(?:want|need|would\s+like)"
    r"(?:\s+you\s+to\s+do)?\s*[.:,]\s*)?"
    r"(?:(?:(?:for\s+)?(?:this|the|your|our|my)\s+|for\s+)?(?:task|goal(?:\s+(?:state|configuration|condition)s?)?|instruction"
    r"|objective|requirements?|target\s+(?:state|configuration)|(?:final|end|desired|goal)\s+(?:state|scene|configuration|layout)"
    r"|spec(?:ification)?|(?:two|three|2|3)\s+things|(?:our\s+|the\s+|your\s+)?(?:first\s+|next\s+|last\s+)?exercise(?:\s+today)?)"
    r"\s*(?::|-|,|\bis\s*:)\s*"
    r"|for\s+(?:this|the)\s+task,?\s+)?"
    r"(?:(?:a|an|the)\s+(?:simple\s+|basic\s+|easy\s+|collaborative\s+|bimanual\s+|dual[- ]arm\s+)?(?:task|challenge|problem)"
    r"\s+(?:where|in\s+which)\s+)?"
    r"(?:the\s+(?:robot(?:ic)?\s+)?(?:robot|agent|arm|gripper|manipulator)\s+(?:has\s+to|needs\s+to|must|should|is\s+to|shall"
    r"|is\s+(?:expected|supposed|required|asked)\s+to|will)\s+|(?:the|your|its)\s+(?:objective|goal|task|job|aim)\s+is\s+to\s+"
    r"|(?:two|both|the|a)\s+(?:robot(?:ic)?\s+)?(?:arms?|robots)\s+(?:need|needs|must|should|have|has|are)\s+(?:to\s+)?"
    r"(?:(?:work\s+together|cooperate|collaborate)\s+(?:to\s+)?)?)?")
"""Framing before a task's verb that says nothing of the goal ("a simple task where the
objective is to push a cube onto the target", "the robot has to stack two cubes", "Task: ...",
"for this task the robot should ...", "Final state: ...", "Spec: ...", "Two things: ..."): dropped."""

ARTICLE_DROPPED_AFTER: tuple[str, ...] = (
    "put", "place", "move", "set", "stack", "push", "slide", "bring", "of", "on", "onto", "to", "at", "near", "beside",
    "behind", "from", "and")
"""Words after which a cube named without its article ("put cyan cube at back right corner of
table", terse or non-native writing) is read with "the" (:func:`rpg.schema.reading.normalize`)."""

CLOSING_RE = re.compile(r"(?:[,.;:]\s*|\s+)(?:and\s+)?that(?:'s|\s+is|\s+will\s+be)\s+(?:everything|all|it)(?:\s+for\s+now)?\s*[.!]?\s*$"
                        r"|(?:[,.;:]\s*|\s+)(?:and\s+)?that(?:'s|\s+is)\s+(?:the\s+)?(?:whole\s+|entire\s+)?(?:episode|task|goal(?:\s+state)?"
                        r"|job|eval(?:uation)?|exercise)\s*[.!]?\s*$"
                        r"|(?:[,.;:]\s*|\s+)(?:please\s+)?make\s+(?:this|that|these|it|them|all\s+of\s+this)\s+(?:true|happen|so|hold)"
                        r"(?:\s+please)?\s*[.!]?\s*$")
"""A closing that says nothing of the goal ("..., and that's everything.", "... Make this true.",
"That's the whole episode."): dropped."""

EVAL_LOGISTICS_RE = re.compile(
    r"(?:[,;]\s*|\s+)(?:and\s+)?(?:then\s+)?(?:run|running|with|over|across|for|repeat(?:ed)?\s+(?:for|over)?)\s*\d+\s+(?:random\s+)?"
    r"(?:seeds?|trials?|episodes?|rollouts?|runs?|repetitions?|repeats?|times)\b(?:\s+each)?\s*(?=[.!;)]|$)"
    r"|(?:[,;]\s*|\s+)(?:and\s+)?(?:log|record|save|report|upload|plot)\s+(?:the\s+)?(?:results?|outcome|metrics?|success\s+rates?"
    r"|videos?|rollouts?)(?:\s+(?:as\s+usual|to\s+\w+|afterwards?))?\s*(?=[.!;]|$)"
    r"|^(?:(?:hey|hi|ok(?:ay)?)\s*,?\s*)?(?:can|could|would)\s+(?:you|someone|somebody)\s+(?:please\s+)?(?:queue|schedule|launch|set\s+up"
    r"|kick\s+off|start|run|add)\s+(?:up\s+)?(?:an?\s+|the\s+)?(?:new\s+)?(?:eval(?:uation)?|run|job|episode|experiment|task|test)"
    r"\s+(?:where|in\s+which|with|that\s+has|for)\s+")
"""How an evaluation is run or recorded, said around the task ("..., run 20 seeds", "... and log the
result as usual", "can you queue an eval where the robot stacks ..."): no part of the goal (dropped;
the question's words before the task are a request, not a question about the scene)."""

EFFECTOR_RE = re.compile(
    r"(?:,\s*)?\b(?:(?:by\s+)?using|use|with|by|via)\s+(?P<what>(?:(?:the|your|its|a|an|one|both|each|another|my|our)\s+)?"
    r"(?:[a-z0-9][a-z0-9\-]*\s+){0,3}?(?:robot(?:'s|ic)?\s+)?"
    r"(?:arms?|grippers?|hands?|end[- ]effectors?|claws?|fingers?|robots?|manipulators?))\b(?:\s+to\b)?(?:\s*,)?")
"""Which effector or robot moves the cubes ("use the left arm to", "with the gripper", "using
both hands", "with the Franka arm", "using the UR5 robot"): a task's goal says where cubes end
up, whichever arm, hand or robot takes them there, so the words are dropped (and listed as
dropped: :func:`rpg.schema.reading.normalize_words`)."""

POSTURE_RE = re.compile(r"\b(?:sitting|resting|lying|laying|sits|rests|lies|sit|rest|lie|located|positioned|seated|perched"
                        r"|lands|landed|settles|settled|balances|balanced|balancing|touch(?:es|ed)?\s+down|comes\s+down"
                        r"|came\s+down|comes\s+to\s+rest|came\s+to\s+rest)\s+"
                        r"(?=(?:on|onto|upon|atop|in|inside|within|at|next|beside|behind|under|below|beneath|underneath|above|"
                        r"between|near|by|to|directly|right|just|exactly)\b)")
"""A posture verb before a place ("the green cube sitting on top of the yellow cube", "so it
is resting on the patch"), or one of coming to rest there ("the red cube touches down on top of
the blue cube", "lands on", "settles on", "balances on"): every cube rests on a face, so only
the place says anything; the verb is dropped (:func:`rpg.schema.reading.normalize`)."""

PILE_ON_RE = re.compile(r"\b(?:pile|heap)(?:\s+up)?\s+(?=[^.;!?]*?\b(?:on|onto|upon|atop)\s+(?:top\s+of\s+)?"
                        r"(?:each\s+other|one\s+another|(?:the|a|an)\s+(?:[a-z]+\s+)?(?:block|cube|one)\b))")
""""pile"/"heap" as a verb that puts cubes on a cube ("pile the orange cube onto the purple
cube", "pile the red, green and blue blocks on top of each other"): read as "stack" (it read
as separate piles by colour); "pile the red blocks on the green patch" stays a pile."""

END_SIDE_RE = re.compile(r"\b(?P<verb>starting|beginning)\s+with\s+(?:the\s+|a\s+|an\s+)?(?P<c>[a-z]+)"
                         r"(?:\s+(?:block|cube|one))?\s+(?:on|at)\s+the\s+(?:far\s+)?(?P<side>left|right|front|back)"
                         r"(?:\s+(?:end|side))?\b")
"""A line's first cube given by its side of the table ("starting with red on the left",
"beginning with blue at the right end"): when it is the first colour the instruction lists,
the side says which way the sequence runs (:data:`END_SIDE_DIRECTION`)."""

END_SIDE_DIRECTION: dict[str, str] = {"left": "left to right", "right": "right to left",
                                      "front": "front to back", "back": "back to front"}
"""The side a sequence starts at -> the direction words it runs in (:data:`END_SIDE_RE`)."""

START_SIDE_RE = re.compile(r"\b(?:starting|beginning|going|counting|reading)\s+(?:from|at)\s+the\s+(?:far\s+|very\s+)?"
                           r"(?P<side>left|right|front|back)(?:\s+end)?\b(?!\s+(?:side|edge|corner|half|part|of)\b)(?!\s*,?\s*with\b)")
"""A listed sequence's direction given by the side it starts from ("red, green and blue,
starting from the left"): read as the direction words (:data:`END_SIDE_DIRECTION`). Not a place
("starting at the left edge of the table")."""

TOTAL_RE = re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:(blocks?|cubes?)\s+)?(?:in\s+)?total\b"
                      r"|\bin\s+total\s*,?\s+(?=\d|one|two|three|four|five|six|seven|eight|nine|ten)")
"""A count said as a total ("six in total", "in total 4 blocks", "three blocks total"): read as "N blocks"."""

NO_GOAL_RE = re.compile(r"\b(?:pick(?:\s+(?:it|them))?\s+up|pick|grab|grasp|take|lift|raise|hold|get|find|locate|point\s+(?:at|to)"
                        r"|look\s+at|reach(?:\s+for)?)\b"
                        r"|\b(?:rotate|turn|flip|push|pull|touch|tap|poke|nudge|move|slide|shift|place|put|set|drop)\s+"
                        r"(?:the\s+|a\s+|an\s+)?(?:[a-z0-9']+\s+){0,2}?(?:block|cube|box|one)s?(?:\s+(?:over|around|down))?\s*[.!]?$")
"""Actions that move no cube to a place ("pick up the orange block", "grab the red cube"), and
a verb whose sentence ends at its cube ("rotate the red block", "push the blue block."): an
instruction that says one and no task is refused as saying no end state."""

PLACEMENT_VERBS: dict[str, str] = {
    "put": "place", "place": "place", "set": "place", "move": "place", "push": "place", "slide": "place",
    "bring": "place", "shift": "place", "transfer": "place", "relocate": "place", "sweep": "place",
    "position": "place", "drop": "place", "lay": "place", "add": "place", "pack": "place",
    "build": "build", "make": "build", "create": "build", "construct": "build", "assemble": "build",
    "form": "build", "erect": "build", "stack": "stack", "pile": "stack", "pull": "place", "drag": "place",
    "pop": "place", "plonk": "place", "plop": "place", "stick": "place", "gather": "place", "collect": "place",
    "chuck": "place", "bung": "place", "realise": "build", "realize": "build",
    "hoist": "place", "heave": "place", "ease": "place", "nudge": "place", "scoot": "place", "shove": "place", "haul": "place",
    "carry": "place", "lug": "place", "deposit": "place", "park": "place", "plant": "place", "station": "place",
    "seat": "place", "perch": "place", "deliver": "place", "dump": "place", "tuck": "place", "send": "place",
    # a cube's own travel to where it ends ("the black cube glides to the left of the white cube", "the red cube travels
    # onto the green patch"): a voice that makes the cubes dancers or travellers (a spin, a roll or a toss stays refused)
    "glide": "place", "travel": "place", "drift": "place", "wander": "place", "stroll": "place", "waltz": "place",
    "sashay": "place", "tiptoe": "place", "scurry": "place", "hop": "place", "shimmy": "place",
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


@lru_cache(maxsize=4096)
def parts_of_speech(word: str) -> frozenset[str]:
    """The parts of speech lemminflect knows ``word`` as (``NOUN``, ``VERB``, ``ADJ``...)."""
    from lemminflect import getAllLemmas

    return frozenset(getAllLemmas(word))


def said(m: re.Match) -> str:
    """The words a match of an :data:`INEXPRESSIBLE` pattern names: its group ``w`` where that
    matched (a pattern that looks at the whole text to decide), else all it matched."""
    return ((m.re.groupindex.get("w") and m.group("w")) or m.group(0)).strip()


def is_dictionary_word(word: str) -> bool:
    """Whether ``word`` is an English word lemminflect knows (so not to be typo-corrected)."""
    return bool(lemmas(word))




VOCAB = set("""
more additional extra a an the this that these those it its them they their each every all some any both of to in into on onto at
by with and or but then first second third next after before finally also so such as from for is are be
being been was were will should must can could would please you your me i we us our make build create
form put place set move stack stacks stacked stacking tower towers arrange arranged arranging arrangement align
aligned line lines row rows column columns sort sorted sorting order ordered ordering spell spelling spells
word words using use used block blocks cube cubes cubic box boxes piece pieces object objects item items
table surface top bottom base left right side front behind back middle center centre near next beside
between under below beneath underneath above over atop adjacent alongside other another simple small
big large tall single straight horizontal vertical circle circular ring round shape square squares grid
rectangle rectangular array pyramid pyramids layer layers level levels cube-shaped pile piles group groups
bunch bunches cluster clusters heap heaps separate separated apart together same different matching match
matches color colors colour colours colored coloured gradient rainbow hue letter letters alphabet alphabetical
alphabetically number numbers numeric numerical numerically digit digits increasing decreasing ascending
descending reverse reversed strictly order equation math maths correct single-digit semantic label labels
labelled labeled face faces facing up upward upwards camera robot visible rotate rotated turn flip show shows
showing so read reads reading goal target patch patches long designated specific respective temporal exact
exactly sequence sequential sequentially one outlier mixed assorted various random two three four five six
seven eight nine ten many several wide high tall height x can build starts start starting initially
begin begins beginning initial there where which who has have how shape shaped form forms do does
shown kind type types by-color own its corresponding respectively per contain containing made consisting
plus minus equals times operator operators symbol symbols mixed upright hold holds just only now want like
out peak apex tip smallest largest lowest highest biggest least greatest tallest longest widest marked labelled labeled showing
alternating alternate alternately alternates going goes go way up down upward downward stand standing
wall walls wide deep long split divide pillar column close far triangle triangular formation write writes
writing addition subtraction multiplication increase increases decrease decreases tier tiers story storey stories storeys instead actually
rather backwards backward pick grab take lift get lay drop small little tiny mini huge one unstack unstacked off remove
through corner corners sum area areas zone zones field fields region regions spot spots location pad pads mat mats tile tiles
marker markers away distant opposite rear edge edges end ends half part workspace robot
""".split())
"""Words the builtin front end understands (besides colours, numbers and labels)."""


COMPASS_CORNER_RE = re.compile(r"\b(?:the\s+)?(nw|ne|sw|se|north[- ]?west|north[- ]?east|south[- ]?west|south[- ]?east)\s+corner\b")


COMPASS_REL_RE = re.compile(r"\b(?:to\s+the\s+|on\s+the\s+)?(north|south|east|west)(?:\s+side)?\s+of\b")


COMPASS_SIDE_RE = re.compile(r"\b(?:the\s+)?(north|south|east|west)(?:ern)?\s+(side|edge|half|part|end)\b")


TOWER_NOUNS = "(?:" + "|".join((*STRUCTURE_KINDS["tower"].words, *STRUCTURE_KINDS["tower"].described_by)) + ")"
"""Nouns of a described tower ("a 4-high white stack", "a tower 3 blocks high"): the tower kind's
words (:mod:`rpg.schema.structures`)."""


HEIGHT_WORDS = r"(?:(?:blocks?|cubes?|stor(?:y|ey|ies|eys)|levels?|tiers?|layers?)(?:\s+(?:high|tall))?|high|tall)"

HEIGHT_SAID_RE = re.compile(r"(?<![\w.])(?P<n>\d+)(?:\s+|-)(?:(?:(?:blocks?|cubes?|bricks?|stor(?:y|ey|ies|eys)|levels?|tiers?|layers?"
                            r"|floors?)(?:\s+|-))?(?:high|tall)\b|(?:stor(?:y|ey|ies|eys)|levels?|tiers?|layers?|floors?)\b(?!\s+(?:of|high|tall)\b))")
"""A height said in cubes ("3 high", "4 cubes tall", "2-storey", "4 layers") that no rewrite turned into a structure's count:
some tower of the goal must have that many cubes, or a layered structure that many layers (mention accounting,
:mod:`rpg.schema.accounting`; "a tower of gray cubes, 3 high" had been a tower of two)."""

EXTENT_SAID_RE = re.compile(r"(?<![\w.])(?P<n>\d+)(?:\s+|-)(?:(?:blocks?|cubes?|bricks?)(?:\s+|-))?(?:long|wide|deep|across)\b")
"""A length said in cubes ("3 long", "4 cubes wide") that no rewrite read: some group of the task must have that many
cubes (mention accounting; "a row of gray cubes, 3 long" had been a row of four, "a tower ..., 3 wide" a tower of two)."""

GRID_SIZE_SAID_RE = re.compile(r"(?<![\d.])(?P<r>\d+)x(?P<c>\d+)(?!\w|\.\d)")
"""A grid's size ("3x3", "2x4"): the task must have a group of rows x columns cubes (mention accounting; "circle x5 x2"
had been a circle of six)."""

START_SAID_RE = re.compile(r"\b(?:robot|scene|task|episode|table|cubes?|blocks?|it|they|tower|stack)\s+(?:starts?|begins?)\s+"
                           r"(?:with|on|as|from|off|stacked|out)\b|\binitially\b"
                           r"|\b(?:initial|starting|start)\s+(?:state|configuration|scene|setup|position)\b")
"""Words that describe how the cubes start ("the robot starts with red on blue", "initially", "initial state"): the
task must read a start (rho_0's structures), or the start had been read as part of the goal (mention accounting)."""

COUNT_TIMES_RE = re.compile(r"(?<![\w.])[x\u00d7]\s?(?P<n>\d+)\b(?!\s*[x\u00d7*]\s*\d)|(?<![\w.])(?P<n2>\d+)\s?[x\u00d7](?=\s+[a-z])")
"""A count written as a multiplier ("circle x5", "5x circle", "blue x3"): the task must have that many cubes of
something (mention accounting; "circle x5" had been a circle of six). Not a grid size ("2x3")."""


OBJECT_PREPOSITION_BEFORE = re.compile(r"\b(?:on|onto|atop|upon|over|above|under|below|beneath|underneath|of|to|behind|beside|near|from"
                              r"|between|by|at|in|into)\s+$")
"""A relation's word just before a cube mention: the mention is the relation's object (mention
accounting, :mod:`rpg.schema.accounting`)."""

PAIRWISE_RELATIONS: tuple[str, ...] = ("left_of", "right_of", "in_front_of", "behind", "next_to", "far_from")
"""Relations between two named cubes that the relational reader states with one predicate of
that name (:data:`rpg.domain.predicates.PREDICATES`)."""

GROUP_SUBJECT_RE = re.compile(
    r"(?:^|[,;]\s*|\band\s+)(?:(?:put|place|move|set|leave|have)\s+)?(?:the\s+)?(?:both|2|all|@?them)(?:\s+(?:both|2|all))?"
    r"(?:\s+of\s+@?them)?(?:\s+(?:cubes|blocks|together))?"
    r"(?:\s+(?:are|go|stand|sit|should\s+be|must\s+be|placed|put|end\s+up))?\s*$")
"""Words that make the cubes of the relation just said the subject of the next phrase ("X left of
Y, both in the back", "X next to Y, both of them on the white patch"); "both" is "2" once
numbers are normalized."""

EACH_OTHER_GAP_RE = re.compile(r"\s*(?:(?:on\s+top\s+of\s+)?each\s+other|one\s+another)\s*,?\s*(?:and\s+)?(?:(?:are|go|placed|put)\s+)?")
"""The words between "X and Y next to" and the next relation when that relation is the pair's too
("the blue cube and the red cube next to each other in front of the green cube")."""

LABEL_SEPARATOR_AFTER = re.compile(rf"\s*(?:-|\u2013|\u2014|:)\s*(?:the\s+)?(?:{COLOR_RE})\b")
"""What follows a role word used as a label ("below - black", "top: white"): a relation word
followed by it names a place in a list, not a relation to the next cube."""

REL_PATTERNS: list[tuple[str, str]] = [
    *((PREDICATES[name].phrases, name) for name in (*PAIRWISE_RELATIONS, "between")),
    (PREDICATES["on"].reverse_phrases, "under"),
    (PREDICATES["on"].phrases, "on"),
    (r"(?:inside|within|into|in|at|to)(?=\s+(?:the\s+|a\s+)?(?:[a-z]+\s+){0,2}patch)", "on"),  # "in the green goal area", "to a patch"
    (r"region_[a-z_]+", "region"),  # "@region_center": "in the middle of the table" (see mark_regions)
]
"""Relation words in the order the relational reader tries them (a longer phrase first: "on
the left side of" before "on"), -> the relation's name.  The words of each relation are
declared on its predicate class (``phrases``), so a new relation adds its class and its name
here."""


_PAIRWISE_WORDS = "(?:" + "|".join(PREDICATES[name].phrases for name in PAIRWISE_RELATIONS) + ")"


def _completed(head: str) -> str:
    """A relation's words with the preposition that takes its object ("to the left" -> "to the
    left of", "next" -> "next to"); words already complete are returned as they are."""
    for tail in ("", " of", " to"):
        if re.fullmatch(_PAIRWISE_WORDS, head + tail):
            return head + tail
    return head
REGION_ANTECEDENT_RE = re.compile(
    rf"\b(?P<c>{COLOR_RE})\s+(?:block|cube|box)\s+(?:(?:goes|is|sits)\s+)?(?P<place>(?:in|at|on|to|into)\s+the\s+(?:far\s+|very\s+)?(?:(?:front|back|rear)[\s-]+(?:left|right)\s+corner"
    r"|left|right|front|back|rear|center|centre|middle)(?:\s+(?:side|half|edge|end|part|area|region|zone))?(?:\s+of\s+the\s+(?:table|workspace))?)\s*,?\s+and\s+"
    rf"(?P<rest>(?:(?:put|place|set|move)\s+)?the\s+(?:{COLOR_RE})\s+(?:block|cube|one)\s+(?:(?:in\s+front\s+of|behind)\s+and\s+)?"
    rf"(?:(?!(?:{COLOR_RE}|grey|and|or|but|not|cubes?|blocks?|patch)\b)[a-z]+\s+){{0,5}}?)"
    r"(?P<pro>(?:to\s+)?its\s+(?P<side>left|right|front|back)(?:\s+side)?|it)\b(?!\s*(?:'s|is)\b)")
"""A cube placed in a region, then another cube related to "it" ("Put the red cube in the center and
the blue cube to its left", "... on the right side and the green one beside it"): the pronoun is the
one cube of the clause before (a region is no cube), so it is written as that cube."""

_COLOR_WORD = "(?:" + "|".join(COLORS) + ")"
END_ROLE_WORD_RE = re.compile(rf"\s*,?\s*(?:with|where|and)\s+(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|being\s+)?"
                              r"(?:the\s+)?(?P<w>lowest|bottommost|highest|topmost|uppermost)(?:\s+(?:one|cube|block))?\b")
"""A cube's end of a tower said by a superlative ("with red lowest", "where blue is highest"): read as
"with the red cube at the bottom" / "on top" (each had been read as one more cube of that colour)."""

INNER_POSITION_RE = re.compile(rf"\b(?:with|where|and)\s+(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|being\s+)?(?:the\s+)?"
                               r"(?P<w>(?:second|third|fourth|fifth|2nd|3rd|4th|5th)\s+(?:one\s+)?from\s+the\s+(?:top|bottom|left|right|front"
                               r"|back|end)|next[\s-]to[\s-]last|second[\s-]to[\s-]last|penultimate)\b")
"""A cube's place inside a structure said by its rank from an end ("with red second from the top"):
refused, naming it (it had been read as one more cube of that colour); a structure said role by
role ("the bottom one is green, the second from the bottom is yellow, ...") is read elsewhere."""

LONE_ORDINAL_ROLE_RE = re.compile(rf"\bthe\s+(?P<o>first|second|third|fourth|fifth|sixth)\s+(?:one\s+)?(?:is|should\s+be"
                                  rf"|must\s+be|will\s+be|=|:)\s*(?:the\s+)?(?:{COLOR_RE})\b")
"""A cube given a colour by its rank alone, the rest of the structure not said so ("stack three cubes; the third is red"):
from which end it counts is not said, and the rank had been dropped (the red cube anywhere in the tower); refused by
:func:`rpg.schema.reading.normalize_words` where :func:`rpg.schema.reading.ordinal_roles` did not read it as part of a
whole order."""

def _rest_of_tower(m: re.Match) -> bool:
    """Whether the cubes said below (or above) 'it' in ``m`` are counted and, with the end cube, make the whole tower: no
    tower size said, or one more than their count ("a 3-block tower, green on top, two orange under it")."""
    said = re.search(rf"\b(\d+|{COUNT_WORD_RE})\s+(?:(?:{COLOR_RE})\s+)?(?:(?:blocks?|cubes?|ones?)\s+)?$", m.group(1))
    if said is None:
        return False
    size = re.search(rf"\b(?:tower|stack)\s+of\s+(\d+|{COUNT_WORD_RE})\b|\b(\d+|{COUNT_WORD_RE})[\s-](?:blocks?|cubes?)[\s-](?:tall\s+)?"
                     r"(?:tower|stack)\b", m.string)
    count = int(NUMBER_WORDS.get(said.group(1), said.group(1)))
    return size is None or int(NUMBER_WORDS.get(size.group(1) or size.group(2), size.group(1) or size.group(2))) == count + 1


PLACE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "a line of five white cubes across the back of the table": along that side ('across' had been refused)
    (re.compile(r"\bacross\s+(?=the\s+(?:very\s+)?(?:back|front|rear|far|near)(?:\s+(?:edge|side))?(?:\s+of\s+the\s+(?:table|workspace)\b"
                r"|\s*(?:[.,;!]|$)))"),
     "along "),
    # "put the blue cube on the same coloured patch", "... on the patch that matches it", "... on its own patch": the
    # patch of that cube's colour (a red and a gray patch had been made up)
    (re.compile(rf"\b(the\s+({COLOR_RE})\s+(?:cube|block))\s+(on|onto|to|in|into)\s+(?:the\s+same[\s-]+colou?red|its\s+own"
                rf"(?:\s+colou?r(?:ed)?)?|the\s+matching)\s+(?:goal\s+|target\s+)?patch\b"
                rf"|\b(the\s+({COLOR_RE})\s+(?:cube|block))\s+(on|onto|to|in|into)\s+the\s+(?:goal\s+|target\s+)?patch\s+"
                r"(?:that|which)\s+matches\s+(?:it|its\s+colou?r)\b"),
     lambda m: f"{m.group(1) or m.group(4)} {m.group(3) or m.group(6)} the {m.group(2) or m.group(5)} patch"),
    # "The cube orange must stay on the patch purple", "yellow stays at the left of orange": where it is at the end
    (re.compile(r"\b(must|should|has\s+to|have\s+to|needs?\s+to|will)\s+(?:to\s+)?(?:stay|remain)\b"), r"\1 be"),
    (re.compile(r"\b(?:stays|remains)\s+(?=(?:on|onto|at|in|inside|next\s+to|beside|behind|under|to\s+the|near|far|between|in\s+front)\b)"),
     "is "),
    # "leave the pair in the back left corner", "keep all the red cubes in the front side", "keep it in the corner": put
    # them there
    (re.compile(r"\b(?:leave|keep)\s+(?=(?:(?:all\s+)?(?:the|both|all|these|those)\s+(?:[a-z]+\s+){0,3}?(?:cubes?|blocks?|pair|ones?|tower"
                r"|stack|row|line)|it|them)\s+(?:on|onto|at|in|inside|next\s+to|beside|behind|in\s+front\s+of|to\s+the|near|far|between"
                r"|under)\b)"), "put "),
    # "put one cube on the red patch and another on the blue patch": another cube (it had been the first cube again)
    (re.compile(rf"\b(one|a|an)\s+((?:(?:{COLOR_RE})\s+)?(?:cube|block))\b(.*?)\banother\s+"
                r"(?=(?:on|onto|in|into|at|next|beside|behind|under|in\s+front)\b)"),
     r"\1 \2\3another \2 "),
    # "... at the same time", "simultaneously": every part of a goal is checked at once, at the end of the episode
    (re.compile(r"\s*,?\s*\b(?:at\s+the\s+same\s+time|simultaneously|all\s+at\s+once)\b"), ""),
    # "red closest to the front" of a line: that end ("with red at the front"), which the line's roles read
    (re.compile(rf"(?:,\s*|\s+with\s+)(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|being\s+)?(?:closest|nearest)\s+to\s+"
                r"(?:the\s+)?(front|back|left|right)(?:\s+(?:edge|side|end))?\b"), r", with \1 at the \2"),
    # "leftmost should be the red cube, then blue, then yellow": the order from that side
    (re.compile(rf"(?:^|(?<=[.;:]\s))(?:the\s+)?(left|right|front|back)(?:most)?(?:\s+(?:one|cube|block))?(?:\s+(?:in|of)\s+the\s+(row|line))?"
                rf"\s+(?:should\s+be|must\s+be|is|will\s+be|goes|comes\s+first)\s*:?\s*(?=(?:the\s+)?(?:{COLOR_RE})\b[^.;]*\bthen\b)"
                r"(?![^.;]*\bof\s+the\s+(?:table|workspace)\b)"),  # (a place of the table's said with it: which cube's?)
     lambda m: (f"a {m.group(2)} " if m.group(2) else "") + {"left": "from left to right: ", "right": "from right to left: ", "front": "from front to back: ",
                "back": "from back to front: "}[m.group(1)]),
    # "in a row so the cyan cube is at the far left, ...": "so that" (its roles had been left unread)
    (re.compile(rf"\bso\s+(?=the\s+(?:{COLOR_RE})\s+(?:cube|block|one)\s+(?:is|ends\s+up|sits|stands)\b)"), "so that "),
    # "so that green is leftmost, then blue, then pink, with red rightmost" ("leftmost" read "left"): the order from that
    # side, its far end's cube the last (the places had been left unread)
    (re.compile(rf"\b(?:so\s+that|such\s+that)\s+(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+is\s+(?:the\s+)?"
                rf"(?:(?:at|on)\s+the\s+)?(?:far\s+)?(?P<a>left|right)(?:\s+(?:end|one))?\s*,\s*(?P<mid>then\s+(?:the\s+)?(?:{COLOR_RE})"
                rf"(?:\s*,\s*then\s+(?:the\s+)?(?:{COLOR_RE}))*)\s*,?\s+(?:and|with)\s+(?:the\s+)?(?P<z>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                r"\s+(?:is\s+)?(?:the\s+)?(?:(?:at|on)\s+the\s+)?(?:far\s+)?(?P<b>left|right)(?:\s+(?:end|one))?(?=\s*(?:[.;!]|$))"),
     lambda m: m.group(0) if m.group("a") == m.group("b") else
     f"from {m.group('a')} to {m.group('b')}: {m.group('c')}, " + re.sub(r"\bthe\s+", "", m.group("mid")) + f", then {m.group('z')}"),
    # "Row of three cubes, purple at the far left, then cyan, then yellow at the far right": the order from that end, its
    # far end's cube the last (the end said had been left unread, and the row refused)
    (re.compile(rf"(?<![\w-])(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:is|goes|sits)\s+)?(?:at|on)\s+the\s+(?:far\s+|very\s+)?"
                rf"(?P<a>left|right)(?:\s+end)?\s*,\s*(?:and\s+)?(?P<mid>then\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?"
                rf"(?:\s*,\s*(?:and\s+)?then\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?)*)"
                r"(?:\s+(?:(?:is|goes|sits)\s+)?(?:at|on)\s+the\s+(?:far\s+|very\s+)?(?P<b>left|right)(?:\s+end)?)?(?=\s*(?:[.;!]|$))"),
     lambda m: m.group(0) if m.group("a") == m.group("b") or not re.search(r"\b(?:rows?|lines?)\b", m.string)
     else f"from {m.group('a')} to {'right' if m.group('a') == 'left' else 'left'}: {m.group('c')}, "
     + re.sub(r"\b(?:the|cube|block|one)\b\s*", "", m.group("mid")).strip(" ,")),
    # "the rightmost is pink, next to it is orange, and the leftmost is gray" of a row of three: from that end
    (re.compile(rf"\b(?:the\s+)?(?P<a>left|right)(?:\s+(?:one|cube|block))?\s+(?:is|should\s+be|must\s+be)\s+(?P<c1>{COLOR_RE})\s*,\s*(?:and\s+)?"
                rf"next\s+to\s+it\s+(?:is|should\s+be|must\s+be|comes)\s+(?P<c2>{COLOR_RE})\s*,?\s+(?:and\s+)?(?:then\s+)?(?:the\s+)?"
                rf"(?P<b>left|right)(?:\s+(?:one|cube|block))?\s+(?:is|should\s+be|must\s+be)\s+(?P<c3>{COLOR_RE})(?=\s*(?:[.;!]|$))"),
     lambda m: m.group(0) if m.group("a") == m.group("b") or not re.search(r"\b(?:3|three)\s+(?:[a-z]+\s+)?(?:cubes|blocks)\b", m.string)
     else f"from {m.group('a')} to {m.group('b')}: {m.group('c1')}, then {m.group('c2')}, then {m.group('c3')}"),
    # "... yellow, then green, then pink on the far right": the last cube at the far end of the order said (said again)
    # ("from the right: the black cube first, then ..., then the cyan cube at the left end": the same, the start side said)
    (re.compile(rf"\b(from\s+(?:(left|right|front|back)\s+to\s+(left|right|front|back)|the\s+(?P<s>left|right|front|back)(?:\s+(?:side|end))?)"
                rf":\s+[^.;]*?\bthen\s+(?:the\s+)?(?:{COLOR_RE})"
                r"(?:\s+(?:cube|block|one))?)\s+(?:on|at)\s+the\s+(?:far\s+|very\s+)?(left|right|front|back)(?:\s+end)?\b(?=\s*(?:[.;!]|$))"),
     lambda m: m.group(1) if m.group(5) == (m.group(3) or END_SIDE_DIRECTION[m.group("s") or "left"].split()[-1]) else m.group(0)),
    # "the leftmost block in the row should be red, then blue, then the rightmost is green": the far end said as the last
    (re.compile(rf"(\bfrom\s+(?:left|right|front|back)\s+to\s+(?P<b>left|right|front|back):\s+[^.;:]*?),?\s+(?:and\s+)?then\s+"
                rf"the\s+(?P=b)(?:most)?(?:\s+(?:one|block|cube))?\s+(?:is|should\s+be|must\s+be)\s+(?P<c>{COLOR_RE})\b"),
     r"\1, then \g<c>"),
    # "stand left beside the gray cube" (German "links neben"): on that side of it ("right next to" is only "next to")
    (re.compile(rf"\b(left)\s+(?:beside|next\s+to|alongside)\s+(?=the\s+(?:{COLOR_RE})\b)"), r"to the \1 of "),
    # "well away from", "well behind": the degree adds nothing a qualitative relation could judge
    (re.compile(r"\bwell\s+(?=(?:away|apart|clear|behind|beyond|in\s+front|to\s+the\s+(?:left|right))\b)"), ""),
    # "the orange, black and pink cubes on the cyan, purple and blue patches respectively": pair by pair, as many cubes as
    # patches (three and more had been read as a stack; other counts stay, refused)
    (re.compile(rf"\bthe\s+(?P<l1>(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))+\s*,?\s*and\s+(?:the\s+)?(?:{COLOR_RE}))\s+(?P<n>block|cube)s\s+"
                rf"(?P<rel>on|onto|to|next\s+to)\s+the\s+(?P<l2>(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))*\s*,?\s*and\s+(?:the\s+)?(?:{COLOR_RE}))"
                r"\s+(?:goal\s+)?patch(?:es)?\s*,?\s+respectively\b"),
     lambda m: (lambda a, b: m.group(0) if len(a) != len(b) else ", ".join(
         f"the {x} {m.group('n')} {m.group('rel')} the {y} patch" for x, y in zip(a[:-1], b[:-1], strict=True))
         + f" and the {a[-1]} {m.group('n')} {m.group('rel')} the {b[-1]} patch")(
         re.findall(rf"\b(?:{COLOR_RE})\b", m.group("l1")), re.findall(rf"\b(?:{COLOR_RE})\b", m.group("l2")))),
    # "between the yellow and (the) pink patches": each colour names a patch (yellow had been read as a cube)
    (re.compile(rf"\b({COLOR_RE})\s+and\s+(?:the\s+)?({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patches|pads|mats|tiles)\b"),
     r"\1 patch and the \2 patch"),
    (re.compile(rf"\bbetween\s+the\s+({COLOR_RE})\s+and\s+(?:the\s+)?({COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|tile)\b"),
     r"between the \1 patch and the \2 patch"),  # "between the yellow and the pink patch": two patches
    # "the red and blue blocks on the yellow patch and the green patch respectively": pair by pair
    (re.compile(rf"\bthe\s+({COLOR_RE})\s+and\s+(?:the\s+)?({COLOR_RE})\s+(block|cube)s\s+(on|onto|to|next\s+to)\s+the\s+"
                rf"({COLOR_RE})\s+patch\s+and\s+the\s+({COLOR_RE})\s+patch\s*,?\s+respectively\b"),
     r"the \1 \3 \4 the \5 patch and the \2 \3 \4 the \6 patch"),
    # "keep the green cube far from the yellow cube", "leave the white cube on the red patch": where it ends up, said as a
    # state to hold
    (re.compile(rf"(?:^|(?<=[.;!,]\s)|(?<=\band\s)|(?<=\bjust\s)|(?<=\bsimply\s)|(?<=\bplease\s)|(?<=\bnow\s))(?:keep|leave)\s+(?=the\s+(?:{COLOR_RE})\s+(?:block|cube|brick)\b|(?:it|them)\s+"
                rf"(?:far|next|near|beside|behind|in\s+front|on|to\s+the|at|left|right)\b)"), "put "),
    # "the table's center", "the table's left side": the place on the table, as "the center of the table" says it
    (re.compile(r"\bthe\s+(table|workspace)(?:'s)?\s+(center|centre|middle)\b"), r"the \2 of the \1"),  # "the table centre"
    (re.compile(r"\bthe\s+(table|workspace)'s\s+(left|right|front|back|far)\s+(side|edge|half|end|corner)\b"), r"the \2 \3 of the \1"),
    # "at the midpoint between", "in the middle between", "centrally between": only between
    (re.compile(r"\b(?:(?:at|in)\s+the\s+(?:midpoint|middle|center|centre)|centrally|midway|cent(?:er|r)ed)\s+(?=between\b)"), ""),
    (re.compile(r"\bcentrally\b"), "at the center of the table"),  # "place red and green centrally"
    (re.compile(r"\binfront\b"), "in front"),  # "infront of the green patch"
    # "a red cube on each side of the black cube", "the two orange cubes on either side of it": the middle one between them
    (re.compile(rf"\b(put|place|set)\s+(?:a|an|1|one|(?:the\s+)?(?:2|two))\s+({COLOR_RE})\s+(block|cube)s?\s+on\s+(?:each|either|both|2|opposite)\s+"
                rf"sides?\s+of\s+the\s+({COLOR_RE})\s+(block|cube)\b"), r"\1 the \4 \5 between the 2 \2 \3s"),
    (re.compile(rf"\band\s+(?:(?:put|place|set)\s+)?(?:the\s+)?(?:2|two)\s+({COLOR_RE})\s+(block|cube)s\s+on\s+(?:each|either|both|2|opposite)\s+"
                r"sides?\s+of\s+it\b"),  # (in a row of five, "two white cubes on each side" are four: the row's own reading)
     lambda m: m.group(0) if re.search(r"\b(?:row|line)\s+of\s+(?:5|five)\b", m.string) else f"and put it between the 2 {m.group(1)} {m.group(2)}s"),
    # "three red cubes in the bottom row and three blue cubes in the row above": the second row
    (re.compile(r"(?<=\bbottom\s)(row|layer|level)\b(.*?)(?:\b(?:in|on)\s+the\s+(?:(?:next|following)\s+(?:row|layer|level)|(?:row|layer|level)\s+"
                r"(?:above|on\s+top)(?:\s+(?:it|that|them|of\s+(?:it|that|them)))?)|\bon\s+top\s+of\s+(?:them|it|those|that))\b"),
     r"\1\2in the second \1"),
    # "the blue patch should have the red cube on it": the cube on the patch
    (re.compile(rf"\bthe\s+({COLOR_RE})\s+patch\s+(?:should|must|needs\s+to|has\s+to|will)\s+have\s+the\s+({COLOR_RE})\s+(cube|block)\s+"
                r"on\s+(?:it|top(?:\s+of\s+it)?)\b"), r"put the \2 \3 on the \1 patch"),
    # "fill the red patch with the three red cubes": those cubes on it
    (re.compile(rf"\bfill\s+the\s+({COLOR_RE})\s+patch\s+with\s+"), r"put on the \1 patch "),
    # "a tower with the black block on top and two yellow blocks below it": below the top cube, the rest of the tower
    # (only when the cubes said below are counted and fill the rest of the tower: "a tower of four blocks: black on top,
    # yellow under it" puts yellow right under black, not at the bottom)
    (re.compile(rf"(\bon\s+top\b[^.;]*?\b(?:blocks?|cubes?|ones?|{COLOR_RE})\s+)(?:below|under|beneath|underneath)\s+(?:it|that\s+one)\b"
                r"(?=\s*(?:[.,;]|$))"), lambda m: f"{m.group(1)}below" if _rest_of_tower(m) else m.group(0)),
    # "the white cube at the bottom of a three-cube tower, with the two pink cubes above it": above the bottom cube
    (re.compile(rf"(\b(?:at|on)\s+the\s+(?:bottom|base)\b[^.;]*?\b(?:blocks?|cubes?|ones?|{COLOR_RE})\s+)(?:above|over|on\s+top\s+of)"
                r"\s+(?:it|that\s+one)\b(?=\s*(?:[.,;]|$))"), lambda m: f"{m.group(1)}above" if _rest_of_tower(m) else m.group(0)),
    # "the letter A cube next to the letter B cube with the letter B block to the left of the letter A block": a second
    # relation of the same labelled cubes, as "and" says it (a coloured cube had been made for 'B' after 'with')
    (re.compile(r"(?i)\bwith\s+(?=the\s+(?:letter|digit)\s+[a-z0-9]\s+(?:block|cube)\s+(?:to\s+the\s+(?:left|right)\s+of|in\s+front\s+of"
                r"|behind|next\s+to|beside|on\s+top\s+of|on|under|far\s+from)\b)"), "and "),
    # "yellow cube in the back, green cube in the front": each cube's place said in turn, as "... and ..." says it
    (re.compile(rf"(\b(?:cube|block)s?\s+(?:in|on|at)\s+the\s+(?:(?:front|back)\s+)?(?:front|back|left|right|center|centre|middle)"
                rf"(?:\s+(?:corner|side|half|edge))?)\s*,\s+(?=(?P<the>the\s+)?(?:{COLOR_RE})\s+(?:cube|block)s?\s+(?:in|on|at)\s+the\s+"
                r"(?:front|back|left|right|center|centre|middle)\b)"), lambda m: f"{m.group(1)} and {'' if m.group('the') else 'the '}"),
    # "build towers of 3 and 2 blocks", "two towers, of 3 and 2 blocks": one of each size (both had been one size)
    (re.compile(rf"\b(?:(?:2|two)\s+)?(tower|stack|row|line|pile|column)s\s*,?\s+(?:of\s+|with\s+)(\d+|{COUNT_WORD_RE})\s+and\s+"
                rf"(\d+|{COUNT_WORD_RE})\s+(blocks|cubes)\b"), r"a \1 of \2 \4 and a \1 of \3 \4"),
    # "in a row along with the green block": together with it
    (re.compile(r"\b(rows?|lines?|circles?|piles?)\s+along\s+with\b"), r"\1 together with"),  # (after a tower, "along with a
    # green cube" may be beside it or in it: not read)
    # "a row running from the front of the table to the back", "a column of three blue cubes running from front to back":
    # the structure's direction, its verb of extent dropped
    (re.compile(r"(\b(?:rows?|lines?|columns?|cubes|blocks)|\))\s+(?:running|going|extending|stretching|(?:that|which)\s+(?:runs?|goes|go"
                r"|extends?|stretch(?:es)?))\s+(?=(?:from\s+)?(?:the\s+)?(?:left|right|front|back)\b[^.;]{0,40}?\b(?:to|towards?)\s+"
                r"(?:the\s+)?(?:left|right|front|back)\b)"), r"\1 "),
    # "from the left to the right": a direction said with articles, as "from left to right" says it
    (re.compile(r"\bfrom\s+the\s+(left|right|front|back|bottom|top)\s+to\s+the\s+(left|right|front|back|bottom|top)\b"
                r"(?!\s+(?:of|side|edge|corner|end)\b)"), r"from \1 to \2"),
    # "running from the front of the table towards the back", "from the left edge to the right edge": the same direction
    (re.compile(r"\bfrom\s+the\s+(left|right|front|back)(?:\s+(?:side|edge|end))?\s+of\s+the\s+table\s+(?:to|towards?)\s+the\s+"
                r"(left|right|front|back)(?:\s+(?:side|edge|end))?\b(?!\s+of\b)"
                r"|\bfrom\s+the\s+(left|right|front|back)\s+(?:side|edge|end)\s+(?:to|towards?)\s+the\s+(left|right|front|back)"
                r"(?:\s+(?:side|edge|end))?\b(?!\s+of\b)"),
     lambda m: f"from {m.group(1) or m.group(3)} to {m.group(2) or m.group(4)}"),
    # "a circle around the center of the table", "a circle with four cubes around the centre of the table": the structure
    # with its middle at the centre
    (re.compile(r"\b(circle|ring)\b([^.;]{0,40}?)\s+around\s+(?=the\s+(?:center|centre|middle)\s+of\s+the\s+(?:table|workspace)\b)"),
     r"\1\2 in "),
    # "along the left side": a side of the table the structure runs along
    (re.compile(r"\balong\s+the\s+(?=(?:left|right|front|back)\s+(?:side|edge)\b)"), "on the "),
    (re.compile(r"\bin\s+back\b(?!\s+of\b)"), "at the back"),  # "a tower of 2 red blocks in back"
    # "at the back of the green cube": behind it (a cube's back, not the table's)
    (re.compile(rf"\b(?:at|to)\s+the\s+back\s+of\s+(?=(?:the\s+)?(?:(?:{COLOR_RE})\s+(?:block|cube|one|patch)|it\b|them\b))"), "behind "),
    # "a pyramid with two cyan cubes along the base", "brown, black and gray along the bottom": a pyramid's or wall's
    # bottom layer (not the table's edge: "along the bottom edge")
    # "Pyramid with a base of the letter blocks D, G and T and the letter block X on top": the base's cubes said "at the
    # base" (a label pyramid's base list had been refused as words no layer role holds)
    (re.compile(rf"\b(pyramids?\s+with\s+)a\s+(?:base|bottom(?:\s+layer)?)\s+of\s+(?P<l>(?:the\s+)?(?:(?:letter|digit|number)\s+"
                rf"(?:blocks|cubes)\s+)?(?:{COLOR_RE}|[a-z0-9])(?:\s*,\s*(?:{COLOR_RE}|[a-z0-9]))*\s*,?\s+and\s+(?:{COLOR_RE}|[a-z0-9])"
                rf"(?:\s+(?:cubes|blocks))?)\s+and\s+(?=(?:the\s+|a\s+|an\s+)?(?:(?:letter|digit|number)\s+)?(?:{COLOR_RE}|[a-z0-9])"
                rf"(?:\s+(?:block|cube))?(?:(?:\s*,\s*|\s+and\s+)(?:the\s+|a\s+|an\s+)?(?:{COLOR_RE}|[a-z0-9])(?:\s+(?:block|cube))?)*"
                r"\s+(?:(?:cubes|blocks)\s+)?(?:on\s+top|at\s+the\s+top)\b(?!\s+of\b))"), r"\1\g<l> at the base and "),
    # (a top of several said after the base list, "... and yellow and pink on top", is the top's: yellow had gone into the
    # base, silently; a pyramid with several on top and no layer between is refused)
    # "a pyramid from two white cubes and a black cube, the black cube at the peak": the one cube said on top, after a
    # comma without "with" (it had been a third black cube of a pyramid of six)
    (re.compile(rf"\b(pyramids?\b[^.;]*?),\s+(?:and\s+)?(?:the\s+)?((?:{COLOR_RE})\s+(?:cube|block|one))\s+(?:at\s+the\s+(?:very\s+)?"
                rf"(?:top|peak|apex|summit|tip)|on\s+(?:the\s+)?top)(?!\s+of\b)(?=\s*[.!]?\s*$)"),
     lambda m: f"{m.group(1)}, with the {m.group(2)} on top" if re.search(rf"\b{m.group(2).split()[0]}\b", m.group(1)) else m.group(0)),
    # (only a cube the pyramid's list holds: "from two gray cubes, the black cube at the tip" adds one, read elsewhere)
    # "a pyramid with yellow along the base": one colour alone along it, no count, is the whole bottom layer's ("with a
    # yellow base"; it had been one yellow cube in the base beside cubes of colours nobody said)
    (re.compile(rf"\b(pyramids?(?:\s+of\s+(?:\d+|[a-z]+)\s+(?:cubes|blocks))?)\s+with\s+(?:the\s+)?({COLOR_RE})\s+along\s+the\s+"
                rf"(?:bottom|base)\b(?!\s+(?:edge|side|of)\b)(?!\s*(?:,|and)\s*(?:the\s+)?(?:{COLOR_RE})\b(?!\s+(?:(?:cubes?|blocks?)\s+)?"
                r"(?:in\s+the\s+middle|on\s+(?:the\s+)?top|at\s+the\s+top|above)))"), r"\1 with a \2 base"),
    (re.compile(r"\b(pyramids?|walls?)\b([^.;]*?)\balong\s+the\s+(bottom|base)\b(?!\s+(?:edge|side|of)\b)"), r"\1\2on the \3"),
    # "a pyramid with the two purple cubes below and the pink cube on top": the cubes below are its base
    (re.compile(r"\b(pyramids?\b[^.;]*?\b(?:\d+|two|three|four)\s+(?:[a-z]+\s+)?(?:cubes|blocks))\s+(?:below|underneath|beneath)"
                r"(?=\s+and\s+(?:the\s+|a\s+|an\s+|1\s+|one\s+)?[a-z]+\s+(?:cube|block|one)\s+(?:on\s+top|at\s+the\s+top)\b(?!\s+of))"),
     r"\1 on the bottom"),
    # "a pyramid whose base is red": the whole bottom layer of a layered structure (a tower's base is its one bottom cube)
    (re.compile(rf"\b((?:pyramids?|walls?)(?:\s+of\s+(?:\d+|[a-z]+)\s+(?:cubes|blocks))?)\s+whose\s+(?:base|bottom)\s+(?:layer\s+|row\s+)?is\s+"
                rf"({COLOR_RE})\b(?!\s*(?:,|and)\s*(?:{COLOR_RE})\b(?!\s+(?:(?:cubes?|blocks?)\s+)?(?:in\s+the\s+middle|on\s+(?:the\s+)?top"
                r"|at\s+the\s+top|above)))"),
     r"\1 with a \2 base"),
    # "a tower whose base is blue and whose top is yellow": the ends said as the tower's own
    (re.compile(rf"\bwhose\s+(?:base|bottom)\s+(?:block\s+|cube\s+)?is\s+({COLOR_RE})\b"), r"with \1 at the bottom"),
    (re.compile(rf"\b(?:and\s+)?whose\s+top\s+(?:block\s+|cube\s+)?is\s+({COLOR_RE})\b"), r"and \1 on top"),
    # "a tower of three where the middle block is yellow": a role said in a clause of the tower's
    (re.compile(rf"\b(?<=(?:tower|stack)\s)(?:of\s+)?((?:\d+|two|three|four|five|six)\s+(?:(?:blocks?|cubes?)\s+)?)?(?:where|in\s+which)\s+the\s+(middle|center|centre)"
                rf"\s+(?:block|cube|one)\s+is\s+(?:the\s+)?({COLOR_RE})(?:\s+(?:one|block|cube))?\b"),
     lambda m: f"{'of ' + m.group(1) if m.group(1) else ''}with {m.group(3)} in the middle"),
    # "with one red block in between" (its ends said): the middle of the structure
    (re.compile(r"\b(with\s+(?:a|an|1|one|the)\s+[a-z]+\s+(?:block|cube))\s+in\s+between\b(?!\s+(?:the|them|those))"), r"\1 in the middle"),
    # "with one red block in the middle": one cube given a role, not a count of the structure
    (re.compile(r"\bwith\s+(?:1|one)\s+(?=[a-z]+\s+(?:block|cube)\s+(?:in|at|on)\s+(?:the\s+)?(?:middle|center|centre|top|bottom|base)\b)"),
     "with a "),
    # "the right back corner": a corner said left/right first
    (re.compile(r"\b(left|right)[\s-]+(front|back|rear)(?=[\s-]+corner\b)"), r"\2 \1"),
    # "Front-left corner: the green cube.": the place said as a heading before the one cube
    (re.compile(rf"^((?:the\s+)?(?:front|back|rear)[\s-]+(?:left|right)\s+corner)\s*:\s*(?:the\s+|a\s+)?({COLOR_RE})\s+"
                r"(block|cube)\s*[.!]?\s*$"), r"put the \2 \3 in the \1"),
    (re.compile(r"\bcent(?:er|r)ed\s+(?:on|in)\s+the\s+(table|workspace)\b"), r"at the center of the \1"),
    # "a centered stack", "in one centred tower": the structure at the centre of the table
    (re.compile(r"\bcent(?:er|r)ed\s+(tower|stack|column|pile|row|line|pyramid|circle|ring|grid|square|wall)"
                r"(\s+of\s+(?:\d+|two|three|four|five|six|seven|eight|nine|ten)\s+(?:[a-z]+\s+)?(?:blocks|cubes|bricks))?\b"
                r"(?=\s*(?:[.,;!]|$|with\b|using\b|where\b|in\s+which\b))"),
     r"\1\2 at the center of the table"),
)
"""Places and pairings said another way, rewritten in order to the form the readers take
(:func:`rpg.schema.reading.normalize_words`, after "the same patch" is resolved): two colours
before one plural patch noun, "respectively", "keep", the table's centre and sides.  A "centered"
left after them says no place and is refused."""

BOTH_OF_THEM_RE = re.compile(rf"\b(?P<subj>(?:the\s+(?P<c>{_COLOR_WORD})\s+(?:block|cube))|(?<![\w-]\s)(?P<c2>{_COLOR_WORD}))\s+"
                             r"(?:(?:goes|go|is|sits|stays|ends\s+up|(?:should|must)\s+(?:be|go|end\s+up))\s+)?"
                             rf"(?P<rel>{_PAIRWISE_WORDS})\s+"
                             r"(?:both\s+of\s+them|them\s+both|both|each\s+of\s+them|the\s+two\s+of\s+them|all\s+of\s+them|them\s+all)\b")
""""The brown cube far from both of them", "..., green far from both": a relation to each of the two cubes named before
it (:func:`rpg.schema.reading.normalize_words` writes them out when exactly two are); the subject ``c`` as "the <colour>
cube", or ``c2`` a bare colour opening its clause."""

DISTRIBUTED_RELATIONS: tuple[tuple[re.Pattern, str], ...] = (
    # "the red and orange blocks far from the blue block but next to the green block": each of them, both relations
    # (the second had gone to the orange block alone)
    (re.compile(rf"(?<!stack\s)(?<!pile\s)\bthe\s+(?P<a>{_COLOR_WORD})\s+and\s+(?:the\s+)?(?P<b>{_COLOR_WORD})\s+(?P<n>block|cube)s\s+"
                rf"(?P<rel>{_PAIRWISE_WORDS})\s+the\s+(?P<c>{_COLOR_WORD})\s+(?:block|cube)\s*,?\s+(?:but|and|yet)\s+(?:also\s+|still\s+)?"
                rf"(?P<rel2>{_PAIRWISE_WORDS})\s+the\s+(?P<d>{_COLOR_WORD})\s+(?:block|cube)\b"),
     r"the \g<a> \g<n> \g<rel> the \g<c> \g<n> and the \g<a> \g<n> \g<rel2> the \g<d> \g<n> and "
     r"the \g<b> \g<n> \g<rel> the \g<c> \g<n> and the \g<b> \g<n> \g<rel2> the \g<d> \g<n>"),
    # "the red and green blocks next to the blue block", "both the red and the orange cube should be next to the white
    # cube": each of them (the red one had been dropped after a verb)
    (re.compile(rf"(?<!stack\s)(?<!pile\s)\b(?:both\s+)?the\s+(?P<a>{_COLOR_WORD})\s+and\s+(?:the\s+)?(?P<b>{_COLOR_WORD})\s+"
                r"(?P<n>block|cube)(?:s\s+|\s+(?=(?:should|must|will|are|go|sit|stand|end)\b))"
                r"(?:(?:should|must|will)\s+(?:be|go|end\s+up|sit|stand)\s+|(?:are|go|sit|stand|end\s+up)\s+)?"
                rf"(?P<rel>{_PAIRWISE_WORDS})\s+the\s+(?P<c>{_COLOR_WORD})\s+(?:block|cube)\b"
                rf"(?!\s*,?\s*(?:and|or)\s+(?:the\s+)?{_COLOR_WORD})"),  # ("... next to the white cube and the black cube": both)
     r"the \g<a> \g<n> \g<rel> the \g<c> \g<n> and the \g<b> \g<n> \g<rel> the \g<c> \g<n>"),
    # "the red block to the left of the blue and green blocks", "... of the blue block and the green block."
    (re.compile(rf"\bthe\s+(?P<a>{_COLOR_WORD})\s+(?P<n>block|cube)\s+(?P<rel>{_PAIRWISE_WORDS})\s+the\s+(?P<b>{_COLOR_WORD})"
                rf"(?:\s+and\s+(?:the\s+)?(?P<c>{_COLOR_WORD})\s+(?:block|cube)s\b"
                rf"|\s+(?:block|cube)\s+and\s+the\s+(?P<c2>{_COLOR_WORD})\s+(?:block|cube)\s*(?=[.!]?$))"),
     lambda m: (f"the {m['a']} {m['n']} {m['rel']} the {m['b']} {m['n']} and the {m['a']} {m['n']} {m['rel']} "
                f"the {m['c'] or m['c2']} {m['n']}")),
    # "to the left and to the right of the yellow block", "behind and to the left of it": each of the object
    (re.compile(rf"\b(?P<r1>{_PAIRWISE_WORDS}|(?:to|on)\s+the\s+(?:left|right)|in\s+front|next)\s+and\s+(?:also\s+)?"
                rf"(?P<r2>{_PAIRWISE_WORDS})\s+(?P<obj>the\s+{_COLOR_WORD}\s+(?:block|cube|one)|it)\b"),
     lambda m: f"{_completed(m['r1'])} {m['obj']} and {m['r2']} {m['obj']}"),
)
"""A pairwise relation (:data:`PAIRWISE_RELATIONS`) said once of two cubes, written out for
each: "the red and green blocks next to the blue block" is red next to blue and green next to
blue; "the red block left of the blue and green blocks" is left of each.  ("between" takes
the two together, "on" two cubes is a bridge, and "stack the red and blue blocks next to the
green block" stacks the two, next to it.)"""


EDIT_RELATIONS: tuple[tuple[str, str], ...] = (
    (r"\b(?:to the |on the )?left\b", "left_of"),
    (r"\b(?:to the |on the )?right\b(?!\s+(?:next\s+to|beside|by|behind|in\s+front|under|on\s+top|above|against)\b)", "right_of"),
    (r"\bin front\b|\bfront\b", "in_front_of"),
    (r"\bbehind\b|\bin back\b|\bto the back\b", "behind"),
    (r"\bfar\s+(?:apart|away|from)\b|\baway\s+from\b", "far_from"),
    (r"\bnext to\b|\bbeside\b|\badjacent\b|\bnear\b|\bclose to\b|\bside by side\b", "next_to"),
    (r"\bunder(?:neath)?\b|\bbelow\b|\bbeneath\b", "under"),
    (r"\bon top\b|\bonto\b|\batop\b|\bstack(?:ed|ing)?\b|\bon (?:it|them|the \w+ (?:block|cube)|the (?:\w+ )?(?:goal )?patch)\b", "on"),
)
"""The relation a steering edit names ("put it on the left instead"), most specific first:
words of an edit, where a side alone names the relation (:mod:`rpg.steer.relations`). "right"
before another relation ("right next to it", "right behind") only stresses that one."""


REF_PREP = r"\b(of|on|onto|to|beside|behind|near|under|below|beneath|above|atop|by|from|alongside|against)\s+"


PLACE_WORDS: frozenset[str] = frozenset({"left", "right", "front", "back", "top", "bottom", "middle", "center", "centre",
                                        "side", "corner", "edge"})
"""Words of a place, which a typo correction may not reach by cutting a longer word short ("righto" is not "right":
:func:`rpg.schema.reading._normalize_words`)."""

REGION_WORDS = {"rear": "back", "far": "back", "near": "front", "middle": "center", "centre": "center"}
"""Words for a place on the table -> the words of :data:`constants.REGION_NAMES`."""


FREE_PAIR_RE = re.compile(r"\b(?:the\s+)?colou?rs?\s+(?:and|or|,)\s+(?:the\s+)?order\s+(?:do\s*n[o']?t|don't|do\s+not|are\s+"
                          r"(?:unimportant|irrelevant|free))(?:\s+matter)?\b"
                          r"|\b(?:the\s+)?order\s+(?:and|or|,)\s+(?:the\s+)?colou?rs?\s+(?:do\s*n[o']?t|don't|do\s+not|are\s+"
                          r"(?:unimportant|irrelevant|free))(?:\s+matter)?\b"
                          r"|\b(?:the\s+)?colou?rs?\s+(?:and|,)\s+(?:the\s+)?order\s*:\s*(?:your\s+choice|any|free|up\s+to\s+you|whatever)\b")
"""Colours and order left free in one phrase ("colours and order do not matter"): said as the two
phrases :data:`FREE_CHOICE_RE` and :data:`ANY_ORDER_RE` read ("colours do not matter, in any order")."""

FREE_PHRASE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "A tower: cyan at the bottom, then red, then cyan again.": a colour said again in a list is one more cube of it ("again"
    # had been refused as picking a cube by what happened earlier)
    (re.compile(rf"(\bthen\s+(?:an?\s+|another\s+)?(?:{COLOR_RE})\b[^.;:!?]*?\bthen\s+(?:an?\s+|another\s+)?(?:{COLOR_RE})(?:\s+(?:one|cube|block))?)"
                r"\s+again\b(?=\s*(?:[.,;!]|$|on\s+top\b|at\s+the\s+top\b))"), r"\1"),  # (a list of two "then"s at least:
    # "stack red on blue, then red again" stays refused)
    # "Stack red, then green, then blue, each one on the previous.": the stack said in order again, cube on cube (had been
    # refused: "previous" picks a cube by an order nobody defined; here the list says it)
    (re.compile(r"(\bstack\b[^.;:!?]*\bthen\b[^.;:!?]*?)\s*,?\s*(?:with\s+)?each\s+(?:one\s+|cube\s+|block\s+)?(?:on(?:\s+top\s+of)?|onto|above"
                r"|resting\s+on)\s+the\s+(?:previous|one\s+before(?:\s+it)?)(?:\s+(?:one|cube|block))?(?=\s*[.!]?\s*$)"), r"\1"),
    # colours left free in other words ("Colours of the cubes are not specified.", "colours are not constrained",
    # "colours of your choosing", "The colours are entirely up to you"): said as the phrase FREE_CHOICE_RE reads, whose
    # check refuses them beside cubes named by colour
    (re.compile(r"\b(?:the\s+)?colou?rs?(?:\s+of\s+the\s+(?:cubes|blocks))?\s+(?:are\s+|is\s+|were\s+)?(?:not|un)\s*(?:specified|constrained"
                r"|fixed|given|stated|prescribed)\b"), "colours do not matter"),
    (re.compile(r"\b(?:the\s+)?colou?rs?\s+(?:of\s+your\s+(?:choosing|choice)|(?:are\s+|is\s+)?(?:entirely\s+|completely\s+|totally\s+)?"
                r"up\s+to\s+you)\b"), "colours do not matter"),
    (re.compile(r"\s*[,;]?\s*\b(?:what|all\s+that)\s+matters\s+is\s+the\s+shape\b|\s*[,;]?\s*\bonly\s+the\s+shape\s+matters\b"), ""),
    # the order left free in other words ("The exact order around the circle is not important", "which goes where is
    # your call")
    (re.compile(r"\s*[,;.]?\s*\b(?:the\s+)?exact\s+order(?:\s+(?:around|along|in)\s+the\s+(?:circle|ring|row|line|tower|stack))?\s+"
                r"(?:is\s+not\s+important|is\s+unimportant|does\s+not\s+matter|doesn't\s+matter)\b"), " in any order"),
    # ("Stack the red and the yellow cube; which one goes at the bottom isn't important")
    (re.compile(r"\s*[,;\u2013\u2014-]\s*which\s+(?:one\s+|cube\s+|block\s+)?(?:goes|is|sits|ends\s+up|stands|lies)\s+(?:where|at\s+the\s+(?:bottom|top)|on\s+(?:the\s+)?(?:top|bottom)"
                r"|first|underneath|below)\s+(?:is\s+(?:your|the\s+robot's)\s+(?:call|choice)|is\s+up\s+to\s+you"
                r"|does\s+not\s+matter|doesn't\s+matter|is\s*n[o']?t\s+important|isn't\s+important|is\s+not\s+important|is\s+unimportant)\b"
                r"(?=\s*(?:[.!;]|$))"),  # (", ..., but yellow": the order said after all, left to the readers)
     lambda m: " in any order" if re.search(r"\b(?:tower|stack|row|line|column)\b", m.string) and "patch" not in m.string else m.group(0)),
    # an arrangement the goal does not judge anyway ("How they are arranged inside that front half does not matter.",
    # "The order of the towers along the table is not something I care about."): dropped
    (re.compile(r"(?:^|(?<=[.;!]\s))how\s+(?:they|the\s+cubes|the\s+blocks)\s+(?:are\s+)?(?:arranged|placed|laid\s+out)\s+"
                r"(?:inside|within)\s+[a-z\s]{1,40}?\s+(?:does\s+not|doesn't)\s+matter\s*[.!]?"), ""),
    (re.compile(r"(?:^|(?<=[.;!]\s))the\s+order\s+of\s+the\s+(?:towers|stacks|piles|rows|groups)(?:\s+(?:along|on|across)\s+the\s+table)?\s+"
                r"(?:is\s+not\s+something\s+(?:i|we)\s+care\s+about|does\s+not\s+matter|doesn't\s+matter|is\s+not\s+important)\s*[.!]?"), ""),
    # a note that the task has no patch, or that nothing else need move ("there are no patches involved", "Nothing else
    # on the table needs to move."): nothing the goal judges
    (re.compile(r"\s*[,;.]?\s*\bthere\s+(?:are|is)\s+no\s+(?:goal\s+)?patch(?:es)?\s+(?:involved|needed|used|in\s+(?:it|this\s+task))\b"),
     lambda m: m.group(0) if re.search(r"\bpatch", m.string[:m.start()] + m.string[m.end():]) else ""),
    (re.compile(r"(?:^|(?<=[.;!]\s))nothing\s+else(?:\s+on\s+the\s+table)?\s+(?:needs|has|is)\s+to\s+(?:move|change|be\s+moved)\s*[.!]?"), ""),
    (re.compile(r"\s*[,.;]\s*(?:and\s+)?nothing\s+else\s*[.!]?\s*$"), ""),
    # Indian English "one time" at the close ("Put the purple cube on the white patch one time."): a request, no count
    (re.compile(r"\s+one\s+time\s*(?=[.!]?\s*$)"), ""),
    # "Gather every pink cube into one pile", "Put each red cube into a tower": all the cubes of that colour in the one
    # structure (read like "all the pink cubes"; the one pile had been refused as naming no cubes)
    (re.compile(rf"\b(?:every|each)\s+(?:single\s+)?({COLOR_RE})\s+(?:cube|block)\b(?=\s+(?:in|into|to|onto)\s+(?:a|one|1|the|a\s+single)\s+"
                r"(?:pile|heap|tower|stack)(?:\s+(?:on|at|in)\s+the\s+(?:left|right|front|back|cent(?:er|re)|middle)(?:\s+side)?"
                r"(?:\s+of\s+the\s+table)?)?\s*(?:[.!]\s*)?$)"), r"all the \1 cubes"),  # (not "into a pile of its own", "..., two
    # per pile", "... but one", "... Then take one out": a hostile helper's)
    # "Two stacks please - one with ..., the other with ...": the heading of structures counted off, its dash a colon
    (re.compile(r"\b((?:two|three|four|[2-4])\s+(?:stacks|towers|rows|lines|piles))\s+please\s*(?:-|\u2013|\u2014)\s+(?=(?:one|1)\b)"),
     r"\1 please: "),
    # Singapore English "any order also can": any order
    (re.compile(r"\s*[,;]?\s*\bany\s+order\s+also\s+(?:can|ok|okay|fine)\b"), " in any order"),
    # "(right as seen from the robot)": rpg's own frame, said in passing
    (re.compile(r"\s*\(\s*(?:(?P<side>left|right)\s+)?(?:as\s+)?(?:seen|viewed)\s+from\s+the\s+robot(?:'s\s+(?:side|view|base))?\s*\)"),
     lambda m: "" if not m.group("side") or re.search(rf"\b{m.group('side')}\b", m.string[:m.start()]) else m.group(0)),
    # thanks before the answer ("ty in advance"), a chat's "outta" ("make a circle outta 6 cubes")
    (re.compile(r"\s*[,.;]?\s*\b(?:ty|thx|thanks|thank\s+you)\s+in\s+advance\b"), ""),
    # a radio's acknowledgement ("Copy that.", "..., copy?", "Over."): no copy of anything (it had been refused as an action)
    (re.compile(r"(?:^|(?<=[.!?]\s))\s*copy\s+that\s*[.!]\s*|\s*,\s*copy\s*\?\s*$"), lambda m: "" if m.group(0).strip().startswith("copy") else "."),
    # "then white last on top", "Stack red first, then blue, then green last": "last" after the list's last "then" says
    # again that it ends the list (it had been an unknown word)
    (re.compile(rf"\b(then\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?)\s+last\b(?![^.;]*\bthen\b)"), r"\1"),
    # a radio's sign-off after the task ("... Wilco?", "... Acknowledge.", "... Over.")
    (re.compile(r"(?<=[.!?])\s+(?:wilco|roger(?:\s+that)?|acknowledge(?:d)?|over|out|over\s+and\s+out)\s*[.!?]?\s*$"), ""),
    (re.compile(r"\boutta\b"), "out of"),
    # the task said to be complete, mid-text ("That is the whole task; there are ...", "thats it.", "(b) thats it")
    (re.compile(r"\s*[,.;:]?\s*(?:\([a-z]\)\s*)?\b(?:that\s+is|thats|that's)\s+(?:it|the\s+whole\s+task|all)\s*(?=[.;!,]|$)"), ""),
)
"""What leaves free what the goal does not judge, in other words than :data:`FREE_CHOICE_RE` and
:data:`ANY_ORDER_RE` read: rewritten to their phrases or dropped before negations are refused
(:func:`rpg.schema.reading.normalize_words`; each had been refused as a negation or an unknown word)."""

NOT_IMPORTANT_RE = re.compile(r"\b(is|are)\s+(?:not\s+(?:important|relevant)|of\s+no\s+importance)\b")
"""" ... are not important": said as "unimportant", which :data:`FREE_PAIR_RE`, :data:`ANY_ORDER_RE` and
:data:`FREE_CHOICE_RE` read (the "not" had been refused as a negation)."""

ANY_ORDER_RE = re.compile(
    r"(?:\s*[,;(\u2013\u2014-]\s*|\s+)(?:(?:in\s+)?(?:any|whatever|whichever|no\s+particular|either|random|some)\s+(?:order|sequence)(?:\s+(?:(?:is|are)\s+(?:fine|ok(?:ay)?|good|allowed)"
    r"|works(?:\s+for\s+you)?|goes|will\s+do|suits\s+you|you\s+see\s+fit"
    r"|(?:(?:that|which)\s+)?(?:sounds|looks|seems|feels)\s+(?:best|right|good|nicest)(?:\s+to\s+you)?))?"
    r"|(?:the\s+)?order\s+(?:does\s*n[o']?t|doesn't|is\s*n[o']?t|isn't)\s+(?:matter|important)|regardless\s+of\s+(?:the\s+)?order"
    r"|(?:the\s+)?order\s+(?:is\s+)?(?:unimportant|irrelevant|immaterial)"
    r"|whichever(?:\s+(?:one|cube|block))?\s+goes\s+where|in\s+whichever\s+order(?:\s+(?:(?:that|which)\s+)?(?:sounds|looks|seems|feels)\s+(?:best|right|good|nicest)(?:\s+to\s+you)?)?"  # "..., whichever
    # goes where", "in whichever order sounds best to you"
    r"|(?:the\s+)?order\s+is\s+(?:up\s+to\s+(?:you|the\s+(?:policy|robot|agent|model))|your\s+(?:choice|call)|free|flexible|open)|order\s+free\b"
    r"|(?:the\s+)?order\s+(?:is\s+)?(?:not|n't|never)\s+(?:annotated|specified|given|stated|labell?ed|recorded|constrained)"
    r"|(?:in\s+)?(?:any|whatever|whichever)\s+order\s+(?:you\s+(?:like|want|choose|prefer|wish|see\s+fit)|suits\s+you|works\s+for\s+you"
    r"|(?:(?:that|which)\s+)?(?:sounds|looks|seems|feels)\s+(?:best|right|good|nicest)(?:\s+to\s+you)?)"
    r"|you\s+(?:can|may)\s+(?:choose|pick|decide)\s+the\s+order"
    r"|(?:the\s+)?order\s+(?:thereof\s+)?(?:being\s+)?at\s+(?:the\s+robot's|your|its)\s+discretion"
    r"|how(?:ever)?\s+you\s+(?:prefer|like|want|wish|please)"
    r"|(?:either|any|whichever)\s+(?:one\s+|1\s+|cube\s+|block\s+|of\s+them\s+)?(?:(?:can|may|could)\s+(?:go|be|sit|stand|end\s+up|come)\s+"
    r"|(?<=whichever\s)(?:(?:one|cube|block)\s+)?(?:ends\s+up|goes|sits|lands|is)\s+)?"
    r"(?:on\s+top|at\s+the\s+(?:top|bottom))(?!\s+of\b)(?:\s+(?:is\s+)?(?:fine|ok(?:ay)?))?"
    r"|whichever\s+way(?:\s+(?:is\s+)?(?:fine|round|around))?|either\s+way\s+(?:round|around|up)"
    # "Which one goes on top is up to you.", "It is up to you which one goes on top."
    r"|which(?:\s+(?:one|cube|block|colou?r))?(?:'s|\s+is|\s+goes|\s+ends\s+up|\s+sits)\s+(?:at\s+the\s+(?:bottom|top|base)|on\s+(?:the\s+)?(?:top|bottom))"
    r"\s+(?:is\s+)?(?:up\s+to\s+you|your\s+(?:choice|call)|free|open)"
    r"|(?:it'?s|it\s+is)\s+(?:up\s+to\s+you|your\s+(?:choice|call))\s+which(?:\s+(?:one|cube|block))?(?:'s|\s+is|\s+goes|\s+ends\s+up|\s+sits)"
    r"\s+(?:at\s+the\s+(?:bottom|top|base)|on\s+(?:the\s+)?(?:top|bottom))"
    r"|(?:it\s+)?(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter\s+(?:in\s+)?(?:which|what)\s+order"
    r"|(?:(?:it\s+)?(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter|(?:i\s+|we\s+)?(?:do\s*n[o']?t|don't|do\s+not)\s+(?:care|mind))"
    r"\s+which(?:\s+(?:one|cube|block|colou?r))?(?:'s|\s+is|\s+goes|\s+ends\s+up|\s+sits)"
    r"\s+(?:at\s+the\s+(?:bottom|top|base)|on\s+(?:the\s+)?(?:top|bottom)|first|last)"
    r"|(?:in\s+)?(?:which|what)\s+order\s+(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter"
    r"|(?:i\s+|we\s+)?(?:do\s*n[o']?t|don't|do\s+not)\s+(?:really\s+)?(?:care|mind)\s+(?:about\s+the\s+order|(?:in\s+)?what\s+order"
    r"|which(?:\s+(?:one|cube|block))?\s+goes\s+where))\b\)?")
"""Words that leave the cubes' order free ("stack them in any order", ", any order is fine",
"the order doesn't matter", "in no particular order"): read as the one phrase " in any order"
before negations are refused (:func:`rpg.schema.reading.normalize`), which no order word
(:data:`ORDER_WORDS`) matches."""

OTHER_WAY_DENIED_RE = re.compile(r"\s*[,;]?\s*(?:and\s+|but\s+)?not\s+the\s+other\s+way\s+(?:round|around)(?=\s*[.!;]?\s*$|\s*[.;]\s)")
""""stack the blue cube onto the red cube, not the other way round": the order said, restated
(dropped, like :data:`OPPOSITE_NEGATED_RE`)."""

OPPOSITE_NEGATED_RE = re.compile(
    r"(?P<said>\b(?:in\s+front\s+of|behind|(?:to\s+the\s+)?left\s+of|(?:to\s+the\s+)?right\s+of|on\s+top\s+of|on|under|below"
    r"|above)\s+(?:the\s+)?[a-z]+\s+(?:cube|block|one)\b)\s*[,;]?\s*(?:and\s+|but\s+)?not\s+(?P<neg>in\s+front\s+of|behind"
    r"|(?:to\s+the\s+)?left(?:\s+of)?|(?:to\s+the\s+)?right(?:\s+of)?|on\s+top\s+of|on|under(?:neath)?|below|beneath|above)"
    r"(?:\s+(?:it|them|the\s+[a-z]+\s+(?:cube|block|one)))?(?=\s*[.!;]?\s*$|\s*[.;]\s)")
"""A relation said, then its opposite denied ("put the black cube in front of the grey cube, not behind
it"): the denial restates the relation and is dropped (:data:`OPPOSITE_RELATIONS`); a denial of any
other relation adds a constraint and stays (refused as a negation)."""

OPPOSITE_RELATIONS: tuple[tuple[str, str], ...] = (
    ("in front", "behind"), ("left", "right"), ("on", "under"), ("on", "below"), ("on", "beneath"), ("above", "below"),
    ("on top", "under"), ("on top", "below"), ("on top", "beneath"),
)
"""Relation words that exclude each other (:data:`OPPOSITE_NEGATED_RE`), either way round, written
without "to the" and a final "of"."""

HARMLESS_NEGATION_RE = re.compile(r"[,;(\u2013\u2014-]?\s*\b(?:nothing|none?\s+too|no\s+need\s+(?:to\s+be|for\s+anything))\s+"
                                  r"(?:fancy|special|complicated|elaborate|too\s+fancy)\b\)?"
                                  r"|[,;]?\s*\b(?:i'?m|i\s+am|we'?re|we\s+are)\s+not\s+(?:fussy|picky|particular)\b"
                                  r"|[,;]?\s*\bif\s+you\s+(?:don'?t|do\s+not)\s+mind\b"
                                  r"|[,;.!]?\s*\b(?:thanks|thank\s+you)\s+(?:ever\s+so|so|very)\s+much\b")
"""A negation about the manner, not the end state ("..., nothing fancy", "I'm not fussy", "if
you don't mind", "thanks so much"): dropped before
negations are refused (:func:`rpg.schema.reading.normalize`)."""

FREE_CHOICE_RE = re.compile(
    r"[,;(\u2013\u2014-]?\s*\b(?:(?:all|any)\s+)?(?:the\s+)?other\s+(?:blocks|cubes|bricks|ones)\s+(?:(?:may|can|could)\s+(?:be|go|stay)"
    r"\s+anywhere|(?:do\s*n[o']?t|don't|do\s+not)\s+matter|(?:are|is)\s+(?:irrelevant|free|up\s+to\s+you))\b"
    r"|[,;(\u2013\u2014-]?\s*\bnothing\s+else\s+(?:matters|is\s+important|counts)\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:the\s+)?(?:other\s+|remaining\s+)?colou?rs?(?:\s+of\s+the\s+(?:others|rest|other\s+(?:cubes|blocks)))?\s+"
    r"(?:do\s*n[o']?t|don't|do\s+not|does\s*n[o']?t|doesn't|does\s+not)\s+matter\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:the\s+)?colou?rs?\s+(?:are\s+)?(?:unimportant|irrelevant)\b"
    r"|(?:[,;(\u2013\u2014-]|(?<=[.!])\s)\s*(?:in\s+)?any\s+colou?rs?(?=\s*[.!;)]|\s*$)"
    r"|[,;.(\u2013\u2014-]?\s*\b(?:the\s+)?colou?rs?\s*:\s*(?:your\s+choice|any|free|whatever|up\s+to\s+you)\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:the\s+)?colou?rs?\s+(?:are\s+)?(?:free|open|up\s+to\s+you|your\s+choice)(?=\s*[.!;)]|\s*$)"
    r"|[,;(\u2013\u2014-]?\s*\b(?:the\s+)?(?:other|remaining|middle)\s+(?:\d+|two|three|four|one)(?:\s+(?:cubes|blocks|ones))?\s+(?:can|may|could)\s+be"
    r"\s+any(?:thing|\s+colou?rs?)?\b"
    r"|[,;.(\u2013\u2014-]?\s*\b(?:the\s+)?others?\s*:\s*(?:any(?:thing|\s+colou?rs?)?|whatever|free|your\s+choice)\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:the\s+)?(?:other|remaining)\s+(?:\d+|two|three|four|one)(?:\s+(?:cubes|blocks|ones))?\s+"
    r"(?:do\s*n[o']?t|don't|do\s+not|does\s*n[o']?t|doesn't|does\s+not)\s+matter\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:it\s+)?(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter\s+(?:exactly\s+|precisely\s+)?where\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:exactly\s+)?where\s+(?:exactly\s+)?(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter\b"
    r"|[,;(\u2013\u2014-]?\s*\bwhich\s+(?:cubes?|blocks?|ones?)\s+(?:do\s*n[o']?t|don't|do\s+not|does\s*n[o']?t|doesn't|does\s+not)"
    r"\s+matter\b"
    r"|[,;(\u2013\u2014-]?\s*\b(?:it\s+)?(?:does\s*n[o']?t|doesn't|does\s+not)\s+matter\s+which\s+(?:cubes?|blocks?|ones?)\b"
    # "a tower of three, pink bottom, rest whatever", "the rest / the other blocks can be any colour": only with a count
    # said elsewhere
    r"|[,;(\u2013\u2014-]?\s*\b(?:and\s+)?(?:the\s+)?(?:rest(?:\s+of\s+(?:them|the\s+(?:cubes|blocks)))?|others|other\s+(?:cubes|blocks|ones))"
    r"\s+(?:whatever|anything"
    r"|(?:can|may|could)\s+be\s+(?:any(?:thing|\s+colou?rs?)?|whatever)|(?:do\s*n[o']?t|don't|do\s+not)\s+matter"
    r"|(?:is|are)\s+(?:free|up\s+to\s+you|your\s+choice))\b")
"""Words that leave free what the goal does not judge anyway ("All other cubes may be anywhere.",
"nothing else matters", "colours don't matter", ", any colours", "doesn't matter exactly
where"): a goal never judges a cube it does not name, a colour nobody said or a spot inside a
place said, so the words are dropped before negations and conditions are refused
(:func:`rpg.schema.reading.normalize`).  "Any colours" only after a comma and last in its
sentence (or a sentence of its own), where it cannot pick cubes ("put any colours on the patch" stays unread)."""

POLITE_CONDITION_RE = re.compile(
    r"\b(?:i|we)(?:'d|\s+would)\s+(?:love|like|appreciate)\s+it\s+if\s+you\s+(?:could|would|can)\s+"
    # "When you're ready, put ...": a condition on the listener, not on the goal
    r"|^\s*(?:when(?:ever)?|once|if)\s+(?:you(?:'re|\s+are)|you're|everyone(?:'s|\s+is))\s+ready\s*,\s*"
    r"|\s*,\s*(?:when(?:ever)?|once)\s+(?:you(?:'re|\s+are)|you're)\s+ready(?=\s*[.!]?\s*$)"
    r"|[,;]?\s*\bif\s+you\s+(?:could|would|can|please)\b(?=\s+(?:please\s+)?(?:put|place|move|set|stack|make|build|arrange|"
    r"take|line|get|bring|slide|push|spell|sort|lay|form|create|pile)\b)"
    r"|[,;(]?\s*\bif\s+(?:at\s+all\s+)?possible\b\)?|[,;]?\s*\bif\s+you\s+(?:could|would|can|please)\s*(?=[.!,;]|$)"
    r"|(?i:[,;]?\s*\bif\s+(?:it|that)\s+(?:is\s+not|isn'?t|is\s+no|'?s\s+not)\s+too\s+much\s+(?:trouble|work|bother)\b\s*,?)"
    r"|(?i:\b(?:it\s+)?(?:is|would\s+be|'?d\s+be)\s+better\s+if\s+you\b)"
    r"|(?i:[,;]?\s*\b(?:when(?:ever)?|once)\s+you\s+(?:get|have|find)\s+(?:a|the)\s+(?:sec|second|minute|min|moment|chance"
    r"|mo)\b\s*[.!,]?)"
    # ", if that's ok", ", if that is alright": asking leave, no condition of the goal
    r"|(?i:[,;]?\s*\bif\s+(?:that|it|this)(?:'s|\s+is|\s+would\s+be|'d\s+be)\s+(?:ok(?:ay)?|alright|all\s+right|fine|possible)"
    r"(?:\s+with\s+you)?(?=\s*[.!]?\s*$))"
    # "... when you're done", "... once you are finished": the episode's end, when every goal is checked
    r"|(?i:[,;]?\s*\b(?:when|once|by\s+the\s+time)\s+(?:you(?:'re|\s+are|\s+have|'ve)|you're|the\s+robot\s+is|it\s+is|it's)\s+"
    r"(?:done|finished|through)(?=\s*[.!]?\s*$))")
"""A condition that is only politeness ("I'd love it if you could take the yellow cube ...", ",
if you could", "if possible"): dropped before conditions are refused, so the request is read
(:func:`rpg.schema.reading.normalize`).  "If the green cube is on the left ..." stays a condition;
"when you get a sec" is only the request's timing, not a condition of the goal; "when you're done" at the end is the
episode's end, when the goal is checked anyway; ", if that's ok" asks leave."""

SMALL_TALK_RE = re.compile(
    r"\b(?:i\s+)?hope\s+(?:you(?:'re|\s+are)|you\s+have\s+been|all\s+is|it(?:'s|\s+is))\s+(?:doing\s+|going\s+)?"
    r"(?:well|good|great|fine|ok(?:ay)?)(?:\s+today)?\s*[.!,]?"
    r"|[,.!]?\s*\b(?:thanks|thank\s+you|cheers)\s+(?:a\s+(?:bunch|lot|million|ton)|heaps|loads|in\s+advance)\b\s*[.!]?"
    r"|\b(?:ok(?:ay)?|sure|will\s+do|roger|got\s+it)[,!.]?\s+(?:i'?m\s+)?on\s+it\b\s*[.!]*"
    r"|(?:^|(?<=[.!?]\s))(?:(?:i'?m|i\s+am|we'?re|we\s+are)\s+)?(?:always\s+)?(?:happy|glad)\s+to\s+(?:help|assist)"
    r"(?:\s+(?:further|more|again|anytime|any\s+time))?\s*[.!]*(?=\s|$)")
"""Small talk that says nothing of the task ("Hope you're doing well.", "Thanks a bunch!",
"thanks in advance", "Happy to help further."): dropped (:func:`rpg.schema.reading.normalize`)."""

MATERIAL_SAID_RE = re.compile(r"\b(?:letter|digit|number|alphabet|lettered|numbered|label(?:l?ed)?)\s+(?:cubes?|blocks?|bricks?)\b")
"""Cubes named by their material ("2 letter cubes", "the digit blocks"): the task must hold
labelled cubes (:func:`rpg.schema.accounting.unaccounted`), and digits alone around a relation
name cubes (:func:`rpg.schema.reading.labels_in_relations`)."""

IDLE_REQUEST_RE = re.compile(r"\b(?:wait|waiting|look|looking|observe|observing|watch|watching|stand\s+by|stay|do\s+nothing"
                             r"|hello|hi|hey|good\s+(?:morning|afternoon|evening|night|job)|thanks|thank\s+you|bye|goodbye"
                             r"|that's\s+all|that\s+is\s+all|getting\s+set\s+up|checking)\b")
"""Words of a message that asks nothing of the cubes ("Just look at the blocks for a moment.",
"Hi robot, good morning!", "Thanks, that's all for today."): with no colour, label or goal word
(:data:`GOAL_WORD_RE`) the text is refused as saying no goal."""

GOAL_WORD_RE = re.compile(r"\b(?:put|place|set|move|stack|build|make|arrange|line|spell|sort|push|slide|bring|form|create|pile"
                          r"|lay|drop|position|sweep|gather|group|swap|reverse|unstack|cover|towers?|stacks?|rows?|lines?"
                          r"|pyramids?|grids?|circles?|rings?|walls?|piles?|patch(?:es)?|next\s+to|beside|left\s+of|right\s+of"
                          r"|behind|in\s+front\s+of|between|under|above|near|far\s+from|onto|letters?|digits?|words?)\b")
"""Words that ask something of the cubes (a placement verb, a structure, a patch, a relation)."""

CHAT_WORDS: frozenset[str] = frozenset("""
lovely great good job yay hooray woohoo wow awesome nice perfect excellent wonderful brilliant super cool amazing
fantastic well done thanks thank you cheers sweetie sweetheart honey dear buddy pal mate folks everyone kiddo ok okay
alright right then so there here we go let's lets that's it that this the way a an chap lad boy girl there's all set
ready now yes yep yeah hello hi hey morning afternoon evening again bravo oh ah aha phew whee see look at lovely
is be will it'll gonna fun easy peasy
""".split())
"""Words of a sentence that only cheers, greets or addresses ("Good job!", "Yay!", "Here we
go, folks!"): a sentence made of these alone is dropped (:data:`ADDRESS_RE` for an address
inside a sentence)."""

INTERJECTIONS: frozenset[str] = frozenset("""
hey hi hello hiya howdy yo oi ahoy arr arrr aye ahem psst hmm hm um uh er erm oh ah aha alas wow whoa welp yep yup nope
gee golly gosh heck jeez sheesh ugh yikes oops whew phew huzzah hurrah hooray yay woohoo ooh alrighty okey dokey lo behold
righto rightio righty-ho righto-ho
hark prithee pray forsooth verily yea nay egad zounds matey mateys landlubber landlubbers ye thee thou y'all yall ya
bro dude fam buddy folks partner sir maam ma'am madam miss mister captain cap'n chief boss team crew gang guys savvy
recruit recruits cadet cadets private soldier soldiers maggot maggots trooper troopers sergeant
""".split())
"""Words that only call out to a listener or exclaim (interjections and nouns of address: "hey", "arr matey", "listen
up, recruit"): a chunk of them alone at a sentence's edge is dropped (:func:`rpg.schema.reading.drop_asides`)."""

ADDRESS_RE = re.compile(r"(?:,\s*|^)(?:(?:okay|ok|now|right)\s+)?(?:sweetie|sweetheart|honey|dear|buddy|pal|mate|folks|everyone|kiddo"
                        r"|there'?s\s+a\s+(?:good\s+)?(?:chap|lad|girl|boy|dear|love))\s*(?=[,.!?]|$)")
"""A listener addressed by a pet name or "there's a good chap": dropped."""

HEADER_RE = re.compile(r"^\s*(?:(?:first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|final|next|review|bonus)\s+)?"
                       r"(?:(?:side|main|daily|bonus)\s+)?(?:lesson|quest|stage|boss\s+stage|level|round|exercise|challenge|mission"
                       r"|chapter|puzzle(?:\s+room)?|drill|practice)(?:\s+#?\d+)?(?:\s+(?:objective|goal|task))?(?:\s*,\s*[^:,.;]{1,40}?)?"
                       r"\s*[:\-\u2013\u2014]\s*")
"""A lesson's, quest's or stage's heading before the task ("Lesson 3: ...", "Side quest, The Lost
Letter: ...", "First lesson, stacking: ..."): the task follows, the heading is dropped."""

SELF_CORRECTION_RE = re.compile(
    r"(?i)(?:[,.;:!?]|\s[-\u2013\u2014])\s*(?:(?:(?:er+m?|uh+|um+)\s*,?\s+)?(?:sorry|i\s+mean|no\s*,?\s+wait|wait\s*,?\s+no"
    r"|(?:er+m?|uh+|um+)\s*,?\s+no|no\s*,?\s+i\s+mean|oops|correction|or\s+rather|make\s+that|scratch\s+that"
    r"|no\s*,?\s+sorry|no(?=\s*,?\s+(?:the|a|an|on|onto|in|into|next|behind|to|at)\b)"
    r"|no(?=\s*,\s*(?:one|two|three|four|five|six|seven|eight|nine"
    r"|ten|\d+)\b)"
    r"|wait(?=\s*,\s*(?:the|a|an|on|onto|in|into|next|behind|under|to|at|\d+|one|two|three|four|five|six)\b))\b[,:!.]*\s+)+(?=\S)")
"""A writer correcting themselves mid-instruction ("..., sorry, the pink patch", "Stack red on
blue, I mean blue on red.", "to the left, er no, to the front", "the red, no, the orange one", "to the left of the,
wait, to the right of"): the correction replaces what it
corrects (:func:`rpg.schema.reading.apply_corrections`); after a pause only (a correction word
that opens the text is read as it is)."""

_CONTRAST_OBJECT = r"(?:\s+(?:it|them|each\s+other|one\s+another|(?:the\s+)?[a-z]+\s+(?:cube|block|one)))?"
CONTRAST_ALTERNATIVES: dict[str, str] = {
    # a whole goal's kind: "not a row, a stack", "not a sorting task ... a spelling task", "not two towers, one tower"
    "structure": r"(?:(?:a|an|one|the|two|three|four|2|3|4|single|plain|simple|just)\s+){0,2}(?:rows?|lines?|stacks?|towers?"
                 r"|pyramids?|walls?|circles?|rings?|grids?|piles?|heaps?|columns?)(?:\s+of\s+(?:the\s+)?(?:cubes|blocks))?"
                 r"|(?:a|an|the)\s+(?:sorting|spelling|stacking|placement|placing|building|pick-and-place)\s+(?:task|one|exercise|problem)",
    # one relation: "not left of it, right of it", "not near each other - far apart"
    "relation": r"(?:(?:to\s+the\s+)?(?:left|right)(?:\s+of)?|in\s+front(?:\s+of)?|behind|on\s+top(?:\s+of)?|under(?:neath)?|below"
                r"|beneath|above|near|next\s+to|beside|far\s+apart|far\s+(?:away\s+)?from|side\s+by\s+side|touching|adjacent(?:\s+to)?)"
                + _CONTRAST_OBJECT,
    # one place: "not the back left corner, the front right corner", "not the blue patch, ... the white patch"
    "place": r"(?:(?:in|at|on|to|into|onto)\s+)?(?:the\s+)?(?:(?:far|very)\s+)?(?:(?:back|front|rear|near)[\s-]+)?(?:(?:left|right)(?:-hand)?[\s-]+)?"
             r"(?:corner|side|half|edge|end|region)|(?:(?:in|at|on|to|into|onto)\s+)?the\s+(?:middle|cent(?:er|re))(?:\s+of\s+the\s+table)?"
             r"|(?:(?:in|at|on|to|into|onto)\s+)?(?:the\s+)?[a-z]+\s+(?:patch|pad|mat)",
    # a direction or sort order: "not descending, ascending", "not left to right but right to left"
    "order": r"(?:in\s+)?(?:descending|ascending|increasing|decreasing|reverse[d]?|alphabetical)(?:\s+order)?"
             r"|(?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left|top\s+to\s+bottom|bottom\s+to\s+top|front\s+to\s+back|back\s+to\s+front)",
    # two cubes one on the other: "red on blue, not blue on red"
    "pair": rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:on(?:\s+top\s+of)?|under|over|above|below|atop)\s+(?:the\s+)?"
            rf"(?:{COLOR_RE})(?:\s+(?:cube|block|one))?",
}
"""The slots a writer contrasts a denied alternative with the one meant ("Not a row, a stack.", "not descending,
ascending", "red on blue, not blue on red", "not a circle but a pile", "a letter stack rather than a row"): each kind's
alternatives as a regular expression over the text (case-insensitive). A denied alternative beside the one meant in the
same slot excludes nothing the meant one does not already exclude, so it is dropped (:func:`rpg.schema.reading.drop_contrasts`);
a denial of anything else ("on the patch, not next to the green cube") stays, and is refused as a negation."""

CONTRAST_EXCLUSIVE: tuple[frozenset[str], ...] = tuple(frozenset(p) for p in (
    ("left", "right"), ("front", "behind"), ("on", "under"), ("on", "below"), ("on", "beneath"), ("above", "below"),
    ("above", "under"), ("above", "beneath"), *((near, "far") for near in ("near", "next", "beside", "side", "touching", "adjacent"))))
"""Relations that exclude each other (by their head word: "left" of "to the left of", "far" of "far apart"): a
relation denied beside one of these is one the meant relation already excludes (:func:`rpg.schema.reading.drop_contrasts`);
any other pair ("left of it, not next to it") adds a constraint and stays refused."""

CONTRAST_LEAD = (r"(?i)(?:^|(?<=[.;:!?]\s)|(?<=[.;:!?]\n))(?:(?:it|this|that)\s+is\s+|(?:it|this|that)'s\s+|the\s+(?:goal|task|target|answer|idea)"
                 r"\s+is\s+)?not\s+(?:just\s+)?(?P<neg>{a})(?:\s*,\s*(?:and\s+)?not\s+(?:{a}))*\s*(?:[,;:.!]|\s[-\u2013\u2014]+)\s*"
                 r"(?:but\s+|rather\s*,?\s+|instead\s*,?\s+)?(?:(?:it\s+is|it's|this\s+is|the\s+(?:goal|task|target)\s+is|just|only)\s+)?"
                 r"(?=(?P<pos>{a})\b)")
"""A denial that opens a sentence, then the alternative meant ("Not a row, a stack.", "not a wall, not a pyramid, just
a plain tower", "It is not a sorting task. It is a spelling task: ..."); ``{a}`` is a kind's alternatives."""
CONTRAST_BUT = r"(?i)\bnot\s+(?P<neg>{a})\s*,?\s+but\s+(?:rather\s+|instead\s+)?(?=(?P<pos>{a})\b)"
"""A denial, then "but" and the alternative meant ("The target is not a line of cubes but a 2x2 grid")."""
CONTRAST_TRAILING = r"(?i)\b(?P<pos>{a})\s*[,;]?\s*(?:and\s+|but\s+)?(?<!\w)not\s+(?P<neg>{a})(?=\s*(?:[.;!)]|$))"
"""The alternative meant, then the denial ("red on blue, not blue on red.")."""
CONTRAST_RATHER = r"(?i)\b(?P<pos>{a})\s+(?:rather\s+than|instead\s+of)\s+(?P<neg>{a})\b"
"""The alternative meant, then the denial ("a letter stack rather than a row")."""
CONTRAST_RES: tuple[tuple[str, re.Pattern], ...] = tuple(
    (kind, re.compile(form.replace("{a}", f"(?:{alternatives})")))
    for kind, alternatives in CONTRAST_ALTERNATIVES.items()
    for form in (CONTRAST_LEAD, CONTRAST_BUT, CONTRAST_TRAILING, CONTRAST_RATHER))
"""Each kind's contrasts in each form, compiled (:func:`rpg.schema.reading.drop_contrasts`)."""
CONTRAST_SENTENCE_RE = re.compile(
    r"(?i)(?:^|(?<=[.;:!?]\s))(?P<subj>the\s+(?:goal|task|target|idea|point)|it|this)\s+(?:is\s+not|isn't|is\s*n[o']?t)\s+[^.;:!?]*[.;:!?]\s*"
    r"(?=(?P=subj)\s+is\b)"
    r"|(?:^|(?<=[.;:!?]\s))(?P<who>i|we)\s+(?:do\s+not|don't|do\s*n[o']?t)\s+(?:want|need)\s+[^.;:!?]*[.;:!?]\s*"
    r"(?=(?P=who)\s+(?:want|need|would\s+like)\b)")
"""A sentence that says what the goal is not, then one with the same subject that says what it is ("The goal isn't to
stack them. The goal is to put ...", "I don't want a tower here; I want a line ..."): the denial is dropped."""

CORRECTION_WORD_CLASSES: dict[str, frozenset[str]] = {
    "det": frozenset("the a an this that".split()),
    "prep": frozenset("to on onto in into at under below above beside behind between next near left right".split()),
}
"""Which words a correction's first word may stand for ("the pink patch" replaces "the yellow
patch"; "to the front" replaces "to the left"): articles for articles, prepositions for
prepositions; a count for a count; a word in capitals for one; other words for themselves."""

def count_word(word: str) -> int:
    """A count said in digits or a number word ("3", "three", "Two"), as an int.

    Raises:
        KeyError: ``word`` is neither digits nor one of :data:`NUMBER_WORDS`."""
    return int(word) if word.isdigit() else NUMBER_WORDS[word.lower()]


def _counted_tower_chain(m: re.Match) -> str:
    """"a two-block tower, orange under cyan" -> "a tower of orange under cyan" when the chain has that many cubes (else as
    said: the count then stays read against it)."""
    count = count_word(m.group("n"))
    said = len(re.findall(rf"\b(?:{COLOR_RE})\b", m.group("chain")))
    return f"{m.group('a') or ''}{m.group('kind')} of {m.group('chain')}" if said == count else m.group(0)


START_COUNTED_TOWER_REWRITE: tuple[re.Pattern, object] = (
    re.compile(rf"(?i)\b(?P<a>an?\s+)?(?P<n>two|three|four|[2-4])[\s-](?:block|cube)\s+(?P<kind>tower|stack)(?:\s*,\s*|\s+of\s+)(?P<chain>(?:{COLOR_RE})"
               rf"(?:\s+(?:on\s+top\s+of|on|under|atop|below|beneath)\s+(?:{COLOR_RE}))+)\b"), _counted_tower_chain)
"""A start tower's chain with its count said first ("There's a two-block tower, orange under cyan."): "a tower of orange
under cyan" (:data:`START_SAID_REWRITES`; the citations read it so too)."""

START_SAID_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Starting from a tower of green (bottom), yellow, white (top), ...": the ends marked in brackets, the list bottom to
    # top (it had been refused as ends the list's places do not have)
    (re.compile(rf"(?i)\b(?P<n>tower|stack)\s+of\s+(?P<a>(?:{COLOR_RE}))\s*\((?:bottom|base)\)\s*,\s*(?P<mid>(?:(?:{COLOR_RE})\s*,\s*)*)"
                rf"(?:and\s+)?(?P<z>(?:{COLOR_RE}))\s*\(top\)"),
     lambda m: f"{m.group('n')} of {m.group('a')}, {m.group('mid')}{m.group('z')} (bottom to top)"),
    # "Given a stack with black at the bottom and gray on top, move ...": the start said as what is given
    (re.compile(rf"(?i)^\s*(?:given|starting\s+(?:from|with)|start(?:ing)?\s+with)\s+a\s+(?:tower|stack)\s+with\s+(?:the\s+)?(?P<b>{COLOR_RE})"
                rf"(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+the\s+(?:bottom|base)\s+and\s+(?:the\s+)?(?P<t>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+"
                r"(?:on\s+top|at\s+the\s+top)\s*,\s*"),
     lambda m: f"Initially the {m.group('t')} cube is on the {m.group('b')} cube. "),
    # "There's a two-cube tower, red on top of white. Add a black cube to the top of it.": the tower said with its chain after
    # a comma, then topped (the chain had been read as the goal with the black cube on white too: a contradiction)
    (re.compile(rf"(?i)^\s*there(?:'s|\s+is)\s+a\s+(?:(?:two|2)[\s-]+(?:cube|block)\s+)?(?:tower|stack)\s*[,:\-\u2014]\s*(?:with\s+)?(?:the\s+)?"
                rf"(?P<top>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:on\s+top\s+of|on|atop)\s+(?:the\s+)?(?P<bottom>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                rf"\s*\.\s+(?P<v>put|place|set|stack|add)\s+(?P<c>(?:a|an|the)\s+(?:{COLOR_RE})\s+(?:cube|block))\s+(?:(?:to|on|onto)\s+the\s+top|on\s+top)"
                r"(?:\s+of\s+(?:it|the\s+(?:tower|stack)))?(?=\s*[.!]?\s*$)"),
     lambda m: f"There is a {m.group('top')} cube on the {m.group('bottom')} cube. {m.group('v')} {m.group('c')} on top of it"),
    # "Starting scene: blue on top of red. Take off ...", "Given: ...": the start said under a heading ('scene' had been
    # refused unread; "Given:" refused as a start not read)
    (re.compile(r"(?i)^\s*(?:(?:the\s+)?(?:starting|start|initial|opening|begin(?:ning)?)\s+(?:scene|state|setup|set-up|configuration"
                r"|layout|position|arrangement)|given)\s*[:\-\u2014]\s*(?=\S)"),
     "Initially "),
    # "Scene before: purple on brown. Scene after: ...", "Before state: ...": the start and the goal said as before and after
    (re.compile(r"(?i)(?:(?<=^)|(?<=[.;!]\s))\s*(?:the\s+)?(?:(?:scene|state|setup|configuration|layout)\s+(?P<a>before|after)"
                r"|(?P<b>before|after)\s+(?:scene|state|setup|configuration|layout))\s*:"),
     lambda m: f"{(m.group('a') or m.group('b')).capitalize()}:"),
    # "take off the blue cube and put it on ...": the cube taken off (read as "take the blue cube off")
    (re.compile(rf"(?i)\btake\s+off\s+(the\s+(?:{COLOR_RE}|[A-Z]|\d)\s+(?:cube|block)|the\s+top\s+(?:cube|block))\b"), r"take \1 off"),
    # "Starting from a tower with yellow on blue": the tower's chain
    (re.compile(rf"(?i)\b(tower|stack)\s+with\s+(?=(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:on|under|atop|on\s+top\s+of)\s)"), r"\1 of "),
    START_COUNTED_TOWER_REWRITE,
    # "Starting from a stack of blue, yellow, pink (bottom to top), unstack everything onto the table": each of its cubes on
    # the table ('everything' had been refused unread)
    (re.compile(r"(?i)\b(?:unstack|dismantle|take\s+apart|disassemble)\s+(?:everything|it\s+all|all\s+of\s+it|it|them|the\s+(?:whole\s+)?(?:tower|stack))"
                r"(?:\s+completely)?\s*,?\s+(?:onto|on|to)\s+the\s+table\b"),
     lambda m: "put every cube on the table" if re.search(r"(?i)\b(?:starting|start|begin(?:ning)?|initially|given|from)\b", m.string[:m.start()])
     else m.group(0)),
    # "Starting from a tower of orange under gray, ...": its two cubes bottom first, said as the chain the start reads
    (re.compile(rf"(?i)^(\s*(?:(?:starting|beginning|start|begin)(?:\s+out)?\s+(?:from|with)|from|given)\s*:?\s+(?:an?|the)\s+(?:tower|stack)\s+of\s+)"
                rf"(?:the\s+)?(?P<lo>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:under|below|beneath|underneath)\s+(?:the\s+)?(?P<up>{COLOR_RE})"
                rf"(?:\s+(?:cube|block))?(?=\s*[,;:])"),
     lambda m: f"{m.group(1)}{m.group('up')} on {m.group('lo')}"),
)
"""A start said in words the initial-scene reader reads another way (:func:`rpg.schema.readers.initial.split`)."""

MARKUP_RES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"~~[^~]*~~"), " "),  # ~~struck out~~: withdrawn by its writer
    (re.compile(r"(?m)^\s*={2,6}\s*(?P<h>[^=\n]{1,60}?)\s*={2,6}\s*"), r"\g<h>: "),  # a wiki's "== Example task ==": its heading
    (re.compile(r"(?m)^\s*#{1,6}\s+(?P<h>(?:[A-Za-z][a-z]*\s+){1,4}?)(?=[A-Z][a-z]+\s)"), r"\g<h>: "),  # "## Task Stack ...": its heading
    (re.compile(r"(?m)^\s*(?:#{1,6}|//|>)\s+"), ""),  # a Markdown heading's hashes, a quote's mark, a code comment's marker
    (re.compile(r"(?m)^\s*[-*+]?\s*\[[ xX]\]\s*"), ""),  # a task checkbox "- [ ] ..."
    (re.compile(r"\*\*|__|`|\"\"\"|'''"), ""),  # **bold**, __bold__, `code`, a docstring's quotes
    (re.compile(r"(?m)^\s*def\s+\w+\s*\([^)]*\)\s*(?:->\s*[\w\[\], ]+)?:\s*"), ""),  # "def build_tower():" before its docstring
    (re.compile(r"(?i)\s*\((?:see|cf\.?)\s+[^)]{1,40}\)"), ""),  # "(see Fig. 3)", "(see test_relations.py)": a reference
    (re.compile(r"(?<![\w*])\*(?=[^\s*])|(?<=[^\s*])\*(?![\w*])"), ""),  # *emphasis*
    (re.compile(r"(?<![\w&])#[A-Za-z]\w*"), " "),  # a post's hashtags ("#robotics #friday"): a topic, no goal
    # a template's filled slots (VIMA-style): "move the {orange} block", "put the {dragged_obj: green cube} into the
    # {base_obj: brown patch}": the value (one item, unquoted: a config's dict stays whole)
    (re.compile(r"(?<=\w\s)\{\s*(?:(?P<key>[A-Za-z_]+)\s*:\s*)?(?P<value>[^{}:,\"']+?)\s*\}"),
     lambda m: m.group("value") + (" patch" if re.search(r"(?i)patch", m.group("key") or "")
                                   and not re.search(r"(?i)\bpatch\b", m.group("value")) else "")),  # "{patch: yellow}"
    # a benchmark table's row: "task_07 | stack | red on blue", "| t23 | spell | ...": its id and pipes
    (re.compile(r"^\s*\|?\s*(?:task|t|row|id)[_\s-]?\d+\s*\|\s*", re.I), ""),
    # an assistant's reply around the task: "Sure! Here is the task:", "Certainly.", "I hope this helps!",
    # "Let me know if you need anything else!", "Feel free to adjust the colours."
    (re.compile(r"(?i)^\s*(?:(?:sure|certainly|of\s+course|absolutely|great\s+question|happy\s+to\s+help)\s*[!.,]\s*)+"), ""),
    (re.compile(r"(?i)^\s*here(?:'s|\s+is)\s+(?:the|a|your)\s+(?:concise\s+|short\s+|simple\s+)?(?:task|specification|spec|goal)\s*:\s*"), ""),
    (re.compile(r"(?i)(?<!\s)\s*(?:let\s+me\s+know\s+if\s+[^.!]*|i\s+hope\s+(?:this|that)\s+helps|feel\s+free\s+to\s+[^.!]*"
                r"|(?:\*\*)?constraints?:?(?:\*\*)?\s*none)\s*[.!]?\s*$"), ""),
    # a user story: "As a lab manager, I want ..., so that the bench looks tidy": the want, not the role or the reason
    (re.compile(r"(?i)^\s*(?:user\s+story\s*:\s*)?as\s+an?\s+[a-z]+(?:\s+[a-z]+)?\s*,?\s+(?=i\s+(?:want|need|would\s+like)\b)"), ""),
    (re.compile(r"(?i)(?<!\s),?\s+so\s+(?:that\s+)?(?:i|we|the\s+(?:bench|table|camera|students?|visitors?))\s+(?:can|could|looks?|sees?"
                r"|understand|understands)\b[^.]*"), ""),
    # a chat's announcement of the task ("ok new eval task: ...", "new task -"): the task follows
    (re.compile(r"(?i)^\s*(?:(?:ok(?:ay)?|so|alright|hey)\s*[,.!]?\s+)?(?:(?:a|the|one|another)\s+)?(?:new\s+(?:eval(?:uation)?\s+)?|eval(?:uation)?\s+)"
                r"(?:task|eval)\s*(?:->|=>|\u2192|[:,\-])?\s*(?=\S)"), ""),
    # a chat's emoji shortcodes (":pray:", ":white_check_mark:", ":red_circle:"): pictures, no words of the task
    (re.compile(r"(?:\s*(?<![\w:]):[a-z0-9_+\-]{2,40}:(?![\w:]))+"), " "),  # a run of them is one blank (runs of blanks had
    # made later patterns quadratic: 50 s for a text of 270 shortcodes)
    # an exam's points: "(5 points)", "Q4 (10 pts)."
    (re.compile(r"(?i)\s*\(\s*\d+\s*(?:points?|pts?|marks?)\s*\)\s*\.?"), " "),
)
"""Markdown markup around the words (a heading flattened onto the line of its text, "## Task
Stack green on red", ends before the next capitalised word and is read as a label; headings, emphasis, code spans, checkboxes): removed before
reading, so "the **blue** patch" is the blue patch; struck-out text is withdrawn and removed
with its words (:func:`rpg.schema.reading.normalize_words`)."""


CHAT_TURN_RES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"\[\s*\d{1,2}:\d{2}(?::\d{2})?(?:\s*[ap]\.?m\.?)?\s*\]\s*"), ". "),  # "[10:32] alice: ...": a turn begins
    (re.compile(r"<[a-z][\w.\-]{0,20}>\s*"), ". "),  # "<dana> can u build ..."
    (re.compile(r"(?:^|(?<=[.!?]\s))(?:me|them|you|us|user|assistant|bot|robot|[a-z]+bot)\s*:\s*$"), ""),  # a turn with no words left
    (re.compile(r"(?:^|(?<=[.!?]\s))[a-z][\w.\-]{0,20}(?<!-)>\s+"), ""),  # "alice> blue cube in front of ..."
)
"""A chat transcript's timestamps and speaker tags ("[10:32] alice: ...", "<dana> ...",
"alice> ..."): each turn read as a sentence, its speaker's name then dropped as a label
(:data:`LABEL_RE`)."""

_REPORT_FRAME_WORDS = (r"(?:describes?|described|evaluat(?:e|es|ed|ing)|uses?|used|consider(?:s|ed)?|stud(?:y|ies|ied)|defines?|defined"
                       r"|propos(?:e|es|ed)|reports?|reported|present(?:s|ed)?|introduc(?:e|es|ed)|deliverables?|milestones?|years?"
                       r"|quarters?|months?|sections?|papers?|work|package|phase|period|reporting|policy|policies|benchmarks?"
                       r"|evaluation|project|lab|team|we|our|i|in|on|for|of|the|a|an|this|that|is|was|here|below|following|as)")
"""The words of a report before the task it names ("Deliverable D4 describes the evaluation task, in which ..."): nothing
else may stand there (a frame that reverses, repeats, negates or changes the task, "Reverse the task in which ...", is
not dropped)."""

TASK_FRAME_RES: tuple[re.Pattern, ...] = (
    # the writer's picture of the goal ("Think of a pyramid made of six cubes.", "Picture three towers ...", "I am
    # picturing a tidy table with ...", "What I have in mind is a small tower ...", "For this scene, picture a row ..."):
    # the scene pictured is the goal
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:for\s+(?:this|the)\s+(?:scene|demonstration|demo|task|episode|test|eval(?:uation)?)\s*,\s*)?"
               r"(?:(?:just|now|so)\s+)?(?:think\s+of|imagine|picture|visuali[sz]e|envision)\s+"
               r"(?=(?:a|an|one|two|three|four|five|six|seven|eight|\d+)\s)"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:i\s+am|i'm|we\s+are|we're)\s+(?:picturing|imagining|envisioning|thinking\s+of)\s+"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))what\s+(?:i|we)\s+(?:have\s+in\s+mind|am\s+picturing|are\s+picturing|want|need|would\s+like|are\s+after)"
               r"\s+(?:here\s+)?is\s+"),
    # a purpose said first ("For the demonstration, the pink cube has to ..."): nothing of the goal
    re.compile(r"^for\s+(?:this|the|our|my)\s+(?:scene|demonstration|demo|episode|test|benchmark|eval(?:uation)?|experiment)\s*,\s*"
               r"(?![\s\S]*\bfor\s+(?:this|the|our|my|a)\s+(?:[a-z]+\s+)?(?:scene|demonstration|demo|episode|test|benchmark|eval(?:uation)?"
               r"|experiment|training|run|robot)\b)"),
    # sentences that introduce the task and say nothing of it ("Here is the setup I want to evaluate.", "Let me describe
    # the goal.", "Our lab uses this as a warm-up task.", "The idea is a little sorting exercise.")
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:here\s+is|here's|this\s+is)\s+the\s+(?:setup|set-up|task|scene|goal|layout|configuration)\s+"
               r"(?:i|we)\s+(?:want|would\s+like|need|plan|intend)\s+to\s+(?:evaluate|test|use|run|try|benchmark|check)\s*[.:]\s*"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))let\s+me\s+(?:describe|explain|spell\s+out)\s+(?:the\s+|my\s+|our\s+)?(?:goal|task|scene|setup|target)\s*[.:]\s*"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:we|i|people)\s+use|(?:our|my|the)\s+lab\s+uses)\s+this\s+(?:one\s+)?as\s+an?\s+(?:[\w-]+\s+){0,2}?"
               r"(?:task|test|benchmark|exercise|check|demo)\s*[.:]\s*"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))the\s+idea\s+is\s+an?\s+(?:[\w-]+\s+){0,3}?(?:exercise|task|test|challenge)\s*[.:]\s*"),
    # a student's assignment of a task ("Design a task where the robot must ...", "Design a task with two goals - ...",
    # "Design a task: ..."): the task it describes
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:please\s+)?(?:design|create|write|define|devise|set\s+up|make)\s+(?:a|an|one)\s+(?:new\s+|simple\s+)?"
               r"(?:task|eval(?:uation)?|episode|scenario|benchmark\s+task)\s*(?:with\s+(?:two|2|three|3|several)\s+(?:goals|parts)\s*)?"
               r"(?:where\s+|in\s+which\s+|:\s*|;\s*|-+\s*|\u2014\s*|\u2013\s*)"),
    # a crowd worker's caption of the finished scene ("You should see three gray cubes ...", "The image shows a wall:
    # ...", "In the final picture you will see ..."): the scene described is the goal
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:in\s+the\s+(?:final|last|end|finished|goal)\s+(?:image|picture|photo|frame|scene|snapshot)"
               r"|at\s+the\s+end)\s*,?\s*)?(?:you\s+(?:should|will|would|must)\s+see|you'?ll\s+see|you\s+see|we\s+(?:should\s+)?see"
               r"|(?:the|this|that)\s+(?:final\s+|finished\s+|goal\s+)?(?:image|picture|photo|photograph|frame|snapshot)\s+"
               r"(?:shows|has|contains|depicts|is\s+of))\s*:?\s+"),
    # "The end state requires the gray block to be adjacent to ...", "The scene we want at the end has ...": the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:final|end|desired|goal|target|resulting)\s+(?:state|scene|configuration|layout|arrangement)"
               r"\s+(?:requires|demands|needs)\s+(?:that\s+)?(?![^.!?]*\?)"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))the\s+(?:scene|state|table|configuration|layout)\s+(?:we|i)\s+want\s+at\s+the\s+end\s+"
               r"(?:has|shows|is|contains)\s*:?\s*"),
    # "The final scene should have ...", "The end state you are looking for is ...": the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:final|end|desired|goal|target|resulting)\s+(?:state|scene|configuration|layout"
               r"|arrangement|setup)(?:\s+(?:you\s+are|you're|we\s+are|we're|i\s+am|i'm)\s+looking\s+for)?\s+(?:should\s+|must\s+|will\s+)?"
               r"(?:have|has|shows|show|contains|contain|be|is)\b\s*:?\s*"),  # ("shows" had left its "s" behind)
    # "I would like the table to look like this at the end: ...", "To complete this task, ...": the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:when\s+the\s+robot\s+is\s+(?:finished|done)\s*,\s*)?(?:(?:i|we)\s+(?:would\s+like|want|need)\s+)?"
               r"the\s+(?:table|scene|workspace)\s+(?:should\s+|to\s+|must\s+|will\s+)?look\s+like\s+this(?:\s+at\s+the\s+end)?\s*[:.]\s*"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:in\s+order\s+)?to\s+(?:complete|solve|finish|pass)\s+(?:this|the)\s+(?:task|episode|level)\s*,\s*"),
    # a dotted section number before the text ("5.3 The tower ...")
    re.compile(r"^\s*\d+(?:\.\d+)+\.?\s+(?=[A-Za-z])"),
    # "Deliverable D4 describes the evaluation task, in which the robot builds ...", "In Year 2 we evaluated the policy
    # on a stacking task in which the robot places ...": a report's words before the task it names, which say nothing
    # of cubes, colours or places and deny nothing (they had been refused for 'describes', 'policy')
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:" + _REPORT_FRAME_WORDS + r"|[a-z]*\d[\w\-]*)\s*,?\s+){0,14}?(?:an?|the|our|this)\s+"
               r"(?:(?:" + _REPORT_FRAME_WORDS + r"|[a-z]+ing|[a-z]+-[a-z]+)\s+){0,3}?"
               r"(?:task|benchmark|environment|setting|challenge|scenario|problem)\s*,?\s+(?:in\s+which|where(?:in)?)\s+"
               r"(?=(?:the\s+)?(?:robot|agent|arm|policy)\b)"),
    # "We evaluate a tower-building task in which the policy must ...": the task it names follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:we\s+(?:evaluate|consider|study|use|define|propose)|consider|this\s+is)\s+an?\s+"
               r"(?:[\w-]+\s+){0,3}?(?:task|benchmark|environment|setting)\s+(?:in\s+which|where)\s+"),
    # a user story: "As a tester, I want the robot to place ..., so that I can check ...": the want is the task
    re.compile(r"(?:^|(?<=[.!?;:]\s))as\s+an?\s+[a-z][a-z\s-]{0,30}?,?\s+(?:i|we)\s+(?:want|need|would\s+like)\s+"
               r"(?:(?:the\s+)?(?:robot|agent|policy|arm)\s+to\s+|(?=(?:a|an|the)\s))"),
    re.compile(r"\s*,?\s+so\s+(?:that\s+)?(?:i|we|the\s+\w+(?:\s+check)?)\s+(?:can|could|will|gets?)\s+[^.;!?]*(?=[.;!?]?\s*$)"),
    # "could you set up the task where the black cube goes on ...": the task it describes
    re.compile(r"\b(?:set\s+up|make|create|add|build)\s+(?:the|a|an)\s+(?:task|eval(?:uation)?|episode|benchmark\s+task)\s+"
               r"(?:where|in\s+which|with|so\s+that)\s+"),
    # "Write a plan so that ...", "Compared with the first picture, ...": the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:write|give|find|produce)\s+(?:a|the)\s+(?:plan|program|policy|sequence\s+of\s+(?:actions|moves))"
               r"\s+(?:so\s+that|such\s+that|in\s+which|where)\s+"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))compared\s+(?:with|to)\s+the\s+(?:first|previous|initial|before|starting)\s+(?:image|picture|frame"
               r"|photo|scene|state)\s*,\s*"),
    # "Success requires no particular orientation.": no goal judges a cube's yaw unless it says so
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:success|the\s+goal|it)\s+(?:requires|needs|demands|has)\s+no\s+particular\s+"
               r"(?:orientation|rotation|yaw|heading)\s*[.!]?\s*"),
    # "In this environment, the green cube must ...", "For this benchmark, put ...": the setting a paper names, no content
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:in|for)\s+this\s+(?:task|episode|environment|setting|benchmark|experiment|study|scenario"
               r"|eval(?:uation)?|variant|level)\s*,\s*"),
    # "This tutorial task asks the agent to build ...", "The benchmark requires the robot to ...": what it asks is the task
    # (its own words before "task" are no colour and no number)
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:this|the|our|each)\s+(?:(?:tutorial|simple|easy|basic|new|main|standard|evaluation|eval"
               r"|benchmark|training|test|demo|example|sample|toy|pilot|warm-up|warmup|introductory|practice|baseline)\s+){0,2}?"
               r"(?:task|benchmark|environment|episode|challenge|exercise|test|experiment|scenario)\s+(?:asks|requires|tells|instructs"
               r"|wants|expects|challenges)\s+(?:the\s+)?(?:agent|robot|policy|arm|learner|controller)\s+to\s+"),
    # "In this task(,) the agent must ...", "The policy must ...": the task follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:in\s+this\s+(?:task|episode|environment|setting)\s*,?\s*)?(?:the\s+)?"
               r"(?:agents?|robots?|polic(?:y|ies)|controllers?|learners?|students?|trainees?|participants?|operators?"
               r"|teleoperators?|demonstrators?|players?|models?)\s+(?:must|should|has\s+to|have\s+to|needs?\s+to"
               r"|(?:is|are)\s+(?:required|asked)\s+to)\s+"),
    # "The episode is successful if ...", "the task succeeds when ...", "Success when ...", "Episode ends when ...": the goal
    # follows (an episode ends on success)
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:episode|task|trial|rollout|attempt)\s+(?:is\s+(?:considered\s+|deemed\s+|"
               r"counted\s+as\s+)?(?:successful|a\s+success|solved|completed?)|succeeds|counts\s+as\s+(?:a\s+)?success(?:ful)?"
               r"|(?:ends|terminates|stops|finishes)(?:\s+(?:successfully|with\s+(?:a\s+)?success))?)\s+"
               r"(?:if|when|once|as\s+soon\s+as)\s+"
               r"|(?:^|(?<=[.!?;:]\s))(?:end|terminate|stop)\s+(?:the\s+)?(?:episode|task|trial|rollout|run)\s+"
               r"(?:successfully\s+)?(?:when|once|as\s+soon\s+as)\s+"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:episode\s+)?success(?:\s+(?:condition|criterion))?\s*(?:(?:is\s+(?:achieved\s+|reached\s+)?)?"
               r"(?:when|if|once)\s+|:=\s*|=\s*)"),
    # a config comment's "done when ...", "reward = 1 iff ...", "returns True if ...": the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:it's|it\s+is|we're|we\s+are|task\s+is|episode\s+is)\s+)?(?:done|finished|complete|solved)"
               r"\s+(?:when|if|once|iff)\s+"
               r"|(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:reward|score|r)\s*(?:=|is|==)\s*(?:1(?:\.0)?|one|\+1)\s+(?:iff|if|when|once)\s+"
               r"|(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:success\s+)?reward\s+(?:fires|triggers|is\s+(?:given|granted|paid)|pays\s+out)\s+(?:only\s+)?"
               r"(?:iff|if|when|once)\s+"
               r"|(?:^|(?<=[.!?;:]\s))(?:(?:it|the\s+check|the\s+predicate|is_success(?:\(\))?)\s+)?returns?\s+true\s+(?:iff|if|when)\s+"),
    # "Success is judged on the final configuration only.": every goal is
    re.compile(r"(?:^|(?<=[.!?;:]\s))success\s+is\s+(?:judged|checked|measured|evaluated|determined|assessed)\s+(?:on|by|at|from)\s+"
               r"(?:the\s+)?(?:final|end|last)\s+(?:configuration|state|scene|frame|arrangement)(?:\s+only)?\s*[.!]?\s*"),
    # "In the final image, ...", "After the robot acts, ...": an annotator's after-image is the goal
    re.compile(r"(?:^|(?<=[.!?;:]\s))in\s+the\s+(?:final|last|end|after|resulting|goal|target)\s+(?:image|frame|picture|photo|snapshot"
               r"|shot|scene|state)\s*,?\s*"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))after\s+the\s+(?:robot|agent|policy|arm)\s+(?:acts|is\s+done|finishes|has\s+(?:acted|finished))"
               r"\s*,\s*"),
    # a voice assistant's wake word and a request passed on ("Alexa, tell the robot to ...", "ask the arm to ...",
    # "have the robot ...", "watch it line up ..."): the request is the task
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:alexa|siri|hey\s+google|ok(?:ay)?\s+google|hey\s+robot|computer)\s*,\s*)?"
               r"(?:(?:please\s+)?(?:tell|ask|instruct|command|get)\s+(?:the\s+)?(?:robot|arm|agent|policy)\s+to\s+"
               r"|(?:please\s+)?(?:have|let)\s+(?:the\s+)?(?:robot(?:ic)?\s+)?(?:robot|arm|agent|policy|gripper|manipulator)\s+(?=[a-z]+\s)"
               r"|(?:now\s+)?watch\s+(?:it|the\s+robot|the\s+arm|me)\s+(?=[a-z]+\s))"),
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:alexa|siri|hey\s+google|ok(?:ay)?\s+google|(?:hey|hi|hello|ok(?:ay)?)\s+(?:robot|bot))\s*,\s*"),
    # "Is necessary to make ..." (a Spanish "es necesario"), "it is required that ...": the task follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:it\s+)?(?:is|'s)\s+(?:necessary|required|needed|essential|mandatory)\s+(?:to|that)\s+"),
    # an annotator's caption of what an arm did ("The arm moved the green block ...", "the gripper stacked ... and then
    # stopped"): the end state it describes, said of the robot; stopping afterwards says nothing of the cubes
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:robot(?:ic)?\s+)?(?:arm|gripper|manipulator|end[- ]effector)\s+(?=[a-z]+ed\b)"),
    re.compile(r"\s*,?\s+(?:and\s+)?(?:then\s+)?(?:it\s+)?(?:stopped|halted|was\s+done|went\s+(?:home|back\s+home)|returned\s+home)\s*[.!]?\s*$"),
    # a rulebook's or game's scoring ("A team scores when its red cube rests on ...", "You win when ..."): the goal follows
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:(?:a|the|each)\s+)?(?:team|player|robot|agent|policy|you|we)\s+(?:scores?|wins?|passes|succeeds?)"
               r"(?:\s+(?:a|one|the)\s+(?:point|round|level|game))?\s+(?:only\s+)?(?:when|if|once)\s+(?:(?:its|their|your|our)\s+(?=\w+\s+(?:block|cube)))?"),
    # "By the end of the exercise(,) ...", "at the end of the episode": every goal is checked then
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:by|at)\s+the\s+end\s+of\s+the\s+(?:exercise|episode|task|trial|run|rollout|lesson|lab|session"
               r"|demo|game|round|level)\s*,?\s*"),
    # an acceptance criterion in given/when/then form whose "when" is the end of the run: the "then" is the goal
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:given\s+[^,;.]{1,60},\s*)?when\s+(?:the\s+)?(?:task|episode|robot|policy|agent|run|trial"
               r"|rollout)\s+(?:finishes|ends|is\s+(?:done|finished|over|complete))\s*,?\s*(?:then\s+)?"),
    # "The final structure shall be a three-level tower ...": the structure said is the goal
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:final|end|goal|target|resulting)\s+(?:structure|configuration|arrangement|state|scene"
               r"|result|layout)\s+(?:shall|should|must|will|has\s+to|is\s+to)\s+be\s+(?=(?:a|an|one)\s)"),
    # a labelled heading ("Task T3 (Year 2 milestone):", "Episode goal (from the dataset card):", "Proposal (#212):"):
    # what it heads is the task
    re.compile(r"^\s*(?:(?:new|proposed)\s+)?(?:proposal|task|episode(?:\s+goal)?|goal|acceptance\s+criteri(?:a|on)|requirement|"
               r"spec(?:ification)?|ticket|item|entry|milestone|deliverable)\b"
               r"(?:(?!\b(?:towers?|stacks?|rows?|lines?|walls?|pyramids?|grids?|circles?|piles?|columns?)\b)[^:()\n]){0,30}"
               r"(?:\([^)\n]{0,60}\))?\s*:\s*"),  # (a structure word before the colon is the task's: "Task 5 - wall: ...")
    # "new eval task "letters in order", cubes ...": the task's name, then the task
    re.compile(r"(?:^|(?<=[.!?;:]\s))(?:a\s+)?(?:new\s+)?(?:eval(?:uation)?\s+|benchmark\s+)?task\s+(?:called\s+|named\s+)?"
               r"(?:\"[^\"\n]{1,40}\"|'[^'\n]{1,40}'|\u201c[^\u201d\n]{1,40}\u201d)\s*[,:]\s*"),
    # "... Ship it.": a reviewer's sign-off says nothing of the cubes
    re.compile(r"(?:^|(?<=[.!?;]))\s*(?:ship\s+it|lgtm|merge\s+it)\s*[.!]*\s*$"),
    # "Before: cubes scattered. After: ...": a start scattered at random is every task's
    re.compile(r"(?:^|(?<=[.!?;:]\s))before\s*:\s*[^.;]*?\b(?:scattered|random(?:ly\s+placed)?|messy|mixed|jumbled|spread\s+out)\b"
               r"[^.;]*[.;]\s*(?:after\s*:\s*)?"),
)
"""How a paper, a benchmark or an annotator frames the goal ("In this task the agent must ...",
"The episode is successful if ...", "Success when ...", "In the final image, ...", "Before:
cubes scattered. After: ..."): the words are dropped and what they frame is read as the goal
(every goal is checked at the end of the episode, from a scattered start; paper Sec. 3)."""


EMOJI_RE = re.compile(r"[\U0001F000-\U0001FAFF\u2600-\u27BF\u2B00-\u2BFF\uFE0F\u200D]+")
"""Emoji and pictographs ("\U0001F525 TOWER TIME", "Them: \U0001F44D"): they say nothing the domain can
check, and are removed before reading."""

SHOUTING_MIN_SHARE = 0.8
"""The share of a text's letters in capitals (of at least :data:`SHOUTING_MIN_LETTERS`) from
which it is read as shouted ("PUT THE 7 CUBE ON THE 2 CUBE!!!!"): its words of two or more
letters are lower-cased (single letters stay letter cubes; a word after "spell" or "read"
stays a spelled word)."""

SHOUTING_MIN_LETTERS = 12

EXCLAIMED_SENTENCE_RE = re.compile(r"(?:^|(?<=[.!?]\s))[^.!?]*!+(?=\s|$)")
"""A sentence ending with "!" (a teacher's or puzzle writer's aside: "What a tower!", "Good luck!", "They need some
space!"); dropped by :func:`rpg.schema.reading.drop_asides` when no word of it says anything of a goal
(:data:`ASIDE_CONTENT_RE`) nor anything the domain cannot express."""

ASIDE_CONTENT_RE = re.compile(
    rf"(?i)\b(?:{COLOR_RE}|grey|\d+|one|two|three|four|five|six|seven|eight|nine|ten|{'|'.join(PLACEMENT_VERBS)}|spell|sort|line|order"
    r"|left|right|front|back|rear|behind|between|next|near|beside|far|top|bottom|middle|cent(?:er|re)|corners?|patch(?:es)?"
    r"|under|above|below|table|letters?|digits?|numbers?|each|every|all|both|not|no|never|if|when|only|instead)\b")
"""Words that make an exclaimed sentence part of the task: a colour, a count, a placement verb, a place or relation,
a label, a quantifier, a negation, a condition."""


FILLER_RE = re.compile(r"(?i)(?:^|(?<=[.!?]\s))(?:prego|allora|ecco|dai|senti|god\s+willing|inshallah|insha'?allah|yalla|omg|lol"
                       r"|yo|hey\s+there|alright\s+then|okay\s+so|ok\s+so|aigoo|jeez|arre+y?|arey|do\s+one\s+thing)\b\s*[,!.]*\s*"  # ("Your": no "yo")
                       r"|(?:^|(?<=[.!?;]\s))(?:look|listen|hey\s+look)\s*,\s*(?=\S)"
                       # "Relax and put the pink cube on ...": a word to the listener before the task
                       r"|(?:^|(?<=[.!?;]\s))(?:relax|chill(?:\s+out)?|breathe|take\s+a\s+(?:deep\s+)?breath)\s*,?\s+and\s+(?=(?:just\s+)?(?:put|place"
                       r"|set|move|stack|build|make|line|arrange)\b)"
                       r"|(?:^|(?<=[.!?;]\s))(?:separately|independently|additionally|in\s+addition|besides|furthermore|moreover"
                       r"|on\s+top\s+of\s+that|apart\s+from\s+that|as\s+a\s+second\s+(?:part|step))\s*,\s*"
                       r"|\b(?:(?:in\s+the\s+)?same\s+way)\s+(?=(?:put|place|keep|move|set)\b)"
                       r"|,?\s*\b(?:va\s+bene|capisci|ok\?|okay\?|right\?|yeah\?)\s*(?=[.!?]*\s*$)"
                       r"|,?\s*\bof\s+course\b\s*,?"
                       r"|(?:^|(?<=[.!?]\s))(?:take\s+your\s+time|no\s+rush|no\s+hurry|there'?s\s+no\s+rush)\s*[.!]*\s*"
                       r"|\s+for\s+(?:the|our|my|this|a)\s+(?:new\s+|latest\s+|current\s+|next\s+)?(?:policy|policies|model|agent|baseline)"
                       r"(?=\s*[.!:])")
"""Interjections said around a task in several languages' habits ("Prego, ...", "Allora, ...",
"..., va bene?", "God willing, ...", "omg"), a sentence's opening that only joins it to the
one before ("Separately, put ...", "In addition, ..."; every sentence of a goal holds together), a pace nobody checks
("Take your time.": a task's goal is judged at the episode's end) and who the task is for ("Corner task for the new
policy."): dropped."""

DISFLUENCY_RE = re.compile(r"(?i)(?P<lead>\s*,)?\s*\b(?!(?-i:[A-Z]{2,})\b)(?:uh+m?|um+|erm*|uhm+|hmm+|mmm+)\b(?!\s*,?\s*no\b)\s*(?P<trail>,)?(?=\s|$)")
"""A speaker's hesitation in a transcript ("put the uh orange cube"): dropped.  A hesitation between
two commas is a pause, dropped with them ("the top one, er, pink": the top one pink), unless a
list item comes before it ("red, um, blue": the list's comma stays; "the top one" is no list item)."""

PAUSE_FILLER_RE = re.compile(r"(?i)\s*,\s*(?:like|you\s+know|i\s+guess|basically|kinda|sort\s+of)\s*,")
"""A filler between two pauses ("reverse that, like, green first", "the top one, you know, red"): the pauses
are one comma.  Only between commas: "a tower like the first one" compares."""

HYPHENED_DIRECTION_RE = re.compile(r"(?i)\b(left|right|front|back|bottom|top)-to-(left|right|front|back|bottom|top)\b")
"""A direction written with hyphens ("right-to-left", "bottom-to-top"): its words apart, as the readers read it
(the direction had been dropped, a sort read left to right)."""

_SIDE_REL = r"(?:to\s+the\s+(?:left|right)\s+of|(?:on\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|behind)"
DIAGONAL_PLACE_RE = re.compile(
    r"(?i)\b(?:diagonally\s+)?(?:(?:to|at|on)\s+the\s+)?(?:(?P<depth>front|back|rear)[\s-]+(?P<side>left|right)"
    r"|(?P<side2>left|right)[\s-]+(?P<depth2>front|back|rear))\s+(?:side\s+)?of\s+"
    rf"(?=(?:the\s+)?(?:(?:{COLOR_RE}|grey)\b(?!\s+(?:goal\s+|target\s+)?patch)|it\b|(?-i:[A-Z0-9])\b"
    r"|(?:cube|block|letter|digit|number)\s+(?-i:[A-Z0-9])\b))"
    rf"|\bdiagonally\s+(?={_SIDE_REL}\s+(?:and|,)\s+{_SIDE_REL}\s)")
"""A cube placed diagonally from another, by a corner's name ("to the front-right of the red cube", "diagonally back
left of it") or by two relations of both axes said together ("diagonally in front of and to the right of the red
cube"): written as the two relations, which hold together as a diagonal pair (:class:`rpg.domain.predicates._Relation`;
"diagonally" had been refused as a pose, the corner's name as a diagonal the relations lack).  A map's "top left of"
stays refused (above, or behind?); "diagonally" alone ("diagonally behind the red cube": on which side?) too."""


DIAGONAL_SIDE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "diagonally behind the yellow cube, off to its right": behind it and to its right
    (re.compile(r"(?i)\bdiagonally\s+(?=(?:behind|in\s+front\s+of)\s+(?:the\s+)?[a-z]+(?:\s+(?:cube|block|one))?\s*,?\s+(?:and\s+)?(?:off\s+)?"
                r"to\s+(?:its|the)\s+(?:left|right)\b)"), ""),
    (re.compile(r"(?i)(\b(?:behind|in\s+front\s+of)\s+(?:the\s+)?[a-z]+(?:\s+(?:cube|block|one))?)\s*,\s*off\s+(to\s+its\s+(?:left|right))\b"),
     r"\1 and \2"),
)
"""A diagonal placement said by its depth and then its side ("diagonally behind the yellow cube, off to its right"): the
two relations of one pair, as :data:`DIAGONAL_PLACE_RE` writes them ('diagonally' had been refused as a pose)."""


def diagonal_place(m: re.Match) -> str:
    """The two relations of :data:`DIAGONAL_PLACE_RE`'s match; as written after a cube said by no colour or label ("move
    the cube to the front-right of the blue cube onto ...": a cube picked by its place, refused)."""
    if re.search(r"(?i)\b(?:the|a|an|any|that)\s+(?:cube|block|one)\s+$", m.string[:m.start()]):
        return m.group(0)
    depth, side = m.group("depth") or m.group("depth2"), m.group("side") or m.group("side2")
    if depth is None:
        return ""  # "diagonally" before two relations said together: the two relations say it
    return f"{'in front of' if depth.lower() == 'front' else 'behind'} and to the {side.lower()} of "


_HEADING = r"(?:goes|going|go|moves|moving|runs|running|leads|leading|stretch(?:es|ing)?|heads|heading|extends|extending|points|pointing|travels|travell?ing|reaches|reaching)"
ROBOT_DIRECTION_RE = re.compile(
    r"(?i)\b(?:(?P<column>column)|(?P<line>row|line|file))\b(?P<mid>\s+of\s+[^.;:!?,]{0,50}?)?\s*,?\s*"
    rf"(?:(?:that\s+|which\s+)?(?P<verb>{_HEADING})\s+(?:straight\s+)?)?(?P<dir>away\s+from|toward|towards)\s+(?:the\s+|our\s+|your\s+)?robot\b")
"""A column or row said to run away from the robot or toward it ("four yellow cubes in a column, moving away from the
robot", "a row of cubes going toward the robot"): a line from front to back (or back to front), on the table; a column
had been read as a tower standing in the back half.  A row or line needs the verb of its running ("a row of three white
cubes away from the robot" may name the far half, and is left to the region reading)."""


_VERTICAL_CUE_RE = re.compile(r"(?i)\b(?:stack\w*|towers?|tops?|bottom|base|rest\w*|above|below|under\w*|up|tall|high|vertical\w*"
                              r"|upright|closest|nearest|farthest|furthest|first|last|it|then)\b")
"""Words that keep a column upright, or order it by other words, in the sentence of :data:`ROBOT_DIRECTION_RE` ("a column
of three cubes heading away from the robot, red at the bottom", "green closest"): it is left as written."""


def robot_direction(m: re.Match) -> str:
    """:data:`ROBOT_DIRECTION_RE`'s match as a line with its direction."""
    start = max(m.string.rfind(".", 0, m.start()), m.string.rfind(";", 0, m.start())) + 1
    stop = min([i for i in (m.string.find(".", m.end()), m.string.find(";", m.end())) if i >= 0] or [len(m.string)])
    if re.match(r"\s*:", m.string[m.end():stop]):  # "a row moving away from the robot: pink, then yellow, then white":
        stop = m.end()  # the list after the colon is the line's order from that end ("then" had left it as written,
        # an unordered line in the back half: silently wrong)
    if (m.group("line") and not m.group("verb")) or _VERTICAL_CUE_RE.search(m.string[start:stop]):
        return m.group(0)
    way = "from front to back" if m.group("dir").lower().startswith("away") else "from back to front"
    mid = m.group("mid") or ""
    return f"line{mid} {way}" if m.group("column") else f"{m.group('line')}{mid} {way}"


LINE_UP_DIRECTION_RE = re.compile(
    rf"(?i)\b(?P<verb>line\s+up|lined\s+up|lining\s+up)\b(?P<mid>\s+[^.;:!?]{{1,60}}?)\s*,?\s*(?:{_HEADING})\s+(?:straight\s+)?"
    r"(?P<dir>away\s+from|toward|towards)\s+(?:the\s+|our\s+|your\s+)?robot\b")
"""Cubes lined up running away from the robot or toward it ("line up the pink, cyan and white cubes going away from the
robot"): a line from front to back (or back to front); the robot's words had been read as the back of the table, an
unordered line there (silently wrong).  Left as written where the sentence stacks or orders by other words."""


def line_up_direction(m: re.Match) -> str:
    """:data:`LINE_UP_DIRECTION_RE`'s match as a line with its direction."""
    stop = min([i for i in (m.string.find(".", m.end()), m.string.find(";", m.end())) if i >= 0] or [len(m.string)])
    if not re.match(r"\s*:", m.string[m.end():stop]) and _VERTICAL_CUE_RE.search(m.string[m.end("verb"):stop]):
        return m.group(0)
    way = "from front to back" if m.group("dir").lower().startswith("away") else "from back to front"
    return f"{m.group('verb')}{m.group('mid')} in a line {way}"


_STRUCTURE_NOUN = r"(?:tower|stack|row|line|pile|column|circle|ring|grid|wall|pyramid)"
ANOTHER_STRUCTURE_RE = re.compile(rf"\b(?:another|an?\s+(?:separate|distinct|different|other))\s+(?:one|(?P<noun>{_STRUCTURE_NOUN}))\s+(?=of\b)")
"""A second structure said as "another one of ...", "another tower of ..." or "a separate pile of ..." after a first ("build a tower of red, blue
and green and another one of yellow, pink and white"): written "a tower of ..." as the first is (the two towers had
been read as one tower of six cubes); see :func:`another_structure`."""


def another_structure(m: re.Match) -> str:
    """``a <noun> `` for :data:`ANOTHER_STRUCTURE_RE`'s match, the noun the one said before it (as written where none
    is said before)."""
    said = list(re.finditer(rf"\b(?:a|one)\s+(?:[a-z\-]+\s+){{0,2}}?({_STRUCTURE_NOUN})\s+of\b", m.string[:m.start()]))
    noun = m.group("noun") or (said[-1].group(1) if said else None)
    return f"a {noun} " if said and noun else m.group(0)


_CHAIN_REL = r"(?:on|onto|upon|over|atop|above|on-top-of|ontop|under|below|beneath)"
HYPHENED_RELATION_RE = re.compile(rf"(?i)(?<!\w)([a-z]+|\d)\s*[-\u2013\u2014]\s*({_CHAIN_REL})\s*[-\u2013\u2014]\s*(?=([a-z]+|\d)(?![\w]))")
"""A tower's cubes said as one hyphenated word ("a red-on-yellow tower", "green-on-blue-on-red", "red - on - yellow", a
typo "red-on-yelow", digit cubes "1-on-2"): its words apart, as the readers read "red on yellow" (it had been read as a
list, bottom up: red under yellow); see :func:`hyphened_relation`."""


COUNTED_TOWER_SAID_RE = re.compile(
    rf"(?i)\b(a|an|one|the)\s+([1-9]\d*|two|three|four|five|six)[-\s](?:block|cube)s?\s+((?:{COLOR_RE})(?:\s+(?:on|onto|upon|over|atop|on\s+top\s+of|under|below|beneath)"
    rf"\s+(?:{COLOR_RE}))*)\s+(tower|stack|column)\b")
"""A tower's count and its colour or chain said before its noun ("a three-block red-on-yellow tower", "a 3-block red
tower"): read as "a 3 block tower of red on yellow", whose count the readers check against the chain (it had been
dropped: a tower of two, or no task)."""

DIGIT_CHAIN_TOWER_RE = re.compile(r"(?i)\b(?:a|an|the)\s+(\d(?:\s*[-\u2013]?\s*(?:on|onto|upon|over|atop|on-top-of)\s*[-\u2013]?\s*\d)+)\s+(tower|stack|column)\b")
"""A tower of digit cubes said as a chain before its noun ("a 1-on-2 tower", "a 3 on 1 on 2 stack"): read as "a tower of
the 1 cube on the 2 cube" (the labels had been dropped: a tower of two made-up cubes); see :func:`digit_chain_tower`."""


def digit_chain_tower(m: re.Match) -> str:
    digits = re.findall(r"\d", m.group(1))
    return f"a {m.group(2)} of " + " on ".join(f"the {d} cube" for d in digits)


def hyphened_chains(text: str) -> str:
    """``text`` with towers said as hyphened chains written as words (:data:`HYPHENED_RELATION_RE`, one hyphen left out
    or a zero-width joiner too: "red on-yellow", "red\u2060-on-yellow"), digit chains before a tower's noun
    (:data:`DIGIT_CHAIN_TOWER_RE`) and a count before a chained tower (:data:`COUNTED_TOWER_SAID_RE`)."""
    text = re.sub(r"[\u2060\u200b\u200c\u200d]", "", text)
    def joined(m: re.Match) -> str:  # "red on-yellow", "red-on yellow": both hyphens, when both ends name cubes
        return f"{m.group(1)}-{m.group(2)}-" if _cube_word(m.group(1)) and _cube_word(m.group(3)) else m.group(0)

    text = re.sub(rf"(?i)\b([a-z]+|\d)\s+({_CHAIN_REL})\s*[-\u2013\u2014]\s*(?=([a-z]+|\d)\b)", joined, text)
    text = re.sub(rf"(?i)\b([a-z]+|\d)\s*[-\u2013\u2014]\s*({_CHAIN_REL})\s+(?=([a-z]+|\d)\b)", joined, text)
    text = HYPHENED_RELATION_RE.sub(hyphened_relation, text)
    text = DIGIT_CHAIN_TOWER_RE.sub(digit_chain_tower, text)
    return COUNTED_TOWER_SAID_RE.sub(r"\1 \2 block \4 of \3", text)


def _cube_word(w: str) -> bool:
    """Whether ``w`` names a cube in a chain: a digit, a colour or a colour's misspelling."""
    import difflib

    return w.isdigit() or w.lower() in COLORS or bool(difflib.get_close_matches(w.lower(), COLORS, n=1, cutoff=0.8))


def hyphened_relation(m: re.Match) -> str:
    """The words of :data:`HYPHENED_RELATION_RE`'s match apart, when both ends are cubes' names (:func:`_cube_word`);
    the match as written otherwise."""
    if not (_cube_word(m.group(1)) and _cube_word(m.group(3))):
        return m.group(0)
    if m.group(1).isdigit() or m.group(3).isdigit():  # "a 1-on-2 tower": digit cubes, read by DIGIT_CHAIN_TOWER_RE
        return m.group(0)
    return f"{m.group(1)} {m.group(2).lower().replace('-', ' ').replace('ontop', 'on top of')} "

_CHAIN_WORDS = rf"(?:{COLOR_RE})\s+(?:on|on\s+top\s+of|atop|over|under|below|beneath)\s+(?:the\s+)?(?:{COLOR_RE})"
A_TOWER_RE = re.compile(rf"\b(?:a|an|one|another|second)\s+(?:{_CHAIN_WORDS}(?:\s+(?:on|under)\s+(?:{COLOR_RE}))*\s+(?:tower|stack|column)"
                        rf"|(?:tower|stack|column)\s+of\s+{_CHAIN_WORDS})\b")
"""A tower said as one of its own by its chain ("a red on yellow tower", "another tower of blue on red"): each asks for a
tower of its own."""


TABLE_SAID_RE = re.compile(
    rf"\b(?:(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?|(?P<p>it|them))\s+(?:(?:must|should|will|has\s+to|needs\s+to|to)\s+)?"
    r"(?:(?:be|end\s+up|ends\s+up|ends?|finish(?:es)?|stay|stays|go|goes|sit|sits|lie|lies|rest|rests|placed|is|back|down|directly|flat)\s+)*"
    r"(?:on|onto)\s+the\s+table\b"
    r"|(?P<q>(?:\band|,)\s+(?:(?:then|finally|afterwards|later|after\s+that)\s+)?(?:back\s+|down\s+)?)(?:on|onto)\s+the\s+table\b")
"""A cube said to end on the table ("put red on the table", "the red cube must end up on the table", "put it on the table":
``p``, a pronoun): where the goal stacks every cube of that colour (of a pronoun: any cube) on another, the words contradict each other (refused by the relational reader); where the
start stacks it, the goal takes it off (:func:`rpg.schema.readers.initial.attach`)."""

ARROW_DIRECTIONS: dict[tuple[str, str], str] = {
    ("l", "r"): "left to right", ("r", "l"): "right to left", ("f", "b"): "front to back", ("b", "f"): "back to front",
    ("b", "t"): "bottom to top", ("t", "b"): "top to bottom",
}
"""A direction written as an arrow between the two ends' initials ("l->r", "L->R", "b->t", "t -> b") or words
("left->right", "bottom -> top"): its two ends by their initials (a "b" is bottom beside "t", back beside "f")."""

ARROW_DIRECTION_RE = re.compile(r"(?i)(?<![\w-])(left|right|front|back|bottom|top|[lrfbt])\s*(?:->|\u2192|=>|-+>)\s*"
                                r"(left|right|front|back|bottom|top|[lrfbt])(?![\w-])")
"""An arrow between two ends (:data:`ARROW_DIRECTIONS`); read by :func:`arrow_direction`."""


def arrow_direction(m: re.Match) -> str:
    """The words of a direction written as an arrow (``"l->r"``: "left to right"); the arrow as it was where its
    ends name no direction ("t->t")."""
    return ARROW_DIRECTIONS.get((m.group(1)[0].lower(), m.group(2)[0].lower()), m.group(0))


MEASURE_WORD_RE = re.compile(rf"(?i)\b(\d+|{'|'.join(w for w in ('two', 'three', 'four', 'five', 'six', 'seven', 'eight', 'nine', 'ten'))})"
                             rf"\s+(?:piece|pieces|pcs?|units?|nos?\.?)\s+(?:of\s+)?(?:(?P<c>{COLOR_RE})\s+)?(?P<n>cubes?|blocks?)\b")
"""A count with a measure word (a literal translation of Chinese "3 ge" or a parts list's "pcs": "3 piece green cube",
"4 pcs of red blocks"): that many cubes, read as "3 green cubes" (the count had reached one cube)."""

_NAMED_TOWER_CUBE = rf"(?:the\s+)?(?:{COLOR_RE}|grey)(?:\s+(?:cube|block))?"
NAMED_TOWER_LIST_RE = re.compile(
    r"(?i)\b(?:(?:tower|stack|column)\s+(?:[A-H]|[1-9]|one|two|three|four)|(?:the\s+)?(?:first|second|third|fourth|1st|2nd|3rd|4th"
    r"|other|next|last)\s+(?:tower|stack|column))\b\s*,?\s*(?:\(\s*)?(?P<dir>(?:listed\s+)?(?:from\s+)?(?:bottom\s+to\s+top|top\s+to\s+bottom"
    r"|bottom\s+up|top\s+down))?\s*\)?\s*[:=]\s*"
    rf"(?P<list>{_NAMED_TOWER_CUBE}(?:\s*(?:,\s*(?:and\s+|then\s+)?|\s+and\s+|\s+then\s+)\s*{_NAMED_TOWER_CUBE})+)"
    r"(?:\s*\(\s*(?P<dir2>(?:listed\s+)?(?:from\s+)?(?:bottom\s+to\s+top|top\s+to\s+bottom|bottom\s+up|top\s+down))\s*\))?\s*(?=[.;]|$)")
"""A tower named by a letter, a digit or an ordinal with its cubes listed ("Tower A: orange, purple.", "Tower two, bottom
to top: cyan, brown, red.", "Second tower: ..."): two or more in a text are each a tower of their own
(:func:`named_towers_listed`)."""


def named_towers_listed(text: str) -> str:
    """Two or more towers each named and listed (:data:`NAMED_TOWER_LIST_RE`: "Tower A: orange, purple. Tower B: cyan, brown,
    red.") -> one sentence per tower ("Build a tower of orange and purple. Build another tower of cyan, brown and red."; with
    its direction said, "Build a tower: purple on orange."): the lists had been read as one tower of all the cubes,
    silently.  A list without its direction leaves the tower's order free, as it is said; one named tower stays as written."""
    found = list(NAMED_TOWER_LIST_RE.finditer(text))
    if len(found) < 2:
        return text

    def tower(i: int, m: re.Match) -> str:
        cubes = [re.sub(r"(?i)^the\s+|\s+(?:cube|block)$", "", c.strip()) for c in
                 re.split(r"(?i)\s*,\s*(?:and\s+|then\s+)?|\s+and\s+|\s+then\s+", m.group("list")) if c.strip()]
        head = "Build a tower" if i == 0 else "Build another tower"
        said = m.group("dir") or m.group("dir2")
        if not said:
            return f"{head} of {', '.join(cubes[:-1])} and {cubes[-1]}"
        bottom_up = re.search(r"(?i)bottom\s+(?:to\s+top|up)", said)
        return f"{head}: " + " on ".join(cubes[::-1] if bottom_up else cubes)

    for i, m in reversed(list(enumerate(found))):
        text = text[:m.start()] + tower(i, m) + text[m.end():]
    return text


STRUCTURE_NAME_RE = re.compile(r"\b((?:[Tt]ower|[Ss]tack|[Rr]ow|[Pp]ile|[Ll]ine|[Cc]olumn|[Ww]all|[Ss]cenario|[Ss]etup)s?)\s+"
                               r"(?:[A-H]|[1-9])\b(?!['\-])(?=\s*(?::|=|\(|\s-\s|\s+is\b|\s+has\b|\s+should\b))")
"""A structure or scenario named by a letter or a digit ("Tower A: yellow, brown", "tower B is pink on gray", "scenario C:"):
the name dropped (the letter had been read as a letter cube, the digit as a count)."""

ORDINAL_ABBREVIATIONS: dict[str, str] = {"1st": "first", "2nd": "second", "3rd": "third", "4th": "fourth", "5th": "fifth",
                                         "6th": "sixth", "7th": "seventh", "8th": "eighth", "9th": "ninth", "10th": "tenth"}
ORDINAL_ABBREVIATION_RE = re.compile(r"(?i)(?<![\w.])(" + "|".join(ORDINAL_ABBREVIATIONS) + r")(?=\s*[=:])")
"""An ordinal written with its digit as a role before "=" or ":" ("bottom=pink, 2nd=gray"), read as its word
("second"), which the role readers read (the tokenizer had split "2nd" into a count and an unknown "nd"; "tower:
bottom=pink, 2nd=gray, 3rd=cyan, top=red" had become a tower of pink and red, its middle dropped silently).  Elsewhere
("Stack: 1st blue, 3rd red, 2nd green", "the 2nd patch") it stays unread and refused: a hostile helper found the
ordinal words' readers there read ranks out of order or a patch by rank, silently."""

GLUED_COUNT_RE = re.compile(r"(?i)\b(stacks?|towers?|piles?|rows?|lines?|walls?|grids?|pyramids?|circles?)((?:-[a-z]+)*)-(\d+)\b")
"""A structure's identifier with a count glued on ("stack-any-4", "pile-5"): the words and the count
written apart, so the count is read, or refused, as a count (a stack of two had been made up)."""

HESITANT_COLOUR_RE = re.compile(rf"(?i)\b(?P<det>the|a|an)\s+(?:{COLOR_RE})\s*,?\s*(?:uh+m?|um+|erm*|uhm+)\s*,?\s*"
                                rf"(?P<c>{COLOR_RE})(?P<noun>\s+(?:cube|block|one|brick))\b(?!s)")
"""One cube named by two colours with a hesitation between ("put the red, er, orange cube on ..."): the
second colour is the one meant (both cubes had been kept)."""


def dropped_hesitation(m: re.Match) -> str:
    """What :data:`DISFLUENCY_RE`'s match ``m`` leaves: a list's comma, or nothing."""
    if not m.group("lead"):
        return ""
    if not m.group("trail"):
        return m.group("lead")
    before = re.search(r"([A-Za-z0-9]+)\W*$", m.string[:m.start()])
    listed = before is not None and (before.group(1).lower() in COLORS or before.group(1).isdigit()
                                     or (before.group(1).lower() in NUMBER_WORDS and before.group(1).lower() != "one")
                                     or len(before.group(1)) == 1)
    return "," if listed else ""

STUTTER_RE = re.compile(r"(?i)\b(?P<run>(?:[a-z']{2,}\s+){0,2}[a-z']{2,})\s+(?P=run)\b")
"""Words of two letters or more said twice in a row in a transcript ("the the", "on the on the", "and then and then",
"stack stack"): said once ("B O O K" spells a word).  :func:`rpg.schema.reading.normalize_words` leaves a run with a colour or
a number alone unless it opens with an article ("the blue the blue cube": a stutter; "blue blue" may
be two cubes)."""

SPELLED_ALOUD_RE = re.compile(r"\b(?P<letters>(?-i:[A-Z])(?:\s+(?-i:[A-Z])){1,9})\s+(?P<word>[A-Za-z]{2,10})\b")
"""A word spelled letter by letter and then said ("D O G dog"): the letters, the word said once
(:func:`rpg.schema.reading.normalize_words` drops the word when it is the letters joined)."""

SPOKEN_ECHO_RE = re.compile(r"(?i)\s*,?\s*\b(?:yeah|yes|yep|yup)\b\s*,?\s+(?:right\s+|just\s+)?(?P<rel>behind|in\s+front\s+of|on\s+top\s+of|onto|on"
                            r"|next\s+to|beside|under|(?:to\s+the\s+)?(?:left|right)\s+of)\s+(?:it|that\s+one)\s*[.!]?\s*$")
"""A speaker confirming what was just said ("put the green cube behind the blue cube yeah behind it"):
dropped when the relation was said before it."""

SAY_LETTERS_RE = re.compile(r"(?i)\b(?:to\s+)?(?:say|show|write|read)\s+(?=(?-i:[A-Z])(?:\s+(?-i:[A-Z]))+\b|(?-i:[A-Z]{2,})\b)")
"""Letter cubes made to "say" or "show" a word ("line up the letter cubes to say D O G"): to spell it."""

SPOKEN_CORRECTION_RE = re.compile(
    r"(?i)(?<=[a-z])\s+(?=(?:no\s+)?i\s+mean\b|no\s+wait\b|no\s+(?:the|a|an|on|onto|in|into|next|behind|to|at)\b)")
"""A correction spoken without a pause ("on the purple patch no I mean the pink patch", "the orange no
the purple cube"): a comma is put before it, so :data:`SELF_CORRECTION_RE` reads it ("no" only before
an article or a place word: "no blue cubes" stays a negation)."""

GRADING_FRAME_RES: tuple[re.Pattern, ...] = (
    # a puzzle card's trailers that ask nothing of the goal ("Bonus: none.", "Time: unlimited.", "Difficulty: easy.")
    re.compile(r"(?i)(?:^|(?<=[.!?;]\s))(?:bonus|extra|hint|par|time(?:\s+limit)?|difficulty|level\s+of\s+difficulty)\s*:\s*"
               r"(?:none|n/?a|nothing|unlimited|no\s+limit|easy|medium|hard|normal)\s*[.!]?\s*(?=$|\S)"),
    re.compile(r"(?i)(?:^|(?<=[.!?;:]\s))q\s*\d+\s*(?:\([^)]{0,20}\))?\s*[.:)]\s*"),  # "Q3.", "Q5 (bonus)."
    re.compile(r"(?i)\s*\(\s*\d+\s+(?:points?|pts?|marks?)\s*\)"),  # "(4 points)"
    # a game's reward before the task ("For triple credit, put ...", "For 50 bonus points: ...")
    re.compile(r"(?i)^\s*for\s+(?:(?:double|triple|extra|bonus|full|\d+|one|two|three|five|ten|a\s+hundred)\s+)+(?:bonus\s+)?"
               r"(?:credit|points?|pts|marks|stars?|coins?|prizes?)\s*[,:]\s*(?=\S)"),
    re.compile(r"(?i)(?:^|(?<=[.!?;:]\s))(?:(?:full\s+(?:marks|credit)|pass(?:es)?|correct)\s+(?:if|when|where)"
               r"|accept\s+(?:any|an|the)\s+(?:answer|solution|response|attempt)\s+(?:where|in\s+which|that\s+has)"
               r"|an?\s+correct\s+(?:answer|solution|response)\s+(?:has|shows|puts|leaves))\s+"),
    re.compile(r"(?i)\s*[;,.]\s*(?:zero|no\s+(?:marks|credit|points)|fail(?:s|ure)?)\s+otherwise\b\s*[.!]?"
               r"|\s*[;,.]\s*otherwise\s+(?:zero|no\s+(?:marks|credit|points)|fail(?:s|ure)?)\b\s*[.!]?"),
)
"""An exam's or a rubric's framing of the goal ("Q3. (4 points) ...", "Rubric: full marks if X;
zero otherwise.", "accept any answer where X", "a correct answer has X"): dropped, X read."""

LEGAL_RES: tuple[tuple[re.Pattern, str], ...] = (
    (re.compile(r"(?i)\s*\(\s*hereinafter[^)]*\)"), ""),
    (re.compile(r"(?i)^(?:it\s+is\s+hereby\s+(?:agreed|required|requested|ordered)|the\s+(?:parties|undersigned)\s+"
                r"(?:hereby\s+)?(?:agrees?|requests?|requires?))\s+that\s+"), ""),
    (re.compile(r"(?i)^(?:forthwith|hereby)\s*,?\s*"), ""),
    (re.compile(r"(?i)\bthe\s+(?:aforementioned|aforesaid|said|above-mentioned)\s+"), "the "),
    (re.compile(r"(?i)\b(?:be\s+)?(?:deposited|situated|emplaced)\b"), "be placed"),
    (re.compile(r"(?i)\b(?:comprising|consisting\s+of)\b"), "of"),
    (re.compile(r"(?i)\b(one|two|three|four|five|six|seven|eight|nine|ten)\s+\(\d+\)"), r"\1"),  # "four (4)"
)
"""A contract's register ("shall", read by :data:`ABBREVIATIONS`; "(hereinafter 'the Cube')",
"the aforementioned green cube", "deposited upon", "four (4)", "It is hereby agreed that"):
each rewritten as plain words."""


WALL_LAYER_ROLE_RE = re.compile(rf"(?<!\d\s)(?<![a-z]\s\d\s)\b(?P<c>{COLOR_RE})\s+(?:on|at|in|for|along)\s+the\s+"
                                r"(?P<where>bottom|top|middle)(?:\s+(?:layer|row|level|tier|course))?\b")
"""In a wall, a colour said at its bottom or top ("with blue on the bottom and green on the top"):
that whole layer's colour (read as "bottom layer blue"); the bottom cube alone had been made blue
and the rest given colours nobody said."""

PER_LAYER_RE = re.compile(rf"\b(?P<n1>\d+|{COUNT_WORD_RE})\s+(?:(?P<c>{COLOR_RE})\s+)?(?:cubes?|blocks?)\s+(?:per|in\s+each|on\s+each|for\s+each|a)\s+"
                          r"(?:layer|row|level|tier|course)\b"
                          rf"|\b(?P<noun>layers|rows|levels|tiers|courses)(?P<sep>,?\s+(?:with\s+|of\s+)?)(?P<n2>\d+|{COUNT_WORD_RE})\s+"
                          r"(?:cubes?|blocks?)\s+each\b"
                          rf"|\b(?P<noun3>layers|rows|levels|tiers|courses)(?P<sep3>,?\s+)(?:each|every)\s+(?:layer|row|level|tier|course)\s+"
                          rf"(?:has\s+|with\s+|of\s+)?(?P<n3>\d+|{COUNT_WORD_RE})\s+(?:cubes?|blocks?)\b")
"""A wall's width said per layer ("three cubes per layer", "two rows, each row three cubes"): read as "N wide"; a colour said with it
("4 cyan cubes per row") is every cube's, read as "N wide, all <colour>"."""


LETTER_GREETING_RE = re.compile(r"^\s*(?i:hi|hello|hey|dear)\s+(?:[A-Z][a-z]+|all|team|everyone)\s*[,!:.-]\s*")
"""A message's greeting before the task ("Hi Sam, ...", "Dear Ana, ..."): removed when the message
is signed (:data:`LETTER_SIGNATURE_RE`; a greeting alone may address the robot), case kept (a name is
capitalised)."""

LETTER_SIGNATURE_RE = re.compile(r"(?<=[.!?])\s*(?i:thanks|thank\s+you|cheers|best|regards|best\s+regards|thx)\s*,\s*(?:[A-Z][a-z]*\.?|[A-Z]\.)\s*$")
"""A message's signature after the task ("... Thanks, Priya", "Best, Marek"): removed, with the
greeting."""


LABEL_RE = re.compile(r"(?:^|(?<=[.!?;|]\s))\s*(?P<label>[a-z@][a-z'\-@, ]{0,140}?(?:\s+#?\d+(?:\s+[a-z][a-z'\-]*){0,3})?(?:\s*\([a-z'\- ]{1,30}\))?)\s*:(?:\s+|$)")
"""A label before a colon, at the start of the text or of a sentence ("Obj: red on blue.",
"Checklist: ...", "Objective (bonus stage): ...", "Level 4 card: ..."): dropped by
:func:`rpg.schema.reading.normalize_words` when none of its words (at most
:data:`LABEL_MAX_WORDS`) is a word of the task (:data:`TASK_CONTENT_RE`) or says what the domain
cannot ("Never: ..." stays, and is refused)."""

DASH_LABEL_WORDS = frozenset("todo todos note notes ticket doc memo reminder fyi task item trial test eval evaluation scenario "
                             "case exercise level stage demo homework hw assignment lesson spec config variant episode new".split())
"""The first word of a note's heading before a dash or an arrow ("new task -> ...", "todo - wall 2x3: ...", "note for
Tues demo - put ...", "ticket 88 - ..."): the words that make it a heading (:data:`DASH_LABEL_RE`; a short word of an
identifier, "no", "set", "part", had dropped words of the task with it)."""

DASH_LABEL_RE = re.compile(r"^\s*(?P<label>[a-z@][a-z'@#\d ]{0,60}?)\s*(?:->|=>|\u2192|\s-+\s|\s\u2014\s|\s\u2013\s)\s*(?=\S)")
"""A heading before a dash or an arrow at the start of a text ("new task -> red cube in the middle", "todo - wall 2x3:
..."): dropped by :func:`rpg.schema.reading.normalize_words` when it names nothing of the task and its first word is a
heading's (:data:`DASH_LABEL_WORDS`)."""

DIFFERENT_WORDS: tuple[str, ...] = ("different", "distinct", "various", "assorted", "varied", "mixed", "differing", "unique")
"""Words that say cubes differ without naming how ("two towers of three cubes of different colours"): with no colour
named, refused rather than given made-up colours (:mod:`rpg.schema.readers`)."""

CAPS_NEVER_SPELLED = frozenset("not no never nor none without except unless if when only until while or either may maybe optional "
                               "optionally".split())
"""Words in capitals that are never a spelled word ("The purple cube MUST NOT be next to ..."): their meaning (a
negation, a condition) is refused as it is in lower case (a capital NOT had passed as a word to spell)."""

CAPS_JARGON = frozenset("todo fyi hw wip nb tbd ps must shall should required".split())
"""Words of a note written in capitals ("TODO eval set: ...", "Robotics HW - goal: ...") that say nothing of a task: no
unread capitals (:func:`rpg.schema.accounting.unaccounted`)."""

ID_LABEL_RE = re.compile(
    r"^\s*(?P<label>(?:\[[A-Za-z]{1,12}\]\s*)?(?:[\w'\"().\-]+,?\s+){0,7}?(?:[\w'\"().\-]*\d[\w'\"().\-]*|[A-Za-z]+(?:[-_][A-Za-z0-9]+)+"
    r"|\"[^\"]{1,24}\"|(?<=part\s)[A-Z]|(?<=Part\s)[A-Z])"
    r"(?:\s*\([^()]{1,40}\))?)(?:\s*\[(?P<params>[^\[\]=]{1,16}=[^\[\]]{1,40})\])?\s*(?::|\.(?=\s+[A-Za-z]))\s+(?P<body>\S.*)$", re.S)
"""A task's identifier before its text, as benchmark specs and papers write it ("Task 7 (Stacking-3):
...", "Relation test R-3: ...", "Unstack-2. init: ...", "Eval condition "mixed-2": ..."): its last word
has a digit or a hyphen, or is quoted.  :func:`rpg.schema.readers.parse` reads the text after it alone
when every word of the label is an identifier word (:data:`LABEL_JARGON`, a number, a letter) or a word
of the task's kind (a structure, sort, spell...), and adds the label's structure word when the text
alone names none ("Task 12 (Line-Sort-Colour): red, orange, yellow, left to right.")."""

LABEL_JARGON = frozenset(
    "task tasks item trial test tests eval evaluation split set condition variant episode scenario case exercise question "
    "level stage problem appendix section clause paper generalisation generalization relation relations multi structure "
    "structures spec config benchmark id no v worksheet objective env environment suite setting demo item nov dec jan feb "
    "mar apr may jun jul aug sep oct lab labs part rule rules criterion criteria acceptance requirement req homework "
    "assignment hw lesson handout seed seeds eval pattern ordered script prompt policy probe ticket teleop rollout scene demo "
    "day data collection robotics card sheet quiz option version ablation baseline module unit week warm warmup instruction "
    "instructions label labels annotation annotations caption buffer replay video clip recording meeting study user sanity "
    "check reviewer sweep batch dataset sample entry slide figure poster".split())
"""Words of a task's identifier that say nothing of the task (:data:`ID_LABEL_RE`): "ordered" and
"pattern" are said by the text after it, which gives the order or the pattern."""

LABEL_FILLER_WORDS = frozenset("for the a an of next this that our my your quick new today's tonight's s".split())
"""Words that join an identifier's words without saying anything of the task ("Instruction for the next rollout: ...",
"Quick one for the demo video: ..."): allowed in :data:`ID_WORDS_LABEL_RE`'s label beside an identifier word."""

ID_WORDS_LABEL_RE = re.compile(r"^\s*(?P<label>[A-Za-z][\w'\-]*(?:,?\s+[\w'\-]+){0,5}?)\s*:\s+(?P<body>\S.*)$", re.S)
"""A task's identifier of words alone before a colon ("Tower variant B: ...", "Demo-day row: ...", "Data-collection script,
line 12: ..."): read as :data:`ID_LABEL_RE`'s when one of its words is an identifier word (:data:`LABEL_JARGON`) and every
word is one, a word of the task's kind, a number or a capital letter (:func:`rpg.schema.readers._identifier_label`)."""

LABEL_PARAMS: dict[str, str] = {"word": "spelling {}", "region": "{place}", "corner": "{place}", "location": "{place}",
                                "seed": ""}
"""An identifier's bracketed parameter (``spell-word [word=SUN]:``, ``pile-5 [region=back]:``) -> the
words it adds to the text after it (``{place}``: the place phrase of a config's region value); a
parameter not listed leaves the label unread."""

LABEL_TASK_KIND_WORDS = frozenset(
    "stack stacking stacks unstack unstacking tower towers line lines row rows pile piles piling wall walls grid grids pyramid "
    "pyramids circle circles ring sort sorting sorted spell spelling word words letter letters digit digits number numbers "
    "place placing placement region regions between patch patches colour color colours colors build building relate arrange "
    "arrangement any order move put relation relations".split())
"""Words of a task's identifier that name the kind of task its text states ("Stacking-3",
"Spell-Word", "Place-Region"): dropped with the identifier (the text says the task)."""

INVENTORY_RE = re.compile(
    r"(?:^|(?<=[.;!?:]\s))(?:(?:you|we)\s+(?:have|get|will\s+need|need|will\s+use)|use|using|there\s+are|given|with)?\s*:?\s*"
    rf"(?P<groups>\d+\s+(?:(?:{COLOR_RE})\s+)?(?:cubes?|blocks?)(?:\s*(?:,|\band\b|,\s*and)\s*\d+\s+(?:(?:{COLOR_RE})\s+)?"
    r"(?:cubes?|blocks?))*)\s*(?:[.;!]|$)")
"""A sentence that only counts the cubes a task has ("Ingredients: 2 cubes.", "You will need: 6 gray
cubes.", "3 red cubes, 1 yellow cube."), in the parser's normalised text: each count is all the
cubes of its colour (or all the cubes), checked by :func:`rpg.schema.accounting.unaccounted`."""

CONFIG_ROLES: dict[str, str] = {
    **dict.fromkeys("structure task type shape kind goal obj objective arrangement layout formation".split(), "structure"),
    **dict.fromkeys("cubes objects colors colours color colour blocks items".split(), "cubes"),
    **dict.fromkeys("n count num num_cubes n_cubes height size length number".split(), "count"),
    **dict.fromkeys("region location place position where area corner".split(), "place"),
    **dict.fromkeys("direction order ordering bottom_first".split(), "direction"),
    **dict.fromkeys("relation predicate rel".split(), "relation"),
    **dict.fromkeys("target subject cube object a first block source".split(), "subject"),
    **dict.fromkeys("anchors anchor reference b second relative_to other".split(), "anchor"),
    **dict.fromkeys("target_colour target_color patch_colour patch_color".split(), "patch_colour"),
    "patch": "patch",
    **dict.fromkeys("instruction goal_text prompt text language_instruction".split(), "text"),
    **dict.fromkeys("seed id name trial episode".split(), "ignored"),
}
"""Keys of a task written as a config -> their role (:mod:`rpg.schema.readers.config`): a key of
no role here makes the text not a config that reader reads."""

CONFIG_RELATIONS: dict[str, str] = {
    **dict.fromkeys("left_of left to_the_left_of".split(), "to the left of"),
    **dict.fromkeys("right_of right to_the_right_of".split(), "to the right of"),
    **dict.fromkeys("in_front_of front in_front".split(), "in front of"),
    **dict.fromkeys("behind back_of".split(), "behind"),
    **dict.fromkeys("next_to adjacent adjacent_to beside near".split(), "next to"),
    **dict.fromkeys("far_from far_apart far".split(), "far from"),
    **dict.fromkeys("on on_top_of stack_on".split(), "on"),
    **dict.fromkeys("on_patch place place_on_patch".split(), "on_patch"),
    "between": "between",
}
"""A config's relation value (``"relation": "between"``, ``"goal": "far_from"``) -> the words that
say it in a sentence (``on_patch`` and ``between`` are written with their own arguments)."""

CALL_ARGUMENT_ROLES: dict[str, str] = {
    **dict.fromkeys("obj object dragged_obj block cube item pick source".split(), "subject"),
    **dict.fromkeys("target base base_obj dest destination place_on onto".split(), "target"),
    **dict.fromkeys("ref reference anchor relative_to".split(), "anchor"),
    **dict.fromkeys("region zone corner location".split(), "place"),
    **dict.fromkeys("seed id".split(), "ignored"),
}
"""Argument names of a task written as a call (``place_on_patch(obj=red cube, target=blue patch)``,
:mod:`rpg.schema.readers.config`) -> their role; ``target`` is the patch where its value is one,
else the anchor cube.  Other names keep their :data:`CONFIG_ROLES` role."""

LABEL_MAX_WORDS = 24
"""The most words a dropped label (:data:`LABEL_RE`) has.  A run before a colon that names nothing of
the task is framing however long ("Success criterion for this episode, checked by the scripted
evaluator after the arm returns home: ...", "here is what I would like to see at the end: ..."); it
was 4 until stranger23 (seventeenth session)."""


PERSON_NOUNS = (r"curators?|brides?|grooms?|clients?|customers?|boss(?:es)?|kids?|sons?|daughters?|child(?:ren)?|coach(?:es)?|judges?"
                r"|panel|team|managers?|supervisors?|directors?|owners?|homeowners?|leads?|artists?|mum|mom|dad|grandma|grandpa|wife"
                r"|husband|partners?|friends?|neighbou?rs?|(?:play)?testers?|players?|buyers?|viewers?|users?|audience|crew|people|folks"
                r"|students?|reviewers?|designers?|producers?|actors?|visitors?|guests?|shoppers?|readers?|parents?|family|everyone"
                r"|everybody|sponsors?|donors?|funders?|investigators?|committee|board|captain|commanders?|stakeholders?|teachers?"
                r"|professors?|advisors?|moderators?|mods|subscribers?|fans|followers|editors?|officers?|participants?|chat")
"""People who ask for, or judge, a steering edit's change ("the curator", "playtesters", "the homeowner"): read by
:data:`_ASKER` and :data:`EDIT_PERSON_REASON_RE`."""
INSTITUTION_NOUNS = (r"court|tribunal|council|authorit(?:y|ies)|inspectors?|department|office|agency|management|headquarters|hq"
                     r"|ministry|administration|jury|referee|umpire|chair|chairperson|governor|mayor|king|queen|general|sergeant")
"""Bodies and offices that order a task as a person asks for one ("The court orders ...", "Headquarters requires ..."):
read by :data:`SOMEONE_WANTS_RE`."""

FINDING_IS_TAKING_RE = re.compile(
    r"\b(?:find|locate|fetch|retrieve|get\s+hold\s+of)\s+(?=(?:the|all|both|a|an|\d+)\b[^.;!?]{1,80}?(?:,?\s*and|,?\s*then|,)"
    r"\s+(?:then\s+)?(?:put|place|set|stack|move|spell|build|make|line|arrange|lay|drop|pile|sort|align|order|stand)\b)")
"""Finding cubes on the way to a placing verb ("Find the letter blocks C, A and T and spell CAT", "locate the red cube,
then put it ..."): read as taking them ('find' had been refused as an action the domain lacks); alone ("Find the red
cube.") it stays refused."""

NAMING_HEADING_RE = re.compile(
    r"(?i)^\s*(?:(?:let's|let\s+us|please|now|ok(?:ay)?|so|right)\s*,?\s+)*(?P<verb>[a-z]+)\s+"
    r"(?P<what>it|this|(?:a|an|the|our|my|your)\s+(?:[a-z'\-]+\s+){0,2}?[a-z'\-]+)"
    r"(?P<like>\s+like\s+(?:a|an|the)\s+(?:[a-z'\-]+\s+){0,2}?[a-z'\-]+)?\s*:\s*(?P<body>\S.*)$", re.DOTALL)
"""A heading that names what the text after its colon builds, in a voice ("Build it like a layer cake: a brown cube on the
bottom, ...", "Plate it: put the red cube on ...", "Stack a survey cairn: a gray cube, ..."): a verb and what it makes,
perhaps a simile; read by :func:`rpg.schema.readers._named_heading` only where the text after the colon is a whole task
by itself and the heading says nothing of a goal (its nouns, 'cake' or 'cairn', then name that task: they had been
refused as objects and shapes the domain lacks)."""

NAMING_HEADING_VERBS_EXEMPT: frozenset[str] = frozenset(
    "build make stack set arrange assemble construct form create pile line put place lay do".split())
""":data:`SCENE_CHANGING_VERBS` a naming heading (:data:`NAMING_HEADING_RE`) may open with: those that make what the text
after it says; any other of them ("Scatter it:", "Hide it:", "Remove it:") may change the task, and the heading stays."""

SOMEONE_WANTS_RE = re.compile(
    r"\b(?:my|our|the|this|your)\s+(?P<who>supervisor|boss|advisor|adviser|professor|prof|pi|manager|lab|team|colleague|labmate|teacher|"
    rf"client|group|mentor|tutor|lecturer|{PERSON_NOUNS}|{INSTITUTION_NOUNS})\s+(?:wants|needs|would\s+like|asked\s+for|asks\s+for"
    r"|requested|requests|orders|ordered|demands|demanded|directs|directed|instructs|instructed|decrees|decreed|rules|ruled"
    r"|requires|required)(?:\s+that)?\b(?!\s+(?:it|them|this|that|those|these|to\s+be\s+told)\b)")
"""Who asks for the task ("my supervisor wants the white cube ...", "The court orders that the blue cube be placed on
...", "The client requests a row of ..."): read as "i want" (the goal is the same whoever asks: a person of
:data:`PERSON_NOUNS` or an institution of :data:`INSTITUTION_NOUNS`; :func:`rpg.schema.reading.normalize_words` lists
``who`` as dropped).  A pronoun after the verb ("the client wants it ...") points at something unsaid and stays."""

_PURPOSE = (r"(?:the|my|our|this|a|tomorrow's|today's|tonight's|friday's|monday's)\s+(?:next\s+|first\s+|upcoming\s+)?(?P<what>run|demo|trial|experiment|test|eval(?:uation)?"
            r"|episode|paper|video|benchmark|session)")
"""What a task is for ("the next run", "my demo"): :data:`PREAMBLE_RE` (said first) and :data:`PURPOSE_RE` (said last)."""

PREAMBLE_RE = re.compile(
    r"^\s*(?:(?:when|once)\s+(?:the\s+robot\s+|it\s+|you\s+|the\s+task\s+)?(?:is|are|has|have)\s+(?:finished|done|completed?)"
    r"(?:\s+with\s+(?:it|the\s+task))?\s*,?\s*(?:the\s+(?:table|scene|workspace)|it|everything)\s+should\s+look\s+like\s+"
    r"(?:this|so|the\s+following)\s*[.:]\s*"
    r"|at\s+the\s+(?:very\s+)?end(?:\s+of\s+the\s+(?:episode|task))?\s*,\s*"
    r"|(?:picture|imagine)\s+the\s+(?:final|end|finished|goal)\s+(?:scene|state|table|configuration)\s*:\s*"
    r"|(?:(?:ok(?:ay)?|so|alright|right|well)\s*,?\s+)*(?:here(?:'s|\s+is)\s+what\s+(?:i'?m|i\s+am|we'?re|we\s+are)\s+thinking"
    r"|(?:i|we)\s+(?:was|were|am|are)\s+(?:just\s+)?thinking|(?:i'?m|we'?re)\s+(?:just\s+)?thinking)\s*[,:.;\u2014\u2013-]*\s*"
    r"|(?:(?:ok(?:ay)?|so|alright|right|well)\s*,?\s+)*let(?:'s|\s+us)\s+(?:do|try|make|build)\s+something"
    r"(?:\s+(?:fun|cool|new|different|simple|easy|nice|interesting|quick))?\s*[:,.!;\u2014\u2013-]\s*"
    r"|for\s+" + _PURPOSE + r"(?:\s*[:,\u2014\u2013-]\s*|\s+(?=(?:could|can|would|will|please)\b))"
    r"|(?:(?:the\s+(?:robot|agent|arm)\s+)?(?:must|should|has\s+to|needs\s+to)\s+)?(?:finish|end(?:\s+up)?)\s+with\s+(?=the\s)"
    r"|(?:success\s+(?:condition|criteri(?:on|a))|task\s+spec(?:ification)?|evaluation\s+task|eval\s+task|test\s+task"
    r"|expected\s+(?:result|outcome|end\s+state|final\s+state|state|behaviou?r)|(?:level\s+\d+\s+)?win(?:ning)?\s+(?:condition|state)"
    r"|goal\s+for\s+this\s+(?:level|round|stage)"
    r"|(?:final|end|goal|target|desired)\s+scene)\s*(?::|\u2014|\u2013|-)\s*)")
"""Framing that names when the goal holds or heads the spec, said before it ("When the robot is
finished, the table should look like this.", "At the end, ...", "Picture the final scene: ...",
"Success condition: ...", "Task spec \u2014 ..."): every goal is checked at the end of the episode, so
the words are dropped before conditions and time are refused (:func:`rpg.schema.reading.normalize`)."""

PURPOSE_RE = re.compile(r"\s+\bfor\s+" + _PURPOSE + r"\b(?=\s*(?:[.!,;]|$))")
"""What the task is for, said last ("need a 2x2 grid of blue cubes for the next run"): nothing
of the goal, dropped (:func:`rpg.schema.reading.normalize_words` lists ``what`` as dropped)."""

STEP_MARKER_RE = re.compile(r"(?:^|(?<=[.;!:,]\s))(?:step\s+(?:\d+|one|two|three|four|five|six)|\(?\d+\))\s*[:.)\-]?\s+")
"""A step's number before it ("Step 1: put ...", "2) stack ..."): the steps' end states are the
goal; the numbers are dropped."""

ARROW_RE = re.compile(r"\b(block|cube|brick)\s*(?:->|\u2192|=>)\s*(?:the\s+)?(?=(?:front|back|rear|left|right|center|centre|middle"
                      r"|far|near)\b)")
"""A cube sent to a place with an arrow ("blue cube -> front left corner"): read as "in the"."""

ARROW_COLOUR_RE = re.compile(rf"(?:\bthe\s+)?\b({COLOR_RE})\s*(?:->|\u2192|=>)\s*(?:the\s+)?(?=(?:front|back|rear|left|right|center|centre"
                             r"|middle|far|near)\b)")
"""A cube named by its colour alone sent to a place with an arrow ("red -> left region", "orange -> front-left"):
"the red cube in the ..."."""

ARROW_PATCH_RE = re.compile(rf"\b({COLOR_RE})(?:\s+(?:block|cube|brick))?\s*(?:->|\u2192|=>)\s*(?:the\s+)?(?=(?:{COLOR_RE})\s+(?:goal\s+)?patch\b)")
"""A cube sent to a patch with an arrow ("pink -> blue patch"): the cube on that patch."""



LABEL_STRUCTURE_KINDS: dict[str, str] = {w: k.name for k in STRUCTURE_KINDS.values() for w in (*k.words, *k.described_by)
                                         if not (k.name == "piles" and w in STRUCTURE_KINDS["tower"].described_by)}
"""A structure's noun in a voice's label before its task ("Tungsten tower: stack ...") -> the kind it names; the label's
noun is the voice's own where its task names that kind too, or where it only qualifies a thing of the voice's world
("Grid reference: ...", "Tower captain speaking: ...")."""

VOICE_LABEL_FILLER_WORDS = frozenset({"the", "a", "an", "for", "of", "my", "our", "your", "this", "that"})
"""Words the parser reads that a voice's label may hold around a structure noun or its own things without saying anything
of the task ("Chip stack for the showdown", "Line of sight check"): no place, count or order (:func:`rpg.schema.reading.\
_label_structure_masked`)."""

LABEL_MASK_HAZARD_RE = re.compile(
    r"\b(?:others?|rest|each|every|all|both|cop(?:y|ies)|duplicat\w*|replica\w*|double\w*|pairs?|paired|twins?|multiple|several"
    r"|view|viewpoint|perspective|eyes?|mirror\w*|reflect\w*|revers\w*|invert\w*|flip\w*|rotat\w*|turned|opposite|inverse"
    r"|negative|counter\w*|wrong|incorrect|decoy|trap|mistakes?|errors?|start\w*|initial\w*|before|setups?|set-up|prior"
    r"|me|you|us|everyone|everybody|guests?|kids?|children|child|family|audience|crowd|public|team|client|friends?|boss|people"
    r"|person|humans?|man|men|woman|women)\b")
"""Words that keep a voice's label whole where it holds a table, an idiom or fillers (:func:`rpg.schema.reading.\
_label_structure_masked`): others or copies ("Line of others:", "Duplicate table:"), someone's view ("Guest table:"), a
turned, unwanted or start state ("Mirror table:", "Setup table:") (a hostile helper's)."""

LABEL_STRUCTURE_HAZARD_RE = re.compile(r"twins?|double|pairs?|duo|trio|parallel|nested|stacked|count\w*|ordered|sorted|revers\w*"
                                       r"|alphabet\w*|rainbow|numbers?|numbered|words?|upper|lower|bottom|top|left|right|front|back"
                                       r"|middle|first|second|third|last|tall|short|long|big|small|little|tiny|wide|high|low|main|other")
"""Words of a voice's label beside a structure noun that may count, order, size or place the structure ("Twin towers",
"Rainbow row", "Countdown row", "Upper tower"): such a label is left whole (:func:`rpg.schema.reading._label_structure_masked`)."""

STRUCTURE_KIND_SAID_RES: dict[str, re.Pattern] = {
    name: re.compile(r"\b(?:" + "|".join(f"{w}(?:s|ed|ing)?" for w in (*k.words, *k.described_by)) + r")\b")
    for name, k in STRUCTURE_KINDS.items() if k.words}
"""A structure kind's name -> its words as a task says them ("stack", "stacked", "rows")."""


STRUCTURE_NOUN = "(?:" + "|".join(sorted({w for k in STRUCTURE_KINDS.values() for w in (*k.words, *k.described_by)}
                                           - {"square", "pile"} | {"wall"})) + ")"
"""A noun that names a structure being described ("a line of ...", "a wall: ..."), from the
structure kinds' own words (a square may be a patch and a pile a heap of cubes, so neither is one
here; a wall is a grid of layers with no kind of its own)."""


IDLE_WORDS: frozenset[str] = IGNORABLE | IGNORABLE_MORE | frozenset("""
a an the this these those is are was were be been being am i me my we our us you your he she his her for of and or but
so do does did have has had will would can could should just very really as wants want""".split())
"""Known words a sentence that says nothing of the task may hold (fillers and function words)."""

_TASK_THINGS = _GOAL_THINGS + r"|\d+|numbers?|on|two|three|four|five|six|seven|eight|nine|ten"
"""The words of the task's things, places and counts that both :data:`TASK_CONTENT_RE` and :data:`SENTENCE_CONTENT_RE`
count as the task's."""

TASK_CONTENT_RE = re.compile(
    r"\b(?:" + _TASK_THINGS + r"|put|place|move|build|make|arrange|set|spell|sort|order|one|it|them|each|every|all|both"
    r"|layers?|tiers?|storeys?|upper|lower)\b")
"""Words that make a sentence part of the task: cubes, colours, counts, structures, places,
the layers of one ("Lower layer: white, gray, white."), relations, placement verbs and references.  A sentence with none of them, only fillers and
unknown nouns ("My supervisor wants this for the demo.") says nothing of the task: its unknown
words are no reason to refuse (:func:`rpg.schema.reading._idle_sentence`)."""

SENTENCE_CONTENT_RE = re.compile(
    r"\b(?:" + _TASK_THINGS + r"|pieces?|areas?|zones?|bridges?|words?|spell\w*|reads?|underneath|beneath|over"
    r"|layers?|levels?|tiers?|storeys?|stories|colou?r(?:s|ed)?)\b|@region_")
"""What makes a sentence of a normalised instruction part of its task: a cube, colour, count, patch, place, relation,
structure or spelled word (a pronoun alone is not: "lift it.").  A sentence with none of them (when the instruction
has more than one) was read by no reader: the compile refuses it (:func:`rpg.schema.accounting.unaccounted`)."""

FREEDOM_SENTENCE_RE = re.compile(r"\b(?:any|whatever|every)\b[^.;]*\b(?:order|colou?rs?)\b|\b(?:order|colou?rs?)\b[^.;]*\b(?:matters?|fine"
                                 r"|okay|ok|free|unimportant|irrelevant|up\s+to\s+you|your\s+choice)\b")
"""A sentence that leaves the order or the colours free ("Any colours, any order.", "The order doesn't matter."): read by
the free-choice rules, so part of the task (:func:`rpg.schema.accounting.unaccounted`'s sentence check)."""

RESTATED_GOAL_RE = re.compile(r"^(?:(?:please|now|just|then|and|so)\s+)*(?:arrange|build|make|do|create|form|set\s+up|go\s+ahead|put|place|set)"
                              r"(?:\s+(?:it|them|this|that|these|those|so|exactly\s+(?:that|this)|it\s+so|that\s+happen|this\s+happen))?"
                              r"(?:\s+please)?\s*[.!]?$")
"""A sentence that only asks for the goal said before ("Arrange them.", "Build exactly that.", "Please do."): part of the
task, adding nothing (:func:`rpg.schema.accounting.unaccounted`'s sentence check)."""

FUNCTION_WORDS: frozenset[str] = frozenset("""
that it its they them their this these those there here what which who is are was were be been would will could should
can may might does did have has had of for to from with by as at in and or but so if than too very just also the a an
please my our your me us i we you great good fine okay ok thanks want wants need needs like
""".split())
"""Words that carry nothing alone: a sentence of these is what a rewrite left of framing."""

_FOLLOW_UP_FILLER = r"(?:(?:ok(?:ay)?|well|no|nope|actually|instead|now|then|sorry|oops|rather|and|but|so|or|i\s+mean|make\s+(?:it|that))\s*,?\s+)*"
SUBJECTLESS_RELATION_RE = re.compile(
    r"(?:^|(?<=[.!?;]\s))" + _FOLLOW_UP_FILLER
    + r"(?:(?:to\s+the\s+)?(?:left|right)(?:\s+of)?|in\s+front(?:\s+of)?|behind|under(?:neath)?|below|beneath|above|on\s+top(?:\s+of)?"
      r"|next\s+to|beside|near|far\s+(?:away\s+)?from|between|on|onto|over)\s+(?:(?<!\bon\s)(?<!\bonto\s)(?:it|them|that)|the\s+(?!table\b)[a-z]+(?:\s+(?:cube|block|one|patch))?)"
      r"\s*(?:,?\s*(?:actually|instead|please|then|i\s+mean|rather))?\s*[.!?]?\s*$|(?:^|(?<=[.!?;]\s))" + _FOLLOW_UP_FILLER
    + r"(?:(?:to\s+the\s+)?(?:left|right)(?:\s+of)?|in\s+front(?:\s+of)?|behind|under(?:neath)?|below|beneath|above|on\s+top(?:\s+of)?"
      r"|next\s+to|beside|near|far\s+(?:away\s+)?from|on|onto|over)\s+(?:(?<!\bon\s)(?<!\bonto\s)(?:it|them|that)|the\s+(?!table\b)[a-z]+(?:\s+(?:cube|block|one|patch))?)"
      r"\s*(?:,?\s*(?:actually|instead|please|then|i\s+mean|rather))?\s*[.!?;]\s")
"""A sentence after the first that is only a relation, with no cube said to be in it ("Right of it.", "Okay, under it.",
"Behind it, actually."): a correction of the relation said before, or another one for some cube?  Refused
(:func:`rpg.schema.accounting.unaccounted`): every such follow-up had been read as nothing, or as an addition."""

REVERSAL_RE = re.compile(r"\b(?:revers(?:ed|es|ing|e)(?!\s+(?:alphabetical|numerical|numeric)\b|d?\s+order\b|,)|backwards?"
                         r"|opposite\s+(?:order|way|direction|sequence)|in\s+the\s+opposite\b|flip(?:s|ped|ping)?"
                         r"|invert\w*|upside[\s-]down|the\s+other\s+way(?:\s+(?:round|around))?|mirror\w*)\b")
"""Words that turn an order or a structure around ("reversed", "backwards", "in the opposite order", "flip the tower"):
read only where rho_0 starts the structure they turn, or as a sort's direction ("in (the) reverse(d) order" of a list,
"reverse alphabetical", and "the reverse, ..." before the order written out are the readers'); any other reading had
kept the order said before them (refused: :func:`rpg.schema.accounting.unaccounted`)."""

REVERSE_ORDER_RE = re.compile(r"\brevers(?:e|ed)\s+order\b")
LISTED_REVERSE_ORDER_RE = re.compile(r"[a-z0-9]+(?:\s+(?:cube|block|one))?\s*,\s*(?:and\s+)?(?:the\s+)?[a-z0-9][^.;]*?\bin\s+(?:the\s+)?"
                                     r"revers(?:e|ed)\s+order\b|\brevers(?:e|ed)\s+order\s*:")
"""A reverse order said of a list ("Stack the red cube, the white cube, the yellow cube in the reversed order", "in reverse
order: blue at the bottom, ..."), which the stack reader reads; said of anything else ("Put the red block on the blue
block in reverse order.") it is a :data:`REVERSAL_RE` word."""

COUNTED_OTHERS_RE = re.compile(
    r"\b(?:on|onto|on\s+top\s+of|atop|under|underneath|beneath|below|above|over)\s+(?:a\s+(?:stack|tower|pile|column)\s+of\s+)?(?P<n>\d+)\s+"
    r"(?:stacked\s+|other\s+)?(?:blocks|cubes)\b"
    r"|\b(?P<m>\d+)\s+(?:other\s+|more\s+)?(?:blocks|cubes)\s+(?:on|onto|on\s+top\s+of|atop|under|beneath|below)\s+"
    r"(?:it|top\s+of\s+it|the\s+(?:" + "|".join(COLORS) + r")\s+(?:block|cube|one))\b")
"""Cubes counted as what a named cube stands on or carries ("the red block on top of two blocks", "on a stack of two
blocks", "stack two blocks on it"): as many cubes besides that one, so the task holds at least one more than the
count (:func:`rpg.schema.accounting.unaccounted`; the count had been met by the named cube itself, one block lost)."""

_BREAKDOWN_GROUP = rf"\d+\s+(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?"
COUNT_BREAKDOWN_RE = re.compile(rf"\b(?P<n>\d+)\s+(?P<noun>cubes|blocks)(?P<rest>[^:.;]*?)\s*:\s*(?P<groups>{_BREAKDOWN_GROUP}"
                                rf"(?:\s*(?:,\s*(?:and\s+)?|and\s+){_BREAKDOWN_GROUP})+)\s*(?=[.;!]|$)")
"""A count of cubes, then the same cubes by colour after a colon ("place 4 cubes on the yellow patch: 2 red and 2 blue"):
read by :func:`rpg.schema.reading.normalize_words` as the groups themselves when they add up to the count."""

ONE_ON_ANOTHER_RE = re.compile(r"\b(?:put|place|set|stack)\s+(?:1|a|an)\s+(?:cube|block)\s+(?:on\s+top\s+of|on|onto|atop)\s+another"
                               r"(?:\s+(?:1|cube|block))?\b")
"""Two unnamed cubes said as one on another ("Please put one cube on top of another."): a stack of two, in any order."""

MIDDLE_GROUP_COLOUR_RE = re.compile(rf"(?P<head>\bthe\s+(?P<n>\d+)\s+(?:cubes\s+|blocks\s+|ones\s+)?(?:in\s+the\s+middle|in\s+between)"
                                    rf"\s+(?:are|is|should\s+be|must\s+be)(?:\s+(?:all|both))?)\s+(?P<c>{COLOR_RE})\b")
"""The middle cubes of a tower or row given one colour ("the three in between are gray"): the colour of each of them
(it had reached one, the others made up)."""

TOWER_FIRST_RE = re.compile(rf"\s*,?\s*(?:(?:starting|beginning)\s+with\s+(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                            rf"|(?:the\s+)?(?P<c2>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+first)(?=\s*(?:[.;!]|$))")
"""A tower's first cube said after its list ("a tower of red, green and blue, starting with blue", "..., yellow first"):
its bottom, as a tower is built from the bottom up."""

WHICH_PLACE_RE = re.compile(rf"(?P<cube>\bthe\s+(?:{COLOR_RE})\s+(?:cube|block))\s*,\s*which\s+(?:should\s+be|must\s+be|is|sits|stands|goes"
                            r"|needs\s+to\s+be|has\s+to\s+be)\s+(?P<place>(?:in|at|on|to)\s+(?:the\s+)?[a-z@_]+(?:\s+[a-z@_]+){0,4}?)"
                            r"(?=\s*(?:[.;!]|$))")
"""A place said of a cube in a relative clause ("put the gray cube in front of the brown cube, which should be in the
center"): the place of that cube (it had gone to the sentence's subject)."""

COLOUR_SPOT_RE = re.compile(rf"\b({COLOR_RE})\s+(?:spot|dot|circle\s+on\s+the\s+table)\b")
"""A coloured spot on the table ("the yellow spot"): a goal patch (it had been read as a yellow cube)."""

COLOUR_GROUP_NOUN_RE = re.compile(rf"\bthe\s+(?P<c>{COLOR_RE})\s+(?P<noun>pair|couple)\b(?!\s+of\b)")
"""Two cubes of one colour named as a pair ("The orange pair is on the bottom"): written as "the 2 orange blocks"
before number words are read (:data:`NUMBER_WORDS` reads "pair" alone as 2, which left "the orange 2")."""


BARE_NUMBERS_RE = re.compile(r"\b(?:put|place|set|move|stack|arrange|line\s+up|lay)\s+(?P<nums>\d+\s*(?:,\s*(?:and\s+)?|\s+and\s+|\s*&\s*)\d+)"
                             r"(?![\w.-])(?!\s+(?:x|by)\b)"
                             r"(?=\s+(?:in|into|on|onto|at|next|beside|left|right|behind|from|as|together)\b|\s*[.!,;]?\s*$)")
"""Two numbers after a verb joined with nothing that says what they are ("put 5 and 8 in a row"): counts of cubes or the labels of
digit cubes; refused unless the text says digit cubes (:data:`rpg.schema.reading.LABEL_CUBES_SAID_RE`)."""


BETWEEN_THEM_RE = re.compile(r"\bbetween\s+(?:them|those\s+two|these\s+two|the\s+two(?:\s+(?:cubes|blocks))?|both\s+of\s+them)\b"
                             r"(?!\s+(?:cubes|blocks|patches))")
"""A cube put between the two cubes named before ("red left of blue, then a green cube between them"): written out as
"between the red cube and the blue cube" when exactly two cubes were named (:func:`rpg.schema.reading.normalize_words`)."""


PAIR_ON_CUBE_RE = re.compile(rf"^(?:(?:please\s+)?(?:put|place|set|stack)\s+)the\s+(?P<a>{COLOR_RE})\s+and\s+(?:the\s+)?(?P<b>{COLOR_RE})\s+"
                             rf"(?:cubes|blocks)\s+(?:both\s+)?(?:on\s+top\s+of|on|onto|atop)\s+the\s+(?P<c>{COLOR_RE})\s+(?:cube|block)\s*[.!]?$")
"""Two cubes put on a third, said as a pair ("put the red and green cubes on the blue cube"): a stack with the third at
the bottom and the pair above it in any order (a sentence of its own; "on both" is a bridge, read elsewhere)."""

LINE_ROLE_RE = re.compile(rf"\b(?:between\s+(?:the\s+)?(?:(?:{COLOR_RE})\s+(?:and\s+(?:the\s+)?(?:{COLOR_RE})\s+)?(?:cubes?|blocks?|ones?)|them|the\s+other)"
                          rf"|ends?(?!\s+up\b)|revers\w*|(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+|sits\s+)?in\s+the\s+middle"
                          r"|leftmost|rightmost|frontmost|backmost|ordered"
                          rf"|(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:first|last)|(?:the\s+)?(?:first|last)\s+(?:is|should|must|one|cube|block)"
                          r"|(?:in|that|this|the\s+same|the\s+listed|the\s+given)\s+order(?!\s+to\b)"
                          rf"|(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:starts?|begins?|opens?|leads?|heads?|closes?|finishes?)\s+"
                          rf"(?:off\s+)?(?:the\s+)?(?:row|line|sequence)|,\s*(?:and\s+)?then\s+(?:the\s+)?(?:{COLOR_RE})"
                          rf"|(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s*,?\s+(?:and\s+)?then\s+(?:the\s+)?(?:{COLOR_RE})"
                          r"|followed\s+by|sequential\w*|in\s+sequence|respectively|as\s+(?:written|listed|given|said|named)"
                          rf"|(?:{COLOR_RE})\s*(?:->|>|\u2192)|beginning\s+with|at\s+the\s+start|(?:second|third|fourth|fifth)\s+(?:place|spot|position)"
                          rf"|in\s+(?:colou?r|alphabetical|numerical|rainbow|size)\s+order|from\s+(?:{COLOR_RE})\s+to\s+(?:{COLOR_RE})"
                          rf"|(?:{COLOR_RE})-(?:{COLOR_RE})|sorted)\b")
"""Words that give a cube a place in a line ("with blue at one end", "the red cube between the other two", "in reverse
order", "red starts the row, then blue"): where the task's line has no order, nobody read them (refused: :func:`rpg.schema.accounting.unaccounted`)."""

LINE_END_SAID_RE = re.compile(
    rf"(?i)(?<![\w'-])(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:must|should|has\s+to|needs\s+to|is\s+to|will)\s+"
    r"(?:be|go|sit|stand)\s+|is\s+|goes\s+|sits\s+|stands\s+)?(?:(?:at|on)\s+(?:the\s+)?(?:very\s+|far\s+)?(?P<side>left|right)"
    r"(?:[\s-]+hand)?\s+end|(?:at|on)\s+the\s+far\s+(?P<side2>left|right)|(?:is\s+)?(?P<most>left|right)most)\b"
    r"(?:\s+of\s+(?:the|a|that)\s+(?:row|line))?"
    rf"|(?<![\w'-])(?:the\s+)?(?P<most2>left|right)most\s+(?:cube|block|one)\s+(?:(?:must|should|has\s+to|will)\s+be|is)\s+"
    rf"(?:the\s+)?(?P<c2>{COLOR_RE})\b")
"""One cube given the left or right end of a row whose order the text leaves free ("a row of red, green and blue with
red at the left end", "the gray one must be at the right end", "the leftmost cube is red"): read by
:func:`rpg.schema.readers.line_with_ends` (an :class:`~rpg.domain.predicates.AnchoredLine`)."""

LABEL_END_SAID_RE = re.compile(r"\b(?:letter|digit|number)\s+(?P<l>[a-z0-9])\s+(?:block|cube)\s+(?:is\s+|goes\s+)?(?:at|on)\s+the\s+"
                               r"(?P<end>bottom|base|top)\b(?!\s+of\b)")
"""A letter or digit cube given an end of a tower ("spell GO in a tower, with G at the bottom"): the tower must have it
there (:func:`rpg.schema.accounting.unaccounted`; a spelled tower reads top to bottom, and G had been put on top)."""

SCENE_COUNT_RE = re.compile(r"\bthere\s+(?:are|will\s+be)\s+(?P<n>\d+)\s+(?:cubes|blocks)\s*(?::|on\s+the\s+table|in\s+(?:total|all)|\.)"
                            r"|\b(?P<n2>\d+)\s+(?:cubes|blocks)\s+in\s+(?:total|all)\b")
"""The number of cubes the whole scene holds ("There are four cubes: ...", "6 blocks in total"): the task holds exactly
that many (a fifth cube had been made up)."""

PRONOUN_MOVED_RE = re.compile(r"\b(?:stack|put|place|set|move|lay|slide|push)\s+(?P<p>it|them)\s+(?:on\s+top\s+of|on|onto|atop|under|next\s+to"
                              r"|beside|behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of)\b")
"""A pronoun as the cube moved ("... and then stack it on the blue cube"): with two cubes named before, which one?
(refused, :func:`rpg.schema.accounting.unaccounted`; it had taken the last one named, and the stack read upside down)."""

PILES_SAID_RE = re.compile(r"\b(?:another|a\s+second|a\s+separate|a\s+different|separate|(?P<n>\d+))\s+piles?\b")
"""More than one pile said ("in one pile and the blue cube in another pile", "3 piles"): the task must hold that many
(they had been merged into one)."""

LEFT_OVER_ALTERNATIVE_RE = re.compile(r"\b(?:instead(?!\s+of\s+(?:on|onto|next|beside|behind|in\s+front|to\s+the|under|below|above|left|right"
                                      r"|far|near|between|at)\b)|rather\s+than|in\s+place\s+of(?:\s+that)?|rather\s*,)\b")
"""An alternative said and not read as a contrast (:func:`rpg.schema.reading.drop_contrasts`) nor as a corrected
relation ("... next to the blue cube instead of on top", the relational reader's): "Instead of putting the red block
next to the blue block, put ...", "... Instead, put ...": which of the two goals stands was kept both ways
(refused: :func:`rpg.schema.accounting.unaccounted`)."""

ORDER_WORDS = re.compile(r"\b(rainbow|alternat\w*|(?<!any\s)order\w*|sequence|gradient|sort\w*|ascending|descending|"
                         r"bottom|base|first|last|then|lightest|darkest|top(?! of (each other|one another)))\b")
"""Words that give a stack's cubes places (an order, a role): a stack read with any of them
keeps its order."""


TOWER_END_SAID_RE = re.compile(
    rf"(?<![\w'-])(?P<c>(?i:{COLOR_RE})|[A-Z]|\d)(?:\s+(?i:block|cube|one))?\s+(?i:(?:(?:must|should|has\s+to|needs\s+to|is\s+to|will)\s+"
    r"(?:be|go|sit|stand)\s+|is\s+|goes\s+|sits\s+|stands\s+|stays\s+)?(?:(?:at|on)\s+(?:the\s+)?(?:very\s+)?(?P<end>bottom|base|top)"
    r"|(?P<end2>base|bottom))\b(?!\s+of\b))")
"""One cube given an end of a tower whose order the text leaves free ("Any order is fine, but A must be at the bottom",
"Tower: purple base, then the yellow and the white cubes above it in any order"): read by
:func:`rpg.schema.readers.any_order_with_ends`."""

ORDER_BEYOND_ENDS_RE = re.compile(r"(?i)\b(?:then|next|followed|after|second|middle|third|fourth|2nd|3rd|above|below|under|over)\b")
"""Words that say more of a tower's order than its ends (:func:`rpg.schema.readers.any_order_with_ends`: "A at the bottom,
then B")."""

FREE_ORDER_PART_RE = re.compile(r"(?i)\b(?:any|either|whatever|whichever|no\s+particular)\s+(?:order|goes)\b")
"""A part of a text that says the rest of a tower's order is free ("then the yellow and the white cubes above it in any
order"): its words say no more of the order (:func:`rpg.schema.readers.any_order_with_ends`)."""

COLOURS_KEPT_RE = re.compile(r"(?i)\b(?:same|the\s+old|original|unchanged)\s+colou?rs?\b|\bcolou?rs?\s+(?:stay|remain|unchanged"
                             r"|as\s+(?:they\s+are|before))")
"""Words of a steering edit that keep the cubes' colours ("same colours left to right"): with a recolour read as well, the
edit is refused (:func:`rpg.steer.edits.interpret`)."""

STACK_ROLE_RE = re.compile(
    r"(?:\bwith|[,;.]|\b(?:so|such)\s+that|\bwhere)\s+(?:the\s+|a\s+|an\s+)?(?P<c>[a-z]+)\s+(?:(?:block|cube|one)\s+)?"
    r"(?:(?:is|goes|sits|stands|(?:should|must|will)\s+be|ends\s+up)\s+)?"
    r"(?:(?:on|at)\s+(?:the\s+)?(?P<end>top|bottom|base)|as\s+(?:the\s+)?(?P<end2>top|bottom|base))\b"
    r"(?!\s+of\b)")
"""A cube given one end of a stack whose other cubes are only listed ("stack the red, blue
and green blocks with red on top", "... with the red block at the bottom"): ``c`` is the
colour, ``end``/``end2`` the end (base = bottom).  Label cubes keep their listed order (the steering
states an anchored stack of coloured cubes only)."""

STACK_FREE_PHRASES = re.compile(
    r"\bon\s+top\s+of\s+(?:each\s+other|one\s+another)\b|\b(?:on|onto|upon|over|above)\s+(?:each\s+other|one\s+another)\b"
    r"|\b(?:on|onto)\s+(?:the\s+|a\s+)?(?:[a-z]+\s+)?(?:goal\s+)?patch(?:es)?\b|\b(?:on|onto)\s+the\s+table\b"
    r"|@region_[a-z_]+|\b(?:on|at|to)\s+the\s+(?:left|right|front|back)\b|\bin\s+any\s+order\b"
    r"|\b(?:end|ends|ended|wind|winds|wound)\s+up\b"
    r"|\b(?:and\s+)?then\s+(?=(?:put|place|set|move|lay|slide|push|bring|make|build|line)\b)")
"""Phrases of a stack instruction that put no cube above another: the stack as a whole ("on
top of each other"), where it stands ("on the green patch", "on the table", a region), the
end state ("should end up stacked")."""

CUBE_ORDER_RE = re.compile(r"\b(?:on|onto|upon|atop|above|over|under|below|beneath|underneath|higher|lower|followed|"
                           r"after|before|next|from(?=[^.;]*\bto\b)|starting|ending|beginning|respectively|that|this|listed|given|"
                           r"named|reverse\w*|up|down|last|first)\b")
"""Words that, left in a stack instruction once :data:`STACK_FREE_PHRASES` and roles are
taken out, may order the cubes it lists ("red on blue", "from bottom to top", "in that
order"): with any of them, or :data:`ORDER_WORDS`, the listed order is kept.  "from" orders only
with a "to" after it ("a tower from two purple cubes" says what it is made of)."""

_COLOR_LIST = "(?:" + "|".join(COLORS) + r")(?:(?:\s*,\s*|\s+)(?:" + "|".join(COLORS) + r"))*(?:,?\s+and\s+(?:" + "|".join(COLORS) + r"))?"
_LAYER_ROLE = (r"(?P<role{i}>top|peak|apex|tip|bottom|base|foundation|middle"
               r"|(?:second|third|fourth|fifth|2nd|3rd|4th|5th)(?=\s+(?:layer|level|row|tier)\b))")
LAYER_ROLE_RE = re.compile(
    r"(?:\b(?P<n0>\d+|a|an|one|the)\s+)?\b(?P<c0>" + _COLOR_LIST + r")\s+(?:(?P<noun0>blocks?|cubes?|ones?|rows?|layers?)\s+)?"
    r"(?:(?:is|are|goes|go|sits?|stands?)\s+)?(?:on|at|as|in|for|forms?|making|makes)\s+(?:the\s+)?"
    + _LAYER_ROLE.format(i=0) + r"\b(?!\s+of\b)"
    r"|\b" + _LAYER_ROLE.format(i=1) + r"(?:\s+(?:layer|level|row|tier|block|cube|one))?\s+"
    r"(?:is|are|of|made\s+of|with|in)\s+(?:the\s+|a\s+|an\s+)?(?:\d+\s+)?(?P<c1>(?:" + "|".join(COLORS) + r")(?:(?:\s*,\s*|,?\s+and\s+)"
    r"(?:" + "|".join(COLORS) + r")\b(?!\s+(?:(?:blocks?|cubes?|ones?)\s+)?(?:on|onto|at|in|to|of|is|are)\b))*)\b"
    r"(?:\s+(?P<noun1>blocks?|cubes?|ones?))?"
    r"|(?:\b(?:a|an|the)\s+|(?<=,\s)|(?<=:\s)|(?<=;\s))(?P<c2>" + "|".join(COLORS) + r")\s+" + _LAYER_ROLE.format(i=2)
    + r"\b(?!\s+of\b)"
    r"|\b(?:the\s+)?(?:(?P<n3>\d+)\s+)?" + _LAYER_ROLE.format(i=3) + r"(?:\s+(?P<m3>\d+))?"
    r"(?:\s+(?P<noun3>layer|level|row|tier|blocks|cubes|ones))?\s*:?\s+(?:being\s+|should\s+be\s+|must\s+be\s+)?(?:all\s+)?"
    r"(?:(?P<k3>\d+)\s+)?(?P<c3>" + _COLOR_LIST + r")\b(?!\s+(?:(?:blocks?|cubes?|ones?)\s+)?(?:on|onto|at|in|to|of|is|are)\b)"
    r"(?:\s+(?:blocks?|cubes?|ones?))?(?<=\w)(?=\s*(?:[,.;]|$|\s+(?:and|with|while)\b))"
    r"|\bthe\s+(?P<n4>\d+)\s+(?:(?:blocks|cubes|ones)\s+)?(?:on|at|in)\s+the\s+" + _LAYER_ROLE.format(i=4)
    + r"(?:\s+(?:layer|level|row|tier))?\s+(?:being|are|is|should\s+be|must\s+be)\s+(?:all\s+)?(?P<c4>" + _COLOR_LIST + r")\b")
"""A colour given a layer of a pyramid or wall ("yellow on top", "the red blocks at the
base", "the top is blue", "a base of red blocks", "a blue base", "a green middle layer", "the
bottom row red", "the bottom three red", "the three on the bottom being red"):
``c0``..``c4`` the colour, ``role0``..``role4`` the layer word (top, peak,
apex, tip: the highest layer; bottom, base, foundation: the lowest; middle: the one between
in a structure three layers high); ``n0``, ``n3``, ``n4`` a count or article before the colour and
``k3`` a count after the layer word ("the bottom row 3 gray blocks"),
``noun0``/``noun1`` the noun after it ("a red block": one cube; "red blocks", "a red base":
the whole layer)."""

LAYER_SYNONYM_RE = re.compile(r"\b(?:(?P<low>lower|lowest|bottommost|first)|(?P<high>upper|uppermost|topmost|highest))"
                              r"\s+(?=(?:layer|level|row|tier)\b)")
"""A layer named by a comparative ("the lower layer", "the upper row"): read as "bottom" or
"top" (:func:`rpg.schema.reading.normalize`); "first" layer counts from the bottom (the
other ordinals are :data:`LAYER_ORDINALS`)."""

LISTED_ROW_RE = re.compile(
    r"\b(?P<role>top|bottom|base|middle|upper|lower|first|second|third)\s+(?:row|layer|level|tier|course|storey|story)\s*"
    r"(?::|\s+(?:of|is|has|with|made\s+of)\b)?\s*(?:the\s+)?"
    r"(?P<cs>(?:" + "|".join(COLORS) + r")(?:(?:\s*,\s*|\s+)(?:" + "|".join(COLORS) + r"))*(?:,?\s+and\s+(?:"
    + "|".join(COLORS) + r"))?)(?=\s*(?:blocks?|cubes?|ones?)?\s*(?:[,.;]|$|\s+(?:and|with|then)\b))")
"""A layer whose cubes are listed one by one ("a bottom row of blue, green, blue"): ``role`` the
layer word, ``cs`` the colours (:func:`rpg.schema.readers.structures.listed_layers`)."""

LISTED_ROW_LAYER = {"bottom": 0, "base": 0, "lower": 0, "first": 0, "second": 1, "middle": 1, "third": 2}
"""A layer word of :data:`LISTED_ROW_RE` -> its layer from the table ("top" and "upper": the last)."""

_RUN = rf"(?:\d+|one|two|three|four|five|six)\s+(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?"
COUNTED_RUNS_RE = re.compile(rf"\b{_RUN}(?:\s*,?\s*(?:and\s+)?(?:then|followed\s+by|and\s+after\s+(?:that|them))\s+{_RUN})+\b"
                             r"(?!\s+(?:each|apiece)\b)")
"""Runs of cubes of one colour counted and said in order ("3 blue cubes and then 3 white cubes", "2 red followed by 1 green"):
each cube listed (:func:`counted_runs_listed`), so an ordered structure reads them in that order (each run had been read as
one cube, and refused)."""


COUNT_THEN_LIST_RE = re.compile(rf"\b(?P<n>\d+|two|three|four|five|six)\s+(?:cubes|blocks)\s*\(\s*(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?"
                                rf"(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+)\s*\)")
"""Cubes counted and then listed in brackets ("a bottom row of three cubes (red, green and blue)"): the list alone where it
holds as many cubes as counted and names a layer's cubes; with another count, refused (:func:`count_then_list`); the count
had been read beside the list, as cubes of its own."""


def count_then_list(m: re.Match) -> str:
    """The list of :data:`COUNT_THEN_LIST_RE`'s match where its length is the count and it follows a layer ("bottom row of");
    as written where the count fits elsewhere (other rules read "a row of three cubes (red, green, blue) running ..."); else
    the count and the list after a colon, which the readers' count checks refuse."""
    listed = re.findall(rf"\b(?:{COLOR_RE})\b", m.group("l"))
    if len(listed) == count_word(m.group("n")):  # a layer's cubes ("a bottom row of three cubes (red, green and blue)"): the
        # list; elsewhere as written, which other rules read ("a row of three cubes (red, green, blue) running ...")
        return m.group("l") if re.search(r"\b(?:bottom|top|middle|first|second)\s+(?:row|layer|level|tier)\s+of\s+$",
                                         m.string[:m.start()]) else m.group(0)
    return f"{m.group('n')} cubes: {m.group('l')}"  # another count: said as "4 cubes: red, green and blue", which is refused
    # (a fourth cube had been made up)


def counted_runs_listed(m: re.Match) -> str:
    """``"blue, blue, blue, then white, white, white"`` for :data:`COUNTED_RUNS_RE`'s match; as written where a run counts
    more cubes than a task may hold."""
    runs = [(count_word(n), c) for n, c in re.findall(rf"(\d+|one|two|three|four|five|six)\s+({COLOR_RE})\b", m.group(0))]
    if sum(n for n, _ in runs) > 12 or any(n < 1 for n, _ in runs) or re.match(
            r"\s+(?:on\s+top|at\s+the\s+(?:top|bottom|base)|on\s+the\s+bottom|above|below|under|beneath|on\s+(?:it|them))\b",
            m.string[m.end():]):  # "two white ones, then three black ones on top": the last run's place (read as said)
        return m.group(0)
    return ", then ".join(", ".join([c] * n) for n, c in runs)


LAYER_FROM_BOTTOM_RE = re.compile(rf"(?P<cubes>\b(?:\d+|the|a|an|one)\s+(?:{COLOR_RE})\s+(?:blocks?|cubes?))\s+(?:(?:is|are|go|goes)\s+)?"
                                  r"(?:in\s+the\s+|on\s+the\s+)?(?P<k>second|third|fourth|fifth|2nd|3rd|4th|5th)\s+(?:(?:layer|row|level|tier)\s+)?"
                                  r"from\s+the\s+bottom\b")
"""Cubes given a layer counted from the table ("3 yellow blocks second from the bottom") of a layered structure: said as
"in the second layer", which :data:`LAYER_ROLE_RE` reads."""

_LAYER_CUBES = rf"(?P<cubes>\b(?:\d+|the|a|an|{COUNT_WORD_RE})\s+(?:{COLOR_RE})\s+(?:blocks?|cubes?))"
LAYER_ABOVE_RE = re.compile(_LAYER_CUBES + r"\s+(?:(?:is|are|go|goes|sit|sits|sitting|rest|rests|resting|placed)\s+)?(?:directly\s+|right\s+)?"
                            r"(?:above|over|on\s+top\s+of|on)\s+(?:them|those|these|that(?:\s+(?:row|layer|level|tier))?)\b")
"""Cubes of a layered structure said to go above the layer said before them ("three white cubes on the bottom row, two
white cubes above them and one white cube at the peak"): that layer's next one (:func:`layers_said_relatively`)."""

_LAYER_SAID_RE = re.compile(r"\b(?P<bottom>bottom|base|foundation|lowest|first)\s+(?:row|layer|level|tier)\b|\bon\s+the\s+(?P<bottom2>bottom|base)\b"
                            r"|\b(?P<k>second|third|fourth|fifth)\s+(?:row|layer|level|tier)\b")
LAYER_BELOW_ABOVE_RE = re.compile(_LAYER_CUBES.replace("cubes>", "low>") + r"\s+(?:(?:go|goes|are|is)\s+)?(?:below|underneath|beneath|under)"
                                  r"(?:\s*,\s*(?:and\s+|with\s+)?|\s+(?:and|with)\s+)" + _LAYER_CUBES.replace("cubes>", "high>")
                                  + r"\s+(?:(?:go|goes|are|is)\s+)?(?:above|over|on\s+top)(?:\s+(?:of\s+)?(?:them|those|these))?"
                                  r"(?=\s*(?:[.;!]|$))")
"""The two layers of a structure two layers high said as the cubes below and the cubes above ("a two-row wall: three blue
cubes below, three green cubes above"): its bottom and top rows (:func:`layers_said_relatively`)."""

_LAYER_WORDS = ("first", "second", "third", "fourth", "fifth")

LAYER_PAIR_RE = re.compile(_LAYER_CUBES.replace("cubes>", "a>") + r"\s+(?:(?:go|goes|are|is|sit|sits|sitting|stand|stands|placed|set)\s+)?"
                           r"(?:(?P<below>below|under|underneath|beneath)|(?P<above>above|over|on\s+top\s+of|atop|on))\s+"
                           + _LAYER_CUBES.replace("cubes>", "b>") + r"(?![a-z])(?!\s+(?:(?:go|goes|are|is|sit|sits)\s+)?(?:below|under|underneath|beneath"
                           r"|above|over|on(?!\s+top\s*(?:[.;,!]|$))|atop)\b)")  # ("... on 2 orange cubes on top.": "on top of"
                           # said again as the normaliser writes it)
"""A structure's two layers said as one set of cubes under or on another ("a wall: two orange cubes under two pink cubes",
"two pink cubes on top of two orange cubes"): its bottom and top rows (:func:`layers_said_relatively`; the layers had been
dropped, or, said "on top of", read upside down)."""
_LAYER_MORE_RE = re.compile(r"\b(?:middle|third|fourth|peak|apex|summit|(?:three|four|five|3|4|5)[\s-]+(?:rows?|layers?|levels?|tiers?|high|tall))\b")


def layers_said_relatively(text: str) -> str:
    """``text`` (a layered structure's, lower case) with each layer said relative to another written as its place from the
    table: "above them" after the bottom row is the second layer, after the second the third (:data:`LAYER_ABOVE_RE`; left
    as it is where no layer was said before it); "N X cubes below, M Y cubes above" of a structure said two layers high, or of a wall
    with no other layer said (:data:`LAYER_BELOW_ABOVE_RE`), its bottom and top rows.  (The cubes above had been read on top of one cube, and the
    count of the cubes below taken for the wall's width.)"""
    def above(m: re.Match) -> str:
        said = list(_LAYER_SAID_RE.finditer(m.string[:m.start()]))
        if not said:
            return m.group(0)
        last = said[-1]
        if re.search(rf"\b(?:{COLOR_RE})\b", m.string[last.end():m.start()]):
            return m.group(0)  # cubes said between that layer and these, with no layer read: above which is unsaid
        k = 0 if (last.group("bottom") or last.group("bottom2")) else _LAYER_WORDS.index(last.group("k"))
        return m.group(0) if k + 1 >= len(_LAYER_WORDS) else f"{m.group('cubes')} in the {_LAYER_WORDS[k + 1]} layer"

    for _ in range(len(_LAYER_WORDS)):  # each in turn: the one after reads the layer this one became
        new = LAYER_ABOVE_RE.sub(above, text, count=1)
        if new == text:
            break
        text = new
    if re.search(r"\b(?:two|2)[\s-]+(?:rows?|layers?|levels?|tiers?|high|tall)\b", text) \
            or (re.search(r"\bwalls?\b", text) and not _LAYER_SAID_RE.search(text) and not _LAYER_MORE_RE.search(text)):
        text = LAYER_BELOW_ABOVE_RE.sub(lambda m: f"{m.group('low')} in the bottom row, {m.group('high')} in the top row", text)
    pairs = list(LAYER_PAIR_RE.finditer(text))
    if len(pairs) == 1 and not _LAYER_SAID_RE.search(text) and not _LAYER_MORE_RE.search(text) \
            and re.search(r"\b(?:walls?|pyramids?)\b", text):
        m = pairs[0]
        low, high = (m.group("a"), m.group("b")) if m.group("below") else (m.group("b"), m.group("a"))
        text = text[:m.start()] + f"{low} in the bottom row, {high} in the top row" + text[m.end():]
    return text


LAYER_ORDINALS = {"second": 1, "2nd": 1, "third": 2, "3rd": 2, "fourth": 3, "4th": 3, "fifth": 4, "5th": 4}
"""A layer named by its place counted from the table ("the second row": layer 1, the bottom one
being 0)."""

LAYER_WORDS = {"top": "top", "peak": "top", "apex": "top", "tip": "top", "bottom": "bottom", "base": "bottom",
               "foundation": "bottom", "middle": "middle"}
"""A layer word of :data:`LAYER_ROLE_RE` -> the layer it names."""

LABEL_TOKEN = r"(?<![\w'\-/])(?:[A-Z]|\d)(?![\w'\-/])"
"""One label cube's name as the normalised, case-kept text writes it: a capital letter or a digit standing alone."""

_LABEL_ITEM = rf"(?:the\s+)?(?:(?:digit|letter|number)\s+)?{LABEL_TOKEN}(?:\s+(?:cube|block))?"
_LABEL_ITEMS = rf"(?P<l>{_LABEL_ITEM}(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+){_LABEL_ITEM})*)"
_PYRAMID_LAYER = r"(?P<r>bottom|base|foundation|top|apex|peak|tip|middle)(?:\s+(?:layer|row|level|tier))?"

LABEL_LAYER_ROLE_RES: tuple[re.Pattern, ...] = (
    re.compile(_LABEL_ITEMS + r"\s+(?:(?:cubes|blocks)\s+)?(?:(?:is|are|goes|go|sits?|stands?|should\s+be|must\s+be)\s+)?"
               r"(?:on|at|in|as|for|forming|form)\s+(?:the\s+)?(?:very\s+)?" + _PYRAMID_LAYER + r"\b(?!\s+of\b)"),
    re.compile(r"\b(?:the\s+)?" + _PYRAMID_LAYER + r"\s*(?:is|are|:|=|has|holds)\s+(?:made\s+of\s+)?(?:the\s+)?"
               r"(?:(?:digit|letter|number)\s+)?(?:(?:cubes|blocks)\s+)?" + _LABEL_ITEMS),
    re.compile(r"\ba\s+" + _PYRAMID_LAYER + r"\s+(?:made\s+)?of\s+(?:the\s+)?(?:(?:digit|letter|number)\s+)?(?:(?:cubes|blocks)\s+)?"
               + _LABEL_ITEMS),
)
"""Label cubes given a layer of a pyramid ("the digit cubes 2, 4 and 6 at the base", "with Y on top", "A and B on the
bottom, C at the apex", "the base is 5 and 6", "with a base of the letter blocks D, G and T"): ``l`` the labels, ``r`` the
layer word (:data:`LAYER_WORDS`)."""

LABEL_CUBE_SAID_RES: tuple[re.Pattern, ...] = (
    re.compile(r"\b(?:block|cube)s?\s+(?:marked|labell?ed|showing)\s+(?:an?\s+|the\s+)?(?:(?:letter|digit|number)\s+)?"
               r"'?(?P<l>[A-Z0-9])'?(?![A-Za-z0-9'])(?!\s+(?:[a-z]+\s+)?(?:blocks|cubes)\b)"),
    re.compile(r"\b(?i:the)\s+'?(?P<l>[A-Z0-9])'?\s+(?i:block|cube)\b"),
    re.compile(r"\b(?i:block|cube)[ \t]+'?(?P<l>[A-Z0-9])'?(?![A-Za-z0-9'])"),
    # "block b in the middle": a letter in lower case where a label stands (it had been dropped, a red cube centred)
    re.compile(r"\b(?i:block|cube)[ \t]+(?P<l>[a-z])\b(?=\s*(?:[,.;:!?)]|$|\s+(?:at|on|onto|in|into|next|to|between|and|or|under"
               r"|behind|beside|above|below|near|left|right|goes|go|is|should|must|sits)\b))"),
)
"""A label cube said by its mark ("the block marked 5", "the 9 block", "block C"; a digit on the next line, "cube\n2. put
...", is a list's number): each such label must have a place in the task read (:func:`rpg.schema.accounting.unaccounted`;
"the block marked 5 on it" had been dropped, silently)."""

LABEL_RELATED_RE = re.compile(r"\b(?:on(?:\s+top\s+of)?|onto|atop|above|over|under|below|beneath|underneath|next\s+to|beside|"
                              r"(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|behind|between|by|near)\s+(?:the\s+)?"
                              r"(?:(?:digit|letter|number)\s+)?" + LABEL_TOKEN)
"""A label cube related to another ("3 on top of 1", "A next to B"): what no layer role says."""

LABEL_PYRAMID_UNREAD_RE = re.compile(
    r"\b(?:upon|crown\w*|tops?|topped|summit|capstone|peak|apex|upper\w*|lower\w*|highest|lowest|levels?|layers?|rows?|tiers?|base"
    r"|bottom|first|second|third|reads?|reading|spell\w*|order\w*|sequence|flat|triangle\w*|3d|3-d|three-dimensional|only|then"
    r"|move\w*|away|each\s+other|higher|above|below|under\w*|over|beneath|left|right|front|back|middle|cent(?:er|re)|between|next"
    r"|beside|near|far|except|but|instead|actually|made|not|no|without)\b")
"""Words of a label pyramid's text that no layer role it reads (:data:`LABEL_LAYER_ROLE_RES`) holds ("with A resting upon B
and C", "the top cube is A", "first layer A, B and C", "so it reads CAB", "flat in a triangle"): refused, never dropped."""

LABEL_COUNT_AFTER_RE = re.compile(r"\s*(?:-|\s+(?:[a-z]+\s+){0,2}(?:blocks|cubes|ones|layers|levels|tiers|rows|stor(?:ey|y|ie)s?|high|wide|tall)\b)")
"""Words after a digit that make it a count ("3 blocks", "2 layers", "3-2-1"), not a digit cube's name."""

LABEL_ARTICLE_AFTER_RE = re.compile(r"\s+(?!(?:and|on|at|in|is|are|goes|sits|cube|block)\b)[a-z]")
"""Words after a capital "A" that make it an article ("A four-cube pyramid", "A pyramid"), not the letter cube A."""


ROLE_BEFORE = re.compile(r"\bwith\s+(?:the\s+|a\s+|an\s+|1\s+)?[a-z0-9]+(?:\s+(?:block|cube|one|digit|letter))?\s*$")
"""Text before "in the middle" that makes it a cube's role in a structure ("with blue in the
middle"), not a place on the table."""

ROLE_LIST_BEFORE = re.compile(r"\b(?:with|so\s+that|such\s+that|where)\s+(?:[^.;]*(?:\b(?:on|at|in)\s+the\s+(?:far\s+|very\s+)?"
                              r"(?:left|right|middle|center|centre|top|bottom)|\bis\s+(?:left|right))(?:most)?\b[^.;]*(?:,|\band)\s+)?"
                              r"(?:the\s+)?[a-z0-9]+"
                              r"(?:\s+(?:block|cube|one))?(?:\s+(?:is|goes|sits))?\s*$")
"""Text before a bare side that makes it a cube's role in a list of roles ("with red on the left,
green in the middle, and blue on the right"; "so that orange is leftmost, purple is in the
middle"), not a place on the table."""

LAYER_LIST_BEFORE = re.compile(r"(?:(?:,|\band|\bthen)\s+(?:the\s+|a\s+|an\s+)?(?:(?:\d+\s+)?[a-z]+|\d+)"
                               r"|\b(?:bottom|base)(?:\s+(?:layer|row|level|tier))?\s+\d+)(?:\s+(?:blocks?|cubes?|ones?))?\s*$")
LAYERED_TEXT = re.compile(r"\b(?:pyramid|wall|tower|stack)s?\b.*\b(?:base|bottom|top)\b|\b(?:base|bottom|top)\b.*\b(?:pyramid|wall|tower|stack)s?\b")
"""A colour or a count in a list of layers before "in the middle" ("3 red at the base, 2 green in the
middle", "three on the bottom, two in the middle", "3 on the bottom 2 in the middle") in a text about a layered structure: "the middle" is then its middle layer, not the
centre of the table."""


def names_a_role(before: str, text: str) -> bool:
    """Whether "in the middle" (or another bare side) after ``before`` gives a cube a role in a
    structure ("with blue in the middle", "3 red at the base, 2 green in the middle") rather
    than a place on the table; ``text`` is the whole instruction."""
    return bool(ROLE_BEFORE.search(before) or ROLE_LIST_BEFORE.search(before) or END_ROLE_LIST_BEFORE.search(before)
                or COLON_ROLE_LIST_BEFORE.search(before) or SORT_END_BEFORE.search(before)
                or (LAYER_LIST_BEFORE.search(before) and LAYERED_TEXT.search(text))
                or (MIDDLE_GROUP_BEFORE.search(before) and re.search(r"\b(?:towers?|stacks?|rows?|lines?)\b", text))
                or (COMMA_ROLE_BEFORE.search(before) and re.search(r"\b(?:rows?|lines?|line\s+up)\b", text)
                    and not re.search(r"\b(?:towers?|stacks?|stacked|columns?|piles?)\b", text)))


COMMA_ROLE_BEFORE = re.compile(rf"(?:(?:^|,)\s*(?:the\s+)?(?:{COLOR_RE}|\d)|\band\s+(?:the\s+)?\d)(?:\s+(?:block|cube|one))?(?:\s+(?:is|goes|sits))?\s*$")
"""Text before a bare side that makes it the place of a cube said after a comma in a row ("two blue and one orange in a
row, orange in the centre", "5 and 8 in a row, 8 on the left and 5 on the right", the text's first words "Orange on the
left, yellow in the middle, blue on the right, all in one row"): its place in the row, not the table's."""


MIDDLE_GROUP_BEFORE = re.compile(r"(?:^|[;,.]\s*|\band\s+)the\s+(?:other\s+)?\d+(?:\s+(?:cubes|blocks|ones))?\s*$")
"""Text before "in the middle" that makes it the middle cubes of a tower or row whose ends were given ("the bottom one is
black and the top one is yellow; the two in the middle are both blue"), not the table's centre."""


TOP_ROLE_SAID_RE = re.compile(rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+)?(?:on\s+top|at\s+the\s+top)\b(?!\s+of\b)")
BOTTOM_ROLE_SAID_RE = re.compile(rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+)?(?:on|at)\s+the\s+(?:bottom|base)\b(?!\s+of\b)")
"""A tower's two ends each given a cube ("red on top, ..., blue on the bottom"): then "in the middle" is the
middle of that tower, not of the table (:func:`rpg.schema.reading.mark_regions`; "in the centre" stays a place)."""


SORT_END_WORD = r"(?:largest|biggest|greatest|highest|smallest|lowest|larger|bigger|greater|higher|smaller)"
"""A label sort's end said by its largest or smallest label ("the biggest number", "smallest"; of
two, "the larger number")."""
SORT_END_NOUN = r"(?:\s+(?:number|digit|value|label|letter|one|cube|block))?"
"""The noun that may follow :data:`SORT_END_WORD` ("largest number", "smallest one")."""

LABEL_PYRAMID_ORDER_RE = re.compile(rf"\b(?:{SORT_END_WORD}|ascending|descending|increasing|decreasing|sorted|order\w*"
                                    r"|alphabetical\w*|revers\w*|numerical\w*)\b")
"""An order said of a label pyramid's cubes ("sorted ascending", "smallest up top"): none its layers read (refused)."""

SORT_END_BEFORE = re.compile(r"\b(?:the\s+)?" + SORT_END_WORD + SORT_END_NOUN + r"(?:\s+(?:is|goes|sits))?\s*$")
"""Text before a bare side that makes it the end of a sorted line ("digits 4, 2 and 7 in a row,
largest on the left"): the sort's largest or smallest label, not a place on the table."""

END_ROLE_LIST_BEFORE = re.compile(r"\b(?:at|on)\s+the\s+(?:left|right|front|back|top|bottom|far)\s+end\b[^.;]*(?:,|\band)\s+"
                                  r"(?:the\s+)?[a-z0-9]+(?:\s+(?:block|cube|one))?(?:\s+(?:is|goes|sits))?\s*$")
"""Text before "in the middle" that lists the ends of a line first ("red at the left end, blue at
the right end, yellow in the middle"): the middle is a cube's role too."""

COLON_ROLE_LIST_BEFORE = re.compile(r"\b(?:row|line|tower|stack|column|pyramid|wall)s?\b[^:.;]*:\s*(?:[^.;:]*(?:,|\band)\s+)?(?:the\s+)?"
                                    r"(?:" + "|".join(COLORS) + r"|\d+)(?:\s+(?:block|cube|one)s?)?(?:\s+(?:is|goes|sits))?\s*$")
"""Text before a bare side in a list of cubes given their places after a structure and a colon
("a row: red on the left, blue on the right, green in the middle"): each side a cube's role."""


ANTECEDENT_RE = re.compile(
    r"\b(?:blocks?|cubes?|box(?:es)?|bricks?|pieces?|objects?|items?|patch(?:es)?|letters?|digits?|numbers?|words?"
    r"|" + "|".join(COLORS) + r")\b"
    r"|\b(?:a|an|the|one|this|that|each|every|\d+)\s+(?:[a-z\-]+\s+)?(?:towers?|stacks?|piles?|lines?|rows?|columns?"
    r"|pyramids?|circles?|rings?|grids?|walls?|squares?|structures?)\b")
"""What a pronoun can refer back to: a cube, a structure, a patch, a label or a colour named
earlier in the instruction."""


# ---------------------------------------------------------------------------
# Steering edits (rpg.steer.edits reads these; the parser does not)
# ---------------------------------------------------------------------------

EDIT_FRESH_RE = re.compile(
    r"(?i)\b(?:new task|another task|start over|start fresh|from scratch|unrelated|something (?:completely |totally )?(?:different|else)"
    r"|(?:a\s+)?(?:completely|totally|entirely)\s+(?:different|new|other)\s+(?:task|one|thing)|different task"
    r"|forget (?:it|that|this|everything|about it|all (?:of )?that)|scr(?:atch|ap) (?:all (?:of )?that|that|this|it|everything)"
    r"(?:\s+and\s+start\s+(?:again|over))?|(?:a\s+)?new\s+(?:thing|one)(?=\s*[:,.!\-])|diff(?:erent)?\s+task|(?:a\s+)?brand\s+new\s+one"
    r"|(?:let'?s\s+)?start (?:again|anew)|never\s*mind|let'?s do something else"
    r"|(?:a\s+)?(?:completely|totally|entirely)\s+(?:different|new|other)\s+(?:set|set-?up|scene|game|puzzle|job|room|project|level)"
    r"|(?:a\s+)?(?:different|new|another)\s+(?:set-?up|scene|game|puzzle|job|room|project|house|idea)(?=\s*[:,.!\-])"
    r"|nothing\s+(?:carried\s+over|(?:kept\s+)?from\s+(?:before|earlier|the\s+(?:old|last|previous|first)\s+one))"
    r"|(?:a\s+)?(?:completely|totally|entirely|brand)\s+new\s+(?:build|piece|protocol|study|round|session|exercise|challenge|layout"
    r"|arrangement|design|setup|set-up)|(?:a\s+)?new\s+(?:piece|build|protocol|study|round|session|exercise|challenge)(?=\s*(?:now\s*)?[:,.!\-])"
    r"|nothing\s+to\s+do\s+with\s+(?:the|this|that|our|my)\s+(?:row|line|tower|stack|pyramid|wall|pile|task|one|last\s+one|"
    r"(?:first|previous|old)\s+one))\b[:,.!]?")
"""Words that make an edit a new, unrelated task (Fresh): "start over: ...", "completely
different task now: ...", "New room, new puzzle: ...", "New idea for the back counter, nothing to do with the row: ...", "A new
piece now, nothing from before: ...", "totally new build: ..."."""

EDIT_ANAPHORA_RE = re.compile(
    r"\b(?:it|them|they|its|their|those|these|instead|back|again|now|also|too|more|rather|both|whole)\b"
    r"|\b(?:add|append|change|replace|swap|substitute|remove|delete|flip|reverse|invert|keep|undo|revert|turn|paint|recolou?r)\b"
    r"|\bmake (?:the|it|them)\b|\bas well\b"
    r"|\bthe\s+(?:[a-z]+\s+)?(?:[a-z]+\s+and\s+[a-z]+\s+)?ones?\b"
    r"|\b(?:the|that|this|your|my|our)\s+(?:existing|current|same|present|old)\b"
    r"|\b(?:the|that|this)\s+(?:whole\s+|entire\s+)?(?:" + "|".join(w for k in STRUCTURE_KINDS.values() for w in k.words)
    + r"|wall|structure|thing)\b(?!\s+(?:of|with)\b)"
    r"|\b(?:you|we|i)\s+(?:have\s+|just\s+|already\s+)*(?:built|made|stacked|created|constructed|have)\b"
    r"|\b(?:from|as)\s+before\b|\bso far\b")
"""Words that make an edit a change to the current task rather than a whole new one: pronouns
("it", "them", "the orange one"), additions ("also", "too", "as well"), edit verbs and a
reference to what exists ("the tower you just built", "the existing line")."""

_EDIT_STRUCTURE_WORDS = "|".join(f"{w}s?" for k in STRUCTURE_KINDS.values() for w in k.words)

EDIT_REFERS_RE = re.compile(
    r"\b(?:the|that|this)\s+(?:whole\s+|entire\s+)?(?:" + _EDIT_STRUCTURE_WORDS + r"|wall|structure|thing)\b(?!\s+(?:of|with)\b)"
    r"|\b(?:it|them|they|its|their|those|these|both|whole)\b|\bthe\s+(?:[a-z]+\s+)?(?:[a-z]+\s+and\s+[a-z]+\s+)?ones?\b"
    r"|\b(?:the|that|this|your|my|our)\s+(?:existing|current|same|present|old)\b")
"""Words of an edit that stand for what the task has ("it", "the orange one", "the tower"):
with them and no change read, the edit is no whole new task (it is refused)."""

EDIT_CHANGE_VERBS = r"change|replace|swap|substitute|remove|delete|flip|reverse|invert|undo|revert|paint|recolou?r"
EDIT_CHANGE_VERB_RE = re.compile(rf"\b(?:{EDIT_CHANGE_VERBS})\b")
"""Verbs that change a task and state no task: an edit with one and no change read is refused."""

EDIT_CLAUSE_VERBS = rf"add|make|insert|append|{EDIT_CHANGE_VERBS}"
"""The verbs that open a change clause of an edit: :data:`EDIT_CHANGE_VERBS` and those that add or restate
(:data:`rpg.steer.edits._CHANGE_CLAUSE_SPLIT` reads each such clause alone)."""

EDIT_OWN_VERB_RE = re.compile(rf"(?i)(?:{EDIT_CLAUSE_VERBS}|extend|raise|lower|shift|move|put|place|set|stack|drop|slide|push|bring"
                               r"|return|restore|keep|leave|turn|use|grow|shrink|widen|lengthen|shorten|top|attach|get|take|go)")
"""Verbs the steering reads as its own operations: never rewritten by :func:`rpg.steer.edits._caused_motion_in_edit`."""


ROWS_SWAPPED_RE = re.compile(r"(?i)^\s*(?:(?:ok(?:ay)?|now|so|and|then)\s*,?\s*)*(?:swap|switch|exchange|flip|trade)\s+(?:the\s+)?(?:two\s+)?"
                              r"(?:rows|layers|levels|tiers|courses)(?:\s+(?:around|round|over))?\s*(?:[:,\u2013\u2014-]\s*(?P<rest>[^.!]+?))?\s*[.!]?\s*$")
"""An edit that swaps a layered structure's rows ("Swap the rows: gray on the bottom, brown on top."): read by
:func:`rpg.steer.steering._rows_swapped_named`."""



EDIT_SWAP_BOTH_RE = re.compile(r"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|actually|and|then|just|hmm|nah)\s*,?\s+)*"
                               r"(?:(?:the\s+two(?:\s+(?:cubes|blocks))?|they|both(?:\s+(?:cubes|blocks))?)\s+(?:should\s+|must\s+|need\s+to\s+)?)?"
                               r"(?:swap|switch|exchange|interchange|trade)\s+(?:them|the\s+two(?:\s+(?:cubes|blocks))?|both(?:\s+of\s+(?:them|their\s+(?:places"
                               r"|sides|positions|spots|patches)))?|(?:their|the)\s+(?:places|sides|positions|spots|patches)|places|sides|positions|patches"
                               r"|the\s+(?:cubes|blocks)(?:\s+(?:between|on|across)\s+the\s+(?:two\s+)?patches)?"
                               r"|which\s+(?:cube|block)\s+goes\s+(?:on|where|to)\s+(?:which\s+patch)?)"
                               r"(?:\s+(?:around|over|please))*\s*(?:,\s*nothing\s+else)?\s*[.!]?\s*$")
"""An edit that swaps the task's two cubes without naming them ("switch them", "please interchange both
of their sides", "swap the patches", "the two cubes should trade patches")."""

EDIT_OF_THE_TASK_RE = re.compile(r"(?i)\b(?:instead|like\s+(?:that|this|it|before)|the\s+same|as\s+(?:before|it\s+is))\b")
"""Words that make an edit stated as a whole task about the task's own cubes ("tower in the back instead",
"3 towers like that")."""

EDIT_ADDITIVE_RE = re.compile(r"\b(?:also|too|as well|add|additionally|additional|another|in addition|plus|(?:\d+|one|two|three|a\s+few|some)\s+more"
                              r"|an?\s+(?:second|third|fourth|separate|further)\s+(?:(?:[a-z]+\s+){0,2}?)(?:towers?|stacks?|piles?|heaps?|rows?"
                              r"|lines?|walls?|pyramids?|grids?|circles?|rings?|columns?))\b")
"""Words that make an edit an addition: what it states joins the task, the rest is kept ("a second heap of three brown
cubes" had replaced the task's pile)."""

EDIT_MOVES_A_TASK_CUBE_RE = re.compile(r"^\s*(?:(?:now|ok(?:ay)?|so|and|then|actually)[\s,]+)*(?:move|shift|relocate|slide|transfer)"
                                       r"\s+(?:the|that)\s+(?!.*\b(?:too|also|as\s+well)\b)", re.IGNORECASE)
"""An edit that moves a cube the task has to a new place ("Move the pink one onto a new green patch"): like "instead", it
replaces that cube's one placement (:func:`rpg.steer.relations.replaced_placement`); kept as well only when it says so
("... too")."""

EDIT_KEEP_TOO_RE = re.compile(r"(?i)\s*,?\s*\b(?:too|as\s+well)\b")
"""The words that keep a moved cube's old place as well ("move the cyan cube to the left too"; see
:data:`EDIT_MOVES_A_TASK_CUBE_RE`), unless that would put the cube in two places (then the words are the other cube's)."""

NEW_PATCH_RE = re.compile(r"\b(an?)\s+(?:new|fresh|second|separate|different|other)\s+(?=(?:[a-z]+\s+)?patch\b)", re.IGNORECASE)
"""A patch said as new ("onto a new green patch"): a patch of that colour, which the task then has."""

IT_ON_A_PATCH_RE = re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|so|and|then|just)[\s,]+)*(?P<v>put|stand|set|place|sit|move|rest)\s+it\s+"
                              rf"(?P<p>(?:on|onto|on\s+top\s+of)\s+(?:the|a)\s+(?:{COLOR_RE})\s+(?:goal\s+)?patch)\b")
"""An edit that puts "it" on a patch ("Stand it on the blue patch."): of a structure task, "it" is the structure."""

LABEL_EXCHANGE_RE = re.compile(
    r"^\s*(?:[^,:;.!?0-9]{1,40}[,:]\s*)?(?i:(?:(?:now|ok(?:ay)?|please|just|so|then)[\s,]+)*(?:swap|switch|replace|change|exchange|trade"
    r"|substitute)\s+(?:the\s+)?(?:(?:letter|digit|number|cube|block)\s+)?)'?[A-Z0-9]'?(?i:(?:\s+(?:cube|block|one))?\s+(?:(?:out\s+)?(?:for"
    r"|with|to|into)|and)\s+(?:an?\s+|the\s+)?(?:(?:letter|digit|number|cube|block)\s+)?)'?[A-Z0-9]'?(?i:(?:\s+(?:cube|block|one))?"
    r"(?:\s+instead)?)\s*[.!]?\s*$")
"""An edit that only replaces one label cube by another or exchanges two ("Wrong letter, swap the K out for an L.", "Swap E
and R."): the whole edit, with at most a short label before it (:func:`rpg.steer.steering._labels_exchanged`)."""

PRONOUN_CUBES_RE = re.compile(r"\b(?:of|stack|line\s+up|arrange|put|place|pile|group|gather|sort|use|with)\s+(?:all\s+(?:of\s+)?|both\s+(?:of\s+)?)?"
                               r"(?P<w>them|those|these)\b")
"""The pronoun "them" (or "those", "these") as the cubes of a structure or a placement ("make a row of them"): the cubes it
stands for must be named (:func:`rpg.schema.readers.pronoun_cubes_made_up`)."""

TOWER_TO_PATCH_RE = re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|so|and|then|just|actually)[\s,]+)*(?:move|put|stand|set|place|shift|slide|transfer)\s+"
                               r"(?:the\s+(?:whole\s+|entire\s+)?(?:tower|stack)|it)\s+(?:over\s+)?(?P<p>(?:on|onto|to)\s+(?:the|a)\s+(?:new\s+)?"
                               rf"(?:{COLOR_RE})\s+(?:goal\s+)?patch)(?:\s+instead)?\s*[.!]?\s*$")
"""An edit that moves a tower standing on a patch to another patch ("Move the stack to the yellow patch."): its bottom cube
moved, which replaces that cube's patch (:func:`rpg.steer.relations.replaced_placement`); read as an addition it had made a
second tower."""

SWAPPED_THEN_SAID_RE = re.compile(r"(?i)^\s*(?:(?P<label>[^:;,.!?]{2,40}):\s+)?(?:(?:now|ok(?:ay)?|so|and|then|right)[\s,]+)*(?:swap|switch|exchange|trade|flip)\s+"
                                  r"(?:them|the\s+two|those|these|both|places|sides|patches|spots|it)(?:\s+(?:over|around|round))?"
                                  r"(?:[^:;,.!?]{0,60}:|\s*[,:])\s*(?=\S)")
"""An exchange announced, then said in full ("Swap them over like switching kegs: white on the green patch, black on the
red patch.", "swap them, yellow on the red patch and blue on the green patch"): the statement after it is the edit when it
reads as a whole task (the announcement had named no change read)."""

STRUCTURE_COPIED_RE = re.compile(
    r"(?i)^\s*(?:(?:now|and|also|then|next)\s*,?\s+)*(?:build|make|add|put|stack|create|set\s+up)\s+(?:a\s+matching|an\s+identical"
    r"|a\s+second\s+identical|another\s+identical|a\s+copy\s+of\s+the|a\s+duplicate\s+of\s+the|an\s+exact\s+copy\s+of\s+the)\s+"
    r"(?P<s>tower|stack)(?:\s+of\s+it)?\s+(?P<place>(?:on|at|to)\s+the\s+(?:left|right|front|back)(?:\s+side)?(?:\s+of\s+the\s+table)?"
    r"|in\s+the\s+(?:back|front)\s+(?:left|right)\s+corner(?:\s+of\s+the\s+table)?)"
    r"(?:\s*,\s*(?:with\s+)?(?:the\s+)?same\s+colou?rs(?:\s+in\s+the\s+same\s+order)?)?\s*[.!]?\s*$")
"""An edit that adds a copy of the task's one tower in another place of the table ("Build a matching tower on the right
side, same colours in the same order."): read by :func:`rpg.steer.steering._copied_tower`."""

EDIT_CONTINUES_RE = re.compile(r"^\s*(?:and\s+|,\s*)?(?:then|next|after\s+that|afterwards|after\s+this)\b")
"""An edit that goes on from the task ("then put C on A", "next, the green cube on the red one"):
an addition, never a whole new task (it had replaced the task, dropping the cubes below)."""

EDIT_BESIDE_RE = re.compile(r"\b(?:left|right|beside|next to|near|behind|in front|front|back|between|around|by|"
                            r"side|apart|away|separate\w*)\b")
"""Words that place a cube added to a structure beside it, not in it ("add a pink block to
the left of the tower")."""

EDIT_LEADING_RE = re.compile(r"^\s*(?:now|ok(?:ay)?|actually|instead|then|next|and|with|so|please|also|oh|hmm|wait|but"
                             r"|can you|could you|would you|i'd like(?: to)?|i want(?: to)?|let's|lets)\b[,:]?\s*", re.IGNORECASE)
"""Words that open an edit and say nothing of the task ("ok now ...", "also ...")."""

EDIT_INTERJECTION_RE = re.compile(
    r"^\s*(?:(?:(?:no(?=\s*[,.!;]|\s+(?:wait|sorry|actually|hold\s+on|scratch))|nope\b|nah\b)|wait|hold\s+on|sorry|oops|hmm+|um+|uh+|mm+(?=\s*,))"
    r"\s*[,.!;]*\s*)+(?=\S)")
"""Words that open an edit as a correction and say nothing of the task ("no wait, put it next
to the blue block", "sorry, make it red", "nah put it on the patch"): not a negation, nor a time
("wait"); "no" opens one only before a pause or a correction word ("no blue blocks" is a negation)."""

INTENSIFIER_RIGHT_RE = re.compile(r"(?i)\b(?:right|directly|just)\s+(?=next\s+to\b|on\s+top\b|onto\b|behind\b|beside\b|in\s+front\b"
                                  r"|above\b|under\b|below\b|between\b|in\s+(?:the\s+)?(?:middle|center|centre)\b)")
""""Right" that only stresses a place ("right next to the blue block"): not the side "right"."""

EDIT_OPENING = r"^\s*(?:(?i:nah|no|ok(?:ay)?|so|and|then|hmm|actually|now)[\s,]+)*"
"""The words an edit may open with before what it says ("nah, other way round", "ok so instead of ...",
"actually, left to right: ..."): they change nothing."""

EDIT_SAME_COUNT_RE = re.compile(
    rf"(?i)^\s*(?:(?:now|ok(?:ay)?|then)\s*,?\s*)*(?:the\s+)?same\s+(?P<n>\d+|{COUNT_WORD_RE})\s*(?:cubes|blocks|ones)?\s*,?\s*"
    r"(?:but\s+)?(?=\S)(?!(?:letters?|digits?|numbers?|colou?rs?|labels?)\b)")
"""An edit that opens by saying the count of the version it builds on again ("same five but reversed", "same 4, but
pink on top"): checked, not applied (the steering refuses when the version has another count); the rest is the change."""

EDIT_REST_STAYS_RE = re.compile(
    rf"(?i)\s*[,;]\s*(?:and\s+|but\s+|while\s+)?(?:the\s+|all\s+the\s+)?(?:rest|others|other\s+(?:ones|cubes|blocks)|ones\s+in\s+between"
    r"|(?:ones|cubes|blocks)\s+in\s+(?:between|the\s+middle)|middle\s+ones|everything\s+else|remaining\s+(?:ones|cubes|blocks))\s+"
    rf"(?:(?:should|must|will|can)\s+)?(?:stay|stays|remain|remains|keep|keeps|are\s+still|still)\s+(?P<c>{COLOR_RE})\s*[.!]?\s*$")
"""A recolour's closing clause that says the other cubes keep their colour ("make both ends orange, the ones in between
stay blue", "bottom layer cyan, rest stay orange"): checked, not applied (the steering refuses when they are not)."""

_EDIT_LABEL_HAZARD_RE = re.compile(
    rf"\b(?:{COLOR_RE}|grey|\d+|one|two|three|four|five|six|same|again|back|undo|revert\w*|previous|last|first|original|version"
    r"|round|step|not|no|never|don't|only|instead|rather|reverse\w*|swap\w*|opposite|more|fewer|less|each|every|all|both|this|that"
    r"|these|those|them|if|unless|when|wait|actually|sorry|oops|cancel|forget|ignore|different|new|fresh|start\w*|over|scratch"
    r"|another|task|afresh|anew|clean|reset|begin\w*|separate|other|else|entirely|completely|whole|flip\w*|mirror\w*|invers\w*"
    r"|upside|backwards?|bad|wrong|example|counter\w*|non|trap|tall\w*|short\w*|big\w*|small\w*|wide\w*|narrow\w*|high\w*"
    r"|low\w*|harder|easier|bigger|smaller|add\w*|also|plus|extra|second|third|alongside|beside|it|its|piece|clue)\b|\bv\d")
"""What keeps a label before an edit's colon (:data:`EDIT_LABEL_RE`): a colour, a count, a version or a step of the
session, a negation, a restriction, a reversal, a pronoun for cubes, a condition, a take-back or a fresh start ("Start
over:", "Completely different task now:") may change the edit."""

EDIT_LABEL_RE = re.compile(r"^\s*(?P<l>[^:.;!?]{3,60}):\s+(?=(?:please\s+)?(?:make|put|add|insert|swap|switch|remove|take|move|change|use|turn"
                           r"|replace|place|stack|set|drop|delete|build|reverse|flip|the\s+[a-z]+\s+(?:cube|block)|the\s+[a-z]+\s+one|also"
                           r"|an?\s+(?:[a-z]+\s+)?(?:cube|block|one)|the\s+(?:tower|stack|row|line|pyramid|wall|pile|circle|grid)"
                           r"|(?:the\s+)?(?:[a-z]+\s+)?(?:cubes|blocks))\b)")
"""A label before an edit that says why or for whom ("Simplify it for the worksheet: make both rows green", "For the
demo: add a red cube on top", "feat: also put ...", "Protocol change: a C cube is added on top"): dropped when it names no cube, structure, place or count and holds nothing that may
change the edit (:data:`_EDIT_LABEL_HAZARD_RE`)."""


EDIT_REASON_SENTENCE_RE = re.compile(
    r"(?i)^\s*(?:(?:oh|well|ok(?:ay)?|so|hmm+|right|alright|honestly|yeah)\s*,?\s+)*"
    r"(?:that'?s|that\s+(?:is|was)|this\s+(?:is|was)|it'?s|it\s+(?:is|was)|(?:she|he|they|we|i|you)(?:'s|'re|'m|'ve|'d|\s+(?:is|are|was|were|am"
    r"|has|have|had|found|finds|find|got|gets|did|does|do|can|could|liked|likes|loved|loves|hated|hates|struggled|struggles|thinks|thought|think"
    r"|said|says|nailed|aced|breezed|finished|felt|feels|seems|seemed))|(?-i:(?!Let\b)[A-Z][a-z]+)(?:'s|\s+(?:is|was|found|finds|got|gets|did|does"
    r"|can|could|liked|likes|loved|hated|struggled|struggles|thinks|thought|said|says|has|had|nailed|aced|breezed|finished|felt|feels|seems"
    r"|seemed)))\b[^.!?;:]*[.!]\s*$")
"""A sentence of a steering edit that says why the change is made, of a person or of the version before ("That's too
much for today.", "She's good at this now.", "Maya found that too easy."): a statement, not a request; set aside when
another sentence of the edit says the change and it holds nothing of a task (:data:`EDIT_REASON_HAZARD_RE`)."""

EDIT_REASON_HAZARD_RE = re.compile(
    rf"\b(?:{COLOR_RE}|grey|\d+|one|two|three|four|five|six|seven|eight|nine|ten|left|right|front|back|top|bottom|middle|centre|center"
    r"|corner|patch\w*|edge|side|half|under\w*|below|above|over|next|beside|between|behind|near|far|tower\w*|stack\w*|rows?|lines?|pyramid\w*"
    r"|walls?|piles?|grids?|circles?|layers?|letters?|digits?|numbers?|labels?|make|put|add|remove|swap|move|change|reverse|flip|replace|take"
    r"|leave|keep|drop|not|no|never|n't|instead|only|should|must|need\w*|want\w*|wish\w*|rather|same|different|again|back|undo|revert\w*"
    r"|version|v\d|if|unless|when|until|before|after|then|previous|original|each|every|all|both|wrong|mistake|error|bug|sorry"
    r"|actually|start\w*|scratch|fresh|new|over|redo|restart|reset|clear|empty|double|twice|triple|half|tall\w*|short\w*|high\w*|low\w*"
    r"|long\w*|wide\w*|narrow\w*|big\w*|small\w*|large\w*|size|more|fewer|less|extra|missing|revers\w*|invert\w*|upside|flip\w*"
    r"|mirror\w*|supposed|meant|has\s+to|have\s+to|had\s+to|like\s+(?:it|them|the|that|this)|likes\s+(?:it|them|the)|says?|said|ask\w*"
    r"|wants?|would|'d|prefer\w*|better|worse|rather|could\s+use|fine\s+with|ok\s+with|okay\s+with|without|lacks?|needs?|so|apart"
    r"|together|spread\w*|diagonal\w*|around|round|away|close\w*|far|keep|stay\w*)\b")
EDIT_EXCLAMATION_RE = re.compile(r"(?i)^\s*[a-z']+(?:\s+[a-z']+){0,2}\s*[.!]+\s*$")
"""A sentence of one to three words before or after a steering edit's change ("Cut!", "Beautiful.", "Nice work!"): an
exclamation, set aside by :func:`rpg.steer.edits.reasons_set_aside` when it holds no word of a change or of a task
(:data:`EDIT_REASON_HAZARD_RE`, :data:`EDIT_SENTENCE_CHANGE_RE`, :data:`EDIT_EXCLAMATION_HAZARD_RE`)."""

EDIT_EXCLAMATION_HAZARD_RE = re.compile(
    r"(?i)\b(?:cent\w*|middle|corner\w*|edge\w*|end\w*|outer|inner|first|last|alternat\w*|sort\w*|spell\w*|rotat\w*|turn\w*"
    r"|upright|sideways|face\w*|aligned|straight\w*|rainbow|mixed|random\w*|shuffl\w*|colou?r\w*|letter\w*|digit\w*|fast\w*|slow\w*"
    r"|quick\w*|careful\w*|gentl\w*|higher|lower|closer|further|farther|nearer|tighter|looser|denser|sparser|even\w*|symmetr\w*"
    r"|square\w*|round\w*|flat\w*|vertical\w*|horizontal\w*|stop|done|finish\w*|end|enough|that|this|it|them|those|these|same|others?)\b")
"""Words that keep a short sentence (:data:`EDIT_EXCLAMATION_RE`) in a steering edit: a place, a role, a manner, an order
or a reference that may be the change itself ("Centered.", "Alternate them!", "Same again.")."""

EDIT_SENTENCE_CHANGE_RE = re.compile(
    rf"(?i)\b(?:add|put|place|stack|set|move|remove|take|drop|make|build|turn|swap|switch|change|another|more|fewer|less|extra|one"
    rf"|two|three|four|five|six|seven|eight|\d+|towers?|rows?|lines?|pyramids?|walls?|grids?|circles?|piles?|patch\w*|left|right|front"
    rf"|back|top|bottom|middle|corners?|sides?|far|apart|together|close\w*|next|near|beside|behind|between|around|spread\w*"
    rf"|diagonal\w*|under\w*|above|below|over|again|undo|revert\w*|swap\w*|revers\w*|flip\w*|{COLOR_RE})\b")
"""A word of a change in one sentence of a steering edit of several ("Add one.", "The tower goes on the right side."): a
sentence with one that the edit's reading does not account for makes it refused (chat, "cool.", "thanks", has none)."""

EDIT_REASON_JUDGEMENT_RE = re.compile(
    r"(?i)\b(?:too|easy|easier|hard|difficult|simple|boring|bored|good|great|ready|struggl\w*|tricky|confus\w*|fun|nice|tired|busy"
    r"|practi[cs]e\w*|progress\w*|improv\w*|mastered|nailed|aced|breezed|finished|done|enjoy\w*|loved|hated|keen|excited|happy|pleased"
    r"|impressive|impressed|works?|worked|working|nervous|confident|patient|impatient|quick|fast|slow|today|now|yesterday)\b")
"""The judgement a reason sentence (:data:`EDIT_REASON_SENTENCE_RE`) makes of a person or of the version before ("too
easy", "good at this now", "struggled"): one is needed, so that only a sentence that says why is set aside."""
"""What keeps a sentence before or after a steering edit's change from being a reason said for it
(:data:`EDIT_REASON_SENTENCE_RE`): a colour, a count, a place, a structure, a label, a change verb, a negation, a
restriction, a wish, a version, a condition or time, an order, a quantifier, a take-back: it may change the edit."""

_SAID_FIRST = r"\s*(?:(?:oh|ok(?:ay)?|so|now|and|then|actually|hmm+|no|nah)\s*,?\s*)*"
"""Words a terse steering edit may open with that change nothing ("ok so", "actually", "nah"), for the rewrites below."""

PATCH_RECOLOUR_RE = re.compile(r"(?i)" + _SAID_FIRST + rf"(?:make|turn|change|paint|colou?r)\s+(?:the\s+)?"
                               rf"(?:goal\s+|target\s+)?(?:patch|pad|mat)\s+(?:to\s+|into\s+)?({COLOR_RE})(?:\s+instead|\s+now)?\s*[.!]?")
"""A steering edit that makes the task's one patch another colour ("make the patch cyan"), after the rewrites of
:data:`EDIT_REWRITES` ("patch should be cyan", "patch -> cyan")."""

EDIT_STEP_NAME_RE = re.compile(
    r"(?i)^\s*(?:(?:the\s+)?(?:next|new|final|another)\s+)?(?:(?:height|colou?r|region|place|position|count|number|label|letter|relation"
    r"|size|order|structure|layout|shape|baseline|control|test|first|second|third|fourth|fifth|bonus|practice|warm-?up)\s+)?"
    r"(?:round|ablation|condition|variant|trial|attempt|iteration|phase|scenario|exercise|challenge|puzzle|setting|take|draft|revision"
    r"|cell|set-?up|shot|playtest|play-test|scene|run|pass|option|mock-?up)(?:\s+(?:#?\d+|[a-z]|one|two|three|four|five|six|seven|eight|nine|ten))?(?:\s+(?:rule\s+)?change)?\s*(?::|,(?=\s+(?:please\s+)?"
    r"(?:make|put|add|swap|switch|remove|take|move|change|use|turn|replace|place|stack|set|drop|delete|build|reverse|flip)\b))\s+(?=\S)")
"""A name the edit gives the version it makes, before its change ("Round 3: ...", "Ablation 1: ...", "Condition C: ...",
"Height ablation: ...", "Next round, add ...", "Round two rule change: ...", "Take two: ...", "Next setup: ...", "Playtest 2:
..."): a session's own count of its
steps, which names the version made, never the one built on (that one is named in the change: "back to the round one tower"
is read, or refused, there); dropped."""

EDIT_KIND_LABEL_RE = re.compile(
    r"(?i)^\s*(?:(?:label|annotation|caption|qa|grading|quick|small|one|another|last|final|config|code|review(?:er)?|ta)\s+)?"
    r"(?:fix|correction|note|nit|update|edit|tweak|request|suggestion|comment|amendment|erratum)(?:\s+#?\d+)?\s*:\s+(?=\S)"
    r"|^\s*re-?(?:annotat|label)\w*\s*:\s+(?=\S)")
"""What an edit calls itself before its change ("Label fix: ...", "Correction: ...", "Nit: ...", "Re-annotating: ..."): the
kind of message, not of the change (which the words after the colon say, and are read); dropped like
:data:`EDIT_STEP_NAME_RE`'s names."""


TOWER_RESTATED_RE = re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|so|now|then)\s*,?\s*)*make\s+the\s+(?:tower|stack)\s+(?P<n>\d+|{COUNT_WORD_RE})"
                               r"\s+(?:cubes|blocks)(?:\s+(?:tall|high))?\s*[:,]\s*(?P<rest>[^.;!?]+)[.!]?\s*$")
"""A steering edit that says a tower again, its count and every cube's colour by counts ("make the tower five cubes:
three red and then two blue on top"), read by the steering as the whole tower (:func:`rpg.steer.steering.plan_schema`)."""


def edit_label_dropped(m: re.Match) -> str:
    """The edit without its label (:data:`EDIT_LABEL_RE`) when the label is inert, else as it is."""
    label = m.group("l").lower()
    if re.fullmatch(r"\s*(?:add|also|plus|addition|and|extra|in\s+addition)\s*", label):
        return "also "  # "add: the red cube is left of the green cube": an addition (it had been read as the whole new task)
    if _EDIT_LABEL_HAZARD_RE.search(label) or GOAL_THING_PREFIX_RE.search(label) or TURNING_LABEL_RE.search(label):
        return m.group(0)  # ("Add a clue: a red cube ...": an addition, kept: dropped, the rest had become the whole new task;
        # "Time permitting: ...": a condition, kept to be refused: it had been dropped)
    return ""


_NOT_CUBE = r"(?:\s+(?:one|cube|block))?"
_EDIT_PLACE = (r"(?:at\s+the\s+(?:bottom|top|base)|on\s+(?:the\s+)?top|in\s+the\s+middle|on\s+the\s+(?:far\s+)?(?:left|right)(?:\s+end)?"
               r"|at\s+the\s+(?:far\s+)?(?:left|right)(?:\s+end)?)")
_ASKER = (r"(?-i:[A-Z][a-z]+)(?<!The)(?<!This)(?<!That)(?<!Then)(?<!Now)(?<!Make)(?<!Put)(?<!Nobody)(?<!Noone)(?<!Nothing)"
          r"(?<!Neither)(?<!Never)(?<!None)|(?i:he|she|they|we|chat)"
          rf"|(?i:the|my|our|your)\s+(?i:{PERSON_NOUNS})")
"""Who asks for a steering edit, said before it ("Maya says ...", "He'd like ...", "The curator asks for ..."); never a
word of negation ("Nobody wants a green cube on top" had added one)."""

SOMEONE_SAID_RE = re.compile(
    r"(?:^|(?<=[.;:!?]\s))(?:(?:my|our|the)\s+(?P<who>supervisor|advisor|adviser|professor|prof|pi|colleague|labmate|teacher|mentor|tutor"
    rf"|lecturer|{PERSON_NOUNS})|(?P<pronoun>he|she|they))\s+(?:said|says|told\s+(?:me|us)|tells\s+(?:me|us)|mentioned)\s*,?\s*(?:that\s+)?"
    # (nothing after it that may take the report back or weigh it: "..., but actually put it on the green one")
    r"(?![\s\S]*\b(?:but|however|actually|instead|rather|though|although|yet|ignore\w*|wrong|disagree\w*|correct\w*|no|not|never|[a-z]+n't"
    r"|said|says|told|think|thinks|unless|if|except|else|other|otherwise|wants?|prefers?|would|'d|maybe|perhaps)\b)"
    r"(?=(?:the|a|an)\s+[^.;:!?]*?\b(?:goes|go|should|must|needs\s+to|has\s+to|is\s+to|are\s+to|belongs?)\b|to\s+(?:put|place|stack|build"
    r"|make|line|set|arrange|move)\b)(?:to\s+)?")
"""Who said the task, reported ("My supervisor said the white cube should go on top of the black cube.", "He told me the
A cube goes to the left of the B cube.", "She told us to stack ..."): the report's own words are the task, read as if
said (a report of what is, "he said the red cube is on ...", or of what not to do, "told me not to ...", stays and is
refused; :func:`rpg.schema.reading.normalize_words` lists ``who`` as dropped)."""

EDIT_PERSON_REASON_RE = re.compile(
    r"(?i)^\s*(?:(?:oh|well|ok(?:ay)?|so|hmm+|right|alright|honestly|yeah|nah|fine|ugh)\s*,?\s+)*(?:(?:the|my|our|your|his|her|their|some|a\s+few"
    rf"|all\s+the)\s+)?(?:{PERSON_NOUNS}|she|he|they|we|i)\s+(?:(?:all|still|just|really|also|totally)\s+)*"
    r"(?:say|says|said|think|thinks|thought|find|finds|found|feel|feels|felt|changed\s+(?:her|his|their|my|our)\s+minds?"
    r"|complain\w*|hated?|hates|loved?|loves|liked?|likes|reckons?|noticed|got\s+bored|(?:keep|keeps|kept)\s+(?:knocking|bumping|tipping)"
    r"|cracked|solved|beat|breezed\s+through|struggled\s+with|got\s+stuck"
    r"|(?:did|do|does)(?:n't|\s+not)\s+(?:get|like|love|understand|see|notice|care\s+for))\b[^.!?;:]*[.!]\s*$")
"""A sentence of a steering edit in which people judge the version before ("Testers say three is clutter.", "The homeowner
thinks it's too plain.", "Nah, players didn't get it.", "Players keep knocking it over.", "Client changed her mind
again."): what they think or did, not a change; set aside by :func:`rpg.steer.edits.reasons_set_aside` when another
sentence of the edit says the change and it holds no word of a change, a want or a version
(:data:`EDIT_PERSON_REASON_HAZARD_RE`)."""

EDIT_PERSON_REASON_HAZARD_RE = re.compile(
    r"\b(?:should|must|need\w*|want\w*|wish\w*|would|'d|rather|prefer\w*|instead|make|put|add|remove|swap|move|change|take"
    r"|replace|reverse|flip|turn|stack|build|back|undo|revert\w*|first|original|before|previous|earlier|version|v\d|if|unless"
    r"|when|until|then|next|only|same|different|like\s+(?:it|them|that|this|the)|better|worse|best|more|fewer|less|extra|no|none"
    rf"|without|{_GOAL_THINGS}|(?:{COLOR_RE})s)\b")
"""What keeps a person's judgement (:data:`EDIT_PERSON_REASON_RE`) in a steering edit: a change, a want, a version named,
a condition, a comparison: it may say the change itself ("Testers say it should be four.", "They liked the first one
better.")."""

EDIT_CUBE_REASON_RE = re.compile(
    rf"(?i)^\s*(?:(?:oh|well|ok(?:ay)?|so|hmm+|honestly|yeah|nah|ugh)\s*,?\s+)*the\s+(?P<c>{COLOR_RE})(?:\s+(?:one|cube|block))?"
    r"(?:'s|\s+is|\s+looks|\s+seems|\s+feels)\s+(?:a\s+bit\s+|a\s+little\s+|way\s+|far\s+|much\s+|just\s+)?too\s+[a-z]+"
    r"(?:\s+for\s+(?:the|this|that|our|my)\s+[a-z]+)?\s*[.!]\s*$")
"""A sentence of a steering edit that judges one cube by its colour ("The orange's too loud."): the "it" of the change
after it is that cube (:func:`rpg.steer.edits.reasons_set_aside`: "Replace it with a gray one" had been refused)."""
_IMPERATIVE_OF = {"replaced": "replace", "moved": "move", "swapped": "swap", "removed": "remove", "painted": "paint",
                  "recoloured": "recolour", "recolored": "recolor", "put": "put", "placed": "place", "stacked": "stack",
                  "taken out": "remove", "taken off": "remove", "taken away": "remove"}
"""A past participle of a reported want ("the yellow cube to be replaced") -> the imperative of the edit it asks for."""

_PLACE_WORDS_RE = re.compile(r"^(?:at|on|in)\s+(?:the\s+)?(?:far\s+)?")
EDIT_NOT_CORRECTIONS: tuple[tuple[re.Pattern, str | Callable[[re.Match], str]], ...] = (
    # "it should be red, not blue", "yellow, not blue": the blue cube is red (every cube had been made red)
    (re.compile(rf"(?i)^\s*(?:(?:it|that|this)\s+(?:should\s+be|is|'s|was\s+(?:supposed|meant)\s+to\s+be|should\s+have\s+been)\s+)?"
                rf"(?:an?\s+|the\s+)?(?P<new>{COLOR_RE}){_NOT_CUBE}\s*,?\s+not\s+(?:an?\s+|the\s+)?(?P<old>{COLOR_RE}){_NOT_CUBE}\s*[.!]?\s*$"),
     lambda m: f"make the {m.group('old')} cube {m.group('new')}"),
    # "blue, not green, is on the right", "blue, not red, at the bottom": the cube there, which must be green now, is blue
    (re.compile(rf"(?i)^\s*(?:the\s+)?(?P<new>{COLOR_RE}){_NOT_CUBE}\s*,\s*not\s+(?:the\s+)?(?P<old>{COLOR_RE}){_NOT_CUBE}\s*,?\s+"
                rf"(?:(?:is|goes|sits|stands|should\s+be|belongs|comes)\s+)?(?P<where>{_EDIT_PLACE})\s*[.!]?\s*$"),
     lambda m: f"make the {_PLACE_WORDS_RE.sub('', m.group('where'))} {m.group('old')} cube {m.group('new')}"),
    # "the top one is green, not red": the same, its place said first
    (re.compile(rf"(?i)^\s*the\s+(?P<where>top|bottom|middle|left|right|leftmost|rightmost|first|last)(?:\s+(?:one|cube|block))?\s+"
                rf"(?:is|should\s+be)\s+(?:an?\s+)?(?P<new>{COLOR_RE}){_NOT_CUBE}\s*,?\s+not\s+(?:an?\s+)?(?P<old>{COLOR_RE}){_NOT_CUBE}\s*[.!]?\s*$"),
     lambda m: f"make the {m.group('where')} {m.group('old')} cube {m.group('new')}"),
)
"""A correction said as "X, not Y" ("it should be red, not blue", "blue, not green, is on the right"): the cube that is Y
now (at the place said) made X (:data:`EDIT_REWRITES`); the negated colour is checked to be the cube's before, never
dropped."""

EDIT_REWRITES: tuple[tuple[re.Pattern, str | Callable[[re.Match], str]], ...] = (
    # "Change the patch to the yellow patch.", "switch the patch to a yellow one": the task's one patch recoloured ('change'
    # had been read as an action)
    (re.compile(rf"(?i)\b(?:change|switch|swap|turn)\s+the\s+patch\s+(?:to|for|into)\s+(?:the\s+|a\s+)?(?P<c>{COLOR_RE})(?:\s+(?:one|patch))?\b"),
     lambda m: f"make the patch {m.group('c')}"),
    # "Take the two cubes off the ends of the row", "remove the two cubes at the ends": the cube at each end removed
    (re.compile(r"(?i)\b(?:take|remove|pull|lift)\s+(?:the\s+)?(?:(?:two|2|both)\s+)?(?:cubes|blocks|ones)\s+(?:off|from|at)\s+"
                r"(?:the\s+|both\s+)?(?:two\s+|2\s+)?ends(?:\s+of\s+the\s+(?:row|line))?\b"), "remove the cubes at both ends"),
    # "the pile goes to the centre of the table instead", "now the tower should go in the front left corner": the task's
    # structure moved there (read as one more placement of a cube, it had been refused)
    (re.compile(r"(?i)(?:^|(?<=[,;:]\s)|(?<=\bnow\s)|(?<=\bso\s))(?:the|that|this)\s+(?P<s>pile|tower|stack|row|line|pyramid|wall|grid|circle)\s+"
                r"(?:goes|should\s+go|must\s+go|needs\s+to\s+go|moves|should\s+move|belongs|should\s+be|is\s+to\s+go)\s+(?:to|in|into|at|on)\s+"
                r"(?=the\s+(?:(?:far|very)\s+)?(?:front|back|rear|left|right|middle|centre|center)\b)"),
     lambda m: f"move the {m.group('s')} to "),
    # "Add a yellow cube on the other side of the pink one, so the pink cube is between the cyan and the yellow": the
    # between said after it places the new cube ('the other side' had been refused as a contrast)
    (re.compile(rf"(?i)\s+on\s+the\s+other\s+side\s+of\s+the\s+(?P<c>{COLOR_RE})\s+(?:one|cube|block)\s*,?\s*so\s+(?:that\s+)?"
                rf"(?=the\s+(?P=c)\s+(?:one|cube|block)\s+(?:is|sits|stands|ends\s+up)\s+between\s+the\s+(?:{COLOR_RE})\b)"),
     " so "),
    # "... between the cyan and the yellow": each cube said with its noun (the second bare colour had not been read)
    (re.compile(rf"(?i)\bbetween\s+the\s+(?P<a>{COLOR_RE})\s+and\s+the\s+(?P<b>{COLOR_RE})(?=\s*(?:[.!;]|$))"),
     lambda m: f"between the {m.group('a')} cube and the {m.group('b')} cube"),
    # "Discard the white one", "bin the red cube": removed from the task
    (re.compile(r"(?i)\b(?:discard|ditch|bin|scrap|dump|lose)\s+(?=the\s+(?:[a-z]+\s+)?(?:one|cube|block)\b)"), "remove "),
    # "Throw a third purple into the heap": one more cube of that colour added ('a third' had been read as a place)
    (re.compile(rf"(?i)\b(?:add|put|throw|toss|drop|place|set|stack)\s+an?\s+(?:second|third|fourth|fifth|sixth)\s+(?=(?:{COLOR_RE})\b)"),
     "add another "),
    # "Lengthen the row with two more orange cubes", "extend the tower with a red cube": those cubes added
    (re.compile(r"(?i)\b(?:lengthen|extend|grow|widen|raise)\s+(?:the\s+(?:row|line|tower|stack|wall)|it)\s+(?:with|by\s+adding)\s+(?=(?:an?|one|two|three"
                r"|four|\d+|another)\b)"), "add "),
    # "add one more layer underneath, three green cubes": another layer of the task's structure (a count "more" of nothing
    # named had refused it)
    (re.compile(r"(?i)\b(?:one|1)\s+more\s+(?=(?:row|layer|level|tier)\b)"), "another "),
    # "stack those six cubes into one tower", "put all the cubes in a single row": the task's cubes, said as "them" (a tower
    # into "one" had been read as a second structure added)
    (re.compile(r"(?i)\b(?P<v>stack|put|arrange|pile|line\s+up|place|set|build)\s+(?:all\s+)?(?:those|the)\s+(?:cubes|blocks)\s+"
                r"(?P<p>into|in|as)\s+(?:one|a|a\s+single|just\s+one)\s+(?P<s>tower|stack|row|line|pile|heap|column)(?=\s*(?:instead\s*)?[.!]?\s*$)"),
     lambda m: f"{m.group('v')} them {m.group('p')} a {m.group('s')}"),  # (a count said, or words after it, are read as said:
    # "stack those three cubes into one tower" of six, "..., red at the bottom" had been dropped)
    # "Round 3: ...", "Condition C: ...", "Next round, add ...": the name of the version made
    (EDIT_STEP_NAME_RE, ""),
    # "Rearrange them from left to right: blue, green, cyan.", "Put them in traffic-light order from left to right: red,
    # yellow, green", "Now the order is blue, green, cyan from left to right.": a new order of the row's cubes, said as that
    # order alone (:data:`AXIS_ORDER_ALONE_RE`; the list had had no place in the change read)
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|and|so|then|please)\s*,?\s+)*(?:let'?s\s+)?(?:(?:re-?arrange|re-?order|re-?sort|sort|order|put|set"
                rf"|arrange|line\s+up)\s+(?:them|the\s+(?:cubes|blocks|row|line))(?:\s+in\s+(?:this|the\s+following|a\s+new|[a-z\-]+)\s+order)?"
                rf"|re-?order|re-?arrange|now\s+the\s+order\s+is|the\s+(?:new\s+)?order\s+(?:is|should\s+be))\s*,?\s*"
                rf"(?:(?:from\s+)?(?P<d>left\s+to\s+right|right\s+to\s+left)\s*:?\s*(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+|then\s+)?(?:{COLOR_RE}))+)"
                rf"|:?\s*(?P<l2>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+|then\s+)?(?:{COLOR_RE}))+)\s*,?\s+(?:from\s+)?(?P<d2>left\s+to\s+right"
                rf"|right\s+to\s+left))\s*(?P<end>[.!]?)\s*$"),
     lambda m: f"From {m.group('d') or m.group('d2')}: {m.group('l') or m.group('l2')}{m.group('end')}"),
    # "add one more tier, a red cube on top": the cube the tier is ('one more' had been refused as naming no cube)
    (re.compile(rf"(?i)\b(?:one\s+more|another|an\s+extra|a\s+further)\s+(?:tier|layer|level|stor(?:e?y)|piece|block|cube)\s*,\s*"
                rf"(?=(?:a|an|one)\s+(?:{COLOR_RE}|[A-Z0-9])\s+(?:cube|block|one)\b)"), ""),
    # "Relocate the stack to the front right corner.": move it ('relocate' had been read as an addition of a place)
    (re.compile(r"(?i)\b(?:relocate|reposition)\b"), "move"),
    # "Top up the green tower with one more green cube.": add it to that tower
    (re.compile(r"(?i)\btop\s+up\s+(the\s+(?:[a-z]+\s+){0,2}?(?:tower|stack|row|line|pile|wall|column))\s+with\s+([^.;!]+?)(?=\s*(?:[.;!]|$))"),
     r"add \2 to \1"),
    # "Add one gray cube next to the cyan cube.": one cube is a cube ("one" had left the addition unread)
    (re.compile(rf"(?i)\b(add|put|place|set)\s+one\s+(?=(?:{COLOR_RE})\s+(?:cube|block)\b(?!s))"), r"\1 a "),
    # "Change the orange cube for a red one.": replace it with that one ('change ... for' had been read as an action)
    (re.compile(rf"(?i)\b(?:change|swap|exchange|trade)\s+(the\s+(?:{COLOR_RE}|[A-Z0-9])\s+(?:cube|block|one|patch))\s+for\s+"
                rf"(an?\s+(?:{COLOR_RE}|[A-Z0-9])\s+(?:cube|block|one|patch))\b"),
     r"replace \1 with \2"),
    # "Amended: the row shall spell JAW.": make it spell that word
    (re.compile(r"(?i)(?:^|(?<=:\s))(?:the\s+(?:row|line|word|tower|stack|cubes|blocks)|it)\s+(?:shall|should|must|will|is\s+to)\s+(?:now\s+)?"
                r"(spell|read)\s+(?=[A-Z]{2,}\b)"), r"make it \1 "),
    # "Further, ...", "Furthermore, ...": a next change said as going on (not a distance)
    (re.compile(r"(?i)^\s*(?:further(?:more)?|moreover)\s*,\s*(?=\S)"), ""),
    # "Convert the line to a tower, ...": turn it into one ('convert' had been refused as an action)
    (re.compile(r"(?i)\bconvert\s+((?:it|them|(?:the|this|that)\s+(?:[a-z\-]+\s+){0,2}?[a-z\-]+))\s+(?:in)?to\s+"), r"turn \1 into "),
    # "the white cube shall be replaced by a black cube": replace it with that one (a passive replacement had been unread)
    (re.compile(rf"(?i)\b(the\s+(?:{COLOR_RE}|[A-Z0-9])\s+(?:cube|block|one|patch))\s+(?:(?:shall|should|must|will|is\s+to|has\s+to|can)\s+be|is|gets)\s+"
                rf"(?:replaced|swapped\s+out|substituted)\s+(?:by|with|for)\s+(an?\s+(?:{COLOR_RE}|[A-Z0-9])\s+(?:cube|block|one|patch))\b"),
     r"replace \1 with \2"),
    # "swap the red cubes with the white cubes": the two colours exchanged (it had read as "replace": every cube white)
    (re.compile(rf"(?i)\b(swap|switch|exchange|trade)\s+(?:the\s+|all\s+the\s+)?({COLOR_RE})(?:\s+(?:cubes|blocks|ones|cube|block|one))?\s+"
                rf"with\s+(?:the\s+|all\s+the\s+)?({COLOR_RE})(?:\s+(?:cubes|blocks|ones|cube|block|one))?\b"), r"\1 \2 and \3"),  # ("swap
    # red for yellow" replaces)
    # "make the two at the ends red": the ends (the count had been left unread)
    (re.compile(r"(?i)\bthe\s+(?:two|2)\s+(?:ones\s+|cubes\s+|blocks\s+)?(?:at|on)\s+(?:the|both|either)\s+ends\b(?!\s+of\b)"), "the ends"),
    # "Fine, let's not risk it.": a reason said as a person's caution, before the change
    (re.compile(r"(?i)^\s*(?:(?:fine|ok(?:ay)?|alright|right|yeah)\s*[,.!]?\s*)?let'?s\s+not\s+risk\s+it\s*[.!]\s+(?=\S)"), ""),
    # "Make it four across" of a wall: four wide
    (re.compile(r"(?i)^\s*(?:(?:now|ok(?:ay)?|and|so)\s*,?\s*)*(make|build)\s+(it|the\s+wall)\s+(\d+|" + COUNT_WORD_RE
                + r")\s+across\b(?=\s*(?:[.!]|$|and\s+(?:\d+|" + COUNT_WORD_RE + r")\s+(?:high|tall)\b))"), r"\1 \2 \3 wide"),
    # "stretch it to five", "shrink it to three": that count
    (re.compile(r"(?i)\b(?:stretch|extend|lengthen|grow|shrink|cut|trim)\s+(it|the\s+(?:row|line|tower|stack))\s+(?:down\s+|out\s+)?to\s+"
                r"(?=(?:\d+|" + COUNT_WORD_RE + r")\b)"), r"make \1 "),
    # "the buyers would rather have them the other way round": the two exchanged
    (re.compile(r"(?i)^\s*(?:(?:the|my|our)\s+[a-z]+\s+|she\s+|he\s+|they\s+|we\s+)?(?:would|'d)\s+rather\s+have\s+(?:them|the\s+two)\s+"
                r"(?:the\s+)?other\s+way\s+(?:a)?round\s*[.!]?\s*$"), "swap them"),  # (nothing else in the edit: "I don't want them
    # the other way round", "add a green cube on top and put them the other way round" are not this)
    # "Shoot it again with the order reversed", "do it again with the order reversed": the order reversed
    (re.compile(r"(?i)^\s*(?:shoot|do|try|build|make|take|run)\s+it\s+again\s*,?\s+(?:but\s+)?with\s+the\s+order\s+reversed\s*[.!]?\s*$"),
     "reverse the order"),
    # "Use a red patch instead of the blue one": that patch recoloured
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|and|so)\s*,?\s*)*(?:use|try|put\s+it\s+on)\s+an?\s+({COLOR_RE})\s+patch\s+instead\s+of\s+the\s+"
                rf"({COLOR_RE})(?:\s+(?:one|patch))?\s*[.!]?\s*$"), r"change the \2 patch to \1"),
    # "Label fix: ...", "Correction: ...": what the message is
    (EDIT_KIND_LABEL_RE, ""),
    # "the homework says both cubes go on the green patch", "my TA says the row has to be in the centre", "the video shows the
    # green cube on top": who asks for the change, or where it was seen, before it (its words had been refused as unknown)
    (re.compile(r"(?i)^\s*(?:(?:and|wait|sorry|also|actually|oh|ok(?:ay)?|so|but|hmm)\s*,?\s+)*(?:the|my|our|your)\s+(?:[a-z\-]+\s+)?"
                r"(?:homework|assignment|exercise|worksheet|(?:lab\s+|task\s+|answer\s+)?sheet|handout|ta|teacher|professor|instructor|tutor"
                r"|reviewer|video|clip|footage|recording|demo|(?:example\s+|model\s+)?solution|spec|brief|rubric|answer\s+key|textbook|book)"
                r"\s+(?:(?:actually|clearly|really|now)\s+)?(?:says|said|shows|showed)\s+(?:that\s+)?(?=\S)"), ""),
    # "Maya says it needs a purple one on top too", "The curator says ...": who asks for the change, a person named or said
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})\s+(?:(?:actually|really|now|also)\s+)?(?:says|said|thinks|insists|reckons|decided|decides)\s+(?:that\s+)?"
                r"(?=\S)"), ""),
    # "He'd like a green cube added at the right end", "The bride wants a white cube put on top": that cube added there
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+like|\s+(?:wants|would\s+like|asks\s+for|asked\s+for))\s+(?P<what>(?:an?|one\s+more|another)\s+[^,.;:!?]+?)\s+"
                r"(?:added|put|placed|set)\s+(?P<where>(?:at|on|onto|to|in|next\s+to|beside|behind|between|under|below|above)\b[^.;!?]*)[.!]?\s*$"),
     r"add \g<what> \g<where>"),
    # "She'd also like a black cube in front of the gray one": that cube added there (a cube and its place, nothing else)
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+(?:also\s+)?like|\s+(?:also\s+)?(?:wants|would\s+like)"
                rf"|\s+would\s+also\s+like)\s+(?P<what>(?:an?|one\s+more|another)\s+(?:{COLOR_RE})\s+(?:cube|block|one))\s+"
                rf"(?P<where>(?:in\s+front\s+of|behind|next\s+to|beside|on\s+top\s+of|on|under|to\s+the\s+(?:left|right)\s+of)\s+the\s+"
                rf"(?:{COLOR_RE})\s+(?:cube|block|one))(?:\s+(?:too|as\s+well))?\s*[.!]?\s*$"),
     r"also add \g<what> \g<where>"),
    # "The curator asks for the yellow cube to be replaced with a cyan one", "She wants the red cube moved to the back"
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+like|\s+(?:wants|would\s+like|asks\s+for|asked\s+for|needs))\s+(?P<what>the\s+[^,.;:!?]+?)\s+(?:to\s+be\s+)?"
                r"(?P<verb>replaced|moved|swapped|removed|painted|recolou?red|put|placed|stacked|taken\s+(?:out|off|away))\b\s*(?P<rest>[^.;!?]*)[.!]?\s*$"),
     lambda m: f"{_IMPERATIVE_OF[' '.join(m.group('verb').split())]} {m.group('what')} {m.group('rest')}".strip()),
    # "it needs a purple one on the very top too": that cube added there
    (re.compile(r"(?i)^\s*(?:it|this|that|the\s+(?:tower|stack|row|line|pile))\s+(?:still\s+)?needs\s+(?P<what>(?:an?|one\s+more|another)\s+[^,.;:!?]+?)\s+"
                r"(?P<where>(?:on|at|to|in|next\s+to|beside|under|below)\b[^.;!?]*?)(?:\s*,?\s+(?:too|as\s+well))?\s*[.!]?\s*$"),
     r"add \g<what> \g<where>"),
    # "The bride wants the yellow and white cubes to trade places": those two swapped
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+like|\s+(?:wants|would\s+like|asks\s+for|asked\s+for))\s+(?P<what>the\s+[^,.;:!?]+?)\s+to\s+"
                r"(?:trade|swap|switch|exchange)\s+(?:places|spots|positions)\s*[.!]?\s*$"), r"swap \g<what>"),
    # "chat wants a red cube in between them", "the sponsor would like another tower": a cube or structure wanted, added
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+(?:also\s+)?like|\s+(?:also\s+)?"
                r"(?:wants|want|would\s+(?:also\s+)?like|asks\s+for|asked\s+for))\s+(?=(?:an?|one\s+more|another)\s)"), "add "),
    # "they want the pyramid in the back right corner": the cube or structure wanted there, put there
    (re.compile(rf"^\s*(?:(?i:now|and|so|ok|okay|then|also|actually|oh|but)\s*,?\s+)*(?:{_ASKER})(?:'d\s+like|\s+(?:wants|want"
                r"|would\s+like))\s+(?=the\s+[^,.;:!?]+?\s+(?:in|at|on|onto|next\s+to|beside|behind|in\s+front\s+of|under)\s)(?![^.;!?]*\bto\s+be\b)"),
     "put "),
    # "For the next take, make the two end cubes purple", "This time round, ...": when, of the session, before the change
    (re.compile(r"(?i)^\s*(?:for|in|on)\s+(?:the\s+)?(?:next|this|the\s+following)\s+(?:take|shot|run|round|trial|attempt|go|iteration"
                r"|pass|scene|session)\s*,\s*(?=\S)"), ""),
    # "Let's go again, but this time a yellow cube goes on top", "Again from the top, but the white cube becomes purple"
    (re.compile(r"(?i)^\s*(?:(?:let'?s\s+)?(?:go|do\s+it|run\s+it|take\s+it)\s+)?again(?:\s+from\s+the\s+top)?\s*,?\s+but\s+"
                r"(?:this\s+time\s*,?\s+)?(?=\S)"), ""),
    # "The top cube reads wrong on camera, make it black": "it" is the cube the first clause judges (every cube had been
    # recoloured, silently)
    (re.compile(r"(?i)^\s*(?P<np>the\s+(?:[a-z]+\s+){0,2}(?:cube|block|one))\s+(?!(?:and|or|with|next|on|under|beside|behind)\b)"
                r"(?P<said>[^,.;:!?]*?)\s*[,;]\s*(?:so\s+|just\s+|please\s+)*(?P<verb>make|paint|turn|colou?r|change|swap|replace|remove"
                r"|move|recolou?r)\s+it\b"),
     lambda m: m.group(0) if EDIT_SENTENCE_CHANGE_RE.search(m.group("said")) else f"{m.group('verb')} {m.group('np')}"),
    # "Two more purple cubes in the row, please.": cubes added, said without the verb
    (re.compile(r"(?i)^\s*(?P<n>\d+|one|two|three|four|five|six|a\s+couple(?:\s+of)?)\s+more\s+(?=(?:[a-z]+\s+)?(?:cubes?|blocks?|ones?)\b)"),
     r"add \g<n> more "),
    # "Raise the tower by two more yellow cubes", "Extend the row by one green cube": those cubes added to it (their colour
    # said: "by two cubes" would make colours up)
    (re.compile(r"(?i)^\s*(?:raise|extend|grow|lengthen|heighten|build\s+up)\s+(?P<s>the\s+(?:tower|stack|row|line|column))\s+by\s+"
                rf"(?P<what>(?:\d+|one|two|three|four|five|six|an?)\s+(?:more\s+)?(?:{COLOR_RE})\s+(?:cubes?|blocks?))\s*(?P<rest>[.!]?)\s*$"),
     r"add \g<what> to \g<s>\g<rest>"),
    # "switch the red cubes to magenta": a recolour; "Strike the blue cube", "ditch the yellow one": a removal
    (re.compile(rf"(?i)\bswitch\s+(?P<what>the\s+(?:{COLOR_RE})\s+(?:cubes?|blocks?|ones?))\s+(?:to|into)\s+(?=[a-z]+\b)"),
     r"change \g<what> to "),
    (re.compile(rf"(?i)\b(?:strike|ditch|nix|axe)\s+(?=the\s+(?:{COLOR_RE}|top|bottom|middle|last|first)\s+(?:cubes?|blocks?|ones?)\b)"),
     "remove "),
    # "remove the blue cube, we don't need it in frame": the removal's reason after it
    (re.compile(r"(?i)^(?P<rm>\s*(?:remove|drop|lose|delete)\s+[^,;.!?]+?)\s*[,;]\s*(?:we|i)\s+(?:don'?t|do\s+not)\s+need\s+"
                r"(?:it|them|that\s+one|those)(?:\s+(?:any\s*more|in\s+(?:the\s+)?(?:frame|shot|scene|picture)))?\s*[.!]?\s*$"), r"\g<rm>"),
    # "Let's go back to take one", "back to round 1": the first version (it had gone back one step, silently)
    (re.compile(r"(?i)\b(back\s+to|return\s+to|revert\s+to|restore)\s+(?:the\s+)?(?:take|round|attempt|try|draft|iteration|pass|shot|setup|set-up)"
                r"\s+(?:one|1)\b(?=\s*(?:[.,;!?]|$))"), r"\1 the original"),  # ("the round one tower": a version named by a shape)
    # "Per the sponsor, ...", "At the request of the client, ...": who asks, before the change
    (re.compile(rf"^\s*(?i:per|according\s+to|as\s+requested\s+by|at\s+the\s+request\s+of|on\s+behalf\s+of)\s+(?:{_ASKER})\s*,\s*(?=\S)"), ""),
    # "the blue top cube is replaced with a yellow one", "the yellow cube gets moved to the back": the change said passively
    (re.compile(r"(?i)^\s*(?P<what>the\s+[^,.;:!?]+?)\s+(?:is|are|gets|get|should\s+be|must\s+be|will\s+be|has\s+to\s+be)\s+"
                r"(?P<verb>replaced|moved|swapped|removed|painted|recolou?red|taken\s+(?:out|off|away))\b\s*(?P<rest>[^.;!?]*)[.!]?\s*$"),
     lambda m: f"{_IMPERATIVE_OF[' '.join(m.group('verb').lower().split())]} {m.group('what')} {m.group('rest')}".strip()),
    *EDIT_NOT_CORRECTIONS,
    # "put tower in back left corner": a place said without its article (it had been dropped with the change)
    (re.compile(r"(?i)\b(in|to|into|at)\s+((?:back|front|rear)(?:\s+(?:left|right))?|left|right)\s+(corner|half|side|edge)\b"),
     r"\1 the \2 \3"),
    # "Simplify it for the worksheet: make both rows green": a label saying why, before the change
    (EDIT_LABEL_RE, edit_label_dropped),
    # "He has trouble telling red from green, so make the green cube yellow instead": the reason said before the change
    # (its colours had been read as the change's); only a statement, never a command, before "so"
    (re.compile(r"(?i)^\s*(?!(?:please\s+)?(?:make|put|add|swap|switch|remove|take|move|change|use|turn|replace|place|stack|set|drop"
                r"|delete|build|reverse|flip|keep|leave|go|do|try|let|give|get|bring|shift|slide)\b)"
                r"(?:i|we|he|she|they|(?-i:[A-Z][a-z]+)|the\s+(?:class|kids|students|children|team|group|reviewer|client|boss"
                r"|users?|learners?|pupils?))(?:'s|'re|'m|'ve)?\s+"
                r"(?![^.;:!?]*?\b(?:should|must|need\w*|want\w*|like|prefer\w*|wish\w*|if|when|unless|upside|swap\w*|revers\w*|flip\w*"
                r"|mirror\w*|turn\w*|go|gone|goes|remov\w*|mov\w*|instead|not|no|n't|never|without|same|chang\w*|different|it|them"
                r"|that|this|those|these)\b[^.;:!?]*?,\s*so\b)"
                r"[^.;:!?]*?,\s*so\s+(?=(?:please\s+)?(?:make|put|add|swap|switch|remove|take|move|change|use|turn|replace"
                r"|place|stack|set|drop|delete|build|reverse|flip)\b)"), ""),
    # "collapse it into one long row", "squash them into a tower": the task's cubes made into that structure
    (re.compile(r"(?i)\b(?:collapse|squash|condense|fold|merge|combine|consolidate)\s+(it|them|everything|the\s+(?:whole\s+)?(?:grid|tower|stack"
                r"|row|line|pyramid|wall|circle|ring|cubes|blocks|towers|stacks|rows|lines))\s+(?:down\s+|up\s+)?into\b"),
     r"turn \1 into"),
    # "now tower, yellow on top", "keep the letters, row instead, reading BAT", "stack it instead, D at the bottom": the
    # task's cubes made into that structure (the roles after it are read with them)
    (re.compile(r"(?i)^\s*(?:(?:now|then|ok(?:ay)?|so)\s*,?\s*)+(tower|stack|row|line|pyramid|circle|ring)\s*(?=,)"), r"make it a \1"),
    (re.compile(r"(?i)(?<=,)\s*(tower|stack|row|line|pyramid|circle|ring)\s+instead\s*(?=,)"), r" make it a \1 instead"),
    (re.compile(r"(?i)^\s*(?:(?:now|then|ok(?:ay)?|so)\s*,?\s*)*(?:stack|pile)\s+(?:it|them|them\s+all|all\s+of\s+them|everything"
                r"|(?:all\s+)?the\s+(?:letters|digits|numbers|cubes|blocks|letter\s+cubes|digit\s+cubes))(?:\s+up)?\s+instead\s*(?=,)"),
     r"make it a tower instead"),
    # "make it 3 tall with a pink one on top": the cube added there (the count said again, checked)
    (re.compile(rf"(?i)\b(tall|high|long)\s+with\s+(an?\s+(?:{COLOR_RE})\s+(?:one|cube|block))\s+(on\s+top|at\s+the\s+(?:top|bottom|end|start))\b"),
     r"\1, put \2 \3"),
    # "four, and the top one orange": that count, and the change after it
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|then)\s*,?\s*)*(\d+|{COUNT_WORD_RE})\s*,\s*(?=and\s+)"), r"make it \1, "),
    # "reversed", "but backwards", "same cubes but in reverse order": the task reversed
    (re.compile(r"(?i)^\s*(?:(?:now|ok(?:ay)?|then|but|and)\s*,?\s*)*(?:(?:the\s+)?same\s+(?:cubes|blocks|ones|thing|letters|digits|numbers)\s*,?\s*(?:but\s+)?)?"
                r"(?:reversed|in\s+reverse(?:\s+order)?|backwards|the\s+other\s+way\s+(?:round|around))\s*[.!]?\s*$"), "reverse it"),
    # "five cubes, add a yellow and an orange at the right end": the count the additions reach (checked), then the additions
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|then)\s*,?\s*)*(\d+|{COUNT_WORD_RE})\s+(cubes|blocks)\s*,\s*(?=(?:and\s+)?add\s)"),
     r"make it \1 \2, "),
    # "all row to back side": the whole structure moved to that side
    (re.compile(r"(?i)^\s*(?:move\s+|put\s+)?all\s+(row|tower|stack|line|pyramid|wall|grid|circle)\s+(?:to|in|on)\s+(?:the\s+)?"
                r"(back|front|left|right)(?:\s+(side|half|edge))?\s*[.!]?\s*$"),
     lambda m: f"move the whole {m.group(1)} to the {m.group(2)} {m.group(3) or 'side'}"),
    # "let's try the row at the front instead", "the tower on the left instead": the whole structure moved to that side
    (re.compile(r"(?i)^" + _SAID_FIRST + r"(?:let'?s\s+)?(?:try|have|put|do|see)\s+(?:the\s+)?"
                r"(row|tower|stack|line|pyramid|wall|grid|circle|pile)\s+(?:at|in|on)\s+the\s+(back|front|left|right)"
                r"(?:\s+(side|half|edge))?(?:\s+of\s+the\s+table)?\s+instead\s*[.!]?\s*$"),
     lambda m: f"move the whole {m.group(1)} to the {m.group(2)} {m.group(3) or 'side'}"),
    # "the red cube, put it to the right of the green one instead": the cube said first, then the change to it
    (re.compile(r"(?i)^" + _SAID_FIRST + rf"(the\s+(?:(?:{COLOR_RE})|letter\s+[a-z]|digit\s+\d|[a-z]+)\s+"
                r"(?:cube|block|one)),\s+(?:please\s+)?(put|move|place|set|make|turn|take|slide|shift|paint|colou?r)\s+it\b"),
     r"\2 \1"),
    # "the tower goes on the right side", "the row should be at the back": the whole structure moved to that side
    (re.compile(r"(?i)^" + _SAID_FIRST + r"the\s+(?:whole\s+)?(row|tower|stack|line|pyramid|wall|grid|circle|pile)\s+"
                r"(?:goes|should\s+go|should\s+be|must\s+be|has\s+to\s+be|is\s+to\s+be|sits|moves)\s+(?:on|in|at|to)\s+the\s+"
                r"(back|front|left|right)(?:\s+(side|half|edge))?(?:\s+of\s+the\s+table)?(?:\s+instead|\s+now)?\s*[.!]?\s*$"),
     lambda m: f"move the whole {m.group(1)} to the {m.group(2)} {m.group(3) or 'side'}"),
    # "patch green instead", "the patch blue": the patch made that colour
    (re.compile(r"(?i)^" + _SAID_FIRST + rf"(?:the\s+)?patch\s+(?:->\s*|(?:should|must|needs\s+to|has\s+to)\s+be\s+|is\s+now\s+|becomes\s+)?({COLOR_RE})"
                r"(?:\s+instead|\s+now)?\s*[.!]?\s*$"),
     r"make the patch \1"),
    # "use the yellow patch", "same but on the cyan patch": the task's one patch in that colour (checked by the steering)
    (re.compile(r"(?i)^" + _SAID_FIRST + rf"(?:(?:use|try)\s+(?:a|the)|(?:same\s+(?:but|thing)\s+)?on\s+(?:a|the))\s+"
                rf"({COLOR_RE})\s+(?:goal\s+)?patch(?:\s+instead)?\s*[.!]?\s*$"), r"make the patch \1"),
    # "the back two should be blue", "top row in yellow", "put the green layer in pink": those cubes made that colour
    (re.compile(r"(?i)^" + _SAID_FIRST + rf"(?:put\s+)?((?:the\s+)?(?:top|bottom|middle|left|right|front|back|first"
                rf"|last|second|third|fourth|end|outer|inner|base|{COLOR_RE})(?:\s+[a-z0-9]+){{0,3}}?)\s+(?:should\s+be|must\s+be|needs\s+to\s+be"
                rf"|has\s+to\s+be|in|->)\s+({COLOR_RE})(?:\s+instead|\s+now)?\s*[.!]?\s*$"), r"make \1 \2"),
    # "move to front left": the task's cubes to that corner
    (re.compile(r"(?i)^" + _SAID_FIRST + r"(?:move|put|shift|slide)\s+(?:it\s+|them\s+|everything\s+)?(?:to|in|into)"
                r"\s+(?:the\s+)?(front|back)[\s-](left|right)(?:\s+corner)?\s*[.!]?\s*$"), r"move it to the \1 \2 corner"),
    # "the word is now DOGS", "word should be 'CAT'": that word spelled instead
    (re.compile(r"(?i)^" + _SAID_FIRST + r"(?:the\s+)?word\s+(?:is\s+now|should\s+be|becomes|is\s+to\s+be|will\s+be)\s+"
                r"(?:now\s+)?(?:(?-i:([A-Z]{2,}))|['\"\u2018\u201c]([A-Za-z]{2,})['\"\u2019\u201d])\s*[.!]?\s*$"),
     lambda m: f"spell {(m.group(1) or m.group(2)).upper()} instead"),  # (a word in capitals or quoted: "now longer" is none)
    # "teams also have to put the green cube on the blue patch": what is to be done, said of whoever does it
    (re.compile(r"(?i)^\s*(?:(?:the\s+)?(?:teams?|players?|students?|robots?|kids|pupils|learners|they|you|we)\s+)(also\s+)?(?:have|has|need|needs"
                r"|must|should)\s+(?:to\s+)?(?=(?:also\s+)?(?:put|place|add|stack|move|set|build|make)\b)"), r"\1"),
    # "I want the same three in a tower instead: ...": the task's cubes made into that structure, the roles after it read
    (re.compile(rf"(?i)^\s*(?:i\s+(?:want|need|'d\s+like)|let'?s\s+(?:have|try|do)|how\s+about|try)\s+(?:the\s+)?same\s+(?P<n>\d+|{COUNT_WORD_RE})?"
                r"\s*(?:cubes\s+|blocks\s+|ones\s+)?(?:in|as)\s+a\s+(?P<s>tower|stack|row|line|pyramid|circle)\s+instead\b"),
     lambda m: (f"same {m.group('n')} but " if m.group("n") else "") + f"make it a {m.group('s')} instead"),
    # "add a row of black cubes on top, three of them": the count said after the row
    (re.compile(rf"(?i)\b(add\s+(?:a|another|one\s+more)\s+(?:row|layer|course|level)\s+of)\s+((?:{COLOR_RE})\s+(?:cubes|blocks)\s+on\s+top)"
                rf"\s*,\s*((?:\d+|{COUNT_WORD_RE}))\s+of\s+them\s*[.!]?\s*$"), r"\1 \3 \2"),
    # "add, um, an eight on top": a digit cube by its number word
    (re.compile(r"(?i)\b(a|an)\s+(zero|two|three|four|five|six|seven|eight|nine)\b(?=\s+(?:on\s+top|at\s+the\s+(?:top|bottom|end|start)"
                r"|to\s+the\s+(?:left|right)|instead)\b)"),
     lambda m: f"{m.group(1)} digit {DIGIT_WORDS.index(m.group(2).lower())}"),
    # "actually in front", "at the back instead": a place alone, where the task's cubes are to be
    (re.compile(r"(?i)^" + _SAID_FIRST + r"(?:in|at|to)\s+(?:the\s+)?(back|front)"
                r"(?:\s+(side|half|edge))?(?:\s+of\s+the\s+table)?(?:\s+instead)?\s*[.!]?\s*$"),
     lambda m: f"move it to the {m.group(1)} {m.group(2) or 'side'}"),
    # "add brown also close to green": a cube of that colour added there
    (re.compile(rf"(?i)\badd\s+({COLOR_RE})\s+(?:also\s+)?(?=(?:close\s+to|next\s+to|near|beside|behind|in\s+front\s+of|on\s+top\s+of|on|to\s+the"
                r"|(?:left|right)\s+of|under|below|between)\b)"),
     r"add a \1 cube "),
    # "add a brown cube next to blue": the cube it goes by, named by its colour alone (the task's other cube had been read)
    (re.compile(rf"(?i)^(\s*add\s+an?\s+(?:{COLOR_RE})\s+cube\s+(?:close\s+to|next\s+to|near|beside|behind|in\s+front\s+of|on\s+top\s+of|on"
                rf"|(?:to\s+the\s+)?(?:left|right)\s+of|under|below))\s+({COLOR_RE})\s*(?=[.!,;]|$)"), r"\1 the \2 cube"),
    # "add a yellow and an orange at the right end", "add yellow and orange on top": a cube of each colour added there
    (re.compile(rf"(?i)\badd\s+(?:(?:a|an|one)\s+)?({COLOR_RE})\s+and\s+(?:(?:a|an|one)\s+)?({COLOR_RE})"
                r"(?=\s+(?:at\s+the\s+(?:(?:left|right|front|back)\s+end|top|bottom|start|end|beginning)|on\s+top)\s*(?:,\s*in\s+that\s+order)?"
                r"\s*[.!]?\s*$)"),
     lambda m: "add " + " and ".join(("an " if c[0] in "aeiou" else "a ") + f"{c} cube" for c in m.group(1, 2))),
    # "switch pink and gray", "swap pink n gray", "swap pink & gray": the two exchanged (texting's "n" and "&" are "and";
    # "switch" had been read as an action)
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*(?:swap|switch|exchange)\s+(?:the\s+)?({COLOR_RE})"
                rf"(?:\s+(?:one|cube|block))?\s+(?:and|n|&|\+|with)\s+(?:the\s+)?({COLOR_RE})(?:\s+(?:ones?|cubes?|blocks?))?\s*[.!]?\s*$"),
     r"swap \1 and \2"),
    # "cyan take out": that cube removed
    (re.compile(rf"(?i)^\s*(?:the\s+)?({COLOR_RE})(?:\s+(?:one|cube|block))?\s+(?:take\s+out|take\s+away|take\s+off|remove|out|away)\s*"
                r"(?:please|pls)?\s*[.!]?\s*$"), r"remove the \1 one"),
    # "Reset the puzzle to the original code.", "restore it to the original": the original version
    (re.compile(r"(?i)(?:^|(?<=[.!?]\s))(?:(?:ok(?:ay)?|fine|so|now|please)\s*,?\s*)*(?:reset|restore|revert|return|change)\s+(?:it|the\s+(?:puzzle"
                r"|task|tower|stack|row|line|pyramid|wall|scene|setup|set-up|layout|thing|whole\s+thing))\s+(?:back\s+)?to\s+(?:the\s+|its\s+)?"
                r"(?:original|first|starting)(?:\s+(?:code|one|version|setup|set-up|layout|state|design|task|puzzle))?\s*[.!]?\s*$"),
     "go back to the original"),
    # "Put it back the way it was at the start.": the original (the "was at" had been refused as another time)
    (re.compile(r"(?i)(?:^|(?<=[.!?]\s))(?:(?:ok(?:ay)?|fine|so|now|please)\s*,?\s*)*(?:put|set|change|turn)\s+it\s+back\s+(?:the\s+way|to\s+(?:how|what))\s+it"
                r"\s+was\s+(?:at\s+the\s+(?:start|beginning)|in\s+the\s+beginning|originally|at\s+first)\s*[.!]?\s*$"), "go back to the original"),
    # "jk put it back, and add an S at the end": the change before undone (then the rest applied to it)
    (re.compile(r"(?i)^\s*(?:(?:jk|j/k|just\s+kidding|kidding|no|nah|oops|hmm+|actually|wait)\s*[,.!]?\s*)*(?:please\s+)?(?:put|change|set|turn|switch)\s+"
                r"it\s+back(?:\s+(?:the\s+way\s+it\s+was|to\s+(?:how|what)\s+it\s+was|again))?(?=\s*(?:[,;.!]|$|\band\b))"), "undo"),
    # "swap the two cube colours": the colours exchanged; "all three the same colour: cyan": every cube that colour
    (re.compile(r"(?i)\b(swap|switch|exchange|flip)\s+the\s+(?:two|2)\s+(?:cube\s+|block\s+)?(colou?rs)\b"), r"\1 the \2"),
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|then)\s*,?\s*)*(?:make\s+)?(?:all\s+(?:\d+|{COUNT_WORD_RE}|of\s+them)|them\s+all|both)\s+"
                rf"(?:(?:the\s+)?same\s+colou?r|one\s+colou?r)\s*[:,-]?\s*({COLOR_RE})\s*[.!]?\s*$"), r"make them all \1"),
    # "undo the swap", "revert that change": the last change taken back (a version had been searched for "swap")
    (re.compile(r"(?i)\b(undo|revert)\s+(?:the|that|this|my|your)\s+(?:last\s+)?(?:swap|change|edit|recolou?r\w*|move|addition|reversal|flip|step"
                r"|rotation|pivot|tweak)\b"), r"\1"),
    # "Lose the purple cube", "and lose one", "ditch the top one": those removed (the verb had been unread)
    (re.compile(rf"(?i)\b(?:lose|ditch|nix|yank)\s+(?=(?:the|one|1|a|an|\d|{COLOR_RE})\b)"), "remove "),
    # "Scratch that last change.", "Scrap the last edit.", "Scratch that.": the whole edit takes the last change back (the
    # verb had been refused as an action); said with more ("scratch that, make it blue") it corrects the edit, not read here
    (re.compile(r"(?i)^\s*(?:(?:ok(?:ay)?|no|nah|hmm+|actually|wait|sorry|oops)\s*[,.!]?\s*)*(?:scratch|scrap|ditch|cancel|forget)"
                r"\s+(?:that|this|(?:that|the|this|my)\s+(?:last\s+|latest\s+|previous\s+)?(?:change|edit|step))"
                r"(?:\s+(?:last\s+)?(?:change|edit|step))?(?:\s*,?\s*(?:please|pls))?\s*[.!]?\s*$"), "undo"),
    # "row", "one long row", "a single tower instead": the task's cubes in that structure (a default task of made-up cubes
    # had been read)
    (re.compile(r"(?i)^\s*(?:(?:now|ok(?:ay)?|then|so|actually)\s*,?\s*)*(?:as\s+|into\s+)?(?:one|a|an|the|single|a\s+single)?\s*"
                r"(?:(?:long|big|tall|single|straight|neat)\s+)?(row|line|tower|stack|pyramid|circle|ring)\s*(?:instead|please|now|then)*\s*[.!]?\s*$"),
     r"make it a \1"),
    # "swap the two middle ones", "the 2 bottom ones swap", "the two middle ones trade places": the pair by its place
    (re.compile(r"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then|level\s+\d+\s*->)\s*,?\s*)*(?:swap|switch|exchange|flip)\s+the\s+(?:two|2)\s+"
                r"(middle|bottom|top|first|last|left|leftmost|right|rightmost|lowest|highest)(?:\s+(?:ones|cubes|blocks))?\s*[.!]?\s*$"),
     r"swap the \1 two"),
    (re.compile(r"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*the\s+(?:two|2)\s+(middle|bottom|top|first|last|left|leftmost|right"
                r"|rightmost|lowest|highest)(?:\s+(?:ones|cubes|blocks))?\s+(?:should\s+|must\s+)?(?:swap|switch|exchange|trade)"
                r"(?:\s+(?:places|spots|positions))?\s*[.!]?\s*$"),
     r"swap the \1 two"),
    # "the green and red trade places", "let red and blue switch places": the two exchanged
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then|let)\s*,?\s*)*(?:have\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:one|cube|block))?\s+and\s+"
                rf"(?:the\s+)?({COLOR_RE})(?:\s+(?:ones?|cubes?|blocks?))?\s+(?:should\s+|must\s+)?(?:swap|switch|exchange|trade)\s+"
                r"(?:places|spots|positions)\s*[.!]?\s*$"),
     r"swap \1 and \2"),
    # "bottom layer cyan", "top one green": that place made that colour (terse, no verb)
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*(?:the\s+)?(top|bottom|base|middle|first|last)"
                rf"(\s+(?:layer|row|level|tier|one|cube|block))?\s+({COLOR_RE})(?:\s+(?:now|instead|please))*\s*[.!]?\s*$"),
     r"make the \1\2 \3"),
    # "make both ends orange", "the ends should be yellow": the first and the last cube that colour (the ends of a row of one
    # colour in no order, too: :func:`rpg.steer.edits.apply_ops`)
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*(?:make|paint|turn|colou?r)\s+(?:both\s+(?:the\s+)?|the\s+(?:two\s+)?)ends\s+"
                rf"(?:of\s+(?:it|the\s+(?:tower|stack|row|line))\s+)?({COLOR_RE})\s*[.!]?\s*$"),
     r"make the ends \1"),
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*(?:both\s+(?:the\s+)?|the\s+(?:two\s+)?)ends\s+(?:should\s+be|must\s+be|become|are)\s+"
                rf"({COLOR_RE})\s*[.!]?\s*$"),
     r"make the ends \1"),
    # "all of them orange", "all pink now": every cube that colour
    (re.compile(rf"(?i)^\s*(?:(?:please|pls|now|ok(?:ay)?|and|then)\s*,?\s*)*(?:all\s+of\s+them|them\s+all|all(?:\s+the)?\s+(?:cubes|blocks))\s+"
                rf"(?:in\s+)?({COLOR_RE})(?:\s+(?:now|instead|please))*\s*[.!]?\s*$"),
     r"make them all \1"),
    # "change all purple to red", "turn every purple one red": each cube of that colour
    (re.compile(rf"(?i)\b(change|turn|make|paint|recolou?r)\s+(?:all|every|each)\s+(?:of\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:ones?|cubes?|blocks?))?"
                rf"\s+(?:(?:to|into)\s+)?(?=(?:{COLOR_RE})\b)"),
     r"\1 the \2 blocks to "),
    # "also put a pink cube on a blue patch, keep the yellow one where it is": what an addition keeps anyway
    (re.compile(rf"(?i)\s*[,;]\s*(?:and\s+)?(?:keep|leave)\s+(?:the\s+)?(?:(?:{COLOR_RE})\s+)?(?:one|cube|block|tower|stack|row|rest|others?"
                r"|everything\s+else)\s+(?:where\s+(?:it|they)\s+(?:is|are)|as\s+(?:it|they)\s+(?:is|are)|in\s+place|unchanged|alone)"
                r"(?=\s*[.!]?\s*$)"),
     ""),
    # "now split it into two towers of two: red under blue, green under yellow": the task's cubes in the structures then
    # listed, a whole task (a pivot; the steering checks they are the task's own cubes)
    (re.compile(r"(?i)^\s*(?:(?:ok(?:ay)?|now|so|then|next)\s*,?\s*)*(?:split|break|divide|separate|turn|rebuild|rearrange|make|change"
                r"|reorganize|reorganise)\s+(?:it|them|this|the\s+(?:tower|stack|row|line|pyramid|structure|cubes|blocks))\s+(?:up\s+)?"
                r"(?:into|in)\s+(?=(?:a|an|one|two|three|2|3)\s+(?:separate\s+|single\s+)?(?:towers?|stacks?|rows?|lines?|piles?)\b[^:]*:\s*\S)"),
     "make "),
    # "now the same three in a tower, red at the bottom, then green, blue on top": the task's cubes in that structure
    (re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|now|so|then|next)\s*,?\s*)*(?:(?:put|make|arrange|place|stack|build)\s+)?(?:the\s+)?same\s+"
                rf"(?:\d+|{COUNT_WORD_RE})(?:\s+(?:cubes|blocks|ones))?\s+(?:in(?:to)?|as)\s+(?=(?:a|an|one)\s+(?:tower|stack|row|line|circle|pile)\b"
                r"\s*,?\s*(?:with\s+)?(?:the\s+)?[a-z]+\b)"),
     "make "),
    # "make it HELLO", "BED -> RED": another word (capitals: a word the cubes spell, not a colour or a count)
    (re.compile(rf"^\s*(?:(?:nah|ok(?:ay)?|now|so|then|actually)\s*,?\s*)*(?:make|change|turn)\s+it\s+(?:to\s+|into\s+)?(?!(?i:{COLOR_RE})\b)([A-Z]{{2,}})\s*[.!]?\s*$"),
     r"make it spell \1"),
    (re.compile(rf"^\s*[A-Z]{{2,}}\s*(?:->|\u2192|=>)\s*(?!(?i:{COLOR_RE})\b)([A-Z]{{2,}})\s*[.!]?\s*$"), r"make it spell \1"),
    # terse recolours: "patch -> cyan", "brown -> cyan, orange -> pink", "s/yellow/blue/": each named thing made that colour
    (re.compile(rf"(?i)^\s*s/({COLOR_RE})/({COLOR_RE})/?\s*$"), r"make the \1 cube \2"),
    (re.compile(rf"(?i)^\s*(?:(?:the|that)\s+)?(?-i:(?![A-Z]{{2,}}\b))[a-z]+(?:\s+[a-z]+){{0,4}}\s*(?:->|\u2192|=>)\s*(?:{COLOR_RE})(?:\s*(?:,|and)\s*(?:(?:the|that)\s+)?"
                rf"[a-z]+(?:\s+[a-z]+)?\s*(?:->|\u2192|=>)\s*(?:{COLOR_RE}))*(?:\s+and\s+(?:{COLOR_RE}))?\s*[.!]?\s*$"),
     lambda m: m.group(0) if re.fullmatch(rf"(?i)\s*(?:{COLOR_RE})\s*(?:->|\u2192|=>)\s*(?:{COLOR_RE})\s*[.!]?\s*", m.group(0)) else "make " + " and ".join(
         (f"the {x} cube" if re.fullmatch(rf"(?i){COLOR_RE}", x) else f"the {re.sub(r'(?i)^(?:the|that)[ ]+', '', x)}") + f" {y}"
         for x, y in re.findall(r"([a-z]+(?:\s+[a-z]+){0,4})\s*(?:->|\u2192|=>)\s*([a-z]+(?:\s+and\s+[a-z]+)?)", m.group(0), re.I))),
    # "same but in the front left corner", "like before but with the yellow cube": the change, to the task as it is
    (re.compile(r"(?i)^\s*(?:(?:ok(?:ay)?|now|so|and)\s*,?\s*)*(?:(?:the\s+)?same(?:\s+thing)?\s+as\s+before|like\s+before)"
                r"\s*,?\s*but\s+(?P<x>.+?)(?:\s+instead)?\s*[.!]?\s*$"), r"\g<x> instead"),
    (re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|now|so|and)\s*,?\s*)*(?:(?:the\s+)?same(?:\s+thing)?\s*,?\s*but\s+)?with\s+(?:the\s+|a\s+)?"
                rf"({COLOR_RE})\s+(?:cube|block|one)(?:\s+instead)?\s*[.!]?\s*$"), r"make the cube \1"),
    # "red <-> green": the two exchanged; "mv tower -> center": moved there; "left to right instead": that direction
    (re.compile(r"(?i)^\s*([a-z]+(?:\s+[a-z]+)?)\s*(?:<->|\u2194|<=>)\s*([a-z]+(?:\s+[a-z]+)?)\s*[.!]?\s*$"), r"swap \1 and \2"),
    (re.compile(r"(?i)^\s*mv\s+(?:the\s+)?([a-z]+(?:\s+[a-z]+)?)\s*(?:->|\u2192|=>|\s+to)\s*(?:the\s+)?([a-z]+(?:\s+[a-z]+)?)\s*[.!]?\s*$"),
     r"move the \1 to the \2"),
    (re.compile(r"(?i)^\s*(?:(?:now|ok(?:ay)?|and)\s*,?\s*)*((?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left|front\s+to\s+back"
                r"|back\s+to\s+front))(?:\s+(?:instead|now|please|pls))*\s*[.!]?\s*$"), r"make it \1 instead"),
    # "nah, like before": the version before this one
    (re.compile(r"(?i)^\s*(?:(?:nah|no|hmm+|ok(?:ay)?|actually)\s*,?\s*)*(?:(?:just\s+)?(?:like|as)\s+(?:it\s+was\s+)?before|as\s+it\s+was)"
                r"\s*[.!]?\s*$"), "undo"),
    # "put white between green and blue": a cube added between two (the edit had replaced the task with that relation)
    (re.compile(rf"(?i)^\s*(?:(?:now|and|also|then)\s+)*(?:put|place|insert|stick|add)\s+(?:a\s+|an\s+|the\s+)?({COLOR_RE})"
                rf"(?:\s+(?:one|cube|block))?\s+(?=between\s+(?:the\s+)?(?:{COLOR_RE})\b)"), r"add a \1 cube "),
    # "the top one is wrong, it should be orange": that cube made orange (every cube had been recoloured)
    (re.compile(rf"(?i)^\s*(the\s+[a-z0-9 ]+?)\s+(?:is|looks)\s+wrong\s*[,;.:]?\s*(?:it|that\s+one|that)\s+(?:should|must|needs\s+to)\s+be\s+"
                rf"({COLOR_RE})\s*[.!]?\s*$"), r"make \1 \2"),
    # "the one in the middle", "the cube on top": the cube by its place, as "the middle one" says it
    (re.compile(r"(?i)\bthe\s+(?:one|cube|block)\s+(?:in\s+the\s+(middle|centre|center)|(?:on|at)\s+(?:the\s+)?(top|bottom))\b(?!\s+of\b)"),
     lambda m: f"the {(m.group(1) or m.group(2)).replace('centre', 'middle').replace('center', 'middle')} one"),
    # "n=6 pls", "count = 4": the structure's count
    (re.compile(r"(?i)^\s*(?:n|count|num|size|length|height)\s*=\s*(\d+)\s*(?:please|pls|plz)?\s*[.!]?\s*$"), r"make it \1"),
    # "now five instead of three": that count
    (re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|now|so|then)\s*,?\s*)*(\d+|{COUNT_WORD_RE})\s+instead\s+of\s+(?:\d+|{COUNT_WORD_RE})\s*[.!]?\s*$"),
     r"use \1 blocks instead"),
    # "extend it to spell STOP": the word changed (no action)
    (re.compile(r"(?i)\b(?:extend|grow|lengthen|expand)\s+(?:it|that|this|the\s+word)\s+to\s+(spell|say|read)\b"), r"make it \1"),
    # "what if the base was black": a recolour said as a wish, no condition on the scene
    (re.compile(rf"(?i)^\s*what\s+if\s+(the\s+(?:[a-z]+\s+){{0,2}}?(?:base|top|bottom|middle|one|cube|block|row|layer|tower|line))\s+"
                rf"(?:was|were|is|became)\s+({COLOR_RE})\s*\??\s*$"), r"make \1 \2"),
    # "same but in yellow": every cube that colour
    (re.compile(rf"(?i)^\s*(?:the\s+)?same\s+(?:thing\s+|task\s+)?but\s+(?:all\s+)?(?:in\s+)?({COLOR_RE})\s*[.!]?\s*$"), r"make them all \1"),
    # "use a purple cube in the middle instead of the yellow one": the cube named replaced where it stands
    (re.compile(rf"(?i)\b(use)\s+(an?\s+)?({COLOR_RE})\s+(cube|block|one)\s+(?:in\s+the\s+(?:middle|centre|center)|on\s+top"
                rf"|at\s+the\s+(?:top|bottom|base|end|start))\s+(instead\s+of|in\s+place\s+of)\s+(the\s+(?:{COLOR_RE})\s+(?:one|cube|block))\b"),
     r"\1 \2\3 \4 \5 \6"),
    # "make it so that the green cube is the lowest one", "make sure the top one is green": what is to hold (the words before
    # it had been read as a recolour of every cube to green); "the green cube should be at the bottom", "make the green one
    # the top one": that cube moved to that end
    (re.compile(r"(?i)^\s*(?:please\s+)?make\s+(?:it\s+)?so\s+(?:that\s+)?|^\s*(?:please\s+)?make\s+sure\s+(?:that\s+)?"
                r"|^\s*(?:please\s+)?change\s+(?:it|this|that|the\s+task)\s+so\s+(?:that\s+)?"), ""),  # ("change it so both are ...")
    # "change the bottom layer so it goes orange, green, orange": that layer's colours, in turn
    (re.compile(r"(?i)^\s*(?:please\s+)?change\s+(the\s+(?:top|bottom|middle|base|first|second|third|lowest|upper|lower)\s+(?:layer|row|level|tier))\s+"
                r"so\s+(?:that\s+)?(?:it|its\s+(?:cubes|blocks|colou?rs))\s+(?:goes|go|reads?|is|are|runs?)\s+"), r"make \1 "),
    (re.compile(rf"(?i)^\s*(?:please\s+)?(?:i\s+want\s+)?(?:the\s+)?({COLOR_RE})\s+(?:cube\s+|block\s+|one\s+)?(?:is|should\s+be|must\s+be|becomes|goes|sits|ends\s+up)\s+"
                r"(?:the\s+|at\s+the\s+|on\s+the\s+|in\s+the\s+|on\s+)?(lowest|bottom|base|bottommost|highest|top|topmost|uppermost)"
                r"(?:\s+(?:one|cube|block|of\s+(?:the\s+)?(?:tower|stack)))?\s*(?:please|instead|now)?\s*[.!]?\s*$"),
     lambda m: f"put the {m.group(1)} cube at the {'bottom' if m.group(2).lower() in ('lowest', 'bottom', 'base', 'bottommost') else 'top'}"),
    (re.compile(rf"(?i)^\s*(?:please\s+)?make\s+the\s+({COLOR_RE})\s+(?:cube\s+|block\s+|one\s+)?the\s+"
                r"(lowest|bottom|bottommost|highest|top|topmost|uppermost)(?:\s+(?:one|cube|block))?\s*(?:please|instead|now)?\s*[.!]?\s*$"),
     lambda m: f"put the {m.group(1)} cube at the {'bottom' if m.group(2).lower() in ('lowest', 'bottom', 'bottommost') else 'top'}"),
    # "add purple on top to finish the rainbow": why the cube is added (the rainbow had been read as a new colour order)
    (re.compile(r"(?i)\s*,?\s*(?:so\s+as\s+)?(?:to|and)\s+(?:finish|complete|close|end|round\s+off)\s+(?:the|it|its|this)\s*"
                r"(?:rainbow|gradient|sequence|pattern|word|tower|stack|row|line|set)?\s*(?:off|up)?(?=\s*[.!]?\s*$)"), ""),
    # "one more on top", "add a third": one more cube
    (re.compile(r"(?i)^\s*(?:and\s+|plus\s+)?(?:add\s+|put\s+)?one\s+more\s+on\s+top\s*[.!]?\s*$"), r"add one more block on top"),
    (re.compile(r"(?i)^\s*(?:and\s+|now\s+)?add\s+a\s+(?:third|fourth|fifth|sixth)(?:\s+(?:one|cube|block))?\s*[.!]?\s*$"), r"add one more block"),
    # "ok then just a green cube at the right end": a cube added at that end
    (re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|fine|alright)\s*,?\s*)?(?:then\s+)?(?:just\s+)?(?:a|an|one)\s+({COLOR_RE})\s+(?:cube|block)\s+"
                r"(?:at|on)\s+the\s+(left|right|top|bottom|front|back)(\s+end)?\s*(?:then|instead)?\s*[.!]?\s*$"), r"add a \1 cube at the \2\3"),
    # "hmm too tall, go down to three": that count (the judgement before it asks nothing more)
    (re.compile(rf"(?i)^\s*(?:(?:hmm+|ok(?:ay)?|nah|actually)\s*,?\s*)*(?:(?:too|a\s+bit)\s+(?:tall|high|long|big|short|small|wide)\s*[,;.]?\s*)?"
                rf"(?:go|come|bring\s+it|take\s+it|cut\s+it|drop\s+it|scale\s+it)\s+(?:back\s+)?(?:down|up)\s+to\s+(\d+|{COUNT_WORD_RE})\b"),
     r"make it \1"),
    # "pile them up into a tower instead, leftmost one at the bottom": the line's order kept, from its left end up
    (re.compile(r"(?i)\s*,?\s*(?:with\s+)?(?:the\s+)?(?:leftmost|left|first)\s+(?:one|cube|block)\s+(?:at|on)\s+(?:the\s+)?(?:bottom|base)\b"),
     " in the same order"),
    # "Then please put them on top of each other. Black is the top.": stack them, that cube at that end
    (re.compile(r"(?i)\b(?:put|place|set)\s+(them|all\s+of\s+them|the\s+cubes|the\s+blocks)\s+on\s+top\s+of\s+(?:each\s+other|one\s+another)\b"),
     r"stack \1"),
    (re.compile(rf"(?i)\s*[.,;]\s*(?:and\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:one|cube|block))?\s+(?:is|should\s+be|goes|must\s+be)\s+"
                r"(?:the\s+|at\s+the\s+|on\s+)(top|bottom)(?:\s+one)?\s*[.!]?\s*$"), r", with \1 at the \2"),
    # "top one red", "left one green": that cube recoloured
    (re.compile(rf"(?i)^\s*(?:(?:and|now|then|ok(?:ay)?)\s*,?\s+)*(?:the\s+)?(top|bottom|middle|left|right|leftmost|rightmost|base)\s+"
                rf"(?:one|cube|block)\s+({COLOR_RE})\s*(?:please|now|instead)?\s*[.!]?\s*$"), r"make the \1 one \2"),
    # "bump it to 8", "bump it up to 8 cubes": that count
    (re.compile(rf"(?i)\bbump\s+(?:it|that|this|them)\s+(?:up\s+)?to\s+(\d+|{COUNT_WORD_RE})\b"), r"make it \1"),
    # "I think green would be better than red", "green would look better than red": one colour for the other
    (re.compile(rf"(?i)^\s*(?:(?:i|we)\s+(?:think|guess|feel|reckon)\s+)?(?:that\s+)?(?:maybe\s+)?(?:an?\s+|the\s+)?({COLOR_RE})"
                rf"(?:\s+(?:one|cube|block))?\s+(?:would|will|might|could)\s+(?:be|look|work)\s+better\s+than\s+(?:the\s+)?({COLOR_RE})"
                r"(?:\s+(?:one|cube|block))?\s*[.!]?\s*$"), r"use \1 instead of \2"),
    # "add two more greens on top", "make it taller with two more blues": that many more cubes of the colour
    (re.compile(rf"(?i)\b(?:make\s+it\s+(?:taller|higher|longer)\s+(?:with|by\s+adding|by)\s+)?(\d+|{COUNT_WORD_RE})\s+more\s+({COLOR_RE})s\b"),
     r"add \1 more \2 blocks"),
    (re.compile(r"(?i)\b(thank\s+you|thanks)\s+(?:so|very)\s+much\b"), r"\1"),  # thanks, not a quantity
    # a greeting and thanks for what was done: nothing to change ("this" there is the task, not a cube)
    (re.compile(r"(?i)^\s*(?:hello|hi|hey)(?:\s+there)?\s*[,!.]\s*"), ""),
    (re.compile(r"(?i)(?:^|(?<=[.!,]))\s*(?:thank\s+you|thanks)(?:\s+a\s+lot)?(?:\s+for\s+(?:this|that|it|the\s+\w+))?\s*[,.!]\s*"), " "),
    (re.compile(r"(?i)\b(could|would|can)\s+you\s+(?:possibly|perhaps|maybe|please)\s+"), r"\1 you "),
    (re.compile(r"(?i)(?:^|(?<=[.!,]))\s*(?:it|this|that)\s+looks\s+(?:really\s+)?(?:great|good|nice|fine|awesome|perfect|cool)\s*[.!,]"), " "),
    # a review's or an annotator's opening ("LGTM otherwise, but", "correction:", "suggestion:", "nit:"): no change said
    (re.compile(r"(?i)^\s*(?:lgtm|looks\s+good|looks\s+great|nice)(?:\s+otherwise)?\s*[,.!]?\s*(?:but\s+)?"), ""),
    (re.compile(r"(?i)^\s*(?:correction|suggestion|nit|fix|update|edit|change)\s*:\s*"), ""),
    (re.compile(r"(?i)\b(put|place|add|stack)\s+also\b"), r"also \1"),  # "put also one red cube under ...": the order of other tongues
    # terse and non-native edits: "more one black on top" (one more), "yellow go to end please" (moved to an end),
    # "now FUN" (the word spelled), "put it in corner, front right" (that corner), "the row should be in the back of the
    # table" (the structure moved there)
    (re.compile(r"(?i)\bmore\s+(one|\d+)\b(?!\s+(?:than|of)\b)"), r"\1 more"),
    (re.compile(rf"(?i)^\s*(?:the\s+)?({COLOR_RE}|(?:(?:letter|digit|number)\s+)?(?-i:[A-Z])|(?:(?:digit|number)\s+)?\d)(?:\s+(?:one|cube|block))?\s+"
                r"(?:go|goes|should\s+go|must\s+go|to)\s+(?:to\s+)?(?:the\s+)?"
                r"(end|last|start|beginning|first)(?:\s+place)?\s*(?:please|pls|plz)?\s*[.!]?\s*$"),
     lambda m: ("move the " + (f"{m.group(1)} one" if re.fullmatch(COLOR_RE, m.group(1), re.I) else
                               f"{'digit' if m.group(1)[-1].isdigit() else 'letter'} {m.group(1).split()[-1]} cube")
                + f" to the {'end' if m.group(2).lower() in ('end', 'last') else 'start'}")),
    # "now FUN", "v2: CART" (the label already gone): the word spelled (not a command said in capitals: "UNDO")
    (re.compile(rf"^\s*(?:(?:now|then|and\s+now|ok(?:ay)?\s+now)\s*,?\s*)?'?(?!(?i:{COLOR_RE})\b)(?!(?:UNDO|REDO|REVERT|RESET|BACK|DONE|OK|OKAY|YES|NO|STOP|NEW|FRESH|AGAIN|SAME)\b)"
                r"([A-Z]{2,})'?\s*[.!]?\s*$"),
     r"make it spell \1"),
    (re.compile(r"(?i)\b(in|to|into)\s+(?:the\s+)?corner\s*,\s*(front|back)[\s-]+(left|right)\b"), r"\1 the \2 \3 corner"),
    (re.compile(r"(?i)\bthe\s+(tower|stack|row|line|pyramid|wall|grid|circle|pile)\s+(?:should|must|needs\s+to|has\s+to)\s+"
                r"(?:be|go|stand|sit)\s+(?:in|at|on)\s+(?=the\s+(?:front|back|left|right|middle|cent))"), r"move the \1 to "),
    # "... on the blue patch together with the red one": the patch it shares, said twice
    (re.compile(rf"(?i)(\bpatch)\s*,?\s+(?:together\s+with|alongside|along\s+with)\s+the\s+(?:{COLOR_RE})\s+(?:one|cube|block)\b"), r"\1"),
    # "hope you're having a good day! ... I was wondering, would it be at all possible to make ...": the request
    (re.compile(r"(?i)^.*?\b(?:would|could)\s+it\s+be\s+(?:at\s+all\s+)?possible\s+to\s+"), ""),
    (re.compile(r"(?i)[.!]?\s*(?:no\s+rush(?:\s+at\s+all)?|thanks?(?:\s+(?:so\s+much|a\s+lot|in\s+advance))?|many\s+thanks"
                r"(?:\s+in\s+advance)?|cheers)\s*[.!]?\s*(?=(?:no\s+rush|thanks?|many\s+thanks|cheers|$))"), ""),
    # "it should be behind, not in front": the relation said, the old one denied (a correction, not a negation)
    (re.compile(r"(?i)\b(behind|in\s+front(?:\s+of\s+it)?|on\s+top|under(?:neath)?|below|above|(?:to\s+the\s+)?(?:left|right)(?:\s+of\s+it)?"
                r"|next\s+to\s+it|on\s+the\s+(?:left|right))\s*,\s*(?:and\s+)?not\s+(?:behind|in\s+front|on\s+top|under(?:neath)?|below|above"
                r"|(?:to\s+the\s+|on\s+the\s+)?(?:left|right)|next\s+to)(?:\s+of)?(?:\s+(?:it|of\s+it))?\s*[.!]?\s*$"), r"\1"),
    # "the bottom one should be blue, not pink": the colour said, the old one denied (a correction, not a negation)
    (re.compile(rf"(?i)\b({COLOR_RE})\s*,\s*(?:and\s+)?not\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:one|cube|block))?"
                r"(?=\s*(?:[.!,;]|$))"), r"\1"),
    # "instead of the blue cube use a green one", "instead of blue use orange": the substitution said the other way round
    (re.compile("(?i)" + EDIT_OPENING + rf"instead\s+of\s+(?P<old>(?:the\s+|an?\s+)?(?:{COLOR_RE})"
                r"(?:\s+(?:cube|block|patch|one)s?)?)\s*,?\s*(?:use|put|take|have|go\s+with|make\s+it)\s+(?P<new>[^,;.!]+?)\s*[.!]?\s*$"),
     lambda m: "use " + re.sub(r"(?i)\s+one$", " cube", m.group("new")) + " instead of " + m.group("old")),
    # "keep everything but the middle one make it purple": that cube recoloured, the rest kept ("it" is that cube)
    (re.compile(rf"(?i)^\s*keep\s+(?:everything|all|the\s+rest)(?:\s+(?:else|the\s+same))?\s*,?\s*(?:but|except)\s+(?:make\s+)?"
                rf"(the\s+(?:[a-z0-9]+\s+){{0,2}}?(?:one|block|cube))\s*[,:]?\s*(?:make\s+it\s+|should\s+be\s+|is\s+|in\s+|as\s+)?"
                rf"({COLOR_RE})\s*[.!]?\s*$"), r"make \1 \2"),
    # "nah, let's do GOD": the word spelled instead
    (re.compile(EDIT_OPENING + r"(?i:let'?s\s+(?:do|go\s+with|try)|do|try|go\s+with|how\s+about)"
                r"\s+([A-Z]{2,})\s*(?i:instead)?\s*[.!?]?\s*$"), r"spell \1 instead"),
    # "back to how it was at the start": the first version
    (re.compile("(?i)" + EDIT_OPENING + r"(?:(?:go|going|get)\s+)?back\s+to\s+(?:how|what)\s+it\s+"
                r"(?:was|looked)\s+(?:at\s+the\s+(?:start|beginning)|originally|at\s+first|in\s+the\s+beginning)\s*[.!]?\s*$"),
     "go back to the original"),
    # "2x2 is enough", "3 by 3 would be better": that size
    (re.compile(r"(?i)^\s*(\d+\s*(?:x|by)\s*\d+)\s+(?:is|would\s+be|will\s+be|should\s+be)\s+(?:enough|fine|plenty|better|good|ok(?:ay)?)"
                r"\b\s*[.!]?\s*$"), r"make it \1"),
    # "one more pair pls": two more cubes (a pattern goes on: :func:`rpg.steer.edits._resize`)
    (re.compile(r"(?i)^\s*(?:(?:add|and)\s+)?(?:one|1|another)\s+more\s+pair\b"), "add 2 more blocks"),
    # "C -> B", "3 => 5": a label cube replaced by another
    (re.compile(r"^\s*([A-Z0-9])\s*(?:->|\u2192|=>)\s*([A-Z0-9])\s*$"), r"replace the \1 with a \2"),
    # "all three in a row instead, brown, green, yellow from left to right": those cubes as a row in that order (the row had
    # been lost: the direction alone was read, of a chain of relations)
    (re.compile(rf"(?i)^\s*(?:(?:now|ok(?:ay)?|so|then|and)\s*,?\s*)*(?:all|the|those|these)\s+(?P<n>\d+|{COUNT_WORD_RE})\s+"
                rf"(?:in|as|into)\s+an?\s+(?:row|line)(?:\s+instead)?\s*[,:;]\s*(?P<list>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE}))+)\s+"
                r"(?P<dir>(?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left|front\s+to\s+back|back\s+to\s+front))\s*[.!]?\s*$"),
     r"line up all \g<n> cubes \g<dir>: \g<list>"),
    # "same stack, but in the back left corner": that structure put there (checked to be the task's: "same row but on the
    # left" of a tower is refused; a stack of two default cubes had been made)
    (re.compile(r"(?i)^\s*(?:the\s+)?same\s+(tower|stack|row|line|pyramid|wall|pile)\s*,?\s*(?:but\s+)?(?=(?:in|on|at|to|into)\s+the\s+"
                r"(?:far\s+|very\s+)?(?:left|right|front|back|rear|middle|cent(?:er|re))(?:[\s-]+(?:left|right))?(?:\s+(?:side|corner|half|edge|end"
                r"|part))?(?:\s+of\s+the\s+(?:table|workspace))?\s*[.!]?\s*$)"), r"put the \1 "),  # (a place and nothing else: "same
    # row but in the front, reversed" had been moved only)
    # "same thing but on the left", "same thing but front to back": the task moved, or run the other way
    (re.compile(r"(?i)^\s*(?:the\s+)?same\s+(?:thing|task|again|as\s+before|set-?up|arrangement|layout)\s*,?\s*but\s+(?:on|to|at|in)\s+the\s+"
                r"(left|right|front|back)(?:\s+side)?(?:\s+of\s+the\s+table)?\s*[.!]?\s*$"), r"move it to the \1 of the table"),
    (re.compile(r"(?i)^\s*(?:the\s+)?same\s+(?:thing|task|again|as\s+before|set-?up|arrangement|layout)\s*,?\s*but\s+(?:going\s+|running\s+|from\s+)?"
                r"(left\s+to\s+right|right\s+to\s+left|front\s+to\s+back|back\s+to\s+front)\s*[.!]?\s*$"), r"make it \1"),
    # "same thing but DOG": the word changed
    (re.compile(r"^\s*(?:(?:the\s+)?same\s+(?:thing|task|again|as\s+before|set-?up|arrangement|layout)\s*,?\s*)?but\s+(?:with\s+)?([A-Z]{2,})\s*[.!]?\s*$"),
     r"spell \1 instead"),
    (re.compile(r"(?i)^\s*(?:the\s+)?same\s+(?:thing|task|again|as\s+before|set-?up|arrangement|layout)\s*,?\s*but\s+"), ""),
    # notebook edits: "n_cubes=3", "region=back", "rel=left_of", "red -> gray", "+green top", "@center"
    (re.compile(r"(?i)^\s*(?:n_?cubes|num_?cubes|n_?blocks|count|n)\s*[=:]\s*(\d+)\s*$"), r"use \1 blocks instead"),
    (re.compile(r"(?i)^\s*(?:rel|relation|predicate)\s*[=:]\s*(left_of|right_of|in_front_of|behind|next_to|far_from|on|on_top_of|under)\s*$"),
     lambda m: f"put it {m.group(1).replace('_', ' ')} instead"),
    (re.compile(r"(?i)^\s*(?:(?:region|place|where|location|loc)\s*[=:]|@)\s*([a-z_]+)\s*$"),
     lambda m: f"move it to the {m.group(1).replace('_', ' ')} of the table"),
    (re.compile(rf"(?i)^\s*({COLOR_RE})\s*(?:->|\u2192|=>)\s*({COLOR_RE})\s*$"), r"make the \1 ones \2"),
    (re.compile(rf"(?i)^\s*\+\s*(?:1\s+)?({COLOR_RE})\s+(?:on\s+)?(top|bottom)\s*$"),
     lambda m: f"add a {m.group(1)} block {'on top' if m.group(2).lower() == 'top' else 'at the bottom'}"),
    # "like v0 but with a yellow top": that end's cube recoloured; "... but with a black cube on top": one added there
    (re.compile(rf"(?i)\bbut\s+with\s+(?:a|an)\s+({COLOR_RE})\s+(top|bottom|base)\b(?!\s+(?:of|layer|row|level))"),
     r"but make the \2 one \1"),
    (re.compile(rf"(?i)\bbut\s+with\s+(?:a|an|one)\s+(?:(?:new|extra|more)\s+)?({COLOR_RE})\s+(?:cube|block|one)\s+"
                r"(on\s+top|at\s+the\s+(?:top|bottom))\b"), r"but add a \1 block \2"),
    (re.compile(r"(?i)\bon\s+top\s+of\s+(?:that|this)(?!\s+\w+\s+(?:block|cube|one)\b)"), "on top of the tower"),  # "and a T on top of that"
    (re.compile(r"(?i)^\s*(?:and|plus)(?:\s+(?:now|then|also))?\s+(?=(?:a|an|another|one\s+more|\d+)\s)"), "add "),  # "and (now) a red block on top"
    (re.compile(r"(?i)\blay\s+(them|it|everything|the\s+(?:blocks|cubes))\s+out\b"), r"put \1"),  # "lay them out in a line"
    (re.compile(r"(?i)^\s*ad\s+(?=(?:a|an|another|one|\d+)\s)"), "add "),  # "ad a yelow block on top"
    # "take one off": a cube taken off a stack is its top one
    (re.compile(r"(?i)^\s*(?:take|pull|lift)\s+(?:1|one)\s+(?:block\s+|cube\s+)?off(?:\s+(?:the\s+)?(?:top|tower|stack))?\s*[.!]?\s*$"),
     "remove the top one"),
    # "paint it blue": in an edit, a cube's new colour (the task's cubes are swapped for cubes of that colour)
    (re.compile(r"(?i)\b(?:paint|repaint|colou?r|recolou?r|dye)\s+(?=(?:it|them|the|that|this|all|both|every|each)\b)"), "make "),
    # "make it blue on white instead": a new stack of the two colours
    (re.compile(rf"(?i)\bmake\s+(?:it|them)\s+({COLOR_RE})\s+on\s+({COLOR_RE})\b"), r"stack the \1 block on the \2 block"),
    # "fine. make the cube white then": the opening word and the closing "then" say nothing of the change
    (re.compile(r"(?i)^\s*(?:fine|ok(?:ay)?|alright|right|cool|great|sure)\s*[.,!]\s*"), ""),
    (re.compile(r"(?i)\s+then\s*[.!]?\s*$"), ""),
    # "front of the table then", "other corner - front left": a place alone, where the task goes now
    (re.compile(r"(?i)^\s*(?:(?:the\s+)?other\s+corner\s*[-:,\u2013\u2014]+\s*)(?:the\s+)?((?:front|back)[\s-]+(?:left|right))(?:\s+corner)?"
                r"\s*(?:instead|please|now)?\s*[.!]?\s*$"), r"move it to the \1 corner"),
    (re.compile(r"(?i)^\s*(?:(?:to|at|on|in|into)\s+)?(?:the\s+)?((?:front|back|rear|left|right)(?:[\s-]+(?:left|right))?"
                r"(?:[\s-]+(?:hand\s+)?(?:side|corner|half|edge|part))?\s+of\s+the\s+table|(?:front|back|rear)[\s-]+(?:left|right)\s+corner)"
                r"\s*(?:instead|please|now)?\s*[.!]?\s*$"), r"move it to the \1"),
    # "put D on top": a new letter or digit cube said by its label alone
    (re.compile(r"\b(put|place|stack|add)\s+([A-Z]|\d)\s+(?=on\s+top\b|at\s+the\s+top\b|on\s+it\b)"), r"\1 a \2 "),
    # "pop a green one on top": the verbs of a casual writer for putting a cube
    (re.compile(r"(?i)\b(?:pop|plonk|plop|stick|chuck|slap|whack)\s+(?=(?:a|an|another|one|the|\d+)\s)"), "put "),
    (re.compile(rf"(?i)\b(?:that|this)\s+(?=(?:{COLOR_RE})\s+(?:one|block|cube)\b)"), "the "),  # "make that blue one white"
    # "make the top row green not red": a colour corrected, not a negation
    (re.compile(rf"(?i)\b({COLOR_RE})\s*,?\s+(?:and\s+)?not\s+({COLOR_RE})\b(?!\s+(?:block|cube|one|patch)s?\b)"), r"\1 instead of \2"),
    # "make each row three cubes wide" (of a wall): its width, not a new line
    (re.compile(r"(?i)\b(?:make\s+)?(?:each|every|every\s+single)\s+(?:row|layer|level)\s+(?=(?:\d+|one|two|three|four|five|six)\s+"
                r"(?:cubes?\s+|blocks?\s+)?(?:wide|long)\b)"), "make it "),
    # "the top row should be red" (of a wall or a pyramid): a layer, not a new line
    (re.compile(r"(?i)\b(top|bottom|middle|lowest|highest|upper|lower|first|second|third)\s+(?:row|level|tier|course)\b"), r"\1 layer"),
    # "other way round": the two ends (or the two related cubes) exchanged, not a circle
    (re.compile(r"(?i)\b(?:the\s+)?other\s+way\s+a?round\b|\bthe\s+opposite\s+way\s+a?round\b"), "reverse the order"),
    # "brown -> grey", "brown to grey": one colour for another
    (re.compile(rf"(?i)^\s*({COLOR_RE})\s*(?:->|\u2192|=>|to|into)\s*({COLOR_RE})\s*(?:instead|please)?\s*[.!]?\s*$"),
     r"make the \1 one \2"),
    # "just one is enough", "3 blocks will do": a count alone
    (re.compile(rf"(?i)^\s*(?:(?:just|only)\s+)?(\d+|{COUNT_WORD_RE})(?:\s+(?:blocks?|cubes?))?\s+"
                r"(?:is|are|will|would|should)\s+(?:be\s+)?(?:do|enough|fine|plenty|ok(?:ay)?|sufficient)"
                r"(?:\s+(?:tbh|really|honestly|imo|i\s+think))*\s*[.!]?\s*$"), r"\1"),
    # "put a red one at the bottom instead of a blue one": the cube at that end, recoloured
    (re.compile(rf"(?i)\b(?:put|place|use|have)\s+an?\s+({COLOR_RE})\s+(?:one|block|cube)\s+(?:at\s+the\s+(top|bottom)|on\s+(top))\s+"
                rf"(?:instead\s+of|rather\s+than|in\s+place\s+of)\s+(?:an?|the)\s+(?:{COLOR_RE})\s+(?:one|block|cube)\b"),
     lambda m: f"make the {m.group(2) or m.group(3)} one {m.group(1)}"),
    # "make it taller, 4 blocks": the count it grows (or shrinks) to
    (re.compile(r"(?i)\b(taller|higher|longer|shorter|smaller|bigger|lower)\s*[,:;-]?\s+"
                r"(?=(?:\d+|two|three|four|five|six|seven|eight)\s+(?:blocks|cubes)\b)"), r"\1 to "),
    # "taller. six": the count it grows (or shrinks) to, said alone after the word
    (re.compile(rf"(?i)^\s*(?:make\s+it\s+)?(taller|higher|longer|shorter|smaller|bigger|lower)\s*[.,:;!-]+\s*(\d+|{COUNT_WORD_RE})"
                r"\s*[.!]?\s*$"), r"make it \1 to \2 blocks"),
    # "no wait, back right": a corner alone, where the task goes now
    (re.compile(r"(?i)^\s*(?:the\s+)?((?:front|back|rear)[\s-]+(?:left|right))\s*(?:instead|please|pls|now)?\s*[.!]?\s*$"),
     r"move it to the \1 corner"),
    # "all yellow now pls": every cube recoloured
    (re.compile(rf"(?i)^\s*(?:make\s+(?:it|them)\s+)?all\s+({COLOR_RE})(?:\s+(?:now|instead))?(?:\s+(?:please|pls|plz))?\s*[.!]?\s*$"),
     r"make them all \1"),
    # "one more": one more cube of the task's kind
    (re.compile(r"(?i)^\s*(?:and\s+)?(?:just\s+)?(?:one|1)\s+more(?:\s+(?:please|pls|plz))?\s*[.!]?\s*$"), "add one more"),
    # "Fresh task please, a line of ...": a new task
    (re.compile(r"(?i)^\s*(?:a\s+)?(?:fresh|new|different|brand\s+new)\s+task(?:\s+(?:please|pls))?\s*[:,.!\-\u2013\u2014]+\s*"),
     "start over: "),
    # "same thing without the yellow cube": that cube removed
    (re.compile(r"(?i)^\s*(?:the\s+)?same\s+(?:thing|task|again|as\s+before|set-?up|arrangement|layout)\s*,?\s+(?:but\s+)?without\s+(?=the\s)"), "remove "),
    # "take one of the black ones off so it's a bit shorter": the purpose said after the change
    (re.compile(r"(?i)\s*,?\s+so\s+(?:that\s+)?it(?:'s|\s+is)\s+(?:a\s+(?:bit|little)\s+|slightly\s+)?(?:shorter|smaller|taller|lower|"
                r"higher|bigger|longer)\b\s*(?=[.!?]?\s*$)"), ""),
    # "can the middle one be red instead of white?": a change asked as a question
    (re.compile(r"(?i)\b(?:can|could)\s+(the\s+[^?]+?)\s+be\s+((?:an?\s+)?[a-z]+(?:\s+(?:instead(?:\s+of\s+[a-z]+)?|too))?)\s*\?\s*$"),
     r"make \1 \2"),
    # "rearrange it to spell RATS": the word changed
    (re.compile(r"(?i)\b(?:re)?(?:arrange|order|shuffle)\s+(it|them|the\s+(?:letters|cubes|blocks|line|row))\s+(?:to|so\s+(?:it|they)|into)\s+"
                r"(?:spell|say|read)s?\b"), r"make \1 spell"),
    # "3 more yellows on top": that many more cubes of a colour
    (re.compile(rf"(?i)^\s*(?:and\s+|plus\s+)?(\d+|{COUNT_WORD_RE})\s+more\s+({COLOR_RE})s?(?:\s+(?:ones|blocks|cubes))?\s+(?=on\s+top|at\s+the\s+)"),
     lambda m: f"add {NUMBER_WORDS.get(m.group(1), m.group(1))} more {m.group(2)} blocks "),
    # "take out the yellow one", "leave out the red cube": that cube removed
    (re.compile(r"(?i)\b(?:take|pull|leave)\s+out\s+(?=the\s)"), "remove "),
    # "throw in a yellow on top", "toss a black one on the patch too": a cube added (throwing "the red cube" stays refused)
    (re.compile(r"(?i)\b(?:throw|toss|chuck|pop|stick)\s+(?:in\s+)?(?=(?:a|an|another|one)\s)"), "put "),
    # "green and blue are backwards, swap them", "you've got the orange and the pink backwards": those two swapped
    (re.compile(rf"(?i)^.*?\b(?:the\s+)?({COLOR_RE}|top|bottom|middle|first|last)(?:\s+(?:one|block|cube))?\s+and\s+(?:the\s+)?"
                rf"({COLOR_RE}|top|bottom|middle|first|last)(?:\s+(?:ones?|blocks?|cubes?|colou?rs?))?\s+"
                r"(?:are\s+|got\s+)?(?:backwards?|swapped|switched|reversed|flipped|mixed\s+up|the\s+wrong\s+way\s+(?:round|around)"
                r"|in\s+the\s+wrong\s+order)\b.*$"), r"swap the \1 and the \2"),
    # "needs one more block", "it needs another cube": one more cube of the task's kind
    (re.compile(r"(?i)^\s*(?:it\s+|this\s+|the\s+\w+\s+)?needs?\s+(?:one\s+more|another|1\s+more|an\s+extra)\s+(?:block|cube)\s*[.!]?\s*$"),
     "add one more"),
    # "mirror it": its order reversed
    (re.compile(r"(?i)^\s*mirror\s+(?:it|that|this|them|the\s+(?:row|line|order|whole\s+thing|tower|stack))\s*[.!]?\s*$"),
     "reverse the order"),
    # "make it taller by two": that many blocks more
    (re.compile(rf"(?i)\b(taller|higher|longer|bigger|shorter|lower|smaller)\s+by\s+(\d+|{COUNT_WORD_RE})(?:\s+(?:blocks?|cubes?))?\b"),
     lambda m: f"{NUMBER_WORDS.get(m.group(2), m.group(2))} blocks {m.group(1)}"),
    # "two fewer", "one fewer red": that many cubes (of that colour) taken away
    (re.compile(rf"(?i)^\s*(\d+|{COUNT_WORD_RE})\s+(?:fewer|less)\s+({COLOR_RE})(?:\s+(?:ones?|blocks?|cubes?))?\s*[.!]?\s*$"),
     lambda m: f"remove {NUMBER_WORDS.get(m.group(1), m.group(1))} {m.group(2)} blocks"),
    (re.compile(rf"(?i)^\s*(\d+|{COUNT_WORD_RE})\s+(?:fewer|less)\s*(?:blocks?|cubes?)?\s*[.!]?\s*$"),
     lambda m: f"{NUMBER_WORDS.get(m.group(1), m.group(1))} fewer blocks"),
    # "make it twice as long": its count doubled
    (re.compile(r"(?i)\b(?:make\s+(?:it|them)\s+)?twice\s+as\s+(?:long|tall|high|many)\b"), "double it"),  # "twice as big" stays a size
    # "too tall, cut it to three": that many blocks
    (re.compile(rf"(?i)^\s*(?:(?:it'?s\s+|that'?s\s+)?too\s+(?:tall|long|high|big)\s*[,.;!-]*\s*)?(?:cut|trim|shorten|chop)\s+(?:it|that|this|the\s+\w+)"
                rf"(?:\s+down)?\s+to\s+(\d+|{COUNT_WORD_RE})(?:\s+(?:blocks?|cubes?))?\s*[.!]?\s*$"),
     lambda m: f"make it {NUMBER_WORDS.get(m.group(1), m.group(1))} blocks"),
    # "fine, a white cube on top": a cube added, said without a verb
    (re.compile(rf"(?i)^\s*(?=(?:an?|another|one)\s+(?:(?:{COLOR_RE})\s+)?(?:cube|block|one)\s+(?:on\s+top|at\s+the\s+(?:top|bottom|end|start)"
                r"|on\s+the\s+(?:left|right)(?:\s+end)?|at\s+the\s+(?:left|right)\s+end)\b)"), "add "),
    # "now in the middle of the table": where the task goes now
    (re.compile(r"(?i)^\s*(?:(?:now|and|then)\s+)*(?:in|to|at|into)\s+the\s+(?:middle|center|centre)(?:\s+of\s+the\s+(?:table|workspace))?"
                r"\s*(?:instead|please|now)?\s*[.!]?\s*$"), "move it to the center of the table"),
    # "the ends are fine but the middle one should be white": what stays is said, then the change
    (re.compile(r"(?i)^.{1,40}?\b(?:is|are)\s+(?:fine|ok(?:ay)?|good|right|correct)\s*,?\s*(?:but|just|only)\s+"), ""),
    # "put that line on the right side of the table": the task's structure
    (re.compile(r"(?i)\b(put|move|shift|slide|place)\s+(?:that|this)\s+(?:line|row|tower|stack|circle|ring|pyramid|wall"
                r"|grid|structure)\b"), r"\1 it"),
)
"""Edits said in fewer words, as the steering reads them: "on top of that" is on top of the task,
"and a red block on top" adds one."""

EDIT_KEEP_THEN_ADD_RE = re.compile(r"(?i)^.*?\bkeep(?:ing)?\s+(?:the|this|that)\s+\w+\s*,?\s*(?:and|but|plus)\s+(?:also\s+)?"
                              r"(?=(?:add|put|place|stack|set)\b)")
"""An edit that keeps the structure and adds a clause ("keep the tower, and also put ..."): the
clause after it."""

EDIT_COUNT_ALONE_RE = re.compile(
    r"(?i)\s*(?:(?:actually|ok(?:ay)?|fine|right|hmm+|so|too\s+(?:many|few)|undo\s+that|nah)\s*[,.!]?\s*)*(?:let'?s\s+)?"
    r"(?:go\s+with|try|use|make\s+(?:it|that)|how\s+about|maybe|only|just)?\s*"
    rf"(\d+|{COUNT_WORD_RE})"
    rf"(?:\s+(?P<color>{COLOR_RE}))?(?:\s+(?:blocks|cubes|bricks|high|tall))?(?:\s+in\s+the\s+(?:row|line|tower|stack|pile|wall|column))?"
    rf"(?:\s+instead(?:\s+of\s+(?P<was>\d+|{COUNT_WORD_RE}))?|\s*,?\s+(?:not|rather\s+than)\s+(?P<was2>\d+|{COUNT_WORD_RE}))?"
    r"(?:\s+(?:please|pls|plz))?\s*[.!]?\s*")
"""An edit that is a count alone ("three", "let's go with 7 instead", "actually, three", "make that
seven pink cubes pls", "only two", "just two high"): the structure's count (a colour said with it must be the
structure's own)."""

EDIT_MORE_ALONE_RE = re.compile(
    rf"(?i)\s*(?:and\s+)?(\d+|{'|'.join(w for w in NUMBER_WORDS if w not in ('single', 'pair', 'couple', 'both', 'one'))})"
    r"\s+more(?:\s+(?:blocks|cubes|bricks))?(?:\s+(?:please|pls|plz))?\s*[.!]?\s*")
"""An edit that is a count of cubes to add alone ("three more"): that many more of the structure's cubes."""

SAME_CUBES_RE = re.compile(rf"\b(?:the\s+)?(?:same|these|those|the)\s+(?:(?:\d+|{COUNT_WORD_RE})\s+)?(?:blocks|cubes|bricks)\b"
                           r"|\b(?:them|all\s+of\s+them)\b", re.IGNORECASE)
"""Words of a whole-task edit that keep the task's cubes ("same blocks, but make two towers of four")."""

SAME_PATCH_RE = re.compile(r"(?i)\b(?:(?:the|that|this)\s+)?same\s+(?:goal\s+)?(?:patch|pad|mat|area|spot)\b|\b(?:that|this)\s+(?:goal\s+)?patch\b")
"""An edit's "the same patch": the task's one patch."""

VARIANT_LABEL_RE = re.compile(r"(?i)^\s*(?:v|version|level|lvl|variant|step|stage|round)\s*#?(?P<n>\d+)(?:\s+of\s+this)?"
                              rf"(?:\s+(?!(?:{COLOR_RE}|grey|\d+)\b)(?:rule|rules|change|changes|update|tweak|variant|version|edit|idea"
                              r"|task|setup|spec|plan|twist)){0,2}\s*(?::|->|\u2192|=>|-|\u2014|\))\s*")  # ("Round 2 rule change:")
"""A curriculum's label of the variant an edit makes ("v2: add a green cube", "level 3 -> descending now"): when its
number names no version the family has yet, it names the one being made, not one to build on
(:func:`rpg.steer.steering.steer` drops it)."""

ADDED_CUBE_RE = re.compile(r"(?i)\bthe\s+(?:new\s+)?(?:cube|block|one)\s+(?:that\s+|which\s+)?(?:you|we|i)\s+(?:just\s+)?added"
                           r"(?:\s+(?:last|just\s+now|in\s+the\s+last\s+(?:step|edit|version)))?(?P<before>\s+before\s+that)?\b")
"""An edit's "the cube you added": the one cube the current version has that the version it was made from lacks
(:func:`rpg.steer.steering.steer`); "the cube you added before that" is refused."""

EDIT_INEXPRESSIBLE: tuple[tuple[str, str, str], ...] = (
    ("reference", r"\b(?:one|block|cube|colou?r)s?\s+(?:that\s+|which\s+)?(?:we|you|i)\s+(?:used|had|moved|placed|picked|took)"
                  r"\s+(?:before|earlier|previously|last\s+time|yesterday)\b",
     "refers to a cube of an earlier turn or session, which the edit cannot find by what happened to it; name "
     "the version it was in (\"go back to version 1\") or say the cube's colour"),
    ("action", r"\b(?:\d+|ninety|forty[- ]five)\s*(?:degrees?|deg|°)|\bdegrees?\b|\b(?:spin|spins|spinning|twirl\w*|wobble\w*"
               r"|wiggle\w*|shake|shaking|juggle\w*|throw\w*|toss\w*|roll(?:s|ing)?|bounce\w*|knock\w*(?:\s+(?:it|them))?\s+over)\b",
     "is an action the domain does not have: a task's goal says where cubes end up and which face is up, "
     "not a motion or an angle"),
    ("size", r"\b(?:twice|thrice|\d+\s+times|half)\s+(?:as\s+)?(?:big|large|small|tall|wide|long|heavy)\b"
             r"|\b(?:bigger|larger|smaller|tinier|heavier|lighter)\s+(?:blocks?|cubes?|ones?)\b"
             r"|\b(?:blocks?|cubes?|ones?|each\s+(?:block|cube))\s+(?:\w+\s+){0,2}?(?:bigger|larger|smaller|tinier|heavier)\b"
             r"|\b\d+\s*x\s+(?:bigger|larger|smaller|wider|heavier)\b",
     "asks for a size: every cube is the same size (5 cm), so no cube is bigger or smaller than another"),
    ("quantity", r"\b(?:closer|further|farther|nearer)\b|\b(?:gaps?|spacing|space\s+between|distance)\b|\bspread\s+(?:them|it|out)\b",
     "asks for a distance: rpg's relations are qualitative (next to, far from) with no distance or quantity to change"),
    ("contradiction", r"\b(?:taller|higher|bigger|longer|larger)\b[^.;]*\band\b[^.;]*\b(?:shorter|lower|smaller)\b"
                      r"|\b(?:shorter|lower|smaller)\b[^.;]*\band\b[^.;]*\b(?:taller|higher|bigger|longer|larger)\b"
                      r"|\b(?:to|on)\s+the\s+left\b(?!\s+(?:side|corner|end|edge|half|of\s+the\s+table))[^.;]*\band\b[^.;]*\b(?:to|on)\s+the\s+right\b"
                      r"(?!\s+(?:side|corner|end|edge|half|of\s+the\s+table))"
                      r"|\b(?:to|on)\s+the\s+right\b(?!\s+(?:side|corner|end|edge|half|of\s+the\s+table))[^.;]*\band\b[^.;]*\b(?:to|on)\s+the\s+left\b"
                      r"(?!\s+(?:side|corner|end|edge|half|of\s+the\s+table))"
                      r"|\bin\s+front\b[^.;]*\band\b[^.;]*\bbehind\b|\bbehind\b[^.;]*\band\b[^.;]*\bin\s+front\b"
                      r"|\bon\s+top\s+of\s+(?:it|them)\b[^.;]*\band\b[^.;]*\b(?:under|underneath|beneath|below)\s+(?:it|them)\b"
                      r"|\b(?:make|paint|colou?r|turn)\s+(?:it|the\s+\w+\s+(?:block|cube|one))\s+(?:both\s+)?(?:" + "|".join(COLORS) + r")"
                      r"\s+and\s+(?:" + "|".join(COLORS) + r")\b(?![^.;]*\balternat)",
     "contradicts itself: the two cannot both hold at the end of the episode; say one"),
    ("shape", r"\b(?:stars?|hearts?|crosses|cross\s+shape|spirals?|zig-?zags?|diamonds?|hexagons?|pentagons?|octagons?|ovals?|ellipses?"
              r"|arch(?:es)?|staircases?|stairs|steps\s+shape|smiley|[ltuvxyz][- ]shaped?|shaped?\s+like(?:\s+an?)?\s+\w+)\b",
     "is a shape the domain does not have: its structures are towers, lines, circles, grids, pyramids, walls and piles "
     "of cubes"),
)
"""Meaning a steering edit may ask for that the domain cannot express, beyond the parser's
:data:`INEXPRESSIBLE` (whose classes steering checks too, except ``reference``: "again", "undo",
"the original" name versions of a family): (class, pattern, why)."""

EDIT_COUNT_RE = re.compile(
    r"\b(?:(?:just|only|like|about|use|using|have|make (?:it|them|the (?:" + "|".join(w for k in STRUCTURE_KINDS.values() for w in k.words)
    + r"|wall)))\s+(?:only\s+|just\s+)?(?P<n>\d+)"
    r"|(?:to|into|with|be|of)\s+(?:only\s+|just\s+)?(?P<n1>\d+)(?=\s+(?:[a-z]+\s+)?(?:blocks?|cubes?)\b|\s+(?:tall|high|long|wide|deep)\b))"
    r"(?:\s+(?!(?:more|fewer|less|extra|additional|other)\b)(?:[a-z]+\s+)?(?:blocks?|cubes?))?"
    r"(?:\s+(?P<dim>tall|high|long|wide|deep|levels?|layers?|stor(?:y|ey|ies|eys)))?"
    r"(?=\s*(?:$|[.,;!?]|(?:please|pls|instead|now|then|and|in total|total|again)\b))"
    r"|\b(?P<n2>\d+)\s+(?P<dim2>tall|high|long|wide|deep)\b")
"""A count an edit gives its structure ("just two", "like 3 blocks", "make it four tall", "four
wide"); ``dim`` (tall, wide...) says which side."""

EDIT_VAGUE_RE = re.compile(
    r"\b(?:a\s+(?:little|bit|tad|lot)|a\s+little\s+bit|slightly|much|way|somewhat|lots|far|even|a\s+few\s+more)\s+"
    r"(?:more\s+)?(?:taller|shorter|bigger|smaller|higher|lower|longer|wider|narrower|closer|further|farther|larger|more|less)\b")
"""A comparative with a vague degree ("a bit taller", "much longer", "slightly closer"): with no
count said in the edit, it names no exact change (refused as a quantity)."""

EDIT_SHOULD_BE_RE = r"(?:should|must|shall|will|would|can|could|has to|have to|needs? to)?\s*(?:be|become|turn|go)"
"""How an edit says what a cube should be ("the top block should be red", "both should be white")."""


def rewrite(rules: tuple[tuple[re.Pattern, object], ...], text: str) -> str:
    """``text`` with each of ``rules`` (pattern, replacement string or function) applied in order."""
    for pattern, written in rules:
        text = pattern.sub(written, text)
    return text


# Surface rewrites of :func:`rpg.schema.reading.normalize_words`, in the order it applies them: each
# table turns one family of surface forms into the words the readers read.

BARE_OBJECT_BEFORE = "|".join(rf"(?<=\b{w}\s)" for w in ARTICLE_DROPPED_AFTER)
"""Lookbehinds for the words after which a terse writer leaves out a cube's article (\"put cyan cube ...\")."""

OUTCOME_VERB_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "cover the green patch with the red block": the red block on it
    (re.compile(rf"\bcover\s+(the\s+(?:{COLOR_RE})\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|tile|block|cube))\s+with\s+"
                rf"(the\s+(?:{COLOR_RE})\s+(?:block|cube))\b"),
     r"put \2 on \1"),
    # "slide the red block until it touches the blue block": next to it; "until it reaches the patch": on it
    (re.compile(rf"\buntil\s+(?:it|they)\s+(?:reach(?:es)?|is\s+on|are\s+on)\s+(?=the\s+(?:(?:{COLOR_RE})\s+)?(?:goal\s+)?patch\b)"),
     "onto "),
    # (only right after the moved cube: "to the left of the white cube until it touches the red cube" had put the
    # white cube next to the red one)
    (re.compile(rf"\b(?:until\s+(?:it|they)\s+(?:touch(?:es)?|hits?|bumps?\s+into|reach(?:es)?)|against)\s+"
                rf"(?=the\s+(?:{COLOR_RE})\s+(?:block|cube|one)\b)"),
     lambda m: m.group(0) if re.search(r"\b(?:left|right|front|behind|next|beside|near|on|onto|between|patch|corner|far|under|above)\b",
                                       re.split(r"[.;!?,]", m.string[:m.start()])[-1]) else "next to "),
)
"""A motion said by its outcome ("cover the green patch with the red block", "slide it until it touches ..."): the relation it ends in."""

_REQUIRER = r"(?:^|(?<=[.!?;:]\s))(?:success|completion|(?:the\s+)?(?:\w+\s+)?(?:task|goal|test|episode)(?:\s+[a-z]*\d[\w-]*)?)\s+(?:requires|needs|demands)\s+"
_GERUND_STEMS: dict[str, str] = {"stack": "stack", "plac": "place", "putt": "put", "lin": "line", "arrang": "arrange",
                                  "build": "build", "mak": "make", "mov": "move", "pil": "pile"}
"""A placing verb's stem before "-ing" -> the verb ("placing" -> "place"); its keys are the alternatives of
:data:`_GERUND_RE`."""
_GERUND_RE = "(" + "|".join(_GERUND_STEMS) + r")ing\b"


GOAL_FRAME_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the robot needs to end with the blue cube resting on the white patch": the end state said (its "end with the blue"
    # had been read as a sequence's end)
    (re.compile(rf"\b(?:the\s+(?:robot|agent|policy|arm)|you|it|we)\s+(?:needs?|has|have|must|should)\s+to\s+end\s+(?:up\s+)?with\s+"
                rf"(?=(?:the|a|an)\s+(?:{COLOR_RE})\s+(?:cube|block)\s+(?:resting|sitting|standing|lying|placed|stacked|on|in|at)\b)"), ""),
    # "Given the blue, cyan and white cubes, put them all in one stack": the cubes the task uses, said as "using" ("given"
    # had been refused as an action)
    (re.compile(rf"(?:^|(?<=[.;!?]\s))given\s+(?=(?:the|these|those)\s+(?:(?:{COLOR_RE}|and|or)[\s,]+)+(?:cubes|blocks)\s*,\s*[a-z]+\s+them\b)"),
     "using "),
    # "Success requires the pink cube to be placed on the table", "Task T3 requires arranging ...", "success requires that
    # ...": what success requires is the goal (its words had been unknown: refused)
    (re.compile(_REQUIRER + r"(?=\w+ing\b)"), "the task is "),
    (re.compile(_REQUIRER + r"(?:that\s+)?(?=[^.;!?]*?\s+(?:to\s+be|be|is|are)\s)(?P<np>[^.;!?]*?)\s+(?:to\s+be|be)\s+"),
     r"\g<np> must be "),
    (re.compile(_REQUIRER + r"that\s+"), ""),
    # "a wall of 6 cubes, 3 across and 2 high", "four along and two high": its width ('across' and 'along' had been unknown)
    (re.compile(rf"\b(\d+|{'|'.join(NUMBER_WORDS)})\s+(?:blocks?\s+|cubes?\s+)?(?:across|along)\s+"
                rf"(?=(?:and|by|x)\s+(?:\d+|{'|'.join(NUMBER_WORDS)})\s+(?:blocks?\s+|cubes?\s+)?(?:high|tall)\b)"), r"\1 wide "),
    # "..., with nothing in between" after a tower's two ends: the two cubes are the tower (its negation had been refused)
    (re.compile(r"\s*,?\s*(?:and\s+|with\s+)?nothing\s+(?:else\s+)?(?:in\s+)?between(?:\s+(?:them|the\s+two))?(?=\s*[.!]?\s*$)"),
     lambda m: "" if re.search(r"\b(?:tower|stack)\b", m.string) and re.search(r"\b(?:bottom|base)\b", m.string)
     and re.search(r"\btop\b", m.string) and not re.search(rf"\b(?:\d+|{'|'.join(NUMBER_WORDS)})\b", m.string) else m.group(0)),
    # "place a cube in the front left corner and another one in the back right corner": another cube (one cube had been
    # put in both corners: refused as a contradiction)
    (re.compile(rf"\b((?:a|an|one)\s+(?:(?P<c>{COLOR_RE})\s+)?(?P<n>cube|block)\b[^.;!?]*?\banother)\s+one\b"),
     lambda m: f"{m.group(1)} {m.group('c') + ' ' if m.group('c') else ''}{m.group('n')}"),
    # "a tower of green on red, and next to the tower a single yellow block": the cube said after the place it goes
    (re.compile(rf"\b(next\s+to|beside|(?:to\s+the\s+)?(?:left|right)\s+of|in\s+front\s+of|behind)\s+(the\s+(?:tower|stack|row|line|pile))\s*,?\s+"
                rf"(?:put\s+|place\s+|goes\s+|sits\s+|stands\s+|there\s+is\s+)?(?:a|one|a\s+single|1)\s+(?:single\s+)?({COLOR_RE})\s+(block|cube)(?=\s*[.!;]?\s*$)"),
     r"a \3 \4 \1 \2"),
    # "right now", "right away": a time, not the right side of the table ("... on the blue cube right now" had put red on
    # the right of blue)
    (re.compile(r"\bright\s+(?:(now)|away)\b"), lambda m: m.group(1) or ""),
    # "The policy is evaluated on placing the blue cube between ...": the act it is judged on is the task
    (re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:agent|robot|policy|arm|learner|controller)\s+is\s+(?:evaluated|tested|scored|judged"
                r"|assessed|graded|rewarded)\s+(?:on|for)\s+(?:(?:its\s+ability\s+to|how\s+well\s+it\s+can)\s+(?=[a-z]+\s)|" + _GERUND_RE + ")"),
     lambda m: _GERUND_STEMS[m.group(1)] if m.group(1) else ""),
    # "Would you mind putting the pink cube behind the cyan one?": a polite request of the act ('mind' had been refused as
    # an action the domain lacks)
    (re.compile(r"\b(?:would|do)\s+you\s+mind\s+(?:please\s+)?" + _GERUND_RE), lambda m: _GERUND_STEMS[m.group(1)]),
    # "Build upward from red block through green block to blue block": a tower from the first cube up (refused before)
    (re.compile(rf"\b(build|stack)\s+(?:it\s+)?(?:upward|upwards|up)\s+from\s+(?:the\s+)?((?:{COLOR_RE})(?:\s+(?:block|cube))?"
                rf"(?:\s*,?\s+(?:to|through|then|and\s+then)\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:block|cube))?)+)\b"),
     lambda m: "build a tower from bottom to top: " + ", ".join(re.findall(rf"\b(?:{COLOR_RE})\b", m.group(2)))),
    # "blue block supported by green block, which is supported by red block": each on the one after it
    (re.compile(r"\b(?:is\s+|are\s+)?(?:supported|held\s+up|carried)\s+by\b"), "on top of"),
    # "from left to right in the specified sequence", "in a linear fashion": in that order, in a row
    (re.compile(r"\bin\s+the\s+(?:specified|given|listed|stated|said|mentioned)\s+(?:sequence|order)\b"), "in that order"),
    (re.compile(r"\bin\s+a\s+(?:linear|straight)\s+(?:fashion|manner|arrangement|formation)\b"), "in a row"),
    # "arranging ... in a row, then stacking them": a later step said as a gerund is a step (it had been dropped)
    (re.compile(r"\b(then|and\s+then|after\s+that|afterwards)\s+" + _GERUND_RE),
     lambda m: f"{m.group(1)} {_GERUND_STEMS[m.group(2)]}"),
    # "in front to the left of the blue cube": both relations to that cube (in front had been dropped)
    (re.compile(rf"\b(in\s+front|behind)\s+(?:and\s+)?(to\s+the\s+(?:left|right)\s+of)\s+(the\s+(?:{COLOR_RE})(?:\s+(?:cube|block))?)"),
     lambda m: f"{m.group(1)}{'' if m.group(1) == 'behind' else ' of'} {m.group(3)} and {m.group(2)} {m.group(3)}"),
    # "so that reading from the top down it says CUP": it spells the word
    (re.compile(r"(\bread(?:ing|s)?\b[^.;!?]{0,40}?\b(?:it|they))\s+says?\b"), r"\1 spells"),
    # "... behind the green patch in the final state": when the goal holds (every goal is checked at the episode's end)
    (re.compile(r"\s*,?\s+(?:in|at)\s+the\s+(?:final|end|goal|target)\s+(?:state|scene|configuration)(?=\s*[.!;]?\s*$)"), ""),
    (re.compile(r"^\s*(?:in|at)\s+the\s+(?:final|end|goal|target)\s+(?:state|scene|configuration)\s*,\s*"), ""),
    # "the task is done when the pink cube is on the red patch": the end state that completes it is the goal
    (re.compile(r"(?:^|(?<=[.!?;:]\s))(?:the\s+)?(?:task|job|episode|run|it|you)\s*(?:is|are|'s|'re)\s+(?:done|finished|complete|completed"
                r"|over|successful|solved|a\s+success)\s+(?:when|once|as\s+soon\s+as|if)\s+"), ""),
    # "make a 3-block tower using pink blocks": what it is made of
    (re.compile(rf"\b(towers?|stacks?|rows?|lines?|pyramids?|walls?|piles?)\s+(?:using|with|out\s+of|from)\s+(?=(?:the\s+)?(?:\d+\s+)?"
                rf"(?:{COLOR_RE})\s+(?:blocks|cubes)\s*(?:[.,;!]|$))"), r"\1 of "),
    # "I reckon the task is a tower: ...", "What you want is a pyramid: ...", "The task you are describing is ...",
    # "For your case the goal would be ...": the task said with an opinion or a reply around it
    (re.compile(r"(?:^|(?<=[.!?;]\s))(?:i\s+(?:think|reckon|guess|believe|suppose|figure)|(?:for|in)\s+(?:your|this)\s+case\s*,?)\s+"
                r"(?=(?:the|your|our)\s+(?:task|goal|target|objective)\b)"), ""),
    (re.compile(r"(?:^|(?<=[.!?;]\s))what\s+(?:you|we|i)\s+(?:want|need|are\s+after|are\s+looking\s+for)\s+is\s+(?=an?\s)"), "the task is "),
    (re.compile(r"\b(the\s+(?:task|goal))\s+(?:you\s+are|you're)\s+(?:describing|asking\s+(?:for|about)|after|looking\s+for)\s+(?=is\b)"),
     r"\1 "),
    (re.compile(r"^\s*(?:about|regarding|re|concerning)\s+(?=the\s+(?:tower|stack|row|line|pyramid|wall|grid|circle)\s*:)"),
     ""),
    # "three cubes of arbitrary colour"
    (re.compile(r"\barbitrary\s+(?=(?:colou?rs?|order)\b)"),
     "any "),
    # "listed top to bottom:"
    (re.compile(r"\b(?:listed|given|written|read)\s+(?=(?:from\s+)?(?:the\s+)?(?:top|bottom)\s+(?:to|up|down)\b)"),
     ""),
    # "In the final row the leftmost cube should be black, ...": the row the goal describes
    (re.compile(r"^\s*(?:in|for)\s+the\s+(?:final|resulting|finished|end|goal|target)\s+(row|line|tower|stack)\s*[,:]?\s*"),
     r"make a \1: "),
    # "put the whole stack on the red patch": the stack
    (re.compile(r"\b(the|that|this)\s+(?:whole|entire|complete|resulting|finished|completed|final)\s+(?=(?:stack|tower|row|line|circle|pyramid|wall|grid|structure)\b)"),
     r"\1 "),
)
"""Words that frame the goal's structure ("about the tower:", "in the final row", "the whole stack", "arbitrary colour"): the structure itself."""

PLACEMENT_WISH_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the yellow one goes in the middle of the two red ones": between them
    (re.compile(rf"\bin\s+(?:the\s+)?(?:middle|center|centre)\s+of\s+(?:the\s+)?(?=(?:two|2|both)\s+(?:(?:{COLOR_RE})\s+)?(?:ones|cubes|blocks)\b"
                rf"|(?:the\s+)?(?:{COLOR_RE})\s+(?:one|cube|block)\s+and\s+the\s+(?:{COLOR_RE})\s+(?:one|cube|block)\b)"),
     "between the "),
    # "kindly keep the white cube in front of the black cube" (Indian English): put it there
    (re.compile(rf"\bkeep\s+(?=(?:(?:the|a|an)\s+)?(?:(?:{COLOR_RE})\s+)?(?:one|cube|block)\s+(?:on|onto|on\s+top\s+of|in|at|next\s+to|beside|"
                r"behind|in\s+front\s+of|under|between|to\s+the\s+(?:left|right)\s+of)\b)"),
     "put "),
    # "i want the red one on the blue one and then ...": a placement said as a wish
    (re.compile(rf"\b(?:i|we)\s+(?:want|need|would\s+like|'d\s+like)\s+(?=(?:the|a|an)\s+(?:(?:{COLOR_RE})\s+)?(?:one|cube|block)?\s*"
                r"(?:on|onto|on\s+top\s+of|next\s+to|beside|behind|in\s+front\s+of|under|between|to\s+the\s+(?:left|right)\s+of)\b)"),
     "put "),
)
"""A placement said as a wish or a keeping ("i want the red one on ...", "keep the white cube in front of ...") or a middle said by its neighbours: the placement."""

ROBOT_SUBJECT_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the robot stacks the red block on ...": the command the sentence describes
    (re.compile(r"^(?:the\s+|a\s+)?(?:robot(?:ic)?(?:\s+arm)?|agent|arm)\s+(stack|put|place|move|push|arrange|build|set|line|pick|slide|lift|make)s\b"),
     r"\1"),
)
""""The robot stacks the red block on ...": the command the sentence describes."""

RESTATEMENT_RE = re.compile(r"\bi\.?e\.?(?=[\s,])|\bthat\s+is\b|\bin\s+other\s+words\b|\bnamely\b|\bmeaning\b|\bput\s+differently\b"
                            r"|\bto\s+(?:be\s+clear|rephrase|restate)\b")
"""Words that say the same goal again ("..., i.e. a red cube must end up on the blue patch"): an indefinite cube after
them is the one said before, not another (:func:`rpg.schema.reading.repeated_indefinites`)."""

START_WORD_RE = re.compile(r"\b(?:start(?:s|ing)?|initial(?:ly)?|beginning|begin|before|setup|set-up)\b")
"""Words of a label that mark the start state ("Let me describe the start: ...", "Before: ..."): such a label is kept
(dropping it had made the start the goal)."""

ENDS_IN_PARENTHESES_RE = re.compile(
    rf"(?i)\b(?P<first>{COLOR_RE})(?:\s+(?:cube|block))?\s*\((?:at\s+the\s+|on\s+the\s+)?(?P<end>bottom|base|top)\)(?:\s*[,/]\s*|\s+(?=(?:and|then)\s))"
    rf"(?P<mid>(?:(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:\s*\((?:in\s+the\s+)?middle\))?(?:\s*[,/]\s*(?:and\s+)?|\s+(?=and\s)))*)(?:and\s+|then\s+)?"
    rf"(?P<last>{COLOR_RE})(?:\s+(?:cube|block))?\s*"
    r"\((?:at\s+the\s+|on\s+)?(?:the\s+)?(?P<end2>top|bottom|base)\)(?!\s*(?:,|and|then|\+)\s*(?:the\s+)?(?:[a-z]+))")
"""A tower listed with its ends in parentheses ("a tower of red (bottom), blue, yellow (top)"): said as the list and its
direction, "red, blue, yellow (bottom to top)", which the tower and start readers read (it had been refused); two joined
by "and" ("brown (bottom) and yellow (top)") too."""


ONE_END_IN_PARENTHESES_RE = re.compile(
    rf"(?i)\b(?P<first>{COLOR_RE})(?:\s+(?:cube|block))?\s*(?:\((?:at\s+the\s+|on\s+)?(?:the\s+)?(?P<end>bottom|base|top)\))?\s*"
    rf"(?P<rest>(?:(?:\s*[,/]\s*(?:and\s+)?|\s+and\s+|\s+then\s+)(?:{COLOR_RE})(?:\s+(?:cube|block))?)+)"
    r"(?:\s*\((?:at\s+the\s+|on\s+)?(?:the\s+)?(?P<end2>bottom|base|top)\)(?!\s*(?:[,/]\s*(?:and\s+)?|\s+and\s+|\s+then\s+)"
    rf"(?:{COLOR_RE})\b))?")
"""A tower listed with one end in parentheses, on its first or its last item ("a tower of red (top), blue, yellow",
"red, blue, yellow (bottom)"): said as the list and its direction (the end had been dropped and the list read from the
bottom: reversed)."""


def one_end_in_parentheses(m: re.Match) -> str:
    """The list of :data:`ONE_END_IN_PARENTHESES_RE` with its direction; as it is when it says no end or both."""
    if bool(m.group("end")) == bool(m.group("end2")):
        return m.group(0)
    items = [m.group("first")] + re.findall(rf"(?i)\b(?:{COLOR_RE})\b", m.group("rest"))
    first_low = (m.group("end") or "") in ("bottom", "base") or (m.group("end2") or "") == "top"
    return f"{', '.join(items)} ({'bottom to top' if first_low else 'top to bottom'})"


def tower_ends_said(text: str) -> str:
    """``text`` with a tower's ends said in parentheses written as its list and direction (:data:`ENDS_IN_PARENTHESES_RE`
    for both ends, then :data:`ONE_END_IN_PARENTHESES_RE` for one); used on the goal and on a stated start alike."""
    text = ENDS_IN_PARENTHESES_RE.sub(ends_in_parentheses, text)
    if len(re.findall(r"(?i)\((?:at\s+the\s+|on\s+)?(?:the\s+)?(?:bottom|base|top)\)", text)) > 1:
        return text  # ends said that no list placed ("brown (bottom) and yellow (top) and red"): left for the refusal
    return ONE_END_IN_PARENTHESES_RE.sub(one_end_in_parentheses, text)


END_LEFT_IN_PARENTHESES_RE = re.compile(rf"(?i)\b(?:{COLOR_RE})(?:\s+(?:cube|block))?\s*\((?:at\s+the\s+|on\s+)?(?:the\s+)?"
                                        r"(?:bottom|base|top)\)")
"""An end in parentheses that :func:`tower_ends_said` could not place (on a middle cube, or one end twice): refused."""


def ends_in_parentheses(m: re.Match) -> str:
    """The list of :data:`ENDS_IN_PARENTHESES_RE` with its direction, or the words as they are when both ends are one."""
    low = {"bottom", "base"}
    if (m.group("end") in low) == (m.group("end2") in low):
        return m.group(0)
    mid = re.sub(r"\s*[,/]\s*(?:and\s+)?", ", ", re.sub(r"(?i)\s*\((?:in\s+the\s+)?middle\)", "", m.group("mid"))).strip(", ")
    listed = ", ".join(x for x in (m.group("first"), mid, m.group("last")) if x)
    return f"{listed} ({'bottom to top' if m.group('end') in low else 'top to bottom'})"


INDEFINITE_CUBE_RE = re.compile(rf"(?P<pre>^|[,;:.!]\s|\band\s|\bthen\s|\b(?:put|place|set|move|stack|leave|have)\s)"
                                rf"(?:a|an|one)\s+(?P<c>{COLOR_RE})\s+(?P<n>cube|block|brick|box)\b")
"""A cube introduced by its colour with "a" or "one" where a clause or its verb begins ("A grey cube on the blue
patch and a grey cube on the red patch"): each such mention is one more cube of that colour, as mention accounting
counts it (:func:`rpg.schema.reading.repeated_indefinites`; the second had been read as the first, put on two
patches). Not after a preposition ("... on a red cube" may be the one already said)."""

LABELS_BETWEEN_RE = re.compile(r"(?i)\bbetween\s+(?:the\s+)?(?P<kind>letter|digit|number)\s+(?:cubes|blocks)\s+(?P<a>[A-Z0-9])\s+and\s+"
                               r"(?P<b>[A-Z0-9])\b(?![\w'])")
""""between the letter cubes A and B": each a cube of its own ("between the letter A cube and the letter B cube"; the
labels had been dropped, two coloured cubes made up)."""

COUNTED_STRUCTURE_RE = re.compile(r"(?i)\b(\d+)\s+(cube|block)\s+(?=(?:tall\s+|high\s+)?(?:towers?|stacks?|rows?|lines?|pyramids?|walls?"
                                  r"|piles?|circles?|rings?|grids?)\b)")
""""the 3 cube tower": a three-cube tower, written "3-cube" before labels are read (a digit-3 cube had been made up)."""

NOTATION_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"(\d)\s*[x\u00d7]\s*(?=\d)"),
     r"\1x"),
    # "2 rows x 3 cubes": rows of that many cubes
    (re.compile(r"\b(\d+)\s+(rows|layers|levels|courses|tiers)\s*[x\u00d7]\s*(?=\d+\b)"),
     r"\1 \2 of "),
    # "3x white", "white x3", "red \u00d7 2": a count of cubes written as a multiplier (a grid's "3x3" stays)
    (re.compile(rf"\b(\d+)\s*[x\u00d7]\s*(?=(?:{COLOR_RE})\b)"),
     r"\1 "),
    (re.compile(rf"\b({COLOR_RE})((?:\s+(?:blocks?|cubes?))?)\s*[x\u00d7]\s*(\d+)\b"),
     r"\3 \1\2"),
    # "circle x5", "5x circle", "tower x 3": a structure's count written as a multiplier (it had been dropped: a
    # circle of six)
    (re.compile(r"\b(circle|ring|row|line|tower|stack|column|pile)\s*[,:]?\s*[x\u00d7]\s*(\d+)\b(?!\s*[x\u00d7]|\s+(?:high|tall|long|wide))"),
     r"\1 of \2"),
    (re.compile(r"(?<![\w.])(\d+)\s*[x\u00d7]\s+(circle|ring|row|line|tower|stack|column|pile)\b"),
     r"a \2 of \1"),
    # a terse spec's "@" for a place ("orange @ front right corner", "pile @ center: ...") and "b/w" for between
    # ("put the green block b/w the red and blue ones"; "b/w cubes" stays: black and white)
    (re.compile(rf"^\s*({COLOR_RE})\s*@\s*(?=(?:the\s+)?(?:front|back|rear|left|right|middle|cent(?:er|re))\b)"),
     r"put the \1 cube in the "),
    (re.compile(r"\b(pile|heap|tower|stack|row|line|circle|ring|grid|wall|pyramid)\s*@\s*(?=(?:the\s+)?(?:front|back|rear|left|right|middle"
                r"|cent(?:er|re))\b)"),
     r"\1 in the "),
    (re.compile(r"\bb/w\s+(?=the\b)"),
     "between "),
    # "3 white in a row": three cubes, not a count and a cube
    (re.compile(rf"\b(\d+)\s+({COLOR_RE})(?=\s+(?:in|into)\s+(?:a|an|one)\s+(?:row|line|column|circle|ring|tower|stack|pile)\b)"),
     r"\1 \2 cubes"),
    (re.compile(r"\b(\d+)(?:\s+|\s*-\s*)by(?:\s+|\s*-\s*)(?=\d)"),
     r"\1x"),
    # "pile - 4 brown cubes - back right": a spec's last field, the place on the table
    (re.compile(r"\s+-\s+(?=(?:(?:front|back|rear)[\s-]+(?:left|right)|left|right|front|back|cent(?:er|re)|middle)\s*$)"),
     " in the "),
    # "build 3-stack": a tower of that many cubes, its count glued to its noun
    (re.compile(r"\b(?:a\s+)?(\d+)-(stack|tower)\b"), r"a \2 of \1"),
    # "a two by two grid": the size in words (number words become digits later, after these rewrites)
    # ("a three-by-three wall", "a wall of orange blocks, two by two": a wall's size, which had been dropped: a 3x2 wall
    # made up)
    (re.compile(r"\b(one|two|three|four|five)(?:\s+|\s*-\s*)by(?:\s+|\s*-\s*)(one|two|three|four|five)(?=\s+(?:grid|square|array|arrangement|wall)s?\b)"
                r"|(?<=\bwall\s)(?:of\s+[a-z]+\s+(?:blocks|cubes)\s*,\s*)?\b(one|two|three|four|five)\s+by\s+(one|two|three|four|five)(?=\s*(?:[.;!]|$))"),
     lambda m: m.group(0)[:m.start(3) - m.start()] + f"{NUMBER_WORDS[m.group(3)]}x{NUMBER_WORDS[m.group(4)]}" if m.group(3)
     else f"{NUMBER_WORDS[m.group(1)]}x{NUMBER_WORDS[m.group(2)]}"),
    # "on(red, green)", "(on red green)": a goal written as a planning predicate
    (re.compile(rf"\(?\bon\s*(?:\(\s*|\s+)({COLOR_RE})\s*,?\s+({COLOR_RE})\s*\)"),
     r"the \1 block on the \2 block"),
    # "put cyan cube at back right corner of table": the articles a terse or non-native writer leaves out
    (re.compile(rf"(?:^|{BARE_OBJECT_BEFORE})(?=(?:{COLOR_RE})\s+(?:block|cube|brick|box)\b)"),
     "the "),
    (re.compile(r"\b(at|to|in|on|of|near)\s+(?=(?:front|back|rear|left|right)(?:\s+(?:left|right))?\s+(?:side|corner|edge|half|part|end)\b"
                r"|(?:middle|center|centre)\s+of\b|table\b|(?:middle|center|centre)\s*(?:[.!,;]|$))"),
     r"\1 the "),
)
"""Counts and goals written as notation ("3x white", "2 rows x 3", "on(red, green)") and articles a terse writer leaves out."""

RESTATED_TOWER_RE = re.compile(
    rf"\b(?:put|place|set|add|stack)\s+(?:a|an|the|one)\s+(?P<c>{COLOR_RE})\s+(?:cube|block)\s+on\s+top\s*,?\s*so\s+(?:that\s+)?"
    rf"(?:the\s+)?(?:tower|stack)\s+(?:reads|is|becomes|ends\s+up\s+as|goes)\s*:?\s*(?P<list>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})"
    rf"|\s+and\s+(?:{COLOR_RE}))+)(?:\s*,?\s+(?P<way>from\s+(?:the\s+)?bottom(?:\s+(?:up|to\s+(?:the\s+)?top))?|bottom\s+to\s+top"
    r"|from\s+(?:the\s+)?top(?:\s+(?:down|to\s+(?:the\s+)?bottom))?|top\s+to\s+bottom)\b)?")
"""A cube put on top, then the whole tower restated ("put a brown cube on top, so the tower reads white, blue, brown from the
bottom"): read as that tower (:func:`_restated_tower`); one whose list does not end at the cube put on top is refused
(:func:`rpg.schema.reading.normalize_words`; it had been read as a fourth cube)."""


def _restated_tower(m: re.Match) -> str:
    """The tower a result clause lists (``list``, read ``way``; with no way said, from whichever end the cube put on top
    (``c``) stands at, if at exactly one), when its top is that cube; otherwise the words as they are (refused by
    :func:`rpg.schema.reading.normalize_words`).  A clause after the list ("... and the pink cube on the red patch") is
    cut off from the tower by a full stop."""
    cubes = re.findall(rf"\b(?:{COLOR_RE})\b", m.group("list"))
    way = m.group("way")
    if way is None:  # no direction said: the list runs from the cube put on top, if it is at exactly one end
        if (cubes[0] == m.group("c")) == (cubes[-1] == m.group("c")):
            return m.group(0)
        up = cubes[-1] == m.group("c")
    else:
        up = "top" not in way or way.index("bottom") < way.index("top") if "bottom" in way else False
    cubes = cubes if up else cubes[::-1]
    if cubes[-1] != m.group("c"):
        return m.group(0)
    more = re.match(r"\s*,?\s*and\s+", m.string[m.end():])  # "..., gray and the pink cube on the red patch": another clause
    return f"build a tower from bottom to top: {', '.join(cubes)}" + ("." if more else "")


_COUNTED_GROUP = rf"(?:the\s+|all\s+)?(?:\d+|two|three|four|five|six|both)\s+(?:{COLOR_RE})\s+(?:cubes|blocks|ones)"
"""A counted group of cubes of one colour ("the two gray cubes", "3 red blocks")."""

SAYS_RE = re.compile(r"(?i)\b((?:tower|stack|column|row|line|word)\s+(?:should\s+|must\s+|will\s+|has\s+to\s+)?)(?:says|say|shows|show)\b")
"""What a structure of label cubes says ("the tower says H, A, T", "so the row shows CAT") is what it reads: rewritten
before the labels are read (:func:`rpg.schema.reading.normalize_words`), so a listed word is spelled as "reads" spells it."""

_CHAINED_PAIR = rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?\s+on(?:\s+top\s+of)?\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?"
"""One cube on another, by colour ("green on red", "the green cube on top of the red one")."""

_CUBES_NP = (r"(?:(?:a|an|the|one|two|three|four|five|six|both|\d+)\s+)?(?:(?:" + COLOR_RE + r")\s+)?(?:cubes?|blocks?)"
             r"(?:(?:\s*,\s*|\s*,?\s+and\s+)(?:(?:a|an|the|one|two|three|four|five|six|\d+)\s+)?(?:(?:" + COLOR_RE
             + r")\s+)?(?:cubes?|blocks?))*")
"""Cubes said by count and colour ("two blue cubes", "a red cube and a blue cube"), for :data:`INTRODUCED_CUBES_RE`."""

INTRODUCED_CUBES_RE = re.compile(
    r"(?:^|(?<=[.!?;]\s))(?:there\s+(?:is|are)|you\s+have|we\s+have|you(?:'ve|\s+have)\s+got|here\s+(?:is|are)"
    r"|(?:take|grab|pick\s+up|get))\s+(?P<np>" + _CUBES_NP + r")(?:\s+(?:on|from)\s+the\s+table)?\s*[.;:]\s+(?:then\s+)?"
    r"(?P<verb>put|place|set|move|stack|arrange|bring|slide|push|lay)\s+"
    r"(?P<pro>them\s+(?:both|all)|both\s+of\s+them|all\s+of\s+them|them|it|both)\b")
"""Cubes introduced in a sentence of their own and placed in the next by a pronoun ("There are two blue cubes on the
table. Place both of them on the blue patch."; "Pick up the red cube. Put it on the green patch."): read as one
command naming them ("place two blue cubes on the blue patch"); each sentence had been read alone (no task in the
first, nothing named in the second)."""

BARE_PLACED_THEN_RE = re.compile(
    rf"(?:^|(?<=[.!?;:]\s))(?:first\s*,?\s*)?(?:place|put|set)\s+(?:down\s+)?the\s+(?P<a>{COLOR_RE})\s+(?:block|cube)(?:\s+down)?(?:\s+first)?"
    r"\s*(?:,\s*|\s+and\s+|[.;]\s+)(?:and\s+)?then\s*,?\s+(?:(?:place|put|set|add)\s+)?(?P<b>the\s+(?:" + COLOR_RE + r")\s+(?:block|cube))\s+"
    r"(?P<rel>to\s+its\s+(?:left|right)(?:\s+side)?|in\s+front\s+of\s+it|behind\s+it|next\s+to\s+it|beside\s+it|on\s+(?:top\s+of\s+)?it)\b")
"""A cube put down with no place ("Place the blue block, then the yellow block to its right"), then another related to
"it": the first is the referent, read as "place the yellow block to the right of the blue block" (the first clause had
no relation, so "its" had nothing to refer to and the first cube no place)."""


def _bare_placed_then(m: re.Match) -> str:
    """:data:`BARE_PLACED_THEN_RE` -> one relation, the pronoun written as the cube put down first."""
    rest = re.split(r"[.!?;]", m.string[m.end():], maxsplit=1)[0]
    if re.search(r"\b(?:it|its|them|their|they|each|both|all)\b", rest):
        return m.group(0)  # ("..., then the red block to its right": which cube "its" is now is not said; "each on ...")
    cube = f"the {m.group('a')} block"
    rel = re.sub(r"\bits\s+(left|right)(?:\s+side)?", rf"the \1 of {cube}", m.group("rel"))
    rel = re.sub(r"\bit$", cube, rel)
    return f"place {m.group('b')} {rel}"


def _introduced_cubes(m: re.Match) -> str:
    """:data:`INTRODUCED_CUBES_RE` -> one command naming the cubes, when the pronoun agrees with them: "it" one cube,
    "both" two, "them"/"all" more than one; otherwise as written (and refused: which cubes is not clear)."""
    np, pro = m.group("np"), m.group("pro")
    counts = [NUMBER_WORDS.get(w, int(w) if w.isdigit() else 1) if w else 1
              for w in re.findall(r"(?:\b(a|an|the|one|two|three|four|five|six|both|\d+)\s+)?(?:(?:" + COLOR_RE + r")\s+)?(?:cubes?|blocks?)\b", np)]
    plural_noun = bool(re.search(r"\b(?:cubes|blocks)\b", np))
    n = sum(counts) if not plural_noun or any(c > 1 for c in counts) else None  # "the red cubes": how many is not said
    if pro == "it":
        ok = n == 1
    elif pro.startswith("both") or pro.endswith("both"):
        ok = n == 2
    else:
        ok = n is not None and n > 1
    return f"{m.group('verb')} {np}" if ok else m.group(0)


_MADE_CUBE = rf"(?:a|an|the)\s+(?:{COLOR_RE})\s+(?:block|cube)"
RELATED_TO_MADE_TOWER_RE = re.compile(
    rf"^(?:please\s+)?(?P<v>put|place|set|move)\s+(?P<x>the\s+(?:{COLOR_RE})\s+(?:block|cube))\s+(?P<rel>next\s+to|beside|behind|in\s+front\s+of"
    r"|to\s+the\s+(?:left|right)\s+of|(?:left|right)\s+of|near)\s+the\s+(?P<s>tower|stack)\s+(?:that\s+is\s+|which\s+is\s+)?"
    r"(?:made\s+(?:up\s+)?of|consisting\s+of|built\s+(?:from|of|out\s+of)|composed\s+of)\s+"
    rf"(?P<chain>{_MADE_CUBE}\s+(?:on\s+top\s+of|on|atop)\s+{_MADE_CUBE})\s*(?=[.!]?\s*$)")
"""A cube related to a tower described after it by its two cubes, one on the other ("Set the green block next to the
tower made of a red block on top of a blue block"): read as the tower built, then the cube related to it (the tower
had been one the speaker sees).  Only this one shape: a description after the noun that does not give the tower's
cubes and their order ("the tower made of wood") is left a reference, refused."""

def _both_onto_patch(m: re.Match) -> str:
    """"put the yellow cube on top of the green one, then both of them on the blue patch": the stack said before, on the
    patch ("... on the green one on the blue patch"), when the text before is that one stack of two named cubes."""
    if not re.fullmatch(rf"(?:put|place|stack|set)\s+the\s+(?:{COLOR_RE})\s+(?:cube|block)\s+on(?:\s+top\s+of)?\s+the\s+(?:{COLOR_RE})"
                        r"\s+(?:cube|block|one)", m.string[:m.start()].strip()):
        return m.group(0)
    return " "


_END_THEN_RE = re.compile(
    rf"\b(?P<first>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:at\s+the\s+(?P<end>front|back|left|right)|on\s+the\s+(?P<end2>left|right))"
    rf"\s*,?\s*(?P<rest>then\s+(?:{COLOR_RE})(?:\s*,?\s*(?:and\s+)?then\s+(?:{COLOR_RE}))*)\b")
"""A sequence whose first item is said with its end ("yellow at the front, then gray, then pink", "with red on the left,
then white, then blue"): read as the list, when the direction said elsewhere starts from that end (:func:`_end_then`)."""


def _end_then(m: re.Match) -> str:
    end = m.group("end") or m.group("end2")
    said = re.search(r"\b(front|back|left|right)\s+to\s+(?:the\s+)?(?:front|back|left|right)\b|\b(bottom)\s+(?:to|up)\b", m.string)
    if not (said and said.group(1) == end) or re.match(r"\s*,?\s*(?:last|at\s+the\s+(?:end|back|front|left|right))\b", m.string[m.end():]):
        return m.group(0)  # the end is not where the direction said starts (or none is said), or the last one is placed
        # too: left as written
    return ", ".join([m.group("first"), *re.findall(rf"\b(?:{COLOR_RE})\b", m.group("rest"))])


_GROUP = rf"(?:one|two|three|four|five|a|an|\d)\s+(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?"
COUNTED_ROW_GROUPS_RE = re.compile(
    r"\b(?:a|one)\s+(?:(?:horizontal|straight|single|neat|long)\s+)?(?:row|line)\s+of\s+(?P<n>one|two|three|four|five|six|seven|eight|\d+)\s+(?:cubes|blocks)\s*[.:,;]\s*"
    rf"(?P<first>{_GROUP})\s+on\s+the\s+left\s*(?P<rest>(?:,\s*(?:and\s+)?then\s+{_GROUP}(?!\s+on\s+the\s+left\b))+)"
    r"(?:\s+on\s+the\s+right)?\b")
"""A row said by counted colour groups from its left end ("two blue on the left, then one yellow, then two blue on the
right"): read as the row's cubes from left to right (:func:`_counted_row_groups`), where the text says a row or line."""


def _counted_row_groups(m: re.Match) -> str:
    cubes = []
    for n, c in re.findall(rf"\b(one|two|three|four|five|a|an|\d)\s+({COLOR_RE})\b", m.group(0)[m.start("first") - m.start():]):
        cubes += [c] * (int(n) if n.isdigit() else NUMBER_WORDS.get(n, 1))
    said = int(m.group("n")) if m.group("n").isdigit() else NUMBER_WORDS[m.group("n")]
    if said != len(cubes):
        return m.group(0)  # the row's count and its groups disagree: left as written (and refused)
    return "a row from left to right: " + ", ".join(cubes)


_SIDE_OF = r"(?:goes\s+|is\s+|sits\s+)?(?:to\s+the\s+|on\s+the\s+)?(?P<r{i}>left|right)\s+of\s+the\s+(?P<b{i}>" + COLOR_RE + r")\s+(?:cube|block)"
SIDES_IN_A_ROW_RE = re.compile(
    rf"(?:(?:put|place|set)\s+)?the\s+(?P<a>{COLOR_RE})\s+(?:cube|block)\s+{_SIDE_OF.format(i=1)}\s*,?\s+and\s+(?:(?:put|place|set)\s+)?the\s+"
    rf"(?P<c>{COLOR_RE})\s+(?:cube|block)\s+{_SIDE_OF.format(i=2)}\s*,\s*(?:with\s+)?all\s+(?:three|3\s+)?\s*(?:of\s+them\s+)?in\s+(?:a|one)\s+"
    r"(?:straight\s+)?(?:row|line)\b")
"""Two cubes on either side of a third, then "all three in a row": the row, left to right (the summary had found no
place in the relations' reading)."""


def _sides_in_a_row(m: re.Match) -> str:
    a, b, c = m.group("a"), m.group("b1"), m.group("c")
    if m.group("b2") != b or m.group("r1") == m.group("r2") or len({a, b, c}) < 3:
        return m.group(0)
    left, right = (a, c) if m.group("r1") == "left" else (c, a)
    return f"a row from left to right: {left}, {b}, {right}"


def _labelled_listed(m: re.Match) -> str:
    """"the cubes labelled 4, 7 and 2" -> each label its own cube ("the cube labelled 4 and the cube labelled 7 and ...");
    digits said again later with a place ("with 4 at the bottom"), outside a "between" -> "the digit cubes 4, 7 and 2", whose
    readers take that digit as its cube (it had been read as a count: four cubes of default colours, silently wrong)."""
    labels = re.findall(r"[a-z0-9]", re.sub(r"\band\b", " ", m.group("l")))
    again = "|".join(labels)
    if all(x.isdigit() for x in labels) and not re.search(r"\bbetween\s*$", m.string[:m.start()]) and re.search(
            rf"(?<![\w.])(?:{again})\s+(?:(?:is|goes|sits|should\s+be)\s+)?(?:at|on|in)\s+(?:the\s+)?(?:very\s+)?(?:bottom|top|base|middle"
            r"|left|right|front|back)\b", m.string[m.end():]):
        return f"the digit {m.group('n')}s " + ", ".join(labels[:-1]) + " and " + labels[-1]
    said = "labelled" if m.group("w") == "numbered" else m.group("w")
    return " and ".join(f"the {m.group('n')} {said} {x}" for x in labels)


WORD_ORDER_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (SIDES_IN_A_ROW_RE, _sides_in_a_row),
    (COUNTED_ROW_GROUPS_RE, _counted_row_groups),
    (_END_THEN_RE, _end_then),
    (re.compile(rf"\s*,?\s*(?:and\s+)?then\s+(?:put\s+|place\s+|move\s+|set\s+)?(?:both\s+of\s+them|them\s+both|both)\s+"
                rf"(?=on\s+(?:to\s+)?the\s+(?:{COLOR_RE})\s+(?:goal\s+)?patch\s*[.!]?\s*$)"), _both_onto_patch),
    (INTRODUCED_CUBES_RE, _introduced_cubes),
    (RELATED_TO_MADE_TOWER_RE, lambda m: f"build a {m.group('s')} of {m.group('chain')} and {m.group('v')} {m.group('x')} {m.group('rel')} it"),
    (BARE_PLACED_THEN_RE, _bare_placed_then),
    # "stack the red cubes into a tower, then crown it with the yellow cube": that cube on top
    (re.compile(rf"\b(?:crown|cap|top)\s+(?:it|them|the\s+(?:tower|stack|pile))(?:\s+off)?\s+with\s+(?P<np>(?:a|an|the|one|1)\s+"
                rf"(?:single\s+)?(?:{COLOR_RE})\s+(?:cube|block|brick|one))\b"),
     r"put \g<np> on top"),
    # "a wall whose bottom row is orange, purple, orange and whose top row is ...": its rows, as "where the" says them
    (re.compile(r"\b((?:wall|pyramid|tower|stack|row|line|grid)s?\s+)whose\b(?P<rest>[^.;]*)"),
     lambda m: m.group(1) + "where the" + re.sub(r"\b(and|,)\s+whose\b", r"\1 the", m.group("rest"))),
    # "into piles by colour: the two red ones in one pile and the two green ones in another": two piles, as listed
    (re.compile(r"\b(into|in)\s+piles\b(?=(?:\s+by\s+colou?r)?\s*:\s*[^.;:]*\bin\s+(?:1|one)\s+pile\b[^.;:]*\band\s+[^.;:]*"
                r"\b(?:in\s+)?another(?:\s+(?:one|pile))?\s*(?:[.!]|$))"), r"\1 2 piles"),
    # "Two towers please. One has green on red, the other has yellow on purple.", "two separate towers. One is green on
    # yellow. The other is blue on pink.", "two towers one red on green the other white on black": each tower said after them
    (re.compile(rf"\b((?:2|two)\s+(?:separate\s+|different\s+)?(?:towers|stacks))(?:\s*,?\s*please)?\s*[.!:,;]?\s+(?:1|one)(?:\s+(?:tower|stack))?"
                rf"(?:\s+(?:has|with|having|is)|\s*:)?\s+(?P<a>{_CHAINED_PAIR})\s*[.,;]?\s*(?:and\s+)?the\s+other(?:\s+(?:one|tower|stack))?"
                rf"(?:\s+(?:has|with|having|is)|\s*:)?\s+(?P<b>{_CHAINED_PAIR})\s*(?=[.!]?\s*$)"),
     lambda m: f"{m.group(1)}: one is {m.group('a')}, the other is {m.group('b')}"),
    # "stack them in this order from the table up: cyan, white, cyan": the pronoun stands for the cubes listed after
    (re.compile(rf"\b(stack|put|place|arrange|set|order|lay\s+out|line\s+up|line)\s+(?:them|these|those)(\s+up)?\b"
                rf"(?=[^.;:]*:\s*(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:the\s+)?(?:{COLOR_RE})"
                rf"(?:\s+(?:cube|block))?)+\s*[.!]?\s*$)"),  # (the list ends the text: what follows it would be a guess)
     lambda m: f"{m.group(1)}{m.group(2) or ''} the cubes"),
    # "line them up: yellow, blue, red", "row: red, green, blue": a row's cubes listed after its colon are its order
    # (either way along it: no side is said)
    # (at a sentence's start only: "4 blocks in a single straight line: red, blue, ..." lists the cubes, in no order)
    (re.compile(rf"(?:^|(?<=[.!?]\s))((?:(?:a|one|1)\s+)?(?:row|line)|line\s+up(?:\s+the\s+cubes)?|line\s+the\s+cubes\s+up)\s*:\s*(?=(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})){{2,}}"
                r"\s*[.!]?\s*$)"), r"\1 in this order: "),
    # "the corner behind, on the right of the table", "the corner of the front at the left": that corner
    (re.compile(r"\b(?:the\s+)?corner\s+(?:of\s+)?(?:the\s+)?(?P<fb>behind|back|rear|front)\s*,?\s*(?:(?:on|at|to|in|of)\s+the\s+)?"
                r"(?P<lr>left|right)\b(?:\s+(?:hand\s+)?(?:side\s+)?(?:of\s+the\s+table)?)?"),
     lambda m: f"the {'front' if m.group('fb') == 'front' else 'back'} {m.group('lr')} corner"),
    # "two towers: (1) cyan on purple (2) white on black": each tower numbered
    (re.compile(rf"\b((?:2|two)\s+(?:separate\s+|different\s+)?(?:towers|stacks))\s*:?\s*(?:\(?(?:1|a|i)[.)]\s*)?(?P<a>{_CHAINED_PAIR})\s*[,;]?\s*"
                rf"(?:and\s+)?\(?(?:2|b|ii)[.)]\s*(?P<b>{_CHAINED_PAIR})\s*(?=[.!]?\s*$)"),
     lambda m: f"{m.group(1)}: one is {m.group('a')}, the other is {m.group('b')}"),
    # "line up the blue cube the white cube and the black cube": a list said without its commas
    (re.compile(rf"\b((?:the|a|an)\s+(?:{COLOR_RE})\s+(?:cube|block))\s+(?=(?:the|a|an)\s+(?:{COLOR_RE})\s+(?:cube|block)\b"
                rf"(?:\s+(?:the|a|an)\s+(?:{COLOR_RE})\s+(?:cube|block)\b)*\s*,?\s+and\s+(?:the|a|an)\s+(?:{COLOR_RE})\s+(?:cube|block)\b)"), r"\1, "),
    # "put a brown cube on top, so the tower reads white, blue, brown from the bottom": the result restates the whole
    # tower, its top the cube put there (the cube had been counted twice, a fourth under the tower)
    (RESTATED_TOWER_RE, lambda m: _restated_tower(m)),
    # "a row running left to right of black, orange, orange", "a row of red, blue, green going left to right": the
    # row's direction said with a verb of motion, or before its cubes
    (re.compile(r"\b(?:running|going|reading|heading)\s+(?:from\s+)?(?=(?:the\s+)?(?:left|right)\s+to\s+(?:the\s+)?(?:left|right)\b)"), "from "),
    (re.compile(rf"\b(row|line)\s+from\s+(?:the\s+)?(left\s+to\s+(?:the\s+)?right|right\s+to\s+(?:the\s+)?left)\s+(?:of|with)\s+"
                rf"(?P<list>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))+)(?=\s*[.!]?\s*$)"),
     r"\1 of \g<list> from \2"),
    # "put the two gray cubes in one pile and the two pink cubes in a separate pile": two piles, each its cubes
    # (each group counted: "the two gray cubes"; a group of no count would leave how many cubes to a default)
    (re.compile(rf"^(?:please\s+)?(?:put|place|set|gather|group|move)\s+(?P<a>{_COUNTED_GROUP})\s+in\s+(?:1|one)\s+pile\s+and\s+(?P<b>{_COUNTED_GROUP})\s+in\s+"
                r"(?:a\s+separate|another|a\s+second|a\s+different|the\s+other)(?:\s+(?:one|pile))?\s*[.!]?\s*$"),
     r"make 2 piles: \g<a> in one pile and \g<b> in another."),
    # "..., and finish by placing the orange block on the gray one": the last step
    (re.compile(r"\b(?:and\s+)?(?:finish|end)\s+(?:off\s+|up\s+)?by\s+(plac|putt|sett|stack|add|lay)ing\b"),
     lambda m: "then " + {"plac": "place", "putt": "put", "sett": "set"}.get(m.group(1), m.group(1))),
    # "put digit 7 on top of digit 2": a label cube named without its article
    (re.compile(r"(?<![\w'])(?<!the\s)(?<!a\s)(?<!each\s)(?<!every\s)(?<!any\s)\b(digit|number|letter)\s+(?=(?:\d|[A-Z])\b(?!\s*(?:,|to\b|-))|(?:\d|[A-Z])\s*,\s*(?:and\s+)?(?:digit|number|letter)\s+(?:\d|[A-Z])\b)"),
     r"the \1 "),
    # "the cube the blue on the cube the red": a colour after its noun and an article (Italian, Arabic)
    (re.compile(rf"\bthe\s+(cubes?|blocks?|box(?:es)?|patch(?:es)?)\s+the\s+({COLOR_RE})\b"
                rf"(?!\s+(?:cubes?|blocks?|box(?:es)?|patch(?:es)?|ones?)\b)"),
     r"the \2 \1"),
    # "the cube brown on the cube orange", "block purple on block yellow", "the cube of colour blue": a colour after its noun
    # a list after the noun ("the cube red, blue and green") is left as it is, not a new clause ("cyan on patch red,
    # purple on patch red also": the red patch, then a purple cube)
    (re.compile(rf"(?<!every )(?<!each )(?<!all )(?<!any )\b(cube|block|box|patch)\s+(?:of\s+(?:the\s+)?colou?r\s+)?({COLOR_RE})\b"
                rf"(?!\s*(?:cubes?|blocks?|box(?:es)?|patch(?:es)?|ones?)\b|\s*(?:,|and\b|or\b)\s*(?:the\s+)?(?:{COLOR_RE})\b"
                r"(?!\s+(?:(?:cube|block|one)\s+)?(?:on|onto|in|into|at|next|beside|near|behind|under|over|above|below|left|right"
                r"|goes|is|should|must)\b))"),
     r"\2 \1"),
    # "two cubes gray and the cube brown": a counted colour after its noun (Russian, Spanish habits)
    # the colour may agree in number ("the two cubes oranges", French and Spanish)
    (re.compile(rf"\b(\d+|{COUNT_WORD_RE})\s+(cubes|blocks)\s+({COLOR_RE})s?\b(?!\s*(?:cubes?|blocks?|ones?|patch(?:es)?)\b|\s*,\s*(?:{COLOR_RE})\b|\s+(?:{COLOR_RE})\b)"),
     r"\1 \3 \2"),
    # "..., green cube on the red patch too": a clause said as well as the others, as every clause of a goal is
    (re.compile(r"(?<=\w)\s*,?\s+(?:too|as\s+well)\s*(?=[.;!]|$)"),
     ""),
    # "between the cubes labelled 4 and 6", "the cubes labelled 4, 7 and 2": each label its own cube (the last of a list of
    # three had been left bare, and a cube of a default colour made up for it: silently wrong)
    (re.compile(r"\bthe\s+(?P<n>cube|block)s\s+(?P<w>labell?ed|marked|numbered|with)\s+(?P<l>[a-z0-9](?:\s*,\s*[a-z0-9])*\s*(?:,\s*|\s+)(?:and\s+)?"
                r"[a-z0-9])\b(?![\w'-])"),
     lambda m: _labelled_listed(m)),
    # "the green in bottom", "with gray between.": a role said without its article or its "in" (non-native habits)
    (re.compile(r"\b(?:in|at|on)\s+bottom\b"),
     "at the bottom"),
    (re.compile(r"(?<!\bin )\bbetween(?=\s*(?:[.;!]|$))"),
     "in between"),
    # "a tower of 3 reds", "two greens and a blue": a counted colour said as a plural noun
    (re.compile(rf"\b(\d+|{COUNT_WORD_RE})\s+({COLOR_RE})s\b(?!\s*(?:cubes?|blocks?|ones?|patch(?:es)?)\b)"),
     r"\1 \2 cubes"),
    # "the corner back right", "the part front of the table": a place's words after its noun (Spanish, French)
    (re.compile(r"\bthe\s+(corner|side|part|edge)\s+((?:front|back|rear)(?:[\s-]+(?:left|right))?|left|right)\b"),
     r"the \2 \1"),
    # "tower | top: pink | bottom: gray", "red / white / red / white": a table row's or a list's separators
    (re.compile(r"\s*\|\s*"),
     ", "),
    (re.compile(rf"\b({COLOR_RE})\s*/\s*(?=(?:{COLOR_RE})\b)"),
     r"\1, "),
    # "a pyramid: the bottom three are yellow, the next two are orange, ...": each layer's count and colour
    (re.compile(rf"\bthe\s+(bottom|lowest|next|middle|top)\s+(\d+|{COUNT_WORD_RE})\s+(?:are|is|being)\s+(?:all\s+)?"
                rf"({COLOR_RE})\b"),
     lambda m: m.group(0) if m.group(2) in ("one", "1") else  # "the top one is red": the top cube's rule
     f"{NUMBER_WORDS.get(m.group(2), m.group(2))} {m.group(3)} cubes "
     + {"bottom": "on the bottom", "lowest": "on the bottom", "top": "on top"}.get(m.group(1), "in the middle")),
)
"""Word orders of other languages and terse notes ("the cube brown", "the corner back right", "in bottom", "3 reds", separators): English order."""

TOWERS_BY_PLACE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Build two towers, one in the front right corner with cyan on top of brown, and one in the back left corner with gray
    # on top of red": each tower's chain, then its place (which cubes make each tower had been read as not said)
    (re.compile(rf"(?i)\bone\s+(?P<where>in\s+the\s+(?:[a-z]+\s+){{0,2}}?(?:corner|half|side|end|middle|centre|center))\s*,?\s+with\s+(?:the\s+)?"
                rf"(?P<a>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?:on\s+top\s+of|on|atop)\s+(?:the\s+)?(?P<b>{COLOR_RE})(?:\s+(?:cube|block))?\b"),
     lambda m: f"{m.group('a')} on {m.group('b')} {m.group('where')}" if re.search(r"(?i)\b(?:two|three|2|3)\s+(?:towers|stacks)\b",
                                                                                m.string[:m.start()]) else m.group(0)),
    (re.compile(rf"(?i)\b((?:two|three|2|3)\s+(?:towers|stacks))\s*,\s+(?=(?:{COLOR_RE})\s+on\s+(?:{COLOR_RE})\s+in\s+the\b)"), r"\1: "),
    # "Stack a white cube on a red cube, and stack a white cube on a blue cube, two separate towers.": the count said last,
    # written as the heading (its "two separate towers" had been read as more cubes)
    (re.compile(r"(?i)^\s*(?P<body>[^:;]+?)\s*[,;\u2013\u2014-]\s*(?:as\s+|in\s+|making\s+|forming\s+|so\s+)?(?P<n>two|three|2|3)\s+"
                r"(?P<kind>(?:separate\s+|distinct\s+|different\s+|independent\s+)?(?:towers|stacks|rows|lines))\s*[.!]?\s*$"),
     lambda m: f"{m.group('n')} {m.group('kind')}: {m.group('body')}."),
)
"""Towers counted, then each said by its place and its chain ("Build two towers, one in the front right corner with cyan on
top of brown, and one in the back left corner with gray on top of red"): written as the heading
:func:`rpg.schema.readers._towers_headed` reads ("two towers: cyan on brown in the front right corner, and ...")."""

def _them_counted_as_listed(m: re.Match) -> bool:
    """Whether "N of them" counts as many cubes as the list after it names ("all three of them, black, gray and brown";
    "all four of them" before three colours stays as said, refused)."""
    counted = re.search(r"\b(\d+|two|three|four|five|six)\s+of\b", m.group(1))
    listed = re.match(r"[^.;!]*", m.string[m.end():])
    return not counted or count_word(counted.group(1)) == len(re.findall(rf"\b(?:{COLOR_RE})\b", listed.group(0)))


BOTTOM_UP_ROLES_RE = re.compile(
    rf"\bthe\s+(?:bottom|lowest|base)\s+(?:cube|block|one)\s+(?:should\s+be|must\s+be|has\s+to\s+be|is|will\s+be)\s+"
    rf"(?P<c1>{COLOR_RE})(?P<mid>(?:\s*,\s*(?:and\s+)?(?:then\s+|the\s+(?:second|third|fourth|fifth|sixth|next)\s+(?:one|cube|block)\s+"
    rf"(?:(?:should|must)\s+be\s+|is\s+)?)(?:{COLOR_RE}))*)\s*,?\s*(?:and\s+)?(?:then\s+)?the\s+(?:top|highest|topmost|last)\s+"
    rf"(?:one|cube|block)\s+(?:(?:should|must|has\s+to|will)\s+be\s+|is\s+)?(?P<cn>{COLOR_RE})(?=\s*(?:[.;!]|$))")
"""A tower said cube by cube from its bottom, up to its top ("The bottom cube should be grey, the second one black, the
third one white and the top one red"; :func:`rpg.schema.reading.bottom_up_roles`)."""


def _relation_then_structure(m: re.Match) -> bool:
    """Whether the clause before ``m`` (its sentence) relates two cubes by colour ("put red on blue") and names no structure,
    and the clause after it builds one of cubes named by colour alone, none of them the first clause's, with nothing that
    refers back ("them", "it", "the rest", "another", "both"): :data:`LOOSE_PHRASE_REWRITES` then makes them two sentences."""
    before = re.split(r"[.;!?]", m.string[:m.start()])[-1]
    after = re.split(r"[.;!?]", m.string[m.end():])[0]
    if not re.search(r"\b(?:on|onto|on\s+top\s+of|next\s+to|beside|left\s+of|right\s+of|behind|in\s+front\s+of|between|under|below|above"
                     r"|far\s+from|away\s+from)\b", before) or re.search(
            r"\b(?:rows?|lines?|towers?|stacks?|piles?|pyramids?|walls?|circles?|rings?|columns?|grids?)\b", before):
        return False
    if re.search(r"\b(?:it|its|them|they|those|these|that|this|both|all|each|every|rest|remaining|others?|another|same|more|too|also|again"
                 r"|with|next\s+to|beside|left|right|behind|front|between|near|around|on\s+top|under|below|above)\b", after):
        return False
    first = set(re.findall(rf"\b(?:{COLOR_RE})\b", before))
    second = set(re.findall(rf"\b(?:{COLOR_RE})\b", after))
    return bool(first) and bool(second) and not first & second


def _other_cubes_in_any_order(m: re.Match) -> str:
    """"Tower of four: yellow on the bottom, and the other three (red, pink, brown) in any order above it" -> "build a
    tower of the yellow, red, pink and brown cubes with the yellow cube at the bottom" ("Row of three: white on the far
    left, then the other two, ...": a row with that end); as said where the count, the end and
    the side the others stand on do not agree (the other three above a top cube)."""
    listed = re.findall(rf"\b(?:{COLOR_RE})\b", m.group("l"))
    n, k = (int(NUMBER_WORDS.get(x, x)) for x in (m.group("n"), m.group("k")))
    cubes = f"the {', '.join([m.group('e'), *listed[:-1]])} and {listed[-1]} cubes"
    if n != k + 1 or len(listed) != k or m.group("e") in listed:
        return m.group(0)
    if m.group("end") in ("left", "right"):  # a row: that end said
        return f"make a row of {cubes} with the {m.group('e')} cube at the {m.group('end')} end" + (m.group("stop") or ".")
    above = m.group("w") in ("above", "over") or m.group("w").startswith("on")
    if above != (m.group("end") in ("bottom", "base")):
        return m.group(0)
    where = "at the bottom" if above else "on top"
    return f"build a tower of {cubes} with the {m.group('e')} cube {where}" + (m.group("stop") or ".")


LOOSE_PHRASE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Tower of four: yellow on the bottom, and the other three (red, pink, brown) in any order above it": the tower of
    # those cubes with its one end said (no task had been found)
    # "Row of three: white on the far left, then the other two, orange and cyan, in any order": a row with that end said
    (re.compile(rf"^(?:(?:build|make|lay\s+out)\s+)?(?:a\s+)?(?:row|line)\s+of\s+(?P<n>\d+|{COUNT_WORD_RE})(?:\s+(?:cubes|blocks))?\s*[:,]\s*"
                rf"(?:the\s+)?(?P<e>{COLOR_RE})(?:\s+(?:one|cube|block))?\s+(?:is\s+|goes\s+)?(?:on|at)\s+the\s+(?:far\s+|very\s+)?"
                r"(?P<end>left|right)(?:\s+end)?\s*[,;]\s*(?:and\s+)?(?:then\s+)?the\s+other\s+"
                rf"(?P<k>\d+|{COUNT_WORD_RE})\s*(?:\(\s*|,\s*)(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))*)"
                r"\s*\)?\s*,?\s*(?:can\s+go\s+|go\s+|are\s+|stand\s+|sit\s+)?in\s+(?:any|either)\s+order\s*(?P<stop>[.!]?)\s*$"),
     lambda m: _other_cubes_in_any_order(m)),
    (re.compile(rf"^(?:(?:build|make|stack)\s+)?(?:a\s+)?(?:tower|stack)\s+of\s+(?P<n>\d+|{COUNT_WORD_RE})(?:\s+(?:cubes|blocks))?\s*[:,]\s*"
                rf"(?:the\s+)?(?P<e>{COLOR_RE})(?:\s+(?:one|cube|block))?\s+(?:is\s+|goes\s+)?(?:on|at)\s+(?:the\s+)?(?:very\s+)?(?P<end>bottom|base|top)"
                rf"\s*[,;]\s*(?:and\s+)?the\s+other\s+(?P<k>\d+|{COUNT_WORD_RE})\s*(?:\(\s*|,\s*)"
                rf"(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE})|\s+and\s+(?:{COLOR_RE}))*)\s*\)?\s*,?\s*"
                r"(?:can\s+go\s+|go\s+|are\s+|stand\s+|sit\s+)?in\s+(?:any|either)\s+order\s+"
                r"(?P<w>above|over|on\s+top\s+of|under|below|beneath|underneath)\s+(?:it|them)\s*(?P<stop>[.!]?)\s*$"),
     lambda m: _other_cubes_in_any_order(m)),
    # "a tower of the cyan, orange and white cubes on the right side, cyan at the bottom and white at the top": the place
    # said after the ends (the place between the list and its ends had cut the list from them: the orange cube refused)
    (re.compile(rf"(?P<head>\b(?:tower|stack|column|row|line)\s+of\s+(?:the\s+)?(?:{COLOR_RE})(?:\s*,\s*(?:{COLOR_RE}))*\s*,?\s+and\s+"
                rf"(?:{COLOR_RE})\s+(?:cubes|blocks))\s+(?P<place>(?:on|at|in)\s+the\s+(?:far\s+)?(?:left|right|front|back|middle|center|centre)"
                r"(?:\s+(?:left|right))?(?:\s+(?:side|edge|corner|half|end)(?:\s+of\s+the\s+table)?)?)\s*,\s*"
                rf"(?P<roles>(?:with\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+(?:the\s+)?(?:very\s+)?"
                r"(?:bottom|base|top|left|right)\b[^.;!?,]*)(?=\s*(?:[.;!?]|$))"),
     lambda m: f"{m.group('head')}, {m.group('roles').rstrip()}, {m.group('place')}"),
    # "From left to right, place red, white, red.": the direction said before the verb and its list (no task had been found)
    (re.compile(rf"^(?P<d>(?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left))\s*,\s*(?P<v>place|put|set|lay\s+out|line\s+up|arrange)\s+"
                rf"(?P<l>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)+"
                rf"(?:\s*,?\s*and\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)?)\s*(?P<e>[.!]?)\s*$"),
     lambda m: f"{m.group('v')} {m.group('l')} {m.group('d')}{m.group('e')}"),
    # "Tower of three: blue on top; the other two, red and white, can go in either order.": one end fixed, the rest free (it
    # had been read as a contradiction)
    (re.compile(rf"(?i)\b(?:tower|stack)\s+of\s+(?:three|3)(?:\s+(?:cubes|blocks))?\s*:\s*(?:the\s+)?(?P<x>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+"
                r"(?:(?:goes|is|sits)\s+)?(?P<end>on\s+top|at\s+the\s+top|at\s+the\s+bottom|on\s+the\s+bottom)\s*[;,.]\s*(?:and\s+)?"
                rf"the\s+other\s+(?:two|2)(?:\s+(?:cubes|blocks|ones))?\s*,?\s*(?:the\s+)?(?P<y>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+and\s+"
                rf"(?:the\s+)?(?P<z>{COLOR_RE})(?:\s+(?:cube|block|one))?\s*,?\s*(?:(?:can|may)\s+)?(?:(?:go|be|are)\s+)?(?:(?:placed|stacked)\s+)?"
                r"in\s+(?:either|any)\s+order(?=\s*(?:[.;!]|$))"),
     lambda m: f"a tower of {m.group('y')}, {m.group('z')} and {m.group('x')} with {m.group('x')} "
               + ("on top" if "top" in m.group("end").lower() else "at the bottom")),
    # "a purple cube with a pink cube on top of it": the pink cube on the purple one (no verb had been found); a cube
    # "with" another under it, the other way; only a single cube each (a row "with a green cube on top" stays as said)
    (re.compile(rf"(?P<pre>^|[:;.]\s+|\b(?:put|place|set|stack|build|make)\s+)(?:a|an|the|one|1)\s+(?P<a>{COLOR_RE})\s+(?:cube|block)"
                rf"\s+with\s+(?:a|an|the|one|1)\s+(?P<b>{COLOR_RE})\s+(?:cube|block)\s+(?:(?:resting|sitting|standing|placed|stacked)\s+)?"
                r"(?P<rel>on\s+top(?:\s+of\s+it)?|on\s+it|atop\s+it|under(?:neath)?\s+it|beneath\s+it|below\s+it)(?=\s*(?:[.;!]|$))"),
     lambda m: m.group("pre") + (f"the {m.group('b')} cube on top of the {m.group('a')} cube"
                                 if not re.match(r"under|beneath|below", m.group("rel")) else f"the {m.group('a')} cube on top of the {m.group('b')} cube")),
    # "a tower of 5 alternating yellow and green": a count of cubes (the alternation had been read without it)
    (re.compile(r"\b(tower|stack|column|row|line)\s+of\s+(\d+|two|three|four|five|six|seven|eight)\s+(?=alternating\b)"), r"\1 of \2 cubes "),
    # "put the yellow and orange cubes one on the other": on top of each other
    (re.compile(r"\bone\s+(?:on\s+top\s+of|on|onto|atop|above)\s+the\s+other\b"), "on top of each other"),
    # "the cube that is red", "the block which is black": the red cube (the relative clause had lost its colour)
    (re.compile(rf"\bthe\s+(cube|block)\s+(?:that|which)\s+is\s+(?P<c>{COLOR_RE})\b(?!\s*(?:and|or|,|-|with|{COLOR_RE})\b)"),
     lambda m: f"the {m.group('c')} {m.group(1)}"),
    # "Lay the cubes out red, orange, yellow, green from left to right": a list given a direction across the table is a row
    # (no structure said anywhere else; it had found no task)
    (re.compile(rf"\b(?P<v>lay|put|place|set|arrange)\s+(?:(?:the\s+|all\s+|the\s+\d+\s+)?(?:cubes|blocks)\s+|them\s+)?(?:out\s+)?"
                rf"(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:{COLOR_RE}))+,?\s+(?:and\s+)?(?:{COLOR_RE}))\s*,?\s+(?P<d>(?:from\s+)?(?:left\s+to\s+right"
                rf"|right\s+to\s+left))\b"),
     lambda m: m.group(0) if re.search(r"\b(?:row|line|tower|stack|pile|pyramid|wall|circle|ring|grid|column|rows|lines|towers|on|onto"
                                       r"|spell\w*|reads?)\b", m.string)
     else f"{m.group('v')} {m.group('l')} in a row {m.group('d')}"),
    # "Put red on blue and make a row of green and yellow": a relation, then a structure of other cubes, two clauses of their
    # own (the row had taken red and blue too, the stack dropped, silently); not when the structure's clause refers back
    # ("and make a tower of them")
    (re.compile(r"(?<=[a-z])\s*,?\s+and\s+(?:then\s+|also\s+)?(?=(?:make|build|form|create|put|place|arrange|line\s+up|stack|set|lay)\b"
                r"[^.;!?]*?\b(?:rows?|lines?|towers?|stacks?|piles?|pyramids?|walls?|circles?|rings?|columns?|in\s+a\s+row|up)\b)"),
     lambda m: ". " if _relation_then_structure(m) else m.group(0)),
    # "a row of the pink cube and the two cyan cubes": one cube and a counted group listed together, the single cube counted
    # one (the article had hidden the second group's count: a row of two, refused)
    (re.compile(rf"\b(?:a|an|the)\s+(?P<a>{COLOR_RE})\s+(?P<n1>cube|block)\s+and\s+(?:the\s+)?(?P<k>{COUNT_WORD_RE}|\d+)\s+(?P<b>{COLOR_RE})\s+"
                r"(?P<n2>cubes|blocks)\b"),
     lambda m: f"one {m.group('a')} {m.group('n1')} and {m.group('k')} {m.group('b')} {m.group('n2')}"),
    (re.compile(rf"\bthe\s+(?P<k>{COUNT_WORD_RE}|\d+)\s+(?P<b>{COLOR_RE})\s+(?P<n2>cubes|blocks)\s+and\s+(?:a|an|the)\s+(?P<a>{COLOR_RE})\s+"
                r"(?P<n1>cube|block)\b"),
     lambda m: f"{m.group('k')} {m.group('b')} {m.group('n2')} and one {m.group('a')} {m.group('n1')}"),
    # "Row of three: yellow in the middle, red and blue on either side of it": after a middle said, the two cubes beside it are
    # the row's ends ("either" had been an unknown word)
    (re.compile(rf"\b(?P<a>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+and\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?)\s+"
                rf"(?:(?:go|are|sit|stand)\s+)?on\s+(?:either|each|both)\s+sides?(?:\s+of\s+(?:it|the\s+(?P<x>{COLOR_RE})(?:\s+(?:cube|block|one))?))?"
                r"(?=\s*(?:[.;!]|$))"),
     lambda m: f"{m.group('a')} at the ends" if (middle := re.search(
         rf"\b(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:is|goes|sits|stands)\s+)?in\s+the\s+(?:middle|center|centre)\b(?!\s+of\s+the\s+table)",
         re.split(r"[.;!?]", m.string[:m.start()])[-1])) and m.group("x") in (None, middle.group("c")) else m.group(0)),
    # "Put red and blue on either side of the yellow cube": the yellow cube between them ("either" had been an unknown word)
    (re.compile(rf"\b(?P<v>put|place|set)\s+(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+and\s+(?:the\s+)?(?P<b>{COLOR_RE})"
                rf"(?:\s+(?:cubes?|blocks?|ones?))?\s+on\s+(?:either|each|both)\s+sides?\s+of\s+the\s+(?P<x>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                r"(?=\s*(?:[.;!]|$))"),
     lambda m: f"{m.group('v')} the {m.group('x')} cube between the {m.group('a')} cube and the {m.group('b')} cube"),
    # "green is on the far left, blue comes next, then black": the next in the order said ("comes" had been an unknown word)
    (re.compile(rf",\s*(?:the\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:comes|is|goes|sits|stands)\s+next\b(?!\s+to\b)"),
     lambda m: f", then {m.group('c')}" if re.search(r"\b(?:far\s+(?:left|right)|leftmost|rightmost|first|at\s+the\s+(?:left|right|bottom|top)"
                                                    r"|on\s+the\s+(?:left|right|bottom)|(?:left|right)\s+end)\b[^.;!?]*$",
                                                    m.string[:m.start()]) else m.group(0)),  # (only after an end said: an order)
    # "with the two white cubes at the ends": one of them at each end of the row (the count had been read against one cube)
    (re.compile(rf"\b(?:the\s+)?(?:two|2|both)\s+(?P<c>{COLOR_RE})\s+(?P<n>cube|block|one)s\s+(?:go\s+|are\s+|sit\s+)?(?:at|on)\s+(?:the\s+)?"
                r"(?:two\s+|both\s+)?ends\b(?!\s+of\s+(?:the|a)\s+(?:table|workspace))"),
     lambda m: f"a {m.group('c')} {'cube' if m.group('n') == 'one' else m.group('n')} at each end"),  # ("the two red ones")
    # "green in the middle, white at the ends": a white cube at each end (one white cube had been read, a red one made up)
    (re.compile(rf"\b(?P<mid>in\s+the\s+middle)(?P<sep>\s*,\s*(?:with\s+|and\s+)?|\s+and\s+)(?P<c>{COLOR_RE})(?:\s+(?:cubes|blocks|ones))?\s+"
                r"(?:go\s+|are\s+|sit\s+)?(?:at|on)\s+(?:the|both)\s+(?:two\s+)?ends\b(?!\s+of\b)"),
     lambda m: f"{m.group('mid')} and a {m.group('c')} cube at each end"),
    # "green in the middle, with a white cube at each end": one clause with the middle (after the comma a white cube had been
    # read once and a red one made up, silently)
    (re.compile(r"\b(in\s+the\s+(?:middle|center|centre))\s*,\s*(?:with\s+|and\s+)?(?=(?:a|an|one)\s+[a-z]+\s+(?:cube|block)\s+at\s+each\s+end\b)"),
     r"\1 and "),
    # "Put the green cube in the middle of a row, with a white cube at each end": the row made, its middle said (the middle
    # had been read as a place on the table)
    (re.compile(rf"(?:^|(?<=[.;:!]\s))(?:put|place|set)\s+the\s+(?P<c>{COLOR_RE})\s+(?P<n>cube|block)\s+in\s+the\s+(?:middle|center|centre)\s+of\s+"
                r"(?:a|the)\s+(?P<s>row|line)\s*,?\s+with\s+(?P<rest>(?:a|an|one)\s+[a-z]+\s+(?:cube|block)\s+at\s+each\s+end)(?=\s*(?:[.;!]|$))"),
     lambda m: f"make a {m.group('s')} with the {m.group('c')} {m.group('n')} in the middle and {m.group('rest')}"),
    # "three white cubes in a row at the back, and three black cubes in a row at the front": two counted groups, each in a
    # structure of its own, two clauses (the second group's count had been read as one cube of the first row); not when
    # the second clause refers back ("... in a row behind them")
    (re.compile(rf"(?<=[a-z])\s*(?:,\s*and|,|\s+and)\s+(?=(?:{COUNT_WORD_RE}|\d+)\s+(?:(?:{COLOR_RE})\s+)?(?:cubes|blocks)\s+in\s+(?:a|one)\s+"
                r"(?:row|line|tower|stack|column|pile)\b(?![^.;!?]*\b(?:it|its|them|they|those|these|both|rest|others?|same)\b))",
                re.IGNORECASE),
     lambda m: "; " if re.search(rf"(?i)(?:^|[:;.!?]\s*|\b(?:put|place|set|arrange|make|build|lay)\s+)(?:{COUNT_WORD_RE}|\d+)\s+(?:(?:{COLOR_RE})\s+)?"
                                 r"(?:cubes|blocks)\s+in\s+(?:a|one)\s+(?:row|line|tower|stack|column|pile)\b[^.;!?,]*$", m.string[:m.start()])
     else m.group(0)),
    # "red at the top and bottom", "red at the bottom and on top": one colour at both ends, said once for two cubes (a colour
    # nobody said had been made up for one end, silently): each end said with its cube
    (re.compile(rf"\b(?P<c>{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?\s+(?:at|on)\s+(?:the\s+(?:very\s+)?)?(?P<e1>top|bottom|base)\s+and\s+"
                r"(?:(?:at|on)\s+)?(?:the\s+(?:very\s+)?)?(?P<e2>top|bottom|base)\b"),
     lambda m: m.group(0) if {m.group("e1"), m.group("e2")} <= {"bottom", "base"} or m.group("e1") == m.group("e2")
     or not re.search(r"\b(?:towers?|stack\w*|columns?)\b", m.string) or re.search(r"\b(?:rows?|lines?|table)\b", m.string)
     else f"{m.group('c')} at the {m.group('e1')} and {m.group('c')} at the {m.group('e2')}"),
    # "put red between blue and green and between yellow and pink": the second between is the same cube's (it had been read
    # of green, silently)
    (re.compile(rf"\b(?P<c>{COLOR_RE})(?P<mid>(?:\s+(?:cube|block|one))?\s+(?:in\s+)?between\s+[^.;!?]*?)\s*,?\s+and\s+(?:also\s+)?(?=between\b)"),
     lambda m: f"{m.group('c')}{m.group('mid')} and {m.group('c')} "),
    # "the purple-coloured patch", "the red coloured cube": the colour (a purple cube had been made up, the patch dropped)
    (re.compile(rf"(?<!\band\s)(?<!,\s)(?<!\bor\s)\b({COLOR_RE})(?:\s*-\s*|\s+)colou?red\s+(?=(?:goal\s+)?(?:patch|pad|mat|tile|square|area|zone)\b)"),
     r"\1 "),  # (of one colour and a patch only: "the red and blue coloured cube" is one cube of two colours, refused)
    # "Put red and yellow on blue": the two cubes named by bare colours on the third, as "the red and yellow cubes on the
    # blue cube" is read (blue at the bottom, the others' order free; it had been ordered as listed, unsaid)
    (re.compile(rf"\b(?P<v>put|place|stack|set)\s+(?P<a>{COLOR_RE})\s+and\s+(?P<b>{COLOR_RE})\s+on(?:\s+top\s+of)?\s+(?P<c>{COLOR_RE})"
                r"(?=\s*(?:[.;!]|$))"),
     lambda m: f"{m.group('v')} the {m.group('a')} and {m.group('b')} cubes on the {m.group('c')} cube"),
    # "next to both the orange cube and the purple cube": next to each of them ("both" had been read as the cubes before it)
    (re.compile(rf"\b(next\s+to|beside|far\s+from|away\s+from|touching)\s+both\s+(?=(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+and\s+"
                rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?|ones?))?\s*(?:[.;!]|$))"), r"\1 "),  # (the sentence ends there: a
    # place or row after it, "... on the yellow patch", "..., in a row", had been read of the last cube alone)
    # "in a line along the front of the table", "... from left to right along the back edge": the line at that side
    (re.compile(r"\balong\s+the\s+(front|back|rear)(?:\s+(?:edge|side))?(?:\s+of\s+the\s+(?:table|workspace))?\b"),
     lambda m: m.group(0) if not re.search(r"\b(?:rows?|lines?|line\s+up|lay|laid|arrange\w*|left\s+to\s+right|right\s+to\s+left)\b", m.string)
     or re.search(r"\b(?:move|moving|slide|sliding|push|pushing|drag|dragging|roll|rolling|go|travel\w*|sweep\w*)\b", m.string)
     else f"at the {m.group(1)} of the table"),  # (a row along the front or back runs left to right, as a row does when no
    # axis is said; along the left side it would run front to back, and a path along an edge is no place: left as written)
    # "a tower of yellow, then green, then blue, counted from the bottom": the direction the list is said in
    (re.compile(r"\bcount(?:ed|ing)\s+(?=from\s+the\s+(?:bottom|top|left|right)\b)"),
     lambda m: m.group(0) if re.search(r"\b(?:first|second|third|fourth|fifth|last|\d+(?:st|nd|rd|th))\b", m.string) else ""),
    # "a row of three that goes blue, gray, pink when you read it from right to left": the direction
    (re.compile(r"\bwhen\s+(?:you\s+|one\s+)?read(?:ing)?\s+(?:it\s+|them\s+)?(?=from\s+(?:the\s+)?(?:right|left|bottom|top)\b)"), "read "),
    # "in a line across the middle of the table": the line in that part of the table
    (re.compile(r"\b(line|row)\s+(?:running\s+|going\s+)?across\s+the\s+(middle|center|centre|front|back)\s+of\s+the\s+table\b"),
     r"\1 in the \2 of the table"),
    # "(their order is up to the policy)": the order left free
    (re.compile(r"\(\s*(?:their|the|its)\s+order\s+(?:is\s+)?(?:up\s+to\s+(?:the\s+)?(?:policy|robot|agent|you|them|the\s+policy)|(?:does\s+not"
                r"|doesn't|does\s+n't)\s+matter|is\s+free|is\s+not\s+important)\s*\)"), "in any order"),
    # "For the poster photo I need ...": what the task is for, before it ('photo' had been read as a picture to look at)
    (re.compile(r"^\s*for\s+(?:the|a|our|my)\s+(?:[a-z\-]+\s+)?(?:photo|picture|photograph|shot|poster|video|figure|slide|demo)\s*,?\s+"
                r"(?=(?:i|we)\s+(?:need|want|would\s+like)\b|(?:please\s+)?(?:put|place|stack|make|build|arrange|set|line)\b)"), ""),
    # "the gray block must be the bottom one": at the bottom (it had been refused as a cube picked by where it stands now)
    (re.compile(r"\b(must|should|has\s+to|needs\s+to|is\s+to)\s+be\s+the\s+(bottom|lowest|base|top|highest|topmost)\s+(?:one|block|cube)\b"
                r"(?!\s+(?:of|in|on|after|when|once|if)\b)(?![^.;]*\band\s+(?:the\s+)?[a-z0-9]+(?:\s+(?:one|block|cube))?\s+the\s+(?:bottom|lowest|base"
                r"|top|highest|topmost)\s+(?:one|block|cube)\b)"),  # not gapped: "..., and X the top one" (read as said)
     lambda m: f"{m.group(1)} be {'at the bottom' if m.group(2) in ('bottom', 'lowest', 'base') else 'on top'}"),
    # "a tower of gray, blue and yellow, gray at the bottom; blue and yellow above it in either order": the tower's other
    # cubes, said again (two more cubes had been made, or the order refused)
    (re.compile(rf"(?:\s*[,;]\s*(?:and\s+)?|\s+and\s+)(?:the\s+)?(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:{COLOR_RE}))*,?\s+and\s+(?:{COLOR_RE}))"
                rf"(?:\s+(?:blocks?|cubes?|ones?))?\s+(?:can\s+|may\s+|should\s+)?(?:go\s+|are\s+|stand\s+|sit\s+)?(?:(?:above|on\s+top\s+of|over|on)"
                rf"\s+(?:it|that|them)\s+)?in\s+(?:any|either)\s+order\b"),
     lambda m: " and the others in any order" if re.search(r"\b(?:at\s+the\s+bottom|on\s+top|at\s+the\s+top)\b", m.string[:m.start()])
     and all(re.search(rf"\b{c}\b", m.string[:m.start()]) for c in re.findall(rf"\b(?:{COLOR_RE})\b", m.group("l"))) else m.group(0)),
    # "the gray block at the bottom, and the blue and yellow blocks go above it in either order": the tower's cubes, its named
    # end and the others free (the order had been read as listed, then refused)
    (re.compile(rf"\b(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:block|cube|one))?(?:\s+(?:must|should|has\s+to|needs\s+to|is\s+to)\s+be)?"
                rf"\s+(?P<r>at\s+the\s+bottom|on\s+top|at\s+the\s+top)\s*[,;]?\s+(?:and\s+)?(?:(?:put|place|stack|set)\s+)?"
                rf"(?:the\s+)?(?P<l>(?:{COLOR_RE})(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE}))*,?\s+and\s+(?:the\s+)?(?:{COLOR_RE}))(?:\s+(?:blocks|cubes|ones))?\s+(?:can\s+|may\s+"
                rf"|should\s+)?(?:go\s+|are\s+|stand\s+|sit\s+)?(?:above|on\s+top\s+of|over|on|below|under|beneath|underneath)\s+(?:it|that|them)\s+"
                rf"in\s+(?:any|either)\s+order\b"),
     lambda m: m.group(0) if "bottom" not in m.group("r") and re.search(r"\b(?:above|on|over)\s+(?:it|that|them)\b", m.group(0))
     or "bottom" in m.group("r") and re.search(r"\b(?:below|under|beneath|underneath)\s+(?:it|that|them)\b", m.group(0)) else
     ("" if re.search(r"\b(?:towers?|stacks?|stacked|stack|columns?)\b", m.string[:m.start()]) else "a tower of ")
     + f"{m.group('a')}, {re.sub(r'(?<![a-z])the ', '', m.group('l'))}, with the {m.group('a')} block {m.group('r')} and the others in "
     "any order" if m.group("a") not in m.group("l") else m.group(0)),
    # "Tower of green, white and red, with red on top. The other two can go either way.": the tower's other cubes free
    (re.compile(r"\s*[.;,]\s*(?:and\s+)?the\s+other\s+(?:two|2|ones|cubes|blocks)(?:\s+(?:cubes|blocks|ones))?\s+(?:can\s+(?:go|be|stand|sit)\s+"
                r"|may\s+(?:go|be|stand|sit)\s+|go\s+|are\s+)?(?:in\s+)?(?:either|any)\s+(?:way|order)(?:\s+(?:round|around))?(?=\s*[.!]?\s*$)"),
     lambda m: " and the others in any order" if re.search(r"\b(?:at\s+the\s+bottom|on\s+top|at\s+the\s+top)\b", m.string[:m.start()])
     and (not re.search(r"\b(?:two|2)\b", m.group(0)) or len(set(re.findall(rf"\b(?:{COLOR_RE})\b", m.string[:m.start()]))) == 3)
     else m.group(0)),
    # "Stack all three of them, black, gray and brown.": the cubes "them" stands for, listed after it (as after a colon)
    (re.compile(rf"\b((?:all\s+)?(?:(?:\d+|two|three|four|five|six)\s+of\s+)?them)\s*[,:]\s+(?=(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?"
                rf"(?:\s*,\s*(?:and\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?|\s+and\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block))?)+"
                r"\s*(?:[.;!]|$))"),
     lambda m: f"{m.group(1)}: " if _them_counted_as_listed(m) else f"{m.group(1)}, "),  # (a count the list does not
    # match: the comma's 'them', refused; "all three of them: black, gray, brown and white" had been a tower of four)
    # "The black cube should finish near the back edge": end up there ('finish' had been read as an action)
    (re.compile(r"\b(should|must|will|has\s+to|needs\s+to|to)\s+finish\s+(?:up\s+)?(?=(?:near|at|in|on|onto|next\s+to|beside|behind|between"
                r"|to\s+the|left|right|in\s+front)\b)"), r"\1 end up "),
    # "Lay out the orange, white and pink cubes side by side, orange on the left end and pink on the right end": a row, its
    # ends said ('next to each other' of three had been refused: which in the middle?)
    (re.compile(rf"\bside\s+by\s+side\b(?=\s*,\s*(?:with\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:on|at)\s+the\s+(?:far\s+)?"
                r"(?:left|right)(?:\s+end)?\b)"), "in a row"),
    # "the black cube is touching the white cube, side by side": next to it, said twice
    (re.compile(rf"\b((?:touching|next\s+to|beside|against)\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?)\s*,?\s*side\s+by\s+side\b"), r"\1"),
    # "a loose heap of the red, yellow and cyan cubes": a pile (every pile is loose: its predicate judges the cubes' spread)
    (re.compile(r"\b(?:loose|messy|untidy|rough|jumbled)\s+(?=(?:pile|heap|bunch|cluster)s?\b)"), ""),
    # "..., then one more green on top": one more green cube, counted against the cubes read (it had been dropped)
    (re.compile(rf"\b(\d+|one|two|three|four|five)\s+more\s+({COLOR_RE})\b(?!\s+(?:cubes?|blocks?|ones?|bricks?|patch))"),
     lambda m: f"{m.group(1)} more {m.group(2)} {'cube' if m.group(1) in ('1', 'one') else 'cubes'}"),
    # "whip up a tower of the pink cube on the yellow cube": build one
    (re.compile(r"\b(?:whip|rustle|knock|cook|throw)\s+(?:up|together)\s+(?=(?:a|an|one|the)\s+(?:tower|stack|row|line|pyramid|wall|circle|grid"
                r"|pile)\b)"), "build "),
    # "the cyan cube goes on the table first, the brown one goes on it": the tower's first cube, at its bottom
    (re.compile(r"\b(goes|go|is|sits|stands|comes)\s+(?:down\s+)?(on|onto)\s+the\s+table\s+first\b(?=\s*,[^.;]*\bon\s+(?:it|top)\b)"),
     r"\1 \2 the table"),
    # "and the gray one finishes the tower", "tops it off", "crowns the stack": the cube on top of it
    (re.compile(r"\b(?:finishes|completes|crowns|caps|tops)\s+(?:(?:it|the\s+(?:tower|stack))(?:\s+off)?|off\s+the\s+(?:tower|stack))\b"
                r"(?=\s*[.;!]?\s*$)"),
     "goes on top"),
    # "in the gap between the blue cube and the yellow cube", "balanced on the red cube", ", whatever arrangement"
    (re.compile(r"\b(?:in|into)\s+the\s+(?:gap|space)\s+between\b"), "between"),
    (re.compile(r"\bbalanced\s+(?=(?:on|onto|atop|upon)\b)"), ""),
    (re.compile(r"\s*,?\s*\b(?:in\s+)?(?:whatever|any|whichever)\s+arrangement(?:\s+(?:you\s+like|is\s+fine))?\b"), " in any order"),
    # "For this trial the red cube should end up on the blue cube": the trial named, no comma after it
    (re.compile(r"^for\s+this\s+(?:trial|run|task|episode|test|eval(?:uation)?|experiment|demo|variant|one)\s+(?=(?:the|a|an)\s|"
                r"(?:put|place|stack|build|make|arrange|set|move|line)\b)"), ""),
    # "blue blue red red", "red blue red blue": a transcript's list of cubes with no commas, a colour
    # said again for each cube; "the red red block" is one cube (a stutter)
    (re.compile(rf"(?P<det>\b(?:the|a|an)\s+)?\b(?P<run>(?:{COLOR_RE})(?:\s+(?:{COLOR_RE}))+)\b(?P<noun>\s+(?:block|cube|one)\b)?"),
     lambda m: (", ".join(m.group("run").split()) if not m.group("det") and not m.group("noun") and len(m.group("run").split()) >= 3
                else m.group(0))  # "line up white gray black": three or more colours, each its cube
     if len(set(m.group("run").split())) == len(m.group("run").split())
     else (m.group("det") + re.sub(rf"\b({COLOR_RE})(?:\s+\1\b)+", r"\1", m.group("run")) + m.group("noun"))
     if m.group("det") and m.group("noun")
     else (m.group("det") or "") + ", ".join(m.group("run").split()) + (m.group("noun") or "")),
    # "in the corner? the back left one", "the corner - the front right one": which corner, said after
    (re.compile(r"\bthe\s+corner\s*(?:[,?:;\-\u2013\u2014]+|\.\.\.)\s*(?:i\s+mean\s+|namely\s+)?the\s+(front|back|rear|far)\s+"
                r"(left|right)\s+(?:one|1|corner)\b"),
     r"the \1 \2 corner"),
    # "LINE front edge: red, red, red": a terse line's place said with no preposition
    (re.compile(r"\b(lines?|rows?)\s+(?=(?:front|back|rear|left|right)\s+(?:edge|side)\b)"),
     r"\1 at the "),
    # "the blue box-shaped block"
    (re.compile(r"\b(?:box|cube|block)[\s-]shaped\s+(?=(?:blocks?|cubes?|bricks?)\b)"),
     ""),
    # "spell out the name EVA"
    (re.compile(r"\b(spell(?:s|ing)?)(?:\s+out)?\s+the\s+(?:name|word)\b"),
     r"\1"),
    # "a long way from the orange block"
    (re.compile(r"\b(?:a\s+)?long\s+way\s+(?:away\s+)?from\b"),
     "far from"),
)
"""Transcripts' and notes' loose phrasings (colours said once per cube, "the corner - the front right one", "box-shaped", "spell out the name", "a long way from")."""

COLOUR_PLURAL_RE = re.compile(rf"\b(?:the\s+)?({'|'.join(c for c in PALETTE if c != 'orange')}|grey)s\b(?!')"
                              r"(?=\s+(?:at|on|go|goes|should|must|are|first|last|together|next|behind|to\s+the|in\s+(?:a|the)\b(?!\s+other)))")
"""A colour said as a plural noun before where it goes ("reds at the bottom", "the blues in a row"): "the red ones"
("oranges" stays a fruit; "reds in one, yellows in the other" stays unread: which tower is which had been lost)."""

ONE_IN_EACH_RE = re.compile(rf"\b(?:2|two)\s+(?P<s>towers|stacks|rows|lines|piles)\s+of\s+(?P<n>\d+|{COUNT_WORD_RE})\s*[-:,;]?\s*"
                            rf"(?:the\s+)?(?P<a>{COLOR_RE})(?:s|\s+(?:ones|cubes|blocks))\s+in\s+one\s*,?\s*(?:and\s+)?(?:the\s+)?"
                            rf"(?P<b>{COLOR_RE})(?:s|\s+(?:ones|cubes|blocks))\s+in\s+the\s+other\b")
"""Two structures of one colour each ("two towers of 2 - reds in one, yellows in the other"): read as "a tower of 2 red
cubes and a tower of 2 yellow cubes" (each tower had mixed the two colours)."""

UP_DOWN_ROLE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "I want wall: down row gray gray gray, up row black black black": a layer said by "down" and "up"
    (re.compile(r"\b(?:down|lower)\s+(?=(?:row|layer|level|tier|course)\b)"),
     "bottom "),
    (re.compile(r"\bup(?:per)?\s+(?=(?:row|layer|level|tier|course)\b)"),
     "top "),
    # "a tower of yellow, blue and cyan - yellow down, cyan up -": an end of a listed tower said by "down" and "up"
    (re.compile(rf"(?<=[,;:(\-]\s)(?P<c>{COLOR_RE})\s+(?P<w>down|up)\b(?=\s*(?:[,;.)\-]|\band\b|$))"),
     lambda m: f"{m.group('c')} {'at the bottom' if m.group('w') == 'down' else 'on top'}"),
    # "with X at the bottom, Y above it and Z on top": the one cube said between the ends by "above it" is the middle (the
    # tower's order had been read X, Z, Y)
    (re.compile(r"(\b(?:at|on)\s+the\s+(?:bottom|base)\s*,\s*(?:and\s+)?(?:then\s+)?[^,;.]{1,40}?)\s+(?:directly\s+|right\s+|just\s+)?"
                r"(?:above|over|on\s+top\s+of|on|upon|atop)\s+(?:it|that(?:\s+one)?)(?=(?P<top>\s*,?\s+(?:and\s+)?(?:then\s+)?[^,;.]{1,40}?\s+"
                r"(?:on\s+top|at\s+the\s+top|on\s+the\s+top)\b))"),
     lambda m: f"{m.group(1)} in the middle" if len(re.findall(rf"\b(?:{COLOR_RE}|letter\s+[a-z]|digit\s+\d|[A-Z]|\d)\b", m.group("top"))) == 1
     else m.group(0)),  # one cube between the middle and the top: four or more cubes leave "above it" as said
)
"""A tower's end or a wall's layer said by "down" and "up" (literal translations: "yellow down, cyan up",
"down row gray gray gray"), and its middle cube by "above it" between its ends; read only in a text that builds a tower or a
wall."""

TOP_DOWN_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Stack red, green, blue from the top down", "Tower (top first): ...": a list from the top
    (re.compile(r"\b(?:from\s+the\s+top(?:\s+down(?:wards?)?)?|from\s+top(?:\s+down(?:wards?)?)?(?!\s+to\b)|top[\s-]+down|top\s+first|starting\s+(?:from|at|with)"
                r"\s+the\s+top)\b(?!\s+(?:of|left|right)\b)"),
     lambda m: m.group(0) if re.search(r"\b(?:second|third|fourth|fifth|\d(?:st|nd|rd|th))\s*(?:one\s+)?$",
                                       m.string[:m.start()]) else "from top to bottom"),
)
""""from the top down", "top first", "alphabetically from top": a list from the top ("second from the top" stays a rank)."""

TOP_FIRST_RE = re.compile(r"\btop\s+(?:to|down\s+to)\s+(?:the\s+)?bottom\b|\bfrom\s+the\s+top\s+down\b")
"""A stack's cubes listed from the top ("from top to bottom: digit 1, digit 2, digit 3"), as :data:`TOP_DOWN_REWRITES` writes it."""

AND_PLACING_CLAUSE_RE = re.compile(r"(?:,\s*|\s+)and\s+(?=(?:please\s+)?(?:put|place|set|move|slide|push|bring|position|lay|stand)\b)")
"""Where ", and put ..." starts a clause of its own ("stack red and blue, and put yellow next to white": white is not the
stack's; :func:`rpg.schema.readers.relational.recognize_relational`)."""

TOP_LIST_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Build a tower: the top is red, then blue, then green": listed from that end (it had been read bottom first)
    (re.compile(rf"\b(?:the\s+)?(top|bottom|base)(?:\s+(?:one|cube|block))?\s+(?:is|:)\s+((?:{COLOR_RE})(?:\s*(?:,\s*(?:and\s+)?(?:then\s+)?"
                rf"|\s+(?:and\s+)?then\s+)(?:{COLOR_RE}))+)\b(?!\s+(?:on|at|in)\b)"),
     lambda m: f"from {'top to bottom' if m.group(1) == 'top' else 'bottom to top'}: {m.group(2)}"),
)
""""the top is red, then blue, then green": listed from that end."""

FAR_APART_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the black cube and the white cube should be far apart": one far from the other
    (re.compile(rf"\b(the\s+(?:{COLOR_RE})\s+(?:block|cube))\s+and\s+(the\s+(?:{COLOR_RE})\s+(?:block|cube))\s+"
                r"((?:should|must|need\s+to|have\s+to)\s+(?:be|end\s+up)|are|end\s+up)\s+far\s+apart\b"),
     r"\1 \3 far from \2"),
    # "keep the orange and blue cubes far apart from each other", "the two red cubes end up far from each other",
    # "placed adjacent to one another": said as the relational reader's "far from each other" / "next to each other"
    # (had been no task found)
    (re.compile(r"\bfar\s+(?:away\s+)?apart(?:\s+(?:from\s+)?(?:each\s+other|one\s+another))?\b|\bfar\s+(?:away\s+)?from\s+(?:each\s+other|one\s+another)\b"),
     "far from each other"),
    (re.compile(r"\badjacent\s+to\s+(?:each\s+other|one\s+another)\b"),
     "next to each other"),
    (re.compile(r"(\d)-(block|cube|layer|level|story|storey|high|tall|wide|long|deep)"),
     r"\1 \2"),
)
""""X and Y should be far apart" (one far from the other), reciprocal "far apart" and "adjacent to one another" said
as the reader's "... each other", and hyphenated sizes ("3-block")."""

RELATION_SIDE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the red cube to the left and the blue cube to the right of the green cube": both sides of the cube said last (the
    # first had been read as the table's left region, silently)
    (re.compile(rf"\bto\s+the\s+(?P<a>left|right)\s+and\s+(?P<b>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+to\s+the\s+(?:left|right)"
                rf"\s+of\s+(?P<c>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?))"),
     lambda m: f"to the {m.group('a')} of {m.group('c')} and {m.group('b')}"),
    # "at top of" ("to the top of the table" is its far side, read below)
    (re.compile(r"\b(?:to|onto)\s+the\s+top\s+of\b(?!\s+the\s+(?:table|workspace|board)\b)|\b(?:at|to|on)\s+top\s+of\b"),
     "on top of"),
    # "to its left": the relation to the cube "it" stands for (resolved like "to the left of it")
    (re.compile(r"\b(?:to|on|at)\s+(its|their)\s+(left|right)(?:\s+(?:hand\s+)?side)?\b"),
     lambda m: f"to the {m.group(2)} of {'it' if m.group(1) == 'its' else 'them'}"),
    # "on the blue block's left": the relation to that cube (it compiled a stack on it)
    (re.compile(rf"\b(?:on|to|at)\s+the\s+((?:{COLOR_RE})\s+(?:block|cube|one))'s\s+(left|right)(?:\s+(?:hand\s+)?side)?\b"),
     r"to the \2 of the \1"),
    (re.compile(rf"\b(?:on|to|at|in)\s+the\s+((?:{COLOR_RE})\s+(?:block|cube|one))'s\s+(front|back|rear)(?:\s+side)?\b"),
     lambda m: f"{'in front of' if m.group(2) == 'front' else 'behind'} the {m.group(1)}"),
    # "the red and green blocks on either side of the blue block": the blue block between them
    (re.compile(rf"\b(put|place|set|move)\s+the\s+({COLOR_RE})\s+and\s+(?:the\s+)?({COLOR_RE})\s+(blocks|cubes)\s+"
                rf"(?:on|at|to)\s+(?:either|each|both|opposite)\s+sides?\s+of\s+the\s+({COLOR_RE})\s+(?:block|cube|one)\b"),
     lambda m: f"{m.group(1)} the {m.group(5)} {m.group(4)[:-1]} between the {m.group(2)} {m.group(4)[:-1]} and "
               f"the {m.group(3)} {m.group(4)[:-1]}"),
    # "put one block on (top of) the other": the two blocks stacked, either on top
    (re.compile(r"\b(put|place|stack|set)\s+one\s+(block|cube)\s+(?:on|onto|upon)\s+(?:top\s+of\s+)?the\s+other(?:\s+one)?\b"),
     r"\1 two \2s on top of each other"),
)
"""A relation said by a cube's side ("to its left", "on the blue block's left", "on either side of", "one on the other")."""

def _each_patch_listed(m: re.Match) -> str:
    """"a pink cube on each of the red, green and blue patches" said cube by cube ("a pink cube on the red patch, another pink
    cube on the green patch and another pink cube on the blue patch"); as written when a patch is listed twice or a cube is
    referred back to (:func:`_refers_back`)."""
    patches = re.findall(rf"\b(?:{COLOR_RE})\b", m.group(3))
    if len(set(patches)) != len(patches) or _refers_back(m):
        return m.group(0)
    cube = f"{m.group(1) + ' ' if m.group(1) else ''}{m.group(2)}"
    each = [f"{cube} on the {p} patch" for p in patches]
    return "a " + ", another ".join(each[:-1]) + " and another " + each[-1]


def _refers_back(m: re.Match) -> bool:
    """Whether the words after a cube said for each of several patches refer back to one of those cubes ("... and put the
    red cube on it", "... the pink cube next to the green cube"): which one is not said, so the words are left as they are
    (to be refused)."""
    after = m.string[m.end():]
    return bool(re.search(r"\b(?:it|its|them|they|those|these|one\s+of\s+them)\b", after) or (
        m.group(1) and re.search(rf"\b{re.escape(m.group(1))}\s+(?:cube|block|one)s?\b", after)))


EDGE_AND_EACH_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "in a row along the back edge[, ...]": at that edge of the table ("along" is otherwise no word of ours)
    (re.compile(r"\balong\s+(?=the\s+(?:(?:far|very)\s+)?(?:front|back|rear|left|right)(?:\s+(?:hand\s+)?(?:side|edge|end))?"
                r"(?:\s+of\s+the\s+(?:table|workspace))?\s*(?:[.!,;]|$))"),
     "at "),
    # "a red tower and a blue tower, each three high": the height reaches each tower
    (re.compile(rf"\b(?:a|one)\s+({COLOR_RE})\s+(tower|stack|column)\s+and\s+(?:a|one|another)\s+({COLOR_RE})\s+(?:tower|stack|column)"
                r",?\s+(?:each|both)\s+(\d+|two|three|four|five|six)\s+(?:(?:blocks?|cubes?|levels?|stor(?:y|ey|ies|eys))\s+)?(?:high|tall)\b"),
     r"a \2 of \4 \1 blocks and a \2 of \4 \3 blocks"),
    # "one cube on each of the red, green and blue patches": a cube on each patch listed (three to six)
    (re.compile(rf"\b(?:a|one|1)\s+(?:({COLOR_RE})\s+)?(block|cube)\s+(?:on|onto)\s+each\s+(?:of\s+)?(?:the\s+)?"
                rf"((?:{COLOR_RE})(?:\s+patch)?(?:\s*,\s*(?:the\s+)?(?:{COLOR_RE})(?:\s+patch)?){{1,4}}\s*,?\s+and\s+(?:the\s+)?(?:{COLOR_RE})"
                rf"\s+(?:goal\s+)?patch(?:es)?)\b(?!\s*,?\s*(?:and\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+patch|\s*[.,]|\s+and))"),
     lambda m: _each_patch_listed(m)),
    # "a green cube on each of the two patches, the red patch and the blue patch", "... on each of the red and blue
    # patches": the two patches named, a cube of that colour on each (refused before: how many patches, or each said twice)
    (re.compile(rf"\b(?:a|one|1)\s+(?:({COLOR_RE})\s+)?(block|cube)\s+(?:on|onto)\s+(?:each|both)\s+(?:of\s+)?(?:the\s+)?"
                rf"(?:(?:2|two)\s+(?:goal\s+)?patches\s*(?:[,:]|\s-|\u2014)\s*(?:the\s+)?({COLOR_RE})(?:\s+patch)?\s+and\s+(?:the\s+)?({COLOR_RE})\s+patch"
                rf"|({COLOR_RE})\s+(?:patch\s+)?and\s+(?:the\s+)?({COLOR_RE})\s+(?:goal\s+)?patch(?:es)?)\b(?!\s*,?\s*(?:and\s+)?(?:the\s+)?(?:{COLOR_RE})(?:\s+patch|\s*[.,]|\s+and))"),
     lambda m: (lambda c, p1, p2: m.group(0) if p1 == p2 or _refers_back(m) else
                f"a {c}{m.group(2)} on the {p1} patch and another {c}{m.group(2)} on the {p2} patch")(
         f"{m.group(1)} " if m.group(1) else "", m.group(3) or m.group(5), m.group(4) or m.group(6))),
    # "place one cube on each patch: red cube on the blue patch, blue cube on the red patch": the heading said again by
    # the assignments after it, each to another patch (refused before as each said twice)
    (re.compile(rf"\b(?:place|put|set)\s+(?:one|a|1)\s+(?:cube|block)\s+on\s+each\s+(?:goal\s+)?patch\s*:\s*"
                rf"(?=(?:the\s+)?(?:{COLOR_RE})\s+(?:cube|block)\s+(?:on|onto)\s+the\s+(?P<p1>{COLOR_RE})\s+(?:goal\s+)?patch\s*(?:,|and)\s*"
                rf"(?:and\s+)?(?:the\s+)?(?:{COLOR_RE})\s+(?:cube|block)\s+(?:on|onto)\s+the\s+(?P<p2>{COLOR_RE})\s+(?:goal\s+)?patch\s*[.!]?\s*$)"),
     lambda m: m.group(0) if m.group("p1") == m.group("p2") else "put the "),
    # "put the red cube and the blue cube next to the cyan cube", "bring both purple cubes next to the cyan cube": the
    # relation said of each cube (refused before: one of them had no place, or one purple cube was read)
    (re.compile(rf"\b(put|place|move|set|bring|position|get)\s+(?:(?:both\s+)?(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+and\s+"
                rf"(?:the\s+)?(?P<b>{COLOR_RE})\s+(?:cubes?|blocks?|ones?)|(?:both\s+(?:the\s+)?|the\s+(?:2|two)\s+|(?:2|two)\s+)(?P<c>{COLOR_RE})\s+(?:cubes|blocks))"
                r"\s+(?P<rel>next\s+to|beside|(?:to\s+the\s+)?(?:left|right)\s+of|behind|in\s+front\s+of|far\s+(?:away\s+)?from|near)\s+"
                rf"(?:the\s+)?(?P<o>{COLOR_RE})(?:\s+(?:cube|block|one))?(?=\s*(?:[.!;]|$))"),
     lambda m: (f"{m.group(1)} the {m.group('a')} cube {m.group('rel')} the {m.group('o')} cube and the {m.group('b')} cube "
                f"{m.group('rel')} the {m.group('o')} cube") if m.group("a") else
               (f"{m.group(1)} a {m.group('c')} cube {m.group('rel')} the {m.group('o')} cube and another {m.group('c')} cube "
                f"{m.group('rel')} the {m.group('o')} cube")),
)
""""along the back edge" (at that edge), "each three high" (the height reaches each tower), "a green cube on each of
the red and blue patches" (one on each patch named) and "the red and the blue cube next to the cyan cube" (each next to
it)."""

PATCH_CENTRE_AND_START_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "into the middle of the black patch": on it (a cube on a patch is on it wherever it stands there)
    (re.compile(rf"\b(?:in|into|onto|on|at|to)\s+the\s+(?:middle|center|centre)\s+of\s+the\s+((?:{COLOR_RE})\s+(?:goal\s+|target\s+)?patch)\b"),
     r"on the \1"),
    # "starting from the left with blue": blue the first from the left
    (re.compile(rf"\b(starting|beginning)\s+(?:from|at)\s+the\s+(left|right|front|back)(?:\s+end)?\s*,?\s*with\s+(?:the\s+)?({COLOR_RE})\b"),
     r"\1 with \3 on the \2"),
)
""""into the middle of the black patch" (on it) and "starting from the left with blue" (blue first from the left)."""

def _robot_side(m: re.Match, side: str) -> str:
    """A place said from the robot, as a side of the table; said of an unnamed cube just before it ("on the cube near the
    robot") or as a superlative ("the cube nearest the robot"), the words as written (a cube picked by where it is,
    refused)."""
    before = m.string[:m.start()]
    noun = re.search(r"\b(?P<det>the|a|an|one)\s+(?:(?P<c>[a-z]+)\s+)?(?:cubes?|blocks?|ones?)\s+(?:that\s+is\s+|which\s+is\s+|that's\s+)?$",
                     before)
    if noun and (re.match(r"(?:near|clos|far)\w*est\b", m.group(0)) or noun.group("c") not in COLORS):
        return m.group(0)  # "the cube nearest the robot", "on the cube near the robot": a cube picked by where it is (refused)
    return side


BARE_ORDER_RE = re.compile(
    r"(?i)^(?:(?:place|put|arrange|set|lay|order|line\s+up)\s+(?:the\s+|all\s+(?:the\s+)?)?(?:cubes|blocks)\s+)?(?:from\s+)?"
    r"(?P<d>left\s+to\s+right|right\s+to\s+left|front\s+to\s+back|back\s+to\s+front)\s*:\s*(?=\S)")
"""An order along an axis said alone ("Left to right: red, green, blue."): a row as a task (:data:`ROW_SAID_BY_ORDER_REWRITES`),
a new order of the task's cubes as a steering edit (:func:`rpg.steer.edits.looks_standalone`)."""

_ROW_ROLE_WORDS = {"left": 0, "leftmost": 0, "middle": 1, "center": 1, "centre": 1, "right": 2, "rightmost": 2}


def _row_roles(m: re.Match) -> str:
    said = {_ROW_ROLE_WORDS[m.group(f"r{i}").lower()]: m.group(f"c{i}") for i in (1, 2, 3)}
    if sorted(said) != [0, 1, 2]:
        return m.group(0)  # a role said twice: left as written (refused)
    return "a row from left to right: " + ", ".join(said[k] for k in (0, 1, 2))


_TOWER_ROLE_RANK = {"top": 2, "upper": 2, "middle": 1, "centre": 1, "center": 1, "bottom": 0, "lower": 0, "base": 0}
_TOWER_ROLE = (r"(?:the\s+)?(?P<r{i}>top|upper|middle|cent(?:er|re)|bottom|lower|base)(?:\s+(?:one|cube|block|layer|level))?"
               r"\s*[:=]\s*(?:the\s+|a\s+)?(?P<c{i}>" + COLOR_RE + r")(?:\s+(?:one|cube|block))?")
BARE_TOWER_ROLES_RE = re.compile(r"(?i)^\s*" + _TOWER_ROLE.format(i=1) + r"\s*[,;.]\s*(?:and\s+)?" + _TOWER_ROLE.format(i=2)
                                 + r"(?:\s*[,;.]\s*(?:and\s+)?" + _TOWER_ROLE.format(i=3) + r")?\s*[.!]?\s*$")
"""A whole text that gives two or three cubes the top, middle and bottom of something and says nothing else ("Top: red.
Middle: green. Bottom: blue.", "Bottom: blue, top: red"): a tower (:func:`bare_tower_roles`; no task had been found)."""


def bare_tower_roles(text: str) -> str:
    """``text`` said as a tower from its bottom when it is only a tower's roles (:data:`BARE_TOWER_ROLES_RE`): each role
    once, a top and a bottom among them (a middle only with both); as it is otherwise."""
    m = BARE_TOWER_ROLES_RE.match(text)
    if m is None:
        return text
    said = [(_TOWER_ROLE_RANK[m.group(f"r{i}").lower()], m.group(f"c{i}")) for i in (1, 2, 3) if m.group(f"r{i}")]
    ranks = sorted(r for r, _ in said)
    if ranks not in ([0, 2], [0, 1, 2]):
        return text  # a role said twice, or no top or bottom: left as written (refused)
    return "build a tower from bottom to top: " + ", ".join(c for _, c in sorted(said)) + "."


def _two_corners(m: re.Match) -> str:
    """"put one blue cube in each of the two back corners" -> "put a blue cube in the back left corner and a blue cube in
    the back right corner"."""
    side = m.group("s")
    corners = [f"{side} left", f"{side} right"] if side in ("back", "front") else [f"back {side}", f"front {side}"]
    cube = f"a {m.group('c') or ''}{m.group('n')}"  # (no colour: two cubes of one colour, either in either corner)
    return f"{m.group('v')} " + " and ".join(f"{cube} in the {c} corner" for c in corners)


_CORNER_ITEM = r"(?:(?:to|in|at|into)\s+(?:the\s+)?)?(?:front|back|rear)[\s-]+(?:left|right)(?:\s+corner)?"
"""A cube's corner in a list of corners ("back left", "to back-left", "in the front right corner")."""


def _corners_listed(m: re.Match) -> str:
    """"one cube per corner: blue back left, red back right, ..." -> each cube put in its corner; unchanged when a corner
    is said twice ("one per corner" of two cubes in one: the readers refuse it)."""
    items = [(c.lower(), fb.lower().replace("rear", "back"), lr.lower())
             for c, fb, lr in re.findall(rf"(?i)\b({COLOR_RE})\s+(?:(?:to|in|at|into)\s+(?:the\s+)?)?(front|back|rear)[\s-]+(left|right)",
                                         m.group("list"))]
    if len({(fb, lr) for _, fb, lr in items}) != len(items) or (re.search(r"(?i)\beach\b", m.group(0)) and len(items) != 4):
        return m.group(0)  # (a corner said twice, or "each corner" with a corner left out: as written, refused)
    return "put " + ", ".join(f"the {c} cube in the {fb} {lr} corner" for c, fb, lr in items)


def _towers_listed(m: re.Match) -> str:
    """"Three towers, each two cubes tall: red on blue, green on yellow, white on black." -> the towers themselves, when
    as many are listed as counted, each as tall as said (otherwise unchanged: the readers decide)."""
    towers = [t for t in re.split(r"\s*(?:,\s*(?:and\s+)?|;\s*|\s+and\s+)", m.group("list").strip()) if t]
    mixed = [t for t in towers if re.search(r"\bon\b", t) and re.search(r"\bunder\b", t)]
    if mixed:
        return m.group(0)  # "red on blue under green": which way up? (the readers decide)
    # "red under blue" -> "blue on red": each tower as "on" from its top
    towers = [" on ".join(reversed(re.split(r"\s+under\s+", t))) if re.search(r"\bunder\b", t) else t for t in towers]
    want = int(NUMBER_WORDS.get(m.group("n").lower(), m.group("n")))
    height = m.group("h") or m.group("h2")
    tall = height and int(NUMBER_WORDS.get(height.lower(), height))
    colors = re.findall(rf"\b(?:{COLOR_RE})\b", m.group("list"))
    if len(towers) != want or any(tall and len(re.findall(r"\bon\b", t)) != tall - 1 for t in towers) \
            or len(set(colors)) != len(colors):  # a colour said twice: which cube is which is the towers' own reading
        return m.group(0)
    verb = m.group("v") or ("" if m.string[:m.start()].strip(" ,;:") else "put")  # "I want three towers: ...": the want kept
    return f"{verb} ".lstrip() + ", ".join(towers[:-1]) + " and " + towers[-1]


_ROW_ROLE = (r"(?:the\s+)?(?:far\s+|very\s+)?(?P<r{i}>left(?:most)?|middle|cent(?:er|re)|right(?:most)?)(?:\s+(?:one|cube|block))?"
             r"(?:\s*[:=]\s*|\s+)(?P<c{i}>" + COLOR_RE + r")")

ROW_SAID_BY_ORDER_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Left to right: red, green, blue.", "Place the cubes from front to back: cyan, brown, purple.": an order along an
    # axis with nothing else to be in it is a row (it had found no task)
    (BARE_ORDER_RE,
     lambda m: m.group(0) if re.search(rf"\b(?:{STRUCTURE_NOUN}|rows?|lines?|piles?|walls?|spell\w*|sort\w*|patch\w*)\b", m.string)
     else f"a row from {m.group('d')}: "),
    # "leftmost: orange, middle: gray, rightmost: pink", "row: far left brown, middle gray, far right green": a row by its
    # three places
    (re.compile(r"(?i)^(?:(?:a\s+)?(?:row|line)\s*:\s*)?" + _ROW_ROLE.format(i=1) + r"\s*[,;.]\s*" + _ROW_ROLE.format(i=2) + r"\s*[,;.]\s*" + _ROW_ROLE.format(i=3)
                + r"(?=\s*[.!]?\s*$)"),
     _row_roles),
    # "put one blue cube in each of the two back corners": one in each of those two corners
    (re.compile(rf"(?i)\b(?P<v>put|place|set)\s+(?:one|a|1)\s+(?P<c>(?:{COLOR_RE})\s+)?(?P<n>cube|block)\s+(?:in|into|at)\s+each\s+of\s+the\s+"
                r"(?:two|2)\s+(?P<s>back|front|left|right)\s+corners\b(?=\s*(?:[.!;]|$))"),  # (what follows may refer to them)
     _two_corners),
    # "Make two towers: one of three green cubes on the left, one of three red cubes on the right": each said in turn
    # ("make two separate piles: one with the brown and pink blocks, one with the white and cyan blocks")
    (re.compile(r"(?i)\b(?P<v>make|build|create|form|stack|line\s+up)\s+(?:two|2)\s+(?:separate\s+)?(?P<s>tower|stack|row|line|pile)s\s*:"
                r"\s*one\s+(?:of|with)\s+(?P<a>[^,;:.]+?)\s*[,;]\s*(?:and\s+)?(?:one|the\s+other)\s+(?:of|with)\s+(?P<b>[^,;:.]+?)(?=\s*(?:[.!]|$))"),
     lambda m: f"{m.group('v')} a {m.group('s')} of {m.group('a')} and a {m.group('s')} of {m.group('b')}"),
    # "Three towers, each two cubes tall: red on blue, green on yellow, white on black.": each tower said in turn
    # ("two towers of two: red under blue, green under yellow": each tower said from its bottom, "under")
    (re.compile(rf"(?i)(?:\b(?P<v>make|build|create|form|stack)\s+)?\b(?P<n>\d+|{COUNT_WORD_RE})\s+(?:towers|stacks)"
                rf"(?:\s*,?\s*each\s+(?:of\s+)?(?P<h>\d+|{COUNT_WORD_RE})\s+(?:cubes?\s+|blocks?\s+)?(?:tall|high)"
                rf"|\s+of\s+(?P<h2>\d+|{COUNT_WORD_RE})(?:\s+(?:cubes|blocks))?(?:\s+each)?)?\s*:\s*"
                rf"(?P<list>(?:{COLOR_RE})(?:\s+(?:on|under)\s+(?:{COLOR_RE}))+(?:\s*(?:,\s*(?:and\s+)?|;\s*|\s+and\s+)(?:{COLOR_RE})"
                rf"(?:\s+(?:on|under)\s+(?:{COLOR_RE}))+)+)(?=\s*(?:[.!]|$))"),
     _towers_listed),
    # "Corners: red back-left, blue back-right, ...", "one cube per corner: blue back left, ...": each cube's corner
    # ("put one cube in each corner of the table: red front left, ...", "one cube is moved to each corner: red to back-left, ...")
    (re.compile(rf"(?i)(?:\b(?:put\s+)?(?:one|a|1)\s+(?:cube|block)\s+(?:is\s+|goes\s+)?(?:moved\s+|placed\s+|put\s+)?(?:per|in\s+each"
                r"|for\s+each|at\s+each|to\s+each|into\s+each)\s+corner(?:\s+of\s+the\s+(?:table|workspace))?|(?:^|(?<=[.;]\s))(?:the\s+)?"
                rf"corners?)\s*[:\-\u2014]\s*(?P<list>(?:{COLOR_RE})\s+{_CORNER_ITEM}(?:\s*(?:[,;]\s*(?:and\s+)?"
                rf"|\s+and\s+)(?:{COLOR_RE})\s+{_CORNER_ITEM})+)"),
     _corners_listed),
    # "so the colours run gray, red, blue going downward": the order from the top
    (re.compile(rf"(?i)(?:,?\s*so\s+(?:that\s+)?(?:the\s+)?colou?rs\s+(?:run|go|read)\s+|\b)(?P<list>(?:{COLOR_RE})(?:\s*,\s*(?:and\s+)?(?:{COLOR_RE}))+"
                rf"(?:\s*,?\s+and\s+(?:{COLOR_RE}))?)\s*,?\s+going\s+(?P<d>down(?:ward|wards)?|up(?:ward|wards)?)\b"),
     lambda m: (" from top to bottom: " if m.group("d").lower().startswith("down") else " from bottom to top: ") + m.group("list")),
    # "put any block on top of the red one": a cube of any colour (one more, whichever)
    (re.compile(r"(?i)\b(put|place|set|stack)\s+any\s+(cube|block)\b(?=\s+(?:on|onto|next\s+to|beside|behind|in\s+front\s+of|to\s+the))"),
     r"\1 a \2"),
    # "a tower of number blocks with 1 at the bottom, then 2, then 3 on top": the labels listed from the bottom (the
    # digits had been read as counts)
    (re.compile(r"(?i)\b(?P<s>tower|stack)\s+of\s+(?P<k>digit|number|numbered|letter|lettered)\s+(?P<n>blocks|cubes)\s*(?:,\s*)?(?:with\s+|:\s*)"
                r"(?P<a>(?-i:[A-Z]|\d))\s+(?:at|on)\s+the\s+(?:bottom|base)\s*,?\s+(?P<mid>(?:then\s+(?-i:[A-Z]|\d)\s*,?\s+)*)"
                r"(?:then\s+|and\s+)?(?P<z>(?-i:[A-Z]|\d))\s+(?:on\s+top|at\s+the\s+top)\b"),
     lambda m: f"{m.group('s')} of {m.group('k')} {m.group('n')} from bottom to top: "
     + ", ".join([m.group("a"), *re.findall(r"[A-Z]|\d", m.group("mid")), m.group("z")])),
    # "the letters B, E, D spelled out left to right", "letters S, T, O, P, left to right": label cubes listed in their
    # order along a direction, with no structure said (it had found no task): spelled, or a row
    (re.compile(r"(?:^|(?<=[.;:]\s))(?i:(?:goal\s*:\s*)?(?:the\s+)?(?:letters?|digits?|numbers?)(?:\s+(?:cubes|blocks))?)\s+"
                r"(?P<l>[A-Z0-9](?:\s*,\s*(?:and\s+)?[A-Z0-9])+)\s*,?\s+(?P<sp>(?i:(?:spelled|spelt|written)(?:\s+out)?\s+))?"
                r"(?P<d>(?i:(?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left)))\b"),
     lambda m: f"spell {m.group('l')} {m.group('d')}" if m.group("sp")
     else f"a row of the letter cubes {m.group('l')} {m.group('d') if m.group('d').lower().startswith('from') else 'from ' + m.group('d')}"),
)
"""A row said by its order or its places alone, corners said two at a time, two structures said after a colon, a cube of
any colour."""


_AXIS_END_MARKS = {
    "front": r"(?:(?:near(?:est)?|clos(?:e|er|est))(?:(?:\s+to)?\s+(?:the\s+|your\s+)?robot)?|at\s+the\s+(?:very\s+)?front|in\s+front)",
    "back": r"(?:far(?:\s+away)?(?:\s+from\s+(?:the\s+|your\s+)?robot)?|at\s+the\s+(?:very\s+)?back|in\s+the\s+back)",
}
"""Words that mark a cube as the one at the front or the back end of a list ("blue nearest the robot", "red farthest away";
"farthest" is read "far")."""


def _axis_ends(m: re.Match) -> str:
    """"from front to back: blue nearest the robot, then yellow, then red farthest away" -> "from front to back: blue, then
    yellow, then red": the marks on the list's first and last cubes say again which end each is (they had been read as a
    place of the table, and the first cube left out of the line); a mark that names the other end stays (refused)."""
    start, end, items = m.group("a"), m.group("b"), m.group("list")
    cube = rf"(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?"
    listed = re.fullmatch(rf"(?P<first>{cube})(?:\s+(?:is\s+)?{_AXIS_END_MARKS[start]})?(?P<mid>(?:\s*,\s*(?:and\s+)?then\s+{cube})*)"
                          rf"\s*,?\s*(?:and\s+)?(?P<last>(?:then\s+)?{cube})(?:\s+(?:is\s+)?{_AXIS_END_MARKS[end]})?", items)
    if listed is None:  # more said in the list ("and red farthest from the yellow cube"): as written, for the readers
        return m.group(0)
    return f"from {start} to {end}: {listed.group('first')}{listed.group('mid')}, {listed.group('last')}"



def _chain_before(m: re.Match) -> bool:
    """Whether the sentence before ``m`` stacks one named cube on another ("put red on blue, then the green one at the very
    top"): "at the top" then tops that tower (without one it is a place of the table: "red in the corner and blue at the
    very top" had made a tower)."""
    start = max((x.end() for x in re.finditer(r"[.!?;]\s", m.string[:m.start()])), default=0)
    return bool(re.search(rf"\b(?:{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:sits|goes|is|stands|rests|lies)\s+)?"
                          rf"(?:on|onto|upon|atop|on\s+top\s+of)\s+(?:the\s+)?(?:{COLOR_RE})\b(?!\s+(?:goal\s+)?patch)",
                          m.string[start:m.start()]))


def _one_chain(m: re.Match) -> bool:
    """Whether the placements said in the text of ``m`` (a chain ending "... and white goes on top") make one tower whose
    top is the cube ``c1`` (two cubes on one, or two chains, leave "on top" unplaced: "green and red sit on blue and white
    goes on top")."""
    pairs = re.findall(rf"\b({COLOR_RE})(?:\s+(?:cube|block))?\s+(?:(?:sits|goes|is|stands|rests|lies)\s+)?on\s+(?:top\s+of\s+)?(?:the\s+)?"
                       rf"({COLOR_RE})\b", m.string[:m.start("c3")])
    if re.search(rf"(?<!on\s)(?<!onto\s)(?<!of\s)\b(?:{COLOR_RE})\s+and\s+(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:cubes?|blocks?))?\s+"
                 r"(?:(?:sit|stand|rest|go|are|both)\s+)?on\b",
                 m.string):
        return False
    under, over = [b for _, b in pairs], [a for a, _ in pairs]
    return len(set(under)) == len(under) and m["c1"] not in under and len(set(under) - set(over)) == 1

LANDMARK_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "to the back edge of the table, far from the robot": the robot's words say that side again (the side had been
    # read twice, refused)
    # ("at the back of the table, away from the robot", "at the back (far from the robot)": the same)
    (re.compile(r"\b((?:the\s+)?back(?:\s+(?:edge|side|half|end|part|row))?(?:\s+of\s+the\s+(?:table|workspace))?)\s*(?:,|\()\s*"
                r"(?:far(?:thest)?\s+(?:away\s+)?|away\s+)from\s+(?:the\s+|your\s+)?robot\b\)?"
                r"|\b((?:the\s+)?front(?:\s+(?:edge|side|half|end|part|row))?(?:\s+of\s+the\s+(?:table|workspace))?)\s*(?:,|\()\s*"
                r"(?:near(?:est)?|clos(?:e|est))(?:\s+to)?\s+(?:the\s+|your\s+)?robot\b\)?"),
     lambda m: m.group(1) or m.group(2)),
    # "near the robot, at the front edge of the table": the same, the robot's words first
    (re.compile(r"\b(?:(?:near(?:est)?|clos(?:e|est))(?:\s+to)?|next\s+to)\s+(?:the\s+|your\s+)?robot\s*,\s*(?=(?:at|on|along|to|in)\s+(?:the\s+)?"
                r"front\s+(?:edge|side|half|end|part|row)\b)"
                r"|\b(?:far(?:thest)?\s+(?:away\s+)?|away\s+)from\s+(?:the\s+|your\s+)?robot\s*,\s*(?=(?:at|on|along|to|in)\s+(?:the\s+)?"
                r"back\s+(?:edge|side|half|end|part|row)\b)"), ""),
    # "from front to back: blue nearest the robot, then yellow, then red farthest away": the ends' marks said again
    (re.compile(r"\bfrom\s+(?P<a>front|back)\s+to\s+(?P<b>front|back)\s*:\s*(?P<list>[^.;:]*?)(?=\s*(?:[.;!]|$))"),
     _axis_ends),
    # the robot as a landmark: its side of the table is the front, its left and right the table's (rpg's frame,
    # :mod:`rpg.domain.constants`) ("in front of the robot", "toward the robot", "on the robot's left": a region of the
    # table; the words had been dropped with "robot's", ignorable, and a row or two cubes read anywhere)
    (re.compile(r"\b(?:in\s+front\s+of|(?:near(?:est)?|clos(?:e|er|est))(?:\s+to)?|right\s+by|towards?)\s+(?:the\s+|your\s+)?robot(?:'s\s+base)?\b"),
     lambda m: _robot_side(m, "at the front of the table")),
    (re.compile(r"\b(?:far(?:thest)?\s+(?:away\s+)?from|away\s+from)\s+(?:the\s+|your\s+)?robot(?:'s\s+base)?\b"),
     lambda m: _robot_side(m, "at the back of the table")),
    (re.compile(r"\b(?:on|to|at|in)\s+the\s+robot's\s+(left|right)(?:[\s-]*hand)?(?:\s+side)?\b(?!\s+of\b)"),
     lambda m: _robot_side(m, f"on the {m.group(1)} side of the table")),
    (re.compile(r"\b(?:to\s+the\s+|on\s+the\s+)?(left|right)(?:[\s-]*hand\s+side)?\s+of\s+the\s+robot(?:'s\s+base)?\b"),
     lambda m: _robot_side(m, f"on the {m.group(1)} side of the table")),
    (re.compile(r"\btoward(?:s)?\b"),
     "to"),
    (re.compile(r"\b(?:inside|within)\s+of\s+(?=the\b)"),  # "inside of the orange patch"
     "in "),
    # "line up 4 cubes in the back row of the table": the table's back (a row of the table is its side)
    (re.compile(r"\b(?:in|along|on|at)\s+the\s+(front|back|rear)\s+(?:row|line|strip)\s+of\s+the\s+(?:table|workspace)\b"),
     r"at the \1 of the table"),
    # "put green cube to yellow cube left side", "to the blue block's right": a side of the landmark cube
    (re.compile(rf"\b(?:to|on|at)\s+(the\s+(?:{COLOR_RE})\s+(?:block|cube|one))(?:'s)?\s+(?:the\s+)?(left|right)(?:\s*-?\s*hand)?"
                rf"(?:\s+side)?\b(?!\s+(?:of|corner|edge|half|part)\b)"),
     r"to the \2 of \1"),
    # "move the red block to the front of the green patch": in front of that cube or patch
    (re.compile(rf"\bto\s+the\s+front\s+of\s+(?=the\s+(?:{COLOR_RE})\s+(?:goal\s+|target\s+)?(?:block|cube|patch|one)\b)"),
     "in front of "),
    # "put a red block on the red block": two red cubes (the other had been the same cube, a contradiction)
    # (alone: in a sequence of placements "the blue block" is one placed before, :mod:`rpg.schema.clauses`)
    (re.compile(rf"\b(a|an)\s+({COLOR_RE})\s+(block|cube)\s+((?:on(?:to)?(?:\s+top\s+of)?|next\s+to|beside)\s+)the\s+\2\s+(block|cube)\b"
                r"(?=\s*[.!]?\s*$)"),
     r"\1 \2 \3 \4another \2 \5"),
    # "push the blue block to the red block": moved up to it, i.e. next to it (Language-Table, Demo2Code)
    (re.compile(rf"\b(push|move|slide|put|bring|shift)\s+the\s+((?:{COLOR_RE})\s+(?:block|cube))\s+to\s+"
                rf"(the\s+(?:{COLOR_RE})\s+(?:block|cube))\b(?!\s+(?:of|patch)\b)"),
     r"\1 the \2 next to \3"),
    (re.compile(r"\b(?:so\s+(?:that\s+)?it(?:'s|\s+is)\s+)?touch(?:ing|es)?\b"),
     "next to"),
    (re.compile(r"\bfollowed\s+by\b|\b(?:topped|crowned|capped)\s+(?:off\s+)?(?:with|by)\b"),
     "then"),
    # "... green sits on blue and white crowns the tower": that cube on top (the verb had left white out)
    (re.compile(r"\b(?:crowns|caps|tops(?:\s+off)?)\s+(?:it|them|the\s+(?:pyramid|tower|stack|structure|pile|whole\s+thing))(?:\s+off)?\b"),
     "goes on top"),
    # "... and green goes on the very top", "then the green one at the very top": the top of the tower the chain built
    # ("at the top" of the table, a side, or a layer keeps its words)
    (re.compile(rf"\b(?:(?<=\bthen\s)|(?<=\band\s)|(?<=,\s))(?P<c>(?:the\s+)?(?:{COLOR_RE})(?:\s+(?:one|cube|block))?)\s+"
                r"(?P<v>(?:goes|sits|is|stands|rests|lies|comes)\s+)?(?:on|at)\s+the\s+(?:very\s+)?top\b"
                r"(?!\s*(?:of|left|right|edge|side|corner|row|layer|level|half|end|part|shelf|-)\b)"
                # (not with another place after it: "..., then green at the very top, next to yellow")
                r"(?!\s*,?\s*(?:and\s+)?(?:next|left|right|behind|in|on|at|near|far|close|beside|between|under|by|away|toward|towards"
                r"|along|inside|outside|opposite|against|touching)\b)"),
     lambda m: f"{m['c']} {m['v'] or ''}on top" if _chain_before(m) else m.group(0)),
    # "... green sits on blue and white goes on top": on the chain's top cube (it had gone on the base)
    (re.compile(rf"\b(?P<c1>{COLOR_RE})(?:\s+(?:cube|block))?\s+(?P<v>(?:sits|goes|is|stands|rests|lies)\s+)?on\s+(?:top\s+of\s+)?(?:the\s+)?"
                rf"(?P<c2>{COLOR_RE})(?:\s+(?:cube|block))?\s*,?\s+and\s+(?:the\s+)?(?P<c3>{COLOR_RE})(?:\s+(?:cube|block))?\s+"
                r"(?:(?:goes|sits|is|stands|rests|lies|comes)\s+)?(?:on|at)\s+(?:the\s+)?top\b(?!\s+(?:of|in|on|at)\b)"),
     lambda m: f"{m['c1']} {m['v'] or ''}on {m['c2']} and {m['c3']} {m['v'] or ''}on {m['c1']}" if _one_chain(m) else m.group(0)),
    # "and a white one topping it", "a white cube crowning the pyramid": that cube on top
    (re.compile(r"\b(?:topping|crowning|capping)\s+(?:it|them|the\s+(?:pyramid|tower|stack|structure|pile|whole\s+thing))(?:\s+off)?\b"),
     "on top"),
    # "the purple block has to finish on top of the white block": where it ends up; "... and leave it there": the same end
    (re.compile(r"\b(?:finish|finishes|finished|finishing)\s+(?=(?:on|in|at|next\s+to|beside|behind|under|below|above|inside|left|right"
                r"|to\s+the|in\s+front)\b)"), "end up "),
    (re.compile(r"\s*,?\s+and\s+(?:then\s+)?leave\s+(?:it|them)\s+(?:there|that\s+way|like\s+that)(?=\s*(?:[.!;]|$))"), ""),
    # "first the orange, after the purple, last the pink": a list said by its steps (a learner's "after" for "then")
    (re.compile(rf"\bfirst\s+(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s*,\s*(?:after|then|next|afterwards)\s+(?:the\s+)?"
                rf"({COLOR_RE})(?:\s+(?:cube|block|one))?\s*,?\s+(?:and\s+)?(?:last|lastly|finally|at\s+last)\s+(?:the\s+)?({COLOR_RE})"
                r"(?:\s+(?:cube|block|one))?\b"),
     r"\1, \2, \3 in that order"),
    # "and finish with a white cube at the top": the last of a sequence
    # only after a sequence ("add yellow, then orange, and finish with white")
    (re.compile(r"\b(?:(and)\s+)?(?:finish|end)(?:\s+(?:it|them|the\s+(?:tower|stack|row|line)))?(?:\s+off)?\s+with\b"),
     lambda m: f"{m.group(1) or ''} then".strip() if re.search(r"\b(?:then|add)\b", m.string[:m.start()])
     else m.group(0)),
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+of\s+the\s+(?=\w+\s+(?:blocks|cubes|boxes)\b)"),
     r"\1 "),
    (re.compile(r"\b(?:to|on|at)\s+the\s+(left|right)(?:[\s-]+hand)?\s+side\s+of\b(?!\s+the\s+(?:table|workspace)\b)"),
     r"to the \1 of"),
    # "left from the black cube", "to the right side from the white cube", "in front to the blue one": a learner's
    # preposition for the side of a cube (a side of the table is not said so)
    (re.compile(rf"\b(?:(?:to|on|at)\s+(?:the\s+)?)?(left|right)(?:\s+side)?\s+from\s+(?=(?:the\s+)?(?:(?:{COLOR_RE})\b|it\b))"),
     r"to the \1 of "),
    (re.compile(rf"\bin\s+(?:the\s+)?front\s+(?:side\s+)?(?:to|of)\s+(?=(?:the\s+)?(?:(?:{COLOR_RE})\b|it\b))"), "in front of "),
    # "put the blue cube left of the tower of two pink cubes": the tower described where it is the landmark, built first
    (re.compile(rf"\b(?P<v>put|place|move|set)\s+(?P<x>the\s+(?:{COLOR_RE})\s+(?:cube|block))\s+(?P<rel>(?:to\s+the\s+)?(?:left|right)\s+of"
                rf"|in\s+front\s+of|behind|next\s+to|beside)\s+(?:the|a)\s+(?P<s>tower|stack|row|line)\s+of\s+(?P<of>(?:\d+|two|three|four|five)"
                rf"\s+(?:{COLOR_RE})\s+(?:cubes|blocks))(?=\s*(?:[.!;]|$))"),  # (of cubes of one colour: a listed tower related by its base
    # would keep its list's order, which the words leave free)
     r"build a \g<s> of \g<of> and \g<v> \g<x> \g<rel> it"),
    # "get the black cube into the right half": put it there
    (re.compile(r"\bget\s+(?=(?:the|a|an|both|all)\s+(?:[a-z]+\s+){0,3}?(?:cube|block)s?\s+(?:in|into|onto|on|to|next\s+to|beside|behind"
                r"|under|over|in\s+front|left|right|@region)\b)"), "put "),
    # "Keep the green cube besides the white cube.": beside it ("besides that, ..." adds, and stays)
    (re.compile(rf"\bbesides\s+(?=the\s+(?:{COLOR_RE})\s+(?:cube|block|one)\b)"), "beside "),
    # "put the red cube and the blue cube next to each other in the front half": the pair's place, both cubes in it (a
    # cube picked by where it stands now is no task's)
    # ("next to the blue cube on the left" may be the blue cube's left: only a half or a side "of the table" is the pair's)
    (re.compile(r"\b((?:next\s+to|beside)\s+(?:each\s+other|one\s+another)|side\s+by\s+side)\s+(?=(?:in|at|on)\s+the\s+"
                r"(?:front|back|rear|left|right)(?:\s+(?:half|side|part))?(?:\s+of\s+the\s+(?:table|workspace))?\s*(?:[.,;!]|$))"
                rf"|\b((?:next\s+to|beside)\s+the\s+(?:{COLOR_RE})\s+(?:cube|block))\s+(?=(?:in|at|on)\s+the\s+(?:front|back|rear|left|right)"
                r"(?:\s+half|(?:\s+(?:side|part|edge))?\s+of\s+the\s+(?:table|workspace))\s*(?:[.,;!]|$))"),
     lambda m: f"{m.group(1) or m.group(2)}, both "),
    (re.compile(r"\b((?:in|at|on)\s+the\s+(?:front|back|rear|left|right)(?:\s+(?:half|side|part))?(?:\s+of\s+the\s+(?:table|workspace))?)"
                r"\s*,?\s+(next\s+to\s+(?:each\s+other|one\s+another)|side\s+by\s+side|beside\s+(?:each\s+other|one\s+another))"
                r"(?=\s*(?:[.,;!]|$))"),
     r"\2, both \1"),
    # "with 3 as the leftmost" ("leftmost" read "left"): the cube at that end of the row
    (re.compile(r"\bas\s+the\s+(left|right)(?:\s+(?:one|cube|block|end))?(?=\s*(?:[,.;!]|$|and\b))"), r"on the far \1"),
    (re.compile(r"\bon\s+top\s+(?=the\b)"),
     "on top of "),
    # "red cube go to back": to the back of the table (an article dropped)
    (re.compile(r"\b(go|goes|move|moves|moved|put|placed|set)\s+to\s+(back|front)(?=\s*(?:[.,;!]|$))"),
     r"\1 to the \2"),
    # "cyan cube put in front green cube", "in front the green cube": in front of it (an 'of' dropped)
    (re.compile(rf"\bin\s+front\s+(?=(?:the\s+)?(?:{COLOR_RE})\s+(?:cube|block|one)\b)"),
     "in front of "),
    # "stack of pink cubes, three pink, on the right": the count said after the cubes, with their colour again
    (re.compile(rf"\b(?P<c>{COLOR_RE})\s+(?P<n>cubes|blocks)\s*,\s*(?P<k>\d+|{COUNT_WORD_RE})\s+(?P=c)(?:\s+(?:cubes|blocks|ones))?"
                r"(?=\s*(?:[,.;!?]|$))"),
     lambda m: f"{NUMBER_WORDS.get(m.group('k'), m.group('k'))} {m.group('c')} {m.group('n')}"),
    # "a row of white cubes, three of them": the count said after the cubes
    (re.compile(rf"\b((?:{COLOR_RE})\s+)?(cubes|blocks)\s*,?\s+(\d+|{COUNT_WORD_RE})\s+of\s+them\b"
                r"(?=\s*(?:[,.;!?]|$|(?:at|in|on|along|across|please)\b))"),
     lambda m: f"{NUMBER_WORDS.get(m.group(3), m.group(3))} {m.group(1) or ''}{m.group(2)}"),
)
"""A landmark cube's sides and approaches ("to yellow cube left side", "push the blue block to the red block", "finish with", "three of them")."""

PLEASE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "two stacks please: ..."
    (re.compile(r"\s+please(?=\s*[:,;.!])"),
     ""),
)
""""two stacks please: ...": the request's "please" before punctuation."""

STRUCTURE_NOUN_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "two separate towers, one of two red cubes and one of two blue cubes": several structures are apart anyway
    (re.compile(rf"\b(\d+|{COUNT_WORD_RE})\s+(?:separate|distinct|different|individual|independent)\s+(?=(?:towers|stacks|rows|lines|piles|columns)\b)"),
     r"\1 "),
    # "two rows: three red cubes at the front and three blue cubes at the back", "build two rows, one of three red cubes
    # and one of three blue cubes": a row of each (refused before: no structure read); two rows, two groups said
    (re.compile(rf"^\s*(?:(?:make|build|form|create)\s+)?(2|two)\s+(rows|lines)\s*(?::\s*(?:one\s+of\s+)?|,\s*one\s+of)\s*"
                rf"(?P<a>\d+|{COUNT_WORD_RE})\s+(?P<ca>{COLOR_RE})\s+(?:cubes|blocks)(?P<pa>\s+(?:at|in|along)\s+the\s+(?:front|back|left|right)(?:\s+(?:side|edge))?)?"
                rf"(?:\s*,?\s+and\s+|\s*[,;]\s*)(?:one\s+of\s+)?(?P<b>\d+|{COUNT_WORD_RE})\s+(?P<cb>{COLOR_RE})\s+(?:cubes|blocks)"
                rf"(?P<pb>\s+(?:at|in|along)\s+the\s+(?:front|back|left|right)(?:\s+(?:side|edge))?)?(?=\s*[.!]?\s*$)"),
     lambda m: f"make a {m.group(2)[:-1]} of {m.group('a')} {m.group('ca')} cubes{m.group('pa') or ''} and a {m.group(2)[:-1]} of "
               f"{m.group('b')} {m.group('cb')} cubes{m.group('pb') or ''}"),
    (re.compile(r"\bvertical (?:column|stack)\b|\bpillar\b"),
     "tower"),
    # "a column of three cubes going from front to back" lies along the table
    (re.compile(r"\bcolumn(s?)\b(?=.*\b(?:front\s+to\s+back|back\s+to\s+front|left\s+to\s+right|right\s+to\s+left)\b)"),
     r"line\1"),
    # "in a column"; "2 columns" stay grids
    (re.compile(r"\b(a|one|single|the same)\s+column\b"),
     r"\1 tower"),
    # "the target square patch": one patch
    (re.compile(r"\b(?:goal|target)\s+(?:area|zone|region|spot|location|position|point|pad|mat|marker|square|tile|field)(s?)"
                r"(?:\s+patch(?:es)?)?\b"),
     r"goal patch\1"),
    (re.compile(rf"\b({COLOR_RE})\s+(?:(?:goal|target)\s+)?(?:pad|mat|marker|zone|area|region|tile|field)(s?)\b"),
     r"\1 patch\2"),
    # "onto the yellow square": a square a cube is put on is a patch ("build a red square" stays a structure)
    (re.compile(rf"\b(on|onto|into|in|to)\s+the\s+({COLOR_RE})\s+square\b"),
     r"\1 the \2 patch"),
    # "onto the blue target" ("the target is a two-high tower": what the goal is, no patch)
    (re.compile(r"\btarget(s?)\b(?!\s+(?:goal\s+)?patch)(?!\s+(?:is|should\s+be|will\s+be)\s+(?:an?|one|\d+)\s)"),
     r"patch\1"),
    # "pick and place a block on ..."
    (re.compile(r"\bpick(?:\s+up)?\s+and\s+(place|put|set|drop)\b"),
     r"\1"),
    (re.compile(r"\b(?:pick up|grab|take|lift|get|pick)\s+(the\s+(?:[a-z0-9']+\s+){0,4}?(?:block|cube|box|one))(?:\s+up)?"
                r"(?:,?\s*and\s+(?:then\s+)?|,?\s*then\s+|,\s*)(place|put|set|stack|move|drop|lay)\s+it\b"),
     r"\2 \1"),
    (re.compile(r"\bside by side\b"),
     "next to each other"),
    # "Lay the blocks out left to right as orange, orange, blue": a row said by its direction
    (re.compile(r"\blay\s+(?:(the\s+(?:blocks|cubes))\s+out|out\s+(the\s+(?:blocks|cubes)))(?=\s+(?:from\s+)?(?:left\s+to\s+right|right\s+to\s+left)\b)"),
     lambda m: f"line up {m.group(1) or m.group(2)}"),
)
"""Structure and patch nouns said otherwise ("a column", "the target", "pick and place", "lay out ... left to right")."""

MAP_WORD_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"\b(the\s+)?(?:top|upper)[\s-]+(left|right)\b(?!\s+of\b)(?=\s+(?:corner|edge|side)\b|\s*(?:[.,;!]|$))"),
     r"\1back \2"),
    (re.compile(r"\b(the\s+)?(?:bottom|lower)[\s-]+(left|right)\b(?!\s+of\b)(?=\s+(?:corner|edge|side)\b|\s*(?:[.,;!]|$))"),
     r"\1front \2"),
    # "push the pink block to the top of the table" (Language-Table's map words): the far side, the back
    (re.compile(r"\bthe\s+(top|upper|bottom|lower)\s+(?:(edge|side|half|part|end)\s+)?of\s+the\s+(?=(?:table|workspace|board)\b)"),
     lambda m: f"the {'back' if m.group(1) in ('top', 'upper') else 'front'} {m.group(2) or ''} of the ".replace("  ", " ")),
)
"""Language-Table's map words ("the top left corner", "the top of the table"): the table's back and front."""

def _one_noun(m: re.Match) -> str:
    """The noun "one" stands for in "the yellow one": a patch where the same place word last named a patch ("the red block
    on the blue patch and the green block on the yellow one": the yellow patch, which had become a block), else a block."""
    before = m.string[:m.start()]
    place = re.search(r"\b(on|onto|in|into|to)\s+the\s+$", before)
    if place:
        said = re.findall(rf"\b(?:on|onto|in|into|to)\s+the\s+(?:{COLOR_RE})\s+(?:goal\s+)?(patch|pad|mat|block|cube)\b", before)
        if said and said[-1] in ("patch", "pad", "mat"):
            return "patch"
    return "block"


LABEL_CUBE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "stack the letter A on the letter B": those are cubes
    (re.compile(r"\b(?:(\w+)\s+)?((?:the|a|an)\s+(?:letter|digit|number)\s+'?[a-z0-9]'?)(?=\s|[.,;!]|$)(?!\s+(?:block|cube|box))"),
     lambda m: m.group(0) if m.group(1) in ("with", "showing", "labeled", "labelled", "marked", "bearing")
     else m.group(0) + " block"),
    (re.compile(rf"\b({COLOR_RE})\s+one(s?)\b"),
     lambda m: f"{m.group(1)} {_one_noun(m)}{'s' if m.group(2) else ''}"),
)
"""Label cubes named without their noun ("the letter A") and "red ones": cubes."""

SPELLING_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"\bgrey\b"),
     "gray"),
    (re.compile(r"(\d)-(block|cube|layer|level|story|storey|high|tall|tier|wide|long|deep)"),
     r"\1 \2"),
)
"""Last spellings ("grey", "3-block")."""

DIRECTION_SAID_RE = re.compile(r"\b(?:left\s+to\s+right|right\s+to\s+left|front\s+to\s+back|back\s+to\s+front|bottom\s+to\s+top"
                               r"|top\s+to\s+bottom)\b|\bfrom\s+the\s+(?:left|right|front|back|bottom|top)\b(?:\s+\w+){0,4}?\s+to\s+the\s+"
                               r"(?:left|right|front|back|bottom|top)\b")
"""A direction a list runs in ("left to right", "from the front of the table to the back"): where one is said, "first"
and "last" name the list's ends."""

_ROW_ROLE_BE = r"(?:\s+(?:one|cube|block))?\s*(?:[:=]|\s(?:is|should\s+be|must\s+be)\s)?\s*"
def _pair_row_side(m: re.Match) -> str:
    """"with X on the left/right" for a side relation of the two cubes of a row of two (:data:`ROW_ROLE_REWRITES`); the
    relation as said where the text names other colours than those two, or either more than once."""
    said = [c.lower() for c in re.findall(rf"(?i)\b(?:{COLOR_RE})\b", m.string)]
    if sorted(set(said)) != sorted({m.group("a").lower(), m.group("b").lower()}) or len(said) != 4 or m.group("a") == m.group("b"):
        return m.group(0)
    return f"{m.group('pre')}with the {m.group('a')} cube on the {m.group('s')}"


def _end_and_the_rest(m: re.Match) -> str:
    """A row of ``n`` cubes said as one cube at an end and the other ``n - 1`` of one colour (:data:`ROW_ROLE_REWRITES`: "a
    row of five cubes: a pink one at the far left, the other four gray") as its order from left to right; as said where
    the counts do not add up."""
    n = count_word(m.group("n"))
    k = count_word(m.group("k")) if m.group("k") else n - 1
    if k != n - 1 or not 2 <= n <= 10:
        return m.group(0)
    rest = [m.group("y") or m.group("y2")] * k
    order = [m.group("x"), *rest] if m.group("s").lower() == "left" else [*rest, m.group("x")]
    return f"{m.group('head')}from left to right: {', '.join(order)}"


ROW_ROLE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "Make a row of five cubes: a pink one at the far left, the other four gray.": that cube at its end and the rest (four
    # gray had been read as one)
    (re.compile(rf"(?i)(?P<head>\b(?:row|line)\s+of\s+(?P<n>\d+|{COUNT_WORD_RE})\s+(?:cubes|blocks)\s*:\s*)(?:a|an|the|one)\s+(?P<x>{COLOR_RE})"
                rf"\s+(?:one|cube|block)\s+(?:(?:is|goes|sits)\s+)?(?:at|on)\s+the\s+(?:far\s+|very\s+)?(?P<s>left|right)(?:\s+end)?\s*(?:,|;|and)\s*(?:and\s+)?"
                rf"(?:(?:the\s+)?(?:other|remaining)\s+(?P<k>\d+|{COUNT_WORD_RE})|the\s+rest(?:\s+of\s+them)?)\s+(?:(?:ones|cubes|blocks)\s+)?"
                rf"(?:(?:are|all)\s+)*(?:(?P<y>{COLOR_RE})|(?P<y2>{COLOR_RE}))(?:\s+(?:ones|cubes|blocks))?(?=\s*(?:[.;!]|$))"),
     _end_and_the_rest),
    # "arrange red and blue cubes in a row, red at left of blue": the row of the two, red on its left (the row had no part
    # in the relation read); only a row of those two cubes, each said twice (as a cube of the row and in the relation)
    (re.compile(rf"(?i)(?P<pre>,\s*|\s)(?:with\s+)?(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:(?:is|goes|sits|stands)\s+)?"
                rf"(?:at\s+|to\s+the\s+|on\s+the\s+)?(?P<s>left|right)\s+of\s+(?:the\s+)?(?P<b>{COLOR_RE})(?:\s+(?:cube|block|one))?"
                r"(?=\s*(?:[.;!]|$))"),
     _pair_row_side),
    # "red cube at leftmost, blue cube at rightmost, yellow cube in middle" (articles dropped): at the row's ends, in its middle
    (re.compile(r"\b(at|on|in)\s+(left|right|middle)(?=\s*(?:[,.;!]|$)|\s+and\b)"), r"\1 the \2"),
    # "row-3: leftmost=cyan, middle=pink, rightmost=brown", "the left one is red, the middle blue and the right one green":
    # the row's order from that side ("left" had been read as a cube picked by where it stands now)
    (re.compile(rf"\b(?:the\s+)?(?P<a>left|right)(?:most)?{_ROW_ROLE_BE}(?P<c1>{COLOR_RE})\s*[,;]\s*(?:the\s+)?(?:middle|center|centre)"
                rf"{_ROW_ROLE_BE}(?P<c2>{COLOR_RE})\s*[,;]?\s*(?:and\s+)?(?:the\s+)?(?P<b>left|right)(?:most)?{_ROW_ROLE_BE}(?P<c3>{COLOR_RE})\b"),
     lambda m: m.group(0) if m.group("a") == m.group("b") else
     f"from {m.group('a')} to {m.group('b')}: {m.group('c1')}, {m.group('c2')}, {m.group('c3')}"),
    # "the leftmost cube should be purple, then orange, with the rightmost being cyan", "leftmost purple, then orange,
    # rightmost cyan": the row's order from that side, the cubes after "then" between its ends
    (re.compile(rf"\b(?:the\s+)?(?P<a>left|right)(?:most)?{_ROW_ROLE_BE}(?P<c1>{COLOR_RE})(?P<mid>(?:\s*[,;]?\s*(?:and\s+)?then\s+(?:{COLOR_RE}))+)"
                rf"\s*[,;]?\s*(?:and\s+|with\s+)?(?:the\s+)?(?P<b>left|right)(?:most)?(?:\s+(?:one|cube|block))?\s*(?:[:=]|\s(?:is|should\s+be"
                rf"|must\s+be|being)\s)?\s*(?P<cn>{COLOR_RE})\b"),
     lambda m: m.group(0) if m.group("a") == m.group("b") else
     f"from {m.group('a')} to {m.group('b')}: " + ", ".join([m.group("c1"), *re.findall(rf"\b(?:{COLOR_RE})\b", m.group("mid")), m.group("cn")])),
    # "row of 3 going left to right: red first, green middle, blue last": the list in its said order (where a direction is
    # said: with none, "first" and "last" name no end, and the words are left to be refused)
    # ("green first, then white, then black last": any number between)
    (re.compile(rf"\b(?P<c1>{COLOR_RE})\s+first\b(?P<mid>(?:\s*[,;]?\s*(?:and\s+)?(?:then\s+)?(?:{COLOR_RE})"
                r"(?:\s+(?:in\s+the\s+)?(?:middle|second|next|third))?(?=\s*[,;]|\s+(?:and|then)\b))*)"
                rf"\s*[,;]?\s*(?:and\s+)?(?:then\s+)?(?P<cn>{COLOR_RE})\s+last\b"),
     lambda m: ", ".join([m.group("c1"), *re.findall(rf"\b(?:{COLOR_RE})\b", m.group("mid")), m.group("cn")])
     if DIRECTION_SAID_RE.search(m.string) else m.group(0)),
)
"""A row said role by role, its ends by side or by first and last: the order listed."""

WALL_ROW_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the bottom row is four orange cubes and the top row is four red cubes", "with a bottom row of 3 brown cubes",
    # "bottom is three brown cubes and the top is three orange": each layer's count and colour (the count had been lost
    # and a wall two wide made up)
    (re.compile(rf"\b(?:with\s+)?(?:an?\s+|the\s+)?(?P<where>bottom|top|lower|upper)(?:\s+(?:row|layer|level|tier|course))?\s*"
                rf"(?:is|are|of|has|:|=)\s*(?:made\s+of\s+)?(?P<n>\d+|{COUNT_WORD_RE})\s+(?P<c>{COLOR_RE})(?:\s+(?:cubes|blocks))?\b"),
     lambda m: f"{NUMBER_WORDS.get(m.group('n'), m.group('n'))} {m.group('c')} cubes "
     + ("on the bottom" if m.group("where") in ("bottom", "lower") else "on top")),
    # "a wall of three green blocks (in one layer) with three orange blocks on top of them": two courses, the first at the
    # bottom (read as a wall 2 wide and 2 high)
    (re.compile(rf"\bwall\s+of\s+(?P<n>\d+|{COUNT_WORD_RE})\s+(?P<c>{COLOR_RE})\s+(?:cubes|blocks)(?:\s+(?:in|as)\s+(?:one|1|a|a\s+single)\s+"
                rf"(?:layer|row|course|level|line|tier))?\s*,?\s+(?:with|and)\s+(?P<n2>\d+|{COUNT_WORD_RE})\s+"
                rf"(?P<c2>{COLOR_RE})\s+(?:cubes|blocks)\s+(?:on\s+top(?:\s+of\s+(?:them|those|it))?|above\s+(?:them|those))\b"),
     lambda m: f"wall with {NUMBER_WORDS.get(m.group('n'), m.group('n'))} {m.group('c')} cubes on the bottom and "
               f"{NUMBER_WORDS.get(m.group('n2'), m.group('n2'))} {m.group('c2')} cubes on top"),
    # "a wall two rows high, each row three green blocks wide": every row that wide and of that colour (a second row of
    # another colour had been made up)
    (re.compile(rf"\s*,?\s*(?:with\s+)?each\s+(?:row|layer|level|tier|course)\s+(?:is\s+|has\s+|of\s+)?(?P<n>\d+|{COUNT_WORD_RE})\s+(?:(?P<c>{COLOR_RE})\s+)?"
                r"(?:cubes|blocks)(?:\s+wide|\s+across|\s+long)?\b"),  # (no colour: "each row" asks no colour of a row)
     lambda m: f" with {NUMBER_WORDS.get(m.group('n'), m.group('n'))} wide" + (f", all {m.group('c')}" if m.group("c") else "")),
)
"""A wall's layers said row by row with their counts: "N c cubes on the bottom", which the wall reader reads."""

HEADING_SENTENCE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "build a pyramid. Three cubes on the bottom, two in the middle and one on top": the sentence after a structure
    # named alone says its parts, as after a colon ("two in the middle" had been read as the table's centre)
    (re.compile(rf"\b((?:build|make|do)\s+(?:me\s+|us\s+)?(?:an?|one)\s+(?:[a-z]+\s+)?(?:pyramid|wall|tower|stack|row|line|grid))"
                rf"\s*[.?!]\s+(?=(?:\d+|{COUNT_WORD_RE})\s)"),
     r"\1: "),
)
"""A structure named in a sentence of its own, its parts counted in the next: one description."""

_LABEL_LIST = r"[A-Z0-9](?:\s*,\s*(?:and\s+)?[A-Z0-9]|\s+and\s+[A-Z0-9])+"


REARRANGED_RE = re.compile(rf"(?P<first>{_LABEL_LIST})\s+(?:(?:re)?(?:arranged|sorted|ordered|placed|put)\s+)?so\s+(?:that\s+)?"
                           rf"(?:they|it)\s+(?:go|are|end\s+up|sit|stand|run|come)\s+(?:in\s+the\s+order\s+)?(?P<then>{_LABEL_LIST})")
"""Labels listed as they start and as they end ("the number cubes 5, 2, 8 rearranged so they go 2, 5, 8 from left
to right"): the end order alone (:func:`rpg.schema.reading.rearranged`; the start order had been read as the goal's)."""


READ_FROM_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"(?i)\b(?:when|as|if)\s+(read|viewed|seen)\s+(?=from\b|left|right|top|bottom)"), r"\1 "),
    # "Two orange cubes -> the white patch.", "cube 5 -> red patch": an arrow to a patch, said as "on"
    (re.compile(rf"(?i)\s*(?:->|=>|\u2192)\s*(?=(?:the\s+|a\s+)?(?:{COLOR_RE})\s+(?:goal\s+)?patch\b)"), " on "),
    # "Swap things around so the black cube is on the white patch and the white cube is on the black patch": the end said
    # in full after "so" (the swap had been refused as a reference to the current scene)
    (re.compile(r"(?i)^\s*(?:please\s+)?(?:swap|switch|exchange|trade)\s+(?:things|them|the\s+(?:two\s+)?(?:cubes|blocks)|everything|stuff)"
                r"(?:\s+(?:around|round|over))?\s*,?\s+so\s+(?:that\s+)?(?=the\s)"), ""),
)
""""when read from left", "as seen from the top": the reading direction, said without its clause; an arrow to a patch;
an exchange whose end is said in full after "so": that end."""

LABEL_NOUN_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the cube with the M", "the block with the 4 on it": the cube labelled so
    (re.compile(r"\b([Tt]he|[Aa]n?)\s+(block|cube)\s+(?:with|bearing|showing|that\s+(?:has|shows))\s+(?:the\s+|an?\s+)?"
                r"(?:(?:letter|digit|number)\s+)?'?([A-Z]|\d)'?(?:\s+on\s+it)?\b(?!'|\s*(?:[x\u00d7+\-=*]|\w+\s+(?:blocks?|cubes?)\b))"),
     lambda m: f"{m.group(1)} {'letter' if m.group(3).isalpha() else 'digit'} {m.group(3)} {m.group(2)}"),
    # "block 4", "cube labelled B", "digit cube 3": a label after its cube's noun ("I" as a pronoun stays)
    (re.compile(r"\b(?:(?:[Ll]etter|[Dd]igit|[Nn]umber)\s+)?([Bb]lock|[Cc]ube)\s+(?:(?:number|labell?ed|marked)\s+)?([A-Z]|\d)\b(?!\s*(?:[x\u00d7+\-=*]|blocks?|cubes?))"
                rf"(?!\s+(?:{COLOR_RE})\s+(?:blocks?|cubes?)\b)"  # ("Block 3 red cubes on ...": a count of cubes, no label)
                r"(?<!\bI(?='[a-z]|\s+(?:[a-z]+ed|[a-z]+ing|am|have|had|want|need|would|will|just|think|said|mean|like|told|see|saw|look|can)\b))"),
     lambda m: f"{'letter' if m.group(2).isalpha() else 'digit'} {m.group(2)} {m.group(1).lower()}"),  # ("Block 4 on ...")
    # "put cubes 3 and 4 next to each other": two label cubes, as "cube 3" is one (two coloured cubes had been made up); a
    # colour before them ("red cubes A and B") is left as said
    (re.compile(r"(?<![\w-])(?:[Tt]he\s+)?(?:cubes|blocks)\s+([A-Z]|\d)\s+and\s+([A-Z]|\d)\s+(next\s+to|beside)\s+(?:each\s+other|one\s+another)\b"),
     lambda m: m.group(0) if re.search(rf"\b(?:{COLOR_RE}|letter|digit|number|label(?:led|ed)?)\s*$", m.string[:m.start()], re.I)
     else f"the {'letter' if m.group(1).isalpha() else 'digit'} {m.group(1)} cube {m.group(3)} the "
          f"{'letter' if m.group(2).isalpha() else 'digit'} {m.group(2)} cube"),
    # "the letter cubes A and B next to each other": the one next to the other (two coloured cubes had been made)
    (re.compile(r"\b(?:[Tt]he\s+)?([Ll]etter|[Dd]igit|[Nn]umber)\s+(?:cubes|blocks)\s+([A-Z]|\d)\s+and\s+([A-Z]|\d)\s+(next\s+to|beside)\s+"
                r"(?:each\s+other|one\s+another)\b"),
     lambda m: f"the {'digit' if m.group(1).lower() == 'number' else m.group(1).lower()} {m.group(2)} cube {m.group(4)} the "
               f"{'digit' if m.group(1).lower() == 'number' else m.group(1).lower()} {m.group(3)} cube"),
)
"""A label cube named with its noun first ("the cube with the M", "block 4"): "the letter M cube"; two said next to each
other."""

LABEL_ARTICLE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the A block", "The K block goes ..." (at a sentence's start, "The A block" had lost its label: 'A' read as an article)
    (re.compile(r"\b([Tt]he|a|an|An)\s+([A-Z])\s+([Bb]lock|[Cc]ube)\b"), r"\1 letter \2 \3"),
    (re.compile(r"\b([Tt]he)\s+(\d)\s+([Bb]lock|[Cc]ube)\b(?!s)"), r"\1 digit \2 \3"),  # "the 3 cube"
)
"""A label between an article and a cube's noun ("the A block", "the 3 cube"): a letter or digit cube."""

_TOWER_PART = {"middle": "middle", "top": "top", "highest": "top", "bottom": "bottom", "base": "bottom", "lowest": "bottom"}


def _tower_parts_said(m: re.Match) -> bool:
    """Whether a text that opens with one place of a tower ("The middle cube of the tower is pink; gray is at the base and
    white at the top") goes on to say the tower's other places, and nothing else: each place once, each a colour of its own,
    the middle between both ends (a tower of three). Otherwise it is left as it is, to be refused."""
    rest = m.string[m.end():].lower()
    first = re.match(rf"\s*(?:is|should\s+be|must\s+be)\s+(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s*[;,.]\s*", rest)
    if not first:
        return False
    ends = re.fullmatch(rf"(?:and\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+|sits\s+)?(?:at|on)\s+(?:the\s+)?"
                        rf"(base|bottom|top)(?:\s*(?:,|;|and)\s*(?:and\s+)?(?:the\s+)?({COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+"
                        rf"|sits\s+)?(?:at|on)\s+(?:the\s+)?(base|bottom|top))?\s*[.!]?\s*", rest[first.end():])
    if not ends:
        return False
    colours = [first.group(1), ends.group(1)] + ([ends.group(3)] if ends.group(3) else [])
    places = [_TOWER_PART[m.group(1).lower()], _TOWER_PART[ends.group(2)]] + ([_TOWER_PART[ends.group(4)]] if ends.group(4) else [])
    return len(set(colours)) == len(colours) and len(set(places)) == len(places) and (
        places[0] != "middle" or {"top", "bottom"} <= set(places))


TOWER_BETWEEN_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "The middle cube of the tower is pink; gray is at the base and white at the top": the tower the text goes on to
    # describe, said as "the tower's middle cube" (it had been refused as a tower nobody described); only where the text
    # gives a second place of the tower to another cube
    (re.compile(r"(?i)^\s*the\s+(middle|top|bottom|base|lowest|highest)\s+(cube|block|one)?\s*of\s+the\s+(tower|stack)\s+(?=(?:is|should\s+be|must\s+be)\s+"
                r"(?:the\s+)?[a-z]+(?:\s+(?:cube|block|one))?\s*[;,.]\s*(?:and\s+)?[a-z]+\s+(?:is\s+|goes\s+|sits\s+)?(?:at|on)\s+(?:the\s+)?(?:base|bottom|top)\b)"),
     lambda m: f"the {m.group(3)}'s {m.group(1)} {m.group(2) or 'cube'} " if _tower_parts_said(m) else m.group(0)),
    # "the cyan cube is sandwiched between them", "with the blue one squeezed in the middle": the middle said plainly
    (re.compile(r"\b(?:wedged|squeezed|sandwiched|tucked|nestled)\s+(?=(?:in\s+)?between\s+(?:them|those\s+two|the\s+two)\b"
                r"|in\s+the\s+middle\b)"), ""),
    (re.compile(r"\b(?:goes\s+|is\s+|sits\s+|stands\s+)?(?:(?:wedged|squeezed|sandwiched|tucked|nestled)\s+)?in\s+between\b"
                r"(?!\s+(?:the|them|those|these|of|a|an|it|each)\b)"),
     "in the middle"),  # ("yellow wedged in between")
    # "a tower with cyan at the bottom and red at the top, with the blue cube between them", "..., one gray block between
    # them": its middle
    # ("purple is at the bottom and green is between them": the same, said as a state)
    (re.compile(rf"(?:(?<=\bwith\s)|(?<=,\sand\s)|(?<=,\s)|(?<=\sand\s))(?:1\s+|one\s+)?((?:the\s+|an?\s+)?(?:{COLOR_RE})(?:\s+(?:cube|block|one))?)\s+"
                r"(?:(?:is|goes|sits|stands)\s+)?(?:in\s+)?between\s+(?:them|those\s+two|the\s+two)\b"
                rf"(?=\s*[.!]?\s*$)"),
     r"\1 in the middle"),
)
"""In a tower, "the green one goes in between" (a middle left unnamed): in the middle."""


def _tower_and_more(m: re.Match) -> str:
    up = m.group("end") in ("bottom", "base")
    if up != (m.group("dir") in ("on", "on top of", "above")):
        return m.group(0)  # "red at the bottom and two more under it": a contradiction, left to the readers
    n = int(NUMBER_WORDS.get(m.group("n"), m.group("n")))
    return f"{m.group('s')} of {n + 1} cubes with the {m.group('c')} cube at the {'bottom' if up else 'top'}"


TOWER_MORE_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    # "the top block of the tower should be green and the bottom one cyan, three blocks total": the goal's tower
    # described, not one the speaker sees (it had been refused as a reference); only where the text begins so
    (re.compile(r"^(?:the\s+)?(top|bottom|base)(?:\s+(?:block|cube|one))?\s+of\s+the\s+(tower|stack)\s+(?=(?:(?:should|must|has\s+to|needs\s+to|will)"
                r"\s+be|is)\b)"),
     lambda m: m.group(0) if re.search(r"\b(?:top|highest)\b" if m.group(1) == "top" else r"\b(?:bottom|base|lowest)\b",
                                       m.string[m.end():]) else f"in a {m.group(2)}, the {m.group(1)} block "),  # (that end said
    # again of another cube: refused, not read as a middle)
    # "a tower with the red cube at the bottom and two more cubes (of any colour) on it": a tower of three, red at the
    # bottom, the others free (the two had been read as more red cubes)
    (re.compile(rf"\b(?P<s>tower|stack)\s*(?::\s*|\s+with\s+)(?:the\s+|a\s+)?(?P<c>{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on|as)\s+"
                rf"(?:the\s+)?(?P<end>bottom|base|top)\s*,?\s+(?:and|with|plus)\s+(?P<n>\d+|{COUNT_WORD_RE})\s+(?:more|other|further|additional)\s+"
                r"(?:cubes|blocks|ones)(?:\s+of\s+any\s+colou?rs?)?\s+(?P<dir>on\s+top\s+of|on|above|under(?:neath)?|below|beneath)"
                r"(?:\s+(?:it|that))?(?=\s*(?:[.,;!]|$))"),
     _tower_and_more),
)
"""Towers said by their parts: the goal's tower described by its top or bottom block ("the top block of the tower should
be green ..."), and a tower said by one end and how many more cubes stand on it or under it (a tower of that many, that
end said)."""

READING_END_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"\bfrom\s+(?:the\s+)?(left|right|front|back)(?:\s+(?:side|end))?\b(?!\s*(?:to|of|side|end|corner|edge|half|part)\b)"),
     lambda m: "from " + {"left": "left to right", "right": "right to left", "front": "front to back", "back": "back to front"}[m.group(1)]),
)
"""Of a line or a sort, "in increasing order from left", "spell it from the right": the reading direction, its far end unsaid."""

MAP_TOP_REWRITES: tuple[tuple[re.Pattern, object], ...] = (
    (re.compile(r"\b(push|move|slide|shift|sweep|bring|drag)\b([^.;]*?)\b(to|towards?)\s+the\s+(top|bottom)\b"
                r"(?!\s+(?:of|left|right|layer|row|cube|block|one|edge|side|corner)\b)"),
     lambda m: f"{m.group(1)}{m.group(2)}{m.group(3)} the {'back' if m.group(4) == 'top' else 'front'}"),
)
"""With no tower to have a top, "move all the red blocks to the bottom": the near side of the map, the front."""

COLOUR_NOUN_AFTER = re.compile(r"(?:\s*(?:,|\band\b|\bor\b)\s*(?:the\s+)?[a-z]+){0,4}"  # a list of colours first ("gold, silver and red")
                               r"\s+(?:(?:coloured|colored|[a-z]+-?ish)\s+)?(?:blocks?|cubes?|bricks?|boxes|box|ones?|patch(?:es)?"
                               r"|squares?|tiles?|pads?|mats?|targets?|objects?)\b")
"""What follows a word that names a cube's or patch's colour ("mauve cube", "teal patch", "the gold,
silver and red cubes")."""

COLOUR_ROLE_AFTER = re.compile(r"\s+(?:(?:at|on|in)\s+(?:the\s+)?(?:bottom|top|base|middle|center|centre)|on\s+top|first|last)\b")
"""What follows a colour name standing for a cube by its role in a structure ("maroon at the bottom, olive on top")."""

PALETTE_LIST_NEAR = re.compile(rf"\b(?:{COLOR_RE})\s*(?:,|\band\b|\bor\b|then\b|/|->|\bover\b|\bon\b)\s*(?:(?:and|then|the)\s+)?$")
"""What precedes a colour name listed after a palette colour ("red, maroon and blue", "blue over teal")."""

PALETTE_LIST_AFTER = re.compile(rf"\s*(?:,|\band\b|\bor\b|then\b|/|->|\bover\b|\bon\b)\s*(?:(?:and|then|the)\s+)?(?:{COLOR_RE})\b")
"""What follows a colour name listed before a palette colour ("maroon, red and blue", "teal on red")."""

LIST_GAP_RE = re.compile(r"\s*(?:,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)\s*")
"""What stands between two items of a listed tower ("red, red and blue", "red, then blue")."""

ROLE_AFTER_RE = re.compile(r"\s+(?:block\s+|cube\s+)?(?:on\s+top|at\s+the\s+(?:top|bottom|base)|on\s+the\s+bottom|in\s+the\s+middle)\b")
"""A role said after a colour ("white on top"): the colour names a cube already listed, not one more."""

PAIR_RELATION_RE = re.compile(
    rf"\bthe\s+(?P<a>{COLOR_RE})\s+(?:block|cube|one)\s+(?:(?:is|goes|sits|should\s+be|must\s+be)\s+)?(?P<rel>on\s+top\s+of|onto|on|next\s+to|beside|behind|in\s+front\s+of"
    rf"|(?:to\s+the\s+)?left\s+of|(?:to\s+the\s+)?right\s+of|under|far\s+from)\s+the\s+(?P<b>{COLOR_RE})\s+(?:block|cube|one)\b")
"""A relation said between two cubes named by colour ("... and put the yellow cube on the blue cube",
"the red cube should be next to the blue cube"): :func:`_pair_relation_dropped` checks the goal relates the two."""
PAIR_RELATION_BARE_RE = re.compile(
    rf"(?:\b(?:put|place|set|stack|move)|,\s*and)\s+(?:the\s+)?(?P<a>{COLOR_RE})(?:\s+(?:block|cube|one))?\s+(?P<rel>on\s+top\s+of|onto|on|next\s+to"
    rf"|beside|behind|in\s+front\s+of|(?:to\s+the\s+)?left\s+of|(?:to\s+the\s+)?right\s+of|under|far\s+from)\s+(?:the\s+)?"
    rf"(?P<b>{COLOR_RE})\b(?!\s+(?:goal\s+)?(?:patch|pad|mat|tile|square|area|region|zone)"
    rf"|\s*(?:,\s*(?:and\s+|or\s+)?|(?:and|or|&|\+)\s+)(?:the\s+)?(?:{COLOR_RE})\b)")
"""The same relation said with bare colours after a verb ("... and put blue on yellow", "put red on blue and line up
green and yellow"): a row of four had been made and the relation dropped, silently.  Not when another colour is listed
after the second ("red on blue and green": which cubes the relation has is the list's)."""
