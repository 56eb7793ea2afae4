"""The replication report: one self-contained HTML page built from in-memory results.

:func:`render` is pure: it takes the scorecard frame, figures as PNG bytes, the errata frame, an
environment mapping and (optionally) the document order of the sources and the design data, and
returns HTML with every figure embedded (base64), so the page opens offline. The workflow script
``workflow/scripts/report.py`` does the reading and writing.

The parts, each in a private module: the judgement (``_verdicts``: status groups, meanings and
a paper's verdict), the headline findings (``_findings``), the parity plots (``_parity``, the
only part that needs matplotlib, imported when a plot is drawn) and the page (``_page``).

What the page holds, per paper: a verdict (:func:`verdict`, criteria in :data:`VERDICT_CRITERIA`),
headline findings written from the check records (:func:`findings`), the design data of every
example, one row per source table in the paper's order linked to its notebook heading, and a
parity plot (published against computed, with the tolerance band) for every table with computed
numbers (:func:`parity_png`; the workflow draws them per paper beforehand, :func:`parity_pngs`).

Statuses come from :data:`gearrep.checks.STATUSES`: the five comparison statuses are grouped as
agreeing, disagreeing or open; any other status (e.g. one for printed design inputs) is counted
apart from the results and never enters a verdict.
"""

from ._findings import findings, highlight
from ._page import absolute_paths, anchor, render
from ._parity import parity_png, parity_pngs, parity_rows
from ._verdicts import (
    AGREE,
    DISAGREE,
    OPEN,
    STATUS_MEANINGS,
    VERDICT_CRITERIA,
    VERDICTS,
    apart_statuses,
    ordered_sources,
    paper_verdicts,
    result_statuses,
    status_meaning,
    verdict,
)

__all__ = [
    "AGREE",
    "DISAGREE",
    "OPEN",
    "STATUS_MEANINGS",
    "VERDICTS",
    "VERDICT_CRITERIA",
    "absolute_paths",
    "anchor",
    "apart_statuses",
    "findings",
    "highlight",
    "ordered_sources",
    "paper_verdicts",
    "parity_png",
    "parity_pngs",
    "parity_rows",
    "render",
    "result_statuses",
    "status_meaning",
    "verdict",
]
