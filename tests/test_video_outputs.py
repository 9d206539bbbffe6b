"""Video outputs (issue 15) and writes that fail (issue 16).

WebM (VP9) and Ogg (Theora) beside MP4 and GIF, all streamed through ffmpeg; a GIF
through ffmpeg's palette filters with its frame times kept; MP4, WebM and Ogg always
even-sized yuv420p; the -q/--quality presets; a warning when frames repeat; and a write
that fails (a full disk, a read-only folder, an encoder that fails or drops frames) is
one line, exit 1, and nothing left beside the output.
"""

from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from PIL import Image

from conftest import ROOT, WIKI, process_alive
from springscene import video
from springscene.model.timeline import frame_steps
from springscene.errors import OutputError
from springscene.outputs import VideoWriter, atomic_path, gif_delays, write_png
from springscene.render import repeated_frames


def moving_frames(n: int, w: int, h: int, detail: float = 0.0) -> np.ndarray:
    """``n`` frames: a shaded background, a red disc moving right, and (``detail``) a
    fixed speckle that costs bits, so encoders' quality settings show in the size."""
    y, x = np.mgrid[0:h, 0:w]
    base = np.empty((h, w, 3), np.float64)
    base[..., 0] = 200 + 40 * x / w
    base[..., 1] = 220 - 60 * y / h
    base[..., 2] = 235
    if detail:
        base += detail * np.random.default_rng(1).standard_normal((h, w, 1))
    out = np.empty((n, h, w, 3), np.uint8)
    r = min(w, h) / 5
    for f in range(n):
        frame = base.copy()
        cx, cy = w * (0.2 + 0.6 * f / max(n - 1, 1)), h / 2
        disc = (x - cx) ** 2 + (y - cy) ** 2 < r * r
        frame[disc] = (220, 30, 30)
        out[f] = np.clip(frame, 0, 255)
    return out


def write_video(path: Path, frames: np.ndarray, fps: int, quality: str = "medium") -> Path:
    with atomic_path(path) as tmp, \
            VideoWriter(tmp, fps, (frames.shape[2], frames.shape[1]), quality) as writer:
        for frame in frames:
            writer.write(frame)
    return path


def decode(path: Path) -> tuple[dict, np.ndarray]:
    reader = imageio_ffmpeg.read_frames(str(path))
    meta = next(reader)
    w, h = meta["size"]
    return meta, np.stack([np.frombuffer(f, np.uint8).reshape(h, w, 3) for f in reader])


# ---- formats ---------------------------------------------------------------------------

@pytest.mark.parametrize("suffix, codec", [(".webm", "vp9"), (".ogv", "theora"),
                                           (".mp4", "h264")])
def test_each_format_decodes_back_whole_and_yuv420p(tmp_path, suffix, codec):
    src = moving_frames(25, 160, 120)
    out = write_video(tmp_path / f"v{suffix}", src, 25)
    meta, frames = decode(out)
    assert meta["codec"].startswith(codec)
    assert meta["pix_fmt"].startswith("yuv420p")
    assert meta["size"] == (160, 120) and len(frames) == 25
    for f in (0, 12, 24):              # the picture itself: the disc where it was drawn
        assert np.abs(frames[f].astype(int) - src[f]).mean() < 4, f
    assert sorted(tmp_path.iterdir()) == [out]


def test_an_ogg_of_a_still_scene_is_whole(tmp_path):
    """Theora stores a frame that repeats the one before as an empty packet (played, never
    decoded: 1 frame decodes here); the read-back counts the 6 frames the video shows."""
    out = write_video(tmp_path / "still.ogv", np.full((6, 128, 160, 3), 200, np.uint8), 25)
    assert video.count_frames(out) == 6
    log = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-i", str(out), "-fps_mode",
                          "passthrough", "-f", "null", "-"], capture_output=True, text=True)
    assert "frame=    1 " in log.stderr.replace("\r", "\n")


def test_render_writes_webm_and_ogg_a_wiki_takes(tmp_path, cli):
    for suffix, codec in ((".webm", "vp9"), (".ogv", "theora")):
        out = tmp_path / f"oscillation{suffix}"
        proc = cli("render", WIKI, "--duration", 0.4, "--fps", 25, "--draft", "--quiet",
                       "-q", "low", "--out", out)
        assert proc.returncode == 0 and proc.stderr == "", proc.stderr
        meta, frames = decode(out)
        assert meta["codec"].startswith(codec) and meta["size"] == (900, 600)
        assert len(frames) == 10
        red = (frames[0][..., 0] > 150) & (frames[0][..., 1] < 80)      # the ball is there
        assert 2000 < red.sum() < 20000


def test_an_odd_size_is_padded_by_its_edge_to_even_yuv420p(tmp_path):
    src = moving_frames(10, 161, 121)
    out = write_video(tmp_path / "odd.mp4", src, 25)
    meta, frames = decode(out)
    assert meta["size"] == (162, 122) and meta["pix_fmt"].startswith("yuv420p")
    assert len(frames) == 10
    inner = frames[:, :121, :161].astype(int)
    assert np.abs(inner - src).mean() < 4
    # the extra column and row repeat the edge (the background), not black
    assert np.abs(frames[:, :121, 161].astype(int) - src[:, :, 160]).mean() < 6
    assert np.abs(frames[:, 121, :161].astype(int) - src[:, 120, :]).mean() < 6


def test_a_writer_keeps_the_frame_size_it_was_given(tmp_path):
    with atomic_path(tmp_path / "v.mp4") as tmp, VideoWriter(tmp, 25, (161, 121)) as writer:
        assert writer.size == (161, 121) and writer.video_size == (162, 122)
        with pytest.raises(ValueError, match="162 x 121"):
            writer.write(np.zeros((121, 162, 3), np.uint8))
        writer.write(np.zeros((121, 161, 3), np.uint8))


# ---- GIF -------------------------------------------------------------------------------

def test_a_gif_keeps_real_time_and_loops(tmp_path):
    src = moving_frames(45, 120, 90)
    out = write_video(tmp_path / "v.gif", src, 30)
    with Image.open(out) as im:
        assert im.n_frames == 45 and im.info.get("loop") == 0
        delays = []
        for f in range(im.n_frames):
            im.seek(f)
            delays.append(im.info["duration"])
            if f == 20:
                picture = np.asarray(im.convert("RGB")).astype(int)
    assert delays == gif_delays(45, 30)
    assert set(delays) == {30, 40}
    ends = np.cumsum(delays)[:-1]                  # each frame ends on t = (f + 1) / 30
    assert np.all(np.abs(ends - np.arange(1, 45) * 1000 / 30) <= 5)
    assert np.abs(picture - src[20]).mean() < 4     # one palette for all: colours kept


def test_a_gif_keeps_an_odd_size_exactly(tmp_path):
    src = moving_frames(5, 161, 121)
    out = write_video(tmp_path / "odd.gif", src, 25)
    with Image.open(out) as im:
        assert im.size == (161, 121) and im.n_frames == 5
        im.seek(4)
        assert np.abs(np.asarray(im.convert("RGB")).astype(int) - src[4]).mean() < 4


def test_gif_delays_model_ffmpeg_s_rounding():
    assert gif_delays(9, 40) == [30, 20, 30, 20, 30, 20, 30, 20, 30]
    assert gif_delays(12, 25) == [40] * 12
    assert sum(gif_delays(90, 30)) == 3000
    assert gif_delays(1, 30) == [30] and gif_delays(0, 30) == []


GIF_MEMORY_SCRIPT = textwrap.dedent("""
    import resource, sys
    import numpy as np
    from pathlib import Path
    from springscene.outputs import VideoWriter, atomic_path

    out = Path(sys.argv[1])
    y, x = np.mgrid[0:600, 0:900]
    base = np.stack([x * 255 // 900, y * 255 // 600, (x + y) % 256], axis=-1).astype(np.uint8)
    with atomic_path(out) as tmp, VideoWriter(tmp, 50, (900, 600)) as writer:
        for f in range(300):
            frame = base.copy()
            frame[200:400, 2 * f:2 * f + 200] = (200, 30, 30)
            writer.write(frame)
            if f == 10:
                early = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    late = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    ffmpeg = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    print(early // 1024, late // 1024, ffmpeg // 1024)
""")


def test_a_gif_is_streamed_not_held_in_memory(tmp_path):
    """300 frames of 900 x 600 (155 MB of pixels): this process grows by none of them,
    and no ffmpeg holds them either."""
    out = tmp_path / "long.gif"
    proc = subprocess.run([sys.executable, "-c", GIF_MEMORY_SCRIPT, str(out)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    early, late, ffmpeg = map(int, proc.stdout.split())
    assert late - early < 30, (early, late)          # MB
    assert ffmpeg < 200, ffmpeg
    assert video.count_frames(out) == 300
    assert sorted(tmp_path.iterdir()) == [out]


# ---- quality ---------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", [".mp4", ".webm", ".ogv", ".gif"])
def test_quality_presets_differ_in_size(tmp_path, suffix):
    src = moving_frames(12, 192, 144, detail=12)
    sizes = [write_video(tmp_path / f"{q}{suffix}", src, 25, q).stat().st_size
             for q in video.QUALITIES]
    assert sizes[0] < sizes[1] < sizes[2], sizes
    for q in video.QUALITIES:
        assert video.count_frames(tmp_path / f"{q}{suffix}") == 12


def test_a_bad_quality_is_refused(tmp_path, cli):
    proc = cli("render", WIKI, "-q", "ultra", "--out", tmp_path / "v.mp4")
    assert proc.returncode == 2 and "--quality" in proc.stderr and "ultra" in proc.stderr
    with pytest.raises(Exception, match="--quality 'ultra'"):
        video.open_encoder(tmp_path / "v.mp4", 25, (16, 16), "ultra")
    assert list(tmp_path.iterdir()) == []


# ---- frames that repeat ----------------------------------------------------------------

def test_fps_above_the_physics_rate_warns_on_one_line(tmp_path, cli):
    out = tmp_path / "v.mp4"
    proc = cli("render", WIKI, "--duration", 0.1, "--fps", 200, "--draft", "--quiet",
                   "--out", out)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("springscene: warning: --fps 200 ")
    assert "100 steps per video second" in lines[0] and "use --fps 100 or less" in lines[0]
    assert video.count_frames(out) == 20


def test_repeated_frames_are_counted():
    assert repeated_frames(frame_steps(1.0, 50, 0.01), 50, 0.01, 1.0) is None
    assert repeated_frames(frame_steps(1.0, 100, 0.01), 100, 0.01, 1.0) is None
    note = repeated_frames(frame_steps(1.0, 400, 0.01), 400, 0.01, 1.0)
    assert "299 of 400 frames repeat" in note       # steps 0 to 100: 101 distinct
    # slow motion: 0.25 simulated s per video second at 50 fps needs dt <= 5 ms
    assert "frames repeat" in repeated_frames(frame_steps(1.0, 50, 0.01, 0.25), 50, 0.01, 0.25)


# ---- writes that fail ------------------------------------------------------------------

def _mount(folder: Path, options: str):
    folder.mkdir()
    if os.geteuid() != 0:
        pytest.skip("mounting a small tmpfs needs root")
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(folder)],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {proc.stderr.strip()}")


@pytest.fixture
def full_disk(tmp_path):
    """A 64 kB file system with all but 4 kB taken by a file named ``filler``."""
    folder = tmp_path / "full"
    _mount(folder, "size=64k")
    try:
        st = os.statvfs(folder)
        (folder / "filler").write_bytes(b"\0" * (st.f_bavail * st.f_frsize - 4096))
        yield folder
    finally:
        subprocess.run(["umount", str(folder)], check=False)


@pytest.fixture
def read_only(tmp_path):
    folder = tmp_path / "ro"
    _mount(folder, "ro,size=64k")
    try:
        yield folder
    finally:
        subprocess.run(["umount", str(folder)], check=False)


@pytest.mark.parametrize("command, name", [
    (["render", "--duration", 0.3, "--draft", "--quiet"], "out.mp4"),
    (["render", "--duration", 0.3, "--fps", 25, "--draft", "--quiet"], "out.gif"),
    (["still", "--draft"], "out.png"),
    (["simulate", "--duration", 5], "out.csv"),
])
def test_a_full_disk_is_one_line_exit_1_and_nothing_left(full_disk, cli, command, name):
    out = full_disk / name
    proc = cli(command[0], WIKI, *command[1:], "--out", out)
    assert proc.returncode == 1, proc.stderr
    assert proc.stderr.splitlines() == [f"springscene: no space left on device writing {out}"]
    assert proc.stdout == ""
    assert sorted(p.name for p in full_disk.iterdir()) == ["filler"]


def test_a_read_only_folder_is_one_line_exit_1(read_only, cli):
    out = read_only / "out.webm"
    proc = cli("render", WIKI, "--duration", 0.2, "--draft", "--quiet", "--out", out)
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [f"springscene: read-only file system writing {out}"]
    assert list(read_only.iterdir()) == []


@pytest.mark.parametrize("code, reason", [(errno.ENOSPC, "no space left on device"),
                                          (errno.EROFS, "read-only file system"),
                                          (errno.EDQUOT, "disk quota exceeded")])
def test_a_write_that_fails_names_the_output_not_its_temporary(tmp_path, monkeypatch, code,
                                                               reason):
    """Without a file system to fill: a PNG write that fails as a full disk does (the PNG
    is encoded in memory, then written)."""
    write = Path.write_bytes

    def failing(self, data):
        write(self, data[:10])
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(Path, "write_bytes", failing)
    out = tmp_path / "frame.png"
    with pytest.raises(OutputError) as caught:
        write_png(out, np.zeros((4, 4, 3), np.uint8))
    assert str(caught.value) == f"{reason} writing {out}"
    assert caught.value.errno == code and caught.value.filename == str(out)
    assert list(tmp_path.iterdir()) == []


def test_a_failed_write_inside_another_names_its_own_file(tmp_path, monkeypatch):
    """A program's scene.capture PNG fails while its video is being written: the message
    names the PNG, not the video."""
    def failing(self, data):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(self))

    monkeypatch.setattr(Path, "write_bytes", failing)
    video_out, capture = tmp_path / "run.mp4", tmp_path / "capture.png"
    with pytest.raises(OutputError) as caught:
        with atomic_path(video_out):
            write_png(capture, np.zeros((4, 4, 3), np.uint8))
    assert str(caught.value) == f"no space left on device writing {capture}"
    assert list(tmp_path.iterdir()) == []


def test_an_unrelated_os_error_is_not_called_a_failed_write(tmp_path):
    with pytest.raises(FileNotFoundError):
        with atomic_path(tmp_path / "a.csv"):
            open(tmp_path / "no such file")
    assert list(tmp_path.iterdir()) == []


def test_an_encoder_that_fails_is_a_failure(tmp_path, monkeypatch):
    bad = {**video.ENCODINGS[".mp4"], "medium": ["-c:v", "libx264", "-crf", "nonsense"]}
    monkeypatch.setitem(video.ENCODINGS, ".mp4", bad)
    out = tmp_path / "v.mp4"
    with pytest.raises(OutputError) as caught:
        write_video(out, moving_frames(5, 64, 48), 25)
    message = str(caught.value)
    assert message.startswith("the encoder failed (ffmpeg exit status ")
    assert message.endswith(f" writing {out}") and "\n" not in message
    assert list(tmp_path.iterdir()) == []


def test_an_encoder_that_drops_frames_is_caught_by_the_read_back(tmp_path, monkeypatch):
    """ffmpeg exits 0 but wrote only 3 of the 10 frames: the count read back says so."""
    dropping = {**video.ENCODINGS[".webm"],
                "medium": [*video.ENCODINGS[".webm"]["low"], "-vf", r"select=lt(n\,3)"]}
    monkeypatch.setitem(video.ENCODINGS, ".webm", dropping)
    out = tmp_path / "v.webm"
    with pytest.raises(OutputError, match=f"the video has 3 of its 10 frames writing {out}"):
        write_video(out, moving_frames(10, 64, 48), 25)
    assert list(tmp_path.iterdir()) == []


def test_an_interrupted_gif_leaves_nothing(tmp_path):
    out = tmp_path / "v.gif"
    with pytest.raises(KeyboardInterrupt):
        with atomic_path(out) as tmp, VideoWriter(tmp, 25, (64, 48)) as writer:
            for f, frame in enumerate(moving_frames(10, 64, 48)):
                writer.write(frame)
                if f == 5:
                    assert len(list(tmp_path.iterdir())) == 2     # the file, the GIF's frames
                    raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []


KILLED_SCRIPT = textwrap.dedent("""
    import subprocess, sys, time
    import numpy as np
    from pathlib import Path
    from springscene import video
    from springscene.outputs import VideoWriter

    if sys.argv[2] == "unguarded":
        video._death_signal = lambda: None
    writer = VideoWriter(Path(sys.argv[1]), 25, (64, 48))
    writer.write(np.zeros((48, 64, 3), np.uint8))
    pipe = writer._encoder._pipe._proc.stdin.fileno()
    # a process that holds ffmpeg's input open: no end of input tells ffmpeg to stop
    holder = subprocess.Popen(["sleep", "60"], pass_fds=(pipe,))
    print(writer._encoder._pipe._proc.pid, holder.pid, flush=True)
    time.sleep(60)
""")


def _ffmpeg_outlives_a_killed_springscene(tmp_path, mode: str) -> bool:
    proc = subprocess.Popen([sys.executable, "-c", KILLED_SCRIPT, str(tmp_path / "v.mp4"),
                             mode], cwd=ROOT, stdout=subprocess.PIPE, text=True)
    ffmpeg, holder = map(int, proc.stdout.readline().split())
    try:
        assert process_alive(ffmpeg)
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        for _ in range(40):
            if not process_alive(ffmpeg):
                return False
            time.sleep(0.05)
        return True
    finally:
        for pid in (holder, ffmpeg):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def test_an_encoder_dies_with_a_killed_springscene(tmp_path):
    """SIGKILL (or the OOM killer) gives springscene no chance to stop its ffmpeg: the
    kernel does (without that, an ffmpeg whose input is held open runs on)."""
    assert not _ffmpeg_outlives_a_killed_springscene(tmp_path, "guarded")
    assert _ffmpeg_outlives_a_killed_springscene(tmp_path, "unguarded")
