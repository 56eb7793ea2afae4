"""One matplotlib style for every gearrep figure.

Rules: axes are labelled with their unit, published values are markers (open symbols, named by
their source table), computed values are lines. Functions take an ``Axes`` and return it; they
never save files (workflow scripts do).
"""

from __future__ import annotations

import re

import matplotlib as mpl

__all__ = [
    "STYLE",
    "use_style",
    "label_axes",
    "computed",
    "published",
    "finish",
]

#: the rcParams of every gearrep figure (applied by :func:`use_style`)
STYLE = {
    "figure.figsize": (6.4, 4.2),
    "figure.dpi": 110,
    "savefig.dpi": 130,
    "savefig.bbox": "tight",
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 8,
    "legend.frameon": False,
    "lines.linewidth": 1.6,
    "lines.markersize": 6,
}

_UNIT = re.compile(r"\[[^\]]+\]|\(([^)]*)\)\s*$")


def use_style() -> None:
    """Apply the gearrep style to matplotlib's global rcParams.

    Examples
    --------
    >>> import matplotlib
    >>> from gearrep.plotting import STYLE, use_style
    >>> with matplotlib.rc_context():  # here only for the example; a figure script calls it once
    ...     use_style()
    ...     matplotlib.rcParams["savefig.dpi"] == STYLE["savefig.dpi"]
    True
    """
    mpl.rcParams.update(STYLE)


def _require_unit(label: str, which: str) -> str:
    if not _UNIT.search(label):
        raise ValueError(
            f"{which} label {label!r} must end with its unit in brackets, e.g. 'KE [arcsec]' "
            "(use '[-]' for dimensionless)"
        )
    return label


def label_axes(ax, xlabel: str, ylabel: str, title: str | None = None):
    """Set axis labels, each required to carry a unit in brackets ('phi1 [deg]').

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    xlabel, ylabel : str
        Labels ending with the unit in brackets ('[-]' for dimensionless).
    title : str, optional
        The title.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``.

    Raises
    ------
    ValueError
        If a label does not end with its unit.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from gearrep import plotting
    >>> fig, ax = plt.subplots()
    >>> plotting.label_axes(ax, "phi1 [deg]", "TE [arcsec]").get_xlabel()
    'phi1 [deg]'
    >>> plotting.label_axes(ax, "phi1", "TE [arcsec]")
    Traceback (most recent call last):
        ...
    ValueError: x label 'phi1' must end with its unit in brackets, e.g. 'KE [arcsec]' (use '[-]' for dimensionless)
    >>> plt.close(fig)
    """
    ax.set_xlabel(_require_unit(xlabel, "x"))
    ax.set_ylabel(_require_unit(ylabel, "y"))
    if title:
        ax.set_title(title)
    return ax


def computed(ax, x, y, label: str, **kw):
    """Computed values: a line (with small dots at the computed points).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    x, y : array_like
        The values (in the axes' units).
    label : str
        Legend label.
    **kw
        Passed to ``ax.plot``.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from gearrep import plotting
    >>> fig, ax = plt.subplots()
    >>> plotting.computed(ax, [0, 1, 2], [0.0, 1.0, 4.0], "computed").lines[0].get_linestyle()
    '-'
    >>> plt.close(fig)
    """
    kw.setdefault("marker", ".")
    kw.setdefault("markersize", 3)
    kw.setdefault("linestyle", "-")
    ax.plot(x, y, label=label, **kw)
    return ax


def published(ax, x, y, source: str, label: str | None = None, **kw):
    """Published values: open markers, labelled with their source (e.g. 'Table 5.3').

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    x, y : array_like
        The values (in the axes' units).
    source : str
        Where they are printed.
    label : str, optional
        Legend label (default 'published').
    **kw
        Passed to ``ax.plot``.

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from gearrep import plotting
    >>> fig, ax = plt.subplots()
    >>> plotting.published(ax, [1, 2], [1.1, 3.9], "Table 5.3").lines[0].get_label()
    'published (Table 5.3)'
    >>> plt.close(fig)
    """
    kw.setdefault("marker", "o")
    kw.setdefault("mfc", "none")
    kw.setdefault("linestyle", "none")
    ax.plot(x, y, label=f"{label or 'published'} ({source})", **kw)
    return ax


def finish(ax, loc: str = "best"):
    """Add the legend (if anything is labelled) and return the figure.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    loc : str, optional
        Legend location.

    Returns
    -------
    matplotlib.figure.Figure
        The axes' figure.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from gearrep import plotting
    >>> fig, ax = plt.subplots()
    >>> plotting.finish(plotting.computed(ax, [0, 1], [0, 1], "computed")) is fig
    True
    >>> plt.close(fig)
    """
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc=loc)
    return ax.figure
