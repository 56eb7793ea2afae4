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
    step of a range check (``not 0 < real_or_nan(tol) <= 1e-3`` refuses a string or a bool too)."""
    if isinstance(value, (str, bytes, bool)) or value is None:
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def check_finite(name: str, value, *, positive: bool = False, nonneg: bool = False) -> float:
    """``value`` as a float when it is a finite real number (and > 0 with ``positive``, >= 0 with
    ``nonneg``); ValueError naming ``name`` and the value otherwise."""
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
    (``tol=inf`` would call every start converged)."""
    x = real_or_nan(value)
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return x


def check_integer(name: str, value, minimum: int = 1) -> int:
    """``value`` as an int when it is an integer >= ``minimum`` (a Python or numpy integer, not a
    bool); ValueError naming ``name`` otherwise (``maxiter=2.5`` is an error, not 2 iterations)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {value!r}")
    return int(value)
