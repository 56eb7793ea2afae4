"""A fixed 3 x 3 matrix (and translation) applied to vectors given by components (structure of
arrays): the mountings of the TCA members. Public names of :mod:`gearrep.frames`; this module is
their home."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["matrix_applier", "apply_matrix"]


def matrix_applier(M, t=None):
    """The map v -> M v (+ t) for ONE fixed 3 x 3 matrix ``M`` (the mounting of a member, say) on
    vectors given by components (3-tuples of broadcastable arrays or floats): each component the
    sum of its three products left to right (plus t), no (n, 3, 3) stack built. Prepared once (the
    matrix is checked here), applied many times; floats in give floats out. ``t``: optional fixed
    3-vector. (Leaving out the zero and +-1 entries, by a function built from a string, saved
    0.4-2.8 % of a single-point contact solve of the README pair at load 0.2 and nothing
    measurable at load 4.6 (0.95-1.11 both ways), with the same contacts bit for bit.)

    Parameters
    ----------
    M : (3, 3) array_like
        One finite matrix.
    t : (3,) array_like, optional
        A finite translation.

    Returns
    -------
    callable
        v -> M v (+ t) on 3-tuples of components.

    Raises
    ------
    ValueError
        If ``M`` is not one finite 3 x 3 matrix or ``t`` not a finite 3-vector.

    Examples
    --------
    >>> from gearrep.frames import matrix_applier, rot_z
    >>> shift = matrix_applier(rot_z(0.0), t=(1.0, 2.0, 3.0))
    >>> shift((1.0, 1.0, 1.0))
    (2.0, 3.0, 4.0)
    """
    M = np.asarray(M, dtype=float)
    if M.shape != (3, 3) or not np.all(np.isfinite(M)):
        raise ValueError(f"M must be one finite 3x3 matrix, got shape {M.shape}")
    tt = (0.0, 0.0, 0.0) if t is None else tuple(float(x) for x in np.asarray(t, dtype=float).reshape(3))
    if not all(math.isfinite(x) for x in tt):
        raise ValueError(f"t must be a finite 3-vector, got {t!r}")
    (a, b, c), (d, e, f), (g, h, i) = M.tolist()
    if not any(tt):

        def apply(v):
            x, y, z = v
            return (a * x + b * y + c * z, d * x + e * y + f * z, g * x + h * y + i * z)

        return apply
    t0, t1, t2 = tt

    def apply_shifted(v):
        x, y, z = v
        return (a * x + b * y + c * z + t0, d * x + e * y + f * z + t1, g * x + h * y + i * z + t2)

    return apply_shifted


def apply_matrix(M, v, t=None):
    """M v (+ t) for one fixed 3 x 3 matrix and a vector by components (:func:`matrix_applier`).

    Parameters
    ----------
    M : (3, 3) array_like
        One finite matrix.
    v : tuple
        (x, y, z) components.
    t : (3,) array_like, optional
        A translation.

    Returns
    -------
    tuple
        The components of M v (+ t).

    Raises
    ------
    ValueError
        As :func:`matrix_applier`.

    Examples
    --------
    >>> from gearrep.frames import apply_matrix
    >>> apply_matrix([[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], (1.0, 1.0, 1.0))
    (2.0, 1.0, 1.0)
    """
    return matrix_applier(M, t)(v)
