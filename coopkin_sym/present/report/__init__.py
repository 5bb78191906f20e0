"""Singularity-locus reports: Markdown, HTML, LaTeX and JSON.

A report says, for a :class:`~coopkin_sym.analysis.locus.types.Locus`: the generic numbers;
every component (its equations, where it reads simply in angles, its numbers and what
changes, what the change means, an exact witness point in ``--at`` syntax, and what a
float rank test says there); how many singular configurations the float tests missed
and how many regular ones they called singular; parameter-only conditions, factors
dropped for having no real points, and what was not explored within the bounds.
Markdown and HTML reports carry plots of the components on pairs of joint variables
(see :mod:`coopkin_sym.present.locus_plot`); the HTML page is self-contained (the PNGs are
embedded). The LaTeX is an appendix to ``\\input`` in a paper (plain ``article``
class, no packages needed). The JSON is :meth:`Locus.to_json` for programs.

The report is built once as a format-neutral document
(:func:`~coopkin_sym.present.report.document.build_document`, its blocks in
:mod:`~coopkin_sym.present.report.blocks`) and written by one renderer per format
(:mod:`~coopkin_sym.present.report.to_markdown`, :mod:`~.to_html`, :mod:`~.to_latex`),
each implementing :class:`~coopkin_sym.present.report.blocks.Renderer`.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Component, Locus
>>> generic = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
>>> locus = Locus("demo", ["t_q1", "t_q2"], "", generic, [Component(
...     ["t_q1 + 1", "t_q2 + 1"], dict(generic, Nm=3, Nc=3, Nh=1),
...     {"q1": "-pi/2", "q2": "-pi/2"}, True, kind="isolated")])
>>> row = next(x for x in render_markdown(locus).splitlines() if x.startswith("| #1"))
>>> row.split(" | ")[3:11]
['**3**', '**3**', '1', '0', '1', '4', '**1**', '`q1=-pi/2,q2=-pi/2`']
"""

from __future__ import annotations

import dataclasses
import os
import re
import warnings
from collections.abc import Mapping, Sequence
from functools import partial
from pathlib import Path
from typing import Any

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.errors import ReportError, SkippedForTime
from coopkin_sym.exact.parse import brief
from coopkin_sym.present.files import check_output_path, write_files
from coopkin_sym.present.locus_plot import PlotError, default_pairs, free_joints, plot_png
from coopkin_sym.present.report.blocks import Renderer, render
from coopkin_sym.present.report.completeness import SHOWN_FAILURES as SHOWN_FAILURES
from coopkin_sym.present.report.document import build_document
from coopkin_sym.present.report.formulas import MAX_EQUATION as MAX_EQUATION
from coopkin_sym.present.report.pictures import (
    MAX_SYSTEM_PICTURES,
    _skipped,
    system_picture_failed,
    system_picture_jobs,
)
from coopkin_sym.present.report.pictures import SYSTEM_PICTURE as SYSTEM_PICTURE
from coopkin_sym.present.report.pictures import SYSTEM_PICTURE_DPI as SYSTEM_PICTURE_DPI
from coopkin_sym.present.report.pictures import drawable_components as drawable_components
from coopkin_sym.present.report.side_by_side import PictureFailed, draw_in_order
from coopkin_sym.present.report.to_html import HtmlRenderer
from coopkin_sym.present.report.to_json import locus_from_json, render_json
from coopkin_sym.present.report.to_latex import LatexRenderer
from coopkin_sym.present.report.to_markdown import MarkdownRenderer
from coopkin_sym.present.report.words import KIND_PLURALS as KIND_PLURALS
from coopkin_sym.present.report.words import KIND_WORDS as KIND_WORDS
from coopkin_sym.present.report.words import NUMBER_WORDS as NUMBER_WORDS
from coopkin_sym.present.report.words import VERDICT_WORDS as VERDICT_WORDS
from coopkin_sym.present.report.words import _changes as _changes
from coopkin_sym.present.report.words import witness_text

__all__ = ["FORMATS", "RENDERERS", "ReportError", "check_target", "locus_from_json",
           "parse_pairs", "render_html", "render_json", "render_latex", "render_markdown",
           "witness_text", "write_report"]

#: Report formats by file suffix.
FORMATS: dict[str, str] = {".md": "markdown", ".html": "html", ".tex": "latex",
                           ".json": "json"}
#: The renderer of each text format (JSON is data: :func:`render_json`).
RENDERERS: dict[str, type[Renderer]] = {"markdown": MarkdownRenderer, "html": HtmlRenderer,
                                        "latex": LatexRenderer}


# ------------------------------------------------------------------ the formats


def render_markdown(locus: Locus, plots: Mapping[tuple[str, str], str] | None = None) -> str:
    """The report as Markdown (GitHub tables); ``plots`` maps joint pairs to the
    relative paths of their PNGs.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> print(render_markdown(Locus("demo", [], "", {"Nm": 1})).splitlines()[0])
    # Singularity locus of demo
    """
    return render(build_document(locus, plots, max_pictures=MAX_SYSTEM_PICTURES),
                  MarkdownRenderer())


def render_html(locus: Locus, plots: Mapping[tuple[str, str], bytes] | None = None) -> str:
    """The report as one self-contained HTML page; ``plots`` maps joint pairs to PNG
    bytes (embedded as data URIs).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> render_html(Locus("demo", [], "", {"Nm": 1})).startswith("<!DOCTYPE html>")
    True
    """
    return render(build_document(locus, plots, max_pictures=MAX_SYSTEM_PICTURES),
                  HtmlRenderer())


def render_latex(locus: Locus, plots: Mapping[tuple[str, str], str] | None = None) -> str:
    """The report as a LaTeX appendix (``\\section*`` and ``tabular`` only: it
    compiles with a plain ``article`` class, and its tables break across pages;
    ``\\input`` it in a paper). ``plots`` maps joint pairs to PNG file names, listed
    in comments (``\\includegraphics`` needs graphicx).

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> print(render_latex(Locus("demo", [], "", {"Nm": 1})).splitlines()[1])
    \\section*{Singularity locus of demo}
    """
    return render(build_document(locus, plots, in_text=False,
                                 max_pictures=MAX_SYSTEM_PICTURES), LatexRenderer())


def check_target(path: str | os.PathLike, note: bool = True) -> str:
    """Check a report path before any work: a known suffix (``.md``, ``.html``,
    ``.tex``, ``.json``) in an existing writable directory. Returns the format. With
    ``note``, the file's state is noted, so that writing it later notices another run
    that wrote it meanwhile (see :func:`coopkin_sym.present.files.write_files`).

    Example
    -------
    >>> check_target("report.html")
    'html'
    >>> check_target("report.txt")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ReportError: report.txt: unknown report format '.txt' ...
    """
    _, suffix = check_output_path(path, FORMATS, ReportError, "report", note=note)
    return FORMATS[suffix]


def parse_pairs(pairs: Sequence[str | Sequence[str]] | None, system: Any = None
                ) -> list[tuple[str, str]] | None:
    """Joint pairs from ``"q1,q2"`` texts (or pairs), checked against the system's
    joints when it is given.

    Example
    -------
    >>> parse_pairs(["q1,q2"])
    [('q1', 'q2')]
    """
    if pairs is None:
        return None
    joints = None
    if system is not None:
        joints = list(getattr(system, "model", system).joint_names)
    out = []
    for p in pairs:
        names = [s.strip() for s in p.split(",")] if isinstance(p, str) else list(p)
        if len(names) != 2 or not all(names):
            raise ReportError(f"pair {brief(p)}: expected two joints, e.g. q1,q2")
        if names[0] == names[1]:
            raise ReportError(f"pair {brief(p)}: the two joints must differ")
        for n in names:
            if joints is not None and n not in joints:
                raise ReportError(f"pair {brief(p)}: unknown joint {brief(n)} (joints: "
                                  f"{', '.join(joints)})")
        out.append((names[0], names[1]))
    return out


def _no_pairs(locus: Locus, system: Any = None) -> str:
    """Why no pair of joints is plotted by default."""
    if not locus.components:
        return "the locus has no component"
    if not any(c.real for c in locus.components):
        return "no component has real points"
    free = free_joints(locus, system)
    if len(free) < 2:
        return (f"a plot takes two free joints as its axes, and the free joints are "
                f"{', '.join(free) or 'none'} (a fixed joint is never an axis)")
    return "no real component involves a joint"


def _png_name(stem: str, pair: tuple[str, str]) -> str:
    safe = [re.sub(r"[^A-Za-z0-9_.-]", "_", j) for j in pair[:2]]
    return f"{stem}_{safe[0]}_{safe[1]}.png"


# drawn here, with this module's plot_png and MAX_SYSTEM_PICTURES: the names a caller
# of coopkin_sym.present.report sees (and may replace) are the ones used
def _plots(locus: Locus, system: Any, pairs: list[tuple[str, str]] | None,
           dpi: int, until: float | None = None
           ) -> tuple[dict[tuple[str, str], bytes], str | None]:
    try:
        chosen = pairs if pairs is not None else default_pairs(locus, system)
        if not chosen:
            _skipped(f"no plot of the components: {_no_pairs(locus, system)}")
        # the plots, then the pictures of the system, drawn side by side where the
        # machine has the cores, and taken in order while time is left
        plots = [(p, partial(plot_png, locus, system, p, dpi=dpi)) for p in chosen]
        pictures = system_picture_jobs(locus, system, dpi, MAX_SYSTEM_PICTURES)
        jobs = plots + pictures
        pngs = {}
        done = 0
        for k, (value, said) in draw_in_order([job for _, job in jobs], until):
            done = k + 1
            for text, category in said:
                warnings.warn(text, category, stacklevel=2)
            key, job = jobs[k]
            if isinstance(value, PictureFailed):
                if key is not None:         # a plot: its error is the report's
                    raise value.error
                system_picture_failed(job, value.error)
                continue
            if key is None:                 # a picture of the system names itself
                value, key = value
            pngs[key] = value
        if done < len(plots):
            _skipped(f"plots of {len(plots) - done} more pairs of joints left out: the "
                     f"time bound was reached", SkippedForTime)
        if done < len(jobs) and pictures:
            left = len(jobs) - max(done, len(plots))
            _skipped(f"pictures of the system at {left} more components left out: the "
                     f"time bound was reached", SkippedForTime)
        return pngs, None
    except PlotError as exc:
        if "matplotlib" in str(exc) and pairs is None:  # pragma: no cover
            _skipped(f"no plots: {exc}")
            return {}, str(exc)
        raise ReportError(str(exc)) from None


def write_report(locus: Locus, path: str | os.PathLike, system: Any = None, *,
                 pairs: Sequence[str | Sequence[str]] | None = None,
                 dpi: int = 110, verification: Mapping | None = None,
                 pictures_until: float | None = None) -> list[Path]:
    """Write the report in the format of ``path``'s suffix (``.md``, ``.html``,
    ``.tex``, ``.json``), with a PNG per joint pair next to it
    (``<stem>_<qi>_<qj>.png``; none for JSON). Everything is rendered first and
    written through temporary files renamed at the end: nothing is half-written on
    an error. Returns the files written, the report first. A part left out (no plot
    when no real component involves a joint, no picture of the system when it cannot
    be drawn) is announced by an :class:`~coopkin_sym.errors.OutputSkipped` warning
    (``coopkin locus`` prints it on stderr).

    Parameters
    ----------
    locus
        The locus.
    path
        The report file.
    system
        The system (joint kinds for the plots); optional.
    pairs
        Joint pairs to plot (``"q1,q2"`` or pairs); default: the pairs that occur
        together in a real component's equations.
    dpi
        Resolution of the PNGs.
    verification
        A verification (:meth:`~coopkin_sym.analysis.locus.verify.Verification.to_json`) to
        add to a JSON report.
    pictures_until
        A ``time.monotonic()`` value after which no more plot or picture is drawn (the
        ones left out are said); None: all of them.

    Example
    -------
    >>> import tempfile, pathlib
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "r.json"
    >>> [p.name for p in write_report(Locus("demo", [], "", {"Nm": 1}), out)]
    ['r.json']
    """
    target = Path(path)
    fmt = check_target(target, note=False)
    chosen = parse_pairs(pairs, system)
    files: dict[Path, bytes] = {}
    if fmt == "json":
        files[target] = render_json(locus, verification).encode()
    else:
        pngs, problem = _plots(locus, system, chosen, dpi, pictures_until)
        if problem:
            locus = dataclasses.replace(locus, notes=[*locus.notes, problem])
        names = {p: _png_name(target.stem, p) for p in pngs}
        if fmt == "html":
            text = render_html(locus, pngs)
        elif fmt == "markdown":
            text = render_markdown(locus, names)
        else:
            text = render_latex(locus, names)
        files[target] = text.encode()
        for p, data in pngs.items():
            files[target.with_name(names[p])] = data
    _write_all(files)
    return list(files)


def _write_all(files: Mapping[Path, bytes]) -> None:
    """Write every file whole, or none (see :func:`coopkin_sym.present.files.write_files`)."""
    write_files(files, ReportError)
