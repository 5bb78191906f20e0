"""A locus report as JSON, for programs (:meth:`Locus.to_json` with the sentences of
the components and remarks), and read back.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Locus
>>> json.loads(render_json(Locus("demo", [], "", {"Nm": 1})))["system"]
'demo'
"""

from __future__ import annotations

import json
from collections.abc import Mapping

from coopkin_sym.analysis.classes import grasp_classes
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.errors import ReportError
from coopkin_sym.present.certificate import certificate_json, completeness_text
from coopkin_sym.present.remarks import remark_text, remark_texts
from coopkin_sym.present.report.words import _has_classes
from coopkin_sym.present.report_input import ReportInputError, validate_report
from coopkin_sym.present.sentences import component_sentences


def _with_meaning(data: dict, component: Component) -> dict:
    """A component's JSON with its sentences as ``"meaning"``, after ``"changes"``, and
    how its numbers were decided in words."""
    out = {}
    for key, value in data.items():
        out[key] = value
        if key == "changes":
            out["meaning"] = component_sentences(component)
    out["decided"] = remark_text(component.decided)
    if _has_classes(component.numbers):
        out["classes"] = list(grasp_classes(component.numbers))
    return out


# the lists of remarks a locus holds, written as sentences
_REMARK_LISTS = ("parameter_conditions", "dropped", "unexplored", "notes")


def render_json(locus: Locus, verification: Mapping | None = None) -> str:
    """The locus as JSON (:meth:`Locus.to_json`), for programs; with a
    ``"verification"`` object when one is given.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> sorted(json.loads(render_json(Locus("demo", [], "", {"Nm": 1}))))[:4]
    ['certificate', 'completeness', 'components', 'dropped']
    """
    data = _worded_certificate(locus.to_json(), locus)
    for key in _REMARK_LISTS:
        data[key] = remark_texts(getattr(locus, key))
    data["components"] = [_with_meaning(d, c)
                          for d, c in zip(data["components"], locus.components, strict=True)]
    if _has_classes(locus.generic):
        data["generic_classes"] = list(grasp_classes(locus.generic))
    if locus.locked is not None:
        data["locked"] = json.loads(render_json(locus.locked))
    if verification is not None:
        data["verification"] = dict(verification)
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def _worded_certificate(data: dict, locus: Locus) -> dict:
    """``data`` with the completeness in words (after ``seconds``) and the certificate's
    JSON (:func:`~coopkin_sym.present.certificate.certificate_json`)."""
    out = {}
    for key, value in data.items():
        if key == "certificate":
            value = None if locus.certificate is None else certificate_json(locus.certificate)
        out[key] = value
        if key == "seconds":
            out["completeness"] = completeness_text(locus)
    return out


def locus_from_json(data: Mapping | str) -> Locus:
    """A :class:`Locus` back from :func:`render_json` (text or parsed), validated like
    a model file: structure, names, and every expression read by the package's parser
    (see :mod:`coopkin_sym.present.report_input`). Nothing in it is ever evaluated.

    Raises
    ------
    ReportError
        One line per problem, each naming the entry.

    Example
    -------
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> locus = Locus("demo", ["t_q1"], "", {"Nm": 1})
    >>> locus_from_json(render_json(locus)) == locus
    True
    """
    try:
        return validate_report(data)
    except ReportInputError as exc:
        raise ReportError(str(exc)) from None
