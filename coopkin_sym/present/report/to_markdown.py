"""The Markdown renderer of a report (GitHub tables; pictures as links to PNG files).

Example
-------
>>> print(MarkdownRenderer().inline([("text", "a_b "), ("eq0", "t_q1")]))
a\\_b `t_q1 = 0`
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from coopkin_sym.present.report.blocks import (
    Bullets,
    Document,
    Figure,
    Heading,
    Paragraph,
    Span,
    Table,
    text_of,
)
from coopkin_sym.present.report.formulas import _one_line


def _md_escape(text: str) -> str:
    return re.sub(r"([\\`*_\[\]|<>])", r"\\\1", _one_line(text))


def _md_code(text: str) -> str:
    """A code span that no text can leave: its fence is longer than any run of
    backticks inside, and pipes are escaped for tables."""
    text = _one_line(text).replace("|", "\\|")
    longest = max((len(run) for run in re.findall(r"`+", text)), default=0)
    fence = "`" * (longest + 1)
    pad = " " if text.startswith("`") or text.endswith("`") or longest else ""
    return f"{fence}{pad}{text}{pad}{fence}"


_ALIGN = {"l": ":--", "c": ":-:", "r": "--:"}


class MarkdownRenderer:
    """Markdown: each block followed by a blank line.

    Example
    -------
    >>> MarkdownRenderer().heading(Heading(2, [("text", "Notes")]))
    ['## Notes', '']
    """

    name = "markdown"

    def inline(self, spans: Sequence[Span]) -> str:
        out = []
        for kind, value in spans:
            if kind == "text":
                out.append(_md_escape(value))
            elif kind == "strong":
                out.append(f"**{_md_escape(value)}**")
            elif kind == "nums":
                out.append(value)
            elif kind == "eq0":
                out.append(_md_code(f"{value} = 0"))
            else:
                out.append(_md_code(value))
        return "".join(out)

    def heading(self, block: Heading) -> list[str]:
        return ["#" * block.level + " " + _md_escape(text_of(block.spans)), ""]

    def paragraph(self, block: Paragraph) -> list[str]:
        return [self.inline(block.spans), ""]

    def bullets(self, block: Bullets) -> list[str]:
        return [f"- {self.inline(item)}" for item in block.items] + [""]

    def table(self, block: Table) -> list[str]:
        lines = ["| " + " | ".join(_md_escape(h) for h in block.header) + " |",
                 "|" + "|".join(_ALIGN[a] for a in block.align) + "|"]
        for row in block.rows:
            lines.append("| " + " | ".join(self.inline(c) for c in row) + " |")
        return lines + [""]

    def figure(self, block: Figure) -> list[str]:
        return [f"![{_md_escape(block.caption)}]({block.ref})", ""]

    def page(self, document: Document, body: list[str]) -> str:
        return "\n".join(body).rstrip() + "\n"
