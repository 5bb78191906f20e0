"""What a computed locus can do: prove itself complete, check itself, be written as a
report, drawn, and tabulated (the methods of
:class:`~coopkin_sym.analysis.locus.types.Locus`).

A locus from :meth:`System.locus <coopkin_sym.system.System.locus>` remembers the
system it was computed for (not part of its data: not in its ``repr``, its comparisons
or its JSON), so ``locus.certify()`` and ``locus.verify()`` need nothing more; a locus
read back from a report is given the system (``locus.verify(system=...)``). The
system does the work (:meth:`System.certify_locus
<coopkin_sym.system.System.certify_locus>`, :meth:`System.verify_locus
<coopkin_sym.system.System.verify_locus>`): the certificate and the check are built on
the locus, so this module cannot import them. Writing
and drawing belong to the presentation layer, which registers them
(:func:`coopkin_sym.analysis.renderers.register_action`); this module does not import
it.

Example
-------
>>> from coopkin_sym import load
>>> locus = load("paper-case1-hard").locus()
>>> [row["condition"] for row in locus.table()][:2]
['q1 = -pi/2, q2 = -pi/2', 'q1 = -pi/2, q2 = pi/2']
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from coopkin_sym.analysis.locus.families import Family, group_families
from coopkin_sym.analysis.numbers import NUMBER_NAMES
from coopkin_sym.analysis.renderers import action
from coopkin_sym.errors import ArgumentError, MissingDependency
from coopkin_sym.model.configuration import assignments_text

if TYPE_CHECKING:  # pragma: no cover
    from pathlib import Path

    from matplotlib.figure import Figure

# the certificate and the verification (analysis.locus.certify, .verify) are built on
# the locus: their classes are not imported here (no cycle), hence ``Any``
Certificate = Verification = Any


class LocusMethods:
    """The methods of a :class:`~coopkin_sym.analysis.locus.types.Locus` beyond its
    data. ``verification`` is the last :meth:`verify` (None before), which
    :meth:`write` puts in a JSON report.

    Example
    -------
    >>> from coopkin_sym import load
    >>> locus = load("paper-case1-hard").locus()
    >>> locus.verification is None, locus.table()[0]["Nm"]
    (True, 3)
    """

    #: The last verification of this locus (:meth:`verify`), or None.
    verification: Verification | None = None
    #: The system the locus was computed for (set by ``System.locus``), or None.
    _system: Any = None

    def _the_system(self, system: Any, what: str) -> Any:
        """The :class:`~coopkin_sym.system.System` to work with: the one given, else the
        one the locus was computed for."""
        system = system if system is not None else self._system
        if system is None:
            raise ArgumentError(f"Locus.{what}: this locus does not know its system (read "
                                f"back from a report?): give it, {what}(system=...)")
        if not hasattr(system, f"{what}_locus"):
            raise ArgumentError(f"Locus.{what}: system: expected a System (coopkin_sym."
                                f"load(...)), got {type(system).__name__}")
        return system

    def _locked_system(self, system: Any) -> Any:
        """The system with every motor held still, for the locked locus."""
        locked = getattr(self.locked, "_system", None)
        return locked if locked is not None else system.with_actuators_locked()

    def finite_mobility(self, order: int | None = None, *, system: Any = None) -> int:
        """The finite mobility at every witness, rational or algebraic (which singular
        families are bifurcations, shaky, or only first-order), kept in each component's ``finite``;
        how many were computed (see :meth:`coopkin_sym.system.System.finite_locus`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> locus = load("four-bar").locus()
        >>> locus.finite_mobility(), locus.components[0].finite["branches"]
        (4, [1, 1])
        """
        return self._the_system(system, "finite").finite_locus(self, order=order)

    def certify(self, timeout: float = 30.0, *, budget: float | None = 300.0,
                system: Any = None) -> Certificate:
        """Prove the locus complete by Gröbner bases (see
        :func:`~coopkin_sym.analysis.locus.certify.certify_locus`), or say why it is
        not proved; the certificate is kept on the locus (and on its locked locus,
        certified too).

        Parameters
        ----------
        timeout
            Seconds for each test.
        budget
            Seconds for the whole certificate.
        system
            The system, for a locus that does not know it.

        Example
        -------
        >>> from coopkin_sym import load
        >>> locus = load("paper-case1-hard").locus()
        >>> locus.certify(timeout=60).certified, locus.certified
        (True, True)
        """
        system = self._the_system(system, "certify")
        certificate = system.certify_locus(self, timeout=timeout, budget=budget)
        self._keep(certificate)
        if self.locked is not None:
            locked = self._locked_system(system).certify_locus(
                self.locked, timeout=timeout, budget=budget)
            self.locked._keep(locked)
        return certificate

    def _keep(self, certificate: Certificate) -> None:
        """Keep ``certificate`` (the exact dataclass) on the locus."""
        self.certificate = certificate

    def verify(self, *, system: Any = None, max_points: int = 50_000, lines: int = 12,
               seed: int = 0, timeout: float | None = None) -> Verification:
        """Check the locus independently (see
        :func:`~coopkin_sym.analysis.locus.verify.verify_locus`): exact numbers on a
        rational grid and on random rational lines must lie on a component with those
        numbers. The result is kept as :attr:`verification`; the locked locus (with
        passive joints) is verified too, on its own ``verification``.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").locus().verify(max_points=200, lines=2).ok
        True
        """
        system = self._the_system(system, "verify")
        options = {"max_points": max_points, "lines": lines, "seed": seed,
                   "timeout": timeout}
        self.verification = system.verify_locus(self, **options)
        if self.locked is not None:
            self.locked.verification = self._locked_system(system).verify_locus(
                self.locked, **options)
        return self.verification

    def write(self, path: str | os.PathLike, format: str | None = None, *,  # noqa: A002
              system: Any = None, pairs: Sequence[str | Sequence[str]] | None = None
              ) -> list[Path]:
        """Write the locus as a report (see :func:`coopkin_sym.present.report.write_report`):
        Markdown, HTML, LaTeX or JSON by ``path``'s suffix (``format``, ``"md"``,
        ``"html"``, ``"tex"`` or ``"json"``, must agree with it; a path without a
        suffix gets it), with its plots next to it. Returns the files written.

        Example
        -------
        >>> import tempfile, pathlib, json
        >>> from coopkin_sym import load
        >>> locus = load("paper-case1-hard").locus()
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> [p.name for p in locus.write(folder / "locus", "json")]
        ['locus.json']
        >>> json.loads((folder / "locus.json").read_text())["generic"]["Nm"]
        2
        """
        system = system if system is not None else self._system
        return action(self, "write")(path, format, system=system, pairs=pairs)

    def plot(self, pair: Sequence[str] | None = None, *, system: Any = None,
             by: str = "auto") -> Figure:
        """A matplotlib figure of the real components on a pair of joint variables
        (see :func:`coopkin_sym.present.locus_plot.plot_components`; default: the first
        pair that occurs together in a component), coloured ``by`` component or by
        family (``"auto"``: by family when many components are drawn).

        Example
        -------
        >>> from coopkin_sym import load
        >>> fig = load("paper-case1-hard").locus().plot()
        >>> len(fig.axes) >= 1
        True
        """
        system = system if system is not None else self._system
        return action(self, "plot")(pair, system=system, by=by)

    def table(self) -> list[dict[str, Any]]:
        """One plain row per component: its number (``#``, from 1), the component it
        lies in (``parent``, its number, or None), ``condition``, ``kind``, ``depth``,
        the seven numbers, ``changed`` (the names of those that differ from the generic
        ones), ``real``, and ``witness`` (``--at`` syntax: the rational witness, else
        the exact algebraic point, else None).

        Example
        -------
        >>> from coopkin_sym import load
        >>> row = load("paper-case1-hard").locus().table()[0]
        >>> row["#"], row["witness"], row["changed"], row["kind"]
        (1, 'q1=-pi/2,q2=-pi/2,L=1', ['Nm', 'Nc', 'Nh'], 'isolated')
        """
        rows = []
        for k, c in enumerate(self.components):
            point = c.witness or (c.algebraic_witness or {}).get("point")
            rows.append({
                "#": k + 1, "parent": None if c.parent is None else c.parent + 1,
                "condition": c.condition.text, "kind": c.kind, "depth": c.depth,
                **{n: c.numbers.get(n) for n in NUMBER_NAMES},
                "changed": [n for n in NUMBER_NAMES if n in c.changes], "real": c.real,
                "witness": assignments_text(point) if point
                else None})
        return rows

    def families(self) -> list[Family]:
        """The components grouped by their numbers: one
        :class:`~coopkin_sym.analysis.locus.families.Family` for each kind of singular
        configuration (what changes), with its members and the one to show first, in
        the order of their first member.

        Example
        -------
        >>> from coopkin_sym import load
        >>> locus = load("paper-case1-hard").locus()
        >>> [(f.changes, f.members) for f in locus.families()][0]
        ({'Nm': (2, 3), 'Nc': (2, 3), 'Nh': (0, 1)}, (0, 1, 2, 3))
        """
        return group_families(self.components, self.generic)

    def to_pandas(self):
        """:meth:`table` as a :class:`pandas.DataFrame`, one row per component (the
        generic numbers in ``attrs["generic"]``). Needs pandas (``pip install pandas``).

        Example
        -------
        >>> from coopkin_sym import load
        >>> frame = load("paper-case1-hard").locus().to_pandas()  # doctest: +SKIP
        >>> frame["Nm"].tolist()[:2]  # doctest: +SKIP
        [3, 3]
        """
        try:
            import pandas as pd
        except ImportError:
            raise MissingDependency("Locus.to_pandas needs pandas: pip install pandas") \
                from None
        rows = self.table()
        columns = ["#", "parent", "condition", "kind", "depth", *NUMBER_NAMES, "changed",
                   "real", "witness"]
        frame = pd.DataFrame(rows, columns=columns)
        frame.attrs["generic"] = dict(self.generic)
        return frame


__all__ = ["LocusMethods"]
