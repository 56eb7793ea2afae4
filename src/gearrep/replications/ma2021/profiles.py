"""Section shapes and the paper's section equations (28)-(29) vs eq (6), and the tooth thickness
of Fig 14, for one CATT gear."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...surfaces.catt import (
    CATTFlank,
    CATTGearData,
    eq28_profile,
    eq29_profile,
    gear_data,
    pitch_thickness_closed_form,
    tooth_thickness,
)

__all__ = ["involute_deviation", "section_shapes", "equation_checks", "thickness_table"]


def _inv(x):
    return np.tan(x) - x


def involute_deviation(points, r_b=None):
    """Max normal deviation (mm) of transverse profile points (n, 2|3) from an involute: best fit
    over the base radius (if ``r_b`` is None) and the rotation. For an involute a rotation dpsi is a
    normal displacement r_b dpsi, so the deviation is r_b times the polar-angle residual."""
    p = np.asarray(points, float)
    r = np.hypot(p[:, 0], p[:, 1])
    psi = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))

    def resid(rb):
        inv = _inv(np.arccos(np.clip(rb / r, -1, 1)))
        # psi = psi0 + sgn * inv(r); fit psi0 and sgn by least squares on the sign giving the better fit
        best = None
        for sg in (1.0, -1.0):
            d = psi - sg * inv
            res = d - d.mean()
            if best is None or np.max(np.abs(res)) < np.max(np.abs(best)):
                best = res
        return rb * best

    if r_b is not None:
        res = resid(r_b)
        return float(np.max(np.abs(res))), float(r_b)
    # 1-D minimisation of the max-abs residual over r_b by golden search around min(r)
    lo, hi = 0.9 * np.min(r) * 0.9, np.min(r) * (1 - 1e-9)
    f = lambda rb: float(np.sqrt(np.mean(resid(rb) ** 2)))  # noqa: E731 - least squares in r_b
    gr = (np.sqrt(5) - 1) / 2
    x1, x2 = hi - gr * (hi - lo), lo + gr * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(200):
        if f1 < f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - gr * (hi - lo)
            f1 = f(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + gr * (hi - lo)
            f2 = f(x2)
        if hi - lo < 1e-12 * hi:
            break
    rb = 0.5 * (lo + hi)
    return float(np.max(np.abs(resid(rb)))), float(rb)


def section_shapes(design: dict, params: dict) -> pd.DataFrame:
    """Middle section (z = 0) vs the involute r_b = R cos(alpha); sections at the offsets of
    ``section_check`` vs their best-fit involute and vs an involute of the nominal r_b; eq (28) and
    eq (29) vs eq (6)."""
    g = gear_data(design, params, 1)
    rows = []
    radii = np.linspace(g.r_form + 1e-6 * g.module, g.r_a, params["section_check"]["n_points"])
    for side in (1, -1):
        f = CATTFlank(g, side)
        for z in [0.0] + list(params["section_check"]["sections_mm"]):
            pts, res = f.section_profile(z, radii)
            dev_nom, _ = involute_deviation(pts, r_b=g.r_b)
            dev_fit, rb_fit = involute_deviation(pts)
            rows.append(
                {
                    "design": design["name"],
                    "side": side,
                    "flank": "convex" if side == 1 else "concave",
                    "section_mm": z,
                    "outside_face_width": z > 0.5 * g.face_width,
                    "max_solve_residual": float(np.max(res.residual)),
                    "dev_nominal_involute_mm": dev_nom,
                    "dev_best_fit_involute_mm": dev_fit,
                    "best_fit_r_b_mm": rb_fit,
                    "nominal_r_b_mm": g.r_b,
                }
            )
    return pd.DataFrame(rows)


def equation_checks(design: dict, params: dict) -> pd.DataFrame:
    """Eq (6) literal vs closed form, eq (28) and eq (29) vs eq (6) in their conventions, and the
    equation of meshing residual (max abs over a parameter grid)."""
    g = gear_data(design, params, 1)
    rows = []
    th = np.linspace(-0.08, 0.08, 9)[:, None]
    for side, upper_lbl in ((1, "upper"), (-1, "lower")):
        f = CATTFlank(g, side)
        ph = np.linspace(f.lower[1], f.upper[1], 11)[None, :]
        T, Pp = np.broadcast_arrays(th, ph)
        d6 = np.max(np.abs(f.position(T, Pp) - f.position_eq6(T, Pp)))
        u = f.blade_u(T, Pp)
        mres = np.max(np.abs(f.meshing_residual(u, T, Pp)))
        rows.append({"check": "eq6_literal_vs_closed_form", "flank": upper_lbl, "max_abs_mm": d6})
        rows.append({"check": "eq6_meshing_equation_n_dot_v", "flank": upper_lbl, "max_abs_mm": mres})
    # eq (29) upper == eq (6) lower at theta = 0 with y -> -y, same roll angle
    phs = np.linspace(-0.25, 0.25, 21)
    for upper, side in ((True, -1), (False, 1)):
        x, y = eq29_profile(g, upper, phs)
        p = CATTFlank(g, side).position(0 * phs, phs)
        rows.append(
            {
                "check": "eq29_vs_eq6_turned_over",
                "flank": "upper" if upper else "lower",
                "max_abs_mm": float(np.max(np.hypot(x - p[:, 0], y + p[:, 1]))),
            }
        )
        # eq (29) is an involute of base radius R cos(alpha)
        dev, _ = involute_deviation(np.column_stack([x, y]), r_b=g.r_b)
        rows.append({"check": "eq29_involute_deviation", "flank": "upper" if upper else "lower", "max_abs_mm": dev})
    # eq (28) upper at offset b == eq (6) lower at z = -b, y -> -y
    for upper, side in ((True, -1), (False, 1)):
        f = CATTFlank(g, side)
        for b in (15.0, 30.0):
            th0 = np.arcsin(b / f.rho0)
            ths = np.linspace(0.9 * th0, 1.1 * th0, 9)
            x, y, phi1, u28 = eq28_profile(g, upper, b, ths)
            p = f.position(ths, phi1)  # theta > 0 gives z = +b in eq (6) with b -> ... checked below
            zdev = float(np.max(np.abs(p[:, 2] + b)))
            pm = f.position(-ths, phi1)
            dev = min(
                float(np.max(np.hypot(x - p[:, 0], y + p[:, 1]))), float(np.max(np.hypot(x - pm[:, 0], y + pm[:, 1])))
            )
            rows.append(
                {"check": f"eq28_vs_eq6_turned_over_b{b:g}", "flank": "upper" if upper else "lower", "max_abs_mm": dev}
            )
            rows.append(
                {
                    "check": f"eq28_section_z_plus_b_b{b:g}",
                    "flank": "upper" if upper else "lower",
                    "max_abs_mm": min(zdev, float(np.max(np.abs(p[:, 2] - b)))),
                }
            )
    return pd.DataFrame(rows)


def thickness_table(params: dict) -> pd.DataFrame:
    """Pitch-circle transverse tooth thickness at the sections of ``params["thickness"]`` for each R_T
    (Fig 14), solved on eq (6) and by its closed form."""
    th = params["thickness"]
    rows = []
    al = np.deg2rad(params["pressure_angle_deg"])
    for RT in th["R_T"]:
        g = CATTGearData(
            int(th["z"]),
            float(th["module"]),
            float(RT),
            float(th["face_width"]),
            al,
            params["addendum"],
            params["clearance"],
        )
        zs = np.asarray(th["sections_mm"], float)
        t, res = tooth_thickness(g, zs)
        tc = pitch_thickness_closed_form(g, zs)
        for z, ti, tci in zip(zs, t, tc):
            rows.append(
                {
                    "R_T_mm": float(RT),
                    "section_mm": float(z),
                    "section": f"B{z:g}",
                    "thickness_mm": ti,
                    "thickness_closed_form_mm": tci,
                    "abs_diff_mm": ti - tci,
                    "outside_face_width": z > 0.5 * g.face_width,
                    "z": g.n_teeth,
                    "module_mm": g.module,
                }
            )
    return pd.DataFrame(rows)
