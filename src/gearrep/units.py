"""Unit conversions at the edges of the library.

Inside gearrep every angle is in radians. Lengths carry the unit of the design data they came
from (mm for seeds 000, 003, 004; inch for seed 002); names and table columns say which.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "DEG",
    "ARCMIN",
    "ARCSEC",
    "MM_PER_IN",
    "deg2rad",
    "rad2deg",
    "arcsec2rad",
    "rad2arcsec",
    "arcmin2rad",
    "rad2arcmin",
    "in2mm",
    "mm2in",
    "TO_INTERNAL",
    "KNOWN_UNITS",
]

DEG = np.pi / 180.0  #: one degree in radians
ARCMIN = DEG / 60.0  #: one arc-minute in radians
ARCSEC = DEG / 3600.0  #: one arc-second in radians
MM_PER_IN = 25.4  #: millimetres in one inch (exact)


def deg2rad(x):
    """Degrees to radians."""
    return np.asarray(x, dtype=float) * DEG


def rad2deg(x):
    """Radians to degrees."""
    return np.asarray(x, dtype=float) / DEG


def arcsec2rad(x):
    """Arc-seconds to radians."""
    return np.asarray(x, dtype=float) * ARCSEC


def rad2arcsec(x):
    """Radians to arc-seconds."""
    return np.asarray(x, dtype=float) / ARCSEC


def arcmin2rad(x):
    """Arc-minutes to radians."""
    return np.asarray(x, dtype=float) * ARCMIN


def rad2arcmin(x):
    """Radians to arc-minutes."""
    return np.asarray(x, dtype=float) / ARCMIN


def in2mm(x):
    """Inches to millimetres."""
    return np.asarray(x, dtype=float) * MM_PER_IN


def mm2in(x):
    """Millimetres to inches."""
    return np.asarray(x, dtype=float) / MM_PER_IN


#: factor from a value in `unit` to the library's internal unit of the same dimension
#: (angles -> rad; lengths keep their unit; 1/length keep theirs). Used by `published`.
TO_INTERNAL = {
    "deg": DEG,
    "rad": 1.0,
    "arcmin": ARCMIN,
    "arcsec": ARCSEC,
    "mm": 1.0,
    "in": 1.0,
    "per_mm": 1.0,
    "per_in": 1.0,
    "mm2": 1.0,
    "in2": 1.0,
    "s": 1.0,
    "pct": 1.0,
    "count": 1.0,
    "1": 1.0,
}

KNOWN_UNITS = frozenset(TO_INTERNAL)
