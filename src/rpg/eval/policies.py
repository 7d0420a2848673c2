"""Policies ``rpg eval`` runs: built-ins, Python plug-ins and remote openpi servers.

A policy is any object with

- ``reset(instruction: str) -> None``: a new episode starts; ``instruction`` is the exact
  text the policy is given (canonical or a paraphrase);
- ``act(obs: dict) -> array``: one action (action_dim,) or an action chunk
  (H, action_dim) for the environment's action space (``ee_delta``: 7 numbers in [-1, 1]).

and optionally ``bind(env)``, called once with the :class:`rpg.env.BlockTaskEnv` before its
episodes (the built-ins use it; a plug-in that reads privileged state may too).

``SPEC`` (:func:`load_policy`): ``oracle``, ``random``, ``noop``; ``module:Class`` or
``path/to/file.py:Class`` (constructed without arguments); ``ws://host:port`` (an openpi
policy server, :mod:`rpg.eval.openpi`).
"""

from __future__ import annotations

import contextlib
import importlib
import importlib.util
import re
import sys
from pathlib import Path

import numpy as np

from rpg.errors import BadInput

BUILTIN = ("oracle", "random", "noop")
"""Built-in policy names."""

CONNECT_TIMEOUT_S = 30.0
"""How long a remote policy server may take to accept the connection, s."""


class PolicyError(BadInput):
    """A policy that cannot be loaded or that answers with something that is not an action."""


class NoopPolicy:
    """Holds still with the gripper open: every action is zero motion, gripper -1."""

    name = "noop"

    def bind(self, env) -> None:
        self._action = np.zeros(env.action_space.shape, np.float32)
        self._action[-1] = -1.0

    def reset(self, instruction: str) -> None:
        pass

    def act(self, obs: dict) -> np.ndarray:
        return self._action


class RandomPolicy:
    """Uniform actions from the action space, from a generator seeded with the episode's seed
    (the same episode gets the same actions whatever the job that runs it)."""

    name = "random"

    def bind(self, env) -> None:
        self._env = env.unwrapped
        self._space = env.action_space

    def reset(self, instruction: str) -> None:
        self._rng = np.random.default_rng([0x5EED, int(self._env._seed or 0)])

    def act(self, obs: dict) -> np.ndarray:
        return self._rng.uniform(self._space.low, self._space.high).astype(np.float32)


class OraclePolicy:
    """:class:`rpg.oracle.Oracle`: privileged planning, the upper-bound baseline."""

    name = "oracle"

    def bind(self, env) -> None:
        from rpg.oracle import Oracle

        self._oracle = Oracle(env)

    def reset(self, instruction: str) -> None:
        self._oracle.reset()

    def act(self, obs: dict) -> np.ndarray:
        return self._oracle.act(obs)


class WebsocketPolicy:
    """A remote policy speaking openpi's websocket protocol (:mod:`rpg.eval.openpi`).

    Args:
        url: ``ws://host:port`` (or ``wss://``).

    Raises:
        PolicyError: the server cannot be reached, or sends no metadata.
    """

    name = "websocket"

    def __init__(self, url: str):
        from websockets.sync.client import connect

        from rpg.eval.openpi import unpackb

        self.url = url
        self._stack = contextlib.ExitStack()
        try:
            self._ws = self._stack.enter_context(
                connect(url, compression=None, max_size=None, open_timeout=CONNECT_TIMEOUT_S))
            self.metadata = unpackb(self._ws.recv(timeout=CONNECT_TIMEOUT_S))
        except (OSError, TimeoutError, ValueError) as exc:
            raise PolicyError(f"cannot reach the policy server at {url}: {exc}") from None
        except Exception as exc:  # websockets' own errors (InvalidURI, InvalidHandshake, ConnectionClosed)
            raise PolicyError(f"cannot reach the policy server at {url}: {type(exc).__name__}: {exc}") from None
        self._prompt = ""

    def reset(self, instruction: str) -> None:
        self._prompt = instruction

    def act(self, obs: dict) -> np.ndarray:
        from rpg.eval.openpi import openpi_observation, packb, unpackb

        try:
            self._ws.send(packb({**openpi_observation(obs), "prompt": self._prompt}))
            reply = self._ws.recv()
        except Exception as exc:  # noqa: BLE001 - a dropped connection ends the run with one line
            raise PolicyError(f"the policy server at {self.url} failed: {type(exc).__name__}: {exc}") from None
        if isinstance(reply, str):
            raise PolicyError(f"the policy server at {self.url} reported an error: {reply[:300]}")
        doc = unpackb(reply)
        if not isinstance(doc, dict) or "actions" not in doc:
            raise PolicyError(f"the policy server at {self.url} answered without 'actions'")
        return np.asarray(doc["actions"])

    def close(self) -> None:
        self._stack.close()


def _load_class(spec: str):
    where, _, cls_name = spec.rpartition(":")
    if where.endswith(".py") or "/" in where:
        path = Path(where)
        if not path.is_file():
            raise PolicyError(f"policy file {where} does not exist")
        mod_name = f"rpg_policy_{re.sub(r'[^0-9A-Za-z_]', '_', path.stem)}"
        loader = importlib.util.spec_from_file_location(mod_name, path)
        module = importlib.util.module_from_spec(loader)
        sys.modules[mod_name] = module
        try:
            loader.loader.exec_module(module)
        except Exception as exc:  # noqa: BLE001 - the user's file: one line, not a traceback
            raise PolicyError(f"policy file {where} failed to import: {type(exc).__name__}: {exc}") from None
    else:
        try:
            module = importlib.import_module(where)
        except Exception as exc:  # noqa: BLE001 - ModuleNotFoundError or the module's own error
            raise PolicyError(f"policy module {where!r} cannot be imported: {type(exc).__name__}: {exc}") from None
    cls = getattr(module, cls_name, None)
    if cls is None:
        raise PolicyError(f"{where} has no {cls_name!r}")
    return cls


def load_policy(spec: str):
    """The policy a ``--policy`` SPEC names (see the module docstring).

    Raises:
        PolicyError: an unknown name, a module or class that cannot be loaded, a class
            without ``reset``/``act``, or an unreachable server.
    """
    spec = str(spec).strip()
    if spec == "oracle":
        return OraclePolicy()
    if spec == "random":
        return RandomPolicy()
    if spec == "noop":
        return NoopPolicy()
    if spec.startswith(("ws://", "wss://")):
        return WebsocketPolicy(spec)
    if ":" not in spec or spec.endswith(":"):
        raise PolicyError(f"unknown policy {spec!r}: give {', '.join(BUILTIN)}, module:Class, "
                          "path/to/file.py:Class or ws://host:port")
    cls = _load_class(spec)
    try:
        policy = cls()
    except Exception as exc:  # noqa: BLE001 - the user's constructor
        raise PolicyError(f"policy {spec} could not be constructed: {type(exc).__name__}: {exc}") from None
    if not (callable(getattr(policy, "reset", None)) and callable(getattr(policy, "act", None))):
        raise PolicyError(f"policy {spec} needs reset(instruction) and act(obs) methods")
    return policy


def action_chunk(raw, action_dim: int) -> np.ndarray:
    """A policy's answer as a chunk (H, action_dim) float32.

    Raises:
        PolicyError: not one action or a chunk of them, or non-finite values.
    """
    a = np.asarray(raw, dtype=np.float32)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != action_dim or a.shape[0] < 1:
        raise PolicyError(f"the policy returned an array of shape {np.shape(raw)}; expected ({action_dim},) "
                          f"or (H, {action_dim})")
    if not np.all(np.isfinite(a)):
        raise PolicyError("the policy returned non-finite actions")
    return a
