"""desdemona: optimal motion cueing for the Desdemona centrifuge-based motion simulator.

The data flow, one module per concept: parameters (:mod:`params`) -> model (:mod:`kinematics`,
:mod:`dynamics`, :mod:`configs`, :mod:`model`) -> perception -> profile -> problem -> solver -> checked
trajectory -> report. The thesis "An optimal controller for Desdemona for an optimal feeling" is the
specification; docstrings cite its sections and equations.
"""

from desdemona.configs import CONFIGURATIONS, Configuration, get_configuration
from desdemona.model import Model
from desdemona.params import (
    Body,
    JointLimits,
    MachineParams,
    ParameterError,
    default_params,
    load_params,
    thesis_toy_params,
)

__version__ = "0.1.0"

__all__ = [
    "CONFIGURATIONS",
    "Body",
    "Configuration",
    "JointLimits",
    "MachineParams",
    "Model",
    "ParameterError",
    "default_params",
    "get_configuration",
    "load_params",
    "thesis_toy_params",
    "__version__",
]
