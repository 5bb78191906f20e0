"""The renderers of a report against one contract: one document holding every block kind
and every kind of inline span goes through each renderer (Markdown, HTML, LaTeX), and
each block comes out exactly as its format writes it. A renderer that lacks a block
kind, or a block kind no renderer writes, fails here."""

from __future__ import annotations

import pytest

from coopkin_sym.analysis.locus.conditions import Condition, Related
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.present.conditions import short_condition
from coopkin_sym.present.report import RENDERERS, render_html, render_latex, render_markdown
from coopkin_sym.present.report.blocks import (
    BLOCKS,
    SPAN_KINDS,
    Bullets,
    Document,
    Figure,
    Heading,
    Paragraph,
    Renderer,
    Table,
    render,
)
from coopkin_sym.present.report.document import build_document

# a condition span is written from the component's exact condition
CONDITION = short_condition(Component(["t_q1 - t_q2"], {}, None, True,
                                      condition=Condition.of(Related("q1", "q2", 1))))
SPANS = [("text", "a_b <c>"), ("strong", "bold"), ("code", "x|y"), ("nums", "(1, 2)"),
         ("eq", "t_q1 + 1"), ("eq0", "t_q2"), ("at", "q1=pi/2"), ("cond", CONDITION)]

BLOCK = {
    "heading": Heading(2, [("text", "Parts & <pieces>")], "parts"),
    "paragraph": Paragraph([x for span in SPANS for x in (span, ("text", " "))][:-1],
                           css="summary"),
    "bullets": Bullets([[("text", "one")], [("strong", "two")]]),
    "table": Table(["#", "value"], [[[("text", "#1")], [("strong", "3")]]], "lc",
                   {0: "1cm"}, css="numbers", details="the table"),
    "figure": Figure("Components in the (q1, q2) plane", "r_q1_q2.png"),
}

#: Every block in every format, exactly.
EXPECTED = {
    "markdown": {
        "heading": ["## Parts & \\<pieces\\>", ""],
        "paragraph": ["a\\_b \\<c\\> **bold** `x\\|y` (1, 2) `t_q1 + 1` `t_q2 = 0` "
                      "`q1=pi/2` `q1 = q2`", ""],
        "bullets": ["- one", "- **two**", ""],
        "table": ["| # | value |", "|:--|:-:|", "| #1 | **3** |", ""],
        "figure": ["![Components in the (q1, q2) plane](r_q1_q2.png)", ""],
    },
    "html": {
        "heading": ['<h2 id="parts">Parts &amp; &lt;pieces&gt;</h2>'],
        "paragraph": ['<p class="summary">a_b &lt;c&gt; <strong>bold</strong> '
                      '<code>x|y</code> <span class="nums">(1, 2)</span> '
                      "<code>t_q1 + 1</code> <code>t_q2 = 0</code> <code>q1=pi/2</code> "
                      "<code>q1 = q2</code></p>"],
        "bullets": ["<ul><li>one</li><li><strong>two</strong></li></ul>"],
        "table": ['<details><summary>the table</summary><div class="table"><table '
                  'class="numbers"><thead><tr><th>#</th><th class="c">value</th></tr>'
                  '</thead><tbody><tr><td>#1</td><td class="c"><strong>3</strong></td>'
                  '</tr></tbody></table></div></details>'],
        "figure": ['<figure><img alt="Components in the (q1, q2) plane" src="r_q1_q2.png">'
                   "<figcaption>Components in the (q1, q2) plane</figcaption></figure>"],
    },
    "latex": {
        "heading": [r"\subsection*{Parts \& $<$pieces$>$}"],
        "paragraph": [r"a\_b $<$c$>$ \textbf{bold} \texttt{x$|$y} (1,2) $t_{q1} + 1$ "
                      r"$t_{q2} = 0$ $q_{1} = \frac{\pi}{2}$ $q_{1} = q_{2}$", ""],
        "bullets": [r"\begin{itemize}", r"\item one", r"\item \textbf{two}",
                    r"\end{itemize}"],
        # one tabular per row (a page breaks between rows), columns of fixed widths
        "table": [r"\begin{center}\footnotesize\setlength{\tabcolsep}{2pt}"
                  r"\setlength{\parskip}{0pt}",
                  r"\begin{tabular}{|p{1cm}|p{3.7em}|}", r"\hline",
                  r"\textbf{\#} & \textbf{value} \tabularnewline \hline",
                  r"\end{tabular}\par\nointerlineskip\nobreak",
                  r"\begin{tabular}{|p{1cm}|p{3.7em}|}",
                  r"\raggedright \#1 & \textbf{3} \tabularnewline \hline",
                  r"\end{tabular}\par\nointerlineskip\penalty0", r"\end{center}"],
        "figure": [r"% \includegraphics[width=0.8\textwidth]{r_q1_q2.png}  "
                   r"% Components in the (q1, q2) plane"],
    },
}


def test_the_contract_covers_every_block_and_span_kind():
    assert sorted(BLOCK) == sorted(BLOCKS)
    assert all(isinstance(BLOCK[k], BLOCKS[k]) for k in BLOCKS)
    assert sorted(k for k, _ in SPANS) == sorted(SPAN_KINDS)
    assert sorted(EXPECTED) == sorted(RENDERERS)
    assert all(sorted(e) == sorted(BLOCKS) for e in EXPECTED.values())


@pytest.mark.parametrize("fmt", sorted(RENDERERS))
def test_every_renderer_writes_every_block_kind(fmt):
    renderer = RENDERERS[fmt]()
    assert renderer.name == fmt
    assert isinstance(renderer, Renderer)
    for kind in BLOCKS:
        assert getattr(renderer, kind)(BLOCK[kind]) == EXPECTED[fmt][kind], kind


@pytest.mark.parametrize("fmt", sorted(RENDERERS))
def test_one_document_through_each_renderer(fmt):
    """The blocks in order, each as its method writes it, inside the page skeleton;
    a block for other formats only is left out."""
    blocks = [BLOCK[k] for k in BLOCKS]
    others = Paragraph([("text", "for the others")], only=("nowhere",))
    doc = Document("Demo & co", "demo\nsystem", [*blocks, others])
    text = render(doc, RENDERERS[fmt]())
    body = [line for k in BLOCKS for line in EXPECTED[fmt][k]]
    if fmt == "markdown":
        assert text == "\n".join(body).rstrip() + "\n"
    elif fmt == "html":
        assert text.startswith("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta "
                               "charset=\"utf-8\">\n<title>Demo &amp; co</title>\n<style>")
        assert text.endswith("</style>\n</head>\n<body>\n" + "\n".join(body)
                             + "\n</body>\n</html>\n")
    else:
        top = "% Singularity-locus report of demo system (coopkin locus); \\input this " \
              "file in a document."
        assert text == "\n".join([top, *body]).rstrip() + "\n"
    assert "for the others" not in text


def test_latex_lists_the_pictures_next_to_it_in_comments():
    doc = Document("Demo", "demo", [], [BLOCK["figure"]])
    assert render(doc, RENDERERS["latex"]()).splitlines()[1:] == [
        "% Plots of the components (need \\usepackage{graphicx}):",
        *EXPECTED["latex"]["figure"]]


def test_html_embeds_png_bytes():
    line, = RENDERERS["html"]().figure(Figure("P", b"\x89PNG"))
    assert line == ('<figure><img alt="P" src="data:image/png;base64,iVBORw=="><figcaption>'
                    "P</figcaption></figure>")


def test_a_renderer_without_a_block_kind_breaks_the_contract():
    """The check can fail: a renderer lacking ``table`` is no :class:`Renderer`, and
    a document with a table cannot go through it."""

    class NoTables:
        name = "none"

        def inline(self, spans):
            return ""

        def heading(self, block):
            return []

        paragraph = bullets = figure = heading

        def page(self, document, body):
            return ""

    assert not isinstance(NoTables(), Renderer)
    with pytest.raises(AttributeError):
        render(Document("x", "x", [BLOCK["table"]]), NoTables())


def test_the_public_functions_render_one_built_document():
    locus = Locus("demo", ["t_q1"], "", {"Nm": 1})
    plots = {("q1", "q2"): "r_q1_q2.png"}
    assert render_markdown(locus, plots) == render(build_document(locus, plots),
                                                   RENDERERS["markdown"]())
    assert render_latex(locus, plots) == render(build_document(locus, plots, in_text=False),
                                                RENDERERS["latex"]())
    assert render_html(locus) == render(build_document(locus), RENDERERS["html"]())
    assert "![Components in the (q1, q2) plane](r_q1_q2.png)" in render_markdown(locus, plots)
