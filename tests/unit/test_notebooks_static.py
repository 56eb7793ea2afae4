"""Notebooks as stored: no outputs, a Python 3 kernelspec, each executed by a rule of the workflow
that reads workflow results (never the seeds or the library's computations directly)."""

from __future__ import annotations

import json
import re

import pytest
from conftest import ROOT

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
RULES = "\n".join(p.read_text() for p in (ROOT / "workflow" / "rules").glob("*.smk"))


def test_there_is_a_notebook_per_replication_module():
    mods = {p.stem for p in (ROOT / "src" / "gearrep" / "replications").glob("*.py") if not p.stem.startswith("_")}
    have = {p.stem for p in NOTEBOOKS}
    assert mods <= have, f"replications without a notebook: {sorted(mods - have)}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_stored_clean_and_wired(path):
    nb = json.loads(path.read_text())
    ks = nb["metadata"].get("kernelspec", {})
    assert ks.get("name") == "python3" and ks.get("language") == "python", ks
    assert nb["metadata"].get("language_info", {}).get("name") == "python"
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            assert not cell.get("outputs") and cell.get("execution_count") is None, (
                f"{path.name}: stored with outputs (clear them before committing)"
            )
    code = "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
    assert "snakemake.input" in code, f"{path.name} must read its inputs from the workflow (snakemake.input)"
    name = path.stem
    assert re.search(rf'notebook:\s*\n?\s*"\.\./\.\./notebooks/{re.escape(name)}\.ipynb"', RULES), (
        f"no rule executes notebooks/{name}.ipynb"
    )
    assert re.search(rf'NOTEBOOKS\.append\(\s*"{re.escape(name)}"\s*\)', RULES), f"{name} not in NOTEBOOKS"
    assert re.search(rf'touch\("results/notebooks/{re.escape(name)}\.executed"\)', RULES)
