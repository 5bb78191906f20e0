"""Building G, D, H and Q costs about the size of Q, not its size times the number
of contacts: a row of H selects one to three rows of ``G^T -D``. Counted in entries
looked at (each ``is_zero`` of a ring element), not timed: twice the contacts must
cost about twice as much (the quadratic product of the dense H with ``G^T -D`` cost
four times as much)."""

from __future__ import annotations

from large_systems import many_arms, many_contacts

from coopkin_sym.analysis import kinematics
from coopkin_sym.exact.ratfunc import RatFunc
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import load_model


def _entries_looked_at(model_dict, monkeypatch) -> int:
    model = load_model(model_dict)
    count = [0]
    is_zero = RatFunc.is_zero

    def counted(self):
        count[0] += 1
        return is_zero(self)

    with monkeypatch.context() as patch:
        patch.setattr(RatFunc, "is_zero", counted)
        kinematics.build(model, Configuration.parse(model, None))
    return count[0]


def test_the_kinematics_of_twice_the_contacts_cost_twice_as_much(monkeypatch):
    small = _entries_looked_at(many_contacts(150), monkeypatch)
    large = _entries_looked_at(many_contacts(300), monkeypatch)
    assert large < 2.2 * small


def test_the_kinematics_of_twice_the_arms_cost_about_four_times_as_much(monkeypatch):
    """Q itself has (3 x arms) x (6 x arms) entries: that much cannot be avoided."""
    small = _entries_looked_at(many_arms(20), monkeypatch)
    large = _entries_looked_at(many_arms(40), monkeypatch)
    assert large < 4.4 * small
