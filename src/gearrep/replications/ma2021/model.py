"""Seed 004's own printed equations of the relative curvature, kept as evidence.

The computation uses the library routes (:mod:`gearrep.curvature`, :mod:`gearrep.ellipse`);
the functions here are the equations as the paper prints them, each tested against the library
route (``tests/unit/replications/test_ma2021_model.py``).
"""

from __future__ import annotations

import numpy as np

__all__ = ["litvin_AB_eq23_26", "eq20_like_indexed"]


def litvin_AB_eq23_26(k1I, k2I, k1II, k2II, sigma):
    """Seed 004 eq (23)-(26) as printed (= Litvin & Fuentes sec. 9.2): A, B and alpha^I from the
    principal curvatures of surfaces I and II (w.r.t. one common normal) and the angle sigma
    between e1^I and e1^II:

        kS = (k1I + k2I) - (k1II + k2II),  g_i = k1_i - k2_i,
        root = sqrt(gI^2 - 2 gI gII cos 2 sigma + gII^2),
        A = (kS - root) / 4,  B = (kS + root) / 4,  cos 2 alpha^I = (gI - gII cos 2 sigma) / root.

    A is a difference of two nearly equal numbers when the smaller relative curvature is small
    (on a CATT pair kS and root agree to 1e-3 .. 1e-4), so A loses that many digits; the library
    route :func:`gearrep.ellipse.litvin_coefficients` (eigenvalues of the relative curvature
    tensor) avoids the cancellation. alpha^I is returned in [0, pi/2] (only cos 2 alpha is
    printed)."""
    kS = (k1I + k2I) - (k1II + k2II)
    gI, gII = k1I - k2I, k1II - k2II
    root = np.sqrt(np.maximum(gI * gI - 2 * gI * gII * np.cos(2 * sigma) + gII * gII, 0.0))
    A = 0.25 * (kS - root)
    B = 0.25 * (kS + root)
    with np.errstate(invalid="ignore", divide="ignore"):
        cos2a = np.where(root > 0, (gI - gII * np.cos(2 * sigma)) / np.where(root > 0, root, 1.0), 1.0)
    return A, B, 0.5 * np.arccos(np.clip(cos2a, -1, 1))


def eq20_like_indexed(k1I, k2I, k1II, k2II):
    """Seed 004 eq (20) as printed: relative curvatures k1^I - k1^II and k2^I - k2^II, pairing the
    algebraically ordered principal curvatures (eq 16) by index. Right only if the first principal
    directions coincide (sigma = 0); the claim ``004-S3-eq20_like_curvature_pairing`` compares it
    with the eigenvalues of the relative curvature tensor."""
    return k1I - k1II, k2I - k2II
