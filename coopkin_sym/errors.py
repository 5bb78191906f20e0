"""The one base class of every error the package raises on purpose.

Bad input (a model file, an option, a report read back, an argument of the API) never
ends in a traceback: it raises a subclass of :class:`CoopkinError` whose message is
one line per problem, naming the entry and what is wrong. Code that wants to tell the
package's own refusals from bugs catches :class:`CoopkinError`.

Example
-------
>>> from coopkin_sym.model import ModelError
>>> issubclass(ModelError, CoopkinError) and issubclass(ModelError, ValueError)
True
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
