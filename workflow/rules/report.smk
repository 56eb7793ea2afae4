# Notebooks (executed by Snakemake's notebook directive, via papermill) rendered to HTML for
# readers, and the one-page report. Each replication's rules add to NOTEBOOKS (names of notebooks/<name>.py.ipynb
# whose executing rule writes results/notebooks/<name>.executed) and to REPORT_FIGURES.


rule render_notebook:
    input:
        "results/notebooks/{name}.executed",
        runner=STEP_RUNNER,
        script="workflow/scripts/render_notebook.py",
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
        # process; the Snakemake preamble removed, code folded, machine paths replaced
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
        "{params.python:q} {input.runner:q} {params.request:q}"


rule report:
    input:
        scorecard="results/scorecard.csv",
        notebooks=expand("results/notebooks/{name}.html", name=NOTEBOOKS),
        figures=REPORT_FIGURES,
        errata="data/errata.csv",
        published=published_files(),
        manifest=f"{PUBLISHED_DIR}/MANIFEST.csv",
        captions="workflow/report/captions.yaml",
        highlights="workflow/report/highlights.yaml",
        config="config/config.yaml",
        lock="requirements.lock",
        code=script_lib("workflow/scripts/report.py"),
    output:
        "results/report.html",
    log:
        "results/logs/report.log",
    benchmark:
        "results/benchmarks/report.tsv"
    conda:
        "../envs/gearrep.yaml"
    script:
        "../scripts/report.py"


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
