"""``rpg steer``: interpret an edit, pick the version it builds on, recompile, record.

Python API::

    from rpg.steer import steer
    r = steer("library/place_blue_cube", "Add a green cube on top of the blue")
    r.version, r.intent, r.reference, r.valid

Steps (paper, "Controlled Task Modifications"): 1. intent and parameters
(:mod:`rpg.steer.edits`); 2. reference version: explicit back-references, history search
by colours, asset material, structure and count, and asset compatibility (an ordering that
needs letter or digit cubes prefers an earlier version that has them); 3. preservation
flags from the intent; 4. the edit applied to the reference's :class:`TaskSpec`, rendered
as a canonical instruction and compiled through all four passes.  A version is recorded
only if every gate passes; an edit whose task equals an existing version's (same code
hash) moves the head back to that version instead of duplicating it.
"""

from __future__ import annotations

import itertools
import re
import shutil
import tempfile
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from rpg.artifact import ArtifactError, load_artifact
from rpg.compiler import CompileResult, build
from rpg.domain.palette import PALETTE
from rpg.domain.predicates import PREDICATES, InLayers, OnPatch, Stack, describe_region
from rpg.errors import BadInput
from rpg.schema.builtin import parse
from rpg.schema.edits import recolor
from rpg.schema.feasibility import check_feasibility
from rpg.schema.lexicon import (
    ADDED_CUBE_RE,
    BETWEEN_THEM_RE,
    COLOR_RE,
    COUNT_WORD_RE,
    EDIT_ADDITIVE_RE,
    EDIT_CONTINUES_RE,
    EDIT_KEEP_THEN_ADD_RE,
    EDIT_KEEP_TOO_RE,
    EDIT_MOVES_A_TASK_CUBE_RE,
    EDIT_OF_THE_TASK_RE,
    EDIT_SWAP_BOTH_RE,
    IT_ON_A_PATCH_RE,
    LABEL_EXCHANGE_RE,
    NEW_PATCH_RE,
    NO_GOAL_RE,
    NUMBER_WORDS,
    PAIRWISE_RELATIONS,
    PATCH_RECOLOUR_RE,
    ROWS_SWAPPED_RE,
    SAME_CUBES_RE,
    SAME_PATCH_RE,
    STRUCTURE_COPIED_RE,
    TOWER_RESTATED_RE,
    TOWER_TO_PATCH_RE,
    VARIANT_LABEL_RE,
)
from rpg.schema.model import TaskSchema
from rpg.schema.reading import canon_color
from rpg.schema.structures import STRUCTURE_RE
from rpg.steer.carried import Carried, region_phrase, split
from rpg.steer.carried import render as render_carried
from rpg.steer.edits import (
    PRESERVATION,
    EditPlan,
    SteerError,
    addition_clause,
    apply_ops,
    carried_after,
    check_said,
    in_place_move,
    intent_of_ops,
    intent_of_standalone,
    interpret,
    normalize_edit,
    strip_edit_words,
    unread_colors,
    unread_labels,
    unread_numbers,
)
from rpg.steer.family import (
    LOCK_TIMEOUT_S,
    Family,
    FamilyHistory,
    create_family,
    is_family,
    snapshot_of,
    task_hash,
)
from rpg.steer.relations import (
    between_roles,
    per_cube,
    places_said,
    relation_of,
    remove_cubes,
    replaced_placement,
    rewrite_moved,
    rewrite_patch,
    rewrite_region,
    same_assets,
)
from rpg.steer.relations import rewrite as rewrite_relation
from rpg.steer.spec import Item, TaskSpec, extract


@dataclass
class SteerResult:
    """Outcome of one steering edit."""

    family: Path
    edit: str
    intent: str
    reference: int | None
    version: int | None
    valid: bool
    reused: bool = False
    instruction: str = ""
    notes: list[str] = field(default_factory=list)
    compile: CompileResult | None = None
    parameters: dict = field(default_factory=dict)
    schema: TaskSchema | None = None  # the task of the version made (or, in a dry run, that would be made)

    def to_json(self) -> dict:
        doc = {"family": str(self.family), "edit": self.edit, "intent": self.intent,
               "reference": None if self.reference is None else f"v{self.reference}",
               "version": None if self.version is None else f"v{self.version}", "valid": self.valid,
               "reused": self.reused, "instruction": self.instruction, "notes": self.notes,
               "parameters": self.parameters}
        if self.compile is not None:
            doc["gates"] = self.compile.to_json()["gates"]
            doc["path"] = str(self.compile.path)
        return doc


def _spec_of(fam: Family, version_id: int) -> tuple[TaskSchema, TaskSpec | None]:
    schema = fam.schema(version_id)
    return schema, split(schema)[0]


def _matches(fam: Family, version_id: int, cue) -> bool:
    schema, spec = _spec_of(fam, version_id)
    cubes = [a for a in schema.assets if a.kind != "goal_patch"]
    colors = {a.color for a in cubes if a.kind == "colored_cube"}
    if cue.colors and (colors != set(cue.colors) if cue.exact else not set(cue.colors) <= colors):
        return False
    if cue.material:
        have = spec.material if spec else ("colors" if all(a.kind == "colored_cube" for a in cubes) else "mixed")
        if have != cue.material:
            return False
    if cue.structure and (spec is None or spec.structure != cue.structure):
        return False
    if cue.word and (spec is None or (spec.word or "".join(i.label or "" for i in spec.items)) != cue.word):
        return False
    return not (cue.count and len(cubes) != cue.count)


def resolve_reference(plan: EditPlan, hist: FamilyHistory, fam: Family) -> tuple[int | None, list[str]]:
    """The version an edit builds on, and notes on how it was chosen.

    Raises:
        SteerError: an explicit reference that names no version.
    """
    cue, head = plan.cue, hist.head
    notes: list[str] = []
    if plan.fresh:
        return None, ["fresh task: no reference"]
    if cue.kind == "version":
        if cue.version >= len(hist.versions):
            raise SteerError(f"{cue.phrase!r}: the family has versions v0..v{len(hist.versions) - 1}")
        return cue.version, [f"explicit reference {cue.phrase!r}"]
    if cue.kind == "original":
        return 0, [f"explicit reference {cue.phrase!r}"]
    if cue.kind == "previous":
        ref = head
        for _ in range(cue.steps):  # "go back two versions": the parent's parent
            parent = hist.get(ref).parent
            ref = parent if parent is not None else max(ref - 1, 0)
        return ref, [f"back-reference {cue.phrase!r}: the version before v{head}" if cue.steps == 1 else
                     f"back-reference {cue.phrase!r}: {cue.steps} versions before v{head}"]
    if cue.kind == "before":  # "the one before the patch": back along the lineage to the first version without it
        ref: int | None = head
        while ref is not None:
            schema, _ = _spec_of(fam, ref)
            kind = "goal_patch" if cue.lacks == "patch" else None
            has = any((a.kind == kind if kind else a.kind != "goal_patch") and (not cue.colors or a.color in cue.colors)
                      for a in schema.assets)
            if not has:
                return ref, [f"back-reference {cue.phrase!r}: v{ref}, the latest version before it was added"]
            ref = hist.get(ref).parent
        raise SteerError(f"{cue.phrase!r}: every version back to the first has it; versions: " +
                         "; ".join(f"v{v.version_id}: {v.goal_summary}" for v in hist.versions))
    if cue.kind == "redo":  # after going back to the head: the latest version built on it, whose change is made again
        children = [v.version_id for v in hist.versions if v.parent == head and v.version_id > head]
        if not children:
            raise SteerError(f"{cue.phrase!r}: no later version was built on v{head}, so there is nothing to redo; say the change")
        return children[-1], [f"redo {cue.phrase!r}: v{children[-1]}, the latest version built on v{head}"]
    if cue.kind == "search":
        for v in reversed(hist.versions):
            if v.version_id != head and _matches(fam, v.version_id, cue):
                return v.version_id, [f"back-reference {cue.phrase!r} matched v{v.version_id} ({v.goal_summary})"]
        if cue.colors or cue.structure or cue.count:
            raise SteerError(f"no earlier version matches {cue.phrase!r}; versions: " +
                             "; ".join(f"v{v.version_id}: {v.goal_summary}" for v in hist.versions))
        notes.append(f"no earlier version matches {cue.phrase!r}; building on the current version")
        return head, notes
    # current, unless an ordering needs labels the current cubes lack and no material change is asked
    need = {"label": "letters", "number": "digits"}
    wants = [need[o.params["key"]] for o in plan.ops if o.op == "ordering" and o.params["key"] in need]
    if wants and not any(o.op == "material" for o in plan.ops):
        _, spec = _spec_of(fam, head)
        if spec is not None and spec.material != wants[0]:
            for v in reversed(hist.versions):
                if v.version_id == head:
                    continue
                _, other = _spec_of(fam, v.version_id)
                if other is not None and other.material == wants[0] and other.structure == spec.structure:
                    return v.version_id, [f"asset compatibility: v{v.version_id} has {wants[0]} cubes"]
            notes.append(f"no earlier version has {wants[0]} cubes; the current version's cubes are replaced")
    return head, notes


ADDITION_OPENING_RE = re.compile(r"^\s*(?:(?:and|plus|also|now|then|ok(?:ay)?|oh)\s*,?\s+)+(?:an?|another|one|\d+)\b", re.IGNORECASE)
"""An edit that opens with a new cube joined on ("and a blue one on the right", "also two green
ones"): an addition, whatever else it is read as."""


def _refuse_addition_that_drops(plan: EditPlan, fam: Family, reference: int | None, schema: TaskSchema) -> None:
    """Refuse an addition whose new task lost a cube of the task it builds on, or gained none.

    An edit that adds (an ``add`` operation, or words of :data:`ADDITION_OPENING_RE` /
    :data:`~rpg.schema.lexicon.EDIT_ADDITIVE_RE`) keeps the rest: every cube of the reference
    version must still be in the new one (by what a person calls it, counted), and an ``add``
    operation must bring in at least one cube.  A reading that fails either applied the
    addition as a replacement or a move ("and a blue one on the right" of a red cube on the left
    had moved the red cube), a silent change of the task, so it is refused (issue 30's steering
    class 8).

    Raises:
        SteerError: a cube of the reference is missing from ``schema``, or an ``add`` added none.
    """
    from rpg.schema.meaning import descriptor

    adds = any(o.op == "add" for o in plan.ops)
    if not (adds or ADDITION_OPENING_RE.search(plan.text) or EDIT_ADDITIVE_RE.search(plan.text.lower())) \
            or reference is None or plan.fresh or any(o.op in ("remove", "recolor", "relabel", "material", "word", "count",
                                                              "dims", "colors", "swap") for o in plan.ops):
        return

    def cubes(sch: TaskSchema) -> Counter:
        return Counter(descriptor(a) for a in sch.assets if a.kind != "goal_patch")

    before, after = cubes(fam.schema(reference)), cubes(schema)
    lost = before - after
    if adds and not lost and not after - before:
        # the cubes it adds are not in the new task ("and a blue one on the right" read as a move)
        raise SteerError(f"the edit \"{plan.text.strip()[:80]}\" adds a cube, but the reading of it adds none; "
                         "say the whole task in the edit, or use --model")
    if lost:
        raise SteerError(f"the edit \"{plan.text.strip()[:80]}\" adds to the task, but the reading of it drops "
                         f"{', '.join(f'the {k} cube' for k in sorted(lost))} of v{reference}; say the whole task in the edit, "
                         "or use --model")


_STRUCTURE_NOUN = {"tower": "tower", "line": "row", "pyramid": "pyramid", "circle": "circle", "grid": "grid"}
"""The noun a structure op's kind is said with when the steering states a pivot as a whole task."""


def _pivot_with_roles(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """The task's own cubes made into the structure an edit names, with the roles it gives them ("put
    the whole thing into a tower, pink in the middle", "keep the letters, row instead, reading BAT",
    "now tower, yellow on top"): stated as a whole task ("Build a tower of the black, pink and black
    cubes, pink in the middle") and read by the parser.  None when the edit is no such pivot, the task
    has patches or cubes of both kinds, or the reading's cubes are not exactly the task's.

    Raises:
        SteerError: the roles name a cube the task lacks ("stack it instead, D at the bottom" of
            coloured cubes), or the parser cannot read them (they are refused, not dropped).
    """
    pivots = [o for o in plan.ops if o.op == "structure" and o.params.get("to") in _STRUCTURE_NOUN and not o.params.get("dims")]
    if len(pivots) != 1 or any(o.op not in ("structure", "keep", "material") for o in plan.ops) \
            or any(a.kind == "goal_patch" for a in ref.assets):
        return None
    cubes = [a for a in ref.assets if a.kind != "goal_patch"]
    text = re.sub(r"^\s*#\s*", "", plan.text)
    nouns = list(re.finditer(rf"(?i)\b{STRUCTURE_RE}", text))
    if len(nouns) == 2 and re.match(r"(?i)\s*(?:into|to)\s+(?:a|an|one)\s+(?:[a-z]+\s+)?$", text[nouns[0].end():nouns[1].start()]) \
            and re.search(r"(?i)\b(?:the|that|this|your|our)\s+(?:[a-z]+\s+)?$", text[:nouns[0].start()]):
        nouns = nouns[1:]  # "turn the pyramid into a tower of the same four cubes, white on top": the task's own, made another
    if len(nouns) != 1 or not cubes:
        return None  # ("turn the red row into a pyramid": which structure's cubes is the edit's own choice)
    noun = nouns[0]
    roles = text[noun.end():]
    roles = re.sub(rf"(?i)^\s*(?:of|with|from)\s+(?:the\s+|all\s+)?same\s+(?:(?:\d+|{COUNT_WORD_RE})\s+)?(?:cubes|blocks|ones)\b\s*,?",
                   "", roles)  # "... a tower of the same four cubes, white on top": the cubes the task has
    roles = roles[roles.index(":") + 1:] if ":" in roles else re.sub(r"(?i)^\s*(?:instead|now|please|then)\b", "", roles)
    roles = roles.strip(" ,;.!")
    if not (re.search(rf"(?i)\b(?:{COLOR_RE})\b|\breading\b|\bspell", roles) or re.search(r"\b[A-Z0-9]\b", roles)) \
            or not re.match(r"[\w']", roles):
        return None
    if all(a.kind == "colored_cube" for a in cubes):
        names = [a.color for a in cubes]
        listed = f"the {', '.join(names[:-1])} and {names[-1]} cubes" if len(names) > 1 else f"the {names[0]} cube"
    elif all(a.label for a in cubes) and len({a.kind for a in cubes}) == 1:
        names = [a.label for a in cubes]
        kind = "digit" if names[0].isdigit() else "letter"
        listed = f"the {kind} cubes {', '.join(names[:-1])} and {names[-1]}"
    else:
        return None
    labels = re.findall(r"\b([A-Z]|\d)\b" if cubes[0].label else r"\b([A-Z])\b", roles)  # (a digit among colours is a count)
    said = {canon_color(c) for c in re.findall(rf"(?i)\b(?:{COLOR_RE})\b", roles)} | set(labels)
    if said - set(names):  # "stack it instead, D at the bottom" of cubes with no D (it had been dropped)
        raise SteerError(f"the edit gives {', '.join(sorted(said - set(names)))} a place in the {pivots[0].params['to']}, but "
                         f"the task has no such cube ({', '.join(names)}); name the task's cubes, or state the whole new task")
    instruction = f"Build a {_STRUCTURE_NOUN[pivots[0].params['to']]} of {listed}, {roles}"
    try:
        schema = parse(instruction)
    except BadInput as exc:  # roles said but not read: refused, not dropped
        raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\": read as \"{instruction[:100]}\", "
                         f"{str(exc).splitlines()[0][:160]}") from None
    if sorted(a.color or a.label for a in schema.assets if a.kind != "goal_patch") != sorted(names):
        return None  # cubes made up or lost ("the red-yellow pair on top" read as two more cubes)
    before = extract(ref)
    return schema, instruction, "modify" if before is not None and before.structure == pivots[0].params["to"] else "pivot"


def plan_schema(plan: EditPlan, fam: Family, reference: int | None) -> tuple[TaskSchema, str, str]:
    """The new version's schema, its canonical instruction and the intent.

    Raises:
        SteerError: the edit does not apply to the reference task.
        ParseError / InfeasibleTask: the resulting task cannot be read or realised.
    """
    ref_schema = None if plan.fresh or reference is None else fam.schema(reference)  # read once
    if ref_schema is not None:
        check_said(plan, ref_schema)  # "same five but ...", "same letters but ...": what the version has, checked
    patches = sorted({a.color or "gray" for a in ref_schema.assets if a.kind == "goal_patch"}) if ref_schema else []
    if len(patches) == 1:  # "also a blue cube on the same patch": the task's one patch
        plan = replace(plan, text=SAME_PATCH_RE.sub(f"the {patches[0]} patch", plan.text))
    elif ref_schema is not None and not patches and (same := re.search(
            r"(?i)(?:\s*,\s*|\s+)(?:(?:in|on|at)\s+)?(?:the\s+)?same\s+(?:spot|area|place)\b", plan.text)) \
            and len(regions := {q.region for q in ref_schema.goal_predicate().walk() if q.name == "in_region"}) == 1 \
            and not re.search(r"(?i)\b(?:other|not|n't|different|away|except|than)\b", plan.text):
        # "stack them into a tower instead, same spot" of cubes in one region of the table: that region, said
        plan = replace(plan, text=plan.text[:same.start()] + ", " + region_phrase(regions.pop()) + plan.text[same.end():])
    if ref_schema is not None and not patches and SAME_PATCH_RE.search(plan.text):  # (a gray patch had been made up)
        raise SteerError(f"'{SAME_PATCH_RE.search(plan.text).group(0)}' names a patch, but v{reference} has none; say which patch "
                         "(e.g. \"on a red patch\"), or use --model")
    stacked = _stacked_in_row_order(plan.text, ref_schema) if ref_schema is not None else None
    if stacked is not None:  # "stack them in that order, R at the bottom" of a row spelling RATS
        return stacked
    copied = _copied_tower(plan.text, ref_schema) if ref_schema is not None else None
    if copied is not None:  # "build a matching tower on the right side": the tower again, there
        return copied
    restated = _tower_restated(plan.text, ref_schema) if ref_schema is not None else None
    if restated is not None:  # "make the tower five cubes: three red and then two blue on top": the whole tower again
        return restated
    recoloured = _patch_recoloured(plan.text, ref_schema, patches) if len(patches) == 1 else None
    if recoloured is not None:  # "patch should be cyan" of a tower on a patch: the one patch in that colour, the rest kept
        return recoloured
    recoloured = _patches_recoloured(plan, ref_schema) if ref_schema is not None else None
    if recoloured is not None:  # "change the red patch to orange", "paint the patch under the red cube yellow"
        return recoloured
    if ref_schema is not None and (roles := between_roles(plan.text, ref_schema)) != plan.text:  # "the middle one"
        plan = replace(interpret(roles), cue=plan.cue)
    if ref_schema is not None:
        relational = (rewrite_relation(plan.text, ref_schema) or rewrite_patch(plan.text, ref_schema)
                      or rewrite_region(plan.text, ref_schema) or rewrite_moved(plan.text, ref_schema))
        if relational is not None and not _relation_rewrite_says_all(plan.text, relational[0], ref_schema,
                                                                     any(o.op == "structure" for o in plan.ops)):
            relational = None  # "line up the M, the O and the P from left to right": a row of three, not M right of O
        if relational is not None:  # "put it in front instead", "swap them": the reference's relation, changed
            instruction, intent = relational
            if any(o.op == "structure" for o in plan.ops):  # "make it a row, green on the left": another structure
                intent = "pivot"
                instruction = _as_row(instruction, plan.ops)
            return parse(instruction), instruction, intent
    moved = in_place_move(plan.text) if ref_schema is not None and not plan.ops else None
    if moved is not None and (spec := split(ref_schema)[0]) is not None and spec.kind.spells:
        plan = replace(plan, ops=[moved], standalone=False)  # "put the white one in the middle" of a row: its middle
    if plan.standalone:
        text = _new_patch_said(strip_edit_words(plan.text), ref_schema)  # "onto a new red patch": a red patch, new to the task
        schema = parse(text)
        if plan.fresh:
            return schema, text, "fresh"
    if ref_schema is None:
        ref_schema = fam.schema(reference)
    ref_spec, carried = split(ref_schema)
    if plan.standalone:
        _refuse_invented_patch(plan.text, ref_schema, schema)
        sorted_piles = _task_cubes_sorted(plan.text, ref_schema, schema)
        if sorted_piles is not None:  # "The collection should be sorted: one pile for each colour.": the task's cubes
            return sorted_piles
        schema = _same_cubes(plan.text, ref_schema, schema)
        schema = _same_cubes_kept(plan.text, ref_schema, schema, ("same", True) in plan.checks)
        instead = re.search(r"(?i)\binstead\b(?!\s+of\b)", plan.text)
        moved = _moves_a_task_cube(plan.text, ref_schema)  # "move the red cube onto the yellow patch": its old place goes
        replaced = replaced_placement(_without_instead(text), ref_schema, parse) if (instead and _relates_a_related_pair(schema, ref_schema)) or moved else None
        if replaced is not None:  # "the cyan cube stands in front of the orange cube instead" of a task that also puts the
            # orange cube on a patch: that one placement exchanged, the rest kept (the patch had been lost as a pivot)
            return replaced[1], replaced[0], "modify"
        if ("swapped", True) in plan.checks and not same_assets(schema, ref_schema):
            raise SteerError(f"the edit announces an exchange, and what it then says ({schema.goal_summary}) is not the task's own "
                             f"cubes and patches ({ref_schema.goal_summary}); say where each of them ends, or use --model")
        if same_assets(schema, ref_schema) and (relation_of(schema) and relation_of(ref_schema) or (
                ref_spec is None and split(schema)[0] is None and ("swapped", True) in plan.checks)):
            return schema, text, "modify"  # the same cubes in another relation, or on each other's patches
        if _stacks_a_new_cube_on_the_task(schema, ref_schema) or _relates_a_new_cube_to_the_task(plan.text, schema, ref_schema):
            # "now put the green cube on the red cube": on top of it; "land the green cube next to the cyan": beside it
            return _addition(replace(plan, text=f"then {text}"), reference, ref_schema)
        intent = intent_of_standalone(extract(schema), ref_spec)
        _refuse_pivot_that_loses_cubes(plan.text, ref_schema, schema, intent, reference)
        _refuse_made_up_cubes(plan.text, ref_schema, schema, reference)
        return schema, text, intent
    swapped = (_swapped(plan, ref_schema) or _labels_exchanged(plan, ref_schema)) if ref_spec is None else None
    if swapped is not None:  # "swap yellow and red" of cubes in several relations: each takes the other's place
        return swapped
    chained = _chain_edit(plan, ref_schema) if ref_spec is None else None
    if chained is not None:  # "reverse the order" of green left of red left of blue: a chain read as its order
        return chained
    if not plan.ops:
        if plan.cue.kind != "current" and not plan.adds:  # "go back to version 1": that version as it is, named by the change from the head
            return ref_schema, ref_schema.instruction, _change_from_head(fam, ref_schema)
        return _addition(plan, reference, ref_schema)
    if all(o.op == "keep" for o in plan.ops) and EDIT_KEEP_THEN_ADD_RE.search(plan.text):
        # "keep the tower, and also put a pink cube on the orange patch": the rest kept, the clause added
        return _addition(replace(plan, text=EDIT_KEEP_THEN_ADD_RE.sub("", plan.text, count=1)), reference, ref_schema)
    _refuse_one_of_several(plan, ref_schema)
    rel = relation_of(ref_schema) if ref_spec is None else None
    if rel is not None and re.search(r"\bit\b", plan.text, re.IGNORECASE) and all(
            o.op == "recolor" and o.params["select"] == {"all": True} for o in plan.ops) and len(plan.ops) == 1:
        subject = next(a for a in ref_schema.assets if a.name == rel.subject)  # "make it blue": the cube the relation moves
        if subject.color:
            plan.ops[0].params["select"] = {"color": subject.color}
    cubes = [a for a in ref_schema.assets if a.kind == "colored_cube"]
    if ref_spec is None and len(cubes) == 1 and len(ref_schema.assets) - 1 == sum(
            a.kind == "goal_patch" for a in ref_schema.assets) and all(
            o.op == "recolor" and o.params["select"].get("all") for o in plan.ops):
        for o in plan.ops:  # "make the cube white" of a task with one cube: that cube
            o.params["select"] = {"color": cubes[0].color}
    if ref_spec is None and all(o.op == "remove" and set(o.params["select"]) == {"color"} for o in plan.ops):
        removed = remove_cubes(plan.text, ref_schema, [o.params["select"]["color"] for o in plan.ops], parse)
        if removed is not None:  # "get rid of the green block" of cubes related to each other: the rest kept
            return removed[1], removed[0], intent_of_ops(plan.ops)
    recoloured = _cubes_recoloured(plan, ref_schema) if ref_spec is None else None
    if recoloured is not None:  # "make the one on the left yellow", "make them both green": the cubes of those roles
        return recoloured
    if ref_spec is None and all(o.op == "recolor" and "color" in o.params["select"] for o in plan.ops):
        schema = ref_schema
        for o in plan.ops:
            shared = o.params["select"]["color"]
            if any(a.kind == "goal_patch" and a.color == shared for a in ref_schema.assets):
                raise SteerError(f"the {shared} cube of v{reference} stands with a {shared} patch, and its instruction does not "
                                 f"read back with only the cube's colour changed; state the whole new task, or use --model")
            try:
                schema = recolor(schema, o.params["select"]["color"], o.params["to"]["color"])
            except BadInput as exc:
                raise SteerError(str(exc)) from None
        return schema, schema.instruction, "tweak"
    if ref_spec is None and any(o.op == "structure" for o in plan.ops) and all(
            o.op in ("structure", "count", "dims", "recolor", "keep") for o in plan.ops):
        # "put them in a tower instead": the task's cubes, in no order, as the structure named
        unread = [c for c in unread_colors(plan) if not any(o.op == "recolor" for o in plan.ops)]
        if unread and (roled := _pivot_with_roles(plan, ref_schema)) is not None:
            return roled  # "put the whole thing into a tower, pink in the middle": the roles read with the cubes
        if unread:  # (the role had been dropped)
            raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\": {', '.join(repr(c) for c in unread)} has no place "
                             "in the change read (the task's cubes as the structure named, in no order); say the order "
                             "(e.g. \"from bottom to top: red, green, blue\"), or use --model")
        walk = list(ref_schema.goal_predicate().walk())
        if any(q.name == "in_region" for q in walk):  # "stack them into a tower instead" of cubes each in a corner: the
            # corner had been dropped (silently)
            raise SteerError(f"v{reference} puts its cubes in places of the table ({ref_schema.goal_summary}); the builtin steering "
                             "would drop them in the new structure: state the whole new task with its place, or use --model")
        structured = {n for q in walk if q.name in ("stack", "unordered_stack", "anchored_stack", "in_line") for n in q.object_names()}
        if structured and any(q.name == "on_patch" and q.a not in structured for q in walk):
            # "make the tower a row" of a tower and another cube on a patch
            raise SteerError(f"v{reference} has parts besides its cubes' structure ({ref_schema.goal_summary}); the builtin steering "
                             "would pull every cube into the new one and drop the patches: state the whole new task, or use --model")
        if any(o.op == "structure" and o.params.get("keep_order") for o in plan.ops):
            raise SteerError(f"the edit keeps the order of v{reference}'s cubes, but its goal gives them no one order "
                             f"({ref_schema.goal_summary}); say the order (e.g. \"from bottom to top: red, green, blue\"), or use --model")
        cubes = tuple(Item(color=a.color) if a.kind == "colored_cube" else Item(label=a.label)
                      for a in ref_schema.assets if a.kind != "goal_patch")
        ref_spec = TaskSpec("line", cubes, direction=None)
        spec = apply_ops(ref_spec, plan.ops)
        if spec.kind.spells and len(set(spec.items)) > 1:
            spec = replace(spec, direction=None)  # nobody said an order
        try:
            instruction, schema = render_carried(spec, Carried(), parse)
        except BadInput as exc:
            raise SteerError(str(exc).splitlines()[0]) from None
        return schema, instruction, "pivot"
    if ref_spec is None and all(o.op == "add" for o in plan.ops):
        return _addition(plan, reference, ref_schema)  # "also stack a white block on the cyan one": a clause of its own
    moved = _moved_to_region(plan, ref_schema)
    if moved is not None:  # "move it to the back" of cubes said only to stand in one region: that region instead
        return moved, moved.instruction, "modify"
    if ref_spec is None:
        raise SteerError(f"v{reference} ({ref_schema.goal_summary}) is not a structure the builtin steering edits in place; "
                         "state the whole new task in the edit, or use --model")
    numbers = unread_numbers(plan)
    same = {int(NUMBER_WORDS.get(m.group(1).lower(), m.group(1))) for m in re.finditer(
        rf"(?i)\bsame\s+(\d+|{COUNT_WORD_RE})\s+(?:letters|digits|numbers|cubes|blocks|ones)\b", plan.text)}
    numbers = [n for n in numbers if not (int(n) in same and int(n) == len(ref_spec.items))]  # "lay the same three letters in
    # a row" of three: the task's own count, said again
    if numbers and all(o.op == "add" for o in plan.ops):  # "same but four cubes, put a yellow one on the very top" of a
        # tower of three: the count the addition makes, said again
        try:
            made = len(apply_ops(ref_spec, plan.ops, keep_layers=carried.layers, anchors=carried.ends).items)
        except SteerError:
            made = None
        numbers = [n for n in numbers if int(n) != made]
    unread = [c for c in unread_colors(plan)  # "make that seven pink cubes" of a pink row, "make it a tower of five pink
              # cubes" of a pink tower: its own colour, not a change
              if not (set(ref_spec.colors()) == {c} and all(o.op in ("count", "structure") for o in plan.ops))] + numbers + (
        unread_labels(plan) if any(o.op == "relabel" for o in plan.ops) else [])  # (a list read as one relabel)
    if (unread or re.search(r"(?i)\b(?:reading|reads?|spell(?:s|ing)?)\b|\b[A-Z0-9]\s+(?:at|on)\s+(?:the\s+)?(?:bottom|top|base)\b",
                            plan.text)) and \
            (roled := _pivot_with_roles(plan, ref_schema)) is not None:
        dropped = [n for n in numbers if int(n) != len(ref_spec.items)]  # "lay the same four letters in a row, spelling BID"
        # of three: a count the roles' reading drops ("make it a tower of 3, pink on top" of three: the task's own)
        if dropped:
            raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\": {', '.join(repr(n) for n in dropped)} has no "
                             f"place in the change read (the task's {len(ref_spec.items)} cubes in a new structure); say the "
                             "count in a separate edit, or use --model")
        return roled  # "turn it into a single tower, same cubes: the reds at the bottom, ...", "row instead, reading BAT": the
        # roles read with the cubes (the word had been dropped)
    made = None
    if unread:
        try:
            made = apply_ops(ref_spec, plan.ops, keep_layers=carried.layers, anchors=carried.ends)
        except SteerError:
            pass
        roled_unread = [c for c in unread if re.search(rf"(?i)\b{c}s?(?:\s+(?:cube|block|one)s?)?\s+(?:is\s+|goes\s+)?(?:at|on|in)\s+(?:the\s+)?"
                                                      r"(?:very\s+)?(?:bottom|top|base|middle|left|right)\b", plan.text)]
        ends_said = {m.group(1).lower() for m in re.finditer(r"(?i)\b(?:at|on)\s+(?:the\s+)?(?:very\s+)?(bottom|top|base)\b|\bon\s+(top)\b",
                                                            plan.text)} if roled_unread else set()
        if made is not None and roled_unread and made.direction is None and made.structure == "tower" and _restated(
                plan.text, made, unread) and ends_said >= {"top"} and ends_said & {"bottom", "base"} and (
                len(made.items) <= 3 or len(set(made.items[1:-1])) == 1):
            made = replace(made, direction="left_to_right")  # "convert the line to a tower, green at the bottom and blue at
            # the top": both ends said leave one order (the roles had been dropped: a tower in any order, silently)
        if made is None or not _restated(plan.text, made, unread) or (roled_unread and made.direction is None):  # ("stack
            # them into a tower, red at the bottom" of a pyramid: a role of a structure in no order is no restatement; the
            # tower had been in any order, silently)
            raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\": {', '.join(repr(c) for c in unread)} has no place "
                             f"in the change read ({', '.join(o.op for o in plan.ops)}); say it in a separate edit, or use --model")
    try:
        spec = made or apply_ops(ref_spec, plan.ops, keep_layers=carried.layers, anchors=carried.ends)  # (made once)
    except SteerError:
        if not all(o.op == "add" for o in plan.ops):
            raise
        try:  # a cube added beside the structure, in a clause of its own: the rest kept
            return _addition(plan, reference, ref_schema)
        except SteerError:
            pass
        raise
    after = carried_after(ref_spec, carried, plan.ops)
    if any(o.op == "add_layer" for o in plan.ops) and spec.kind.layered and len(set(spec.colors())) > 1:
        after = replace(after, layers=True)  # "add a third row on top, in black": that layer's colour is judged
    try:
        instruction, schema = render_carried(spec, after, parse)
    except BadInput as exc:
        raise SteerError(str(exc).splitlines()[0]) from None
    return schema, instruction, intent_of_ops(plan.ops, ref_spec)


_END_INDEX = {"bottom": 0, "base": 0, "top": -1}
_LINE_END_INDEX = {("left_to_right", "left"): 0, ("left_to_right", "right"): -1, ("right_to_left", "right"): 0,
                   ("right_to_left", "left"): -1, ("front_to_back", "front"): 0, ("front_to_back", "back"): -1,
                   ("back_to_front", "back"): 0, ("back_to_front", "front"): -1}


def _restated(text: str, spec: TaskSpec, unread: list[str]) -> bool:
    """Whether each value an edit names that no operation read (``unread``: colours, counts) is said again of the edited
    structure ``spec`` and holds there: a tower's end ("build it upside down, yellow at the bottom and red on top" of a
    reversal), a line's end ("..., 1 at the left end"), the whole order listed after the edit's last colon, or the count of
    its cubes ("make the tower five cubes ...")."""
    names = [i.color or i.label for i in spec.items]
    low = normalize_edit(text)
    held: set[str] = set()
    if re.search(rf"\b{len(names)}\s+(?:blocks?|cubes?|high|tall|long|wide)\b", low):
        held.add(str(len(names)))
    value = rf"(?:(?:letter|digit)\s+'?)?(?P<v>{COLOR_RE}|[a-z0-9])'?(?:\s+(?:cube|block|one))?"
    for m in re.finditer(rf"\b{value}\s+(?:is\s+|goes\s+|sits\s+|ends\s+up\s+|should\s+be\s+)?(?:(?:at|on)\s+(?:the\s+)?(?:very\s+)?"
                         r"(?P<e>bottom|base|top|left|right|front|back)(?:\s+end)?|on\s+(?P<t>top))\b", low):
        v, end = canon_color(m.group("v")) if re.fullmatch(COLOR_RE, m.group("v")) else m.group("v").upper(), m.group("e") or m.group("t")
        at = _END_INDEX.get(end) if spec.structure == "tower" else _LINE_END_INDEX.get((spec.direction, end))
        if at is not None and names and str(names[at]).lower() == str(v).lower():
            held.add(str(v).lower())
    if spec.structure == "line":  # "reverse that, green first": the line's first or last cube in its own order
        for m in re.finditer(rf"\b{value}\s+(?:is\s+|goes\s+|comes\s+)?(?P<e>first|last)\b", low):
            v = canon_color(m.group("v")) if re.fullmatch(COLOR_RE, m.group("v")) else m.group("v").upper()
            if names and str(names[0 if m.group("e") == "first" else -1]).lower() == str(v).lower():
                held.add(str(v).lower())
    counted = re.sub(r"\b\d+\s+(?:blocks?|cubes?|high|tall|long|wide)\b", " ", low.rsplit(":", 1)[-1])  # "make it two cubes,
    listed = [canon_color(x) if re.fullmatch(COLOR_RE, x) else x for x in re.findall(rf"\b(?:{COLOR_RE}|\d)\b", counted)]  # yellow
    # and green": the count is no cube of the list
    if not any(str(n).isdigit() for n in names):  # "make it five, purple white purple white purple": no digit cube either
        listed = [x for x in listed if not str(x).isdigit()]
    if len(listed) == len(names) > 1 and [str(x).lower() for x in listed] == [str(n).lower() for n in names]:
        held |= {str(x).lower() for x in listed}
    return all(str(u).lower() in held for u in unread)


_ROW_OF_RELATION = {"left_of": ("left to right", False), "right_of": ("left to right", True),
                    "in_front_of": ("front to back", False), "behind": ("front to back", True)}
"""A side relation of two cubes as a row read in a direction: (direction, whether the relation's
object comes first)."""


def _as_row(instruction: str, ops: list) -> str:
    """A two-cube relation instruction restated as a row when the edit asks for a row ("turn it
    into a row, bottom cube on the left": green left of purple, in a row), else as it is."""
    if not any(o.op == "structure" and o.params.get("to") == "line" for o in ops):
        return instruction
    schema = parse(instruction)
    rel = relation_of(schema)
    if rel is None or rel.kind not in _ROW_OF_RELATION:
        return instruction
    names = {a.name: (a.color or a.label) for a in schema.assets}
    direction, object_first = _ROW_OF_RELATION[rel.kind]
    first, second = (rel.object, rel.subject) if object_first else (rel.subject, rel.object)
    return f"Put the {names[first]} and {names[second]} blocks in a row from {direction}: {names[first]}, {names[second]}"


def _swapped(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """The task with two cubes exchanged ("swap yellow and red" of "yellow between red and green";
    "switch them" of two cubes on two patches): its instruction said again with the two colours
    exchanged wherever they name a cube (a patch keeps its colour), read again.  None when the edit
    is no such swap or a colour names no one cube of the task."""
    cubes = [a.color for a in ref.assets if a.kind == "colored_cube"]
    ops = plan.ops
    if len(ops) == 1 and ops[0].op == "swap" and set(ops[0].params) == {"a", "b"} and \
            set(ops[0].params["a"]) == {"color"} == set(ops[0].params["b"]):
        a, b = ops[0].params["a"]["color"], ops[0].params["b"]["color"]
    elif not ops and EDIT_SWAP_BOTH_RE.match(plan.text) and len(cubes) == 2 and len(set(cubes)) == 2:
        a, b = cubes
    else:
        return None
    if a == b or cubes.count(a) != 1 or cubes.count(b) != 1:
        return None
    def exchange(m: re.Match) -> str:
        c = canon_color(m.group(1))
        return {a: b, b: a}.get(c, m.group(1))
    instruction = re.sub(rf"(?i)\b({COLOR_RE})\b(?!\s+(?:goal\s+|target\s+)?(?:patch|pad|mat|area|zone|square))", exchange,
                         ref.instruction)
    try:
        schema = parse(instruction)
    except BadInput as exc:
        raise SteerError(f"cannot swap the {a} and {b} cubes of the task: {str(exc).splitlines()[0]}") from None
    return schema, instruction, "modify"


def _labels_exchanged(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A task of label cubes related to each other with a label replaced ("Wrong letter, swap the K out for an L" of "cube K
    in front of cube J") or two labels exchanged ("Swap E and R" of "E between A and R"): its instruction said again with
    the labels changed where they stand alone, read again, and kept only when its meaning is the old one with exactly those
    labels changed (an article "A" or a count read as a label fails that check).  None when the edit is no such change, a
    label named is not one cube of the task, or a new label is one it has already."""
    from rpg.schema.meaning import meaning

    if not LABEL_EXCHANGE_RE.match(plan.text):
        return None  # the exchange and nothing else ("swap the K for an L on the red patch": the patch had been dropped)
    labels = [a.label for a in ref.assets if a.kind != "goal_patch" and a.label]
    material = "letters" if labels and all(x.isalpha() for x in labels) else "digits" if labels and all(x.isdigit() for x in labels) else None
    ops = [o for o in plan.ops if not (o.op == "material" and o.params == {"to": material})]  # "Wrong letter, ...": what it has
    if ops and all(o.op == "relabel" and set(o.params.get("select", {})) == {"label"} and set(o.params.get("to", {})) == {"label"}
                   for o in ops):
        mapping, intent = {o.params["select"]["label"]: o.params["to"]["label"] for o in ops}, "tweak"
        if set(mapping.values()) & set(labels):
            return None
    elif len(ops) == 1 and ops[0].op == "swap" and set(ops[0].params) == {"a", "b"} \
            and set(ops[0].params["a"]) == {"label"} == set(ops[0].params["b"]):
        a, b = ops[0].params["a"]["label"], ops[0].params["b"]["label"]
        mapping, intent = {a: b, b: a}, "modify"
    else:
        return None
    if any(labels.count(k) != 1 for k in mapping) or any(a.kind == "colored_cube" for a in ref.assets):
        return None

    def changed(text: str) -> str:
        return re.sub(r"(?<![\w'])([A-Z0-9])(?![\w'])", lambda m: mapping.get(m.group(1), m.group(1)), text)

    instruction = changed(ref.instruction)
    try:
        schema = parse(instruction)
    except BadInput:
        return None
    want = sorted(re.sub(r"(?<=[(,;|])([A-Z0-9])(?=[),;|@])", lambda m: mapping.get(m.group(1), m.group(1)), atom) for atom in meaning(ref))
    return (schema, instruction, intent) if sorted(meaning(schema)) == want else None


_CHAIN_WORDS = {"left_of": ("left_to_right", False), "right_of": ("left_to_right", True),
                "in_front_of": ("front_to_back", False), "behind": ("front_to_back", True)}
"""A side relation -> (the direction its chain is read in, whether the relation's object comes first)."""
_CHAIN_PHRASE = {"left_to_right": ("to the left of", False), "right_to_left": ("to the left of", True),
                 "front_to_back": ("in front of", False), "back_to_front": ("in front of", True)}
"""A direction -> (the relation that states it, whether the order is stated from its far end)."""


def _chain_order(ref: TaskSchema) -> tuple[list[str], str] | None:
    """The cubes' colours in order and its direction when the goal is one chain of side relations
    over three or more cubes of distinct colours ("green left of red, red left of blue": green, red,
    blue left to right); None otherwise."""
    names = {PREDICATES[name]: name for name in PAIRWISE_RELATIONS}
    parts = list(ref.goal_predicate().conjuncts())
    kinds = [names.get(type(p)) for p in parts]
    if len(parts) < 2 or any(k not in _CHAIN_WORDS for k in kinds) or len({_CHAIN_WORDS[k][0] for k in kinds}) != 1:
        return None
    direction = _CHAIN_WORDS[kinds[0]][0]  # "yellow left of orange, pink right of orange": one axis, either word
    pairs = [(p.b, p.a) if _CHAIN_WORDS[k][1] else (p.a, p.b) for p, k in zip(parts, kinds, strict=True)]  # (earlier, later)
    after = dict(pairs)
    starts = set(after) - set(after.values())
    if len(after) != len(pairs) or len(starts) != 1:
        return None
    order = [starts.pop()]
    while order[-1] in after:
        order.append(after[order[-1]])
    colors = {a.name: a.color for a in ref.assets if a.kind == "colored_cube"}
    if len(order) != len(pairs) + 1 or any(n not in colors for n in order) or len(set(colors[n] for n in order)) != len(order):
        return None
    return [colors[n] for n in order], direction


def _chain_edit(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A chain of side relations edited as the order it states: reversed ("reverse the order",
    "flip it") or read in another direction ("now make it front to back instead of left to right",
    the order kept).  None when the edit is not only that or the task is no such chain."""
    chain = _chain_order(ref)
    if chain is None or len(plan.ops) != 1:
        return None
    order, direction = chain
    op = plan.ops[0]
    t = plan.text.lower()
    first_on_top = re.search(r"\btop\s+to\s+bottom\b|\bfrom\s+the\s+top\b|\b(?:first|(?:left|front)(?:most)?)\s+(?:one\s+)?(?:on\s+top|at\s+the\s+top)\b"
                             r"|\b(?:last|(?:right|back)(?:most)?)\s+(?:one\s+)?(?:at|on)\s+the\s+bottom\b", t)
    first_below = re.search(r"\b(?:first|(?:left|front)(?:most)?)\s+(?:one\s+)?(?:at|on)\s+the\s+bottom\b"
                            r"|\b(?:last|(?:right|back)(?:most)?)\s+(?:one\s+)?(?:on\s+top|at\s+the\s+top)\b", t)
    if op.op == "structure" and op.params.get("to") == "tower" and not op.params.get("end") and (
            op.params.get("keep_order") or first_on_top or first_below):
        # "make it a tower, same order bottom to top": the chain's order from its first end up (the cubes had been
        # stacked in the order the task named them); "... top to bottom", "leftmost on top": from its first end down
        if re.search(r"\b(?:left|right)", t) and direction not in ("left_to_right", "right_to_left") \
                or re.search(r"\b(?:front|back)(?:most)?\b", t) and direction not in ("front_to_back", "back_to_front"):
            return None  # an end of another axis than the chain's: not read
        seq = order[::-1] if first_on_top else order
        instruction = "Stack the blocks from bottom to top: " + ", ".join(seq)
        return parse(instruction), instruction, "pivot"
    if op.op not in ("reverse", "direction"):
        return None
    if op.op == "reverse":
        order = order[::-1]
    else:
        direction = op.params["to"]
    phrase, from_far_end = _CHAIN_PHRASE[direction]
    seq = order[::-1] if from_far_end else order
    instruction = "Put " + " and ".join(f"the {a} block {phrase} the {b} block" for a, b in itertools.pairwise(seq))
    return parse(instruction), instruction, "modify"


def _change_from_head(fam: Family, schema: TaskSchema) -> str:
    """The intent of going back to ``schema`` from the family's head: Tweak, Modify or Pivot as a
    whole task stated against the head (two tasks with no editable structure: Tweak when their goals
    relate the same kinds of things, else Modify)."""
    from rpg.schema.meaning import meaning

    head = fam.schema(fam.load().head)
    new, now = extract(schema), extract(head)
    if new is not None and now is not None and new.structure == now.structure:
        if len(new.items) > len(now.items) and not Counter(now.items) - Counter(new.items):
            return "extend"  # "redo" of an addition: the head's cubes and more
        if Counter(new.items) == Counter(now.items) and new.items != now.items:
            return "modify"  # "undo that" of a reordering: the same cubes in another order
    if new is not None or now is not None:
        return intent_of_standalone(new, now)
    def kinds(s: TaskSchema) -> list[str]:
        return sorted({a.split("(")[0] for a in meaning(s)})

    return "tweak" if kinds(schema) == kinds(head) else "modify"


def _moves_a_task_cube(text: str, ref: TaskSchema) -> re.Match | None:
    """The move of a cube the task has (:data:`~rpg.schema.lexicon.EDIT_MOVES_A_TASK_CUBE_RE`), or None: a cube named by
    colour or label that the task lacks is added, not moved ("Land the green cube right next to the cyan" of a task with
    only a cyan cube had replaced the cyan cube's place, silently)."""
    m = EDIT_MOVES_A_TASK_CUBE_RE.match(text)
    named = re.match(rf"(?i)(?:(?P<c>{COLOR_RE})|(?:letter|digit|number)\s+'?(?P<l>[a-z0-9])'?)\b", text[m.end():]) if m else None
    if named is None:
        return m
    said = canon_color(named.group("c").lower()) if named.group("c") else named.group("l").upper()
    return m if any(said in (a.color, (a.label or "").upper()) for a in ref.assets if a.kind != "goal_patch") else None


def _relates_a_new_cube_to_the_task(edit: str, schema: TaskSchema, ref: TaskSchema) -> bool:
    """Whether a whole-task reading of an edit keeps every cube of the task, adds cubes of colours (or labels) the task lacks,
    and says nothing of the task's own cubes but how the new ones stand to them ("Land the green cube right next to the
    cyan" of a cyan cube in the middle of the table), with no word that replaces ("instead", "rather", "only"): an addition
    (read as a whole task it had dropped the cyan cube's place, silently; :func:`_addition` keeps it only when the task's own
    goal is kept whole)."""
    from rpg.schema.meaning import descriptor, meaning

    if re.search(r"(?i)\b(?:instead|rather|only|just|anymore|no\s+longer|replace\w*|scrap\w*|new\s+task|start\s+over|afresh)\b", edit):
        return False
    had = {descriptor(a) for a in ref.assets}
    now = {descriptor(a) for a in schema.assets}
    new = now - had
    if not new or had - now or any(a.kind == "goal_patch" for a in ref.assets):
        return False
    said = meaning(schema)
    if any(not re.match(r"(?:next_to|left_of|right_of|in_front_of|behind|far_from|between|on_patch|in_region|stack\([^(),]+,[^(),]+\))", a)
           for a in said):
        return False  # a structure of its own ("a 3x3x3 cube of assorted colours" of a 3x3 grid): a pivot, as before
    atoms = [set(re.findall(r"[\w:]+", a.split("(", 1)[1])) for a in said if "(" in a]
    return bool(atoms) and all(a & new for a in atoms) and any(a & had for a in atoms)


def _stacks_a_new_cube_on_the_task(schema: TaskSchema, ref: TaskSchema) -> bool:
    """Whether a whole-task reading of an edit only stacks a cube the task lacks on one it has,
    or the base of the task's tower on a cube it lacks, the task having more ("put the green cube
    on the red cube" of red on blue, "put the green cube under the blue cube"): the cube joins
    the task's, an addition (read as a whole task it had dropped the others; :func:`_addition` keeps it only
    when the task's own goal is kept whole)."""
    from rpg.schema.meaning import descriptor, meaning

    m = re.fullmatch(r"stack\(([^(),;|@]+),([^(),;|@]+)\)", "; ".join(meaning(schema)))
    had = [descriptor(a) for a in ref.assets if a.kind != "goal_patch"]
    if not m or len(had) < 2:
        return False
    if m.group(1) in had and m.group(2) not in had:
        return True
    tower = re.fullmatch(r"stack\(([^()|;@]+)\)", "; ".join(meaning(ref)))  # the new cube under the task's tower
    return m.group(1) not in had and bool(tower) and tower.group(1).split(",")[0] == m.group(2)


def _refuse_pivot_that_loses_cubes(edit: str, ref: TaskSchema, schema: TaskSchema, intent: str, reference: int) -> None:
    """Refuse a whole-task reading of an edit, not marked as a new task, that keeps none of the
    structure and fewer of the cubes of the task it builds on while naming no count and no
    structure: "blacks on the left, whites on the right" of a line of six had become one black
    cube left of one white cube, "use a gray one in the middle instead" of a cube between two
    others a gray cube in the centre of the table (a pivot that silently drops cubes).

    Raises:
        SteerError: the reading drops cubes the edit does not say to drop.
    """
    from rpg.schema.meaning import descriptor

    old = [a for a in ref.assets if a.kind != "goal_patch"]
    new = [a for a in schema.assets if a.kind != "goal_patch"]
    lost = {descriptor(a) for a in old} - {descriptor(a) for a in new}
    if intent == "pivot" and lost and EDIT_ADDITIVE_RE.search(edit.lower()):  # "Additional traffic: a pink cube onto the orange
        # patch." (the green cube had been lost: the label dropped, the rest read as a new task)
        raise SteerError(f"the edit says it adds ('{EDIT_ADDITIVE_RE.search(edit.lower()).group(0)}') but reads as a new task "
                         f"without the cubes of v{reference} ({', '.join(sorted(lost))}); say the addition with a verb (e.g. \"also put "
                         "...\"), or use --model")
    as_structure = re.search(rf"(?i)\b(?:as|into|to)\s+(?:a|one)\s+{STRUCTURE_RE}|\bmake\s+(?:it|them)\s+(?:a|one)\s+{STRUCTURE_RE}", edit)
    if intent != "pivot" or len(new) >= len(old) or re.search(rf"\b(?:\d+|{'|'.join(NUMBER_WORDS)})\b", edit, re.IGNORECASE) or (
            re.search(STRUCTURE_RE, edit, re.IGNORECASE) and not as_structure):
        return  # ("now as a tower, orange bottom pink top" of three cubes: the task's cubes as a tower, none dropped)
    raise SteerError(f"the edit reads as a new task of {len(new)} cube{'s' if len(new) != 1 else ''} ({schema.goal_summary}), but "
                     f"v{reference} has {len(old)} and the edit says neither how many nor to start a new task; say what "
                     f"changes in v{reference} (e.g. \"make the middle one gray\"), or \"new task: ...\"")


def _refuse_made_up_cubes(edit: str, ref: TaskSchema, schema: TaskSchema, reference: int) -> None:
    """Refuse a whole-task reading of an edit about the task's own cubes (:data:`~rpg.schema.lexicon.EDIT_OF_THE_TASK_RE`)
    that names no colour or label, yet whose cubes are not the task's: "tower in the back instead"
    of a purple-yellow tower had become a red-blue tower, "3 towers like that" three towers of
    colours nobody named (made-up cubes, silently).

    Raises:
        SteerError: the reading's cubes are not among the task's and the edit names none.
    """
    if not EDIT_OF_THE_TASK_RE.search(edit) or re.search(rf"(?i)\b(?:{COLOR_RE})\b|\b[A-Z]\b|\bletters?\b|\bdigits?\b", edit):
        return
    had = {a.color or a.label for a in ref.assets if a.kind != "goal_patch"}
    new = sorted({a.color or a.label for a in schema.assets if a.kind != "goal_patch"} - had)  # (more of its colours: a size)
    ref_colors = Counter(a.color or a.label for a in ref.assets if a.kind != "goal_patch")
    if not new and len(ref_colors) > 1:  # several of one colour where the task had one of each: cubes given one colour
        # because nobody named theirs ("3 towers like that" of a yellow-orange-red tower read as six red cubes)
        more = Counter(a.color or a.label for a in schema.assets if a.kind != "goal_patch") - ref_colors
        new = sorted(more) if len(more) == 1 and sum(more.values()) > 1 else []
    if new:
        raise SteerError(f"the edit reads as a new task ({schema.goal_summary}) with cubes of colours v{reference} does not "
                         f"have ({', '.join(new)}) and the edit names none; say what changes in "
                         f"v{reference} (e.g. \"move the tower to the back\"), or state the whole new task with its cubes")


_NOT_A_RELATION_RE = re.compile(r"(?i)\b(?:line\s+(?:them\s+|it\s+|\w+\s+)?up|spell\w*|reads?|words?|pyramids?|walls?|circles?|rings?"
                                r"|piles?|grids?)\b")
"""Words of a structure that no relation between two cubes is ("line them up", "spell MOP"): an edit that says one, and no
structure the steering reads, is not read as a relation of the task's cubes changed."""


def _relation_rewrite_says_all(edit: str, instruction: str, ref: TaskSchema, structure: bool = False) -> bool:
    """Whether the relation task an edit was rewritten to (:func:`rpg.steer.relations.rewrite` and its kin) keeps every
    colour and label the edit names that the reference lacks ("instead of the blue patch" names one it had), and the edit
    names no structure beyond a relation (:data:`_NOT_A_RELATION_RE`) unless it names one the steering reads: a
    long edit had been read by its one relation word ("She wants it to spell MOP, so line up the M, the O and the P from
    left to right" as M right of O; "Line them up with a gray cube: pink, purple, then gray" with gray on the wrong side)."""
    if _NOT_A_RELATION_RE.search(edit) and not structure:
        return False
    kept = re.sub(r"(?i)\b(?:instead\s+of|rather\s+than|in\s+place\s+of|not)\b[^,;.]*", " ", edit)  # ("instead of on top": the old)
    if re.search(r"(?i)\b(?:stack\w*|towers?|on\s+top)\b", kept) and not re.search(
            r"(?i)\bstack\b|\bon\s+(?:top\s+of\s+)?the\s+[\w ]+?(?:block|cube)\b", instruction):
        return False  # "stack them both in the centre, green on top": a stack the rewrite (both in the centre) had lost
    said = {canon_color(c) for c in re.findall(rf"(?i)\b(?:{COLOR_RE})\b", edit)}
    kept = {canon_color(c) for c in re.findall(rf"(?i)\b(?:{COLOR_RE})\b", instruction)} | {a.color for a in ref.assets if a.color}
    labels = {a or b for a, b in re.findall(r"\b(?:the|letter|cube|block)\s+([A-Z])\b(?!')|\b([A-Z])\s+(?:cube|block)s?\b", edit)} \
        - {a.label for a in ref.assets if a.label}  # a letter said as a cube ("the P"), not a name ("Variant B")
    return said <= kept and all(re.search(rf"\b(?:letter\s+)?{lab}\b", instruction) for lab in labels)


def _task_cubes_sorted(edit: str, ref: TaskSchema, schema: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A sort into piles by colour said of the task's cubes, naming none ("The collection should be sorted: one pile for
    each colour."): the reference's coloured cubes, each colour's own pile (the whole-task reading's cubes, the default
    colours, had been made up); None for any other edit or task."""
    from rpg.schema.meaning import meaning

    atoms = meaning(schema)
    if len(atoms) != 1 or not re.fullmatch(r"piles\([^()]*;by=color\)", atoms[0]) \
            or re.search(rf"(?i)\b(?:{COLOR_RE})\b|\b\d+\b|\b(?:letters?|digits?|numbers?)\b", edit):
        return None
    cubes = [a for a in ref.assets if a.kind != "goal_patch"]
    counts = Counter(a.color for a in cubes)
    if any(a.kind != "colored_cube" for a in cubes) or len(counts) < 2:
        return None
    listed = [f"{n} {c}" for c, n in sorted(counts.items())]
    instruction = f"Sort {', '.join(listed[:-1])} and {listed[-1]} cubes into piles by colour"
    try:
        new = parse(instruction)
    except BadInput:
        return None
    if sorted(a.color for a in new.assets if a.kind != "goal_patch") != sorted(a.color for a in cubes):
        return None
    return new, instruction, "modify"


def _same_cubes(edit: str, ref: TaskSchema, schema: TaskSchema) -> TaskSchema:
    """A whole-task edit that keeps the task's cubes and names no colour: the new task's cubes
    take the reference's colour (all one colour), as many as it had.

    Raises:
        SteerError: the reference's cubes have several colours and the edit does not say where each goes.
    """
    if not SAME_CUBES_RE.search(edit) or re.search(rf"\b(?:{COLOR_RE})\b", edit, re.IGNORECASE):
        return schema
    old = [a for a in ref.assets if a.kind != "goal_patch"]
    new = [a for a in schema.assets if a.kind != "goal_patch"]
    if len(old) != len(new) and re.search(rf"\bsame\s+(?:(?:\d+|{COUNT_WORD_RE})\s+)?(?:blocks|cubes|bricks)\b", edit, re.IGNORECASE):
        raise SteerError(f"the edit keeps the task's {len(old)} cubes, but the task it states has {len(new)}; say how many "
                         "cubes each part has, or use --model")
    if len(old) != len(new) or any(a.kind != "colored_cube" for a in old + new):
        return schema
    colors = {a.color for a in old}
    if len(colors) > 1:
        if sorted(a.color for a in old) == sorted(a.color for a in new):
            return schema
        raise SteerError(f"the edit keeps the task's cubes ({', '.join(sorted(a.color for a in old))}) but does not say "
                         "which colour goes where; name the colours in the edit, or use --model")
    (color,) = colors
    for c in sorted({a.color for a in new} - {color}):
        schema = recolor(schema, c, color, merge=True)
    return schema


def _same_cubes_kept(edit: str, ref: TaskSchema, schema: TaskSchema, kept: bool = False) -> TaskSchema:
    """A whole-task reading of an edit that keeps the task's cubes ("same letters as a tower, D at the bottom and S on top",
    "same three, but as a tower, yellow on the bottom and cyan on top", "all three in a row"): the reading when its cubes
    are the task's; a tower said by its ends with the one cube left between them (:func:`_tower_middle_filled`); else
    refused (the tower had been built of D and S alone).

    Raises:
        SteerError: the reading has other cubes than the version built on.
    """
    from rpg.schema.meaning import descriptor

    if not re.search(r"(?i)\b(?:the\s+)?same\s+(?:\d+\s+|[a-z]+\s+)?(?:letters?|digits?|numbers?|cubes|blocks|ones|tower|stack|row|line"
                     r"|pyramid|wall|pile|structure)\b", edit) \
            and not re.search(rf"(?i)\b(?:(?:the\s+)?same|all)\s+(?:\d+|{COUNT_WORD_RE})\b(?!\s*(?:more|of|x)\b|\s+(?:{COLOR_RE})\b)",
                              edit) and not kept:  # "same three, but as a tower", "all three in a row instead": the task's
        return schema  # cubes (``kept``: said so before the edit was rewritten, "same three as a tower, ...")
    had = Counter(descriptor(a) for a in ref.assets if a.kind != "goal_patch")
    now = Counter(descriptor(a) for a in schema.assets if a.kind != "goal_patch")
    if had != now:
        filled = _tower_middle_filled(edit, ref, schema)
        if filled is None:
            raise SteerError(f"the edit keeps the task's cubes, but reads as a task of other cubes ({schema.goal_summary}); name "
                             "every cube's place, or use --model")
        schema = filled
    placed = {q.name for q in ref.goal_predicate().walk() if q.name in ("in_region", "on_patch")}
    if placed - {q.name for q in schema.goal_predicate().walk()}:
        # "all three in a row instead, ..." of a tower in the back left corner: the corner had been dropped
        raise SteerError(f"the edit keeps the task's cubes but says nothing of where they stand ({ref.goal_summary}); "
                         "say the place again (e.g. \"..., in the back left corner\"), or use --model")
    return schema


def _tower_middle_filled(edit: str, ref: TaskSchema, schema: TaskSchema) -> TaskSchema | None:
    """A tower said by its two ends of a task that keeps its cubes ("same three, but as a tower, yellow on the bottom and
    cyan on top"): the one cube of the reference left over stands between them; ``None`` unless the reading is a tower of
    two cubes, both the reference's, with exactly one of the reference's cubes left (coloured cubes alone), and the edit
    says the one at the bottom and the other at the top and no other place ("cyan on top of yellow" puts cyan right on
    yellow, "yellow first and cyan second" makes cyan second: neither is filled)."""
    from rpg.schema.meaning import descriptor

    low = edit.lower()
    ends = [m.group(1) for m in re.finditer(rf"\b({COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:is\s+|goes\s+|sits\s+)?(?:(?:at|on)\s+the\s+"
                                            r"(?:very\s+)?(?:bottom|base)|at\s+the\s+(?:very\s+)?top|on\s+(?:the\s+very\s+)?top)\b(?!\s+of\b)",
                                            low)]
    if len(ends) != 2 or re.search(r"\b(?:of|under\w*|below|beneath|above|over|atop|onto|directly|just|right|first|second|third"
                                   r"|next|then|middle|after|before|between|from)\b", re.sub(r"\bfrom\s+the\s+bottom\s+up\b", " ", low)
                                   .split("tower", 1)[-1]):
        return None

    stacks = [q for q in schema.goal_predicate().walk() if q.name == "stack"]
    if len(stacks) != 1 or any(a.kind != "colored_cube" for a in schema.assets + ref.assets):
        return None
    names = stacks[0].object_names()
    by_name = {a.name: a for a in schema.assets}
    left = Counter(descriptor(a) for a in ref.assets) - Counter(descriptor(a) for a in schema.assets)
    if len(names) != 2 or len(schema.assets) != 2 or sum(left.values()) != 1 or \
            Counter(descriptor(by_name[n]) for n in names) - Counter(descriptor(a) for a in ref.assets):
        return None
    (middle,) = left
    words = [descriptor(by_name[names[0]]), middle, descriptor(by_name[names[1]])]
    if [canon_color(c) for c in ends] not in ([words[0], words[2]], [words[2], words[0]]):
        return None
    return parse("Build a tower from bottom to top: " + ", ".join(words) + ".")


def _refuse_one_of_several(plan, ref_schema) -> None:
    """Raise :class:`SteerError` when an edit recolours or removes "the blue one" (one cube, by
    colour) and the task has several cubes of that colour: which one is not said, and changing
    them all is more than was asked."""
    for o in plan.ops:
        color = (o.params.get("select") or {}).get("color") if o.op in ("recolor", "remove") else None
        n = sum(a.kind == "colored_cube" and a.color == color for a in ref_schema.assets) if color else 0
        if n > 1 and re.search(rf"\b(?:the|that|this)\s+{color}\s+(?:one|block|cube|brick)\b(?!s)", plan.text, re.IGNORECASE):
            raise SteerError(f"'the {color} one' names one of the task's {n} {color} cubes but not which; say which (e.g. "
                             f"\"the top one\"), or name them all (\"the {color} cubes\")")


def _moved_to_region(plan, ref_schema: TaskSchema) -> TaskSchema | None:
    """The task whose cubes all stand in one region (and nothing else), moved to the region the
    edit's one ``region`` op names ("Put a red cube in the middle of the table" + "move it to the
    back"); None for any other task or edit."""
    goal = ref_schema.goal_predicate().conjuncts()
    cubes = [a for a in ref_schema.assets if a.kind != "goal_patch"]
    if (len(plan.ops) != 1 or plan.ops[0].op != "region" or len(cubes) != len(ref_schema.assets) or not goal
            or any(p.name != "in_region" for p in goal) or len({p.region for p in goal}) != 1
            or len(goal) != len(cubes) or not all(a.kind == "colored_cube" for a in cubes)):
        return None
    names = " and ".join(f"the {a.color} cube" for a in cubes)
    try:
        return parse(f"Put {names} in {describe_region(plan.ops[0].params['region'])} of the table.")
    except BadInput as exc:
        raise SteerError(str(exc).splitlines()[0]) from None


def _refuse_invented_patch(edit: str, ref: TaskSchema, schema: TaskSchema) -> None:
    """Refuse a whole-task edit that says "the patch" of a task that has one, read as a patch of a
    colour nobody named ("put the blue block next to the patch instead" of the yellow patch).

    Raises:
        SteerError: the new task's patch is not the task's and its colour is not said.
    """
    had = {a.color for a in ref.assets if a.kind == "goal_patch"}
    new = [a.color for a in schema.assets if a.kind == "goal_patch" and a.color not in had]
    said = re.findall(r"\b(\w+)\s+(?:goal\s+)?patch", edit.lower())
    if had and new and re.search(r"\bthe\s+(?:goal\s+)?patch\b", edit.lower()) and not set(new) <= set(said):
        raise SteerError(f"\"{edit.strip()[:80]}\": 'the patch' is the task's {', '.join(sorted(had))} patch, but the edit read "
                         f"alone has a {', '.join(new)} patch nobody named; say the patch's colour, or state the whole new task")


def _refuse_as_parser_would(edit: str) -> None:
    """An edit steering cannot read, refused for the parser's reason where the parser names one
    (an object, shape or action the domain lacks, an unknown word), not for a pronoun (steering
    knows what "it" is).

    Raises:
        SteerError: the parser classifies what the edit asks for.
    """
    from rpg.schema.reading import Inexpressible, ParseError

    try:
        parse(strip_edit_words(edit))
    except Inexpressible as exc:
        if not all("refers to something" in why or "picks a cube" in why for _, _, why in exc.reasons):
            raise SteerError(str(exc).splitlines()[0]) from None
    except ParseError as exc:
        if str(exc).startswith("could not parse"):
            raise SteerError(str(exc).splitlines()[0]) from None
    except (BadInput, ValueError):
        pass


def _tower_restated(text: str, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A task that is one tower and nothing else (no place, patch or other cube), said again with its count and each cube's
    colour by counts that add up to it (:data:`TOWER_RESTATED_RE`: "make the tower five cubes: three red and then two blue on
    top"): the tower read from those words, checked to be one tower of exactly the colours counted; None for any other edit
    or task, or where the words do not read so."""
    from collections import Counter

    from rpg.schema.meaning import meaning

    m = TOWER_RESTATED_RE.match(text)
    if m is None or not re.fullmatch(r"stack\([^()@;|]*\)", " ".join(meaning(ref))) \
            or any(a.kind != "colored_cube" for a in ref.assets) or re.search(r"(?i)\b(?:any|random|whatever|no)\s+order\b", text):
        return None  # (letter cubes recoloured, an order said free: not the tower said again)
    n = int(NUMBER_WORDS.get(m.group("n").lower(), m.group("n")))
    rest = m.group("rest").lower()
    counted = re.findall(rf"\b(\d+|{COUNT_WORD_RE})\s+({COLOR_RE})\b", rest)
    colours = Counter({canon_color(c): 0 for _, c in counted})
    for k, c in counted:
        colours[canon_color(c)] += int(NUMBER_WORDS.get(k, k))
    if not counted or sum(colours.values()) != n or len(re.findall(rf"\b(?:{COLOR_RE})\b", rest)) != len(counted):
        return None  # a colour without its count, or counts that do not make the tower: not every cube said
    instruction = f"Build a tower of {n} cubes: {m.group('rest').strip()}"
    try:
        schema = parse(instruction)
    except (BadInput, ValueError):
        return None
    atoms = meaning(schema)
    got = re.fullmatch(r"stack\(([^()@;|]*)\)", " ".join(atoms))
    if got is None or Counter(got.group(1).split(",")) != colours:
        return None
    return schema, instruction, intent_of_standalone(extract(schema), extract(ref))


def _patch_recoloured(text: str, ref: TaskSchema, patches: list[str]) -> tuple[TaskSchema, str, str] | None:
    """The task's one patch made another colour ("make the patch cyan", "patch should be cyan": :data:`PATCH_RECOLOUR_RE`)
    with the rest of its goal kept: its instruction with that patch's colour word changed, read back and checked to mean
    the task with only the patch's colour changed (:func:`_recoloured_by_words`); None for any other edit, or where the
    instruction does not read so."""
    m = PATCH_RECOLOUR_RE.fullmatch(text.strip())
    new = canon_color(m.group(1)) if m else None
    if new is None or new == patches[0] or any(a.color == new for a in ref.assets if a.kind == "goal_patch"):
        return None
    return _recoloured_by_words(ref, {patches[0]: new}, patches=True)


_SIDE_ORDER = {"left": ("left_of", "right_of"), "right": ("right_of", "left_of"), "front": ("in_front_of", "behind"),
               "back": ("behind", "in_front_of")}
"""For "the one on the left" (and right, front, back): the relation whose subject stands there, and its mirror, whose object
does."""


def _relation_role(sel: dict, ref: TaskSchema) -> set[str] | None:
    """The cubes of a relational task (no structure) that a recolour's selector picks by their role in its relations: all
    of them ("them", "both", "all"), every cube of a colour ("the red cube"; not a patch of it), the one on one side of
    every pair on that axis ("the one on the left": the subject of
    left_of, the object of right_of; the same one in each relation), the one in the middle of a between, or its two ends;
    None where the selector picks by something else or the roles do not pick one cube."""
    cubes = {a.name for a in ref.assets if a.kind == "colored_cube"}
    if len(cubes) != sum(a.kind != "goal_patch" for a in ref.assets):
        return None  # a label cube keeps its label, not a colour
    if set(sel) <= {"all", "both"} and sel.get("all"):
        return cubes
    if set(sel) == {"color"}:  # "make the red cube green": every cube of that colour (not a patch of it)
        return {a.name for a in ref.assets if a.kind == "colored_cube" and a.color == sel["color"]} or None
    leaves = [p for p in ref.goal_predicate().walk() if not p.children()]
    if set(sel) == {"next", "of"} and set(sel["of"]) == {"color"}:  # "the cube behind the red one": the cube the goal relates so
        return _neighbour_in_relations(sel["next"], sel["of"]["color"], ref, leaves)
    if set(sel) == {"on_patch"}:  # "the cube on the red patch": the cubes the goal puts on that colour's patch
        patches = {a.name for a in ref.assets if a.kind == "goal_patch" and (a.color or "gray") == sel["on_patch"]}
        return {p.a for p in leaves if p.name == "on_patch" and p.patch in patches} or None
    if set(sel) == {"end", "n"} and sel["n"] == 1 and sel["end"] in _SIDE_ORDER:
        own, mirror = _SIDE_ORDER[sel["end"]]
        picked = {p.a for p in leaves if p.name == own} | {p.b for p in leaves if p.name == mirror}
        other = {p.b for p in leaves if p.name == own} | {p.a for p in leaves if p.name == mirror}
        end = picked - other  # a chain's end: on that side of one cube, on the other side of none
        return end if len(end) == 1 else None
    betweens = [p for p in leaves if p.name == "between"]
    if len(betweens) == 1 and set(sel) == {"position"} and sel["position"] == "middle":
        return {betweens[0].a}
    if len(betweens) == 1 and set(sel) == {"position"} and sel["position"] in ("bottom", "top"):
        return {betweens[0].b, betweens[0].c}  # "make the ends gray": both ends, said as two recolours
    return None


def _relates_a_related_pair(schema: TaskSchema, ref: TaskSchema) -> bool:
    """Whether ``schema`` (a standalone edit read) is one relation between two cubes of ``ref`` that ``ref`` also relates to
    each other ("the cyan cube in front of the orange cube" of a task with the cyan cube behind it): no cube of its own."""
    from rpg.schema.meaning import descriptor, meaning

    said = meaning(schema)
    pair = re.fullmatch(r"[a-z_]+(?:\[[^\]]*\])?\(([^(),;|]+),([^(),;|]+)\)", said[0]) if len(said) == 1 else None
    if pair is None or not {descriptor(a) for a in schema.assets} <= {descriptor(a) for a in ref.assets}:
        return False
    return any((m := re.fullmatch(r"[a-z_]+(?:\[[^\]]*\])?\(([^(),;|]+),([^(),;|]+)\)(?:@\w+)?", a))
               and {m.group(1), m.group(2)} == {pair.group(1), pair.group(2)} for a in meaning(ref))


STACKED_IN_ORDER_RE = re.compile(
    rf"(?i)^\s*(?:(?:now|then|ok(?:ay)?|so|and|actually)\s*,?\s+)*(?:stack|pile)\s+(?:them|it|all\s+of\s+them|them\s+all|the\s+(?:cubes|blocks"
    rf"|letters|digits|numbers))(?:\s+up)?(?P<kept>(?:\s+(?:instead|in\s+(?:that|the\s+same|this)\s+order))*)\s*[,:]\s*(?:with\s+)?(?:the\s+)?"
    rf"(?P<x>(?-i:[A-Z])|\d|{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+the\s+(?P<end>bottom|base|top)(?:\s*(?:,\s*and|,|and)\s+(?:the\s+)?"
    rf"(?P<y>(?-i:[A-Z])|\d|{COLOR_RE})(?:\s+(?:cube|block|one))?\s+(?:at|on)\s+the\s+(?P<end2>bottom|base|top))?\s*[.!]?\s*$")
"""A row stacked in its own order from a named end ("stack them in that order, R at the bottom", "stack them, B at the top
and X at the bottom"): read by :func:`_stacked_in_row_order`."""


def _stacked_in_row_order(text: str, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A row with an order made a tower in that order, from the end the edit names (:data:`STACKED_IN_ORDER_RE`): the named
    cube is one end of the row, and the tower takes the row's cubes from it (a second cube named must be the row's other
    end, at the tower's other end); None for any other edit, a row with no order, a named cube at neither end, or more than
    one cube's place left unsaid without "in that order" (the order would be a guess)."""
    m = STACKED_IN_ORDER_RE.match(text)
    spec = extract(ref) if m else None
    if spec is None or spec.structure != "line" or spec.direction is None or len(spec.items) < 2:
        return None
    def at(said: str) -> list[int]:
        return [i for i, it in enumerate(spec.items) if (it.label or it.color) == (said if len(said) == 1 else canon_color(said))]

    named, ends = at(m.group("x")), {0, len(spec.items) - 1}
    if len(named) != 1 or named[0] not in ends:
        return None
    if m.group("y") and (at(m.group("y")) != [next(iter(ends - {named[0]}))] or {m.group("end"), m.group("end2")} - {"base"} !=
                         {"bottom", "top"}):
        return None  # "B at the top and X at the bottom": the row's other end, at the tower's other end
    unsaid = len(spec.items) - (2 if m.group("y") else 1)
    if "order" not in m.group("kept") and unsaid > 1:
        return None  # "stack them, R at the bottom" of four: the others' order is not said
    items = list(spec.items) if named[0] == 0 else list(reversed(spec.items))
    if m.group("end") == "top":
        items.reverse()
    try:
        instruction, schema = render_carried(TaskSpec("tower", tuple(items)), Carried(), parse)
    except BadInput:
        return None
    return schema, instruction, "pivot"


_PATCH_NOUN = r"(?:goal\s+|target\s+)?(?:patch|patches|pad|pads|mat|mats)\b"


def _recoloured_by_words(ref: TaskSchema, change: dict[str, str], patches: bool) -> tuple[TaskSchema, str, str] | None:
    """``ref`` with the colours of ``change`` changed in the cubes' words (``patches`` False: every colour word not before a
    patch's noun) or the patches' (True: only those before one): the instruction rewritten, read back and kept only where
    it means ``ref`` with exactly those colours changed (cubes' or patches' atoms alone); None otherwise."""
    from rpg.schema.meaning import meaning

    which = r"(?=\s+" + _PATCH_NOUN + ")" if patches else r"(?!\s+" + _PATCH_NOUN + ")"
    words = re.compile(rf"(?i)\b({'|'.join(map(re.escape, change))})\b{which}")
    instruction = words.sub(lambda m: change[m.group(1).lower()], ref.instruction)
    if instruction == ref.instruction:
        return None
    try:
        schema = parse(instruction)
    except (BadInput, ValueError):
        return None
    token = re.compile(r"(?<=patch:)([a-z]+)" if patches else r"(?<![:\w])([a-z]+)(?=[,;)|]|$)")
    want = sorted(token.sub(lambda m: change.get(m.group(1), m.group(1)), a) for a in meaning(ref))
    return (schema, instruction, "tweak") if sorted(meaning(schema)) == want else None


_NEIGHBOUR_RELATIONS = {"behind": ("behind", "in_front_of"), "front": ("in_front_of", "behind"), "left": ("left_of", "right_of"),
                        "right": ("right_of", "left_of"), "beside": ("next_to", "next_to"), "far": ("far_from", "far_from"),
                        "above": ("stack", None), "below": (None, "stack")}
"""A neighbour pick's side -> (the relation whose subject is the cube picked, the one whose object is)."""


def _neighbour_in_relations(side: str, colour: str, ref: TaskSchema, leaves: list) -> set[str] | None:
    """The one cube a task of relations puts on ``side`` of the cube of ``colour`` ("the cube behind the red one": X of
    behind(X, red) or in_front_of(red, X)); None where no one cube stands so (then the edit is refused)."""
    anchors = {a.name for a in ref.assets if a.kind == "colored_cube" and a.color == colour}
    own, mirror = _NEIGHBOUR_RELATIONS.get(side, (None, None))
    if len(anchors) != 1:
        return None
    (anchor,) = anchors
    picked = set()
    for p in leaves:
        a, b = getattr(p, "a", None), getattr(p, "b", None)
        if p.name == own and b == anchor and a is not None:
            picked.add(a)
        if p.name == mirror and a == anchor and b is not None:
            picked.add(b)
    return picked if len(picked) == 1 else None


def _patch_colour(sel: dict, ref: TaskSchema) -> str | None:
    """The colour of the patch a selector names: said ("the red patch"), or the one patch the goal puts a cube of a colour on
    ("the patch under the red cube"); None where no one patch is named so."""
    if "patch_of" not in sel:
        return sel.get("patch") or sel.get("color")
    colour = {a.name: a.color for a in ref.assets}
    under = {colour[p.patch] or "gray" for p in ref.goal_predicate().walk() if p.name == "on_patch" and colour.get(p.a) == sel["patch_of"]}
    return under.pop() if len(under) == 1 else None


def _patches_recoloured(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """Patches recoloured, named by colour ("make the red patch purple", "instead of the green patch use the blue one") or
    by the cube on them ("paint the patch under the red cube yellow"), in any task: the instruction with each patch's colour
    word changed, read back and kept only where it means the task with those patches' colours changed
    (:func:`_recoloured_by_words`); None where the edit recolours no patch.

    Raises:
        SteerError: a patch recoloured beside other changes, or not read back so."""
    if not plan.ops or any(o.op != "recolor" or "color" not in o.params["to"] for o in plan.ops):
        return None
    said = [o for o in plan.ops if {"patch", "patch_of"} & set(o.params["select"]) or set(o.params["select"]) == {"color"} and re.search(
        rf"(?i)\b{re.escape(o.params['select']['color'])}\s+{_PATCH_NOUN}", plan.text)]
    if not said:
        return None
    olds = [_patch_colour(o.params["select"], ref) for o in plan.ops] if len(said) == len(plan.ops) else [None]
    done = None if None in olds else _recoloured_by_words(
        ref, {old: o.params["to"]["color"] for old, o in zip(olds, plan.ops, strict=True)}, patches=True)
    if done is None:
        raise SteerError(f"the edit \"{plan.text.strip()[:80]}\" recolours a patch, and the task's instruction does not read back with "
                         "only that patch's colour changed; change one patch per edit (named by its colour), state the whole new "
                         "task, or use --model")
    return done


def _cubes_recoloured(plan: EditPlan, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """Cubes of a relational task recoloured, picked by their relations ("make the one on the left yellow", "the cube in the
    middle should be white", "make them both green", "make the ends gray") or by colour, or a patch named by its colour
    ("make the red patch purple"): the instruction with each picked colour's words changed (the cubes' or the patches'),
    read back and kept only where it means the task with those colours changed and nothing else
    (:func:`_recoloured_by_words`); None for any other edit, or where a picked colour is shared with a cube not picked (its
    words would name both)."""
    if not plan.ops or any(o.op != "recolor" or "color" not in o.params["to"] for o in plan.ops):
        return None
    names = {a.name: a.color for a in ref.assets if a.kind == "colored_cube"}
    change: dict[str, str] = {}
    picked_all: set[str] = set()
    for o in plan.ops:
        picked = _relation_role(o.params["select"], ref)
        if not picked:
            return None
        picked_all |= picked
        for n in picked:
            if change.get(names[n], o.params["to"]["color"]) != o.params["to"]["color"]:
                return None  # one colour made two
            change[names[n]] = o.params["to"]["color"]
    if any(c in change and n not in picked_all for n, c in names.items()) or all(old == new for old, new in change.items()):
        return None
    return _recoloured_by_words(ref, change, patches=False)


def _pair(atom: str) -> frozenset[str] | None:
    """The two cubes a relation atom of :func:`rpg.schema.meaning.meaning` relates (``left_of(red,blue)``,
    ``stack(blue,red)``), or None for an atom over more or fewer."""
    m = re.fullmatch(r"[a-z_]+(?:\[[^\]]*\])?\(([^(),;|]+),([^(),;|]+)\)(?:@\w+)?", atom)
    return frozenset(m.groups()) if m and m.group(1) != m.group(2) else None


def _without_instead(text: str) -> str:
    """``text`` without its "instead" (not "instead of"): a placement said again, read as one placement."""
    return re.sub(r"(?i)\s*\binstead\b(?!\s+of\b)", "", text)


def _new_patch_said(text: str, ref: TaskSchema | None) -> str:
    """``text`` with a patch said as new (:data:`NEW_PATCH_RE`, "onto a new green patch") said as a patch of its colour,
    when the task has no patch of that colour; else as it is (a new patch of a colour the task has is a second one, which
    the builtin steering does not make: it is refused, never merged into the task's)."""
    have = {a.color for a in ref.assets if a.kind == "goal_patch"} if ref is not None else set()

    def sub(m: re.Match) -> str:
        colour = re.match(rf"\s*({COLOR_RE})\b", text[m.end():], re.IGNORECASE)
        return m.group(0) if colour is None or canon_color(colour.group(1)) in have else f"{m.group(1)} "
    return NEW_PATCH_RE.sub(sub, text)


def _copied_tower(text: str, ref: TaskSchema) -> tuple[TaskSchema, str, str] | None:
    """A copy of the task's one tower, its cubes in the same order, in a place of the table the edit names
    (:data:`STRUCTURE_COPIED_RE`): the tower stated again where it stands, then its copy there; None for any other edit.

    Raises:
        SteerError: the task is no single tower in order, the copy's place is the tower's own, or the two do not read back
            as the task's tower and its copy (checked, so nothing else is lost or added)."""
    from collections import Counter

    from rpg.schema.meaning import meaning

    m = STRUCTURE_COPIED_RE.match(text)
    if m is None:
        return None
    spec, carried = split(ref)
    places = places_said(f" {m.group('place')} ")
    where = next(iter(places)) if len(places) == 1 else None
    if spec is None or spec.structure != "tower" or spec.direction is None or any(i.label for i in spec.items) or where is None \
            or carried.region == where or carried.patch or carried.layers or carried.ends:
        raise SteerError(f"'{m.group(0).strip()}' copies the task's tower to {m.group('place')}; the builtin steering copies one tower "
                         "of coloured cubes in an order to another place of the table; state the whole new task, or use --model")
    colours = [i.color for i in spec.items]
    listed = f"{', '.join(colours[:-1])} and {colours[-1]} from the bottom"
    made = f"Stack {listed}{' ' + region_phrase(carried.region) if carried.region else ''}. Stack another {listed} " \
           f"{region_phrase(where)}."  # (the task stated anew, a sentence each: its own words had not read back beside the copy)
    try:
        schema = parse(made)
    except (BadInput, ValueError) as exc:
        raise SteerError(f"the task's tower and its copy {m.group('place')} do not read back together ({str(exc).splitlines()[0]}); "
                         "state the whole new task, or use --model") from None
    copy = f"stack({','.join(colours)})@{where}"
    if Counter(meaning(schema)) != Counter(meaning(ref)) + Counter([copy]):
        raise SteerError(f"the task's tower and its copy {m.group('place')} read back as {schema.goal_summary!r}, not the tower and "
                         "its copy; state the whole new task, or use --model")
    return schema, made, "extend"


def _extends(old: str, new: str) -> bool:
    """Whether meaning atom ``new`` is tower ``old`` built higher or lower (``stack(blue,red)`` ->
    ``stack(blue,red,green)`` or ``stack(green,blue,red)``, the same place): the old tower's
    order kept, whole, with cubes only above or below it (none between its cubes); or a cube in a place of the table
    (``in_region(brown,back_right)``) the base of a tower there (``stack(brown,green)@back_right``)."""
    a = re.fullmatch(r"stack\(([^()|;]*)\)(@\w+)?", old)
    b = re.fullmatch(r"stack\(([^()|;]*)\)(@\w+)?", new)
    placed = re.fullmatch(r"in_region\(([^(),|;]+),(\w+)\)", old)
    if placed and b and b.group(2) == f"@{placed.group(2)}" and b.group(1).split(",")[0] == placed.group(1):
        return True  # a cube in a place of the table made a tower's base there ("stack a green cube on it" of the brown cube
        # in the back right corner): its place kept, as the tower's
    if not (a and b) or a.group(2) != b.group(2):
        return False
    was, now = a.group(1).split(","), b.group(1).split(",")
    return len(now) > len(was) and any(now[i:i + len(was)] == was for i in range(len(now) - len(was) + 1))


def _addition(plan: EditPlan, reference: int, ref_schema: TaskSchema) -> tuple[TaskSchema, str, str]:
    """An edit that adds to the task in a clause of its own ("also stack a white block on the
    cyan one"): the reference's instruction, then the clause.  Kept only when every atom of
    the reference's meaning is still there and the clause adds one (an addition keeps the rest).

    Raises:
        SteerError: no clause to add, or the two do not read as the reference plus more.
    """
    from collections import Counter

    from rpg.schema.meaning import descriptor, meaning

    where = f"v{reference} ({ref_schema.goal_summary})"
    clause = addition_clause(plan.text)
    cubes = [a for a in ref_schema.assets if a.kind != "goal_patch"]
    if clause is None and len(cubes) == 1 and re.search(r"(?i)\b(?:next\s+to|beside|behind|in\s+front\s+of|on(?:to)?|under|"
                                                          r"(?:left|right)\s+of|near|on\s+top\s+of|atop|above|below)\s+it\b", plan.text):
        if any(a.kind == "goal_patch" for a in ref_schema.assets) and re.search(
                r"(?i)\bon(?:to)?\s+it\s*,?\s*(?:too|as\s+well)\b|\balso\b[^.;]*\bon(?:to)?\s+it\b", plan.text):
            try:  # ("the block that's closest to the robot": refused for that first)
                parse(re.sub(r"(?i)\bit\b", "the patch", plan.text))
            except BadInput as exc:
                raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\": {str(exc).splitlines()[0]}") from None
            except ValueError:
                pass
            raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\" to {where}: 'on it' may be the cube or the patch "
                             "it stands on; name which (e.g. \"on the orange cube\" or \"on the patch\")")  # ("+ a brown cube on
            # it too" of a cube on a patch had been stacked on the cube; "too" says the patch)
        one = f"the {cubes[0].color} block" if cubes[0].color else f"the {cubes[0].label} block"  # the task's one cube
        clause = addition_clause(re.sub(r"(?i)\bit\b", one, plan.text))
    spec = split(ref_schema)[0] if clause is None and len(cubes) > 1 else None
    if spec is not None and spec.structure == "tower" and IT_ON_A_PATCH_RE.match(plan.text):  # "stand it on the blue patch" of
        # a tower: the tower (a wider structure is no patch's: a pyramid or wall there had crashed)
        clause = addition_clause(IT_ON_A_PATCH_RE.sub(r"\g<v> the tower \g<p>", plan.text, count=1))
    towered = TOWER_TO_PATCH_RE.match(plan.text)
    bottoms = [p.objects[0] for p in ref_schema.goal_predicate().conjuncts() if isinstance(p, Stack)] if towered else []
    tower_moved = len(bottoms) == 1 and bottoms[0] in {p.a for p in ref_schema.goal_predicate().conjuncts() if type(p) is OnPatch}
    if tower_moved:  # "move the stack to the yellow patch" of a tower on a patch: its bottom cube moved there, from its patch
        cube = next(a for a in ref_schema.assets if a.name == bottoms[0])
        clause = addition_clause(f"move the {cube.color or cube.label} block {towered.group('p')}")
    named = [f"the {a.color} block" if a.color else f"the {a.label} block" for a in cubes]
    if clause is None and len(cubes) == 2 and len(set(named)) == 2 and BETWEEN_THEM_RE.search(plan.text.lower()):
        # "put a green cube between them": between the task's two cubes
        clause = addition_clause(BETWEEN_THEM_RE.sub(f"between {named[0]} and {named[1]}", plan.text.lower()))
    action = NO_GOAL_RE.search(plan.text.lower())
    if action is not None and not re.search(r"\b(?:on|onto|in|into|next|beside|behind|under|left|right|front|top)\b", plan.text.lower()):
        raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\" to {where}: it says no end state: "
                         f"'{action.group(0)}' is an action, and a task's goal says where cubes end up; say where the cube should go")
    if clause is None:
        _refuse_as_parser_would(plan.text)
        raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\" to {where}: it refers to the task but names no "
                         "change the builtin steering reads (add, remove, recolour, resize, reorder, move it, another "
                         "structure); say what to change, e.g. \"make the top block red\", or use --model")
    instead = re.search(r"(?i)\binstead\b(?!\s+of\b)", plan.text)
    moved = _moves_a_task_cube(plan.text, ref_schema) or tower_moved  # "move the pink one onto a new green patch": its old
    # place goes too
    replaced = replaced_placement(_new_patch_said(_without_instead(clause), ref_schema), ref_schema, parse) \
        if instead or moved else None
    if replaced is not None:  # "put the red cube to the right of the green one instead": that one placement exchanged
        text, schema = replaced
        return schema, text, "modify"
    if instead:  # "put the pink one on the red patch instead": its old place goes, which an addition would keep
        raise SteerError(f"cannot apply the edit \"{plan.text.strip()[:80]}\" to {where}: 'instead' replaces what the task "
                         "says of that cube, and the builtin steering reads it only as one more placement; say the whole "
                         "new task in the edit, or use --model")
    text = f"{ref_schema.instruction.strip().rstrip('.!')}, then {clause}"
    try:
        schema = parse(text)
    except (BadInput, ValueError) as exc:
        kept_too = EDIT_KEEP_TOO_RE.sub("", clause)  # "Move the cyan cube to the front left corner as well, right next to the brown one":
        # its old place kept too is a contradiction (one cube in two corners), so "as well" is the other cube's; a move
        if "contradiction" in str(exc) and EDIT_KEEP_TOO_RE.search(plan.text) and _moves_a_task_cube(EDIT_KEEP_TOO_RE.sub("", plan.text), ref_schema):
            replaced = replaced_placement(_new_patch_said(kept_too, ref_schema), ref_schema, parse)
            if replaced is not None:
                return replaced[1], replaced[0], "modify"
        raise SteerError(f"cannot add \"{clause}\" to {where}: {str(exc).splitlines()[0]}") from None
    before, now = Counter(per_cube(meaning(ref_schema))), Counter(per_cube(meaning(schema)))
    had = Counter(descriptor(a) for a in ref_schema.assets)
    opened = (re.match(r"\s*(?:and|also|plus)\b", plan.text, re.IGNORECASE)  # "and the blue block in the corner": one more
              or EDIT_CONTINUES_RE.match(plan.text.lower())  # "then put the green cube on the red cube"
              or re.search(r"\b(?:too|as\s+well|also)\s*[.!]?\s*$", plan.text, re.IGNORECASE))  # "... on the red patch too"
    no_patch = not any(a.kind == "goal_patch" for a in ref_schema.assets)  # "the orange patch" of a task with none: a new one
    said_as_new = (r"\b(?:an?|another|one more|\d+|two|three|four)\s+(?:new\s+|more\s+|extra\s+|second\s+|2nd\s+|third\s+|3rd\s+)?"
                   if not opened else r"\b")  # after "and", "also", "then", "too": "the green cube", "C" are the new ones
    invented = [d for d in Counter(descriptor(a) for a in schema.assets) - had  # a new cube is one said with "a", "another", a count
                if not ((no_patch or re.search(rf"(?i)\b{re.escape(d.split(':')[-1])}\s+(?:goal\s+|target\s+)?(?:patch|pad|mat)\b", clause))
                        and d.startswith("patch:"))  # a patch named by its colour: the edit names it
                and not re.search(rf"{said_as_new}{re.escape(d.split(':')[-1])}\b", clause, re.IGNORECASE)]
    if invented:
        raise SteerError(f"cannot add \"{clause}\" to {where}: together they read as {schema.goal_summary!r}, with "
                         f"{', '.join(invented)} nobody named; name it, or state the whole new task in the edit")
    added = now - before
    related = [_pair(a) for a in before]
    clash = next((a for a in added if _pair(a) and _pair(a) in related  # a second cube of a colour on a patch is no clash
                  and not a.startswith("on_patch(")), None)
    if clash is not None:  # "stack the yellow block on the purple block too" when it stands in front of it
        raise SteerError(f"cannot add \"{clause}\" to {where}: {clash} would relate two cubes the task already relates "
                         f"({next(a for a in before if _pair(a) == _pair(clash))}); the two contradict. Say one, or state the "
                         "whole new task")
    lost = [a for a in before - now if not any(_extends(a, b) for b in now - before)]  # a tower built higher is kept
    if lost or not now - before:
        raise SteerError(f"cannot add \"{clause}\" to {where}: together they read as {schema.goal_summary!r}, which does not "
                         "keep the task's goal and add to it; state the whole new task in the edit, or use --model")
    return schema, text, "extend"


def _refuse_no_change(plan: EditPlan, fam: Family, reference: int | None, schema: TaskSchema) -> None:
    """Refuse an edit of the current version that leaves its goal as it was (same meaning, and the
    same summary or the same goal predicates): the edit was not read as what it asks (a back-reference, or an edit built on an
    earlier version for its cubes, that returns to a version is not one; ``reference`` None).

    Raises:
        SteerError: nothing the goal judges changed.
    """
    from rpg.schema.meaning import meaning

    if plan.fresh or plan.cue.kind != "current" or reference is None:
        return
    ref = fam.schema(reference)
    same_goal = schema.goal_summary == ref.goal_summary or schema.goal.to_dict() == ref.goal.to_dict()
    if meaning(schema) == meaning(ref) and same_goal:  # (a summary worded otherwise of the same predicates is no change:
        # "Extend the wall: a fourth cube in each row" had rebuilt the same wall, summarised as a 1x3x2 block)
        raise SteerError(f"the edit \"{plan.text.strip()[:80]}\" changes nothing v{reference}'s goal judges ({ref.goal_summary}); "
                         "say what should be different, or use --model")


def _added_cube_named(edit: str, hist: FamilyHistory, fam: Family) -> str:
    """``edit`` with "the cube you added" written as that cube ("the black cube"): the one cube the head version has
    that its parent lacks.

    Raises:
        SteerError: the head is the base, added no cube or several, or the edit says "the cube you added before that".
    """
    from rpg.schema.meaning import descriptor

    m = ADDED_CUBE_RE.search(edit)
    if m is None:
        return edit
    head = hist.get(hist.head)
    if m.group("before"):
        raise SteerError(f"'{m.group(0)}' names a cube of an edit before the last, which the builtin steering does not trace "
                         "back; name the cube by its colour")
    if head.parent is None:
        raise SteerError(f"'{m.group(0)}': v{hist.head} is the base task, to which no cube was added; name the cube by its colour")
    new = Counter(descriptor(a) for a in fam.schema(hist.head).assets if a.kind != "goal_patch") - Counter(
        descriptor(a) for a in fam.schema(head.parent).assets if a.kind != "goal_patch")
    if sum(new.values()) != 1:
        raise SteerError(f"'{m.group(0)}': v{hist.head} added {sum(new.values()) or 'no'} cubes to v{head.parent}; "
                         "name the cube by its colour")
    said = next(iter(new))
    cube = f"the {said} cube" if said in PALETTE else f"the {said} block"
    return edit[:m.start()] + cube + edit[m.end():]


def _two_cubes(hist: FamilyHistory, fam: Family) -> list | None:
    """The head version's two cubes when it has exactly two, both coloured and of two colours, and nothing else but patches
    (the task "them", "the two" and "only the blue one" name); else ``None``."""
    cubes = [a for a in fam.schema(hist.head).assets if a.kind != "goal_patch"]
    if len(cubes) != 2 or any(a.kind != "colored_cube" for a in cubes) or cubes[0].color == cubes[1].color:
        return None
    return cubes


_BETWEEN_THEM_RE = re.compile(r"(?i)\b(?:in\s+)?between\s+(?:them|the\s+two(?:\s+(?:cubes|blocks|of\s+them))?|those\s+two)\b")
"""A place between the two cubes of the task, said by a pronoun ("stick a gray cube in between them")."""


def _between_them_named(edit: str, hist: FamilyHistory, fam: Family) -> str:
    """``edit`` with "between them" written as between the head version's two cubes (:func:`_two_cubes`: "between the black
    cube and the white cube"); else ``edit`` as it is (refused later: which two?)."""
    m = _BETWEEN_THEM_RE.search(edit)
    if m is None or len(re.findall(rf"(?i)\b(?:{COLOR_RE})\b", edit)) != 1:
        return edit  # (only the cube put between named: "add a green and a yellow cube ... and a gray one between the two" is
        # of the cubes the edit adds)
    cubes = _two_cubes(hist, fam)
    if cubes is None:
        return edit
    return f"{edit[:m.start()]}between the {cubes[0].color} cube and the {cubes[1].color} cube{edit[m.end():]}"


_ONLY_CUBE_RE = re.compile(rf"(?i)^\s*(?:(?:ok(?:ay)?|now|so|actually|hmm+)\s*,?\s*)*(?:just|only)\s+the\s+(?P<c>{COLOR_RE})\s+(?:cube|block|one)"
                           r"(?:\s+(?:this\s+time|now|then|please|instead))*\s*[.!]?\s*$")
"""An edit that keeps one cube of the task ("Only the blue cube this time.")."""


def _only_cube_named(edit: str, hist: FamilyHistory, fam: Family) -> str:
    """``edit`` as the removal of the head version's other cube when it keeps one cube by its colour ("Only the blue cube
    this time." of a red and a blue cube on a patch: "remove the red cube"): the head's two cubes (:func:`_two_cubes`), one of
    them the one named; else ``edit`` as it is."""
    m = _ONLY_CUBE_RE.match(edit)
    if m is None:
        return edit
    cubes = _two_cubes(hist, fam)
    kept = canon_color(m.group("c").lower())
    if cubes is None or kept not in {a.color for a in cubes}:
        return edit
    return f"remove the {next(a.color for a in cubes if a.color != kept)} cube"


def _rows_swapped_named(edit: str, hist: FamilyHistory, fam: Family) -> str:
    """``edit`` as the exchange of the two colours of the head version's two layers when it swaps its rows (:data:`~rpg.schema.lexicon.ROWS_SWAPPED_RE`)
    and each layer is of one colour of its own ("Swap the rows" of a wall of brown under gray: "swap brown and gray"); a
    restatement after it ("...: gray on the bottom, brown on top") must say that result, or the edit stays as said (and is
    refused).  Else ``edit`` as it is (a swap of rows had been refused as a reference)."""
    m = ROWS_SWAPPED_RE.match(edit)
    if m is None:
        return edit
    head = fam.schema(hist.head)
    colour = {a.name: a.color for a in head.assets if a.kind == "colored_cube"}
    layered = [p for p in head.goal_predicate().walk() if isinstance(p, InLayers)]
    if len(layered) != 1 or any(o not in colour for o in layered[0].objects):
        return edit
    by_level: dict[int, set[str]] = {}
    for o, level in zip(layered[0].objects, layered[0].levels, strict=True):
        by_level.setdefault(level, set()).add(colour[o])
    if sorted(by_level) != [0, 1] or any(len(c) != 1 for c in by_level.values()) or by_level[0] == by_level[1]:
        return edit
    low, high = next(iter(by_level[0])), next(iter(by_level[1]))
    if m.group("rest"):
        said = re.fullmatch(rf"(?i)\s*(?:the\s+)?(?P<b>{COLOR_RE})(?:\s+(?:row|layer|ones?|cubes?))?\s+(?:on|at)\s+the\s+(?:bottom|base)\s*"
                            rf"(?:,|and|;)\s*(?:and\s+)?(?:the\s+)?(?P<t>{COLOR_RE})(?:\s+(?:row|layer|ones?|cubes?))?\s+(?:on\s+top|at\s+the\s+top)\s*",
                            m.group("rest"))
        if said is None or (canon_color(said.group("b").lower()), canon_color(said.group("t").lower())) != (high, low):
            return edit
    return f"swap {low} and {high}"


class RouteAnswer(BaseModel):
    """The model's reading of an edit: intent, reference version, extracted parameters."""

    model_config = ConfigDict(extra="forbid")

    intent: Literal["tweak", "extend", "modify", "pivot", "fresh"]
    reference: int | None = None
    parameters: dict = Field(default_factory=dict)


ROUTE_PROMPT = """You route edits of a robot-manipulation task family (paper: RoboPlayground, steering).
Classify the edit into one intent:
- tweak: parameter changes only (colors, counts, sizes); builds on the current version
- extend: additive changes (add cubes or goals); builds on the current version
- modify: property changes within the existing structure (asset material, ordering); current version
- pivot: a structural rewrite that overwrites the goals; current version
- fresh: an unrelated new task; no reference
The reference is the version the edit builds on: the current (head) version unless the edit refers back
("go back to", "the earlier version", "version 2", "the letter version", "when it was just red and blue"),
or unless it needs assets (letter or digit cubes) that only an earlier version has.
Answer with one JSON object: {"intent": ..., "reference": <version id or null>, "parameters": {...}}.

Versions (id, intent, description, goal summary, assets):
"""


def llm_route(edit: str, hist: FamilyHistory, client) -> RouteAnswer:
    """Ask the model for the edit's intent and reference version (validated, with retries)."""
    from rpg.schema.llm import ask_validated

    listing = "\n".join(f"v{v.version_id} [{v.intent}] {v.description} | {v.goal_summary} | {', '.join(v.assets_used)}"
                        for v in hist.versions)
    messages = [{"role": "system", "content": ROUTE_PROMPT + listing + f"\nCurrent version: v{hist.head}\n"},
                {"role": "user", "content": edit}]

    def validate(doc: dict) -> RouteAnswer:
        ans = RouteAnswer.model_validate(doc)
        if ans.intent == "fresh":
            ans.reference = None
        elif ans.reference is None or not 0 <= ans.reference < len(hist.versions):
            raise ValueError(f"reference must be a version id from 0 to {len(hist.versions) - 1} for intent {ans.intent}")
        return ans

    return ask_validated(client, messages, "route", validate)


def llm_edit_schema(edit: str, intent: str, reference: TaskSchema, client) -> TaskSchema:
    """Ask the model for the new version's TaskSchema: the reference's schema with the edit applied."""
    from rpg.schema.llm import ask_validated, system_prompt

    flags = ", ".join(k for k, v in PRESERVATION[intent].items() if v) or "nothing"
    messages = [{"role": "system", "content": system_prompt()},
                {"role": "user", "content": f"Reference task (TaskSchema JSON):\n{reference.model_dump_json()}\n\n"
                                            f"Edit ({intent}; preserve {flags}): {edit}\n"
                                            "Answer with the complete TaskSchema of the edited task."}]
    return ask_validated(client, messages, "schema", TaskSchema.model_validate)


def steer(family: str | Path, edit: str | None, seed: int | None = None, disabled: frozenset[str] = frozenset(),
          llm=None, replay: str | Path | None = None, author: str | None = None,
          enabled: frozenset[str] = frozenset(), dry_run: bool = False) -> SteerResult:
    """Apply an edit to a family (a compiled task becomes v0 of a new family first).

    ``enabled`` names optional gates the new version must pass too (e.g. ``{"solvable"}``).

    With ``dry_run`` the edit is read, classified and its task checked for feasibility as it would be, and nothing
    is built or written: the result has the intent, reference, instruction and ``schema`` of the version it would
    record, ``version`` None and ``valid`` False (a compiled task that is not yet a family is previewed on a copy).

    With ``llm`` (an :class:`rpg.schema.llm.LLMClient`) the model classifies the edit and
    writes the new schema; its exchanges are recorded in the version's ``llm_log.jsonl``,
    and ``replay`` (that file or the version directory) re-applies them offline.

    Raises:
        SteerError: the edit cannot be interpreted or applied (the family is unchanged).
        FamilyError / ArtifactError: not a family or artifact, or a corrupt history.
        ParseError / InfeasibleTask: the edited task cannot be read or realised.
        ProviderError / ModelOutputError / ReplayError: as for ``compile_instruction``.
    """
    if replay is not None:
        from rpg.schema.llm import LLMClient, load_record

        header, exchanges = load_record(replay)
        edit, llm = header["instruction"], LLMClient(header["model"], replay=exchanges)
    if not edit or not edit.strip():
        raise SteerError("the edit is empty; say what to change, e.g. \"add a green block on top\"")
    if not dry_run:
        from rpg.validate.sandbox import prepare

        prepare()  # the new version's validation child starts up while the edit is read
    from rpg.compiler import check_text
    from rpg.validate.gates import check_gate_names, check_optional_gates

    check_text(edit, "the edit")
    edit = re.sub(r"[ \t]{2,}", " ", edit)  # a run of blanks is one (the readers' patterns had taken minutes over 7000)
    disabled = check_gate_names(disabled)
    enabled = check_optional_gates(enabled)
    path = Path(family)
    if dry_run and not is_family(path):
        load_artifact(path)  # (not a task: refused as steer refuses it)
        with tempfile.TemporaryDirectory(prefix="rpg-preview-") as tmp:
            copy = Path(tmp) / path.name
            shutil.copytree(path, copy)
            create_family(copy)
            result = steer(copy, edit, seed, disabled, llm=llm, author=author, enabled=enabled, dry_run=True)
        result.family = path
        return result
    if not is_family(path):
        from filelock import FileLock

        lock_file = path.parent / f".{path.name}.family.lock"
        try:  # refuse a path that is no artifact before anything is written beside it ...
            load_artifact(path)
        except ArtifactError:
            if not lock_file.exists():
                raise
            # ... unless another steer holds the lock and is moving it into v0 right now: its
            # files are half moved; the check under the lock below decides
        # the first steer turns the artifact into a family: once, even when two steer at once
        with FileLock(str(lock_file), timeout=LOCK_TIMEOUT_S):
            if not is_family(path):
                load_artifact(path)
                create_family(path)
    fam = Family(path)
    with fam.lock():
        hist = fam.load()
        if not dry_run:
            fam.remove_orphans(hist)
        extra, backend = None, "builtin"
        said, label = edit, VARIANT_LABEL_RE.match(edit)  # the edit as said is what the version records
        if label and int(label.group("n")) >= len(hist.versions) and edit[label.end():].strip():
            edit = edit[label.end():]  # "v2: add a green cube" of a family of v0 only: the label of the variant made
        edit = _added_cube_named(edit, hist, fam)
        if llm is None:
            edit = _between_them_named(edit, hist, fam)  # "stick a gray cube in between them" of a task of two cubes
            edit = _only_cube_named(edit, hist, fam)  # "Only the blue cube this time." of a task of two cubes
            edit = _rows_swapped_named(edit, hist, fam)  # "Swap the rows." of a wall of two one-coloured rows
            plan = interpret(edit)
            reference, notes = resolve_reference(plan, hist, fam)
            notes += [f"set aside: {x!r} (a reason said for the change)" for x in plan.set_aside]
            schema, instruction, intent = plan_schema(plan, fam, reference)
            parameters = plan.parameters()
            _refuse_no_change(plan, fam, reference if reference == hist.head else None, schema)
            _refuse_addition_that_drops(plan, fam, reference, schema)
        else:
            from rpg.schema.llm import llm_parse

            route = llm_route(edit, hist, llm)
            intent, reference, parameters = route.intent, route.reference, route.parameters
            notes = [f"model {llm.model}: {intent}, reference {'none' if reference is None else f'v{reference}'}"]
            schema = (llm_parse(edit, llm) if intent == "fresh"
                      else llm_edit_schema(edit, intent, fam.schema(reference), llm))
            instruction, backend = schema.instruction, "litellm"
        schema = check_feasibility(schema)
        if llm is not None:
            extra = {"llm_log.jsonl": llm.log_text(edit, "steer")}
        if seed is None:
            seed = int(load_artifact(fam.version_dir(hist.head))[1].get("provenance", {}).get("seed", 0))
        result = SteerResult(path, said, intent, reference, None, False, instruction=instruction, notes=notes,
                             parameters=parameters, schema=schema)
        if dry_run:
            return result
        digest = task_hash(schema)
        same = next((v for v in hist.versions if (v.task_hash or v.code_hash) == digest), None)
        if same is not None:
            hist.head = same.version_id
            fam.save(hist)
            result.version, result.valid, result.reused = same.version_id, True, True
            result.notes.append(f"the edit loops back to v{same.version_id}; reusing it (no new version)")
            return result
        vid = len(hist.versions)
        compiled = build(schema, path, seed, disabled, backend=backend, model=llm.model if llm else None,
                         name=f"v{vid}", extra_files=extra, author=author, enabled=enabled)
        result.compile = compiled
        if not compiled.valid:
            result.notes.append(f"validation failed after repair; the attempt is in {compiled.path}")
            return result
        parent = hist.get(reference if reference is not None else hist.head)
        snap = snapshot_of(compiled.path, vid, said, parent, reference, intent, parameters, PRESERVATION[intent])
        hist.versions.append(snap)
        hist.head = vid
        fam.save(hist)
        result.version, result.valid = vid, True
        return result
