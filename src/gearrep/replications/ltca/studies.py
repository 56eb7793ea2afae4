"""The jobs of the loaded-contact validation: one function per job, each returning its tables.

Every computation is :func:`gearrep.ltca.loaded_contact` on pairs of :mod:`.design`; the ISO
closed forms are :mod:`gearrep.ltca.iso`. Lengths mm, loads N, torques N m, pressures MPa,
stiffness N/(mm um).
"""

from __future__ import annotations

import time

import numpy as np
import pandas as pd

from ... import ltca
from ...ltca import iso as iso6336
from ...meshing import contact_ratio_closed_form
from ...tca import contact_hertz, solve_contact
from .._face import Job
from .design import (
    ISO_DESIGNS,
    Design,
    catt_pair,
    helical_pair,
    iso_pair,
    pitch_torque_Nm,
    readme_pair,
    symmetric_pair,
)

__all__ = ["JOBS", "iso", "iso_pressure", "iso_stiffness", "properties", "convergence", "cycle", "LOAD_N_PER_MM"]

#: nominal tangential load per face width of the ISO comparisons [N/mm] (ISO 6336-1 states c' for
#: F_t K_A / b >= 100 N/mm)
LOAD_N_PER_MM = 300.0
#: torque of the README pair [N m] (docs/ltca.md)
README_TORQUE_NM = 50.0


def _kw(settings: dict) -> dict:
    return dict(n_nodes=int(settings["n_nodes"]), tol=float(settings["tol"]))


def _design_row(z1, z2, m, g1, T) -> dict:
    return dict(
        design=f"z1={z1};z2={z2};m_mm={m:g}", z1=z1, z2=z2, module_mm=m, face_width_mm=g1.face_width, torque_Nm=T
    )


def _pitch(pair) -> np.ndarray:
    return ltca.cycle_positions(pair, 3)[[1]]


def iso(settings: dict, design: Design) -> dict:
    """Job ``iso``: the comparisons with ISO 6336's closed forms (:func:`iso_pressure`,
    :func:`iso_stiffness`)."""
    return iso_pressure(settings, design) | iso_stiffness(settings, design)


def iso_pressure(settings: dict, design: Design) -> dict:
    """Pitch-point Hertz pressure of unmodified spur pairs with one tooth pair carrying the load,
    against ISO 6336-2's sigma_H0 (Z_eps = Z_beta = 1); beside it the pressure with every tooth
    pair free to take load (the neighbours' tip edges close under load)."""
    rows = []
    for z1, z2, m in ISO_DESIGNS:
        pair = iso_pair(z1, z2, m)
        g1 = pair.flank1.gear
        T = pitch_torque_Nm(pair, LOAD_N_PER_MM)
        one = ltca.loaded_contact(pair, T, _pitch(pair), pairs=[0], **_kw(settings))
        every = ltca.loaded_contact(pair, T, _pitch(pair), **_kw(settings))
        Ft = 1000.0 * T / g1.r_p
        ref = iso6336.pitch_point_stress_MPa(
            Ft,
            2.0 * g1.r_p,
            g1.face_width,
            z2 / z1,
            iso6336.zone_factor(g1.alpha_t),
            iso6336.elasticity_factor(206000.0, 0.3),
        )
        rows.append(
            _design_row(z1, z2, m, g1, T)
            | dict(
                Ft_N=Ft,
                sigma_H0_iso_MPa=ref,
                p_ltca_MPa=float(one.max_pressure_MPa[0]),
                rel_err=float(one.max_pressure_MPa[0] / ref - 1.0),
                status=int(one.status[0]),
                p_every_pair_MPa=float(every.max_pressure_MPa[0]),
                pairs_loaded_every_pair=int(every.pairs_loaded[0]),
                tip_edge_load_share=float(every.tip_edge_load_N[0] / every.normal_load_N[0]),
                n_nodes=int(settings["n_nodes"]),
            )
        )
    return {"iso_pressure": pd.DataFrame(rows)}


def _single_stiffness(pair, T, settings, bore=(None, None), n=21):
    """Largest single-pair stiffness over one tooth pair's engagement (pair 0 alone, positions one
    pitch either side of the pitch point) and the stiffness at the pitch point."""
    p1 = 2.0 * np.pi / pair.n1
    phi = _pitch(pair)[0] + np.linspace(-p1, p1, n)
    r = ltca.loaded_contact(pair, T, phi, pairs=[0], bore_radius_mm=bore, **_kw(settings))
    k = np.where(r.converged, r.mesh_stiffness_N_per_mm_um, np.nan)
    return float(np.nanmax(k)), float(k[n // 2])


def iso_stiffness(settings: dict, design: Design) -> dict:
    """Single-pair stiffness c' (largest over one pair's engagement) and mean mesh stiffness
    c_gamma (over a meshing cycle, every tooth pair) of the ISO designs at F_t/b = LOAD_N_PER_MM,
    against ISO 6336-1's theoretical value for the pair's basic rack, c'_th C_B, and
    c_gamma_alpha = c'_th C_B (0.75 eps_alpha + 0.25); the single
    stiffness with a thin rim (bore h_f = 1.4) and a small bore (h_f = 3) beside it; and the
    shares of the compliance at the pitch point (both members' bending, shear, compression and
    foundation, and the contact approach)."""
    rows, shares = [], []
    for z1, z2, m in ISO_DESIGNS:
        pair = iso_pair(z1, z2, m)
        g1, g2 = pair.flank1.gear, pair.flank2.gear
        T = pitch_torque_Nm(pair, LOAD_N_PER_MM)
        c_single, c_pitch = _single_stiffness(pair, T, settings, n=int(settings["single_positions"]))
        thin = _single_stiffness(pair, T, settings, (g1.r_f / 1.4, g2.r_f / 1.4), n=3)[1]
        small = _single_stiffness(pair, T, settings, (g1.r_f / 3.0, g2.r_f / 3.0), n=3)[1]
        cyc = ltca.loaded_contact(pair, T, ltca.cycle_positions(pair, int(settings["n_positions"])), **_kw(settings))
        summ = cyc.summary()
        eps = float(contact_ratio_closed_form(g1.r_a, g1.r_b, g2.r_a, g2.r_b, pair.centre_distance, g1.base_pitch))
        c_B = 0.5 * sum(iso6336.basic_rack_factor(g.h_f, np.degrees(g.pressure_angle)) for g in (g1, g2))
        c_th = iso6336.single_stiffness_theoretical(z1, z2)
        c_ref = c_th * c_B  # ISO's theoretical value for the pair's basic rack
        c_ga = iso6336.mesh_stiffness_c_gamma_alpha(c_ref, eps)
        rows.append(
            _design_row(z1, z2, m, g1, T)
            | dict(
                eps_alpha=eps,
                c_single_N_per_mm_um=c_single,
                c_single_pitch_N_per_mm_um=c_pitch,
                c_single_thin_rim_N_per_mm_um=thin,
                c_single_small_bore_N_per_mm_um=small,
                c_th_iso_N_per_mm_um=c_th,
                basic_rack_factor=c_B,
                c_ref_iso_N_per_mm_um=c_ref,
                single_ratio=c_single / c_ref,
                c_gamma_N_per_mm_um=summ.mesh_stiffness_mean_N_per_mm_um,
                c_gamma_alpha_iso_N_per_mm_um=c_ga,
                mesh_ratio=summ.mesh_stiffness_mean_N_per_mm_um / c_ga,
                tip_edge_contact_positions=summ.tip_edge_contact_positions,
                n_failed=summ.n_failed,
            )
        )
        shares.append(_compliance_shares(pair, T, settings) | {"design": rows[-1]["design"]})
    return {"iso_stiffness": pd.DataFrame(rows), "stiffness_terms": pd.DataFrame(shares)}


def _compliance_shares(pair, T, settings) -> dict:
    """Shares of the pitch-point compliance (single pair, uniform load along the face)."""
    r = ltca.loaded_contact(pair, T, _pitch(pair), pairs=[0], **_kw(settings))
    c = r.separations.contacts
    j = int(np.flatnonzero(r.separations.in_contact.ravel())[len(r.separations.z_mm[0, 0]) // 2])
    out = {}
    for name, flank, u, v in (("1", pair.flank1, c.u1[j], c.v1[j]), ("2", pair.flank2, c.u2[j], c.v2[j])):
        for term, val in ltca.ToothCompliance(flank).terms(np.array([u]), np.array([v])).items():
            out[f"{term}{name}_mm2_per_N"] = float(val[0])
    w = float(r.normal_load_N[0] / (pair.flank1.gear.face_width))
    h1 = float(ltca.ToothCompliance(pair.flank1).load_geometry(np.array([c.u1[j]]))[2][0])
    h2 = float(ltca.ToothCompliance(pair.flank2).load_geometry(np.array([c.u2[j]]))[2][0])
    k = float(r.separations.k_rel_per_mm[0, 0, 0])
    out["contact_mm2_per_N"] = float(ltca.weber_contact_approach_mm(w, k, h1, h2, ltca.STEEL, ltca.STEEL) / w)
    total = sum(out.values())
    return out | {"total_mm2_per_N": total, "stiffness_N_per_mm_um": 1e-3 / total}


def _balance(name, r, normal_N=None) -> dict:
    ok = r.converged
    rel = np.nan if normal_N is None else float(np.max(np.abs(r.normal_load_N[ok] / normal_N - 1.0)))
    return dict(
        case=name,
        n_positions=int(ok.size),
        n_failed=int(np.sum(~ok)),
        moment_residual_max=float(np.max(r.moment_residual[ok])),
        normal_load_rel_err_max=rel,
    )


def properties(settings: dict, design: Design) -> dict:
    """Job ``properties``: load balance of every converged position (spur, crowned and misaligned,
    helical, CATT), symmetry of an equal pair, the unloaded limit, the rigid-tooth (Hertz) limit and
    the grid convergence (:func:`convergence`)."""
    kw = _kw(settings)
    n = int(settings["n_positions"])
    rows = []
    spur = readme_pair(design, misaligned=False, crowned=False)
    rb = spur.flank1.gear.r_b
    rows.append(
        _balance(
            "spur_52_72",
            ltca.loaded_contact(spur, README_TORQUE_NM, **kw | {"n_nodes": 11}),
            1000.0 * README_TORQUE_NM / rb,
        )
    )
    crowned = readme_pair(design)
    rows.append(_balance("readme_pair", ltca.loaded_contact(crowned, README_TORQUE_NM, **kw)))
    hel = helical_pair()
    g = hel.flank1.gear
    r = ltca.loaded_contact(hel, 30.0, ltca.cycle_positions(hel, n), **kw | {"n_nodes": 11})
    rows.append(_balance("helical_40_37", r, 30e3 / (g.r_b * np.cos(g.beta_b))))
    catt, c = catt_pair(design), design.catt
    r = ltca.loaded_contact(
        catt,
        c["torque_Nm"],
        ltca.cycle_positions(catt, 9),
        materials=ltca.Material(c["E_MPa"], c["poisson"]),
        pairs=[-1, 0, 1],
        **kw,
    )
    rows.append(_balance("catt_sec4_B", r))
    out = {"balance": pd.DataFrame(rows)}
    out["limits"] = pd.DataFrame([_symmetry(kw), *_unloaded(crowned, kw), _hertz_limit(design, kw)])
    return out | convergence(settings, design)


def _symmetry(kw) -> dict:
    pair = symmetric_pair()
    phi_p = _pitch(pair)[0]
    d = np.linspace(0.0, np.pi / 30, 6)
    a, b = (ltca.loaded_contact(pair, 40.0, phi_p + sgn * d, **kw) for sgn in (1, -1))
    scale = np.max(np.abs(a.lte_urad))
    dev = max(
        float(np.max(np.abs(a.lte_urad - b.lte_urad)) / scale),
        float(np.max(np.abs(a.max_pressure_MPa / b.max_pressure_MPa - 1.0))),
        float(np.max(np.abs(np.sort(a.pair_load_N, axis=1) - np.sort(b.pair_load_N, axis=1))) / np.max(a.pair_load_N)),
    )
    return dict(case="symmetry_30_30", quantity="mirror_deviation_max", value=dev, bound=np.nan, detail="")


def _unloaded(pair, kw) -> list:
    """The rigid TE of the nodes against the TCA's point-contact TE (of the leading tooth pair),
    and the loaded TE's elastic part at a vanishing torque."""
    phi = ltca.cycle_positions(pair, 9)
    full = ltca.loaded_contact(pair, README_TORQUE_NM, phi, **kw)
    tiny = ltca.loaded_contact(pair, 1e-6 * README_TORQUE_NM, phi, **kw)
    p1 = 2.0 * np.pi / pair.n1
    tcas = [solve_contact(pair, phi - j * p1) for j in (-1, 0, 1)]
    te_tca = np.max([np.where(c.converged, c.te, -np.inf) for c in tcas], axis=0)
    deficit = te_tca - full.te_unloaded_rad
    sep = full.separations
    first = np.nanargmax(np.where(sep.in_contact, sep.sense * sep.te_rad, -np.inf).reshape(phi.size, -1), axis=1)
    k = first // sep.z_mm.shape[2]
    dz = np.diff(sep.z_mm, axis=-1)[np.arange(phi.size), k, 0]  # the leading pair's node spacing
    c1 = pair.flank1.crowning.c1
    bound = c1 * (dz / 2.0) ** 2 / pair.flank2.gear.r_b
    e_full = np.abs(full.te_loaded_rad - full.te_unloaded_rad)
    e_tiny = np.abs(tiny.te_loaded_rad - tiny.te_unloaded_rad)
    return [
        dict(
            case="readme_pair",
            quantity="rigid_te_deficit_over_bound",
            value=float(np.max(deficit / bound)),
            bound=float(np.max(bound)),
            detail=f"bound c1 (dz/2)^2 / r_b2 up to {np.max(bound):.3g} rad (node "
            f"spacings {np.min(dz):.3g} to {np.max(dz):.3g} mm); smallest deficit {np.min(deficit):.2e} rad",
        ),
        dict(
            case="readme_pair",
            quantity="elastic_te_ratio_1e-6_torque",
            value=float(np.max(e_tiny / e_full)),
            bound=1e-4,
            detail="elastic TE at 1e-6 of the torque over the elastic TE at the torque",
        ),
    ]


def _hertz_limit(design: Design, kw) -> dict:
    """Rigid teeth (tooth compliance off), crowned aligned pair, one tooth pair at the pitch point,
    a small load: the coupled nodes against Hertz's point contact (gearrep.tca.contact_hertz)."""
    pair = readme_pair(design, misaligned=False)
    phi = _pitch(pair)
    r = ltca.loaded_contact(pair, 0.05, phi, pairs=[0], tooth_bending=False, maxiter=300, **kw | {"n_nodes": 41})
    c = solve_contact(pair, phi)
    h = contact_hertz(pair, c, r.normal_load_N[0], 206000.0, 0.3)
    sep = r.separations
    j = int(np.argmax(np.nan_to_num(r.node_load_N[0, 0])))
    h1 = float(ltca.ToothCompliance(pair.flank1).load_geometry(np.array([sep.contacts.u1[j]]))[2][0])
    a, b = float(h.a[0]), float(h.b[0])
    est = (b / a) ** 2 * np.log(a / b) + (a / h1) ** 2 / 8.0
    return dict(
        case="readme_pair_aligned_rigid",
        quantity="pressure_over_hertz",
        value=float(r.max_pressure_MPa[0] / h.p0[0]),
        bound=est,
        detail=f"a = {a:.4g} mm, b = {b:.4g} mm, h1 = {h1:.4g} mm, Hertz p0 = {float(h.p0[0]):.5g} MPa, "
        f"strips {float(r.max_pressure_MPa[0]):.5g} MPa; status {int(r.status[0])}",
    )


def convergence(settings: dict, design: Design) -> dict:
    """The README pair at 9 positions of a cycle with the node counts of ``convergence_nodes``
    (each halving the spacing): largest flank pressure, loaded TE peak to peak, mean mesh
    stiffness and run time per position."""
    pair = readme_pair(design)
    phi = ltca.cycle_positions(pair, 9)
    rows = []
    for n in settings["convergence_nodes"]:
        t0 = time.perf_counter()
        r = ltca.loaded_contact(pair, README_TORQUE_NM, phi, n_nodes=int(n), tol=float(settings["tol"]))
        dt = time.perf_counter() - t0
        summ = r.summary()
        rows.append(
            dict(
                n_nodes=int(n),
                max_pressure_MPa=summ.max_contact_pressure_MPa,
                lte_peak_to_peak_urad=summ.lte_peak_to_peak_urad,
                mesh_stiffness_mean_N_per_mm_um=summ.mesh_stiffness_mean_N_per_mm_um,
                n_failed=summ.n_failed,
                seconds_per_position=dt / phi.size,
            )
        )
    return {"convergence": pd.DataFrame(rows)}


def cycle(settings: dict, design: Design) -> dict:
    """Loaded cycles of the README pair and of the same pair unmodified and aligned over three
    meshing cycles (one row per position and tooth pair), and the pressure map of the README pair's
    position of largest pressure."""
    rows, maps = [], []
    n = int(settings["n_positions"])
    for name, pair in (("readme_pair", readme_pair(design)), ("unmodified", readme_pair(design, False, False))):
        phi = ltca.cycle_positions(pair, n)
        p1 = 2.0 * np.pi / pair.n1
        phi = np.concatenate([phi[:-1] - p1, phi[:-1], phi + p1])
        r = ltca.loaded_contact(pair, README_TORQUE_NM, phi, **_kw(settings))
        for i in range(phi.size):
            for k, pk in enumerate(r.separations.pairs):
                if not np.any(r.separations.in_contact[i, k]):
                    continue
                rows.append(
                    dict(
                        case=name,
                        phi1_rad=phi[i],
                        pair=int(pk),
                        te_unloaded_urad=r.te_unloaded_rad[i] * 1e6,
                        te_unloaded_um=r.te_unloaded_rad[i] * pair.flank2.gear.r_b * 1000.0,
                        lte_urad=r.lte_urad[i],
                        lte_um=r.lte_um[i],
                        pair_load_N=r.pair_load_N[i, k],
                        normal_load_N=r.normal_load_N[i],
                        max_pressure_MPa=r.max_pressure_MPa[i],
                        tip_edge_load_N=r.tip_edge_load_N[i],
                        mesh_stiffness_N_per_mm_um=r.mesh_stiffness_N_per_mm_um[i],
                        status=int(r.status[i]),
                    )
                )
        if name == "readme_pair":
            i = int(np.nanargmax(np.where(r.converged, r.max_pressure_MPa, -np.inf)))
            pm = r.pressure_map(i, n_across=41)
            for k, pk in enumerate(pm.pairs):
                for j in range(pm.z_mm.shape[1]):
                    if pm.kind[k, j] == 0:
                        continue
                    for x, p in zip(pm.across_mm, pm.pressure_MPa[k, j]):
                        maps.append(
                            dict(
                                phi1_rad=phi[i],
                                pair=int(pk),
                                z_mm=pm.z_mm[k, j],
                                across_mm=x,
                                radius1_mm=float(np.hypot(*pm.position_mm[k, j, :2])),
                                pressure_MPa=p,
                            )
                        )
    return {"cycle": pd.DataFrame(rows), "pressure_map": pd.DataFrame(maps)}


def _job(fn, *names, priority=0):
    return Job(fn, {n: f"ltca/{n}.csv" for n in names}, " ".join(fn.__doc__.split("\n\n")[0].split()), priority)


JOBS = {
    "iso": _job(iso, "iso_pressure", "iso_stiffness", "stiffness_terms", priority=5),
    "properties": _job(properties, "balance", "limits", "convergence", priority=5),
    "cycle": _job(cycle, "cycle", "pressure_map", priority=3),
}
