"""The words of a locus's remarks (:class:`~coopkin_sym.analysis.locus.remarks.Remark`).

Every kind of remark the search makes has one sentence here, written from its facts;
a remark read back from a report is already a sentence and is kept as it is.

Example
-------
>>> from coopkin_sym.analysis.locus.remarks import Remark
>>> remark_text(Remark.of("time_depth", depth=1, equations=("t_q1 + 1",)))
'depth 1 inside t_q1 + 1: not explored, time bound reached'
>>> remark_text("a sentence read back from a report")
'a sentence read back from a report'
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

from coopkin_sym.analysis.locus.remarks import Remark
from coopkin_sym.errors import TimeLimitReached

_NO_PARAMETRIZATION = "no rational parametrization"


def _reason(facts: Mapping[str, Any]) -> str:
    reason, bound = facts["reason"], facts["bound"]
    if reason == "max_depth":
        return f"max depth {bound}"
    if reason == "nested_splits":
        return f"more than {bound} nested zero sets of single minors"
    if reason == "hidden_depth":
        return f"more than {bound} such set{'s' if bound > 1 else ''} deep"
    if reason == "irrational_family":
        return ("a family with irrational coordinates; only its intersections with the "
                "families found with it")
    return _NO_PARAMETRIZATION


def _numbers(pairs: Sequence[tuple[str, Any]]) -> str:
    return ", ".join(f"{name} {value}" for name, value in pairs)


def _modular(facts: Mapping[str, Any]) -> str:
    return " (found modulo a prime)" if facts["modular"] else ""


def _inside(equations: Sequence[str], sep: str = "; ") -> str:
    return " inside " + sep.join(equations) if equations else ""


def _where(facts: Mapping[str, Any]) -> str:
    """A component by its number, or a candidate set by its equations."""
    if facts["component"] is not None:
        return f"component #{facts['component'] + 1}"
    return ", ".join(facts["equations"]) + " (enclosing numbers there)"


def _inside_limit(facts: Mapping[str, Any]) -> str:
    """Why the search inside a family without a rational parametrization stopped."""
    if facts["limit"] == "steps":
        return (f"deeper drops searched within a work budget of {facts['bound']:,} steps "
                "only (the bound of one such family): what was found by then is listed, "
                "the rest not searched")
    return (f"deeper drops not searched (a family with no rational parametrization and "
            f"{facts['size']} terms: more than {facts['bound']})")


#: Why the drops inside a component at joints at pi it was not found at are not searched.
_OWN_CHART = ("a set inside a component of another chart: past the work budget of such "
              "searches in this slice, or not run")


def _at_pi(joints: Sequence[str]) -> str:
    return ", ".join(f"{n} = pi" for n in joints)


def _block_not_solved(f: Mapping[str, Any]) -> str:
    if f["limit"] == "splits":
        why = f"more than {f['bound']} nested zero sets of single minors"
    else:
        size, count = f["bound"]
        why = f"minors larger than {size} x {size}, or more than {count} of them"
    return (f"rank drops of codimension 2 or more of a {f['rows']} x {f['columns']} "
            f"block ({f['block'] or 'a block'}) in {f['variables']} variables: not solved "
            f"({why})")


def _deeper_not_explored(f: Mapping[str, Any]) -> str:
    where = f"inside component #{f['component'] + 1} ({f['condition']})"
    if len(where) > 160:
        where = f"inside component #{f['component'] + 1}"
    return f"{where}: deeper drops not explored ({_reason(f)})"


def _joined_fields(f: Mapping[str, Any]) -> str:
    fields = ("Q(alpha, beta), two linearly disjoint fields" if f["fields"] == 2 else
              "Q(alpha)" if f["fields"] == 1 else "the function field of the free variables")
    return f"exact over {fields}"


_WORDS: dict[str, Callable[[Mapping[str, Any]], str]] = {
    "candidates_probabilistic": lambda f: (
        "Candidate sets come from random integer combinations of maximal minors "
        "(Cauchy-Binet): their common zeros contain every set where the rank drops, and "
        "every component reported is then decided exactly, so nothing is wrongly "
        "reported; a combination that vanishes identically is drawn again, and a block "
        "whose combinations all vanish is listed as not explored."),
    "irrational_witness_floats": lambda f: (
        "A witness with irrational coordinates is decided over Q(alpha); its float "
        "checks use a rational point within 1e-40 of it (the same float64 image), "
        "with the witness's own exact numbers at distance 0."),
    "float_checks_left_out": lambda f: (
        f"No float rank tests at the witnesses: Q is {f['rows']:,} x {f['columns']:,}, "
        f"over {f['bound']:,} entries (a float SVD costs the cube of its size)."),
    "pi_chart": lambda f: (
        "s_q = cot(q/2): an equation s_q (= 0) is q = pi, outside the chart of t_q; "
        "every set of joints at pi is searched like the t chart."),
    "uniform_scaling": lambda f: (
        f"Every length is a multiple of {f['parameter']}: uniform scaling changes no "
        f"number, so {f['parameter']} = 1 (equations in prismatic displacements are in "
        f"units of {f['parameter']})."),
    "snapped_model": lambda f: (
        f"{f['count']} float{'' if f['count'] == 1 else 's'} of URDF files "
        f"{'was' if f['count'] == 1 else 'were'} replaced by exact values (at most "
        f"{f['largest']:.2g} rad away): this is the exact locus of the snapped model."),
    "no_real_points": lambda f: f"{f['polynomial']} = 0 (no real points)",
    "parameter_condition": lambda f: f"{f['polynomial']} = 0",
    "time_depth": lambda f: (f"depth {f['depth']}{_inside(f['equations'])}: not explored, "
                             "time bound reached"),
    "time_component": lambda f: (f"component {f['polynomial']} = 0 (depth {f['depth']}): "
                                 "not decided, time bound reached"),
    "time_pi_set": lambda f: f"{_at_pi(f['joints'])}: not searched, time bound reached",
    "time_pi_sets_left": lambda f: (
        f"{_at_pi(f['joints'])} and {f['left']} more sets of joints at q = pi: not "
        f"searched, time bound reached"),
    "time_whole_run": lambda f: (
        f"{TimeLimitReached(f['seconds'], f['where'])} (the search's wall-clock bound; "
        "coopkin locus --timeout gives it four fifths of its bound): the rest of the "
        "search was not explored (remaining candidates, deeper components, the q = pi "
        "chart)"),
    "block_not_solved": _block_not_solved,
    "combinations_vanish": lambda f: (
        f"block {f['block']}: {f['tries']} random combinations of its maximal minors "
        "all vanished identically; the drops it cuts out were not searched there"),
    "outside_parametrization": lambda f: (
        f"{f['polynomial']} = 0 inside {'; '.join(f['equations'])}: outside the "
        "parametrization of the enclosing component"),
    "enclosing_not_searched": lambda f: (
        f"inside {', '.join(f['equations'])} (enclosing numbers there): deeper drops not "
        f"searched ({_reason(f)})"),
    "family_too_large": lambda f: (
        f"a family of {f['terms']} terms, degree {f['degree']} in "
        f"{', '.join(f['variables'])}{_inside(f['equations'], ', ')}: not decided (ranks "
        f"modulo a polynomial of more than {f['bound']} terms)"),
    "too_many_variables": lambda f: (
        f"inside {_where(f)}: deeper drops not searched ({_NO_PARAMETRIZATION}, and "
        f"{f['variables']} variables)"),
    "divisors_only": lambda f: (
        f"inside {_where(f)}: only where a divisor of the rows vanishes was searched "
        "(drops cut out by minors alone not searched: a family with no rational "
        "parametrization)"),
    "inside_not_searched": lambda f: f"inside {_where(f)}: {_inside_limit(f)}",
    "lower_dimensional_not_solved": lambda f: (
        f"depth {f['depth']}: lower-dimensional drops in {len(f['variables'])} variables "
        f"({', '.join(f['variables'])}) not solved (solved: up to two variables; curves "
        f"in three or four and points in three when the equations have at most "
        f"{f['bound']} terms)"),
    "operation_too_large": lambda f: (
        f"a {f['operation']} in {', '.join(f['variables'])} of about {f['size']} terms "
        f"(more than {f['bound']}, and it cannot be interrupted) was not computed: the "
        "sets it would have solved were not searched"),
    "operation_too_slow": lambda f: (
        f"a {f['operation']} in {', '.join(f['variables'])} estimated at about "
        f"{f['seconds']} s (more than the {f['left']} s left under the time bound, and "
        "it cannot be interrupted) was not computed: the sets it would have solved were "
        "not searched"),
    "operation_over_bound": lambda f: (
        f"a {f['operation']} in {', '.join(f['variables'])} estimated at about "
        f"{f['seconds']} s (over the {f['bound']} s one step that cannot be interrupted "
        "may take) was not computed: the sets it would have solved were not searched"),
    "points_not_decided": lambda f: (
        f"the real points where {f['polynomial']} = 0 (degree {f['degree']}) inside a "
        f"family with no rational parametrization: numbers not decided (points of "
        f"degree up to {f['bound']} are decided there)"),
    "shared_values_undecided": lambda f: (
        f"real points where {f['polynomial']} = 0 and {f['count']} values of "
        f"{f['variable']} share each {f['over']}: numbers not decided"),
    "fields_not_disjoint": lambda f: (
        f"where components #{f['first'] + 1} and #{f['second'] + 1} meet: not decided "
        "(their fields are not proved linearly disjoint)"),
    "deeper_not_explored": _deeper_not_explored,
    "common_root_not_searched": lambda f: (
        f"inside {', '.join(f['equations'])}, {f['variable']} a common root of the minors "
        f"(enclosing numbers there): deeper drops not searched ({_NO_PARAMETRIZATION})"),
    "shared_values_not_solved": lambda f: (
        f"depth {f['depth']}: where {f['polynomial']} = 0, {f['count']} values of "
        f"{f['variable']} share each point: not solved"),
    "pi_deeper_not_explored": lambda f: (
        f"inside {_at_pi(f['joints'])}: deeper drops not explored (max depth "
        f"{f['bound']})"),
    "pi_inside_not_searched": lambda f: (
        f"inside component #{f['component'] + 1} where {_at_pi(f['joints'])}: deeper "
        f"drops not searched ({_OWN_CHART})"),
    "pi_set_not_searched": lambda f: (
        f"inside {_at_pi(f['joints'])}: {'deeper ' if f['deeper'] else ''}drops not "
        f"searched (sets of joints at pi are searched inside up to {f['bound']} at once: "
        "pi_size)"),
    "decided_function_field": lambda f: "exact over the component's function field",
    "decided_modulo_family": lambda f: (
        "exact over the component's function field (rank modulo its irreducible "
        "polynomial)"),
    "decided_two_substitutions": lambda f: (
        "exact over the family's function field (two substitutions)"),
    "decided_substitution_modulo": lambda f: (
        "exact over the family's function field (a substitution, then ranks modulo its "
        "irreducible polynomial)"),
    "decided_family_modulo": lambda f: (
        "exact over the family's function field (ranks modulo its irreducible "
        "polynomial)"),
    "decided_joined_fields": _joined_fields,
    "decided_free_variables": lambda f: "exact over the function field of the free variables",
    "decided_other_variables": lambda f: (
        "exact over the function field of the other variables"),
    "decided_at_point": lambda f: "exact at the point",
    "decided_algebraic": lambda f: (
        f"exact over Q(alpha), alpha = {f['variable']} a root of {f['minimal_polynomial']} "
        "(every conjugate point at once)"),
    "cert_time_before_tests": lambda f: (
        f"{TimeLimitReached(f['seconds'], f['where'])}, before the first test"),
    "cert_generic_differs": lambda f: (
        f"the locus's generic numbers ({_numbers(f['given'])}) differ from the exact ones "
        f"({_numbers(f['exact'])})"),
    "cert_chart_not_run": lambda f: (
        f"not run: {TimeLimitReached(f['seconds'], f['where'])}"
        + (f"; the {f['left']} chart{'s' if f['left'] > 1 else ''} after it were not "
           "tested" if f["left"] else "")),
    "cert_stopped_early": lambda f: (
        "Stopped at the first test not certified; the tests after it were not run."),
    "cert_depth_limited": lambda f: (
        f"Only depths up to {f['depth']} were tested: the drops inside the components of "
        f"depth {f['depth']} and deeper were not tested."),
    "cert_no_singular": lambda f: (
        f"Singular is not installed ({f['hint']}): the proofs ran on flint's exact "
        "Buchberger algorithm, which is slow beyond small systems."),
    "cert_no_msolve": lambda f: (
        f"msolve is not installed ({f['hint']}): what is missing was looked for exactly "
        "on small subspaces only."),
    "cert_numbers_inconsistent": lambda f: (
        f"component #{f['component'] + 1}: its numbers ({_numbers(f['given'])}) do not fit "
        f"one another (from Nm, Ni, Nr: {_numbers(f['implied'])}): the component is not "
        "used"),
    "cert_denominator_may_vanish": lambda f: (
        f"component #{f['component'] + 1}: a denominator of its parametrization may "
        "vanish on its equations (saturation is not computed here): the component is "
        "not used"),
    "cert_denominator_residual": lambda f: (
        f"the points of component #{f['component'] + 1} where a denominator of its "
        f"parametrization vanishes ({f['polynomial']} = 0) are "
        + ("not decided to" if f["undecided"] else "not proved to")
        + " lie in the other components"),
    "cert_component_unreadable": lambda f: f"{f['error']}: the component is not used",
    "cert_numbers_unreadable": lambda f: (
        f"component #{f['component'] + 1}: its numbers cannot be read: the component is "
        "not used"),
    "cert_condition_unreadable": lambda f: f"{f['error']}: the condition is not used",
    "cert_conditions_left_out": lambda f: (
        "Parameter values on the locus's parameter conditions are left out (they are "
        "reported apart)."),
    "cert_minors_too_large": lambda f: (
        f"the {f['size']} x {f['size']} minors of the {f['rows']} x {f['columns']} matrix "
        f"left after the pivots without real zeros may have {f['terms']:.2g} terms "
        f"(largest entry {f['largest']} terms): too large to write"),
    "cert_no_larger_rank": lambda f: "no larger rank at any point",
    "cert_larger_everywhere": lambda f: (
        "the rank is larger than the component's numbers give at every real point"),
    "cert_larger_somewhere": lambda f: (
        "the rank is larger than the component's numbers give at some of its points"
        + _modular(f)),
    "cert_never_drops": lambda f: "the rank never drops at a real point",
    "cert_component_not_real": lambda f: (
        "the component has no real point on this chart (a polynomial that vanishes on "
        "it has no real zero): nothing to test"),
    "cert_real_points_tests": lambda f: (
        f"{f['count']} test{'' if f['count'] == 1 else 's'} proved at the real points only: "
        "outside the components, the drop sets there have complex points alone (a "
        "polynomial that vanishes on them has no real zero)."),
    "cert_real_points_only": lambda f: (
        "proved at the real points (the points outside the components are not real: "
        "a polynomial that vanishes on them has no real zero)"),
    "cert_whole_slice": lambda f: (
        f"the whole slice lies in component #{f['component'] + 1}"),
    "cert_drops_elsewhere": lambda f: (
        "the rank drops " + ("below its generic value at points on no listed component"
                             if f["depth"] == 0 else "below its value on the component at "
                             "points on no component listed after it") + _modular(f)),
    "cert_modular_only": lambda f: f"not proved ({f['backend']} works modulo a prime)",
    "cert_undecided": lambda f: (
        (f["detail"] or "undecided")
        + (f" (Singular not installed: {f['hint']})" if f["hint"] else "")),
    "cert_not_tested": lambda f: "not tested (max_depth)",
    "cert_nothing_to_test": lambda f: "nothing to test",
    "cert_depths_untested": lambda f: f"depths beyond {f['depth']} were not tested",
    "cert_time_bound": lambda f: (
        f"{TimeLimitReached(f['seconds'], f['where'])}, before every test was run"),
    "verify_other_system": lambda f: (
        f"the locus is about {f['locus_system']!r}, the model is {f['model_system']!r}"),
    "verify_parameter_unset": lambda f: (
        f"{f['parameter']} is neither free nor fixed in the locus: checked at "
        f"{f['parameter']} = 1 (uniform scaling)."),
}


def remark_text(remark: Remark | str) -> str:
    """The sentence of a remark (a string, from a report read back, is returned as it
    is; an empty one too: a component with no ``decided``).

    Example
    -------
    >>> remark_text(Remark.of("no_real_points", polynomial="t_q1**2 + 1"))
    't_q1**2 + 1 = 0 (no real points)'
    """
    if isinstance(remark, str):
        return remark
    return _WORDS[remark.kind](dict(remark.facts))


def remark_texts(remarks: Sequence[Remark | str]) -> list[str]:
    """The sentences of a list of remarks, in order.

    Example
    -------
    >>> remark_texts([Remark.of("pi_chart"), "read back"])[1]
    'read back'
    """
    return [remark_text(r) for r in remarks]


#: The facts that locate a remark (which component, polynomial, equations or joints
#: at pi): remarks that differ only in these are said once, with what varies listed.
VARYING = ("component", "condition", "polynomial", "equations", "joints")

#: Most places listed in a grouped remark, and the longest place shown whole (the
#: JSON report lists every remark).
MAX_LISTED = 12
MAX_PLACE = 120

# A grouped remark's sentence without the facts that vary.
_GROUP_WORDS: dict[str, Callable[[Mapping[str, Any]], str]] = {
    "deeper_not_explored": lambda f: f"deeper drops not explored ({_reason(f)})",
    "time_depth": lambda f: f"depth {f['depth']}: not explored, time bound reached",
    "time_component": lambda f: (f"components of depth {f['depth']} not decided, time "
                                 "bound reached"),
    "time_pi_set": lambda f: "sets of joints at pi not searched, time bound reached",
    "outside_parametrization": lambda f: ("outside the parametrization of the enclosing "
                                          "component"),
    "enclosing_not_searched": lambda f: (f"deeper drops not searched ({_reason(f)}; "
                                         "enclosing numbers there)"),
    "too_many_variables": lambda f: (f"deeper drops not searched ({_NO_PARAMETRIZATION}, "
                                     f"and {f['variables']} variables)"),
    "divisors_only": lambda f: (
        "only where a divisor of the rows vanishes was searched (drops cut out by minors "
        "alone not searched: a family with no rational parametrization)"),
    "inside_not_searched": lambda f: _inside_limit(f),
    "common_root_not_searched": lambda f: (
        f"{f['variable']} a common root of the minors (enclosing numbers there): deeper "
        f"drops not searched ({_NO_PARAMETRIZATION})"),
    "pi_deeper_not_explored": lambda f: f"deeper drops not explored (max depth {f['bound']})",
    "pi_inside_not_searched": lambda f: f"deeper drops at q = pi not searched ({_OWN_CHART})",
    "pi_set_not_searched": lambda f: (
        f"{'deeper ' if f['deeper'] else ''}drops not searched (sets of joints at pi are "
        f"searched inside up to {f['bound']} at once: pi_size)"),
}


def _place(facts: Mapping[str, Any]) -> str:
    """Where one remark of a group is: its component, else its polynomial, equations
    or joints at pi (cut at :data:`MAX_PLACE` characters)."""
    if facts.get("component") is not None:
        at = f" ({_at_pi(facts['joints'])})" if facts.get("joints") else ""
        return f"#{facts['component'] + 1}{at}"
    parts = []
    if facts.get("polynomial"):
        parts.append(f"{facts['polynomial']} = 0")
    if facts.get("equations"):
        parts.append(", ".join(facts["equations"]))
    if facts.get("joints"):
        parts.append(_at_pi(facts["joints"]))
    place = " inside ".join(parts) or "(no place)"
    return place if len(place) <= MAX_PLACE else place[:MAX_PLACE - 4] + " ..."


def _group_key(remark: Remark | str) -> tuple:
    if isinstance(remark, str):
        return ("", remark)
    return (remark.kind, tuple((k, v) for k, v in remark.facts if k not in VARYING))


def _group_text(group: Sequence[Remark | str], max_listed: int) -> str:
    first = group[0]
    n = len(group)
    if isinstance(first, str) or all(r == first for r in group):
        return f"{remark_text(first)} ({n} times)"
    facts = dict(first.facts)
    places = [_place(dict(r.facts)) for r in group]
    in_components = all(p.startswith("#") for p in places)
    # a component at several sets of joints at pi: places in components
    distinct = len({p.split(" (")[0] for p in places}) == n
    what = "components" if in_components and distinct else "places"
    shown = ", ".join(places[:max_listed]) if in_components else "; ".join(places[:max_listed])
    if n > max_listed:
        shown += f", ... ({n - max_listed} more, all listed in the JSON report)"
    words = _GROUP_WORDS.get(first.kind)
    if words is None:
        return f"{remark_text(first)}; the same in {n - 1} more {what}: " + ", ".join(
            places[1:max_listed]) + (f", ... ({n - max_listed} more, all listed in the "
                                     "JSON report)" if n > max_listed else "")
    return f"{words(facts)}, inside {n} {what}: {shown}"


def grouped_remark_texts(remarks: Sequence[Remark | str], max_listed: int = MAX_LISTED,
                         names: Mapping[str, str] | None = None) -> list[str]:
    """The sentences of ``remarks`` with the remarks of one kind that differ only in
    where they are (:data:`VARYING`) said once: their count and their places (at most
    ``max_listed``; the JSON report keeps every remark); a polynomial by its name
    when ``names`` maps its text to one (``P3``). Equal sentences read back
    from a report are said once with their count. In the order of first occurrence.

    Example
    -------
    >>> same = [Remark.of("deeper_not_explored", component=k, condition="q1 = 0",
    ...                   reason="max_depth", bound=2) for k in (2, 4, 6)]
    >>> grouped_remark_texts(same + [Remark.of("pi_chart")])[0]
    'deeper drops not explored (max depth 2), inside 3 components: #3, #5, #7'
    >>> grouped_remark_texts(same[:1]) == remark_texts(same[:1])
    True
    >>> grouped_remark_texts(["read back", "read back"])
    ['read back (2 times)']
    >>> grouped_remark_texts([Remark.of("pi_chart")] * 2)[0].endswith("chart. (2 times)")
    True
    """
    groups: dict[tuple, list] = {}
    for r in remarks:
        groups.setdefault(_group_key(r), []).append(_renamed(r, names or {}))
    return [remark_text(g[0]) if len(g) == 1 else _group_text(g, max_listed)
            for g in groups.values()]


def _renamed(remark: Remark | str, names: Mapping[str, str]) -> Remark | str:
    """``remark`` with its polynomials by their ``names`` where they have one."""
    if isinstance(remark, str) or not names:
        return remark
    facts = []
    for key, value in remark.facts:
        if key == "polynomial" and isinstance(value, str):
            value = names.get(value, value)
        elif key == "equations":
            value = tuple(names.get(e, e) for e in value)
        facts.append((key, value))
    return Remark(remark.kind, tuple(facts))
