"""desdemona: optimal motion cueing for the Desdemona centrifuge-based motion simulator.

The data flow, one module per concept: parameters (:mod:`params`) -> model (:mod:`kinematics`,
:mod:`dynamics`, :mod:`configs`, :mod:`model`) -> perception -> profile -> problem -> solver
(:mod:`offline`, :mod:`online`) -> plan (:mod:`plan`) -> checked trajectory (:mod:`simulate`) ->
metrics -> report and figures. The thesis "An optimal controller for Desdemona for an optimal feeling"
is the specification; docstrings cite its sections and equations.

The main jobs from one import::

    import desdemona as dd

    path = dd.load_path("catapult")                     # or a CSV file
    model = dd.Model(dd.default_params(), "yaw-track-cabin")
    result = dd.optimize(path, model)                   # off-line, checked
    live = dd.run_online(dd.load_path("dfs-catapult"), dd.Model(config="dfs"))
    dd.metrics.of_trajectory(result.trajectory, model.config.joint_names).headline()
    result.to_dataframe()                               # with pandas installed
"""

from desdemona import metrics
from desdemona._version import __version__
from desdemona.configs import CONFIGURATIONS, Configuration, Limits, get_configuration
from desdemona.model import Model
from desdemona.offline import OptimizeOptions, Result, optimize
from desdemona.online import MPCOptions, OnlineOptions, OnlineResult
from desdemona.online import run as run_online
from desdemona.params import (
    Body,
    JointLimits,
    MachineParams,
    ParameterError,
    default_params,
    load_params,
    thesis_toy_params,
)
from desdemona.plan import Plan
from desdemona.problem import ProblemOptions
from desdemona.profiles import PROFILES, DesiredPath, ProfileError
from desdemona.profiles import load as load_path
from desdemona.simulate import LimitViolation

__all__ = [
    "CONFIGURATIONS",
    "PROFILES",
    "Body",
    "Configuration",
    "DesiredPath",
    "JointLimits",
    "LimitViolation",
    "Limits",
    "MPCOptions",
    "MachineParams",
    "Model",
    "OnlineOptions",
    "OnlineResult",
    "OptimizeOptions",
    "ParameterError",
    "Plan",
    "ProblemOptions",
    "ProfileError",
    "Result",
    "default_params",
    "get_configuration",
    "load_params",
    "load_path",
    "metrics",
    "optimize",
    "run_online",
    "thesis_toy_params",
    "__version__",
]
