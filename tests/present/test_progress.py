"""The progress display (:mod:`coopkin_sym.present.progress`): an HTML output updated in
place in a Jupyter kernel (no widget package, no warning), rich's line on a terminal,
nothing when the output goes elsewhere.

The Jupyter tests run a real kernel (nbclient) on a notebook built here and record
every message the kernel sends for each cell: the bar, and the displays the kernel
sends for results (HTML where MathJax would refuse the LaTeX).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from coopkin_sym.present import progress
from coopkin_sym.present.progress import ProgressDisplay, progress_display

ROOT = Path(__file__).resolve().parents[2]


class _Handle:
    """A display handle that records its updates."""

    def __init__(self, shown: list):
        self.shown = shown

    def update(self, bundle, raw=False):
        self.shown.append(("update", bundle))


def _fake_jupyter(monkeypatch) -> list:
    import IPython.display

    shown: list = []

    def display(bundle, raw=False, display_id=False):
        assert raw and display_id
        shown.append(("display", bundle))
        return _Handle(shown)

    monkeypatch.setattr(IPython.display, "display", display)
    return shown


def test_outside_a_kernel_and_a_terminal_nothing_is_shown(capsys):
    """Under pytest stderr is captured (not a terminal) and there is no kernel."""
    assert progress.jupyter_kernel() is False
    assert progress.progress_medium() is None
    with progress_display(True, "locus", delay=0) as show:
        show("depth 0: the numbers", 0.5)
    assert (show.enabled, show.shown) == (False, False)
    assert capsys.readouterr() == ("", "")


def test_jupyter_updates_one_output_at_most_five_times_a_second(monkeypatch):
    shown = _fake_jupyter(monkeypatch)
    clock = [100.0]
    monkeypatch.setattr(progress.time, "monotonic", lambda: clock[0])
    with progress_display(True, "locus", delay=1.0) as show:
        show.medium = "jupyter"
        show.enabled = True
        show("the start")
        assert shown == []                      # not before a second
        clock[0] = 101.0
        show("depth 0: t_q1", 0.25)
        for k in range(10):                     # ten steps in 0.1 s: none shown
            clock[0] += 0.01
            show(f"depth 1: step {k}", 0.5)
        clock[0] = 101.3
        show("depth 1: t_q2 - 1", 0.75)
    kinds = [kind for kind, _ in shown]
    assert kinds == ["display", "update", "update"]
    first, middle, last = (bundle for _, bundle in shown)
    assert first["text/plain"] == "locus: depth 0: t_q1, 25%, 0:01"
    assert '<progress value="2500" max="10000"' in first["text/html"]
    assert middle["text/plain"] == "locus: depth 1: t_q2 - 1, 75%, 0:01"
    assert last["text/plain"] == "locus: done, 0:01"
    assert '<progress value="10000" max="10000"' in last["text/html"]


def test_jupyter_keeps_where_it_stopped(monkeypatch):
    shown = _fake_jupyter(monkeypatch)
    with pytest.raises(KeyboardInterrupt):
        with progress_display(True, "sweep", delay=0) as show:
            show.medium, show.enabled = "jupyter", True
            show("the sweep of <case 1>, 3 of 10 done", None)
            raise KeyboardInterrupt
    assert shown[-1][1]["text/plain"] == ("sweep: stopped during the sweep of <case 1>, "
                                          "3 of 10 done, 0:00")
    html = shown[0][1]["text/html"]
    assert "&lt;case 1&gt;" in html and "<case" not in html
    assert "<progress max=" in html                 # no share known: no value


def test_the_share_is_clipped_and_text_is_short():
    show = ProgressDisplay(False, "locus")
    show("x" * 500, 1.5)
    assert show.text().endswith("x") and len(show.text()) == 240
    show("step", -0.5)
    assert show.text() == "locus: step, 0%, 0:00"


@pytest.fixture(scope="module")
def kernel_messages(tmp_path_factory) -> dict[int, list[dict]]:
    """Every message a real Jupyter kernel sends for each cell of a notebook built here
    (the kernel imports this checkout)."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")

    messages: dict[int, list[dict]] = {}

    class Client(nbclient.NotebookClient):
        def process_message(self, msg, cell, cell_index):
            messages.setdefault(cell_index, []).append(msg)
            return super().process_message(msg, cell, cell_index)

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(source) for source in (
        "import coopkin_sym.present.progress as p\n"
        "p.DELAY = 0   # show it at once: the locus is quick\n"
        "from coopkin_sym import load",
        "locus = load('paper-case1-hard').locus(progress=True)\nlen(locus.components)",
        "load('paper-case2-hard').analyze(generic=True).coordinated_factored()",
        "load('five-bar').analyze()")]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]))
    folder = tmp_path_factory.mktemp("kernel")
    Client(nb, timeout=120, kernel_name="python3",
           resources={"metadata": {"path": str(folder)}}).execute(env=env)
    return messages


def _results(messages: list[dict]) -> list[dict]:
    return [m["content"]["data"] for m in messages if m["msg_type"] == "execute_result"]


def test_a_real_kernel_shows_the_bar_and_no_widget_warning(kernel_messages):
    """``locus(progress=True)`` in a Jupyter kernel: a ``display_data`` with the bar,
    ``update_display_data`` to its last state, nothing on stderr."""
    messages = kernel_messages[1]
    types = [m["msg_type"] for m in messages]
    assert "display_data" in types and "update_display_data" in types
    shown = [m["content"]["data"] for m in messages
             if m["msg_type"] in ("display_data", "update_display_data")]
    assert all('<progress' in d["text/html"] and d["text/plain"].startswith("locus: ")
               for d in shown)
    assert shown[-1]["text/plain"].startswith("locus: done, 0:0")
    streams = [m["content"] for m in messages if m["msg_type"] == "stream"]
    assert [s for s in streams if s["name"] == "stderr"] == []
    assert not any("ipywidgets" in s["text"] for s in streams)
    assert [r["text/plain"] for r in _results(messages)] == ["5"]


def test_a_real_kernel_gets_html_where_latex_would_be_refused(kernel_messages):
    (factored,) = _results(kernel_messages[2])
    assert "text/latex" not in factored                 # over what MathJax accepts
    assert "<code>t_q8**2 + 2*t_q8 - 1</code>" in factored["text/html"]
    assert factored["text/plain"].startswith("<FactoredMotions paper case 2")
    (five_bar,) = _results(kernel_messages[3])
    assert set(five_bar) == {"text/plain", "text/html", "text/latex"}
    assert "Passive joints: q2, q4 (actuated: q1, q3)" in five_bar["text/html"]
    assert ("  Passive: Na = 2  Np = 2  Nco = 2  Nuo = 1  Npi = 0  Nar = 0  Nam = 2"
            in five_bar["text/plain"].splitlines())
    assert all(len(m["content"]["data"].get("text/latex", "")) <= 4000
               for cell in kernel_messages.values() for m in cell
               if m["msg_type"] == "execute_result")
