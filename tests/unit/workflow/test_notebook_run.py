"""A study's notebook executed and rendered (workflow/scripts/notebook.py): the kernel gets the
job's ``snakemake`` object, talks over Unix sockets, a failing cell fails the job, and the page
hides the first cell and the machine's paths."""

from __future__ import annotations

import asyncio
import importlib.util
import json
import os
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

import pytest
from conftest import ROOT

nbformat = pytest.importorskip("nbformat")
papermill = pytest.importorskip("papermill")
pytest.importorskip("ipykernel")
sys.path.insert(0, str(ROOT / "workflow" / "scripts"))


def _module():
    spec = importlib.util.spec_from_file_location("notebook_script", ROOT / "workflow" / "scripts" / "notebook.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


NB = _module()


def _job(tmp_path, cells):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# design data")] + [nbformat.v4.new_code_cell(c) for c in cells]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    source = tmp_path / "study.ipynb"
    nbformat.write(nb, source)
    return SimpleNamespace(
        input=SimpleNamespace(notebook=str(source), template=str(ROOT / "workflow/report/notebook/collapsed.html.j2")),
        output=SimpleNamespace(
            notebook=str(tmp_path / "out" / "study.ipynb"), html=str(tmp_path / "out" / "study.html")
        ),
        params=SimpleNamespace(settings={"n": 3}),
        log=[str(tmp_path / "study.log")],
    )


def test_the_kernel_gets_the_jobs_snakemake_object_and_the_page_hides_the_first_cell(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    cells = [
        "print(snakemake.params.settings['n'] * 2, snakemake.input.notebook.endswith('study.ipynb'))",
        "import os\nprint(os.getcwd())",
        "from ipykernel.kernelapp import IPKernelApp\napp = IPKernelApp.instance()\nprint(app.transport)",
    ]
    smk = _job(tmp_path, cells)
    NB.execute(smk)
    NB.render(smk)
    out = json.loads(Path(smk.output.notebook).read_text())["cells"]
    texts = ["".join(o.get("text", "")) for c in out if c["cell_type"] == "code" for o in c.get("outputs", [])]
    assert texts == ["6 True\n", f"{tmp_path}\n", "ipc\n" if os.name == "posix" else "tcp\n"]
    page = Path(smk.output.html).read_text(encoding="utf-8")
    assert NB.PREAMBLE_TAG not in page and "pickle" not in page and str(tmp_path) not in page
    assert page.count('<details class="gearrep-code">') == len(cells)


def test_a_failing_cell_fails_the_job(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(papermill.PapermillExecutionError, match="ZeroDivisionError"):
        NB.execute(_job(tmp_path, ["x = 1", "1 / 0", "y = 2"]))


def test_the_kernel_sockets_live_in_a_directory_of_their_own():
    """No TCP ports: two notebooks started together could both be given one
    (https://github.com/nteract/papermill/issues/511). The directory goes with the kernel."""
    if os.name != "posix":
        pytest.skip("Unix sockets: POSIX only")
    before = set(Path(tempfile.gettempdir()).glob("gearrep-kernel-*"))
    km = NB.IpcKernelManager(kernel_name="python3")
    assert km.transport == "ipc" and Path(km.ip).parent.is_dir() and len(km.ip) < 80
    asyncio.run(km.cleanup_resources())
    assert not Path(km.ip).parent.exists()
    assert set(Path(tempfile.gettempdir()).glob("gearrep-kernel-*")) == before


def test_the_job_and_its_kernel_write_errors_to_the_job_log(tmp_path):
    """A notebook job's standard error, and that of the kernel it starts (a child process: here a
    stand-in), goes to the job's log, not to the run's terminal (ipykernel can print an error about
    a socket closed under it at shutdown)."""
    import subprocess

    log = tmp_path / "notebook.log"
    code = (
        f"import subprocess, sys; sys.path.insert(0, {str(ROOT / 'workflow' / 'scripts')!r}); "
        "import importlib.util as u; "
        f"s = u.spec_from_file_location('nb', {str(ROOT / 'workflow' / 'scripts' / 'notebook.py')!r}); "
        "m = u.module_from_spec(s); s.loader.exec_module(m); "
        f"m.log_stderr({str(log)!r}); print('job says', file=sys.stderr, flush=True); "
        "subprocess.run([sys.executable, '-c', 'import sys; sys.stderr.write(\"kernel says\\\\n\")'], check=True)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    assert log.read_text().splitlines() == ["job says", "kernel says"]
