"""The passive-joint analysis and the results of a batch in a notebook: an HTML view
and the text IPython prints, like an :class:`~coopkin_sym.analysis.mobility.Analysis`
(registered by :mod:`coopkin_sym.present.display`).

Example
-------
>>> from coopkin_sym import load
>>> p = load("five-bar").analyze("L=1").passive
>>> print(passive_pretty(p).splitlines()[2])
  Na = 2  Np = 2  Nco = 2  Nuo = 1  Npi = 0  Nar = 0  Nam = 2
>>> '<td style="text-align:center">1</td>' in passive_html(p)
True
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from coopkin_sym.analysis.batch import BatchResult
from coopkin_sym.analysis.locus.types import Certificate
from coopkin_sym.analysis.locus.verify_results import Verification
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.analysis.passive import PASSIVE_NUMBER_NAMES, PassiveAnalysis
from coopkin_sym.present.certificate import certificate_summary, check_text
from coopkin_sym.present.classes import classes_text
from coopkin_sym.present.html_parts import bullet_list, div, escape, numbers_table, table
from coopkin_sym.present.mathjax import math_html, typesets
from coopkin_sym.present.passive import PASSIVE_WORDS, passive_lines
from coopkin_sym.present.verification import summary_lines

__all__ = ["PASSIVE_JOINTS_SHOWN", "analysis_passive", "batch_html", "batch_pretty",
           "certificate_html", "certificate_pretty", "verification_html",
           "verification_pretty",
           "passive_html", "passive_numbers_table", "passive_pretty", "passive_section"]

#: An analysis shows its passive-joint numbers for up to this many joints (beyond,
#: they are not computed for a display: ``analysis.passive`` gives them).
PASSIVE_JOINTS_SHOWN = 24

# the subspaces of a passive analysis, with what they are
_SPACES = (("controlled", "object motions the motors drive"),
           ("uncontrolled", "object motions with every motor still"),
           ("internal", "passive joint motions with the object and the motors still"),
           ("actuated_redundant", "motor motions that leave the object still"))


def analysis_passive(a: Any) -> PassiveAnalysis | str | None:
    """The passive analysis an analysis display shows: None without passive joints,
    a sentence instead when the system is too large to compute it for a display.

    Example
    -------
    >>> from coopkin_sym import load
    >>> analysis_passive(load("paper-case1-hard").analyze()) is None
    True
    """
    if not a.model.passive_joints:
        return None
    if a.r > PASSIVE_JOINTS_SHOWN:
        return (f"Passive-joint numbers: not computed for the display ({a.r} joints); "
                "analysis.passive gives them.")
    return a.passive


def passive_numbers_table(p: PassiveAnalysis) -> str:
    """The passive-joint numbers with their meanings as an HTML table.

    Example
    -------
    >>> from coopkin_sym import load
    >>> '<td style="text-align:left">Nco</td>' in passive_numbers_table(
    ...     load("five-bar").analyze("L=1").passive)
    True
    """
    values = p.numbers.as_dict()
    rows = [[escape(k), escape(values[k]), escape(PASSIVE_WORDS[k])]
            for k in PASSIVE_NUMBER_NAMES]
    return table(["number", "value", "meaning"], rows, centered=(1,))


def _said(p: PassiveAnalysis) -> list[str]:
    """The sentences of ``coopkin analyze`` about the passive joints, without dashes."""
    return [line[2:] for line in passive_lines(p)[2:]]


def passive_section(p: PassiveAnalysis) -> list[str]:
    """The parts an analysis view adds for its passive joints (HTML)."""
    return [f"<p><strong>{escape(passive_lines(p)[0])}</strong></p>",
            passive_numbers_table(p), bullet_list(_said(p))]


def _space_html(name: str, words: str, matrix: sp.Matrix) -> str:
    title = f"<p><strong>{name}</strong> ({matrix.rows} x {matrix.cols}): {escape(words)}"
    if matrix.cols == 0:
        return f"{title}: none</p>"
    tex = sp.latex(matrix)
    if typesets(matrix, tex):
        return f"{title}</p>{math_html(tex)}"
    return f"{title}</p><pre>{escape(sp.sstr(matrix))}</pre>"


def passive_html(p: PassiveAnalysis) -> str:
    """A passive-joint analysis as HTML: the joints, the numbers with their meanings,
    what they say, and the subspaces (typeset when small).

    Example
    -------
    >>> from coopkin_sym import load
    >>> "2 independent motor velocities keep every contact" in passive_html(
    ...     load("five-bar").analyze("L=1").passive)
    True
    """
    return div([*passive_section(p),
                *(_space_html(name, words, getattr(p, name)) for name, words in _SPACES)])


def passive_pretty(p: PassiveAnalysis) -> str:
    """The text IPython prints: the ``repr`` and what ``coopkin analyze`` prints
    about the passive joints.

    Example
    -------
    >>> from coopkin_sym import load
    >>> print(passive_pretty(load("five-bar").analyze("L=1").passive).splitlines()[1])
      Passive joints: q2, q4 (actuated: q1, q3)
    """
    return "\n".join([repr(p), *("  " + line for line in passive_lines(p))])


def _batch_head(r: BatchResult) -> str:
    return f"Item {r.index}: {r.source} at {r.at or 'home'}"


def batch_html(r: BatchResult) -> str:
    """One result of a batch as HTML: the item, its numbers with their meanings and
    the grasp classes, or its error.

    Example
    -------
    >>> from coopkin_sym.analysis.numbers import Numbers
    >>> page = batch_html(BatchResult(0, "five-bar", None, Numbers(3, 3, 1, 0, 2, 0, 0)))
    >>> "Item 0: five-bar at home" in page, "graspable (Ng = 2)" in page
    (True, True)
    """
    parts = [f"<p><strong>{escape(_batch_head(r))}</strong></p>"]
    if r.error is not None:
        parts.append(f"<p>Error: {escape(r.error)}</p>")
    elif r.numbers is not None:
        parts += [numbers_table(r.numbers), f"<p>{escape(classes_text(r.numbers))}</p>"]
    if r.document is not None:
        parts.append("<p>With its JSON document (<code>.document</code>).</p>")
    return div(parts)


def batch_pretty(r: BatchResult) -> str:
    """The text IPython prints: the ``repr`` and, when computed, the numbers and the
    grasp classes.

    Example
    -------
    >>> from coopkin_sym.analysis.numbers import Numbers
    >>> print(batch_pretty(BatchResult(0, "five-bar", None, Numbers(3, 3, 1, 0, 2, 0, 0))))
    <BatchResult 0 five-bar: Nm=3 Nc=3 Ni=1 Nr=0 Ng=2 Nd=0 Nh=0>
      Nm = 3  Nc = 3  Ni = 1  Nr = 0  Ng = 2  Nd = 0  Nh = 0
      Grasp classes: indeterminate (Ni = 1), graspable (Ng = 2)
    """
    lines = [repr(r)]
    if r.numbers is not None and r.error is None:
        values = r.numbers.as_dict()
        lines += ["  " + "  ".join(f"{k} = {values[k]}" for k in NUMBER_NAMES),
                  "  " + classes_text(r.numbers)]
    return "\n".join(lines)


def _certificate_rows(cert: Certificate) -> list[list[str]]:
    rows = []
    for kind, table_ in (("depth", cert.depths), ("chart", cert.charts)):
        for name, entry in table_.items():
            why = entry.get("why")
            rows.append([escape(f"{kind} {name}"),
                         "yes" if entry.get("certified") else "<strong>no</strong>",
                         escape(entry.get("tests", 0)), escape(entry.get("failed", 0)),
                         escape(check_text(why) if why is not None else "")])
    return rows


def certificate_html(cert: Certificate) -> str:
    """A completeness certificate as HTML: its verdict, and depth by depth and chart by
    chart whether it is certified, how many tests, how many failed, and why not.

    Example
    -------
    >>> from coopkin_sym import load
    >>> locus = load("paper-case1-hard").locus(certify=True)
    >>> "hard/hard</strong>: complete (certified)</p>" in certificate_html(locus.certificate)
    True
    """
    return div([f"<p><strong>Completeness of the locus of {escape(cert.system)}</strong>"
                f": {escape(certificate_summary(cert))}</p>",
                table(["where", "certified", "tests", "failed", "why not"],
                      _certificate_rows(cert), centered=(1, 2, 3))])


def certificate_pretty(cert: Certificate) -> str:
    """The text IPython prints: the ``repr`` and the verdict.

    Example
    -------
    >>> from coopkin_sym import load
    >>> print(certificate_pretty(load("paper-case1-hard").locus(certify=True).certificate))
    <Certificate paper case 1, hard/hard: certified; 46 tests, 0 not certified>
      complete (certified)
    """
    return f"{repr(cert)}\n  {certificate_summary(cert)}"


def verification_html(v: Verification) -> str:
    """An independent check of a locus as HTML: the verdict and what was checked (the
    lines ``coopkin locus --verify`` prints).

    Example
    -------
    >>> from coopkin_sym import load
    >>> v = load("paper-case1-hard").locus(verify=True).verification
    >>> "Verification: passed (0 uncovered points, 0 unsound components)" in (
    ...     verification_html(v))
    True
    """
    lines = summary_lines(v)
    return div([f"<p><strong>{escape(lines[0])}</strong> ({escape(v.system)})</p>",
                bullet_list([line.strip() for line in lines[1:]])])


def verification_pretty(v: Verification) -> str:
    """The text IPython prints: the ``repr`` and what was checked."""
    return "\n".join([repr(v), *summary_lines(v)[1:]])
