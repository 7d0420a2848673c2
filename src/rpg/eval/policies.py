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
import math
import re
import sys
import time
from pathlib import Path

import numpy as np

from rpg.errors import BadInput, PeerError
from rpg.eval.openpi import MAX_MESSAGE_BYTES

BUILTIN = ("oracle", "random", "noop")
"""Built-in policy names."""

CONNECT_TIMEOUT_S = 10.0
"""Default time a remote policy server has to accept the connection and send its metadata, s."""

INFERENCE_TIMEOUT_S = 30.0
"""Default time one ``policy.act`` may take, s: a remote policy server's time to answer one
observation (sending it included), and the alarm ``rpg eval`` sets around a Python plug-in's
call.  With the connect timeout, a silent server fails each episode within 40 s."""

CLOSE_TIMEOUT_S = 2.0
"""How long closing the connection waits for the server's closing handshake, s."""

MAX_CHUNK = 1024
"""Most actions a policy may return in one chunk (H)."""

ACTION_DIM = 7
"""Action size a remote policy must answer with before :meth:`WebsocketPolicy.bind` (``ee_delta``)."""


class PolicyError(BadInput):
    """A policy that cannot be loaded or that answers with something that is not an action."""


class PolicyServerError(PolicyError, PeerError):
    """A remote policy server that failed (closed the connection, reported an error) or sent
    something rpg refuses (not openpi's msgpack-numpy, a non-numeric dtype, an array its bytes
    do not hold, actions of another shape than asked for, a message over the size limit)."""


class PolicyTimeout(PolicyServerError):
    """A remote policy server that did not connect, or did not answer, within its timeout; the
    message says which timeout fired."""


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

    The server is a peer rpg does not trust: its messages are decoded by
    :func:`rpg.eval.openpi.unpackb` (numeric dtypes only, shapes that match their bytes), at
    most ``max_message_bytes`` each (websockets' ``max_size``; two messages are buffered at
    most), its actions must be (action_dim,) or (H, action_dim) with 1 <= H <= ``max_chunk``,
    and every wait has a deadline: ``connect_timeout`` for the connection and the metadata,
    ``inference_timeout`` for each observation's answer (a server that stops reading the
    observation is cut off at the same deadline).  After an error the connection is closed.

    Args:
        url: ``ws://host:port`` (or ``wss://``).
        connect_timeout: seconds the server has to accept the connection and send its metadata.
        inference_timeout: seconds the server has to answer one observation.
        max_message_bytes: largest message accepted from the server, bytes.
        max_chunk: most actions in one answer (H).

    Raises:
        PolicyError: a timeout or size that is not positive.
        PolicyTimeout: the server did not connect or send its metadata within ``connect_timeout``.
        PolicyServerError: the server cannot be reached, or its metadata is refused or not a map.
    """

    name = "websocket"

    def __init__(self, url: str, connect_timeout: float = CONNECT_TIMEOUT_S,
                 inference_timeout: float = INFERENCE_TIMEOUT_S, max_message_bytes: int = MAX_MESSAGE_BYTES,
                 max_chunk: int = MAX_CHUNK):
        from websockets.sync.client import connect

        for what, value in (("connect_timeout", connect_timeout), ("inference_timeout", inference_timeout),
                            ("max_message_bytes", max_message_bytes), ("max_chunk", max_chunk)):
            if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0 or not math.isfinite(value):
                raise PolicyError(f"{what} must be a positive number, not {value!r}")
        self.url = url
        self.connect_timeout = float(connect_timeout)
        self.inference_timeout = float(inference_timeout)
        self.max_message_bytes = int(max_message_bytes)
        self.max_chunk = int(max_chunk)
        self._action_dim = ACTION_DIM
        self._prompt = ""
        self._stack = contextlib.ExitStack()
        self._ws = None
        deadline = time.monotonic() + self.connect_timeout
        try:
            try:
                self._ws = self._stack.enter_context(
                    connect(url, compression=None, max_size=self.max_message_bytes, max_queue=2,
                            open_timeout=self.connect_timeout, close_timeout=CLOSE_TIMEOUT_S))
            except TimeoutError:
                raise PolicyTimeout(f"the policy server at {url} did not accept the connection within "
                                    f"{self.connect_timeout:g} s (connect timeout)") from None
            except (OSError, ValueError) as exc:
                raise PolicyServerError(f"cannot reach the policy server at {url}: {_one_line(exc)}") from None
            except Exception as exc:  # websockets' own errors (InvalidURI, InvalidHandshake, ConnectionClosed)
                raise PolicyServerError(f"cannot reach the policy server at {url}: {type(exc).__name__}: "
                                        f"{_one_line(exc)}") from None
            raw = self._recv(deadline, "sent no metadata within {t:g} s of connecting (connect timeout)",
                             self.connect_timeout)
            self.metadata = self._decode(raw, "metadata")
            if not isinstance(self.metadata, dict):
                raise PolicyServerError(f"the policy server at {url} sent metadata that is not a map "
                                        f"({type(self.metadata).__name__})")
        except BaseException:
            self.close()
            raise

    def bind(self, env) -> None:
        """Answers must have ``env``'s action size from now on."""
        self._action_dim = int(env.action_space.shape[0])

    def reset(self, instruction: str) -> None:
        self._prompt = instruction

    def act(self, obs: dict) -> np.ndarray:
        """Send one observation and return the server's actions, (action_dim,) or (H, action_dim).

        Raises:
            PolicyTimeout: no answer within ``inference_timeout``.
            PolicyServerError: the connection failed or was closed, the server reported an
                error (a text frame: its last line is shown), or its answer is refused (see
                the class docstring).
        """
        from rpg.eval.openpi import openpi_observation, packb

        if self._ws is None:
            raise PolicyServerError(f"the connection to the policy server at {self.url} is closed")
        try:
            message = packb({**openpi_observation(obs), "prompt": self._prompt})
            deadline = time.monotonic() + self.inference_timeout
            self._send(message)
            reply = self._recv(deadline, "did not answer within {t:g} s (inference timeout)", self.inference_timeout)
            if isinstance(reply, str):
                lines = [x.strip() for x in reply.splitlines() if x.strip()]
                raise PolicyServerError(f"the policy server at {self.url} reported an error: "
                                        f"{(lines[-1] if lines else '')[:300]}")
            doc = self._decode(reply, "answer")
            if not isinstance(doc, dict) or "actions" not in doc:
                raise PolicyServerError(f"the policy server at {self.url} answered without 'actions'")
            actions = doc["actions"]
            if not isinstance(actions, np.ndarray):
                raise PolicyServerError(f"the policy server at {self.url} answered with 'actions' that are a "
                                        f"{type(actions).__name__}, not an array")
            dim = self._action_dim
            if not (actions.shape == (dim,) or (actions.ndim == 2 and actions.shape[1] == dim
                                                and 1 <= actions.shape[0] <= self.max_chunk)):
                raise PolicyServerError(f"the policy server at {self.url} answered with actions of shape "
                                        f"{actions.shape}; expected ({dim},) or (H, {dim}) with 1 <= H <= "
                                        f"{self.max_chunk}")
            return actions
        except BaseException:
            self.close()  # a late or refused answer must not be read as the next observation's
            raise

    def _send(self, message: bytes) -> None:
        """Send ``message``; a server that does not read it is cut off after ``inference_timeout``."""
        import socket
        import threading

        fired = threading.Event()

        def cut() -> None:
            fired.set()
            with contextlib.suppress(OSError):
                self._ws.socket.shutdown(socket.SHUT_RDWR)  # wakes a sendall blocked on a full buffer

        timer = threading.Timer(self.inference_timeout, cut)
        timer.daemon = True
        timer.start()
        try:
            self._ws.send(message)
        except Exception as exc:  # noqa: BLE001 - a dropped connection ends the run with one line
            if fired.is_set():
                raise PolicyTimeout(f"the policy server at {self.url} did not read the observation within "
                                    f"{self.inference_timeout:g} s (inference timeout)") from None
            raise PolicyServerError(f"the policy server at {self.url} failed: {type(exc).__name__}: "
                                    f"{_one_line(exc)}") from None
        finally:
            timer.cancel()
        if fired.is_set():
            raise PolicyTimeout(f"the policy server at {self.url} did not read the observation within "
                                f"{self.inference_timeout:g} s (inference timeout)")

    def _recv(self, deadline: float, late: str, seconds: float):
        """The next message before ``deadline`` (``time.monotonic()``), or an error: ``late``
        (formatted with ``t=seconds``) when it does not come."""
        from websockets.exceptions import ConnectionClosed

        try:
            return self._ws.recv(timeout=max(0.0, deadline - time.monotonic()))
        except TimeoutError:
            raise PolicyTimeout(f"the policy server at {self.url} {late.format(t=seconds)}") from None
        except ConnectionClosed as exc:
            if exc.sent is not None and exc.sent.code == 1009:  # websockets' max_size fired
                raise PolicyServerError(f"the policy server at {self.url} sent a message over the "
                                        f"{self.max_message_bytes}-byte limit (max_message_bytes)") from None
            raise PolicyServerError(f"the policy server at {self.url} closed the connection: "
                                    f"{_one_line(exc)}") from None
        except Exception as exc:  # noqa: BLE001 - a dropped connection ends the run with one line
            raise PolicyServerError(f"the policy server at {self.url} failed: {type(exc).__name__}: "
                                    f"{_one_line(exc)}") from None

    def _decode(self, raw, what: str):
        from rpg.eval.openpi import ProtocolError, unpackb

        try:
            return unpackb(raw, self.max_message_bytes)
        except ProtocolError as exc:
            raise PolicyServerError(f"the policy server at {self.url} sent {what} rpg refuses: {exc}") from None

    def close(self) -> None:
        self._ws = None
        self._stack.close()


def _one_line(exc: BaseException) -> str:
    """An exception's message as one line of at most 300 characters."""
    return " ".join(str(exc).split())[:300]


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


def load_policy(spec: str, inference_timeout: float = INFERENCE_TIMEOUT_S, connect_timeout: float = CONNECT_TIMEOUT_S):
    """The policy a ``--policy`` SPEC names (see the module docstring); a remote server gets
    ``connect_timeout`` and ``inference_timeout`` (s).

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
        return WebsocketPolicy(spec, connect_timeout=connect_timeout, inference_timeout=inference_timeout)
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
        PolicyError: not one action or a chunk of at most :data:`MAX_CHUNK` of them, or
            non-finite values.
    """
    a = np.asarray(raw, dtype=np.float32)
    if a.ndim == 1:
        a = a[None, :]
    if a.ndim != 2 or a.shape[1] != action_dim or not 1 <= a.shape[0] <= MAX_CHUNK:
        raise PolicyError(f"the policy returned an array of shape {np.shape(raw)}; expected ({action_dim},) "
                          f"or (H, {action_dim}) with 1 <= H <= {MAX_CHUNK}")
    if not np.all(np.isfinite(a)):
        raise PolicyError("the policy returned non-finite actions")
    return a
