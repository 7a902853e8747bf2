"""``python -m flake8_rosgraph`` is the ``flake8-rosgraph`` command."""
import sys

from .cli import main

sys.exit(main())
