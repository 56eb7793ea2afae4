"""Gear pair on its axes (frames in :mod:`gearrep.tca`), transmission error and the contact record."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import ClassVar

import numpy as np

from ..frames import matrix_applier, rot_x, rot_y, rot_z
from ..inputs import check_finite, real_or_nan
from ..solve import Status, status_names
from ..units import ARCSEC

__all__ = ["Misalignment", "GearPair", "transmission_error", "ContactPoints"]


def _mv(M, v):
    return np.einsum("...ij,...j->...i", M, v)


def _wrap(x):
    """x - 2 pi round(x / 2 pi): exact when |x| < pi."""
    return x - 2.0 * np.pi * np.round(x / (2.0 * np.pi))


# ----------------------------------------------------------------------------------------------
# pair geometry
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Misalignment:
    """Assembly errors of member 2 (see module docstring for the frames).

    Parameters
    ----------
    d_gamma_in : float, optional
        Rotation [rad] about y_f, in the plane of the axes (axes intersect); ``|d_gamma_in| < 0.5``.
    d_gamma_out : float, optional
        Rotation [rad] about x_f, the centre line (axes cross); ``|d_gamma_out| < 0.5``.
    d_E : float, optional
        Centre-distance change [length of the design data].
    d_H : float, optional
        Offset along y_f [length].
    d_Z : float, optional
        Axial displacement along z_f [length].

    Raises
    ------
    ValueError
        If a value is not finite, or an angle is not small (``|angle| >= 0.5 rad``).

    Notes
    -----
    The angular errors pivot about O2 (member 2's axis at mid-face). A pivot at another point Q is
    the same rotation plus the translation (I - R)(Q - O2), i.e. extra d_E, d_H, d_Z. The choice
    matters for helical gears: turning member 2 about y_f through O2 by dg also shifts its pitch
    point axially by about r_p2 dg, which turns its helix by dg tan(beta) (a constant TE offset of
    ~45 arcsec for dg = 0.05 deg, beta = 14 deg) that a pivot at the pitch point would not produce.

    Examples
    --------
    >>> import math
    >>> from gearrep.tca import Misalignment
    >>> Misalignment(d_gamma_out=math.radians(0.05), d_E=0.01).d_E  # rad, mm
    0.01
    >>> Misalignment(d_gamma_in=1.0)
    Traceback (most recent call last):
        ...
    ValueError: d_gamma_in must be a small angle, |d_gamma_in| < 0.5 rad, got 1.0
    """

    d_gamma_in: float = 0.0
    d_gamma_out: float = 0.0
    d_E: float = 0.0
    d_H: float = 0.0
    d_Z: float = 0.0

    def __post_init__(self):
        for n in ("d_gamma_in", "d_gamma_out", "d_E", "d_H", "d_Z"):
            check_finite(n, getattr(self, n))
        for n in ("d_gamma_in", "d_gamma_out"):
            if abs(getattr(self, n)) >= 0.5:
                raise ValueError(f"{n} must be a small angle, |{n}| < 0.5 rad, got {getattr(self, n)!r}")


def _bounds(surface):
    lo = getattr(surface, "lower", None)
    hi = getattr(surface, "upper", None)
    lo = np.full(2, -np.inf) if lo is None else np.asarray(lo, float)
    hi = np.full(2, np.inf) if hi is None else np.asarray(hi, float)
    return lo, hi


class GearPair:
    """Two tooth surfaces mounted on their axes (frames in the module docstring).

    Parameters
    ----------
    flank1, flank2 : gearrep.surface.Surface
        The tooth surfaces; optional attributes ``lower``, ``upper`` (flank domain) and
        ``outward_sign``; the reduced formulation needs ``flank2.cylindrical`` (u = radius,
        v = axial coordinate).
    n1, n2 : int
        Numbers of teeth (ratio N1/N2 in the TE, angular pitches 2 pi / N); equal to the flanks'
        ``gear.n_teeth`` where they have one.
    centre_distance : float
        a > 0 [length of the design data] (shortest distance between the axes when aligned).
    misalignment : Misalignment, optional
        Assembly errors of member 2 (None: aligned).
    shaft_angle : float, optional
        Nominal angle between the axes about x_f [rad], 0 for parallel axes, in [-pi, pi].
    phase2 : float, optional
        Fixed turn of member 2 in its frame [rad]; default pi - side pi / n2 (see module docstring).

    Raises
    ------
    ValueError
        If a tooth number is not a positive integer or disagrees with its flank's, the centre
        distance is not > 0, an angle is out of range, ``misalignment`` is not a
        :class:`Misalignment`, or a flank is spherical (bevel flanks pair as :class:`BevelPair`).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> pair.ratio, round(float(pair.O2[0]), 6)  # N1/N2; member 2's axis at x_f = a + d_E [mm]
    (0.5609756097560976, 96.01)
    >>> r, n = pair.member1(35.0, 0.0, 0.0)  # u1 [mm], v1 [mm], phi1 [rad]
    >>> round(float(np.linalg.norm(r[:2])), 9), round(float(np.linalg.norm(n)), 12)
    (35.0, 1.0)
    >>> aligned = pair.with_misalignment(Misalignment())
    >>> float(aligned.O2[0])
    96.0
    """

    #: whether the axes intersect (the bevel pair); spherical flanks need it
    _INTERSECTING_AXES = False

    def __init__(
        self,
        flank1,
        flank2,
        n1: int,
        n2: int,
        centre_distance: float,
        *,
        misalignment=None,
        shaft_angle: float = 0.0,
        phase2=None,
    ):
        if not self._INTERSECTING_AXES and any(getattr(f, "spherical", False) for f in (flank1, flank2)):
            raise ValueError(
                "bevel (spherical) flanks mesh on intersecting axes, with the cone apex at the origin: pair them "
                "with gearrep.tca.BevelPair, not GearPair"
            )
        for name, n in (("n1", n1), ("n2", n2)):
            if not math.isfinite(real_or_nan(n)) or int(n) != n or n < 1:
                raise ValueError(f"{name} must be a positive integer, got {n!r}")
        for name, n, flank in (("n1", n1, flank1), ("n2", n2, flank2)):
            own = getattr(getattr(flank, "gear", None), "n_teeth", None)  # the flank's own tooth number
            if own is not None and int(own) != int(n):
                raise ValueError(
                    f"{name} = {n!r} disagrees with the tooth number of flank{name[1]} "
                    f"(flank{name[1]}.gear.n_teeth = {own!r}); allowed: {name} = {own!r}"
                )
        a = check_finite("centre_distance", centre_distance, positive=True)
        if abs(check_finite("shaft_angle", shaft_angle)) > np.pi:
            raise ValueError(f"shaft_angle must be in [-pi, pi] rad, got {shaft_angle!r}")
        if phase2 is not None:
            check_finite("phase2", phase2)
        mis = Misalignment() if misalignment is None else misalignment
        if not isinstance(mis, Misalignment):
            raise ValueError("misalignment must be a Misalignment or None")
        self.flank1, self.flank2 = flank1, flank2
        self.n1, self.n2 = int(n1), int(n2)
        self.ratio = self.n1 / self.n2
        self.centre_distance = a
        self.misalignment = mis
        self.shaft_angle = float(shaft_angle)
        if phase2 is None:
            side = getattr(flank1, "side", 1)
            phase2 = np.pi - side * np.pi / self.n2
        self.phase2 = float(phase2)
        self.A2 = rot_y(mis.d_gamma_in) @ rot_x(self.shaft_angle + mis.d_gamma_out)
        self.O2 = np.array([a + mis.d_E, mis.d_H, mis.d_Z])
        self.w2 = -self.A2[:, 2]  # axis of positive phi2
        self._Q = rot_z(-self.phase2) @ self.A2.T  # S_f (relative to O2) -> member-2 axis frame
        self.sign1 = int(getattr(flank1, "outward_sign", 1))
        self.sign2 = int(getattr(flank2, "outward_sign", 1))
        self.lower1, self.upper1 = _bounds(flank1)
        self.lower2, self.upper2 = _bounds(flank2)

    def with_misalignment(self, misalignment) -> GearPair:
        """Same pair with another misalignment.

        Parameters
        ----------
        misalignment : Misalignment
            The new assembly errors.

        Returns
        -------
        GearPair
            The same flanks, teeth, centre distance, shaft angle and phase.
        """
        return GearPair(
            self.flank1,
            self.flank2,
            self.n1,
            self.n2,
            self.centre_distance,
            misalignment=misalignment,
            shaft_angle=self.shaft_angle,
            phase2=self.phase2,
        )

    @cached_property
    def _soa(self) -> dict:
        """The fixed part of the pair's frames prepared once for the structure-of-arrays kernels of
        :mod:`gearrep.tca._kernels`: ``A2``, ``Q`` (v -> A2 v, Q v on component tuples),
        ``minus_O2`` (v -> v - O2), ``w2`` and ``O2`` (tuples of floats)."""
        return {
            "A2": matrix_applier(self.A2),
            "Q": matrix_applier(self._Q),
            "minus_O2": matrix_applier(np.eye(3), -self.O2),
            "w2": tuple(float(x) for x in self.w2),
            "O2": tuple(float(x) for x in self.O2),
        }

    def _free_bounds(self, free: tuple) -> tuple:
        """(lower, upper) bounds of the free unknowns ``free`` (indices into (u1, v1, u2, v2, phi2))
        of a contact solve, prepared once per pair and choice of free unknowns."""
        cache = self.__dict__.setdefault("_free_bounds_cache", {})
        if free not in cache:
            lo = np.concatenate([self.lower1, self.lower2, [-np.inf]])
            hi = np.concatenate([self.upper1, self.upper2, [np.inf]])
            cache[free] = (lo[list(free)], hi[list(free)])
        return cache[free]

    @cached_property
    def _mid_flanks(self) -> tuple:
        """(u, v) at the middle of each flank's domain (0 where a bound is infinite), the
        default start of :func:`gearrep.tca.default_start`."""
        return tuple(
            np.where(np.isfinite(lo + hi), 0.5 * (lo + hi), 0.0)
            for lo, hi in ((self.lower1, self.upper1), (self.lower2, self.upper2))
        )

    @cached_property
    def _flank1_facing(self) -> float:
        """The side flank 1 faces (:func:`gearrep.tca.flank_sense`): the sign of (r x n)_z of
        member 1 at the middle of its box, the same at every phi1 (member 1 turns about z_f, which
        leaves the z component of r x n unchanged)."""
        mid = 0.5 * (self.lower1 + self.upper1)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            r, n = self.member1(mid[:1], mid[1:], np.zeros(1))
        return float(np.sign(r[0, 0] * n[0, 1] - r[0, 1] * n[0, 0]))

    @cached_property
    def _flank2_limits(self) -> tuple:
        """(u_lo, u_hi, v_lo, v_hi) of member 2's flank with a relative slack of 1e-12 (a solved
        point beyond them is OFF_FLANK)."""
        tol2 = 1e-12 * (1 + np.abs(np.concatenate([self.lower2, self.upper2])))
        lo, hi = self.lower2, self.upper2
        return (lo[0] - tol2[0], hi[0] + tol2[2], lo[1] - tol2[1], hi[1] + tol2[3])

    def R1(self, phi1):
        """Rotation of member 1, Rz(phi1).

        Parameters
        ----------
        phi1 : float or array_like
            Angle of member 1 [rad].

        Returns
        -------
        numpy.ndarray
            (..., 3, 3) rotation matrices.
        """
        return rot_z(phi1)

    def R2(self, phi2):
        """Rotation of member 2, A2 Rz(phase2 - phi2).

        Parameters
        ----------
        phi2 : float or array_like
            Angle of member 2 in its driven sense [rad].

        Returns
        -------
        numpy.ndarray
            (..., 3, 3) rotation matrices.
        """
        return self.A2 @ rot_z(self.phase2 - np.asarray(phi2, float))

    def member1(self, u1, v1, phi1):
        """Position and outward unit normal of member 1 in S_f.

        Parameters
        ----------
        u1, v1 : float or array_like
            Flank parameters of member 1 (its family's units, e.g. mm).
        phi1 : float or array_like
            Angle of member 1 [rad].

        Returns
        -------
        tuple of numpy.ndarray
            (position [length], outward unit normal), each (..., 3).
        """
        P = self.flank1.evaluate(u1, v1)
        R = self.R1(phi1)
        return _mv(R, P.r), self.sign1 * _mv(R, P.normal)

    def member2(self, u2, v2, phi2):
        """Position and outward unit normal of member 2 in S_f.

        Parameters
        ----------
        u2, v2 : float or array_like
            Flank parameters of member 2.
        phi2 : float or array_like
            Angle of member 2 [rad].

        Returns
        -------
        tuple of numpy.ndarray
            (position [length], outward unit normal), each (..., 3).
        """
        P = self.flank2.evaluate(u2, v2)
        R = self.R2(phi2)
        return self.O2 + _mv(R, P.r), self.sign2 * _mv(R, P.normal)


def transmission_error(phi1, phi2, n1, n2, phi10=0.0, phi20=0.0):
    """Transmission error (thesis eq 14), radians: (phi2 - phi20) - (N1/N2)(phi1 - phi10).

    phi2 must be measured in the driven sense (see module docstring); TE > 0: member 2 leads.

    Parameters
    ----------
    phi1, phi2 : float or array_like
        Angles of members 1 and 2 [rad].
    n1, n2 : float
        Numbers of teeth, > 0.
    phi10, phi20 : float, optional
        The reference angles [rad].

    Returns
    -------
    float or numpy.ndarray
        TE [rad].

    Raises
    ------
    ValueError
        If ``n1`` or ``n2`` is not a finite number > 0.

    Examples
    --------
    >>> from gearrep.tca import transmission_error
    >>> round(transmission_error(0.1, 0.05, 20, 40), 12)  # rad
    0.0
    """
    for name, n in (("n1", n1), ("n2", n2)):
        ok = (math.isfinite(n) and n > 0) if type(n) in (int, float) else (np.isfinite(n) and n > 0)
        if not ok:
            raise ValueError(f"{name} must be > 0, got {n!r}")
    if type(phi1) is float and type(phi2) is float:  # one point: the same operations on floats
        return (phi2 - phi20) - (n1 / n2) * (phi1 - phi10)
    phi1 = np.asarray(phi1, float)
    phi2 = np.asarray(phi2, float)
    return (phi2 - phi20) - (n1 / n2) * (phi1 - phi10)


# ----------------------------------------------------------------------------------------------
# contact record
# ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactPoints:
    """Contact points of a batch of solves (all arrays of length n; position/normal (n, 3)).

    Attributes
    ----------
    u1, v1, u2, v2 : (n,) numpy.ndarray
        Surface parameters of members 1 and 2 (the families' units, mm for involute flanks).
    phi1, phi2 : (n,) numpy.ndarray
        Rotation angles [rad].
    position : (n, 3) numpy.ndarray
        Contact point in S_f [length].
    normal : (n, 3) numpy.ndarray
        Outward unit normal of member 1 in S_f.
    te : (n,) numpy.ndarray
        Transmission error [rad] (eq 14 with the pair's nominal reference); ``te_arcsec`` in arcsec.
    residual, iterations, status : (n,) numpy.ndarray
        From :func:`gearrep.solve.newton`, with OFF_FLANK (member-2 parameters outside its flank,
        reduced form) and WRONG_ROOT (normals not opposite) added.
    formulation : str
        "reduced" or "conventional".
    condition : (n,) numpy.ndarray or None
        Condition number of the Newton Jacobian at the last iteration (see
        :class:`gearrep.solve.SolveResult`); None when the points were not built by a solve.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, Misalignment, solve_contact
    >>> g1 = InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
    >>> g2 = InvoluteGearData(41, 3.0, math.radians(20), 25.0)
    >>> f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4))  # 1/mm
    >>> pair = GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=Misalignment(d_E=0.01))
    >>> c = solve_contact(pair, [-0.05, 0.0, 0.05])  # phi1 [rad]
    >>> len(c), c.status_name.tolist(), np.round(c.u1, 4).tolist()  # u1 = radius [mm]
    (3, ['converged', 'converged', 'converged'], [34.7106, 35.3223, 35.9966])
    >>> np.round(c.te_arcsec, 3).tolist()  # d_E moves the gear back: a constant lag
    [-12.212, -12.212, -12.212]
    >>> c.take([1]).unknowns("conventional").shape  # a start for the five-unknown solve
    (1, 5)
    >>> len(type(c).concatenate([c, c.take(c.converged)]))
    6
    """

    #: the per-point array fields (every field but ``formulation`` and ``condition``)
    ARRAYS: ClassVar[tuple[str, ...]] = (
        "u1",
        "v1",
        "u2",
        "v2",
        "phi1",
        "phi2",
        "position",
        "normal",
        "te",
        "residual",
        "iterations",
        "status",
    )

    u1: np.ndarray
    v1: np.ndarray
    u2: np.ndarray
    v2: np.ndarray
    phi1: np.ndarray
    phi2: np.ndarray
    position: np.ndarray
    normal: np.ndarray
    te: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    formulation: str = "reduced"
    condition: np.ndarray | None = None

    def __len__(self):
        return len(self.status)

    @property
    def te_arcsec(self) -> np.ndarray:
        """Transmission error [arcsec]."""
        return self.te / ARCSEC

    @property
    def converged(self) -> np.ndarray:
        """Boolean mask of the rows with status CONVERGED."""
        return self.status == Status.CONVERGED

    @property
    def status_name(self) -> np.ndarray:
        """Lower-case status name of each row (``converged``, ``off_flank``, ...)."""
        return status_names(self.status)

    #: the fields that describe the contact (NaN in a row that did not converge, see :meth:`failed_as_nan`)
    CONTACT: ClassVar[tuple[str, ...]] = ("u1", "v1", "u2", "v2", "phi2", "position", "normal", "te")

    def failed_as_nan(self) -> ContactPoints:
        """This record with every contact field (:attr:`CONTACT`: flank parameters, phi2, position,
        normal, TE) NaN in the rows whose status is not CONVERGED: a failed solve's last iterate is
        not a contact. phi1 (the given angle), residual, iterations, status and condition stay.

        Returns
        -------
        ContactPoints
            This record itself when every row converged, else a copy.
        """
        bad = ~self.converged
        if not bad.any():
            return self
        kw = {}
        for f in self.CONTACT:
            a = np.array(getattr(self, f), dtype=float, copy=True)
            a[bad] = np.nan
            kw[f] = a
        return replace(self, **kw)

    def take(self, idx) -> ContactPoints:
        """Subset by index or boolean mask.

        Parameters
        ----------
        idx : int array or bool array
            Rows to keep.

        Returns
        -------
        ContactPoints
            The selected rows.
        """
        kw = {f: getattr(self, f)[idx] for f in self.ARRAYS}
        cond = None if self.condition is None else self.condition[idx]
        return ContactPoints(formulation=self.formulation, condition=cond, **kw)

    @staticmethod
    def concatenate(items) -> ContactPoints:
        """Records joined row-wise (the formulation of the first).

        Parameters
        ----------
        items : iterable of ContactPoints
            Records to join.

        Returns
        -------
        ContactPoints
            All their rows in order (``condition`` None unless every record has one).
        """
        items = list(items)
        kw = {f: np.concatenate([getattr(c, f) for c in items]) for f in ContactPoints.ARRAYS}
        conds = [c.condition for c in items]
        cond = None if any(c is None for c in conds) else np.concatenate(conds)
        return ContactPoints(formulation=items[0].formulation, condition=cond, **kw)

    def unknowns(self, formulation=None) -> np.ndarray:
        """Solution as a start array: (u1, v1) for reduced, (u1, v1, u2, v2, phi2) for conventional.

        Parameters
        ----------
        formulation : {"reduced", "conventional"}, optional
            Default: the record's own.

        Returns
        -------
        numpy.ndarray
            (n, 2) or (n, 5).
        """
        f = formulation or self.formulation
        if f == "reduced":
            return np.stack([self.u1, self.v1], axis=-1)
        return np.stack([self.u1, self.v1, self.u2, self.v2, self.phi2], axis=-1)
