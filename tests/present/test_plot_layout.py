"""Pictures that keep their shape: locus plots with many components and long
conditions (the legend outside the axes, the axes a sensible size, no layout warning)."""

from __future__ import annotations

import warnings

import pytest

from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.present.locus_plot import plot_components

pytest.importorskip("matplotlib")

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}


def crowded(count: int) -> Locus:
    """A locus of ``count`` isolated points on (q1, q2), each with a long condition."""
    components = []
    for k in range(count):
        a, b = k % 7 - 3, k // 7 - 3
        text = (f"q1 = 2*atan({a}), q2 = 2*atan({b}), 3*t_q1**2*t_q2**2 + 8*t_q1*t_q2 "
                f"+ 3*t_q1**2 - 7*t_q2 + 11*t_q1*L**2 + 13*t_q2*L**3 - 17*L**4 + 1 = 0")
        components.append(Component([f"t_q1 - ({a})", f"t_q2 - ({b})"],
                                    dict(GENERIC, Ni=2), {"q1": f"2*atan({a})",
                                                          "q2": f"2*atan({b})"},
                                    True, kind="isolated", condition=text))
    return Locus("a system with a rather long name, to make the title wrap as well",
                  ["t_q1", "t_q2", "L"], "", GENERIC, components)


def drawn(fig):
    """The figure drawn once, with every warning an error (a layout that gives up
    warns "constrained_layout not applied")."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig.canvas.draw()
    return fig


@pytest.mark.parametrize("count", [1, 6, 30])
def test_axes_keep_their_size_and_the_legend_stays_in_the_figure(count):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig = drawn(plot_components(crowded(count), None))
    ax = fig.axes[0]
    box = ax.get_position()
    assert box.width > 0.7 and box.height > 0.35          # fractions of the figure
    size = fig.get_size_inches() * fig.dpi
    assert box.width * size[0] > 450 and box.height * size[1] > 400   # pixels
    renderer = fig.canvas.get_renderer()
    whole = fig.bbox
    (legend,) = fig.legends
    for artist in (legend, ax.title, ax.xaxis.label, ax.yaxis.label):
        extent = artist.get_window_extent(renderer)
        assert whole.x0 - 1 <= extent.x0 and extent.x1 <= whole.x1 + 1, artist
        assert whole.y0 - 1 <= extent.y0 and extent.y1 <= whole.y1 + 1, artist
    # the legend lies below the axes, not on them
    assert legend.get_window_extent(renderer).y1 <= ax.get_window_extent(renderer).y0


def test_long_legend_entries_are_wrapped_and_long_lists_counted():
    fig = plot_components(crowded(30), None, by="component")
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert all(len(line) <= 64 for t in texts for line in t.splitlines())
    assert all(t.count("\n") <= 2 for t in texts)
    assert texts[-2] == "\u2026 and 6 more (see the report)"
    assert texts[-1] == "exact witness point"
    assert all(len(line) <= 78 for line in fig.axes[0].get_title().splitlines())


def test_plot_on_given_axes_keeps_the_legend_with_them():
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(12, 8), layout="constrained")
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    plot_components(crowded(3), None, ax=right)
    drawn(fig)
    assert right.get_legend() is not None and not fig.legends
    assert left.get_legend() is None
