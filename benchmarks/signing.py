"""What signing costs a datagram: pack and read of each kind of message, unsigned and signed, and the
cost of refusing a forged one (what a flood of them costs the service).

    python benchmarks/signing.py            # the table on stdout
    python benchmarks/signing.py --n 50000

Per kind: the median over ``--repeats`` batches of ``--n`` datagrams of the time per datagram [us] to
pack it (:meth:`Outgoing.pack`: the session, and with a key the timestamp and HMAC-SHA256 tag) and to
read it (:meth:`Incoming.read`: the checks, and with a key the tag and the session's timestamp), on
one core, in CPU time (the process's own, so that other jobs on the machine do not count); the
difference is what a key adds to a message's way from the host to the setpoint (the
host signs, the service verifies) and from the service to the machine.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import numpy as np

from desdemona.service import protocol, signing

KEY = bytes(range(32))


def messages() -> dict[str, protocol.Message]:
    six = np.array([0.1, -0.2, 0.3, 0.5, -2.0, 9.81])
    return {
        "Motion, modulus": protocol.Motion(1, 0.0, np.array([9.81])),
        "Motion, S": protocol.Motion(1, 0.0, six),
        "Motion, S + 1 s forecast at 100 Hz": protocol.Motion(1, 0.0, six, np.tile(six, (100, 1)), 0.01),
        "Setpoint": protocol.Setpoint(1, 0.0, "running", "plan", 1, 0.0, 0.02, six, six, six, six),
        "State": protocol.MachineState(1, 0.0, "following", "none", None, 1, 0.0, six, six),
        "Command": protocol.Command(1, 0.0, "park"),
    }


def per_datagram(message: protocol.Message, key: bytes | None, n: int, repeats: int) -> tuple[float, float]:
    """(pack, read) [s per datagram], the median of ``repeats`` batches of ``n``."""
    packs, reads = [], []
    for _ in range(repeats):
        out, into = signing.Outgoing(key), signing.Incoming(key)
        started = time.process_time()
        data = [out.pack(message) for _ in range(n)]
        packed = time.process_time()
        for datagram in data:
            into.read(datagram)
        packs.append((packed - started) / n)
        reads.append((time.process_time() - packed) / n)
    return float(np.median(packs)), float(np.median(reads))


def forged(message: protocol.Message, n: int, repeats: int) -> float:
    """The time to refuse a datagram signed with another key [s], the median of ``repeats`` batches."""
    data = signing.Outgoing(bytes(32)).pack(message)
    into, times = signing.Incoming(KEY), []
    for _ in range(repeats):
        started = time.process_time()
        for _ in range(n):
            try:
                into.read(data)
            except protocol.ProtocolError:
                pass
        times.append((time.process_time() - started) / n)
    return float(np.median(times))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=20_000, help="datagrams per batch (default: 20000)")
    parser.add_argument("--repeats", type=int, default=5, help="batches (default: 5)")
    args = parser.parse_args(argv)
    print("| message | bytes unsigned / signed | pack [us] unsigned / signed | read [us] unsigned / signed "
          "| added by the key, pack + read [us] | refuse a forged one [us] |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name, message in messages().items():
        plain, signed = per_datagram(message, None, args.n, args.repeats), per_datagram(message, KEY, args.n,
                                                                                       args.repeats)
        sizes = len(signing.Outgoing().pack(message)), len(signing.Outgoing(KEY).pack(message))
        added = 1e6 * (sum(signed) - sum(plain))
        print(f"| {name} | {sizes[0]} / {sizes[1]} | {1e6 * plain[0]:.1f} / {1e6 * signed[0]:.1f} | "
              f"{1e6 * plain[1]:.1f} / {1e6 * signed[1]:.1f} | {added:.1f} | "
              f"{1e6 * forged(message, args.n, args.repeats):.1f} |")
    print(f"\nPython {sys.version.split()[0]}, load average {os.getloadavg()[0]:.2f}; measured "
          f"{time.strftime('%Y-%m-%d')}.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
