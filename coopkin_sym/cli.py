"""The ``coopkin`` command: a thin shell over the library.

``coopkin analyze MODEL [--at ...] [--generic] [--free q1,q2] [--json] [--latex]``,
``coopkin examples [NAME [--show]]``, ``coopkin --version``,
``coopkin sweep MODEL --grid q1=-pi..pi:181,q2=... [-o out.csv]``.
``coopkin locus MODEL -o report.{md,html,tex,json} [--at ...] [--max-depth N]
[--pair q1,q2] [--verify] [--certify [--certify-timeout S]]``,
``coopkin verify MODEL REPORT.json [--max-points N] [--lines K] [--seed S]``,
``coopkin manipulability MODEL [--at ...] [--controlled v_x,v_y] [--json]``.
A part of an output left out (a plot with nothing to show, a motion not available at
the configuration) is announced on stderr as ``coopkin: note: ...``.

``analyze``, ``locus``, ``sweep``, ``manipulability``, ``verify`` and ``draw`` take
``--timeout SECONDS``, a wall-clock bound on the whole run, held whatever the step
(see :mod:`coopkin_sym.exact.bounded`), and show what they are doing on stderr once
they have run for a second (when stderr is a terminal; ``--no-progress``: never).

Exit status: 0 done; 1 a verification found something uncovered or unsound; 2 bad
input (one clear error on stderr, no traceback, nothing half-written); 3 the time
bound was reached: one line ``coopkin: error: time bound of N s reached during
<step>; <what was cut or written>`` (a cut locus still writes its report, which says
what was not explored, as soon as its generic numbers are known: when it was ended
inside a step that cannot be interrupted, as far as it was a second before; the other
commands write nothing); 130 interrupted (Ctrl-C).

Example
-------
>>> from typer.testing import CliRunner
>>> out = CliRunner().invoke(app, ["analyze", "paper-case1-hard", "--json"]).stdout
>>> import json; json.loads(out)["numbers"]["Nm"]
2
"""

from __future__ import annotations

import json
import os
import signal
import sys
import time
import warnings
from contextlib import contextmanager
from typing import Annotated

import typer

from coopkin_sym import (
    ArgumentError,
    BlockTooLarge,
    CoopkinError,
    FiniteMobilityError,
    ManipulabilityError,
    OutputSkipped,
    ReportError,
    SkippedForTime,
    TimeLimitReached,
)
from coopkin_sym.cli_options import (
    AnalyzeOptions,
    Command,
    Group,
    LocusOptions,
    ManipulabilityOptions,
    ModelArg,
    NoProgressOption,
    TimeoutOption,
    options_command,
)

#: Exit status of a run cut by ``--timeout`` (2 is bad input, 1 a failed verification,
#: 130 an interrupt).
TIME_BOUND_EXIT = 3

# Each command imports what it needs when it runs: the command line starts quickly,
# and ``coopkin analyze`` does not pay for the locus, the reports or the pictures.

app = typer.Typer(add_completion=False, no_args_is_help=True, cls=Group,
                  help="Exact mobility and kinematic analysis of cooperating robot systems.")


def _show_version(value: bool) -> None:
    """``coopkin --version``: the installed package's version, then exit 0."""
    if value:
        from coopkin_sym import version

        typer.echo(f"coopkin {version()}")
        raise typer.Exit()


@app.callback()
def _main_options(
    show_version: Annotated[bool, typer.Option(
        "--version", callback=_show_version, is_eager=True,
        help="Print the version and exit.")] = False,
) -> None:
    """Exact mobility and kinematic analysis of cooperating robot systems."""


#: Every error the package raises on purpose (bad input, budgets, time bounds): each is
#: a :class:`~coopkin_sym.CoopkinError`.
USER_ERRORS = (CoopkinError,)


def _fail(message: str) -> None:
    typer.echo(f"coopkin: error: {message}", err=True)
    raise typer.Exit(2)


def _cut(exc: TimeLimitReached, outcome: str) -> None:
    """The one line of a run cut by its time bound, then exit 3."""
    typer.echo(f"coopkin: error: {exc}; {outcome}", err=True)
    raise typer.Exit(TIME_BOUND_EXIT)


def _bounded(work, timeout: float | None, what: str, no_progress: bool, output=None):
    """``work()`` under the time bound, counted from the start of the command, its
    steps shown after a second when stderr is a terminal (see
    :func:`coopkin_sym.run_bounded`; the work then runs in a separate process even
    without a bound, so that the display keeps moving while a step holds the
    interpreter)."""
    from coopkin_sym import run_bounded

    return run_bounded(work, timeout, what=what, owner=f"coopkin {what}",
                       progress=not no_progress, output=output, started=_STARTED[0])


@contextmanager
def _notes():
    """Print every part of an output left out (an
    :class:`~coopkin_sym.errors.OutputSkipped` warning) on stderr, one
    ``coopkin: note: ...`` line each, once the block has run; other warnings pass on.
    Yields a list that then holds the notes' kinds (the warning classes)."""
    kinds: list[type] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", OutputSkipped)
        yield kinds
    kinds.extend(w.category for w in caught)
    for w in caught:
        if issubclass(w.category, OutputSkipped):
            typer.echo(f"coopkin: note: {w.message}", err=True)
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)


@options_command(app, "analyze", AnalyzeOptions)
def analyze(model: str, o: AnalyzeOptions) -> None:
    """Mobility Nm, connectivity Nc, indeterminacy Ni, redundancy Nr (and Ng, Nd, Nh),
    with the block decomposition of the paper, exactly; with --finite, whether the
    first-order motions are finite ones."""
    printer = _PartPrinter()
    try:
        text = _bounded(lambda: _analyze_work(model, o), o.timeout, "analyze",
                        o.no_progress, output=printer)
    except KeyboardInterrupt:
        if printer.names is None:
            raise
        typer.echo(f"interrupted while computing {printer.next_name()}; not shown: "
                   f"{', '.join(printer.left())}", err=True)
        raise typer.Exit(130) from None
    except TimeLimitReached as exc:
        left = printer.left()
        _cut(exc, f"not shown: {', '.join(left)}" if printer.shown else "nothing shown")
    except USER_ERRORS as exc:
        _fail(str(exc))
    if text is not None:
        typer.echo(text)


def _analyze_work(model: str, o: AnalyzeOptions) -> str | None:
    """The work of ``coopkin analyze`` (in the bounded worker): the parts as they come,
    or the whole JSON or LaTeX text."""
    from coopkin_sym import analysis_json, analysis_latex, analysis_parts, analysis_text, load
    from coopkin_sym import deliver_part as deliver
    from coopkin_sym import report_step as report

    if o.finite_problem() is not None:
        raise FiniteMobilityError(o.finite_problem())
    report("loading the model")
    system = load(model)
    report("the analysis")
    result = system.analyze(o.at, generic=o.generic, free=o.free_joints)
    finite = None
    if o.finite:
        report("the finite mobility")
        # at irrational angles, over the number field of the configuration
        finite = result.finite_mobility(order=o.order)
    if not (o.as_json or o.latex or _irrational(result)):
        parts = analysis_parts(result)
        if finite is not None:
            from coopkin_sym import finite_lines
            parts.append(("finite mobility", lambda: finite_lines(finite)))
        deliver(("names", [name for name, _ in parts]))
        for name, part in parts:
            report(f"the {name}" if name in ("numbers", "sentences") else name)
            deliver(("part", name, part()))
        return None
    report("the JSON document" if o.as_json else "the text")
    if o.as_json:
        return analysis_json(result, finite)
    if not _irrational(result):
        text = analysis_latex(result) if o.latex else analysis_text(result)
        if finite is not None:
            from coopkin_sym import finite_latex, finite_lines
            text += ("\n" + finite_latex(finite)) if o.latex else (
                "\n" + "\n".join(finite_lines(finite)))
        return text
    from coopkin_sym import finite_latex, finite_lines, irrational_latex, irrational_text
    text = irrational_latex(result) if o.latex else irrational_text(result)
    if finite is not None:
        text += ("\n" + finite_latex(finite)) if o.latex else (
            "\n" + "\n".join(finite_lines(finite)))
    return text


class _PartPrinter:
    """Prints the parts of ``coopkin analyze`` as they come (the numbers first) and
    remembers which were shown."""

    def __init__(self):
        self.names: list[str] | None = None
        self.shown: list[str] = []

    def __call__(self, item) -> None:
        if item[0] == "names":
            self.names = list(item[1])
            return
        _, name, lines = item
        typer.echo("\n".join(lines))
        self.shown.append(name)

    def left(self) -> list[str]:
        return [n for n in (self.names or []) if n not in self.shown]

    def next_name(self) -> str:
        left = self.left()
        return left[0] if left else "the output"


@app.command(cls=Command)
def examples(
    name: Annotated[str | None, typer.Argument(
        help="One example: its line, or with --show its model file.")] = None,
    show: Annotated[bool, typer.Option(
        "--show", help="Print the example's model file (YAML), to start a model "
                       "from.")] = False,
) -> None:
    """List the shipped example systems (the first sentence of each file's header), or
    print one example's model file."""
    from coopkin_sym import describe_example, example_path, examples

    try:
        if show and name is None:
            raise ArgumentError("--show: name the example to show (see `coopkin "
                                "examples`)")
        if show:
            typer.echo(example_path(name).read_text(encoding="utf-8"), nl=False)
            return
        for each in examples() if name is None else [name]:
            typer.echo(f"{each:28s} {describe_example(each)}")
    except USER_ERRORS as exc:
        _fail(str(exc))


@app.command(cls=Command)
def draw(
    model: ModelArg,
    output: Annotated[str, typer.Option(
        "--output", "-o", help="The picture to write: .png, .pdf or .svg.")],
    at: Annotated[str | None, typer.Option(
        "--at", help="Joint values and parameters, as for `coopkin analyze`; parameters "
                     "left symbolic are drawn at 1.")] = None,
    motion: Annotated[str | None, typer.Option(
        "--motion", help="One motion to draw: coordinated:K (C12, C22), indeterminate:K "
                         "(C11) or redundant:K (C23), K from 1.")] = None,
    ellipsoid: Annotated[bool, typer.Option(
        "--ellipsoid", help="Also draw the manipulability ellipsoid of the object's "
                            "translations at unit joint speed (scale stated in the "
                            "title).")] = False,
    labels: Annotated[str, typer.Option(
        "--labels", help="Name labels: names (long ones shortened), short (joint "
                         "numbers in their arm) or none.")] = "names",
    timeout: TimeoutOption = None,
    no_progress: NoProgressOption = False,
) -> None:
    """Draw the system (arms, joints, contacts, object) and optionally one motion."""
    from coopkin_sym import DrawError

    styles = {"names": True, "short": "short", "none": False}

    def work():
        from coopkin_sym import load, save_picture
        from coopkin_sym import report_step as report

        report("loading the model")
        system = load(model)
        with warnings.catch_warnings(record=True) as caught:   # said by the command
            warnings.simplefilter("always", OutputSkipped)
            path = save_picture(system, output, at=at, motion=motion, ellipsoid=ellipsoid,
                                labels=styles[labels])
        return path, [str(w.message) for w in caught if issubclass(w.category,
                                                                    OutputSkipped)]

    try:
        if labels not in styles:
            raise DrawError(f"--labels: names, short or none (not {labels!r})")
        path, notes = _bounded(work, timeout, "draw", no_progress)
    except TimeLimitReached as exc:
        _cut(exc, "nothing written")
    except USER_ERRORS as exc:
        _fail(str(exc))
    for note in notes:
        typer.echo(f"coopkin: note: {note}", err=True)
    typer.echo(f"wrote {path}")


@options_command(app, "manipulability", ManipulabilityOptions)
def manipulability_command(model: str, options: ManipulabilityOptions) -> None:
    """The kinematic manipulability ellipsoid of chosen object velocities, exactly: E,
    det E, its rank and where it degenerates; at a point also its semi-axes (floats)."""
    o = options

    def work() -> str:
        from coopkin_sym import load, manipulability_json, manipulability_text
        from coopkin_sym import report_step as report

        report("loading the model")
        system = load(model)
        free_joints = [f.strip() for f in o.free.split(",") if f.strip()] if o.free else None
        report("the analysis")
        result = system.analyze(o.at, generic=o.generic, free=free_joints)
        if _irrational(result):
            raise ManipulabilityError("--at: the ellipsoid is computed at rational "
                                      "configurations only (tan(q/2) rational)")
        names = [c.strip() for c in o.controlled.split(",")] if o.controlled else None
        where = [c.strip() for c in o.point.split(",")] if o.point else None
        report("the ellipsoid")
        budget = {} if o.max_terms is None else {"max_terms": o.max_terms}
        m = result.manipulability(names, length=o.length, point=where, **budget)
        report("the text")
        return (manipulability_json(m, result) if o.as_json
                else manipulability_text(m, result))

    try:
        text = _bounded(work, o.timeout, "manipulability", o.no_progress)
    except TimeLimitReached as exc:
        _cut(exc, "nothing shown")
    except BlockTooLarge as exc:   # cut by the budget of terms, as by a time bound
        typer.echo(f"coopkin: error: {exc}", err=True)
        raise typer.Exit(TIME_BOUND_EXIT) from None
    except USER_ERRORS as exc:
        _fail(str(exc))
    typer.echo(text)


@app.command(cls=Command)
def sweep(
    model: ModelArg,
    grid_spec: Annotated[str, typer.Option(
        "--grid", help="Joints to sweep: NAME=LO..HI:COUNT,... e.g. "
                       "q1=-pi..pi:181,q2=-pi..pi:181 (angles with an irrational tan(q/2) "
                       "are snapped to exact ones within 1e-9 rad, and the output says so).")],
    at: Annotated[str | None, typer.Option(
        "--at", help="Values of the other joints and of parameters, as for "
                     "`coopkin analyze`.")] = None,
    output: Annotated[str | None, typer.Option(
        "--output", "-o", help="Write the table to a .csv file (and its metadata to "
                               "FILE.csv.json), a .json or a .parquet file (default: CSV "
                               "on standard output).")] = None,
    as_json: Annotated[bool, typer.Option(
        "--json", help="Print JSON instead of CSV when no --output is given.")] = False,
    workers: Annotated[int, typer.Option(
        "--workers", min=1, help="Worker processes for the sweep.")] = 1,
    no_progress: NoProgressOption = False,
    timeout: TimeoutOption = None,
) -> None:
    """Exact numbers at every point of a grid: ranks modulo a prime certify generic
    points, every other point is rechecked exactly over Q."""
    from coopkin_sym import SweepError, SweepResult, check_output_path, write_files

    fmt = "json" if as_json else "csv"
    try:
        target = None
        if output is not None:
            target, suffix = check_output_path(output, (".csv", ".json", ".parquet"),
                                               SweepError, "table (--output)")
            fmt = suffix.lstrip(".")
            if fmt == "parquet":
                SweepResult.check_parquet()
            if fmt == "csv":            # its metadata file, noted as the table is
                check_output_path(SweepResult.metadata_path(target), (".json",), SweepError,
                                  "table metadata (--output)")
    except USER_ERRORS as exc:
        _fail(str(exc))

    def work():
        from coopkin_sym import grid, load
        from coopkin_sym import report_step as report

        report("loading the model")
        system = load(model)
        report("reading the grid")
        points = grid(system, grid_spec)
        result = _sweep(system, points, at, workers)
        report("the table")
        if target is not None:
            return result.files(target), result.summary(), result.prime
        text = result.json_text() if fmt == "json" else result.to_csv()
        return text, result.summary(), result.prime

    try:
        text, counts, prime = _bounded(work, timeout, "sweep", no_progress)
        if target is not None:
            write_files(text, SweepError)
    except TimeLimitReached as exc:
        _cut(exc, "nothing written")
    except USER_ERRORS as exc:
        _fail(str(exc))
    if target is None:
        typer.echo(text, nl=False)
        return
    c = counts
    typer.echo(f"{c['points']} points: {c['certified_mod_p']} certified modulo "
               f"{prime}, {c['rechecked_exact']} rechecked exactly; "
               f"{c['snapped_values']} snapped angles; wrote "
               + " and ".join(str(p) for p in text))


@options_command(app, "locus", LocusOptions)
def locus(model: str, options: LocusOptions) -> None:
    """The singularity locus: every family of configurations where the numbers differ
    from the generic ones, decided exactly, as a report."""
    from coopkin_sym import check_report_target

    try:
        check_report_target(options.output)
    except ReportError as exc:
        _fail(str(exc))
    started = _STARTED[0] if _STARTED[0] is not None else time.monotonic()
    try:
        result, checked, checked_locked, cut, written = _locus_report(model, options,
                                                                      started)
    except TimeLimitReached as exc:
        _cut(_in_command_bound(exc, options.timeout), "nothing written")
    except USER_ERRORS as exc:
        _fail(str(exc))
    _echo_locus(result, written)
    if cut is not None:
        pictures = len(written) - 1
        also = f" and {pictures} picture{'' if pictures == 1 else 's'}" if pictures else ""
        _cut(cut, f"the report says what was not explored; wrote {written[0]}{also}")
    if checked is not None:
        if checked_locked is not None:
            _echo_locked(checked_locked, checked)
        _echo_verification(checked)


def _locus_report(model: str, o: LocusOptions, started: float):
    """The locus of ``coopkin locus`` (under its share of the bound), its certificate
    and verification when asked, and its report written: ``(locus, verification,
    verification of the locked locus, the TimeLimitReached that cut it or None, the
    files written)``."""
    from coopkin_sym import load, parse_pairs, verification_json, write_report

    def work():
        from coopkin_sym import deliver_part as deliver
        from coopkin_sym import report_step as report

        report("loading the model")
        system = load(model)
        pairs = parse_pairs(o.pair, system) if o.pair else None
        deliver((system, pairs))
        return _locus_work(system, o.at, o.max_depth, o.timeout, o.free_joints,
                           o.pi_size, o.certify, o.certify_timeout, o.verify, o.finite)

    loaded: list = []
    # the search has a share of the bound, the report the rest: its text first, then
    # its pictures while time is left (those left out are said)
    search = None if o.timeout is None else o.timeout * SEARCH_SHARE
    try:
        result, checked, checked_locked, cut = _bounded(work, search, "locus",
                                                        o.no_progress,
                                                        output=loaded.append)
    except TimeLimitReached as exc:  # ended at the bound: the last copy kept
        cut = _in_command_bound(exc, o.timeout)
        result, checked, checked_locked = _ended_locus(cut, loaded), None, None
    system, pairs = loaded[0]
    shown = verification_json(checked) if checked else None
    if shown is not None and checked_locked is not None:
        shown["locked"] = verification_json(checked_locked)
    until = None if o.timeout is None else started + o.timeout
    with _notes() as notes:
        written = write_report(result, o.output, system, pairs=pairs,
                               verification=shown, pictures_until=until)
    if cut is None and SkippedForTime in notes:
        cut = TimeLimitReached(o.timeout, "the pictures of the report")
    elif cut is not None:
        cut = _in_command_bound(cut, o.timeout)
    return result, checked, checked_locked, cut, written


def _echo_locus(result, written) -> None:
    """The summary lines of ``coopkin locus``: components, completeness, files."""
    from coopkin_sym import completeness_text

    real = sum(1 for c in result.components if c.real)
    n, u = len(result.components), len(result.unexplored)
    left = f"; {u} item{'' if u == 1 else 's'} not explored" if u else ""
    files = ", ".join(str(p) for p in written)
    typer.echo(f"{n} component{'' if n == 1 else 's'} ({real} real){left}; "
               f"{completeness_text(result)}; wrote " + files)
    if result.locked is not None:
        lk = result.locked
        typer.echo(f"with the motors held still (where the passive-joint numbers change): "
                   f"{len(lk.components)} component{'' if len(lk.components) == 1 else 's'}"
                   f"; {completeness_text(lk)}")


#: What the work of ``coopkin locus`` delivers once its search is whole.
SEARCH_DONE = "the search is complete"

#: The share of ``coopkin locus --timeout`` given to the search (and its certificate and
#: verification); the report has the rest.
SEARCH_SHARE = 0.8


def _in_command_bound(exc: TimeLimitReached, timeout: float | None) -> TimeLimitReached:
    """``exc`` told with the command's bound (the search ran under a share of it)."""
    if timeout is None or exc.seconds == timeout:
        return exc
    told = TimeLimitReached(timeout, exc.where, hard=exc.hard)
    told.kept = getattr(exc, "kept", None)
    return told


def _ended_locus(exc: TimeLimitReached, loaded: list):
    """The locus of a run ended at its bound inside a step that cannot be interrupted:
    the last copy the search kept (as far as it got), with what was cut; or ``exc``
    again when there is none (before the generic numbers, or no copy yet)."""
    from coopkin_sym import ended_at_bound

    # after the whole search, the work delivers SEARCH_DONE (its copy is then whole)
    locus = ended_at_bound(exc, SEARCH_DONE in loaded) if loaded else None
    if locus is None:
        raise exc
    return locus


def _locus_work(system, at, max_depth, timeout, free_joints, pi_size, certify,
                certify_timeout, verify, finite=False):
    """The computation of ``coopkin locus`` (run under its bound): the locus, its
    certificate and verification when asked, and the
    :class:`~coopkin_sym.errors.TimeLimitReached` that cut it (None if none did)."""
    if finite:              # said before the search, not after it
        system.check_finite()
    result = system.search_locus(at, max_depth=max_depth, timeout=timeout,
                                 progress=True, free=free_joints, pi_size=pi_size)
    from coopkin_sym import Certificate, keep_result
    from coopkin_sym import deliver_part as deliver
    from coopkin_sym import report_step as report

    cut = _time_cut(result, timeout)
    locked = system.with_actuators_locked() if result.locked else None
    checked = checked_locked = None
    if cut is not None:      # the bound has passed: nothing more to run
        return result, checked, checked_locked, cut
    parts = [result] + ([result.locked] if result.locked is not None else [])
    if certify:              # until it is made, the certificate says the bound ended it
        for part in parts:
            part.certificate = Certificate.cut_at_bound(part.system, timeout,
                                                        "the completeness certificate")
    keep_result(result)      # a run ended at its bound from here on has the whole search
    deliver(SEARCH_DONE)
    stage = ""
    try:
        if finite:
            stage = "the finite mobility at the witnesses"
            report(stage)
            system.finite_locus(result)
        if certify:
            stage = "the completeness certificate"
            report(stage)
            result.certificate = system.certify_locus(result, budget=certify_timeout)
            if result.locked is not None:
                result.locked.certificate = locked.certify_locus(result.locked,
                                                                 budget=certify_timeout)
            keep_result(result)
        if verify:
            stage = "the verification"
            report(stage)
            checked = system.verify_locus(result)
            if result.locked is not None:
                checked_locked = locked.verify_locus(result.locked)
    except TimeLimitReached as exc:  # the report is written without what was cut
        for part in parts:
            if getattr(getattr(part.certificate, "refused", None), "kind",
                       None) == "cert_time_bound":
                part.certificate = Certificate.cut_at_bound(
                    part.system, timeout, "the completeness certificate")
        if not exc.where:
            exc = TimeLimitReached(exc.seconds, stage, hard=exc.hard)
        return result, None, None, exc
    return result, checked, checked_locked, None


def _time_cut(locus, timeout: float | None):
    """The :class:`~coopkin_sym.errors.TimeLimitReached` behind a locus (or its locked
    locus) cut by its time bound, inside a long computation or between the steps of
    the search; None if it was not cut."""
    steps = {"time_depth": lambda r: f"the search at depth {r['depth']}",
             "time_component": lambda r: f"a component at depth {r['depth']}",
             "time_pi_set": lambda r: "the slices at q = pi",
             "time_pi_sets_left": lambda r: "the slices at q = pi"}
    for part in (locus, locus.locked):
        for item in (part.unexplored if part is not None else ()):
            kind = getattr(item, "kind", None)
            if kind == "time_whole_run":
                return TimeLimitReached(item["seconds"], item["where"])
            if kind in steps and timeout is not None:
                return TimeLimitReached(timeout, steps[kind](item))
    return None


def _echo_locked(locked, checked) -> None:
    """The verification of the locked system's locus (where the passive-joint numbers
    change), indented; on failure the main one too, then exit 1."""
    from coopkin_sym import verification_lines
    typer.echo("\n".join(["with the motors held still:"]
                          + ["  " + x for x in verification_lines(locked)]))
    if not locked.ok:
        typer.echo("\n".join(verification_lines(checked)))
        raise typer.Exit(1)


def _echo_verification(checked) -> None:
    from coopkin_sym import verification_lines
    typer.echo("\n".join(verification_lines(checked)))
    if not checked.ok:
        raise typer.Exit(1)


@app.command("verify", cls=Command)
def verify_report(
    model: ModelArg,
    report: Annotated[str, typer.Argument(help="A locus report in JSON (coopkin locus "
                                                 "MODEL -o REPORT.json).")],
    max_points: Annotated[int, typer.Option(
        "--max-points", min=1, help="Largest grid (smaller value sets beyond it).")] = 50_000,
    lines: Annotated[int, typer.Option(
        "--lines", min=0, help="Random rational lines to check.")] = 12,
    seed: Annotated[int, typer.Option("--seed", help="Seed of the lines.")] = 0,
    as_json: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
    timeout: TimeoutOption = None,
    no_progress: NoProgressOption = False,
) -> None:
    """Check a locus report independently: exact numbers on a rational grid (q = pi
    included) and at every drop point of random rational lines; every point with
    non-generic numbers must lie on a component with those numbers, and every witness
    must check. Exit 1 when something is uncovered or unsound."""
    from coopkin_sym import load, read_locus, verification_json

    try:
        system = load(model)
        locus = read_locus(report)
    except USER_ERRORS as exc:
        _fail(str(exc))

    def work():
        checked = system.verify_locus(locus, max_points=max_points, lines=lines, seed=seed)
        locked = None
        if locus.locked is not None:  # where the passive-joint numbers change
            locked = system.with_actuators_locked().verify_locus(
                locus.locked, max_points=max_points, lines=lines, seed=seed)
        return checked, locked

    try:
        checked, locked = _bounded(work, timeout, "verify", no_progress)
    except TimeLimitReached as exc:
        _cut(exc, "no verdict")
    except USER_ERRORS as exc:
        _fail(str(exc))
    if as_json:
        data = verification_json(checked)
        if locked is not None:
            data["locked"] = verification_json(locked)
        typer.echo(json.dumps(data, indent=2))
        if not checked.ok or (locked is not None and not locked.ok):
            raise typer.Exit(1)
        return
    if locked is not None:
        _echo_locked(locked, checked)
    _echo_verification(checked)


def _irrational(result) -> bool:
    """Whether ``result`` is an analysis over a number field (an
    :class:`~coopkin_sym.analysis.irrational.IrrationalAnalysis`, whose module is only
    imported when that path is taken), not over Q or Q(t, L)."""
    from coopkin_sym import Analysis
    return not isinstance(result, Analysis)


def worker_count(requested: int, points: int, cpus: int | None = None) -> int:
    """Worker processes actually started: never more than requested, than the
    machine's processors, or than the points to share out.

    Example
    -------
    >>> worker_count(1000, 10, cpus=2)
    2
    >>> worker_count(8, 1, cpus=16)
    1
    """
    cpus = cpus if cpus is not None else (os.cpu_count() or 1)
    return max(1, min(requested, cpus, points))


def _sweep(system, points, at, workers: int):
    """The sweep, in ``worker_count`` processes, its progress reported; on Ctrl-C or
    an error the worker processes are stopped at once (no waiting for their chunks)."""
    import concurrent.futures
    import multiprocessing

    from coopkin_sym import sweep

    n = len(points)
    count = worker_count(workers, n)
    if count == 1:
        return sweep(system, points, at=at, progress=True)

    chunk = max(1, min(16384, -(-n // (4 * count))))
    pool = concurrent.futures.ProcessPoolExecutor(count)  # looked up at use (tests patch it)
    try:
        result = sweep(system, points, at=at, executor=pool, progress=True, chunk=chunk)
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        for child in multiprocessing.active_children():
            child.terminate()
        raise
    pool.shutdown()
    return result


def _interrupted(signum, frame) -> None:
    """Ctrl-C: one line on stderr; the KeyboardInterrupt then unwinds (temporary files
    are removed on the way) and the command exits with 130."""
    sys.stderr.write("coopkin: interrupted\n")
    sys.stderr.flush()
    raise KeyboardInterrupt


#: When the command started (``time.monotonic()``, set by :func:`main`; None: the
#: bound of ``--timeout`` starts with the computation), and the command's process id.
_STARTED: list = [None, None]


def _terminated(signum, frame) -> None:
    """SIGTERM or SIGHUP (``timeout 60 coopkin ...``, a closed terminal): unwind, so
    that the processes the command started are ended, and exit with 128 + signal. In
    a process forked from the command (a sweep worker) the signal does what it does by
    default: it ends that process at once."""
    if os.getpid() != _STARTED[1]:
        signal.signal(signum, signal.SIG_DFL)
        os.kill(os.getpid(), signum)
        return
    raise SystemExit(128 + signum)


def main() -> None:
    """Console-script entry point."""
    _STARTED[:] = [time.monotonic(), os.getpid()]
    # the command validates its own files with pydantic: looking through every
    # installed package for pydantic plugins would cost ~20 ms at each start
    os.environ.setdefault("PYDANTIC_DISABLE_PLUGINS", "__all__")
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, _interrupted)
    for name in ("SIGTERM", "SIGHUP"):   # unwind: a bounded child is ended on the way
        number = getattr(signal, name, None)
        if number is not None and signal.getsignal(number) is signal.SIG_DFL:
            signal.signal(number, _terminated)
    try:
        app()
    except KeyboardInterrupt:  # pragma: no cover - typer turns it into exit 130
        _exit_interrupted()
    except SystemExit as exc:
        if exc.code == 130:
            _exit_interrupted()
        raise


def _exit_interrupted() -> None:
    """Exit with 130 after Ctrl-C without running exit handlers: they join the threads
    of a worker pool whose processes were just stopped, which can wait for ever.
    Temporary files are already removed (the interrupt unwound through them)."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(130)
