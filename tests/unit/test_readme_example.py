"""The README's library example runs as printed (it is the first python block of the
"Using the library" section)."""

import re

from conftest import ROOT


def test_readme_library_example_runs(capsys):
    text = (ROOT / "README.md").read_text()
    section = text.split("## Using the library", 1)[1].split("\n## ", 1)[0]
    code = re.search(r"```python\n(.*?)```", section, flags=re.S).group(1)
    exec(compile(code, "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert "contact ratio" in out and "semi-axes" in out
