"""The completeness of a locus in a report: its summary line and the certificate's
section (per depth, the tests not certified, its notes).

The one module of the report that reads :attr:`Locus.certificate`.

Example
-------
>>> from coopkin_sym.analysis.locus.types import Locus
>>> _completeness_line(Locus("demo", [], "", {})).spans[0][0]
'strong'
"""

from __future__ import annotations

from coopkin_sym.analysis.locus.types import Locus
from coopkin_sym.present.certificate import certificate_json, completeness_text
from coopkin_sym.present.remarks import grouped_remark_texts
from coopkin_sym.present.report.blocks import Bullets, Paragraph, _h, _t
from coopkin_sym.present.report.formulas import _list_or


def _completeness_line(locus: Locus) -> Paragraph:
    """Whether the locus is proved complete, in the summary."""
    said = completeness_text(locus)
    return Paragraph([("strong", said[:1].upper() + said[1:]), _t(".")]
                     if locus.certificate is None else
                     [_t("Completeness: "), ("strong", said), _t(".")], css="summary")


#: Tests not certified listed one by one in a report (all are in its JSON).
SHOWN_FAILURES = 10


def _certificate_blocks(locus: Locus) -> list:
    """The completeness certificate: per depth, the tests not certified, its notes."""
    out: list = [_h(2, "Completeness certificate", "certificate")]
    if locus.certificate is None:
        said = completeness_text(locus)
        out.append(Paragraph([_t(said[:1].upper() + said[1:]
                                 + ": no proof was made that the components above hold every "
                                   "configuration where the numbers change.")]))
        return out
    cert = certificate_json(locus.certificate)
    tests = cert.get("tests", 0)
    out.append(Paragraph([("strong", cert["summary"]),
                          _t(f" ({tests} exact test{'' if tests == 1 else 's'} in "
                             f"{len(cert.get('charts', {}))} chart"
                             f"{'' if len(cert.get('charts', {})) == 1 else 's'}, "
                             f"{cert.get('seconds', 0):.1f} s).")], css="summary"))  # float-ok
    lines = []
    for depth, entry in cert.get("depths", {}).items():
        n, failed = entry.get("tests", 0), entry.get("failed", 0)
        if entry.get("certified"):
            lines.append([_t(f"Depth {depth}: certified ({n} test{'' if n == 1 else 's'}"
                             + (f"; {entry['why']}" if entry.get("why") else "") + ").")])
        else:
            lines.append([_t(f"Depth {depth}: not certified ({failed} of {n} tests): "
                             f"{entry.get('why', '')}.")])
    if lines:
        out.append(Bullets(lines))
    failed = cert.get("failed", [])
    if failed:
        shown = [[_t(f"{c.get('chart')}, depth {c.get('depth')}"
                     + (f", component #{c['inside'] + 1}" if c.get("inside") is not None
                        else "")
                     + (", rank of " if c.get("kind") == "drops" else ", numbers, rank of ")
                     + f"{c.get('matrix')}: {c.get('why')}")]
                 for c in failed[:SHOWN_FAILURES]]
        more = len(failed) - SHOWN_FAILURES
        out.append(Paragraph([_t(f"Tests not certified ({len(failed)}"
                                 + (f"; the first {SHOWN_FAILURES} here, all in the JSON"
                                    if more > 0 else "") + "):")]))
        out.append(Bullets(shown))
    if cert.get("notes"):
        out.extend(_list_or(grouped_remark_texts(cert["notes"]), ""))
    return out
