"""Execute a study's notebook (workflow script of the rules ``<study>_notebook``, run by the step
runner ``run_study_step.py`` like the figure scripts).

The notebook ``snakemake.params.source`` gets a first code cell, tagged ``gearrep-step-properties``,
that gives its kernel the rule's named input, output, params, log and wildcards as
``snakemake.<field>.<name>`` (the step runner's ``StepFiles``, as under Snakemake's ``notebook:``
directive) and moves the kernel to this working directory. papermill then executes it in this
process (its Jupyter kernel is the notebook's ``python3`` kernelspec: this interpreter), writing the
executed notebook to ``snakemake.params.executed``. A failing cell fails the step, and papermill
leaves the traceback in the executed notebook; the rendering (``render_notebook.py``) removes the
tagged cell.

Why not the ``notebook:`` directive: Snakemake runs such a job in a fresh process that parses the
whole workflow again, asks ``papermill --version`` and starts the papermill command, about 3 s
before the kernel starts; here that is the warm process's fork.
"""

import json
import os
from pathlib import Path

import nbformat
import papermill

smk = snakemake  # noqa: F821  (provided by the step runner)

PREAMBLE_TAG = "gearrep-step-properties"
SCRIPTS = Path(__file__).resolve().parent


def preamble_cell():
    """The first cell: ``snakemake`` with the rule's named files and params, and the working
    directory of the workflow."""
    fields = {k: dict(getattr(smk, k).items()) for k in ("input", "output", "params", "log", "wildcards")}
    source = "\n".join(
        [
            "import json as _json, os as _os, sys as _sys",
            "from types import SimpleNamespace as _NS",
            f"_sys.path.insert(0, {str(SCRIPTS)!r})",
            "from run_study_step import StepFiles as _Files",
            f"_os.chdir({os.getcwd()!r})",
            f"snakemake = _NS(**{{_k: _Files(_v) for _k, _v in _json.loads({json.dumps(fields)!r}).items()}})",
        ]
    )
    return nbformat.v4.new_code_cell(source, metadata={"tags": [PREAMBLE_TAG]})


nb = nbformat.read(smk.params.source, as_version=4)
nb.cells.insert(0, preamble_cell())
Path(smk.params.executed).parent.mkdir(parents=True, exist_ok=True)
papermill.execute_notebook(
    nb,
    smk.params.executed,
    cwd=os.getcwd(),
    log_output=False,
    progress_bar=False,
    request_save_on_cell_execute=False,
)
