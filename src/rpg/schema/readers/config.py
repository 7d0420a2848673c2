"""A task written as a config: key-value pairs ("structure=line; n=5; colour=green; region=back",
"- cubes: 4 x blue - structure: tower - location: front right corner", a flat JSON or YAML dict
after a label: 'Goal spec: {"relation": "between", "target": "white", "anchors": ["black", "brown"]}').

Each key has a role (:data:`rpg.schema.lexicon.CONFIG_ROLES`): the structure, the cubes, their
count, the place, the direction, a relation with its subject and its anchors, a patch.
:func:`sentence` writes the pairs as the sentence they stand for ("build a line of 5 green cubes
at the back of the table"), which the whole front end then reads, so a value it cannot express
is refused as it would be in a sentence.  A config with a key of no known role, a nested value,
or no structure and no relation is not read here (the instruction is then read as written).
"""

from __future__ import annotations

import re

from rpg.schema.lexicon import CALL_ARGUMENT_ROLES, CONFIG_RELATIONS, CONFIG_ROLES, NUMBER_WORDS
from rpg.schema.structures import STRUCTURE_WORDS

_PAIR_RE = re.compile(r"""["']?(?P<key>[A-Za-z][\w ]{0,24}?)["']?\s*(?::|=)\s*(?P<value>\[[^\[\]]*\]|"[^"]*"|'[^']*'|[^,;{}\[\]\n]+?)"""
                      r"""\s*(?=[,;}\n]|\s+-\s+|\s*$)""")
_DICT_RE = re.compile(r"\{(?P<body>[^{}]*)\}")
_BULLETS_RE = re.compile(r"(?:^|\s)-\s+(?=[A-Za-z_ ]{1,24}\s*:)")


def _pairs(text: str) -> dict[str, str] | None:
    """The key-value pairs of ``text`` (keys lower-cased, ``_`` and spaces as ``_``), or None when
    it is not a config: fewer than two pairs, text outside them beyond a short label, a key twice."""
    found = _DICT_RE.search(text)
    if found:
        outside = (text[:found.start()] + " " + text[found.end():]).strip(" .:")
        if "{" in found.group("body") or len(re.findall(r"[A-Za-z]+", outside)) > 6:
            return None
        body = found.group("body")
    else:
        body = _BULLETS_RE.sub("; ", text.strip())
        head = re.match(r"\s*[A-Za-z][\w ]{0,24}:\s*(?=[A-Za-z_ ]{1,24}\s*[:=])", body)  # "config: structure=line; ..."
        body = body[head.end():] if head else body
    pairs: dict[str, str] = {}
    if not found and ";" in body:  # "obj=stack; cubes=gray,gray,black": a value may hold commas
        matches = [re.fullmatch(r"\s*(?P<key>[A-Za-z][\w ]{0,24}?)\s*[:=]\s*(?P<value>.+?)\s*[.]?\s*", seg)
                   for seg in body.split(";") if seg.strip()]
        if not all(matches):
            return None
        rest = ""
    else:
        matches, rest = list(_PAIR_RE.finditer(body)), body
        for m in matches:
            rest = rest.replace(m.group(0), " ", 1)
    for m in matches:
        key = re.sub(r"[\s_]+", "_", m.group("key").strip().lower())
        if key in pairs:
            return None
        pairs[key] = m.group("value").strip().strip("\"'")
    if len(pairs) < 2 or re.search(r"[A-Za-z]", re.sub(r"[\s,;.{}\-]+", " ", rest)):
        return None
    return pairs


def _values(value: str) -> list[str]:
    """A value's items: a list ``[red, green]`` or ``red, green`` split, ``4 x blue`` as four."""
    value = value.strip().strip("[]")
    items = [v.strip().strip("\"'") for v in re.split(r"\s*,\s*|\s+and\s+", value) if v.strip()]
    out: list[str] = []
    for v in items:
        times = re.fullmatch(r"(\d+)\s*[x\u00d7*]\s*(.+)|(.+?)\s*[x\u00d7*]\s*(\d+)", v)
        if times:
            n, what = (times.group(1), times.group(2)) if times.group(1) else (times.group(4), times.group(3))
            out += [what.strip()] * int(n)
        else:
            out.append(v)
    return out


def _words(value: str) -> str:
    return value.replace("_", " ").strip()


def place_phrase(value: str) -> str | None:
    """A region value as a phrase: ``back_right`` -> "in the back right corner", ``back`` -> "at the back of the
    table"; None for a value that names no region of the table (it is not guessed: "region=nowhere")."""
    v = re.sub(r"[\s-]+", " ", _words(value).lower()).removesuffix(" corner")
    if re.fullmatch(r"(?:front|back)\s+(?:left|right)", v):
        return f"in the {v} corner"
    if v in ("front", "back", "left", "right"):
        return f"on the {v} side of the table" if v in ("left", "right") else f"at the {v} of the table"
    if v in ("center", "centre", "middle"):
        return "in the center of the table"
    return None


_CALL_RE = re.compile(r"^\s*(?P<ident>[A-Za-z]+(?:[-_][A-Za-z0-9]+)*)\s*(?:\((?P<args>[^()]*=[^()]*)\)|:\s*(?P<pairs>[A-Za-z_]+\s*=[^:]*))"
                      r"\s*\.?\s*$")
"""A task written as a call or a spec line, its identifier naming the relation: "place_on_patch(obj=red cube,
target=blue patch)", "in-front-of(obj=brown, ref=gray)", "put-block-in-region: block=purple, region=front-right"."""


def _call_roles(instruction: str) -> dict[str, str] | None:
    """The roles of a task written as a call (:data:`_CALL_RE`): its arguments by
    :data:`rpg.schema.lexicon.CALL_ARGUMENT_ROLES` (a target that is a patch is the patch, else the
    anchor) and the relation its identifier names; None when it is no such call or an argument has
    no role."""
    m = _CALL_RE.match(instruction)
    if m is None:
        return None
    roles: dict[str, str] = {}
    for item in re.split(r"\s*,\s*", (m.group("args") or m.group("pairs")).strip()):
        key, eq, value = item.partition("=")
        key, value = re.sub(r"[\s-]+", "_", key.strip().lower()), value.strip().strip("\"'")
        role = CALL_ARGUMENT_ROLES.get(key, CONFIG_ROLES.get(key))
        if role == "target":
            role = "patch" if re.search(r"\bpatch$", value, re.IGNORECASE) else "anchor"
        if not eq or not value or role is None or role in roles:
            return None
        roles[role] = re.sub(r"(?i)\s+patch$", "", value) if role == "patch" else value
    ident = m.group("ident").lower().replace("-", "_")
    relation = next((ident[len(v):] for v in ("", "put_", "place_", "move_") if ident.startswith(v)
                     and ident[len(v):] in CONFIG_RELATIONS), None)
    if relation is not None:
        roles.setdefault("relation", relation)
    roles.pop("ignored", None)
    return roles


def sentence(instruction: str) -> str | None:
    """The sentence a config stands for (see the module docstring), or None when ``instruction``
    is not a config this module reads."""
    roles = _call_roles(instruction)
    if roles is not None and "relation" not in roles and set(roles) == {"subject", "place"}:
        where = place_phrase(roles["place"])  # "put-block-in-region: block=purple, region=front-right"
        cube = f"the {_words(roles['subject'])}" + ("" if re.search(r"\b(?:cube|block)\b", roles["subject"]) else " cube")
        return f"put {cube} {where}" if where else None
    if roles is None:
        pairs = _pairs(instruction)
        if pairs is None:
            return None
        roles = {}
        for key, value in pairs.items():
            role = "patch" if key == "target" and value.lower() == "patch" else CONFIG_ROLES.get(key)  # "target": "patch"
            if role is None or role in roles:
                return None  # a key of no known role, or two keys of one role: not guessed
            roles[role] = value
        roles.pop("ignored", None)
    if "text" in roles:
        return roles["text"] if len(roles) == 1 else None
    kind = _words(roles.get("structure", "")).lower()
    relation = CONFIG_RELATIONS.get(_words(roles.get("relation", kind)).lower().replace(" ", "_"))
    if relation is not None:
        subject = _values(roles.get("subject", roles.get("cubes", "")))
        anchors = _values(roles.get("anchor", ""))
        patch = roles.get("patch_colour") or (roles.get("patch") if roles.get("patch", "").lower() != "patch" else None)
        if len(subject) != 1:
            return None
        cube = f"the {_words(subject[0])}" + ("" if re.search(r"\b(?:cube|block)\b", subject[0]) else " cube")
        if relation == "on_patch":
            return f"put {cube} on the {_words(patch)} patch" if patch and not anchors else None
        if relation == "between":
            return f"put {cube} between the {_words(anchors[0])} cube and the {_words(anchors[1])} cube" \
                if len(anchors) == 2 else None
        if len(anchors) != 1:
            return None
        return f"put {cube} {relation} the {_words(anchors[0])} cube"
    if kind not in STRUCTURE_WORDS and kind.rstrip("s") not in STRUCTURE_WORDS and kind != "stacking":
        return None
    cubes = [_words(c) for c in _values(roles.get("cubes", ""))]
    count = roles.get("count")
    if count is not None and not re.fullmatch(r"\d+", count.strip()) and count.strip().lower() not in NUMBER_WORDS:
        return None
    phrase = f"build a {kind} of "
    if cubes and len(cubes) > 1:
        phrase += ", ".join(cubes[:-1]) + f" and {cubes[-1]}"
    else:
        phrase += f"{count or ''} {cubes[0] if cubes else ''} cubes".replace("  ", " ")
    direction = roles.get("direction")
    if direction:
        d = _words(direction).lower()
        if d in ("yes", "true", "bottom first"):
            d = "bottom to top"
        if not re.fullmatch(r"(?:left to right|right to left|front to back|back to front|bottom to top|top to bottom)", d):
            return None
        phrase += f" from {d}"
    if "place" in roles:
        where = place_phrase(roles["place"])
        if where is None:
            return None
        phrase += " " + where
    return phrase if cubes or count else None  # a structure of cubes nobody counted or named: not guessed
