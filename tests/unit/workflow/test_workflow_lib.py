"""The workflow's own modules (workflow/lib): the import walker behind lib(), and the one
configuration declaration that the schema, the config files and the test configuration follow."""

import ast
import copy
import json
import sys

import pytest
import yaml
from conftest import ROOT

sys.path.insert(0, str(ROOT / "workflow" / "lib"))

import modgraph  # noqa: E402
import wfconfig  # noqa: E402

from gearrep import settings as S  # noqa: E402
from gearrep.replications import REGISTRY  # noqa: E402


# -- import walker ----------------------------------------------------------------------------
@pytest.fixture
def pkg(tmp_path):
    """A small package: a -> b (relative), b -> c.d (absolute), c/d imports nothing; e alone."""
    p = tmp_path / "src" / "gearrep"
    (p / "c").mkdir(parents=True)
    (p / "__init__.py").write_text("")
    (p / "a.py").write_text("from . import b\nimport numpy\n")
    (p / "b.py").write_text("from gearrep.c.d import x\n")
    (p / "c" / "__init__.py").write_text("")
    (p / "c" / "d.py").write_text("x = 1\n")
    (p / "e.py").write_text("from .c import d\n")
    return modgraph.ModuleGraph(tmp_path / "src", tmp_path)


def test_closure_follows_relative_and_absolute_imports(pkg):
    assert pkg.closure("a") == [
        "src/gearrep/__init__.py",
        "src/gearrep/a.py",
        "src/gearrep/b.py",
        "src/gearrep/c/__init__.py",
        "src/gearrep/c/d.py",
    ]
    assert pkg.closure("e") == [
        "src/gearrep/__init__.py",
        "src/gearrep/c/__init__.py",
        "src/gearrep/c/d.py",
        "src/gearrep/e.py",
    ]
    assert pkg.closure() == []
    with pytest.raises(ValueError, match="no module gearrep.zz"):
        pkg.closure("zz")


def test_scripts_and_notebooks(pkg, tmp_path):
    script = tmp_path / "s.py"
    script.write_text("import gearrep\nfrom gearrep import a\nfrom gearrep.c import d as dd\nimport os\n")
    assert pkg.source_modules(script) == ["", "a", "c", "c.d"]
    nb = tmp_path / "n.ipynb"
    nb.write_text(
        '{"cells": [{"cell_type": "code", "source": ["%matplotlib inline\\n", "from gearrep import e\\n"]},'
        ' {"cell_type": "markdown", "source": ["import gearrep.a"]}]}'
    )
    assert pkg.source_modules(nb) == ["", "e"]
    assert "src/gearrep/b.py" in pkg.source_closure(script)
    assert pkg.source_closure(nb, "a")[-1] == "src/gearrep/e.py"


def _full_walk_imports(text):
    """Every import node of a full parse (what the line scan of modgraph must equal)."""
    return [n for n in ast.walk(ast.parse(text)) if isinstance(n, (ast.Import, ast.ImportFrom))]


def test_import_scan_equals_the_full_parse_for_every_source_file():
    """modgraph parses only the lines that start an import statement (fast enough for every
    workflow start); on every module, script and notebook of the project it finds exactly the
    import statements a full parse finds."""
    files = sorted((ROOT / "src" / "gearrep").rglob("*.py")) + sorted((ROOT / "workflow" / "scripts").glob("*.py"))
    assert len(files) > 50
    for f in files:
        text = f.read_text()
        fast = sorted(ast.dump(n) for n in modgraph._import_nodes(text, str(f)))
        assert fast == sorted(ast.dump(n) for n in _full_walk_imports(text)), f


def test_import_scan_reads_multiline_and_continued_imports_and_skips_prose():
    text = (
        "from gearrep.tca import (\n    a,\n    b,\n)\n"
        "def f():\n    from . import c  # lazy\n"
        "import gearrep.x, \\\n    gearrep.y\n"
        '"""\nfrom the flank the pinion is cut\n"""\n'
    )
    nodes = modgraph._import_nodes(text, "t.py")
    assert sorted(ast.dump(n) for n in nodes) == sorted(ast.dump(n) for n in _full_walk_imports(text))
    assert len(nodes) == 3


# -- configuration ------------------------------------------------------------------------------
def _config(name):
    return yaml.safe_load((ROOT / "config" / name).read_text()) or {}


def test_schema_file_is_generated_from_the_declarations():
    text = (ROOT / "config" / "schema.json").read_text()
    assert json.loads(text) == json.loads(json.dumps(wfconfig.schema())), (
        "config/schema.json differs from the settings declarations: run `make schema`"
    )
    assert json.loads(text)["$comment"] == wfconfig.SCHEMA_COMMENT
    assert not (ROOT / "config" / "schema.yaml").exists()


def test_every_study_is_declared_and_every_config_key_is_a_setting():
    decl = wfconfig.declaration()
    assert set(REGISTRY) <= set(decl)
    for name in ("config.yaml", "test.yaml"):
        wfconfig.resolve_config(_config(name), ROOT)  # raises on any undeclared key or bad value
    both = copy.deepcopy(_config("config.yaml"))
    for k, v in _config("test.yaml").items():
        both.setdefault(k, {}).update(v)
    wfconfig.resolve_config(both, ROOT)


@pytest.mark.parametrize(
    "config, message",
    [
        ({"litvin200": {}}, r"config\.litvin200: unknown setting \(did you mean 'litvin2000'\?\)"),
        ({"temirkhan2023": {"tol": float("nan")}}, r"config\.temirkhan2023\.tol: got nan"),
        ({"bench": {"replications": ["temirkhan2023", "cat"]}}, r"config\.bench\.replications\[1\]: got 'cat'"),
        ({"published_dir": "no/such/dir"}, r"config\.published_dir: 'no/such/dir' is not a directory"),
    ],
)
def test_bad_config_names_the_key(config, message):
    with pytest.raises(S.SettingError, match=message):
        wfconfig.resolve_config(config, ROOT)


@pytest.mark.parametrize(
    "config, message",
    [
        ({"temirkhan2023": {"tol": float("nan")}}, r"temirkhan2023\.tol: got nan"),
        ({"ma2021": {"thickness": {"face_width": float("inf")}}}, r"ma2021\.thickness\.face_width: got inf"),
        ({"hobcut_tca": {"phi1_step_deg": 60.0}}, r"hobcut_tca\.phi1_step_deg"),
        ({"ma2021": {"section_check": {"design": "no_such_design"}}}, r"ma2021\.section_check\.design"),
        ({"published_dir": "nowhere"}, r"published_dir: 'nowhere' is not a directory"),
    ],
)
def test_issue16_config_values_stop_before_any_job(config, message):
    """Values the schema let through and that failed only inside a job: refused by
    the parse-time resolution and the studies' cross-field validation."""
    with pytest.raises(S.SettingError, match=message):
        wfconfig.validate_studies(wfconfig.resolve_config(config, ROOT), ROOT)


def test_config_yaml_holds_only_overrides_with_reasons():
    """A key in config/config.yaml must differ from its declared value (else it is a second copy)."""
    decl, cfg = wfconfig.declaration(), _config("config.yaml")

    def walk(d, over, where):
        for k, v in over.items():
            if isinstance(v, dict) and decl_of(d, k).kind == "group":
                walk(decl_of(d, k).fields, v, f"{where}.{k}")
            else:
                assert v != decl_of(d, k).value, f"{where}.{k} repeats its declared value {v!r}"

    def decl_of(d, k):
        return d[k]

    walk(decl, cfg, "config")
