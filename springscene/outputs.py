"""Output files: checked up front, written to a temporary file and renamed into place.

A failed or interrupted run never leaves a half-written file at the output path.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

import numpy as np

from .errors import UserError

VIDEO_FORMATS = (".mp4", ".gif")


NAME_MAX = 255       # bytes in a file name on Linux's file systems


def check_output(path: str | Path, formats: tuple[str, ...], flag: str = "--out") -> Path:
    """Return ``path`` if its suffix is one of ``formats`` and its folder is writable."""
    if not str(path).strip():
        raise UserError(f"{flag} is empty: give a file name ({', '.join(formats)})")
    path = Path(path)
    if path.suffix.lower() not in formats:
        raise UserError(f"{flag} {path}: unknown output format {path.suffix or '(none)'!r} "
                        f"(use {', '.join(formats)})")
    longest = NAME_MAX - 10 - len(path.suffix)      # the temporary ".NAME.XXXXXXXX.SUFFIX"
    if len(os.fsencode(path.name)) > longest:
        raise UserError(f"{flag} {path.name[:40]}...: the file name is "
                        f"{len(os.fsencode(path.name))} bytes; the limit is {longest}")
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise UserError(f"{flag} {path}: folder {parent} does not exist")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise UserError(f"{flag} {path}: folder {parent} is not writable")
    if path.is_dir():
        raise UserError(f"{flag} {path}: is a directory")
    return path


GIF_MAX_FPS = 50   # GIF delays are whole centiseconds; browsers slow delays under 2 cs


def check_video_fps(path: Path, fps: int) -> None:
    if path.suffix.lower() == ".gif" and fps > GIF_MAX_FPS:
        raise UserError(f"--fps {fps}: a GIF plays at most {GIF_MAX_FPS} frames/s "
                        f"(its delays are whole centiseconds of at least 2)")


def gif_delays(n: int, fps: int) -> list[int]:
    """Per-frame delays in ms, whole centiseconds, whose running sum stays on t = (f+1)/fps."""
    ends = np.rint(np.arange(1, n + 1) * 100 / fps).astype(int)
    return (10 * np.diff(ends, prepend=0)).tolist()


@contextlib.contextmanager
def atomic_path(path: Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path`` (same suffix); rename it to ``path`` on success."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix,
                                   dir=path.parent or ".")
    except OSError as exc:
        raise UserError(f"--out {path}: cannot write there ({exc.strerror})") from None
    os.close(fd)
    tmp = Path(tmp)
    try:
        yield tmp
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_png(path: Path, image: np.ndarray) -> None:
    import imageio.v3 as iio  # noqa: PLC0415  heavy: imageio

    with atomic_path(path) as tmp:
        iio.imwrite(tmp, image, extension=".png")


class VideoWriter:
    """Streams RGB frames to an MP4 (H.264 through imageio-ffmpeg) or a GIF (Pillow).

    The frame size is kept exactly (no padding to macro blocks). Use as a context
    manager around :func:`atomic_path`'s temporary file.
    """

    def __init__(self, path: Path, fps: int, size: tuple[int, int]) -> None:
        self.path, self.fps, self.size = path, fps, size
        self.frames = 0
        self._gif: list = []
        self._palette = None
        if path.suffix.lower() == ".mp4":
            import imageio_ffmpeg  # noqa: PLC0415  heavy: imageio

            w, h = size
            pix = "yuv420p" if w % 2 == 0 and h % 2 == 0 else "yuv444p"
            self._mp4 = imageio_ffmpeg.write_frames(
                str(path), size, fps=fps, codec="libx264", pix_fmt_out=pix, quality=None,
                macro_block_size=1, ffmpeg_log_level="error",
                output_params=["-preset", "veryfast", "-crf", "20"])
            self._mp4.send(None)
        else:
            self._mp4 = None

    def write(self, frame: np.ndarray) -> None:
        if frame.shape[:2] != (self.size[1], self.size[0]):
            raise ValueError(f"a frame of {frame.shape[1]} x {frame.shape[0]} px in a video of "
                             f"{self.size[0]} x {self.size[1]}")
        if self._mp4 is not None:
            self._mp4.send(np.ascontiguousarray(frame))
        else:
            from PIL import Image  # noqa: PLC0415  heavy: Pillow

            image = Image.fromarray(frame)
            if self._palette is None:   # one palette for the whole GIF: no colour flicker
                self._palette = image.quantize(256, method=Image.Quantize.FASTOCTREE)
            self._gif.append(image.quantize(palette=self._palette, dither=Image.Dither.NONE))
        self.frames += 1

    def close(self) -> None:
        if self._mp4 is not None:
            self._mp4.close()
            self._mp4 = None
        elif self._gif:
            first, rest = self._gif[0], self._gif[1:]
            first.save(self.path, format="GIF", save_all=True, append_images=rest,
                       duration=gif_delays(len(self._gif), self.fps), loop=0, optimize=False)
            self._gif = []

    def __enter__(self) -> "VideoWriter":
        return self

    def __exit__(self, exc_type, *exc) -> None:
        if exc_type is None:
            self.close()
        elif self._mp4 is not None:
            self._mp4.close()
