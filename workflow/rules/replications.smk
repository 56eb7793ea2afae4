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
                runner=STEP_RUNNER,
                code=_code,
                design=published_files(*_study.DESIGN_DATA),
            output:
                **{t: f"results/{p}" for t, p in _spec.tables.items()},
                # the job's own wall, CPU and compute seconds (replication_io.write_timing)
                job_timing=f"results/benchmarks/{_key}/{_job}.tsv",
            log:
                f"results/logs/{_key}/{_job}.log",
            # scheduling only: every table job before any checks/figures/notebook job (priority 0,
            # which would otherwise starve a short table job to the end of a cold run), the longest
            # first (Job.priority), so the run ends on short steps
            priority: 1 + _spec.priority
            conda:
                "../envs/gearrep.yaml"
            resources:
                runtime=10,
            params:
                python=PYTHON,
                # what the step runner needs (study, job, settings, files): a changed setting or
                # file list reruns the job
                request=step_request(
                    _key,
                    _job,
                    settings=SETTINGS[_key],
                    published=published_files(*_study.DESIGN_DATA),
                    outputs={t: f"results/{p}" for t, p in _spec.tables.items()},
                    timing=f"results/benchmarks/{_key}/{_job}.tsv",
                    log=f"results/logs/{_key}/{_job}.log",
                ),
            shell:
                "{params.python:q} -S {input.runner:q} {params.request:q}"

    rule:
        name:
            f"{_key}_checks"
        input:
            io=REPLICATION_IO,
            runner=STEP_RUNNER,
            tables=_tables,
            published=_check_data,
            code=_code,
        output:
            **{n: f"results/{p}" for n, p in _study.CHECK_OUTPUTS.items()},
            job_timing=f"results/benchmarks/{_key}/checks.tsv",
        log:
            f"results/logs/{_key}/checks.log",
        conda:
            "../envs/gearrep.yaml"
        params:
            python=PYTHON,
            request=step_request(
                _key,
                "checks",
                tables=_tables,
                published=_check_data,
                outputs={n: f"results/{p}" for n, p in _study.CHECK_OUTPUTS.items()},
                timing=f"results/benchmarks/{_key}/checks.tsv",
                log=f"results/logs/{_key}/checks.log",
            ),
        shell:
            "{params.python:q} -S {input.runner:q} {params.request:q}"

    if _figures:

        rule:
            name:
                f"{_key}_figures"
            input:
                runner=STEP_RUNNER,
                script=f"workflow/scripts/{_key}_figures.py",
                tables=_tables,
                published=_check_data,
                code=script_lib(f"workflow/scripts/{_key}_figures.py"),
            output:
                **{k: figure(p, _key) for k, p in _figures.items()},
                job_timing=f"results/benchmarks/{_key}/figures.tsv",
            log:
                f"results/logs/{_key}/figures.log",
            conda:
                "../envs/gearrep.yaml"
            params:
                python=PYTHON,
                # the script reads snakemake.input.tables / .published and snakemake.output.<key>,
                # as under the script: directive; run by the step runner's warm process
                request=script_request(
                    f"workflow/scripts/{_key}_figures.py",
                    input={"tables": _tables, "published": _check_data},
                    output=_figures,
                    log=f"results/logs/{_key}/figures.log",
                    timing=f"results/benchmarks/{_key}/figures.tsv",
                    preload=FIGURE_MODULES,
                ),
            shell:
                "{params.python:q} -S {input.runner:q} {params.request:q}"

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
            runner=STEP_RUNNER,
            script=NOTEBOOK_EXECUTOR,
            notebook=f"notebooks/{_key}.ipynb",
            code=script_lib(f"notebooks/{_key}.ipynb"),
        output:
            touch(f"results/notebooks/{_key}.executed"),
            job_timing=f"results/benchmarks/{_key}/notebook.tsv",
        log:
            f"results/logs/{_key}/notebook.log",
            notebook=f"results/notebooks/{_key}.ipynb",
        conda:
            "../envs/gearrep.yaml"
        params:
            python=PYTHON,
            # notebooks/<study>.ipynb executed by papermill in the step runner's warm process; the
            # notebook reads snakemake.input.<name> and snakemake.params.settings
            request=notebook_request(
                _key,
                input={
                    "checks": f"results/{_study.CHECK_OUTPUTS['checks']}",
                    "check_outputs": [f"results/{p}" for p in _study.CHECK_OUTPUTS.values()],
                    "tables": _tables,
                    "figures": list(_figures.values()),
                    "published": _check_data,
                    "benchmarks": _benchmarks,
                },
                settings=SETTINGS[_key],
            ),
        shell:
            "{params.python:q} -S {input.runner:q} {params.request:q}"

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
