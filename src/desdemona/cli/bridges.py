"""The commands of the simulator bridges: ``desdemona host flightgear`` and ``desdemona host xplane``
(:mod:`desdemona.service.flightgear`, :mod:`desdemona.service.xplane`): read the simulator's own UDP
output, check it live and forward it to ``serve``."""

from __future__ import annotations

import sys

from desdemona.cli.exits import UserError
from desdemona.cli.serving import key_of


def _address(text: str, option: str) -> tuple[str, int]:
    from desdemona.service import protocol

    try:
        return protocol.address(text, option)
    except ValueError as exc:
        raise UserError(str(exc)) from None


def _say(text: str) -> None:
    print(f"desdemona: {text}", file=sys.stderr, flush=True)


def _report(result: dict, to: str) -> None:
    delay = (f"; the bridge's own delay median {1e6 * result['delay_median']:.0f} us, p99 "
             f"{1e6 * result['delay_p99']:.0f} us" if result.get("forwarded") else "")
    print(f"forwarded {result.get('forwarded', 0)} of {result.get('samples', 0)} samples to {to} in "
          f"{result['duration']:.1f} s ({len(result['starts'])} start(s), {len(result['stops'])} stop(s)){delay}")
    for at, reason in result["stops"]:
        print(f"  stopped at {at:.2f} s: {reason}")


def _check(wait: float, duration: float | None) -> None:
    if not wait > 0:
        raise UserError(f"--wait {wait!r}: give a number of seconds > 0")
    if duration is not None and not duration > 0:
        raise UserError(f"--duration {duration!r}: give a number of seconds > 0")


def run_host_flightgear(args) -> int:
    from desdemona.service import flightgear

    listen, to = _address(args.listen, "--listen"), _address(args.to, "--to")
    _check(args.wait, args.duration)
    key = key_of(args)
    _say(f"reading FlightGear's native FDM on {args.listen} (fgfs --native-fdm=socket,out,60,{listen[0]},"
         f"{listen[1]},udp --max-fps=60); forwarding to {args.to} once its first seconds look like a vehicle")
    try:
        result = flightgear.run(listen, to, modulus=args.modulus, wait=args.wait, duration=args.duration, say=_say,
                                key=key)
    except OSError as exc:
        raise UserError(f"--listen {args.listen} / --to {args.to}: {exc.strerror or exc}") from None
    _report(result, args.to)
    return result.get("stopped_by", 0)


def run_host_xplane(args) -> int:
    from desdemona.service import xplane

    xp, listen, to = _address(args.xplane, "--xplane"), _address(args.listen, "--listen"), _address(args.to, "--to")
    _check(args.wait, args.duration)
    key = key_of(args)
    if not 1 <= args.rate <= 99:
        raise UserError(f"--rate {args.rate}: X-Plane answers 1 ... 99 times a second")
    _say(f"subscribing to X-Plane at {args.xplane} ({len(xplane.DATAREFS)} datarefs, {args.rate} a second), "
         f"answers to {args.listen}; forwarding to {args.to} once its first seconds look like a vehicle")
    try:
        result = xplane.run(xp, listen, to, rate=args.rate, modulus=args.modulus, wait=args.wait,
                            duration=args.duration, say=_say, key=key)
    except OSError as exc:
        raise UserError(f"--listen {args.listen} / --xplane {args.xplane}: {exc.strerror or exc}") from None
    _report(result, args.to)
    return result.get("stopped_by", 0)
