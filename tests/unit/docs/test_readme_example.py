"""The library example of docs/library.md runs as printed (its first python block)."""

import re

from conftest import ROOT


def test_library_example_runs(capsys):
    text = (ROOT / "docs" / "library.md").read_text()
    code = re.search(r"```python\n(.*?)```", text, flags=re.S).group(1)
    exec(compile(code, "docs/library.md", "exec"), {})
    out = capsys.readouterr().out
    assert "contact ratio" in out and "semi-axes" in out


def test_library_loaded_example_runs(capsys):
    """The loaded example (the second python block) runs on the first block's pair."""
    text = (ROOT / "docs" / "library.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    ns = {}
    for code in blocks[:2]:
        exec(compile(code, "docs/library.md", "exec"), ns)
    assert ns["s"].n_failed == 0 and ns["s"].mesh_stiffness_mean_N_per_mm_um > 0
