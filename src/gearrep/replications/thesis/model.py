"""The thesis's own conventions and printed formulas, kept as evidence (each tested against the
library route in tests/replication/test_thesis.py).

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
