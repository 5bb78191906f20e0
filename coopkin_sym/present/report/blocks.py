"""The format-neutral document of a report, and the protocol its renderers implement.

A report is built once (:mod:`coopkin_sym.present.report.document`) as a
:class:`Document`: a list of blocks (:class:`Heading`, :class:`Paragraph`,
:class:`Bullets`, :class:`Table`, :class:`Figure`) whose text is a list of inline spans
``(kind, value)`` (see :data:`SPAN_KINDS`). One renderer per format (Markdown, HTML,
LaTeX) implements :class:`Renderer`; :func:`render` walks the blocks once for all of
them, so that the structure exists once and each format's inline formatting once.

Example
-------
>>> from coopkin_sym.present.report.to_markdown import MarkdownRenderer
>>> doc = Document("Demo", "demo", [Heading(1, [("text", "Demo")]),
...                                 Paragraph([("text", "Nm is "), ("strong", "2")])])
>>> print(render(doc, MarkdownRenderer()), end="")
# Demo
<BLANKLINE>
Nm is **2**
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, ClassVar, Protocol, runtime_checkable

from coopkin_sym.present.formula import Formula as Formula

#: An inline span: ``(kind, value)``, the kind one of :data:`SPAN_KINDS`.
Span = tuple[str, str]



#: The kinds of inline spans, with what their value is.
SPAN_KINDS: dict[str, str] = {
    "text": "plain words",
    "strong": "words in bold",
    "code": "text shown as typed (names, commands)",
    "nums": "a tuple of numbers, kept on one line",
    "eq": "a polynomial (mathematics in LaTeX; a Formula's tex is its LaTeX)",
    "eq0": "a polynomial equated to zero (mathematics in LaTeX; a Formula's tex is the "
           "polynomial's LaTeX)",
    "at": "a point in --at syntax (mathematics in LaTeX)",
    "cond": "a condition in angles (mathematics in LaTeX; a Formula's tex is all of it)",
}


def text_of(spans: Sequence[Span]) -> str:
    """The spans' values run together: their text without formatting.

    Example
    -------
    >>> text_of([("text", "Component #1: "), ("cond", "q1 = 0")])
    'Component #1: q1 = 0'
    """
    return "".join(value for _, value in spans)


@dataclass
class Heading:
    """A heading of ``level`` 1 (the title) to 3, with an ``anchor`` for links.

    Example
    -------
    >>> Heading(2, [("text", "Components")], "components").kind
    'heading'
    """

    level: int
    spans: list[Span]
    anchor: str = ""
    only: tuple[str, ...] = ()          # formats that show it (all when empty)
    kind: ClassVar[str] = "heading"


@dataclass
class Paragraph:
    """A paragraph; ``css`` a style class for the formats that have them.

    Example
    -------
    >>> Paragraph([("text", "None.")]).kind
    'paragraph'
    """

    spans: list[Span]
    css: str = ""
    only: tuple[str, ...] = ()
    kind: ClassVar[str] = "paragraph"


@dataclass
class Bullets:
    """A bulleted list, one list of spans per item.

    Example
    -------
    >>> len(Bullets([[("text", "one")], [("text", "two")]]).items)
    2
    """

    items: list[list[Span]]
    only: tuple[str, ...] = ()
    kind: ClassVar[str] = "bullets"


@dataclass
class Table:
    """A table: a header of plain texts, rows of cells (each a list of spans).

    ``align`` has one letter per column (``l``, ``c``, ``r``); ``latex_widths`` gives
    paragraph columns their width in LaTeX, and ``latex_skip`` the columns LaTeX leaves
    out (a page is narrow); ``css`` is a style class, and ``details`` (HTML) the
    summary of a collapsed table.

    Example
    -------
    >>> Table(["#", "where"], [[[("text", "#1")], [("cond", "q1 = 0")]]], "ll").kind
    'table'
    """

    header: list[str]
    rows: list[list[list[Span]]]
    align: str = ""
    latex_widths: dict[int, str] | None = None
    css: str = ""
    latex_skip: tuple[int, ...] = ()
    only: tuple[str, ...] = ()
    details: str = ""
    kind: ClassVar[str] = "table"


@dataclass
class Figure:
    """A picture with its caption; ``ref`` is what the format needs of it (a file name,
    or the PNG bytes of a self-contained page).

    Example
    -------
    >>> Figure("Components in the (q1, q2) plane", "r_q1_q2.png").kind
    'figure'
    """

    caption: str
    ref: Any
    only: tuple[str, ...] = ()
    kind: ClassVar[str] = "figure"


#: Every kind of block, by the name of the renderer method that writes it.
BLOCKS: dict[str, type] = {b.kind: b for b in (Heading, Paragraph, Bullets, Table, Figure)}

Block = Heading | Paragraph | Bullets | Table | Figure


@dataclass
class Document:
    """A report: its ``title``, the ``subject`` it is about (the system's name), its
    ``blocks``, and ``files``: pictures written next to the report that the format
    does not place in its text (LaTeX lists them at the end).

    Example
    -------
    >>> Document("Singularity locus of demo", "demo", []).blocks
    []
    """

    title: str
    subject: str
    blocks: list[Block]
    files: list[Figure] = field(default_factory=list)


@runtime_checkable
class Renderer(Protocol):
    """One output format: a method per block kind (see :data:`BLOCKS`), each giving
    the block's lines; ``inline`` formats spans (the one place that does, per format);
    ``page`` puts the lines of the blocks into the page skeleton.

    Example
    -------
    >>> from coopkin_sym.present.report.to_html import HtmlRenderer
    >>> isinstance(HtmlRenderer(), Renderer)
    True
    """

    #: The format's name, as blocks' ``only`` name it.
    name: str

    def inline(self, spans: Sequence[Span]) -> str: ...

    def heading(self, block: Heading) -> list[str]: ...

    def paragraph(self, block: Paragraph) -> list[str]: ...

    def bullets(self, block: Bullets) -> list[str]: ...

    def table(self, block: Table) -> list[str]: ...

    def figure(self, block: Figure) -> list[str]: ...

    def page(self, document: Document, body: list[str]) -> str: ...


def shown_in(block: Block, fmt: str) -> bool:
    """Whether the format ``fmt`` shows ``block`` (every format, unless its ``only``
    names some).

    Example
    -------
    >>> shown_in(Paragraph([], only=("latex",)), "html")
    False
    """
    return not block.only or fmt in block.only


def render(document: Document, renderer: Renderer) -> str:
    """The document in the renderer's format: each block it shows by the renderer's
    method for its kind, then the page around them.

    Example
    -------
    >>> from coopkin_sym.present.report.to_latex import LatexRenderer
    >>> doc = Document("Demo", "demo", [Paragraph([("eq0", "t_q1")])])
    >>> render(doc, LatexRenderer()).splitlines()[1]
    '$t_{q1} = 0$'
    """
    body: list[str] = []
    for block in document.blocks:
        if shown_in(block, renderer.name):
            body.extend(getattr(renderer, block.kind)(block))
    return renderer.page(document, body)


def _t(text: str) -> Span:
    return ("text", text)


def _h(level: int, text: str, anchor: str = "") -> Heading:
    return Heading(level, [_t(text)], anchor)
