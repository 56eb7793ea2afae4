"""The files around the code: licence, citation metadata, changelog, the pinned environment and
Snakemake's default workflow profile agree with pyproject.toml and with each other."""

import re
import tomllib

import pytest
import yaml
from conftest import ROOT
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from gearrep import published as pub

PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
LOCK = ROOT / "requirements.lock"


def _lock_pins() -> dict[str, tuple[str, int]]:
    """{canonical name: (version, number of hashes)} of requirements.lock."""
    pins, name = {}, None
    for line in LOCK.read_text().splitlines():
        m = re.match(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==([^ \\]+)", line)
        if m:
            name = canonicalize_name(m.group(1))
            pins[name] = (m.group(2), 0)
        elif name and line.strip().startswith("--hash=sha256:"):
            version, n = pins[name]
            pins[name] = (version, n + 1)
    return pins


def test_license_is_the_mit_text_pyproject_names():
    text = (ROOT / "LICENSE").read_text()
    assert PYPROJECT["license"] == {"text": "MIT"}
    assert text.startswith("MIT License\n\nCopyright (c) 2026 the gearrep developers\n")
    assert 'THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND' in text


def test_citation_names_this_version_and_the_four_documents():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0"
    assert cff["title"] == PYPROJECT["name"]
    assert cff["version"] == PYPROJECT["version"]
    assert cff["license"] == "MIT"
    seeds = [re.search(r"Seed (\d{3}) of data/published", ref["notes"]).group(1) for ref in cff["references"]]
    assert seeds == list(pub.SEEDS)
    for ref in cff["references"]:
        assert ref["title"].strip() and ref["authors"] and ref["type"], ref


def test_changelog_has_an_unreleased_section():
    text = (ROOT / "CHANGELOG.md").read_text()
    assert re.search(r"^## \[Unreleased\]$", text, flags=re.M)


def test_lock_pins_every_declared_dependency_within_its_range_with_hashes():
    pins = _lock_pins()
    declared = [Requirement(r) for r in [*PYPROJECT["dependencies"], *PYPROJECT["optional-dependencies"]["test"]]]
    for req in declared:
        name = canonicalize_name(req.name)
        assert name in pins, f"{req.name} is not in requirements.lock: run `make lock`"
        version, _ = pins[name]
        assert req.specifier.contains(version, prereleases=True), f"{name}=={version} outside {req}"
    unhashed = [n for n, (_, k) in pins.items() if k == 0]
    assert not unhashed, f"pins without hashes: {unhashed}"
    assert "Python 3.11" in LOCK.read_text().splitlines()[1]


def test_makefile_installs_from_the_lock_and_rebuilds_when_it_changes():
    make = (ROOT / "Makefile").read_text()
    assert re.search(r"^\$\(STAMP\): \$\(LOCK\)", make, flags=re.M)
    assert "--require-hashes -r $(LOCK)" in make
    assert re.search(r"^lock:", make, flags=re.M)


def test_default_workflow_profile_sets_valid_snakemake_options():
    snakemake_cli = pytest.importorskip("snakemake.cli")
    profile = yaml.safe_load((ROOT / "profiles" / "default" / "config.yaml").read_text())
    assert profile == {"cores": 2, "rerun-incomplete": True, "logger": "rich"}
    args = []
    for key, value in profile.items():
        args += [f"--{key}"] if value is True else [f"--{key}", str(value)]
    parsed = snakemake_cli.get_argument_parser().parse_args(args)
    assert (parsed.cores, parsed.rerun_incomplete, parsed.logger) == (2, True, ["rich"])
    # every key says why it is there
    text = (ROOT / "profiles" / "default" / "config.yaml").read_text()
    for key in profile:
        before = text.split(f"\n{key}:", 1)[0].rstrip().splitlines()
        assert before and before[-1].startswith("#"), f"profile key {key} without its reason"


def test_readme_documents_the_seed_texts_and_keeps_snakemakes_report_under_results():
    """The README names GEARREP_SEEDS (where the seed-text tests look), and its
    `snakemake --report` command writes under results/ (git-ignored), not into the repository."""
    import re

    text = (ROOT / "README.md").read_text()
    assert "GEARREP_SEEDS" in text
    reports = re.findall(r"snakemake --report (\S+)", text)
    assert reports and all(r.startswith("results/") for r in reports), reports


#: how a file would speak of how the project was developed rather than of the project: a work
#: session or an internal issue number (another project's tracker is cited by its link)
DEVELOPMENT_WORDS = re.compile(
    r"\bsessions? [0-9]|\b(first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|eleventh|twelfth|"
    r"thirteenth|fourteenth|fifteenth|sixteenth|seventeenth|eighteenth|nineteenth|twentieth) session|\bissues? #?[0-9]+",
    re.IGNORECASE,
)
PROJECT_FILES = ["README.md", "CHANGELOG.md", "docs", "src/gearrep", "workflow", "tests", "notebooks", "data", "config"]


def test_project_files_speak_of_the_project_alone():
    """No work sessions and no internal issue numbers in the project's files (a reason states the
    reason itself); a line citing another project's tracker carries its github.com link."""
    found = []
    for name in PROJECT_FILES:
        root = ROOT / name
        for f in [root] if root.is_file() else sorted(p for p in root.rglob("*") if p.is_file()):
            if "__pycache__" in f.parts or f.suffix in {".png", ".pyc", ".pdf", ".parquet"}:
                continue
            for i, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
                if DEVELOPMENT_WORDS.search(line) and "github.com/" not in line:
                    found.append(f"{f.relative_to(ROOT)}:{i}: {line.strip()[:120]}")
    assert not found, "\n".join(found[:30])
