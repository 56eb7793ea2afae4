"""Solver variants of both TCA formulations (see :mod:`gearrep.tca`), as the start-robustness
study compares them.

Conventional variants (five unknowns u1, v1, u2, v2, phi2 at a given phi1):
``plain`` full Newton steps, iterates free; ``damped`` Armijo backtracking; ``domain`` damped with
every iterate projected onto the flank boxes; ``seeded`` plain Newton from (u1, v1) and the u2, v2,
phi2 that the reduced relations (eq 39-44) give for them (:func:`seed_from_reduced`); ``robust``
plain Newton from :func:`robust_start`, seeded likewise.

Reduced variants (two unknowns u1, v1): ``reduced`` plain Newton, ``reduced_damped``,
``reduced_robust`` plain Newton from :func:`robust_start`: a start whose explicit u2 would fall
below flank 2 is moved down the profile (:func:`guard_reduced_starts`), then onto the
instantaneous contact line by a 1-D solve (:func:`transverse_stage`).
"""

from __future__ import annotations

import numpy as np

from ..inputs import check_integer, check_positive, real_or_nan
from ..solve import SolveResult, Status, newton
from ..surface import cross
from ._formulations import _conventional_callables, newton_rows, reduced_unknowns, solve_contact
from ._pair import GearPair

__all__ = [
    "CONVENTIONAL_VARIANTS",
    "REDUCED_VARIANTS",
    "flank_boxes",
    "solve_conventional",
    "seed_from_reduced",
    "guard_reduced_starts",
    "transverse_stage",
    "robust_start",
    "solve_reduced",
    "solve_variant",
]

#: the solver variants of the conventional formulation (module docstring)
CONVENTIONAL_VARIANTS = ("plain", "damped", "domain", "seeded", "robust")
#: the solver variants of the reduced formulation (module docstring)
REDUCED_VARIANTS = ("reduced", "reduced_damped", "reduced_robust")


def _one_angle(phi1) -> float:
    """``phi1`` as one finite angle [rad] (a scalar or a length-1 array)."""
    a = np.asarray(phi1, dtype=float)
    if a.size != 1 or a.ndim > 1 or not np.isfinite(a).all():
        raise ValueError(f"phi1 must be one finite angle [rad], got {phi1!r}")
    return float(a.reshape(()))


def _start_pairs(phi1, u1, v1):
    """(phi1 (n,), u1 (n,), v1 (n,)) of (u1, v1) starts: u1, v1 1-D of one length n >= 1, finite
    phi1 one angle or one per start."""
    u1 = np.asarray(u1, dtype=float)
    v1 = np.asarray(v1, dtype=float)
    if u1.ndim != 1 or u1.size == 0 or v1.shape != u1.shape:
        raise ValueError(
            f"u1 and v1 must be non-empty 1-D arrays of the same length (one per start), got shapes {u1.shape} "
            f"and {v1.shape}"
        )
    ph = np.asarray(phi1, dtype=float)
    if not (ph.ndim == 0 or (ph.ndim == 1 and len(ph) in (1, len(u1)))):
        raise ValueError(f"phi1 must be one angle or one per start (length {len(u1)}), got shape {ph.shape}")
    if not np.all(np.isfinite(ph)):
        raise ValueError(f"phi1 must be finite, got {phi1!r}")
    return np.broadcast_to(ph, u1.shape), u1, v1


def _starts5(x0, name: str = "x0") -> np.ndarray:
    """Conventional starts as an (n, 5) array, n >= 1."""
    a = np.asarray(x0, dtype=float)
    if a.ndim != 2 or a.shape[0] == 0 or a.shape[1] != 5:
        raise ValueError(
            f"{name} must be an (n, 5) array of starts (u1, v1, u2, v2, phi2), n >= 1, got shape {a.shape}"
        )
    return a


def _check_margin(margin) -> None:
    if not 0.0 <= real_or_nan(margin) < 0.5:
        raise ValueError(f"margin must be in [0, 0.5) (fraction of the flank height), got {margin!r}")


def flank_boxes(pair: GearPair, margin: float = 0.0):
    """Lower and upper bounds of x = (u1, v1, u2, v2, phi2) on both flanks (phi2 free), u limits
    moved ``margin`` x height inward (the involute cusp at u = r_b has an infinite second derivative).

    Parameters
    ----------
    pair : GearPair
        The pair (its flanks' ``lower``, ``upper``; unbounded where a flank has none).
    margin : float, optional
        Fraction of each flank's height [1] by which both u limits move inward, in [0, 0.5).

    Returns
    -------
    lower, upper : numpy.ndarray
        (5,) bounds in the flanks' units (mm for involute flanks) and rad; phi2 is -inf .. inf.

    Raises
    ------
    ValueError
        If ``margin`` is not in [0, 0.5).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, flank_boxes
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> lo, hi = flank_boxes(pair, margin=0.1)
    >>> np.round(lo, 4).tolist()  # u1 [mm], v1 [mm], u2 [mm], v2 [mm], phi2 [rad]
    [32.9275, -12.5, 58.462, -12.5, -inf]
    >>> np.round(hi, 4).tolist()
    [36.9919, 12.5, 63.8291, 12.5, inf]
    """
    _check_margin(margin)
    lo = np.concatenate([pair.lower1, pair.lower2, [-np.inf]]).astype(float)
    hi = np.concatenate([pair.upper1, pair.upper2, [np.inf]]).astype(float)
    for j in (0, 2):
        h = hi[j] - lo[j]
        lo[j] += margin * h
        hi[j] -= margin * h
    return lo, hi


def solve_conventional(
    pair: GearPair,
    phi1: float,
    x0,
    *,
    variant: str = "plain",
    equations: str = "five",
    drop: int = 0,
    tol: float = 1e-12,
    maxiter: int = 50,
    margin: float = 1e-6,
) -> SolveResult:
    """Conventional TCA at a fixed ``phi1`` from starts ``x0`` (n, 5) with solver ``variant``
    (:data:`CONVENTIONAL_VARIANTS`; ``seeded`` and ``robust`` expect x0 already prepared by
    :func:`seed_from_reduced`, and run plain Newton).

    ``equations``: ``"five"`` drops normal component ``drop``, ``"six"`` keeps all three (least
    squares), ``"drop_nz"`` drops the axial component z (singular for spur gears). The status is
    the solver's; roots outside the flank boxes are OFF_FLANK.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float
        The angle of member 1 [rad], one finite angle.
    x0 : (n, 5) array_like
        Starts (u1, v1, u2, v2, phi2) [flank units (mm for involute flanks), rad].
    variant : str, optional
        One of :data:`CONVENTIONAL_VARIANTS`.
    equations : {"five", "six", "drop_nz"}, optional
        Which components of the normal equation are kept (see above).
    drop : {0, 1, 2}, optional
        The normal component dropped with ``equations="five"``.
    tol : float, optional
        Residual tolerance [flank units] (> 0, finite).
    maxiter : int, optional
        Iteration limit.
    margin : float, optional
        The ``domain`` variant's inward margin, a fraction of the flank height in [0, 0.5)
        (:func:`flank_boxes`).

    Returns
    -------
    gearrep.solve.SolveResult
        The solver's record: x (n, 5), residual, iterations, status per start.

    Raises
    ------
    ValueError
        Before any solve: an unknown variant or equation set, a ``drop`` outside (0, 1, 2), ``phi1``
        not one finite angle, ``x0`` not (n, 5), a bad tolerance, iteration limit or margin.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, default_start, solve_conventional
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> x0 = default_start(pair, 0.0, "conventional")  # the middle of both flanks, phi2 = 0
    >>> r = solve_conventional(pair, 0.0, x0, variant="damped")
    >>> r.status.tolist(), np.round(r.x[:, [0, 2]], 4).tolist()  # converged; u1, u2 [mm]
    ([0], [[35.3186, 60.7784]])
    """
    if variant not in CONVENTIONAL_VARIANTS:
        raise ValueError(f"variant must be one of {CONVENTIONAL_VARIANTS}, got {variant!r}")
    phi1 = _one_angle(phi1)
    x0 = _starts5(x0)
    check_positive("tol", tol)
    check_integer("maxiter", maxiter)
    _check_margin(margin)
    if equations not in ("five", "six", "drop_nz"):
        raise ValueError(f"equations must be 'five', 'six' or 'drop_nz', got {equations!r}")
    if equations == "five" and drop not in (0, 1, 2):
        raise ValueError(f"equations='five' needs drop in (0, 1, 2), got {drop!r}")
    F, J, FJ = _conventional_callables(pair, phi1, {"five": drop, "six": None, "drop_nz": 2}[equations])
    lo, hi = flank_boxes(pair, 0.0)
    kw = dict(tol=tol, maxiter=maxiter, lower=lo, upper=hi)
    if variant == "domain":
        lo_m, hi_m = flank_boxes(pair, margin)
        kw.update(damped=True, keep_inside=True, lower=lo_m, upper=hi_m)
    else:
        kw.update(damped=(variant == "damped"))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        return newton(F, np.asarray(x0, float), J, inverse_square=True, fun_jac=FJ, **kw)


def seed_from_reduced(pair: GearPair, phi1, u1, v1) -> np.ndarray:
    """Conventional starts (u1, v1, u2, v2, phi2) with u2, v2, phi2 from the reduced relations
    (eq 39-44) for the given (u1, v1).

    Parameters
    ----------
    pair : GearPair
        The pair; member 2 in explicit (cylindrical or spherical) form.
    phi1 : float
        The angle of member 1 [rad].
    u1, v1 : (n,) array_like
        Points of flank 1 [flank units, mm for involute flanks].

    Returns
    -------
    numpy.ndarray
        (n, 5) starts (u1, v1, u2, v2, phi2) [flank units, rad]; NaN where the explicit u2 or phi2 is
        undefined (the point maps inside member 2's base circle).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, seed_from_reduced
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> x0 = seed_from_reduced(pair, 0.0, np.array([35.0]), np.array([0.0]))  # rad, mm, mm
    >>> x0.shape, round(float(x0[0, 2]), 4)  # u2 [mm] of the point of member 2 where u1 lies
    ((1, 5), 61.1083)
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        u2, v2, phi2 = reduced_unknowns(pair, u1, v1, np.full(np.shape(u1), phi1))
    return np.column_stack([u1, v1, u2, v2, phi2])


def guard_reduced_starts(pair: GearPair, phi1, u1, v1, n_bisect: int = 40):
    """Move starts whose explicit u2 (eq 40) is below flank 2 (or undefined) down the profile of
    flank 1 (bisection in u1 towards u1_min) onto the part of flank 1 that maps onto flank 2.
    ``phi1`` scalar or one angle per start. Returns (u1, moved mask).

    Parameters
    ----------
    pair : GearPair
        The pair; member 2 in explicit form.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad]: one, or one per start (finite).
    u1, v1 : (n,) array_like
        Starts on flank 1 [flank units, mm for involute flanks], 1-D of one length n >= 1.
    n_bisect : int, optional
        Bisection steps.

    Returns
    -------
    u1 : numpy.ndarray
        (n,) guarded u1 [flank units].
    moved : numpy.ndarray
        (n,) bool, the starts whose explicit u2 was below flank 2 or undefined.

    Raises
    ------
    ValueError
        If the starts are not 1-D arrays of one length, ``phi1`` is not finite or matches neither
        one angle nor one per start, or ``n_bisect`` is not an integer.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, guard_reduced_starts
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> u1, moved = guard_reduced_starts(pair, 0.0, [31.0, 35.0], [0.0, 0.0])  # rad, mm, mm
    >>> np.round(u1, 4).tolist(), moved.tolist()  # the first start lay below flank 1's root (32.4194 mm)
    ([32.4194, 35.0], [True, False])
    """
    ph, u1, v1 = _start_pairs(phi1, u1, v1)
    check_integer("n_bisect", n_bisect)
    return _guard(pair, ph, u1.copy(), v1, n_bisect)


def _guard(pair, ph, u1, v1, n_bisect):
    lo_u2 = pair.lower2[0]

    def ok(u):
        with np.errstate(invalid="ignore", divide="ignore"):
            u2, _, phi2 = reduced_unknowns(pair, u, v1, ph)
        return np.isfinite(phi2) & (u2 >= lo_u2)

    bad = ~ok(u1)
    if np.any(bad):
        a = np.full(u1.shape, pair.lower1[0] + 1e-9 * (pair.upper1[0] - pair.lower1[0]))
        fixable = bad & ok(a)
        b = u1.copy()
        for _ in range(n_bisect):
            mid = 0.5 * (a + b)
            good = ok(mid)
            a = np.where(fixable & good, mid, a)
            b = np.where(fixable & ~good, mid, b)
        u1 = np.where(fixable, a, u1)
    return u1, bad


def transverse_stage(pair: GearPair, phi1, u1, v1, tol: float = 1e-10, maxiter: int = 50):
    """Move each start along the profile onto the instantaneous line of contact of the unmodified
    pair: solve (n_f1 x n_f2) . z_f = 0 for u1 at the start's own v1 (reduced relations eq 39-44).

    For involute spur and helical flanks this axial component is the transverse-plane mismatch of
    the normals, which vanishes on the plane of action; the remaining (v1) direction is the nearly
    flat valley along the contact line that crowning makes a point. ``phi1`` scalar or one angle
    per start. Returns (u1, iterations); rows that fail keep their u1.

    Parameters
    ----------
    pair : GearPair
        The pair; member 2 in explicit form.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad]: one, or one per start (finite).
    u1, v1 : (n,) array_like
        Starts on flank 1 [flank units, mm for involute flanks], 1-D of one length n >= 1.
    tol : float, optional
        Tolerance on the axial component of n_f1 x n_f2 [1] (> 0, finite).
    maxiter : int, optional
        Iteration limit of the 1-D damped Newton solve.

    Returns
    -------
    u1 : numpy.ndarray
        (n,) u1 on the contact line [flank units] (the start's own where the solve fails).
    iterations : numpy.ndarray
        (n,) iterations of the 1-D solve.

    Raises
    ------
    ValueError
        If the starts or angles are malformed (as :func:`guard_reduced_starts`), or the tolerance or
        iteration limit is bad.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, transverse_stage
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> u1, it = transverse_stage(pair, 0.0, [33.0, 37.0], [0.0, 5.0])  # rad, mm, mm
    >>> np.round(u1, 4).tolist()  # the contact line of the unmodified pair [mm]
    [35.3186, 35.3176]
    """
    ph, u1, v1 = _start_pairs(phi1, u1, v1)
    check_positive("tol", tol)
    check_integer("maxiter", maxiter)
    return _transverse(pair, ph, u1, v1, tol, maxiter)


def _transverse(pair, ph, u1, v1, tol, maxiter):
    def F(x, q):
        uu, vv, pp = x[:, 0], q[:, 0], q[:, 1]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            u2, v2, p2 = reduced_unknowns(pair, uu, vv, pp)
            _, n1 = pair.member1(uu, vv, pp)
            _, n2 = pair.member2(u2, v2, p2)
        return cross(n1, n2)[:, 2:3]

    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        r = newton_rows(
            F, None, u1[:, None], np.column_stack([v1, ph]), jacobian="numeric", tol=tol, maxiter=maxiter, damped=True
        )
    ok = r.status == Status.CONVERGED
    return np.where(ok, r.x[:, 0], u1), r.iterations


def robust_start(pair: GearPair, phi1, u1, v1):
    """Guarded start (:func:`guard_reduced_starts`) moved onto the contact line
    (:func:`transverse_stage`). Returns (u1, iterations of the 1-D stage).

    Parameters
    ----------
    pair : GearPair
        The pair; member 2 in explicit form.
    phi1 : float or (n,) array_like
        Angles of member 1 [rad]: one, or one per start (finite).
    u1, v1 : (n,) array_like
        Starts on flank 1 [flank units, mm for involute flanks], 1-D of one length n >= 1.

    Returns
    -------
    u1 : numpy.ndarray
        (n,) moved u1 [flank units].
    iterations : numpy.ndarray
        (n,) iterations of the 1-D stage.

    Raises
    ------
    ValueError
        If the starts or angles are malformed (as :func:`guard_reduced_starts`).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, robust_start
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> u1, it = robust_start(pair, 0.0, [33.0, 37.0], [0.0, 5.0])  # rad, mm, mm
    >>> np.round(u1, 4).tolist()
    [35.3186, 35.3176]
    """
    ph, u1, v1 = _start_pairs(phi1, u1, v1)
    u1g, _ = _guard(pair, ph, u1.copy(), v1, 40)
    return _transverse(pair, ph, u1g, v1, 1e-10, 50)


def solve_reduced(pair: GearPair, phi1: float, u1, v1, *, variant: str = "reduced", tol=1e-12, maxiter=50):
    """Reduced TCA (:func:`solve_contact`) from (u1, v1) starts with solver ``variant``
    (:data:`REDUCED_VARIANTS`). Returns (x (n, 5) = (u1, v1, u2, v2, phi2), status, iterations,
    residual); the iterations of the transverse stage are included.

    Parameters
    ----------
    pair : GearPair
        The pair; member 2 in explicit form.
    phi1 : float
        The angle of member 1 [rad].
    u1, v1 : (n,) array_like
        Starts on flank 1 [flank units, mm for involute flanks].
    variant : str, optional
        One of :data:`REDUCED_VARIANTS`.
    tol : float, optional
        Residual tolerance of the solve [1, components of n_f1 x n_f2].
    maxiter : int, optional
        Iteration limit.

    Returns
    -------
    x : numpy.ndarray
        (n, 5) (u1, v1, u2, v2, phi2) [flank units, rad]; NaN where the row did not converge.
    status : numpy.ndarray
        (n,) :class:`gearrep.solve.Status` codes.
    iterations : numpy.ndarray
        (n,) Newton iterations, the transverse stage's included.
    residual : numpy.ndarray
        (n,) final residual norms.

    Raises
    ------
    ValueError
        If ``variant`` is unknown (and, from the solve, on bad starts, angle or solver settings).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import GearPair, solve_reduced
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> x, status, it, res = solve_reduced(pair, 0.0, [33.0, 37.0], [-10.0, 12.0], variant="reduced_robust")
    >>> status.tolist(), np.round(x[:, 0], 4).tolist()  # both converged to the one contact, u1 [mm]
    ([0, 0], [35.3186, 35.3186])
    """
    if variant not in REDUCED_VARIANTS:
        raise ValueError(f"variant must be one of {REDUCED_VARIANTS}, got {variant!r}")
    u1 = np.asarray(u1, float)
    v1 = np.asarray(v1, float)
    extra = np.zeros(u1.shape, dtype=int)
    if variant == "reduced_robust":
        u1, extra = robust_start(pair, phi1, u1, v1)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        c = solve_contact(
            pair,
            phi1,
            np.column_stack([u1, v1]),
            formulation="reduced",
            damped=(variant == "reduced_damped"),
            tol=tol,
            maxiter=maxiter,
        )
    return c.unknowns("conventional"), c.status, c.iterations + extra, c.residual


def solve_variant(
    pair: GearPair,
    phi1: float,
    starts,
    variant: str,
    *,
    equations: str = "five",
    drop: int = 0,
    tol: float = 1e-12,
    maxiter: int = 50,
    margin: float = 1e-6,
):
    """Solve conventional starts ``starts`` (n, 5) with any variant of either formulation (the
    reduced ones use only the (u1, v1) columns). Returns (x (n, 5), status, iterations); a seeded
    or robust start whose seed is undefined (u2 inside the base circle of member 2) is DIVERGED.

    Parameters
    ----------
    pair : GearPair
        The pair.
    phi1 : float
        The angle of member 1 [rad], one finite angle.
    starts : (n, 5) array_like
        Conventional starts (u1, v1, u2, v2, phi2) [flank units (mm for involute flanks), rad].
    variant : str
        One of :data:`CONVENTIONAL_VARIANTS` or :data:`REDUCED_VARIANTS`.
    equations, drop, margin : optional
        The conventional system and the ``domain`` margin, as in :func:`solve_conventional`.
    tol : float, optional
        Residual tolerance [flank units for the conventional system, 1 for the reduced].
    maxiter : int, optional
        Iteration limit.

    Returns
    -------
    x : numpy.ndarray
        (n, 5) solved unknowns [flank units, rad].
    status : numpy.ndarray
        (n,) :class:`gearrep.solve.Status` codes.
    iterations : numpy.ndarray
        (n,) iterations, a start stage's included.

    Raises
    ------
    ValueError
        Before any solve: an unknown variant, ``phi1`` not one finite angle, ``starts`` not (n, 5),
        or bad solver settings (:func:`solve_conventional`).

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
    >>> from gearrep.tca import CONVENTIONAL_VARIANTS, REDUCED_VARIANTS, GearPair, solve_variant
    >>> g1, g2 = (InvoluteGearData(n, 3.0, math.radians(20), 25.0) for n in (23, 41))  # module mm, rad, face mm
    >>> pair = GearPair(*mating_flanks(g1, g2, crowning1=ParabolicCrowning(1e-4)), 23, 41, g1.r_p + g2.r_p)
    >>> starts = np.array([[33.0, -10.0, 60.0, 5.0, 0.0], [37.0, 12.0, 60.0, -5.0, 0.0]])  # mm, rad
    >>> for variant in CONVENTIONAL_VARIANTS + REDUCED_VARIANTS:
    ...     x, status, it = solve_variant(pair, 0.0, starts, variant)
    ...     print(variant, status.tolist(), np.round(x[:, 0], 4).tolist())
    plain [0, 0] [35.3186, 35.3186]
    damped [0, 0] [35.3186, 35.3186]
    domain [0, 0] [35.3186, 35.3186]
    seeded [0, 0] [35.3186, 35.3186]
    robust [0, 0] [35.3186, 35.3186]
    reduced [0, 0] [35.3186, 35.3186]
    reduced_damped [0, 0] [35.3186, 35.3186]
    reduced_robust [0, 0] [35.3186, 35.3186]
    """
    if variant not in CONVENTIONAL_VARIANTS + REDUCED_VARIANTS:
        raise ValueError(f"variant must be one of {CONVENTIONAL_VARIANTS + REDUCED_VARIANTS}, got {variant!r}")
    phi1 = _one_angle(phi1)
    starts = _starts5(starts, "starts")
    if variant in REDUCED_VARIANTS:
        x, status, iters, _ = solve_reduced(
            pair, phi1, starts[:, 0], starts[:, 1], variant=variant, tol=tol, maxiter=maxiter
        )
        return x, status, np.asarray(iters)
    x0, extra = starts, 0
    if variant == "seeded":
        x0 = seed_from_reduced(pair, phi1, starts[:, 0], starts[:, 1])
    elif variant == "robust":
        u1r, extra = robust_start(pair, phi1, starts[:, 0], starts[:, 1])
        x0 = seed_from_reduced(pair, phi1, u1r, starts[:, 1])
    r = solve_conventional(
        pair, phi1, x0, variant=variant, equations=equations, drop=drop, tol=tol, maxiter=maxiter, margin=margin
    )
    status = r.status
    if variant in ("seeded", "robust"):
        status = np.where(np.all(np.isfinite(x0), axis=1), status, int(Status.DIVERGED))
    return r.x, status, np.asarray(r.iterations + extra)
