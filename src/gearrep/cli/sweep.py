"""``gearrep sweep``: a grid of designs (misalignment x modification x ...) as a Snakemake workflow.

A sweep file names a base design, the grid axes (dotted design keys, each a list of values or
``{start, stop, num}``), the contact solves per grid point and the shard size. The command checks
all of it before creating anything (refusals exit 2 and leave no directory), writes the resolved
sweep into ``DIR/sweep.json`` and runs the workflow ``sweep.smk`` of this package in ``DIR``: one
job per shard (about ``solves_per_shard`` contact solves each, with declared threads, mem_mb and
runtime) and one local aggregation job. Points whose design is refused (e.g. a misalignment that
moves the contact off the flank) are rows with status ``refused`` and the message, not failures.

Each point is computed alone from its own design, so the numbers do not depend on how the grid is
split into shards or where the shards run. Re-running in the same ``DIR`` with the same sweep
resumes; another sweep is refused.
"""

from __future__ import annotations

import itertools
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

from .. import settings as st
from ..settings import SettingError
from . import loaded
from .analysis import sweep_point
from .design import canonical_hash, check, require_analysis, resolve, set_dotted
from .families import REGISTRY, family_of
from .inputs import Refusal, load_yaml
from .keys import lookup
from .output import exact, provenance

__all__ = ["SWEEP", "SNAKEFILE", "resolve_sweep", "points", "run_shard", "aggregate", "run_cli"]

SNAKEFILE = Path(__file__).with_name("sweep.smk")

SWEEP = st.declare(
    design=st.text(None, "the base design file (a path relative to the sweep file)"),
    phi1_points=st.integer(
        401, "1", "contact solves per grid point over one tooth pair's engagement window", ge=11, le=100001
    ),
    solves_per_shard=st.integer(
        100000, "1", "contact solves per shard (job); about 1e5 keeps the per-job start-up cost small", ge=1, le=10**9
    ),
    ltca=st.flag(
        False,
        "also the loaded analysis of each design (gearrep ltca's cycle summary over analysis.n_points positions: "
        "loaded TE, mesh stiffness, largest pressure); needs the design's load.torque_Nm, and costs 5-25 times a "
        "point's TCA on the involute examples, about 350 times on the CATT one",
    ),
    resources=st.group(
        "resources each shard job asks for (Snakemake threads, mem_mb, runtime)",
        threads=st.integer(1, "1", "threads per shard (the solves run in one process)", ge=1, le=256),
        mem_mb=st.integer(1000, "MB", "memory per shard", ge=100, le=10**7),
        runtime_min=st.integer(60, "min", "wall-time limit per shard", ge=1, le=10**5),
    ),
)

_MAX_POINTS = 10**7


def _axis_values(key, spec):
    if isinstance(spec, dict):
        extra = set(spec) - {"start", "stop", "num"}
        if extra or len(spec) != 3:
            raise SettingError(
                f"sweep.grid.{key}: got {spec!r}; allowed: a list of values or a mapping with keys start, stop, num"
            )
        lin = st.number(None, "", "", ge=-1e9, le=1e9)
        axis = st.declare(start=lin, stop=lin, num=st.integer(None, "1", "", ge=1, le=100000))
        r = st.resolve(axis, spec, where=f"sweep.grid.{key}")
        a, b, n = r["start"], r["stop"], r["num"]
        return [float(x) for x in np.linspace(a, b, n)]
    if not isinstance(spec, list) or not 1 <= len(spec) <= 100000:
        raise SettingError(
            f"sweep.grid.{key}: got {spec!r}; allowed: a list of 1..100000 values or a mapping start, stop, num"
        )
    return list(spec)


def resolve_sweep(raw, base_design) -> dict:
    """The sweep mapping checked: its own keys, each grid axis (a declared design key, every value
    in that key's range) and the grid size. ``base_design``: the base design mapping. Returns the
    resolved sweep with ``axes`` (list of (key, values)), ``base`` (the resolved base design),
    ``n_points``, ``points_per_shard`` and ``n_shards``."""
    if not isinstance(raw, dict):
        raise SettingError(f"sweep: got {raw!r}; allowed: a mapping with keys {sorted(SWEEP) + ['grid']}")
    grid = raw.get("grid")
    if not isinstance(grid, dict) or not grid:
        raise SettingError(f"sweep.grid: got {grid!r}; allowed: a mapping of dotted design keys to lists of values")
    rest = {k: v for k, v in raw.items() if k != "grid"}
    out = st.resolve(SWEEP, rest, where="sweep")
    if out["design"] is None:
        raise SettingError("sweep.design: missing; allowed: the path of the base design file")
    base = resolve(base_design)
    family = family_of(base["family"])
    decl = family.keys
    if out["ltca"] and "ltca" not in family.analyses:
        loaded_families = [k for k, f in REGISTRY.items() if "ltca" in f.analyses]
        raise SettingError(
            f"sweep.ltca: got True; allowed: false for the {family.name} family (the loaded analysis takes the "
            f"families {loaded_families})"
        )
    axes = []
    for key, spec in grid.items():
        if not isinstance(key, str):
            raise SettingError(f"sweep.grid: key {key!r}; allowed: dotted design keys")
        try:
            leaf = lookup(decl, key)
        except (KeyError, AttributeError, TypeError):
            leaf = None
        if leaf is None or leaf.kind == "group" or key == "family":
            raise SettingError(
                f"sweep.grid.{key}: not a design key of family {base['family']!r}; allowed: a dotted key such as "
                "misalignment.d_gamma_out_deg or pinion.crowning.crown_mm"
            )
        values = _axis_values(key, spec)
        for i, v in enumerate(values):
            try:
                resolve(set_dotted(base, key, v))
            except SettingError as e:
                raise SettingError(f"sweep.grid.{key}[{i}]: {e}") from None
        axes.append((key, values))
    n = math.prod(len(v) for _, v in axes)
    if n > _MAX_POINTS:
        raise SettingError(f"sweep.grid: {n} points; allowed: at most {_MAX_POINTS}")
    per_point = family.solves_per_point(out["phi1_points"]) + (loaded.solves_per_design(base) if out["ltca"] else 0)
    pps = max(1, math.ceil(out["solves_per_shard"] / per_point))
    if not out["ltca"]:
        del out["ltca"]  # asked for only: a sweep without it is recorded (sweep.json) as before
    out.update(
        grid={k: v for k, v in axes},
        axes=[[k, v] for k, v in axes],
        base=base,
        n_points=n,
        points_per_shard=pps,
        n_shards=math.ceil(n / pps),
    )
    return out


def points(spec: dict):
    """Every grid point as (index, {key: value}) in row-major order of the axes."""
    keys = [k for k, _ in spec["axes"]]
    for i, combo in enumerate(itertools.product(*(v for _, v in spec["axes"]))):
        yield i, dict(zip(keys, combo))


def _point_row(spec, i, assign) -> dict:
    values = spec["base"]
    for k, v in assign.items():
        values = set_dotted(values, k, v)
    row = {"point": i, **{k.replace(".", "__"): v for k, v in assign.items()}}
    try:
        d = check(values)
        if spec.get("ltca"):
            require_analysis(d, "ltca")
        m = sweep_point(d, spec["phi1_points"])
        if spec.get("ltca"):
            m.update(loaded.sweep_metrics(d))
        row.update(status="ok", message="", **m)
    except (SettingError, ValueError) as e:
        row.update(status="refused" if isinstance(e, SettingError) else "failed", message=str(e))
    return row


_COLUMNS = [
    "contact_ratio",
    "te_peak_to_peak_arcsec",
    "max_ellipse_semi_major_mm",
    "solves",
    "converged",
    "max_residual_mm",
]


def _frame(spec, rows) -> pd.DataFrame:
    keys = ["point"] + [k.replace(".", "__") for k, _ in spec["axes"]] + ["status", "message"] + _COLUMNS
    keys += list(loaded.SWEEP_COLUMNS) if spec.get("ltca") else []
    return pd.DataFrame(rows, columns=keys)


def _hashed(spec: dict) -> tuple:
    """The keys of the sweep that its hash covers (``ltca`` where it is asked for)."""
    return ("axes", "phi1_points", "solves_per_shard") + (("ltca",) if spec.get("ltca") else ())


def _sidecar(path: Path, spec: dict, extra: dict):
    prov = provenance(
        spec["base"],
        "sweep",
        {
            "sweep_sha256": canonical_hash({k: spec[k] for k in _hashed(spec)}),
            "file": path.name,
            **extra,
        },
    )
    path.with_name(path.name + ".prov.json").write_text(json.dumps(prov, indent=1, sort_keys=True) + "\n")


def run_shard(spec_path, shard: int, out_path, log_path=None):
    """Compute shard ``shard`` of the sweep in ``spec_path`` and write its CSV (+ sidecar); the log
    (optional) gets one line per point and the shard's wall time."""
    t0 = time.perf_counter()
    spec = json.loads(Path(spec_path).read_text())
    lo = shard * spec["points_per_shard"]
    hi = min(spec["n_points"], lo + spec["points_per_shard"])
    rows = [_point_row(spec, i, a) for i, a in itertools.islice(points(spec), lo, hi)]
    out = Path(out_path)
    _frame(spec, rows).to_csv(out, index=False, float_format=exact)
    _sidecar(out, spec, {"shard": shard, "points": [lo, hi]})
    if log_path is not None:
        lines = [f"point {r['point']}: {r['status']} {r['message']}".rstrip() for r in rows]
        lines.append(f"shard {shard}: points {lo}..{hi - 1}, {time.perf_counter() - t0:.1f} s")
        Path(log_path).write_text("\n".join(lines) + "\n")


def aggregate(spec_path, shard_paths, out_path):
    """Concatenate the shard tables in point order into the sweep table (+ sidecar)."""
    spec = json.loads(Path(spec_path).read_text())
    df = pd.concat([pd.read_csv(p, keep_default_na=False, na_values=[""]) for p in shard_paths], ignore_index=True)
    df = df.sort_values("point", kind="stable")
    out = Path(out_path)
    df[list(_frame(spec, []).columns)].to_csv(out, index=False, float_format=exact)
    _sidecar(out, spec, {"shards": len(list(shard_paths))})


def run_cli(args) -> int:
    """``gearrep sweep``: check, write DIR/sweep.json, run Snakemake in DIR."""
    sweep_file = Path(args.sweep)
    raw = load_yaml(sweep_file)
    if not isinstance(raw, dict) or not isinstance(raw.get("design"), str):
        raise SettingError(
            f"sweep.design: got {raw.get('design') if isinstance(raw, dict) else raw!r}; allowed: the path of the "
            "base design file"
        )
    design_path = (sweep_file.parent / raw["design"]).resolve()
    spec = resolve_sweep(raw, load_yaml(design_path))
    base = check(spec["base"])
    require_analysis(base, "sweep")  # the base design itself must be analysable
    if spec.get("ltca"):
        require_analysis(base, "ltca")
    spec["design"] = str(design_path)
    out = Path(args.output).resolve()
    spec_path = out / "sweep.json"
    text = json.dumps(spec, indent=1, sort_keys=True) + "\n"
    if out.exists():
        if not out.is_dir() or (any(out.iterdir()) and not spec_path.is_file()):
            raise Refusal(f"-o {out}: exists and holds no sweep; allowed: a new directory or this sweep's own")
        if spec_path.is_file() and spec_path.read_text() != text:
            raise Refusal(f"-o {out}: holds another sweep (sweep.json differs); allowed: a new directory")
    out.mkdir(parents=True, exist_ok=True)
    if not spec_path.is_file():
        spec_path.write_text(text)
    print(
        f"sweep: {spec['n_points']} points x {spec['phi1_points']} solves in {spec['n_shards']} shards of "
        f"{spec['points_per_shard']} points",
        file=sys.stderr,
    )
    cmd = [sys.executable, "-m", "snakemake", "--snakefile", str(SNAKEFILE), "--directory", str(out)]
    cmd += ["--config", f"spec={spec_path}", "--cores", str(args.cores)]
    # the sweep's own settings wherever the command runs: not the workflow profile (profiles/default)
    # that Snakemake would otherwise pick up from the current directory
    cmd += ["--workflow-profile", "none"]
    if args.profile:  # a path is taken relative to where the command runs, not to DIR
        prof = Path(args.profile)
        cmd += ["--profile", str(prof.resolve()) if prof.exists() else args.profile]
    if args.dry_run:
        cmd += ["--dry-run"]
    cmd += list(args.snakemake_args)
    return subprocess.run(cmd).returncode
