"""Finite-difference derivatives of gearrep.surface against a sphere's closed forms."""

import numpy as np
import pytest

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


@pytest.mark.parametrize("shape", [(), (7,), (3, 4)])
def test_fd_derivatives_in_one_call_equal_the_calls_per_offset(shape):
    """``one_call`` evaluates every stencil point in one call of a pointwise position: the same
    values bit for bit (scalar, 1-D and 2-D parameters), with one call instead of 33."""
    rng = np.random.default_rng(3)
    u, v = rng.uniform(-1.0, 1.0, shape), rng.uniform(0.0, 5.0, shape)
    calls = []

    def counted(a, b):
        calls.append(np.shape(a))
        return sphere(a, b)

    p = fd_derivatives(counted, u, v, 1e-3, 2e-3)
    n_each = len(calls)
    q = fd_derivatives(counted, u, v, 1e-3, 2e-3, one_call=True)
    assert n_each == 33 and len(calls) == 34
    for f in ("r", "r_u", "r_v", "r_uu", "r_uv", "r_vv"):
        np.testing.assert_array_equal(getattr(q, f), getattr(p, f), err_msg=f)
        assert getattr(q, f).shape == (*shape, 3)


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


def test_rotated_surface_moves_points_keeps_curvatures_and_passes_attributes():
    from gearrep.curvature import principal_curvatures
    from gearrep.frames import rot_x, rot_z
    from gearrep.surface import RotatedSurface
    from gearrep.surfaces.analytic import Torus

    base = Torus(3.0, 1.0)
    base.lower, base.upper, base.outward_sign = np.array([0.0, 0.0]), np.array([1.0, 2.0]), -1
    Q, t = rot_z(0.4) @ rot_x(-1.1), np.array([1.0, -2.0, 0.5])
    s = RotatedSurface(base, Q, t)
    u, v = np.array([0.2, 1.4]), np.array([0.3, -2.0])
    p, q = base.evaluate(u, v), s.evaluate(u, v)
    np.testing.assert_allclose(q.r, p.r @ Q.T + t, atol=1e-14)
    np.testing.assert_allclose(s.position(u, v), q.r, atol=0)
    for f in ("r_u", "r_v", "r_uu", "r_uv", "r_vv"):
        np.testing.assert_allclose(getattr(q, f), getattr(p, f) @ Q.T, atol=1e-14)
    pb, pq = principal_curvatures(p), principal_curvatures(q)
    np.testing.assert_allclose(pq.k1, pb.k1, rtol=1e-13)
    np.testing.assert_allclose(pq.k2, pb.k2, rtol=1e-13)
    np.testing.assert_allclose(pq.normal, pb.normal @ Q.T, atol=1e-14)
    assert s.outward_sign == -1 and s.upper[1] == 2.0 and not hasattr(s, "side")
    with pytest.raises(ValueError, match="proper rotation"):
        RotatedSurface(base, np.diag([1.0, 1.0, -1.0]))


def test_evaluate_components_equal_evaluate():
    """Structure-of-arrays evaluation: the default (from evaluate), the involute flank's
    own (arrays and one point on floats) and a rotated surface give evaluate's numbers."""
    from gearrep.frames import rot_x
    from gearrep.surface import RotatedSurface, SurfacePoint, cross3, dot3
    from gearrep.surfaces.analytic import Sphere
    from gearrep.surfaces.involute import InvoluteFlank, InvoluteGearData, ParabolicCrowning, TipRelief

    g = InvoluteGearData(31, 2.0, np.radians(20), 20.0, helix_angle=np.radians(12))
    flanks = [
        Sphere(5.0),
        InvoluteFlank(g, 1, 1, crowning=ParabolicCrowning(0.002)),
        InvoluteFlank(g, -1, -1, relief=(TipRelief(0.01, g.r_a - 0.8, g.r_a),)),
    ]
    flanks.append(RotatedSurface(flanks[1], rot_x(0.3), (1.0, 2.0, 3.0)))
    rng = np.random.default_rng(2)
    for f in flanks:
        lo, hi = (np.array([0.3, 0.2]), np.array([1.2, 2.0])) if isinstance(f, Sphere) else (f.lower, f.upper)
        u, v = rng.uniform(lo[0] + 0.01, hi[0], 20), rng.uniform(lo[1], hi[1], 20)
        P = f.evaluate(u, v)
        C = f.evaluate_components(u, v)
        for vec, comps in zip((P.r, P.r_u, P.r_v, P.r_uu, P.r_uv, P.r_vv), C):
            got = np.column_stack(np.broadcast_arrays(*comps))
            np.testing.assert_allclose(got, vec, rtol=0, atol=1e-12 * (1 + np.abs(vec).max()))
        one = f.evaluate_components(float(u[0]), float(v[0]))
        for vec, comps in zip((P.r, P.r_u, P.r_v, P.r_uu, P.r_uv, P.r_vv), one):
            np.testing.assert_allclose(
                np.array(comps, float).reshape(3), vec[0], rtol=0, atol=1e-12 * (1 + np.abs(vec).max())
            )
    # SurfacePoint.from_components is the inverse of components, floats broadcast
    P = flanks[1].evaluate(u, v)
    np.testing.assert_array_equal(SurfacePoint.from_components(P.components()).r_vv, P.r_vv)
    Q = SurfacePoint.from_components(flanks[1].evaluate_components(u, v))
    assert Q.r_u.shape == (20, 3) and np.all(Q.r_u[:, 2] == 0.0) and np.all(Q.r_v[:, 2] == 1.0)
    with pytest.raises(ValueError, match="six vectors"):
        SurfacePoint.from_components(P.components()[:5])
    with pytest.raises(ValueError, match="do not broadcast"):
        SurfacePoint.from_components(((u, v[:3], 0.0),) + P.components()[1:])
    a, b = (1.0, 2.0, 3.0), (-1.0, 0.5, 4.0)
    np.testing.assert_array_equal(cross3(a, b), np.cross(a, b))
    assert dot3(a, b) == 12.0
    with pytest.raises(ValueError):  # one point inside the base circle: floats raise (arrays give NaN)
        flanks[1].evaluate_components(float(0.5 * g.r_b), 0.0)
