"""The name labels of a picture: which are drawn (``labels=True``, ``"short"`` or
``False``), how long names are shortened, and where each label goes so that labels do
not cover one another.

* ``True`` (the default): joint and contact names; a joint name longer than
  :data:`NAME_CHARACTERS` loses the start it shares with every joint of its arm (the
  arm is the label's colour: ``left_hand_index_finger_mcp`` is ``…mcp``), a name
  still too long is shortened in its middle (its start and its end stay); joints at
  one point share one label (a long list of them as ``first … last (n)``);
* ``"short"``: each joint by its number in its arm (``1``, ``2, 3``; the arm is the
  label's colour), contacts by their names shortened;
* ``False``: no name labels (the title, the legend and the rates of a motion stay).

Labels are then moved apart in the picture's plane (:func:`spread_labels`).

Example
-------
>>> shorten("left_index_finger_proximal_joint")
'left_ind…al_joint'
>>> arm_prefix(["left_hand_index_finger_mcp", "left_hand_index_finger_pip"])
'left_hand_index_finger_'
>>> joint_label(["p1_1", "p1_2"], [1, 2], True), joint_label(["p1_1", "p1_2"], [1, 2], "short")
('p1_1, p1_2', '1, 2')
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from coopkin_sym.errors import DrawError

__all__ = ["LABEL_STYLES", "NAME_CHARACTERS", "arm_prefix", "check_labels", "contact_label",
           "joint_label", "label_boxes", "name_labels", "shorten", "spread_labels"]

#: What ``labels=`` takes.
LABEL_STYLES = (True, False, "short")

#: The longest name a label shows whole.
NAME_CHARACTERS = 17

#: The longest list of joints at one point a label shows whole (characters).
_LIST_CHARACTERS = 28

# where a label may go beside its point, in points (right, up): first where it was
# drawn (joints below right, contacts above right), then the next free place
_FIRST = {"joint": (7, -12), "contact": (7, 8)}
_PLACES = ((7, -12), (7, 8), (-7, 8), (-7, -12), (7, 22), (7, -26), (-7, 22), (-7, -26),
           (7, 36), (7, -40))


def check_labels(labels: Any) -> bool | str:
    """``labels`` when it is one of :data:`LABEL_STYLES`, else a
    :class:`~coopkin_sym.errors.DrawError`.

    Example
    -------
    >>> check_labels("short")
    'short'
    >>> check_labels("long")
    Traceback (most recent call last):
    ...
    coopkin_sym.errors.DrawError: labels: True, False or 'short' (not 'long')
    """
    if not any(labels is style or (isinstance(labels, str) and labels == style)
               for style in LABEL_STYLES):
        raise DrawError(f"labels: True, False or 'short' (not {labels!r})")
    return labels


def shorten(name: str, limit: int = NAME_CHARACTERS) -> str:
    """``name``, at most ``limit`` characters: its start and its end around ``…``.

    Example
    -------
    >>> shorten("c1"), shorten("abcdefghijklmnopqrstuvwxyz", 10)
    ('c1', 'abcd…vwxyz')
    """
    if len(name) <= limit:
        return name
    head = (limit - 1) // 2
    return name[:head] + "…" + name[len(name) - (limit - 1 - head):]


def arm_prefix(names: Sequence[str]) -> str:
    """The start every name of an arm's joints shares, up to a separator (``_``,
    ``-``, ``.``, ``/``, ``:``); empty for fewer than two joints.

    Example
    -------
    >>> arm_prefix(["p1_1", "p1_2"]), arm_prefix(["q1"]), arm_prefix(["ab1", "ab2"])
    ('p1_', '', '')
    """
    if len(names) < 2:
        return ""
    common = os.path.commonprefix(list(names))
    cut = max(common.rfind(sep) for sep in "_-./:")
    return common[:cut + 1] if cut >= 0 else ""


def _joint_word(name: str, prefix: str) -> str:
    if len(name) > NAME_CHARACTERS and prefix and len(name) > len(prefix):
        name = "…" + name[len(prefix):]
    return shorten(name)


def joint_label(names: Sequence[str], numbers: Sequence[int], style: bool | str,
                prefix: str = "") -> str:
    """The label of the joints at one point: ``names`` (or, ``"short"``, their
    ``numbers`` in their arm), a long name without the ``prefix`` of its arm
    (:func:`arm_prefix`), shortened.

    Example
    -------
    >>> joint_label([f"j{k}" for k in range(1, 12)], range(1, 12), True)
    'j1 … j11 (11)'
    >>> joint_label(["left_hand_index_finger_mcp"], [1], True, "left_hand_index_finger_")
    '…mcp'
    """
    words = ([str(k) for k in numbers] if style == "short"
             else [_joint_word(n, prefix) for n in names])
    text = ", ".join(words)
    if len(text) > _LIST_CHARACTERS and len(words) > 2:
        text = f"{words[0]} … {words[-1]} ({len(words)})"
    return text


def contact_label(name: str, style: bool | str) -> str:
    """The label of a contact: its name, shortened (more with ``"short"``).

    Example
    -------
    >>> contact_label("left_fingertip_contact", "short")
    'lef…act'
    """
    return shorten(name, 7 if style == "short" else NAME_CHARACTERS)


def name_labels(ax: Any) -> list[Any]:
    """The name labels drawn in ``ax`` (texts whose gid starts ``label:``)."""
    return [t for t in ax.texts if (t.get_gid() or "").startswith("label:")]


@contextmanager
def _projected(ax: Any) -> Iterator[Callable[[Any], Any]]:
    """``box(text)``: where a label of the 3D axes is drawn (its window extent), in
    the final layout (a 3D text alone measures its unprojected position)."""
    from mpl_toolkits.mplot3d import proj3d

    fig = ax.figure
    fig.draw_without_rendering()       # the final layout: the axes where they will be
    renderer = fig.canvas.get_renderer()
    projection = ax.get_proj()

    def box(text: Any) -> Any:
        x, y = text._x, text._y
        px, py, _ = proj3d.proj_transform(x, y, text._z, projection)
        text.set_position((px, py))
        try:
            return text.get_window_extent(renderer)
        finally:
            text.set_position((x, y))
    yield box


def label_boxes(ax: Any) -> list[Any]:
    """The window extents of the name labels of a 3D picture, as drawn.

    Example
    -------
    >>> from coopkin_sym import load
    >>> boxes = label_boxes(load("paper-case1-hard").draw().axes[0])
    >>> len(boxes), any(a.overlaps(b) for a in boxes for b in boxes if a is not b)
    (4, False)
    """
    with _projected(ax) as box:
        return [box(t) for t in name_labels(ax)]


def spread_labels(ax: Any) -> int:
    """Move the name labels of a 3D picture (texts whose gid starts ``label:``) so that
    none covers another in the picture's plane, each beside its point at the first of
    a few places that is free (else where it was drawn first); the number not at
    their first place (none on a figure whose canvas cannot measure text). Drawing
    does it (``labels=True`` or ``"short"``); doing it again changes nothing.

    Example
    -------
    >>> from coopkin_sym import load
    >>> fig = load("five-bar").draw()
    >>> spread_labels(fig.axes[0])       # two joint labels met: one moved
    1
    """
    from matplotlib.transforms import offset_copy

    fig = ax.figure
    if not hasattr(fig.canvas, "get_renderer"):   # a figure that cannot measure text
        return 0
    taken: list[Any] = []
    moved = 0
    with _projected(ax) as box:
        for text in name_labels(ax):
            start = _FIRST.get(text.get_gid().split(":")[1], _PLACES[0])
            places = [start, *(p for p in _PLACES if p != start)]
            for k, (right, up) in enumerate(places):
                text.set_transform(offset_copy(ax.transData, fig=fig, x=right, y=up,
                                               units="points"))
                text.set_horizontalalignment("left" if right > 0 else "right")
                extent = box(text)
                if not any(extent.expanded(1.1, 1.15).overlaps(o) for o in taken):
                    moved += k > 0
                    break
            else:                           # nowhere free: where it was drawn
                text.set_transform(offset_copy(ax.transData, fig=fig, x=start[0],
                                               y=start[1], units="points"))
                text.set_horizontalalignment("left")
                extent = box(text)
            taken.append(extent)
    return moved
