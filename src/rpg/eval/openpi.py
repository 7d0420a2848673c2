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

Decoding trusts nothing the server says (:func:`unpackb`): a message is at most
:data:`MAX_MESSAGE_BYTES` (the client also gives websockets that ``max_size``), arrays and
scalars must have a bool, integer or float dtype (:data:`NUMERIC_KINDS`; object, void, string,
datetime, complex and structured dtypes are refused before numpy parses them), and a declared
shape must account for exactly the bytes sent, so a 150-byte message never allocates more
than 150 bytes.  :class:`ProtocolError` says what was refused, in one line.

Observation keys (:data:`OBSERVATION_KEYS`): the environment's observation is mapped to the
key names openpi's examples use.
"""

from __future__ import annotations

import functools
import math
import re

import msgpack
import numpy as np

from rpg.errors import PeerError

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


MAX_MESSAGE_BYTES = 64 * 1024**2
"""Default cap on one message from a policy server, bytes (websockets' ``max_size``, and what
:func:`unpackb` accepts): an action chunk is a few KB, metadata rarely more."""

NUMERIC_KINDS = frozenset("biuf")
"""dtype kinds :func:`unpack_array` decodes: bool, signed and unsigned integers, floats."""

MAX_ARRAY_DIMS = 8
"""Most dimensions of a decoded array."""

_DTYPE_STR = re.compile(r"[<>|=]?[biuf?][0-9]{0,2}")
"""What a numeric ``dtype.str`` looks like (``<f4``, ``|u1``, ``|b1``); anything else is refused
before numpy parses it (numpy reads lists, dicts and strings such as ``"f8,O"`` as structured
or object dtypes)."""


class ProtocolError(PeerError):
    """A message from a policy server that is not openpi's msgpack-numpy, or that declares an
    array its bytes do not hold, of a dtype other than bool, integer or float."""


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


def _numeric_dtype(raw) -> np.dtype:
    """The dtype a peer named, if it is a plain bool, integer or float dtype.

    Raises:
        ProtocolError: anything else (object, void, string, datetime, complex, structured, subarray).
    """
    if not isinstance(raw, str) or len(raw) > 8 or not _DTYPE_STR.fullmatch(raw):
        raise ProtocolError(f"dtype {str(raw)[:40]!r} is refused: only bool, integer and float arrays are decoded")
    try:
        dt = np.dtype(raw)
    except (TypeError, ValueError):
        raise ProtocolError(f"dtype {raw!r} is not a numpy dtype") from None
    if dt.kind not in NUMERIC_KINDS or dt.fields is not None or dt.subdtype is not None or dt.hasobject:
        raise ProtocolError(f"dtype {raw!r} is refused: only bool, integer and float arrays are decoded")
    return dt


def unpack_array(obj):
    """msgpack ``object_hook``: the inverse of :func:`pack_array`, for numeric dtypes only.

    The declared shape must be at most :data:`MAX_ARRAY_DIMS` non-negative integers whose
    product times the item size is exactly the length of ``data``; the array is a view of
    those bytes (read-only), so decoding never allocates more than the message holds.

    Raises:
        ProtocolError: a dtype that is not bool, integer or float (:data:`NUMERIC_KINDS`), a
            malformed shape, or a shape whose size does not match the data's length.
    """
    if b"__ndarray__" in obj:
        dt = _numeric_dtype(obj.get(b"dtype"))
        shape, data = obj.get(b"shape"), obj.get(b"data")
        if (not isinstance(shape, list | tuple) or len(shape) > MAX_ARRAY_DIMS
                or not all(type(n) is int and n >= 0 for n in shape)):
            raise ProtocolError(f"array shape {str(shape)[:60]} is not a list of at most {MAX_ARRAY_DIMS} "
                                "non-negative integers")
        if not isinstance(data, bytes):
            raise ProtocolError("array data is not bytes")
        if math.prod(shape) * dt.itemsize != len(data):
            raise ProtocolError(f"array of shape {tuple(shape)} and dtype {dt.str} needs "
                                f"{math.prod(shape) * dt.itemsize} bytes; the message holds {len(data)}")
        return np.frombuffer(data, dtype=dt).reshape(shape)
    if b"__npgeneric__" in obj:
        dt = _numeric_dtype(obj.get(b"dtype"))
        item = obj.get(b"data")
        if type(item) not in (bool, int, float):
            raise ProtocolError(f"scalar of dtype {dt.str} holds a {type(item).__name__}, not a number")
        try:
            return dt.type(item)
        except (OverflowError, ValueError, TypeError):
            raise ProtocolError(f"scalar {str(item)[:40]} does not fit dtype {dt.str}") from None
    return obj


packb = functools.partial(msgpack.packb, default=pack_array)


def unpackb(data, max_bytes: int = MAX_MESSAGE_BYTES):
    """Decode one message (:func:`unpack_array` for arrays and scalars).

    Args:
        data: the message, bytes.
        max_bytes: refuse a longer message, bytes.

    Raises:
        ProtocolError: not bytes, longer than ``max_bytes``, not one msgpack document, or an
            array :func:`unpack_array` refuses.  msgpack itself bounds the lengths it reads by
            the message's length, so a short message cannot make it allocate much.
    """
    if not isinstance(data, bytes | bytearray | memoryview):
        raise ProtocolError(f"a message is {type(data).__name__}, not bytes")
    if len(data) > max_bytes:
        raise ProtocolError(f"a message of {len(data)} bytes is over the {max_bytes}-byte limit")
    try:
        return msgpack.unpackb(data, object_hook=unpack_array)
    except ProtocolError:
        raise
    except Exception as exc:  # noqa: BLE001 - msgpack's ExtraData, FormatError, StackError, UnicodeDecodeError...
        why = str(exc).splitlines()[0][:200] if str(exc) else ""
        raise ProtocolError(f"a message is not one msgpack document ({type(exc).__name__}"
                            + (f": {why})" if why else ")")) from None


def openpi_observation(obs: dict) -> dict:
    """The openpi observation map of an environment observation (keys present only)."""
    return {key: obs[ours] for key, ours in OBSERVATION_KEYS.items() if ours in obs}
