"""Shared test support: the independent reference implementation (``independent``),
the random systems (``random_systems``), the hypothesis strategies (``strategies``)
and the large honest systems (``large_systems``) live next to this file and are
importable from every test directory.

The test directories mirror the package's layers: ``exact/``, ``model/``,
``analysis/``, ``present/``; whole-package tests (the CLI, the architecture, the
no-evaluation and fuzz tests) sit here.
"""

from __future__ import annotations

import sys
from pathlib import Path

HERE = str(Path(__file__).resolve().parent)
if HERE not in sys.path:
    sys.path.insert(0, HERE)
