"""Replication of seed 003 (Temirkhan, PhD thesis 2023): conventional vs reduced TCA.

What is replicated (one job per table group, :data:`JOBS`):

* convergence from random starts (sec 6.1-6.2, Table 10): the conventional five-unknown TCA
  (eq 26-32) against the reduced two-unknown TCA (eq 33-44) on the crowned spur pair 52/72, the
  25/25 pitch-point example of sec 6.1 and the helical pair of Table 9 (aligned and misaligned),
  with the solver variants and start strategies of :mod:`gearrep.tca` (:mod:`.convergence`);
* TE and path of contact of crowned spur (sec 4.1) and helical (Tables 3-4) gears under in-plane
  and out-of-plane misalignment, the TE areas S_c, S_p, S_l and candidate readings of the printed
  Delta phi_max (:mod:`.te`);
* the errata found and the convergence protocol as run (:mod:`.studies`, which holds :data:`JOBS`);
* the Hertz stress ratios of the crowned helical 40/37 pair (sec 4.2, Fig 29; :mod:`.stress`), the
  sec 6.1 path study with offset phi2 guesses (:mod:`.path_guess`) and the helical/spur contact
  shift at a common angle and crown (:func:`.te.shift_common_angle_table`).

* straight and spiral bevel gears (sec 5.1-5.2, Tables 11-12; :mod:`.bevel`): their convergence
  rows in ``convergence.csv`` (:mod:`.bevel_convergence`) and the contact studies (TE, path, Hertz pressure) of jobs
  ``bevel_straight`` and ``bevel_spiral``.

The thesis's frame and printed formulas are in :mod:`.model`; its design data
enter only through :func:`params_from_published` (:mod:`.design`); checks and claims are in
:mod:`.checks` and :mod:`.claims`.

Errata (evidence in errata.csv and the tests): eq (27) n1 - n2 = 0 should read n1 + n2 = 0; the
worded sign rule of eq (43)-(44) gives the wrong sign; Table 1's tip diameter d_b + 2m should be
d_p + 2m; Tables 3-4's crowning amounts fall as the misalignment grows while the TE grows linearly;
sec 6.1's "-1.3 rad - phi2_sol = -0.335 rad" has the wrong sign; eq (1)/(57), (5)/(58) see
:mod:`gearrep.surfaces.involute`.
"""

from __future__ import annotations

import numpy as np

from ... import settings as st
from .._face import FACE, run_jobs
from .bench import bench_cases  # noqa: F401  (face: in __all__ through *FACE)
from .bevel import bevel_pair
from .checks import checks, fact_key  # noqa: F401  (face: in __all__ through *FACE)
from .claims import CLAIMS, claim_verdicts, conv_row
from .convergence import (
    OUTCOMES,
    STREAMS,
    Reference,
    classify,
    reference_contact,
    rng,
    run_variant,
    study_reference,
)
from .design import (  # noqa: F401  (face: in __all__ through *FACE)
    TABLE34,
    Design,
    design_pair,
    misalignment,
    pair_40_37,
    params_from_published,
    validate,
)
from .model import ThesisFrame, crown_curvature, crowning_object, profile_crowning, wrap
from .stress import FIG29_ANGLES_DEG, crown_amounts, path_pressure, reference_pressure
from .studies import JOBS
from .te import first_order_te, te_study

SEED = "003"

_TWO_PI = 2 * np.pi
_WINDOW = st.number(None, "rad", "", gt=0, le=_TWO_PI)
_A2 = st.number(None, "1", "", gt=0, lt=1)

SETTINGS = st.declare(
    seed=st.integer(20231019, "1", "random starts: numpy default_rng([seed, stream])", ge=0),
    tol=st.number(
        1.0e-13,
        "mm",
        "Newton residual norm (mm / unit normals); 1e-13 keeps both formulations within "
        "1e-9 mm (bench: fastest meeting the target); a converged point must be a contact",
        gt=0,
        le=1e-6,
    ),
    maxiter=st.integer(50, "1", "Newton iteration limit", ge=1, le=1000),
    match_tol_mm=st.number(
        1.0e-6, "mm", "a converged start is the reference contact if |du|, |dv| are below this", gt=0
    ),
    match_tol_rad=st.number(1.0e-8, "rad", "... and |dphi2| (mod 2 pi) below this", gt=0),
    agree_tol_mm=st.number(1.0e-9, "mm", "the two formulations' reference contacts must agree to this", gt=0),
    agree_tol_rad=st.number(1.0e-10, "rad", "... and in phi2 to this", gt=0),
    domain_margin=st.number(
        1.0e-6,
        "1",
        "domain-kept Newton: u limits moved in by this fraction of the flank height (the involute cusp at u = r_b)",
        gt=0,
        lt=0.5,
    ),
    n_starts=st.integer(
        5000,
        "1",
        "Table 10 random starts (as in the thesis; bench: 2000 already meets the 0.18 pp target, 5000 costs 0.1 s)",
        ge=10,
        le=100000,
    ),
    n_starts_sec61=st.integer(1000, "1", "sec 6.1 and Table 9 studies (as in the thesis)", ge=10, le=100000),
    n_starts_window=st.integer(
        1000, "1", "phi2-window sweep (sampling error ~1 pp, enough for the curve)", ge=10, le=100000
    ),
    primary_phi2_window_rad=st.number(
        _TWO_PI, "rad", "Table 10: phi2 start over a full turn (not stated in the thesis)", gt=0, le=_TWO_PI
    ),
    phi2_windows_rad=st.array(
        [0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.0, 2.5, np.pi, 4.0, 5.0],
        "rad",
        "widths of the phi2-window sweep (a width equal to primary_phi2_window_rad is the "
        "Table 10 row itself and is not rerun)",
        _WINDOW,
    ),
    timing_loop_n=st.integer(25, "1", "one-start-per-call timing loop", ge=1, le=10000),
    te_n_points=st.integer(
        61,
        "1",
        "TE grid points per mesh cycle (bench: no grid meets 5e-8 arcsec; knee at 41, 61 kept for the curves)",
        ge=5,
        le=2001,
    ),
    crowning_log_a2=st.number(0.9, "1", "eq (12) a2, not printed in the thesis", gt=0, lt=1),
    crowning_log_a2_sensitivity=st.array(
        [0.5, 0.9, 0.99], "1", "a2 values of the logarithmic-crown sensitivity rows (te_sensitivity.csv)", _A2
    ),
    crowning_rows=st.array(
        [1, 2, 3],
        "1",
        "rows of Tables 3-4 computed (1 = first printed row; row 1 is needed by the crowning areas)",
        st.integer(None, "1", "", ge=1, le=3),
        max_items=3,
    ),
    stress_n_points=st.integer(
        21,
        "1",
        "stress ratios (sec 4.2): contact points per mesh cycle along the path (grid 4 n + 1 over 2.5 pitches); "
        "p_max along the path moves by < 0.5 % from 21 to 121 (it lies at the end of engagement)",
        ge=5,
        le=2001,
    ),
    stress_loaded_positions=st.integer(
        41,
        "1",
        "stress ratios, loaded reading (sec 4.2; gearrep.ltca): mesh positions per cycle of the loaded analysis; "
        "the largest pressures lie where the load passes between tooth pairs, so a coarse grid misses them "
        "(the reference pressure p_o grows with the number of positions up to about 41: docs/ltca.md)",
        ge=5,
        le=2001,
    ),
    bevel_n_starts=st.integer(
        1000, "1", "Tables 11-12 random starts per bevel pair (as in the thesis)", ge=10, le=100000
    ),
    bevel_conv_crown_straight_per_mm=st.number(
        0.002857 / 2.5,
        "1/mm",
        "Table 11 pair's parabolic lead crown on gear 1 (not printed): Table 10's a_1 = 0.002857 (m = 1) scaled to m = 2.5 mm",
        gt=0,
        le=0.1,
    ),
    bevel_conv_crown_spiral=st.number(
        0.002,
        "1/module",
        "Table 12 pair's parabolic lead crown on gear 1 (not printed): Table 7's smallest c_1",
        gt=0,
        le=0.1,
    ),
    bevel_conv_crown_spiral_sensitivity=st.array(
        [0.005, 0.02],
        "1/module",
        "further c_1 of the Table 12 study (plain, reduced, reduced_robust only): Figs 46-53 and Table 7's largest",
        st.number(None, "1/module", "", gt=0, le=0.1),
        min_items=0,
    ),
    bevel_te_n_points=st.integer(
        121,
        "1",
        "bevel TE grid points per mesh cycle (sec 5.1-5.2 studies; 4 n + 1 angles per tooth pair; the TE extremes "
        "read from the envelope at 64 n + 1 angles): the spiral rows' TE peak-to-peak moves by <= 0.01 arcsec from "
        "121 to 481",
        ge=5,
        le=2001,
    ),
    bevel_straight_crown_per_mm=st.array(
        [0.0008, 0.008],
        "1/mm",
        "sec 5.1 small and large lead crown (not printed): Table 7's c_1 range 0.002-0.02 (module units) scaled to m = 2.5 mm",
        st.number(None, "1/mm", "", gt=0, le=0.1),
        min_items=2,
        max_items=2,
    ),
    bevel_straight_relief_mm=st.array(
        [0.4, 0.2],
        "mm",
        "sec 5.1 tip and root relief length L and amount c on gear 1 (not printed): Table 7's L_t = 0.16, c_t = 0.08 (module units) scaled to m = 2.5 mm",
        st.number(None, "mm", "", gt=0, le=5.0),
        min_items=2,
        max_items=2,
    ),
    bevel_straight_shaft_angles_deg=st.array(
        [0.1, 0.2],
        "deg",
        "shaft-angle errors of the crown-type comparison (Figs 38-39; Table 6's 0.2 deg and half of it)",
        st.number(None, "deg", "", gt=0, lt=5),
    ),
    bevel_spiral_angles_deg=st.array(
        [0.05, 0.1, 0.2],
        "deg",
        "spiral pair angular errors (Table 7 range 0-0.2 deg)",
        st.number(None, "deg", "", gt=0, lt=5),
    ),
    bevel_spiral_sweep=st.array(
        [0.02, 0.04, 0.06, 0.08, 0.1],
        "module",
        "dE, dH and dE = dH values of the Fig 53 sweep (Table 7 range 0.02-0.1)",
        st.number(None, "module", "", gt=0, le=0.5),
        min_items=2,
    ),
    te_pivot=st.choice(
        "pitch_point",
        ("pitch_point", "axis"),
        "misalignment pivot for the TE studies: pitch_point or axis (member 2's mid-face axis point)",
    ),
)

DESIGN_DATA = ("params_003_*.csv",)
CHECK_DATA = ("values_003_*.csv", "claims_003.csv")


CHECK_OUTPUTS = {"checks": "checks/temirkhan2023.csv"}
FIGURES = {
    "clouds": "temirkhan2023/figures/convergence_clouds_table10.png",
    "clouds_phi2": "temirkhan2023/figures/convergence_clouds_phi2.png",
    "window": "temirkhan2023/figures/convergence_vs_phi2_window.png",
    "guess": "temirkhan2023/figures/convergence_vs_phi2_guess_sec61.png",
    "te": "temirkhan2023/figures/te_curves.png",
    "paths": "temirkhan2023/figures/contact_paths.png",
}
REPORT_FIGURES = ("window", "clouds")


def run(settings: dict, design: Design, jobs=None) -> dict:
    """Tables of the named jobs (all if None) in one process (pure: no file access)."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)


__all__ = [
    *FACE,  # the replication face (gearrep.replications._face)
    # the study's building blocks (used by the tests and the notebook)
    "Design",
    "design_pair",
    "pair_40_37",
    "misalignment",
    "TABLE34",
    "ThesisFrame",
    "wrap",
    "profile_crowning",
    "crowning_object",
    "crown_curvature",
    "Reference",
    "reference_contact",
    "study_reference",
    "classify",
    "run_variant",
    "rng",
    "STREAMS",
    "OUTCOMES",
    "te_study",
    "first_order_te",
    "fact_key",
    "CLAIMS",
    "claim_verdicts",
    "conv_row",
    "FIG29_ANGLES_DEG",
    "crown_amounts",
    "reference_pressure",
    "path_pressure",
    "bevel_pair",
]
