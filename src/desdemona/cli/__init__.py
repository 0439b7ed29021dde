"""The ``desdemona`` command: thin wrappers around the library, ``main(argv) -> exit code``.

:mod:`desdemona.cli.options` is the table of commands and options, :mod:`desdemona.cli.commands`
what each command does (a session's choices are resolved by :mod:`desdemona.runs.session`),
:mod:`desdemona.cli.exits` how a command ends.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys


def _stop_behind(exc: BaseException, kinds: tuple = (KeyboardInterrupt,)) -> BaseException | None:
    """The stop (one of ``kinds``) that ``exc`` is or was caused by, None if neither. A stop that comes
    while a module is being loaded reaches the command wrapped: Python reports one raised inside a
    class's creation (a dataclass field's __set_name__) as a RuntimeError caused by it, and one inside
    an extension module's initialisation (SciPy's HiGHS) as an ImportError caused by it."""
    return next((e for e in (exc, exc.__cause__) if isinstance(e, kinds)), None)


def _stopped_loading(exc: BaseException) -> int:
    """The exit code of a Ctrl-C that came while modules were loading (re-raising anything else), told
    in one line."""
    if _stop_behind(exc) is None:
        raise exc
    print("desdemona: interrupted (SIGINT): stopped, nothing written", file=sys.stderr)
    return 128 + signal.SIGINT


try:  # a Ctrl-C while the libraries load (a second or two) ends the command quietly, as later
    from desdemona import profiles
    from desdemona.cli.exits import EXIT_NOT_CONVERGED, EXIT_UNSAFE, EXIT_USAGE, UserError
    from desdemona.cli.options import build_parser
    from desdemona.cueing import sizing
    from desdemona.machine.params import ParameterError
    from desdemona.runs import session
    from desdemona.support import allocator, guard
except (KeyboardInterrupt, RuntimeError, ImportError) as exc:  # see _stop_behind
    raise SystemExit(_stopped_loading(exc)) from None

__all__ = ["EXIT_NOT_CONVERGED", "EXIT_UNSAFE", "EXIT_USAGE", "UserError", "main"]


def _tell(text: str) -> None:
    print(f"desdemona: {text}", file=sys.stderr, flush=True)


def main(argv: list[str] | None = None) -> int:
    try:  # building the table of commands takes a tenth of a second, where a Ctrl-C may come too
        args = build_parser().parse_args(argv)
    except SystemExit as exc:  # argparse has printed its message (or --help): report, do not exit
        return int(exc.code or 0)
    except KeyboardInterrupt:
        print(f"desdemona: {guard.Interrupted(signal.SIGINT).message}", file=sys.stderr)
        return 128 + signal.SIGINT
    blank = next((name for name in ("out", "csv")
                  if isinstance(getattr(args, name, None), str) and not getattr(args, name).strip()), None)
    if blank is not None:  # Path("") is the current folder: never what an empty name meant
        print(f"desdemona: error: --{blank} {getattr(args, blank)!r}: give a name", file=sys.stderr)
        return EXIT_USAGE
    try:  # the result's modules load here, where a Ctrl-C may still come
        from desdemona.check.simulate import LimitViolation
        from desdemona.results.report import ReportError
    except (KeyboardInterrupt, RuntimeError, ImportError) as exc:
        return _stopped_loading(exc)

    allocator.reuse_freed_memory()  # IPOPT's factorisations reuse their workspace (allocator.py)
    allocator.one_blas_thread()  # one process per start, no spinning BLAS threads between them
    try:
        # args.held: the output folders this run holds (report.claim), released as it ends
        # a compile into a fresh cache is told, whatever the command (guard.lasting)
        with guard.interruptible(), contextlib.ExitStack() as args.held, guard.reporting(None, tell=_tell):
            return args.run(args)
    except KeyboardInterrupt:  # a Ctrl-C before the guard was in place (or after it was removed)
        print(f"desdemona: {guard.Interrupted(signal.SIGINT).message}", file=sys.stderr)
        return 128 + signal.SIGINT
    except BrokenPipeError:  # the reader of stdout has gone (`| head`): the rest is not wanted
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nor a traceback at exit's flush
        return 0
    except (UserError, ParameterError, profiles.ProfileError, session.ChoiceError, ReportError,
            sizing.TooLarge, sizing.TooLong) as exc:
        print(f"desdemona: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except LimitViolation as exc:
        print(f"desdemona: no result written: {exc}", file=sys.stderr)
        return EXIT_UNSAFE
    except guard.Interrupted as exc:
        end_bar = "\n" if sys.stderr.isatty() else ""  # a progress bar may be half drawn
        print(f"{end_bar}desdemona: {exc.message}", file=sys.stderr)
        return exc.code
    except (RuntimeError, ImportError) as exc:  # a stop that came while a module was being loaded
        stop = _stop_behind(exc, (guard.Interrupted, KeyboardInterrupt))
        if isinstance(stop, guard.Interrupted):
            print(f"desdemona: {stop.message}", file=sys.stderr)
            return stop.code
        if isinstance(stop, KeyboardInterrupt):
            print(f"desdemona: {guard.Interrupted(signal.SIGINT).message}", file=sys.stderr)
            return 128 + signal.SIGINT
        raise
