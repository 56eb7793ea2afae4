# Shared helpers for the rules: the configuration resolved before any job, library modules as
# inputs, published-data files, report figures.
import json
import os
import sys
from pathlib import Path

# Tools the rules run (papermill, nbconvert: imported by the step runner) come from the interpreter
# that runs Snakemake, not from whatever PATH the user has: .venv/bin/snakemake works unactivated.
PYTHON = sys.executable
os.environ["PATH"] = os.pathsep.join([str(Path(PYTHON).parent), os.environ.get("PATH", "")])

sys.path.insert(0, str(Path(workflow.basedir, "workflow", "lib")))

from modgraph import ModuleGraph
from wfconfig import resolve_config, validate_studies
from wftimers import cancel_pending_timers

from gearrep import published as _published
from gearrep.replications import REGISTRY
from gearrep.replications import load as load_study
from gearrep.replications._face import table_paths

# Every setting of every study resolved and checked (unknown keys, ranges, NaN, cross-field limits)
# before any job runs; a bad value stops here, naming its key.
RESOLVED = resolve_config(config, workflow.basedir)
PUBLISHED_DIR = RESOLVED["published_dir"]
SETTINGS = {key: RESOLVED[key] for key in REGISTRY}
# The published data as committed (data/published/MANIFEST.csv: checksum, rows per seed of every
# file): a missing, emptied, cut, altered or unlisted file stops here, naming the file.
_published.verify_manifest(Path(workflow.basedir, PUBLISHED_DIR))
_published.load_errata(Path(workflow.basedir, "data", "errata.csv"))
# Each study's cross-field limits with its design data (e.g. a design name that must exist).
validate_studies(RESOLVED, workflow.basedir)

_GRAPH = ModuleGraph(Path(workflow.basedir, "src"), workflow.basedir)


def lib(*modules):
    """Files of the gearrep modules a rule imports AND of everything they import in turn, declared
    as inputs so that a library change reruns exactly the jobs that use it."""
    return _GRAPH.closure(*modules)


def script_lib(path, *extra):
    """lib() of what a script or notebook (path relative to the workflow) imports."""
    return _GRAPH.source_closure(Path(workflow.basedir, path), *extra)


#: I/O helpers the generic run and check scripts import (declared as their input)
REPLICATION_IO = "workflow/scripts/replication_io.py"
#: the runner of every study step (a job or the checks), with its warm process
STEP_RUNNER = "workflow/scripts/run_study_step.py"


def step_request(study, step, **fields):
    """The JSON request of one study step for STEP_RUNNER (paths relative to the working directory)."""
    return json.dumps({"study": study, "step": step, **fields}, sort_keys=True)


#: modules the warm process imports once for every figure script (matplotlib, the plot style)
FIGURE_MODULES = ["matplotlib", "matplotlib.pyplot", "gearrep.plotting"]
#: and for every notebook rendering (nbconvert's HTML exporter and ours, beside the scripts; the
#: notebook format's validators compiled once)
RENDER_MODULES = ["nbformat", "nbconvert", "notebook_html", "notebook_validators"]
#: the HTML exporter the rendering script imports (declared as its input)
NOTEBOOK_HTML = "workflow/scripts/notebook_html.py"
#: the script that executes a study's notebook, and what the warm process imports once for it
NOTEBOOK_EXECUTOR = "workflow/scripts/execute_notebook.py"
NOTEBOOK_MODULES = [
    "nbformat",
    "notebook_validators",  # the notebook format's validators, compiled once (beside the scripts)
    "papermill",
    # what the notebooks' forked kernels import (execute_notebook.py): the kernel itself, then the
    # notebooks' own imports
    "ipykernel.kernelapp",
    "matplotlib_inline.backend_inline",
    "IPython.display",
    "numpy",
    "pandas",
    "matplotlib.pyplot",
    "gearrep.plotting",
    "gearrep.published",
    "gearrep.settings",
    "gearrep.replications.catt",
]


def script_request(script, *, input, output, log, timing, params=None, wildcards=None, preload=()):
    """The JSON request of a workflow script run by STEP_RUNNER: the script reads the rule's named
    input, output, log and params as ``snakemake.<field>.<name>`` (see StepFiles there)."""
    return json.dumps(
        {
            "script": script,
            "input": input,
            "output": output,
            "log": {"log": log},
            "params": params or {},
            "wildcards": dict(wildcards or {}),
            "timing": timing,
            "preload": list(preload),
        },
        sort_keys=True,
    )


def notebook_request(study, *, input, settings):
    """The step-runner request that executes notebooks/<study>.ipynb (NOTEBOOK_EXECUTOR) with the
    rule's named ``input`` and the study's settings as ``snakemake.params.settings``."""
    return script_request(
        NOTEBOOK_EXECUTOR,
        input=input,
        output={"executed": f"results/notebooks/{study}.executed"},
        log=f"results/logs/{study}/notebook.log",
        timing=f"results/benchmarks/{study}/notebook.tsv",
        params={
            "study": study,
            "settings": settings,
            "source": f"notebooks/{study}.ipynb",
            "executed": f"results/notebooks/{study}.ipynb",
        },
        preload=NOTEBOOK_MODULES,
    )


def published_files(*patterns):
    """Published-data files matching any of ``patterns`` (globs in the published-data directory)."""
    d = Path(workflow.basedir, PUBLISHED_DIR)
    found = {p.name for pat in (patterns or ("*.csv",)) for p in d.glob(pat)} - {_published.MANIFEST_NAME}
    return sorted(str(Path(PUBLISHED_DIR, name)) for name in found)


def figure(path, replication):
    """A figure output flagged for `snakemake --report` under the replication's category."""
    return report(path, caption="../report/figure.rst", category=replication)
