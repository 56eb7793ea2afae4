"""Look-ups on the frames of the published data (:func:`gearrep.published.load`): a row key's
parts, one example's parameters, values by key, the design table of every example and the
document order of the sources. Public names of :mod:`gearrep.published`; this module is their home.
"""

from __future__ import annotations

import pandas as pd

from ._published_format import PARAM_COLUMNS, SEEDS, PublishedDataError

__all__ = ["parse_row", "param_table", "values_by", "design_table", "document_order"]


def parse_row(row: str) -> dict[str, str]:
    """``'l1_mm=4.381;side=L'`` -> ``{'l1_mm': '4.381', 'side': 'L'}``.

    Parameters
    ----------
    row : str
        ``name=value`` parts separated by ``;``.

    Returns
    -------
    dict
        The parts, as strings.

    Raises
    ------
    PublishedDataError
        If a part is not ``name=value``.

    Examples
    --------
    >>> from gearrep.published import parse_row
    >>> parse_row("l1_mm=4.381;side=L")  # mm
    {'l1_mm': '4.381', 'side': 'L'}
    """
    out = {}
    for part in filter(None, (p.strip() for p in str(row).split(";"))):
        k, sep, val = part.partition("=")
        if not sep:
            raise PublishedDataError(f"row key part {part!r} is not name=value")
        out[k.strip()] = val.strip()
    return out


def param_table(params: pd.DataFrame, file: str, example: str | None = None) -> dict[str, float]:
    """``{parameter: value}`` of one params file (and example), in the file's units.

    Parameters
    ----------
    params : pandas.DataFrame
        A typed params frame.
    file : str
        The file name.
    example : str, optional
        The example (default: every example of the file).

    Returns
    -------
    dict
        ``{parameter: value}`` [the file's units].

    Raises
    ------
    KeyError
        If the file (and example) has no parameters.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import param_table
    >>> params = pd.DataFrame(
    ...     {"file": ["p.csv", "p.csv"], "example": ["5.1", "5.1"], "parameter": ["module", "teeth"], "value": [3.0, 20.0]}
    ... )
    >>> param_table(params, "p.csv", "5.1")  # mm, 1
    {'module': 3.0, 'teeth': 20.0}
    """
    # on the columns' lists: the studies call this for every design they read, and two boolean
    # selections of the frame cost a few milliseconds each time
    files, examples = params["file"].tolist(), params["example"].tolist()
    keep = [i for i, f in enumerate(files) if f == file and (example is None or examples[i] == example)]
    if not keep:
        raise KeyError(f"no parameters for file={file!r} example={example!r}")
    names, values = params["parameter"].tolist(), params["value"].tolist()
    return {names[i]: values[i] for i in keep}


def values_by(frame: pd.DataFrame, keys: list[str]) -> dict[tuple, list]:
    """``{(frame[keys[0]], ...): [value, ...]}`` of a values or params frame, in row order: every
    look-up of a study's design data from one pass over the frame (a boolean selection per
    parameter cost more than the rest of reading the design). A key with other than one value is
    the caller's to refuse.

    Parameters
    ----------
    frame : pandas.DataFrame
        A values or params frame (with a ``value`` column).
    keys : list of str
        The key columns.

    Returns
    -------
    dict
        ``{key tuple: [value, ...]}``.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import values_by
    >>> frame = pd.DataFrame({"example": ["5.1", "5.1", "5.2"], "parameter": ["m", "m", "m"], "value": [3.0, 3.5, 4.0]})
    >>> values_by(frame, ["example", "parameter"])  # mm
    {('5.1', 'm'): [3.0, 3.5], ('5.2', 'm'): [4.0]}
    """
    out: dict[tuple, list] = {}
    for key, v in zip(zip(*(frame[k].tolist() for k in keys)), frame["value"].tolist()):
        out.setdefault(key, []).append(v)
    return out


def design_table(params: pd.DataFrame, seed: str | None = None) -> pd.DataFrame:
    """The design data of every example (of ``seed``, if given), one row per example in the
    order the document prints them: columns ``seed``, ``example``, ``source`` (where it is
    printed, with its first seed-file line), ``file`` (its params files) and ``design``
    (``name = printed unit; ...`` as printed, in the files' order; ``name = (not printed)`` for a
    value the text only implies).

    Parameters
    ----------
    params : pandas.DataFrame
        ``Published.params`` of :func:`load`.
    seed : str, optional
        One of :data:`SEEDS`.

    Returns
    -------
    pandas.DataFrame
        One row per example.

    Raises
    ------
    ValueError
        If a column is missing or ``seed`` is unknown.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import PARAM_COLUMNS, design_table
    >>> rows = [["p.csv", "000", "Table 5.1", 600, "5.1", "module", "3", 3.0, "mm", ""]]
    >>> rows += [["p.csv", "000", "Table 5.1", 601, "5.1", "n_pinion", "20", 20.0, "1", ""]]
    >>> table = design_table(pd.DataFrame(rows, columns=["file", *PARAM_COLUMNS]))
    >>> table.loc[0, "source"], table.loc[0, "design"]
    ('Table 5.1 (line 600)', 'module = 3 mm; n_pinion = 20')
    """
    missing = [c for c in ("file", *PARAM_COLUMNS) if c not in params.columns]
    if missing:
        raise ValueError(f"params lacks columns {missing} (pass Published.params of load())")
    if seed is not None and seed not in SEEDS:
        raise ValueError(f"seed={seed!r} is not one of {list(SEEDS)}")
    p = params if seed is None else params[params["seed"] == seed]
    rows = []
    for (s, example), g in p.groupby(["seed", "example"], sort=False):
        items = []
        for r in g.itertuples(index=False):
            printed = str(r.printed).strip()
            unit = "" if r.unit in ("1", "count") else f" {r.unit}"
            items.append(f"{r.parameter} = {printed}{unit}" if printed else f"{r.parameter} = (not printed)")
        sources = list(dict.fromkeys(str(x) for x in g["source"]))
        rows.append(
            {
                "seed": s,
                "example": example,
                "source": "; ".join(sources) + f" (line {int(g['line'].min())})",
                "file": "; ".join(dict.fromkeys(g["file"])),
                "design": "; ".join(items),
                "_line": int(g["line"].min()),
            }
        )
    out = pd.DataFrame(rows, columns=["seed", "example", "source", "file", "design", "_line"])
    return (
        out.sort_values(["seed", "_line", "file", "example"], kind="stable")
        .drop(columns="_line")
        .reset_index(drop=True)
    )


def document_order(*frames: pd.DataFrame) -> dict[tuple[str, str], int]:
    """``{(seed, source): line}``: the first seed-file line of each source over the given values /
    claims / params frames, i.e. where the paper prints it. Sorting sources by it gives the paper's
    order ("Table 4.3" before "Fig. 5.7" before "Section 5.5"), not the string order.

    Parameters
    ----------
    *frames : pandas.DataFrame
        Frames with ``seed``, ``source`` and ``line`` columns.

    Returns
    -------
    dict
        ``{(seed, source): first line}``.

    Raises
    ------
    ValueError
        If a frame lacks a column.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import document_order
    >>> frame = pd.DataFrame({"seed": ["000"] * 3, "source": ["Fig. 5.7", "Table 4.3", "Table 4.3"], "line": [640, 370, 366]})
    >>> sorted(document_order(frame).items(), key=lambda item: item[1])
    [(('000', 'Table 4.3'), 366), (('000', 'Fig. 5.7'), 640)]
    """
    order: dict[tuple[str, str], int] = {}
    for f in frames:
        missing = [c for c in ("seed", "source", "line") if c not in f.columns]
        if missing:
            raise ValueError(f"frame lacks columns {missing} (pass frames of load())")
        for (s, src), line in f.groupby(["seed", "source"])["line"].min().items():
            order[(s, src)] = min(int(line), order.get((s, src), int(line)))
    return order
