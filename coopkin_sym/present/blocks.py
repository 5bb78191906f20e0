"""One block of a result as LaTeX, named, for a notebook's ``IPython.display.Math``.

Example
-------
>>> import sympy as sp
>>> named_latex("C_{11}", sp.Matrix([[1], [0]]))
'C_{11} = \\\\left[\\\\begin{matrix}1\\\\\\\\0\\\\end{matrix}\\\\right]'
"""

from __future__ import annotations

import sympy as sp


def named_latex(name: str, matrix: sp.Matrix) -> str:
    """``name = <matrix>`` as LaTeX, an empty block as the empty set.

    Example
    -------
    >>> named_latex("C_{23}", sp.zeros(2, 0))
    'C_{23} = \\\\emptyset'
    """
    body = sp.latex(matrix) if 0 not in matrix.shape else r"\emptyset"
    return f"{name} = {body}"


__all__ = ["named_latex"]
