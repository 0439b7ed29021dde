"""``serve --console HOST:PORT``: the operator's console (:mod:`desdemona.service.console`) opened
for a session, its address (and token) said in one line, a bad address or token one line and exit 2."""

from __future__ import annotations

import importlib.util
import signal
import sys

from desdemona.cli.exits import UserError


def live_console(args, model, h: float):
    """The console of ``args.console`` for a session of ``model`` at step ``h`` [s], serving (None without
    the option); closed with ``args.held``. :class:`UserError` where it cannot be."""
    if args.console is None:
        return None
    from desdemona.service import console, protocol

    if importlib.util.find_spec("websockets") is None:
        raise UserError("--console needs the websockets package: pip install 'desdemona[console]'")
    try:
        address = protocol.address(args.console, "--console")
        token = console.access_token(address[0], args.console_token)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    live = console.Console(model, h, address, token, say=lambda line: print(f"desdemona: {line}", file=sys.stderr,
                                                                           flush=True))
    try:
        args.held.enter_context(live)
    except OSError as exc:
        raise UserError(f"--console {args.console}: {exc.strerror or exc}") from None
    kind = "loopback: no token" if token is None else "its token in the address: give it only to the operator"
    print(f"desdemona: the operator's console at {live.url} ({kind})", file=sys.stderr, flush=True)
    return live


def ending(served) -> str:
    """What the console's page says when the session is over."""
    if served is None:
        return "the service stopped"
    if served.stopped_by is not None:
        return f"the service was stopped ({signal.Signals(served.stopped_by).name}) and parked the machine"
    return "the session ended"
