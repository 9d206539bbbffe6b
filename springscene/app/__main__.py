import sys

from .signals import main

sys.exit(main())
