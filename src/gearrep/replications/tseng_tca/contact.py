"""The seed-000 pair and its TCA (eq 5.1-5.11): the Table 5.1 pinion and gear, the assembly
errors of sec 5.2, continuation from the ideal pair, and the KE table (eq 5.12).

The 9-unknown tangency system of the two hob-generated flanks, its solve, the path and the
choice among several tangencies are library code (:mod:`gearrep.tca_envelope`). The member
frames are the tooth-centred frames of :mod:`gearrep.surfaces.hob`, the gear's turned by a
further pi to face the pinion; the printed matrices are read as active rotations (:mod:`.model`).
Near-line contact (R_cp ~ R_cg): :func:`physical_contact` keeps, among several tangencies at one
phi1', the one the gear reaches first (no interference at the others).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ... import tca_envelope as _te
from ...surfaces.hob import GeneratedGear, ZAHob
from ...tca_envelope import ContactPath, Flank, make_flank, require, solve_points
from ...units import ARCSEC
from . import model

__all__ = [
    "Assembly",
    "PairDesign",
    "Pair",
    "make_pair",
    "ideal_start",
    "continue_to",
    "physical_contact",
    "ke_table",
    "KE_COLUMNS",
]

#: the interface columns of a KE table (issue 8), thesis frame and signs
KE_COLUMNS = ["phi1_deg", "phi2_deg", "l_p_mm", "Z_p_mm", "l_g_mm", "Z_g_mm", "KE_arcsec"]


@dataclass(frozen=True)
class PairDesign:
    """The pinion and gear of a pair cut by one hob: tooth numbers ``n_pinion``, ``n_gear`` (integers
    in [4, 10000]), the face width ``face_width_mm`` of both members (in (0, 1000] mm) and the
    :class:`gearrep.surfaces.hob.ZAHob`. Seed 000's values come from Table 5.1 through
    :func:`gearrep.replications.tseng_tca.params_from_published`."""

    n_pinion: int
    n_gear: int
    face_width_mm: float
    hob: ZAHob

    def __post_init__(self):
        for name in ("n_pinion", "n_gear"):
            v = getattr(self, name)
            if not (isinstance(v, (int, np.integer)) and 4 <= v <= 10000):
                raise ValueError(f"{name} must be an integer in [4, 10000], got {v!r}")
        w = self.face_width_mm
        if not (isinstance(w, (int, float)) and np.isfinite(w) and 0 < w <= 1000):
            raise ValueError(f"face_width_mm must be in (0, 1000] mm, got {w!r}")
        if not isinstance(self.hob, ZAHob):
            raise ValueError(f"hob must be a ZAHob, got {self.hob!r}")

    def with_hob(self, **changes) -> PairDesign:
        """The same pair cut by a hob with ``changes`` (e.g. ``pitch_radius_mm``)."""
        return replace(self, hob=replace(self.hob, **changes))


@dataclass(frozen=True)
class Assembly:
    """Assembly errors of seed 000 sec 5.2: dgamma_h, dgamma_v [rad] turn the pinion (eq 5.1),
    dC [mm] changes the centre distance and dZ [mm] shifts the gear along its axis (eq 5.3)."""

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
        return Assembly(t * self.dgamma_h, t * self.dgamma_v, t * self.dC, t * self.dZ)


@dataclass(frozen=True)
class Pair:
    """Pinion and gear flanks and the assembly errors (frames in the module docstring)."""

    pinion: Flank
    gear: Flank
    face_width_mm: float
    assembly: Assembly = field(default_factory=Assembly)

    @property
    def ratio(self) -> float:
        return self.pinion.n_teeth / self.gear.n_teeth

    @property
    def centre_distance(self) -> float:
        """C' = C + dC (eq 5.3)."""
        return self.pinion.r_pitch_mm + self.gear.r_pitch_mm + self.assembly.dC

    def _tilt(self):
        return model.M_fh(self.assembly.dgamma_h) @ model.M_hv(self.assembly.dgamma_v)

    def pinion_rotation(self, phi1, deriv=False):
        """S_2 (pinion generation frame) -> S_f: M_fh M_hv M_vp(phi1) placement (eq 5.1-5.2);
        with ``deriv`` its derivative in phi1."""
        phi1 = np.asarray(phi1, float)
        if deriv:
            return self._tilt() @ model.dM_vp(phi1) @ self.pinion.placement
        return self._tilt() @ model.M_vp(phi1) @ self.pinion.placement

    def gear_rotation(self, phi2, deriv=False):
        """S_2 (gear generation frame) -> S_f: M_fg(phi2) placement (eq 5.3-5.4)."""
        R = (model.dM_fg if deriv else model.M_fg)(phi2)
        return R @ self.gear.placement

    @property
    def gear_origin(self):
        return np.array([self.centre_distance, 0.0, self.assembly.dZ])


def make_pair(design: PairDesign, R_cp_mm: float, R_cg_mm: float, assembly: Assembly | None = None) -> Pair:
    """The pair of ``design`` (seed 000: Table 5.1): pinion, convex flank (thread side +1, arc
    centre -1: Sigma_2R of ch. 4), and gear, concave flank (thread side +1, arc centre +1), both
    in their thesis frames (tooth centred on X), the gear turned by pi to face the pinion. The
    circular tooth traces must span the face: R_c > face_width_mm / 2."""
    if not isinstance(design, PairDesign):
        raise ValueError(f"design must be a PairDesign, got {design!r}")
    half = design.face_width_mm / 2
    for name, v in (("R_cp_mm", R_cp_mm), ("R_cg_mm", R_cg_mm)):
        if not (np.isfinite(v) and 20.0 <= v <= 1e6 and v > half):
            raise ValueError(f"{name} must be in [20, 1e6] mm and > face_width_mm / 2 = {half:g} mm, got {v!r}")
    hob = design.hob
    pin = GeneratedGear(hob=hob, n_teeth=int(design.n_pinion), R_c_mm=float(R_cp_mm), side=1, arc_centre=-1)
    gear = GeneratedGear(hob=hob, n_teeth=int(design.n_gear), R_c_mm=float(R_cg_mm), side=1, arc_centre=1)
    return Pair(make_flank(pin), make_flank(gear, np.pi), float(design.face_width_mm), assembly or Assembly())


def ideal_start(pair: Pair, *, tol: float = 1e-11) -> ContactPath:
    """Contact at phi1' = 0 of ``pair`` from a generic start: both members at mid-face (psi = 0)
    near the hob pitch line, (phi, theta) solved by each envelope, phi2' = 0."""
    l0 = _te.hob_pitch_l(pair.pinion.gear.hob)
    qp = pair.pinion.gear.solve(l0, 0.0).params[0]
    qg = pair.gear.gear.solve(l0, 0.0).params[0]
    return solve_points(pair, [0.0], np.r_[qp, qg, 0.0][None], tol=tol)


_START_CACHE: dict = {}  # ideal starts by (design, R_cp, R_cg0, tol): shared by the Examples of one process


def continue_to(
    design: PairDesign, R_cp_mm, R_cg_mm, assembly: Assembly, *, steps: int = 4, tol=1e-11, R_gap_mm: float = 3.0
) -> tuple[Pair, ContactPath]:
    """Contact at phi1' = 0 of the pair (``design``, R_cp, R_cg, assembly) by continuation from the ideal
    pair: start at R_cg0 = max(R_cg, R_cp + R_gap) (a well-localised contact; R_cg = R_cp is an
    almost-line contact) with no assembly errors, then move R_cg and the errors linearly to
    their targets in ``steps`` warm-started solves; of the tangencies at the target, the physical
    one is returned (:func:`physical_contact`)."""
    if int(steps) != steps or steps < 1:
        raise ValueError(f"steps must be a positive integer, got {steps!r}")
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
    """:func:`gearrep.tca_envelope.physical_contact` over the pair's face width."""
    return _te.physical_contact(pair, sol, face_width_mm=pair.face_width_mm, **kw)


def ke_table(sol: ContactPath, ratio: float) -> pd.DataFrame:
    """Table 5.x columns from a path that contains phi1' = 0: phi2' and KE re-zeroed at
    phi1' = 0 (eq 5.12 with the tables' normalisation), KE in arc-seconds."""
    i0 = np.flatnonzero(np.abs(sol.phi1) < 1e-12)
    if i0.size != 1:
        raise ValueError("the path must contain phi1' = 0 exactly once (the tables' zero of KE)")
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
