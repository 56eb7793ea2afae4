"""gearrep.ellipse: elastic-approach contact ellipse (seed 002 eq 2.6.1-2.6.6) and Hertz."""

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from gearrep import curvature as cv
from gearrep import ellipse as el
from gearrep.solve import Status
from gearrep.surfaces.analytic import Sphere

# ----------------------------------------------------------------- Litvin's formulas


def test_litvin_coefficients_equal_printed_formulas():
    rng = np.random.default_rng(11)
    kI1, kII1, kI2, kII2 = rng.normal(size=(4, 300))
    sigma = rng.uniform(-np.pi, np.pi, 300)
    A, B, alpha = el.litvin_coefficients(kI1, kII1, kI2, kII2, sigma)
    kS1, kS2, g1, g2 = kI1 + kII1, kI2 + kII2, kI1 - kII1, kI2 - kII2
    R = np.sqrt(g1**2 - 2 * g1 * g2 * np.cos(2 * sigma) + g2**2)
    np.testing.assert_allclose(A, 0.25 * (kS1 - kS2 - R), atol=1e-13)  # eq 2.6.4
    np.testing.assert_allclose(B, 0.25 * (kS1 - kS2 + R), atol=1e-13)  # eq 2.6.5
    np.testing.assert_allclose(np.cos(2 * alpha), (g1 - g2 * np.cos(2 * sigma)) / R, atol=1e-11)  # 2.6.1
    # eq 2.6.2 printed with +g2 sin 2sigma measures alpha the other way round
    np.testing.assert_allclose(np.sin(2 * alpha), -g2 * np.sin(2 * sigma) / R, atol=1e-11)
    d = 0.00632
    e = el.elastic_ellipse(kI1, kII1, kI2, kII2, sigma, d)
    ok = e.elliptic
    litvin_a, litvin_b = np.sqrt(np.abs(d / A)), np.sqrt(np.abs(d / B))  # eq 2.6.3
    np.testing.assert_allclose(e.a, np.maximum(litvin_a, litvin_b), rtol=1e-12)
    np.testing.assert_allclose(e.b, np.minimum(litvin_a, litvin_b), rtol=1e-12)
    np.testing.assert_allclose(e.area, np.pi * e.a * e.b, rtol=1e-15)
    assert np.all(e.ratio >= 1.0)
    np.testing.assert_array_equal(ok, A * B > 0)
    # positive relative curvature (Litvin's orientation): a from A, b from B, alpha -> b axis
    pos = (A > 0) & (B > 0)
    np.testing.assert_allclose(e.a[pos], litvin_a[pos], rtol=1e-12)
    np.testing.assert_allclose(np.cos(2 * e.alpha[pos]), np.cos(2 * alpha[pos]), atol=1e-12)


def test_unsigned_sigma_gives_same_axes():
    # seed 000 eq 5.15 takes sigma = arccos(e_I1 . e_I2) in [0, pi]: only cos 2 sigma matters
    args = (0.02, 1.4, -0.01, 0.6)
    e1 = el.elastic_ellipse(*args, -0.4, 0.00025)
    e2 = el.elastic_ellipse(*args, 0.4, 0.00025)
    np.testing.assert_allclose([e1.a, e1.b], [e2.a, e2.b], rtol=1e-14)
    np.testing.assert_allclose(e1.alpha, -e2.alpha, atol=1e-15)


@pytest.mark.parametrize("bad", [0.0, -1e-3, np.nan, np.inf])
def test_delta_validation(bad):
    with pytest.raises(ValueError, match="delta.*> 0"):
        el.elastic_ellipse(1.0, 0.5, 0.0, 0.0, 0.0, bad)
    with pytest.raises(ValueError, match="delta"):
        el.elastic_ellipse_from_relative(1.0, 0.5, np.array([1e-3, bad]))


# ---------------------------------------------------------------- closed forms


def test_sphere_on_plane_and_two_spheres():
    R, d = 25.0, 0.002
    # sphere on a plane: relative curvature 1/R in every direction -> circle sqrt(2 R delta)
    e = el.elastic_ellipse(1 / R, 1 / R, 0.0, 0.0, 0.3, d)
    assert e.a == pytest.approx(np.sqrt(2 * R * d), rel=1e-14)
    assert e.b == pytest.approx(np.sqrt(2 * R * d), rel=1e-14)
    assert e.elliptic
    # two convex spheres, external contact: kappa1 = 1/R1, kappa2 = -1/R2 (common normal)
    R1, R2 = 10.0, 4.0
    e = el.elastic_ellipse(1 / R1, 1 / R1, -1 / R2, -1 / R2, 1.0, d)
    Re = 1 / (1 / R1 + 1 / R2)
    assert e.a == pytest.approx(np.sqrt(2 * Re * d), rel=1e-14)
    # concave-convex (ball in a socket R2 > R1): kappa2 = +1/R2
    e = el.elastic_ellipse(1 / R1, 1 / R1, 1 / 40.0, 1 / 40.0, 0.0, d)
    assert e.a == pytest.approx(np.sqrt(2 * d / (1 / R1 - 1 / 40.0)), rel=1e-14)


def test_two_sphere_surfaces_via_principal_curvatures_and_normal_flip():
    R1, R2, d = 3.0, 1.0, 1e-4
    p1 = Sphere(R1).evaluate(0.4, 0.3)
    p2 = Sphere(R2).evaluate(0.4 + np.pi, -0.3)  # outward normal = -p1.normal
    c1 = cv.principal_curvatures(p1)
    c2 = cv.with_opposite_normal(cv.principal_curvatures(p2))
    e = el.elastic_ellipse_at(c1, c2, d)
    assert e.a == pytest.approx(np.sqrt(2 * d / (1 / R1 + 1 / R2)), rel=1e-13)
    # the same contact described with the other common normal gives the same ellipse
    f = el.elastic_ellipse_at(cv.with_opposite_normal(c1), cv.with_opposite_normal(c2), d)
    np.testing.assert_allclose([f.a, f.b], [e.a, e.b], rtol=1e-14)


@pytest.mark.parametrize("R1,R2", [(20.0, 5.0), (5.0, 20.0), (8.0, 8.0)])
def test_crossed_cylinders_90deg(R1, R2):
    # cylinder 1 axis along x (curvature 1/R1 across, in y), cylinder 2 axis along y
    # (curvature 1/R2 in x), external contact; common normal with positive relative curvature
    d = 0.003
    e = el.elastic_ellipse(1 / R2, 1 / R1, 0.0, 0.0, 0.0, d)  # pinion-like: e_I = x, e_II = y
    assert e.a == pytest.approx(np.sqrt(2 * d * max(R1, R2)), rel=1e-14)
    assert e.b == pytest.approx(np.sqrt(2 * d * min(R1, R2)), rel=1e-14)
    if R1 != R2:
        # major axis along the direction of the smaller relative curvature (the larger radius)
        minor_dir = 0.0 if R2 < R1 else np.pi / 2  # angle from x of the minor axis
        assert np.cos(2 * (e.alpha - minor_dir)) == pytest.approx(1.0, abs=1e-14)
    # the same pair as two curved surfaces w.r.t. the normal out of body 1: surface 1
    # e_I = x (axis, 0), e_II = y (-1/R1); surface 2 e_I = y (axis, 0), e_II = -x (+1/R2);
    # sigma = +90 deg from e_I(1) to e_I(2)
    f = el.elastic_ellipse(0.0, -1 / R1, 0.0, 1 / R2, np.pi / 2, d)
    np.testing.assert_allclose([f.a, f.b], [e.a, e.b], rtol=1e-13)


def _exact_gap_boundary(R1, R2, gamma, delta, theta):
    """Distance from the contact point, in direction theta (from x), to where the exact normal
    gap of two crossed cylinders reaches delta: lower body cylinder axis x at z = -R1, upper
    body cylinder axis at angle gamma at z = +R2."""

    def gap(rho):
        x, y = rho * np.cos(theta), rho * np.sin(theta)
        w2 = -np.sin(gamma) * x + np.cos(gamma) * y
        z1 = -R1 + np.sqrt(R1**2 - y**2)
        z2 = R2 - np.sqrt(R2**2 - w2**2)
        return z2 - z1 - delta

    hi = 1e-6
    while gap(hi) < 0:
        hi *= 2
    return brentq(gap, 0.0, hi, xtol=1e-16, rtol=1e-15)


@pytest.mark.parametrize("gamma", [0.35, np.pi / 4, 1.2, np.pi / 2, 2.5])
def test_crossed_cylinders_at_angle_against_exact_separation(gamma):
    R1, R2 = 30.0, 12.0
    delta = 1e-7 * R2
    # curvatures w.r.t. the common normal +z (out of the lower body, into the upper body):
    # surface 1 bends away from +z across its axis; surface 2 bends toward +z across its axis
    kI1, kII1 = 0.0, -1 / R1  # e_I(1) = x (axis), e_II(1) = y
    kI2, kII2 = 1 / R2, 0.0  # e_I(2) = across axis 2 = angle gamma + 90 deg from x
    sigma = gamma + np.pi / 2  # signed, counter-clockwise about +z
    e = el.elastic_ellipse(kI1, kII1, kI2, kII2, sigma, delta)
    assert e.elliptic and e.A < 0 and e.B < 0  # this normal gives negative relative curvature
    major_dir = e.alpha + np.pi / 2
    for theta in np.linspace(0, np.pi, 7, endpoint=False):
        rho = _exact_gap_boundary(R1, R2, gamma, delta, theta)
        q = theta - major_dir
        r_ell = 1 / np.sqrt(np.cos(q) ** 2 / e.a**2 + np.sin(q) ** 2 / e.b**2)
        assert rho == pytest.approx(r_ell, rel=1e-5)


def test_elastic_ellipse_at_vectors_crossed_cylinders():
    from gearrep.surface import SurfacePoint
    from gearrep.surfaces.analytic import Cylinder

    R1, R2, gamma, d = 30.0, 12.0, 0.7, 1e-6
    p1 = Cylinder(R1).evaluate(0.0, 0.0)  # (R1, 0, 0), outward normal +x, axis z
    c, s = np.cos(gamma), np.sin(gamma)
    Rx = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    q = Cylinder(R2).evaluate(np.pi, 0.0)  # (-R2, 0, 0), outward normal -x
    t = np.array([R1 + R2, 0.0, 0.0])
    rot = lambda x: x @ Rx.T  # noqa: E731
    p2 = SurfacePoint(rot(q.r) + t, rot(q.r_u), rot(q.r_v), rot(q.r_uu), rot(q.r_uv), rot(q.r_vv))
    c1 = cv.principal_curvatures(p1)
    c2 = cv.with_opposite_normal(cv.principal_curvatures(p2))
    e = el.elastic_ellipse_at(c1, c2, d)
    # independent: exact gap boundary in the tangent plane (y, z) of the contact point
    for th in np.linspace(0, np.pi, 5, endpoint=False):
        u = np.array([0.0, np.cos(th), np.sin(th)])

        def gap(rho):
            y, z = rho * u[1], rho * u[2]
            x1 = np.sqrt(R1**2 - y**2)  # surface 1 x at (y, z)
            w = c * y + s * z  # across cylinder 2 (its axis is Rx(gamma) z = (0, -s, c))
            x2 = R1 + R2 - np.sqrt(R2**2 - w**2)
            return (x2 - x1) - d

        rho = brentq(gap, 0.0, 1.0, xtol=1e-16, rtol=1e-15)
        r_ell = 1 / np.sqrt(np.dot(u, e.major_axis) ** 2 / e.a**2 + np.dot(u, e.minor_axis) ** 2 / e.b**2)
        assert rho == pytest.approx(r_ell, rel=1e-5)
    np.testing.assert_allclose(np.dot(e.major_axis, e.minor_axis), 0.0, atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(e.major_axis), 1.0, rtol=1e-15)


def test_from_relative_order_and_non_elliptic_flag():
    d = 1e-3
    e1 = el.elastic_ellipse_from_relative(2.0, 0.5, d)
    e2 = el.elastic_ellipse_from_relative(0.5, 2.0, d)
    np.testing.assert_allclose([e1.a, e1.b], [np.sqrt(2 * d / 0.5), np.sqrt(2 * d / 2.0)])
    np.testing.assert_allclose([e2.a, e2.b], [e1.a, e1.b])
    assert np.cos(2 * e1.alpha) == pytest.approx(1.0) and np.cos(2 * e2.alpha) == pytest.approx(-1.0)
    h = el.elastic_ellipse_from_relative(np.array([1.0, 1.0, -1.0]), np.array([-0.5, 0.0, -0.2]), d)
    np.testing.assert_array_equal(h.elliptic, [False, False, True])
    assert np.isinf(h.a[1])


# --------------------------------------------------------------------------- Hertz


def test_hertz_ratio_against_scipy_legendre_integrals():
    k = np.array([0.999, 0.7, 0.3, 0.05, 0.01])  # b/a
    m = 1 - k**2  # scipy's parameter m = e^2
    K, E = ellipk(m), ellipe(m)
    legendre = ((1 / k**2) * E - K) / (K - E)  # Johnson eq 4.33 form
    np.testing.assert_allclose(el.hertz_ratio(k), legendre, rtol=1e-9)
    assert el.hertz_ratio(1.0) == 1.0


def test_hertz_sphere_sphere_closed_form():
    R1, R2, P = 12.0, 30.0, 250.0
    E1, nu1, E2, nu2 = 206e3, 0.3, 115e3, 0.33
    h = el.hertz_contact(1 / R1 + 1 / R2, 1 / R1 + 1 / R2, P, E1, nu1, E2, nu2)
    Es = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    R = 1 / (1 / R1 + 1 / R2)
    a = (3 * P * R / (4 * Es)) ** (1 / 3)
    assert h.status == Status.CONVERGED
    assert h.a == pytest.approx(a, rel=1e-13) and h.b == pytest.approx(a, rel=1e-13)
    assert h.p0 == pytest.approx(3 * P / (2 * np.pi * a**2), rel=1e-13)
    assert h.p0 == pytest.approx((6 * P * Es**2 / (np.pi**3 * R**2)) ** (1 / 3), rel=1e-13)
    assert h.approach == pytest.approx(a**2 / R, rel=1e-13)
    assert h.e == 0.0
    assert h.Estar == pytest.approx(Es, rel=1e-15)


def test_hertz_crossed_equal_cylinders_is_sphere_on_plane():
    R, P, E, nu = 15.0, 80.0, 210e3, 0.3
    h = el.hertz_contact(1 / R, 1 / R, P, E, nu)
    Es = E / (2 * (1 - nu**2))
    assert h.a == pytest.approx((3 * P * R / (4 * Es)) ** (1 / 3), rel=1e-13)
    # the sign of the common normal does not matter
    g = el.hertz_contact(-1 / R, -1 / R, P, E, nu)
    assert g.a == pytest.approx(h.a, rel=1e-15)


def _displacement(a, b, p0, Es, x0, y0):
    """Normal displacement (1/(pi E*)) int int p / r dA of the Hertz pressure
    p0 sqrt(1 - x^2/a^2 - y^2/b^2) at (x0, y0): polar integration about the point, radial
    integral in closed form (independent of the elliptic-integral formulas)."""
    from scipy.integrate import quad

    def radial(th):
        c, s = np.cos(th), np.sin(th)
        al = (c / a) ** 2 + (s / b) ** 2
        be = 2 * (x0 * c / a**2 + y0 * s / b**2)
        ga = (x0 / a) ** 2 + (y0 / b) ** 2 - 1
        disc = np.sqrt(be * be - 4 * al * ga)
        rmax, rmin = (-be + disc) / (2 * al), (-be - disc) / (2 * al)
        w, cc = 0.5 * (rmax - rmin), 0.5 * (rmax + rmin)
        # int_0^rmax sqrt(al (rmax - r)(r - rmin)) dr
        val = np.pi * w**2 / 4 + 0.5 * cc * np.sqrt(max(w * w - cc * cc, 0.0)) + 0.5 * w**2 * np.arcsin(cc / w)
        return np.sqrt(al) * val

    tot = quad(radial, 0, 2 * np.pi, epsabs=0, epsrel=1e-12, limit=400, points=[np.pi / 2, np.pi, 1.5 * np.pi])[0]
    return p0 * tot / (np.pi * Es)


@pytest.mark.parametrize("ratio", [1.0, 7.0, 100.0, 1600.0])
def test_hertz_elliptic_against_direct_displacement_integral(ratio):
    # in the contact the surfaces' displacements must close the gap: u = approach - A x^2 - B y^2
    P, E, nu = 100.0, 210e3, 0.3
    h = el.hertz_contact(0.1, 0.1 * ratio, P, E, nu)
    assert h.status == Status.CONVERGED and h.residual < 1e-12
    a, b, p0, Es = float(h.a), float(h.b), float(h.p0), float(h.Estar)
    assert a >= b
    for fx, fy in [(0.0, 0.0), (0.5, 0.0), (0.0, 0.5), (0.3, 0.6)]:
        x0, y0 = fx * a, fy * b
        u = _displacement(a, b, p0, Es, x0, y0)
        assert u == pytest.approx(float(h.approach) - float(h.A) * x0**2 - float(h.B) * y0**2, rel=1e-9)
    assert h.p0 == pytest.approx(3 * P / (2 * np.pi * a * b), rel=1e-14)


def test_hertz_batch_status_and_validation():
    h = el.hertz_contact(np.array([[1.0, 1.0], [1.0, 2.0]]), np.array([[1.0, -1.0], [0.0, 30.0]]), 10.0, 200e3, 0.3)
    assert h.a.shape == (2, 2)
    np.testing.assert_array_equal(h.status, [[Status.CONVERGED, Status.SINGULAR], [Status.SINGULAR, Status.CONVERGED]])
    assert np.isnan(h.a[0, 1]) and np.isnan(h.p0[1, 0])
    with pytest.raises(ValueError, match="load"):
        el.hertz_contact(1.0, 1.0, 0.0, 200e3, 0.3)
    with pytest.raises(ValueError, match="E1"):
        el.hertz_contact(1.0, 1.0, 1.0, -200e3, 0.3)
    with pytest.raises(ValueError, match="nu2"):
        el.hertz_contact(1.0, 1.0, 1.0, 200e3, 0.3, 200e3, 0.7)
    with pytest.raises(ValueError, match="nu1"):
        el.effective_modulus(1.0, -1.0)


# ------------------------------------------------- Hertz route: surfaces -> ellipse -> p_max


def test_hertz_contact_at_two_spheres_closed_form_max_pressure():
    """Sphere R1 on sphere R2 (external contact) through the surface route: p_max from the
    curvatures and the load equals Johnson's closed form (6 P E*^2 / (pi^3 R^2))^(1/3)."""
    R1, R2, P, E, nu = 3.0, 1.0, 200.0, 206e3, 0.3
    p1 = Sphere(R1).evaluate(0.4, 0.3)
    p2 = Sphere(R2).evaluate(0.4 + np.pi, -0.3)
    c1 = cv.principal_curvatures(p1)
    c2 = cv.with_opposite_normal(cv.principal_curvatures(p2))
    h = el.hertz_contact_at(c1, c2, P, E, nu)
    Es = E / (2 * (1 - nu**2))
    R = 1 / (1 / R1 + 1 / R2)
    assert h.status == Status.CONVERGED
    assert h.p0 == pytest.approx((6 * P * Es**2 / (np.pi**3 * R**2)) ** (1 / 3), rel=1e-12)
    assert el.hertz_max_pressure_MPa(P, h.a, h.b) == pytest.approx(h.p0, rel=1e-14)
    # the other common normal gives the same contact
    g = el.hertz_contact_at(cv.with_opposite_normal(c1), cv.with_opposite_normal(c2), P, E, nu)
    assert g.p0 == pytest.approx(h.p0, rel=1e-13)


@pytest.mark.parametrize("a_mm,b_mm", [(1.0, 1.0), (2.5, 0.4), (7.0, 0.05)])
def test_hertz_max_pressure_carries_the_load(a_mm, b_mm):
    """The ellipsoidal pressure p_max sqrt(1 - x^2/a^2 - y^2/b^2) integrates to the load (polar
    coordinates x = a r cos t, y = b r sin t: int = 2 pi a b p_max / 3)."""
    from scipy.integrate import quad

    P = 137.0
    p = el.hertz_max_pressure_MPa(P, a_mm, b_mm)
    radial = quad(lambda r: np.sqrt(1 - r * r) * r, 0, 1)[0]
    assert 2 * np.pi * a_mm * b_mm * p * radial == pytest.approx(P, rel=1e-12)
    np.testing.assert_allclose(el.hertz_max_pressure_MPa([P, 2 * P], a_mm, b_mm), [p, 2 * p], rtol=1e-15)


def test_line_contact_pressure_closed_form_and_slender_ellipse_limit():
    """Cylinders (Johnson eq 4.45): p_max = sqrt(P' E* / (pi R)), half-width b = sqrt(4 P' R / (pi E*)),
    P' = pi b p_max / 2. A very slender Hertz ellipse (B/A = 1e6) approaches plane strain at its
    centre: with P' = pi b p0 / 2 the line formula gives back p0 to within the 3-D correction
    (about (b/a)^2 ln(a/b), here < 1e-3)."""
    P_line, R, E, nu = 12.0, 3.5, 206e3, 0.3
    Es = float(el.effective_modulus(E, nu))
    p = el.hertz_line_max_pressure_MPa(P_line, 1 / R, Es)
    half = np.sqrt(4 * P_line * R / (np.pi * Es))
    assert p == pytest.approx(np.sqrt(P_line * Es / (np.pi * R)), rel=1e-15)
    assert np.pi * half * p / 2 == pytest.approx(P_line, rel=1e-14)
    assert el.hertz_line_max_pressure_MPa(P_line, -1 / R, Es) == p  # sign of the normal
    h = el.hertz_contact(1 / R, 1e-6 / R, 200.0, E, nu)
    assert h.a / h.b > 1e3
    p_line = el.hertz_line_max_pressure_MPa(np.pi * h.b * h.p0 / 2, 1 / R, Es)
    assert p_line == pytest.approx(h.p0, rel=1e-3)


def test_hertz_pressure_functions_name_bad_arguments():
    with pytest.raises(ValueError, match="load_N"):
        el.hertz_max_pressure_MPa(0.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="b_mm"):
        el.hertz_max_pressure_MPa(1.0, 1.0, np.nan)
    with pytest.raises(ValueError, match="k_rel_per_mm"):
        el.hertz_line_max_pressure_MPa(1.0, 0.0, 1e5)
    with pytest.raises(ValueError, match="Estar_MPa"):
        el.hertz_line_max_pressure_MPa(1.0, 0.1, -1.0)


def test_hertz_line_contact_from_rounding_is_flagged_not_a_tiny_pressure():
    # conjugate flanks: one relative curvature is zero up to rounding -> no ellipse, status SINGULAR
    h = el.hertz_contact([0.29, 0.29, 0.29], [3e-13, 2.9e-3, -1e-3], 200.0, 206e3, 0.3)
    np.testing.assert_array_equal(h.status, [Status.SINGULAR, Status.CONVERGED, Status.SINGULAR])
    assert np.isnan(h.p0[0]) and np.isfinite(h.p0[1]) and np.isnan(h.p0[2])
