"""The exception types: bad input (exit 2), a program's own error and a failed write (exit 1)."""

import errno


class UserError(Exception):
    """Bad input from the user (file, key, flag or value); the message names which."""


class ProgramError(Exception):
    """A user's VPython program raised: ``str()`` is its own traceback (exit status 1)."""


class OutputError(OSError):
    """An output could not be written: no space, a read-only folder, an encoder that failed
    (exit status 1). ``str()`` is one line: "no space left on device writing out.mp4".

    An ``OSError`` with ``errno`` (ENOSPC, EROFS, ...; EIO for an encoder's own failure),
    ``strerror`` (the reason) and ``filename`` (the output), so whatever reports an
    ``OSError`` reports it too.
    """

    def __init__(self, reason: str, path, code: int = errno.EIO) -> None:
        super().__init__(code, reason, str(path))
        self.reason, self.path = reason, path

    def __str__(self) -> str:
        return f"{self.reason} writing {self.path}"

    def __reduce__(self):          # pickled whole (e.g. from a child process)
        return OutputError, (self.reason, self.path, self.errno)

    def at(self, path) -> "OutputError":
        """The same failure named by the file the user asked for (not its temporary)."""
        return OutputError(self.reason, path, self.errno)
