"""desdemona: optimal motion cueing for the Desdemona centrifuge-based motion simulator.

The folders are the layers, lowest first; a module imports only from its own folder and those below
(``tests/test_layout.py`` holds the order):

- :mod:`~desdemona.support`: CasADi helpers, interrupts, files written whole, constants;
- :mod:`~desdemona.occupant`: the person in the cabin, the vestibular model (chapter 6), head movements'
  cross-coupling and the sickness dose;
- :mod:`~desdemona.profiles`: desired paths and their sources (built-in, CSV, JSBSim, logs);
- :mod:`~desdemona.machine`: parameters, kinematics, dynamics, configurations, model, plans (appendices A, B);
- :mod:`~desdemona.check`: the independent limit check and the felt figures;
- :mod:`~desdemona.baselines`: the classical loops and the thesis' method;
- :mod:`~desdemona.cueing`: the cueing problem, its transcription and its off-line solvers (chapters 3-5, 7);
- :mod:`~desdemona.control`: the MPC, its predictors and the on-line session (section 7.5);
- :mod:`~desdemona.results`: result folders, figures, the 3D view, comparisons;
- :mod:`~desdemona.runs`: a session's choices resolved once, batches;
- :mod:`~desdemona.service`: the real-time service, its hosts and the machine stand-in;
- :mod:`~desdemona.cli`: the ``desdemona`` command.

The names below are the public Python API; module paths inside the folders may move between
versions. The thesis "An optimal controller for Desdemona for an optimal feeling" is the
specification; docstrings cite its sections and equations.

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
    "CONFIGURATIONS": "machine.configs", "Configuration": "machine.configs", "Limits": "machine.configs",
    "get_configuration": "machine.configs",
    "Model": "machine.model",
    "OptimizeOptions": "cueing.offline", "Result": "cueing.offline", "optimize": "cueing.offline",
    "MPCOptions": "control.mpc", "OnlineOptions": "control.online", "OnlineResult": "control.online",
    "run_online": ("control.online", "run"),
    "Body": "machine.params", "JointLimits": "machine.params", "MachineParams": "machine.params",
    "ParameterError": "machine.params", "default_params": "machine.params", "load_params": "machine.params",
    "thesis_toy_params": "machine.params",
    "Plan": "machine.plan",
    "ProblemOptions": "cueing.formulation",
    "PROFILES": "profiles", "DesiredPath": "profiles", "ProfileError": "profiles",
    "load_path": ("profiles", "load"),
    "LimitViolation": "check.simulate",
}


#: Modules of the public API by their short names: the felt figures and the vestibular model, which
#: tools that read result folders use (``from desdemona import perception``).
_MODULES = {"metrics": "desdemona.check.metrics", "perception": "desdemona.occupant.perception"}


def __getattr__(name: str):
    import importlib

    if name in _MODULES:
        return importlib.import_module(_MODULES[name])
    if name not in _EXPORTS:
        raise AttributeError(f"module 'desdemona' has no attribute {name!r}")
    module, attribute = _EXPORTS[name] if isinstance(_EXPORTS[name], tuple) else (_EXPORTS[name], name)
    value = getattr(importlib.import_module(f"desdemona.{module}"), attribute)
    globals()[name] = value
    return value


def __dir__():
    return sorted([*globals(), *_EXPORTS, *_MODULES])


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
    "perception",
    "optimize",
    "run_online",
    "thesis_toy_params",
    "__version__",
]
