"""The pieces of the HTML views of results: escaped text, tables, lists, the numbers.

Every view of :mod:`coopkin_sym.present.display` (and of the modules it registers)
is built from these, so that they look alike in a notebook.

Example
-------
>>> table(["a", "b"], [["1", "<b>2</b>"]])
'<table><thead><tr><th style="text-align:left">a</th><th style="text-align:left">b</th>\
</tr></thead><tbody><tr><td style="text-align:left">1</td><td style="text-align:left">\
<b>2</b></td></tr></tbody></table>'
"""

from __future__ import annotations

import html
from collections.abc import Mapping, Sequence

from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers
from coopkin_sym.present.report import NUMBER_WORDS

__all__ = ["bullet_list", "div", "escape", "numbers_rows", "numbers_table", "table"]

_CELL = ' style="text-align:left"'
_CENTER = ' style="text-align:center"'


def escape(text: object) -> str:
    """``text`` escaped for HTML.

    Example
    -------
    >>> escape("a < b & c")
    'a &lt; b &amp; c'
    """
    return html.escape(str(text))


def table(header: Sequence[str], rows: Sequence[Sequence[str]],
          centered: Sequence[int] = ()) -> str:
    """An HTML table; the header is text, the cells are HTML already (escaped by the
    caller); the columns in ``centered`` are centered."""
    def cell(tag: str, k: int, body: str) -> str:
        return f"<{tag}{_CENTER if k in centered else _CELL}>{body}</{tag}>"
    head = "".join(cell("th", k, escape(h)) for k, h in enumerate(header))
    body = "".join("<tr>" + "".join(cell("td", k, c) for k, c in enumerate(row)) + "</tr>"
                   for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def numbers_rows(numbers: Numbers | Mapping[str, int]) -> list[list[str]]:
    """One row ``[name, value, meaning]`` per number (``?`` for one not given)."""
    get = numbers.get if isinstance(numbers, Mapping) else numbers.as_dict().get
    return [[escape(k), escape(get(k, "?")), escape(NUMBER_WORDS[k])]
            for k in NUMBER_NAMES]


def numbers_table(numbers: Numbers | Mapping[str, int]) -> str:
    """The seven numbers with their meanings, as an HTML table.

    Example
    -------
    >>> '<td style="text-align:center">4</td>' in numbers_table(Numbers(2, 2, 1, 0, 1, 4, 0))
    True
    """
    return table(["number", "value", "meaning"], numbers_rows(numbers), centered=(1,))


def numbers_strip(numbers: Numbers | Mapping[str, int]) -> str:
    """The seven numbers as one compact HTML table (names above values), each name
    carrying its meaning as a tooltip.

    Example
    -------
    >>> strip = numbers_strip(Numbers(2, 2, 1, 0, 1, 4, 0))
    >>> 'title="connectivity: independent motions of the object">Nc</th>' in strip
    True
    """
    get = numbers.get if isinstance(numbers, Mapping) else numbers.as_dict().get
    head = "".join(f'<th{_CENTER} title="{escape(NUMBER_WORDS[k])}">{escape(k)}</th>'
                   for k in NUMBER_NAMES)
    values = "".join(f"<td{_CENTER}>{escape(get(k, '?'))}</td>" for k in NUMBER_NAMES)
    return f"<table><thead><tr>{head}</tr></thead><tbody><tr>{values}</tr></tbody></table>"


def div(parts: Sequence[str]) -> str:
    """The parts (HTML; empty ones left out) in the ``coopkin`` block of a view."""
    return '<div class="coopkin">' + "\n".join(p for p in parts if p) + "</div>"


def bullet_list(items: Sequence[str]) -> str:
    """The items (text) as an HTML list; nothing when there are none.

    Example
    -------
    >>> bullet_list(["a < b"]), bullet_list([])
    ('<ul><li>a &lt; b</li></ul>', '')
    """
    return "<ul>" + "".join(f"<li>{escape(s)}</li>" for s in items) + "</ul>" if items else ""
