"""The thesis's own conventions and printed formulas, kept as evidence (each tested against the
library route in tests/replication/test_temirkhan2023.py).

Frames. The library pair (:class:`gearrep.tca.GearPair`) puts member 2 on +x_f and measures phi2
in the driven sense; its involute flanks are centred on x_i with v = 0 at mid-face. The thesis
puts gear 2 on +y, measures both angles about +z and starts both involutes at polar angle 0
(eq 3-4, v from the face edge). Its pitch-point example is reproduced to all printed digits by

    phi1_thesis = phi1 + pi/2 - off1,      phi2_thesis = pi/2 + phase2 - phi2 - off2   (mod 2 pi),
    off_i = c_i - twist_i(-b/2)            (c_i: polar-angle offset of the flank; twist_i: helix),
    v_thesis = v + b/2.

Crowning: eq (10) parabolic c1, eq (11) circular c_c, eq (12) logarithmic a1 (with an unprinted
a2); Table 9's profile crowning as Litvin's parabolic rack-cutter (first-order mapping).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...solve import newton
from ...surfaces.involute import (
    CircularCrowning,
    InvoluteGearData,
    LogarithmicCrowning,
    ParabolicCrowning,
    RootRelief,
    TipRelief,
)


def wrap(x):
    """Angle(s) reduced to [-pi, pi]."""
    return x - 2 * np.pi * np.round(x / (2 * np.pi))


@dataclass(frozen=True)
class ThesisFrame:
    """Angle and face-coordinate maps between a library pair and the thesis's frame (module doc)."""

    off1: float
    off2: float
    phase2: float
    half_width: float

    @classmethod
    def of(cls, pair) -> ThesisFrame:
        f1, f2 = pair.flank1, pair.flank2
        hw = 0.5 * f1.gear.face_width
        off1 = f1.c - float(f1.twist(np.array(-hw))[0])
        off2 = f2.c - float(f2.twist(np.array(-hw))[0])
        return cls(off1=off1, off2=off2, phase2=pair.phase2, half_width=hw)

    def phi1_from_thesis(self, phi1_t):
        return np.asarray(phi1_t, float) - np.pi / 2 + self.off1

    def phi1_to_thesis(self, phi1):
        return np.asarray(phi1, float) + np.pi / 2 - self.off1

    def phi2_to_thesis(self, phi2):
        x = np.pi / 2 + self.phase2 - np.asarray(phi2, float) - self.off2
        return x - 2 * np.pi * np.round(x / (2 * np.pi))

    def phi2_from_thesis(self, phi2_t):
        return np.pi / 2 + self.phase2 - np.asarray(phi2_t, float) - self.off2

    def v_to_thesis(self, v):
        return np.asarray(v, float) + self.half_width

    def window_from_thesis(self, lo_t, hi_t):
        """A phi2 window (low, high) printed in the thesis frame, in library angles (ordered)."""
        a, b = self.phi2_from_thesis(lo_t), self.phi2_from_thesis(hi_t)
        return (min(a, b), max(a, b))


def profile_crowning(gear: InvoluteGearData, a_c: float):
    """Parabolic profile crowning of coefficient ``a_c`` [1/length] (Litvin's parabolic rack-cutter,
    Table 9), as a relief pair centred on the pitch circle.

    The rack profile deviation a_c u_c^2 (u_c along the rack profile in the normal section) reaches
    the gear at radius ~ r_p + u_c cos(alpha_n) (first order), and the library's offset is
    transverse (3-D normal offset = delta cos(beta_b)), so delta(u) = a_c ((u - r_p)/cos alpha_n)^2 /
    cos(beta_b). First-order mapping, stated because the thesis does not define the parameter.
    """
    if a_c <= 0:
        return ()
    k = a_c / (np.cos(gear.pressure_angle) ** 2 * np.cos(gear.beta_b))
    return (TipRelief(gear.r_p, 1.0, k), RootRelief(gear.r_p, 1.0, k))


def crowning_object(kind: str, amount: float, face_width: float, log_a2: float):
    """Crowning of eq (10)-(12) centred at mid-face: parabolic c1 (eq 10), circular c_c (eq 11),
    logarithmic a1 with the unprinted a2 = ``log_a2`` and half width b/2 (eq 12)."""
    if kind == "parabolic":
        return ParabolicCrowning(amount)
    if kind == "circular":
        return CircularCrowning(amount, face_width)
    if kind == "logarithmic":
        return LogarithmicCrowning(amount, log_a2, 0.5 * face_width)
    raise ValueError(f"unknown crowning kind {kind!r}")


def crown_curvature(kind: str, amount: float, face_width: float, log_a2: float) -> float:
    """Central coefficient c of a crown, delta ~ c w^2 near mid-face (first-order estimate)."""
    if kind == "parabolic":
        return float(amount)
    if kind == "circular":
        return 0.5 / CircularCrowning(amount, face_width).radius
    if kind == "logarithmic":
        return float(amount) * log_a2 / (0.5 * face_width) ** 2
    raise ValueError(f"unknown crowning kind {kind!r}")


def printed_hertz(k_max1, k_min1, k_max2, k_min2, load_N, E1_MPa, nu1, E2_MPa, nu2, *, tol=1e-13, maxiter=50):
    """Thesis eq 19-24 as printed (evidence; the library route is :func:`gearrep.ellipse.hertz_contact_at`):
    2A = k_max1 + k_max2, 2B = k_min1 + k_min2 (eq 19; each surface's principal curvatures w.r.t.
    its own outward normal, magnitudes taken, A <= B), the eccentricity e from
    [E(e)/(1 - e^2) - K(e)] / [K(e) - E(e)] = B/A (eq 20) by Newton, with K, E the complete
    elliptic integrals of modulus e (eq 21 prints sqrt(1 - e^2 theta): sin^2 theta is meant),
    a = (3 P C_E (K - E) / (2 pi e^2 A))^(1/3), b = a sqrt(1 - e^2) (eq 22), C_E of eq 23 and
    p = 3 P / (2 pi a b) (eq 24). Eq 19 adds curvatures of equal index, i.e. assumes the principal
    directions of both surfaces coincide (true for aligned parallel-axis flanks, nearly so here).
    Returns dict(a_mm, b_mm, e, p_MPa, residual, iterations, status) of scalars."""
    from scipy.special import ellipe, ellipk

    A = 0.5 * abs(float(k_max1) + float(k_max2))
    B = 0.5 * abs(float(k_min1) + float(k_min2))
    A, B = min(A, B), max(A, B)
    if not A > 0:
        raise ValueError(f"printed_hertz: eq 19 gives A = {A!r}; a line contact has no ellipse (A must be > 0)")
    ratio = B / A

    def eq20(m):  # m = e^2
        K, E = ellipk(m), ellipe(m)
        return (E / (1 - m) - K) / (K - E)

    # unknown t = ln(1 - e^2) <= 0, so every iterate keeps 0 < e < 1
    def fun(x, rows):
        m = -np.expm1(x[:, 0])
        return (np.log(eq20(m)) - np.log(ratio))[:, None]

    x0 = np.array([[-(4.0 / 3.0) * np.log(ratio) if ratio > 1 else -1e-3]])  # b/a ~ (A/B)^(2/3)
    sr = newton(fun, x0, tol=tol, maxiter=maxiter, upper=[-1e-300], rows=True)
    m = float(-np.expm1(sr.x[0, 0]))
    K, E = ellipk(m), ellipe(m)
    C_E = (1 - nu1**2) / E1_MPa + (1 - nu2**2) / E2_MPa  # eq 23
    a = (3 * load_N * C_E * (K - E) / (2 * np.pi * m * A)) ** (1 / 3)  # eq 22
    b = a * np.sqrt(1 - m)
    return dict(
        a_mm=a,
        b_mm=b,
        e=float(np.sqrt(m)),
        p_MPa=3 * load_N / (2 * np.pi * a * b),  # eq 24
        residual=float(sr.residual[0]),
        iterations=int(sr.iterations[0]),
        status=int(sr.status[0]),
    )
