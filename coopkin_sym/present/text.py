"""Analyses as text and LaTeX: what ``coopkin analyze`` prints.

Example
-------
>>> from coopkin_sym import load
>>> text = analysis_text(load("paper-case1-hard").analyze())
>>> "Nm = 2  Nc = 2  Ni = 1" in text
True
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from typing import TYPE_CHECKING

import sympy as sp

from coopkin_sym.analysis.factored import FactoredMotions
from coopkin_sym.analysis.mobility import Analysis
from coopkin_sym.exact.parse import brief
from coopkin_sym.model.configuration import assignments_text
from coopkin_sym.present.classes import classes_text
from coopkin_sym.present.passive import PASSIVE_WORDS, passive_lines, passive_numbers_text
from coopkin_sym.present.sentences import (
    configuration_words,
    irrational_sentences,
    sentences,
)

if TYPE_CHECKING:  # pragma: no cover
    from coopkin_sym.analysis.finite import FiniteMobility
    from coopkin_sym.analysis.irrational import IrrationalAnalysis

__all__ = ["JSON_KEYS", "analysis_document", "analysis_json", "analysis_latex",
           "analysis_parts", "analysis_text", "block_table", "irrational_text", "object_frame_text",
           "snapped_lines", "urdf_note_lines"]

# why an analysis at an irrational point has no blocks
_IRRATIONAL_OMITTED = ("at a configuration with irrational coordinates only the numbers "
                       "(and their motions in words) are computed")


def analysis_parts(a: Analysis) -> list[tuple[str, Callable[[], list[str]]]]:
    """The report of ``coopkin analyze`` in the order it is computed and printed: each
    part's name and a function giving its lines. The numbers come first; the sentences
    and the blocks (which may take long) after them.

    Example
    -------
    >>> from coopkin_sym import load
    >>> [name for name, _ in analysis_parts(load("paper-case1-hard").analyze())]
    ['numbers', 'sentences', 'C11', 'C12', 'C22', 'C23']
    """
    def head() -> list[str]:
        lines = [f"System: {a.model.name}"]
        lines.append(f"Configuration: {configuration_words(a)}")
        twist = "(v_x, v_y, w_z), planar" if a.model.planar else "(v, w)"
        lines.append(f"Object twist {twist}: {object_frame_text(a.model.object_frame)}")
        lines.extend(snapped_lines(a.model.snapped))
        lines.extend(urdf_note_lines(a.model.renamed, a.model.ignored))
        if a.variables:
            lines.append(f"Symbols: {', '.join(map(str, a.variables))}"
                         + (" (t_q = tan(q/2))" if any(str(v).startswith("t_")
                                                      for v in a.variables) else ""))
        n = a.numbers
        lines.append("")
        lines.append("  ".join(f"{k} = {v}" for k, v in n.as_dict().items()))
        doubt = certificate_text(a.certificate)
        if doubt:
            lines.append(doubt)
        lines.append(classes_text(n))
        return lines

    def said() -> list[str]:
        lines = [""] + [f"- {s}" for s in sentences(a)]
        if a.model.passive_joints:
            lines.append("")
            lines.extend(passive_lines(a.passive))
        return lines

    def block(name: str) -> Callable[[], list[str]]:
        def lines() -> list[str]:
            out = [""]
            blocks, omitted = a.available_blocks()
            mat = blocks[name]
            if mat is None:
                out.append(f"{name}: not shown: {omitted[name]}")
                if name == "C22":
                    out.extend(factored_lines(a.coordinated_factored()))
                return out
            labels = list(a.model.twist_names if name in ("C11", "C12")
                          else a.model.joint_names)
            out.append(f"{name} ({mat.rows} x {mat.cols})"
                       + (": empty" if mat.cols == 0 else ""))
            if mat.cols:
                out.extend(block_table(mat, labels))
            return out
        return lines

    return [("numbers", head), ("sentences", said)] + [
        (name, block(name)) for name in ("C11", "C12", "C22", "C23")]


def analysis_text(a: Analysis) -> str:
    """The human report of ``coopkin analyze``: numbers, sentences and blocks (the
    parts of :func:`analysis_parts`, joined).

    Example
    -------
    >>> from coopkin_sym import load
    >>> print(analysis_text(load("paper-case1-hard").analyze()).splitlines()[0])
    System: paper case 1, hard/hard
    """
    return "\n".join(line for _, part in analysis_parts(a) for line in part())


def factored_lines(f: FactoredMotions) -> list[str]:
    """The coordinated joint motions in factored form, as text: each arm's map ``K``
    (``qdot_arm = K u`` for every column ``u`` of ``C12``) and the named factors of
    the denominators.

    Example
    -------
    >>> from coopkin_sym import load
    >>> f = load("planar-two-fingers").analyze(generic=True).coordinated_factored()
    >>> print("\\n".join(factored_lines(f)[:2]))
    C22 factored: the joint velocities of each arm are K_arm u for each column u of C12
    K_left (rows: joints; columns: v_x, v_y, w_z)
    """
    out = ["C22 factored: the joint velocities of each arm are K_arm u for each column u "
           "of C12"]
    maps = f.maps()
    for arm in f.arms:
        out.append(f"K_{arm.name} (rows: joints; columns: {', '.join(f.twist_names)})")
        out.extend(block_table(maps[arm.name], list(arm.joints)))
    if f.factors:
        out.append("where")
        out.extend(f"  {name} = {sp.sstr(poly)}" for name, poly in f.factors)
    return out


def factored_document(f: FactoredMotions) -> dict:
    """The factored coordinated motions as plain data (``factored`` of
    ``coopkin analyze --json``)."""
    maps = f.maps()
    return {
        "arms": [{"name": arm.name, "joints": list(arm.joints),
                  "map": [[sp.sstr(e) for e in maps[arm.name].row(i)]
                          for i in range(len(arm.joints))]} for arm in f.arms],
        "factors": [{"name": name, "polynomial": sp.sstr(poly)} for name, poly in f.factors],
    }


def certificate_text(certificate) -> str | None:
    """One sentence when the numbers are not certified (``None`` when they are).

    Example
    -------
    >>> from coopkin_sym.analysis.generic import NumbersCertificate, RankBound
    >>> cert = NumbersCertificate.from_ranks(
    ...     [RankBound("Q", 6, "size"), RankBound("Gt", 5, "sampled")], 2, 118)
    >>> print(certificate_text(cert))
    Probabilistic numbers: rank Gt is the exact rank at 2 random points, not certified; \
the chance that a number is wrong is below 2^-118.
    """
    if certificate.exact:
        return None
    open_ranks = [r.matrix for r in certificate.ranks if not r.certified]
    verb = "is" if len(open_ranks) == 1 else "are"
    ranks = "rank " + ", ".join(open_ranks)
    return (f"Probabilistic numbers: {ranks} {verb} the exact rank at {certificate.points} "
            f"random points, not certified; the chance that a number is wrong is below "
            f"2^-{certificate.error_bits}.")


def snapped_lines(snapped) -> list[str]:
    """What was snapped to exact values when URDF files were read, one line each.

    Example
    -------
    >>> from coopkin_sym.model.urdf import Snapped
    >>> snapped_lines([Snapped("arms[0] (f.urdf): joint 'pip' origin rpy[2]", "1.5708",
    ...                        "pi/2", 3.67e-06)])[1]
    "  arms[0] (f.urdf): joint 'pip' origin rpy[2]: 1.5708 -> pi/2 (3.7e-06 rad away)"
    """
    if not snapped:
        return []
    return [f"Snapped: {len(snapped)} float{'' if len(snapped) == 1 else 's'} of URDF "
            "files replaced by exact values (the analysis is exact for those):",
            *(f"  {s.where}: {s.given} -> {s.exact} ({s.error:.2g} rad away)"
              for s in snapped)]


def urdf_note_lines(renamed, ignored) -> list[str]:
    """The names of URDF files given safe names, and the joints off the arms' chains
    that were ignored, one line each.

    Example
    -------
    >>> from coopkin_sym.model.urdf import IgnoredJoint, Renamed
    >>> lines = urdf_note_lines([Renamed("arms[0] (h.urdf)", "joint", "j_0.0", "j_0_0")],
    ...     [IgnoredJoint("arms[1] (p.urdf)", "finger2", "prismatic", "finger1")])
    >>> lines[1], lines[3]
    ("  arms[0] (h.urdf): joint 'j_0.0' is j_0_0", "  arms[1] (p.urdf): joint 'finger2' \
('prismatic', mimics 'finger1')")
    """
    lines = []
    if renamed:
        lines.append(f"Renamed: {len(renamed)} name{'' if len(renamed) == 1 else 's'} of "
                     f"URDF files that are not usable names (write the new name, e.g. in "
                     f"--at or link: ARM/LINK):")
        lines.extend(f"  {r.where}: {r.what} {brief(r.given)} is {r.name}" for r in renamed)
    if ignored:
        lines.append(f"Ignored: {len(ignored)} joint{'' if len(ignored) == 1 else 's'} of "
                     f"URDF files off the arms' chains, left out (an arm cannot have "
                     f"them: mimic, floating, planar or of an unknown type):")
        for j in ignored:
            what = brief(j.type) if j.type is not None else "no type"
            if j.mimics is not None:
                what += f", mimics {brief(j.mimics)}"
            lines.append(f"  {j.where}: joint {brief(j.joint)} ({what})")
    return lines


def object_frame_text(frame) -> str:
    """Where object twists are referenced and in which axes, in words.

    Example
    -------
    >>> object_frame_text(None)
    'v at the base origin, in base axes'
    >>> import sympy as sp
    >>> yaw = sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    >>> print(object_frame_text((yaw, (1, 0, 0))).replace(", x'", ",\\n  x'"))
    v at the object point (1, 0, 0), in the object axes,
      x' = (0, 1, 0), y' = (-1, 0, 0), z' = (0, 0, 1)
    """
    if frame is None:
        return "v at the base origin, in base axes"
    rotation, origin = frame
    point = ", ".join(sp.sstr(x) for x in origin)
    axes = ", ".join(f"{name}' = ({', '.join(sp.sstr(x) for x in rotation[:, k])})"
                     for k, name in enumerate("xyz"))
    if rotation == sp.eye(3):
        return f"v at the object point ({point}), in base axes"
    return f"v at the object point ({point}), in the object axes, {axes}"


def _is_monomial(a: sp.Expr) -> bool:
    return all(f.is_Number or f.is_Symbol or (f.is_Pow and f.base.is_Symbol)
               for f in sp.Mul.make_args(a))


def _terms(p: sp.Expr) -> int:
    """The number of terms of ``p`` expanded (counted without expanding when it is a
    sum of monomials already, as the blocks are)."""
    args = sp.Add.make_args(p)
    if all(_is_monomial(a) for a in args):
        return len(args)
    return len(sp.Add.make_args(sp.expand(p)))


def _cell(e: sp.Expr, width: int = 48) -> str:
    """An entry as text, or its size when it is too long to read in a table."""
    num, den = sp.fraction(e)
    # a sum of more than width/3 terms cannot be written in width characters (each
    # term takes one and each " + " three): no need to print it to know
    if len(sp.Add.make_args(num)) * 4 - 3 <= width:
        text = sp.sstr(e)
        if len(text) <= width:
            return text
    extra = "" if den == 1 else f"/{_terms(den)}"
    return f"<{_terms(num)}{extra} terms>"


def block_table(mat: sp.Matrix, labels: list[str]) -> list[str]:
    """A matrix as aligned text rows, each led by its label."""
    cells = [[_cell(mat[i, j]) for j in range(mat.cols)] for i in range(mat.rows)]
    widths = [max(len(cells[i][j]) for i in range(mat.rows)) for j in range(mat.cols)]
    lw = max(len(x) for x in labels)
    return [f"  {labels[i]:>{lw}} | " + "  ".join(c.rjust(w) for c, w in zip(row, widths,
                                                                          strict=True))
            for i, row in enumerate(cells)]


def _latex_comment(text: str) -> str:
    """``text`` as one LaTeX comment line (control characters cannot end it)."""
    return r"% " + " ".join(re.sub(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]", " ", text).split())


def analysis_latex(a: Analysis) -> str:
    """The numbers and blocks of an analysis as LaTeX.

    Example
    -------
    >>> from coopkin_sym import load
    >>> print(analysis_latex(load("paper-case1-hard").analyze()).splitlines()[1])
    $N_{m} = 2$, $N_{c} = 2$, $N_{i} = 1$, $N_{r} = 0$, $N_{g} = 1$, $N_{d} = 4$, $N_{h} = 0$
    """
    head = f"{a.model.name} at {a.configuration.at_text() or 'home'}"
    out = [_latex_comment(head)]
    out.append(", ".join(f"$N_{{{k[1:]}}} = {v}$" for k, v in a.numbers.as_dict().items()))
    out.append(r"% " + classes_text(a.numbers))
    if a.model.passive_joints:
        out.append(", ".join(f"$N_{{{k[1:]}}} = {v}$"
                             for k, v in a.passive.numbers.as_dict().items())
                   + "  % " + "; ".join(f"N{k[1:]}: {w}" for k, w in PASSIVE_WORDS.items()))
    blocks, omitted = a.available_blocks()
    for name, mat in blocks.items():
        if mat is None:
            out.append(f"% {name} not shown: {omitted[name]}")
            continue
        body = sp.latex(mat) if mat.cols else r"\emptyset"
        out.append(rf"\[ C_{{{name[1:]}}} = {body} \]")
    return "\n".join(out)


def irrational_text(result: IrrationalAnalysis) -> str:
    """The human report of ``coopkin analyze`` at a configuration with irrational
    coordinates.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")
    >>> print(irrational_text(a).splitlines()[1])
    Configuration: q1=-pi/6,q2=pi/6
    """
    at = assignments_text(result.at)
    tangents = ", ".join(f"tan({k}/2) = {v}" for k, v in result.tangents.items())
    lines = [f"System: {result.system}", f"Configuration: {at}",
             f"Irrational: {tangents}; exact over Q(alpha), alpha = {result.alpha}, a root "
             f"of {result.minimal_polynomial} (every conjugate point at once)", "",
             "  ".join(f"{k} = {v}" for k, v in result.numbers.as_dict().items()),
             classes_text(result.numbers), ""]
    lines += [f"- {s}" for s in irrational_sentences(result)]
    if result.passive is not None:
        lines += ["", "Passive-joint numbers: " + passive_numbers_text(result.passive)]
    lines += ["", "Blocks: not computed at a configuration with irrational coordinates "
                  "(the numbers are exact; use a rational configuration for C11..C23)."]
    return "\n".join(lines)


def irrational_latex(result: IrrationalAnalysis) -> str:
    """The numbers at a configuration with irrational coordinates as LaTeX (the blocks
    are not computed there, and a comment says so).

    Example
    -------
    >>> from coopkin_sym import load
    >>> lines = irrational_latex(load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6"))
    >>> print("\\n".join(lines.splitlines()[:2]))
    % paper case 1, hard/hard at q1=-pi/6,q2=pi/6
    $N_{m} = 3$, $N_{c} = 3$, $N_{i} = 3$, $N_{r} = 0$, $N_{g} = 3$, $N_{d} = 4$, $N_{h} = 1$
    """
    at = assignments_text(result.at)
    head = f"{result.system} at {at}"
    out = [_latex_comment(head)]
    out.append(", ".join(f"$N_{{{k[1:]}}} = {v}$" for k, v in result.numbers.as_dict().items()))
    out.append(r"% " + classes_text(result.numbers))
    out.append("% blocks not computed at a configuration with irrational coordinates")
    return "\n".join(out)


#: The top-level keys of ``coopkin analyze --json``, in order, on every path; ``passive``
#: follows for a model with passive joints (docs/analyze-json.md).
JSON_KEYS = ("system", "configuration", "point", "variables", "joints", "twist", "numbers",
             "classes", "blocks", "shapes", "coordinated_form", "object_frame", "snapped",
             "renamed", "ignored", "field", "omitted", "meaning", "certificate", "factored",
             "finite")

# why the finite mobility is not in an analysis document
_FINITE_NOT_ASKED = "not computed: ask for it with coopkin analyze --finite"

# the numbers at an irrational point: exact ranks over the number field
_EXACT_IN_FIELD = {"exact": True, "error_bits": None, "points": 0, "ranks": []}

# why the subspaces of the passive joints are not given at an irrational point
_IRRATIONAL_PASSIVE = ("at a configuration with irrational coordinates only the "
                       "passive-joint numbers are computed")
# why the coordinated form is not given when a block is omitted
_FORM_OMITTED = "not given when a block is omitted"


def analysis_document(result: Analysis | IrrationalAnalysis, finite=None) -> dict:
    """The data of ``coopkin analyze --json``: the same keys (:data:`JSON_KEYS`, then
    ``passive`` for a model with passive joints) at a rational point, generically and
    at irrational angles; a value not computed is null (or empty) and ``omitted``
    says why, by key (a block name ``C11``..``C23``, ``coordinated_form``,
    ``passive``). The schema: ``docs/analyze-json.schema.json``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> data = analysis_document(load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6"))
    >>> data["point"], data["blocks"]["C11"], sorted(data["omitted"])[:2]
    ('irrational', None, ['C11', 'C12'])
    >>> list(analysis_document(load("paper-case1-hard").analyze())) == list(JSON_KEYS)
    True
    """
    data = result.as_json()
    omitted = dict(data.get("omitted") or {})
    if not isinstance(result, Analysis):  # an IrrationalAnalysis
        omitted.update(dict.fromkeys(data["blocks"], _IRRATIONAL_OMITTED))
        omitted["coordinated_form"] = _IRRATIONAL_OMITTED
        if "passive" in data:
            omitted["passive"] = _IRRATIONAL_PASSIVE
        meaning = irrational_sentences(result)
        data["certificate"] = _EXACT_IN_FIELD
        data["factored"] = None
    else:
        if data["coordinated_form"] is None:
            omitted["coordinated_form"] = _FORM_OMITTED
        meaning = sentences(result)
        data["factored"] = (factored_document(result.coordinated_factored())
                            if "C22" in omitted else None)
    if finite is None:
        omitted["finite"] = _FINITE_NOT_ASKED
        data["finite"] = None
    else:
        from coopkin_sym.present.finite import finite_json
        data["finite"] = finite_json(finite)
    data.update(omitted=omitted, meaning=meaning, **urdf_notes_json(result.model))
    out = {k: data[k] for k in JSON_KEYS}
    if "passive" in data:
        out["passive"] = data["passive"]
    return out


def urdf_notes_json(model) -> dict[str, list[dict]]:
    """The names of URDF files given safe names (``renamed``) and the joints off an
    arm's chain that were left out (``ignored``), as plain data.

    Example
    -------
    >>> from coopkin_sym import load
    >>> urdf_notes_json(load("urdf-two-fingers").model)
    {'renamed': [], 'ignored': []}
    """
    renamed = getattr(model, "renamed", ()) if model is not None else ()
    ignored = getattr(model, "ignored", ()) if model is not None else ()
    return {"renamed": [{"where": r.where, "what": r.what, "given": r.given, "name": r.name}
                        for r in renamed],
            "ignored": [{"where": i.where, "joint": i.joint, "type": i.type,
                         "mimics": i.mimics} for i in ignored]}


def analysis_json(result: Analysis | IrrationalAnalysis,
                  finite: FiniteMobility | None = None) -> str:
    """What ``coopkin analyze --json`` prints: :func:`analysis_document` as text (with
    the finite mobility ``finite`` when given: ``--finite``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> data = json.loads(analysis_json(load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6")))
    >>> data["numbers"]["Nm"], data["configuration"], data["field"]["alpha"]
    (3, 'q1=-pi/6,q2=pi/6', '-2 + sqrt(3)')
    """
    return json.dumps(analysis_document(result, finite), indent=2)
