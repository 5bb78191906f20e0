"""Every public result shows like an :class:`Analysis`: a one-line ``repr`` with its
numbers, IPython's text, and an HTML view that states the exact numbers; an analysis
with passive joints shows the passive-joint numbers ``coopkin analyze`` prints.
"""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

import coopkin_sym
from coopkin_sym.analysis.batch import BatchResult
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.cli import app
from coopkin_sym.present.passive import PASSIVE_WORDS
from coopkin_sym.present.result_display import PASSIVE_JOINTS_SHOWN
from tests.present.test_display import parse_html

PASSIVE = {"Na": 2, "Np": 2, "Nco": 2, "Nuo": 1, "Npi": 0, "Nar": 0, "Nam": 2}
PASSIVE_LINE = "Na = 2  Np = 2  Nco = 2  Nuo = 1  Npi = 0  Nar = 0  Nam = 2"


@pytest.fixture(scope="module")
def five_bar():
    return coopkin_sym.load("five-bar").analyze()


@pytest.fixture(scope="module")
def printed() -> list[str]:
    """The passive-joint lines of ``coopkin analyze five-bar``."""
    result = CliRunner().invoke(app, ["analyze", "five-bar"])
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    start = lines.index("Passive joints: q2, q4 (actuated: q1, q3)")
    end = lines.index("", start)
    assert lines[start + 1] == PASSIVE_LINE
    return lines[start:end]


def test_the_analysis_html_has_what_the_cli_prints_about_passive_joints(five_bar, printed):
    parsed = parse_html(five_bar._repr_html_())
    text = "".join(parsed.text)
    assert printed[0] in text
    for k, v in PASSIVE.items():
        assert [k, str(v), PASSIVE_WORDS[k]] in parsed.rows, k
    for sentence in printed[2:]:
        assert sentence.startswith("- ") and sentence[2:] in text


def test_the_analysis_text_and_latex_have_the_passive_numbers(five_bar):
    from IPython.lib.pretty import pretty

    assert pretty(five_bar).splitlines()[3] == "  Passive: " + PASSIVE_LINE
    assert (r"\text{Passive-joint numbers: Na = 2 Np = 2 Nco = 2 Nuo = 1 Npi = 0 Nar = 0 "
            r"Nam = 2}") in five_bar._repr_latex_()
    # every joint actuated: nothing about passive joints
    case1 = coopkin_sym.load("paper-case1-hard").analyze()
    assert "Passive" not in case1._repr_html_() and "Passive" not in pretty(case1)


def test_a_large_system_does_not_compute_its_passive_numbers_for_a_display(
        five_bar, monkeypatch):
    from coopkin_sym.present import result_display

    monkeypatch.setattr(result_display, "PASSIVE_JOINTS_SHOWN", 3)
    a = coopkin_sym.load("five-bar").analyze("L=1")
    page = a._repr_html_()
    assert ("Passive-joint numbers: not computed for the display (4 joints); "
            "analysis.passive gives them.") in page
    assert "passive" not in vars(a)
    assert PASSIVE_JOINTS_SHOWN == 24


def test_passive_analysis_shows_its_numbers_and_subspaces(five_bar, printed):
    from IPython.lib.pretty import pretty

    p = five_bar.passive
    assert repr(p) == ("<PassiveAnalysis passive q2, q4 (actuated q1, q3): Na=2 Np=2 Nco=2 "
                       "Nuo=1 Npi=0 Nar=0 Nam=2>")
    assert pretty(p).splitlines() == [repr(p), *("  " + line for line in printed)]
    page = p._repr_html_()
    parsed = parse_html(page)
    for k, v in PASSIVE.items():
        assert [k, str(v), PASSIVE_WORDS[k]] in parsed.rows, k
    text = "".join(parsed.text)
    assert r"$$\left[\begin{matrix}2 L\\0\\1\end{matrix}\right]$$" in text  # uncontrolled
    assert ("internal (4 x 0): passive joint motions with the object and the motors "
            "still: none") in text
    assert p._repr_latex_() is None


def test_batch_results_show_their_numbers_or_their_error():
    from IPython.lib.pretty import pretty

    good, bad = coopkin_sym.load("five-bar").analyze_many(["q1=0", "q9=1"])
    assert repr(good) == ("<BatchResult 0 five-bar linkage with passive elbows at q1=0: "
                          "Nm=3 Nc=3 Ni=1 Nr=0 Ng=2 Nd=0 Nh=0>")
    assert pretty(good).splitlines()[1:] == [
        "  Nm = 3  Nc = 3  Ni = 1  Nr = 0  Ng = 2  Nd = 0  Nh = 0",
        "  Grasp classes: indeterminate (Ni = 1), graspable (Ng = 2)"]
    parsed = parse_html(good._repr_html_())
    assert [r[:2] for r in parsed.rows[1:]] == [
        ["Nm", "3"], ["Nc", "3"], ["Ni", "1"], ["Nr", "0"], ["Ng", "2"], ["Nd", "0"],
        ["Nh", "0"]]
    text = "".join(parse_html(bad._repr_html_()).text)
    assert text == ("Item 1: five-bar linkage with passive elbows at q9=1\nError: --at q9: "
                    "unknown name 'q9' (known: q1, q2, q3, q4, L)")
    assert pretty(bad) == repr(bad)
    home = BatchResult(3, "x", None, Numbers(2, 2, 1, 0, 1, 4, 0), document={"a": 1})
    assert "Item 3: x at home" in home._repr_html_()
    assert "With its JSON document" in home._repr_html_()


def test_certificate_and_verification_show_their_verdicts():
    from IPython.lib.pretty import pretty

    locus = coopkin_sym.load("paper-case1-hard").locus(certify=True, verify=True)
    cert, check = locus.certificate, locus.verification
    assert repr(cert) == ("<Certificate paper case 1, hard/hard: certified; 46 tests, "
                          "0 not certified>")
    assert pretty(cert) == repr(cert) + "\n  complete (certified)"
    parsed = parse_html(cert._repr_html_())
    assert parsed.rows[1:3] == [["depth 0", "yes", "31", "0", ""],
                                ["depth 1", "yes", "15", "0", ""]]
    assert ["chart q1 = pi", "yes", "4", "0", ""] in parsed.rows
    assert repr(check) == ("<Verification paper case 1, hard/hard: passed (0 uncovered "
                           "points, 0 unsound components)>")
    text = "".join(parse_html(check._repr_html_()).text)
    assert text.startswith("Verification: passed (0 uncovered points, 0 unsound "
                           "components) (paper case 1, hard/hard)")
    assert ("components: 5; witnesses checked: 5; with no witness and no point checked: 0"
            in text)
    assert pretty(check).splitlines()[3] == ("  components: 5; witnesses checked: 5; with "
                                             "no witness and no point checked: 0")
    assert cert._repr_latex_() is None and check._repr_latex_() is None
