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

The kernel is a fork of this process (:class:`ForkedKernelManager`) where the kernelspec would
start this interpreter's ``ipykernel_launcher``: the fork runs the same kernel application with the
same arguments, environment and working directory, but finds numpy, pandas, matplotlib, IPython
and gearrep already imported (the warm process imports them once, ``NOTEBOOK_MODULES``), where a
fresh kernel process spent 1-2 s of CPU importing them for every notebook. Any other kernel command
(another interpreter or kernel) is started as a process, as jupyter_client does.

The kernel and papermill talk over Unix sockets (ZeroMQ's ``ipc`` transport) in a private
directory of the manager, not over TCP ports of 127.0.0.1: jupyter_client picks five free ports
(binds and closes them) and the kernel binds them later, so a second notebook starting at the same
time, or any connection's local port, can take one in between; the kernel then dies with "Address
already in use" (papermill issue 511, open). It happened in a cold ``snakemake --cores 2`` run
(the thesis and CATT notebooks started together); a socket path of its own cannot be taken.
"""

import asyncio
import gc
import json
import os
import shutil
import signal
import sys
import tempfile
from pathlib import Path

import nbformat
import papermill
from jupyter_client.manager import AsyncKernelManager
from traitlets import default

PREAMBLE_TAG = "gearrep-step-properties"
SCRIPTS = Path(__file__).resolve().parent


def preamble_cell(smk):
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


class _ForkedKernel:
    """The kernel fork, seen as the ``subprocess.Popen`` that jupyter_client's local provisioner
    holds (poll, wait, send_signal, terminate, kill, pid, returncode; no pipes). ``wait`` blocks
    whatever its timeout: the provisioner calls it only after ``poll`` has seen the end."""

    stdin = stdout = stderr = None

    def __init__(self, pid: int):
        self.pid = pid
        self.returncode = None

    def _reap(self, flags: int):
        if self.returncode is None:
            try:
                pid, status = os.waitpid(self.pid, flags)
            except ChildProcessError:
                # reaped already (SIGCHLD ignored): ended, status unknown; Popen then says 0 too
                self.returncode = 0
                return self.returncode
            if pid:
                self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode

    def poll(self):
        return self._reap(os.WNOHANG)

    def wait(self, timeout=None):
        return self._reap(0)

    def send_signal(self, signum):
        if self.poll() is None:
            os.kill(self.pid, signum)

    def terminate(self):
        self.send_signal(signal.SIGTERM)

    def kill(self):
        self.send_signal(signal.SIGKILL)


def _is_this_ipykernel(cmd) -> bool:
    """Whether the kernel command is this interpreter's ``-m ipykernel_launcher -f <file>``, with
    only ``--Name.trait=value`` options besides (papermill adds one: no history file)."""
    return (
        len(cmd) >= 5
        and os.path.realpath(cmd[0]) == os.path.realpath(sys.executable)
        and cmd[1:4] == ["-m", "ipykernel_launcher", "-f"]
        and all(a.startswith("--") and "=" in a for a in cmd[5:])
    )


def _run_kernel(argv, env, cwd, parent_pid) -> None:
    """In the fork: what ``python -m ipykernel_launcher ARGV`` does in a fresh process started by
    jupyter_client (its own session, the given environment and directory, stdin from /dev/null,
    the launcher's sys.path without this script's directory); never returns."""
    code = 1
    try:
        os.setsid()
        # a fresh event loop: the inherited one is the parent's (its selector's descriptors are
        # shared with the parent, which runs it)
        asyncio.set_event_loop(asyncio.new_event_loop())
        if env is not None:
            os.environ.clear()
            os.environ.update(env)
        os.environ["JPY_PARENT_PID"] = str(parent_pid)  # as jupyter_client's launcher sets it
        # ... and given as an option too: the kernel application read the variable when the warm
        # process imported it (the kernel exits when its parent dies, and prints no console hint)
        argv = [*argv, f"--IPKernelApp.parent_handle={parent_pid}"]
        if cwd:
            os.chdir(cwd)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.close(null)
        sys.path[:] = [p for p in sys.path if p not in ("", str(SCRIPTS))]
        sys.argv = ["ipykernel_launcher", *argv]
        pd = sys.modules.get("pandas")
        if pd is not None:
            # pandas picks this default when imported: 0 (fit the terminal) outside IPython, as in
            # the warm process, 20 inside a kernel, as a fresh kernel imports it
            pd.set_option("display.max_columns", 20)
        from ipykernel.kernelapp import IPKernelApp

        IPKernelApp.launch_instance(argv=argv)
        code = 0
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    except BaseException:  # noqa: B036  (report anything, then leave without the parent's cleanup)
        import traceback

        traceback.print_exc()
    finally:
        for stream in (sys.stdout, sys.stderr, sys.__stdout__, sys.__stderr__):
            try:
                stream.flush()
            except Exception:  # noqa: BLE001,S110  (a closed stream: nothing to flush)
                pass
        os._exit(code)


class ForkedKernelManager(AsyncKernelManager):
    """jupyter_client's kernel manager, with this interpreter's ipykernel started as a fork and
    its channels on Unix sockets in a directory of its own (where the platform has them)."""

    _socket_dir: str | None = None

    @default("transport")
    def _default_transport(self) -> str:
        return "ipc" if self._forks() else "tcp"

    def _forks(self) -> bool:
        """Whether the kernel will be this interpreter's ipykernel as a fork (on Unix sockets);
        another kernel keeps jupyter_client's TCP (not every kernel speaks ``ipc``)."""
        try:
            argv = list(self.kernel_spec.argv)
        except Exception:  # noqa: BLE001  (no kernelspec: jupyter_client reports it at launch)
            return False
        if argv and argv[0] in {"python", f"python{sys.version_info[0]}", "python{}.{}".format(*sys.version_info[:2])}:
            argv[0] = sys.executable  # as jupyter_client's format_kernel_cmd does
        return hasattr(os, "fork") and _is_this_ipykernel(argv)

    @default("ip")
    def _default_ip(self) -> str:
        if self.transport != "ipc":
            return super()._ip_default()
        # a short path (a Unix socket's path is limited to about 107 bytes): the runtime
        # directory's kernel-<uuid>-ipc-N can pass that under a long home directory
        self._socket_dir = tempfile.mkdtemp(prefix="gearrep-kernel-")
        return os.path.join(self._socket_dir, "k")

    async def _async_cleanup_resources(self, restart: bool = False) -> None:
        await super()._async_cleanup_resources(restart=restart)
        if self._socket_dir and not restart:
            shutil.rmtree(self._socket_dir, ignore_errors=True)
            self._socket_dir = None

    cleanup_resources = _async_cleanup_resources  # as AsyncKernelManager's (the base class's function)

    async def _async_launch_kernel(self, kernel_cmd, **kw):
        if not (hasattr(os, "fork") and _is_this_ipykernel(kernel_cmd)):
            return await super()._async_launch_kernel(kernel_cmd, **kw)
        sys.stdout.flush()
        sys.stderr.flush()
        parent_pid = os.getpid()
        gc.freeze()  # the kernel's full collections skip what it inherits (as the warm process's children)
        pid = os.fork()
        if pid == 0:
            _run_kernel(kernel_cmd[3:], kw.get("env"), kw.get("cwd"), parent_pid)
        gc.unfreeze()  # the freeze is the kernel's; this process collects as before
        prov = self.provisioner
        prov.process = _ForkedKernel(pid)
        prov.pid = pid
        prov.pgid = pid  # the fork is its session's leader (os.setsid), as Popen's start_new_session
        prov.cwd = kw.get("cwd") or os.getcwd()
        self._reconcile_connection_info(prov.connection_info)


def main(smk) -> None:
    """Execute ``smk.params.source`` into ``smk.params.executed`` with the preamble cell."""
    nb = nbformat.read(smk.params.source, as_version=4)
    nb.cells.insert(0, preamble_cell(smk))
    Path(smk.params.executed).parent.mkdir(parents=True, exist_ok=True)
    papermill.execute_notebook(
        nb,
        smk.params.executed,
        cwd=os.getcwd(),
        log_output=False,
        progress_bar=False,
        request_save_on_cell_execute=False,
        kernel_manager_class=ForkedKernelManager,
    )


if __name__ == "__main__":  # run by the step runner (the tests import the module)
    main(snakemake)  # noqa: F821  (provided by the step runner)
