"""The work budget of :mod:`coopkin_sym.exact.deadline`: steps of ``check`` counted, not
seconds, so a computation is cut at the same place every time."""

from __future__ import annotations

import pytest

from coopkin_sym.errors import TimeLimitReached, WorkLimitReached
from coopkin_sym.exact import deadline


def _steps_until_cut(budget: int) -> int:
    done = 0
    with deadline.work_limit(budget, "a test"):
        try:
            while True:
                deadline.check("a loop")
                done += 1
        except WorkLimitReached:
            return done


def test_a_budget_of_n_steps_lets_exactly_n_checks_pass():
    assert [_steps_until_cut(n) for n in (0, 1, 7, 1000)] == [0, 1, 7, 1000]


def test_spend_charges_many_steps_at_once_and_never_starts_past_the_budget():
    with deadline.work_limit(10) as bound:
        deadline.spend(4, "a resultant")
        assert deadline.budget_left() == 5          # four spent, one check
        with pytest.raises(WorkLimitReached, match="work budget of 10 steps used up "
                                                   "during a resultant"):
            deadline.spend(5, "a resultant")
        assert bound.budget == [-1]
    assert deadline.budget_left() is None


def test_an_inner_budget_counts_against_the_outer_one_and_is_clipped_by_it():
    with deadline.work_limit(10, "outer") as outer:
        for _ in range(4):
            deadline.check()
        with deadline.work_limit(100, "inner") as inner:
            assert inner.budget == [6]              # what the outer one has left
            deadline.check()
            deadline.check()
            assert deadline.active("outer") and deadline.active("inner")
        assert outer.budget == [4]
        assert not deadline.active("inner")


def test_a_time_bound_inside_a_budget_shares_it_and_both_apply():
    with deadline.work_limit(3):
        with deadline.time_limit(60, "timed"):
            deadline.check()
            deadline.check()
            assert deadline.budget_left() == 1
            assert 0 < deadline.remaining() <= 60
        deadline.check()
        assert deadline.budget_left() == 0
        with pytest.raises(WorkLimitReached):
            deadline.check()
    with deadline.time_limit(0.0), deadline.work_limit(1000):
        with pytest.raises(TimeLimitReached):
            deadline.check()


def test_a_budget_alone_is_no_time_bound():
    with deadline.work_limit(5):
        assert deadline.remaining() is None
        assert deadline.active()
