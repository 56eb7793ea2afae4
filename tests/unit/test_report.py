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
    return pd.DataFrame({
        "replication": ["tseng_curvature", "tseng_curvature", ""],
        "id": ["a", "b", "c"], "seed": ["000", "000", "004"],
        "source": ["Table 4.3", "Table 4.3", "Fig 12"], "row": ["l1_mm=4.381"] * 2 + [""],
        "quantity": ["k_s", "k_q", "trend"], "unit": ["per_mm", "per_mm", ""],
        "published": [0.008067, 0.058372, float("nan")], "computed": [0.008067, 0.0584, float("nan")],
        "abs_err": [0.0, 2.8e-5, float("nan")], "tolerance": [5e-7, 5e-7, float("nan")],
        "status": ["reproduced", "deviates", "not-computed"], "note": ["", "l1 rounding", "pending"],
    })


def png():
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    return buf.getvalue()


def test_render_contains_every_paper_status_and_figure(card):
    errata = pd.DataFrame({"seed": ["004"], "location": ["eq (8)"], "printed": ["|r_t . r_p|"],
                           "correction": ["|r_t x r_p|"], "evidence": ["normal must be unit"]})
    html = report.render(card, {"curvature: k_s": png()}, errata, {"python": "3.11"},
                         notebooks={"tseng_curvature": "notebooks/tseng_curvature.html"}, runtime_s=12.5)
    assert html.startswith("<!doctype html>") and html.rstrip().endswith("</html>")
    for text in ("paper-000", "paper-004", "reproduced", "deviates", "not-computed", "data:image/png;base64,",
                 "eq (8)", "12.5 s", "notebooks/tseng_curvature.html#Table-4.3"):
        assert text in html, text
    assert "http://" not in html and "https://" not in html  # opens offline


def test_render_rejects_broken_scorecard(card):
    with pytest.raises(ValueError, match="status"):
        report.render(card.drop(columns=["status"]), {}, pd.DataFrame(), {})


def test_anchor_matches_nbconvert_headings():
    assert report.anchor("Table 4.3") == "Table-4.3"
