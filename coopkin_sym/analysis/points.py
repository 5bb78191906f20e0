"""When a point analysis takes the compiled path: from a model's second configuration
on (with the same parameter values), so that one analysis never pays for compiling
``Q`` and the compiler (and numpy) is not even imported for it.

Example
-------
>>> from coopkin_sym.model import load_model
>>> from coopkin_sym.model.configuration import Configuration
>>> model = load_model("paper-case1-hard")
>>> config = Configuration.parse(model, "q1=pi/2,q2=pi/2,L=1")
>>> point_ranks(model, config) is None, point_ranks(model, config)
(True, (6, (5, 5, 2)))
"""

from __future__ import annotations

from collections import OrderedDict

from coopkin_sym.model.configuration import Configuration
from coopkin_sym.model.model import Model

_SEEN: OrderedDict[tuple, Model] = OrderedDict()


def point_ranks(model: Model, config: Configuration
                ) -> tuple[int, tuple[int, int, int]] | None:
    """``m`` and the exact ranks of ``Q``, ``H G^T`` and ``H D`` on the compiled path
    (see :func:`coopkin_sym.analysis.sweep.compiled.point_ranks`), or ``None`` for the
    first point of a model and parameter values, a symbolic joint, or a displacement
    that depends on a symbolic parameter."""
    if config.free:
        return None
    key = (id(model), tuple(sorted((str(k), str(v)) for k, v in config.parameters.items())))
    if _SEEN.get(key) is not model:
        _SEEN[key] = model
        while len(_SEEN) > 64:
            _SEEN.popitem(last=False)
        return None
    _SEEN.move_to_end(key)
    from coopkin_sym.analysis.sweep.compiled import point_ranks as compiled_ranks

    return compiled_ranks(model, config)
