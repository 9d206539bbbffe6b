"""GlowScript's own library, the one VPython 7.6.5 draws with, for the interactive page.

The page (:mod:`.interactive`) inlines ``glow.min.js`` (GlowScript: the canvas, the
objects, the WebGL renderer and the mouse's camera controls) with the jQuery and jQuery UI
it runs on, exactly the files the ``vpython`` 7.6.5 wheel ships in
``vpython/vpython_libraries/``, and the wheel's MIT licence. springscene does not depend on
the ``vpython`` package (it pulls in Jupyter); :func:`library` finds the files, in order:

1. an installed ``vpython`` package (found with :func:`importlib.util.find_spec`, which does
   not import it), when its files are 7.6.5's;
2. the cache: ``$SPRINGSCENE_GLOW_DIR``, else ``$XDG_CACHE_HOME/springscene/glowscript-7.6.5``
   (``~/.cache/...`` by default), holding the four files, or a ``vpython-7.6.5`` wheel
   they are taken from;
3. the wheel downloaded with ``python -m pip download vpython==7.6.5 --no-deps`` (the
   JavaScript is the same in every platform's wheel), its four files written into the cache.

Every file is checked against its pinned SHA-256. When none of these works (no network),
:class:`~springscene.errors.OutputError` says in one line what to do: the page is an
output that cannot be written, the program's run itself succeeded, so exit status 1, not
the bad-input status 2 of ``UserError``.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import importlib.metadata
import importlib.util
import os
import subprocess
import sys
import tempfile
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

from ...errors import OutputError

__all__ = ["GlowLibrary", "library", "cache_dir", "VERSION", "FILES"]

VERSION = "7.6.5"
# the files the page inlines, by name in the cache, with their SHA-256 in vpython 7.6.5
FILES = {
    "glow.min.js": "4da74fea5317d5dabc1320530e94a4b02006dc4164f731237f0809cf67e55805",
    "jquery.min.js": "5f1ab65fe2ad6b381a1ae036716475bf78c9b2e309528cf22170c1ddeefddcbf",
    "jquery-ui.custom.min.js":
        "d52a99908b8cd44dffa18ce0d8444eb22866c2561b52dca1810851d02f2aa957",
    "LICENSE.txt": "c98185cf6ee6c6a0004398c332a14f5e12e45d884fe1a1bfefa7bc5ea9911357",
}
_IN_WHEEL = {name: f"vpython/vpython_libraries/{name}" for name in FILES}
_IN_WHEEL["LICENSE.txt"] = f"vpython-{VERSION}.dist-info/LICENSE.txt"
_PIP_TIMEOUT_S = 300
RETRY_AFTER_S = 3600        # after a failed download, runs do not try again for this long

_JS = ("glow.min.js", "jquery.min.js", "jquery-ui.custom.min.js")
_found: dict[Path, GlowLibrary] = {}      # by cache folder: read once a process


@dataclass(frozen=True)
class GlowLibrary:
    """The library's files as text, and the folder they were read from."""

    folder: Path
    glow_js: str
    jquery_js: str
    jquery_ui_js: str
    license_text: str


def cache_dir() -> Path:
    """Where the library is kept: ``$SPRINGSCENE_GLOW_DIR``, else the user's cache."""
    if os.environ.get("SPRINGSCENE_GLOW_DIR"):
        return Path(os.environ["SPRINGSCENE_GLOW_DIR"]).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(base) / "springscene" / f"glowscript-{VERSION}"


def library(download: bool = True, retry: bool = False) -> GlowLibrary:
    """GlowScript's library: installed, cached, or downloaded into the cache (above).

    Parameters
    ----------
    download : bool
        Whether to download it when it is neither installed nor cached.
    retry : bool
        Download even when a download failed less than :data:`RETRY_AFTER_S` ago (without
        it, every run on a machine with no network would wait for pip to give up).

    Raises
    ------
    OutputError
        None of the ways gave the files; the message says what to do.
    """
    folder = cache_dir()
    if folder not in _found:
        found = _installed() or _cached()
        if found is None and not download:
            raise _missing(folder, "not downloaded here")
        if found is None and not retry and _failed_recently(folder):
            raise _missing(folder, "the last download failed less than an hour ago; "
                           "`python -m springscene.vpython.page.glow_library` tries again")
        _found[folder] = found or _download_noting_failure(folder)
    return _found[folder]


def _failure_mark(folder: Path) -> Path:
    return folder.parent / f".{folder.name}.download-failed"


def _failed_recently(folder: Path) -> bool:
    try:
        return time.time() - _failure_mark(folder).stat().st_mtime < RETRY_AFTER_S
    except OSError:
        return False


def _download_noting_failure(folder: Path) -> GlowLibrary:
    """:func:`_downloaded`; a failure is marked beside the cache (when it can be), so the
    runs of the next hour say so at once."""
    try:
        found = _downloaded()
    except OutputError:
        with contextlib.suppress(OSError):
            folder.parent.mkdir(parents=True, exist_ok=True)
            _failure_mark(folder).touch()
        raise
    _failure_mark(folder).unlink(missing_ok=True)
    return found


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _load(paths: dict[str, Path]) -> GlowLibrary | None:
    """The library from these files, or None if one is missing or is not 7.6.5's."""
    texts = {}
    for name, path in paths.items():
        try:
            data = path.read_bytes()
        except OSError:
            return None
        if _sha256(data) != FILES[name]:
            return None
        texts[name] = data.decode("utf-8")
    return GlowLibrary(paths["glow.min.js"].parent, texts["glow.min.js"],
                       texts["jquery.min.js"], texts["jquery-ui.custom.min.js"],
                       texts["LICENSE.txt"])


def _installed() -> GlowLibrary | None:
    """The files of an installed ``vpython`` package (not imported: it starts a server)."""
    try:
        spec = importlib.util.find_spec("vpython")
    except (ImportError, ValueError):     # a vpython module in sys.modules without a spec
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = Path(next(iter(spec.submodule_search_locations))) / "vpython_libraries"
    licence = _installed_licence()
    if licence is None:
        return None
    paths = {name: folder / name for name in _JS}
    return _load({**paths, "LICENSE.txt": licence})


def _installed_licence() -> Path | None:
    """The LICENSE.txt of the installed vpython distribution, if it is 7.6.5."""
    try:
        dist = importlib.metadata.distribution("vpython")
    except importlib.metadata.PackageNotFoundError:
        return None
    if dist.version != VERSION:
        return None
    for f in dist.files or ():
        if f.name == "LICENSE.txt":
            return Path(str(dist.locate_file(f)))
    return None


def _cached() -> GlowLibrary | None:
    """The files in the cache folder, or taken from a vpython 7.6.5 wheel put there."""
    folder = cache_dir()
    found = _load({name: folder / name for name in FILES})
    if found is not None:
        return found
    for wheel in sorted(folder.glob(f"vpython-{VERSION}-*.whl")):
        try:
            _unpack(wheel, folder)
        except (OSError, zipfile.BadZipFile, KeyError, ValueError):
            continue
        return _load({name: folder / name for name in FILES})
    return None


def _downloaded() -> GlowLibrary:
    """The wheel downloaded with pip, its files written into the cache."""
    folder = cache_dir()
    with tempfile.TemporaryDirectory(prefix="springscene-glow-") as tmp:
        cmd = [sys.executable, "-m", "pip", "download", f"vpython=={VERSION}", "--no-deps",
               "--only-binary=:all:", "--platform", "manylinux2014_x86_64",
               "--python-version", "3.11", "--quiet", "--disable-pip-version-check",
               "-d", tmp]
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=_PIP_TIMEOUT_S)
            why = _last_line(proc.stderr) if proc.returncode else ""
        except (OSError, subprocess.TimeoutExpired) as e:
            proc, why = None, str(e)
        wheels = sorted(Path(tmp).glob(f"vpython-{VERSION}-*.whl"))
        if proc is None or proc.returncode or not wheels:
            raise _missing(folder, why or "pip gave no wheel")
        try:
            _unpack(wheels[0], folder)
        except (zipfile.BadZipFile, KeyError, ValueError) as e:
            raise _missing(folder, f"the downloaded wheel is not vpython {VERSION}'s: {e}")
        except OSError as e:
            raise OutputError(f"cannot write GlowScript's library: {e.strerror or e}",
                              folder, e.errno or errno.EIO) from None
    found = _load({name: folder / name for name in FILES})
    if found is None:
        raise _missing(folder, "the files written do not read back")
    return found


def _last_line(text: str) -> str:
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    errors = [ln for ln in lines if ln.startswith("ERROR")]
    return (errors or lines or [""])[-1]


def _missing(folder: Path, why: str) -> OutputError:
    return OutputError(
        f"GlowScript's library (vpython {VERSION}'s glow.min.js) is not installed or "
        f"cached and could not be downloaded ({why}); run `make setup` with network, or "
        f"`pip download vpython=={VERSION} --no-deps --only-binary=:all: -d DIR` where "
        f"there is network and set SPRINGSCENE_GLOW_DIR=DIR (the wheel in it is enough)",
        folder, errno.ENETUNREACH)


def _unpack(wheel: Path, folder: Path) -> None:
    """Write the four files of ``wheel`` into ``folder``, checked, each put in place whole.

    Raises ValueError when a file is not 7.6.5's, KeyError when one is missing.
    """
    with zipfile.ZipFile(wheel) as z:
        data = {name: z.read(member) for name, member in _IN_WHEEL.items()}
    for name, blob in data.items():
        if _sha256(blob) != FILES[name]:
            raise ValueError(f"{name} differs from vpython {VERSION}'s")
    folder.mkdir(parents=True, exist_ok=True)
    for name, blob in data.items():
        fd, tmp = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=folder)
        try:
            with os.fdopen(fd, "wb") as f:
                f.write(blob)
            os.chmod(tmp, 0o644)
            os.replace(tmp, folder / name)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise


def main() -> int:
    """``python -m springscene.vpython.page.glow_library``: get the library into the cache
    now (``make setup`` does), say where it is, or say in one line why it cannot be had."""
    try:
        print(f"GlowScript's library (vpython {VERSION}): {library(retry=True).folder}")
    except OutputError as e:
        print(f"springscene: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
