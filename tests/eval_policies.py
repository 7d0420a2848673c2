"""A scripted policy for the rpg eval tests: a pure function of the observation's TCP state
(no memory across calls, so a server that never sees episode boundaries acts the same), that
answers with action chunks (4, 7)."""

from __future__ import annotations

import numpy as np

TARGET = np.array([0.55, 0.05, 1.02])


class Scripted:
    """Moves the TCP toward TARGET in four-step chunks, closing the gripper when it is near."""

    def reset(self, instruction: str) -> None:
        self.instruction = instruction

    def act(self, obs: dict) -> np.ndarray:
        tcp = np.asarray(obs["state"], dtype=np.float64)[:3]
        step = np.clip((TARGET - tcp) * 10.0, -1.0, 1.0)
        grip = 1.0 if np.linalg.norm(TARGET - tcp) < 0.02 else -1.0
        return np.array([[*(step * (1.0 - 0.2 * k)), 0.0, 0.0, 0.0, grip] for k in range(4)], np.float32)
