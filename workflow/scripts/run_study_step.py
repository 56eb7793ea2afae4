"""One step of the workflow, run by its rule as ``python -S run_study_step.py REQUEST`` with REQUEST the
JSON the rule builds: a study's job (its tables) or its checks (workflow/rules/replications.smk:
study, step, settings, input and output paths, log), or a workflow script (a study's figures, a
notebook's rendering: ``script`` with the rule's named ``input``, ``output``, ``log``, ``params``
and ``wildcards``, which the script reads as ``snakemake.input.<name>`` and so on, as under Snakemake's
``script:`` directive, and ``preload``, modules the warm process imports once for every such step).

Why not a plain script: every step of the 70 would otherwise be a fresh Python process that pays
0.7-1 s of CPU for the interpreter, numpy, pandas and gearrep before computing anything (often for
half a second of computation; README, Performance). So the first step of a run starts a *warm
process* (``--serve``) that imports them once and then forks one child per step: the child runs
the step exactly as a fresh process would (same code, same inputs; the fork shares nothing
mutable with other steps) with this client's stdin, stdout and stderr, and its exit status becomes
this client's. The warm process

* listens on a Unix socket under ``.snakemake/`` of the working directory, readable by its owner
  only, named after the interpreter, ``PYTHONPATH`` and this file, so another environment or
  workflow copy never shares it; clients that find no warm process take turns on a lock file
  beside it, so that steps starting together start one;
* refuses work and exits as soon as a source file it has imported changed (the client then starts
  a fresh one), and exits after ``IDLE_SECONDS`` without a request;
* is optional: with ``GEARREP_WARM_PROCESS=0``, or when it cannot be reached (e.g. a cluster node
  that does not share the socket), the client runs the step itself, as a plain script would.

The numerics are in ``gearrep.replications.<study>``; the reading and writing in replication_io.
"""

from __future__ import annotations

# the client (one per step: 89 in a full run) imports only what it needs to hand its step to the
# warm process: everything else is imported where it is used. json, pathlib, subprocess and re
# would cost it about 28 ms of CPU each time, hashlib 6 ms; and it speaks to the warm process
# through ``_socket``, the socket module's C core, because ``socket`` itself costs 19 ms (it builds
# its enums from the C constants and imports selectors and enum). The rules start it with
# ``python -S`` (no site-packages: 10 ms less); a client that runs its step itself turns site on.
import _socket
import os
import sys

IDLE_SECONDS = 30.0
_ACCEPTED = b"A"
_INT_SIZE = 4  # a C int, as SCM_RIGHTS carries file descriptors (socket.send_fds's array("i"))
#: what the library imports inside functions (for a single process, scipy's 0.3-0.7 s are only paid
#: where used) but a full run's steps need again and again: nine of the jobs imported scipy, each in
#: its own child (about 5 s of CPU in a cold run). The warm process imports them once, after forking
#: its first child when no other step is waiting (the steps that started it do not wait for them),
#: so that later children inherit them.
BACKGROUND_IMPORTS = ("scipy.optimize", "scipy.interpolate", "scipy.special")


# -- the step itself ---------------------------------------------------------------------------
class StepFiles(list):
    """A rule's named files (or params) for a script: the values in order, a named list flattened,
    each name also an attribute and a key (``items()``) — what the scripts use of Snakemake's
    ``Namedlist``."""

    def __init__(self, named: dict):
        super().__init__(x for v in named.values() for x in (v if isinstance(v, list) else [v]))
        self._named = dict(named)
        for name, value in named.items():
            setattr(self, name, value)

    def __getitem__(self, i):
        return self._named[i] if isinstance(i, str) else super().__getitem__(i)

    def items(self):
        return self._named.items()

    def keys(self):
        return self._named.keys()


def run_script(req: dict) -> None:
    """Run a workflow script with a ``snakemake`` object of the rule's named input, output, log and
    params (raises on failure; the traceback goes to the first log)."""
    import runpy
    from types import SimpleNamespace

    import replication_io

    io = {k: StepFiles(req.get(k, {})) for k in ("input", "output", "log", "params", "wildcards")}
    with replication_io.logged(io["log"][0]):
        seconds, _ = replication_io.timed(
            runpy.run_path, req["script"], {"snakemake": SimpleNamespace(**io)}, "__main__"
        )
        replication_io.write_timing(req["timing"], seconds)


def run_step(req: dict) -> None:
    """Run one job or the checks of a study, or a workflow script, from its request (raises on
    failure; the traceback goes to the step's log)."""
    from pathlib import Path

    import replication_io

    if "script" in req:
        run_script(req)
        return

    from gearrep import published
    from gearrep.replications import load

    with replication_io.logged(req["log"]):
        study = load(req["study"])
        data = req["published"]  # exactly the published files the rule declares as inputs
        pub = published.load(Path(data[0]).parent, data)
        if req["step"] == "checks":
            tables = replication_io.read_tables(req["tables"])
            seconds, out = replication_io.timed(study.checks, tables, pub)
            missing = sorted(set(study.CHECK_OUTPUTS) - set(out))
            if missing:
                raise RuntimeError(f"{req['study']}.checks returned no {missing}")
            for name in study.CHECK_OUTPUTS:
                if name == "checks":
                    replication_io.write_checks(out[name], req["outputs"][name], req["log"])
                else:
                    replication_io.write_table(out[name], req["outputs"][name])
        else:
            job = study.JOBS[req["step"]]
            design = study.params_from_published(pub)
            seconds, tables = replication_io.timed(job.compute, dict(req["settings"]), design)
            label = f"{req['study']}.{req['step']}"
            replication_io.write_tables(tables, list(req["outputs"].values()), req["log"], label, seconds)
        replication_io.write_timing(req["timing"], seconds)


def _run_here(req: dict) -> int:
    try:
        run_step(req)
    except BaseException:  # noqa: B036  (the traceback is in the log and on stderr; exit status 1)
        import traceback

        traceback.print_exc()
        return 1
    return 0


# -- the warm process ----------------------------------------------------------------------------
def _fnv1a64(data: bytes) -> int:
    """64-bit FNV-1a hash (a name, not a secret: no import for the client)."""
    h = 0xCBF29CE484222325
    for byte in data:
        h = ((h ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def socket_path() -> str:
    """The socket of this environment's warm process (relative to the working directory)."""
    key = "\0".join([sys.executable, os.environ.get("PYTHONPATH", ""), os.path.realpath(__file__)])
    return os.path.join(".snakemake", f"gearrep-warm-{_fnv1a64(os.fsencode(key)):016x}.sock")


def _imported_sources() -> dict[str, int]:
    """mtime_ns of every imported source file of gearrep and of the scripts beside this one."""
    here = os.path.dirname(os.path.realpath(__file__))
    out = {}
    for m in list(sys.modules.values()):
        f = getattr(m, "__file__", None)
        if f and (m.__name__.split(".")[0] == "gearrep" or os.path.dirname(os.path.realpath(f)) == here):
            try:
                out[f] = os.stat(f).st_mtime_ns
            except OSError:
                out[f] = -1
    return out


def _unchanged(sources: dict[str, int]) -> bool:
    for f, t in sources.items():
        try:
            if os.stat(f).st_mtime_ns != t:
                return False
        except OSError:
            return False
    return True


def serve(path) -> None:
    """The warm process (socket at ``path``, a pathlib.Path): import once, then fork one child per
    request until idle or stale."""
    import gc
    import json
    import select
    import signal
    import socket

    import replication_io  # noqa: F401  (imported once for every child)

    from gearrep import published  # noqa: F401
    from gearrep.replications import REGISTRY, load

    for key in REGISTRY:
        load(key)
    sources_self = os.stat(__file__).st_mtime_ns
    me = os.path.realpath(__file__)
    sources = _imported_sources() | {me: sources_self}
    tmp = path.with_name(f"{path.name}.{os.getpid()}")
    srv = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    srv.bind(str(tmp))
    os.chmod(tmp, 0o600)
    srv.listen(64)
    os.replace(tmp, path)  # atomically over a stale socket or a racing warm process's
    signal.signal(signal.SIGCHLD, signal.SIG_IGN)  # children are reaped by the kernel
    srv.settimeout(IDLE_SECONDS)
    background = BACKGROUND_IMPORTS
    try:
        while True:
            try:
                conn, _ = srv.accept()
            except TimeoutError:
                break
            if not _unchanged(sources):
                conn.close()  # not accepted: the client runs the step itself and replaces us
                break
            fds = []
            try:
                conn.settimeout(5.0)
                msg, fds, _, _ = socket.recv_fds(conn, 1 << 20, 3)
                conn.settimeout(None)
                cwd, _, text = msg.partition(b"\0")  # the client's working directory, then its request
                req = dict(json.loads(text), cwd=os.fsdecode(cwd))
                if _preload(req.get("preload", ())):
                    sources = _imported_sources() | {me: sources_self}
            except (OSError, ValueError, TypeError, ImportError):  # TypeError: a request not a JSON object
                for fd in fds:  # the client's stdio: held open here, its reader would wait for us
                    os.close(fd)
                conn.close()  # not accepted: the client runs the step itself
                continue
            # every object so far out of the collector's reach (the permanent generation): a
            # child's full collections then walk only what the step created, not the warm process's
            # ~170 000 inherited objects (each such walk cost a figure or rendering step ~0.2 s of
            # CPU, most of it copying the pages it touched: 13 in a cold run)
            gc.freeze()
            if os.fork() == 0:
                srv.close()
                os._exit(_child(conn, req, fds))
            gc.unfreeze()  # the freeze is the child's; this process collects as before
            for fd in fds:
                os.close(fd)
            conn.close()
            # the background imports once no other client is waiting (a run's first steps start
            # together: the second would otherwise wait for them, 0.5-0.7 s)
            if background and not select.select([srv], [], [], 0)[0]:
                try:
                    _preload(background)
                except Exception:  # noqa: BLE001,S110  (a step that needs it imports it and reports its own error)
                    pass
                background = ()
    finally:
        srv.close()
        try:
            if _is_ours(path):
                os.unlink(path)
        except OSError:
            pass


def _preload(modules) -> bool:
    """Import ``modules`` into the warm process (once: later children inherit them); whether any
    was new."""
    import importlib

    new = [m for m in modules if m not in sys.modules]
    for m in new:
        importlib.import_module(m)
    return bool(new)


def _is_ours(path) -> bool:
    """Whether the socket file at ``path`` is still this process's (not a newer warm process's)."""
    import socket

    try:
        probe = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        probe.settimeout(0.2)
        probe.connect(str(path))
        probe.close()
        return False  # someone answers: a newer process owns it
    except OSError:
        return True


def _child(conn, req: dict, fds) -> int:
    """A forked child: take the client's stdio, run the step, report the status. The child waits
    for its own children as a fresh process does (the warm process ignores SIGCHLD so that the
    kernel reaps its forks; inherited, that would hide a step's subprocesses' exit status and CPU
    time, e.g. a notebook's kernel)."""
    import signal

    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
    try:
        for fd, target in zip(fds, (0, 1, 2)):
            os.dup2(fd, target)
            os.close(fd)
        sys.stdout = os.fdopen(1, "w", buffering=1, closefd=False)
        sys.stderr = os.fdopen(2, "w", buffering=1, closefd=False)
        os.chdir(req["cwd"])
        conn.sendall(_ACCEPTED)
        rc = _run_here(req)
        sys.stdout.flush()
        sys.stderr.flush()
        conn.sendall(rc.to_bytes(4, "big", signed=True))
        return rc
    except BaseException:  # noqa: B036
        return 1


# -- the client ----------------------------------------------------------------------------------
def _connect(path: str):
    s = _socket.socket(_socket.AF_UNIX, _socket.SOCK_STREAM)
    try:
        s.connect(path)
        return s
    except OSError:
        s.close()
        return None


def _start_warm_process(path: str):
    """Start the warm process and connect to it, or connect to the one another client started
    meanwhile: the clients of steps that start together (a run's first two) take turns on a lock
    file beside the socket, so a run has one warm process (two of them had each imported everything,
    1.6 s of CPU, and served the run's first steps between them)."""
    import fcntl
    import subprocess
    import time

    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(os.path.splitext(path)[0] + ".lock", "ab") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file is closed
        s = _connect(path)
        if s is not None:
            return s
        log = open(os.path.splitext(path)[0] + ".log", "ab")  # noqa: SIM115  (handed to the child process)
        subprocess.Popen(
            [sys.executable, __file__, "--serve", path],
            stdin=subprocess.DEVNULL,
            stdout=log,
            stderr=log,
            start_new_session=True,
            close_fds=True,
        )
        log.close()
        deadline = time.monotonic() + 20.0
        while time.monotonic() < deadline:
            s = _connect(path)
            if s is not None:
                return s
            time.sleep(0.02)
    return None


def _via_warm_process(request: str) -> int | None:
    """The step's exit status from the warm process, or None when it did not take the step
    (``request``: the step's JSON, handed on unparsed with this working directory)."""
    path = socket_path()
    s = _connect(path) or _start_warm_process(path)
    if s is None:
        return None
    try:
        try:
            # the working directory and the request, with the client's stdin, stdout and stderr
            # (what socket.send_fds sends: the descriptors as C ints in one SCM_RIGHTS message)
            fds = b"".join(fd.to_bytes(_INT_SIZE, sys.byteorder, signed=True) for fd in (0, 1, 2))
            cwd = os.fsencode(os.getcwd())
            s.sendmsg([cwd + b"\0" + request.encode()], [(_socket.SOL_SOCKET, _socket.SCM_RIGHTS, fds)])
            if s.recv(1) != _ACCEPTED:
                return None  # refused (stale code) before starting: run here
        except OSError:
            return None
        status = b""
        while len(status) < 4:
            chunk = s.recv(4 - len(status))
            if not chunk:
                print("gearrep warm process: the step's child ended without a status", file=sys.stderr)
                return 1
            status += chunk
        return int.from_bytes(status, "big", signed=True)
    finally:
        s.close()


def main(argv: list[str]) -> int:
    if argv[:1] == ["--serve"]:
        from pathlib import Path

        serve(Path(argv[1]))
        return 0
    if os.environ.get("GEARREP_WARM_PROCESS", "1") != "0" and hasattr(_socket, "SCM_RIGHTS"):
        rc = _via_warm_process(argv[0])
        if rc is not None:
            return rc
    if sys.flags.no_site:  # started with -S: the step needs site-packages
        import site

        site.main()
    import json

    return _run_here(dict(json.loads(argv[0]), cwd=os.getcwd()))


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
    sys.exit(main(sys.argv[1:]))
