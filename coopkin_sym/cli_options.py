"""The options of the ``coopkin`` commands that take many, as small dataclasses.

A command with many options (``coopkin locus``) is written as ``run(model, options)``
taking one :class:`LocusOptions`; :func:`options_command` registers it with typer,
which sees one parameter per field (its ``Annotated`` typer option), exactly as if
they were written in the command's signature.

Example
-------
>>> from typer.testing import CliRunner
>>> app = typer.Typer()
>>> @dataclass
... class Hello:
...     loud: Annotated[bool, typer.Option("--loud")] = False
>>> @options_command(app, "hello", Hello)
... def hello(model: str, options: Hello) -> None:
...     '''Say hello.'''
...     typer.echo(model.upper() if options.loud else model)
>>> CliRunner().invoke(app, ["five-bar", "--loud"]).stdout
'FIVE-BAR\\n'
"""

from __future__ import annotations

import dataclasses
import inspect
import typing
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated

import typer

ModelArg = Annotated[str, typer.Argument(
    help="A model file (YAML/JSON) or a shipped example name (see `coopkin examples`).")]
TimeoutOption = Annotated[float | None, typer.Option(
    "--timeout", min=0, help="Wall-clock bound in seconds for the whole run, held even "
                             "inside steps that cannot be interrupted; past it the "
                             "command stops, says what was cut and exits with 3.")]
NoProgressOption = Annotated[bool, typer.Option(
    "--no-progress", help="No progress display (none is shown when stderr is not a "
                          "terminal, nor in the first second).")]


class _PlainFlags:
    """Shows an on/off option (``--json``, ``--help``) as a plain flag in the help,
    without a value type: it takes no value."""

    def get_params(self, ctx):
        params = super().get_params(ctx)  # type: ignore[misc]
        for param in params:
            if getattr(param, "is_flag", False) and param.metavar is None:
                param.metavar = ""
        return params


class Command(_PlainFlags, typer.core.TyperCommand):
    """A ``coopkin`` command: its flags shown as plain flags in the help, and its line
    in ``coopkin --help`` the first paragraph of its docstring as one paragraph (the
    docstring's own line breaks left out).

    Example
    -------
    >>> from typer.testing import CliRunner
    >>> app = typer.Typer()
    >>> @app.command(cls=Command)
    ... def hello(loud: Annotated[bool, typer.Option("--loud", help="Shout.")] = False):
    ...     "Say hello."
    >>> "<bool>" in CliRunner().invoke(app, ["--help"]).stdout
    False
    >>> Command("go", help="Go there,\\n  quickly.\\n\\nMore.").short_help
    'Go there, quickly.'
    """

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        if self.short_help is None and self.help:
            first = inspect.cleandoc(self.help).split("\n\n")[0]
            self.short_help = " ".join(first.split())


class Group(_PlainFlags, typer.core.TyperGroup):
    """The ``coopkin`` command line (its commands and options such as ``--version``),
    its flags shown as plain flags in the help.

    Example
    -------
    >>> from typer.testing import CliRunner
    >>> app = typer.Typer(cls=Group)
    >>> @app.callback()
    ... def main(quiet: Annotated[bool, typer.Option("--quiet")] = False):
    ...     "A tool."
    >>> @app.command(cls=Command)
    ... def hello():
    ...     "Say hello."
    >>> "<bool>" in CliRunner().invoke(app, ["--help"]).stdout
    False
    """


def options_command(app: typer.Typer, name: str, options: type
                    ) -> Callable[[Callable], Callable]:
    """Register ``run(model, options)`` as the command ``name`` of ``app``: typer sees
    the model argument, then one option per field of the dataclass ``options``."""
    hints = typing.get_type_hints(options, include_extras=True)
    keyword = inspect.Parameter.KEYWORD_ONLY
    params = [inspect.Parameter("model", keyword, annotation=ModelArg)]
    for f in dataclasses.fields(options):
        default = inspect.Parameter.empty if f.default is dataclasses.MISSING else f.default
        params.append(inspect.Parameter(f.name, keyword, default=default,
                                        annotation=hints[f.name]))

    def register(run: Callable) -> Callable:
        def command(**values) -> None:
            model = values.pop("model")
            return run(model, options(**values))

        command.__signature__ = inspect.Signature(params)  # type: ignore[attr-defined]
        command.__annotations__ = {p.name: p.annotation for p in params}
        command.__doc__, command.__name__ = run.__doc__, run.__name__
        app.command(name, cls=Command)(command)
        return run
    return register


@dataclass
class LocusOptions:
    """The options of ``coopkin locus``.

    Example
    -------
    >>> LocusOptions("report.md", free="q1, q2").free_joints
    ['q1', 'q2']
    """

    output: Annotated[str, typer.Option(
        "--output", "-o", help="The report to write: .md, .html, .tex or .json (plots of "
                               "the components go next to it as <stem>_<qi>_<qj>.png).")]
    at: Annotated[str | None, typer.Option(
        "--at", help="Values fixing some joints or parameters, as for `coopkin analyze`; "
                     "the other joints stay free.")] = None
    max_depth: Annotated[int, typer.Option(
        "--max-depth", min=0, help="How deep to look inside components for further "
                                   "drops (0: the generic locus only).")] = 2
    timeout: Annotated[float | None, typer.Option(
        "--timeout", min=0, help="Wall-clock bound in seconds for the whole run (the "
                                 "generic step, --certify and --verify included), held "
                                 "even inside steps that cannot be interrupted; a run "
                                 "cut at a check of the bound writes its report, which "
                                 "says what was cut, and exits with 3.")] = None
    no_progress: NoProgressOption = False
    pair: Annotated[list[str] | None, typer.Option(
        "--pair", help="Two joints to plot the components on, e.g. q1,q2 (repeatable; "
                       "default: the pairs that occur together in a component).")] = None
    free: Annotated[str | None, typer.Option(
        "--free", help="Comma-separated joints to keep free, as for `coopkin analyze`; "
                       "the others not set with --at stay at home (q = 0).")] = None
    pi_size: Annotated[int | None, typer.Option(
        "--pi-size", min=0, help="Sets of joints at q = pi are searched inside up to this "
                                 "many joints at once (default: all for up to four "
                                 "revolute joints, then fewer).")] = None
    verify: Annotated[bool, typer.Option(
        "--verify", help="Check the locus independently afterwards (see `coopkin verify`); "
                         "exit 1 when something is uncovered or unsound.")] = False
    certify: Annotated[bool, typer.Option(
        "--certify", help="Prove the locus complete by Groebner bases, chart by chart and "
                          "depth by depth, or say why it is not proved (the report's "
                          "summary line).")] = False
    certify_timeout: Annotated[float, typer.Option(
        "--certify-timeout", min=0, help="Wall-clock bound in seconds for the whole "
                                         "certificate (each test at most 30 s).")] = 300.0
    finite: Annotated[bool, typer.Option(
        "--finite", help="Also the finite mobility at each component's witness (rational, "
                         "else algebraic, over its number field): "
                         "which singular families are bifurcations, which are shaky, "
                         "which only change the first-order numbers (hard, complete and "
                         "frictionless contacts).")] = False

    @property
    def free_joints(self) -> list[str] | None:
        """``--free`` as a list of joint names (None when not given)."""
        return _names(self.free)


@dataclass
class AnalyzeOptions:
    """The options of ``coopkin analyze``.

    Example
    -------
    >>> AnalyzeOptions(free="q1, q2").free_joints, AnalyzeOptions().order
    (['q1', 'q2'], None)
    """

    at: Annotated[str | None, typer.Option(
        "--at", help="Joint values and parameters, e.g. q1=pi/2,q2=2*atan(1/3),L=1000 "
                     "(angles in radians, or in degrees: q1=90deg); unset joints stay at "
                     "home (q = 0), unset parameters symbolic.")] = None
    generic: Annotated[bool, typer.Option(
        "--generic", help="Keep every joint variable symbolic (t_q = tan(q/2)).")] = False
    free: Annotated[str | None, typer.Option(
        "--free", help="Comma-separated joints to keep symbolic.")] = None
    as_json: Annotated[bool, typer.Option("--json", help="Print one JSON object.")] = False
    latex: Annotated[bool, typer.Option("--latex", help="Print the blocks as LaTeX.")] = False
    finite: Annotated[bool, typer.Option(
        "--finite", help="Also the finite mobility: the local dimension of the closed "
                         "system's configuration space, its branches and whether the "
                         "first-order motions are finite (hard, complete and "
                         "frictionless contacts; every joint at an exact angle).")] = False
    order: Annotated[int | None, typer.Option(
        "--order", min=2, help="With --finite: expand to exactly this order (default: "
                               "2, 3, 4 until decided).")] = None
    timeout: TimeoutOption = None
    no_progress: NoProgressOption = False

    @property
    def free_joints(self) -> list[str] | None:
        return _names(self.free)

    def finite_problem(self) -> str | None:
        """Why ``--finite`` or ``--order`` cannot be asked as given (None: they can)."""
        if self.order is not None and not self.finite:
            return "--order is the order of the finite mobility's expansion: give it with --finite"
        if self.finite and (self.generic or self.free_joints):
            return ("--finite needs every joint at an exact angle (a rational or "
                    "algebraic tan(q/2); not --generic or --free)")
        return None


@dataclass
class ManipulabilityOptions:
    """The options of ``coopkin manipulability``.

    Example
    -------
    >>> ManipulabilityOptions(controlled="v_x,v_y").length
    '1'
    """

    at: Annotated[str | None, typer.Option(
        "--at", help="Joint values and parameters, as for `coopkin analyze`.")] = None
    generic: Annotated[bool, typer.Option(
        "--generic", help="Keep every joint variable symbolic: E as rational functions "
                          "and where it degenerates.")] = False
    free: Annotated[str | None, typer.Option(
        "--free", help="Comma-separated joints to keep symbolic.")] = None
    controlled: Annotated[str | None, typer.Option(
        "--controlled", help="Comma-separated object velocities, e.g. v_x,v_y "
                             "(default: the whole twist).")] = None
    length: Annotated[str, typer.Option(
        "--length", help="The characteristic length angular velocities are scaled by "
                         "(a positive number or a parameter, e.g. L).")] = "1"
    point: Annotated[str | None, typer.Option(
        "--point", help="x,y,z: v is the velocity of this object point (base frame).")
    ] = None
    as_json: Annotated[bool, typer.Option("--json", help="Print one JSON object.")] = False
    max_terms: Annotated[int | None, typer.Option(
        "--max-terms", min=1,
        help="The budget of terms of one symbolic entry on the way (numerator and "
             "denominator; default 10000): past it the run stops, says where, and exits "
             "with status 3.")] = None
    timeout: TimeoutOption = None
    no_progress: NoProgressOption = False


def _names(text: str | None) -> list[str] | None:
    return [f.strip() for f in text.split(",") if f.strip()] if text else None


__all__ = ["Command", "Group", "LocusOptions", "ManipulabilityOptions", "ModelArg",
           "NoProgressOption",
           "TimeoutOption", "options_command"]
