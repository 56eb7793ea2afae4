"""Loaded tooth contact analysis of a pair over mesh positions: load distribution, loaded TE,
pressure and mesh stiffness (assembled from :mod:`._separation`, :mod:`._compliance` and
:mod:`._distribution`; the model is described in :mod:`gearrep.ltca`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..ellipse import effective_modulus
from ..inputs import check_finite, check_integer
from ..solve import Status
from ..tca import GearPair
from . import _compliance as compliance
from ._compliance import STEEL, Material
from ._distribution import solve_contact_loads
from ._separation import Separations, initial_separations

__all__ = ["LoadedContact", "CycleSummary", "PressureMap", "cycle_positions", "loaded_contact"]

_DRIVING = ("pinion", "gear")


def cycle_positions(pair: GearPair, n_positions: int = 41) -> np.ndarray:
    """Member-1 angles [rad] of one meshing cycle (one angular pitch 2 pi / N1, both ends included)
    centred on the position where tooth pair 0's mid-face section is at the pitch point (the middle
    position for odd ``n_positions``)."""
    n = check_integer("n_positions", n_positions, 2)
    side = getattr(pair.flank1, "side", 1)
    tw = float(np.asarray(pair.flank1.twist(np.zeros(1))[0])[0]) if hasattr(pair.flank1, "twist") else 0.0
    pitch = -side * np.pi / (2 * pair.n1) - tw
    return pitch + (2.0 * np.pi / pair.n1) * np.linspace(-0.5, 0.5, n)


@dataclass(frozen=True)
class PressureMap:
    """Hertz pressure over the contact strips of one position: ``pressure_MPa`` (n_pairs, n_slices,
    n_across) at face coordinates ``v1_mm`` (n_slices,) and offsets ``across_mm`` (n_across,) across
    the contact line from the section contact point at radius ``u1_mm`` (n_pairs, n_slices) of
    member 1 (NaN where the strip is not a candidate contact)."""

    pairs: np.ndarray
    v1_mm: np.ndarray
    across_mm: np.ndarray
    u1_mm: np.ndarray
    pressure_MPa: np.ndarray


@dataclass(frozen=True)
class CycleSummary:
    """One row of cycle results (units in the names); ``n_failed``: positions not converged."""

    torque_Nm: float
    normal_load_N: float
    lte_peak_to_peak_urad: float
    lte_peak_to_peak_um: float
    mesh_stiffness_mean_N_per_mm_um: float
    single_pair_stiffness_max_N_per_mm_um: float
    max_contact_pressure_MPa: float
    load_share_max: float
    load_share_min: float
    n_positions: int
    n_failed: int


@dataclass(frozen=True)
class LoadedContact:
    """Loaded contact of a pair at mesh positions (arrays over positions unless noted).

    phi1_rad; te_unloaded_rad (rigid TCA); te_loaded_rad; lte_urad, lte_um (loaded TE in micro-radians
    of member 2 and in micrometres along the transverse line of action, r_b2 TE); normal_load_N (sum of
    the loads); pair_load_N (n_pos, n_pairs) per tooth pair; pairs_loaded; max_pressure_MPa;
    mesh_stiffness_N_per_um (transverse base tangential force / elastic transverse approach r_b2
    (TE_unloaded - TE_loaded)) and per face width ``_N_per_mm_um``; moment_residual (relative torque
    balance); iterations (fixed-point iterations); status (:class:`gearrep.solve.Status`; NaN results
    where not CONVERGED). Per strip (n_pos, n_pairs, n_slices): slice_load_N, pressure_MPa (peak),
    half_width_mm. ``separations`` holds the geometry (:class:`Separations`).
    """

    torque_Nm: float
    driving: str
    face_width_mm: float
    separations: Separations
    phi1_rad: np.ndarray
    te_unloaded_rad: np.ndarray
    te_loaded_rad: np.ndarray
    lte_urad: np.ndarray
    lte_um: np.ndarray
    normal_load_N: np.ndarray
    pair_load_N: np.ndarray
    pairs_loaded: np.ndarray
    max_pressure_MPa: np.ndarray
    mesh_stiffness_N_per_um: np.ndarray
    mesh_stiffness_N_per_mm_um: np.ndarray
    moment_residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    slice_load_N: np.ndarray
    pressure_MPa: np.ndarray
    half_width_mm: np.ndarray

    @property
    def converged(self) -> np.ndarray:
        return self.status == Status.CONVERGED

    def summary(self) -> CycleSummary:
        """Cycle results over the converged positions (NaN if none)."""
        ok = self.converged
        nan = float("nan")

        def ext(a, f):
            a = np.asarray(a)[ok]
            return float(f(a)) if a.size else nan

        share = self.pair_load_N / self.normal_load_N[:, None]
        single = ok & (self.pairs_loaded == 1)
        return CycleSummary(
            torque_Nm=self.torque_Nm,
            normal_load_N=ext(self.normal_load_N, np.mean),
            lte_peak_to_peak_urad=ext(self.lte_urad, np.ptp),
            lte_peak_to_peak_um=ext(self.lte_um, np.ptp),
            mesh_stiffness_mean_N_per_mm_um=ext(self.mesh_stiffness_N_per_mm_um, np.mean),
            single_pair_stiffness_max_N_per_mm_um=float(np.max(self.mesh_stiffness_N_per_mm_um[single]))
            if np.any(single)
            else nan,
            max_contact_pressure_MPa=ext(self.max_pressure_MPa, np.max),
            load_share_max=ext(np.max(share, axis=1), np.max),
            load_share_min=ext(np.max(share, axis=1), np.min),
            n_positions=int(ok.size),
            n_failed=int(np.sum(~ok)),
        )

    def pressure_map(self, position: int, n_across: int = 21) -> PressureMap:
        """Semi-elliptic Hertz pressure across every loaded strip of position ``position`` (index)."""
        i = int(position)
        n = check_integer("n_across", n_across, 3)
        b = self.half_width_mm[i]
        bmax = float(np.nanmax(b)) if np.any(b > 0) else 0.0
        x = np.linspace(-bmax, bmax, n)
        with np.errstate(invalid="ignore", divide="ignore"):
            q = 1.0 - (x / b[..., None]) ** 2
            p = np.where(q > 0, self.pressure_MPa[i][..., None] * np.sqrt(np.maximum(q, 0.0)), 0.0)
        p = np.where(self.separations.in_contact[i][..., None], p, np.nan)
        u1 = self.separations.contacts.u1.reshape(self.separations.shape)[i]
        return PressureMap(
            self.separations.pairs, self.separations.v1_mm, x, np.where(self.separations.in_contact[i], u1, np.nan), p
        )


def _check_inputs(pair, torque_Nm, driving, materials, tol, maxiter):
    if not isinstance(pair, GearPair):
        raise ValueError(f"pair must be a gearrep.tca.GearPair, got {type(pair).__name__}")
    T = check_finite("torque_Nm", torque_Nm, positive=True)
    if driving not in _DRIVING:
        raise ValueError(f"driving must be one of {_DRIVING}, got {driving!r}")
    if isinstance(materials, Material):
        materials = (materials, materials)
    materials = tuple(materials)
    if len(materials) != 2 or not all(isinstance(m, Material) for m in materials):
        raise ValueError("materials must be a gearrep.ltca.Material or a pair of them (member 1, member 2)")
    check_finite("tol", tol, positive=True)
    check_integer("maxiter", maxiter, 1)
    return T, materials


class _Strips:
    """Per-candidate data of all positions, flattened: compliances and Hertz inputs."""

    def __init__(self, pair, sep: Separations, materials, bore_radius_mm):
        c = sep.contacts
        ok = sep.in_contact.ravel()
        t1 = compliance.ToothCompliance(pair.flank1, materials[0], bore_radius_mm[0])
        t2 = compliance.ToothCompliance(pair.flank2, materials[1], bore_radius_mm[1])
        beta_b = float(pair.flank1.gear.beta_b)
        self.length_mm = sep.slice_width_mm / np.cos(beta_b)  # contact-line length of a strip
        n = ok.size
        self.lam = np.full(n, np.nan)
        self.h1 = np.full(n, np.nan)
        self.h2 = np.full(n, np.nan)
        if np.any(ok):
            self.lam[ok] = t1.compliance(c.u1[ok]) + t2.compliance(c.u2[ok])
            self.h1[ok] = t1.load_geometry(c.u1[ok])[2]
            self.h2[ok] = t2.load_geometry(c.u2[ok])[2]
        self.k = sep.k_rel_per_mm.ravel()
        self.materials = materials
        self.Estar = float(
            effective_modulus(materials[0].E_MPa, materials[0].poisson, materials[1].E_MPa, materials[1].poisson)
        )

    def compliance(self, rows, F):
        """Secant compliance [mm/N] of strips ``rows`` at loads F [N] (tooth + Weber approach)."""
        L = self.length_mm
        dH = compliance.weber_contact_approach_mm(F / L, self.k[rows], self.h1[rows], self.h2[rows], *self.materials)
        return self.lam[rows] / L + dH / F


def _one_position(strips: _Strips, rows, gap, arm, moment, tol, maxiter, guess=None):
    """Loads of one position by fixed-point iteration on the secant compliance, from the loads
    ``guess`` (e.g. the previous position's; default an even share); returns (ContactLoads,
    iterations, status)."""
    F_ref = moment / float(np.sum(arm))  # an even share: the linearisation point of unloaded strips
    F = np.full(rows.size, F_ref) if guess is None else guess
    working = None if guess is None or not np.any(guess > 0) else np.flatnonzero(guess > 0)
    status = int(Status.NOT_CONVERGED)
    sol = None
    for it in range(1, maxiter + 1):
        c = strips.compliance(rows, np.where(F > 0, F, F_ref))
        sol = solve_contact_loads(c, gap, arm, moment, working=working)
        if sol.status != Status.CONVERGED:
            return sol, it, sol.status
        change = float(np.max(np.abs(sol.loads_N - F)))
        F = sol.loads_N
        working = np.flatnonzero(F > 0)
        if change <= tol * float(np.sum(F)):
            status = int(Status.CONVERGED)
            break
    return sol, it, status


def loaded_contact(
    pair: GearPair,
    torque_Nm: float,
    phi1=None,
    *,
    driving: str = "pinion",
    materials=STEEL,
    n_slices: int = 20,
    bore_radius_mm=(None, None),
    pairs=None,
    tol: float = 1e-10,
    maxiter: int = 100,
) -> LoadedContact:
    """Loaded tooth contact analysis of ``pair`` under ``torque_Nm`` [N m] on the driving member at
    member-1 angles ``phi1`` [rad] (default :func:`cycle_positions`, 41 positions).

    ``materials``: one :class:`Material` for both members or (member 1, member 2), default steel;
    ``n_slices``: face strips; ``bore_radius_mm``: (member 1, member 2) gear-body bores for the
    foundation term (None: half the root radius); ``pairs``: tooth-pair offsets (default -4 ... 4);
    ``tol``: relative load change that ends the fixed-point iteration; ``maxiter`` its limit.
    Needs involute flanks for the tooth compliance (ValueError otherwise).
    """
    T, materials = _check_inputs(pair, torque_Nm, driving, materials, tol, maxiter)
    if np.ndim(bore_radius_mm) != 1 or len(bore_radius_mm) != 2:
        raise ValueError(
            f"bore_radius_mm must be a pair (member 1, member 2) of radii [mm] or None, got {bore_radius_mm!r}"
        )
    phi1 = cycle_positions(pair) if phi1 is None else phi1
    sep = initial_separations(pair, phi1, n_slices=n_slices, pairs=pairs)
    strips = _Strips(pair, sep, materials, tuple(bore_radius_mm))
    shape = sep.shape
    n_pos = shape[0]
    moment = 1000.0 * T  # N mm
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    arm_all = sep.sense * (sep.arm1_mm if driving == "pinion" else sep.arm2_mm).reshape(n_pos, -1)
    te_factor = sep.sense * (pair.ratio if driving == "pinion" else 1.0)
    F_bt = moment / float(g1.r_b if driving == "pinion" else g2.r_b)
    out = {k: np.full(n_pos, np.nan) for k in ("te_loaded", "residual", "k_mesh", "pmax")}
    loads = np.zeros((n_pos, shape[1] * shape[2]))
    its = np.zeros(n_pos, dtype=int)
    status = np.full(n_pos, int(Status.OFF_FLANK), dtype=int)
    for i in range(n_pos):
        cand = sep.in_contact[i].ravel()
        rows_local = np.flatnonzero(cand)
        if rows_local.size == 0:
            continue
        if np.any(sep.expected[i] & ~sep.in_contact[i]):
            status[i] = int(Status.NOT_CONVERGED)  # a section expected on the flanks was not found
            continue
        rows = i * cand.size + rows_local
        guess = loads[i - 1, rows_local] if i and status[i - 1] == Status.CONVERGED else None
        sol, its[i], status[i] = _one_position(
            strips, rows, sep.gap_mm[i].ravel()[rows_local], arm_all[i, rows_local], moment, tol, maxiter, guess
        )
        if status[i] != Status.CONVERGED:
            continue
        loads[i, rows_local] = sol.loads_N
        out["te_loaded"][i] = sep.te_rigid_rad[i] - te_factor * sol.rotation
        out["residual"][i] = sol.moment_residual
        approach = sep.sense * (sep.te_rigid_rad[i] - out["te_loaded"][i]) * float(g2.r_b) * 1000.0  # um
        out["k_mesh"][i] = F_bt / approach
    return _record(pair, T, driving, sep, strips, loads, out, its, status)


def _record(pair, T, driving, sep, strips: _Strips, loads, out, its, status) -> LoadedContact:
    shape = sep.shape
    ok = status == Status.CONVERGED
    slice_load = np.where(ok[:, None], loads, np.nan).reshape(shape)
    w = slice_load / strips.length_mm
    k = sep.k_rel_per_mm
    p0 = np.where(
        sep.in_contact,
        compliance.line_contact_pressure_MPa(np.nan_to_num(w), np.where(sep.in_contact, k, 1.0), strips.Estar),
        np.nan,
    )
    b = np.where(
        sep.in_contact,
        compliance.contact_half_width_mm(np.nan_to_num(w), np.where(sep.in_contact, k, 1.0), strips.Estar),
        np.nan,
    )
    p0 = np.where(ok[:, None, None], p0, np.nan)
    b = np.where(ok[:, None, None], b, np.nan)
    pair_load = np.nansum(slice_load, axis=2)
    pair_load = np.where(ok[:, None], pair_load, np.nan)
    normal = np.where(ok, np.nansum(pair_load, axis=1), np.nan)
    loaded_pairs = np.where(ok, np.sum(pair_load > 0, axis=1), 0)
    with np.errstate(invalid="ignore"):
        pmax = np.where(ok, np.nanmax(np.where(np.isfinite(p0), p0, -np.inf), axis=(1, 2)), np.nan)
    te_l = np.where(ok, out["te_loaded"], np.nan)
    r_b2 = float(pair.flank2.gear.r_b)
    face = float(pair.upper1[1] - pair.lower1[1])
    k_mesh = np.where(ok, out["k_mesh"], np.nan)
    return LoadedContact(
        torque_Nm=T,
        driving=driving,
        face_width_mm=face,
        separations=sep,
        phi1_rad=sep.phi1_rad,
        te_unloaded_rad=sep.te_rigid_rad,
        te_loaded_rad=te_l,
        lte_urad=te_l * 1e6,
        lte_um=te_l * r_b2 * 1000.0,
        normal_load_N=normal,
        pair_load_N=pair_load,
        pairs_loaded=loaded_pairs,
        max_pressure_MPa=pmax,
        mesh_stiffness_N_per_um=k_mesh,
        mesh_stiffness_N_per_mm_um=k_mesh / face,
        moment_residual=np.where(ok, out["residual"], np.nan),
        iterations=its,
        status=status,
        slice_load_N=slice_load,
        pressure_MPa=p0,
        half_width_mm=b,
    )
