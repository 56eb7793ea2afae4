"""One package per replicated paper, every one with the same face and the same files for the
same roles (:mod:`._face`).

:data:`REGISTRY` is the one list of studies: key -> seed -> document (the document titles and
names per seed are the published data's :data:`gearrep.published.PAPERS` and
:data:`~gearrep.published.PAPER_NAMES`). A study's key is its document's name
(``litvin2000``), or ``<name>_<part>`` when one document has two studies (``hobcut_curvature``,
``hobcut_tca``); a validation study (no paper) is named by what it validates (``ltca``). The workflow's rules, the
scorecard and the report read it (a test keeps the data README's seed table equal to it);
:func:`load` imports a study's package.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from types import ModuleType

from ..checks import VALIDATION
from ..published import PAPER_NAMES, PAPERS

__all__ = ["Study", "REGISTRY", "load"]


@dataclass(frozen=True)
class Study:
    """A replicated study: its package key, the seed id of its document, what it covers."""

    key: str
    seed: str
    scope: str
    title: str = ""

    @property
    def validation(self) -> bool:
        """A validation study (no paper): its seed is :data:`gearrep.checks.VALIDATION`."""
        return self.seed == VALIDATION

    @property
    def paper(self) -> str:
        """The name of the replicated document (:data:`gearrep.published.PAPER_NAMES`), or a
        validation study's key."""
        return self.key if self.validation else PAPER_NAMES[self.seed]

    @property
    def document(self) -> str:
        """Title of the replicated document (one per seed, :data:`gearrep.published.PAPERS`), or
        a validation study's own title."""
        return self.title if self.validation else PAPERS[self.seed]


REGISTRY: dict[str, Study] = {
    study.key: study
    for study in (
        Study("hobcut_curvature", "000", "ch. 4: curvature tables 4.2-4.5 of the hob-generated gear"),
        Study("hobcut_tca", "000", "ch. 5: TCA and kinematic-error tables 5.2-5.9, contact ellipses"),
        Study("litvin2000", "002", "curvatures, contact ellipses, TCA and TE under misalignment, worm-plunged pinion"),
        Study("temirkhan2023", "003", "convergence of conventional vs reduced TCA, TE of crowned gears"),
        Study("ma2021", "004", "contact-ellipse area along the path and every stated trend"),
        Study(
            "ltca",
            VALIDATION,
            "loaded TCA against ISO 6336 closed forms, load balance, symmetry, convergence and its limits",
            "Validation of the loaded tooth contact analysis (gearrep.ltca)",
        ),
    )
}


def load(key: str) -> ModuleType:
    """The package of study ``key`` (a key of :data:`REGISTRY`)."""
    if key not in REGISTRY:
        raise KeyError(f"no study {key!r}; studies: {sorted(REGISTRY)}")
    return importlib.import_module(f"{__name__}.{key}")
