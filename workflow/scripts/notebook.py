"""Execute a study's notebook and render it to HTML for readers (Snakemake script of the rules
``<study>_notebook``).

Execution: ``snakemake.input.notebook`` gets a first code cell, tagged ``gearrep-snakemake``, that
gives its kernel this job's ``snakemake`` object (the rule's named input, output, params, log, as
under Snakemake's ``notebook:`` directive) and moves the kernel to the working directory; papermill
then executes it with this interpreter's ``python3`` kernel, writing ``snakemake.output.notebook``.
A failing cell fails the job (papermill leaves the traceback in the executed notebook). The
``script:`` directive runs papermill's Python API with the interpreter running Snakemake, where
the ``notebook:`` directive would look for a ``papermill`` command on PATH.

The kernel and papermill talk over Unix sockets (ZeroMQ's ``ipc`` transport) in a private
directory, not over TCP ports: jupyter_client picks free ports by binding and closing them and the
kernel binds them later, so two notebooks starting together can be given the same port
(https://github.com/nteract/papermill/issues/511); a socket path of its own cannot be taken.

Rendering, ``snakemake.output.html``:

* the tagged first cell (the machine's working directory, the job's files) is removed;
* every code cell is folded under a "code" toggle (template ``snakemake.input.template``), so
  prose, tables and figures come first;
* the page is JupyterLab's (``notebook_html.LabExporter``: nbconvert's HTML exporter without its
  BeautifulSoup round trip, the same page once parsed);
* paths of the machine that ran the notebook (working directory, interpreter prefix, home) are
  replaced in every output by relative or neutral names (the report job then refuses any rendered
  page that still shows an absolute path: ``gearrep.report.absolute_paths``; the check is not made
  here so that a change of gearrep.report reruns the report alone).
"""

import os
import pickle
import shutil
import sys
import tempfile
from pathlib import Path

import nbformat
import papermill
from jupyter_client.manager import AsyncKernelManager
from nbconvert.preprocessors import TagRemovePreprocessor
from notebook_html import LabExporter
from traitlets import default

PREAMBLE_TAG = "gearrep-snakemake"


class IpcKernelManager(AsyncKernelManager):
    """jupyter_client's kernel manager with the kernel's channels on Unix sockets in a directory
    of its own (removed with the kernel)."""

    _socket_dir: str | None = None

    @default("transport")
    def _default_transport(self) -> str:
        return "ipc" if os.name == "posix" else "tcp"

    @default("ip")
    def _default_ip(self) -> str:
        if self.transport != "ipc":
            return super()._ip_default()
        # a short path (a Unix socket's path is limited to about 107 bytes)
        self._socket_dir = tempfile.mkdtemp(prefix="gearrep-kernel-")
        return os.path.join(self._socket_dir, "k")

    async def _async_cleanup_resources(self, restart: bool = False) -> None:
        await super()._async_cleanup_resources(restart=restart)
        if self._socket_dir and not restart:
            shutil.rmtree(self._socket_dir, ignore_errors=True)
            self._socket_dir = None

    cleanup_resources = _async_cleanup_resources  # as AsyncKernelManager's (the base class's function)


def preamble_cell(smk):
    """The first cell: this job's ``snakemake`` object and the workflow's working directory."""
    source = "\n".join(
        [
            "import os as _os, pickle as _pickle",
            f"_os.chdir({os.getcwd()!r})",
            f"snakemake = _pickle.loads({pickle.dumps(smk)!r})",
        ]
    )
    return nbformat.v4.new_code_cell(source, metadata={"tags": [PREAMBLE_TAG]})


def execute(smk) -> None:
    """Execute ``smk.input.notebook`` into ``smk.output.notebook`` with the preamble cell."""
    nb = nbformat.read(smk.input.notebook, as_version=4)
    nb.cells.insert(0, preamble_cell(smk))
    Path(smk.output.notebook).parent.mkdir(parents=True, exist_ok=True)
    papermill.execute_notebook(
        nb,
        smk.output.notebook,
        cwd=os.getcwd(),
        log_output=False,
        progress_bar=False,
        kernel_manager_class=IpcKernelManager,
    )


def _replacements() -> list[tuple[str, str]]:
    """Machine prefixes, longest first, and what a reader sees instead."""
    pairs = {
        str(Path.cwd()) + os.sep: "",
        str(Path.cwd()): ".",
        sys.prefix: "{python}",
        sys.base_prefix: "{python}",
        str(Path.home()): "~",
    }
    return sorted(((k, v) for k, v in pairs.items() if len(k) > 1), key=lambda kv: -len(kv[0]))


def _clean(text: str, pairs) -> str:
    for old, new in pairs:
        text = text.replace(old, new)
    return text


def clean_notebook(nb, pairs) -> None:
    """Replace machine paths in every output (streams, tracebacks, rich data) of ``nb``."""
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            if "text" in out:
                out["text"] = _clean(out["text"], pairs)
            if "traceback" in out:
                out["traceback"] = [_clean(t, pairs) for t in out["traceback"]]
            if "evalue" in out:
                out["evalue"] = _clean(out["evalue"], pairs)
            for mime, data in out.get("data", {}).items():
                if mime.startswith("text/") and isinstance(data, str):
                    out["data"][mime] = _clean(data, pairs)


def render(smk) -> None:
    """``smk.output.notebook`` as one HTML page, ``smk.output.html``."""
    nb = nbformat.read(smk.output.notebook, as_version=4)
    clean_notebook(nb, _replacements())
    template = Path(smk.input.template)
    exporter = LabExporter(template_name="lab", extra_template_paths=[str(template.parent.resolve())])
    exporter.template_file = template.name
    exporter.register_preprocessor(TagRemovePreprocessor(remove_cell_tags={PREAMBLE_TAG}, enabled=True), enabled=True)
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": Path(smk.output.html).stem}})
    Path(smk.output.html).write_text(body, encoding="utf-8")
    with open(smk.log[0], "a", encoding="utf-8") as log:
        log.write(f"executed and rendered {smk.input.notebook}: {len(nb.cells)} cells\n")


def log_stderr(path) -> None:
    """Send this process's standard error, and so its kernel's (a child inherits the descriptor),
    to the job's log: a kernel's messages, such as ipykernel's occasional error about a socket closed
    under it at shutdown, belong to the job's log, not to the run's terminal."""
    with open(path, "w", encoding="utf-8") as log:
        os.dup2(log.fileno(), sys.stderr.fileno())


if __name__ == "__main__":  # run by Snakemake (the tests import the module)
    smk = snakemake  # noqa: F821  (provided by Snakemake)
    log_stderr(smk.log[0])
    execute(smk)
    render(smk)
