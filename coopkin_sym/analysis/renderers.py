"""How results show in IPython and Jupyter: a registry the presentation layer fills.

The results of this layer are data, not words. A result class inherits
:class:`Displayable`: its ``_repr_html_``, ``_repr_latex_`` and ``_repr_pretty_`` ask
the renderer registered for its class and format (:func:`register`), which the
presentation layer (:mod:`coopkin_sym.present.display`) installs. Importing
:mod:`coopkin_sym` does not import it (start-up stays short): it sets a loader
(:func:`load_before_render`) that imports it the first time anything is displayed.
With no renderer registered, a result shows as its ``repr`` (the short one each class
defines, with :func:`clip`).

The same registry holds what a result does with the presentation layer beyond its
display: writing a report, drawing a plot (:func:`register_action`, :func:`action`;
e.g. :meth:`Locus.write <coopkin_sym.analysis.locus.facade.LocusMethods.write>`), so
that this layer calls them without importing the layer above.

Example
-------
>>> class Point(Displayable):
...     def __repr__(self):
...         return "<Point>"
>>> Point()._repr_html_() is None                 # nothing registered for Point
True
>>> register(Point, "html", lambda p: "<b>a point</b>")
>>> Point()._repr_html_()
'<b>a point</b>'
>>> unregister(Point, "html")
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from coopkin_sym.errors import ArgumentError, NotAvailable

#: The formats a renderer can be registered for.
FORMATS = ("html", "latex", "pretty")

#: Renderers by (class, format); empty until the presentation layer is imported.
_RENDERERS: dict[tuple[type, str], Callable[[Any], str]] = {}

#: Actions by (class, name): what a result does with the presentation layer.
_ACTIONS: dict[tuple[type, str], Callable[..., Any]] = {}

#: Loaders still to run before the first lookup (each registers renderers).
_LOADERS: list[Callable[[], object]] = []


def load_before_render(loader: Callable[[], object]) -> None:
    """Run ``loader()`` once, just before the first renderer lookup: a layer above this
    one installs its renderers only when something is first displayed.

    Example
    -------
    >>> seen = []
    >>> load_before_render(lambda: seen.append("loaded"))
    >>> render(3, "html") is None, seen
    (True, ['loaded'])
    >>> render(3, "html") is None, seen               # once only
    (True, ['loaded'])
    """
    _LOADERS.append(loader)


def register(cls: type, kind: str, renderer: Callable[[Any], str]) -> None:
    """Show instances of ``cls`` (and of its subclasses) in the format ``kind``
    (``"html"``, ``"latex"`` or ``"pretty"``) with ``renderer(obj) -> str``.

    Example
    -------
    >>> register(int, "svg", str)
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.ArgumentError: unknown display format 'svg' (formats: html, latex, pretty)
    """
    if kind not in FORMATS:
        raise ArgumentError(f"unknown display format {kind!r} (formats: {', '.join(FORMATS)})")
    _RENDERERS[(cls, kind)] = renderer


def unregister(cls: type, kind: str) -> None:
    """Forget the renderer of ``cls`` in the format ``kind`` (if any).

    Example
    -------
    >>> unregister(int, "html")
    """
    _RENDERERS.pop((cls, kind), None)


def render(obj: object, kind: str) -> str | None:
    """``obj`` in the format ``kind`` by the renderer registered for its class (or the
    nearest base class), or None when there is none.

    Example
    -------
    >>> render(3, "html") is None
    True
    """
    _load()
    for cls in type(obj).__mro__:
        renderer = _RENDERERS.get((cls, kind))
        if renderer is not None:
            return renderer(obj)
    return None


def _load() -> None:
    while _LOADERS:
        _LOADERS.pop(0)()


def register_action(cls: type, name: str, function: Callable[..., Any]) -> None:
    """Let instances of ``cls`` (and of its subclasses) do ``name`` (``"write"``,
    ``"plot"``...) with ``function(obj, ...)``, a function of the presentation layer.

    Example
    -------
    >>> class Note:
    ...     pass
    >>> register_action(Note, "shout", lambda note, word: word.upper())
    >>> action(Note(), "shout")("hello")
    'HELLO'
    >>> unregister_action(Note, "shout")
    """
    _ACTIONS[(cls, name)] = function


def unregister_action(cls: type, name: str) -> None:
    """Forget the action ``name`` of ``cls`` (if any)."""
    _ACTIONS.pop((cls, name), None)


def action(obj: object, name: str) -> Callable[..., Any]:
    """The action ``name`` registered for ``obj``'s class (or the nearest base class),
    bound to ``obj``.

    Raises
    ------
    NotAvailable
        Nothing is registered for it.

    Example
    -------
    >>> action(3, "write")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.NotAvailable: int.write is not available (nothing of the ...
    """
    _load()
    for cls in type(obj).__mro__:
        function = _ACTIONS.get((cls, name))
        if function is not None:
            return lambda *args, **kwargs: function(obj, *args, **kwargs)
    raise NotAvailable(f"{type(obj).__name__}.{name} is not available (nothing of the "
                       "presentation layer is registered for it)")


class Displayable:
    """A result that IPython and Jupyter show with the registered renderers: HTML,
    LaTeX, and the text IPython prints (its ``repr`` when nothing is registered).

    Example
    -------
    >>> class Thing(Displayable):
    ...     def __repr__(self):
    ...         return "<Thing>"
    >>> Thing()._repr_latex_() is None
    True
    """

    def __init_subclass__(cls, **kwargs: Any) -> None:
        # IPython's printer takes a class's own __repr__ before a _repr_pretty_ it
        # inherits: each subclass gets the method in its own namespace
        super().__init_subclass__(**kwargs)
        if "_repr_pretty_" not in cls.__dict__:
            cls._repr_pretty_ = Displayable._repr_pretty_

    def _repr_html_(self) -> str | None:
        return render(self, "html")

    def _repr_latex_(self) -> str | None:
        return render(self, "latex")

    def _repr_pretty_(self, p: Any, cycle: bool) -> None:
        text = None if cycle else render(self, "pretty")
        for k, line in enumerate((repr(self) if text is None else text).split("\n")):
            if k:
                p.break_()
            p.text(line)


def clip(text: object, limit: int) -> str:
    """``text`` on one line, shortened to at most ``limit`` characters (``...`` at the
    end when cut).

    Example
    -------
    >>> clip("q1=pi/2,\\nq2=pi/3", 40), clip("x" * 50, 10)
    ('q1=pi/2, q2=pi/3', 'xxxxxxx...')
    """
    one = " ".join(str(text).split())
    return one if len(one) <= limit else one[:max(limit - 3, 0)] + "..."


__all__ = ["FORMATS", "Displayable", "action", "clip", "load_before_render", "register",
           "register_action", "render", "unregister", "unregister_action"]
