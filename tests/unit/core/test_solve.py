"""gearrep.solve: statuses, damping, bounds, singular Jacobians, over-determined systems."""

import numpy as np
import pytest
from _numerics import assert_same_solve

from gearrep.solve import Status, newton, numeric_jacobian, status_names


def sqrt2(x):
    return np.stack([x[:, 0] ** 2 - 2.0, x[:, 1] - x[:, 0]], axis=1)


def test_converges_to_both_roots_with_status():
    r = newton(sqrt2, np.array([[1.0, 0.0], [-3.0, 1.0]]))
    assert np.all(r.converged)
    # error <= residual / |df/dx| ~ 1e-14 / 2.8
    np.testing.assert_allclose(r.x[:, 0], [np.sqrt(2), -np.sqrt(2)], rtol=1e-13)
    assert np.all(r.residual < 1e-12) and np.all(r.iterations >= 1)


def test_singular_start_is_flagged():
    r = newton(sqrt2, np.array([[0.0, 0.0]]))
    assert r.status[0] == Status.SINGULAR
    assert status_names(r.status)[0] == "singular"


def test_root_outside_bounds_is_off_flank():
    r = newton(sqrt2, np.array([[-1.0, -1.0]]), lower=[0.0, 0.0], upper=[10.0, 10.0])
    assert r.status[0] == Status.OFF_FLANK


def test_keep_inside_projects_iterates():
    r = newton(sqrt2, np.array([[-1.0, -1.0]]), lower=[0.1, 0.1], upper=[10.0, 10.0], keep_inside=True)
    assert r.status[0] == Status.CONVERGED and r.x[0, 0] > 0


def test_plain_newton_can_fail_where_damped_succeeds():
    # arctan: plain Newton diverges from |x0| > 1.39, damped converges
    f = lambda x: np.arctan(x)  # noqa: E731
    x0 = np.array([[2.0]])
    assert newton(f, x0, damped=False, maxiter=30).status[0] != Status.CONVERGED
    assert newton(f, x0, damped=True).status[0] == Status.CONVERGED


def test_iteration_limit_gives_not_converged():
    f = lambda x: np.exp(x) - 1e-30  # noqa: E731  slow descent from far away
    r = newton(f, np.array([[50.0]]), maxiter=3)
    assert r.status[0] == Status.NOT_CONVERGED and r.iterations[0] == 3


def test_nonfinite_is_diverged():
    f = lambda x: np.where(x > 0.5, np.nan, x - 1.0)  # noqa: E731
    r = newton(f, np.array([[0.0]]), damped=False)
    assert r.status[0] in (Status.DIVERGED, Status.NOT_CONVERGED)
    assert not r.converged[0]


def test_overdetermined_consistent_system():
    # three equations, two unknowns, consistent: least-squares Newton converges
    f = lambda x: np.stack([x[:, 0] - 1, x[:, 1] - 2, x[:, 0] + x[:, 1] - 3], axis=1)  # noqa: E731
    r = newton(f, np.zeros((4, 2)))
    assert np.all(r.converged)
    np.testing.assert_allclose(r.x, [[1, 2]] * 4, atol=1e-14)


def test_numeric_jacobian_accuracy():
    x = np.array([[0.3, 1.7]])
    J = numeric_jacobian(sqrt2, x)
    np.testing.assert_allclose(J[0], [[0.6, 0.0], [-1.0, 1.0]], atol=1e-8)


def test_bad_arguments():
    with pytest.raises(ValueError, match="tol"):
        newton(sqrt2, np.zeros((1, 2)), tol=-1)
    with pytest.raises(ValueError, match="maxiter"):
        newton(sqrt2, np.zeros((1, 2)), maxiter=0)
    with pytest.raises(ValueError, match="equations"):
        newton(lambda x: x[:, :1], np.zeros((1, 2)))


def test_with_status_marks_wrong_root():
    r = newton(sqrt2, np.array([[1.0, 0.0], [-3.0, 1.0]]))
    w = r.with_status(r.x[:, 0] < 0, Status.WRONG_ROOT)
    assert list(w.status_name) == ["converged", "wrong_root"]


def test_start_already_at_root_is_converged_with_zero_iterations():
    r = newton(sqrt2, np.array([[np.sqrt(2), np.sqrt(2)]]))
    assert r.status[0] == Status.CONVERGED and r.iterations[0] == 0


def test_rows_mode_passes_indices_of_active_rows():
    # x^2 = p_i for each row; rows converge at different iterations, indices must stay aligned
    p = np.array([4.0, 100.0, 1e-2, 2.0])
    f = lambda x, i: x**2 - p[i, None]  # noqa: E731
    j = lambda x, i: (2 * x)[:, :, None]  # noqa: E731
    for jac in (j, None):
        r = newton(f, np.ones((4, 1)), jac, rows=True)
        assert np.all(r.converged)
        np.testing.assert_allclose(r.x[:, 0], np.sqrt(p), atol=1e-11)  # residual 1e-12 / |2x|


def test_condition_number_of_the_last_jacobian_is_reported():
    A = np.diag([1.0, 1e-3])
    b = np.array([2.0, 3e-3])

    def fun(x):
        return x @ A.T - b

    res = newton(fun, np.zeros((2, 2)), lambda x: np.broadcast_to(A, (len(x), 2, 2)), tol=1e-12)
    assert np.all(res.converged)
    np.testing.assert_allclose(res.condition, 1e3, rtol=1e-12)
    solved = newton(fun, np.array([[2.0, 3.0]]), tol=1e-12)  # start is the root: no iteration taken
    assert solved.iterations[0] == 0 and np.isnan(solved.condition[0])
    assert np.array_equal(res.with_status([True, False], Status.WRONG_ROOT).condition, res.condition)


def test_closed_form_2x2_step_matches_the_svd_step():
    from gearrep._newton_steps import step_2x2 as _step_2x2
    from gearrep._newton_steps import svd_step as _svd_step

    rng = np.random.default_rng(7)
    J = rng.normal(size=(400, 2, 2)) * 10.0 ** rng.uniform(-4, 4, size=(400, 1, 1))
    J[:50, 1] = 3.0 * J[:50, 0]  # exactly singular rows
    J[50:60, 1] = 3.0 * J[50:60, 0]
    J[50:60, 1, 1] += 1e-9 * np.abs(J[50:60, 0]).max(axis=-1)  # condition ~1e9
    F = rng.normal(size=(400, 2))
    d1, sing1, s1 = _step_2x2(J, F, 1e-13)
    d2, sing2, s2 = _svd_step(J, F, 1e-13)
    np.testing.assert_array_equal(sing1, sing2)
    assert sing1[:50].all() and not sing1[50:].any()
    # singular values agree to rounding relative to the largest one (the SVD's own accuracy)
    assert np.all(np.abs(s1 - s2) <= 1e-13 * s2[:, :1] + 1e-12 * s2)
    ok = ~sing1
    np.testing.assert_allclose(d1[ok][10:], d2[ok][10:], rtol=1e-9)  # well-conditioned rows
    np.testing.assert_allclose(d1[50:60], d2[50:60], rtol=1e-5)  # condition ~1e9: same step to its accuracy
    np.testing.assert_array_equal(d1[:50], d2[:50])  # singular rows: the SVD pseudo-inverse step itself


def _cubic_sine_rows(p):
    """(fun, jac) of the 2 x 2 systems x0^3 + x1 = p0, sin x0 + x1^2 = p1, one per row of ``p``,
    for ``newton(rows=True)``."""

    def fun(x, i):
        return np.column_stack([x[:, 0] ** 3 + x[:, 1] - p[i, 0], np.sin(x[:, 0]) + x[:, 1] ** 2 - p[i, 1]])

    def jac(x, i):
        J = np.empty((len(x), 2, 2))
        J[:, 0, 0], J[:, 0, 1] = 3 * x[:, 0] ** 2, 1.0
        J[:, 1, 0], J[:, 1, 1] = np.cos(x[:, 0]), 2 * x[:, 1]
        return J

    return fun, jac


def test_residual_and_jacobian_in_one_call_give_the_same_solves():
    """newton(fun_jac=...): the same iterates and records as fun + jac, with fewer calls."""
    rng = np.random.default_rng(3)
    p = rng.uniform(0.5, 2.0, (40, 2))
    calls = {"fj": 0}

    fun, jac = _cubic_sine_rows(p)

    def fun_jac(x, i):
        calls["fj"] += 1
        return fun(x, i), jac(x, i)

    x0 = rng.uniform(-2, 2, (40, 2))
    for damped in (True, False):
        a = newton(fun, x0, jac, rows=True, damped=damped)
        b = newton(fun, x0, jac, rows=True, damped=damped, fun_jac=fun_jac)
        for f in ("x", "residual", "iterations", "status", "condition"):
            np.testing.assert_array_equal(getattr(a, f), getattr(b, f))
    assert calls["fj"] > 0


def test_a_lazy_jacobian_gives_the_same_solves_and_is_formed_only_for_rows_that_step_again():
    """newton(fun_jac=...) whose J is a function of the rows: the same records as an
    eager J, bit for bit (damped and plain, rows converging at different steps, a batch of one);
    J is called at most once per evaluation, only for rows that are not done after it, and never
    for the evaluation at which every row has converged."""
    rng = np.random.default_rng(3)
    p = rng.uniform(0.5, 2.0, (40, 2))

    fun, jac = _cubic_sine_rows(p)

    log = []

    def fun_jac_lazy(x, i):
        F, n_rows = fun(x, i), len(x)
        entry = {"n": n_rows, "asked": []}
        log.append(entry)

        def J(rows=None):
            entry["asked"].append(n_rows if rows is None else len(rows))
            full = jac(x, i)
            return full if rows is None else full[rows]

        return F, J

    x0 = rng.uniform(-2, 2, (40, 2))
    for damped in (True, False):
        for start in (x0, x0[:1]):
            log.clear()
            a = newton(fun, start, jac, rows=True, damped=damped, fun_jac=lambda x, i: (fun(x, i), jac(x, i)))
            b = newton(fun, start, jac, rows=True, damped=damped, fun_jac=fun_jac_lazy)
            for f in ("x", "residual", "iterations", "status", "condition"):
                np.testing.assert_array_equal(getattr(a, f), getattr(b, f))
            assert all(len(e["asked"]) <= 1 for e in log)
            if len(start) > 1:
                # the first evaluation (the start) forms every row; the last one none
                assert log[0]["asked"] == [len(start)] and log[-1]["asked"] == []
                assert sum(sum(e["asked"]) for e in log) < sum(e["n"] for e in log)
                assert len(np.unique(a.iterations)) > 1 and (a.status == Status.CONVERGED).any()


def test_square_step_matches_the_svd_step_and_flags_the_same_rows():
    from gearrep._newton_steps import step_square as _step_square
    from gearrep._newton_steps import svd_step as _svd_step

    rng = np.random.default_rng(8)
    J = rng.normal(size=(300, 5, 5)) * 10.0 ** rng.uniform(-3, 3, size=(300, 1, 1))
    J[:20, 4] = 2.0 * J[:20, 0]  # exactly singular rows
    J[20:30, 4] = J[20:30, 0] + 1e-11 * rng.normal(size=(10, 5)) * np.abs(J[20:30, 0]).max(axis=-1, keepdims=True)
    F = rng.normal(size=(300, 5))
    d1, sing1, sv1 = _step_square(J, F, 1e-13)
    d2, sing2, s2 = _svd_step(J, F, 1e-13)
    np.testing.assert_array_equal(sing1, sing2)
    ok = ~sing1
    np.testing.assert_allclose(d1[30:], d2[30:], rtol=1e-8, atol=1e-10 * np.abs(d2[30:]).max())
    # bounds: ||J||_F >= s_max, 1/||J^-1||_F <= s_min, ratio within a factor k = 5 of the 2-norm condition
    c1, c2 = sv1[ok, 0] / sv1[ok, 1], s2[ok, 0] / s2[ok, -1]
    assert np.all(c1 >= c2 * (1 - 1e-9)) and np.all(c1 <= 5 * c2 * (1 + 1e-9))


@pytest.mark.parametrize("k", [3, 4, 5, 6])
def test_gauss_jordan_matches_the_inverse_and_one_system_alone_gets_its_batch_values(k):
    """The batch elimination (rows of 1-D arrays, per-system pivots) gives J^-1 F and the squared
    Frobenius norms of J and J^-1 to rounding, and the written-out float version of one system
    gives bit for bit what that system gets in the batch: random, scaled, pivot-heavy (every
    pivot choice differs between systems), exactly singular and non-finite systems."""
    from gearrep._newton_steps import GAUSS_JORDAN_FLOATS, gauss_jordan, step_floats, step_square

    rng = np.random.default_rng(k)
    n = 400
    J = rng.normal(size=(n, k, k)) * 10.0 ** rng.uniform(-3, 3, size=(n, 1, 1))
    J[:50] *= 1.0 + np.tril(np.full((k, k), 1e3), -1)  # large lower triangle: pivots move off the diagonal
    J[50:60, -1] = 2.0 * J[50:60, 0]  # exactly singular
    J[60:62, 1, 1] = np.nan
    F = rng.normal(size=(n, k))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        x, q_inv, q_J = gauss_jordan(J, F)
    ok = np.arange(n) >= 62
    inv = np.linalg.inv(J[ok])
    np.testing.assert_allclose(x[ok], np.einsum("nij,nj->ni", inv, F[ok]), rtol=1e-7, atol=1e-9 * np.abs(x[ok]).max())
    np.testing.assert_allclose(q_inv[ok], np.einsum("nij,nij->n", inv, inv), rtol=1e-7)
    np.testing.assert_allclose(q_J, np.einsum("nij,nij->n", J, J), rtol=1e-13)
    one = GAUSS_JORDAN_FLOATS[k]
    for r in range(n):
        try:
            xr, qi, qj = one(J[r].tolist(), F[r].tolist())
        except ZeroDivisionError:
            assert not np.isfinite(q_inv[r]) or r < 62
            continue
        np.testing.assert_array_equal(np.array(xr), x[r], err_msg=f"system {r}")
        np.testing.assert_array_equal([qi, qj], [q_inv[r], q_J[r]], err_msg=f"system {r}")
    for r in [*range(50, 60), *range(62, n)]:  # steps (the solver zeroes a non-finite Jacobian first)
        Jr, Fr = J[r : r + 1], F[r : r + 1]
        d, singular, cond = step_floats(Jr[0].tolist(), Fr[0].tolist(), 1e-13, True)
        db, sb, sv = step_square(Jr, Fr, 1e-13)
        np.testing.assert_array_equal(np.array([d]), db, err_msg=f"step of system {r}")
        with np.errstate(divide="ignore"):
            assert singular == sb[0] and cond == sv[0, 0] / sv[0, 1], f"step of system {r}"


def _looped_gauss_jordan(J, F):
    """Gauss-Jordan elimination of one system on floats in loops: the reference the written-out
    eliminations are read against (the same operations in the same order)."""
    k = len(F)
    R = [J[i] + [F[i]] for i in range(k)]

    def squares():
        q = 0.0
        for row in R:
            for v in row[:k]:
                q = q + v * v
        return q

    q_J = squares()
    for c in range(k):
        p = max(range(c, k), key=lambda i: (abs(R[i][c]), -i))  # the first row with the largest |entry|
        R[c], R[p] = R[p], R[c]
        a = R[c]
        inv = 1.0 / a[c]
        b = R[c] = [inv if j == c else a[j] * inv for j in range(k + 1)]
        for i in range(k):
            if i != c:
                a, f = R[i], R[i][c]
                R[i] = [-(f * inv) if j == c else a[j] - f * b[j] for j in range(k + 1)]
    return [R[i][k] for i in range(k)], squares(), q_J


def test_the_written_out_eliminations_are_readable_compiled_at_import_and_equal_the_loops():
    """Each size's elimination on floats is compiled at import from gauss_jordan_source, which is
    its source (inspect.getsource reads it back, a traceback shows its lines), straight-line code
    (no loop but the one building the rows), and gives bit for bit what the same elimination in
    loops gives."""
    import inspect
    import traceback

    from gearrep._newton_steps import GAUSS_JORDAN_FLOATS, gauss_jordan_source, step_floats, step_square

    assert sorted(GAUSS_JORDAN_FLOATS) == list(range(3, 7))
    rng = np.random.default_rng(11)
    for k, fn in GAUSS_JORDAN_FLOATS.items():
        source = gauss_jordan_source(k)
        assert inspect.getsource(fn) == source
        assert source.count(" for ") == 1 and "while" not in source
        for _ in range(50):
            J = (rng.normal(size=(k, k)) * 10.0 ** rng.uniform(-3, 3, size=(k, 1))).tolist()
            F = rng.normal(size=k).tolist()
            assert fn(J, F) == _looped_gauss_jordan(J, F)
    # a size without a written-out elimination: the batch elimination on a batch of one
    J, F = rng.normal(size=(1, 7, 7)), rng.normal(size=(1, 7))
    d, singular, cond = step_floats(J[0].tolist(), F[0].tolist(), 1e-13, True)
    np.testing.assert_array_equal(np.array([d]), step_square(J, F, 1e-13)[0])
    with pytest.raises(ZeroDivisionError) as err:
        GAUSS_JORDAN_FLOATS[3]([[0.0] * 3] * 3, [1.0, 2.0, 3.0])
    assert "inv = 1.0 / a[0]" in "".join(traceback.format_tb(err.value.__traceback__))


@pytest.mark.numerics
@pytest.mark.parametrize("damped", [True, False])
@pytest.mark.parametrize("mode", ["analytic", "numeric", "fun_jac", "least_squares"])
def test_one_problem_alone_gives_its_batch_record(damped, mode):
    """newton on one row (its own scalar bookkeeping) returns what the same row gets in a batch:
    the status, and where converged the solution, residual, iterations and condition within the
    solver's accuracy (tests/_numerics.py), for converging, diverging, singular, stalling and
    non-finite starts."""
    rng = np.random.default_rng(5)
    x0 = np.vstack(
        [
            rng.uniform(-3, 3, (30, 2)),
            [[0.0, 0.0], [np.nan, 1.0], [1e200, 1.0], [np.pi / 2, 0.0], [-1.0, 4.0]],
        ]
    )
    p = rng.uniform(0.2, 1.5, (len(x0), 2))

    def fun(x, i):
        f = np.column_stack([np.sin(x[:, 0]) * x[:, 1] - p[i, 0], x[:, 0] ** 2 + np.cos(x[:, 1]) - p[i, 1]])
        if mode == "least_squares":
            f = np.column_stack([f, 0.1 * (x[:, 0] - x[:, 1])])
        return f

    def jac(x, i):
        J = np.zeros((len(x), 3 if mode == "least_squares" else 2, 2))
        J[:, 0, 0], J[:, 0, 1] = np.cos(x[:, 0]) * x[:, 1], np.sin(x[:, 0])
        J[:, 1, 0], J[:, 1, 1] = 2 * x[:, 0], -np.sin(x[:, 1])
        if mode == "least_squares":
            J[:, 2, 0], J[:, 2, 1] = 0.1, -0.1
        return J

    kw = dict(rows=True, damped=damped, maxiter=25, lower=[-2.5, -np.inf], upper=[2.5, np.inf])
    if mode == "fun_jac":
        kw["fun_jac"] = lambda x, i: (fun(x, i), jac(x, i))
    j = None if mode == "numeric" else jac
    with np.errstate(all="ignore"):
        batch = newton(fun, x0, j, **kw)
        for r in range(len(x0)):
            one = newton(
                lambda x, i, r=r: fun(x, np.array([r])),
                x0[r : r + 1],
                None if j is None else (lambda x, i, r=r: jac(x, np.array([r]))),
                **{
                    **kw,
                    **(
                        {"fun_jac": lambda x, i, r=r: (fun(x, np.array([r])), jac(x, np.array([r])))}
                        if mode == "fun_jac"
                        else {}
                    ),
                },
            )
            assert_same_solve(one, batch, 1e-12, ("x", "residual"), [0], [r], what=f"row {r}")
    assert len(set(batch.status.tolist())) >= 3  # converged, diverged and another outcome are all exercised
