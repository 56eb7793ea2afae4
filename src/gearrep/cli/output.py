"""Writing results of the ``gearrep`` command: a temporary directory renamed at the end, tidy CSV
(optional Parquet), STL, figures, the one-page HTML summary, and a provenance sidecar
``<file>.prov.json`` beside every result file (gearrep version, commit, hashes of the settings and
of the design, creation time)."""

from __future__ import annotations

import base64
import contextlib
import datetime as _dt
import html
import io
import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from .. import __version__
from .design import canonical_hash, split_settings

__all__ = [
    "atomic_dir",
    "check_output",
    "commit",
    "provenance",
    "Writer",
    "stl_text",
    "exact",
    "SUMMARY_FIELDS",
    "LTCA_SUMMARY_FIELDS",
    "TCA_TABLES",
    "LTCA_TABLES",
]


def _refuse_target(target: Path, overwrite: bool) -> None:
    """Raise FileExistsError (a refusal) if ``target`` cannot take a result."""
    if target.exists() or target.is_symlink():
        if not target.is_dir():
            raise FileExistsError(f"-o {target}: exists and is not a directory; allowed: a new or empty directory")
        if not overwrite and any(target.iterdir()):
            raise FileExistsError(
                f"-o {target}: exists and is not empty; allowed: a new or empty directory, or --overwrite to replace it"
            )


def _stage_in(target: Path) -> Path:
    """Where the result is written before it becomes ``target``: inside an existing empty
    directory (which may be a mount point that cannot be replaced), else beside ``target``."""
    if target.is_dir() and not any(target.iterdir()):
        return target
    return target.parent


def check_output(target, overwrite: bool = False) -> Path:
    """Check before any work that ``target`` can take a result: a new directory, an empty one, or
    (``overwrite``) a previous result; and that a directory can be written where the result is
    staged (one is created and removed). Raises FileExistsError naming ``target`` otherwise."""
    target = Path(target)
    _refuse_target(target, overwrite)
    parent = target.parent
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    where = _stage_in(target) if target.exists() else parent
    try:
        probe = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=where))
        probe.rmdir()
    except OSError as e:
        raise FileExistsError(
            f"-o {target}: cannot write in {where} ({e.strerror or e}); allowed: a directory you can write"
        ) from None
    return target


@contextlib.contextmanager
def atomic_dir(target: Path, overwrite: bool = False):
    """A staging directory that becomes ``target`` when the block succeeds and is removed when it
    fails (a failed run leaves no output directory and nothing beside it). ``target`` must not
    exist, or be an empty directory (the result is staged inside it and moved up), or with
    ``overwrite`` hold a previous result, which is replaced only when the new one is complete (it is
    renamed aside, the new one renamed in, then it is removed; restored if the swap fails). An
    error naming ``target`` is raised when the result cannot be put in place."""
    target = Path(target)
    _refuse_target(target, overwrite)
    target.parent.mkdir(parents=True, exist_ok=True)
    inside = target.is_dir() and not any(target.iterdir())
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=target if inside else target.parent))
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o777 & ~umask)  # mkdtemp makes it private; the result is an ordinary directory
    try:
        yield tmp
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    moved = []
    try:
        if inside:
            for entry in os.listdir(tmp):
                os.replace(tmp / entry, target / entry)
                moved.append(target / entry)
            tmp.rmdir()
        elif target.exists():  # overwrite: swap
            old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old.", dir=target.parent))
            try:
                os.replace(target, old / "previous")
                try:
                    os.replace(tmp, target)
                except OSError:
                    os.replace(old / "previous", target)
                    raise
            finally:
                shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, target)
    except OSError as e:
        shutil.rmtree(tmp, ignore_errors=True)
        for p in moved:
            shutil.rmtree(p, ignore_errors=True) if p.is_dir() else p.unlink(missing_ok=True)
        raise OSError(
            f"-o {target}: the result could not be put in place ({e.strerror or e}); nothing written"
        ) from None


def commit() -> str:
    """The git commit of the gearrep source tree (with ``-dirty`` for uncommitted changes), or
    ``unknown`` outside a git checkout."""
    here = Path(__file__).resolve().parent
    try:
        sha = subprocess.run(
            ["git", "-C", str(here), "rev-parse", "HEAD"], capture_output=True, text=True, timeout=10, check=True
        ).stdout.strip()
        dirty = subprocess.run(
            ["git", "-C", str(here), "status", "--porcelain", "--untracked-files=no", "--", "."],
            capture_output=True,
            text=True,
            timeout=10,
        ).stdout.strip()
        return sha + ("-dirty" if dirty else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def provenance(values: dict, command: str, extra: dict | None = None) -> dict:
    """The provenance record of a result made from the resolved design ``values``."""
    design, analysis = split_settings(values)
    out = {
        "gearrep_version": __version__,
        "commit": commit(),
        "command": command,
        "design_sha256": canonical_hash(design),
        "settings_sha256": canonical_hash(analysis),
        "created_utc": _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
    }
    if extra:
        out.update(extra)
    return out


def stl_text(points: np.ndarray, name: str) -> str:
    """ASCII STL of a grid surface ``points`` (n_u, n_v, 3), two triangles per grid cell whose four
    corners exist (NaN corners are left out); facet normals from the triangle winding."""
    lines = [f"solid {name}"]
    n_u, n_v, _ = points.shape
    for i in range(n_u - 1):
        for j in range(n_v - 1):
            quad = points[i : i + 2, j : j + 2]
            if not np.all(np.isfinite(quad)):
                continue
            for a, b, c in ((quad[0, 0], quad[1, 0], quad[1, 1]), (quad[0, 0], quad[1, 1], quad[0, 1])):
                n = np.cross(b - a, c - a)
                ln = np.linalg.norm(n)
                n = n / ln if ln > 0 else n
                lines.append(f"  facet normal {n[0]:.9e} {n[1]:.9e} {n[2]:.9e}")
                lines.append("    outer loop")
                for p in (a, b, c):
                    lines.append(f"      vertex {p[0]:.9e} {p[1]:.9e} {p[2]:.9e}")
                lines.append("    endloop")
                lines.append("  endfacet")
    lines.append(f"endsolid {name}")
    return "\n".join(lines) + "\n"


def exact(x) -> str:
    """A float as its shortest round-trip text (the CSV tables keep every digit, nothing more)."""
    return repr(float(x))


_exact = exact


class Writer:
    """Writes result files into ``root`` (the temporary directory), each with its sidecar."""

    def __init__(self, root: Path, prov: dict, parquet: bool = False):
        self.root = Path(root)
        self.prov = prov
        self.parquet = parquet
        self.files: list[str] = []

    def _sidecar(self, path: Path):
        rec = dict(self.prov, file=path.name)
        path.with_name(path.name + ".prov.json").write_text(json.dumps(rec, indent=1, sort_keys=True) + "\n")
        self.files.append(path.name)

    def table(self, name: str, df: pd.DataFrame):
        p = self.root / f"{name}.csv"
        df.to_csv(p, index=False, float_format=_exact)
        self._sidecar(p)
        if self.parquet:
            q = self.root / f"{name}.parquet"
            df.to_parquet(q, index=False)
            self._sidecar(q)

    def text(self, name: str, text: str):
        p = self.root / name
        p.write_text(text)
        self._sidecar(p)

    def figure(self, name: str, fig) -> str:
        """Save ``fig`` as PNG; returns it base64-encoded (for the HTML page)."""
        import matplotlib.pyplot as plt

        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=110, metadata={"Software": None})
        plt.close(fig)
        p = self.root / "figures" / f"{name}.png"
        p.parent.mkdir(exist_ok=True)
        p.write_bytes(buf.getvalue())
        self._sidecar(p)
        return base64.b64encode(buf.getvalue()).decode()


#: one line on each field of ``summary.csv`` (shown beside the value in ``summary.html``)
SUMMARY_FIELDS = {
    "design": "the design's name",
    "family": "the tooth-surface family of the design file",
    "line_contact": "True: the flanks touch along a line (aligned, unmodified pair); no contact ellipse then",
    "contact_ratio": "TCA contact ratio: (phi1 at which one tooth pair leaves mesh - phi1 at which it enters) / "
    "pinion angular pitch, under the design's modifications and misalignment",
    "contact_ratio_method": "how the engagement limits of the contact ratio were found",
    "transverse_contact_ratio_iso": "ISO transverse contact ratio eps_alpha of the nominal involute pair: path "
    "of contact in the transverse section / transverse base pitch (NaN: not an involute pair)",
    "overlap_ratio_iso": "ISO overlap ratio eps_beta = b sin(beta) / (pi m_n) of the nominal involute pair",
    "total_contact_ratio_iso": "ISO total contact ratio eps_gamma = eps_alpha + eps_beta (nominal pair, no crowning "
    "or misalignment; the TCA contact ratio is the one under them)",
    "phi1_begin_rad": "pinion angle at which one tooth pair enters mesh",
    "phi1_end_rad": "pinion angle at which that tooth pair leaves mesh",
    "te_peak_to_peak_arcsec": "peak-to-peak transmission error of the driven gear over a meshing cycle",
    "drive_sense": "max: the driven gear is pushed to the most advanced position the tooth pairs in mesh demand "
    "(the pinion drives); min: to the least advanced",
    "te_zero": "the angle at which the TE (kinematic error) is zero",
    "solves": "contact solves of the analysis",
    "points_converged": "rows of contact_path.csv whose solve converged inside both flanks",
    "points_total": "rows of contact_path.csv",
    "max_residual_mm": "largest residual of the converged contact solves",
    "max_ellipse_semi_major_mm": "largest contact-ellipse semi-major axis along the path (elastic approach "
    "analysis.elastic_approach_mm)",
    "edge_contact_positions": "positions whose contact ellipse reaches a face edge or a tip circle (cut there: "
    "contact_path.csv's edge_contact names the edges; NaN: not evaluated for this family)",
    "transfer_kind": "how the load passes from one tooth pair to the next: crossing (TE curves cross), "
    "at_engagement, at_exit, indeterminate (conjugate action), or envelope of sampled pairs",
}


#: one line on each field of ``ltca_summary.csv`` (shown beside the value in the ``gearrep ltca`` summary.html)
LTCA_SUMMARY_FIELDS = {
    "design": "the design's name",
    "family": "the tooth-surface family of the design file",
    "driving": "the member the torque drives (load.driving)",
    "torque_Nm": "torque on the driving member (load.torque_Nm)",
    "normal_load_N": "sum of the contact loads (normal to the flanks), mean over the converged positions; "
    "T / (r_b cos beta_b) of the driving member where no tip edge carries load",
    "lte_peak_to_peak_urad": "peak-to-peak loaded transmission error of the gear (member 2) over the cycle",
    "lte_peak_to_peak_um": "the same along the transverse line of action (times the gear's base radius)",
    "mesh_stiffness_mean_N_per_mm_um": "mean over the cycle of the mesh stiffness per face width: transverse "
    "base tangential force / elastic transverse approach (unloaded minus loaded TE along the line of action) / "
    "face width",
    "single_pair_stiffness_max_N_per_mm_um": "largest mesh stiffness per face width of the cycle's positions where "
    "one tooth pair carries the load (NaN: no such position, e.g. unrelieved tips whose corners close under "
    "load; see pitch_point_single_pair_stiffness_N_per_mm_um)",
    "max_contact_pressure_MPa": "largest Hertz pressure on the flanks over the cycle (tip edges apart)",
    "load_share_max": "largest share of the normal load carried by one tooth pair",
    "load_share_min": "smallest over the positions of the largest share (0.5: two pairs share equally)",
    "tip_edge_contact_positions": "positions where a tip edge (corner contact at mesh entry or exit) carries load",
    "tip_edge_load_share_max": "largest share of the normal load carried at tip edges",
    "max_tip_edge_pressure_MPa": "largest Hertz pressure at a tip edge, for an edge radius of a tenth of the module",
    "face_end_contact_positions": "positions where the load reaches a face end",
    "n_positions": "positions of the cycle (analysis.n_points, over one angular pitch of the pinion)",
    "n_failed": "positions not converged (NaN rows of ltca_positions.csv, with their status)",
    "max_pressure_phi1_rad": "pinion angle of the position with max_contact_pressure_MPa (its map: "
    "ltca_pressure_map.csv)",
    "pitch_point_phi1_rad": "pinion angle at which tooth pair 0's unloaded contact lies on the pinion's operating "
    "pitch circle (solved; NaN: none, see pitch_point_status)",
    "pitch_point_status": "converged, or why the pitch position or its loaded analysis was not found",
    "pitch_point_pressure_MPa": "largest flank pressure at the pitch position, every tooth pair free to take load",
    "pitch_point_pairs_loaded": "tooth pairs carrying load at the pitch position",
    "pitch_point_load_share": "share of the normal load carried by the tooth pair at the pitch point there",
    "pitch_point_pressure_single_pair_MPa": "largest flank pressure at the pitch position with that tooth pair "
    "alone carrying the load (ISO 6336-2's case)",
    "pitch_point_single_pair_stiffness_N_per_mm_um": "mesh stiffness per face width of that tooth pair alone at "
    "the pitch position (the validation's c')",
    "pitch_point_pressure_iso_MPa": "ISO 6336-2 nominal pitch-point stress Z_H Z_E sqrt(F_t/(d1 b) (u+1)/u) with "
    "Z_eps = Z_beta = 1 of the nominal pair (NaN: no closed form for the family); for an unmodified spur pair "
    "pitch_point_pressure_single_pair_MPa matches it within the validation's tolerance (docs/ltca.md)",
    "ltca_nodes": "nodes along the face per tooth pair (analysis.ltca_nodes)",
    "node_placements": "node placements of the analysis (1 + refinements over a localized contact's span)",
    "max_torque_balance_residual": "largest relative residual of the torque balance over the converged positions",
}

#: the tables each command's summary.html names
TCA_TABLES = (
    "contact_path.csv (contact points, TE, contact ellipses), te_cycle.csv (TE over the meshing cycle), "
    "summary.csv; flanks: flank_pinion.csv / flank_gear.csv (points and outward normals) and .stl."
)
LTCA_TABLES = (
    "ltca_positions.csv (one row per position: TE, loads per tooth pair, pressure, stiffness, status), "
    "ltca_summary.csv, ltca_pressure_map.csv (the pressure map of the position with the largest pressure)."
)


def _table_html(df: pd.DataFrame) -> str:
    return df.to_html(index=False, float_format=lambda x: f"{x:.6g}", border=0, classes="t")


def summary_html(
    title: str,
    design_yaml: str,
    summary: pd.DataFrame,
    figures: dict,
    prov: dict,
    fields: dict = SUMMARY_FIELDS,
    tables: str = TCA_TABLES,
) -> str:
    """One-page HTML summary (opens offline: the figures are embedded): the summary row with the
    meaning of each field (``fields``), the figures, the design, the provenance and ``tables``."""
    figs = "".join(
        f'<figure><img alt="{html.escape(k)}" src="data:image/png;base64,{v}"><figcaption>{html.escape(k)}'
        "</figcaption></figure>"
        for k, v in figures.items()
    )
    rows = summary.T.reset_index()
    rows.columns = ["quantity", "value"]
    rows["meaning"] = [fields.get(k, "") for k in rows["quantity"]]
    prov_rows = pd.DataFrame({"field": list(prov), "value": [str(v) for v in prov.values()]})
    return f"""<!doctype html><html><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body{{font-family:sans-serif;max-width:1100px;margin:1em auto}}table.t{{border-collapse:collapse}}
table.t td,table.t th{{padding:2px 8px;border-bottom:1px solid #ddd;text-align:left}}
figure{{display:inline-block;margin:4px}}img{{max-width:520px}}pre{{background:#f6f6f6;padding:6px}}</style>
</head><body><h1>{html.escape(title)}</h1>
<h2>Results</h2>{_table_html(rows)}
<h2>Figures</h2>{figs}
<h2>Design</h2><pre>{html.escape(design_yaml)}</pre>
<h2>Provenance</h2>{_table_html(prov_rows)}
<p>Tables: {html.escape(tables)}</p>
</body></html>
"""
