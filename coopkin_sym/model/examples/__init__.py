"""The shipped model files: the paper's case studies and systems from the literature.

Bicchi, Melchiorri and Balluchi (ICRA 1992), section 4: case study 1 (two one-link
arms, four contact-model combinations) and case study 2 (two SCARA-type robots,
complete-constraint and hard-finger contacts). Each file's header comment cites the
section and the numbers the paper states. The ``dh-`` examples give their arms as
Denavit-Hartenberg tables: a three-finger hand and two PUMA 560 arms holding a box;
``panda-two-arm-box`` (two Franka Panda arms holding a box) and ``allegro-hand-sphere``
(an Allegro-like four-finger hand holding a sphere) are real robots at their
published sizes, also given by DH tables;
``urdf-two-fingers`` reads its arms from a URDF file shipped beside it;
``quadruped-standing`` is a four-legged vehicle seen as a hand grasping the ground;
``five-bar`` and ``underactuated-finger`` have passive joints (``actuated: false``);
``four-bar`` (folded, it bifurcates), ``shaky-pinned-bars`` (a first-order motion
and no finite one) and ``seven-r-loop`` (three branches crossing, with irrational
tangents) show finite mobility, and ``bennett-linkage``, ``bricard-linkage`` (loops
of four and six revolute joints in space) and ``parallel-cranks`` (three cranks
pinned to a coupler in the plane), overconstrained loops that move although the
Grübler-Kutzbach count says they cannot, finite motions that no expansion decides.

Example
-------
>>> list_examples()[8:10]
['paper-case1-complete-hard', 'paper-case1-hard']
>>> example_path("paper-case1-hard").name
'paper-case1-hard.yaml'
"""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path

from coopkin_sym.errors import ArgumentError

__all__ = ["describe_example", "example_path", "list_examples"]

_SUFFIX = ".yaml"


def list_examples() -> list[str]:
    """Names of the shipped examples, sorted, without extension.

    Example
    -------
    >>> "paper-case2-hard" in list_examples()
    True
    """
    return sorted(entry.name[: -len(_SUFFIX)] for entry in files(__name__).iterdir()
                  if entry.name.endswith(_SUFFIX))


def example_path(name: str) -> Path:
    """The file of the shipped example ``name``.

    Raises
    ------
    ValueError
        If there is no such example (the message lists the shipped ones).

    Example
    -------
    >>> example_path("paper-case2-complete").suffix
    '.yaml'
    """
    names = list_examples()
    if name not in names:
        raise ArgumentError(f"unknown example '{name}'; shipped examples: {', '.join(names)}")
    return Path(str(files(__name__) / f"{name}{_SUFFIX}"))


def describe_example(name: str) -> str:
    """One line about the example: the first sentence of its header comment (whole,
    however many comment lines it takes), or else its name.

    Raises
    ------
    ArgumentError
        If there is no such example (the message lists the shipped ones).

    Example
    -------
    >>> describe_example("paper-case1-soft")[:20]
    'Paper case study 1 ('
    >>> describe_example("four-bar")[-40:]
    'with pins (hard contacts) at their tips.'
    """
    header = []
    for line in example_path(name).read_text(encoding="utf-8").splitlines():
        text = line.strip()
        if not text.startswith("#"):
            break
        header.append(text.lstrip("#").strip())
    return first_sentence(" ".join(w for w in header if w)) or name


def first_sentence(text: str) -> str:
    """The first sentence of ``text``: up to the first full stop outside parentheses
    that ends the text or is followed by a space and a capital letter (``fig. 2``
    does not end a sentence).

    Example
    -------
    >>> first_sentence("Case 1 (fig. 2), two arms. At home q = 0.")
    'Case 1 (fig. 2), two arms.'
    """
    depth = 0
    for k, char in enumerate(text):
        depth += (char == "(") - (char == ")")
        if char != "." or depth > 0:
            continue
        rest = text[k + 1:]
        if not rest.strip() or (rest[:1] == " " and rest.lstrip()[:1].isupper()):
            return text[:k + 1]
    return text.strip()
