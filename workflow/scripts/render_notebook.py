"""Render an executed notebook to HTML for readers (Snakemake script of rule render_notebook).

* the preamble cell (tag ``gearrep-step-properties``, written by ``execute_notebook.py``: the rule's
  files and the machine's working directory) is removed;
* every code cell is folded under a "code" toggle (template ``workflow/report/notebook``), so
  prose, tables and figures come first;
* the page is JupyterLab's (``notebook_html.LabExporter``: nbconvert's HTML exporter without its
  BeautifulSoup round trip, the same page once parsed);
* paths of the machine that ran the notebook (working directory, interpreter prefix, home) are
  replaced in every output by relative or neutral names (the report job then refuses any rendered
  page that still shows an absolute path: ``gearrep.report.absolute_paths``; the check is not made
  here so that a change of gearrep.report reruns the report alone).
"""

import os
import sys
from pathlib import Path

import nbformat
from nbconvert.preprocessors import TagRemovePreprocessor
from notebook_html import LabExporter

smk = snakemake  # noqa: F821  (provided by Snakemake)

PREAMBLE_TAG = "gearrep-step-properties"
TEMPLATE_DIR = Path(smk.input.template).parent


def _replacements() -> list[tuple[str, str]]:
    """Machine prefixes, longest first, and what a reader sees instead."""
    pairs = {
        str(Path.cwd()) + os.sep: "",
        str(Path.cwd()): ".",
        sys.prefix: "{python}",
        sys.base_prefix: "{python}",
        str(Path.home()): "~",
    }
    return sorted(((k, v) for k, v in pairs.items() if len(k) > 1), key=lambda kv: -len(kv[0]))


def _clean(text: str, pairs) -> str:
    for old, new in pairs:
        text = text.replace(old, new)
    return text


def clean_notebook(nb, pairs) -> None:
    """Replace machine paths in every output (streams, tracebacks, rich data) of ``nb``."""
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            if "text" in out:
                out["text"] = _clean(out["text"], pairs)
            if "traceback" in out:
                out["traceback"] = [_clean(t, pairs) for t in out["traceback"]]
            if "evalue" in out:
                out["evalue"] = _clean(out["evalue"], pairs)
            for mime, data in out.get("data", {}).items():
                if mime.startswith("text/") and isinstance(data, str):
                    out["data"][mime] = _clean(data, pairs)


nb = nbformat.read(smk.params.notebook, as_version=4)
clean_notebook(nb, _replacements())
exporter = LabExporter(template_name="lab", extra_template_paths=[str(TEMPLATE_DIR.resolve())])
exporter.template_file = Path(smk.input.template).name
exporter.register_preprocessor(TagRemovePreprocessor(remove_cell_tags={PREAMBLE_TAG}, enabled=True), enabled=True)
body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": Path(smk.output[0]).stem}})
Path(smk.output[0]).write_text(body, encoding="utf-8")
Path(smk.log[0]).write_text(f"rendered {smk.params.notebook}: {len(nb.cells)} cells, preamble removed\n")
