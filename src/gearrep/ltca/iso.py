"""ISO 6336 closed forms used to validate the loaded contact analysis.

Sources
-------
* ISO 6336-2:2019, "Calculation of load capacity of spur and helical gears - Part 2: Calculation of
  surface durability (pitting)": nominal contact stress at the pitch point
  sigma_H0 = Z_H Z_E Z_eps Z_beta sqrt(F_t / (d_1 b) (u + 1) / u); zone factor
  Z_H = sqrt(2 cos(beta_b) cos(alpha_wt) / (cos^2(alpha_t) sin(alpha_wt)));
  elasticity factor Z_E = sqrt(1 / (pi ((1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2))) (189.8 sqrt(MPa)
  for steel on steel).
  With Z_eps = Z_beta = 1 (one tooth pair carrying the whole load of a spur pair) this is the Hertz
  line-contact pressure at the pitch point with the load spread evenly over the face width.
* ISO 6336-1:2019, "Part 1: Basic principles, introduction and general influence factors", tooth
  stiffness parameters c' and c_gamma (method B): the theoretical single stiffness
  c'_th = 1 / q' of solid disc gears with the standard basic rack, with
  q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 + C8 x1^2 + C9 x2^2
  [mm um / N] (coefficients below), and the mesh stiffness (mean of the total stiffness in
  the transverse plane) c_gamma_alpha = c' (0.75 eps_alpha + 0.25); c' = c'_th C_M C_R C_B cos(beta)
  with C_M = 0.8 (measured over theoretical values of solid disc gears), C_R = 1 (solid disc gears)
  and the basic rack factor C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg - alpha_Pn)] (0.975
  for the dedendum 1.25 m_n of ISO 53's basic rack). The q' formula is an empirical
  fit to theoretical stiffness computations, not a model: a computed stiffness is compared with it
  within a band, never equated to it.

Units: N, mm, MPa (= N/mm^2); stiffness per unit face width in N / (mm um).
"""

from __future__ import annotations

import numpy as np

from ..ellipse import effective_modulus
from ..inputs import check_finite, check_positive

__all__ = [
    "Q_PRIME_COEFFICIENTS",
    "zone_factor",
    "elasticity_factor",
    "pitch_point_stress_MPa",
    "q_prime",
    "single_stiffness_theoretical",
    "mesh_stiffness_c_gamma_alpha",
    "basic_rack_factor",
    "C_M",
]

#: ISO 6336-1 correction factor C_M: measured over theoretical single stiffness of solid disc gears
C_M = 0.8

#: ISO 6336-1: C1 ... C9 of the q' formula [mm um / N]
Q_PRIME_COEFFICIENTS = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


def zone_factor(alpha_t: float, alpha_wt: float | None = None, beta_b: float = 0.0) -> float:
    """ISO 6336-2 zone factor Z_H = sqrt(2 cos(beta_b) cos(alpha_wt) / (cos^2(alpha_t) sin(alpha_wt)))
    (angles in rad; ``alpha_wt`` defaults to ``alpha_t``, the standard centre distance).

    Parameters
    ----------
    alpha_t : float
        Transverse pressure angle [rad], > 0.
    alpha_wt : float, optional
        Working transverse pressure angle [rad], > 0.
    beta_b : float, optional
        Base helix angle [rad], >= 0.

    Returns
    -------
    float
        Z_H [1].

    Raises
    ------
    ValueError
        If an angle is out of range.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca.iso import zone_factor
    >>> round(zone_factor(math.radians(20.0)), 4)  # a spur pair at the standard centre distance
    2.4946
    """
    at = check_positive("alpha_t", alpha_t)
    awt = at if alpha_wt is None else check_positive("alpha_wt", alpha_wt)
    bb = check_finite("beta_b", beta_b, nonneg=True)
    return float(np.sqrt(2.0 * np.cos(bb) * np.cos(awt) / (np.cos(at) ** 2 * np.sin(awt))))


def elasticity_factor(E1_MPa: float, nu1: float, E2_MPa: float | None = None, nu2: float | None = None) -> float:
    """ISO 6336-2 elasticity factor Z_E = sqrt(E* / pi) [sqrt(MPa)], 1/E* = sum (1 - nu_i^2)/E_i
    (:func:`gearrep.ellipse.effective_modulus`); 189.8 sqrt(MPa) for steel (206000 MPa, 0.3).

    Parameters
    ----------
    E1_MPa : float
        Young's modulus of member 1 [MPa].
    nu1 : float
        Its Poisson ratio [1].
    E2_MPa, nu2 : float, optional
        Those of member 2 (default member 1's).

    Returns
    -------
    float
        Z_E [sqrt(MPa)].

    Examples
    --------
    >>> from gearrep.ltca.iso import elasticity_factor
    >>> round(elasticity_factor(206000.0, 0.3), 1)  # steel on steel [sqrt(MPa)]
    189.8
    """
    return float(np.sqrt(effective_modulus(E1_MPa, nu1, E2_MPa, nu2) / np.pi))


def pitch_point_stress_MPa(F_t_N: float, d1_mm: float, b_mm: float, u: float, Z_H: float, Z_E: float) -> float:
    """ISO 6336-2 nominal contact stress at the pitch point with one tooth pair carrying the load
    (Z_eps = Z_beta = 1): Z_H Z_E sqrt(F_t / (d_1 b) (u + 1) / u) [MPa]; ``F_t`` the nominal
    tangential load at the reference circle [N], ``u`` = z_2 / z_1.

    Parameters
    ----------
    F_t_N : float
        Nominal tangential load at the reference circle [N], > 0.
    d1_mm : float
        Reference diameter of the pinion [mm], > 0.
    b_mm : float
        Face width [mm], > 0.
    u : float
        Gear ratio z_2 / z_1 [1], > 0.
    Z_H : float
        Zone factor [1] (:func:`zone_factor`), > 0.
    Z_E : float
        Elasticity factor [sqrt(MPa)] (:func:`elasticity_factor`), > 0.

    Returns
    -------
    float
        sigma_H0 [MPa].

    Raises
    ------
    ValueError
        If a value is not > 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca.iso import elasticity_factor, pitch_point_stress_MPa, zone_factor
    >>> Z_H, Z_E = zone_factor(math.radians(20.0)), elasticity_factor(206000.0, 0.3)
    >>> round(pitch_point_stress_MPa(3000.0, 69.0, 25.0, 41 / 23, Z_H, Z_E), 1)  # N, mm, mm -> MPa
    780.2
    """
    for name, x in (("F_t_N", F_t_N), ("d1_mm", d1_mm), ("b_mm", b_mm), ("u", u), ("Z_H", Z_H), ("Z_E", Z_E)):
        check_positive(name, x)
    return float(Z_H * Z_E * np.sqrt(F_t_N / (d1_mm * b_mm) * (u + 1.0) / u))


def q_prime(z_n1: float, z_n2: float, x1: float = 0.0, x2: float = 0.0) -> float:
    """ISO 6336-1 minimum tooth flexibility q' [mm um / N] of a tooth pair (:data:`Q_PRIME_COEFFICIENTS`);
    ``z_n`` the virtual tooth numbers (z / cos^3(beta) for helical gears), ``x`` profile shifts.

    Parameters
    ----------
    z_n1, z_n2 : float
        Virtual tooth numbers [1], > 0.
    x1, x2 : float, optional
        Profile shift coefficients [1].

    Returns
    -------
    float
        q' [mm um / N].

    Raises
    ------
    ValueError
        If a tooth number is not > 0 or a shift is not finite.

    Examples
    --------
    >>> from gearrep.ltca.iso import q_prime
    >>> round(q_prime(23, 41), 6)  # mm um / N
    0.060282
    """
    z1, z2 = check_positive("z_n1", z_n1), check_positive("z_n2", z_n2)
    x1, x2 = check_finite("x1", x1), check_finite("x2", x2)
    c = Q_PRIME_COEFFICIENTS
    return float(
        c[0]
        + c[1] / z1
        + c[2] / z2
        + c[3] * x1
        + c[4] * x1 / z1
        + c[5] * x2
        + c[6] * x2 / z2
        + c[7] * x1**2
        + c[8] * x2**2
    )


def single_stiffness_theoretical(z_n1: float, z_n2: float, x1: float = 0.0, x2: float = 0.0) -> float:
    """ISO 6336-1 theoretical single stiffness c'_th = 1 / q' [N / (mm um)] (solid disc gears,
    standard basic rack, per unit face width, in the normal plane).

    Parameters
    ----------
    z_n1, z_n2 : float
        Virtual tooth numbers [1].
    x1, x2 : float, optional
        Profile shift coefficients [1].

    Returns
    -------
    float
        c'_th [N / (mm um)].

    Examples
    --------
    >>> from gearrep.ltca.iso import single_stiffness_theoretical
    >>> round(single_stiffness_theoretical(23, 41), 3)  # N / (mm um)
    16.589
    """
    return 1.0 / q_prime(z_n1, z_n2, x1, x2)


def mesh_stiffness_c_gamma_alpha(c_single: float, eps_alpha: float) -> float:
    """ISO 6336-1 mesh stiffness c_gamma_alpha = c' (0.75 eps_alpha + 0.25) [N / (mm um)]: the mean
    over the meshing cycle of the total stiffness of the tooth pairs in contact (eps_alpha >= 1.2 per
    ISO; transverse contact ratio).

    Parameters
    ----------
    c_single : float
        Single stiffness c' [N / (mm um)], > 0.
    eps_alpha : float
        Transverse contact ratio [1], > 0.

    Returns
    -------
    float
        c_gamma_alpha [N / (mm um)].

    Raises
    ------
    ValueError
        If a value is not > 0.

    Examples
    --------
    >>> from gearrep.ltca.iso import mesh_stiffness_c_gamma_alpha
    >>> round(mesh_stiffness_c_gamma_alpha(14.0, 1.6), 6)  # N / (mm um)
    20.3
    """
    return float(check_positive("c_single", c_single) * (0.75 * check_positive("eps_alpha", eps_alpha) + 0.25))


def basic_rack_factor(h_fP_over_mn: float, alpha_Pn_deg: float = 20.0) -> float:
    """ISO 6336-1 basic rack factor C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 - alpha_Pn)] of
    one member's basic rack (dedendum ``h_fP_over_mn`` in normal modules, pressure angle
    ``alpha_Pn_deg`` in degrees): the theoretical stiffness of a pair cut with another rack than the
    one of the q' fit is c'_th C_B (ISO: C_B of a pair is the mean of its members').

    Parameters
    ----------
    h_fP_over_mn : float
        Dedendum of the basic rack in normal modules (> 0; 1.25 for ISO 53's standard rack).
    alpha_Pn_deg : float, optional
        Normal pressure angle of the basic rack [deg] (> 0).

    Returns
    -------
    float
        C_B (dimensionless).

    Raises
    ------
    ValueError
        For a non-finite or non-positive argument.

    Examples
    --------
    >>> from gearrep.ltca.iso import basic_rack_factor
    >>> round(basic_rack_factor(1.25), 6)  # the standard rack's dedendum 1.25 m_n, 20 deg
    0.975
    """
    h = check_positive("h_fP_over_mn", h_fP_over_mn)
    a = check_positive("alpha_Pn_deg", alpha_Pn_deg)
    return float((1.0 + 0.5 * (1.2 - h)) * (1.0 - 0.02 * (20.0 - a)))
