"""The openpi websocket policy protocol, spoken with ``msgpack`` and ``websockets``.

Wire format (openpi-client 0.1.2, ``openpi_client/msgpack_numpy.py`` and
``websocket_client_policy.py``; not a dependency here, since it pins numpy < 2):

- every message is one binary websocket frame holding a msgpack document;
- a numpy array is packed as the map ``{b"__ndarray__": True, b"data": <raw bytes>,
  b"dtype": <dtype.str, e.g. "<f4">, b"shape": <tuple>}`` and a numpy scalar as
  ``{b"__npgeneric__": True, b"data": <item>, b"dtype": <dtype.str>}``;
- the server sends its metadata (a map) first, on connection;
- the client then sends one observation map per inference and receives one map holding
  ``"actions"`` (an array (H, action_dim): an action chunk); a text frame is an error.

Observation keys (:data:`OBSERVATION_KEYS`): the environment's observation is mapped to the
key names openpi's examples use.
"""

from __future__ import annotations

import functools

import msgpack
import numpy as np

OBSERVATION_KEYS = {
    "observation/image": "agentview_image",
    "observation/wrist_image": "wrist_image",
    "observation/state": "state",
    "prompt": "instruction",
}
"""openpi observation key -> :class:`rpg.env.BlockTaskEnv` observation key.  ``state`` is the
TCP position (3, m, world frame), its orientation as an axis-angle (3, rad) and the two finger
positions (2, m), float64 as the environment gives it (a server casts what it needs); images
are (H, W, 3) uint8."""


def pack_array(obj):
    """msgpack ``default`` hook: numpy arrays and scalars in openpi's layout.

    Raises:
        ValueError: an object, void or complex dtype (openpi refuses them too).
    """
    if isinstance(obj, np.ndarray | np.generic) and obj.dtype.kind in ("V", "O", "c"):
        raise ValueError(f"unsupported dtype: {obj.dtype}")
    if isinstance(obj, np.ndarray):
        return {b"__ndarray__": True, b"data": np.ascontiguousarray(obj).tobytes(), b"dtype": obj.dtype.str,
                b"shape": obj.shape}
    if isinstance(obj, np.generic):
        return {b"__npgeneric__": True, b"data": obj.item(), b"dtype": obj.dtype.str}
    return obj


def unpack_array(obj):
    """msgpack ``object_hook``: the inverse of :func:`pack_array`."""
    if b"__ndarray__" in obj:
        return np.ndarray(buffer=obj[b"data"], dtype=np.dtype(obj[b"dtype"]), shape=obj[b"shape"])
    if b"__npgeneric__" in obj:
        return np.dtype(obj[b"dtype"]).type(obj[b"data"])
    return obj


packb = functools.partial(msgpack.packb, default=pack_array)
unpackb = functools.partial(msgpack.unpackb, object_hook=unpack_array)


def openpi_observation(obs: dict) -> dict:
    """The openpi observation map of an environment observation (keys present only)."""
    return {key: obs[ours] for key, ours in OBSERVATION_KEYS.items() if ours in obs}
