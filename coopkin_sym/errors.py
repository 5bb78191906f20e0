"""Every error the package raises on purpose, under one base class.

Bad input (a model file, an option, a report read back, an argument of the API) never
ends in a traceback: it raises a subclass of :class:`CoopkinError` whose message is
one line per problem, naming the entry and what is wrong. Code that wants to tell the
package's own refusals from bugs catches :class:`CoopkinError`.

All of them live here, grouped by the layer that raises them: arguments of the API
(:class:`ArgumentError`, :class:`ArgumentTypeError`, :class:`MissingDependency`), exact
numbers and ideals (:class:`NumberError`, :class:`UndeclaredSymbol`,
:class:`GroebnerError`), files and models (:class:`TreeError`, :class:`ModelError`,
:class:`ConfigurationError`), analyses (:class:`BlockTooLarge`,
:class:`InfeasibleMotion`, :class:`ManipulabilityError`, :class:`SweepError`,
:class:`NotIrrational`, :class:`LocusError`, :class:`CertifyError`,
:class:`VerifyError`, :class:`TimeLimitReached`, :class:`WorkLimitReached`) and outputs
(:class:`ReportError`, :class:`ReportInputError`, :class:`DrawError`,
:class:`PlotError`). Each also keeps its historical base (``ValueError``), so older
``except ValueError`` code still catches it.

One warning, :class:`OutputSkipped`, says that a part of an output was left out
while the rest was written (a plot with nothing to show, a motion not available at
the configuration); ``coopkin`` prints each as a note on stderr.

Example
-------
>>> issubclass(ModelError, CoopkinError) and issubclass(ModelError, ValueError)
True
>>> from coopkin_sym import load
>>> try:
...     load("no-such-example")
... except CoopkinError as error:
...     print(type(error).__name__)
ModelError
"""

from __future__ import annotations


class CoopkinError(Exception):
    """Base class of the package's own errors (each also keeps its historical base,
    such as ``ValueError``).

    Example
    -------
    >>> from coopkin_sym import load
    >>> issubclass(ModelError, CoopkinError)
    True

    Every one pickles whole (its class, message and attributes), so that it comes
    back from a worker process as itself:

    >>> import pickle
    >>> error = pickle.loads(pickle.dumps(ModelError(["arms: empty"], "m.yaml")))
    >>> type(error).__name__, str(error), error.problems
    ('ModelError', 'm.yaml: arms: empty', ['arms: empty'])
    """

    def __reduce__(self):
        return _rebuilt, (type(self), self.args, dict(self.__dict__))


def _rebuilt(cls: type, args: tuple, state: dict) -> CoopkinError:
    """An error of class ``cls`` with these ``args`` and attributes, without calling
    its ``__init__`` (whose parameters differ from class to class)."""
    error = cls.__new__(cls)
    error.args = args
    error.__dict__.update(state)
    return error


class TimeLimitReached(CoopkinError):
    """A computation ran past the wall-clock bound it was given.

    ``where`` names the step that was running when the bound was noticed (for a
    report saying what was cut); ``seconds`` is the bound; ``hard`` is true when the
    work was ended at the bound from outside (its process stopped: nothing of it was
    kept), false when it stopped itself at a check of the bound.

    Example
    -------
    >>> str(TimeLimitReached(5.0, "the generic decomposition"))
    'time bound of 5 s reached during the generic decomposition'
    >>> TimeLimitReached(5.0, "a factorization", hard=True).hard
    True
    """

    def __init__(self, seconds: float, where: str = "", hard: bool = False):
        self.seconds = seconds
        self.where = where
        self.hard = hard
        shown = f"{seconds:g}"
        super().__init__(f"time bound of {shown} s reached"
                         + (f" during {where}" if where else ""))


class WorkLimitReached(CoopkinError):
    """A computation used up the work budget it was given (a number of steps, the
    same on every machine and under any load: see :func:`.deadline.work_limit`).

    Example
    -------
    >>> str(WorkLimitReached(1000, "a determinant"))
    'work budget of 1000 steps used up during a determinant'
    """

    def __init__(self, steps: int, where: str = ""):
        self.steps = steps
        self.where = where
        super().__init__(f"work budget of {steps} steps used up"
                         + (f" during {where}" if where else ""))


class ArgumentError(ValueError, CoopkinError):
    """An argument of the API that cannot be used: a value out of range, an unknown
    name or format, a matrix of the wrong shape, a request the object cannot answer.

    Example
    -------
    >>> from coopkin_sym.model.builders import planar_hand
    >>> planar_hand(0, 2)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentError: fingers of planar_hand: need at least one ...
    """


class ArgumentTypeError(TypeError, ArgumentError):
    """An argument of the API of a kind the function does not take (also a
    ``TypeError``).

    Example
    -------
    >>> from coopkin_sym.exact.rationals import to_fraction
    >>> to_fraction(0.5)
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentTypeError: not an exact rational: 0.5
    """


class MissingDependency(ImportError, CoopkinError):
    """An optional package that a requested output needs is not installed; the
    message says what to install.

    Example
    -------
    >>> str(MissingDependency("to_pandas needs pandas: pip install pandas"))
    'to_pandas needs pandas: pip install pandas'
    """


class WorkerFailed(RuntimeError, CoopkinError):
    """The process a bounded computation ran in ended without an answer (killed from
    outside, or out of memory); the message names the computation and the exit code.

    Example
    -------
    >>> str(WorkerFailed("the worker process of a locus stopped without an answer"))
    'the worker process of a locus stopped without an answer'
    """


class NumberError(ValueError, CoopkinError):
    """A number, angle or expression that is not exact or cannot be read.

    ``where`` names the entry (``arms[0].joints[0].point``, ``q1``); ``message`` says
    what is wrong; ``str(error)`` is ``"where: message"``.

    Example
    -------
    >>> str(NumberError("q1", "'x' cannot be parsed"))
    "q1: 'x' cannot be parsed"
    """

    def __init__(self, where: str, message: str):
        self.where = where
        self.message = message
        super().__init__(f"{where}: {message}" if where else message)


class UndeclaredSymbol(NumberError):
    """A number or expression that uses a name that is not declared (a parameter, a
    variable). A model whose parameter list cannot be read does not report these
    about its numbers: the list's own problem is the one to fix.

    Example
    -------
    >>> from coopkin_sym.exact.parse import parse_number
    >>> parse_number("2*M", {}, "contacts[0].point")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.UndeclaredSymbol: contacts[0].point: '2*M' uses undeclared symbol M ...
    """


class GroebnerError(ValueError, CoopkinError):
    """A malformed ideal or an unknown backend.

    Example
    -------
    >>> from coopkin_sym.exact.groebner import covers
    >>> covers([], [], backend="magic")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.GroebnerError: unknown backend 'magic' (known: ...)
    """


class TreeError(ValueError, CoopkinError):
    """A file or tree that cannot be read: one line saying where and why.

    Example
    -------
    >>> from coopkin_sym.model.trees import read_text
    >>> read_text("a: [1, 2", "m.yaml")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.TreeError: line 2, column 1: not valid YAML: did not find expected ',' or ']'
    """


class ModelError(ValueError, CoopkinError):
    """A model that cannot be accepted.

    ``problems`` lists one line per problem, each naming the entry
    (``contacts[1].normal: not a unit vector``); ``str(error)`` is the whole message,
    prefixed by the file name when the model came from a file.

    Example
    -------
    >>> from coopkin_sym import load
    >>> try:
    ...     load({"name": "x"})
    ... except ModelError as error:
    ...     print(error.problems[0])
    arms: at least one arm with one joint is needed
    """

    def __init__(self, problems: list[str], source: str | None = None):
        self.problems = list(problems)
        self.source = source
        prefix = f"{source}: " if source else ""
        super().__init__("\n".join(prefix + p for p in self.problems))


class UrdfError(ValueError, CoopkinError):
    """A URDF file that cannot be used for an arm (a floating joint, a closed loop, a
    mimic joint, a branching robot without a tip...). The model loader reports it as
    one line of a :class:`ModelError`, naming the arm.

    Example
    -------
    >>> from coopkin_sym.model.urdf import read_urdf_text
    >>> read_urdf_text('<robot name="r"><link name="b"/><link name="o"/><joint '
    ...     'name="j" type="floating"><parent link="b"/><child link="o"/></joint></robot>',
    ...     "r.urdf")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.UrdfError: r.urdf: joint 'j': type 'floating' is not supported ...
    """


class MjcfError(ValueError, CoopkinError):
    """An MJCF (MuJoCo) file that cannot be used for an arm (a ball or free joint on
    the chain, an ``<include>``, a branching body tree without a tip...). The model
    loader reports it as one line of a :class:`ModelError`, naming the arm.

    Example
    -------
    >>> from coopkin_sym.model.mjcf import read_mjcf_text
    >>> read_mjcf_text('<mujoco><worldbody><body name="b"><joint type="ball"/></body>'
    ...                '</worldbody></mujoco>', "m.xml")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.MjcfError: m.xml: body 'b': a ball joint is not supported on ...arm)
    """


class ConfigurationError(ValueError, CoopkinError):
    """A configuration that names an unknown variable or has an inexact value.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load("paper-case1-hard").analyze("q7=0")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ConfigurationError: --at q7: unknown name 'q7' (known: q1, q2, L)
    """


class BlockTooLarge(ValueError, CoopkinError):
    """A symbolic block whose entries would exceed the analysis's term budget.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze(generic=True)
    >>> a.term_budget = 1
    >>> a.C22  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.BlockTooLarge: C22: the coordinated joint motions would have ...
    """


class NotAvailable(AttributeError, CoopkinError):
    """A part of a result that this kind of result does not have (the blocks of an
    analysis at irrational coordinates); also an ``AttributeError``, so ``hasattr``
    answers ``False``.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load("paper-case1-hard").analyze("q1=-pi/6,q2=pi/6").C12  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.NotAvailable: C12 is not available at a configuration with ...
    """


class InfeasibleMotion(ValueError, CoopkinError):
    """A requested velocity that the system cannot realize without breaking a contact.

    Example
    -------
    >>> from coopkin_sym import load
    >>> a = load("paper-case1-hard").analyze("q1=pi/2,q2=pi/2")
    >>> a.joint_velocities([1, 0, 0, 0, 0, 0])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.InfeasibleMotion: object twist u is not feasible: ...
    """


class ManipulabilityError(ValueError, CoopkinError):
    """A manipulability request that cannot be answered: an unknown object motion, a
    characteristic length that is not a positive exact number or parameter.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load("paper-case1-hard").analyze().manipulability(["v_w"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ManipulabilityError: controlled: unknown object motion 'v_w' ...
    """


class SweepError(ConfigurationError):
    """A grid or a list of points that cannot be swept (unknown joint, bad range...).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.sweep import grid
    >>> grid(load("paper-case1-hard"), "q9=0..1:3")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.SweepError: --grid q9: unknown joint 'q9' (joints: q1, q2)
    """


class NotIrrational(ValueError, CoopkinError):
    """Every value of the configuration is rational: use the rational analysis.

    Example
    -------
    >>> from coopkin_sym.analysis.irrational import analyze_irrational
    >>> from coopkin_sym.model import load_model
    >>> analyze_irrational(load_model("paper-case1-hard"), "q1=pi/2")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.NotIrrational: every value is rational
    """


class LocusError(ValueError, CoopkinError):
    """A locus that cannot be computed for this input.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load("paper-case1-hard").locus("q1=0,q2=0")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.LocusError: every joint has a value: a locus needs at least one free joint
    """


class FiniteMobilityError(ValueError, CoopkinError):
    """A finite-mobility question this system or configuration cannot be asked: a
    contact that is not holonomic (``soft``: no spin about the normal is a condition on
    velocities, not on positions), a parameter without a value, or an irrational
    configuration.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.finite import finite_mobility
    >>> finite_mobility(load("paper-case1-soft").model, "q1=0,q2=0")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.FiniteMobilityError: contact 1 is soft: its no-spin condition ...
    """


class CertifyError(ValueError, CoopkinError):
    """A locus that does not belong to the system (other variables or values).

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.certify import certify_locus
    >>> locus = load("paper-case1-hard").locus()
    >>> certify_locus(load("paper-case2-hard"), locus)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.CertifyError: the locus has variables t_q1, t_q2 but the system ...
    """


class VerifyError(ValueError, CoopkinError):
    """A locus that cannot be checked against this model (names or texts that do not
    fit), with the entry and the problem.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.analysis.locus.verify import verify_locus
    >>> locus = load("paper-case1-hard").locus()
    >>> verify_locus(load("paper-case2-hard"), locus)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.VerifyError: the locus's variables ['t_q1', 't_q2'] do not match ...
    """


class ReportError(ValueError, CoopkinError):
    """A report that cannot be written: unknown format, missing directory, a bad plot
    request, or an I/O error.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.present.report import write_report
    >>> write_report(load("paper-case1-hard").locus(), "r.txt")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ReportError: r.txt: unknown report format '.txt' (expected ...)
    """


class ReportInputError(ValueError, CoopkinError):
    """A report that cannot be read back: one line per problem.

    Example
    -------
    >>> from coopkin_sym.present.report_input import validate_report
    >>> validate_report("[1]")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ReportInputError: not a locus report: (top level): expected a mapping, ...
    """

    def __init__(self, problems: list[str]):
        self.problems = list(problems)
        super().__init__("\n".join(f"not a locus report: {p}" for p in self.problems))


class DrawError(ValueError, CoopkinError):
    """A picture that cannot be drawn: a bad motion request, an unknown file format,
    matplotlib missing, or an output file that cannot be written.

    Example
    -------
    >>> from coopkin_sym import load
    >>> load("paper-case1-hard").draw(motion="twisting:1")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.DrawError: motion: unknown kind 'twisting' (expected ...)
    """


class PlotError(ValueError, CoopkinError):
    """A pair of joints that cannot be plotted (unknown, the same twice, or not
    among the locus's variables), or matplotlib missing.

    Example
    -------
    >>> from coopkin_sym import load
    >>> from coopkin_sym.present.locus_plot import plot_png
    >>> system = load("paper-case1-hard")
    >>> plot_png(system.locus(), system, ("q1", "q1"))
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.PlotError: pair: the two joints must differ, got 'q1' twice
    """


class OutputSkipped(UserWarning):
    """A part of an output left out while the rest was written: a plot with nothing
    to show, a picture that could not be drawn, a motion not available at the
    configuration. A warning, not an error; ``coopkin`` prints each on stderr as
    ``coopkin: note: ...``.

    Example
    -------
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warnings.warn("no plot: nothing to show", OutputSkipped)
    >>> caught[0].category.__name__, str(caught[0].message)
    ('OutputSkipped', 'no plot: nothing to show')
    """


class SkippedForTime(OutputSkipped):
    """A part of an output left out because the time bound was reached (the pictures
    of a locus report not drawn in the time left); ``coopkin`` prints it as a note and
    the run counts as cut by its bound.

    Example
    -------
    >>> issubclass(SkippedForTime, OutputSkipped)
    True
    """
