"""The report page: :func:`render` assembles the HTML of every section (summary, legend, key
figures, per paper its verdict, findings, design data, sources and parity plots, errata,
environment) with every figure embedded; :func:`anchor` and :func:`absolute_paths` serve the
notebooks' pages too."""

from __future__ import annotations

import base64
import html
import re
from collections.abc import Mapping
from urllib.parse import quote

import numpy as np
import pandas as pd

from .. import checks as _checks
from ..published import PAPER_NAMES, PAPERS
from ._findings import findings, highlight
from ._parity import parity_pngs, parity_rows
from ._verdicts import (
    _APART_COLOUR,
    _COLOURS,
    _VERDICT_COLOURS,
    AGREE,
    VERDICT_CRITERIA,
    VERDICTS,
    _checked_card,
    apart_statuses,
    ordered_sources,
    paper_verdicts,
    result_statuses,
    status_meaning,
)

__all__ = [
    "anchor",
    "absolute_paths",
    "render",
]

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2rem auto;max-width:1200px;
color:#1f2328;line-height:1.45;padding:0 1rem}
h1{font-size:1.7rem}h2{border-bottom:1px solid #d0d7de;padding-bottom:.2rem;margin-top:2.2rem}
h3{margin-top:1.4rem}
table{border-collapse:collapse;font-size:.82rem;margin:.6rem 0}
th,td{border:1px solid #d0d7de;padding:.2rem .45rem;text-align:left;vertical-align:top}
th{background:#f6f8fa}td.num{text-align:right;font-variant-numeric:tabular-nums}
.status{font-weight:600}.fig{display:inline-block;margin:.5rem;max-width:46%;vertical-align:top}
.fig img{max-width:100%;border:1px solid #d0d7de}.fig p,figcaption{font-size:.82rem;margin:.2rem 0}
figure.parity{display:inline-block;margin:.4rem;width:47%;vertical-align:top}
figure.parity img{width:100%;border:1px solid #d0d7de}
details{margin:.4rem 0}summary{cursor:pointer;font-weight:600}
.bar{display:flex;height:14px;width:260px;border:1px solid #d0d7de}.bar span{display:block;height:100%}
.verdict{font-size:1.05rem;padding:.5rem .8rem;border-left:6px solid;background:#f6f8fa;margin:.6rem 0}
.verdict b{text-transform:uppercase;letter-spacing:.03em}
ul.findings li{margin:.25rem 0}
table.design td:nth-child(3){max-width:760px}
.apart{color:#57606a}
"""


def _colour(status: str) -> str:
    return _COLOURS.get(status, _APART_COLOUR)


def _status(status: str) -> str:
    return f'<span class="status" style="color:{_colour(status)}">{html.escape(status)}</span>'


def anchor(text: str) -> str:
    """The id nbconvert gives a markdown heading (also one displayed from a code cell): spaces become
    '-', then URL quoting that keeps ?/:@!$&'()*+,;= (nbconvert.filters.strings._convert_header_id).

    Parameters
    ----------
    text : str
        The heading.

    Returns
    -------
    str
        The id.

    Examples
    --------
    >>> from gearrep.report import anchor
    >>> anchor("Table 4.3 (Sigma_2R)")
    'Table-4.3-(Sigma_2R)'
    """
    return quote(re.sub(r"\s+", " ", str(text).strip()).replace(" ", "-"), safe="?/:@!$&'()*+,;=")


#: an absolute POSIX path under a root that holds user, build or system files, not preceded by a
#: character that makes it part of a URL, a base64 blob or a word (the look-behind after the first
#: "/" lets the regex engine jump from one "/" to the next: a page of megabytes scans in milliseconds)
_POSIX = (
    r"/(?<![\w.:/~+=%-]/)(?:home|root|tmp|work|usr|opt|var|srv|mnt|media|private|Users|nix|gnu|scratch|data|builds?)"
    r"/[^\s\"'<>)]*"
)


#: the same, a Windows drive path or a file:// URL
_ABSOLUTE = re.compile(_POSIX + r"|\b[A-Za-z]:\\(?:Users|Windows|Program Files)[^\s\"'<>]*" + r"|file://[^\s\"'<>]+")


_ABSOLUTE_POSIX = re.compile(_POSIX)


def absolute_paths(text: str) -> list[str]:
    """Absolute machine paths found in ``text`` (a rendered page must show none). A text without
    ``:\\`` and ``file://`` can hold only POSIX paths, found by the fast POSIX pattern alone.

    Parameters
    ----------
    text : str
        The page.

    Returns
    -------
    list of str
        The paths found.

    Examples
    --------
    >>> from gearrep.report import absolute_paths
    >>> absolute_paths("see /home/me/x.csv, not data/published/MANIFEST.csv")
    ['/home/me/x.csv,']
    """
    if ":\\" in text or "file://" in text:
        return _ABSOLUTE.findall(text)
    return _ABSOLUTE_POSIX.findall(text)


def _fmt(v) -> str:
    if isinstance(v, float):
        if pd.isna(v):
            return ""
        return f"{v:.6g}"
    return html.escape(str(v))


def _table(
    df: pd.DataFrame,
    status_col: str | None = "status",
    links: dict | None = None,
    cls: str = "",
    raw: tuple[str, ...] = (),
) -> str:
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in df.columns)
    rows = []
    for _, r in df.iterrows():
        cells = []
        for c in df.columns:
            v = r[c]
            num = isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool)
            text = str(v) if c in raw else _fmt(v)
            if c == status_col:
                text = _status(str(v))
            if links and c in links and links[c](r):
                text = f'<a href="{html.escape(links[c](r))}">{text}</a>'
            cells.append(f"<td{' class=num' if num else ''}>{text}</td>")
        rows.append("<tr>" + "".join(cells) + "</tr>")
    klass = f' class="{cls}"' if cls else ""
    return f"<table{klass}><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"


def _bar(counts: Mapping[str, int]) -> str:
    """Bar of the result statuses (statuses that are not results, e.g. printed inputs, stay out)."""
    shown = result_statuses()
    total = max(int(sum(counts.get(s, 0) for s in shown)), 1)
    spans = "".join(
        f'<span title="{html.escape(s)}: {int(counts.get(s, 0))}" '
        f'style="width:{100 * counts.get(s, 0) / total:.2f}%;background:{_colour(s)}"></span>'
        for s in shown
    )
    return f'<div class="bar">{spans}</div>'


def _counts(grp: pd.DataFrame) -> dict[str, int]:
    vc = grp["status"].value_counts()
    return {s: int(vc.get(s, 0)) for s in _checks.STATUSES}


def _paper_findings(grp, errata, order, specs) -> list[str]:
    own = [highlight(grp, h["text"], h.get("ids"), h.get("statuses"))[1] for h in specs]
    return (own + findings(grp, errata, order))[: max(5, len(own))]


def _img(png: bytes, alt: str) -> str:
    return f"<img alt='{html.escape(alt)}' src='data:image/png;base64,{base64.b64encode(png).decode('ascii')}'>"


def _agreement_word(k: int, n: int) -> str:
    return "agrees" if k == n else ("agrees in part" if k else "does not agree")


def _paper_parity(seed: str, grp: pd.DataFrame, parity) -> dict[str, bytes]:
    """{source: PNG} of one paper: drawn here (``parity`` True), none (False), or the plots drawn
    beforehand (``parity[seed]``), which must be exactly those of :func:`parity_rows`."""
    if parity is True:
        return parity_pngs(grp)
    if not parity:
        return {}
    given = dict(parity.get(seed, {}))
    wanted = set(parity_rows(grp))
    if set(given) != wanted:
        raise ValueError(
            f"parity plots of seed {seed}: missing for sources {sorted(wanted - set(given))}, "
            f"given for sources without computed numbers {sorted(set(given) - wanted)}"
        )
    return given


def _head(card: pd.DataFrame, runtime_s: float | None, validation: bool = False) -> list[str]:
    parts = [
        "<!doctype html><html><head><meta charset='utf-8'><title>gearrep replication report</title>"
        f"<style>{_CSS}</style></head><body>",
        "<h1>gearrep replication report</h1>",
        f"<p>{len(card)} published values and claims of {card['seed'].nunique()} papers checked against our "
        "computations. Each paper below has a verdict, its headline findings, the design data it prints, "
        "one row per table in the paper's order (linked to the notebook section that computes it) and a "
        "parity plot per table with computed numbers. Contents: "
        + ", ".join(
            f"<a href='#paper-{s}'>{html.escape(PAPER_NAMES.get(s, f'seed {s}'))}</a>"
            for s in sorted(card["seed"].unique())
        )
        + ", <a href='#statuses'>statuses and verdicts</a>, <a href='#figures'>key figures</a>, "
        + ("<a href='#validation'>validation of the library</a>, " if validation else "")
        + "<a href='#errata'>errata</a>, <a href='#environment'>environment</a>.</p>",
    ]
    if runtime_s is not None:
        parts.append(f"<p>Total workflow run time (sum of job wall times): {runtime_s:.1f} s.</p>")
    return parts


def _summary(papers: Mapping[str, pd.DataFrame], verdicts: Mapping[str, tuple[str, str]]) -> list[str]:
    res_st, apart_st = result_statuses(), apart_statuses()
    head = ["seed", "name", "paper", "verdict", "agree", "", *res_st, "total"] + (
        [f"{s} (not a result)" for s in apart_st]
    )
    rows = []
    for seed, grp in papers.items():
        counts = _counts(grp)
        v = verdicts[seed][0]
        agree, scored = sum(counts[s] for s in AGREE if s in counts), sum(counts[s] for s in res_st)
        rows.append(
            f"<tr><td>{html.escape(seed)}</td><td>{html.escape(PAPER_NAMES.get(seed, ''))}</td>"
            f"<td><a href='#paper-{seed}'>{html.escape(PAPERS.get(seed, ''))}</a></td>"
            f"<td><span class='status' style='color:{_VERDICT_COLOURS.get(v, '#1f2328')}'>{v}</span></td>"
            f"<td class='num'>{agree} of {scored} ({100 * agree / max(scored, 1):.0f} %)</td>"
            f"<td>{_bar(counts)}</td>"
            + "".join(f"<td class='num'>{counts[s]}</td>" for s in res_st)
            + f"<td class='num'>{sum(counts[s] for s in res_st)}</td>"
            + "".join(f"<td class='num apart'>{counts[s]}</td>" for s in apart_st)
            + "</tr>"
        )
    return [
        "<h2 id='summary'>Summary by paper</h2>",
        "<table><thead><tr>"
        + "".join(f"<th>{html.escape(h)}</th>" for h in head)
        + f"</tr></thead><tbody>{''.join(rows)}</tbody></table>",
    ]


def _legend() -> list[str]:
    res_st, apart_st = result_statuses(), apart_statuses()
    parts = [
        "<h2 id='statuses'>Statuses and verdicts</h2>",
        "<p>Every published number and every stated claim of a paper is one row of the scorecard with one "
        "status (the vocabulary of <code>gearrep.checks</code>):</p><ul>"
        + "".join(f"<li>{_status(s)}: {html.escape(status_meaning(s))}</li>" for s in res_st)
        + "</ul>",
    ]
    if apart_st:
        parts.append(
            "<p>Not results (counted apart, never in a verdict):</p><ul>"
            + "".join(f"<li>{_status(s)}: {html.escape(status_meaning(s))}</li>" for s in apart_st)
            + "</ul>"
        )
    parts.append(
        "<p>Verdict of a paper, in the manner of ReScience C (over the rows with a result status):</p><ul>"
        + "".join(
            f"<li><b style='color:{_VERDICT_COLOURS[v]}'>{v}</b>: {html.escape(VERDICT_CRITERIA[v])}</li>"
            for v in VERDICTS
        )
        + "</ul><p>The verdict is strict on purpose; the share that agrees and the findings say how much of "
        "a paper stands.</p>"
    )
    return parts


def _key_figures(figures: Mapping[str, bytes]) -> list[str]:
    parts = ["<h2 id='figures'>Key figures</h2>"]
    if figures:
        for caption, png in figures.items():
            parts.append(f"<div class='fig'>{_img(png, caption)}<p>{html.escape(caption)}</p></div>")
    else:
        parts.append("<p>No key figures.</p>")
    return parts


def _paper_head(seed, grp, verdict_, notebooks, errata, order, specs) -> list[str]:
    """Heading, verdict, notebook links and headline findings of one paper."""
    v, why = verdict_
    colour = _VERDICT_COLOURS.get(v, "#57606a")
    parts = [
        f"<h2 id='paper-{seed}'>{html.escape(PAPER_NAMES.get(seed, ''))} (seed {seed}): "
        f"{html.escape(PAPERS.get(seed, ''))}</h2>",
        f"<div class='verdict' id='verdict-{seed}' style='border-color:{colour}'>"
        f"Verdict: <b style='color:{colour}'>{v}</b>. {html.escape(why)}</div>",
    ]
    reps = sorted({r for r in grp["replication"] if r})
    if reps:
        parts.append(
            "<p>Notebooks: "
            + ", ".join(
                f"<a href='{html.escape(notebooks[r])}'>{html.escape(r)}</a>" if r in notebooks else html.escape(r)
                for r in reps
            )
            + "</p>"
        )
    er = errata[errata["seed"] == seed] if "seed" in errata.columns else errata.iloc[:0]
    parts.append(
        f"<h3 id='findings-{seed}'>Headline findings</h3><ul class='findings'>"
        + "".join(f"<li>{f}</li>" for f in _paper_findings(grp, er, order, specs))
        + "</ul>"
    )
    return parts


def _design_section(seed: str, design: pd.DataFrame | None) -> list[str]:
    if design is None:
        return []
    d = design[design["seed"] == seed]
    parts = [f"<h3 id='design-{seed}'>Design data of the examples (as printed)</h3>"]
    if len(d):
        parts.append(
            f"<p>{len(d)} examples, parameters exactly as printed (<code>data/published/params_{seed}_*.csv"
            "</code>; the line is that of the seed text).</p>"
            + _table(d[["example", "source", "design"]], status_col=None, cls=f"design design-{seed}")
        )
    else:
        parts.append("<p>The paper prints no design data we use.</p>")
    return parts


def _parity_figure(pid: str, src: str, rows: pd.DataFrame, png: bytes) -> str:
    comp = rows[rows["computed"].notna()]
    k = int((comp["status"] == "reproduced").sum())
    cap = (
        f"{src}: computed against published for {len(comp)} printed numbers (left; the band is each "
        f"value's tolerance from its printed precision) and the error in tolerances (right; inside "
        f"the band means reproduced). {k} of {len(comp)} within tolerance: the table "
        f"{_agreement_word(k, len(comp))}."
    )
    return (
        f"<figure class='parity' id='{pid}' data-source='{html.escape(src)}'>{_img(png, 'parity plot: ' + src)}"
        f"<figcaption>{html.escape(cap)}</figcaption></figure>"
    )


def _sources_section(seed, grp, srcs, notebooks, pngs: Mapping[str, bytes]) -> list[str]:
    """The table of a paper's sources in document order (counts, notebook link, parity link) and
    its parity plots."""
    res_st, apart_st = result_statuses(), apart_statuses()
    plotted = parity_rows(grp) if pngs else {}
    plots, trows = [], []
    for k, (_, src) in enumerate(srcs):
        g = grp[grp["source"] == src]
        counts = _counts(g)
        rep = next((r for r in g["replication"] if r), "")
        link = f"{notebooks[rep]}#{anchor(src)}" if rep in notebooks else ""
        name = f"<a href='{html.escape(link)}'>{html.escape(src)}</a>" if link else html.escape(src)
        pid = f"parity-{seed}-{k}"
        plot_cell = ""
        if src in plotted:
            plots.append(_parity_figure(pid, src, plotted[src], pngs[src]))
            plot_cell = f"<a href='#{pid}'>plot</a>"
        trows.append(
            "<tr>"
            + f"<td>{name}</td><td>{html.escape(rep)}</td><td>{_bar(counts)}</td>"
            + "".join(f"<td class='num'>{counts[s]}</td>" for s in res_st)
            + "".join(f"<td class='num apart'>{counts[s]}</td>" for s in apart_st)
            + f"<td class='num'>{len(g)}</td><td>{plot_cell}</td></tr>"
        )
    th = ["source (link: notebook section)", "replication", "", *res_st]
    th += [f"{s} (not a result)" for s in apart_st] + ["total", "parity"]
    parts = [
        f"<h3 id='tables-{seed}'>Tables and sources, in the paper's order</h3>",
        f"<table class='sources' id='sources-{seed}'><thead><tr>"
        + "".join(f"<th>{html.escape(h)}</th>" for h in th)
        + f"</tr></thead><tbody>{''.join(trows)}</tbody></table>",
    ]
    if plots:
        parts.append(f"<h3 id='parity-{seed}'>Parity plots: published against computed, per table</h3>")
        parts.append("".join(plots))
    return parts


def _all_rows(grp, srcs, notebooks) -> str:
    """Every scorecard row of a paper, folded, in document order of the sources."""
    cols = ["id", "source", "row", "quantity", "unit", "published", "computed", "abs_err", "tolerance", "status"]
    cols += ["note", "replication"]
    rank = {s: i for i, (_, s) in enumerate(srcs)}
    allrows = grp.assign(_r=grp["source"].map(rank)).sort_values(["_r", "id"], kind="stable")[cols]

    def link(r, _nb=notebooks):
        rep = r.get("replication", "")
        return f"{_nb[rep]}#{anchor(r['source'])}" if rep in _nb else ""

    return f"<details><summary>All {len(grp)} rows</summary>" + _table(allrows, links={"source": link}) + "</details>"


def _errata_and_environment(errata: pd.DataFrame, environment: Mapping) -> list[str]:
    parts = ["<h2 id='errata'>Errata found in the papers</h2>"]
    if len(errata):
        parts.append(_table(errata, status_col=None))
    else:
        parts.append("<p>None recorded yet.</p>")
    parts.append("<h2 id='environment'>Environment</h2>")
    env = pd.DataFrame({"item": list(environment), "value": [str(v) for v in environment.values()]})
    parts.append(_table(env, status_col=None))
    parts.append("</body></html>")
    return parts


def render(
    card: pd.DataFrame,
    figures: dict[str, bytes],
    errata: pd.DataFrame,
    environment: dict,
    notebooks: dict[str, str] | None = None,
    runtime_s: float | None = None,
    *,
    order: Mapping[tuple[str, str], int] | None = None,
    design: pd.DataFrame | None = None,
    parity: bool | Mapping[str, Mapping[str, bytes]] = True,
    highlights: Mapping[str, list] | None = None,
) -> str:
    """HTML of the report.

    Parameters
    ----------
    card : pandas.DataFrame
        The scorecard (columns of gearrep.checks.scorecard plus ``replication``).
    figures : dict
        {caption: PNG bytes}, embedded in order (the caption says what the figure shows and
        whether it agrees).
    errata : pandas.DataFrame
        Columns seed, location, printed, correction, evidence (None: no errata).
    environment : dict
        {name: value} (versions, git commit, config hash).
    notebooks : dict, optional
        {replication: relative href of its rendered notebook}.
    runtime_s : float, optional
        Total workflow run time [s] (sum of the jobs' benchmarks).
    order : mapping, optional
        {(seed, source): line of the seed text}, the paper's order of its tables
        (gearrep.published.document_order); without it sources sort as strings.
    design : pandas.DataFrame, optional
        gearrep.published.design_table of every paper (one row per example).
    parity : bool or mapping, optional
        The parity plot of every source with computed numbers: True draws them here, False leaves
        them out, and {seed: {source: PNG}} embeds plots drawn beforehand by :func:`parity_pngs`
        (exactly one per source of :func:`parity_rows`, else ValueError).
    highlights : mapping, optional
        {seed: [{"text", "ids", "statuses"}, ...]}, hand-written headline findings, each checked
        against its records by :func:`highlight`; the findings of a paper are these followed by
        :func:`findings`, five at most.

    Returns
    -------
    str
        The page.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import absolute_paths, render
    >>> card = pd.DataFrame(
    ...     {
    ...         "seed": ["000"] * 2,
    ...         "source": ["Table 4.3"] * 2,
    ...         "id": ["000-a", "000-b"],
    ...         "status": ["reproduced", "deviates"],
    ...         "published": [1.0, 3.0],
    ...         "computed": [1.0, 3.5],
    ...     }
    ... )
    >>> page = render(card, {}, None, {"python": "3.11"}, parity=False)
    >>> page.startswith("<!doctype html>"), "partially reproduced" in page, absolute_paths(page)
    (True, True, [])
    """
    card = _checked_card(card)
    notebooks = notebooks or {}
    errata = errata if errata is not None else pd.DataFrame(columns=["seed", "location"])
    validation = card[card["seed"] == _checks.VALIDATION]
    card = card[card["seed"] != _checks.VALIDATION]
    papers = dict(list(card.groupby("seed", sort=True)))
    verdicts = paper_verdicts(card)
    parts = _head(card, runtime_s, len(validation) > 0) + _summary(papers, verdicts) + _legend() + _key_figures(figures)
    for seed, grp in papers.items():
        srcs = ordered_sources(grp, order)
        specs = (highlights or {}).get(seed, [])
        parts += _paper_head(seed, grp, verdicts[seed], notebooks, errata, order, specs)
        parts += _design_section(seed, design)
        parts += _sources_section(seed, grp, srcs, notebooks, _paper_parity(seed, grp, parity))
        parts.append(_all_rows(grp, srcs, notebooks))
    parts += _validation_section(validation, notebooks)
    return "\n".join(parts + _errata_and_environment(errata, environment))


def _validation_section(rows: pd.DataFrame, notebooks) -> list[str]:
    """The validation studies' records: no paper, no verdict; a table per source and every row."""
    if rows.empty:
        return []
    srcs = [(_checks.VALIDATION, s) for s in dict.fromkeys(rows["source"])]
    counts = _counts(rows)
    agree = sum(counts[s] for s in AGREE)
    parts = [
        "<h2 id='validation'>Validation of the library (not a paper)</h2>",
        f"<p>{len(rows)} checks of gearrep's own models against closed forms, exact properties and limits "
        "(no printed number of a paper: no verdict, and the papers' counts above leave them out). Each row's "
        f"tolerance basis states its reason. {agree} of {len(rows)} agree.</p>",
    ]
    parts += _sources_section(_checks.VALIDATION, rows, srcs, notebooks, {})[:2]
    parts.append(_all_rows(rows, srcs, notebooks))
    return parts
