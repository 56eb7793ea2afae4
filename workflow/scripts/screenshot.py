"""Headless-browser screenshot of an HTML page (Chromium or Chrome), usable as a Snakemake script or a CLI.

    python workflow/scripts/screenshot.py results/report.html results/report.png [width] [height]

Exits with a clear message when no Chromium/Chrome binary is found (install Debian's `chromium`).
"""

import shutil
import subprocess
import sys
from pathlib import Path

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome")


def find_browser() -> str | None:
    """Path of the first Chromium-family browser on PATH, or None."""
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    return None


def screenshot(html: Path, png: Path, width: int = 1280, height: int = 1800, timeout_s: float = 120) -> Path:
    """Render ``html`` (a local file, opened offline) headless and write a PNG of the top of the page."""
    browser = find_browser()
    if browser is None:
        raise RuntimeError(f"no Chromium-family browser on PATH (tried {', '.join(BROWSERS)})")
    html, png = Path(html).resolve(), Path(png).resolve()
    if not html.is_file():
        raise FileNotFoundError(f"html: no such file {html}")
    png.parent.mkdir(parents=True, exist_ok=True)
    cmd = [
        browser,
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--hide-scrollbars",
        "--disable-extensions",
        "--no-first-run",
        f"--window-size={width},{height}",
        f"--screenshot={png}",
        html.as_uri(),
    ]
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s)
    if out.returncode != 0 or not png.is_file():
        raise RuntimeError(f"{browser} failed ({out.returncode}): {out.stderr[-1500:]}")
    return png


if __name__ == "__main__":
    if "snakemake" in globals():
        smk = snakemake  # noqa: F821  (provided by Snakemake)
        screenshot(Path(smk.input[0]), Path(smk.output[0]))
    else:
        if len(sys.argv) not in (3, 5):
            sys.exit(__doc__)
        size = [int(v) for v in sys.argv[3:5]] or [1280, 1800]
        screenshot(Path(sys.argv[1]), Path(sys.argv[2]), *size)
