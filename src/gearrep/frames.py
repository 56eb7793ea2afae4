"""Coordinate transformations in Litvin's M_ij / L_ij notation, and misalignment set-ups.

Source: Litvin & Fuentes, *Gear Geometry and Applied Theory* (2nd ed.), ch. 1
("Coordinate transformation"): r_i = M_ij r_j with 4x4 homogeneous matrices M_ij, and
L_ij = the upper-left 3x3 block of M_ij for free vectors (normals, tangents). Misalignment
set-ups: seed 000 sect. 5.2 / Fig 5.1 (S_h rotated about X_h by dgamma_h relative to S_f,
S_v rotated about Y_h by dgamma_v relative to S_h, centre-distance change dC, axial error dZ
along the gear axis) and seed 002 sect. 2.8 / Fig 2.8.1 (shortest-distance change dE, shaft
angle change dgamma).

Conventions
-----------
* Right-handed Cartesian frames; all angles in radians.
* ``rot_x(a)``, ``rot_y(a)``, ``rot_z(a)`` are ACTIVE rotations by +a (counter-clockwise
  looking down the axis towards the origin): rot_z(a) @ (1, 0, 0) = (cos a, sin a, 0).
* M_ij maps coordinates of a point in frame S_j to its coordinates in frame S_i:
  r_i = M_ij r_j. Chains multiply left to right: M_ik = M_ij M_jk (:func:`compose`), and
  M_ji = M_ij^-1 (:func:`inverse`).
* If frame S_j is obtained from S_i by turning it through the angle phi about their common z
  axis (and translating its origin to t, given in S_i), then M_ij = homogeneous(rot_z(phi), t)
  and M_ji = homogeneous(rot_z(-phi), -rot_z(-phi) t). E.g. a gear frame S_1 rotating by phi_1
  about the fixed z_f axis: M_f1 = homogeneous(rot_z(phi_1)), M_1f = homogeneous(rot_z(-phi_1))
  (Litvin's M_1f has +sin phi_1 in row 1, column 2, i.e. rot_z(-phi_1)).
* Matrices are stacked over leading batch dimensions: an angle array of shape S gives
  (S, 3, 3) or (S, 4, 4); points (..., 3) broadcast against them.
"""

from __future__ import annotations

import math

import numpy as np

from ._applier import apply_matrix, matrix_applier

__all__ = [
    "rot_x",
    "rot_y",
    "rot_z",
    "drot_x",
    "drot_y",
    "drot_z",
    "rotation",
    "rotation_about_axis",
    "drotation_about_axis",
    "rotation_about_axis_with_derivatives",
    "axis_generators",
    "homogeneous",
    "translation",
    "compose",
    "transform_points",
    "transform_vectors",
    "inverse",
    "is_rigid",
    "rotation_about_line",
    "misalignment_rotation",
    "gear_mounting",
    "rotate_z",
    "apply_matrix",
    "matrix_applier",
]


def _rot(a, i, j):
    a = np.asarray(a, dtype=float)
    c, s = np.cos(a), np.sin(a)
    R = np.zeros(a.shape + (3, 3))
    k = 3 - i - j
    R[..., k, k] = 1.0
    R[..., i, i] = c
    R[..., j, j] = c
    R[..., i, j] = -s
    R[..., j, i] = s
    return R


def rot_x(a) -> np.ndarray:
    """Active rotation by ``a`` about x: [[1, 0, 0], [0, c, -s], [0, s, c]] (Litvin ch. 1).

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotation matrices.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_x
    >>> (np.round(rot_x(np.pi / 2), 12) + 0.0).tolist()
    [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
    """
    return _rot(a, 1, 2)


def rot_y(a) -> np.ndarray:
    """Active rotation by ``a`` about y: [[c, 0, s], [0, 1, 0], [-s, 0, c]] (Litvin ch. 1).

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotation matrices.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_y
    >>> (np.round(rot_y(np.pi / 2), 12) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    return _rot(a, 2, 0)


def rot_z(a) -> np.ndarray:
    """Active rotation by ``a`` about z: [[c, -s, 0], [s, c, 0], [0, 0, 1]] (Litvin ch. 1).

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotation matrices.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_z
    >>> (np.round(rot_z(np.pi / 2), 12) + 0.0).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    return _rot(a, 0, 1)


def _drot(a, i, j, order):
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2, got {order!r}")
    a = np.asarray(a, dtype=float)
    c, s = np.cos(a), np.sin(a)
    R = np.zeros(a.shape + (3, 3))
    if order == 1:  # d/da [[c, -s], [s, c]] = [[-s, -c], [c, -s]]
        R[..., i, i] = -s
        R[..., j, j] = -s
        R[..., i, j] = -c
        R[..., j, i] = c
    else:  # d2/da2 = [[-c, s], [-s, -c]]
        R[..., i, i] = -c
        R[..., j, j] = -c
        R[..., i, j] = s
        R[..., j, i] = -s
    return R


def drot_x(a, order: int = 1) -> np.ndarray:
    """Derivative d^order rot_x(a) / da^order (order 1 or 2), batched like :func:`rot_x`:
    order 1 [[0, 0, 0], [0, -s, -c], [0, c, -s]].

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).
    order : {1, 2}, optional
        The order of the derivative.

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) derivatives [1/rad^order].

    Raises
    ------
    ValueError
        If ``order`` is not 1 or 2.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import drot_x
    >>> (np.round(drot_x(0.0), 12) + 0.0).tolist()
    [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
    """
    return _drot(a, 1, 2, order)


def drot_y(a, order: int = 1) -> np.ndarray:
    """Derivative d^order rot_y(a) / da^order (order 1 or 2), batched like :func:`rot_y`:
    order 1 [[-s, 0, c], [0, 0, 0], [-c, 0, -s]].

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).
    order : {1, 2}, optional
        The order of the derivative.

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) derivatives [1/rad^order].

    Raises
    ------
    ValueError
        If ``order`` is not 1 or 2.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import drot_y
    >>> (np.round(drot_y(0.0), 12) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    return _drot(a, 2, 0, order)


def drot_z(a, order: int = 1) -> np.ndarray:
    """Derivative d^order rot_z(a) / da^order (order 1 or 2), batched like :func:`rot_z`:
    order 1 [[-s, -c, 0], [c, -s, 0], [0, 0, 0]].

    Parameters
    ----------
    a : float or array_like
        Angle [rad]; an array of shape S gives a stack (S, 3, 3).
    order : {1, 2}, optional
        The order of the derivative.

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) derivatives [1/rad^order].

    Raises
    ------
    ValueError
        If ``order`` is not 1 or 2.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import drot_z
    >>> (np.round(drot_z(0.0), 12) + 0.0).tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    """
    return _drot(a, 0, 1, order)


def rotation(axis: str, a) -> np.ndarray:
    """``rot_x``/``rot_y``/``rot_z`` selected by ``axis`` in {'x', 'y', 'z'}.

    Parameters
    ----------
    axis : {"x", "y", "z"}
        The axis.
    a : float or array_like
        Angle [rad].

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotation matrices.

    Raises
    ------
    ValueError
        If ``axis`` is not 'x', 'y' or 'z'.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_y, rotation
    >>> bool((rotation("y", 0.3) == rot_y(0.3)).all())
    True
    """
    try:
        return {"x": rot_x, "y": rot_y, "z": rot_z}[axis](a)
    except KeyError:
        raise ValueError(f"axis must be 'x', 'y' or 'z', got {axis!r}") from None


def _axis_generator(axis):
    """Cross-product matrix K of the unit direction of ``axis`` (..., 3): K x = unit(axis) x x."""
    k = np.asarray(axis, dtype=float)
    if k.ndim == 1:  # one axis (the common case, e.g. every factor of a motion chain): scalar work
        nrm = math.sqrt(float(k @ k)) if k.shape == (3,) else 0.0
        if nrm == 0.0:
            raise ValueError(f"axis must be a non-zero 3-vector, got {axis!r}")
        x, y, z = (float(e) / nrm for e in k)
        return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    nrm = np.linalg.norm(k, axis=-1, keepdims=True)
    if np.any(nrm == 0):
        raise ValueError("axis must be a non-zero vector")
    k = k / nrm
    K = np.zeros(k.shape[:-1] + (3, 3))
    K[..., 0, 1], K[..., 0, 2] = -k[..., 2], k[..., 1]
    K[..., 1, 0], K[..., 1, 2] = k[..., 2], -k[..., 0]
    K[..., 2, 0], K[..., 2, 1] = -k[..., 1], k[..., 0]
    return K


def rotation_about_axis(axis, a) -> np.ndarray:
    """Active rotation by ``a`` about the unit direction of ``axis`` (..., 3) (Rodrigues:
    R = I + sin a K + (1 - cos a) K^2, K the cross-product matrix of the unit axis). Batch
    dimensions of ``axis`` (without its last) and ``a`` broadcast.

    Parameters
    ----------
    axis : (..., 3) array_like
        Direction of the axis (any non-zero length).
    a : float or array_like
        Angle [rad].

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotation matrices.

    Raises
    ------
    ValueError
        If an axis is the zero vector.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rot_z, rotation_about_axis
    >>> bool(np.allclose(rotation_about_axis([0.0, 0.0, 2.0], 0.4), rot_z(0.4), rtol=0, atol=1e-15))
    True
    """
    K = _axis_generator(axis)
    a = np.asarray(a, dtype=float)
    s, c = np.sin(a)[..., None, None], np.cos(a)[..., None, None]
    return np.eye(3) + s * K + (1.0 - c) * (K @ K)


def drotation_about_axis(axis, a, order: int = 1) -> np.ndarray:
    """Derivative d^order R / da^order (order 1 or 2) of :func:`rotation_about_axis`:
    dR/da = cos a K + sin a K^2, d2R/da2 = -sin a K + cos a K^2.

    Parameters
    ----------
    axis : (..., 3) array_like
        Direction of the axis.
    a : float or array_like
        Angle [rad].
    order : {1, 2}, optional
        The order of the derivative.

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) derivatives [1/rad^order].

    Raises
    ------
    ValueError
        If ``order`` is not 1 or 2, or an axis is zero.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import drot_z, drotation_about_axis
    >>> bool(np.allclose(drotation_about_axis([0.0, 0.0, 1.0], 0.4), drot_z(0.4), rtol=0, atol=1e-15))
    True
    """
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2, got {order!r}")
    return rotation_about_axis_with_derivatives(axis, a)[order]


def axis_generators(axis):
    """(K, K^2): the cross-product matrix K of the unit direction of ``axis`` and its square, as
    :func:`rotation_about_axis_with_derivatives` forms them (pass them as ``generators`` where the
    same axis turns again and again, e.g. a factor of a motion chain).

    Parameters
    ----------
    axis : (..., 3) array_like
        Direction of the axis.

    Returns
    -------
    tuple of numpy.ndarray
        (K, K^2), each (..., 3, 3).

    Raises
    ------
    ValueError
        If an axis is zero.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import axis_generators
    >>> K, K2 = axis_generators([0.0, 0.0, 1.0])
    >>> K.tolist()
    [[0.0, -1.0, 0.0], [1.0, 0.0, -0.0], [-0.0, 0.0, 0.0]]
    """
    K = _axis_generator(axis)
    return K, K @ K


def rotation_about_axis_with_derivatives(axis, a, generators=None):
    """(R, dR/da, d2R/da2) of :func:`rotation_about_axis` in one evaluation (one generator K,
    one K^2, one sine and cosine): what a chain of rotations differentiated by the product rule
    needs at every step. ``generators``: :func:`axis_generators` of ``axis``, if the caller keeps
    them (the same values).

    Parameters
    ----------
    axis : (..., 3) array_like
        Direction of the axis.
    a : float or array_like
        Angle [rad].
    generators : tuple, optional
        :func:`axis_generators` of ``axis``.

    Returns
    -------
    tuple of numpy.ndarray
        (R, dR/da, d2R/da2), each (..., 3, 3).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rotation_about_axis_with_derivatives
    >>> R, dR, d2R = rotation_about_axis_with_derivatives([1.0, 0.0, 0.0], 0.0)
    >>> (np.round(dR, 12) + 0.0).tolist()  # the generator of x
    [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]
    """
    K, K2 = axis_generators(axis) if generators is None else generators
    a = np.asarray(a, dtype=float)
    s, c = np.sin(a)[..., None, None], np.cos(a)[..., None, None]
    return np.eye(3) + s * K + (1.0 - c) * K2, c * K + s * K2, -s * K + c * K2


def rotate_z(c, s, v):
    """rot_z(a) applied to a vector given by components (structure of arrays), with c = cos a and
    s = sin a given (computed once by the caller): (c v0 - s v1, s v0 + c v1, v2). ``v`` is a
    3-tuple of broadcastable arrays or floats; returns a 3-tuple.

    Parameters
    ----------
    c, s : float or array_like
        cos a and sin a.
    v : tuple
        (x, y, z) components.

    Returns
    -------
    tuple
        The rotated components.

    Examples
    --------
    >>> from gearrep.frames import rotate_z
    >>> rotate_z(0.0, 1.0, (1.0, 0.0, 5.0))  # a quarter turn
    (0.0, 1.0, 5.0)
    """
    v0, v1, v2 = v
    return (c * v0 - s * v1, s * v0 + c * v1, v2)


def homogeneous(R=None, t=None) -> np.ndarray:
    """4x4 homogeneous matrix [[R, t], [0 0 0 1]] (Litvin ch. 1). R (..., 3, 3) defaults to
    the identity, t (..., 3) to zero; batch dimensions broadcast.

    Parameters
    ----------
    R : (..., 3, 3) array_like, optional
        Rotation block.
    t : (..., 3) array_like, optional
        Translation [length].

    Returns
    -------
    numpy.ndarray
        (..., 4, 4) matrices.

    Raises
    ------
    ValueError
        If ``R`` or ``t`` has the wrong shape.

    Examples
    --------
    >>> from gearrep.frames import homogeneous
    >>> homogeneous(t=[1.0, 2.0, 3.0])[:3, 3].tolist()
    [1.0, 2.0, 3.0]
    """
    R = np.eye(3) if R is None else np.asarray(R, dtype=float)
    t = np.zeros(3) if t is None else np.asarray(t, dtype=float)
    if R.shape[-2:] != (3, 3):
        raise ValueError(f"R must have shape (..., 3, 3), got {R.shape}")
    if t.shape[-1:] != (3,):
        raise ValueError(f"t must have shape (..., 3), got {t.shape}")
    batch = np.broadcast_shapes(R.shape[:-2], t.shape[:-1])
    M = np.zeros(batch + (4, 4))
    M[..., :3, :3] = R
    M[..., :3, 3] = t
    M[..., 3, 3] = 1.0
    return M


def translation(t) -> np.ndarray:
    """Pure translation homogeneous(None, t).

    Parameters
    ----------
    t : (..., 3) array_like
        Translation [length].

    Returns
    -------
    numpy.ndarray
        (..., 4, 4) matrices.

    Examples
    --------
    >>> from gearrep.frames import transform_points, translation
    >>> transform_points(translation([1.0, 0.0, 0.0]), [0.0, 0.0, 0.0]).tolist()
    [1.0, 0.0, 0.0]
    """
    return homogeneous(None, t)


def compose(*M) -> np.ndarray:
    """Matrix product left to right: compose(M_ij, M_jk, M_kl) = M_il (Litvin ch. 1).

    Works for 4x4 or 3x3 stacks with broadcasting batch dimensions.

    Parameters
    ----------
    *M : array_like
        (..., 4, 4) or (..., 3, 3) matrices, at least one.

    Returns
    -------
    numpy.ndarray
        Their product.

    Raises
    ------
    ValueError
        If no matrix is given.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import compose, rot_z
    >>> bool(np.allclose(compose(rot_z(0.1), rot_z(0.2)), rot_z(0.3), rtol=0, atol=1e-15))
    True
    """
    if not M:
        raise ValueError("compose needs at least one matrix")
    out = np.asarray(M[0], dtype=float)
    for m in M[1:]:
        out = out @ np.asarray(m, dtype=float)
    return out


def transform_points(M, p) -> np.ndarray:
    """r_i = M_ij r_j for points p (..., 3) given in S_j; M (..., 4, 4) (or (..., 3, 3)
    for a pure rotation). Batch dimensions broadcast.

    Parameters
    ----------
    M : (..., 4, 4) or (..., 3, 3) array_like
        M_ij.
    p : (..., 3) array_like
        Points in S_j [length].

    Returns
    -------
    numpy.ndarray
        (..., 3) points in S_i.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import homogeneous, rot_z, transform_points
    >>> M = homogeneous(rot_z(np.pi / 2), [10.0, 0.0, 0.0])
    >>> np.round(transform_points(M, [[1.0, 0.0, 0.0]]), 12).tolist()
    [[10.0, 1.0, 0.0]]
    """
    M = np.asarray(M, dtype=float)
    p = np.asarray(p, dtype=float)
    out = np.einsum("...ij,...j->...i", M[..., :3, :3], p)
    if M.shape[-1] == 4:
        out = out + M[..., :3, 3]
    return out


def transform_vectors(M, v) -> np.ndarray:
    """Free vectors (normals, tangents, velocities): v_i = L_ij v_j with L_ij the 3x3 block of
    M_ij (Litvin ch. 1); the translation is ignored.

    Parameters
    ----------
    M : (..., 4, 4) or (..., 3, 3) array_like
        M_ij.
    v : (..., 3) array_like
        Free vectors in S_j.

    Returns
    -------
    numpy.ndarray
        (..., 3) vectors in S_i.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import homogeneous, rot_z, transform_vectors
    >>> M = homogeneous(rot_z(np.pi / 2), [10.0, 0.0, 0.0])
    >>> (np.round(transform_vectors(M, [1.0, 0.0, 0.0]), 12) + 0.0).tolist()
    [0.0, 1.0, 0.0]
    """
    M = np.asarray(M, dtype=float)
    return np.einsum("...ij,...j->...i", M[..., :3, :3], np.asarray(v, dtype=float))


def is_rigid(M, tol: float = 1e-10) -> np.ndarray:
    """True where the 3x3 block of M is a proper rotation (R^T R = I, det R = +1 within tol)
    and the last row is (0, 0, 0, 1).

    Parameters
    ----------
    M : (..., 4, 4) or (..., 3, 3) array_like
        Matrices.
    tol : float, optional
        Absolute tolerance of the entries.

    Returns
    -------
    numpy.ndarray of bool
        One per matrix.

    Examples
    --------
    >>> from gearrep.frames import is_rigid, rot_x
    >>> bool(is_rigid(rot_x(0.7))), bool(is_rigid(2.0 * rot_x(0.7)))
    (True, False)
    """
    M = np.asarray(M, dtype=float)
    R = M[..., :3, :3]
    orth = np.max(np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)), axis=(-2, -1)) <= tol
    ok = orth & (np.abs(np.linalg.det(R) - 1.0) <= tol)
    if M.shape[-1] == 4:
        ok &= np.max(np.abs(M[..., 3, :] - np.array([0, 0, 0, 1.0])), axis=-1) <= tol
    return ok


def inverse(M, check: bool = True, tol: float = 1e-10) -> np.ndarray:
    """Inverse of a rigid transform: M_ji = M_ij^-1 = [[R^T, -R^T t], [0, 1]] (Litvin ch. 1).

    3x3 input returns R^T. With ``check`` a ValueError is raised if M is not rigid (use
    numpy.linalg.inv for general matrices).

    Parameters
    ----------
    M : (..., 4, 4) or (..., 3, 3) array_like
        Rigid transforms.
    check : bool, optional
        Check that M is rigid first.
    tol : float, optional
        Tolerance of that check.

    Returns
    -------
    numpy.ndarray
        M^-1, of the shape of M.

    Raises
    ------
    ValueError
        With ``check``, if M is not rigid.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import compose, homogeneous, inverse, rot_y
    >>> M = homogeneous(rot_y(0.3), [1.0, 2.0, 3.0])
    >>> bool(np.allclose(compose(inverse(M), M), np.eye(4), rtol=0, atol=1e-15))
    True
    """
    M = np.asarray(M, dtype=float)
    if check and not np.all(is_rigid(M, tol)):
        raise ValueError("inverse: M is not a rigid transform (R^T R != I, det R != 1 or bad last row)")
    Rt = np.swapaxes(M[..., :3, :3], -1, -2)
    if M.shape[-1] == 3:
        return Rt.copy()
    return homogeneous(Rt, -np.einsum("...ij,...j->...i", Rt, M[..., :3, 3]))


def rotation_about_line(point, axis, a) -> np.ndarray:
    """Homogeneous active rotation by ``a`` about the line through ``point`` with direction
    ``axis``: x -> R (x - point) + point.

    Parameters
    ----------
    point : (..., 3) array_like
        A point of the line [length].
    axis : (..., 3) array_like
        Its direction.
    a : float or array_like
        Angle [rad].

    Returns
    -------
    numpy.ndarray
        (..., 4, 4) matrices.

    Raises
    ------
    ValueError
        If an axis is zero.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import rotation_about_line, transform_points
    >>> M = rotation_about_line([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], np.pi)  # half a turn about x = 1
    >>> (np.round(transform_points(M, [0.0, 0.0, 0.0]), 12) + 0.0).tolist()
    [2.0, 0.0, 0.0]
    """
    R = rotation_about_axis(axis, a)
    point = np.asarray(point, dtype=float)
    return homogeneous(R, point - np.einsum("...ij,...j->...i", R, point))


def misalignment_rotation(gamma_h=0.0, gamma_v=0.0, axes: str = "xy") -> np.ndarray:
    """Rotation L_fv of a misaligned frame S_v relative to the fixed frame S_f (seed 000
    Fig 5.1): S_h is turned about X_h (= X_f) by gamma_h relative to S_f, then S_v about Y_h
    by gamma_v relative to S_h, so L_fv = L_fh L_hv = rot_x(gamma_h) rot_y(gamma_v).

    ``axes`` = two letters naming the axes of the first and second rotation (default 'xy'
    as in seed 000); callers decide which is the "horizontal" / "vertical" one for their
    frames. Vectorised over angle arrays.

    Parameters
    ----------
    gamma_h, gamma_v : float or array_like, optional
        The two angles [rad].
    axes : str, optional
        Two different letters of 'xyz'.

    Returns
    -------
    numpy.ndarray
        (..., 3, 3) rotations L_fv.

    Raises
    ------
    ValueError
        If ``axes`` is not two different letters of 'xyz'.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import misalignment_rotation, rot_x, rot_y
    >>> L = misalignment_rotation(0.01, 0.02)
    >>> bool(np.allclose(L, rot_x(0.01) @ rot_y(0.02), rtol=0, atol=1e-15))
    True
    """
    if len(axes) != 2 or axes[0] == axes[1]:
        raise ValueError(f"axes must be two different letters of 'xyz', got {axes!r}")
    return rotation(axes[0], gamma_h) @ rotation(axes[1], gamma_v)


def gear_mounting(
    center_distance, *, d_center=0.0, d_axial=0.0, gamma_in_plane=0.0, gamma_out_of_plane=0.0, center_axis: str = "x"
) -> np.ndarray:
    """M_fq: coordinates in the (non-rotating) mounting frame S_q of a misaligned gear ->
    the fixed frame S_f of the pinion, for parallel-axis gears.

    Nominal set-up: the pinion axis is z_f through O_f; the gear axis is parallel to z_f and
    passes through O_q = C e_c, C = ``center_distance``, e_c = x_f (``center_axis`` = 'x') or
    y_f ('y') the centre-distance line. S_q coincides with S_f translated to O_q. Errors:

    * ``d_center`` (dC, seed 000; dE, seed 002): O_q moves to (C + dC) e_c;
    * ``gamma_in_plane``: rotation of the gear axis about the line through O_q normal to the
      plane of the axes (direction z_f x e_c). The axes stay coplanar (they intersect): this
      is the misalignment "in the plane of the axes";
    * ``gamma_out_of_plane``: rotation about the centre-distance line e_c through O_q. The axes
      become crossed (shaft-angle change dgamma of seed 002); "out of the plane of the axes";
    * ``d_axial`` (dZ, seed 000): the gear slides by dZ along its own (misaligned) axis z_q.

    M_fq = T((C + dC) e_c) R_in(gamma_in_plane) R_out(gamma_out_of_plane) T(dZ z), i.e. the
    in-plane rotation is applied about the fixed frame's axis and the out-of-plane one about
    the once-rotated centre line (to first order in small angles the order does not matter).
    The gear's own rotating frame S_2 then follows as M_f2 = M_fq @ homogeneous(rot_z(phi_2)).
    Which of the two angles a paper calls "horizontal" or "vertical" depends on its frame
    (seed 000 rotates about X_h then Y_h, see :func:`misalignment_rotation`); state it in the
    caller. Vectorised over array arguments.

    Parameters
    ----------
    center_distance : float or array_like
        C [length].
    d_center, d_axial : float or array_like, optional
        dC and dZ [length].
    gamma_in_plane, gamma_out_of_plane : float or array_like, optional
        The angular errors [rad].
    center_axis : {"x", "y"}, optional
        The centre-distance line e_c.

    Returns
    -------
    numpy.ndarray
        (..., 4, 4) matrices M_fq.

    Raises
    ------
    ValueError
        If ``center_axis`` is not 'x' or 'y'.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.frames import gear_mounting
    >>> M = gear_mounting(100.0, d_center=0.05)  # mm
    >>> M[:3, 3].tolist(), bool(np.allclose(M[:3, :3], np.eye(3)))
    ([100.05, 0.0, 0.0], True)
    """
    if center_axis not in ("x", "y"):
        raise ValueError(f"center_axis must be 'x' or 'y', got {center_axis!r}")
    C = np.asarray(center_distance, dtype=float) + np.asarray(d_center, dtype=float)
    zero = np.zeros_like(C)
    if center_axis == "x":
        origin = np.stack(np.broadcast_arrays(C, zero, zero), -1)
        R = rot_y(gamma_in_plane) @ rot_x(gamma_out_of_plane)
    else:
        # plane of axes = y-z plane; its normal z x y = -x: rotate about -x by gamma_in_plane
        origin = np.stack(np.broadcast_arrays(zero, C, zero), -1)
        R = rot_x(-np.asarray(gamma_in_plane, dtype=float)) @ rot_y(gamma_out_of_plane)
    dz = np.asarray(d_axial, dtype=float)
    axial = np.stack(np.broadcast_arrays(np.zeros_like(dz), np.zeros_like(dz), dz), -1)
    return compose(translation(origin), homogeneous(R), translation(axial))
