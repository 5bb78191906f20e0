"""The locus progress bar moves with the work: a share of a tree of parts, never
full before the search ends, with the current step as its description."""

from __future__ import annotations

from fractions import Fraction

from coopkin_sym import load
from coopkin_sym.analysis.locus import context, search
from coopkin_sym.analysis.locus.context import Progress


def test_parts_share_their_span_and_only_grow():
    bar = Progress(False)
    seen = []
    with bar:
        with bar.parts(3):
            for k in range(3):
                bar.step(f"factor {k}")
                seen.append(bar.done)
                with bar.parts(2):          # a component searched inside
                    bar.step("inner a")
                    seen.append(bar.done)
                    bar.step("inner b")
                    seen.append(bar.done)
            assert bar.text == "factor 2"
        seen.append(bar.done)
        assert bar.done == 1 and bar.text == "locus"      # back to the whole
    assert seen == [0, 0, Fraction(1, 6), Fraction(1, 3), Fraction(1, 3), Fraction(1, 2),
                    Fraction(2, 3), Fraction(2, 3), Fraction(5, 6), 1]


def test_weights_and_extra_steps():
    bar = Progress(False)
    with bar, bar.parts(2, [3, 1]):
        bar.step("heavy")
        assert bar.done == 0
        bar.step("light")
        assert bar.done == Fraction(3, 4)
        bar.step("one more than announced")        # stays in the last part
        assert bar.done == Fraction(3, 4) and bar.text == "one more than announced"
    assert bar.done == 1


def test_a_search_is_not_complete_before_it_ends(monkeypatch):
    record: list[tuple[Fraction, str]] = []
    advance = Progress._advance

    def recording(self, to):
        advance(self, to)
        record.append((self.done, self.text))

    monkeypatch.setattr(context.Progress, "_advance", recording)
    locus = search.compute_locus(load("paper-case1-hard"))
    assert locus.components
    shares = [d for d, _ in record]
    texts = [t for _, t in record]
    assert shares == sorted(shares)                  # it only grows
    full = shares.index(1)           # full only after the last step: then only the
    assert set(texts[full:]) <= {"q = pi", "locus"}      # enclosing steps close
    assert full > len(record) / 2
    assert texts[0] == "depth 0: the numbers and their candidates"
    assert any(t.startswith("depth 0: t_q") for t in texts)
    assert "q1 = pi" in texts and "q1 = pi, q2 = pi" in texts
    # the t chart is half of the work, the slices at q = pi the other half
    assert min(d for d, t in record if t == "q1 = pi") == Fraction(1, 2)
