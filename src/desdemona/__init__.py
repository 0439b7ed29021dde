"""desdemona: optimal motion cueing for the Desdemona centrifuge-based motion simulator.

The data flow, one module per concept: parameters (:mod:`params`) -> model (:mod:`kinematics`,
:mod:`dynamics`, :mod:`configs`, :mod:`model`) -> perception -> desired path (:mod:`profiles`) ->
a session's choices (:mod:`session`) -> problem (:mod:`problem`, :mod:`transcription`) -> solver
(:mod:`offline`; :mod:`mpc` and :mod:`online`) -> plan (:mod:`plan`) -> checked trajectory
(:mod:`simulate`) -> metrics -> report and figures. The layers are in the README. The thesis "An optimal controller for Desdemona for an optimal feeling"
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

from desdemona._version import __version__

# The names of the top level, each loaded from its module on first use (PEP 562): `import desdemona`
# (and the command line, which must answer a Ctrl-C while CasADi and NumPy load) stays fast.
_EXPORTS = {
    "CONFIGURATIONS": "configs", "Configuration": "configs", "Limits": "configs", "get_configuration": "configs",
    "Model": "model",
    "OptimizeOptions": "offline", "Result": "offline", "optimize": "offline",
    "MPCOptions": "mpc", "OnlineOptions": "online", "OnlineResult": "online", "run_online": ("online", "run"),
    "Body": "params", "JointLimits": "params", "MachineParams": "params", "ParameterError": "params",
    "default_params": "params", "load_params": "params", "thesis_toy_params": "params",
    "Plan": "plan",
    "ProblemOptions": "problem",
    "PROFILES": "profiles", "DesiredPath": "profiles", "ProfileError": "profiles",
    "load_path": ("profiles", "load"),
    "LimitViolation": "simulate",
}


def __getattr__(name: str):
    import importlib

    if name == "metrics":
        return importlib.import_module("desdemona.metrics")
    if name not in _EXPORTS:
        raise AttributeError(f"module 'desdemona' has no attribute {name!r}")
    module, attribute = _EXPORTS[name] if isinstance(_EXPORTS[name], tuple) else (_EXPORTS[name], name)
    value = getattr(importlib.import_module(f"desdemona.{module}"), attribute)
    globals()[name] = value
    return value


def __dir__():
    return sorted([*globals(), *_EXPORTS, "metrics"])


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
