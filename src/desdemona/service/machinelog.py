"""What the motion-system stand-in (:mod:`desdemona.service.machine`) writes into its folder as it
goes: its CSV files, appended and flushed at every State, and ``summary.json``."""

from __future__ import annotations

import csv
import io
import json
import math
import os
from pathlib import Path

import numpy as np

from desdemona._version import __version__
from desdemona.check.simulate import TOLERANCE
from desdemona.machine.params import JOINT_NAMES
from desdemona.service.checker import ABSOLUTE, CONTINUITY
from desdemona.support.files import beside

FILES = ("setpoints.csv", "violations.csv", "motion.csv", "events.csv", "summary.json")
WRITTEN_BY = "desdemona machine"
#: Violations kept in the report (all are counted and written to ``violations.csv``).
MAX_KEPT = 1000

SETPOINT_COLUMNS = (("time", "sequence", "sent", "status", "source", "answers", "cycle_time", "step")
                    + tuple(f"{name}_{q}" for name in JOINT_NAMES
                            for q in ("position", "rate", "acceleration", "jerk")))
VIOLATION_COLUMNS = ("time", "sequence", "joint", "what", "value", "limit", "detail")
MOTION_COLUMNS = (("t", "status", "fault", "fault_joint", "applied", "applied_time")
                  + tuple(f"{name}_{q}" for name in JOINT_NAMES for q in ("position", "rate", "acceleration")))
EVENT_COLUMNS = ("time", "what", "detail")


def number(x: float) -> str:
    return repr(float(x))


class Files:
    """The folder's CSV files, opened for appending rows, each flushed as a State is sent."""

    def __init__(self, out: Path):
        self.handles = {name: open(out / name, "w", newline="") for name in FILES if name.endswith(".csv")}
        self.rows = {name: csv.writer(f) for name, f in self.handles.items()}
        for name, columns in (("setpoints.csv", SETPOINT_COLUMNS), ("violations.csv", VIOLATION_COLUMNS),
                              ("motion.csv", MOTION_COLUMNS), ("events.csv", EVENT_COLUMNS)):
            self.rows[name].writerow(columns)
        self.flush()

    def write(self, name: str, row) -> None:
        self.rows[name].writerow(row)

    def flush(self) -> None:
        for f in self.handles.values():
            f.flush()

    def close(self) -> None:
        for f in self.handles.values():
            f.close()


def record(report, checker, sp, t: float, violations, use, files: Files):
    report.received += 1
    report.statuses[sp.status] = report.statuses.get(sp.status, 0) + 1
    report.sources[sp.source] = report.sources.get(sp.source, 0) + 1
    if report.first_cycle_time is None:
        report.first_cycle_time = sp.cycle_time
    report.last_cycle_time = sp.cycle_time
    for kind, per_joint in use.items():
        k = int(np.argmax(per_joint))
        if per_joint[k] > report.worst[kind]:
            report.worst[kind] = float(per_joint[k])
            report.worst_joint[kind] = checker.names[k]
    row = [number(t), sp.sequence, number(sp.time), sp.status, sp.source,
           "" if sp.answers is None else sp.answers, number(sp.cycle_time), number(sp.step)]
    for i in range(6):
        row += [number(sp.position[i]), number(sp.rate[i]), number(sp.acceleration[i]), number(sp.jerk[i])]
    files.write("setpoints.csv", row)
    for v in violations:
        violation(report, v, files)


def violation(report, v, files: Files) -> None:
    report.counts[v.what] += 1
    if len(report.violations) < MAX_KEPT:
        report.violations.append(v)
    files.write("violations.csv", [number(v.time), v.sequence, v.joint, v.what, number(v.value), number(v.limit),
                                   v.detail])


def summary(report, model) -> dict:
    """The contents of ``summary.json``."""
    def finite(x):
        return x if x is None or math.isfinite(x) else str(x)

    return {
        "written_by": WRITTEN_BY, "version": __version__, "passed": report.passed,
        "config": model.config.name, "params": model.params.name, "free": list(model.config.joint_names),
        "listen": list(report.address), "stopped": report.stopped, "elapsed": report.elapsed,
        "datagrams": report.datagrams, "received": report.received, "dropped": dict(sorted(report.dropped.items())),
        "dropped_sample": report.drop_samples,
        "refused": dict(sorted(report.refused.items())), "gaps": report.gaps, "missing": report.missing,
        "reanchored": report.reanchored, "states_sent": report.states,
        "violations": dict(report.counts), "violation_count": report.violation_count,
        "timing_faults": dict(report.timing), "latest_after_due_s": report.latest,
        "ended_moving": report.ended_moving,
        "own_stops": [{"why": s.why, "start": s.start, "shortest_stop_s": s.bound, "at_rest": s.rest}
                      for s in report.stops],
        "worst_use": {k: finite(v) for k, v in report.worst.items()}, "worst_joint": dict(report.worst_joint),
        "worst_use_made": {k: finite(v) for k, v in report.made.items()}, "worst_joint_made": dict(report.made_joint),
        "first_cycle_time": report.first_cycle_time, "last_cycle_time": report.last_cycle_time,
        "statuses": dict(report.statuses), "sources": dict(report.sources),
        "tolerance": TOLERANCE, "continuity_tolerance": {"relative": CONTINUITY, "absolute": ABSOLUTE},
    }


def write_summary(report, model) -> None:
    target = report.out / "summary.json"
    with beside(target) as tmp:
        text = io.StringIO()
        json.dump(summary(report, model), text, indent=2)
        tmp.write_text(text.getvalue() + "\n")
        os.replace(tmp, target)
