"""``coopkin analyze`` prints the numbers first; an interrupt while the rest is
computed stops it and says what was not shown."""

from __future__ import annotations

from typer.testing import CliRunner

import coopkin_sym.present.text as text
from coopkin_sym import load
from coopkin_sym.cli import app


def test_parts_join_to_the_report():
    a = load("paper-case2-hard").analyze(generic=True)
    parts = text.analysis_parts(a)
    assert [name for name, _ in parts] == ["numbers", "sentences", "C11", "C12", "C22",
                                           "C23"]
    joined = "\n".join(line for _, part in parts for line in part())
    assert joined == text.analysis_text(a)


def test_interrupt_after_the_numbers(monkeypatch):
    def interrupted(analysis):
        raise KeyboardInterrupt

    monkeypatch.setattr(text, "sentences", interrupted)
    result = CliRunner().invoke(app, ["analyze", "paper-case1-hard"])
    assert result.exit_code == 130
    assert "Nm = 2  Nc = 2  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 0" in result.output
    assert ("interrupted while computing sentences; not shown: sentences, C11, C12, C22, "
            "C23") in result.output
    assert "C11 (" not in result.output
