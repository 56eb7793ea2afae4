"""The ``gearrep`` command (also ``python -m gearrep``): analyses of your own gear pair from a
design file, sweeps on Snakemake, and the replications.

    gearrep check DESIGN.yaml                 validate only (exit 0 / 2)
    gearrep tca DESIGN.yaml -o DIR            TCA over the meshing cycle: tables, figures, summary.html
    gearrep ltca DESIGN.yaml -o DIR           loaded TCA under the design's load: TE, load sharing, pressure
    gearrep curvature DESIGN.yaml -o DIR      principal curvatures and directions on a grid
    gearrep sweep SWEEP.yaml -o DIR           a grid of designs as a Snakemake workflow (sharded)
    gearrep replicate [TARGET]                the replications (the repository's Snakefile)
    gearrep schema                            the JSON schema of design files

This package is the file-reading layer: it reads design files, checks them before any work
(:mod:`gearrep.cli.design`), and writes into a temporary directory renamed at the end
(:mod:`gearrep.cli.output`). A refused design or option prints one line naming the key, the value
and the allowed range on stderr and exits with code 2, leaving no output directory.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import subprocess
import sys
import textwrap
from pathlib import Path

import yaml

from .. import __version__
from ..settings import SettingError
from . import analysis, figures, loaded, sweep
from .design import build, json_schema, require_analysis, resolve
from .inputs import Refusal, load_yaml
from .output import (
    LTCA_SUMMARY_FIELDS,
    LTCA_TABLES,
    Writer,
    atomic_dir,
    check_output,
    provenance,
    stl_text,
    summary_html,
)

__all__ = ["main", "load_yaml", "Refusal"]

EXIT_REFUSED = 2


class _Progress:
    """One status line on stderr (only when stderr is a terminal, or with --progress)."""

    def __init__(self, enabled: bool, label: str):
        self.enabled, self.label = enabled, label

    def __call__(self, what: str, fraction: float):
        if self.enabled:
            sys.stderr.write(f"\r[gearrep {self.label}] {fraction * 100:5.1f} % {what:<40}")
            sys.stderr.flush()

    def done(self):
        if self.enabled:
            sys.stderr.write(f"\r[gearrep {self.label}] done{' ' * 48}\n")


def _parquet_ok(args):
    if getattr(args, "parquet", False):
        if importlib.util.find_spec("pyarrow") is None and importlib.util.find_spec("fastparquet") is None:
            raise Refusal(
                "--parquet: pyarrow is not installed; allowed: install the extra (pip install 'gearrep[parquet]') "
                "or leave out --parquet (CSV is always written)"
            )


def _design(path, analysis_name=None, contact=True):
    """The checked design of the file ``path`` (:func:`gearrep.cli.design.check`), refused before
    its contact check if its family does not support ``analysis_name`` or it lacks a key that
    analysis requires."""
    design = build(resolve(load_yaml(path)))
    if analysis_name is not None:
        require_analysis(design, analysis_name)
    if contact:
        design.family.check_contact(design)
    return design


def _out_dir(args):
    """The output directory of ``-o``, checked before any work (:func:`gearrep.cli.output.check_output`)."""
    return check_output(args.output, overwrite=args.overwrite)


def _cmd_check(args) -> int:
    design = _design(args.design)
    v = design.values
    print(
        f"ok: {args.design}: {v['name']!r} ({design.family.name}, {v['pinion']['teeth']}/{v['gear']['teeth']} teeth"
        f"{', line contact' if design.line_contact else ''})"
    )
    return 0


def _yaml_text(values) -> str:
    return yaml.safe_dump(values, sort_keys=False)


def _cmd_tca(args) -> int:
    out = _out_dir(args)
    _parquet_ok(args)
    design = _design(args.design, "tca")
    prog = _Progress(args.progress, "tca")
    tables = analysis.tca_tables(design, progress=prog)
    prov = provenance(design.values, "tca")
    with atomic_dir(out, overwrite=args.overwrite) as tmp:
        w = Writer(tmp, prov, parquet=args.parquet)
        for name, df in tables.items():
            w.table(name, df)
        prog("flank point clouds and STL", 0.8)
        for member, name in ((1, "pinion"), (2, "gear")):
            pts, _, cloud = analysis.flank_cloud(design, member)
            w.table(f"flank_{name}", cloud)
            w.text(f"flank_{name}.stl", stl_text(pts, f"{design.name} {name} flank"))
        prog("figures", 0.9)
        figs = {k: w.figure(k, f) for k, f in figures.tca_figures(design, tables).items()}
        w.text("design.yaml", _yaml_text(design.values))
        w.text("summary.html", summary_html(design.name, _yaml_text(design.values), tables["summary"], figs, prov))
    prog.done()
    print(f"wrote {out}/ ({len(w.files)} files, each with a .prov.json sidecar)")
    return 0


def _cmd_ltca(args) -> int:
    out = _out_dir(args)
    _parquet_ok(args)
    design = _design(args.design, "ltca")
    prog = _Progress(args.progress, "ltca")
    res = loaded.ltca_tables(design, progress=prog)
    prov = provenance(design.values, "ltca")
    with atomic_dir(out, overwrite=args.overwrite) as tmp:
        w = Writer(tmp, prov, parquet=args.parquet)
        for name, df in res.tables.items():
            w.table(name, df)
        prog("figures", 0.9)
        figs = {k: w.figure(k, f) for k, f in figures.ltca_figures(design, res).items()}
        w.text("design.yaml", _yaml_text(design.values))
        page = summary_html(
            design.name,
            _yaml_text(design.values),
            res.tables["ltca_summary"],
            figs,
            prov,
            LTCA_SUMMARY_FIELDS,
            LTCA_TABLES,
        )
        w.text("summary.html", page)
    prog.done()
    summary = res.tables["ltca_summary"].iloc[0]
    print(
        f"wrote {out}/ ({len(w.files)} files, each with a .prov.json sidecar): {summary['n_positions'] - summary['n_failed']} of "
        f"{summary['n_positions']} positions converged"
    )
    return 0


def _cmd_curvature(args) -> int:
    out = _out_dir(args)
    _parquet_ok(args)
    design = _design(args.design, "curvature", contact=False)
    table = analysis.curvature_table(design)
    with atomic_dir(out, overwrite=args.overwrite) as tmp:
        w = Writer(tmp, provenance(design.values, "curvature"), parquet=args.parquet)
        w.table("curvatures", table)
        w.figure("curvatures", figures.curvature_figure(design, table))
        w.text("design.yaml", _yaml_text(design.values))
    print(f"wrote {out}/curvatures.csv ({len(table)} points)")
    return 0


def _cmd_schema(args) -> int:
    text = json.dumps(json_schema(), indent=1) + "\n"
    if args.write:
        Path(args.write).write_text(text)
    else:
        sys.stdout.write(text)
    return 0


def _cmd_sweep(args) -> int:
    return sweep.run_cli(args)


def _cmd_replicate(args) -> int:
    root = Path(args.directory)
    if not (root / "Snakefile").is_file() or not (root / "workflow").is_dir():
        raise Refusal(
            f"--directory {root}: no gearrep repository here (Snakefile and workflow/ missing); allowed: the root of a "
            "gearrep checkout (the replications need its data/ and workflow/)"
        )
    cmd = [sys.executable, "-m", "snakemake", "--cores", str(args.cores), *([args.target] if args.target else [])]
    cmd += args.snakemake_args
    print("running:", " ".join(cmd), f"(in {root})", file=sys.stderr)
    return subprocess.run(cmd, cwd=root).returncode


_DESCRIPTIONS = {
    None: "Tooth contact analysis of your own gear pair: check a design file, run the TCA over the meshing "
    "cycle, the loaded TCA, the flank curvatures, a sweep of designs, or the replications of the published studies.",
    "check": "Validate a design file without analysing it: types, ranges, unknown or missing keys, undercut, "
    "interference and contact ratio at the operating centre distance, crown and relief against the tooth "
    "thickness, contact at the pitch position under the misalignment. Exit 0: valid; 2: refused, with one "
    "line naming the key, its value and the allowed range.",
    "tca": "Tooth contact analysis over the meshing cycle of the design's pair: the path of contact, "
    "transmission error (one tooth pair and the meshing cycle), contact ellipses, the contact ratio (with "
    "the ISO transverse, overlap and total ratios), flank point clouds and STL, figures and a one-page "
    "summary.html. The design is checked first; results are written to -o DIR only when complete.",
    "ltca": "Loaded tooth contact analysis over the meshing cycle under the design's load (load.torque_Nm on "
    "load.driving) and the members' materials (pinion.material, gear.material; default steel): loaded and unloaded "
    "TE, the load of each tooth pair, the Hertz pressure and edge contact at tips and face ends, the mesh "
    "stiffness, the pressure at the solved pitch position (beside ISO 6336-2's closed form), the pressure map of "
    "the most loaded position, figures and a one-page summary.html (gearrep.ltca; docs/ltca.md for the model). "
    "The design is checked first; results are written to -o DIR only when complete.",
    "curvature": "Principal curvatures k1 >= k2 [1/mm] and principal directions of both flanks on the grid "
    "analysis.curvature_grid over their active profile (from the lowest point that meets the mating tip to "
    "the tip), with a figure.",
    "sweep": "Run a grid of designs (dotted design keys with lists of values or start/stop/num) as a "
    "Snakemake workflow in shards; one row per design in DIR/sweep.csv with the contact ratio and TE of "
    "gearrep tca. A re-run in the same DIR resumes.",
    "replicate": "Run the replications of the published studies (the repository's Snakefile), from the "
    "root of a gearrep checkout.",
    "schema": "Print the JSON schema of design files: every key with its unit, range and default.",
}

_EXAMPLES = {
    None: "example:\n  gearrep check examples/crowned_spur.yaml\n  gearrep tca examples/crowned_spur.yaml -o results/my/spur"
    "\n  gearrep COMMAND --help   (each command's options and an example)",
    "check": "example:\n  gearrep check examples/crowned_spur.yaml",
    "tca": "example:\n  gearrep tca examples/crowned_spur.yaml -o results/my/spur   # then open results/my/spur/summary.html",
    "ltca": "example:\n  gearrep ltca examples/spur.yaml -o results/my/spur_loaded   # then open results/my/spur_loaded/summary.html",
    "curvature": "example:\n  gearrep curvature examples/helical.yaml -o results/my/helical_k",
    "sweep": "example:\n  gearrep sweep examples/sweep_crowned_spur.yaml -o results/my/sweep --cores 2",
    "replicate": "example:\n  gearrep replicate results/scorecard.md --cores 2",
    "schema": "example:\n  gearrep schema --write design.schema.json",
}


def _wrap(text: str) -> str:
    return textwrap.fill(text, 90)


def _command(sub, name: str, help: str, note: str = ""):
    """A subcommand's parser with its description and example (and ``note`` before the example)."""
    return sub.add_parser(
        name,
        help=help,
        description=_wrap(_DESCRIPTIONS[name]),
        epilog=(note + "\n\n" if note else "") + _EXAMPLES[name],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="gearrep",
        description=_wrap(_DESCRIPTIONS[None]),
        epilog=_EXAMPLES[None],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action="version", version=f"gearrep {__version__}")
    p.add_argument("--debug", action="store_true", help="show the traceback of an unexpected error")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    def progress(q):
        q.add_argument(
            "--progress",
            action=argparse.BooleanOptionalAction,
            default=sys.stderr.isatty(),
            help="status line on stderr (default: when stderr is a terminal)",
        )

    q = _command(sub, "check", "validate a design file (exit 0: valid, 2: refused)")
    q.add_argument("design", help="design file (YAML)")
    q.set_defaults(func=_cmd_check)

    for name, func, what in (
        ("tca", _cmd_tca, "TCA over the meshing cycle: TE, contact path, ellipses, contact ratio, figures, HTML"),
        ("ltca", _cmd_ltca, "loaded TCA under the design's load: loaded TE, load sharing, pressure, stiffness, HTML"),
        ("curvature", _cmd_curvature, "principal curvatures and directions of both flanks on a grid"),
    ):
        q = _command(sub, name, what)
        q.add_argument("design", help="design file (YAML)")
        q.add_argument("-o", "--output", required=True, help="output directory (new or empty, or see --overwrite)")
        q.add_argument(
            "--overwrite",
            action="store_true",
            help="replace a previous result in the output directory (only once the new one is complete)",
        )
        q.add_argument("--parquet", action="store_true", help="also write Parquet tables (needs pyarrow)")
        progress(q)
        q.set_defaults(func=func)

    q = _command(
        sub,
        "sweep",
        "a grid of designs run as a Snakemake workflow, split into shards",
        "Snakemake options and targets go after --, e.g. -- --executor slurm --jobs 100",
    )
    q.add_argument("sweep", help="sweep file (YAML)")
    q.add_argument("-o", "--output", required=True, help="output directory (created; a re-run resumes it)")
    q.add_argument("--cores", type=int, default=1, help="cores for a local run (default 1)")
    q.add_argument("--profile", help="Snakemake profile, e.g. profiles/slurm (executor, resources)")
    q.add_argument("--dry-run", action="store_true", help="list the jobs only")
    q.set_defaults(func=_cmd_sweep, passthrough=True)

    q = _command(
        sub,
        "replicate",
        "the replications (runs the repository's Snakefile)",
        "Snakemake options go after --, e.g. -- --configfile config/test.yaml",
    )
    q.add_argument("target", nargs="?", help="a target, e.g. results/scorecard.md (default: everything)")
    q.add_argument("--cores", type=int, default=2)
    q.add_argument("--directory", default=".", help="the gearrep repository root (default: .)")
    q.set_defaults(func=_cmd_replicate, passthrough=True)

    q = _command(sub, "schema", "print the JSON schema of design files")
    q.add_argument("--write", help="write it to this file instead")
    q.set_defaults(func=_cmd_schema)
    return p


def main(argv=None) -> int:
    """Run the command; returns the exit code (0 ok, 2 refused input, 1 failure)."""
    parser = _parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    extra = []
    if "--" in argv:  # sweep / replicate: everything after -- goes to Snakemake unchanged
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1 :]
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:  # argparse: --help (0) or a usage error (2)
        return int(e.code or 0)
    if extra and not getattr(args, "passthrough", False):
        print(f"gearrep {args.command}: refused: arguments after --: {extra}; allowed: none", file=sys.stderr)
        return EXIT_REFUSED
    args.snakemake_args = extra
    try:
        return int(args.func(args))
    except (Refusal, SettingError, FileExistsError) as e:
        print(f"gearrep {args.command}: refused: {e}", file=sys.stderr)
        return EXIT_REFUSED
    except KeyboardInterrupt:
        print(f"gearrep {args.command}: interrupted", file=sys.stderr)
        return 130
    except Exception as e:
        if args.debug:
            raise
        print(
            f"gearrep {args.command}: failed: {e.__class__.__name__}: {e} (run with --debug for the traceback)",
            file=sys.stderr,
        )
        return 1
