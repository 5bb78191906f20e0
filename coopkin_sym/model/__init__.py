"""The model layer: what a cooperating robot system is, validated and exact.

Model files (YAML, JSON or a dict) become a :class:`~coopkin_sym.model.model.Model`:
arms of revolute and prismatic joints, contacts with their models, the object, and
the symbolic parameters, every number exact. Configurations (values of the joint
variables and parameters) are read by :mod:`coopkin_sym.model.configuration`; the
shipped examples live in :mod:`coopkin_sym.model.examples`; builders of families of
systems (hands, legged vehicles) in :mod:`coopkin_sym.model.builders`. The model
layer imports only from :mod:`coopkin_sym.exact` and the package's base modules
(errors, limits).

Example
-------
>>> from coopkin_sym.model import load_model
>>> load_model("paper-case1-hard").joint_names
('q1', 'q2')
"""

from coopkin_sym.model.model import Model, ModelError, load_model

__all__ = ["Model", "ModelError", "load_model"]
