"""Flank modifications of the involute family: lengthwise crowning (thesis eq 10-12) and profile
relief (eq 13), each the material removed, ``(delta, d delta, d2 delta)`` as a function of one flank
parameter. They are public names of :mod:`gearrep.surfaces.involute` (the bevel flanks take them
too); this module is their home."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..inputs import check_finite as _check_finite

__all__ = ["ParabolicCrowning", "CircularCrowning", "LogarithmicCrowning", "TipRelief", "RootRelief"]


@dataclass(frozen=True)
class ParabolicCrowning:
    """Longitudinal parabolic crowning, thesis eq (10): delta = c1 w^2 + c2 w + c3, w = v - v0.

    Called with the axial coordinate ``v`` [length] it returns the removal and its first two
    derivatives, ``(delta, d delta/dv, d2 delta/dv2)``.

    Parameters
    ----------
    c1 : float
        The crowning coefficient (thesis a_1, a_p, c_1) [1/length].
    c2 : float, optional
        A lead slope [1].
    c3 : float, optional
        A uniform thinning [length].
    v0 : float, optional
        Axial position of the crown's top [length] (0: mid-face).

    Raises
    ------
    ValueError
        If a coefficient is not finite.

    Examples
    --------
    >>> from gearrep.surfaces.involute import ParabolicCrowning
    >>> crown = ParabolicCrowning(2e-3)  # 1/mm
    >>> [round(float(x), 9) for x in crown(5.0)]  # 5 mm from mid-face: mm, 1, 1/mm
    [0.05, 0.02, 0.004]
    """

    c1: float
    c2: float = 0.0
    c3: float = 0.0
    v0: float = 0.0

    def __post_init__(self):
        for n in ("c1", "c2", "c3", "v0"):
            _check_finite(n, getattr(self, n))

    def __call__(self, v):
        if type(v) is float:  # one point: the same operations on Python floats
            w = v - float(self.v0)
            c1, c2 = float(self.c1), float(self.c2)
            return c1 * w * w + c2 * w + float(self.c3), 2.0 * c1 * w + c2, 2.0 * c1
        w = np.asarray(v, dtype=float) - self.v0
        return self.c1 * w * w + self.c2 * w + self.c3, 2.0 * self.c1 * w + self.c2, np.full_like(w, 2.0 * self.c1)


@dataclass(frozen=True)
class CircularCrowning:
    """Longitudinal circular-arc crowning, thesis eq (11): delta = R - sqrt(R^2 - w^2), w = v - v0,
    with R = (4 c_c^2 + b^2) / (8 c_c) so that delta = c_c at the face edges w = +-b/2.

    Called with ``v`` [length] it returns ``(delta, d delta/dv, d2 delta/dv2)``.

    Parameters
    ----------
    crown : float
        c_c, the removal at the face edges [length], in (0, face_width/2) so the arc spans the face.
    face_width : float
        b [length], > 0.
    v0 : float, optional
        Axial position of the crown's top [length].

    Raises
    ------
    ValueError
        If a value is not finite or out of its range.

    Examples
    --------
    >>> from gearrep.surfaces.involute import CircularCrowning
    >>> crown = CircularCrowning(0.01, 20.0)  # mm
    >>> round(crown.radius, 6), round(float(crown(10.0)[0]), 12)  # R [mm]; delta at the edge [mm]
    (5000.005, 0.01)
    """

    crown: float
    face_width: float
    v0: float = 0.0

    def __post_init__(self):
        _check_finite("crown", self.crown, positive=True)
        _check_finite("face_width", self.face_width, positive=True)
        _check_finite("v0", self.v0)
        if not self.crown < 0.5 * self.face_width:
            raise ValueError(f"crown must be in (0, face_width/2) = (0, {0.5 * self.face_width}), got {self.crown!r}")

    @property
    def radius(self) -> float:
        """Arc radius R of eq (11) [length]."""
        return (4.0 * self.crown**2 + self.face_width**2) / (8.0 * self.crown)

    def __call__(self, v):
        w = np.asarray(v, dtype=float) - self.v0
        R = self.radius
        with np.errstate(invalid="ignore", divide="ignore"):
            q = np.sqrt(R * R - w * w)
            return R - q, w / q, R * R / q**3


@dataclass(frozen=True)
class LogarithmicCrowning:
    """Longitudinal logarithmic crowning, thesis eq (12): delta = a1 ln(1 / (1 - a2 (w/h)^2)),
    w = v - v0, h = ``half_width`` (the thesis's v_o = b/2, see correction 5).

    Called with ``v`` [length] it returns ``(delta, d delta/dv, d2 delta/dv2)``.

    Parameters
    ----------
    a1 : float
        Scale of the drop [length], >= 0.
    a2 : float
        In [0, 1): keeps the logarithm finite over the face (delta(+-h) = a1 ln(1/(1 - a2))).
    half_width : float
        h [length], > 0.
    v0 : float, optional
        Axial position of the crown's top [length].

    Raises
    ------
    ValueError
        If a value is not finite or out of its range.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.involute import LogarithmicCrowning
    >>> crown = LogarithmicCrowning(0.01, 0.5, 10.0)  # mm, 1, mm
    >>> round(float(crown(10.0)[0]), 12) == round(0.01 * math.log(2.0), 12)  # at the face edge
    True
    """

    a1: float
    a2: float
    half_width: float
    v0: float = 0.0

    def __post_init__(self):
        _check_finite("a1", self.a1, nonneg=True)
        _check_finite("half_width", self.half_width, positive=True)
        _check_finite("v0", self.v0)
        a2 = _check_finite("a2", self.a2)
        if not 0.0 <= a2 < 1.0:
            raise ValueError(f"a2 must be in [0, 1), got {self.a2!r}")

    def __call__(self, v):
        s = (np.asarray(v, dtype=float) - self.v0) / self.half_width
        h = self.half_width
        with np.errstate(invalid="ignore", divide="ignore"):
            q = 1.0 - self.a2 * s * s
            d = -self.a1 * np.log(q)
            d1 = 2.0 * self.a1 * self.a2 * s / (h * q)
            d2 = 2.0 * self.a1 * self.a2 * (1.0 + self.a2 * s * s) / (h * h * q * q)
        return d, d1, d2


def _check_relief_curvature(length, amount) -> None:
    """Refuse a relief length whose square underflows or whose curvature 2 c_m / L^2 overflows:
    the relief's derivatives would divide by zero or be infinite."""
    sq = float(length) ** 2
    if not (sq >= np.finfo(float).tiny and np.isfinite(float(amount) / sq)):
        raise ValueError(
            f"length: got {length!r}; allowed: a length L with L**2 a normal float and amount / L**2 finite "
            f"(amount {amount!r})"
        )


@dataclass(frozen=True)
class _ParabolicRelief:
    """A parabolic profile relief, thesis eq (13): c_m (w/L)^2 over the distance w = u - u0 past
    its start toward the tip (``_toward_tip``) or w = u0 - u toward the root; zero before it."""

    u0: float
    length: float
    amount: float
    _toward_tip: ClassVar[bool]

    def __post_init__(self):
        _check_finite("u0", self.u0, positive=True)
        _check_finite("length", self.length, positive=True)
        _check_finite("amount", self.amount, nonneg=True)
        _check_relief_curvature(self.length, self.amount)

    def __call__(self, u):
        if type(u) is float:  # one point: the same operations on Python floats
            w = u - float(self.u0) if self._toward_tip else float(self.u0) - u
            k = float(self.amount) / float(self.length) ** 2
            dw = 2 * k * w if self._toward_tip else -2 * k * w
            return (k * w * w, dw, 2 * k) if w > 0 else (0.0, 0.0, 0.0)
        u = np.asarray(u, dtype=float)
        w = u - self.u0 if self._toward_tip else self.u0 - u
        on = w > 0
        k = self.amount / self.length**2
        dw = 2 * k * w if self._toward_tip else -2 * k * w
        return np.where(on, k * w * w, 0.0), np.where(on, dw, 0.0), np.where(on, 2 * k, 0.0)


@dataclass(frozen=True)
class TipRelief(_ParabolicRelief):
    """Tip relief, thesis eq (13): delta = H(u - u0) c_m ((u - u0)/L)^2 (u = radius).

    C1 at u0; the second derivative (curvature) jumps there. Called with the radius ``u``
    [length] it returns ``(delta, d delta/du, d2 delta/du2)``.

    Parameters
    ----------
    u0 : float
        Start radius of the relief [length], > 0.
    length : float
        L [length], > 0.
    amount : float
        c_m, the relief at u0 + L [length], >= 0.

    Raises
    ------
    ValueError
        If a value is not finite or out of its range.

    Examples
    --------
    >>> from gearrep.surfaces.involute import TipRelief
    >>> relief = TipRelief(u0=30.0, length=2.0, amount=0.01)  # mm
    >>> [round(float(relief(u)[0]), 12) for u in (29.0, 31.0, 32.0)]  # mm
    [0.0, 0.0025, 0.01]
    """

    _toward_tip = True


@dataclass(frozen=True)
class RootRelief(_ParabolicRelief):
    """Root relief, eq (13) mirrored: delta = H(u0 - u) c_m ((u0 - u)/L)^2 (u = radius).

    Called with the radius ``u`` [length] it returns ``(delta, d delta/du, d2 delta/du2)``.

    Parameters
    ----------
    u0 : float
        Radius where the relief starts, going down the flank [length], > 0.
    length : float
        L [length], > 0.
    amount : float
        c_m, the relief at u0 - L [length], >= 0.

    Raises
    ------
    ValueError
        If a value is not finite or out of its range.

    Examples
    --------
    >>> from gearrep.surfaces.involute import RootRelief
    >>> relief = RootRelief(u0=26.0, length=2.0, amount=0.01)  # mm
    >>> [round(float(relief(u)[0]), 12) for u in (24.0, 25.0, 27.0)]  # mm
    [0.01, 0.0025, 0.0]
    """

    _toward_tip = False
