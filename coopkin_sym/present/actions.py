"""What results do with this layer beyond their display, registered with
:func:`coopkin_sym.analysis.renderers.register_action`: a locus is written as a report
and drawn, a certificate is kept on its locus as its JSON. Imported (with
:mod:`coopkin_sym.present.display`) the first time any of it is asked for.

Example
-------
>>> from coopkin_sym.analysis.renderers import action
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> locus = Locus("demo", ["t_q1", "t_q2"], "", generic, [Component(
...     ["t_q1 + 1", "t_q2 + 1"], dict(generic, Nm=3), {"q1": "-pi/2", "q2": "-pi/2"},
...     True, kind="isolated")])
>>> len(action(locus, "plot")(None).axes) >= 1
True
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.analysis.renderers import register_action
from coopkin_sym.errors import ReportError

#: Report formats by name, and the suffix of each.
SUFFIXES = {"md": ".md", "markdown": ".md", "html": ".html", "tex": ".tex",
            "latex": ".tex", "json": ".json"}


def report_path(path: str | os.PathLike, format: str | None) -> Path:  # noqa: A002
    """The report's path: ``path``, given the suffix of ``format`` when it has none.

    Example
    -------
    >>> report_path("out/locus", "html").name, report_path("r.md", None).name
    ('locus.html', 'r.md')
    >>> report_path("r.md", "json")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ReportError: r.md: the format json asks for the suffix .json
    """
    target = Path(path)
    if format is None:
        return target
    suffix = SUFFIXES.get(str(format).lower())
    if suffix is None:
        raise ReportError(f"unknown report format {format!r} (formats: md, html, tex, "
                          "json)")
    if not target.suffix:
        return target.with_suffix(suffix)
    if target.suffix.lower() != suffix:
        raise ReportError(f"{target}: the format {format} asks for the suffix {suffix}")
    return target


def write_locus(locus: Locus, path: str | os.PathLike, format: str | None = None, *,  # noqa: A002
                system: Any = None, pairs: Sequence | None = None) -> list[Path]:
    """``Locus.write``: the report (with the locus's last verification in JSON)."""
    from coopkin_sym.present.report import write_report
    from coopkin_sym.present.verification import verification_json

    checked = getattr(locus, "verification", None)
    shown = verification_json(checked) if checked is not None else None
    locked = getattr(locus.locked, "verification", None)
    if shown is not None and locked is not None:
        shown["locked"] = verification_json(locked)
    return write_report(locus, report_path(path, format), system, pairs=pairs,
                        verification=shown)


def plot_locus(locus: Locus, pair: Sequence[str] | None = None, *, system: Any = None,
               by: str = "auto"):
    """``Locus.plot``: the components on ``pair`` (default: the first pair shown in a
    report, else the first two joints), coloured ``by`` component or family."""
    from coopkin_sym.present.locus_plot import default_pairs, plot_components

    if pair is None:
        pairs = default_pairs(locus, system)
        pair = pairs[0] if pairs else ("q1", "q2")
    return plot_components(locus, system, tuple(pair), by=by)


register_action(Locus, "write", write_locus)
register_action(Locus, "plot", plot_locus)

__all__ = ["SUFFIXES", "plot_locus", "report_path", "write_locus"]
