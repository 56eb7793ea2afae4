"""Headline findings of a paper written from its check records, and hand-written findings checked
against the records they name (HTML fragments)."""

from __future__ import annotations

import fnmatch
import html
import re
from collections.abc import Mapping

import pandas as pd

from .. import checks as _checks
from ._verdicts import _COLOURS, OPEN, ordered_sources, result_statuses

__all__ = [
    "findings",
    "highlight",
]


def _short(text: str, n: int = 240) -> str:
    text = re.sub(r"\s+", " ", str(text)).strip()
    return text if len(text) <= n else text[: n - 1].rsplit(" ", 1)[0] + " …"


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

    Parameters
    ----------
    grp : pandas.DataFrame
        One paper's scorecard rows.
    errata : pandas.DataFrame, optional
        The paper's errata (``location``).
    order : mapping, optional
        ``{(seed, source): line}``, the paper's order of its tables.

    Returns
    -------
    list of str
        At most five HTML fragments.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import findings
    >>> card = pd.DataFrame(
    ...     {
    ...         "seed": ["000"] * 3,
    ...         "source": ["Table 4.3"] * 3,
    ...         "id": ["000-a", "000-b", "000-c"],
    ...         "status": ["reproduced", "reproduced", "deviates"],
    ...         "published": [1.0, 2.0, 3.0],
    ...         "note": ["", "", "an OCR slip"],
    ...     }
    ... )
    >>> for line in findings(card):
    ...     print(line)
    <b>1 printed number deviates</b>, most in Table 4.3 (1). Recorded explanations: 1 of them: an OCR slip
    <b>Reproduced within printed precision</b>: no table in full; in part: Table 4.3 (2 of 3).
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
    outlive its evidence silently.

    Parameters
    ----------
    card : pandas.DataFrame
        The scorecard (``id``, ``status``).
    text : str
        The finding.
    ids : iterable of str
        Check ids or fnmatch patterns, at least one.
    statuses : iterable of str
        Statuses of :data:`gearrep.checks.STATUSES`, at least one.

    Returns
    -------
    supported : bool
        Whether every record named has one of ``statuses``.
    html : str
        The finding as HTML.

    Raises
    ------
    ValueError
        If ``ids`` or ``statuses`` is empty or a status is unknown.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import highlight
    >>> card = pd.DataFrame({"id": ["000-a", "000-b", "000-c"], "status": ["reproduced", "reproduced", "deviates"]})
    >>> highlight(card, "Both hold", ["000-a", "000-b"], ["reproduced"])
    (True, "Both hold <span class='apart'>(check records: 2, all reproduced)</span>")
    >>> highlight(card, "All hold", ["000-*"], ["reproduced"])[0]  # 000-c deviates: struck through
    False
    """
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
