"""The records of an envelope (private module of :mod:`gearrep.envelope`, whose docstring gives
the family, the equations of meshing and the singular points): the local geometry at a batch of
parameter points, and the generated points with their solve record.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .solve import SolveResult
from .surface import SurfacePoint

__all__ = ["LocalGeometry", "EnvelopeResult"]


@dataclass(frozen=True)
class LocalGeometry:
    """Local quantities at a batch of parameter points q (n, 2+k); every vector in the tool
    frame S_1 (rotate by M[:, :3, :3] into S_2). Returned by :meth:`Envelope.local`.

    Parameters
    ----------
    M : numpy.ndarray
        (n, 4, 4) the motion M_21.
    tool : gearrep.surface.SurfacePoint
        Tool point [length] and derivatives in S_1.
    N, n : numpy.ndarray
        (n, 3) r_u x r_v and the unit normal.
    w, omega : numpy.ndarray
        (n, k, 3) relative velocities v^(12, j) and angular velocities.
    Xr : numpy.ndarray
        (n, k, k, 3) M^-1 d2M_ij r_h (direction part).
    f : numpy.ndarray
        (n, k) meshing functions (unit normal).
    J : numpy.ndarray
        (n, k, 2+k) Jacobian of f in q.
    T, H : numpy.ndarray
        (n, 2+k, 3) dr_2/dq and (n, 2+k, 2+k, 3) d^2 r_2/dq dq in S_1.
    n_q : numpy.ndarray
        (n, 2+k, 3) dn/dq in S_1: (n_u, n_v) of the tool, omega_j x n of the motion.

    Examples
    --------
    >>> import math
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0))  # rad, r_p mm
    >>> loc = env.local([[1.0, 0.0, 0.0]])  # u [mm], v [mm], phi [rad]
    >>> loc.M.shape, loc.f.shape, loc.J.shape
    ((1, 4, 4), (1, 1), (1, 1, 3))
    """

    M: np.ndarray  # (n,4,4)
    tool: SurfacePoint  # tool point and derivatives in S_1
    N: np.ndarray  # (n,3) r_u x r_v
    n: np.ndarray  # (n,3) unit normal
    w: np.ndarray  # (n,k,3) relative velocities v^(12,j)
    omega: np.ndarray  # (n,k,3) relative angular velocities
    Xr: np.ndarray  # (n,k,k,3) M^-1 d2M_ij r_h (direction part)
    f: np.ndarray  # (n,k) meshing functions (unit normal)
    J: np.ndarray  # (n,k,2+k) Jacobian of f in q
    T: np.ndarray  # (n,2+k,3) dr_2/dq in S_1
    H: np.ndarray  # (n,2+k,2+k,3) d^2 r_2/dq dq in S_1
    n_q: np.ndarray  # (n,2+k,3) dn/dq in S_1: (n_u, n_v) of the tool, omega_j x n of the motion

    @cached_property
    def in_member_frame(self) -> tuple:
        """(point, dpoint/dq (n, 2+k, 3), normal, dnormal/dq (n, 2+k, 3)) in the generated member's
        frame S_2 (the tool frame's vectors turned by M), formed once per local geometry (a solve's
        record evaluates the converged iterate again: :data:`_RECENT`); read-only arrays."""
        R = self.M[:, :3, :3]
        out = (
            (R @ self.tool.r[:, :, None])[:, :, 0] + self.M[:, :3, 3],
            self.T @ np.swapaxes(R, 1, 2),
            (R @ self.n[:, :, None])[:, :, 0],
            self.n_q @ np.swapaxes(R, 1, 2),
        )
        for a in out:
            a.flags.writeable = False
        return out


@dataclass(frozen=True)
class EnvelopeResult:
    """Points of an envelope with their generating parameters and the solve record.

    Parameters
    ----------
    names : tuple of str
        Parameter names, ("u", "v") + motion names.
    params : numpy.ndarray
        (n, 2 + k) generating parameters q = (u, v, m) (last iterate where not converged).
    point : numpy.ndarray
        (n, 3) generated point in S_2 [length].
    normal : numpy.ndarray
        (n, 3) unit tool normal n_1 = unit(r_u x r_v) carried into S_2 (the common normal).
    tangents : numpy.ndarray
        (n, 2, 3) derivatives of the generated point in the two free parameters (S_2).
    singular_measure : numpy.ndarray
        (n,) smallest / largest singular value of Litvin's (2+k)-square matrix with unit-scaled
        rows (0 at a singular point of the generated surface).
    singular : numpy.ndarray
        (n,) singular_measure < singular_tol.
    litvin_det : numpy.ndarray
        (n,) determinant of that matrix (tangential components in the basis t1 = unit(r_u),
        t2 = n x t1); changes sign across Litvin's limiting line.
    solve : gearrep.solve.SolveResult
        The solve of the solved parameters.

    Examples
    --------
    >>> import math
    >>> import numpy as np
    >>> from gearrep.envelope import Envelope, rack_generation_motion
    >>> from gearrep.surfaces.rack import StraightRackCutter
    >>> env = Envelope(StraightRackCutter(math.radians(20)), rack_generation_motion(30.0))  # rad, r_p mm
    >>> rec = env.solve([0.0, 1.0], 0.0, guess=0.0)  # u [mm], v [mm]; phi [rad] solved
    >>> len(rec), rec.converged.tolist(), np.round(rec.param("phi"), 6).tolist()  # rad
    (2, [True, True], [0.0, 0.09746])
    """

    names: tuple[str, ...]
    params: np.ndarray
    point: np.ndarray
    normal: np.ndarray
    tangents: np.ndarray
    singular_measure: np.ndarray
    singular: np.ndarray
    litvin_det: np.ndarray
    solve: SolveResult

    def param(self, name: str) -> np.ndarray:
        """Column of ``params`` by name.

        Parameters
        ----------
        name : str
            One of ``names``.

        Returns
        -------
        numpy.ndarray
            (n,) values.

        Raises
        ------
        ValueError
            If ``name`` is not a parameter.
        """
        if name not in self.names:
            raise ValueError(f"name must be one of {self.names}, got {name!r}")
        return self.params[:, self.names.index(name)]

    @property
    def status(self) -> np.ndarray:
        """(n,) :class:`gearrep.solve.Status` codes of the solve."""
        return self.solve.status

    @property
    def residual(self) -> np.ndarray:
        """(n,) meshing residuals of the solve."""
        return self.solve.residual

    @property
    def iterations(self) -> np.ndarray:
        """(n,) Newton iterations of the solve."""
        return self.solve.iterations

    @property
    def converged(self) -> np.ndarray:
        """(n,) bool, status CONVERGED."""
        return self.solve.converged

    def __len__(self) -> int:
        return self.params.shape[0]
