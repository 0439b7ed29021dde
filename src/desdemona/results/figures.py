"""Figures: every PNG that desdemona draws, in one module.

- :func:`draw_result`: the figures of a result folder: ``path.png`` S against S_d per channel (thesis
  figures 5.7-5.16 (a)); ``joints.png`` joint positions and rates ((b), (c)); ``limits.png``
  normalised force/torque and power with the +-1 limit lines ((d), (e)); for a modulus path
  ``modulus.png``, M_d against M and their difference (figure 7.3 (a), (b)); with perception
  ``perceived.png``; ``felt.png`` (:func:`draw_felt`); off-line ``limit_prices.png``
  (:mod:`desdemona.results.pricefigure`).
- :func:`draw_online`: ``online.png`` (like thesis figures 7.5/7.6, with the classical loop),
  ``online_felt.png`` (:func:`draw_felt` of the MPC beside the classical loop) and ``compute_time.png``
  (compute time per cycle against the deadline).
- :func:`draw_felt`: what the occupant feels beyond the path: the felt-direction error [deg]
  and the felt rotation per canal channel [deg/s] over time, with their thresholds
  (:mod:`desdemona.check.metrics` defines both), one column per trajectory.
- :func:`draw_suffered`: what the occupant suffers beyond the cue: the Coriolis cross-coupling of a
  standard head nod started at each instant (:mod:`desdemona.occupant.coriolis`) and the sickness dose
  building up over the session (:mod:`desdemona.occupant.sickness`), one column per trajectory
  (``suffered.png``; ``online_suffered.png`` with the classical loop beside the MPC).
- :func:`draw_comparison`: overlays of several result folders (``desdemona compare``).
- :func:`plot_bode`: Bode diagrams of a vestibular model (thesis figures 6.4, 6.6).

Figures are drawn with matplotlib's object interface (:class:`matplotlib.figure.Figure`), which needs
no display and leaves matplotlib's global backend as the caller set it. matplotlib is imported only
when a figure is drawn.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from desdemona.machine.configs import CONFIGURATIONS
from desdemona.occupant import perception
from desdemona.occupant.perception import THRESHOLDS
from desdemona.results import pricefigure

CHANNEL_LABELS = ("omega_x [rad/s]", "omega_y [rad/s]", "omega_z [rad/s]",
                  "f_x [m/s^2]", "f_y [m/s^2]", "f_z [m/s^2]")


def _figure(**kw):
    from matplotlib.figure import Figure

    return Figure(**kw)


def _save(fig, path: Path, title: str | None = None, dpi: int = 100) -> Path:
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    return path


def _limit_lines(ax) -> None:
    for bound in (-1, 1):
        ax.axhline(bound, color="r", lw=0.8, ls=":")


def draw_result(traj, summary: dict, out_dir: str | Path) -> list[Path]:
    """Draw a result's figures into ``out_dir`` from its trajectory and summary; returns their paths.

    traj : a :class:`desdemona.check.simulate.Trajectory`; summary : the result's summary.json as a dict.
    """
    out = Path(out_dir)
    joints = summary["configuration"]["free_joints"]
    limits = summary["parameters"]["joints"]
    title = f"{summary['path']['name']} on {summary['configuration']['name']}"
    paths = []

    weights = _weights(summary)

    def channels(desired, actual, labels, style, bands=None):
        fig = _figure(figsize=(11, 8))
        axes = fig.subplots(3, 2, sharex=True)
        for i, ax in enumerate(axes.T.ravel()):
            if bands is not None:  # where the felt difference is below the perception threshold
                ax.fill_between(traj.t, desired[:, i] - bands[i], desired[:, i] + bands[i], color="0.85",
                                lw=0, label="below threshold")
            ax.plot(traj.t, desired[:, i], "k-", lw=1.5, label=labels[0])
            ax.plot(traj.t, actual[:, i], style, lw=1.2, label=labels[1])
            weightless = weights is not None and weights[i] == 0.0
            ax.set_ylabel(CHANNEL_LABELS[i] + ("\n(weight 0: not in the cost)" if weightless else ""))
            ax.grid(alpha=0.3)
        axes[0, 0].legend(fontsize=8)
        for ax in axes[-1]:
            ax.set_xlabel("t [s]")
        return fig

    if traj.S_d is not None:
        paths.append(_save(channels(traj.S_d, traj.S, ("S_d (desired)", "S (Desdemona)"), "C0--"),
                           out / "path.png", title))
    paths.append(_save(_joints_figure(traj, summary), out / "joints.png", title))
    fig = _figure(figsize=(10, 6))
    axes = fig.subplots(2, 1, sharex=True)
    for k, name in enumerate(joints):
        axes[0].plot(traj.t, traj.tau[:, k] / limits[name]["effort"], label=name)
        axes[1].plot(traj.t, traj.power[:, k] / limits[name]["power"], label=name)
    for ax, label in zip(axes, ("force / max", "power / max")):
        _limit_lines(ax)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper right")
    axes[-1].set_xlabel("t [s]")
    paths.append(_save(fig, out / "limits.png", title))
    config = CONFIGURATIONS.get(summary["configuration"]["name"])
    if traj.S_d is None or (config is not None and config.takes_modulus):  # the modulus is the cue
        fig = _figure(figsize=(10, 6))
        axes = fig.subplots(2, 1, sharex=True)
        axes[0].plot(traj.t, traj.M_d, "k-", label="M_d (desired)")
        axes[0].plot(traj.t, traj.M, "C0--", label="M (Desdemona)")
        axes[0].set_ylabel("modulus [m/s^2]")
        axes[1].plot(traj.t, traj.M_d - traj.M, "C0")
        axes[1].set_ylabel("M_d - M [m/s^2]")
        axes[1].set_xlabel("t [s]")
        for ax in axes:
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        paths.append(_save(fig, out / "modulus.png", title))
    if traj.S_perc is not None:
        paths.append(_save(channels(traj.S_d_perc, traj.S_perc, ("perceived S_d", "perceived S"), "C1--",
                                    bands=THRESHOLDS), out / "perceived.png", title))
    paths.append(draw_felt([traj], [None], out / "felt.png",
                           _vestibular((summary.get("quality") or {}).get("vestibular_model")), title))
    paths.append(draw_suffered([traj], [None], out / "suffered.png", title))
    if (priced := pricefigure.draw(summary, out / "limit_prices.png", title)) is not None:
        paths.append(priced)
    return paths


def draw_suffered(trajectories, labels, path: str | Path, title: str | None = None) -> Path:
    """What the occupant suffers beyond the cue, one column per trajectory, to a PNG; returns its path.

    Top: the peak cross-coupled angular velocity [deg/s] of a pitch, roll and yaw nod of the head
    (30 deg in 0.5 s) started at each instant, with the lowest canal threshold. Middle: the vertical
    force through ISO 2631-1's W_f [m/s^2]. Bottom: the sickness incidence [%] building up: ISO's
    K_m MSDV_z of the session so far, and Bos & Bles' subjective vertical conflict model.
    trajectories : :class:`desdemona.check.simulate.Trajectory` (sharing the axes' scales); labels : a
    title per column (None: none)."""
    from desdemona.occupant import coriolis, sickness

    fig = _figure(figsize=(5.5 * len(trajectories) + 1.5, 8))
    axes = fig.subplots(3, len(trajectories), sharex=True, sharey="row", squeeze=False)
    threshold = math.degrees(float(np.min(THRESHOLDS[:3])))
    for (top, middle, bottom), traj, label in zip(axes.T, trajectories, labels):
        for k, nod in enumerate(coriolis.NODS):
            peak = coriolis.per_start(traj.t, traj.S[:, :3], nod)[0]
            top.plot(traj.t, np.degrees(peak), f"C{k}", lw=1.1, label=f"{nod.name} nod")
        top.axhline(threshold, color="r", lw=0.8, ls=":", label=f"lowest canal threshold {threshold:.2g} deg/s")
        if label:
            top.set_title(label)
        a_w = sickness.weighted_vertical(traj.t, traj.S[:, 5])
        middle.plot(traj.t, a_w, "C0", lw=1.0, label="f_z through W_f")
        bottom.plot(traj.t, sickness.K_M * sickness.msdv_so_far(traj.t, a_w), "C0", lw=1.2,
                    label="ISO 2631-1: K_m MSDV_z so far")
        bottom.plot(traj.t, sickness.conflict_incidence(traj.t, traj.S[:, 5]), "C3", lw=1.2,
                    label="Bos & Bles: vertical conflict")
        bottom.set_xlabel("t [s]")
        for ax in (top, middle, bottom):
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8, loc="upper left")
    axes[0, 0].set_ylabel("cross-coupled angular\nvelocity of a nod [deg/s]")
    axes[1, 0].set_ylabel("weighted vertical\nforce a_w [m/s^2]")
    axes[2, 0].set_ylabel("sickness incidence [%]")
    return _save(fig, Path(path), title)


def _joints_figure(traj, summary: dict):
    """Every joint of the machine over time, position and rate with their limits: the free ones as
    planned, the held ones at their positions, at rest."""
    joints = summary["configuration"]["free_joints"]
    limits = summary["parameters"]["joints"]
    held = summary["configuration"].get("held_positions")
    shown = list(limits) if held is not None else joints
    fig = _figure(figsize=(11, 1.6 * len(shown) + 1))
    axes = fig.subplots(len(shown), 2, sharex=True, squeeze=False)
    for k, name in enumerate(shown):
        revolute = limits[name]["kind"] == "revolute"
        scale, unit = (180.0 / np.pi, "deg") if revolute else (1.0, "m")
        if name in joints:
            q, qd, label = traj.q[:, joints.index(name)], traj.qd[:, joints.index(name)], name
        else:
            q, qd = np.full(len(traj.t), held[k]), np.zeros(len(traj.t))
            label = f"{name}\n(held)"  # on one line "outer_gimbal (held) [deg]" ran past its axes
        axes[k, 0].plot(traj.t, q * scale)
        axes[k, 0].set_ylabel(f"{label} [{unit}]")
        if limits[name]["position"] is not None:
            for bound in limits[name]["position"]:
                axes[k, 0].axhline(bound * scale, color="r", lw=0.8, ls=":")
        axes[k, 1].plot(traj.t, qd * scale)
        axes[k, 1].set_ylabel(f"rate [{unit}/s]")
        for bound in (-1, 1):
            axes[k, 1].axhline(bound * limits[name]["velocity"] * scale, color="r", lw=0.8, ls=":")
    for ax in axes.ravel():
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("t [s]")
    return fig


def _vestibular(name) -> perception.VestibularModel:
    """The perception model a result's metrics used, by its name; the thesis' where unknown (None, or a
    summary written before the name was kept)."""
    return perception.get_model(name) if name in perception.MODELS else perception.thesis_model()


def draw_felt(trajectories, labels, path: str | Path, vestibular: perception.VestibularModel | None = None,
              title: str | None = None) -> Path:
    """What the occupant feels beyond the path, one column per trajectory, to a PNG; returns its path.

    Top: the felt-direction error [deg] (:func:`desdemona.check.metrics.direction_error`: the angle of f to
    the desired force, or to cabin +z where the path gives only the modulus) with its assumed threshold.
    Bottom: |felt rotation| [deg/s] per canal channel (:func:`desdemona.check.metrics.felt_rotation`) with
    each channel's threshold in its colour. trajectories : :class:`desdemona.check.simulate.Trajectory`
    (several, e.g. the MPC and the classical loop, share their axes' scales); labels : a title per
    column (None: none); vestibular : default the thesis' model.
    """
    from desdemona.check import metrics

    vestibular = perception.judging(vestibular)
    thresholds = np.degrees(np.asarray(vestibular.thresholds, float))
    tilt = math.degrees(metrics.direction_threshold(vestibular.thresholds))
    fig = _figure(figsize=(5.5 * len(trajectories) + 1.5, 6.5))
    axes = fig.subplots(2, len(trajectories), sharex=True, sharey="row", squeeze=False)
    for (top, bottom), traj, label in zip(axes.T, trajectories, labels):
        f_d = None if traj.S_d is None else traj.S_d[:, 3:]
        direction = np.degrees(metrics.direction_error(traj.S[:, 3:], f_d))
        rotation = np.degrees(metrics.felt_rotation(traj.S, traj.S_d, metrics.step_of(traj.t), vestibular))
        top.plot(traj.t, direction, "C0", lw=1.2, label="angle of f to " + ("cabin +z" if f_d is None else "f_d"))
        top.axhline(tilt, color="r", lw=0.8, ls=":", label=f"threshold {tilt:.2g} deg (assumed)")
        if label:
            top.set_title(label)
        for i in range(3):
            bottom.plot(traj.t, np.abs(rotation[:, i]), f"C{i}", lw=1.1, label=f"|felt {CHANNEL_LABELS[i][:7]}|")
            bottom.axhline(thresholds[i], color=f"C{i}", lw=0.8, ls=":", label=f"threshold {thresholds[i]:.2g} deg/s")
        bottom.set_xlabel("t [s]")
        for ax in (top, bottom):
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8, loc="upper right")
    axes[0, 0].set_ylabel("felt direction error [deg]")
    axes[1, 0].set_ylabel(f"felt rotation [deg/s]\n({vestibular.name} canals)")
    return _save(fig, Path(path), title)


def _weights(summary: dict):
    """The cost's weights of S as the run used them (its options), else the path's; None if unknown."""
    problem = (summary.get("options") or {}).get("problem") or {}
    weights = problem.get("weights") or summary.get("path", {}).get("weights")
    return None if weights is None else [float(w) for w in weights]


def draw_online(result, out_dir: str | Path) -> list[Path]:
    """``online.png``, ``online_felt.png`` and ``compute_time.png`` of an
    :class:`desdemona.control.online.OnlineResult`."""
    lim = result.model.limits
    return draw_online_run(result.trajectory, result.baseline, lim.effort, lim.power, result.loop.compute_times,
                           result.deadline, f"{result.path.name} on-line, {result.model.config.name}",
                           result.quality.vestibular, out_dir, result.model.config.joint_names)


def draw_online_run(traj, classical, effort, power, compute_times, deadline: float, title: str, vestibular,
                    out_dir: str | Path, joints=None) -> list[Path]:
    """The figures of :func:`draw_online` from the values a result folder keeps: the MPC's and the
    classical loop's (or None) trajectories, the free joints' effort [N*m | N] and power [W] limits,
    each cycle's compute time [s], the deadline [s], the vestibular model's name and the free joints'
    names (the limits' legends)."""
    out = Path(out_dir)
    fig = _figure(figsize=(11, 9))
    axes = fig.subplots(3, 2, sharex=True)
    axes[0, 0].plot(traj.t, traj.M_d, "k-", label="M_d (desired)")
    axes[0, 0].plot(traj.t, traj.M, "C0--", label="M (MPC)")
    axes[1, 0].plot(traj.t, traj.M_d - traj.M, "C0", label="M_d - M (MPC)")
    if classical is not None:
        axes[0, 0].plot(classical.t, classical.M, "C3:", label="M (classical loop)")
        axes[1, 0].plot(classical.t, classical.M_d - classical.M, "C3:", label="M_d - M (classical loop)")
    axes[0, 0].set_ylabel("modulus [m/s^2]")
    axes[1, 0].set_ylabel("error [m/s^2]")
    for ax, k, name in ((axes[0, 1], 3, "S_x"), (axes[1, 1], 4, "S_y")):
        if traj.S_d is not None:
            ax.plot(traj.t, traj.S_d[:, k], "k-", label=f"{name}_d (desired)")
        ax.plot(traj.t, traj.S[:, k], "C0--", label=f"{name} (MPC)")
        if classical is not None:
            ax.plot(classical.t, classical.S[:, k], "C3:", label=f"{name} (classical loop)")
        ax.set_ylabel(f"{name} [m/s^2]")
    names = list(joints) if joints is not None else [None] * traj.tau.shape[1]
    for ax, values, limit, label in ((axes[2, 0], traj.tau, effort, "force / max"),
                                     (axes[2, 1], traj.power, power, "power / max")):
        for k, name in enumerate(names):
            ax.plot(traj.t, values[:, k] / limit[k], label=name)
        ax.set_ylabel(label)
    for ax in axes.ravel():
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    for ax in axes[2]:
        _limit_lines(ax)
        ax.set_xlabel("t [s]")
    paths = [_save(fig, out / "online.png", title)]
    runs = [traj] if classical is None else [traj, classical]
    paths.append(draw_felt(runs, ["MPC", "classical loop"][:len(runs)], out / "online_felt.png",
                           _vestibular(vestibular), title))
    paths.append(draw_suffered(runs, ["MPC", "classical loop"][:len(runs)], out / "online_suffered.png", title))
    fig = _figure(figsize=(8, 4))
    ax = fig.subplots()
    ax.hist(np.asarray(compute_times) * 1e3, bins=50)
    ax.axvline(deadline * 1e3, color="r", ls=":", label=f"deadline {deadline * 1e3:g} ms")
    ax.set_xlabel("compute time per cycle [ms]")
    ax.set_ylabel("cycles")
    ax.legend()
    paths.append(_save(fig, out / "compute_time.png"))
    return paths


def plot_bode(model, path: str | Path, w=None) -> Path:
    """Bode diagrams of a :class:`desdemona.occupant.perception.VestibularModel`'s canal and otolith channels to
    a PNG (like thesis figures 6.4, 6.6). w : frequencies [rad/s], default 1e-3 to 1e3."""
    w = np.logspace(-3, 3, 600) if w is None else np.asarray(w)
    fig = _figure(figsize=(11, 7))
    axes = fig.subplots(2, 2, sharex=True)
    for col, (title, channels) in enumerate((("semicircular canals (input: angular velocity)",
                                              model.channels[:3]),
                                             ("otoliths (input: specific force)", model.channels[3:]))):
        for ch in channels:
            h = ch.frequency_response(w)
            axes[0, col].semilogx(w, 20 * np.log10(np.abs(h)), label=ch.name)
            axes[1, col].semilogx(w, np.degrees(np.unwrap(np.angle(h))), label=ch.name)
        axes[0, col].set_title(f"{model.name}: {title}")
        axes[0, col].set_ylabel("magnitude [dB]")
        axes[1, col].set_ylabel("phase [deg]")
        axes[1, col].set_xlabel("frequency [rad/s]")
        for ax in axes[:, col]:
            ax.grid(True, which="both", alpha=0.3)
        axes[0, col].legend(fontsize=8)
    return _save(fig, Path(path), dpi=110)


def draw_comparison(entries, out_dir: str | Path) -> list[Path]:
    """Overlay figures of result folders read back (:class:`desdemona.results.compare.Entry`) in ``out_dir``:
    ``compare_path.png``, ``compare_felt.png``, ``compare_modulus.png`` (modulus-only paths) and
    ``compare_qdd.png``; returns their paths."""
    from desdemona.check.metrics import joint_units

    out, paths = Path(out_dir), []

    def save(fig, name, title):
        paths.append(_save(fig, out / name, title))

    def six_channels():
        fig = _figure(figsize=(12, 8))
        axes = fig.subplots(3, 2, sharex=True)
        for ax in axes[-1]:
            ax.set_xlabel("t [s]")
        return fig, axes.T.ravel()

    full = [e for e in entries if e.trajectory.S_d is not None]
    if full:
        fig, axes = six_channels()
        for i, ax in enumerate(axes):
            ax.plot(full[0].trajectory.t, full[0].trajectory.S_d[:, i], "k-", lw=1.8, label=f"S_d ({full[0].label})")
            for k, e in enumerate(full):
                ax.plot(e.trajectory.t, e.trajectory.S[:, i], f"C{k}--", lw=1.1, label=e.label)
            ax.set_ylabel(CHANNEL_LABELS[i])
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        save(fig, "compare_path.png", "path S over the desired S_d")
        fig, axes = six_channels()
        for i, ax in enumerate(axes):
            ax.axhspan(-THRESHOLDS[i], THRESHOLDS[i], color="0.8", label="below threshold")
            for k, e in enumerate(full):
                ax.plot(e.trajectory.t, e.felt[:, i], f"C{k}", lw=1.1, label=e.label)
            ax.set_ylabel(f"felt error {CHANNEL_LABELS[i]}")
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=8)
        save(fig, "compare_felt.png", f"perceived S - S_d ({entries[0].metrics.vestibular} model)")
    if len(full) < len(entries):
        fig = _figure(figsize=(10, 4))
        ax = fig.subplots()
        ax.plot(entries[0].trajectory.t, entries[0].trajectory.M_d, "k-", lw=1.8, label=f"M_d ({entries[0].label})")
        for k, e in enumerate(entries):
            ax.plot(e.trajectory.t, e.trajectory.M, f"C{k}--", lw=1.1, label=e.label)
        ax.set_ylabel("modulus [m/s^2]")
        ax.set_xlabel("t [s]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        save(fig, "compare_modulus.png", "modulus M over the desired M_d")
    joints = list(dict.fromkeys(j for e in entries for j in e.joints))
    units = joint_units(joints)
    fig = _figure(figsize=(10, 1.9 * len(joints) + 1))
    axes = fig.subplots(len(joints), 1, sharex=True, squeeze=False)
    for ax, joint, unit in zip(axes[:, 0], joints, units):
        for k, e in enumerate(entries):
            if joint in e.joints:
                column = e.joints.index(joint)
                ax.plot(e.trajectory.t, e.trajectory.qdd[:, column], f"C{k}", lw=1.0, drawstyle="steps-post",
                        label=e.label)
        ax.set_ylabel(f"qdd {joint} [{unit}/s^2]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    axes[-1, 0].set_xlabel("t [s]")
    save(fig, "compare_qdd.png", "commanded joint accelerations")
    return paths
