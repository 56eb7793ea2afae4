"""One package per replicated paper, every one with the same face (:mod:`._face`).

:data:`REGISTRY` is the one list of studies: key -> seed -> document. The workflow's rules, the
data README and the report read it; :func:`load` imports a study's package.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from types import ModuleType

__all__ = ["Study", "REGISTRY", "load"]


@dataclass(frozen=True)
class Study:
    """A replicated study: its package key, the seed id of its document, the document."""

    key: str
    seed: str
    document: str


REGISTRY: dict[str, Study] = {
    s.key: s
    for s in (
        Study("tseng_curvature", "000", "curvilinear-tooth cylindrical gears cut by a ZA worm hob, ch. 4 (curvatures)"),
        Study("tseng_tca", "000", "curvilinear-tooth cylindrical gears cut by a ZA worm hob, ch. 5 (TCA, KE)"),
        Study("nasa", "002", "NASA CR-2000-209415, Novikov-Wildhaber helical gears"),
        Study("thesis", "003", "PhD thesis 2023, conventional vs reduced TCA"),
        Study("catt", "004", "Ma et al. 2021, circular-arc-tooth-trace (CATT) cylindrical gears"),
    )
}


def load(key: str) -> ModuleType:
    """The package of study ``key`` (a key of :data:`REGISTRY`)."""
    if key not in REGISTRY:
        raise KeyError(f"no study {key!r}; studies: {sorted(REGISTRY)}")
    return importlib.import_module(f"{__name__}.{key}")
