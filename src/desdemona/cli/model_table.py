"""The ``desdemona model`` command's text: a configuration's joints, limits and bodies, and the model
evaluated at one sample state."""

from __future__ import annotations

import numpy as np

from desdemona.machine.model import Model


def describe(model: Model) -> str:
    """A human-readable summary of a model and its values at one sample state."""
    p, c = model.params, model.config
    lines = [f"Desdemona model: parameters '{p.name}', configuration '{c.name}'",
             f"  {c.description}",
             f"  gravity {p.gravity:g} m/s^2, head offset {list(p.head_offset)} m (cabin coordinates)",
             "", "Joints (limits; * = free in this configuration):"]
    wide = max(len(j.name) for j in p.joints) + 4  # "q1 " and the name, a space after the longest
    lines.append(f"  {'':2}{'joint':<{wide}}{'position':>18}{'velocity':>14}{'acceleration':>16}"
                 f"{'force/torque':>16}{'power':>12}")
    for i, j in enumerate(p.joints):
        rev = j.kind == "revolute"
        scale, unit = (180.0 / np.pi, "deg") if rev else (1.0, "m")
        if j.position is None:
            pos = "unbounded"
        else:
            pos = f"[{j.position[0] * scale:g}, {j.position[1] * scale:g}] {unit}"
        held = "" if (position := c.held.get(i)) is None else f"  held at {position * scale:g} {unit}"
        lines.append(
            f"  {'*' if position is None else ' '} {f'q{i + 1} {j.name}':<{wide}}{pos:>18}"
            f"{f'{j.velocity * scale:.4g} {unit}/s':>14}{f'{j.acceleration * scale:.4g} {unit}/s2':>16}"
            f"{f'{j.effort / 1e3:.4g} ' + ('kN*m' if rev else 'kN'):>16}{f'{j.power / 1e3:.4g} kW':>12}{held}")
    lines += ["", "Bodies:"]
    for b in p.bodies:
        lines.append(f"  {b.name:<15} {b.mass:8g} kg  com {list(b.com)} m  "
                     f"inertia diag {[round(b.inertia[k][k], 6) for k in range(3)]} kg*m^2")
    # A sample state: every free joint moving at a third of its velocity and acceleration limits.
    lim = model.limits
    q = np.where(np.isfinite(lim.position_max), 0.5 * lim.position_max, 0.3)
    qd, qdd = lim.velocity / 3.0, lim.acceleration / 3.0
    S = model.S(q, qd, qdd)
    tau = model.tau(q, qd, qdd)
    power = model.power(q, qd, qdd)
    eig = np.linalg.eigvalsh(model.mass_matrix(q))
    fmt = lambda v: "[" + ", ".join(f"{x:.4g}" for x in v) + "]"  # noqa: E731
    lines += ["", "Sample state (free joints at 1/3 of their rate and acceleration limits):",
              f"  q    = {fmt(q)}", f"  qd   = {fmt(qd)}", f"  qdd  = {fmt(qdd)}",
              f"  omega_cabin = {fmt(S[:3])} rad/s",
              f"  f_cabin     = {fmt(S[3:])} m/s^2   |f| = {np.linalg.norm(S[3:]):.4g} m/s^2",
              f"  tau         = {fmt(tau)}   (use {fmt(np.abs(tau) / lim.effort)} of the limits)",
              f"  power       = {fmt(power)} W (use {fmt(np.abs(power) / lim.power)} of the limits)",
              f"  inertia eigenvalues = {fmt(eig)}"]
    return "\n".join(lines)
