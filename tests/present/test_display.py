"""How results show in IPython and Jupyter (:mod:`coopkin_sym.present.display`).

Every result has a short ``repr`` (under 300 characters, with its numbers), IPython's
text (``_repr_pretty_``) starts with it, ``_repr_latex_`` is display math that parses
(balanced braces and environments; every cell rendered by matplotlib's mathtext) and
``_repr_html_`` is balanced HTML that states the exact numbers. No display starts a
long computation or lets :class:`~coopkin_sym.errors.BlockTooLarge` out.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser

import pytest
import sympy as sp

import coopkin_sym
from coopkin_sym.analysis import renderers
from coopkin_sym.analysis.locus.certify import Certificate
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.analysis.numbers import NUMBER_NAMES, Numbers
from coopkin_sym.analysis.sweep import grid
from coopkin_sym.present import display, mathjax
from coopkin_sym.present.report import NUMBER_WORDS

GENERIC = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
# text a name could hold that HTML and LaTeX reserve
NASTY = "<script>alert('x')</script> & a_b^c {d} $e$ 50% #f ~g \\h\nnew line"


@pytest.fixture(scope="module")
def results() -> dict[str, object]:
    case1 = coopkin_sym.load("paper-case1-hard")
    case2 = coopkin_sym.load("paper-case2-hard")
    locus = case1.locus()
    return {
        "system": case1,
        "case1 at a point": case1.analyze("q1=pi/2,q2=pi/2"),
        "case2 at a point": case2.analyze("q1=pi/2,q2=pi/2"),
        "planar": coopkin_sym.load("planar-two-fingers").analyze(),
        "case2 generic": case2.analyze(generic=True),
        "case1 one joint symbolic": coopkin_sym.load("paper-case1-soft").analyze(
            "L=2", free=["q1"]),
        "irrational": case1.analyze("q1=pi/3"),
        "irrational, two joints": case1.analyze("q1=-pi/6,q2=pi/6"),
        "locus": locus,
        "component": locus.components[-1],
        "sweep": case1.sweep(grid(case1, "q1=-pi..pi:9,q2=-pi..pi:5")),
        "manipulability": case1.analyze("L=1").manipulability(["v_x", "v_y"]),
        "numbers": Numbers(2, 2, 1, 0, 1, 4, 0),
        "nasty locus": _nasty_locus(),
        "nasty component": _nasty_locus().components[0],
    }


def _nasty_locus() -> Locus:
    long_equation = " + ".join(f"{k}*t_q1**{k}*t_q2" for k in range(1, 400))
    component = Component([long_equation], dict(GENERIC, Nm=3), {"q1": NASTY}, True,
                          condition=f"{long_equation} = 0", changes={"Nm": (2, 3)})
    return Locus(NASTY * 20, ["t_q1", "t_q2"], NASTY, GENERIC, [component] * 250,
                 certificate=Certificate(NASTY, certified=True))


NAMES = ["system", "case1 at a point", "case2 at a point", "planar", "case2 generic",
         "case1 one joint symbolic", "irrational", "irrational, two joints", "locus",
         "component", "sweep", "manipulability", "numbers", "nasty locus",
         "nasty component"]


# ------------------------------------------------------------------ checkers


class _Html(HTMLParser):
    """Checks that every tag is closed in order; collects the text of table rows."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.rows: list[list[str]] = []
        self.text: list[str] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        self.stack.append(tag)
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        assert self.stack, f"</{tag}> closes nothing"
        top = self.stack.pop()
        assert top == tag, f"</{tag}> closes <{top}>"
        if tag in ("td", "th"):
            self.rows[-1].append("".join(self._cell or []))
            self._cell = None

    def handle_data(self, data):
        self.text.append(data)
        if self._cell is not None:
            self._cell.append(data)


def parse_html(page: str) -> _Html:
    parser = _Html()
    parser.feed(page)
    parser.close()
    assert parser.stack == [], f"unclosed tags: {parser.stack}"
    return parser


def check_latex(tex: str) -> None:
    """Display math whose braces and environments balance, every cell of which
    matplotlib's mathtext renders (its arrays and matrices taken apart, ``\\&``, which
    LaTeX and MathJax read in math but mathtext does not, replaced)."""
    mathtext = pytest.importorskip("matplotlib.mathtext")
    assert tex.startswith("$$") and tex.endswith("$$"), tex[:40]
    body = tex[2:-2]
    assert "$" not in body.replace(r"\$", ""), "math mode left inside display math"
    depth = 0
    for m in re.finditer(r"\\\\|\\[{}]|[{}]", body):
        if m.group() in ("{", "}"):
            depth += 1 if m.group() == "{" else -1
            assert depth >= 0, "a } closes nothing"
    assert depth == 0, "unbalanced braces"
    stack = []
    for kind, env in re.findall(r"\\(begin|end)\{(\w+)\}", body):
        if kind == "begin":
            stack.append(env)
        else:
            assert stack and stack.pop() == env, f"\\end{{{env}}} closes nothing"
    assert stack == []
    flat = re.sub(r"\\(begin|end)\{\w+\}(\{[lcr]+\})?", " ", body)
    flat = flat.replace(r"\left[", " ").replace(r"\right]", " ").replace(r"\&", "+")
    parser = mathtext.MathTextParser("path")
    cells = [c for c in re.split(r"\\\\|&", flat) if c.strip()]
    assert cells
    for cell in cells:
        parser.parse(f"${cell.strip()}$")


def numbers_of(obj) -> dict[str, int]:
    if isinstance(obj, Numbers):
        return obj.as_dict()
    if isinstance(obj, Locus):
        return obj.generic
    if hasattr(obj, "generic") and isinstance(obj.generic, Numbers):
        return obj.generic.as_dict()
    numbers = obj.numbers
    return numbers if isinstance(numbers, dict) else numbers.as_dict()


# ------------------------------------------------------------------ repr


@pytest.mark.parametrize("name", NAMES)
def test_repr_is_short_and_one_line(results, name):
    text = repr(results[name])
    assert len(text) < 300, text
    assert "\n" not in text
    assert " at 0x" not in text


@pytest.mark.parametrize("name", [n for n in NAMES if n not in (
    "system", "manipulability", "component", "nasty component")])
def test_repr_states_the_numbers(results, name):
    obj = results[name]
    numbers = numbers_of(obj)
    text = repr(obj)
    assert all(f"{k}={v}" in text for k, v in numbers.items()), text


def test_reprs_read_as_documented(results):
    assert repr(results["case1 at a point"]) == (
        "<Analysis paper case 1, hard/hard at q1=pi/2,q2=pi/2: "
        "Nm=3 Nc=3 Ni=1 Nr=0 Ng=1 Nd=4 Nh=1>")
    assert repr(results["case2 generic"]).startswith(
        "<Analysis paper case 2, two SCARA robots, hard/hard generic: Nm=8")
    assert repr(results["case1 one joint symbolic"]).startswith(
        "<Analysis paper case 1, soft/soft at L=2, symbolic q1: ")
    assert repr(results["planar"]).startswith("<Analysis planar two-finger grasp at home: ")
    assert repr(results["locus"]).endswith("; 5 components, not certified>")
    assert repr(results["nasty locus"]).endswith("; 250 components, certified>")
    assert repr(results["irrational"]).startswith(
        "<IrrationalAnalysis paper case 1, hard/hard at q1=pi/3 in Q(")
    assert repr(results["component"]).endswith(
        "(isolated): Nm 2->3, Nc 2->3, Ni 1->3, Ng 1->3, Nh 0->1>")
    assert repr(results["sweep"]).startswith(
        "<SweepResult paper case 1, hard/hard over q1, q2: 45 points, ")
    assert repr(results["system"]) == ("System('paper case 1, hard/hard': 2 arms, "
                                       "2 joints, 2 contacts)")


def test_numbers_stay_a_plain_dataclass():
    n = Numbers(2, 2, 1, 0, 1, 4, 0)
    assert repr(n) == "Numbers(Nm=2, Nc=2, Ni=1, Nr=0, Ng=1, Nd=4, Nh=0)"
    assert n == Numbers(**GENERIC) and hash(n) == hash(Numbers(**GENERIC))
    assert n != Numbers(3, 2, 1, 0, 1, 4, 0)
    with pytest.raises(AttributeError):
        n.Nm = 3  # type: ignore[misc]


# ------------------------------------------------------------------ IPython text


@pytest.mark.parametrize("name", NAMES)
def test_pretty_starts_with_the_repr(results, name):
    pretty = pytest.importorskip("IPython.lib.pretty").pretty
    obj = results[name]
    text = pretty(obj)
    if name == "system":
        assert text.splitlines()[0] == "paper case 1, hard/hard"
        assert "contacts: c1 (hard, a1 link 1), c2 (hard, a2 link 1)" in text
        return
    assert text.splitlines()[0] == repr(obj)


def test_pretty_says_more_on_more_lines(results):
    pretty = pytest.importorskip("IPython.lib.pretty").pretty
    lines = pretty(results["case1 at a point"]).splitlines()
    assert lines[1] == "  Nm = 3  Nc = 3  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 1"
    assert lines[2].startswith("  Grasp classes: indeterminate (Ni = 1)")
    assert lines[3] == "  Blocks: C11 (6 x 1), C12 (6 x 2), C22 (2 x 2), C23 (2 x 0)"
    locus = pretty(results["locus"]).splitlines()
    assert locus[1] == "  completeness not certified (run with --certify)"
    assert locus[4:6] == [
        "  family A (4 components, e.g. #1): Nm 2 -> 3, Nc 2 -> 3, Nh 0 -> 1",
        "  family B (#5): Nm 2 -> 3, Nc 2 -> 3, Ni 1 -> 3, Ng 1 -> 3, Nh 0 -> 1"]
    assert locus[6] == ("  #1 q1 = -pi/2, q2 = -pi/2 (isolated point): Nm 2 -> 3, "
                        "Nc 2 -> 3, Nh 0 -> 1; becomes hyperstatic")
    nasty = pretty(results["nasty locus"]).splitlines()
    assert nasty[-1] == "  ... and 238 more components"
    assert max(len(line) for line in nasty) < 300
    sweep = pretty(results["sweep"]).splitlines()
    assert sweep[2].startswith("  Nm = 3  Nc = 3  Ni = 1  Nr = 0  Ng = 1  Nd = 4  Nh = 1: ")


def test_pretty_of_a_cycle_is_the_repr(results):
    class Printer:
        def __init__(self):
            self.out = []

        def text(self, s):
            self.out.append(s)

        def break_(self):
            self.out.append("\n")

    a = results["case1 at a point"]
    p = Printer()
    a._repr_pretty_(p, True)
    assert "".join(p.out) == repr(a)


# ------------------------------------------------------------------ LaTeX


LATEX = ["case1 at a point", "case2 at a point", "planar", "case2 generic",
         "case1 one joint symbolic", "irrational", "irrational, two joints",
         "manipulability", "numbers"]


@pytest.mark.parametrize("name", LATEX)
def test_latex_is_display_math_that_parses(results, name):
    tex = results[name]._repr_latex_()
    check_latex(tex)
    if name != "manipulability":
        numbers = numbers_of(results[name])
        for k in NUMBER_NAMES:
            assert f"N_{{{k[1:]}}} = {numbers[k]} & " in tex


def test_latex_of_an_analysis_has_its_small_blocks(results):
    tex = results["case1 at a point"]._repr_latex_()
    assert r"C_{11} = \left[\begin{matrix}0\\0\\0\\1\\0\\0\end{matrix}\right]" in tex
    assert r"C_{23} = \emptyset" in tex
    generic = results["case2 generic"]._repr_latex_()
    assert r"C_{11}\ (6 \times 1): \text{not shown here: entries of up to about" in generic
    assert r"C_{23} = \left[" in generic


def test_latex_escapes_names():
    tex = display._math([display._tex_text(NASTY)])
    check_latex(tex)
    assert "\n" not in tex[len("$$\\begin{array}{l}\n"):-len("\n\\end{array}$$")]
    assert r"\text{ a}\_\text{b}\hat{}\text{c }\{\text{d}\}" in tex
    assert r"\text{h new line}" in tex


def test_results_without_latex_say_none(results):
    for name in ("locus", "sweep", "component"):
        assert results[name]._repr_latex_() is None


# ------------------------------------------------------------------ HTML


HTML = ["system", "case1 at a point", "case2 at a point", "planar", "case2 generic",
        "case1 one joint symbolic", "irrational", "irrational, two joints", "locus",
        "component", "sweep", "numbers", "nasty locus", "nasty component"]


@pytest.mark.parametrize("name", HTML)
def test_html_is_balanced_and_states_the_numbers(results, name):
    page = results[name]._repr_html_()
    parsed = parse_html(page)
    assert "<script" not in page and "<style" not in page
    if name == "system":
        assert ["c1", "hard", "a1 link 1"] in parsed.rows
        return
    numbers = numbers_of(results[name])
    if isinstance(results[name], Locus):   # compact: names (meanings as tooltips), values
        assert list(NUMBER_NAMES) in parsed.rows
        assert [str(numbers[k]) for k in NUMBER_NAMES] in parsed.rows
        assert all(f'title="{NUMBER_WORDS[k]}"' in page for k in NUMBER_NAMES)
        return
    for k in NUMBER_NAMES:
        assert [k, str(numbers[k]), NUMBER_WORDS[k]] in parsed.rows, k


def test_html_of_an_analysis(results):
    parsed = parse_html(results["case1 at a point"]._repr_html_())
    text = "".join(parsed.text)
    assert "Analysis of paper case 1, hard/hard at q1=pi/2,q2=pi/2" in text
    assert ("Grasp classes: indeterminate (Ni = 1), graspable (Ng = 1), defective (Nd = 4), "
            "hyperstatic (Nh = 1)") in text
    assert ("Ni = 1: with every joint locked, the object can still rotate about the line "
            "through c1 and c2.") in text
    assert "  q1 | -1  1\n  q2 | -1  0" in text
    assert "C23 (2 x 0): empty" in text


def test_html_of_a_locus_has_a_row_per_component(results):
    parsed = parse_html(results["locus"]._repr_html_())
    rows = [r for r in parsed.rows if r and r[0].startswith("#") and r[0] != "#"]
    assert len(rows) == 5
    assert rows[0] == ["#1", "q1 = -pi/2, q2 = -pi/2", "isolated point", "3", "3", "1", "0",
                       "1", "4", "1", "Nm 2 \u2192 3, Nc 2 \u2192 3, Nh 0 \u2192 1; becomes "
                       "hyperstatic", "q1=-pi/2,q2=-pi/2,L=1"]
    text = "".join(parsed.text)
    assert "Completeness not certified (run with --certify)." in text
    nasty = results["nasty locus"]._repr_html_()
    parsed = parse_html(nasty)
    assert "... and 50 more components." in "".join(parsed.text)
    # many components of one family: the family is said, the components (up to 200)
    # are folded under one line that says so
    opened, folded = nasty.split("<details><summary>components #1 to #200</summary>")
    assert opened.count("<tr><td") == 1 + 1       # the generic numbers, the family
    assert "<p>By what changes: 1 family.</p>" in opened
    assert folded.count("<tr><td") == 200
    listed = [r[0] for r in parsed.rows if r and r[0].startswith("#") and r[0] != "#"]
    assert [x.split()[0] for x in listed] == [f"#{k}" for k in range(1, 201)]
    assert "Completeness: complete (certified)." in "".join(parsed.text)


def test_html_escapes_every_text(results):
    for name in ("nasty locus", "nasty component"):
        page = results[name]._repr_html_()
        assert "<script>" not in page and "&lt;script&gt;" in page
        assert NASTY.split("\n")[0] not in page


def test_html_of_a_sweep_counts_each_set_of_numbers(results):
    parsed = parse_html(results["sweep"]._repr_html_())
    res = results["sweep"]
    counted = [r for r in parsed.rows if len(r) == 9 and r[7].isdigit()]
    assert sum(int(r[7]) for r in counted) == len(res)
    assert ["3", "3", "1", "0", "1", "4", "1", str(res.not_generic()),
            "q1=-pi/2,q2=-pi/2"] in counted


# ------------------------------------------------------------------ no long computation


def test_display_builds_no_large_block():
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    a._repr_html_()
    a._repr_latex_()
    built = {name for name in ("C11", "C12", "C22", "C23") if name in vars(a)}
    assert built == {"C23"}


def test_display_says_a_block_over_the_budget_is_too_large(monkeypatch):
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    a.term_budget = 10
    # the budget held on C22 alone: C11 (276 terms) and the rest still shown
    monkeypatch.setattr(type(a), "_fits", lambda self, name, vectors, what: None)
    monkeypatch.setattr(display, "_ENTRY_TERMS", 10**6)
    monkeypatch.setattr(display, "_BLOCK_TERMS", 10**9)
    monkeypatch.setattr(display, "_MAX_LATEX", 10**9)
    monkeypatch.setattr(mathjax, "MATHJAX_LATEX_LIMIT", 10**9)   # the whole in LaTeX
    page = a._repr_html_()
    parse_html(page)
    assert "<strong>C22</strong> (8 x 5): too large: C22: the coordinated joint motions" in page
    tex = a._repr_latex_()
    assert r"C_{22}\ (8 \times 5): \text{too large: C22: the coordinated" in tex


def test_without_renderers_a_result_shows_as_its_repr(results, monkeypatch):
    monkeypatch.setattr(renderers, "_RENDERERS", {})
    a = results["case1 at a point"]
    assert a._repr_html_() is None and a._repr_latex_() is None
    pretty = pytest.importorskip("IPython.lib.pretty").pretty
    assert pretty(a) == repr(a)


def test_importing_the_package_installs_the_renderers():
    kinds = {(cls.__name__, kind) for cls, kind in renderers._RENDERERS}
    assert {("Analysis", "html"), ("Analysis", "latex"), ("Analysis", "pretty"),
            ("Numbers", "latex"), ("Locus", "html"), ("SweepResult", "html")} <= kinds


# ------------------------------------------------------------------ what MathJax accepts


def test_no_latex_over_what_mathjax_accepts(results, monkeypatch):
    """MathJax refuses 12,218 characters (its TeX buffer holds 5 * 1024): a display
    longer than the limit gives no LaTeX, and its HTML view remains."""
    assert mathjax.MATHJAX_LATEX_LIMIT == 4000
    for name in LATEX:
        assert len(results[name]._repr_latex_()) <= mathjax.MATHJAX_LATEX_LIMIT, name
    a = coopkin_sym.load("paper-case2-hard").analyze(generic=True)
    a.term_budget = 10
    # the budget held on C22 alone: C11 (276 terms) and the rest still shown
    monkeypatch.setattr(type(a), "_fits", lambda self, name, vectors, what: None)
    monkeypatch.setattr(display, "_ENTRY_TERMS", 10**6)
    monkeypatch.setattr(display, "_BLOCK_TERMS", 10**9)
    monkeypatch.setattr(display, "_MAX_LATEX", 10**9)
    assert a._repr_latex_() is None
    page = a._repr_html_()
    parse_html(page)
    assert "<strong>C22</strong> (8 x 5): too large" in page


def test_factored_motions_of_case2_show_as_html_with_the_named_factors():
    f = coopkin_sym.load("paper-case2-hard").analyze(generic=True).coordinated_factored()
    assert len("$$" + r" \\ ".join(f.latex().splitlines()) + "$$") == 12218
    assert f._repr_latex_() is None
    page = f._repr_html_()
    assert len(page) < 12000
    parsed = parse_html(page)
    factors = [r for r in parsed.rows if len(r) == 2 and r[0].startswith("d")]
    assert factors == [["d1", "L"], ["d2", "t_q2 - 1"], ["d3", "t_q2 + 1"],
                       ["d4", "t_q1**2 + 1"], ["d5", "t_q2**2 + 1"], ["d6", "t_q8**2 + 1"],
                       ["d7", "t_q7**2 + 1"], ["d8", "t_q6**2 + 1"],
                       ["d9", "t_q8**2 + 2*t_q8 - 1"]]
    # C12 (zeros and ones) is typeset; the maps, too wide, are listed entry by entry
    assert r"$$C_{12} = \left[\begin{matrix}0 &amp; 0 &amp; 0 &amp; 0 &amp; 0\\1 &amp; 0" in page
    assert "$$K_" not in page
    entries = [r for r in parsed.rows if len(r) == 3 and r[0].startswith("q")]
    assert [r[:2] for r in entries if r[0] in ("q5", "q6")] == [
        ["q5", "v_x"], ["q5", "w_y"], ["q5", "w_z"]]            # q6 moves with no twist
    assert ["q5", "v_x", "1"] in entries and ["q4", "v_z", "1"] in entries
    assert len(entries) == 13 + 13
    (cut,) = [r[2] for r in entries if r[:2] == ["q7", "w_y"]]
    assert cut.endswith("...") and len(cut) == 300
    whole = sp.sstr(f.maps()["s2"][2, 4])
    assert len(whole) == 1057 and cut[:297] == whole[:297]
    text = "".join(parsed.text)
    assert "Entries longer than 300 characters are cut here." in text
    assert "All of it: .latex() (LaTeX), .maps() (SymPy matrices" in text
    assert repr(f) == ("<FactoredMotions paper case 2, two SCARA robots, hard/hard: 5 "
                       "coordinated motions; arms s1 (4 joints), s2 (4 joints); 9 named factors>")


def test_small_factored_motions_keep_their_latex():
    f = coopkin_sym.load("paper-case1-hard").analyze(generic=True).coordinated_factored()
    tex = f._repr_latex_()
    assert tex == "$$" + r" \\ ".join(f.latex().splitlines()) + "$$"
    assert tex.endswith(r"d_{1} = L \\ d_{2} = t_{q1} \\ d_{3} = t_{q2}$$")
    check_latex(tex)
    parse_html(f._repr_html_())


def test_html_of_an_analysis_typesets_its_small_blocks(results):
    page = results["case1 at a point"]._repr_html_()
    assert (r"$$C_{11} = \left[\begin{matrix}0\\0\\0\\1\\0\\0\end{matrix}\right]$$"
            in page)
    assert "<details><summary>as text (rows: v_x, v_y, v_z, w_x, w_y, w_z)</summary>" in page
