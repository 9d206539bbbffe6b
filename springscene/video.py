"""Video files streamed through ffmpeg: MP4 (H.264), WebM (VP9), Ogg (Theora) and GIF.

Every format goes through the ffmpeg that imageio-ffmpeg bundles, fed raw RGB frames on
a pipe as they are drawn, so no video is ever held in memory. A GIF takes two passes
with ffmpeg's palette filters: while the frames stream in, one ffmpeg writes them to a
lossless H.264 intermediate in a private hidden folder beside the output and builds
the palette of the whole video (``palettegen``); at the end a second maps the
intermediate onto it (``paletteuse``). MP4, WebM and Ogg are yuv420p, the pixel format
every browser and phone plays, so a frame of odd width or height is padded by one pixel
repeating its edge (the scene's background).

A write that fails is a failure (:class:`springscene.errors.OutputError`): the
encoder's exit status is checked when it closes, and the finished file is decoded
again and its frames counted before it is accepted.
"""

from __future__ import annotations

import ctypes
import errno
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import weakref
from pathlib import Path

import numpy as np

from .errors import OutputError, UserError

QUALITIES = ("low", "medium", "high")
DEFAULT_QUALITY = "medium"

# ffmpeg's output options per format and quality (-q/--quality), in the spirit of
# Manim's presets: low is quick to encode and small, high is near transparent
_YUV = ["-pix_fmt", "yuv420p"]
ENCODINGS: dict[str, dict[str, list[str]]] = {
    ".mp4": {q: ["-c:v", "libx264", *_YUV, "-preset", preset, "-crf", crf,
                 "-movflags", "+faststart"]
             for q, preset, crf in (("low", "veryfast", "28"), ("medium", "veryfast", "20"),
                                    ("high", "slow", "15"))},
    ".webm": {q: ["-c:v", "libvpx-vp9", *_YUV, "-b:v", "0", "-crf", crf, "-deadline", deadline,
                  "-cpu-used", cpu, "-row-mt", "1"]
              for q, crf, deadline, cpu in (("low", "40", "realtime", "8"),
                                            ("medium", "32", "good", "5"),
                                            ("high", "24", "good", "2"))},
    ".ogv": {q: ["-c:v", "libtheora", *_YUV, "-q:v", qv]
             for q, qv in (("low", "4"), ("medium", "7"), ("high", "9"))},
}
# GIF: palettegen's colours and paletteuse's dithering
GIF_PALETTES = {"low": (64, "none"), "medium": (256, "none"), "high": (256, "sierra2_4a")}
# the GIF's lossless intermediate (x264's RGB lossless mode: fast and about 25 kB a frame)
_INTERMEDIATE = ["-c:v", "libx264rgb", "-qp", "0", "-preset", "ultrafast"]
VIDEO_SUFFIXES = (".mp4", ".webm", ".ogv", ".gif")

# an OSError with one of these while an output is written is that write failing; ffmpeg
# names them in strerror's words
WRITE_ERRNOS = (errno.ENOSPC, errno.EDQUOT, errno.EROFS, errno.EFBIG, errno.EIO)


def check_quality(quality: str) -> str:
    if quality not in QUALITIES:
        raise UserError(f"--quality {quality!r}: choose {', '.join(QUALITIES)}")
    return quality


def reason_of(exc: OSError) -> str:
    """An OSError's reason as the message says it: "no space left on device"."""
    text = exc.strerror or os.strerror(exc.errno or errno.EIO)
    return text[:1].lower() + text[1:]


def _failure(log: str, returncode: int, what: str, path: Path) -> OutputError:
    """What went wrong, from ffmpeg's log: a disk error in its own words, else the
    encoder's last line."""
    for code in WRITE_ERRNOS:
        if os.strerror(code) in log:
            return OutputError(reason_of(OSError(code, os.strerror(code))), path, code)
    lines = [line.strip() for line in log.splitlines() if line.strip()]
    last = lines[-1][:200] if lines else "no message"
    return OutputError(f"{what} failed (ffmpeg exit status {returncode}: {last})", path)


def ffmpeg_exe() -> str:
    import imageio_ffmpeg  # noqa: PLC0415  heavy: imageio_ffmpeg

    return imageio_ffmpeg.get_ffmpeg_exe()


def run_ffmpeg(args: list[str], path: Path, what: str = "the encoder") -> None:
    """Run ffmpeg to the end; a non-zero exit is an :class:`OutputError` on ``path``."""
    with tempfile.TemporaryFile() as log:
        proc = subprocess.run([ffmpeg_exe(), "-hide_banner", "-nostdin", "-y", "-loglevel",
                               "error", *args], stdin=subprocess.DEVNULL,
                              stdout=subprocess.DEVNULL, stderr=log, start_new_session=True,
                              preexec_fn=_death_signal())
        if proc.returncode != 0:
            log.seek(0)
            raise _failure(log.read().decode(errors="replace"), proc.returncode, what, path)


_PRCTL = []           # libc's prctl, looked up once in this process (never after a fork)


def _death_signal():
    """What ffmpeg's process runs before ffmpeg starts: on Linux it asks to be killed when
    springscene dies, so a springscene killed outright (SIGKILL, the OOM killer) leaves no
    encoder running. None elsewhere."""
    if sys.platform != "linux":
        return None
    if not _PRCTL:
        _PRCTL.append(ctypes.CDLL(None, use_errno=True).prctl)
    prctl = _PRCTL[0]
    return lambda: prctl(1, signal.SIGKILL)                  # PR_SET_PDEATHSIG


_PIPES: "weakref.WeakSet[FfmpegPipe]" = weakref.WeakSet()   # the pipes made in this process


def pipe_fds() -> list[int]:
    """The file descriptors of the encoders' open stdin pipes: what a fork of a VPython
    program must let go of, or ffmpeg would wait for its input's end (``vpython.lineage``)."""
    return [p._proc.stdin.fileno() for p in list(_PIPES)
            if p._proc.stdin is not None and not p._proc.stdin.closed]


class FfmpegPipe:
    """One ffmpeg process reading raw RGB frames of ``size`` on its stdin.

    Its log goes to a temporary file (a pipe could fill and stall it); it runs in its own
    session, so a Ctrl-C at the terminal reaches springscene alone, which stops it; and
    it dies with springscene (on Linux, with the thread that started it: start a writer
    in a thread that outlives it).
    """

    def __init__(self, size: tuple[int, int], fps: int, outputs: list[str], path: Path) -> None:
        w, h = size
        self.path = path
        self._log = tempfile.TemporaryFile()
        cmd = [ffmpeg_exe(), "-hide_banner", "-y", "-loglevel", "error",
               "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}", "-framerate", str(fps),
               "-i", "pipe:0", *outputs]
        self._proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                      stderr=self._log, start_new_session=True,
                                      preexec_fn=_death_signal())
        _PIPES.add(self)

    def send(self, frame: np.ndarray) -> None:
        try:
            self._proc.stdin.write(memoryview(np.ascontiguousarray(frame)).cast("B"))
        except (BrokenPipeError, OSError):      # ffmpeg stopped: say why
            self.finish()
            raise OutputError("the encoder stopped early", self.path) from None

    def finish(self, what: str = "the encoder") -> None:
        """Close the pipe, wait for ffmpeg, and raise if it failed."""
        proc = self._proc
        try:
            proc.stdin.close()
        except OSError:
            pass
        returncode = proc.wait()
        self._log.seek(0)
        log = self._log.read().decode(errors="replace")
        self._log.close()
        if returncode != 0:
            raise _failure(log, returncode, what, self.path)

    def kill(self) -> None:
        if self._proc.poll() is None:
            self._proc.kill()
        self._proc.wait()
        for stream in (self._proc.stdin, self._log):
            try:
                stream.close()
            except OSError:
                pass


def count_frames(path: Path) -> int:
    """The frames of a video file, which must decode without error (an
    :class:`OutputError` otherwise).

    The frames decoded are counted, but in an Ogg its packets: Theora stores a frame that
    repeats the one before as an empty packet, shown by players but never decoded.
    """
    decoded = _count(path, [])
    return _count(path, ["-c", "copy"]) if path.suffix.lower() == ".ogv" else decoded


def _count(path: Path, options: list[str]) -> int:
    with tempfile.TemporaryFile() as log:
        proc = subprocess.run([ffmpeg_exe(), "-hide_banner", "-nostdin", "-nostats",
                               "-loglevel", "error", "-xerror", "-i", str(path), "-map", "0:v:0",
                               *options, "-fps_mode", "passthrough", "-f", "null",
                               "-progress", "pipe:1", "-"],
                              stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=log,
                              start_new_session=True, preexec_fn=_death_signal())
        log.seek(0)
        errors = log.read().decode(errors="replace")
    counts = [line.split("=", 1)[1] for line in proc.stdout.decode().splitlines()
              if line.startswith("frame=")]
    if proc.returncode != 0 or not counts:
        raise _failure(errors, proc.returncode, "reading the video back", path)
    return int(counts[-1])


def even(size: tuple[int, int]) -> tuple[int, int]:
    """``size`` rounded up to even width and height (yuv420p halves the colour planes)."""
    return size[0] + size[0] % 2, size[1] + size[1] % 2


def pad_even(frame: np.ndarray) -> np.ndarray:
    """``frame`` with its last column and row repeated where its size is odd."""
    h, w = frame.shape[:2]
    if w % 2 == 0 and h % 2 == 0:
        return frame
    return np.pad(frame, ((0, h % 2), (0, w % 2), (0, 0)), mode="edge")


class StreamEncoder:
    """MP4, WebM or Ogg: one ffmpeg encoding frames as they come."""

    def __init__(self, path: Path, fps: int, size: tuple[int, int], quality: str) -> None:
        self.path = path
        self.video_size = even(size)
        options = ENCODINGS[path.suffix.lower()][quality]
        self._pipe = FfmpegPipe(self.video_size, fps, [*options, str(path)], path)

    def write(self, frame: np.ndarray) -> None:
        self._pipe.send(pad_even(frame))

    def finish(self) -> None:
        self._pipe.finish()

    def abort(self) -> None:
        self._pipe.kill()


class GifEncoder:
    """A GIF in two passes through ffmpeg's palette filters (one palette for the whole
    video: no colour flicker), with no frame held in memory.

    Pass one streams the frames to a lossless intermediate in a private hidden folder
    beside ``path`` (about 25 kB a frame; inside a supervised run's or a figure set's
    private folder when ``path`` is) and builds the palette as they pass; pass two maps
    the intermediate onto the palette.
    Frame f ends at t = (f + 1) / fps rounded to whole centiseconds (ffmpeg's GIF muxer
    rounds each frame's time stamp; :func:`springscene.outputs.gif_delays`).
    """

    def __init__(self, path: Path, fps: int, size: tuple[int, int], quality: str) -> None:
        self.path, self.video_size = path, size
        self.colors, self.dither = GIF_PALETTES[quality]
        try:
            self.folder = Path(tempfile.mkdtemp(prefix=f".{path.name}.", suffix=".frames",
                                                dir=path.parent))
        except OSError as exc:
            raise OutputError(reason_of(exc), path, exc.errno) from None
        self.frames_file = self.folder / "frames.nut"
        self.palette = self.folder / "palette.png"
        graph = f"[0:v]split[a][b];[b]palettegen=max_colors={self.colors}[p]"
        try:
            self._pipe = FfmpegPipe(size, fps, [
                "-filter_complex", graph, "-map", "[a]", *_INTERMEDIATE, str(self.frames_file),
                "-map", "[p]", "-update", "1", "-frames:v", "1", str(self.palette)], path)
        except BaseException:
            shutil.rmtree(self.folder, ignore_errors=True)
            raise

    def write(self, frame: np.ndarray) -> None:
        self._pipe.send(frame)

    def finish(self) -> None:
        try:
            self._pipe.finish("the GIF's first pass")
            mapping = f"[0:v][1:v]paletteuse=dither={self.dither}:diff_mode=rectangle"
            run_ffmpeg(["-i", str(self.frames_file), "-i", str(self.palette), "-lavfi", mapping,
                        "-f", "gif", str(self.path)], self.path, "the GIF's palette pass")
        finally:
            shutil.rmtree(self.folder, ignore_errors=True)

    def abort(self) -> None:
        self._pipe.kill()
        shutil.rmtree(self.folder, ignore_errors=True)


def open_encoder(path: Path, fps: int, size: tuple[int, int], quality: str = DEFAULT_QUALITY):
    """The encoder of ``path``'s format (its suffix), started."""
    check_quality(quality)
    suffix = path.suffix.lower()
    if suffix == ".gif":
        return GifEncoder(path, fps, size, quality)
    if suffix in ENCODINGS:
        return StreamEncoder(path, fps, size, quality)
    raise UserError(f"{path}: no video format {suffix!r} (use {', '.join(VIDEO_SUFFIXES)})")
