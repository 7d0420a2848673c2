"""rpg/BlockTask-v0: Gymnasium API, determinism, scripted pick-and-stack with both embodiments,
loading through the validation checks, and the play / render commands."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import rpg.env  # noqa: F401  (registers rpg/BlockTask-v0)
from rpg.domain import constants as C
from rpg.env import ENV_ID, BlockTaskEnv, episode_step_limit
from rpg.env.embodiments import EmbodimentError
from rpg.env.scripted import cube_yaw, follow, pick_place_waypoints
from rpg.errors import BadInput, TaskInvalid

LIBRARY = Path(__file__).resolve().parents[1] / "library"
STACK = LIBRARY / "stack_blocks"  # G: stack red (bottom), blue
EMBODIMENTS = ("floating_gripper", "panda")


def _env(embodiment: str, **kw) -> BlockTaskEnv:
    kw.setdefault("cameras", ())
    return gym.make(ENV_ID, task=str(kw.pop("task", STACK)), embodiment=embodiment, **kw)


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_check_env_passes(embodiment):
    env = _env(embodiment, cameras=("agentview", "wrist"), image_size=(48, 64), privileged=True)
    check_env(env.unwrapped, skip_render_check=True)
    obs, info = env.reset(seed=3)
    assert obs["agentview_image"].shape == (48, 64, 3) and obs["agentview_image"].dtype == np.uint8
    assert obs["wrist_image"].shape == (48, 64, 3)
    assert obs["agentview_image"].std() > 5  # a rendered scene, not a blank frame
    assert obs["state"].shape == (8,) and obs["object_poses"].shape == (2, 7)
    assert obs["instruction"] == "Stack two blocks on top of each other."
    assert info["success"] is False and info["is_grasped"] is False
    assert info["diagnostics"]["unsatisfied"], "G is false at rho_0 (non-trivial gate)"
    env.close()


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_reset_samples_rho0_of_the_seed_and_starts_at_home(embodiment):
    env = _env(embodiment, privileged=True)
    obs, _ = env.reset(seed=7)
    task = env.unwrapped.task
    sampled = task.data.draws(7, 1)[0]  # rho_0 sample 0 of seed 7, as the sandbox drew it: what every rpg command uses
    for row, name in zip(obs["object_poses"], env.unwrapped.object_names, strict=True):
        assert np.allclose(row[:2], sampled[name].pos[:2], atol=2e-3), name
    # TCP at the home pose: above the front of the workspace, pointing down
    assert np.allclose(obs["state"][:3], [C.WORKSPACE_X[0], 0.0, C.TABLE_TOP_Z + C.HOME_TCP_HEIGHT], atol=5e-3)
    assert np.allclose(obs["state"][6:], 0.04, atol=1e-3)  # gripper open
    other, _ = env.reset(seed=8)
    assert not np.allclose(other["object_poses"], obs["object_poses"])
    env.close()


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_same_seed_and_actions_give_identical_bytes(embodiment):
    runs = []
    for _ in range(2):
        env = _env(embodiment, cameras=("agentview",), image_size=(32, 32), privileged=True)
        env.action_space.seed(11)
        actions = [env.action_space.sample() for _ in range(15)]
        obs, _ = env.reset(seed=5)
        frames = [obs]
        for a in actions:
            frames.append(env.step(a)[0])
        runs.append((frames, env.unwrapped.data.qpos.copy(), env.unwrapped.data.qvel.copy()))
        env.close()
    (fa, qa, va), (fb, qb, vb) = runs
    assert qa.tobytes() == qb.tobytes() and va.tobytes() == vb.tobytes()
    for oa, ob in zip(fa, fb, strict=True):
        for key in oa:
            if key != "instruction":
                assert oa[key].tobytes() == ob[key].tobytes(), key


def test_async_vector_env_with_two_envs():
    # "rpg.env:" imports the module that registers the id in each spawned worker
    envs = gym.vector.AsyncVectorEnv([lambda: gym.make(f"rpg.env:{ENV_ID}", task=str(STACK), embodiment="floating_gripper",
                                                       cameras=("agentview",), image_size=(32, 32))] * 2,
                                  context="spawn")  # forking a process that rendered with EGL can hang
    try:
        obs, infos = envs.reset(seed=[0, 1])
        assert obs["state"].shape == (2, 8) and obs["agentview_image"].shape == (2, 32, 32, 3)
        assert not np.allclose(obs["agentview_image"][0], obs["agentview_image"][1])
        for _ in range(3):
            obs, rew, term, trunc, infos = envs.step(envs.action_space.sample())
        assert rew.shape == (2,) and list(infos["elapsed_steps"]) == [3, 3]
    finally:
        envs.close()


def _stack_episode(embodiment: str, seed: int) -> list[dict]:
    """Pick blue and put it on red through ee_delta actions only; the infos of every step."""
    env = _env(embodiment, privileged=True)
    obs, _ = env.reset(seed=seed)
    poses = dict(zip(env.unwrapped.object_names, obs["object_poses"], strict=True))
    blue, red = poses["blue"], poses["red"]
    wps = pick_place_waypoints(blue[:3], cube_yaw(blue[3:]), red[:3] + np.array([0, 0, C.CUBE_EDGE]), cube_yaw(red[3:]))
    infos = [out[4] for out in follow(env, wps)]
    env.close()
    return infos


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
@pytest.mark.parametrize("seed", [0, 3])
def test_scripted_pick_and_stack_succeeds_only_after_release(embodiment, seed):
    infos = _stack_episode(embodiment, seed)
    assert infos[-1]["success"], infos[-1]["diagnostics"]
    first = next(i for i, info in enumerate(infos) if info["success"])
    assert any(info["is_grasped"] and info["grasped"] == "blue" for info in infos[:first]), "blue was carried"
    # while the gripper still held blue, G could hold but success could not
    assert all(not info["success"] for info in infos if info["is_grasped"])
    assert any(info["goal_satisfied"] and info["is_grasped"] for info in infos[:first])
    assert not infos[first]["is_grasped"]


def test_reused_goal_evaluations_equal_fresh_ones_at_every_step():
    """The environment re-evaluates G only when an object moved (GOAL_REEVALUATE_TOL): at every
    step of a stacking episode its success equals a fresh evaluation of the task's G, and its
    diagnostics are those of the last evaluation (cubes side by side tie in height, and which
    one a stack check names first can flip with a 1e-11 m change)."""
    env = _env("floating_gripper", privileged=True)
    obs, _ = env.reset(seed=1)
    poses = dict(zip(env.unwrapped.object_names, obs["object_poses"], strict=True))
    blue, red = poses["blue"], poses["red"]
    wps = pick_place_waypoints(blue[:3], cube_yaw(blue[3:]), red[:3] + np.array([0, 0, C.CUBE_EDGE]), cube_yaw(red[3:]))
    reused, last = 0, None
    for out in follow(env, wps):
        info, u = out[4], env.unwrapped
        fresh = u.task.evaluate()
        assert info["goal_satisfied"] == fresh.satisfied
        if np.array_equal(u._goal_cache[0], u.scene.pose_vector()):  # evaluated at this step
            last = [r.reason for r in fresh.leaves() if not r.satisfied]
        else:
            reused += 1
            assert np.max(np.abs(u._goal_cache[0] - u.scene.pose_vector())) <= C.GOAL_REEVALUATE_TOL
        assert info["diagnostics"]["unsatisfied"] == last
    assert info["success"] and reused > 0  # some steps reused the result of an earlier state
    env.close()


def test_episode_is_truncated_at_the_limit_and_the_rule_is_documented():
    env = _env("floating_gripper")
    assert env.unwrapped.max_episode_steps == episode_step_limit(2) == C.EPISODE_BASE_STEPS + 2 * C.EPISODE_STEPS_PER_CUBE
    # a 14-cube pyramid on a 3x3 base: 13 of its goals touch a neighbour in their layer (not the
    # top cube), and each of those is pushed into place
    pyramid = BlockTaskEnv(LIBRARY / "pyramid_construction" / "v1", embodiment="floating_gripper", cameras=())
    assert pyramid.max_episode_steps == episode_step_limit(14, 13) == (
        C.EPISODE_BASE_STEPS + 14 * C.EPISODE_STEPS_PER_CUBE + 13 * C.EPISODE_STEPS_PER_PUSH)
    pyramid.close()
    short = _env("floating_gripper", max_episode_steps=3)
    short.reset(seed=0)
    noop = np.array([0, 0, 0, 0, 0, 0, -1], np.float32)
    assert short.step(noop)[3] is False and short.step(noop)[3] is False
    _, _, terminated, truncated, info = short.step(noop)
    assert truncated is True and terminated is False and info["elapsed_steps"] == 3


def test_joint_pos_control_moves_the_panda_to_the_commanded_joints():
    env = _env("panda", control_mode="joint_pos")
    assert env.action_space.shape == (8,)
    obs, _ = env.reset(seed=0)
    target = obs["qpos"][:7].copy()
    target[0] += 0.3
    for _ in range(20):
        obs = env.step(np.append(target, -1.0).astype(np.float32))[0]
    assert np.allclose(obs["qpos"][:7], target, atol=0.02)
    with pytest.raises(EmbodimentError, match="no control mode 'joint_pos'"):
        _env("floating_gripper", control_mode="joint_pos")


def test_ee_abs_control_reaches_a_pose():
    env = _env("floating_gripper", control_mode="ee_abs")
    env.reset(seed=0)
    goal = np.array([0.55, 0.10, C.TABLE_TOP_Z + 0.15, np.pi, 0.0, 0.0, -1.0], np.float32)  # pointing down
    for _ in range(30):
        obs = env.step(goal)[0]
    assert np.allclose(obs["state"][:3], goal[:3], atol=3e-3)


def test_paraphrase_instruction_and_bad_arguments():
    env = _env("floating_gripper", instruction="paraphrase:1")
    obs, info = env.reset(seed=0)
    assert obs["instruction"] == info["instruction"] == "Goal: a stack of red, blue in any order."
    for kwargs, message in [({"instruction": "paraphrase:9"}, "paraphrases"), ({"embodiment": "ur5"}, "unknown embodiment"),
                            ({"cameras": ("top",)}, "unknown camera"), ({"image_size": (0, 10)}, "image_size")]:
        kw = {"embodiment": "floating_gripper", **kwargs}
        with pytest.raises(EmbodimentError, match=message):
            gym.make(ENV_ID, task=str(STACK), **kw)
    with pytest.raises(ValueError, match="action must be 7"):
        env.step(np.zeros(3, np.float32))


def test_loading_goes_through_the_validation_checks(tmp_path):
    task = tmp_path / "stack"
    shutil.copytree(STACK, task)
    code = task / "code.py"
    code.write_text(code.read_text().replace("Stack(objects=['red', 'blue'])", "Stack(objects=['blue', 'red'])"))
    with pytest.raises(BadInput, match="content hash differs"):
        BlockTaskEnv(task, embodiment="floating_gripper", cameras=())
    with pytest.raises(BadInput, match="no task at"):
        BlockTaskEnv(tmp_path / "missing", embodiment="floating_gripper", cameras=())
    # an artifact whose hash matches but whose code the text gate refuses
    forged = _rehashed_copy(tmp_path, "class ", "import os\n\n\nclass ")
    with pytest.raises(TaskInvalid, match="task code rejected"):
        BlockTaskEnv(forged, embodiment="floating_gripper", cameras=())


def test_family_version_targets(tmp_path):
    fam = LIBRARY / "progressive_tower"
    history = load_history(fam)
    env = BlockTaskEnv(f"{fam}@v0", embodiment="floating_gripper", cameras=())
    assert env.source.directory == fam / "v0"
    assert env.source.content_hash == history["versions"][0]["content_hash"]
    head = BlockTaskEnv(fam, embodiment="floating_gripper", cameras=())
    assert head.source.directory == fam / f"v{history['head']}"
    with pytest.raises(BadInput, match="names a version of a family only"):
        BlockTaskEnv(f"{STACK}@v1", embodiment="floating_gripper", cameras=())


def load_history(fam: Path) -> dict:
    from rpg.yamlio import load

    return load((fam / "family.yaml").read_text())


def test_visibility_rays_ignore_the_robot():
    """A semantic task's G (readability rays from the default camera) is the same with a robot."""
    env = _env("panda", task=LIBRARY / "arrange_word")
    env.reset(seed=0)
    env.unwrapped.set_goal_state()
    assert env.unwrapped.task.evaluate().satisfied


def _rpg(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "rpg.cli", *args], capture_output=True, text=True, cwd=cwd, timeout=600)


def test_play_writes_a_video_and_render_shows_the_robot(tmp_path):
    import av

    video = tmp_path / "out.mp4"
    r = _rpg("play", str(STACK), "--embodiment", "floating_gripper", "--policy", "random", "--steps", "6",
             "--video", str(video), "--json")
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["steps"] == 6 and summary["frames"] == 7 and summary["success"] is False
    with av.open(str(video)) as container:
        frames = [f.to_ndarray(format="rgb24") for f in container.decode(video=0)]
    assert len(frames) == 7 and frames[0].shape == (256, 512, 3)
    shots = tmp_path / "new" / "shots"  # -o creates the directory
    for embodiment in EMBODIMENTS:
        r = _rpg("render", str(STACK), "--embodiment", embodiment, "-o", str(shots))
        assert r.returncode == 0, r.stderr
    from PIL import Image

    panda = np.asarray(Image.open(shots / "goal_panda.png")).astype(int)
    hand = np.asarray(Image.open(shots / "goal_floating_gripper.png")).astype(int)
    assert panda.shape == (480, 640, 3)
    # the same goal scene; the Panda's arm rises behind its hand, the floating hand has none
    assert (np.abs(panda - hand).sum(axis=2) > 30).mean() > 0.01
    assert np.abs(np.asarray(Image.open(shots / "initial_panda.png")).astype(int) - panda).max() > 0
    plugin = Path(__file__).with_name("eval_policies.py")
    r = _rpg("play", str(STACK), "--embodiment", "floating_gripper", "--policy", f"{plugin}:Scripted", "--steps", "5",
             "--json")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["policy"] == "Scripted" and json.loads(r.stdout)["steps"] == 5
    bad = _rpg("play", str(STACK), "--policy", "smart")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "unknown policy" in bad.stderr
    bad = _rpg("play", str(STACK), "--video", str(tmp_path / "no" / "out.mp4"))
    assert bad.returncode == 2 and "existing directory" in bad.stderr


def test_snapshots_have_no_black_band_and_agentview_sees_past_the_arm():
    from rpg.domain.render import render_image

    env = _env("panda", cameras=("agentview", "default"), image_size=(120, 160))
    obs, _ = env.reset(seed=0)
    for key in ("agentview_image", "default_image"):
        top = obs[key][:12].astype(float)  # what lies beyond the table: floor or sky, never black
        assert top.mean() > 40, key
    block_only = render_image(env.unwrapped.task.scratch().scene, 160, 120)
    assert block_only is not None and block_only[:12].mean() > 40
    # the Panda at home hides little of the workspace from agentview: compare with the floating hand
    hand = _env("floating_gripper", cameras=("agentview",), image_size=(120, 160)).reset(seed=0)[0]
    differs = np.abs(obs["agentview_image"].astype(int) - hand["agentview_image"].astype(int)).sum(axis=2) > 30
    assert differs[40:].mean() < 0.1  # the table and cubes (lower two thirds) look the same but for shadows


@pytest.mark.parametrize("embodiment", EMBODIMENTS)
def test_every_library_entry_is_an_environment(embodiment):
    from rpg.library.build import load_manifest

    entries = load_manifest(LIBRARY / "manifest.yaml").entries
    assert len(entries) >= 40
    for entry in entries:
        env = BlockTaskEnv(LIBRARY / entry.name, embodiment=embodiment, cameras=(), privileged=True)
        obs, info = env.reset(seed=0)
        assert not info["success"], entry.name  # the non-trivial gate's guarantee holds with a robot too
        sampled = env.task.data.draws(0, 1)[0]
        for row, name in zip(obs["object_poses"], env.object_names, strict=True):
            assert np.allclose(row[:2], sampled[name].pos[:2], atol=3e-3), (entry.name, name)  # the robot hit nothing
        env.step(np.zeros(7, np.float32))


def _rehashed_copy(tmp_path: Path, old: str, new: str) -> Path:
    """A copy of stack_blocks whose code.py has ``old`` replaced by ``new`` and whose recorded
    content hash matches again (as a forger who recomputes it would leave it)."""
    from rpg.artifact import content_hash
    from rpg.yamlio import dump, load

    task = tmp_path / "forged"
    shutil.copytree(STACK, task)
    code = task / "code.py"
    text = code.read_text()
    assert old in text
    code.write_text(text.replace(old, new))
    doc = load((task / "task.yaml").read_text())
    doc["content_hash"] = content_hash(doc, code.read_text(), (task / "goal_state_code.py").read_text())
    (task / "task.yaml").write_text(dump(doc))
    return task


@pytest.mark.parametrize("attack", [
    "self.scene.robot.home = self.assets",      # patch the robot's method
    "self.scene.robot.command = None",          # or its controller
    "BlockTask.evaluate = self.assets",         # or success itself
])
def test_task_code_in_an_environment_cannot_patch_the_robot_or_the_interface(tmp_path, attack):
    """Task code runs in the sandboxed child, which has no robot and no trusted task: the
    attack fails there, and the environment refuses the seed as invalid task data."""
    from rpg.errors import TaskInvalid

    task = _rehashed_copy(tmp_path, "    def initial_state(self, rng):\n",
                          f"    def initial_state(self, rng):\n        {attack}\n")
    env = BlockTaskEnv(task, embodiment="floating_gripper", cameras=())
    with pytest.raises(TaskInvalid, match="initial_state"):
        env.reset(seed=0)
    from rpg.domain.task import Task

    assert Task.evaluate.__module__ == "rpg.domain.task" and callable(env.robot.command)


def test_a_video_interrupted_by_an_error_leaves_no_file(tmp_path):
    from rpg.env.video import VideoWriter

    path = tmp_path / "v.mp4"
    with pytest.raises(RuntimeError), VideoWriter(path, 20) as writer:
        writer.write(np.zeros((32, 32, 3), np.uint8))
        raise RuntimeError("policy crashed")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(ValueError, match="even"), VideoWriter(path, 20) as writer:
        writer.write(np.zeros((31, 32, 3), np.uint8))
    assert list(tmp_path.iterdir()) == []


def test_an_environment_loads_its_task_and_first_episodes_in_one_sandboxed_run(monkeypatch):
    """The task's data and rho_0 of seeds 0-19 come from one sandboxed child (a reset had started a second one)."""
    import rpg.validate.data as data

    seeds_asked, start = [], data._start
    monkeypatch.setattr(data, "_start", lambda sources, seeds, *a, **k: seeds_asked.append(list(seeds)) or start(sources, seeds, *a, **k))
    env = BlockTaskEnv(LIBRARY / "three_block_stack", embodiment="floating_gripper", cameras=(), privileged=True)
    starts = {env.reset(seed=s)[0]["object_poses"].tobytes() for s in range(3)}
    assert seeds_asked == [list(range(data.PREFETCH_SEEDS))] and len(starts) == 3
    env.reset(seed=data.PREFETCH_SEEDS)  # a seed past them: the next block in one more run
    assert seeds_asked[1:] == [list(range(data.PREFETCH_SEEDS, 2 * data.PREFETCH_SEEDS))]


def test_an_environment_loads_and_runs_without_the_language_front_end():
    """Loading a task and stepping it reads the task's files and G, never the instruction's words: no module of the
    parser is imported (its lexicon compiles ~1,400 regular expressions, a second in every process that loads an
    environment), and the canonical instruction is still there, made from G alone."""
    code = ("import sys\nfrom rpg.env import BlockTaskEnv\n"
            f"env = BlockTaskEnv({str(LIBRARY / 'arrange_numbers')!r}, instruction='canonical', cameras=())\n"
            "obs, info = env.reset(seed=0)\nenv.step(env.action_space.sample())\n"
            "print(obs['instruction'])\n"
            "print(sorted(m for m in sys.modules if m.startswith('rpg.schema.') and m not in "
            "('rpg.schema.model', 'rpg.schema.meaning', 'rpg.schema.citations')))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[-1] == "[]"
    assert out[0].strip() and out[0] != BlockTaskEnv(LIBRARY / "arrange_numbers").instruction
