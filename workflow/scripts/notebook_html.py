"""JupyterLab's HTML export of a notebook without its BeautifulSoup pass (the notebook rules' script, notebook.py).

nbconvert's ``HTMLExporter`` renders the page from its templates and then parses the whole page
(1-2.3 MB here, the figures inline) with BeautifulSoup only to add two attributes, and
serialises it again: about half of a render's CPU (3.4 s of a cold run's 6.3 s). ``LabExporter``
adds the same attributes to the rendered text directly:

* ``alt`` on an image without one (nbconvert's wording), for screen readers;
* ``tabindex="0"`` on every input area (``jp-Cell-inputWrapper``) and output area
  (``jp-OutputArea-output``), so the keyboard reaches them.

Parsed by an HTML parser, the page is the stock exporter's page (tests/unit/workflow/test_notebook_html.py
compares the two on a notebook with every kind of cell and output; the five notebooks of a cold run
were compared when this was written); only the serialisation of the markup that the parser
would have rewritten (quoting, void tags) may differ, not what a browser shows.
"""

from __future__ import annotations

import re

from nbconvert import HTMLExporter
from nbconvert.exporters.templateexporter import TemplateExporter
from nbconvert.filters.highlight import Highlight2HTML
from nbconvert.filters.widgetsdatatypefilter import WidgetsDataTypeFilter

__all__ = ["LabExporter", "accessible"]

#: nbconvert's alternative text for an image without one
MISSING_ALT = "No description has been provided for this image"
_IMG_WITHOUT_ALT = re.compile(r"<img\b(?![^>]*\balt=)([^>]*?)(\s*/?)>")
_FOCUSABLE = re.compile(
    r'<div\b([^>]*\bclass="(?:jp-Cell-inputWrapper|[^"]*\bjp-OutputArea-output\b[^"]*)"[^>]*?)(?<!tabindex="0")>'
)


def accessible(html: str) -> str:
    """``html`` with ``alt`` on every image that has none and ``tabindex="0"`` on every input and
    output area (what nbconvert's HTMLExporter adds after rendering)."""
    html = _IMG_WITHOUT_ALT.sub(lambda m: f'<img{m.group(1)} alt="{MISSING_ALT}"{m.group(2)}>', html)
    return _FOCUSABLE.sub(lambda m: f'<div{m.group(1)} tabindex="0">', html)


class LabExporter(HTMLExporter):
    """``HTMLExporter`` whose page gets its accessibility attributes from :func:`accessible`
    instead of a BeautifulSoup round trip; the filters are set up as ``HTMLExporter`` does."""

    def from_notebook_node(self, nb, resources=None, **kw):
        lang = nb.metadata.get("language_info", {})
        lexer = lang.get("pygments_lexer", lang.get("name", None))
        highlight = self.filters.get("highlight_code", Highlight2HTML(pygments_lexer=lexer, parent=self))
        resources = self._init_resources(resources)
        data_type = WidgetsDataTypeFilter(notebook_metadata=self._nb_metadata, parent=self, resources=resources)
        self.register_filter("highlight_code", highlight)
        self.register_filter("filter_data_type", data_type)
        html, resources = TemplateExporter.from_notebook_node(self, nb, resources, **kw)
        return accessible(html), resources
