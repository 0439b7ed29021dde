"""What a served session leaves for a person to read (:mod:`desdemona.service.serve`): its every cycle
(``session.csv``), its events (``events.csv``), the ``service`` entry of its ``summary.json`` and the
line the command prints."""

from __future__ import annotations

import signal
from collections import Counter
from typing import TYPE_CHECKING

import numpy as np

from desdemona.service.pacing import PHASES

if TYPE_CHECKING:
    from desdemona.service.livetrajectory import LiveTrajectory

#: The timing columns of a cycle after the others [s]: its phases and its compute's processor time.
TIMED = (*(f"{phase}_s" for phase in PHASES), "compute_cpu_s")


def session_table(served) -> str:
    """``session.csv``: every cycle of the session, on its clock (also before the host came and after
    it had gone): its time, status, command, the host message's age, the latency and the compute time
    [s], the reason of a fallback or a parking, the machine's own status as its newest State said and
    the use of the tracking tolerance (1 = a fault; empty without States), then its phases and the
    processor time of its compute [s] (:data:`TIMED`, :mod:`desdemona.service.pacing`)."""
    columns, loop = served.columns, served.loop
    lines = ["t,status,command,message_age_s,latency_s,compute_time_s,reason,machine,tracking_use," + ",".join(TIMED)]
    for k, t in enumerate(loop.cycle_times):
        lines.append(f"{t:.6g},{columns['status'][k]},{columns['command'][k]},{columns['message_age_s'][k]:.6g},"
                     f"{columns['latency_s'][k]:.6g},{loop.compute_times[k]:.6g},\"{loop.reasons[k]}\","
                     f"{columns['machine'][k]},{columns['tracking_use'][k]:.6g},"
                     + ",".join(f"{columns[key][k]:.6g}" for key in TIMED))
    return "\n".join(lines) + "\n"


def events_table(served) -> str:
    """``events.csv``: every operator command, machine fault and notice of the session with its time [s,
    the session's clock]."""
    lines = ["t,what,detail"] + [f"{t:.6g},{what},\"{detail}\"" for t, what, detail in served.events]
    return "\n".join(lines) + "\n"


def summary(served, serving) -> dict:
    """The ``service`` entry of the session's ``summary.json``: addresses, counts of cycles by status and
    command, datagrams dropped by reason, and the times that matter for real time [s], all over the
    whole session; the span it is judged on (``judged_span_s``, on the session's clock) and the
    judged result's time of the host's time 0 (``host_time_offset_s``)."""
    columns, times = served.columns, served.loop.compute_times
    latency, age = columns["latency_s"], columns["message_age_s"]

    def spread(values):
        values = values[np.isfinite(values)]
        if len(values) == 0:
            return None
        return {"median": float(np.median(values)), "p99": float(np.percentile(values, 99)), "max": float(values.max())}

    return {"listen": f"{serving.listen[0]}:{serving.listen[1]}", "send": f"{serving.send[0]}:{serving.send[1]}",
            "timeout_cycles": serving.timeout, "cycles": len(times),
            "status": dict(Counter(map(str, columns["status"]))), "command": dict(Counter(map(str, columns["command"]))),
            "dropped": dict(served.dropped), "dropped_sample": served.drop_samples,
            "received": int(len(served.received_t)),
            "latency_s": spread(latency), "message_age_s": spread(age),
            "phases_s": {key[:-2]: spread(columns[key]) for key in TIMED},
            "compute_over_deadline": int(np.sum(times > served.deadline)),
            "judged_span_s": [float(served.loop.plan.t_nodes[k]) for k in served.span()],
            "host_time_offset_s": served.offset - float(served.loop.plan.t_nodes[served.span()[0]]),
            "stopped_by": None if served.stopped_by is None else signal.Signals(served.stopped_by).name,
            "machine_states": served.states, "reanchored_cycles": served.reanchored,
            "tracking_use_max": None if not np.any(np.isfinite(columns["tracking_use"]))
            else float(np.nanmax(columns["tracking_use"])),
            "events": [{"t": t, "what": what, "detail": detail} for t, what, detail in served.events]}


def describe(summary: dict) -> str:
    """The session in one line: cycles, latency, deadlines, what was dropped, how it parked."""
    latency = summary["latency_s"]
    lat = "no host message answered" if latency is None else (
        f"latency median {1e3 * latency['median']:.2f} ms, p99 {1e3 * latency['p99']:.2f} ms")
    dropped = sum(summary["dropped"].values())
    status = ", ".join(f"{k} {v}" for k, v in summary["status"].items())
    machine = ("no State from the machine (planned on its own command)" if not summary["machine_states"] else
               f"{summary['machine_states']} machine States, tracking error at most {summary['tracking_use_max']:.3g} "
               f"of its tolerance, {summary['reanchored_cycles']} cycles re-anchored")
    faults = [e for e in summary["events"] if e["what"] in ("machine fault",) or e["what"].startswith("command")]
    return (f"served {summary['cycles']} cycles ({status}), {summary['received']} host messages, {lat}, "
            f"{summary['compute_over_deadline']} over the deadline, {dropped} datagrams dropped; {machine}"
            + "".join(f"\n  {e['t']:.3f} s: {e['what']}" + (f": {e['detail']}" if e["detail"] else "") for e in faults))


class LiveLog:
    """The session's log written as it goes into its result folder ``out``: ``session.csv`` (every cycle:
    the columns of :func:`session_table`, then the free joints' commanded positions, rates and
    accelerations at the cycle's start and the newest State's measured positions and rates, with the time on the setpoints' time line they
    were measured at) and ``events.csv``, each row appended and flushed, so that a service that is
    killed leaves them to its last cycle; ``summary.json`` marks the folder as a result of ours being
    written (``"live": true``), so that the session's end replaces it with the whole result."""

    def __init__(self, out, names, result_format: str, trajectory: LiveTrajectory | None = None,
                 description: dict | None = None):
        import json
        from pathlib import Path

        self.out = Path(out)
        self.out.mkdir(parents=True, exist_ok=True)
        (self.out / "summary.json").write_text(json.dumps({"format": result_format, "live": True,
                                                           "written_by": "desdemona serve, as it goes",
                                                           **(description or {})}))
        self.trajectory = trajectory
        if trajectory is not None:
            trajectory.begin(self.out / "trajectory.csv")
        self.session = open(self.out / "session.csv", "w")  # noqa: SIM115 -- appended to cycle by cycle
        self.events = open(self.out / "events.csv", "w")  # noqa: SIM115
        joints = [f"{kind}_{name}_{q}" for kind, quantities in (("commanded", ("position", "rate", "acceleration")),
                                                                ("measured", ("position", "rate")))
                  for q in quantities for name in names]
        self.session.write(",".join(["t,status,command,message_age_s,latency_s,compute_time_s,reason,machine,"
                                     "tracking_use", *joints, "measured_at", *TIMED]) + "\n")
        self.events.write("t,what,detail\n")
        self.written = 0

    def cycle(self, row: dict, commanded, measured, events, desired=None) -> None:
        """One cycle's ``row`` (as :class:`desdemona.service.serve` records it), ``commanded`` (q, qd, and
        the commanded acceleration qdd) and ``measured`` (q, qd, time on the setpoints' line) or None,
        every event so far, and ``desired``: the values of the host's newest message (None before the
        first), for the live trajectory.csv."""
        n = len(commanded[0])
        values = [*commanded[0], *commanded[1], *commanded[2], *(measured[0] if measured else [np.nan] * n),
                  *(measured[1] if measured else [np.nan] * n)]
        self.session.write(f"{row['t']:.6g},{row['status']},{row['command']},{row['message_age_s']:.6g},"
                           f"{row['latency_s']:.6g},{row['compute_time_s']:.6g},\"{row['reason']}\","
                           f"{row['machine']},{row['tracking_use']:.6g},"
                           + ",".join(f"{v:.10g}" for v in values)
                           + f",{measured[2] if measured else np.nan:.6g},"
                           + ",".join(f"{row[key]:.6g}" for key in TIMED) + "\n")
        for t, what, detail in events[self.written:]:
            self.events.write(f"{t:.6g},{what},\"{detail}\"\n")
        self.written = len(events)
        self.session.flush()
        self.events.flush()
        if self.trajectory is not None and desired is not None:
            self.trajectory.add(row["t"], *commanded[:3], desired)

    def close(self) -> tuple[str, str]:
        """Closed; the text of session.csv and events.csv, to go into the whole result."""
        if self.trajectory is not None:
            self.trajectory.close()
        self.session.close()
        self.events.close()
        return (self.out / "session.csv").read_text(), (self.out / "events.csv").read_text()
