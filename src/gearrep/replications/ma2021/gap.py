"""Exact separation check of the elastic-approach ellipse: the region where the two flanks are
at most delta apart around a TCA point, found along rays of the tangent plane."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd

from ...frames import rot_z
from ...solve import newton
from ...surfaces.catt import Mesh

__all__ = ["exact_contact_region"]


def _heights(surface_pos, surface_eval, P, e1, e2, n, w1, w2, start):
    """Heights h along n of a surface above tangent-plane points P + w1 e1 + w2 e2 (Newton on the
    two in-plane equations; parameters frozen per row)."""
    m = len(w1)

    def F(X):
        r = surface_pos(X[:, 0], X[:, 1]) - P
        return np.column_stack([r @ e1 - X[:, 2], r @ e2 - X[:, 3], np.zeros(len(X)), np.zeros(len(X))])

    def J(X):
        Q = surface_eval(X[:, 0], X[:, 1])
        Jm = np.zeros((len(X), 4, 4))
        Jm[:, 0, 0], Jm[:, 0, 1], Jm[:, 0, 2] = Q.r_u @ e1, Q.r_v @ e1, -1
        Jm[:, 1, 0], Jm[:, 1, 1], Jm[:, 1, 3] = Q.r_u @ e2, Q.r_v @ e2, -1
        Jm[:, 2, 2] = Jm[:, 3, 3] = 1
        return Jm

    x0 = np.column_stack([np.broadcast_to(start, (m, 2)), w1, w2])
    res = newton(F, x0, J, tol=1e-12, maxiter=30)
    r = surface_pos(res.x[:, 0], res.x[:, 1]) - P
    return r @ n, res


def exact_contact_region(mesh: Mesh, row: pd.Series, params: dict, n_dirs: int) -> dict:
    """Region where the exact separation of the two flanks is <= delta, around a TCA point:
    boundary radius found along ``n_dirs`` directions of the tangent plane; its area and centroid
    compared with the ellipse."""
    delta = params["delta_mm"]
    phi1, phi2 = np.radians(row["phi1_mesh_deg"]), np.radians(row["phi2_mesh_deg"])
    R1, R2 = rot_z(phi1), rot_z(-phi2)
    O2 = mesh.gear_pair.O2
    pos1 = lambda u, v: mesh.p1.position(u, v) @ R1.T  # noqa: E731
    pos2 = lambda u, v: mesh.p2.position(u, v) @ R2.T + O2  # noqa: E731

    def _E(surf, R):
        def ev(u, v):
            Q = surf.evaluate(u, v)
            return SimpleNamespace(r_u=Q.r_u @ R.T, r_v=Q.r_v @ R.T)

        return ev

    ev1, ev2 = _E(mesh.p1, R1), _E(mesh.p2, R2)
    P = np.array([row["x_mm"], row["y_mm"], row["z_mm"]])
    Q1 = mesh.p1.evaluate(row["theta1_rad"], row["phig1_rad"])
    n = np.cross(Q1.r_u @ R1.T, Q1.r_v @ R1.T)
    n /= np.linalg.norm(n)
    e1 = np.array([0.0, 0.0, 1.0]) - n * n[2]
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    psi = np.linspace(0, 2 * np.pi, n_dirs, endpoint=False)
    c, s = np.cos(psi), np.sin(psi)
    # start from the ellipse radius in each direction (long axis ~ e1)
    a, b = row["a_mm"], row["b_mm"]
    rho = 1.0 / np.sqrt((c / a) ** 2 + (s / b) ** 2)
    st1 = np.array([row["theta1_rad"], row["phig1_rad"]])
    st2 = np.array([row["theta2_rad"], row["phig2_rad"]])
    ok = np.ones(n_dirs, bool)
    for _ in range(12):
        h1, r1 = _heights(pos1, ev1, P, e1, e2, n, rho * c, rho * s, st1)
        h2, r2 = _heights(pos2, ev2, P, e1, e2, n, rho * c, rho * s, st2)
        gap = h2 - h1
        ok = r1.converged & r2.converged & (gap > 0)
        new = rho * np.sqrt(delta / np.where(ok, gap, delta))
        if np.max(np.abs(new - rho) / rho) < 1e-12:
            rho = new
            break
        rho = new
    area = 0.5 * np.sum(rho**2) * (2 * np.pi / n_dirs)
    cx = np.sum(rho**3 * c) * (2 * np.pi / n_dirs) / 3 / area
    cy = np.sum(rho**3 * s) * (2 * np.pi / n_dirs) / 3 / area
    return {
        "area_exact_mm2": area,
        "centroid_long_mm": cx,
        "centroid_short_mm": cy,
        "max_radius_mm": float(rho.max()),
        "min_radius_mm": float(rho.min()),
        "all_solved": bool(ok.all()),
    }
