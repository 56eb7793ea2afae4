"""The runner of every study step (workflow/scripts/run_study_step.py): a job run through the warm
process writes exactly what the same job writes in a fresh process, a failure keeps its status
and traceback, and the warm process steps aside when it cannot or must not take a step."""

import json
import os
import socket
import subprocess
import sys
from pathlib import Path

from conftest import ROOT

sys.path.insert(0, str(ROOT / "workflow" / "scripts"))

import run_study_step  # noqa: E402

RUNNER = ROOT / "workflow" / "scripts" / "run_study_step.py"


def request(out, study="tseng_tca", job="ke_table_5_4"):
    from conftest import study_settings

    from gearrep.replications import load

    mod = load(study)
    published = sorted(
        str(p) for pat in mod.DESIGN_DATA for p in (ROOT / "data" / "published").glob(pat) if p.name != "MANIFEST.csv"
    )
    tables = mod.JOBS[job].tables if job in mod.JOBS else {"x": "x.csv"}
    return {
        "study": study,
        "step": job,
        "settings": study_settings(study),
        "published": published,
        "outputs": {t: str(out / p) for t, p in tables.items()},
        "timing": str(out / "timing.tsv"),
        "log": str(out / "step.log"),
    }


def run(cwd, req, warm, timeout=300):
    """The client as the rules start it (``python -S``: without site-packages until it runs a step
    itself)."""
    env = dict(os.environ, GEARREP_WARM_PROCESS="1" if warm else "0")
    return subprocess.run(
        [sys.executable, "-S", str(RUNNER), json.dumps(req)],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=timeout,
    )


def test_a_step_through_the_warm_process_writes_what_a_fresh_process_writes(tmp_path):
    fresh, warm = tmp_path / "fresh", tmp_path / "warm"
    a = run(tmp_path, request(fresh), warm=False)
    assert a.returncode == 0, a.stderr
    assert not (tmp_path / ".snakemake").exists()  # GEARREP_WARM_PROCESS=0: no warm process
    for _ in range(2):  # the first call starts the warm process, the second reuses it
        b = run(tmp_path, request(warm), warm=True)
        assert b.returncode == 0, b.stderr
    assert len(list((tmp_path / ".snakemake").glob("gearrep-warm-*.sock"))) == 1
    out = sorted(p.name for p in fresh.rglob("*.csv"))
    assert out and out == sorted(p.name for p in warm.rglob("*.csv"))
    for name in out:
        assert (fresh / "tseng" / name).read_bytes() == (warm / "tseng" / name).read_bytes(), name
    timing = (warm / "timing.tsv").read_text().splitlines()
    assert timing[0].split("\t") == ["s", "cpu_time", "max_rss", "compute_s"]


def test_a_failing_step_keeps_its_exit_status_and_traceback(tmp_path):
    req = dict(request(tmp_path / "out"), step="no_such_job")
    for warm in (False, True):
        r = run(tmp_path, req, warm)
        assert r.returncode == 1
        assert "KeyError" in r.stderr and "no_such_job" in r.stderr
        assert "no_such_job" in (tmp_path / "out" / "step.log").read_text()


def test_a_stale_socket_is_replaced_and_a_changed_source_refused(tmp_path, monkeypatch):
    # a dead socket file where the warm process's would be: the client starts a new one over it
    # (bound by its path relative to the working directory, as the runner does: socket paths are
    # limited to about 100 characters)
    monkeypatch.chdir(tmp_path)
    path = Path(run_study_step.socket_path())
    path.parent.mkdir()
    dead = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    dead.bind(str(path))
    dead.close()
    r = run(tmp_path, request(tmp_path / "out"), warm=True)
    assert r.returncode == 0, r.stderr
    # the staleness test the warm process makes before each step
    src = tmp_path / "mod.py"
    src.write_text("x = 1\n")
    seen = {str(src): os.stat(src).st_mtime_ns}
    assert run_study_step._unchanged(seen)
    os.utime(src, ns=(1, 1))
    assert not run_study_step._unchanged(seen)
    src.unlink()
    assert not run_study_step._unchanged(seen)


def test_the_warm_process_can_be_switched_off(tmp_path):
    r = run(tmp_path, request(tmp_path / "out"), warm=False)
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / ".snakemake").exists()


def test_a_script_step_reads_the_rules_named_files_as_under_the_script_directive(tmp_path):
    # what the figure and render scripts use of the snakemake object: named and positional
    # access, a named list flattened in order, items(); the preloaded modules are imported once
    script = tmp_path / "script.py"
    script.write_text(
        "import json, sys\n"
        "smk = snakemake  # noqa: F821\n"
        "out = {'tables': smk.input.tables, 'first': smk.input[0], 'flat': list(smk.input),\n"
        "       'named': smk.output['fig'], 'items': sorted(smk.output.items()), 'study': smk.params.study,\n"
        "       'preloaded': 'json' in sys.modules}\n"
        "open(smk.output.fig, 'w').write(json.dumps(out))\n"
        "open(smk.log[0], 'w').write('ok')\n"
    )
    for warm in (False, True, True):
        out = tmp_path / f"out_{warm}.json"
        req = {
            "script": str(script),
            "input": {"tables": ["a.csv", "b.csv"], "published": "p.csv"},
            "output": {"fig": str(out)},
            "log": {"log": str(tmp_path / "script.log")},
            "params": {"study": "thesis"},
            "timing": str(tmp_path / "timing.tsv"),
            "preload": ["json"],
        }
        r = run(tmp_path, req, warm)
        assert r.returncode == 0, r.stderr
        got = json.loads(out.read_text())
        assert got == {
            "tables": ["a.csv", "b.csv"],
            "first": "a.csv",
            "flat": ["a.csv", "b.csv", "p.csv"],
            "named": str(out),
            "items": [["fig", str(out)]],
            "study": "thesis",
            "preloaded": True,
        }
        assert (tmp_path / "timing.tsv").read_text().splitlines()[0].split("\t")[-1] == "compute_s"


def test_a_failing_script_step_keeps_its_status_and_traceback(tmp_path):
    script = tmp_path / "bad.py"
    script.write_text("raise ValueError('figure data missing')\n")
    req = {"script": str(script), "log": {"log": str(tmp_path / "bad.log")}, "timing": str(tmp_path / "t.tsv")}
    for warm in (False, True):
        r = run(tmp_path, req, warm)
        assert r.returncode == 1
        assert "figure data missing" in r.stderr and "figure data missing" in (tmp_path / "bad.log").read_text()
    # a module that cannot be preloaded: the warm process declines, the client runs the script itself
    # (and the warm process lets go of the client's stdout/stderr at once: the reader of the
    # client's output would otherwise wait for the warm process's idle exit, IDLE_SECONDS later)
    assert run_study_step.IDLE_SECONDS > 20
    r = run(tmp_path, dict(req, preload=["no_such_module_xyz"]), True, timeout=20)
    assert r.returncode == 1 and "figure data missing" in r.stderr


def test_a_script_step_waits_for_its_own_subprocesses_as_a_fresh_process(tmp_path):
    """The warm process ignores SIGCHLD; its forked step must not inherit that: a subprocess's exit
    status reaches the step, and its CPU time counts in the step's timing (a notebook's kernel)."""
    script = tmp_path / "sub.py"
    script.write_text(
        "import subprocess, sys\n"
        "smk = snakemake  # noqa: F821\n"
        "busy = 'import time\\nt = time.process_time()\\nwhile time.process_time() - t < 0.3: pass\\nraise SystemExit(3)'\n"
        "rc = subprocess.run([sys.executable, '-c', busy]).returncode\n"
        "open(smk.output.rc, 'w').write(str(rc))\n"
    )
    for warm in (False, True, True):
        req = {
            "script": str(script),
            "output": {"rc": str(tmp_path / "rc.txt")},
            "log": {"log": str(tmp_path / "sub.log")},
            "timing": str(tmp_path / "t.tsv"),
        }
        r = run(tmp_path, req, warm)
        assert r.returncode == 0, r.stderr
        assert (tmp_path / "rc.txt").read_text() == "3"
        head, values = (line.split("\t") for line in (tmp_path / "t.tsv").read_text().splitlines())
        assert float(dict(zip(head, values))["cpu_time"]) >= 0.3


def test_later_steps_inherit_the_modules_the_warm_process_imports_after_its_first_child(tmp_path):
    """The library imports scipy inside the functions that use it; the warm process imports those
    modules once, after forking its first child, so that every later step inherits them instead of
    importing them again (nine jobs of a full run did)."""
    script = tmp_path / "mods.py"
    script.write_text(
        "import sys\n"
        "smk = snakemake  # noqa: F821\n"
        f"names = {list(run_study_step.BACKGROUND_IMPORTS)!r}\n"
        "open(smk.output.seen, 'w').write(' '.join(str(n in sys.modules) for n in names))\n"
    )
    seen = []
    for i in range(2):
        req = {
            "script": str(script),
            "output": {"seen": str(tmp_path / f"seen{i}.txt")},
            "log": {"log": str(tmp_path / "mods.log")},
            "timing": str(tmp_path / "t.tsv"),
        }
        r = run(tmp_path, req, warm=True)
        assert r.returncode == 0, r.stderr
        seen.append((tmp_path / f"seen{i}.txt").read_text().split())
    assert seen[1] == ["True"] * len(run_study_step.BACKGROUND_IMPORTS), seen


def test_the_client_imports_only_what_it_needs_to_hand_a_step_on():
    """Every step starts a client process (89 in a full run): json, pathlib, subprocess, hashlib
    and re (34 ms of CPU) are imported only where used, and the client speaks through ``_socket``
    (the socket module, with selectors and enum, costs 19 ms), started without site-packages."""

    def modules(code):
        out = subprocess.run(
            [sys.executable, "-S", "-c", code + "; print(' '.join(sys.modules))"], capture_output=True, text=True
        )
        assert out.returncode == 0, out.stderr
        return set(out.stdout.split())

    bare = modules("import sys")
    client = modules(f"import sys; sys.path.insert(0, {str(RUNNER.parent)!r}); import run_study_step")
    assert "_socket" in client
    assert not {"json", "pathlib", "subprocess", "hashlib", "re", "socket", "struct", "selectors", "enum"} & (
        client - bare
    )
    # the rules start it with -S (the shell command of every rule that runs it)
    rules = "".join(p.read_text() for p in (ROOT / "workflow" / "rules").glob("*.smk"))
    assert rules.count("{input.runner:q}") == rules.count("{params.python:q} -S {input.runner:q}") > 0


def test_a_client_without_site_packages_runs_its_step_itself_when_no_warm_process_takes_it(tmp_path):
    """Started with -S (as the rules do) and the warm process switched off, the client turns
    site-packages on before it imports the step's modules (numpy, pandas, gearrep)."""
    r = run(tmp_path, request(tmp_path / "out"), warm=False)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "out" / "timing.tsv").exists()


def test_the_socket_name_is_a_stable_hash_of_the_environment():
    """FNV-1a 64 (the client imports no hashlib): the published test vectors, and the name
    follows the interpreter, PYTHONPATH and the runner's path."""
    assert run_study_step._fnv1a64(b"") == 0xCBF29CE484222325
    assert run_study_step._fnv1a64(b"a") == 0xAF63DC4C8601EC8C
    assert run_study_step._fnv1a64(b"foobar") == 0x85944171F73967E8
    name = run_study_step.socket_path()
    assert name.startswith(os.path.join(".snakemake", "gearrep-warm-")) and name.endswith(".sock")
    assert len(os.path.basename(name)) == len("gearrep-warm-.sock") + 16


def test_a_request_that_is_not_a_json_object_fails_its_step_and_leaves_the_warm_process_serving(tmp_path):
    ok = run(tmp_path, request(tmp_path / "a"), warm=True)
    assert ok.returncode == 0, ok.stderr
    sock = tmp_path / run_study_step.socket_path()
    inode = os.stat(sock).st_ino
    bad = run(tmp_path, [1, 2], warm=True)  # refused by the warm process; the client's own run fails
    assert bad.returncode != 0 and "TypeError" in bad.stderr
    again = run(tmp_path, request(tmp_path / "b"), warm=True)
    assert again.returncode == 0, again.stderr
    assert os.stat(sock).st_ino == inode  # the same warm process took the step


def test_steps_that_start_together_start_one_warm_process(tmp_path):
    """The first steps of a run start at the same moment; their clients take turns on a lock, so the
    second finds the warm process the first started instead of starting (and importing) another."""
    script = tmp_path / "parent.py"
    script.write_text("import os\nopen(snakemake.output.pid, 'w').write(str(os.getppid()))  # noqa: F821\n")
    env = dict(os.environ, GEARREP_WARM_PROCESS="1")
    procs = []
    for i in range(3):
        req = {
            "script": str(script),
            "output": {"pid": str(tmp_path / f"pid{i}.txt")},
            "log": {"log": str(tmp_path / f"p{i}.log")},
            "timing": str(tmp_path / f"t{i}.tsv"),
        }
        procs.append(
            subprocess.Popen(
                [sys.executable, str(RUNNER), json.dumps(req)],
                cwd=tmp_path,
                env=env,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                text=True,
            )
        )
    for p in procs:
        _, err = p.communicate(timeout=300)
        assert p.returncode == 0, err
    parents = {(tmp_path / f"pid{i}.txt").read_text() for i in range(3)}
    assert len(parents) == 1, parents  # every step a child of the same warm process
    # and no other warm process was started (one that lost the race would idle until its timeout)
    if Path("/proc/self/cwd").exists():
        serving = []
        for d in Path("/proc").iterdir():
            try:
                if "--serve" in (d / "cmdline").read_bytes().decode() and (d / "cwd").resolve() == tmp_path.resolve():
                    serving.append(d.name)
            except OSError:
                continue
        assert serving == list(parents), serving


def test_a_step_does_not_walk_the_warm_processs_objects_when_it_collects(tmp_path):
    """The warm process freezes its objects (``gc.freeze``) before forking a step: the step's full
    collections walk only what the step created, not the ~170 000 objects it inherited (and so do
    not copy the pages they sit on); the warm process itself collects as before."""
    script = tmp_path / "frozen.py"
    script.write_text("import gc\nopen(snakemake.output.n, 'w').write(str(gc.get_freeze_count()))  # noqa: F821\n")
    counts = {}
    for warm in (False, True):
        req = {
            "script": str(script),
            "output": {"n": str(tmp_path / f"n{warm}.txt")},
            "log": {"log": str(tmp_path / "f.log")},
            "timing": str(tmp_path / "t.tsv"),
        }
        r = run(tmp_path, req, warm)
        assert r.returncode == 0, r.stderr
        counts[warm] = int((tmp_path / f"n{warm}.txt").read_text())
    assert counts[False] == 0 and counts[True] > 10_000, counts


def test_notebook_steps_inherit_the_compiled_notebook_validators(tmp_path):
    """The notebook steps preload ``notebook_validators``: nbformat's strict and relaxed validators
    of the current format are compiled once in the warm process (0.05-0.08 s of CPU each), and a
    step that reads or writes a notebook finds them compiled."""
    script = tmp_path / "val.py"
    script.write_text(
        "from nbformat import current_nbformat, validator\n"
        "keys = sorted(k[1:] for k in validator.validators)\n"
        "open(snakemake.output.keys, 'w').write(repr(keys))  # noqa: F821\n"
    )
    req = {
        "script": str(script),
        "output": {"keys": str(tmp_path / "keys.txt")},
        "log": {"log": str(tmp_path / "v.log")},
        "timing": str(tmp_path / "t.tsv"),
        "preload": ["nbformat", "notebook_validators"],
    }
    r = run(tmp_path, req, warm=True)
    assert r.returncode == 0, r.stderr
    import nbformat

    minor = nbformat.v4.nbformat_minor
    assert (tmp_path / "keys.txt").read_text() == repr([(4, minor, False), (4, minor, True)])
    rules = (ROOT / "workflow" / "rules" / "common.smk").read_text()
    assert rules.count('"notebook_validators"') == 2  # NOTEBOOK_MODULES and RENDER_MODULES
