"""Flanks, curvatures at Q and gear pairs of seed 002 (lengths in inches, curvatures in 1/in).

Report convention: the unit normal is the one for which the convex pinion has positive
curvatures (minus the rack-cutter normal of :mod:`gearrep.surfaces.rack`); kappa_I is the
curvature along the principal direction closest to the rack generatrix (fig. 2.5.1:
kappa_I^(c) = 0 along the generatrix, eq 2.5.1), kappa_II the other. Curvatures two ways:
Litvin's generating/generated relations (:func:`gearrep.curvature_relations.generated_curvatures`)
and differential geometry of the generated surface (:mod:`gearrep.curvature`). TCA frames:
:mod:`gearrep.surfaces.novikov`."""

from __future__ import annotations

import numpy as np

from ... import frames
from ...curvature import PrincipalCurvatures, principal_curvatures
from ...curvature_relations import generated_curvatures
from ...ellipse import elastic_ellipse_at
from ...surfaces.novikov import (
    DiskGroundPinion,
    RackGeneratedFlank,
    aligned_start,
    member_flank,
    pitch_radius,
)
from ...surfaces.rack import vertex_pitch_distance
from ...surfaces.worm_ground import WormGeneratedPinion
from ...tca import GearPair, offset_start, solve_contact
from ...units import DEG
from .design import design_beta
from .model import a_d_eq_5_4_13

__all__ = [
    "basics",
    "make_flank",
    "point_curvatures",
    "report_principal",
    "line_angle",
    "pair_at_Q",
    "make_pair",
    "contact",
    "make_worm_pair",
    "worm_rack_coefficients",
    "make_disk_pair",
    "disk_start",
    "solve_with_retries",
    "worm_start",
]


def basics(design: dict):
    """(P_n, alpha_n, beta, l) of the sec. 2.5 design: l = |QP| = cos(alpha_n)/P_n."""
    Pn, an, beta = design["P_n_per_in"], design["alpha_n_deg"] * DEG, design_beta(design)
    return Pn, an, beta, vertex_pitch_distance(an, Pn)


def make_flank(design, a, alpha_n, l, beta, member, tol=1e-13, beta_rack=None) -> RackGeneratedFlank:
    """:func:`gearrep.surfaces.novikov.member_flank` of the report's design ``d`` (tooth number
    ``N1`` for the pinion, ``N2`` for the gear, ``P_n_per_in``); lengths in inches."""
    N = design["N1"] if member == "pinion" else design["N2"]
    return member_flank(N, design["P_n_per_in"], a, alpha_n, l, beta, member, tol=tol, beta_rack=beta_rack)


def _report_curvatures(k1, k2, e1, e2, generatrix):
    """(kappa_I, kappa_II, e_I, e_II) in the report convention (normal -n): kappa_I along the
    principal direction closest to the rack generatrix."""
    kI_is_1 = np.abs(np.sum(e1 * generatrix, -1)) >= np.abs(np.sum(e2 * generatrix, -1))
    kI = np.where(kI_is_1, -k1, -k2)
    kII = np.where(kI_is_1, -k2, -k1)
    eI = np.where(kI_is_1[..., None], e1, e2)
    eII = np.where(kI_is_1[..., None], e2, e1)
    return kI, kII, eI, eII


def point_curvatures(flank: RackGeneratedFlank, u=0.0, theta=0.0) -> dict:
    """Curvatures of a generated surface at rack parameters (u, theta) by both methods."""
    u = np.atleast_1d(np.asarray(u, float))
    theta = np.broadcast_to(np.asarray(theta, float), u.shape)
    rec = flank.solve(u, theta)
    if not np.all(rec.converged):
        raise RuntimeError(f"envelope solve did not converge: {rec.solve.status_name}")
    gc = generated_curvatures(flank.envelope, rec.params)
    pc = principal_curvatures(flank.evaluate(u, theta))
    # direct curvatures w.r.t. the tool normal (the common normal)
    flip = np.sum(pc.normal * gc.normal, -1) < 0
    dk1 = np.where(flip, -pc.k2, pc.k1)
    dk2 = np.where(flip, -pc.k1, pc.k2)
    gen = frames.transform_vectors(flank.envelope.local(rec.params).M, flank.rack.t)  # rack generatrix
    kI, kII, eI, eII = _report_curvatures(gc.k1, gc.k2, gc.e1, gc.e2, gen)
    dI, dII, _, _ = _report_curvatures(
        dk1, dk2, np.where(flip[:, None], pc.e2, pc.e1), np.where(flip[:, None], pc.e1, pc.e2), gen
    )
    sig = np.degrees(np.arccos(np.clip(np.abs(np.sum(eI * gen, -1)), 0, 1)))
    return dict(
        rec=rec,
        gc=gc,
        kI=kI,
        kII=kII,
        eI=eI,
        eII=eII,
        kI_dg=dI,
        kII_dg=dII,
        normal=-gc.normal,
        sigma_rack_deg=sig,
        path_tangent=rec.tangents[:, 1],
    )


def report_principal(cv, i=0) -> PrincipalCurvatures:
    """PrincipalCurvatures (report normal) of point ``i`` of a :func:`point_curvatures` record."""
    kI, kII = cv["kI"][i], cv["kII"][i]
    eI, eII, n = cv["eI"][i], cv["eII"][i], cv["normal"][i]
    if np.dot(np.cross(eI, eII), n) < 0:
        eII = -eII
    if kI >= kII:
        return PrincipalCurvatures(np.array(kI), np.array(kII), eI, eII, n)
    return PrincipalCurvatures(np.array(kII), np.array(kI), eII, -eI, n)


def _signed_angle(a, b, n):
    return float(np.degrees(np.arctan2(np.dot(n, np.cross(a, b)), np.dot(a, b))))


def line_angle(a, b, n):
    """Angle from line a to line b about n, wrapped to (-90, 90] deg."""
    x = _signed_angle(a, b, n)
    return 90.0 - np.mod(90.0 - x, 180.0)


def pair_at_Q(design, rho_c, rho_t, alpha_n, l, beta, delta, tol=1e-13) -> dict:
    """Curvatures of pinion and gear at Q and the contact ellipse of elastic approach ``delta`` (one row)."""
    c1 = point_curvatures(make_flank(design, 1 / (2 * rho_c), alpha_n, l, beta, "pinion", tol))
    c2 = point_curvatures(make_flank(design, 1 / (2 * rho_t), alpha_n, l, beta, "gear", tol))
    p1, p2 = report_principal(c1), report_principal(c2)
    el = elastic_ellipse_at(p1, p2, delta)
    n = p1.normal
    major = np.asarray(el.major_axis)
    t1 = c1["path_tangent"][0]
    t2 = c2["path_tangent"][0]
    return dict(
        kappa_I_1_per_in=c1["kI"][0],
        kappa_II_1_per_in=c1["kII"][0],
        kappa_I_2_per_in=c2["kI"][0],
        kappa_II_2_per_in=c2["kII"][0],
        kappa_I_1_dg_per_in=c1["kI_dg"][0],
        kappa_II_1_dg_per_in=c1["kII_dg"][0],
        kappa_I_2_dg_per_in=c2["kI_dg"][0],
        kappa_II_2_dg_per_in=c2["kII_dg"][0],
        sigma_deg=line_angle(c1["eI"][0], c2["eI"][0], n),
        sigma_1c_deg=c1["sigma_rack_deg"][0],
        sigma_2t_deg=c2["sigma_rack_deg"][0],
        major_2a_in=2 * float(el.a),
        minor_2b_in=2 * float(el.b),
        area_in2=float(el.area),
        alpha1_deg=float(np.degrees(el.alpha)),
        elliptic=bool(el.elliptic),
        mu1_deg=line_angle(t1, major, n),
        mu2_deg=line_angle(t2, major, n),
        path_tangent_angle_deg=abs(line_angle(t1, t2, n)),
    )


def make_pair(design, rho_c, rho_t, alpha_n, l, beta, *, misalignment=None, d_lambda=0.0, tol=1e-13, hand="left"):
    """Profile-crowned pair in :class:`gearrep.tca.GearPair` frames. ``hand`` of the pinion:
    "left" as in the report (sec. 2.1) uses the rack helix angle -beta (with member_side -1 a
    positive rack helix angle generates a right-hand member, :mod:`gearrep.surfaces.rack`).
    ``d_lambda`` > 0 increases the pinion's lead angle (decreases its helix angle) while its
    pitch cylinder is kept."""
    if hand not in ("left", "right"):
        raise ValueError(f"hand must be 'left' or 'right', got {hand!r}")
    h = -1.0 if hand == "left" else 1.0
    pin = make_flank(design, 1 / (2 * rho_c), alpha_n, l, h * beta, "pinion", tol, beta_rack=h * (beta - d_lambda))
    gear = make_flank(design, 1 / (2 * rho_t), alpha_n, l, h * beta, "gear", tol)
    E = pin.r_p + gear.r_p
    return GearPair(pin, gear, design["N1"], design["N2"], E, misalignment=misalignment, phase2=0.0)


def contact(pair, phi1, settings: dict, start=None):
    """Conventional TCA at ``phi1``; ``settings``: the settings. Default start: the aligned contact
    (:func:`aligned_start`) moved by the misalignment's offset solved at one of the angles
    (:func:`gearrep.tca.offset_start`; the same roots, 2-3 Newton iterations each instead of about
    30 under a 3 arcmin crossing error)."""
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    if start is None:
        start = offset_start(pair, phi1, aligned_start, tol=settings["tol"], maxiter=settings["maxiter"])
    return solve_contact(
        pair, phi1, start, formulation="conventional", tol=settings["tol"], maxiter=settings["maxiter"]
    )


def worm_rack_coefficients(design, which: str) -> tuple[float, float]:
    """(a_c, a_t) in 1/in of the worm-ground pair: ``"s5.4_printed"`` the sec. 5.4 example's printed
    0.425 / 0.394, ``"eq_2.7.2"`` 1/(2 rho) with rho = (5.88, 6.35)/P_n (0.42517 / 0.39370)."""
    if which == "s5.4_printed":
        return design["a_c_s54_per_in"], design["a_t_s54_per_in"]
    if which == "eq_2.7.2":
        Pn = design["P_n_per_in"]
        return Pn / (2 * design["rho_c_times_Pn"]), Pn / (2 * design["rho_t_times_Pn"])
    raise ValueError(f"worm_rack_coefficients must be 's5.4_printed' or 'eq_2.7.2', got {which!r}")


def make_worm_pair(
    design, settings, *, misalignment=None, d_lambda=0.0, a_pl=None, feed=None, worm_hand=None, racks=None
):
    """Pinion ground by the plunging worm of sec. 5.4 (r_pw, a_pl, N_w = 1) with the profile-
    crowned gear (rack-generated), in :class:`gearrep.tca.GearPair` frames; left-hand pinion by
    default (``pinion_hand``). ``d_lambda``: pinion lead-angle error (worm set to beta - d_lambda).
    ``feed``, ``worm_hand``: :class:`gearrep.surfaces.worm_ground.WormGeneratedPinion`; ``racks``:
    :func:`worm_rack_coefficients` (defaults: the settings ``worm_feed``, ``worm_hand``,
    ``worm_rack_coefficients``)."""
    a_c, a_t = worm_rack_coefficients(design, settings["worm_rack_coefficients"] if racks is None else racks)
    Pn, an, beta, l = basics(design)
    h = -1.0 if settings["pinion_hand"] == "left" else 1.0
    r_p1 = pitch_radius(design["N1"], Pn, beta)
    worm = WormGeneratedPinion(
        a_c,
        an,
        l,
        h * (beta - d_lambda),
        r_p1,
        Pn,
        design["r_pw_in"],
        design["a_pl_per_in"] if a_pl is None else a_pl,
        N_w=int(design["N_w"]),
        tol=settings["tol"],
        feed=settings["worm_feed"] if feed is None else feed,
        worm_hand=settings["worm_hand"] if worm_hand is None else worm_hand,
    )
    rec = worm.solve(np.array([0.0]), np.array([0.0]))
    nrm = worm.evaluate(np.array([0.0]), np.array([0.0])).normal[0]
    worm.outward_sign = int(np.sign(np.dot(nrm, rec.normal[0])))
    gear = make_flank(design, a_t, an, l, h * beta, "gear", settings["tol"])
    pair = GearPair(
        worm.light(), gear, design["N1"], design["N2"], r_p1 + gear.r_p, misalignment=misalignment, phase2=0.0
    )
    # TCA starts: the pinion turns by psi + kappa l (kappa = 0 for the translation feed), so the
    # contact at phi1 has psi ~ -phi1 - kappa l; z of the generated point ~ z0 + z_psi psi + z_l l
    zs = worm.solve(np.array([0.0, 0.0, 0.2]), np.array([-1.0, 1.0, 0.0])).point[:, 2]
    z0, z_l, z_psi = 0.5 * (zs[0] + zs[1]), 0.5 * (zs[1] - zs[0]), (zs[2] - 0.5 * (zs[0] + zs[1])) / 0.2
    k = worm.kappa

    def start_of(z, phi1):
        ll = (np.asarray(z) - z0 + z_psi * np.asarray(phi1)) / (z_l - z_psi * k)
        return -np.asarray(phi1) - k * ll, ll

    pair.worm_start_of = start_of
    return pair


def make_disk_pair(design, settings, E_d, *, misalignment=None, d_lambda=0.0):
    """Pinion ground by the plunging disk (sec. 4.2, appendices A-B; disk-pinion shortest distance
    ``E_d``, plunge a_pd of eq 5.4.13 from a_pl) with the profile-crowned gear; racks of sec. 5.4
    (``worm_rack_coefficients``), tooth space from ``heights_rack_tooth_over_pitch``; left-hand
    pinion by default. ``d_lambda``: lead-angle error of the ground helicoid (beta - d_lambda)."""
    Pn, an, beta, l = basics(design)
    h = -1.0 if settings["pinion_hand"] == "left" else 1.0
    a_c, a_t = worm_rack_coefficients(design, settings["worm_rack_coefficients"])
    pin = make_flank(design, a_c, an, l, h * beta, "pinion", settings["tol"], beta_rack=h * (beta - d_lambda))
    gear = make_flank(design, a_t, an, l, h * beta, "gear", settings["tol"])
    alpha_t = np.arctan(np.tan(an) / np.cos(beta))
    p_n = np.pi / Pn
    disk = DiskGroundPinion(
        pin,
        design["N1"],
        p_n,
        settings["heights_rack_tooth_over_pitch"] * p_n,
        E_d,
        a_d_eq_5_4_13(design["a_pl_per_in"], alpha_t, design["N1"]),
    )
    return GearPair(disk, gear, design["N1"], design["N2"], pin.r_p + gear.r_p, misalignment=misalignment, phase2=0.0)


def disk_start(pair, phi1):
    """TCA start for the disk-ground pinion: the aligned profile-crowned contact (u = 0 helices),
    the screw angle psi = -z/p from its axial position."""
    rack_like = aligned_start(_RackView(pair), phi1)
    th2 = rack_like[:, 3]
    z = pair.flank2.evaluate(np.zeros_like(th2), th2).r[:, 2]
    return np.column_stack([np.zeros_like(z), -z / pair.flank1.p, np.zeros_like(z), th2, pair.ratio * np.asarray(phi1)])


def solve_with_retries(pair, phi, start, settings, passes=3):
    """Conventional TCA at all phi from ``start``; points that fail are restarted from the nearest
    converged neighbour (linear predictor from two neighbours when available)."""
    c = solve_contact(pair, phi, start, formulation="conventional", tol=settings["tol"], maxiter=settings["maxiter"])
    for _ in range(passes):
        bad = np.nonzero(~c.converged)[0]
        good = np.nonzero(c.converged)[0]
        if len(bad) == 0 or len(good) == 0:
            break
        X = c.unknowns("conventional")
        st = []
        for i in bad:
            j = good[np.argsort(np.abs(good - i))[:2]]
            if len(j) == 2 and phi[j[0]] != phi[j[1]]:
                st.append(X[j[0]] + (X[j[0]] - X[j[1]]) * (phi[i] - phi[j[0]]) / (phi[j[0]] - phi[j[1]]))
            else:
                st.append(X[j[0]])
        c2 = solve_contact(
            pair, phi[bad], np.array(st), formulation="conventional", tol=settings["tol"], maxiter=settings["maxiter"]
        )
        fixed = c2.converged
        if not fixed.any():
            break
        idx = bad[fixed]
        parts = {f: getattr(c, f).copy() for f in c.ARRAYS}
        for f in parts:
            parts[f][idx] = getattr(c2, f)[fixed]
        c = type(c)(formulation=c.formulation, **parts)
    return c


class _RackView:
    """Duck-typed pair for :func:`aligned_start` using only the gear flank (its theta start)."""

    def __init__(self, pair):
        self.flank1, self.flank2, self.ratio = pair.flank2, pair.flank2, pair.ratio


def worm_start(pair, phi1):
    """TCA start for the worm-ground pinion: the aligned profile-crowned contact (u = 0 helices),
    mapped to the pinion's generating parameters (psi from the pinion turn, l from the axial
    position: :func:`make_worm_pair`)."""
    rack_like = aligned_start(_RackView(pair), phi1)
    th2 = rack_like[:, 3]
    g = pair.flank2.evaluate(np.zeros_like(th2), th2).r
    z = g[:, 2]
    psi, ll = pair.worm_start_of(z, phi1)
    return np.column_stack([psi, ll, np.zeros_like(z), th2, pair.ratio * np.asarray(phi1)])
