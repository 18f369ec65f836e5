"""Every public function and class has a numpydoc docstring with its sections.

The public API is every name in the ``__all__`` of propmap and of its public modules (names
without a leading underscore). A function with parameters documents them under
``Parameters``; one that returns a value has ``Returns`` (or ``Yields``); one whose body
raises has ``Raises``; a class documents its fields under ``Parameters`` or ``Attributes``
(exceptions excepted). Found missing 2026-11-27: FlapResult, BodyTable and
holdout_comparison.
"""

import ast
import importlib
import inspect
import pkgutil
import textwrap

import propmap


def _public_objects():
    modules = [propmap] + [importlib.import_module(m.name)
                           for m in pkgutil.walk_packages(propmap.__path__, "propmap.")
                           if not any(part.startswith("_") for part in m.name.split("."))]
    seen = {}
    for mod in modules:
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name, None)
            if (inspect.isfunction(obj) or inspect.isclass(obj)) and id(obj) not in seen:
                seen[id(obj)] = (f"{mod.__name__}.{name}", obj)
    return list(seen.values())


def _missing_sections(obj) -> list:
    doc = inspect.getdoc(obj) or ""
    if inspect.isclass(obj):
        if issubclass(obj, Exception) or "Parameters" in doc or "Attributes" in doc:
            return []
        return ["Parameters or Attributes"]
    missing = []
    tree = ast.parse(textwrap.dedent(inspect.getsource(obj)))
    if inspect.signature(obj).parameters and "Parameters" not in doc:
        missing.append("Parameters")
    returns = any(isinstance(n, ast.Return) and n.value is not None for n in ast.walk(tree))
    if returns and "Returns" not in doc and "Yields" not in doc:
        missing.append("Returns")
    if any(isinstance(n, ast.Raise) for n in ast.walk(tree)) and "Raises" not in doc:
        missing.append("Raises")
    return missing


def test_public_api_is_large_enough_to_mean_something():
    # (a walk that found nothing would pass the test below)
    names = {name for name, _ in _public_objects()}
    assert len(names) > 150
    assert {"propmap.rotor_loads", "propmap.vehicle_wrench", "propmap.core.flapping.FlapResult"} <= names


def test_every_public_function_and_class_has_its_numpydoc_sections():
    gaps = {name: m for name, obj in _public_objects() if (m := _missing_sections(obj))}
    assert gaps == {}
