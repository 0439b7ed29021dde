"""The real-time service's commands (``serve``, ``machine``, ``command``, ``host replay|jsbsim``): each
one to three calls of :mod:`desdemona.service`, as :mod:`desdemona.cli.commands` does for the others."""

from __future__ import annotations

import signal
import socket
import sys
import time

import numpy as np

from desdemona import profiles
from desdemona.cli.commands import _inputs, _machine, _result_folder
from desdemona.cli.console import ending, live_console
from desdemona.cli.exits import EXIT_USAGE, UserError
from desdemona.runs import session


def run_serve(args) -> int:
    from desdemona.results import report
    from desdemona.service import protocol, serve, sessionlog
    from desdemona.service.livetrajectory import LiveTrajectory

    model = _machine(args)
    key = key_of(args)  # before the folder: a key refused leaves nothing behind
    out = _result_folder(args)
    channels = args.channels or serve.default_channels(model.config)
    try:
        listen, send = protocol.address(args.listen, "--listen"), protocol.address(args.send, "--send")
        serving = serve.ServeOptions(listen=listen, send=send,
                                     channels=channels, timeout=args.timeout, duration=args.duration,
                                     quiet_end=args.quiet_end, operator=args.operator, state_lost=args.state_lost,
                                     key=key)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    try:  # bound before the controller is built (seconds): a port in use is said at once
        inbound = args.held.enter_context(serve.listening(listen))
    except OSError as exc:
        raise UserError(f"--listen {args.listen}: {exc.strerror or exc}") from None
    reference = None if args.reference is None else profiles.load(args.reference)
    resolved = session.live(model, session.Choices.of(args), channels=channels, rate=args.rate, span=args.duration,
                            horizon=args.horizon, reach=args.reach, predictor=args.predictor, reference=reference,
                            tail_step=args.tail_step)
    options = resolved.options
    console = live_console(args, model, options.mpc.step)  # bound before the session: a port in use said at once

    def say_ready(early):
        before = (f"; {early} host datagram{'s' if early != 1 else ''} came before it was ready (dropped: start "
                  "the host after this line)" if early else "")
        print(f"desdemona: serving {model.config.name} at {1.0 / options.mpc.step:g} Hz, ready: motion from "
              f"{args.listen}, setpoints to {args.send}; Ctrl-C parks the machine and ends the session{before}",
              file=sys.stderr, flush=True)

    def dropping(line):  # at most one a second per reason (service.drops)
        print(f"desdemona: dropping datagrams: {line}", file=sys.stderr, flush=True)

    log = None

    def ready(early):
        nonlocal log  # the log is begun once the service is ready
        log = sessionlog.LiveLog(out, model.config.joint_names, report.RESULT_FORMAT,
                                 trajectory=LiveTrajectory(model, channels, every=round(0.1 / options.mpc.step)),
                                 description={**report.run_description(resolved.path, model.config),
                                              "parameters": model.params.to_dict()})
        say_ready(early)

    served = None
    try:
        served = serve.serve(model, options, serving, ready=ready, on_drop=dropping, inbound=inbound,
                             log=_Later(lambda: log), console=console, record=out)
    finally:
        logged = None if log is None else log.close()
        if console is not None:
            console.close(ending(served))
    if not np.any(served.columns["status"] == "running"):
        dropped = sum(served.dropped.values())
        print(f"desdemona: the session never followed the host: no valid motion came to {args.listen} "
              f"({dropped} datagrams dropped); only its log is in {out}", file=sys.stderr)
        return EXIT_USAGE if served.stopped_by is None else 128 + served.stopped_by
    result = serve.result(served, model, options)
    summary = serve.summary(served, serving)
    k0, k1 = served.span()
    # the whole result replaces the log written as the session went, keeping that log's rows
    report.write_online(result, out, report.command_line(), True, protect=_inputs(args), view=args.view,
                        cycle_columns={k: v[k0:k1] for k, v in served.columns.items()},
                        extra_summary={"service": summary}, files={"session.csv": logged[0], "events.csv": logged[1]})
    print(serve.describe(summary) + f"; written to {out}")
    print(f"  felt while following the host: {result.quality.headline()}")
    if served.stopped_by is not None:
        print(f"desdemona: stopped ({signal.Signals(served.stopped_by).name}): the machine was parked",
              file=sys.stderr)
        return 128 + served.stopped_by
    return 0


def run_machine(args) -> int:
    from desdemona.service import machine, protocol, servo

    model = _machine(args)
    key = key_of(args)
    try:
        listen = protocol.address(args.listen, "--listen")
        options = machine.MachineOptions(
            delay=servo.DELAY if args.delay is None else args.delay,
            bandwidth_hz=servo.BANDWIDTH_HZ if args.bandwidth is None else args.bandwidth,
            noise=servo.NOISE if args.noise is None else tuple(args.noise), state_rate=args.state_rate,
            timeout=args.timeout, late=args.late, fault=None if args.fault is None else machine.parse_fault(args.fault),
            operator=args.operator, seed=args.seed, state_outage=_pair(args.state_outage, "--state-outage"),
            key=key)
        report = machine.run(model, listen, args.out, idle=args.idle, duration=args.duration, options=options)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    except OSError as exc:
        raise UserError(f"--listen {args.listen}: {exc.strerror or exc}") from None
    print(report.describe())
    if report.received == 0:
        print(f"desdemona: no setpoint came to {args.listen}: is it the address 'serve --send' sends to?",
              file=sys.stderr)
        return 1
    if not report.passed:
        return machine.exit_code(report)
    return 128 + signal.SIGINT if report.stopped.startswith("interrupted") else 0


def _pair(text: str | None, option: str) -> tuple[float, float] | None:
    """(start, length) of ``START,LENGTH`` in seconds, or None; UserError naming ``option``."""
    if text is None:
        return None
    try:
        start, length = (float(x) for x in text.split(","))
    except ValueError:
        raise UserError(f"{option} {text!r}: give START,LENGTH in seconds, e.g. 2,1") from None
    if not (start >= 0 and length >= 0):
        raise UserError(f"{option} {text!r}: START and LENGTH must be numbers >= 0")
    return start, length


def run_command(args) -> int:
    from desdemona.service import protocol, signing

    outgoing = signing.Outgoing(key_of(args))
    try:
        to = protocol.address(args.to, "--to")
    except ValueError as exc:
        raise UserError(str(exc)) from None
    action = {"estop": "emergency stop"}.get(args.action, args.action)
    # the sequence: the time in milliseconds, so that commands sent one after another increase
    message = protocol.Command(int(time.time() * 1e3) & 0xFFFFFFFF, time.time(), action)
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
            sock.sendto(outgoing.pack(message), to)
    except OSError as exc:
        raise UserError(f"--to {args.to}: {exc.strerror or exc}") from None
    print(f"sent {action} to {args.to}")
    return 0


def _host_options(args) -> dict:
    from desdemona.service import protocol

    outage = _pair(args.outage, "--outage")
    try:
        to = protocol.address(args.to, "--to")
    except ValueError as exc:
        raise UserError(str(exc)) from None
    return {"to": to, "speed": args.speed, "forecast": args.forecast, "modulus": args.modulus, "drop": args.drop,
            "outage": outage, "seed": args.seed, "key": key_of(args)}


def key_of(args) -> bytes | None:
    """The shared key of ``--key FILE`` (None without one); :class:`UserError` (one line, exit 2) where
    the file cannot be used: missing, not 64 hex digits, or readable by others than its owner."""
    from desdemona.service import signing

    if args.key is None:
        return None
    try:
        return signing.load_key(args.key)
    except ValueError as exc:
        raise UserError(str(exc)) from None


def _say_sent(counts: dict, to: str) -> None:
    print(f"sent {counts['sent']} messages to {to} in {counts['duration']:.1f} s (sequence "
          f"{counts['first_sequence']}-{counts['last_sequence']}; left out: {counts['dropped']} by --drop, "
          f"{counts['outage']} by --outage; latest {1e3 * counts['late']:.1f} ms behind its time)")


def run_host_replay(args) -> int:
    from desdemona.service import hosts

    options = _host_options(args)
    path = profiles.load(args.profile)
    print(f"desdemona: sending {path.name} ({path.duration:g} s) to {args.to}", file=sys.stderr, flush=True)
    try:
        counts = hosts.replay(path, **options)
    except (ValueError, OSError) as exc:
        raise UserError(f"--to {args.to}: {exc.strerror}" if isinstance(exc, OSError) and exc.strerror else str(exc)) from None
    _say_sent(counts, args.to)
    return 0


def run_host_jsbsim(args) -> int:
    from desdemona.service import hosts

    options = _host_options(args)
    print(f"desdemona: flying {args.script} and sending its motion to {args.to}", file=sys.stderr, flush=True)
    try:
        counts = hosts.jsbsim(args.script, rate=args.rate, start=args.start, end=args.end, **options)
    except (ValueError, OSError) as exc:
        raise UserError(f"--to {args.to}: {exc.strerror}" if isinstance(exc, OSError) and exc.strerror else str(exc)) from None
    _say_sent(counts, args.to)
    print(f"  {counts['aircraft']}, from {counts['start']:g} s ({counts['start_reason']}); {counts['ended']}")
    return 0


class _Later:
    """The log the service writes to, once it exists (it is begun when the service listens)."""

    def __init__(self, get):
        self.get = get

    def cycle(self, *args) -> None:
        log = self.get()
        if log is not None:
            log.cycle(*args)
