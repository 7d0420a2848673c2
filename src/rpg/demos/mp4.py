"""MP4 videos of demonstrations, with PyAV: an episode's frames encoded with a short keyframe
interval, episodes concatenated into one file without re-encoding (LeRobot v3.0's video
files), and frames read back by index or timestamp.

Encoding: H.264 (``libx264``), yuv420p, no B-frames, a keyframe at least every ``gop`` frames
(:data:`DEFAULT_GOP` = 2, LeRobot's own default ``g=2``).  libx264's default puts a single
keyframe at the start of an episode, so reading frame t decodes t frames; with ``gop`` = 2 a
reader seeks to a keyframe at most one frame before t, and the cost of a sample does not grow
with t.  Without B-frames every packet's decode order is its presentation order, so a file
can be cut after any packet and episodes can be joined packet by packet: each episode's
first frame is a keyframe (an IDR frame), and its timestamps are shifted by the duration of
the episodes before it in the file.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np

from rpg.env.video import VideoWriter

DEFAULT_GOP = 2
"""Frames between keyframes at most (LeRobot's ``g=2``)."""


def encoder_options(gop: int) -> dict[str, str]:
    """libx264 options of :class:`EpisodeVideo`: keyframe interval ``gop``, no B-frames, and one encoder thread, so that
    a dataset's bytes do not depend on how threads were scheduled (a Ray run under load had written 18 of 350 frames,
    in whole keyframe pairs, that decode up to 16 levels apart from the process pool's: the encoder's doing, not the
    renderer's, as far as the pairs show)."""
    if int(gop) < 1:
        raise ValueError(f"gop must be at least 1, not {gop}")
    return {"g": str(int(gop)), "bf": "0", "threads": "1"}


class EpisodeVideo(VideoWriter):
    """Frames (H, W, 3) uint8 RGB to an MP4 at ``fps`` with a keyframe at least every ``gop``
    frames and no B-frames (:func:`encoder_options`); the file appears only when closed
    without error, as :class:`rpg.env.video.VideoWriter`'s.

    Raises:
        ValueError: a frame of another shape than the first, an odd width or height, or
            ``gop`` < 1.
    """

    def __init__(self, path: str | Path, fps: float, gop: int = DEFAULT_GOP):
        super().__init__(path, fps, encoder_options(gop))


def _packets(container):
    stream = container.streams.video[0]
    for packet in container.demux(stream):
        if packet.dts is not None and packet.size:
            yield packet


def stream_signature(path: str | Path) -> tuple:
    """What must agree for two MP4s to be joined packet by packet: codec, size, pixel format,
    time base, frame rate and the decoder configuration (SPS/PPS)."""
    import av

    with av.open(str(path)) as c:
        s = c.streams.video[0]
        cc = s.codec_context
        return (cc.name, cc.width, cc.height, str(cc.pix_fmt), s.time_base, s.average_rate, bytes(cc.extradata or b""))


def join(parts: list[tuple[Path, int | None]], out: Path) -> int:
    """Write ``out``: the first ``n`` packets (frames) of each ``(path, n)`` in order (every
    packet when ``n`` is None), timestamps shifted so the frames follow each other at the
    files' frame rate.  No re-encoding; ``out`` is written in place (callers write a temporary
    name and rename it).

    Returns:
        The number of frames written.

    Raises:
        ValueError: the parts do not share :func:`stream_signature`, a part has B-frames
            (decode order differs from presentation order) or fewer packets than asked.
    """
    import av

    if not parts:
        raise ValueError("nothing to join")
    signature = stream_signature(parts[0][0])
    written = 0
    offset = 0  # in the output stream's time base
    with av.open(str(out), mode="w", format="mp4") as dst:
        ost = None
        for path, keep in parts:
            if stream_signature(path) != signature:
                raise ValueError(f"{path} was encoded differently from {parts[0][0]}; it cannot be joined to it")
            with av.open(str(path)) as src:
                ist = src.streams.video[0]
                if ost is None:
                    ost = dst.add_stream_from_template(ist)
                    ost.time_base = ist.time_base
                tick = int(round(1 / (float(ist.average_rate) * float(ist.time_base))))
                n = 0
                for packet in _packets(src):
                    if keep is not None and n >= keep:
                        break
                    if packet.pts != packet.dts or packet.pts != n * tick:
                        raise ValueError(f"{path}: packet {n} has pts {packet.pts}, dts {packet.dts}; expected "
                                         f"{n * tick} (a constant frame rate, no B-frames)")
                    packet.pts = packet.dts = offset + n * tick
                    packet.stream = ost
                    dst.mux(packet)
                    n += 1
                if keep is not None and n < keep:
                    raise ValueError(f"{path} holds {n} frames, fewer than the {keep} asked")
                offset += n * tick
                written += n
    return written


def frame_count(path: str | Path) -> int:
    """Frames (packets) of an MP4's video stream, counted without decoding."""
    import av

    with av.open(str(path)) as c:
        return sum(1 for _ in _packets(c))


def keyframes(path: str | Path) -> list[int]:
    """Indices of the keyframes of an MP4's video stream (in presentation order), without decoding."""
    import av

    with av.open(str(path)) as c:
        return [i for i, p in enumerate(_packets(c)) if p.is_keyframe]


def read_frames(path: str | Path) -> list[np.ndarray]:
    """Every frame of an MP4, (H, W, 3) uint8 RGB."""
    import av

    with av.open(str(path)) as c:
        return [f.to_ndarray(format="rgb24") for f in c.decode(video=0)]


def read_frame_at(path: str | Path, timestamp: float) -> tuple[np.ndarray, int]:
    """The frame shown at ``timestamp`` (s) as a reader that seeks does it: seek to the last
    keyframe at or before it, then decode forward.

    Returns:
        The frame (H, W, 3) uint8 RGB and the number of frames decoded to reach it.

    Raises:
        ValueError: no frame within half a frame of ``timestamp``.
    """
    import av

    with av.open(str(path)) as c:
        s = c.streams.video[0]
        half = Fraction(1, 2) / Fraction(s.average_rate)
        target = Fraction(timestamp).limit_denominator(10**6)
        c.seek(max(int(round(target / s.time_base)), 0), stream=s, backward=True, any_frame=False)
        decoded = 0
        for frame in c.decode(s):
            decoded += 1
            t = frame.pts * s.time_base
            if abs(t - target) <= half:
                return frame.to_ndarray(format="rgb24"), decoded
            if t > target:
                break
    raise ValueError(f"{path} has no frame at {timestamp} s")
