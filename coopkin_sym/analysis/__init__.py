"""The analysis layer: kinematics, the seven numbers, and where they change.

:mod:`~coopkin_sym.analysis.kinematics` builds ``G``, ``D`` and ``H`` over
``Q(t, L)``; :mod:`~coopkin_sym.analysis.mobility` decomposes ``Q`` into the
subspaces, blocks and maps of the paper and counts them; :mod:`~coopkin_sym.analysis.sweep`
evaluates the numbers at many points; :mod:`coopkin_sym.analysis.locus` finds where
they change. Results are exact data; wording lives in :mod:`coopkin_sym.present`.
This layer imports only from the model and exact layers below it.

Example
-------
>>> from coopkin_sym.analysis.mobility import analyze
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> model = load_model("paper-case1-hard")
>>> analyze(model, Configuration.parse(model, "q1=pi/2,q2=pi/2")).numbers.Nm
3
"""
