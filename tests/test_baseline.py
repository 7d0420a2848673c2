"""examples/baseline: train a few steps on two tiny demonstrations, evaluate one episode with rpg eval."""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

torch = pytest.importorskip("torch", reason="the baseline needs PyTorch: pip install -e '.[baseline]' "
                                            "(make install adds it)")

ROOT = Path(__file__).resolve().parents[1]
BASELINE = ROOT / "examples" / "baseline"
TASK = "library/stack_red_on_yellow"
RPG = str(Path(sys.executable).with_name("rpg"))


def _module(name: str):
    spec = importlib.util.spec_from_file_location(f"test_baseline_{name}", BASELINE / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def demos(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("demos") / "stack"
    subprocess.run([RPG, "demos", TASK, "--format", "hdf5", "--cameras", "", "--embodiment", "panda", "-n", "2",
                    "-o", str(out)], check=True, cwd=ROOT, capture_output=True)
    return out


def test_train_and_eval(demos: Path, tmp_path: Path) -> None:
    train = _module("train")
    ckpt = tmp_path / "bc.pt"
    record = train.train([demos], ckpt, steps=3, batch=32, threads=1, width=32, layers=1, heads=2, log_every=0)
    assert record["episodes"] == 2 and record["samples"] > 0 and ckpt.is_file()
    # deterministic: the same seed gives the same weights
    again = train.train([demos], tmp_path / "again.pt", steps=3, batch=32, threads=1, width=32, layers=1, heads=2,
                        log_every=0)
    assert again["final_loss"] == record["final_loss"]
    a, b = torch.load(ckpt, weights_only=True)["model"], torch.load(tmp_path / "again.pt", weights_only=True)["model"]
    assert all(torch.equal(a[k], b[k]) for k in a)

    run = tmp_path / "run"
    res = subprocess.run([RPG, "eval", TASK, "--policy", "examples/baseline/policy.py:BCPolicy", "--cameras", "",
                          "--seeds", "1000", "-o", str(run)], cwd=ROOT, capture_output=True, text=True,
                         env={**os.environ, "RPG_BC_CHECKPOINT": str(ckpt)})
    assert res.returncode == 0, res.stdout + res.stderr
    episodes = [json.loads(x) for x in (run / "episodes.jsonl").read_text().splitlines() if x.strip()]
    assert len(episodes) == 1 and not episodes[0].get("error") and episodes[0]["steps"] > 0
    assert json.loads((run / "summary.json").read_text())["overall"]["n"] == 1


def test_features_match_the_environment(demos: Path) -> None:
    """The features trained on (from the HDF5 dataset) are those BCPolicy computes from the env."""
    from rpg.artifact import load_artifact
    from rpg.env import BlockTaskEnv
    from rpg.env.embodiments.base import axis_angle_to_quat

    train = _module("train")
    p = train.P
    data = train.load_demos([demos], horizon=4)
    env = BlockTaskEnv(TASK, cameras=())
    try:
        obs, _ = env.reset(seed=0)  # the dataset's first episode is seed 0
        s = obs["state"]
        robot = p.robot_features(s[:3], axis_angle_to_quat(s[3:6]), s[6:8])
        poses = env.scene.poses()
        names = sorted(poses)
        consts = p.describe_assets(load_artifact(env.source.directory)[0].assets)
        objects = p.object_features(names, np.array([[*poses[n].pos, *poses[n].quat] for n in names]), s[:3], consts)
    finally:
        env.close()
    np.testing.assert_allclose(data["robot"][0], robot, atol=1e-6)
    np.testing.assert_allclose(data["objects"][0][: len(names)], objects, atol=1e-6)
