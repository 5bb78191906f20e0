"""The documentation site builds with warnings as errors and holds what it should.

The site (``docs/conf.py``: the Markdown pages of ``docs/``, the API reference from the
docstrings, the JSON schemas, the committed notebooks) is built by Sphinx into a
temporary folder with ``-W`` (every warning an error), as
``python -m sphinx -W --keep-going -b html docs docs/_build/html`` does. It needs the
``docs`` extra (``pip install ".[docs]"``) and is skipped without it."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import coopkin_sym

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    pytest.importorskip("sphinx", reason="the docs extra is not installed "
                                         "(pip install '.[docs]')")
    pytest.importorskip("myst_nb", reason="the docs extra is not installed "
                                          "(pip install '.[docs]')")
    out = tmp_path_factory.mktemp("site")
    done = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         "-d", str(out / "doctrees"), str(DOCS), str(out / "html")],
        cwd=ROOT, capture_output=True, text=True, timeout=900,
        env={**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg"})
    assert done.returncode == 0, (done.stdout + done.stderr)[-5000:]
    return out / "html"


@pytest.mark.slow
def test_the_site_has_the_pages(site):
    for page in ["index", "model-format", "analyze-json", "locus-report", "sweep-files",
                 "finite-mobility", "schemas", "notebooks", "api/index", "api/system",
                 "api/analysis", "api/locus", "api/sweep", "api/errors"]:
        assert (site / f"{page}.html").is_file(), page
    for notebook in (ROOT / "notebooks").glob("*.ipynb"):
        assert (site / "notebooks" / f"{notebook.stem}.html").is_file(), notebook.name


@pytest.mark.slow
def test_the_api_reference_documents_every_public_name(site):
    text = "".join(p.read_text(encoding="utf-8") for p in (site / "api").glob("*.html"))
    for name in coopkin_sym.__all__:
        assert f'id="coopkin_sym.{name}"' in text, name
    for method in ["System.analyze", "System.locus", "Analysis.numbers", "Locus.components",
                   "SweepResult.write"]:
        assert f'id="coopkin_sym.{method}"' in text, method


@pytest.mark.slow
def test_the_schemas_page_holds_every_schema(site):
    text = (site / "schemas.html").read_text(encoding="utf-8")
    for path in sorted(DOCS.glob("*.schema.json")):
        assert path.name in text
        assert json.loads(path.read_text(encoding="utf-8"))["title"].replace(
            "<", "&lt;").replace(">", "&gt;").replace('"', "&quot;") in text, path.name


@pytest.mark.slow
def test_the_notebooks_are_shown_with_their_outputs(site):
    text = (site / "notebooks" / "01_two_one_link_arms.html").read_text(encoding="utf-8")
    assert "cell_output" in text


LINK = re.compile(r"\]\(([^)\s]+)\)")
WORDS = ("DE" + "SIGN",)   # a document that is not in the repository


def _texts() -> list[Path]:
    return [ROOT / "README.md", *sorted(DOCS.glob("*.md")), *sorted(DOCS.glob("api/*.md")),
            *sorted((ROOT / "coopkin_sym").rglob("*.py")), *sorted((ROOT / "tests").rglob("*.py"))]


def test_the_docs_and_the_code_cite_no_file_outside_the_repository():
    for path in _texts():
        text = path.read_text(encoding="utf-8")
        for word in WORDS:
            assert not re.search(rf"\b{word}\b", text), f"{path.relative_to(ROOT)}: {word}"


def test_every_relative_link_of_the_docs_names_a_file_of_the_repository():
    for path in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]:
        for target in LINK.findall(path.read_text(encoding="utf-8")):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            file = (path.parent / target.split("#")[0]).resolve()
            assert file.is_relative_to(ROOT) and file.exists(), f"{path.name}: {target}"


def test_the_schemas_page_lists_every_schema_as_it_is():
    page = (DOCS / "schemas.md").read_text(encoding="utf-8")
    for path in sorted(DOCS.glob("*.schema.json")):
        schema = json.loads(path.read_text(encoding="utf-8"))
        assert f"```{{literalinclude}} {path.name}\n" in page, path.name
        assert f"**{schema['title']}**" in page, path.name
        assert schema["description"] in page, path.name


def test_every_public_name_has_an_entry_in_the_api_pages():
    """The quick form of the check above, without Sphinx: every name of
    ``coopkin_sym.__all__`` is named by one ``auto...`` directive of ``docs/api``."""
    directive = re.compile(
        r"^\.\. auto(?:function|class|data|exception):: (?:coopkin_sym\.)?(\w+)\s*$", re.M)
    named = set()
    for page in (DOCS / "api").glob("*.md"):
        named.update(directive.findall(page.read_text(encoding="utf-8")))
    missing = [name for name in coopkin_sym.__all__ if name not in named]
    assert missing == []
