"""The ``catt`` family: cylindrical gears with arc tooth traces (CATT, seed 004), cut by a
circular-arc cutter of radius R_T; :func:`gearrep.surfaces.catt.assemble` mounts both members.

The flanks are parameterised by the cutter (no explicit form): contacts are solved with the
conventional formulation, completed from the study's middle-section starts
(:func:`gearrep.surfaces.catt.starts`, moved half a module off the middle section). The solve's
box is a box around the true flank boundaries (root-form and tip circles, face edges), which mark
the contacts outside them. The engagement interval is the middle section's, in closed form
(:func:`gearrep.surfaces.catt.path_limits`).
"""

from __future__ import annotations

import math

import numpy as np

from ... import settings as st
from ...settings import SettingError
from ...solve import Status
from ...surfaces.catt import assemble, path_limits, starts
from ..family import UNLOADED, Design, PairFamily
from ..keys import LOAD, LOADED_ANALYSIS, MATERIAL, MISALIGNMENT, head
from .involute import undercut_teeth

__all__ = ["KEYS", "CATTFamily", "FAMILY"]

KEYS = st.declare(
    **head("catt", "module of the middle section"),
    cutter_radius_mm=st.number(None, "mm", "cutter (tooth-trace arc) radius R_T", gt=0, le=1e5),
    pressure_angle_deg=st.number(20.0, "deg", "blade pressure angle", ge=10, le=35),
    addendum=st.number(1.0, "1", "addendum coefficient h*", ge=0.5, le=1.5),
    clearance=st.number(0.25, "1", "clearance coefficient c*", ge=0, le=0.5),
    flank_pair=st.choice(
        "B", ("A", "B"), "A: pinion convex on gear concave; B: pinion concave on gear convex (seed 004 assembly)"
    ),
    pinion=st.group(
        "member 1 (the driving member unless load.driving says gear)",
        teeth=st.integer(None, "1", "number of teeth", ge=5, le=10000),
        material=MATERIAL,
    ),
    gear=st.group("member 2", teeth=st.integer(None, "1", "number of teeth", ge=5, le=10000), material=MATERIAL),
    misalignment=MISALIGNMENT,
    load=LOAD,
    analysis=LOADED_ANALYSIS,
)


class CATTFamily(PairFamily):
    """CATT pairs (module docstring)."""

    name = "catt"
    keys = KEYS
    param_names = ("theta_rad", "phi_rad")
    formulation = "conventional"
    analyses = (*UNLOADED, "ltca")
    contact_ratio_method = "middle-section closed form"
    engagement_solves = 0  # closed form

    def build(self, values: dict) -> Design:
        v = values
        m, B, R_T = v["module_mm"], v["face_width_mm"], v["cutter_radius_mm"]
        least = 0.5 * B + math.pi * m
        if not R_T > least:
            raise SettingError(
                f"design.cutter_radius_mm: got {R_T!r}; allowed: above half the face width plus pi modules "
                f"({least:.6g} mm), so that the arc spans the face"
            )
        for member in ("pinion", "gear"):
            # the middle section is an involute cut by a straight rack of addendum h* (seed 004 eq 5)
            undercut_teeth(member, v[member]["teeth"], m, v["pressure_angle_deg"], B, v["addendum"], "")
        design = {"z1": v["pinion"]["teeth"], "z2": v["gear"]["teeth"], "module": m, "R_T": R_T, "face_width": B}
        params = {"pressure_angle_deg": v["pressure_angle_deg"], "addendum": v["addendum"], "clearance": v["clearance"]}
        mesh = assemble(design, v["flank_pair"], params)
        mesh.gear_pair = mesh.gear_pair.with_misalignment(self.misalignment(v))
        return Design(v, self, mesh.gear_pair, mesh=mesh)

    def nominal(self, design: Design, phi1):
        """The study's starts: the middle-section estimate moved half a module off it."""
        offset = 0.5 * design.values["module_mm"]
        return lambda pair, ph: starts(design.mesh, ph, offset)

    def on_flanks(self, design: Design, c, face: bool = True):
        """Contacts outside the true flank boundaries (the solve bounds are a box around them) get
        status OFF_FLANK."""
        ok = c.converged
        inside = np.zeros(len(c), bool)
        if ok.any():
            inside[ok] = np.asarray(design.pair.flank1.contains(c.u1[ok], c.v1[ok]), bool) & np.asarray(
                design.pair.flank2.contains(c.u2[ok], c.v2[ok]), bool
            )
        st_ = c.status.copy()
        st_[ok & ~inside] = Status.OFF_FLANK
        return type(c)(**{**c.__dict__, "status": st_}).failed_as_nan()

    def engagement(self, design: Design) -> tuple:
        lim = path_limits(design.mesh)
        return lim["phi1_lo"], lim["phi1_hi"]

    def flank_grid(self, design: Design, member: int, n_u: int, n_v: int) -> tuple:
        """The box grid kept where the flank exists (its true boundaries)."""
        flank, u, v = super().flank_grid(design, member, n_u, n_v)
        keep = np.asarray(flank.contains(u, v), bool)
        return flank, u[keep], v[keep]

    def cloud_grid(self, design: Design, member: int, n_u: int, n_v: int) -> tuple:
        """The full box grid (the cloud keeps its shape), NaN outside the flank."""
        flank, u, v = super().flank_grid(design, member, n_u, n_v)
        return u, v, np.asarray(flank.contains(u, v), bool)


FAMILY = CATTFamily()
