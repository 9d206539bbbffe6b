"""A run's child kept in its room: the interpreter started inside bubblewrap's namespaces.

:func:`command` gives the ``bwrap`` command line a supervised run (:mod:`.supervise`)
puts before its child interpreter. Inside, the program sees:

- read-only: this Python's installation (``sys.base_prefix``, ``sys.prefix``, the site
  folders), springscene's own package, ``/usr`` and the ``/lib*``, ``/bin`` links, the
  pieces of ``/etc`` the loader, fonts and ``alternatives`` need, GlowScript's library
  cache, the CPUs' description in ``/sys``; the program file and :attr:`Sandbox.readable`;
- writable: only the run's private output folder; a private ``/tmp`` holding a throwaway
  ``HOME`` and a ``/dev/shm``, both small (memory ``--max-memory`` does not see); its own
  ``/proc`` (the kernel's settings read-only) and a minimal, read-only ``/dev``; the rest
  of its root is read-only, and so are the folders leading to what it sees in ``/tmp``;
- nothing else: no capabilities, no network (``--unshare-all``), its own user and PID
  namespaces (when the sandbox's first process dies, every process inside dies with it;
  ``--die-with-parent`` ends it with springscene), a new session (no terminal to type
  into), a cleared environment but for the locale, springscene's and the renderer's
  variables (:func:`environment`).

A program's read or write outside fails as on any file missing or read-only: its own
``FileNotFoundError``, ``PermissionError`` or ``OSError`` naming the path.
"""

from __future__ import annotations

import functools
import os
import shutil
import site
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from ...errors import OutputError
from ..page import glow_library

PACKAGE = Path(__file__).resolve().parents[2]       # springscene's own package folder
HOME = "/tmp/home"                                  # the throwaway HOME, in the private /tmp
MPLCONFIGDIR = f"{HOME}/.config/matplotlib"
# what the loader, fonts, Debian's alternatives (libblas, ...) and Mesa need (not the
# machine's users)
ETC = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "alternatives", "fonts", "localtime",
       "mime.types", "drirc", "glvnd")
SYSTEM = ("/usr", "/lib", "/lib32", "/lib64", "/libx32", "/bin", "/sbin")
SHARED = ("/var/cache/fontconfig", "/sys/devices/system/cpu")
# the environment kept inside: the locale, and springscene's, VTK's, Mesa's, EGL's and
# the numeric libraries' own variables
KEPT = ("LANG", "LANGUAGE", "TZ", "PYTHONHASHSEED", "PYTHONIOENCODING", "PYTHONUTF8",
        "LP_NUM_THREADS", "GALLIUM_DRIVER", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS",
        "MKL_NUM_THREADS")
KEPT_PREFIXES = ("LC_", "SPRINGSCENE_", "VTK_", "MESA_", "LIBGL_", "EGL_", "__EGL_")
TRIAL_TIMEOUT = 30.0        # s: bwrap's trial run
TMP_SIZE = 256 << 20        # the private /tmp and /dev/shm: memory --max-memory does not see
SHM_SIZE = 64 << 20         # (/dev/shm: multiprocessing's semaphores)
# every namespace of its own (a user namespace too: no power over the host's objects, even
# for a root caller's program, which keeps uid 0 but no capability); ended with
# springscene; no terminal to type into
ISOLATION = ("--unshare-all", "--unshare-user", "--cap-drop", "ALL", "--die-with-parent",
             "--new-session")
# its own /proc, but the kernel's settings and sysrq read-only (uid 0 could write them),
# a minimal /dev, a private /tmp
SYSTEM_FILES = ("--proc", "/proc", "--ro-bind", "/proc/sys", "/proc/sys",
                "--ro-bind-try", "/proc/sysrq-trigger", "/proc/sysrq-trigger",
                "--dev", "/dev", "--size", str(TMP_SIZE), "--tmpfs", "/tmp")


@dataclass(frozen=True)
class Sandbox:
    """A run kept in its room. ``readable``: the files and folders the program may read
    besides what its interpreter and springscene need (its own folder, or only its file
    when the folder holds other people's files). The network is always off."""

    readable: tuple[str, ...] = ()


def bwrap() -> str | None:
    """bubblewrap's ``bwrap`` on the PATH, or None."""
    return shutil.which("bwrap")


@functools.cache
def unavailable() -> str | None:
    """None where a sandbox works here (bwrap found and a trial run of it succeeded; the
    answer kept for this process), else the reason, one line."""
    found = bwrap()
    if found is None:
        return "bwrap is not installed (Debian's bubblewrap)"
    trial = [found, *ISOLATION, "--ro-bind", "/", "/", *SYSTEM_FILES, "true"]
    try:
        done = subprocess.run(trial, stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=TRIAL_TIMEOUT)
    except (OSError, subprocess.TimeoutExpired) as exc:
        return f"bwrap does not run here ({exc})"
    if done.returncode != 0:
        said = (done.stderr.strip().splitlines() or [f"exit status {done.returncode}"])[-1]
        return f"bwrap cannot make its namespaces here ({said})"
    return None


def own_folder(program: str | Path) -> tuple[str, ...]:
    """What one program may read: its folder, unless that folder is shared (the root, a
    home folder or one holding homes, a temporary folder): then its file alone."""
    path = Path(program).resolve()
    folder = path.parent
    homes = {Path.home().resolve(), Path("/home"), Path("/root"), Path("/"), Path("/tmp"),
             Path("/var/tmp"), Path("/dev/shm"), Path(tempfile.gettempdir()).resolve()}
    if any(folder == home or home.is_relative_to(folder) for home in homes):
        return (str(path),)
    return (str(folder),)


def command(sandbox: Sandbox, program: str | Path, writable: Path) -> list[str]:
    """The ``bwrap`` command line that starts what follows it in the sandbox: the run of
    ``program`` writing into ``writable`` (the run's private folder) alone."""
    args = [bwrap() or "bwrap", *ISOLATION, "--clearenv", *SYSTEM_FILES,
            "--size", str(SHM_SIZE), "--tmpfs", "/dev/shm",
            "--dir", HOME]
    writable = os.path.abspath(writable)
    shown = [str(program), *sandbox.readable, writable]
    args += _closed_folders(shown)
    for path in SYSTEM:
        args += _bound(path)
    for name in ETC:
        args += _bound(f"/etc/{name}")
    for path in [*SHARED, *_python_folders(), str(PACKAGE)]:
        args += _bound(path)
    library = _glow_folder()
    if library is not None:
        args += _bound(str(library))
    for fonts in _font_lists():          # (else matplotlib makes its list anew: 0.5 s a run)
        args += ["--ro-bind", str(fonts), f"{MPLCONFIGDIR}/{fonts.name}"]
    for path in (str(program), *sandbox.readable):
        args += _bound(os.path.abspath(path))
    args += ["--bind", writable, writable]
    args += ["--remount-ro", "/", "--remount-ro", "/dev"]    # (their tmpfs, bwrap's own)
    for name, value in environment(library).items():
        args += ["--setenv", name, value]
    args += ["--chdir", _working_folder(sandbox, program, writable)]
    return args + ["--"]


def environment(library: Path | None = None) -> dict[str, str]:
    """The child's environment inside: a fixed ``PATH``, the throwaway ``HOME``, this
    springscene first on Python's path, GlowScript's library where it was found, and the
    locale's and renderers' variables this process has (:data:`KEPT`)."""
    env = {name: value for name, value in os.environ.items()
           if name in KEPT or name.startswith(KEPT_PREFIXES)}
    env.setdefault("LANG", "C.UTF-8")
    env.update(PATH=f"{sys.prefix}/bin:/usr/local/bin:/usr/bin:/bin", HOME=HOME,
               TMPDIR="/tmp", PYTHONPATH=str(PACKAGE.parent), PYTHONDONTWRITEBYTECODE="1",
               XDG_CACHE_HOME=f"{HOME}/.cache", MPLCONFIGDIR=MPLCONFIGDIR)
    if library is not None:
        env["SPRINGSCENE_GLOW_DIR"] = str(library)
    return env


def _bound(path: str) -> list[str]:
    """``path`` read-only at its own place: a link as the same link, a folder or file
    bound (the place it names, when its own path passes through a link); nothing for a
    path that is not there."""
    if os.path.islink(path) and os.path.dirname(path) == "/":
        return ["--symlink", os.readlink(path), path]
    if not os.path.exists(path):
        return []
    real = os.path.realpath(path)
    same = ["--ro-bind", real, real]
    return same if real == path else same + ["--ro-bind", real, path]


def _closed_folders(paths: list[str]) -> list[str]:
    """The folders that lead to ``paths`` inside the private ``/tmp``, made read-only
    (``0555``; the program runs without capabilities): the host's paths around what the
    program sees cannot be written even in its throwaway ``/tmp``. (Elsewhere they are in
    the sandbox's read-only root.)"""
    folders: set[str] = set()
    for path in paths:
        parent = os.path.dirname(os.path.abspath(path))
        while parent.startswith("/tmp/"):
            folders.add(parent)
            parent = os.path.dirname(parent)
    args: list[str] = []
    for folder in sorted(folders, key=lambda f: f.count("/")):
        args += ["--perms", "0555", "--dir", folder]
    return args


def _python_folders() -> list[str]:
    """This Python's installation and the site folders springscene imports from (not the
    working folder or a test's folders that ``sys.path`` may hold, nor the user's site)."""
    prefixes = {sys.base_prefix, sys.prefix, sys.exec_prefix, sys.base_exec_prefix}
    folders = set(prefixes) | set(site.getsitepackages())
    return sorted(f for f in folders if f and f != "/" and os.path.isabs(f))


def _glow_folder() -> Path | None:
    """GlowScript's library folder as this process finds it (downloaded here, outside,
    where it must be), or None when it cannot be had (the page then says so)."""
    try:
        return glow_library.library().folder
    except OutputError:
        return None


def _font_lists() -> list[Path]:
    """matplotlib's lists of the fonts found here (``fontlist-v*.json`` in its cache
    folder, as matplotlib finds it without importing it), read-only inside: the fonts they
    name are in this Python's and the system's folders, which the sandbox shows."""
    base = os.environ.get("MPLCONFIGDIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "matplotlib")
    return sorted(Path(base).glob("fontlist-v*.json"))


def _working_folder(sandbox: Sandbox, program: str | Path, writable: str) -> str:
    """The program's working folder inside: this process's, when the program may read it;
    else the program's own folder when readable; else the throwaway HOME."""
    here = os.getcwd()
    program_folder = os.path.dirname(os.path.abspath(program))
    readable = [os.path.abspath(p) for p in sandbox.readable if os.path.isdir(p)] + [writable]
    for folder in (here, program_folder):
        if any(folder == r or folder.startswith(r.rstrip("/") + "/") for r in readable):
            return folder
    return HOME


__all__ = ["Sandbox", "unavailable", "command", "environment", "own_folder", "bwrap"]
