"""Checks on files the package writes (pictures, reports): before any work is done.

Example
-------
>>> check_output_path("report.txt", (".md", ".html"), ValueError, "report")
Traceback (most recent call last):
...
ValueError: report.txt: unknown report format '.txt' (expected .md, .html)
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path


def check_output_path(path: str | os.PathLike, formats: Iterable[str],
                      error: type[Exception], what: str) -> tuple[Path, str]:
    """The target and its lower-case suffix, or ``error`` naming the file when the
    suffix is not one of ``formats`` or its directory does not exist."""
    target = Path(path)
    suffix = target.suffix.lower()
    formats = list(formats)
    if suffix not in formats:
        raise error(f"{target}: unknown {what} format {suffix or '(no suffix)'!r} "
                    f"(expected {', '.join(formats)})")
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise error(f"{target}: no such directory {str(folder)!r}")
    return target, suffix
