"""Kinematic manipulability, exactly: which object velocities unit joint velocities
produce, as an ellipsoid (Bicchi, Melchiorri and Balluchi, "On the mobility and
manipulability of general multiple limb robots", IEEE T-RA 1995, after Yoshikawa's
ellipsoid of one arm).

With passive joints (``actuated: false``) only the motors' speeds count: from a
basis ``[Y; X; .]`` of ``N(Q)`` (``X`` its motor rows), the motions that move no motor
(``N(X)``) are free, their object part ``Y N(X)`` (the uncontrolled motions of
:mod:`coopkin_sym.analysis.passive`) takes the place of ``C11`` below, and ``C12``,
``A`` become ``Y K1`` and ``(X K1)^T X K1`` with ``K1`` a basis of the row space of
``X``. With every joint actuated this is the formula below.

The joint velocities that keep every contact are ``qdot = C22 x + C23 y``; they move
the object by ``u = C12 x + C11 z`` (``z``, the indeterminate motions, is not driven
by the joints: the object motion is known modulo ``C11``, and the ellipsoid is of its
part orthogonal to ``C11`` in the weighted metric below, a choice that does not depend
on the basis). The least
joint speed that gives the coordinated motion ``x`` removes the redundant part::

    min_y |C22 x + C23 y|^2 = x^T A x,   A = C22^T C22 - C22^T C23 (C23^T C23)^-1 C23^T C22

(the Schur complement of ``C23^T C23`` in the Gram matrix of ``[C23, C22]``; ``A`` is
positive definite because the coordinated columns meet ``N(Q)`` only in 0). The
object velocities reached with ``|qdot| <= 1`` are the ellipsoid
``{C12 x : x^T A x <= 1}``. Of a chosen set of object-velocity components ``S u``
(``controlled``), weighted so that angular velocities count in length units (``w``
times a characteristic ``length``, so that linear and angular parts are not mixed
blindly), the ellipsoid is ``{y : y^T E^+ y <= 1}`` on the range of

    E = S P W C12 A^-1 C12^T W P^T S^T    (W = diag(1, 1, 1, length, length, length),
                                          P: projector along W C11),

the analogue of ``J J^T`` for one arm: its eigenvalues are the squared semi-axes,
``det E`` the squared manipulability index, exact (rational functions of the free
joint variables and parameters, or rationals at a point). ``E`` loses rank where some
controlled direction cannot be driven any more: the numerator of ``det E``, factored,
is its degeneracy locus in the chosen directions.

Over rational functions every entry made on the way (of ``A``, ``A^-1``, the
projected columns, ``E`` and ``det E``) is held to a budget of terms, ``max_terms``
(numerator and denominator; default :data:`MAX_TERMS`): past it the computation stops
at once with a :class:`~coopkin_sym.errors.BlockTooLarge` that names the step, the
size reached and the budget (``coopkin manipulability --max-terms N``; it then exits
with status 3, as a run cut by its time bound).

Example
-------
>>> from coopkin_sym import load
>>> m = load("paper-case1-soft").analyze("L=2").manipulability()
>>> m.shape[0, 0], m.rank
(2, 1)
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from coopkin_sym.analysis.kinematics import PLANAR_COLUMNS, spatial_twist
from coopkin_sym.analysis.renderers import Displayable, clip
from coopkin_sym.errors import BlockTooLarge, ManipulabilityError
from coopkin_sym.exact import matrix as exact_matrix
from coopkin_sym.exact.field_matrix import FieldMatrix
from coopkin_sym.exact.parse import NumberError, exact_expr

#: The default budget of terms of one entry of the ellipsoid's exact matrices (its
#: numerator and denominator): a generic ellipsoid within it is computed in seconds.
MAX_TERMS = 10_000


@dataclass(frozen=True)
class Manipulability(Displayable):
    """The manipulability ellipsoid of the controlled object velocities.

    Attributes
    ----------
    controlled
        The object-velocity components the ellipsoid is of (names of the model's
        twist, e.g. ``("v_x", "v_y", "v_z")``).
    length
        The characteristic length angular velocities are scaled by (exact).
    form
        ``A`` (k x k, k = Nc - Ni): the least squared joint speed of each coordinated
        motion ``x`` is ``x^T A x``.
    shape
        ``E`` (one row and column per controlled component): the ellipsoid is
        ``{y : y^T E^+ y <= 1}`` on the range of ``E``; exact.
    index
        ``det E``, the squared manipulability index (0 when ``E`` loses rank).
    rank
        The rank of ``E``: how many controlled directions the joints drive (generic
        rank for symbolic entries).
    degeneracy
        The factors of the numerator of ``det E`` that involve the free variables
        (``det E = 0`` on their zero sets); empty at a point or when ``E`` is singular
        everywhere.

    Example
    -------
    >>> from coopkin_sym import load
    >>> m = load("planar-two-fingers").analyze("L=1").manipulability(length=1)
    >>> m.controlled, m.rank
    (('v_x', 'v_y', 'w_z'), 3)
    >>> m
    <Manipulability of v_x, v_y, w_z (length 1): rank 3 of 3, det E = 1/8>

    Written as JSON and read back, it is the same result:

    >>> Manipulability.from_json(json.dumps(m.to_json())) == m
    True
    """

    controlled: tuple[str, ...]
    length: sp.Expr
    form: sp.Matrix
    shape: sp.Matrix
    index: sp.Expr
    rank: int
    degeneracy: tuple[sp.Expr, ...]

    def __repr__(self) -> str:
        return (f"<Manipulability of {clip(', '.join(self.controlled), 80)} (length "
                f"{clip(sp.sstr(self.length), 30)}): rank {self.rank} of "
                f"{len(self.controlled)}, det E = {clip(sp.sstr(self.index), 100)}>")

    def to_json(self) -> dict:
        """Plain JSON data: every exact entry as text, and the assumptions of the
        symbols in them (``"positive"`` for a parameter, ``"real"`` for a joint
        variable); the schema is ``docs/manipulability.schema.json``.

        Example
        -------
        >>> from coopkin_sym import load
        >>> m = load("paper-case1-soft").analyze(generic=True).manipulability()
        >>> m.to_json()["symbols"]
        {'L': 'positive', 't_q1': 'real', 't_q2': 'real'}
        """
        exprs = [self.length, self.index, *self.form, *self.shape, *self.degeneracy]
        names = sorted({s for e in exprs for s in getattr(e, "free_symbols", ())}, key=str)
        return {"controlled": list(self.controlled), "length": sp.sstr(self.length),
                "form": _rows(self.form), "shape": _rows(self.shape),
                "index": sp.sstr(self.index), "rank": self.rank,
                "degeneracy": [sp.sstr(f) for f in self.degeneracy],
                "symbols": {s.name: _assumption(s) for s in names}}

    @classmethod
    def from_json(cls, data: Mapping | str) -> Manipulability:
        """The result of :meth:`to_json` (a tree, or its JSON text) read back: every
        entry checked, every exact text read by the package's one parser.

        Raises
        ------
        ManipulabilityError
            One line naming the first bad entry (``shape[0][1]: ...``).

        Example
        -------
        >>> Manipulability.from_json('{"rank": 1}')
        Traceback (most recent call last):
        ...
        coopkin_sym.errors.ManipulabilityError: not a manipulability result: controlled: missing
        """
        from coopkin_sym.analysis.saved import Entries
        entries = Entries(ManipulabilityError, "not a manipulability result")
        return _from_tree(entries, entries.tree(data))

    @classmethod
    def read(cls, path: str | os.PathLike) -> Manipulability:
        """The result in the JSON file ``path`` written by :meth:`write`."""
        from coopkin_sym.analysis.saved import Entries
        entries = Entries(ManipulabilityError, "not a manipulability result")
        return _from_tree(entries, entries.file(path))

    def write(self, path: str | os.PathLike) -> None:
        """Write :meth:`to_json` to ``path`` as JSON (read it back with :meth:`read`).

        Example
        -------
        >>> import tempfile, pathlib
        >>> from coopkin_sym import load
        >>> m = load("paper-case1-soft").analyze().manipulability()
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.json"
        >>> m.write(path)
        >>> Manipulability.read(path) == m
        True
        """
        with open(path, "w", encoding="utf-8") as out:
            json.dump(self.to_json(), out, indent=2)
            out.write("\n")


_KEYS = ("controlled", "length", "form", "shape", "index", "rank", "degeneracy", "symbols")
_ASSUMPTIONS = {"positive": {"positive": True}, "real": {"real": True}, "none": {}}


def _rows(matrix: sp.Matrix) -> list[list[str]]:
    return [[sp.sstr(x) for x in matrix.row(i)] for i in range(matrix.rows)]


def _assumption(symbol: sp.Symbol) -> str:
    return "positive" if symbol.is_positive else "real" if symbol.is_real else "none"


def _from_tree(e, tree: Mapping) -> Manipulability:
    """A :class:`Manipulability` from its checked JSON tree (see ``from_json``)."""
    from coopkin_sym.exact.parse import parse_expression

    e.keys(tree, _KEYS, "")
    kinds = e.field(tree, "symbols", dict, "")
    symbols = {}
    for name, kind in kinds.items():
        if e.value(kind, str, f"symbols.{name}") not in _ASSUMPTIONS:
            raise e.fail(f"symbols.{name}", f"expected one of {', '.join(_ASSUMPTIONS)}")
        if not name.isidentifier():
            raise e.fail("symbols", f"not a name: {name!r}")
        symbols[name] = sp.Symbol(name, **_ASSUMPTIONS[kind])

    def expr(text: object, where: str) -> sp.Expr:
        try:
            return parse_expression(e.value(text, str, where), symbols, where)
        except NumberError as exc:
            raise e.fail("", str(exc)) from None

    controlled = tuple(e.texts(tree, "controlled", ""))
    k = len(controlled)
    square = []
    for key in ("form", "shape"):
        rows = e.field(tree, key, list, "")
        size = k if key == "shape" else len(rows)
        if len(rows) != size or any(not isinstance(r, list) or len(r) != size for r in rows):
            raise e.fail(key, f"expected a square matrix of {size} rows")
        entries = [[expr(x, f"{key}[{i}][{j}]") for j, x in enumerate(r)]
                   for i, r in enumerate(rows)]
        square.append(_in_one_field([sp.Matrix(size, size, sum(entries, []))])[0])
    form, shape = (sp.ImmutableMatrix(m.to_Matrix()) for m in square)
    index = sp.factor(expr(tree["index"], "index"))
    rank = e.field(tree, "rank", int, "")
    if not 0 <= rank <= k:
        raise e.fail("rank", f"expected 0 to {k}, got {rank}")
    degeneracy = tuple(expr(f, f"degeneracy[{i}]")
                       for i, f in enumerate(e.field(tree, "degeneracy", list, "")))
    return Manipulability(controlled, expr(tree["length"], "length"), form, shape, index,
                          rank, degeneracy)


def manipulability(analysis, controlled: Sequence[str] | None = None,
                   length=1, point: Sequence | None = None, *,
                   max_terms: int | None = MAX_TERMS) -> Manipulability:
    """The manipulability ellipsoid of ``analysis`` for the object-velocity components
    ``controlled`` (default: all of the model's twist), angular parts scaled by
    ``length`` (a positive exact number or a parameter of the model, e.g. ``"L"``).
    With ``point`` (exact base coordinates), ``v`` is the velocity of that point of
    the object, in base axes; else the twist is as the analysis writes it (its object
    frame). ``max_terms``: the budget of terms of an entry on the way (None: none).

    Raises
    ------
    ManipulabilityError
        An unknown component name, a length that is not positive and exact, or a
        budget that is not a positive integer.
    BlockTooLarge
        An entry over the budget of terms: the step, the size and the budget named.
    """
    max_terms = _checked_budget(max_terms)
    names = analysis.model.twist_names
    controlled, ell = _controlled_and_length(analysis, names, controlled, length)
    if analysis.model.passive_joints:
        c12, gram, c11 = _motor_parts(analysis)
        parts = None
    else:
        c12, c11 = analysis.C12, analysis.C11
        parts = (analysis.C22, analysis.C23)
    if point is not None:
        c12, c11 = (_at_point(analysis, c, point) for c in (c12, c11))
    weight = sp.diag(*[sp.Integer(1) if n.startswith("v") else ell for n in names])
    rows = [names.index(c) for c in controlled]
    # all the arithmetic in one exact field of rational functions (DomainMatrix)
    mats = [c12, c11, weight] + (list(parts) if parts else [gram])
    gram, driven, shape_dm, det = _ellipsoid(_in_one_field(mats), bool(parts), rows,
                                             max_terms)
    field = gram.domain
    form = sp.ImmutableMatrix(gram.to_Matrix())
    shape = sp.ImmutableMatrix(shape_dm.to_Matrix())
    index = sp.factor(field.to_sympy(det)) if len(rows) else sp.Integer(1)
    # A is positive definite, so E has the rank of the driven rows (exact, over the
    # field of rational functions of the symbols)
    rank = exact_matrix.rank(driven, None, exact_matrix.SYMPY) if driven.shape[1] else 0
    return Manipulability(controlled, ell, form, shape, index, rank, _degeneracy(index))


def _controlled_and_length(analysis, names: Sequence[str], controlled, length):
    """The controlled object motions (checked) and the exact positive length."""
    if isinstance(controlled, str):
        controlled = ()
    controlled = tuple(names if controlled is None else controlled)
    if not controlled:
        raise ManipulabilityError("controlled: expected a non-empty list of object "
                                  f"motions from {', '.join(names)}")
    for c in controlled:
        if c not in names:
            raise ManipulabilityError(f"controlled: unknown object motion {c!r} (the "
                                      f"object twist has {', '.join(names)})")
    if len(set(controlled)) != len(controlled):
        raise ManipulabilityError("controlled: a motion is named twice")
    symbols = {p.name: p for p in analysis.model.parameters}
    try:
        ell = exact_expr(length, symbols, "length")
    except NumberError as exc:
        raise ManipulabilityError(str(exc)) from None
    if ell.is_positive is not True:
        raise ManipulabilityError(f"length: expected a positive length (a number or a "
                                  f"parameter such as L), got {sp.sstr(ell)}")
    return controlled, ell


def _checked_budget(max_terms: object) -> int | None:
    if max_terms is None:
        return None
    if isinstance(max_terms, bool) or not isinstance(max_terms, int) or max_terms < 1:
        raise ManipulabilityError(f"max_terms: expected a positive integer (terms of an "
                                  f"entry) or None, got {clip(repr(max_terms), 40)}")
    return max_terms


def _step(what: str, work):
    """``work()``; an entry over the budget of terms is said to be of ``what``."""
    try:
        return work()
    except BlockTooLarge as exc:
        raise BlockTooLarge(f"manipulability: {what}: {exc} (terms of its numerator and "
                            "denominator; max_terms= or --max-terms N raises it); the "
                            "ellipsoid is not computed") from None


def _ellipsoid(dms: list[DomainMatrix], with_parts: bool, rows: list[int],
               max_terms: int | None = None):
    """``(gram, driven, shape, det shape)`` from the matrices ``C12, C11, W`` and either
    ``C22, C23`` or the motor Gram matrix, all over one field (DomainMatrix); over
    rational functions each entry made is held to ``max_terms``."""
    field = dms[0].domain
    # over a field of rational functions, the products, inverses and the determinant
    # are done with python-flint (SymPy's own gcds take minutes on these entries)
    flint_field = bool(getattr(field, "is_FractionField", False))
    if flint_field:
        c12, c11, weight, *rest = _step("the blocks", lambda: [
            FieldMatrix.of(d, max_terms) for d in dms])
    else:
        c12, c11, weight, *rest = dms
    if with_parts:
        c22, c23 = rest

        def schur():
            gram = c22.transpose() * c22
            if c23.shape[1]:
                cross = c23.transpose() * c22
                gram = gram - cross.transpose() * (c23.transpose() * c23).inv() * cross
            return gram
        gram = _step("the Gram matrix A of the coordinated joint motions", schur)
    else:
        (gram,) = rest
    driven = weight * c12
    if c11.shape[1] and driven.shape[1]:
        # modulo the indeterminate motions: the part W-orthogonal to W C11
        free = weight * c11
        driven = _step("the driven object motions modulo the indeterminate ones",
                       lambda: driven - free * (free.transpose() * free).inv() * (
                           free.transpose() * driven))
    driven = _rows_of(driven, rows)
    if driven.shape[1]:
        inverse = _step("the inverse of A", gram.inv)
        shape_dm = _step("E", lambda: driven * inverse * driven.transpose())
    else:
        shape_dm = None
    det = None
    if flint_field:
        if len(rows) and shape_dm is not None:
            det = _step("det E", shape_dm.det_element)
        gram, driven = gram.to_domain_matrix(), driven.to_domain_matrix()
        shape_dm = None if shape_dm is None else shape_dm.to_domain_matrix()
    if shape_dm is None:
        shape_dm = DomainMatrix.zeros((len(rows), len(rows)), field)
    if det is None and len(rows):
        det = shape_dm.det()
    return gram, driven, shape_dm, det


def _rows_of(m, rows: list[int]):
    """The rows ``rows`` of ``m`` (a :class:`DomainMatrix` or a :class:`FieldMatrix`)."""
    if isinstance(m, FieldMatrix):
        return FieldMatrix([m.rows[r] for r in rows], (len(rows), m.shape[1]), m.field,
                           m.ctx, m.max_terms)
    return m.extract(rows, list(range(m.shape[1])))


def _in_one_field(mats: Sequence[sp.Matrix]) -> list[DomainMatrix]:
    """The matrices as :class:`DomainMatrix` over one field (rationals, or rational
    functions of their symbols): exact, and far faster than SymPy expressions."""
    dms = [DomainMatrix.from_Matrix(sp.Matrix(m)) if m.rows * m.cols else None
           for m in mats]
    domain = None
    for d in dms:
        if d is not None:
            domain = d.domain if domain is None else domain.unify(d.domain)
    field = (domain if domain is not None else sp.QQ).get_field()
    return [d.convert_to(field) if d is not None
            else DomainMatrix.zeros(m.shape, field) for d, m in zip(dms, mats, strict=True)]


def _motor_parts(analysis) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """With passive joints: object twists ``Y K1``, the form ``A = (X K1)^T X K1`` and
    the uncontrolled twists ``Y K0``, from a basis ``[Y; X; .]`` of ``N(Q)`` (``X`` its
    motor rows), ``K0`` a basis of ``N(X)`` and ``K1`` one of the row space of ``X``:
    motor speed is ``|X K1 x|``, and motions in ``K0`` cost none."""
    d = analysis.dim
    c = sp.Matrix(analysis.C)
    motors = [d + k for k, j in enumerate(analysis.model.joints) if j.actuated]
    y, x = c[:d, :], c.extract(motors, list(range(c.cols)))
    if not x.rows or not c.cols:
        return sp.zeros(d, 0), sp.zeros(0, 0), y
    xt = DomainMatrix.from_Matrix(x.T)
    _, pivots = xt.rref()
    k1 = x.T.extract(list(range(c.cols)), list(pivots))
    k0 = DomainMatrix.from_Matrix(x).nullspace().to_Matrix().T \
        if len(pivots) < c.cols else sp.zeros(c.cols, 0)
    drive = (x * k1).applyfunc(sp.cancel)
    return (y * k1).applyfunc(sp.cancel), drive.T * drive, (y * k0).applyfunc(sp.cancel)


def _at_point(analysis, columns: sp.Matrix, point: Sequence) -> sp.Matrix:
    """Twist columns as ``(velocity of point, w)`` in base axes."""
    p = sp.Matrix([exact_expr(x, {s.name: s for s in analysis.model.parameters},
                              f"point[{i}]") for i, x in enumerate(point)])
    if p.rows != 3:
        raise ManipulabilityError(f"point: expected three coordinates, got {p.rows}")
    out = []
    for k in range(columns.cols):
        u = spatial_twist(analysis.twist_in_base(columns.col(k)))
        v = sp.Matrix(u[:3]) + sp.Matrix(u[3:]).cross(p)
        moved = [*v, *u[3:]]
        out.append([sp.expand(moved[c]) for c in (PLANAR_COLUMNS if analysis.model.planar
                                                  else range(6))])
    return sp.Matrix(out).T if out else columns


def _degeneracy(index: sp.Expr) -> tuple[sp.Expr, ...]:
    """The factors of the numerator of ``det E`` that may vanish."""
    num, _ = sp.fraction(sp.cancel(index))
    if num == 0 or not num.free_symbols:
        return ()
    _, factors = sp.factor_list(num)
    # a positive parameter alone (L) never vanishes
    return tuple(f for f, _ in factors if f.free_symbols
                 and not (f.is_Symbol and f.is_positive) and not _no_real_zero(f))


def _no_real_zero(f: sp.Expr) -> bool:
    """Whether a factor in one variable has no real zero (``t**2 + 1``), exactly."""
    symbols = f.free_symbols
    if len(symbols) != 1:
        return False
    return sp.Poly(f, *symbols).count_roots() == 0


__all__ = ["Manipulability", "manipulability"]
