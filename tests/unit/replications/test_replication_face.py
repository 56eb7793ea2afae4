"""Every registered study is a package with the same face (gearrep.replications._face)."""

import pytest
from conftest import study_settings

from gearrep import settings as S
from gearrep.replications import REGISTRY, _face, load


@pytest.mark.parametrize("key", sorted(REGISTRY))
def test_face(key, published):
    mod = load(key)
    _face.check_face(mod)
    assert mod.SEED == REGISTRY[key].seed
    assert mod.__file__.endswith("__init__.py"), "a study is a package"
    for name, s in mod.SETTINGS.items():
        assert isinstance(s, S.Setting) and (s.kind == "group" or s.reason), name
    settings = study_settings(key)
    design = mod.params_from_published(published)
    mod.validate(settings, design)
    assert all(p.startswith(("checks/", "")) for p in mod.CHECK_OUTPUTS.values())
    assert set(mod.REPORT_FIGURES) <= set(mod.FIGURES)


def test_jobs_write_disjoint_tables():
    seen = {}
    for key in REGISTRY:
        for path in _face.table_paths(load(key).JOBS).values():
            assert path not in seen, f"{path} written by {key} and {seen[path]}"
            seen[path] = key


def test_face_checker_refuses_incomplete_packages():
    import types

    with pytest.raises(TypeError, match="lacks"):
        _face.check_face(types.ModuleType("gearrep.replications.empty"))
    # every face name is public: a package's __all__ starts with *FACE
    partial = types.ModuleType("gearrep.replications.partial")
    partial.__dict__.update({n: getattr(load("litvin2000"), n) for n in _face.FACE})
    partial.__all__ = [n for n in _face.FACE if n != "bench_cases"]
    with pytest.raises(TypeError, match=r"__all__ lacks \['bench_cases'\]"):
        _face.check_face(partial)
    with pytest.raises(ValueError, match="must end in"):
        _face.Job(lambda s, d: {}, {"a": "x/b.csv"})


def test_data_readme_lists_the_registry():
    """The data README's seed table names, per seed, exactly the registered studies of papers (a
    validation study reads no paper)."""
    import re

    from conftest import ROOT

    from gearrep.published import PAPERS

    text = (ROOT / "data" / "published" / "README.md").read_text()
    rows = re.findall(r"^\| `(\d{3})` \|[^|]*\| (.*) \|$", text, flags=re.M)
    listed = {seed: set(re.findall(r"`(\w+)`", studies)) for seed, studies in rows}
    registered = {}
    for key, study in REGISTRY.items():
        if not study.validation:
            registered.setdefault(study.seed, set()).add(key)
    assert listed == registered
    assert set(registered) == set(PAPERS)


@pytest.mark.parametrize("key", sorted(REGISTRY))
def test_role_files(key):
    """The same file for the same role in every package (gearrep.replications._face.ROLES)."""
    _face.check_roles(load(key))


def test_role_checker_refuses_a_misplaced_or_renamed_role(tmp_path, monkeypatch):
    import importlib
    import types

    mod = load("litvin2000")
    moved = types.ModuleType(mod.__name__)
    moved.__path__ = mod.__path__
    moved.__dict__.update({n: getattr(mod, n) for n in _face.FACE})
    moved.checks = mod.validate  # a face name not defined in its role file
    with pytest.raises(TypeError, match=r"checks must be defined in checks\.py"):
        _face.check_roles(moved)
    pkg = tmp_path / "toy_replication"
    pkg.mkdir()
    for name in ("__init__", "design", "studies", "bench", "records"):
        (pkg / f"{name}.py").write_text("")
    monkeypatch.syspath_prepend(str(tmp_path))
    toy = importlib.import_module("toy_replication")
    with pytest.raises(TypeError, match=r"lacks the role files \['checks\.py'\]"):
        _face.check_roles(toy)
    (pkg / "checks.py").write_text("")
    with pytest.raises(TypeError, match=r"modules \['records'\] repeat a role"):
        _face.check_roles(toy)


def test_one_name_per_paper():
    """A study's key is its document's name (gearrep.published.PAPER_NAMES) or <name>_<part>;
    every document has one name, and no name is a seed id."""
    from gearrep.published import PAPER_NAMES, PAPERS

    assert set(PAPER_NAMES) == set(PAPERS)
    assert len(set(PAPER_NAMES.values())) == len(PAPER_NAMES)
    for key, study in REGISTRY.items():
        if study.validation:
            assert study.paper == key
            continue
        assert study.paper == PAPER_NAMES[study.seed]
        assert key == study.paper or key.startswith(study.paper + "_"), key
        assert study.seed not in key
