"""The replication report: one self-contained HTML page built from in-memory results.

:func:`render` is pure: it takes the scorecard frame, figures as PNG bytes, the errata frame and
an environment mapping, and returns HTML with the figures embedded (base64), so the page opens
offline. The workflow script ``workflow/scripts/report.py`` does the reading and writing.
"""

from __future__ import annotations

import base64
import html
import re
from urllib.parse import quote

import pandas as pd

from .checks import INPUT_STATUSES, RESULT_STATUSES, STATUSES, summary
from .published import PAPERS

__all__ = [
    "anchor",
    "render",
]

_STATUS_COLOURS = {
    "reproduced": "#1a7f37",
    "deviates": "#cf222e",
    "qualitative-holds": "#1a7f37",
    "qualitative-fails": "#cf222e",
    "not-computed": "#6e7781",
    "input": "#0969da",
}

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2rem auto;max-width:1200px;
color:#1f2328;line-height:1.45;padding:0 1rem}
h1{font-size:1.7rem}h2{border-bottom:1px solid #d0d7de;padding-bottom:.2rem;margin-top:2rem}
table{border-collapse:collapse;font-size:.82rem;margin:.6rem 0}
th,td{border:1px solid #d0d7de;padding:.2rem .45rem;text-align:left;vertical-align:top}
th{background:#f6f8fa}td.num{text-align:right;font-variant-numeric:tabular-nums}
.status{font-weight:600}.fig{display:inline-block;margin:.5rem;max-width:46%}
.fig img{max-width:100%;border:1px solid #d0d7de}.fig p{font-size:.8rem;margin:.2rem 0}
details{margin:.4rem 0}summary{cursor:pointer;font-weight:600}
.bar{display:flex;height:14px;width:320px;border:1px solid #d0d7de}.bar span{display:block;height:100%}
"""


def anchor(text: str) -> str:
    """The id nbconvert gives a markdown heading (also one displayed from a code cell): spaces become
    '-', then URL quoting that keeps ?/:@!$&'()*+,;= (nbconvert.filters.strings._convert_header_id)."""
    return quote(re.sub(r"\s+", " ", str(text).strip()).replace(" ", "-"), safe="?/:@!$&'()*+,;=")


def _fmt(v) -> str:
    if isinstance(v, float):
        if pd.isna(v):
            return ""
        return f"{v:.6g}"
    return html.escape(str(v))


def _table(df: pd.DataFrame, status_col: str | None = "status", links: dict | None = None) -> str:
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in df.columns)
    rows = []
    for _, r in df.iterrows():
        cells = []
        for c in df.columns:
            v = r[c]
            cls = ' class="num"' if isinstance(v, (int, float)) and not isinstance(v, bool) else ""
            text = _fmt(v)
            if c == status_col:
                col = _STATUS_COLOURS.get(str(v), "#1f2328")
                text = f'<span class="status" style="color:{col}">{text}</span>'
            if links and c in links and links[c](r):
                text = f'<a href="{html.escape(links[c](r))}">{text}</a>'
            cells.append(f"<td{cls}>{text}</td>")
        rows.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"


def _bar(counts: pd.Series) -> str:
    """Bar of the result statuses (printed inputs are not results: not in the bar)."""
    total = max(int(counts[list(RESULT_STATUSES)].sum()), 1)
    spans = "".join(
        f'<span title="{s}: {int(counts.get(s, 0))}" style="width:{100 * counts.get(s, 0) / total:.2f}%;'
        f'background:{_STATUS_COLOURS[s]}{"" if s in ("reproduced", "deviates", "not-computed") else "99"}"></span>'
        for s in RESULT_STATUSES
    )
    return f'<div class="bar">{spans}</div>'


def render(
    card: pd.DataFrame,
    figures: dict[str, bytes],
    errata: pd.DataFrame,
    environment: dict,
    notebooks: dict[str, str] | None = None,
    runtime_s: float | None = None,
) -> str:
    """HTML of the report.

    card : the scorecard (columns of gearrep.checks.scorecard plus ``replication``)
    figures : {caption: PNG bytes}, embedded in order
    errata : columns seed, location, printed, correction, evidence
    environment : {name: value} (versions, git commit, config hash)
    notebooks : {replication: relative href of its rendered notebook}
    runtime_s : total workflow run time in seconds (sum of the jobs' benchmarks)
    """
    if "status" not in card.columns or "seed" not in card.columns:
        raise ValueError("scorecard needs 'seed' and 'status' columns")
    notebooks = notebooks or {}
    parts = [
        f"<!doctype html><html><head><meta charset='utf-8'><title>gearrep replication report</title>"
        f"<style>{_CSS}</style></head><body>",
        "<h1>gearrep replication report</h1>",
        f"<p>{len(card)} published values and claims checked against our computations. "
        "Status legend: "
        + ", ".join(f'<span class="status" style="color:{_STATUS_COLOURS[s]}">{s}</span>' for s in RESULT_STATUSES)
        + "; printed design inputs, used as printed and counted apart from the results: "
        + ", ".join(f'<span class="status" style="color:{_STATUS_COLOURS[s]}">{s}</span>' for s in INPUT_STATUSES)
        + ".</p>",
    ]
    if runtime_s is not None:
        parts.append(f"<p>Total workflow run time (sum of job wall times): {runtime_s:.1f} s.</p>")

    parts.append("<h2 id='summary'>Summary by paper</h2>")
    by = summary(card, by=("seed",))
    by.insert(1, "paper", by["seed"].map(PAPERS))
    rows = []
    for _, r in by.iterrows():
        counts = pd.Series({s: r[s] for s in STATUSES})
        rows.append(
            f"<tr><td>{r['seed']}</td><td><a href='#paper-{r['seed']}'>{html.escape(str(r['paper']))}</a>"
            f"</td><td>{_bar(counts)}</td>"
            + "".join(f"<td class='num'>{int(r[s])}</td>" for s in (*RESULT_STATUSES, "results", *INPUT_STATUSES))
            + f"<td class='num'>{int(r['total'])}</td></tr>"
        )
    head = "".join(
        f"<th>{h}</th>" for h in ["seed", "paper", "", *RESULT_STATUSES, "results", *INPUT_STATUSES, "total"]
    )
    parts.append(f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>")

    if figures:
        parts.append("<h2 id='figures'>Key figures</h2>")
        for caption, png in figures.items():
            b64 = base64.b64encode(png).decode("ascii")
            parts.append(
                f"<div class='fig'><img alt='{html.escape(caption)}' src='data:image/png;base64,{b64}'>"
                f"<p>{html.escape(caption)}</p></div>"
            )

    for seed, grp in card.groupby("seed", sort=True):
        parts.append(f"<h2 id='paper-{seed}'>Seed {seed}: {html.escape(PAPERS.get(seed, ''))}</h2>")
        reps = sorted({r for r in grp.get("replication", pd.Series(dtype=str)).fillna("") if r})
        if reps:
            parts.append(
                "<p>Notebooks: "
                + ", ".join(
                    f"<a href='{html.escape(notebooks[r])}'>{html.escape(r)}</a>" if r in notebooks else html.escape(r)
                    for r in reps
                )
                + "</p>"
            )
        by_src = summary(grp, by=("source",))
        parts.append(_table(by_src, status_col=None))
        cols = [
            c
            for c in [
                "id",
                "source",
                "row",
                "quantity",
                "unit",
                "published",
                "computed",
                "abs_err",
                "tolerance",
                "status",
                "note",
            ]
            if c in grp.columns
        ]

        def link(r, _nb=notebooks):
            rep = r.get("replication", "")
            return f"{_nb[rep]}#{anchor(r['source'])}" if rep in _nb else ""

        parts.append(
            f"<details><summary>All {len(grp)} rows</summary>"
            + _table(
                grp.assign(replication=grp.get("replication", ""))[cols + ["replication"]]
                if "replication" in grp.columns
                else grp[cols],
                links={"source": link},
            )
            + "</details>"
        )

    parts.append("<h2 id='errata'>Errata found in the papers</h2>")
    if len(errata):
        parts.append(_table(errata, status_col=None))
    else:
        parts.append("<p>None recorded yet.</p>")

    parts.append("<h2 id='environment'>Environment</h2>")
    env = pd.DataFrame({"item": list(environment), "value": [str(v) for v in environment.values()]})
    parts.append(_table(env, status_col=None))
    parts.append("</body></html>")
    return "\n".join(parts)
