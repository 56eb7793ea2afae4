"""Contact geometry at the TCA points of an assembled CATT pair: curvatures, relative curvature,
the elastic-approach ellipse (seed 004 eq 21-27) with and without truncation by the flank edges.

Routes, each a column group of the ``cycle`` table:

* main: principal curvatures of each flank (:mod:`gearrep.curvature`, w.r.t. the pinion's
  normal) and Litvin's elastic-approach ellipse with the true sigma (:mod:`gearrep.ellipse`):
  ``a_mm``, ``b_mm``, ``S_mm2``;
* tensor: eigenvalues of K = -(II_1 + II_2) (second forms w.r.t. each flank's outward normal in
  one orthonormal tangent basis (axial, profile)): ``kappa_long/short_per_mm``, ``S_tensor_mm2``;
* the paper's eq (16)-(26): curvatures ordered k1 >= k2 (eq 16), the angle ``sigma_deg`` between
  e1^I and e1^II, A, B and alpha^I (eq 23-26, computed by the library route
  :func:`gearrep.ellipse.litvin_coefficients`), and eq (20)'s like-indexed differences next to
  the differences paired by direction;
* the closed form on the middle section (:func:`.assembly.closed_form_ellipse`).

Precision: on the middle section the long axis comes from kappa_a ~ c (pi m / 2) / R_T^2, a
difference of two axial curvatures ~ c / R_T that are 30 to 130 times larger (table
``precision``), so the surfaces' derivatives are analytic.

Truncation (``S_clipped_mm2``): the ellipse in the tangent plane is intersected with the
projections of both flanks, bounded by each member's tip edge (solved on the real surface over
the face width) and the face ends |z| <= B/2; contact beyond a tip gives 0.
"""

from __future__ import annotations

import functools

import numpy as np
import pandas as pd

from ... import curvature as _curv
from ... import ellipse as _ellipse
from ...frames import rot_z
from ...solve import Status, status_names
from ...surface import SurfacePoint
from ...surfaces.catt import Mesh
from ...units import ARCSEC
from .assembly import closed_form_ellipse
from .model import eq20_like_indexed

__all__ = ["tip_edges", "gauss_nodes", "clip_area", "contact_geometry", "COLUMNS"]

_FIELDS = ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv")

#: columns of :func:`contact_geometry`, in order
COLUMNS = (
    "phi1_mesh_deg",
    "phi2_mesh_deg",
    "status",
    "residual",
    "iterations",
    "solved",
    "on_flank",
    "x_mm",
    "y_mm",
    "z_mm",
    "r1_mm",
    "r2_mm",
    "te_arcsec",
    "theta1_rad",
    "phig1_rad",
    "theta2_rad",
    "phig2_rad",
    "normal_mismatch",
    "k1_pinion_per_mm",
    "k2_pinion_per_mm",
    "k1_gear_per_mm",
    "k2_gear_per_mm",
    "k_axial_pinion_per_mm",
    "k_profile_pinion_per_mm",
    "k_axial_gear_per_mm",
    "k_profile_gear_per_mm",
    "sigma_deg",
    "kappa_long_per_mm",
    "kappa_short_per_mm",
    "a_mm",
    "b_mm",
    "S_mm2",
    "S_clipped_mm2",
    "S_tensor_mm2",
    "sigma_true_deg",
    "orientation_deg",
    "alphaI_eq26_deg",
    "A_eq23",
    "B_eq24",
    "eq20_algebraic_1_per_mm",
    "eq20_algebraic_2_per_mm",
    "eq20_paired_axial_per_mm",
    "eq20_paired_profile_per_mm",
    "S_closed_form_mm2",
    "a_closed_form_mm",
    "b_closed_form_mm",
    "S_rel_diff_closed_form",
)


def tip_edges(mesh: Mesh, n_tip_edge: int):
    """Tip edges of both flanks in their placed (pre-rotated) frames, ``n_tip_edge`` samples of z
    over the face width (NaN where the point solve did not converge)."""
    out = []
    for f, p in ((mesh.f1, mesh.p1), (mesh.f2, mesh.p2)):
        z = np.linspace(-0.5 * f.gear.face_width, 0.5 * f.gear.face_width, n_tip_edge)
        pts, res = f.tip_edge(z)
        pts = np.where(res.converged[:, None], pts, np.nan)
        out.append(np.einsum("ij,nj->ni", p.Q, pts) + p.t)
    return out


@functools.lru_cache(maxsize=8)
def gauss_nodes(n_nodes):
    """Gauss-Legendre nodes and weights mapped to t in (-pi/2, pi/2), cached (leggauss costs
    O(n^3)); the arrays are read-only."""
    t, w = np.polynomial.legendre.leggauss(n_nodes)
    t, w = 0.5 * np.pi * t, 0.5 * np.pi * w
    t.flags.writeable = False
    w.flags.writeable = False
    return t, w


def clip_area(a, b, e_long, e_short, P, tip1, tip2, B1, B2, nodes):
    """Area of the ellipse (semi-axes a along e_long, b along e_short, centre P) inside the
    projections of both flanks: for each xi along the long axis, the chord |eta| <= b sqrt(1 -
    xi^2/a^2) is cut by the projected tip edge of each member (on the side away from P) and by
    the face ends |z| <= B/2. Gauss-Legendre in t with xi = a sin t (``nodes``: :func:`gauss_nodes`)."""
    t, w = nodes
    xi = a * np.sin(t)
    h = b * np.cos(t)
    lo, hi = -h, h.copy()
    for tip in (tip1, tip2):
        ok = np.all(np.isfinite(tip), axis=1)
        d = tip[ok] - P
        txi, teta = d @ e_long, d @ e_short
        order = np.argsort(txi)
        txi, teta = txi[order], teta[order]
        f0 = np.interp(0.0, txi, teta)
        f = np.interp(xi, txi, teta, left=np.nan, right=np.nan)
        f = np.where(np.isfinite(f), f, np.inf if f0 > 0 else -np.inf)
        if f0 > 0:
            hi = np.minimum(hi, f)
        else:
            lo = np.maximum(lo, f)
    # face ends: axial coordinate of the tangent-plane point ~ P_z + xi e_long_z (+ eta e_short_z)
    zc = P[2] + xi * e_long[2]
    inside = (np.abs(zc) <= 0.5 * B1) & (np.abs(zc) <= 0.5 * B2)
    L = np.where(inside, np.maximum(hi - lo, 0.0), 0.0)
    return float(np.sum(w * L * a * np.cos(t)))


def _rotate(Rs, v):
    return np.einsum("nij,nj->ni", Rs, v)


def _carried(P: SurfacePoint, Rs, t=None) -> SurfacePoint:
    """Surface points and derivatives carried by the rotations ``Rs`` (n, 3, 3) (and translation t)."""
    r = _rotate(Rs, P.r) + (0 if t is None else t)
    return SurfacePoint(r, *(_rotate(Rs, getattr(P, f)) for f in _FIELDS[1:]))


def _unit_normal(M: SurfacePoint):
    n = np.cross(M.r_u, M.r_v)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def _eig(K):
    """Eigenvalues (max, min) and the angle of the max eigenvector in the basis, of symmetric 2x2
    forms K (..., 2, 2) (:func:`gearrep.curvature.sym2_eig`)."""
    return _curv.sym2_eig(K[..., 0, 0], K[..., 1, 0], K[..., 1, 1])


def _library_route(M1, M2, n1, n2, delta):
    """Main route: principal curvatures of each flank w.r.t. the pinion's normal and Litvin's
    elastic-approach ellipse with the true sigma. NaN where the normals are not opposite."""
    n = len(n1)
    ok = np.all(np.isfinite(n1), axis=-1) & np.all(np.isfinite(n2), axis=-1) & (np.sum(n1 * n2, axis=-1) < -0.999)
    a, b, S, sigma = (np.full(n, np.nan) for _ in range(4))
    e_long = np.full((n, 3), np.nan)
    if ok.any():
        sp1 = SurfacePoint(*(getattr(M1, f)[ok] for f in _FIELDS))
        sp2 = SurfacePoint(*(getattr(M2, f)[ok] for f in _FIELDS))
        pc1 = _curv.principal_curvatures(sp1)
        pc2 = _curv.with_opposite_normal(_curv.principal_curvatures(sp2))  # gear w.r.t. the pinion's normal
        el = _ellipse.elastic_ellipse_at(pc1, pc2, delta, normal_tol=1e-6)
        rel = _curv.relative_curvature(pc1, pc2, normal_tol=1e-6)
        a[ok], b[ok], S[ok] = el.a, el.b, el.area
        sigma[ok] = np.degrees(np.abs(rel.sigma))
        e_long[ok] = el.major_axis
        if not np.all(el.elliptic):
            raise RuntimeError("relative curvature is not definite at a contact point (no elastic-approach ellipse)")
    return {"a_mm": a, "b_mm": b, "S_mm2": S, "sigma_true_deg": sigma}, e_long


def _paper_route(K1, K2, concave_is_1: bool) -> dict:
    """Seed 004 eq (16)-(26) with Sigma^I concave, Sigma^II convex, common normal = outward normal
    of the convex flank: k1 >= k2 ordered algebraically (eq 16), sigma between e1^I and e1^II,
    A, B, alpha^I (eq 23-26 by the library route), eq (20) as printed and paired by direction."""
    KI = -(K1 if concave_is_1 else K2)  # concave member w.r.t. the outward normal of the convex one
    KII = K2 if concave_is_1 else K1  # convex member w.r.t. its outward normal
    k1I, k2I, thI = _eig(KI)
    k1II, k2II, thII = _eig(KII)
    cs = np.clip(np.abs(np.cos(thI) * np.cos(thII) + np.sin(thI) * np.sin(thII)), 0, 1)
    sigma = np.arccos(cs)  # angle between e1^I and e1^II (algebraic ordering, eq 16)
    A, B, alphaI = _ellipse.litvin_coefficients(k1I, k2I, k1II, k2II, sigma)
    eq20_1, eq20_2 = eq20_like_indexed(k1I, k2I, k1II, k2II)
    return {
        "sigma_deg": np.degrees(sigma),
        "alphaI_eq26_deg": np.degrees(np.abs(alphaI)),
        "A_eq23": A,
        "B_eq24": B,
        "eq20_algebraic_1_per_mm": eq20_1,
        "eq20_algebraic_2_per_mm": eq20_2,
        "eq20_paired_axial_per_mm": KI[..., 0, 0] - KII[..., 0, 0],
        "eq20_paired_profile_per_mm": KI[..., 1, 1] - KII[..., 1, 1],
    }


def _truncated_areas(mesh, cp, params, tips, R1, R2, n1, e_long, a, b, S, solved):
    """S_clipped at every solved point on both flanks (0 elsewhere)."""
    on = solved & mesh.f1.contains(cp.u1, cp.v1) & mesh.f2.contains(cp.u2, cp.v2)
    O2 = mesh.gear_pair.O2
    Sc = np.zeros(len(cp.phi1))
    nodes = gauss_nodes(params["n_clip_nodes"])
    for i in range(len(Sc)):
        if not (on[i] and np.isfinite(S[i])):
            continue
        t1 = _rotate(np.broadcast_to(R1[i], (len(tips[0]), 3, 3)), tips[0])
        t2 = _rotate(np.broadcast_to(R2[i], (len(tips[1]), 3, 3)), tips[1]) + O2
        es = np.cross(n1[i], e_long[i])
        Sc[i] = clip_area(
            a[i], b[i], e_long[i], es, cp.position[i], t1, t2, mesh.g1.face_width, mesh.g2.face_width, nodes
        )
    return Sc, on


def contact_geometry(mesh: Mesh, cp, params: dict, tips=None, clip: bool = True) -> pd.DataFrame:
    """Curvatures, relative curvature and the ellipse (with and without truncation) at TCA points
    ``cp``. ``params`` brings ``delta_mm`` and ``n_tip_edge``/``n_clip_nodes``; ``tips`` from
    :func:`tip_edges` (computed if None); ``clip=False`` skips the truncation (S_clipped NaN)."""
    delta = params["delta_mm"]
    R1, R2 = rot_z(np.asarray(cp.phi1, float)), rot_z(-np.asarray(cp.phi2, float))
    with np.errstate(invalid="ignore", divide="ignore"):
        M1 = _carried(mesh.p1.evaluate(cp.u1, cp.v1), R1)
        M2 = _carried(mesh.p2.evaluate(cp.u2, cp.v2), R2, mesh.gear_pair.O2)
        n1, n2 = _unit_normal(M1), _unit_normal(M2)
        e_ax = np.array([0.0, 0.0, 1.0]) - n1 * n1[:, 2:3]
        e_ax /= np.linalg.norm(e_ax, axis=-1, keepdims=True)
        e_pr = np.cross(n1, e_ax)
        K1 = _curv.second_form_in_basis(M1, n1, e_ax, e_pr)
        K2 = _curv.second_form_in_basis(M2, n2, e_ax, e_pr)
        k1_pin, k2_pin, _ = _eig(K1)
        k1_gear, k2_gear, _ = _eig(K2)
        kb, ka, _ = _eig(-(K1 + K2))  # eigenvalues of the relative curvature tensor
        S_tensor = np.pi * np.sqrt(2 * delta / ka) * np.sqrt(2 * delta / kb)
    main, e_long = _library_route(M1, M2, n1, n2, delta)
    # angle of the long axis to the axial tangent direction e_ax (projection of the gear axis)
    orient = np.degrees(
        np.arctan2(np.linalg.norm(np.cross(e_long, e_ax), axis=-1), np.abs(np.sum(e_long * e_ax, axis=-1)))
    )
    solved = (cp.status == Status.CONVERGED) | (cp.status == Status.OFF_FLANK)
    if clip:
        tips = tip_edges(mesh, params["n_tip_edge"]) if tips is None else tips
        Sc, on = _truncated_areas(
            mesh, cp, params, tips, R1, R2, n1, e_long, main["a_mm"], main["b_mm"], main["S_mm2"], solved
        )
    else:
        Sc, on = np.full(len(cp.phi1), np.nan), solved & mesh.f1.contains(cp.u1, cp.v1) & mesh.f2.contains(cp.u2, cp.v2)
    cf = closed_form_ellipse(mesh, cp.phi1, delta)
    O2 = mesh.gear_pair.O2
    df = pd.DataFrame(
        {
            "phi1_mesh_deg": np.degrees(cp.phi1),
            "phi2_mesh_deg": np.degrees(cp.phi2),
            "status": status_names(cp.status),
            "residual": cp.residual,
            "iterations": cp.iterations,
            "solved": solved,
            "on_flank": on,
            "x_mm": cp.position[:, 0],
            "y_mm": cp.position[:, 1],
            "z_mm": cp.position[:, 2],
            "r1_mm": np.hypot(M1.r[:, 0], M1.r[:, 1]),
            "r2_mm": np.hypot(M2.r[:, 0] - O2[0], M2.r[:, 1] - O2[1]),
            "te_arcsec": cp.te / ARCSEC,
            "theta1_rad": cp.u1,
            "phig1_rad": cp.v1,
            "theta2_rad": cp.u2,
            "phig2_rad": cp.v2,
            "normal_mismatch": np.linalg.norm(n1 + n2, axis=-1),
            "k1_pinion_per_mm": k1_pin,
            "k2_pinion_per_mm": k2_pin,
            "k1_gear_per_mm": k1_gear,
            "k2_gear_per_mm": k2_gear,
            "k_axial_pinion_per_mm": K1[..., 0, 0],
            "k_profile_pinion_per_mm": K1[..., 1, 1],
            "k_axial_gear_per_mm": K2[..., 0, 0],
            "k_profile_gear_per_mm": K2[..., 1, 1],
            "kappa_long_per_mm": ka,
            "kappa_short_per_mm": kb,
            **{k: main[k] for k in ("a_mm", "b_mm", "S_mm2")},
            "S_clipped_mm2": Sc,
            "S_tensor_mm2": S_tensor,
            "sigma_true_deg": main["sigma_true_deg"],
            "orientation_deg": orient,
            **_paper_route(K1, K2, mesh.f1.side == -1),
            "S_closed_form_mm2": cf["S"],
            "a_closed_form_mm": cf["a"],
            "b_closed_form_mm": cf["b"],
        }
    )
    with np.errstate(invalid="ignore", divide="ignore"):
        df["S_rel_diff_closed_form"] = df["S_mm2"] / df["S_closed_form_mm2"] - 1.0
    df.loc[~df["solved"], ["S_mm2", "a_mm", "b_mm"]] = np.nan
    return df[list(COLUMNS)]
