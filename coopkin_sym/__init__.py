"""coopkin_sym: exact mobility and kinematic analysis of cooperating robot systems.

Given arms (revolute and prismatic joints), one object and the contacts between them
(hard finger, soft finger, complete constraint, frictionless), it computes exactly
the mobility ``Nm``, connectivity ``Nc``, indeterminacy ``Ni`` and redundancy ``Nr``
of the system (Bicchi, Melchiorri and Balluchi, ICRA 1992), the subspaces behind
them and the joint-to-object velocity maps, over the rationals or over fields of
rational functions of the joint variables and link lengths.

Example
-------
>>> import coopkin_sym
>>> a = coopkin_sym.load("paper-case1-hard").analyze()
>>> a.numbers.Nm, a.numbers.Ni
(2, 1)
"""

from coopkin_sym.analysis.mobility import Analysis, BlockTooLarge, InfeasibleMotion, Motion
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.errors import CoopkinError
from coopkin_sym.model.configuration import Configuration, ConfigurationError
from coopkin_sym.model.model import Model, ModelError
from coopkin_sym.system import System, load

__all__ = [
    "Analysis",
    "BlockTooLarge",
    "Configuration",
    "ConfigurationError",
    "CoopkinError",
    "InfeasibleMotion",
    "Model",
    "ModelError",
    "Motion",
    "Numbers",
    "System",
    "load",
]
__version__ = "0.1.0"
