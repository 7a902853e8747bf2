"""``python -m flake8_rosgraph`` is the ``flake8-rosgraph`` command.

``python -m`` puts the current directory first on ``sys.path``; run inside the analysed
workspace, a file there named like a module we import (``argparse.py``, ``json.py``)
would be executed. The tool must never run analysed code, so that entry goes first.
"""
import os
import sys

if sys.path and sys.path[0] in ("", ".", os.getcwd()):
    del sys.path[0]

from flake8_rosgraph.cli import main  # noqa: E402  (after the path is made safe)

sys.exit(main())
