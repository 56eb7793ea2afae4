"""Headless-browser screenshot of an HTML page (Chromium or Chrome), usable as a Snakemake script or a CLI.

    python workflow/scripts/screenshot.py results/report.html results/report.png [width] [height]

Exits with a clear message when no Chromium/Chrome binary is found (install Debian's `chromium`).

:func:`probe` opens a page in the same browser and reports what a reader sees: which verdicts,
parity plots and design tables are laid out visibly (images decoded), and every link with whether
it resolves (an in-page anchor that exists, or a local file, and the anchor inside it, that exist).
"""

import html as _html
import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from urllib.parse import unquote, urlsplit

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


#: run in the page after load: what is laid out, and every link; written into <pre id=gearrep-probe>
_PROBE_JS = """
<script>
window.addEventListener("load", function () {
  function shown(el) {
    const r = el.getBoundingClientRect(), st = getComputedStyle(el);
    return r.width > 0 && r.height > 0 && st.visibility !== "hidden" && st.display !== "none"
      && !el.closest("details:not([open])");
  }
  function imgs(el) {
    return Array.from(el.querySelectorAll("img")).map(i => i.complete && i.naturalWidth > 0 && shown(i));
  }
  const out = {
    verdicts: Array.from(document.querySelectorAll(".verdict")).map(
      e => ({id: e.id, text: e.textContent, visible: shown(e)})),
    parity: Array.from(document.querySelectorAll("figure.parity")).map(
      e => ({id: e.id, source: e.dataset.source, visible: shown(e), images: imgs(e)})),
    design: Array.from(document.querySelectorAll("table.design")).map(
      e => ({cls: e.className, visible: shown(e), rows: e.querySelectorAll("tbody tr").length})),
    figures: Array.from(document.querySelectorAll("div.fig")).map(e => ({visible: shown(e), images: imgs(e)})),
    links: Array.from(document.querySelectorAll("a[href]")).map(a => a.getAttribute("href")),
    ids: Array.from(document.querySelectorAll("[id]")).map(e => e.id),
  };
  const pre = document.createElement("pre");
  pre.id = "gearrep-probe";
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>
"""


def probe(html: Path, timeout_s: float = 180) -> dict:
    """What the browser lays out in ``html`` (see the module docstring), plus ``unresolved``: every
    link that does not resolve. The page is copied beside itself with the probe script appended
    (so relative links resolve as in the original), opened headless, and the copy removed."""
    browser = find_browser()
    if browser is None:
        raise RuntimeError(f"no Chromium-family browser on PATH (tried {', '.join(BROWSERS)})")
    html = Path(html).resolve()
    text = html.read_text(encoding="utf-8")
    with tempfile.NamedTemporaryFile("w", suffix=".html", dir=html.parent, delete=False, encoding="utf-8") as tmp:
        tmp.write(text.replace("</body>", _PROBE_JS + "</body>") if "</body>" in text else text + _PROBE_JS)
    try:
        cmd = [
            browser,
            "--headless=new",
            "--no-sandbox",
            "--disable-gpu",
            "--no-first-run",
            "--disable-extensions",
            "--window-size=1280,1800",
            "--dump-dom",
            Path(tmp.name).as_uri(),
        ]
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s)
    finally:
        Path(tmp.name).unlink()
    m = re.search(r'<pre id="gearrep-probe">(.*?)</pre>', out.stdout, re.S)
    if out.returncode != 0 or not m:
        raise RuntimeError(f"{browser} gave no probe result ({out.returncode}): {out.stderr[-1500:]}")
    seen = json.loads(_html.unescape(m.group(1)))
    seen["unresolved"] = unresolved_links(html, seen["links"], set(seen["ids"]))
    return seen


def _ids(path: Path) -> set[str]:
    text = path.read_text(encoding="utf-8", errors="replace")
    return {_html.unescape(i) for i in re.findall(r'\bid="([^"]*)"', text) + re.findall(r"\bid='([^']*)'", text)}


def unresolved_links(page: Path, hrefs, page_ids: set[str]) -> list[str]:
    """Links of ``page`` that do not resolve: an in-page anchor without its element, a local file
    that does not exist, or a file's anchor without its element there. External (http) links are
    refused too: the report must open offline."""
    bad, cache = [], {}
    for href in hrefs:
        parts = urlsplit(href)
        if parts.scheme in ("http", "https", "file") or parts.netloc:
            bad.append(href)
            continue
        frag = unquote(parts.fragment)
        if not parts.path:
            if frag not in page_ids and parts.fragment not in page_ids:
                bad.append(href)
            continue
        target = (page.parent / unquote(parts.path)).resolve()
        if not target.is_file():
            bad.append(href)
            continue
        if frag:
            if target not in cache:
                cache[target] = _ids(target) if target.suffix == ".html" else set()
            ids = cache[target]
            if frag not in ids and parts.fragment not in ids:
                bad.append(href)
    return bad


if __name__ == "__main__":
    if "snakemake" in globals():
        smk = snakemake  # noqa: F821  (provided by Snakemake)
        screenshot(Path(smk.input[0]), Path(smk.output[0]))
    else:
        if len(sys.argv) not in (3, 5):
            sys.exit(__doc__)
        size = [int(v) for v in sys.argv[3:5]] or [1280, 1800]
        screenshot(Path(sys.argv[1]), Path(sys.argv[2]), *size)
