"""Envelopes of one- and two-parameter families of surfaces, and their singular points.

A tool surface r_1(u, v), given in its own frame S_1, is carried into the frame S_2 of the
generated member by a rigid motion M_21(m) that depends on k = 1 or 2 motion parameters
m = (m_1, ..., m_k). The family and the equations of meshing are

    r_2(u, v, m) = M_21(m) r_1(u, v)                                            (F)
    f_j(u, v, m) = n_1 . v^(12, j) = 0,   j = 1..k                              (E)

with n_1 = unit(r_u x r_v) the tool normal and v^(12, j) = d r_2 / d m_j the velocity of the
tool point relative to the generated member when m_j alone varies. Sources:

* one-parameter family: Litvin & Fuentes, *Gear Geometry and Applied Theory* (GGAT), 2nd ed.,
  ch. 6 (family of surfaces, equation of meshing n . v^(12) = 0); seed 002 eq 2.2.6-2.2.9 and
  2.3.5-2.3.6 (rack-cutter generation, where (E) reduces to (r_p psi - y) N_x + x N_y = 0);

* two-parameter family: seed 000 eq 4.3-4.5 (the hob surface moved by (theta, psi)).

All vectors are evaluated in S_1 (the tool frame) and rotated into S_2 at the end. With
W_j = M_21^{-1} dM_21/dm_j (a twist: rotation part Omega_j = [omega_j]_x, translation t_j),
the relative velocity in S_1 is w_j = Omega_j r_1 + t_j, and f_j = n_1 . w_j.

Generated surface. The 2 + k parameters q = (u, v, m) satisfy k equations, so two of them
(``free``) parameterise the envelope and the other k (``solved``) follow from (E) by
:func:`gearrep.solve.newton`. Seed 000 (docs/reading-notes.md, 000-C) needs free = (l, psi), solved =
(phi, theta), because the Jacobian of (E) in (theta, psi) is singular at mid-face; any choice
is allowed here. The first derivatives of the generated surface are analytic (implicit
differentiation: dq_S/dq_F = -(df/dq_S)^{-1} df/dq_F). Every partial derivative of r_2 with
respect to q is tangent to the surface at the contact point (r_u, r_v are tool tangents; the
v^(12, j) are tangent by (E)), so the NORMAL components of the second derivatives need no
second derivatives of the solved parameters and are analytic too: the second fundamental form,
hence every curvature, is exact to rounding. The tangential components of the second
derivatives contain d^2 q_S / dq_F^2, taken by 4th-order central differences of the analytic
first derivatives (error ~ h^4 + eps/h, about 1e-11 relative with the default steps).

Singular points (undercutting). GGAT ch. 6 (and seed 002 sec. 2.4): a point of the generated
surface is singular when the contact point can move on the tool and in the motion without
moving on the generated surface, i.e. when the system

    r_u du + r_v dv + sum_j v^(12, j) dm_j = 0        (2 tangential components)
    df_j = f_ju du + f_jv dv + sum_i f_j,mi dm_i = 0   (k equations)

has a nonzero solution. Its (2 + k)-square matrix is Litvin's determinant test (for k = 1 the
3 x 3 determinant of GGAT ch. 6: rows (r_u, r_v, v^(12)) projected on the tangent plane and
(f_u, f_v, f_phi)). Equivalently the k x k matrix E of :mod:`gearrep.curvature_relations`
(Litvin's a_33 for k = 1) is singular, or the generated surface's tangent vectors are linearly
dependent. :func:`singular_points` solves (E) together with det = 0 (Litvin's limiting line on
the tool surface).

The motions live in :mod:`gearrep.motion` (re-exported here, the names of this module's face).

Usage (the two-parameter hob set-up of seed 000; tool parameters are always called u, v):

    motion = ChainMotion([rotation((0, 0, 1), [1 / N, 0]),            # gear turns theta / N
                          rotation((1, 0, 0), [0, 1], point=(E, R_c, 0)),  # swivel psi
                          translation((1, 0, 0), [0, 0], offset=E),        # centre distance
                          rotation((1, 0, 0), [0, 0], offset=-pi / 2 + lam),
                          rotation((0, 0, 1), [1, 0])],                    # hob spin theta

                         names=("theta", "psi"))

    env = Envelope(hob, motion, free=("u", "psi"))    # generated surface r(l, psi)
    rec = env.solve(l, psi, guess=[pi, 0.0])          # EnvelopeResult (status per point)
    surf = env.surface(guess=[pi, 0.0])               # a Surface of (l, psi)
    gc = gearrep.curvature_relations.generated_curvatures(env, rec.params)

(tests/unit/_envelope_cases.py builds this with a ZA-type thread; it reproduces the k_q column
of seed 000 Table 4.3/4.4 at l = 4.38148 and 10.354, but the k_s of the concave flank: its swivel
centre at +R_c makes the upper-sign thread cut the concave side, and k_q at mid-face does not
depend on the tooth trace while k_s does. The tables' convex flank needs the centre at -R_c;
:class:`gearrep.surfaces.hob.GeneratedGear` with ``arc_centre=-1`` reproduces both columns, see
tests/unit/surfaces/test_hob.py::test_hob_case_is_the_other_arc_centre.)
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from ._envelope_records import EnvelopeResult, LocalGeometry
from .inputs import check_integer, check_positive
from .motion import *  # noqa: F403  (the motions are part of this module's face, re-exported)
from .motion import TOOL_NAMES, Motion
from .motion import __all__ as _MOTION_NAMES
from .solve import SolveResult, Status, newton
from .surface import D1_OFFSETS, D1_WEIGHTS, Surface, SurfacePoint, cross

__all__ = [
    *_MOTION_NAMES,
    "EnvelopeResult",
    "Envelope",
    "EnvelopeSurface",
    "singular_points",
    "LocalGeometry",
    "local_geometry",
]


# --------------------------------------------------------------------------------------------
# local envelope geometry
# --------------------------------------------------------------------------------------------
def local_geometry(tool: Surface, motion: Motion, q: np.ndarray) -> LocalGeometry:
    """:meth:`Envelope.local` without input validation, for use inside a solver's iterations: a
    non-finite row of ``q`` (n, 2+k) gives non-finite outputs in that row (which
    :func:`gearrep.solve.newton` reports as DIVERGED) instead of raising for the whole batch.

    Parameters
    ----------
    tool : gearrep.surface.Surface
        The tool surface.
    motion : gearrep.motion.Motion
        The motion.
    q : (n, 2+k) array_like
        Parameters (u, v, m).

    Returns
    -------
    LocalGeometry
        The local quantities (read-only arrays for up to 256 points).

    Examples
    --------
    >>> import math
    >>> from gearrep.envelope import local_geometry, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> loc = local_geometry(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0), [[0.0, 0.0, 0.0]])
    >>> loc.f.tolist()  # the rack's pitch point meshes at phi = 0 [mm]
    [[0.0]]
    """
    return _local(tool, motion, np.asarray(q, dtype=float))


#: the local geometries of the last few small batches, newest first: [tool, motion, q's shape and
#: bytes, LocalGeometry, its rows by bytes (formed when first needed; :data:`_GATHERED` for one
#: assembled from others' rows)]. A solve's record, a TCA's
#: finish and the generated curvatures evaluate the converged iterate again: a third of the calls
#: of the seed 000 and NASA jobs repeat one of the four before (measured), and a batch solve's
#: record gathers rows its iterations evaluated in different batches (rows converge at different
#: iterations). The tool and motion are held, so their identities stay theirs (a tool or motion is
#: not changed after it is made: none of the library's is); the arrays are read-only, so that no
#: caller can change what another receives.
_RECENT: list = []
_RECENT_SIZE = 4
_RECENT_MAX_ROWS = 256


def _local(tool: Surface, motion: Motion, q: np.ndarray) -> LocalGeometry:
    """:func:`_local_geometry`, or the same values again where one of the last few calls had this
    tool, motion and q (:data:`_RECENT`); a q whose rows they hold in part is assembled from their
    rows and only the others are evaluated."""
    if q.ndim != 2 or q.shape[0] > _RECENT_MAX_ROWS:
        return _local_geometry(tool, motion, q)
    key = q.tobytes()
    mine = [entry for entry in _RECENT if entry[0] is tool and entry[1] is motion]
    for entry in mine:
        if entry[2] == q.shape and entry[3] == key:
            return entry[4]
    held = [entry for entry in mine if entry[5] is not _GATHERED]
    loc = _from_rows(held, q) if held else None
    rows = None if loc is None else _GATHERED  # a gathered one is found again whole, not by rows
    if loc is None:
        loc = _local_geometry(tool, motion, q)
    for a in (*(getattr(loc, f.name) for f in fields(loc)), *(getattr(loc.tool, f.name) for f in fields(loc.tool))):
        if isinstance(a, np.ndarray):
            a.flags.writeable = False
    _RECENT.insert(0, [tool, motion, q.shape, key, loc, rows])
    del _RECENT[_RECENT_SIZE:]
    return loc


#: the rows entry of a :data:`_RECENT` geometry gathered from others' rows (its rows are theirs)
_GATHERED = ()


def _from_rows(entries, q):
    """The local geometry at q gathered from the rows of recent ones (``entries`` of
    :data:`_RECENT`, one tool and motion) that have the same parameters, bit for bit, and
    evaluated at the rest; None where no row is held. Rows are matched by their bytes (as fixed
    length byte strings, sorted once per entry)."""
    width = f"S{q.dtype.itemsize * q.shape[1]}"
    keys = np.ascontiguousarray(q).view(width)[:, 0]
    where = np.full(len(q), -1)
    at = np.zeros(len(q), dtype=int)
    for e, entry in enumerate(entries):
        if entry[5] is None:  # the entry's rows as byte strings, sorted, with their order
            stored = np.frombuffer(entry[3], dtype=float).reshape(entry[2]).view(width)[:, 0]
            order = np.argsort(stored, kind="stable")
            entry[5] = (stored[order], order)
        ks, order = entry[5]
        pos = np.minimum(np.searchsorted(ks, keys), len(ks) - 1)
        hit = (ks[pos] == keys) & (where < 0)
        where[hit], at[hit] = e, order[pos[hit]]
    if not np.any(where >= 0):
        return None
    sources = [(entries[e][4], where == e) for e in range(len(entries)) if np.any(where == e)]
    missing = where < 0
    if missing.any():
        sources.append((_local_geometry(entries[0][0], entries[0][1], q[missing]), missing))
        at[missing] = np.arange(missing.sum())

    def gather(name, part=None):
        parts = [(getattr(src if part is None else getattr(src, part), name), rows) for src, rows in sources]
        out = np.empty((len(q),) + parts[0][0].shape[1:])
        for arr, rows in parts:
            out[rows] = arr[at[rows]]
        return out

    tool = SurfacePoint(*(gather(f.name, "tool") for f in fields(SurfacePoint)))
    return LocalGeometry(*(tool if f.name == "tool" else gather(f.name) for f in fields(LocalGeometry)))


def _local_geometry(tool: Surface, motion: Motion, q: np.ndarray) -> LocalGeometry:
    k = motion.n_params
    u, v, m = q[:, 0], q[:, 1], q[:, 2:]
    p = tool.evaluate(u, v)
    tw = motion.twists(m)  # M^-1 dM = (omega x) + v, M^-1 d2M on tool points (gearrep.motion)
    omega = tw.omega
    r = p.r
    w = cross(omega, r[:, None, :]) + tw.v
    Xr = tw.second(r)
    N = cross(p.r_u, p.r_v)
    Nn = np.sqrt(np.sum(N * N, axis=-1, keepdims=True))
    n = N / Nn
    f = np.sum(n[:, None, :] * w, axis=-1)
    # derivatives of the unit normal: n_x = (I - n n^T) N_x / |N|
    N_u = cross(p.r_uu, p.r_v) + cross(p.r_u, p.r_uv)
    N_v = cross(p.r_uv, p.r_v) + cross(p.r_u, p.r_vv)

    def dn(Nx):
        return (Nx - n * np.sum(n * Nx, -1, keepdims=True)) / Nn

    n_u, n_v = dn(N_u), dn(N_v)
    Om_ru = cross(omega, p.r_u[:, None, :])
    Om_rv = cross(omega, p.r_v[:, None, :])
    f_u = np.sum(n_u[:, None, :] * w, axis=-1) + np.sum(n[:, None, :] * Om_ru, axis=-1)
    f_v = np.sum(n_v[:, None, :] * w, axis=-1) + np.sum(n[:, None, :] * Om_rv, axis=-1)
    # df_j/dm_i = n . (X_ij r_h) - n . (omega_i x w_j), the second term omega_i . (w_j x n)
    nX = (Xr.reshape(len(q), k * k, 3) @ n[:, :, None]).reshape(len(q), k, k)
    f_m = np.swapaxes(nX - omega @ np.swapaxes(cross(w, n[:, None, :]), 1, 2), 1, 2)
    J = np.concatenate([f_u[..., None], f_v[..., None], f_m], axis=-1)
    T = np.concatenate([p.r_u[:, None], p.r_v[:, None], w], axis=1)
    nq = 2 + k
    H = np.zeros((q.shape[0], nq, nq, 3))
    H[:, 0, 0], H[:, 0, 1], H[:, 1, 0], H[:, 1, 1] = p.r_uu, p.r_uv, p.r_uv, p.r_vv
    H[:, 0, 2:], H[:, 2:, 0] = Om_ru, Om_ru
    H[:, 1, 2:], H[:, 2:, 1] = Om_rv, Om_rv
    H[:, 2:, 2:] = Xr
    n_q = np.concatenate([n_u[:, None], n_v[:, None], cross(omega, n[:, None, :])], axis=1)
    return LocalGeometry(tw.M, p, N, n, w, omega, Xr, f, J, T, H, n_q)


# --------------------------------------------------------------------------------------------
# singularity of the generated surface (Litvin's matrix)
# --------------------------------------------------------------------------------------------
def _litvin_matrix(loc: LocalGeometry):
    """Litvin's singularity matrix [[T . t1], [T . t2], [J]] ((2+k)-square) per point."""
    t1 = loc.tool.r_u / np.linalg.norm(loc.tool.r_u, axis=-1, keepdims=True)
    t2 = cross(loc.n, t1)
    A = np.concatenate(
        [np.einsum("nqa,na->nq", loc.T, t1)[:, None], np.einsum("nqa,na->nq", loc.T, t2)[:, None], loc.J], axis=1
    )
    return A


def _singularity(loc: LocalGeometry):
    """(singular_measure, litvin_det); NaN where the local data are not finite."""
    A = _litvin_matrix(loc)
    ok = np.all(np.isfinite(A), axis=(1, 2))
    meas = np.full(A.shape[0], np.nan)
    det = np.full(A.shape[0], np.nan)
    if np.any(ok):
        Ao = A[ok]
        det[ok] = np.linalg.det(Ao)
        scale = np.linalg.norm(Ao, axis=-1, keepdims=True)
        s = np.linalg.svd(Ao / np.where(scale > 0, scale, 1.0), compute_uv=False)
        with np.errstate(divide="ignore", invalid="ignore"):
            meas[ok] = np.where(s[:, 0] > 0, s[:, -1] / np.where(s[:, 0] > 0, s[:, 0], 1.0), 0.0)
    return meas, det


# --------------------------------------------------------------------------------------------
# the envelope
# --------------------------------------------------------------------------------------------
class Envelope:
    """Envelope of the family r_2(u, v, m) = M_21(m) r_1(u, v) (eq F, E of the module doc).

    Parameters
    ----------
    tool : gearrep.surface.Surface
        The generating surface (in S_1).
    motion : Motion
        k = 1 or 2 parameters.
    free : (str or int, str or int), optional
        The two parameters (names or indices into ("u", "v") + motion.names) that parameterise the
        generated surface; the other k are solved from the meshing equations.
    lower, upper : array_like, optional
        Bounds of the SOLVED parameters (k,), giving status OFF_FLANK outside.
    tol : float, optional
        Passed to :func:`gearrep.solve.newton`: tolerance on the meshing residual (whose unit is
        length for a rotation parameter).
    maxiter : int, optional
        Passed to :func:`gearrep.solve.newton`.
    singular_tol : float, optional
        Threshold on ``singular_measure`` for the ``singular`` flag, >= 0.

    Raises
    ------
    ValueError
        If the tool, motion, free parameters, bounds or solver settings are bad.

    Examples
    --------
    A straight rack (20 deg) generating a gear of pitch radius 30 mm:

    >>> import math
    >>> import numpy as np
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0), free=("u", "v"))
    >>> env.free_names, env.solved_names
    (('u', 'v'), ('phi',))
    >>> rec = env.solve(1.0, 0.0, guess=0.0)  # u [mm], v [mm]
    >>> np.round(rec.point, 5).tolist(), bool(abs(env.meshing(rec.params)[0, 0]) < 1e-12)  # mm
    ([[31.04409, 0.44108, 0.0]], True)
    """

    def __init__(
        self,
        tool: Surface,
        motion: Motion,
        free=("u", "v"),
        *,
        lower=None,
        upper=None,
        tol: float = 1e-12,
        maxiter: int = 50,
        singular_tol: float = 1e-6,
    ):
        if not isinstance(tool, Surface):
            raise ValueError("tool must be a gearrep.surface.Surface")
        if not isinstance(motion, Motion) or motion.n_params not in (1, 2):
            raise ValueError("motion must be a gearrep.envelope.Motion with 1 or 2 parameters")
        self.tool, self.motion = tool, motion
        self.k = motion.n_params
        self.names = TOOL_NAMES + tuple(motion.names)
        idx = []
        for f in free:
            if isinstance(f, str):
                if f not in self.names:
                    raise ValueError(f"free must name parameters among {self.names}, got {f!r}")
                idx.append(self.names.index(f))
            else:
                i = int(f)
                if not 0 <= i < len(self.names):
                    raise ValueError(f"free index must be in [0, {len(self.names) - 1}], got {f!r}")
                idx.append(i)
        if len(idx) != 2 or idx[0] == idx[1]:
            raise ValueError(f"free must be two distinct parameters, got {free!r}")
        self.free = tuple(idx)
        self.solved = tuple(i for i in range(2 + self.k) if i not in idx)
        try:
            self.lower = None if lower is None else np.broadcast_to(np.asarray(lower, float), (self.k,))
            self.upper = None if upper is None else np.broadcast_to(np.asarray(upper, float), (self.k,))
        except ValueError:
            raise ValueError(f"lower and upper must broadcast to ({self.k},) (one per solved parameter)") from None
        check_positive("tol", tol)
        if not (singular_tol >= 0):
            raise ValueError(f"singular_tol must be >= 0, got {singular_tol!r}")
        maxiter = check_integer("maxiter", maxiter)
        self.tol, self.maxiter, self.singular_tol = float(tol), maxiter, float(singular_tol)

    # ---- basic evaluations --------------------------------------------------------------
    def _q(self, q):
        q = np.asarray(q, dtype=float)
        if q.shape[-1] != 2 + self.k:
            raise ValueError(f"q must have last dimension {2 + self.k} ({self.names}), got {q.shape}")
        return q

    def meshing(self, q) -> np.ndarray:
        """Equations of meshing f_j = n_1 . v^(12, j) (eq E; seed 000 eq 4.4-4.5;
        seed 002 eq 2.2.7) at q (..., 2+k) -> (..., k).

        Parameters
        ----------
        q : array_like
            (..., 2+k) parameters (u, v, m).

        Returns
        -------
        numpy.ndarray
            (..., k) [length per unit of m].
        """
        q = self._q(q)
        flat = q.reshape(-1, 2 + self.k)
        return np.array(_local(self.tool, self.motion, flat).f).reshape(q.shape[:-1] + (self.k,))

    def meshing_jacobian(self, q) -> np.ndarray:
        """Partial derivatives of the meshing functions in q: (..., k, 2+k).

        Parameters
        ----------
        q : array_like
            (..., 2+k) parameters.

        Returns
        -------
        numpy.ndarray
            (..., k, 2+k).
        """
        q = self._q(q)
        flat = q.reshape(-1, 2 + self.k)
        return np.array(_local(self.tool, self.motion, flat).J).reshape(q.shape[:-1] + (self.k, 2 + self.k))

    def family(self, q) -> np.ndarray:
        """Family of tool surfaces in S_2, r_2 = M_21(m) r_1(u, v) (eq F) at q -> (..., 3).

        Parameters
        ----------
        q : array_like
            (..., 2+k) parameters.

        Returns
        -------
        numpy.ndarray
            (..., 3) points [length].
        """
        q = self._q(q)
        flat = q.reshape(-1, 2 + self.k)
        r = self.tool.position(flat[:, 0], flat[:, 1])
        M, _, _ = self.motion.matrices(flat[:, 2:])
        out = np.einsum("nab,nb->na", M[:, :3, :3], r) + M[:, :3, 3]
        return out.reshape(q.shape[:-1] + (3,))

    def local(self, q) -> LocalGeometry:
        """All local quantities at flat q (n, 2+k) (vectors in the tool frame S_1): the tool
        point and derivatives, unit normal, w_j = v^(12, j), omega_j, the meshing functions and
        their Jacobian (used by :mod:`gearrep.curvature_relations`). For up to 256 points the arrays
        are read-only: the same geometry is returned to a repeated call (copy one to change it).

        Parameters
        ----------
        q : array_like
            (n, 2+k) finite parameters.

        Returns
        -------
        LocalGeometry
            The local quantities.

        Raises
        ------
        ValueError
            If ``q`` has the wrong shape or is not finite.
        """
        q = np.atleast_2d(self._q(q))
        if q.ndim != 2 or not np.all(np.isfinite(q)):
            raise ValueError(f"q must be a finite (n, {2 + self.k}) array")
        return _local(self.tool, self.motion, q)

    # ---- solving ------------------------------------------------------------------------
    def _assemble(self, a, b, xs):
        n = xs.shape[0]
        q = np.empty((n, 2 + self.k))
        q[:, self.free[0]], q[:, self.free[1]] = a, b
        q[:, list(self.solved)] = xs
        return q

    def _solve_flat(self, a, b, x0):
        S = list(self.solved)

        def fun(x, idx):
            return _local(self.tool, self.motion, self._assemble(a[idx], b[idx], x)).f

        def fun_jac(x, idx):  # the local geometry gives both: one evaluation per full step
            loc = _local(self.tool, self.motion, self._assemble(a[idx], b[idx], x))
            return loc.f, loc.J[:, :, S]

        def jac(x, idx):
            return fun_jac(x, idx)[1]

        res = newton(
            fun,
            x0,
            jac,
            tol=self.tol,
            maxiter=self.maxiter,
            lower=self.lower,
            upper=self.upper,
            rows=True,
            fun_jac=fun_jac,
        )
        return res, self._assemble(a, b, res.x)

    def _free_values(self, a, b):
        try:
            a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
        except ValueError:
            raise ValueError("the two free parameter arrays must broadcast to a common shape") from None
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            raise ValueError(f"free parameters {self.free_names} must be finite")
        return a, b

    def _guess(self, guess, a, b):
        if guess is None:
            raise ValueError(f"guess for the solved parameters {self.solved_names} is required")
        g = guess(a, b) if callable(guess) else guess
        g = np.asarray(g, dtype=float)
        if not np.all(np.isfinite(g)):
            raise ValueError(f"guess for {self.solved_names} must be finite")
        if self.k == 1 and (g.ndim == 0 or g.shape[-1] != 1):
            g = g[..., None]
        try:
            return np.broadcast_to(g, a.shape + (self.k,)).reshape(-1, self.k).copy()
        except ValueError:
            raise ValueError(f"guess must broadcast to {a.shape + (self.k,)}, got shape {g.shape}") from None

    @property
    def free_names(self):
        """Names of the two free parameters."""
        return tuple(self.names[i] for i in self.free)

    @property
    def solved_names(self):
        """Names of the k solved parameters."""
        return tuple(self.names[i] for i in self.solved)

    def _derivs(self, loc: LocalGeometry):
        """dq/dq_F (n, 2+k, 2) by implicit differentiation of the meshing equations."""
        n = loc.J.shape[0]
        JS = loc.J[:, :, list(self.solved)]
        JF = loc.J[:, :, list(self.free)]
        D = np.zeros((n, 2 + self.k, 2))
        D[:, self.free[0], 0] = 1.0
        D[:, self.free[1], 1] = 1.0
        ok = np.all(np.isfinite(loc.J), axis=(1, 2))
        ok[ok] = np.abs(np.linalg.det(JS[ok])) > 0
        sol = np.full((n, self.k, 2), np.nan)
        if np.any(ok):
            sol[ok] = -np.linalg.solve(JS[ok], JF[ok])
        D[:, list(self.solved), :] = sol
        return D

    def solve(self, a, b, guess=None) -> EnvelopeResult:
        """Solve the meshing equations for the solved parameters at free values (a, b).

        Parameters
        ----------
        a, b : float or array_like
            Free parameter values, broadcast to a common shape S (finite).
        guess : callable or array_like
            Start of the Newton iteration: (a, b) -> S + (k,), or an array broadcastable to it.

        Returns
        -------
        EnvelopeResult
            n = prod(S) points (flattened, C order).
        """
        a, b = self._free_values(a, b)
        x0 = self._guess(guess, a, b)
        af, bf = a.reshape(-1), b.reshape(-1)
        res, q = self._solve_flat(af, bf, x0)
        return self._record(q, res)

    def _record(self, q, res):
        loc = _local(self.tool, self.motion, q)
        D = self._derivs(loc)
        R = loc.M[:, :3, :3]
        point = np.einsum("nab,nb->na", R, loc.tool.r) + loc.M[:, :3, 3]
        normal = np.einsum("nab,nb->na", R, loc.n)
        tan1 = np.einsum("nqa,nqf->nfa", loc.T, D)
        tangents = np.einsum("nab,nfb->nfa", R, tan1)
        meas, det = _singularity(loc)
        return EnvelopeResult(
            self.names, q, point, normal, tangents, meas, np.nan_to_num(meas, nan=np.inf) < self.singular_tol, det, res
        )

    def at(self, q) -> EnvelopeResult:
        """Record at given full parameters q (n, 2+k) without solving (status CONVERGED where
        the meshing residual is below ``tol``, NOT_CONVERGED elsewhere).

        Parameters
        ----------
        q : array_like
            (n, 2+k) parameters.

        Returns
        -------
        EnvelopeResult
            The record.
        """
        q = np.atleast_2d(self._q(q)).astype(float)
        f = self.meshing(q)
        r = np.linalg.norm(f, axis=-1)
        st = np.where(r < self.tol, int(Status.CONVERGED), int(Status.NOT_CONVERGED))
        res = SolveResult(q[:, list(self.solved)], r, np.zeros(len(r), int), st)
        return self._record(q, res)

    def surface(self, guess, fd_step=(1e-3, 1e-3)) -> EnvelopeSurface:
        """The generated surface as a :class:`gearrep.surface.Surface` of the two free
        parameters (see :class:`EnvelopeSurface`).

        Parameters
        ----------
        guess : callable or array_like
            Start of the solves (:meth:`solve`).
        fd_step : (float, float), optional
            Steps of the finite differences [units of the free parameters].

        Returns
        -------
        EnvelopeSurface
            The surface.
        """
        return EnvelopeSurface(self, guess, fd_step)


class EnvelopeSurface(Surface):
    """The envelope as a Surface r(a, b) of the two free parameters of an :class:`Envelope`.

    ``position`` solves the meshing equations (NaN where the solve fails; OFF_FLANK points are
    returned). ``evaluate`` returns analytic first derivatives and second derivatives whose
    normal components are analytic (so curvatures are exact to rounding); their tangential
    components use 4th-order central differences of the analytic first derivatives with steps
    ``fd_step`` (error ~ h^4 + 1e-16/h relative). Its normal unit(r_a x r_b) is +- the tool
    normal; compare with :meth:`EnvelopeSurface.solve` (``normal``) to know which.

    Parameters
    ----------
    envelope : Envelope
        The envelope.
    guess : callable or array_like
        Start of the solves (:meth:`Envelope.solve`).
    fd_step : (float, float), optional
        Positive steps [units of the free parameters].

    Raises
    ------
    ValueError
        If ``envelope`` is not an :class:`Envelope` or a step is not > 0.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0))  # rad, r_p mm
    >>> surface = env.surface(guess=0.0)
    >>> np.round(surface.position(1.0, 0.0), 5).tolist()  # u [mm], v [mm] -> mm
    [31.04409, 0.44108, 0.0]
    """

    def __init__(self, envelope: Envelope, guess, fd_step=(1e-3, 1e-3)):
        if not isinstance(envelope, Envelope):
            raise ValueError("envelope must be a gearrep.envelope.Envelope")
        h = tuple(float(x) for x in np.broadcast_to(np.asarray(fd_step, float), (2,)))
        if not all(x > 0 for x in h):
            raise ValueError(f"fd_step must be two positive steps, got {fd_step!r}")
        self.envelope, self.guess, self.fd_step = envelope, guess, h

    def solve(self, u, v) -> EnvelopeResult:
        """The :class:`EnvelopeResult` at free parameters (u, v).

        Parameters
        ----------
        u, v : float or array_like
            Free parameter values.

        Returns
        -------
        EnvelopeResult
            The solve.
        """
        return self.envelope.solve(u, v, self.guess)

    def position(self, u, v):
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        rec = self.solve(u, v)
        ok = np.isin(rec.status, (int(Status.CONVERGED), int(Status.OFF_FLANK)))
        pts = np.where(ok[:, None], rec.point, np.nan)
        return pts.reshape(u.shape + (3,))

    def evaluate(self, u, v) -> SurfacePoint:
        env = self.envelope
        u, v = env._free_values(u, v)
        shape = u.shape
        a, b = u.reshape(-1), v.reshape(-1)
        S = list(env.solved)
        res, q = env._solve_flat(a, b, env._guess(self.guess, u, v))
        bad = ~np.isin(res.status, (int(Status.CONVERGED), int(Status.OFF_FLANK)))
        loc = _local(env.tool, env.motion, q)
        D = env._derivs(loc)
        # D at shifted free parameters, warm-started by the first-order predictor
        shifted = {}
        for d, h in enumerate(self.fd_step):
            for o in (-2, -1, 1, 2):
                da, db = (o * h, 0.0) if d == 0 else (0.0, o * h)
                x0 = q[:, S] + D[:, S, d] * (o * h)
                r2, q2 = env._solve_flat(a + da, b + db, x0)
                bad |= ~np.isin(r2.status, (int(Status.CONVERGED), int(Status.OFF_FLANK)))
                shifted[(d, o)] = env._derivs(_local(env.tool, env.motion, q2))
        # second derivatives of the solved parameters: d/d(free_d) of D[..., e]
        D2 = np.zeros((a.size, 2 + env.k, 2, 2))
        for d, h in enumerate(self.fd_step):
            dD = sum(w * shifted[(d, int(o))] for w, o in zip(D1_WEIGHTS, D1_OFFSETS)) / h  # d/d(free_d) of D
            D2[:, :, :, d] = dD
        D2 = 0.5 * (D2 + np.swapaxes(D2, -1, -2))
        D2[:, list(env.free)] = 0.0
        R = loc.M[:, :3, :3]
        first = np.einsum("nqa,nqf->nfa", loc.T, D)  # (n,2,3) in S_1
        second = np.einsum("npqa,npf,nqg->nfga", loc.H, D, D) + np.einsum("nqa,nqfg->nfga", loc.T, D2)
        first = np.einsum("nab,nfb->nfa", R, first)
        second = np.einsum("nab,nfgb->nfga", R, second)
        r = np.einsum("nab,nb->na", R, loc.tool.r) + loc.M[:, :3, 3]
        nanify = lambda x: np.where(bad.reshape((-1,) + (1,) * (x.ndim - 1)), np.nan, x)
        r, first, second = nanify(r), nanify(first), nanify(second)

        def sh(x):
            return x.reshape(shape + (3,))

        return SurfacePoint(
            sh(r), sh(first[:, 0]), sh(first[:, 1]), sh(second[:, 0, 0]), sh(second[:, 0, 1]), sh(second[:, 1, 1])
        )


def singular_points(envelope: Envelope, fixed_name, fixed_value, guess) -> EnvelopeResult:
    """Litvin's limiting points: solve the meshing equations together with the singularity
    condition det(A) = 0 (A = Litvin's (2+k)-square matrix, module doc; GGAT ch. 6 for k = 1;
    seed 002 sec. 2.4) with one parameter ``fixed_name`` held at ``fixed_value`` (array).

    ``guess`` (n, 1+k) or broadcastable: starting values of the other 1 + k parameters in the
    order of ``envelope.names`` without the fixed one. The points found on the tool surface
    form Litvin's line L: tool points beyond it generate an undercut (self-intersecting)
    surface. Returns an :class:`EnvelopeResult` (its ``solve`` holds the combined solve).

    Parameters
    ----------
    envelope : Envelope
        The envelope.
    fixed_name : str
        One of ``envelope.names``.
    fixed_value : float or array_like
        Its values (finite).
    guess : array_like
        (n, 1+k) starts of the other parameters.

    Returns
    -------
    EnvelopeResult
        The limiting points.

    Raises
    ------
    ValueError
        If ``fixed_name`` is unknown, a value is not finite or ``guess`` does not broadcast.

    Examples
    --------
    A straight rack (20 deg) undercuts a gear of pitch radius 5 mm below the height
    r_p sin^2(alpha) = 0.58489 mm from its pitch line:

    >>> import math
    >>> import numpy as np
    >>> from gearrep.envelope import Envelope, rack_generation_motion, singular_points
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> rack = StraightRackCutter(math.radians(20))
    >>> env = Envelope(rack, rack_generation_motion(5.0))  # r_p [mm]
    >>> sp = singular_points(env, "v", [0.0], guess=[[-1.0, 0.0]])  # v = 0 mm; starts u [mm], phi [rad]
    >>> sp.converged.tolist(), np.round(rack.profile(sp.param("u"))[0], 5).tolist()  # height x_b [mm]
    ([True], [-0.58489])
    """
    if fixed_name not in envelope.names:
        raise ValueError(f"fixed_name must be one of {envelope.names}, got {fixed_name!r}")
    j = envelope.names.index(fixed_name)
    others = [i for i in range(2 + envelope.k) if i != j]
    fv = np.atleast_1d(np.asarray(fixed_value, dtype=float)).reshape(-1)
    if not np.all(np.isfinite(fv)):
        raise ValueError("fixed_value must be finite")
    try:
        x0 = np.broadcast_to(np.asarray(guess, dtype=float), (fv.size, 1 + envelope.k)).copy()
    except ValueError:
        raise ValueError(
            f"guess must broadcast to ({fv.size}, {1 + envelope.k}): the parameters "
            f"{tuple(n for n in envelope.names if n != fixed_name)}"
        ) from None

    def assemble(x, idx):
        q = np.empty((x.shape[0], 2 + envelope.k))
        q[:, j] = fv[idx]
        q[:, others] = x
        return q

    def fun(x, idx):
        loc = _local(envelope.tool, envelope.motion, assemble(x, idx))
        A = _litvin_matrix(loc)
        scale = np.prod(np.linalg.norm(A, axis=-1), axis=-1)
        return np.concatenate([loc.f, (np.linalg.det(A) / scale)[:, None]], axis=1)

    res = newton(fun, x0, tol=envelope.tol * 10, maxiter=envelope.maxiter, rows=True)
    rec = envelope._record(assemble(res.x, np.arange(fv.size)), res)
    return rec
