"""The least-squares Newton step of :func:`gearrep.solve.newton`: ``d = -J^+ F`` for a batch of
small systems (J (n, m, k), F (n, m), arrays: :func:`step_batch`) and for one system on Python
floats (lists: :func:`step_floats`), with a singular flag and the condition number.

By default the step is the pseudo-inverse step by SVD (:func:`svd_step`), so square and
over-determined systems take one code path and a rank-deficient Jacobian is detected from its
singular values instead of being inverted. Two cases take a cheaper route to the same step: 2 x 2
systems a closed form (:func:`step_2x2`), and with ``inverse_square`` larger square systems
Gauss-Jordan elimination with partial pivoting up to 6 x 6, LAPACK's inverse above
(:func:`step_square`, the choice by size measured: :data:`GAUSS_JORDAN_MAX_K`), with a
Frobenius-norm bound of the condition; the rows these cannot clear of singularity go through the
SVD. The float forms
do the same IEEE operations in the same order as the batch forms, so one system gets bit for bit
the step its row gets in a batch.

The float form of Gauss-Jordan elimination is written out for each size, without loops:
:func:`gauss_jordan_source` writes its source, which is compiled once at import for k = 3 ... 6
(:data:`GAUSS_JORDAN_FLOATS`) and registered with :mod:`linecache`, so ``inspect.getsource`` and
tracebacks show it. Against the same elimination in loops it costs 6.7 instead of 15.7 us for
k = 5, and a single-point conventional contact solve of the README pair 658 instead of 795
reference-kernel elements (one interleaved run).
"""

from __future__ import annotations

import linecache
import math

import numpy as np

__all__ = [
    "step_batch",
    "svd_step",
    "step_2x2",
    "step_square",
    "gauss_jordan",
    "lapack_inverse",
    "GAUSS_JORDAN_MAX_K",
    "step_floats",
    "step_2x2_floats",
    "step_square_floats",
    "gauss_jordan_source",
    "GAUSS_JORDAN_FLOATS",
]


def _ratio(a: float, b: float) -> float:
    """a / b with numpy's result for b = 0 (inf, -inf or NaN) instead of an exception."""
    if b == 0.0:
        return math.inf if a > 0 else (-math.inf if a < 0 else math.nan)
    return a / b


def step_batch(J: np.ndarray, F: np.ndarray, rcond: float, inverse_square: bool = False):
    """Least-squares Newton step ``d = -J^+ F`` of a batch (J (n, m, k), F (n, m)), a singular mask,
    and the extreme singular values (n, 2), or bounds of them, for the condition number.

    Square 2x2 systems (the reduced TCA) take a closed form (:func:`step_2x2`), with
    ``inverse_square`` larger square ones Gauss-Jordan elimination (:func:`step_square`), every
    other system the SVD (:func:`svd_step`)."""
    if J.shape[1:] == (2, 2):
        return step_2x2(J, F, rcond)
    if inverse_square and J.shape[1] == J.shape[2] > 2 and J.shape[0] > 0:
        return step_square(J, F, rcond)
    d, singular, s = svd_step(J, F, rcond)
    return d, singular, s[:, [0, -1]]


def svd_step(J, F, rcond):
    """The pseudo-inverse step by batched SVD: (d, singular, all singular values (n, min(m, k)))."""
    U, s, Vt = np.linalg.svd(J, full_matrices=False)
    smax = s[:, :1]
    singular = ~(s[:, -1] > rcond * smax[:, 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = np.where(s > rcond * smax, 1.0 / s, 0.0)
    coef = np.einsum("nmk,nm->nk", U, F) * inv
    d = -np.einsum("nkj,nk->nj", Vt, coef)
    return d, singular, s


def step_2x2(J, F, rcond):
    """2 x 2 systems: singular values from the rotation/reflection split of the matrix
    (s1 = Q + R, s2 = |det| / s1 with Q = |((a+d)/2, (c-b)/2)|, R = |((a-d)/2, (c+b)/2)|) and the
    step from the adjugate; rows found singular go through the SVD, so that they get the same
    pseudo-inverse step."""
    a, b, c, d = J[:, 0, 0], J[:, 0, 1], J[:, 1, 0], J[:, 1, 1]
    s1 = np.hypot(0.5 * (a + d), 0.5 * (c - b)) + np.hypot(0.5 * (a - d), 0.5 * (c + b))
    det = a * d - b * c
    n = len(J)
    step = np.empty((n, 2))
    sv = np.empty((n, 2))
    with np.errstate(divide="ignore", invalid="ignore"):
        s2 = np.where(s1 > 0, np.abs(det) / s1, 0.0)
        singular = ~(s2 > rcond * s1)
        step[:, 0] = -(d * F[:, 0] - b * F[:, 1]) / det
        step[:, 1] = -(a * F[:, 1] - c * F[:, 0]) / det
    sv[:, 0], sv[:, 1] = s1, s2
    if singular.any():
        idx = np.flatnonzero(singular)
        step[idx], _, sv[idx] = svd_step(J[idx], F[idx], rcond)
    return step, singular, sv


#: the largest square system whose step :func:`step_square` takes from the batched Gauss-Jordan
#: elimination (the sizes with a written-out elimination on floats, :data:`GAUSS_JORDAN_FLOATS`,
#: so that one system alone gets its batch values); larger ones take LAPACK's inverse
#: (:func:`lapack_inverse`). Its cost per system grows with k^3 numpy calls over the batch:
#: measured on the reference machine (2026-12-02, in reference-kernel elements per system,
#: Gauss-Jordan / LAPACK), k = 5: 5.8 / 2.2 at 200 systems, 2.2 / 2.1 at 1 000, 1.2 / 2.2 at
#: 5 000; k = 9: 36 / 7.7 at 200, 13 / 6.9 at 1 000, 7.5 / 7.0 at 5 000
GAUSS_JORDAN_MAX_K = 6


def step_square(J, F, rcond):
    """Square k x k systems (k > 2, e.g. the conventional TCA): the step and the inverse from
    Gauss-Jordan elimination with partial pivoting over the batch (:func:`gauss_jordan`) for k up
    to :data:`GAUSS_JORDAN_MAX_K`, from LAPACK (:func:`lapack_inverse`) above, and instead of the
    singular values the bounds ||J||_F >= s_max and 1 / ||J^-1||_F <= s_min, whose ratio (the
    Frobenius condition number) is at most k times the 2-norm one. Rows where that ratio exceeds
    1 / rcond (only these can be singular; a zero pivot gives a non-finite inverse, which counts
    so) go through the SVD, which decides and gives them the pseudo-inverse step and their exact
    extreme singular values."""
    eliminate = gauss_jordan if J.shape[1] <= GAUSS_JORDAN_MAX_K else lapack_inverse
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        x, q_inv, q_J = eliminate(J, F)
        step = -x
        sv = np.stack([np.sqrt(q_J), 1.0 / np.sqrt(q_inv)], axis=-1)
        flagged = ~(sv[:, 1] > rcond * sv[:, 0])
    singular = np.zeros(len(J), dtype=bool)
    if flagged.any():
        idx = np.flatnonzero(flagged)
        step[idx], singular[idx], s = svd_step(J[idx], F[idx], rcond)
        sv[idx] = s[:, [0, -1]]
    return step, singular, sv


def gauss_jordan(J, F):
    """(x (n, k) = J^-1 F, ||J^-1||_F^2 (n,), ||J||_F^2 (n,)) of n square systems J (n, k, k),
    F (n, k) by Gauss-Jordan elimination with partial pivoting (per system the first row with the
    largest |entry| of the column, as LAPACK's idamax), in place on the augmented rows [J | F] held
    as k x (k + 1) contiguous 1-D arrays over the batch: a 5 x 5 batch costs about a sixth of
    numpy's batched inverse, which pays a LAPACK call per matrix. The inverse is formed in place
    with its columns in pivot order, which the Frobenius norm does not see; F's column follows the
    row swaps, so x needs no reordering. Sums of squares run left to right over the rows. A zero
    pivot gives inf/NaN in its system (callers test the norm). The written-out float form
    (:func:`gauss_jordan_source`) does the same operations in the same order, so one system gets
    the same values alone."""
    n, k = F.shape
    M = np.empty((k, k + 1, n))
    M[:, :k] = J.transpose(1, 2, 0)
    M[:, k] = F.T
    R = [[M[i, j] for j in range(k + 1)] for i in range(k)]
    tmp = np.empty(n)
    q_J = _sum_squares(R, k, tmp)
    for c in range(k):
        if c < k - 1:
            _pivot_rows(R, c, n)
        row = R[c]
        inv = 1.0 / row[c]
        row[c] = inv
        for j in range(k + 1):
            if j != c:
                row[j] *= inv
        for i in range(k):
            if i == c:
                continue
            ri = R[i]
            f = ri[c]
            for j in range(k + 1):
                if j != c:
                    np.multiply(f, row[j], out=tmp)
                    ri[j] -= tmp
            np.multiply(f, inv, out=f)
            np.negative(f, out=f)
    return np.stack([R[i][k] for i in range(k)], axis=-1), _sum_squares(R, k, tmp), q_J


def lapack_inverse(J, F):
    """:func:`gauss_jordan`'s (x = J^-1 F, ||J^-1||_F^2, ||J||_F^2) from LAPACK's inverse
    (``numpy.linalg.inv``, LU with partial pivoting, one call for the batch). A batch in which
    LAPACK meets an exactly singular system is inverted system by system, the singular ones
    (or non-finite) infinite, so every system gets the values it gets alone."""
    try:
        inv = np.linalg.inv(J)
    except np.linalg.LinAlgError:
        inv = np.empty_like(J)
        for i, Ji in enumerate(J):
            try:
                inv[i] = np.linalg.inv(Ji)
            except np.linalg.LinAlgError:
                inv[i] = np.inf
    x = (inv @ F[:, :, None])[:, :, 0]
    return x, np.einsum("nij,nij->n", inv, inv), np.einsum("nij,nij->n", J, J)


def _sum_squares(R, k, tmp):
    """Sum of the squares of the first k columns of the rows R (1-D arrays), row by row."""
    q = np.zeros(len(tmp))
    for i in range(k):
        for j in range(k):
            np.multiply(R[i][j], R[i][j], out=tmp)
            q += tmp
    return q


def _pivot_rows(R, c, n):
    """Partial pivoting of column ``c`` of the rows ``R`` (lists of 1-D arrays): per system, the
    first row i >= c with the largest |R[i][c]| is swapped with row c (a plain list swap where
    every system picks the same one, else by np.where)."""
    best = np.abs(R[c][c])
    cand = np.empty(n)
    idx = None
    for i in range(c + 1, len(R)):
        np.abs(R[i][c], out=cand)
        more = cand > best
        if more.any():
            if idx is None:
                idx = np.full(n, c)
            idx[more] = i
            np.copyto(best, cand, where=more)
    if idx is None:
        return
    lo, hi = int(idx.min()), int(idx.max())
    if lo == hi:
        R[c], R[lo] = R[lo], R[c]
        return
    for i in range(c + 1, len(R)):
        s = idx == i
        if s.any():
            R[c], R[i] = (
                [np.where(s, b, a) for a, b in zip(R[c], R[i])],
                [np.where(s, a, b) for a, b in zip(R[c], R[i])],
            )


def step_floats(J, F, rcond, inverse_square):
    """:func:`step_batch` of one system given as lists (J rows, F): (step list, singular,
    condition number), on Python floats where a closed form applies (2 x 2; square with
    ``inverse_square``, k = 3 ... 6), else (and where the elimination meets a zero or non-finite
    pivot or cannot clear the system of singularity) by the batch step on a batch of one; a 2 x 2
    system the closed form finds singular takes the SVD step, as in a batch."""
    m, k = len(J), len(J[0])
    out = None
    if m == k == 2:
        out = step_2x2_floats(J, F, rcond)
        if out is None:  # singular by the closed form: the SVD's pseudo-inverse step, as in a batch
            d, _, s = svd_step(np.array([J], dtype=float), np.array([F], dtype=float), rcond)
            return d[0].tolist(), True, _ratio(float(s[0, 0]), float(s[0, -1]))
    elif m == k and inverse_square:
        out = step_square_floats(J, F, rcond)
    if out is not None:
        return out[0], False, _ratio(out[1], out[2])
    d, singular, sv = step_batch(np.array([J], dtype=float), np.array([F], dtype=float), rcond, inverse_square)
    return d[0].tolist(), bool(singular[0]), _ratio(float(sv[0, 0]), float(sv[0, -1]))


def step_2x2_floats(J, F, rcond):
    """:func:`step_2x2` of one system by the same operations on Python floats (np.hypot kept):
    (step, s1, s2), or None where the closed form finds the system singular."""
    (a, b), (c, d) = J
    f0, f1 = F
    s1 = float(np.hypot(0.5 * (a + d), 0.5 * (c - b))) + float(np.hypot(0.5 * (a - d), 0.5 * (c + b)))
    det = a * d - b * c
    s2 = abs(det) / s1 if s1 > 0 else 0.0
    if not (s2 > rcond * s1):
        return None
    return [-(d * f0 - b * f1) / det, -(a * f1 - c * f0) / det], s1, s2


def step_square_floats(J, F, rcond):
    """:func:`step_square` of one system by the same operations on Python floats (the elimination
    written out for its size, :data:`GAUSS_JORDAN_FLOATS`): (step, fro, s2), or None where it
    needs the SVD, meets a zero or non-finite pivot or has no written-out elimination."""
    eliminate = GAUSS_JORDAN_FLOATS.get(len(F))
    if eliminate is None:
        return None
    try:
        x, q_inv, q_J = eliminate(J, F)
    except ArithmeticError:
        return None
    fro = math.sqrt(q_J)
    s2 = 1.0 / math.sqrt(q_inv) if q_inv > 0.0 else (math.inf if q_inv == 0.0 else math.nan)
    if not (s2 > rcond * fro):
        return None
    return [-v for v in x], fro, s2


def gauss_jordan_source(k: int) -> str:
    """Source of ``gauss_jordan_<k>(J, F) -> (x, ||J^-1||_F^2, ||J||_F^2)``: :func:`gauss_jordan`
    of one k x k system on Python floats (J a list of k rows, F a list), written out for the size
    k: the same operations in the same order (rows [J | F] swapped in a list for the pivots, the
    inverse formed in place column by column, sums of squares left to right). ZeroDivisionError on
    a zero pivot."""
    r = range(k)
    lines = [
        f"def gauss_jordan_{k}(J, F):",
        f"    R = [J[i] + [F[i]] for i in range({k})]",
        *_sum_squares_lines("q_J", k),
    ]
    for c in r:
        lines.append(f"    # column {c}")
        if c < k - 1:  # partial pivoting: the first row with the largest |entry| (LAPACK's idamax)
            lines.append(f"    p, best = {c}, abs(R[{c}][{c}])")
            for i in range(c + 1, k):
                lines += [f"    a = abs(R[{i}][{c}])", f"    if a > best: p, best = {i}, a"]
            lines.append(f"    if p != {c}: R[{c}], R[p] = R[p], R[{c}]")
        lines += [f"    a = R[{c}]", f"    inv = 1.0 / a[{c}]"]
        scaled = ", ".join("inv" if j == c else f"a[{j}] * inv" for j in range(k + 1))
        lines.append(f"    b = R[{c}] = [{scaled}]")
        for i in (i for i in r if i != c):
            eliminated = ", ".join("-(f * inv)" if j == c else f"a[{j}] - f * b[{j}]" for j in range(k + 1))
            lines += [f"    a = R[{i}]", f"    f = a[{c}]", f"    R[{i}] = [{eliminated}]"]
    lines += _sum_squares_lines("q_inv", k)
    lines.append("    return [" + ", ".join(f"R[{i}][{k}]" for i in r) + "], q_inv, q_J")
    return "\n".join(lines) + "\n"


def _sum_squares_lines(name, k):
    """Source lines of :func:`_sum_squares` on the float rows R (same order)."""
    lines = [f"    {name} = 0.0"]
    for i in range(k):
        lines.append(f"    {name} = {name} + " + " + ".join(f"R[{i}][{j}] * R[{i}][{j}]" for j in range(k)))
    return lines


def _compile_gauss_jordan(k: int):
    """The function of :func:`gauss_jordan_source` for size ``k``, its source registered with
    :mod:`linecache` under the file name ``<gearrep.solve gauss_jordan_<k>>``."""
    source = gauss_jordan_source(k)
    filename = f"<gearrep.solve gauss_jordan_{k}>"
    linecache.cache[filename] = (len(source), None, source.splitlines(keepends=True), filename)
    namespace: dict = {}
    exec(compile(source, filename, "exec"), namespace)  # noqa: S102 (source written above from ints only)
    return namespace[f"gauss_jordan_{k}"]


#: the written-out eliminations of one system on floats, by size, compiled at import (5 ms): the
#: library's square solves have 4 unknowns (loaded contact) and 5 (conventional TCA); a system of
#: another size takes the batch elimination on a batch of one
GAUSS_JORDAN_FLOATS = {k: _compile_gauss_jordan(k) for k in range(3, 7)}
