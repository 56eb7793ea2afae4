"""Studies at the design point Q and of the centre-distance sensitivity (seed 002): one function
per table, each ``f(settings, design) -> DataFrame`` callable alone (lengths in inches).

* :func:`curvatures` (sec. 2.5) and :func:`ellipse` (sec. 2.6, Table 6.2.4): versions 1-2 have
  circular-arc rack profiles whose centre (pinion addendum) lies on the pitch line (sec. 6.2),
  so |QP| = rho_pinion; the curvatures at Q depend only on the rack profile curvature there, so
  the arc is represented by its osculating parabola a = 1/(2 rho).
* :func:`sensitivity` (Table 6.2.3): eq 2.8.6-2.8.7 and TCA (contact point on the pinion at
  phi1 = 0 with dE: d alpha = atan(2 a_c u_c), the turn of the rack profile tangent).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import frames
from ...solve import Status
from ...surfaces.novikov import RackGeneratedFlank, addendum_limit, pitch_radius, pointing_limit
from ...surfaces.rack import vertex_pitch_distance
from ...tca import Misalignment
from ...units import ARCMIN, ARCSEC, DEG, MM_PER_IN
from .._face import Job
from . import model, te_studies
from .design import design_beta, validate
from .geometry import basics, contact, make_flank, make_pair, pair_at_Q, point_curvatures, report_principal

__all__ = [
    "JOBS",
    "curvatures",
    "ellipse",
    "path_curvatures",
    "concavity",
    "transverse_section",
    "concave_pinion",
    "sensitivity",
    "shifts",
    "rho_sweep",
    "parabola_relations",
    "heights",
    "concave_heights",
]


def _q_variants(design):
    """(case, beta, rho_c, rho_t) at Q: the design, the printed helix angle, the printed a_c, a_t."""
    Pn, _, beta, _ = basics(design)
    rho_c, rho_t = design["rho_c_times_Pn"] / Pn, design["rho_t_times_Pn"] / Pn
    return [
        ("design", beta, rho_c, rho_t),
        ("beta_printed", design["beta_printed_deg"] * DEG, rho_c, rho_t),
        ("a_printed", beta, 1 / (2 * design["a_c_printed_per_in"]), 1 / (2 * design["a_t_printed_per_in"])),
    ]


def curvatures(settings: dict, design: dict) -> pd.DataFrame:
    """Sec. 2.5: principal curvatures at Q of pinion and gear by the curvature relations and by
    differential geometry (``_dg``), for the design and the printed beta / a_c, a_t variants."""
    _, an, _, l = basics(design)
    rows = []
    for name, b, rc, rt in _q_variants(design):
        for m, rho in (("pinion", rc), ("gear", rt)):
            cv = point_curvatures(make_flank(design, 1 / (2 * rho), an, l, b, m, settings["tol"]))
            a_rel = np.array([cv["kI"][0], cv["kII"][0]])
            a_dg = np.array([cv["kI_dg"][0], cv["kII_dg"][0]])
            rows.append(
                dict(
                    case=name,
                    member=m,
                    beta_deg=np.degrees(b),
                    rho_rack_in=rho,
                    kappa_I_per_in=a_rel[0],
                    kappa_II_per_in=a_rel[1],
                    kappa_I_dg_per_in=a_dg[0],
                    kappa_II_dg_per_in=a_dg[1],
                    max_rel_diff=float(np.max(np.abs(a_rel - a_dg)) / np.max(np.abs(a_rel))),
                    gaussian_per_in2=a_rel[0] * a_rel[1],
                    sigma_to_rack_deg=cv["sigma_rack_deg"][0],
                )
            )
    return pd.DataFrame(rows)


def ellipse(settings: dict, design: dict) -> pd.DataFrame:
    """Table 6.2.4 and sec. 2.6: contact ellipse at Q of versions 1-3 (version 3 also with the
    printed beta, the printed a_c, a_t and the sec. 2.6 elastic approach)."""
    _, an, _, l = basics(design)
    rows = []
    for name, b, rc, rt in _q_variants(design):
        cases = [(name, design["delta_in"])] + ([("delta_sec2.6", design["delta_s26_in"])] if name == "design" else [])
        for case, delta in cases:
            r = pair_at_Q(design, rc, rt, an, l, b, delta, settings["tol"])
            rows.append(
                dict(
                    version=3,
                    zone="single",
                    case=case,
                    alpha_n_deg=np.degrees(an),
                    beta_deg=np.degrees(b),
                    l_in=l,
                    rho_pinion_in=rc,
                    rho_gear_in=rt,
                    delta_in=delta,
                    **r,
                )
            )
    # versions 1 and 2 (circular arcs, centre of the pinion-addendum arc on the pitch line: l = rho)
    an12 = design["alpha_n_v12_deg"] * DEG
    for version, zone, (rc, rt) in (
        (1, "single", design["rho_v1"]),
        (2, "pinion_addendum", design["rho_v2_add"]),
        (2, "pinion_dedendum", design["rho_v2_ded"]),
    ):
        for name, b in (("design", design_beta(design)), ("beta_printed", design["beta_printed_deg"] * DEG)):
            r = pair_at_Q(design, rc, rt, an12, rc, b, design["delta_in"], settings["tol"])
            rows.append(
                dict(
                    version=version,
                    zone=zone,
                    case=name,
                    alpha_n_deg=np.degrees(an12),
                    beta_deg=np.degrees(b),
                    l_in=rc,
                    rho_pinion_in=rc,
                    rho_gear_in=rt,
                    delta_in=design["delta_in"],
                    **r,
                )
            )
    return pd.DataFrame(rows)


def path_curvatures(settings: dict, design: dict) -> pd.DataFrame:
    """Curvatures along the helix u = 0 traced by Q (claim: constant along the path)."""
    Pn, an, beta, l = basics(design)
    rows = []
    th = np.linspace(-1.0, 1.0, int(settings["n_path_points"]))
    for m, rho in (("pinion", design["rho_c_times_Pn"] / Pn), ("gear", design["rho_t_times_Pn"] / Pn)):
        cv = point_curvatures(make_flank(design, 1 / (2 * rho), an, l, beta, m, settings["tol"]), np.zeros_like(th), th)
        for i, t in enumerate(th):
            rows.append(dict(member=m, theta_in=t, kappa_I_per_in=cv["kI"][i], kappa_II_per_in=cv["kII"][i]))
    return pd.DataFrame(rows)


def concavity(settings: dict, design: dict) -> pd.DataFrame:
    """Eq 2.7.1: the rho_t at which the gear's normal curvature along the rack profile
    direction at Q changes sign, against the printed bound N2 sin(alpha_n)/(2 P_n cos^3 beta) + l."""
    Pn, an, beta, l = basics(design)

    def k_profile(rho_t):
        f = make_flank(design, 1 / (2 * rho_t), an, l, beta, "gear", settings["tol"])
        cv = point_curvatures(f)
        r_u = f.rack.evaluate(0.0, 0.0).r_u
        e_prof = frames.transform_vectors(f.envelope.local(cv["rec"].params).M[0], r_u / np.linalg.norm(r_u))
        pc = report_principal(cv)
        c = np.dot(e_prof, pc.e1)
        sn = np.dot(e_prof, pc.e2)
        return float(pc.k1 * c * c + pc.k2 * sn * sn)

    bound = model.rho_t_bound_eq_2_7_1(design["N2"], an, Pn, beta, l)
    k_design = k_profile(design["rho_t_times_Pn"] / Pn)
    from scipy.optimize import brentq  # here: scipy.optimize costs 0.5 s per process

    root = brentq(k_profile, 0.5 * bound, 2.0 * bound, xtol=1e-12)
    pin = point_curvatures(
        make_flank(design, Pn / (2 * design["rho_c_times_Pn"]), an, l, beta, "pinion", settings["tol"])
    )
    return pd.DataFrame(
        [
            dict(
                bound_eq271_in=bound,
                rho_t_sign_change_in=root,
                rel_diff=(root - bound) / bound,
                kappa_profile_design_per_in=k_design,
                kappa_profile_pinion_sign=np.sign(pin["kII"][0]),
            )
        ]
    )


def transverse_section(settings: dict, design: dict) -> pd.DataFrame:
    """Sec. 2.4, eq 2.4.1: the transverse section (plane z_c = 0) of the pinion rack cylinder is the
    normal parabola stretched by 1/cos(beta) across the tooth (theta = y_b tan(beta) on the
    plane), hence a parabola; its curvature at Q against 2 a_c* (eq 2.4.1), and the discriminant
    of a conic fitted to the section (0 for a parabola). Q is not the vertex of the transverse
    parabola (the stretch is not along its axis)."""
    Pn, an, beta, l = basics(design)
    a = design["a_c_printed_per_in"]
    rack = make_flank(design, a, an, l, beta, "pinion", settings["tol"]).rack
    u = np.linspace(-0.3, 0.3, 61)
    xb, yb = rack.profile(u)[:2]
    X, Y = xb, yb / np.cos(beta)  # transverse coordinates (height, along the pitch line)
    # points on the rack surface in the plane z = 0: theta = y_b tan(beta)
    pts = rack.position(u, yb * np.tan(beta))
    plane_err = float(np.max(np.abs(pts[:, 2])))
    _, _, x1, y1, x2, y2 = (float(np.asarray(q)) for q in rack.profile(0.0))  # analytic derivatives at Q
    Xd, Yd, Xdd, Ydd = x1, y1 / np.cos(beta), x2, y2 / np.cos(beta)
    kappa = abs(Xd * Ydd - Yd * Xdd) / (Xd**2 + Yd**2) ** 1.5
    alpha_t = np.arctan(np.tan(an) / np.cos(beta))
    a_star = model.a_c_star_eq_2_4_1(a, an, beta)
    # conic A X^2 + B XY + C Y^2 + D X + E Y + F = 0 through the section points (null vector)
    Mtx = np.column_stack([X * X, X * Y, Y * Y, X, Y, np.ones_like(X)])
    A, B, C = np.linalg.svd(Mtx)[2][-1][:3]
    disc = (B * B - 4 * A * C) / (A * A + B * B + C * C)
    return pd.DataFrame(
        [
            dict(
                a_c_per_in=a,
                a_star_eq241_per_in=a_star,
                half_curvature_at_Q_per_in=kappa / 2,
                rel_diff=kappa / 2 / a_star - 1,
                conic_discriminant_rel=disc,
                plane_error_in=plane_err,
                alpha_t_deg=np.degrees(alpha_t),
            )
        ]
    )


_ELLIPSE_COLUMNS = (
    "kappa_I_1_per_in",
    "kappa_II_1_per_in",
    "kappa_I_2_per_in",
    "kappa_II_2_per_in",
    "major_2a_in",
    "minor_2b_in",
    "area_in2",
    "elliptic",
)


def concave_pinion(settings: dict, design: dict) -> pd.DataFrame:
    """Sec. 3.2-3.4: contact ellipse at Q of the pinion concave-gear convex design (rack data of
    sec. 3.2: a_c = 1.25 P_n, a_t = 1.389 P_n, l_c = 0.906/P_n, alpha_n = 25 deg) with the sec. 2
    gear data, against the sec. 2 design. Our reading of fig. 3.2.1 (not in the text): both
    rack profiles bend away from P (convex pinion rack, a < 0 in :mod:`gearrep.surfaces.rack`);
    of the four sign choices it is the only one with a concave pinion and an elliptic contact
    (all four are listed)."""
    Pn, an, beta, l = basics(design)
    ac, at, lc = design["s3_a_c_over_Pn"] * Pn, design["s3_a_t_over_Pn"] * Pn, design["s3_l_c_times_Pn"] / Pn
    rows = []
    for sc in (1, -1):
        for st in (1, -1):
            r = pair_at_Q(design, sc / (2 * ac), st / (2 * at), an, lc, beta, design["delta_in"], settings["tol"])
            rows.append(
                dict(
                    design="sec3",
                    sign_a_c=sc,
                    sign_a_t=st,
                    pinion_concave=bool(r["kappa_II_1_per_in"] < 0),
                    **{k: r[k] for k in _ELLIPSE_COLUMNS},
                )
            )
    r = pair_at_Q(
        design,
        design["rho_c_times_Pn"] / Pn,
        design["rho_t_times_Pn"] / Pn,
        an,
        l,
        beta,
        design["delta_in"],
        settings["tol"],
    )
    rows.append(
        dict(
            design="sec2",
            sign_a_c=1,
            sign_a_t=1,
            pinion_concave=bool(r["kappa_II_1_per_in"] < 0),
            **{k: r[k] for k in _ELLIPSE_COLUMNS},
        )
    )
    return pd.DataFrame(rows)


def _sensitivity_tca(settings, design, version, step, dE, r1, r2, an, l, beta, h) -> dict:
    """TCA row of Table 6.2.3: contact on the pinion at phi1 = 0 with dE; d alpha = atan(2 a u)."""
    pair = make_pair(
        design,
        r1,
        r2,
        an,
        l,
        beta,
        misalignment=Misalignment(d_E=dE),
        tol=settings["tol"],
        hand=settings["pinion_hand"],
    )
    c = contact(pair, [0.0], settings)
    u = float(c.u1[0])
    a = pair.flank1.rack.a
    arc = u * np.sqrt(1 + 4 * a * a * u * u) / 2 + np.arcsinh(2 * a * u) / (4 * a)
    da = np.degrees(abs(np.arctan(2 * a * u)))
    ok = c.status[0] == Status.CONVERGED
    return dict(
        version=version,
        step=step,
        delta_E_in=dE,
        method="tca",
        delta_alpha_deg=da if ok else np.nan,
        shift_in=abs(arc) if ok else np.nan,
        h_active_in=h,
        delta_1=abs(arc) / h if ok else np.nan,
        status=c.status_name[0],
        u1_in=u,
        alpha_sign=float(np.sign(u)),  # NaN where the solve failed (u1 is NaN there)
    )


def _formula_row(v, step, dE, method, da, r1, h) -> dict:
    """One eq 2.8.6-2.8.7 row of the sensitivity table (``da`` in deg, NaN: no solution)."""
    ok = np.isfinite(da) and np.isfinite(dE)
    return dict(
        version=v,
        step=step,
        delta_E_in=dE,
        method=method,
        delta_alpha_deg=da,
        shift_in=r1 * np.radians(da),
        h_active_in=h,
        delta_1=model.delta_1_eq_2_8_6(r1, da, h),
        status="formula" if ok else "no_solution",
    )


def sensitivity(settings: dict, design: dict) -> pd.DataFrame:
    """Table 6.2.3: pressure-angle change d alpha and delta_1 = shift / active height for a
    centre-distance change dE, by eq 2.8.7 (both signs) and by TCA, for versions 1-3 and the
    steps: printed 0.0001 mm (eq only), ``delta_E_table623_in``, 0.0001 in; and (step
    ``implied_by_printed``) the dE that reproduces each printed d alpha by eq 2.8.7 (both signs)
    with the d alpha that the printed delta_1 implies by eq 2.8.6."""
    Pn, an3, beta, l3 = basics(design)
    an12 = design["alpha_n_v12_deg"] * DEG
    versions = {
        1: (design["rho_v1"], an12, design["rho_v1"][0], design["h_Pn"][1] / Pn),
        2: (design["rho_v2_add"], an12, design["rho_v2_add"][0], design["ha_Pn_v2"] / Pn),
        3: (
            (design["rho_c_times_Pn"] / Pn, design["rho_t_times_Pn"] / Pn),
            an3,
            vertex_pitch_distance(an3, Pn),
            design["h_Pn"][3] / Pn,
        ),
    }
    steps = {
        "printed_0.0001mm": design["delta_E_printed_mm"] / MM_PER_IN,
        "0.001in": settings["delta_E_table623_in"],
        "0.0001in": 0.0001,
    }
    rows = []
    for v, ((r1, r2), an, l, h) in versions.items():
        for sname, dE in steps.items():
            for sign, label in ((-1, "eq2.8.7_decrease"), (1, "eq2.8.7_increase")):
                da = model.delta_alpha_eq_2_8_7_deg(an, dE, r1, r2, sign)
                rows.append(_formula_row(v, sname, dE, label, da, r1, h))
            if sname != "printed_0.0001mm":
                rows.append(_sensitivity_tca(settings, design, v, sname, dE, r1, r2, an, l, beta, h))
        # the step each printed d alpha implies (eq 2.8.7 inverted), and the d alpha the printed
        # delta_1 implies (eq 2.8.6 inverted: d alpha = delta_1 h / rho_1)
        da_p, d1_p = design["delta_alpha_T623_deg"][v], design["delta_1_T623"][v]
        for sign, label in ((-1, "eq2.8.7_inverse_decrease"), (1, "eq2.8.7_inverse_increase")):
            dE = model.delta_E_eq_2_8_7(an, da_p, r1, r2, sign)
            row = _formula_row(v, "implied_by_printed", dE, label, da_p, r1, h)
            rows.append(dict(row, delta_alpha_from_printed_delta_1_deg=float(np.degrees(d1_p * h / r1))))
    return pd.DataFrame(rows)


def shifts(settings: dict, design: dict) -> pd.DataFrame:
    """Contact shift across the pinion profile (rack parameter u1 at phi1 = 0) for the error sizes
    of fig. 1.10 (dE) and sec. 2.8 (3 arcmin dgamma, dlambda)."""
    Pn, an, beta, l = basics(design)
    mis = settings["misalignment_arcmin"] * ARCMIN
    rows = []
    for name, kw in (
        ("dE_fig1.10", dict(misalignment=Misalignment(d_E=settings["delta_E_fig110_mm"] / MM_PER_IN))),
        ("dgamma_plus", dict(misalignment=Misalignment(d_gamma_out=mis))),
        ("dgamma_minus", dict(misalignment=Misalignment(d_gamma_out=-mis))),
        ("dlambda_helix_plus", dict(d_lambda=mis)),
        ("dlambda_helix_minus", dict(d_lambda=-mis)),
        ("dgamma_intersecting", dict(misalignment=Misalignment(d_gamma_in=mis))),
    ):
        pair = make_pair(
            design,
            design["rho_c_times_Pn"] / Pn,
            design["rho_t_times_Pn"] / Pn,
            an,
            l,
            beta,
            tol=settings["tol"],
            hand=settings["pinion_hand"],
            **kw,
        )
        c = contact(pair, [0.0], settings)
        rows.append(
            dict(case=name, u1_in=float(c.u1[0]), status=c.status_name[0], profile_shift_in=abs(float(c.u1[0])))
        )
    return pd.DataFrame(rows)


def rho_sweep(settings: dict, design: dict) -> pd.DataFrame:
    """Sweep of the gear rack radius (claim: a larger rho_t - rho_c gives a smaller shift): eq 2.8.7
    and the TCA contact shift for dE = ``delta_E_table623_in``."""
    Pn, an, beta, l = basics(design)
    rc = design["rho_c_times_Pn"] / Pn
    dE = settings["delta_E_table623_in"]
    rows = []
    for rt_pn in settings["rho_t_sweep_times_Pn"]:
        rt = rt_pn / Pn
        pair = make_pair(
            design,
            rc,
            rt,
            an,
            l,
            beta,
            misalignment=Misalignment(d_E=dE),
            tol=settings["tol"],
            hand=settings["pinion_hand"],
        )
        c = contact(pair, [0.0], settings)
        rows.append(
            dict(
                rho_t_in=rt,
                rho_diff_in=rt - rc,
                delta_alpha_eq_deg=model.delta_alpha_eq_2_8_7_deg(an, dE, rc, rt),
                tca_shift_in=abs(float(c.u1[0])) if c.converged[0] else np.nan,
                status=c.status_name[0],
            )
        )
    return pd.DataFrame(rows)


def parabola_relations(settings: dict, design: dict) -> pd.DataFrame:
    """a_phi from a_pl by eq 5.4.3 and eq 5.4.12, and the contact shift of eq 5.4.7 for
    ``misalignment_arcmin`` (sec. 5.4 data; beta = 19.95 deg as printed there)."""
    Pn, an = design["P_n_per_in"], design["alpha_n_deg"] * DEG
    b = design["beta_s54_deg"] * DEG
    a_pl, r_pw = design["a_pl_per_in"], design["r_pw_in"]
    a543 = model.a_phi_eq_5_4_3(
        design["a_c_printed_per_in"],
        design["a_t_printed_per_in"],
        a_pl,
        r_pw,
        an,
        b,
        Pn,
        design["N1"],
        design["N2"],
        vertex_pitch_distance(an, Pn),
    )
    a5412 = model.a_phi_eq_5_4_12(a_pl, an, b, Pn, design["N1"], design["N2"])
    phi_end = np.pi / design["N1"]
    dl = model.delta_l_eq_5_4_7(settings["misalignment_arcmin"] * ARCMIN, a_pl, r_pw, an, b)
    return pd.DataFrame(
        [
            dict(equation="5.4.3", a_phi_per_rad=a543, te_at_half_cycle_arcsec=a543 * phi_end**2 / ARCSEC),
            dict(equation="5.4.12", a_phi_per_rad=a5412, te_at_half_cycle_arcsec=a5412 * phi_end**2 / ARCSEC),
            dict(equation="5.4.7", a_phi_per_rad=np.nan, te_at_half_cycle_arcsec=np.nan, delta_l_in=dl),
        ]
    )


#: readings of the pinion's tooth thickness at the pitch line (job heights, ``heights_tooth_axis``):
#: where P, the point where the profile normal at Q meets the pitch line, sits
TOOTH_AXIS_READINGS = {
    "pinion_tooth": "P on the axis of symmetry of the generated (pinion) tooth, i.e. of the rack's space (fig. 1.6 "
    "caption; the tooth of that figure carries the top land S_a and the fillet): pinion tooth 2 w at the pitch line",
    "rack_tooth": "P on the axis of symmetry of the rack-cutter tooth: rack tooth 2 w, pinion tooth pitch - 2 w",
    "half_pitch": "tooth and space equal at the pitch line (not from the text)",
}


def rack_tooth_fraction(reading: str, half_width_Pn: float, P_n: float) -> float:
    """Rack tooth thickness at the pitch line / normal pitch for a reading of
    :data:`TOOTH_AXIS_READINGS`, with w = ``half_width_Pn`` / P_n the distance along the pitch line
    from P to the working profile's crossing."""
    p_n = np.pi / P_n
    w = half_width_Pn / P_n
    return {"pinion_tooth": 1.0 - 2.0 * w / p_n, "rack_tooth": 2.0 * w / p_n, "half_pitch": 0.5}[reading]


def _pitch_line_half_width(f) -> float:
    """Distance along the rack pitch line (normal section) from P = (0, y0) to where the working
    profile through Q crosses the line (the crossing nearest Q)."""
    from scipy.optimize import brentq

    rack = f.rack

    def x_b(u):
        return float(rack.profile(np.array([u]))[0][0])

    us = np.linspace(-4.0, 4.0, 4001) * max(abs(rack.l), 1e-3)
    xs = np.array([x_b(u) for u in us])
    i = np.nonzero(np.sign(xs[1:]) != np.sign(xs[:-1]))[0]
    if not len(i):
        return np.nan
    u_p = min((brentq(x_b, us[k], us[k + 1], xtol=1e-15) for k in i), key=abs)
    return abs(float(rack.profile(np.array([u_p]))[1][0]) - float(getattr(rack, "y0", 0.0)))


def _rack_heights(N, a, alpha_n, l, P_n, beta, profile="parabola", addendum=None):
    """h_a P_n and the kind of limit of the rack that generates an N-tooth member on the side
    x_c < 0 (:func:`gearrep.surfaces.novikov.addendum_limit`: Litvin's limiting line, a zero
    pressure angle or the end of the profile), h_d(rack tooth / pitch, top land P_n) ->
    (h_d P_n, tip radius) (pointing), and w P_n (:func:`_pitch_line_half_width`). ``addendum`` =
    (a, l) of a separate arc for the rack addendum (version 2's convex tip arc); lengths in inches."""
    r_p = pitch_radius(N, P_n, beta)
    f = RackGeneratedFlank(a, alpha_n, l, beta, r_p, -1, profile=profile)
    if addendum is None:
        f_add = f
    else:
        f_add = RackGeneratedFlank(addendum[0], alpha_n, addendum[1], beta, r_p, -1, profile=profile)
    if profile == "parabola":
        u_end, u_top = -3.0 / P_n, 3.0 / P_n
    else:  # half a circle towards the member; up to the top of the arc away from it
        u_end, u_top = -np.pi * abs(f_add.rack.rho), f.rack.rho * (np.pi / 2 - alpha_n)
    _, x_u, kind = addendum_limit(f_add, u_end)
    p_n = np.pi / P_n

    def hd(rack_tooth_over_pitch, top_land_Pn):
        _, x_p, r_tip = pointing_limit(f, p_n, rack_tooth_over_pitch * p_n, top_land_Pn / P_n, u_top)
        return x_p * P_n, r_tip

    # h_a: 0 when there is no working addendum (a limit at the pitch line, to rounding)
    return max(-x_u * P_n, 0.0) + 0.0, kind, hd, _pitch_line_half_width(f) * P_n


def _required_rack_tooth(hd_of, hd_printed, t):
    """Rack tooth thickness / pitch giving the printed h_d for top land t P_n: the first bracket on
    a 0.025 grid over (0.2, 0.8), refined by Brent's method (NaN if none)."""
    from scipy.optimize import brentq

    def g(x):
        return hd_of(x, t)[0] - hd_printed

    xs = np.arange(0.2, 0.8001, 0.025)
    v = np.array([g(x) for x in xs])
    i = np.nonzero(np.isfinite(v[:-1]) & np.isfinite(v[1:]) & (v[:-1] * v[1:] <= 0))[0]
    return brentq(g, xs[i[0]], xs[i[0] + 1], xtol=1e-10) if len(i) else np.nan


def heights(settings: dict, design: dict) -> pd.DataFrame:
    """Active heights of the pinion's racks (sec. 2.4, 6.2, Table 6.2.2), one ``version`` per rack:
    3 the parabolic rack of sec. 2, 1 and 2 the circular arcs of sec. 6.2. h_a P_n is the
    addendum limit (:func:`gearrep.surfaces.novikov.addendum_limit`, column ``ha_limit``: Litvin's
    limiting line, a zero pressure angle, or the end of the arc; no assumption needed) and h_d P_n
    comes from pointing, which needs the tooth thickness at the pitch line and the minimal top land.
    The thickness follows from where P sits (``heights_tooth_axis``, :data:`TOOTH_AXIS_READINGS`;
    fig. 1.6's caption puts P on the tooth's axis of symmetry, the tooth of that figure being the
    generated one): with w the distance along the pitch line from P to the working profile's
    crossing (``half_width_Pn`` = w P_n), the pinion tooth is 2 w. The top land
    (``heights_top_land_times_Pn``) is sec. 3.3's rule, t_a = 0.3/P_n on the addendum circle
    (transverse); the same rules for every version. Arc placement (sec. 6.2: the arcs that generate convex addenda are centred
    on the pitch line): the arc through Q at alpha_n = 27 deg centred on the pitch point, |QP| =
    rho; version 2's convex rack tip (rho = 0.258, pinion dedendum) touches the gear rack's arc
    (0.230, centred on the pitch line) at the mirror point Q' below the line, so its centre lies on
    the common normal 0.028 in beyond the pitch point. Rows: ``design`` (the stated reading),
    ``reading`` (each reading of :data:`TOOTH_AXIS_READINGS` at the design top land), ``sweep`` (the
    rack tooth and the top land varied alone), ``required`` (the rack tooth thickness that gives the
    printed h_d for each swept top land), and ``fig2.4.2`` (version 3, h over 10 <= N1 <= 30 for
    beta = 20 deg: the sec. 2.4 claim)."""
    Pn, an, beta, l3 = basics(design)
    a_c = Pn / (2 * design["rho_c_times_Pn"])
    an12 = design["alpha_n_v12_deg"] * DEG
    N1 = design["N1"]
    axis, t0 = settings["heights_tooth_axis"], settings["heights_top_land_times_Pn"]
    rho1, rho2a, rho2d, rho2g = (
        design["rho_v1"][0],
        design["rho_v2_add"][0],
        design["rho_v2_ded"][0],
        design["rho_v2_ded"][1],
    )
    racks = {
        3: dict(a=a_c, alpha_n=an, l=l3, profile="parabola"),
        1: dict(a=1 / (2 * rho1), alpha_n=an12, l=rho1, profile="circular_arc"),
        # version 2's tip arc: Q' = P + rho_gear y_a (below the line), centre rho2d beyond Q' towards P
        2: dict(a=1 / (2 * rho2a), alpha_n=an12, l=rho2a, profile="circular_arc", addendum=(-1 / (2 * rho2d), -rho2g)),
    }
    rows = []
    limits = {}

    def limit(version, N, b):
        if (version, N, b) not in limits:
            limits[version, N, b] = _rack_heights(N, P_n=Pn, beta=b, **racks[version])
        return limits[version, N, b]

    def row(kind, version, N, b, sr, t, reading=None):
        ha, ha_kind, hd_of, w = limit(version, N, b)
        if reading is not None:
            sr = rack_tooth_fraction(reading, w, Pn)
        hd, rt = hd_of(sr, t) if np.isfinite(sr) else (np.nan, np.nan)
        rows.append(
            dict(
                kind=kind,
                version=version,
                N1=N,
                beta_deg=np.degrees(b),
                tooth_axis=reading or "",
                half_width_Pn=w,
                rack_tooth_over_pitch=sr,
                top_land_times_Pn=t,
                ha_Pn=ha,
                ha_limit=ha_kind,
                hd_Pn=hd,
                h_Pn=ha + hd,
                tip_radius_in=rt,
            )
        )

    for v in (3, 1, 2):
        row("design", v, N1, beta, np.nan, t0, axis)
        for reading in TOOTH_AXIS_READINGS:
            row("reading", v, N1, beta, np.nan, t0, reading)
        for sr in settings["heights_sweep_rack_tooth_over_pitch"]:
            row("sweep", v, N1, beta, sr, t0)
        for t in settings["heights_sweep_top_land_times_Pn"]:
            row("sweep", v, N1, beta, np.nan, t, axis)
        hd_of = limit(v, N1, beta)[2]
        for t in settings["heights_sweep_top_land_times_Pn"]:
            row("required", v, N1, beta, _required_rack_tooth(hd_of, design["hd_Pn"][v], t), t)
    for N in range(10, 31, 2):
        row("fig2.4.2", 3, N, 20 * DEG, np.nan, t0, axis)
    return pd.DataFrame(rows)


def _switch_radius(N, an, l, beta, Pn, tol):
    """Radius rho of a pinion rack bending its profile with the sign of l (centre on the side of
    a < 0, :mod:`gearrep.surfaces.rack`) at which the generated pinion profile at Q turns from
    concave to convex (kappa_II through zero; NaN if not in 0.2-20 /P_n)."""
    from scipy.optimize import brentq

    r_p = pitch_radius(N, Pn, beta)

    def k(rho):
        f = RackGeneratedFlank(-1 / (2 * rho), an, l, beta, r_p, -1, tol=tol)
        return float(point_curvatures(f)["kII"][0])

    rs = np.linspace(0.2, 20.0, 100) / Pn
    v = np.array([k(r) for r in rs])
    i = np.nonzero(np.sign(v[1:]) != np.sign(v[:-1]))[0]
    return brentq(k, rs[i[0]], rs[i[0] + 1], xtol=1e-12) if len(i) else np.nan


def concave_heights(settings: dict, design: dict) -> pd.DataFrame:
    """Sec. 3.2-3.3 (pinion concave, gear convex): can the undercutting and pointing analysis of the
    heights job run on the sec. 3.2 racks (a_c = 1.25 P_n, a_t = 1.389 P_n, l_c = 0.906/P_n, alpha_n
    = 25 deg, both profiles bending away from their pitch point on the Q side: a < 0)? Two
    placements of Q (fig. 3.2.1 is not in the text): in the pinion addendum (l > 0, the reading of
    job concave_pinion) or in its dedendum (l < 0). Per placement: the rack radius at which the
    pinion's profile at Q turns from concave to convex (``rho_switch_Pn``, N1 = 17) against the
    bound of inequality 3.2.1, N1 sin(alpha_n)/(2 P_n cos^3 beta) + l_c; and along the gear rack
    (N2 = N2_min = 70, the gear on x_c > 0) the limits of its profile from Q towards the gear root
    and towards the gear tip (:func:`gearrep.surfaces.novikov.addendum_limit`), and whether the part
    between them crosses the pitch line (needed to split h = h_a + h_d and to place a tooth
    thickness at the pitch line). Heights in units of 1/P_n."""
    Pn, _, beta, _ = basics(design)
    an = design["alpha_n_deg"] * DEG
    ac, at, lc = design["s3_a_c_over_Pn"] * Pn, design["s3_a_t_over_Pn"] * Pn, design["s3_l_c_times_Pn"] / Pn
    N1, N2 = design["N1"], int(design["s3_N2_min"])
    bound = N1 * np.sin(an) / (2 * Pn * np.cos(beta) ** 3) + lc
    rows = []
    for placement, l in (("Q_in_pinion_addendum", lc), ("Q_in_pinion_dedendum", -lc)):
        g = RackGeneratedFlank(-at, an, l, beta, pitch_radius(N2, Pn, beta), +1, tol=settings["tol"])
        u_root, x_root, k_root = addendum_limit(g, 3.0 / Pn)
        u_tip, x_tip, k_tip = addendum_limit(g, -3.0 / Pn)
        x = g.rack.profile(np.linspace(u_tip, u_root, 2001))[0]
        rows.append(
            dict(
                placement=placement,
                l_times_Pn=l * Pn,
                rho_c_times_Pn=Pn / (2 * ac),
                rho_switch_Pn=_switch_radius(N1, an, l, beta, Pn, settings["tol"]) * Pn,
                rho_bound_eq_3_2_1_Pn=bound * Pn,
                N2=N2,
                x_Q_Pn=float(g.rack.profile(np.array([0.0]))[0][0]) * Pn,
                gear_root_limit_x_Pn=x_root * Pn,
                gear_root_limit=k_root,
                gear_tip_limit_x_Pn=x_tip * Pn,
                gear_tip_limit=k_tip,
                working_part_crosses_pitch_line=bool(np.any(np.diff(np.sign(x)) != 0)),
            )
        )
    return pd.DataFrame(rows)


def _job(fn, *names, priority: int = 0) -> Job:
    """Job of a study function ``fn(settings, design)`` returning a table or {name: table}
    (``priority``: :class:`.._face.Job`)."""

    def compute(settings, design):
        validate(settings, design)
        out = fn(settings, design)
        return out if isinstance(out, dict) else {names[0]: out}

    compute.__name__, compute.__doc__ = fn.__name__, fn.__doc__
    doc = " ".join((fn.__doc__ or "").strip().split("\n\n")[0].split())  # first paragraph
    return Job(compute, {n: f"litvin2000/{n}.csv" for n in names}, doc=doc, priority=priority)


#: one job per table or study; output paths under results/
JOBS = {
    "curvatures": _job(curvatures, "curvatures"),
    "ellipse": _job(ellipse, "ellipse"),
    "path_curvatures": _job(path_curvatures, "path_curvatures"),
    "concavity": _job(concavity, "concavity"),
    "transverse_section": _job(transverse_section, "transverse_section"),
    "concave_pinion": _job(concave_pinion, "concave_pinion"),
    "te": _job(te_studies.te, "te_single", "te_cycle", "te_summary", priority=7),
    "sensitivity": _job(sensitivity, "sensitivity"),
    "shifts": _job(shifts, "shifts", priority=4),
    "rho_sweep": _job(rho_sweep, "rho_sweep"),
    "parabola_relations": _job(parabola_relations, "parabola_relations"),
    "heights": _job(heights, "heights"),
    "concave_heights": _job(concave_heights, "concave_heights"),
    "worm": _job(te_studies.worm, "worm_single", "worm_cycle", "worm_summary", priority=20),
    "worm_choices": _job(te_studies.worm_choices, "worm_choices", priority=30),
    "disk": _job(te_studies.disk, "disk", priority=10),
}
