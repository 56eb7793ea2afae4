"""Curvature of a regular surface and relative (induced) curvature of two tangent surfaces.

Sources
-------
* First and second fundamental forms, normal curvature k_n = II/I, the Weingarten (shape)
  operator, principal curvatures/directions, Gaussian K and mean H curvature: Litvin & Fuentes,
  *Gear Geometry and Applied Theory* (2nd ed.), ch. 7 ("Curvatures of surfaces and curves"),
  and any differential-geometry text (e.g. do Carmo, sect. 3-2/3-3). Seed 004 eq (7)-(16)
  uses the same quantities (with the typos of docs/reading-notes.md, 004-A: eq (8) must divide by
  |r_theta x r_phi|, eq (15) reads x^2 - 2 H x + K = 0 and eq (16) k = H +- sqrt(H^2 - K)).
* Euler's formula k_n(theta) = k_I cos^2 theta + k_II sin^2 theta (Litvin ch. 7).
* Relative (induced) normal curvature of two surfaces in tangency,
  kappa^(12) = kappa^(1) - kappa^(2), with the true angle sigma between the first principal
  directions (Litvin ch. 8/9 "relations between principal curvatures ... contact ellipse";
  seed 002 eq 2.6.1-2.6.6, seed 000 eq 5.14-5.15). Seed 004 eq (20), which pairs k_1 with k_1,
  is the special case sigma = 0.

Conventions (the gearrep contract)
----------------------------------
* The unit normal is n = unit(r_u x r_v) (:attr:`SurfacePoint.normal`).
* k_n = II/I with L = r_uu . n, M = r_uv . n, N = r_vv . n: a curvature is POSITIVE where the
  surface bends TOWARD n (a sphere with inward normal has k = +1/R). This is Litvin's sign
  (his Rodrigues formula dn = -kappa dr).
* k1 >= k2 algebraically; e1, e2 are unit 3-vectors, e1 x e2 = n. At an umbilic (k1 = k2 within
  ``umbilic_tol``) every direction is principal and we return e1 = unit(r_u).
* Principal directions are lines: e and -e are the same direction. Angles between them are
  therefore meaningful modulo pi, and every formula below only uses 2*angle.
* Relative curvature: both surfaces' curvatures must refer to ONE common unit normal n (use
  :func:`with_opposite_normal` to re-express a surface whose own normal is -n). sigma is the
  signed angle from e_I^(1) to e_I^(2), counter-clockwise about n; alpha is the signed angle,
  in the same sense, from e_I^(1) to the direction of the algebraically largest relative
  curvature. (Litvin's eq 2.6.2 with a "+" sign measures alpha^(1) in the sense opposite to
  sigma: alpha_Litvin = -alpha here. Only |alpha| is determined when sigma is taken unsigned
  as arccos(e_I^(1) . e_I^(2)), seed 000 eq 5.15.)

Everything is vectorised over leading batch dimensions: scalars are (...) arrays and vectors
(..., 3) arrays.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .surface import SurfacePoint, cross, unit

__all__ = [
    "DEFAULT_UMBILIC_TOL",
    "FundamentalForms",
    "PrincipalCurvatures",
    "RelativeCurvature",
    "fundamental_forms",
    "shape_matrix",
    "principal_curvatures",
    "normal_curvature",
    "euler_normal_curvature",
    "gaussian_curvature",
    "mean_curvature",
    "with_opposite_normal",
    "signed_angle",
    "relative_principal_curvatures",
    "relative_curvature",
    "sym2_eig",
    "second_form_in_basis",
]

#: relative eigenvalue gap below which a point counts as umbilic (isotropic curvature)
DEFAULT_UMBILIC_TOL = 1e-8


class FundamentalForms(NamedTuple):
    """Coefficients of I = E du^2 + 2F du dv + G dv^2 and II = L du^2 + 2M du dv + N dv^2.

    L, M, N use the unit normal n = unit(r_u x r_v) (L = r_uu . n, ...).

    Attributes
    ----------
    E, F, G : numpy.ndarray
        First form [length^2 per parameter units squared].
    L, M, N : numpy.ndarray
        Second form [length per parameter units squared].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import fundamental_forms
    >>> [round(float(x), 12) for x in fundamental_forms(p)]
    [4.0, 0.0, 1.0, -2.0, 0.0, 0.0]
    """

    E: np.ndarray
    F: np.ndarray
    G: np.ndarray
    L: np.ndarray
    M: np.ndarray
    N: np.ndarray


class PrincipalCurvatures(NamedTuple):
    """Principal curvatures k1 >= k2 (w.r.t. ``normal``), unit directions e1, e2 (e1 x e2 =
    normal). Scalars (...), vectors (..., 3).

    Attributes
    ----------
    k1, k2 : numpy.ndarray
        Principal curvatures, k1 >= k2 [1/length].
    e1, e2 : numpy.ndarray
        Unit principal directions (..., 3).
    normal : numpy.ndarray
        The unit normal the signs refer to (..., 3).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import principal_curvatures
    >>> pc = principal_curvatures(p)
    >>> round(float(pc.k1), 12), round(float(pc.k2), 12), round(float(abs(pc.e1[2])), 12)  # 1/mm
    (0.0, -0.5, 1.0)
    """

    k1: np.ndarray
    k2: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    normal: np.ndarray

    @property
    def gaussian(self) -> np.ndarray:
        """K = k1 k2."""
        return self.k1 * self.k2

    @property
    def mean(self) -> np.ndarray:
        """H = (k1 + k2)/2 (sign follows the normal)."""
        return 0.5 * (self.k1 + self.k2)


class RelativeCurvature(NamedTuple):
    """Principal relative curvatures of kappa^(12) = kappa^(1) - kappa^(2) (k1 >= k2).

    sigma: signed angle e_I^(1) -> e_I^(2) about ``normal``; alpha: signed angle e_I^(1) -> e1.
    e1, e2 (unit, e1 x e2 = normal) and normal are None when only angles were given.

    Attributes
    ----------
    k1, k2 : numpy.ndarray
        Principal relative curvatures, k1 >= k2 [1/length].
    alpha : numpy.ndarray
        Signed angle e_I^(1) -> e1 [rad].
    sigma : numpy.ndarray
        Signed angle e_I^(1) -> e_I^(2) [rad].
    e1, e2, normal : numpy.ndarray or None
        Directions and common normal (..., 3).

    Examples
    --------
    See :func:`relative_curvature`.

    >>> from gearrep.curvature import RelativeCurvature
    >>> RelativeCurvature(0.2, -0.3, 0.0, 0.0).e1 is None
    True
    """

    k1: np.ndarray
    k2: np.ndarray
    alpha: np.ndarray
    sigma: np.ndarray
    e1: np.ndarray | None = None
    e2: np.ndarray | None = None
    normal: np.ndarray | None = None


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def fundamental_forms(p: SurfacePoint) -> FundamentalForms:
    """First and second fundamental forms (E, F, G, L, M, N) at a surface point.

    Litvin ch. 7: E = r_u.r_u, F = r_u.r_v, G = r_v.r_v; L = r_uu.n, M = r_uv.n, N = r_vv.n
    with n = unit(r_u x r_v) (seed 004 eq (9)-(13), same quantities).

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.

    Returns
    -------
    FundamentalForms
        E, F, G, L, M, N of the shape of the point.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import fundamental_forms
    >>> ff = fundamental_forms(p)
    >>> round(float(ff.E), 12), round(float(ff.L), 12)  # R^2 [mm^2], -R [mm]
    (4.0, -2.0)
    """
    n = p.normal
    return FundamentalForms(
        _dot(p.r_u, p.r_u),
        _dot(p.r_u, p.r_v),
        _dot(p.r_v, p.r_v),
        _dot(p.r_uu, n),
        _dot(p.r_uv, n),
        _dot(p.r_vv, n),
    )


def _tangent_frame(p: SurfacePoint):
    """Orthonormal tangent basis t1 = unit(r_u), t2 = n x t1, the normal n, and the 2x2 shape
    matrix S (symmetric) of the Weingarten map in that basis: k_n(x) = x.S.x / x.x for a
    tangent vector with components x = (dr.t1, dr.t2)."""
    n = p.normal
    t1 = unit(p.r_u)
    t2 = cross(n, t1)
    # coordinates of r_u, r_v in (t1, t2): J = [[j11, j12], [0, j22]], j22 > 0
    j11 = np.linalg.norm(p.r_u, axis=-1)
    j12 = _dot(p.r_v, t1)
    j22 = _dot(p.r_v, t2)
    L, M, N = _dot(p.r_uu, n), _dot(p.r_uv, n), _dot(p.r_vv, n)
    # S = J^-T [[L, M], [M, N]] J^-1 with J^-1 = [[pp, q], [0, s]]
    pp = 1.0 / j11
    s = 1.0 / j22
    q = -j12 * pp * s
    S11 = pp * pp * L
    S12 = pp * (q * L + s * M)
    S22 = q * q * L + 2.0 * q * s * M + s * s * N
    return t1, t2, n, S11, S12, S22


def shape_matrix(p: SurfacePoint):
    """Shape operator as a symmetric 2x2 matrix in the orthonormal basis (t1, t2) =
    (unit(r_u), n x unit(r_u)); returns (t1, t2, n, S11, S12, S22).

    This is I^-1 II (Weingarten map, Litvin ch. 7) written in an orthonormal tangent basis,
    where it becomes symmetric; its eigenvalues are the principal curvatures.

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.

    Returns
    -------
    tuple
        (t1, t2, n) unit vectors (..., 3) and S11, S12, S22 [1/length].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import shape_matrix
    >>> t1, t2, n, S11, S12, S22 = shape_matrix(p)
    >>> [round(float(x), 12) for x in (S11, S12, S22)]  # 1/mm
    [-0.5, 0.0, 0.0]
    """
    return _tangent_frame(p)


def sym2_eig(a, b, c, umbilic_tol: float = DEFAULT_UMBILIC_TOL):
    """Eigen-decomposition of the symmetric matrix [[a, b], [b, c]] (batched).

    Returns (lam1 >= lam2, theta) with theta in (-pi/2, pi/2] the angle of the lam1
    eigenvector (cos theta, sin theta). The smaller-magnitude eigenvalue is computed as
    det/(larger) to avoid cancellation. Where the eigenvalue gap 2d satisfies
    d <= umbilic_tol * max(``|a|, |b|, |c|``) (isotropic case), theta = 0.

    Parameters
    ----------
    a, b, c : float or array_like
        Matrix entries (any unit).
    umbilic_tol : float, optional
        Relative gap below which the matrix counts as isotropic.

    Returns
    -------
    tuple
        (lam1, lam2, theta [rad]).

    Examples
    --------
    >>> from gearrep.curvature import sym2_eig
    >>> lam1, lam2, theta = sym2_eig(2.0, 1.0, 2.0)
    >>> round(float(lam1), 12), round(float(lam2), 12), round(float(theta), 12)  # theta = pi/4
    (3.0, 1.0, 0.785398163397)
    """
    a, b, c = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (a, b, c)))
    m = 0.5 * (a + c)
    h = 0.5 * (a - c)
    d = np.hypot(h, b)
    big = m + np.where(m >= 0.0, d, -d)  # eigenvalue of largest magnitude
    det = a * c - b * b
    with np.errstate(divide="ignore", invalid="ignore"):
        small = np.where(big != 0.0, det / np.where(big != 0.0, big, 1.0), 0.0)
    lam1 = np.where(m >= 0.0, big, small)
    lam2 = np.where(m >= 0.0, small, big)
    # guard ordering against rounding in det/big
    lam1, lam2 = np.maximum(lam1, lam2), np.minimum(lam1, lam2)
    scale = np.maximum(np.maximum(np.abs(a), np.abs(c)), np.abs(b))
    iso = d <= umbilic_tol * scale
    theta = np.where(iso, 0.0, 0.5 * np.arctan2(b, h))
    return lam1, lam2, theta


def second_form_in_basis(p: SurfacePoint, n, e1, e2) -> np.ndarray:
    """Second fundamental form II(e_i, e_j) of surface point(s) ``p`` with respect to the unit
    normal ``n``, in the orthonormal tangent basis (e1, e2): shapes (..., 3) -> (..., 2, 2).

    Each basis vector is written as e = x r_u + y r_v (x, y from the first fundamental form),
    then II(e_i, e_j) = L x_i x_j + M (x_i y_j + y_i x_j) + N y_i y_j with L = r_uu . n,
    M = r_uv . n, N = r_vv . n (Litvin ch. 7). ``n`` may be either unit normal (the form
    changes sign with it), so two surfaces in tangency can be written in one common basis;
    with n = unit(r_u x r_v) and (e1, e2) = (t1, t2) of :func:`shape_matrix` this is that
    shape matrix. Eigenvalues: the principal curvatures w.r.t. ``n``.

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.
    n : (..., 3) array_like
        The unit normal of the form.
    e1, e2 : (..., 3) array_like
        An orthonormal tangent basis.

    Returns
    -------
    numpy.ndarray
        II (..., 2, 2) [1/length].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import principal_curvatures, second_form_in_basis
    >>> pc = principal_curvatures(p)
    >>> (np.round(second_form_in_basis(p, pc.normal, pc.e1, pc.e2), 12) + 0.0).tolist()
    [[0.0, 0.0], [0.0, -0.5]]
    """
    E, F, G = _dot(p.r_u, p.r_u), _dot(p.r_u, p.r_v), _dot(p.r_v, p.r_v)
    L, M, N = _dot(p.r_uu, n), _dot(p.r_uv, n), _dot(p.r_vv, n)
    det = E * G - F * F
    coef = []
    for e in (e1, e2):
        bu, bv = _dot(p.r_u, e), _dot(p.r_v, e)
        coef.append(((G * bu - F * bv) / det, (E * bv - F * bu) / det))  # e = x r_u + y r_v
    out = np.empty(E.shape + (2, 2))
    for i in range(2):
        for j in range(2):
            xi, yi = coef[i]
            xj, yj = coef[j]
            out[..., i, j] = L * xi * xj + M * (xi * yj + yi * xj) + N * yi * yj
    return out


def principal_curvatures(p: SurfacePoint, umbilic_tol: float = DEFAULT_UMBILIC_TOL) -> PrincipalCurvatures:
    """Principal curvatures k1 >= k2 [1/length of the surface data, 1/mm in the examples] and unit
    principal directions e1, e2 (e1 x e2 = n).

    Eigenvalues/eigenvectors of the Weingarten map (Litvin ch. 7; k = H +- sqrt(H^2 - K),
    corrected seed 004 eq (14)-(16)), computed from the symmetric shape matrix in the
    orthonormal basis (unit(r_u), n x unit(r_u)) so no non-symmetric eigenproblem is solved.
    Sign: k > 0 where the surface bends toward n = unit(r_u x r_v). At an umbilic
    (``|k1 - k2| <= 2 umbilic_tol max|S_ij|``) e1 = unit(r_u).

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.
    umbilic_tol : float, optional
        Relative eigenvalue gap below which the point counts as umbilic.

    Returns
    -------
    PrincipalCurvatures
        k1 >= k2 [1/length], e1, e2 and the normal.

    Examples
    --------
    >>> from gearrep.curvature import principal_curvatures
    >>> from gearrep.surfaces.analytic import Sphere
    >>> pc = principal_curvatures(Sphere(R=4.0).evaluate(0.3, 0.2))  # outward normal
    >>> round(float(pc.k1), 12), round(float(pc.k2), 12)  # 1/mm
    (-0.25, -0.25)
    """
    t1, t2, n, S11, S12, S22 = _tangent_frame(p)
    k1, k2, th = sym2_eig(S11, S12, S22, umbilic_tol)
    c, s = np.cos(th)[..., None], np.sin(th)[..., None]
    e1 = c * t1 + s * t2
    e2 = -s * t1 + c * t2
    return PrincipalCurvatures(k1, k2, e1, e2, n)


def normal_curvature(p: SurfacePoint, direction) -> np.ndarray:
    """Normal curvature k_n = II(d)/I(d) in the tangent direction ``direction`` (..., 3).

    Litvin ch. 7. The component of ``direction`` along the normal is discarded; its length
    does not matter. Sign as in :func:`principal_curvatures`.

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.
    direction : (..., 3) array_like
        A tangent direction (any length).

    Returns
    -------
    numpy.ndarray
        k_n [1/length].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import normal_curvature
    >>> round(float(normal_curvature(p, p.r_u + 2.0 * p.r_v)), 12)  # 45 deg between z and around
    -0.25
    """
    t1, t2, n, S11, S12, S22 = _tangent_frame(p)
    d = np.asarray(direction, dtype=float)
    x, y = _dot(d, t1), _dot(d, t2)
    return (S11 * x * x + 2.0 * S12 * x * y + S22 * y * y) / (x * x + y * y)


def euler_normal_curvature(pc: PrincipalCurvatures, direction) -> np.ndarray:
    """Euler's formula k_n = k1 cos^2 q + k2 sin^2 q, q the angle from e1 to ``direction``
    (Litvin ch. 7). The normal component of ``direction`` is discarded.

    Parameters
    ----------
    pc : PrincipalCurvatures
        The principal curvatures and directions.
    direction : (..., 3) array_like
        A tangent direction (any length).

    Returns
    -------
    numpy.ndarray
        k_n [1/length].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import euler_normal_curvature, principal_curvatures
    >>> pc = principal_curvatures(p)
    >>> round(float(euler_normal_curvature(pc, pc.e1 + pc.e2)), 12)  # 1/mm
    -0.25
    """
    d = np.asarray(direction, dtype=float)
    x, y = _dot(d, pc.e1), _dot(d, pc.e2)
    return (pc.k1 * x * x + pc.k2 * y * y) / (x * x + y * y)


def gaussian_curvature(p: SurfacePoint) -> np.ndarray:
    """K = (LN - M^2)/(EG - F^2) (Litvin ch. 7; independent of the normal's orientation).

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.

    Returns
    -------
    numpy.ndarray
        K [1/length^2].

    Examples
    --------
    >>> from gearrep.curvature import gaussian_curvature
    >>> from gearrep.surfaces.analytic import Sphere
    >>> round(float(gaussian_curvature(Sphere(R=2.0).evaluate(0.3, 0.2))), 12)  # 1/R^2 [1/mm^2]
    0.25
    """
    f = fundamental_forms(p)
    return (f.L * f.N - f.M**2) / (f.E * f.G - f.F**2)


def mean_curvature(p: SurfacePoint) -> np.ndarray:
    """H = (EN - 2FM + GL) / (2(EG - F^2)) = (k1 + k2)/2 (Litvin ch. 7; sign follows n).

    Parameters
    ----------
    p : gearrep.surface.SurfacePoint
        Surface point(s) with first and second derivatives.

    Returns
    -------
    numpy.ndarray
        H [1/length].

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import mean_curvature
    >>> round(float(mean_curvature(p)), 12)  # 1/mm
    -0.25
    """
    f = fundamental_forms(p)
    return (f.E * f.N - 2.0 * f.F * f.M + f.G * f.L) / (2.0 * (f.E * f.G - f.F**2))


def with_opposite_normal(pc: PrincipalCurvatures) -> PrincipalCurvatures:
    """The same curvature data expressed with the normal -n.

    Every normal curvature changes sign, so k1' = -k2, k2' = -k1 (keeping k1' >= k2'); the
    directions swap, e1' = e2, e2' = e1, which keeps e1' x e2' = -n = n'.

    Parameters
    ----------
    pc : PrincipalCurvatures
        Curvatures with the normal n.

    Returns
    -------
    PrincipalCurvatures
        The same with -n.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.analytic import Cylinder
    >>> p = Cylinder(R=2.0).evaluate(0.3, 1.0)  # radius 2 mm: k = 0 along z, -1/2 around
    >>> from gearrep.curvature import principal_curvatures, with_opposite_normal
    >>> flipped = with_opposite_normal(principal_curvatures(p))
    >>> round(float(flipped.k1), 12), round(float(flipped.k2), 12) + 0.0  # 1/mm
    (0.5, 0.0)
    """
    return PrincipalCurvatures(-pc.k2, -pc.k1, pc.e2, pc.e1, -pc.normal)


def signed_angle(a, b, n) -> np.ndarray:
    """Signed angle from tangent vector a to tangent vector b, counter-clockwise about n, in
    (-pi, pi].

    Parameters
    ----------
    a, b : (..., 3) array_like
        Tangent vectors.
    n : (..., 3) array_like
        The unit normal the angle turns about.

    Returns
    -------
    numpy.ndarray
        The angle [rad].

    Examples
    --------
    >>> import math
    >>> from gearrep.curvature import signed_angle
    >>> round(float(signed_angle([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])), 12) == round(math.pi / 2, 12)
    True
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    return np.arctan2(_dot(np.asarray(n, dtype=float), cross(a, b)), _dot(a, b))


def relative_principal_curvatures(kI1, kII1, kI2, kII2, sigma, umbilic_tol: float = DEFAULT_UMBILIC_TOL):
    """Principal relative curvatures of two tangent surfaces from principal curvatures and
    the angle sigma between e_I^(1) and e_I^(2) (common normal; sigma counter-clockwise
    about it). Returns (k1_rel >= k2_rel, alpha).

    kappa^(12)(q) = kappa^(1)(q) - kappa^(2)(q)
                  = (kS1 - kS2)/2 + (1/2) sqrt(g1^2 - 2 g1 g2 cos 2sigma + g2^2) cos 2(q - alpha)

    with kS_i = kI_i + kII_i and g_i = kI_i - kII_i (seed 002 eq 2.6.6), so
    k_rel = (kS1 - kS2 +- sqrt(g1^2 - 2 g1 g2 cos 2sigma + g2^2)) / 2 = 2B, 2A of seed 002
    eq 2.6.4-2.6.5, and cos 2alpha = (g1 - g2 cos 2sigma)/R, sin 2alpha = -g2 sin 2sigma/R
    (seed 002 eq 2.6.1-2.6.2 with alpha measured in the sense of sigma; Litvin's printed
    sin 2alpha^(1) = +g2 sin 2sigma/R measures alpha^(1) the other way round).
    Computed as the eigen-decomposition of the relative curvature tensor in the basis
    (e_I^(1), e_II^(1)), which avoids the cancellation in kS1 - kS2 - R when the smaller
    relative curvature is a small difference of large numbers.

    Parameters
    ----------
    kI1, kII1, kI2, kII2 : float or array_like
        Principal curvatures of surfaces 1 and 2 [1/length], with the common normal.
    sigma : float or array_like
        Angle from e_I^(1) to e_I^(2) [rad].
    umbilic_tol : float, optional
        As :func:`sym2_eig`.

    Returns
    -------
    tuple
        (k1_rel >= k2_rel [1/length], alpha [rad]).

    Examples
    --------
    >>> from gearrep.curvature import relative_principal_curvatures
    >>> k1, k2, alpha = relative_principal_curvatures(-0.5, 0.0, 0.1, 0.0, 0.0)  # 1/mm, rad
    >>> round(float(k1), 12), round(float(k2), 12), round(float(abs(alpha)), 9)
    (0.0, -0.6, 1.570796327)
    """
    kI1, kII1, kI2, kII2, sigma = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (kI1, kII1, kI2, kII2, sigma))
    )
    c, s = np.cos(sigma), np.sin(sigma)
    C11 = kI1 - (kI2 * c * c + kII2 * s * s)
    C22 = kII1 - (kI2 * s * s + kII2 * c * c)
    C12 = -(kI2 - kII2) * s * c
    k1, k2, alpha = sym2_eig(C11, C12, C22, umbilic_tol)
    return k1, k2, alpha


def relative_curvature(
    c1: PrincipalCurvatures,
    c2: PrincipalCurvatures,
    *,
    normal_tol: float = 1e-6,
    umbilic_tol: float = DEFAULT_UMBILIC_TOL,
) -> RelativeCurvature:
    """Relative (induced) curvature kappa^(12) = kappa^(1) - kappa^(2) of two surfaces in
    tangency at a point, with the true angle sigma between e_I^(1) and e_I^(2).

    Both inputs must be expressed with a COMMON unit normal (``c2.normal`` = ``c1.normal``
    within ``normal_tol`` radians); otherwise ValueError (use :func:`with_opposite_normal`).
    Returns principal relative curvatures k1 >= k2, unit directions e1, e2 (e1 x e2 = n,
    n = c1.normal), sigma and alpha (signed, about n). Litvin ch. 9 / seed 002 eq 2.6.1-2.6.6;
    see :func:`relative_principal_curvatures`. If the relative curvature is isotropic,
    e1 = e_I^(1).

    Parameters
    ----------
    c1, c2 : PrincipalCurvatures
        The two surfaces' curvatures, with a common normal.
    normal_tol : float, optional
        Angle [rad] the two normals may differ by.
    umbilic_tol : float, optional
        As :func:`sym2_eig`.

    Returns
    -------
    RelativeCurvature
        k1 >= k2 [1/length], alpha, sigma [rad], e1, e2 and the normal.

    Raises
    ------
    ValueError
        If the normals differ by more than ``normal_tol``.

    Examples
    --------
    A cylinder of radius 2 mm against a sphere of radius 5 mm, both with the outward normal
    (1, 0, 0):

    >>> from gearrep.curvature import principal_curvatures, relative_curvature
    >>> from gearrep.surfaces.analytic import Cylinder, Sphere
    >>> c1 = principal_curvatures(Cylinder(R=2.0).evaluate(0.0, 0.0))
    >>> c2 = principal_curvatures(Sphere(R=5.0).evaluate(0.0, 0.0))
    >>> rel = relative_curvature(c1, c2)
    >>> round(float(rel.k1), 12), round(float(rel.k2), 12)  # 1/mm
    (0.2, -0.3)
    """
    n = np.asarray(c1.normal, dtype=float)
    cosang = np.clip(_dot(n, c2.normal), -1.0, 1.0)
    bad = ~(cosang >= np.cos(normal_tol))
    if np.any(bad):
        raise ValueError(
            "relative_curvature: the two surfaces' normals differ by up to "
            f"{np.degrees(np.max(np.arccos(cosang))):.6g} deg (allowed: <= normal_tol = "
            f"{normal_tol:g} rad); express both with a common normal (with_opposite_normal)"
        )
    # e_I^(2) projected into the tangent plane of surface 1 (removes the tiny normal mismatch)
    e2I = c2.e1 - _dot(c2.e1, n)[..., None] * n
    sigma = signed_angle(c1.e1, e2I, n)
    k1, k2, alpha = relative_principal_curvatures(c1.k1, c1.k2, c2.k1, c2.k2, sigma, umbilic_tol)
    ca, sa = np.cos(alpha)[..., None], np.sin(alpha)[..., None]
    e1 = ca * c1.e1 + sa * c1.e2
    e2 = cross(n, e1)
    return RelativeCurvature(k1, k2, alpha, sigma, e1, e2, n)
