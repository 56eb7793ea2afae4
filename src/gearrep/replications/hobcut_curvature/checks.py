"""Check records of seed 000 ch. 4: every printed value of Tables 4.3/4.4 (at the printed l_1,
with the rounded-l_1 allowance derived by differentiation) and the chapter's claims
(:mod:`.claims`)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import checks as _checks
from .claims import claim_records, normalise

__all__ = ["check_records", "checks", "SURVIVING"]

SURVIVING = ("4.3", "4.4")


def _grid_ok(pub_row, value):
    lo, hi, _ = _checks.printed_interval(pub_row["printed"], pub_row["rounding"])
    return lo - 1e-12 * max(abs(value), 1e-300) <= value <= hi + 1e-12 * max(abs(value), 1e-300)


def _value_record(pub, r, l_pr) -> dict:
    """The record of one printed value against its computed detail row ``r``."""
    q = pub["quantity"]
    comp = float(r[f"{q}_printed_l"])
    grid_v = float(r[f"{q}_grid"])
    flip = ""
    if q == "e_s_z" and np.sign(float(pub["value"])) == -1:
        # a principal direction is a line: e_s and -e_s are the same (published-data note)
        comp, grid_v = -comp, -grid_v
        flip = (
            "compared up to sign: printed -1.000 while every other row prints +1.000 and a principal "
            "direction is a line (erratum listed); "
        )
    allowance = abs(float(r[f"d_{q}_dl1"])) * 0.5 * 10.0 ** (-3)
    grid_ok = _grid_ok(pub, grid_v)
    note = (
        f"{flip}computed at the printed l1 = {l_pr:.3f} mm; at the reconstructed l1 grid "
        f"{r['l1_grid_mm']:.7f} mm: {grid_v:.10g} (error {grid_v - float(pub['value']):.2e}, "
        f"{'within' if grid_ok else 'OUTSIDE'} the printed half-unit without allowance)"
    )
    if allowance > 0:
        return _checks.compare_value(
            pub,
            comp,
            extra_tol=allowance,
            extra_basis=f"l1 is printed to 3 decimals (+-0.0005 mm) and |d {q}/d l1| = "
            f"{abs(float(r[f'd_{q}_dl1'])):.3g} per mm (central difference)",
            note=note,
        )
    return _checks.compare_value(pub, comp, note=note)


def check_records(tables: dict, published) -> pd.DataFrame:
    """Check records for Tables 4.3/4.4 (every printed value) and the chapter-4 claims."""
    vals = published.values
    tables = normalise(tables)
    d = tables["curvature_detail"]
    recs = []
    for tab in SURVIVING:
        pv = vals[(vals["seed"] == "000") & (vals["source"] == f"Table {tab}")]
        dt = d[d["table"] == tab]
        for _, pub in pv.iterrows():
            l_pr = float(pub["row"].split("=")[1])
            m = dt[np.isclose(dt["l1_printed_mm"], l_pr, atol=1e-9)]
            if len(m) != 1:
                recs.append(
                    _checks.not_computed(pv[pv["id"] == pub["id"]], f"no computed row at l1={l_pr}").iloc[0].to_dict()
                )
                continue
            recs.append(_value_record(pub, m.iloc[0], l_pr))
    recs.extend(claim_records(tables, published))
    return _checks.validate_checks(pd.DataFrame(recs, columns=_checks.CHECK_COLUMNS))


def checks(tables: dict, published) -> dict:
    """{"checks": records of every value of Tables 4.3/4.4 and the chapter-4 claims}."""
    return {"checks": check_records(tables, published)}
