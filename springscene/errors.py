"""The one exception type for bad input: the app prints its message on one line and exits 2."""


class UserError(Exception):
    """Bad input from the user (file, key, flag or value); the message names which."""


class ProgramError(Exception):
    """A user's VPython program raised: ``str()`` is its own traceback (exit status 1)."""
