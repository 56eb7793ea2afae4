"""Shared test cases for test_envelope.py and test_curvature_relations.py (envelope engineer).

Tool surfaces with analytic derivatives and two-parameter motions whose envelopes are known in
closed form:

* a cylinder of radius rho whose axis is carried tangentially over a torus (axis tilted by
  gamma from the parallel circle): the envelope is the offset torus with tube radius r0 + rho
  (a cylinder about a line tangent to a surface S at p touches the offset S_rho at p + rho n);
* a plane moved by its support function h(n) = sqrt(a^2 n_x^2 + b^2 n_y^2 + c^2 n_z^2): the
  envelope is the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1;
* a ZA-hob-like Archimedean thread cut into a gear by hob spin theta (gear turning theta/N) and
  a swivel psi about an axis parallel to the centre-distance line, R_c from the hob centre
  (the two-parameter generation of seed 000; no closed form, cross-checked against direct
  differential geometry).
"""

from __future__ import annotations

import numpy as np

from gearrep.envelope import ChainMotion, FunctionMotion, fixed, rotation, translation
from gearrep.surface import Surface, SurfacePoint

try:
    from gearrep.curvature import principal_curvatures as _pc
except ImportError:  # until gearrep.curvature exists
    _pc = None


def principal(p: SurfacePoint):
    """(k1, k2, e1, e2, normal) of gearrep.curvature.principal_curvatures (private fallback with
    the same convention until that module exists)."""
    if _pc is not None:
        r = _pc(p)
        return r.k1, r.k2, r.e1, r.e2, r.normal
    from gearrep.curvature_relations import _principal

    return _principal(p)


def principal_wrt(p: SurfacePoint, normal):
    """Principal curvatures of p re-signed for the given normal orientation (k1 >= k2)."""
    k1, k2, e1, e2, n = principal(p)
    s = np.sign(np.sum(n * normal, axis=-1))
    return np.where(s > 0, k1, -k2), np.where(s > 0, k2, -k1)


class Cylinder(Surface):
    """r = (rho cos u, rho sin u, v); normal outward."""

    def __init__(self, rho):
        self.rho = rho

    def position(self, u, v):
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        return np.stack([self.rho * np.cos(u), self.rho * np.sin(u), v], -1)

    def evaluate(self, u, v):
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        z = np.zeros_like(u)
        r = self.position(u, v)
        ru = np.stack([-self.rho * np.sin(u), self.rho * np.cos(u), z], -1)
        rv = np.stack([z, z, z + 1], -1)
        ruu = np.stack([-self.rho * np.cos(u), -self.rho * np.sin(u), z], -1)
        return SurfacePoint(r, ru, rv, ruu, np.zeros_like(r), np.zeros_like(r))


class Plane(Surface):
    """r = (u, v, 0); normal +z."""

    def position(self, u, v):
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        return np.stack([u, v, 0 * u], -1)

    def evaluate(self, u, v):
        r = self.position(u, v)
        o = np.zeros_like(r)
        ex, ey = o.copy(), o.copy()
        ex[..., 0] = 1.0
        ey[..., 1] = 1.0
        return SurfacePoint(r, ex, ey, o, o.copy(), o.copy())


# ---- torus ---------------------------------------------------------------------------------
TORUS = dict(R0=40.0, r0=12.0, rho=3.0, gamma=0.4)


def torus_motion(R0, r0, gamma, **_):
    """Cylinder frame -> torus frame: tool x axis = torus outward normal at (theta, psi), tool z
    axis (the cylinder axis) tilted by gamma from the parallel-circle direction."""
    d = np.array([0.0, np.cos(gamma), np.sin(gamma)])
    x = np.array([1.0, 0.0, 0.0])
    O = np.eye(4)
    O[:3, 0], O[:3, 1], O[:3, 2] = x, np.cross(d, x), d
    return ChainMotion(
        [
            rotation((0, 0, 1), [1, 0]),
            translation((1, 0, 0), [0, 0], offset=R0),
            rotation((0, 1, 0), [0, -1]),
            translation((1, 0, 0), [0, 0], offset=r0),
            fixed(O),
        ],
        names=("theta", "psi"),
    )


# ---- ellipsoid -----------------------------------------------------------------------------
ELLIPSOID_AXES = np.array([3.0, 2.0, 1.2])


def _rz(a):
    c, s, z, o = np.cos(a), np.sin(a), np.zeros_like(a), np.ones_like(a)
    return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)


def _ry(a):
    c, s, z, o = np.cos(a), np.sin(a), np.zeros_like(a), np.ones_like(a)
    return np.stack([np.stack([c, z, s], -1), np.stack([z, o, z], -1), np.stack([-s, z, c], -1)], -2)


def ellipsoid_motion(axes=ELLIPSOID_AXES):
    A2 = np.asarray(axes, float) ** 2

    def M(m):
        R = _rz(m[..., 0]) @ _ry(m[..., 1])
        n = R[..., :, 2]
        h = np.sqrt(np.sum(A2 * n * n, -1))
        out = np.zeros(m.shape[:-1] + (4, 4))
        out[..., :3, :3] = R
        out[..., :3, 3] = h[..., None] * n
        out[..., 3, 3] = 1.0
        return out

    return FunctionMotion(M, 2, ("theta", "psi"))


def ellipsoid_curvatures(X, axes=ELLIPSOID_AXES):
    """Closed-form principal curvatures (k1 >= k2) of the ellipsoid at points X, signed for the
    outward normal (negative): K = 1/(a^2 b^2 c^2 S^2), H = (|X|^2 - a^2 - b^2 - c^2) /
    (2 a^2 b^2 c^2 S^{3/2}), S = x^2/a^4 + y^2/b^4 + z^2/c^4."""
    A2 = np.asarray(axes, float) ** 2
    S = np.sum(X**2 / A2**2, -1)
    abc2 = np.prod(A2)
    K = 1.0 / (abc2 * S**2)
    H = (np.sum(X**2, -1) - A2.sum()) / (2 * abc2 * S**1.5)
    root = np.sqrt(np.maximum(H * H - K, 0.0))
    return H + root, H - root


# ---- ZA-hob-like two-parameter generation (seed 000 set-up, reconstructed) -------------------
HOB = dict(m=3.0, N=20, alpha=np.radians(20.0), r_h=30.0, R_c=110.0)


def hob_constants(m, N, alpha, r_h, R_c):
    lam = np.arcsin(m / (2 * r_h))
    r_t = r_h - (np.pi * m / 4) / np.tan(alpha)
    P = m / (2 * np.cos(lam))
    return lam, r_t, P, m * N / 2 + r_h


class ArchimedeanThread(Surface):
    """Straight line in the axial section at angle alpha, screwed with lead P per radian:
    r = ((r_t + l cos a) cos phi, -(r_t + l cos a) sin phi, l sin a - P phi)."""

    def __init__(self, r_t, alpha, P):
        self.r_t, self.alpha, self.P = r_t, alpha, P

    def position(self, l, p):
        l, p = np.broadcast_arrays(np.asarray(l, float), np.asarray(p, float))
        rr = self.r_t + l * np.cos(self.alpha)
        return np.stack([rr * np.cos(p), -rr * np.sin(p), l * np.sin(self.alpha) - self.P * p], -1)

    def evaluate(self, l, p):
        l, p = np.broadcast_arrays(np.asarray(l, float), np.asarray(p, float))
        ca, sa = np.cos(self.alpha), np.sin(self.alpha)
        rr = self.r_t + l * ca
        c, s, z = np.cos(p), np.sin(p), np.zeros_like(l)
        r = self.position(l, p)
        rl = np.stack([ca * c, -ca * s, z + sa], -1)
        rp = np.stack([-rr * s, -rr * c, z - self.P], -1)
        rlp = np.stack([-ca * s, -ca * c, z], -1)
        rpp = np.stack([-rr * c, rr * s, z], -1)
        return SurfacePoint(r, rl, rp, np.zeros_like(r), rlp, rpp)


def hob_case():
    lam, r_t, P, E = hob_constants(**HOB)
    tool = ArchimedeanThread(r_t, HOB["alpha"], P)
    motion = ChainMotion(
        [
            rotation((0, 0, 1), [1.0 / HOB["N"], 0.0]),  # gear turns theta/N
            rotation((1, 0, 0), [0.0, 1.0], point=(E, HOB["R_c"], 0.0)),  # swivel psi
            translation((1, 0, 0), [0.0, 0.0], offset=E),  # centre distance
            rotation((1, 0, 0), [0.0, 0.0], offset=-np.pi / 2 + lam),  # hob axis set at the lead angle
            rotation((0, 0, 1), [1.0, 0.0]),  # hob spin theta
        ],
        names=("theta", "psi"),
    )
    return tool, motion
