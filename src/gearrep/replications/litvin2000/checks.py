"""Check records of seed 002: every published value and claim against the tables of the jobs
(gearrep.checks; tolerances from the printed precision only).

:data:`VALUES` maps a value id to its computed counterpart: a :class:`.rules.Rule` (tables ->
(computed value, note)), a :class:`.rules.PrintedInput` (a printed design input, status ``input``)
or the reason it is not computed; :data:`.claims.CLAIMS` does the same for the claims."""

from __future__ import annotations

from functools import partial

import numpy as np
import pandas as pd

from ... import checks as ck
from .claims import CLAIMS
from .rules import INPUT_RADII, NOT_COMPUTED_SEC3, PrintedInput, Rule, evaluate, one

__all__ = ["VALUES", "check_records", "checks"]


def _design(t, case="design", member="pinion"):
    return one(t["curvatures"], case=case, member=member)


def _base(t) -> str:
    pin, gear = _design(t), _design(t, member="gear")
    return (
        f"rack generation at Q, beta = arccos(94/100) = {pin['beta_deg']:.3f} deg (printed 19.548 is a misprint, "
        f"errata), rho_c = 5.88/P_n, rho_t = 6.35/P_n (eq 2.7.2); report normal (pinion convex > 0); "
        f"relations and differential geometry agree to {max(pin['max_rel_diff'], gear['max_rel_diff']):.1e}"
    )


def _pinion_kappa(col, t):
    return _design(t)[col], f"{_base(t)}; with 19.548 deg: {_design(t, 'beta_printed')[col]:.5f}"


def _gear_kappa_I(t):
    k = _design(t, member="gear")["kappa_I_per_in"]
    return abs(k), (
        f"{_base(t)}; compared in magnitude: our signed value is {k:.5f} (the gear is hyperbolic, "
        "the printed value lost its minus sign; claim 002-S2.5-gear_hyperbolic_sign_lost)"
    )


def _gear_kappa_II(t):
    k, ka = _design(t, member="gear")["kappa_II_per_in"], _design(t, "a_printed", "gear")["kappa_II_per_in"]
    return k, (
        f"{_base(t)}. kappa_II(2) depends on the gear rack radius: {k:.5f} with rho_t = 1.270 in, "
        f"{ka:.5f} with the printed a_t = 0.394 (rho_t = 1.2690); the printed 0.5940 lies between, "
        "i.e. the report used an unrounded a_t/rho_t we cannot recover (one unit of the last digit off)"
    )


def _rho(member, note, t):
    return _design(t, member=member)["rho_rack_in"], note


def _rho_ratio(t):
    return _design(t, member="gear")["rho_rack_in"] / _design(t)["rho_rack_in"], "eq 2.7.2: (6.35/P_n)/(5.88/P_n)"


_ZONE = {1: "single", 2: "pinion_addendum", 3: "single"}
_V1_MAJOR = (
    "; 2a is set by the radius difference 0.001 in (0.5 %): 2a = 0.285 would need rho_gear - rho_pinion "
    "about 0.99e-3 in, so the printed 0.201 (or the helix angle used) carries the difference"
)


def _ellipse(v, col, suffix, t):
    """Table 6.2.4, version ``v``: ``col`` of the design case and the note."""
    ell = t["ellipse"]
    r = one(ell, version=v, zone=_ZONE[v], case="design")
    rb = one(ell, version=v, zone=_ZONE[v], case="beta_printed")
    extra = ""
    if v == 2:
        rd = one(ell, version=2, zone="pinion_dedendum", case="design")
        extra = f"; the other zone (pinion dedendum) gives 2a = {rd['major_2a_in']:.4f}, 2b = {rd['minor_2b_in']:.4f}"
    if v == 1:
        extra = _V1_MAJOR
    if v == 3:
        rs = one(ell, version=3, zone="single", case="delta_sec2.6")
        extra = f"; with the sec. 2.6 delta = 0.0025 in: 2a = {rs['major_2a_in']:.4f}, 2b = {rs['minor_2b_in']:.4f}"
    note = (
        f"elastic approach 0.00025 in, alpha_n = {r['alpha_n_deg']:.0f} deg, |QP| = {r['l_in']:.4f} in, "
        f"rho = {r['rho_pinion_in']:.3f}/{r['rho_gear_in']:.3f} in, beta = {r['beta_deg']:.3f} deg, "
        f"sigma = {r['sigma_deg']:.3f} deg; with beta = 19.548 deg: 2a = {rb['major_2a_in']:.4f}, "
        f"2b = {rb['minor_2b_in']:.4f}{extra}"
    )
    return r[col], note + suffix


def _sensitivity(v, col, t):
    """Table 6.2.3, version ``v``: TCA with dE = 0.001 in (printed step 0.0001 mm: errata)."""
    sens = t["sensitivity"]
    tca = one(sens, version=v, step="0.001in", method="tca")
    eqd = one(sens, version=v, step="0.001in", method="eq2.8.7_decrease")
    eqi = one(sens, version=v, step="0.001in", method="eq2.8.7_increase")
    pr = one(sens, version=v, step="printed_0.0001mm", method="eq2.8.7_decrease")
    note = (
        f"TCA with dE = +0.001 in (status {tca['status']}); eq 2.8.7: {eqd['delta_alpha_deg']:.4f} "
        f"(alpha decreasing, the sign TCA shows) / {eqi['delta_alpha_deg']:.4f} deg; with the printed step "
        f"0.0001 mm eq 2.8.7 gives {pr['delta_alpha_deg']:.5f} deg (errata); delta_1 = shift / "
        f"{tca['h_active_in']:.3f} in (Table 6.2.2 height{' of one zone, ha' if v == 2 else ''})"
    )
    imp = {
        m: one(sens, version=v, step="implied_by_printed", method=f"eq2.8.7_inverse_{m}")
        for m in ("decrease", "increase")
    }
    note += (
        f"; the printed {imp['decrease']['delta_alpha_deg']:.2f} deg needs dE = {imp['decrease']['delta_E_in']:.6f} in "
        f"(alpha decreasing) or {imp['increase']['delta_E_in']:.6f} in (increasing) by eq 2.8.7, and the printed delta_1 "
        f"implies d alpha = {imp['decrease']['delta_alpha_from_printed_delta_1_deg']:.3f} deg by eq 2.8.6"
    )
    if v == 1:
        note += (
            "; version 1 (rho difference 0.001 in) has no contact for dE = 0.001 in, the step of versions 2 and 3 (TCA does "
            "not converge: NaN; eq 2.8.7 gives 60.09 deg decreasing, no solution increasing); with dE = 0.0001 in TCA gives "
            f"{one(sens, version=1, step='0.0001in', method='tca')['delta_alpha_deg']:.2f} deg. 19.50 implies a step about "
            "a third of the other versions' (0.00032 or 0.00027 in, 0.0082 or 0.0069 mm), and its delta_1 = 0.383 and "
            "d alpha = 19.50 disagree by 2 % under eq 2.8.6: the report's version-1 computation is not recoverable"
        )
    return tca[col], note


def _profile_common(g) -> str:
    return (
        f"TCA of the profile-crowned pair (no plunging, the same pinion for both tools), left-hand pinion as in "
        f"the report, TE_max = peak-to-peak TE over the meshing cycle (face width {g['face_width_in']:.3f} in >= "
        f"axial pitch {g['axial_pitch_in']:.3f} in; TE_max does not depend on it)"
    )


def _profile_dgamma(t):
    g, gm = one(t["te_summary"], case="dgamma_plus"), one(t["te_summary"], case="dgamma_minus")
    return g["te_max_arcsec"], (
        f"{_profile_common(g)}; dgamma = +3 arcmin about the centre line x_f (pinion to gear axis, right-hand rule); "
        f"-3 arcmin gives {gm['te_max_arcsec']:.3f}: the report's sign convention (fig. 2.8.1) is not in the text"
    )


def _profile_dlambda(t):
    """dlambda = 3' of the profile-crowned pair, two readings side by side: the value is the turn
    of the pinion about the centre line (= dgamma of opposite sign), the reading that reproduces
    the report; the literal lead (helix-angle) error is in the note."""
    te = t["te_summary"]
    g, gm = one(te, case="dgamma_plus"), one(te, case="dgamma_minus")
    lh, lm = one(te, case="dlambda_helix_plus"), one(te, case="dlambda_helix_minus")
    return gm["te_max_arcsec"], (
        f"{_profile_common(g)}; two readings of dlambda = 3': (a) a turn of the pinion about the centre line, i.e. "
        f"dgamma = -3' (the value: {gm['te_max_arcsec']:.3f}; +3' gives {g['te_max_arcsec']:.3f}), and (b) the literal "
        f"pinion lead-angle error (pinion generated with helix angle beta - 3', same pitch cylinder): "
        f"{lh['te_max_arcsec']:.3f} (+3') / {lm['te_max_arcsec']:.3f} (-3'), about 1/cos^2(beta) times (a). "
        "Reading (a) reproduces the report's 'the same 40.48 in both cases' to 0.07 %, reading (b) is 13 % above: "
        "the report's dlambda acts as a turn about the centre line (so do its worm-ground dlambda results); "
        "(a) is 0.02 arcsec outside the printed precision"
    )


#: the worm-ground TE_max: total tolerance (relative) from the rounding of the printed a_t = 0.394
_WORM_TOL_REL = 0.005
_WORM_TOL_BASIS = (
    "0.5 % of the printed value: the sec. 5.4 rack coefficients are printed to 3 decimals and TE_max grows with "
    "a_c - a_t (0.03100 -> 0.03147, the unrounded 1/(2 rho) of eq 2.7.2, raises it by 0.55 %), so half a unit of "
    "the last digit of a_t alone moves TE_max by about 0.58 %"
)


def _worm_note(w) -> str:
    a = w.loc["worm_aligned"]
    return (
        f"TCA of the pinion ground by the plunging worm (gearrep.surfaces.worm_ground.WormGeneratedPinion; r_pw = 3.82 "
        f"in, N_w = 1, a_pl = 0.00139 1/in, beta = 19.948 deg, a_c = {a['a_c_per_in']:.3f}, a_t = {a['a_t_per_in']:.3f} "
        f"1/in as printed in sec. 5.4). Set-up as printed: feed by translation l_w along the pinion axis plus "
        f"l_w tan(beta) tangentially, plunge E0 - a_pl l_w^2 along the fixed shortest distance (eq 5.2.5, 5.3.3, "
        f"5.3.7), crossing angle 90 - beta - lambda_w = {a['crossing_angle_deg']:.3f} deg (eq 5.2.1; that angle "
        f"belongs to a worm of the opposite hand to the pinion). TE_max = peak-to-peak TE over the meshing cycle "
        f"between the transfer points (TE_0(phi1) = TE_0(phi1 -+ 2 pi/N1)), contact on the active profile of Table "
        f"6.2.2 v3, face not limiting (a face of {a['face_width_in']:.3f} in would give "
        f"{a['te_max_face_limited_arcsec']:.3f}). Our earlier set-up (feed as an extra pinion turn, eq 5.3.2) gave "
        f"8.50 / 12.96 / 16.56: results/litvin2000/worm_choices.csv shows each choice's effect"
    )


def _worm(case, t):
    w = t["worm_summary"].set_index("case")
    note = _worm_note(w)
    if case == "worm_dgamma_plus":
        note += (
            f"; dgamma = +3 arcmin (the sign that gives the printed value; -3 arcmin gives "
            f"{w.loc['worm_dgamma_minus', 'te_max_arcsec']:.3f}, face-limited {w.loc[case, 'te_max_face_limited_arcsec']:.3f})"
        )
    if case == "worm_dgamma_minus":
        note += (
            f"; dlambda = 3' read as a turn of the pinion about the centre line, i.e. dgamma = -3' (the reading of the "
            f"profile-crowned rows); the literal lead-angle error (worm set to beta -+ 3') gives "
            f"{w.loc['worm_dlambda_plus', 'te_max_arcsec']:.3f} (+3') / {w.loc['worm_dlambda_minus', 'te_max_arcsec']:.3f}"
            f" (-3'): the turn reading reproduces the report"
        )
    return w.loc[case, "te_max_arcsec"], note, _WORM_TOL_REL, _WORM_TOL_BASIS


def _dependence_text(sw) -> str:
    """'h1, h2, ... for (rack tooth / pitch, top land P_n) = (a1, b1), ...' of the sweep rows."""
    return (
        ", ".join(f"{x:.3f}" for x in sw["hd_Pn"])
        + " for (rack tooth / pitch, top land P_n) = "
        + ", ".join(f"({a:.2f}, {b:.2f})" for a, b in zip(sw["rack_tooth_over_pitch"], sw["top_land_times_Pn"]))
    )


def _thickness_text(r, hv) -> str:
    """How h_d's tooth thickness and top land are read (design row ``r``), and h_d under the other
    readings of the tooth's axis (``hv``: the version's rows)."""
    rd = hv[hv["kind"] == "reading"].set_index("tooth_axis")
    other = {
        "pinion_tooth": "P on the pinion tooth's axis",
        "rack_tooth": "P on the rack tooth's axis",
        "half_pitch": "tooth = space (no text behind it)",
    }
    return (
        f"h_d from pointing: P (where the profile normal at Q meets the pitch line) lies on the tooth's axis of "
        f"symmetry (fig. 1.6's caption; that figure's tooth carries the top land S_a and the fillet, so it is the "
        f"generated one), so the pinion tooth at the pitch line is 2 w, w = {r['half_width_Pn']:.4f}/P_n from P to "
        f"where the rack profile crosses the line (rack tooth {r['rack_tooth_over_pitch']:.3f} x normal pitch); top "
        f"land {r['top_land_times_Pn']:.2f}/P_n on the addendum circle (sec. 3.3's rule; sec. 2 gives no value): "
        f"h_d P_n = {r['hd_Pn']:.4f} (reading {r['tooth_axis']}). The other readings: "
        + ", ".join(f"{other[k]} {rd.loc[k, 'hd_Pn']:.4f}" for k in other if k in rd.index and k != r["tooth_axis"])
    )


def _height(col, t):
    """Table 6.2.2 version 3 (and sec. 3.3's 1.8 for the convex pinion): the design row of the
    heights table, with the assumption dependence in the note."""
    h = t["heights"]
    h = h[h["version"] == 3]
    r = one(h, kind="design")
    sw = h[h["kind"] == "sweep"]
    req = h[h["kind"] == "required"]
    note = (
        f"pinion rack of sec. 2 (a_c = 1/(2 x 5.88/P_n), alpha_n = 25 deg, beta = {r['beta_deg']:.3f} deg, N1 = 17): "
        f"h_a P_n = {r['ha_Pn']:.4f} from undercutting (Litvin's limiting line, gearrep.surfaces.novikov.undercut_limit; "
        "no assumption). "
        + _thickness_text(r, h)
        + ". Dependence: h_d P_n = "
        + _dependence_text(sw)
        + ". The printed h_d P_n = 1.25 needs a rack tooth of "
        + ", ".join(f"{a:.3f}" for a in req["rack_tooth_over_pitch"])
        + " pitches for top lands "
        + ", ".join(f"{b:.2f}" for b in req["top_land_times_Pn"])
        + f"/P_n; then h P_n = {req['h_Pn'].iloc[0]:.3f}. Rack tooth / pitch giving each version's printed h_d over "
        "top lands 0-0.4/P_n: " + _required_text(t["heights"])
    )
    return r[col], note


def _required_text(h) -> str:
    """'v: a-b' ranges of the rack tooth / pitch that give each version's printed h_d (top lands swept)."""
    out = []
    for v in (3, 1, 2):
        req = h[(h["kind"] == "required") & (h["version"] == v)]
        x = req["rack_tooth_over_pitch"].dropna()
        at = (
            one(req, top_land_times_Pn=0.3)["rack_tooth_over_pitch"]
            if (req["top_land_times_Pn"] == 0.3).any()
            else np.nan
        )
        out.append(f"version {v} {x.min():.3f}-{x.max():.3f} ({at:.3f} at 0.3/P_n)")
    return "; ".join(out)


_HA_LIMIT = {
    "singular": "Litvin's limiting line (undercutting)",
    "zero_pressure_angle": (
        "the zero pressure angle: the arc is centred on the pitch line (sec. 6.2), so it meets the line with a "
        "profile parallel to the tooth height and below it would turn back (a rack tooth widening towards its tip)"
    ),
    "profile_end": (
        "the lowest point of the convex tip arc (pressure angle 90 deg): neither undercutting nor a zero pressure "
        "angle occurs on it, so the printed 0.90 is not an undercutting limit of this arc (it must come from the "
        "standard racks of refs. 3-4, not in the report)"
    ),
}


def _height_arc(version, col, t):
    """Table 6.2.2 versions 1-2 (circular-arc racks): the design row of the heights table, same
    assumption as version 3, with the dependence and the one-assumption test in the note."""
    h = t["heights"]
    hv = h[h["version"] == version]
    r = one(hv, kind="design")
    sw = hv[hv["kind"] == "sweep"]
    if version == 1:
        rack = "arc rho = 0.200 in centred on the pitch point (sec. 6.2), alpha_n = 27 deg at Q, |QP| = rho"
    else:
        rack = (
            "addendum-generating arc rho = 0.230 in centred on the pitch point, alpha_n = 27 deg; convex tip arc "
            "rho = 0.258 in touching the gear rack's 0.230 arc (centred on the pitch line) at the mirror point Q' "
            "below the line, centre 0.028 in beyond the pitch point on that normal (Table 6.2.1 footnote)"
        )
    note = (
        f"pinion rack of version {version} ({rack}; N1 = 17, beta = {r['beta_deg']:.3f} deg; "
        "gearrep.surfaces.rack.CircularArcRackCutter). "
        f"h_a P_n = {abs(r['ha_Pn']):.4f}, limited by {_HA_LIMIT[r['ha_limit']]}; no thickness or top-land "
        "assumption. "
        + _thickness_text(r, hv)
        + " (the same rules as version 3). Dependence: h_d P_n = "
        + _dependence_text(sw)
        + ". Rack tooth / pitch that gives each version's printed h_d over top lands 0-0.4/P_n: "
        + _required_text(h)
        + ": no one reading reproduces the printed h_d of all three versions (versions 1-2 need a rack tooth "
        "thicker than half the pitch, version 3 a thinner one)"
    )
    return (abs(r[col]) if col == "ha_Pn" else r[col]), note


def _disk_common(r) -> str:
    return (
        f"pinion ground by the plunging disk (gearrep.surfaces.novikov.DiskGroundPinion, appendices A-B; plunge a_pd = "
        f"{r['a_pd_per_in']:.6f} 1/in by eq 5.4.13 from a_pl = 0.00139, racks of sec. 5.4, rack tooth 0.5 pitch). The "
        f"report gives no disk size: INFERRED disk-pinion shortest distance E_d = {r['E_d_in']:.4f} in (crossing angle "
        f"{abs(r['gamma_d_deg']):.3f} deg) from the printed aligned 11.54 (one parameter); TE_max over the cycle "
        "between the transfer points"
    )


def _disk_input(t):
    """The aligned disk row is the calibration input of the inference, not a check (status input)."""
    r = one(t["disk"], case="aligned")
    return PrintedInput(
        f"used as the input of an inference, not checked: {_disk_common(r)}; with it the aligned TE_max is "
        f"{r['te_max_arcsec']:.4f} by construction. The dgamma and dlambda rows are the predictions"
    )


def _disk(case, t):
    dk = t["disk"]
    r = one(dk, case=case)
    note = f"PREDICTION with the inferred disk: {_disk_common(r)}"
    if case == "dgamma_plus":
        note += (
            f"; dgamma = +3' (the sign of the worm rows); -3' gives {one(dk, case='dgamma_minus')['te_max_arcsec']:.3f}"
        )
    else:
        note += (
            f"; dlambda = 3' read as a turn about the centre line (dgamma = -3', as for the worm); the literal lead "
            f"error gives {one(dk, case='dlambda_lead_plus')['te_max_arcsec']:.3f}"
        )
    return r["te_max_arcsec"], note


_RADII_12 = [
    f"002-T6.2.1-version={v}-{m}"
    for v in ("1", "2;zone=pinion_addendum", "2;zone=pinion_dedendum")
    for m in ("rho_pinion", "rho_gear")
]
_CUR, _ELL, _SENS, _TE, _WORM = ("curvatures",), ("ellipse",), ("sensitivity",), ("te_summary",), ("worm_summary",)

#: value id -> Rule (tables -> (computed, note)) or the reason it is not computed
VALUES: dict = {
    "002-S2.5-member=1-kappa_I": Rule(_CUR, partial(_pinion_kappa, "kappa_I_per_in")),
    "002-S2.5-member=1-kappa_II": Rule(_CUR, partial(_pinion_kappa, "kappa_II_per_in")),
    "002-S2.5-member=2-kappa_I": Rule(_CUR, _gear_kappa_I),
    "002-S2.5-member=2-kappa_II": Rule(_CUR, _gear_kappa_II),
    "002-S2.7-design=recommended-rho_t_over_rho_c": Rule(_CUR, _rho_ratio),
    "002-T6.2.1-version=3-rho_pinion": Rule(
        _CUR, partial(_rho, "pinion", "eq 2.7.2: 5.88/P_n (= 1/(2 a_c) = 1.1765 with the printed a_c)")
    ),
    "002-T6.2.1-version=3-rho_gear": Rule(
        _CUR, partial(_rho, "gear", "eq 2.7.2: 6.35/P_n (1/(2 a_t) = 1.2690 with the printed a_t = 0.394)")
    ),
    **{vid: INPUT_RADII for vid in _RADII_12},
    **{
        f"002-T6.2.2-version={v}-{q}": Rule(("heights",), partial(_height_arc, v, q))
        for v in (1, 2)
        for q in ("ha_Pn", "hd_Pn", "h_Pn")
    },
    **{f"002-T6.2.2-version=3-{q}": Rule(("heights",), partial(_height, q)) for q in ("ha_Pn", "hd_Pn", "h_Pn")},
    "002-S3.3-design=pinion_concave;N2_min=70-h_Pn": NOT_COMPUTED_SEC3,
    "002-S3.3-design=pinion_convex-h_Pn": Rule(("heights",), partial(_height, "h_Pn")),
    **{
        f"002-T6.2.4-version={v}-{q}": Rule(_ELL, partial(_ellipse, v, col, sfx))
        for v in (1, 2, 3)
        for q, col, sfx in (
            ("major_axis_2a", "major_2a_in", ""),
            ("minor_axis_2b", "minor_2b_in", ""),
            ("area_F1", "area_in2", "; area = pi a b"),
        )
    },
    **{
        f"002-T6.2.3-version={v}-{q}": Rule(_SENS, partial(_sensitivity, v, col))
        for v in (1, 2, 3)
        for q, col in (("delta_alpha", "delta_alpha_deg"), ("delta_1", "delta_1"))
    },
    **{
        f"002-S5.5-crowning=profile;tool={tool};misalignment={m}-TE_max": Rule(_TE, fn)
        for tool in ("disk", "worm")
        for m, fn in (("dgamma_3arcmin", _profile_dgamma), ("dlambda_3arcmin", _profile_dlambda))
    },
    "002-S5.5-crowning=disk;misalignment=none-TE_max": Rule(("disk",), _disk_input),
    "002-S5.5-crowning=disk;misalignment=dgamma_3arcmin-TE_max": Rule(("disk",), partial(_disk, "dgamma_plus")),
    "002-S5.5-crowning=disk;misalignment=dlambda_3arcmin-TE_max": Rule(("disk",), partial(_disk, "dgamma_minus")),
    **{
        f"002-S5.5-crowning=worm;misalignment={m}-TE_max": Rule(_WORM, partial(_worm, case))
        for m, case in (
            ("none", "worm_aligned"),
            ("dgamma_3arcmin", "worm_dgamma_plus"),
            ("dlambda_3arcmin", "worm_dgamma_minus"),
        )
    },
}


def check_records(tables: dict, published, seed: str, values: dict, claims: dict) -> pd.DataFrame:
    """One check record per published value and claim of ``seed``: ``values`` / ``claims`` map
    ids to a :class:`Rule` or a reason; ids not in them are 'not computed' with a generic reason."""
    recs = []
    vals = published.values[published.values["seed"] == seed]
    for _, r in vals.iterrows():
        got = evaluate(values.get(r["id"], "no computed counterpart in this replication"), tables)
        if isinstance(got, PrintedInput):
            recs.append(ck.printed_input(r.to_frame().T, got).iloc[0].to_dict())
        elif isinstance(got, str):
            recs.append(ck.not_computed(r.to_frame().T, got).iloc[0].to_dict())
        else:
            extra = {}
            if len(got) > 2:  # (value, note, rel_tol, basis): total tolerance rel_tol |published|, stated reason
                lo, hi, _ = ck.printed_interval(r["printed"], r["rounding"])
                widen = got[2] * abs(float(r["value"])) - 0.5 * (hi - lo)
                if widen > 0:
                    extra = dict(extra_tol=widen, extra_basis=got[3])
            recs.append(ck.compare_value(r, float(got[0]), note=got[1], **extra))
    cl = published.claims[published.claims["seed"] == seed]
    for _, c in cl.iterrows():
        got = evaluate(claims.get(c["id"], "claim not evaluated by this replication"), tables)
        if isinstance(got, str):
            recs.append(ck.not_computed(c.to_frame().T, got).iloc[0].to_dict())
        else:
            recs.append(ck.qualitative(c, bool(got[0]), got[1]))
    return ck.validate_checks(pd.DataFrame(recs, columns=ck.CHECK_COLUMNS))


def checks(tables: dict, published) -> dict[str, pd.DataFrame]:
    """Check records of every seed-002 value and claim on file (gearrep.checks; tolerances from
    the printed precision only): ``{"checks": records}``."""
    return {"checks": check_records(tables, published, "002", VALUES, CLAIMS)}
