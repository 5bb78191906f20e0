"""The public entry point: a loaded system and its analyses.

Example
-------
>>> from coopkin_sym import load
>>> system = load("paper-case2-hard")
>>> system.analyze().numbers.as_dict()["Nm"]
8
>>> system.analyze(generic=True).numbers.Nc
6
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping

from .configuration import Configuration
from .mobility import Analysis, analyze
from .model import Model, load_model


class System:
    """A validated cooperating robot system, ready to analyze.

    Parameters
    ----------
    model
        The validated model (see :func:`coopkin_sym.model.load_model`).
    """

    def __init__(self, model: Model):
        self.model = model

    @property
    def name(self) -> str:
        return self.model.name

    @property
    def joint_names(self) -> tuple[str, ...]:
        return self.model.joint_names

    def configuration(self, at: str | Mapping | None = None,
                      free: Iterable[str] | str | None = None) -> Configuration:
        """Parse ``at`` (``"q1=pi/2,L=1000"`` or a mapping) and the free joints."""
        return Configuration.parse(self.model, at, free)

    def analyze(self, at: str | Mapping | Configuration | None = None, *,
                generic: bool = False, free: Iterable[str] | None = None) -> Analysis:
        """Exact mobility and kinematic analysis.

        Parameters
        ----------
        at
            Values of joint variables (angles in SymPy syntax, displacements) and
            parameters; unset joints are at home (q = 0), unset parameters symbolic.
        generic
            Keep every joint variable symbolic (the generic analysis over Q(t, L)).
        free
            Joint names to keep symbolic (the rest at their values).
        """
        if isinstance(at, Configuration):
            config = at
        else:
            config = self.configuration(at, "all" if generic else free)
        return analyze(self.model, config)

    def sweep(self, points, *, at: str | Mapping | None = None, executor=None,
              progress: bool = False, chunk: int = 16384):
        """Exact numbers at many points, fast (see :func:`coopkin_sym.sweep.sweep`).

        ``points`` is a grid (:func:`coopkin_sym.sweep.grid`) or an iterable of points
        (``"q1=pi/2,q2=0"`` or mappings); ``executor`` any
        :class:`concurrent.futures.Executor`.

        Example
        -------
        >>> from coopkin_sym import load
        >>> res = load("paper-case1-hard").sweep(["q1=pi/2,q2=pi/2", "q1=0"])
        >>> res.numbers[:, 0].tolist()
        [3, 2]
        """
        from .sweep import sweep

        return sweep(self, points, at=at, executor=executor, progress=progress, chunk=chunk)

    def __repr__(self) -> str:
        return (f"System({self.model.name!r}: {len(self.model.arms)} arms, "
                f"{len(self.model.joints)} joints, {len(self.model.contacts)} contacts)")


def load(source: str | os.PathLike | Mapping) -> System:
    """Load a model file (YAML or JSON), a dict, or a shipped example by name."""
    return System(load_model(source))
