"""Materials, tooth compliance (Weber-Banaschek beam and Sainsot fillet foundation) and the Hertz
line-contact approach and pressure.

Sources
-------
* C. Weber, K. Banaschek, "Formänderung und Profilrücknahme bei gerad- und schrägverzahnten
  Rädern", Schriftenreihe Antriebstechnik 11, Vieweg, 1953: the tooth as a cantilever of variable
  thickness loaded along the profile normal, deflection along the load line from the strain energy
  of bending, shear and compression; the contact approach of two cylinders (Weber 1949).
* P. Sainsot, P. Velex, O. Duverger, "Contribution of gear body to tooth deflections - a new
  bidimensional analytical formula", J. Mech. Design 126 (2004) 748-752: the fillet-foundation
  deflection (the fit of its Table 1, coefficients below).
* K. L. Johnson, "Contact Mechanics", CUP 1985, sect. 4.3 and 5.2: line contact half-width and
  maximum pressure (also :func:`gearrep.ellipse.hertz_line_max_pressure_MPa`).

Model (per unit length of contact line, plane strain; load F along the profile normal)
-----------------------------------------------------------------------------------------
The tooth section is read from the flank surface itself: the half tooth angle theta(u) at radius u
is the flank's polar angle at mid-face (the tooth is symmetric about its x axis), continued
radially below the base circle down to the root circle (the root fillet is not modelled). The
centre line is the x axis; y = u cos(theta) runs along it and x(y) = u sin(theta) is the half
thickness. At a contact radius r_c with half angle theta_c and transverse outward normal n, the
load angle alpha_F (between the load line and the normal to the centre line) has
cos(alpha_F) = |n_y| / |n_t|; the load line meets the centre line at y_F = r_c cos(theta_c) -
r_c sin(theta_c) n_x / n_y. The deflection along the load line per unit load and length [mm^2/N]:

    bending      12 (1 - nu^2) cos^2(alpha_F) / E  int (y_F - y)^2 / (2x)^3 dy
    shear        2 kappa (1 + nu) cos^2(alpha_F) / E  int dy / (2x),   kappa = 1.2
    compression  (1 - nu^2) sin^2(alpha_F) / E  int dy / (2x)
    foundation   cos^2(alpha_F) / E [L* (u_f/S_f)^2 + M* (u_f/S_f) + P* (1 + Q* tan^2(alpha_F))]

integrals over y from the root chord (y = r_f cos(theta_f)) to y_F (Gauss-Legendre), u_f = y_F - r_f,
S_f = 2 r_f sin(theta_f), and X* = A/theta_f^2 + B h_f^2 + C h_f/theta_f + D/theta_f + E h_f + F with
h_f = r_f / r_bore (Sainsot et al. Table 1).

Contact approach of the two flanks under the load w per unit length (Weber):
    delta_H = (2 w / pi) sum_i (1 - nu_i^2)/E_i [ln(2 h_i / b_H) - nu_i / (2 (1 - nu_i))],
b_H = sqrt(4 w / (pi E* k)) the Hertz half-width, k the relative curvature across the contact line,
h_i the distance from the contact point to member i's tooth centre line along the load line.
The approach is non-linear in w (logarithmic); the load distribution solves it by fixed-point
iteration on the secant compliance (:mod:`gearrep.ltca._analysis`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..ellipse import effective_modulus
from ..inputs import check_finite

__all__ = [
    "Material",
    "STEEL",
    "SAINSOT_COEFFICIENTS",
    "ToothCompliance",
    "contact_half_width_mm",
    "line_contact_pressure_MPa",
    "weber_contact_approach_mm",
]

#: Sainsot, Velex & Duverger (2004) Table 1: rows L*, M*, P*, Q*; columns A, B, C, D, E, F
SAINSOT_COEFFICIENTS = np.array(
    [
        [-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045],
        [60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086],
        [-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236],
        [-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904],
    ]
)

#: shear correction factor of a rectangular section (Timoshenko), used by Weber
SHEAR_FACTOR = 1.2


@dataclass(frozen=True)
class Material:
    """Isotropic elastic material of a gear member: Young's modulus ``E_MPa`` [MPa] > 0 and Poisson
    ratio ``poisson`` in (-1, 0.5]. The default is steel, 206 000 MPa and 0.3 (ISO 6336-2's
    reference for Z_E = 189.8 sqrt(MPa))."""

    E_MPa: float = 206000.0
    poisson: float = 0.3

    def __post_init__(self):
        check_finite("E_MPa", self.E_MPa, positive=True)
        nu = check_finite("poisson", self.poisson)
        if not -1.0 < nu <= 0.5:
            raise ValueError(f"poisson must be in (-1, 0.5], got {self.poisson!r}")


STEEL = Material()


def _involute_gear_of(flank, name: str):
    gear = getattr(flank, "gear", None)
    needed = ("r_b", "r_f", "r_a", "beta_b")
    if gear is None or not all(hasattr(gear, a) for a in needed) or not hasattr(flank, "polar_angle"):
        raise ValueError(
            f"{name}: the tooth compliance needs an involute flank (gearrep.surfaces.involute.InvoluteFlank, "
            f"whose section gives the tooth thickness), got {type(flank).__name__}"
        )
    return gear


class ToothCompliance:
    """Weber-Banaschek tooth compliance of one member (bending, shear, compression and the Sainsot
    fillet foundation), per unit length of contact line, from the member's own flank surface.

    Parameters
    ----------
    flank : an involute flank (``gearrep.surfaces.involute.InvoluteFlank``)
    material : :class:`Material`
    bore_radius_mm : radius of the gear body's bore [mm], default half the root radius (h_f = 2);
        must be below the root radius
    n_profile, n_gauss : points of the tooth-thickness table and Gauss-Legendre nodes of the
        beam integrals
    """

    def __init__(
        self, flank, material: Material = STEEL, bore_radius_mm=None, *, n_profile: int = 2000, n_gauss: int = 64
    ):
        gear = _involute_gear_of(flank, "flank")
        if not isinstance(material, Material):
            raise ValueError(f"material must be a gearrep.ltca.Material, got {type(material).__name__}")
        self.flank, self.material = flank, material
        r_f, r_b = float(gear.r_f), float(gear.r_b)
        bore = 0.5 * r_f if bore_radius_mm is None else check_finite("bore_radius_mm", bore_radius_mm, positive=True)
        if not bore < r_f:
            raise ValueError(f"bore_radius_mm must be < the root radius {r_f!r} mm, got {bore_radius_mm!r}")
        self.r_f, self.r_b, self.bore_radius_mm = r_f, r_b, float(bore)
        u = np.linspace(r_f, float(gear.r_a), int(n_profile))
        theta = self.half_angle(u)
        self._y, self._x = u * np.cos(theta), u * np.sin(theta)
        self.theta_f = float(theta[0])
        self._gauss = np.polynomial.legendre.leggauss(int(n_gauss))
        h_f = r_f / self.bore_radius_mm
        t = self.theta_f
        self._LMPQ = SAINSOT_COEFFICIENTS @ np.array([1 / t**2, h_f**2, h_f / t, 1 / t, h_f, 1.0])

    def half_angle(self, u) -> np.ndarray:
        """Half tooth angle theta(u) [rad] at radius ``u`` [mm]: the flank's polar angle at mid-face
        (side-corrected), constant below the base circle (radial flank down to the root)."""
        f = self.flank
        uu = np.maximum(np.asarray(u, dtype=float), self.r_b)
        tw = f.twist(np.zeros_like(uu))[0]
        return f.side * (f.polar_angle(uu, np.zeros_like(uu)) - tw)

    def load_geometry(self, r_c):
        """(alpha_F [rad], y_F [mm], h [mm], theta_c [rad]) at contact radii ``r_c`` [mm]: load angle,
        where the load line meets the centre line, the distance from the contact point to the centre
        line along the load line, and the half tooth angle."""
        r_c = np.asarray(r_c, dtype=float)
        th = self.half_angle(r_c)
        n = self.flank.evaluate(r_c, np.zeros_like(r_c)).normal
        nx, ny = np.abs(n[..., 0]), np.abs(n[..., 1])
        cos_a = ny / np.hypot(nx, ny)
        px, py = r_c * np.cos(th), r_c * np.sin(th)
        return np.arccos(np.clip(cos_a, -1.0, 1.0)), px - py * nx / ny, py / cos_a, th

    def compliance(self, r_c) -> np.ndarray:
        """Tooth compliance [mm^2 / N] (deflection along the load line per unit load per unit length
        of contact line) at contact radii ``r_c`` [mm]; the sum of the four terms of the module
        docstring."""
        E, nu = self.material.E_MPa, self.material.poisson
        alpha, y_F, _, _ = self.load_geometry(r_c)
        y0 = self.r_f * np.cos(self.theta_f)
        top = np.maximum(y_F, y0)
        s, wq = self._gauss
        half = 0.5 * (top - y0)
        y = y0 + half[..., None] * (s + 1.0)  # (..., n_gauss)
        two_x = 2.0 * np.interp(y, self._y, self._x)
        i_bend = half * np.sum(wq * (top[..., None] - y) ** 2 / two_x**3, axis=-1)
        i_area = half * np.sum(wq / two_x, axis=-1)
        c2, s2 = np.cos(alpha) ** 2, np.sin(alpha) ** 2
        bend = 12.0 * (1.0 - nu**2) * c2 * i_bend / E
        shear = 2.0 * SHEAR_FACTOR * (1.0 + nu) * c2 * i_area / E
        comp = (1.0 - nu**2) * s2 * i_area / E
        L, M, P, Q = self._LMPQ
        ratio = (y_F - self.r_f) / (2.0 * self.r_f * np.sin(self.theta_f))
        found = c2 / E * (L * ratio**2 + M * ratio + P * (1.0 + Q * np.tan(alpha) ** 2))
        return bend + shear + comp + found


def contact_half_width_mm(w_N_per_mm, k_rel_per_mm, Estar_MPa) -> np.ndarray:
    """Hertz line-contact half-width b_H = sqrt(4 w / (pi E* k)) [mm] (Johnson eq 4.45) for the load
    per unit length ``w`` [N/mm] >= 0 (0 gives 0), relative curvature across the line ``k`` [1/mm]."""
    w = np.asarray(w_N_per_mm, dtype=float)
    return np.sqrt(4.0 * np.maximum(w, 0.0) / (np.pi * Estar_MPa * np.asarray(k_rel_per_mm, dtype=float)))


def line_contact_pressure_MPa(w_N_per_mm, k_rel_per_mm, Estar_MPa) -> np.ndarray:
    """Maximum Hertz line-contact pressure sqrt(w E* k / pi) [MPa] (Johnson eq 4.45; the formula of
    :func:`gearrep.ellipse.hertz_line_max_pressure_MPa`, here accepting zero loads, which give 0)."""
    w = np.asarray(w_N_per_mm, dtype=float)
    return np.sqrt(np.maximum(w, 0.0) * Estar_MPa * np.asarray(k_rel_per_mm, dtype=float) / np.pi)


def weber_contact_approach_mm(w_N_per_mm, k_rel_per_mm, h1_mm, h2_mm, material1: Material, material2: Material):
    """Weber's approach [mm] of two tooth flanks in line contact under the load ``w`` [N/mm] per unit
    length (module docstring); ``h1_mm``, ``h2_mm`` the distances of the contact point from the
    tooth centre lines along the load line. 0 where w = 0."""
    w = np.maximum(np.asarray(w_N_per_mm, dtype=float), 0.0)
    Es = float(effective_modulus(material1.E_MPa, material1.poisson, material2.E_MPa, material2.poisson))
    b = contact_half_width_mm(w, k_rel_per_mm, Es)
    out = np.zeros(np.broadcast_shapes(w.shape, np.shape(h1_mm), np.shape(h2_mm)))
    with np.errstate(divide="ignore", invalid="ignore"):
        for h, m in ((h1_mm, material1), (h2_mm, material2)):
            nu = m.poisson
            term = (1.0 - nu**2) / m.E_MPa * (np.log(2.0 * np.asarray(h) / b) - nu / (2.0 * (1.0 - nu)))
            out = out + np.where(w > 0, 2.0 * w / np.pi * term, 0.0)
    return out
