"""The operator's console (``serve --console HOST:PORT``): one page in the browser that shows a served
session live and takes the operator's pause, park, resume, emergency stop and reset.

- **Off the hot path.** Each cycle the service hands :meth:`Console.publish` a :class:`Snapshot`: a
  tuple of references to what the cycle has already made (its starting state, command, record, the
  machine's newest State, the host's newest message, two counts), appended to a deque: no copy, no
  JSON, no I/O, no lock held by the cycle. The console's own thread (an asyncio loop running the
  `websockets` server) takes the snapshots 25 times a second, works out what the page shows
  (:class:`Frames`: the felt force at the head of eq. 3.2, the felt direction and the canals'
  felt rotation of chapter 6 against their thresholds, each joint's use of its limits) and sends it.
- **Commands** from the page go into a deque that the cycle empties (:meth:`Console.commands`) into
  the same path as an operator's Command datagram (``_Session.operator`` of
  :mod:`desdemona.service.serve`): logged in the session's events with the cycle's time and who sent
  it (``console <client's address>``).
- **Who may connect** (:func:`access_token`): bound to a loopback address the console needs no token
  (only this computer reaches it); bound to any other address it needs one, read from a file only its
  owner may read, or made at start and printed with the page's address; the page, its stream and so
  every operator command then need it (``?token=``). A stream opened from another site's page (its
  Origin is not this host) is refused, and without a token a request that names another host than a
  loopback one (a site's name made to resolve to this computer), so that a web page elsewhere cannot
  command the machine through the operator's browser.
- **The end.** :meth:`Console.close` sends the page why the session ended and closes the stream; the
  page says so and disables its buttons (as it does when the stream breaks).
"""

from __future__ import annotations

import asyncio
import hmac
import ipaddress
import json
import math
import secrets
import socket
import stat
import threading
import time
from collections import deque
from pathlib import Path
from typing import NamedTuple
from urllib.parse import parse_qs, urlsplit

import numpy as np

from desdemona.check import metrics
from desdemona.machine.params import JOINT_NAMES
from desdemona.occupant import perception
from desdemona.service import protocol

#: Frames sent a second (the page redraws at each).
RATE_HZ = 25.0
#: Snapshots kept for the console's thread (about ten seconds at 100 Hz): the oldest go first if it
#: falls behind; the cycle never waits for it.
KEPT = 1000
#: How long the console's thread lets go between the steps of a frame [s]: a sleep lets go of the
#: interpreter's lock, so that the service's cycle never waits for a whole frame (about a millisecond of
#: model calls), only for one step.
YIELD_S = 1e-4
#: Characters of a made token (URL-safe base64: 32 bytes of randomness).
TOKEN_BYTES = 32
MIN_TOKEN = 16
#: What the page may load and reach: its own inlined code and style, and its host's stream, nothing else.
POLICY = ("default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data:; "
          "connect-src 'self'")
#: The limits whose use a frame shows, in the order of the 3D replay's.
USE_KINDS = ("position", "velocity", "acceleration", "effort", "power")
#: What the page may ask, as the protocol's Command actions.
ACTIONS = protocol.ACTIONS


class ConsoleError(ValueError):
    """The console's address or token cannot be used; the message says which and why (exit 2)."""


class Snapshot(NamedTuple):
    """What one cycle hands the console: references only, nothing computed.

    t : the cycle's time [s, the session's clock]; state : its starting (q, qd, a) of the free joints;
    command : (qdd, jerk); row : the service's record of the cycle (status, command, reason, latency,
    compute time, message age, machine status); paused : the operator's pause, park or stop (None);
    machine : the newest :class:`protocol.MachineState` (None without States); host : the newest
    :class:`protocol.Motion` (None before the first); received, dropped : host messages taken and
    datagrams dropped so far."""

    t: float
    state: tuple
    command: tuple
    row: dict
    paused: str | None
    machine: protocol.MachineState | None
    host: protocol.Motion | None
    received: int
    dropped: int


def is_loopback(host: str) -> bool:
    """Whether ``host`` (an address or a name) is this computer's loopback (127.0.0.0/8, ::1)."""
    try:
        return ipaddress.ip_address(socket.gethostbyname(host)).is_loopback
    except (OSError, ValueError):
        return False


def _names_loopback(host: str) -> bool:
    """Whether a request's Host names this computer's loopback as written (never looked up: a site's
    name may be made to resolve to it)."""
    try:
        return host == "localhost" or ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def read_token(path: str | Path) -> str:
    """The token in the file ``path`` (its first line), refused (:class:`ConsoleError`) where others
    than its owner may read it, it is missing or shorter than :data:`MIN_TOKEN` characters."""
    path = Path(path)
    try:
        mode = path.stat().st_mode
        text = path.read_text(encoding="utf-8").strip().splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise ConsoleError(f"--console-token {path}: {getattr(exc, 'strerror', None) or exc}") from None
    if mode & (stat.S_IRWXG | stat.S_IRWXO):
        raise ConsoleError(f"--console-token {path}: others may read it (mode {stat.S_IMODE(mode):o}): "
                           f"chmod 600 {path}")
    token = text[0].strip() if text else ""
    if len(token) < MIN_TOKEN or any(c.isspace() for c in token):
        raise ConsoleError(f"--console-token {path}: the token must be one word of at least {MIN_TOKEN} "
                           "characters, e.g. as 'openssl rand -hex 32' writes one")
    return token


def access_token(host: str, token_file: str | Path | None = None) -> str | None:
    """The token the console at ``host`` needs: the file's (:func:`read_token`) where one is given;
    else None on a loopback address (only this computer reaches it), a new random one on any other."""
    if token_file is not None:
        return read_token(token_file)
    return None if is_loopback(host) else secrets.token_urlsafe(TOKEN_BYTES)


def _number(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _numbers(values) -> list:
    return [_number(x) for x in np.asarray(values, float).ravel()]


class Frames:
    """What the page shows of the snapshots, one frame at a time, for ``model`` at the session's step
    ``h`` [s]: the canals' filter (chapter 6, ``vestibular``) is run over every cycle, so the felt
    rotation is the one :func:`desdemona.check.metrics.felt_rotation` gives on the session's log."""

    def __init__(self, model, h: float, vestibular: perception.VestibularModel | None = None):
        self.model, self.h = model, h
        self.vestibular = perception.thesis_model() if vestibular is None else vestibular
        self.filter = self.vestibular.discretize(h)
        self.x = None  # the canals' state
        self.made: dict | None = None  # the newest frame (steps)
        # the model's functions and the limits looked up once: a frame is a few calls, not a few lookups
        self.S_of, self.tau_of = model.functions["S"], model.functions["tau"]
        lim = model.limits
        self.bounds = {"velocity": lim.velocity, "acceleration": lim.acceleration, "effort": lim.effort,
                       "power": lim.power}
        bounded = np.isfinite(lim.position_max) & np.isfinite(lim.position_min)
        with np.errstate(invalid="ignore"):  # an unbounded joint's position uses none of a limit
            self.middle = np.where(bounded, 0.5 * (lim.position_max + lim.position_min), 0.0)
            self.half = np.where(bounded, 0.5 * (lim.position_max - lim.position_min), np.inf)
        self.names = model.config.joint_names
        self.thresholds = {"direction_deg": math.degrees(metrics.direction_threshold(self.vestibular.thresholds)),
                           "rotation_deg_s": [math.degrees(x) for x in self.vestibular.thresholds[:3]]}

    def S(self, snap: Snapshot) -> np.ndarray:
        """(6,) S at the head at the cycle's start (eq. 3.2)."""
        q, qd, _ = snap.state
        return np.asarray(self.S_of(q, qd, snap.command[0]), float).ravel()

    @staticmethod
    def desired(snap: Snapshot) -> np.ndarray | None:
        """(6,) S_d of the host's newest message; for the modulus, (0, 0, 0, 0, 0, M): the force along the
        occupant's z. None before the first."""
        if snap.host is None:
            return None
        values = np.asarray(snap.host.values, float).ravel()
        if len(values) == 1:
            return np.array([0.0, 0.0, 0.0, 0.0, 0.0, values[0]])
        return values

    def felt_rotation(self, S: np.ndarray, snaps: list[Snapshot]) -> np.ndarray:
        """(3,) the canals' felt rotation [rad/s] after the cycles ``snaps`` (in order) whose S (K, 6) is
        ``S``, from the filter's state after the ones before."""
        u = np.zeros_like(S)  # the rotation only: the force channels see no difference (metrics.felt_rotation)
        u[:, :3] = S[:, :3]
        for k, snap in enumerate(snaps):
            if snap.host is not None and len(snap.host.values) == 6:
                u[k, :3] -= snap.host.values[:3]
        y, states = self.filter.simulate(u, self.x)
        self.x = states[-1]
        return y[-1, :3]

    def use(self, snap: Snapshot) -> dict:
        """Each free joint's use of its limits at the cycle's start (1 = at a limit): the worst and
        which (position, velocity, acceleration, effort, power), as the 3D replay shows them."""
        q, qd, _ = snap.state
        qdd = snap.command[0]
        tau = np.asarray(self.tau_of(q, qd, qdd), float).ravel()
        table = np.vstack([np.abs(q - self.middle) / self.half, np.abs(qd) / self.bounds["velocity"],
                           np.abs(qdd) / self.bounds["acceleration"], np.abs(tau) / self.bounds["effort"],
                           np.abs(tau * qd) / self.bounds["power"]])
        worst = np.argmax(table, axis=0)
        return {name: {"use": _number(table[worst[i], i]), "kind": USE_KINDS[worst[i]]}
                for i, name in enumerate(self.names)}

    def frame(self, snaps: list[Snapshot]) -> dict:
        """The page's frame after the cycles ``snaps`` (at least one, in order): the newest in full."""
        steps = self.steps(snaps)
        for _ in steps:
            pass
        return self.made

    def steps(self, snaps: list[Snapshot]):
        """:meth:`frame` made a step at a time (one model call each), as a generator: the console's
        thread lets the service's cycle run between steps, so that it never waits on the console for
        longer than one; the frame is then in ``self.made``."""
        S_all = []
        for s in snaps:
            S_all.append(self.S(s))
            yield
        S_all = np.array(S_all)
        rotation = self.felt_rotation(S_all, snaps)
        yield
        use = self.use(snaps[-1])
        yield
        snap = snaps[-1]
        config = self.model.config
        S = S_all[-1]
        S_d = self.desired(snap)
        q = config.expand(snap.state[0])
        f_d = None if S_d is None else S_d[3:]
        direction = metrics.direction_error(S[3:], f_d)[0]
        row = snap.row
        machine = snap.machine
        self.made = {
            "t": snap.t, "status": row["status"], "command": row["command"], "reason": row["reason"],
            "paused": snap.paused,
            "q": dict(zip(JOINT_NAMES, _numbers(q))),
            "measured": None if machine is None else {
                "q": dict(zip(JOINT_NAMES, _numbers(machine.position))), "status": machine.status,
                "fault": machine.fault, "applied_time": _number(machine.applied_time)},
            "omega": _numbers(S[:3]), "f": _numbers(S[3:]),
            "omega_d": None if S_d is None else _numbers(S_d[:3]), "f_d": None if f_d is None else _numbers(f_d),
            "direction_deg": _number(math.degrees(direction)),
            "rotation_deg_s": _numbers(np.degrees(np.abs(rotation))),
            "use": use,
            "latency_ms": _number(1e3 * row["latency_s"]), "compute_ms": _number(1e3 * row["compute_time_s"]),
            "age_ms": _number(1e3 * row["message_age_s"]),
            "host": None if snap.host is None else {"sequence": snap.host.sequence, "time": snap.host.time,
                                                    "values": _numbers(snap.host.values)},
            "received": snap.received, "dropped": snap.dropped,
            "machine_status": row["machine"], "tracking_use": _number(row["tracking_use"]),
        }


def page_data(model, h: float, vestibular: perception.VestibularModel | None = None) -> dict:
    """What the page is built with (the frames bring the rest): the machine's sizes, its joints, which
    are free, their kinds, the thresholds and the session's rate."""
    from desdemona.results.view import geometry

    params = model.params.to_dict()
    frames = Frames(model, h, vestibular)
    return {"title": f"live session on {model.config.name}", "joints": list(JOINT_NAMES),
            "free": list(model.config.joint_names),
            "kinds": {j: params["joints"][j]["kind"] for j in JOINT_NAMES}, "geometry": geometry(params),
            "thresholds": {**frames.thresholds, "vestibular": frames.vestibular.name},
            "rate_hz": 1.0 / h, "frame_hz": RATE_HZ, "actions": list(ACTIONS)}


def page(model, h: float) -> str:
    """The console's page: self-contained (three.js, uPlot and the machine's drawing inlined), its
    stream from the host that served it."""
    from desdemona.results.view import fill

    data = page_data(model, h)
    return fill("console.html", "console.js", f"desdemona console: {data['title']}", data)


class Console:
    """The console of a session of ``model`` at step ``h`` [s] at ``address`` (host, port), needing
    ``token`` (None: none; see :func:`access_token`). :meth:`start` binds and serves in a thread of its
    own; ``say(line)`` is told of each operator command (and of the console's own troubles)."""

    def __init__(self, model, h: float, address: tuple[str, int], token: str | None = None, say=None):
        self.model, self.h, self.address, self.token = model, h, address, token
        self.say = say or (lambda line: None)
        self.snapshots: deque[Snapshot] = deque(maxlen=KEPT)
        self.queue: deque[tuple[float, str, str]] = deque()
        self.frames = Frames(model, h)
        self.html = page(model, h).encode("utf-8")
        self.ended: str | None = None
        self.clients: set = set()
        self.loop: asyncio.AbstractEventLoop | None = None
        self.thread: threading.Thread | None = None
        self.latest: dict | None = None
        self.sent = 0  # frames sent (to any client)

    # ---- the cycle's side: cheap, never waits ----

    def publish(self, session, inbox, link) -> None:
        """Hand the cycle just recorded by the service's ``session`` (with its ``inbox`` of host messages
        and ``link`` to the machine) to the console: a tuple of references appended to a deque."""
        self.snapshots.append(Snapshot(session.rows[-1]["t"], session.starts[-1], session.command, session.rows[-1],
                                       session.paused, link.newest, inbox.newest, len(inbox.t),
                                       sum(inbox.dropped.values()) + sum(link.dropped.values())))

    def commands(self) -> list[tuple[float, str, str]]:
        """The operator commands that came from the page since the last call: (arrived [monotonic s],
        action, who) each, in order."""
        if not self.queue:
            return []
        return [self.queue.popleft() for _ in range(len(self.queue))]

    # ---- the console's thread ----

    @property
    def url(self) -> str:
        host, port = self.address[:2]
        shown = f"[{host}]" if ":" in host else host
        return f"http://{shown}:{port}/" + (f"?token={self.token}" if self.token else "")

    def start(self) -> None:
        """Bind and serve in a thread of its own; OSError (the port in use, ...) raised here."""
        bound = threading.Event()
        failure: list[BaseException] = []
        self.thread = threading.Thread(target=lambda: asyncio.run(self._main(bound, failure)),
                                       name="desdemona-console", daemon=True)
        self.thread.start()
        bound.wait(timeout=30)
        if failure:
            raise failure[0]
        if not bound.is_set():
            raise OSError(f"the console did not start on {self.address[0]}:{self.address[1]}")

    async def _main(self, bound: threading.Event, failure: list) -> None:
        from websockets.asyncio.server import serve

        self.stop = asyncio.Event()
        self.loop = asyncio.get_running_loop()
        try:
            server = await serve(self._client, self.address[0], self.address[1], process_request=self._request,
                                 max_size=4096, ping_interval=None)
        except OSError as exc:
            failure.append(exc)
            bound.set()
            return
        if self.address[1] == 0:  # a free port chosen by the system: the one it is
            self.address = server.sockets[0].getsockname()[:2]
        bound.set()
        async with server:
            ticker = asyncio.create_task(self._tick())
            await self.stop.wait()
            ticker.cancel()
            await self._broadcast(json.dumps({"ended": self.ended}))
            for client in list(self.clients):
                await client.close(1001, "the session ended")
            server.close()

    def _allowed(self, request) -> bool:
        if self.token is None:
            return True
        given = parse_qs(urlsplit(request.path).query).get("token", [""])[0]
        return hmac.compare_digest(given.encode(), self.token.encode())

    def _request(self, connection, request):
        """The page (GET /), the stream (/stream, a WebSocket from this host's page) or a refusal."""
        from websockets.datastructures import Headers
        from websockets.http11 import Response

        path = urlsplit(request.path).path
        named = request.headers.get_all("Host")
        netloc = named[0] if len(named) == 1 else ""  # none, or several: no host of ours
        host = urlsplit("//" + netloc).hostname or ""
        if self.token is None and not _names_loopback(host):
            # a name of another site that resolved to this computer (DNS rebinding): not this page's
            return connection.respond(403, "open the console by its loopback address, e.g. 127.0.0.1\n")
        if not self._allowed(request):
            return connection.respond(403, "the console needs its token: open the address it printed at start\n")
        if path == "/stream":
            origins = request.headers.get_all("Origin")
            origin = origins[0] if len(origins) == 1 else (None if not origins else "")
            if origin is not None and urlsplit(origin).netloc != netloc:
                return connection.respond(403, "a stream for this host's own page only\n")
            return None  # the WebSocket handshake goes on
        if path != "/":
            return connection.respond(404, "the console has one page: /\n")
        headers = Headers([("Content-Type", "text/html; charset=utf-8"), ("Cache-Control", "no-store"),
                           ("Content-Security-Policy", POLICY), ("Content-Length", str(len(self.html)))])
        return Response(200, "OK", headers, self.html)

    async def _client(self, websocket) -> None:
        self.clients.add(websocket)
        who = "console {}:{}".format(*websocket.remote_address[:2])
        try:
            if self.latest is not None:
                await websocket.send(json.dumps(self.latest))
            async for message in websocket:
                reply = self._command(message, who)
                await websocket.send(json.dumps(reply))
        except Exception as exc:  # noqa: BLE001 -- a client's broken stream ends that client only
            from websockets.exceptions import ConnectionClosed

            if not isinstance(exc, ConnectionClosed):
                self.say(f"console: {who}: {exc}")
        finally:
            self.clients.discard(websocket)

    def _command(self, message, who: str) -> dict:
        """An operator's command from the page, ``{"command": action}``: queued for the next cycle."""
        try:
            action = json.loads(message)["command"]
        except (ValueError, TypeError, KeyError):
            return {"refused": "not a command"}
        if action not in ACTIONS:
            return {"refused": f"unknown command {str(action)[:40]!r}"}
        if self.ended is not None:
            return {"refused": f"the session has ended ({self.ended})"}
        self.queue.append((time.monotonic(), action, who))
        self.say(f"console: {action} from {who.removeprefix('console ')}")
        return {"accepted": action}

    async def _tick(self) -> None:
        period = 1.0 / RATE_HZ
        while True:
            await asyncio.sleep(period)
            snaps = [self.snapshots.popleft() for _ in range(len(self.snapshots))]
            if not snaps:
                continue
            try:
                for _ in self.frames.steps(snaps):
                    await asyncio.sleep(YIELD_S)  # the GIL let go: the service's cycle runs if it waits
                self.latest = self.frames.made
            except Exception as exc:  # noqa: BLE001 -- the console must never take the session down
                self.say(f"console: a frame could not be made: {exc}")
                continue
            if self.clients:
                await self._broadcast(json.dumps(self.latest))
                self.sent += 1

    async def _broadcast(self, text: str) -> None:
        from websockets.asyncio.server import broadcast

        broadcast(self.clients, text)

    def close(self, why: str) -> None:
        """Tell the page the session ended (``why``) and stop serving (waits a moment for the thread)."""
        self.ended = why
        if self.loop is not None and self.thread is not None and self.thread.is_alive():
            self.loop.call_soon_threadsafe(self.stop.set)
            self.thread.join(timeout=5)

    def __enter__(self):
        self.start()
        return self

    def __exit__(self, *exc):
        self.close(self.ended or "the service stopped")

