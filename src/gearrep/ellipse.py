"""Instantaneous contact ellipse: Litvin's elastic-approach ellipse and the Hertz ellipse.

Sources
-------
* Elastic-approach ellipse: seed 002 sect. 2.6 eq 2.6.1-2.6.6 (= seed 000 eq 5.14-5.17 =
  seed 004 eq 21-26; Litvin & Fuentes, *Gear Geometry and Applied Theory*, "contact ellipse"):
  kS_i = k_I^(i) + k_II^(i), g_i = k_I^(i) - k_II^(i),
  A = (kS1 - kS2 - R)/4, B = (kS1 - kS2 + R)/4, R = sqrt(g1^2 - 2 g1 g2 cos 2sigma + g2^2),
  a = |delta/A|^(1/2), b = |delta/B|^(1/2), cos 2alpha = (g1 - g2 cos 2sigma)/R,
  sin 2alpha = g2 sin 2sigma / R (2.6.2, see the sign note below); area S = pi a b (seed 004
  eq 27).
* Hertz: Johnson, *Contact Mechanics* (1985), sect. 4.2 and eq 3.63-3.64 (ellipsoidal
  pressure p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) on an elastic half-space), written with Carlson
  symmetric elliptic integrals (scipy.special.elliprf / elliprd; DLMF 19.25.1) so that neither
  the circular limit (e -> 0) nor very slender ellipses (e -> 1) lose digits.

Derivation and conventions (elastic approach)
---------------------------------------------
Let n be the common unit normal of the two surfaces at the contact point and kappa^(i)(q) the
normal curvature of surface i in the tangent direction q, both w.r.t. n (k > 0 where the
surface bends toward n, gearrep.curvature). To second order, surface i lies at height
z_i = kappa^(i)(q) rho^2 / 2 above the tangent plane (along n) at distance rho in direction q,
so the normal separation of the surfaces is |z_1 - z_2| = |kappa^(12)(q)| rho^2 / 2 with the
relative curvature kappa^(12) = kappa^(1) - kappa^(2). By Euler's formula
kappa^(12)(q) = (kS1 - kS2)/2 + (R/2) cos 2(q - alpha), whose extrema are 2B (at q = alpha)
and 2A (at q = alpha + pi/2); in principal relative axes (xi along alpha + pi/2, eta along
alpha) the separation is A xi^2 + B eta^2. The elastic-approach contact region is where the
separation does not exceed the elastic approach delta: A xi^2 + B eta^2 = delta (seed 004
eq 21), i.e. semi-axes |delta/A|^(1/2) along xi and |delta/B|^(1/2) along eta. For a sphere of
radius R on a plane A = B = 1/(2R) and the radius is sqrt(2 R delta).

This module returns ``a`` = semi-MAJOR and ``b`` = semi-MINOR axis, whichever of A, B they
come from, and ``alpha`` = the angle from e_I^(1) to the MINOR axis (the direction of largest
|kappa^(12)|), counter-clockwise about n in the same sense as sigma, wrapped to (-pi/2, pi/2].
With Litvin's orientation of n (kappa^(12) >= 0, no interference) this is exactly his labelling
(a from A, b from B, alpha^(1) to the b axis); with the opposite n all curvatures flip sign,
A and B swap roles, and the returned ellipse is unchanged. Sign note: eq 2.6.2 as printed
(sin 2alpha = +g2 sin 2sigma / R) measures alpha^(1) in the sense opposite to sigma; here
sin 2alpha = -g2 sin 2sigma / R with both angles counter-clockwise about n (|alpha| agrees).
``elliptic`` is False where A and B have opposite signs or one vanishes (saddle-shaped
separation: the region is not an ellipse; a or b is then the |delta/.|^(1/2) formal value or inf).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .curvature import PrincipalCurvatures, relative_curvature, relative_principal_curvatures
from .solve import SolveResult, Status, newton

__all__ = [
    "ContactEllipse",
    "HertzContact",
    "litvin_coefficients",
    "elastic_ellipse",
    "elastic_ellipse_from_relative",
    "elastic_ellipse_at",
    "effective_modulus",
    "hertz_ratio",
    "hertz_contact",
    "hertz_contact_at",
    "hertz_max_pressure_MPa",
    "hertz_line_max_pressure_MPa",
    "LINE_CONTACT_RTOL",
]


class ContactEllipse(NamedTuple):
    """Elastic-approach contact ellipse (see module docstring for conventions).

    a, b: semi-major / semi-minor axis; alpha: angle e_I^(1) -> minor axis (about n, sense of
    sigma); A, B: Litvin's coefficients (A <= B algebraically); area = pi a b; elliptic: A B > 0 and
    ``min(|A|, |B|) > LINE_CONTACT_RTOL max(|A|, |B|)`` (else a line contact, whose a is no contact
    length). major_axis, minor_axis: unit 3-vectors (only from :func:`elastic_ellipse_at`).

    Attributes
    ----------
    a, b : numpy.ndarray
        Semi-major and semi-minor axis [length].
    alpha : numpy.ndarray
        Angle e_I^(1) -> minor axis [rad].
    A, B : numpy.ndarray
        Litvin's coefficients [1/length].
    area : numpy.ndarray
        pi a b [length^2].
    elliptic : numpy.ndarray of bool
        Whether the contact is an ellipse (not a line contact).
    major_axis, minor_axis : numpy.ndarray or None
        Unit 3-vectors of the axes.

    Examples
    --------
    >>> from gearrep.ellipse import elastic_ellipse_from_relative
    >>> el = elastic_ellipse_from_relative(0.02, 0.07, 0.001)  # 1/mm, 1/mm, mm
    >>> round(float(el.a), 6), round(float(el.b), 6), round(float(el.ratio), 6)  # mm, mm, 1
    (0.316228, 0.169031, 1.870829)
    """

    a: np.ndarray
    b: np.ndarray
    alpha: np.ndarray
    A: np.ndarray
    B: np.ndarray
    area: np.ndarray
    elliptic: np.ndarray
    major_axis: np.ndarray | None = None
    minor_axis: np.ndarray | None = None

    @property
    def ratio(self) -> np.ndarray:
        """a / b (>= 1) [1]."""
        return self.a / self.b


def _check_positive(name, x, allow_inf=False):
    x = np.asarray(x, dtype=float)
    ok = (x > 0) & (np.isfinite(x) | allow_inf)
    if not np.all(ok):
        bad = x[~ok] if x.ndim else x
        raise ValueError(f"{name} must be > 0 and finite, got {np.ravel(bad)[:5]!r}")
    return x


def litvin_coefficients(kI1, kII1, kI2, kII2, sigma):
    """Litvin's A, B (seed 002 eq 2.6.4-2.6.6) and alpha (eq 2.6.1-2.6.2, measured in the
    sense of sigma) from the principal curvatures of both surfaces w.r.t. a common normal and
    the angle sigma from e_I^(1) to e_I^(2). Returns (A, B, alpha), A <= B, alpha the angle of
    the B direction (largest algebraic relative curvature).

    Computed as 2A, 2B = principal relative curvatures (gearrep.curvature), algebraically equal
    to the printed formulas but free of the cancellation in kS1 - kS2 - R.

    Parameters
    ----------
    kI1, kII1, kI2, kII2 : float or array_like
        Principal curvatures of surfaces 1 and 2 w.r.t. the common normal [1/length].
    sigma : float or array_like
        Angle from e_I^(1) to e_I^(2) [rad].

    Returns
    -------
    tuple
        (A, B [1/length], alpha [rad]).

    Examples
    --------
    >>> from gearrep.ellipse import litvin_coefficients
    >>> A, B, alpha = litvin_coefficients(-0.05, 0.0, 0.02, 0.02, 0.0)  # 1/mm, rad
    >>> round(float(A), 12), round(float(B), 12)
    (-0.035, -0.01)
    """
    k1, k2, alpha = relative_principal_curvatures(kI1, kII1, kI2, kII2, sigma)
    return 0.5 * k2, 0.5 * k1, alpha


def _wrap_half_pi(x):
    """Wrap an axis angle to (-pi/2, pi/2]."""
    return np.pi / 2 - np.mod(np.pi / 2 - x, np.pi)


def _ellipse_from_AB(A, B, alpha_B, delta):
    delta = _check_positive("delta (elastic approach)", delta)
    A, B, alpha_B, delta = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (A, B, alpha_B, delta)))
    with np.errstate(divide="ignore"):
        sa = np.sqrt(np.abs(delta / A))  # along the A direction (alpha_B + pi/2)
        sb = np.sqrt(np.abs(delta / B))  # along the B direction (alpha_B)
    # minor axis = direction of larger |relative curvature|
    b_is_minor = np.abs(B) >= np.abs(A)
    a = np.where(b_is_minor, sa, sb)
    b = np.where(b_is_minor, sb, sa)
    alpha = _wrap_half_pi(np.where(b_is_minor, alpha_B, alpha_B + np.pi / 2))
    # both relative curvatures of one sign, the smaller not a rounding-made fraction of the larger
    # (a line contact: conjugate flanks give ~1e-12 of it, and an axis of ~1e15 mm)
    elliptic = (A * B > 0) & (np.minimum(np.abs(A), np.abs(B)) > LINE_CONTACT_RTOL * np.maximum(np.abs(A), np.abs(B)))
    return ContactEllipse(a, b, alpha, A, B, np.pi * a * b, elliptic)


def elastic_ellipse(kI1, kII1, kI2, kII2, sigma, delta) -> ContactEllipse:
    """Elastic-approach contact ellipse from both surfaces' principal curvatures (common
    normal), the angle sigma between e_I^(1) and e_I^(2) and the elastic approach ``delta``
    (> 0). Seed 002 eq 2.6.1-2.6.6 = seed 000 eq 5.14-5.17 = seed 004 eq 21-27.

    Only cos 2sigma enters a and b, so an unsigned sigma = arccos(e_I^(1).e_I^(2)) (seed 000
    eq 5.15) gives the right axes; alpha's sign then follows that sigma's sense.

    Parameters
    ----------
    kI1, kII1, kI2, kII2 : float or array_like
        Principal curvatures of surfaces 1 and 2 w.r.t. the common normal [1/length].
    sigma : float or array_like
        Angle from e_I^(1) to e_I^(2) [rad].
    delta : float or array_like
        Elastic approach [length], > 0.

    Returns
    -------
    ContactEllipse
        Semi-axes [length], angle, coefficients, area (no axis vectors).

    Raises
    ------
    ValueError
        If ``delta`` is not finite and > 0.

    Examples
    --------
    >>> from gearrep.ellipse import elastic_ellipse
    >>> el = elastic_ellipse(-0.05, 0.0, 0.02, 0.02, 0.0, 0.001)  # 1/mm, rad, mm
    >>> round(float(el.a), 6), round(float(el.b), 6), bool(el.elliptic)  # mm
    (0.316228, 0.169031, True)
    """
    A, B, alpha = litvin_coefficients(kI1, kII1, kI2, kII2, sigma)
    return _ellipse_from_AB(A, B, alpha, delta)


def elastic_ellipse_from_relative(k1_rel, k2_rel, delta, alpha=0.0) -> ContactEllipse:
    """Elastic-approach ellipse from the two principal relative curvatures (any order) and
    delta: A = min/2, B = max/2 (seed 002 eq 2.6.3-2.6.5 with 2A, 2B the principal relative
    curvatures). ``alpha`` is the angle of the max-relative-curvature direction from the
    reference direction (default 0); the returned alpha refers to the minor axis.

    Parameters
    ----------
    k1_rel, k2_rel : float or array_like
        Principal relative curvatures [1/length].
    delta : float or array_like
        Elastic approach [length], > 0.
    alpha : float or array_like, optional
        Angle of the max-relative-curvature direction [rad].

    Returns
    -------
    ContactEllipse
        Semi-axes [length], angle, coefficients, area.

    Raises
    ------
    ValueError
        If ``delta`` is not finite and > 0.

    Examples
    --------
    >>> from gearrep.ellipse import elastic_ellipse_from_relative
    >>> el = elastic_ellipse_from_relative(0.07, 0.02, 0.001)  # any order
    >>> round(float(el.A), 12), round(float(el.B), 12)  # 1/mm
    (0.01, 0.035)
    """
    k1_rel, k2_rel = np.broadcast_arrays(np.asarray(k1_rel, float), np.asarray(k2_rel, float))
    alpha = np.asarray(alpha, dtype=float)
    swap = k2_rel > k1_rel
    hi = np.where(swap, k2_rel, k1_rel)
    lo = np.where(swap, k1_rel, k2_rel)
    alpha_B = np.where(swap, alpha + np.pi / 2, alpha)
    return _ellipse_from_AB(0.5 * lo, 0.5 * hi, alpha_B, delta)


def elastic_ellipse_at(
    c1: PrincipalCurvatures, c2: PrincipalCurvatures, delta, *, normal_tol: float = 1e-6
) -> ContactEllipse:
    """Elastic-approach ellipse from both surfaces' :class:`PrincipalCurvatures` at the
    contact point (same unit normal; see gearrep.curvature.with_opposite_normal), including
    the unit 3-vectors of the major and minor axes. Seed 002 eq 2.6.1-2.6.6 with the true
    signed sigma (gearrep.curvature.relative_curvature).

    Parameters
    ----------
    c1, c2 : gearrep.curvature.PrincipalCurvatures
        Both surfaces at the contact point, with the same unit normal.
    delta : float or array_like
        Elastic approach [length], > 0.
    normal_tol : float, optional
        Angle [rad] the two normals may differ by.

    Returns
    -------
    ContactEllipse
        With the axes' unit vectors.

    Raises
    ------
    ValueError
        If the normals differ or ``delta`` is bad.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.curvature import principal_curvatures, with_opposite_normal
    >>> from gearrep.surfaces.analytic import Cylinder, Sphere
    >>> c1 = principal_curvatures(Cylinder(R=20.0).evaluate(0.0, 0.0))  # mm; normal (1, 0, 0)
    >>> c2 = with_opposite_normal(principal_curvatures(Sphere(R=50.0).evaluate(np.pi, 0.0)))  # facing it
    >>> from gearrep.ellipse import elastic_ellipse_at
    >>> el = elastic_ellipse_at(c1, c2, 0.001)  # delta [mm]
    >>> round(float(el.a), 6), round(float(el.b), 6), np.round(np.abs(el.major_axis), 12).tolist()
    (0.316228, 0.169031, [0.0, 0.0, 1.0])
    """
    rel = relative_curvature(c1, c2, normal_tol=normal_tol)
    el = _ellipse_from_AB(0.5 * rel.k2, 0.5 * rel.k1, rel.alpha, delta)
    b_is_minor = (np.abs(el.B) >= np.abs(el.A))[..., None]
    minor = np.where(b_is_minor, rel.e1, rel.e2)
    major = np.cross(minor, rel.normal)  # perpendicular, in the tangent plane
    return el._replace(major_axis=major, minor_axis=minor)


# ------------------------------------------------------------------------------------ Hertz


class HertzContact(NamedTuple):
    """Hertz elliptical contact (Johnson sect. 4.2).

    a >= b: semi-axes (a along the direction of the SMALLER relative curvature); p0: maximum
    pressure = 3P/(2 pi a b); approach: mutual approach of distant points = p0 b K(e) / E*;
    e: eccentricity sqrt(1 - b^2/a^2); A, B: gap coefficients (gap = A x^2 + B y^2, A <= B);
    Estar: effective modulus; residual, iterations, status: the eccentricity solve
    (gearrep.solve record; Status.SINGULAR where the relative curvatures are not both of one
    sign, outputs NaN there).

    Attributes
    ----------
    a, b : numpy.ndarray
        Semi-axes, a >= b [length].
    p0 : numpy.ndarray
        Maximum pressure [force/length^2, MPa for N and mm].
    approach : numpy.ndarray
        Mutual approach of distant points [length].
    e : numpy.ndarray
        Eccentricity [1].
    A, B : numpy.ndarray
        Gap coefficients [1/length].
    Estar : numpy.ndarray
        Effective modulus [force/length^2].
    residual, iterations, status : numpy.ndarray
        The eccentricity solve's record.

    Examples
    --------
    >>> from gearrep.ellipse import hertz_contact
    >>> h = hertz_contact(0.02, 0.07, 1000.0, 210e3, 0.3)  # 1/mm, N, MPa
    >>> round(float(h.a), 4), round(float(h.b), 4), round(float(h.e), 4)  # mm, mm, 1
    (0.8273, 0.3609, 0.8998)
    """

    a: np.ndarray
    b: np.ndarray
    p0: np.ndarray
    approach: np.ndarray
    e: np.ndarray
    A: np.ndarray
    B: np.ndarray
    Estar: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    status: np.ndarray

    @property
    def converged(self) -> np.ndarray:
        """Boolean mask of the rows whose eccentricity solve converged."""
        return self.status == Status.CONVERGED


def effective_modulus(E1, nu1, E2=None, nu2=None) -> np.ndarray:
    """E* with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson eq 4.22); the second body
    defaults to the first material. E must be > 0 and -1 < nu <= 0.5.

    Parameters
    ----------
    E1, nu1 : float or array_like
        Young's modulus [any unit, MPa in the library] and Poisson's ratio of body 1.
    E2, nu2 : float or array_like, optional
        Those of body 2 (default body 1's).

    Returns
    -------
    numpy.ndarray
        E* [the unit of E].

    Raises
    ------
    ValueError
        If a modulus is not finite and > 0 or a Poisson's ratio is outside (-1, 0.5].

    Examples
    --------
    >>> from gearrep.ellipse import effective_modulus
    >>> round(float(effective_modulus(210e3, 0.3)), 3)  # steel on steel [MPa]
    115384.615
    """
    E2 = E1 if E2 is None else E2
    nu2 = nu1 if nu2 is None else nu2
    for name, E in (("E1", E1), ("E2", E2)):
        _check_positive(name + " (Young's modulus)", E)
    for name, nu in (("nu1", nu1), ("nu2", nu2)):
        nu = np.asarray(nu, dtype=float)
        if not np.all((nu > -1.0) & (nu <= 0.5)):
            raise ValueError(f"{name} (Poisson ratio) must be in (-1, 0.5], got {np.ravel(nu)[:5]!r}")
    E1, nu1, E2, nu2 = (np.asarray(x, dtype=float) for x in (E1, nu1, E2, nu2))
    return 1.0 / ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2)


def _integrals(p):
    """I_s = int_0^{pi/2} sin^2 t / D dt and I_c = int cos^2 t / D dt, D = sqrt(1 - m sin^2 t),
    m = e^2 = 1 - p, p = (b/a)^2: I_s = R_D(0, p, 1)/3 = (K - E)/m, I_c = p R_D(0, 1, p)/3 =
    (E - p K)/m (DLMF 19.25.1); and K(m) = R_F(0, p, 1)."""
    from scipy.special import elliprd, elliprf  # imported here: scipy.special costs 0.2 s per process

    return elliprd(0.0, p, 1.0) / 3.0, p * elliprd(0.0, 1.0, p) / 3.0, elliprf(0.0, p, 1.0)


def hertz_ratio(b_over_a) -> np.ndarray:
    """B/A of the Hertz gap for an ellipse of aspect b/a (Johnson eq 4.32-4.33):
    B/A = [(a/b)^2 E(e) - K(e)] / [K(e) - E(e)] = R_D(0, 1, p) / R_D(0, p, 1), p = (b/a)^2.
    (scipy's ellipk/ellipe take the parameter m = e^2; the Carlson form avoids the 0/0 at
    e -> 0.)

    Parameters
    ----------
    b_over_a : float or array_like
        Aspect b/a of the ellipse, in (0, 1].

    Returns
    -------
    numpy.ndarray
        B/A [1].

    Examples
    --------
    >>> from gearrep.ellipse import hertz_ratio
    >>> round(float(hertz_ratio(1.0)), 12), round(float(hertz_ratio(0.5)), 6)
    (1.0, 2.842753)
    """
    p = np.asarray(b_over_a, dtype=float) ** 2
    from scipy.special import elliprd

    return elliprd(0.0, 1.0, p) / elliprd(0.0, p, 1.0)


#: a relative curvature below this fraction of the other counts as zero: line contact, no ellipse
#: (conjugate flanks give ~1e-12 from rounding, the flattest crowned contacts here ~1e-3)
LINE_CONTACT_RTOL = 1e-9


def hertz_contact(
    k1_rel,
    k2_rel,
    load,
    E1,
    nu1,
    E2=None,
    nu2=None,
    *,
    tol: float = 1e-13,
    maxiter: int = 50,
    line_rtol: float = LINE_CONTACT_RTOL,
) -> HertzContact:
    """Hertz contact of two elastic bodies from the principal relative curvatures at the
    contact point (kappa^(1) - kappa^(2), any common normal; both must have one sign), the
    normal load and the elastic constants. Johnson sect. 4.2 (eq 4.33-4.36, 3.63-3.64):

    gap = A x^2 + B y^2, A = min|k_rel|/2, B = max|k_rel|/2; the aspect b/a solves
    B/A = R_D(0, 1, p)/R_D(0, p, 1), p = (b/a)^2 (:func:`hertz_ratio`), by Newton on
    s = ln(a/b) >= 0 (gearrep.solve.newton; residual/status reported); then
    a^3 = 3 P I_s / (2 pi A E*), I_s = (K - E)/e^2, b = a sqrt(p), p0 = 3P/(2 pi a b),
    approach = p0 b K(e)/E*. Circular case: a^3 = 3 P R/(4 E*) with 1/R = 2A.
    A row whose smaller |relative curvature| is at most ``line_rtol`` times the larger is a line
    contact (no finite ellipse; :func:`hertz_line_max_pressure_MPa` applies): NaN, status SINGULAR,
    not a tiny rounding-made pressure.

    Parameters
    ----------
    k1_rel, k2_rel : float or array_like
        Principal relative curvatures [1/length], both of one sign.
    load : float or array_like
        Normal load [force], > 0.
    E1, nu1, E2, nu2 : float
        Elastic constants (as :func:`effective_modulus`; force/length^2).
    tol, maxiter : optional
        Newton settings of the eccentricity solve.
    line_rtol : float, optional
        Ratio of the relative curvatures below which the contact is a line.

    Returns
    -------
    HertzContact
        Semi-axes [length], p0 [force/length^2], approach [length], ... and the solve's record.

    Raises
    ------
    ValueError
        If the load or an elastic constant is bad.

    Examples
    --------
    >>> from gearrep.ellipse import hertz_contact
    >>> h = hertz_contact(0.1, 0.1, 1000.0, 210e3, 0.3)  # 1/mm, N, MPa: a ball of radius 20 mm on a flat
    >>> round(float(h.a), 6), round(float(h.p0), 2), int(h.status)  # mm, MPa
    (0.402073, 2953.47, 0)
    """
    load = _check_positive("load", load)
    Estar = effective_modulus(E1, nu1, E2, nu2)
    k1_rel, k2_rel, load, Estar = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (k1_rel, k2_rel, load, Estar))
    )
    shape = k1_rel.shape
    k1f, k2f = k1_rel.ravel(), k2_rel.ravel()
    ok = (k1f * k2f > 0) & np.isfinite(k1f) & np.isfinite(k2f)
    ok &= np.minimum(np.abs(k1f), np.abs(k2f)) > line_rtol * np.maximum(np.abs(k1f), np.abs(k2f))
    A = 0.5 * np.minimum(np.abs(k1f), np.abs(k2f))
    B = 0.5 * np.maximum(np.abs(k1f), np.abs(k2f))
    n = k1f.size
    s = np.full(n, np.nan)
    res = np.full(n, np.nan)
    its = np.zeros(n, dtype=int)
    status = np.full(n, int(Status.SINGULAR), dtype=int)
    idx = np.flatnonzero(ok)
    if idx.size:
        target = np.log(B[idx] / A[idx])

        def fun(x, rows):
            p = np.exp(-2.0 * x[:, 0])
            return (np.log(hertz_ratio(np.sqrt(p))) - target[rows])[:, None]

        x0 = (2.0 / 3.0) * target  # a/b ~ (B/A)^(2/3) (Johnson)
        sr: SolveResult = newton(fun, x0[:, None], tol=tol, maxiter=maxiter, lower=[0.0], rows=True)
        s[idx], res[idx], its[idx], status[idx] = sr.x[:, 0], sr.residual, sr.iterations, sr.status
    p = np.exp(-2.0 * s)
    Is, _, K = _integrals(np.where(ok, p, 1.0))
    P, Es = load.ravel(), Estar.ravel()
    with np.errstate(invalid="ignore", divide="ignore"):
        a = np.cbrt(3.0 * P * Is / (2.0 * np.pi * A * Es))
        b = a * np.sqrt(p)
        p0 = 3.0 * P / (2.0 * np.pi * a * b)
        approach = p0 * b * K / Es
        e = np.sqrt(np.maximum(-np.expm1(-2.0 * s), 0.0))
    bad = ~ok
    for arr in (a, b, p0, approach, e):
        arr[bad] = np.nan
    r = lambda x: x.reshape(shape)  # noqa: E731
    return HertzContact(r(a), r(b), r(p0), r(approach), r(e), r(A), r(B), Estar, r(res), r(its), r(status))


def hertz_contact_at(
    c1: PrincipalCurvatures,
    c2: PrincipalCurvatures,
    load_N,
    E1_MPa,
    nu1,
    E2_MPa=None,
    nu2=None,
    *,
    normal_tol: float = 1e-6,
    tol: float = 1e-13,
    maxiter: int = 50,
) -> HertzContact:
    """Hertz contact at a contact point from both surfaces' :class:`PrincipalCurvatures` (lengths in
    mm, curvatures in 1/mm, same unit normal; see gearrep.curvature.with_opposite_normal), the
    normal load [N] and the elastic constants [MPa]: the relative curvature
    (gearrep.curvature.relative_curvature, true angle sigma between the principal directions) into
    :func:`hertz_contact`. Returns a, b [mm], p0 [MPa] (the maximum contact pressure, equal to
    :func:`hertz_max_pressure_MPa` of the load and the semi-axes), approach [mm]. This is the route
    of thesis eq 15-24 (seed 003), which adds the principal curvatures of equal index (eq 19) and
    so holds only where the principal directions of both surfaces coincide (sigma = 0).

    Parameters
    ----------
    c1, c2 : gearrep.curvature.PrincipalCurvatures
        Both surfaces at the contact point (1/mm), with the same unit normal.
    load_N : float or array_like
        Normal load [N].
    E1_MPa, nu1, E2_MPa, nu2 : float
        Elastic constants [MPa] (body 2 defaults to body 1).
    normal_tol, tol, maxiter : optional
        As :func:`gearrep.curvature.relative_curvature` and :func:`hertz_contact`.

    Returns
    -------
    HertzContact
        a, b [mm], p0 [MPa], approach [mm], ...

    Raises
    ------
    ValueError
        If the normals differ, or the load or an elastic constant is bad.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.curvature import principal_curvatures, with_opposite_normal
    >>> from gearrep.surfaces.analytic import Cylinder, Sphere
    >>> c1 = principal_curvatures(Cylinder(R=20.0).evaluate(0.0, 0.0))  # mm; normal (1, 0, 0)
    >>> c2 = with_opposite_normal(principal_curvatures(Sphere(R=50.0).evaluate(np.pi, 0.0)))  # facing it
    >>> from gearrep.ellipse import hertz_contact_at
    >>> h = hertz_contact_at(c1, c2, 1000.0, 210e3, 0.3)  # N, MPa
    >>> round(float(h.a), 4), round(float(h.b), 4), round(float(h.p0), 1)  # mm, mm, MPa
    (0.8273, 0.3609, 1599.1)
    """
    rel = relative_curvature(c1, c2, normal_tol=normal_tol)
    return hertz_contact(rel.k1, rel.k2, load_N, E1_MPa, nu1, E2_MPa, nu2, tol=tol, maxiter=maxiter)


def hertz_max_pressure_MPa(load_N, a_mm, b_mm) -> np.ndarray:
    """Maximum pressure [MPa = N/mm^2] of a Hertz (ellipsoidal) pressure distribution carrying the
    normal load ``load_N`` [N] on an ellipse of semi-axes ``a_mm``, ``b_mm`` [mm]:
    p_max = 3 P / (2 pi a b) (Johnson eq 3.63-3.64; seed 003 eq 24). The load is the integral of
    p_max sqrt(1 - x^2/a^2 - y^2/b^2) over the ellipse.

    Parameters
    ----------
    load_N : float or array_like
        Normal load [N], > 0.
    a_mm, b_mm : float or array_like
        Semi-axes [mm], > 0.

    Returns
    -------
    numpy.ndarray
        p_max [MPa].

    Raises
    ------
    ValueError
        If a value is not finite and > 0.

    Examples
    --------
    >>> from gearrep.ellipse import hertz_max_pressure_MPa
    >>> round(float(hertz_max_pressure_MPa(1000.0, 1.0, 0.5)), 4)  # N, mm, mm -> MPa
    954.9297
    """
    P = _check_positive("load_N", load_N)
    a = _check_positive("a_mm (semi-axis)", a_mm)
    b = _check_positive("b_mm (semi-axis)", b_mm)
    return 3.0 * P / (2.0 * np.pi * a * b)


def hertz_line_max_pressure_MPa(load_per_length_N_per_mm, k_rel_per_mm, Estar_MPa) -> np.ndarray:
    """Maximum pressure [MPa] of a Hertz line contact (two cylinders with parallel axes, plane
    strain; Johnson eq 4.43-4.45): p_max = sqrt(P' E* k / pi) with P' the load per unit length
    [N/mm], k = 1/R the relative curvature across the line [1/mm] and E* the effective modulus
    [MPa] (:func:`effective_modulus`); the contact half-width is 2 P' / (pi p_max). The limit of
    the elliptical contact when one relative curvature vanishes (line contact of conjugate
    flanks), where :func:`hertz_contact` has no finite ellipse.

    Parameters
    ----------
    load_per_length_N_per_mm : float or array_like
        P' [N/mm], > 0.
    k_rel_per_mm : float or array_like
        Relative curvature across the line [1/mm], > 0.
    Estar_MPa : float or array_like
        E* [MPa], > 0.

    Returns
    -------
    numpy.ndarray
        p_max [MPa].

    Raises
    ------
    ValueError
        If a value is not finite and > 0.

    Examples
    --------
    >>> from gearrep.ellipse import effective_modulus, hertz_line_max_pressure_MPa
    >>> round(float(hertz_line_max_pressure_MPa(100.0, 0.1, effective_modulus(210e3, 0.3))), 3)  # MPa
    606.037
    """
    w = _check_positive("load_per_length_N_per_mm", load_per_length_N_per_mm)
    k = np.abs(np.asarray(k_rel_per_mm, dtype=float))
    _check_positive("|k_rel_per_mm| (relative curvature across the line)", k)
    Es = _check_positive("Estar_MPa", Estar_MPa)
    return np.sqrt(w * Es * k / np.pi)
