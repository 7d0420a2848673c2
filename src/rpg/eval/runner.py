"""Running a policy over the episodes of a target and recording them (``rpg eval``).

A run directory holds ``run.json`` (the settings), ``episodes.jsonl`` (one line per finished
episode, appended and fsynced as the episode ends: the run's commit log), ``summary.json``
(:func:`rpg.eval.stats.summarize`) and, with ``video``, ``videos/``.  A run killed at any
point resumes: committed episodes are kept and only the missing ones run; a torn last line is
discarded.  Settings are checked before anything is written: a refused setting leaves the
run directory as it was.

An episode whose policy raises, answers with something that is not an action, or exceeds a
timeout (``inference_timeout`` per call, ``episode_timeout`` per episode; a remote server's
connect timeout when it is loaded) is committed with an ``error`` field and counts as a
failure; the run goes on (``fail_fast`` stops it) and the next episode gets a fresh policy
(a remote one reconnects).

Episodes run in ``jobs`` spawned processes, or as Ray tasks (``backend="ray"``,
:mod:`rpg.parallel`), one episode per work unit; only this process appends to
``episodes.jsonl``, as episodes finish.  Every episode is determined by (task, seed,
instruction) and the policy, so a deterministic policy gives the same ``summary.json`` for any
job count and backend, byte for byte apart from its ``timing`` block.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import signal
import threading
import time
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from filelock import FileLock, Timeout

from rpg.errors import BadInput, TaskInvalid
from rpg.eval.policies import BUILTIN, INFERENCE_TIMEOUT_S, PolicyError, action_chunk, load_policy
from rpg.jsonl import cut_torn_line, read_jsonl

EPISODE_TIMEOUT_S = 600.0
"""Default wall-clock time one episode may take, policy calls and simulation together, s."""

DEFAULT_IMAGE_SIZE = (224, 224)
"""Camera images (height, width) sent to learned policies, pixels (openpi's input size)."""

LOCK_NAME = ".rpg-eval.lock"
"""The lock file that keeps a second ``rpg eval`` from writing the same run directory."""

VIDEO_SIZE = (256, 256)
"""Agentview video frames (height, width) with ``video``, pixels."""


@dataclass(frozen=True)
class EvalTask:
    """One task of a target: its artifact directory and where it sits in the library."""

    path: str
    name: str
    family: str | None = None
    version: int | None = None
    intent: str | None = None
    split: str | None = None
    paraphrases: int = 0

    @property
    def key(self) -> str:
        return f"{self.family}@v{self.version}" if self.family else self.name


@dataclass(frozen=True)
class EvalConfig:
    """The settings of a run (recorded in ``run.json``; a resumed run must have the same).

    Attributes:
        target: what to evaluate (see :func:`eval_tasks`).
        policy: the policy SPEC (:func:`rpg.eval.policies.load_policy`).
        seeds: episode seeds, the same for every task (rho_0 samples).
        embodiment: ``panda`` or ``floating_gripper``.
        instruction: ``original`` (as written), ``canonical`` (G stated exactly),
            ``paraphrase:K`` or ``all`` (the original and every paraphrase).
        cameras: camera observations; None: none for built-in policies, agentview and
            wrist for the others.
        image_size: (height, width) of camera observations, pixels.
        replan: actions of a returned chunk executed before the policy is asked again
            (None: the whole chunk).
        video: write an agentview MP4 per episode.
        library: the manifest a ``KEY=VALUE`` target filters.
        control_mode: the action space (``ee_delta``, ``ee_abs``, ``joint_pos``).
        inference_timeout: seconds one ``policy.act`` may take (> 0).
        episode_timeout: seconds one episode may take (> 0).
        allow_unstated: score tasks whose sent instruction does not state every constraint
            of G (:func:`instruction_check`); refused otherwise.
        visual: the robot's meshes in the images, ``decimated`` (default) or ``stock``
            (:class:`rpg.env.BlockTaskEnv`'s ``visual``); each episode's record says which
            its environment drew.  A run from before this setting resumes as ``decimated``.
        wrist_supersample: the wrist camera drawn at this many times the image size per side
            and averaged back (1: off, the default; 2: anti-aliased wrist shadows, at a cost
            in steps/s; :class:`rpg.env.BlockTaskEnv`'s ``wrist_supersample``); each
            episode's record says what its environment drew with.  A run from before this
            setting resumes as 1.
    """

    target: str
    policy: str
    seeds: tuple[int, ...]
    embodiment: str = "panda"
    instruction: str = "original"
    cameras: tuple[str, ...] | None = None
    image_size: tuple[int, int] = DEFAULT_IMAGE_SIZE
    replan: int | None = None
    video: bool = False
    library: str = "library/manifest.yaml"
    control_mode: str = "ee_delta"
    inference_timeout: float = INFERENCE_TIMEOUT_S
    episode_timeout: float = EPISODE_TIMEOUT_S
    allow_unstated: bool = False
    visual: str = "decimated"
    wrist_supersample: int = 1

    def camera_list(self) -> tuple[str, ...]:
        if self.cameras is not None:
            return tuple(self.cameras)
        return () if self.policy in BUILTIN else ("agentview", "wrist")

    def to_json(self) -> dict:
        doc = asdict(self)
        doc["seeds"] = list(self.seeds)
        doc["image_size"] = list(self.image_size)
        doc["cameras"] = list(self.camera_list())
        return doc


# -- targets -----------------------------------------------------------------------
def _family_tasks(path: Path, name: str, split: str | None, only: int | None = None) -> list[EvalTask]:
    from rpg.artifact import load_artifact
    from rpg.steer.family import Family

    fam = Family(path)
    out = []
    for v in fam.load().versions:
        if only is not None and v.version_id != only:
            continue
        d = fam.version_dir(v.version_id)
        schema, _ = load_artifact(d)
        out.append(EvalTask(str(d), schema.name, name, v.version_id, v.intent, split, len(schema.paraphrases)))
    return out


def _plain_task(path: Path, split: str | None = None, name: str | None = None) -> EvalTask:
    from rpg.artifact import load_artifact

    schema, _ = load_artifact(path)
    return EvalTask(str(path), name or path.name, split=split, paraphrases=len(schema.paraphrases))


def _manifest_tasks(manifest_path: Path) -> list[EvalTask]:
    from rpg.library.build import load_manifest

    manifest = load_manifest(manifest_path)
    base = manifest_path.parent
    out: list[EvalTask] = []
    for e in manifest.entries:
        if e.kind == "family":
            out += _family_tasks(base / e.name, e.name, e.split)
        else:
            out.append(_plain_task(base / e.name, e.split, e.name))
    return out


def _tag_matches(directory: str, key: str, value: str) -> bool:
    from rpg.artifact import load_artifact

    _, doc = load_artifact(Path(directory))
    have = (doc.get("tags") or {}).get(key)
    values = have if isinstance(have, list) else [have]
    return value in [str(v) for v in values]


def eval_tasks(target: str, library: str | Path = "library/manifest.yaml") -> list[EvalTask]:
    """The tasks a target names, in a fixed order.

    ``target``: a task directory; a family directory (every version) or ``FAMILY@vN`` (one);
    a library manifest (every entry, a family's every version); or a filter ``KEY=VALUE``
    over ``library``'s manifest: ``split=NAME`` (the manifest's split) or a tag of
    ``task.yaml`` (``reasoning=semantic``, ``complexity=hierarchical``, ``asset_class=SemanticCube``...).

    Raises:
        BadInput: no such target, an unreadable manifest, or a filter that selects nothing.
    """
    from rpg.steer.family import Family, is_family

    text = str(target)
    path = Path(text)
    if path.is_file() and path.suffix in (".yaml", ".yml"):
        return _manifest_tasks(path)
    if "=" in text and not path.exists():
        key, _, value = text.partition("=")
        key, value = key.strip(), value.strip()
        lib = Path(library)
        if not lib.is_file():
            raise BadInput(f"filter {text!r} needs a library manifest; {lib} does not exist (give --library)")
        tasks = _manifest_tasks(lib)
        chosen = [t for t in tasks if (t.split == value if key == "split" else _tag_matches(t.path, key, value))]
        if not chosen:
            raise BadInput(f"filter {text!r} selects no task of {lib}")
        return chosen
    if "@" in text and not path.exists():
        fam_text, _, ref = text.rpartition("@")
        if is_family(Path(fam_text)):
            version = Family(Path(fam_text)).resolve(ref).version_id
            return _family_tasks(Path(fam_text), Path(fam_text).name, None, only=version)
    if is_family(path):
        return _family_tasks(path, path.name, None)
    if (path / "task.yaml").is_file():
        return [_plain_task(path)]
    raise BadInput(f"no task at {text!r}: give a task directory, a family (or FAMILY@vN), a library manifest "
                   "or a filter KEY=VALUE")


def instruction_variants(mode: str, task: EvalTask) -> list[str]:
    """The instructions a task is evaluated with: ``original``, ``canonical``, ``paraphrase:K``,
    or for ``all`` the original and every paraphrase.

    Raises:
        BadInput: an unknown mode, or a paraphrase the task does not have.
    """
    if mode == "all":
        return ["original", *(f"paraphrase:{k}" for k in range(task.paraphrases))]
    head, _, k = mode.partition(":")
    if mode in ("original", "canonical"):
        return [mode]
    if head == "paraphrase" and k.isdigit():
        if int(k) >= task.paraphrases:
            raise BadInput(f"--instruction {mode}: {task.key} has {task.paraphrases} paraphrases "
                           f"(they count from 0)")
        return [mode]
    raise BadInput(f"--instruction must be original, canonical, paraphrase:K or all, not {mode!r}")


def sent_instruction(task: EvalTask, variant: str, schema=None) -> str:
    """The text a policy is sent for ``variant`` of ``task`` (what the environment sends);
    ``schema``: the task's, when the caller has read it already."""
    from rpg.artifact import load_artifact
    from rpg.schema.citations import canonical_instruction

    if schema is None:
        schema, _ = load_artifact(Path(task.path))
    if variant == "original":
        return schema.instruction
    if variant == "canonical":
        return canonical_instruction(schema)
    return schema.paraphrases[int(variant.partition(":")[2])]


def instruction_check(work: list[tuple[EvalTask, str]]) -> dict[str, list[str]]:
    """For every (task, instruction variant) of a run, the constraints of G that the sent
    instruction does not state (:func:`rpg.schema.citations.unstated`): ``"KEY VARIANT" ->
    [constraint, ...]``, sorted; empty lists where the instruction states all of G.

    A paraphrase's frame (:data:`rpg.schema.builder.PARAPHRASE_FRAMES`) adds nothing to what
    it states, so the goal summary inside it is what is read."""
    from rpg.artifact import load_artifact
    from rpg.schema.builder import unframe
    from rpg.schema.citations import unstated

    out = {}
    for task, variant in work:
        schema, _ = load_artifact(Path(task.path))
        text = sent_instruction(task, variant, schema)
        out[f"{task.key} {variant}"] = unstated(schema, unframe(text))
    return dict(sorted(out.items()))


# -- episodes ------------------------------------------------------------------------
class EpisodeTimeout(PolicyError):
    """A policy call or an episode that ran past its timeout."""


def _state_hash(env) -> str:
    """A short hash of every object's pose (rounded to 1e-6): tells episodes' states apart."""
    poses = env.unwrapped.scene.poses()
    flat = np.array([[*p.pos, *p.quat] for _, p in sorted(poses.items())]).round(6)
    return hashlib.sha256(flat.tobytes()).hexdigest()[:16]


@contextlib.contextmanager
def _alarm(seconds: float, what: str):
    """Raise :class:`EpisodeTimeout` (``what``) in this thread after ``seconds``: a Python
    policy's call cannot be stopped otherwise.  Only the main thread receives signals; in any
    other thread this does nothing (a remote policy keeps its own timeouts)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def fire(signum, frame):
        raise EpisodeTimeout(what)

    before = signal.signal(signal.SIGALRM, fire)
    signal.setitimer(signal.ITIMER_REAL, max(seconds, 1e-3))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, before)


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())[:300]
    return text if isinstance(exc, PolicyError) else f"{type(exc).__name__}: {text}"


def run_episode(env, policy, seed: int, replan: int | None, video_path: Path | None = None,
                inference_timeout: float = INFERENCE_TIMEOUT_S, episode_timeout: float = EPISODE_TIMEOUT_S) -> dict:
    """One episode of ``policy`` from ``seed``; the record's outcome fields.

    ``progress`` is the fraction of G's leaves that hold at the end (``info["progress"]``),
    ``progress_max`` its maximum over the episode; ``latency_s`` the duration of each
    ``policy.act`` call (s); ``wall_s`` the episode's wall-clock time (s).

    Raises:
        PolicyError: the policy answered with something that is not an action (chunk).
        EpisodeTimeout: a call ran past ``inference_timeout`` or the episode past ``episode_timeout``.
    """
    from rpg.env.video import VideoWriter

    t0 = time.monotonic()
    deadline = t0 + episode_timeout
    obs, info = env.reset(seed=int(seed))
    initial = _state_hash(env)
    policy.reset(env.unwrapped.instruction)
    dim = env.action_space.shape[0]
    steps, queue, done, truncated = 0, [], False, False
    progress_max = float(info["progress"])
    latency: list[float] = []
    # the video appears only when the episode ends without error (VideoWriter discards a torn one)
    with VideoWriter(video_path, fps=env.metadata["render_fps"]) if video_path else contextlib.nullcontext() as writer:
        if writer:
            writer.write(env.unwrapped.render_camera("agentview"))
        while not done:
            if not queue:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise EpisodeTimeout(f"the episode ran past its {episode_timeout:g} s (episode timeout)")
                which = "inference" if inference_timeout <= left else "episode"
                limit = min(inference_timeout, left)
                t = time.monotonic()
                with _alarm(limit, f"the policy did not answer within {limit:g} s ({which} timeout)"):
                    answer = policy.act(obs)
                latency.append(time.monotonic() - t)
                chunk = action_chunk(answer, dim)
                queue = list(chunk[: replan or len(chunk)])
            obs, _, terminated, truncated, info = env.step(queue.pop(0))
            steps += 1
            progress_max = max(progress_max, float(info["progress"]))
            done = terminated or truncated
            if writer:
                writer.write(env.unwrapped.render_camera("agentview"))
    return {"success": bool(info["success"]), "steps": steps, "truncated": bool(truncated),
            "initial_state": initial, "final_state": _state_hash(env), "instruction": env.unwrapped.instruction,
            "unsatisfied": list(info["diagnostics"]["unsatisfied"]),
            "satisfied": list(info["diagnostics"]["satisfied"]),
            "progress": round(float(info["progress"]), 6), "progress_max": round(progress_max, 6),
            "latency_s": [round(x, 6) for x in latency], "wall_s": round(time.monotonic() - t0, 3), "error": None}


@dataclass(frozen=True)
class Unit:
    """Work for one process: one episode (a seed of one task with one instruction)."""

    task: EvalTask
    variant: str
    seed: int
    config: EvalConfig
    run_dir: str


ENV_MEMORY_MB = {"state-only": 20, "cameras": 90, "cameras, wrist 2x": 170}
"""Resident memory one more open Panda environment adds to a process, MB, by whether it renders
(two cameras, or the agentview video) and whether its wrist camera is supersampled (a second
renderer and GL context): the measured figure rounded up by ~20%, which
``tests/test_eval.py`` asserts as a bound.  Measured with ``benchmarks/bench_env_memory.py``
(the growth of ``VmRSS`` while a process opens and resets 6 more environments of different
library tasks, divided by 6) on the 2-core CPU with Mesa's llvmpipe: with the decimated meshes
(the default, what ``rpg eval`` uses) 16.6 MB state-only and 73.2 MB with two 224x224 cameras
(each environment has its own renderer and GL context, ~56 MB); with ``visual="stock"`` 112
and 198 MB (the old "~115 MB a Panda scene" was the stock meshes); the floating gripper 9.8
and 65.1 MB; the Panda's two cameras with ``wrist_supersample=2`` 139.5 MB."""

ENV_BUDGET_MB = 256
"""Memory a process may keep in open environments, MB (what the old cap of two stock-mesh
Panda scenes held, 2 x ~115 MB, rounded up); :func:`env_cache_size` divides it by
:data:`ENV_MEMORY_MB`."""


def env_cache_size(renders: bool, wrist_supersampled: bool = False) -> int:
    """Environments a process keeps open (least recently used closed first):
    :data:`ENV_BUDGET_MB` // :data:`ENV_MEMORY_MB` (12 state-only, 2 rendering, 1 rendering a
    supersampled wrist camera), at least 1.
    A process that ran every task of a library used to keep all of them (6 GB per worker for
    58 stock-mesh Panda tasks)."""
    key = ("cameras, wrist 2x" if wrist_supersampled else "cameras") if renders else "state-only"
    return max(1, ENV_BUDGET_MB // ENV_MEMORY_MB[key])


_ENVS: OrderedDict = OrderedDict()
"""This process's environments by (task path, instruction variant), least recently used first."""
_POLICY: dict = {}
"""This process's policies by SPEC: [policy, the environment it is bound to]."""


def _env_for(unit: Unit):
    from rpg.env import BlockTaskEnv

    key = (unit.task.path, unit.variant)
    if key not in _ENVS:
        cfg = unit.config
        cams = cfg.camera_list()
        while len(_ENVS) >= env_cache_size(bool(cams) or cfg.video, "wrist" in cams and cfg.wrist_supersample > 1):
            _ENVS.popitem(last=False)[1][0].close()
        size = VIDEO_SIZE if cfg.video and not cfg.camera_list() else tuple(cfg.image_size)
        env = BlockTaskEnv(unit.task.path, embodiment=cfg.embodiment, control_mode=cfg.control_mode,
                           cameras=cfg.camera_list(), image_size=size, instruction=unit.variant, visual=cfg.visual,
                           wrist_supersample=cfg.wrist_supersample)
        _ENVS[key] = (env, env.source.content_hash)
    _ENVS.move_to_end(key)
    return _ENVS[key]


def _policy_for(config: EvalConfig, env):
    """This process's policy for ``config.policy``, bound to ``env`` (``bind`` again when the
    environment changes)."""
    spec = config.policy
    if spec not in _POLICY:
        _POLICY[spec] = [load_policy(spec, inference_timeout=config.inference_timeout), None]
    entry = _POLICY[spec]
    if entry[1] is not env and callable(getattr(entry[0], "bind", None)):
        entry[0].bind(env)
    entry[1] = env
    return entry[0]


def _drop_policy(spec: str) -> None:
    """Forget this process's policy for ``spec`` after a failed episode: the next episode gets
    a fresh one (a remote server is connected again; a late answer is never read)."""
    entry = _POLICY.pop(spec, None)
    if entry is not None and callable(getattr(entry[0], "close", None)):
        with contextlib.suppress(Exception):
            entry[0].close()


def close_workers() -> None:
    """Close this process's environments and policies (a remote policy's connection)."""
    for env, _ in _ENVS.values():
        env.close()
    for spec in list(_POLICY):
        _drop_policy(spec)
    _ENVS.clear()


def run_unit(unit: Unit) -> dict:
    """Run a unit's episode; its ``episodes.jsonl`` record.  A failure of the policy (an
    exception, a timeout, a refused answer, a server that cannot be reached) is the record's
    ``error``, with ``success`` false."""
    cfg = unit.config
    env, content_hash = _env_for(unit)
    video = None
    if cfg.video:
        video = Path(unit.run_dir) / "videos" / f"{unit.task.key.replace('@', '-')}-{unit.variant.replace(':', '')}-s{unit.seed}.mp4"
        video.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()
    try:
        policy = _policy_for(cfg, env)
        result = run_episode(env, policy, unit.seed, cfg.replan, video, cfg.inference_timeout, cfg.episode_timeout)
    except TaskInvalid:
        raise  # the task's failure (a seed whose sample is refused), not the policy's: the run stops
    except Exception as exc:  # noqa: BLE001 - the policy's failure is this episode's outcome
        _drop_policy(cfg.policy)
        result = {"success": False, "steps": None, "truncated": False, "initial_state": None, "final_state": None,
                  "instruction": env.unwrapped.instruction, "unsatisfied": [], "satisfied": [],
                  "progress": 0.0, "progress_max": 0.0, "latency_s": [],
                  "wall_s": round(time.monotonic() - t0, 3), "error": _one_line(exc)}
        video = None
    return {"task": unit.task.name, "task_path": unit.task.path, "task_hash": content_hash,
            "family": unit.task.family, "version": unit.task.version, "intent": unit.task.intent,
            "split": unit.task.split, "seed": int(unit.seed), "instruction_variant": unit.variant,
            "embodiment": cfg.embodiment, "visual": env.unwrapped.robot.visual,
            "wrist_supersample": env.unwrapped.wrist_supersample, "policy": cfg.policy, **result,
            "video": str(video.relative_to(unit.run_dir)) if video and video.exists() else None}


def _episode_key(rec: dict) -> tuple:
    return rec["task_path"], rec["instruction_variant"], int(rec["seed"])


def read_episodes(path: Path) -> list[dict]:
    """The complete lines of ``episodes.jsonl`` (a torn last line, from a kill mid-write, is
    not read; :func:`rpg.jsonl.cut_torn_line` removes it before a resumed run appends)."""
    return read_jsonl(path)


RUN_DEFAULTS = {"visual": "decimated", "wrist_supersample": 1}
"""What a ``run.json`` from before a setting existed ran with."""


def _check_run_dir(run_dir: Path, config: EvalConfig) -> None:
    settings = run_dir / "run.json"
    if run_dir.exists() and not run_dir.is_dir():
        raise BadInput(f"-o {run_dir} exists and is not a directory")
    if settings.is_file():
        try:
            before = json.loads(settings.read_text())
        except ValueError:
            raise BadInput(f"{settings} is not readable JSON; give a new -o directory") from None
        if isinstance(before, dict):
            before = RUN_DEFAULTS | before  # a run from before --visual / --wrist-supersample
        if before != config.to_json():
            changed = sorted(k for k in set(before) | set(config.to_json()) if before.get(k) != config.to_json().get(k))
            raise BadInput(f"{run_dir} holds a run with other settings ({', '.join(changed)}); give a new -o "
                           "directory, or the same settings to resume it")
    elif run_dir.is_dir() and any(p.name != LOCK_NAME for p in run_dir.iterdir()):
        raise BadInput(f"{run_dir} is not empty and holds no run.json; give a new -o directory")


def check_settings(config: EvalConfig) -> list[tuple[EvalTask, str]]:
    """Every setting of ``config`` checked, before anything is written; the (task, instruction
    variant) pairs it runs.

    Raises:
        BadInput: no seeds, a bad replan, timeout, embodiment, control mode, camera, image
            size, visual, wrist supersampling, target, instruction mode or paraphrase, or a
            policy that cannot be loaded.
    """
    from rpg.env.core import CAMERAS
    from rpg.env.embodiments import make_embodiment
    from rpg.env.embodiments.visuals import VISUALS
    from rpg.env.render import check_wrist_supersample

    if not config.seeds:
        raise BadInput("no seeds: give --episodes N (N >= 1) or --seeds LIST")
    if config.replan is not None and config.replan < 1:
        raise BadInput("--replan must be at least 1")
    if config.visual not in VISUALS:
        raise BadInput(f"--visual must be one of {', '.join(VISUALS)}, not {config.visual!r}")
    check_wrist_supersample(config.wrist_supersample)
    for name, value in (("--inference-timeout", config.inference_timeout), ("--episode-timeout", config.episode_timeout)):
        if not (isinstance(value, int | float) and value > 0 and value == value and value != float("inf")):
            raise BadInput(f"{name} must be a positive number of seconds, not {value!r}")
    modes = make_embodiment(config.embodiment).CONTROL_MODES  # EmbodimentError (BadInput) for an unknown one
    if config.control_mode not in modes:
        raise BadInput(f"{config.embodiment} has no control mode {config.control_mode!r}; it has {', '.join(modes)}")
    bad = [c for c in config.camera_list() if c not in CAMERAS]
    if bad:
        raise BadInput(f"unknown camera {bad[0]!r} in --cameras; cameras are {', '.join(CAMERAS)}")
    h, w = config.image_size
    if not (16 <= h <= 2048 and 16 <= w <= 2048):
        raise BadInput(f"image size must be between 16 and 2048 pixels, not {h}x{w}")
    tasks = eval_tasks(config.target, config.library)
    work = [(t, v) for t in tasks for v in instruction_variants(config.instruction, t)]
    unstated = {k: v for k, v in instruction_check(work).items() if v}
    if unstated and not config.allow_unstated:
        key, missing = next(iter(unstated.items()))
        more = f" (and {len(unstated) - 1} more task instructions)" if len(unstated) > 1 else ""
        raise BadInput(f"{key}: the instruction sent does not state {'; '.join(missing)}, which G checks: a policy "
                       f"would be scored on what it was not told{more}. Send --instruction canonical (G stated "
                       "exactly), or give --allow-unstated to score it anyway (recorded in summary.json)")
    if config.policy not in BUILTIN:
        close = getattr(load_policy(config.policy), "close", None)  # a bad module or an unreachable server
        if callable(close):
            close()
    return work


def run_eval(config: EvalConfig, run_dir: str | Path, jobs: int = 1,
             progress: Callable[[dict], None] | None = None, fail_fast: bool = False,
             backend: str = "local", address: str | None = None) -> dict:
    """Run ``config`` into ``run_dir`` (resuming what is there); return the summary.

    ``backend``: ``local`` (``jobs`` spawned processes) or ``ray`` (Ray tasks on a local
    instance with ``jobs`` CPUs, or on the cluster at ``address``); see :mod:`rpg.parallel`.
    Neither is a setting of the run: a run resumes on either.

    Raises:
        BadInput: a bad setting (:func:`check_settings`) or run directory, or another
            ``rpg eval`` writing ``run_dir``; nothing is written then.
        rpg.parallel.BackendError: an unknown backend, Ray not installed or its cluster
            unreachable; nothing is written then.
        rpg.parallel.WorkerLost: a worker died (the episodes committed before are kept).
        PolicyError: with ``fail_fast``, the first episode that failed (the episodes
            committed before it are kept).
    """
    from rpg.parallel import open_backend

    run_dir = Path(run_dir)
    _check_run_dir(run_dir, config)
    work = check_settings(config)
    with open_backend(backend, jobs, address) as runner:
        run_dir.mkdir(parents=True, exist_ok=True)
        lock = FileLock(str(run_dir / LOCK_NAME))
        try:
            lock.acquire(timeout=0)
        except Timeout:
            raise BadInput(f"another rpg eval is writing {run_dir}; wait for it to finish or give a new -o "
                           "directory") from None
        try:
            return _run_locked(config, run_dir, work, runner, progress, fail_fast)
        finally:
            lock.release()


def _run_locked(config: EvalConfig, run_dir: Path, work: list, runner, progress, fail_fast: bool) -> dict:
    """The part of :func:`run_eval` that writes the run directory (its lock held); ``runner``
    an open :class:`rpg.parallel.Backend`."""
    from rpg.artifact import write_file
    from rpg.eval.stats import summarize

    write_file(run_dir / "run.json", json.dumps(config.to_json(), indent=2, sort_keys=True) + "\n")
    log = run_dir / "episodes.jsonl"
    records = cut_torn_line(log)
    done = {_episode_key(r) for r in records}
    units = [Unit(task, variant, int(s), config, str(run_dir)) for task, variant in work for s in config.seeds
             if (task.path, variant, int(s)) not in done]
    with open(log, "ab") as fh:
        def commit(rec: dict) -> None:
            fh.write((json.dumps(rec, sort_keys=True) + "\n").encode())
            fh.flush()
            os.fsync(fh.fileno())
            records.append(rec)
            if progress:
                progress(rec)
            if fail_fast and rec["error"]:
                raise PolicyError(f"{rec['task']} seed {rec['seed']} ({rec['instruction_variant']}) failed: "
                                  f"{rec['error']}; the run stopped (--fail-fast); the finished episodes are kept")

        try:
            with contextlib.closing(runner.imap(run_unit, units)) as results:  # as episodes finish, any order
                for rec in results:
                    commit(rec)
        finally:
            close_workers()  # what one job opened in this process
    wanted = {(t.path, v, int(s)) for t, v in work for s in config.seeds}
    summary = summarize([r for r in records if _episode_key(r) in wanted], config.to_json())
    summary["instruction_check"] = instruction_check(work)
    write_file(run_dir / "summary.json", json.dumps(summary, indent=2, sort_keys=True) + "\n")
    return summary


__all__ = ["EpisodeTimeout", "EvalConfig", "EvalTask", "PolicyError", "check_settings", "eval_tasks", "read_episodes",
           "run_eval", "run_episode"]
