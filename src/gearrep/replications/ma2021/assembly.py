"""The readings of seed 004's abscissa and its middle-section closed forms, on the assembled
CATT pair of the library (:func:`gearrep.surfaces.catt.assemble`: our choices, the paper states
none of them: pinion and turned-over gear cut by the same cutter with eq (6), flank pair "A" =
pinion convex on gear concave, "B" = pinion concave on gear convex).

Readings of the paper's abscissa phi1 (not stated): "R1" = pinion angle, contact from the
pinion root to its top; "R2" = gear angle, gear root to top. The primary reading is B/R1 (the
paper names the concave surface first and indexes the abscissa with 1; in R1 the window
-14.5..14.5 deg matches the real meshing cycle of the z1 = 21 pinion).
"""

from __future__ import annotations

import numpy as np

from ...surfaces.catt import Mesh, middle_section_curvatures

__all__ = [
    "PAIR_NAMES",
    "READINGS",
    "PRIMARY",
    "contact_radii",
    "reading_to_mesh",
    "mesh_to_reading",
    "closed_form_ellipse",
    "pitch_point_closed_form",
]

PAIR_NAMES = {"A": "pinion convex / gear concave", "B": "pinion concave / gear convex"}
READINGS = {"R1": "phi1 = pinion angle, pinion root -> top", "R2": "phi1 = gear angle, gear root -> top"}
PRIMARY = ("B", "R1")


def contact_radii(mesh: Mesh, phi1):
    """Closed-form middle-section contact radii (r1, r2) at mesh pinion angle phi1."""
    g1, g2 = mesh.g1, mesh.g2
    c, a = np.cos(g1.pressure_angle), np.sin(g1.pressure_angle)
    D = g1.r_p * np.asarray(phi1, float)
    r1 = np.sqrt(c * c * D * D - 2 * mesh.f1.side * a * c * g1.r_p * D + g1.r_p**2)
    r2 = np.sqrt(c * c * D * D - 2 * mesh.f2.side * a * c * g2.r_p * D + g2.r_p**2)
    return r1, r2


def reading_to_mesh(mesh: Mesh, reading: str, phi_paper):
    """Mesh pinion angle phi1 for the paper abscissa ``phi_paper`` (rad) in ``reading``.

    R1: the pinion radius grows with phi_paper (root -> top): phi1 = -s1 phi_paper.
    R2: the gear radius grows with phi_paper: phi2 = s1 phi_paper, phi1 = phi2 z2 / z1."""
    phi_paper = np.asarray(phi_paper, float)
    if reading == "R1":
        return -mesh.s1 * phi_paper
    if reading == "R2":
        return mesh.s1 * phi_paper / mesh.ratio
    raise ValueError(f"reading must be 'R1' or 'R2', got {reading!r}")


def mesh_to_reading(mesh: Mesh, reading: str, phi1):
    """Inverse of :func:`reading_to_mesh`."""
    phi1 = np.asarray(phi1, float)
    return -mesh.s1 * phi1 if reading == "R1" else mesh.s1 * phi1 * mesh.ratio


def closed_form_ellipse(mesh: Mesh, phi1, delta: float) -> dict:
    """Closed-form relative curvatures, semi-axes and area on the middle-section path."""
    r1, r2 = contact_radii(mesh, phi1)
    kp1, ka1, rho1, _ = middle_section_curvatures(mesh.g1, mesh.f1.side, r1)
    kp2, ka2, rho2, _ = middle_section_curvatures(mesh.g2, mesh.f2.side, r2)
    k_prof = -(kp1 + kp2)
    k_ax = -(ka1 + ka2)
    with np.errstate(invalid="ignore", divide="ignore"):
        a = np.sqrt(2 * delta / k_ax)
        b = np.sqrt(2 * delta / k_prof)
    return {
        "kappa_axial": k_ax,
        "kappa_profile": k_prof,
        "a": a,
        "b": b,
        "S": np.pi * a * b,
        "rho_blade1": rho1,
        "rho_blade2": rho2,
    }


def pitch_point_closed_form(design: dict, params: dict) -> dict:
    """Closed-form ellipse at the pitch point (middle section, involute): profile radii
    R_i sin(alpha), axial radii R_T -+ q (q = pi m / 4), S = 2 pi delta / sqrt(k_profile k_axial)."""
    al = np.deg2rad(params["pressure_angle_deg"])
    R1, R2 = design["module"] * design["z1"] / 2, design["module"] * design["z2"] / 2
    q = np.pi * design["module"] / 4
    RT = design["R_T"]
    kp = (1 / R1 + 1 / R2) / np.sin(al)
    ka = np.cos(al) * (1 / (RT - q) - 1 / (RT + q))
    d = params["delta_mm"]
    a, b = np.sqrt(2 * d / ka), np.sqrt(2 * d / kp)
    return {
        "kappa_axial": ka,
        "kappa_profile": kp,
        "a": a,
        "b": b,
        "S": np.pi * a * b,
        "S_formula": 2 * np.pi * d / np.sqrt(ka * kp),
    }
