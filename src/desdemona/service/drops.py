"""Datagrams a receiver dropped: counted by one of the protocol's fixed reasons
(:data:`desdemona.service.protocol.REASONS`), a bounded sample of what each was, and lines for the
person watching that a flood cannot multiply: at most one per reason per :data:`EVERY` seconds, with
the count since the last."""

from __future__ import annotations

import time
from collections import Counter

from desdemona.service import protocol

#: At most one line per reason this often [s]
EVERY = 1.0
#: What is kept of each reason's datagrams: this many, each this many characters at most
SAMPLES, SAMPLE_CHARS = 5, 160


class Drops:
    """Counts (``counts``: reason -> datagrams) and samples (``samples``: reason -> [(time [s, the
    clock], what it was)], the first :data:`SAMPLES`); ``say(line)``, if given, is told at most once
    per reason per ``every`` seconds of ``clock``."""

    def __init__(self, say=None, clock=time.monotonic, every: float = EVERY):
        self.say, self.clock, self.every = say, clock, every
        self.counts: Counter = Counter()
        self.samples: dict[str, list] = {}
        self.said: dict[str, float] = {}
        self.unsaid: Counter = Counter()

    def __call__(self, reason: str, detail: str = "") -> None:
        """One datagram dropped for ``reason`` (a key of :data:`protocol.REASONS`); ``detail``: the
        offending value or what was wrong, for the sample."""
        if reason not in protocol.REASONS:
            raise KeyError(f"not a drop reason: {reason!r}")
        self.counts[reason] += 1
        now = self.clock()
        sample = self.samples.setdefault(reason, [])
        if len(sample) < SAMPLES:
            sample.append((now, detail[:SAMPLE_CHARS]))
        self.unsaid[reason] += 1
        if self.say is not None and now - self.said.get(reason, -float("inf")) >= self.every:
            count = self.unsaid.pop(reason)
            since = "" if reason not in self.said else f" ({count} since {now - self.said[reason]:.1f} s ago)"
            self.said[reason] = now
            self.say(f"{protocol.REASONS[reason]}{since}" + (f": {detail[:SAMPLE_CHARS]}" if detail else ""))

    def error(self, error: protocol.ProtocolError) -> None:
        """A datagram :func:`protocol.read` refused."""
        self(error.reason, str(error))

    def sample(self) -> dict[str, list[str]]:
        """reason -> the first datagrams' details, for a log."""
        return {reason: [detail for _, detail in kept] for reason, kept in sorted(self.samples.items())}
