"""The notebooks' kernel started as a fork of the step process (workflow/scripts/execute_notebook.py):
the same outputs as the fresh kernel process jupyter_client starts, and a failing cell still fails."""

from __future__ import annotations

import importlib.util
import json
import re
import sys
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
papermill = pytest.importorskip("papermill")
pytest.importorskip("ipykernel")

ROOT = Path(__file__).resolve().parents[2]


def _executor():
    spec = importlib.util.spec_from_file_location(
        "execute_notebook", ROOT / "workflow" / "scripts" / "execute_notebook.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


EX = _executor()

#: cells whose outputs depend on state a fork inherits: pandas' import-time display default, the
#: matplotlib backend and figure, the environment, the working directory, the argument list
CELLS = [
    "import sys\nprint('_pytest' in sys.modules)",  # the fork's mark: the test process's modules
    "import pandas as pd\npd.DataFrame({f'column_{i}': [i, i + 0.5] for i in range(30)})",
    "%matplotlib inline\nimport matplotlib.pyplot as plt\nplt.plot([0, 1, 2], [1, 0, 1])\nplt.show()",
    "import os\nprint(os.getcwd(), os.environ.get('JPY_PARENT_PID') is not None)",
    "import numpy as np\nnp.arange(5) / 3",
]


def _run(tmp_path, cells, name, **kw):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in cells]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    out = tmp_path / f"{name}.ipynb"
    papermill.execute_notebook(
        nb, str(out), cwd=str(tmp_path), log_output=False, progress_bar=False, kernel_name="python3", **kw
    )
    return json.loads(out.read_text())


def _outputs(nb):
    cells = []
    for cell in nb["cells"]:
        outs = []
        for o in cell.get("outputs", []):
            o = {k: v for k, v in o.items() if k not in ("execution_count", "metadata")}
            outs.append(re.sub(r" at 0x[0-9a-f]+", " at 0x", json.dumps(o, sort_keys=True)))
        cells.append(outs)
    return cells


def test_the_forked_kernel_gives_the_fresh_kernels_outputs(tmp_path):
    assert EX._is_this_ipykernel([sys.executable, "-m", "ipykernel_launcher", "-f", "k.json"])
    import pandas  # noqa: F401  (imported before the fork, as in the warm process)

    forked = _outputs(_run(tmp_path, CELLS, "forked", kernel_manager_class=EX.ForkedKernelManager))
    fresh = _outputs(_run(tmp_path, CELLS, "fresh"))
    assert "True" in forked[0][0] and "False" in fresh[0][0]  # forked, resp. a fresh process
    assert forked[1:] == fresh[1:]
    assert any("image/png" in o for o in forked[2])


def test_a_failing_cell_fails_the_forked_kernels_run(tmp_path):
    with pytest.raises(papermill.PapermillExecutionError, match="ZeroDivisionError"):
        _run(tmp_path, ["x = 1", "1 / 0", "y = 2"], "failing", kernel_manager_class=EX.ForkedKernelManager)


def test_other_kernel_commands_are_started_as_processes():
    assert not EX._is_this_ipykernel(["/usr/bin/other-python", "-m", "ipykernel_launcher", "-f", "k.json"])
    assert not EX._is_this_ipykernel([sys.executable, "-m", "other_kernel", "-f", "k.json"])
    assert not EX._is_this_ipykernel([sys.executable, "-m", "ipykernel_launcher", "-f", "k.json", "positional"])
    assert EX._is_this_ipykernel(
        [sys.executable, "-m", "ipykernel_launcher", "-f", "k.json", "--HistoryManager.hist_file=:memory:"]
    )


def test_the_fork_handle_reports_an_exit_status_and_an_already_reaped_child():
    import os

    pid = os.fork()
    if pid == 0:
        os._exit(3)
    k = EX._ForkedKernel(pid)
    assert k.wait() == 3 and k.poll() == 3
    k.kill()  # ended: no signal is sent
    pid = os.fork()
    if pid == 0:
        os._exit(0)
    os.waitpid(pid, 0)  # reaped by someone else
    assert EX._ForkedKernel(pid).poll() == 0


def test_the_kernel_talks_over_unix_sockets_in_a_directory_of_its_own(tmp_path):
    """No TCP ports: two notebooks started together could both be given one (papermill issue 511;
    it happened in a cold two-core run). The sockets' directory is removed with the kernel."""
    import asyncio
    import os
    import tempfile

    if os.name != "posix":
        pytest.skip("Unix sockets: POSIX only")
    before = set(Path(tempfile.gettempdir()).glob("gearrep-kernel-*"))
    km = EX.ForkedKernelManager(kernel_name="python3")
    assert km.transport == "ipc" and not km.cache_ports
    assert Path(km.ip).parent.is_dir() and len(km.ip) < 80
    asyncio.run(km.cleanup_resources())
    assert not Path(km.ip).parent.exists()

    other = EX.ForkedKernelManager(kernel_name="python3")
    other.kernel_spec.argv = ["/usr/bin/other-kernel", "-f", "{connection_file}"]
    assert other.transport == "tcp"  # not every kernel speaks ipc: another one keeps TCP

    cell = "from ipykernel.kernelapp import IPKernelApp\napp = IPKernelApp.instance()\nprint(app.transport, app.ip)"
    out = _run(tmp_path, [cell], "ipc", kernel_manager_class=EX.ForkedKernelManager)
    transport, ip = "".join(out["cells"][0]["outputs"][0]["text"]).split()
    assert transport == "ipc" and Path(ip).name == "k"
    assert not Path(ip).parent.exists()
    assert set(Path(tempfile.gettempdir()).glob("gearrep-kernel-*")) == before


def test_the_forked_kernel_does_not_walk_the_objects_it_inherits_when_it_collects(tmp_path):
    """The step process freezes its objects (``gc.freeze``) before forking the kernel: the kernel's
    full collections walk only what its cells create; the step process collects as before."""
    import gc

    import pandas  # noqa: F401  (imported before the fork, as in the warm process)

    out = _run(
        tmp_path, ["import gc\nprint(gc.get_freeze_count())"], "frozen", kernel_manager_class=EX.ForkedKernelManager
    )
    assert int("".join(out["cells"][0]["outputs"][0]["text"])) > 10_000
    assert gc.get_freeze_count() == 0
