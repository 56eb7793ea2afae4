"""The dissertation's printed TCA equations (seed 000 ch. 5), named as printed.

The coordinate transformations of eq 5.1-5.4 read as active rotations (the printed M_fh has an
OCR-garbled last row, [0 0 1 1]), every rotation from :mod:`gearrep.frames`; the library's
:class:`gearrep.tca.HobbedPair` places the members by the same rotations (tested against these).
Eq 5.12 (kinematic error) and eq 5.13 (contact ratio, with the angular pitch 2 pi / T_p instead
of the printed 360 deg: erratum in data/errata.csv) are kept here as printed; the tests compare
them with the library route.
"""

from __future__ import annotations

import numpy as np

from ...frames import drot_z, rot_x, rot_y, rot_z

__all__ = ["M_vp", "dM_vp", "M_hv", "M_fh", "M_fg", "dM_fg", "kinematic_error", "contact_ratio"]


def M_vp(phi1):
    """Rotation part of M_vp (eq 5.1): the pinion turned by phi1' [rad], Rz(-phi1'); batched."""
    return rot_z(-np.asarray(phi1, float))


def dM_vp(phi1):
    """d M_vp / d phi1' (batched)."""
    return -drot_z(-np.asarray(phi1, float))


def M_hv(dgamma_v: float):
    """Rotation of M_hv (eq 5.1): vertical misalignment dgamma_v [rad] about Y, Ry(dgamma_v)."""
    return rot_y(dgamma_v)


def M_fh(dgamma_h: float):
    """Rotation of M_fh (eq 5.1): horizontal misalignment dgamma_h [rad] about X, Rx(-dgamma_h)."""
    return rot_x(-dgamma_h)


def M_fg(phi2):
    """Rotation part of M_fg (eq 5.3): the gear turned by phi2' [rad], Rz(phi2'); its
    translation is (C' = C + dC, 0, dZ). Batched."""
    return rot_z(np.asarray(phi2, float))


def dM_fg(phi2):
    """d M_fg / d phi2' (batched)."""
    return drot_z(np.asarray(phi2, float))


def kinematic_error(phi1, phi2, T_p: int, T_g: int):
    """Eq 5.12: KE = phi2'(phi1') - (T_p / T_g) phi1' [rad] (unnormalised)."""
    return np.asarray(phi2, float) - (T_p / T_g) * np.asarray(phi1, float)


def contact_ratio(phi1_B_deg: float, phi1_E_deg: float, T_p: int) -> float:
    """Eq 5.13 with the angular pitch (erratum): m_c = |phi1_E - phi1_B| / (360 deg / T_p)."""
    return abs(phi1_B_deg - phi1_E_deg) / (360.0 / T_p)
