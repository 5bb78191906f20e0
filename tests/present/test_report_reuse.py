"""Writing a report reuses what the search holds: the pictures of the system at the
witnesses are drawn from the exact analyses made there, none is made again."""

from __future__ import annotations

import warnings

from coopkin_sym import load
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.present.report import write_report


def test_write_report_makes_no_analysis_at_rational_witnesses(tmp_path, monkeypatch):
    system = load("paper-case1-hard")
    locus = system.locus()
    made = []
    init = Analysis.__init__

    def count(self, *args, **kwargs):
        made.append(args[1] if len(args) > 1 else kwargs.get("config"))
        init(self, *args, **kwargs)

    monkeypatch.setattr(Analysis, "__init__", count)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        written = write_report(locus, tmp_path / "r.md", system)
    assert made == []
    # the four rational witnesses and the algebraic one are drawn, with the plot
    assert sorted(p.name for p in written) == [
        "r.md", "r_q1_q2.png", *(f"r_system_component_{k}.png" for k in range(1, 6))]
