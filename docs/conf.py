"""Sphinx configuration of the coopkin_sym documentation.

Build (warnings are errors)::

    python -m sphinx -W --keep-going -b html docs docs/_build/html

The Markdown pages are read by MyST, the numpydoc docstrings by autodoc and napoleon,
and the committed notebooks (``docs/notebooks`` is a link to ``notebooks/``) are shown
with the outputs they hold, without being run.
"""

from __future__ import annotations

import os
import sys

sys.path.insert(0, os.path.abspath(".."))

import coopkin_sym  # noqa: E402

project = "coopkin_sym"
author = "coopkin_sym developers"
copyright = "coopkin_sym developers"
release = coopkin_sym.version()
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "myst_nb",          # the Markdown pages (MyST) and the notebooks
]

source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}
exclude_patterns = ["_build", "notebooks/*.py", "**/.ipynb_checkpoints"]

# the notebooks are shown as committed (python notebooks/make_notebooks.py runs them)
nb_execution_mode = "off"
nb_output_stderr = "show"

# options and file names are shown as written (--at, not an en dash)
smartquotes = False

myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3

autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"members": True}
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_rtype = False

html_theme = "alabaster"
html_title = f"coopkin_sym {release}"
html_static_path: list[str] = []
# wide enough for the 100-column code of the pages and the notebooks
html_theme_options = {"page_width": "1280px", "sidebar_width": "250px", "body_max_width": "none"}
