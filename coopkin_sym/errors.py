"""Every error the package raises on purpose, under one base class.

Bad input (a model file, an option, a report read back, an argument of the API) never
ends in a traceback: it raises a subclass of :class:`CoopkinError` whose message is
one line per problem, naming the entry and what is wrong. Code that wants to tell the
package's own refusals from bugs catches :class:`CoopkinError`.

All of them live here, grouped by the layer that raises them: exact numbers and ideals
(:class:`NumberError`, :class:`GroebnerError`), files and models (:class:`TreeError`,
:class:`ModelError`, :class:`ConfigurationError`), analyses (:class:`BlockTooLarge`,
:class:`InfeasibleMotion`, :class:`SweepError`, :class:`NotIrrational`,
:class:`LocusError`, :class:`CertifyError`, :class:`VerifyError`,
:class:`TimeLimitReached`) and outputs (:class:`ReportError`, :class:`ReportInputError`,
:class:`DrawError`, :class:`PlotError`). Each also keeps its historical base
(``ValueError``), so older ``except ValueError`` code still catches it.

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
    such as ``ValueError``)."""


class TimeLimitReached(CoopkinError):
    """A computation ran past the wall-clock bound it was given.

    ``where`` names the step that was running when the bound was noticed (for a
    report saying what was cut); ``seconds`` is the bound.

    Example
    -------
    >>> str(TimeLimitReached(5.0, "the generic decomposition"))
    'time bound of 5 s reached during the generic decomposition'
    """

    def __init__(self, seconds: float, where: str = ""):
        self.seconds = seconds
        self.where = where
        shown = f"{seconds:g}"
        super().__init__(f"time bound of {shown} s reached"
                         + (f" during {where}" if where else ""))


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


class GroebnerError(ValueError, CoopkinError):
    """A malformed ideal or an unknown backend."""


class TreeError(ValueError, CoopkinError):
    """A file or tree that cannot be read: one line saying where and why."""


class ModelError(ValueError, CoopkinError):
    """A model that cannot be accepted.

    ``problems`` lists one line per problem, each naming the entry
    (``contacts[1].normal: not a unit vector``); ``str(error)`` is the whole message,
    prefixed by the file name when the model came from a file.
    """

    def __init__(self, problems: list[str], source: str | None = None):
        self.problems = list(problems)
        self.source = source
        prefix = f"{source}: " if source else ""
        super().__init__("\n".join(prefix + p for p in self.problems))


class ConfigurationError(ValueError, CoopkinError):
    """A configuration that names an unknown variable or has an inexact value."""


class BlockTooLarge(ValueError, CoopkinError):
    """A symbolic block whose entries would exceed the analysis's term budget."""


class InfeasibleMotion(ValueError, CoopkinError):
    """A requested velocity that the system cannot realize without breaking a contact."""


class SweepError(ConfigurationError):
    """A grid or a list of points that cannot be swept (unknown joint, bad range...)."""


class NotIrrational(ValueError, CoopkinError):
    """Every value of the configuration is rational: use the rational analysis."""


class LocusError(ValueError, CoopkinError):
    """A locus that cannot be computed for this input."""


class CertifyError(ValueError, CoopkinError):
    """A locus that does not belong to the system (other variables or values)."""


class VerifyError(ValueError, CoopkinError):
    """A locus that cannot be checked against this model (names or texts that do not
    fit), with the entry and the problem."""


class ReportError(ValueError, CoopkinError):
    """A report that cannot be written: unknown format, missing directory, a bad plot
    request, or an I/O error."""


class ReportInputError(ValueError, CoopkinError):
    """A report that cannot be read back: one line per problem."""

    def __init__(self, problems: list[str]):
        self.problems = list(problems)
        super().__init__("\n".join(f"not a locus report: {p}" for p in self.problems))


class DrawError(ValueError, CoopkinError):
    """A picture that cannot be drawn: a bad motion request, an unknown file format,
    matplotlib missing, or an output file that cannot be written."""


class PlotError(ValueError, CoopkinError):
    """A pair of joints that cannot be plotted (unknown, the same twice, or not
    among the locus's variables), or matplotlib missing."""
