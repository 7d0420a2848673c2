"""The environment API around rpg/BlockTask-v0: an id per library task and suites by filter
(rpg.env.registration), reset(options={"state": ...}) from saved and recorded states
(rpg.env.state), and the wrapper for learners that refuse a Text space (rpg.env.wrappers).
Real library tasks, real MuJoCo episodes, real rpg demos datasets."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import gymnasium as gym
import mujoco
import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from gymnasium.utils.env_checker import check_env

import rpg.env
from rpg.demos.record import SIM_STATE, dataset_state, record_episode
from rpg.env.state import ENV_STATE, RECORDED_STATE, STATE_SPECS
from rpg.env.wrappers import INDEX_KEY, NoTextObservation
from rpg.errors import BadInput
from rpg.eval.runner import eval_tasks
from rpg.library.build import load_manifest
from rpg.steer.family import Family

ROOT = Path(__file__).resolve().parents[1]
LIBRARY = ROOT / "library"
MANIFEST = LIBRARY / "manifest.yaml"
STACK = LIBRARY / "stack_blocks"


def _rpg(*args):
    env = dict(os.environ, MUJOCO_GL="egl", LITELLM_LOCAL_MODEL_COST_MAP="True")
    r = subprocess.run([sys.executable, "-m", "rpg.cli", *map(str, args)], capture_output=True, text=True, env=env,
                       timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return r


def _physics(env) -> np.ndarray:
    """The MuJoCo state rpg demos records (robomimic's ``states`` row)."""
    u = env.unwrapped
    out = np.empty(mujoco.mj_stateSize(u.model, SIM_STATE))
    mujoco.mj_getState(u.model, u.data, out, SIM_STATE)
    return out


# -- ids and suites -----------------------------------------------------------------------
def test_every_library_entry_has_an_id_and_registering_loads_no_task():
    manifest = load_manifest(MANIFEST)
    want = []
    for e in manifest.entries:
        want.append(f"rpg/{e.name}-v0")
        if e.kind == "family":
            want += [f"rpg/{e.name}.v{v.version_id}-v0" for v in Family(LIBRARY / e.name).load().versions]
    assert rpg.env.LIBRARIES["rpg"].ids == tuple(want) and len(want) > len(manifest.entries)
    assert all(i in gym.registry for i in want)
    # a fresh interpreter: importing rpg.env registers them without loading (sandboxing) any task
    code = textwrap.dedent("""
        import sys, time
        import rpg.env
        from rpg.env.registration import register_library
        t = time.perf_counter()
        ids = register_library(sys.argv[1], namespace="timing")
        took = time.perf_counter() - t
        print(len(rpg.env.LIBRARIES["rpg"].ids), len(ids), round(took, 4),
              "rpg.validate.data" in sys.modules, "rpg.validate.sandbox" in sys.modules)
    """)
    out = subprocess.run([sys.executable, "-c", code, str(MANIFEST)], capture_output=True, text=True, timeout=300,
                         cwd="/", env=dict(os.environ, RPG_LIBRARY=str(LIBRARY)))
    assert out.returncode == 0, out.stderr
    n, n_again, took, data_loaded, sandbox_loaded = out.stdout.split()
    assert (int(n), int(n_again), data_loaded, sandbox_loaded) == (len(want), len(want), "False", "False")
    assert float(took) < 1.0, f"registering {len(want)} ids took {took} s: it must read the manifest only"


def test_a_library_id_makes_its_task_with_the_environments_kwargs():
    env = gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=("agentview",), image_size=(32, 48),
                   privileged=True, instruction="paraphrase:0")
    ref = gym.make(rpg.env.ENV_ID, task=str(STACK), embodiment="floating_gripper", cameras=(), privileged=True)
    try:
        u = env.unwrapped
        assert u.source.directory == STACK and u.robot.NAME == "floating_gripper"
        assert env.spec.id == "rpg/stack_blocks-v0" and env.spec.max_episode_steps == u.max_episode_steps
        obs, info = env.reset(seed=4)
        assert obs["agentview_image"].shape == (32, 48, 3) and obs["instruction"] == u.source.paraphrases[0]
        ref_obs, _ = ref.reset(seed=4)
        assert np.array_equal(obs["object_poses"], ref_obs["object_poses"])  # the same rho_0 sample
        assert info["task_hash"] == ref.unwrapped.source.content_hash
    finally:
        env.close()
        ref.close()
    head = Family(LIBRARY / "progressive_tower").load().head
    for i, version in (("rpg/progressive_tower.v2-v0", 2), ("rpg/progressive_tower-v0", head)):
        env = gym.make(i, embodiment="floating_gripper", cameras=())
        try:
            assert env.unwrapped.source.directory == LIBRARY / "progressive_tower" / f"v{version}", i
        finally:
            env.close()


def test_make_suite_selects_with_rpg_evals_targets():
    manifest = load_manifest(MANIFEST)
    suite = rpg.env.make_suite("split=eval")
    assert suite == tuple(f"rpg/{e.name}-v0" for e in manifest.entries if e.split == "eval") and len(suite) == 12
    assert len(suite) == len(eval_tasks("split=eval", library=MANIFEST))  # the same parser
    train = rpg.env.make_suite("split=train")
    assert train == tuple(f"rpg/{e.name}-v0" for e in manifest.entries if e.split == "train") and len(train) == 10
    assert not set(train) & set(suite)
    assert rpg.env.make_suite(str(LIBRARY / "progressive_tower")) == tuple(
        f"rpg/progressive_tower.v{k}-v0" for k in range(6))
    assert rpg.env.make_suite(f"{LIBRARY / 'pile_sorting'}@v1") == ("rpg/pile_sorting.v1-v0",)
    everything = rpg.env.make_suite(str(MANIFEST))
    assert set(suite) < set(everything) and "rpg/progressive_tower-v0" not in everything  # versions, not heads
    with pytest.raises(BadInput, match="selects no task"):
        rpg.env.make_suite("split=nonexistent")
    with pytest.raises(BadInput, match="no library is registered in namespace 'nothing'"):
        rpg.env.make_suite("split=eval", namespace="nothing")


def test_another_library_registers_in_its_own_namespace(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    shutil.copytree(STACK, lib / "stack_blocks")
    (lib / "manifest.yaml").write_text("entries:\n- name: stack_blocks\n  instruction: Stack two blocks on top of "
                                       "each other.\n  split: eval\n")
    ns = f"lib{tmp_path.name[-12:].replace('_', '')}"  # one namespace per test run (the registry is global)
    assert rpg.env.register_library(lib, namespace=ns) == (f"{ns}/stack_blocks-v0",)
    assert rpg.env.register_library(lib / "manifest.yaml", namespace=ns) == (f"{ns}/stack_blocks-v0",)  # again: no-op
    assert rpg.env.make_suite("split=eval", namespace=ns) == (f"{ns}/stack_blocks-v0",)
    env = gym.make(f"{ns}/stack_blocks-v0", embodiment="floating_gripper", cameras=())
    try:
        assert env.unwrapped.source.directory == lib / "stack_blocks"
    finally:
        env.close()
    with pytest.raises(BadInput, match=f"namespace '{ns}' already holds the library"):
        rpg.env.register_library(MANIFEST, namespace=ns)
    with pytest.raises(BadInput, match="is not a task of .* registered in namespace 'rpg'"):
        rpg.env.make_suite(str(lib / "stack_blocks"))
    with pytest.raises(BadInput, match="no library manifest at"):
        rpg.env.register_library(tmp_path / "missing", namespace="missing")


# -- reset(options={"state": ...}) ------------------------------------------------------------
def test_recorded_robomimic_states_replay_to_the_recorded_next_states(tmp_path):
    """rpg demos' robomimic states (floating gripper): each restored state is the recorded one
    bit for bit, its observation the recorded one, and the recorded action from it gives the
    recorded next state; replaying the rest of the demo from its middle ends as it did."""
    import h5py

    _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", tmp_path / "ds", "-n", "1", "--cameras", "",
         "--format", "hdf5")
    with h5py.File(tmp_path / "ds" / "demo.hdf5") as f:
        demo = f["data/demo_0"]
        states, actions = demo["states"][()], demo["actions"][()]
        eef, next_eef = demo["obs/robot0_eef_pos"][()], demo["next_obs/robot0_eef_pos"][()]
        assert demo.attrs["embodiment"] == "floating_gripper" and int(demo.attrs["success"]) == 1
    env = gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=())
    try:
        for t in range(len(actions)):
            obs, info = env.reset(options={"state": states[t]})
            assert np.array_equal(_physics(env), states[t]) and info["elapsed_steps"] == 0
            assert np.abs(obs["state"][:3] - eef[t]).max() < 1e-12, t  # the observation the demo recorded
            obs, *_ = env.step(actions[t])
            if t + 1 < len(actions):
                assert np.abs(_physics(env) - states[t + 1]).max() < 1e-6, t
            assert np.abs(obs["state"][:3] - next_eef[t]).max() < 1e-6, t
        middle = len(actions) // 2
        env.reset(options={"state": states[middle]})
        for t in range(middle, len(actions)):
            obs, reward, terminated, truncated, info = env.step(actions[t])
            if t + 1 < len(actions):
                assert np.abs(_physics(env) - states[t + 1]).max() < 1e-6, t
        assert terminated and info["success"] and info["elapsed_steps"] == len(actions) - middle
    finally:
        env.close()


def test_panda_get_state_restores_exactly_and_recorded_rows_closely():
    ep = record_episode(str(STACK), seed=1, embodiment="panda", cameras=())
    assert ep.success
    env = gym.make("rpg/stack_blocks-v0", embodiment="panda", cameras=(), privileged=True)
    try:
        u = env.unwrapped
        obs, _ = env.reset(seed=1)
        saved, observed = [], []
        for a in ep.actions:  # the recording, replayed from its seed: the env's own states
            saved.append(u.get_state())
            observed.append(obs)
            obs, *_ = env.step(a)
        assert saved[0].shape == (mujoco.mj_stateSize(u.model, ENV_STATE),)
        for t in range(0, ep.length, 7):
            obs, _ = env.reset(options={"state": saved[t]})
            for key in ("state", "qpos", "qvel", "object_poses"):
                assert np.array_equal(obs[key], observed[t][key]), (t, key)
            env.step(ep.actions[t])
            if t + 1 < ep.length:
                assert np.array_equal(u.get_state(), saved[t + 1]), t  # the same bits
        # rpg demos' rows hold no actuator commands: the arm's targets are estimated
        nq = u.model.nq
        errors = []
        for t in range(ep.length):
            obs, _ = env.reset(options={"state": ep.sim_states[t]})
            assert np.allclose(dataset_state(obs["state"]), ep.states[t], atol=1e-6), t
            env.step(ep.actions[t])
            errors.append(np.abs(_physics(env)[1:1 + nq] - ep.sim_states[t + 1][1:1 + nq]).max())
        assert max(errors) < 0.01 and np.median(errors) < 1e-3, (max(errors), np.median(errors))
        env.reset(options={"state": ep.sim_states[ep.length // 2]})
        for a in ep.actions[ep.length // 2:]:
            *_, info = env.step(a)
        assert info["success"]
    finally:
        env.close()


def test_lerobot_joint_and_object_columns_restore_that_frame(tmp_path):
    """A dict state from a LeRobot dataset's observation.joint_pos and observation.object_poses
    (written by default): the robot and every object where the frame says, at rest, and G
    judged on that state as the recording judged it."""
    _rpg("demos", STACK, "--embodiment", "floating_gripper", "--out", tmp_path / "ds", "-n", "1", "--cameras", "")
    frames = pa.concat_tables([pq.read_table(f) for f in sorted((tmp_path / "ds" / "data").glob("chunk-*/*.parquet"))])
    joints = np.array(frames["observation.joint_pos"].to_pylist(), np.float32)
    poses = np.array(frames["observation.object_poses"].to_pylist(), np.float32)
    env = gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=(), privileged=True)
    try:
        for t in (0, len(joints) // 2, len(joints) - 1):
            obs, info = env.reset(options={"state": {"qpos": joints[t], "object_poses": poses[t]}})
            assert np.abs(obs["qpos"] - joints[t]).max() < 1e-6 and not obs["qvel"].any()
            assert np.abs(obs["object_poses"].ravel() - poses[t]).max() < 1e-6
            assert info["elapsed_steps"] == 0 and info["seed"] is None
        u = env.unwrapped
        u.set_goal_state()
        goal = {"qpos": u.robot.robot_qpos(), "object_poses": np.array([[*p.pos, *p.quat] for p in u.scene.poses().values()])}
        env.reset(seed=0)
        obs, info = env.reset(options={"state": goal})
        assert info["goal_satisfied"] and info["success"], "a solved state is accepted, and reported solved"
    finally:
        env.close()


MALFORMED = [
    ("short row", lambda s, q: s[:-1], r"state row has shape \(\d+,\); this environment's .* has \d+ \(mjSTATE_"),
    ("matrix", lambda s, q: np.stack([s, s]), r"state row has shape \(2, \d+\)"),
    ("NaN", lambda s, q: np.where(np.arange(s.size) == 3, np.nan, s), r"non-finite values .* at index 3"),
    ("text", lambda s, q: "qpos", "state must be a MuJoCo state row .* not str"),
    ("zero quaternion", lambda s, q: np.where((np.arange(s.size) >= 4) & (np.arange(s.size) < 8), 0.0, s),  # blue's
     r"the quaternion of 'blue_joint' has norm 0, not 1"),
    ("unknown key", lambda s, q: {"qpos": np.zeros(9), "object_poses": np.zeros((2, 7)), "joints": 1},
     r"unknown key\(s\) 'joints'"),
    ("no poses", lambda s, q: {"qpos": np.zeros(9)}, "state has no object_poses"),
    ("scene qpos", lambda s, q: {"qpos": np.zeros(23), "object_poses": np.zeros((2, 7))},
     r"state\['qpos'\] has 23 values; floating_gripper's qpos has 9"),
    ("hand quaternion", lambda s, q: {"qpos": q * [1, 1, 1, 0, 0, 0, 0, 1, 1],
                                      "object_poses": np.zeros((2, 7))},
     r"state\['qpos'\]: the quaternion of 'robot/hand_joint' has norm 0"),
    ("poses shape", lambda s, q: {"qpos": q, "object_poses": np.zeros((3, 7))},
     r"state\['object_poses'\] has shape \(3, 7\); \w+ has 2 objects \(blue, red\)"),
    ("pose quaternion", lambda s, q: {"qpos": q, "object_poses": np.zeros((2, 7))},
     r"the quaternion of 'blue' has norm 0"),
]


def test_malformed_states_are_refused_with_the_problem_named():
    env = gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=())
    try:
        env.reset(seed=0)
        env.step(np.array([0.3, 0, -0.2, 0, 0, 0, -1], np.float32))
        good, before = _physics(env), env.unwrapped.get_state()
        robot = env.unwrapped.robot.robot_qpos()
        for name, make, message in MALFORMED:
            with pytest.raises(ValueError, match=message):
                env.reset(options={"state": make(good, robot)})
            assert np.array_equal(env.unwrapped.get_state(), before), f"{name}: a refused state changed the env"
        with pytest.raises(ValueError, match="the only option is 'state'"):
            env.reset(options={"init_state": good})
        assert env.reset(options={"state": good})[1]["elapsed_steps"] == 0
        assert set(STATE_SPECS) == {ENV_STATE, RECORDED_STATE} and RECORDED_STATE == SIM_STATE
    finally:
        env.close()


# -- NoTextObservation ----------------------------------------------------------------------
def _leaves(space):
    if isinstance(space, gym.spaces.Dict):
        return [leaf for s in space.spaces.values() for leaf in _leaves(s)]
    return [space]


def test_no_text_observation_passes_check_env_and_vectorizes():
    env = NoTextObservation(gym.make("rpg/stack_blocks-v0", embodiment="floating_gripper", cameras=("agentview",),
                                     image_size=(32, 32), instruction="paraphrase:1"), index=True)
    try:
        check_env(env, skip_render_check=True)
        assert all(isinstance(s, (gym.spaces.Box, gym.spaces.Discrete)) for s in _leaves(env.observation_space))
        obs, info = env.reset(seed=0)
        u = env.unwrapped
        assert "instruction" not in obs and info["instruction"] == u.source.paraphrases[1]
        assert obs[INDEX_KEY] == 3 and u.instructions[obs[INDEX_KEY]] == info["instruction"]
        obs, *_, info = env.step(env.action_space.sample())
        assert env.observation_space.contains(obs) and info["instruction"] == u.source.paraphrases[1]
        with pytest.raises(ValueError, match="apply it once"):
            NoTextObservation(env)
    finally:
        env.close()
    venv = gym.make_vec("rpg/stack_blocks-v0", num_envs=2, vectorization_mode="sync", wrappers=[NoTextObservation],
                        embodiment="floating_gripper", cameras=())
    try:
        assert all(isinstance(s, gym.spaces.Box) for s in _leaves(venv.observation_space))
        obs, infos = venv.reset(seed=[0, 1])
        assert obs["state"].shape == (2, 8) and "instruction" not in obs
        obs, reward, terminated, truncated, infos = venv.step(venv.action_space.sample())
        assert list(infos["instruction"]) == ["Stack two blocks on top of each other."] * 2
        assert list(infos["elapsed_steps"]) == [1, 1]
    finally:
        venv.close()


def test_library_ids_in_spawned_vector_workers():
    # "rpg.env:" imports rpg.env in each spawned worker, which registers the default library
    venv = gym.vector.AsyncVectorEnv(
        [lambda: NoTextObservation(gym.make("rpg.env:rpg/stack_green_on_blue-v0", embodiment="floating_gripper",
                                            cameras=()))] * 2, context="spawn")
    try:
        obs, infos = venv.reset(seed=[0, 1])
        assert obs["state"].shape == (2, 8) and list(infos["seed"]) == [0, 1]
        obs, *_, infos = venv.step(venv.action_space.sample())
        assert list(infos["elapsed_steps"]) == [1, 1]
        assert all("green" in text for text in infos["instruction"])
    finally:
        venv.close()
