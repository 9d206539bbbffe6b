"""Output files: checked up front, written to a temporary file and renamed into place.

A failed or interrupted run never leaves a half-written file at the output path, and
a write that fails is a failure: no space, a read-only folder or an encoder error is
an :class:`~springscene.errors.OutputError` naming the output (exit status 1), with
the temporary file removed. Videos are streamed through ffmpeg (:mod:`springscene.video`).
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import tempfile
from pathlib import Path
from typing import Iterator

import numpy as np

from .errors import OutputError, UserError
from .video import (DEFAULT_QUALITY, VIDEO_SUFFIXES, WRITE_ERRNOS, count_frames, open_encoder,
                    reason_of)

VIDEO_FORMATS = VIDEO_SUFFIXES          # .mp4, .webm, .ogv, .gif


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
    check_writable_folder(parent, path, flag)
    if path.is_dir():
        raise UserError(f"{flag} {path}: is a directory")
    return path


def check_writable_folder(folder: Path, path: Path, flag: str = "--out") -> None:
    """That files can be made in ``folder`` (for ``path``): a read-only file system is a
    write that cannot succeed (an :class:`OutputError`, exit 1, as a full disk); a folder
    the user may not write to is bad input (a :class:`UserError`, exit 2)."""
    if not os.access(folder, os.W_OK | os.X_OK):
        if _read_only(folder):
            raise OutputError(reason_of(OSError(errno.EROFS, os.strerror(errno.EROFS))), path,
                              errno.EROFS)
        raise UserError(f"{flag} {path}: folder {folder} is not writable")


def _read_only(folder: Path) -> bool:
    try:
        return bool(os.statvfs(folder).f_flag & os.ST_RDONLY)
    except OSError:
        return False


GIF_MAX_FPS = 50   # GIF delays are whole centiseconds; browsers slow delays under 2 cs


def check_video_fps(path: Path, fps: int) -> None:
    if path.suffix.lower() == ".gif" and fps > GIF_MAX_FPS:
        raise UserError(f"--fps {fps}: a GIF plays at most {GIF_MAX_FPS} frames/s "
                        f"(its delays are whole centiseconds of at least 2)")


def gif_delays(n: int, fps: int) -> list[int]:
    """Per-frame delays in ms of an ``n``-frame GIF at ``fps``, as ffmpeg's GIF muxer
    writes them: whole centiseconds whose running sum stays on t = (f+1)/fps (rounded half
    up), the last frame shown for 1/fps rounded."""
    ends = (200 * np.arange(1, n + 1) + fps) // (2 * fps)
    delays = np.diff(ends, prepend=0)
    if n:
        delays[-1] = (200 + fps) // (2 * fps)
    return (10 * delays).tolist()


def hidden_name(path: Path) -> str:
    """The start of a hidden file's or folder's name beside ``path``: ``.NAME``, cut to
    leave room in a legal name for what follows (a run's folder, a recording on its way)."""
    name = Path(path).name
    while len(os.fsencode(name)) > 200:
        name = name[:-1]
    return "." + name


def remove_if_abandoned(folder: Path, pid: str) -> None:
    """Remove a private working folder whose maker, process ``pid`` (as its name gives
    it), is gone: killed outright (SIGKILL leaves no chance to clean up). A folder of this
    process's, of a live process, or not named with a pid is left alone."""
    if not pid.isdigit() or int(pid) == os.getpid():
        return
    try:
        os.kill(int(pid), 0)
    except ProcessLookupError:
        shutil.rmtree(folder, ignore_errors=True)
    except OSError:
        pass


@contextlib.contextmanager
def atomic_path(path: Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path`` (same suffix); on success flush it to the disk
    and rename it to ``path``. A failed write (no space, read-only, an encoder error) is an
    :class:`OutputError` naming ``path``; on any failure the temporary file is removed."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix,
                                   dir=path.parent or ".")
    except OSError as exc:
        if exc.errno in WRITE_ERRNOS:
            raise OutputError(reason_of(exc), path, exc.errno) from None
        raise UserError(f"--out {path}: cannot write there ({exc.strerror})") from None
    os.close(fd)
    tmp = Path(tmp)
    try:
        yield tmp
        _flush(tmp)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except OutputError as exc:          # named by the file the user asked for
        tmp.unlink(missing_ok=True)
        if str(exc.path) != str(tmp):       # another output's, written meanwhile
            raise
        raise exc.at(path) from None
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        if exc.errno in WRITE_ERRNOS:
            named = path if exc.filename in (None, str(tmp)) else exc.filename
            raise OutputError(reason_of(exc), named, exc.errno) from None
        raise
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def _flush(tmp: Path) -> None:
    """The file's data on the disk (a delayed write that fails fails here, not later)."""
    fd = os.open(tmp, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def write_png(path: Path, image: np.ndarray) -> None:
    """``image`` as a PNG at ``path`` (atomically). Encoded in memory, then written by a plain
    file: a write that fails (no space) fails once, here, with no encoder left holding the
    file to fail again when it is collected (imageio's ``PluginV3.__del__`` would print it)."""
    import imageio.v3 as iio  # noqa: PLC0415  heavy: imageio

    data = iio.imwrite("<bytes>", image, extension=".png")
    with atomic_path(path) as tmp:
        tmp.write_bytes(data)


class VideoWriter:
    """Streams RGB frames to a video through ffmpeg: MP4 (H.264), WebM (VP9), Ogg (Theora)
    or GIF (palette filters), chosen by ``path``'s suffix (:mod:`springscene.video`).

    ``size`` is the frames' (width, height); MP4, WebM and Ogg are padded to even sizes
    (:attr:`video_size`). ``quality`` is low, medium or high. At :meth:`close` the
    encoder's exit status is checked and the file decoded again to count its frames: a
    video that is not whole is an :class:`OutputError`. Use as a context manager around
    :func:`atomic_path`'s temporary file; an exception inside stops the encoder at once.
    """

    def __init__(self, path: Path, fps: int, size: tuple[int, int],
                 quality: str = DEFAULT_QUALITY) -> None:
        self.path, self.fps, self.size, self.quality = path, fps, size, quality
        self.frames = 0
        self._encoder = open_encoder(path, fps, size, quality)
        self.video_size = self._encoder.video_size

    def write(self, frame: np.ndarray) -> None:
        if frame.shape[:2] != (self.size[1], self.size[0]):
            raise ValueError(f"a frame of {frame.shape[1]} x {frame.shape[0]} px in a video of "
                             f"{self.size[0]} x {self.size[1]}")
        self._encoder.write(frame)
        self.frames += 1

    def close(self) -> None:
        """Finish the video and check it: the encoder's status, then its frames read back."""
        encoder, self._encoder = self._encoder, None
        if encoder is None:
            return
        try:
            encoder.finish()
        except BaseException:
            encoder.abort()
            raise
        found = count_frames(self.path)
        if found != self.frames:
            raise OutputError(f"the video has {found} of its {self.frames} frames", self.path)

    def abort(self) -> None:
        """Stop the encoder without finishing the file (it is left to the caller's
        :func:`atomic_path` to remove)."""
        encoder, self._encoder = self._encoder, None
        if encoder is not None:
            encoder.abort()

    def __enter__(self) -> "VideoWriter":
        return self

    def __exit__(self, exc_type, *exc) -> None:
        if exc_type is None:
            self.close()
        else:
            self.abort()
