"""Convergence from random starts: conventional vs reduced TCA (thesis sec 6.1-6.2, Table 10).

The protocol is written out in ``protocol.csv`` (:func:`.studies.protocol_table`); the solver
variants and start strategies are :mod:`gearrep.tca`'s. One random stream per study:
``default_rng([seed, STREAMS[study]])``. The ``convergence`` job, which runs these studies and the
bevel pairs' (Tables 11-12), is :func:`.bevel_convergence.convergence_tables`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ...benchmark import time_interleaved
from ...solve import Status
from ...tca import (
    CONVENTIONAL_VARIANTS,
    REDUCED_VARIANTS,
    GearPair,
    Misalignment,
    draw_starts,
    flank_boxes,
    line_of_action_start,
    seed_from_reduced,
    solve_contact,
    solve_conventional,
    solve_variant,
)
from ...units import ARCMIN, DEG
from .design import Design, design_pair, helical_pair
from .model import ThesisFrame, wrap

ALL_VARIANTS = CONVENTIONAL_VARIANTS + REDUCED_VARIANTS
OUTCOMES = ("correct", "wrong_root", "not_converged", "singular", "diverged")
#: variants that use the phi2 start (the others derive phi2 from (u1, v1))
USES_PHI2_START = ("plain", "damped", "domain")
#: one random stream per study: default_rng([seed, stream])
STREAMS = {
    "table10": 1,
    "window": 2,
    "sec61_guess": 3,
    "sec61_window": 4,
    "sec61_misaligned": 5,
    "helical": 6,
    "helical_misaligned": 7,
    "sec61_printed": 8,
    "helical_sensitivity": 9,
    "sec61_full_turn": 10,
    "helical_full_turn": 11,
    "helical_misaligned_full_turn": 12,
}
CONVERGENCE_COLUMNS = [
    "case",
    "formulation",
    "variant",
    "n_starts",
    "phi2_window_rad",
    "correct_pct",
    "wrong_root_pct",
    "mean_iterations",
    "seconds_per_solve",
]
EQUATION_ABLATION = {"plain_six": ("plain", "six"), "plain_drop_nz": ("plain", "drop_nz")}


def rng(settings: dict, study: str) -> np.random.Generator:
    return np.random.default_rng([int(settings["seed"]), STREAMS[study]])


@dataclass(frozen=True)
class Reference:
    """Verified reference contact (u1, v1, u2, v2, phi2) at phi1, solved by both formulations."""

    phi1: float
    x: np.ndarray
    x_conventional: np.ndarray
    drop: int

    @property
    def max_diff_mm(self) -> float:
        return float(np.max(np.abs(self.x[:4] - self.x_conventional[:4])))

    @property
    def diff_rad(self) -> float:
        return float(abs(wrap(self.x[4] - self.x_conventional[4])))


def reference_contact(pair: GearPair, phi1: float, tol: float = 1e-12, agree_mm=1e-9, agree_rad=1e-10) -> Reference:
    """Verified reference: reduced solve from the line-of-action start, then conventional from the
    seeded start; both must converge inside the flanks and agree (else ValueError)."""
    s = line_of_action_start(pair, phi1)
    with np.errstate(invalid="ignore", divide="ignore"):
        c = solve_contact(pair, phi1, s[None, :], formulation="reduced", tol=tol, maxiter=100)
    if c.status[0] != Status.CONVERGED:
        raise ValueError(f"no reference contact at phi1 = {phi1!r} (reduced status {c.status_name[0]})")
    x = c.unknowns("conventional")[0]
    _, n1 = pair.member1(x[:1], x[1:2], phi1)
    drop = int(np.argmax(np.abs(n1[0])))
    r = solve_conventional(
        pair, phi1, seed_from_reduced(pair, phi1, x[:1], x[1:2]), variant="damped", drop=drop, tol=tol, maxiter=100
    )
    if r.status[0] != Status.CONVERGED:
        raise ValueError(f"conventional reference did not converge at phi1 = {phi1!r}")
    ref = Reference(phi1=float(phi1), x=x, x_conventional=r.x[0].copy(), drop=drop)
    if ref.max_diff_mm > agree_mm or ref.diff_rad > agree_rad:
        raise ValueError(f"reference: formulations disagree by {ref.max_diff_mm:.3g} mm / {ref.diff_rad:.3g} rad")
    return ref


def study_reference(settings: dict, pair: GearPair, phi1_thesis: float) -> tuple[ThesisFrame, Reference]:
    fr = ThesisFrame.of(pair)
    return fr, reference_contact(
        pair,
        fr.phi1_from_thesis(phi1_thesis),
        tol=settings["tol"],
        agree_mm=settings["agree_tol_mm"],
        agree_rad=settings["agree_tol_rad"],
    )


def classify(pair: GearPair, x, status, ref: Reference, tol_mm=1e-6, tol_rad=1e-8) -> np.ndarray:
    """Outcome names (:data:`OUTCOMES`) of solves ``x`` (n, 5) with solver ``status``."""
    x = np.asarray(x, float)
    status = np.asarray(status)
    d = x - ref.x
    d[:, 4] = wrap(d[:, 4])
    with np.errstate(invalid="ignore"):
        same = np.all(np.abs(d[:, :4]) < tol_mm, axis=1) & (np.abs(d[:, 4]) < tol_rad)
    lo, hi = flank_boxes(pair, 0.0)
    slack = 1e-12 * (1 + np.abs(np.where(np.isfinite(lo), lo, 0)))
    with np.errstate(invalid="ignore"):
        inside = np.all((x >= lo - slack) & (x <= hi + slack), axis=1)
    solved = np.isin(status, [Status.CONVERGED, Status.OFF_FLANK, Status.WRONG_ROOT])
    out = np.full(len(x), "not_converged", dtype=object)
    out[status == Status.SINGULAR] = "singular"
    out[status == Status.DIVERGED] = "diverged"
    out[solved] = "wrong_root"
    out[solved & same & inside] = "correct"
    return out


#: timed repetitions of a batch solve: its seconds are the least CPU time of this process over them
#: (a batch of a few hundred starts takes milliseconds, which one wall-clock reading on a shared
#: machine can double; the least CPU time is what the solve itself costs)
TIMING_REPEATS = 3


def run_variant(
    pair: GearPair, ref: Reference, starts: np.ndarray, variant: str, settings: dict, equations: str = "five"
):
    """Solve all ``starts`` with ``variant``; returns (outcomes, iterations, x, seconds): seconds is
    the least CPU time of :data:`TIMING_REPEATS` timed solves (:func:`gearrep.benchmark.time_interleaved`)."""

    def solve():
        return solve_variant(
            pair,
            ref.phi1,
            starts,
            variant,
            equations=equations,
            drop=ref.drop,
            tol=settings["tol"],
            maxiter=settings["maxiter"],
            margin=settings["domain_margin"],
        )

    x, status, iters = solve()
    sec = time_interleaved({variant: solve}, repeats=TIMING_REPEATS, warmup=0, clock=time.process_time)[variant]
    return classify(pair, x, status, ref, settings["match_tol_mm"], settings["match_tol_rad"]), iters, x, sec


def formulation(variant: str) -> str:
    return "reduced" if variant in REDUCED_VARIANTS else "conventional"


def summarise(case, form, variant, outcomes, iters, sec, window, **extra) -> dict:
    n = len(outcomes)
    ok = outcomes == "correct"
    row = dict(
        case=case,
        formulation=form,
        variant=variant,
        n_starts=n,
        phi2_window_rad=window,
        correct_pct=100.0 * ok.mean(),
        wrong_root_pct=100.0 * np.mean(outcomes == "wrong_root"),
        mean_iterations=float(np.mean(iters[ok])) if ok.any() else np.nan,
        seconds_per_solve=sec / n,
    )
    for o in OUTCOMES[2:]:
        row[f"{o}_pct"] = 100.0 * np.mean(outcomes == o)
    row.update(extra)
    return row


@dataclass
class StudyResult:
    """Outcome of one convergence study: summary rows and per-start outcomes per variant."""

    rows: list
    starts: np.ndarray
    outcomes: dict  # variant -> (outcome names, x (n,5), iterations)
    ref: Reference
    pair: GearPair


def convergence_study(
    label: str,
    pair: GearPair,
    ref: Reference,
    starts: np.ndarray,
    variants,
    settings: dict,
    *,
    window: float,
    study: str,
    start_rule: str,
    equations: dict | None = None,
) -> StudyResult:
    """Run ``variants`` on the same ``starts``; ``equations`` maps a variant label to (variant, equations)
    for equation-choice ablations (e.g. ``{"plain_six": ("plain", "six")}``)."""
    rows, outcomes = [], {}
    jobs = [(v, v, "five") for v in variants] + [(lab, v, e) for lab, (v, e) in (equations or {}).items()]
    for lab, v, eq in jobs:
        out, it, x, sec = run_variant(pair, ref, starts, v, settings, equations=eq)
        w = window if v in USES_PHI2_START else np.nan
        rows.append(
            summarise(
                label,
                formulation(v),
                lab,
                out,
                it,
                sec,
                w,
                study=study,
                start_rule=start_rule,
                equations=eq if formulation(v) == "conventional" else "n1 x n2 (2 of 3)",
            )
        )
        outcomes[lab] = (out, x, it)
    return StudyResult(rows=rows, starts=starts, outcomes=outcomes, ref=ref, pair=pair)


def agreement_rows(res: StudyResult, label: str) -> list:
    """Largest difference between the two formulations at every start where both converged to the
    correct contact: each conventional variant against ``reduced_robust`` and each reduced variant
    against the conventional ``robust``."""
    rows = []
    if "reduced_robust" not in res.outcomes or "robust" not in res.outcomes:
        return rows
    for lab, (o, x, _) in res.outcomes.items():
        other = "robust" if lab in REDUCED_VARIANTS else "reduced_robust"
        o_r, x_r, _ = res.outcomes[other]
        both = (o == "correct") & (o_r == "correct")
        if not both.any():
            rows.append(
                dict(case=label, variant=lab, against=other, n_compared=0, max_diff_mm=np.nan, max_diff_rad=np.nan)
            )
            continue
        d = np.abs(x[both, :4] - x_r[both, :4])
        dphi = np.abs(wrap(x[both, 4] - x_r[both, 4]))
        rows.append(
            dict(
                case=label,
                variant=lab,
                against=other,
                n_compared=int(both.sum()),
                max_diff_mm=float(d.max()),
                max_diff_rad=float(dphi.max()),
            )
        )
    return rows


def reference_row(label: str, ref: Reference, frame: ThesisFrame) -> dict:
    x = ref.x
    return dict(
        case=label,
        phi1_rad=ref.phi1,
        phi1_thesis_rad=float(frame.phi1_to_thesis(ref.phi1)),
        u1_mm=x[0],
        v1_thesis_mm=float(frame.v_to_thesis(x[1])),
        u2_mm=x[2],
        v2_thesis_mm=float(frame.v_to_thesis(x[3])),
        phi2_rad=x[4],
        phi2_thesis_rad=float(frame.phi2_to_thesis(x[4])),
        conventional_minus_reduced_mm=ref.max_diff_mm,
        conventional_minus_reduced_rad=ref.diff_rad,
        dropped_normal_component="xyz"[ref.drop],
    )


@dataclass
class Collected:
    """Rows of convergence/agreement/references gathered over the studies, and the studies whose
    per-start outcomes are tabulated."""

    rows: list
    agree: list
    refs: list
    details: dict


# ----------------------------------------------------------------------------------------------
# the studies
# ----------------------------------------------------------------------------------------------
def table10_starts(settings: dict, design: Design):
    """Pair, reference and starts of the Table 10 study (spur 52/72, phi2 on the primary window)."""
    pair = design_pair(design, "spur_52_72")
    fr, ref = study_reference(settings, pair, design.pairs["spur_52_72"]["phi1_thesis"])
    w0 = float(settings["primary_phi2_window_rad"])
    st = draw_starts(
        pair, int(settings["n_starts"]), rng(settings, "table10"), phi2_window=(ref.x[4] - w0 / 2, ref.x[4] + w0 / 2)
    )
    return pair, fr, ref, st


TABLE10_RULE = "u1,v1,u2,v2 uniform on the flanks; phi2 uniform on the window centred on the root"


def table10_studies(settings: dict, design: Design, out: Collected) -> None:
    """Table 10 (all variants, equation ablation), its start-rule sensitivity and the window sweep."""
    pair, fr, ref, st = table10_starts(settings, design)
    out.refs.append(reference_row("spur_52_72", ref, fr))
    w0 = float(settings["primary_phi2_window_rad"])
    r = convergence_study(
        "spur_52_72",
        pair,
        ref,
        st,
        ALL_VARIANTS,
        settings,
        window=w0,
        study="Table 10",
        start_rule=TABLE10_RULE,
        equations=EQUATION_ABLATION,
    )
    out.rows += r.rows
    out.agree += agreement_rows(r, "spur_52_72")
    out.details["table10"] = r
    # start-rule sensitivity: (u2, v2) at the mid-point of flank 2 (sec 6.1's rule)
    st_mid = st.copy()
    st_mid[:, 2] = 0.5 * (pair.lower2[0] + pair.upper2[0])
    st_mid[:, 3] = 0.5 * (pair.lower2[1] + pair.upper2[1])
    out.rows += convergence_study(
        "spur_52_72_uv2_midpoint",
        pair,
        ref,
        st_mid,
        USES_PHI2_START,
        settings,
        window=w0,
        study="Table 10 (start-rule sensitivity)",
        start_rule="as Table 10 but u2,v2 at the mid-point of flank 2",
    ).rows
    # phi2 window sweep: same uniform draws, scaled to each window (the primary window is the Table 10 row)
    base = draw_starts(pair, int(settings["n_starts_window"]), rng(settings, "window"), phi2_window=(-0.5, 0.5))
    for w in settings["phi2_windows_rad"]:
        if abs(w - w0) < 1e-12:
            continue
        stw = base.copy()
        stw[:, 4] = ref.x[4] + base[:, 4] * w
        out.rows += convergence_study(
            "spur_52_72",
            pair,
            ref,
            stw,
            USES_PHI2_START,
            settings,
            window=float(w),
            study="phi2 window sweep",
            start_rule="as Table 10, window width varied",
        ).rows


def sec61_guess_studies(settings, design, pair, fr, ref, out: Collected) -> None:
    """Sec 6.1: fixed phi2 guesses (thesis frame), u2, v2 at the mid-point of flank 2."""
    base = draw_starts(
        pair, int(settings["n_starts_sec61"]), rng(settings, "sec61_guess"), phi2_fixed=0.0, uv2="midpoint"
    )
    for g in design.sec61_phi2_guesses_thesis:
        stg = base.copy()
        stg[:, 4] = fr.phi2_from_thesis(g)
        out.rows += convergence_study(
            f"spur_25_25_guess_{g:+.2f}rad",
            pair,
            ref,
            stg,
            USES_PHI2_START,
            settings,
            window=0.0,
            study="sec 6.1 fixed phi2 guess",
            start_rule=f"u1,v1 uniform; u2,v2 mid-point of flank 2; phi2 = {g} rad (thesis frame)",
        ).rows


def sec61_printed_flank_studies(settings, design, pair, fr, ref, win, out: Collected) -> None:
    """Start-domain sensitivity: the flank as Table 1 prints it (u up to r_b + m)."""
    lo_t, hi_t = design.sec61_phi2_window_thesis
    n6 = int(settings["n_starts_sec61"])
    rb, m = pair.flank1.r_b, design.pairs["spur_25_25"]["module"]
    g = rng(settings, "sec61_printed")
    u1p = g.uniform(rb, rb + m, n6)
    v1p = g.uniform(pair.lower1[1], pair.upper1[1], n6)
    php = g.uniform(*win, n6)
    stp = np.column_stack([u1p, v1p, np.full(n6, rb + 0.5 * m), np.zeros(n6), php])
    out.rows += convergence_study(
        "spur_25_25_window_thesis_table1_printed",
        pair,
        ref,
        stp,
        USES_PHI2_START,
        settings,
        window=hi_t - lo_t,
        study="sec 6.1 phi2 window (start-domain sensitivity)",
        start_rule="as sec 6.1 window but u1 uniform on [r_b, r_b + m] and u2 = r_b + m/2 (Table 1 as printed)",
    ).rows
    for gs in design.sec61_phi2_guesses_thesis:
        stg = stp.copy()
        stg[:, 4] = fr.phi2_from_thesis(gs)
        out.rows += convergence_study(
            f"spur_25_25_guess_{gs:+.2f}rad_table1_printed",
            pair,
            ref,
            stg,
            ("plain",),
            settings,
            window=0.0,
            study="sec 6.1 fixed phi2 guess (start-domain sensitivity)",
            start_rule="as the fixed-guess study with the Table 1 flank as printed",
        ).rows


def sec61_studies(settings: dict, design: Design, out: Collected) -> None:
    """Sec 6.1: spur 25/25, m = 2.5: fixed guesses, the printed window, start-domain sensitivity,
    a full turn, and the in-plane misaligned pair."""
    pair = design_pair(design, "spur_25_25")
    fr, ref = study_reference(settings, pair, design.pairs["spur_25_25"]["phi1_thesis"])
    out.refs.append(reference_row("spur_25_25", ref, fr))
    n6 = int(settings["n_starts_sec61"])
    sec61_guess_studies(settings, design, pair, fr, ref, out)
    lo_t, hi_t = design.sec61_phi2_window_thesis
    win = fr.window_from_thesis(lo_t, hi_t)
    stw = draw_starts(pair, n6, rng(settings, "sec61_window"), phi2_window=win, uv2="midpoint")
    r = convergence_study(
        "spur_25_25_window_thesis",
        pair,
        ref,
        stw,
        ALL_VARIANTS,
        settings,
        window=hi_t - lo_t,
        study="sec 6.1 phi2 window",
        start_rule=f"u1,v1 uniform; u2,v2 mid-point; phi2 uniform in ({lo_t}, {hi_t}) rad (thesis frame)",
    )
    out.rows += r.rows
    out.agree += agreement_rows(r, "spur_25_25_window_thesis")
    out.details["sec61"] = r
    sec61_printed_flank_studies(settings, design, pair, fr, ref, win, out)
    # the widest reading of "random phi2" (claim 003-S6.1-random_phi2_fails): a full turn
    stf = draw_starts(
        pair, n6, rng(settings, "sec61_full_turn"), phi2_window=(ref.x[4] - np.pi, ref.x[4] + np.pi), uv2="midpoint"
    )
    out.rows += convergence_study(
        "spur_25_25_full_turn",
        pair,
        ref,
        stf,
        ("plain",),
        settings,
        window=2 * np.pi,
        study="sec 6.1 random phi2 (full turn)",
        start_rule="u1,v1 uniform; u2,v2 mid-point of flank 2; phi2 uniform on a full turn",
    ).rows
    deg = design.sec61_misalignment_deg
    pair_m = design_pair(design, "spur_25_25", misalignment=Misalignment(d_gamma_in=float(deg) * DEG))
    fr_m = ThesisFrame.of(pair_m)
    ref_m = reference_contact(
        pair_m, ref.phi1, tol=settings["tol"], agree_mm=settings["agree_tol_mm"], agree_rad=settings["agree_tol_rad"]
    )
    lab = f"spur_25_25_inplane_{deg:g}deg"
    out.refs.append(reference_row(lab, ref_m, fr_m))
    stm = draw_starts(
        pair_m, n6, rng(settings, "sec61_misaligned"), phi2_window=fr_m.window_from_thesis(lo_t, hi_t), uv2="midpoint"
    )
    r = convergence_study(
        lab,
        pair_m,
        ref_m,
        stm,
        ALL_VARIANTS,
        settings,
        window=hi_t - lo_t,
        study="sec 6.1 misaligned",
        start_rule=f"as sec 6.1 window; in-plane misalignment {deg} deg",
    )
    out.rows += r.rows
    out.agree += agreement_rows(r, lab)


def helical_studies(settings: dict, design: Design, out: Collected) -> None:
    """Table 9 helical 25/77, aligned and misaligned: the printed window, iteration limit x 4, a full turn."""
    lo_t, hi_t = design.helical_phi2_window_thesis
    n6 = int(settings["n_starts_sec61"])
    arcmin = design.helical_misalignment_arcmin
    for key, mis in (("helical", None), ("helical_misaligned", Misalignment(d_gamma_in=float(arcmin) * ARCMIN))):
        pair = design_pair(design, "helical_25_77", misalignment=mis)
        fr, ref = study_reference(settings, pair, design.pairs["helical_25_77"]["phi1_thesis"])
        lab = "helical_25_77" if mis is None else f"helical_25_77_inplane_{arcmin:g}arcmin"
        out.refs.append(reference_row(lab, ref, fr))
        sth = draw_starts(pair, n6, rng(settings, key), phi2_window=fr.window_from_thesis(lo_t, hi_t), uv2="midpoint")
        r = convergence_study(
            lab,
            pair,
            ref,
            sth,
            ALL_VARIANTS,
            settings,
            window=hi_t - lo_t,
            study="Table 9 helical",
            start_rule=f"u1,v1 uniform; u2,v2 mid-point; phi2 uniform in ({lo_t}, {hi_t}) rad (thesis frame)",
        )
        out.rows += r.rows
        out.agree += agreement_rows(r, lab)
        out.details[key] = r
        if mis is None:  # claim 003-S6.1-helical_more_iterations_no_help: same starts, iteration limit x 4
            s4 = dict(settings, maxiter=4 * int(settings["maxiter"]))
            out.rows += convergence_study(
                f"{lab}_maxiter_x4",
                pair,
                ref,
                sth,
                ("plain",),
                s4,
                window=hi_t - lo_t,
                study="Table 9 helical (iteration limit x 4)",
                start_rule=f"as {lab}, iteration limit {s4['maxiter']}",
            ).rows
        # claim 003-S6.1-helical_random_phi2_fails: phi2 uniform on a full turn
        stf = draw_starts(
            pair,
            n6,
            rng(settings, key + "_full_turn"),
            phi2_window=(ref.x[4] - np.pi, ref.x[4] + np.pi),
            uv2="midpoint",
        )
        out.rows += convergence_study(
            f"{lab}_full_turn",
            pair,
            ref,
            stf,
            ("plain",),
            settings,
            window=2 * np.pi,
            study="Table 9 helical random phi2 (full turn)",
            start_rule="u1,v1 uniform; u2,v2 mid-point; phi2 uniform on a full turn",
        ).rows


HELICAL_READINGS = [
    ("uv2_uniform", 1.0, "true", "uniform", "five"),
    ("equations_six", 1.0, "true", "midpoint", "six"),
    ("equations_drop_nz", 1.0, "true", "midpoint", "drop_nz"),
    ("crown_x10", 10.0, "true", "midpoint", "five"),
    ("crown_x0.1", 0.1, "true", "midpoint", "five"),
    ("helix_eq58", 1.0, "asin", "midpoint", "five"),
]


def helical_sensitivity(settings: dict, design: Design) -> list:
    """Table 9 pair, thesis window: plain Newton under other readings of the thesis (each a row)."""
    d = design.pairs["helical_25_77"]
    lo_t, hi_t = design.helical_phi2_window_thesis
    n = max(10, int(settings["n_starts_sec61"]) // 2)
    rows = []
    for lab, scale, form, uv2, eq in HELICAL_READINGS:
        pair = helical_pair(
            d["n1"],
            d["n2"],
            d["module"],
            d["pressure_angle_deg"] * DEG,
            d["helix_angle_deg"] * DEG,
            d["face_width"],
            hand1=d["hand1"],
            profile_crown1=scale * d["profile_crown1"],
            profile_crown2=scale * d["profile_crown2"],
            helix_form=form,
        )
        try:
            fr, ref = study_reference(settings, pair, d["phi1_thesis"])
        except ValueError:
            continue
        st = draw_starts(
            pair, n, rng(settings, "helical_sensitivity"), phi2_window=fr.window_from_thesis(lo_t, hi_t), uv2=uv2
        )
        rows += convergence_study(
            f"helical_25_77_{lab}",
            pair,
            ref,
            st,
            (),
            settings,
            window=hi_t - lo_t,
            study="Table 9 helical (sensitivity)",
            start_rule=f"thesis window; {lab}",
            equations={"plain" if eq == "five" else f"plain_{eq}": ("plain", eq)},
        ).rows
    return rows


def starts_table(res: StudyResult, frame: ThesisFrame) -> pd.DataFrame:
    """Per-start table of a study: the start (thesis frame too) and the outcome of every variant."""
    st = res.starts
    df = pd.DataFrame(
        dict(
            u1_0_mm=st[:, 0],
            v1_0_thesis_mm=frame.v_to_thesis(st[:, 1]),
            u2_0_mm=st[:, 2],
            v2_0_thesis_mm=frame.v_to_thesis(st[:, 3]),
            phi2_0_thesis_rad=frame.phi2_to_thesis(st[:, 4]),
        )
    )
    for lab, (o, x, it) in res.outcomes.items():
        df[f"outcome_{lab}"] = o
        df[f"iterations_{lab}"] = it
        df[f"u1_{lab}_mm"] = x[:, 0]
        df[f"v1_{lab}_thesis_mm"] = frame.v_to_thesis(x[:, 1])
    return df


#: Table 10: total time for 5000 converged points, failed starts replaced (Mathematica, unknown hardware)
THESIS_TABLE10_TOTAL_S = {"conventional": 839.62, "reduced": 232.09}
TIMED_VARIANTS = ("plain", "robust", "reduced", "reduced_robust")


def loop_timing(settings: dict, pair, ref: Reference, rows: list, starts: np.ndarray, variant: str) -> dict:
    """Seconds per solve of ``variant``: the vectorised batch of a study (its row in ``rows``) beside
    a loop of single-start calls over the first ``timing_loop_n`` of its ``starts`` (the way a
    per-point solver such as Mathematica's FindRoot is used)."""
    batch = next(r for r in rows if r["variant"] == variant)
    sub = starts[: int(settings["timing_loop_n"])]
    t0 = time.perf_counter()
    for i in range(len(sub)):
        run_variant(pair, ref, sub[i : i + 1], variant, settings)
    loop = (time.perf_counter() - t0) / len(sub)
    return dict(
        case=batch["case"],
        formulation=batch["formulation"],
        variant=variant,
        seconds_per_solve_batch=batch["seconds_per_solve"],
        seconds_per_solve_loop=loop,
        n_loop=len(sub),
        correct_pct=batch["correct_pct"],
    )


def timing_table(settings: dict, res: StudyResult) -> pd.DataFrame:
    """Seconds per solve of both formulations on the Table 10 starts (:func:`loop_timing` of the
    study ``res``), per correct solve, beside the thesis's totals."""
    rows = []
    for lab in TIMED_VARIANTS:
        row = loop_timing(settings, res.pair, res.ref, res.rows, res.starts, lab)
        thesis_total = THESIS_TABLE10_TOTAL_S[row["formulation"]]
        ok = row["correct_pct"] > 0
        rows.append(
            row
            | dict(
                seconds_per_correct_solve_batch=row["seconds_per_solve_batch"] * 100.0 / row["correct_pct"]
                if ok
                else np.nan,
                seconds_per_correct_solve_loop=row["seconds_per_solve_loop"] * 100.0 / row["correct_pct"]
                if ok
                else np.nan,
                thesis_total_s_5000=thesis_total,
                thesis_seconds_per_correct_point=thesis_total / 5000,
            )
        )
    return pd.DataFrame(rows)
