"""The interactive view (:mod:`coopkin_sym.present.interactive`): sliders over exact
joint values, the exact numbers and the picture at the values chosen, each
configuration analyzed once; bad input is one clear error naming the entry.

The last test runs the view in a real Jupyter kernel (nbclient) and reads the widget
state the kernel sends when a slider moves.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

from coopkin_sym import load
from coopkin_sym.errors import ArgumentError, ConfigurationError, MissingDependency

pytest.importorskip("ipywidgets")

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def planar():
    return load("paper-case1-planar")


def test_the_default_sliders_run_over_the_multiples_of_pi_over_12(planar):
    view = planar.interactive(at="L=1")
    options = view.sliders["q1"].options
    assert len(options) == 24 and options[0] == "-11*pi/12" and options[-1] == "pi"
    assert {"0", "pi/12", "pi/2", "-5*pi/12"} <= set(options)
    assert list(view.sliders) == ["q1", "q2"] and view.at == "q1=0,q2=0,L=1"


def test_the_numbers_follow_the_sliders_singular_and_regular(planar):
    """At q1 = q2 = pi/2 the two contacts meet a singular configuration: Nm goes up;
    the view shows what System.analyze says, at every step."""
    view = planar.interactive(at="L=1")
    regular = planar.analyze("q1=0,q2=0,L=1").numbers
    assert view.numbers == regular and view.numbers.Nm == 1
    view.sliders["q1"].value = "pi/2"
    view.sliders["q2"].value = "pi/2"
    singular = planar.analyze("q1=pi/2,q2=pi/2,L=1").numbers
    assert view.at == "q1=pi/2,q2=pi/2,L=1"
    assert view.numbers == singular and (singular.Nm, singular.Nh) == (2, 1)
    assert "at q1=pi/2,q2=pi/2,L=1" in view.table.value
    assert '<td style="text-align:left">Nm</td><td style="text-align:center">2</td>' in (
        view.table.value)
    view.select("q1=-pi/6,q2=pi/6")   # irrational tangents: exact over Q(sqrt(3))
    assert view.numbers == planar.analyze("q1=-pi/6,q2=pi/6,L=1").numbers
    assert view.numbers.Ni == 1 and view.error is None


def test_each_configuration_is_analyzed_and_drawn_once(planar, monkeypatch):
    view = planar.interactive(steps=4, at="L=1")
    calls: list[str] = []
    analyze = type(planar).analyze

    def counted(self, at=None, **kwargs):
        calls.append(at)
        return analyze(self, at, **kwargs)

    monkeypatch.setattr(type(planar), "analyze", counted)
    home = view.picture.value
    assert home[:4] == b"\x89PNG"
    view.sliders["q1"].value = "pi/2"
    moved = view.picture.value
    assert moved != home
    view.sliders["q1"].value = "0"
    view.sliders["q1"].value = "pi/2"
    assert view.picture.value == moved
    assert calls == ["q1=pi/2,q2=0,L=1"]
    assert set(view.cache) == {"q1=0,q2=0,L=1", "q1=pi/2,q2=0,L=1"}


def test_select_moves_several_sliders_with_one_update(planar, monkeypatch):
    view = planar.interactive(steps=4, at="L=1")
    seen: list[str] = []
    computed = view._computed
    monkeypatch.setattr(view, "_computed", lambda at: seen.append(at) or computed(at))
    view.select({"q1": "pi/2", "q2": "pi/2"})
    assert seen == ["q1=pi/2,q2=pi/2,L=1"]


def test_it_shows_as_a_widget_with_the_numbers_where_no_widget_can_be(planar):
    view = planar.interactive(steps=4, at="L=1").select("q1=pi/2,q2=pi/2")
    bundle = view._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["text/plain"] == repr(view) == (
        "<InteractiveView paper case 1, planar, hard/hard at q1=pi/2,q2=pi/2,L=1: "
        "Numbers(Nm=2, Nc=2, Ni=0, Nr=0, Ng=1, Nd=2, Nh=1)>")
    assert "at q1=pi/2,q2=pi/2,L=1" in bundle["text/html"]


def test_given_values_and_a_subset_of_joints(planar):
    view = planar.interactive("q2", at="q1=pi/2,L=1",
                              values={"q2": ["0", "pi/2", "2*atan(1/3)"]})
    assert list(view.sliders) == ["q2"]
    assert view.sliders["q2"].options == ("0", "pi/2", "2*atan(1/3)")
    view.sliders["q2"].value = "pi/2"
    assert view.at == "q2=pi/2,q1=pi/2,L=1"
    assert view.numbers == planar.analyze("q1=pi/2,q2=pi/2,L=1").numbers


def test_a_prismatic_slider_and_exact_angles_as_values():
    from coopkin_sym.exact.angles import ExactAngle

    case2 = load("paper-case2-hard")
    view = case2.interactive(["q4", "q1"], at="L=1",
                             values={"q1": [ExactAngle(1, 3), "0", "pi/2"]})
    assert view.sliders["q4"].options == ("-1", "-3/4", "-1/2", "-1/4", "0", "1/4", "1/2",
                                          "3/4", "1")
    assert view.sliders["q1"].options == ("2*atan(1/3)", "0", "pi/2")
    view.select("q4=1/2,q1=2*atan(1/3)")
    assert view.at == "q4=1/2,q1=2*atan(1/3),L=1"
    assert view.numbers == case2.analyze("q1=2*atan(1/3),q4=1/2,L=1").numbers


@pytest.mark.parametrize("kwargs, message", [
    ({"joints": ["q9"]}, "joints: unknown joint q9 (joints: q1, q2)"),
    ({"joints": []}, "joints: no joint to give a slider"),
    ({"steps": 1}, "steps: between 2 and 720 values per joint, got 1"),
    ({"steps": "24"}, "steps: an integer number of values per joint, got str"),
    ({"values": {"q1": ["1"]}}, "--at q1"),
    ({"values": {"q1": "pi/2"}}, "values q1: a non-empty list of exact values"),
    ({"values": {"q9": ["0"]}}, "values: q9 has no slider (sliders: q1, q2)"),
    ({"at": "L=-1"}, "--at L: parameters are lengths and must be positive"),
    ({"at": "q1=1"}, "--at q1"),
])
def test_bad_input_is_one_clear_error_naming_the_entry(planar, kwargs, message):
    with pytest.raises((ConfigurationError, ArgumentError)) as info:
        planar.interactive(**kwargs)
    assert message in str(info.value)


def test_the_view_of_something_else_than_a_system_is_refused():
    from coopkin_sym.errors import ArgumentTypeError
    from coopkin_sym.present.interactive import interactive

    with pytest.raises(ArgumentTypeError, match=r"system: expected a System \(coopkin_sym"
                                                r"\.load\(\.\.\.\)\), got str"):
        interactive("paper-case1-planar")


def test_select_refuses_a_value_off_its_slider(planar):
    view = planar.interactive(steps=4, at="L=1")
    with pytest.raises(ConfigurationError, match=r"select q1: pi/12 is not a value of its "
                                                 r"slider \(-pi/2, 0, pi/2, pi\)"):
        view.select("q1=pi/12")
    with pytest.raises(ConfigurationError, match="select L: no slider"):
        view.select("L=2")


def test_without_ipywidgets_the_error_says_what_to_install(planar, monkeypatch):
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    with pytest.raises(MissingDependency, match="needs ipywidgets: pip install ipywidgets"):
        planar.interactive()


def test_an_analysis_that_fails_is_said_in_the_view(planar, monkeypatch):
    from coopkin_sym.errors import NumberError

    view = planar.interactive(steps=4, at="L=1")

    def refused(self, at=None, **kwargs):
        raise NumberError("--at q1", "over the degree budget")

    monkeypatch.setattr(type(planar), "analyze", refused)
    view.sliders["q1"].value = "pi/2"
    assert view.numbers is None and "over the degree budget" in view.error
    assert "Not analyzed: " in view.table.value


@pytest.mark.slow
def test_a_real_kernel_updates_the_numbers_when_a_slider_moves(tmp_path):
    """In a Jupyter kernel the view is a widget; moving a slider from code sends the new
    table (a comm message with the HTML widget's value) with the exact numbers."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    messages: dict[int, list[dict]] = {}

    class Client(nbclient.NotebookClient):
        def process_message(self, msg, cell, cell_index):
            messages.setdefault(cell_index, []).append(msg)
            return super().process_message(msg, cell, cell_index)

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(source) for source in (
        "from coopkin_sym import load\n"
        "view = load('paper-case1-planar').interactive(steps=4, at='L=1')\nview",
        "view.sliders['q1'].value = 'pi/2'\nview.sliders['q2'].value = 'pi/2'\n"
        "view.numbers.Nm")]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]))
    Client(nb, timeout=120, kernel_name="python3",
           resources={"metadata": {"path": str(tmp_path)}}).execute(env=env)
    shown = [m["content"]["data"] for m in messages[0] if m["msg_type"] == "execute_result"]
    assert "application/vnd.jupyter.widget-view+json" in shown[0]
    results = [m["content"]["data"]["text/plain"] for m in messages[1]
               if m["msg_type"] == "execute_result"]
    assert results == ["2"]
    states = [m["content"]["data"].get("state", {}) for m in messages[1]
              if m["msg_type"] == "comm_msg"]
    tables = [s["value"] for s in states if isinstance(s.get("value"), str)
              and "<table>" in s["value"]]
    assert tables and "at q1=pi/2,q2=pi/2,L=1" in tables[-1]
    assert '<td style="text-align:left">Nm</td><td style="text-align:center">2</td>' in (
        tables[-1])
    streams = [m["content"] for m in messages[1] if m["msg_type"] == "stream"]
    assert [s for s in streams if s["name"] == "stderr"] == []
