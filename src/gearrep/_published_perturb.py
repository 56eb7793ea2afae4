"""The portability check's nudge of the published design data (``docs/validation.md``): every
length, angle and curvature moved by a few units in the last place. Public names of
:mod:`gearrep.published`, whose :func:`~gearrep.published.load` applies it; this module is their home.
"""

from __future__ import annotations

import hashlib
import math
import os

import pandas as pd

__all__ = ["PERTURB_ENV", "PERTURBED_UNITS", "perturbed_value", "perturbed_params", "perturb_ulps_from_env"]

#: environment variable of the portability check (``docs/validation.md``): a whole number k >= 1
#: moves every design length and angle read by :func:`load` by 1 to k units in the last place
#: (:func:`perturbed_params`); unset, empty or 0 reads the data as printed
PERTURB_ENV = "GEARREP_PERTURB_ULPS"
#: the units of the parameters it moves: lengths, angles and curvatures (not counts or ratios,
#: whose printed values are exact)
PERTURBED_UNITS = frozenset({"mm", "in", "deg", "rad", "arcmin", "per_mm", "per_in"})


def perturbed_value(value: float, ulps: int) -> float:
    """``value`` moved by 1 to ``ulps`` units in the last place, up or down, the count and direction
    drawn from a hash of the value itself (the same in every process; equal values move alike).
    Zero, NaN and infinities are returned as they are; ``ulps`` = 0 returns ``value``.

    Parameters
    ----------
    value : float
        The value [any unit].
    ulps : int
        The largest move, in units in the last place, >= 0.

    Returns
    -------
    float
        The moved value.

    Raises
    ------
    ValueError
        If ``ulps`` is not a whole number >= 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.published import perturbed_value
    >>> (3.0 - perturbed_value(3.0, 2)) / math.ulp(2.9)  # 3 mm moved down by 2 ulps
    2.0
    >>> perturbed_value(0.0, 2), perturbed_value(3.0, 0)
    (0.0, 3.0)
    """
    if isinstance(ulps, bool) or not isinstance(ulps, int) or ulps < 0:
        raise ValueError(f"ulps must be a whole number >= 0, got {ulps!r}")
    value = float(value)
    if ulps == 0 or value == 0.0 or not math.isfinite(value):
        return value
    h = int.from_bytes(hashlib.blake2b(repr(value).encode(), digest_size=4).digest(), "little")
    step, toward = 1 + h % ulps, math.inf if (h >> 16) & 1 else -math.inf
    for _ in range(step):
        value = math.nextafter(value, toward)
    return value


def perturbed_params(params: pd.DataFrame, ulps: int) -> pd.DataFrame:
    """``params`` with every value in :data:`PERTURBED_UNITS` moved by 1 to ``ulps`` units in the
    last place, up or down.

    A result that such a nudge of its inputs moves beyond its stated tolerance is ill-conditioned
    or tested too tightly; the portability check runs the number-comparing tests on these inputs.
    The count and direction come from a hash of the printed value, so they are the same in every
    process, and equal values stay equal (a design's stated equalities, such as equal cutter radii
    or a symmetric pair, are part of the design); zero stays zero (an exact statement, such as an
    aligned assembly).

    Parameters
    ----------
    params : pandas.DataFrame
        A typed params frame (:func:`validate_params`).
    ulps : int
        The largest move, in units in the last place, >= 0.

    Returns
    -------
    pandas.DataFrame
        A copy with the values moved.

    Raises
    ------
    ValueError
        If ``ulps`` is not a whole number >= 0.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import perturbed_params
    >>> params = pd.DataFrame({"parameter": ["module", "teeth"], "value": [3.0, 20.0], "unit": ["mm", "1"]})
    >>> moved = perturbed_params(params, 4)["value"].tolist()
    >>> moved[0] != 3.0, moved[1]  # a length moves, a tooth count does not
    (True, 20.0)
    """
    if isinstance(ulps, bool) or not isinstance(ulps, int) or ulps < 0:
        raise ValueError(f"ulps must be a whole number >= 0, got {ulps!r}")
    out = params.copy()
    if ulps == 0:
        return out
    values = out["value"].to_numpy(dtype=float).copy()
    for i, unit in enumerate(out["unit"].tolist()):
        if unit in PERTURBED_UNITS:
            values[i] = perturbed_value(values[i], ulps)
    out["value"] = values
    return out


def perturb_ulps_from_env() -> int:
    """The ulps of :data:`PERTURB_ENV` (0 when unset or empty); anything but a whole number is refused.

    Returns
    -------
    int
        k >= 0.

    Raises
    ------
    ValueError
        If the variable holds anything but a whole number.

    Examples
    --------
    >>> import os
    >>> from gearrep.published import PERTURB_ENV, perturb_ulps_from_env
    >>> saved = os.environ.pop(PERTURB_ENV, None)
    >>> perturb_ulps_from_env()
    0
    >>> os.environ[PERTURB_ENV] = "4"
    >>> perturb_ulps_from_env()
    4
    >>> if saved is None:
    ...     del os.environ[PERTURB_ENV]
    ... else:
    ...     os.environ[PERTURB_ENV] = saved
    """
    text = os.environ.get(PERTURB_ENV, "").strip()
    if not text:
        return 0
    if not text.isdigit():
        raise ValueError(f"environment variable {PERTURB_ENV}={text!r}: must be a whole number >= 0 (0 or unset: off)")
    return int(text)
