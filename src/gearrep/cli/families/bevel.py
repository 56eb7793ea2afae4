"""The ``bevel`` family: straight and logarithmic-spiral bevel pairs with spherical-involute
profiles on intersecting axes (the thesis's sec 5.1-5.2 pairs, seed 003), with lengthwise crowning
and tip/root relief on either member.

The members are :class:`gearrep.surfaces.bevel.SphericalInvoluteFlank` (flank parameters: the
polar angle u from the member's axis and the cone distance v from the apex) from
:func:`gearrep.surfaces.bevel.mating_bevel_flanks` in a :class:`gearrep.tca.BevelPair`, with the
assembly errors of :class:`gearrep.tca.BevelMisalignment` (thesis eq 47-48). ``module_mm`` is the
transverse module at the outer cone distance R_e; the crowning is a function of the cone distance
about the mean cone distance R_m = R_e - b / 2; a relief length runs along the profile at R_m
(:func:`gearrep.surfaces.bevel.relief_from_length`). ``spiral_angle_deg`` is the spiral angle on
the base cone (0: straight teeth), and ``pinion_flank`` which lengthwise flank of a spiral pinion
drives. The TCA is the library's meshing cycle (engagement limits solved on the flank
boundaries); an aligned unmodified pair is in line contact along a generatrix, traced at R_m.
The contact ellipses end at the flank edges: the spheres v = R_e - b and v = R_e about each
member's apex and its face cone.
"""

from __future__ import annotations

import math

import numpy as np

from ... import settings as st
from ...settings import SettingError
from ...surfaces.bevel import BevelGearData, mating_bevel_flanks, relief_from_length, spherical_involute_azimuth
from ...tca import BevelMisalignment, BevelPair
from ..family import Design, PairFamily
from ..keys import ANALYSIS, CROWNING, crowning, head, relief
from .involute import check_crowning, crowned, refuse_relief

__all__ = ["KEYS", "BevelFamily", "FAMILY", "cone_edges"]

_RELIEF = relief(
    "profile relief (parabolic in the polar angle, thesis eq 13)",
    "material removed at the tip (tip relief) or root cone (root relief)",
    "length of the relief along the profile at the mean cone distance",
)


def _member(reason):
    return st.group(
        reason,
        teeth=st.integer(None, "1", "number of teeth", ge=5, le=10000),
        crowning=CROWNING,
        tip_relief=_RELIEF,
        root_relief=_RELIEF,
    )


KEYS = st.declare(
    **head("bevel", "transverse module at the outer cone distance"),
    pressure_angle_deg=st.number(20.0, "deg", "profile angle at the pitch cone", ge=10, le=35),
    shaft_angle_deg=st.number(90.0, "deg", "angle between the intersecting axes", ge=10, le=170),
    spiral_angle_deg=st.number(
        0.0,
        "deg",
        "spiral angle on the base cone of the logarithmic spiral (thesis eq 51); 0: straight teeth",
        ge=0,
        le=60,
    ),
    pinion_flank=st.choice(
        "convex",
        ("convex", "concave"),
        "lengthwise flank of the pinion that drives a spiral pair: convex (on the gear's concave flank) or concave "
        "(no effect on straight teeth)",
    ),
    addendum=st.number(1.0, "1", "addendum coefficient h_a at the outer cone distance", ge=0.5, le=1.5),
    dedendum=st.number(1.25, "1", "dedendum coefficient h_f at the outer cone distance", ge=0.8, le=2),
    pinion=_member("the driving member (member 1)"),
    gear=_member("the driven member (member 2)"),
    misalignment=st.group(
        "assembly errors of a bevel pair (thesis eq 47-48), the angle pivoting about the pinion's apex",
        d_gamma_deg=st.number(0.0, "deg", "shaft-angle change: the shaft angle becomes Sigma - d_gamma", ge=-5, le=5),
        d_E_mm=st.number(0.0, "mm", "offset of the gear along the common perpendicular of the axes", ge=-100, le=100),
        d_A_mm=st.number(0.0, "mm", "axial displacement of the pinion along its axis", ge=-100, le=100),
        d_G_mm=st.number(0.0, "mm", "axial displacement of the gear along its axis", ge=-100, le=100),
    ),
    analysis=ANALYSIS,
)


def _gears(v) -> tuple[BevelGearData, BevelGearData]:
    kw = dict(
        module=v["module_mm"],
        pressure_angle=math.radians(v["pressure_angle_deg"]),
        face_width=v["face_width_mm"],
        shaft_angle=math.radians(v["shaft_angle_deg"]),
        spiral_angle=math.radians(v["spiral_angle_deg"]),
        h_a=v["addendum"],
        h_f=v["dedendum"],
    )
    n1, n2 = v["pinion"]["teeth"], v["gear"]["teeth"]
    g1 = BevelGearData(n1, n2, **kw)
    if not v["face_width_mm"] < g1.outer_cone_distance:
        raise SettingError(
            f"design.face_width_mm: got {v['face_width_mm']!r}; allowed: below the outer cone distance "
            f"{g1.outer_cone_distance:.6g} mm (module x teeth / (2 sin of the pitch cone angle))"
        )
    return g1, BevelGearData(n2, n1, **kw)


def _half_thickness(g: BevelGearData, u: float, v: float) -> float:
    """Half the tooth thickness [mm] along the profile normal at polar angle ``u`` [rad] and cone
    distance ``v`` [mm] of the unmodified tooth: its flank's azimuth from the tooth's centre,
    pi / (2 N) + I(delta_p) - I(u), times v sin(a_b) (an offset along the normal turns the spherical
    involute about the axis by offset / (v sin a_b))."""
    a_b = g.base_cone_angle
    c = math.pi / (2 * g.n_teeth) + float(spherical_involute_azimuth(g.pitch_cone_angle, a_b))
    return (c - float(spherical_involute_azimuth(u, a_b))) * v * math.sin(a_b)


def _modifications(v, member: str, g: BevelGearData) -> tuple:
    """(crowning, reliefs) of ``member``, refused where they remove more than the tooth holds at
    the inner end of the face (crown plus tip relief at the face cone, crown plus root relief at
    the start of the flank) or a relief is longer than the flank's depth at R_m."""
    check_crowning(v, member)
    mv = v[member]
    u_lo, u_hi = max(g.base_cone_angle, g.root_cone_angle), g.face_cone_angle
    inner = g.outer_cone_distance - g.face_width
    tip = _half_thickness(g, u_hi, inner)
    if not tip > 0:
        raise SettingError(
            f"design.addendum: got {v['addendum']!r}; allowed: a smaller addendum (the {member}'s tooth is pointed "
            f"below its face cone at the inner end of the face, {inner:.4g} mm from the apex)"
        )
    crown = mv["crowning"]["crown_mm"] if mv["crowning"]["kind"] != "none" else 0.0
    for key, amount, u, where in (
        ("crowning.crown_mm", crown, u_hi, "the face cone"),
        ("tip_relief.amount_mm", mv["tip_relief"]["amount_mm"], u_hi, "the face cone"),
        ("root_relief.amount_mm", mv["root_relief"]["amount_mm"], u_lo, "the start of the flank"),
    ):
        most = _half_thickness(g, u, inner) - (crown if key != "crowning.crown_mm" else 0.0)
        if amount > 0 and not amount < most:
            raise SettingError(
                f"design.{member}.{key}: got {amount!r}; allowed: below {most:.4g} mm (more removes the whole tooth "
                f"thickness at {where} at the inner end of the face, {inner:.4g} mm from the apex: the flank would "
                "cross the tooth's centre)"
            )
    depth = (u_hi - u_lo) * g.mean_cone_distance
    relief = []
    for key, root in (("tip_relief", False), ("root_relief", True)):
        r = mv[key]
        if r["amount_mm"] == 0.0:
            continue
        if not r["length_mm"] < depth:
            raise SettingError(
                f"design.{member}.{key}.length_mm: got {r['length_mm']!r}; allowed: below the depth of the flank "
                f"along the profile at the mean cone distance ({depth:.6g} mm)"
            )
        relief.append(relief_from_length(g, r["length_mm"], r["amount_mm"], root=root))
    return crowning(mv["crowning"], g.face_width, v0=g.mean_cone_distance), tuple(relief)


def cone_edges(pair, P) -> list:
    """Half-spaces (name, u (n, 3), d (n,)) of the flank edges of a :class:`gearrep.tca.BevelPair`
    at the contact points ``P`` (n, 3) [mm] (:func:`gearrep.cli.edges.cut_at_edges`): each member's
    face ends, the spheres of cone distance R_e - b and R_e about its apex (the plane normal to the
    radius through P), and its face cone (the plane tangent to it along the great circle through P,
    at distance rho sin(delta_a - u) from P: rho the cone distance and u the polar angle of P)."""
    out = []
    for member, flank, apex, axis in (
        ("pinion", pair.flank1, np.zeros(3), np.array([0.0, 0.0, 1.0])),
        ("gear", pair.flank2, np.asarray(pair.O2, float), pair.A2[:, 2]),
    ):
        g = flank.gear
        rel = np.asarray(P, float) - apex
        rho = np.linalg.norm(rel, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            e_rho = rel / rho[:, None]
            ax = rel @ axis
            radial = rel - np.outer(ax, axis)
            r = np.linalg.norm(radial, axis=1)
            u = np.arctan2(r, ax)
            e_u = np.cos(u)[:, None] * radial / r[:, None] - np.sin(u)[:, None] * axis
        out.append((f"{member}_face", e_rho, g.outer_cone_distance - rho))
        out.append((f"{member}_face", -e_rho, rho - (g.outer_cone_distance - g.face_width)))
        out.append((f"{member}_tip", e_u, rho * np.sin(g.face_cone_angle - u)))
    return out


class BevelFamily(PairFamily):
    """Straight and spiral bevel pairs (module docstring)."""

    name = "bevel"
    keys = KEYS
    param_names = ("polar_angle_rad", "cone_distance_mm")

    def misalignment(self, values: dict) -> BevelMisalignment:
        m = values["misalignment"]
        return BevelMisalignment(
            d_A=m["d_A_mm"], d_E=m["d_E_mm"], d_G=m["d_G_mm"], d_gamma=math.radians(m["d_gamma_deg"])
        )

    def build(self, values: dict) -> Design:
        v = values
        g1, g2 = _gears(v)
        c1, r1 = _modifications(v, "pinion", g1)
        c2, r2 = _modifications(v, "gear", g2)
        hand1 = 1 if v["pinion_flank"] == "convex" else -1
        f1, f2 = mating_bevel_flanks(g1, g2, hand1=hand1, crowning1=c1, relief1=r1, crowning2=c2, relief2=r2)
        pair = BevelPair(
            f1,
            f2,
            g1.n_teeth,
            g2.n_teeth,
            shaft_angle=math.radians(v["shaft_angle_deg"]),
            misalignment=self.misalignment(v),
        )
        return Design(v, self, pair)

    def line_section(self, design: Design) -> float:
        return design.pair.flank1.gear.mean_cone_distance

    def conjugate(self, design: Design) -> bool:
        """No crown on either member and no assembly error: the spherical-involute flanks
        (straight, or spirals of opposite hands) touch along a line."""
        return not crowned(design.values) and not any(x != 0.0 for x in design.values["misalignment"].values())

    def mesh_check(self, design: Design) -> None:
        """A relieved profile in line contact is refused (:func:`refuse_relief`)."""
        if self.conjugate(design):
            refuse_relief(design.values)

    def tca(self, design: Design, progress=None) -> tuple:
        return self.meshing_cycle_tables(design)

    def edges(self, design: Design, P) -> list:
        return cone_edges(design.pair, P)

    def te_radius_mm(self, design: Design) -> float:
        """The gear's base-cone radius at the mean cone distance, R_m sin(a_b2)."""
        g2 = design.pair.flank2.gear
        return float(g2.mean_cone_distance * np.sin(g2.base_cone_angle))

    def draw_face_edges(self, design: Design, ax) -> None:
        """The pinion's face ends, arcs of cone distance R_e - b and R_e about its apex."""
        g1 = design.pair.flank1.gear
        u = np.linspace(design.pair.lower1[0], design.pair.upper1[0], 21)
        for rho in (g1.outer_cone_distance - g1.face_width, g1.outer_cone_distance):
            ax.plot(rho * np.cos(u), rho * np.sin(u), c="0.5", lw=0.6)


FAMILY = BevelFamily()
