"""What a locus search says beyond its components, as data.

A :class:`Remark` names what happened (its ``kind``: a bound reached, a set left
unsolved, a factor with no real points, how a component's numbers were decided) and
holds the facts that locate it: polynomials and equations (as the package prints
them), depths, counts, component indices, limits. No sentence is written here;
:mod:`coopkin_sym.present.remarks` words every kind, and a report read back keeps its
sentences as plain strings in the same places.

Example
-------
>>> r = Remark.of("no_real_points", polynomial="t_q1**2 + 1")
>>> r.kind, r["polynomial"]
('no_real_points', 't_q1**2 + 1')
>>> r.to_json()
{'kind': 'no_real_points', 'polynomial': 't_q1**2 + 1'}
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from coopkin_sym.errors import ArgumentError

#: Every kind of remark, with the facts it holds. Groups: what was not explored
#: (``Locus.unexplored``), what is said once per search (``Locus.notes``), factors
#: (``Locus.dropped`` and ``Locus.parameter_conditions``) and how a component's
#: numbers were decided (``Component.decided``).
REMARK_KINDS: dict[str, tuple[str, ...]] = {
    # notes
    "candidates_probabilistic": (),
    "irrational_witness_floats": (),
    "float_checks_left_out": ("rows", "columns", "bound"),
    "pi_chart": (),
    "uniform_scaling": ("parameter",),
    "snapped_model": ("count", "largest"),
    # factors
    "no_real_points": ("polynomial",),
    "parameter_condition": ("polynomial",),
    # not explored: bounds of time
    "time_depth": ("depth", "equations"),
    "time_component": ("polynomial", "depth"),
    "time_pi_set": ("joints",),
    "time_pi_sets_left": ("joints", "left"),
    "time_whole_run": ("seconds", "where"),
    # not explored: sets the search does not solve
    "block_not_solved": ("rows", "columns", "block", "variables", "limit", "bound"),
    "combinations_vanish": ("block", "tries"),
    "outside_parametrization": ("polynomial", "equations"),
    "enclosing_not_searched": ("equations", "reason", "bound"),
    "family_too_large": ("terms", "degree", "variables", "equations", "bound"),
    "too_many_variables": ("component", "equations", "variables"),
    "divisors_only": ("component", "equations"),
    "inside_not_searched": ("component", "equations", "limit", "size", "bound"),
    "lower_dimensional_not_solved": ("depth", "variables", "bound"),
    "shared_values_undecided": ("polynomial", "count", "variable", "over"),
    "points_not_decided": ("polynomial", "degree", "bound"),
    "operation_too_large": ("operation", "variables", "size", "bound"),
    "operation_too_slow": ("operation", "variables", "seconds", "left"),
    "operation_over_bound": ("operation", "variables", "seconds", "bound"),
    "fields_not_disjoint": ("first", "second"),
    "deeper_not_explored": ("component", "condition", "reason", "bound"),
    "common_root_not_searched": ("equations", "variable"),
    "shared_values_not_solved": ("depth", "polynomial", "count", "variable"),
    "pi_deeper_not_explored": ("joints", "bound"),
    "pi_set_not_searched": ("joints", "deeper", "bound"),
    "pi_inside_not_searched": ("component", "joints"),
    # how a component's numbers were decided
    "decided_function_field": (),
    "decided_modulo_family": (),
    "decided_two_substitutions": (),
    "decided_substitution_modulo": (),
    "decided_family_modulo": (),
    "decided_joined_fields": ("fields",),
    "decided_free_variables": (),
    "decided_other_variables": (),
    "decided_at_point": (),
    "decided_algebraic": ("variable", "minimal_polynomial"),
    # a certificate: why a test is (not) certified, what it assumed or did not use
    "cert_time_before_tests": ("seconds", "where"),
    "cert_generic_differs": ("given", "exact"),
    "cert_chart_not_run": ("seconds", "where", "left"),
    "cert_stopped_early": (),
    "cert_depth_limited": ("depth",),
    "cert_no_singular": ("hint",),
    "cert_no_msolve": ("hint",),
    "cert_numbers_inconsistent": ("component", "given", "implied"),
    "cert_denominator_may_vanish": ("component",),
    "cert_denominator_residual": ("component", "polynomial", "undecided"),
    "cert_component_unreadable": ("error",),
    "cert_numbers_unreadable": ("component",),
    "cert_condition_unreadable": ("error",),
    "cert_conditions_left_out": (),
    "cert_minors_too_large": ("size", "rows", "columns", "terms", "largest"),
    "cert_no_larger_rank": (),
    "cert_larger_everywhere": (),
    "cert_larger_somewhere": ("depth", "modular"),
    "cert_never_drops": (),
    "cert_real_points_only": (),
    "cert_component_not_real": (),
    "cert_real_points_tests": ("count",),
    "cert_whole_slice": ("component",),
    "cert_drops_elsewhere": ("depth", "modular"),
    "cert_modular_only": ("backend",),
    "cert_undecided": ("detail", "hint"),
    "cert_not_tested": (),
    "cert_nothing_to_test": (),
    "cert_depths_untested": ("depth",),
    "cert_time_bound": ("seconds", "where"),
    # a verification: what it could not use
    "verify_other_system": ("locus_system", "model_system"),
    "verify_parameter_unset": ("parameter",),
}

#: Certificate notes that leave a component or condition out: each makes the
#: certificate fail (a covering could rest on what was left out).
NOT_USED = frozenset({"cert_numbers_inconsistent", "cert_denominator_may_vanish",
                      "cert_component_unreadable", "cert_numbers_unreadable",
                      "cert_condition_unreadable"})

#: Why deeper drops were not searched (the ``reason`` of a remark).
REASONS = ("max_depth", "no_parametrization", "irrational_family", "nested_splits",
           "hidden_depth")


@dataclass(frozen=True)
class Remark:
    """One thing a locus search says: its ``kind`` (a key of :data:`REMARK_KINDS`)
    and its facts (plain data: texts of polynomials, ints, tuples), in the order the
    kind lists them.

    Example
    -------
    >>> Remark.of("time_depth", depth=1, equations=("t_q1",))["equations"]
    ('t_q1',)
    >>> Remark.of("time_depth", depth=1)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentError: remark 'time_depth' needs the facts depth, ...
    """

    kind: str
    facts: tuple[tuple[str, Any], ...] = ()

    @classmethod
    def of(cls, kind: str, **facts: Any) -> Remark:
        """The remark of ``kind`` with exactly the facts the kind lists (lists become
        tuples, so remarks compare and hash as values)."""
        names = REMARK_KINDS.get(kind)
        if names is None:
            raise ArgumentError(f"unknown remark kind {kind!r}")
        if set(facts) != set(names):
            raise ArgumentError(f"remark {kind!r} needs the facts {', '.join(names)} "
                             f"(given: {', '.join(facts) or 'none'})")
        if "reason" in facts and facts["reason"] not in REASONS:
            raise ArgumentError(f"remark {kind!r}: unknown reason {facts['reason']!r}")
        return cls(kind, tuple((n, _frozen(facts[n])) for n in names))

    def __getitem__(self, name: str) -> Any:
        for key, value in self.facts:
            if key == name:
                return value
        raise KeyError(name)

    def __contains__(self, text: object) -> bool:
        raise TypeError("a Remark is data, not text: present.remarks.remark_text words it")

    def __iter__(self):
        raise TypeError("a Remark is data, not text: present.remarks.remark_text words it")

    def to_json(self) -> dict[str, Any]:
        """Plain JSON data: the kind and the facts (tuples as lists)."""
        return {"kind": self.kind, **{k: _plain(v) for k, v in self.facts}}


def _frozen(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return tuple(_frozen(v) for v in value)
    return value


def _plain(value: Any) -> Any:
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


def add_once(remarks: list, remark: Remark) -> None:
    """Append ``remark`` to ``remarks`` unless an equal one is there (a remark is said
    once).

    Example
    -------
    >>> said = []
    >>> for _ in range(2):
    ...     add_once(said, Remark.of("pi_chart"))
    >>> len(said)
    1
    """
    if remark not in remarks:
        remarks.append(remark)
