"""The import graph of ``gearrep``: no module imports itself in turn (no cycle), no module takes
a private name or a private module from outside the package that holds it, and outside the
command-line package every import of the package is at module top.

Every module of ``src/gearrep`` is parsed with ``ast``; every import statement counts, also those
inside functions and methods (an import placed in a function hides a cycle at import time but not
the dependency), and relative imports are resolved against the importing module's package.

An edge ``a -> b`` means that importing ``a`` runs ``b``: ``import p.q.m`` and ``from p.q import m``
(``m`` a module) run ``p``, ``p.q`` and ``p.q.m``, except the packages that hold ``a`` (already
running when ``a`` runs); ``from p.q import name`` reads ``name`` from ``p.q``'s namespace, so it
needs ``p.q`` itself, even when ``p.q`` holds ``a`` (the classic circle: a submodule importing a
name from its own package's ``__init__``).

Private means a name with one leading underscore (not a dunder). A private module ``p._m`` (or
anything under it) may be imported only by modules of ``p`` (so a private module of the top-level
package, such as ``gearrep._newton_steps``, by the library only); a private name of module ``p.m``
(or of the package ``p`` itself) only by the other modules of ``p``. The top-level modules of
``gearrep`` are concepts of their own, not the parts of one: a private name of ``gearrep.m`` is
imported by nobody else."""

from __future__ import annotations

import ast
from dataclasses import dataclass

import pytest
from conftest import ROOT

PKG = ROOT / "src" / "gearrep"
ROOT_PACKAGE = "gearrep"


@dataclass(frozen=True)
class Import:
    """One imported module or name: ``importer`` (dotted) at ``line`` takes ``module`` (dotted)
    or, when ``name`` is set, the attribute ``name`` of ``module``."""

    importer: str
    line: int
    module: str
    name: str | None = None

    def __str__(self):
        what = f"{self.name} from {self.module}" if self.name else self.module
        return f"{self.importer}:{self.line} imports {what}"


def source_tree(pkg_dir=PKG) -> dict[str, tuple[str, bool]]:
    """dotted module name -> (source, is_package) of every module under ``pkg_dir``."""
    out = {}
    for path in sorted(pkg_dir.rglob("*.py")):
        parts = list(path.relative_to(pkg_dir.parent).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        if is_package:
            parts.pop()
        out[".".join(parts)] = (path.read_text(), is_package)
    return out


def _private(part: str) -> bool:
    return part.startswith("_") and not (part.startswith("__") and part.endswith("__"))


def _parent(name: str) -> str:
    return name.rpartition(".")[0]


def imports_of(module: str, source: str, is_package: bool, known: set[str]) -> list[Import]:
    """The package modules and names that ``module`` imports (every import statement, at any
    depth), relative imports resolved; ``known`` is the set of the package's modules."""
    package = module if is_package else _parent(module)
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [Import(module, node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            for a in node.names:
                sub = f"{target}.{a.name}"
                found.append(
                    Import(module, node.lineno, sub) if sub in known else Import(module, node.lineno, target, a.name)
                )
    return [i for i in found if i.module == ROOT_PACKAGE or i.module.startswith(ROOT_PACKAGE + ".")]


def _holders(module: str) -> set[str]:
    """The packages that hold ``module`` (running when it runs)."""
    parts = module.split(".")
    return {".".join(parts[:i]) for i in range(1, len(parts))}


def edges(tree: dict[str, tuple[str, bool]]) -> dict[str, dict[str, Import]]:
    """importer -> {imported module: the first import statement that makes the edge}."""
    known = set(tree)
    graph: dict[str, dict[str, Import]] = {m: {} for m in tree}
    for module, (source, is_package) in tree.items():
        holders = _holders(module)
        for imp in imports_of(module, source, is_package, known):
            parts = imp.module.split(".")
            runs = {".".join(parts[:i]) for i in range(1, len(parts) + 1)} - holders
            if imp.name is not None:
                runs.add(imp.module)  # the name comes from that module's namespace
            for target in sorted(runs & known - {module}):
                graph[module].setdefault(target, imp)
    return graph


def cycles(graph: dict[str, dict[str, Import]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan): each a set of modules
    that import one another in turn, as a sorted list."""
    index, low, stack, on_stack, comps = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(comps)


def show_cycle(graph, comp: list[str]) -> str:
    """A component of the graph, with the import statement behind each of its edges."""
    inside = [f"    {graph[a][b]}" for a in comp for b in sorted(graph[a]) if b in comp]
    return "  " + " <-> ".join(comp) + "\n" + "\n".join(inside)


def private_imports(tree: dict[str, tuple[str, bool]]) -> list[Import]:
    """Imports of a private module or name from outside the package that holds it."""
    known = set(tree)
    bad = []
    for module, (source, is_package) in tree.items():
        for imp in imports_of(module, source, is_package, known):
            parts = imp.module.split(".")
            for i, part in enumerate(parts):
                holder = ".".join(parts[:i])
                if _private(part) and not (module == holder or module.startswith(holder + ".")):
                    bad.append(imp)
                    break
            else:
                if imp.name is None or not _private(imp.name):
                    continue
                owner_is_package = tree.get(imp.module, ("", False))[1]
                holder = imp.module if owner_is_package else _parent(imp.module)
                inside = module != imp.module and (module == holder or module.startswith(holder + "."))
                if holder == ROOT_PACKAGE and not owner_is_package:
                    inside = False
                if not inside:
                    bad.append(imp)
    return bad


def nested_imports(tree: dict[str, tuple[str, bool]], modules) -> list[Import]:
    """Package imports inside functions or methods of ``modules``."""
    found = []
    for module in modules:
        source, is_package = tree[module]
        functions = (f for f in ast.walk(ast.parse(source)) if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)))
        inner = {n.lineno for f in functions for n in ast.walk(f) if isinstance(n, (ast.Import, ast.ImportFrom))}
        found += [i for i in imports_of(module, source, is_package, set(tree)) if i.line in inner]
    return found


TREE = source_tree()
GRAPH = edges(TREE)


def test_the_package_has_no_import_cycle():
    found = cycles(GRAPH)
    shown = "\n".join(show_cycle(GRAPH, c) for c in found)
    assert not found, f"import cycles:\n{shown}"


def test_the_package_imports_itself_at_module_top():
    """Every import of the package is at module top, where the import order shows the layers
    (third-party imports, such as scipy and matplotlib, may wait for the function that needs them)."""
    found = nested_imports(TREE, list(TREE))
    assert not found, "package imports inside functions:\n" + "\n".join(f"    {i}" for i in found)


def test_no_private_name_or_module_is_imported_from_outside_its_package():
    bad = private_imports(TREE)
    assert not bad, "private imports from outside their package:\n" + "\n".join(f"    {b}" for b in bad)


# -- the checks see what they look for ------------------------------------------------------------
def _toy(**modules):
    """A toy package ``gearrep`` from ``dotted_name=source`` (``__init__`` names a package)."""
    tree = {}
    for key, source in modules.items():
        parts = key.split("__")
        is_package = parts[-1] == "init"
        name = ".".join(["gearrep", *[p for p in parts if p != "init"]])
        tree[name] = (source, is_package)
    return tree


def test_the_graph_sees_relative_nested_and_absolute_imports():
    tree = _toy(
        init="",
        a="from .b import f\n",
        b="def f():\n    from . import c\n",
        c="import gearrep.d.e\n",
        d__init="",
        d__e="class K:\n    def m(self):\n        from ..a import f\n",
    )
    g = edges(tree)
    assert set(g["gearrep.a"]) == {"gearrep.b"}
    assert set(g["gearrep.b"]) == {"gearrep.c"}  # inside a function; the root package is running
    assert set(g["gearrep.c"]) == {"gearrep.d", "gearrep.d.e"}  # the package __init__ runs first
    assert set(g["gearrep.d.e"]) == {"gearrep.a"}  # two dots, in a method
    assert cycles(g) == [["gearrep.a", "gearrep.b", "gearrep.c", "gearrep.d.e"]]


def test_nested_imports_are_found():
    tree = _toy(init="", a="import numpy\nfrom . import b\n", b="def f():\n    import scipy\n    from .a import x\n")
    assert [(i.importer, i.line) for i in nested_imports(tree, tree)] == [("gearrep.b", 3)]


def test_a_name_from_the_own_package_init_is_a_cycle_but_a_sibling_module_is_not():
    tree = _toy(p__init="from ._x import f\nfrom . import y\n", p___x="", p__y="")
    assert cycles(edges(tree)) == []
    tree["gearrep.p.y"] = ("from . import f\n", False)  # f is a name of the package p
    assert cycles(edges(tree)) == [["gearrep.p", "gearrep.p.y"]]


def test_private_imports_from_outside_the_package_are_found():
    tree = _toy(
        init="",
        m="_h = 1\n",
        n="from .m import _h\n",  # a top-level module's private name: refused
        p__init="from ._k import _g\n",  # inside p: allowed
        p___k="_g = 2\n",
        p__q="from ._k import _g\n",  # a sibling in p: allowed
        r="from .p._k import g\nfrom .p import _g\nimport gearrep.p._k\n",  # three refused
        s="from .p import q\n",  # public: allowed
    )
    bad = [(b.importer, b.line) for b in private_imports(tree)]
    assert sorted(bad) == [("gearrep.n", 1), ("gearrep.r", 1), ("gearrep.r", 2), ("gearrep.r", 3)]


@pytest.mark.parametrize("module", ["gearrep.tca", "gearrep.replications", "gearrep.cli"])
def test_the_graph_covers_the_whole_package(module):
    assert module in TREE and len(TREE) > 80
    assert GRAPH[module], f"{module} imports nothing?"
