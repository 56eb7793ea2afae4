"""gearrep.frames: rotations, homogeneous transforms (Litvin M_ij notation), misalignment."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from gearrep import frames as fr

ang = st.floats(-7.0, 7.0, allow_nan=False)


def test_active_rotation_closed_forms():
    a = 0.3
    c, s = np.cos(a), np.sin(a)
    np.testing.assert_allclose(fr.rot_z(a) @ [1, 0, 0], [c, s, 0], atol=1e-16)
    np.testing.assert_allclose(fr.rot_z(a) @ [0, 1, 0], [-s, c, 0], atol=1e-16)
    np.testing.assert_allclose(fr.rot_x(a) @ [0, 1, 0], [0, c, s], atol=1e-16)
    np.testing.assert_allclose(fr.rot_y(a) @ [0, 0, 1], [s, 0, c], atol=1e-16)
    # quarter turns: right-handed cyclic x -> y -> z -> x
    np.testing.assert_allclose(fr.rot_z(np.pi / 2) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(fr.rot_x(np.pi / 2) @ [0, 1, 0], [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(fr.rot_y(np.pi / 2) @ [0, 0, 1], [1, 0, 0], atol=1e-15)


def test_vectorised_shapes_and_rotation_selector():
    a = np.linspace(0, 1, 6).reshape(2, 3)
    for f in (fr.rot_x, fr.rot_y, fr.rot_z):
        R = f(a)
        assert R.shape == (2, 3, 3, 3)
        np.testing.assert_allclose(R[1, 2], f(a[1, 2]))
    np.testing.assert_array_equal(fr.rotation("y", a), fr.rot_y(a))
    with pytest.raises(ValueError, match="axis"):
        fr.rotation("w", 0.1)


@settings(max_examples=50, deadline=None)
@given(ang, ang)
def test_rotation_group_properties(a, b):
    for f, axis in ((fr.rot_x, [1, 0, 0]), (fr.rot_y, [0, 1, 0]), (fr.rot_z, [0, 0, 1])):
        R = f(a)
        np.testing.assert_allclose(R.T @ R, np.eye(3), atol=1e-14)
        assert np.linalg.det(R) == pytest.approx(1.0, abs=1e-14)
        np.testing.assert_allclose(f(a) @ f(b), f(a + b), atol=1e-13)
        np.testing.assert_allclose(fr.rotation_about_axis(axis, a), R, atol=1e-14)


def test_rotation_about_axis_rodrigues():
    k = np.array([1.0, 2.0, -0.5])
    a = 0.7
    R = fr.rotation_about_axis(k, a)
    np.testing.assert_allclose(R @ k, k, atol=1e-14)  # axis fixed
    x = np.array([0.3, -1.0, 2.0])
    ku = k / np.linalg.norm(k)
    rod = x * np.cos(a) + np.cross(ku, x) * np.sin(a) + ku * np.dot(ku, x) * (1 - np.cos(a))
    np.testing.assert_allclose(R @ x, rod, atol=1e-14)
    with pytest.raises(ValueError):
        fr.rotation_about_axis([0, 0, 0], 0.1)


def test_litvin_rotating_gear_convention():
    # S_1 turned by phi about z_f: M_f1 = rot_z(phi); a point fixed on the gear at x_1 = 1
    # appears at angle phi in S_f; M_1f = rot_z(-phi) has +sin(phi) in row 1, column 2
    phi = 0.4
    M_f1 = fr.homogeneous(fr.rot_z(phi))
    M_1f = fr.homogeneous(fr.rot_z(-phi))
    np.testing.assert_allclose(fr.transform_points(M_f1, [1, 0, 0]), [np.cos(phi), np.sin(phi), 0])
    assert M_1f[0, 1] == pytest.approx(np.sin(phi))
    np.testing.assert_allclose(fr.compose(M_f1, M_1f), np.eye(4), atol=1e-15)
    np.testing.assert_allclose(fr.inverse(M_f1), M_1f, atol=1e-16)


def test_homogeneous_compose_inverse_and_transforms():
    rng = np.random.default_rng(3)
    a = rng.uniform(-3, 3, (5, 3))
    t = rng.normal(size=(5, 3))
    R = fr.rot_z(a[:, 0]) @ fr.rot_x(a[:, 1]) @ fr.rot_y(a[:, 2])
    M = fr.homogeneous(R, t)
    assert M.shape == (5, 4, 4)
    assert np.all(fr.is_rigid(M))
    p = rng.normal(size=(5, 3))
    np.testing.assert_allclose(fr.transform_points(M, p), np.einsum("nij,nj->ni", R, p) + t)
    np.testing.assert_allclose(fr.transform_vectors(M, p), np.einsum("nij,nj->ni", R, p))
    Mi = fr.inverse(M)
    np.testing.assert_allclose(Mi, np.linalg.inv(M), atol=1e-13)
    np.testing.assert_allclose(fr.transform_points(Mi, fr.transform_points(M, p)), p, atol=1e-13)
    np.testing.assert_allclose(fr.inverse(R), np.swapaxes(R, -1, -2))
    # chain rule M_ik = M_ij M_jk
    M2 = fr.homogeneous(fr.rot_y(0.2), [1.0, 2.0, 3.0])
    np.testing.assert_allclose(
        fr.transform_points(fr.compose(M, M2), p), fr.transform_points(M, fr.transform_points(M2, p)), atol=1e-13
    )
    np.testing.assert_allclose(fr.compose(M), M)
    # points broadcast against a single matrix
    q = rng.normal(size=(4, 7, 3))
    assert fr.transform_points(M2, q).shape == (4, 7, 3)
    np.testing.assert_array_equal(fr.translation([1, 2, 3])[:3, 3], [1, 2, 3])


def test_input_validation():
    with pytest.raises(ValueError, match="rigid"):
        fr.inverse(np.diag([2.0, 1.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="R must"):
        fr.homogeneous(np.eye(2))
    with pytest.raises(ValueError, match="t must"):
        fr.homogeneous(None, [1, 2])
    with pytest.raises(ValueError):
        fr.compose()
    with pytest.raises(ValueError, match="axes"):
        fr.misalignment_rotation(0.1, 0.1, axes="xx")
    with pytest.raises(ValueError, match="center_axis"):
        fr.gear_mounting(10.0, center_axis="z")


def test_rotation_about_line():
    P = np.array([1.0, 2.0, 0.0])
    M = fr.rotation_about_line(P, [0, 0, 1], np.pi / 2)
    np.testing.assert_allclose(fr.transform_points(M, P), P, atol=1e-15)
    np.testing.assert_allclose(fr.transform_points(M, P + [1, 0, 5]), P + [0, 1, 5], atol=1e-15)


def test_misalignment_rotation_seed000_chain():
    gh, gv = 3 / 60 * np.pi / 180, 2 / 60 * np.pi / 180
    L = fr.misalignment_rotation(gh, gv)
    np.testing.assert_allclose(L, fr.rot_x(gh) @ fr.rot_y(gv), atol=0)
    # z axis of S_v in S_f: to first order (sin gv, -sin gh, 1)
    z = L @ [0, 0, 1]
    np.testing.assert_allclose(z, [np.sin(gv), -np.sin(gh) * np.cos(gv), np.cos(gh) * np.cos(gv)], atol=1e-16)
    np.testing.assert_allclose(fr.misalignment_rotation(gh, gv, axes="yx"), fr.rot_y(gh) @ fr.rot_x(gv))


def _axes_distance_and_angle(M):
    """Shortest distance and angle between the pinion axis (z_f) and the gear axis of M_fq."""
    o = M[:3, 3]
    d = M[:3, 2]
    z = np.array([0.0, 0.0, 1.0])
    c = np.cross(z, d)
    if np.linalg.norm(c) < 1e-15:
        return np.linalg.norm(o - np.dot(o, z) * z), 0.0
    return abs(np.dot(o, c)) / np.linalg.norm(c), np.arccos(np.clip(np.dot(z, d), -1, 1))


@pytest.mark.parametrize("center_axis", ["x", "y"])
def test_gear_mounting_geometry(center_axis):
    C, dC, dZ, g = 100.0, 0.2, 0.1, 3 / 60 * np.pi / 180
    e = np.array([1.0, 0, 0]) if center_axis == "x" else np.array([0, 1.0, 0])
    # aligned: pure translation to (C + dC) e_c, plus dZ along z
    M = fr.gear_mounting(C, d_center=dC, d_axial=dZ, center_axis=center_axis)
    np.testing.assert_allclose(M[:3, :3], np.eye(3), atol=0)
    np.testing.assert_allclose(M[:3, 3], (C + dC) * e + [0, 0, dZ], atol=1e-14)
    # in-plane: axes stay coplanar (shortest distance 0 unless parallel) at angle g
    M = fr.gear_mounting(C, gamma_in_plane=g, center_axis=center_axis)
    d = M[:3, 2]
    assert abs(np.dot(np.cross([0, 0, 1], d), M[:3, 3])) < 1e-12  # coplanar: axes intersect
    np.testing.assert_allclose(np.arccos(d[2]), g, rtol=1e-9)
    np.testing.assert_allclose(np.dot(d, e), np.sin(g), rtol=1e-12)  # tilts toward +e_c
    # out-of-plane: crossed axes, shortest distance stays C, crossing angle g
    M = fr.gear_mounting(C, gamma_out_of_plane=g, center_axis=center_axis)
    dist, angle = _axes_distance_and_angle(M)
    assert dist == pytest.approx(C, rel=1e-12)
    assert angle == pytest.approx(g, rel=1e-9)
    np.testing.assert_allclose(np.dot(M[:3, 2], e), 0.0, atol=1e-16)
    # axial slide is along the misaligned axis
    M = fr.gear_mounting(C, d_axial=dZ, gamma_in_plane=g, gamma_out_of_plane=g, center_axis=center_axis)
    np.testing.assert_allclose(M[:3, 3], C * e + dZ * M[:3, 2], atol=1e-13)
    assert fr.is_rigid(M)


def test_gear_mounting_vectorised():
    g = np.linspace(0, 1e-3, 4)
    M = fr.gear_mounting(50.0, gamma_in_plane=g, d_center=np.zeros(4))
    assert M.shape == (4, 4, 4)
    np.testing.assert_allclose(M[2], fr.gear_mounting(50.0, gamma_in_plane=g[2]))


@pytest.mark.parametrize("rot, drot", [(fr.rot_x, fr.drot_x), (fr.rot_y, fr.drot_y), (fr.rot_z, fr.drot_z)])
def test_rotation_derivatives_match_finite_differences(rot, drot):
    a = np.array([[-2.9, -0.4, 0.0], [0.3, 1.2, 5.0]])
    h = 1e-4
    # 4th-order central differences: error ~ h^4 / 30 + eps / h, about 1e-12 here
    d1 = (rot(a - 2 * h) - 8 * rot(a - h) + 8 * rot(a + h) - rot(a + 2 * h)) / (12 * h)
    d2 = (-rot(a - 2 * h) + 16 * rot(a - h) - 30 * rot(a) + 16 * rot(a + h) - rot(a + 2 * h)) / (12 * h * h)
    assert drot(a).shape == (2, 3, 3, 3)
    np.testing.assert_allclose(drot(a), d1, rtol=0, atol=1e-11)
    np.testing.assert_allclose(drot(a, order=2), d2, rtol=0, atol=1e-7)
    # closed forms: dR/da = R K and d2R/da2 = R K^2 with K the generator of the axis
    K = drot(0.0)
    np.testing.assert_allclose(drot(a), rot(a) @ K, atol=1e-15)
    np.testing.assert_allclose(drot(a, 2), rot(a) @ K @ K, atol=1e-15)
    np.testing.assert_array_equal(drot(0.7), drot(np.array([0.7]))[0])
    with pytest.raises(ValueError, match="order"):
        drot(0.1, order=3)


def test_rotation_about_axis_derivatives_match_finite_differences():
    k = np.array([1.0, 2.0, -0.5])
    a = np.array([-1.3, 0.2, 2.8])
    h = 1e-4

    def R(x):
        return fr.rotation_about_axis(k, x)

    d1 = (R(a - 2 * h) - 8 * R(a - h) + 8 * R(a + h) - R(a + 2 * h)) / (12 * h)
    d2 = (-R(a - 2 * h) + 16 * R(a - h) - 30 * R(a) + 16 * R(a + h) - R(a + 2 * h)) / (12 * h * h)
    np.testing.assert_allclose(fr.drotation_about_axis(k, a), d1, rtol=0, atol=1e-11)
    np.testing.assert_allclose(fr.drotation_about_axis(k, a, order=2), d2, rtol=0, atol=1e-7)
    # about a coordinate axis they are drot_x / drot_z
    np.testing.assert_allclose(fr.drotation_about_axis([1, 0, 0], a), fr.drot_x(a), atol=1e-15)
    np.testing.assert_allclose(fr.drotation_about_axis([0, 0, 2], a, 2), fr.drot_z(a, 2), atol=1e-15)
    R, dR, d2R = fr.rotation_about_axis_with_derivatives(k, a)
    np.testing.assert_array_equal(R, fr.rotation_about_axis(k, a))
    np.testing.assert_array_equal(dR, fr.drotation_about_axis(k, a))
    np.testing.assert_array_equal(d2R, fr.drotation_about_axis(k, a, 2))
    with pytest.raises(ValueError, match="order"):
        fr.drotation_about_axis(k, 0.1, order=0)
    with pytest.raises(ValueError):
        fr.drotation_about_axis([0, 0, 0], 0.1)


def test_component_rotations_equal_the_matrix_products():
    """rotate_z and matrix_applier (structure of arrays) against rot_z / M @ v + t."""
    rng = np.random.default_rng(4)
    v = rng.normal(size=(50, 3))
    a = rng.uniform(-3, 3, 50)
    got = np.column_stack(fr.rotate_z(np.cos(a), np.sin(a), tuple(v.T)))
    np.testing.assert_allclose(got, np.einsum("nij,nj->ni", fr.rot_z(a), v), rtol=0, atol=1e-15)
    M = rng.normal(size=(3, 3))
    M[0, 1], M[1, 1], M[2, 0], M[2, 2] = 0.0, 1.0, -1.0, 0.0  # the skipped and the free terms
    t = np.array([0.5, 0.0, -2.0])
    ap = fr.matrix_applier(M, t)
    np.testing.assert_allclose(np.column_stack(ap(tuple(v.T))), v @ M.T + t, rtol=0, atol=1e-14)
    one = ap(tuple(float(x) for x in v[0]))  # floats in, floats out
    assert all(type(x) is float for x in one)
    np.testing.assert_allclose(one, M @ v[0] + t, atol=1e-14)
    assert fr.apply_matrix(np.zeros((3, 3)), (1.0, 2.0, 3.0)) == (0.0, 0.0, 0.0)
    for bad in (np.eye(2), np.full((3, 3), np.nan)):
        with pytest.raises(ValueError, match="M must be one finite 3x3 matrix"):
            fr.matrix_applier(bad)
    with pytest.raises(ValueError, match="t must be a finite 3-vector"):
        fr.matrix_applier(np.eye(3), [0.0, np.inf, 0.0])
