"""Lazy public names of a package (PEP 562): imported from their modules on first use."""

from __future__ import annotations

import importlib


def lazy_exports(package: str, exports: dict[str, str], namespace: dict):
    """(``__getattr__``, ``__dir__``) for ``package`` whose names map to submodules.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    exports : dict
        Public name -> module path relative to ``package`` (e.g. ``"core.solver"``).
    namespace : dict
        The package's ``globals()``: a name, once imported, is cached there.
    """

    def __getattr__(name: str):
        if name in exports:
            value = getattr(importlib.import_module(f".{exports[name]}", package), name)
            namespace[name] = value
            return value
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    def __dir__():
        return sorted(namespace.get("__all__", exports))

    return __getattr__, __dir__
