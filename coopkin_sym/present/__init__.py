"""The presentation layer: every word, table, report and picture the package makes.

Sentences (:mod:`~coopkin_sym.present.sentences`), locus reports in Markdown, HTML,
LaTeX and JSON (:mod:`~coopkin_sym.present.report`, read back by
:mod:`~coopkin_sym.present.report_input`), pictures of systems and loci
(:mod:`~coopkin_sym.present.draw`, :mod:`~coopkin_sym.present.locus_plot`), and files
written whole or not at all (:mod:`~coopkin_sym.present.files`). It reads the exact
results of :mod:`coopkin_sym.analysis` and never decides anything itself.

Example
-------
>>> from coopkin_sym import load
>>> from coopkin_sym.present.sentences import sentences
>>> sentences(load("paper-case1-hard").analyze())[0].startswith("Nm = 2")
True
"""
