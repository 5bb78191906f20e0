"""Finite mobility in words, LaTeX and JSON (:mod:`coopkin_sym.analysis.finite`).

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.finite import finite_mobility
>>> fm = finite_mobility(load("four-bar").model, "q1=-pi/2,q2=-pi/2")
>>> print(finite_lines(fm)[0])
Finite mobility: 1 (first-order motions: 2) - a bifurcation: 2 branches of 1 motion cross here.
"""

from __future__ import annotations

import sympy as sp

from coopkin_sym.analysis.finite import Branch, FiniteMobility
from coopkin_sym.exact.parse import parse_expression

_CLASS_WORDS = {
    "regular": "a regular configuration: the system moves with all its first-order "
               "motions",
    "kinematic_singularity": "a kinematic singularity at a smooth point of the "
                             "configuration space: the instantaneous numbers change, "
                             "the finite motions do not",
    "kinematic_singularity_loop": "a smooth point of the configuration space of an "
                                  "overconstrained loop: the instantaneous numbers are "
                                  "not those of generic joint values (where the loop "
                                  "does not close); whether they change along the "
                                  "motion is not decided",
    "bifurcation": "a bifurcation: {branches} branches of {dim} motion{s} cross here",
    "cusp": "a singular point of the configuration space: one branch of {dim} "
            "motion{s} through it, not smooth here (a cusp, or a branch with a "
            "fractional power)",
    "cone": "a singular point of the configuration space: its motions form a cone "
            "of dimension {dim}, not smooth here (how many branches it holds is not "
            "decided)",
    "shaky": "shaky: first-order motions exist, but no finite motion follows them",
    "shaky_partly": "shaky: only {dim} of the first-order motions {verb} finite; no "
                    "finite motion follows the others",
    "undecided": "undecided at order {order}: the expansion proves only "
                 "{lower} <= finite mobility <= {upper}",
}

_REASON_WORDS = {
    "submersion": "the constraints are independent here (their Jacobian has full row "
                  "rank), so the configuration space is smooth (implicit function "
                  "theorem)",
    "constant_rank": "the rank of Q here is its generic rank, so it is constant nearby "
                     "and the configuration space is smooth (constant rank theorem)",
    "real_cone_origin": "the lowest-order terms of the reduced constraints have no real "
                        "zero but the origin, so no real motion leaves the configuration",
    "cone_regular_points": "the reduced constraint's quadratic term is indefinite, so "
                           "real branches leave along its zero set (implicit function "
                           "theorem after a blow-up)",
    "binary_form_roots": "each simple real root of the reduced constraint's lowest "
                         "term is the tangent of one smooth branch",
    "closure_saturation": "the loop is overconstrained: its closure conditions "
                          "that are dependent here vanish, by exact ideal saturations, on "
                          "the smooth set the independent ones cut out, so the "
                          "configuration space is smooth here, of the dimension of the "
                          "first-order motions",
    "closure_bezout": "the loop is overconstrained: the closure conditions that are "
                      "independent here cut out a smooth curve, and each dependent one "
                      "vanishes along it to an order above Bezout's bound (the product of "
                      "the degrees), so on all of it; the configuration space is that "
                      "curve here",
    "no_first_order_motion": "there is no first-order motion",
    "newton_polygon": "along each tangent where the reduced constraint's lowest term "
                      "has a multiple root, the edges of its Newton polygon give the "
                      "real branches (a simple real root of an edge's polynomial is one "
                      "real half-branch, by the implicit function theorem after a "
                      "weighted blow-up); each simple tangent is one smooth branch",
    "group_orbit": "every first-order motion is a rotation of the object that keeps "
                   "each contact with the joints still; these rotations form a group "
                   "acting on the configuration space, whose orbit through here is "
                   "smooth and of their dimension",
}

_ASSUMPTION_WORDS = {
    "unit_length": "the one length parameter was set to 1 (scaling changes no dimension)",
    "frictionless_flat_face": "each frictionless contact is read as the link's point "
                              "kept on a flat face of the object",
    "closure_expansion": "the expansion is that of the loop closure's polynomials, without "
                         "the closure conditions that hold identically near the "
                         "configuration or were proved to follow from the others",
    "closure_saturation_inconclusive": "tried as well: the loop closure's exact "
                                       "saturations (Gröbner bases, with a time bound) "
                                       "proved nothing here, so the expansion's bounds are "
                                       "all that is proved",
}


def classification_text(fm: FiniteMobility) -> str:
    """The classification in words."""
    return _classification_words(fm.classification, fm.dimension,
                                 [b.dimension for b in fm.branches], fm.order, fm.bounds,
                                 fm.reason, fm.assumptions)


#: The proofs that use the loop closure: the configuration space of an
#: overconstrained loop, away from generic joint values.
_CLOSURE_REASONS = frozenset({"closure_saturation", "closure_bezout"})


def _classification_words(kind: str, dimension: int | None, branches: list[int],
                          order: int, bounds, reason: str = "",
                          notes: tuple = ()) -> str:
    dim = branches[0] if branches else dimension
    if kind == "shaky" and dimension:
        kind = "shaky_partly"
    if kind == "kinematic_singularity" and (reason in _CLOSURE_REASONS
                                            or "closure_expansion" in notes):
        kind = "kinematic_singularity_loop"
    return _CLASS_WORDS[kind].format(branches=len(branches), dim=dim,
                                     s="" if dim == 1 else "s", order=order,
                                     verb="is" if dim == 1 else "are",
                                     lower=bounds[0], upper=bounds[1])


def finite_summary(data: dict) -> str:
    """One line for a component's finite mobility (the plain data a locus keeps).

    Example
    -------
    >>> finite_summary({"dimension": 1, "bounds": [1, 1], "first_order": 2,
    ...                 "classification": "bifurcation", "reason": "cone_regular_points",
    ...                 "order": 2, "branches": [1, 1]})
    '1 (first-order motions: 2): a bifurcation: 2 branches of 1 motion cross here'
    """
    value = "undecided" if data["dimension"] is None else str(data["dimension"])
    words = _classification_words(data["classification"], data["dimension"],
                                  list(data["branches"]), data["order"], data["bounds"],
                                  data.get("reason", ""),
                                  tuple(data.get("assumptions", ())))
    field = data.get("field")
    over = (f" (exact over Q(alpha), alpha = {field['alpha']})" if field else "")
    read = [_ASSUMPTION_WORDS[a] for a in data.get("assumptions", ())
            if a in _MODEL_ASSUMPTIONS]
    assumed = f" (assumed: {'; '.join(read)})" if read else ""
    return (f"{value} (first-order motions: {data['first_order']}): {words}{over}"
            f"{assumed}{_along_words(data.get('along'))}")


#: The assumptions that say how the model was read (the others say what was tried).
_MODEL_ASSUMPTIONS = ("unit_length", "frictionless_flat_face")


#: A classification as the column of a family reads it.
_FAMILY_WORDS = {"regular": "regular", "kinematic_singularity": "first-order only",
                 "bifurcation": "bifurcation", "cusp": "cusp (not smooth)",
                 "cone": "cone (not smooth)",
                 "shaky": "shaky", "undecided": "undecided"}


def family_finite_text(finites: list[dict | None]) -> str:
    """What the finite mobility is at the witnesses of one family's members (their
    ``finite`` data, None where not computed), counted.

    Example
    -------
    >>> family_finite_text([{"classification": "bifurcation"},
    ...                     {"classification": "bifurcation"},
    ...                     {"classification": "shaky"}, None])
    'bifurcation at 2, shaky at 1 (of 4; 1 not computed)'
    """
    counts: dict[str, int] = {}
    for f in finites:
        if f is not None:
            words = _FAMILY_WORDS[f["classification"]]
            counts[words] = counts.get(words, 0) + 1
    done = sum(counts.values())
    if not done:
        return "not computed"
    said = ", ".join(f"{w} at {k}" for w, k in counts.items())
    if len(counts) == 1 and done == len(finites):
        return f"{next(iter(counts))} ({'all ' + str(done) if done > 1 else 'its witness'})"
    left = len(finites) - done
    return f"{said} (of {len(finites)}{f'; {left} not computed' if left else ''})"


def _along_words(along: dict | None) -> str:
    """What is known along the component beyond its witness, in words ("" if nothing).

    Example
    -------
    >>> _along_words({"how": "constant_rank", "dimension": 1,
    ...               "classification": "kinematic_singularity"})[:60]
    '; the same at every point of the component where its numbers'
    """
    if not along:
        return ""
    if along["how"] == "constant_rank":
        return ("; the same at every point of the component where its numbers hold (the "
                "rank of Q is the same there)")
    if along["dimension"] is None:
        value = f"undecided ({along['bounds'][0]} to {along['bounds'][1]})"
    else:
        words = _classification_words(along["classification"], along["dimension"], [], 0,
                                      along["bounds"])
        value = f"{along['dimension']}, {words.split(':')[0]}"
    at = ",".join(f"{k}={v}" for k, v in along["point"].items())
    return (f"; at a second point of the component, {at}: {value} (one more point, not "
            f"a proof for the whole component)")


def _vector(v) -> str:
    return "(" + ", ".join(str(x if isinstance(x, sp.Basic) and not x.is_Rational
                               else sp.nsimplify(x)) for x in v) + ")"


def _written_with_s(branch: Branch) -> bool:
    """Whether a branch tangent is written with ``s`` (a root of degree three or more,
    not in radicals) rather than its exact value."""
    return branch.direction is not None and branch.direction.root.degree > 2


def _tangent_rows(branch: Branch) -> tuple:
    """The spanning vectors shown: the tangent of an irrational direction of degree
    three or more in ``s`` (then the first vector), the exact values otherwise."""
    if not _written_with_s(branch):
        return branch.tangent
    return (branch.direction.tangent,) + tuple(branch.tangent[1:])


def _root_words(branch: Branch) -> str:
    """``, where s ... is the real root of ... in (lo, hi]`` for a tangent written with
    ``s``, else nothing."""
    if not _written_with_s(branch):
        return ""
    d = branch.direction
    lo, hi = d.interval
    return (f", where s (= {d.free[0]}/{d.free[1]} along the branch) is the real root of "
            f"{d.polynomial} in ({lo}, {hi}]")


def _field_words(fm: FiniteMobility) -> str | None:
    """The number field of an irrational configuration, in words (None at a rational
    one)."""
    if fm.field is None:
        return None
    return (f"exactly over the number field Q(alpha), alpha = {fm.field['alpha']} (a root "
            f"of {fm.field['minimal_polynomial']}; every sign decided on rational "
            f"isolating intervals of alpha)")


def finite_lines(fm: FiniteMobility) -> list[str]:
    """The lines ``coopkin analyze --finite`` prints.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.finite import finite_mobility
    >>> fm = finite_mobility(load("shaky-pinned-bars").model, "q1=0,q2=0")
    >>> print(finite_lines(fm)[0].replace(" - ", chr(10)))
    Finite mobility: 0 (first-order motions: 1)
    shaky: first-order motions exist, but no finite motion follows them.
    """
    value = "undecided" if fm.dimension is None else str(fm.dimension)
    lines = [f"Finite mobility: {value} (first-order motions: {fm.first_order}) - "
             f"{classification_text(fm)}."]
    if fm.reason in _REASON_WORDS:
        how = {"closure_saturation": "exact Gröbner bases",
               "closure_bezout": "exact power series",
               "group_orbit": "first order, the group's rotations split off"}.get(fm.reason,
                                                           f"expansion to order {fm.order}")
        lines.append(f"  Proof: {_REASON_WORDS[fm.reason]} ({how}).")
    for k, branch in enumerate(fm.branches, 1):
        if branch.tangent is not None:
            rows = _tangent_rows(branch)
            span = ", ".join(_vector(v) for v in rows) or "{0}"
            lines.append(f"  Branch {k}: {branch.dimension} motion"
                         f"{'' if branch.dimension == 1 else 's'}, tangent to the span of "
                         f"{span} in (u, qdot){_root_words(branch)}")
        else:
            lines.append(f"  Tangent cone ({branch.dimension} motions): {branch.cone} = 0 "
                         f"(x1, x2, ...: coordinates of the first-order motions)")
    lines += columns_lines(fm)
    if len(fm.orders) > 1:
        lines.append("  First-order motions that extend to order i: "
                     + ", ".join(f"order {i}: {m}" for i, m in fm.orders))
    if fm.equations and fm.dimension is None:
        if all(e == "0" for e in fm.equations):
            lines.append(f"  The reduced constraints vanish to order {fm.order}: every "
                         f"first-order motion extends that far.")
        else:
            lines.append(f"  Reduced constraints (to order {fm.order}): "
                         + "; ".join(f"{e} = 0" for e in fm.equations))
    lines += [f"  Assumed: {_ASSUMPTION_WORDS[a]}." for a in fm.assumptions]
    if fm.field is not None:
        lines.append(f"  Computed {_field_words(fm)}.")
    return lines


def columns_lines(fm: FiniteMobility) -> list[str]:
    """Which columns of the blocks are finite motions, in words (none when the
    verdicts were not asked).

    Example
    -------
    >>> from coopkin_sym import load
    >>> fm = load("four-bar").analyze("q1=-pi/2,q2=-pi/2").finite_mobility()
    >>> print(columns_lines(fm)[0].replace("; ", chr(10)))
      Columns of C: C12/C22 column 1 is a finite motion's velocity
    C12/C22 column 2 is not (the constraints fail along it at order 2).
    """
    if not fm.columns:
        return []
    name = {"C11": "C11", "C12": "C12/C22", "C23": "C23"}
    finite = [f"{name[c.block]} column {c.index}" for c in fm.columns
              if c.verdict == "finite"]
    parts = []
    if finite:
        parts.append(f"{_listed(finite)} {'is a' if len(finite) == 1 else 'are'} finite "
                     f"motion{'' if len(finite) == 1 else 's'}'"
                     f"{'s' if len(finite) == 1 else ''} velocit"
                     f"{'y' if len(finite) == 1 else 'ies'}")
    for c in fm.columns:
        if c.verdict == "fails":
            parts.append(f"{name[c.block]} column {c.index} is not (the constraints fail "
                         f"along it at order {c.order})")
        elif c.verdict == "undecided":
            parts.append(f"{name[c.block]} column {c.index} extends to order {c.order}, "
                         f"beyond that not decided")
    return [f"  Columns of C: {'; '.join(parts)}."]


def _listed(items: list[str]) -> str:
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def finite_latex(fm: FiniteMobility) -> str:
    """A LaTeX paragraph: the finite mobility, its classification and its branches
    (what ``coopkin analyze --finite --latex`` adds).

    Example
    -------
    >>> from coopkin_sym import load
    >>> fm = load("shaky-pinned-bars").finite_mobility("q1=0,q2=0")
    >>> finite_latex(fm).splitlines()[0][:50]
    'Finite mobility $0$ (first-order motions: $1$): sh'
    """
    value = r"\text{undecided}" if fm.dimension is None else str(fm.dimension)
    out = [f"Finite mobility ${value}$ (first-order motions: ${fm.first_order}$): "
           f"{classification_text(fm)}."]
    for k, branch in enumerate(fm.branches, 1):
        if branch.tangent:
            span = ", ".join(sp.latex(sp.Matrix(v).T) for v in _tangent_rows(branch))
            where = ""
            if _written_with_s(branch):
                lo, hi = branch.direction.interval
                where = (f", where $s$ is the real root of "
                         f"${sp.latex(branch.direction.polynomial)} = 0$ in "
                         f"$({sp.latex(sp.Rational(lo.numerator, lo.denominator))}, "
                         f"{sp.latex(sp.Rational(hi.numerator, hi.denominator))}]$")
            out.append(f"Branch {k}: tangent to $\\operatorname{{span}}\\{{{span}\\}}$"
                       f"{where}.")
        elif branch.cone is not None:
            out.append(f"Tangent cone: ${sp.latex(branch.cone)} = 0$ in the coordinates "
                       f"$x_i$ of the first-order motions.")
    if fm.reason in _REASON_WORDS:
        out.append(f"Proof: {_REASON_WORDS[fm.reason]}.")
    out += [line.strip().replace("C12/C22", "$C_{12}/C_{22}$").replace(
        "C11", "$C_{11}$").replace("C23", "$C_{23}$") for line in columns_lines(fm)]
    out += [f"Assumed: {_ASSUMPTION_WORDS[a]}." for a in fm.assumptions]
    if fm.field is not None:
        alpha = sp.latex(parse_expression(fm.field["alpha"], [], "field.alpha"))
        poly = sp.latex(parse_expression(fm.field["minimal_polynomial"], ["alpha"],
                                         "field.minimal_polynomial"))
        out.append(f"Computed exactly over $\\mathbb{{Q}}(\\alpha)$, $\\alpha = {alpha}$, "
                   f"a root of ${poly}$.")
    return "\n".join(out) + "\n"


def _direction_json(branch: Branch) -> dict | None:
    """An irrational branch direction as plain data (None for the others)."""
    d = branch.direction
    if d is None:
        return None
    return {"free": list(d.free), "minimal_polynomial": str(d.polynomial),
            "interval": [str(x) for x in d.interval], "tangent": [str(x) for x in d.tangent]}


def finite_json(fm: FiniteMobility) -> dict:
    """The ``"finite"`` entry of the analyze JSON: plain data, exact values as text.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.finite import finite_mobility
    >>> data = finite_json(finite_mobility(load("four-bar").model, "q1=0,q2=0"))
    >>> data["dimension"], data["classification"], data["branches"][0]["dimension"]
    (1, 'regular', 1)
    """
    return {
        "dimension": fm.dimension,
        "bounds": list(fm.bounds),
        "first_order": fm.first_order,
        "classification": fm.classification,
        "classification_text": classification_text(fm),
        "reason": fm.reason,
        "branches": [{"dimension": b.dimension,
                      "tangent": None if b.tangent is None else
                      [[str(x) for x in v] for v in b.tangent],
                      "cone": None if b.cone is None else str(b.cone),
                      "direction": _direction_json(b)}
                     for b in fm.branches],
        "orders": [{"order": i, "dimension": m} for i, m in fm.orders],
        "order": fm.order,
        "assumptions": list(fm.assumptions),
        "field": None if fm.field is None else dict(fm.field),
        "reduced_constraints": list(fm.equations),
        "group_motions": [[str(x) for x in v] for v in fm.group_motions],
        "columns": [{"block": c.block, "index": c.index, "verdict": c.verdict,
                     "order": c.order} for c in fm.columns],
    }
