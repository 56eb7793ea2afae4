"""The ``involute`` family: spur and helical involute pairs on parallel axes (the thesis's
cylindrical gears), with profile shifts, lengthwise crowning and tip/root relief on either member.

The pair is :func:`gearrep.surfaces.involute.InvoluteFlank` x 2 in a :class:`gearrep.tca.GearPair`
at the standard centre distance r_p1 + r_p2 (moved by the misalignment). Checks before any work:
the undercut limit of each member, a tooth pointed below its tip circle, crown and relief against
the tooth thickness, and the operating centre distance against the range in which the pair meshes
(:func:`gearrep.meshing.centre_distance_limits`: tip interference below, a total contact ratio
below 1 above). The TCA is the library's meshing cycle (engagement limits solved on the flank
boundaries); an aligned unmodified pair is in line contact, traced in the mid-face section v1 = 0.
"""

from __future__ import annotations

import math

import numpy as np

from ... import settings as st
from ...ltca import iso
from ...meshing import centre_distance_limits, contact_ratio_closed_form
from ...settings import SettingError
from ...surfaces.involute import (
    InvoluteFlank,
    InvoluteGearData,
    RootRelief,
    TipRelief,
    involute_polar_angle,
    undercut_limit,
)
from ...tca import GearPair
from ..family import ISO_RATIOS, UNLOADED, Design, PairFamily
from ..keys import CROWNING, LOAD, LOADED_ANALYSIS, MATERIAL, MISALIGNMENT, RELIEF, crowning, head, materials

__all__ = ["KEYS", "InvoluteFamily", "FAMILY", "undercut_teeth", "check_crowning", "crowned", "refuse_relief"]


def _member(reason):
    return st.group(
        reason,
        teeth=st.integer(None, "1", "number of teeth", ge=3, le=10000),
        profile_shift=st.number(0.0, "1", "profile-shift coefficient x", ge=-1.5, le=1.5),
        crowning=CROWNING,
        tip_relief=RELIEF,
        root_relief=RELIEF,
        material=MATERIAL,
    )


KEYS = st.declare(
    **head("involute", "normal module"),
    pressure_angle_deg=st.number(20.0, "deg", "normal pressure angle", ge=10, le=35),
    helix_angle_deg=st.number(0.0, "deg", "helix angle at the pitch cylinder (0: spur)", ge=0, le=45),
    hand=st.choice("right", ("right", "left"), "helix hand of the pinion (the gear has the other hand)"),
    addendum=st.number(1.0, "1", "addendum coefficient h_a", ge=0.5, le=1.5),
    dedendum=st.number(1.25, "1", "dedendum coefficient h_f", ge=0.8, le=2),
    pinion=_member("member 1 (the driving member unless load.driving says gear)"),
    gear=_member("member 2"),
    misalignment=MISALIGNMENT,
    load=LOAD,
    analysis=LOADED_ANALYSIS,
)


def undercut_teeth(member, z, module, alpha_deg, face_width, addendum, how):
    """Refuse ``member``'s tooth number below the undercut limit of its middle section, an involute
    cut by a straight rack of ``addendum`` modules (also the CATT and hob-cut families' check)."""
    lim = undercut_limit(InvoluteGearData(max(z, 3), module, math.radians(alpha_deg), face_width, h_a=addendum))
    if z < lim:
        raise SettingError(
            f"design.{member}.teeth: got {z}; allowed: an integer >= {math.ceil(lim - 1e-9)} "
            f"(undercut limit {lim:.4g} teeth of the middle section{how})"
        )


def _check_pointed(v, member):
    """Refuse a profile shift that leaves ``member``'s tooth pointed below its tip circle (the tooth's
    half angle at the tip, s/(2 r_p) + inv(alpha_t) - inv(alpha_a), falls to zero as x grows: the
    tip circle grows by x m while the flanks lean in), naming the largest shift allowed."""
    m, z = v["module_mm"], v[member]["teeth"]
    a_n, beta = math.radians(v["pressure_angle_deg"]), math.radians(v["helix_angle_deg"])
    m_t = m / math.cos(beta)
    a_t = math.atan(math.tan(a_n) / math.cos(beta))
    r_p = 0.5 * z * m_t
    r_b = r_p * math.cos(a_t)

    def half_angle(x):
        s = m_t * (0.5 * math.pi + 2.0 * x * math.tan(a_n))
        r_a = r_p + (v["addendum"] + x) * m
        return s / (2 * r_p) + float(involute_polar_angle(r_p, r_b)) - float(involute_polar_angle(max(r_a, r_b), r_b))

    x = v[member]["profile_shift"]
    if half_angle(x) > 0:
        return
    # scipy.optimize is imported only here, on the way to this refusal: it takes about a third of
    # the command's start-up (0.2-0.4 s), which `gearrep --help`, `schema` and `check` then skip
    from scipy.optimize import brentq

    limit = brentq(half_angle, -1.5, x) if half_angle(-1.5) > 0 else float("nan")
    raise SettingError(
        f"design.{member}.profile_shift: got {x!r}; allowed: below {limit:.4g} for {z} teeth (a larger shift leaves "
        "the tooth pointed below its tip circle)"
    )


def _check_removal(v, member, g, u_lo, u_hi):
    """Refuse a crown or relief that removes more than the tooth holds: the crown alone at the tip
    circle, and at the face edge the crown plus the tip relief at the tip circle and plus the root
    relief at the start of the involute; where the removal reaches :meth:`InvoluteGearData.max_flank_removal` the flank
    crosses the tooth's centre plane (no material left)."""
    mv = v[member]
    crown = mv["crowning"]["crown_mm"] if mv["crowning"]["kind"] != "none" else 0.0
    for key, amount, r, where in (
        ("crowning.crown_mm", crown, u_hi, "the tip circle"),
        ("tip_relief.amount_mm", mv["tip_relief"]["amount_mm"], u_hi, "the tip circle"),
        ("root_relief.amount_mm", mv["root_relief"]["amount_mm"], u_lo, "the start of the involute"),
    ):
        most = g.max_flank_removal(r) - (crown if key != "crowning.crown_mm" else 0.0)
        if amount > 0 and not amount < most:
            raise SettingError(
                f"design.{member}.{key}: got {amount!r}; allowed: below {most:.4g} mm (more removes the whole "
                f"tooth thickness at {where}, r = {r:.4g} mm, at the face edge: the flank would cross the tooth's "
                "centre plane)"
            )


def check_crowning(v, member):
    """Refuse a crown the member's crowning form cannot take: a circular crown of half the face
    width or more, a crowning form with no crown (also the bevel family's check)."""
    c = v[member]["crowning"]
    if c["kind"] == "circular" and not c["crown_mm"] < 0.5 * v["face_width_mm"]:
        raise SettingError(
            f"design.{member}.crowning.crown_mm: got {c['crown_mm']!r}; allowed: below half the face width "
            f"({0.5 * v['face_width_mm']:g} mm) for a circular crown"
        )
    if c["kind"] != "none" and c["crown_mm"] == 0.0:
        raise SettingError(
            f"design.{member}.crowning.crown_mm: got 0.0; allowed: > 0 mm for crowning kind {c['kind']!r} "
            "(or kind: none)"
        )


def crowned(v) -> bool:
    """Whether either member of the resolved design ``v`` is crowned (also the bevel family's)."""
    return any(v[m]["crowning"]["kind"] != "none" and v[m]["crowning"]["crown_mm"] > 0 for m in ("pinion", "gear"))


def refuse_relief(v) -> None:
    """Refuse a profile relief on a pair in line contact (also the bevel family's): the line
    contact is traced in one face section, which the contact leaves where a profile is relieved."""
    for member in ("pinion", "gear"):
        for kind in ("tip_relief", "root_relief"):
            x = v[member][kind]["amount_mm"]
            if x > 0:
                raise SettingError(
                    f"design.{member}.{kind}.amount_mm: got {x!r}; allowed: 0 while neither member is crowned and the "
                    "axes are aligned (a line contact, traced in one face section, which a relieved profile leaves; "
                    "crown a member to analyse the relief)"
                )


def _gear(v, member) -> InvoluteGearData:
    """Member ``member``'s gear data, refused below the undercut limit or wider than 20 pitch radii."""
    mv = v[member]
    _check_pointed(v, member)
    g = InvoluteGearData(
        mv["teeth"],
        v["module_mm"],
        math.radians(v["pressure_angle_deg"]),
        v["face_width_mm"],
        math.radians(v["helix_angle_deg"]),
        x=mv["profile_shift"],
        h_a=v["addendum"],
        h_f=v["dedendum"],
    )
    lim = undercut_limit(g)
    if mv["teeth"] < lim:
        raise SettingError(
            f"design.{member}.teeth: got {mv['teeth']}; allowed: an integer >= {math.ceil(lim - 1e-9)} "
            f"(undercut limit {lim:.4g} teeth for x = {mv['profile_shift']:g}; raise {member}.profile_shift "
            "to lower it)"
        )
    if v["face_width_mm"] > 20 * g.r_p:
        raise SettingError(
            f"design.face_width_mm: got {v['face_width_mm']!r}; allowed: at most 20 pitch radii of the "
            f"{member} ({20 * g.r_p:.6g} mm)"
        )
    return g


def _reliefs(v, member, u_lo, u_hi) -> tuple:
    """The tip and root relief of ``member`` on its involute flank from r = ``u_lo`` to ``u_hi``."""
    relief = []
    for kind, cls in (("tip_relief", TipRelief), ("root_relief", RootRelief)):
        r = v[member][kind]
        if r["amount_mm"] == 0.0:
            continue
        if not r["length_mm"] < u_hi - u_lo:
            raise SettingError(
                f"design.{member}.{kind}.length_mm: got {r['length_mm']!r}; allowed: below the radial height of "
                f"the involute flank ({u_hi - u_lo:.6g} mm)"
            )
        u0 = u_hi - r["length_mm"] if kind == "tip_relief" else u_lo + r["length_mm"]
        relief.append(cls(u0, r["length_mm"], r["amount_mm"]))
    return tuple(relief)


class InvoluteFamily(PairFamily):
    """Spur and helical involute pairs (module docstring)."""

    name = "involute"
    keys = KEYS
    param_names = ("radius_mm", "axial_mm")
    analyses = (*UNLOADED, "ltca")

    def build(self, values: dict) -> Design:
        v = values
        gears, flanks = [], []
        hand = 1 if v["hand"] == "right" else -1
        for i, member in enumerate(("pinion", "gear")):
            g = _gear(v, member)
            check_crowning(v, member)
            u_lo, u_hi = max(g.r_b, g.r_f), g.r_a
            _check_removal(v, member, g, u_lo, u_hi)
            relief = _reliefs(v, member, u_lo, u_hi)
            gears.append(g)
            c = crowning(v[member]["crowning"], v["face_width_mm"])
            flanks.append(InvoluteFlank(g, 1, hand if i == 0 else -hand, crowning=c, relief=relief))
        a = gears[0].r_p + gears[1].r_p
        pair = GearPair(flanks[0], flanks[1], gears[0].n_teeth, gears[1].n_teeth, a, misalignment=self.misalignment(v))
        return Design(v, self, pair)

    def line_section(self, design: Design) -> float:
        return 0.0  # mid-face

    def conjugate(self, design: Design) -> bool:
        """No crown on either member and no angular misalignment: the involute helicoids touch
        along a line (a centre-distance change, offset or axial shift keeps it)."""
        m = design.values["misalignment"]
        return not crowned(design.values) and m["d_gamma_in_deg"] == 0.0 and m["d_gamma_out_deg"] == 0.0

    def tca(self, design: Design, progress=None) -> tuple:
        return self.meshing_cycle_tables(design)

    def mesh_check(self, design: Design) -> None:
        """Refuse a design whose operating centre distance (the nominal one changed by the
        misalignment d_E and d_H) leaves the range of :func:`gearrep.meshing.centre_distance_limits`:
        below it a tip meets the other member below its involute (tip interference: no engagement
        limit on the flanks), above it the total contact ratio is below 1 (a gap in the meshing);
        and a relieved profile in line contact (:func:`refuse_relief`)."""
        pair, v = design.pair, design.values
        if self.conjugate(design):
            refuse_relief(v)
        g1, g2 = pair.flank1.gear, pair.flank2.gear
        eps_b = float(g1.face_width * abs(np.sin(g1.helix_angle)) / (np.pi * g1.module))
        lim = centre_distance_limits(
            g1.r_a, g1.r_b, float(pair.lower1[0]), g2.r_a, g2.r_b, float(pair.lower2[0]), g1.base_pitch, eps_b
        )
        a0 = g1.r_p + g2.r_p
        m = v["misalignment"]
        d_e, d_h = m["d_E_mm"], m["d_H_mm"]
        a = math.hypot(a0 + d_e, d_h)
        if lim["a_min"] < a < lim["a_max"]:
            return
        lo = math.sqrt(max(lim["a_min"] ** 2 - d_h**2, 0.0)) - a0
        hi = math.sqrt(lim["a_max"] ** 2 - d_h**2) - a0 if lim["a_max"] > abs(d_h) else float("nan")
        tip = "gear" if lim["a_min_tip2"] >= lim["a_min_tip1"] else "pinion"
        root = "pinion" if tip == "gear" else "gear"
        if a <= lim["a_min"]:
            why = (
                f"tip interference: at a centre distance below {lim['a_min']:.6g} mm the {tip}'s tip meets the {root} "
                f"below the start of its involute (r = {float((pair.lower1 if root == 'pinion' else pair.lower2)[0]):.5g} mm)"
            )
        else:
            ratio = (
                math.sqrt(g1.r_a**2 - g1.r_b**2)
                + math.sqrt(g2.r_a**2 - g2.r_b**2)
                - math.sqrt(a**2 - (g1.r_b + g2.r_b) ** 2)
            ) / g1.base_pitch + eps_b
            why = (
                f"total contact ratio {ratio:.3g} < 1 at a centre distance of {a:.6g} mm: a gap in the "
                f"meshing (the next tooth pair engages after the last one left) above {lim['a_max']:.6g} mm"
            )
        if lo < hi:  # the centre distance is the design's knob (profile shifts leave it at r_p1 + r_p2)
            raise SettingError(
                f"design.misalignment.d_E_mm: got {d_e!r}; allowed: {lo:.4g} < d_E_mm < {hi:.4g} mm for this pair"
                f"{f' with d_H_mm = {d_h!r}' if d_h else ''} ({why})"
            )
        key, got = (
            (f"{tip}.profile_shift", v[tip]["profile_shift"]) if a <= lim["a_min"] else ("addendum", v["addendum"])
        )
        raise SettingError(
            f"design.{key}: got {got!r}; allowed: a value with which the pair meshes at its centre distance "
            f"{a0:.6g} mm ({why})"
        )

    def iso_contact_ratios(self, design: Design) -> dict:
        """The ISO-style contact ratios of the nominal pair (ISO 21771 / ISO 6336-1 definitions, no
        modification or misalignment): transverse eps_alpha = (length of the path of contact in the
        transverse section) / (transverse base pitch), overlap eps_beta = b sin(beta) / (pi m_n)
        and total eps_gamma = eps_alpha + eps_beta."""
        g1, g2 = design.pair.flank1.gear, design.pair.flank2.gear
        eps_a = float(
            contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, design.pair.centre_distance, g1.base_pitch)
        )
        eps_b = float(g1.face_width * abs(np.sin(g1.helix_angle)) / (np.pi * g1.module))
        return dict(zip(ISO_RATIOS, (eps_a, eps_b, eps_a + eps_b)))

    def iso_pitch_pressure_MPa(self, design: Design) -> float:
        """ISO 6336-2's nominal contact stress at the pitch point, Z_H Z_E sqrt(F_t / (d_1 b) (u + 1) /
        u) with Z_eps = Z_beta = 1 (one tooth pair carrying the load evenly along its line), of the
        nominal pair at its operating centre distance (alpha_wt from the misalignment's d_E_mm and
        d_H_mm), F_t = 2000 T / d of the driving member, Z_E of the two materials
        (:mod:`gearrep.ltca.iso`)."""
        v, pair = design.values, design.pair
        g1, g2 = pair.flank1.gear, pair.flank2.gear
        m = v["misalignment"]
        a0 = g1.r_p + g2.r_p
        alpha_wt = math.acos(min(1.0, a0 * math.cos(g1.alpha_t) / math.hypot(a0 + m["d_E_mm"], m["d_H_mm"])))
        driving = g1 if v["load"]["driving"] == "pinion" else g2
        F_t = 1000.0 * v["load"]["torque_Nm"] / driving.r_p
        (m1, m2) = materials(v)
        Z_E = iso.elasticity_factor(m1.E_MPa, m1.poisson, m2.E_MPa, m2.poisson)
        Z_H = iso.zone_factor(g1.alpha_t, alpha_wt, g1.beta_b)
        return iso.pitch_point_stress_MPa(F_t, 2.0 * g1.r_p, g1.face_width, g2.n_teeth / g1.n_teeth, Z_H, Z_E)

    def active_profile_start(self, design: Design) -> tuple[float, float]:
        """Radii [mm] at which the active profiles begin (pinion, gear): where the mating member's
        tip circle cuts the line of action, sqrt(r_b^2 + (sqrt(a^2 - (r_b1 + r_b2)^2) -
        sqrt(r_a'^2 - r_b'^2))^2) (a: the operating centre distance), and not below the start of
        the involute flank."""
        pair, m = design.pair, design.values["misalignment"]
        g1, g2 = pair.flank1.gear, pair.flank2.gear
        a = float(np.hypot(g1.r_p + g2.r_p + m["d_E_mm"], m["d_H_mm"]))
        loa = np.sqrt(max(a**2 - (g1.r_b + g2.r_b) ** 2, 0.0))
        out = []
        for g, other, lo in ((g1, g2, pair.lower1[0]), (g2, g1, pair.lower2[0])):
            t = max(loa - np.sqrt(other.r_a**2 - other.r_b**2), 0.0)
            out.append(max(float(np.hypot(g.r_b, t)), float(lo)))
        return out[0], out[1]

    def flank_grid(self, design: Design, member: int, n_u: int, n_v: int) -> tuple:
        """The grid over the active profile: from where the mating tip reaches (not the base-circle
        cusp) to the tip, across the face."""
        flank, lo, hi, _ = self.member(design, member)
        u0 = self.active_profile_start(design)[member - 1]
        u, v = np.meshgrid(np.linspace(u0, hi[0], n_u), np.linspace(lo[1], hi[1], n_v), indexing="ij")
        return flank, u.ravel(), v.ravel()


FAMILY = InvoluteFamily()
