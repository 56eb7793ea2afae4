"""The report page builds from a small results fixture and is self-contained."""

import io

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402

from gearrep import report  # noqa: E402


@pytest.fixture()
def card():
    return pd.DataFrame(
        {
            "replication": ["tseng_curvature", "tseng_curvature", ""],
            "id": ["a", "b", "c"],
            "seed": ["000", "000", "004"],
            "source": ["Table 4.3", "Table 4.3", "Fig 12"],
            "row": ["l1_mm=4.381"] * 2 + [""],
            "quantity": ["k_s", "k_q", "trend"],
            "unit": ["per_mm", "per_mm", ""],
            "published": [0.008067, 0.058372, float("nan")],
            "computed": [0.008067, 0.0584, float("nan")],
            "abs_err": [0.0, 2.8e-5, float("nan")],
            "tolerance": [5e-7, 5e-7, float("nan")],
            "status": ["reproduced", "deviates", "not-computed"],
            "note": ["", "l1 rounding", "pending"],
        }
    )


def png():
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    return buf.getvalue()


def test_render_contains_every_paper_status_and_figure(card):
    errata = pd.DataFrame(
        {
            "seed": ["004"],
            "location": ["eq (8)"],
            "printed": ["|r_t . r_p|"],
            "correction": ["|r_t x r_p|"],
            "evidence": ["normal must be unit"],
        }
    )
    html = report.render(
        card,
        {"curvature: k_s": png()},
        errata,
        {"python": "3.11"},
        notebooks={"tseng_curvature": "notebooks/tseng_curvature.html"},
        runtime_s=12.5,
    )
    assert html.startswith("<!doctype html>") and html.rstrip().endswith("</html>")
    for text in (
        "paper-000",
        "paper-004",
        "reproduced",
        "deviates",
        "not-computed",
        "data:image/png;base64,",
        "eq (8)",
        "12.5 s",
        "notebooks/tseng_curvature.html#Table-4.3",
    ):
        assert text in html, text
    assert "http://" not in html and "https://" not in html  # opens offline


def test_render_rejects_broken_scorecard(card):
    with pytest.raises(ValueError, match="status"):
        report.render(card.drop(columns=["status"]), {}, pd.DataFrame(), {})


def test_anchor_matches_nbconvert_headings():
    from nbconvert.filters.strings import add_anchor

    for heading in ("Table 4.3", 'Table 10 "Convergence outcomes" (sec 6.2)', "Section 5.5: TE, 3'", "Fig 12 & 13"):
        html = add_anchor(f"<h2>{heading.replace('&', '&amp;')}</h2>")
        assert f'id="{report.anchor(heading)}"' in html.replace("&amp;", "&"), (heading, html)


def _load_screenshot_module():
    import importlib.util

    from conftest import ROOT

    spec = importlib.util.spec_from_file_location("screenshot", ROOT / "workflow" / "scripts" / "screenshot.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_report_screenshot_in_headless_browser(card, tmp_path):
    """The page opens offline in a real browser and shows the status colours of the summary bar.

    .ci/run installs Debian's chromium when it is missing; elsewhere the test is skipped."""
    import matplotlib.image as mpimg
    import numpy as np

    shot = _load_screenshot_module()
    if shot.find_browser() is None:
        pytest.skip("no Chromium-family browser installed")
    page = tmp_path / "report.html"
    page.write_text(
        report.render(card, {"curvature: k_s": png()}, pd.DataFrame(), {"python": "3.11"}), encoding="utf-8"
    )
    out = shot.screenshot(page, tmp_path / "report.png", width=1000, height=800)
    img = mpimg.imread(out)[..., :3]
    assert img.shape[:2] == (800, 1000)
    assert img.std() > 0.05, "screenshot is blank"
    for hex_colour in ("#1a7f37", "#cf222e"):  # reproduced (green) and deviates (red) in the summary bar
        rgb = np.array([int(hex_colour[i : i + 2], 16) for i in (1, 3, 5)]) / 255.0
        assert (np.abs(img - rgb).max(axis=-1) < 0.03).sum() > 20, f"{hex_colour} not on screen"


def test_printed_inputs_are_shown_apart_from_results(card):
    from gearrep import checks

    assert set(report._STATUS_COLOURS) == set(checks.STATUSES)  # every status has its colour
    extra = card.iloc[[0, 0]].assign(id=["i1", "i2"], status="input", computed=float("nan"), note="design input")
    html = report.render(pd.concat([card, extra], ignore_index=True), {}, pd.DataFrame(), {})
    legend = html.split("Status legend:", 1)[1].split("</p>", 1)[0]
    assert legend.index("not-computed") < legend.index("printed design inputs") < legend.index(">input<")
    head = html.split("<h2 id='summary'>", 1)[1].split("</thead>", 1)[0]
    assert head.index("<th>results</th>") < head.index("<th>input</th>") < head.index("<th>total</th>")
    row = html.split("href='#paper-000'", 1)[1].split("</tr>", 1)[0]
    # seed 000: 1 reproduced, 1 deviates, 0 qualitative, 0 not-computed | 2 results | 2 inputs | 4 total
    assert row.split("</div></td>", 1)[1].count("<td class='num'>") == len(checks.STATUSES) + 2
    nums = [int(x.split("<")[0]) for x in row.split("<td class='num'>")[1:]]
    assert nums == [1, 1, 0, 0, 0, 2, 2, 4]
    bar = row.split('<div class="bar">', 1)[1].split("</div>", 1)[0]
    assert "input" not in bar  # the bar shows results only
