# Gather every replication's check file into one scorecard; every published value and claim
# without a check shows `not-computed`.


rule scorecard:
    input:
        checks=CHECK_FILES,
        published=published_files(),
        manifest=f"{PUBLISHED_DIR}/MANIFEST.csv",
        code=script_lib("workflow/scripts/scorecard.py"),
    output:
        csv=report("results/scorecard.csv", caption="../report/scorecard.rst", category="scorecard"),
        md="results/scorecard.md",
    log:
        "results/logs/scorecard.log",
    benchmark:
        "results/benchmarks/scorecard.tsv"
    script:
        "../scripts/scorecard.py"
