"""The singularity locus: where in configuration space the numbers change.

:mod:`~coopkin_sym.analysis.locus.search` runs the search and
returns a :class:`~coopkin_sym.analysis.locus.types.Locus`;
:mod:`~coopkin_sym.analysis.locus.algebra` and :mod:`~coopkin_sym.analysis.locus.witness`
solve the families and find exact witnesses; :mod:`~coopkin_sym.analysis.locus.certify`
proves the result complete where it can; :mod:`~coopkin_sym.analysis.locus.verify`
searches for points it missed, independently.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.analysis.locus.search import compute_locus
>>> locus = compute_locus(load("paper-case1-hard"))
>>> locus.generic["Nm"], len(locus.components)
(2, 5)
"""
