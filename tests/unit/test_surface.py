"""Finite-difference derivatives of gearrep.surface against a sphere's closed forms."""

import numpy as np

from gearrep.surface import Surface, fd_derivatives, unit

R = 7.0


def sphere(u, v):
    return np.stack([R * np.cos(u) * np.cos(v), R * np.cos(u) * np.sin(v), R * np.sin(u)], axis=-1)


def test_fd_derivatives_sphere():
    u = np.linspace(-1.0, 1.0, 7)
    v = np.linspace(0.0, 5.0, 7)
    p = fd_derivatives(sphere, u, v)
    cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
    r_u = R * np.stack([-su * cv, -su * sv, cu], -1)
    r_v = R * np.stack([-cu * sv, cu * cv, 0 * u], -1)
    r_uv = R * np.stack([su * sv, -su * cv, 0 * u], -1)
    r_vv = R * np.stack([-cu * cv, -cu * sv, 0 * u], -1)
    np.testing.assert_allclose(p.r_u, r_u, atol=1e-11 * R)
    np.testing.assert_allclose(p.r_v, r_v, atol=1e-11 * R)
    np.testing.assert_allclose(p.r_uu, -p.r, atol=1e-9 * R)
    np.testing.assert_allclose(p.r_uv, r_uv, atol=1e-9 * R)
    np.testing.assert_allclose(p.r_vv, r_vv, atol=1e-9 * R)


def test_normal_orientation_and_flip():
    class S(Surface):
        def position(self, u, v):
            return sphere(u, v)

    p = S().evaluate(np.array(0.2), np.array(0.4))
    # r_u x r_v points inward on this parameterisation
    assert np.dot(p.normal, p.r) < 0
    np.testing.assert_allclose(p.flipped().normal, -p.normal)
    np.testing.assert_allclose(np.linalg.norm(unit(p.r)), 1.0)


def test_cross_matches_numpy_with_broadcasting():
    from gearrep.surface import cross

    rng = np.random.default_rng(0)
    a, b = rng.normal(size=(4, 1, 3)), rng.normal(size=(5, 3))
    np.testing.assert_array_equal(cross(a, b), np.cross(a, b))
    np.testing.assert_array_equal(cross([1.0, 0, 0], [0, 1.0, 0]), [0, 0, 1.0])
