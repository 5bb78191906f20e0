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

from coopkin_sym.analysis.batch import BatchResult
from coopkin_sym.analysis.irrational import IrrationalAnalysis
from coopkin_sym.analysis.locus.types import Component, Locus
from coopkin_sym.analysis.mobility import Analysis, Motion
from coopkin_sym.analysis.numbers import Numbers
from coopkin_sym.analysis.sweep import SweepResult
from coopkin_sym.errors import (
    BlockTooLarge,
    ConfigurationError,
    CoopkinError,
    InfeasibleMotion,
    ManipulabilityError,
    ModelError,
)
from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model
from coopkin_sym.present import display as _display  # noqa: F401  (installs the renderers)
from coopkin_sym.system import System, analyze_many, load

__all__ = [
    "Analysis",
    "BatchResult",
    "BlockTooLarge",
    "Component",
    "Configuration",
    "ConfigurationError",
    "CoopkinError",
    "InfeasibleMotion",
    "IrrationalAnalysis",
    "Locus",
    "ManipulabilityError",
    "Model",
    "ModelError",
    "Motion",
    "Numbers",
    "SweepResult",
    "System",
    "analyze_many",
    "load",
]
__version__ = "0.1.0"
