"""The core's shape: every core module (src/gearrep/*.py, the tca and report packages and
src/gearrep/surfaces/*.py) declares its public names in ``__all__``, and the layers only import
downwards: no core module imports from gearrep.replications, and no top-level core module imports
from gearrep.surfaces (the surface protocol lives in gearrep.surface, below the families).
Imports are read from the source with ast (also those inside functions)."""

from __future__ import annotations

import ast
import importlib

import pytest
from conftest import ROOT

PKG = ROOT / "src" / "gearrep"
#: the core below the surface families: top-level modules, the tca package and the report package
TOP = sorted(PKG.glob("*.py")) + sorted((PKG / "tca").glob("*.py")) + sorted((PKG / "report").glob("*.py"))
#: packages whose face re-exports the public names of their private modules (the others' __all__
#: names their submodules)
FACES = ("gearrep", "gearrep.tca", "gearrep.report")
SURFACES = sorted((PKG / "surfaces").glob("*.py"))


def _name(path):
    rel = path.relative_to(PKG.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports(path):
    """Absolute names of the gearrep modules imported by the file at ``path``."""
    mod = _name(path)
    package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            out.add(target)
            out |= {f"{target}.{a.name}" for a in node.names}
    return {m for m in out if m == "gearrep" or m.startswith("gearrep.")}


def _top_level_public(tree):
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names |= {t.id for t in targets if isinstance(t, ast.Name)}
    return {n for n in names if not n.startswith("_")}


@pytest.mark.parametrize("path", TOP + SURFACES, ids=_name)
def test_core_module_declares_its_public_names(path):
    mod = _name(path)
    module = importlib.import_module(mod)
    assert isinstance(getattr(module, "__all__", None), list), f"{mod} has no __all__ list"
    declared = module.__all__
    assert len(declared) == len(set(declared)), f"{mod}.__all__ repeats a name"
    if path.name == "__init__.py" and mod not in FACES:
        missing = [n for n in declared if not (path.parent / f"{n}.py").exists()]
        assert not missing, f"{mod}.__all__ names no submodule: {missing}"
        return
    missing = [n for n in declared if not hasattr(module, n)]
    assert not missing, f"{mod}.__all__ names undefined names: {missing}"
    undeclared = sorted(_top_level_public(ast.parse(path.read_text())) - set(declared))
    assert not undeclared, f"public names of {mod} missing from __all__: {undeclared}"


@pytest.mark.parametrize("path", TOP + SURFACES, ids=_name)
def test_core_module_imports_only_downwards(path):
    mod = _name(path)
    imported = _imports(path)
    up = sorted(m for m in imported if m.startswith("gearrep.replications"))
    assert not up, f"{mod} imports from the replications: {up}"
    if path in TOP:
        up = sorted(m for m in imported if m.startswith("gearrep.surfaces"))
        assert not up, f"{mod} imports from gearrep.surfaces (use gearrep.surface): {up}"


def test_import_reader_sees_relative_and_nested_imports():
    # the reader itself: relative imports of each level, and imports inside functions
    f = PKG / "curvature_relations.py"
    assert {"gearrep.curvature", "gearrep.envelope", "gearrep.surface"} <= _imports(f)
    hob = PKG / "surfaces" / "hob.py"
    assert "gearrep.surface.RotatedSurface" in _imports(hob)
    nov = PKG / "surfaces" / "_rack_generated.py"
    assert {"gearrep.surfaces.rack", "gearrep.curvature_relations"} <= _imports(nov)
    # imports inside functions: ast.walk sees them like any other (the library has none left
    # outside the command; tests/unit/architecture/test_import_graph.py reads them on a toy package)


CLI = sorted((PKG / "cli").rglob("*.py"))
#: what the command still takes from the replication packages, by module: none (the Novikov-
#: Wildhaber, CATT and hobbed families are library code); this list may only stay empty
CLI_REPLICATION_DEBT: dict[str, set[str]] = {}


@pytest.mark.parametrize("path", CLI, ids=_name)
def test_cli_uses_the_library_not_the_replications(path):
    """The user-facing command is a user of the library: it imports no replication package (the
    hobbed_curvilinear family uses gearrep.tca and gearrep.surfaces.hob, not hobcut_tca), except
    the modules listed in CLI_REPLICATION_DEBT."""
    mod = _name(path)
    allowed = CLI_REPLICATION_DEBT.get(mod, set())
    rep = {m for m in _imports(path) if m.startswith("gearrep.replications")}
    extra = sorted(m for m in rep if not any(m == a or m.startswith(a + ".") for a in allowed))
    assert not extra, f"{mod} imports from the replications: {extra}"
    assert not any(m.startswith(("gearrep.replications.hobcut", "gearrep.replications._hobcut")) for m in rep)


def test_cli_replication_debt_is_current():
    # each listed import still exists (an entry whose import was removed must leave the list)
    for mod, allowed in CLI_REPLICATION_DEBT.items():
        path = PKG / "cli" / f"{mod.rsplit('.', 1)[1]}.py"
        rep = {m for m in _imports(path) if m.startswith("gearrep.replications")}
        assert allowed <= rep, f"{mod} no longer imports {sorted(allowed - rep)}: remove it from CLI_REPLICATION_DEBT"
