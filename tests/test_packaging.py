"""What ships with the package and describes it: ``py.typed``, the classifiers, the
changelog and the citation file."""

from __future__ import annotations

import re
import tomllib
from importlib import resources
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
SETUPTOOLS = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))[
    "tool"]["setuptools"]


def test_py_typed_is_in_the_package_and_its_package_data():
    marker = resources.files("coopkin_sym").joinpath("py.typed")
    assert marker.is_file() and marker.read_text() == ""
    assert "py.typed" in SETUPTOOLS["package-data"]["coopkin_sym"]
    assert "Typing :: Typed" in PROJECT["classifiers"]


def test_the_classifiers_agree_with_the_project():
    classifiers = PROJECT["classifiers"]
    assert len(classifiers) == len(set(classifiers))
    low = re.fullmatch(r">=3\.(\d+)", PROJECT["requires-python"]).group(1)
    assert f"Programming Language :: Python :: 3.{low}" in classifiers
    # the license is given as an SPDX expression, which excludes a license classifier
    assert PROJECT["license"] == "BSD-3-Clause"
    assert not [c for c in classifiers if c.startswith("License ::")]


def test_the_changelog_has_an_unreleased_section_and_the_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert text.startswith("# Changelog\n")
    assert "Keep a Changelog" in text
    sections = re.findall(r"^## \[(.+?)\]", text, re.MULTILINE)
    assert sections[0] == "Unreleased"
    assert re.search(r"^### Added$", text, re.MULTILINE)
    assert f"is {PROJECT['version']};" in text


def test_the_citation_file_is_cff_1_2_0_with_the_software_and_the_paper():
    data = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert {"cff-version", "message", "title", "authors"} <= set(data)
    assert data["cff-version"] == "1.2.0"
    assert data["type"] == "software"
    assert data["version"] == PROJECT["version"]
    assert data["license"] == PROJECT["license"]
    assert data["authors"] == [{"name": a["name"]} for a in PROJECT["authors"]]
    paper = data["preferred-citation"]
    assert paper["type"] == "conference-paper"
    assert paper["title"] == ("Mobility and Kinematic Analysis of General Cooperating "
                              "Robot Systems")
    assert [a["family-names"] for a in paper["authors"]] == ["Bicchi", "Melchiorri",
                                                             "Balluchi"]
    assert paper["year"] == 1992
    assert "International Conference on Robotics and Automation (ICRA)" in paper[
        "conference"]["name"]
    assert all(isinstance(a["given-names"], str) for a in paper["authors"])
