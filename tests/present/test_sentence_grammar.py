"""Every sentence ``coopkin analyze`` prints on the shipped examples reads as English:
no phrase where a verb is missing ("the object can still a motion ...") or doubled
("can still make make")."""

from __future__ import annotations

import re

import pytest
import sympy as sp
from typer.testing import CliRunner

from coopkin_sym.cli import app
from coopkin_sym.model.examples import list_examples
from coopkin_sym.present.sentences import twist_words

runner = CliRunner()

# (example, mode) pairs that take over 10 s (urdf-two-fingers generic: about 45 s)
SLOW = {("urdf-two-fingers", "generic")}
# 10 to 20 s each (the generic blocks of 14 and 16 joints): run with the slow tests
LONG = {("panda-two-arm-box", "generic"), ("allegro-hand-sphere", "generic")}

# a modal verb followed by an article or a count instead of a verb, or a word twice
BROKEN = [
    re.compile(r"\b(can|cannot|could|must|may|will)( still| not| freely)? "
               r"(a|an|the|one|two|three|four|five|six|no)\b"),
    re.compile(r"\b([A-Za-z]{2,}) \1\b"),
    re.compile(r"\bby moving (a|an) motion\b"),
]


def broken_phrases(text: str) -> list[str]:
    """The phrases of ``text`` that a pattern of :data:`BROKEN` matches."""
    return [m.group(0) for pattern in BROKEN for m in pattern.finditer(text)]


def test_the_patterns_catch_the_known_fault():
    assert broken_phrases("the object can still a motion too large") == ["can still a"]
    assert broken_phrases("the arms can still make make one") == ["make make"]
    assert broken_phrases("the object can still rotate about c1") == []


def test_a_motion_too_large_for_words_is_a_verb_phrase():
    huge = [sum(sp.Symbol(f"x{i}") ** i for i in range(1, 500))] + [0] * 5
    words = twist_words(huge)
    assert words.startswith("make a motion too large to describe in words")
    assert not broken_phrases(f"the object can still {words}.")


CASES = [pytest.param(name, mode, marks=pytest.mark.skip(reason="over 10 s")
                      if (name, mode) in SLOW
                      else pytest.mark.slow if (name, mode) in LONG else ())
         for name in list_examples() for mode in ("home", "generic")]


@pytest.mark.parametrize("name, mode", CASES)
def test_analyze_sentences_are_grammatical(name, mode):
    args = ["analyze", name] + (["--generic"] if mode == "generic" else [])
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    sentences = [line for line in result.stdout.splitlines() if line.startswith("- ")]
    assert sentences
    bad = [(s, broken_phrases(s)) for s in sentences if broken_phrases(s)]
    assert not bad


def test_a_joint_motion_is_sized_by_its_moving_joints_only(monkeypatch):
    """Describing a motion of a few joints among many costs the few (the joints at
    rest are not measured): a system of 200 arms has 600 such motions of 1200 joints."""
    from coopkin_sym.present import sentences

    measured = []
    count_ops = sp.count_ops
    monkeypatch.setattr(sentences.sp, "count_ops",
                        lambda e: measured.append(e) or count_ops(e))
    qdot = [0] * 1200
    qdot[3], qdot[4], qdot[7] = 1, 2, sp.Rational(1, 3)
    words = sentences.joint_motion_words(qdot, [f"q{k}" for k in range(1200)])
    assert words == "joints in the ratio q3: 1, q4: 2, q7: 1/3"
    assert len(measured) == 3
