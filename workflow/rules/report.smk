# Notebooks (executed by Snakemake's notebook directive, via papermill) rendered to HTML for
# readers, and the one-page report. Each replication's rules add to NOTEBOOKS (names of notebooks/<name>.py.ipynb
# whose executing rule writes results/notebooks/<name>.executed) and to REPORT_FIGURES.


rule render_notebook:
    input:
        "results/notebooks/{name}.executed",
        template="workflow/report/notebook/collapsed.html.j2",
        code=script_lib("workflow/scripts/render_notebook.py"),
    output:
        "results/notebooks/{name}.html",
    log:
        "results/logs/render_{name}.log",
    benchmark:
        "results/benchmarks/render_{name}.tsv"
    conda:
        "../envs/gearrep.yaml"
    params:
        notebook="results/notebooks/{name}.ipynb",
    script:
        # nbconvert of the interpreter running Snakemake; the Snakemake preamble removed, code
        # folded, machine paths replaced
        "../scripts/render_notebook.py"


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
