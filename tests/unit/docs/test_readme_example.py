"""The library example of docs/library.md runs as printed (its first python block)."""

import re

from conftest import ROOT


def test_library_example_runs(capsys):
    text = (ROOT / "docs" / "library.md").read_text()
    code = re.search(r"```python\n(.*?)```", text, flags=re.S).group(1)
    exec(compile(code, "docs/library.md", "exec"), {})
    out = capsys.readouterr().out
    assert "contact ratio" in out and "semi-axes" in out
