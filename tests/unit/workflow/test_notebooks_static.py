"""Notebooks as stored: no outputs, a Python 3 kernelspec, each executed by a rule of the workflow
that reads workflow results (never the seeds or the library's computations directly)."""

from __future__ import annotations

import json
import re

import pytest
from conftest import ROOT

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
RULES = "\n".join(p.read_text() for p in (ROOT / "workflow" / "rules").glob("*.smk"))


def test_there_is_a_notebook_per_study_and_a_study_per_notebook():
    from gearrep.replications import REGISTRY

    assert set(REGISTRY) == {p.stem for p in NOTEBOOKS}


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
    # the generic notebook rule of every registered study executes notebooks/<study>.ipynb
    from gearrep.replications import REGISTRY

    assert path.stem in REGISTRY, f"{path.name}: no study {path.stem!r} in the registry, so no rule runs it"
    assert re.search(r'notebook=f"notebooks/\{_key\}\.ipynb"', RULES) and '"../scripts/notebook.py"' in RULES
    assert "NOTEBOOKS.append(_key)" in RULES
    assert re.search(r'html=f"results/notebooks/\{_key\}\.html"', RULES)
