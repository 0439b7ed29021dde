"""The felt-motion and suffered figures: drawn for a result (felt.png, suffered.png) and an on-line result
beside its classical loop (online_felt.png, online_suffered.png), for full and modulus-only paths,
without matplotlib's global state."""

from types import SimpleNamespace

import matplotlib
import numpy as np

from desdemona import default_params
from desdemona.check.simulate import Trajectory
from desdemona.profiles import G
from desdemona.results import figures

PNG = b"\x89PNG\r\n\x1a\n"


def trajectory(modulus_only: bool, wobble: float = 1.0) -> Trajectory:
    """A yaw-only trajectory of 4 s at 50 Hz whose force tilts and whose cabin rolls a little."""
    t = np.arange(0.0, 4.0 + 1e-9, 0.02)
    K = len(t)
    S = np.zeros((K, 6))
    S[:, 0] = wobble * np.radians(5.0) * np.sin(3.0 * t)
    S[:, 4] = wobble * 0.5 * np.sin(t)
    S[:, 5] = G
    S_d = None if modulus_only else np.tile(np.r_[0.0, 0.0, 0.0, 0.0, 0.0, G], (K, 1))
    M = np.linalg.norm(S[:, 3:], axis=1)
    column = np.sin(t)[:, None]
    return Trajectory(t=t, q=column, qd=column, qdd=column, tau=column, power=column, S=S, S_d=S_d,
                      M=M, M_d=np.full(K, G))


def test_draw_result_adds_felt_png_for_a_modulus_path(tmp_path):
    joints = default_params().to_dict()["joints"]
    summary = {"configuration": {"name": "dfs", "free_joints": ["yaw"]}, "parameters": {"joints": joints},
               "path": {"name": "test"}, "quality": {"vestibular_model": "telban-cardullo"}}
    names = {p.name for p in figures.draw_result(trajectory(True), summary, tmp_path)}
    assert {"felt.png", "modulus.png", "suffered.png"} <= names
    assert (tmp_path / "felt.png").read_bytes()[:8] == PNG
    assert (tmp_path / "suffered.png").read_bytes()[:8] == PNG


def test_draw_online_sets_the_mpc_beside_the_classical_loop(tmp_path):
    backend = matplotlib.get_backend()
    limits = SimpleNamespace(effort=np.array([3e5]), power=np.array([6e5]))
    result = SimpleNamespace(trajectory=trajectory(False), baseline=trajectory(False, 2.0),
                             model=SimpleNamespace(limits=limits, config=SimpleNamespace(name="dfs", joint_names=("yaw",))),
                             path=SimpleNamespace(name="test"), loop=SimpleNamespace(compute_times=np.full(10, 1e-3)),
                             deadline=0.01, quality=SimpleNamespace(vestibular="thesis"))
    names = {p.name for p in figures.draw_online(result, tmp_path)}
    assert {"online_felt.png", "online_suffered.png"} <= names
    assert (tmp_path / "online_felt.png").read_bytes()[:8] == PNG
    assert (tmp_path / "online_suffered.png").read_bytes()[:8] == PNG
    assert matplotlib.get_backend() == backend
