"""PX4 ULog topics as pyulog parses them: a topic's timestamps and fields, and whether it is in
a log (the ULog reader's access shared by :mod:`propmap.io.ulog` and
:mod:`propmap.io.ulog_motors`)."""

from __future__ import annotations

import numpy as np


def _missing(ulog, name: str) -> str:
    """How topic ``name`` is missing from a log: declared (its format is in the log) without a
    message, or not at all (a zero-message topic was said to be 'not in the log')."""
    formats = getattr(ulog, "message_formats", None) or {}
    return "has no message in the log (its format is declared)" if name in formats else "not in the log"


def _topic(ulog, name: str, fields: list[str], where: str, error: type[ValueError], instance: int | None = None):
    """(t [s], columns) of topic ``name``'s instance ``instance`` (multi_id; default the
    lowest); the error names what is missing."""
    sets = [d for d in ulog.data_list if d.name == name and (instance is None or d.multi_id == instance)]
    if not sets:
        found = sorted({d.name for d in ulog.data_list})
        raise error(f"{where}: topic {name!r} {_missing(ulog, name)} (topics found: {', '.join(found)[:300]})")
    d = min(sets, key=lambda s: s.multi_id)
    missing = [f for f in fields if f not in d.data]
    if missing:
        raise error(f"{where}: topic {name!r} lacks field(s) {', '.join(missing)} (fields: "
                    f"{', '.join(sorted(d.data))[:300]})")
    return d.data["timestamp"] * 1e-6, np.column_stack([np.asarray(d.data[f], float) for f in fields])


def _has(ulog, name: str) -> bool:
    return any(d.name == name for d in ulog.data_list)
