# Gather every replication's check file into one scorecard; every published value and claim
# without a check shows `not-computed`.


rule scorecard:
    input:
        runner=STEP_RUNNER,
        script="workflow/scripts/scorecard.py",
        checks=CHECK_FILES,
        published=published_files(),
        manifest=f"{PUBLISHED_DIR}/MANIFEST.csv",
        code=script_lib("workflow/scripts/scorecard.py"),
    output:
        csv=report("results/scorecard.csv", caption="../report/scorecard.rst", category="scorecard"),
        md="results/scorecard.md",
        job_timing="results/benchmarks/scorecard.tsv",
    log:
        "results/logs/scorecard.log",
    conda:
        "../envs/gearrep.yaml"
    params:
        python=PYTHON,
        # run by the step runner's warm process (the script reads snakemake.input.<name>)
        request=script_request(
            "workflow/scripts/scorecard.py",
            input={
                "checks": CHECK_FILES,
                "published": published_files(),
                "manifest": f"{PUBLISHED_DIR}/MANIFEST.csv",
            },
            output={"csv": "results/scorecard.csv", "md": "results/scorecard.md"},
            log="results/logs/scorecard.log",
            timing="results/benchmarks/scorecard.tsv",
        ),
    shell:
        "{params.python:q} -S {input.runner:q} {params.request:q}"
