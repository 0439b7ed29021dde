"""Figures: PNGs are written without touching matplotlib's global state."""

import matplotlib

from desdemona.occupant.perception import MODELS
from desdemona.results import figures


def test_bode_plot_png_leaves_the_backend_alone(tmp_path):
    backend = matplotlib.get_backend()
    for name, make in MODELS.items():
        path = figures.plot_bode(make(), tmp_path / f"{name}.png")
        data = path.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000
    assert matplotlib.get_backend() == backend
