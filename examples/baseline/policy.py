"""A language-conditioned behaviour-cloning policy for rpg, state only (``BCPolicy``).

``rpg eval split=eval --policy examples/baseline/policy.py:BCPolicy --cameras ''`` loads the
checkpoint that ``examples/baseline/train.py`` wrote (``build/baseline/bc.pt``, or the file
``RPG_BC_CHECKPOINT`` names) and answers each observation with an action chunk.

Inputs, the same at training (from ``rpg demos --format hdf5``) and at evaluation (from the
environment, :meth:`BCPolicy.bind`):

- the robot: TCP position, its orientation as the first two columns of its rotation matrix,
  the two finger openings (11 numbers);
- every object of the scene (privileged: cubes and goal patches, read from the simulator as
  ``rpg demos`` records them, sorted by name): position, position relative to the TCP, yaw
  modulo 90 degrees (sin and cos of 4 yaw), tilt, the colour's RGB from rpg's palette, the
  kind (coloured cube, letter/digit cube, goal patch), a long-patch flag and the edge; one
  token each;
- the instruction: WordLlama's 256-d embedding (the model rpg's diversity measures use,
  loaded offline from its wheel).

The network is a small transformer encoder over [instruction, robot, objects...] tokens; a
readout token predicts a chunk of ``horizon`` actions (``ee_delta``, 7 numbers), of which the
policy returns the first ``execute`` (it asks again after them).
"""

from __future__ import annotations

import os
from pathlib import Path

import mujoco
import numpy as np
import torch
from torch import nn

HERE = Path(__file__).resolve().parent
DEFAULT_CHECKPOINT = HERE.parents[1] / "build" / "baseline" / "bc.pt"
"""Where ``train.py`` writes the checkpoint by default (the repository's ``build/``)."""

ROBOT_DIM = 11
OBJECT_DIM = 17
TEXT_DIM = 256
OBJECT_CONTINUOUS = 9
"""Leading object features that are normalized (position, relative position, yaw, tilt); the
rest (colour, kind, shape, edge) enter as they are."""

KINDS = ("colored_cube", "semantic_cube", "goal_patch")


def _palette() -> dict[str, tuple[float, float, float]]:
    from rpg.domain.palette import PALETTE

    return PALETTE


def describe_assets(assets) -> dict[str, np.ndarray]:
    """Per object name, its constant features (colour RGB, kind one-hot, long flag, edge m);
    ``assets`` is a task schema's asset list (:func:`rpg.artifact.load_artifact`)."""
    palette = _palette()
    out = {}
    for a in assets:
        rgb = palette.get(a.color or "", (0.5, 0.5, 0.5)) if a.kind != "semantic_cube" else (1.0, 1.0, 1.0)
        kind = [float(a.kind == k) for k in KINDS]
        out[a.name] = np.array([*rgb, *kind, float(a.shape == "long"), float(a.size or 0.04) / 0.04], np.float32)
    return out


def _rot6(quat_wxyz: np.ndarray) -> np.ndarray:
    m = np.zeros(9)
    mujoco.mju_quat2Mat(m, np.asarray(quat_wxyz, float))
    m = m.reshape(3, 3)
    return np.concatenate([m[:, 0], m[:, 1]])


def robot_features(pos: np.ndarray, quat_wxyz: np.ndarray, fingers: np.ndarray) -> np.ndarray:
    """(11,) TCP position, rotation (two matrix columns), finger openings."""
    return np.concatenate([pos, _rot6(quat_wxyz), fingers]).astype(np.float32)


def object_features(names: list[str], poses: np.ndarray, tcp_pos: np.ndarray,
                    consts: dict[str, np.ndarray]) -> np.ndarray:
    """(N, 17) object tokens; ``poses`` (N, 7) position and quaternion (w, x, y, z) in the
    order of ``names``."""
    out = np.zeros((len(names), OBJECT_DIM), np.float32)
    for i, name in enumerate(names):
        pos, q = poses[i, :3], poses[i, 3:7]
        m = np.zeros(9)
        mujoco.mju_quat2Mat(m, np.asarray(q, float))
        m = m.reshape(3, 3)
        yaw = np.arctan2(m[1, 0], m[0, 0])
        out[i, :OBJECT_CONTINUOUS] = [*pos, *(pos - tcp_pos), np.sin(4 * yaw), np.cos(4 * yaw), m[2, 2]]
        out[i, OBJECT_CONTINUOUS:] = consts[name]
    return out


_EMBEDDINGS: dict[str, np.ndarray] = {}


def embed_instruction(text: str) -> np.ndarray:
    """WordLlama's unit-length 256-d embedding of ``text`` (offline; cached)."""
    if text not in _EMBEDDINGS:
        from rpg.diversity.embeddings import embed

        _EMBEDDINGS[text] = embed([text], "wordllama")[0].astype(np.float32)
    return _EMBEDDINGS[text]


class BCNet(nn.Module):
    """Transformer encoder over [readout, instruction, robot, objects] tokens -> action chunk."""

    def __init__(self, horizon: int = 10, action_dim: int = 7, width: int = 128, layers: int = 2, heads: int = 4):
        super().__init__()
        self.horizon, self.action_dim = horizon, action_dim
        self.readout = nn.Parameter(torch.zeros(1, 1, width))
        self.text = nn.Linear(TEXT_DIM, width)
        self.robot = nn.Sequential(nn.Linear(ROBOT_DIM, width), nn.GELU(), nn.Linear(width, width))
        self.obj = nn.Sequential(nn.Linear(OBJECT_DIM, width), nn.GELU(), nn.Linear(width, width))
        self.kind = nn.Parameter(torch.zeros(4, width))  # token type: readout, text, robot, object
        layer = nn.TransformerEncoderLayer(width, heads, dim_feedforward=2 * width, dropout=0.0,
                                           batch_first=True, norm_first=True)
        self.encoder = nn.TransformerEncoder(layer, layers, enable_nested_tensor=False)
        self.head = nn.Sequential(nn.LayerNorm(width), nn.Linear(width, 2 * width), nn.GELU(),
                                  nn.Linear(2 * width, horizon * action_dim))

    def forward(self, text, robot, objects, mask):
        """text (B, 256), robot (B, 11), objects (B, N, 17), mask (B, N) True where an object
        is present -> actions (B, horizon, action_dim)."""
        b = text.shape[0]
        tokens = torch.cat([
            self.readout.expand(b, 1, -1) + self.kind[0],
            (self.text(text) + self.kind[1])[:, None],
            (self.robot(robot) + self.kind[2])[:, None],
            self.obj(objects) + self.kind[3],
        ], dim=1)
        pad = torch.cat([torch.zeros(b, 3, dtype=torch.bool), ~mask], dim=1)
        h = self.encoder(tokens, src_key_padding_mask=pad)
        return self.head(h[:, 0]).view(b, self.horizon, self.action_dim)


class Normalizer:
    """Feature standardization with the training set's statistics (stored in the checkpoint)."""

    def __init__(self, stats: dict):
        self.stats = {k: torch.as_tensor(v, dtype=torch.float32) for k, v in stats.items()}

    def robot(self, x):
        return (x - self.stats["robot_mean"]) / self.stats["robot_std"]

    def objects(self, x):
        c = OBJECT_CONTINUOUS
        head = (x[..., :c] - self.stats["obj_mean"]) / self.stats["obj_std"]
        return torch.cat([head, x[..., c:]], dim=-1)


def load_checkpoint(path: str | Path):
    """(net, normalizer, config) from a checkpoint ``train.py`` wrote."""
    ckpt = torch.load(path, map_location="cpu", weights_only=True)
    cfg = ckpt["config"]
    net = BCNet(cfg["horizon"], cfg["action_dim"], cfg["width"], cfg["layers"], cfg["heads"])
    net.load_state_dict(ckpt["model"])
    net.eval()
    return net, Normalizer(ckpt["stats"]), cfg


class BCPolicy:
    """The trained behaviour-cloning policy as an ``rpg eval`` plug-in.

    Reads the robot state from the observation and the objects' poses from the environment
    (privileged); returns the first ``execute`` actions of each predicted chunk, the gripper
    snapped to open/closed.
    """

    name = "bc"

    def __init__(self, checkpoint: str | Path | None = None):
        path = Path(checkpoint or os.environ.get("RPG_BC_CHECKPOINT") or DEFAULT_CHECKPOINT)
        if not path.is_file():
            raise FileNotFoundError(f"no checkpoint at {path}: run `make baseline` or examples/baseline/train.py")
        torch.set_num_threads(1)  # rpg eval runs one policy per worker process
        self.net, self.norm, self.cfg = load_checkpoint(path)
        self.execute = int(self.cfg["execute"])

    def bind(self, env) -> None:
        from rpg.artifact import load_artifact

        self._env = env.unwrapped
        schema, _ = load_artifact(self._env.source.directory)
        self._consts = describe_assets(schema.assets)

    def reset(self, instruction: str) -> None:
        self._text = torch.from_numpy(embed_instruction(instruction))[None]

    def act(self, obs: dict) -> np.ndarray:
        from rpg.env.embodiments.base import axis_angle_to_quat

        state = np.asarray(obs["state"], float)
        robot = robot_features(state[:3], axis_angle_to_quat(state[3:6]), state[6:8])
        poses = self._env.scene.poses()
        names = sorted(poses)
        arr = np.array([[*poses[n].pos, *poses[n].quat] for n in names])
        objects = object_features(names, arr, state[:3], self._consts)
        with torch.no_grad():
            chunk = self.net(self._text, self.norm.robot(torch.from_numpy(robot)[None]),
                             self.norm.objects(torch.from_numpy(objects)[None]),
                             torch.ones(1, len(names), dtype=torch.bool))[0].numpy()
        chunk = np.clip(chunk[: self.execute], -1.0, 1.0)
        chunk[:, -1] = np.where(chunk[:, -1] >= 0, 1.0, -1.0)
        return chunk.astype(np.float32)
