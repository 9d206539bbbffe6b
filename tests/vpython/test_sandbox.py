"""A sandboxed run (issue 28): hostile programs kept in their room. Each runs as one student's
submission in a class folder beside the instructor's grading file and another student's
work, with a secret key in the instructor's home; what it reads or writes outside its own
folder and its output fails as on a missing or read-only file (its own error, exit 1),
nothing of the host is read or written, no network, nothing left running.

The sandbox needs bubblewrap (``make system-deps``): without it these tests skip, or fail
where ``SPRINGSCENE_REQUIRE_BACKENDS`` is set (CI). Every test here starts a supervised
run's interpreter: the slow tier (tests/conftest.py, rule 4)."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from springscene.errors import ProgramError, UserError
from springscene.vpython.run import sandbox as sandboxing
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.sandbox import Sandbox
from springscene.vpython.run.supervise import EXIT_MEMORY, EXIT_TIMEOUT, RunEnded, \
    run_supervised

pytestmark = pytest.mark.slow

TINY = "from vpython import *\nscene.width = 64\nscene.height = 48\nb = sphere()\n"
SECRETS = {"grading": "INSTRUCTOR-ANSWER-7f3a", "bob": "BOB-WORK-c41d", "ssh": "SSH-KEY-92be"}
# tried by each hostile program, each failure printed: the last one raised at the end
ATTEMPTS = """
import os, sys
refused = []
def attempt(what, action):
    try:
        got = action()
    except OSError as exc:
        print("refused", what, type(exc).__name__, flush=True)
        refused.append(exc)
    else:
        print("done", what, repr(got)[:200], flush=True)
"""


@pytest.fixture(autouse=True)
def needs_a_sandbox(request):
    """Skip (fail in CI) where bwrap is missing or cannot make its namespaces (but for the
    test of that case)."""
    if request.node.name == "test_where_no_sandbox_can_be_made_the_flag_says_why_in_one_line":
        return
    why = sandboxing.unavailable()
    if why is not None:
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"a sandbox is required here: {why}")
        pytest.skip(f"no sandbox here: {why}")


@pytest.fixture
def course(tmp_path, monkeypatch) -> dict[str, Path]:
    """A class: the instructor's tests, two students' folders, the output folder, and the
    instructor's HOME with an SSH key."""
    room = tmp_path / "course"
    (room / "alice").mkdir(parents=True)
    (room / "bob").mkdir()
    (room / "out").mkdir()
    (room / "grading.py").write_text(f"ANSWER = {SECRETS['grading']!r}\n")
    (room / "bob" / "spring.py").write_text(f"# {SECRETS['bob']}\n")
    home = tmp_path / "home"
    (home / ".ssh").mkdir(parents=True)
    (home / ".ssh" / "id_rsa").write_text(SECRETS["ssh"] + "\n")
    monkeypatch.setenv("HOME", str(home))
    return {"room": room, "alice": room / "alice", "out": room / "out", "home": home,
            "grading": room / "grading.py", "bob": room / "bob" / "spring.py",
            "key": home / ".ssh" / "id_rsa"}


def hostile(course, body: str, **kwargs):
    """Alice's program (``body`` after :data:`ATTEMPTS`) run in the sandbox that sees her
    folder alone: (the error raised, what was printed)."""
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + ATTEMPTS + textwrap.dedent(body)
                    + "\nif refused:\n    raise refused[-1]\n")
    with pytest.raises((ProgramError, RunEnded)) as raised:
        run_supervised(prog, course["out"] / "alice.png", RunOptions(),
                       sandbox=Sandbox((str(course["alice"]),)), **kwargs)
    return raised.value


def untouched(course, capfd, error) -> str:
    """What the run printed; no secret in it nor in the error, and no file written
    outside Alice's output (her folder as she left it, nothing in the output folder)."""
    out, err = capfd.readouterr()
    for secret in SECRETS.values():
        assert secret not in out + err + str(error)
    assert sorted(p.name for p in course["alice"].iterdir()) == ["prog.py"]
    assert list(course["out"].iterdir()) == []
    assert sorted(p.name for p in (course["home"] / ".ssh").iterdir()) == ["id_rsa"]
    return out


def last_line(error) -> str:
    return str(error).strip().splitlines()[-1]


def test_the_graders_tests_another_students_work_and_the_home_cannot_be_read(course, capfd):
    error = hostile(course, f"""
        attempt("grading", lambda: open({str(course['grading'])!r}).read())
        attempt("listing", lambda: sorted(os.listdir({str(course['room'])!r})))
        attempt("bob", lambda: open({str(course['bob'])!r}).read())
        attempt("key", lambda: open({str(course['key'])!r}).read())
        attempt("home key", lambda: open(os.path.expanduser("~/.ssh/id_rsa")).read())
        attempt("root", lambda: os.listdir("/root/.ssh"))
        attempt("tests", lambda: os.listdir({str(Path(__file__).parent)!r}))
    """)
    assert isinstance(error, ProgramError) and not isinstance(error, RunEnded)
    out = untouched(course, capfd, error)
    for what in ("grading", "bob", "key", "home key", "root", "tests"):
        assert f"refused {what} FileNotFoundError" in out
    # the class folder shows only the places of Alice's folder and of her output's
    assert "done listing ['alice', 'out']" in out
    assert last_line(error) == ("FileNotFoundError: [Errno 2] No such file or directory: "
                                f"'{Path(__file__).parent}'")


def test_writing_outside_the_output_is_refused_or_kept_private(course, capfd):
    host_tmp = Path("/tmp") / f"springscene-sandbox-{os.getpid()}.txt"
    error = hostile(course, f"""
        attempt("own folder", lambda: open({str(course['alice'] / 'evil.txt')!r}, "w").write("x"))
        attempt("output folder", lambda: open({str(course['out'] / 'evil.txt')!r}, "w").write("x"))
        attempt("host tmp", lambda: open({str(host_tmp)!r}, "w").write("x"))
        attempt("key folder", lambda: open({str(course['key'].parent / 'evil')!r}, "w").write("x"))
        attempt("kernel", lambda: open("/proc/sys/kernel/core_pattern", "w").write(
            open("/proc/sys/kernel/core_pattern").read()))      # (the same: harmless)
        attempt("grading", lambda: open({str(course['grading'])!r}, "a").write("x"))
    """)
    out = untouched(course, capfd, error)
    assert "refused own folder OSError" in out            # read-only: [Errno 30]
    # the folders leading to what it sees are read-only (in its /tmp here: the class is
    # in the host's /tmp; elsewhere they are in the sandbox's read-only root)
    assert "refused output folder PermissionError" in out
    assert "done host tmp" in out and not host_tmp.exists()     # its own /tmp, thrown away
    assert "refused key folder FileNotFoundError" in out
    assert "refused kernel OSError" in out                # read-only
    assert "refused grading PermissionError" in out
    assert course["grading"].read_text() == f"ANSWER = {SECRETS['grading']!r}\n"
    assert last_line(error) == ("PermissionError: [Errno 13] Permission denied: "
                                f"'{course['grading']}'")


def test_no_network_not_even_to_a_server_on_this_machine(course, capfd):
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    server.settimeout(0.2)
    port, came, stop = server.getsockname()[1], [], threading.Event()

    def serve():
        while not stop.is_set():
            try:
                came.append(server.accept())
            except OSError:
                pass

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        error = hostile(course, f"""
            import socket
            attempt("far", lambda: socket.create_connection(("192.0.2.1", 80), timeout=3))
            attempt("here", lambda: socket.create_connection(("127.0.0.1", {port}), timeout=3))
        """)
    finally:
        stop.set()
        thread.join()
        server.close()
    out = untouched(course, capfd, error)
    assert came == []
    assert "refused far OSError" in out                   # network unreachable
    assert last_line(error) == "ConnectionRefusedError: [Errno 111] Connection refused"


def _marked(marker: str) -> list[int]:
    """The processes of this machine whose command line holds ``marker``."""
    found = []
    for name in filter(str.isdigit, os.listdir("/proc")):
        try:
            if marker.encode() in Path(f"/proc/{name}/cmdline").read_bytes():
                found.append(int(name))
        except OSError:
            pass
    return found


def test_a_lingering_process_dies_with_the_run_and_writes_nothing(course, capfd):
    """A daemon (double fork, its own session) that would write into the run's output and
    a host folder after 2 s: gone with the run."""
    marker = f"lingering-{os.getpid()}-{time.time_ns()}"
    late = [str(course["out"] / "late.txt"), str(course["alice"] / "late.txt"),
            str(course["out"] / "alice.png")]
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + textwrap.dedent(f"""
        import os, sys
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                os.execv(sys.executable, [sys.executable, "-c",
                         "import sys, time; time.sleep(2); "
                         "[open(p, 'w').write('late') for p in sys.argv[1:-1]]",
                         *{late!r}, {marker!r}])
            os._exit(0)
        rate(50)
    """))
    run_supervised(prog, course["out"] / "alice.png", RunOptions(),
                   sandbox=Sandbox((str(course["alice"]),)))
    assert _marked(marker) == []
    time.sleep(2.5)
    assert sorted(p.name for p in course["out"].iterdir()) == ["alice.html", "alice.png"]
    assert sorted(p.name for p in course["alice"].iterdir()) == ["prog.py"]
    assert _marked(marker) == []
    capfd.readouterr()


def test_a_program_reads_its_own_data_and_texture_and_gives_its_video(course, monkeypatch):
    """Readable works: a data file and a texture in the program's folder; the video is the
    one a run without a sandbox gives."""
    monkeypatch.chdir(course["alice"])           # (for the run without a sandbox)
    alice = course["alice"]
    (alice / "start.txt").write_text("0.5 0 0\n")
    Image.fromarray(np.full((8, 8, 3), (0, 200, 0), np.uint8)).save(alice / "green.png")
    prog = alice / "prog.py"
    prog.write_text(textwrap.dedent("""
        from vpython import *
        scene.width, scene.height = 160, 120
        scene.range = 2
        x, y, z = map(float, open("start.txt").read().split())
        b = box(pos=vector(x, y, z), size=vector(1.5, 1.5, 1.5), texture="green.png")
        for i in range(25):
            rate(50)
            b.pos.x -= 0.02
    """))
    result = run_supervised(prog, course["out"] / "alice.mp4",
                            RunOptions(duration=0.5, fps=50, page=False),
                            sandbox=Sandbox((str(alice),)))
    assert result.frames == 25
    assert sorted(p.name for p in course["out"].iterdir()) == ["alice.mp4"]
    # the same bytes as the run without a sandbox
    run_supervised(prog, course["out"] / "plain.mp4", RunOptions(duration=0.5, page=False))
    assert (course["out"] / "alice.mp4").read_bytes() == \
        (course["out"] / "plain.mp4").read_bytes()
    still = course["out"] / "alice.png"
    run_supervised(prog, still, RunOptions(page=False), sandbox=Sandbox((str(alice),)))
    pixels = np.asarray(Image.open(still).convert("RGB")).astype(int)
    middle = pixels[pixels.shape[0] // 2, pixels.shape[1] // 2]
    assert middle[1] > 100 and middle[1] > 2 * max(middle[0], middle[2])   # the texture


def test_timeout_and_the_stall_diagnosis_reach_a_program_inside(course, capfd):
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + "rate(50)\nwhile True:\n    pass\n")
    start, said = time.monotonic(), []
    with pytest.raises(RunEnded) as ended:
        run_supervised(prog, course["out"] / "alice.mp4", RunOptions(), timeout=6,
                       stall_after=1, say=said.append,
                       sandbox=Sandbox((str(course["alice"]),)))
    assert ended.value.status == EXIT_TIMEOUT and "--timeout 6 s" in str(ended.value)
    assert time.monotonic() - start < 20
    assert any("no rate() or sleep() call in" in line and "of prog.py" in line
               for line in said), said
    assert _gone(str(prog), within=5)
    assert list(course["out"].iterdir()) == []
    capfd.readouterr()


@pytest.mark.parametrize("where", ["interpreter", "fork"])
def test_max_memory_stops_a_program_or_its_fork_inside(course, capfd, where):
    """The memory measured is the sandboxed interpreter's and its children's."""
    grow = "a = []\nwhile True:\n    a.append(bytearray(20 << 20))\n    time.sleep(0.01)\n"
    body = ("import os, time\n" + (grow if where == "interpreter" else
            "if os.fork() == 0:\n" + textwrap.indent(grow, "    ")
            + "time.sleep(60)\n"))
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + body)
    with pytest.raises(RunEnded) as ended:
        run_supervised(prog, course["out"] / "alice.png", RunOptions(), max_memory="700M",
                       timeout=60, sandbox=Sandbox((str(course["alice"]),)))
    assert ended.value.status == EXIT_MEMORY, str(ended.value)
    assert "over --max-memory 700M" in str(ended.value)
    assert list(course["out"].iterdir()) == []
    capfd.readouterr()


ENDINGS = [("import sys; sys.exit(3)", 3, "the program exited with status 3 (sys.exit)"),
           ("import os; os._exit(7)", 7, "ended with status 7 (os._exit?)"),
           ("import ctypes; ctypes.string_at(0)", 139, "killed by SIGSEGV (a crash")]


@pytest.mark.parametrize("end, status, said", ENDINGS, ids=["sys.exit", "os._exit", "segfault"])
def test_a_program_inside_ends_as_outside(course, capfd, end, status, said):
    """bwrap passes on the exit status, and an interpreter's death by a signal as 128 + n:
    the same line and status as without a sandbox."""
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + "rate(50)\n" + end + "\n")
    with pytest.raises(RunEnded) as ended:
        run_supervised(prog, course["out"] / "alice.mp4", RunOptions(),
                       sandbox=Sandbox((str(course["alice"]),)))
    assert ended.value.status == status and said in str(ended.value), str(ended.value)
    assert list(course["out"].iterdir()) == []
    capfd.readouterr()


def _default_signals() -> None:
    for signum in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(signum, signal.SIG_DFL)


def _gone(marker: str, within: float) -> bool:
    deadline = time.monotonic() + within
    while _marked(marker):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGKILL], ids=["ctrl-c", "sigkill"])
def test_ctrl_c_or_springscene_killed_ends_everything_inside(course, signum):
    """springscene's Ctrl-C kills the sandbox; killed outright, bubblewrap kills it and the
    janitor outside removes the run's folder. The program spins with a fork of its own."""
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + "import os\nos.fork()\nrate(50)\nwhile True:\n    pass\n")
    proc = subprocess.Popen([str(Path(sys.executable).parent / "springscene"), "vpython",
                             str(prog), "--out", str(course["out"] / "alice.mp4"),
                             "--sandbox"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, preexec_fn=_default_signals)
    deadline = time.monotonic() + 60
    while len(_marked(str(prog))) < 4:      # bwrap, its first process, the program, its fork
        assert time.monotonic() < deadline and proc.poll() is None
        time.sleep(0.05)
    time.sleep(1)
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=60)
    if signum == signal.SIGINT:
        assert proc.returncode == 130 and err.strip().splitlines()[-1].startswith(
            "springscene: interrupted")
    else:
        assert proc.returncode == -signal.SIGKILL
    assert _gone(str(prog), within=10)
    deadline = time.monotonic() + 10
    while list(course["out"].iterdir()) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert list(course["out"].iterdir()) == []


def test_the_command_line_flag_runs_the_program_in_its_folder(course, cli):
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY + f"print(open({str(course['grading'])!r}).read())\n")
    proc = cli("vpython", prog, "--out", course["out"] / "alice.png", "--sandbox")
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines()[-1] == (
        f"FileNotFoundError: [Errno 2] No such file or directory: '{course['grading']}'")
    assert SECRETS["grading"] not in proc.stdout + proc.stderr
    prog.write_text(TINY + "print(len(open('prog.py').readlines()))\n")
    proc = cli("vpython", prog, "--out", course["out"] / "alice.png", "--sandbox", check=True)
    assert proc.stdout.startswith("5\n")         # its working folder is its own


def test_the_command_lines_program_reads_its_folder_unless_the_folder_is_shared(tmp_path):
    own = tmp_path / "alice" / "prog.py"
    assert sandboxing.own_folder(own) == (str(tmp_path / "alice"),)
    for shared in (Path.home(), Path("/tmp"), Path("/")):
        assert sandboxing.own_folder(shared / "prog.py") == (str(shared / "prog.py"),)


def test_where_no_sandbox_can_be_made_the_flag_says_why_in_one_line(course, cli, monkeypatch,
                                                                     tmp_path):
    prog = course["alice"] / "prog.py"
    prog.write_text(TINY)
    sandboxing.unavailable.cache_clear()
    monkeypatch.setattr(sandboxing, "bwrap", lambda: None)
    try:
        proc = cli("vpython", prog, "--out", course["out"] / "alice.png", "--sandbox")
        assert proc.returncode == 2
        assert proc.stderr.strip().splitlines() == [
            "springscene: error: --sandbox: no sandbox here: bwrap is not installed "
            "(Debian's bubblewrap)"]
        # a bwrap that cannot make namespaces (a container's seccomp, say): its own words
        fake = tmp_path / "bwrap"
        fake.write_text("#!/bin/sh\necho 'bwrap: No permissions to create new namespace' >&2"
                        "\nexit 1\n")
        fake.chmod(0o755)
        monkeypatch.setattr(sandboxing, "bwrap", lambda: str(fake))
        sandboxing.unavailable.cache_clear()
        with pytest.raises(UserError, match=r"^--sandbox: no sandbox here: bwrap cannot make "
                           r"its namespaces here \(bwrap: No permissions to create new "
                           r"namespace\)$"):
            run_supervised(prog, course["out"] / "alice.png", sandbox=Sandbox())
        assert list(course["out"].iterdir()) == []
    finally:
        sandboxing.unavailable.cache_clear()


def test_a_program_named_by_a_relative_path_runs_in_the_sandbox(course, monkeypatch):
    """The child starts in the program's folder inside the sandbox, so the program it is
    given is the absolute path, whatever the working folder outside."""
    (course["alice"] / "prog.py").write_text(TINY)
    monkeypatch.chdir(course["room"])
    result = run_supervised(Path("alice") / "prog.py", Path("out") / "alice.png", RunOptions(),
                            sandbox=Sandbox(("alice",)))
    assert result.frames >= 1 and (course["out"] / "alice.png").is_file()
