"""The oracle: goal configurations adapted to the episode, its primitives (stacking, moving a
cube off a stack, flipping a letter cube, patches, temporal order) on real library tasks
through env.step, and what it reports when a goal is fragile."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rpg.env import BlockTaskEnv
from rpg.oracle import Oracle, OracleError
from rpg.oracle.goal import placement_order, pose_matches

LIBRARY = Path(__file__).resolve().parents[1] / "library"


def _solve(task: str, embodiment: str, seed: int, **kw):
    env = BlockTaskEnv(LIBRARY / task, embodiment=embodiment, cameras=(), **kw)
    oracle = Oracle(env)
    obs, info = env.reset(seed=seed)
    oracle.reset(obs)
    first_unsatisfied = list(info["diagnostics"]["unsatisfied"])
    done = False
    while not done:
        obs, _, terminated, truncated, info = env.step(oracle.act(obs))
        done = terminated or truncated
    env.close()
    return info, oracle, first_unsatisfied


@pytest.mark.parametrize("embodiment", ["floating_gripper", "panda"])
@pytest.mark.parametrize("task", ["stack_blocks", "three_block_stack", "place_on_goal_patch", "arrange_word"])
def test_oracle_solves_library_tasks_through_env_step(task, embodiment):
    info, oracle, before = _solve(task, embodiment, seed=1)
    assert before, "G was false at the start"
    assert info["success"], (oracle.failure, info["diagnostics"])
    assert oracle.failure is None


def test_a_stack_is_built_on_the_bottom_cube_where_it_lies():
    env = BlockTaskEnv(LIBRARY / "stack_blocks", embodiment="floating_gripper", cameras=())
    env.reset(seed=4)
    red = env.scene.pose("red").pos
    oracle = Oracle(env)
    oracle.act()
    plan = oracle.plan
    assert plan.moves == 1 and plan.order == ["red", "blue"]
    assert np.allclose(plan.targets["red"].pos[:2], red[:2], atol=1e-9)  # red stays
    assert np.allclose(plan.targets["blue"].pos[:2], red[:2], atol=1e-9)  # blue goes on it


def test_targets_follow_the_goal_patch_where_rho0_put_it():
    env = BlockTaskEnv(LIBRARY / "place_on_goal_patch", embodiment="floating_gripper", cameras=())
    for seed in (0, 5):
        env.reset(seed=seed)
        patch = env.scene.pose("gray_patch").pos
        oracle = Oracle(env)
        oracle.act()
        for name in ("red", "blue"):
            assert np.abs(np.subtract(oracle.plan.targets[name].pos[:2], patch[:2])).max() < 0.05


def test_unstacking_an_initial_stack_first():
    info, oracle, _ = _solve("yellow_on_red_unstack_restack", "floating_gripper", seed=0)
    assert info["success"], oracle.failure


def test_a_letter_cube_is_flipped_to_show_its_face():
    env = BlockTaskEnv(LIBRARY / "rotate_cube", embodiment="floating_gripper", cameras=())
    env.reset(seed=0)
    up_before = env.task.evaluate().satisfied
    info, oracle, _ = _solve("rotate_cube", "floating_gripper", seed=0)
    assert not up_before and info["success"], oracle.failure


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 5])
def test_the_panda_flips_a_letter_cube_within_the_episode_budget(seed):
    """B starts on a side face pointing back at the robot (rho_0): the grasp tilts the hand,
    the swing and the turn after it keep the wrist in range (the old flip's sideways hand
    flung the cube off the table: 0 of 20 episodes)."""
    info, oracle, before = _solve("rotate_cube", "panda", seed=seed)
    assert before and info["success"], (oracle.failure, info["diagnostics"])


def test_a_face_down_letter_cube_comes_up_in_two_flips():
    env = BlockTaskEnv(LIBRARY / "rotate_cube", embodiment="floating_gripper", cameras=(), max_episode_steps=400)
    env.reset(seed=1)
    pos = env.scene.pose("letter_b").pos
    env.scene.set_poses({"letter_b": (pos, (np.sqrt(0.5), 0.0, -np.sqrt(0.5), 0.0))})  # local -x (B) down
    obs, *_ = env.step(np.array([0, 0, 0, 0, 0, 0, -1], np.float32))
    oracle = Oracle(env)
    flips = []
    original = oracle._flip

    def counted_flip(name, *args):
        flips.append(name)
        yield from original(name, *args)

    oracle._flip = counted_flip
    oracle.reset(obs)
    done = False
    while not done:
        obs, _, terminated, truncated, info = env.step(oracle.act(obs))
        done = terminated or truncated
    assert info["success"], (oracle.failure, info["diagnostics"])
    assert flips == ["letter_b", "letter_b"]


def test_a_flip_keeps_the_hand_in_the_wrist_range_and_ends_at_the_target_orientation():
    """For every direction the face may point, the planned flip (grasp yaw, turn, 90-degree
    swing, turn after) brings the face up with the hand's yaw within range and no forward tilt
    beyond the Panda's, and it says whether the cube ends at the target's orientation: 15 of 24
    directions do (the others need a pick and place to turn it further than the wrist can)."""
    from rpg.domain.state import yaw_quat
    from rpg.oracle.goal import rot
    from rpg.oracle.planner import FLIP_FORWARD_MAX, YAW_LIMIT, _swing, _wrap

    env = BlockTaskEnv(LIBRARY / "rotate_cube", embodiment="floating_gripper", cameras=())
    env.reset(seed=0)
    oracle = Oracle(env)
    oracle.act()
    target = oracle.plan.targets["letter_b"]
    ends = 0
    for yaw in np.linspace(-np.pi, np.pi, 24, endpoint=False):
        r_now = rot(yaw_quat(yaw))  # upright: B (-x) points at yaw + pi
        theta = _wrap(yaw + np.pi)
        aim, grasp_yaw, tilt, settle, last = oracle._flip_aim(theta, r_now, target)
        after = rot(yaw_quat(settle)) @ _swing(aim, np.pi / 2) @ rot(yaw_quat(_wrap(aim - theta))) @ r_now
        assert after[:, 0] @ (0.0, 0.0, -1.0) > 0.999  # B (-x) up
        assert np.allclose(after, rot(target.quat), atol=0.05) == last
        assert last or abs(yaw) > np.pi / 4  # rho_0 of rotate_cube (yaw within 45 degrees): one move
        ends += last
        turned = grasp_yaw + _wrap(aim - theta)
        assert max(abs(grasp_yaw), abs(turned), abs(turned + settle)) <= YAW_LIMIT
        assert tilt * max(0.0, -np.cos(theta)) <= FLIP_FORWARD_MAX + 1e-9
        assert (np.pi / 2 - tilt) * max(0.0, np.cos(aim)) <= FLIP_FORWARD_MAX + 1e-9
    assert ends >= 12, ends


def test_temporal_order_is_followed_and_the_environment_judges_it():
    info, oracle, _ = _solve("sequential_place_on_target", "floating_gripper", seed=2)
    assert info["success"]
    assert oracle.plan.order.index("blue") < oracle.plan.order.index("red")  # "blue first, then red"
    # the same final state reached in the wrong order is not a success: the env's monitor
    env = BlockTaskEnv(LIBRARY / "sequential_place_on_target", embodiment="floating_gripper", cameras=())
    env.reset(seed=2)
    targets = oracle.plan.targets
    env.scene.set_poses({"red": (targets["red"].pos, targets["red"].quat)})
    env.step(np.array([0, 0, 0, 0, 0, 0, -1], np.float32))
    env.scene.set_poses({"blue": (targets["blue"].pos, targets["blue"].quat)})
    _, _, _, _, info = env.step(np.array([0, 0, 0, 0, 0, 0, -1], np.float32))
    assert info["goal_satisfied"] is False and info["success"] is False
    assert any("out of order" in line for line in info["diagnostics"]["unsatisfied"])


def test_a_fragile_goal_is_reported():
    """A goal configuration that satisfies G only until it settles: each cube of a three-cube
    stack 19 mm off the one below (On allows 20 mm), so the top two together overhang and fall."""
    from dataclasses import replace

    from rpg.domain.state import Pose
    from rpg.domain.task import Task
    from rpg.oracle.goal import plan_goal

    env = BlockTaskEnv(LIBRARY / "three_block_stack", embodiment="floating_gripper", cameras=())
    env.reset(seed=0)
    leaning = {"red": Pose((0.55, 0.0, 0.97), (1, 0, 0, 0)), "green": Pose((0.569, 0.0, 1.0105), (1, 0, 0, 0)),
               "yellow": Pose((0.588, 0.0, 1.051), (1, 0, 0, 0))}
    sizes = {n: 0.04 for n in leaning}
    plan = plan_goal(Task(replace(env.task.data, goal_poses=leaning)), env.scene.poses(), sizes)
    assert any("fragile" in n and "on" in n for n in plan.notes), plan.notes
    upright = {n: Pose((0.55, 0.0, p.pos[2]), p.quat) for n, p in leaning.items()}
    assert not plan_goal(Task(replace(env.task.data, goal_poses=upright)), env.scene.poses(), sizes).notes


@pytest.mark.slow
@pytest.mark.parametrize("task, seed", [("pyramid_construction/v1", 0), ("stack_and_modify/v0", 1)])
def test_the_oracle_builds_layouts_of_touching_cubes_by_placing_beside_and_pushing(task, seed):
    """A 3x3-base pyramid and a 3x3 square of touching cubes (0.5 mm apart): no finger fits
    between two cubes, so most cubes are released beside their goal and pushed in (floating
    gripper; issue 15's dense placement primitive)."""
    import rpg.oracle.planner as planner

    pushes = []
    push = planner.Oracle._push

    def counting(self, name, *args, **kw):
        pushes.append(name)
        yield from push(self, name, *args, **kw)

    planner.Oracle._push = counting
    try:
        info, oracle, before = _solve(task, "floating_gripper", seed=seed)
    finally:
        planner.Oracle._push = push
    assert before and info["success"], (oracle.failure, info["diagnostics"]["unsatisfied"])
    assert sum(t.dense for t in oracle.plan.targets.values()) >= 9
    assert len(set(pushes)) >= 4, pushes  # most of the base went in by a push


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 5])
def test_the_panda_builds_a_pyramid_of_touching_letter_cubes(seed):
    """The Panda's tracking is looser than the floating hand's: it overshot ~6 mm into the
    layout, a held cube crept along the pads and landed ~2.4 mm short, and a push's turn ran
    the wrist into its limit.  Seed 0 failed before the first two were handled, seed 5
    before the last."""
    info, oracle, before = _solve("block_stacking_to_pyramid_building/v1", "panda", seed=seed)
    assert before and info["success"], (oracle.failure, info["diagnostics"]["unsatisfied"])
    assert sum(t.dense for t in oracle.plan.targets.values()) >= 5  # the top cube has no neighbour


@pytest.mark.slow
@pytest.mark.parametrize("task, seed", [("pyramid_construction/v1", 17), ("pyramid_construction/v0", 13)])
def test_the_panda_builds_a_14_cube_pyramid_on_a_3x3_base_within_the_budget(task, seed):
    """Two pyramids of 14 touching cubes with the Panda that needed more than the 2180 steps
    the budget gave before it counted pushes (2229-2275 of 2830 now): 13 of the cubes are
    released beside their goal and pushed in."""
    info, oracle, before = _solve(task, "panda", seed=seed)
    assert before and info["success"], (oracle.failure, info["diagnostics"]["unsatisfied"])
    assert info["elapsed_steps"] > 2180
    assert sum(t.dense for t in oracle.plan.targets.values()) == 13  # the top cube has no neighbour


def test_the_panda_joint_targets_move_in_increments_over_a_control_step():
    """Measured on four Panda tasks x 5 seeds (a 2D pyramid, 3x3 square, piles, a 3x3-base
    pyramid): the oracle succeeded 16/20 with five increments, 10/20 with one jump per step."""
    env = BlockTaskEnv(LIBRARY / "stack_blocks", embodiment="panda", cameras=())
    env.reset(seed=0)
    robot = env.unwrapped.robot
    before = robot.data.ctrl[robot.arm_act].copy()
    robot.command("ee_delta", np.array([1.0, 0.5, -0.5, 0.0, 0.0, 0.4, 1.0]))
    target = robot._to.copy()
    assert np.abs(target - before).max() > 0.01
    n = robot.INTERPOLATION_POINTS
    assert n == 5
    for k in range(n):
        robot.substep(k, n)
        np.testing.assert_allclose(robot.data.ctrl[robot.arm_act], before + (k + 1) / n * (target - before))
    env.close()


def test_a_top_down_turn_of_more_than_pi_goes_through_home_not_across_the_back():
    from rpg.env.embodiments.base import TcpPose
    from rpg.env.scripted import Waypoint, heading, rotation_error, tcp_yaw, top_down_quat

    tcp = TcpPose(np.zeros(3), top_down_quat(1.8))
    assert tcp_yaw(tcp.quat) == pytest.approx(1.8)
    step = heading(tcp, Waypoint((0.0, 0.0, 0.0), -1.8, -1.0))
    assert tcp_yaw(step) == pytest.approx(1.8 - np.pi / 2)  # a quarter turn toward home
    assert rotation_error(tcp, step)[2] < 0  # the shortest way to -1.8 would turn the other way
    near = heading(tcp, Waypoint((0.0, 0.0, 0.0), 1.0, -1.0))
    assert tcp_yaw(near) == pytest.approx(1.0)


def test_placement_order_is_bottom_up_then_temporal_and_refuses_cycles():
    from rpg.oracle.goal import Target

    t = {n: Target(n, (0.5, 0.0, 0.97), (1, 0, 0, 0), 0.04, False, s)
         for n, s in (("a", ()), ("b", ("a",)), ("c", ()))}
    assert placement_order(t, []) == ["a", "b", "c"]
    assert placement_order(t, [["c"], ["a"]]) == ["c", "a", "b"]
    with pytest.raises(OracleError, match="cycle"):
        placement_order(t, [["b"], ["a"]])
    # a dense layout: layer by layer, far row (high x) first, each row from +y to -y
    grid = {f"c{r}{c}": Target(f"c{r}{c}", (0.5 + 0.0405 * r, -0.0405 * c, 0.97), (1, 0, 0, 0), 0.04, False, (), True)
            for r in range(2) for c in range(2)}
    grid["top"] = Target("top", (0.52, -0.02, 1.0105), (1, 0, 0, 0), 0.04, False, tuple(grid), True)
    assert placement_order(grid, []) == ["c10", "c11", "c00", "c01", "top"]


def test_pose_matches_respects_cube_symmetry():
    from rpg.oracle.goal import Target

    coloured = Target("c", (0.5, 0.0, 0.97), (1, 0, 0, 0), 0.04, exact=False)
    letter = Target("l", (0.5, 0.0, 0.97), (1, 0, 0, 0), 0.04, exact=True)
    quarter = (np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4))  # 90 degrees about z
    assert pose_matches(coloured, (0.5, 0.0, 0.97), quarter)
    assert not pose_matches(letter, (0.5, 0.0, 0.97), quarter)
    assert not pose_matches(coloured, (0.53, 0.0, 0.97), (1, 0, 0, 0))


def test_the_oracle_needs_ee_delta_control():
    env = BlockTaskEnv(LIBRARY / "stack_blocks", embodiment="floating_gripper", cameras=(), control_mode="ee_abs")
    with pytest.raises(OracleError, match="ee_delta"):
        Oracle(env)


# -- the solvable gate -------------------------------------------------------------------
def _rpg(*args, cwd=None):
    import os
    import subprocess
    import sys

    env = {**os.environ, "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl"), "LITELLM_LOCAL_MODEL_COST_MAP": "True"}
    return subprocess.run([sys.executable, "-m", "rpg.cli", *args], capture_output=True, text=True, env=env,
                          cwd=cwd, timeout=600)


def test_the_solvable_gate_records_the_oracle_success_rate(tmp_path):
    import json

    import yaml

    r = _rpg("compile", "Put the red block on the blue block", "-o", str(tmp_path), "--gate", "solvable")
    assert r.returncode == 0, r.stdout + r.stderr
    (task,) = [p for p in tmp_path.iterdir() if p.is_dir() and not p.name.startswith(".")]
    gates = {g["gate"]: g for g in json.loads((task / "validation.json").read_text())["gates"]}
    solvable = gates["solvable"]
    assert solvable["status"] == "pass"
    assert solvable["details"]["embodiment"] == "floating_gripper"
    # the gate stops once its verdict is known: three successes of the five seeds it may run
    assert solvable["details"]["episodes"] == 3 and solvable["details"]["successes"] == 3
    assert solvable["details"]["rate"] == 1.0
    assert yaml.safe_load((task / "task.yaml").read_text())["provenance"]["gates"]["solvable"] == "pass"
    # without --gate the optional gate does not run
    r = _rpg("compile", "Put the red block on the blue block", "-o", str(tmp_path / "plain"))
    assert r.returncode == 0
    (plain,) = [p for p in (tmp_path / "plain").iterdir() if p.is_dir() and not p.name.startswith(".")]
    assert "solvable" not in {g["gate"] for g in json.loads((plain / "validation.json").read_text())["gates"]}


@pytest.mark.slow
def test_a_task_the_oracle_cannot_build_is_rejected_and_no_environment_loads_it(tmp_path):
    """A 3x3x3 cube of touching cubes is stable and valid, but the oracle cannot build its
    upper layers (the last cube of a layer has no side to be released beside and pushed in
    from): with --gate solvable the compile is refused, naming the gate."""
    import json

    from rpg.errors import TaskInvalid

    r = _rpg("compile", "Make a 3x3x3 cube of blue blocks", "-o", str(tmp_path), "--gate", "solvable", "--json")
    assert r.returncode == 1, r.stdout + r.stderr
    gates = {g["gate"]: g for g in json.loads(r.stdout)["gates"]}
    assert gates["goal_state"]["status"] == "pass"
    assert gates["solvable"]["status"] == "fail" and "the oracle solved" in gates["solvable"]["message"]
    # three failures of five seeds decide it: the two seeds left are not run
    assert "solved 0 of 3 episodes" in gates["solvable"]["message"]
    (rejected,) = [p for p in (tmp_path / ".rejected").iterdir() if p.is_dir()]
    with pytest.raises(TaskInvalid, match="solvable"):
        BlockTaskEnv(rejected, embodiment="floating_gripper", cameras=())


def test_gate_names_are_checked(tmp_path):
    r = _rpg("compile", "Put the red block on the blue block", "-o", str(tmp_path), "--gate", "visibility")
    assert r.returncode == 2 and "always runs" in r.stderr and "Traceback" not in r.stderr
    r = _rpg("validate", str(LIBRARY / "stack_blocks"), "--gate", "solveable")
    assert r.returncode == 2 and "not an optional gate" in r.stderr
    assert not any(tmp_path.iterdir())


def test_a_manifest_waiver_names_an_optional_gate_and_a_reason(tmp_path):
    from rpg.library.build import ManifestError, load_manifest

    for waive, msg in (({"visibility": "x"}, "not an optional gate"), ({"solvable": " "}, "needs its reason")):
        (tmp_path / "m.yaml").write_text(
            __import__("yaml").safe_dump({"entries": [{"name": "a", "instruction": "stack two blocks",
                                                         "waive": waive}]}))
        with pytest.raises(ManifestError, match=msg):
            load_manifest(tmp_path / "m.yaml")


def test_the_library_passed_the_solvable_gate_or_says_why_not():
    import json

    from rpg.library.build import load_manifest

    for e in load_manifest(LIBRARY / "manifest.yaml").entries:
        dirs = [LIBRARY / e.name] if e.kind == "task" else sorted((LIBRARY / e.name).glob("v*"))
        for d in dirs:
            gates = {g["gate"]: g for g in json.loads((d / "validation.json").read_text())["gates"]}
            if "solvable" in e.waive:
                assert "solvable" not in gates
            else:
                assert gates["solvable"]["status"] == "pass", d
                assert gates["solvable"]["details"]["successes"] >= 3


def test_a_knocked_cube_in_a_dense_layout_is_pushed_back_not_picked_again():
    """A 3x3 base of touching cubes with one cube knocked 15 mm out of its row and turned
    0.1 rad: the oracle pushes it back square (Oracle._nudge) instead of picking it from
    between its neighbours, and the neighbours stay at their goals (the Panda)."""
    from rpg.domain.state import yaw_quat
    from rpg.oracle.goal import rot

    task = LIBRARY / "pyramid_construction/v1"
    env = BlockTaskEnv(task, embodiment="panda", cameras=(), max_episode_steps=400)
    env.reset(seed=0)
    goal = env.task.data.goal_poses
    base = {n: p for n, p in goal.items() if abs(p.pos[2] - 0.97) < 1e-3}
    assert len(base) == 9
    poses = {n: (p.pos, p.quat) for n, p in base.items()}
    aside = [(0.66, -0.2), (0.66, -0.12), (0.66, 0.12), (0.66, 0.2), (0.42, 0.2)]
    for (x, y), n in zip(aside, sorted(set(goal) - set(base)), strict=True):
        poses[n] = ((x, y, 0.97), (1.0, 0.0, 0.0, 0.0))
    knocked = min(base, key=lambda n: (base[n].pos[0], abs(base[n].pos[1])))  # the near row's middle
    x, y, z = base[knocked].pos
    poses[knocked] = ((x - 0.015, y, z), tuple(yaw_quat(0.1)))
    env.scene.set_poses(poses)
    obs, *_ = env.step(np.array([0, 0, 0, 0, 0, 0, -1], np.float32))
    oracle = Oracle(env)
    calls = []
    oracle.reset(obs)
    oracle.act(obs)  # plans
    assert not oracle._at_target(knocked)
    for method in ("_nudge", "_pick_place"):
        original = getattr(oracle, method)

        def recorded(name, *args, _original=original, _method=method):
            calls.append((_method, name))
            return _original(name, *args)
        setattr(oracle, method, recorded)
    oracle.reset(obs)
    for _ in range(120):
        obs, *_ = env.step(oracle.act(obs))
        if calls and calls[0][0] == "_nudge" and oracle._at_target(knocked):
            break
    assert calls[0] == ("_nudge", knocked), calls
    assert ("_pick_place", knocked) not in calls
    assert oracle._at_target(knocked), np.subtract(env.scene.pose(knocked).pos, base[knocked].pos)
    assert abs(np.arctan2(*rot(env.scene.pose(knocked).quat)[1::-1, 0])) < 0.1
    moved = [n for n in base if n != knocked and not oracle._at_target(n)]
    assert not moved, moved


def test_solvability_without_needed_runs_every_seed_and_with_it_stops_once_decided():
    """The benchmark measures a rate over every seed; the gate stops once its verdict is known."""
    from rpg.oracle.solvable import solvability

    full = solvability(LIBRARY / "stack_blocks", seed=0, episodes=4)
    assert full["episodes"] == 4 and full["successes"] == 4 and full["rate"] == 1.0
    decided = solvability(LIBRARY / "stack_blocks", seed=0, episodes=4, needed=2)
    assert decided["episodes"] == 2 and decided["successes"] == 2
