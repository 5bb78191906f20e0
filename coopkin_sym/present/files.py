"""Files the package writes (tables, reports, pictures, plots): checked before any work,
written whole or not at all.

* :func:`check_output_path` runs before the computation: a known suffix, an existing
  writable directory, a target that is not a directory. ``sweep -o nodir/x.csv``
  fails at once, not after the sweep.
* :func:`write_files` writes each file to a new temporary file in the target's
  directory, created exclusively (``O_EXCL``, a random name: no symlink planted at a
  predictable name can redirect the write), with the permissions of a plain file
  (``0o666`` less the umask), then renames them into place. On any error, and on
  Ctrl-C, the temporary files are removed: nothing partial is left. Renaming replaces
  a symlink at the target itself, never the file it points to.
* Two runs writing the same file never lose data silently: when the target changed
  after :func:`check_output_path` looked at it (another run wrote it meanwhile), the
  new data is kept under a free sibling name and the error says where.

Example
-------
>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> target, suffix = check_output_path(folder / "t.csv", (".csv",), ValueError, "table")
>>> [p.name for p in write_files({target: b"a,b\\n"}, ValueError)]
['t.csv']
>>> check_output_path("report.txt", (".md", ".html"), ValueError, "report")
Traceback (most recent call last):
...
ValueError: report.txt: unknown report format '.txt' (expected .md, .html)
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

__all__ = ["check_output_path", "plain_file_mode", "write_files"]

#: What a target looked like when it was checked (None: it did not exist).
_SEEN: dict[str, tuple[int, int, int] | None] = {}


def _signature(path: Path) -> tuple[int, int, int] | None:
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_ino, st.st_mtime_ns, st.st_size


def _shown(path: Path) -> str:
    text = str(path)
    return text if len(text) <= 200 else text[:120] + "..." + text[-40:]


def check_output_path(path: str | os.PathLike, formats: Iterable[str],
                      error: type[Exception], what: str, *,
                      note: bool = True) -> tuple[Path, str]:
    """The target and its lower-case suffix, or ``error`` naming the file when the
    suffix is not one of ``formats``, its directory does not exist or cannot be
    written, or the target is a directory. Call it before any work; with ``note`` it
    also notes the target's state, so that :func:`write_files` can tell when another
    run wrote it meanwhile.

    Example
    -------
    >>> import tempfile, pathlib
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> target, suffix = check_output_path(folder / "t.CSV", (".csv",), ValueError, "table")
    >>> target.name, suffix
    ('t.CSV', '.csv')
    """
    target = Path(path)
    suffix = target.suffix.lower()
    formats = list(formats)
    if suffix not in formats:
        raise error(f"{_shown(target)}: unknown {what} format {suffix or '(no suffix)'!r} "
                    f"(expected {', '.join(formats)})")
    check_writable(target, error)
    if note:
        _SEEN[str(target.absolute())] = _signature(target)
    return target, suffix


def check_writable(target: Path, error: type[Exception]) -> None:
    """``error`` when ``target`` cannot be written as a plain file: its directory is
    missing or not writable, or the target is a directory."""
    folder = target.parent if str(target.parent) else Path(".")
    try:
        if not folder.is_dir():
            raise error(f"{_shown(target)}: no such directory {_shown(folder)!r}")
        if target.is_dir():
            raise error(f"{_shown(target)}: is a directory")
    except OSError as exc:
        raise error(f"{_shown(target)}: {exc.strerror or exc}") from None
    if not os.access(folder, os.W_OK | os.X_OK):
        raise error(f"{_shown(target)}: the directory {_shown(folder)!r} is not writable")


def plain_file_mode() -> int:
    """``0o666`` less the process's umask: the mode ``open()`` would give a new file."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask


Writer = bytes | Callable[[str], None]


def write_files(files: Mapping[Path, Writer], error: type[Exception]) -> list[Path]:
    """Write every file whole, or none at all (see the module docstring).

    Parameters
    ----------
    files
        Target path -> its bytes, or a function writing the file at the temporary
        path it is given (a picture's ``savefig``).
    error
        The exception class raised, naming the file, on any problem.

    Returns
    -------
    list of Path
        The files written (the targets).

    Example
    -------
    >>> import tempfile, pathlib
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "t.csv"
    >>> [p.name for p in write_files({target: b"a,b\\n"}, ValueError)], target.read_text()
    (['t.csv'], 'a,b\\n')
    """
    targets = [Path(p) for p in files]
    for target in targets:
        check_writable(target, error)
    temps: dict[Path, str] = {}
    mode = plain_file_mode()
    current = targets[0] if targets else None
    try:
        for target, data in zip(targets, files.values(), strict=True):
            current = target
            handle, tmp = tempfile.mkstemp(prefix=f".{target.name[:80]}.",
                                           suffix=".partial", dir=target.parent or ".")
            temps[target] = tmp
            if isinstance(data, bytes | bytearray):
                with os.fdopen(handle, "wb") as fh:
                    fh.write(data)
            else:
                os.close(handle)
                data(tmp)
            os.chmod(tmp, mode)
        moved_aside = []
        for target in targets:
            current = target
            seen = _SEEN.pop(str(target.absolute()), "unknown")
            if seen != "unknown" and _signature(target) != seen:
                moved_aside.append((target, _keep_aside(temps.pop(target), target)))
                continue
            os.replace(temps.pop(target), target)
        if moved_aside:
            where = "; ".join(f"{_shown(t)} -> {_shown(k)}" for t, k in moved_aside)
            raise error(f"{_shown(moved_aside[0][0])}: another run wrote this file while "
                        f"this one was computing; this run's result was kept under a new "
                        f"name instead ({where})")
    except OSError as exc:
        raise error(f"{_shown(current)}: cannot write: {exc.strerror or exc}") from None
    finally:
        for tmp in temps.values():
            try:
                os.unlink(tmp)
            except OSError:
                pass                 # a read-only or vanished directory: nothing to add
    return targets


def _keep_aside(tmp: str, target: Path) -> Path:
    """Give the finished temporary file a free visible name next to ``target``."""
    for k in range(1, 1000):
        candidate = target.with_name(f"{target.stem}.{k}{target.suffix}")
        try:
            os.link(tmp, candidate)          # fails if the name exists: no overwrite
        except FileExistsError:
            continue
        os.unlink(tmp)
        return candidate
    raise OSError(f"no free name next to {target}")
