"""Equations printed in the report, kept as evidence and named as printed (seed 002).

Each is checked against the library route (surfaces, curvature, TCA) by a study and a claim:
eq 2.4.1 against the curvature of the transverse section (:func:`..studies.transverse_section`),
eq 2.7.1 against the sign change of the gear's profile curvature (:func:`..studies.concavity`),
eq 2.8.6-2.8.7 against TCA with a centre-distance change (:func:`..studies.sensitivity`),
eq 5.4.3, 5.4.12 and 5.4.7 against TCA of the worm-ground pinion (:func:`..te_studies.worm`).
Angles in radians unless the name says ``_deg``; lengths in inches."""

from __future__ import annotations

import numpy as np

__all__ = [
    "a_c_star_eq_2_4_1",
    "rho_t_bound_eq_2_7_1",
    "delta_alpha_eq_2_8_7_deg",
    "delta_1_eq_2_8_6",
    "delta_E_eq_2_8_7",
    "a_phi_eq_5_4_3",
    "a_phi_eq_5_4_12",
    "delta_l_eq_5_4_7",
    "a_d_eq_5_4_13",
]


def a_c_star_eq_2_4_1(a_c, alpha_n, beta):
    """Eq 2.4.1: parabola coefficient of the rack profile in the transverse section,
    a_c* = a_c cos^3(alpha_t) / (cos^3(alpha_n) cos(beta)), tan(alpha_t) = tan(alpha_n)/cos(beta)."""
    alpha_t = np.arctan(np.tan(alpha_n) / np.cos(beta))
    return a_c * np.cos(alpha_t) ** 3 / (np.cos(alpha_n) ** 3 * np.cos(beta))


def rho_t_bound_eq_2_7_1(N2, alpha_n, P_n, beta, l):
    """Eq 2.7.1: gear rack radius below which the gear profile at Q stays concave,
    N2 sin(alpha_n) / (2 P_n cos^3(beta)) + l."""
    return N2 * np.sin(alpha_n) / (2 * P_n * np.cos(beta) ** 3) + l


def delta_alpha_eq_2_8_7_deg(alpha_n, delta_E, rho_1, rho_2, sign=-1):
    """Eq 2.8.7: sin(alpha_n') = sin(alpha_n) + sign dE / (rho_2 - rho_1) (the report's
    b2 - b1 - dE over rho2 - rho1 with b2 - b1 = (rho2 - rho1) sin(alpha_n)); returns
    |alpha_n' - alpha_n| in degrees, NaN where |sin(alpha_n')| > 1 (no contact)."""
    s = np.sin(alpha_n) + sign * delta_E / (rho_2 - rho_1)
    return np.degrees(abs(np.arcsin(s) - alpha_n)) if abs(s) <= 1 else np.nan


def delta_E_eq_2_8_7(alpha_n, delta_alpha_deg, rho_1, rho_2, sign=-1):
    """Eq 2.8.7 solved for the centre-distance change: the dE (same length unit as the radii) for
    which the pressure angle moves by ``delta_alpha_deg`` (decreasing for ``sign`` = -1, increasing
    for +1): |sin(alpha_n + sign d alpha) - sin(alpha_n)| (rho_2 - rho_1); the inverse of
    :func:`delta_alpha_eq_2_8_7_deg`. NaN if alpha_n + sign d alpha leaves (-90, 90) deg."""
    a2 = alpha_n + sign * np.radians(delta_alpha_deg)
    if not abs(a2) < np.pi / 2:
        return np.nan
    return abs(np.sin(a2) - np.sin(alpha_n)) * (rho_2 - rho_1)


def delta_1_eq_2_8_6(rho_1, delta_alpha_deg, h):
    """Eq 2.8.6: delta_1 = rho_1 |d alpha| / h, the contact shift along the profile over the
    active height."""
    return rho_1 * np.radians(delta_alpha_deg) / h


def a_phi_eq_5_4_3(a_c, a_t, a_pl, r_pw, alpha_n, beta, P_n, N1, N2, l_t):
    """Eq 5.4.3: coefficient a_phi (1/rad) of the parabolic TE function of the plunged pinion, with
    a_pr = a_c - a_t, m_t = 1 - 2 a_t l_t, m_w = 1 - 2 a_pl r_pw."""
    a_pr = a_c - a_t
    m_t = 1 - 2 * a_t * l_t
    m_w = 1 - 2 * a_pl * r_pw
    return (
        a_pl
        * a_pr
        * np.tan(alpha_n)
        * np.sin(alpha_n)
        / (a_pl * m_t**2 * np.cos(beta) ** 2 + a_pr * m_w * np.sin(alpha_n) * np.tan(beta) ** 2)
        * N1**2
        / (2 * P_n * N2)
    )


def a_phi_eq_5_4_12(a_pl, alpha_n, beta, P_n, N1, N2):
    """Eq 5.4.12: the report's approximation of a_phi, N1^2 tan(alpha_n) a_pl / (2 P_n N2 sin^2 beta)."""
    return N1**2 * np.tan(alpha_n) / (2 * P_n * N2 * np.sin(beta) ** 2) * a_pl


def delta_l_eq_5_4_7(d_lambda, a_pl, r_pw, alpha_n, beta):
    """Eq 5.4.7: axial shift of the bearing contact caused by a lead-angle error d_lambda,
    d_lambda (1 - 2 a_pl r_pw) / (2 a_pl tan(alpha_n) cos(beta))."""
    m_w = 1 - 2 * a_pl * r_pw
    return d_lambda * m_w / (2 * a_pl * np.tan(alpha_n) * np.cos(beta))


def a_d_eq_5_4_13(a_pl, alpha_t, N1):
    """Eq 5.4.13: plunging coefficient of the grinding disk equivalent to the worm's a_pl,
    a_d ~ a_pl sin(alpha_t) / sin(alpha_t + pi/N1)."""
    return a_pl * np.sin(alpha_t) / np.sin(alpha_t + np.pi / N1)
