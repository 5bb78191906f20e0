"""A locus verification (:mod:`coopkin_sym.analysis.locus.verify`) in words: the lines
``coopkin verify`` prints and the JSON a report carries.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.verify import verify_locus
>>> system = load("paper-case1-hard")
>>> summary_lines(verify_locus(system, system.locus(), max_points=200))[0]
'Verification: passed (0 uncovered points, 0 unsound components)'
"""

from __future__ import annotations

from collections.abc import Mapping

from coopkin_sym.analysis.locus.verify import Verification
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.model.configuration import assignments_text
from coopkin_sym.present.remarks import remark_texts

__all__ = ["summary_lines", "verification_json"]


def _numbers_text(numbers: Mapping[str, int] | None) -> str:
    if not numbers:
        return ""
    return " ".join(f"{k} {numbers[k]}" for k in NUMBER_NAMES if k in numbers)


def summary_lines(v: Verification) -> list[str]:
    """The verification in a few plain lines (for the command line).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> from coopkin_sym.analysis.locus.verify import verify_locus
    >>> generic = {"Nm": 0, "Nc": 0, "Ni": 0, "Nr": 0, "Ng": 3, "Nd": 7, "Nh": 1}
    >>> v = verify_locus(load("paper-case1-complete-hard"),
    ...                  Locus("c", ["t_q1", "t_q2"], "L=1", generic), lines=0)
    >>> summary_lines(v)[0]
    'Verification: FAILED (20 uncovered points, 0 unsound components)'
    """
    status = "passed" if v.ok else "FAILED"
    out = [f"Verification: {status} ({v.uncovered_total} uncovered point"
           f"{'' if v.uncovered_total == 1 else 's'}, {len(v.unsound_components)} unsound "
           f"component{'' if len(v.unsound_components) == 1 else 's'})"]
    sets = {}
    for name, xs in v.values.items():
        sets.setdefault(tuple(xs), []).append(name)
    grid = "; ".join(f"{', '.join(names)} in {{{', '.join(xs)}}}" for xs, names in sets.items())
    out.append(f"  grid: {v.grid_points} points ({grid}"
               f"{', cut to fit --max-points' if v.reduced else ''}), "
               f"{v.grid_drops} with non-generic numbers")
    out.append(f"  lines: {v.lines} random rational lines (seed {v.seed}), {v.line_points} "
               f"points decided exactly, {v.line_drops} with non-generic numbers, "
               f"{v.singular_lines} lying in the locus")
    out.append(f"  components: {v.components}; witnesses checked: {v.witnesses_checked}; "
               f"with no witness and no point checked: {len(v.unchecked)}")
    if v.boundary_points:
        out.append(f"  {v.boundary_points} point(s) where a component's equations hold and "
                   "a denominator of its parametrization vanishes, ranks not above its "
                   "own: taken as on it")
    for i, why in v.unread_witnesses.items():
        out.append(f"  witness of component {i + 1} not read here: {why}")
    for u in v.uncovered:
        where = assignments_text(u.point)
        if u.kind == "root":
            where = (f"{where} (approximately; lam a root of {u.algebraic['root_of']} on "
                     f"the line {u.algebraic['line']})")
        elif u.kind == "line":
            where = f"every point of the line {where}"
        out.append(f"  uncovered ({u.source}): {where}: {_numbers_text(u.numbers)}"
                   + (f" (on component {', '.join(str(i + 1) for i in u.on)} with other "
                      "numbers)" if u.on else ""))
    if v.uncovered_total > len(v.uncovered):
        out.append(f"  ... {v.uncovered_total - len(v.uncovered)} more uncovered points")
    for issue in v.unsound:
        name = "the generic numbers" if issue.component < 0 else \
            f"component {issue.component + 1}"
        where = assignments_text(issue.point or {})
        out.append(f"  unsound: {name}: {_ISSUE_WORDS.get(issue.kind, issue.kind)}"
                   + (f" at {where}" if where else "")
                   + (f": {_numbers_text(issue.numbers)}" if issue.numbers else "")
                   + (f" ({issue.detail})" if issue.detail else ""))
    out.extend(f"  note: {n}" for n in remark_texts(v.notes))
    out.append(f"  {v.seconds} s")
    return out


_ISSUE_WORDS = {
    "witness-off": "its equations do not vanish at its witness",
    "witness-numbers": "its witness has other numbers",
    "rank-above": "a point on it has a rank above the component's (numbers there)",
    "generic-numbers": "its numbers are the generic ones",
    "generic": "the report's generic numbers are wrong",
}


def verification_json(v: Verification) -> dict:
    """The verification as JSON data, its notes as sentences (what a report carries).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.types import Locus
    >>> from coopkin_sym.analysis.locus.verify import verify_locus
    >>> locus = Locus("another", ["t_q1", "t_q2"], "L=1", {})
    >>> verification_json(verify_locus(load("paper-case1-hard"), locus, lines=0))["notes"]
    ["the locus is about 'another', the model is 'paper case 1, hard/hard'"]
    """
    out = v.to_json()
    out["notes"] = remark_texts(v.notes)
    return out
