"""``python -m app`` in a checkout: the same command line as ``springscene``.

This folder is not installed (the installed app is :mod:`springscene.app`).
"""

import sys

from springscene.app.signals import main    # the signal handlers first, then cli.main

sys.exit(main())
