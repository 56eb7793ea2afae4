"""Input checks: a bad argument is refused before any work, with a ValueError of one line naming
the argument, the value given and what is allowed.

The library's public functions check their numeric knobs and design values here. A string, a bool
or None is not a number here: a numeric string would be stored as a string and fail far from where
it was given, and ``True`` would pass as 1.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["real_or_nan", "check_finite", "check_positive", "check_integer"]


def real_or_nan(value) -> float:
    """``value`` as a float if it is a real number (not a string, bool or None), else NaN: the first
    step of a range check (``not 0 < real_or_nan(tol) <= 1e-3`` refuses a string or a bool too).

    Parameters
    ----------
    value : object
        Anything a caller passed as a number.

    Returns
    -------
    float
        ``float(value)``, or NaN for a string, bytes, a bool, None or what ``float`` refuses.

    Examples
    --------
    >>> from gearrep.inputs import real_or_nan
    >>> real_or_nan(2), real_or_nan("2"), real_or_nan(True)
    (2.0, nan, nan)
    """
    if isinstance(value, (str, bytes, bool)) or value is None:
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def check_finite(name: str, value, *, positive: bool = False, nonneg: bool = False) -> float:
    """``value`` as a float when it is a finite real number (and > 0 with ``positive``, >= 0 with
    ``nonneg``); ValueError naming ``name`` and the value otherwise.

    Parameters
    ----------
    name : str
        The argument's name, as the error message gives it.
    value : object
        The value to check (any unit: the check is on the number).
    positive : bool, optional
        Require ``value > 0``.
    nonneg : bool, optional
        Require ``value >= 0``.

    Returns
    -------
    float
        ``value`` as a float.

    Raises
    ------
    ValueError
        If ``value`` is not a finite real number, or breaks ``positive`` / ``nonneg``.

    Examples
    --------
    >>> from gearrep.inputs import check_finite
    >>> check_finite("d_E", -0.01)
    -0.01
    >>> check_finite("face_width", 0.0, positive=True)
    Traceback (most recent call last):
        ...
    ValueError: face_width must be > 0, got 0.0
    """
    x = real_or_nan(value)
    if not math.isfinite(x):
        number = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)
        what = "finite" if number else "a finite number"
        raise ValueError(f"{name} must be {what}, got {value!r}")
    if positive and not x > 0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    if nonneg and not x >= 0:
        raise ValueError(f"{name} must be >= 0, got {value!r}")
    return x


def check_positive(name: str, value) -> float:
    """``value`` as a float when it is a finite number > 0; ValueError naming ``name`` otherwise
    (``tol=inf`` would call every start converged).

    Parameters
    ----------
    name : str
        The argument's name, as the error message gives it.
    value : object
        The value to check.

    Returns
    -------
    float
        ``value`` as a float.

    Raises
    ------
    ValueError
        If ``value`` is not a finite real number > 0.

    Examples
    --------
    >>> from gearrep.inputs import check_positive
    >>> check_positive("tol", 1e-10)
    1e-10
    >>> check_positive("tol", float("inf"))
    Traceback (most recent call last):
        ...
    ValueError: tol must be a finite number > 0, got inf
    """
    x = real_or_nan(value)
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return x


def check_integer(name: str, value, minimum: int = 1) -> int:
    """``value`` as an int when it is an integer >= ``minimum`` (a Python or numpy integer, not a
    bool); ValueError naming ``name`` otherwise (``maxiter=2.5`` is an error, not 2 iterations).

    Parameters
    ----------
    name : str
        The argument's name, as the error message gives it.
    value : object
        The value to check.
    minimum : int, optional
        The smallest value allowed (default 1).

    Returns
    -------
    int
        ``value`` as a Python int.

    Raises
    ------
    ValueError
        If ``value`` is not a Python or numpy integer, is a bool, or is below ``minimum``.

    Examples
    --------
    >>> from gearrep.inputs import check_integer
    >>> check_integer("maxiter", 50)
    50
    >>> check_integer("maxiter", 2.5)
    Traceback (most recent call last):
        ...
    ValueError: maxiter must be an integer >= 1, got 2.5
    """
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)
