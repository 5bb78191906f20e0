"""The contact-model registry: every consumer reads it, so one more entry is a new
contact model for model files, the rows of H (kinematics and sweeps), the words and
the pictures, with no other edit."""

from __future__ import annotations

import copy

import pytest
import sympy as sp

from coopkin_sym import load
from coopkin_sym.analysis import kinematics
from coopkin_sym.analysis.sweep import chains
from coopkin_sym.analysis.sweep.compiled import compile_system
from coopkin_sym.errors import ArgumentError, CoopkinError, ModelError
from coopkin_sym.exact.sympy_bridge import matrix_to_sympy, ratfunc_to_sympy
from coopkin_sym.model import contacts
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.contacts import REGISTRY, ContactKind, contact_kind, register
from coopkin_sym.model.model import CONTACT_MODELS, load_model
from coopkin_sym.present.sentences import contact_phrase, contact_words

#: A contact model that is not shipped: it keeps the relative velocity and the spin
#: along the normal only (spatial), or v.n and w_z (planar).
SPINNING = ContactKind("spinning", ("normal-spin",), ("v.n", "w.n"), ("v.n", "w_z"),
                       "spinning point", "*")

CASE1 = {
    "name": "two one-link arms", "parameters": ["L"],
    "arms": [
        {"name": "a1", "joints": [
            {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]},
        {"name": "a2", "joints": [
            {"name": "q2", "type": "revolute", "axis": [0, 0, 1], "point": ["L", 0, 0]}]}],
    "contacts": [
        {"name": "c1", "link": "a1/1", "point": [0, "L", 0], "normal": [1, 0, 0],
         "model": "normal-spin"},
        {"name": "c2", "link": "a2/1", "point": ["L", "L", 0], "normal": [-1, 0, 0],
         "model": "hard"}],
}


@pytest.fixture
def spinning(monkeypatch):
    """The registry with :data:`SPINNING` registered (removed after the test)."""
    monkeypatch.setattr(contacts, "REGISTRY", dict(REGISTRY))
    register(SPINNING)
    return SPINNING


def _tree(planar: bool = False) -> dict:
    tree = copy.deepcopy(CASE1)
    if planar:
        tree["planar"] = True
    return tree


# --- the shipped entries -------------------------------------------------------------


def test_the_shipped_models_and_their_rows():
    assert CONTACT_MODELS == ("complete", "soft", "hard", "frictionless")
    assert tuple(REGISTRY) == CONTACT_MODELS
    assert [(k.rows(planar=False), k.rows(planar=True)) for k in REGISTRY.values()] == [
        (6, 3), (4, 0), (3, 2), (1, 1)]
    assert [k.needs_normal for k in REGISTRY.values()] == [False, True, False, True]
    assert [k.planar is None for k in REGISTRY.values()] == [False, True, False, False]


def test_every_registered_model_has_words_and_a_marker():
    from coopkin_sym.present.draw import contact_marker
    words = [contact_words(name) for name in REGISTRY]
    assert words == ["complete constraint", "soft finger", "hard finger", "frictionless"]
    assert len(set(words)) == len(words)
    markers = [contact_marker(name) for name in REGISTRY]
    assert markers == ["s", "D", "o", "^"]


def test_a_model_without_words_marker_or_sound_rows_is_refused():
    with pytest.raises(ArgumentError, match="words and a marker are required"):
        ContactKind("mute", (), ("v_x",), None, "", "x")
    with pytest.raises(ArgumentError, match="words and a marker are required"):
        ContactKind("blank", (), ("v_x",), None, "blank", "")
    with pytest.raises(ArgumentError, match="spatial components"):
        ContactKind("odd", (), ("v_q",), None, "odd", "x")
    with pytest.raises(ArgumentError, match="planar components"):
        ContactKind("odd", (), ("v_x",), ("w.n",), "odd", "x")
    with pytest.raises(ArgumentError, match="in the order"):
        ContactKind("odd", (), ("w_z", "v_x"), None, "odd", "x")
    with pytest.raises(ArgumentError, match="already registered"):
        register(ContactKind("other", ("hard",), ("v_x",), None, "other", "x"))
    assert issubclass(ArgumentError, CoopkinError)


def test_words_of_an_unknown_model_are_an_error():
    with pytest.raises(ArgumentError, match="no words for the contact model 'sticky'"):
        contact_words("sticky")


# --- one more entry, and nothing else ------------------------------------------------


def test_a_new_model_is_read_from_model_files_by_name_or_alias(spinning):
    m = load_model(_tree())
    assert [c.model for c in m.contacts] == ["spinning", "hard"]
    tree = _tree()
    tree["contacts"][0]["model"] = "spinning"
    assert load_model(tree).contacts == m.contacts
    del tree["contacts"][0]["normal"]
    with pytest.raises(ModelError) as info:
        load_model(tree)
    assert info.value.problems == ["contacts[0].normal: required for a spinning contact"]
    tree["contacts"][0]["model"] = "rigid"
    with pytest.raises(ModelError) as info:
        load_model(tree)
    assert info.value.problems == [
        "contacts[0].model: unknown contact model 'rigid' (expected complete, soft, hard, "
        "frictionless or spinning)"]


def test_without_the_entry_the_model_is_unknown():
    with pytest.raises(ModelError, match="unknown contact model 'normal-spin'"):
        load_model(_tree())


def test_a_new_model_has_its_rows_in_h(spinning):
    kin = kinematics.build(load_model(_tree()), Configuration())
    assert kin.row_labels == ["c1: v.n", "c2: v_x", "c2: v_y", "c2: v_z", "c1: w.n"]
    assert kin.row_contacts == [0, 1, 1, 1, 0]
    h = [[str(ratfunc_to_sympy(x, kin.symbols)) for x in row] for row in kin.H]
    assert h[0] == ["1", "0", "0", "0", "0", "0"] + ["0"] * 6
    assert h[4] == ["0"] * 6 + ["1", "0", "0", "0", "0", "0"]
    assert chains.row_contacts(load_model(_tree())) == [0, 1, 1, 1, 0]


def test_a_new_model_has_its_planar_rows(spinning):
    model = load_model(_tree(planar=True))
    kin = kinematics.build(model, Configuration())
    assert kin.row_labels == ["c1: v.n", "c2: v_x", "c2: v_y", "c1: w_z"]
    assert kin.row_contacts == [0, 1, 1, 0]
    h = [[str(ratfunc_to_sympy(x, kin.symbols)) for x in row] for row in kin.H]
    assert h == [["1", "0", "0", "0", "0", "0"], ["0", "0", "1", "0", "0", "0"],
                 ["0", "0", "0", "1", "0", "0"], ["0", "0", "0", "0", "1", "0"]]
    assert chains.row_contacts(model) == [0, 1, 1, 0]


def _sympy_rows(rows, width: int) -> sp.Matrix:
    return sp.Matrix(len(rows), width, [sp.Rational(int(x.p), int(x.q))
                                        for row in rows for x in row])


@pytest.mark.parametrize("planar", [False, True])
def test_the_sweep_rows_of_a_new_model_are_the_kinematics(spinning, planar):
    """The rows of the sweeps (point by point, and the compiled numbers) are those of
    the kinematics, at q1 = 2 atan(1/3), q2 = pi/2, L = 2."""
    model = load_model(_tree(planar))
    chain = chains.ChainQ(chains.chain_data(model, Configuration.parse(model, "L=2"),
                                            ("q1", "q2")))
    rows = chain.rows(chains.RationalField(), [(1, 3), (1, 1)])
    text = "q1=2*atan(1/3),q2=pi/2,L=2"
    kin = kinematics.build(model, Configuration.parse(model, text))
    width = model.object_dim + 2
    q = matrix_to_sympy(kin.Q, kin.ring, kin.symbols, (len(kin.Q), width))
    assert _sympy_rows(rows, width) == q
    compiled = compile_system(model, model.joint_names, "L=2")
    assert compiled.numbers("q1=2*atan(1/3),q2=pi/2") == load(_tree(planar)).analyze(
        text).numbers
    assert compiled._grasp_bound() == (3 if planar else 5)   # min(rows, object dim)


def test_a_new_model_has_words_and_is_drawn(spinning):
    from coopkin_sym.present.draw import draw_system
    assert contact_words("spinning") == "spinning point"
    assert contact_phrase("spinning") == "spinning point contact"
    fig = draw_system(load(_tree()))
    (dot,) = [a for a in fig.axes[0].get_children() if a.get_gid() == "contact:c1"]
    assert dot.get_marker() == "*"
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "spinning point contact" in legend and "hard finger contact" in legend


def test_a_new_model_without_a_planar_form_is_refused_in_the_plane(monkeypatch):
    monkeypatch.setattr(contacts, "REGISTRY", dict(REGISTRY))
    register(ContactKind("twisting", (), ("v_x", "v_y", "v_z", "w.n"), None, "twisting",
                         "P", no_planar="it twists out of the plane"))
    tree = _tree(planar=True)
    tree["contacts"][0]["model"] = "twisting"
    with pytest.raises(ModelError) as info:
        load_model(tree)
    assert info.value.problems == [
        "contacts[0].model: a twisting contact has no planar model (it twists out of the "
        "plane); use complete, hard or frictionless"]
    assert contact_kind("twisting").rows(planar=True) == 0
