# Notebooks (executed by papermill in the step runner: workflow/scripts/execute_notebook.py) rendered to HTML for
# readers, and the one-page report. Each replication's rules add to NOTEBOOKS (names of notebooks/<name>.py.ipynb
# whose executing rule writes results/notebooks/<name>.executed) and to REPORT_FIGURES. The report job
# only assembles the page: every figure it embeds, the parity plots included, is drawn by a job of its own.


rule render_notebook:
    input:
        "results/notebooks/{name}.executed",
        runner=STEP_RUNNER,
        script="workflow/scripts/render_notebook.py",
        exporter=NOTEBOOK_HTML,
        template="workflow/report/notebook/collapsed.html.j2",
        code=script_lib("workflow/scripts/render_notebook.py"),
    output:
        "results/notebooks/{name}.html",
        job_timing="results/benchmarks/render_{name}.tsv",
    log:
        "results/logs/render_{name}.log",
    conda:
        "../envs/gearrep.yaml"
    params:
        python=PYTHON,
        # nbconvert of the interpreter running Snakemake, imported once by the step runner's warm
        # process; the preamble cell removed, code folded, machine paths replaced
        request=lambda wc: script_request(
            "workflow/scripts/render_notebook.py",
            input={"template": "workflow/report/notebook/collapsed.html.j2"},
            output={"html": f"results/notebooks/{wc.name}.html"},
            log=f"results/logs/render_{wc.name}.log",
            timing=f"results/benchmarks/render_{wc.name}.tsv",
            params={"notebook": f"results/notebooks/{wc.name}.ipynb"},
            preload=RENDER_MODULES,
        ),
    shell:
        "{params.python:q} -S {input.runner:q} {params.request:q}"


# The parity plots of one paper (seed), drawn as soon as the checks of its studies exist, so that
# the report job at the end of a run only assembles the page.
PARITY_SEEDS = sorted({study.seed for study in REGISTRY.values()})
#: the check files of each seed's studies
SEED_CHECKS = {
    seed: [
        f"results/{load_study(key).CHECK_OUTPUTS['checks']}" for key, study in REGISTRY.items() if study.seed == seed
    ]
    for seed in PARITY_SEEDS
}


rule report_parity:
    input:
        runner=STEP_RUNNER,
        script="workflow/scripts/report_parity.py",
        checks=lambda wildcards: SEED_CHECKS[wildcards.seed],
        published=lambda wildcards: published_files(f"values_{wildcards.seed}_*.csv", f"claims_{wildcards.seed}.csv"),
        code=script_lib("workflow/scripts/report_parity.py"),
    output:
        directory("results/parity/{seed}"),
        job_timing="results/benchmarks/parity/{seed}.tsv",
    log:
        "results/logs/parity_{seed}.log",
    wildcard_constraints:
        seed="|".join(PARITY_SEEDS),
    conda:
        "../envs/gearrep.yaml"
    params:
        python=PYTHON,
        # run by the step runner's warm process, matplotlib preloaded
        request=lambda wc: script_request(
            "workflow/scripts/report_parity.py",
            input={
                "checks": SEED_CHECKS[wc.seed],
                "published": published_files(f"values_{wc.seed}_*.csv", f"claims_{wc.seed}.csv"),
            },
            output={"parity": f"results/parity/{wc.seed}"},
            log=f"results/logs/parity_{wc.seed}.log",
            timing=f"results/benchmarks/parity/{wc.seed}.tsv",
            params={"published_dir": PUBLISHED_DIR},
            wildcards={"seed": wc.seed},
            preload=FIGURE_MODULES,
        ),
    shell:
        "{params.python:q} -S {input.runner:q} {params.request:q}"


BENCHMARKS.extend(expand("results/benchmarks/parity/{seed}.tsv", seed=PARITY_SEEDS))

#: the report's named inputs (also the script's snakemake.input)
REPORT_INPUT = {
    "scorecard": "results/scorecard.csv",
    "notebooks": expand("results/notebooks/{name}.html", name=NOTEBOOKS),
    "figures": REPORT_FIGURES,
    "parity": expand("results/parity/{seed}", seed=PARITY_SEEDS),
    "errata": "data/errata.csv",
    "published": published_files(),
    "manifest": f"{PUBLISHED_DIR}/MANIFEST.csv",
    "captions": "workflow/report/captions.yaml",
    "highlights": "workflow/report/highlights.yaml",
    "config": "config/config.yaml",
    "lock": "requirements.lock",
}


rule report:
    input:
        **REPORT_INPUT,
        runner=STEP_RUNNER,
        script="workflow/scripts/report.py",
        code=script_lib("workflow/scripts/report.py"),
    output:
        "results/report.html",
        job_timing="results/benchmarks/report.tsv",
    log:
        "results/logs/report.log",
    conda:
        "../envs/gearrep.yaml"
    params:
        python=PYTHON,
        # run by the step runner's warm process
        request=script_request(
            "workflow/scripts/report.py",
            input=REPORT_INPUT,
            output={"html": "results/report.html"},
            log="results/logs/report.log",
            timing="results/benchmarks/report.tsv",
        ),
    shell:
        "{params.python:q} -S {input.runner:q} {params.request:q}"


# Optional (not in the default target; needs Chromium): `snakemake --cores 1 results/report.png`.
rule report_screenshot:
    input:
        "results/report.html",
    output:
        "results/report.png",
    log:
        "results/logs/report_screenshot.log",
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/screenshot.py"
