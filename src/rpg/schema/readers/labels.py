"""Readers of labelled cubes: rotate a label to face a way, equations, spelled words."""

from __future__ import annotations

import re

from rpg.domain import constants as C
from rpg.domain.layouts import (
    line_layout,
    stack_layout,
)
from rpg.domain.predicates import (
    Equation,
    InLine,
    LabelFacing,
    Reads,
    Stack,
)
from rpg.domain.state import Pose
from rpg.schema.builder import Builder
from rpg.schema.readers.common import (
    directed_line,
    direction_of,
    line_axis,
    orientation_showing,
    single_label,
    spelled_word,
)
from rpg.schema.readers.registry import reader
from rpg.schema.reading import Features, ParseError


@reader(order=70)
def recognize_rotate(f: Features, b: Builder) -> bool:
    m = re.search(r"\b(faces?|facing|shows?|showing|points?|pointing)\s+(up|upward|upwards|the camera|the robot|front|forward|toward the robot|toward the camera)", f.text)
    if not m and not f.has("rotate", "rotated", "turn", "flip"):
        return False
    label = single_label(f)
    if label is None:
        return False
    direction = "up" if (m is None or m.group(2).startswith("up")) else "front"
    others = [ch for ch in "ABCDEFGHIJKLMNOPQRSTUVWXYZ" if ch != label][:5] if label.isalpha() else [d for d in "0123456789" if d != label][:5]
    faces = {"-x": label, "+x": others[0], "+y": others[1], "-y": others[2], "+z": others[3], "-z": others[4]}
    if direction == "front":
        faces = {"+z": label, "+x": others[0], "+y": others[1], "-y": others[2], "-x": others[3], "-z": others[4]}
    name = b.semantic(label, faces)
    face = "-x" if direction == "up" else "+z"
    quat = orientation_showing(face, direction)
    b.place({name: Pose((*C.WORKSPACE_CENTER, C.TABLE_TOP_Z + C.CUBE_EDGE / 2 + C.SPAWN_CLEARANCE), quat)})
    b.preds.append(LabelFacing(name, label, direction))
    b.primitives += ["rotate"]
    b.summary.append(f"the cube shows {label!r} facing {direction}, upright")
    return True


EQUATION_RE = re.compile(r"(?<!\d)(?<!\d\.)(\d\s*[+\-x*\u00d7]\s*\d\s*=\s*\d+)(?!\d|\.\d)")


@reader(order=80)
def recognize_equation(f: Features, b: Builder) -> bool:
    m = EQUATION_RE.search(f.original)
    if not (m or f.has("equation", "math", "maths", "arithmetic", "sum")):
        return False
    text = re.sub(r"\s+", "", m.group(1)).replace("*", "x").replace("\u00d7", "x") if m else "3+4=7"
    left, result = text.split("=")
    a, op, c = int(left[0]), left[1], int(left[2])
    if {"+": a + c, "-": a - c, "x": a * c}[op] != int(result):
        raise ParseError(f"{text} is not a correct equation, so no arrangement of it can succeed; "
                         "give a true one (e.g. 2+3=5)")
    names = [b.semantic(ch) for ch in text]
    b.place(line_layout(names))
    b.preds += [InLine(tuple(names), order="left_to_right"), Equation(tuple(names))]
    b.primitives += ["arrange"]
    b.summary.append(f"the cubes read a correct equation left to right (e.g. {text})")
    return True


@reader(order=90)
def recognize_spell(f: Features, b: Builder) -> bool:
    word = spelled_word(f)
    if word is None or not f.has("spell", "spells", "spelling", "word", "read", "reads"):
        return False
    if re.search(r"\b(?:backwards?|reversed|in\s+reverse(?:\s+order)?)\b", f.text):
        word = word[::-1]  # "spell CAT backwards": the cubes read TAC
    names = [b.semantic(ch) for ch in word]
    if f.has("tower", "stack", "stacked", "stacking", "column", "vertical", "vertically") or re.search(
            r"\b(?:top\s+to\s+(?:the\s+)?bottom|bottom\s+to\s+(?:the\s+)?top)\b", f.text):  # "stacked to read BED from top to bottom"
        upward = re.search(r"\b(?:(?:from\s+)?(?:the\s+)?bottom\s+(?:to\s+(?:the\s+)?top|up(?:wards?)?)|upwards?)\b", f.text)
        bottom_first = names if upward else list(reversed(names))  # "read D, O, G from bottom to top": D at the bottom
        direction = "bottom_to_top" if upward else "top_to_bottom"
        b.place(stack_layout(bottom_first, C.WORKSPACE_CENTER))
        b.preds += [Stack(tuple(bottom_first)), Reads(tuple(names), word, direction, "front")]
        b.summary.append(f"a tower whose front faces read {word!r} from {direction.replace('_', ' ')}")
        b.primitives += ["stack"]
    else:
        direction = direction_of(f)
        b.place(directed_line(names, direction))
        b.preds += [InLine(tuple(names), axis=line_axis(direction), order=direction), Reads(tuple(names), word, direction)]
        b.summary.append(f"the cubes spell {word!r} {direction.replace('_', ' ')} in a line")
        b.primitives += ["arrange"]
    return True
