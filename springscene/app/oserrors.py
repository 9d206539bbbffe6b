"""An ``OSError`` from any command (no space left, a read-only folder, no permission) as
one line naming the file the user asked for, never its hidden temporary.

``springscene: no space left on device writing renders/wiki/energy.png`` (exit 1).
"""

from __future__ import annotations

import errno
import os
import re
from pathlib import Path

EXIT_WRITE_FAILED = 1

# failures that only a write meets
_WRITE_ERRNOS = {errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EROFS, errno.EIO}

# an ``outputs.atomic_path`` temporary: ".NAME.XXXXXXXX.SUFFIX" (tempfile's 8 characters)
_TEMPORARY = re.compile(r"\.(?P<name>.+)\.[a-z0-9_]{8}(?P<suffix>\.[^.]*)?")
STAGING_PREFIX = ".springscene-"    # a private folder a set is staged in (figures)


def user_path(path: str | os.PathLike) -> str:
    """``path`` as the user named it: a staging folder left out, a temporary file's
    hidden name turned back into the name it is moved to."""
    parts = [p for p in Path(path).parts if not p.startswith(STAGING_PREFIX)]
    if parts:
        found = _TEMPORARY.fullmatch(parts[-1])
        if found and found["name"].endswith(found["suffix"] or ""):
            parts[-1] = found["name"]
    return str(Path(*parts)) if parts else str(path)


def line(exc: OSError, out: str | os.PathLike | None = None) -> str:
    """The failure on one line: what happened and to which file (``out``, the command's
    ``--out``, when the error names none)."""
    reason = (exc.strerror or str(exc) or type(exc).__name__).lower()
    named = isinstance(exc.filename, (str, bytes, os.PathLike))
    name = exc.filename if named else out
    if name is None:
        return reason
    name = user_path(os.fsdecode(name))
    if not named or exc.errno in _WRITE_ERRNOS:
        return f"{reason} writing {name}"
    return f"{reason}: {name}"
