"""The whole default workflow, run once cold in a private copy of the repository.

`snakemake --cores 2` with the shipped config (every replication is fast enough to run in full:
see docs/performance.md) must build the scorecard, every replication's checks and figures,
execute and render every notebook and write `results/report.html`; afterwards a dry run plans
nothing and a no-op run is quick. The rendered report links every check row to a heading of its
notebook, and a notebook fed a result without its columns fails with the traceback, not a blank
figure. Nothing here reads the working tree's results/.
"""

from __future__ import annotations

import html
import importlib.util
import json
import re
import subprocess
import sys
import time

import pandas as pd
import pytest
from _numerics import reference_mismatches
from conftest import ROOT, copy_workflow, tool_env


def smk(cwd, *args, timeout=900):
    return subprocess.run(
        [sys.executable, "-m", "snakemake", *args],
        cwd=cwd,
        capture_output=True,
        env=tool_env(),
        text=True,
        timeout=timeout,
    )


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    d = tmp_path_factory.mktemp("full")
    copy_workflow(d)
    t0 = time.perf_counter()
    out = smk(d, "--cores", "2")
    elapsed = time.perf_counter() - t0
    assert out.returncode == 0, out.stdout[-4000:] + out.stderr[-4000:]
    # timings are printed, not asserted (no timed assertion in the default run; targets: make bench)
    print(f"\ncold default workflow: {elapsed:.1f} s")
    (d / "run.log").write_text(out.stdout + out.stderr)
    return d


def test_the_run_prints_a_short_log_ending_with_the_report_and_the_verdicts(run):
    """What `make reproduce` shows (the default profile's logger): Snakemake's plan and progress,
    not every job's files and command, and at the end where the report is and each paper's
    verdict."""
    from gearrep import published, report

    lines = (run / "run.log").read_text().splitlines()
    # the plan has one line per rule: 105 lines with the papers' studies, the validation study's 6 rules
    # and the CATT footprint job make 112
    assert len(lines) <= 115, f"{len(lines)} lines"
    at = [i for i, ln in enumerate(lines) if ln.startswith("Report: results/report.html")]
    assert len(at) == 1, lines[-20:]
    verdicts = [ln for ln in lines[at[0] + 1 :] if re.match(r"^  \w+ \(seed \d{3}\): ", ln)]
    assert [ln.split()[0] for ln in verdicts] == list(published.PAPER_NAMES.values()), lines[at[0] :][:8]
    assert all(any(v.upper() in ln for v in report.VERDICTS) for ln in verdicts), verdicts


@pytest.mark.numerics
def test_scorecard_equals_the_reference_id_by_id(run):
    """Results do not change unnoticed: the same ids and statuses (exact) as
    tests/data/scorecard_reference.csv, the accepted scorecard (regenerated in the commit that
    accepts a change of results; CHANGELOG.md lists what moved and why), and every computed value
    (run times excepted) within the computation's resolution of it (tests/_numerics.py:
    RTOL_REFERENCE relative plus the unit's absolute resolution, scaled by the condition number an
    ill-conditioned row's check states), except the deliberate changes listed with their reasons in
    tests/data/scorecard_changes.csv, which must hold their new values."""
    ref = pd.read_csv(ROOT / "tests" / "data" / "scorecard_reference.csv", dtype=str, keep_default_na=False)
    changes = pd.read_csv(ROOT / "tests" / "data" / "scorecard_changes.csv", dtype=str, keep_default_na=False)
    ref = ref.set_index("id")
    for _, c in changes.iterrows():
        assert ref.loc[c["id"], "computed"] == c["previous"], c["id"]
        assert len(c["reason"]) > 40, c["id"]
        ref.loc[c["id"], "computed"] = c["new"]
    new = pd.read_csv(run / "results" / "scorecard.csv", dtype=str, keep_default_na=False).set_index("id")
    assert sorted(ref.index) == sorted(new.index)
    new = new.loc[ref.index]
    changed = ref.index[ref["status"] != new["status"]]
    assert changed.empty, list(zip(changed, ref.loc[changed, "status"], new.loc[changed, "status"]))[:10]
    bad = reference_mismatches(ref, new)
    assert not bad, f"{len(bad)} values moved (id, reference, now, allowed): {bad[:10]}"


def notebooks(d) -> list[str]:
    return sorted(p.stem for p in (d / "results" / "notebooks").glob("*.html"))


def test_default_target_builds_scorecard_report_and_every_notebook(run):
    card = pd.read_csv(run / "results" / "scorecard.csv", dtype={"seed": str})
    assert set(card["seed"]) == {"000", "002", "003", "004", "validation"}
    assert "## Counts by paper" in (run / "results" / "scorecard.md").read_text()
    names = {p.stem for p in (ROOT / "notebooks").glob("*.ipynb")}
    assert set(notebooks(run)) == names, "every notebook in notebooks/ is executed and rendered"
    page = (run / "results" / "report.html").read_text(encoding="utf-8")
    for seed in ("000", "002", "003", "004"):
        assert seed in page
    assert "<img" in page or not names  # key figures are embedded once replications add them


def test_every_deviation_and_gap_carries_its_explanation(run):
    """A value that deviates, a claim that fails and a value not computed each say why; a printed
    input says why it is an input and where it is used."""
    card = pd.read_csv(run / "results" / "scorecard.csv", dtype=str, keep_default_na=False)
    need = card[card["status"].isin(["deviates", "qualitative-fails", "not-computed", "input"])]
    short = need[need["note"].str.strip().str.len() < 20]
    assert short.empty, (
        f"{len(short)} rows without an explanation, e.g. {short[['id', 'status', 'note']].head(5).to_dict('records')}"
    )


def test_readme_counts_are_the_scorecard_counts(run):
    """The README's "Results at a glance" table must not drift from what the workflow computes."""
    card = pd.read_csv(run / "results" / "scorecard.csv", dtype={"seed": str})
    counts = card.groupby(["seed", "status"]).size()
    from gearrep.checks import STATUSES

    cols = list(STATUSES)  # the result statuses, then the printed inputs (column "inputs")
    text = (ROOT / "README.md").read_text()
    block = text.split("## Results at a glance", 1)[1].split("\n## ", 1)[0]
    rows = [ln.split("|")[1:-1] for ln in block.splitlines() if re.match(r"^\| 00\d \|", ln)]
    assert {r[0].strip() for r in rows} == {"000", "002", "003", "004"}
    for r in rows:
        seed = r[0].strip()
        got = [int(counts.get((seed, c), 0)) for c in cols]
        n = len(cols)
        assert [int(x) for x in r[1 : 1 + n]] == got, f"README row {seed}: {r[1 : 1 + n]} but the scorecard has {got}"


def test_rendered_notebooks_have_no_errors_and_a_heading_per_check_source(run):
    card = pd.read_csv(run / "results" / "scorecard.csv", dtype=str, keep_default_na=False)
    for name in notebooks(run):
        text = (run / "results" / "notebooks" / f"{name}.html").read_text(encoding="utf-8")
        executed = json.loads((run / "results" / "notebooks" / f"{name}.ipynb").read_text())
        errors = [
            o
            for c in executed["cells"]
            if c["cell_type"] == "code"
            for o in c.get("outputs", [])
            if o.get("output_type") == "error"
        ]
        assert not errors, f"{name}: {errors[0].get('ename')}: {errors[0].get('evalue')}"
        assert "<img" in text or "image/png" in text, f"{name}: no figure rendered"
        ids = set(re.findall(r'id="([^"]+)"', text))
        from gearrep.report import anchor

        sources = set(card.loc[card["replication"] == name, "source"])
        missing = sorted(s for s in sources if anchor(s) not in ids and html.escape(anchor(s)) not in ids)
        assert not missing, f"{name}: no heading for check sources {missing[:8]} (report links would be dead)"


def test_dry_run_after_full_run_plans_nothing(run):
    out = smk(run, "-n")
    assert out.returncode == 0 and "Nothing to be done" in out.stdout + out.stderr
    t0 = time.perf_counter()
    out = smk(run, "--cores", "2")
    elapsed = time.perf_counter() - t0
    assert out.returncode == 0 and "Nothing to be done" in out.stdout + out.stderr
    print(f"\nno-op re-run: {elapsed:.1f} s")


def test_real_report_in_headless_browser(run):
    """The real report in a real browser: a verdict per paper, one parity plot per table
    with computed numbers (image decoded), the design table of every paper, all laid out visibly,
    and every link (in-page anchors, notebooks and their headings) resolves."""
    spec = importlib.util.spec_from_file_location("screenshot", ROOT / "workflow" / "scripts" / "screenshot.py")
    shot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(shot)
    if shot.find_browser() is None:
        pytest.skip("no Chromium-family browser installed")
    import matplotlib.image as mpimg

    from gearrep import checks, published, report

    page = run / "results" / "report.html"
    img = mpimg.imread(shot.screenshot(page, run / "results" / "report.png", width=1200, height=900))[..., :3]
    assert img.std() > 0.05, "screenshot of the report is blank"

    seen = shot.probe(page)
    card = pd.read_csv(run / "results" / "scorecard.csv", dtype={"seed": str}, keep_default_na=False, na_values=[""])
    # the validation studies' rows are no paper: no verdict, no parity plot, no design table
    card = card[card["seed"] != checks.VALIDATION]
    seeds = sorted(card["seed"].unique())
    assert seeds == sorted(report.paper_verdicts(card))
    verdicts = {v["id"]: v for v in seen["verdicts"]}
    assert sorted(verdicts) == [f"verdict-{s}" for s in seeds]
    for v in verdicts.values():
        assert v["visible"] and any(w in v["text"] for w in report.VERDICTS), v
    numeric = card[card["published"].notna() & card["computed"].notna() & card["status"].isin(report.result_statuses())]
    expected = sorted(set(zip(numeric["seed"], numeric["source"])))
    got = sorted((p["id"].split("-")[1], p["source"]) for p in seen["parity"])
    assert got == expected, "one parity plot per table with computed numbers"
    assert all(p["visible"] and p["images"] == [True] for p in seen["parity"])
    params = published.load(ROOT / "data" / "published").params
    design = published.design_table(params)
    tables = {d["cls"].split()[-1]: d for d in seen["design"]}
    assert sorted(tables) == [f"design-{s}" for s in seeds]
    for s in seeds:
        assert tables[f"design-{s}"]["visible"] and tables[f"design-{s}"]["rows"] == int((design["seed"] == s).sum())
    assert seen["unresolved"] == [], seen["unresolved"][:10]
    assert any(h.startswith("notebooks/") and "#" in h for h in seen["links"])


def test_no_rendered_file_shows_an_absolute_path(run):
    """No page under results/ (report, notebooks, scorecard) names a path of the machine that built
    it: not the run directory, not the interpreter's prefix, not any absolute path."""
    from gearrep.report import absolute_paths

    pages = [p for ext in ("*.html", "*.md", "*.svg") for p in (run / "results").rglob(ext)]
    assert {p.name for p in pages} >= {"report.html", "scorecard.md"} | {f"{n}.html" for n in notebooks(run)}
    for p in pages:
        text = p.read_text(encoding="utf-8", errors="replace")
        assert str(run) not in text and sys.prefix not in text, p.name
        assert not absolute_paths(text), (p.name, absolute_paths(text)[:5])


def test_rendered_notebooks_hide_the_preamble_and_fold_the_code(run):
    """No preamble cell, code folded, the design data at the top and at least as
    many embedded images as the study has figure files."""
    from gearrep.replications import load

    for name in notebooks(run):
        text = (run / "results" / "notebooks" / f"{name}.html").read_text(encoding="utf-8")
        assert "gearrep-snakemake" not in text and "os.chdir" not in text and "pickle" not in text, name
        assert text.count('<details class="gearrep-code">') >= 3, name
        assert "design data" in text, name
        assert text.count("<img") >= len(load(name).FIGURES), f"{name}: fewer images than figure files"


def test_notebook_fails_loudly_on_a_result_without_its_columns(run, tmp_path):
    """Each notebook rule, fed a copy of its first CSV input with every column but the first
    removed, must fail (papermill leaves the traceback in the executed notebook). All notebooks
    are re-run together (--keep-going) and each must be reported as failed."""
    from gearrep.replications import REGISTRY

    rules = {f"{key}_notebook" for key in REGISTRY}
    assert len(rules) == len(list((ROOT / "notebooks").glob("*.ipynb")))
    goals = {r: f"results/notebooks/{r[: -len('_notebook')]}.html" for r in sorted(rules)}
    force = ["--forcerun", *sorted(rules)]
    plain = ["--workflow-profile", "none"]  # the plain log: every job's input, "Error in rule ..."
    jobs = smk(run, *plain, "-n", *force, "--", *goals.values()).stdout
    saved = {}
    try:
        for rule in sorted(rules):
            m = re.search(rf"rule {rule}:\n    input: ([^\n]+)", jobs)
            assert m, jobs[-2000:]
            csvs = [p.strip() for p in m.group(1).split(",") if p.strip().endswith(".csv")]
            assert csvs, f"{rule} reads no CSV"
            target = run / csvs[0]
            assert target not in saved, f"{rule} shares its first CSV with another notebook"
            saved[target] = target.read_bytes()
            pd.read_csv(target).iloc[:, :1].to_csv(target, index=False)
        out = smk(run, *plain, "--cores", "2", "--keep-going", *force, "--", *goals.values())
        text = out.stdout + out.stderr
        assert out.returncode != 0
        ok = [r for r in rules if f"Error in rule {r}:" not in text]
        assert not ok, f"rendered although a result lost its columns: {ok}"
    finally:
        for target, data in saved.items():
            target.write_bytes(data)
