"""The options of the stand-in for the motion system (``desdemona machine``), of an operator's
``desdemona command``, of the simulator bridges (``desdemona host flightgear|xplane``), the key every
party takes, and the service's about them: beside :mod:`desdemona.cli.options`' table."""

from __future__ import annotations

from desdemona.cli import bridges, serving


def add_bridge_parsers(kinds) -> None:
    """``desdemona host flightgear`` and ``desdemona host xplane``: the simulator bridges."""
    checked = ("Nothing is forwarded until the stream's first still second (at rest or in level flight) reads "
               "+1 g up in SI units; a stream that then turns implausible (a pause, a reset, wrong units, a "
               "crash) stops being forwarded, with the reason, and 'serve' parks the machine. Exit 2 when the "
               "start check refuses the stream or it does not start within --wait.")
    fg = kinds.add_parser("flightgear", help="forward a running FlightGear's motion (its native FDM output)",
                          description="Read FlightGear's native FDM packets (fgfs --native-fdm=socket,out,60,"
                                      "127.0.0.1,5600,udp --max-fps=60) and send the pilot's motion to 'serve'. "
                                      + checked + " Needs pip install 'desdemona[flightgear]'.")
    fg.add_argument("--listen", default="127.0.0.1:5600", metavar="HOST:PORT",
                    help="where FlightGear sends its native FDM (default: 127.0.0.1:5600)")
    xp = kinds.add_parser("xplane", help="forward a running X-Plane's motion (RREF dataref subscriptions)",
                          description="Subscribe to X-Plane's body rates, g-loads, attitude and position over "
                                      "UDP (RREF) and send the motion to 'serve'. " + checked)
    xp.add_argument("--xplane", default="127.0.0.1:49000", metavar="HOST:PORT",
                    help="X-Plane's UDP port (default: 127.0.0.1:49000)")
    xp.add_argument("--listen", default="127.0.0.1:49005", metavar="HOST:PORT",
                    help="where X-Plane's answers arrive (default: 127.0.0.1:49005)")
    xp.add_argument("--rate", type=int, default=60, metavar="HZ", help="answers a second (default: 60)")
    for parser, run in ((fg, bridges.run_host_flightgear), (xp, bridges.run_host_xplane)):
        parser.add_argument("--to", required=True, metavar="HOST:PORT", help="where 'serve' listens, e.g. 127.0.0.1:5500")
        parser.add_argument("--modulus", action="store_true", help="send the modulus |f| only (for dfs)")
        parser.add_argument("--wait", type=float, default=120.0, metavar="SECONDS",
                            help="the longest the stream may take to start (default: 120; FlightGear's first "
                                 "packets come 10-35 s after it is launched)")
        parser.add_argument("--duration", type=float, default=None, metavar="SECONDS",
                            help="stop after this long (default: when stopped, Ctrl-C)")
        parser.set_defaults(run=run)


KEY_HELP = ("a file holding the shared key (64 hex digits: openssl rand -hex 32 > FILE; chmod 600 FILE): "
            "every datagram is signed with it, and only datagrams signed with it are taken (docs/protocol.md)")


def add_key_options(kinds) -> None:
    """``--key FILE`` on every host (the subcommands ``kinds`` of ``desdemona host``)."""
    for parser in kinds.choices.values():
        parser.add_argument("--key", default=None, metavar="FILE", help=KEY_HELP)


def add_serve_arguments(serve) -> None:
    """The service's options about the machine it drives, the operator it obeys and its key."""
    serve.add_argument("--key", default=None, metavar="FILE", help=KEY_HELP)
    serve.add_argument("--operator", default="127.0.0.1", metavar="HOST",
                       help="the host whose Commands (pause, park, resume, estop, reset) it takes (default: "
                            "127.0.0.1)")
    serve.add_argument("--state-lost", type=float, default=0.5, metavar="SECONDS", dest="state_lost",
                       help="park when the machine's States, once they came, stop for this long (default: 0.5)")
    serve.add_argument("--console", default=None, metavar="HOST:PORT",
                       help="serve the operator's console (a live page with pause, park, resume, emergency stop) "
                            "at http://HOST:PORT/, e.g. 127.0.0.1:8765; any address but loopback needs a token")
    serve.add_argument("--console-token", default=None, metavar="FILE", dest="console_token",
                       help="the console's token, in a file only you may read (default: none on loopback, "
                            "else a new one, printed at start)")


def add_machine_arguments(machine) -> None:
    """The stand-in's own options (after the machine's, which every command shares)."""
    machine.add_argument("--listen", required=True, metavar="HOST:PORT",
                         help="where the setpoints arrive, e.g. 127.0.0.1:5501; States go back to their sender")
    machine.add_argument("--out", required=True, metavar="DIR", help="folder for what was received, made and checked")
    machine.add_argument("--idle", type=float, default=2.0, metavar="SECONDS",
                         help="stop this long after the last datagram, once at rest (default: 2)")
    machine.add_argument("--duration", type=float, default=None, metavar="SECONDS",
                         help="stop after this long (default: when idle or stopped)")
    machine.add_argument("--delay", type=float, default=None, metavar="SECONDS",
                         help="each servo's transport delay (default: 0.010)")
    machine.add_argument("--bandwidth", type=float, default=None, metavar="HZ",
                         help="each servo's position loop, for what the fed-forward rate and acceleration do "
                              "not carry (default: 5)")
    machine.add_argument("--noise", type=float, nargs=2, default=None, metavar=("POSITION", "RATE"),
                         help="measurement noise, one standard deviation [rad or m, rad/s or m/s] "
                              "(default: 1e-5 1e-4)")
    machine.add_argument("--state-rate", type=float, default=100.0, metavar="HZ", dest="state_rate",
                         help="State messages a second, and rows of motion.csv (default: 100)")
    machine.add_argument("--timeout", type=int, default=3, metavar="CYCLES",
                         help="how far behind the setpoints' time line it runs: no setpoint for this many "
                              "cycles and it brakes on its own (default: 3)")
    machine.add_argument("--late", type=float, default=1.5, metavar="CYCLES",
                         help="a setpoint this long after its cycle was due is a timing fault (default: 1.5)")
    machine.add_argument("--fault", default=None, metavar="AT:JOINT",
                         help="inject a drive fault on JOINT (yaw, track, heave, outer_gimbal, inner_gimbal, "
                              "cabin) AT seconds after the first setpoint")
    machine.add_argument("--operator", default="127.0.0.1", metavar="HOST",
                         help="the host whose Commands it takes (default: 127.0.0.1)")
    machine.add_argument("--seed", type=int, default=0, help="seed of the measurement noise (default: 0)")
    machine.add_argument("--key", default=None, metavar="FILE", help=KEY_HELP)
    machine.add_argument("--state-outage", default=None, metavar="START,LENGTH", dest="state_outage",
                         help="send no State for LENGTH seconds from START seconds after the first setpoint "
                              "(a test of the service's loss of them)")
    machine.set_defaults(run=serving.run_machine)


def add_command_parser(sub) -> None:
    """``desdemona command ACTION --to HOST:PORT``."""
    command = sub.add_parser(
        "command", help="an operator's command to 'serve' or 'machine': pause, park, resume, estop, reset",
        description="Send one Command (docs/protocol.md): pause (the service holds the present cue until resume), "
                    "park, resume, estop (an emergency stop: the fastest stop; no motion until reset), reset "
                    "(clears the motion system's fault or emergency stop, at rest).")
    command.add_argument("action", choices=("pause", "park", "resume", "estop", "reset"),
                         help="the operator's action: pause, park, resume, estop or reset")
    command.add_argument("--to", required=True, metavar="HOST:PORT",
                         help="the service's --listen or the machine's --listen address")
    command.add_argument("--key", default=None, metavar="FILE", help=KEY_HELP)
    command.set_defaults(run=serving.run_command)
