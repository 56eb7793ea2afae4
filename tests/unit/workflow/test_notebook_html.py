"""The notebook page without nbconvert's BeautifulSoup round trip (workflow/scripts/notebook_html.py):
once parsed, the page is exactly the stock HTMLExporter's, and the attributes that round trip adds
(alt text, tabindex) are there."""

import base64
import sys

import pytest
from conftest import ROOT

pytest.importorskip("nbconvert")
sys.path.insert(0, str(ROOT / "workflow" / "scripts"))

import nbformat  # noqa: E402
from bs4 import BeautifulSoup  # noqa: E402
from nbconvert import HTMLExporter  # noqa: E402
from nbformat import v4  # noqa: E402
from notebook_html import MISSING_ALT, LabExporter, accessible  # noqa: E402

TEMPLATE = ROOT / "workflow" / "report" / "notebook"
PNG = base64.b64encode(bytes.fromhex("89504e470d0a1a0a")).decode()


def notebook():
    """Every kind of cell and output the rendered notebooks hold."""
    code = v4.new_code_cell("x = 1\nprint(x)", execution_count=1)
    code.outputs = [
        v4.new_output("stream", name="stdout", text="1 < 2 & 3\n"),
        v4.new_output("display_data", data={"image/png": PNG, "text/plain": "<Figure>"}),
        v4.new_output(
            "execute_result",
            data={"text/html": "<table><tr><td>a &amp; b</td></tr></table><br>", "text/plain": "t"},
            execution_count=1,
        ),
        v4.new_output("error", ename="ValueError", evalue="bad", traceback=["ValueError: bad"]),
    ]
    cells = [
        v4.new_markdown_cell("# Title\n\ntext with <img src='a.png'> and <img src='b.png' alt='b'>"),
        code,
        v4.new_raw_cell("raw"),
    ]
    nb = v4.new_notebook(cells=cells)
    nb.metadata["language_info"] = {"name": "python", "pygments_lexer": "ipython3"}
    return nbformat.from_dict(nb)


@pytest.mark.parametrize("template", ["lab", "collapsed"])
def test_the_page_parses_to_the_stock_exporters_page(template):
    nb, pages = notebook(), []  # one notebook: its cells' ids are random
    for cls in (HTMLExporter, LabExporter):
        ex = cls(template_name="lab", extra_template_paths=[str(TEMPLATE)])
        if template == "collapsed":
            ex.template_file = "collapsed.html.j2"
        pages.append(ex.from_notebook_node(nb, resources={"metadata": {"name": "t"}})[0])
    stock, ours = pages
    assert str(BeautifulSoup(ours, features="html.parser")) == stock
    assert ours.count(f'alt="{MISSING_ALT}"') == 2  # the figure and the markdown image without alt
    assert ours.count('tabindex="0"') == stock.count('tabindex="0"') > 0


def test_accessible_adds_each_attribute_once_and_keeps_existing_ones():
    html = (
        '<div class="jp-Cell-inputWrapper"><img src="a.png"><img src="b.png" alt="b"/></div>'
        '<div class="jp-RenderedText jp-OutputArea-output" data-mime-type="text/plain">x</div>'
        '<div class="jp-OutputArea-child">y</div>'
    )
    once = accessible(html)
    assert accessible(once) == once
    assert once.count('tabindex="0"') == 2 and 'jp-OutputArea-child" tabindex' not in once
    assert f'<img src="a.png" alt="{MISSING_ALT}">' in once and '<img src="b.png" alt="b"/>' in once
