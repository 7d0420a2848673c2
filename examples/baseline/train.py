"""Train the behaviour-cloning baseline (examples/baseline/policy.py) on ``rpg demos`` datasets.

    python examples/baseline/train.py build/baseline/demos -o build/baseline/bc.pt

DEMOS: ``rpg demos --format hdf5`` datasets (every ``demo.hdf5`` under the directories given).
Deterministic on the CPU for a given seed, thread count and torch version: fixed seeds,
``torch.use_deterministic_algorithms(True)``, a fixed number of threads, batches drawn from a
seeded generator.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import sys
import time
from pathlib import Path

import h5py
import numpy as np
import torch


def _policy_module():
    name = "rpg_baseline_policy"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, Path(__file__).resolve().parent / "policy.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


P = _policy_module()


def _xyzw_to_wxyz(q: np.ndarray) -> np.ndarray:
    return q[..., [3, 0, 1, 2]]


def load_demos(roots: list[Path], horizon: int) -> dict:
    """Every step of every demonstration under ``roots`` as arrays: text (S, 256), robot
    (S, 11), objects (S, N, 17) zero-padded, mask (S, N), actions (S, horizon, 7) (the
    step's action and the next ones), action_mask (S, horizon) (False past the episode's end)."""
    from rpg.artifact import load_artifact

    files = sorted({f for r in roots for f in ([r] if r.is_file() else Path(r).rglob("demo.hdf5"))})
    if not files:
        raise SystemExit(f"no demo.hdf5 under {', '.join(map(str, roots))}")
    consts_by_task: dict[str, dict] = {}
    rows = {"text": [], "robot": [], "objects": [], "actions": [], "action_mask": []}
    episodes, tasks = 0, set()
    for path in files:
        with h5py.File(path, "r") as f:
            for key in sorted(f["data"], key=lambda k: int(k.split("_")[-1])):
                g = f["data"][key]
                task = str(g.attrs["task"])
                if task not in consts_by_task:
                    schema, _ = load_artifact(task)
                    consts_by_task[task] = P.describe_assets(schema.assets)
                consts = consts_by_task[task]
                names = sorted(json.loads(g.attrs["final_poses"]))
                text = P.embed_instruction(str(g.attrs["instruction"]))
                pos = g["obs/robot0_eef_pos"][()]
                quat = _xyzw_to_wxyz(g["obs/robot0_eef_quat"][()])
                fingers = np.abs(g["obs/robot0_gripper_qpos"][()])  # openings (the file has robosuite's signs: +, -)
                obj = g["obs/object"][()].reshape(len(pos), len(names), 7)
                obj = np.concatenate([obj[..., :3], _xyzw_to_wxyz(obj[..., 3:])], axis=-1)
                actions = g["actions"][()].astype(np.float32)
                t_len = len(actions)
                for t in range(t_len):
                    rows["text"].append(text)
                    rows["robot"].append(P.robot_features(pos[t], quat[t], fingers[t]))
                    rows["objects"].append(P.object_features(names, obj[t], pos[t], consts))
                    chunk = np.zeros((horizon, actions.shape[1]), np.float32)
                    n = min(horizon, t_len - t)
                    chunk[:n] = actions[t:t + n]
                    rows["actions"].append(chunk)
                    rows["action_mask"].append(np.arange(horizon) < n)
                episodes += 1
                tasks.add(task)
    n_max = max(len(o) for o in rows["objects"])
    objects = np.zeros((len(rows["objects"]), n_max, P.OBJECT_DIM), np.float32)
    mask = np.zeros((len(rows["objects"]), n_max), bool)
    for i, o in enumerate(rows["objects"]):
        objects[i, :len(o)] = o
        mask[i, :len(o)] = True
    return {"text": np.stack(rows["text"]), "robot": np.stack(rows["robot"]), "objects": objects, "mask": mask,
            "actions": np.stack(rows["actions"]), "action_mask": np.stack(rows["action_mask"]),
            "episodes": episodes, "tasks": sorted(tasks)}


def train(demos: list[Path], out: Path, steps: int = 3000, batch: int = 256, lr: float = 1e-3, seed: int = 0,
          threads: int = 2, horizon: int = 10, execute: int = 5, width: int = 128, layers: int = 2,
          heads: int = 4, noise: float = 0.05, log_every: int = 250) -> dict:
    """Train and write the checkpoint to ``out``; returns the training record (also
    ``out`` with ``.json``)."""
    torch.set_num_threads(threads)
    torch.use_deterministic_algorithms(True)
    torch.manual_seed(seed)
    np.random.seed(seed)
    t0 = time.monotonic()
    data = load_demos(demos, horizon)
    robot = torch.from_numpy(data["robot"])
    objects = torch.from_numpy(data["objects"])
    mask = torch.from_numpy(data["mask"])
    cont = objects[..., :P.OBJECT_CONTINUOUS][mask]
    stats = {"robot_mean": robot.mean(0), "robot_std": robot.std(0).clamp_min(1e-2),
             "obj_mean": cont.mean(0), "obj_std": cont.std(0).clamp_min(1e-2)}
    norm = P.Normalizer(stats)
    text = torch.from_numpy(data["text"])
    robot_n = norm.robot(robot)
    objects_n = norm.objects(objects) * mask[..., None]
    actions = torch.from_numpy(data["actions"])
    amask = torch.from_numpy(data["action_mask"]).float()
    net = P.BCNet(horizon, actions.shape[-1], width, layers, heads)
    opt = torch.optim.AdamW(net.parameters(), lr=lr, weight_decay=1e-4)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=lr, total_steps=steps, pct_start=0.05)
    gen = torch.Generator().manual_seed(seed)
    n = len(robot)
    losses = []
    net.train()
    for step in range(1, steps + 1):
        idx = torch.randint(0, n, (min(batch, n),), generator=gen)
        r = robot_n[idx] + noise * torch.randn(len(idx), robot_n.shape[1], generator=gen)
        o = objects_n[idx].clone()
        o[..., :P.OBJECT_CONTINUOUS] += noise * torch.randn(o[..., :P.OBJECT_CONTINUOUS].shape, generator=gen)
        pred = net(text[idx], r, o, mask[idx])
        err = (pred - actions[idx]).abs().mean(-1)  # L1, as ACT
        loss = (err * amask[idx]).sum() / amask[idx].sum()
        opt.zero_grad()
        loss.backward()
        torch.nn.utils.clip_grad_norm_(net.parameters(), 1.0)
        opt.step()
        sched.step()
        losses.append(float(loss.detach()))
        if log_every and (step % log_every == 0 or step == steps):
            print(f"step {step}/{steps}: L1 {np.mean(losses[-log_every:]):.4f} ({time.monotonic() - t0:.0f} s)",
                  flush=True)
    config = {"horizon": horizon, "execute": execute, "action_dim": int(actions.shape[-1]), "width": width,
              "layers": layers, "heads": heads}
    record = {"config": config, "steps": steps, "batch": batch, "lr": lr, "seed": seed, "threads": threads,
              "noise": noise, "samples": n, "episodes": data["episodes"], "tasks": data["tasks"],
              "final_loss": float(np.mean(losses[-min(len(losses), 100):])),
              "parameters": sum(p.numel() for p in net.parameters()),
              "seconds": round(time.monotonic() - t0, 1), "torch": torch.__version__}
    out.parent.mkdir(parents=True, exist_ok=True)
    torch.save({"model": net.state_dict(), "stats": {k: v for k, v in stats.items()}, "config": config}, out)
    out.with_suffix(".json").write_text(json.dumps(record, indent=2) + "\n")
    return record


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("demos", nargs="+", type=Path, help="rpg demos --format hdf5 datasets (directories or files)")
    ap.add_argument("-o", "--out", type=Path, default=P.DEFAULT_CHECKPOINT)
    ap.add_argument("--steps", type=int, default=3000)
    ap.add_argument("--batch", type=int, default=256)
    ap.add_argument("--lr", type=float, default=1e-3)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--horizon", type=int, default=10)
    ap.add_argument("--execute", type=int, default=5)
    args = ap.parse_args(argv)
    record = train(args.demos, args.out, steps=args.steps, batch=args.batch, lr=args.lr, seed=args.seed,
                   threads=args.threads, horizon=args.horizon, execute=args.execute)
    print(f"{args.out}: {record['episodes']} episodes, {record['samples']} samples, {record['parameters']} "
          f"parameters, final L1 {record['final_loss']:.4f}, {record['seconds']} s")


if __name__ == "__main__":
    main()
