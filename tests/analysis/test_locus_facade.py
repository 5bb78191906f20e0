"""The methods of a computed locus (coopkin_sym.analysis.locus.facade): certify,
verify, write, plot, table, to_pandas, and System.locus(certify=, verify=)."""

from __future__ import annotations

import json

import pytest

import coopkin_sym
from coopkin_sym.errors import ArgumentError, MissingDependency, NotAvailable, ReportError
from coopkin_sym.present.certificate import completeness_text


@pytest.fixture(scope="module")
def system():
    return coopkin_sym.load("paper-case1-hard")


@pytest.fixture(scope="module")
def locus(system):
    return system.locus()


def test_locus_with_certify_and_verify(system):
    locus = system.locus(certify=True, verify=True)
    assert locus.certified
    assert locus.completeness() == (True, None)
    assert completeness_text(locus) == "complete (certified)"
    assert locus.verification is not None and locus.verification.ok
    assert [c.condition.text for c in locus.components][:2] == ["q1 = -pi/2, q2 = -pi/2",
                                                          "q1 = -pi/2, q2 = pi/2"]


def test_the_system_is_not_part_of_the_data(system, locus):
    assert locus._system is system
    assert "System" not in repr(locus)
    assert "_system" not in json.dumps(locus.to_json())
    again = system.locus()
    assert again.components == locus.components and again._system is system


def test_certify_later_keeps_the_certificate(system):
    locus = system.locus()
    assert not locus.certified
    certificate = locus.certify(timeout=60)
    assert certificate.certified is True
    assert locus.certified and locus.certificate.certified is True


def test_a_locus_read_back_is_given_its_system(system, locus, tmp_path):
    from coopkin_sym.present.report import locus_from_json

    (path,) = locus.write(tmp_path / "locus.json")
    back = locus_from_json(path.read_text())
    with pytest.raises(ArgumentError, match="^Locus.verify: this locus does not know its "
                                            "system"):
        back.verify()
    with pytest.raises(ArgumentError, match="^Locus.certify: system: expected a System"):
        back.certify(system=system.model)
    assert back.verify(system=system, max_points=200, lines=2).ok


@pytest.mark.slow
def test_write_every_format(locus, tmp_path):
    written = locus.write(tmp_path / "r.md")
    assert written[0].name == "r.md" and all(p.exists() for p in written)
    assert [p.name for p in locus.write(tmp_path / "r", "tex")][0] == "r.tex"
    assert locus.write(tmp_path / "r.html", "html")[0].read_text().startswith("<!DOCTYPE")
    data = json.loads(locus.write(tmp_path / "r.json")[0].read_text())
    assert data["generic"]["Nm"] == 2 and len(data["components"]) == 5


def test_write_refuses_a_format_against_the_suffix(locus, tmp_path):
    with pytest.raises(ReportError, match="the format json asks for the suffix .json"):
        locus.write(tmp_path / "r.md", "json")
    with pytest.raises(ReportError, match="unknown report format 'pdf'"):
        locus.write(tmp_path / "r", "pdf")


def test_a_verified_locus_writes_its_verification(system, tmp_path):
    locus = system.locus()
    locus.verify(max_points=200, lines=2)
    data = json.loads(locus.write(tmp_path / "v.json")[0].read_text())
    assert data["verification"]["ok"] is True


def test_plot_and_table(locus):
    fig = locus.plot()
    assert fig.axes
    fig2 = locus.plot(("q1", "q2"))
    assert fig2.axes[0].get_xlabel().startswith("q1")
    rows = locus.table()
    assert len(rows) == 5
    assert rows[0] == {"#": 1, "parent": None, "condition": "q1 = -pi/2, q2 = -pi/2",
                       "kind": "isolated", "depth": 0, "Nm": 3, "Nc": 3, "Ni": 1,
                       "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 1,
                       "changed": ["Nm", "Nc", "Nh"], "real": True,
                       "witness": "q1=-pi/2,q2=-pi/2,L=1"}


def test_to_pandas_or_missing_dependency(locus):
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(MissingDependency, match="pip install pandas"):
            locus.to_pandas()
        return
    frame = locus.to_pandas()
    assert frame["Nm"].tolist() == [row["Nm"] for row in locus.table()]
    assert frame.attrs["generic"]["Nm"] == 2


def test_a_passive_locus_knows_its_locked_system():
    system = coopkin_sym.load("five-bar")
    locus = system.locus(max_depth=0)
    assert locus.locked is not None
    assert locus.locked._system.model.locked == frozenset({"q1", "q3"})
    assert locus.locked._system.model.joint_names == system.joint_names


@pytest.mark.slow
def test_a_passive_locus_has_its_locked_part_certified_and_verified():
    system = coopkin_sym.load("five-bar")
    locus = system.locus(certify=True, verify=True)
    assert locus.locked.certificate is not None and locus.certificate is not None
    assert locus.verification.ok
    assert locus.locked.verification is not None


def test_an_action_nothing_registered_for_is_not_available():
    from coopkin_sym.analysis.renderers import action

    with pytest.raises(NotAvailable, match="^int.plot is not available"):
        action(3, "plot")
