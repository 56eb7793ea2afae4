"""The seed-000 TCA of an envelope pair: two hob-generated flanks, the assembly errors and the
9-unknown tangency system (eq 5.1-5.11), solved along the path by continuation.

Unknowns x = (l_p, phi_p, theta_p, psi_p, l_g, phi_g, theta_g, psi_g, phi2') at a given phi1':
two equations of meshing per member (each flank is a two-parameter envelope, free (l, psi),
solved (phi, theta)), R_f^(p) - R_f^(g) = 0 and two components of n_f^(p) x n_f^(g) = 0. The
member frames are the "thesis frames" of :mod:`gearrep.surfaces.hob` (tooth centred on X), the
gear's turned by a further pi to face the pinion; the printed matrices are read as active
rotations (:mod:`.model`). All phi1' are solved at once (:func:`gearrep.solve.newton`, analytic
Jacobian), warm-started by the first-order predictor dx/dphi1' = -F_x^{-1} F_phi1.

Near-line contact (R_cp ~ R_cg): the system may have several isolated tangencies at one phi1';
:func:`physical_contact` keeps the one the gear reaches first (no interference at the others).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ...frames import rot_z
from ...envelope import local_geometry
from ...solve import SolveResult, Status, newton, status_names
from ...surfaces.hob import GeneratedGear, ZAHob
from ...units import ARCSEC
from . import model

__all__ = [
    "Flank", "make_flank", "Assembly", "Pair", "make_pair", "KEResult", "solve_points", "predict",
    "ideal_start", "continue_to", "trace_path", "physical_contact", "ke_table", "KE_COLUMNS",
    "FACE_WIDTH_MM", "N_PINION", "N_GEAR", "l_pitch", "require",
]

#: the interface columns of a KE table (issue 8), thesis frame and signs
KE_COLUMNS = ["phi1_deg", "phi2_deg", "l_p_mm", "Z_p_mm", "l_g_mm", "Z_g_mm", "KE_arcsec"]
N_PINION, N_GEAR = 20, 40  # Table 5.1
FACE_WIDTH_MM = 40.0  # pinion and gear face width, seed 000 Table 5.1


# --------------------------------------------------------------------------------------------
# flanks, assembly, pair
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Flank:
    """A member's working flank for the TCA: the generated surface ``gear``
    (:class:`gearrep.surfaces.hob.GeneratedGear`, a two-parameter envelope with free (l, psi)
    and solved (phi, theta)) and ``placement``, the 3 x 3 rotation from its generation frame S_2
    into the member frame of eq 5.1/5.3 (the thesis frame, turned by ``extra_turn_rad`` about
    Z to face the other member)."""

    gear: GeneratedGear
    placement: np.ndarray
    tool: object
    motion: object

    @property
    def n_teeth(self) -> int:
        return int(self.gear.n_teeth)

    @property
    def r_pitch_mm(self) -> float:
        return float(self.gear.pitch_radius_mm)

    @property
    def r_outside_mm(self) -> float:
        """Outside radius (standard addendum m, no profile shift; Table 5.1: 33 and 63 mm)."""
        return float(self.gear.pitch_radius_mm + self.gear.hob.module_mm)


def make_flank(gear: GeneratedGear, extra_turn_rad: float = 0.0) -> Flank:
    """Wrap a generated flank (any :class:`GeneratedGear`) for the TCA."""
    if not isinstance(gear, GeneratedGear):
        raise ValueError("gear must be a gearrep.surfaces.hob.GeneratedGear")
    if not np.isfinite(extra_turn_rad):
        raise ValueError(f"extra_turn_rad must be finite, got {extra_turn_rad!r}")
    env = gear.envelope()
    return Flank(gear, rot_z(extra_turn_rad) @ gear.to_thesis, env.tool, env.motion)


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

    def scaled(self, t: float) -> "Assembly":
        return Assembly(t * self.dgamma_h, t * self.dgamma_v, t * self.dC, t * self.dZ)


@dataclass(frozen=True)
class Pair:
    """Pinion and gear flanks and the assembly errors (frames in the module docstring)."""

    pinion: Flank
    gear: Flank
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


def make_pair(R_cp_mm: float, R_cg_mm: float, assembly: Assembly | None = None,
              hob: ZAHob | None = None) -> Pair:
    """The pair of seed 000 Table 5.1: 20-tooth pinion, convex flank (thread side +1, arc centre
    -1: Sigma_2R of ch. 4), and 40-tooth gear, concave flank (thread side +1, arc centre +1),
    both in their thesis frames (tooth centred on X), the gear turned by pi to face the pinion."""
    for name, v in (("R_cp_mm", R_cp_mm), ("R_cg_mm", R_cg_mm)):
        if not (np.isfinite(v) and 20.0 <= v <= 1e6):
            raise ValueError(f"{name} must be in [20, 1e6] mm, got {v!r}")
    hob = ZAHob() if hob is None else hob
    pin = GeneratedGear(hob=hob, n_teeth=N_PINION, R_c_mm=float(R_cp_mm), side=1, arc_centre=-1)
    gear = GeneratedGear(hob=hob, n_teeth=N_GEAR, R_c_mm=float(R_cg_mm), side=1, arc_centre=1)
    return Pair(make_flank(pin), make_flank(gear, np.pi), assembly or Assembly())


# --------------------------------------------------------------------------------------------
# the 9 x 9 system
# --------------------------------------------------------------------------------------------
def _member(flank: Flank, q):
    """Point, d point/dq, hob normal, d normal/dq (generation frame S_2) and the meshing
    functions with their Jacobian at q = (l, phi, theta, psi) (n, 4)."""
    loc = local_geometry(flank.tool, flank.motion, q)
    R = loc.M[:, :3, :3]
    p = loc.tool
    r = np.einsum("nab,nb->na", R, p.r) + loc.M[:, :3, 3]
    T = np.einsum("nab,nqb->nqa", R, loc.T)
    n1 = loc.n
    Nn = np.linalg.norm(loc.N, axis=-1, keepdims=True)
    N_u = np.cross(p.r_uu, p.r_v) + np.cross(p.r_u, p.r_uv)
    N_v = np.cross(p.r_uv, p.r_v) + np.cross(p.r_u, p.r_vv)

    def dn(Nx):
        return (Nx - n1 * np.sum(n1 * Nx, -1, keepdims=True)) / Nn

    # d n / d m_j = R (omega_j x n1): the normal is carried by the motion's rotation
    dn1 = np.stack([dn(N_u), dn(N_v), np.cross(loc.omega[:, 0], n1), np.cross(loc.omega[:, 1], n1)], 1)
    return r, T, np.einsum("nab,nb->na", R, n1), np.einsum("nab,nqb->nqa", R, dn1), loc.f, loc.J


_KEEP = np.array([[1, 2], [0, 2], [0, 1]])


def _system(pair: Pair, x, phi1, drop, derivs=True):
    """F (n, 9); with ``derivs`` also F_x (n, 9, 9) and F_phi1 (n, 9). Rows: meshing of the
    pinion (2) and gear (2), R_f^(p) - R_f^(g) (3, eq 5.7-5.9), two components of
    n_f^(p) x n_f^(g) (eq 5.10-5.11; the component along the largest |n| is dropped)."""
    phi1 = np.asarray(phi1, float)
    rp, Tp, np_, Dnp, fp, Jp = _member(pair.pinion, x[:, 0:4])
    rg, Tg, ng, Dng, fg, Jg = _member(pair.gear, x[:, 4:8])
    Ap, Ag = pair.pinion_rotation(phi1), pair.gear_rotation(x[:, 8])
    Np = np.einsum("nab,nb->na", Ap, np_)
    Ng = np.einsum("nab,nb->na", Ag, ng)
    keep = _KEEP[drop]
    rows = np.arange(len(x))[:, None]
    dpos = np.einsum("nab,nb->na", Ap, rp) - np.einsum("nab,nb->na", Ag, rg) - pair.gear_origin
    F = np.concatenate([fp, fg, dpos, np.cross(Np, Ng)[rows, keep]], axis=1)
    if not derivs:
        return F, None, None
    n = len(x)
    J = np.zeros((n, 9, 9))
    J[:, 0:2, 0:4], J[:, 2:4, 4:8] = Jp, Jg
    dAg = pair.gear_rotation(x[:, 8], deriv=True)
    J[:, 4:7, 0:4] = np.einsum("nab,nqb->naq", Ap, Tp)
    J[:, 4:7, 4:8] = -np.einsum("nab,nqb->naq", Ag, Tg)
    J[:, 4:7, 8] = -np.einsum("nab,nb->na", dAg, rg)
    dc_p = np.cross(np.einsum("nab,nqb->nqa", Ap, Dnp), Ng[:, None])
    dc_g = np.cross(Np[:, None], np.einsum("nab,nqb->nqa", Ag, Dng))
    dc_2 = np.cross(Np, np.einsum("nab,nb->na", dAg, ng))
    J[:, 7:9, 0:4] = np.swapaxes(dc_p, 1, 2)[rows, keep]
    J[:, 7:9, 4:8] = np.swapaxes(dc_g, 1, 2)[rows, keep]
    J[:, 7:9, 8] = dc_2[rows, keep]
    dAp = pair.pinion_rotation(phi1, deriv=True)
    Fphi = np.zeros((n, 9))
    Fphi[:, 4:7] = np.einsum("nab,nb->na", dAp, rp)
    Fphi[:, 7:9] = np.cross(np.einsum("nab,nb->na", dAp, np_), Ng)[rows, keep]
    return F, J, Fphi


@dataclass
class KEResult:
    """Contact points along the path (one row per phi1): the unknowns x (n, 9) =
    (l_p, phi_p, theta_p, psi_p, l_g, phi_g, theta_g, psi_g, phi2') [mm, rad], phi1' [rad], the
    solve record (status WRONG_ROOT where the full normal cross product is not small), the
    contact point r_f and the two hob normals in S_f, Z and radius of the point in each member
    frame, and the condition number of the 9 x 9 Jacobian."""

    phi1: np.ndarray
    x: np.ndarray
    solve: SolveResult
    r_f: np.ndarray
    n_p: np.ndarray
    n_g: np.ndarray
    Z_p: np.ndarray
    Z_g: np.ndarray
    radius_p: np.ndarray
    radius_g: np.ndarray
    cond: np.ndarray
    #: set by :func:`physical_contact`: distinct tangencies found at each phi1' (same tooth pair,
    #: on the face), the spread of their phi2' [rad], the first-order normal gap [mm] of the kept
    #: one at the others (>= 0: no interference) and the phi2' of the continuation root [rad]
    n_tangencies: np.ndarray | None = None
    tangency_phi2_spread: np.ndarray | None = None
    tangency_min_gap: np.ndarray | None = None
    phi2_continuation: np.ndarray | None = None

    @property
    def phi2(self):
        return self.x[:, 8]

    @property
    def converged(self):
        return self.solve.status == Status.CONVERGED

    @property
    def status_name(self):
        return status_names(self.solve.status)

    def take(self, idx) -> "KEResult":
        s = self.solve
        return KEResult(self.phi1[idx], self.x[idx], SolveResult(s.x[idx], s.residual[idx], s.iterations[idx],
                        s.status[idx], None if s.condition is None else s.condition[idx]), *(getattr(self, f)[idx] for f in
                        ("r_f", "n_p", "n_g", "Z_p", "Z_g", "radius_p", "radius_g", "cond")),
                        *(None if getattr(self, f) is None else getattr(self, f)[idx] for f in _DIAG))


_DIAG = ("n_tangencies", "tangency_phi2_spread", "tangency_min_gap", "phi2_continuation")
_ROW_FIELDS = ("r_f", "n_p", "n_g", "Z_p", "Z_g", "radius_p", "radius_g", "cond")


def _drop(pair, x, phi1):
    Np = np.einsum("nab,nb->na", pair.pinion_rotation(phi1), _member(pair.pinion, x[:, :4])[2])
    return np.argmax(np.abs(Np), axis=1)


def _finish(pair: Pair, x, phi1, res: SolveResult, drop) -> KEResult:
    rp, _, np_, _, _, _ = _member(pair.pinion, x[:, 0:4])
    rg, _, ng, _, _, _ = _member(pair.gear, x[:, 4:8])
    Ap, Ag = pair.pinion_rotation(phi1), pair.gear_rotation(x[:, 8])
    Np = np.einsum("nab,nb->na", Ap, np_)
    Ng = np.einsum("nab,nb->na", Ag, ng)
    _, J, _ = _system(pair, x, phi1, drop)
    ok = np.all(np.isfinite(J), axis=(1, 2))
    cond = np.full(len(x), np.inf)
    if np.any(ok):
        s = np.linalg.svd(J[ok], compute_uv=False)
        cond[ok] = s[:, 0] / np.where(s[:, -1] > 0, s[:, -1], np.nan)
    status = res.status.copy()
    false_root = np.linalg.norm(np.cross(Np, Ng), axis=1) > 1e-9
    status[(status == Status.CONVERGED) & false_root] = int(Status.WRONG_ROOT)
    res = SolveResult(res.x, res.residual, res.iterations, status, res.condition)
    # member frames: S_p = the pinion's thesis frame (z kept by M_vp), S_g: z_g = z_f - dZ
    rpm = np.einsum("ab,nb->na", pair.pinion.placement, rp)
    rgm = np.einsum("ab,nb->na", pair.gear.placement, rg)
    return KEResult(np.asarray(phi1, float), x, res, np.einsum("nab,nb->na", Ap, rp), Np, Ng, rpm[:, 2],
                    rgm[:, 2], np.hypot(rpm[:, 0], rpm[:, 1]), np.hypot(rgm[:, 0], rgm[:, 1]), cond)


def solve_points(pair: Pair, phi1, x0, *, tol: float = 1e-11, maxiter: int = 30, max_halvings: int = 12) -> KEResult:
    """Solve the 9 x 9 TCA system at pinion angles phi1' (n,) [rad] from starts x0 (n, 9), all
    points at once (:func:`gearrep.solve.newton`, analytic Jacobian, Armijo backtracking with at
    most ``max_halvings`` halvings per step)."""
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    x0 = np.array(x0, float).reshape(len(phi1), 9)
    if not np.all(np.isfinite(x0)):
        raise ValueError("x0 must be finite")
    drop = _drop(pair, x0, phi1)

    def fun(x, idx):
        return _system(pair, x, phi1[idx], drop[idx], derivs=False)[0]

    def jac(x, idx):
        return _system(pair, x, phi1[idx], drop[idx])[1]

    res = newton(fun, x0, jac, tol=tol, maxiter=maxiter, max_halvings=max_halvings, rows=True)
    return _finish(pair, res.x, phi1, res, drop)


def predict(pair: Pair, x, phi1, phi1_new) -> np.ndarray:
    """First-order predictor along the path: x(phi1_new) ~ x + (dx/dphi1)(phi1_new - phi1),
    dx/dphi1 = -F_x^{-1} F_phi1 at the converged x (n, 9)."""
    x = np.atleast_2d(x)
    phi1 = np.broadcast_to(np.asarray(phi1, float), (len(x),))
    _, J, Fphi = _system(pair, x, phi1, _drop(pair, x, phi1))
    dx = -np.linalg.solve(J, Fphi[..., None])[..., 0]
    return x + dx * (np.asarray(phi1_new, float) - phi1)[:, None]


def ideal_start(pair: Pair, *, tol: float = 1e-11) -> KEResult:
    """Contact at phi1' = 0 of ``pair`` from a generic start: both members at mid-face (psi = 0)
    near the hob pitch line, (phi, theta) solved by each envelope, phi2' = 0."""
    l0 = l_pitch(pair.pinion.gear.hob)
    qp = pair.pinion.gear.solve(l0, 0.0).params[0]
    qg = pair.gear.gear.solve(l0, 0.0).params[0]
    return solve_points(pair, [0.0], np.r_[qp, qg, 0.0][None], tol=tol)


def l_pitch(hob: ZAHob) -> float:
    return (hob.pitch_radius_mm - hob.apex_radius_mm) / np.cos(hob.pressure_angle_rad)


def require(sol: KEResult, what: str):
    if not np.all(sol.converged):
        raise RuntimeError(f"{what}: TCA solve did not converge (status {list(sol.status_name)}, "
                           f"residual {sol.solve.residual})")


_START_CACHE: dict = {}  # ideal starts by (R_cp, R_cg0, tol, hob): shared by the Examples


def continue_to(R_cp_mm, R_cg_mm, assembly: Assembly, *, hob=None, steps: int = 4, tol=1e-11,
                R_gap_mm: float = 3.0) -> tuple[Pair, KEResult]:
    """Contact at phi1' = 0 of the pair (R_cp, R_cg, assembly) by continuation from the ideal
    pair: start at R_cg0 = max(R_cg, R_cp + R_gap) (a well-localised contact; R_cg = R_cp is an
    almost-line contact) with no assembly errors, then move R_cg and the errors linearly to
    their targets in ``steps`` warm-started solves; of the tangencies at the target, the physical
    one is returned (:func:`physical_contact`)."""
    if int(steps) != steps or steps < 1:
        raise ValueError(f"steps must be a positive integer, got {steps!r}")
    R0 = max(R_cg_mm, R_cp_mm + R_gap_mm)
    pair = make_pair(R_cp_mm, R0, None, hob)
    key = (float(R_cp_mm), float(R0), float(tol), pair.pinion.gear.hob)
    if key not in _START_CACHE:
        sol = ideal_start(pair, tol=tol)
        require(sol, f"ideal start R_cp={R_cp_mm}, R_cg={R0}")
        _START_CACHE[key] = sol
    sol = _START_CACHE[key]
    for t in np.linspace(0.0, 1.0, int(steps) + 1)[1:]:
        pair = make_pair(R_cp_mm, R0 + t * (R_cg_mm - R0), assembly.scaled(t), hob)
        sol = solve_points(pair, [0.0], sol.x, tol=tol)
        require(sol, f"continuation step t={t:.3g} to R_cg={R_cg_mm}, {assembly}")
    return pair, physical_contact(pair, sol, tol=tol)


def trace_path(pair: Pair, start: KEResult, phi1, *, tol: float = 1e-11, max_step_rad: float = np.radians(4.0),
               branch_tol: float = 0.1):
    """Contact points at all phi1' (n,) [rad] from a converged point ``start`` (one row): the
    predictor from ``start`` gives every point's start and all are solved at once. A root farther
    than ``branch_tol`` (mm or rad, any unknown) from its predicted start is another branch (e.g.
    a neighbouring tooth; the predictor error is < 0.01 over +-28 deg) and gets WRONG_ROOT; such
    points and unconverged ones are re-solved by marching from ``start`` in steps of at most
    ``max_step_rad`` (each step checked the same way)."""
    phi1 = np.atleast_1d(np.asarray(phi1, float))
    x0 = predict(pair, np.repeat(start.x, len(phi1), 0), np.repeat(start.phi1, len(phi1)), phi1)
    sol = solve_points(pair, phi1, x0, tol=tol)
    far = np.max(np.abs(sol.x - x0), axis=1) > branch_tol
    sol.solve.status[sol.converged & far] = int(Status.WRONG_ROOT)
    for i in np.flatnonzero(~sol.converged):
        n = max(1, int(np.ceil(abs(phi1[i] - start.phi1[0]) / max_step_rad)))
        cur = start
        for a in np.linspace(start.phi1[0], phi1[i], n + 1)[1:]:
            xp = predict(pair, cur.x, cur.phi1, [a])
            cur = solve_points(pair, [a], xp, tol=tol)
            if cur.converged[0] and np.max(np.abs(cur.x - xp)) > branch_tol:
                cur.solve.status[0] = int(Status.WRONG_ROOT)
            if not cur.converged[0]:
                break
        for f in _ROW_FIELDS:
            getattr(sol, f)[i] = getattr(cur, f)[0]
        sol.x[i] = cur.x[0]
        for f in ("residual", "iterations", "status"):
            getattr(sol.solve, f)[i] = getattr(cur.solve, f)[0]
    return sol



def _pinion_outward(pair: Pair, sol: KEResult) -> np.ndarray:
    """Unit normal of the pinion flank in S_f pointing out of its tooth (n, 3). The hob normal
    keeps its side of the flank everywhere, so its outward sign is taken once, at the pitch
    point of the mid-face section (:meth:`GeneratedGear.outward` there; that test by the polar
    angle fails past the tip, where the extended flank crosses the tooth's centre line)."""
    q0 = pair.pinion.gear.solve(l_pitch(pair.pinion.gear.hob), 0.0).params[0]
    r0, _, n0, _, _, _ = _member(pair.pinion, np.asarray(q0, float)[None])
    R = pair.pinion.gear.to_thesis
    s = float(np.sign(np.sum(GeneratedGear.outward(r0 @ R.T, n0 @ R.T) * (n0 @ R.T))))
    _, _, n, _, _, _ = _member(pair.pinion, sol.x[:, :4])
    return s * np.einsum("nab,nb->na", pair.pinion_rotation(sol.phi1), n)


def physical_contact(pair: Pair, sol: KEResult, *, n_starts: int = 9, tol: float = 1e-11, maxiter: int = 12,
                     max_halvings: int = 3, same_tooth_rad: float = 1e-3, distinct_mm: float = 1e-3) -> KEResult:
    """The physical contact among all tangencies of the 9 x 9 system at each phi1' of ``sol``.

    Where the lengthwise curvatures almost agree (110/110: an almost-line contact) the system has
    several isolated roots at the same phi1' (e.g. Z_p = 0 and +-1.0967 mm for the ideal 110/110
    pair at phi1' = 0), each a genuine tangency but with slightly different phi2'. The contact is
    the tangency the gear reaches first, i.e. the one at which the flanks do not interfere at any
    other tangency. With the gear at the phi2' of root A, the normal gap at root B is, to first
    order in the (tiny) difference, g(B|A) = (phi2'_A - phi2'_B) s_B,
    s_B = (e_z x (r_B - O_g)) . n_p,out(B) (rigid turn of the gear about its axis, measured along
    the pinion's outward normal; < 0 = interference). The kept root maximises min_B g(B|A), which
    is >= 0 (up to round-off) when s_B has one sign. In the frames of this module a positive turn
    of the gear moves its flank into the pinion tooth (s_B < 0), so the physical contact is the
    tangency with the SMALLEST phi2'. Ties (phi2' equal to round-off, e.g. the symmetric pair)
    keep the root nearest the continuation root in Z_p, then the larger Z_p.

    Search: from the continuation root x, ``n_starts`` starts spread across the face
    (Z_p = -0.45..0.45 of the face width, Table 5.1) along the direction d with d_psi_p = 1 that
    minimises |F_x d| (the almost-null direction of the Jacobian, i.e. along the contact line),
    all solved at once. Converged roots of the same tooth pair (|phi2' - phi2'_0| < same_tooth_rad)
    whose contact lies on both faces count; roots closer than ``distinct_mm`` in (Z_p, l_p) are one.
    Starts that do not converge are discarded (they only search); the continuation root is always
    a candidate, so every returned row is a converged, verified tangency. The result carries
    n_tangencies, tangency_phi2_spread [rad], tangency_min_gap [mm] and phi2_continuation [rad]."""
    if int(n_starts) != n_starts or n_starts < 2:
        raise ValueError(f"n_starts must be an integer >= 2, got {n_starts!r}")
    m = int(n_starts)
    cand, keep = _face_search(pair, sol, m, tol, maxiter, max_halvings, same_tooth_rad)
    s_all = _turn_gap_factor(pair, cand)
    s_own = _turn_gap_factor(pair, sol)
    out = copy.deepcopy(sol)
    n = len(sol.phi1)
    n_tan = np.ones(n, int)
    spread, min_gap = np.zeros(n), np.zeros(n)
    for i in range(n):
        idx = i * m + np.flatnonzero(keep[i * m:(i + 1) * m])
        if not sol.converged[i]:
            n_tan[i] = 0
            continue
        j, n_tan[i], spread[i], min_gap[i] = _choose_tangency(sol, cand, i, idx, s_own[i], s_all[idx], distinct_mm)
        if j >= 0:
            _copy_row(out, i, cand, j)
    out.n_tangencies, out.tangency_phi2_spread, out.tangency_min_gap = n_tan, spread, min_gap
    out.phi2_continuation = sol.phi2.copy()
    return out


def _face_search(pair: Pair, sol: KEResult, m: int, tol, maxiter, max_halvings, same_tooth_rad):
    """Roots from ``m`` starts per row spread across the face along the almost-null direction of
    the Jacobian (d_psi_p = 1); returns the candidates (n * m rows) and which of them count."""
    n = len(sol.phi1)
    _, J, _ = _system(pair, sol.x, sol.phi1, _drop(pair, sol.x, sol.phi1))
    others = np.r_[0:3, 4:9]
    d = np.zeros((n, 9))
    d[:, 3] = 1.0
    d[:, others] = -np.einsum("nij,nj->ni", np.linalg.pinv(J[:, :, others]), J[:, :, 3])
    Tp = _member(pair.pinion, sol.x[:, 0:4])[1]
    dZ = np.einsum("nq,nq->n", Tp[:, :, 2], d[:, 0:4])  # dZ_p / dpsi_p along d (placement keeps z)
    z_t = np.linspace(-0.45, 0.45, m) * FACE_WIDTH_MM
    t = (z_t[None, :] - sol.Z_p[:, None]) / np.where(np.abs(dZ) > 1e-12, dZ, np.nan)[:, None]
    x0 = np.repeat(sol.x, m, 0) + t.reshape(-1, 1) * np.repeat(d, m, 0)
    ok0 = np.all(np.isfinite(x0), axis=1)
    x0[~ok0] = np.repeat(sol.x, m, 0)[~ok0]
    phi1 = np.repeat(sol.phi1, m)
    cand = solve_points(pair, phi1, x0, tol=tol, maxiter=maxiter, max_halvings=max_halvings)
    keep = (ok0 & cand.converged & (np.abs(cand.phi2 - np.repeat(sol.phi2, m)) < same_tooth_rad)
            & (np.abs(cand.Z_p) <= FACE_WIDTH_MM / 2) & (np.abs(cand.Z_g) <= FACE_WIDTH_MM / 2))
    return cand, keep


def _turn_gap_factor(pair: Pair, sol: KEResult) -> np.ndarray:
    """s = (e_z x (r - O_g)) . n_p,out: normal gap per unit turn of the gear about its axis."""
    return np.sum(np.cross([0.0, 0.0, 1.0], sol.r_f - pair.gear_origin) * _pinion_outward(pair, sol), -1)


def _choose_tangency(sol: KEResult, cand: KEResult, i: int, idx, s_own, s_idx, distinct_mm):
    """(candidate row kept or -1 for the continuation root, number of distinct tangencies,
    their phi2' spread [rad], the kept one's smallest first-order gap [mm]) at row i."""
    zs = np.r_[sol.Z_p[i], cand.Z_p[idx]]
    ls = np.r_[sol.x[i, 0], cand.x[idx, 0]]
    p2 = np.r_[sol.phi2[i], cand.phi2[idx]]
    sg = np.r_[s_own, s_idx]
    src = np.r_[-1, idx]
    uniq = []  # distinct tangencies, the continuation root first
    for k in range(len(zs)):
        if all(np.hypot(zs[k] - zs[u], ls[k] - ls[u]) > distinct_mm for u in uniq):
            uniq.append(k)
    uniq = np.array(uniq)
    G = (p2[uniq][:, None] - p2[uniq][None, :]) * sg[uniq][None, :]  # G[A, B] = g(B | A)
    score = G.min(axis=1)
    best = score >= score.max() - 1e-12
    order = np.lexsort((-zs[uniq], np.round(np.abs(zs[uniq] - sol.Z_p[i]), 6), ~best))
    a = order[0]
    return int(src[uniq[a]]), len(uniq), np.ptp(p2[uniq]), score[a]


def _copy_row(out: KEResult, i: int, src: KEResult, j: int) -> None:
    """Row i of ``out`` replaced by row j of ``src`` (unknowns, geometry and solve record)."""
    out.x[i] = src.x[j]
    for f in _ROW_FIELDS:
        getattr(out, f)[i] = getattr(src, f)[j]
    for f in ("x", "residual", "iterations", "status"):
        getattr(out.solve, f)[i] = getattr(src.solve, f)[j]


def ke_table(sol: KEResult, ratio: float) -> pd.DataFrame:
    """Table 5.x columns from a path that contains phi1' = 0: phi2' and KE re-zeroed at
    phi1' = 0 (eq 5.12 with the tables' normalisation), KE in arc-seconds."""
    i0 = np.flatnonzero(np.abs(sol.phi1) < 1e-12)
    if i0.size != 1:
        raise ValueError("the path must contain phi1' = 0 exactly once (the tables' zero of KE)")
    i0 = int(i0[0])
    ke = (sol.phi2 - sol.phi2[i0]) - ratio * (sol.phi1 - sol.phi1[i0])
    return pd.DataFrame({
        "phi1_deg": np.degrees(sol.phi1),
        "phi2_deg": np.degrees(ratio * sol.phi1 + ke),
        "l_p_mm": sol.x[:, 0], "Z_p_mm": sol.Z_p, "l_g_mm": sol.x[:, 4], "Z_g_mm": sol.Z_g,
        "KE_arcsec": ke / ARCSEC,
        "psi_p_rad": sol.x[:, 3], "psi_g_rad": sol.x[:, 7],
        "radius_p_mm": sol.radius_p, "radius_g_mm": sol.radius_g,
        "status": sol.status_name, "residual": sol.solve.residual, "iterations": sol.solve.iterations,
        "jacobian_cond": sol.cond,
        **({} if sol.n_tangencies is None else {
            "n_tangencies": sol.n_tangencies,
            "tangency_phi2_spread_arcsec": sol.tangency_phi2_spread / ARCSEC,
            "tangency_min_gap_mm": sol.tangency_min_gap,
            "phi2_continuation_root_minus_phi2_arcsec": (sol.phi2_continuation - sol.phi2) / ARCSEC}),
    })



