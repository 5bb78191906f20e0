"""How results show in IPython and Jupyter: a registry the presentation layer fills.

The results of this layer are data, not words. A result class inherits
:class:`Displayable`: its ``_repr_html_``, ``_repr_latex_`` and ``_repr_pretty_`` ask
the renderer registered for its class and format (:func:`register`), which the
presentation layer (:mod:`coopkin_sym.present.display`) installs. Importing
:mod:`coopkin_sym` does not import it (start-up stays short): it sets a loader
(:func:`load_before_render`) that imports it the first time anything is displayed.
With no renderer registered, a result shows as its ``repr`` (the short one each class
defines, with :func:`clip`).

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

from coopkin_sym.errors import ArgumentError

#: The formats a renderer can be registered for.
FORMATS = ("html", "latex", "pretty")

#: Renderers by (class, format); empty until the presentation layer is imported.
_RENDERERS: dict[tuple[type, str], Callable[[Any], str]] = {}

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
    while _LOADERS:
        _LOADERS.pop(0)()
    for cls in type(obj).__mro__:
        renderer = _RENDERERS.get((cls, kind))
        if renderer is not None:
            return renderer(obj)
    return None


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


__all__ = ["FORMATS", "Displayable", "clip", "load_before_render", "register", "render",
           "unregister"]
