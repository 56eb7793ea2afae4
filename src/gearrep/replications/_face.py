"""The face every replication package shows (one shape for all papers; see the package docstring)
and the files that hold each part of it (the same file for the same role in every package).

A replication is a package ``gearrep.replications.<key>`` whose ``__init__`` defines (or imports
from its role file, below):

``SEED``
    the seed id of the replicated document (``"000"`` ...), as in ``data/published``.
``SETTINGS``
    its numerical settings, declared once with :mod:`gearrep.settings` (value, range, unit,
    reason). The config section ``<key>:`` and the test configuration only override them.
``DESIGN_DATA``
    glob patterns of the ``data/published`` files that ``params_from_published`` reads (declared
    as inputs of every job of the study).
``CHECK_DATA``
    glob patterns of the ``data/published`` files its checks compare with.
``params_from_published(published) -> design``
    the paper's design data (any object) from a :class:`gearrep.published.Published`; the one
    route by which design data enter. Pure: it reads no file.
``JOBS``
    ``{job name: Job}`` (in ``studies.py``): each job computes its tables alone (one workflow job per requested
    output). ``Job.compute(settings, design) -> {table name: DataFrame}``.
``run(settings, design, jobs=None) -> {table name: DataFrame}``
    every job (or the named ones) in one process: :func:`run_jobs`.
``checks(tables, published) -> {"checks": DataFrame, ...}``
    check records of every published value and claim of the seed (``gearrep.checks``); further
    keys are extra tables written beside them (``CHECK_OUTPUTS`` gives their paths).
``CHECK_OUTPUTS``
    ``{name: path under results/}`` of what ``checks`` returns (``"checks"`` first).
``FIGURES``
    ``{figure key: path under results/}`` drawn by ``workflow/scripts/<key>_figures.py``;
    ``REPORT_FIGURES``: the keys the report embeds.
``bench_cases(settings, design) -> list``
    the time-vs-error cases of ``gearrep.benchmark``.
``validate(settings, design) -> None``
    cross-field checks beyond each setting's own range (raise ``SettingError`` naming the key);
    called before any job runs.


Files by role (:data:`ROLES`; :func:`check_roles`). Every package has the required ones and gives
no other module a role's name or a synonym of one (:data:`ROLE_SYNONYMS`):

``__init__.py``
    the face: ``SEED``, ``SETTINGS``, the data globs, ``run``, ``CHECK_OUTPUTS``, ``FIGURES``;
    it imports the rest from the role files and computes nothing itself.
``design.py``
    design data: ``params_from_published`` (the design object from the published data),
    ``validate`` (cross-field checks of the settings) and what is built from the design alone.
``studies.py``
    what is computed: ``JOBS`` and the functions of the jobs (one per job, ``f(settings,
    design)``); a large study keeps its functions in a topic module that ``studies.py`` imports.
``checks.py``
    check records: ``checks(tables, published)``; every published value routed to its computed
    counterpart with its tolerance, every claim's verdict made a record.
``claims.py`` (where the document states claims)
    claim predicates: claim id -> small predicate of the tables returning (holds, evidence).
``model.py`` (where the replication keeps the paper's equations)
    the paper's own printed equations and conventions, named as printed, kept as evidence and
    tested against the library route.
``bench.py``
    ``bench_cases`` (time against error, :mod:`gearrep.benchmark`) and, where the study has
    one, ``robustness_cases`` (the start-robustness table).

Any other module is a topic of the study (``geometry.py``, ``bevel.py``, ``te.py``), named by its
subject; the part of a role file split out for one topic is ``<topic>_<role>.py``
(``bevel_checks.py``, ``te_studies.py``). The design data two studies of one document share live
in ``replications/_<paper>_design.py``.

Paths are relative to ``results/``; table names are the file stems.
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from types import ModuleType

__all__ = ["Job", "run_jobs", "table_paths", "FACE", "check_face", "ROLES", "ROLE_SYNONYMS", "check_roles"]


@dataclass(frozen=True)
class Job:
    """One job of a study: ``compute(settings, design)`` returns exactly the tables named in
    ``tables`` ({table name: output path under results/}). ``priority``: about the job's run
    time in seconds for the long jobs (0 for the short ones); scheduling only: a cold workflow run
    starts the longest jobs first (its job rules get priority 1 + ``priority``)."""

    compute: Callable
    tables: Mapping[str, str]
    doc: str = field(default="")
    priority: int = 0

    def __post_init__(self):
        for name, path in self.tables.items():
            if PurePosixPath(path).stem != name or not path.endswith(".csv"):
                raise ValueError(f"table {name!r}: path {path!r} must end in {name}.csv")


def run_jobs(jobs: Mapping[str, Job], settings: dict, design, names=None) -> dict:
    """Tables of the named jobs (all if ``names`` is None), checked to be the declared ones."""
    names = list(jobs) if names is None else list(names)
    out = {}
    for name in names:
        if name not in jobs:
            raise KeyError(f"no job {name!r}; jobs: {sorted(jobs)}")
        got = jobs[name].compute(settings, design)
        if set(got) != set(jobs[name].tables):
            raise RuntimeError(f"job {name!r} returned tables {sorted(got)}, declared {sorted(jobs[name].tables)}")
        out.update(got)
    return out


def table_paths(jobs: Mapping[str, Job]) -> dict:
    """{table name: path under results/} over every job (a table belongs to one job only)."""
    out = {}
    for job in jobs.values():
        for name, path in job.tables.items():
            if name in out:
                raise ValueError(f"table {name!r} is written by two jobs")
            out[name] = path
    return out


#: names every replication package defines
FACE = (
    "SEED",
    "SETTINGS",
    "DESIGN_DATA",
    "CHECK_DATA",
    "params_from_published",
    "JOBS",
    "run",
    "checks",
    "CHECK_OUTPUTS",
    "FIGURES",
    "REPORT_FIGURES",
    "bench_cases",
    "validate",
)


def check_face(module: ModuleType) -> None:
    """Raise if ``module`` lacks a name of :data:`FACE` (or leaves one out of its ``__all__``, which
    each package starts with ``*FACE``) or a name has the wrong kind."""
    missing = [n for n in FACE if not hasattr(module, n)]
    if missing:
        raise TypeError(f"{module.__name__} lacks {missing} of the replication face")
    unlisted = [n for n in FACE if n not in getattr(module, "__all__", FACE)]
    if unlisted:
        raise TypeError(f"{module.__name__}.__all__ lacks {unlisted} of the replication face (start it with *FACE)")
    for n in ("params_from_published", "run", "checks", "bench_cases", "validate"):
        if not callable(getattr(module, n)):
            raise TypeError(f"{module.__name__}.{n} is not callable")
    if not all(isinstance(j, Job) for j in module.JOBS.values()):
        raise TypeError(f"{module.__name__}.JOBS must map names to Job")
    if next(iter(module.CHECK_OUTPUTS)) != "checks":
        raise TypeError(f"{module.__name__}.CHECK_OUTPUTS must start with 'checks'")
    table_paths(module.JOBS)


#: role file -> (required, the face names it defines)
ROLES = {
    "__init__": (True, ()),
    "design": (True, ("params_from_published", "validate")),
    "studies": (True, ("JOBS",)),
    "checks": (True, ("checks",)),
    "claims": (False, ()),
    "model": (False, ()),
    "bench": (True, ("bench_cases",)),
}
#: module names that would say a role under another name (a role has one name)
ROLE_SYNONYMS = ("records", "facts", "values", "verdicts", "params", "parameters", "equations", "jobs", "benchmark")


def check_roles(module: ModuleType) -> None:
    """Raise unless package ``module`` has every required file of :data:`ROLES`, each face name is
    defined in its role file (``module.checks is module.checks.checks``, ...), and no module is
    named by a synonym of a role (:data:`ROLE_SYNONYMS`)."""
    names = {m.name for m in pkgutil.iter_modules(module.__path__)} | {"__init__"}
    missing = [r for r, (required, _) in ROLES.items() if required and r not in names]
    if missing:
        raise TypeError(f"{module.__name__} lacks the role files {[f'{r}.py' for r in missing]}")
    synonyms = sorted(names & set(ROLE_SYNONYMS))
    if synonyms:
        raise TypeError(f"{module.__name__}: modules {synonyms} repeat a role under another name (see ROLES)")
    for role, (_, face_names) in ROLES.items():
        if not face_names:
            continue
        home = importlib.import_module(f"{module.__name__}.{role}")
        for n in face_names:
            obj = getattr(module, n)
            if getattr(home, n, None) is not obj or (callable(obj) and obj.__module__ != home.__name__):
                raise TypeError(f"{module.__name__}.{n} must be defined in {role}.py")
