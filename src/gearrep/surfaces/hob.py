"""ZA worm-type hob cutter and the curvilinear-tooth gear it generates (two-parameter envelope).

Sources
-------
* Hob thread surface: seed 000 eq 4.40 (position), 4.41 (normal N_1 = r_l x r_phi), 4.46-4.48
  (second derivatives), principal curvatures and directions eq 4.42-4.45 (computed here by
  :func:`gearrep.curvature.principal_curvatures`, the same quantities from the fundamental forms).
  In eq 4.40 the upper sign is the right-side thread surface, the lower sign the left side.
* Generation (two-parameter enveloping, seed 000 eq 4.1-4.5 and sec. 4.5): seed 000 chapters 2-3
  (the machine kinematics) are NOT in the text; the set-up below is the reconstruction written up in
  docs/reading-notes.md (section 000-C), verified here against the surviving numbers of
  Tables 4.3/4.4 (see :mod:`gearrep.replications.hobcut_curvature`):

  - hob of Table 5.1: normal module m = 3 mm, alpha_n = 20 deg, pitch radius r_h = 30 mm,
    single start; lead angle sin(lambda) = m / (2 r_h) (Table 5.1 prints 2.866 deg);
    lead per radian P_1 = m / (2 cos lambda); r_t (the radius of the apex of the V-shaped thread
    groove, where l = 0) = r_h - (pi m / 4) / tan(alpha_n) = 23.52641 mm;
  - theta = hob spin, the work gear turns theta / N; psi swivels the whole hob about an axis
    parallel to the centre-distance line X, through the arc centre, which lies R_c from the hob
    centre in the tangential (Y) direction; centre distance E = m N / 2 + r_h; hob axis set at
    the lead angle. The chain (hob frame S_1 -> gear frame S_2, :class:`gearrep.motion.ChainMotion`):

        M_21 = Rot_z(theta/N) Rot_x(psi; about (E, s_c R_c, 0)) Trans_x(E) Rot_x(lambda - pi/2) Rot_z(theta)

    with s_c = ``arc_centre`` (+1 or -1) the side of the arc centre. ``arc_centre = -1`` (the
    default) makes the upper-sign (right-side) thread generate the CONVEX flank Sigma_2R of the
    tables (k_s, k_q > 0, elliptic) and the lower-sign thread the concave flank Sigma_2L
    (hyperbolic), as seed 000 sec. 4.5 states. ``arc_centre = +1`` (the choice of the older test
    case tests/unit/_envelope_cases.py::hob_case) swaps convex and concave: that case reproduces
    k_q but not k_s of Table 4.3 because it computes the concave flank.

* Two variants of the thread profile (``ZAHob.variant``):

  - ``"axial"`` (default): a straight line in the AXIAL section at alpha_n (a true ZA hob),
    i.e. eq 4.40 with the sin(beta)/cos(beta) factors removed from the profile terms
    (P_1 phi kept). This variant reproduces Tables 4.3/4.4.
  - ``"printed"``: eq 4.40 exactly as printed, with beta = the hob lead angle: the profile line
    is tilted out of the axial section (a straight line in the normal section).

Gear frame of the tables (the "tooth frame" S_f): Z_f = gear axis, X_f along the centre line of
the tooth whose flanks are generated at theta ~ pi (tooth symmetric about X_f: the flank of the
upper sign lies on +Y_f, the lower-sign flank on -Y_f); it is the generation frame S_2 turned
by +pi/N about Z (``GeneratedGear.frame_rotation_rad``). The mid-face Z_f = 0 is psi = 0.

Parameterisation of the generated surface: (l, psi) free, (phi, theta) solved from the two
equations of meshing, because the Jacobian of the meshing equations in (theta, psi) is singular
at mid-face (docs/reading-notes.md, 000-C; tested in tests/unit/core/test_envelope.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np

from .. import frames
from ..curvature import PrincipalCurvatures, principal_curvatures
from ..curvature_relations import (
    GeneratedCurvatures,
    generated_curvatures,
    two_parameter_b_coefficients,
    two_parameter_principal_curvatures,
    two_parameter_system,
)
from ..envelope import Envelope, EnvelopeResult, EnvelopeSurface
from ..inputs import check_integer, check_positive
from ..motion import ChainMotion, rotation, translation
from ..solve import SolveResult, Status, newton
from ..surface import RotatedSurface, Surface, SurfacePoint

__all__ = [
    "HOB_VARIANTS",
    "FLANK_SIDE",
    "ZAHob",
    "HobThread",
    "GeneratedGear",
    "FlankCurvatures",
    "za_hob",
    "PairDesign",
]

#: the thread profiles of :class:`ZAHob` (``variant``): a true ZA hob, or eq 4.40 as printed
HOB_VARIANTS = ("axial", "printed")
#: thread side (sign of eq 4.40) that generates each flank of the tables with arc_centre = -1
FLANK_SIDE = {"R": +1, "L": -1}


@dataclass(frozen=True)
class ZAHob:
    """Design data of the ZA worm-type hob (defaults: Table 5.1 of seed 000).

    Parameters
    ----------
    module_mm : float, optional
        Normal module m [mm] (> 0).
    pressure_angle_rad : float, optional
        alpha_n [rad], in (0, pi/2).
    pitch_radius_mm : float, optional
        r_h [mm] (> m / 2, so that the lead angle exists).
    variant : {"axial", "printed"}, optional
        "axial" (true ZA, reproduces the tables) or "printed" (eq 4.40 as printed).

    Raises
    ------
    ValueError
        If a value is out of range, or the groove apex radius r_t would be <= 0.

    Examples
    --------
    >>> import math
    >>> from gearrep.surfaces.hob import ZAHob
    >>> hob = ZAHob()  # m = 3 mm, alpha_n = 20 deg, r_h = 30 mm
    >>> round(math.degrees(hob.lead_angle_rad), 3), round(hob.apex_radius_mm, 5)  # deg (Table 5.1: 2.866), mm
    (2.866, 23.52641)
    """

    module_mm: float = 3.0
    pressure_angle_rad: float = float(np.radians(20.0))
    pitch_radius_mm: float = 30.0
    variant: str = "axial"

    def __post_init__(self):
        m = check_positive("module_mm", self.module_mm)
        a = float(self.pressure_angle_rad)
        if not (np.isfinite(a) and 0 < a < np.pi / 2):
            raise ValueError(f"pressure_angle_rad must be in (0, pi/2), got {self.pressure_angle_rad!r}")
        r = check_positive("pitch_radius_mm", self.pitch_radius_mm)
        if r <= m / 2:
            raise ValueError(f"pitch_radius_mm must be > module_mm / 2 = {m / 2}, got {r!r}")
        if self.variant not in HOB_VARIANTS:
            raise ValueError(f"variant must be one of {HOB_VARIANTS}, got {self.variant!r}")
        if self.apex_radius_mm <= 0:
            raise ValueError("pitch_radius_mm too small: the thread-groove apex radius r_t would be <= 0")

    @property
    def lead_angle_rad(self) -> float:
        """lambda, sin(lambda) = m / (2 r_h) (Table 5.1: 2.866 deg)."""
        return float(np.arcsin(self.module_mm / (2 * self.pitch_radius_mm)))

    @property
    def lead_per_rad_mm(self) -> float:
        """P_1 = m / (2 cos lambda) (single start; eq 4.40)."""
        return float(self.module_mm / (2 * np.cos(self.lead_angle_rad)))

    @property
    def apex_radius_mm(self) -> float:
        """r_t = r_h - (pi m / 4) / tan(alpha_n): radius of the groove apex (l = 0)."""
        return float(self.pitch_radius_mm - (np.pi * self.module_mm / 4) / np.tan(self.pressure_angle_rad))

    @property
    def beta_rad(self) -> float:
        """beta of eq 4.40 (the lead angle in the printed variant, 0 in the axial variant)."""
        return self.lead_angle_rad if self.variant == "printed" else 0.0

    def thread(self, side: int) -> HobThread:
        """The thread surface of eq 4.40: side +1 = upper sign (right side), -1 = lower sign.

        Parameters
        ----------
        side : {1, -1}
            The sign of eq 4.40.

        Returns
        -------
        HobThread
            The thread surface.
        """
        return HobThread(self, side)


class HobThread(Surface):
    """Hob thread surface r_1(l, phi) of seed 000 eq 4.40 in the hob frame S_1, with the
    analytic derivatives of eq 4.41 (r_l, r_phi), 4.46 (r_ll = 0), 4.47, 4.48. Surface
    parameters u = l (mm, along the straight profile line from the groove apex) and v = phi
    (rad). The normal is unit(r_l x r_phi) (eq 4.41).

    Parameters
    ----------
    hob : ZAHob
        The hob.
    side : {1, -1}
        +1 upper sign of eq 4.40 (right side), -1 lower sign.

    Raises
    ------
    ValueError
        If ``hob`` is not a :class:`ZAHob` or ``side`` is not +-1.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import ZAHob
    >>> thread = ZAHob().thread(1)
    >>> np.round(thread.position(5.0, 0.1), 5).tolist()  # l [mm], phi [rad] -> mm
    [28.08387, -2.81779, 1.55991]
    >>> round(float(thread.principal(np.array([5.0]), np.array([0.1])).k1[0]), 8)  # k_f [1/mm]
    0.00022317
    """

    def __init__(self, hob: ZAHob, side: int):
        if not isinstance(hob, ZAHob):
            raise ValueError("hob must be a ZAHob")
        if side not in (1, -1):
            raise ValueError(f"side must be +1 (upper sign of eq 4.40) or -1 (lower sign), got {side!r}")
        self.hob, self.side = hob, int(side)
        a, b = hob.pressure_angle_rad, hob.beta_rad
        self._ca, self._sa = np.cos(a), np.sin(a)
        self._sb, self._cb = np.sin(b), np.cos(b)
        self._rt, self._P = hob.apex_radius_mm, hob.lead_per_rad_mm

    def _parts(self, l, p):
        l, p = np.broadcast_arrays(np.asarray(l, float), np.asarray(p, float))
        s = self.side
        A = self._rt + l * self._ca
        B = s * l * self._sa * self._sb
        C = s * l * self._sa * self._cb
        return l, p, A, B, C, np.cos(p), np.sin(p)

    def position(self, l, p):
        l, p, A, B, C, c, sn = self._parts(l, p)
        return np.stack([A * c - B * sn, -A * sn - B * c, C - self._P * p], -1)

    def evaluate(self, l, p) -> SurfacePoint:
        l, p, A, B, C, c, sn = self._parts(l, p)
        s = self.side
        ca, Bl, Cl = self._ca, s * self._sa * self._sb, s * self._sa * self._cb  # dA/dl, dB/dl, dC/dl
        z = np.zeros_like(l)
        r = np.stack([A * c - B * sn, -A * sn - B * c, C - self._P * p], -1)
        r_l = np.stack([ca * c - Bl * sn, -ca * sn - Bl * c, z + Cl], -1)
        r_p = np.stack([-A * sn - B * c, -A * c + B * sn, z - self._P], -1)
        r_lp = np.stack([-ca * sn - Bl * c, -ca * c + Bl * sn, z], -1)
        r_pp = np.stack([-A * c + B * sn, A * sn + B * c, z], -1)
        return SurfacePoint(r, r_l, r_p, np.zeros_like(r), r_lp, r_pp)

    def principal(self, l, p) -> PrincipalCurvatures:
        """k_f >= k_h and e_f, e_h of the thread (eq 4.42-4.45), signed for unit(r_l x r_phi).

        Parameters
        ----------
        l : array_like
            Profile parameter [mm].
        p : array_like
            Thread angle phi [rad].

        Returns
        -------
        gearrep.curvature.PrincipalCurvatures
            Curvatures [1/mm] and directions.
        """
        return principal_curvatures(self.evaluate(l, p))


class FlankCurvatures(NamedTuple):
    """Principal curvatures of the generated flank labelled as in seed 000 Tables 4.2-4.5, in
    the tooth frame S_f. Curvatures are signed w.r.t. ``normal`` = the hob normal
    unit(r_l x r_phi) of eq 4.41 carried into S_f (the tables' convention: k > 0 where the flank
    bends toward it).

    Parameters
    ----------
    k_s, e_s : numpy.ndarray
        The principal curvature [1/mm] and direction nearest the gear axis Z_f (along Z_f at
        mid-face), with e_s . Z_f >= 0.
    k_q, e_q : numpy.ndarray
        The other one [1/mm]; e_q = n_out x e_s (n_out the normal pointing out of the tooth): the
        orientation the printed tables use for both flanks (see the replication module).
    normal : numpy.ndarray
        (n, 3) the hob normal in S_f.
    normal_out : numpy.ndarray
        (n, 3) n_out.
    point : numpy.ndarray
        (n, 3) the flank point [mm] in S_f.
    k_s_two_parameter, k_q_two_parameter, sigma_two_parameter : numpy.ndarray
        The same pair [1/mm] and the angle [rad] from the two-parameter-envelope system of seed 000
        (eq 4.33-4.39 with the corrected signs, then 4.24-4.26; e_s nearest the hob direction e_f).
    generated : gearrep.curvature_relations.GeneratedCurvatures
        The curvatures from K_2 = K_1 + C E^-1 C^T, generation frame.
    result : gearrep.envelope.EnvelopeResult
        The envelope solve (generation frame) with the statuses.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.surfaces.hob import GeneratedGear
    >>> c = GeneratedGear().curvatures([6.0], 0.0)  # the convex flank, l [mm], psi [rad]
    >>> np.round(c.k_s, 6).tolist(), np.round(c.k_q, 6).tolist()  # 1/mm
    ([0.008369], [0.078881])
    """

    k_s: np.ndarray
    k_q: np.ndarray
    e_s: np.ndarray
    e_q: np.ndarray
    normal: np.ndarray
    normal_out: np.ndarray
    point: np.ndarray
    k_s_two_parameter: np.ndarray
    k_q_two_parameter: np.ndarray
    sigma_two_parameter: np.ndarray
    generated: GeneratedCurvatures
    result: EnvelopeResult


@dataclass(frozen=True)
class GeneratedGear:
    """One flank of the curvilinear-tooth gear generated by the ZA hob (module doc).

    Parameters
    ----------
    hob : ZAHob, optional
        The hob.
    n_teeth : int, optional
        N of the work gear (>= 4).
    R_c_mm : float, optional
        Nominal radius of the circular-arc tooth trace [mm] (> 0); ``np.inf`` gives the spur-gear
        limit, where the swivel becomes a translation along the gear axis and psi is that axial
        feed in mm (Z_f = psi for arc_centre = -1).
    side : {1, -1}, optional
        Thread side (+1 upper sign of eq 4.40, -1 lower sign); with arc_centre = -1, +1 generates
        Sigma_2R (convex) and -1 Sigma_2L (concave): see :data:`FLANK_SIDE`.
    arc_centre : {-1, 1}, optional
        Side of the arc centre, -1 (default, the tables' convention) or +1.
    tol : float, optional
        Tolerance on the meshing residual [mm] for R_c <= 100 mm (see :attr:`effective_tol`).
    maxiter : int, optional
        Iteration limit of the meshing solve.

    Raises
    ------
    ValueError
        If a value is out of range.

    Examples
    --------
    The addendum tip of the Table 5.1 pinion (r_a = 33 mm) is generated at l = 4.381 mm
    (seed 000 sec. 4.5):

    >>> import numpy as np
    >>> from gearrep.surfaces.hob import GeneratedGear
    >>> gear = GeneratedGear()  # 20 teeth, R_c = 110 mm, the convex flank
    >>> gear.pitch_radius_mm, gear.centre_distance_mm  # mm
    (30.0, 60.0)
    >>> np.round(gear.l_at_radius(33.0).x[:, 0], 3).tolist()  # mm
    [4.381]
    """

    hob: ZAHob = field(default_factory=ZAHob)
    n_teeth: int = 20
    R_c_mm: float = 110.0
    side: int = 1
    arc_centre: int = -1
    tol: float = 1e-12
    maxiter: int = 50

    def __post_init__(self):
        if not isinstance(self.hob, ZAHob):
            raise ValueError("hob must be a ZAHob")
        if int(self.n_teeth) != self.n_teeth or self.n_teeth < 4:
            raise ValueError(f"n_teeth must be an integer >= 4, got {self.n_teeth!r}")
        if not (float(self.R_c_mm) > 0 and not np.isnan(float(self.R_c_mm))):
            raise ValueError(f"R_c_mm must be > 0 (np.inf for the spur-gear limit), got {self.R_c_mm!r}")
        if self.side not in (1, -1):
            raise ValueError(f"side must be +1 or -1, got {self.side!r}")
        if self.arc_centre not in (1, -1):
            raise ValueError(f"arc_centre must be +1 or -1, got {self.arc_centre!r}")
        check_positive("tol", self.tol)
        check_integer("maxiter", self.maxiter)

    @classmethod
    def flank(cls, name: str, **kw) -> GeneratedGear:
        """Sigma_2R (``name="R"``) or Sigma_2L (``"L"``) of seed 000 with arc_centre = -1.

        Parameters
        ----------
        name : {"R", "L"}
            The flank.
        **kw
            The other fields of :class:`GeneratedGear`.

        Returns
        -------
        GeneratedGear
            The flank.

        Raises
        ------
        ValueError
            If ``name`` is not "R" or "L".
        """
        if name not in FLANK_SIDE:
            raise ValueError(f"name must be 'R' or 'L', got {name!r}")
        return cls(side=FLANK_SIDE[name], **kw)

    # ---- set-up ---------------------------------------------------------------------------
    @property
    def pitch_radius_mm(self) -> float:
        """Pitch radius m N / 2 [mm]."""
        return self.hob.module_mm * self.n_teeth / 2

    @property
    def centre_distance_mm(self) -> float:
        """E = m N / 2 + r_h (hob cutting at the standard centre distance, no profile shift)."""
        return self.pitch_radius_mm + self.hob.pitch_radius_mm

    @property
    def frame_rotation_rad(self) -> float:
        """Angle (about Z) from the generation frame S_2 to the tooth frame S_f: pi / N."""
        return float(np.pi / self.n_teeth)

    @property
    def to_tooth_frame(self) -> np.ndarray:
        """3 x 3 rotation L_f2 (generation frame S_2 -> tooth frame S_f): rot_z(pi / N)."""
        return frames.rot_z(self.frame_rotation_rad)

    def thread(self) -> HobThread:
        """The hob thread surface of this flank's side.

        Returns
        -------
        HobThread
            The thread.
        """
        return self.hob.thread(self.side)

    def motion(self) -> ChainMotion:
        """M_21(theta, psi) of the module doc (hob frame -> generation frame S_2).

        Returns
        -------
        gearrep.motion.ChainMotion
            The motion, parameters (theta, psi).
        """
        E, lam = self.centre_distance_mm, self.hob.lead_angle_rad
        if np.isinf(self.R_c_mm):  # spur-gear limit: the swivel becomes an axial feed (psi in mm)
            swivel = translation((0.0, 0.0, -float(self.arc_centre)), [0.0, 1.0])
        else:
            swivel = rotation((1, 0, 0), [0.0, 1.0], point=(E, self.arc_centre * self.R_c_mm, 0.0))  # swivel psi
        return ChainMotion(
            [
                rotation((0, 0, 1), [1.0 / self.n_teeth, 0.0]),  # work gear turns theta / N
                swivel,
                translation((1, 0, 0), [0.0, 0.0], offset=E),  # centre distance
                rotation((1, 0, 0), [0.0, 0.0], offset=lam - np.pi / 2),  # hob axis set at the lead angle
                rotation((0, 0, 1), [1.0, 0.0]),  # hob spin theta
            ],
            names=("theta", "psi"),
        )

    @property
    def effective_tol(self) -> float:
        """Meshing-residual tolerance actually used: ``tol`` * max(1, R_c / 100 mm). The psi
        equation of meshing is a velocity with lever arm ~R_c, so its rounding floor grows like
        eps * R_c (about 1e-12 mm at R_c = 5000 mm); R_c = inf (axial feed) is not scaled."""
        scale = 1.0 if np.isinf(self.R_c_mm) else max(1.0, float(self.R_c_mm) / 100.0)
        return self.tol * scale

    def envelope(self) -> Envelope:
        """The two-parameter envelope with free (l, psi) and solved (phi, theta).

        Returns
        -------
        gearrep.envelope.Envelope
            The envelope (tolerance :attr:`effective_tol`).
        """
        return Envelope(self.thread(), self.motion(), free=("u", "psi"), tol=self.effective_tol, maxiter=self.maxiter)

    DEFAULT_GUESS = (np.pi, 0.0)  #: (phi, theta) start: the thread at the work gear's tooth space

    # ---- points ---------------------------------------------------------------------------
    def solve(self, l_mm, psi_rad, guess=None) -> EnvelopeResult:
        """Generated points at (l, psi) (broadcast, flattened), in the GENERATION frame S_2.

        ``guess`` for (phi, theta): by default the mid-face solution, itself started from the
        spur-gear limit (R_c = inf) solved from (pi, 0) (a far start can reach another branch
        of the meshing equations for large R_c); away from mid-face continued in psi when the
        direct start fails. Every converged point is verified (:meth:`verify`): a root outside
        the generated tooth (radial band r_p +- 2.5 m, angular sector +-pi/N about X_f) gets
        status WRONG_ROOT, never passed on as converged.

        Parameters
        ----------
        l_mm : float or array_like
            Hob profile parameter l [mm].
        psi_rad : float or array_like
            Swivel psi [rad] (axial feed [mm] for R_c = inf).
        guess : array_like, optional
            Start for (phi, theta) [rad].

        Returns
        -------
        gearrep.envelope.EnvelopeResult
            Points and normals in S_2, with the statuses.
        """
        env = self.envelope()
        l, ps = np.broadcast_arrays(np.asarray(l_mm, float), np.asarray(psi_rad, float))
        lf, pf = l.reshape(-1), ps.reshape(-1)
        if guess is not None:
            return self.verify(env.solve(lf, pf, guess=guess))
        x0 = self._mid_solution(env, lf)
        rec = env.solve(lf, pf, guess=x0)
        if not np.all(rec.converged):
            rec = self._march(env, lf, pf, x0)
        return self.verify(rec)

    def _mid_solution(self, env, l):
        """(phi, theta) at (l, psi = 0): spur limit from (pi, 0), then this R_c from there."""
        S = list(env.solved)
        spur = env if np.isinf(self.R_c_mm) else replace(self, R_c_mm=np.inf).envelope()
        r0 = spur.solve(l, 0 * l, guess=self.DEFAULT_GUESS)
        x = np.where(r0.converged[:, None], r0.params[:, S], np.asarray(self.DEFAULT_GUESS))
        if not np.isinf(self.R_c_mm):
            r1 = env.solve(l, 0 * l, guess=x)
            x = np.where(r1.converged[:, None], r1.params[:, S], x)
        return x

    def _march(self, env, l, ps, x, step=0.02):
        """Continuation in psi from mid-face (warm starts), for large |psi|."""
        nstep = max(1, int(np.ceil(np.max(np.abs(ps)) / step)))
        for t in np.linspace(0, 1, nstep + 1)[1:]:
            rec = env.solve(l, t * ps, guess=x)
            x = np.where(rec.converged[:, None], rec.params[:, list(env.solved)], x)
        return rec

    def verify(self, rec: EnvelopeResult) -> EnvelopeResult:
        """Mark converged roots outside the generated tooth as WRONG_ROOT (see :meth:`solve`).

        Parameters
        ----------
        rec : gearrep.envelope.EnvelopeResult
            A solve of this flank's envelope.

        Returns
        -------
        gearrep.envelope.EnvelopeResult
            ``rec`` with the statuses of such roots changed.
        """
        pt = rec.point @ self.to_tooth_frame.T
        r = np.hypot(pt[:, 0], pt[:, 1])
        ang = np.arctan2(pt[:, 1], pt[:, 0])
        m = self.hob.module_mm
        Rc = self.R_c_mm
        # the tooth's centre line leaves X_f along the arc trace: circumferential offset R_c - sqrt(R_c^2 - Z^2)
        drift = 0.0 if np.isinf(Rc) else (Rc - np.sqrt(np.maximum(Rc**2 - pt[:, 2] ** 2, 0.0))) / self.pitch_radius_mm
        inside = (np.abs(r - self.pitch_radius_mm) <= 2.5 * m) & (np.abs(ang) <= np.pi / self.n_teeth + drift)
        bad = rec.converged & ~inside
        if np.any(bad):
            rec = replace(rec, solve=rec.solve.with_status(bad, Status.WRONG_ROOT))
        return rec

    def points(self, l_mm, psi_rad, guess=None):
        """(point, hob normal, EnvelopeResult) with point and normal in the tooth frame S_f.

        Parameters
        ----------
        l_mm : float or array_like
            Hob profile parameter l [mm].
        psi_rad : float or array_like
            Swivel psi [rad].
        guess : array_like, optional
            Start for (phi, theta) [rad].

        Returns
        -------
        point : numpy.ndarray
            (n, 3) [mm] in S_f.
        normal : numpy.ndarray
            (n, 3) in S_f.
        result : gearrep.envelope.EnvelopeResult
            The solve (generation frame).
        """
        rec = self.solve(l_mm, psi_rad, guess)
        R = self.to_tooth_frame
        return rec.point @ R.T, rec.normal @ R.T, rec

    def l_at_radius(self, radius_mm, psi_rad=0.0, l0_mm=6.0) -> SolveResult:
        """The l whose generated point at psi lies at distance ``radius_mm`` from the gear axis
        (e.g. the tip r_a = 33 mm: first row of Tables 4.2-4.5). Newton on l (one unknown).

        Parameters
        ----------
        radius_mm : float or array_like
            Radii [mm], > 0.
        psi_rad : float or array_like, optional
            Swivel [rad].
        l0_mm : float, optional
            Start [mm].

        Returns
        -------
        gearrep.solve.SolveResult
            x (n, 1) = l [mm], residual [mm], iterations, status.

        Raises
        ------
        ValueError
            If a radius is not finite and > 0.
        """
        r_target, ps = np.broadcast_arrays(
            np.atleast_1d(np.asarray(radius_mm, float)), np.atleast_1d(np.asarray(psi_rad, float))
        )
        r_target, ps = r_target.reshape(-1), ps.reshape(-1)
        if np.any(~np.isfinite(r_target) | (r_target <= 0)):
            raise ValueError(f"radius_mm must be finite and > 0, got {radius_mm!r}")

        def fun(x, idx):
            rec = self.solve(x[:, 0], ps[idx])
            r = np.hypot(rec.point[:, 0], rec.point[:, 1])
            out = (r - r_target[idx])[:, None]
            out[~rec.converged] = np.nan
            return out

        return newton(fun, np.full((r_target.size, 1), float(l0_mm)), tol=1e-11, rows=True)

    # ---- curvatures -----------------------------------------------------------------------
    def curvatures(self, l_mm, psi_rad=0.0, guess=None) -> FlankCurvatures:
        """Principal curvatures and directions of the generated flank at (l, psi), labelled
        and oriented as in seed 000 Tables 4.2-4.5 (see :class:`FlankCurvatures`), from
        K_2 = K_1 + C E^-1 C^T (:func:`gearrep.curvature_relations.generated_curvatures`) and,
        independently, from the chapter's eq 4.33-4.39 (corrected) and 4.24-4.26.

        Parameters
        ----------
        l_mm : float or array_like
            Hob profile parameter l [mm].
        psi_rad : float or array_like, optional
            Swivel psi [rad].
        guess : array_like, optional
            Start for (phi, theta) [rad].

        Returns
        -------
        FlankCurvatures
            Curvatures [1/mm] and directions in S_f.
        """
        rec = self.solve(l_mm, psi_rad, guess)
        env = self.envelope()
        gc = generated_curvatures(env, rec.params)
        R = self.to_tooth_frame
        e1, e2, n = gc.e1 @ R.T, gc.e2 @ R.T, gc.normal @ R.T
        pt = rec.point @ R.T
        # e_s: the principal direction nearest Z_f
        use1 = np.abs(e1[:, 2]) >= np.abs(e2[:, 2])
        k_s = np.where(use1, gc.k1, gc.k2)
        k_q = np.where(use1, gc.k2, gc.k1)
        e_s = np.where(use1[:, None], e1, e2)
        e_s = e_s * np.where(e_s[:, 2] < 0, -1.0, 1.0)[:, None]
        n_out = self.outward(pt, n)
        e_q = np.cross(n_out, e_s)
        # the chapter's method (eq 4.33-4.39 corrected, 4.24-4.26)
        b = two_parameter_system(env, rec.params)
        b11, b12, b22 = two_parameter_b_coefficients(b)
        ks_b, kq_b, sig_b = two_parameter_principal_curvatures(b11, b12, b22, gc.k_f, gc.k_h)
        return FlankCurvatures(k_s, k_q, e_s, e_q, n, n_out, pt, ks_b, kq_b, sig_b, gc, rec)

    @staticmethod
    def outward(point, normal) -> np.ndarray:
        """+-normal pointing out of the tooth (away from its centre line X_f) at tooth-frame
        points: the sign of (polar angle of the point) * (normal . e_theta).

        Parameters
        ----------
        point : array_like
            (..., 3) points in S_f [mm].
        normal : array_like
            (..., 3) normals there.

        Returns
        -------
        numpy.ndarray
            (..., 3) the normals, reversed where they point into the tooth.
        """
        point, normal = np.asarray(point, float), np.asarray(normal, float)
        ang = np.arctan2(point[..., 1], point[..., 0])
        e_th = np.stack([-np.sin(ang), np.cos(ang), np.zeros_like(ang)], -1)
        s = np.sign(ang * np.sum(normal * e_th, -1))
        return normal * np.where(s == 0, 1.0, s)[..., None]

    def surface(self, frame: str = "tooth", fd_step=(1e-3, 1e-4)) -> Surface:
        """The generated flank as a :class:`gearrep.surface.Surface` of (l, psi) (for
        direct differential geometry and TCA): analytic first derivatives, second derivatives
        with analytic normal components (:class:`gearrep.envelope.EnvelopeSurface`). ``frame``
        "tooth" (S_f, the tooth centred on X_f) or "generation" (S_2). Its normal unit(r_l x r_psi) is +- the hob normal.

        Parameters
        ----------
        frame : {"tooth", "generation"}, optional
            The frame of the surface.
        fd_step : (float, float), optional
            Finite-difference steps in (l [mm], psi [rad]) of the solved parameters' derivatives.

        Returns
        -------
        gearrep.surface.Surface
            The flank, parameters (l [mm], psi [rad]).

        Raises
        ------
        ValueError
            If ``frame`` is unknown.
        """
        s = EnvelopeSurface(self.envelope(), self.DEFAULT_GUESS, fd_step)
        if frame == "generation":
            return s
        if frame == "tooth":
            return RotatedSurface(s, self.to_tooth_frame)
        raise ValueError(f"frame must be 'tooth' or 'generation', got {frame!r}")


def za_hob(module_mm: float, pressure_angle_deg: float, pitch_radius_mm: float, variant: str = "axial") -> ZAHob:
    """The single-start ZA hob of normal module ``module_mm`` [mm], normal pressure angle
    ``pressure_angle_deg`` [deg] and pitch radius ``pitch_radius_mm`` [mm] (ranges: :class:`ZAHob`).

    Parameters
    ----------
    module_mm : float
        Normal module [mm].
    pressure_angle_deg : float
        Normal pressure angle [deg], in (0, 90).
    pitch_radius_mm : float
        Pitch radius [mm].
    variant : {"axial", "printed"}, optional
        The thread profile (:class:`ZAHob`).

    Returns
    -------
    ZAHob
        The hob.

    Raises
    ------
    ValueError
        If a value is out of range.

    Examples
    --------
    >>> from gearrep.surfaces.hob import ZAHob, za_hob
    >>> za_hob(3.0, 20.0, 30.0) == ZAHob()  # mm, deg, mm: the hob of Table 5.1
    True
    """
    a = float(pressure_angle_deg)
    if not (np.isfinite(a) and 0.0 < a < 90.0):
        raise ValueError(f"pressure_angle_deg must be in (0, 90) deg, got {pressure_angle_deg!r}")
    return ZAHob(
        module_mm=module_mm,
        pressure_angle_rad=float(np.radians(pressure_angle_deg)),
        pitch_radius_mm=pitch_radius_mm,
        variant=variant,
    )


@dataclass(frozen=True)
class PairDesign:
    """The pinion and gear of a curvilinear-tooth pair cut by one hob: tooth numbers ``n_pinion``,
    ``n_gear`` (integers in [4, 10000]), the face width ``face_width_mm`` of both members (in
    (0, 1000] mm) and the :class:`ZAHob`. :meth:`cut` generates the two working flanks; the pair
    for the TCA is :func:`gearrep.tca.hobbed_pair`.

    Parameters
    ----------
    n_pinion, n_gear : int
        Tooth numbers [1], in [4, 10000].
    face_width_mm : float
        Face width of both members [mm], in (0, 1000].
    hob : ZAHob
        The hob.

    Raises
    ------
    ValueError
        If a value is out of range.

    Examples
    --------
    >>> from gearrep.surfaces.hob import PairDesign, za_hob
    >>> design = PairDesign(20, 40, 30.0, za_hob(3.0, 20.0, 30.0))  # teeth, face mm; module mm, deg, radius mm
    >>> pinion, gear = design.cut(100.0, 110.0)  # tooth-trace radii [mm]
    >>> (pinion.n_teeth, pinion.arc_centre), (gear.n_teeth, gear.arc_centre)
    ((20, -1), (40, 1))
    >>> design.with_hob(pitch_radius_mm=40.0).hob.pitch_radius_mm  # mm
    40.0
    """

    n_pinion: int
    n_gear: int
    face_width_mm: float
    hob: ZAHob

    def __post_init__(self):
        for name in ("n_pinion", "n_gear"):
            v = getattr(self, name)
            if not (isinstance(v, (int, np.integer)) and 4 <= v <= 10000):
                raise ValueError(f"{name} must be an integer in [4, 10000], got {v!r}")
        w = self.face_width_mm
        if not (isinstance(w, (int, float)) and np.isfinite(w) and 0 < w <= 1000):
            raise ValueError(f"face_width_mm must be in (0, 1000] mm, got {w!r}")
        if not isinstance(self.hob, ZAHob):
            raise ValueError(f"hob must be a ZAHob, got {self.hob!r}")

    def with_hob(self, **changes) -> PairDesign:
        """The same pair cut by a hob with ``changes`` (e.g. ``pitch_radius_mm``).

        Parameters
        ----------
        **changes
            Fields of :class:`ZAHob`.

        Returns
        -------
        PairDesign
            The new design.
        """
        return replace(self, hob=replace(self.hob, **changes))

    def cut(self, R_cp_mm: float, R_cg_mm: float) -> tuple[GeneratedGear, GeneratedGear]:
        """(pinion, gear) flanks for tooth-trace radii ``R_cp_mm``, ``R_cg_mm`` [mm]: the pinion's
        convex flank (thread side +1, arc centre -1: Sigma_2R) and the gear's concave flank (thread
        side +1, arc centre +1), each in its generation frame.

        Parameters
        ----------
        R_cp_mm, R_cg_mm : float
            Tooth-trace radii of pinion and gear [mm], finite and > 0.

        Returns
        -------
        pinion, gear : GeneratedGear
            The two flanks.

        Raises
        ------
        ValueError
            If a radius is not finite and > 0.
        """
        for name, v in (("R_cp_mm", R_cp_mm), ("R_cg_mm", R_cg_mm)):
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"{name} must be a finite radius > 0 mm, got {v!r}")
        pin = GeneratedGear(hob=self.hob, n_teeth=int(self.n_pinion), R_c_mm=float(R_cp_mm), side=1, arc_centre=-1)
        gear = GeneratedGear(hob=self.hob, n_teeth=int(self.n_gear), R_c_mm=float(R_cg_mm), side=1, arc_centre=1)
        return pin, gear
