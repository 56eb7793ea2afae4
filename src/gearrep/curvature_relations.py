"""Principal curvatures of an enveloping (generated) surface from those of the generating tool.

Sources: Litvin & Fuentes, *Gear Geometry and Applied Theory* (GGAT), 2nd ed., ch. 8, "Direct
relations between principal curvatures and directions of mating surfaces" (one-parameter
enveloping, coefficients a_13, a_23, a_33); seed 000 ch. 4, eq 4.6-4.39 (two-parameter
enveloping: the 4 x 4 system 4.33, b_11, b_12, b_22 from 4.37-4.39, sigma, k_s, k_q from
4.24-4.26). The derivation below is ours, in the sign convention of :mod:`gearrep.curvature`
(k > 0 where the surface bends towards the normal n = unit(r_u x r_v) of the TOOL, which is
the common normal at the contact point), and with the kinematics written through the motion
matrix M_21(m) of :mod:`gearrep.envelope` instead of the fixed-frame vectors (rho, P, V^(O))
of seed 000 eq 4.6.

Derivation (all vectors in the tool frame S_1 at the instant; tangent vectors in the
orthonormal basis e_f, e_h of the tool's principal directions, k_f >= k_h):

* Let the contact point move: x = v_r^(1) its velocity over the tool, mu = dm/dt the motion
  rates, w_j = v^(12, j) and omega_j the relative (tool w.r.t. generated member) velocity and
  angular velocity per unit m_j, i.e. the twist W_j = M_21^{-1} dM_21/dm_j. Its velocity over
  the generated surface is y = v_r^(2) = x + sum_j w_j mu_j (seed 000 eq 4.13/4.15), and the
  normal, fixed in S_2, satisfies dn^(2) = dn^(1) + sum_j (omega_j x n) mu_j (eq 4.14/4.16).

* Rodrigues' formula on both surfaces, dn^(i) = -K_i v_r^(i) (K_i the symmetric shape operator;
  seed 000 eq 4.9-4.10 with K_1 = -diag(k_f, k_h)), gives (K_2 - K_1) y = C mu with columns

      c_j = -K_1 w_j + (n x omega_j)          (GGAT: a_13 = c_j . e_f, a_23 = c_j . e_h)

  which is seed 000 eq 4.17-4.20 (B = K_2 - K_1 = K_1^seed - L_12 K_2^seed L_21).

* Differentiating the equations of meshing n . w_j = 0 along the motion (seed 000 eq 4.6,
  GGAT's differentiated equation of meshing) gives c_j . y = sum_i E_ji mu_i with

      E_ij = -II_1(w_i, w_j) + n . (omega_i x w_j) + n . (omega_j x w_i) - n . (M^{-1} d2M_ij r_1)

  (symmetric; for k = 1 this is GGAT's a_33; seed 000 eq 4.27-4.32 are the same rows).

* For every mu (the contact path is free in two-parameter enveloping; for one-parameter
  enveloping y ranges over the line c . y = E) the two must hold together, so the (2+k)-square
  matrix [[K_2 - K_1, C], [C^T, E]] has rank k (seed 000: rank of 4.33 equals two; GGAT: the
  3 x 3 matrix of a_ij has rank one), whence

      K_2 = K_1 + C E^{-1} C^T.                                                    (*)

  k = 1: K_2 = K_1 + c c^T / a_33, i.e. k_s + k_q = k_f + k_h + (a_13^2 + a_23^2)/a_33 and
  tan 2 sigma = 2 a_13 a_23 / (a_13^2 - a_23^2 + (k_f - k_h) a_33) (GGAT ch. 8).
  E singular (a_33 = 0) is exactly the singular-point condition of :mod:`gearrep.envelope`.

Errors found in the printed seed 000 equations (evidence: cofactor expansion of 4.34-4.36 and
the tests in tests/unit/core/test_curvature_relations.py):

* eq 4.37-4.39: the numerators have the wrong sign. Expanding the rank condition 4.34 along its
  first row gives b_11 (b_33 b_44 - b_34 b_43) = b_13 (b_31 b_44 - b_34 b_41)
  - b_14 (b_31 b_43 - b_33 b_41), i.e. b_11 = [b_13 b_31 b_44 - b_13 b_34 b_41 - b_14 b_31 b_43
  + b_14 b_33 b_41] / (b_33 b_44 - b_34 b_43): every term of the printed numerator has the
  opposite sign. The same holds for b_12 (4.38, from 4.36) and b_22 (4.39, from 4.35). With the
  printed signs K_2 = K_1 - C E^{-1} C^T, which disagrees with the directly computed curvatures
  of the generated surface (tested); with the corrected signs they agree to ~1e-10.

* eq 4.23: the last form lacks the factor 0.5: -k_h + 0.5 (k_s + k_q) - 0.5 (k_s - k_q) cos 2 sigma
  (the first form, -k_h + k_q cos^2 sigma + k_s sin^2 sigma, is right; possibly lost in OCR).

* eq 4.36 as printed repeats the row (b_32, b_33, b_34); it must be the determinant of
  [[b_12, b_13, b_14], [b_32, b_33, b_34], [b_42, b_43, b_44]] (OCR).

* eq 4.24 prints "= 2 b_12 / b_12" after the correct first form (OCR).

* eq 4.25-4.26 are right but divide by sin 2 sigma; :func:`two_parameter_principal_curvatures` uses
  the equivalent k_s - k_q = 2 b_12 / sin 2 sigma = sign * hypot(2 b_12, D), exact also at
  b_12 = 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .curvature import principal_curvatures, sym2_eig
from .envelope import Envelope
from .surface import cross

__all__ = [
    "GeneratedCurvatures",
    "generated_curvatures",
    "litvin_one_parameter",
    "two_parameter_system",
    "two_parameter_b_coefficients",
    "two_parameter_principal_curvatures",
]


@dataclass(frozen=True)
class GeneratedCurvatures:
    """Curvatures of the generated surface at contact points, from eq (*) of the module doc.

    All vectors are in the generated member's frame S_2; curvatures are signed with respect to
    ``normal`` (the tool normal n_1 = unit(r_u x r_v) carried into S_2).

    Parameters
    ----------
    k1, k2 : numpy.ndarray
        (n,) principal curvatures of the generated surface [1/length], k1 >= k2 (k_s, k_q of
        seed 000 in the algebraic order; see :func:`two_parameter_principal_curvatures` for the
        seed's labels).
    e1, e2 : numpy.ndarray
        (n, 3) its principal directions (unit, e1 x e2 = normal).
    normal : numpy.ndarray
        (n, 3) the tool normal in S_2.
    k_f, k_h : numpy.ndarray
        (n,) tool principal curvatures [1/length] (k_f >= k_h).
    e_f, e_h : numpy.ndarray
        (n, 3) tool principal directions in S_2.
    sigma : numpy.ndarray
        (n,) angle from e_f to e1 about ``normal`` [rad], in (-pi/2, pi/2].
    A : numpy.ndarray
        (n, 2+k, 2+k) [[K_2 - K_1, C], [C^T, E]] in the basis (e_f, e_h); rank k. For k = 1
        A = [[a11, a12, a13], [a12, a22, a23], [a13, a23, a33]] (GGAT ch. 8 notation).

    Examples
    --------
    A straight rack (a plane, k_f = k_h = 0) generates an involute cylinder: at the pitch point its
    profile curvature is 1 / (r_p sin alpha):

    >>> import math
    >>> import numpy as np
    >>> from gearrep.curvature_relations import generated_curvatures
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0))  # rad, r_p mm
    >>> gc = generated_curvatures(env, env.solve(0.0, 0.0, guess=0.0).params)  # u, v [mm]
    >>> np.round([gc.k1[0], gc.k2[0]], 6).tolist(), round(1 / (30.0 * math.sin(math.radians(20))), 6)  # 1/mm
    ([0.0, -0.09746], 0.09746)
    >>> gc.C.shape, gc.E.shape  # k = 1
    ((1, 2, 1), (1, 1, 1))
    """

    k1: np.ndarray
    k2: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    normal: np.ndarray
    k_f: np.ndarray
    k_h: np.ndarray
    e_f: np.ndarray
    e_h: np.ndarray
    sigma: np.ndarray
    A: np.ndarray

    @property
    def C(self) -> np.ndarray:
        """(n, 2, k) columns c_j in (e_f, e_h) components (GGAT a_13, a_23 for k = 1)."""
        return self.A[:, :2, 2:]

    @property
    def E(self) -> np.ndarray:
        """(n, k, k) the matrix E (GGAT a_33 for k = 1); singular at singular points."""
        return self.A[:, 2:, 2:]


def _coefficients(envelope: Envelope, q):
    """Tool principal data and the C, E coefficients (module doc) at flat q, in S_1."""
    loc = envelope.local(q)
    pc = principal_curvatures(loc.tool)
    k1, k2, e1, e2 = pc.k1, pc.k2, pc.e1, pc.e2
    n = loc.n
    w, om = loc.w, loc.omega  # (n,k,3)
    wf = np.einsum("nka,na->nk", w, e1)
    wh = np.einsum("nka,na->nk", w, e2)
    nxo = cross(n[:, None, :], om)  # n x omega_j
    C = np.stack(
        [-k1[:, None] * wf + np.einsum("nka,na->nk", nxo, e1), -k2[:, None] * wh + np.einsum("nka,na->nk", nxo, e2)],
        axis=1,
    )  # (n,2,k)
    II = k1[:, None, None] * wf[:, :, None] * wf[:, None, :] + k2[:, None, None] * wh[:, :, None] * wh[:, None, :]
    ow = np.einsum("na,nija->nij", n, cross(om[:, :, None, :], w[:, None, :, :]))  # n.(omega_i x w_j)
    E = -II + ow + np.swapaxes(ow, 1, 2) - np.einsum("na,nija->nij", n, loc.Xr)
    return loc, k1, k2, e1, e2, C, E


def generated_curvatures(envelope: Envelope, q) -> GeneratedCurvatures:
    """Principal curvatures and directions of the generated surface at contact points q
    (n, 2+k) of ``envelope`` (k = 1: GGAT ch. 8; k = 2: seed 000 eq 4.33-4.39 corrected):
    K_2 = K_1 + C E^{-1} C^T (eq * of the module doc). q must satisfy the equations of meshing
    (e.g. ``EnvelopeResult.params``); E singular (a singular point) gives non-finite values.

    Parameters
    ----------
    envelope : gearrep.envelope.Envelope
        The envelope.
    q : array_like
        (n, 2+k) finite contact parameters.

    Returns
    -------
    GeneratedCurvatures
        Curvatures [1/length] and directions in S_2.

    Raises
    ------
    ValueError
        If ``envelope`` is not an :class:`~gearrep.envelope.Envelope` or ``q`` is malformed.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.curvature_relations import generated_curvatures
    >>> from gearrep.surfaces.hob import GeneratedGear
    >>> gear = GeneratedGear()  # the convex flank of seed 000's pinion (20 teeth, R_c = 110 mm)
    >>> rec = gear.solve([6.0], [0.0])  # l [mm], psi [rad]
    >>> gc = generated_curvatures(gear.envelope(), rec.params)
    >>> np.round(gc.k1, 6).tolist(), np.round(gc.k2, 6).tolist()  # 1/mm
    ([0.078881], [0.008369])
    """
    if not isinstance(envelope, Envelope):
        raise ValueError("envelope must be a gearrep.envelope.Envelope")
    q = np.atleast_2d(np.asarray(q, dtype=float))
    if q.ndim != 2 or q.shape[1] != 2 + envelope.k or not np.all(np.isfinite(q)):
        raise ValueError(f"q must be a finite array of shape (n, {2 + envelope.k}), got {q.shape}")
    loc, k_f, k_h, e_f, e_h, C, E = _coefficients(envelope, q)
    with np.errstate(divide="ignore", invalid="ignore"):
        good = np.abs(np.linalg.det(E)) > 0
        Einv = np.full(E.shape, np.nan)
        if np.any(good):
            Einv[good] = np.linalg.inv(E[good])
        B = np.einsum("nai,nij,nbj->nab", C, Einv, C)
    b11 = B[:, 0, 0] + k_f
    b12 = B[:, 0, 1]
    b22 = B[:, 1, 1] + k_h
    k1, k2, sigma = sym2_eig(b11, b12, b22)
    R = loc.M[:, :3, :3]

    def carried(v):  # a vector of the generating frame in the frame of the surface
        return np.einsum("nab,nb->na", R, v)

    e1 = np.cos(sigma)[:, None] * e_f + np.sin(sigma)[:, None] * e_h
    nk = envelope.k
    A = np.zeros((q.shape[0], 2 + nk, 2 + nk))
    A[:, :2, :2], A[:, :2, 2:], A[:, 2:, :2], A[:, 2:, 2:] = B, C, np.swapaxes(C, 1, 2), E
    return GeneratedCurvatures(
        k1, k2, carried(e1), carried(cross(loc.n, e1)), carried(loc.n), k_f, k_h, carried(e_f), carried(e_h), sigma, A
    )


def litvin_one_parameter(k_f, k_h, a13, a23, a33):
    """Generated-surface curvatures from GGAT ch. 8 (one-parameter enveloping):

        tan 2 sigma = 2 a13 a23 / (a13^2 - a23^2 + (k_f - k_h) a33)
        k_s + k_q   = k_f + k_h + (a13^2 + a23^2) / a33
        k_s - k_q   = 2 a13 a23 / (a33 sin 2 sigma)   (= hypot(.)/a33 with the sign of 2 sigma)

    in the sign convention of the module doc (a_ij = entries of ``GeneratedCurvatures.A``).
    Returns (k_s, k_q, sigma) with k_s >= k_q and sigma in (-pi/2, pi/2] the angle from e_f to
    e_s. Vectorised; a33 must be nonzero (a33 = 0 is a singular point).

    Parameters
    ----------
    k_f, k_h : float or array_like
        Tool principal curvatures [1/length].
    a13, a23, a33 : float or array_like
        Entries of A [1/length, 1, length] (``GeneratedCurvatures.A``); a33 nonzero.

    Returns
    -------
    k_s, k_q : numpy.ndarray
        [1/length], k_s >= k_q.
    sigma : numpy.ndarray
        [rad].

    Raises
    ------
    ValueError
        If some a33 is zero.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.curvature_relations import generated_curvatures, litvin_one_parameter
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0))  # rad, r_p mm
    >>> gc = generated_curvatures(env, env.solve(0.0, 0.0, guess=0.0).params)  # u, v [mm]
    >>> A = gc.A[0]
    >>> k_s, k_q, sigma = litvin_one_parameter(gc.k_f, gc.k_h, A[0, 2], A[1, 2], A[2, 2])
    >>> np.round([k_s[0], k_q[0]], 6).tolist()  # 1/mm, as generated_curvatures
    [0.0, -0.09746]
    """
    k_f, k_h, a13, a23, a33 = np.broadcast_arrays(*(np.asarray(x, float) for x in (k_f, k_h, a13, a23, a33)))
    if np.any(a33 == 0):
        raise ValueError("a33 must be nonzero (a33 = 0 is a singular point of the generated surface)")
    # K_2 = K_1 + c c^T / a33 in (e_f, e_h)
    return sym2_eig(k_f + a13**2 / a33, a13 * a23 / a33, k_h + a23**2 / a33)


def two_parameter_system(envelope: Envelope, q) -> np.ndarray:
    """The 4 x 4 matrix of seed 000 eq 4.33 in the seed's arrangement (rows 4.18, 4.27, 4.30;
    unknowns (v_f^(2), v_h^(2), dtheta/dt, dpsi/dt)) at contact points q (n, 4) of a
    two-parameter envelope: [[B, -C], [C^T, -E]] with the unknown block B = (b_11, b_12; b_21,
    b_22) returned as NaN (it follows from :func:`two_parameter_b_coefficients`).

    Parameters
    ----------
    envelope : gearrep.envelope.Envelope
        A two-parameter envelope.
    q : array_like
        (n, 4) contact parameters.

    Returns
    -------
    numpy.ndarray
        (n, 4, 4), the block B NaN.

    Raises
    ------
    ValueError
        If the envelope is not a two-parameter one.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.curvature_relations import two_parameter_system
    >>> from gearrep.surfaces.hob import GeneratedGear
    >>> gear = GeneratedGear()
    >>> b = two_parameter_system(gear.envelope(), gear.solve([6.0], [0.0]).params)  # l [mm], psi [rad]
    >>> b.shape, bool(np.isnan(b[0, :2, :2]).all())
    ((1, 4, 4), True)
    """
    if envelope.k != 2:
        raise ValueError(f"envelope must be a two-parameter envelope (k = 2), got k = {envelope.k}")
    q = np.atleast_2d(np.asarray(q, dtype=float))
    _, _, _, _, _, C, E = _coefficients(envelope, q)
    b = np.full((q.shape[0], 4, 4), np.nan)
    b[:, :2, 2:] = -C
    b[:, 2:, :2] = np.swapaxes(C, 1, 2)
    b[:, 2:, 2:] = -E
    return b


def two_parameter_b_coefficients(b) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """b_11, b_12, b_22 from the rank-2 condition of seed 000 eq 4.34-4.36, with the sign of
    the printed eq 4.37-4.39 CORRECTED (module doc): B = R Q^{-1} P with R = (b_13 b_14; b_23
    b_24), Q = (b_33 b_34; b_43 b_44), P = (b_31 b_32; b_41 b_42), e.g.

        b_11 = (b_13 b_31 b_44 - b_13 b_34 b_41 - b_14 b_31 b_43 + b_14 b_33 b_41)
               / (b_33 b_44 - b_34 b_43).

    ``b`` (..., 4, 4); entries b_11..b_22 are ignored.

    Parameters
    ----------
    b : array_like
        (..., 4, 4) the system of :func:`two_parameter_system`.

    Returns
    -------
    b11, b12, b22 : numpy.ndarray
        [1/length].

    Raises
    ------
    ValueError
        If ``b`` is not (..., 4, 4) or b_33 b_44 - b_34 b_43 vanishes.

    Examples
    --------
    The corrected coefficients are K_2 - K_1 of :func:`generated_curvatures`, entry by entry:

    >>> import numpy as np
    >>> from gearrep.curvature_relations import generated_curvatures, two_parameter_b_coefficients
    >>> from gearrep.curvature_relations import two_parameter_system
    >>> from gearrep.surfaces.hob import GeneratedGear
    >>> gear = GeneratedGear()
    >>> q = gear.solve([6.0], [0.0]).params  # l [mm], psi [rad]
    >>> b11, b12, b22 = two_parameter_b_coefficients(two_parameter_system(gear.envelope(), q))
    >>> A = generated_curvatures(gear.envelope(), q).A[0]
    >>> bool(np.allclose([b11[0], b12[0], b22[0]], [A[0, 0], A[0, 1], A[1, 1]], rtol=1e-12, atol=0))
    True
    """
    b = np.asarray(b, dtype=float)
    if b.shape[-2:] != (4, 4):
        raise ValueError(f"b must have shape (..., 4, 4), got {b.shape}")
    g = lambda i, j: b[..., i - 1, j - 1]  # noqa: E731 - 1-based like the seed
    den = g(3, 3) * g(4, 4) - g(3, 4) * g(4, 3)
    if np.any(den == 0):
        raise ValueError("b_33 b_44 - b_34 b_43 must be nonzero (it vanishes at singular points)")
    b11 = (
        g(1, 3) * g(3, 1) * g(4, 4)
        - g(1, 3) * g(3, 4) * g(4, 1)
        - g(1, 4) * g(3, 1) * g(4, 3)
        + g(1, 4) * g(3, 3) * g(4, 1)
    ) / den
    b12 = (
        g(1, 3) * g(3, 2) * g(4, 4)
        - g(1, 3) * g(3, 4) * g(4, 2)
        - g(1, 4) * g(3, 2) * g(4, 3)
        + g(1, 4) * g(3, 3) * g(4, 2)
    ) / den
    b22 = (
        g(2, 3) * g(3, 2) * g(4, 4)
        - g(2, 3) * g(3, 4) * g(4, 2)
        - g(2, 4) * g(3, 2) * g(4, 3)
        + g(2, 4) * g(3, 3) * g(4, 2)
    ) / den
    return b11, b12, b22


def _two_parameter_b_coefficients_printed(b):
    """Seed 000 eq 4.37-4.39 exactly as printed (wrong sign; kept to document the error)."""
    b = np.asarray(b, dtype=float)
    g = lambda i, j: b[..., i - 1, j - 1]  # noqa: E731
    den = g(3, 3) * g(4, 4) - g(3, 4) * g(4, 3)
    b11 = (
        g(1, 3) * g(3, 4) * g(4, 1)
        + g(1, 4) * g(4, 3) * g(3, 1)
        - g(1, 4) * g(3, 3) * g(4, 1)
        - g(1, 3) * g(3, 1) * g(4, 4)
    ) / den
    b12 = (
        g(1, 3) * g(3, 4) * g(4, 2)
        + g(1, 4) * g(4, 3) * g(3, 2)
        - g(1, 4) * g(3, 3) * g(4, 2)
        - g(1, 3) * g(3, 2) * g(4, 4)
    ) / den
    b22 = (
        g(2, 3) * g(3, 4) * g(4, 2)
        + g(2, 4) * g(4, 3) * g(3, 2)
        - g(2, 4) * g(3, 3) * g(4, 2)
        - g(2, 3) * g(3, 2) * g(4, 4)
    ) / den
    return b11, b12, b22


def two_parameter_principal_curvatures(b11, b12, b22, k_f, k_h):
    """k_s, k_q and sigma from seed 000 eq 4.24-4.26 (sigma from e_f to e_s about n).

    tan 2 sigma = 2 b_12 / (b_11 - b_22 + k_f - k_h) on the principal branch, sigma in
    [-pi/4, pi/4] (so e_s is the generated principal direction nearest e_f, the seed's
    labelling; k_s may be smaller than k_q), and
    k_s, k_q = 0.5 (b_11 + b_22 + k_f + k_h +- 2 b_12 / sin 2 sigma), evaluated as
    +- sign(D) hypot(2 b_12, D), D = b_11 - b_22 + k_f - k_h (equal, and finite at b_12 = 0).

    Parameters
    ----------
    b11, b12, b22 : float or array_like
        Coefficients of :func:`two_parameter_b_coefficients` [1/length].
    k_f, k_h : float or array_like
        Tool principal curvatures [1/length].

    Returns
    -------
    k_s, k_q : numpy.ndarray
        [1/length], the seed's labels.
    sigma : numpy.ndarray
        [rad], in [-pi/4, pi/4].

    Raises
    ------
    ValueError
        If a value is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.curvature_relations import two_parameter_principal_curvatures
    >>> k_s, k_q, sigma = two_parameter_principal_curvatures(0.0772, 0.0099, 0.0217, 0.0002, 0.0)  # 1/mm
    >>> np.round([k_s, k_q, sigma], 6).tolist()  # 1/mm, 1/mm, rad
    [0.079107, 0.019993, 0.170772]
    """
    b11, b12, b22, k_f, k_h = np.broadcast_arrays(*(np.asarray(x, float) for x in (b11, b12, b22, k_f, k_h)))
    if not all(np.all(np.isfinite(x)) for x in (b11, b12, b22, k_f, k_h)):
        raise ValueError("b11, b12, b22, k_f and k_h must be finite")
    D = b11 - b22 + k_f - k_h
    with np.errstate(divide="ignore", invalid="ignore"):
        sigma = np.where(D == 0, np.sign(b12) * np.pi / 4, 0.5 * np.arctan(2 * b12 / np.where(D == 0, 1.0, D)))
    diff = np.where(D >= 0, 1.0, -1.0) * np.hypot(2 * b12, D)
    tr = b11 + b22 + k_f + k_h
    return 0.5 * (tr + diff), 0.5 * (tr - diff), sigma
