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
    """Degrees to radians.

    Parameters
    ----------
    x : float or array_like
        The angle [deg].

    Returns
    -------
    numpy.ndarray
        The angle [rad], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import deg2rad
    >>> deg2rad([90.0, 180.0]).round(6)
    array([1.570796, 3.141593])
    """
    return np.asarray(x, dtype=float) * DEG


def rad2deg(x):
    """Radians to degrees.

    Parameters
    ----------
    x : float or array_like
        The angle [rad].

    Returns
    -------
    numpy.ndarray
        The angle [deg], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.units import rad2deg
    >>> float(rad2deg(np.pi / 4).round(9))
    45.0
    """
    return np.asarray(x, dtype=float) / DEG


def arcsec2rad(x):
    """Arc-seconds to radians.

    Parameters
    ----------
    x : float or array_like
        The angle [arcsec].

    Returns
    -------
    numpy.ndarray
        The angle [rad], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import arcsec2rad, DEG
    >>> round(float(arcsec2rad(3600.0) / DEG), 12)
    1.0
    """
    return np.asarray(x, dtype=float) * ARCSEC


def rad2arcsec(x):
    """Radians to arc-seconds.

    Parameters
    ----------
    x : float or array_like
        The angle [rad].

    Returns
    -------
    numpy.ndarray
        The angle [arcsec], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import rad2arcsec
    >>> float(rad2arcsec(1e-5).round(4))  # a transmission error of 10 micro-rad
    2.0626
    """
    return np.asarray(x, dtype=float) / ARCSEC


def arcmin2rad(x):
    """Arc-minutes to radians.

    Parameters
    ----------
    x : float or array_like
        The angle [arcmin].

    Returns
    -------
    numpy.ndarray
        The angle [rad], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import arcmin2rad, DEG
    >>> round(float(arcmin2rad(60.0) / DEG), 12)
    1.0
    """
    return np.asarray(x, dtype=float) * ARCMIN


def rad2arcmin(x):
    """Radians to arc-minutes.

    Parameters
    ----------
    x : float or array_like
        The angle [rad].

    Returns
    -------
    numpy.ndarray
        The angle [arcmin], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import rad2arcmin, DEG
    >>> float(rad2arcmin(DEG).round(9))
    60.0
    """
    return np.asarray(x, dtype=float) / ARCMIN


def in2mm(x):
    """Inches to millimetres.

    Parameters
    ----------
    x : float or array_like
        The length [in].

    Returns
    -------
    numpy.ndarray
        The length [mm], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import in2mm
    >>> float(in2mm(2.0))  # exact: 25.4 mm per inch
    50.8
    """
    return np.asarray(x, dtype=float) * MM_PER_IN


def mm2in(x):
    """Millimetres to inches.

    Parameters
    ----------
    x : float or array_like
        The length [mm].

    Returns
    -------
    numpy.ndarray
        The length [in], float, of the shape of ``x`` (a 0-d array for a scalar).

    Examples
    --------
    >>> from gearrep.units import mm2in
    >>> float(mm2in(50.8).round(12))
    2.0
    """
    return np.asarray(x, dtype=float) / MM_PER_IN


#: factor from a value in ``unit`` to the library's internal unit of the same dimension
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

#: the unit names of the published data's ``unit`` column (the keys of :data:`TO_INTERNAL`)
KNOWN_UNITS = frozenset(TO_INTERNAL)
