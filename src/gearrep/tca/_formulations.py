"""The public contact solves of the two TCA formulations (conventional eq 26-32, reduced eq 33-44;
their equations and Jacobians in :mod:`gearrep.tca._kernels`) and the contact record (see
:mod:`gearrep.tca`); Newton with per-row data is in ``_rows``, the path by continuation in
``_path``."""

from __future__ import annotations

import math

import numpy as np

from ..frames import rotate_z
from ..inputs import check_integer, real_or_nan
from ..solve import Status, finite_rows, newton
from ..surface import cross3, dot3
from ._kernels import (
    _SCALAR_ERRORS,
    _conventional_FJ,
    _conventional_FJ3,
    _reduced_FJ3,
    _reduced_kernel,
    _stack3,
    _wrap_any,
)
from ._pair import ContactPoints, GearPair, _wrap, transmission_error
from ._rows import newton_rows  # noqa: F401 - its home is _rows; the start strategies import it from here

__all__ = [
    "conventional_system",
    "check_formulation",
    "MAX_CONTACT_TOL",
    "default_start",
    "solve_contact",
    "reduced_unknowns",
]


def conventional_system(pair: GearPair, phi1: float, drop: int | None):
    """(F, J) callables of the conventional TCA (eq 26-32, eq 27 corrected to n_f1 + n_f2 = 0) at a
    fixed ``phi1`` for x = (u1, v1, u2, v2, phi2) (n, 5), as :func:`gearrep.solve.newton` takes them.

    F = [r_f1 - r_f2, components of n_f1 + n_f2] with outward unit normals; ``drop`` = 0, 1 or 2
    leaves that normal component out (five equations), None keeps all three (six equations, least
    squares). The one implementation behind :func:`solve_contact` (``formulation="conventional"``).

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float
        Angle of member 1 [rad].
    drop : {0, 1, 2} or None
        The normal component left out.

    Returns
    -------
    tuple of callable
        ``F(x) -> (n, 5 or 6)`` [length and unit-normal components] and ``J(x) -> (n, 5 or 6, 5)``.

    Raises
    ------
    ValueError
        If ``drop`` is not None, 0, 1 or 2.

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
    >>> from gearrep.solve import newton
    >>> from gearrep.tca import conventional_system, default_start
    >>> F, J = conventional_system(pair, 0.0, drop=0)
    >>> r = newton(F, default_start(pair, 0.0, "conventional"), J)
    >>> r.status_name.tolist(), bool(r.residual[0] < 1e-12)
    (['converged'], True)
    """
    return _conventional_callables(pair, phi1, drop)[:2]


def _conventional_callables(pair: GearPair, phi1: float, drop: int | None):
    """(F, J, FJ) of :func:`conventional_system`; FJ(x) = (F(x), J) from one evaluation (the
    residual by the same expressions as F alone) with J lazy (see :func:`gearrep.solve.newton`), for
    ``newton(fun_jac=...)``; J(x) the Jacobian as an array."""
    if drop is not None and drop not in (0, 1, 2):
        raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")

    def rows(x):
        return np.atleast_2d(x), drop

    def FJ(x, derivs=True):
        x, d = rows(x)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _conventional_FJ(pair, x, phi1, d, derivs=derivs)

    return (lambda x: FJ(x, derivs=False)[0]), (lambda x: FJ(x)[1]), (lambda x: FJ(x, derivs=_LAZY))


# ----------------------------------------------------------------------------------------------
# public solves
# ----------------------------------------------------------------------------------------------
def _angles(phi1, name: str = "phi1") -> np.ndarray:
    """``phi1`` as a non-empty 1-D float array [rad]; a scalar becomes length 1."""
    a = np.asarray(phi1, dtype=float)
    if a.ndim > 1 or a.size == 0:
        raise ValueError(f"{name} must be a scalar or a non-empty 1-D array of angles [rad], got shape {a.shape}")
    return np.atleast_1d(a)


def _face_coordinates(v1, n: int) -> np.ndarray:
    """Fixed face-width coordinates ``v1`` (scalar, length 1 or length ``n``) as an (n,) array."""
    a = np.asarray(v1, dtype=float)
    if a.ndim > 1 or (a.ndim == 1 and len(a) not in (1, n)):
        raise ValueError(f"v1 must be a scalar or a 1-D array of length 1 or {n} (one per phi1), got shape {a.shape}")
    return np.broadcast_to(a, (n,)).copy()


def _prep(phi1, start, width):
    start = np.atleast_2d(np.asarray(start, dtype=float))
    phi1 = _angles(phi1)
    if start.shape[-1] != width:
        raise ValueError(f"start must have {width} columns, got shape {start.shape}")
    n = max(len(phi1), len(start))
    if len(phi1) not in (1, n) or len(start) not in (1, n):
        raise ValueError(f"phi1 ({len(phi1)}) and start ({len(start)}) must have equal length or length 1")
    if not np.isfinite(phi1).all():
        raise ValueError("phi1 must be finite")
    if len(phi1) == n and len(start) == n:
        return phi1.copy(), start.copy()
    return np.broadcast_to(phi1, (n,)).copy(), np.broadcast_to(start, (n, width)).copy()


def _largest_normal_component(pair, u1, v1, c1, s1, keep=None) -> np.ndarray:
    """Per row the index (as float) of the largest component of member 1's unit normal in S_f at
    (u1, v1) turned by (cos, sin) = (c1, s1); 0 where it is not finite (the solve reports those).
    ``keep``: a dict that receives member 1's flank evaluated at (u1, v1) by components as
    ``keep["flank1"] = (u1, v1, P)`` (arrays only; see :meth:`_Rows.start_flank1`)."""
    if len(u1) == 1:  # one point: on floats (numpy scalars where the family has no float path)
        try:
            with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
                P = pair.flank1.evaluate_components(float(u1[0]), float(v1[0]))
                N = rotate_z(float(c1[0]), float(s1[0]), cross3(P[1], P[2]))
                L = math.sqrt(dot3(N, N))
                a = [abs(x / L) for x in N]
            if all(math.isfinite(x) for x in a):  # else as arrays (NaN counts as 0 there)
                return np.array([float(a.index(max(a)))])
        except _SCALAR_ERRORS:
            pass
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):  # a non-finite start ends as DIVERGED
        P = pair.flank1.evaluate_components(u1, v1)
        if keep is not None:
            keep["flank1"] = (u1, v1, P)
        N = rotate_z(c1, s1, cross3(P[1], P[2]))
        L = np.sqrt(dot3(N, N))
        a0, a1, a2 = (np.nan_to_num(np.abs(np.broadcast_to(x / L, u1.shape)), nan=0.0) for x in N)
        # the first largest (argmax's choice on ties), by components
        return np.where(a2 > np.maximum(a0, a1), 2.0, (a1 > a0).astype(float))


def check_formulation(formulation) -> str:
    """``formulation`` when it names a TCA formulation ('reduced': 2 unknowns per point,
    'conventional': 5); ValueError otherwise.

    Parameters
    ----------
    formulation : object
        The name to check.

    Returns
    -------
    str
        ``formulation``.

    Raises
    ------
    ValueError
        If it is neither 'reduced' nor 'conventional'.

    Examples
    --------
    >>> from gearrep.tca import check_formulation
    >>> check_formulation("reduced")
    'reduced'
    """
    if formulation not in ("reduced", "conventional"):
        raise ValueError(f"formulation must be 'reduced' or 'conventional', got {formulation!r}")
    return formulation


#: the largest solver tolerance a contact solve takes: its residual holds unit-normal components
#: (and distances in the design's length unit), so a tolerance near 1 calls an untouched start
#: converged (the bench's time-against-error sweep goes up to this value)
MAX_CONTACT_TOL = 1e-3


def _check_knobs(tol, maxiter, phi10, phi20) -> None:
    """ValueError naming the knob: tol in (0, MAX_CONTACT_TOL], maxiter an integer >= 1, the TE reference
    angles phi10, phi20 one finite number each [rad] (a string or a bool is no number: :func:`gearrep.inputs.real_or_nan`)."""
    if not 0 < real_or_nan(tol) <= MAX_CONTACT_TOL:
        raise ValueError(
            f"tol must be a number in (0, {MAX_CONTACT_TOL:g}] (a larger one calls an untouched start converged), got {tol!r}"
        )
    check_integer("maxiter", maxiter)
    for name, value in (("phi10", phi10), ("phi20", phi20)):
        if np.ndim(value) != 0 or not math.isfinite(real_or_nan(value)):
            raise ValueError(f"{name} (TE reference angle) must be one finite number [rad], got {value!r}")


def default_start(pair: GearPair, phi1, formulation: str = "reduced") -> np.ndarray:
    """Starting point at the middle of the flanks, phi2 = (N1/N2) phi1 (the thesis's choice of u2, v2).

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad].
    formulation : {"reduced", "conventional"}, optional
        Which unknowns.

    Returns
    -------
    numpy.ndarray
        (n, 2) (u1, v1) or (n, 5) (u1, v1, u2, v2, phi2), in the flanks' units and rad.

    Raises
    ------
    ValueError
        If ``formulation`` is unknown or ``phi1`` is not a scalar or a non-empty 1-D array.

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
    >>> from gearrep.tca import default_start
    >>> np.round(default_start(pair, [0.0, 0.1]), 4).tolist()  # mid-flank u1 [mm], v1 [mm]
    [[34.9597, 0.0], [34.9597, 0.0]]
    """
    check_formulation(formulation)
    phi1 = _angles(phi1)
    mid1, mid2 = pair._mid_flanks
    if formulation == "reduced":
        return np.tile(mid1, (len(phi1), 1))
    return np.column_stack([np.tile(mid1, (len(phi1), 1)), np.tile(mid2, (len(phi1), 1)), pair.ratio * phi1])


class _Record:
    """The contact geometry the kernel evaluations gave (u2, v2, phi2 of the reduced form; point r
    and normals n1, n2 of both), kept with the unknowns they were evaluated at, so that the contact
    record of a row whose final iterate was the last point evaluated is not computed a second time
    (:meth:`at`; rows whose final iterate differs, e.g. a stalled line search, are). Evaluations are
    only listed while solving (``rows`` None: all rows); :meth:`at` takes each row's last one."""

    def __init__(self, n: int, k: int):
        self.n, self.k = n, k
        self.entries = []

    def store(self, rows, x, K):
        self.entries.append((rows, x, K))

    def at(self, x):
        """(mask of the rows recorded at exactly ``x``, the record: ``x``, ``scalars`` and
        ``vectors`` (n, 3) of each row's last evaluation). The last evaluation of every row is the
        base; the later evaluations of some rows are written over it in their order."""
        n = self.n
        entries, self.entries = self.entries, []
        full = max((i for i, e in enumerate(entries) if e[0] is None), default=-1)
        later = entries[full + 1 :]
        if full >= 0:
            _, xe, K = entries[full]
            xe = np.array([xe], dtype=float) if type(xe) is list else xe  # a list: one point on floats
            if not later:  # the last evaluation covered every row: its arrays as they are
                self.x = xe
                self.scalars = {key: np.array(K[key], dtype=float).reshape(n) for key in _SCALARS if key in K}
                self.vectors = {key: _stack3(K[key], n) for key in _VECTORS}
                return (self.x == x).all(axis=1), self
            self.x = np.array(xe, dtype=float)
            scalars = {key: _own(K.get(key, np.nan), n) for key in _SCALARS}
            comps = {key: [_own(c, n) for c in K[key]] for key in _VECTORS}
        else:
            self.x = np.full((n, self.k), np.nan)
            scalars = {key: np.full(n, np.nan) for key in _SCALARS}
            comps = {key: [np.full(n, np.nan) for _ in range(3)] for key in _VECTORS}
        for rows, xe, K in later:
            self.x[rows] = xe
            for key, arr in scalars.items():
                if key in K:
                    arr[rows] = K[key]
            for key, arrs in comps.items():
                for arr, c in zip(arrs, K[key]):
                    arr[rows] = c
        self.scalars = scalars
        self.vectors = {key: _stack3(c, n) for key, c in comps.items()}
        return (self.x == x).all(axis=1), self


#: the record's entries (reduced: also u2, v2, phi2)
_SCALARS, _VECTORS = ("u2", "v2", "phi2"), ("r", "n1", "n2")


def _own(c, n):
    """A copy of the (n,) array (or float, broadcast) ``c`` that may be written to."""
    return np.array(np.broadcast_to(c, (n,)), dtype=float)


def _check_solve_inputs(pair: GearPair, phi1, start, formulation, v1, jacobian, drop):
    """Validated (phi1 (n,), start (n, width) with a fixed v1 written into its column 1, fixed);
    ValueError naming the argument otherwise (before any work)."""
    check_formulation(formulation)
    if jacobian not in ("analytic", "numeric"):
        raise ValueError(f"jacobian must be 'analytic' or 'numeric', got {jacobian!r}")
    if drop is not None and drop not in (0, 1, 2):
        raise ValueError(f"drop must be None or one of 0, 1, 2, got {drop!r}")
    if formulation == "reduced" and not (
        getattr(pair.flank2, "cylindrical", False) or getattr(pair.flank2, "spherical", False)
    ):
        raise ValueError(
            "the reduced formulation needs flank2 in cylindrical or spherical form "
            "(flank2.cylindrical = True or flank2.spherical = True)"
        )
    width = 2 if formulation == "reduced" else 5
    phi1 = _angles(phi1)
    if start is None:
        start = default_start(pair, phi1, formulation)
    phi1, start = _prep(phi1, start, width)
    fixed = v1 is not None
    if fixed:
        v1a = _face_coordinates(v1, len(phi1))
        if not np.isfinite(v1a).all():
            raise ValueError("v1 must be finite")
        start[:, 1] = v1a
    return phi1, start, fixed


class _Rows:
    """Per-row data of a contact solve (phi1, cos, sin, the dropped normal component as the masks
    drop == 0 and drop == 2, a fixed v1) as contiguous arrays, gathered for the active rows
    (``idx``; no gather while all rows are active), and for one row as Python floats. Where every
    row drops the same component the masks are Python bools (the kernels then pick the kept
    components without a per-row selection)."""

    def __init__(self, phi1, c1, s1, drop, v1, start_flank1=None):
        self.n = len(phi1)
        self._start_flank1 = start_flank1
        first0, last2 = drop == 0, drop == 2
        if self.n > 1 and (drop == drop[0]).all():
            first0, last2 = bool(first0[0]), bool(last2[0])
        self.cols = {"phi1": phi1, "c1": c1, "s1": s1, "first0": first0, "last2": last2, "v1": v1}
        self.one = None
        if self.n == 1:
            d = float(drop[0])
            self.one = {
                "phi1": float(phi1[0]),
                "c1": float(c1[0]),
                "s1": float(s1[0]),
                "first0": d == 0,
                "last2": d == 2,
                "v1": float(v1[0]),
            }

    def start_flank1(self, u1, v1):
        """Member 1's flank evaluated at the starts when the dropped component was chosen
        (``start_flank1`` = (u1, v1, P)), handed out once: for the solve's first evaluation, if
        that is at exactly these (u1, v1) (else None, and the caller evaluates it)."""
        kept, self._start_flank1 = self._start_flank1, None
        if kept is not None and np.array_equal(u1, kept[0]) and np.array_equal(v1, kept[1]):
            return kept[2]
        return None

    def take(self, idx):
        if len(idx) == self.n:
            return self.cols
        return {k: (v if type(v) is bool else v[idx]) for k, v in self.cols.items()}


#: the ``derivs`` of the kernels for the solves' evaluations: the Jacobian is a lazy one
#: (:func:`gearrep.tca._kernels._lazy_jacobian`), which :func:`gearrep.solve.newton` forms only for
#: the rows that take another Newton step (a row's last evaluation, at its root, needs no Jacobian)
_LAZY = "lazy"


def _with_one_point(floats, arrays):
    """FJ(x, idx, derivs) for ``newton(rows=True)``: ``floats`` (see :func:`_reduced_FJ_rows`) at a
    single row where given and it evaluates (packed as the arrays F (1, m), J (1, m, k)), else
    ``arrays(x, idx, derivs)``; returns (FJ, floats)."""

    def FJ(x, idx, derivs=True):
        if floats is not None and len(x) == 1:  # one point: the kernel on floats
            out = floats(x[0].tolist(), derivs)
            if out is not None:
                J = out[1]
                if callable(J):  # a lazy Jacobian on floats: its list formed now (one row)
                    J = J()
                return np.array([out[0]], dtype=float), (None if J is None else np.array([J], dtype=float))
        return arrays(x, idx, derivs)

    return FJ, floats


def _reduced_FJ_rows(pair, data: _Rows, fixed, record):
    """(FJ(x, idx, derivs), floats(x, derivs) or None) of the reduced system for
    ``newton(rows=True, fun_jac=FJ, floats=floats)`` (see :func:`solve_contact`); ``floats``, for
    a solve of one row, evaluates on Python floats (None where the kernel on floats raises, see
    _SCALAR_ERRORS, and the arrays then evaluate)."""
    v_column = not fixed
    q = data.one

    def floats(x, derivs=True):
        try:
            F, J, K = _reduced_FJ3(
                pair,
                x[0],
                q["v1"] if fixed else x[1],
                q["phi1"],
                q["c1"],
                q["s1"],
                q["first0"],
                q["last2"],
                derivs=_LAZY if derivs else False,
                v_column=v_column,
                lists=True,
            )
        except _SCALAR_ERRORS:
            return None
        record.store(None, x, K)
        return F, J

    def arrays(x, idx, derivs):
        p = data.take(idx)
        v1 = p["v1"] if fixed else x[:, 1]
        out = _reduced_FJ3(
            pair,
            x[:, 0],
            v1,
            p["phi1"],
            p["c1"],
            p["s1"],
            p["first0"],
            p["last2"],
            _LAZY if derivs else False,
            v_column,
            P1=data.start_flank1(x[:, 0], v1),
        )
        record.store(None if len(idx) == data.n else idx, x, out[2])
        return out[:2]

    return _with_one_point(floats if q is not None else None, arrays)


#: the ``drop`` argument of :func:`_conventional_FJ3` for five equations (any value but None; the
#: dropped component itself comes as the masks first0, last2)
_FIVE = 5


def _conventional_FJ_rows(pair, data: _Rows, free, record):
    """(FJ(x, idx, derivs), floats(x, derivs) or None) of the conventional system for
    ``newton(rows=True, fun_jac=FJ, floats=floats)`` (free columns ``free`` of the five unknowns;
    a fixed v1 from the row data; ``floats`` as for :func:`_reduced_FJ_rows`)."""
    cols = tuple(free)
    q = data.one

    def floats(x, derivs=True):
        keep = {}
        x5 = x if len(x) == 5 else [x[0], q["v1"], *x[1:]]  # free = all five or (0, 2, 3, 4)
        try:
            out = _conventional_FJ3(
                pair,
                x5,
                q["c1"],
                q["s1"],
                _FIVE,
                q["first0"],
                q["last2"],
                cols,
                _LAZY if derivs else False,
                keep,
                lists=True,
            )
        except _SCALAR_ERRORS:
            return None
        record.store(None, x, keep)
        return out

    def arrays(x, idx, derivs):
        p = data.take(idx)
        full = _expand(x, free, p["v1"])
        keep = {}
        x5 = tuple(full[:, i] for i in range(5))
        P1 = data.start_flank1(x5[0], x5[1])
        out = _conventional_FJ3(
            pair, x5, p["c1"], p["s1"], _FIVE, p["first0"], p["last2"], cols, _LAZY if derivs else False, keep, P1=P1
        )
        record.store(None if len(idx) == data.n else idx, x, keep)
        return out

    return _with_one_point(floats if q is not None else None, arrays)


def _expand(x, free, v1):
    """The full unknowns (n, width) from the free columns ``x``; column 1 = the fixed ``v1``
    where v1 is not among the free ones."""
    width = 2 if len(free) <= 2 else 5
    if len(free) == width:
        return x
    full = np.empty((x.shape[0], width))
    full[:, free] = x
    full[:, 1] = v1
    return full


#: the most rows :func:`solve_contact` solves in one batch; a larger one is solved in equal blocks
#: (the rows are independent: the same results bit for bit). An array of 20 000 rows holds 160 kB,
#: so an operation's operands stay within a core's L2 cache (512 kB on the reference machine):
#: library example pair (docs/library.md), reduced, one batch of 80 000 rows cost 9.6-10 reference elements per solve against
#: 6.9-7.5 in batches of 13 000-20 000 (below about 5 000 rows numpy's per-call cost grows)
_BLOCK_ROWS = 20_000


def solve_contact(
    pair: GearPair,
    phi1,
    start=None,
    *,
    formulation: str = "reduced",
    v1=None,
    jacobian: str = "analytic",
    tol: float = 1e-12,
    maxiter: int = 50,
    damped: bool = True,
    phi10: float = 0.0,
    phi20: float = 0.0,
    drop=None,
    keep_failed: bool = False,
) -> ContactPoints:
    """Contact points of ``pair`` at member-1 angles ``phi1`` (vectorised over starts and angles).

    Parameters
    ----------
    pair : GearPair
        The pair (or a :class:`BevelPair`).
    phi1 : float or (n,) array_like
        Angles of member 1 [rad].
    start : (n, 2) or (n, 5) array_like, optional
        (u1, v1) for ``formulation="reduced"`` (eq 33-44) or (u1, v1, u2, v2, phi2) for
        ``"conventional"`` (eq 26-32), in the flanks' units and rad; default :func:`default_start`.
    formulation : {"reduced", "conventional"}, optional
        Two unknowns per point (member 2 explicit) or five.
    v1 : float or (n,) array_like, optional
        None (point contact: v1 unknown) or the fixed face-width coordinate of member 1 [length]
        (line contact; the v1 column of ``start`` is then ignored).
    jacobian : {"analytic", "numeric"}, optional
        Analytic, or central differences.
    tol : float, optional
        Residual tolerance, in (0, :data:`MAX_CONTACT_TOL`] (unit-normal components and lengths).
    maxiter : int, optional
        Iteration limit, >= 1.
    damped : bool, optional
        Passed to :func:`gearrep.solve.newton`.
    phi10, phi20 : float, optional
        TE reference (eq 14) [rad].
    drop : {0, 1, 2}, optional
        None (default: the component j = argmax ``|n_f1,j|`` at the start, per row) or the
        component of n_f1 + n_f2 (conventional) or n_f1 x n_f2 (reduced) left out of the system.
        Other choices than the default can make the Jacobian singular (see module docstring).
    keep_failed : bool, optional
        False (default): a row whose status is not CONVERGED has NaN flank parameters,
        phi2, position, normal and TE (:meth:`ContactPoints.failed_as_nan`); True keeps the
        solver's last iterate there (a root beyond the flank, OFF_FLANK, tells which boundary the
        path of contact crossed; continuation and boundary searches use it).

    Returns
    -------
    ContactPoints
        One row per angle; status CONVERGED only for a verified root inside both flanks. A batch
        of more than ``_BLOCK_ROWS`` (20 000) rows is solved in equal blocks (faster: arrays that
        fit a core's cache), with the same results.

    Raises
    ------
    ValueError
        Before any solve, naming the argument: an unknown formulation, Jacobian or ``drop``; a
        ``tol`` outside (0, :data:`MAX_CONTACT_TOL`]; a bad ``maxiter``, angle, ``v1`` or
        ``start`` shape; a pair without the explicit member 2 the reduced formulation needs.

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
    >>> c = solve_contact(pair, np.linspace(-0.05, 0.05, 5))
    >>> bool(c.converged.all()), bool(c.residual.max() < 1e-12)
    (True, True)
    >>> np.round(c.u1, 4).tolist()  # the contact climbs the pinion flank [mm]
    [34.7106, 35.0084, 35.3223, 35.6518, 35.9966]
    >>> conv = solve_contact(pair, 0.0, formulation="conventional")  # five unknowns, same contact
    >>> round(float(conv.u1[0]), 6) == round(float(c.u1[2]), 6)
    True
    """
    _check_knobs(tol, maxiter, phi10, phi20)
    phi1, start, fixed = _check_solve_inputs(pair, phi1, start, formulation, v1, jacobian, drop)
    n = len(phi1)
    if n > _BLOCK_ROWS:  # equal blocks of at most _BLOCK_ROWS rows, each solved as a batch
        edges = np.linspace(0, n, -(-n // _BLOCK_ROWS) + 1).round().astype(int)
        kw = dict(formulation=formulation, jacobian=jacobian, tol=tol, maxiter=maxiter, damped=damped)
        kw.update(phi10=phi10, phi20=phi20, drop=drop, keep_failed=keep_failed)
        return ContactPoints.concatenate(
            solve_contact(pair, phi1[a:b], start[a:b], v1=start[a:b, 1] if fixed else None, **kw)
            for a, b in zip(edges[:-1], edges[1:])
        )
    c1, s1 = np.cos(phi1), np.sin(phi1)
    # dropped normal component: the largest of member 1's normal at the start
    first = {}  # member 1's flank at the starts, evaluated once for the drop and the first iterate
    if drop is None:
        drop = _largest_normal_component(pair, start[:, 0], start[:, 1], c1, s1, keep=first)
    else:
        drop = np.full(n, float(drop))
    reduced = formulation == "reduced"
    free = ([0] if fixed else [0, 1]) if reduced else ([0, 2, 3, 4] if fixed else [0, 1, 2, 3, 4])
    lo, hi = pair._free_bounds(tuple(free))
    x0 = start[:, : len(free)] if free == list(range(len(free))) else start[:, free]  # a view where contiguous
    data = _Rows(phi1, c1, s1, drop, start[:, 1] if fixed else np.full(n, np.nan), first.get("flank1"))
    record = _Record(n, len(free))
    FJ, floats = (
        _reduced_FJ_rows(pair, data, fixed, record) if reduced else _conventional_FJ_rows(pair, data, free, record)
    )
    analytic = jacobian == "analytic"
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):  # non-finite iterates end as DIVERGED
        res = newton(
            lambda x, idx: FJ(x, idx, derivs=False)[0],
            x0,
            (lambda x, idx: FJ(x, idx)[1]) if analytic else None,
            tol=tol,
            maxiter=maxiter,
            damped=damped,
            lower=lo,
            upper=hi,
            rows=True,
            fun_jac=FJ if analytic else None,
            inverse_square=True,
            floats=floats,
        )
    sol = _expand(res.x, free, data.cols["v1"])
    out = None
    if n == 1:  # one point: on floats where the last evaluation was at the solution
        out = _finish_one(pair, formulation, sol, phi1, res, phi10, phi20, record)
    if out is None:
        out = _finish(pair, formulation, sol, phi1, res, phi10, phi20, record.at(res.x))
    return out if keep_failed else out.failed_as_nan()


def _finish(pair, formulation, sol, phi1, res, phi10, phi20, recorded=None) -> ContactPoints:
    """Contact record of the solved rows; ``recorded`` = (mask, :class:`_Record`): the rows whose
    geometry the solve's last kernel evaluation already gave at exactly these unknowns."""
    u2, v2, phi2, r, n1, n2 = _contact_geometry(pair, formulation, sol, phi1, recorded)
    status = _final_status(pair, formulation, res.status.copy(), r, n1, n2, u2, v2)
    te = transmission_error(phi1, phi2, pair.n1, pair.n2, phi10, phi20)
    return ContactPoints(
        u1=sol[:, 0],
        v1=sol[:, 1],
        u2=u2,
        v2=v2,
        phi1=phi1,
        phi2=phi2,
        position=r,
        normal=n1,
        te=te,
        residual=res.residual,
        iterations=res.iterations,
        status=status,
        formulation=formulation,
        condition=res.condition,
    )


def _finish_one(pair, formulation, sol, phi1, res, phi10, phi20, record: _Record):
    """:func:`_finish` of a one-point solve on Python floats (the same operations) when the
    solve's last evaluation, on floats (see :func:`_reduced_FJ_rows`), was at exactly the
    solution; None otherwise (or where floats raise), and the arrays finish it."""
    if not record.entries:
        return None
    _, xe, K = record.entries[-1]
    if type(xe) is not list or xe != res.x[0].tolist():
        return None
    p1 = float(phi1[0])
    if formulation == "reduced":
        u2, v2, phi2 = K["u2"], K["v2"], K["phi2"]
    else:
        x5 = sol[0].tolist()
        u2, v2 = x5[2], x5[3]
        ref = pair.ratio * p1
        try:
            phi2 = ref + _wrap_any(x5[4] - ref)
        except _SCALAR_ERRORS:
            return None
    record.entries = []
    r, n1, n2 = K["r"], K["n1"], K["n2"]
    nan3 = (math.nan, math.nan, math.nan)
    r = r if all(map(math.isfinite, r)) else nan3  # a point or normal with a non-finite component is not a vector
    n1 = n1 if all(map(math.isfinite, n1)) else nan3
    status = _final_status_floats(pair, formulation, int(res.status[0]), n1, n2, u2, v2)
    return ContactPoints(
        u1=sol[:, 0],
        v1=sol[:, 1],
        u2=np.array([u2], dtype=float),
        v2=np.array([v2], dtype=float),
        phi1=phi1,
        phi2=np.array([phi2], dtype=float),
        position=np.array([r], dtype=float),
        normal=np.array([n1], dtype=float),
        te=np.array([transmission_error(p1, phi2, pair.n1, pair.n2, phi10, phi20)], dtype=float),
        residual=res.residual,
        iterations=res.iterations,
        status=np.array([status]),
        formulation=formulation,
        condition=res.condition,
    )


def _contact_geometry(pair, formulation, sol, phi1, recorded):
    """(u2, v2, phi2, r, n1, n2) of the solved rows: from the record where it holds them (see
    :func:`_finish`), else evaluated; a point or normal with a non-finite component is NaN."""
    u1, v1 = sol[:, 0], sol[:, 1]
    n = len(sol)
    hit, rec = recorded if recorded is not None else (np.zeros(n, dtype=bool), None)
    reduced = formulation == "reduced"
    if reduced:
        u2, v2, phi2 = (np.empty(n) for _ in range(3))
    else:
        u2, v2 = sol[:, 2], sol[:, 3]
        ref = pair.ratio * phi1
        phi2 = ref + _wrap(sol[:, 4] - ref)
    if rec is not None and hit.all():  # every row recorded: the record's arrays as they are
        r, n1, n2 = (rec.vectors[key] for key in ("r", "n1", "n2"))
        if reduced:
            u2, v2, phi2 = (rec.scalars[key] for key in ("u2", "v2", "phi2"))
        miss = np.zeros(0, dtype=int)
    else:
        r, n1, n2 = (np.empty((n, 3)) for _ in range(3))
        if rec is not None and hit.any():
            for key, arr in zip(("r", "n1", "n2"), (r, n1, n2)):
                arr[hit] = rec.vectors[key][hit]
            if reduced:
                for key, arr in zip(("u2", "v2", "phi2"), (u2, v2, phi2)):
                    arr[hit] = rec.scalars[key][hit]
        miss = np.flatnonzero(~hit)
    if miss.size:
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            if reduced:
                K = _reduced_kernel(pair, u1[miss], v1[miss], phi1[miss], derivs=False)
                u2[miss], v2[miss], phi2[miss] = K["u2"], K["v2"], K["phi2"]
                r[miss], n1[miss], n2[miss] = K["r"], K["n1"], K["n2"]
            else:
                r[miss], n1[miss] = pair.member1(u1[miss], v1[miss], phi1[miss])
                n2[miss] = pair.member2(u2[miss], v2[miss], phi2[miss])[1]
    for vec in (r, n1):  # a point or normal with a non-finite component is not a vector
        bad = ~finite_rows(vec)
        if bad.any():
            vec[bad] = np.nan
    return u2, v2, phi2, r, n1, n2


#: status codes as ints (an IntEnum member looked up on its class costs more than the test itself)
_CONVERGED, _OFF_FLANK, _WRONG_ROOT = int(Status.CONVERGED), int(Status.OFF_FLANK), int(Status.WRONG_ROOT)


def _final_status(pair, formulation, status, r, n1, n2, u2, v2):
    """The solver's statuses with WRONG_ROOT (normals not opposite; conventional: n1 + n2 not
    ~0) and OFF_FLANK (member 2's parameters outside its flank) set."""
    if len(status) == 1:
        return _final_status_one(pair, formulation, status, n1, n2, u2, v2)
    with np.errstate(invalid="ignore", over="ignore"):
        # the sums written out: numpy sums a row of three the same way, left to right
        opposite = (n1[:, 0] * n2[:, 0] + n1[:, 1] * n2[:, 1] + n1[:, 2] * n2[:, 2]) < 0
        if formulation == "conventional":
            s = n1 + n2
            opposite &= np.sqrt(s[:, 0] * s[:, 0] + s[:, 1] * s[:, 1] + s[:, 2] * s[:, 2]) < 1e-6
    if not opposite.all():
        solved = (status == _CONVERGED) | (status == _OFF_FLANK)
        status[solved & ~opposite] = _WRONG_ROOT
    ulo, uhi, vlo, vhi = pair._flank2_limits
    outside2 = ~((u2 >= ulo) & (u2 <= uhi) & (v2 >= vlo) & (v2 <= vhi))
    if outside2.any():
        status[(status == _CONVERGED) & outside2] = _OFF_FLANK
    return status


def _final_status_one(pair, formulation, status, n1, n2, u2, v2):
    """:func:`_final_status` of one point by :func:`_final_status_floats`."""
    status[0] = _final_status_floats(
        pair, formulation, int(status[0]), n1[0].tolist(), n2[0].tolist(), float(u2[0]), float(v2[0])
    )
    return status


def _final_status_floats(pair, formulation, st: int, a, b, u: float, v: float) -> int:
    """:func:`_final_status` of one point on Python floats (status ``st``, normals ``a``, ``b``,
    member 2's parameters ``u``, ``v``): the same tests (NaN fails them alike)."""
    opposite = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < 0
    if formulation == "conventional":
        s = [x + y for x, y in zip(a, b)]
        opposite = opposite and math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) < 1e-6
    if st in (_CONVERGED, _OFF_FLANK) and not opposite:
        st = _WRONG_ROOT
    ulo, uhi, vlo, vhi = pair._flank2_limits
    if st == _CONVERGED and not (u >= ulo and u <= uhi and v >= vlo and v <= vhi):
        st = _OFF_FLANK
    return st


def reduced_unknowns(pair: GearPair, u1, v1, phi1):
    """(u2, v2, phi2) from (u1, v1, phi1) by the explicit relations of the reduced formulation (eq 39-44).

    Parameters
    ----------
    pair : GearPair
        The pair (member 2 in explicit cylindrical form).
    u1, v1 : float or array_like
        Flank parameters of member 1 [length].
    phi1 : float or array_like
        Angle of member 1 [rad].

    Returns
    -------
    tuple of numpy.ndarray
        (u2 [length], v2 [length], phi2 [rad]), of the broadcast shape.

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
    >>> from gearrep.tca import reduced_unknowns
    >>> c = solve_contact(pair, 0.0)
    >>> u2, v2, phi2 = reduced_unknowns(pair, c.u1, c.v1, c.phi1)
    >>> round(float(u2[0] - c.u2[0]), 9), round(float(phi2[0] - c.phi2[0]), 12)
    (0.0, 0.0)
    """
    u1, v1, phi1 = np.broadcast_arrays(*(np.asarray(a, float) for a in (u1, v1, phi1)))
    shape = u1.shape
    K = _reduced_kernel(pair, u1.ravel(), v1.ravel(), phi1.ravel(), derivs=False)
    return K["u2"].reshape(shape), K["v2"].reshape(shape), K["phi2"].reshape(shape)
