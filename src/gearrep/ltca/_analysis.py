"""Loaded tooth contact analysis of a pair over mesh positions: load distribution, loaded TE,
pressure and mesh stiffness (assembled from :mod:`._separation`, :mod:`._compliance` and
:mod:`._distribution`; the model is described in :mod:`gearrep.ltca`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..inputs import check_finite, check_integer
from ..solve import Status
from ..tca import GearPair
from . import _compliance as compliance
from ._compliance import STEEL, Material
from ._distribution import solve_checked
from ._families import members, pitch_phi1
from ._nodes import Nodes
from ._separation import EDGE_KINDS, Separations, initial_separations

__all__ = ["LoadedContact", "CycleSummary", "PressureMap", "cycle_positions", "loaded_contact"]

_DRIVING = ("pinion", "gear")


def cycle_positions(pair: GearPair, n_positions: int = 41) -> np.ndarray:
    """Member-1 angles [rad] of one meshing cycle (one angular pitch 2 pi / N1, both ends included)
    centred on the position where tooth pair 0's mid-face section is at the pitch point (the middle
    position for odd ``n_positions``).

    Parameters
    ----------
    pair : gearrep.tca.GearPair
        The pair.
    n_positions : int, optional
        Positions, >= 2.

    Returns
    -------
    numpy.ndarray
        Angles [rad].

    Raises
    ------
    ValueError
        If ``n_positions`` is not an integer >= 2 (or the flanks are not of a supported family).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.ltca import cycle_positions
    >>> from gearrep.surfaces.involute import InvoluteGearData, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2), 23, 41, g1.r_p + g2.r_p)
    >>> phi1 = cycle_positions(pair, 3)
    >>> round(float(phi1[2] - phi1[0]), 12) == round(2 * math.pi / 23, 12)  # one angular pitch [rad]
    True
    """
    n = check_integer("n_positions", n_positions, 2)
    m1, _ = members(pair)
    return pitch_phi1(pair, m1) + (2.0 * np.pi / pair.n1) * np.linspace(-0.5, 0.5, n)


@dataclass(frozen=True)
class PressureMap:
    """Hertz pressure over the contact nodes of one position: ``pressure_MPa`` (n_pairs, n_nodes,
    n_across) at the nodes' axial positions ``z_mm`` (n_pairs, n_nodes) and offsets ``across_mm``
    (n_across,) across the contact line from each node's contact point ``position_mm`` (n_pairs,
    n_nodes, 3; fixed frame), whose across direction is ``across`` (n_pairs, n_nodes, 3); ``kind``
    the node's contact kind (:data:`gearrep.ltca.KINDS`, 0 none; NaN pressure there).

    Parameters
    ----------
    pairs : numpy.ndarray
        (n_pairs,) tooth-pair offsets.
    z_mm : numpy.ndarray
        (n_pairs, n_nodes) node positions [mm].
    across_mm : numpy.ndarray
        (n_across,) offsets across the line [mm].
    position_mm : numpy.ndarray
        (n_pairs, n_nodes, 3) contact points [mm].
    across : numpy.ndarray
        (n_pairs, n_nodes, 3) across directions.
    kind : numpy.ndarray
        (n_pairs, n_nodes) contact kinds.
    pressure_MPa : numpy.ndarray
        (n_pairs, n_nodes, n_across) [MPa].

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.ltca import cycle_positions, loaded_contact
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> lc = loaded_contact(pair, 100.0, cycle_positions(pair, 3), n_nodes=11)  # N m on the pinion
    >>> pm = lc.pressure_map(1, n_across=5)
    >>> pm.pressure_MPa.shape, bool(np.isclose(np.nanmax(pm.pressure_MPa), lc.max_pressure_MPa[1]))
    ((9, 11, 5), True)
    """

    pairs: np.ndarray
    z_mm: np.ndarray
    across_mm: np.ndarray
    position_mm: np.ndarray
    across: np.ndarray
    kind: np.ndarray
    pressure_MPa: np.ndarray


@dataclass(frozen=True)
class CycleSummary:
    """One row of cycle results (units in the names); ``n_failed``: positions not converged;
    ``max_contact_pressure_MPa``: on the flanks (tip edges apart); ``tip_edge_*``: positions where
    a tip edge carries load, the largest share of the normal load it carries and its Hertz pressure
    (for the stated edge radius); ``face_end_contact_positions``: positions where the load reaches
    a face end (of member 1, or member 2's inside member 1's face).

    Parameters
    ----------
    torque_Nm : float
        [N m].
    normal_load_N : float
        Mean normal load [N].
    lte_peak_to_peak_urad, lte_peak_to_peak_um : float
        Peak-to-peak loaded TE [urad, um].
    mesh_stiffness_mean_N_per_mm_um : float
        Mean mesh stiffness [N/(mm um)].
    single_pair_stiffness_max_N_per_mm_um : float
        Largest stiffness where one pair is loaded [N/(mm um)].
    max_contact_pressure_MPa : float
        [MPa].
    load_share_max, load_share_min : float
        Largest and smallest share of the most loaded pair [1].
    tip_edge_contact_positions : int
        Positions with a loaded tip edge.
    tip_edge_load_share_max : float
        [1].
    max_tip_edge_pressure_MPa : float
        [MPa].
    face_end_contact_positions : int
        Positions where the load reaches a face end.
    n_positions, n_failed : int
        Positions, and those not converged.

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca import cycle_positions, loaded_contact
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> s = loaded_contact(pair, 100.0, cycle_positions(pair, 3), n_nodes=11).summary()  # N m
    >>> s.n_positions, s.n_failed, s.load_share_max, s.tip_edge_contact_positions  # one pair alone at the pitch point
    (3, 0, 1.0, 0)
    """

    torque_Nm: float
    normal_load_N: float
    lte_peak_to_peak_urad: float
    lte_peak_to_peak_um: float
    mesh_stiffness_mean_N_per_mm_um: float
    single_pair_stiffness_max_N_per_mm_um: float
    max_contact_pressure_MPa: float
    load_share_max: float
    load_share_min: float
    tip_edge_contact_positions: int
    tip_edge_load_share_max: float
    max_tip_edge_pressure_MPa: float
    face_end_contact_positions: int
    n_positions: int
    n_failed: int


@dataclass(frozen=True)
class LoadedContact:
    """Loaded contact of a pair at mesh positions (arrays over positions unless noted).

    Parameters
    ----------
    torque_Nm : float
        Torque on the driving member [N m].
    driving : {"pinion", "gear"}
        The driving member.
    face_width_mm : float
        [mm].
    separations : Separations
        The geometry of the last refinement.
    phi1_rad : numpy.ndarray
        Member-1 angles [rad].
    te_unloaded_rad, te_loaded_rad : numpy.ndarray
        Rigid TCA and loaded TE [rad].
    lte_urad, lte_um : numpy.ndarray
        Loaded TE in micro-radians of member 2 and in micrometres along the transverse line of
        action (r_b2 TE).
    normal_load_N : numpy.ndarray
        Sum of the loads [N].
    pair_load_N : numpy.ndarray
        (n_pos, n_pairs) per tooth pair [N].
    pairs_loaded : numpy.ndarray
        Tooth pairs carrying load.
    max_pressure_MPa : numpy.ndarray
        On the flanks, tip edges apart [MPa].
    tip_edge_load_N, tip_edge_pressure_MPa : numpy.ndarray
        Load carried at tip edges [N] and its largest Hertz pressure [MPa] for the edge radius
        ``separations.edge_radius_mm`` (a sharp edge has none).
    face_end_load_N : numpy.ndarray
        Load carried by nodes at a face end [N].
    mesh_stiffness_N_per_um, mesh_stiffness_N_per_mm_um : numpy.ndarray
        Transverse base tangential force / elastic transverse approach r_b2 (TE_unloaded -
        TE_loaded) [N/um], and per face width [N/(mm um)].
    moment_residual : numpy.ndarray
        Relative torque balance.
    iterations : numpy.ndarray
        Fixed-point iterations.
    status : numpy.ndarray
        :class:`gearrep.solve.Status`; NaN results where not CONVERGED.
    node_load_N, pressure_MPa, half_width_mm : numpy.ndarray
        Per node (n_pos, n_pairs, n_nodes): load [N], peak of the Hertz strip [MPa], half-width [mm].
    passes : int
        Node placements (1 + refinements).

    Examples
    --------
    >>> import math
    >>> from gearrep.ltca import loaded_contact
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> lc = loaded_contact(pair, 100.0, [0.0], n_nodes=11)  # N m, rad
    >>> lc.converged.tolist(), bool(lc.te_loaded_rad[0] < lc.te_unloaded_rad[0])  # the load holds member 2 back
    ([True], True)
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
    tip_edge_load_N: np.ndarray
    tip_edge_pressure_MPa: np.ndarray
    face_end_load_N: np.ndarray
    mesh_stiffness_N_per_um: np.ndarray
    mesh_stiffness_N_per_mm_um: np.ndarray
    moment_residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray
    node_load_N: np.ndarray
    pressure_MPa: np.ndarray
    half_width_mm: np.ndarray
    passes: int

    @property
    def converged(self) -> np.ndarray:
        """(n_pos,) bool, status CONVERGED."""
        return self.status == Status.CONVERGED

    def summary(self) -> CycleSummary:
        """Cycle results over the converged positions (NaN if none).

        Returns
        -------
        CycleSummary
            One row of cycle results.
        """
        ok = self.converged
        nan = float("nan")

        def ext(a, f):
            a = np.asarray(a)[ok]
            return float(f(a)) if a.size else nan

        with np.errstate(invalid="ignore", divide="ignore"):
            share = self.pair_load_N / self.normal_load_N[:, None]
            edge_share = self.tip_edge_load_N / self.normal_load_N
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
            tip_edge_contact_positions=int(np.sum(ok & (self.tip_edge_load_N > 0))),
            tip_edge_load_share_max=ext(edge_share, np.max),
            max_tip_edge_pressure_MPa=ext(np.nan_to_num(self.tip_edge_pressure_MPa), np.max),
            face_end_contact_positions=int(np.sum(ok & (self.face_end_load_N > 0))),
            n_positions=int(ok.size),
            n_failed=int(np.sum(~ok)),
        )

    def pressure_map(self, position: int, n_across: int = 21) -> PressureMap:
        """Semi-elliptic Hertz pressure across every loaded node of position ``position`` (index).

        Parameters
        ----------
        position : int
            Index of the position.
        n_across : int, optional
            Points across the contact line, >= 3.

        Returns
        -------
        PressureMap
            The pressures [MPa].

        Raises
        ------
        ValueError
            If ``n_across`` is not an integer >= 3.
        """
        i = int(position)
        n = check_integer("n_across", n_across, 3)
        b = self.half_width_mm[i]
        bmax = float(np.nanmax(b)) if np.any(b > 0) else 0.0
        x = np.linspace(-bmax, bmax, n)
        with np.errstate(invalid="ignore", divide="ignore"):
            q = 1.0 - (x / b[..., None]) ** 2
            p = np.where(q > 0, self.pressure_MPa[i][..., None] * np.sqrt(np.maximum(q, 0.0)), 0.0)
        sep = self.separations
        p = np.where(sep.in_contact[i][..., None], p, np.nan)
        pos = sep.contacts.position.reshape(sep.shape + (3,))[i]
        return PressureMap(sep.pairs, sep.z_mm[i], x, pos, sep.across[i], sep.kind[i], p)


def _check_inputs(pair, torque_Nm, driving, materials, tol, maxiter, bore_radius_mm):
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
    if np.ndim(bore_radius_mm) != 1 or len(bore_radius_mm) != 2:
        raise ValueError(
            f"bore_radius_mm must be a pair (member 1, member 2) of radii [mm] or None, got {bore_radius_mm!r}"
        )
    return T, materials


def _one_position(nodes: Nodes, rows, groups, gap, arm, moment, tol, maxiter, guess=None, history: int = 3):
    """Loads of one position by fixed-point iteration on the secant compliance, from the loads
    ``guess`` (e.g. the previous position's; default an even share); returns (ContactLoads,
    iterations, status).

    The map from the loads at which the compliance is evaluated to the loads of the contact problem
    it gives is iterated with Anderson acceleration over the last ``history`` steps (Walker & Ni,
    SIAM J. Numer. Anal. 49 (2011) 1715-1735; 0: plain iteration); it converges when two successive
    contact solutions differ by less than ``tol`` of the normal load. Every iterate is a solution of
    the contact problem, so the loads balance the torque whatever the iteration count."""
    F_ref = moment / float(np.sum(arm))  # an even share: the first linearisation point
    F = np.full(rows.size, F_ref) if guess is None else guess
    x = np.where(F > 0, F, F_ref)
    working = None if guess is None or not np.any(guess > 0) else np.flatnonzero(guess > 0)
    status = int(Status.NOT_CONVERGED)
    sol = None
    it = 0
    block = nodes.prepare(rows, groups) if nodes.coupling else None
    xs, gs = [], []
    best = np.inf
    for it in range(1, maxiter + 1):
        c = nodes.compliance(rows, x, groups, block)
        if not np.all(np.isfinite(c)) or np.any((np.diag(c) if c.ndim == 2 else c) <= 0):
            raise ValueError(
                "the nodes' compliance is not finite and positive (a contact with no defined curvature or depth)"
            )
        sol = solve_checked(c, gap, arm, moment, working=working)
        if sol.status != Status.CONVERGED:
            return sol, it, sol.status
        change = float(np.max(np.abs(sol.loads_N - F)))
        F = sol.loads_N
        working = np.flatnonzero(F > 0)
        if change <= tol * float(np.sum(F)):
            status = int(Status.CONVERGED)
            break
        # an unloaded node keeps the compliance of its last load: linearised at an even share again
        # it would re-enter and leave the contact in turn
        g = np.where(F > 0, F, x)
        if change > best:  # not contracting (e.g. the contact set changed): restart the history
            xs, gs = [], []
        best = min(best, change)
        xs.append(x)
        gs.append(g)
        xs, gs = xs[-(history + 1) :], gs[-(history + 1) :]
        x = g
        if len(xs) > 1:
            f = np.array(gs) - np.array(xs)  # residuals of the kept steps
            dF, dG = np.diff(f, axis=0).T, np.diff(np.array(gs), axis=0).T
            gamma = np.linalg.lstsq(dF, f[-1], rcond=None)[0]
            x = g - dG @ gamma
            x = np.where(x > 0, x, g)
    return sol, it, status


def _solve(pair, sep: Separations, nodes: Nodes, T, driving, tol, maxiter):
    """Loads at every position of ``sep``; returns (loads (n_pos, n_pairs n_nodes), results dict,
    iterations, status)."""
    shape = sep.shape
    n_pos = shape[0]
    moment = 1000.0 * T  # N mm
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    arm_all = sep.sense * (sep.arm1_mm if driving == "pinion" else sep.arm2_mm).reshape(n_pos, -1)
    te_factor = sep.sense * (pair.ratio if driving == "pinion" else 1.0)
    F_bt = moment / float(g1.r_b if driving == "pinion" else g2.r_b)
    out = {k: np.full(n_pos, np.nan) for k in ("te_loaded", "residual", "k_mesh")}
    loads = np.zeros((n_pos, shape[1] * shape[2]))
    its = np.zeros(n_pos, dtype=int)
    status = np.full(n_pos, int(Status.OFF_FLANK), dtype=int)
    group_of = np.repeat(np.arange(shape[1]), shape[2])
    for i in range(n_pos):
        cand = sep.in_contact[i].ravel()
        rows_local = np.flatnonzero(cand)
        if rows_local.size == 0:
            continue
        if np.any(sep.expected[i] & ~sep.in_contact[i]):
            status[i] = int(Status.NOT_CONVERGED)  # a section expected on the flanks was not found
            continue
        rows = i * cand.size + rows_local
        guess = None  # the previous position's loads, where its nodes are these (the same windows)
        same = i and status[i - 1] == Status.CONVERGED and np.array_equal(sep.z_mm[i], sep.z_mm[i - 1])
        if same and np.any(loads[i - 1, rows_local] > 0):
            guess = loads[i - 1, rows_local]
        sol, its[i], status[i] = _one_position(
            nodes,
            rows,
            group_of[rows_local],
            sep.gap_mm[i].ravel()[rows_local],
            arm_all[i, rows_local],
            moment,
            tol,
            maxiter,
            guess,
        )
        if status[i] != Status.CONVERGED:
            continue
        loads[i, rows_local] = sol.loads_N
        out["te_loaded"][i] = sep.te_rigid_rad[i] - te_factor * sol.rotation
        out["residual"][i] = sol.moment_residual
        approach = sep.sense * (sep.te_rigid_rad[i] - out["te_loaded"][i]) * float(g2.r_b) * 1000.0  # um
        out["k_mesh"][i] = F_bt / approach
    return loads, out, its, status


#: a loaded span narrower than this fraction of the face is solved again on nodes over it
REFINE_BELOW = 0.7
#: a node counts as loaded for the node placement above this fraction of its position's largest
#: node load (a load at rounding level must not move the nodes from one machine to another)
LOADED_RTOL = 1e-9


def _loaded(L, status):
    """(n_pos, n_pairs, n_nodes) mask of the nodes loaded above LOADED_RTOL at converged positions."""
    top = np.max(np.where(np.isfinite(L), L, 0.0), axis=(1, 2), keepdims=True)
    return (L > LOADED_RTOL * top) & (status == Status.CONVERGED)[:, None, None]


def _windows(sep: Separations, loads, status, m1):
    """Face windows (n_pos, n_pairs, 2) around each tooth pair's loaded nodes (one node spacing
    beyond the outermost loaded nodes) where the loaded span is narrower than REFINE_BELOW of the
    face, the present node range elsewhere; and that mask of narrow windows."""
    lo, hi = m1.z_lo, m1.z_hi
    shape = sep.shape
    loaded = _loaded(loads.reshape(shape), status)
    z = sep.z_mm
    step = np.diff(z, axis=-1)[..., :1]
    with np.errstate(invalid="ignore"):
        za = np.min(np.where(loaded, z, np.inf), axis=-1, keepdims=True) - step
        zb = np.max(np.where(loaded, z, -np.inf), axis=-1, keepdims=True) + step
    za, zb = np.maximum(za, z[..., :1]), np.minimum(zb, z[..., -1:])
    narrow = np.any(loaded, axis=-1, keepdims=True) & ((zb - za) < REFINE_BELOW * (hi - lo))
    w = np.concatenate([np.where(narrow, za, z[..., :1]), np.where(narrow, zb, z[..., -1:])], axis=-1)
    return w, narrow[..., 0]


def _reaches_window_end(sep: Separations, loads, status, m1):
    """True where a tooth pair's load reaches a window end that is not a face end (the window was
    too narrow)."""
    loaded = _loaded(loads.reshape(sep.shape), status)
    z = sep.z_mm
    inner_lo = z[..., 0] > m1.z_lo + 1e-9 * (m1.z_hi - m1.z_lo)
    inner_hi = z[..., -1] < m1.z_hi - 1e-9 * (m1.z_hi - m1.z_lo)
    return (loaded[..., 0] & inner_lo) | (loaded[..., -1] & inner_hi)


def loaded_contact(
    pair: GearPair,
    torque_Nm: float,
    phi1=None,
    *,
    driving: str = "pinion",
    materials=STEEL,
    n_nodes: int = 21,
    refine: bool = True,
    coupling: bool = True,
    tooth_bending: bool = True,
    edge_radius_mm=None,
    bore_radius_mm=(None, None),
    pairs=None,
    tol: float = 1e-10,
    maxiter: int = 100,
) -> LoadedContact:
    """Loaded tooth contact analysis of ``pair`` under ``torque_Nm`` [N m] on the driving member at
    member-1 angles ``phi1`` [rad] (default :func:`cycle_positions`, 41 positions).

    ``driving``: "pinion" (member 1) or "gear"; ``materials``: one :class:`Material` for both
    members or (member 1, member 2), default steel; ``n_nodes``: nodes along the face (over the
    whole face, then, with ``refine``, over each tooth pair's loaded span where it is narrower than
    REFINE_BELOW of the face: the localized contact gets the same number of nodes as a line);
    ``coupling``: the half-space coupling of the nodes' contact deformation (False: Weber's approach
    per node, independent strips); ``tooth_bending``: False leaves the tooth compliance out (the
    rigid-tooth limit, Hertz's contact); ``edge_radius_mm``: tip-edge radius (default 0.1 module);
    ``bore_radius_mm``: (member 1, member 2) gear-body bores for the foundation term (None: half
    the root radius); ``pairs``: tooth-pair offsets (default -4 ... 4); ``tol``: relative load
    change that ends the fixed-point iteration; ``maxiter`` its limit. The flanks must be of a
    family of :data:`gearrep.ltca.SUPPORTED` (ValueError otherwise).

    Parameters
    ----------
    pair : gearrep.tca.GearPair
        The pair.
    torque_Nm : float
        Torque on the driving member [N m].
    phi1 : array_like, optional
        Member-1 angles [rad].
    driving : {"pinion", "gear"}, optional
        The driving member.
    materials : Material or (Material, Material), optional
        Of both members, or of each.
    n_nodes : int, optional
        Nodes along the face.
    refine : bool, optional
        Place the nodes again over a narrow loaded span.
    coupling : bool, optional
        The half-space coupling of the nodes.
    tooth_bending : bool, optional
        Include the tooth compliance.
    edge_radius_mm : float, optional
        Tip-edge radius [mm].
    bore_radius_mm : (float or None, float or None), optional
        Gear-body bores [mm].
    pairs : array_like of int, optional
        Tooth-pair offsets.
    tol : float, optional
        Relative load change that ends the fixed-point iteration.
    maxiter : int, optional
        Its limit.

    Returns
    -------
    LoadedContact
        The results per position.

    Raises
    ------
    ValueError
        Before any solve: a pair of an unsupported family, a torque that is not > 0, an unknown
        driving member, a bad material, bore or solver setting.

    Examples
    --------
    A spur pair under 100 N m: the normal load is the torque over the pinion's base radius, carried
    by two tooth pairs at the ends of the cycle and one at the pitch point:

    >>> import math
    >>> from gearrep.ltca import cycle_positions, loaded_contact
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> lc = loaded_contact(pair, 100.0, cycle_positions(pair, 3), n_nodes=11)  # N m
    >>> lc.status.tolist(), lc.pairs_loaded.tolist(), round(float(100e3 / g1.r_b), 1)  # N
    ([0, 0, 0], [2, 1, 2], 3084.6)
    >>> [round(float(f), 1) for f in lc.normal_load_N]  # N
    [3084.6, 3084.6, 3084.6]
    """
    T, materials = _check_inputs(pair, torque_Nm, driving, materials, tol, maxiter, bore_radius_mm)
    m1, m2 = members(pair)
    phi1 = cycle_positions(pair) if phi1 is None else phi1
    bore = tuple(bore_radius_mm)
    kw = dict(n_nodes=n_nodes, pairs=pairs, edge_radius_mm=edge_radius_mm)

    def run(windows=None, previous=None, keep=None):
        sep = initial_separations(pair, phi1, windows=windows, previous=previous, keep=keep, **kw)
        nodes = Nodes(sep, m1, m2, materials, bore, tooth_bending=tooth_bending, coupling=coupling)
        return sep, nodes, _solve(pair, sep, nodes, T, driving, tol, maxiter)

    sep, nodes, (loads, out, its, status) = run()
    passes = 1
    if refine:
        windows, narrow = _windows(sep, loads, status, m1)
        while np.any(narrow) and passes < 4:
            sep, nodes, (loads, out, its, status) = run(windows, sep, ~narrow)
            passes += 1
            wide = _reaches_window_end(sep, loads, status, m1)
            if not np.any(wide):
                break
            step = np.diff(sep.z_mm, axis=-1)[..., :1] * (sep.z_mm.shape[-1] - 1) / 4.0
            grown = np.concatenate([windows[..., :1] - step, windows[..., 1:] + step], axis=-1)
            grown = np.clip(grown, m1.z_lo, m1.z_hi)
            windows = np.where(wide[..., None], grown, windows)
            narrow = wide
    return _record(pair, T, driving, sep, nodes, loads, out, its, status, passes, m1)


def _record(pair, T, driving, sep, nodes: Nodes, loads, out, its, status, passes, m1) -> LoadedContact:
    shape = sep.shape
    ok = status == Status.CONVERGED
    node_load = np.where(ok[:, None], loads, np.nan).reshape(shape)
    L = nodes.L.reshape(shape)
    w = node_load / L
    k = np.where(sep.in_contact, sep.k_rel_per_mm, 1.0)
    p0 = np.where(sep.in_contact, compliance.line_contact_pressure_MPa(np.nan_to_num(w), k, nodes.Estar), np.nan)
    b = np.where(sep.in_contact, compliance.contact_half_width_mm(np.nan_to_num(w), k, nodes.Estar), np.nan)
    p0 = np.where(ok[:, None, None], p0, np.nan)
    b = np.where(ok[:, None, None], b, np.nan)
    pair_load = np.where(ok[:, None], np.nansum(node_load, axis=2), np.nan)
    normal = np.where(ok, np.nansum(pair_load, axis=1), np.nan)
    loaded_pairs = np.where(ok, np.sum(pair_load > 0, axis=1), 0)
    tip = np.isin(sep.kind, EDGE_KINDS)
    span = m1.z_hi - m1.z_lo
    at_end = (sep.kind == 4) | (np.abs(sep.z_mm - m1.z_lo) < 1e-9 * span) | (np.abs(sep.z_mm - m1.z_hi) < 1e-9 * span)
    loaded = np.nan_to_num(node_load) > 0

    def total(mask):
        return np.where(ok, np.nansum(np.where(mask, node_load, 0.0), axis=(1, 2)), np.nan)

    def peak(mask):
        with np.errstate(invalid="ignore"):
            v = np.nanmax(np.where(mask & loaded & np.isfinite(p0), p0, -np.inf), axis=(1, 2))
        return np.where(ok & np.isfinite(v), v, np.nan)

    tip_load, face_end_load = total(tip), total(at_end & loaded)
    pmax = np.where(ok, np.nan_to_num(peak(~tip), nan=0.0), np.nan)
    tip_p = peak(tip)
    te_l = np.where(ok, out["te_loaded"], np.nan)
    r_b2 = float(pair.flank2.gear.r_b)
    face = float(m1.z_hi - m1.z_lo)
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
        tip_edge_load_N=tip_load,
        tip_edge_pressure_MPa=tip_p,
        face_end_load_N=face_end_load,
        mesh_stiffness_N_per_um=k_mesh,
        mesh_stiffness_N_per_mm_um=k_mesh / face,
        moment_residual=np.where(ok, out["residual"], np.nan),
        iterations=its,
        status=status,
        node_load_N=node_load,
        pressure_MPa=p0,
        half_width_mm=b,
        passes=passes,
    )
