"""The surface protocol: a regular surface r(u, v) with its first and second partial derivatives.

A surface family subclasses :class:`Surface` and implements :meth:`Surface.position`; when its
equations give the derivatives in closed form it also overrides :meth:`Surface.evaluate`.
Otherwise :meth:`Surface.evaluate` differentiates ``position`` with fourth-order central
differences (:func:`fd_derivatives`), whose error is quantified in its docstring and tested.

Arrays broadcast: ``u`` and ``v`` of any (equal, broadcastable) shape ``S`` give points of shape
``S + (3,)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import frames

__all__ = [
    "Surface",
    "SurfacePoint",
    "RotatedSurface",
    "AxialForm",
    "cross",
    "cross3",
    "cross3_sparse",
    "add3",
    "dot3",
    "fd_derivatives",
    "unit",
    "D1_WEIGHTS",
    "D1_OFFSETS",
    "D2_WEIGHTS",
    "D2_OFFSETS",
]


def unit(v: np.ndarray, axis: int = -1) -> np.ndarray:
    """Vectors scaled to unit length along ``axis``.

    Parameters
    ----------
    v : array_like
        Vectors (any unit).
    axis : int, optional
        The axis of the components.

    Returns
    -------
    numpy.ndarray
        The unit vectors [1] (NaN for a zero vector).

    Examples
    --------
    >>> from gearrep.surface import unit
    >>> unit([[3.0, 0.0, 4.0]]).tolist()
    [[0.6, 0.0, 0.8]]
    """
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v, axis=axis, keepdims=True)


def cross(a, b) -> np.ndarray:
    """Cross product along the last axis with broadcasting, written out by components (same
    result as ``np.cross(a, b)``, several times faster on small batches).

    Parameters
    ----------
    a, b : (..., 3) array_like
        Vectors; batch dimensions broadcast.

    Returns
    -------
    (..., 3) numpy.ndarray
        a x b.

    Examples
    --------
    >>> from gearrep.surface import cross
    >>> cross([1.0, 0.0, 0.0], [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).tolist()
    [[0.0, 0.0, 1.0], [0.0, -1.0, 0.0]]
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = a1 * b2 - a2 * b1
    out[..., 1] = a2 * b0 - a0 * b2
    out[..., 2] = a0 * b1 - a1 * b0
    return out


def cross3(a, b):
    """Cross product of two vectors given by components (structure of arrays): ``a`` and ``b`` are
    3-tuples of broadcastable arrays or floats; returns the 3-tuple of components (no stacking).

    Parameters
    ----------
    a, b : tuple
        (x, y, z) components, arrays or floats.

    Returns
    -------
    tuple
        The components of a x b.

    Examples
    --------
    >>> from gearrep.surface import cross3
    >>> cross3((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    (0.0, 0.0, 1.0)
    """
    a0, a1, a2 = a
    b0, b1, b2 = b
    return (a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0)


def _times(x, y):
    """x * y, or None where a factor is the float 0.0 (an exact zero); a float 1.0 factor returns
    the other unchanged."""
    if type(x) is float:
        if x == 0.0:
            return None
        if x == 1.0:
            return y
    if type(y) is float:
        if y == 0.0:
            return None
        if y == 1.0:
            return x
    return x * y


def _minus(p, q):
    """p - q of :func:`_times` products (None = zero)."""
    if q is None:
        return 0.0 if p is None else p
    return -q if p is None else p - q


def cross3_sparse(a, b):
    """:func:`cross3` for vectors whose constant components are Python floats (e.g. the axial
    components 0.0 and 1.0 of a cylindrical flank's derivatives, see
    :meth:`Surface.evaluate_components`): products with a float 0.0 are left out and a float 1.0
    factor is not multiplied, so the same values (up to the sign of an exact zero) cost fewer array
    operations; a component that is structurally zero comes back as the float 0.0.

    Parameters
    ----------
    a, b : tuple
        (x, y, z) components, arrays or floats.

    Returns
    -------
    tuple
        The components of a x b.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surface import cross3_sparse
    >>> x = np.array([1.0, 2.0])
    >>> cross3_sparse((x, x, 0.0), (0.0, 0.0, 1.0))  # (x, x, 0) x z
    (array([1., 2.]), array([-1., -2.]), 0.0)
    """
    a0, a1, a2 = a
    b0, b1, b2 = b
    return (
        _minus(_times(a1, b2), _times(a2, b1)),
        _minus(_times(a2, b0), _times(a0, b2)),
        _minus(_times(a0, b1), _times(a1, b0)),
    )


def add3(a, b):
    """a + b of vectors by components, a float 0.0 component adding nothing (see :func:`cross3_sparse`).

    Parameters
    ----------
    a, b : tuple
        (x, y, z) components, arrays or floats.

    Returns
    -------
    tuple
        The components of a + b.

    Examples
    --------
    >>> from gearrep.surface import add3
    >>> add3((1.0, 0.0, 2.0), (0.0, 3.0, 1.0))
    (1.0, 3.0, 3.0)
    """
    return tuple(
        y if (type(x) is float and x == 0.0) else (x if (type(y) is float and y == 0.0) else x + y)
        for x, y in zip(a, b)
    )


def dot3(a, b):
    """Dot product of two vectors given by components (3-tuples, as :func:`cross3`).

    Parameters
    ----------
    a, b : tuple
        (x, y, z) components, arrays or floats.

    Returns
    -------
    float or numpy.ndarray
        a . b.

    Examples
    --------
    >>> from gearrep.surface import dot3
    >>> dot3((1.0, 2.0, 3.0), (4.0, 5.0, 6.0))
    32.0
    """
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@dataclass(frozen=True)
class SurfacePoint:
    """Position and partial derivatives of a surface at parameters (u, v); each (..., 3).

    Parameters
    ----------
    r : (..., 3) numpy.ndarray
        Position [length].
    r_u, r_v : (..., 3) numpy.ndarray
        First partial derivatives [length per unit of u, v].
    r_uu, r_uv, r_vv : (..., 3) numpy.ndarray
        Second partial derivatives.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Sphere
    >>> p = Sphere(R=2.0).evaluate(0.0, 0.0)  # longitude, latitude [rad]
    >>> np.round(p.r, 12).tolist(), np.round(p.normal, 12).tolist()
    ([2.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    >>> float(p.flipped().normal[0])  # (v, u): the other orientation
    -1.0
    """

    r: np.ndarray
    r_u: np.ndarray
    r_v: np.ndarray
    r_uu: np.ndarray
    r_uv: np.ndarray
    r_vv: np.ndarray

    @property
    def normal(self) -> np.ndarray:
        """Unit normal n = (r_u x r_v) / ``|r_u x r_v|`` (the orientation every curvature uses)."""
        return unit(cross(self.r_u, self.r_v))

    @classmethod
    def from_components(cls, comps) -> SurfacePoint:
        """The point of :meth:`Surface.evaluate_components`'s six vectors ``comps`` (3-tuples of
        broadcastable arrays or floats): each stacked into a (..., 3) array (the inverse of
        :meth:`components`; a float component is broadcast to the arrays' shape).

        Parameters
        ----------
        comps : tuple
            The six vectors (r, r_u, r_v, r_uu, r_uv, r_vv), each a 3-tuple of components.

        Returns
        -------
        SurfacePoint
            The stacked point.

        Raises
        ------
        ValueError
            If ``comps`` is not six 3-tuples or their shapes do not broadcast.
        """
        if len(comps) != 6 or any(len(vec) != 3 for vec in comps):
            raise ValueError(
                "comps must be the six vectors (r, r_u, r_v, r_uu, r_uv, r_vv), each a 3-tuple of "
                f"components; got {len(comps)} entries of lengths {[len(vec) for vec in comps]}"
            )
        try:
            shape = np.broadcast_shapes(*(np.shape(c) for vec in comps for c in vec))
        except ValueError:
            raise ValueError(
                f"the components' shapes do not broadcast: {[[np.shape(c) for c in vec] for vec in comps]}"
            ) from None
        out = np.empty((6,) + shape + (3,))
        for i, vec in enumerate(comps):
            for k, c in enumerate(vec):
                out[i, ..., k] = c
        return cls(*out)

    def components(self) -> tuple:
        """The six vectors (r, r_u, r_v, r_uu, r_uv, r_vv), each as a 3-tuple of component arrays
        (views, no copies): the structure-of-arrays form of :meth:`Surface.evaluate_components`.

        Returns
        -------
        tuple
            Six 3-tuples of component arrays.
        """
        return tuple(
            (x[..., 0], x[..., 1], x[..., 2]) for x in (self.r, self.r_u, self.r_v, self.r_uu, self.r_uv, self.r_vv)
        )

    def flipped(self) -> SurfacePoint:
        """The same point with the parameters swapped (v, u): the normal changes sign.

        Returns
        -------
        SurfacePoint
            The point with r_u and r_v, r_uu and r_vv exchanged.
        """
        return SurfacePoint(self.r, self.r_v, self.r_u, self.r_vv, self.r_uv, self.r_uu)


#: fourth-order central differences (the surfaces' and the motions' finite-difference
#: derivatives): first derivative = sum(D1_WEIGHTS * f(x + D1_OFFSETS h)) / h
D1_WEIGHTS = np.array([1.0, -8.0, 8.0, -1.0]) / 12.0
#: offsets of the first-derivative stencil, in steps h
D1_OFFSETS = np.array([-2.0, -1.0, 1.0, 2.0])
#: second derivative = sum(D2_WEIGHTS * f(x + D2_OFFSETS h)) / h^2
D2_WEIGHTS = np.array([-1.0, 16.0, -30.0, 16.0, -1.0]) / 12.0
#: offsets of the second-derivative stencil, in steps h
D2_OFFSETS = np.array([-2.0, -1.0, 0.0, 1.0, 2.0])


def fd_derivatives(position, u, v, h_u: float = 1e-3, h_v: float = 1e-3, *, one_call: bool = False) -> SurfacePoint:
    """First and second partial derivatives of ``position(u, v)`` by 4th-order central differences.

    Truncation error is O(h^4) and rounding error O(eps/h) for first and O(eps/h^2) for second
    derivatives. For a surface whose parameters vary on a scale L (choose ``h ~ 1e-3 L``), the
    relative error is about 1e-12 for first and 1e-10 for second derivatives, which keeps
    principal curvatures accurate to ~1e-9 relative (tested in tests/unit/core/test_surface.py).

    ``one_call``: evaluate the 25 distinct points of the stencils (centre, 4 along u, 4 along v,
    16 crossed) in ONE call of ``position`` on the stacked parameters instead of one call per
    offset (33 calls, the axial offsets twice): the same values with a fraction of the calls. Only
    for a ``position`` whose value at a point does not depend on the other points of the call
    (no iteration with a common stopping test; :attr:`Surface.pointwise`).

    Parameters
    ----------
    position : callable
        (u, v) -> (..., 3) points, vectorised.
    u, v : float or array_like
        Parameters where the derivatives are wanted (broadcast).
    h_u, h_v : float, optional
        Steps in parameter units.
    one_call : bool, optional
        Evaluate every stencil point in one call of ``position``.

    Returns
    -------
    SurfacePoint
        Position and the five partial derivatives.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surface import fd_derivatives
    >>> def saddle(u, v):
    ...     return np.stack(np.broadcast_arrays(u, v, u * v), -1)
    >>> p = fd_derivatives(saddle, 0.5, 2.0)
    >>> np.round(p.r_u, 9).tolist(), round(float(p.r_uv[2]), 6)  # r_uv = (0, 0, 1)
    ([1.0, 0.0, 2.0], 1.0)
    """
    u = np.asarray(u, dtype=float)
    v = np.asarray(v, dtype=float)
    u, v = np.broadcast_arrays(u, v)
    if one_call:
        return _fd_one_call(position, u, v, h_u, h_v)
    r = np.asarray(position(u, v), dtype=float)

    def d1(f, du, dv):
        return sum(w * f(o * du, o * dv) for w, o in zip(D1_WEIGHTS, D1_OFFSETS))

    def shifted(a, b):
        return np.asarray(position(u + a, v + b), dtype=float)

    return _fd_combine(r, shifted, h_u, h_v)


def _fd_combine(r, shifted, h_u, h_v) -> SurfacePoint:
    """The stencil sums of :func:`fd_derivatives` from the centre value ``r`` and ``shifted(a, b)``
    (the position at (u + a, v + b))."""
    r_u = sum(w * shifted(o * h_u, 0.0) for w, o in zip(D1_WEIGHTS, D1_OFFSETS)) / h_u
    r_v = sum(w * shifted(0.0, o * h_v) for w, o in zip(D1_WEIGHTS, D1_OFFSETS)) / h_v
    r_uu = sum(w * (r if o == 0 else shifted(o * h_u, 0.0)) for w, o in zip(D2_WEIGHTS, D2_OFFSETS)) / h_u**2
    r_vv = sum(w * (r if o == 0 else shifted(0.0, o * h_v)) for w, o in zip(D2_WEIGHTS, D2_OFFSETS)) / h_v**2
    r_uv = sum(
        wi * wj * shifted(oi * h_u, oj * h_v)
        for wi, oi in zip(D1_WEIGHTS, D1_OFFSETS)
        for wj, oj in zip(D1_WEIGHTS, D1_OFFSETS)
    ) / (h_u * h_v)
    return SurfacePoint(r, r_u, r_v, r_uu, r_uv, r_vv)


def _fd_one_call(position, u, v, h_u, h_v) -> SurfacePoint:
    """:func:`fd_derivatives` with every stencil point in one call of ``position``."""
    offsets = [(0.0, 0.0)]
    offsets += [(o * h_u, 0.0) for o in D1_OFFSETS] + [(0.0, o * h_v) for o in D1_OFFSETS]
    offsets += [(oi * h_u, oj * h_v) for oi in D1_OFFSETS for oj in D1_OFFSETS]
    uu = np.concatenate([(u + a).ravel() for a, _ in offsets])
    vv = np.concatenate([(v + b).ravel() for _, b in offsets])
    P = np.asarray(position(uu, vv), dtype=float).reshape(len(offsets), *u.shape, 3)
    at = {o: P[i] for i, o in enumerate(offsets)}
    return _fd_combine(at[(0.0, 0.0)], lambda a, b: at[(a, b)], h_u, h_v)


class Surface:
    """Base class of a parametric surface r(u, v).

    Subclasses implement :meth:`position` and may override :meth:`evaluate` with analytic
    derivatives. ``fd_step`` sets the finite-difference steps (h_u, h_v) in parameter units.

    Examples
    --------
    A surface defined by its position alone, differentiated by finite differences:

    >>> import numpy as np
    >>> from gearrep.surface import Surface
    >>> class Paraboloid(Surface):
    ...     pointwise = True
    ...     def position(self, u, v):
    ...         u, v = np.broadcast_arrays(u, v)
    ...         return np.stack([u, v, 0.5 * (u * u + v * v)], -1)
    >>> p = Paraboloid().evaluate(0.0, 0.0)
    >>> np.round(p.r_uu, 6).tolist(), np.round(Paraboloid().normal(0.0, 0.0), 12).tolist()
    ([0.0, 0.0, 1.0], [0.0, 0.0, 1.0])
    """

    fd_step: tuple[float, float] = (1e-3, 1e-3)  #: finite-difference steps (h_u, h_v) in parameter units
    #: True where ``position`` gives each point's value independently of the other points of a
    #: call (closed forms, interpolation; not an iteration with a common stopping test): the finite
    #: differences then evaluate all their points in one call (:func:`fd_derivatives` ``one_call``)
    pointwise: bool = False

    def position(self, u, v) -> np.ndarray:  # pragma: no cover - abstract
        """Points r(u, v) of the surface (implemented by each family).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters (units of the family: a length, or an angle in rad), broadcast
            against each other to a shape S.

        Returns
        -------
        numpy.ndarray
            Points of shape S + (3,) [length].

        Raises
        ------
        NotImplementedError
            On the base class.
        """
        raise NotImplementedError

    def evaluate(self, u, v) -> SurfacePoint:
        """Position and first/second derivatives at (u, v).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters (units of the family: a length, or an angle in rad), broadcast
            against each other to a shape S.

        Returns
        -------
        SurfacePoint
            r, r_u, r_v, r_uu, r_uv, r_vv, each of shape S + (3,).
        """
        return fd_derivatives(self.position, u, v, *self.fd_step, one_call=self.pointwise)

    def evaluate_components(self, u, v) -> tuple:
        """:meth:`evaluate` in structure-of-arrays form: (r, r_u, r_v, r_uu, r_uv, r_vv), each a
        3-tuple of components (arrays, or floats for components that are constant). Families whose
        equations allow it override this to skip the (..., 3) arrays (the TCA kernels use it).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters (units of the family: a length, or an angle in rad), broadcast
            against each other to a shape S.

        Returns
        -------
        tuple
            Six 3-tuples of components, each an array of shape S or a float.
        """
        return self.evaluate(u, v).components()

    def normal(self, u, v) -> np.ndarray:
        """Unit normal (r_u x r_v) / ``|r_u x r_v|`` at (u, v).

        Parameters
        ----------
        u, v : float or array_like
            Surface parameters (units of the family: a length, or an angle in rad), broadcast
            against each other to a shape S.

        Returns
        -------
        numpy.ndarray
            Unit normals of shape S + (3,).
        """
        return self.evaluate(u, v).normal


class RotatedSurface(Surface):
    """A surface carried by a fixed rotation Q (3 x 3, proper) and translation t: r' = Q r + t.

    Derivatives rotate with Q, so the normal unit(r_u x r_v) rotates too and curvatures are
    unchanged. The attributes ``outward_sign``, ``lower``, ``upper``, ``gear``, ``side`` and
    ``fd_step`` of the wrapped surface, where present, and :meth:`contains` pass through.

    Parameters
    ----------
    surface : Surface
        The surface carried.
    Q : (3, 3) array_like
        A proper rotation.
    t : (3,) array_like, optional
        A translation [length].

    Raises
    ------
    ValueError
        If ``Q`` is not a 3 x 3 proper rotation (within 1e-12).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_z
    >>> from gearrep.surface import RotatedSurface
    >>> from gearrep.surfaces.analytic import Sphere
    >>> s = RotatedSurface(Sphere(R=2.0), rot_z(np.pi / 2), t=(0.0, 0.0, 1.0))
    >>> np.round(s.position(0.0, 0.0), 12).tolist()
    [0.0, 2.0, 1.0]
    """

    _PASSED = ("outward_sign", "lower", "upper", "gear", "side", "fd_step")

    def __init__(self, surface: Surface, Q, t=(0.0, 0.0, 0.0)):
        Q = np.asarray(Q, float)
        if Q.shape != (3, 3) or not frames.is_rigid(Q, tol=1e-12):
            raise ValueError("Q must be a 3x3 proper rotation matrix (Q Q^T = I, det Q = +1)")
        self.surface = surface
        self.Q = Q
        self.t = np.asarray(t, float).reshape(3)
        self._apply_r = frames.matrix_applier(Q, self.t)
        self._apply = frames.matrix_applier(Q)
        for name in self._PASSED:
            if hasattr(surface, name):
                setattr(self, name, getattr(surface, name))

    def _q(self, v):
        return np.einsum("ij,...j->...i", self.Q, v)

    def position(self, u, v):
        return self._q(self.surface.position(u, v)) + self.t

    def evaluate(self, u, v) -> SurfacePoint:
        P = self.surface.evaluate(u, v)
        return SurfacePoint(
            self._q(P.r) + self.t, self._q(P.r_u), self._q(P.r_v), self._q(P.r_uu), self._q(P.r_uv), self._q(P.r_vv)
        )

    def evaluate_components(self, u, v) -> tuple:
        P = self.surface.evaluate_components(u, v)
        return (self._apply_r(P[0]),) + tuple(self._apply(x) for x in P[1:])

    def contains(self, u, v, tol: float = 1e-9):
        """The wrapped surface's ``contains`` (parameters are unchanged by the motion).

        Parameters
        ----------
        u, v : float or array_like
            Parameters of the wrapped surface (units of the family: a length, or an angle in rad), broadcast
            against each other to a shape S.
        tol : float, optional
            Slack passed on.

        Returns
        -------
        numpy.ndarray of bool
            Where (u, v) lies in the wrapped surface's domain.
        """
        return self.surface.contains(u, v, tol)


class AxialForm(Surface):
    """A spherical flank (``flank.spherical``: u = polar angle from its axis z, v = distance from
    the apex, e.g. :class:`gearrep.surfaces.bevel.SphericalInvoluteFlank`) reparameterised by the cylindrical coordinates of its own axis frame:
    r(rho, z) = S(u(rho, z), v(rho, z)) with u = atan2(rho, z), v = hypot(rho, z).

    This is the explicit form about the member's own axis that the reduced TCA (eq 35-40) reads
    (u = distance from the axis, v = axial coordinate); same points, same normal orientation
    (d(u, v)/d(rho, z) has determinant 1/v > 0). Derivatives by the chain rule with
    u_rho = z/v^2, u_z = -rho/v^2, v_rho = rho/v, v_z = z/v,
    u_rhorho = -2 rho z/v^4, u_rhoz = (rho^2 - z^2)/v^4, u_zz = 2 rho z/v^4,
    v_rhorho = z^2/v^3, v_rhoz = -rho z/v^3, v_zz = rho^2/v^3.

    Parameters
    ----------
    flank : Surface
        A spherical flank (``flank.spherical`` true).

    Raises
    ------
    ValueError
        If ``flank`` is not spherical.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.surface import AxialForm
    >>> from gearrep.surfaces.bevel import BevelGearData, SphericalInvoluteFlank
    >>> g = BevelGearData(20, 40, 3.0, math.radians(20), 10.0)  # teeth, mate's teeth, mm, rad, mm
    >>> flank = SphericalInvoluteFlank(g)
    >>> axial = AxialForm(flank)
    >>> u, v = 0.5 * (flank.lower + flank.upper)
    >>> rho, z = v * math.sin(u), v * math.cos(u)
    >>> bool(np.allclose(axial.position(rho, z), flank.position(u, v), rtol=0, atol=1e-12))
    True
    """

    cylindrical = True

    def __init__(self, flank: Surface):
        if not getattr(flank, "spherical", False):
            raise ValueError("flank must be a spherical flank (flank.spherical = True)")
        self.flank = flank
        for name in ("outward_sign", "gear", "side"):
            if hasattr(flank, name):
                setattr(self, name, getattr(flank, name))

    def position(self, rho, z):
        rho, z = np.broadcast_arrays(np.asarray(rho, float), np.asarray(z, float))
        return self.flank.position(np.arctan2(rho, z), np.hypot(rho, z))

    def evaluate(self, rho, z) -> SurfacePoint:
        return SurfacePoint.from_components(self.evaluate_components(rho, z))

    def evaluate_components(self, rho, z) -> tuple:
        """The chain rule of the class docstring by components (structure of arrays), on the
        flank's own :meth:`~Surface.evaluate_components` (Python floats for one point)."""
        if type(rho) is float and type(z) is float:  # one point: on Python floats
            v, u = math.hypot(rho, z), math.atan2(rho, z)
        else:
            rho, z = np.broadcast_arrays(np.asarray(rho, float), np.asarray(z, float))
            v, u = np.hypot(rho, z), np.arctan2(rho, z)
        r, r_u, r_v, r_uu, r_uv, r_vv = self.flank.evaluate_components(u, v)
        v2, v3, v4 = v * v, v**3, v**4
        ua, ub = z / v2, -rho / v2
        va, vb = rho / v, z / v
        uaa, uab, ubb = -2 * rho * z / v4, (rho * rho - z * z) / v4, 2 * rho * z / v4
        vaa, vab, vbb = z * z / v3, -rho * z / v3, rho * rho / v3

        def first(pu, pv):
            return tuple(r_u[k] * pu + r_v[k] * pv for k in range(3))

        def second(pu, pv, qu, qv, uxy, vxy):
            mixed = pu * qv + qu * pv
            return tuple(
                r_uu[k] * pu * qu + r_uv[k] * mixed + r_vv[k] * pv * qv + r_u[k] * uxy + r_v[k] * vxy for k in range(3)
            )

        return (
            r,
            first(ua, va),
            first(ub, vb),
            second(ua, va, ua, va, uaa, vaa),
            second(ua, va, ub, vb, uab, vab),
            second(ub, vb, ub, vb, ubb, vbb),
        )
