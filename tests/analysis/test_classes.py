"""Grasp classes, checked against the nullspaces they name, computed here with SymPy
over the rationals: redundant ``N(J)``, indeterminate ``N(G^T)``, graspable ``N(G)``,
defective ``N(J^T)``, hyperstatic ``N(G) & N(J^T)`` (``G^T = H G^T``, ``J = H D``)."""

from __future__ import annotations

import json
import random

import pytest
import sympy as sp
from test_planar import at_text, random_planar_system, random_point

import coopkin_sym
from coopkin_sym.analysis.classes import GRASP_CLASSES, class_changes, grasp_classes
from coopkin_sym.present.classes import class_changes_text, classes_text
from coopkin_sym.present.report import locus_from_json, render_json, render_markdown
from coopkin_sym.present.text import analysis_json, analysis_text


def classes_from_nullspaces(q: sp.Matrix, dim: int) -> tuple[str, ...]:
    gt, j = q[:, :dim], q[:, dim:]
    left_g = gt.T.nullspace()              # internal forces: y with y^T G^T = 0
    left_j = j.T.nullspace() if j.cols else [sp.eye(q.rows).col(k) for k in range(q.rows)]
    both = q.T.nullspace()                 # y in N(G) and N(J^T) at once
    held = {"redundant": bool(j.nullspace()) if j.cols else False,
            "indeterminate": bool(gt.nullspace()),
            "graspable": bool(left_g), "defective": bool(left_j), "hyperstatic": bool(both)}
    return tuple(c for c in GRASP_CLASSES if held[c])


@pytest.mark.parametrize("seed", range(1, 24, 2))
def test_classes_are_the_nullspaces_they_name(seed):
    raw = random_planar_system(seed)
    system = coopkin_sym.load(raw)
    rng = random.Random(seed)
    for special in (False, True, True):
        a = system.analyze(at_text(raw, random_point(raw, rng, special)))
        assert a.classes == classes_from_nullspaces(a.Q, 3)


@pytest.mark.parametrize("name, at", [
    ("paper-case1-hard", None), ("paper-case1-hard", "q1=pi/2,q2=pi/2"),
    ("paper-case1-soft", "L=2"), ("paper-case2-hard", "L=1"),
    ("paper-case2-complete", "L=1"), ("quadruped-standing", None),
])
def test_classes_of_spatial_examples(name, at):
    a = coopkin_sym.load(name).analyze(at)
    assert a.classes == classes_from_nullspaces(a.Q, 6)


def test_paper_case1_classes_and_their_words():
    a = coopkin_sym.load("paper-case1-hard").analyze()
    assert a.classes == ("indeterminate", "graspable", "defective")
    assert classes_text(a.numbers) == ("Grasp classes: indeterminate (Ni = 1), graspable "
                                       "(Ng = 1), defective (Nd = 4)")
    assert classes_text(a.numbers) in analysis_text(a).splitlines()
    assert json.loads(analysis_json(a))["classes"] == list(a.classes)
    irrational = coopkin_sym.load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")
    assert json.loads(analysis_json(irrational))["classes"] == list(
        grasp_classes(irrational.numbers))


def test_classes_change_where_the_numbers_do():
    fingers = coopkin_sym.load("planar-two-fingers")
    generic, stretched = fingers.analyze(), fingers.analyze("q2=pi/2")
    assert generic.classes == ("graspable",)
    assert stretched.classes == ("redundant", "graspable", "defective")
    assert class_changes(stretched.numbers, generic.numbers) == {"redundant": True,
                                                                 "defective": True}
    assert class_changes_text(stretched.numbers, generic.numbers) == (
        "becomes redundant and defective")
    assert class_changes_text(generic.numbers, stretched.numbers) == (
        "is no longer redundant and defective")
    assert class_changes_text(generic.numbers, generic.numbers) == "as generic"


def test_locus_reports_show_classes_and_read_back():
    system = coopkin_sym.load("paper-case1-planar")
    locus = system.locus()
    text = render_json(locus)
    data = json.loads(text)
    assert data["generic_classes"] == ["graspable", "defective"]
    for comp, c in zip(data["components"], locus.components, strict=True):
        assert comp["classes"] == list(grasp_classes(c.numbers))
    # the component at q1 = q2 = -pi/2 (the first before the components had a canonical
    # order)
    (point,) = [comp for comp in data["components"]
                if comp["equations"] == ["t_q1 + 1", "t_q2 + 1"]]
    assert "hyperstatic" in point["classes"]
    again = locus_from_json(text)
    assert [c.numbers for c in again.components] == [c.numbers for c in locus.components]
    md = render_markdown(locus)
    assert "Grasp classes: graspable (Ng = 1), defective (Nd = 2)." in md
    assert "- **Grasp classes:** graspable, defective, hyperstatic (becomes hyperstatic)" in md
