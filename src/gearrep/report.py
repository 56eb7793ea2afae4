"""The replication report: one self-contained HTML page built from in-memory results.

:func:`render` is pure: it takes the scorecard frame, figures as PNG bytes, the errata frame, an
environment mapping and (optionally) the document order of the sources and the design data, and
returns HTML with every figure embedded (base64), so the page opens offline. The workflow script
``workflow/scripts/report.py`` does the reading and writing.

What the page holds, per paper: a verdict (:func:`verdict`, criteria in :data:`VERDICT_CRITERIA`),
headline findings written from the check records (:func:`findings`), the design data of every
example, one row per source table in the paper's order linked to its notebook heading, and a
parity plot (published against computed, with the tolerance band) for every table with computed
numbers (:func:`parity_png`; the workflow draws them per paper beforehand, :func:`parity_pngs`).

Statuses come from :data:`gearrep.checks.STATUSES`: the five comparison statuses are grouped as
agreeing, disagreeing or open; any other status (e.g. one for printed design inputs) is counted
apart from the results and never enters a verdict.
"""

from __future__ import annotations

import base64
import contextlib
import fnmatch
import html
import io
import re
from collections.abc import Mapping
from urllib.parse import quote

import numpy as np
import pandas as pd

from . import checks as _checks
from .published import PAPERS

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

#: statuses that mean the paper's number or statement is confirmed by our computation
AGREE = ("reproduced", "qualitative-holds")
#: statuses that mean our computation contradicts the paper's number or statement
DISAGREE = ("deviates", "qualitative-fails")
#: statuses that mean no comparison was made
OPEN = ("not-computed",)

STATUS_MEANINGS = {
    "reproduced": "a printed number that our computation gives at the precision the paper printed it: the "
    "computed value, rounded (or truncated, where the paper truncates) to the printed digits, is the printed "
    "number. The tolerance is derived from the printed string by gearrep.checks (half a unit of the last "
    "printed digit), widened only by a stated physical reason shown in the row's tolerance basis; it is never "
    "chosen to make a check pass.",
    "deviates": "a printed number that our computation does not give within that tolerance (or for which it "
    "returns no finite value); the row's note gives our best explanation.",
    "qualitative-holds": "a statement of the paper (a trend, or a number stated only loosely) whose "
    "confirmation criterion, written in data/published/claims_*.csv before computing, is met; the note "
    "gives the numbers behind the verdict.",
    "qualitative-fails": "a statement whose confirmation criterion is not met; the note gives the numbers.",
    "not-computed": "a printed number or statement that no computation of ours addresses; the note says why "
    "(outside gearrep's scope, or data the paper does not give).",
    "input": "a printed number that is not a comparison of a computed result with a published one: a design "
    "input of the paper (a crowning amount the author chose, a rack-cutter radius from earlier work) or the one "
    "calibration input of a parameter the paper does not print; used as printed (the note says where), "
    "counted apart from the results, never in a verdict.",
}

VERDICTS = ("reproduced", "partially reproduced", "not reproduced")
#: the verdict criteria, stated on the page
VERDICT_CRITERIA = {
    "reproduced": "every published number and statement of the paper that we score agrees "
    "(reproduced or qualitative-holds): nothing deviates, fails or is left not computed.",
    "partially reproduced": "at least one published number or statement agrees, and at least one deviates, "
    "fails or is not computed.",
    "not reproduced": "none agrees: everything scored deviates, fails or is not computed.",
}

_COLOURS = {
    "reproduced": "#1a7f37",
    "deviates": "#cf222e",
    "qualitative-holds": "#4ac26b",
    "qualitative-fails": "#ff8182",
    "not-computed": "#8c959f",
}
_APART_COLOUR = "#8250df"
_VERDICT_COLOURS = {"reproduced": "#1a7f37", "partially reproduced": "#9a6700", "not reproduced": "#cf222e"}

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


# ----------------------------------------------------------------------------- vocabulary


def result_statuses() -> tuple[str, ...]:
    """The statuses of gearrep.checks that are comparison results (agree, disagree or open)."""
    return tuple(s for s in _checks.STATUSES if s in AGREE + DISAGREE + OPEN)


def apart_statuses() -> tuple[str, ...]:
    """Statuses of gearrep.checks that are not comparison results (shown apart, never in a verdict)."""
    return tuple(s for s in _checks.STATUSES if s not in AGREE + DISAGREE + OPEN)


def status_meaning(status: str) -> str:
    """What a status means, for the legend; a status unknown here is described as not a result."""
    if status in STATUS_MEANINGS:
        return STATUS_MEANINGS[status]
    if status not in _checks.STATUSES:
        raise ValueError(f"status={status!r} is not one of gearrep.checks.STATUSES {_checks.STATUSES}")
    return (
        "a record that is not a comparison of a computed result with a published one (for example a "
        "design input the paper prints and we use as given); counted apart from the results, never in a verdict."
    )


def _colour(status: str) -> str:
    return _COLOURS.get(status, _APART_COLOUR)


def _status(status: str) -> str:
    return f'<span class="status" style="color:{_colour(status)}">{html.escape(status)}</span>'


# ----------------------------------------------------------------------------- small helpers


def anchor(text: str) -> str:
    """The id nbconvert gives a markdown heading (also one displayed from a code cell): spaces become
    '-', then URL quoting that keeps ?/:@!$&'()*+,;= (nbconvert.filters.strings._convert_header_id)."""
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
    ``:\\`` and ``file://`` can hold only POSIX paths, found by the fast POSIX pattern alone."""
    if ":\\" in text or "file://" in text:
        return _ABSOLUTE.findall(text)
    return _ABSOLUTE_POSIX.findall(text)


def _fmt(v) -> str:
    if isinstance(v, float):
        if pd.isna(v):
            return ""
        return f"{v:.6g}"
    return html.escape(str(v))


def _short(text: str, n: int = 240) -> str:
    text = re.sub(r"\s+", " ", str(text)).strip()
    return text if len(text) <= n else text[: n - 1].rsplit(" ", 1)[0] + " …"


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


# ----------------------------------------------------------------------------- order, verdict, findings


def ordered_sources(card: pd.DataFrame, order: Mapping[tuple[str, str], int] | None = None) -> list[tuple[str, str]]:
    """(seed, source) pairs of ``card`` in document order: by seed, then by the line where the paper
    prints the source (``order``, from :func:`gearrep.published.document_order`); sources without
    a line come last, in string order."""
    order = order or {}
    pairs = list(dict.fromkeys(zip(card["seed"], card["source"])))
    big = 10**9
    return sorted(pairs, key=lambda p: (p[0], order.get(p, big), p[1]))


def verdict(grp: pd.DataFrame) -> tuple[str, str]:
    """(verdict, one-line reason) of one paper's scorecard rows by :data:`VERDICT_CRITERIA`.

    Only result statuses count (:func:`result_statuses`); rows of any other status are left out."""
    res = grp[grp["status"].isin(result_statuses())]
    if res.empty:
        raise ValueError("verdict needs at least one scorecard row with a result status")
    n = len(res)
    agree = int(res["status"].isin(AGREE).sum())
    disagree = int(res["status"].isin(DISAGREE).sum())
    open_ = int(res["status"].isin(OPEN).sum())
    if agree == n:
        v = "reproduced"
    elif agree > 0:
        v = "partially reproduced"
    else:
        v = "not reproduced"
    values = res[res["published"].notna()] if "published" in res.columns else res.iloc[:0]
    claims = res.drop(values.index)
    why = (
        f"{agree} of {n} scored items agree ({100 * agree / n:.0f} %): "
        f"{int((values['status'] == 'reproduced').sum())} of {len(values)} printed numbers reproduced, "
        f"{int((claims['status'] == 'qualitative-holds').sum())} of {len(claims)} statements hold; "
        f"{disagree} deviate or fail, {open_} not computed."
    )
    return v, why


def paper_verdicts(card: pd.DataFrame) -> dict[str, tuple[str, str]]:
    """{seed: (verdict, one-line reason)} of every paper of the scorecard, in seed order ("no
    results" for a paper without a row of a result status); the validation studies' rows (seed
    :data:`gearrep.checks.VALIDATION`) are no paper and have no verdict."""
    card = _checked_card(card)
    card = card[card["seed"] != _checks.VALIDATION]
    return {
        seed: verdict(grp) if grp["status"].isin(result_statuses()).any() else ("no results", "")
        for seed, grp in card.groupby("seed", sort=True)
    }


def _group_notes(rows: pd.DataFrame, n: int = 2, width: int = 230) -> list[tuple[int, str]]:
    """The most frequent explanations among ``rows`` (grouped on the note's first 60 characters)."""
    notes = rows["note"].fillna("").astype(str).str.strip()
    key = notes.str[:60]
    out = []
    for k, cnt in key.value_counts().head(n).items():
        out.append((int(cnt), _short(notes[key == k].iloc[0], width)))
    return out


def findings(
    grp: pd.DataFrame, errata: pd.DataFrame | None = None, order: Mapping[tuple[str, str], int] | None = None
) -> list[str]:
    """Three to five headline findings of one paper, written from its check records (HTML strings).

    1. where the printed numbers deviate, the largest groups and their recorded explanation;
    2. what is not computed and why (the most frequent reasons);
    3. the errata we found in the paper (``errata``: rows of data/errata.csv for this paper);
    4. what is reproduced in full, table by table, in the paper's order;
    5. the statements that hold and those that fail.
    """
    res = grp[grp["status"].isin(result_statuses())]
    out = []
    dev = res[res["status"] == "deviates"]
    if len(dev):
        worst = dev["source"].value_counts().head(3)
        where = ", ".join(f"{html.escape(s)} ({c})" for s, c in worst.items())
        expl = "; ".join(f"{c} of them: {html.escape(t)}" for c, t in _group_notes(dev))
        n = f"{len(dev)} printed number{'s deviate' if len(dev) > 1 else ' deviates'}"
        out.append(f"<b>{n}</b>, most in {where}. Recorded explanations: {expl}")

    nc = res[res["status"].isin(OPEN)]
    if len(nc):
        reasons = "; ".join(f"{c}: {html.escape(t)}" for c, t in _group_notes(nc, n=3, width=200))
        out.append(f"<b>{len(nc)} item{'s' if len(nc) > 1 else ''} not computed</b>. Why: {reasons}")

    if errata is not None and len(errata):
        locs = ", ".join(html.escape(str(x)) for x in errata["location"])
        out.append(
            f"<b>{len(errata)} errata in the paper</b> found and corrected, each with its evidence "
            f"(<a href='#errata'>Errata</a>): {locs}."
        )
    by_src = []
    for key in ordered_sources(res, order):
        g = res[res["source"] == key[1]]
        nums = g[g["published"].notna()]
        if len(nums):
            by_src.append((key[1], int((nums["status"] == "reproduced").sum()), len(nums)))
    full = [f"{html.escape(s)} ({k} of {n})" for s, k, n in by_src if k == n]
    part = [f"{html.escape(s)} ({k} of {n})" for s, k, n in by_src if 0 < k < n]
    if full or part:
        text = "<b>Reproduced within printed precision</b>: "
        text += ("in full: " + "; ".join(full)) if full else "no table in full"
        text += ("; in part: " + "; ".join(part)) if part else ""
        out.append(text + ".")
    elif by_src:
        out.append("<b>No printed number is reproduced</b> within its printed precision.")
    else:
        out.append("<b>The paper prints no numbers we compare</b>: every check is a stated trend or claim.")

    cl = res[res["status"].isin(("qualitative-holds", "qualitative-fails"))]
    if len(cl):
        fails = cl[cl["status"] == "qualitative-fails"]
        text = f"<b>{int((cl['status'] == 'qualitative-holds').sum())} of {len(cl)} stated trends and claims hold</b>"
        if len(fails):
            items = "; ".join(
                f"<code>{html.escape(str(r['id']))}</code> ({html.escape(_short(r['note'], 150))})"
                for _, r in fails.head(3).iterrows()
            )
            more = f" and {len(fails) - 3} more" if len(fails) > 3 else ""
            text += f"; failing: {items}{more}"
        out.append(text + ".")

    return out[:5]


def highlight(card: pd.DataFrame, text: str, ids, statuses) -> tuple[bool, str]:
    """A hand-written headline finding checked against the records it rests on.

    ``ids``: check ids or fnmatch patterns (``000-T5.4-*-KE``); ``statuses``: the statuses the
    finding claims for all of them. Returns (supported, HTML): the text with the evidence
    ("12 records, all reproduced"), or, when a record is missing or now has another status, the
    text struck through and the records that no longer support it, so a finding can never
    outlive its evidence silently."""
    ids, statuses = list(ids or []), set(statuses or [])
    if not ids or not statuses:
        raise ValueError(f"highlight {text[:40]!r}: needs ids and statuses (got ids={ids}, statuses={statuses})")
    unknown = sorted(statuses - set(_checks.STATUSES))
    if unknown:
        raise ValueError(f"highlight {text[:40]!r}: statuses {unknown} not in gearrep.checks.STATUSES")
    all_ids = card["id"].astype(str)
    hit = pd.Series(False, index=card.index)
    empty = []
    for pat in ids:
        m = all_ids.map(lambda i, _p=pat: fnmatch.fnmatchcase(i, _p))
        if not m.any():
            empty.append(pat)
        hit |= m
    rows = card[hit]
    wrong = rows[~rows["status"].isin(statuses)]
    if empty or len(wrong):
        why = [f"no record {html.escape(p)}" for p in empty]
        why += [f"{html.escape(str(r['id']))}: {html.escape(str(r['status']))}" for _, r in wrong.head(5).iterrows()]
        return False, (
            f"<s>{html.escape(text)}</s> <span class='status' style='color:{_COLOURS['deviates']}'>"
            f"(the check records no longer support this: {'; '.join(why)})</span>"
        )
    st = " or ".join(sorted(set(rows["status"])))
    return True, f"{html.escape(text)} <span class='apart'>(check records: {len(rows)}, all {st})</span>"


# ----------------------------------------------------------------------------- parity plot


def parity_png(rows: pd.DataFrame, title: str) -> bytes:
    """PNG of a parity plot of one source table: left, computed against published with the line of
    equality and each value's tolerance as a band around it; right, (computed - published) /
    tolerance per value in table order, with the band |.| <= 1 that means "reproduced".

    ``rows``: scorecard rows with ``published``, ``computed``, ``tolerance``, ``status``,
    ``quantity``; rows without a finite computed value are left out (and counted in the title)."""
    plotted = _parity_plotted(rows, title)  # bad rows are refused before a figure is made
    with _parity_canvas() as fig:
        return _draw_parity(fig, rows, plotted, title)


@contextlib.contextmanager
def _parity_canvas():
    """The figure parity plots are drawn on (cleared for each): one figure, hence one Agg renderer
    and its parsed math text (the symlog axis's tick labels, e.g. 10^3), for all plots of a paper.
    matplotlib keeps the parses per renderer, i.e. per figure: with a figure per plot, seed 003's 11
    plots parsed 84 labels (about 6 ms each), 15 of them distinct; now 15."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(8.4, 3.3), dpi=72)
    try:
        yield fig
    finally:
        plt.close(fig)


def _parity_plotted(rows: pd.DataFrame, title: str) -> pd.DataFrame:
    """The rows of a parity plot with both a published and a computed value (ValueError naming the
    missing columns, or the plot without such a row)."""
    missing = [c for c in ("published", "computed", "tolerance", "status", "quantity") if c not in rows.columns]
    if missing:
        raise ValueError(f"parity rows lack columns {missing}")
    r = rows[np.isfinite(rows["published"].astype(float)) & np.isfinite(rows["computed"].astype(float))]
    if r.empty:
        raise ValueError(f"{title}: no row with both a published and a computed value")
    return r


def _draw_parity(fig, rows: pd.DataFrame, r: pd.DataFrame, title: str) -> bytes:
    """:func:`parity_png` of ``rows`` drawn on ``fig`` (cleared first); ``r``: its plotted rows
    (:func:`_parity_plotted`)."""
    p = r["published"].astype(float).to_numpy()
    c = r["computed"].astype(float).to_numpy()
    tol = r["tolerance"].astype(float).fillna(0.0).to_numpy()
    ok = (r["status"] == "reproduced").to_numpy()
    fig.clear()
    a1, a2 = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.35]})
    lo, hi = float(min(p.min(), c.min())), float(max(p.max(), c.max()))
    pad = 0.05 * (hi - lo or abs(hi) or 1.0)
    xs = np.linspace(lo - pad, hi + pad, 2)
    a1.plot(xs, xs, color="#57606a", lw=0.8, label="computed = published")
    order = np.argsort(p)
    a1.fill_between(p[order], p[order] - tol[order], p[order] + tol[order], color="#1a7f37", alpha=0.25, lw=0)
    a1.scatter(p[ok], c[ok], s=14, color=_COLOURS["reproduced"], label="reproduced", zorder=3)
    a1.scatter(p[~ok], c[~ok], s=16, marker="x", color=_COLOURS["deviates"], label="deviates", zorder=3)
    a1.set_xlabel("published [table units]")
    a1.set_ylabel("computed [table units]")
    a1.legend(fontsize=7, frameon=False, loc="upper left")
    # a zero tolerance (none printed) puts any difference far outside the band
    z = np.clip((c - p) / np.where(tol > 0, tol, 1e-300), -1e6, 1e6)
    idx = np.arange(len(z))
    a2.axhspan(-1, 1, color="#1a7f37", alpha=0.2, lw=0, label="within tolerance")
    a2.scatter(idx[ok], z[ok], s=12, color=_COLOURS["reproduced"], zorder=3)
    a2.scatter(idx[~ok], z[~ok], s=14, marker="x", color=_COLOURS["deviates"], zorder=3)
    a2.set_yscale("symlog", linthresh=1.0)
    a2.set_xlabel("value in table order [-]")
    a2.set_ylabel("(computed - published) / tolerance [-]")
    a2.legend(fontsize=7, frameon=False, loc="upper right")
    for ax in (a1, a2):
        ax.grid(alpha=0.3)
    left = len(rows) - len(r)
    fig.suptitle(
        f"{title}: {int(ok.sum())} of {len(r)} within tolerance" + (f" ({left} not computed)" if left else ""),
        fontsize=9,
    )
    fig.subplots_adjust(left=0.09, right=0.99, bottom=0.15, top=0.88, wspace=0.3)
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


def parity_rows(grp: pd.DataFrame) -> dict[str, pd.DataFrame]:
    """{source: rows} of one paper's scorecard rows for every source that gets a parity plot: the
    source's printed numbers with a result status (printed inputs are not results), for the sources
    where at least one of them is computed. The rows are those :func:`parity_png` draws."""
    missing = [c for c in ("source", "published", "computed", "status") if c not in grp.columns]
    if missing:
        raise ValueError(f"parity rows need scorecard columns {missing}")
    nums = grp[grp["published"].notna() & grp["status"].isin(result_statuses())]
    out = {}
    for src in dict.fromkeys(nums["source"]):
        rows = nums[nums["source"] == src]
        if rows["computed"].notna().any():
            out[src] = rows
    return out


def parity_pngs(grp: pd.DataFrame) -> dict[str, bytes]:
    """{source: PNG} of the parity plots of one paper (its scorecard rows ``grp``): one per source
    of :func:`parity_rows`. The workflow draws them per seed, as soon as that seed's checks exist,
    and hands them to :func:`render`."""
    todo = parity_rows(grp)
    plotted = {src: _parity_plotted(rows, src) for src, rows in todo.items()}  # all refused before drawing
    with _parity_canvas() as fig:
        return {src: _draw_parity(fig, rows, plotted[src], src) for src, rows in todo.items()}


def _paper_findings(grp, errata, order, specs) -> list[str]:
    own = [highlight(grp, h["text"], h.get("ids"), h.get("statuses"))[1] for h in specs]
    return (own + findings(grp, errata, order))[: max(5, len(own))]


def _img(png: bytes, alt: str) -> str:
    return f"<img alt='{html.escape(alt)}' src='data:image/png;base64,{base64.b64encode(png).decode('ascii')}'>"


def _agreement_word(k: int, n: int) -> str:
    return "agrees" if k == n else ("agrees in part" if k else "does not agree")


# ----------------------------------------------------------------------------- page


def _checked_card(card: pd.DataFrame) -> pd.DataFrame:
    """A copy of the scorecard with every column the page shows (missing ones empty); refused when
    it lacks seed or status or holds a status unknown to gearrep.checks."""
    if "status" not in card.columns or "seed" not in card.columns:
        raise ValueError("scorecard needs 'seed' and 'status' columns")
    unknown = sorted(set(card["status"]) - set(_checks.STATUSES))
    if unknown:
        raise ValueError(f"scorecard has statuses {unknown} not in gearrep.checks.STATUSES {_checks.STATUSES}")
    card = card.copy()
    for col in ("replication", "source", "note", "id", "row", "quantity", "unit"):
        if col not in card.columns:
            card[col] = ""
    for col in ("published", "computed", "tolerance", "abs_err"):
        if col not in card.columns:
            card[col] = np.nan
    card["replication"] = card["replication"].fillna("").astype(str)
    return card


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
        + ", ".join(f"<a href='#paper-{s}'>seed {s}</a>" for s in sorted(card["seed"].unique()))
        + ", <a href='#statuses'>statuses and verdicts</a>, <a href='#figures'>key figures</a>, "
        + ("<a href='#validation'>validation of the library</a>, " if validation else "")
        + "<a href='#errata'>errata</a>, <a href='#environment'>environment</a>.</p>",
    ]
    if runtime_s is not None:
        parts.append(f"<p>Total workflow run time (sum of job wall times): {runtime_s:.1f} s.</p>")
    return parts


def _summary(papers: Mapping[str, pd.DataFrame], verdicts: Mapping[str, tuple[str, str]]) -> list[str]:
    res_st, apart_st = result_statuses(), apart_statuses()
    head = ["seed", "paper", "verdict", "agree", "", *res_st, "total"] + ([f"{s} (not a result)" for s in apart_st])
    rows = []
    for seed, grp in papers.items():
        counts = _counts(grp)
        v = verdicts[seed][0]
        agree, scored = sum(counts[s] for s in AGREE if s in counts), sum(counts[s] for s in res_st)
        rows.append(
            f"<tr><td>{html.escape(seed)}</td><td><a href='#paper-{seed}'>{html.escape(PAPERS.get(seed, ''))}</a></td>"
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
        f"<h2 id='paper-{seed}'>Seed {seed}: {html.escape(PAPERS.get(seed, ''))}</h2>",
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

    card : the scorecard (columns of gearrep.checks.scorecard plus ``replication``)
    figures : {caption: PNG bytes}, embedded in order (the caption says what the figure shows and
        whether it agrees)
    errata : columns seed, location, printed, correction, evidence
    environment : {name: value} (versions, git commit, config hash)
    notebooks : {replication: relative href of its rendered notebook}
    runtime_s : total workflow run time in seconds (sum of the jobs' benchmarks)
    order : {(seed, source): line of the seed text}, the paper's order of its tables
        (gearrep.published.document_order); without it sources sort as strings
    design : gearrep.published.design_table of every paper (one row per example)
    parity : the parity plot of every source with computed numbers: True draws them here, False
        leaves them out, and {seed: {source: PNG}} embeds plots drawn beforehand by
        :func:`parity_pngs` (exactly one per source of :func:`parity_rows`, else ValueError)
    highlights : {seed: [{"text", "ids", "statuses"}, ...]}, hand-written headline findings, each
        checked against its records by :func:`highlight`; the findings of a paper are these
        followed by :func:`findings`, five at most
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
