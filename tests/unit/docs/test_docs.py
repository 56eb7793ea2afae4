"""The API reference: it builds without a warning (as ``make docs`` does), it documents every
module of the library's public face, and each public name of those modules carries the numpydoc
sections a user looks for: Parameters (every argument), Returns (where it returns a value), Raises
(where it raises or checks its input) and an Examples section with a doctest (the doctests run in
``make test`` through ``--doctest-modules``)."""

from __future__ import annotations

import enum
import importlib
import inspect
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT
from numpydoc.docscrape import ClassDoc, FunctionDoc
from sphinx.pycode import ModuleAnalyzer

API = ROOT / "docs" / "api"

#: the modules of the reference (every page), whose public names are checked section by section
CHECKED = (
    "gearrep.units",
    "gearrep.inputs",
    "gearrep.solve",
    "gearrep.surface",
    "gearrep.surfaces.involute",
    "gearrep.meshing",
    "gearrep.curvature",
    "gearrep.ellipse",
    "gearrep.frames",
    "gearrep.surfaces.analytic",
    "gearrep.surfaces.rack",
    "gearrep.plotting",
    "gearrep.settings",
    "gearrep.motion",
    "gearrep.checks",
    "gearrep.tca",
    "gearrep.surfaces.catt",
    "gearrep.surfaces.novikov",
    "gearrep.surfaces.worm_ground",
    "gearrep.surfaces.hob",
    "gearrep.surfaces.bevel",
    "gearrep.envelope",
    "gearrep.curvature_relations",
    "gearrep.published",
    "gearrep.report",
    "gearrep.ltca",
    "gearrep.ltca.iso",
)

#: the input checks whose call means the function raises ``ValueError`` on bad input
_CHECK_CALL = re.compile(r"\b(check_finite|check_positive|check_integer|raise)\b")


def test_api_reference_builds_without_warnings(tmp_path):
    # a fresh build (no saved environment): every page and docstring is read again; -W makes a
    # warning an error and --keep-going reports all of them
    out = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html", "-d", str(tmp_path / "doctrees")]
        + [str(API), str(tmp_path / "html")],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert out.returncode == 0, out.stderr[-6000:]
    assert (tmp_path / "html" / "gearrep.tca.html").is_file()


def test_every_public_module_has_a_page():
    pages = {p.stem for p in API.glob("gearrep.*.rst")}
    listed = set(re.findall(r"^\s+(gearrep[\w.]*)$", (API / "index.rst").read_text(), flags=re.M))
    assert pages == listed, "every page is in the index's table of contents"
    assert set(CHECKED) == pages, "every module page is checked section by section"


def _public(module):
    mod = importlib.import_module(module)
    return [(name, getattr(mod, name)) for name in mod.__all__]


def _own_members(cls):
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if inspect.isfunction(value) or isinstance(value, (classmethod, staticmethod)):
            yield name, getattr(cls, name)
        elif isinstance(value, property):
            yield name, value


def _missing_sections(obj, doc, *, example: bool) -> list[str]:
    """Names of the numpydoc sections ``obj``'s docstring lacks."""
    missing = []
    if not inspect.getdoc(obj):
        return ["docstring"]
    if isinstance(obj, property):
        return []
    func = obj.__init__ if inspect.isclass(obj) else obj
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        sig = None
    params = [] if sig is None else [p for p in sig.parameters if p not in ("self", "cls")]
    if inspect.isclass(obj) and issubclass(obj, enum.Enum):
        params = []  # members, not constructor arguments
    documented = {n.strip().lstrip("*") for p in doc["Parameters"] + doc["Other Parameters"] for n in p.name.split(",")}
    if inspect.isclass(obj) and not documented:
        documented = {n.strip() for p in doc["Attributes"] for n in p.name.split(",")}
    undocumented = [p for p in params if p not in documented and p.lstrip("*") not in documented]
    if undocumented:
        missing.append(f"Parameters {undocumented}")
    if not inspect.isclass(obj):
        try:
            src = inspect.getsource(func)
        except (OSError, TypeError):
            src = ""
        body = src.split('"""', 2)[-1] if src.count('"""') >= 2 else src
        if re.search(r"^\s+(return|yield)\s+\S", body, flags=re.M) and not (doc["Returns"] or doc["Yields"]):
            missing.append("Returns")
        if _CHECK_CALL.search(body) and not doc["Raises"]:
            missing.append("Raises")
    if example and ">>>" not in "\n".join(doc["Examples"]):
        missing.append("Examples")
    return missing


def _protocol_documented(cls, member) -> bool:
    """Whether ``cls.member`` implements a method a base class documents with its sections (the
    surface protocol's ``evaluate``, ``position``, ...): the protocol states them once."""
    for base in cls.__mro__[1:]:
        doc = inspect.getdoc(vars(base).get(member)) or ""
        if "Parameters\n---" in doc or "Returns\n---" in doc:
            return bool(inspect.getdoc(getattr(cls, member)))
    return False


@pytest.mark.parametrize("module", CHECKED)
def test_public_names_have_numpydoc_sections(module):
    gaps = {}
    for name, obj in _public(module):
        if not (inspect.isclass(obj) or inspect.isfunction(obj)):
            continue
        doc = ClassDoc(obj, config={"show_class_members": False}) if inspect.isclass(obj) else FunctionDoc(obj)
        missing = _missing_sections(obj, doc, example=True)
        if inspect.isclass(obj):
            for member, value in _own_members(obj):
                if _protocol_documented(obj, member):
                    continue
                target = value.fget if isinstance(value, property) else value
                mdoc = FunctionDoc(target) if inspect.getdoc(target) else None
                gaps_m = ["docstring"] if mdoc is None else _missing_sections(value, mdoc, example=False)
                if gaps_m:
                    gaps[f"{name}.{member}"] = gaps_m
        if missing:
            gaps[name] = missing
    assert not gaps, f"{module}: {gaps}"


def _attribute_docs(module) -> set[str]:
    """Names given a ``#:`` comment or a docstring in ``module`` or, for a package with a face,
    in its private modules (where the face's names are defined)."""
    mod = importlib.import_module(module)
    sources = [module]
    if hasattr(mod, "__path__"):
        sources += [f"{module}.{p.stem}" for p in Path(mod.__path__[0]).glob("_*.py") if p.stem != "__init__"]
    names = set()
    for source in sources:
        names |= {name for (_, name) in ModuleAnalyzer.for_module(source).find_attr_docs()}
    return names


def _documented_where_defined(module, name) -> bool:
    """Whether the constant ``name`` that ``module`` re-exports from another gearrep module (the
    same object under the same name) has its ``#:`` comment there."""
    obj = getattr(importlib.import_module(module), name)
    for other in sorted(m for m in sys.modules if m.startswith("gearrep.") and m != module):
        if getattr(sys.modules[other], name, None) is obj and name in _attribute_docs(other):
            return True
    return False


@pytest.mark.parametrize("module", CHECKED)
def test_public_constants_are_documented(module):
    documented = _attribute_docs(module)
    constants = [n for n, obj in _public(module) if not (inspect.isclass(obj) or inspect.isroutine(obj))]
    constants = [n for n in constants if not inspect.ismodule(getattr(importlib.import_module(module), n))]
    missing = [n for n in constants if n not in documented and not _documented_where_defined(module, n)]
    assert not missing, f"{module}: constants without a #: comment"
