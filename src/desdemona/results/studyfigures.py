"""The figures of a design study (:mod:`desdemona.runs.study`), drawn from its table's rows.

- :func:`draw_felt`: ``felt.png``, the felt error (the weighted RMS of ``S - S_d`` that each point
  minimised, eq. 3.6) against each parameter varied, one colour per recording and configuration, the
  mean over the other parameters at each grid value joined by a line;
- :func:`draw_front`: ``front.png``, two chosen figures of the table against each other and their
  trade-off front (the points no other point beats in both, both taken smaller-is-better), one per
  recording and configuration;
- :func:`draw_binding`: ``binding.png``, which limit binds most: each limit's mean price (its size: a
  held position's is signed) over the points where the results carry prices (``price_*`` columns),
  else the share of points that use it to :data:`desdemona.runs.study.BINDS` or more (``use_*``
  columns).

The rows are dictionaries of the table's columns (numbers as floats, missing ones None); only the
points solved (status "ok" or "not converged") are drawn.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

#: The figure drawn against each parameter.
FELT = "rms"
SOLVED = ("ok", "not converged")


def _figure(**kw):
    from matplotlib.figure import Figure

    return Figure(**kw)


def _groups(rows: list[dict]) -> dict[tuple[str, str], list[dict]]:
    groups: dict[tuple[str, str], list[dict]] = {}
    for row in rows:
        if row.get("status") in SOLVED:
            groups.setdefault((str(row["recording"]), str(row["configuration"])), []).append(row)
    return groups


def _label(group: tuple[str, str]) -> str:
    return f"{Path(group[0]).stem} on {group[1]}"


def _numbers(rows: list[dict], column: str) -> np.ndarray:
    return np.array([np.nan if row.get(column) is None else float(row[column]) for row in rows])


def draw_felt(rows: list[dict], keys: tuple[str, ...], out: Path) -> Path | None:
    """``felt.png``: :data:`FELT` against each parameter of ``keys``; None where nothing is drawn."""
    groups = _groups(rows)
    if not keys or not groups:
        return None
    fig = _figure(figsize=(5.0 * min(len(keys), 3), 3.6 * -(-len(keys) // 3)))
    for i, key in enumerate(keys):
        ax = fig.add_subplot(-(-len(keys) // 3), min(len(keys), 3), i + 1)
        for group, members in groups.items():
            x, y = _numbers(members, key), _numbers(members, FELT)
            dots = ax.plot(x, y, "o", ms=4, alpha=0.6, label=_label(group))[0]
            levels = np.unique(x[np.isfinite(x)])
            if len(levels) < len(x):  # a grid: the mean over the other parameters at each value
                ax.plot(levels, [np.nanmean(y[x == v]) for v in levels], "-", color=dots.get_color())
        ax.set_xlabel(key)
        ax.set_ylabel("felt error: weighted RMS(S - S_d)")
        ax.grid(alpha=0.3)
    fig.axes[0].legend(fontsize=7)
    fig.suptitle("Felt error against each parameter")
    fig.tight_layout()
    fig.savefig(out / "felt.png", dpi=100)
    return out / "felt.png"


def front(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The indices of the points (x, y) that no other point beats in both (smaller is better),
    ordered by x: the trade-off (Pareto) front."""
    finite = np.flatnonzero(np.isfinite(x) & np.isfinite(y))
    order = finite[np.lexsort((y[finite], x[finite]))]
    kept, best = [], np.inf
    for i in order:
        if y[i] < best:
            kept.append(i)
            best = y[i]
    return np.array(kept, dtype=int)


def draw_front(rows: list[dict], a: str, b: str, out: Path) -> Path | None:
    """``front.png``: the columns ``a`` and ``b`` of every point, and their front (:func:`front`) per
    recording and configuration; None where nothing is drawn."""
    groups = _groups(rows)
    if not groups:
        return None
    fig = _figure(figsize=(6.4, 4.8))
    ax = fig.add_subplot(1, 1, 1)
    for group, members in groups.items():
        x, y = _numbers(members, a), _numbers(members, b)
        dots = ax.plot(x, y, "o", ms=4, alpha=0.4)[0]
        best = front(x, y)
        ax.plot(x[best], y[best], "-o", ms=6, color=dots.get_color(), label=f"{_label(group)}: front")
    ax.set_xlabel(a)
    ax.set_ylabel(b)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(f"Trade-off front of {a}\nand {b} (both smaller-is-better)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "front.png", dpi=100)
    return out / "front.png"


def binding(rows: list[dict], binds: float) -> tuple[str, dict[str, float]]:
    """(what, value per limit) of :func:`draw_binding`: the mean price per ``price_*`` column where
    any point has one, else the share of points with a ``use_*`` at ``binds`` or more; largest first."""
    solved = [row for row in rows if row.get("status") in SOLVED]
    names = sorted({k for row in solved for k in row if k.startswith("price_")})
    if any(row.get(k) is not None for row in solved for k in names):
        values = {k[6:]: float(np.nanmean(np.abs(_numbers(solved, k)))) for k in names}  # a held position's is signed
        what = "mean |price| over the points: felt error per 10 % of the limit"
    else:
        names = sorted({k for row in solved for k in row if k.startswith("use_")})
        values = {k[4:]: float(np.mean(np.nan_to_num(_numbers(solved, k)) >= binds)) for k in names}
        what = f"share of the points that use the limit to {binds:g} or more"
    return what, dict(sorted(values.items(), key=lambda item: -np.nan_to_num(item[1])))


def draw_binding(rows: list[dict], binds: float, out: Path, shown: int = 15) -> Path | None:
    """``binding.png``: :func:`binding`'s ``shown`` largest, as bars; None where there is nothing."""
    what, values = binding(rows, binds)
    values = {k: v for k, v in list(values.items())[:shown] if np.isfinite(v) and v > 0}
    if not values:
        return None
    fig = _figure(figsize=(6.4, 0.9 + 0.32 * len(values)))
    ax = fig.add_subplot(1, 1, 1)
    ax.barh(list(values)[::-1], list(values.values())[::-1])
    ax.set_xlabel(what, fontsize=9)
    ax.set_title("Which limit binds most")
    ax.grid(alpha=0.3, axis="x")
    fig.tight_layout()
    fig.savefig(out / "binding.png", dpi=100)
    return out / "binding.png"


def draw(rows: list[dict], keys: tuple[str, ...], out: Path, front_of: tuple[str, str] | None,
         binds: float) -> list[Path]:
    """Every figure of a study into ``out``: the felt error against each parameter of ``keys``, the
    front of ``front_of`` (where given) and which limit binds most; the files written."""
    drawn = [draw_felt(rows, keys, out), draw_front(rows, *front_of, out) if front_of else None,
             draw_binding(rows, binds, out)]
    return [path for path in drawn if path is not None]
