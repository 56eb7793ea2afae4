"""Public helpers of the core not covered by the topic tests: unit conversions, the batched 2x2
eigen-solver, the shape matrix, per-row Newton solves, not-computed records, check validation,
parameter tables and the load average."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from gearrep import benchmark, checks, curvature, published, tca, units
from gearrep.surfaces.analytic import Cylinder, Sphere


@pytest.mark.parametrize(
    "to, back, x, y",
    [
        (units.deg2rad, units.rad2deg, 180.0, math.pi),
        (units.arcmin2rad, units.rad2arcmin, 60.0, math.pi / 180.0),
        (units.arcsec2rad, units.rad2arcsec, 3600.0, math.pi / 180.0),
        (units.in2mm, units.mm2in, 1.0, 25.4),
    ],
)
def test_unit_conversions_exact_and_inverse(to, back, x, y):
    assert to(x) == pytest.approx(y, rel=1e-15)
    arr = np.array([-2.5, 0.0, 1e-9, 7.0])
    np.testing.assert_allclose(back(to(arr)), arr, rtol=1e-15, atol=0)


def test_sym2_eig_matches_numpy_eigh():
    rng = np.random.default_rng(1)
    a, b, c = rng.normal(size=(3, 500)) * 10.0 ** rng.uniform(-6, 6, size=(3, 500))
    lam1, lam2, theta = curvature.sym2_eig(a, b, c)
    M = np.stack([np.stack([a, b], -1), np.stack([b, c], -1)], -2)
    w = np.linalg.eigvalsh(M)
    scale = np.abs(w).max(axis=1)
    np.testing.assert_allclose(lam1, w[:, 1], rtol=0, atol=1e-13 * scale.max())
    assert np.all(np.abs(lam1 - w[:, 1]) <= 1e-12 * scale)
    assert np.all(np.abs(lam2 - w[:, 0]) <= 1e-12 * scale)
    e = np.stack([np.cos(theta), np.sin(theta)], -1)
    Me = np.einsum("nij,nj->ni", M, e)
    assert np.all(np.linalg.norm(Me - lam1[:, None] * e, axis=1) <= 1e-10 * scale)
    assert np.all((theta > -np.pi / 2 - 1e-15) & (theta <= np.pi / 2 + 1e-15))


def test_sym2_eig_small_eigenvalue_without_cancellation_and_umbilic():
    # [[1, 1e-8], [1e-8, 1e-16 + 1e-16]]: det = 1e-16 exactly representable -> small eigenvalue 1e-16
    lam1, lam2, _ = curvature.sym2_eig(1.0, 1e-8, 2e-16)
    assert lam2 == pytest.approx(1e-16, rel=1e-8)
    l1, l2, th = curvature.sym2_eig(np.array([2.0, -3.0]), np.array([0.0, 0.0]), np.array([2.0, -3.0]))
    np.testing.assert_array_equal(l1, l2)
    np.testing.assert_array_equal(th, 0.0)


@pytest.mark.parametrize("surface, expected", [(Sphere(R=4.0), (-0.25, -0.25)), (Cylinder(R=2.0), (0.0, -0.5))])
def test_shape_matrix_eigenvalues_are_principal_curvatures(surface, expected):
    u, v = np.array([0.3, 1.1]), np.array([0.2, -0.4])
    t1, t2, n, S11, S12, S22 = curvature.shape_matrix(surface.evaluate(u, v))
    np.testing.assert_allclose(np.einsum("...i,...i", t1, t2), 0.0, atol=1e-15)
    np.testing.assert_allclose(np.einsum("...i,...i", t1, n), 0.0, atol=1e-15)
    k1, k2, _ = curvature.sym2_eig(S11, S12, S22)
    got = np.sort(np.stack([k1, k2]), axis=0)
    np.testing.assert_allclose(got, np.sort(np.array(expected))[:, None] * np.ones(2), rtol=1e-12, atol=1e-14)


def test_newton_rows_solves_each_row_with_its_own_data():
    # x^2 = p0, y = p1 x: roots (sqrt(p0), p1 sqrt(p0)) from positive starts
    p = np.array([[4.0, 1.0], [9.0, -2.0], [2.0, 0.5]])

    def F(x, q):
        return np.column_stack([x[:, 0] ** 2 - q[:, 0], x[:, 1] - q[:, 1] * x[:, 0]])

    def FJ(x, q):
        J = np.zeros((len(x), 2, 2))
        J[:, 0, 0] = 2 * x[:, 0]
        J[:, 1, 0] = -q[:, 1]
        J[:, 1, 1] = 1.0
        return F(x, q), J

    exact = np.column_stack([np.sqrt(p[:, 0]), p[:, 1] * np.sqrt(p[:, 0])])
    for jac in ("analytic", "numeric"):
        res = tca.newton_rows(F, FJ, np.ones((3, 2)), p, jacobian=jac, tol=1e-12)
        assert np.all(res.converged), jac
        np.testing.assert_allclose(res.x, exact, rtol=1e-10)
        assert np.all(res.residual < 1e-12) and np.all(res.iterations >= 1)
    with pytest.raises(ValueError, match="params has 2 rows for 3 starts"):
        tca.newton_rows(F, FJ, np.ones((3, 2)), p[:2])
    with pytest.raises(ValueError, match="jacobian must be"):
        tca.newton_rows(F, FJ, np.ones((3, 2)), p, jacobian="complex")


def _values():
    return pd.DataFrame(
        {
            "id": ["x-1", "x-2"],
            "seed": ["000", "000"],
            "source": ["Table 1"] * 2,
            "row": ["a=1", "a=2"],
            "quantity": ["k", "k"],
            "unit": ["per_mm"] * 2,
            "value": ["0.5", "-1.25"],
        }
    )


def test_not_computed_records_values_and_claims():
    rec = checks.not_computed(_values(), "needs a bevel surface")
    assert list(rec.columns) == checks.CHECK_COLUMNS
    assert list(rec["status"]) == ["not-computed"] * 2
    assert list(rec["published"]) == [0.5, -1.25] and rec["computed"].isna().all()
    assert (rec["note"] == "needs a bevel surface").all()
    claims = pd.DataFrame(
        {
            "id": ["c-1"],
            "seed": ["004"],
            "source": ["sec 4"],
            "kind": ["trend"],
            "statement": ["S grows"],
            "parameters": ["R_T=300"],
        }
    )
    rc = checks.not_computed(claims, "later")
    assert rc.loc[0, "row"] == "R_T=300" and rc.loc[0, "quantity"] == "trend" and math.isnan(rc.loc[0, "published"])
    checks.validate_checks(pd.concat([rec, rc], ignore_index=True))


def test_validate_checks_rejects_bad_tables():
    rec = checks.not_computed(_values(), "r")
    with pytest.raises(ValueError, match="lacks columns"):
        checks.validate_checks(rec.drop(columns=["status"]))
    bad = rec.copy()
    bad.loc[0, "status"] = "ok"
    with pytest.raises(ValueError, match="unknown statuses"):
        checks.validate_checks(bad)
    with pytest.raises(ValueError, match="duplicate check ids"):
        checks.validate_checks(pd.concat([rec, rec.iloc[:1]]))


def test_param_table_selects_file_and_example():
    params = pd.DataFrame(
        {
            "file": ["p_a.csv", "p_a.csv", "p_a.csv", "p_b.csv"],
            "example": ["e1", "e1", "e2", "e1"],
            "parameter": ["m", "z", "m", "m"],
            "value": [2.5, 25.0, 3.0, 1.0],
        }
    )
    assert published.param_table(params, "p_a.csv", "e1") == {"m": 2.5, "z": 25.0}
    assert published.param_table(params, "p_b.csv") == {"m": 1.0}
    with pytest.raises(KeyError, match="example='e9'"):
        published.param_table(params, "p_a.csv", "e9")


def test_load_average_is_a_nonnegative_number_or_nan():
    la = benchmark.load_average()
    assert isinstance(la, float) and (math.isnan(la) or la >= 0.0)


def test_check_csv_round_trip_keeps_seed_text_and_bad_seeds_are_rejected(tmp_path):
    rec = checks.not_computed(_values(), "r")
    f = tmp_path / "c.csv"
    rec.to_csv(f, index=False)
    back = pd.read_csv(f, dtype=checks.TEXT_COLUMNS, keep_default_na=False, na_values=[""])
    assert list(back["seed"]) == ["000", "000"]
    checks.validate_checks(back)
    with pytest.raises(ValueError, match="three-digit string"):
        checks.validate_checks(pd.read_csv(f, keep_default_na=False, na_values=[""]))


def test_normal_derivatives_match_finite_differences():
    from gearrep.surfaces.analytic import Torus

    surf = Torus(c=5.0, a=1.5)
    u, v = np.array([0.3, 1.2]), np.array([0.7, -2.0])
    n, n_u, n_v = tca.normal_derivatives(surf.evaluate(u, v), -1)
    h = 1e-6
    for d, (du, dv) in ((n_u, (h, 0.0)), (n_v, (0.0, h))):
        plus = surf.evaluate(u + du, v + dv).normal
        minus = surf.evaluate(u - du, v - dv).normal
        np.testing.assert_allclose(d, -(plus - minus) / (2 * h), atol=1e-8)
    np.testing.assert_allclose(n, -surf.evaluate(u, v).normal, atol=1e-15)


def test_catt_turn_over_is_a_half_turn_about_x():
    from gearrep.surfaces.catt import turn_over

    T = turn_over()
    np.testing.assert_array_equal(T @ np.array([1.0, 2.0, 3.0]), [1.0, -2.0, -3.0])
    np.testing.assert_allclose(T @ T, np.eye(3))
    assert np.linalg.det(T) == pytest.approx(1.0)  # a rotation, not a mirror
