"""A completeness certificate (:class:`~coopkin_sym.analysis.locus.certify.Certificate`)
in words: its one-line summary, a locus's completeness, and the JSON a locus report
carries (and reads back, :class:`CertificateRead`).

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.certify import certify_locus
>>> system = load("paper-case1-hard")
>>> certificate_summary(certify_locus(system, system.locus(), timeout=60))
'complete (certified)'
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from coopkin_sym.analysis.locus.certify import Certificate, Check
from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.present.remarks import remark_text, remark_texts

__all__ = ["CERTIFIED", "NOT_CERTIFIED", "CertificateRead", "certificate_json",
           "certificate_summary", "check_text", "completeness_text"]

#: The summary of a certificate that proves its locus complete.
CERTIFIED = "complete (certified)"
#: What a locus without a completeness certificate says about its completeness.
NOT_CERTIFIED = "completeness not certified (run with --certify)"


@dataclass
class CertificateRead(Certificate):
    """A certificate read back from a report: its tests not certified (every test when
    the report lists them all), its reasons as the report's sentences, and what the
    report states of the rest (``summary``, the number of ``tests``, how many each
    backend certified).

    Example
    -------
    >>> read = CertificateRead("demo", True, summary=CERTIFIED, tests=3,
    ...                        backends={"flint": 3})
    >>> certificate_summary(read), read.certified_by()
    ('complete (certified)', {'flint': 3})
    """

    summary: str = ""
    tests: int = 0
    backends: dict[str, int] = field(default_factory=dict)

    def certified_by(self) -> dict[str, int]:
        return dict(self.backends)

    def failures(self) -> list[Check | Remark | str]:
        if self.certified:
            return []
        failed: list[Check | Remark | str] = [c for c in self.checks if not c.certified]
        return failed or [self.summary.removeprefix("not certified: ")]


def check_text(why: Check | Remark | str | None) -> str:
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
    if isinstance(cert, CertificateRead):
        return cert.summary
    failing = cert.failures()
    if not failing:
        return CERTIFIED if cert.certified else "not certified: no test was run"
    more = f" (and {len(failing) - 1} more)" if len(failing) > 1 else ""
    return f"not certified: {check_text(failing[0])}{more}"


def completeness_text(locus: Locus) -> str:
    """Whether ``locus`` is proved complete, in one line: ``"complete (certified)"``,
    ``"not certified: <why>"``, or that no certificate was made.

    Example
    -------
    >>> completeness_text(Locus("demo", [], "", {}))
    'completeness not certified (run with --certify)'
    """
    if locus.certificate is None:
        return NOT_CERTIFIED
    return certificate_summary(locus.certificate)


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
    tests = cert.tests if isinstance(cert, CertificateRead) else len(cert.checks)
    return {"system": cert.system, "certified": cert.certified,
            "summary": certificate_summary(cert),
            "depths": {str(k): _table_json(v) for k, v in sorted(cert.depths.items())},
            "charts": {k: _table_json(v) for k, v in cert.charts.items()},
            "tests": tests, "certified_by": cert.certified_by(),
            "failed": [_check_json(c) for c in shown if not c.certified],
            **({"checks": [_check_json(c) for c in shown]} if every_check else {}),
            "notes": remark_texts(cert.notes), "seconds": cert.seconds}


def certificate_read(data: Any) -> CertificateRead:
    """A certificate back from :func:`certificate_json` data (validated by
    :mod:`coopkin_sym.present.report_input`: attributes as its keys).

    Example
    -------
    >>> from types import SimpleNamespace as N
    >>> data = N(system="demo", certified=True, summary=CERTIFIED, depths={}, charts={},
    ...          tests=0, certified_by={}, failed=[], checks=None, notes=[], seconds=0)
    >>> certificate_read(data).certified
    True
    """
    def check(c) -> Check:
        return Check(c.chart, c.depth, c.inside, c.matrix, c.kind, c.certified,
                     c.why or None, c.backend, c.seconds)

    def table(entry) -> dict:
        return {"certified": entry.certified, "why": entry.why or None,
                "tests": entry.tests, "failed": entry.failed}

    checks = data.checks if data.checks is not None else data.failed
    return CertificateRead(
        data.system, data.certified,
        depths={int(k): table(v) for k, v in data.depths.items()},
        charts={k: table(v) for k, v in data.charts.items()},
        checks=[check(c) for c in checks], notes=list(data.notes), seconds=data.seconds,
        summary=data.summary, tests=data.tests, backends=dict(data.certified_by))
