"""Tooth contact analysis of a curvilinear-tooth pair cut by one ZA hob (seed 000 ch. 5 is its
first user): the pair with its assembly errors, the contact at phi1' = 0 by continuation from the
ideal pair, the physical contact among several tangencies, the kinematic-error (KE) table, where
the contact reaches a tip circle, and the elastic contact ellipses along a path.

The 9-unknown tangency system, its solve and the path are in :mod:`gearrep.tca._envelope`; the
flanks come from :class:`gearrep.surfaces.hob.PairDesign` (``design.cut``), typed here by what is
used (the core does not import the surface families).

Frames: the fixed frame S_f has the pinion axis along z for an aligned pinion and the gear axis
through (C', 0, dZ); the member frames are the tooth-centred frames of
:mod:`gearrep.surfaces.hob`, the gear's turned by a further pi to face the pinion. The pinion is
placed by Rx(-dgamma_h) Ry(dgamma_v) Rz(-phi1') (seed 000 eq 5.1-5.2, read as active rotations)
and the gear by Rz(phi2') (eq 5.3-5.4). Lengths in mm, angles in rad unless a name says deg.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pandas as pd

from ..curvature import PrincipalCurvatures, with_opposite_normal
from ..curvature_relations import generated_curvatures
from ..ellipse import elastic_ellipse_at
from ..frames import drot_z, rot_x, rot_y, rot_z
from ..units import ARCSEC
from . import _envelope as _te
from . import _envelope_contact
from ._envelope import ContactPath, Flank, make_flank, predict, require, solve_points

# a gearrep.surfaces.hob.PairDesign (typed by what is used: n_pinion, n_gear, face_width_mm, hob, cut)
_PairDesign = Any

__all__ = [
    "KE_COLUMNS",
    "Assembly",
    "Pair",
    "make_pair",
    "ideal_start",
    "continue_to",
    "clear_start_cache",
    "physical_contact",
    "ke_table",
    "phi1_grid",
    "tip_crossing",
    "elastic_ellipses",
]

#: the interface columns of a KE table, thesis frame and signs
KE_COLUMNS = ["phi1_deg", "phi2_deg", "l_p_mm", "Z_p_mm", "l_g_mm", "Z_g_mm", "KE_arcsec"]


@dataclass(frozen=True)
class Assembly:
    """Assembly errors (seed 000 sec 5.2): ``dgamma_h``, ``dgamma_v`` [rad, within +-0.01] turn the
    pinion about x and y (eq 5.1), ``dC`` [mm, within +-2] changes the centre distance and ``dZ``
    [mm, within +-2] shifts the gear along its axis (eq 5.3).

    Parameters
    ----------
    dgamma_h : float, optional
        Turn of the pinion about x [rad], in [-0.01, 0.01].
    dgamma_v : float, optional
        Turn of the pinion about y [rad], in [-0.01, 0.01].
    dC : float, optional
        Change of the centre distance [mm], in [-2, 2].
    dZ : float, optional
        Shift of the gear along its axis [mm], in [-2, 2].

    Raises
    ------
    ValueError
        If a value is not finite or out of its range.

    Examples
    --------
    >>> import math
    >>> from gearrep.tca import HobbedAssembly
    >>> a = HobbedAssembly(dgamma_h=math.radians(3 / 60), dC=0.1)  # 3 arcmin [rad], mm
    >>> a.scaled(0.5).dC  # mm
    0.05
    >>> HobbedAssembly(dC=3.0)
    Traceback (most recent call last):
        ...
    ValueError: dC must be finite and in [-2, 2] mm, got 3.0
    """

    dgamma_h: float = 0.0
    dgamma_v: float = 0.0
    dC: float = 0.0
    dZ: float = 0.0

    def __post_init__(self):
        for n in ("dgamma_h", "dgamma_v"):
            v = getattr(self, n)
            if not (np.isfinite(v) and abs(v) <= 0.01):
                raise ValueError(f"{n} must be a finite angle in [-0.01, 0.01] rad, got {v!r}")
        for n in ("dC", "dZ"):
            v = getattr(self, n)
            if not (np.isfinite(v) and abs(v) <= 2.0):
                raise ValueError(f"{n} must be finite and in [-2, 2] mm, got {v!r}")

    def scaled(self, t: float) -> Assembly:
        """All four errors times ``t``.

        Parameters
        ----------
        t : float
            The factor [1].

        Returns
        -------
        HobbedAssembly
            The scaled errors.
        """
        return Assembly(t * self.dgamma_h, t * self.dgamma_v, t * self.dC, t * self.dZ)


@dataclass(frozen=True)
class Pair:
    """Pinion and gear flanks (:class:`gearrep.tca.EnvelopeFlank`), the face width [mm] of both
    and the assembly errors; the placements of the module docstring.

    Parameters
    ----------
    pinion, gear : EnvelopeFlank
        The working flanks, each placed in its member frame.
    face_width_mm : float
        Face width of both members [mm].
    assembly : HobbedAssembly, optional
        Assembly errors (default: none).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_pair
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> pair.ratio, pair.centre_distance, pair.gear_origin.tolist()  # 1, mm, mm
    (0.5, 90.0, [90.0, 0.0, 0.0])
    >>> pair.pinion_rotation([0.0, 0.1]).shape  # one rotation per phi1' [rad]
    (2, 3, 3)
    """

    pinion: Flank
    gear: Flank
    face_width_mm: float
    assembly: Assembly = field(default_factory=Assembly)

    @property
    def ratio(self) -> float:
        """N_p / N_g."""
        return self.pinion.n_teeth / self.gear.n_teeth

    @property
    def centre_distance(self) -> float:
        """C' = C + dC [mm] (eq 5.3)."""
        return self.pinion.r_pitch_mm + self.gear.r_pitch_mm + self.assembly.dC

    def _tilt(self):
        return rot_x(-self.assembly.dgamma_h) @ rot_y(self.assembly.dgamma_v)

    def pinion_rotation(self, phi1, deriv=False):
        """S_2 (pinion generation frame) -> S_f: Rx(-dgamma_h) Ry(dgamma_v) Rz(-phi1') placement
        (eq 5.1-5.2); with ``deriv`` its derivative in phi1' [rad]. Batched.

        Parameters
        ----------
        phi1 : float or array_like
            Pinion angles phi1' [rad].
        deriv : bool, optional
            The derivative in phi1' instead.

        Returns
        -------
        numpy.ndarray
            (..., 3, 3) rotations (or their derivatives [per rad]).
        """
        phi1 = np.asarray(phi1, float)
        if deriv:
            return self._tilt() @ -drot_z(-phi1) @ self.pinion.placement
        return self._tilt() @ rot_z(-phi1) @ self.pinion.placement

    def gear_rotation(self, phi2, deriv=False):
        """S_2 (gear generation frame) -> S_f: Rz(phi2') placement (eq 5.3-5.4); with ``deriv`` its
        derivative in phi2' [rad]. Batched.

        Parameters
        ----------
        phi2 : float or array_like
            Gear angles phi2' [rad].
        deriv : bool, optional
            The derivative in phi2' instead.

        Returns
        -------
        numpy.ndarray
            (..., 3, 3) rotations (or their derivatives [per rad]).
        """
        R = (drot_z if deriv else rot_z)(np.asarray(phi2, float))
        return R @ self.gear.placement

    @property
    def gear_origin(self):
        """Gear centre in S_f [mm]: (C', 0, dZ)."""
        return np.array([self.centre_distance, 0.0, self.assembly.dZ])


def make_pair(design: _PairDesign, R_cp_mm: float, R_cg_mm: float, assembly: Assembly | None = None) -> Pair:
    """The pair of ``design`` (a :class:`gearrep.surfaces.hob.PairDesign`) with tooth-trace radii
    ``R_cp_mm`` (pinion, convex) and ``R_cg_mm`` (gear, concave) [mm, in [20, 1e6] and above half
    the face width, so that the arcs span the face] under ``assembly`` (default: none): both flanks
    in their tooth frames, the gear turned by pi to face the pinion.

    Parameters
    ----------
    design : gearrep.surfaces.hob.PairDesign
        Tooth numbers, face width and hob.
    R_cp_mm, R_cg_mm : float
        Tooth-trace radii of pinion and gear [mm].
    assembly : HobbedAssembly, optional
        Assembly errors.

    Returns
    -------
    HobbedPair
        The pair.

    Raises
    ------
    ValueError
        If ``design`` is not a pair design, ``assembly`` not a :class:`HobbedAssembly`, or a radius
        is out of range.

    Examples
    --------
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import HobbedAssembly, hobbed_pair
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0, HobbedAssembly(dC=0.1))  # tooth-trace radii [mm]
    >>> pair.pinion.n_teeth, pair.gear.n_teeth, round(pair.centre_distance, 6)  # mm
    (20, 40, 90.1)
    >>> hobbed_pair(design, 10.0, 110.0)
    Traceback (most recent call last):
        ...
    ValueError: R_cp_mm must be in [20, 1e6] mm and > face_width_mm / 2 = 15 mm, got 10.0
    """
    if not all(hasattr(design, a) for a in ("cut", "face_width_mm", "n_pinion", "n_gear")):
        raise ValueError(f"design must be a gearrep.surfaces.hob.PairDesign, got {design!r}")
    if assembly is not None and not isinstance(assembly, Assembly):
        raise ValueError(f"assembly must be a gearrep.tca.HobbedAssembly or None, got {assembly!r}")
    half = design.face_width_mm / 2
    for name, v in (("R_cp_mm", R_cp_mm), ("R_cg_mm", R_cg_mm)):
        if not (np.isfinite(v) and 20.0 <= v <= 1e6 and v > half):
            raise ValueError(f"{name} must be in [20, 1e6] mm and > face_width_mm / 2 = {half:g} mm, got {v!r}")
    pin, gear = design.cut(R_cp_mm, R_cg_mm)
    return Pair(make_flank(pin), make_flank(gear, np.pi), float(design.face_width_mm), assembly or Assembly())


def _check_tol(tol):
    if not (np.isfinite(tol) and 0 < tol < 1e-3):
        raise ValueError(f"tol must be in (0, 1e-3), got {tol!r}")


def ideal_start(pair: Pair, *, tol: float = 1e-11) -> ContactPath:
    """Contact at phi1' = 0 of ``pair`` from a generic start: both members at mid-face (psi = 0)
    near the hob pitch line, (phi, theta) solved by each envelope, phi2' = 0; ``tol`` the
    solver's tolerance (residual, mm and rad).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    tol : float, optional
        Residual tolerance [mm, rad], in (0, 1e-3).

    Returns
    -------
    EnvelopeContactPath
        One row at phi1' = 0 (its status says whether it converged).

    Raises
    ------
    ValueError
        If ``pair`` is not a :class:`HobbedPair` or ``tol`` is out of range.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_ideal_start, hobbed_pair
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> start = hobbed_ideal_start(hobbed_pair(design, 100.0, 110.0))  # tooth-trace radii [mm]
    >>> start.status_name.tolist(), np.round(start.radius_p, 4).tolist(), np.round(start.radius_g, 4).tolist()  # mm
    (['converged'], [30.8237], [59.283])
    """
    if not isinstance(pair, Pair):
        raise ValueError(f"pair must be a gearrep.tca.HobbedPair, got {pair!r}")
    _check_tol(tol)
    l0 = _te.hob_pitch_l(pair.pinion.gear.hob)
    qp = pair.pinion.gear.solve(l0, 0.0).params[0]
    qg = pair.gear.gear.solve(l0, 0.0).params[0]
    return solve_points(pair, [0.0], np.r_[qp, qg, 0.0][None], tol=tol)


_START_CACHE: dict = {}  # ideal starts by (design, R_cp, R_cg0, tol): shared by the calls of one process


def clear_start_cache() -> None:
    """Forget the ideal starts :func:`continue_to` keeps per (design, R_cp, R_cg0, tol) (for a cold
    timing; the results do not depend on the cache).

    Examples
    --------
    >>> from gearrep.tca import clear_hobbed_start_cache
    >>> clear_hobbed_start_cache()
    """
    _START_CACHE.clear()


def continue_to(
    design: _PairDesign,
    R_cp_mm: float,
    R_cg_mm: float,
    assembly: Assembly,
    *,
    steps: int = 4,
    tol: float = 1e-11,
    R_gap_mm: float = 3.0,
) -> tuple[Pair, ContactPath]:
    """(pair, physical contact at phi1' = 0) of (``design``, R_cp, R_cg [mm], ``assembly``) by
    continuation from the ideal pair: start at R_cg0 = max(R_cg, R_cp + ``R_gap_mm``) (a
    well-localised contact; R_cg = R_cp is an almost-line contact) with no assembly errors, then
    move R_cg and the errors linearly to their targets in ``steps`` warm-started solves; of the
    tangencies at the target, the physical one (:func:`physical_contact`). RuntimeError when a
    solve does not converge.

    Parameters
    ----------
    design : gearrep.surfaces.hob.PairDesign
        Tooth numbers, face width and hob.
    R_cp_mm, R_cg_mm : float
        Tooth-trace radii of pinion and gear [mm].
    assembly : HobbedAssembly
        The target's assembly errors.
    steps : int, optional
        Continuation steps, >= 1.
    tol : float, optional
        Residual tolerance [mm, rad], in (0, 1e-3).
    R_gap_mm : float, optional
        How much larger than R_cp the starting R_cg is at least [mm], >= 0.

    Returns
    -------
    pair : HobbedPair
        The target pair.
    contact : EnvelopeContactPath
        Its physical contact at phi1' = 0.

    Raises
    ------
    ValueError
        If ``steps`` is not a positive integer, ``assembly`` is not a :class:`HobbedAssembly`,
        ``R_gap_mm`` is negative or ``tol`` is out of range (before any solve).
    RuntimeError
        If a continuation step does not converge.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import HobbedAssembly, hobbed_continue_to
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair, c = hobbed_continue_to(design, 100.0, 110.0, HobbedAssembly(dgamma_v=0.001), steps=2)  # mm, rad
    >>> c.status_name.tolist(), np.round(c.Z_p, 3).tolist()  # the tilt moves the contact along the face [mm]
    (['converged'], [0.102])
    """
    if int(steps) != steps or steps < 1:
        raise ValueError(f"steps must be a positive integer, got {steps!r}")
    if not isinstance(assembly, Assembly):
        raise ValueError(f"assembly must be a gearrep.tca.HobbedAssembly, got {assembly!r}")
    if not (np.isfinite(R_gap_mm) and R_gap_mm >= 0):
        raise ValueError(f"R_gap_mm must be a finite length >= 0 mm, got {R_gap_mm!r}")
    _check_tol(tol)
    R0 = max(R_cg_mm, R_cp_mm + R_gap_mm)
    pair = make_pair(design, R_cp_mm, R0)
    key = (design, float(R_cp_mm), float(R0), float(tol))
    if key not in _START_CACHE:
        sol = ideal_start(pair, tol=tol)
        require(sol, f"ideal start R_cp={R_cp_mm}, R_cg={R0}")
        _START_CACHE[key] = sol
    sol = _START_CACHE[key]
    for t in np.linspace(0.0, 1.0, int(steps) + 1)[1:]:
        pair = make_pair(design, R_cp_mm, R0 + t * (R_cg_mm - R0), assembly.scaled(t))
        sol = solve_points(pair, [0.0], sol.x, tol=tol)
        require(sol, f"continuation step t={t:.3g} to R_cg={R_cg_mm}, {assembly}")
    return pair, physical_contact(pair, sol, tol=tol)


def physical_contact(pair: Pair, sol: ContactPath, **kw) -> ContactPath:
    """:func:`gearrep.tca.envelope_physical_contact` over the pair's face width (``kw``: its
    search settings).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    sol : EnvelopeContactPath
        The continuation roots.
    **kw
        ``n_starts``, ``tol``, ``maxiter``, ``max_halvings``, ``same_tooth_rad``, ``distinct_mm`` of
        :func:`gearrep.tca.envelope_physical_contact`.

    Returns
    -------
    EnvelopeContactPath
        The physical contact per row, with the tangency diagnostics.

    Raises
    ------
    ValueError
        If ``pair`` is not a :class:`HobbedPair` (or a search setting is bad).

    Examples
    --------
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_ideal_start, hobbed_pair, hobbed_physical_contact
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> hobbed_physical_contact(pair, hobbed_ideal_start(pair)).n_tangencies.tolist()  # a localised contact
    [1]
    """
    if not isinstance(pair, Pair):
        raise ValueError(f"pair must be a gearrep.tca.HobbedPair, got {pair!r}")
    return _envelope_contact.physical_contact(pair, sol, face_width_mm=pair.face_width_mm, **kw)


def ke_table(sol: ContactPath, ratio: float) -> pd.DataFrame:
    """KE table of a path that contains phi1' = 0 exactly once, for the tooth ratio ``ratio``
    (N_p / N_g > 0): phi2' and KE = phi2' - ratio phi1' (seed 000 eq 5.12) re-zeroed at phi1' = 0,
    KE in arc-seconds; the :data:`KE_COLUMNS`, then the flank parameters, radii, solve record and
    (after :func:`physical_contact`) the tangency diagnostics.

    Parameters
    ----------
    sol : EnvelopeContactPath
        The path, phi1' = 0 exactly once among its angles.
    ratio : float
        N_p / N_g [1], > 0.

    Returns
    -------
    pandas.DataFrame
        One row per point.

    Raises
    ------
    ValueError
        If ``ratio`` is not > 0 or phi1' = 0 is not in the path exactly once.

    Examples
    --------
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import KE_COLUMNS, hobbed_ideal_start, hobbed_pair, hobbed_phi1_grid, ke_table
    >>> from gearrep.tca import trace_envelope_path
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> path = trace_envelope_path(pair, hobbed_ideal_start(pair), hobbed_phi1_grid(-4.0, 4.0, 4.0))  # deg
    >>> table = ke_table(path, pair.ratio)
    >>> table["KE_arcsec"].round(2).tolist()
    [1.16, 0.0, -0.44]
    >>> table.columns[: len(KE_COLUMNS)].tolist() == KE_COLUMNS
    True
    """
    if not (np.isfinite(ratio) and ratio > 0):
        raise ValueError(f"ratio must be a finite tooth ratio > 0, got {ratio!r}")
    i0 = np.flatnonzero(np.abs(sol.phi1) < 1e-12)
    if i0.size != 1:
        raise ValueError("sol: the path must contain phi1' = 0 exactly once (the tables' zero of KE)")
    i0 = int(i0[0])
    ke = (sol.phi2 - sol.phi2[i0]) - ratio * (sol.phi1 - sol.phi1[i0])
    return pd.DataFrame(
        {
            "phi1_deg": np.degrees(sol.phi1),
            "phi2_deg": np.degrees(ratio * sol.phi1 + ke),
            "l_p_mm": sol.x[:, 0],
            "Z_p_mm": sol.Z_p,
            "l_g_mm": sol.x[:, 4],
            "Z_g_mm": sol.Z_g,
            "KE_arcsec": ke / ARCSEC,
            "psi_p_rad": sol.x[:, 3],
            "psi_g_rad": sol.x[:, 7],
            "radius_p_mm": sol.radius_p,
            "radius_g_mm": sol.radius_g,
            "status": sol.status_name,
            "residual": sol.solve.residual,
            "iterations": sol.solve.iterations,
            "jacobian_cond": sol.cond,
            **(
                {}
                if sol.n_tangencies is None
                else {
                    "n_tangencies": sol.n_tangencies,
                    "tangency_phi2_spread_arcsec": sol.tangency_phi2_spread / ARCSEC,
                    "tangency_min_gap_mm": sol.tangency_min_gap,
                    "phi2_continuation_root_minus_phi2_arcsec": (sol.phi2_continuation - sol.phi2) / ARCSEC,
                }
            ),
        }
    )


def phi1_grid(start_deg: float, end_deg: float, step_deg: float) -> np.ndarray:
    """Pinion angles phi1' [rad] from ``start_deg`` to ``end_deg`` [deg] in ``step_deg`` steps
    (the end rounded to a whole number of steps; a grid value within 1e-9 deg of 0 is exactly 0).

    Parameters
    ----------
    start_deg, end_deg : float
        First and last angle [deg], ``end_deg >= start_deg``.
    step_deg : float
        Step [deg], > 0.

    Returns
    -------
    numpy.ndarray
        The angles [rad].

    Raises
    ------
    ValueError
        If a value is not finite, the step is not > 0 or the end lies before the start.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.tca import hobbed_phi1_grid
    >>> np.degrees(hobbed_phi1_grid(-0.3, 0.3, 0.1)).round(6).tolist()  # deg; the middle value exactly 0
    [-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3]
    """
    for name, v in (("start_deg", start_deg), ("end_deg", end_deg), ("step_deg", step_deg)):
        if not np.isfinite(v):
            raise ValueError(f"{name} must be finite, got {v!r}")
    if not (step_deg > 0 and end_deg >= start_deg):
        raise ValueError(
            f"step_deg must be > 0 with end_deg >= start_deg, got {step_deg!r} ({start_deg!r}..{end_deg!r})"
        )
    n = int(round((end_deg - start_deg) / step_deg))
    g = start_deg + step_deg * np.arange(n + 1)
    g[np.abs(g) < 1e-9] = 0.0
    return np.radians(g)


def tip_crossing(pair: Pair, path: ContactPath, member: str, ra: float, window_deg: float, tol: float) -> dict:
    """Where the contact reaches the circle of radius ``ra`` [mm] (the tip circle) of ``member``
    (``"pinion"`` or ``"gear"``): secant method on the TCA path ``path``, which must cross that
    circle exactly once (else RuntimeError naming the +-``window_deg`` window searched), every
    evaluation a converged physical contact solved to ``tol``. Returns edge, radius_mm, phi1_deg,
    l_p_mm, l_g_mm, radius_error_mm.

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    path : EnvelopeContactPath
        The TCA path bracketing the crossing.
    member : {"pinion", "gear"}
        Whose tip circle.
    ra : float
        The circle's radius [mm], > 0.
    window_deg : float
        The half-width of the window the path spans [deg] (for the message).
    tol : float
        Residual tolerance of the solves [mm, rad], in (0, 1e-3).

    Returns
    -------
    dict
        ``edge`` (``"pinion_tip"`` or ``"gear_tip"``), ``radius_mm``, ``phi1_deg`` [deg],
        ``l_p_mm``, ``l_g_mm`` [mm] and ``radius_error_mm`` [mm] of the last secant iterate.

    Raises
    ------
    ValueError
        If ``member``, ``ra`` or ``tol`` is bad.
    RuntimeError
        If the path does not cross the circle exactly once, or a secant solve does not converge.

    Examples
    --------
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_ideal_start, hobbed_pair, hobbed_phi1_grid, hobbed_tip_crossing
    >>> from gearrep.tca import trace_envelope_path
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> path = trace_envelope_path(pair, hobbed_ideal_start(pair), hobbed_phi1_grid(-12.0, -8.0, 2.0))  # deg
    >>> tip = hobbed_tip_crossing(pair, path, "pinion", 33.0, 12.0, 1e-11)  # pinion tip r_a = 33 mm
    >>> tip["edge"], round(float(tip["phi1_deg"]), 3), round(float(tip["l_p_mm"]), 3)  # deg, mm
    ('pinion_tip', -9.55, 4.381)
    """
    if member not in ("pinion", "gear"):
        raise ValueError(f"member must be 'pinion' or 'gear', got {member!r}")
    if not (np.isfinite(ra) and ra > 0):
        raise ValueError(f"ra must be a finite radius > 0 mm, got {ra!r}")
    _check_tol(tol)
    rad = path.radius_p if member == "pinion" else path.radius_g
    g = rad - ra
    k = np.flatnonzero(np.sign(g[:-1]) != np.sign(g[1:]))
    if k.size != 1:
        raise RuntimeError(f"contact ratio: the {member} tip is not crossed once in +-{window_deg} deg")
    a, b = path.phi1[k[0]], path.phi1[k[0] + 1]
    ga, gb = g[k[0]], g[k[0] + 1]
    cur = path.take([k[0]])
    for _ in range(30):
        c = b - gb * (b - a) / (gb - ga)
        s = physical_contact(pair, solve_points(pair, [c], predict(pair, cur.x, cur.phi1, [c]), tol=tol), tol=tol)
        require(s, "contact-ratio secant")
        gc = (s.radius_p if member == "pinion" else s.radius_g)[0] - ra
        a, ga, b, gb, cur = b, gb, c, gc, s
        if abs(gc) < 1e-10:
            break
    return {
        "edge": f"{member}_tip",
        "radius_mm": ra,
        "phi1_deg": np.degrees(b),
        "l_p_mm": cur.x[0, 0],
        "l_g_mm": cur.x[0, 4],
        "radius_error_mm": gb,
    }


def _principal_in_fixed(flank: Flank, q, R):
    """Principal curvatures [1/mm] of a member at full parameters q (n, 4), vectors rotated into
    S_f by R (n, 3, 3) (generation frame -> S_f)."""
    env = flank.gear.envelope()
    gc = generated_curvatures(env, q)
    rot = lambda v: np.einsum("nab,nb->na", R, v)  # noqa: E731
    return PrincipalCurvatures(gc.k1, gc.k2, rot(gc.e1), rot(gc.e2), rot(gc.normal))


def elastic_ellipses(pair: Pair, sol: ContactPath, delta_mm: float):
    """Contact ellipses of elastic approach ``delta_mm`` [mm, > 0] at every contact point of
    ``sol`` (curvature method, seed 000 eq 5.14-5.17; :func:`gearrep.ellipse.elastic_ellipse_at`)
    from the two-parameter-envelope curvatures of both flanks
    (:func:`gearrep.curvature_relations.generated_curvatures`): (ContactEllipse with the axes as
    unit 3-vectors in S_f, pinion curvatures [1/mm], gear curvatures expressed with the pinion's
    normal).

    Parameters
    ----------
    pair : HobbedPair
        The pair.
    sol : EnvelopeContactPath
        Contact points.
    delta_mm : float
        Elastic approach [mm], > 0.

    Returns
    -------
    ellipse : gearrep.ellipse.ContactEllipse
        Semi-axes [mm] and axes at each point.
    pinion, gear : gearrep.curvature.PrincipalCurvatures
        Principal curvatures [1/mm] and directions in S_f.

    Raises
    ------
    ValueError
        If ``delta_mm`` is not > 0.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> from gearrep.tca import hobbed_elastic_ellipses, hobbed_ideal_start, hobbed_pair
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pair = hobbed_pair(design, 100.0, 110.0)  # tooth-trace radii [mm]
    >>> ellipse, k_pinion, k_gear = hobbed_elastic_ellipses(pair, hobbed_ideal_start(pair), 0.00632)  # mm
    >>> np.round(ellipse.a, 4).tolist(), np.round(ellipse.b, 4).tolist()  # semi-axes [mm]
    ([3.9247], [0.3056])
    """
    if not (np.isfinite(delta_mm) and delta_mm > 0):
        raise ValueError(f"delta_mm must be > 0, got {delta_mm!r}")
    cp = _principal_in_fixed(pair.pinion, sol.x[:, 0:4], pair.pinion_rotation(sol.phi1))
    cg = _principal_in_fixed(pair.gear, sol.x[:, 4:8], pair.gear_rotation(sol.phi2))
    flip = np.sum(cp.normal * cg.normal, axis=-1) < 0
    cgo = with_opposite_normal(cg)
    cg = PrincipalCurvatures(*(np.where(flip if a.ndim == 1 else flip[:, None], b, a) for a, b in zip(cg, cgo)))
    return elastic_ellipse_at(cp, cg, delta_mm), cp, cg
