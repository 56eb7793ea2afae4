"""The report's judgement of the scorecard: which statuses agree, disagree or stay open, what each
means, and the verdict of a paper (reproduced / partially reproduced / not reproduced) by the
criteria stated on the page."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from .. import checks as _checks

__all__ = [
    "AGREE",
    "DISAGREE",
    "OPEN",
    "STATUS_MEANINGS",
    "VERDICTS",
    "VERDICT_CRITERIA",
    "result_statuses",
    "apart_statuses",
    "status_meaning",
    "ordered_sources",
    "verdict",
    "paper_verdicts",
]

#: statuses that mean the paper's number or statement is confirmed by our computation
AGREE = ("reproduced", "qualitative-holds")


#: statuses that mean our computation contradicts the paper's number or statement
DISAGREE = ("deviates", "qualitative-fails")


#: statuses that mean no comparison was made
OPEN = ("not-computed",)


#: what each status means, as the page's legend says it
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


#: the verdicts of a paper, from best to worst (:func:`verdict`)
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


def result_statuses() -> tuple[str, ...]:
    """The statuses of gearrep.checks that are comparison results (agree, disagree or open).

    Returns
    -------
    tuple of str
        The result statuses, in the order of :data:`gearrep.checks.STATUSES`.

    Examples
    --------
    >>> from gearrep.report import result_statuses
    >>> result_statuses()
    ('reproduced', 'deviates', 'qualitative-holds', 'qualitative-fails', 'not-computed')
    """
    return tuple(s for s in _checks.STATUSES if s in AGREE + DISAGREE + OPEN)


def apart_statuses() -> tuple[str, ...]:
    """Statuses of gearrep.checks that are not comparison results (shown apart, never in a verdict).

    Returns
    -------
    tuple of str
        The other statuses.

    Examples
    --------
    >>> from gearrep.report import apart_statuses
    >>> apart_statuses()
    ('input',)
    """
    return tuple(s for s in _checks.STATUSES if s not in AGREE + DISAGREE + OPEN)


def status_meaning(status: str) -> str:
    """What a status means, for the legend; a status unknown here is described as not a result.

    Parameters
    ----------
    status : str
        One of :data:`gearrep.checks.STATUSES`.

    Returns
    -------
    str
        Its meaning, one paragraph.

    Raises
    ------
    ValueError
        If ``status`` is not a status of :mod:`gearrep.checks`.

    Examples
    --------
    >>> from gearrep.report import status_meaning
    >>> status_meaning("deviates").split(";")[0]
    'a printed number that our computation does not give within that tolerance (or for which it returns no finite value)'
    """
    if status in STATUS_MEANINGS:
        return STATUS_MEANINGS[status]
    if status not in _checks.STATUSES:
        raise ValueError(f"status={status!r} is not one of gearrep.checks.STATUSES {_checks.STATUSES}")
    return (
        "a record that is not a comparison of a computed result with a published one (for example a "
        "design input the paper prints and we use as given); counted apart from the results, never in a verdict."
    )


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


def ordered_sources(card: pd.DataFrame, order: Mapping[tuple[str, str], int] | None = None) -> list[tuple[str, str]]:
    """(seed, source) pairs of ``card`` in document order: by seed, then by the line where the paper
    prints the source (``order``, from :func:`gearrep.published.document_order`); sources without
    a line come last, in string order.

    Parameters
    ----------
    card : pandas.DataFrame
        Scorecard rows (``seed``, ``source``).
    order : mapping, optional
        ``{(seed, source): line}``.

    Returns
    -------
    list of (str, str)
        The (seed, source) pairs, each once.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import ordered_sources
    >>> card = pd.DataFrame({"seed": ["000", "000", "000"], "source": ["Table 5.3", "Table 4.3", "Fig. 5.5"]})
    >>> ordered_sources(card, {("000", "Table 4.3"): 366, ("000", "Table 5.3"): 640})  # Fig. 5.5: no line
    [('000', 'Table 4.3'), ('000', 'Table 5.3'), ('000', 'Fig. 5.5')]
    """
    order = order or {}
    pairs = list(dict.fromkeys(zip(card["seed"], card["source"])))
    big = 10**9
    return sorted(pairs, key=lambda p: (p[0], order.get(p, big), p[1]))


def verdict(grp: pd.DataFrame) -> tuple[str, str]:
    """(verdict, one-line reason) of one paper's scorecard rows by :data:`VERDICT_CRITERIA`.

    Only result statuses count (:func:`result_statuses`); rows of any other status are left out.

    Parameters
    ----------
    grp : pandas.DataFrame
        One paper's scorecard rows (``status``, ``published``).

    Returns
    -------
    verdict : str
        One of :data:`VERDICTS`.
    reason : str
        The counts behind it.

    Raises
    ------
    ValueError
        If no row has a result status.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import verdict
    >>> card = pd.DataFrame({"status": ["reproduced", "reproduced", "deviates"], "published": [1.0, 2.0, 3.0]})
    >>> verdict(card)[0]
    'partially reproduced'
    >>> verdict(card)[1]
    '2 of 3 scored items agree (67 %): 2 of 3 printed numbers reproduced, 0 of 0 statements hold; 1 deviate or fail, 0 not computed.'
    """
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
    :data:`gearrep.checks.VALIDATION`) are no paper and have no verdict.

    Parameters
    ----------
    card : pandas.DataFrame
        The scorecard (``seed``, ``status``; every status one of :data:`gearrep.checks.STATUSES`).

    Returns
    -------
    dict
        ``{seed: (verdict, reason)}``.

    Raises
    ------
    ValueError
        If ``seed`` or ``status`` is missing or a status is unknown.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import paper_verdicts
    >>> card = pd.DataFrame({"seed": ["000", "000", "002"], "status": ["reproduced", "reproduced", "input"]})
    >>> {seed: v for seed, (v, _) in paper_verdicts(card).items()}
    {'000': 'reproduced', '002': 'no results'}
    """
    card = _checked_card(card)
    card = card[card["seed"] != _checks.VALIDATION]
    return {
        seed: verdict(grp) if grp["status"].isin(result_statuses()).any() else ("no results", "")
        for seed, grp in card.groupby("seed", sort=True)
    }
