"""Chapter-4 claims of seed 000: a table of claim id -> predicate.

Each predicate takes the computed tables (``table`` keys normalised to "4.x") and the published
values and returns (holds, evidence text)."""

from __future__ import annotations

from functools import partial

import numpy as np
import pandas as pd

from ... import checks as _checks
from .studies import TABLES

__all__ = ["CLAIMS", "claim_records", "normalise"]


def normalise(tables: dict) -> dict:
    """Tables read back from CSV: the ``table`` key as the string "4.x"."""
    out = dict(tables)
    for name in ("curvature_detail", "variants"):
        if name in out:
            out[name] = out[name].assign(table=out[name]["table"].map(lambda x: f"{float(x):.1f}"))
    return out


def _fmt(a, n=6):
    return np.array2string(np.asarray(a, float), precision=n, separator=", ")


def _four(tables) -> dict:
    return {t: tables[f"curvature_table_{t.replace('.', '_')}"] for t in TABLES}


def _against_printed(tables, vals, tab: str, ref: str):
    """The predicted k_q, e_q of Table ``tab`` against the printed Table ``ref`` with the value
    checks' comparison (at the printed l1, allowance from d/dl1): (n reproduced, n, worst |k_q error|)."""
    det = tables["curvature_detail"]
    dm = det[det["table"] == tab].set_index("l1_printed_mm")
    pv = vals[(vals["source"] == f"Table {ref}") & vals["quantity"].isin(["k_q", "e_q_x", "e_q_y"])]
    n_ok, worst = 0, 0.0
    for _, pub in pv.iterrows():
        r = dm.loc[float(pub["row"].split("=")[1])]
        q = pub["quantity"]
        al = abs(float(r[f"d_{q}_dl1"])) * 0.5e-3
        rec = _checks.compare_value(pub, float(r[f"{q}_printed_l"]), extra_tol=al, extra_basis="rounded l1")
        n_ok += rec["status"] == "reproduced"
        if q == "k_q":
            worst = max(worst, abs(rec["abs_err"]))
    return n_ok, len(pv), worst


def _missing_table(tables, vals, *, tab: str, ref: str, hyper: bool):
    """A missing table predicted by the surviving block of the other R_c (same k_q, e_q)."""
    T = _four(tables)
    t = T[tab]
    prod = t["k_s_per_mm"] * t["k_q_per_mm"]
    sign_ok = bool(np.all(prod < 0)) if hyper else bool(np.all(prod > 0))
    es_ok = bool(np.all(np.abs(t[["e_s_x", "e_s_y"]].to_numpy()) < 5e-4) and np.all(np.abs(t["e_q_z"]) < 5e-4))
    n_ok, n, worst = _against_printed(tables, vals, tab, ref)
    ks_other = T[ref]["k_s_per_mm"].to_numpy()
    holds = sign_ok and es_ok and n_ok == n and bool(np.all(np.abs(t["k_s_per_mm"] - ks_other) > 1e-6))
    return holds, (
        f"computed Table {tab} (no printed data) at the 11 rows: k_s = {_fmt(t['k_s_per_mm'], 7)} 1/mm, "
        f"k_q = {_fmt(t['k_q_per_mm'])} 1/mm; sign of k_s*k_q as stated: {sign_ok}; e_s = (0,0,1) and e_q_z = 0: "
        f"{es_ok}; k_q, e_q_x, e_q_y equal the printed Table {ref} values within printed rounding (+ the rounded-l1 "
        f"allowance, as the value checks) in {n_ok}/{n} cases (max |k_q error| {worst:.2e} 1/mm at the "
        f"printed l1); k_s differs from Table {ref}'s (R_c changes it)."
    )


def _e_s_along_zf(tables, vals):
    allt = pd.concat(_four(tables).values())
    dev = float(np.max(np.abs(allt[["e_s_x", "e_s_y", "e_q_z"]].to_numpy())))
    return dev < 5e-4, (
        f"all four computed tables (44 rows): max |e_s_x|, |e_s_y|, |e_q_z| = {dev:.1e} (criterion "
        f"5e-4); e_s_z = {allt['e_s_z'].min():.12f}..{allt['e_s_z'].max():.12f}."
    )


def _surface_kind(tables, vals, *, tabs: tuple, hyper: bool):
    T = _four(tables)
    ks = np.concatenate([T[t]["k_s_per_mm"] for t in tabs])
    kq = np.concatenate([T[t]["k_q_per_mm"] for t in tabs])
    prod = np.concatenate([T[t]["k_s_per_mm"] * T[t]["k_q_per_mm"] for t in tabs])
    ok = bool(np.all(ks > 0) and np.all(kq < 0)) if hyper else bool(np.all(prod > 0))
    return ok, (
        f"Tables {tabs[0]} and {tabs[1]} (R_c = 110 and 5000 mm): k_s*k_q from {prod.min():.3e} to "
        f"{prod.max():.3e} 1/mm^2 over the 22 rows; k_s range {ks.min():.4e}..{ks.max():.4e}."
    )


def _only_k_s_depends_on_rc(tables, vals):
    T = _four(tables)
    dq = max(
        float(np.max(np.abs(T["4.2"]["k_q_per_mm"] - T["4.4"]["k_q_per_mm"]))),
        float(np.max(np.abs(T["4.3"]["k_q_per_mm"] - T["4.5"]["k_q_per_mm"]))),
    )
    de = max(
        float(np.max(np.abs(T[a][["e_q_x", "e_q_y"]].to_numpy() - T[b][["e_q_x", "e_q_y"]].to_numpy())))
        for a, b in (("4.2", "4.4"), ("4.3", "4.5"))
    )
    dks = float(np.min(np.abs(T["4.3"]["k_s_per_mm"] - T["4.5"]["k_s_per_mm"])))
    return dq < 0.5e-6 and de < 5e-4 and dks > 1e-4, (
        f"same flank, R_c 110 vs 5000: max |dk_q| = {dq:.1e} 1/mm, max |de_q| = {de:.1e} (e_s along Z_f in both), "
        f"min |dk_s| = {dks:.3e} 1/mm: the mid-face profile (psi = 0) does not see R_c, the trace curvature does."
    )


def _l1_range(tables, vals):
    det = tables["curvature_detail"]
    first = det[(det["table"] == "4.3") & (det["row"] == 0)].iloc[0]
    lastr = det[(det["table"] == "4.3") & (det["row"] == det["row"].max())].iloc[0]
    und = tables.get("undercut")
    mid = und[und["psi_rad"] == 0.0] if und is not None else None
    und_ok = bool(
        mid is None
        or (mid["all_converged"].all() and not mid["any_singular"].any() and (mid["det_sign_changes"] == 0).all())
    )
    ends = und[(und["psi_rad"] != 0.0) & (und["det_sign_changes"] > 0)] if und is not None else und
    ends_txt = (
        "; at the face ends (psi = +-asin(b/2R_c)) a singular point enters the last rows: "
        + ", ".join(
            f"{r.flank} R_c={r.R_c_mm:g} Z_f={r.Z_f_singular_mm:.1f}: l1={r.l1_singular_mm:.3f} (r={r.radius_singular_mm:.3f})"
            for r in ends.itertuples()
        )
        if ends is not None and len(ends)
        else ""
    )
    ok = abs(first["l1_grid_mm"] - 4.381) <= 5e-4 and und_ok
    return bool(ok), (
        f"l1 giving r = 33.000 mm (tip circle of the Table 5.1 pinion, d_a = 66) at mid-face: {first['l1_grid_mm']:.7f} mm "
        f"(printed 4.381); l1 = {lastr['l1_grid_mm']:.3f} gives r = {lastr['radius_mm']:.4f} mm (base radius "
        f"{30 * np.cos(np.radians(20)):.4f}: the lower end of the generated involute-like working profile). No singular "
        f"(undercut) point between them on either flank at mid-face: {und_ok} (min Litvin measure "
        f"{float(mid['min_singular_measure'].min()) if mid is not None else float('nan'):.2e}){ends_txt}."
    )


#: claim id -> predicate(tables, published values) -> (holds, evidence text)
CLAIMS = {
    "000-T4.2-missing": partial(_missing_table, tab="4.2", ref="4.4", hyper=True),
    "000-T4.5-missing": partial(_missing_table, tab="4.5", ref="4.3", hyper=False),
    "000-ch4-e_s-along-Zf": _e_s_along_zf,
    "000-ch4-Sigma2L-hyperbolic": partial(_surface_kind, tabs=("4.2", "4.4"), hyper=True),
    "000-ch4-Sigma2R-elliptic": partial(_surface_kind, tabs=("4.3", "4.5"), hyper=False),
    "000-ch4-only-k_s-depends-on-R_c": _only_k_s_depends_on_rc,
    "000-ch4-l1-range": _l1_range,
}


def claim_records(tables: dict, published) -> list[dict]:
    """One qualitative record per claim of :data:`CLAIMS`."""
    tables = normalise(tables)
    cl = published.claims.set_index("id", drop=False)
    recs = []
    for cid, predicate in CLAIMS.items():
        holds, evidence = predicate(tables, published.values)
        recs.append(_checks.qualitative(cl.loc[cid], holds, evidence))
    return recs
