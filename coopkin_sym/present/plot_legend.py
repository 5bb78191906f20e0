"""The legend of a locus plot: one (colour, marker) style per component, entries
wrapped and counted.

Example
-------
>>> style(0), _wrapped("a b c", 3)
(('tab:blue', 'o'), 'a b\\nc')
"""

from __future__ import annotations

import textwrap

COLORS = ("tab:blue", "tab:red", "tab:green", "tab:purple", "tab:orange", "tab:brown",
          "tab:pink", "tab:olive", "tab:cyan", "tab:gray")
#: Markers of the components ("*" is the witnesses'): with the colours, 110 styles.
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "p", "h", "<", ">")
#: The style of components drawn after every (colour, marker) pair is taken: grey
#: dots, counted in one legend entry.
OVERFLOW_STYLE = ("0.55", ".")


def style(n: int) -> tuple[str, str]:
    """The (colour, marker) of the ``n``-th component drawn (from 0): no two alike
    among the first ``len(COLORS) * len(MARKERS)`` (the counts are coprime: colour and
    marker both change from one to the next), then :data:`OVERFLOW_STYLE`.

    Example
    -------
    >>> style(0), style(1), style(10)
    (('tab:blue', 'o'), ('tab:red', 's'), ('tab:blue', '>'))
    >>> len({style(n) for n in range(110)}), style(110)
    (110, ('0.55', '.'))
    """
    if n >= len(COLORS) * len(MARKERS):
        return OVERFLOW_STYLE
    return COLORS[n % len(COLORS)], MARKERS[n % len(MARKERS)]


#: Characters per line of a legend entry, and lines per entry at most.
LABEL_WIDTH = 64
LABEL_LINES = 3
#: Characters per title line.
TITLE_WIDTH = 78


def _wrapped(text: str, width: int, lines: int | None = None) -> str:
    """``text`` broken into lines of at most ``width`` characters (``lines`` of them at
    most, the last one ending in an ellipsis when text is left out)."""
    out = textwrap.wrap(text, width, max_lines=lines, placeholder=" \u2026",
                        break_on_hyphens=False)
    return "\n".join(out)


#: Legend entries listed at most (every component is drawn; the rest are counted).
LEGEND_ENTRIES = 24


def _legend(fig, ax, handles: list, Line2D, own: bool,  # noqa: N803 - a class
            unlisted: int = 0) -> float:  # float-ok
    """The legend below the axes, outside them: a figure legend that constrained
    layout makes room for (on a figure of our own), else below the given axes. Long
    lists are cut at :data:`LEGEND_ENTRIES` and the rest counted; more than eight
    entries go in two narrower columns; ``unlisted`` components, drawn after every
    style was taken, are counted in that last entry. Returns its height in lines of
    text."""
    left = max(len(handles) - LEGEND_ENTRIES, 0) + unlisted
    if left > 0:
        handles = handles[:LEGEND_ENTRIES]
        color, marker = OVERFLOW_STYLE
        handles.append(Line2D([], [], linestyle="none", marker=marker, color=color,
                              label=f"\u2026 and {left} more (see the report)"))
    handles.append(Line2D([], [], linestyle="none", marker="*", markersize=10,
                          color="white", markeredgecolor="black",
                          label="exact witness point"))
    ncol = 1 if len(handles) <= 9 else 2
    if ncol == 2:
        for h in handles:
            h.set_label(_wrapped(h.get_label().replace("\n", " "), LABEL_WIDTH // 2 + 4,
                                 LABEL_LINES))
    options = {"handles": handles, "ncol": ncol, "fontsize": 8, "frameon": False}
    if own:
        fig.legend(loc="outside lower center", **options)
    else:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), **options)  # float-ok
    per = [h.get_label().count("\n") + 1 for h in handles]
    # matplotlib fills the columns of a legend one after the other
    tall = -(-len(per) // ncol)
    columns = [per[i:i + tall] for i in range(0, len(per), tall)]
    return max(sum(c) + 0.5 * len(c) for c in columns)  # float-ok: lines and gaps


def _height(title: str, rows: float) -> float:  # float-ok: inches
    """A figure height that keeps the axes about 5.5 inches tall under ``title``
    and above a legend of ``rows`` lines (a line of 8-point text is about 0.15 inch).

    Example
    -------
    >>> round(_height("one line", 0), 2)
    6.59
    """
    return 6.4 + 0.19 * (title.count("\n") + 1) + 0.15 * rows  # float-ok: inches
