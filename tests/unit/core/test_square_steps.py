"""Newton steps of square systems above the Gauss-Jordan sizes (LAPACK's inverse,
gearrep._newton_steps.lapack_inverse) and the envelope-pair TCA's record of the Jacobian at its
roots (gearrep.tca.solve_envelope_points)."""

import numpy as np
import pytest

from gearrep import tca
from gearrep._newton_steps import GAUSS_JORDAN_MAX_K, gauss_jordan, lapack_inverse, step_floats, step_square, svd_step
from gearrep.replications import load
from gearrep.settings import defaults


def _systems(k, n, seed):
    """Random, scaled, exactly singular (rows 10-14) and zeroed (non-finite Jacobian the solver
    zeroes, rows 15-16) k x k systems."""
    rng = np.random.default_rng(seed)
    J = rng.normal(size=(n, k, k)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1, 1))
    J[10:15, -1] = 2.0 * J[10:15, 0]
    J[15:17] = 0.0
    return J, rng.normal(size=(n, k))


@pytest.mark.parametrize("k", [7, 9])
def test_larger_square_steps_match_the_svd_step_and_a_system_alone_gets_its_batch_values(k):
    """Above GAUSS_JORDAN_MAX_K the step is LAPACK's: the SVD step on the regular systems (to the
    rounding of the conditioning), the same singular flags, Gauss-Jordan's inverse norms; one
    system alone (a batch of one, and the float form, which has no written-out elimination of
    this size) gets bit for bit its values in the batch, and so does a system of a batch in which
    LAPACK meets a singular one."""
    assert k > GAUSS_JORDAN_MAX_K
    J, F = _systems(k, 200, k)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        d, singular, sv = step_square(J, F, 1e-13)
        d_svd, singular_svd, s = svd_step(J, F, 1e-13)
        x_gj, q_inv_gj, q_J_gj = gauss_jordan(J, F)
    np.testing.assert_array_equal(singular, singular_svd)
    assert singular[10:17].all() and not singular[17:].any() and not singular[:10].any()
    ok = ~singular
    np.testing.assert_allclose(d[ok], d_svd[ok], rtol=1e-7, atol=1e-9 * np.abs(d_svd[ok]).max())
    x, q_inv, q_J = lapack_inverse(J[ok], F[ok])
    np.testing.assert_allclose(x, x_gj[ok], rtol=1e-7, atol=1e-9 * np.abs(x).max())
    np.testing.assert_allclose(q_inv, q_inv_gj[ok], rtol=1e-7)
    np.testing.assert_allclose(q_J, q_J_gj[ok], rtol=1e-13)
    regular = lapack_inverse(J[20:40], F[20:40])  # no singular system: one LAPACK call
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # the singular ones: inf or huge
        mixed = lapack_inverse(J[:40], F[:40])
    assert not (mixed[1][10:17] < 1e20).any()  # inf, or huge where rounding leaves a pivot
    for got, alone in zip(mixed, regular):
        np.testing.assert_array_equal(got[20:40], alone)
    for r in (0, 12, 16, 50):
        one = step_floats(J[r].tolist(), F[r].tolist(), 1e-13, True)
        batch_of_one = step_square(J[r : r + 1], F[r : r + 1], 1e-13)
        np.testing.assert_array_equal(np.array([one[0]]), batch_of_one[0])
        np.testing.assert_array_equal(batch_of_one[0], d[r : r + 1])
        assert one[1] == singular[r] == batch_of_one[1][0]


@pytest.fixture(scope="module")
def hob_cut(published):
    """The hob-cut pair of the Table 5.4 example with its errors, and its contact traced at
    five angles (the robustness table's case)."""
    from gearrep.replications.hobcut_tca.bench import robustness_cases

    mod = load("hobcut_tca")
    s = defaults(mod.SETTINGS)
    c = robustness_cases(s, mod.params_from_published(published))[1]
    return c["pair"], c["phi1"], c["nominal"](c["phi1"]), c["tol"]


def test_the_envelope_solve_records_the_jacobian_at_its_roots(hob_cut):
    """solve_envelope_points keeps the Jacobian of each row's last evaluation where that was at
    its root: the record equals the system evaluated afresh at the roots (to rounding: the rows
    were evaluated in other batches), its condition number is the SVD's, a row taken or copied
    carries its Jacobian along, and a row whose record is not at its root is evaluated afresh."""
    pair, phi, x0, tol = hob_cut
    sol = tca.solve_envelope_points(pair, phi, x0, tol=tol)
    assert sol.converged.all()
    _, J, _ = tca.envelope_tangency_system(pair, sol.x, sol.phi1, tca.envelope_dropped_component(pair, x0, phi))
    np.testing.assert_allclose(sol.jacobian, J, rtol=1e-10, atol=1e-12 * np.abs(J).max())
    s = np.linalg.svd(J, compute_uv=False)
    np.testing.assert_allclose(sol.cond, s[:, 0] / s[:, -1], rtol=1e-8)
    part = sol.take([3, 1])
    np.testing.assert_array_equal(part.jacobian, sol.jacobian[[3, 1]])
    np.testing.assert_array_equal(part.cond, sol.cond[[3, 1]])
    # a row whose last evaluation with a Jacobian was not at its root (a step the line search
    # shortened is evaluated without one): evaluated afresh, the others taken from the record
    from gearrep.tca._envelope import _PARTS, _Record, _tangency

    drop = tca.envelope_dropped_component(pair, x0, phi)
    record = _Record(len(phi))
    stale = sol.x.copy()
    stale[[0, 3], 0] += 1e-3
    for x in (stale[:, :], sol.x[1:3]):
        idx = np.arange(len(phi)) if len(x) == len(phi) else np.arange(1, 3)
        _, Jx, _, parts = _tangency(pair, x, phi[idx], drop[idx], phi_column=False)
        record.store(idx, x, Jx, parts)
    J_rec, parts = record.at(sol.x, phi, drop, pair)
    _, J_now, _, now = _tangency(pair, sol.x, phi, drop, phi_column=False)
    np.testing.assert_allclose(J_rec, J_now, rtol=1e-10, atol=1e-12 * np.abs(J_now).max())
    for p in _PARTS:
        np.testing.assert_allclose(parts[p], now[p], rtol=1e-12, atol=1e-12)
