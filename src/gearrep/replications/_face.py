"""The face every replication package shows (one shape for all papers; see the package docstring).

A replication is a package ``gearrep.replications.<key>`` whose ``__init__`` defines:

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
    ``{job name: Job}``: each job computes its tables alone (one workflow job per requested
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

Paths are relative to ``results/``; table names are the file stems.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from types import ModuleType

__all__ = ["Job", "run_jobs", "table_paths", "FACE", "check_face"]


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
