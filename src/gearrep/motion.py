"""Rigid motions M_21(m) of a tool frame S_1 into a generated member's frame S_2, with their first
and second derivatives in the k = 1 or 2 motion parameters m: what :mod:`gearrep.envelope` needs
for the equations of meshing and the generated surface's derivatives.

* :class:`ChainMotion`: a product of rotations, translations and fixed matrices whose parameters
  are affine in m (Litvin's chain M_21 = M_2f M_fh ...; GGAT ch. 2), differentiated exactly by the
  product rule; :func:`rack_generation_motion` is the rack-cutter chain of seed 002 sec. 2.2-2.3.
* :class:`FunctionMotion`: any M(m), with given or finite-difference derivatives.
* :class:`Motion`: the base class (subclasses implement :meth:`Motion.matrices`).

:meth:`Motion.twists` gives what the equations of meshing need in the tool frame without the
4 x 4 derivative stacks: M, the angular and translational velocities (omega_j, v_j) of
M^-1 dM/dm_j (the point velocity is omega_j x r + v_j) and the second derivatives
M^-1 d^2M/dm_i dm_j applied to tool points. :class:`ChainMotion` forms them from the factors'
twists (below); any other motion from its matrices.

Twists of a chain (GGAT ch. 2's product of elementary motions, differentiated as a product of
one-parameter subgroups): a rotation about the unit axis a through p by s is F(s) = exp(s Xi)
with the twist Xi x = a x x + p x a, a translation by s d has Xi x = d, so F^-1 dF/ds = Xi and
F^-1 d^2F/ds^2 = Xi^2 (constant). With S_i = F_(i+1) ... F_n (the factors after factor i) and
s_i = offset_i + c_i . m, the twist of factor i seen in the tool frame is Xi~_i = S_i^-1 Xi_i S_i
(omega~ = R^T omega, v~ = R^T (omega x t + v) for S_i = (R, t)), and

    M^-1 dM/dm_j = sum_i c_ij Xi~_i,
    M^-1 d^2M/dm_j dm_k = sum_(i<l) (c_ij c_lk + c_lj c_ik) Xi~_i Xi~_l + sum_i c_ij c_ik Xi~_i^2,

i < l meaning factor i comes before factor l in the chain; on a tool point r,
Xi~_i Xi~_l r = omega~_i x (omega~_l x r + v~_l). Tested against :meth:`ChainMotion.matrices`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from . import frames
from .surface import (  # the fourth-order central differences of the surfaces, and cross
    D1_OFFSETS,
    D1_WEIGHTS,
    D2_OFFSETS,
    D2_WEIGHTS,
    cross,
)

__all__ = [
    "Motion",
    "MotionTwists",
    "FunctionMotion",
    "ChainMotion",
    "rotation",
    "translation",
    "fixed",
    "rack_generation_motion",
    "TOOL_NAMES",
]

#: the tool surface's parameter names (a motion parameter may not take them)
TOOL_NAMES = ("u", "v")


def _check_names(names, k):
    names = tuple(str(s) for s in names)
    if len(names) != k:
        raise ValueError(f"names must have {k} entries (one per motion parameter), got {names!r}")
    if len(set(names)) != k or set(names) & set(TOOL_NAMES):
        raise ValueError(f"motion parameter names must be distinct and not 'u' or 'v', got {names!r}")
    return names


@dataclass(frozen=True)
class MotionTwists:
    """A motion's first and second derivatives in the tool frame at n parameter points (module doc).

    Parameters
    ----------
    M : (n, 4, 4) numpy.ndarray
        The motion's matrices.
    omega, v : (n, k, 3) numpy.ndarray
        Angular and translational velocity of each parameter in the tool frame:
        M^-1 dM/dm_j = (omega_j x) + v_j, so a tool point r moves at omega_j x r + v_j per unit of
        m_j (rad or length per parameter unit).
    second : callable
        ``second(r)`` -> (n, k, k, 3): M^-1 d^2M/dm_i dm_j applied to the tool points r (n, 3).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.motion import ChainMotion, rotation
    >>> tw = ChainMotion([rotation((0.0, 0.0, 1.0))]).twists(np.array([[0.3]]))
    >>> tw.omega.round(12).tolist()
    [[[0.0, 0.0, 1.0]]]
    """

    M: np.ndarray
    omega: np.ndarray
    v: np.ndarray
    second: Callable


class Motion:
    """A rigid motion M_21(m) from the tool frame S_1 to the generated member's frame S_2.

    Subclasses implement :meth:`matrices`. ``n_params`` is k (1 or 2) and ``names`` names the
    motion parameters (e.g. ``("phi",)`` or ``("theta", "psi")``).

    Examples
    --------
    >>> from gearrep.motion import ChainMotion, Motion, rotation
    >>> isinstance(ChainMotion([rotation((0.0, 0.0, 1.0))]), Motion)
    True
    """

    n_params: int = 1  #: k, the number of motion parameters (1 or 2)
    names: tuple[str, ...] = ("phi",)  #: the motion parameters' names

    def matrices(self, m):  # pragma: no cover - abstract
        """(M, dM, d2M) at parameters m (..., k): shapes (..., 4, 4), (..., k, 4, 4) and
        (..., k, k, 4, 4); dM[..., j] = dM/dm_j, d2M[..., i, j] = d^2 M / dm_i dm_j.

        Parameters
        ----------
        m : (..., k) array_like
            Motion parameters (rad for angles, the design's length unit for feeds).

        Returns
        -------
        tuple of numpy.ndarray
            (M, dM, d2M).

        Raises
        ------
        NotImplementedError
            On the base class.
        """
        raise NotImplementedError

    def twists(self, m) -> MotionTwists:
        """:class:`MotionTwists` at parameters m (module doc), here from :meth:`matrices`.

        Parameters
        ----------
        m : (n, k) array_like
            Motion parameters (rad for angles, the design's length unit for feeds).

        Returns
        -------
        MotionTwists
            The motion's matrices and its twists in the tool frame.
        """
        M, dM, d2M = self.matrices(m)
        M = M.reshape(-1, 4, 4)
        k = self.n_params
        Mi = frames.inverse(M, check=False)  # rigid by construction; NaN rows pass through
        W = Mi[:, None] @ dM.reshape(-1, k, 4, 4)
        X = Mi[:, None, None] @ d2M.reshape(-1, k, k, 4, 4)
        Om = W[..., :3, :3]
        omega = np.stack([Om[..., 2, 1], Om[..., 0, 2], Om[..., 1, 0]], axis=-1)

        def second(r):
            return np.einsum("nijab,nb->nija", X[..., :3, :3], r) + X[..., :3, 3]

        return MotionTwists(M, omega, W[..., :3, 3], second)

    def _params(self, m):
        m = np.asarray(m, dtype=float)
        if self.n_params == 1 and (m.ndim == 0 or m.shape[-1] != 1):
            m = m[..., None]
        if m.shape[-1] != self.n_params:
            raise ValueError(
                f"m must have last dimension {self.n_params} (motion parameters {self.names}), got shape {m.shape}"
            )
        return m


class FunctionMotion(Motion):
    """A motion given by a function ``M(m)`` (m (..., k) -> (..., 4, 4)).

    ``dM`` and ``d2M`` (same signatures as :meth:`Motion.matrices` returns) may be supplied;
    otherwise they are taken by 4th-order central differences with step ``fd_step`` (error
    O(h^4) + O(eps/h) for dM and O(eps/h^2) for d2M: with h = 1e-3 and O(1) parameters about
    1e-12 and 1e-10 relative, enough for curvatures to ~1e-9). Prefer :class:`ChainMotion`
    (exact derivatives) when the motion is a product of rotations and translations.

    Parameters
    ----------
    M : callable
        m (..., k) -> (..., 4, 4).
    n_params : int, optional
        k, 1 or 2.
    names : sequence of str, optional
        The parameters' names (not 'u' or 'v').
    dM, d2M : callable, optional
        The derivatives, as :meth:`Motion.matrices` returns them.
    fd_step : float, optional
        Finite-difference step in parameter units, > 0.

    Raises
    ------
    ValueError
        If ``n_params``, ``names`` or ``fd_step`` is bad.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import homogeneous, rot_z
    >>> from gearrep.motion import FunctionMotion
    >>> turn = FunctionMotion(lambda m: homogeneous(rot_z(m[..., 0])))
    >>> M, dM, d2M = turn.matrices([[0.0]])  # rad
    >>> (np.round(dM[0, 0, :2, :2], 9) + 0.0).tolist()  # the generator of z
    [[0.0, -1.0], [1.0, 0.0]]
    """

    def __init__(
        self,
        M: Callable,
        n_params: int = 1,
        names: Sequence[str] | None = None,
        dM: Callable | None = None,
        d2M: Callable | None = None,
        fd_step: float = 1e-3,
    ):
        if n_params not in (1, 2):
            raise ValueError(f"n_params must be 1 or 2, got {n_params!r}")
        if not (fd_step > 0):
            raise ValueError(f"fd_step must be > 0, got {fd_step!r}")
        self.n_params = int(n_params)
        self.names = _check_names(names or (("phi",) if n_params == 1 else ("theta", "psi")), n_params)
        self._M, self._dM, self._d2M, self.fd_step = M, dM, d2M, float(fd_step)

    def matrices(self, m):
        m = self._params(m)
        k, h = self.n_params, self.fd_step
        M = np.asarray(self._M(m), dtype=float)
        eye = np.eye(k)

        def at(off):
            return np.asarray(self._M(m + off), dtype=float)

        if self._dM is not None:
            dM = np.asarray(self._dM(m), dtype=float)
        else:
            dM = np.stack(
                [sum(w * at(o * h * eye[j]) for w, o in zip(D1_WEIGHTS, D1_OFFSETS)) / h for j in range(k)], axis=-3
            )
        if self._d2M is not None:
            d2M = np.asarray(self._d2M(m), dtype=float)
        else:
            rows = []
            for i in range(k):
                row = []
                for j in range(k):
                    if i == j:
                        row.append(
                            sum(w * (M if o == 0 else at(o * h * eye[i])) for w, o in zip(D2_WEIGHTS, D2_OFFSETS))
                            / h**2
                        )
                    else:
                        row.append(
                            sum(
                                wi * wj * at(oi * h * eye[i] + oj * h * eye[j])
                                for wi, oi in zip(D1_WEIGHTS, D1_OFFSETS)
                                for wj, oj in zip(D1_WEIGHTS, D1_OFFSETS)
                            )
                            / h**2
                        )
                rows.append(np.stack(row, axis=-3))
            d2M = np.stack(rows, axis=-4)
        return M, dM, d2M


@dataclass(frozen=True)
class _Factor:
    """One factor F(s) of a :class:`ChainMotion`; s = offset + coeffs . m (affine in m)."""

    kind: str  # "rot", "trans", "fixed"
    vector: np.ndarray  # unit axis (rot) or direction (trans)
    point: np.ndarray  # a point on the rotation axis
    coeffs: np.ndarray  # (k,) or empty for a fixed factor
    offset: float
    matrix: np.ndarray | None = None
    generators: tuple | None = None  # (K, K^2) of a rotation's axis (frames.axis_generators)

    def twist(self):
        """(omega, v) of the factor's constant twist F^-1 dF/ds (module doc): (a, p x a) of a
        rotation, (0, d) of a translation."""
        if self.kind == "rot":
            return self.vector, np.cross(self.point, self.vector)
        return np.zeros(3), self.vector

    def rigid(self, s):
        """(Q (n, 3, 3), t (n, 3)) of F at scalar parameters s (n,) (a moving factor): Rodrigues'
        rotation about the axis through the point, or the translation (no derivatives)."""
        if self.kind == "trans":
            return np.eye(3), s[:, None] * self.vector
        K, K2 = self.generators
        sn, cs = np.sin(s)[:, None, None], np.cos(s)[:, None, None]
        Q = np.eye(3) + sn * K + (1.0 - cs) * K2
        return Q, self.point - Q @ self.point

    def evaluate(self, s):
        """F, dF/ds, d^2F/ds^2 at scalar parameters s (n,) -> (n, 4, 4) each."""
        n = s.shape[0]
        F = np.broadcast_to(np.eye(4), (n, 4, 4)).copy()
        dF = np.zeros((n, 4, 4))
        d2F = np.zeros((n, 4, 4))
        if self.kind == "fixed":
            F[:] = self.matrix
            return F, dF, d2F
        if self.kind == "trans":
            F[:, :3, 3] = s[:, None] * self.vector
            dF[:, :3, 3] = self.vector
            return F, dF, d2F
        R, dR, d2R = frames.rotation_about_axis_with_derivatives(self.vector, s, self.generators)
        p = self.point
        F[:, :3, :3] = R
        F[:, :3, 3] = p - R @ p
        dF[:, :3, :3] = dR
        dF[:, :3, 3] = -dR @ p
        d2F[:, :3, :3] = d2R
        d2F[:, :3, 3] = -d2R @ p
        return F, dF, d2F


def _unit3(v, name):
    v = np.asarray(v, dtype=float).reshape(-1)
    if v.shape != (3,) or not np.all(np.isfinite(v)) or np.linalg.norm(v) == 0:
        raise ValueError(f"{name} must be a finite nonzero 3-vector, got {v!r}")
    return v / np.linalg.norm(v)


def _coeffs(coeffs):
    c = np.atleast_1d(np.asarray(coeffs, dtype=float))
    if c.ndim != 1 or c.size not in (1, 2) or not np.all(np.isfinite(c)):
        raise ValueError(f"coeffs must be 1 or 2 finite numbers (one per motion parameter), got {coeffs!r}")
    return c


def rotation(axis, coeffs=1.0, offset: float = 0.0, point=(0.0, 0.0, 0.0)) -> _Factor:
    """Factor of a :class:`ChainMotion`: rotation about ``axis`` through ``point`` by the angle
    s = offset + coeffs . m (right-hand rule; GGAT ch. 2 rotation matrices, Rodrigues' form).

    Parameters
    ----------
    axis : (3,) array_like
        Direction of the axis (finite, non-zero).
    coeffs : float or sequence of float, optional
        The angle's rate per motion parameter [rad per parameter unit].
    offset : float, optional
        Constant part of the angle [rad].
    point : (3,) array_like, optional
        A point of the axis [length].

    Returns
    -------
    object
        The factor.

    Raises
    ------
    ValueError
        If ``axis`` is zero or not finite, or ``coeffs`` is not 1 or 2 finite numbers.

    Examples
    --------
    >>> from gearrep.motion import ChainMotion, rotation
    >>> M, _, _ = ChainMotion([rotation((0.0, 0.0, 1.0), point=(1.0, 0.0, 0.0))]).matrices([[3.141592653589793]])
    >>> (M[0, :3, 3].round(12) + 0.0).tolist()  # half a turn about the line x = 1 moves the origin
    [2.0, 0.0, 0.0]
    """
    k, p = _unit3(axis, "axis"), np.asarray(point, dtype=float).reshape(3)
    return _Factor("rot", k, p, _coeffs(coeffs), float(offset), generators=frames.axis_generators(k))


def translation(direction, coeffs=1.0, offset: float = 0.0) -> _Factor:
    """Factor of a :class:`ChainMotion`: translation by s * direction, s = offset + coeffs . m
    (``direction`` is used as given, not normalised, so s may be an angle times a radius).

    Parameters
    ----------
    direction : (3,) array_like
        The direction (its length scales s).
    coeffs : float or sequence of float, optional
        The rate of s per motion parameter.
    offset : float, optional
        Constant part of s.

    Returns
    -------
    object
        The factor.

    Raises
    ------
    ValueError
        If ``direction`` is not a finite 3-vector or ``coeffs`` is bad.

    Examples
    --------
    >>> from gearrep.motion import ChainMotion, translation
    >>> M, dM, _ = ChainMotion([translation((0.0, 2.0, 0.0))]).matrices([[1.5]])
    >>> M[0, :3, 3].tolist(), dM[0, 0, :3, 3].tolist()  # s = 1.5 times (0, 2, 0); ds/dm
    ([0.0, 3.0, 0.0], [0.0, 2.0, 0.0])
    """
    d = np.asarray(direction, dtype=float).reshape(-1)
    if d.shape != (3,) or not np.all(np.isfinite(d)):
        raise ValueError(f"direction must be a finite 3-vector, got {direction!r}")
    return _Factor("trans", d, np.zeros(3), _coeffs(coeffs), float(offset))


def fixed(M) -> _Factor:
    """Factor of a :class:`ChainMotion`: a constant 4 x 4 homogeneous matrix.

    Parameters
    ----------
    M : (4, 4) array_like
        A finite matrix.

    Returns
    -------
    object
        The factor.

    Raises
    ------
    ValueError
        If ``M`` is not a finite 4 x 4 matrix.

    Examples
    --------
    >>> from gearrep.frames import translation as shift
    >>> from gearrep.motion import ChainMotion, fixed
    >>> M, dM, _ = ChainMotion([fixed(shift([0.0, 0.0, 5.0]))]).matrices([[0.7]])
    >>> float(M[0, 2, 3]), float(abs(dM).max())  # constant: no derivative
    (5.0, 0.0)
    """
    M = np.asarray(M, dtype=float)
    if M.shape != (4, 4) or not np.all(np.isfinite(M)):
        raise ValueError(f"M must be a finite 4x4 matrix, got shape {M.shape}")
    return _Factor("fixed", np.zeros(3), np.zeros(3), np.zeros(0), 0.0, M)


class ChainMotion(Motion):
    """M_21(m) = F_1 F_2 ... F_n, each factor a :func:`rotation`, :func:`translation` or
    :func:`fixed` matrix (Litvin's chain M_21 = M_2f M_fh ... of GGAT ch. 2), with exact first
    and second derivatives by the product rule. Factor parameters are affine in m.

    Parameters
    ----------
    factors : sequence
        :func:`rotation`, :func:`translation` and :func:`fixed` factors, left to right.
    names : sequence of str, optional
        The motion parameters' names (1 or 2; not 'u' or 'v').

    Raises
    ------
    ValueError
        If ``names`` is bad or a factor's coefficients do not match the parameters.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.motion import ChainMotion, rotation, translation
    >>> m = ChainMotion([rotation((0.0, 0.0, 1.0)), translation((1.0, 0.0, 0.0), 0.0, offset=10.0)])
    >>> M, dM, d2M = m.matrices([[np.pi / 2]])  # phi [rad]: turn, then the fixed 10 mm offset
    >>> (np.round(M[0, :3, 3], 12) + 0.0).tolist(), dM.shape, d2M.shape
    ([0.0, 10.0, 0.0], (1, 1, 4, 4), (1, 1, 1, 4, 4))
    """

    def __init__(self, factors: Sequence[_Factor], names: Sequence[str] = ("phi",)):
        names = tuple(names)
        if len(names) not in (1, 2):
            raise ValueError(f"names must name 1 or 2 motion parameters, got {names!r}")
        self.n_params = len(names)
        self.names = _check_names(names, self.n_params)
        if len(factors) == 0:
            raise ValueError("factors must not be empty")
        for f in factors:
            if not isinstance(f, _Factor):
                raise ValueError("factors must be made by rotation(), translation() or fixed()")
            if f.kind != "fixed" and f.coeffs.size != self.n_params:
                raise ValueError(f"each factor needs {self.n_params} coeffs (one per motion parameter), got {f.coeffs}")
        self.factors = tuple(factors)
        self._steps = self._plan()
        # for twists(): each moving factor's twist, the coefficients (F, k) and the weights of
        # omega~_i x (omega~_l x r + v~_l) in M^-1 d^2M/dm_j dm_k (module doc), (F, F, k, k)
        movers = [st[1] for st in self._steps if st[0] != "fixed"]
        self._twist_of = {id(f): f.twist() for f in movers}
        nf = len(movers)
        self._coef = np.array([f.coeffs for f in movers]).reshape(nf, self.n_params)
        c = self._coef
        wt = np.zeros((nf, nf, self.n_params, self.n_params))
        for i in range(nf):
            wt[i, i] = np.outer(c[i], c[i])
            for j in range(i + 1, nf):
                wt[i, j] = np.outer(c[i], c[j]) + np.outer(c[j], c[i])
        self._pair_weights = wt.reshape(nf * nf, self.n_params**2).T.copy()  # (k k, F F)

    def _plan(self):
        """The factors as steps of :meth:`matrices`: ("fixed", M) for a fixed factor or one whose
        coefficients are all zero (a constant: M at its offset), ("one", factor, j) for a factor
        that moves with the single parameter j, ("any", factor) otherwise."""
        plan = []
        for f in self.factors:
            nz = np.flatnonzero(f.coeffs)
            if f.kind == "fixed":
                plan.append(("fixed", f.matrix))
            elif len(nz) == 0:
                plan.append(("fixed", f.evaluate(np.array([f.offset]))[0][0]))
            elif len(nz) == 1:
                plan.append(("one", f, int(nz[0])))
            else:
                plan.append(("any", f))
        return tuple(plan)

    def matrices(self, m):
        """M, dM and d2M by the product rule, factor by factor. The blocks that are zero are not
        formed: a constant factor has no derivatives, and one that moves with a single parameter j
        adds to dP only in column j and to d2P only in row and column j (the sums that remain are
        those of the full product rule, in the same order).

        Parameters
        ----------
        m : (..., k) array_like
            Motion parameters.

        Returns
        -------
        tuple of numpy.ndarray
            (M, dM, d2M), as :meth:`Motion.matrices`.
        """
        m = self._params(m)
        shape = m.shape[:-1]
        k = self.n_params
        mm = m.reshape(-1, k)
        n = mm.shape[0]
        P = dP = d2P = None  # the identity and zeros before the first factor
        for step in self._steps:
            kind, f = step[0], step[1]
            if kind == "fixed":
                if P is None:
                    P, dP, d2P = np.broadcast_to(f, (n, 4, 4)).copy(), np.zeros((n, k, 4, 4)), np.zeros((n, k, k, 4, 4))
                else:
                    P, dP, d2P = P @ f, dP @ f, d2P @ f
                continue
            F, Fs, Fss = f.evaluate(f.offset + mm @ f.coeffs)
            if kind == "one":
                j = step[2]
                c = f.coeffs[j]
                dFj, d2Fjj = c * Fs, (c * c) * Fss
                if P is None:
                    dP, d2P = np.zeros((n, k, 4, 4)), np.zeros((n, k, k, 4, 4))
                    P, dP[:, j], d2P[:, j, j] = F, dFj, d2Fjj
                    continue
                G = dP @ dFj[:, None]  # dP_i dF_j
                d2P = d2P @ F[:, None, None]
                d2P[:, :, j] += G
                d2P[:, j, :] += G
                d2P[:, j, j] += P @ d2Fjj
                dP = dP @ F[:, None]
                dP[:, j] += P @ dFj
                P = P @ F
                continue
            dF = f.coeffs[None, :, None, None] * Fs[:, None]  # (n, k, 4, 4)
            d2F = (f.coeffs[:, None] * f.coeffs[None, :])[None, :, :, None, None] * Fss[:, None, None]
            if P is None:
                P, dP, d2P = F, dF, d2F
                continue
            d2P = (
                d2P @ F[:, None, None]
                + dP[:, :, None] @ dF[:, None, :]
                + dP[:, None, :] @ dF[:, :, None]
                + P[:, None, None] @ d2F
            )
            dP = dP @ F[:, None] + P[:, None] @ dF
            P = P @ F
        return (P.reshape(shape + (4, 4)), dP.reshape(shape + (k, 4, 4)), d2P.reshape(shape + (k, k, 4, 4)))

    def twists(self, m) -> MotionTwists:
        """:class:`MotionTwists` from the factors' twists (module doc): the products S_i of the
        factors after each moving one, built from the tool side, carry each twist into the tool
        frame; no derivative matrices are formed.

        Parameters
        ----------
        m : (n, k) array_like
            Motion parameters (rad for angles, the design's length unit for feeds).

        Returns
        -------
        MotionTwists
            The motion's matrices and its twists in the tool frame.
        """
        m = self._params(m).reshape(-1, self.n_params)
        n, k = m.shape
        oms, vs = [], []  # omega~, v~ of the moving factors, from the last one
        R, t = None, None  # S_i (rotation, translation); None: the identity
        for step in reversed(self._steps):
            if step[0] == "fixed":
                QF, tF = step[1][:3, :3], step[1][:3, 3]
            else:
                f = step[1]
                om, v = self._twist_of[id(f)]
                if R is None:
                    oms.append(np.broadcast_to(om, (n, 3)))
                    vs.append(np.broadcast_to(v, (n, 3)))
                else:  # R^T omega, R^T (omega x t + v)
                    oms.append(om @ R)
                    vs.append((cross(om, t) + v)[:, None, :] @ R)
                QF, tF = f.rigid(f.offset + m @ f.coeffs)
            if R is None:
                R, t = np.broadcast_to(QF, (n, 3, 3)), np.broadcast_to(tF, (n, 3))
            else:  # F S = (R_F R, R_F t + t_F)
                R, t = QF @ R, (QF @ t[:, :, None])[:, :, 0] + tF
        M = np.zeros((n, 4, 4))
        M[:, :3, :3], M[:, :3, 3], M[:, 3, 3] = R, t, 1.0
        if not oms:
            z = np.zeros((n, k, 3))
            return MotionTwists(M, z, z.copy(), lambda r: np.zeros((len(r), k, k, 3)))
        om_f = np.stack([x.reshape(n, 3) for x in reversed(oms)], axis=1)  # (n, F, 3) in chain order
        v_f = np.stack([x.reshape(n, 3) for x in reversed(vs)], axis=1)
        c, wt = self._coef, self._pair_weights
        omega, v = np.einsum("nfa,fj->nja", om_f, c), np.einsum("nfa,fj->nja", v_f, c)

        nf = c.shape[0]

        def second(r):
            y = cross(om_f, r[:, None, :]) + v_f  # (n, F, 3): the velocity of each factor
            Z = cross(om_f[:, :, None, :], y[:, None, :, :]).reshape(n, nf * nf, 3)
            return (wt @ Z).reshape(n, k, k, 3)

        return MotionTwists(M, omega, v, second)


def rack_generation_motion(r_p: float, member_side: int = -1, name: str = "phi") -> ChainMotion:
    """Rack-cutter -> member motion of seed 002 sec. 2.2-2.3 (fig. 2.2.3): M_1c(phi).

    The rack frame S_c has its pitch plane x_c = 0 and the member's axis parallel to z_c, at
    x_c = member_side * r_p (``member_side`` = -1, the default, puts the member on the side
    x_c < 0; +1 on x_c > 0, e.g. the gear of seed 002, generated by the rigidly connected rack on
    the other side from the pinion). The rack translates by s_c = r_p phi (along -y in the fixed
    frame) while the member turns by phi (clockwise for member_side = -1)::

        member_side = -1:  M_1c = Rot_z(phi)  Trans(r_p, -r_p phi, 0)
        member_side = +1:  M_1c = Rot_z(-phi) Trans(-r_p, -r_p phi, 0)

    In both cases the instantaneous axis is x_c = 0, y_c = r_p phi (the point (X_c, Y_c) of
    seed 002 eq 2.2.8-2.2.9) and the generic meshing equation n . v^(1c) = 0 equals seed 002
    eq 2.3.6, +-[(r_p phi - y_c) N_x + x_c N_y] = 0 (tested). With member_side = -1 a rack of
    helix angle beta > 0 (:mod:`gearrep.surfaces.rack`) generates a right-hand member; with
    member_side = +1 a left-hand one (seed 002 sec. 2.1: one rack generates a left-hand pinion
    and a right-hand gear).

    Parameters
    ----------
    r_p : float
        Pitch radius of the member [length], > 0.
    member_side : {-1, 1}, optional
        The side of the pitch plane the member lies on.
    name : str, optional
        The motion parameter's name.

    Returns
    -------
    ChainMotion
        M_1c(phi).

    Raises
    ------
    ValueError
        If ``r_p`` is not finite and > 0 or ``member_side`` is not +-1.

    Examples
    --------
    >>> from gearrep.motion import rack_generation_motion
    >>> motion = rack_generation_motion(10.0)  # mm
    >>> M, _, _ = motion.matrices([[0.0]])
    >>> M[0, :3, 3].tolist(), motion.names  # at phi = 0 the member's axis is 10 mm from the pitch plane
    ([10.0, 0.0, 0.0], ('phi',))
    """
    if not (np.isfinite(r_p) and r_p > 0):
        raise ValueError(f"r_p (pitch radius) must be finite and > 0, got {r_p!r}")
    if member_side not in (1, -1):
        raise ValueError(f"member_side must be +1 or -1, got {member_side!r}")
    s = -float(member_side)
    return ChainMotion(
        [
            rotation((0, 0, 1), [s]),
            translation((1.0, 0.0, 0.0), [0.0], offset=s * r_p),
            translation((0.0, -r_p, 0.0), [1.0]),
        ],
        names=(name,),
    )
