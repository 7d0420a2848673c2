"""A compact, readable statement of what a task means: its goal as atoms over object descriptors.

A task's meaning abstracts away object names and poses: each atom names a goal relation and
the objects it relates by what a person would call them (a coloured cube by its colour, a
letter/digit cube by its label, a goal patch as ``patch:<colour>``).  Examples::

    stack(red,blue,green)                 a tower, bottom to top
    stack(yellow,yellow)@back_left        a tower standing in a region of the table
    line(red,red,red)@back                a structure all of whose cubes stand in one region (or, wider than
                                          the centre third, whose middle stands there: ``centred_in``)
    on_patch(red,red,patch:green)         left_of(red,blue)    next_to(blue,red)
    right_of(red,blue); in_front_of(red,blue)   two relations of one pair along both axes: diagonally
    line(green,green,green)               line[left_to_right](red,green,blue)
    line[sequence](red,green,red)         a row in that order from either end, along no said axis ("red, green, red in a row")
    line[left_end](red,blue,green)        a row with red at its left end, the rest in any order (sorted; right_end: the last)
    wall(red,red,red|blue,blue,blue)      layers bottom to top (rows, walls, 3D blocks)
    pyramid(blue,green,red|yellow)        layers bottom to top, each layer sorted
    pyramid(blue,green,red)               a pyramid whose cubes may stand in any layer
    pile(orange,orange,orange)@center     one pile (piles by colour: piles(...;by=color); separate piles of said cubes: pile(...) each)

A pyramid or wall shows its layers only where the goal judges which cubes stand in which
layer (:class:`~rpg.domain.predicates.InLayers`); otherwise its cubes are one sorted list,
since any of them may stand anywhere.  An expected atom whose objects are all wildcards
(``pyramid(?,?|?)``) or all one colour (``wall(red,red|red,red)``) matches either form with as
many objects.
    start:stack(red,blue); on_table(blue) a stack rho_0 starts, and its top cube taken off
    start:stack(red,blue); on_table(blue); on_table(red)  ... and both cubes on the table (a start's bottom cube is
                                          listed where the goal sends it to the table too: "unstack it")

The development corpus (``tests/corpus/instructions.yaml``) states each instruction's
expected meaning in this notation, with two wildcards: ``?`` for any one object and ``red*``
for one or more red cubes.  :func:`matches` compares an expected meaning with a schema's.
"""

from __future__ import annotations

import itertools
import re
from collections import Counter

from rpg.domain import predicates as P
from rpg.schema.model import TaskSchema

_SKIP = (P.OnTable, P.Upright, P.LayersUniform)  # layers' colours show in the layer breakdown
_SYMMETRIC = (P.NextTo, P.FarFrom)
_SYMMETRIC_ATOM_RE = re.compile(rf"({'|'.join(k.name for k in _SYMMETRIC)})\(([^(),;]+),([^(),;]+)\)")
"""An atom of a symmetric relation (``next_to(pink,Z)``): its two cubes in either order."""


def descriptor(asset) -> str:
    """What a person calls an object: its colour, its label, or ``patch:<colour>``."""
    if asset.kind == "goal_patch":
        return f"patch:{asset.color or 'gray'}"
    if asset.kind == "semantic_cube":
        return str(asset.label)
    return str(asset.color)


def _inner(a: str, b: str) -> str | None:
    """Of two regions one of which lies within the other (``back_right`` in ``back``), the inner one, which says
    both; None when neither holds the other."""
    def within(x: str, y: str) -> bool:
        return all(any(ox[0] >= oy[0] - 1e-9 and ox[1] <= oy[1] + 1e-9 and px[0] >= py[0] - 1e-9 and px[1] <= py[1] + 1e-9
                       for oy, py in P.region_boxes(y)) for ox, px in P.region_boxes(x))
    return a if within(a, b) else b if within(b, a) else None


def _conjuncts(p: P.Predicate) -> list[P.Predicate]:
    if isinstance(p, (P.And, P.InOrder)):
        return [q for c in p.children() for q in _conjuncts(c)]
    return [p]


def _layers(names, layout) -> list[list[str]]:
    """Names grouped by goal height (bottom first), each group in name order."""
    levels: dict[int, list[str]] = {}
    for n in names:
        levels.setdefault(round(layout[n].position[2] / 0.02), []).append(n)
    return [levels[k] for k in sorted(levels)]


def _one_pile(p: P.Piles, d: dict[str, str]) -> bool:
    """Whether a piles predicate asks for one pile: one explicit group, or cubes sorted by their
    colour when all share one (a single pile, written ``pile(...)``)."""
    if p.groups:
        return len(p.groups) == 1 and not p.objects
    return p.by in (None, "color") and len({d[n] for n in p.objects}) == 1


def meaning(schema: TaskSchema) -> list[str]:
    """The task's goal as a sorted list of atoms (see the module docstring).

    Every object of the task appears in some atom: an object the goal does not mention is
    reported as ``extra(<descriptor>)``, so a task with a stray cube never reads as meant.
    """
    d = {a.name: descriptor(a) for a in schema.assets}
    layout = schema.goal_layout
    atoms: list[str] = []
    placed: list[tuple[int, tuple[str, ...]]] = []  # (atom index, its objects) of structures a region may hold
    used: set[str] = set()
    chains: list[list[str]] = []
    regions: dict[str, str] = {}
    on_edges: list[tuple[str, str]] = []
    on_patch: dict[str, list[str]] = {}

    def names(ns):
        used.update(ns)
        return ",".join(d[n] for n in ns)

    def sorted_names(ns):
        used.update(ns)
        return ",".join(sorted(d[n] for n in ns))

    starts = [list(s) for s in schema.initial_state.structures]
    started_on = {n for s in starts for n in s[1:]}  # cubes rho_0 stacks on another
    conjuncts = _conjuncts(schema.goal_predicate())
    based = {p.objects[0] for p in conjuncts if isinstance(p, P.Stack)}  # a stack's bottom rests on the table: said by it
    for p in conjuncts:
        if isinstance(p, P.OnTable) and (p.a in started_on or starts) and p.a not in based:
            atoms.append(f"on_table({names([p.a])})")
        elif isinstance(p, _SKIP):
            used.update(p.object_names())
        elif isinstance(p, P.Stack):
            chains.append(list(p.objects))
        elif isinstance(p, P.On):
            on_edges.append((p.b, p.a))
        elif isinstance(p, P.InRegion):
            if p.a in regions and regions[p.a] != p.region:  # two places of one cube: the goal is both
                inner = _inner(regions[p.a], p.region)
                if inner is None:
                    atoms.append(f"in_region({names([p.a])},{p.region})")
                    continue
                regions[p.a] = inner  # "the back right corner, at the back of the table": the corner (the wider had won)
            else:
                regions[p.a] = p.region
            used.add(p.a)
        elif isinstance(p, P.CentredIn):  # a structure standing with its middle in a region: "circle(...)@center" too
            regions.update(dict.fromkeys(p.objects, p.region))
            used.update(p.objects)
        elif isinstance(p, P.OnPatch):
            on_patch.setdefault(p.patch, []).append(p.a)
        elif isinstance(p, _SYMMETRIC):
            atoms.append(f"{p.name}({sorted_names([p.a, p.b])})")
        elif isinstance(p, P.Between):
            atoms.append(f"between({names([p.a])};{sorted_names([p.b, p.c])})")
        elif isinstance(p, P.AnchoredLine):  # "line[left_end](red,blue,green)": red at the left end, the rest sorted
            rest = p.objects[p.left:len(p.objects) - p.right]
            ends = ",".join(["left_end"] * p.left + ["right_end"] * p.right)
            body = ",".join(filter(None, [names(p.objects[:1]) if p.left else "", sorted_names(rest),
                                          names(p.objects[-1:]) if p.right else ""]))
            atoms.append(f"line[{ends}]({body})")
            placed.append((len(atoms) - 1, p.objects))
        elif isinstance(p, P.InLine):
            ordered = p.order and len(set(names(p.objects).split(","))) > 1  # cubes of one colour: no order to say,
            directed = p.order and p.order != "sequence"  # but a direction still says the line's axis
            order = f"[{p.order}]" if ordered or directed else ""
            body = names(p.objects) if ordered else sorted_names(p.objects)
            atoms.append(f"line{order}({body})")
            placed.append((len(atoms) - 1, p.objects))
        elif isinstance(p, P.InLayers):
            used.update(p.objects)
        elif isinstance(p, (P.Grid, P.Pyramid)):
            kind = "pyramid" if isinstance(p, P.Pyramid) else ("wall" if getattr(p, "layers", 1) > 1 else "grid")
            judged = any(isinstance(q, P.InLayers) and set(q.objects) == set(p.objects) for q in conjuncts)
            layers = _layers(p.objects, layout) if judged or kind == "grid" else [list(p.objects)]
            body = "|".join(sorted_names(layer) for layer in layers)
            if kind == "grid":
                body = f"{p.rows}x{p.cols}:{body}"
            atoms.append(f"{kind}({body})")
            placed.append((len(atoms) - 1, p.objects))
        elif isinstance(p, P.InCircle):
            atoms.append(f"circle({sorted_names(p.objects)})")
            placed.append((len(atoms) - 1, p.objects))
        elif isinstance(p, P.Piles) and _one_pile(p, d):
            members = p.object_names()
            atoms.append(f"pile({sorted_names(members)})")
            placed.append((len(atoms) - 1, tuple(members)))
        elif isinstance(p, P.Piles) and p.groups and not p.objects:  # separate piles, each its own cubes: one atom a pile
            for group in p.groups:
                atoms.append(f"pile({sorted_names(group)})")
                placed.append((len(atoms) - 1, tuple(group)))
        elif isinstance(p, P.Piles) and not p.groups:  # piles by an attribute: which cube is listed first says nothing
            atoms.append(f"piles({sorted_names(p.objects)};by={p.by or 'color'})")
        else:
            objs = p.object_names()
            used.update(objs)
            # a relation's diagonal flag is implied by its pair's second relation along the other axis: not written
            extra = {k: v for k, v in p.args().items() if not isinstance(v, (list, tuple)) and k not in p.object_fields
                     and k != "diagonal"}
            arg = ",".join(d.get(n, n) for n in objs)
            atoms.append(f"{p.name}({arg}{';' if extra and arg else ''}{','.join(f'{k}={v}' for k, v in sorted(extra.items()))})")
    for i, objs in placed:  # a structure every cube of which stands in one region: "line(red,red,red)@back"
        where = {regions.get(n) for n in objs}
        if len(where) == 1 and None not in where:
            atoms[i] += f"@{where.pop()}"
            for n in objs:
                regions.pop(n)
    # On edges become towers: follow b -> a links from each cube that supports but is not supported.
    above = dict(on_edges)
    below = {a: b for b, a in on_edges}
    for base in sorted(b for b, _ in on_edges if b not in below):
        chain = [base]
        while chain[-1] in above and above[chain[-1]] not in chain:
            chain.append(above[chain[-1]])
        chains.append(chain)
    for chain in chains:
        where = sorted({regions.pop(n) for n in chain if n in regions})
        atoms.append(f"stack({names(chain)})" + (f"@{where[0]}" if len(where) == 1 else ""))
    for patch, cubes in sorted(on_patch.items()):
        used.update(cubes + [patch])
        atoms.append(f"on_patch({','.join(sorted(d[c] for c in cubes))},{d[patch]})")
    for n, region in sorted(regions.items()):
        atoms.append(f"in_region({d[n]},{region})")
    for s in starts:
        atoms.append(f"start:stack({names(s)})")
    for n in sorted(set(d) - used):
        atoms.append(f"extra({d[n]})")
    return sorted(atoms)


def _pattern(atom: str, either_way: bool = True) -> re.Pattern:
    """A regular expression for one expected atom (``?`` and ``X*`` wildcards); a symmetric pair
    with a wildcard (``next_to(red,?)``) in either order."""
    pair = _SYMMETRIC_ATOM_RE.fullmatch(atom.strip())
    if either_way and pair and "?" in atom and pair.group(2) != pair.group(3):
        one, other = (_pattern(f"{pair.group(1)}({a},{b})", False).pattern for a, b in (pair.group(2, 3), pair.group(3, 2)))
        return re.compile(f"(?:{one[:-2]}|{other[:-2]})" + r"\Z")
    out = []
    for tok in re.split(r"([(),;|@\[\]])", atom.strip()):
        if "?" in tok and not tok.endswith("*"):
            out.append(r"[^(),;|@]+".join(re.escape(part) for part in tok.split("?")))
        elif tok.endswith("*") and tok[:-1]:
            t = re.escape(tok[:-1])
            out.append(rf"{t}(?:[,|]{t})*")
        else:
            out.append(re.escape(tok))
    return re.compile("".join(out) + r"\Z")


def _wild(atom: str) -> bool:
    """Whether a layered atom's objects are all alike: all ``?``, or all one colour (which cube
    stands in which layer then changes nothing, so layers need not be judged)."""
    head, _, body = atom.partition("(")
    body = body.rpartition(")")[0]  # the objects, without a place suffix ("...)@center")
    tokens = {t.strip() for t in re.split(r"[,|]", body)}
    return "|" in body and head in ("pyramid", "wall") and len(tokens) == 1 and "*" not in next(iter(tokens))


_CONVERSES = {k.name: k.converse for k in vars(P).values()
              if isinstance(k, type) and issubclass(k, P.Predicate) and isinstance(getattr(k, "converse", None), str)}
"""Relation name -> its converse's (``behind`` -> ``in_front_of``): ``behind(a,b)`` is ``in_front_of(b,a)``."""


def _converse_written_once(atom: str) -> str:
    """A relation of a pair written with the name of a converse pair that sorts first:
    ``in_front_of(blue,red)`` as ``behind(red,blue)``, ``right_of(a,b)`` as ``left_of(b,a)`` (one goal,
    two spellings; an annotation had written "A behind B" as ``in_front_of(B,A)``)."""
    m = re.fullmatch(r"(\w+)\(([^(),;|]+),([^(),;|]+)\)", atom)
    if m is None or m.group(1) not in _CONVERSES or _CONVERSES[m.group(1)] > m.group(1):
        return atom
    return f"{_CONVERSES[m.group(1)]}({m.group(3)},{m.group(2)})"


def _unordered(atom: str) -> str:
    """An atom whose objects have no order (``piles(red,blue,red;by=color)``, ``pile(...)``, the two cubes
    of ``next_to``/``far_from``, a line with no direction, a circle) with its objects sorted, so an expected meaning may
    list them in any order."""
    atom = _converse_written_once(atom)
    flanks = re.fullmatch(r"between\(([^;()]+);([^;(),]+),([^;(),]+)\)", atom)
    if flanks and not re.search(r"[?*]", atom):  # "between(white;red,blue)": the two it stands between in either order
        return f"between({flanks.group(1)};{','.join(sorted(flanks.group(2, 3)))})"
    pair = _SYMMETRIC_ATOM_RE.fullmatch(atom)
    if pair and "?" not in atom:  # symmetric: "next_to(pink,Z)" is "next_to(Z,pink)" (a wildcard's pattern takes both)
        return f"{pair.group(1)}({','.join(sorted(pair.group(2, 3)))})"
    m = re.fullmatch(r"(piles?)\(([^;()]*)(;[^()]*)?\)(@\w+)?", atom) or (
        # a line said with no order (no direction) and a circle: their cubes in no order (meaning() writes them sorted; an
        # annotation had listed them as said, a right reading counted wrong)
        None if re.search(r"[?*]", atom) else re.fullmatch(r"(line|circle)\(([^;()|\[\]]*)()\)(@\w+)?", atom))
    if m is None:
        return atom
    return f"{m.group(1)}({','.join(sorted(m.group(2).split(',')))}{m.group(3) or ''}){m.group(4) or ''}"


def _per_cube(atom: str) -> list[str]:
    """A place said of several cubes at once (``in_region(red,red,back)``) as one atom per cube,
    the way :func:`meaning` writes it; any other atom as it is."""
    m = re.fullmatch(r"in_region\(([^()]+),(\w+)\)", atom)
    if m is None or "," not in m.group(1):
        return [atom]
    return [f"in_region({c},{m.group(2)})" for c in m.group(1).split(",")]


def _one_atom_a_patch(atoms: list[str]) -> list[str]:
    """Cubes put on one patch in atoms of their own (``on_patch(red,patch:green); on_patch(blue,patch:green)``) as the
    one atom :func:`meaning` writes for that patch (``on_patch(blue,red,patch:green)``); atoms with a wildcard as they are."""
    said: dict[str, list[str]] = {}
    rest = []
    for a in atoms:
        m = re.fullmatch(r"on_patch\(([^()?*]+),(patch:\w+)\)", a)
        if m:
            said.setdefault(m.group(2), []).extend(m.group(1).split(","))
        else:
            rest.append(a)
    return rest + [f"on_patch({','.join(sorted(cubes))},{patch})" for patch, cubes in sorted(said.items())]


def _by_colour(atoms: list[str]) -> list[str]:
    """Separate piles each of one colour, no two alike (``pile(red,red); pile(blue,blue)``), as the
    one atom of piles sorted by colour (``piles(blue,blue,red,red;by=color)``): the same goal."""
    piles = [a for a in atoms if re.fullmatch(r"pile\([^;()?*]*\)", a)]
    colours = [set(a[5:-1].split(",")) for a in piles]
    if len(piles) < 2 or any(len(c) != 1 for c in colours) or len({next(iter(c)) for c in colours}) != len(piles):
        return atoms
    cubes = sorted(c for a in piles for c in a[5:-1].split(","))
    return [a for a in atoms if a not in piles] + [f"piles({','.join(cubes)};by=color)"]


_REVERSED_DIRECTIONS = {"right_to_left": "left_to_right", "back_to_front": "front_to_back"}


def _forward(text: str) -> str:
    """``text`` with each line read in a reversed direction written forward: ``line[right_to_left](a,b)``
    is ``line[left_to_right](b,a)`` (one goal, two spellings)."""
    return re.sub(r"\bline\[(\w+)\]\(([^()]*)\)",
                  lambda m: (f"line[{_REVERSED_DIRECTIONS[m.group(1)]}](" + ",".join(reversed(m.group(2).split(","))) + ")"
                             if m.group(1) in _REVERSED_DIRECTIONS else m.group(0)), text)


def _middle_of_three(text: str) -> str:
    """``text`` with each line of three cubes in an order from either end (``line[sequence](red,white,blue)``) written as
    the cube between the other two in a line of no order (``between(white;blue,red); line(blue,red,white)``): one goal,
    two spellings ("a row of red, white and blue with white in the middle")."""
    def split(m: re.Match) -> str:
        x, y, z = m.group(1).split(",")
        return f"between({y};{','.join(sorted((x, z)))}); line({','.join(sorted((x, y, z)))}){m.group(2) or ''}"
    return re.sub(r"\bline\[sequence\]\(([^()?*,;|]+,[^()?*,;|]+,[^()?*,;|]+)\)(@\w+)?", split, text)


_ANCHORED_LINE_RE = re.compile(r"\bline\[(left_end|right_end|left_end,right_end)\]\(([^()]*)\)")


def completions(actual: list[str]) -> list[list[str]]:
    """The meanings a line with its ends said and the rest free (``line[left_end](red,blue,green)``) accepts, each with
    that line written in one full order from left to right (``line[left_to_right](red,blue,green)``,
    ``line[left_to_right](red,green,blue)``); ``[actual]`` when it has none.  An expected meaning given as alternatives
    equals such a line when the alternatives are exactly its completions (:func:`matches_alternatives`)."""
    out = [list(actual)]
    for i, atom in enumerate(actual):
        m = _ANCHORED_LINE_RE.search(atom)
        if m is None:
            continue
        cubes = m.group(2).split(",")
        left, right = "left_end" in m.group(1), "right_end" in m.group(1)
        head, rest, tail = cubes[:left], cubes[left:len(cubes) - right], cubes[len(cubes) - right:]
        orders = sorted({tuple(head + list(q) + tail) for q in itertools.permutations(rest)})
        out = [c[:i] + [atom[:m.start()] + f"line[left_to_right]({','.join(o)})" + atom[m.end():]] + c[i + 1:]
               for c in out for o in orders]
    return out


def matches_alternatives(alternatives: list[str], actual: list[str]) -> bool:
    """Whether ``actual`` means what the expected ``alternatives`` (any one of them right) say together: one of them
    matches it, or, where ``actual`` leaves a line's order free but at its ends, its completions and the alternatives
    match one to one (a line free but for one end is right only where every order it accepts was expected, or where an
    alternative writes that same line with its end, ``line[right_end](...)``)."""
    if any(matches(m, actual) for m in alternatives if re.search(r"\[\w+_end\]", m)):
        return True
    done = completions(actual)
    if len(done) == 1:
        return any(matches(m, actual) for m in alternatives)
    return all(any(matches(m, c) for m in alternatives) for c in done) and all(
        any(matches(m, c) for c in done) for m in alternatives)


def matches(expected: str, actual: list[str]) -> bool:
    """Whether a corpus meaning (atoms separated by ``; `` outside brackets) equals ``actual``.

    Each expected atom must match a distinct actual atom and no actual atom may be left over.
    A per-cube atom whose cube is ``red*`` (``in_region(red*,back)``: every red cube there)
    matches one or more actual atoms, one per red cube (``in_region(red,back)`` twice), and
    ``in_region(red,red,back)`` stands for one atom per cube; ``reads(DOG)`` matches the reads atom whose text is DOG, whatever its cubes and face; a pile's
    or piles' cubes match in any order, and one-colour piles of distinct colours match piles sorted by colour; a grid written without its size (``grid(gray,gray|gray,gray)``) matches a
    grid of those cubes, whatever its rows; a line in a reversed direction matches the same line written forward; a line of three in an order from either
    end matches its middle cube between the other two in a line of no order.
    """
    if re.search(r"\bgrid\((?!\d+x\d+:)", expected):  # "grid(gray,gray|gray,gray)": a grid's size and rows left unsaid
        expected = re.sub(r"\bgrid\(([^()]*)\)", lambda m: "grid(" + ",".join(sorted(re.split(r"[,|]", m.group(1)))) + ")", expected)
        actual = [re.sub(r"^grid\((?:\d+x\d+:)?([^()]*)\)(?=@|$)", lambda m: "grid(" + ",".join(sorted(re.split(r"[,|]", m.group(1)))) + ")", a)
                  for a in actual]
    expected, actual = _forward(expected), [_forward(a) for a in actual]
    expected, actual = _middle_of_three(expected), [b for a in actual for b in re.split(r"; ", _middle_of_three(a))]
    wanted = _by_colour([w for a in re.split(r";\s+(?![^()]*\))", expected) if a.strip() for w in _per_cube(_unordered(a.strip()))])
    wanted = _one_atom_a_patch(wanted)  # (an annotation had written a patch's cubes one atom each)
    actual = _by_colour([w for a in actual for w in _per_cube(_unordered(a))])
    for w in [w for w in wanted if re.fullmatch(r"reads\([A-Za-z0-9]+\)", w)]:  # "reads(DOG)": the word read, shortly
        word = w[6:-1]
        actual = [f"reads({word})" if re.fullmatch(rf"reads\([^()]*\btext={re.escape(word)}\b[^()]*\)", a) else a for a in actual]
    for w in [w for w in wanted if re.match(r"^\w+\((?:(\w+)\*,[^,*]+|[^,*]+,(\w+)\*)\)$", w)]:  # (its second cube too:
        # "in_front_of(red*,blue)" is written "behind(blue,red*)")
        each = w.replace("*", "", 1)
        if each in actual:  # one atom per cube of that colour (a single atom of the star form may match too)
            wanted.remove(w)
            actual = [a for a in actual if a != each]
    if len(wanted) != len(actual):
        return False
    left = Counter(actual)
    # most specific patterns first, so a wildcard does not take an atom a literal needs
    for w in sorted(wanted, key=lambda a: (a.count("?") + a.count("*"), a)):
        pat = _pattern(w)
        if _wild(w):  # any cube in any layer: the layers' sizes are the structure's own
            pat = re.compile(pat.pattern.replace(r"\|", "[,|]"))
        hit = next((a for a in sorted(left) if left[a] and pat.match(a)), None)
        if hit is None:
            return False
        left[hit] -= 1
    return True
