"""The ``coopkin`` command: a thin shell over the library.

``coopkin analyze MODEL [--at ...] [--generic] [--free q1,q2] [--json] [--latex]``,
``coopkin examples``. Bad input prints one clear error to stderr and exits 2; no
traceback, nothing half-written.

Example
-------
>>> from typer.testing import CliRunner
>>> out = CliRunner().invoke(app, ["analyze", "paper-case1-hard", "--json"]).stdout
>>> import json; json.loads(out)["numbers"]["Nm"]
2
"""

from __future__ import annotations

import json
import sys
from typing import Annotated

import sympy as sp
import typer

from .configuration import ConfigurationError
from .exactnum import NumberError
from .mobility import Analysis, InfeasibleMotion
from .model import ModelError
from .system import load

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="Exact mobility and kinematic analysis of cooperating robot systems.")

USER_ERRORS = (ModelError, ConfigurationError, NumberError, InfeasibleMotion)


def _fail(message: str) -> None:
    typer.echo(f"coopkin: error: {message}", err=True)
    raise typer.Exit(2)


@app.command()
def analyze(
    model: Annotated[str, typer.Argument(help="A model file (YAML/JSON) or a shipped "
                                              "example name (see `coopkin examples`).")],
    at: Annotated[str | None, typer.Option(
        "--at", help="Joint values and parameters, e.g. q1=pi/2,q2=2*atan(1/3),L=1000; "
                     "unset joints stay at home (q = 0), unset parameters symbolic.")] = None,
    generic: Annotated[bool, typer.Option(
        "--generic", help="Keep every joint variable symbolic (t_q = tan(q/2)).")] = False,
    free: Annotated[str | None, typer.Option(
        "--free", help="Comma-separated joints to keep symbolic.")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print one JSON object.")] = False,
    latex: Annotated[bool, typer.Option("--latex", help="Print the blocks as LaTeX.")] = False,
) -> None:
    """Mobility Nm, connectivity Nc, indeterminacy Ni, redundancy Nr (and Ng, Nd, Nh),
    with the block decomposition of the paper, exactly."""
    try:
        system = load(model)
        free_joints = [f.strip() for f in free.split(",") if f.strip()] if free else None
        result = system.analyze(at, generic=generic, free=free_joints)
        if as_json:
            text = json.dumps(result.as_json(), indent=2)
        elif latex:
            text = render_latex(result)
        else:
            text = render_text(result)
    except USER_ERRORS as exc:
        _fail(str(exc))
    typer.echo(text)


@app.command()
def examples() -> None:
    """List the shipped example systems."""
    from .examples import describe_example, list_examples

    for name in list_examples():
        typer.echo(f"{name:28s} {describe_example(name)}")


def render_text(a: Analysis) -> str:
    """The human report of ``coopkin analyze``."""
    from .interpret import sentences

    lines = [f"System: {a.model.name}"]
    where = a.configuration.at_text() or "home (all joints at 0)"
    if a.configuration.free:
        where += f"; symbolic joints: {', '.join(sorted(a.configuration.free))}"
    lines.append(f"Configuration: {where}")
    if a.variables:
        lines.append(f"Symbols: {', '.join(map(str, a.variables))}"
                     + (" (t_q = tan(q/2))" if any(str(v).startswith("t_")
                                                  for v in a.variables) else ""))
    n = a.numbers
    lines.append("")
    lines.append("  ".join(f"{k} = {v}" for k, v in n.as_dict().items()))
    lines.append("")
    for s in sentences(a):
        lines.append(f"- {s}")
    object_rows = ["v_x", "v_y", "v_z", "w_x", "w_y", "w_z"]
    joint_rows = list(a.model.joint_names)
    for name, mat in a.blocks().items():
        lines.append("")
        labels = object_rows if name in ("C11", "C12") else joint_rows
        lines.append(f"{name} ({mat.rows} x {mat.cols})" + (": empty" if mat.cols == 0 else ""))
        if mat.cols:
            lines.extend(block_table(mat, labels))
    return "\n".join(lines)


def block_table(mat: sp.Matrix, labels: list[str]) -> list[str]:
    """A matrix as aligned text rows, each led by its label."""
    cells = [[sp.sstr(mat[i, j]) for j in range(mat.cols)] for i in range(mat.rows)]
    widths = [max(len(cells[i][j]) for i in range(mat.rows)) for j in range(mat.cols)]
    lw = max(len(x) for x in labels)
    return [f"  {labels[i]:>{lw}} | " + "  ".join(c.rjust(w) for c, w in zip(row, widths,
                                                                          strict=True))
            for i, row in enumerate(cells)]


def render_latex(a: Analysis) -> str:
    """The blocks and numbers as LaTeX."""
    out = [r"% " + a.model.name + " at " + (a.configuration.at_text() or "home")]
    out.append(", ".join(f"$N_{{{k[1:]}}} = {v}$" for k, v in a.numbers.as_dict().items()))
    for name, mat in a.blocks().items():
        body = sp.latex(mat) if mat.cols else r"\emptyset"
        out.append(rf"\[ C_{{{name[1:]}}} = {body} \]")
    return "\n".join(out)


def main() -> None:
    """Console-script entry point."""
    try:
        app()
    except KeyboardInterrupt:  # pragma: no cover
        typer.echo("coopkin: interrupted", err=True)
        sys.exit(130)
