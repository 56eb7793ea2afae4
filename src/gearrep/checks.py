"""Check records: computed against published, with a tolerance that has a stated basis.

A numeric check passes (``reproduced``) when the computed value, read at the printed precision,
gives the printed number:

* ``rounding=round``, ``decimals=d``: ``|computed - printed| <= 0.5 * 10**-d``;
* ``rounding=truncate``, ``decimals=d``: ``computed`` chopped toward zero to ``d`` decimals equals
  the printed number, i.e. it lies in ``[p, p + 10**-d)`` for ``p >= 0`` (mirrored for ``p < 0``);
* ``sig=s``: ``|computed - printed| <= 0.5 * 10**(floor(log10|p|) - s + 1)``.

A computed value whose magnitude is below :func:`resolution` of its unit (1e-12 in the library's
internal unit: rad for angles, the design's own length unit for lengths) is written as 0: the
workflow's solves stop at residuals of 1e-12, so such a value is zero to the computation's accuracy
(a residual or a vector component that is zero in exact arithmetic), and its digits would differ
from machine to machine. The smallest nonzero published magnitude is 1e-10, so no comparison moves.

These tolerances are computed here from the printed string, never typed by hand. A replication
may widen one only with ``extra_tol`` and a stated physical reason (``extra_basis``), e.g. the
uncertainty a rounded table key (l_1 printed to 3 decimals) propagates into the value. A tiny
floating-point slack (1e-12 relative) keeps exact ties from failing on representation error.

Statuses (:data:`STATUSES`, the one place they are defined): the results ``reproduced``,
``deviates``, ``qualitative-holds``, ``qualitative-fails``, ``not-computed`` (:data:`RESULT_STATUSES`),
and ``input`` (:data:`INPUT_STATUSES`): a printed number that is a design input of the paper (a
crowning amount the author chose, a rack-cutter radius taken from earlier work), not the outcome of a
computation, or a printed result spent as the one calibration input of a parameter the paper does not
print (its note names the inference, and the rows predicted with it are the checks). An input row is used as printed (its note says where); it is neither a result nor a
gap, and :func:`summary` counts it apart (column ``results`` = rows that are not inputs).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from .published import printed_precision
from .units import TO_INTERNAL

__all__ = [
    "VALIDATION",
    "compare_reference",
    "STATUSES",
    "RESULT_STATUSES",
    "INPUT_STATUSES",
    "INPUT",
    "CHECK_COLUMNS",
    "TEXT_COLUMNS",
    "RESOLUTION_INTERNAL",
    "resolution",
    "printed_interval",
    "compare_value",
    "check_values",
    "claim_verdict",
    "qualitative",
    "not_computed",
    "printed_input",
    "validate_checks",
    "scorecard",
    "summary",
]

#: the ``seed`` of a validation study's records: computed against a closed form or a property of the
#: model, not against a printed number of a paper (no scorecard row of it comes from data/published)
VALIDATION = "validation"

#: statuses of a result (computed against published, or not computed)
RESULT_STATUSES = ("reproduced", "deviates", "qualitative-holds", "qualitative-fails", "not-computed")
#: a printed design input: used as printed, not a result and not a gap
INPUT = "input"
#: the statuses of a printed input
INPUT_STATUSES = (INPUT,)
#: every status a check record may have
STATUSES = RESULT_STATUSES + INPUT_STATUSES

#: the columns of a check table, in order
CHECK_COLUMNS = [
    "id",
    "seed",
    "source",
    "row",
    "quantity",
    "unit",
    "published",
    "computed",
    "abs_err",
    "rel_err",
    "tolerance",
    "tolerance_basis",
    "status",
    "note",
]

#: check-table columns that hold text: give these as ``dtype`` when reading a check CSV, or
#: pandas turns seeds such as "003" into the integer 3 (`validate_checks` rejects that)
TEXT_COLUMNS = {
    c: str for c in ("id", "seed", "source", "row", "quantity", "unit", "tolerance_basis", "status", "note")
}

_FP_SLACK = 1e-12

#: the absolute resolution of a computed value in the library's internal units (rad; lengths in
#: the design's unit): the Newton residual tolerance of the workflow's solves
RESOLUTION_INTERNAL = 1e-12


def resolution(unit: str) -> float:
    """Absolute resolution of a computed value given in ``unit`` (:data:`RESOLUTION_INTERNAL`
    converted: 2.06e-7 arcsec, 5.73e-11 deg; 1e-12 for lengths, ratios and units it does not
    know). A computed value of smaller magnitude is recorded as 0 (see the module docstring).

    Parameters
    ----------
    unit : str
        A unit of the published data ('arcsec', 'deg', 'mm', ...).

    Returns
    -------
    float
        The resolution in that unit.

    Examples
    --------
    >>> from gearrep.checks import resolution
    >>> f"{resolution('arcsec'):.3g}", resolution("mm")
    ('2.06e-07', 1e-12)
    """
    return RESOLUTION_INTERNAL / TO_INTERNAL.get(unit, 1.0)


def printed_interval(printed: str, rounding: str = "round") -> tuple[float, float, str]:
    """Interval ``[lo, hi]`` of true values that print as ``printed``, and its basis.

    For truncation the end away from zero is open.

    Parameters
    ----------
    printed : str
        The number as printed.
    rounding : {"round", "truncate"}, optional
        How the paper shortened it.

    Returns
    -------
    tuple
        (lo, hi, basis in words).

    Raises
    ------
    ValueError
        For an unknown rounding, or truncation of a number given to significant digits.

    Examples
    --------
    >>> from gearrep.checks import printed_interval
    >>> lo, hi, basis = printed_interval("0.0123")
    >>> round(lo, 12), round(hi, 12), basis
    (0.01225, 0.01235, 'printed to 4 decimals, rounded: +-5e-05')
    """
    p = float(printed)
    kind, prec = printed_precision(printed)
    if kind == "decimals":
        unit = 10.0 ** (-prec)
        what = f"{prec} decimals"
    else:
        exp = math.floor(math.log10(abs(p))) if p != 0 else 0
        unit = 10.0 ** (exp - prec + 1)
        what = f"{prec} significant digits"
    if rounding == "round":
        return p - 0.5 * unit, p + 0.5 * unit, f"printed to {what}, rounded: +-{0.5 * unit:.3g}"
    if rounding == "truncate":
        if kind != "decimals":
            raise ValueError("truncation is only defined for decimals precision")
        neg = printed.strip().startswith("-")
        lo, hi = (p - unit, p) if neg else (p, p + unit)
        return lo, hi, f"printed to {what}, truncated toward zero: in [{lo:.{prec}f}, {hi:.{prec}f})"
    raise ValueError(f"rounding must be 'round' or 'truncate', got {rounding!r}")


def compare_value(
    pub: pd.Series, computed: float, extra_tol: float = 0.0, extra_basis: str = "", note: str = ""
) -> dict:
    """One check record for a published value row (a row of ``Published.values``).

    Parameters
    ----------
    pub : pandas.Series
        The published value's row (``printed``, ``rounding``, ``value``, ``unit``, ids).
    computed : float
        The computed value, in the row's unit (None or NaN: the computation gave none).
    extra_tol : float, optional
        A widening of the printed interval [the row's unit], >= 0, only with ``extra_basis``.
    extra_basis : str, optional
        The stated physical reason for ``extra_tol``.
    note : str, optional
        A note for the record.

    Returns
    -------
    dict
        The record (:data:`CHECK_COLUMNS`).

    Raises
    ------
    ValueError
        If ``extra_tol`` is negative or has no stated reason.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> pub = pd.Series({"id": "v1", "seed": "000", "source": "Table 4.2", "row": "1", "quantity": "k1",
    ...                  "unit": "per_mm", "value": 0.0123, "printed": "0.0123", "rounding": "round"})
    >>> rec = checks.compare_value(pub, 0.01232)
    >>> rec["status"], round(rec["tolerance"], 9), rec["tolerance_basis"]
    ('reproduced', 5e-05, 'printed to 4 decimals, rounded: +-5e-05')
    >>> checks.compare_value(pub, 0.0125)["status"]
    'deviates'
    """
    lo, hi, basis = printed_interval(pub["printed"], pub["rounding"])
    if extra_tol < 0:
        raise ValueError(f"extra_tol must be >= 0, got {extra_tol}")
    if extra_tol and not extra_basis:
        raise ValueError("extra_tol needs a stated physical reason (extra_basis)")
    if extra_tol >= resolution(str(pub.get("unit", ""))):  # below it, a widening is rounding noise
        lo, hi = lo - extra_tol, hi + extra_tol
        basis = f"{basis}; plus {extra_tol:.3g} because {extra_basis}"
    value = float(pub["value"])
    rec = {k: pub.get(k, "") for k in ("id", "seed", "source", "row", "quantity", "unit")}
    rec.update(published=value, tolerance=max(hi - value, value - lo), tolerance_basis=basis, note=note)
    if computed is None or not np.isfinite(computed):
        rec.update(
            computed=np.nan,
            abs_err=np.nan,
            rel_err=np.nan,
            status="deviates",
            note=(note + "; " if note else "") + "computation returned no finite value",
        )
        return rec
    computed = float(computed)
    if abs(computed) < resolution(str(rec["unit"])):
        computed = 0.0  # zero to the computation's accuracy (no -0.0, no rounding noise)
    slack = _FP_SLACK * max(abs(value), abs(computed), 1e-300)
    if pub["rounding"] == "truncate":
        # the end away from zero is open: -4.998 truncated covers (-4.999, -4.998]
        if str(pub["printed"]).strip().startswith("-"):
            ok = lo < computed <= hi + slack
        else:
            ok = lo - slack <= computed < hi
    else:
        ok = lo - slack <= computed <= hi + slack
    abs_err = computed - value
    rel_err = abs_err / abs(value) if value != 0 else np.nan
    rec.update(computed=computed, abs_err=abs_err, rel_err=rel_err, status="reproduced" if ok else "deviates")
    return rec


def check_values(published_values: pd.DataFrame, computed: pd.DataFrame) -> pd.DataFrame:
    """Check records for every published value that ``computed`` gives a number for.

    ``computed`` has columns ``id``, ``computed`` and optionally ``extra_tol``, ``extra_basis``,
    ``note``. Ids not in ``published_values`` raise KeyError (a typo must not pass silently).

    Parameters
    ----------
    published_values : pandas.DataFrame
        Published value rows.
    computed : pandas.DataFrame
        ``id``, ``computed`` (and optional ``extra_tol``, ``extra_basis``, ``note``).

    Returns
    -------
    pandas.DataFrame
        One check record per computed id.

    Raises
    ------
    KeyError
        For an id that is not published.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> pub = pd.Series({"id": "v1", "seed": "000", "source": "Table 4.2", "row": "1", "quantity": "k1",
    ...                  "unit": "per_mm", "value": 0.0123, "printed": "0.0123", "rounding": "round"})
    >>> table = checks.check_values(pd.DataFrame([pub]), pd.DataFrame({"id": ["v1"], "computed": [0.01232]}))
    >>> table[["id", "status"]].values.tolist()
    [['v1', 'reproduced']]
    """
    pub = published_values.set_index("id", drop=False)
    unknown = sorted(set(computed["id"]) - set(pub.index))
    if unknown:
        raise KeyError(f"computed ids not in the published data: {unknown[:10]}")
    recs = []
    for _, c in computed.iterrows():
        recs.append(
            compare_value(
                pub.loc[c["id"]],
                c["computed"],
                extra_tol=float(c.get("extra_tol", 0.0) or 0.0),
                extra_basis=str(c.get("extra_basis", "") or ""),
                note=str(c.get("note", "") or ""),
            )
        )
    return pd.DataFrame(recs, columns=CHECK_COLUMNS)


def claim_verdict(confirm: bool, refute: bool, evidence: str) -> tuple[bool, str]:
    """(holds, evidence) of a claim from the outcomes of its ``confirm_if`` and ``refute_if``
    criteria (data/published/claims_*.csv): it holds only if the confirm criterion is met; when
    neither is met it is not confirmed (fails) and the evidence says so. ValueError if both are
    met (the criteria on file contradict each other).

    Parameters
    ----------
    confirm, refute : bool
        Whether each criterion is met.
    evidence : str
        The numbers behind the verdict.

    Returns
    -------
    tuple
        (holds, evidence).

    Raises
    ------
    ValueError
        If both criteria are met.

    Examples
    --------
    >>> from gearrep.checks import claim_verdict
    >>> claim_verdict(True, False, "TE 0.1 arcsec < 1 arcsec")
    (True, 'TE 0.1 arcsec < 1 arcsec')
    """
    if confirm and refute:
        raise ValueError(f"claim criteria contradict each other: {evidence}")
    tail = "" if (confirm or refute) else " [confirm criterion not met; refute criterion not met either]"
    return bool(confirm), evidence + tail


def compare_reference(
    id: str,
    source: str,
    row: str,
    quantity: str,
    unit: str,
    reference: float,
    computed: float,
    tolerance: float,
    basis: str,
    note: str = "",
) -> dict:
    """Check record of a validation study (seed :data:`VALIDATION`): ``computed`` against a
    ``reference`` that is no printed number (a closed form, an exact property, another solution of
    the same problem) within ``tolerance`` (absolute, in ``unit``), whose ``basis`` states its
    physical or numerical reason. ``reproduced`` when |computed - reference| <= tolerance, else
    ``deviates``; a non-finite computed value deviates.

    Parameters
    ----------
    id, source, row, quantity, unit : str
        The record's id (a validation study's own, no published id), where the check comes from,
        its row key, the quantity and its unit.
    reference : float
        The reference value, in ``unit``.
    computed : float or None
        The computed value, in ``unit`` (None or non-finite: the computation gave none).
    tolerance : float
        Absolute tolerance in ``unit``, finite and >= 0.
    basis : str
        The tolerance's stated reason (required).
    note : str, optional
        A note carried into the record.

    Returns
    -------
    dict
        A check record (the columns of :data:`CHECK_COLUMNS`), seed :data:`VALIDATION`.

    Raises
    ------
    ValueError
        For an empty ``basis`` or a tolerance that is negative or not finite.

    Examples
    --------
    >>> from gearrep.checks import compare_reference
    >>> rec = compare_reference("val-1", "closed form", "case=a", "p_max", "MPa", 1000.0, 1000.4, 1.0,
    ...                         "discretisation error of the grid")
    >>> rec["status"], round(rec["abs_err"], 6)
    ('reproduced', 0.4)
    """
    if not basis:
        raise ValueError("a validation tolerance needs its stated basis")
    tol = float(tolerance)
    if not (np.isfinite(tol) and tol >= 0):
        raise ValueError(f"tolerance must be a finite number >= 0, got {tolerance!r}")
    ref = float(reference)
    rec = dict(
        id=id,
        seed=VALIDATION,
        source=source,
        row=row,
        quantity=quantity,
        unit=unit,
        published=ref,
        tolerance=tol,
        tolerance_basis=basis,
        note=note,
    )
    if computed is None or not np.isfinite(computed):
        return rec | dict(
            computed=np.nan,
            abs_err=np.nan,
            rel_err=np.nan,
            status="deviates",
            note=(note + "; " if note else "") + "computation returned no finite value",
        )
    c = float(computed)
    err = c - ref
    ok = abs(err) <= tol * (1.0 + _FP_SLACK)
    return rec | dict(
        computed=c,
        abs_err=err,
        rel_err=err / abs(ref) if ref != 0 else np.nan,
        status="reproduced" if ok else "deviates",
    )


def qualitative(claim: pd.Series, holds: bool, evidence: str) -> dict:
    """Check record for a claim row, with the numbers behind the verdict in ``evidence``.

    Parameters
    ----------
    claim : pandas.Series
        The claim's row (ids, ``source``).
    holds : bool
        The verdict.
    evidence : str
        The numbers behind it.

    Returns
    -------
    dict
        The record, status ``qualitative-holds`` or ``qualitative-fails``.

    Raises
    ------
    ValueError
        If ``evidence`` is empty.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.checks import qualitative
    >>> claim = pd.Series({"id": "c1", "seed": "000", "source": "sec. 5.4", "kind": "qualitative"})
    >>> qualitative(claim, False, "TE 3.2 arcsec")["status"]
    'qualitative-fails'
    """
    if not evidence:
        raise ValueError("a qualitative verdict needs its evidence (the numbers behind it)")
    return {
        "id": claim["id"],
        "seed": claim["seed"],
        "source": claim["source"],
        "row": claim.get("parameters", ""),
        "quantity": claim["kind"],
        "unit": "",
        "published": np.nan,
        "computed": np.nan,
        "abs_err": np.nan,
        "rel_err": np.nan,
        "tolerance": np.nan,
        "tolerance_basis": claim.get("confirm_if", ""),
        "status": "qualitative-holds" if holds else "qualitative-fails",
        "note": evidence,
    }


def not_computed(rows: pd.DataFrame, reason: str) -> pd.DataFrame:
    """``not-computed`` records for published values or claims, with the reason.

    Parameters
    ----------
    rows : pandas.DataFrame
        Published value or claim rows.
    reason : str
        Why they are not computed.

    Returns
    -------
    pandas.DataFrame
        One record per row.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> pub = pd.Series({"id": "v1", "seed": "000", "source": "Table 4.2", "row": "1", "quantity": "k1",
    ...                  "unit": "per_mm", "value": 0.0123, "printed": "0.0123", "rounding": "round"})
    >>> checks.not_computed(pd.DataFrame([pub]), "needs the loaded model")[["status", "note"]].values.tolist()
    [['not-computed', 'needs the loaded model']]
    """
    return _uncompared(rows, reason, "not-computed")


def printed_input(rows: pd.DataFrame, use: str) -> pd.DataFrame:
    """``input`` records for published values that are design inputs of the paper (not results):
    ``use`` says why the number is an input and where the replication uses it as printed.

    Parameters
    ----------
    rows : pandas.DataFrame
        Published value rows.
    use : str
        Why they are inputs and where they are used.

    Returns
    -------
    pandas.DataFrame
        One ``input`` record per row.

    Raises
    ------
    ValueError
        If ``use`` is empty or the rows are claims.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> pub = pd.Series({"id": "v1", "seed": "000", "source": "Table 4.2", "row": "1", "quantity": "k1",
    ...                  "unit": "per_mm", "value": 0.0123, "printed": "0.0123", "rounding": "round"})
    >>> checks.printed_input(pd.DataFrame([pub]), "the design's curvature")["status"].tolist()
    ['input']
    """
    if not use:
        raise ValueError("an input record needs its note: why the number is an input and where it is used")
    if "statement" in rows.columns:
        raise ValueError("claims are statements, not printed inputs; give value rows")
    return _uncompared(rows, use, INPUT)


def _uncompared(rows: pd.DataFrame, reason: str, status: str) -> pd.DataFrame:
    recs = []
    for _, r in rows.iterrows():
        is_claim = "kind" in r.index and "statement" in r.index
        recs.append(
            {
                "id": r["id"],
                "seed": r["seed"],
                "source": r["source"],
                "row": r.get("parameters", "") if is_claim else r["row"],
                "quantity": r["kind"] if is_claim else r["quantity"],
                "unit": "" if is_claim else r["unit"],
                "published": np.nan if is_claim else float(r["value"]),
                "computed": np.nan,
                "abs_err": np.nan,
                "rel_err": np.nan,
                "tolerance": np.nan,
                "tolerance_basis": "",
                "status": status,
                "note": reason,
            }
        )
    return pd.DataFrame(recs, columns=CHECK_COLUMNS)


def validate_checks(checks: pd.DataFrame) -> pd.DataFrame:
    """Raise ValueError unless ``checks`` has the check columns, known statuses, unique ids.

    Parameters
    ----------
    checks : pandas.DataFrame
        A check table.

    Returns
    -------
    pandas.DataFrame
        ``checks``.

    Raises
    ------
    ValueError
        Naming the missing column, unknown status or repeated id.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> checks.validate_checks(pd.DataFrame({"id": ["v1"]}))
    Traceback (most recent call last):
        ...
    ValueError: ...
    """
    missing = [c for c in CHECK_COLUMNS if c not in checks.columns]
    if missing:
        raise ValueError(f"check table lacks columns {missing}")
    bad = sorted(set(checks["status"]) - set(STATUSES))
    if bad:
        raise ValueError(f"unknown statuses {bad}; allowed {STATUSES}")
    if checks["id"].duplicated().any():
        raise ValueError(f"duplicate check ids: {sorted(set(checks['id'][checks['id'].duplicated()]))[:10]}")
    bad_seed = [
        s
        for s in checks["seed"].unique()
        if not (isinstance(s, str) and (s == VALIDATION or (len(s) == 3 and s.isdigit())))
    ]
    if bad_seed:
        raise ValueError(
            f"seed must be a three-digit string such as '003' (or {VALIDATION!r} for a validation study), "
            f"got {bad_seed[:5]} (read check CSVs with dtype=checks.TEXT_COLUMNS)"
        )
    return checks


def scorecard(check_tables: dict[str, pd.DataFrame], values: pd.DataFrame, claims: pd.DataFrame) -> pd.DataFrame:
    """One row per published value and claim: the replication's check where there is one,
    ``not-computed`` otherwise, then the records of the validation studies (seed :data:`VALIDATION`,
    whose ids are their own, none of them a published id). ``check_tables`` maps replication name
    -> check table.

    Parameters
    ----------
    check_tables : dict
        Replication name -> check table.
    values, claims : pandas.DataFrame
        Every published value and claim.

    Returns
    -------
    pandas.DataFrame
        The scorecard, with a ``replication`` column.

    Raises
    ------
    ValueError
        For a bad check table, an id checked twice or an id that is not published.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> values = pd.DataFrame({"id": ["v1", "v2"], "seed": "000", "source": "Table 4.2", "row": ["1", "2"],
    ...                        "quantity": "k1", "unit": "per_mm", "value": 0.0123, "printed": "0.0123",
    ...                        "rounding": "round"})
    >>> claims = pd.DataFrame({"id": ["c1"], "seed": ["000"], "source": ["sec. 5.4"], "kind": ["qualitative"],
    ...                        "statement": ["the TE is small"]})
    >>> checked = checks.check_values(values.iloc[:1], pd.DataFrame({"id": ["v1"], "computed": [0.01232]}))
    >>> card = checks.scorecard({"hobcut_curvature": checked}, values, claims)
    >>> card[["id", "status"]].values.tolist()
    [['v1', 'reproduced'], ['v2', 'not-computed'], ['c1', 'not-computed']]
    """
    frames = []
    for name, tab in check_tables.items():
        tab = validate_checks(tab).copy()
        tab.insert(0, "replication", name)
        frames.append(tab)
    done = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=["replication", *CHECK_COLUMNS])
    if done["id"].duplicated().any():
        raise ValueError(f"ids checked by two replications: {sorted(set(done['id'][done['id'].duplicated()]))[:10]}")
    known = set(values["id"]) | set(claims["id"])
    own = done["seed"] == VALIDATION
    stray = sorted(set(done.loc[~own, "id"]) - known)
    if stray:
        raise ValueError(f"check ids not in the published data: {stray[:10]}")
    taken = sorted(set(done.loc[own, "id"]) & known)
    if taken:
        raise ValueError(f"validation records use published ids: {taken[:10]}")
    reason = "no replication has computed this yet"
    rest_v = values[~values["id"].isin(done["id"])]
    rest_c = claims[~claims["id"].isin(done["id"])]
    pending = [not_computed(x, reason) for x in (rest_v, rest_c) if len(x)]
    for p in pending:
        p.insert(0, "replication", "")
    card = pd.concat([done, *pending], ignore_index=True)
    return card.sort_values(["seed", "source", "id"], kind="stable").reset_index(drop=True)


def summary(card: pd.DataFrame, by=("seed",)) -> pd.DataFrame:
    """Counts by status (columns, in :data:`STATUSES` order) for each group in ``by``, then
    ``results`` (rows with a result status: every row but the printed inputs) and ``total``.

    Parameters
    ----------
    card : pandas.DataFrame
        A scorecard (:func:`scorecard`).
    by : tuple of str, optional
        The grouping columns.

    Returns
    -------
    pandas.DataFrame
        One row per group.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep import checks
    >>> values = pd.DataFrame({"id": ["v1", "v2"], "seed": "000", "source": "Table 4.2", "row": ["1", "2"],
    ...                        "quantity": "k1", "unit": "per_mm", "value": 0.0123, "printed": "0.0123",
    ...                        "rounding": "round"})
    >>> claims = pd.DataFrame({"id": ["c1"], "seed": ["000"], "source": ["sec. 5.4"], "kind": ["qualitative"],
    ...                        "statement": ["the TE is small"]})
    >>> checked = checks.check_values(values.iloc[:1], pd.DataFrame({"id": ["v1"], "computed": [0.01232]}))
    >>> card = checks.scorecard({"hobcut_curvature": checked}, values, claims)
    >>> row = checks.summary(card).iloc[0]
    >>> int(row["reproduced"]), int(row["not-computed"]), int(row["total"])
    (1, 2, 3)
    """
    counts = card.groupby(list(by))["status"].value_counts().unstack(fill_value=0)
    for s in STATUSES:
        if s not in counts.columns:
            counts[s] = 0
    counts = counts[list(STATUSES)]
    counts["results"] = counts[list(RESULT_STATUSES)].sum(axis=1)
    counts["total"] = counts[list(STATUSES)].sum(axis=1)
    return counts.reset_index()
