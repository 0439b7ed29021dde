"""``limit_prices.png``: what each limit of the machine costs the felt error, and when it binds.

Drawn from a result's ``summary.json`` (its ``limit_prices``, :mod:`desdemona.cueing.prices`), so that
``desdemona plot`` redraws it from the folder alone. Left: each limit's price, the felt error's
first-order fall if the limit were 10 % wider [m/s^2], dearest at the top; right: the spans of time
in which each of those limits binds (its multiplier is active), over the path's duration.
"""

from __future__ import annotations

from pathlib import Path

#: The most limits the figure shows (the dearest ones).
SHOWN = 14


def draw(summary: dict, path: str | Path, title: str | None = None) -> Path | None:
    """``limit_prices.png`` of a summary with ``limit_prices``; None (nothing drawn) without them."""
    from matplotlib.figure import Figure

    prices = summary.get("limit_prices")
    if not prices:
        return None
    rows = sorted(((family, joint, entry) for family, joints in prices.items() for joint, entry in joints.items()),
                  key=lambda row: -abs(row[2]["price"]))[:SHOWN][::-1]  # dearest at the top
    labels = [f"{family}: {joint}" for family, joint, _ in rows]
    fig = Figure(figsize=(11, 0.9 + 0.32 * max(len(rows), 4)))
    bars, spans = fig.subplots(1, 2, sharey=True, gridspec_kw={"width_ratios": (1, 2)})
    values = [entry["price"] for _, _, entry in rows]
    bars.barh(range(len(rows)), values, color=["C0" if v >= 0 else "C3" for v in values])
    bars.set_yticks(range(len(rows)), labels, fontsize=8)
    bars.axvline(0.0, color="k", lw=0.6)
    bars.set_xlabel("felt error's fall per 10 % of the limit [m/s^2]")
    bars.grid(axis="x", alpha=0.3)
    for k, (_, _, entry) in enumerate(rows):
        pieces = list(zip(entry["binds_from_s"], entry["binds_to_s"]))
        spans.broken_barh([(a, max(b - a, 1e-3)) for a, b in pieces], (k - 0.3, 0.6), color="C1")
    spans.set_xlim(0.0, summary["path"]["duration_s"])
    spans.set_xlabel("t [s]: where the limit binds")
    spans.grid(axis="x", alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    return Path(path)
