"""Validation of the loaded tooth contact analysis :mod:`gearrep.ltca` (a validation study, not a
replicated paper: its records have the seed :data:`gearrep.checks.VALIDATION`).

What is checked (docs/ltca.md, :mod:`.checks` for every tolerance's reason): the pitch-point
Hertz pressure of unmodified spur pairs with one tooth pair loaded against ISO 6336-2's closed
form; the single-pair and mean mesh stiffness of standard spur pairs (several tooth numbers and
modules) against ISO 6336-1's c'_th and c_gamma_alpha; the load balance at every position of
spur, helical, crowned-misaligned and CATT pairs; the symmetry of an equal pair; the grid
convergence; the unloaded TCA as the torque vanishes; Hertz's point contact when the teeth are
rigid. Modules: :mod:`.design` (the pairs), :mod:`.studies` (one function per job),
:mod:`.checks`, :mod:`.bench`. The notebook ``notebooks/ltca.ipynb`` tells the findings.
"""

from __future__ import annotations

from ... import settings as _s
from ...checks import VALIDATION
from .._face import FACE, run_jobs
from .bench import bench_cases  # noqa: F401  (face: in __all__ through *FACE)
from .checks import checks  # noqa: F401  (face: in __all__ through *FACE)
from .design import Design, params_from_published, validate  # noqa: F401
from .studies import JOBS

__all__ = [*FACE, "Design"]

SEED = VALIDATION

SETTINGS = _s.declare(
    n_nodes=_s.integer(
        21,
        "1",
        "nodes along the face per tooth pair (bench: 21 holds the 1 % of a halving on the README pair)",
        ge=2,
        le=1001,
    ),
    n_positions=_s.integer(41, "1", "mesh positions per meshing cycle", ge=3, le=2001),
    single_positions=_s.integer(
        21, "1", "positions over one tooth pair's engagement for the largest single-pair stiffness", ge=3, le=2001
    ),
    tol=_s.number(
        1e-10,
        "1",
        "relative load change that ends the fixed-point iteration of the Hertz non-linearity",
        ge=1e-14,
        le=1e-4,
    ),
    convergence_nodes=_s.array(
        [11, 21, 41, 81],
        "1",
        "node counts of the grid convergence, each halving the spacing (validate)",
        _s.integer(None, "1", "", ge=2, le=2001),
        min_items=2,
    ),
)

DESIGN_DATA = ["params_003_spur_52_72.csv", "params_004_examples.csv"]
CHECK_DATA = []


CHECK_OUTPUTS = {"checks": "checks/ltca.csv"}

FIGURES = {
    "cycle": "ltca/figures/loaded_te_and_load_sharing.png",
    "pressure": "ltca/figures/pressure_map.png",
    "stiffness": "ltca/figures/stiffness_vs_iso.png",
    "convergence": "ltca/figures/grid_convergence.png",
}
REPORT_FIGURES = ["cycle", "stiffness"]


def run(settings: dict, design: Design, jobs=None) -> dict:
    """Tables of every job (or of the named ``jobs``), after :func:`validate`."""
    validate(settings, design)
    return run_jobs(JOBS, settings, design, jobs)
