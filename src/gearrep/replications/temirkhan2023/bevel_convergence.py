"""The convergence study of the bevel pairs (Tables 11-12: straight bevel 39/32 and spiral bevel
17/17) with the protocol of Table 10 (:mod:`.convergence`), and the ``convergence`` job, which runs
it beside the cylindrical pairs' studies. Readings and the pairs are in :mod:`.bevel`."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ...solve import Status
from ...tca import BevelPair, draw_starts, seed_from_reduced, solve_contact, solve_conventional
from .bevel import BEVEL_STREAMS, CASES, READINGS, bevel_pair
from .convergence import (
    ALL_VARIANTS,
    CONVERGENCE_COLUMNS,
    EQUATION_ABLATION,
    Collected,
    Reference,
    convergence_study,
    helical_sensitivity,
    helical_studies,
    loop_timing,
    sec61_studies,
    starts_table,
    table10_studies,
    timing_table,
)
from .design import Design
from .model import ThesisFrame, wrap

__all__ = ["bevel_reference", "convergence_pair", "bevel_convergence", "rng_bevel", "convergence_tables"]


# ----------------------------------------------------------------------------------------------
# convergence (Tables 11-12)
# ----------------------------------------------------------------------------------------------
def bevel_reference(pair: BevelPair, phi1: float, settings: dict) -> Reference:
    """Verified reference contact: reduced solve from mid-flank (several starts along the profile),
    then the conventional formulation from the seeded start; both must converge and agree."""
    lo, hi = pair.lower1, pair.upper1
    u0 = lo[0] + np.array([0.5, 0.3, 0.7, 0.15, 0.85]) * (hi[0] - lo[0])
    st = np.column_stack([u0, np.full(len(u0), 0.5 * (lo[1] + hi[1]))])
    c = solve_contact(pair, np.full(len(u0), phi1), st, formulation="reduced", tol=settings["tol"], maxiter=100)
    ok = np.flatnonzero(c.converged)
    if not len(ok):
        raise ValueError(f"no bevel reference contact at phi1 = {phi1!r}")
    x = c.unknowns("conventional")[ok[0]]
    _, n1 = pair.member1(x[:1], x[1:2], phi1)
    drop = int(np.argmax(np.abs(n1[0])))
    r = solve_conventional(
        pair,
        phi1,
        seed_from_reduced(pair, phi1, x[:1], x[1:2]),
        variant="damped",
        drop=drop,
        tol=settings["tol"],
        maxiter=100,
    )
    if r.status[0] != Status.CONVERGED:
        raise ValueError(f"conventional bevel reference did not converge at phi1 = {phi1!r}")
    ref = Reference(phi1=float(phi1), x=x, x_conventional=r.x[0].copy(), drop=drop)
    if ref.max_diff_mm > settings["agree_tol_mm"] or ref.diff_rad > settings["agree_tol_rad"]:
        raise ValueError(f"bevel reference: formulations disagree by {ref.max_diff_mm:.3g} / {ref.diff_rad:.3g} rad")
    return ref


def convergence_pair(settings: dict, design, case: str) -> BevelPair:
    crown = (
        settings["bevel_conv_crown_straight_per_mm"]
        if case.startswith("straight")
        else settings["bevel_conv_crown_spiral"]
    )
    return bevel_pair(design, case, crown=crown)


def bevel_convergence(settings: dict, design) -> dict:
    """Tables 11-12: every variant of Table 10 (and its equation ablation) from the same random
    starts (u1, v1, u2, v2 uniform on the flanks, phi2 uniform on the primary window centred on the
    root), correct root inside both flanks only. Returns rows (convergence), references, the
    per-solve accuracy (mean |x - x_ref| over the correct starts and the five unknowns, phi2
    wrapped) with the batch and one-start-per-call loop times of plain and reduced Newton."""
    rows, refs, acc, timing = [], [], [], []
    w0 = float(settings["primary_phi2_window_rad"])
    for case in CASES:
        pair = convergence_pair(settings, design, case)
        ref = bevel_reference(pair, READINGS["phi1_rad"], settings)
        refs.append(_reference_row(case, ref))
        n = int(settings["bevel_n_starts"])
        st = draw_starts(pair, n, rng_bevel(settings, case), phi2_window=(ref.x[4] - w0 / 2, ref.x[4] + w0 / 2))
        study = "Table 11" if case.startswith("straight") else "Table 12"
        r = convergence_study(
            case,
            pair,
            ref,
            st,
            ALL_VARIANTS,
            settings,
            window=w0,
            study=study,
            start_rule="u1,v1,u2,v2 uniform on the flanks; phi2 uniform on the window centred on the root",
            equations=EQUATION_ABLATION,
        )
        rows += r.rows
        if case.startswith("spiral"):
            rows += _crown_sensitivity_rows(settings, design, case, ref, st, w0)
            rows += _other_flank_rows(settings, design, case, ref, st, w0)
        acc += _accuracy_rows(case, r, ref)
        timing += [loop_timing(settings, pair, ref, r.rows, st, lab) for lab in ("plain", "reduced")]
    accuracy = pd.DataFrame(acc).merge(
        pd.DataFrame(timing)[["case", "variant", "seconds_per_solve_batch", "seconds_per_solve_loop", "n_loop"]],
        on=["case", "variant"],
        how="left",
    )
    return dict(rows=rows, refs=pd.DataFrame(refs), accuracy=accuracy)


def _reference_row(case: str, ref: Reference) -> dict:
    """Row of bevel_references.csv: the verified reference contact of one pair."""
    return dict(
        case=case,
        phi1_rad=ref.phi1,
        u1_rad=ref.x[0],
        v1=ref.x[1],
        u2_rad=ref.x[2],
        v2=ref.x[3],
        phi2_rad=ref.x[4],
        conventional_minus_reduced=ref.max_diff_mm,
        conventional_minus_reduced_rad=ref.diff_rad,
        dropped_normal_component="xyz"[ref.drop],
    )


def _same_starts_rows(settings, design, case, ref, st, w0, c1, flank_pair, label, study, start_rule) -> list:
    """The Table 12 starts (phi2 moved with the root) on the spiral pair with crown ``c1`` meshing
    ``flank_pair``: rows of plain, reduced and reduced_robust."""
    pc = bevel_pair(design, case, crown=float(c1), flank_pair=flank_pair)
    rc = bevel_reference(pc, READINGS["phi1_rad"], settings)
    stc = st.copy()
    stc[:, 4] += rc.x[4] - ref.x[4]
    return convergence_study(
        label,
        pc,
        rc,
        stc,
        ("plain", "reduced", "reduced_robust"),
        settings,
        window=w0,
        study=study,
        start_rule=start_rule,
    ).rows


def _crown_sensitivity_rows(settings: dict, design, case: str, ref: Reference, st: np.ndarray, w0: float) -> list:
    """Crown sensitivity of the Table 12 study: the same starts on the pair with each crown c_1 of
    the settings."""
    rows = []
    for c1 in settings["bevel_conv_crown_spiral_sensitivity"]:
        rule = f"as Table 12 with c_1 = {float(c1):g}"
        rows += _same_starts_rows(
            settings,
            design,
            case,
            ref,
            st,
            w0,
            c1,
            "convex1",
            f"{case}_c1_{float(c1):g}",
            "Table 12 (crown sensitivity)",
            rule,
        )
    return rows


def _other_flank_rows(settings: dict, design, case: str, ref: Reference, st: np.ndarray, w0: float) -> list:
    """The Table 12 study on the spiral pair's other flank pair (``concave1``: gear 1's lengthwise
    concave flank drives), at the Table 12 crown and at each crown of the sensitivity rows, from the
    same starts."""
    rows = []
    for c1 in [settings["bevel_conv_crown_spiral"], *settings["bevel_conv_crown_spiral_sensitivity"]]:
        tag = "" if float(c1) == float(settings["bevel_conv_crown_spiral"]) else f"_c1_{float(c1):g}"
        rule = f"as Table 12 on the other flank pair (gear 1 concave) with c_1 = {float(c1):g}"
        rows += _same_starts_rows(
            settings,
            design,
            case,
            ref,
            st,
            w0,
            c1,
            "concave1",
            f"{case}_concave1{tag}",
            "Table 12 (other flank pair)",
            rule,
        )
    return rows


def _accuracy_rows(case: str, r, ref: Reference) -> list:
    """Per variant: mean and max |x - x_ref| over the correct starts and the five unknowns (phi2 wrapped)."""
    acc = []
    for lab, (o, x, _) in r.outcomes.items():
        ok = o == "correct"
        d = np.abs(x[ok] - ref.x) if ok.any() else np.full((1, 5), np.nan)
        d[:, 4] = np.abs(wrap(d[:, 4]))
        acc.append(
            dict(
                case=case,
                variant=lab,
                n_correct=int(ok.sum()),
                mean_abs_error=float(np.mean(d)),
                max_abs_error=float(np.max(d)),
            )
        )
    return acc


def rng_bevel(settings: dict, case: str) -> np.random.Generator:
    return np.random.default_rng([int(settings["seed"]), BEVEL_STREAMS[case]])


def convergence_tables(settings: dict, design: Design) -> dict:
    """Job ``convergence``: every convergence study -> convergence (summary), convergence_detail,
    agreement, references, the per-start tables of Table 10, sec 6.1 and Table 9, and the timing of
    the Table 10 study."""
    out = Collected(rows=[], agree=[], refs=[], details={})
    table10_studies(settings, design, out)
    sec61_studies(settings, design, out)
    helical_studies(settings, design, out)
    out.rows += helical_sensitivity(settings, design)
    bev = bevel_convergence(settings, design)  # straight and spiral bevel pairs (Tables 11-12)
    out.rows += bev["rows"]
    detail = pd.DataFrame(out.rows)
    tables = dict(
        convergence=detail[CONVERGENCE_COLUMNS].copy(),
        convergence_detail=detail,
        agreement=pd.DataFrame(out.agree),
        references=pd.DataFrame(out.refs),
    )
    for name, key in (("starts_table10", "table10"), ("starts_sec61", "sec61"), ("starts_helical", "helical")):
        res = out.details[key]
        tables[name] = starts_table(res, ThesisFrame.of(res.pair))
    tables["timing"] = timing_table(settings, out.details["table10"])
    tables["bevel_references"] = bev["refs"]
    tables["bevel_accuracy"] = bev["accuracy"]
    return tables
