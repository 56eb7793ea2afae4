"""Verdicts of the sweep claims of Figs 12, 13 and 15 (S along the meshing cycle for a swept
module, tooth-line radius or gear tooth number) for one flank pair and reading of phi1.

Each kind of claim is one small function of the curves S(phi) of the swept designs; the table
:data:`SWEEP_VERDICTS` maps the kind to it. A curve is the ``cycle`` rows of one design, pair and
reading inside the window and (except for the cliff) on the real path.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

__all__ = ["SWEEPS", "CycleIndex", "curve", "sweep_curves", "verdict_sweep", "verdict_cliff", "SWEEP_VERDICTS"]

#: figure -> (design group, swept column, sweep values, fixed selectors (one curve family each))
SWEEPS = {
    "F12": ("fig12", "module_mm", [4.0, 8.0, 12.0, 16.0], [{}]),
    "F13": ("fig13", "R_T_mm", [300.0, 400.0, 500.0, 600.0, 800.0], [{"z2": 29}, {"z2": 89}]),
    "F15": ("fig15", "z2", [29, 49, 69, 89, 109], [{}]),
}


class CycleIndex:
    """The cycle table split once by (design, pair, reading), plus one row per design, and the
    designs and curves looked up so far (the claims ask for 19 designs 324 times and 156 curves
    328 times)."""

    def __init__(self, df: pd.DataFrame):
        self.by = {k: g for k, g in df.groupby(["design", "pair", "reading"], sort=False)}
        self.designs = df.drop_duplicates("design")
        self.found: dict = {}


def _design(cycle: CycleIndex, fig, v, fixed) -> str:
    key = ("design", fig, v, tuple(sorted(fixed.items())))
    if key not in cycle.found:
        cycle.found[key] = _find_design(cycle, fig, v, fixed)
    return cycle.found[key]


#: a sweep value names the design whose parameter was printed as that value: they agree to rounding
_SAME_VALUE_RTOL = 1e-9


def _find_design(cycle: CycleIndex, fig, v, fixed) -> str:
    group, col = SWEEPS[fig][:2]
    d = cycle.designs
    # a design's value is the printed one as read (within rounding: 1e-9 relative), not its bits
    sel = d[(d["group"] == group) & np.isclose(d[col], v, rtol=_SAME_VALUE_RTOL, atol=0.0)]
    for k, x in fixed.items():
        sel = sel[np.isclose(sel[k], x, rtol=_SAME_VALUE_RTOL, atol=0.0)]
    names = sorted(set(sel["design"]))
    if len(names) != 1:
        raise ValueError(f"{fig}: expected one design with {col}={v} {fixed}, found {names}")
    return names[0]


def curve(cycle: CycleIndex, design, pair, reading, on_path_only=True) -> pd.DataFrame:
    """Rows of one design, pair and reading inside the window (and on the path), by phi (one frame
    per curve for all verdicts: read, never written)."""
    key = ("curve", design, pair, reading, bool(on_path_only))
    if key not in cycle.found:
        c = cycle.by[(design, pair, reading)]
        c = c[c["in_window"].astype(bool)]
        if on_path_only:
            c = c[c["on_path"].astype(bool)]
        cycle.found[key] = c.sort_values("phi_paper_deg")
    return cycle.found[key]


def sweep_curves(cycle: CycleIndex, fig, pair, reading, fixed) -> dict:
    """{sweep value: curve} of one curve family of a figure."""
    return {v: curve(cycle, _design(cycle, fig, v, fixed), pair, reading) for v in SWEEPS[fig][2]}


def _drop_start(c, near_top_lo):
    """Angle of the maximum of S over the curve (where any fall starts) and whether it lies in the
    near-top zone (phi >= near_top_lo) or at the end of the curve."""
    i = int(np.argmax(c["S_mm2"].to_numpy()))
    ph = c["phi_paper_deg"].to_numpy()
    return float(ph[i]), bool(ph[i] >= near_top_lo - 1e-9 or i == len(ph) - 1)


def _rise(c, near_top_lo, concave=False):
    """Root-to-top growth of one curve over its pre-drop part: (holds, numbers)."""
    ph, S = c["phi_paper_deg"].to_numpy(), c["S_mm2"].to_numpy()
    t_drop, in_zone = _drop_start(c, near_top_lo)
    end = t_drop if in_zone else max(t_drop, near_top_lo)
    Sm = S[ph <= end + 1e-9]
    draw = float(np.max((np.maximum.accumulate(Sm) - Sm) / np.maximum.accumulate(Sm)))
    nondec = bool(np.all(np.diff(Sm) >= -1e-12 * Sm[:-1]))
    info = {
        "phi_max_S_deg": t_drop,
        "drop_in_near_top_zone": in_zone,
        "max_drawdown_pre_drop": draw,
        "S_start_mm2": float(Sm[0]),
        "S_pre_drop_end_mm2": float(Sm[-1]),
    }
    ok = nondec and bool(Sm[-1] > Sm[0]) and in_zone
    if concave:
        d2 = np.diff(Sm, 2)
        frac = float(np.mean(d2 > 1e-9 * np.max(Sm))) if len(d2) else 0.0
        info["fraction_slope_increasing"] = frac
        ok = ok and frac == 0.0
    return ok, info


def _fmt(d):
    return ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in d.items())


def _at(c, phi):
    ph, S = c["phi_paper_deg"].to_numpy(), c["S_mm2"].to_numpy()
    return float(np.interp(phi, ph, S)) if ph[0] - 1e-9 <= phi <= ph[-1] + 1e-9 else np.nan


def _order(vals, increasing):
    v = np.asarray(vals, float)
    if not np.all(np.isfinite(v)):
        return False
    d = np.diff(v)
    return bool(np.all(d > 0) if increasing else np.all(d < 0))


def _root_top_angles(curves, params):
    """The near-root angle (latest of the window start and the curves' path starts), the near-top
    angle (earliest of near_top_eval_deg, the drops and the curves' ends, not below the root
    angle) and whether some curve falls from its first point (no pre-drop near-top angle)."""
    nt_lo = params["window_deg"][1] - params["near_top_deg"]
    root = max([params["window_deg"][0]] + [float(c["phi_paper_deg"].iloc[0]) for c in curves.values()])
    drops = [_drop_start(c, nt_lo)[0] for c in curves.values()]
    top = min([params["near_top_eval_deg"]] + drops + [float(c["phi_paper_deg"].iloc[-1]) for c in curves.values()])
    return root, max(top, root), top <= root + 1e-9


def _v_rise(concave):
    def verdict(fig, curves, tag, params):
        nt_lo = params["window_deg"][1] - params["near_top_deg"]
        oks, infos = [], []
        for v, c in curves.items():
            ok, inf = _rise(c, nt_lo, concave=concave or fig == "F15")
            oks.append(ok)
            infos.append(f"[{tag}{' ' if tag else ''}{v:g}: {'ok' if ok else 'FAIL'} {_fmt(inf)}]")
        return oks, infos

    return verdict


def _v_falls_near_root(fig, curves, tag, params):
    root, _, _ = _root_top_angles(curves, params)
    Sr = [_at(c, root) for c in curves.values()]
    return [_order(Sr, increasing=False)], [f"[{tag} phi_root={root:.3g} deg: S={np.round(Sr, 3).tolist()} mm2]"]


def _v_grows_near_top(fig, curves, tag, params):
    _, top, no_top = _root_top_angles(curves, params)
    St = [_at(c, top) for c in curves.values()]
    note = "; a curve falls from the root on, no near-top angle before its drop" if no_top else ""
    return [_order(St, increasing=True) and not no_top], [
        f"[{tag} phi_top={top:.3g} deg: S={np.round(St, 3).tolist()} mm2{note}]"
    ]


def _v_top_more_sensitive(fig, curves, tag, params):
    root, top, no_top = _root_top_angles(curves, params)
    vals = list(curves)
    spread_r = np.ptp([_at(c, root) for c in curves.values()])
    spread_t = np.ptp([_at(c, top) for c in curves.values()])
    lo_c, hi_c = curves[vals[0]], curves[vals[-1]]
    ph = np.intersect1d(np.round(lo_c["phi_paper_deg"], 9), np.round(hi_c["phi_paper_deg"], 9))
    dd = np.array([_at(lo_c, x) - _at(hi_c, x) for x in ph])
    sc = np.nonzero(np.sign(dd[1:]) != np.sign(dd[:-1]))[0]
    cross = [float(ph[i] - dd[i] * (ph[i + 1] - ph[i]) / (dd[i + 1] - dd[i])) for i in sc]
    ok = bool(spread_t > spread_r and len(cross) > 0 and all(x < 0 for x in cross)) and not no_top
    return [ok], [
        f"[{tag} spread root ({root:.3g} deg)={spread_r:.4g}, top ({top:.3g} deg)={spread_t:.4g} mm2; "
        f"crossings of {vals[0]:g} and {vals[-1]:g} at {np.round(cross, 2).tolist()} deg]"
    ]


def _v_grows_with_RT(fig, curves, tag, params):
    nt_lo = params["window_deg"][1] - params["near_top_deg"]
    vals = list(curves)
    drops = min(_drop_start(c, nt_lo)[0] for c in curves.values())
    common = sorted(set.intersection(*(set(np.round(c["phi_paper_deg"], 9)) for c in curves.values())))
    common = [x for x in common if x < drops - 1e-9] or common[:1]
    bad = [x for x in common if not _order([_at(curves[v], x) for v in vals], increasing=True)]
    s0 = [_at(curves[v], 0.0) for v in vals]
    return [not bad], [
        f"[{tag}: ordered at {len(common) - len(bad)}/{len(common)} angles below {drops:.3g} deg; "
        f"S(phi=0)={np.round(s0, 3).tolist()} mm2]"
    ]


def _v_gain_diminishing(fig, curves, tag, params):
    vals = list(curves)
    S0 = np.array([_at(curves[v], 0.0) for v in vals])
    g = np.diff(S0) / np.diff(np.asarray(vals, float))
    return [bool(np.all(np.diff(g) < 0))], [
        f"[{tag}: gain per mm at phi=0: {np.array2string(g, precision=7)} mm2/mm; "
        f"relative fall of the gain from the first to the last step "
        f"{1 - g[-1] / g[0]:.2e}]"
    ]


#: kind of sweep claim -> verdict(fig, curves of one family, family tag, params) -> (oks, infos)
SWEEP_VERDICTS = {
    "root_to_top": _v_rise(concave=False),
    "root_to_top_falling_rate": _v_rise(concave=True),
    "falls_near_root": _v_falls_near_root,
    "grows_near_top": _v_grows_near_top,
    "top_more_sensitive": _v_top_more_sensitive,
    "grows_with_RT": _v_grows_with_RT,
    "gain_diminishing": _v_gain_diminishing,
}


def verdict_sweep(kind, fig, cycle: CycleIndex, pair, reading, params):
    """Verdict and numbers of one sweep claim for one (pair, reading)."""
    oks, infos = [], []
    for fixed in SWEEPS[fig][3]:
        tag = ",".join(f"{k}={v}" for k, v in fixed.items())
        o, i = SWEEP_VERDICTS[kind](fig, sweep_curves(cycle, fig, pair, reading, fixed), tag, params)
        oks += o
        infos += i
    return bool(all(oks)), " ".join(infos)


def _cliff_of(c, params):
    """(reaches a flank edge, holds, info) of one curve: the clipped area S_clipped (0 off the
    path) against the paper's pi a b over the window."""
    whi = params["window_deg"][1]
    ph = c["phi_paper_deg"].to_numpy()
    Sc = np.where(c["on_path"].astype(bool), c["S_clipped_mm2"].to_numpy(), 0.0)
    Su = c["S_mm2"].to_numpy()
    i = int(np.argmax(Sc))
    after = slice(i, len(ph))
    # the grid ends at most off_path_margin_deg beyond the path; past it there is no contact
    reaches_edge = bool(ph[-1] < whi - 1e-9 or np.any(Sc[after] < Su[after] * (1 - 1e-6)))
    drop_c = 1.0 - (0.0 if ph[-1] < whi - 1e-9 else float(np.min(Sc[after]))) / Sc[i]
    below = np.nonzero(Sc[after] < 0.7 * Sc[i])[0]
    phi_drop = float(ph[i + below[0]]) if len(below) else (float(ph[-1]) if ph[-1] < whi - 1e-9 else np.nan)
    iu = int(np.nanargmax(Su))
    drop_u = 1.0 - float(np.nanmin(Su[iu:])) / Su[iu]
    ok = (not reaches_edge) or (
        drop_c >= 0.3 and np.isfinite(phi_drop) and phi_drop >= whi - params["near_top_deg"] - 1e-9
    )
    onp = c["on_path"].astype(bool).to_numpy()
    root_ratio = float(Sc[onp][0] / Su[onp][0]) if onp.any() else np.nan
    return (
        reaches_edge,
        ok,
        (
            f"clipped drop {100 * drop_c:.0f}% at {phi_drop:.3g} deg, pi*a*b drop "
            f"{100 * drop_u:.1f}%, clipped/unclipped at the path start {root_ratio:.2f}]"
        ),
    )


def verdict_cliff(fig, cycle: CycleIndex, pair, reading, params):
    """Cliff near the top: the truncated ellipse area drops by 30 % or more in the near-top zone
    on every curve that reaches a flank edge in the window (and at least one does)."""
    _, _, values, fixeds = SWEEPS[fig]
    oks, infos, n_edge = [], [], 0
    for fixed in fixeds:
        tag = ",".join(f"{k}={x}" for k, x in fixed.items())
        for v in values:
            c = curve(cycle, _design(cycle, fig, v, fixed), pair, reading, on_path_only=False)
            edge, ok, info = _cliff_of(c, params)
            n_edge += edge
            oks.append(ok)
            infos.append(f"[{tag}{' ' if tag else ''}{v:g}: {info}")
    return bool(all(oks) and n_edge > 0), f"{n_edge} curves reach a flank edge in the window. " + " ".join(infos)
