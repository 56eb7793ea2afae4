"""Materials, tooth compliance (Weber-Banaschek beam and Sainsot fillet foundation), the Hertz
line-contact approach and pressure, and the kernels that couple the nodes along the face (the
Boussinesq half-space relative to depth, the cantilever plate).

Sources
-------
* C. Weber, K. Banaschek, "Formänderung und Profilrücknahme bei gerad- und schrägverzahnten
  Rädern", Schriftenreihe Antriebstechnik 11, Vieweg, 1953: the tooth as a cantilever of variable
  thickness loaded along the profile normal, deflection along the load line from the strain energy
  of bending, shear and compression; the contact approach of two cylinders (Weber 1949).
* P. Sainsot, P. Velex, O. Duverger, "Contribution of gear body to tooth deflections - a new
  bidimensional analytical formula", J. Mech. Design 126 (2004) 748-752: the fillet-foundation
  deflection (the fit of its Table 1, coefficients below).
* K. L. Johnson, "Contact Mechanics", CUP 1985, sect. 3.2, 4.3 and 5.2: Boussinesq's point load,
  line contact half-width and maximum pressure (also :func:`gearrep.ellipse.hertz_line_max_pressure_MPa`).
* T. J. Jaramillo, "Deflections and moments due to a concentrated load on a cantilever plate of
  infinite length", J. Appl. Mech. 17 (1950) 67-72; L. E. Wellauer, A. Seireg, "Bending strength of
  gear teeth by cantilever-plate theory", J. Eng. Ind. 82 (1960) 213-222: the cantilever plate of
  :func:`cantilever_plate_ratio`.

Model (per unit length of contact line, plane strain; load F along the profile normal)
-----------------------------------------------------------------------------------------
The tooth section is read from the flank surface itself (:mod:`gearrep.ltca._families`): the half
tooth angle theta(u) at radius u about the section's centre line (an involute flank's polar angle at
mid-face, its centre line turned by the helix along the face; a CATT tooth's half thickness between
its convex and concave flanks in each section), continued radially below the lowest point of the
working profile down to the root circle (the root fillet is not modelled). The centre line is the x
axis of the section; y = u cos(theta) runs along it and x(y) = u sin(theta) is the half
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
iteration on the secant compliance (:mod:`gearrep.ltca._analysis`). With the nodes coupled
(:mod:`gearrep.ltca._nodes`) it is the plane limit of :func:`half_space_segment_mm2_per_N`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..ellipse import effective_modulus
from ..inputs import check_finite
from ._families import Member, member_of

__all__ = [
    "Material",
    "STEEL",
    "SAINSOT_COEFFICIENTS",
    "ToothCompliance",
    "contact_half_width_mm",
    "line_contact_pressure_MPa",
    "weber_contact_approach_mm",
    "half_space_segment_mm2_per_N",
    "HERTZ_STRIP_OFFSET",
    "cantilever_plate_ratio",
    "plate_kernel",
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
    reference for Z_E = 189.8 sqrt(MPa)).

    Parameters
    ----------
    E_MPa : float, optional
        Young's modulus [MPa], > 0.
    poisson : float, optional
        Poisson ratio [1], in (-1, 0.5].

    Raises
    ------
    ValueError
        If a value is out of range.

    Examples
    --------
    >>> from gearrep.ltca import STEEL, Material
    >>> Material() == STEEL, STEEL.E_MPa, STEEL.poisson  # MPa, 1
    (True, 206000.0, 0.3)
    >>> Material(200000.0, 0.6)
    Traceback (most recent call last):
        ...
    ValueError: poisson must be in (-1, 0.5], got 0.6
    """

    E_MPa: float = 206000.0
    poisson: float = 0.3

    def __post_init__(self):
        check_finite("E_MPa", self.E_MPa, positive=True)
        nu = check_finite("poisson", self.poisson)
        if not -1.0 < nu <= 0.5:
            raise ValueError(f"poisson must be in (-1, 0.5], got {self.poisson!r}")


#: structural steel, 206 000 MPa and 0.3 (the default material)
STEEL = Material()


class ToothCompliance:
    """Weber-Banaschek tooth compliance of one member (bending, shear, compression and the Sainsot
    fillet foundation), per unit length of contact line, from the member's own tooth section.

    Parameters
    ----------
    member : gearrep.surface.Surface
        A flank of a supported family (:data:`gearrep.ltca.SUPPORTED`) or its
        :class:`gearrep.ltca._families.Member`.
    material : Material, optional
        The member's material.
    bore_radius_mm : float, optional
        Radius of the gear body's bore [mm], default half the root radius (h_f = 2); must be below
        the root radius.
    n_gauss : int, optional
        Gauss-Legendre nodes of the beam integrals.

    Raises
    ------
    ValueError
        If the flank's family is not supported, ``material`` is not a :class:`Material` or the bore
        is not inside the root circle.

    Notes
    -----
    The section is read from the flank (:mod:`gearrep.ltca._families`): the tooth half angle theta
    at each radius, about the section's centre line, continued radially below the lowest point of
    the working profile down to the root circle (the root fillet is not modelled). Where the
    section changes along the face (CATT) the compliance is computed with the two tabulated
    sections around the contact's axial position and interpolated linearly between them.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.ltca import ToothCompliance
    >>> from gearrep.surfaces.involute import InvoluteGearData, mating_flanks
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> tooth = ToothCompliance(mating_flanks(g1, g2)[0])  # the pinion's, steel
    >>> c_low, c_high = tooth.compliance([33.0, 36.0], 0.0)  # radius [mm], axial position [mm] -> mm^2/N
    >>> bool(0 < c_low < c_high)  # a load nearer the tip bends the tooth more
    True
    >>> bool(np.isclose(sum(tooth.terms(36.0).values()), c_high, rtol=1e-12))  # the four terms
    True
    """

    def __init__(self, member, material: Material = STEEL, bore_radius_mm=None, *, n_gauss: int = 64):
        m = member if isinstance(member, Member) else member_of(member, "flank")
        if not isinstance(material, Material):
            raise ValueError(f"material must be a gearrep.ltca.Material, got {type(material).__name__}")
        self.member, self.material = m, material
        r_f = m.r_root
        bore = 0.5 * r_f if bore_radius_mm is None else check_finite("bore_radius_mm", bore_radius_mm, positive=True)
        if not bore < r_f:
            raise ValueError(f"bore_radius_mm must be < the root radius {r_f!r} mm, got {bore_radius_mm!r}")
        self.r_f, self.bore_radius_mm = r_f, float(bore)
        r = m.r_table
        self._y = r * np.cos(m.half_angle)  # (n_sections, n_r): along the centre line
        self._x = r * np.sin(m.half_angle)  # half thickness
        self.theta_f = m.half_angle[:, 0]  # (n_sections,)
        self._gauss = np.polynomial.legendre.leggauss(int(n_gauss))
        h_f = r_f / self.bore_radius_mm
        t = self.theta_f
        basis = np.stack([1 / t**2, np.full_like(t, h_f**2), h_f / t, 1 / t, np.full_like(t, h_f), np.ones_like(t)])
        self._LMPQ = SAINSOT_COEFFICIENTS @ basis  # (4, n_sections)

    def load_geometry(self, u, v=0.0):
        """(alpha_F [rad], y_F [mm], h [mm], theta_c [rad]) at flank parameters (u, v) (for an
        involute flank u = radius, v = axial position): load angle, where the load line meets the
        centre line, the distance from the contact point to the centre line along the load line, and
        the contact point's angle from the centre line.

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters [mm for an involute flank].

        Returns
        -------
        alpha_F, y_F, h, theta_c : numpy.ndarray
            [rad], [mm], [mm], [rad].
        """
        m = self.member
        u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        P = m.base.evaluate(u, v)
        p, n = P.r, P.normal
        _, psi_c = m.section_at(p[..., 2])
        c, s = np.cos(psi_c), np.sin(psi_c)
        px, py = c * p[..., 0] + s * p[..., 1], np.abs(-s * p[..., 0] + c * p[..., 1])
        nx, ny = np.abs(c * n[..., 0] + s * n[..., 1]), np.abs(-s * n[..., 0] + c * n[..., 1])
        cos_a = ny / np.hypot(nx, ny)
        return np.arccos(np.clip(cos_a, -1.0, 1.0)), px - py * nx / ny, py / cos_a, np.arctan2(py, px)

    def cantilever_length(self, u, v=0.0) -> np.ndarray:
        """Length [mm] of the tooth as a cantilever at flank parameters (u, v): from the root chord to
        where the load line meets the centre line (y_F - y_root), the length of the plate whose
        bending spreads a load along the face (:func:`plate_kernel`).

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters [mm for an involute flank].

        Returns
        -------
        numpy.ndarray
            H [mm].
        """
        y_F = self.load_geometry(u, v)[1]
        m = self.member
        y0 = self._y[:, 0]
        if m.z_independent:
            return np.maximum(y_F - y0[0], 1e-3 * self.r_f)
        z = m.base.evaluate(*np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))).r[..., 2]
        return np.maximum(y_F - np.interp(z, m.sections, y0), 1e-3 * self.r_f)

    def _beam(self, k, alpha, y_F):
        """Compliance [mm^2/N] of section k for load angles alpha and load heights y_F."""
        return sum(self._beam_terms(k, alpha, y_F).values())

    def _beam_terms(self, k, alpha, y_F) -> dict:
        """The four terms of :meth:`_beam` (bending, shear, compression, foundation)."""
        E, nu = self.material.E_MPa, self.material.poisson
        y_tab, x_tab = self._y[k], self._x[k]
        y0 = y_tab[0]
        top = np.maximum(y_F, y0)
        s, wq = self._gauss
        half = 0.5 * (top - y0)
        y = y0 + half[..., None] * (s + 1.0)  # (..., n_gauss)
        two_x = 2.0 * np.interp(y, y_tab, x_tab)
        i_bend = half * np.sum(wq * (top[..., None] - y) ** 2 / two_x**3, axis=-1)
        i_area = half * np.sum(wq / two_x, axis=-1)
        c2, s2 = np.cos(alpha) ** 2, np.sin(alpha) ** 2
        bend = 12.0 * (1.0 - nu**2) * c2 * i_bend / E
        shear = 2.0 * SHEAR_FACTOR * (1.0 + nu) * c2 * i_area / E
        comp = (1.0 - nu**2) * s2 * i_area / E
        L, M, P, Q = self._LMPQ[:, k]
        ratio = (y_F - self.r_f) / (2.0 * self.r_f * np.sin(self.theta_f[k]))
        found = c2 / E * (L * ratio**2 + M * ratio + P * (1.0 + Q * np.tan(alpha) ** 2))
        return {"bending": bend, "shear": shear, "compression": comp, "foundation": found}

    def terms(self, u, v=0.0) -> dict:
        """The terms of :meth:`compliance` [mm^2/N] (bending, shear, compression, foundation) at
        flank parameters (u, v) of a section that does not change along the face (involute).

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters [mm].

        Returns
        -------
        dict
            ``{"bending", "shear", "compression", "foundation"}`` [mm^2/N].

        Raises
        ------
        ValueError
            If the section changes along the face (a CATT tooth).
        """
        if not self.member.z_independent:
            raise ValueError("terms() needs a tooth section that is the same along the face (an involute flank)")
        alpha, y_F, _, _ = self.load_geometry(u, v)
        return self._beam_terms(0, alpha, y_F)

    def compliance(self, u, v=0.0) -> np.ndarray:
        """Tooth compliance [mm^2 / N] (deflection along the load line per unit load per unit length
        of contact line) at flank parameters (u, v); the sum of the four terms of the module
        docstring.

        Parameters
        ----------
        u, v : float or array_like
            Flank parameters [mm for an involute flank].

        Returns
        -------
        numpy.ndarray
            [mm^2/N].
        """
        alpha, y_F, _, _ = self.load_geometry(u, v)
        m = self.member
        if m.z_independent:
            return self._beam(0, alpha, y_F)
        u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        z = m.base.evaluate(u, v).r[..., 2]
        zs = m.sections
        j = np.clip(np.searchsorted(zs, z) - 1, 0, zs.size - 2)
        f = np.clip((z - zs[j]) / (zs[j + 1] - zs[j]), 0.0, 1.0)
        out = np.zeros(np.shape(z))
        for k in np.unique(np.concatenate([j.ravel(), j.ravel() + 1])):
            w = np.where(j == k, 1.0 - f, 0.0) + np.where(j + 1 == k, f, 0.0)
            sel = w > 0
            if np.any(sel):
                out[sel] += w[sel] * self._beam(int(k), alpha[sel], y_F[sel])
        return out


def contact_half_width_mm(w_N_per_mm, k_rel_per_mm, Estar_MPa) -> np.ndarray:
    """Hertz line-contact half-width b_H = sqrt(4 w / (pi E* k)) [mm] (Johnson eq 4.45) for the load
    per unit length ``w`` [N/mm] >= 0 (0 gives 0), relative curvature across the line ``k`` [1/mm].

    Parameters
    ----------
    w_N_per_mm : float or array_like
        Load per unit length [N/mm].
    k_rel_per_mm : float or array_like
        Relative curvature [1/mm], > 0.
    Estar_MPa : float
        Effective modulus E* [MPa] (:func:`gearrep.ellipse.effective_modulus`).

    Returns
    -------
    numpy.ndarray
        b_H [mm].

    Examples
    --------
    >>> from gearrep.ellipse import effective_modulus
    >>> from gearrep.ltca import contact_half_width_mm
    >>> Es = effective_modulus(206000.0, 0.3, 206000.0, 0.3)  # steel on steel [MPa]
    >>> round(float(contact_half_width_mm(100.0, 0.05, Es)), 6), float(contact_half_width_mm(0.0, 0.05, Es))  # mm
    (0.149993, 0.0)
    """
    w = np.asarray(w_N_per_mm, dtype=float)
    return np.sqrt(4.0 * np.maximum(w, 0.0) / (np.pi * Estar_MPa * np.asarray(k_rel_per_mm, dtype=float)))


def line_contact_pressure_MPa(w_N_per_mm, k_rel_per_mm, Estar_MPa) -> np.ndarray:
    """Maximum Hertz line-contact pressure sqrt(w E* k / pi) [MPa] (Johnson eq 4.45; the formula of
    :func:`gearrep.ellipse.hertz_line_max_pressure_MPa`, here accepting zero loads, which give 0).

    Parameters
    ----------
    w_N_per_mm : float or array_like
        Load per unit length [N/mm].
    k_rel_per_mm : float or array_like
        Relative curvature [1/mm].
    Estar_MPa : float
        Effective modulus E* [MPa].

    Returns
    -------
    numpy.ndarray
        p_max [MPa].

    Examples
    --------
    >>> from gearrep.ellipse import effective_modulus
    >>> from gearrep.ltca import line_contact_pressure_MPa
    >>> Es = effective_modulus(206000.0, 0.3, 206000.0, 0.3)  # MPa
    >>> round(float(line_contact_pressure_MPa(100.0, 0.05, Es)), 3)  # 100 N/mm, 1/mm -> MPa
    424.432
    """
    w = np.asarray(w_N_per_mm, dtype=float)
    return np.sqrt(np.maximum(w, 0.0) * Estar_MPa * np.asarray(k_rel_per_mm, dtype=float) / np.pi)


def weber_contact_approach_mm(w_N_per_mm, k_rel_per_mm, h1_mm, h2_mm, material1: Material, material2: Material):
    """Weber's approach [mm] of two tooth flanks in line contact under the load ``w`` [N/mm] per unit
    length (module docstring); ``h1_mm``, ``h2_mm`` the distances of the contact point from the
    tooth centre lines along the load line. 0 where w = 0.

    Parameters
    ----------
    w_N_per_mm : float or array_like
        Load per unit length [N/mm].
    k_rel_per_mm : float or array_like
        Relative curvature across the line [1/mm].
    h1_mm, h2_mm : float or array_like
        Distances of the contact point from the two tooth centre lines along the load line [mm].
    material1, material2 : Material
        The members' materials.

    Returns
    -------
    numpy.ndarray
        delta_H [mm].

    Examples
    --------
    >>> from gearrep.ltca import STEEL, weber_contact_approach_mm
    >>> round(float(weber_contact_approach_mm(100.0, 0.05, 5.0, 5.0, STEEL, STEEL)), 7)  # N/mm, 1/mm, mm -> mm
    0.0022416
    """
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


def half_space_segment_mm2_per_N(x1, x2, lateral_mm, depth_mm, material: Material) -> np.ndarray:
    """Normal displacement [mm] of a surface point of an elastic half-space relative to the point at
    depth ``depth_mm`` below it, per unit intensity [N/mm] of a line load on the segment
    x in [x1, x2] [mm] (x along the line, measured from the point) at ``lateral_mm`` > 0 from it.

    Boussinesq's point load P on the surface displaces a point at distance rho (depth z) by
    u_z = P (1 + nu) / (2 pi E) [2 (1 - nu) / rho + z^2 / rho^3] (Johnson, Contact Mechanics, eq 3.20);
    the segment integral of the difference between z = 0 and z = h is in closed form (asinh). Over
    an infinite line with the lateral offset y_e = (b/2) exp(-1/2) this is exactly Weber's
    line-contact approach for a Hertz strip of half-width b (:func:`weber_contact_approach_mm`, to
    O((b/h)^2)): the mean of ln|y| over the semi-elliptic pressure is ln(b/2) - 1/2.

    Parameters
    ----------
    x1, x2 : float or array_like
        Ends of the loaded segment along the line [mm].
    lateral_mm : float or array_like
        Lateral offset of the line from the point [mm], > 0.
    depth_mm : float or array_like
        Depth of the reference point [mm].
    material : Material
        The body's material.

    Returns
    -------
    numpy.ndarray
        [mm per N/mm].

    Examples
    --------
    Over a long line at the offset of a Hertz strip, both bodies together give Weber's approach:

    >>> from gearrep.ellipse import effective_modulus
    >>> from gearrep.ltca import STEEL, contact_half_width_mm, half_space_segment_mm2_per_N, weber_contact_approach_mm
    >>> b = float(contact_half_width_mm(100.0, 0.05, effective_modulus(206000.0, 0.3, 206000.0, 0.3)))  # mm
    >>> y_e = 0.5 * b * 2.718281828459045**-0.5  # the strip's equivalent offset [mm]
    >>> one = float(half_space_segment_mm2_per_N(-1e6, 1e6, y_e, 5.0, STEEL))  # mm per N/mm
    >>> round(2 * 100.0 * one / float(weber_contact_approach_mm(100.0, 0.05, 5.0, 5.0, STEEL, STEEL)), 4)
    1.0
    """
    a = np.asarray(lateral_mm, dtype=float)
    surf = _surface_coefficient(material) * (np.arcsinh(x2 / a) - np.arcsinh(x1 / a))
    return surf - _depth_term(x1, x2, a, np.asarray(depth_mm, dtype=float), material)


def _surface_coefficient(material: Material) -> float:
    return (1.0 - material.poisson**2) / (np.pi * material.E_MPa)


def _depth_term(x1, x2, a, h, material: Material):
    """The segment integral of Boussinesq's u_z at depth h (lateral offset a) per unit intensity."""
    nu = material.poisson
    c2 = a * a + h * h
    c = np.sqrt(c2)
    far = 2.0 * (1.0 - nu) * (np.arcsinh(x2 / c) - np.arcsinh(x1 / c))
    far = far + h * h / c2 * (x2 / np.sqrt(x2 * x2 + c2) - x1 / np.sqrt(x1 * x1 + c2))
    return (1.0 + nu) / (2.0 * np.pi * material.E_MPa) * far


#: lateral offset of a line load equivalent to a Hertz strip of half-width b, over b: (1/2) exp(-1/2)
HERTZ_STRIP_OFFSET = 0.5 * np.exp(-0.5)


# ----------------------------------------------------------------------------------------------
# coupling of the tooth compliance along the face: the cantilever plate
# ----------------------------------------------------------------------------------------------
def cantilever_plate_ratio(q, nu: float) -> np.ndarray:
    """Edge compliance of a cantilever plate under a line load varying as cos(k z) along the face,
    over its value for a uniform load (the beam, H^3 / (3 D)): R(q), q = k H, H the cantilever
    length from the clamped root to the loaded edge, nu the Poisson ratio.

    Kirchhoff plate (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, ch. 10) on
    0 <= y <= H: D (d^2/dy^2 - k^2)^2 w = 0, clamped at y = 0 (w = w_y = 0), free and loaded at
    y = H (M_y = -D (w_yy - nu k^2 w) = 0, V_y = -D (w_yyy - (2 - nu) k^2 w_y) = q). The general
    solution in the edge-decaying basis e^{-k (H - y)}, (H - y) e^{-k (H - y)}, e^{-k y}, y e^{-k y}
    (no overflow for large k; below q = 0.05, where it degenerates, the quadratic Taylor form) gives w(H); this is the Fourier form of Jaramillo's concentrated load
    on a cantilever plate of infinite length (J. Appl. Mech. 17 (1950) 67-72), applied to gear
    teeth by Wellauer & Seireg (J. Eng. Ind. 82 (1960) 213-222). R(0) = 1, R ~ 6 / ((1 - nu)(3 + nu) q^3)
    for large q.

    Parameters
    ----------
    q : float or array_like
        k H [1], >= 0.
    nu : float
        Poisson ratio [1].

    Returns
    -------
    numpy.ndarray
        R(q) [1].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.ltca import cantilever_plate_ratio
    >>> np.round(cantilever_plate_ratio([0.0, 1.0, 10.0], 0.3), 6).tolist()
    [1.0, 0.635465, 0.002597]
    """
    q = np.atleast_1d(np.asarray(q, dtype=float))
    out = np.ones_like(q)
    small = q < _Q_SMALL  # the basis degenerates as q -> 0: R is even in q, R = 1 + (R(q_s) - 1) (q/q_s)^2
    if np.any(small):
        out[small] = 1.0 + (cantilever_plate_ratio(np.array([_Q_SMALL]), nu)[0] - 1.0) * (q[small] / _Q_SMALL) ** 2
    k = q[~small]
    if k.size == 0:
        return out
    kk = k[:, None]

    def h(t, order, m):  # d^order/dt^order of t^m e^{-k t}
        e = np.exp(-kk * t)
        if m == 0:
            return (e, -kk * e, kk**2 * e, -(kk**3) * e)[order]
        return (t * e, (1 - kk * t) * e, (-2 * kk + kk**2 * t) * e, (3 * kk**2 - kk**3 * t) * e)[order]

    def phi(y, order):  # the four basis functions' y-derivatives at y, (n, 4)
        s, sg = 1.0 - y, (-1.0) ** order
        return np.concatenate([sg * h(s, order, 0), sg * h(s, order, 1), h(y, order, 0), h(y, order, 1)], axis=1)

    A = np.stack(
        [
            phi(0.0, 0),
            phi(0.0, 1),
            phi(1.0, 2) - nu * kk**2 * phi(1.0, 0),
            phi(1.0, 3) - (2.0 - nu) * kk**2 * phi(1.0, 1),
        ],
        axis=1,
    )
    rhs = np.zeros((k.size, 4, 1))
    rhs[:, 3, 0] = -1.0
    c = np.linalg.solve(A, rhs)[..., 0]
    out[~small] = 3.0 * np.sum(phi(1.0, 0) * c, axis=1)
    return out


#: below this q the edge-decaying basis is ill-conditioned (R is then its quadratic Taylor form, error O(q^4))
_Q_SMALL = 0.05


_PLATE_TABLES: dict = {}


def _plate_table(nu: float):
    """(u, P(u)) on 0 <= u <= 20: P from the point-load kernel g(u) = (1/pi) int_0^inf R(q) cos(q u) dq
    (the trapezoid rule in q with 2^15 steps up to q = 322, where R < 1e-7, summed by a real FFT on
    the grid u_j = 0.01 j) integrated in u (trapezoid); P(20) equals 1/2 to 1e-9."""
    n = 2**16
    du = 0.01
    dq = 2.0 * np.pi / (n * du)
    R = cantilever_plate_ratio(dq * np.arange(n // 2 + 1), nu)
    g = (dq / np.pi) * (n / 2.0) * np.fft.irfft(R, n)  # (dq/pi) (R_0/2 + sum_k R_k cos(q_k u_j))
    u = du * np.arange(2001)
    g = g[: u.size]
    P = np.concatenate([[0.0], np.cumsum(0.5 * (g[1:] + g[:-1]) * du)])
    return u, P


def plate_kernel(u, nu: float) -> np.ndarray:
    """P(u) = (1/pi) int_0^inf R(q) sin(q u) / q dq (R of :func:`cantilever_plate_ratio`): the edge
    deflection of the cantilever plate at z = 0 due to a uniform unit load on 0 < z < u H, over the
    beam value (odd in u, P(+-inf) = +-1/2). The deflection at a point due to a load on [x1, x2] is
    (P(x2/H) - P(x1/H)) times the slice compliance; over a uniformly loaded face it is the slice
    compliance itself. Tabulated once per nu (:func:`_plate_table`) and interpolated; 1/2 beyond
    |u| = 20, where the kernel's remainder is below 1e-6.

    Parameters
    ----------
    u : float or array_like
        Load extent over the cantilever length [1].
    nu : float
        Poisson ratio [1].

    Returns
    -------
    numpy.ndarray
        P(u) [1].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.ltca import plate_kernel
    >>> np.round(plate_kernel([-30.0, 0.0, 1.0, 30.0], 0.3), 4).tolist()
    [-0.5, 0.0, 0.362, 0.5]
    """
    key = round(float(nu), 12)
    if key not in _PLATE_TABLES:
        _PLATE_TABLES[key] = _plate_table(key)
    uu, vals = _PLATE_TABLES[key]
    u = np.asarray(u, dtype=float)
    a = np.abs(u)
    return np.sign(u) * np.where(a >= uu[-1], 0.5, np.interp(a, uu, vals))
