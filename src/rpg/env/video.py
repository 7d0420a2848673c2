"""MP4 videos of episodes, written with PyAV (it bundles FFmpeg; no system ffmpeg needed)."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

import numpy as np

VIDEO_CODEC = "libx264"
"""H.264 in yuv420p: what browsers, LeRobot and most players decode."""


class VideoWriter:
    """Frames (H, W, 3) uint8 RGB to an MP4 at ``fps``; the file appears only when closed
    without error (written to a temporary file in the same directory, then renamed).

    Raises:
        ValueError: a frame of another shape than the first, or an odd width or height
            (yuv420p needs even sides).
    """

    def __init__(self, path: str | Path, fps: float, options: dict[str, str] | None = None):
        self.path = Path(path)
        self.fps = fps
        self.options = dict(options or {})  # the encoder's (libx264's) options, e.g. {"g": "2"}
        self._container = None
        self._stream = None
        self._shape: tuple[int, ...] | None = None
        self.frames = 0
        fd, tmp = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".mp4", dir=self.path.parent or ".")
        os.close(fd)
        self._tmp = Path(tmp)

    def __enter__(self) -> VideoWriter:
        return self

    def write(self, frame: np.ndarray) -> None:
        import av

        frame = np.ascontiguousarray(frame, dtype=np.uint8)
        if self._container is None:
            h, w = frame.shape[:2]
            if frame.ndim != 3 or frame.shape[2] != 3 or h % 2 or w % 2:
                raise ValueError(f"video frames must be (H, W, 3) with even H and W, got {frame.shape}")
            self._shape = frame.shape
            self._container = av.open(str(self._tmp), mode="w", format="mp4")
            self._stream = self._container.add_stream(VIDEO_CODEC, rate=round(self.fps), options=self.options)
            self._stream.width, self._stream.height = w, h
            self._stream.pix_fmt = "yuv420p"
        elif frame.shape != self._shape:
            raise ValueError(f"frame shape {frame.shape} differs from the first frame's {self._shape}")
        for packet in self._stream.encode(av.VideoFrame.from_ndarray(frame, format="rgb24")):
            self._container.mux(packet)
        self.frames += 1

    def __exit__(self, exc_type, *exc) -> None:
        try:
            if self._container is not None:
                if exc_type is None:
                    for packet in self._stream.encode():
                        self._container.mux(packet)
                self._container.close()
            if exc_type is None and self.frames:
                umask = os.umask(0)
                os.umask(umask)
                os.chmod(self._tmp, 0o666 & ~umask)
                os.replace(self._tmp, self.path)
        finally:
            with contextlib.suppress(OSError):
                self._tmp.unlink()

