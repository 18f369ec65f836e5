"""The package's import structure (docs/conventions.md, Code layout: core <- io <- identify, maps,
vehicle, ... <- cli).

Every import is read from the source (module level and inside functions alike, with
:mod:`ast`), so a function-local import that closes a cycle counts as one; imports under
``if TYPE_CHECKING:`` (annotations only, never executed) do not.
"""

from __future__ import annotations

import ast
from pathlib import Path

import propmap

ROOT = Path(propmap.__file__).parent
#: none since 2026-11-23 (io.calibration no longer reads parameter files: io.params_file.set_coverage
#: does, on top of io.calibration.coverage)
KNOWN_CYCLES = []
#: layers: a module may import its own layer and those below it
LAYERS = {"core": 0, "io": 1, "cli": 3, "__main__": 3}
LEAVES = {"vehicle": {"identify", "maps", "rotormap", "mapresults", "export_c", "simexport", "validation", "cases",
                       "cases_gill2019", "plots", "plots_flight"}}


def _modules() -> dict[str, tuple[Path, bool]]:
    out = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        package = parts[-1] == "__init__"
        out[".".join(parts[:-1] if package else parts)] = (path, package)
    return out


def _lazy_exports(path: Path) -> dict[str, str]:
    """A package's ``_EXPORTS`` table (name -> submodule, relative; propmap/_lazy.py), or {}."""
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if (isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "_EXPORTS" for t in node.targets)
                and isinstance(node.value, ast.Dict)):
            return {k.value: v.value for k, v in zip(node.value.keys, node.value.values)}
    return {}


def _ancestors(name: str) -> list[str]:
    parts = name.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts))]


def _imports(name: str, path: Path, package: bool, modules, lazy) -> set[str]:
    """The propmap modules and packages that importing ``name`` runs, from its source.

    Importing a.b.c runs the packages a.b and a first (their ``__init__``), so those count
    too, except the importer's own packages, which are being imported already. A name
    taken from a package's lazy ``_EXPORTS`` table counts as its submodule.
    """
    found = set()
    own = set(_ancestors(name))
    tree = ast.parse(path.read_text(encoding="utf-8"))
    typing_only = {id(n) for block in ast.walk(tree) if isinstance(block, ast.If)
                   and getattr(block.test, "id", getattr(block.test, "attr", None)) == "TYPE_CHECKING"
                   for stmt in block.body for n in ast.walk(stmt)}
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        targets = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if package else name.split(".")[:-1]
                base = base[:len(base) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            for a in node.names:
                sub = f"{mod}.{a.name}"
                if sub not in modules and a.name in lazy.get(mod, {}):
                    sub = f"{mod}.{lazy[mod][a.name]}"
                targets.append(sub if sub in modules else mod)
        for t in targets:
            while t not in modules and "." in t:
                t = t.rsplit(".", 1)[0]
            if t in modules:
                found.update(a for a in [*_ancestors(t), t] if a in modules and a != name and a not in own)
    return found


def _graph():
    modules = _modules()
    lazy = {m: _lazy_exports(p) for m, (p, pkg) in modules.items() if pkg}
    return modules, {m: _imports(m, p, pkg, modules, lazy) for m, (p, pkg) in modules.items()}


def _cycles(graph: dict[str, set[str]], nodes: list[str]) -> list[set[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in graph or w not in nodes:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                on.discard(w)
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(comp)

    for v in nodes:
        if v not in index:
            visit(v)
    return out


def _top(module: str) -> str:
    return module.split(".")[1] if "." in module else ""


def test_the_import_graph_is_read():
    """The reader sees the imports it must (guards the checks below against an empty graph)."""
    modules, graph = _graph()
    assert len(modules) > 60
    assert "propmap.core.solver" in graph["propmap.maps"]  # a module-level relative import
    assert "propmap.io.calibration" in graph["propmap.io.params_file"]  # a function-local import
    assert "propmap.vehicle" in graph["propmap.identify.flight"]  # through the package's __init__
    assert "propmap.identify.flight_samples" not in graph["propmap.identify.flight_scores"]  # its TYPE_CHECKING import
    assert "propmap.vehicle.layout" not in graph["propmap.vehicle._jacobians"]  # its TYPE_CHECKING import of Vehicle


def test_no_import_cycles():
    modules, graph = _graph()
    assert _cycles(graph, list(graph)) == KNOWN_CYCLES


def test_modules_import_only_their_layer_and_below():
    """core imports no other layer, io only core; nothing but the CLI imports the CLI; the
    vehicle model imports none of the modules that use it."""
    modules, graph = _graph()
    bad = []
    for m, deps in graph.items():
        if modules[m][1]:
            continue
        layer = LAYERS.get(_top(m), 2)
        for d in deps:
            if d == "propmap":  # the package itself: its __version__
                if layer < 2:
                    bad.append((m, d))
                continue
            if LAYERS.get(_top(d), 2) > layer or _top(d) in LEAVES.get(_top(m), ()):
                bad.append((m, d))
    assert bad == []


def test_no_function_takes_20_arguments():
    """docs/conventions.md: a function of 20 arguments asks to be split by responsibility
    (the kernels pack their per-annulus and per-point data into arrays, the commands their
    option groups into one value each). The largest today: the kernel's solve_batch, 19."""
    worst = []
    for name, (path, _) in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                a = node.args
                n = (len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (a.vararg is not None)
                     + (a.kwarg is not None))
                worst.append((n, f"{name}.{node.name}"))
    worst.sort(reverse=True)
    assert len(worst) > 500  # every module was read
    assert worst[0][0] < 20, worst[:3]


def test_no_module_past_650_lines():
    """docs/conventions.md: a file past about 600 lines asks to be split by responsibility (the
    CLI's shared helpers were, 2026-11-29: 654 lines -> _common, _air and _coverage). The largest
    today: core/_annulus.py, 640 lines."""
    sizes = sorted(((len(path.read_text(encoding="utf-8").splitlines()), name)
                    for name, (path, _) in _modules().items()), reverse=True)
    assert len(sizes) > 100  # every module was read
    assert sizes[0][0] <= 650, sizes[:3]


def test_rpm_is_converted_in_one_place():
    """Every rpm <-> rad/s conversion goes through propmap.core.units.RPM (docs/nomenclature.md):
    23 inline forms (x * pi / 30, x * 2 * pi / 60, x * 30 / pi), evaluated in different orders,
    could differ from x * RPM in the last bit."""
    import re

    from propmap.core.units import RPM, RPM_MAX

    assert RPM == 2 * 3.141592653589793 / 60 and RPM_MAX == 954929.0
    assert RPM_MAX * RPM <= 1e5 < (RPM_MAX + 1) * RPM  # the solver's Omega bound in whole rpm
    inline = re.compile(r"((math|np)\.pi\s*/\s*30|2\s*\*\s*(math|np)\.pi\s*/\s*60|30(\.0)?\s*/\s*(math|np)\.pi|"
                        r"60(\.0)?\s*/\s*\(2\s*\*\s*(math|np)\.pi\))")
    found = [f"{p.relative_to(ROOT)}:{i}" for p in ROOT.rglob("*.py") if p.name != "units.py"
             for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if inline.search(line)]
    assert not found, found
