"""What a long run tells while it works, on stderr: how far it is and when it will end, from the
estimate made before it started (:mod:`desdemona.cueing.sizing`) and its pace since
(:func:`desdemona.support.guard.estimated_end`)."""

from __future__ import annotations

import sys
import time

from desdemona.cueing import sizing
from desdemona.support import guard


class Starts:
    """Progress of an off-line run on stderr: a bar on a terminal; else (a log file, a CI job) a line
    when the run starts, one per finished start with the elapsed time and the best cost so far, and one
    every ``PROGRESS_EVERY`` seconds (:mod:`desdemona.cli.commands`) inside a long solve."""

    def __init__(self, starts: int, size: sizing.Size, path, config, estimate: float | None = None):
        self.begin, self.estimate = time.perf_counter(), estimate
        self.tty = sys.stderr.isatty()
        if not self.tty:
            about = "" if estimate is None else (f", about {sizing.duration_words(estimate)} (ends about "
                                                 f"{guard.estimated_end(self.begin, 0, starts, estimate)})")
            self.say(f"{path.name} on {config.name}: {size.intervals:,} control intervals, {size.variables:,} "
                     f"variables, {starts} start{'s' if starts > 1 else ''}{about}")

    def say(self, text: str) -> None:
        print(f"desdemona: {text}", file=sys.stderr, flush=True)

    def start_done(self, done: int, total: int, best: float) -> None:
        if self.tty:
            bar = "#" * done + "." * (total - done)
            print(f"\r  starts [{bar}] {done}/{total}", end="" if done < total else "\n", file=sys.stderr,
                  flush=True)
        else:
            ends = "" if done == total else f", ends about {guard.estimated_end(self.begin, done, total)}"
            self.say(f"start {done}/{total} done, {time.perf_counter() - self.begin:.1f} s, best cost so far "
                     f"{best:.6g}{ends}")

    def window(self, index: int, count: int, start: float, end: float) -> None:
        self.say(f"window {index}/{count}: {start:g}-{end:g} s")

    def solving(self, iteration: int, cost: float, seconds: float) -> None:
        if not self.tty:
            ends = "" if self.estimate is None else f", ends about {guard.estimated_end(self.begin, 0, 1, self.estimate)}"
            self.say(f"  solving: iteration {iteration}, cost {cost:.6g}, {seconds:.0f} s in this start, "
                     f"{time.perf_counter() - self.begin:.1f} s in all{ends}")


class Steps:
    """Progress of an on-line run on stderr (:func:`desdemona.support.guard.counting`'s counter): a line
    when it starts, where it is estimated to take longer than ``every`` seconds, and one per ``every``
    seconds with the closed-loop steps done and the estimated end."""

    def __init__(self, path, config, estimate: float, every: float):
        self.begin = time.perf_counter()
        if estimate > every:
            print(f"desdemona: {path.name} on-line on {config.name}: about {sizing.duration_words(estimate)} "
                  f"(ends about {guard.estimated_end(self.begin, 0, 1, estimate)})", file=sys.stderr, flush=True)

    def __call__(self, done: int, total: int) -> None:
        print(f"desdemona: step {done:,}/{total:,} ({100 * done / total:.0f} %), "
              f"{time.perf_counter() - self.begin:.0f} s, ends about {guard.estimated_end(self.begin, done, total)}",
              file=sys.stderr, flush=True)
