"""The shared figure style: units required on axes, published as markers, computed as lines."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from gearrep import plotting  # noqa: E402


def test_axes_need_units():
    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="unit"):
        plotting.label_axes(ax, "phi1", "KE [arcsec]")
    plotting.label_axes(ax, "phi1 [deg]", "a/b [-]")
    plt.close(fig)


def test_markers_and_lines():
    plotting.use_style()
    fig, ax = plt.subplots()
    plotting.computed(ax, [0, 1], [0, 1], "computed")
    plotting.published(ax, [0, 1], [0, 1.1], "Table 5.3")
    lines = ax.get_lines()
    assert lines[0].get_linestyle() == "-"
    assert lines[1].get_linestyle() == "None" and "Table 5.3" in lines[1].get_label()
    assert plotting.finish(ax) is fig and ax.get_legend() is not None
    plt.close(fig)
