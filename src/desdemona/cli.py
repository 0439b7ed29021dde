"""The ``desdemona`` command: thin wrappers around the library, ``main(argv) -> exit code``."""

from __future__ import annotations

import argparse
import sys

import numpy as np

from desdemona import __version__
from desdemona.configs import CONFIGURATIONS, get_configuration
from desdemona.model import Model
from desdemona.params import BUILTIN_SETS, ParameterError, load_params

EXIT_USAGE = 2


class UserError(Exception):
    """Bad input from the user: reported as one line on stderr with exit code 2."""


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        return args.run(args)
    except (UserError, ParameterError) as exc:
        print(f"desdemona: error: {exc}", file=sys.stderr)
        return EXIT_USAGE


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="desdemona",
        description="Optimal motion cueing for the Desdemona simulator.")
    parser.add_argument("--version", action="version", version=f"desdemona {__version__}")
    sub = parser.add_subparsers(title="commands", required=True, metavar="COMMAND")

    model = sub.add_parser(
        "model", help="print the machine model of a configuration and one sample evaluation",
        description="Print the joints, limits and bodies of a configuration and evaluate the model "
                    "(path S, torques, power, inertia) at one sample state.")
    _add_machine_options(model)
    model.set_defaults(run=_run_model)
    return parser


def _add_machine_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--config", default="full", metavar="NAME",
                        help=f"configuration, one of: {', '.join(CONFIGURATIONS)} (default: full)")
    parser.add_argument("--params", metavar="FILE",
                        help="TOML file overriding any subset of the machine parameters")
    parser.add_argument("--base", choices=BUILTIN_SETS, default=None,
                        help="built-in parameter set to start from (default: default)")


def _machine(args) -> Model:
    try:
        config = get_configuration(args.config)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    return Model(load_params(args.params, base=args.base), config)


def _run_model(args) -> int:
    model = _machine(args)
    print(describe(model))
    return 0


def describe(model: Model) -> str:
    """A human-readable summary of a model and its values at one sample state."""
    p, c = model.params, model.config
    lines = [f"Desdemona model: parameters '{p.name}', configuration '{c.name}'",
             f"  {c.description}",
             f"  gravity {p.gravity:g} m/s^2, head offset {list(p.head_offset)} m (cabin coordinates)",
             "", "Joints (limits; * = free in this configuration):",
             f"  {'':2}{'joint':<14}{'position':>18}{'velocity':>14}{'acceleration':>16}"
             f"{'force/torque':>16}{'power':>12}"]
    for i, j in enumerate(p.joints):
        rev = j.kind == "revolute"
        scale, unit = (180.0 / np.pi, "deg") if rev else (1.0, "m")
        if j.position is None:
            pos = "unbounded"
        else:
            pos = f"[{j.position[0] * scale:g}, {j.position[1] * scale:g}] {unit}"
        held = "" if i in c.free else f"  held at {c.fixed[i] * scale:g} {unit}"
        lines.append(
            f"  {'*' if i in c.free else ' '} q{i + 1} {j.name:<11}{pos:>18}"
            f"{f'{j.velocity * scale:.4g} {unit}/s':>14}{f'{j.acceleration * scale:.4g} {unit}/s2':>16}"
            f"{f'{j.effort / 1e3:.4g} ' + ('kN*m' if rev else 'kN'):>16}{f'{j.power / 1e3:.4g} kW':>12}{held}")
    lines += ["", "Bodies:"]
    for b in p.bodies:
        lines.append(f"  {b.name:<15} {b.mass:8g} kg  com {list(b.com)} m  "
                     f"inertia diag {[round(b.inertia[k][k], 6) for k in range(3)]} kg*m^2")
    # A sample state: every free joint moving at a third of its velocity and acceleration limits.
    lim = model.limits
    q = np.where(np.isfinite(lim["position_max"]), 0.5 * lim["position_max"], 0.3)
    qd, qdd = lim["velocity"] / 3.0, lim["acceleration"] / 3.0
    S = model.S(q, qd, qdd)
    tau = model.tau(q, qd, qdd)
    power = model.power(q, qd, qdd)
    eig = np.linalg.eigvalsh(model.mass_matrix(q))
    fmt = lambda v: "[" + ", ".join(f"{x:.4g}" for x in v) + "]"  # noqa: E731
    lines += ["", "Sample state (free joints at 1/3 of their rate and acceleration limits):",
              f"  q    = {fmt(q)}", f"  qd   = {fmt(qd)}", f"  qdd  = {fmt(qdd)}",
              f"  omega_cabin = {fmt(S[:3])} rad/s",
              f"  f_cabin     = {fmt(S[3:])} m/s^2   |f| = {np.linalg.norm(S[3:]):.4g} m/s^2",
              f"  tau         = {fmt(tau)}   (use {fmt(np.abs(tau) / lim['effort'])} of the limits)",
              f"  power       = {fmt(power)} W (use {fmt(np.abs(power) / lim['power'])} of the limits)",
              f"  inertia eigenvalues = {fmt(eig)}"]
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
