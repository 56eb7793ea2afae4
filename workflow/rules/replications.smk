# Every replication's rules, generated from the registry (gearrep.replications.REGISTRY) and each
# study's package face (gearrep.replications._face): one rule per job (a published table or a
# study: asking for one table runs that job alone), one checks rule, one figures rule and one
# notebook rule per study. The rules only move data; the numerics are in the packages.

for _key in REGISTRY:
    _study = load_study(_key)
    _code = lib(f"replications.{_key}", "published", "checks")
    _tables = [f"results/{p}" for p in table_paths(_study.JOBS).values()]
    _check_data = published_files(*_study.CHECK_DATA, *_study.DESIGN_DATA)
    _benchmarks = [f"results/benchmarks/{_key}/{j}.tsv" for j in _study.JOBS]
    _figures = {k: f"results/{p}" for k, p in _study.FIGURES.items()}

    for _job, _spec in _study.JOBS.items():

        rule:
            name:
                f"{_key}_{_job}"
            input:
                io=REPLICATION_IO,
                code=_code,
                design=published_files(*_study.DESIGN_DATA),
            output:
                **{t: f"results/{p}" for t, p in _spec.tables.items()},
            log:
                f"results/logs/{_key}/{_job}.log",
            benchmark:
                f"results/benchmarks/{_key}/{_job}.tsv"
            # scheduling only: every table job before any checks/figures/notebook job (priority 0,
            # which would otherwise starve a short table job to the end of a cold run), the longest
            # first (Job.priority), so the run ends on short steps
            priority: 1 + _spec.priority
            resources:
                runtime=10,
            params:
                study=_key,
                job=_job,
                settings=SETTINGS[_key],  # a changed setting reruns the study's jobs
            script:
                "../scripts/run_job.py"

    rule:
        name:
            f"{_key}_checks"
        input:
            io=REPLICATION_IO,
            tables=_tables,
            published=_check_data,
            code=_code,
        output:
            **{n: f"results/{p}" for n, p in _study.CHECK_OUTPUTS.items()},
        log:
            f"results/logs/{_key}/checks.log",
        benchmark:
            f"results/benchmarks/{_key}/checks.tsv"
        params:
            study=_key,
        script:
            "../scripts/run_checks.py"

    if _figures:

        rule:
            name:
                f"{_key}_figures"
            input:
                tables=_tables,
                published=_check_data,
                code=script_lib(f"workflow/scripts/{_key}_figures.py"),
            output:
                **{k: figure(p, _key) for k, p in _figures.items()},
            log:
                f"results/logs/{_key}/figures.log",
            benchmark:
                f"results/benchmarks/{_key}/figures.tsv"
            params:
                # the script's path is formatted when the job runs, when the loop variable holds the
                # last study: params hold this rule's own
                study=_key,
            script:
                "../scripts/{params.study}_figures.py"

    # notebooks/<study>.ipynb executed with papermill, then rendered to HTML for readers; the
    # notebook reads snakemake.input.<name> and snakemake.params.settings
    rule:
        name:
            f"{_key}_notebook"
        input:
            checks=f"results/{_study.CHECK_OUTPUTS['checks']}",
            check_outputs=[f"results/{p}" for p in _study.CHECK_OUTPUTS.values()],
            tables=_tables,
            figures=list(_figures.values()),
            published=_check_data,
            benchmarks=_benchmarks,
            notebook=f"notebooks/{_key}.ipynb",
            template="workflow/report/notebook/collapsed.html.j2",
            # what the notebook and the script executing and rendering it import
            code=sorted({*script_lib(f"notebooks/{_key}.ipynb"), *script_lib("workflow/scripts/notebook.py")}),
        output:
            notebook=f"results/notebooks/{_key}.ipynb",
            html=f"results/notebooks/{_key}.html",
        log:
            f"results/logs/{_key}/notebook.log",
        benchmark:
            f"results/benchmarks/{_key}/notebook.tsv"
        params:
            settings=SETTINGS[_key],
        script:
            "../scripts/notebook.py"

    CHECK_FILES.append(f"results/{_study.CHECK_OUTPUTS['checks']}")
    FINAL_OUTPUTS.extend(
        _tables + [f"results/{p}" for p in _study.CHECK_OUTPUTS.values()] + list(_figures.values())
    )
    REPORT_FIGURES.extend(_figures[k] for k in _study.REPORT_FIGURES)
    NOTEBOOKS.append(_key)
    BENCHMARKS.extend(
        _benchmarks
        + [f"results/benchmarks/{_key}/{step}.tsv" for step in ("checks", "notebook")]
        + ([f"results/benchmarks/{_key}/figures.tsv"] if _figures else [])
    )
