"""``python3 -m freecad_groove``: the command line (see freecad_groove.cli)."""

import sys

from .cli import main

sys.exit(main())
