"""Validated, immutable description of a cooperating robot system.

A model is what a model file (YAML, JSON or a Python dict: docs/model-format.md) says,
checked and with every number exact: a SymPy ``Rational`` or a polynomial with
rational coefficients in the declared parameters (each a positive ``Symbol``).
Nothing here computes kinematics; see :mod:`coopkin_sym.analysis.kinematics`.

Example
-------
>>> from coopkin_sym.model.model import load_model
>>> m = load_model({
...     "name": "one arm", "parameters": ["L"],
...     "arms": [{"name": "a", "joints": [
...         {"name": "q1", "type": "revolute", "axis": [0, 0, 1], "point": [0, 0, 0]}]}],
...     "contacts": [{"name": "c", "link": "a/1", "point": ["L", 0, 0],
...                   "normal": [1, 0, 0], "model": "hard"}]})
>>> [j.name for j in m.joints]
['q1']
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import sympy as sp

from coopkin_sym.errors import ArgumentTypeError, ModelError
from coopkin_sym.model.arm_entries import read_arms
from coopkin_sym.model.contact_entries import _planar_problems, read_contacts
from coopkin_sym.model.entries import (
    RESERVED_NAMES,
    _brief,
    _Names,
    _ObjectIn,
    _placement,
    _TopIn,
    _UndeclaredProblem,
    _validate,
)
from coopkin_sym.model.examples import example_path, list_examples
from coopkin_sym.model.structure import (
    CONTACT_MODELS,
    JOINT_TYPES,
    PLANAR_TWIST,
    SPATIAL_TWIST,
    Arm,
    Contact,
    ContactModel,
    Joint,
    JointType,
    Model,
    Vector,
)
from coopkin_sym.model.trees import TreeError, check_tree, read_file

__all__ = ["CONTACT_MODELS", "JOINT_TYPES", "PLANAR_TWIST", "RESERVED_NAMES", "SPATIAL_TWIST",
           "Arm", "Contact", "ContactModel", "Joint", "JointType", "Model", "ModelError",
           "Vector", "list_examples", "load_model", "model_of"]


def _build(tree: object, source: str | None, default_name: str) -> Model:
    """Validate a model tree and convert it into a :class:`Model`."""
    problems: list[str] = []
    if tree is None:
        raise ModelError(["(top level): the model is empty"], source)
    top, top_bad = _validate(_TopIn, tree, "", problems)
    if top is None:
        raise ModelError(problems, source)
    names = _Names(problems)
    parameters, parameters_unknown = _parameters(top.parameters or [], names, problems)
    parameters_unknown |= "parameters" in top_bad   # which names were meant is unknown
    arms = read_arms(top.arms or [], top_bad, parameters, names, problems, source)
    contacts, contact_paths = read_contacts(top.contacts or [], top_bad, parameters, names,
                                            arms, problems)
    object_frame = None
    if top.object is not None:
        entry, bad = _validate(_ObjectIn, top.object, "object", problems)
        if entry is not None and not bad:
            object_frame = _placement({"xyz": entry.point, "rpy": entry.rpy}, "object",
                                      parameters, problems, point_key="point")
            if object_frame is not None:
                object_frame = (sp.ImmutableMatrix(object_frame[0]), object_frame[1])
    if top.planar:
        _planar_problems(arms.arms, arms.joint_paths,
                         zip(contact_paths, contacts, strict=True), object_frame, problems)
    if parameters_unknown:   # numbers that use a parameter: its entry has the problem
        problems[:] = [p for p in problems if not isinstance(p, _UndeclaredProblem)]
    if problems:
        raise ModelError([str(p) for p in problems], source)
    return Model(name=top.name if top.name is not None else default_name,
                 parameters=tuple(parameters.values()), arms=tuple(arms.arms),
                 contacts=tuple(contacts), source=source, object_frame=object_frame,
                 snapped=tuple(arms.snapped), planar=bool(top.planar),
                 renamed=tuple(arms.notes[0]), ignored=tuple(arms.notes[1]))


def _parameters(raw: list[Any], names: _Names, problems: list[str]
                ) -> tuple[dict[str, sp.Symbol], bool]:
    """The declared parameters (positive symbols), and whether a name meant could not
    be read."""
    parameters: dict[str, sp.Symbol] = {}
    unknown = False
    for i, pname in enumerate(raw):
        path = f"parameters[{i}]"
        if not isinstance(pname, str):
            problems.append(f"{path}: expected a name, got {_brief(pname)}")
            unknown = True
        elif pname in names.where:
            names.add(pname, path, symbol=True)   # a duplicate: declared all the same
        elif names.add(pname, path, symbol=True):
            parameters[pname] = sp.Symbol(pname, positive=True)
        else:
            unknown = True
    return parameters, unknown


def _read_tree(path: Path, source: str) -> object:
    """Read a YAML or JSON file into a plain tree (see :mod:`coopkin_sym.model.trees`: every
    float kept as its text, budgets on size, nesting and aliases)."""
    if path.suffix.lower() == ".urdf":
        raise ModelError([f"a URDF file describes one robot, not a cooperating system: "
                          f"write a model file with an arm 'urdf: {path.name}' and "
                          f"contacts on its links (docs/model-format.md, Arms from URDF "
                          f"files)"], source)
    try:
        return read_file(path)
    except TreeError as exc:
        raise ModelError([str(exc)], source) from None


def _source_name(name: str) -> str:
    """A file name as shown in messages (very long ones shortened)."""
    return name if len(name) <= 200 else name[:120] + "..." + name[-40:]


def model_of(source: Any) -> Model:
    """The model of ``source``: a :class:`Model` itself, or the ``.model`` of an object
    that holds one (a :class:`~coopkin_sym.System`, an analysis). The layers below the
    public facade take either, without importing it.

    Example
    -------
    >>> from coopkin_sym import load
    >>> model_of(load("paper-case1-hard")).joint_names
    ('q1', 'q2')
    """
    model = source if isinstance(source, Model) else getattr(source, "model", None)
    if not isinstance(model, Model):
        raise ArgumentTypeError(f"expected a model or a system, got {type(source).__name__}")
    return model


def load_model(source: str | os.PathLike[str] | Mapping[str, Any]) -> Model:
    """Load and validate a model (the format of docs/model-format.md).

    Parameters
    ----------
    source : str, path or mapping
        A ``.yaml``/``.yml``/``.json`` file, the name of a shipped example
        (``"paper-case1-hard"``, see :mod:`coopkin_sym.model.examples`), or the same tree
        as a Python mapping.

    Returns
    -------
    Model
        Every number exact (``Rational`` or a polynomial in the parameters, which are
        positive ``Symbol``).

    Raises
    ------
    ModelError
        With one line per problem, each naming the entry
        (``contacts[1].normal: not a unit vector``), and the file when there is one.

    Example
    -------
    >>> m = load_model("paper-case2-hard")
    >>> m.arms[0].joints[3].type, m.contacts[1].point
    ('prismatic', (3*L, L, L))
    """
    if isinstance(source, Mapping):
        try:
            check_tree(source)
        except TreeError as exc:
            raise ModelError([f"(top level): {exc}"]) from None
        return _build(source, None, "unnamed")
    if not isinstance(source, str | os.PathLike):
        raise ModelError([f"(top level): expected a file name, an example name or a "
                          f"mapping, got {type(source).__name__}"])
    name = os.fspath(source)
    if not isinstance(name, str):
        raise ModelError(["(top level): expected a file name as text, got bytes"])
    shown = _source_name(name)
    path = Path(name)
    try:
        exists = path.exists()
    except (OSError, ValueError) as exc:
        reason = getattr(exc, "strerror", None) or str(exc)
        raise ModelError([f"cannot read the file: {reason}"], shown) from None
    if not exists:
        if isinstance(source, str) and source in list_examples():
            path = example_path(source)
            return _build(_read_tree(path, str(path)), str(path), path.stem)
        shipped = ", ".join(list_examples())
        close = difflib.get_close_matches(name, list_examples(), n=1) \
            if isinstance(source, str) else []
        hint = f"; did you mean {close[0]}?" if close else ""
        raise ModelError([f"no such file (nor a shipped example: {shipped}){hint}"], shown)
    return _build(_read_tree(path, shown), shown, path.stem)
