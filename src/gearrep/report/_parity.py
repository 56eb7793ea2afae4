"""Parity plots: published against computed values of one source table, with each value's
tolerance as a band (PNG bytes). matplotlib is imported when the first plot is drawn: the
verdicts of the report (read at the end of every workflow run) do not need it."""

from __future__ import annotations

import contextlib
import io

import numpy as np
import pandas as pd

from ._verdicts import _COLOURS, result_statuses

__all__ = [
    "parity_rows",
    "parity_png",
    "parity_pngs",
]


def parity_rows(grp: pd.DataFrame) -> dict[str, pd.DataFrame]:
    """{source: rows} of one paper's scorecard rows for every source that gets a parity plot: the
    source's printed numbers with a result status (printed inputs are not results), for the sources
    where at least one of them is computed. The rows are those :func:`parity_png` draws.

    Parameters
    ----------
    grp : pandas.DataFrame
        One paper's scorecard rows (``source``, ``published``, ``computed``, ``status``).

    Returns
    -------
    dict
        ``{source: rows}``.

    Raises
    ------
    ValueError
        If a column is missing.

    Examples
    --------
    >>> import numpy as np
    >>> import pandas as pd
    >>> from gearrep.report import parity_rows
    >>> card = pd.DataFrame(
    ...     {
    ...         "source": ["Table 4.3", "Table 4.3", "Table 5.3"],
    ...         "status": ["reproduced", "deviates", "not-computed"],
    ...         "published": [1.0, 3.0, 2.0],
    ...         "computed": [1.0, 3.5, np.nan],
    ...     }
    ... )
    >>> {source: len(rows) for source, rows in parity_rows(card).items()}  # Table 5.3: nothing computed
    {'Table 4.3': 2}
    """
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


def parity_png(rows: pd.DataFrame, title: str) -> bytes:
    """PNG of a parity plot of one source table: left, computed against published with the line of
    equality and each value's tolerance as a band around it; right, (computed - published) /
    tolerance per value in table order, with the band |.| <= 1 that means "reproduced".

    ``rows``: scorecard rows with ``published``, ``computed``, ``tolerance``, ``status``,
    ``quantity``; rows without a finite computed value are left out (and counted in the title).

    Parameters
    ----------
    rows : pandas.DataFrame
        The rows (see above).
    title : str
        The plot's title (the source).

    Returns
    -------
    bytes
        The PNG.

    Raises
    ------
    ValueError
        If a column is missing or no row has both a published and a computed value.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import parity_png
    >>> rows = pd.DataFrame(
    ...     {
    ...         "published": [1.0, 2.0, 3.0],
    ...         "computed": [1.0, 2.01, 3.5],
    ...         "tolerance": [0.05, 0.05, 0.05],
    ...         "status": ["reproduced", "reproduced", "deviates"],
    ...         "quantity": ["k_s"] * 3,
    ...     }
    ... )
    >>> parity_png(rows, "Table 4.3")[1:4]
    b'PNG'
    """
    plotted = _parity_plotted(rows, title)  # bad rows are refused before a figure is made
    with _parity_canvas() as fig:
        return _draw_parity(fig, rows, plotted, title)


def parity_pngs(grp: pd.DataFrame) -> dict[str, bytes]:
    """{source: PNG} of the parity plots of one paper (its scorecard rows ``grp``): one per source
    of :func:`parity_rows`. The workflow draws them per seed, as soon as that seed's checks exist,
    and hands them to :func:`render`.

    Parameters
    ----------
    grp : pandas.DataFrame
        One paper's scorecard rows.

    Returns
    -------
    dict
        ``{source: PNG bytes}``.

    Raises
    ------
    ValueError
        If a column is missing or a plot has no row to draw.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.report import parity_pngs
    >>> card = pd.DataFrame(
    ...     {
    ...         "source": ["Table 4.3"] * 2,
    ...         "published": [1.0, 3.0],
    ...         "computed": [1.0, 3.5],
    ...         "tolerance": [0.05, 0.05],
    ...         "status": ["reproduced", "deviates"],
    ...         "quantity": ["k_s", "k_s"],
    ...     }
    ... )
    >>> {source: png[1:4] for source, png in parity_pngs(card).items()}
    {'Table 4.3': b'PNG'}
    """
    todo = parity_rows(grp)
    plotted = {src: _parity_plotted(rows, src) for src, rows in todo.items()}  # all refused before drawing
    with _parity_canvas() as fig:
        return {src: _draw_parity(fig, rows, plotted[src], src) for src, rows in todo.items()}


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
