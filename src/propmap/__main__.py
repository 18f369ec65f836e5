"""``python -m propmap``: the command line (same as the ``propmap`` script)."""

import sys

from propmap.cli.main import main

if __name__ == "__main__":
    sys.exit(main())
