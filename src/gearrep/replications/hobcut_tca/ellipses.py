"""Contact ellipses at TCA points (seed 000 sec 5.4): curvature analysis (eq 5.14-5.17) and the
surface-topology pattern (eq 5.18-5.20: in each tangent-plane direction, the distance at which
the normal separation of the flanks equals the paint thickness)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...solve import newton
from ...surfaces.hob import PairDesign
from ...tca import (
    EnvelopeContactPath,
    EnvelopeFlank,
    HobbedAssembly,
    HobbedPair,
    hob_pitch_l,
    hobbed_continue_to,
    hobbed_elastic_ellipses,
    predict_envelope_contact,
    require_converged,
    solve_envelope_points,
)

__all__ = ["contact_ellipses", "pitch_point_ratio", "topology_pattern"]


def contact_ellipses(pair: HobbedPair, sol: EnvelopeContactPath, delta_mm: float) -> pd.DataFrame:
    """Elastic-approach ellipse (eq 5.14-5.17; :func:`gearrep.ellipse.elastic_ellipse_at`) at
    every contact point of ``sol``: the chapter-4 curvatures of both flanks (two-parameter
    relations, :func:`gearrep.curvature_relations.generated_curvatures`) at the TCA point,
    expressed with the pinion's normal. a/b does not depend on delta (a/b = sqrt(B_e/A_e))."""
    el, cp, cg = hobbed_elastic_ellipses(pair, sol, delta_mm)  # the library route (gearrep.tca)
    return pd.DataFrame(
        {
            "phi1_deg": np.degrees(sol.phi1),
            "l_p_mm": sol.x[:, 0],
            "Z_p_mm": sol.Z_p,
            "a_mm": el.a,
            "b_mm": el.b,
            "a_over_b": el.ratio,
            "alpha_deg": np.degrees(el.alpha),
            "major_axis_z": el.major_axis[:, 2],
            "k_I_p_per_mm": cp.k1,
            "k_II_p_per_mm": cp.k2,
            "k_I_g_per_mm": cg.k1,
            "k_II_g_per_mm": cg.k2,
            "elliptic": el.elliptic,
        }
    )


def pitch_point_ratio(
    gears: PairDesign, R_cp_mm: float, R_cg_mm: float, alpha_deg: float, *, delta_mm: float, tol=1e-11
) -> dict:
    """a/b of the ideal pair ``gears`` (R_cp, R_cg, the hob's pressure angle set to alpha) at the
    contact point where the pinion's contact passes the hob pitch line (l_p = l_pitch; Fig 5.7
    does not say which point it uses: the pitch point is our choice); a, b for the elastic
    approach ``delta_mm``."""
    gears = gears.with_hob(pressure_angle_rad=float(np.radians(alpha_deg)))
    hob = gears.hob
    pair, s0 = hobbed_continue_to(gears, R_cp_mm, R_cg_mm, HobbedAssembly(), steps=2, tol=tol)
    lp = hob_pitch_l(hob)
    # dl_p/dphi1 from the predictor, then Newton on l_p(phi1) = l_pitch (secant, converged TCA points)
    a, cur = 0.0, s0
    for _ in range(20):
        d = np.radians(1e-3)
        s1 = solve_envelope_points(pair, [a + d], predict_envelope_contact(pair, cur.x, cur.phi1, [a + d]), tol=tol)
        slope = (s1.x[0, 0] - cur.x[0, 0]) / d
        a_new = a + (lp - cur.x[0, 0]) / slope
        cur = solve_envelope_points(pair, [a_new], predict_envelope_contact(pair, cur.x, cur.phi1, [a_new]), tol=tol)
        require_converged(cur, "pitch-point contact")
        a = a_new
        if abs(cur.x[0, 0] - lp) < 1e-9:
            break
    el = contact_ellipses(pair, cur, delta_mm).iloc[0]
    return {
        "R_cp_mm": R_cp_mm,
        "R_cg_mm": R_cg_mm,
        "alpha_n_deg": alpha_deg,
        "phi1_deg": float(np.degrees(a)),
        "l_p_mm": float(cur.x[0, 0]),
        "a_over_b": float(el["a_over_b"]),
        f"a_mm_delta_{delta_mm:g}": float(el["a_mm"]),
        f"b_mm_delta_{delta_mm:g}": float(el["b_mm"]),
    }


def _height(flank: EnvelopeFlank, R, origin, q0, O, t1, t2, n, X, tol=1e-12, maxiter=30):
    """Signed height (along n) above the tangent plane of the flank point that projects on the
    tangent-plane points X (m, 3) (Newton on the flank parameters (l, psi), analytic Jacobian
    from the envelope tangents; (phi, theta) warm-started from the contact q0)."""
    g = flank.gear
    env = g.envelope()
    guess = np.broadcast_to(q0[[1, 2]], (len(X), 2)).copy()

    def fun_jac(y, idx, derivs=True):  # one envelope solve gives the residual and the Jacobian
        rec = env.solve(y[:, 0], y[:, 1], guess=guess[idx])
        P = np.einsum("ab,nb->na", R, rec.point) + origin - X[idx]
        out = np.stack([P @ t1, P @ t2], -1)
        out[~rec.converged] = np.nan
        if not derivs:
            return out, None
        Tf = np.einsum("ab,nfb->nfa", R, rec.tangents)  # (m, 2 free, 3)
        return out, np.stack([Tf @ t1, Tf @ t2], 1)

    res = newton(
        lambda y, idx: fun_jac(y, idx, derivs=False)[0],
        np.broadcast_to(q0[[0, 3]], (len(X), 2)).copy(),
        lambda y, idx: fun_jac(y, idx)[1],
        tol=tol,
        maxiter=maxiter,
        rows=True,
        fun_jac=fun_jac,
    )
    rec = env.solve(res.x[:, 0], res.x[:, 1], guess=guess)
    P = np.einsum("ab,nb->na", R, rec.point) + origin
    ok = res.converged & rec.converged
    return np.where(ok, (P - O) @ n, np.nan), ok


def topology_pattern(
    pair: HobbedPair, sol: EnvelopeContactPath, i: int, delta_mm: float, n_dirs: int = 24
) -> pd.DataFrame:
    """Boundary of the contact pattern at contact point i of ``sol``: in each of ``n_dirs``
    directions of the common tangent plane, the distance rho at which the normal separation of
    the two flanks equals delta (eq 5.18-5.20: the paint-thickness criterion), found by the
    secant method started from the curvature-method ellipse. Directions are measured from the
    curvature-method major axis. Returns theta_deg, rho_mm, rho_curvature_mm, converged."""
    if int(n_dirs) != n_dirs or n_dirs < 4 or n_dirs % 4:
        raise ValueError(f"n_dirs must be a positive multiple of 4, got {n_dirs!r}")
    one = sol.take([i])
    el = contact_ellipses(pair, one, delta_mm).iloc[0]
    ell, cp, _ = hobbed_elastic_ellipses(pair, one, delta_mm)
    n = cp.normal[0]
    t1 = ell.major_axis[0] / np.linalg.norm(ell.major_axis[0])
    t2 = np.cross(n, t1)
    O = one.r_f[0]
    Rp = pair.pinion_rotation(one.phi1)[0]
    Rg = pair.gear_rotation(one.phi2)[0]
    th = np.linspace(0, 2 * np.pi, int(n_dirs), endpoint=False)
    a, b = float(el["a_mm"]), float(el["b_mm"])
    rho_c = 1.0 / np.sqrt((np.cos(th) / a) ** 2 + (np.sin(th) / b) ** 2)
    d = np.cos(th)[:, None] * t1 + np.sin(th)[:, None] * t2

    def sep(rho):
        X = O + rho[:, None] * d
        hp, okp = _height(pair.pinion, Rp, np.zeros(3), one.x[0, 0:4], O, t1, t2, n, X)
        hg, okg = _height(pair.gear, Rg, pair.gear_origin, one.x[0, 4:8], O, t1, t2, n, X)
        return np.abs(hp - hg) - delta_mm, okp & okg

    r0, r1 = rho_c, 1.02 * rho_c
    f0, ok0 = sep(r0)
    f1, ok1 = sep(r1)
    ok = ok0 & ok1
    for _ in range(12):
        with np.errstate(divide="ignore", invalid="ignore"):
            r2 = np.where(np.abs(f1 - f0) > 0, r1 - f1 * (r1 - r0) / (f1 - f0), r1)
        r0, f0 = r1, f1
        r1 = r2
        f1, okk = sep(r1)
        ok &= okk
        if np.all(np.abs(f1[ok]) < 1e-10):
            break
    ok &= np.abs(f1) < 1e-9
    return pd.DataFrame(
        {
            "theta_deg": np.degrees(th),
            "rho_mm": r1,
            "rho_curvature_mm": rho_c,
            "converged": ok,
            "phi1_deg": float(np.degrees(one.phi1[0])),
        }
    )
