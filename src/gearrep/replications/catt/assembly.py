"""The assembled CATT pair of seed 004 and its middle-section closed forms.

Assembly (our choices; the paper states none of them): member 1 = pinion (z1), member 2 = gear
(z2), both cut by the same cutter (same R_T, m, alpha) with eq (6). Flank pair "A" = pinion
convex (s1 = +1) on gear concave (s2 = -1), pair "B" = pinion concave on gear convex. The gear
is turned over ((x, y, z) -> (x, -y, -z)) so that its circular tooth traces bend the same way
as the pinion's in the common pitch plane. Frames are those of :mod:`gearrep.tca` (pinion axis z
through the origin, gear axis through (R1 + R2, 0, 0)); each flank is pre-rotated so that its
middle-section pitch point lies at the pitch point at phi1 = phi2 = 0.

Readings of the paper's abscissa phi1 (not stated): "R1" = pinion angle, contact from the
pinion root to its top; "R2" = gear angle, gear root to top. The primary reading is B/R1 (the
paper names the concave surface first and indexes the abscissa with 1; in R1 the window
-14.5..14.5 deg matches the real meshing cycle of the z1 = 21 pinion).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...frames import rot_z
from ...surface import RotatedSurface
from ...surfaces.catt import CATTFlank, CATTGearData, middle_section_curvatures, turn_over

__all__ = [
    "PAIRS",
    "PAIR_NAMES",
    "READINGS",
    "PRIMARY",
    "Mesh",
    "gear_data",
    "assemble",
    "path_limits",
    "contact_radii",
    "reading_to_mesh",
    "mesh_to_reading",
    "closed_form_ellipse",
    "pitch_point_closed_form",
    "starts",
    "solve_cycle",
]

PAIRS = {"A": (1, -1), "B": (-1, 1)}  #: flank pair -> (pinion side, gear side); +1 convex, -1 concave
PAIR_NAMES = {"A": "pinion convex / gear concave", "B": "pinion concave / gear convex"}
READINGS = {"R1": "phi1 = pinion angle, pinion root -> top", "R2": "phi1 = gear angle, gear root -> top"}
PRIMARY = ("B", "R1")


@dataclass
class Mesh:
    """One assembled CATT pair with flank pair ``pair_id`` ("A" or "B")."""

    design: dict
    pair_id: str
    g1: CATTGearData
    g2: CATTGearData
    f1: CATTFlank
    f2: CATTFlank
    p1: RotatedSurface
    p2: RotatedSurface
    gear_pair: object

    @property
    def s1(self):
        return self.f1.side

    @property
    def ratio(self):
        return self.g1.n_teeth / self.g2.n_teeth


def gear_data(design: dict, prm: dict, member: int) -> CATTGearData:
    """Gear data of member 1 (pinion) or 2 (gear) of ``design``; ``prm`` brings the pressure angle
    (deg), addendum and clearance coefficients."""
    return CATTGearData(
        design["z1"] if member == 1 else design["z2"],
        design["module"],
        design["R_T"],
        design["face_width"],
        np.deg2rad(prm["pressure_angle_deg"]),
        prm["addendum"],
        prm["clearance"],
    )


def assemble(design: dict, pair_id: str, prm: dict) -> Mesh:
    """Mount pinion and turned-over gear (module docstring) in the frames of :mod:`gearrep.tca`."""
    from ...tca import GearPair

    s1, s2 = PAIRS[pair_id]
    g1, g2 = gear_data(design, prm, 1), gear_data(design, prm, 2)
    f1, f2 = CATTFlank(g1, s1), CATTFlank(g2, s2)
    Q1 = rot_z(0.5 * np.pi - s1 * g1.q / g1.r_p)
    Q2 = rot_z(0.5 * np.pi + s2 * g2.q / g2.r_p) @ turn_over()
    p1, p2 = RotatedSurface(f1, Q1), RotatedSurface(f2, Q2)
    gp = GearPair(p1, p2, g1.n_teeth, g2.n_teeth, g1.r_p + g2.r_p, phase2=0.0)
    return Mesh(design, pair_id, g1, g2, f1, f2, p1, p2, gp)


def path_limits(mesh: Mesh) -> dict:
    """Real meshing cycle on the middle section in mesh pinion angle phi1 (closed form).

    The middle-section contact at pinion angle phi1 lies at line-of-action coordinate D = R1 phi1
    from the pitch point; radii r_i^2 = c^2 D^2 - 2 s_i a_s c R_i D + R_i^2. The cycle is where
    both radii are below the tips."""
    g1, g2 = mesh.g1, mesh.g2
    c, a = np.cos(g1.pressure_angle), np.sin(g1.pressure_angle)
    lims = []
    for g, s in ((g1, mesh.f1.side), (g2, mesh.f2.side)):
        A, B, C = c * c, -2 * s * a * c * g.r_p, g.r_p**2 - g.r_a**2  # c^2 D^2 - 2 s a c R D + R^2 - r_a^2 = 0
        disc = math.sqrt(B * B - 4 * A * C)
        lims.append(sorted([(-B - disc) / (2 * A), (-B + disc) / (2 * A)]))
    Dlo = max(lims[0][0], lims[1][0])
    Dhi = min(lims[0][1], lims[1][1])
    pb = 2 * np.pi * g1.r_b / g1.n_teeth
    return {
        "phi1_lo": Dlo / g1.r_p,
        "phi1_hi": Dhi / g1.r_p,
        "D_lo": Dlo,
        "D_hi": Dhi,
        "contact_ratio": c * (Dhi - Dlo) / pb,
    }


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


def pitch_point_closed_form(design: dict, prm: dict) -> dict:
    """Closed-form ellipse at the pitch point (middle section, involute): profile radii
    R_i sin(alpha), axial radii R_T -+ q (q = pi m / 4), S = 2 pi delta / sqrt(k_profile k_axial)."""
    al = np.deg2rad(prm["pressure_angle_deg"])
    R1, R2 = design["module"] * design["z1"] / 2, design["module"] * design["z2"] / 2
    q = np.pi * design["module"] / 4
    RT = design["R_T"]
    kp = (1 / R1 + 1 / R2) / np.sin(al)
    ka = np.cos(al) * (1 / (RT - q) - 1 / (RT + q))
    d = prm["delta_mm"]
    a, b = np.sqrt(2 * d / ka), np.sqrt(2 * d / kp)
    return {
        "kappa_axial": ka,
        "kappa_profile": kp,
        "a": a,
        "b": b,
        "S": np.pi * a * b,
        "S_formula": 2 * np.pi * d / np.sqrt(ka * kp),
    }


def starts(mesh: Mesh, phi1, offset_mm):
    """Starting points (theta1, phi_g1, theta2, phi_g2, phi2): the middle-section estimate moved
    ``offset_mm`` off the middle section on both members and slightly off in roll and phi2."""
    g1, g2 = mesh.g1, mesh.g2
    phi1 = np.asarray(phi1, float)
    th1 = offset_mm / mesh.f1.rho0
    th2 = -0.7 * offset_mm / mesh.f2.rho0
    pg1 = phi1 - mesh.f1.side * g1.q / g1.r_p + 2e-3
    phi2 = mesh.ratio * phi1
    pg2 = phi2 - mesh.f2.side * g2.q / g2.r_p - 1.5e-3
    n = len(phi1)
    return np.column_stack([np.full(n, th1), pg1, np.full(n, th2), pg2, phi2 + 1e-3])


def solve_cycle(mesh: Mesh, phi1, prm: dict):
    """TCA at mesh pinion angles ``phi1`` by :func:`gearrep.tca.solve_contact` (conventional);
    ``prm`` brings ``start_offset_mm``, ``tol`` and ``maxiter``."""
    from ...tca import solve_contact

    start = starts(mesh, phi1, prm["start_offset_mm"])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return solve_contact(
            mesh.gear_pair, phi1, start, formulation="conventional", tol=prm["tol"], maxiter=prm["maxiter"]
        )
