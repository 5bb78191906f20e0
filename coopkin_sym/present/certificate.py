"""A completeness certificate (:class:`~coopkin_sym.analysis.locus.certify.Certificate`)
in words: its one-line summary and the JSON a locus report carries.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.certify import certify_locus
>>> system = load("paper-case1-hard")
>>> certificate_summary(certify_locus(system, system.locus(), timeout=60))
'complete (certified)'
"""

from __future__ import annotations

from typing import Any

from coopkin_sym.analysis.locus.certify import Certificate, Check
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.present.remarks import remark_text, remark_texts

__all__ = ["CERTIFIED", "certificate_json", "certificate_summary", "check_text"]

#: The summary of a certificate that proves its locus complete.
CERTIFIED = "complete (certified)"


def check_text(why: Check | Remark | None) -> str:
    """A test not certified as ``"<which test>: <why>"``, or a remark's sentence.

    Example
    -------
    >>> check = Check("t chart", 0, None, "Q", "drops", why=Remark.of("cert_never_drops"))
    >>> check_text(check)
    't chart, depth 0, rank of Q: the rank never drops at a real point'
    """
    if isinstance(why, Check):
        return f"{why.where()}: {remark_text(why.why) if why.why is not None else ''}"
    return remark_text(why) if why is not None else ""


def certificate_summary(cert: Certificate) -> str:
    """``"complete (certified)"``, or ``"not certified: <the first reason>"`` with how
    many more there are.

    Example
    -------
    >>> certificate_summary(Certificate("demo", untested_beyond=0))
    'not certified: depths beyond 0 were not tested'
    """
    failing = cert.failures()
    if not failing:
        return CERTIFIED if cert.certified else "not certified: no test was run"
    more = f" (and {len(failing) - 1} more)" if len(failing) > 1 else ""
    return f"not certified: {check_text(failing[0])}{more}"


def _check_json(check: Check) -> dict[str, Any]:
    return {"chart": check.chart, "depth": check.depth, "inside": check.inside,
            "matrix": check.matrix, "kind": check.kind, "certified": check.certified,
            "why": remark_text(check.why) if check.why is not None else "",
            "backend": check.backend, "seconds": check.seconds}


def _table_json(entry: dict) -> dict:
    return {**entry, "why": check_text(entry["why"])}


def certificate_json(cert: Certificate, every_check: bool = False) -> dict:
    """The certificate as JSON data: the summary, per depth, per chart, the tests not
    certified (with ``every_check``, every test) and the notes, in words.

    Example
    -------
    >>> certificate_json(Certificate("demo", certified=True))["summary"]
    'complete (certified)'
    """
    shown = cert.checks if every_check else [c for c in cert.checks if not c.certified]
    return {"system": cert.system, "certified": cert.certified,
            "summary": certificate_summary(cert),
            "depths": {str(k): _table_json(v) for k, v in sorted(cert.depths.items())},
            "charts": {k: _table_json(v) for k, v in cert.charts.items()},
            "tests": len(cert.checks), "certified_by": cert.certified_by(),
            "failed": [_check_json(c) for c in shown if not c.certified],
            **({"checks": [_check_json(c) for c in shown]} if every_check else {}),
            "notes": remark_texts(cert.notes), "seconds": cert.seconds}
