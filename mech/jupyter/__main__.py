"""``python -m mech.jupyter -f CONNECTION_FILE [--dialect m2]``: the mech kernel (Jupyter starts it
from the kernel spec that ``mech --install-kernel`` installs)."""
import sys

from mech.jupyter.kernel import launch

launch(sys.argv[1:])
