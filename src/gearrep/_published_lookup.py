"""Look-ups on the frames of the published data (:func:`gearrep.published.load`): a row key's
parts, one example's parameters, values by key, the design table of every example and the
document order of the sources. Public names of :mod:`gearrep.published`; this module is their home.
"""

from __future__ import annotations

import pandas as pd

from ._published_format import PARAM_COLUMNS, SEEDS, PublishedDataError

__all__ = ["parse_row", "param_table", "values_by", "design_table", "document_order"]


def parse_row(row: str) -> dict[str, str]:
    """``'l1_mm=4.381;side=L'`` -> ``{'l1_mm': '4.381', 'side': 'L'}``."""
    out = {}
    for part in filter(None, (p.strip() for p in str(row).split(";"))):
        k, sep, val = part.partition("=")
        if not sep:
            raise PublishedDataError(f"row key part {part!r} is not name=value")
        out[k.strip()] = val.strip()
    return out


def param_table(params: pd.DataFrame, file: str, example: str | None = None) -> dict[str, float]:
    """``{parameter: value}`` of one params file (and example), in the file's units."""
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
    the caller's to refuse."""
    out: dict[tuple, list] = {}
    for key, v in zip(zip(*(frame[k].tolist() for k in keys)), frame["value"].tolist()):
        out.setdefault(key, []).append(v)
    return out


def design_table(params: pd.DataFrame, seed: str | None = None) -> pd.DataFrame:
    """The design data of every example (of ``seed``, if given), one row per example in the
    order the document prints them: columns ``seed``, ``example``, ``source`` (where it is
    printed, with its first seed-file line), ``file`` (its params files) and ``design``
    (``name = printed unit; ...`` as printed, in the files' order; ``name = (not printed)`` for a
    value the text only implies)."""
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
    order ("Table 4.3" before "Fig. 5.7" before "Section 5.5"), not the string order."""
    order: dict[tuple[str, str], int] = {}
    for f in frames:
        missing = [c for c in ("seed", "source", "line") if c not in f.columns]
        if missing:
            raise ValueError(f"frame lacks columns {missing} (pass frames of load())")
        for (s, src), line in f.groupby(["seed", "source"])["line"].min().items():
            order[(s, src)] = min(int(line), order.get((s, src), int(line)))
    return order
