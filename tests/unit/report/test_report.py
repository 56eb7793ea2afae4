"""The report page builds from a small results fixture and is self-contained; verdicts, findings,
document order, parity plots, design tables and the status vocabulary."""

import io
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402
from conftest import PUBLISHED_DIR  # noqa: E402

from gearrep import checks, published, report  # noqa: E402

NAN = float("nan")


@pytest.fixture()
def card():
    return pd.DataFrame(
        {
            "replication": ["hobcut_curvature", "hobcut_curvature", ""],
            "id": ["a", "b", "c"],
            "seed": ["000", "000", "004"],
            "source": ["Table 4.3", "Table 4.3", "Fig 12"],
            "row": ["l1_mm=4.381"] * 2 + [""],
            "quantity": ["k_s", "k_q", "trend"],
            "unit": ["per_mm", "per_mm", ""],
            "published": [0.008067, 0.058372, NAN],
            "computed": [0.008067, 0.0584, NAN],
            "abs_err": [0.0, 2.8e-5, NAN],
            "tolerance": [5e-7, 5e-7, NAN],
            "status": ["reproduced", "deviates", "not-computed"],
            "note": ["", "l1 rounding", "pending"],
        }
    )


def _row(id_, source, status, published=NAN, computed=NAN, tol=NAN, note="why it is so: explained", rep="study"):
    return {
        "replication": rep,
        "id": id_,
        "seed": "000",
        "source": source,
        "row": "",
        "quantity": "q",
        "unit": "mm",
        "published": published,
        "computed": computed,
        "abs_err": computed - published,
        "tolerance": tol,
        "status": status,
        "note": note,
    }


@pytest.fixture()
def paper():
    """One paper whose sources sort differently as strings and in the document."""
    rows = [
        _row("s1", "Section 5.5", "reproduced", 1.0, 1.0, 0.05),
        _row("f1", "Fig. 5.7", "deviates", 43.2, 43.66, 0.05, note="the text names neither point nor radius"),
        _row("t1", "Table 4.3", "reproduced", 0.008067, 0.0080671, 5e-7),
        _row("t2", "Table 4.3", "reproduced", 0.058372, 0.0583719, 5e-7),
        _row("c1", "Section 5.6", "qualitative-holds"),
        _row("c2", "Section 5.6", "qualitative-fails", note="ratio 1.64 outside [1.615, 1.625)"),
        _row("n1", "Table 5.2", "not-computed", note="data of Table 5.2 did not survive"),
    ]
    order = {
        ("000", "Table 4.3"): 366,
        ("000", "Table 5.2"): 622,
        ("000", "Fig. 5.7"): 624,
        ("000", "Section 5.5"): 640,
        ("000", "Section 5.6"): 767,
    }
    return pd.DataFrame(rows), order


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
        notebooks={"hobcut_curvature": "notebooks/hobcut_curvature.html"},
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
        "notebooks/hobcut_curvature.html#Table-4.3",
        "verdict-000",
        "partially reproduced",
        "not reproduced",
    ):
        assert text in html, text
    assert "http://" not in html and "https://" not in html  # opens offline


def test_render_rejects_broken_scorecard(card):
    with pytest.raises(ValueError, match="status"):
        report.render(card.drop(columns=["status"]), {}, pd.DataFrame(), {})
    with pytest.raises(ValueError, match="not in gearrep.checks.STATUSES"):
        report.render(card.assign(status=["reproduced", "typo", "deviates"]), {}, pd.DataFrame(), {})


def test_anchor_matches_nbconvert_headings():
    from nbconvert.filters.strings import add_anchor

    for heading in ("Table 4.3", 'Table 10 "Convergence outcomes" (sec 6.2)', "Section 5.5: TE, 3'", "Fig 12 & 13"):
        html = add_anchor(f"<h2>{heading.replace('&', '&amp;')}</h2>")
        assert f'id="{report.anchor(heading)}"' in html.replace("&amp;", "&"), (heading, html)


def test_verdict_criteria():
    ok = pd.DataFrame({"status": ["reproduced", "qualitative-holds"], "published": [1.0, NAN]})
    assert report.verdict(ok)[0] == "reproduced"
    part = pd.DataFrame({"status": ["reproduced", "not-computed"], "published": [1.0, 2.0]})
    v, why = report.verdict(part)
    assert v == "partially reproduced" and "1 of 2 scored items agree" in why and "1 not computed" in why
    none = pd.DataFrame({"status": ["deviates", "qualitative-fails", "not-computed"], "published": [1.0, NAN, NAN]})
    assert report.verdict(none)[0] == "not reproduced"
    with pytest.raises(ValueError, match="result status"):
        report.verdict(none.iloc[:0])
    assert set(report.VERDICT_CRITERIA) == set(report.VERDICTS)


def test_sources_follow_the_paper_not_the_string_order(paper):
    card, order = paper
    assert [s for _, s in report.ordered_sources(card, order)] == [
        "Table 4.3",
        "Table 5.2",
        "Fig. 5.7",
        "Section 5.5",
        "Section 5.6",
    ]
    # without a line a source goes last; string order only among those
    assert [s for _, s in report.ordered_sources(card, {("000", "Section 5.6"): 1})][:2] == ["Section 5.6", "Fig. 5.7"]
    html = report.render(card, {}, pd.DataFrame(), {}, notebooks={"study": "notebooks/study.html"}, order=order)
    table = html.split("id='sources-000'", 1)[1].split("</table>", 1)[0]
    linked = re.findall(r"<a href='notebooks/study\.html#([^']+)'>", table)
    assert linked == ["Table-4.3", "Table-5.2", "Fig.-5.7", "Section-5.5", "Section-5.6"]


def test_document_order_of_the_published_data():
    data = published.load(PUBLISHED_DIR)
    order = published.document_order(data.values, data.claims)
    fig = ("000", "Fig. 5.7 (sec 5.5, read off the figure by the author)")
    assert order[("000", "Table 4.3")] < order[fig] < order[("000", "Table 5.3")]
    with pytest.raises(ValueError, match="line"):
        published.document_order(data.values.drop(columns=["line"]))


def test_one_parity_plot_per_table_with_computed_numbers(paper):
    card, order = paper
    html = report.render(card, {}, pd.DataFrame(), {}, order=order)
    figs = re.findall(r"<figure class='parity' id='([^']+)' data-source='([^']+)'", html)
    # Table 4.3, Fig. 5.7 and Section 5.5 have computed numbers; Table 5.2 (not computed) and the
    # claims of Section 5.6 have none
    assert [s for _, s in figs] == ["Table 4.3", "Fig. 5.7", "Section 5.5"]
    for pid, _ in figs:
        assert f"href='#{pid}'" in html  # the table row links to its plot
    assert "2 of 2 within tolerance: the table agrees." in html
    assert "0 of 1 within tolerance: the table does not agree." in html
    assert report.parity_png(card[card["source"] == "Table 4.3"], "Table 4.3").startswith(b"\x89PNG")
    with pytest.raises(ValueError, match="no row with both"):
        report.parity_png(card[card["source"] == "Table 5.2"], "Table 5.2")


def test_parity_plots_drawn_beforehand_give_the_same_page(paper):
    """The workflow draws each paper's parity plots in a job of their own (parity_pngs) and the
    report embeds them: the page is the one that draws them itself, byte for byte; plots that do
    not match the paper's sources with computed numbers are refused, naming the sources."""
    card, order = paper
    assert list(report.parity_rows(card)) == ["Section 5.5", "Fig. 5.7", "Table 4.3"]  # in row order
    assert [len(r) for r in report.parity_rows(card).values()] == [1, 1, 2]
    pngs = report.parity_pngs(card)
    assert all(p.startswith(b"\x89PNG") for p in pngs.values())
    drawn = report.render(card, {}, pd.DataFrame(), {}, order=order)
    assert report.render(card, {}, pd.DataFrame(), {}, order=order, parity={"000": pngs}) == drawn
    assert "<figure class='parity'" not in report.render(card, {}, pd.DataFrame(), {}, order=order, parity=False)
    fewer = {k: v for k, v in pngs.items() if k != "Table 4.3"}
    with pytest.raises(ValueError, match=r"seed 000: missing for sources \['Table 4.3'\]"):
        report.render(card, {}, pd.DataFrame(), {}, parity={"000": fewer})
    with pytest.raises(ValueError, match=r"without computed numbers \['Table 5.2'\]"):
        report.render(card, {}, pd.DataFrame(), {}, parity={"000": pngs | {"Table 5.2": pngs["Table 4.3"]}})
    with pytest.raises(ValueError, match="computed"):
        report.parity_rows(card.drop(columns=["computed"]))


def test_parity_plots_of_a_paper_share_one_figure_and_nothing_else(paper):
    """parity_pngs draws a paper's plots on one cleared figure (one renderer: the symlog axis's
    math-text tick labels are parsed once, not once per plot); every plot is byte for byte the
    one parity_png draws on a figure of its own."""
    from matplotlib.mathtext import MathTextParser

    card, _ = paper
    rows = report.parity_rows(card)
    alone = {src: report.parity_png(r, src) for src, r in rows.items()}
    MathTextParser._parse_cached.cache_clear()
    together = report.parity_pngs(card)
    shared = MathTextParser._parse_cached.cache_info()
    assert together == alone
    MathTextParser._parse_cached.cache_clear()
    for src, r in rows.items():
        report.parity_png(r, src)
    assert shared.misses < MathTextParser._parse_cached.cache_info().misses


def test_findings_are_written_from_the_records(paper):
    card, order = paper
    errata = pd.DataFrame({"seed": ["000"], "location": ["eq 4.23"]})
    f = report.findings(card, errata, order)
    assert 3 <= len(f) <= 5
    text = " ".join(f)
    assert "Table 4.3 (2 of 2)" in text and "Section 5.5 (1 of 1)" in text
    assert "1 printed number deviates" in text and "the text names neither point nor radius" in text
    assert "1 of 2 stated trends and claims hold" in text and "c2" in text
    assert "data of Table 5.2 did not survive" in text
    assert "eq 4.23" in text


def test_design_tables_of_the_published_examples():
    pub = published
    params = pub.load(PUBLISHED_DIR).params
    d = pub.design_table(params)
    assert set(d["seed"]) == set(pub.SEEDS)
    # one row per example, every printed parameter in it, in the document's order
    assert len(d) == len(params.groupby(["seed", "example"]))
    t10 = d[(d["seed"] == "003") & (d["example"] == "spur_52_72")].iloc[0]
    assert "N1 = 52" in t10["design"] and "pressure_angle = 20 deg" in t10["design"]
    assert "line" in t10["source"]
    with pytest.raises(ValueError, match="seed"):
        pub.design_table(params, seed="9")
    card = pd.DataFrame([_row("x", "Table 4.3", "reproduced", 1.0, 1.0, 0.1)])
    html = report.render(card, {}, pd.DataFrame(), {}, design=d)
    assert 'class="design design-000"' in html
    assert html.count('<table class="design') == 1  # only the papers of the scorecard


def test_printed_inputs_and_any_new_status_are_shown_apart_and_kept_out_of_the_verdict(monkeypatch, paper):
    card, order = paper
    assert report.apart_statuses() == checks.INPUT_STATUSES == ("input",)
    assert "input" not in report.result_statuses()
    with_input = pd.concat([card, pd.DataFrame([_row("i1", "Table 4.3", "input", 3.0)])], ignore_index=True)
    assert report.verdict(with_input) == report.verdict(card)
    html = report.render(with_input, {}, pd.DataFrame(), {}, order=order)
    assert "input (not a result)" in html and "Not results (counted apart" in html
    assert "not a comparison" in report.status_meaning("input")
    for bar in html.split('<div class="bar">')[1:]:
        assert "input:" not in bar.split("</div>", 1)[0]  # the bars show results only
    # a status added to gearrep.checks later appears apart without a change here
    monkeypatch.setattr(checks, "STATUSES", (*checks.STATUSES, "withdrawn"))
    assert report.apart_statuses() == ("input", "withdrawn")
    assert "not a comparison" in report.status_meaning("withdrawn")
    with pytest.raises(ValueError, match="STATUSES"):
        report.status_meaning("no-such-status")


def test_absolute_paths_are_found_and_urls_and_base64_are_not():
    found = report.absolute_paths(
        "see /home/user/gearrep/src/x.py and /tmp/pytest-1/full0/results; C:\\Users\\me\\x file:///work/a"
    )
    assert found == [
        "/home/user/gearrep/src/x.py",
        "/tmp/pytest-1/full0/results;",
        "C:\\Users\\me\\x",
        "file:///work/a",
    ]
    clean = (
        "results/notebooks/x.html https://cdnjs.cloudflare.com/ajax/libs/require.js/2.1/require.min.js "
        "data:image/png;base64,iVBORw0KGgo+/tmp/AAAA/usr/x== src/gearrep/report.py 1/work/2"
    )
    assert report.absolute_paths(clean) == []
    # the fast route (no drive path or file:// URL in the text) finds the same POSIX paths,
    # also at the very start of the text, and none inside a URL, a word or a base64 blob
    assert report.absolute_paths("/home/a b\n/tmp/x =/tmp/y a/home/b .:/usr/c (/opt/d)") == [
        "/home/a",
        "/tmp/x",
        "/opt/d",
    ]


def _load_screenshot_module():
    import importlib.util

    from conftest import ROOT

    spec = importlib.util.spec_from_file_location("screenshot", ROOT / "workflow" / "scripts" / "screenshot.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_unresolved_links_are_named(tmp_path):
    shot = _load_screenshot_module()
    (tmp_path / "notebooks").mkdir()
    (tmp_path / "notebooks" / "a.html").write_text('<h2 id="Table-4.3">x</h2><h2 id="Table-10-%22C%22">y</h2>')
    page = tmp_path / "report.html"
    hrefs = [
        "#top",
        "#gone",
        "notebooks/a.html",
        "notebooks/a.html#Table-4.3",
        "notebooks/a.html#Table-10-%22C%22",
        "notebooks/a.html#Table-9",
        "notebooks/b.html",
        "https://example.org",
    ]
    assert shot.unresolved_links(page, hrefs, {"top"}) == [
        "#gone",
        "notebooks/a.html#Table-9",
        "notebooks/b.html",
        "https://example.org",
    ]


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


def test_fixture_report_probed_in_headless_browser(paper, tmp_path):
    """In a real browser: the verdict, one parity plot per table with computed numbers (image
    decoded) and the design table are laid out visibly, and every link resolves."""
    shot = _load_screenshot_module()
    if shot.find_browser() is None:
        pytest.skip("no Chromium-family browser installed")
    card, order = paper
    (tmp_path / "notebooks").mkdir()
    ids = "".join(f'<h2 id="{report.anchor(s)}">{s}</h2>' for s in card["source"].unique())
    (tmp_path / "notebooks" / "study.html").write_text(f"<html><body>{ids}</body></html>")
    design = pd.DataFrame(
        {"seed": ["000"], "example": ["5.1"], "source": ["Table 5.1 (line 608)"], "design": ["N = 40"]}
    )
    page = tmp_path / "report.html"
    page.write_text(
        report.render(
            card, {}, pd.DataFrame(), {}, notebooks={"study": "notebooks/study.html"}, order=order, design=design
        ),
        encoding="utf-8",
    )
    seen = shot.probe(page)
    assert [(v["id"], v["visible"]) for v in seen["verdicts"]] == [("verdict-000", True)]
    assert "partially reproduced" in seen["verdicts"][0]["text"]
    assert [p["source"] for p in seen["parity"]] == ["Table 4.3", "Fig. 5.7", "Section 5.5"]
    assert all(p["visible"] and p["images"] == [True] for p in seen["parity"])
    assert seen["design"] == [{"cls": "design design-000", "visible": True, "rows": 1}]
    assert seen["unresolved"] == [] and len(seen["links"]) > 10


def test_a_highlight_is_checked_against_its_records(paper):
    card, _ = paper
    ok, text = report.highlight(card, "Table 4.3 holds", ["t*"], ["reproduced"])
    assert ok and "(check records: 2, all reproduced)" in text
    ok, text = report.highlight(card, "all reproduced", ["t1", "f1", "zz*"], ["reproduced"])
    assert not ok and text.startswith("<s>") and "f1: deviates" in text and "no record zz*" in text
    with pytest.raises(ValueError, match="needs ids"):
        report.highlight(card, "x", [], ["reproduced"])
    with pytest.raises(ValueError, match="not in gearrep.checks.STATUSES"):
        report.highlight(card, "x", ["t1"], ["holds"])
    html = report.render(
        card, {}, pd.DataFrame(), {}, highlights={"000": [{"text": "Mine", "ids": ["t1"], "statuses": ["reproduced"]}]}
    )
    findings = html.split("<ul class='findings'>", 1)[1].split("</ul>", 1)[0]
    assert findings.startswith("<li>Mine") and findings.count("<li>") <= 5


def _yaml(name):
    import yaml
    from conftest import ROOT

    return yaml.safe_load((ROOT / "workflow" / "report" / name).read_text(encoding="utf-8"))


def test_the_written_highlights_hold_on_the_reference_scorecard():
    """workflow/report/highlights.yaml against tests/data/scorecard_reference.csv (the scorecard
    of main): every finding is supported by the records it names."""
    from conftest import ROOT

    card = pd.read_csv(ROOT / "tests" / "data" / "scorecard_reference.csv", dtype=str, keep_default_na=False)
    specs = _yaml("highlights.yaml")
    assert set(specs) == set(published.SEEDS)
    for seed, items in specs.items():
        assert 1 <= len(items) <= 3, seed
        for h in items:
            ok, text = report.highlight(card[card["seed"] == seed], h["text"], h["ids"], h["statuses"])
            assert ok, text


def test_every_key_figure_has_a_caption():
    from gearrep.replications import REGISTRY, load

    captions = _yaml("captions.yaml")
    keys = {load(k).FIGURES[f] for k in REGISTRY for f in load(k).REPORT_FIGURES}
    assert keys <= set(captions), sorted(keys - set(captions))
    for key, spec in captions.items():
        assert len(spec["shows"]) > 80 and spec.get("sources"), key
