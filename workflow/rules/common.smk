# Shared helpers for the rules: the configuration resolved before any job, library modules as
# inputs, published-data files, report figures.
import sys
from pathlib import Path

sys.path.insert(0, str(Path(workflow.basedir, "workflow", "lib")))

from modgraph import ModuleGraph
from wfconfig import resolve_config, validate_studies

from gearrep import published as _published
from gearrep.replications import REGISTRY
from gearrep.replications import load as load_study
from gearrep.replications._face import table_paths
from gearrep.settings import SettingError

# Every setting of every study resolved and checked (unknown sections and keys, types, ranges,
# NaN, cross-field limits with the design data) before any job runs, whether it comes from
# config/config.yaml, --configfile or --config: a bad value stops the run with one line naming the
# key, the value and what is allowed (the closest declared name for an unknown one), not a
# traceback.
try:
    RESOLVED = resolve_config(config, workflow.basedir)
    # Each study's cross-field limits with its design data (e.g. a design name that must exist).
    validate_studies(RESOLVED, workflow.basedir)
except SettingError as _e:
    sys.exit(f"gearrep: bad configuration: {_e}")
PUBLISHED_DIR = RESOLVED["published_dir"]
SETTINGS = {key: RESOLVED[key] for key in REGISTRY}
# The published data as committed (data/published/MANIFEST.csv: checksum, rows per seed of every
# file): a missing, emptied, cut, altered or unlisted file stops here, naming the file.
_published.verify_manifest(Path(workflow.basedir, PUBLISHED_DIR))
_published.load_errata(Path(workflow.basedir, "data", "errata.csv"))

_GRAPH = ModuleGraph(Path(workflow.basedir, "src"), workflow.basedir)


def lib(*modules):
    """Files of the gearrep modules a rule imports AND of everything they import in turn, declared
    as inputs so that a library change reruns exactly the jobs that use it."""
    return _GRAPH.closure(*modules)


def script_lib(path, *extra):
    """lib() of what a script or notebook (path relative to the workflow) imports."""
    return _GRAPH.source_closure(Path(workflow.basedir, path), *extra)


#: I/O helpers the job and check scripts import (declared as their input)
REPLICATION_IO = "workflow/scripts/replication_io.py"


def published_files(*patterns):
    """Published-data files matching any of ``patterns`` (globs in the published-data directory)."""
    d = Path(workflow.basedir, PUBLISHED_DIR)
    found = {p.name for pat in (patterns or ("*.csv",)) for p in d.glob(pat)} - {_published.MANIFEST_NAME}
    return sorted(str(Path(PUBLISHED_DIR, name)) for name in found)


def figure(path, replication):
    """A figure output flagged for `snakemake --report` under the replication's category."""
    return report(path, caption="../report/figure.rst", category=replication)
