"""Task code's answers as the trusted side accepts them: bounded, schema-checked data.

The sandboxed child (:mod:`rpg.validate.child`) runs task code and returns plain data.
This module asks for it (:func:`fetch_task_data`), checks it against a schema with hard
bounds (sizes, counts, finite numbers, known names) and rebuilds it with rpg's own classes
(:func:`rpg.domain.assets.asset_from_dict`, :func:`rpg.domain.predicates.from_dict`) into a
:class:`rpg.domain.task.TaskData`.  Samples of rho_0 are cached per process by the code's
SHA-256 and the seed; a seed not yet asked for is fetched together with the next
:data:`PREFETCH_SEEDS` seeds in one sandboxed run.
"""

from __future__ import annotations

import hashlib
import math
import threading
from collections import OrderedDict

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from rpg.domain import constants as C
from rpg.domain.state import Pose
from rpg.errors import TaskInvalid

MAX_OBJECTS = 64
"""Most assets a task may have (the largest library task has 27 cubes)."""

MAX_COORD = 10.0
"""Largest absolute pose component accepted from task code (m, or quaternion units)."""

MAX_GOAL_NODES = 256
"""Most predicates a goal tree may have (the largest library goal has ~60)."""

MAX_GOAL_INT = 64
"""Largest absolute integer argument of a predicate (counts, layers, sizes are at most
the number of objects)."""

PREFETCH_SEEDS = 20
"""Seeds fetched in one sandboxed run when an environment asks for one it has not seen
(``rpg eval``'s default is 20 seeds per task); an environment fetches the first block (seeds 0
to PREFETCH_SEEDS - 1) with the task's data (:func:`rpg.env.loading.task_data`: one sandboxed
run, not two)."""

CACHE_ENTRIES = 4096
"""(code, seed) entries of rho_0 samples kept per process."""

PoseList = list[float]


class ChildError(BaseModel):
    model_config = ConfigDict(extra="ignore")

    kind: str = Field("runtime", max_length=40)
    message: str = Field("", max_length=4000)
    traceback: str = Field("", max_length=8000)
    seed: int | None = None


class ChildResult(BaseModel):
    """The child's answer to a ``data`` request; anything else is refused as malformed."""

    model_config = ConfigDict(extra="forbid")

    class_: str = Field(alias="class", max_length=200)
    assets: list[dict] = Field(max_length=MAX_OBJECTS)
    goal: dict
    goal_poses: dict[str, PoseList] | None = None
    rho0: dict[str, list[dict[str, PoseList]]] = Field(default_factory=dict)
    errors: dict[str, ChildError] = Field(default_factory=dict)


class DataError(TaskInvalid):
    """Task code's data is malformed, out of bounds or inconsistent.

    Attributes:
        kind: the repair kind (``api_usage``, ``runtime``, ``syntax``...).
        stage: ``compile`` (the code's description of the task), ``initial_state`` or
            ``goal_state``.
    """

    def __init__(self, message: str, kind: str = "api_usage", stage: str = "compile", details: dict | None = None):
        super().__init__(message)
        self.kind = kind
        self.stage = stage
        self.details = details or {}


def code_digest(sources: dict[str, str]) -> str:
    """SHA-256 over the code files' names and text (what rho_0's samples are cached under)."""
    h = hashlib.sha256()
    for name in sorted(sources):
        h.update(name.encode() + b"\0" + str(sources[name]).encode() + b"\0")
    return h.hexdigest()


def _check_goal_value(node, field_name: str, value, names: set[str]) -> None:
    """One argument of a goal predicate as the trusted side accepts it.

    Raises:
        DataError: an object name that is not an asset, a list of the wrong shape, an
            integer beyond :data:`MAX_GOAL_INT`, a float that is not finite or beyond
            :data:`MAX_COORD`, a string over 200 characters, or another type.
    """
    from rpg.domain.predicates import Predicate

    where = f"goal(): {node.name}.{field_name}"
    if field_name in node.object_fields:
        if not isinstance(value, str) or value not in names:
            raise DataError(f"{where} must name an object of the task, not {str(value)[:60]!r}")
    elif field_name in node.list_fields:
        if not (isinstance(value, tuple) and len(value) <= MAX_OBJECTS and all(isinstance(v, str) and v in names for v in value)):
            raise DataError(f"{where} must list objects of the task")
    elif isinstance(value, Predicate):
        return
    elif isinstance(value, tuple):
        if len(value) > MAX_GOAL_NODES:
            raise DataError(f"{where} is too long")
        for v in value:
            _check_goal_value(node, field_name + "[]", v, names)
    elif isinstance(value, bool) or value is None:
        return
    elif isinstance(value, int):
        if abs(value) > MAX_GOAL_INT:
            raise DataError(f"{where} = {value} is out of range (|n| <= {MAX_GOAL_INT})")
    elif isinstance(value, float):
        if not (math.isfinite(value) and abs(value) <= MAX_COORD):
            raise DataError(f"{where} = {value} is not a finite number within {MAX_COORD}")
    elif isinstance(value, str):
        if len(value) > 200:
            raise DataError(f"{where} is longer than 200 characters")
    else:
        raise DataError(f"{where} has a {type(value).__name__}, which no predicate takes")


def check_goal(goal, names) -> None:
    """The rebuilt goal's size and every argument (:func:`_check_goal_value`), and that
    each field has the type of its declared default: what a predicate is given decides how
    long evaluating it takes, so it is bounded before anything evaluates it.

    Raises:
        DataError: too many predicates, or an argument out of bounds or of the wrong type.
    """
    from dataclasses import MISSING, fields

    nodes = list(goal.walk())
    if len(nodes) > MAX_GOAL_NODES:
        raise DataError(f"goal() has {len(nodes)} predicates; at most {MAX_GOAL_NODES}")
    names = set(names) | {"table"}
    for node in nodes:
        for f in fields(node):
            value = getattr(node, f.name)
            default = f.default
            if default not in (MISSING, None) and value is not None and not isinstance(default, tuple):
                want = (int, float) if isinstance(default, int | float) and not isinstance(default, bool) else type(default)
                if not isinstance(value, want) or (isinstance(value, bool) and not isinstance(default, bool)):
                    raise DataError(f"goal(): {node.name}.{f.name} must be a {type(default).__name__}")
            _check_goal_value(node, f.name, value, names)


def _pose(name: str, values: PoseList, what: str) -> Pose:
    if len(values) != 7 or not all(isinstance(v, int | float) and math.isfinite(v) and abs(v) <= MAX_COORD
                                   for v in values):
        raise DataError(f"{what}: the pose of {name!r} must be 7 finite numbers (x, y, z m; quaternion w, x, y, z)",
                        stage=what)
    if math.sqrt(sum(v * v for v in values[3:])) < 1e-6:  # MuJoCo normalises the rest
        raise DataError(f"{what}: {name!r} has a zero quaternion", stage=what)
    return Pose(tuple(float(v) for v in values[:3]), tuple(float(v) for v in values[3:]))


def _poses(doc: dict[str, PoseList], names: list[str], what: str) -> dict[str, Pose]:
    missing, extra = sorted(set(names) - set(doc)), sorted(set(doc) - set(names))
    if missing or extra:
        which = f"lacks {missing[0]!r}" if missing else f"names {extra[0]!r}, which is not an asset of the task"
        raise DataError(f"{what} must give every object's pose and no other: it {which}", stage=what)
    return {n: _pose(n, doc[n], what) for n in sorted(names)}


class _Samples:
    """rho_0's samples of one task's code: a per-process cache in front of the sandbox."""

    _cache: OrderedDict[tuple[str, int], list[dict[str, Pose]]] = OrderedDict()
    _lock = threading.Lock()

    def __init__(self, sources: dict[str, str], digest: str, names: list[str], restricted: bool):
        self.sources, self.digest, self.names, self.restricted = sources, digest, names, restricted
        self.errors: dict[int, DataError] = {}

    def store(self, result: ChildResult) -> None:
        """Keep the samples of a child's answer; a seed whose samples are malformed, or the
        seed at which ``initial_state`` raised, keeps its error instead."""
        err = result.errors.get("initial_state")
        if err is not None and err.seed is not None:
            self.errors[err.seed] = DataError(f"initial_state (seed {err.seed}): {err.message}", kind=err.kind,
                                              stage="initial_state", details={"traceback": err.traceback})
        for key, draws in result.rho0.items():
            seed = int(key)
            try:
                poses = [_poses(d, self.names, "initial_state") for d in draws]
            except DataError as exc:
                self.errors[seed] = exc
                continue
            with self._lock:
                self._cache[(self.digest, seed)] = poses
                self._cache.move_to_end((self.digest, seed))
                while len(self._cache) > CACHE_ENTRIES:
                    self._cache.popitem(last=False)

    def __call__(self, seed: int, n: int) -> list[dict[str, Pose]]:
        seed = int(seed)
        if seed in self.errors:
            raise self.errors[seed]
        with self._lock:
            have = self._cache.get((self.digest, seed))
        if have is None or len(have) < n:
            seeds = [seed] if have is not None else list(range(seed, seed + PREFETCH_SEEDS))
            seeds = [s for s in seeds if 0 <= s < 2**63]
            result = _request(self.sources, seeds, n, goal_state=False, restricted=self.restricted)
            self.store(result)
            if seed in self.errors:
                raise self.errors[seed]
            with self._lock:
                have = self._cache.get((self.digest, seed), [])
            if len(have) < n:
                raise DataError(f"initial_state returned {len(have)} samples for seed {seed}, not {n}",
                                stage="initial_state")
        return have[:n]


def _start(sources: dict[str, str], seeds: list[int], draws: int, goal_state: bool, restricted: bool):
    from rpg.validate.sandbox import ChildRun

    return ChildRun({"op": "data", "sources": dict(sources), "seeds": seeds, "draws": draws,
                     "goal_state": goal_state, "restricted": restricted})


def _request(sources: dict[str, str], seeds: list[int], draws: int, goal_state: bool, restricted: bool,
             run=None) -> ChildResult:
    run = run or _start(sources, seeds, draws, goal_state, restricted)
    doc = run.wait()
    if not isinstance(doc, dict) or not doc.get("ok"):
        raise DataError(str((doc or {}).get("message", "the task code could not be loaded"))[:2000],
                        kind=str((doc or {}).get("kind", "runtime"))[:40],
                        details={"traceback": str((doc or {}).get("traceback", ""))[:4000]})
    try:
        result = ChildResult.model_validate(doc.get("result"))
    except ValidationError as exc:
        raise DataError(f"task code returned malformed data: {str(exc).splitlines()[0][:200]}") from None
    return result


def gate_seeds(seed: int, enabled=frozenset()) -> range:
    """The seeds whose rho_0 samples the validation gates read (non-trivial and bounds;
    solvable when asked for)."""
    return range(seed, seed + max(C.NONTRIVIAL_SEEDS, C.SOLVABLE_SEEDS if "solvable" in enabled else 0))


def start_task_data(sources: dict[str, str], seeds=(), restricted: bool = True):
    """Start :func:`fetch_task_data`'s sandboxed run and return a function that waits for
    it and returns the checked data (the caller works while the child runs).

    Raises:
        WorkerError: the child could not be started (the returned function raises what
            :func:`fetch_task_data` raises).
    """
    seeds = list(seeds)
    run = _start(sources, seeds, C.INITIAL_DRAWS, goal_state=True, restricted=restricted)
    return lambda: fetch_task_data(sources, seeds, restricted, _run=run)


def fetch_task_data(sources: dict[str, str], seeds=(), restricted: bool = True, _run=None):
    """Run task code in the sandbox and return its checked data.

    Args:
        sources: ``code.py`` and ``goal_state_code.py`` text (gated by the caller's text gate;
            the child gates it again).
        seeds: seeds whose rho_0 samples to fetch now (more are fetched on demand).
        restricted: run the code under RestrictedPython (False only for ``--disable text``).

    Returns:
        :class:`rpg.domain.task.TaskData`.

    Raises:
        DataError: the code cannot be loaded, or its description of the task (assets,
            goal) is malformed or inconsistent.  An error of ``goal_state`` is kept in the
            data's ``goal_error``; one of ``initial_state`` is raised when that seed's samples
            are asked for.
        WorkerError: the sandboxed run crashed, ran out of time or wrote too much.
    """
    from rpg.domain.assets import asset_from_dict
    from rpg.domain.predicates import from_dict
    from rpg.domain.task import TaskData

    digest = code_digest(sources)
    result = _request(sources, list(seeds), C.INITIAL_DRAWS, goal_state=True, restricted=restricted, run=_run)
    try:
        assets = tuple(asset_from_dict(a) for a in result.assets)
    except ValueError as exc:
        raise DataError(f"assets(): {exc}") from None
    names = [a.name for a in assets]
    if len(set(names)) != len(names) or {"table", "floor"} & set(names):
        raise DataError("assets() must name each object once (and not 'table' or 'floor')")
    if not any(a.movable for a in assets):
        raise DataError("assets() has no cube to move")
    try:
        goal = from_dict(result.goal)
    except (ValueError, TypeError, KeyError, RecursionError) as exc:
        raise DataError(f"goal(): {exc}"[:2000]) from None
    check_goal(goal, names)
    samples = _Samples(dict(sources), digest, names, restricted)
    samples.store(result)
    err = result.errors.get("goal_state")
    goal_poses, goal_error = None, None
    if err is not None:
        goal_error = DataError(f"goal_state: {err.message}", kind=err.kind, stage="goal_state",
                               details={"traceback": err.traceback})
    else:
        try:
            goal_poses = _poses(result.goal_poses or {}, names, "goal_state")
        except DataError as exc:
            goal_error = exc
    return TaskData(assets=assets, goal=goal, goal_poses=goal_poses, draws=samples,
                    class_name=result.class_, goal_error=goal_error)
