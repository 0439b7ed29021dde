"""Guarding the user's time: interrupts that stop a whole run, and word from a long solve.

A run may spend minutes inside IPOPT. Ctrl-C (SIGINT) or SIGTERM must stop all of it within a second
or two, write nothing, and leave the command to exit 128 + the signal number. Three obstacles:

- CasADi checks for signals at each IPOPT iteration, but turns an exception raised by a Python handler
  into a warning and a failed start (``NonIpopt_Exception_Thrown``), and the run goes on. So inside a
  solve that carries :class:`SolveMonitor` (the problem's ``iteration_callback``) the handler only
  records the signal; the monitor asks IPOPT to stop at its next iteration and :func:`solving` raises
  :class:`Interrupted` once the solver has returned.
- fatrop has no iteration callback, and an exception raised into the CasADi functions it evaluates
  only fails that evaluation: it backtracks and goes on (measured: 400 s to stop the car lap on full,
  ending in a traceback). Inside such a solve (:func:`solving` without a monitor) the handler ends the
  process at once with ``os._exit``: nothing is being written while a solver runs (result folders are
  written after, atomically), so nothing is left half.
- Other compiled code (the on-line controller's QP solver) may swallow the exception the same way.
  After the first signal a repeating timer raises :class:`Interrupted` again every :data:`REPEAT`
  seconds until it reaches Python code that lets it through.
- Compiled code that runs for long without returning to the interpreter (CasADi building or
  factorising a problem of a million variables) keeps even the handler from running: a Python handler
  runs between bytecodes. A watchdog thread hears the signal at once through the interpreter's wakeup
  file descriptor (:func:`signal.set_wakeup_fd`) and, if the command has not ended :data:`GRACE`
  seconds later with the handler never run (:data:`GRACE_ACTING` once it has: the command is
  stopping), ends the process as above, unless the signal is held back (:func:`deferred`).
- Worker processes: they ignore SIGINT (:func:`worker_signals`), so only the parent decides, and the
  parent terminates them (``multiprocessing.Pool`` sends SIGTERM on leaving its ``with`` block), which
  stops them the same way. A pool whose work is done is ended by :func:`finish` instead.

Signals and signal handlers are process-wide, so is the state here: it is set only inside the CLI's
``with interruptible():`` and is inert for a library user who never enters it.

The same monitor reports on a long solve: every ``every`` seconds it calls the reporter given to
:func:`reporting` with the iteration count and the current cost. A step of compiled code that says
nothing while it runs (compiling generated C into the cache: a minute on a fresh cache) is wrapped in
:func:`lasting`: it is told as it begins and ends with its time, it is the :func:`step` a command's
own clock names while it runs, and its time adds to :func:`compile_seconds`, which a command prints
apart from the solve's. :func:`estimated_end` turns a run's estimate and its pace into the time of
day it will end.
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import sys
import threading
import time

import casadi as ca

REPEAT = 0.2  # [s] re-raise period once a signal was received and something swallowed the exception
#: [s] after a signal, how long the command has to end by itself before the watchdog ends the process:
#: a command stops within a second or two of Ctrl-C, whatever compiled code it is in.
GRACE = 1.5
#: [s] the same once the handler has run: the command is then ending by itself (an interrupted batch
#: stops its workers and writes its table), unless compiled code swallowed the exception and runs on.
GRACE_ACTING = 10.0
STOPPING = (signal.SIGINT, signal.SIGTERM)


class Interrupted(SystemExit):
    """The user asked the run to stop (SIGINT or SIGTERM). A SystemExit with code 128 + the signal
    number: ``except Exception`` clauses that turn failures into table lines let it through, and a
    worker process that meets it ends quietly with that code."""

    def __init__(self, signum: int):
        super().__init__(128 + signum)
        self.signum = signum
        self.name = signal.Signals(signum).name
        self.message = f"interrupted ({self.name}): stopped, no partial result written"


class _State:
    """What the handlers and monitors share within one process."""

    def __init__(self):
        self.signum: int | None = None  # the first signal received
        self.monitored = 0  # depth of solves whose monitor will stop the solver
        self.unstoppable = 0  # depth of solves nothing but ending the process stops
        self.speak = False  # say why the process ends (the command's own process, not a worker)
        self.reporter = None  # reporter(iteration, cost, seconds) for long solves
        self.every = 10.0
        self.on_hard_exit = []  # callables run before the process ends with os._exit (release a lock)
        self.deferring = 0  # depth of blocks that must not be cut in two (deferred)
        self.acted = False  # the handler has run since the signal: the main thread knows of it
        self.held = False  # a signal arrived inside a deferred block: it is acted on as the block ends
        self.tell = None  # tell(text): a line for the user about a long step (lasting)
        self.step = None  # what the lasting step now running does, else None
        self.compiling = 0.0  # [s] spent in lasting steps in this process


_state = _State()


@contextlib.contextmanager
def before_hard_exit(action):
    """Within this block, ``action()`` is called if a signal ends the process at once (``os._exit``
    inside a solve nothing else stops), as ``finally`` clauses are not run then."""
    _state.on_hard_exit.append(action)
    try:
        yield
    finally:
        _state.on_hard_exit.remove(action)


def _handler(signum, frame):
    _state.acted = True
    if _state.signum is None:
        _state.signum = signum
        # a backstop for exceptions swallowed by compiled code: raise again until one gets through
        signal.signal(signal.SIGALRM, _repeat)
        signal.setitimer(signal.ITIMER_REAL, REPEAT, REPEAT)
    if _state.deferring:
        _state.held = True  # deferred() raises as it ends
        return
    if _state.monitored:
        return  # the solve's monitor stops IPOPT cleanly; solving() raises after it returns
    if _state.unstoppable:
        _hard_exit(signum)
    raise Interrupted(_state.signum)


def _hard_exit(signum: int) -> None:
    """End the process at once with 128 + ``signum``, saying why and releasing what it holds."""
    if _state.speak:
        print(f"desdemona: {Interrupted(signum).message}", file=sys.stderr, flush=True)
    sys.stdout.flush()
    for action in list(_state.on_hard_exit):
        try:
            action()
        except Exception:  # ending the process matters more than tidying up
            pass
    os._exit(128 + signum)


def _watchdog(wakeup: socket.socket, ended: threading.Event) -> None:
    """Thread: on SIGINT or SIGTERM (read from the wakeup socket), end the process if the command has
    not ended (``ended``) within :data:`GRACE` seconds. It blocks the signals itself, so that they reach
    the main thread, and while the main thread holds them back (:func:`deferred`) none is read here."""
    signal.pthread_sigmask(signal.SIG_BLOCK, STOPPING)
    while not ended.is_set():
        try:
            received = wakeup.recv(64)
        except OSError:  # closed as the command ended
            return
        signums = [s for s in received if s in STOPPING]
        if not received or ended.is_set():
            return
        if not signums:
            continue
        while _state.deferring and not ended.is_set():  # a block that must not be cut in two
            ended.wait(0.05)
        if not ended.wait(GRACE) and not (_state.acted and ended.wait(GRACE_ACTING - GRACE)):
            _hard_exit(signums[0])


def _repeat(signum, frame):
    if _state.signum is not None and not _state.monitored and not _state.deferring:
        raise Interrupted(_state.signum)


@contextlib.contextmanager
def interruptible():
    """Within this block SIGINT and SIGTERM raise :class:`Interrupted` (main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    saved = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGALRM)}
    _state.signum, _state.speak, _state.acted, _state.held = None, True, False, False
    for s in (signal.SIGINT, signal.SIGTERM):
        signal.signal(s, _handler)
    listen, wakeup = socket.socketpair()
    wakeup.setblocking(False)
    saved_wakeup = signal.set_wakeup_fd(wakeup.fileno(), warn_on_full_buffer=False)
    ended = threading.Event()
    watchdog = threading.Thread(target=_watchdog, args=(listen, ended), name="desdemona-watchdog", daemon=True)
    watchdog.start()
    try:
        yield
    finally:
        ended.set()
        signal.set_wakeup_fd(saved_wakeup)
        wakeup.close()  # the watchdog's recv returns empty: it ends
        watchdog.join()
        listen.close()
        signal.setitimer(signal.ITIMER_REAL, 0)
        for s, h in saved.items():
            signal.signal(s, h)
        _state.signum, _state.monitored, _state.unstoppable, _state.speak = None, 0, 0, False


@contextlib.contextmanager
def handled_here(handler):
    """Within this block SIGINT and SIGTERM call ``handler(signum)`` and nothing else: no exception, no
    repeated raising, no watchdog ending the process. For a loop that must act on a stop itself and
    take its time doing it (the real-time service brakes the machine to rest before it exits)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    saved = {s: signal.getsignal(s) for s in STOPPING}
    saved_wakeup = signal.set_wakeup_fd(-1)  # the watchdog hears nothing from this block
    for s in STOPPING:
        signal.signal(s, lambda signum, frame: handler(signum))
    try:
        yield
    finally:
        for s, h in saved.items():
            signal.signal(s, h)
        signal.set_wakeup_fd(saved_wakeup, warn_on_full_buffer=False)


def check() -> None:
    """Raise :class:`Interrupted` if a stop was requested (between pieces of work)."""
    if _state.signum is not None:
        raise Interrupted(_state.signum)


@contextlib.contextmanager
def solving(monitor: SolveMonitor | None):
    """Around one solver call; raises :class:`Interrupted` after it if a stop was asked for.

    monitor : the solver's :class:`SolveMonitor`, or None. With one, a signal only asks the monitor to
    stop the solver at its next iteration: the handler must not raise into it. Without one (fatrop),
    a signal ends the process.
    """
    monitored = monitor is not None
    if monitored:
        monitor.restart()
    _state.monitored += monitored
    _state.unstoppable += not monitored
    try:
        yield
    finally:
        _state.monitored -= monitored
        _state.unstoppable -= not monitored
    check()


@contextlib.contextmanager
def deferred():
    """Hold SIGINT and SIGTERM back for a short block that must not be cut in two (renaming a result
    folder into place); they are acted on when it ends. Blocking them in this thread is not enough:
    a signal may reach another thread (a BLAS worker), and the interpreter then runs the handler here
    all the same; the handler and the watchdog leave a deferred block alone, and its end raises."""
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, STOPPING)
    _state.deferring += 1
    try:
        yield
    finally:
        _state.deferring -= 1
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)  # a signal held back is delivered now
    if not _state.deferring and _state.held:
        _state.held = False
        check()


def worker_signals(writes: bool = False) -> None:
    """Initializer of worker processes: ignore SIGINT (a terminal sends it to the whole process group:
    the parent decides, and terminates the workers with SIGTERM). On SIGTERM a worker that only
    computes dies at once; one that ``writes`` result folders stops as the parent would, so that a
    folder being written is removed, not left half (at the cost of up to an IPOPT iteration)."""
    _state.signum, _state.monitored, _state.unstoppable, _state.reporter, _state.speak = None, 0, 0, None, False
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _handler if writes else signal.SIG_DFL)


def finish(pool) -> None:
    """End a ``multiprocessing.Pool`` whose work is done: each worker is sent the end of its task
    queue and exits by itself (``close``, ``join``). Leaving the pool's ``with`` block only
    terminates it, which first takes the task queue's lock for good and then signals the workers; a
    test run once hung there for good, in ``join``, on a worker that waited for that lock and had not
    acted on the signal. The block's termination stays for an interrupted pool."""
    pool.close()
    pool.join()


@contextlib.contextmanager
def reporting(reporter, every: float = 10.0, tell=None):
    """Within this block a long solve calls ``reporter(iteration, cost, seconds)`` every ``every`` s,
    and a :func:`lasting` step ``tell(text)`` as it begins and ends."""
    saved = _state.reporter, _state.every, _state.tell
    _state.reporter, _state.every, _state.tell = reporter, every, tell
    try:
        yield
    finally:
        _state.reporter, _state.every, _state.tell = saved


@contextlib.contextmanager
def lasting(what: str, where: str = "", told: bool = True):
    """Around a step of compiled code that says nothing while it runs: compiling generated C into the
    cache. ``what`` ("compiling the stage functions") and ``where`` (", once, into FOLDER") are told as
    it begins where ``told`` (a step known to be long; a short one is only timed), ``what`` is the
    :func:`step` while it runs and is told with its time as it ends; its time adds to
    :func:`compile_seconds`."""
    tell = _state.tell if told else None
    if tell is not None:
        tell(f"{what}{where}")
    begin = time.perf_counter()
    saved, _state.step = _state.step, (what, begin)
    try:
        yield
    finally:
        seconds = time.perf_counter() - begin
        _state.step = saved
        _state.compiling += seconds
        if tell is not None:
            tell(f"{what}: {seconds:.1f} s")


def step() -> str | None:
    """What the :func:`lasting` step now running does and for how long it has, None outside one (read
    by a command's clock)."""
    if _state.step is None:
        return None
    what, begin = _state.step
    return f"{what} ({time.perf_counter() - begin:.0f} s so far)"


def compile_seconds() -> float:
    """[s] spent in :func:`lasting` steps (compiling) in this process so far."""
    return _state.compiling


def estimated_end(begin: float, done: float, total: float, estimate: float | None = None) -> str:
    """The time of day (HH:MM:SS) that work begun at ``begin`` (:func:`time.perf_counter`) ends: at the
    pace of the share ``done`` of ``total`` so far, else (nothing done yet) after ``estimate`` seconds."""
    elapsed = time.perf_counter() - begin
    if done > 0:
        left = elapsed * (total - done) / done
    else:
        left = max((estimate or 0.0) - elapsed, 0.0)
    return time.strftime("%H:%M:%S", time.localtime(time.time() + left))


class SolveMonitor(ca.Callback):
    """IPOPT's ``iteration_callback``: stops the solve when a signal was received (a non-zero return
    makes IPOPT end with User_Requested_Stop) and reports a long solve's progress.

    nx, ng : numbers of decision variables and constraints of the NLP.
    """

    def __init__(self, nx: int, ng: int):
        ca.Callback.__init__(self)
        self.nx, self.ng = nx, ng
        self.iteration, self.started, self.last = 0, 0.0, 0.0
        self.construct("monitor", {})

    def get_n_in(self):
        return ca.nlpsol_n_out()

    def get_n_out(self):
        return 1

    def get_name_in(self, i):
        return ca.nlpsol_out(i)

    def get_name_out(self, i):
        return "stop"

    def get_sparsity_in(self, i):
        name = ca.nlpsol_out(i)
        if name == "f":
            return ca.Sparsity.scalar()
        if name in ("x", "lam_x"):
            return ca.Sparsity.dense(self.nx)
        if name in ("g", "lam_g"):
            return ca.Sparsity.dense(self.ng)
        return ca.Sparsity(0, 0)

    def restart(self) -> None:
        self.iteration, self.started = 0, time.perf_counter()
        self.last = self.started

    def eval(self, arg):
        self.iteration += 1
        now = time.perf_counter()
        if _state.reporter is not None and now - self.last >= _state.every:
            self.last = now
            _state.reporter(self.iteration, float(arg[1]), now - self.started)
        return [1.0 if _state.signum is not None else 0.0]
