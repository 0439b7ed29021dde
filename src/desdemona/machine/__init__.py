"""The machine: its parameters (:mod:`.params`, thesis appendix A), kinematics and dynamics
(:mod:`.kinematics`, :mod:`.dynamics`, appendices A and B), the configurations that fix some joints and
say what the rest can do (:mod:`.configs`), the model a solver uses (:mod:`.model`), and joint motion
plans with their braking (:mod:`.plan`).

Only this folder knows joint indices and configuration names; every other layer asks a
:class:`~desdemona.machine.configs.Configuration` what it can do."""
