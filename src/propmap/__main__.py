"""``python -m propmap``: the command line (same as the ``propmap`` script)."""

from propmap.cli.main import run

if __name__ == "__main__":
    run()
