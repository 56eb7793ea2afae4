"""Straight and spiral bevel gears of the thesis (sec 5.1-5.2, 6.3-6.4, Tables 5-7, 11-12).

The pairs are spherical-involute bevel gears (:mod:`gearrep.surfaces.bevel`, eq 48-51) on
intersecting axes (:class:`gearrep.tca.BevelPair`, misalignments eq 47-48). Everything that is
computed here:

* the convergence study of Tables 11 (straight bevel 39/32) and 12 (spiral bevel 17/17) with the
  protocol of Table 10 (:func:`.bevel_convergence.bevel_convergence`; rows of ``convergence.csv``);
* the contact studies of sec 5.1-5.2 (:func:`bevel_contact_tables`): TE over a mesh cycle (upper
  envelope of the tooth pairs, :mod:`gearrep.meshing`), path of contact and the Hertz maximum
  contact pressure along it (:mod:`gearrep.ellipse`) under the thesis's misalignments.

Readings where the thesis prints nothing (:data:`READINGS`, also in protocol.csv): the pressure
angle of the spiral pair (20 deg, as for every other pair of the thesis; with the design data,
:data:`.design.READINGS`); phi1 of the convergence
studies (0 in our frame: the aligned pair's conjugate position, contact near mid-face); the crown
of the Table 11 pair (Table 10's a_1 scaled to m = 2.5); the crown of the Table 12 pair (Table 7's
smallest c_1 = 0.002); the straight pair's crown and relief amounts of sec 5.1 (settings); the
reading of sec 5.2's z-axis error dH as member 2's axial displacement dG (Fig 31 d); the relief
length L_t in module units along the profile at the mean cone distance, starting L_t below the
tip (:func:`gearrep.surfaces.bevel.relief_from_length`); the relief amount c_t and the lead crown
c_1 in module units (non-dimensional, eq 52); the spiral pair's flank pair (gear 1's lengthwise
convex flank against gear 2's concave one, :data:`FLANK_PAIRS`; the other pair is run beside).
Member 1 is gear 1 (the crowned member, N1 teeth) and drives (phi1 given); the thesis calls the
crowned member "driven" in sec 5.1. A TE amplitude is the peak-to-peak of the transmitted TE (the
thesis counts a constant offset as no TE, sec 5.2); pitch-point quantities are taken where the
contact lies on gear 1's pitch cone (:func:`pitch_cone_contact`), not at phi1 = 0.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...curvature import relative_curvature
from ...ellipse import hertz_contact
from ...meshing import sampled_cycle
from ...surfaces.bevel import BevelGearData, mating_bevel_flanks, relief_from_length, spherical_involute_azimuth
from ...surfaces.involute import CircularCrowning, LogarithmicCrowning, ParabolicCrowning, RootRelief
from ...tca import BevelMisalignment, BevelPair, contact_curvatures, solve_contact
from ...units import ARCSEC, DEG
from .te import JUMP_TOL_ARCSEC, PAIRS

CASES = ("straight_bevel_39_32", "spiral_bevel_17_17")
#: our readings where the thesis prints nothing (module docstring)
READINGS = {
    "phi1_rad": 0.0,
    "dH_is_dG": True,
}
#: the two flank pairs of the spiral pair: gear 1's spiral hand in gearrep.surfaces.bevel (gear 2 has
#: the opposite one) for gear 1's lengthwise convex (``convex1``) or concave (``concave1``) flank
#: meshing; the straight pair has no lengthwise curvature and uses ``convex1``
FLANK_PAIRS = {"convex1": 1, "concave1": -1}
#: the transmitted TE's extremes are read at this many times the cycle's angles (bevel_te_study):
#: the spiral TE rows' peak-to-peak then moves by <= 0.01 arcsec from 121 to 481 contact angles
#: per cycle, where the cycle's own angles miss the hand-over dips by up to 2.5 arcsec at 31
CYCLE_REFINE = 64
#: the random stream of each bevel convergence study (default_rng([seed, stream]); 1-12 are the
#: cylindrical studies' in :data:`.convergence.STREAMS`)
BEVEL_STREAMS = {"straight_bevel_39_32": 21, "spiral_bevel_17_17": 22}


def bevel_gears(pair_data: dict) -> tuple[BevelGearData, BevelGearData]:
    kw = dict(
        module=pair_data["module"],
        pressure_angle=pair_data["pressure_angle_deg"] * DEG,
        face_width=pair_data["face_width"],
        shaft_angle=pair_data["shaft_angle_deg"] * DEG,
        spiral_angle=pair_data["spiral_angle_deg"] * DEG,
    )
    return BevelGearData(pair_data["n1"], pair_data["n2"], **kw), BevelGearData(pair_data["n2"], pair_data["n1"], **kw)


def lead_crown(g: BevelGearData, kind: str, amount: float, log_a2: float = 0.9):
    """Longitudinal crown on gear 1 about the mean cone distance: ``parabolic`` c_1 [1/length]
    (eq 10), ``circular`` c_c [length] at the face ends (eq 11), ``logarithmic`` a_1 [length] with
    a_2 = ``log_a2`` (eq 12); amount 0 gives None."""
    if amount == 0:
        return None
    rm = g.mean_cone_distance
    if kind == "parabolic":
        return ParabolicCrowning(amount, v0=rm)
    if kind == "circular":
        return CircularCrowning(amount, g.face_width, v0=rm)
    if kind == "logarithmic":
        return LogarithmicCrowning(amount, log_a2, 0.5 * g.face_width, v0=rm)
    raise ValueError(f"kind must be 'parabolic', 'circular' or 'logarithmic', got {kind!r}")


def active_profile_start(design, case: str, hand1: int = 1) -> float:
    """Polar angle on gear 1 where the contact of the aligned unmodified pair begins at the mean
    cone distance (the tip of gear 2 reaches it): the start of gear 1's active profile. The root
    relief of sec 5.2 ("tip/root relief") starts its length L above this point (our reading: a
    relief below it would never be in contact)."""
    d = design.pairs[case]
    g1, g2 = bevel_gears(d)
    f1, f2 = mating_bevel_flanks(g1, g2, hand1=hand1)
    pair = BevelPair(f1, f2, d["n1"], d["n2"], shaft_angle=d["shaft_angle_deg"] * DEG)
    p1 = 2 * np.pi / d["n1"]
    phi = np.linspace(-1.5 * p1, 0.0, 121)
    with np.errstate(invalid="ignore", divide="ignore"):
        c = solve_contact(
            pair, phi, np.array([[g1.pitch_cone_angle, g1.mean_cone_distance]]), v1=g1.mean_cone_distance, tol=1e-12
        )
    ok = c.converged
    if ok.sum() < 2 or ok[0]:
        raise ValueError(f"{case}: the start of the active profile is not inside the angle grid")
    return float(c.u1[ok].min())


def bevel_pair(
    design,
    case: str,
    *,
    crown_kind="parabolic",
    crown=0.0,
    tip=None,
    root=None,
    misalignment=None,
    log_a2=0.9,
    flank_pair="convex1",
) -> BevelPair:
    """The bevel pair ``case`` with a lead crown and tip/root relief (L, c) on gear 1 (lengths in the
    pair's units: mm for the straight pair, module units for the spiral one). ``flank_pair``
    (:data:`FLANK_PAIRS`) picks which flanks of the spiral pair mesh: ``convex1`` (gear 1's
    lengthwise convex flank against gear 2's concave one) or ``concave1`` (the other flank pair)."""
    hand1 = FLANK_PAIRS[flank_pair]
    d = design.pairs[case]
    g1, g2 = bevel_gears(d)
    relief = []
    if tip is not None and tip[1] > 0:
        relief.append(relief_from_length(g1, tip[0], tip[1]))
    if root is not None and root[1] > 0:
        w = root[0] / g1.mean_cone_distance
        relief.append(RootRelief(active_profile_start(design, case, hand1) + w, w, root[1]))
    f1, f2 = mating_bevel_flanks(
        g1, g2, hand1=hand1, crowning1=lead_crown(g1, crown_kind, crown, log_a2), relief1=relief
    )
    return BevelPair(f1, f2, d["n1"], d["n2"], shaft_angle=d["shaft_angle_deg"] * DEG, misalignment=misalignment)


# ----------------------------------------------------------------------------------------------
# contact studies (sec 5.1-5.2)
# ----------------------------------------------------------------------------------------------


def _solve_grid(pair: BevelPair, phi: np.ndarray, tol: float, rounds: int = 30):
    """Contact points of ``pair`` at every angle of the sorted grid ``phi`` (vectorised): a verified
    start at the grid angle nearest 0 (several starts along the profile), then every angle from a
    linear predictor in phi1 and from a 4 x 3 grid of starts on flank 1 (of the roots found at one
    angle, the one of largest TE: the tangency member 2 is pushed to), then repair rounds that
    restart the failed angles next to a converged one from that neighbour's solution (the rounds
    stop when no angle is gained). None if no start converges."""
    i0 = int(np.argmin(np.abs(phi)))
    lo, hi = pair.lower1, pair.upper1
    u0 = lo[0] + np.array([0.5, 0.3, 0.7, 0.15, 0.85, 0.05, 0.95]) * (hi[0] - lo[0])
    best = None
    for vf in (0.5, 0.25, 0.75):
        st = np.column_stack([u0, np.full(len(u0), lo[1] + vf * (hi[1] - lo[1]))])
        c0 = solve_contact(pair, np.full(len(u0), phi[i0]), st, tol=tol, damped=True, maxiter=100)
        ok = np.flatnonzero(c0.converged)
        if len(ok):
            best = c0.unknowns()[ok[0]]
            break
    if best is None:
        return None
    j = i0 + 1 if i0 + 1 < len(phi) else i0 - 1
    c1 = solve_contact(pair, phi[j], best[None, :], tol=tol, damped=False, maxiter=30)
    slope = (c1.unknowns()[0] - best) / (phi[j] - phi[i0]) if c1.converged[0] else np.zeros(2)
    x = np.clip(best + np.outer(phi - phi[i0], slope), lo, hi)
    # every angle from the predictor and from a 4 x 3 grid of starts on flank 1 at once; the
    # crowned contact at one angle is unique, so any start that converges inside the flanks finds it
    fu, fv = np.meshgrid([0.1, 0.4, 0.7, 0.95], [0.2, 0.5, 0.8])
    grid = lo + np.column_stack([fu.ravel(), fv.ravel()]) * (hi - lo)
    k = 1 + len(grid)
    starts = np.concatenate([x[:, None, :], np.broadcast_to(grid, (len(phi), len(grid), 2))], axis=1).reshape(-1, 2)
    call = solve_contact(pair, np.repeat(phi, k), starts, tol=tol, damped=False, maxiter=30)
    okm = call.converged.reshape(len(phi), k)
    # where starts reach different tangencies at one angle, member 2 (driven) is pushed to the most
    # advanced one: the contact that carries the load is the root of largest TE (the others would
    # need the flanks to pass through each other)
    te_k = np.where(okm, call.te.reshape(len(phi), k), -np.inf)
    first = np.where(okm.any(axis=1), np.argmax(te_k, axis=1), 0)
    c = call.take(np.arange(len(phi)) * k + first)
    idx = np.arange(len(phi))
    tried = c.converged.copy()
    for _ in range(rounds):
        conv = c.converged
        left = np.r_[False, conv[:-1]]
        right = np.r_[conv[1:], False]
        front = np.flatnonzero(~conv & ~tried & (left | right))
        if not len(front):
            break
        src = np.where(left[front], front - 1, front + 1)
        cr = solve_contact(pair, phi[front], c.unknowns()[src], tol=tol, damped=False, maxiter=30)
        tried[front] = True
        take = np.zeros(len(phi), bool)
        take[front[cr.converged]] = True
        if not take.any():
            break
        pos = np.full(len(phi), -1)
        pos[front] = np.arange(len(front))
        parts = [c.take(idx[~take]), cr.take(pos[take])]
        order = np.argsort(np.concatenate([idx[~take], idx[take]]))
        c = type(c).concatenate(parts).take(order)
    return _upper_tangency(pair, phi, c, tol, rounds)


def _upper_tangency(pair: BevelPair, phi: np.ndarray, c, tol: float, rounds: int):
    """Every angle restarted from its neighbours' solutions; where that reaches a tangency of larger
    TE, it replaces the one found (a start grid can miss the loaded contact at an isolated angle
    and stop at a second tangency the flanks pass through). Rounds stop when nothing changes."""
    n = len(phi)
    for _ in range(rounds):
        conv = c.converged
        x = c.unknowns()
        src = np.concatenate([np.arange(1, n), np.arange(0, n - 1)])
        dst = np.concatenate([np.arange(0, n - 1), np.arange(1, n)])
        keep = conv[src]
        src, dst = src[keep], dst[keep]
        if not len(dst):
            break
        cr = solve_contact(pair, phi[dst], x[src], tol=tol, damped=False, maxiter=30)
        te_now = np.where(conv, c.te, -np.inf)
        gain = cr.converged & (cr.te > te_now[dst] + max(1e3 * tol, 1e-9))
        if not gain.any():
            break
        best = np.full(n, -1)
        te_best = te_now.copy()
        for j in np.flatnonzero(gain):  # the largest gain per angle
            if cr.te[j] > te_best[dst[j]]:
                te_best[dst[j]] = cr.te[j]
                best[dst[j]] = j
        take = best >= 0
        idx = np.arange(n)
        pos = np.full(n, -1)
        pos[take] = best[take]
        parts = [c.take(idx[~take]), cr.take(pos[take])]
        order = np.argsort(np.concatenate([idx[~take], idx[take]]))
        c = type(c).concatenate(parts).take(order)
    return c


def bevel_te_study(pair: BevelPair, n_points: int, tol: float = 1e-12) -> dict:
    """TE (eq 14, library sign: > 0 = member 2 leads), path of contact of one tooth pair over
    +-1.25 angular pitches, and the TE transmitted over one cycle (upper envelope of the pairs
    k = -2..2; its peak-to-peak ``env_pp``, largest value ``te_top`` and largest magnitude
    ``te_extreme`` from the envelope at CYCLE_REFINE n_points + 1 angles). A grid point counts only if the contact lies inside both flanks (edge contact is
    not modelled: a gap in the envelope, i.e. a discontinuous TE). The hand-over test is
    :func:`gearrep.meshing.handover_gap` (a crossing between grid points is continuous)."""
    p1 = 2 * np.pi / pair.n1
    phi = np.linspace(-1.25 * p1, 1.25 * p1, 4 * int(n_points) + 1)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = _solve_grid(pair, phi, tol)
    if c is None:
        ok = np.zeros(len(phi), bool)
        nan = np.full(len(phi), np.nan)
        c_fields = dict(u1=nan, v1=nan, u2=nan, v2=nan)
        te = nan
    else:
        ok = c.converged
        te = np.where(ok, c.te, np.nan)
        c_fields = dict(u1=c.u1, v1=c.v1, u2=c.u2, v2=c.v2)
    cycle = sampled_cycle(phi, te, p1, int(n_points), PAIRS, handover="gap")
    # the extremes of the transmitted TE lie at hand-over crossings and relief dips between cycle
    # angles: read them from the same pair curves at CYCLE_REFINE times as many angles
    fine = sampled_cycle(phi, te, p1, CYCLE_REFINE * int(n_points) + 1, PAIRS, handover="gap")
    return dict(
        phi1=phi,
        te=te,
        ok=ok,
        contact=c,
        cycle_phi1=cycle.phi1,
        cycle_te=cycle.te,
        continuous=cycle.continuous(JUMP_TOL_ARCSEC),
        te_extreme=fine.te_extreme,
        te_top=float(np.nanmax(fine.te)) if np.isfinite(fine.te).any() else np.nan,
        env_pp=fine.te_peak_to_peak,
        jump_arcsec=cycle.jump_arcsec,
        te_pair_range=(float(np.nanmin(te)), float(np.nanmax(te))) if ok.any() else (np.nan, np.nan),
        engagement=(float(phi[ok].min()), float(phi[ok].max())) if ok.any() else (np.nan, np.nan),
        **c_fields,
    )


def polar_angle1(contact) -> np.ndarray:
    """Polar angle [rad] of each contact point from member 1's axis z_f, seen from its apex (the
    origin of S_f): the cone through the point. On member 1's pitch cone it equals delta_1."""
    p = np.asarray(contact.position, float)
    return np.arctan2(np.hypot(p[:, 0], p[:, 1]), p[:, 2])


def pitch_cone_contact(pair: BevelPair, phi: np.ndarray, contact, tol: float = 1e-12):
    """The mesh position where one tooth pair's contact lies on member 1's pitch cone (polar angle
    delta_1 from its axis): the pitch point of the pair, solved, not assumed. ``phi``/``contact``: the
    pair's sampled path (:func:`bevel_te_study`); the crossing of the polar angle through delta_1
    nearest phi1 = 0 is bracketed on the grid and refined by Brent's method, each angle solved from
    the converged neighbour. Returns (phi1 [rad], ContactPoints of one row), or (NaN, None) when the
    path does not cross the pitch cone or a solve fails."""
    from scipy.optimize import brentq

    if contact is None:
        return np.nan, None
    delta1 = pair.flank1.gear.pitch_cone_angle
    ok = np.flatnonzero(contact.converged)
    if len(ok) < 2:
        return np.nan, None
    g = polar_angle1(contact.take(ok)) - delta1
    # a crossing between neighbouring grid angles (no failed angle between them)
    i = np.flatnonzero((np.sign(g[1:]) != np.sign(g[:-1])) & (np.diff(ok) == 1))
    if not len(i):
        return np.nan, None
    j = i[np.argmin(np.abs(phi[ok[i]]))]
    a, b = ok[j], ok[j + 1]
    xa, xb = contact.unknowns()[a], contact.unknowns()[b]

    def solve(q):
        w = (q - phi[a]) / (phi[b] - phi[a])
        return solve_contact(pair, q, ((1 - w) * xa + w * xb)[None, :], tol=tol, damped=False, maxiter=50)

    def f(q):
        c = solve(q)
        if not c.converged[0]:
            raise ValueError("no contact")
        return float(polar_angle1(c)[0] - delta1)

    try:
        q = brentq(f, phi[a], phi[b], xtol=1e-13, rtol=1e-13)
    except ValueError:
        return np.nan, None
    c = solve(q)
    return (float(q), c) if c.converged[0] else (np.nan, None)


def contact_pressure(pair: BevelPair, contact, load: float, E: float, nu: float) -> np.ndarray:
    """Hertz maximum contact pressure p0 at every converged contact point (NaN elsewhere) for the
    normal ``load`` (gearrep.ellipse.hertz_contact from the relative curvatures of
    gearrep.tca.contact_curvatures)."""
    out = np.full(len(contact), np.nan)
    ok = np.flatnonzero(contact.converged)
    if not len(ok):
        return out
    c1, c2 = contact_curvatures(pair, contact.take(ok))
    rel = relative_curvature(c1, c2)
    h = hertz_contact(rel.k1, rel.k2, load, E, nu)
    out[ok] = np.where(h.converged, h.p0, np.nan)
    return out


def _leading(phi, te, p1):
    """Mask of the grid angles where tooth pair 0 carries the load (its TE is not below the
    neighbouring pairs' TE_0(phi -+ p1); a pair without contact counts as -inf)."""
    t = np.where(np.isfinite(te), te, -np.inf)
    fin = np.isfinite(te)

    def at(q):
        inside = (q >= phi[fin].min()) & (q <= phi[fin].max()) if fin.any() else np.zeros_like(q, bool)
        return np.where(inside, np.interp(q, phi[fin], te[fin]) if fin.any() else -np.inf, -np.inf)

    return fin & (t >= at(phi - p1)) & (t >= at(phi + p1))


def _asymmetry(phi, te, lead):
    """Quadratic fit of one pair's TE over the interval where it leads: largest residual as % of
    the TE range there, and the offset of the TE maximum from the interval centre as % of its length."""
    x, y = phi[lead], te[lead]
    if len(x) < 4 or np.ptp(y) == 0:
        return np.nan, np.nan
    c = np.polyfit(x, y, 2)
    resid = 100.0 * np.max(np.abs(np.polyval(c, x) - y)) / np.ptp(y)
    off = 100.0 * abs(x[np.argmax(y)] - 0.5 * (x.min() + x.max())) / np.ptp(x)
    return float(resid), float(off)


def _pitch_columns(pair: BevelPair, res: dict, p0: np.ndarray, material) -> dict:
    """Summary columns at the pitch point (contact on gear 1's pitch cone, solved) and at phi1 = 0."""
    phi = res["phi1"]
    i0 = int(np.argmin(np.abs(phi)))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        phi_p, cp = pitch_cone_contact(pair, phi, res["contact"])
    found = cp is not None
    return dict(
        phi1_pitch_rad=phi_p,
        p0_pitch_MPa=float(contact_pressure(pair, cp, *material)[0]) if found else np.nan,
        v1_pitch=float(cp.v1[0]) if found else np.nan,
        te_pitch_arcsec=float(cp.te[0]) / ARCSEC if found else np.nan,
        p0_at_phi1_0_MPa=float(p0[i0]),
        v1_at_phi1_0=float(res["v1"][i0]),
        u1_at_phi1_0_rad=float(res["u1"][i0]),
    )


def _material(pair_data: dict, case: str):
    """Normal load [N], E [N/mm^2], nu: Table 5 (straight, mm), or sec 5.2's non-dimensional load
    F = P / (E m b) (eq 56) with m = 1 mm, so that lengths in module units are mm."""
    if case.startswith("straight"):
        return pair_data["load"], pair_data["young_modulus"], pair_data["poisson_ratio"]
    return (
        pair_data["load"] * pair_data["young_modulus"] * 1.0 * pair_data["face_width"],
        pair_data["young_modulus"],
        pair_data["poisson_ratio"],
    )


def contact_study(
    settings: dict,
    design,
    label: str,
    case: str,
    *,
    claim: str,
    kind="parabolic",
    crown=0.0,
    tip=None,
    root=None,
    mis=None,
    flank_pair="convex1",
):
    """One TE / path / pressure study -> (summary row, curve rows). TE: ``te_pp_arcsec`` is the
    peak-to-peak of the TE transmitted over a cycle (the TE amplitude), ``te_constant_offset_arcsec``
    its largest value (the constant a change of backlash adds; the TE less this offset peaks at 0
    and reaches -te_pp). Pitch point: the mesh position whose contact lies on gear 1's pitch cone
    (:func:`pitch_cone_contact`, solved), with its p0, cone distance v1 and TE; ``*_at_phi1_0``
    columns are taken at phi1 = 0, which is not the pitch point."""
    mis = mis or BevelMisalignment()
    pair = bevel_pair(
        design,
        case,
        crown_kind=kind,
        crown=crown,
        tip=tip,
        root=root,
        misalignment=mis,
        log_a2=settings["crowning_log_a2"],
        flank_pair=flank_pair,
    )
    res = bevel_te_study(pair, int(settings["bevel_te_n_points"]), tol=1e-12)
    d = design.pairs[case]
    phi, te = res["phi1"], res["te"]
    p1 = 2 * np.pi / pair.n1
    lead = _leading(phi, te, p1)
    load, E, nu = _material(d, case)
    p0 = (
        contact_pressure(pair, res["contact"], load, E, nu) if res["contact"] is not None else np.full(len(phi), np.nan)
    )
    resid, off = _asymmetry(phi, te, lead)
    pl = p0[lead & np.isfinite(p0)]
    row = dict(
        study=label,
        case=case,
        claim=claim,
        flank_pair=flank_pair,
        crown_kind=kind,
        crown=crown,
        tip_length=tip[0] if tip else 0.0,
        tip_amount=tip[1] if tip else 0.0,
        root_length=root[0] if root else 0.0,
        root_amount=root[1] if root else 0.0,
        d_A=mis.d_A,
        d_E=mis.d_E,
        d_G=mis.d_G,
        d_gamma_deg=mis.d_gamma / DEG,
        n_contacts=int(res["ok"].sum()),
        continuous=res["continuous"],
        handover_gap_arcsec=res["jump_arcsec"],
        te_pp_arcsec=res["env_pp"] / ARCSEC,
        te_constant_offset_arcsec=res["te_top"] / ARCSEC,
        te_pair_min_arcsec=res["te_pair_range"][0] / ARCSEC,
        te_pair_max_arcsec=res["te_pair_range"][1] / ARCSEC,
        te_quadratic_residual_pct=resid,
        te_max_offset_pct=off,
        p0_max_MPa=float(pl.max()) if len(pl) else np.nan,
        **_pitch_columns(pair, res, p0, (load, E, nu)),
        load_N=load,
    )
    return row, _curve_rows(label, case, res, lead, p0)


def _curve_rows(label: str, case: str, res: dict, lead: np.ndarray, p0: np.ndarray) -> pd.DataFrame:
    """Rows of bevel_*_curves.csv: one pair's path, TE and p0 on the grid, then the cycle's TE."""
    curves = pd.DataFrame(
        dict(
            study=label,
            case=case,
            phi1_rad=res["phi1"],
            te_arcsec=res["te"] / ARCSEC,
            leading=lead,
            u1_rad=res["u1"],
            v1=res["v1"],
            p0_MPa=p0,
        )
    )
    cyc = pd.DataFrame(
        dict(study=label, case=case, phi1_rad=res["cycle_phi1"], cycle_te_arcsec=res["cycle_te"] / ARCSEC)
    )
    return pd.concat([curves, cyc], ignore_index=True)


def _equal_drop(g: BevelGearData, c1: float, a2: float) -> dict:
    """The three lead crowns with the same drop c1 (b/2)^2 at the face ends (Fig 38-39)."""
    drop = c1 * (0.5 * g.face_width) ** 2
    return {"parabolic": c1, "circular": drop, "logarithmic": drop / np.log(1.0 / (1.0 - a2))}


def straight_contact_tables(settings: dict, design) -> dict:
    """Job ``bevel_straight``: sec 5.1 on the Table 5 pair with the Table 6 misalignments: lead crown
    alone vs lead crown with tip/root relief (Figs 33-35), small vs large lead crown at the centre
    distance error (Figs 36a, 37), the three crown types at shaft-angle errors (Figs 38-39)."""
    case = "straight_bevel_39_32"
    d = design.pairs[case]
    t6 = d["table6"]
    small, large = settings["bevel_straight_crown_per_mm"]
    L, c = settings["bevel_straight_relief_mm"]
    rel = dict(tip=(L, c), root=(L, c))
    rows, curves = [], []

    def add(*a, **k):
        r, cv = contact_study(settings, design, *a, **k)
        rows.append(r)
        curves.append(cv)

    add("aligned", case, claim="reference", crown=small, **rel)
    for name in ("d_gamma", "d_E", "d_A", "d_G"):
        mis = BevelMisalignment(**{name: t6[name]})
        add(f"table6_{name}_lead_only", case, claim="tip_relief_needed", crown=small, mis=mis)
        add(f"table6_{name}_lead_relief", case, claim="tip_relief_needed", crown=small, mis=mis, **rel)
    add(
        "table6_d_E_large_crown",
        case,
        claim="pressure_increase",
        crown=large,
        mis=BevelMisalignment(d_E=t6["d_E"]),
        **rel,
    )
    g1, _ = bevel_gears(d)
    for ang in settings["bevel_straight_shaft_angles_deg"]:
        for kind, amount in _equal_drop(g1, small, settings["crowning_log_a2"]).items():
            add(
                f"shaft_{ang:g}deg_{kind}",
                case,
                claim="crown_types_similar",
                kind=kind,
                crown=amount,
                mis=BevelMisalignment(d_gamma=ang * DEG),
                **rel,
            )
    return {"bevel_straight_summary": pd.DataFrame(rows), "bevel_straight_curves": pd.concat(curves, ignore_index=True)}


def spiral_contact_tables(settings: dict, design) -> dict:
    """Job ``bevel_spiral``: sec 5.2 on the 17/17 pair: angular errors with c_1 = 0.002 and no
    relief (Figs 42-43), dE and dH (= dG) = 0.04 with c_1 = 0.02, c_t = 0.08, L_t = 0.16 (Figs 45, 48),
    combined errors (Figs 50-52), the stress along the path at dE or dH = 0.08 with c_1 = 0.005,
    c_t = 0.04 (Figs 46, 49) and the dE/dH sweep with c_1 = 0.005 (Fig 53). Gear 1's lengthwise convex
    flank drives (``convex1``); the three TE studies of Figs 45, 48 and 51 are repeated on the
    other flank pair (``*_concave1``)."""
    case = "spiral_bevel_17_17"
    rows, curves = [], []

    def add(*a, **k):
        r, cv = contact_study(settings, design, *a, **k)
        rows.append(r)
        curves.append(cv)

    def mis(dE=0.0, dH=0.0, dg=0.0):
        return BevelMisalignment(d_E=dE, d_G=dH, d_gamma=dg * DEG)

    rel = dict(tip=(0.16, 0.08), root=(0.16, 0.08))
    for ang in [0.0] + list(settings["bevel_spiral_angles_deg"]):
        add(f"angular_{ang:g}deg", case, claim="angular_no_TE", crown=0.002, mis=mis(dg=ang))
    add("dE_0.04", case, claim="te_amplitude", crown=0.02, mis=mis(dE=0.04), **rel)
    add("dH_0.04", case, claim="te_amplitude", crown=0.02, mis=mis(dH=0.04), **rel)
    add("dE_dH_0.04", case, claim="te_amplitude", crown=0.005, mis=mis(0.04, 0.04), **rel)
    # the same three on the other flank pair (gear 1's concave flank drives)
    for lab, c1, m in (
        ("dE_0.04", 0.02, mis(dE=0.04)),
        ("dH_0.04", 0.02, mis(dH=0.04)),
        ("dE_dH_0.04", 0.005, mis(0.04, 0.04)),
    ):
        add(f"{lab}_concave1", case, claim="te_amplitude_other_flanks", crown=c1, mis=m, flank_pair="concave1", **rel)
    for c1 in (0.005, 0.02):
        add(f"dE_dH_0.08_c1_{c1:g}", case, claim="stress_ratio_increase", crown=c1, mis=mis(0.08, 0.08), **rel)
    rel4 = dict(tip=(0.16, 0.04), root=(0.16, 0.04))
    add("fig46_dE_0.08", case, claim="stress_peak_mid", crown=0.005, mis=mis(dE=0.08), **rel4)
    add("fig49_dH_0.08", case, claim="stress_peak_mid", crown=0.005, mis=mis(dH=0.08), **rel4)
    add("aligned_c1_0.005", case, claim="dE_stronger_than_dH", crown=0.005, **rel)
    for x in settings["bevel_spiral_sweep"]:
        add(f"sweep_dE_{x:g}", case, claim="dE_stronger_than_dH", crown=0.005, mis=mis(dE=x), **rel)
        add(f"sweep_dH_{x:g}", case, claim="dE_stronger_than_dH", crown=0.005, mis=mis(dH=x), **rel)
        add(f"sweep_dE_dH_{x:g}", case, claim="dE_stronger_than_dH", crown=0.005, mis=mis(x, x), **rel)
    return {"bevel_spiral_summary": pd.DataFrame(rows), "bevel_spiral_curves": pd.concat(curves, ignore_index=True)}


def bevel_protocol_items(p: dict) -> list:
    """(item, value) rows of protocol.csv for the bevel studies (the readings of this module)."""
    return [
        (
            "bevel pairs",
            "spherical involutes (gearrep.surfaces.bevel, eq 48-51), base cones sin a_b = sin delta_p cos alpha "
            "(Table 5's 'base cones' are the root cones), depth tapering to the apex (addendum m, dedendum 1.25 m at "
            "R_e); spiral pair: spiral angle 35 deg on the base cone, opposite hands, pressure angle 20 deg (not "
            "printed), gear 1's lengthwise convex flank against gear 2's concave one (not printed; the other flank "
            "pair is run beside: rows *_concave1); gear 1 crowned, gear 2 unmodified",
        ),
        (
            "bevel convergence (Tables 11-12)",
            f"{p['bevel_n_starts']} starts per pair drawn as for Table 10 (u1, v1, u2, v2 uniform on the flanks, phi2 "
            "uniform on a full turn centred on the root), phi1 = 0 (aligned pair; contact near mid-face), streams "
            f"{BEVEL_STREAMS}; lead crown {p['bevel_conv_crown_straight_per_mm']:.6g} 1/mm (straight: Table 10's a_1 "
            f"scaled to m = 2.5) and {p['bevel_conv_crown_spiral']:g} (spiral: Table 7's smallest c_1), "
            f"sensitivity c_1 = {list(p['bevel_conv_crown_spiral_sensitivity'])}; the reference is the reduced solve "
            "from mid-flank confirmed by the conventional one; robust variants as for the cylindrical pairs",
        ),
        (
            "bevel misalignments",
            "eq 47-48 on gear 2's apex: dE along the common perpendicular y_f, dG along gear 2's axis, dA along gear "
            "1's axis (applied as the opposite shift of gear 2), dgamma = shaft-angle change about the apex; sec 5.2's "
            "dH read as dG",
        ),
        (
            "bevel TE and pressure",
            f"{p['bevel_te_n_points']} points per cycle, +-1.25 angular pitches per tooth pair, upper envelope of pairs "
            f"-2..2 (where starts reach two tangencies at one angle, the one of larger TE), TE amplitude = its "
            f"peak-to-peak with the extremes read at {CYCLE_REFINE} n + 1 angles, the constant offset (its largest "
            "value) reported apart, hand-over steps by gearrep.meshing.handover_gap; pitch-point quantities at the "
            "mesh position whose contact lies on gear 1's pitch cone (solved); Hertz p0 (gearrep.ellipse) with Table 5's 1.5 kN, "
            "206 GPa, 0.3 (straight) and F = 55.5e-6 (eq 56, m = 1 mm, 210 GPa, 0.3; spiral); relief: tip relief from "
            "L below the face cone and root relief from L above the start of the active profile, L along the profile "
            "at the mean cone distance",
        ),
    ]


def bevel_errata_rows(design) -> list:
    """Rows of errata.csv (job ``errata``) for the bevel part: Table 5's base cones, eq (46), eq (45)."""
    d = design.pairs["straight_bevel_39_32"]
    g1, g2 = bevel_gears(d)
    printed = d["printed_base_cone_deg"]
    rows = [
        dict(
            item="Table 5 base cone angles",
            finding="the printed 'base cone angles' are the root cones (pitch cone minus the dedendum angle); the base "
            "cones of the spherical involute follow from sin a_b = sin delta_p cos alpha",
            evidence=f"printed {printed[0]} / {printed[1]} deg; root cones {g1.root_cone_angle / DEG:.3f} / "
            f"{g2.root_cone_angle / DEG:.3f} deg; base cones {g1.base_cone_angle / DEG:.3f} / "
            f"{g2.base_cone_angle / DEG:.3f} deg (pitch cones {g1.pitch_cone_angle / DEG:.3f} / "
            f"{g2.pitch_cone_angle / DEG:.3f} deg)",
        )
    ]
    a_b, u = g1.base_cone_angle, 48.0 * DEG
    q = np.tan(a_b) / np.tan(u)
    eq46 = np.tan(q) - q  # (1/sin a) sin a tan(tan a / tan u) - tan a / tan u, as printed
    rows.append(
        dict(
            item="eq (46) involute polar angle",
            finding="as printed it is not the polar angle of the spherical involute (it is not even zero on the base "
            "cone); the azimuth follows from eq (48)-(49) (gearrep.surfaces.bevel.spherical_involute_azimuth)",
            evidence=f"gear 1 of Table 5, u = 48 deg: eq (46) gives {eq46:.4f} rad, the spherical involute "
            f"{float(spherical_involute_azimuth(u, a_b)):.5f} rad",
        )
    )
    f1, f2 = mating_bevel_flanks(g1, g2, crowning1=lead_crown(g1, "parabolic", 0.0008))
    pair = BevelPair(f1, f2, d["n1"], d["n2"], misalignment=BevelMisalignment(d_E=d["table6"]["d_E"]))
    c = solve_contact(pair, 0.0, np.array([[g1.pitch_cone_angle, g1.mean_cone_distance]]), tol=1e-12)
    az = np.arctan2(c.position[:, 1], c.position[:, 0])
    S = pair.shaft_angle
    u2_45 = np.arccos(np.cos(S) * np.cos(c.u1) + np.sin(S) * np.sin(c.u1) * np.cos(az))
    rows.append(
        dict(
            item="eq (45) u2 from (u1, phi1)",
            finding="the spherical cosine rule holds only with a common apex; under an offset or axial error u2 "
            "follows from the point in gear 2's axis frame (gearrep.tca._bevel)",
            evidence=f"aligned pair: eq (45) exact (tests/unit/tca/test_bevel.py); Table 6's dE = {d['table6']['d_E']} mm: "
            f"eq (45) gives u2 = {float(u2_45[0]):.6f} rad, the contact {float(c.u2[0]):.6f} rad",
        )
    )
    return rows
