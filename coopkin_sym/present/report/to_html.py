"""The HTML renderer of a report: one self-contained page (pictures embedded as data
URIs), its skeleton a :class:`string.Template`.

Example
-------
>>> HtmlRenderer().inline([("text", "a < b "), ("strong", "3")])
'a &lt; b <strong>3</strong>'
"""

from __future__ import annotations

import base64
import html
from collections.abc import Sequence
from string import Template

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

_CSS = """
body { font-family: -apple-system, "Segoe UI", Helvetica, Arial, sans-serif;
  color: #1f2328; max-width: 1100px; margin: 2em auto; padding: 0 1.5em;
  line-height: 1.5; font-size: 15px; }
h1 { font-size: 1.7em; border-bottom: 2px solid #d0d7de; padding-bottom: .3em; }
h2 { font-size: 1.3em; margin-top: 1.8em; border-bottom: 1px solid #d8dee4;
  padding-bottom: .2em; }
h3 { font-size: 1.05em; margin-top: 1.5em; }
code { font-family: ui-monospace, Menlo, Consolas, monospace; font-size: .9em;
  background: #f3f4f6; padding: .1em .3em; border-radius: 4px; }
table { border-collapse: collapse; margin: .6em 0 1em; font-size: .92em; }
th, td { border: 1px solid #d0d7de; padding: .3em .6em; text-align: left;
  vertical-align: top; }
th { background: #f0f3f6; font-weight: 600; }
tr:nth-child(even) td { background: #fafbfc; }
td.c, th.c { text-align: center; }
table.components td strong, table.checks td strong, table.floatsum td strong {
  color: #b42318; }
table.components td.c strong { display: inline-block; min-width: 1.2em;
  background: #fde8e7; border-radius: 3px; }
p.summary { background: #f6f8fa; border-left: 4px solid #0969da; padding: .5em .9em; }
ul { padding-left: 1.4em; }
li { margin: .15em 0; }
figure { margin: 1em 0; }
figure img { max-width: 100%; border: 1px solid #d8dee4; border-radius: 4px; }
figcaption { color: #57606a; font-size: .9em; }
details { margin: .3em 0 1em; }
details summary { cursor: pointer; color: #0969da; }
table.checks code { word-break: break-all; font-size: .85em; }
table.components code, li code { overflow-wrap: anywhere; }
table.components td code { word-break: break-all; }
div.table { overflow-x: auto; max-width: 100%; }
.nums { white-space: nowrap; }
"""

_PAGE = Template("""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>$title</title>
<style>$css</style>
</head>
<body>
$body
</body>
</html>
""")


def _css(css: str) -> str:
    return f' class="{css}"' if css else ""


class HtmlRenderer:
    """HTML: one element per block.

    Example
    -------
    >>> HtmlRenderer().heading(Heading(2, [("text", "Notes")], "notes"))
    ['<h2 id="notes">Notes</h2>']
    """

    name = "html"

    def inline(self, spans: Sequence[Span]) -> str:
        out = []
        for kind, value in spans:
            if kind == "text":
                out.append(html.escape(value))
            elif kind == "nums":
                out.append(f'<span class="nums">{html.escape(value)}</span>')
            elif kind == "strong":
                out.append(f"<strong>{html.escape(value)}</strong>")
            elif kind == "eq0":
                out.append(f"<code>{html.escape(value)} = 0</code>")
            else:
                out.append(f"<code>{html.escape(value)}</code>")
        return "".join(out)

    def heading(self, block: Heading) -> list[str]:
        anchor = f' id="{block.anchor}"' if block.anchor else ""
        text = html.escape(text_of(block.spans))
        return [f"<h{block.level}{anchor}>{text}</h{block.level}>"]

    def paragraph(self, block: Paragraph) -> list[str]:
        return [f"<p{_css(block.css)}>{self.inline(block.spans)}</p>"]

    def bullets(self, block: Bullets) -> list[str]:
        return ["<ul>" + "".join(f"<li>{self.inline(i)}</li>" for i in block.items)
                + "</ul>"]

    def table(self, block: Table) -> list[str]:
        cls = [' class="c"' if a == "c" else "" for a in block.align]
        head = "".join(f"<th{c}>{html.escape(h)}</th>"
                       for h, c in zip(block.header, cls, strict=True))
        rows = "".join("<tr>" + "".join(f"<td{c}>{self.inline(cell)}</td>"
                                        for cell, c in zip(row, cls, strict=True))
                       + "</tr>" for row in block.rows)
        # in a box that scrolls sideways: a wide table is never cut off
        table = (f'<div class="table"><table{_css(block.css)}><thead><tr>{head}</tr>'
                 f"</thead><tbody>{rows}</tbody></table></div>")
        if block.details:
            table = (f"<details><summary>{html.escape(block.details)}</summary>{table}"
                     f"</details>")
        return [table]

    def figure(self, block: Figure) -> list[str]:
        """PNG bytes embedded as a data URI (the page stays self-contained), or a
        file name linked."""
        if isinstance(block.ref, bytes):
            src = "data:image/png;base64," + base64.b64encode(block.ref).decode("ascii")
        else:
            src = html.escape(str(block.ref))
        caption = html.escape(block.caption)
        return [f'<figure><img alt="{caption}" src="{src}">'
                f"<figcaption>{caption}</figcaption></figure>"]

    def page(self, document: Document, body: list[str]) -> str:
        return _PAGE.substitute(title=html.escape(document.title), css=_CSS,
                                body="\n".join(body))
