"""Reading TOML input files with errors that name the file."""

from __future__ import annotations

import tomllib
from pathlib import Path

__all__ = ["load_toml"]


def load_toml(path: Path, error: type[ValueError]) -> dict:
    """Parse the TOML file ``path``; raise ``error`` naming the file if unreadable or invalid."""
    try:
        return tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as exc:
        raise error(f"{path}: cannot read ({exc.strerror})") from None
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: not valid TOML ({exc})") from None
