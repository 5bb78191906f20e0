"""An interactive view in Jupyter: joint sliders over exact values, the picture and the
exact numbers at the configuration they choose.

Each slider of an :class:`InteractiveView` runs over exact values of one joint (by
default the multiples of ``2*pi/steps`` in ``(-pi, pi]`` for a revolute joint, the
multiples of 1/4 in ``[-1, 1]`` for a prismatic one; any exact values with ``values=``).
An angle whose ``tan(q/2)`` is irrational but algebraic (``pi/12``) is analyzed exactly
over the number field it generates (:mod:`coopkin_sym.analysis.irrational`). On every
change the view shows the seven numbers (Nm, Nc, Ni, Nr, Ng, Nd, Nh) of
:meth:`System.analyze <coopkin_sym.System.analyze>` at that configuration, with their
meanings and the grasp classes, and redraws the picture
(:func:`~coopkin_sym.present.draw.draw_system`); each configuration is analyzed and
drawn once (kept in :attr:`InteractiveView.cache`). Only the picture is floating point.

ipywidgets is needed (``pip install "coopkin_sym[notebook]"``); without it the view is
a :class:`~coopkin_sym.errors.MissingDependency` saying so. The widgets work outside a
kernel too (the values can be set from code, as the tests do).

Example
-------
>>> from coopkin_sym import load
>>> view = interactive(load("paper-case1-planar"), steps=4, at="L=1")
>>> view.select("q1=pi/2,q2=pi/2").numbers.Nm
2
"""

from __future__ import annotations

import io
from collections import OrderedDict
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import sympy as sp

from coopkin_sym.analysis.irrational import irrational_values
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import (
    ArgumentError,
    ArgumentTypeError,
    ConfigurationError,
    CoopkinError,
    MissingDependency,
)
from coopkin_sym.exact.angles import ExactAngle
from coopkin_sym.model.configuration import Configuration, assignments_text, split_assignments
from coopkin_sym.present.html_parts import escape

__all__ = ["CACHE_SIZE", "InteractiveView", "MAX_STEPS", "interactive", "joint_values"]

#: Configurations whose analysis and picture a view keeps (the oldest go first).
CACHE_SIZE = 256
#: At most this many values on one slider.
MAX_STEPS = 720
# the values of a prismatic slider by default: the multiples of 1/4 in [-1, 1]
_PRISMATIC = tuple(sp.Rational(k, 4) for k in range(-4, 5))


def _widgets():
    try:
        import ipywidgets
    except ImportError:
        raise MissingDependency("the interactive view needs ipywidgets: "
                                'pip install ipywidgets (or "coopkin_sym[notebook]")') from None
    return ipywidgets


def joint_values(kind: str, steps: int) -> list[str]:
    """The default exact values of a slider, as ``--at`` text: ``steps`` angles
    ``k*2*pi/steps`` in ``(-pi, pi]`` for a revolute joint, the multiples of 1/4 in
    ``[-1, 1]`` for a prismatic one.

    Example
    -------
    >>> joint_values("revolute", 4), joint_values("prismatic", 4)[:3]
    (['-pi/2', '0', 'pi/2', 'pi'], ['-1', '-3/4', '-1/2'])
    """
    if kind != "revolute":
        return [sp.sstr(v) for v in _PRISMATIC]
    return [sp.sstr(sp.pi * sp.Rational(2 * k - steps, steps)) for k in range(1, steps + 1)]


def _checked_steps(steps: object) -> int:
    if isinstance(steps, bool) or not isinstance(steps, int):
        raise ArgumentTypeError(f"steps: an integer number of values per joint, got "
                                f"{type(steps).__name__}")
    if not 2 <= steps <= MAX_STEPS:
        raise ArgumentError(f"steps: between 2 and {MAX_STEPS} values per joint, got {steps}")
    return steps


def _checked_value(model, name: str, value: object) -> str:
    """``value`` of joint ``name`` as ``--at`` text, read by the package's parser (an
    angle with an algebraic ``tan(q/2)`` is kept); a bad one names the joint."""
    text = _text(value)
    if not isinstance(text, str | int):
        raise ConfigurationError(f"values {name}: an exact value as text (\"pi/2\", "
                                 f"\"2*atan(1/3)\", \"1/2\"), got {type(value).__name__}")
    text = str(text)
    rational, _ = irrational_values(model, {name: text})
    Configuration.parse(model, dict(rational))
    return text


def _text(value: object) -> object:
    """An exact value as ``--at`` text (other objects as they are)."""
    if isinstance(value, ExactAngle):
        return value.text
    if isinstance(value, sp.Basic):
        return sp.sstr(value)
    if isinstance(value, int) and not isinstance(value, bool):
        return str(value)
    return value


class InteractiveView:
    """Sliders over exact joint values, the picture and the exact numbers there.

    Parameters
    ----------
    system
        A :class:`~coopkin_sym.System`.
    joints
        The joints that get a slider (default: every joint).
    steps
        Values per revolute slider: the multiples of ``2*pi/steps`` in ``(-pi, pi]``
        (24: the multiples of ``pi/12``).
    at
        Values of the other joints and of the parameters (``"L=1"``), as for
        :meth:`System.analyze <coopkin_sym.System.analyze>`; a joint with a slider
        starts at its value here (else at 0, or the slider's first value).
    values
        Exact values of some sliders (``{"q1": ["0", "pi/2", "2*atan(1/3)"]}``),
        instead of the default ones.

    Attributes
    ----------
    sliders
        Joint -> its ``ipywidgets.SelectionSlider`` (its value is ``--at`` text).
    cache
        Configuration text -> (analysis or error, PNG of the picture).

    Example
    -------
    >>> from coopkin_sym import load
    >>> view = load("paper-case1-planar").interactive(steps=4, at="L=1")
    >>> view.sliders["q1"].value = "pi/2"
    >>> view.at, view.numbers.Nm
    ('q1=pi/2,q2=0,L=1', 1)
    """

    def __init__(self, system: Any, joints: Iterable[str] | str | None = None,
                 steps: int = 24, at: str | Mapping | None = None,
                 values: Mapping[str, Sequence] | None = None):
        if not (callable(getattr(system, "analyze", None)) and hasattr(system, "model")):
            raise ArgumentTypeError(f"system: expected a System (coopkin_sym.load(...)), "
                                    f"got {type(system).__name__}")
        widgets = _widgets()
        self.system = system
        model = system.model
        kinds = {j.name: j.type for j in model.joints}
        if joints is None:
            chosen = list(kinds)
        else:
            chosen = [joints] if isinstance(joints, str) else list(joints)
        unknown = [j for j in chosen if j not in kinds]
        if unknown:
            raise ConfigurationError(f"joints: unknown joint {', '.join(map(str, unknown))} "
                                     f"(joints: {', '.join(kinds)})")
        if not chosen:
            raise ConfigurationError("joints: no joint to give a slider")
        steps = _checked_steps(steps)
        values = dict(values or {})
        extra = [j for j in values if j not in chosen]
        if extra:
            raise ConfigurationError(f"values: {', '.join(map(str, extra))} has no slider "
                                     f"(sliders: {', '.join(chosen)})")
        base = split_assignments(at, "--at") if at is not None else []
        for name, value in base:   # checked here, so that a bad one is said at once
            if name in kinds:
                _checked_value(model, name, value)
        self._fixed = [(n, str(_text(v))) for n, v in base if n not in chosen]
        Configuration.parse(model, {n: v for n, v in self._fixed if n not in kinds})
        start = {n: str(_text(v)) for n, v in base if n in chosen}
        self.sliders: dict[str, Any] = {}
        for name in chosen:
            given = values.get(name)
            if given is None:
                options = joint_values(kinds[name], steps)
            else:
                if isinstance(given, str) or not isinstance(given, Sequence) or not given:
                    raise ConfigurationError(f"values {name}: a non-empty list of exact "
                                             "values")
                options = list(dict.fromkeys(_checked_value(model, name, v) for v in given))
            first = start.get(name, "0" if "0" in options else options[0])
            if first not in options:
                options = [first, *options]
            slider = widgets.SelectionSlider(options=options, value=first, description=name,
                                             continuous_update=False)
            slider.observe(self._changed, names="value")
            self.sliders[name] = slider
        self.cache: OrderedDict[str, tuple[Any, bytes]] = OrderedDict()
        self.picture = widgets.Image(format="png")
        self.table = widgets.HTML()
        self.widget = widgets.VBox([widgets.VBox(list(self.sliders.values())),
                                    widgets.HBox([self.picture, self.table])])
        self._holding = False
        self.result: Any = None
        self.error: str | None = None
        self._update()

    # ------------------------------------------------------------------ state

    @property
    def at(self) -> str:
        """The configuration shown, in ``--at`` syntax (sliders, then the fixed values)."""
        return assignments_text([*((n, s.value) for n, s in self.sliders.items()),
                                 *self._fixed])

    @property
    def numbers(self) -> Numbers | None:
        """The exact numbers shown (None when the configuration could not be analyzed)."""
        return None if self.result is None else self.result.numbers

    def select(self, at: str | Mapping) -> InteractiveView:
        """Set several sliders at once (``"q1=pi/2,q2=pi/12"``), then update once;
        a value that is not on its slider is refused, naming it."""
        items = split_assignments(at, "--at")
        items = [(name, str(_text(value))) for name, value in items]
        for name, value in items:
            slider = self.sliders.get(name)
            if slider is None:
                raise ConfigurationError(f"select {name}: no slider "
                                         f"(sliders: {', '.join(self.sliders)})")
            if value not in slider.options:
                raise ConfigurationError(f"select {name}: {value} is not a value of its "
                                         f"slider ({', '.join(slider.options)})")
        self._holding = True
        try:
            for name, value in items:
                self.sliders[name].value = value
        finally:
            self._holding = False
        self._update()
        return self

    # ------------------------------------------------------------------ updates

    def _changed(self, change: Any) -> None:
        if not self._holding:
            self._update()

    def _computed(self, at: str) -> tuple[Any, bytes]:
        if at in self.cache:
            self.cache.move_to_end(at)
            return self.cache[at]
        try:
            result = self.system.analyze(at)
        except CoopkinError as exc:
            entry: tuple[Any, bytes] = (str(exc), b"")
        else:
            entry = (result, _png(result))
        self.cache[at] = entry
        while len(self.cache) > CACHE_SIZE:
            self.cache.popitem(last=False)
        return entry

    def _update(self) -> None:
        from coopkin_sym.present.display import numbers_html

        at = self.at
        result, png = self._computed(at)
        if isinstance(result, str):
            self.result, self.error = None, result
            self.table.value = (f"<p><strong>at {escape(at)}</strong></p>"
                                f"<p>Not analyzed: {escape(result)}</p>")
            return
        self.result, self.error = result, None
        self.table.value = (f"<p><strong>at {escape(at)}</strong></p>"
                            + numbers_html(result.numbers))
        self.picture.value = png

    # ------------------------------------------------------------------ display

    def _repr_mimebundle_(self, **kwargs: Any) -> dict[str, Any]:
        """The widget, with the numbers shown as HTML and text where no widget can be
        shown (a notebook read without its kernel)."""
        bundle = dict(self.widget._repr_mimebundle_(**kwargs) or {})
        bundle["text/plain"] = repr(self)
        bundle["text/html"] = f'<div class="coopkin">{self.table.value}</div>'
        return bundle

    def __repr__(self) -> str:
        return f"<InteractiveView {self.system.model.name} at {self.at}: {self.numbers}>"


def _png(result: Any) -> bytes:
    from coopkin_sym.present.draw import draw_system

    fig = draw_system(result)
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=72)
    return buffer.getvalue()


def interactive(system: Any, joints: Iterable[str] | str | None = None, *, steps: int = 24,
                at: str | Mapping | None = None,
                values: Mapping[str, Sequence] | None = None) -> InteractiveView:
    """The :class:`InteractiveView` of ``system`` (see there for the parameters)."""
    return InteractiveView(system, joints, steps=steps, at=at, values=values)
