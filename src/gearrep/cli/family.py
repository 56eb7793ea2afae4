"""What a gear family of the ``gearrep`` command declares, and the analyses shared by the
families whose pair is a :class:`gearrep.tca.GearPair` (parallel, crossed or intersecting axes).

A family is one :class:`Family` object registered in :data:`gearrep.cli.families.REGISTRY` under
the ``family`` value of its design files; the command knows families only through it. A family
declares its design keys (:attr:`Family.keys`, with units, ranges and defaults: the generated
schema comes from them), the names of its flank parameters, the analyses it supports, and
implements the validation and pair construction (:meth:`Family.build`), the contact check
before any work (:meth:`Family.check_contact`), the TCA tables, the sweep metrics, the flank
grids of the curvature table and point clouds, and the family-specific parts of the figures.

:class:`PairFamily` implements all of that for a pair of the library's TCA; a family then only
declares its keys and builds its pair (and overrides what differs: its start, flank limits,
engagement). Every contact is solved by the library's robust start strategy,
:func:`gearrep.tca.robust_contact` (each start projected into the domain where member 2's
explicit surface is defined, then the reduced solve, the conventional one seeded from it; rows
that fail or reach a root that does not mesh are restarted), from the family's start
(:meth:`PairFamily.starts`, moved along the path where many angles are solved at once:
:meth:`PairFamily.robust_solve`; families whose member 2 has no explicit form also give
:meth:`PairFamily.nominal`, the conventional start it is completed with). The meshing cycle is
either the library's (:meth:`PairFamily.meshing_cycle_tables`: engagement limits solved on the
flank boundaries, :func:`gearrep.meshing.meshing_cycle`) or sampled
(:meth:`PairFamily.sampled_cycle`: the contact at ``n`` angles between the family's engagement
limits, the TE over the cycle as the upper envelope of the neighbouring tooth pairs in the drive
sense, :func:`gearrep.tca.flank_sense`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..curvature import principal_curvatures, with_opposite_normal
from ..ltca import refusal
from ..meshing import contact_ratio, engagement_limits, meshing_cycle
from ..settings import SettingError
from ..solve import Status
from ..tca import contact_ellipse, flank_sense, offset_start, robust_contact, solve_contact
from ..units import ARCSEC
from .edges import axial_edges, cut_at_edges
from .keys import misalignment, set_dotted
from .tables import cloud, curvature_frame, cycle_summary, te_envelope

__all__ = ["Design", "Family", "PairFamily", "ISO_RATIOS", "ANALYSES", "UNLOADED"]

#: the analyses a family can support (the commands that solve or evaluate its flanks)
ANALYSES = ("tca", "curvature", "sweep", "ltca")
#: the analyses of every family of the library's unloaded TCA (the default of :attr:`Family.analyses`;
#: ``ltca``, the loaded analysis, is declared by the families :mod:`gearrep.ltca` supports)
UNLOADED = ("tca", "curvature", "sweep")
#: the summary entries of the ISO contact ratios (NaN for a family without them)
ISO_RATIOS = ("transverse_contact_ratio_iso", "overlap_ratio_iso", "total_contact_ratio_iso")


@dataclass
class Design:
    """A checked design: ``values`` (the resolved mapping), its ``family`` (the registered
    :class:`Family`), the library ``pair`` it built, whether the flanks touch along a line
    (``line_contact``, set by the contact check), the family's helpers (``mesh``) and the contact
    the check found at phi1 = 0 where a family keeps it (``start``)."""

    values: dict
    family: Family
    pair: object
    line_contact: bool = False
    mesh: object = None
    start: object = None

    @property
    def analysis(self) -> dict:
        return self.values["analysis"]

    @property
    def name(self) -> str:
        return self.values["name"]


class Family:
    """One gear family of the command. Subclasses set the class attributes and implement the
    methods that raise NotImplementedError here (:class:`PairFamily` implements all of them for a
    pair of the library's TCA).

    Attributes: ``name`` (the design files' ``family`` value), ``keys`` (the declaration of its
    design keys, :func:`gearrep.settings.declare`; every family has ``name``, ``module_mm``,
    ``face_width_mm``, ``pinion.teeth``, ``gear.teeth``, ``misalignment`` and ``analysis``),
    ``param_names`` (the two flank parameters with their units, column names of the tables),
    ``analyses`` (the commands it supports, of :data:`ANALYSES`; a family listing ``ltca`` declares
    the keys :data:`gearrep.cli.keys.LOAD`, :data:`~gearrep.cli.keys.MATERIAL` per member and
    :data:`~gearrep.cli.keys.LOADED_ANALYSIS`, and its pair is a :class:`PairFamily`'s)."""

    name: str = ""
    keys: dict = {}
    param_names: tuple = ("u", "v")
    analyses: tuple = UNLOADED

    def build(self, values: dict) -> Design:
        """The pair of the resolved design ``values``, its geometry checked (SettingError naming
        the key, value and allowed range); no contact solve."""
        raise NotImplementedError

    def check_contact(self, design: Design) -> None:
        """Check that the flanks of the built ``design`` meet where the analyses start (and set
        what that finds on it); SettingError naming the key otherwise."""
        raise NotImplementedError

    def tca(self, design: Design, progress=None) -> tuple:
        """(contact_path, te_cycle, summary entries, further tables) of ``gearrep tca`` over the
        meshing cycle, with ``d.analysis['n_points']`` positions."""
        raise NotImplementedError

    def sweep_point(self, design: Design, n_phi: int) -> dict:
        """The metrics of one sweep point (``gearrep sweep``) with ``n_phi`` contact positions."""
        raise NotImplementedError

    def solves_per_point(self, n_phi: int) -> int:
        """Contact solves of one sweep point with ``n_phi`` positions (the sweep's shard sizes)."""
        raise NotImplementedError

    def curvature_table(self, design: Design) -> pd.DataFrame:
        """Principal curvatures [1/mm] and directions on the curvature grid over both flanks."""
        raise NotImplementedError

    def flank_cloud(self, design: Design, member: int) -> tuple:
        """(points (n_u, n_v, 3) with NaN off the flank, outward unit normals, table) of member
        ``member``'s flank on the flank grid."""
        raise NotImplementedError

    def iso_contact_ratios(self, design: Design) -> dict:
        """The ISO contact ratios of the nominal pair (:data:`ISO_RATIOS`); NaN by default."""
        return dict.fromkeys(ISO_RATIOS, float("nan"))

    def why_not(self, design: Design, analysis: str) -> str:
        """Why the family does not support ``analysis`` (shown in the refusal): for ``ltca`` the
        library's reason for refusing :meth:`pinion_surface` (:func:`gearrep.ltca.refusal`); ""
        otherwise."""
        if analysis != "ltca":
            return ""
        why = refusal(self.pinion_surface(design))
        return f"gearrep.ltca refuses {self.name} flanks: {why}" if why else ""

    def pinion_surface(self, design: Design):
        """The pinion's flank surface (by default ``d.pair.flank1``)."""
        return design.pair.flank1

    def iso_pitch_pressure_MPa(self, design: Design) -> float:
        """ISO 6336-2's nominal pitch-point contact stress of the nominal pair under the design's
        load and materials (``gearrep ltca``'s reference); NaN by default (no closed form)."""
        return float("nan")

    def pitch_radius_mm(self, design: Design) -> float:
        """Operating pitch radius [mm] of the pinion: r_w1 = a' N1 / (N1 + N2), a' the centre distance
        (N1 + N2) m_t / 2 of a cylindrical pair (from ``module_mm``, the teeth and
        ``helix_angle_deg``) moved by the misalignment's ``d_E_mm`` and ``d_H_mm`` (``gearrep
        ltca``'s pitch position: where the contact reaches it)."""
        v = design.values
        n1, n2 = v["pinion"]["teeth"], v["gear"]["teeth"]
        m_t = v["module_mm"] / np.cos(np.radians(v.get("helix_angle_deg", 0.0)))
        mis = v.get("misalignment", {})
        a = float(np.hypot(0.5 * m_t * (n1 + n2) + mis.get("d_E_mm", 0.0), mis.get("d_H_mm", 0.0)))
        return a * n1 / (n1 + n2)

    def te_radius_mm(self, design: Design) -> float:
        """Radius [mm] that turns a TE of the driven gear in angle into a displacement along the
        line of action (figures): by default the base radius r_b2 = r_p2 cos(alpha_t) of a
        cylindrical gear from ``module_mm``, ``gear.teeth``, ``pressure_angle_deg`` and
        ``helix_angle_deg`` (0 where the family has none)."""
        v = design.values
        beta = np.radians(v.get("helix_angle_deg", 0.0))
        alpha_t = np.arctan(np.tan(np.radians(v["pressure_angle_deg"])) / np.cos(beta))
        return float(0.5 * v["gear"]["teeth"] * v["module_mm"] / np.cos(beta) * np.cos(alpha_t))

    def draw_face_edges(self, design: Design, ax) -> None:
        """Draw the pinion's face edges on the contact-path figure (axial position [mm] against
        radius [mm]): by default the planes at +-face_width_mm / 2 from mid-face."""
        half = 0.5 * design.values["face_width_mm"]
        ax.axvline(-half, c="0.5", lw=0.6)
        ax.axvline(half, c="0.5", lw=0.6)


class PairFamily(Family):
    """A family whose pair is a :class:`gearrep.tca.GearPair` (module docstring). Subclasses set
    ``name``, ``keys`` and ``param_names`` and implement :meth:`build`; the class attributes
    ``formulation`` (of the robust solve: ``reduced`` needs member 2 in explicit form),
    ``contact_ratio_method`` (the summary's words for how the engagement limits were found) and
    ``engagement_solves`` (the solves that find them, beyond the path's) may be set too."""

    formulation = "reduced"
    contact_ratio_method = "engagement limits solved on the flank boundaries"
    #: contact solves that find the engagement limits (about 40 for the walk of
    #: :func:`gearrep.meshing.engagement_limits` in steps of a tenth of the angular pitch through a
    #: contact ratio up to about 3, and the boundary solves)
    engagement_solves = 40

    # -- the pair, its start and its flanks -----------------------------------------------------
    def misalignment(self, values: dict):
        """The library's misalignment of the resolved design (by default the keys of
        :data:`gearrep.cli.keys.MISALIGNMENT`)."""
        return misalignment(values)

    def remisaligned(self, design: Design, values: dict) -> Design:
        """The ``design`` under the misalignment of ``values`` (the rest of the design unchanged)."""
        return Design(values, self, design.pair.with_misalignment(self.misalignment(values)), mesh=design.mesh)

    def mesh_check(self, design: Design) -> None:
        """Checks of the meshing that need no contact solve, run before the contact check (none
        by default)."""

    def line_section(self, design: Design):
        """Face coordinate v1 of member 1 in which a line contact is traced (None: the family's
        flanks never touch along a line)."""
        return None

    def nominal(self, design: Design, phi1):
        """For a member 2 without explicit form: ``nominal(pair, phi)`` -> (n, 5) conventional
        starts at angles ``phi`` among ``phi1`` [rad] (:func:`gearrep.tca.robust_contact` completes
        its starts with them); None (the default) for an explicit member 2."""
        return None

    def starts(self, design: Design, phi1, nominal=None) -> tuple:
        """(u1, v1) starts on flank 1 at the angles ``phi1`` [rad]: those of the ``nominal`` starts
        where the family has them, else the middle of flank 1's box."""
        phi1 = np.atleast_1d(np.asarray(phi1, float))
        if nominal is not None:
            x = np.asarray(nominal(design.pair, phi1), float)
            return x[:, 0], x[:, 1]
        mid = 0.5 * (design.pair.lower1 + design.pair.upper1)
        return np.full(len(phi1), mid[0]), np.full(len(phi1), mid[1])

    def on_flanks(self, design: Design, c, face: bool = True):
        """``c`` with the contacts outside the true flanks (where the solve's box is wider) marked
        OFF_FLANK and NaN; ``face=False`` keeps contacts beyond the face width where a family
        extends its flanks along the face. By default ``c``."""
        return c

    #: the degree in the angle of the offset by which :meth:`robust_solve` moves the starts of many
    #: angles along the path (:func:`gearrep.tca.offset_start`)
    start_order = 2

    def robust_solve(self, d: Design, phi1, fallback: bool = True):
        """:func:`gearrep.tca.robust_contact` at pinion angles ``phi1`` [rad] from :meth:`starts`
        (completed by :meth:`nominal`), with the design's tolerance and iteration limit;
        ``fallback=False``: the strategy's first step alone (projection and solve).

        Where member 2 is explicit (no :meth:`nominal`), the starts of more than
        :attr:`start_order` + 1 angles are first moved along the path: by the offset, a
        polynomial of degree :attr:`start_order` in the angle, of the contacts that the same
        robust solve finds from the family's start at a few of the angles
        (:func:`gearrep.tca.offset_start`). The family's start (the middle of flank 1) is far from
        the contact near the ends of a long path, where damped Newton creeps or fails and the
        strategy restarts from its grid: the spiral bevel example's 1001-angle path took 20.4
        Newton iterations per angle from it, 2.2 from the moved starts, the same contacts."""
        s = d.analysis
        phi1 = np.atleast_1d(np.asarray(phi1, float))
        kw = dict(formulation=self.formulation, tol=s["tol"], maxiter=s["maxiter"])
        with np.errstate(all="ignore"):
            nominal = self.nominal(d, phi1)
            u1, v1 = self.starts(d, phi1, nominal)
            if nominal is None:
                moved = offset_start(
                    d.pair,
                    phi1,
                    lambda pair, ph: np.column_stack(self.starts(d, ph)),
                    formulation="reduced",
                    solve=lambda pair, ph, x0: robust_contact(pair, ph, x0[:, 0], x0[:, 1], **kw),
                    order=self.start_order,
                )
                u1, v1 = moved[:, 0], moved[:, 1]
            return robust_contact(d.pair, phi1, u1, v1, nominal=nominal, fallback=fallback, **kw)

    def contact_at(self, design: Design, phi1, face: bool = True):
        """Contact points (:class:`gearrep.tca.ContactPoints`) at pinion angles ``phi1`` [rad], one
        independent solve each: :meth:`robust_solve` (a line contact: the fixed section
        :meth:`line_section`), then :meth:`on_flanks`."""
        if design.line_contact:
            analysis = design.analysis
            with np.errstate(all="ignore"):
                c = solve_contact(
                    design.pair, phi1, v1=self.line_section(design), tol=analysis["tol"], maxiter=analysis["maxiter"]
                )
        else:
            c = self.robust_solve(design, phi1)
        return self.on_flanks(design, c, face)

    def conjugate(self, design: Design) -> bool:
        """Whether the design's flanks are conjugate by construction (unmodified lengthwise and
        aligned, so that they touch along a line; False by default)."""
        return False

    def is_line_contact(self, design: Design) -> bool:
        """Whether the flanks touch along a line: conjugate by construction (:meth:`conjugate`), or
        the contact system at phi1 = 0 solved from the projected start (the robust strategy's first
        step) is singular; False for a family without :meth:`line_section`."""
        if self.line_section(design) is None:
            return False
        if self.conjugate(design):
            return True
        return bool(self.robust_solve(design, [0.0], fallback=False).status[0] == Status.SINGULAR)

    # -- the contact check ------------------------------------------------------------------------
    def check_contact(self, design: Design) -> None:
        """Solve the contact at phi1 = 0 and refuse a design whose flanks do not meet there inside
        their limits, naming the misalignment (and its approximate limit) when one is given."""
        self.mesh_check(design)
        design.line_contact = self.is_line_contact(design)
        c = self.contact_at(design, [0.0], face=False)  # a family extending its flanks along the face: anywhere on it
        if c.converged[0]:
            return
        values = design.values
        mis = {k: x for k, x in values["misalignment"].items() if x != 0.0}
        if not mis:
            raise SettingError(
                f"design: no contact inside the flanks at the pitch position of the aligned pair (solve status "
                f"{c.status_name[0]}); allowed: a pair whose flanks meet there (check teeth, module and profile "
                "shifts)"
            )
        if len(mis) == 1:
            name, x = next(iter(mis.items()))
            limit = self.largest_with_contact(design, name, x)
            raise SettingError(
                f"design.misalignment.{name}: got {x!r}; allowed: |{name}| below about {limit:.2g} for this pair (larger "
                f"values move the contact at the pitch position off the flanks: status {c.status_name[0]})"
            )
        raise SettingError(
            f"design.misalignment: got {mis!r}; allowed: a misalignment that keeps the contact at the pitch "
            f"position inside the flanks (solve status there: {c.status_name[0]})"
        )

    def largest_with_contact(self, design: Design, name: str, x: float, steps: int = 6) -> float:
        """Bisection on the magnitude of misalignment ``name`` (same sign as ``x``) between 0
        (contact) and ``x`` (none): the smallest magnitude found without contact at phi1 = 0, to
        2^-steps of |x| (an estimate of the limit, which the message calls approximate)."""
        lo, hi = 0.0, abs(x)
        for _ in range(steps):
            mid = 0.5 * (lo + hi)
            dm = self.remisaligned(design, set_dotted(design.values, f"misalignment.{name}", math.copysign(mid, x)))
            c = self.contact_at(dm, [0.0], face=False)
            lo, hi = (mid, hi) if c.converged[0] else (lo, mid)
        return hi

    # -- the meshing cycle ----------------------------------------------------------------------
    def start_at_zero(self, design: Design) -> np.ndarray:
        """(1, 2) reduced unknowns (u1, v1) of the contact at phi1 = 0 (the start of the walks
        along the path); ValueError when there is none."""
        c = self.contact_at(design, [0.0])
        if not c.converged[0]:
            raise ValueError(f"no contact inside the flanks at phi1 = 0 (status {c.status_name[0]})")
        return c.unknowns("reduced")

    def engagement(self, design: Design) -> tuple:
        """Engagement limits (phi_1B, phi_1E) [rad] of one tooth pair: the angles at which the
        contact reaches a flank boundary, solved exactly (:func:`gearrep.meshing.engagement_limits`
        from the contact at phi1 = 0, the same solve as :meth:`meshing_cycle_tables`)."""
        start = self.start_at_zero(design)
        v1 = self.line_section(design) if design.line_contact else None
        with np.errstate(all="ignore"):
            b, e = engagement_limits(design.pair, 0.0, start, v1=v1, tol=design.analysis["tol"])
        return b.phi1, e.phi1

    def drive(self, design: Design) -> float:
        """+1 if member 1's flank moves along its outward normal as phi1 grows (it pushes member 2:
        the TE over the cycle is the most advanced tooth pair's), else -1
        (:func:`gearrep.tca.flank_sense`)."""
        with np.errstate(all="ignore"):
            return 1.0 if float(flank_sense(design.pair, [0.0])[0]) >= 0 else -1.0

    def sampled_cycle(self, design: Design, n_phi: int) -> tuple:
        """(path ContactPoints on the engagement interval, TE envelope table, summary entries) with
        ``n_phi`` positions from :meth:`engagement` (``gearrep sweep`` of every family, ``gearrep
        tca`` of the families without an exact cycle)."""
        p1 = 2.0 * np.pi / design.pair.n1
        b, e = self.engagement(design)
        phi = np.linspace(b, e, int(n_phi))
        c = self.contact_at(design, phi)
        te = np.where(c.converged & (phi >= b - 1e-12) & (phi <= e + 1e-12), c.te, np.nan)
        drive = self.drive(design)
        at, env, lead = te_envelope(phi, te, drive, p1, b, n_phi)
        table = pd.DataFrame({"phi1_rad": at, "te_arcsec": env / ARCSEC, "tooth_pair": lead})
        summary = {
            "contact_ratio": float(contact_ratio(b, e, design.pair.n1)),
            "contact_ratio_method": self.contact_ratio_method,
            **cycle_summary(b, e, env, drive),
            "solves": self.solves_per_point(int(n_phi)),
        }
        return c, table, summary

    def meshing_cycle_tables(self, design: Design) -> tuple:
        """The :meth:`tca` tables from the library's meshing cycle
        (:func:`gearrep.meshing.meshing_cycle` from the contact at phi1 = 0: engagement limits
        solved exactly, the contact ratio, the TE envelope and the kind of transfer between pairs)."""
        analysis = design.analysis
        v1 = self.line_section(design) if design.line_contact else None
        start = self.start_at_zero(design)
        with np.errstate(all="ignore"):
            cyc = meshing_cycle(design.pair, 0.0, start, v1=v1, n_points=analysis["n_points"], tol=analysis["tol"])
        te = pd.DataFrame({"phi1_rad": cyc.phi1, "te_arcsec": cyc.te / ARCSEC, "tooth_pair": cyc.pair_index})
        summary = {
            "contact_ratio": cyc.contact_ratio,
            "contact_ratio_method": self.contact_ratio_method,
            "phi1_begin_rad": cyc.begin.phi1,
            "phi1_end_rad": cyc.end.phi1,
            "te_peak_to_peak_arcsec": cyc.te_peak_to_peak / ARCSEC,
            "drive_sense": "max",
            "transfer_kind": cyc.transfer_kind,
        }
        return self.path_table(design, cyc.path), te, summary, {}

    def tca(self, design: Design, progress=None) -> tuple:
        """The sampled cycle (:meth:`sampled_cycle`) with its contact path; families with an exact
        cycle return :meth:`meshing_cycle_tables` instead."""
        c, te, summary = self.sampled_cycle(design, design.analysis["n_points"])
        return self.path_table(design, c), te, summary, {}

    def edges(self, design: Design, P) -> list:
        """Half-spaces of the flank edges at the contact points ``P`` (n, 3) [mm] that cut the
        contact ellipses (:func:`gearrep.cli.edges.cut_at_edges`): by default the face planes and
        tip cylinders of members on parallel or crossed axes (:func:`gearrep.cli.edges.axial_edges`)."""
        return axial_edges(design.pair, design.values["face_width_mm"], P)

    def ellipses(self, design: Design, c):
        """The contact ellipses of the contacts ``c`` at the design's elastic approach, NaN where
        the contact is no ellipse (a line contact: relative curvature zero to rounding)."""
        with np.errstate(all="ignore"):
            el = contact_ellipse(design.pair, c, design.analysis["elastic_approach_mm"])
        ell = np.asarray(el.elliptic, bool) & (not design.line_contact)
        return el._replace(
            a=np.where(ell, el.a, np.nan),
            b=np.where(ell, el.b, np.nan),
            area=np.where(ell, el.area, np.nan),
            major_axis=np.where(ell[:, None], el.major_axis, np.nan),
        )

    def path_table(self, design: Design, c) -> pd.DataFrame:
        """The contact-path table of the contacts ``c``: solve record, flank parameters, point,
        normal, the contact ellipse and its cut at the flank edges."""
        pu, pv = self.param_names
        el = self.ellipses(design, c)
        r = np.hypot(c.position[:, 0], c.position[:, 1])
        cut = cut_at_edges(lambda P: self.edges(design, P), c.position, c.normal, el.major_axis, el.a, el.b)
        return pd.DataFrame(
            {
                "phi1_rad": c.phi1,
                "phi2_rad": c.phi2,
                "te_arcsec": np.where(c.converged, c.te / ARCSEC, np.nan),
                "status": c.status_name,
                "residual": c.residual,
                "iterations": c.iterations,
                f"pinion_{pu}": c.u1,
                f"pinion_{pv}": c.v1,
                f"gear_{pu}": c.u2,
                f"gear_{pv}": c.v2,
                "x_mm": c.position[:, 0],
                "y_mm": c.position[:, 1],
                "z_mm": c.position[:, 2],
                "radius_on_pinion_mm": r,
                "normal_x": c.normal[:, 0],
                "normal_y": c.normal[:, 1],
                "normal_z": c.normal[:, 2],
                "ellipse_semi_major_mm": el.a,
                "ellipse_semi_minor_mm": el.b,
                "ellipse_area_mm2": el.area,
                "ellipse_major_x": el.major_axis[:, 0],
                "ellipse_major_y": el.major_axis[:, 1],
                "ellipse_major_z": el.major_axis[:, 2],
                "ellipse_major_from_mm": cut.lo,
                "ellipse_major_to_mm": cut.hi,
                "ellipse_area_on_flank_mm2": cut.area,
                "edge_contact": cut.edge,
            }
        )

    def solves_per_point(self, n_phi: int) -> int:
        """The path's ``n_phi`` solves and the :attr:`engagement_solves` that find its limits."""
        return int(n_phi) + self.engagement_solves

    def sweep_point(self, design: Design, n_phi: int) -> dict:
        """TE over the meshing cycle (envelope of the sampled pairs), contact ratio, largest
        contact-ellipse semi-axis, convergence (:meth:`sampled_cycle` with ``n_phi`` positions)."""
        c, _, summary = self.sampled_cycle(design, n_phi)
        a = self.ellipses(design, c).a
        ok = c.converged
        return {
            "contact_ratio": summary["contact_ratio"],
            "te_peak_to_peak_arcsec": summary["te_peak_to_peak_arcsec"],
            "max_ellipse_semi_major_mm": float(np.nanmax(a)) if np.isfinite(a).any() else float("nan"),
            "solves": summary["solves"],
            "converged": int(ok.sum()),
            "max_residual_mm": float(c.residual[ok].max()) if ok.any() else float("nan"),
        }

    # -- flank grids: curvatures and point clouds, each member in its own frame ------------------
    def member(self, design: Design, member: int) -> tuple:
        """(flank, lower, upper, outward sign) of member ``member`` (1: pinion, 2: gear)."""
        p = design.pair
        return (p.flank1, p.lower1, p.upper1, p.sign1) if member == 1 else (p.flank2, p.lower2, p.upper2, p.sign2)

    def flank_grid(self, design: Design, member: int, n_u: int, n_v: int) -> tuple:
        """(flank, u, v): the parameters of an n_u x n_v grid over member ``member``'s flank
        (ravelled, profile-major), kept where the flank exists; by default its box."""
        flank, lo, hi, _ = self.member(design, member)
        u, v = np.meshgrid(np.linspace(lo[0], hi[0], n_u), np.linspace(lo[1], hi[1], n_v), indexing="ij")
        return flank, u.ravel(), v.ravel()

    def cloud_grid(self, design: Design, member: int, n_u: int, n_v: int) -> tuple:
        """(u, v, keep) of the n_u x n_v point cloud (the full grid; ``keep`` False where it leaves
        the flank): by default :meth:`flank_grid`, all kept."""
        _, u, v = self.flank_grid(design, member, n_u, n_v)
        return u, v, np.ones(len(u), bool)

    def curvature_table(self, design: Design) -> pd.DataFrame:
        """Principal curvatures [1/mm] and directions on :meth:`flank_grid` over both flanks (each
        in its own frame; curvature positive where the surface bends toward its outward normal)."""
        n_u, n_v = design.analysis["curvature_grid"][:2]
        rows = []
        for member, name in ((1, "pinion"), (2, "gear")):
            flank, u, v = self.flank_grid(design, member, n_u, n_v)
            sign = self.member(design, member)[3]
            with np.errstate(all="ignore"):
                P = flank.evaluate(u, v)
                pc = principal_curvatures(P)
                if sign < 0:
                    pc = with_opposite_normal(pc)
            rows.append(curvature_frame(name, self.param_names, u, v, P.r, pc))
        return pd.concat(rows, ignore_index=True)

    def flank_cloud(self, design: Design, member: int) -> tuple:
        """Point cloud of member ``member``'s flank in its own frame on :meth:`cloud_grid`."""
        n_u, n_v = design.analysis["flank_grid"][:2]
        flank, _, _, sign = self.member(design, member)
        u, v, keep = self.cloud_grid(design, member, n_u, n_v)
        with np.errstate(all="ignore"):
            P = flank.evaluate(u, v)
            nrm = sign * P.normal
        return cloud(self.param_names, u, v, P.r, nrm, keep, n_u, n_v)
