"""``python -m mech``: the same as the ``mech`` command."""
import sys

from .cli import main

sys.exit(main())
