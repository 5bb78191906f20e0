"""The public facade: a loaded system and everything the package can do with it.

:class:`System` gathers the layers below: ``analyze`` (at rational or algebraic
configurations, or generically), ``locus`` (where the numbers change), ``sweep``
(exact numbers at many points) and ``draw`` (a picture). Every method takes a
configuration the same way: ``at`` as ``--at`` text (``"q1=pi/2,L=1000"``) or a mapping.

Example
-------
>>> from coopkin_sym import load
>>> system = load("paper-case2-hard")
>>> system.analyze().numbers.as_dict()["Nm"]
8
>>> system.analyze(generic=True).numbers.Nc
6
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from concurrent.futures import Executor
from typing import TYPE_CHECKING, Any, TypeVar

from coopkin_sym.analysis.mobility import Analysis, analyze
from coopkin_sym.analysis.renderers import clip
from coopkin_sym.errors import ConfigurationError, NotIrrational
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model, load_model

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from coopkin_sym.analysis.batch import BatchResult
    from coopkin_sym.analysis.finite import FiniteMobility
    from coopkin_sym.analysis.irrational import IrrationalAnalysis
    from coopkin_sym.analysis.locus.certify import Certificate
    from coopkin_sym.analysis.locus.types import Locus
    from coopkin_sym.analysis.locus.verify import Verification
    from coopkin_sym.present.interactive import InteractiveView

T = TypeVar("T")


class System:
    """A validated cooperating robot system, ready to analyze.

    Parameters
    ----------
    model
        The validated model (see :func:`coopkin_sym.model.model.load_model`).

    Example
    -------
    >>> system = load("paper-case1-hard")
    >>> system
    System('paper case 1, hard/hard': 2 arms, 2 joints, 2 contacts)
    >>> system.analyze().numbers.Nm, system.locus().generic["Ni"]
    (2, 1)
    """

    def __init__(self, model: Model):
        self.model = model

    @property
    def name(self) -> str:
        return self.model.name

    @property
    def joint_names(self) -> tuple[str, ...]:
        return self.model.joint_names

    def configuration(self, at: str | Mapping | None = None,
                      free: Iterable[str] | str | None = None) -> Configuration:
        """Parse ``at`` (``"q1=pi/2,L=1000"`` or a mapping) and the free joints."""
        return Configuration.parse(self.model, at, free)

    def analyze(self, at: str | Mapping | Configuration | None = None, *,
                generic: bool = False, free: Iterable[str] | None = None,
                timeout: float | None = None) -> Analysis | IrrationalAnalysis:
        """Exact mobility and kinematic analysis.

        Parameters
        ----------
        at
            Values of joint variables (angles in SymPy syntax, displacements) and
            parameters; unset joints are at home (q = 0), unset parameters symbolic.
            An angle whose ``tan(q/2)`` is irrational but algebraic (``q1=-pi/6``) is
            analyzed exactly over the number field it generates: the result is then an
            :class:`~coopkin_sym.analysis.irrational.IrrationalAnalysis` (the numbers
            and, for a quadratic field, the motions behind ``Ni`` and ``Nr``).
        generic
            Keep every joint variable symbolic (the generic analysis over Q(t, L)).
        free
            Joint names to keep symbolic (the rest at their values).
        timeout
            Wall-clock bound in seconds on the analysis (its numbers, computed at once
            then, and the decomposition behind them), held even inside steps that
            cannot be interrupted (see :func:`coopkin_sym.exact.bounded.run_bounded`);
            past it
            :class:`~coopkin_sym.errors.TimeLimitReached` names the step.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6").numbers.Ni
        3
        >>> load("paper-case1-hard").analyze(generic=True, timeout=60).numbers.Nm
        2
        """
        if timeout is not None:
            from coopkin_sym.exact.bounded import run_bounded

            def numbers():
                result = self.analyze(at, generic=generic, free=free)
                result.numbers  # noqa: B018 - computed under the bound, kept in the result
                return result
            return run_bounded(numbers, timeout, owner="System.analyze")
        if isinstance(at, Configuration):
            return analyze(self.model, at)
        try:
            config = self.configuration(at, "all" if generic else free)
        except ConfigurationError as error:
            if generic or free or at is None:
                raise
            from coopkin_sym.analysis.irrational import analyze_irrational
            try:
                return analyze_irrational(self.model, at)
            except NotIrrational:
                raise error from None
        return analyze(self.model, config)

    def locus(self, at: str | Mapping | None = None, *, max_depth: int = 2,
              timeout: float | None = None, progress: bool = False,
              free: Iterable[str] | None = None, pi_size: int | None = None,
              certify: bool = False, verify: bool = False) -> Locus:
        """Where the numbers change: every family of configurations whose numbers
        differ from the generic ones (see
        :func:`coopkin_sym.analysis.locus.search.compute_locus`).

        With ``certify``, the locus is then proved complete or not
        (:meth:`Locus.certify <coopkin_sym.analysis.locus.facade.LocusMethods.certify>`:
        its certificate is kept on it); with ``verify``, checked independently
        (:meth:`Locus.verify <coopkin_sym.analysis.locus.facade.LocusMethods.verify>`:
        kept as ``locus.verification``). The locus remembers this system, so both can
        also be asked for later.

        With a ``timeout`` (for the whole run, certificate and verification included),
        a search cut by the bound returns what it found
        (:attr:`~coopkin_sym.analysis.locus.types.Locus.unexplored` says what was
        cut): at a check of the bound, or, when a step that cannot be interrupted is
        ended at the bound, as far as it was about a second before (see
        :func:`coopkin_sym.exact.bounded.run_bounded`); before the generic numbers
        it raises :class:`~coopkin_sym.errors.TimeLimitReached`. ``progress`` shows
        the steps after a second: in a Jupyter cell, or on standard error when it is
        a terminal (nowhere else).

        Example
        -------
        >>> from coopkin_sym import load
        >>> locus = load("paper-case1-hard").locus(certify=True)
        >>> locus.generic["Nm"], [c.condition.text for c in locus.components][:2]
        (2, ['q1 = -pi/2, q2 = -pi/2', 'q1 = -pi/2, q2 = pi/2'])
        >>> locus.certified, locus.completeness()
        (True, (True, None))
        """
        from coopkin_sym.analysis.locus.search import compute_locus
        from coopkin_sym.analysis.locus.types import ended_at_bound
        from coopkin_sym.errors import TimeLimitReached

        def work():
            locus = self._known(compute_locus(self, at, max_depth, timeout, progress,
                                              free, pi_size))
            if certify:
                locus.certify()
            if verify:
                locus.verify()
            return locus

        try:
            return self._known(_bounded(work, timeout, "locus", progress))
        except TimeLimitReached as exc:   # ended inside a step: the last copy kept
            locus = ended_at_bound(exc)
            if locus is None:
                raise
            return self._known(locus)

    def search_locus(self, at: str | Mapping | None = None, *, max_depth: int = 2,
                     timeout: float | None = None, progress: bool = False,
                     free: Iterable[str] | None = None,
                     pi_size: int | None = None) -> Locus:
        """The search of :meth:`locus` alone, here: no bound of its own (``timeout``
        only stops it from exploring new components at its checks of the clock),
        no certificate, no verification. For a caller that runs it under its own
        bound (:func:`run_bounded`; ``coopkin locus`` does), where ``progress``
        reports the steps to that bound's display (see
        :func:`coopkin_sym.analysis.locus.search.compute_locus`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> locus = load("paper-case1-hard").search_locus(max_depth=0)
        >>> locus.generic["Nm"], len(locus.components) > 0
        (2, True)
        """
        from coopkin_sym.analysis.locus.search import compute_locus
        return compute_locus(self, at=at, max_depth=max_depth, timeout=timeout,
                             progress=progress, free=free, pi_size=pi_size)

    def _known(self, locus: Locus) -> Locus:
        """``locus`` (and its locked locus) told which system it is about."""
        locus._system = self
        if locus.locked is not None:
            locus.locked._system = self.with_actuators_locked()
        return locus

    def certify_locus(self, locus: Locus, *, timeout: float = 30.0,
                      budget: float | None = 300.0) -> Certificate:
        """The completeness certificate of ``locus`` (a locus of this system; see
        :func:`coopkin_sym.analysis.locus.certify.certify_locus`): ``timeout`` seconds
        for each test, ``budget`` for the whole. :meth:`Locus.certify
        <coopkin_sym.analysis.locus.facade.LocusMethods.certify>` also keeps it.

        Example
        -------
        >>> from coopkin_sym import load
        >>> system = load("paper-case1-hard")
        >>> system.certify_locus(system.locus(), timeout=60).certified
        True
        """
        from coopkin_sym.analysis.locus.certify import certify_locus
        return certify_locus(self, locus, timeout=timeout, budget=budget)

    def check_finite(self) -> None:
        """Nothing when the finite mobility is defined for this system (every contact
        constrains positions), else the
        :class:`~coopkin_sym.errors.FiniteMobilityError` saying which contact is not:
        checked before a long locus search whose witnesses it would be asked at.

        Example
        -------
        >>> from coopkin_sym import load
        >>> load("four-bar").check_finite()
        >>> load("paper-case1-soft").check_finite()
        Traceback (most recent call last):
        ...
        coopkin_sym.errors.FiniteMobilityError: contact 1 is soft: ...
        """
        from coopkin_sym.analysis.finite.constraints import check_holonomic
        check_holonomic(self.model)

    def finite_locus(self, locus: Locus, *, order: int | None = None) -> int:
        """The finite mobility at every witness (rational, else algebraic) of ``locus``
        (a locus of this system), kept in each component's ``finite`` (see
        :func:`coopkin_sym.analysis.finite.on_locus.finite_at_witnesses`); how many
        were computed. :meth:`Locus.finite_mobility
        <coopkin_sym.analysis.locus.facade.LocusMethods.finite_mobility>` calls it.

        Example
        -------
        >>> from coopkin_sym import load
        >>> system = load("shaky-pinned-bars")
        >>> locus = system.locus()
        >>> system.finite_locus(locus), locus.components[0].finite["classification"]
        (2, 'shaky')
        """
        from coopkin_sym.analysis.finite.on_locus import finite_at_witnesses
        return finite_at_witnesses(locus, self.model, order)

    def verify_locus(self, locus: Locus, *, max_points: int = 50_000, lines: int = 12,
                     seed: int = 0, timeout: float | None = None) -> Verification:
        """An independent check of ``locus`` (see
        :func:`coopkin_sym.analysis.locus.verify.verify_locus`).

        Example
        -------
        >>> from coopkin_sym import load
        >>> system = load("paper-case1-hard")
        >>> system.verify_locus(system.locus(), max_points=200, lines=2).ok
        True
        """
        from coopkin_sym.analysis.locus.verify import verify_locus
        return verify_locus(self, locus, max_points=max_points, lines=lines, seed=seed,
                            timeout=timeout)

    def with_actuators_locked(self) -> System:
        """The same system with every motor held still (the system of a locus's
        ``locked`` part: where the passive-joint numbers change).

        Example
        -------
        >>> from coopkin_sym import load
        >>> sorted(load("five-bar").with_actuators_locked().model.locked)
        ['q1', 'q3']
        """
        return System(self.model.with_actuators_locked())

    def finite_mobility(self, at: str | Mapping | Configuration | None = None, *,
                        order: int | None = None) -> FiniteMobility:
        """The finite mobility at ``at``: the local dimension of the closed system's
        configuration space, its branches and classification, exactly (see
        :func:`coopkin_sym.analysis.finite.finite_mobility`; every joint at a rational
        ``tan(q/2)``, or an algebraic one such as ``pi/3`` (over its number field);
        hard, complete or frictionless contacts).

        Example
        -------
        >>> from coopkin_sym import load
        >>> fm = load("four-bar").finite_mobility("q1=-pi/2,q2=-pi/2")
        >>> fm.dimension, fm.first_order, fm.classification
        (1, 2, 'bifurcation')
        """
        from coopkin_sym.analysis.finite import finite_mobility
        return finite_mobility(self.model, at, order)

    def draw(self, at: str | Mapping | None = None, motion: str | Sequence | None = None,
             title: str | None = None, labels: bool | str = True) -> Figure:
        """A picture of the system at ``at`` (see
        :func:`coopkin_sym.present.draw.draw_system`), with one of its motions;
        ``labels``: joint and contact names (long ones shortened), ``"short"`` (joint
        numbers in their arm) or ``False`` (none).

        Example
        -------
        >>> from coopkin_sym import load
        >>> fig = load("paper-case1-hard").draw("q1=pi/2,q2=pi/2", motion="coordinated:1")
        >>> len(fig.axes)
        1
        """
        from coopkin_sym.present.draw import draw_system
        return draw_system(self, at, motion=motion, title=title, labels=labels)

    def interactive(self, joints: Iterable[str] | str | None = None, *, steps: int = 24,
                    at: str | Mapping | None = None,
                    values: Mapping[str, Sequence] | None = None) -> InteractiveView:
        """A view for Jupyter: a slider per joint over exact values, the picture and the
        exact numbers (as :meth:`analyze` gives them) at the values chosen, updated on
        every change, each configuration analyzed once (see
        :class:`~coopkin_sym.present.interactive.InteractiveView`).

        ``steps`` values per revolute slider (the multiples of ``2*pi/steps`` in
        ``(-pi, pi]``; 24: of ``pi/12``, analyzed exactly over the number field of
        their tangents), ``at`` the other values (``"L=1"``), ``values`` the exact
        values of some sliders (``{"q1": ["0", "pi/2", "2*atan(1/3)"]}``). Needs
        ipywidgets (``pip install "coopkin_sym[notebook]"``).

        Example
        -------
        >>> from coopkin_sym import load
        >>> view = load("paper-case1-planar").interactive(steps=4, at="L=1")
        >>> view.select("q1=pi/2,q2=pi/2").numbers.Nm, view.numbers == (
        ...     load("paper-case1-planar").analyze("q1=pi/2,q2=pi/2,L=1").numbers)
        (2, True)
        """
        from coopkin_sym.present.interactive import interactive
        return interactive(self, joints, steps=steps, at=at, values=values)

    def sweep(self, points, *, at: str | Mapping | None = None, executor=None,
              progress: bool = False, chunk: int = 16384, timeout: float | None = None):
        """Exact numbers at many points, fast (see :func:`coopkin_sym.analysis.sweep.sweep`).

        ``points`` is a grid (:func:`coopkin_sym.analysis.sweep.grid`) or an iterable of points
        (``"q1=pi/2,q2=0"`` or mappings); ``executor`` any
        :class:`concurrent.futures.Executor`, a dask ``distributed.Client`` or a pool
        with ``apply_async`` (``ray.util.multiprocessing.Pool``, ``multiprocessing.Pool``);
        ``progress`` shows a bar after a second (in a Jupyter cell, or on
        standard error when it is a terminal); ``timeout`` is a
        wall-clock bound in seconds (past it,
        :class:`~coopkin_sym.errors.TimeLimitReached`); the bounded sweep runs in a
        process of its own, which cannot use an executor made outside it: give one
        or the other (``coopkin sweep --workers N --timeout S`` makes its pool inside).

        Example
        -------
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"])
        >>> res.numbers[:, 0].tolist()
        [3, 2]
        """
        from coopkin_sym.analysis.sweep import sweep
        if timeout is not None and executor is not None:
            from coopkin_sym.errors import SweepError
            raise SweepError("timeout: a bounded sweep runs in a process of its own and "
                             "cannot use an executor made outside it (give one or the "
                             "other)")
        return _bounded(lambda: sweep(self, points, at=at, executor=executor,
                                      progress=progress, chunk=chunk),
                        timeout, "sweep", progress)

    def __repr__(self) -> str:
        return (f"System({clip(self.model.name, 100)!r}: {len(self.model.arms)} arms, "
                f"{len(self.model.joints)} joints, {len(self.model.contacts)} contacts)")

    def _repr_pretty_(self, p: Any, cycle: bool) -> None:
        from coopkin_sym.present.display import system_text
        lines = [repr(self)] if cycle else system_text(self.model).split("\n")
        for k, line in enumerate(lines):
            if k:
                p.break_()
            p.text(line)

    def _repr_html_(self) -> str:
        from coopkin_sym.present.display import system_html
        return system_html(self.model)

    def analyze_many(self, points: Iterable[str | Mapping | None], *, json: bool = False,
                     free: Iterable[str] | None = None, executor: Executor | None = None,
                     progress: bool = False,
                     chunk: int | None = None) -> list[BatchResult]:
        """:meth:`analyze` at many configurations, here or on any executor (see
        :func:`analyze_many`): one :class:`~coopkin_sym.analysis.batch.BatchResult`
        per point, in order, with the error of a bad point in its own result. The
        model travels to the workers pickled.

        Example
        -------
        >>> from coopkin_sym import load
        >>> results = load("paper-case1-hard").analyze_many(["q1=pi/2,q2=pi/2", "q1=7"])
        >>> results[0].numbers.Nm, results[1].ok
        (3, False)
        """
        return analyze_many([(self.model, at) for at in points], json=json, free=free,
                            executor=executor, progress=progress, chunk=chunk)


def _bounded(work, timeout: float | None, what: str, progress: bool):
    """``work()`` under ``timeout`` (see :func:`coopkin_sym.exact.bounded.run_bounded`),
    its steps shown after a second when ``progress`` (in a Jupyter cell, or on a
    terminal; see :func:`coopkin_sym.present.progress.progress_medium`)."""
    from coopkin_sym.exact.bounded import run_bounded
    if not progress:
        return run_bounded(work, timeout, owner=f"System.{what}")

    from coopkin_sym.present.progress import progress_display
    with progress_display(True, what) as display:
        return run_bounded(work, timeout, owner=f"System.{what}", progress=display)


def read_locus(path: str | os.PathLike) -> Locus:
    """A locus back from its JSON report (``coopkin locus MODEL -o REPORT.json``),
    validated like a model file: nothing in it is evaluated, every expression is read
    by the package's parser.

    Raises
    ------
    ReportError
        When the file cannot be read or is not a locus report: one line per problem,
        each naming the file.

    Example
    -------
    >>> import pathlib, tempfile
    >>> locus = load("paper-case1-hard").locus()
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "locus.json"
    >>> _ = locus.write(path)
    >>> [c.equations for c in read_locus(path).components] == [
    ...     c.equations for c in locus.components]
    True
    """
    from pathlib import Path

    from coopkin_sym.errors import ReportError
    from coopkin_sym.model.input_files import read_text_file
    from coopkin_sym.present.report import locus_from_json

    text = read_text_file(Path(path), ReportError)
    try:
        return locus_from_json(text)
    except ValueError as exc:   # one line per problem, each naming the file once
        lead = "not a locus report"
        lines = [line if line.startswith(lead) else f"{lead}: {line}"
                 for line in (str(exc).splitlines() or [lead])]
        raise ReportError("\n".join(f"{path}: {line}" for line in lines)) from None


def run_bounded(work: Callable[[], T], timeout: float | None, *, what: str = "run",
                owner: str | None = None, progress: bool = False,
                output: Callable[[Any], None] | None = None,
                started: float | None = None) -> T:
    """``work()`` under a wall-clock bound of ``timeout`` seconds (None: no bound),
    held even inside steps that cannot be interrupted (see
    :func:`coopkin_sym.exact.bounded.run_bounded`); past it,
    :class:`~coopkin_sym.errors.TimeLimitReached`.

    Parameters
    ----------
    work
        The computation; it may say where it is with :func:`report_step` and hand
        over finished parts of its output with :func:`deliver_part`.
    timeout
        The bound in seconds, counted from ``started`` (``time.monotonic()``;
        default: now).
    what
        What is computed, for the progress display (``"locus"``).
    owner
        The name of the bound (default ``what``).
    progress
        Show the steps after a second: in a Jupyter cell, or on standard error when
        it is a terminal (the work then runs in a process of its own, so that the
        display keeps moving).
    output
        Called here with each part the work delivers, in order, as it comes.

    Example
    -------
    >>> from coopkin_sym import deliver_part, report_step
    >>> parts = []
    >>> def work():
    ...     report_step("the first part")
    ...     deliver_part("part 1")
    ...     return 42
    >>> run_bounded(work, 60, output=parts.append), parts
    (42, ['part 1'])
    """
    from coopkin_sym.exact.bounded import run_bounded as exact_run_bounded
    from coopkin_sym.present.progress import progress_display

    with progress_display(progress, what, started=started) as display:
        # on a terminal the work runs apart, so that the line keeps moving; a Jupyter
        # kernel is not forked for it
        apart = display.medium == "terminal"
        return exact_run_bounded(work, timeout, owner=owner or what, progress=display,
                                 output=output, separate=apart, started=started)


def load(source: str | os.PathLike | Mapping) -> System:
    """Load a model file (YAML or JSON), a dict, or a shipped example by name."""
    return System(load_model(source))


def analyze_many(items: Iterable[Any], *, generic: bool = False,
                 free: Iterable[str] | None = None, json: bool = False,
                 executor: Executor | None = None, progress: bool = False,
                 chunk: int | None = None) -> list[BatchResult]:
    """Many analyses (many systems, many configurations), here or on any executor.

    Parameters
    ----------
    items
        Plain data, each a model source (a shipped example's name, a model file, a
        model as a mapping) or a pair ``(source, at)``, ``at`` in ``--at`` syntax
        (``"q1=pi/2,L=1"``) or a mapping (None: home).
    generic, free
        As for :meth:`System.analyze`, for every item.
    json
        Also give each result the JSON document of ``coopkin analyze --json``.
    executor
        Any :class:`concurrent.futures.Executor` (a process pool,
        ``distributed.Client(...).get_executor()``), a dask ``distributed.Client``
        itself, or a pool with ``apply_async`` (``ray.util.multiprocessing.Pool``,
        ``multiprocessing.Pool``); None runs here. Anything else is an
        :class:`~coopkin_sym.errors.ArgumentTypeError` saying what to pass.
    progress
        Show a progress bar after a second (in a Jupyter cell, or on stderr when it
        is a terminal).
    chunk
        Items per task (see :func:`coopkin_sym.analysis.batch.run_batch`).

    Returns
    -------
    list of BatchResult
        In input order, the same on every executor: the exact numbers (and document)
        of each item, or the error of that item alone.

    Example
    -------
    >>> results = analyze_many(["five-bar", ("paper-case1-hard", "q1=pi/2,q2=pi/2"),
    ...                         ("paper-case1-hard", "q1=1")])
    >>> [r.numbers.Nm if r.ok else "error" for r in results]
    [3, 3, 'error']
    """
    from coopkin_sym.analysis.batch import run_batch

    options = (generic, None if free is None else tuple(free), json)
    return _bounded(lambda: run_batch(_analyze_item, items, options=options,
                                      executor=executor, progress=progress, chunk=chunk),
                    None, "analyze", progress)


def _analyze_item(model: Model, at, generic: bool, free, json: bool):
    """One item of :func:`analyze_many`: numbers and, when asked, the JSON document."""
    result = System(model).analyze(at, generic=generic, free=free)
    if not json:
        return result.numbers, None
    from coopkin_sym.present.text import analysis_document

    return result.numbers, analysis_document(result)
