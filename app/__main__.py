"""``python -m app`` in a checkout: the same command line as ``springscene``.

This folder is not installed (the installed app is :mod:`springscene.app`).
"""

import sys

from springscene.app.cli import main

sys.exit(main())
