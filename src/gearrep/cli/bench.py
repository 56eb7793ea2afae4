"""``python -m gearrep.cli.bench [OUT.csv]`` (run by ``make bench``): a 1 000-design sweep of the
example sweep's kind (the crowned spur pair, misalignment x crowning, 1001 pinion angles per design:
engagement limits, TE over the meshing cycle, contact ratio, ellipses) run by ``gearrep sweep`` on
the machine's cores, timed end to end (Snakemake start, shard jobs, aggregation). Prints and writes
one row: designs, cores, wall time [s], designs per second, and the 1-minute load average before
and after (a busy machine shows there). The sweep runs in a temporary directory, removed after.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd
import yaml

from . import main as gearrep_main

__all__ = ["GRID", "run_bench", "main"]

#: the grid of the benchmark sweep: 40 x 25 = 1000 designs of examples/crowned_spur.yaml
GRID = {
    "misalignment.d_gamma_out_deg": {"start": -0.1, "stop": 0.1, "num": 40},
    "pinion.crowning.crown_mm": {"start": 0.02, "stop": 0.25, "num": 25},
}


def run_bench(design: Path, cores: int) -> dict:
    """Run the benchmark sweep of ``design`` on ``cores`` cores; returns its row."""
    with tempfile.TemporaryDirectory(prefix="gearrep-bench-") as tmp:
        sweep = Path(tmp) / "sweep.yaml"
        doc = {"design": str(Path(design).resolve()), "grid": GRID, "phi1_points": 1001, "solves_per_shard": 50000}
        sweep.write_text(yaml.safe_dump(doc))
        load0 = os.getloadavg()[0]
        t0 = time.perf_counter()
        rc = gearrep_main(["sweep", str(sweep), "-o", str(Path(tmp) / "out"), "--cores", str(cores), "--", "--quiet"])
        seconds = time.perf_counter() - t0
        table = pd.read_csv(Path(tmp) / "out" / "sweep.csv") if rc == 0 else None
    n = 0 if table is None else len(table)
    ok = 0 if table is None else int((table["status"] == "ok").sum())
    return {
        "designs": n,
        "designs_ok": ok,
        "cores": cores,
        "wall_s": round(seconds, 2),
        "designs_per_s": round(n / seconds, 2) if n else float("nan"),
        "load_1min_before": round(load0, 2),
        "load_1min_after": round(os.getloadavg()[0], 2),
        "exit_code": rc,
    }


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    out = Path(argv[0]) if argv else Path("results/bench/sweep_throughput.csv")
    root = Path(__file__).resolve().parents[3]
    row = run_bench(root / "examples" / "crowned_spur.yaml", int(os.environ.get("CORES", "2")))
    out.parent.mkdir(parents=True, exist_ok=True)
    pd.DataFrame([row]).to_csv(out, index=False)
    print(
        f"sweep benchmark: {row['designs']} designs ({row['designs_ok']} ok) on {row['cores']} cores in "
        f"{row['wall_s']} s: {row['designs_per_s']} designs/s (load {row['load_1min_before']} -> "
        f"{row['load_1min_after']}); {out}"
    )
    return 0 if row["exit_code"] == 0 and row["designs"] == 1000 else 1


if __name__ == "__main__":
    raise SystemExit(main())
