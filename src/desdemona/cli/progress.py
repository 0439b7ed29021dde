"""What a long command says on stderr while it runs, so that no minute passes in silence.

On a terminal: one line drawn over itself (a bar of the starts, the on-line session's time). Else (a
log file, a CI job): whole lines, one as each piece of work ends, and a clock that says what the
command is doing whenever nothing was said for :data:`EVERY` seconds: the compile of a fresh cache
(:func:`desdemona.support.guard.lasting`), the problem being built, the starts being solved, the
on-line session's time. Where the run's time was estimated before it began
(:mod:`desdemona.cueing.sizing`), its lines say when it should end, revised at its pace
(:func:`desdemona.support.guard.estimated_end`). The clock is a thread; it speaks while the main thread waits on a compiler
or on worker processes, or runs Python code (the on-line loop), not inside one long call of compiled
code that holds the interpreter (CasADi setting a problem up).
"""

from __future__ import annotations

import sys
import threading
import time

from desdemona.cueing import sizing
from desdemona.support import guard

EVERY = 10.0  # [s] at most between lines when stderr is not a terminal
DRAW_EVERY = 0.2  # [s] between redraws of the line on a terminal


class Progress:
    """A command's progress lines (see the module). ``doing`` names the work in hand, for the clock;
    :meth:`close` (or leaving the ``with`` block) stops the clock."""

    def __init__(self, doing: str = "preparing", every: float | None = None, tty: bool | None = None):
        self.begin = self.last = time.perf_counter()
        self.tty = sys.stderr.isatty() if tty is None else tty
        self.doing, self.every = doing, EVERY if every is None else every
        self.drawn = 0.0  # when the terminal's line was last drawn
        self._ended = threading.Event()
        self._clock = threading.Thread(target=self._tick, name="desdemona-progress", daemon=True)
        self._clock.start()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        self._ended.set()
        self._clock.join()
        if self.tty and self.drawn:
            print(file=sys.stderr, flush=True)  # end the line drawn over itself
            self.drawn = 0.0

    def elapsed(self) -> float:
        return time.perf_counter() - self.begin

    def say(self, text: str) -> None:
        """One whole line (on a terminal below the line being drawn)."""
        end_drawn = "\n" if self.tty and self.drawn else ""
        self.drawn = 0.0
        print(f"{end_drawn}desdemona: {text}", file=sys.stderr, flush=True)
        self.last = time.perf_counter()

    def draw(self, text: str) -> None:
        """On a terminal, ``text`` over the line drawn before (at most every :data:`DRAW_EVERY` s)."""
        now = time.perf_counter()
        if self.tty and now - self.drawn >= DRAW_EVERY:
            print(f"\r  {text}\033[K", end="", file=sys.stderr, flush=True)
            self.drawn = self.last = now

    def _tick(self) -> None:
        tick = min(0.25, self.every / 4)
        while not self._ended.wait(tick):
            now = time.perf_counter()
            if not self.tty and now - self.last >= self.every - 2 * tick:  # said within every s, ticks and all
                self.say(f"{guard.step() or self.doing}: {now - self.begin:.0f} s in all")


class OfflineProgress(Progress):
    """Progress of an off-line run: a bar of the starts on a terminal; else a line when the run starts,
    one per finished start with the elapsed time and the best cost so far, one every :data:`EVERY`
    seconds inside a long IPOPT solve (:func:`desdemona.support.guard.reporting`), and the clock."""

    def __init__(self, starts: int, size, path, config, tty: bool | None = None, estimate: float | None = None):
        super().__init__("building the problem", tty=tty)
        self.starts, self.estimate = starts, estimate
        if not self.tty:
            about = "" if estimate is None else f", about {sizing.duration_words(estimate)} (ends about {self.end(0, starts)})"
            self.say(f"{path.name} on {config.name}: {size.intervals:,} control intervals, {size.variables:,} "
                     f"variables, {starts} start{'s' if starts > 1 else ''}{about}")

    def end(self, done: int, total: int) -> str:
        """When the run should end: at its pace once a start is done, else by its estimate."""
        return guard.estimated_end(self.begin, done, total, self.estimate)

    def start_done(self, done: int, total: int, best: float) -> None:
        if done == 0:  # the problem is built: its starts are solved now (a window's clock keeps its window)
            if self.doing == "building the problem":
                self.doing = f"solving: 0 of {total} starts done"
            return
        self.doing = f"solving: {done} of {total} starts done"
        if self.tty:
            bar = "#" * done + "." * (total - done)
            print(f"\r  starts [{bar}] {done}/{total}", end="" if done < total else "\n", file=sys.stderr,
                  flush=True)
        else:
            ends = "" if done == total else f", ends about {self.end(done, total)}"
            self.say(f"start {done}/{total} done, {self.elapsed():.1f} s, best cost so far {best:.6g}{ends}")

    def window(self, index: int, count: int, start: float, end: float) -> None:
        self.doing = f"window {index}/{count}"
        self.say(f"window {index}/{count}: {start:g}-{end:g} s")

    def solving(self, iteration: int, cost: float, seconds: float) -> None:
        if not self.tty:
            ends = "" if self.estimate is None else f", ends about {self.end(0, self.starts)}"
            self.say(f"  solving: iteration {iteration}, cost {cost:.6g}, {seconds:.0f} s in this start, "
                     f"{self.elapsed():.1f} s in all{ends}")


class OnlineProgress(Progress):
    """Progress of an on-line session in closed loop: its time against the path's, drawn over itself
    on a terminal, else a line every :data:`EVERY` seconds (the clock)."""

    def __init__(self, duration: float, tty: bool | None = None, estimate: float | None = None):
        super().__init__("building the controller and placing the machine for its first plan", tty=tty)
        self.duration = duration
        if estimate is not None and estimate > self.every and not self.tty:
            self.say(f"on-line: about {sizing.duration_words(estimate)} (ends about "
                     f"{guard.estimated_end(self.begin, 0, 1, estimate)})")

    def cycle(self, now: float) -> None:
        """The session has reached ``now`` [s] of the path."""
        ends = f", ends about {guard.estimated_end(self.begin, now, self.duration)}" if now > 0 else ""
        self.doing = f"on-line: {now:.1f} of {self.duration:.1f} s of the path{ends}"
        self.draw(f"{self.doing}, {self.elapsed():.0f} s")


def compile_words(seconds: float) -> str:
    """The printed part of a command's line for the time spent compiling (:func:`guard.compile_seconds`),
    "" where it was too little to name."""
    return f" (and {seconds:.1f} s compiling)" if seconds >= 0.5 else ""
