"""rpg's public task API: everything a generated ``code.py`` may import.

    from rpg.task_api import BlockTask, ColoredCube, Pose, Stack, sample_scattered

Generated task code imports only this module, numpy and math (checked by the text gate).
"""

from rpg.domain import constants
from rpg.domain.assets import ColoredCube, GoalPatch, SemanticCube
from rpg.domain.layouts import (
    circle_layout,
    cluster_layout,
    grid_layout,
    line_layout,
    pyramid_layout,
    stack_layout,
)
from rpg.domain.predicates import (
    AnchoredLine,
    AnchoredStack,
    And,
    Behind,
    Between,
    Bridge,
    CentredIn,
    Equation,
    FarFrom,
    Grid,
    InCircle,
    InFrontOf,
    InLayers,
    InLine,
    InOrder,
    InRegion,
    LabelFacing,
    LayersUniform,
    LeftOf,
    NextTo,
    Not,
    On,
    OnPatch,
    OnTable,
    Piles,
    Pyramid,
    Reads,
    RightOf,
    SortedBy,
    Stack,
    StackOnPatch,
    TemporalMonitor,
    UnorderedStack,
    Upright,
)
from rpg.domain.sampling import sample_scattered
from rpg.domain.state import Pose, quat_mul, yaw_quat
from rpg.domain.task_code import BlockTask

__all__ = [
    "AnchoredLine", "AnchoredStack", "And", "Behind", "Between", "BlockTask", "Bridge", "CentredIn", "ColoredCube", "Equation", "FarFrom", "GoalPatch", "Grid",
    "InCircle", "InFrontOf", "InLayers", "InLine", "InOrder", "InRegion", "LabelFacing", "LayersUniform", "LeftOf",
    "NextTo", "Not", "On", "OnPatch", "OnTable", "Piles", "Pose", "Pyramid", "Reads",
    "RightOf", "SemanticCube", "SortedBy", "Stack", "StackOnPatch", "TemporalMonitor", "UnorderedStack", "Upright",
    "circle_layout", "cluster_layout", "constants", "grid_layout", "line_layout",
    "pyramid_layout", "quat_mul", "sample_scattered", "stack_layout", "yaw_quat",
]
