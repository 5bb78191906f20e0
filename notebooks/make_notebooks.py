"""Build the notebooks of this folder and run them, storing their outputs.

After editing a notebook's cells here, regenerate every notebook with::

    python notebooks/make_notebooks.py

It writes each notebook's cells, runs it top to bottom in a fresh ``python3`` kernel
(nbclient, from the dev extras) with this folder as working directory, and stores the
outputs: text, LaTeX, Markdown tables and pictures (PNG at 80 dpi, stored with 256
colours to keep the files small). ``python notebooks/make_notebooks.py 03``
regenerates only the notebooks whose names start with ``03``.

Running the command again without a change rewrites the same files: the volatile
metadata (cell timings, the kernel's Python version) is left out, and a cell whose new
outputs differ from the stored ones only in volatile parts (printed timings, temporary
paths, float noise: see ``normalize``) keeps the stored ones.

Each notebook checks the paper's numbers with ``assert`` cells, so a wrong result fails
the run (and the test suite, which runs every notebook through nbmake).
``tests/test_notebooks_up_to_date.py`` checks that the committed notebooks have the
cells built here and print the numbers the code prints now.
"""

from __future__ import annotations

import argparse
import base64
import copy
import io
import os
import re
import tempfile
import textwrap
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook
from PIL import Image

HERE = Path(__file__).resolve().parent


def md(text: str):
    return new_markdown_cell(textwrap.dedent(text).strip())


def code(text: str):
    return new_code_cell(textwrap.dedent(text).strip())


SETUP = code("""
    import matplotlib
    import sympy as sp
    from IPython.display import Markdown, Math, display

    import coopkin_sym
    from coopkin_sym import draw, example_path, named_latex, same_span, sentences


    def numbers_table(rows):
        \"\"\"A Markdown table of (label, Numbers) pairs.\"\"\"
        head = "| | Nm | Nc | Ni | Nr | Ng | Nd | Nh |\\n|---|---|---|---|---|---|---|---|\\n"
        body = "".join(f"| {label} | " + " | ".join(str(v) for v in n.as_dict().values())
                       + " |\\n" for label, n in rows)
        return Markdown(head + body)


    matplotlib.rcParams["figure.dpi"] = 80  # pictures of modest size
""")


# ---------------------------------------------------------------------------- 01

NB01 = [
    md("""
    # Case study 1: two one-link arms holding an object

    The first example of Bicchi, Melchiorri and Balluchi, *Mobility and Kinematic
    Analysis of General Cooperating Robot Systems* (ICRA 1992): section 2.1 builds its
    matrices G, D, H (fig. 2) and section 4.1 analyzes it for several contact models.
    Two one-link arms turn about vertical axes through $o_1 = (0, 0, 0)$ and
    $o_2 = (L, 0, 0)$; their links (length $L$) touch the object at $c_1 = (0, L, 0)$ and
    $c_2 = (L, L, 0)$ with normals $n_1 = (1, 0, 0)$, $n_2 = (-1, 0, 0)$.

    Everything below is computed exactly by `coopkin_sym`; the length $L$ stays a symbol.
    """),
    SETUP,
    md("""
    ## The model

    The system ships as model files, one per contact-model combination
    (`paper-case1-hard`, `-soft`, `-soft-hard`, `-complete-hard`). Each file is the
    paper's data, nothing else:
    """),
    code("""
    print(example_path("paper-case1-hard").read_text())
    hard = coopkin_sym.load("paper-case1-hard")
    L = hard.model.parameters[0]
    a = hard.analyze()          # joints at home (q1 = q2 = 0), L symbolic
    """),
    md("""
    ## G and D (paper eqs. 2 to 4)

    $G^T$ maps the object's twist $\\dot u = (v, \\omega)$ (reference point at the base
    origin) to the velocities of the object's contact frames; $D$ maps the joint rates
    to the velocities of the links' contact frames. Rows: all linear blocks first
    ($\\dot c_1, \\dot c_2$), then the angular ones ($\\omega_1, \\omega_2$), as in the paper.
    """),
    code("""
    display(Math(named_latex("G", a.G)))
    display(Math(named_latex("D", a.D)))
    """),
    code("""
    def S(c):
        return sp.Matrix([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])


    c1, c2 = sp.Matrix([0, L, 0]), sp.Matrix([L, L, 0])
    I3, O3 = sp.eye(3), sp.zeros(3)
    assert a.G == sp.Matrix(sp.BlockMatrix([[I3, I3, O3, O3], [S(c1), S(c2), I3, I3]]))
    # joint k moves its contact by s_k x (c - o_k) and turns it by s_k
    assert a.D.T == sp.Matrix([[-L, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0],
                               [0, 0, 0, -L, 0, 0, 0, 0, 0, 0, 0, 1]])
    """),
    md("""
    ## H for each contact model

    $H$ keeps the velocity components a contact constrains: a **hard finger** (point
    contact with friction) the three linear ones; a **soft finger** also the rotation
    about the normal ($n_i^T$ on the angular block); a **complete constraint** all six.
    These are the paper's $H$ matrices of section 2.1.
    """),
    code("""
    names = ["paper-case1-hard", "paper-case1-soft", "paper-case1-soft-hard",
             "paper-case1-complete-hard"]
    analyses = {name: coopkin_sym.load(name).analyze() for name in names}
    for name, an in analyses.items():
        display(Markdown(f"`{name}`: contacts "
                         + ", ".join(f"{c.name} {c.model}" for c in an.model.contacts)))
        display(Math(named_latex("H", an.H)))
    """),
    code("""
    assert analyses["paper-case1-hard"].H == sp.eye(6).row_join(sp.zeros(6))
    soft_rows = sp.Matrix([[0] * 6 + [1, 0, 0, 0, 0, 0], [0] * 6 + [0, 0, 0, -1, 0, 0]])
    assert analyses["paper-case1-soft"].H == sp.eye(6).row_join(sp.zeros(6)).col_join(soft_rows)
    assert analyses["paper-case1-soft-hard"].H.shape == (7, 12)
    assert analyses["paper-case1-complete-hard"].H.shape == (9, 12)
    """),
    md("""
    ## Q and its nullspace C (eqs. 7 and 8), both contacts hard

    $Q = (H G^T \\mid -H D)$ acts on $(\\dot u, \\dot q)$; the columns of $C$ span its
    nullspace, arranged by column operations as
    $C = \\begin{pmatrix} C_{11} & C_{12} & 0 \\\\ 0 & C_{22} & C_{23} \\end{pmatrix}$.
    """),
    code("""
    display(Math(named_latex("Q", a.Q)))
    display(Math(named_latex("C", a.C)))
    for name, block in a.blocks().items():
        display(Math(named_latex(name, block)))
    assert a.check()           # Q C = 0, exactly
    a.numbers
    """),
    md("""
    The paper (section 4.1): *"the mobility and connectivity of the system are
    $N_m = N_c = 2$, being the redundancy $N_r = 0$. The system is quasi-statically
    indeterminate ($N_i = 1$)"*, with $C_{11} = (0, 0, -L, 1, 0, 0)^T$ and one
    coordinated motion $C_{12} = (-L, 0, 0, 0, 0, 0)^T$, $C_{22} = (1, 1)^T$ (a
    translation along $x$; the scanned text says $z$, a misprint). Bases may differ by
    a scale factor, so we compare spans:
    """),
    code("""
    n = a.numbers
    assert (n.Nm, n.Nc, n.Ni, n.Nr) == (2, 2, 1, 0)
    assert same_span(a.C11, sp.Matrix([0, 0, -L, 1, 0, 0]))
    assert same_span(a.C12.col_join(a.C22), sp.Matrix([-L, 0, 0, 0, 0, 0, 1, 1]))
    for s in sentences(a):
        print("-", s)
    """),
    md("""
    **Interpretation** (section 4.1). With every joint locked the object can still spin
    about the line through the two contact points: hard fingers cannot resist that
    rotation ($C_{11}$). Besides this free motion there is one coordinated motion: both
    joints at the same rate translate the object along $x$ ($C_{12}$, $C_{22}$).

    ## All four contact models

    Soft fingers (friction about the normals) remove the free spin; one soft finger is
    enough; a complete-constraint contact stops everything:
    """),
    code("""
    paper = {  # section 4.1
        "paper-case1-hard": (2, 2, 1, 0),
        "paper-case1-soft": (1, 1, 0, 0),
        "paper-case1-soft-hard": (1, 1, 0, 0),   # "the same result ... any single contact soft"
        "paper-case1-complete-hard": (0, 0, 0, 0),
    }
    display(numbers_table([(f"`{name}`", an.numbers) for name, an in analyses.items()]))
    for name, expected in paper.items():
        n = analyses[name].numbers
        assert (n.Nm, n.Nc, n.Ni, n.Nr) == expected, name
    for name in ["paper-case1-soft", "paper-case1-soft-hard"]:
        an = analyses[name]
        assert same_span(an.C12.col_join(an.C22), sp.Matrix([-L, 0, 0, 0, 0, 0, 1, 1]))
    assert analyses["paper-case1-complete-hard"].C.shape == (8, 0)
    """),
    md("""
    ## The kinematic maps (eqs. 11 and 12)

    Which joint rates move the object along $-L\\,x$? And what does the object do when
    both joints turn at rate 1? (Eq. 12 adds the indeterminate spin $C_{11} y$.) A
    velocity outside the feasible subspace would break a contact and is refused.
    """),
    code("""
    m = a.joint_velocities([-L, 0, 0, 0, 0, 0])
    display(Math(named_latex(r"\\dot q", m.particular)))
    assert m.particular == sp.Matrix([1, 1]) and m.free.shape == (2, 0)
    u = a.object_velocities([1, 1])
    display(Math(named_latex(r"\\dot u", u.particular)))
    display(Math(named_latex(r"\\text{plus any multiple of}", u.free)))
    assert u.particular == sp.Matrix([-L, 0, 0, 0, 0, 0]) and same_span(u.free, a.C11)
    try:
        a.joint_velocities([0, 1, 0, 0, 0, 0])
    except coopkin_sym.InfeasibleMotion as exc:
        print("translation along y:", exc)
    """),
    code("""
    draw(a, motion=("coordinated", 1))
    """),
    md("""
    ## The arms' angles free: the generic analysis

    With `generic=True` both joint angles stay symbolic, through $t_i = \\tan(q_i/2)$
    (then $\\cos q_i = (1 - t_i^2)/(1 + t_i^2)$ and $\\sin q_i = 2t_i/(1 + t_i^2)$): the
    result holds for almost every configuration. The numbers are those of the home
    configuration:
    """),
    code("""
    g = hard.analyze(generic=True)
    print("variables:", g.variables)
    for name, block in g.blocks().items():
        display(Math(named_latex(name, block.applyfunc(sp.factor))))
    assert (g.numbers.Nm, g.numbers.Nc, g.numbers.Ni, g.numbers.Nr) == (2, 2, 1, 0)
    generic = {name: coopkin_sym.load(name).analyze(generic=True).numbers for name in names}
    display(numbers_table([(f"`{name}`, generic", n) for name, n in generic.items()]))
    for name, expected in paper.items():
        n = generic[name]
        assert (n.Nm, n.Nc, n.Ni, n.Nr) == expected, name
    """),
    md("""
    ## Where the numbers change

    The object keeps its size when both arms turn together ($q_1 = q_2$: the links and
    the object form a parallelogram). Along that family the numbers are the generic
    ones except where both links lie on the contact line, $q_1 = q_2 = \\pm\\pi/2$: there
    $N_m$ jumps from 2 to 3. The exact engine sees this at the exact angle and nowhere
    else (angles are exact when $\\tan(q/2)$ is rational, e.g. `2*atan(1/3)`):
    """),
    code("""
    family = ["0", "2*atan(1/3)", "2*atan(9/10)", "pi/2", "2*atan(11/10)", "pi",
              "2*atan(-99/100)", "-pi/2", "2*atan(-101/100)"]
    rows = [(f"q1 = q2 = `{q}`", hard.analyze(f"q1={q},q2={q}").numbers) for q in family]
    display(numbers_table(rows))
    for q, (_, n) in zip(family, rows, strict=True):
        assert n.Nm == (3 if q in ("pi/2", "-pi/2") else 2), q
    """),
    code("""
    s = hard.analyze("q1=-pi/2,q2=-pi/2")
    for name, block in s.blocks().items():
        display(Math(named_latex(name, block)))
    for line in sentences(s):
        print("-", line)
    assert (s.numbers.Nm, s.numbers.Nc, s.numbers.Ni, s.numbers.Nr) == (3, 3, 1, 0)
    assert same_span(s.C11, sp.Matrix([0, 0, 0, 1, 0, 0]))       # spin about the x axis
    assert same_span(s.C12.col_join(s.C22),
                     sp.Matrix([[0, L, 0, 0, 0, 0, 1, 1], [0, 0, 0, 0, 0, 1, 1, 2]]).T)
    """),
    md("""
    At $q_1 = q_2 = -\\pi/2$ the contacts are $c_1 = (L, 0, 0)$ and $c_2 = (2L, 0, 0)$
    and both links lie along the $x$ axis. Each contact can only move across its link
    (along $y$), and since the two links no longer turn the contact line, the two
    contact speeds are independent to first order: besides the translation along $y$
    ($\\dot q_1 = \\dot q_2$) the object can now turn about the $z$ axis through the base
    ($\\dot q_2 = 2\\dot q_1$). This is a first-order (instantaneous) statement, as in the
    paper; the extra motion does not persist (second-order effects, cf. the paper's
    remark on higher-order motions). The other contact models change there too:
    """),
    code("""
    rows = [(f"`{name}`", coopkin_sym.load(name).analyze("q1=-pi/2,q2=-pi/2").numbers)
            for name in names]
    display(numbers_table(rows))
    assert [n.Nm for _, n in rows] == [3, 3, 3, 1]
    draw(s, motion=("coordinated", 2))
    """),
    md("""
    ## The same system in the plane

    Every joint of case 1 turns about $z$ and every contact lies in the $xy$-plane, so
    the system can also be read as a planar one (`planar: true`): object twists
    $(v_x, v_y, \\omega_z)$, and a hard finger (a point contact with friction) holds
    the two in-plane components of the contact velocity. $G$ is $3 \\times 3n$ and
    $Q$ is $4 \\times 5$.

    The spatial indeterminate motion $N_i = 1$ is the spin about the line through the
    two contacts, which lies in the plane: it lifts the object out of the plane, so a
    planar analysis does not have it. In the plane $N_m = N_c = 1$ and $N_i = 0$: the
    only motion left is the coordinated translation along $x$. The force domain changes
    with it: of the four in-plane contact force components, $N_g = 1$ squeezes the
    object along the contact line and $N_d = 2$ load no joint.
    """),
    code("""
    print(example_path("paper-case1-planar").read_text())
    flat = coopkin_sym.load("paper-case1-planar").analyze()
    for name, block in flat.blocks().items():
        display(Math(named_latex(name, block)))
    for line in sentences(flat):
        print("-", line)
    n = flat.numbers
    assert (n.Nm, n.Nc, n.Ni, n.Nr, n.Ng, n.Nd, n.Nh) == (1, 1, 0, 0, 1, 2, 0)
    assert flat.Q.shape == (4, 5) and flat.G.shape == (3, 6)
    # the spatial analysis restricted to the plane: rows v_x, v_y, columns v_x, v_y, w_z
    plane = a.Q.extract([0, 1, 3, 4], [0, 1, 5, 6, 7])
    assert plane == flat.Q
    # the spatial indeterminate spin has no in-plane component
    assert [a.C11[k, 0] for k in (0, 1, 5)] == [0, 0, 0]
    assert same_span(flat.C12.col_join(flat.C22), sp.Matrix([L, 0, 0, -1, -1]))
    """),
    md("""
    In the plane the numbers change where both links line up with the contact line
    ($q_1$ and $q_2$ each $\\pm\\pi/2$), and where the two contacts meet
    ($q_1 = -q_2$ with $\\tan(q_2/2) = 2 \\pm \\sqrt 3$, i.e. $q_2 = \\pi/6$ or
    $5\\pi/6$: the object may then turn about the common point). The locus is
    certified complete, and the system is drawn from above:
    """),
    code("""
    planar = coopkin_sym.load("paper-case1-planar")
    flat_locus = planar.locus()
    for c in flat_locus.components:
        print(c.condition.text, c.numbers)
    assert "q1 = pi/2, q2 = pi/2" in [c.condition.text for c in flat_locus.components]
    certificate = flat_locus.certify()
    print(flat_locus.completeness())
    assert certificate.certified_by() is not None and not certificate.failures()
    draw(planar.analyze("q1=pi/2,q2=pi/2"), motion=("coordinated", 2))
    """),
    md("""
    ## Moving the joints by hand

    `interactive()` gives a slider per joint over exact values (here the multiples of
    $\\pi/12$; `steps=` or `values=` choose others). Each change redraws the system and
    shows its seven numbers, computed exactly at that configuration as `analyze` does
    (an angle such as $\\pi/12$, whose $\\tan(q/2)$ is irrational, over the number field
    of its tangent); a configuration already seen is not computed again. The view needs
    ipywidgets (`pip install "coopkin_sym[notebook]"`), and its sliders can be set from
    code too: below, first the regular home configuration, then the singular one where
    both links line up with the contact line.
    """),
    code("""
    view = planar.interactive(at="L=1")
    print(view.at, view.numbers)
    assert view.numbers == planar.analyze("q1=0,q2=0,L=1").numbers
    view.select("q1=pi/2,q2=pi/2")
    print(view.at, view.numbers)
    assert view.numbers == planar.analyze("q1=pi/2,q2=pi/2,L=1").numbers
    assert view.numbers.Nm == 2
    display(draw(view.result))   # the picture the view shows there
    view
    """),
]


# ---------------------------------------------------------------------------- 02

NB02 = [
    md("""
    # Case study 2: two SCARA robots

    Section 4.2 of the paper (fig. 3): two four-joint SCARA-type robots hold an object.
    Robot `s1` has revolute joints q1, q2, q3 about $z$ and a prismatic q4 along $z$;
    robot `s2` a prismatic q5 along $x$ and revolute joints q6, q7, q8 about $x$. The
    contacts are at $c_1 = (L, L, L)$ and $c_2 = (3L, L, L)$ with normals $\\pm x$. The
    paper analyzes two grips: complete-constraint contacts (grippers) and hard-finger
    contacts ("sticks").
    """),
    SETUP,
    code("""
    print(example_path("paper-case2-hard").read_text())
    complete = coopkin_sym.load("paper-case2-complete")
    hard = coopkin_sym.load("paper-case2-hard")
    L = hard.model.parameters[0]
    """),
    md("""
    ## Complete-constraint contacts

    The paper: *"connectivity $N_c = 3$, no redundancy nor indeterminacy. The feasible
    motions for the object are all pure translations (the last three rows of $C_{12}$ are
    zeroes)"*, with $C_{12}$ and $C_{22}$ printed in full. Ours are the same matrices:
    """),
    code("""
    c = complete.analyze()
    display(Math(named_latex("C_{12}", c.C12)))
    display(Math(named_latex("C_{22}", c.C22)))
    paper_c12 = sp.Matrix([[L, 0, 0], [0, L, 0], [0, 0, L], [0, 0, 0], [0, 0, 0], [0, 0, 0]])
    paper_c22 = sp.Matrix([[0, 1, 0], [1, -1, 0], [-1, 0, 0], [0, 0, L], [L, 0, 0],
                           [0, -1, 0], [0, 1, -1], [0, 0, 1]])
    n = c.numbers
    assert (n.Nm, n.Nc, n.Ni, n.Nr) == (3, 3, 0, 0)
    assert same_span(c.C12.col_join(c.C22), paper_c12.col_join(paper_c22))
    assert c.C12[3:, :] == sp.zeros(3, 3)       # translations only
    for s in sentences(c):
        print("-", s)
    """),
    md("""
    ## Hard-finger contacts

    The paper: *"the mechanism has full connectivity ($N_c = 6$), although one of the
    movements of the object is quasi-statically indeterminate ($N_i = 1$). The system
    also exhibits redundant degrees of freedom in this configuration ($N_r = 2$)"*. (Its
    printed $C$ has unreadable entries, so we check the subspaces it describes in words.)
    """),
    code("""
    h = hard.analyze()
    for name, block in h.blocks().items():
        display(Math(named_latex(name, block)))
    n = h.numbers
    assert (n.Nm, n.Nc, n.Ni, n.Nr) == (8, 6, 1, 2)
    assert h.check()
    assert h.C11.row_join(h.C12).rank() == 6      # every object motion is possible
    """),
    md("""
    **Indeterminate motion** ($C_{11}$): *"rotations of the object about the axis joining
    the two contact points, which cannot be resisted by hard-point contacts"*. The
    twist of a rotation about the line through $c_1$ with direction $w$ is
    $(c_1 \\times w, w)$:
    """),
    code("""
    c1, c2 = sp.Matrix([L, L, L]), sp.Matrix([3 * L, L, L])
    w = (c2 - c1) / (2 * L)
    spin = c1.cross(w).col_join(w)
    display(Math(named_latex(r"(c_1 \\times w, w)", spin)))
    assert same_span(h.C11, spin)
    """),
    md("""
    **Redundant motions** ($C_{23}$): *"obtained by moving any of the third and sixth
    joint, i.e. rotations about the axis of the SCARA arms"*. At home $c_1$ lies on the
    axis of q3 and $c_2$ on the axis of q6, so each of these joints turns its link
    about the contact point and the object does not move:
    """),
    code("""
    e = sp.eye(8)
    assert same_span(h.C23, e[:, 2].row_join(e[:, 5]))        # q3 alone, q6 alone
    print(h.model.joint_names)
    m = h.object_velocities([0, 0, 1, 0, 0, 0, 0, 0])          # eq. (12), q3 alone
    display(Math(named_latex(r"\\dot u", m.particular)))
    display(Math(named_latex(r"\\text{plus any multiple of}", m.free)))
    assert m.particular == sp.zeros(6, 1) and same_span(m.free, h.C11)
    """),
    md("""
    **Coordinated motions** (eq. 11): for any object velocity the joint rates are a
    particular solution plus any combination of the redundant motions. For instance a
    translation of the object along $z$:
    """),
    code("""
    m = h.joint_velocities([0, 0, L, 0, 0, 0])
    display(Math(named_latex(r"\\dot q", m.particular)))
    display(Math(named_latex(r"\\text{plus}", m.free)))
    assert h.Q * sp.Matrix([0, 0, L, 0, 0, 0, *m.particular]) == sp.zeros(h.m, 1)
    for s in sentences(h):
        print("-", s)
    """),
    code("""
    draw(h, motion=("indeterminate", 1))
    """),
    code("""
    draw(h, motion=("redundant", 2))
    """),
    md("""
    ## All eight joints symbolic: the generic analysis

    `generic=True` keeps every joint variable symbolic ($t_i = \\tan(q_i/2)$ for the six
    revolute joints, the displacements q4 and q5) and $L$ too: nine variables. The
    numbers are those of the paper's configuration, so that configuration is generic
    for both grips:
    """),
    code("""
    gh = hard.analyze(generic=True)
    gc = complete.analyze(generic=True)
    print("variables:", gh.variables)
    display(numbers_table([("complete, generic", gc.numbers), ("hard, generic", gh.numbers)]))
    assert (gh.numbers.Nm, gh.numbers.Nc, gh.numbers.Ni, gh.numbers.Nr) == (8, 6, 1, 2)
    assert (gc.numbers.Nm, gc.numbers.Nc, gc.numbers.Ni, gc.numbers.Nr) == (3, 3, 0, 0)
    """),
    md("""
    The generic blocks are exact polynomial matrices, too large to read in full. Their
    sizes (terms of the largest entry, terms in all):
    """),
    code("""
    def terms(e):
        return len(sp.Add.make_args(sp.expand(e))) if e != 0 else 0

    rows = "".join(f"| {name} | {b.rows} x {b.cols} | {max((terms(x) for x in b), default=0)} "
                   f"| {sum(terms(x) for x in b)} |\\n" for name, b in gh.blocks().items())
    display(Markdown("| block | shape | largest entry | all entries |\\n|---|---|---|---|\\n"
                     + rows))
    assert {k: v.shape for k, v in gh.blocks().items()} == {
        "C11": (6, 1), "C12": (6, 5), "C22": (8, 5), "C23": (8, 2)}
    """),
    md("""
    $C_{23}$ is small and tells something the home configuration hides: for robot `s2`
    the generic redundant motion combines q6, q7 and q8 (three parallel revolute axes
    placing the contact point in a plane leave one motion free). At home the contact
    lies on the axis of q6 and the combination reduces to q6 alone:
    """),
    code("""
    display(Math(named_latex("C_{23}", gh.C23.applyfunc(sp.factor))))
    home = {v: 0 for v in gh.variables if v != L}             # every joint at home
    assert same_span(gh.C23.subs(home), h.C23)
    """),
    code("""
    draw(h, motion=("coordinated", 4))
    """),
]


# ---------------------------------------------------------------------------- 03

NB03 = [
    md("""
    # Singularity loci: where the numbers change, exactly

    The paper computes the mobility numbers at one configuration; notebook 01 found by
    hand, along one family, where they jump. `System.locus` finds
    every family of configurations where the numbers differ from the generic ones
    (the *locus*), decides each family's numbers exactly, gives an exact witness point
    on it (checked by a direct analysis), recurses inside each family for deeper drops,
    and lists what it did not explore. `Locus.write` writes it up.

    Angles are handled through $t = \\tan(q/2)$, so a component such as
    `t_q1 - 1 = 0` is $q_1 = \\pi/2$. Floats appear only in the plots.
    """),
    code("""
    import io
    import tempfile
    from pathlib import Path

    import matplotlib
    import sympy as sp
    from IPython.display import Image, Markdown, display

    import coopkin_sym
    from coopkin_sym import component_sentences, draw, remark_text, remark_texts

    matplotlib.rcParams["figure.dpi"] = 80  # pictures of modest size


    def png(figure):
        \"\"\"A matplotlib figure (Locus.plot returns a plain one) as an inline PNG.\"\"\"
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png", dpi=80, bbox_inches="tight")
        return Image(buffer.getvalue())


    def recheck(system, locus):
        \"\"\"Each rational witness again, by a direct exact analysis (irrational ones
        were checked by the engine over Q(alpha)); prints the first eight.\"\"\"
        kinds = {"rechecked directly": 0, "irrational, checked over Q(alpha)": 0,
                 "real points undecided": 0}
        for k, (c, row) in enumerate(zip(locus.components, locus.table(), strict=True)):
            if c.real_points == "undecided":     # no real witness found: not called real
                assert not c.real
                kind, said = "real points undecided", "real points: undecided"
            elif c.witness is None:
                assert c.witness_checked, c.condition.text
                kind, said = "irrational, checked over Q(alpha)", "irrational: over Q(alpha)"
            else:
                n = system.analyze(c.witness).numbers.as_dict()
                assert c.witness_checked and n == c.numbers, c.condition.text
                kind, said = "rechecked directly", f"Nm={n['Nm']} Nc={n['Nc']} Nr={n['Nr']}"
            kinds[kind] += 1
            if k < 8:
                print(f"{(row['witness'] or c.condition.text)[:58]:58} {said}")
        if len(locus.components) > 8:
            print(f"... all {len(locus.components)} agree: " + ", ".join(
                f"{n} {what}" for what, n in kinds.items() if n))
    """),
    md("""
    ## 1. Paper case 1, both angles free

    Two one-link arms, hard contacts (section 4.1 of the paper). Both joint angles are
    free; $L$ only scales the system, so the engine sets it to 1 (the report notes it).
    """),
    code("""
    case1 = coopkin_sym.load("paper-case1-hard")
    locus1 = case1.locus()
    print("free variables:", locus1.variables, "| fixed:", locus1.fixed)
    display(locus1)
    """),
    code("""
    GENERIC1 = {"Nm": 2, "Nc": 2, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 4, "Nh": 0}
    assert locus1.generic == GENERIC1            # the paper's numbers, now generic
    assert [c.condition.text for c in locus1.components] == [
        "q1 = -pi/2, q2 = -pi/2", "q1 = -pi/2, q2 = pi/2",
        "q1 = pi/2, q2 = -pi/2", "q1 = pi/2, q2 = pi/2",
        "q1 = -5*pi/6, q2 = 5*pi/6 or q1 = -pi/6, q2 = pi/6"]
    for c in locus1.components:
        assert c.kind == "isolated" and c.depth == 0 and c.real
    for c in locus1.components[:4]:
        assert c.numbers == dict(GENERIC1, Nm=3, Nc=3, Nh=1)
        assert c.changes == {"Nm": (2, 3), "Nc": (2, 3), "Nh": (0, 1)}
    coincident = locus1.components[4]
    assert coincident.numbers == dict(GENERIC1, Nm=3, Nc=3, Ni=3, Ng=3, Nh=1)
    assert [e.text for e in coincident.equations] == ["t_q1**2 + 4*t_q1 + 1", "t_q1 + t_q2"]
    for line in component_sentences(locus1.components[3]):
        print("-", line)
    """),
    md("""
    Four isolated configurations, $q_1, q_2 = \\pm\\pi/2$: both links lie on the line
    through the two contacts, and the object gains a rotation about $z$ ($N_m$ and
    $N_c$ go from 2 to 3, with one more internal force the joints cannot control,
    $N_h$). Notebook 01 saw two of them on the family $q_1 = q_2$; the locus finds
    exactly these four, and a fifth family at irrational tangents (below). In the
    $(q_1, q_2)$ plane:
    """),
    code("""
    png(locus1.plot(("q1", "q2")))
    """),
    md("""
    Each witness is an exact point; a direct exact analysis there (with nothing from
    the locus engine) gives the reported numbers, at $L = 1$ and with $L$ symbolic:
    """),
    code("""
    recheck(case1, locus1)
    for c in locus1.components[:4]:
        symbolic_L = {k: v for k, v in c.witness.items() if k != "L"}
        assert case1.analyze(symbolic_L).numbers.as_dict() == c.numbers
    """),
    md("""
    ### The report

    `locus.write` writes the report (Markdown here; also HTML, LaTeX, JSON) with a
    PNG per joint pair, everything rendered before anything is written. Its opening
    and its last sections:
    """),
    code("""
    out = Path(tempfile.mkdtemp()) / "case1_locus.md"
    print([p.name for p in locus1.write(out)])
    report = out.read_text()
    opening, *sections = report.split("\\n## ")
    keep = ("Dropped factors (no real points)", "Not explored")
    display(Markdown(opening.replace("# ", "#### ", 1) + "\\n\\n" + "\\n\\n".join(
        "#### " + s for s in sections if s.split("\\n", 1)[0] in keep)))
    assert "Nothing: the search finished within its bounds." in report
    assert remark_texts(locus1.dropped) == ["t_q1**2 + 1 = 0 (no real points)",
                                            "t_q2**2 + 1 = 0 (no real points)"]
    assert locus1.unexplored == []
    """),
    md("""
    **The fifth family: irrational, decided over $\\mathbb{Q}(\\sqrt 3)$.** Its
    equations $t_{q_1}^2 + 4 t_{q_1} + 1 = 0$, $t_{q_2} = -t_{q_1}$ have the real roots
    $t = -2 \\pm \\sqrt 3$, that is $q_1 = -\\pi/6$ or $-5\\pi/6$, with $q_2 = -q_1$:
    there the two contact points coincide. No point of it has a rational
    $\\tan(q/2)$, so the analysis over the rationals refuses it; the engine computes
    the ranks in $\\mathbb{Q}(\\alpha)$, $\\alpha^2 + 4\\alpha + 1 = 0$ (one computation
    for both conjugate points), and writes the witness exactly:
    """),
    code("""
    t = sp.Symbol("t")
    q1s = sorted(2 * sp.atan(r) for r in sp.solve(t**2 + 4 * t + 1, t))
    assert q1s == [-5 * sp.pi / 6, -sp.pi / 6]
    L = sp.Symbol("L", positive=True)
    for q1 in q1s:
        q2 = -q1
        c1 = sp.Matrix([-L * sp.sin(q1), L * sp.cos(q1), 0])      # (0, L, 0) turned by q1
        c2 = sp.Matrix([L - L * sp.sin(q2), L * sp.cos(q2), 0])   # (L, L, 0) about (L, 0, 0)
        assert c1 == c2
        print(f"q1 = {q1}, q2 = {q2}: c1 = c2 = {list(c1)}")
    try:
        case1.analyze("q1=-pi/6,q2=pi/6")
    except coopkin_sym.ConfigurationError as exc:
        print("direct analysis over Q:", exc)
    # a separate path (fresh kinematics, a primitive element of the field), the one
    # `coopkin analyze --at q1=-pi/6,q2=pi/6` takes
    again = case1.analyze("q1=-pi/6,q2=pi/6")
    print("over Q(alpha):", again.numbers.as_dict(), "| alpha =", again.alpha)
    assert again.numbers.as_dict() == coincident.numbers
    print("decided:", remark_text(coincident.decided))
    print("witness:", coincident.algebraic_witness["point"],
          "| alpha =", coincident.algebraic_witness["root"])
    assert coincident.algebraic_witness["point"] == {"q1": "-5*pi/6", "q2": "5*pi/6",
                                                     "L": "1"}
    assert coincident.witness is None and coincident.witness_checked
    """),
    md("""
    An independent check by hand: with $c_1 = c_2$ the hard contacts constrain only the
    velocity of one point, so
    $H G^T = \\begin{pmatrix} I & S(c)^T \\\\ I & S(c)^T \\end{pmatrix}$ has rank 3 and
    $N_i = 6 - 3 = 3$ (any rotation about the common point) instead of 1, as reported.
    Deciding such points in floating point, or skipping them because they have no
    rational coordinates, would make the report look complete when it is not.
    """),
    code("""
    def S(c):
        return sp.Matrix([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])


    c = sp.Matrix([L / 2, sp.sqrt(3) * L / 2, 0])               # the common point, q1 = -pi/6
    block = sp.eye(3).row_join(S(c).T)
    HGt = block.col_join(block)
    assert HGt.rank() == 3                                      # so Ni = 6 - 3 = 3
    assert coincident.numbers["Ni"] == 6 - HGt.rank()
    """),
    md("""
    ## 2. Where the recursion matters: two planar 2R fingers

    A constructed example: two fingers with two revolute joints about $z$ each (links of
    length $L$), bases at $(0, 0, 0)$ and $(3L, 0, 0)$, holding an object with hard
    contacts at the fingertips. At home both fingers point up along $y$.
    """),
    code("""
    TWO_FINGERS = {
        "name": "two planar 2R fingers", "parameters": ["L"],
        "arms": [
            {"name": "f1", "joints": [
                {"name": "a1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]},
                {"name": "a2", "type": "revolute", "axis": [0, 0, 1], "point": [0, "L", 0]}]},
            {"name": "f2", "joints": [
                {"name": "b1", "type": "revolute", "axis": [0, 0, 1], "point": ["3*L", 0, 0]},
                {"name": "b2", "type": "revolute", "axis": [0, 0, 1],
                 "point": ["3*L", "L", 0]}]}],
        "contacts": [
            {"name": "c1", "link": "f1/2", "point": [0, "2*L", 0], "normal": [1, 0, 0],
             "model": "hard"},
            {"name": "c2", "link": "f2/2", "point": ["3*L", "2*L", 0], "normal": [-1, 0, 0],
             "model": "hard"}]}
    fingers = coopkin_sym.load(TWO_FINGERS)
    locus2 = fingers.locus(max_depth=2)
    display(locus2)
    """),
    code("""
    assert locus2.generic == {"Nm": 4, "Nc": 4, "Ni": 1, "Nr": 0, "Ng": 1, "Nd": 2, "Nh": 0}
    by = {c.condition.text: c for c in locus2.components}
    index = {c.condition.text: k for k, c in enumerate(locus2.components)}
    straight = {"Nc": (4, 3), "Nr": (0, 1), "Nd": (2, 3)}
    for cond in ("a2 = 0", "b2 = 0"):                     # one finger straight
        assert by[cond].kind == "hypersurface" and by[cond].depth == 0
        assert by[cond].changes == straight
    both = by["a2 = 0, b2 = 0"]                           # both straight: codimension 2
    assert both.kind == "subvariety" and both.depth == 1 and both.parent == index["a2 = 0"]
    assert both.changes == {"Nc": (4, 2), "Nr": (0, 2), "Nd": (2, 4)}
    t_chart = [c for c in locus2.components              # every t = tan(q/2) finite
               if not any(e.text.startswith("s_") for e in c.equations)]
    deepest = [c for c in t_chart if c.depth == 2 and c.witness]  # on the line
    assert sorted(c.condition.text for c in deepest) == sorted(
        f"a2 = 0, b2 = 0, a1 = {a}, b1 = {b}" for a in ("pi/2", "-pi/2")
        for b in ("pi/2", "-pi/2"))
    for c in deepest:
        assert c.kind == "isolated" and c.parent == index["a2 = 0, b2 = 0"]
        assert c.changes == {"Nm": (4, 5), "Nc": (4, 3), "Nr": (0, 2), "Nd": (2, 4),
                             "Nh": (0, 1)}
    (together,) = [c for c in t_chart if c.depth == 0 and c.kind == "subvariety"]
    assert together.changes == {"Nm": (4, 5), "Nc": (4, 5), "Ni": (1, 3), "Ng": (1, 3),
                                "Nh": (0, 1)}
    assert together.witness_checked and len(together.equations) == 2
    (tips,) = [c for c in t_chart if c.depth == 2 and not c.witness]
    assert [e.text for e in tips.equations] == [
        "t_a2", "t_b2", "3*t_a1**2 + 8*t_a1 + 3", "t_a1 + t_b1"]
    assert tips.changes == {"Nm": (4, 5), "Nc": (4, 3), "Ni": (1, 3), "Nr": (0, 2),
                            "Ng": (1, 3), "Nd": (2, 4), "Nh": (0, 1)}
    charts = [c for c in locus2.components if c.kind == "chart"]  # q = pi: t infinite
    assert {c.condition.text: [e.text for e in c.equations] for c in charts} == {
        "a2 = pi": ["s_a2"], "b2 = pi": ["s_b2"], "a2 = pi, b2 = pi": ["s_a2", "s_b2"]}
    assert [c.changes for c in charts] == [straight, straight, both.changes]
    mixed = by["a2 = pi, b2 = 0"]                         # one folded, one straight
    assert mixed.changes == both.changes and mixed.parent == index["a2 = pi"]
    recheck(fingers, locus2)
    """),
    md("""
    Read the table from the top:

    * **One finger straight** ($a_2 = 0$ or $b_2 = 0$, hypersurfaces): the fingertip
      cannot move along the finger. The object loses a direction ($N_c$ 4 to 3) and the
      finger gains a self-motion that keeps its tip still to first order ($N_r$ 0 to 1:
      joints in the ratio $a_1 : a_2 = 1 : -2$).
    * **Both straight** ($a_2 = b_2 = 0$, codimension 2): not a component of the generic
      locus, so a one-level search reports only the two hypersurfaces. The engine
      finds it by recursing inside $a_2 = 0$: there the numbers are computed over the
      component's own function field and $b_2$ drops them again ($N_c$ 2, $N_r$ 2).
    * **Both straight along the contact line** ($a_1, b_1 = \\pm\\pi/2$ inside that,
      depth 2): the object gains a rotation about $z$ as in case 1 ($N_m$ 4 to 5).
    * **The fingertips at one point** (a two-dimensional family, codimension 2 in four
      variables and inside no hypersurface): found by solving two angles over the
      field of the other two (a resultant, then a gcd over the family's function
      field); its witness is irrational. The two point contacts act as a spherical
      joint: $N_i$ 1 to 3, and the object gains a direction ($N_c$ 4 to 5).
    * **Both straight with the tips at one point** (depth 2, irrational):
      $b_1 = -a_1$ and $\\sin a_1 = -3/4$, that is $3t^2 + 8t + 3 = 0$ for
      $t = \\tan(a_1/2)$; decided over $\\mathbb{Q}(\\sqrt 7)$. As in case 1 the two
      point contacts act as one spherical joint ($N_i$ 1 to 3).
    * **Folded back** ($a_2 = \\pi$ or $b_2 = \\pi$), where $t = \\tan(q/2)$ is infinite:
      every set of joints at $\\pi$ is a system of its own, written with
      $s = \\cot(q/2) = 0$ and searched like the $t$ chart. Folded back acts as
      straight: one finger ($N_r$ 0 to 1), both, or one folded and the other straight
      ($N_r$ 0 to 2), and inside those the same points on the contact line.
    """),
    md("""
    In the $(a_2, b_2)$ plane the hypersurfaces are lines (the folded-back ones at
    $\\pm\\pi$, one angle drawn twice) and the deeper components all sit at $(0, 0)$
    (the $(a_1, b_1)$ plane of the report separates the four depth-2 points):
    """),
    code("""
    png(locus2.plot(("a2", "b2")))
    """),
    md("""
    The system at the witness of the component $a_2 = b_2 = 0$, $a_1 = b_1 = -\\pi/2$:
    both fingers straight and along the line through the contacts (the numbers in the
    title come from a fresh exact analysis):
    """),
    code("""
    witness = by["a2 = 0, b2 = 0, a1 = -pi/2, b1 = -pi/2"].witness
    assert witness == {"a1": "-pi/2", "a2": "0", "b1": "-pi/2", "b2": "0", "L": "1"}
    draw(fingers, at=witness)
    """),
    code("""
    said = coopkin_sym.grouped_remark_texts(locus2.unexplored)
    print(f"{len(said)} item{'' if len(said) == 1 else 's'} not explored")
    for item in said:
        print("-", item if len(item) < 160 else item[:160] + " ...")
    assert all(any(words in item for words in ("not solved", "not explored",
                                               "not searched"))
               for item in remark_texts(locus2.unexplored))
    """),
    md("""
    Here the search left nothing out. Two components found in the t chart meet the
    slices a1 = pi and b1 = pi: the sets they hold there are not recorded again, but
    they are searched inside in those slices too. Inside each curved family, a minor
    that cuts out a deeper set is solved factor by factor. Where the search leaves
    something out, the report lists it (section 3 has such items): families where one
    angle does not determine the other (two values share each point), blocks whose
    equations in four variables are too large to solve with parameters, curved
    families inside which it did not search for deeper drops, candidate sets with the
    enclosing numbers that it did not search inside, and sets at q = pi held by a
    component of another chart once the work budget of those searches is spent.

    ## 3. Paper case 2, all eight joints free

    Two SCARA-type robots with hard contacts (section 4.2): six revolute and two
    prismatic joints, all free. One level of recursion. With this many components the
    display says first the *families*: the components grouped by the numbers that
    change (one kind of singular configuration each, wherever the search met it), in
    words, each with an example and its witness; the table of components is folded
    under it.
    """),
    code("""
    case2 = coopkin_sym.load("paper-case2-hard")
    locus3 = case2.locus(max_depth=1)
    print(f"{len(locus3.variables)} variables: {', '.join(locus3.variables)}; "
          f"computed in {locus3.seconds:.2f} s")
    display(locus3)
    """),
    code("""
    assert locus3.generic == {"Nm": 8, "Nc": 6, "Ni": 1, "Nr": 2, "Ng": 1, "Nd": 0, "Nh": 0}
    t_chart3 = [c for c in locus3.components
                if not any(e.text.startswith("s_") for e in c.equations)]
    elbow = [c for c in t_chart3 if c.kind == "hypersurface"]
    assert [c.condition.text for c in elbow] == ["q2 = -pi/2", "q2 = pi/2"]
    for c in elbow:
        assert [e.text for e in c.equations] in (["t_q2 + 1"], ["t_q2 - 1"])
        assert c.changes == {"Nc": (6, 5), "Nr": (2, 3), "Nd": (0, 1)}
        print(c.condition.text, "->", component_sentences(c)[1])
    one = {"Nc": (6, 5), "Nr": (2, 3), "Nd": (0, 1)}
    in_line = [c for c in t_chart3 if c.depth == 0 and c.kind == "subvariety"
               and c.changes == one]
    assert [[e.text for e in c.equations] for c in in_line] == [
        ["t_q8**2 + 2*t_q8 - 1", "t_q7 + 1"], ["t_q8**2 + 2*t_q8 - 1", "t_q7 - 1"]]
    for c in in_line:
        print(c.condition.text)
    meet = [c for c in t_chart3 if c.depth == 0 and c.changes != one]
    assert meet and all(c.changes == {"Ni": (1, 3), "Ng": (1, 3)} for c in meet)
    print("contact points meeting:", len(meet[0].equations), "equations, e.g. at",
          locus3.table()[locus3.components.index(meet[0])]["witness"])
    both = [c for c in t_chart3 if c.depth == 1]
    two = {"Nc": (6, 4), "Nr": (2, 4), "Nd": (0, 2)}
    elbow_meet = {"Nc": (6, 5), "Ni": (1, 3), "Nr": (2, 3), "Ng": (1, 3), "Nd": (0, 1)}
    found = sorted(str(c.changes) for c in both)
    assert all(found.count(str(k)) == n for k, n in ((two, 4), (elbow_meet, 2)))
    deeper = [c for c in both if c.changes not in (two, elbow_meet)]
    for c in deeper:   # more inside q2 = +-pi/2, real points not decided
        assert c.equations[0].text in ("t_q2 + 1", "t_q2 - 1") and c.numbers["Ni"] == 3
        print("deeper:", c.changes, "real points:", c.real_points)
    at_pi = [c for c in locus3.components if c not in t_chart3]   # joints at pi
    assert not any(c.kind == "chart" for c in at_pi)
    assert all(c.changes in [d.changes for d in t_chart3]
               or (c.real_points == "undecided" and not c.real) for c in at_pi)
    families = locus3.families()
    assert sorted(k for f in families for k in f.members) == list(range(len(locus3.components)))
    assert [f.changes for f in families][:2] == [one, two]
    recheck(case2, locus3)
    """),
    md("""
    The hypersurfaces are the elbow of robot `s1` straight ($q_2 = \\pi/2$, the
    link q2-q3 in line with the link q1-q2) or folded back ($q_2 = -\\pi/2$, the axes
    of q1 and q3 coincide). Either way the axes of q1, q2, q3 meet the horizontal
    plane in three points on a line, and the contact (on the axis of q3) cannot be
    moved along that line: the object loses a direction ($N_c$ 6 to 5) and the arm
    gains a self-motion ($N_r$ 2 to 3).

    Robot `s2` works in the plane $x = $ const with three axes along $x$, and its
    contact is *not* on its last axis, so it needs two conditions to line up: the axes
    of q6, q7, q8 in line ($q_7 = \\pm\\pi/2$) and the contact on that line too
    ($q_8 = \\pi/4$ or $-3\\pi/4$, where $\\tan(q_8/2) = -1 \\pm \\sqrt 2$ is irrational).
    These codimension-2 families are decided over $\\mathbb{Q}(\\sqrt 2)$, with the same
    changes as for `s1`; inside $q_2 = \\pm\\pi/2$ both robots are singular at once
    ($N_c$ 6 to 4, $N_r$ 2 to 4).

    Where the two contact points meet ($c_1 = c_2$: three equations, codimension 3),
    the object can turn about that point in every direction with every joint locked
    ($N_i$ 1 to 3). The search finds it inside the zero set of one minor of
    $H G^T$: one equation linear in $q_5$ (the $x$ coordinates agree), one linear in
    $q_4$ (the heights agree), and a curve ($y$). Inside $q_2 = \\pm\\pi/2$ it meets
    the elbow family. The same family is also listed in pieces found along other paths
    (with the same numbers). Deeper inside $q_2 = -\\pi/2$ the search also finds a
    family where the object gains two motions ($N_m$ 8 to 10); no real point of it was
    found, so the report calls its real points undecided rather than real.

    No set of joints at $\\pi$ changes a number by itself; what the search finds there
    is the same robot in line with another joint turned half a turn (listed with
    $s_q = \\cot(q/2) = 0$ where the $t$ chart's equations involve that joint).
    """),
    md("""
    In the plot the components are coloured by family (a legend entry per family):
    """),
    code("""
    png(locus3.plot(("q1", "q2")))
    """),
    code("""
    unexplored = remark_texts(locus3.unexplored)
    said = coopkin_sym.grouped_remark_texts(locus3.unexplored)
    print(f"{len(unexplored)} items not explored, said in {len(said)} sentences, e.g.:")
    for item in said[:4]:
        print("-", item if len(item) < 160 else item[:160] + " ...")
    assert len(said) < len(unexplored) // 4
    assert sum("not solved" in u for u in unexplored) >= 3
    assert all(any(words in u for words in ("not solved", "not explored", "not searched",
                                            "not decided"))
               for u in unexplored)
    assert sorted(2 * sp.atan(r) for r in sp.solve(t**2 + 2 * t - 1, t)) == [
        -3 * sp.pi / 4, sp.pi / 4]
    """),
    md("""
    So the report does not claim these families are the whole locus. It says which
    drop sets of codimension 2 or more were not solved (equations in too many
    variables), where the numbers of real points were not decided (two values of one
    variable over each point), and that inside the families at irrational angles (and
    at the depth bound) it did not search deeper. A reader gets the boundary of what
    was checked along with the result; `--certify` then says whether the whole is
    proved complete.

    Notebook 04 (section 4) compares these loci with what floating-point rank tests
    say at and near every witness.
    """),
]


# ---------------------------------------------------------------------------- 04

NB04 = [
    md("""
    # Exact versus floating-point rank tests

    Mobility numbers are ranks. A floating-point rank test (an SVD with a tolerance,
    e.g. `numpy.linalg.matrix_rank`) decides whether a small singular value is zero,
    and near a singular configuration, or when lengths have very different scales, it
    decides wrongly. `coopkin_sym` never decides a rank in floating point: at a
    configuration with exact (rational) data the answer is exact, whatever the scale.

    In this notebook floats appear only where marked: the float baselines we compare
    with, the numerical integration of section 3, the float rank tests along the loci
    of section 4 and the plots.
    """),
    code("""
    import math
    from fractions import Fraction

    import matplotlib.pyplot as plt  # float-ok: plots
    import numpy as np  # float-ok: the float baselines
    import sympy as sp
    from IPython.display import Markdown, display

    import coopkin_sym

    plt.rcParams["figure.dpi"] = 80  # pictures of modest size


    def float_nm(analysis, tol=None):  # float-ok
        \"\"\"Nm decided the usual way: numpy's SVD rank of the float Q.\"\"\"
        q = np.array(analysis.Q.tolist(), dtype=float)                # float-ok
        return 6 + analysis.r - int(np.linalg.matrix_rank(q, tol=tol))  # float-ok


    def table(header, rows):
        lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
        lines += ["| " + " | ".join(str(x) for x in row) + " |" for row in rows]
        return Markdown("\\n".join(lines))
    """),
    md("""
    ## 1. Near a singular configuration, at different scales

    Paper case 1 with hard fingers: $N_m = 2$ everywhere on the family $q_1 = q_2$
    except at $q_1 = q_2 = -\\pi/2$ (both links on the contact line), where $N_m = 3$
    (notebook 01). Approach that configuration along exact angles
    $q = 2\\arctan(-1 + \\varepsilon)$, $\\varepsilon = 10^{-k}$ (the angle is then within
    about $\\varepsilon$ of $-\\pi/2$), with the length $L$ given in three units. Columns:
    the exact $N_m$, and $N_m$ from numpy's rank with its default tolerance and with a
    fixed tolerance $10^{-9}$.
    """),
    code("""
    case1 = coopkin_sym.load("paper-case1-hard")
    rows, results = [], {}
    for length in ["1/1000", "1", "1000"]:
        for k in [3, 6, 9, 12, 15, None]:
            eps = sp.Rational(1, 10**k) if k is not None else 0
            q = f"2*atan({-1 + eps})"
            a = case1.analyze({"q1": q, "q2": q, "L": length})
            found = (a.numbers.Nm, float_nm(a), float_nm(a, tol=1e-9))  # float-ok
            results[length, k] = found
            rows.append((f"L = {length}", f"1e-{k}" if k else "0 (singular)", *found))
    display(table(["length", "ε", "exact Nm", "numpy default", "numpy tol=1e-9"], rows))
    """),
    code("""
    # exact: 2 at every distance, 3 exactly at the singular configuration, for every unit
    for (_, k), (exact, _, _) in results.items():
        assert exact == (3 if k is None else 2)
    # float: the same configuration gets a different answer in millimetres and metres
    assert results["1/1000", 12][1] == 3 and results["1000", 12][1] == 2
    assert results["1", 15][1] == 3 and results["1/1000", 6][2] == 3
    """),
    md("""
    Read the table: with $L$ = 1/1000 numpy's default test calls the configuration
    singular ($N_m = 3$) at $\\varepsilon = 10^{-12}$, where the exact answer is 2; with
    $L$ = 1000 the same configuration is (correctly) regular. A fixed tolerance is worse:
    $10^{-9}$ already fails at $\\varepsilon = 10^{-6}$ when $L$ = 1/1000. The smallest
    singular value of $Q$ is proportional to $L\\varepsilon$, so any float test has a
    scale-dependent blind zone; the exact test has none.

    ## 2. Two lengths of very different scale

    A variant of case 1 where the links are short ($l$) and the joints far apart ($d$):
    contacts at $(0, l, 0)$ and $(d, l, 0)$. The singular configuration is again
    $q_1 = q_2 = -\\pi/2$. With $l$ = 1/1000 and $d$ = 1000 in one system, numpy's
    default test is wrong already at distance $10^{-10}$:
    """),
    code("""
    model = {
        "name": "short links far apart", "parameters": ["l", "d"],
        "arms": [
            {"name": "a1", "joints": [{"name": "q1", "type": "revolute", "axis": [0, 0, 1],
                                       "point": [0, 0, 0]}]},
            {"name": "a2", "joints": [{"name": "q2", "type": "revolute", "axis": [0, 0, 1],
                                       "point": ["d", 0, 0]}]},
        ],
        "contacts": [
            {"name": "c1", "link": "a1/1", "point": [0, "l", 0], "normal": [1, 0, 0],
             "model": "hard"},
            {"name": "c2", "link": "a2/1", "point": ["d", "l", 0], "normal": [-1, 0, 0],
             "model": "hard"},
        ],
    }
    scales = coopkin_sym.load(model)
    rows, results = [], {}
    for k in [3, 6, 8, 10, 12, None]:
        eps = sp.Rational(1, 10**k) if k is not None else 0
        q = f"2*atan({-1 + eps})"
        a = scales.analyze({"q1": q, "q2": q, "l": "1/1000", "d": 1000})
        symbolic = scales.analyze({"q1": q, "q2": q})      # l and d left symbolic
        results[k] = (a.numbers.Nm, float_nm(a), symbolic.numbers.Nm)  # float-ok
        rows.append((f"1e-{k}" if k else "0 (singular)", *results[k]))
    display(table(["ε", "exact Nm (l=1/1000, d=1000)", "numpy default",
                   "exact Nm, l and d symbolic"], rows))
    """),
    code("""
    for k, (exact, _, symbolic) in results.items():
        assert exact == symbolic == (3 if k is None else 2)
    assert results[10][1] == 3 and results[12][1] == 3     # float: wrong
    assert results[3][1] == 2                              # float: right far away
    """),
    md("""
    The last column is computed with $l$ and $d$ left as symbols: the exact engine
    works over the field of rational functions in $l, d$ and finds $N_m = 2$ for
    almost all lengths, and 3 at the singular angle; no scale can fool it.

    ## 3. Resolved-rate control with the exact kinematic maps

    The paper proposes the maps (10)-(12) for resolved-rate control. Take case study 2
    with complete-constraint grips ($N_i = N_r = 0$: eq. (10) is one-to-one): ask the
    object to translate with velocity $v = (1/2, 1/4, 1/4)$ (in $R(C_{12})$: the object
    can only translate) and at each step get the joint rates exactly from
    `Analysis.joint_velocities`. The configuration is integrated with small midpoint
    steps in floating point (labelled); wherever rates are needed the float state is
    rounded to the nearest exact configuration (rational $\\tan(q/2)$), the exact
    analysis runs there and we check $Q\\,(\\dot u, \\dot q) = 0$ exactly: the rates keep
    every contact.
    """),
    code("""
    system = coopkin_sym.load("paper-case2-complete")
    joints = system.model.joints
    u = [sp.Rational(1, 2), sp.Rational(1, 4), sp.Rational(1, 4), 0, 0, 0]


    def exact_configuration(q):  # float-ok: rounds the float state to exact values
        at = {"L": 1}
        for joint, value in zip(joints, q, strict=True):
            if joint.type == "revolute":
                t = Fraction(math.tan(value / 2)).limit_denominator(10**6)  # float-ok
                at[joint.name] = f"2*atan({t})"
            else:
                at[joint.name] = str(Fraction(value).limit_denominator(10**6))  # float-ok
        return at


    def exact_rates(q):
        \"\"\"Exact rates for u at the exact configuration nearest q; checks Q (u, qdot) = 0.\"\"\"
        a = system.analyze(exact_configuration(q))
        qdot = a.joint_velocities(u).particular                   # eq. (10), exact
        kept.append(a.Q * sp.Matrix([*u, *qdot]) == sp.zeros(a.m, 1))
        points = [[float(x) for x in p]                             # float-ok
                  for p in coopkin_sym.contact_points(a)]
        return np.array([float(x) for x in qdot]), points         # float-ok


    h, steps = 0.05, 24                 # float-ok: the integration (midpoint rule)
    q = np.zeros(len(joints))           # float-ok: start at home
    path, rates, kept = [], [], []
    for _ in range(steps):
        qdot, points = exact_rates(q)
        path.append(points)
        rates.append(qdot)
        qdot_mid, _ = exact_rates(q + h / 2 * qdot)               # float-ok
        q = q + h * qdot_mid                                      # float-ok
    path.append(exact_rates(q)[1])
    assert all(kept)
    print(f"{len(kept)} exact analyses, Q (u, qdot) = 0 exactly at every one of them")
    """),
    code("""
    path = np.array(path)               # float-ok: (step, contact, xyz)
    gap = path[:, 1, :] - path[:, 0, :]  # float-ok: c2 - c1 should stay (2L, 0, 0)
    drift = np.abs(gap - [2, 0, 0]).max()                         # float-ok
    moved = path[-1, 0, :] - path[0, 0, :]                         # float-ok
    print("largest change of c2 - c1 (float, from the integration):", f"{drift:.2e}")
    asked = np.array([float(x) for x in u[:3]]) * h * steps      # float-ok
    print("c1 moved by", np.round(moved, 5), "; asked", np.round(asked, 5))
    assert drift < 1e-3 and np.abs(moved - asked).max() < 1e-3    # float-ok

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))     # float-ok: plots
    t = h * np.arange(steps + 1)                                  # float-ok
    for i, name in enumerate(["c1", "c2"]):
        for axis, style in zip("xyz", ["-", "--", ":"], strict=True):
            left.plot(t, path[:, i, "xyz".index(axis)], style, label=f"{name} {axis}")
    left.set(title="contact points (float integration)", xlabel="time")
    left.legend(fontsize=7, ncol=2)
    for j, joint in enumerate(joints):
        right.plot(t[:-1], np.array(rates)[:, j], label=joint.name)  # float-ok
    right.set(title="exact joint rates at each step (plotted as floats)", xlabel="time")
    right.legend(fontsize=7, ncol=2)
    plt.show()
    """),
    md("""
    Both contact points move with the commanded velocity and keep their distance (the
    small drift is the integration's, not the rates'). A velocity outside the
    feasible subspace, such as a rotation, is refused exactly:
    """),
    code("""
    try:
        system.analyze().joint_velocities([0, 0, 0, 1, 0, 0])
    except coopkin_sym.InfeasibleMotion as exc:
        print("rotation about x:", exc)
    else:
        raise AssertionError("a rotation should break a complete-constraint contact")
    """),
    md("""
    ## 4. Along a whole singularity locus

    At and near every witness (at 1e-6, 1e-9 and 1e-12 rad on one joint, with the
    lengths at 1, 1/1000 and 1000) the engine also computes the numbers the usual way,
    with numpy's `matrix_rank` at its default tolerance, and compares them with the
    exact ones. The loci of notebook 03: paper case 1, the planar two-finger grasp, and
    paper case 2 with every joint free (one level of recursion):
    """),
    code("""
    loci = {"paper case 1": coopkin_sym.load("paper-case1-hard").locus(),
            "two fingers": coopkin_sym.load("planar-two-fingers").locus(),
            "paper case 2": coopkin_sym.load("paper-case2-hard").locus(max_depth=1)}
    rows = ["| system | tests | disagree | missed singular | regular called singular |",
            "|---|---|---|---|---|"]
    for name, locus in loci.items():
        checks = [f for c in locus.components for f in c.float_checks]
        s = locus.float_summary()
        rows.append(f"| {name} | {len(checks)} | {sum(not f.agree for f in checks)} | "
                    f"{s['missed_singular']} | {s['false_singular']} |")
    display(Markdown("\\n".join(rows)))
    print({name: locus.float_summary() for name, locus in loci.items()})
    """),
    code("""
    rows = ["| system | near | lengths | distance | exact Nm | float Nm |",
            "|---|---|---|---|---|---|"]
    for name, locus in loci.items():
        shown = 0
        for c in locus.components:
            for f in c.float_checks:
                if not f.agree and not shown:      # the first of each system
                    shown += 1
                    rows.append(f"| {name} | `{c.condition.text}` | {f.scale} | "
                                f"{f.distance:.0e} rad | {f.exact['Nm']} | {f.float['Nm']} |")
    display(Markdown("\\n".join(rows)))

    wrong = as_component = at_point = unit_lengths = 0
    for locus in loci.values():
        for c in locus.components:
            for f in c.float_checks:
                if f.agree:
                    continue
                if f.scale not in ("L=1/1000", "L=1000"):
                    # with L = 1: off the component (up to 1e-6 rad), where exactly
                    # the numbers are its parent's or the generic ones
                    parent = locus.generic if c.parent is None else \\
                        locus.components[c.parent].numbers
                    assert f.distance > 0 and f.exact in (parent, locus.generic)
                    unit_lengths += 1
                    continue
                if f.distance == 0:                                    # float-ok
                    # on the component itself: the contact points meeting, seen by
                    # numpy as apart (Ni too low)
                    assert "Ni" in c.changes and f.float["Ni"] < f.exact["Ni"]
                    at_point += 1
                    continue
                assert 0 < f.distance <= 1e-6                          # float-ok
                # exactly: off the component, in its parent (or regular)
                parent = locus.generic if c.parent is None else \\
                    locus.components[c.parent].numbers
                assert f.exact in (parent, locus.generic)
                wrong += 1
                as_component += f.float == c.numbers   # numpy: "on the component"
    print({"at a point of the family": at_point, "off a component": wrong,
           "of which given the component's numbers": as_component,
           "with L = 1": unit_lengths})
    """),
    md("""
    Almost every disagreement comes with the lengths rescaled to 1/1000 or 1000, and is
    of one of two kinds (the counts are printed above). Numpy is *at* an exact point
    of a family where the two contact points of case 2 meet, and sees them apart: it
    misses the singularity itself ($N_i$ too low). Or it is slightly off a
    component ($10^{-12}$ rad mostly, up to $10^{-6}$ beside one where a rank falls
    slowly) (moving a joint of its last equation, so the point stays in the
    enclosing component, or leaves it too), and mostly gives the numbers of the
    component it has just left, sometimes numbers that belong to neither. Some happen
    with $L = 1$ too: beside components found in the slices at $q = \\pi$ (of $q_1$,
    $q_2$, $q_3$, $q_2$ and $q_6$ together), numpy still sees a rank drop from
    $10^{-12}$ up to $10^{-6}$ rad away, where exactly there is none. In
    case 1 it calls regular configurations singular; for the fingers and inside case
    2's hypersurfaces it gives configurations of a singular family the numbers of a
    deeper family next to them
    (counted as missed: a singular configuration given the wrong numbers).

    For a float-based tool this means that its locus is a band of unknown width around
    the true one, and the width depends on the unit of length: the same configuration
    is singular in millimetres and regular in metres, and nothing in the output says
    which answer is wrong. A difference of $10^{-12}$ rad is physically negligible, but
    it shows that such a tool cannot certify any configuration near the locus, in
    either direction. The exact components of the loci have no tolerance: they are where
    they are at every scale, and every reported number was re-derived at an exact
    witness.
    """),
]


# ---------------------------------------------------------------------------- 05

NB05 = [
    md("""
    # Passive joints: what the motors control

    A joint marked `actuated: false` in a model file has no motor: it moves as the
    contacts and the other joints let it. Underactuated fingers have such joints, and
    so has every closed-chain mechanism (the passive joints of a parallel robot).
    Bicchi and Prattichizzo, *Manipulability of cooperating robots with unactuated
    joints and closed-chain mechanisms* (IEEE T-RA 2000), analyze these systems by
    splitting the joint velocities into actuated ones $\\dot q_a$ and passive ones
    $\\dot q_p$. We do not reproduce that paper's equation numbers: the definitions
    below follow from the kinematic relation alone,

    $$\\tilde G^T \\dot u - \\tilde D_p \\dot q_p = \\tilde D_a \\dot q_a, \\qquad (1)$$

    with $\\tilde G^T = H G^T$, $\\tilde D = H D = (\\tilde D_a \\mid \\tilde D_p)$ split by
    columns (the matrices of notebook 01). With the motors held still ($\\dot q_a = 0$),
    (1) is the analysis of the *locked system*. The numbers:

    * $N_a$, $N_p$: actuated and passive joints;
    * $N_{uo}$ **uncontrolled** object motions: possible with every motor still, the
      object part of $N(\\tilde G^T \\mid -\\tilde D_p)$;
    * $N_{pi}$ **internal passive** motions: passive joints moving with the object and
      the motors still, $\\dim N(\\tilde D_p)$;
    * $N_{co} = N_c - N_{uo}$ **controlled** object motions: what the motors drive;
    * $N_{ar} = N_r - N_{pi}$ **actuated redundant** motions: motor motions that leave
      the object still (the passive joints following);
    * $N_{am} = N_{co} + N_{ar}$, the **actuated mobility**: independent motor
      velocities the contacts admit.

    With every joint actuated, $N_{uo} = N_i$, $N_{pi} = 0$: the numbers of the 1992
    paper. Everything below is exact; floats appear only in the pictures.
    """),
    SETUP,
    code("""
    from fractions import Fraction

    from coopkin_sym import PASSIVE_NUMBER_NAMES


    def passive_table(rows):
        \"\"\"A Markdown table of (label, PassiveNumbers) pairs.\"\"\"
        head = ("| | " + " | ".join(PASSIVE_NUMBER_NAMES) + " |\\n"
                + "|---" * (len(PASSIVE_NUMBER_NAMES) + 1) + "|\\n")
        body = "".join(f"| {label} | " + " | ".join(str(v) for v in n.as_dict().values())
                       + " |\\n" for label, n in rows)
        return Markdown(head + body)


    def show_passive(p):
        \"\"\"The four subspaces of a passive analysis.\"\"\"
        display(Math(named_latex(r"\\text{controlled}", p.controlled)))
        display(Math(named_latex(r"\\text{uncontrolled}", p.uncontrolled)))
        display(Math(named_latex(r"\\text{internal passive}", p.internal)))
        display(Math(named_latex(r"\\text{actuated redundant}", p.actuated_redundant)))


    def from_q(a):
        \"\"\"The passive numbers again, from Q alone with plain SymPy: its columns split
        into object, actuated and passive blocks, ranks and nullspaces by the definitions
        at the top of this notebook.\"\"\"
        q = sp.Matrix(a.Q)
        joints = a.model.joints
        d = q.cols - len(joints)
        rows = list(range(q.rows))
        obj = list(range(d))
        act = [d + k for k, j in enumerate(joints) if j.actuated]
        pas = [d + k for k, j in enumerate(joints) if not j.actuated]

        def rank(cols):
            return q.extract(rows, cols).rank() if cols else 0

        nm = q.cols - q.rank()
        nr = len(joints) - rank(act + pas)
        nc = nm - nr
        locked = q.extract(rows, obj + pas).nullspace()      # motors still
        free = [v[:d, :] for v in locked]
        nuo = sp.Matrix.hstack(*free).rank() if free else 0
        npi = len(pas) - rank(pas)
        # Nam directly: the motor velocities of N(Q), independent ones
        motors = [v.extract(act, [0]) for v in q.nullspace()]
        nam = sp.Matrix.hstack(*motors).rank() if motors else 0
        assert nam == (nc - nuo) + (nr - npi)
        numbers = {"Na": len(act), "Np": len(pas), "Nco": nc - nuo, "Nuo": nuo,
                   "Npi": npi, "Nar": nr - npi, "Nam": nam}
        return numbers, free


    def check_against_q(a):
        \"\"\"Asserts that the engine's passive numbers and uncontrolled motions are those
        of from_q.\"\"\"
        numbers, free = from_q(a)
        p = a.passive
        assert p.numbers.as_dict() == numbers, (p.numbers, numbers)
        if free:
            assert same_span(p.uncontrolled, sp.Matrix.hstack(*free))
        return numbers
    """),
    md("""
    ## 1. An underactuated finger

    The shipped example `underactuated-finger`: a planar finger with two phalanges, a
    motor at the proximal joint q1 and a passive distal joint q2, touching the object
    with both phalanges (hard contacts: points with friction), and a one-link thumb
    (motor q3) whose pad touches the object without friction. The file's header says
    what to expect and why:
    """),
    code("""
    print(example_path("underactuated-finger").read_text())
    finger = coopkin_sym.load("underactuated-finger")
    L = finger.model.parameters[0]
    a = finger.analyze()                      # home, L symbolic
    display(numbers_table([("home", a.numbers)]))
    display(passive_table([("home", a.passive.numbers)]))
    show_passive(a.passive)
    for line in sentences(a):
        print("-", line)
    """),
    code("""
    assert a.numbers.as_dict() == {"Nm": 1, "Nc": 1, "Ni": 0, "Nr": 0, "Ng": 2, "Nd": 2,
                                   "Nh": 0}
    p = a.passive
    assert p.actuated == ("q1", "q3") and p.passive == ("q2",)
    assert p.numbers.as_dict() == {"Na": 2, "Np": 1, "Nco": 1, "Nuo": 0, "Npi": 0,
                                   "Nar": 0, "Nam": 1}
    assert same_span(p.controlled, sp.Matrix([0, 0, 1]))   # a turn about the base (0, 0)
    # that turn: the object and q1 at rate 1, q2 still, the thumb at rate 1
    assert (a.Q * sp.Matrix([0, 0, 1, 1, 0, 1])).is_zero_matrix
    generic = finger.analyze(generic=True)
    assert generic.numbers == a.numbers and generic.passive.numbers == p.numbers
    """),
    md("""
    **Reading.** The inner contact $(0, L)$, the distal joint $(0, 2L)$ and the
    fingertip $(L, 2L)$ make a triangle of the object and the two phalanges (both
    contacts hold the contact point's velocity): the passive joint cannot turn on its
    own ($N_{pi} = 0$), and with the motors still nothing moves ($N_{uo} = 0$). The one
    object motion the contacts allow is a turn of the object with the proximal phalanx
    about the finger's base, the thumb following at the same rate while its pad slides:
    the motors control it ($N_{co} = N_{am} = 1$). The generic analysis ($q_1, q_2, q_3$
    and $L$ symbolic) gives the same numbers, so home is a generic configuration.

    ### The same numbers from Q alone

    An independent check with plain SymPy: take $Q$, split its columns into the object
    block, the actuated and the passive joints, and compute ranks and nullspaces by the
    definitions above. `from_q` does not use the engine's decomposition:
    """),
    code("""
    display(Math(named_latex("Q", a.Q)))
    numbers = check_against_q(a)
    print(numbers)
    assert numbers["Nuo"] == 0 and numbers["Npi"] == 0 and numbers["Nco"] == 1
    """),
    md("""
    ### Where the distal phalanx lines up

    With the finger straight ($q_2 = \\pi/2$) the three points of the triangle are on
    one line, and the object may also turn about the inner contact with the distal
    phalanx following. With the thumb at home its pad's normal is the horizontal line
    through the inner contact: that turn moves the pad along its face, so it needs no
    motor. Slightly further on ($q_1 = 2\\arctan(1/2)$) the normal misses the inner
    contact and the thumb must push: both motions are controlled. Folded back
    ($q_2 = -\\pi/2$) the fingertip lies on the inner contact.
    """),
    code("""
    places = {"straight": "q2=pi/2", "straight, q1 turned": "q1=2*atan(1/2),q2=pi/2",
              "folded": "q2=-pi/2"}
    lined = {name: finger.analyze(at) for name, at in places.items()}
    display(numbers_table([("home", a.numbers)]
                          + [(f"{k}: `{places[k]}`", v.numbers) for k, v in lined.items()]))
    display(passive_table([("home", a.passive.numbers)]
                          + [(f"{k}: `{places[k]}`", v.passive.numbers)
                             for k, v in lined.items()]))
    show_passive(lined["straight"].passive)
    """),
    code("""
    straight = lined["straight"]
    assert straight.numbers.as_dict() == {"Nm": 2, "Nc": 2, "Ni": 0, "Nr": 0, "Ng": 2,
                                          "Nd": 2, "Nh": 1}
    ps = straight.passive.numbers
    assert (ps.Nco, ps.Nuo, ps.Npi, ps.Nar, ps.Nam) == (1, 1, 0, 0, 1)
    # the uncontrolled motion: the object spins about the inner contact (0, L) ...
    assert straight.passive.uncontrolled == sp.Matrix([L, 0, 1])
    # ... with q2 at twice its rate and both motors still
    assert (straight.Q * sp.Matrix([L, 0, 1, 0, 2, 0])).is_zero_matrix
    pt = lined["straight, q1 turned"].passive.numbers
    assert (pt.Nco, pt.Nuo, pt.Nam) == (2, 0, 2)
    pf = lined["folded"]
    assert (pf.numbers.Ni, pf.passive.numbers.Nuo, pf.passive.numbers.Nco) == (1, 1, 1)
    for an in lined.values():
        check_against_q(an)
    """),
    md("""
    The finger at home turning the object (the coordinated motion), and straight:
    """),
    code("""
    draw(finger.analyze("L=1"), motion=("coordinated", 1),
                title="underactuated finger at home")
    """),
    code("""
    draw(finger.analyze("q2=pi/2,L=1"), motion=("coordinated", 1),
                title="underactuated finger, straight (q2 = pi/2)")
    """),
    md("""
    ### Where the passive numbers change: the locus, motors locked

    With the thumb at home and the two finger joints free, `locus` finds where the
    numbers of the system change, and `locus.locked` where those of the locked system
    (motors held still) change: there $N_{uo} = N_c$ and $N_{pi} = N_r - N_a$ of the
    locked system. The numbers change on the whole lines $q_2 = \\pm\\pi/2$, but the
    uncontrolled motion appears only at $q_1 = 0$ on them:
    """),
    code("""
    floc = finger.locus(free=["q1", "q2"])
    display(floc)
    display(floc.locked)
    assert floc.generic == a.numbers.as_dict()
    assert {"q2 = pi/2", "q2 = -pi/2"} <= {c.condition.text for c in floc.components}
    assert {c.condition.text for c in floc.locked.components} == {"q1 = 0, q2 = -pi/2",
                                                             "q1 = 0, q2 = pi/2"}
    for c in floc.locked.components:
        direct = finger.analyze(c.witness).passive.numbers
        assert (direct.Nuo, direct.Npi) == (c.numbers["Nc"], c.numbers["Nr"] - 2) == (1, 0)
    """),
    md("""
    ## 2. A closed chain: the five-bar linkage

    The shipped `five-bar`: two legs with a motor at the base (q1, q3) and a passive
    elbow (q2, q4), their distal links pinned to the moving platform (the object) at one
    point. Each pin is a planar hard contact (it holds $v_x$, $v_y$ of the pin and leaves
    the rotation free).

    **A caveat.** Like the 1992 paper, the analysis takes each joint variable as given
    and puts each contact at its link's current point. For a closed chain only the
    configurations where the two pins coincide are assemblies of the five-bar; where
    they are apart the same matrices describe another mechanism (an object pinned at
    two points). The home configuration ($L = 1$: bases $(\\mp 1, 0)$, elbows
    $(\\mp 1, 1)$, pin $(0, 2)$) is an assembly:
    """),
    code("""
    print(example_path("five-bar").read_text())
    five = coopkin_sym.load("five-bar")


    def pins(analysis):
        \"\"\"The two contact points (the pins), exact, at a configuration with L = 1.\"\"\"
        return coopkin_sym.contact_points(analysis)


    home = five.analyze("L=1")
    print("pins at home:", pins(home))
    assert pins(home)[0] == pins(home)[1] == (0, 2, 0)
    display(numbers_table([("home", home.numbers)]))
    display(passive_table([("home", home.passive.numbers)]))
    show_passive(home.passive)
    """),
    code("""
    assert home.numbers.as_dict() == {"Nm": 3, "Nc": 3, "Ni": 1, "Nr": 0, "Ng": 2,
                                      "Nd": 0, "Nh": 0}
    ph = home.passive.numbers
    assert ph.as_dict() == {"Na": 2, "Np": 2, "Nco": 2, "Nuo": 1, "Npi": 0, "Nar": 0,
                            "Nam": 2}
    assert home.passive.uncontrolled == sp.Matrix([2, 0, 1])     # spin about (0, 2)
    assert check_against_q(home) == ph.as_dict()
    """),
    md("""
    With the motors still, the elbows are still and so is the pin: only the platform's
    spin about the pin is free ($N_{uo} = N_i = 1$); the two motors drive the pin's
    velocity ($N_{co} = N_{am} = 2$).

    ### Singular assemblies, exactly

    Where are there assemblies with other passive numbers? Search exactly: for small
    rational $t = \\tan(q/2)$ of each motor angle and of each distal link's absolute
    angle, compute each leg's pin with exact rationals, and keep the pairs whose pins
    coincide. Each such assembly is then analyzed:
    """),
    code("""
    T = sorted({Fraction(p, q) for p in range(-3, 4) for q in range(1, 4)})


    def cos_sin(t):
        return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


    def angle(t):
        return {0: "0", 1: "pi/2", -1: "-pi/2"}.get(t, f"2*atan({t})")


    def leg(base_x, home_dir):
        \"\"\"Pin -> [(tan(q_motor/2), tan(q_elbow/2))] for one leg (L = 1): the elbow at
        (base_x, 0) + R(q)(0, 1), the pin at elbow + R(q + q')(home_dir).\"\"\"
        out = {}
        for t in T:
            c, s = cos_sin(t)
            for tau in T:                   # tan((q + q')/2)
                if 1 + tau * t == 0:
                    continue                # q' = pi, left out
                cc, ss = cos_sin(tau)
                dx, dy = home_dir
                pin = (base_x - s + cc * dx - ss * dy, c + ss * dx + cc * dy)
                out.setdefault(pin, []).append((t, (tau - t) / (1 + tau * t)))
        return out


    left, right = leg(-1, (1, 1)), leg(1, (-1, 1))
    assemblies = [f"q1={angle(t1)},q2={angle(t2)},q3={angle(t3)},q4={angle(t4)},L=1"
                  for pin, ls in left.items() for (t1, t2) in ls
                  for (t3, t4) in right.get(pin, [])]
    groups = {}
    for at in assemblies:
        an = five.analyze(at)
        assert pins(an)[0] == pins(an)[1]            # an assembly, checked by the engine
        key = (an.numbers, an.passive.numbers)
        groups.setdefault(key, []).append(at)
    print(len(assemblies), "assemblies with tan(q/2) in", len(T), "values")
    display(Markdown("| Nm Nc Ni Nr | Nco Nuo Npi Nar Nam | assemblies | e.g. |\\n"
                     "|---|---|---|---|\\n" + "\\n".join(
                         f"| {n.Nm} {n.Nc} {n.Ni} {n.Nr} | {p.Nco} {p.Nuo} {p.Npi} "
                         f"{p.Nar} {p.Nam} | {len(v)} | `{min(v, key=len)}` |"
                         for (n, p), v in groups.items())))
    """),
    code("""
    at_home = groups[(home.numbers, home.passive.numbers)]
    assert "q1=0,q2=0,q3=0,q4=0,L=1" in at_home
    singular = {key: v for key, v in groups.items() if key[1] != home.passive.numbers}
    assert len(singular) == 1
    (n_s, p_s), found = next(iter(singular.items()))
    assert (p_s.Nco, p_s.Nuo, p_s.Npi, p_s.Nar, p_s.Nam) == (1, 2, 0, 0, 1)
    S = "q1=0,q2=2*atan(-1/2),q3=2*atan(-1/2),q4=pi/2,L=1"
    assert S in found
    for at in found:
        print(at)
    """),
    md("""
    Every singular assembly found has $N_{uo} = 2$: with the motors still the pin can
    move too. In most of them the elbows coincide at $(0, 0)$ ($q_1 = -\\pi/2$,
    $q_3 = \\pi/2$) and the distal links lie on each other. The other two are mirror
    images; take `S` (left motor at home): the elbows are at $(-1, 1)$ and
    $(9/5, 3/5)$, $2\\sqrt 2$ apart, and the pin is at their midpoint $(2/5, 4/5)$: both
    distal links lie on one line, the "parallel" singularity. The pin can move across
    that line with every motor still, and the motors control only its motion along the
    line:
    """),
    code("""
    s_an = five.analyze(S)
    print("pins:", pins(s_an))
    assert pins(s_an)[0] == pins(s_an)[1] == (sp.Rational(2, 5), sp.Rational(4, 5), 0)
    display(numbers_table([("home", home.numbers), ("S", s_an.numbers)]))
    display(passive_table([("home", home.passive.numbers), ("S", s_an.passive.numbers)]))
    show_passive(s_an.passive)
    """),
    code("""
    check_against_q(s_an)
    pin = sp.Matrix([sp.Rational(2, 5), sp.Rational(4, 5)])


    def pin_velocity(twist):
        \"\"\"The velocity of the pin for an object twist (v_x, v_y, w_z) at the origin.\"\"\"
        return sp.Matrix([twist[0] - twist[2] * pin[1], twist[1] + twist[2] * pin[0]])


    free = [pin_velocity(s_an.passive.uncontrolled.col(k)) for k in range(2)]
    across = next(v for v in free if v != sp.zeros(2, 1))
    along = sp.Matrix([7, -1])                     # the line of the distal links
    assert across.dot(along) == 0                  # free: across the line
    assert sp.Matrix.hstack(*free).rank() == 1     # and the spin about the pin
    driven = pin_velocity(s_an.passive.controlled.col(0))
    assert sp.Matrix.hstack(driven, across).rank() == 2   # driven: along the line
    """),
    md("""
    ### The locked locus on a slice through S

    Keep the motors at S ($q_1 = 0$, $q_3 = 2\\arctan(-1/2)$) and free both elbows. The
    elbows are then $2\\sqrt 2$ apart, so this slice has one assembly, S itself. The
    locus of the system and that of the locked system:
    """),
    code("""
    slice_locus = five.locus(at="q1=0,q3=2*atan(-1/2),L=1", free=["q2", "q4"])
    display(slice_locus)
    display(slice_locus.locked)
    """),
    code("""
    s_point = {"q1": "0", "q3": "2*atan(-1/2)", "q2": "2*atan(-1/2)", "q4": "pi/2",
               "L": "1"}
    # generic in the slice: the pins apart (an object pinned at two points), Ni = 0
    assert slice_locus.generic["Ni"] == 0 and slice_locus.locked.generic["Nc"] == 1
    # the one assembly is a component of its own: the pins meet, Ni goes to 1
    meet = [c for c in slice_locus.components if c.witness == s_point]
    assert len(meet) == 1 and meet[0].numbers == s_an.numbers.as_dict()
    # the locked locus: isolated points with Nuo = 2, S among them
    for c in slice_locus.locked.components:
        direct = five.analyze(c.witness).passive.numbers
        assert (direct.Nuo, direct.Npi) == (c.numbers["Nc"], c.numbers["Nr"] - 2)
        assert direct.Nuo == 2
    assert s_point in [c.witness for c in slice_locus.locked.components]
    """),
    md("""
    Read the slice with the caveat in mind: its generic numbers ($N_i = 0$, and
    $N_{uo} = 1$ for the locked system: the object is the coupler of a four-bar) are
    those of the pins apart, and the five-bar itself is only the component where they
    meet. The locked locus has four points where both distal links lie on the line
    through the two pins ($N_{uo} = 2$); one of them is the assembly S. The components
    with irrational witnesses are where a leg is stretched or folded
    ($\\tan(q_2/2) = -1 \\pm \\sqrt 2$ or $\\tan(q_4/2) = 1 \\pm \\sqrt 2$); none of them is
    an assembly in this slice.

    ## 3. Manipulability of the pin

    The manipulability ellipse of the pin's velocity (`controlled` $v_x, v_y$ at
    `point` = the pin): the pin velocities reached with unit speed, the ellipse
    $\\{y : y^T E^+ y \\le 1\\}$ with $E$ = `shape` exact, `index` $= \\det E$ and
    `rank` (see `coopkin_sym.analysis.manipulability`). At home:
    """),
    code("""
    m_home = home.manipulability(controlled=["v_x", "v_y"], length=1, point=[0, 2, 0])
    display(Math(named_latex("E", m_home.shape)))
    print("rank:", m_home.rank, "| index:", m_home.index)
    assert m_home.shape == m_home.shape.T and m_home.shape[0, 1] == 0  # mirror symmetry
    assert m_home.rank == 2 and m_home.index > 0
    draw(home, ellipsoid=True, title="five-bar at home")
    """),
    md("""
    At S the ellipse is flat: the pin's motion across the line of the distal links is
    not driven by the motors, so $E$ loses rank and its range is the driven direction:
    """),
    code("""
    m_s = s_an.manipulability(controlled=["v_x", "v_y"], length=1, point=[*pin, 0])
    display(Math(named_latex("E", m_s.shape)))
    print("rank:", m_s.rank, "| index:", m_s.index)
    assert m_s.shape == m_s.shape.T and m_s.index == 0 and m_s.rank == 1
    assert (m_s.shape * across).is_zero_matrix          # the free direction: no extent
    draw(s_an, ellipsoid=True, title="five-bar at S (distal links in line)")
    """),
]


NB06 = [
    md("""
    # Instantaneous or finite? The finite mobility at a singular configuration

    The seven numbers count first-order motions: velocities that keep every contact.
    At a singular configuration some of them may have no finite motion behind them,
    and the configuration space may branch. With hard and complete contacts the arms
    and the object form a linkage, and `finite_mobility` expands its loop closure
    exactly at a configuration: the local dimension of the configuration space, its
    branches, and how it was proved (see `docs/finite-mobility.md`).
    """),
    code("""
    import sympy as sp

    from coopkin_sym import load

    four_bar = load("four-bar")
    home = four_bar.analyze("q1=0,q2=0").finite_mobility()
    print(home.dimension, home.first_order, home.classification, home.reason)
    assert (home.dimension, home.first_order, home.classification) == (1, 1, "regular")
    """),
    md("""
    ## The folded four-bar: two branches

    At `q1 = q2 = -pi/2` the crank, coupler, rocker and ground lie on one line. There
    are two first-order motions, but the loop closure's reduced equation,
    $3u_1^2 - 2u_1u_2 - u_2^2 = 0$ in $u_k = \\tan(\\Delta q_k/2)$, is a product of two lines:
    the parallelogram and the anti-parallelogram motions cross, each of one motion.
    """),
    code("""
    folded = four_bar.analyze("q1=-pi/2,q2=-pi/2")
    fm = folded.finite_mobility()
    print(fm.dimension, fm.first_order, fm.classification, fm.equations)
    for branch in fm.branches:
        v = sp.Matrix(branch.tangent[0])
        print("branch tangent (u, qdot):", list(v), " Q v = 0:", (folded.Q * v).is_zero_matrix)
        assert (folded.Q * v).is_zero_matrix
    assert (fm.dimension, fm.first_order, fm.classification) == (1, 2, "bifurcation")
    assert fm.orders == ((1, 2), (2, 1))
    four_bar.draw("q1=-pi/2,q2=-pi/2", title="four-bar, folded: two branches cross")
    """),
    md("""
    Which of the paper's first-order motions are finite ones? Each column of `C12`/`C22`
    (here the driven motions) is either in a branch's tangent (`finite`), or a
    lowest-order term of the reduced constraint is not zero along it: no finite motion
    has that velocity, and the constraints fail at that order.
    """),
    code("""
    for c in fm.columns:
        print(f"{c.block} column {c.index}: {c.verdict}"
              + (f" at order {c.order}" if c.order else ""))
    assert [(c.verdict, c.order) for c in fm.columns] == [("finite", None), ("fails", 2)]
    """),
    md("""
    ## Paper case 1 as a linkage

    In the plane, case 1 with hard contacts is a four-bar with all four lengths equal
    (a rhombus). At $q_1 = q_2 = \\pi/2$ it folds and bifurcates. In space, the object
    can also spin about the line through the two contacts. With the joints still,
    those rotations keep both contacts, so they are split off and counted, and the
    expansion decides the rest: at $q_1 = \\pi/2$, $q_2 = -\\pi/2$ only the spin is a
    finite motion.
    """),
    code("""
    planar = load("paper-case1-planar").finite_mobility("q1=pi/2,q2=pi/2")
    spatial = load("paper-case1-hard").finite_mobility("q1=pi/2,q2=-pi/2")
    print("planar:", planar.dimension, planar.first_order, planar.classification)
    print("spatial:", spatial.dimension, spatial.first_order, spatial.classification,
          "spin:", spatial.group_motions)
    assert (planar.dimension, planar.classification) == (1, "bifurcation")
    assert (spatial.dimension, spatial.first_order, spatial.classification) == (1, 3, "shaky")
    """),
    md("""
    ## A shaky structure, and what is not decided

    Two bars pinned end to end on the line of their pivots can start to move: the pin
    moves across the line, one first-order motion. But no finite motion follows. Where
    nothing is proved (three parallel cranks lying on the ground line: two reduced
    equations whose lowest terms share a real direction), the result says *undecided*
    and gives the bounds it proves.
    """),
    code("""
    shaky = load("shaky-pinned-bars").finite_mobility("q1=0,q2=0")
    print(shaky.dimension, shaky.first_order, shaky.classification, shaky.equations)
    assert (shaky.dimension, shaky.first_order, shaky.classification) == (0, 1, "shaky")
    open_question = load("parallel-cranks").finite_mobility("q1=pi/2,q2=pi/2,q3=pi/2")
    print(open_question.dimension, open_question.bounds, open_question.reason)
    assert open_question.dimension is None and open_question.bounds == (0, 1)
    """),
    md("""
    ## Along the locus

    The singularity locus of the four-bar has four isolated configurations. At each
    witness, the finite mobility says which ones are bifurcations, where the system is
    shaky, and which are only first-order.
    """),
    code("""
    locus = four_bar.locus()
    for c in locus.components:
        at = ",".join(f"{k}={v}" for k, v in c.witness.items())
        fm = four_bar.finite_mobility(at)
        print(f"{c.condition.text:28} Nm {c.numbers['Nm']}: finite {fm.dimension}, "
              f"{fm.classification}")
    kinds = sorted(four_bar.finite_mobility(",".join(f"{k}={v}" for k, v in
                   c.witness.items())).classification for c in locus.components)
    assert kinds == ["bifurcation", "bifurcation", "shaky", "shaky"], kinds
    """),
    md("""
    ## The paper's cases along their loci

    In the plane, case 1 is a four-bar with four equal links (the base, the two arms
    and the object between the contacts). Its locus has four folded configurations
    and two more points, `q1 = -q2` with `tan(q2/2) = 2 -+ sqrt(3)` (`q2 = pi/6` or
    `5 pi/6`); `Locus.finite_mobility()` computes the finite mobility at every
    witness. Three folded points are bifurcations: two of the equal-link four-bar's
    modes of motion (one of them the parallelogram) cross there. At the fourth the first-order
    motions have no finite motion behind them (shaky). At the two points with
    `q1 = -q2` only the instantaneous numbers change: the configuration space is
    smooth there.
    """),
    code("""
    case1 = load("paper-case1-planar").locus()
    case1.finite_mobility()
    for c in case1.components:
        f = c.finite
        print(f"{c.condition.text:34} Nm {c.numbers['Nm']}: finite {f['dimension']} "
              f"of {f['first_order']}, {f['classification']}")
    kinds = sorted(c.finite["classification"] for c in case1.components)
    assert kinds == ["bifurcation"] * 3 + ["kinematic_singularity", "shaky"], kinds
    """),
    md("""
    Case 2 with welded contacts (`paper-case2-complete`), on the slice where joints
    q2, q3, q6 and q7 move and the others stay at home: every component of the locus
    is a smooth point of the configuration space. The rank of `Q` at each witness is
    its generic rank along the component (`along` says how that was proved), so the
    singularities of case 2 there are only first-order: the numbers change, the finite
    motions do not.
    """),
    code("""
    from collections import Counter

    case2 = load("paper-case2-complete").locus("q1=0,q4=0,q5=0,q8=0,L=1",
                                                free=["q2", "q3", "q6", "q7"])
    case2.finite_mobility()
    seen = Counter((c.finite["dimension"], c.finite["first_order"],
                    c.finite["classification"], c.finite["reason"])
                   for c in case2.components)
    for (dim, first, kind, reason), count in sorted(seen.items()):
        print(f"{count} components: finite {dim} of {first} first-order, {kind} ({reason})")
    assert {kind for _, _, kind, _ in seen} == {"kinematic_singularity"}
    """),
    md("""
    ## Overconstrained loops: Bennett, Bricard, parallel cranks

    Grübler-Kutzbach counts `6 (links - 1) - 5 joints` motions for a loop of revolute
    joints: -2 for four joints in space, 0 for six. Bennett's linkage (four joints) and
    Bricard's line-symmetric linkage (six) move all the same, once: their special
    geometry makes some closure conditions follow from the others at every nearby
    configuration. So do three parallel cranks pinned to a coupler in the plane
    (`3 (5 - 1) - 2 * 6 = 0`). The expansion cannot see it (every first-order motion
    extends to every order computed), so the loop closure is written as polynomials
    (dual quaternions, one variable per joint; contact points compared for pins), and
    the dependent conditions are proved to vanish on the smooth curve the independent
    ones cut out: along it to an order above Bezout's bound, the product of the
    degrees (the reason `closure_bezout`), or by exact Gröbner saturations
    (`closure_saturation`). It also runs over a number field: Bennett's linkage at a
    point of its motion where `q1 = pi/6`.
    """),
    code("""
    bennett_curve = "2*atan((65*sqrt(3)-70)/311)"
    loops = [("bennett-linkage", None, -2), ("bricard-linkage", None, 0),
             ("parallel-cranks", None, 0),
             ("bennett-linkage", f"q1=pi/6,q2={bennett_curve},q3=pi/6,q4={bennett_curve}",
              -2)]
    for name, at, count in loops:
        fm = load(name).finite_mobility(at)
        field = "" if fm.field is None else f" over Q({fm.field['alpha']})"
        print(f"{name}{' at q1=pi/6' if at else ''}: Gruebler {count}, first-order "
              f"{fm.first_order}, finite {fm.dimension} ({fm.reason}){field}")
        assert (fm.dimension, fm.reason) == (1, "closure_bezout")
    """),
    md("""
    ## Three branches along the roots of a cubic

    `seven-r-loop` is a loop of seven revolute joints whose axes are all horizontal at
    home: two first-order motions instead of one, a second-order closure term that
    vanishes, and a third-order one that is an irreducible cubic with three real roots.
    Three branches cross; each tangent is exact, with its root `s` given by its minimal
    polynomial and an isolating interval with rational ends.
    """),
    code("""
    fm = load("seven-r-loop").finite_mobility()
    print(fm.classification, len(fm.branches), "branches")
    for branch in fm.branches:
        d = branch.direction
        print(f"  s in ({d.interval[0]}, {d.interval[1]}], root of {d.polynomial}")
    assert len({b.direction.polynomial for b in fm.branches}) == 1
    """),
]


NB07 = [
    md("""
    # Real robots: two Franka Panda arms holding a box, a four-finger hand

    Two shipped examples are real robots at their published sizes, each arm a DH table
    read exactly: `panda-two-arm-box` (Franka's modified DH table, 7 joints per arm,
    each hand holding the box rigidly at its grasp point 0.2104 m beyond frame 7) and
    `allegro-hand-sphere` (an Allegro-like hand: three fingers and a thumb of four
    joints each, soft fingertips on a sphere).
    """),
    code("""
    from coopkin_sym import load, sentences

    cell = load("panda-two-arm-box")
    bent = ("l2=2*atan(1/5),l4=2*atan(-2),l6=2*atan(2),l7=2*atan(2/5),"
            "r2=2*atan(1/5),r4=2*atan(-2),r6=2*atan(2),r7=2*atan(2/5)")
    generic, home, reach = (cell.analyze(generic=True), cell.analyze(), cell.analyze(bent))
    for label, a in [("generic", generic), ("home", home), ("reaching", reach)]:
        print(f"{label:9}", a.numbers.as_dict())
    assert generic.numbers.as_dict() == reach.numbers.as_dict() == {
        "Nm": 8, "Nc": 6, "Ni": 0, "Nr": 2, "Ng": 6, "Nd": 0, "Nh": 0}
    assert home.numbers.as_dict() == {"Nm": 9, "Nc": 5, "Ni": 0, "Nr": 4, "Ng": 6,
                                      "Nd": 2, "Nh": 1}
    """),
    md("""
    Generically the box can move in every direction and each arm keeps one
    self-motion (its seventh joint). At home each arm stands straight up with joints
    1, 3 and 5 about one vertical line: each arm gains a self-motion and the box loses
    a motion. The self-motions at home, in words:
    """),
    code("""
    print([line for line in sentences(home) if line.startswith("Nr")][0])
    cell.draw(bent, title="two Panda arms holding a box")
    """),
    md("""
    ## Where the left arm's elbow and wrist are singular

    A locus on a slice: every joint at an exact value but the left arm's `l4` (elbow)
    and `l6` (wrist). Each component's witness is an exact point (here with quadratic
    coordinates); the numbers there are those of the component.
    """),
    code("""
    slice_ = ("l1=0,l2=2*atan(1/5),l3=0,l5=0,l7=2*atan(2/5),r1=0,r2=2*atan(1/5),r3=0,"
              "r4=2*atan(-2),r5=0,r6=2*atan(2),r7=2*atan(2/5)")
    locus = cell.locus(slice_, free=["l4", "l6"])
    for c in locus.components:
        print(c.kind, "|", c.condition.text, "|", c.changes)
    assert all(c.witness_checked for c in locus.components)
    assert any(c.kind == "hypersurface" and c.changes["Nc"] == (6, 5)
               for c in locus.components)
    """),
    md("""
    ## The four-finger hand

    Each long finger has three parallel flexion joints: with its tip held on the
    sphere, it can still roll the tip (a soft finger does not stop rolling), so the
    hand has three self-motions and the sphere keeps three motions.
    """),
    code("""
    hand = load("allegro-hand-sphere")
    curled = ("i1=2*atan(1/2),i2=2*atan(1/3),i3=2*atan(1/3),m1=2*atan(1/2),"
              "m2=2*atan(1/3),m3=2*atan(1/3),r1=2*atan(1/2),r2=2*atan(1/3),"
              "r3=2*atan(1/3),t0=pi/2,t2=2*atan(1/3),t3=2*atan(1/3)")
    for label, a in [("generic", hand.analyze(generic=True)), ("home", hand.analyze()),
                     ("curled", hand.analyze(curled))]:
        print(f"{label:8}", a.numbers.as_dict())
    assert hand.analyze(curled).numbers.as_dict() == {"Nm": 6, "Nc": 3, "Ni": 0, "Nr": 3,
                                                      "Ng": 10, "Nd": 3, "Nh": 0}
    hand.draw(curled, title="an Allegro-like hand holding a sphere")
    """),
]


NOTEBOOKS = {
    "01_two_one_link_arms.ipynb": NB01,
    "02_two_scara_robots.ipynb": NB02,
    "03_singularity_locus.ipynb": NB03,
    "04_exact_vs_float.ipynb": NB04,
    "05_passive_joints_and_manipulability.ipynb": NB05,
    "06_finite_mobility.ipynb": NB06,
    "07_real_robots.ipynb": NB07,
}


KERNEL = "python3"
"""The kernel every notebook runs in."""

METADATA = {
    "kernelspec": {"display_name": "Python 3", "language": "python", "name": KERNEL},
    "language_info": {"name": "python"},
}
"""The notebook metadata, the same after a run (no Python version)."""

CELL_TIMEOUT = 1800
"""Seconds one cell may run before the run fails."""


def build(name: str, cells: list) -> nbformat.NotebookNode:
    """A notebook of the given cells, without outputs.

    Parameters
    ----------
    name
        The notebook's file name (``01_two_one_link_arms.ipynb``); its number prefixes
        the cell ids.
    cells
        The cells, made by :func:`md` and :func:`code`.

    Returns
    -------
    nbformat.NotebookNode
        A valid nbformat-4 notebook with stable cell ids.
    """
    nb = new_notebook(cells=cells, metadata=METADATA)
    stem = name.split("_")[0]
    for i, cell in enumerate(nb.cells):   # stable ids: rebuilding changes nothing
        cell["id"] = f"nb{stem}-{i:02d}"
    nbformat.validate(nb)
    return nb


def compact_png(data: str) -> str:
    """A base64 PNG redrawn with 256 colours on white (a third of the size, same look).

    Parameters
    ----------
    data
        The base64 text of a PNG, as a notebook stores it.

    Returns
    -------
    str
        The base64 text of the smaller PNG (no text chunks: the same bytes on every run).
    """
    picture = Image.open(io.BytesIO(base64.b64decode(data))).convert("RGBA")
    white = Image.new("RGBA", picture.size, "white")
    flat = Image.alpha_composite(white, picture).convert("RGB")
    small = flat.quantize(colors=256, method=Image.Quantize.MEDIANCUT,
                          dither=Image.Dither.NONE)
    buffer = io.BytesIO()
    small.save(buffer, format="PNG", optimize=True)
    return base64.b64encode(buffer.getvalue()).decode("ascii")


_MASKS = [
    (re.compile(r"/tmp/ipykernel_\d+/\d+\.py"), "<cell>"),
    (re.compile(re.escape(tempfile.gettempdir()) + r"/[^\s'\"`)]*"), "<tmp>"),
    (re.compile(r" at 0x[0-9a-fA-F]+"), " at 0x…"),
    (re.compile(r"\b\d+(?:\.\d+)?(?:e[+-]?\d+)? ?(?:ms|µs|us|s|sec|seconds|min)\b"), "<time>"),
]
_FLOAT = re.compile(r"(?<![\w.])-?\d+\.\d+(?:e[+-]?\d+)?(?![\w.])")


def _round(match: re.Match) -> str:
    return f"{float(match.group()):.4g}"  # float-ok: masks float noise in printed text


def normalize(text: str) -> str:
    """Printed text with its volatile parts masked and its exact content kept.

    Parameters
    ----------
    text
        One output's text.

    Returns
    -------
    str
        The text with timings, memory addresses and temporary paths replaced by
        placeholders, decimal numbers rounded to four significant digits, runs of
        spaces shortened to one and no spaces inside brackets or at line ends.

    Examples
    --------
    >>> normalize("computed in 149.51 s; c1 moved by [0.59998 0.30003 0.3    ]")
    'computed in <time>; c1 moved by [0.6 0.3 0.3]'
    >>> normalize("Nm=2, C22 = Matrix([[1], [1]]), L=1/1000, 1e-12 rad")
    'Nm=2, C22 = Matrix([[1], [1]]), L=1/1000, 1e-12 rad'
    """
    for pattern, placeholder in _MASKS:
        text = pattern.sub(placeholder, text)
    text = _FLOAT.sub(_round, text)
    text = re.sub(r"[ \t]+", " ", text)
    text = re.sub(r"\[ ", "[", re.sub(r" \]", "]", text))
    return "\n".join(line.rstrip() for line in text.splitlines())


def printed(cell: nbformat.NotebookNode, streams: tuple[str, ...] = ("stdout",),
            pictures: bool = False) -> list[tuple[str, str]]:
    """What a code cell printed, as (kind, normalized text) pairs in output order.

    Parameters
    ----------
    cell
        A code cell with outputs.
    streams
        The streams to include (``"stdout"``, ``"stderr"``); consecutive chunks of one
        stream are joined, since their splitting varies between runs.
    pictures
        Also include each PNG picture (its base64 text, unchanged).

    Returns
    -------
    list of (str, str)
        One pair per stream run, per ``text/*`` form of a result or display (plain
        text, LaTeX, Markdown, HTML) and per error; ``kind`` says which.
    """
    found: list[tuple[str, str]] = []
    for output in cell.get("outputs", []):
        if output.output_type == "stream":
            if output.name in streams:
                kind = f"stream {output.name}"
                if found and found[-1][0] == kind:
                    found[-1] = (kind, found[-1][1] + output.text)
                else:
                    found.append((kind, output.text))
            continue
        if output.output_type == "error":
            found.append(("error", f"{output.ename}: {output.evalue}"))
        for kind, value in sorted(output.get("data", {}).items()):
            if kind.startswith("text/"):
                found.append((f"{output.output_type} {kind}", value))
            elif kind == "image/png" and pictures:
                found.append((f"{output.output_type} {kind}", value))
    return [(kind, value if kind.endswith("image/png") else normalize(value))
            for kind, value in found]


def _coalesce_streams(cell: nbformat.NotebookNode) -> None:
    """Join consecutive chunks of one stream into one output."""
    outputs = []
    for output in cell.outputs:
        if (output.output_type == "stream" and outputs
                and outputs[-1].output_type == "stream" and outputs[-1].name == output.name):
            outputs[-1].text += output.text
        else:
            outputs.append(output)
    cell.outputs = outputs


def execute(nb: nbformat.NotebookNode,
            timeout: int = CELL_TIMEOUT) -> nbformat.NotebookNode:
    """Run a notebook top to bottom in a fresh kernel and store its outputs.

    Parameters
    ----------
    nb
        A notebook from :func:`build`; changed in place.
    timeout
        Seconds one cell may run.

    Returns
    -------
    nbformat.NotebookNode
        ``nb``, with outputs and execution counts, pictures made smaller by
        :func:`compact_png`, and without the volatile metadata nbclient records (cell
        timings, the kernel's ``language_info``).

    Raises
    ------
    nbclient.exceptions.CellExecutionError
        A cell raised (a failed ``assert`` included); the message names the cell.
    """
    # pictures inline as PNG, whatever backend the calling process chose
    env = dict(os.environ, MPLBACKEND="module://matplotlib_inline.backend_inline")
    client = NotebookClient(nb, timeout=timeout, kernel_name=KERNEL, record_timing=False,
                            resources={"metadata": {"path": str(HERE)}})
    client.execute(env=env)
    nb.metadata = nbformat.from_dict(METADATA)
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
        if cell.cell_type != "code":
            continue
        _coalesce_streams(cell)
        for output in cell.outputs:
            if "image/png" in output.get("data", {}):
                output.data["image/png"] = compact_png(output.data["image/png"])
    nbformat.validate(nb)
    return nb


def keep_unchanged_outputs(committed: nbformat.NotebookNode,
                           fresh: nbformat.NotebookNode) -> int:
    """Keep a cell's committed outputs where the fresh ones differ only in volatile parts.

    A cell's outputs are the same when they print the same text once normalized (see
    :func:`normalize`: timings, addresses, temporary paths, float noise), standard error
    included, and draw the same pictures byte for byte. Then the committed outputs are
    kept, so regenerating without a change rewrites the same file.

    Parameters
    ----------
    committed
        The notebook as it was on disk.
    fresh
        The same notebook just run (:func:`execute`); changed in place.

    Returns
    -------
    int
        The number of code cells whose new outputs were written.
    """
    changed = 0
    for index, cell in enumerate(fresh.cells):
        if cell.cell_type != "code":
            continue
        old = committed.cells[index] if index < len(committed.cells) else None
        streams = ("stdout", "stderr")
        if (old is not None and old.cell_type == "code"
                and printed(old, streams, pictures=True) == printed(cell, streams,
                                                                   pictures=True)):
            cell.outputs = copy.deepcopy(old.outputs)
            _coalesce_streams(cell)
            for output in cell.outputs:
                if output.output_type == "execute_result":
                    output.execution_count = cell.execution_count
        else:
            changed += 1
    return changed


def main(argv: list[str] | None = None) -> None:
    """Build, run and write the notebooks (all, or those whose names start as given).

    Parameters
    ----------
    argv
        Command-line arguments (``sys.argv[1:]`` when ``None``).
    """
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("only", nargs="*", metavar="PREFIX",
                        help="regenerate only the notebooks whose names start with PREFIX")
    args = parser.parse_args(argv)
    chosen = [name for name in NOTEBOOKS
              if not args.only or any(name.startswith(p) for p in args.only)]
    if not chosen:
        parser.error(f"no notebook starts with {' or '.join(args.only)}: {', '.join(NOTEBOOKS)}")
    for name in chosen:
        start = time.perf_counter()
        path = HERE / name
        nb = execute(build(name, NOTEBOOKS[name]))
        changed = "all"
        if path.exists():
            changed = keep_unchanged_outputs(nbformat.read(path, as_version=4), nb)
        nbformat.write(nb, path)
        print(f"wrote {path} ({path.stat().st_size // 1024} KB, ran in "
              f"{time.perf_counter() - start:.0f} s, new outputs in {changed} cells)",
              flush=True)


if __name__ == "__main__":
    main()
