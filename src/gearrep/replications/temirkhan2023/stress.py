"""Stress ratios of sec 4.2 (helical 40/37, Fig 29): Hertz maximum contact pressure along the path
of contact under out-of-plane misalignment, divided by the pressure of the aligned, unmodified
pair (thesis eq 15-25).

Route: the contact points of one tooth pair over its engagement (:func:`.te.engagement_contacts`,
reduced TCA), the principal curvatures of both flanks there and the Hertz ellipse and maximum
pressure for the printed load and material (:func:`gearrep.tca.contact_hertz` ->
:func:`gearrep.ellipse.hertz_contact_at` -> :func:`gearrep.ellipse.hertz_contact`; p_max =
3 P / (2 pi a b), eq 24 = :func:`gearrep.ellipse.hertz_max_pressure_MPa`). Every contact point
carries the whole load (Table 2: 200 N; no load sharing between pairs: the thesis states none).

Choices the thesis does not print (stated in every check note):

* the reference p_o of eq 25 ("aligned and unmodified" contact). That contact is a line, for which
  eq 22-24 give no finite ellipse (one relative curvature vanishes); we take the Hertz line-contact
  pressure (:func:`gearrep.ellipse.hertz_line_max_pressure_MPa`) of the aligned, unmodified pair at
  phi1 = 0 (tooth 1 centred on the centre line) with the load spread over its contact line (the part inside both flanks);
* the crowning amounts: Fig 29 does not restate them. At 0.05, 0.1 and 0.2 deg we use the printed
  amounts of Table 4 (each row of ``crowning_rows``; the checks quote row 1); at 0.01 and 0.02 deg,
  for which no amount is printed, the row-1 amounts of 0.05 deg (the smallest printed angle);
* the logarithmic crown's a2 (eq 12, setting ``crowning_log_a2``);
* "SR at an angle" read as the largest pressure along the path of contact (the value at
  phi1 = 0 is in the table too).

The loaded reading (columns ``*_loaded``; :func:`loaded_pressure`): the loaded tooth contact
analysis :func:`gearrep.ltca.loaded_contact` of the crowned pair over a meshing cycle under the
torque that puts the 200 N normal load on the aligned unmodified pair, the load shared by the tooth
pairs in mesh, over the same analysis of the aligned, unmodified pair (its largest flank pressure
over the cycle: a finite p_o of the line contact, without a choice of contact-line length). These
are the stress ratios the checks compare (row 1 of Table 4); the Hertz reading stands beside them.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import ltca
from ...curvature import relative_curvature
from ...ellipse import effective_modulus, hertz_line_max_pressure_MPa
from ...solve import Status
from ...tca import contact_curvatures, contact_hertz, solve_contact
from ...units import DEG
from .design import TABLE34, Design, misalignment, pair_40_37
from .model import crowning_object
from .te import engagement_contacts

#: out-of-plane angles of the stress-ratio study (Fig 29; sec 4.2 text names 0.01, 0.02, 0.05, 0.1, 0.2)
FIG29_ANGLES_DEG = (0.01, 0.02, 0.05, 0.1, 0.2)
KINDS = ("circular", "parabolic", "logarithmic")
#: points along the aligned pair's contact line (at phi1 = 0) for its length inside the
#: flanks: the ends are found to b / (LINE_POINTS - 1) = 0.05 mm, p_o (~ length^-1/2) to ~0.2 %
LINE_POINTS = 401


def crown_amounts(angle_deg: float) -> tuple[dict, str]:
    """{crown kind: printed amounts (Table 4 rows 1-3)} used at an out-of-plane angle, and where
    they come from (Table 4 at that angle, or at 0.05 deg where the thesis prints none)."""
    key = ("out", float(angle_deg))
    if key in TABLE34:
        return TABLE34[key], f"Table 4 at {angle_deg:g} deg"
    lowest = min(a for (pl, a) in TABLE34 if pl == "out")
    return TABLE34[("out", lowest)], f"Table 4 at {lowest:g} deg (no amount printed for {angle_deg:g} deg)"


def reference_pressure(design: Design, tol: float = 1e-12) -> dict:
    """p_o of eq 25: the aligned, unmodified 40/37 pair touches along a line; Hertz line-contact
    pressure at phi1 = 0 (not the pitch-point position) with the load over the contact line.

    The contact line is traced at LINE_POINTS face positions v1 (line-contact solve, v1 fixed); its
    relative curvature across the line is the larger principal relative curvature (the other is ~0);
    its length is the face-width span of the traced points inside both flanks over cos(beta_b)
    (the contact line is straight on the plane of action, inclined at beta_b to the axis)."""
    d = design.pairs["helical_40_37"]
    pair = pair_40_37(design)
    b = d["face_width"]
    v = np.linspace(-0.5 * b, 0.5 * b, LINE_POINTS)
    with np.errstate(invalid="ignore", divide="ignore"):
        c = solve_contact(
            pair,
            np.zeros(LINE_POINTS),
            np.column_stack([np.full(LINE_POINTS, pair.flank1.gear.r_p), v]),
            formulation="reduced",
            v1=v,
            tol=tol,
        )
    ok = c.status == Status.CONVERGED
    if not ok[LINE_POINTS // 2]:
        raise ValueError("no line contact of the aligned 40/37 pair at phi1 = 0")
    mid = c.take([LINE_POINTS // 2])
    rel = relative_curvature(*contact_curvatures(pair, mid))
    k_across = float(max(abs(rel.k1[0]), abs(rel.k2[0])))
    k_along = float(min(abs(rel.k1[0]), abs(rel.k2[0])))
    length = float(v[ok].max() - v[ok].min()) / np.cos(pair.flank1.gear.beta_b)
    Es = float(effective_modulus(d["young_modulus_MPa"], d["poisson_ratio"]))
    w = d["load_N"] / length
    return dict(
        p0_line_MPa=float(hertz_line_max_pressure_MPa(w, k_across, Es)),
        k_across_per_mm=k_across,
        k_along_per_mm=k_along,
        line_length_mm=float(length),
        line_inside_fraction=float(ok.mean()),
        load_per_length_N_per_mm=float(w),
        Estar_MPa=Es,
    )


def path_pressure(pair, n_points: int, load_N: float, E_MPa: float, nu: float, tol: float = 1e-12) -> dict:
    """Hertz contact along one pair's engagement: the largest p_max and where, and the values at the
    contact nearest phi1 = 0."""
    phi, c = engagement_contacts(pair, n_points, tol)
    h = contact_hertz(pair, c, load_N, E_MPa, nu)
    good = h.status == Status.CONVERGED
    if not good.any():
        return dict(p_max_MPa=np.nan, p_at_phi1_0_MPa=np.nan, n_points=0)
    i = int(np.nanargmax(np.where(good, h.p0, -np.inf)))
    j = int(np.argmin(np.where(good, np.abs(phi), np.inf)))
    return dict(
        p_max_MPa=float(h.p0[i]),
        phi1_at_p_max_rad=float(phi[i]),
        v1_at_p_max_mm=float(c.v1[i]),
        p_at_phi1_0_MPa=float(h.p0[j]),
        v1_at_phi1_0_mm=float(c.v1[j]),
        a_at_phi1_0_mm=float(h.a[j]),
        b_at_phi1_0_mm=float(h.b[j]),
        p_min_path_MPa=float(np.nanmin(np.where(good, h.p0, np.inf))),
        n_points=int(good.sum()),
    )


def loaded_pressure(pair, design: Design, n_positions: int) -> dict:
    """Largest flank pressure of ``pair`` over one meshing cycle of the loaded analysis under the
    torque T = 200 N x r_b1 cos(beta_b) (the Table 2 load as the normal load of the aligned pair),
    Table 2's material; with the torque, failed positions and the positions where a tip edge carries
    load."""
    d = design.pairs["helical_40_37"]
    g1 = pair.flank1.gear
    T = d["load_N"] * float(g1.r_b * np.cos(g1.beta_b)) / 1000.0
    r = ltca.loaded_contact(
        pair,
        T,
        ltca.cycle_positions(pair, n_positions),
        materials=ltca.Material(d["young_modulus_MPa"], d["poisson_ratio"]),
    )
    sm = r.summary()
    return dict(
        p_max_loaded_MPa=sm.max_contact_pressure_MPa,
        torque_loaded_Nm=T,
        failed_loaded=sm.n_failed,
        tip_edge_positions_loaded=sm.tip_edge_contact_positions,
        pairs_loaded_max=int(np.max(r.pairs_loaded)),
    )


def stress_table(settings: dict, design: Design) -> dict:
    """Job ``stress``: stress ratios of the crowned 40/37 pair at the Fig 29 out-of-plane angles,
    each crown kind and each Table 4 row of ``crowning_rows`` (see the module docstring)."""
    d = design.pairs["helical_40_37"]
    n = int(settings["stress_n_points"])
    a2 = float(settings["crowning_log_a2"])
    ref = reference_pressure(design, tol=float(settings["tol"]))
    base = pair_40_37(design)
    n_loaded = int(settings["stress_loaded_positions"])
    p0_loaded = loaded_pressure(base, design, n_loaded)["p_max_loaded_MPa"]
    rows = []
    for ang in FIG29_ANGLES_DEG:
        amounts, source = crown_amounts(ang)
        mis = misalignment("out", ang * DEG, base, settings["te_pivot"])
        for kind in KINDS:
            for i, amount in enumerate(amounts[kind]):
                if i + 1 not in settings["crowning_rows"] or (i > 0 and "no amount" in source):
                    continue
                pair = pair_40_37(design, crowning_object(kind, amount, d["face_width"], a2), mis)
                r = path_pressure(pair, n, d["load_N"], d["young_modulus_MPa"], d["poisson_ratio"])
                loaded = loaded_pressure(pair, design, n_loaded) if i == 0 else {}  # row 1: the checked one
                p_l = loaded.get("p_max_loaded_MPa", np.nan)
                rows.append(
                    dict(
                        plane="out",
                        misalignment_deg=ang,
                        crown_kind=kind,
                        table_row=i + 1,
                        crown_amount=amount,
                        amount_source=source,
                        log_a2=a2,
                        **r,
                        stress_ratio=r["p_max_MPa"] / ref["p0_line_MPa"],
                        stress_ratio_at_phi1_0=r["p_at_phi1_0_MPa"] / ref["p0_line_MPa"],
                        **loaded,
                        p0_loaded_MPa=p0_loaded,
                        loaded_positions=n_loaded,
                        stress_ratio_loaded=p_l / p0_loaded,
                        load_N=d["load_N"],
                        young_modulus_MPa=d["young_modulus_MPa"],
                        poisson_ratio=d["poisson_ratio"],
                        **ref,
                    )
                )
    return dict(stress=pd.DataFrame(rows))
