"""Reading a file named from outside: a regular file only, within the size budget.

Every file the package reads on a user's word (a model file, a URDF file named by a
model, a report read back) goes through :func:`read_input_bytes`. Before anything is
read the path must name a regular file: a named pipe (FIFO) would block the reader
forever, a device such as ``/dev/zero`` or ``/dev/tty`` never ends or waits for a key,
and a directory or a socket holds no text. The file is opened without blocking, checked
again on the opened descriptor (so that a file swapped for a pipe between the check and
the open is still refused), and read up to :data:`~coopkin_sym.limits.MAX_FILE_BYTES`
bytes. Each refusal is one :class:`~coopkin_sym.errors.TreeError` saying what the path
is; the caller puts the file's name before it.

Example
-------
>>> read_input_bytes("/")
Traceback (most recent call last):
...
coopkin_sym.errors.TreeError: is a directory, not a file
>>> read_input_bytes("/dev/null")
Traceback (most recent call last):
...
coopkin_sym.errors.TreeError: is a character device, not a regular file
"""

from __future__ import annotations

import os
import stat

from coopkin_sym import limits
from coopkin_sym.errors import TreeError

__all__ = ["read_input_bytes", "read_input_text", "read_text_file", "size_text"]

_KINDS = ((stat.S_ISFIFO, "a named pipe (FIFO)"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


def size_text(n: int) -> str:
    """A size in bytes as shown in messages.

    Example
    -------
    >>> size_text(8 * 1024 * 1024), size_text(4096)
    ('8.0 MB', '4,096 bytes')
    """
    return f"{n / 1024 / 1024:.1f} MB" if n >= 1024 * 1024 else f"{n:,} bytes"


def _kind_problem(mode: int) -> str | None:
    """Why a file of this mode is not read, or ``None`` for a regular file."""
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "is a directory, not a file"
    for test, kind in _KINDS:
        if test(mode):
            return f"is {kind}, not a regular file"
    return "is not a regular file"


def _too_large() -> TreeError:
    return TreeError(f"the file is larger than {size_text(limits.MAX_FILE_BYTES)} (the "
                     f"limit for a model file, a URDF file or a report)")


def _os_problem(exc: OSError | ValueError) -> TreeError:
    if isinstance(exc, FileNotFoundError):
        return TreeError("no such file")
    if isinstance(exc, IsADirectoryError):
        return TreeError("is a directory, not a file")
    reason = getattr(exc, "strerror", None) or str(exc)
    return TreeError(f"cannot read the file: {reason}")


def read_input_bytes(path: str | os.PathLike[str]) -> bytes:
    """The bytes of a regular file of at most
    :data:`~coopkin_sym.limits.MAX_FILE_BYTES` bytes (see the module).

    Raises
    ------
    TreeError
        The path does not exist, is not a regular file (a directory, a named pipe, a
        device, a socket), cannot be opened, or holds more than the limit.

    Example
    -------
    >>> from coopkin_sym.model.examples import example_path
    >>> read_input_bytes(example_path("paper-case1-hard"))[:1]
    b'#'
    """
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError) as exc:   # ValueError: a NUL character in the name
        raise _os_problem(exc) from None
    problem = _kind_problem(mode)
    if problem is not None:
        raise TreeError(problem)
    flags = os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOCTTY", 0) \
        | getattr(os, "O_CLOEXEC", 0)
    try:
        descriptor = os.open(path, flags)
    except OSError as exc:
        raise _os_problem(exc) from None
    with open(descriptor, "rb", closefd=True) as handle:
        try:
            opened = os.fstat(descriptor)
        except OSError as exc:
            raise _os_problem(exc) from None
        problem = _kind_problem(opened.st_mode)
        if problem is not None:   # swapped for something else since the check
            raise TreeError(problem)
        if opened.st_size > limits.MAX_FILE_BYTES:
            raise _too_large()
        try:
            data = handle.read(limits.MAX_FILE_BYTES + 1)
        except OSError as exc:
            raise _os_problem(exc) from None
    if len(data) > limits.MAX_FILE_BYTES:   # grew since, or a size the system does not know
        raise _too_large()
    return data


def read_input_text(path: str | os.PathLike[str]) -> str:
    """:func:`read_input_bytes` decoded as UTF-8 text.

    Raises
    ------
    TreeError
        As :func:`read_input_bytes`, or the bytes are not UTF-8 text.

    Example
    -------
    >>> from coopkin_sym.model.examples import example_path
    >>> read_input_text(example_path("paper-case1-hard")).startswith("#")
    True
    """
    data = read_input_bytes(path)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise TreeError("not a text file (UTF-8 expected)") from None


def read_text_file(path: str | os.PathLike[str], error: type[Exception]) -> str:
    """:func:`read_input_text`, a problem raised as ``error("<path>: <problem>")``: how
    every reader of a file (URDF, MJCF, a report read back) names the file it refuses.

    Example
    -------
    >>> from coopkin_sym.errors import UrdfError
    >>> read_text_file("/no/such/file.urdf", UrdfError)
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.UrdfError: /no/such/file.urdf: no such file
    """
    try:
        return read_input_text(path)
    except TreeError as exc:
        raise error(f"{path}: {exc}") from None
