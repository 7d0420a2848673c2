"""Every number that defines the block domain, in one place.

Units are SI throughout: metres (m), radians (rad), seconds (s), kilograms (kg).

World frame (used by every relation and reading order in the project):
    The robot stands at the origin looking along +x.  +z is up.
    "left"  = +y,  "right"  = -y,
    "in front of" = closer to the robot (smaller x), "behind" = larger x.
    "From left to right" runs from +y to -y.
    The default camera is fixed behind and above the robot looking along +x, so the
    left of every snapshot is +y.

Sources: "paper" is ``shared/paper/roboplayground.tex``; the section is named at each
constant.  Values marked "project" are this project's own choices, documented here.
"""

from __future__ import annotations

import math

# ---------------------------------------------------------------------------
# Table and workspace (paper, appendix "Simulation Configuration")
# ---------------------------------------------------------------------------
TABLE_TOP_Z: float = 0.95
"""Height of the table surface above the floor, m (paper, Simulation Configuration)."""

WORKSPACE_X: tuple[float, float] = (0.40, 0.70)
"""Workspace bounds along x, m (paper, Simulation Configuration)."""

WORKSPACE_Y: tuple[float, float] = (-0.25, 0.25)
"""Workspace bounds along y, m (paper, Simulation Configuration)."""

WORKSPACE_CENTER: tuple[float, float] = (
    0.5 * (WORKSPACE_X[0] + WORKSPACE_X[1]),
    0.5 * (WORKSPACE_Y[0] + WORKSPACE_Y[1]),
)
"""Centre of the workspace in the table plane, m."""

TABLE_HALF_EXTENT: tuple[float, float, float] = (0.40, 0.60, 0.025)
"""Half sizes of the table box (x, y, z), m (project).  Larger than the workspace."""

TABLE_CENTER_XY: tuple[float, float] = (0.55, 0.0)
"""Centre of the table box in the plane, m (project)."""

FLOOR_RGBA: tuple[float, float, float, float] = (0.315, 0.335, 0.365, 1.0)
"""Colour of the untextured floor of the validation scene (the mean of the environments'
checker squares), RGBA in [0, 1] (project)."""

FLOOR_GRID: float = 0.5
"""Spacing of the floor plane's rendering grid, m (MuJoCo draws a plane as quads of this
side, twice with shadows: at 0.05 m the 12 m floor was 57,600 quads and half of a
snapshot's rendering time).  Physics does not read it (project)."""

BOUNDS_MARGIN: float = 0.005
"""Slack on the workspace bounds for an object's centre in the bounds gate, m (project)."""

# ---------------------------------------------------------------------------
# Assets (project)
# ---------------------------------------------------------------------------
CUBE_EDGE: float = 0.04
"""Default cube edge length, m (4 cm)."""

CUBE_EDGE_RANGE: tuple[float, float] = (0.02, 0.08)
"""Cube edges (m) the trusted side accepts from task code's data (project: half to twice
:data:`CUBE_EDGE`; every builtin cube is :data:`CUBE_EDGE`)."""

CUBE_MASS: float = 0.05
"""Mass of one cube, kg."""

CUBE_FRICTION: tuple[float, float, float] = (1.0, 0.005, 0.0001)
"""Sliding, torsional and rolling friction of cubes and table."""

PATCH_SIZE: tuple[float, float] = (0.08, 0.08)
"""Full extents (x, y) of a square goal patch, m."""

LONG_PATCH_SIZE: tuple[float, float] = (0.08, 0.20)
"""Full extents (x, y) of a "long" goal patch, m."""

PATCH_THICKNESS: float = 0.001
"""Full thickness of a goal patch, m.  Patches are visual only and never collide."""

GLYPH_TEXTURE_PX: int = 128
"""Side of one face image of a semantic cube's texture, pixels."""

MAX_DISTINCT_LETTERS: int = 26
"""Distinct letter labels available (A-Z) (paper, Task Proposal Feasibility Reasoning)."""

MAX_DISTINCT_DIGITS: int = 10
"""Distinct digit labels available (0-9) (paper, Task Proposal Feasibility Reasoning)."""

MAX_OBJECTS: int = 64
"""Most cubes one task may hold (project)."""

MAX_TOWER_HEIGHT: float = 0.40
"""Highest a structure may rise above the table, m: the reach of a tabletop arm (project)."""

# ---------------------------------------------------------------------------
# Physics, fixed globally and not per task (paper, Simulation Configuration)
# ---------------------------------------------------------------------------
TIMESTEP: float = 0.002
"""Simulation time step, s."""

IMPRATIO: float = 10.0
"""Frictional-to-normal constraint impedance ratio (elliptic cones)."""

GRAVITY: tuple[float, float, float] = (0.0, 0.0, -9.81)
"""Gravity, m/s^2."""

CONTACT_SOLREF: tuple[float, float] = (0.005, 1.0)
"""Cube and table contact solref (time constant s, damping ratio).

Measured to keep a 27-cube block within 0.1 mm over 5000 steps (project).
"""

CONTACT_SOLIMP: tuple[float, float, float, float, float] = (0.95, 0.99, 0.001, 0.5, 2.0)
"""Cube and table contact solimp (dmin, dmax, width m, midpoint, power)."""

# ---------------------------------------------------------------------------
# Validation (paper, appendix "Validation Parameters and Stability Checks")
# ---------------------------------------------------------------------------
SETTLE_STEPS: int = 50
"""Zero-action steps to settle a goal state before checking G (paper)."""

STABILITY_STEPS: int = 50
"""Further zero-action steps over which the goal state must stay stable (paper)."""

SMOKE_STEPS: int = 10
"""Zero-action steps of the smoke gate (project)."""

MAX_DRIFT: float = 0.01
"""Largest allowed displacement of an object during the stability window, m (paper)."""

MAX_DROP: float = 0.02
"""Largest allowed fall of an object (toppling) during the stability window, m (paper)."""

NONTRIVIAL_SEEDS: int = 5
"""Seeds on which the non-trivial gate resets the task (project)."""

NONTRIVIAL_MIN_FALSE: int = 4
"""Of NONTRIVIAL_SEEDS resets, at least this many must have G false (project)."""

SOLVABLE_SEEDS: int = 5
"""Episodes (seeds seed, seed+1, ...) the oracle runs in the optional ``solvable`` gate (project;
issue "oracle ... and a solvable gate")."""

SOLVABLE_MIN_SUCCESS: int = 3
"""Of SOLVABLE_SEEDS oracle episodes, at least this many must succeed (project); the gate stops
once this many did, or once so many failed that this many cannot."""

SOLVABLE_EMBODIMENT: str = "floating_gripper"
"""The embodiment the ``solvable`` gate's oracle drives (project: the gate asks whether a
gripper can build the goal at all, not whether one arm reaches it)."""

# ---------------------------------------------------------------------------
# Initial-state distribution rho_0 (project)
# ---------------------------------------------------------------------------
MIN_SEPARATION: float = 0.07
"""Default minimum centre distance between sampled objects, m."""

DEFAULT_YAW_RANGE: float = math.pi / 4
"""Default half-range of sampled yaw, rad (cubes are symmetric every pi/2)."""

SPAWN_CLEARANCE: float = 0.0005
"""Gap between a spawned cube and what it rests on, m."""

MAX_SAMPLING_TRIES: int = 2000
"""Rejection-sampling attempts before a layout is declared infeasible."""

MAX_TRIVIAL_REDRAWS: int = 50
"""Times a rho_0 sample in which G already holds is drawn again at reset (project; issue
"rpg eval": a policy that does nothing must score 0)."""

INITIAL_DRAWS: int = 3
"""Samples of rho_0 the sandbox returns per seed at first; the rest of the
MAX_TRIVIAL_REDRAWS + 1 are asked for only when all of these satisfy G (project: a cost
bound, it does not change which sample a seed gets)."""

MAX_REGION_REDRAWS: int = 200
"""Whole layouts drawn at most to keep cubes outside their goal regions (``avoid``)."""

# ---------------------------------------------------------------------------
# Predicate tolerances (project)
# ---------------------------------------------------------------------------
ON_XY_TOL: float = 0.5 * CUBE_EDGE
"""`on(a, b)`: largest horizontal offset of a's centre from b's centre, m."""

ON_Z_TOL: float = 0.008
"""`on(a, b)`: tolerance on the vertical gap (a.z - b.z - contact height), m."""

TABLE_Z_TOL: float = 0.008
"""`on_table(a)`: tolerance on a's centre height above the table, m."""

RELATION_MIN_GAP: float = 0.02
"""`left_of` etc.: least separation along the relation's axis, m."""

RELATION_MAX_OFF_AXIS: float = 0.10
"""`left_of` etc.: largest offset across the relation's axis, m."""

NEXT_TO_MAX_DIST: float = 0.08
"""`next_to(a, b)`: largest centre distance in the plane, m."""

FAR_FROM_MIN_DIST: float = 0.20
"""`far_from(a, b)`: least centre distance in the plane, m (two thirds of the workspace depth)."""

REGION_NAMES: tuple[str, ...] = ("center", "front", "back", "left", "right",
                                 "front_left", "front_right", "back_left", "back_right")
"""Named regions of the workspace for `in_region`: the workspace split in thirds along x
(front = near the robot, smaller x; back) and along y (left = +y; right); ``center`` is the
middle third both ways, a side (``left``) is its whole third, a corner (``back_left``) is
where two thirds meet (project)."""

REGION_GROUPS: dict[str, tuple[str, ...]] = {
    "corner": ("back_left", "back_right", "front_left", "front_right"),
    "edge": ("back", "front", "left", "right"),
}
"""Places said without saying which one: "at the corner of the table" is any of the four
corners, "at the edge" any of the four sides (the outer ring of the 3x3 split, i.e. anywhere
but the ``center``).  `in_region` over a group holds in any of its members, because the
instruction names none of them (issue 30, "never add what was not said") (project)."""

LINE_TOL: float = 0.015
"""`in_line`, `between`: largest offset of a centre from the fitted line, m."""

LINE_MAX_GAP: float = 0.12
"""`in_line`: largest centre spacing between neighbours in the line, m."""

CIRCLE_RADIUS_TOL: float = 0.015
"""`in_circle`: largest deviation of a centre from the mean radius, m."""

CIRCLE_MIN_RADIUS: float = 0.04
"""`in_circle`: smallest mean radius that counts as a circle, m."""

GRID_TOL: float = 0.012
"""`grid`, `pyramid`: largest offset of a centre from its lattice site, m."""

PILE_RADIUS: float = 0.09
"""`piles`: largest distance of a member from its pile's centroid, m."""

PILE_SEPARATION: float = 0.10
"""`piles`: least distance between the centroids of two piles, m."""

PILE_LINK: float = 0.075
"""`piles` with explicit groups: two cubes closer than this (centres, m) belong to the same
pile (single linkage); cubes in a pile touch (~0.05 m apart), piles are >= PILE_SEPARATION apart."""

PATCH_XY_MARGIN: float = 0.005
"""`on_patch`: a centre may overhang the patch edge by this much, m."""

UPRIGHT_COS: float = 0.97
"""`upright(a)`: least cosine between the cube's local +z and world +z."""

# ---------------------------------------------------------------------------
# Visibility and readability (paper, appendix "Geometric Visibility and Face Readability")
# ---------------------------------------------------------------------------
VISIBILITY_SAMPLE_FRACTION: float = 0.8
"""Face sample points sit at this fraction of the half extent from the centre (paper)."""

VISIBILITY_MIN_RAYS: int = 3
"""A face is visible if at least this many of its 5 rays are unobstructed (paper)."""

READABLE_NORMAL_COS: float = 0.97
"""Least cosine between a face normal and the expected viewing direction (~14 deg) (paper)."""

READABLE_UP_COS: float = 0.94
"""Least cosine between a glyph's up vector and the expected up (~20 deg) (paper)."""

VISIBILITY_MIN_FACING_COS: float = 0.1
"""A face seen edge-on (cosine between its normal and the direction to the camera below
this) is not visible, whatever its rays hit (project)."""

RAY_HIT_TOL: float = 0.002
"""A ray reaches its sample point if it first hits the face within this distance, m."""

# ---------------------------------------------------------------------------
# Camera and snapshots (project)
# ---------------------------------------------------------------------------
CAMERA_NAME: str = "default"
"""Name of the fixed default camera."""

CAMERA_POS: tuple[float, float, float] = (0.05, 0.0, 1.42)
"""Default camera position, m: behind and above the robot."""

CAMERA_TARGET: tuple[float, float, float] = (0.56, 0.0, TABLE_TOP_Z)
"""Point the default camera looks at, m."""

CAMERA_FOVY: float = 45.0
"""Vertical field of view of the default camera, degrees."""

SNAPSHOT_SIZE: tuple[int, int] = (640, 480)
"""Snapshot width and height, pixels."""

SNAPSHOT_SHADOW_SIZE: int = 1024
"""Side of the shadow map used for snapshots, texels (MuJoCo's default is 4096).  On a
software renderer (Mesa llvmpipe) a 4096 map doubles the CPU time of a snapshot; at
640x480 the two images differ by < 0.05 grey levels on average."""

# ---------------------------------------------------------------------------
# Robot, control and episodes (project, issue 14; defaults follow robosuite / LIBERO)
# ---------------------------------------------------------------------------
ROBOT_BASE_POS: tuple[float, float, float] = (0.0, 0.0, TABLE_TOP_Z)
"""Panda base (``link0``) position, m: at the world origin, mounted at table height, facing
+x.  Every point of the workspace is within 0.75 m of it, inside the arm's reach (project)."""

CONTROL_HZ: float = 20.0
"""Control frequency of the environment, Hz (robosuite, LIBERO, ManiSkill3 defaults)."""

CONTROL_SUBSTEPS: int = round(1.0 / (CONTROL_HZ * TIMESTEP))
"""Physics steps per control step (25 at 2 ms)."""

TCP_OFFSET: float = 0.1034
"""Tool centre point (between the finger pads) along the hand's +z from the hand frame, m
(Franka Emika's flange-to-TCP distance)."""

HOME_QPOS: tuple[float, ...] = (0.0, -0.3389, 0.0, -2.649, 0.0, 2.310, 0.785398)
"""Panda joint angles (rad) of the home pose: TCP at (0.40, 0, table + HOME_TCP_HEIGHT),
gripper pointing down, fingers closing along y (solved with the IK, project)."""

HOME_TCP_QUAT: tuple[float, float, float, float] = (0.0, 1.0, 0.0, 0.0)
"""TCP (and hand) orientation at home, w, x, y, z: approach axis (the hand's +z) pointing
down, fingers closing along world y (a half turn about world x).  Top-down grasps turn it
about world z (project)."""

HOME_TCP_HEIGHT: float = 0.25
"""Height of the TCP above the table at home (both embodiments), m (project)."""

GRIPPER_CTRL_OPEN: float = 255.0
"""Menagerie hand actuator command of a fully open gripper (its ``ctrlrange`` is 0-255)."""

GRIPPER_RELEASE_CTRL: float = 180.0
"""Least actuator command that releases a held 4 cm cube, measured (issue 14)."""

GRIPPER_GAIN: float = 5.0
"""Gain multiplier of the hand's finger actuator, both embodiments.  The stock Menagerie gain
squeezes ~2 N (a real Panda hand holds 70 N): a 4 cm cube slipped out of the floating hand
12/100 times at 1x and 0/100 at 5x (issue 14), and out of the Panda's hand when a policy
lifts at full speed (1 m/s) at 1x (measured: 2 of 12 scripted stacks)."""

FINGER_PAD_FRICTION: tuple[float, float, float] = (1.0, 0.005, 0.0001)
"""Sliding, torsional and rolling friction of the finger pads (condim 4: torsional
friction keeps a held cube from twisting; measured 100/100 stacks vs 83/100 at condim 3)."""

FINGER_PAD_CONDIM: int = 4
"""Contact dimensionality of finger-pad contacts (see FINGER_PAD_FRICTION)."""

EE_DELTA_POS_LIMIT: float = 0.05
"""``ee_delta`` control: largest TCP translation per control step, m (an action of 1.0;
robosuite's OSC default output limit)."""

EE_DELTA_ROT_LIMIT: float = 0.5
"""``ee_delta`` control: largest TCP rotation per control step, rad (robosuite's default)."""

MOCAP_WELD_SOLREF: tuple[float, float] = (0.02, 1.0)
"""solref of the weld between the floating hand and its mocap target (time constant s,
damping ratio): stiff enough to lift, soft enough not to fling a cube it touches (project)."""

MOCAP_INTERPOLATION_POINTS: int = 5
"""Increments in which the floating hand's mocap target moves to a control step's target
(every CONTROL_SUBSTEPS / 5 = 5 physics steps, 10 ms): at most 1 cm and 0.1 rad at a time
(project)."""

JOINT_INTERPOLATION_POINTS: int = 5
"""Increments in which the Panda's joint targets move to a control step's targets (every
CONTROL_SUBSTEPS / 5 = 5 physics steps, 10 ms), as a robot's controller interpolates a
20 Hz policy's commands (project)."""

GOAL_REEVALUATE_TOL: float = 1e-9
"""An environment re-evaluates G after a step only when some object's position (m) or
quaternion component moved more than this since G was last evaluated (objects at rest
drift ~1e-13 per control step; every predicate tolerance is millimetres or more), which
takes the predicates off most control steps (project)."""

RESET_SETTLE_STEPS: int = 50
"""Physics steps after placing rho_0's sample and the robot's home pose, before the first
observation of an episode (project)."""

EPISODE_BASE_STEPS: int = 80
"""Control steps of every episode before the per-cube allowance (project)."""

EPISODE_STEPS_PER_CUBE: int = 150
"""Control steps added per movable cube: one pick and place at 20 Hz takes ~100 with the
floating gripper and ~130 with the Panda (the oracle, measured; project)."""

DENSE_GAP: float = 0.015
"""A goal layout is dense around a cube when a neighbour in its layer stands closer than
this (m, face to face): no finger fits between them (project)."""

EPISODE_STEPS_PER_PUSH: int = 50
"""Control steps added per cube whose goal is dense (:data:`DENSE_GAP`): it is released
beside its goal and pushed in, a push of ~40 steps with the Panda (the oracle, measured;
project).  A 14-cube pyramid got 2180 steps without it, and the Panda's oracle needed
1730-2180 (project).
``max_episode_steps = EPISODE_BASE_STEPS + EPISODE_STEPS_PER_CUBE * cubes
+ EPISODE_STEPS_PER_PUSH * dense cubes``."""

AGENTVIEW_POS: tuple[float, float, float] = (1.45, 0.0, TABLE_TOP_Z + 0.90)
"""Agentview camera position, m: across the table, facing the robot, 1.45 m in front of its
base and 0.90 m above the table, pitched 36.5 degrees down: LIBERO's agentview (1.32 m in
front of its robot's base, 0.71 m above the table, 38.9 degrees; its tabletop scenes)
moved back and up so that the Panda's home pose, whose hand is higher than LIBERO's, shows
its hand, forearm and upper arm above the workspace (issue 32: the camera at
(1.15, 0, 1.50) looking at the workspace saw only the hand).  Its image's left is the
robot's right (-y)."""

AGENTVIEW_TARGET: tuple[float, float, float] = (0.30, 0.0, TABLE_TOP_Z + 0.05)
"""Point the agentview camera looks at, m."""

AGENTVIEW_FOVY: float = 45.0
"""Vertical field of view of the agentview camera, degrees (LIBERO's, MuJoCo's default)."""

WRIST_CAMERA_FOVY: float = 75.0
"""Vertical field of view of the wrist camera, degrees."""

ENV_IMAGE_SIZE: tuple[int, int] = (256, 256)
"""Default (height, width) of camera observations, pixels (LIBERO, openpi)."""
