"""Bevel pairs: intersecting axes, the thesis's bevel misalignments (eq 47-48) and the explicit
spherical form of member 2 for the reduced formulation (thesis sec 3.3, eq 45).

Frames (fixed frame S_f, apex of member 1 at the origin)
-------------------------------------------------------
Member 1 turns about z_f: r_f = Rz(phi1) r_1(u1, v1), as in :class:`~gearrep.tca.GearPair`.
Member 2 turns about its own axis through its apex O2:
    r_f = O2 + A2 Rz(phase2 - phi2) r_2(u2, v2),   A2 = Ry(Sigma - d_gamma),
so its axis A2 z lies in the x_f z_f plane at the shaft angle Sigma_o = Sigma - d_gamma from z_f
(eq 48; the pivot of the shaft-angle change is the common apex). With the tooth of each member
centred on its own x axis, the pitch line of the aligned pair lies in the x_f z_f plane between the
axes, at azimuth 0 of member 1 and azimuth pi of member 2 (the same layout as the cylindrical pair,
whose centre line is x_f), so the default ``phase2 = pi - side pi / N2`` of GearPair applies and the
aligned standard pair is in conjugate mesh at phi1 = phi2 = 0. As for parallel axes, phi1 = 0 is not
the pitch-point contact: with tooth 1 centred on the pitch line its flank touches off the pitch cone
(0.59 deg of polar angle for the thesis's straight 39/32 pair, 1.30 deg for the spiral 17/17 pair);
the contact lies on the pitch cone half a tooth angle away, phi1 = -side pi/(2 N1) for these standard
teeth. phi2 > 0 turns member 2 about
w2 = -A2 z (the driven sense), so TE (eq 14) keeps its meaning.

Misalignment (eq 47: a_12 = (dA, dE, dG)), all as a displacement of member 2's apex:
    O2 = dE y_f + dG (A2 z) - dA z_f.
``d_E`` offsets member 2 along the common perpendicular y_f of the axes (the axes then cross: the
"centre distance" error of sec 5.1 and the y-axis error of sec 5.2); ``d_G`` moves member 2 along
its own axis (the gear's axial error; sec 5.2's z-axis error dH is read as this one);
``d_A`` is member 1's axial displacement along its axis, applied as the opposite displacement of
member 2 (the relative position, the contact on both flanks and the TE are the same; positions in
S_f are then measured from member 1's displaced apex). The thesis states neither the pivot nor the
signs: positive values move member 2's apex along +y_f, along its own axis away from its teeth
(+A2 z) and member 1 along +z_f.

Reduced formulation for member 2 in explicit form about its own axis
-------------------------------------------------------------------
Member 2 is a :class:`~gearrep.surfaces.bevel.SphericalInvoluteFlank`,
    r_2(u, v) = v (sin u cos psi(u, v), sin u sin psi(u, v), cos u),
with u the polar angle from its axis and v the cone distance. This is explicit about the axis in
the sense of eq (35)-(36): the azimuth psi is a function of the two coordinates that a rotation
about the axis leaves unchanged. Hence for a point s = Rz(-phase2) A2^T (r_f1 - O2) of member 1
(member-2 axis frame, before the turn by phi2):
    v2 = |s|,   u2 = acos(s_z / |s|) = atan2(sqrt(s_x^2 + s_y^2), s_z),
    phi2 = psi(u2, v2) - atan2(s_y, s_x)  (on the branch nearest (N1/N2) phi1).
With a common apex (no dA, dE, dG) |s| = |r_f1| = v1, and u2 is eq (45) with the spherical
cosine rule; under offsets eq (45) no longer holds, the relations above do. The derivatives with
respect to (u1, v1) follow from those of rho = sqrt(s_x^2 + s_y^2) and s_z:
dv2 = (rho drho + s_z ds_z)/|s|, du2 = (s_z drho - rho ds_z)/|s|^2. The implementation reuses the cylindrical kernel of the reduced
formulation on the same flank written in its axis-frame cylindrical coordinates (rho, z)
(:class:`~gearrep.surface.AxialForm`: u = atan2(rho, z), v = hypot(rho, z), the same
surface and normal) and maps (rho2, z2) to (u2, v2) with those relations, so both formulations
report member 2 in the thesis's (u2, v2).
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import numpy as np

from ..frames import rot_y, rot_z
from ..inputs import check_finite
from ..surface import AxialForm
from ._pair import GearPair

__all__ = ["BevelMisalignment", "BevelPair", "spherical_unknowns"]


@dataclass(frozen=True)
class BevelMisalignment:
    """Assembly errors of a bevel pair (thesis eq 47-48; frames in :mod:`gearrep.tca._bevel`).

    Parameters
    ----------
    d_A : float, optional
        Axial displacement of member 1 along its axis [length].
    d_E : float, optional
        Offset of member 2 along the common perpendicular y_f of the axes [length].
    d_G : float, optional
        Axial displacement of member 2 along its own axis [length].
    d_gamma : float, optional
        Shaft-angle change [rad], Sigma_o = Sigma - d_gamma, pivot at the apex; ``|d_gamma| < 0.5``.

    Raises
    ------
    ValueError
        If a value is not finite or ``d_gamma`` is not a small angle.

    Examples
    --------
    >>> import math
    >>> from gearrep.tca import BevelMisalignment
    >>> BevelMisalignment(d_E=0.01, d_gamma=math.radians(0.05)).d_E  # mm, rad
    0.01
    """

    d_A: float = 0.0
    d_E: float = 0.0
    d_G: float = 0.0
    d_gamma: float = 0.0

    def __post_init__(self):
        for n in ("d_A", "d_E", "d_G", "d_gamma"):
            check_finite(n, getattr(self, n))
        if abs(self.d_gamma) >= 0.5:
            raise ValueError(f"d_gamma must be a small angle, |d_gamma| < 0.5 rad, got {self.d_gamma!r}")


class BevelPair(GearPair):
    """Two bevel flanks on intersecting axes (shaft angle ``shaft_angle``), with
    :class:`BevelMisalignment`. Same interface as :class:`~gearrep.tca.GearPair` (every solve of
    :mod:`gearrep.tca` accepts it); ``centre_distance`` is 0. The reduced formulation needs
    ``flank2.spherical`` (u = polar angle, v = cone distance).

    Parameters
    ----------
    flank1, flank2 : gearrep.surface.Surface
        The bevel flanks (cone apex at the origin of each member's frame).
    n1, n2 : int
        Numbers of teeth.
    shaft_angle : float, optional
        Angle between the axes [rad], in (0, pi).
    misalignment : BevelMisalignment, optional
        Assembly errors (None: aligned).
    phase2 : float, optional
        Fixed turn of member 2 in its frame [rad] (as :class:`~gearrep.tca.GearPair`).

    Raises
    ------
    ValueError
        If the shaft angle is out of range, ``misalignment`` is not a :class:`BevelMisalignment`,
        or a tooth number is bad.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.bevel import BevelGearData, mating_bevel_flanks
    >>> from gearrep.surfaces.involute import ParabolicCrowning
    >>> from gearrep.tca import BevelMisalignment, BevelPair, solve_contact
    >>> g1 = BevelGearData(20, 40, 3.0, math.radians(20), 10.0)  # teeth, mate's teeth, mm, rad, mm
    >>> g2 = BevelGearData(40, 20, 3.0, math.radians(20), 10.0)
    >>> f1, f2 = mating_bevel_flanks(g1, g2)
    >>> v_mid = float(f1.lower[1] + f1.upper[1]) / 2  # mean cone distance [mm]
    >>> f1, f2 = mating_bevel_flanks(g1, g2, crowning1=ParabolicCrowning(1e-3, v0=v_mid))
    >>> pair = BevelPair(f1, f2, 20, 40, misalignment=BevelMisalignment(d_E=0.01))  # 90 deg shaft angle
    >>> c = solve_contact(pair, [0.0])  # phi1 [rad]
    >>> c.status_name.tolist(), round(float(c.te_arcsec[0]), 3)  # TE [arcsec]
    (['converged'], -37.104)
    """

    _INTERSECTING_AXES = True

    def __init__(
        self, flank1, flank2, n1: int, n2: int, *, shaft_angle: float = np.pi / 2, misalignment=None, phase2=None
    ):
        S = float(shaft_angle)
        if not (np.isfinite(S) and 0.0 < S < np.pi):
            raise ValueError(f"shaft_angle must be in (0, pi) rad, got {shaft_angle!r}")
        mis = BevelMisalignment() if misalignment is None else misalignment
        if not isinstance(mis, BevelMisalignment):
            raise ValueError("misalignment must be a BevelMisalignment or None")
        # tooth numbers, flanks, bounds, signs and phase2 as for parallel axes; then the bevel frame
        super().__init__(flank1, flank2, n1, n2, 1.0, phase2=phase2)
        self.centre_distance = 0.0
        self.misalignment = mis
        self.shaft_angle = S
        self.A2 = rot_y(S - mis.d_gamma)
        self.O2 = np.array([0.0, mis.d_E, 0.0]) + mis.d_G * self.A2[:, 2] - np.array([0.0, 0.0, mis.d_A])
        self.w2 = -self.A2[:, 2]
        self._Q = rot_z(-self.phase2) @ self.A2.T
        self._axial = None

    def with_misalignment(self, misalignment) -> BevelPair:
        return BevelPair(
            self.flank1,
            self.flank2,
            self.n1,
            self.n2,
            shaft_angle=self.shaft_angle,
            misalignment=misalignment,
            phase2=self.phase2,
        )

    @property
    def axial_view(self) -> BevelPair:
        """The same pair with member 2 in its axis-frame cylindrical coordinates (AxialForm)."""
        if self._axial is None:
            view = copy.copy(self)
            view.flank2 = AxialForm(self.flank2)
            view._axial = None
            self._axial = view
        return self._axial


def spherical_unknowns(K: dict, derivs: bool = True, v_column: bool = True) -> dict:
    """Member 2's spherical unknowns from the cylindrical back-substitution on the axial view (module
    docstring): (rho2, z2) = (u2, v2) of ``K`` -> (u2, v2) = (atan2(rho2, z2), |s|), with the
    derivatives (suffix ``_u``, and ``_v`` with ``v_column``) by the chain rule. ``K`` is the
    structure-of-arrays dict of :func:`gearrep.tca._kernels._reduced3`; it is updated in place."""
    rho, z = K["u2"], K["v2"]
    if type(rho) is float and type(z) is float:  # one point on Python floats
        v = math.hypot(rho, z)
        K["u2"], K["v2"] = math.atan2(rho, z), v
    else:
        v = np.hypot(rho, z)
        K["u2"], K["v2"] = np.arctan2(rho, z), v
    if derivs:
        for j in ("_u", "_v") if v_column else ("_u",):
            drho, dz = K["du2" + j], K["dv2" + j]
            K["du2" + j] = (z * drho - rho * dz) / (v * v)
            K["dv2" + j] = (rho * drho + z * dz) / v
    return K
