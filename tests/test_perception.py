"""Vestibular models (chapter 6) against scipy, closed forms and exact step responses."""

import casadi as ca
import numpy as np
import pytest
import scipy.signal

from desdemona.occupant import perception
from desdemona.occupant.perception import Channel, canals_model, get_model, telban_cardullo_model, thesis_model

W = np.logspace(-3, 3, 400)
ALPHA = 500.0


def closed_forms():
    """The published transfer functions, typed out by hand from their equations."""
    s = 1j * W
    thesis_canal = 5.9 * (1 + 0.11 * s) / ((1 + 5.9 * s) * (1 + 0.005 * s)) * s / (s / ALPHA + 1)  # eq. 6.3
    thesis_otolith = (1 + 1.0 * s) / ((1 + 0.5 * s) * (1 + 0.016 * s))  # eq. 6.5, unit DC gain
    tc_canal = [tl * 30 * s**2 / ((1 + tl * s) * (1 + 0.1 * s) * (1 + 30 * s)) for tl in (6.1, 5.3, 10.2)]
    ym_otolith = (1 + 13.2 * s) / ((1 + 5.33 * s) * (1 + 0.66 * s))
    adaptation = 5.9 * s / (1 + 5.9 * s)  # the thesis canal's dominant time constant alone
    return {"thesis": [thesis_canal] * 3 + [thesis_otolith] * 3,
            "telban-cardullo": tc_canal + [ym_otolith] * 3,
            "canals": [adaptation] * 3 + [np.ones_like(s)] * 3}


MODELS = {"thesis": thesis_model(ALPHA), "telban-cardullo": telban_cardullo_model(), "canals": canals_model()}


def ss_response(A, B, C, D, w):
    """C (jw I - A)^-1 B + D for a single-input single-output realisation."""
    eye = np.eye(len(A))
    return np.array([(C @ np.linalg.solve(1j * wk * eye - A, B) + D)[0, 0] for wk in w])


@pytest.mark.parametrize("name", list(MODELS))
def test_bode_equals_scipy_and_closed_form(name):
    model = MODELS[name]
    expected = closed_forms()[name]
    A, B, C, D = model.state_space()
    for i, ch in enumerate(model.channels):
        h = ch.frequency_response(W)
        _, h_tf = scipy.signal.freqresp(ch.polynomials(), W)
        h_ss = ss_response(*ch.state_space(), W)
        for ref in (h_tf, h_ss, expected[i]):
            np.testing.assert_allclose(np.abs(h), np.abs(ref), rtol=1e-9)
            np.testing.assert_allclose(np.unwrap(np.angle(h)), np.unwrap(np.angle(ref)), atol=1e-9)
        # the six-channel block-diagonal system routes channel i to output i only
        h_block = ss_response(A, B[:, [i]], C[[i], :], D[[i]][:, [i]], W)
        np.testing.assert_allclose(h_block, h, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("name", list(MODELS))
@pytest.mark.parametrize("dt", [0.002, 0.01, 0.1])
def test_discrete_step_equals_analytic_step(name, dt):
    model = MODELS[name]
    system = model.discretize(dt)
    t = np.arange(0.0, 40.0, dt)
    for i, ch in enumerate(model.channels):
        u = np.zeros((len(t), 6))
        u[:, i] = 1.0
        y, _ = system.simulate(u, x0=np.zeros(model.n_states))
        np.testing.assert_allclose(y[:, i], ch.step_response(t), rtol=0, atol=1e-9)
        assert np.abs(np.delete(y, i, axis=1)).max() == 0.0


def test_discretisation_equals_scipy_zoh():
    model = MODELS["thesis"]
    A, B, C, D = model.state_space()
    Ad, Bd, *_ = scipy.signal.cont2discrete((A, B, C, D), 0.01, method="zoh")
    system = model.discretize(0.01)
    np.testing.assert_allclose(system.Ad, Ad, atol=1e-12)
    np.testing.assert_allclose(system.Bd, Bd, atol=1e-12)


@pytest.mark.parametrize("name", list(MODELS))
def test_discrete_and_casadi_agree(name):
    system = MODELS[name].discretize(0.02)
    rng = np.random.default_rng(21)
    u = rng.normal(size=(300, 6)) * [1, 1, 1, 5, 5, 5]
    x0 = rng.normal(size=len(system.Ad))
    y, states = system.simulate(u, x0)
    step = system.casadi_step()
    x = ca.DM(x0)
    for k in range(len(u)):
        x_next, y_k = step(x, u[k])
        np.testing.assert_allclose(np.asarray(y_k).ravel(), y[k], rtol=1e-12, atol=1e-12)
        x = x_next
        np.testing.assert_allclose(np.asarray(x).ravel(), states[k + 1], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("dt", [0.005, 0.02, 0.1, 0.2])
def test_first_order_discretisation_in_closed_form_equals_scipy_zoh(dt):
    """The canals model's states do not couple: its discretisation is a closed form in the step, a
    CasADi expression that a grid of varying steps evaluates per interval; it equals the matrix
    exponential of :meth:`discretize` and scipy's zero-order hold."""
    model = MODELS["canals"]
    assert model.diagonal and model.n_states == 3 and not MODELS["thesis"].diagonal
    h = ca.SX.sym("h")
    Ad_h, Bd_h = model.casadi_discrete(h)
    Ad, Bd = (np.asarray(ca.Function("f", [h], [m])(dt)) for m in (Ad_h, Bd_h))
    reference = scipy.signal.cont2discrete(model.state_space(), dt, method="zoh")
    for mine, theirs in ((Ad, reference[0]), (Bd, reference[1]), (model.discretize(dt).Ad, reference[0])):
        np.testing.assert_allclose(mine, theirs, rtol=1e-12, atol=1e-15)
    with pytest.raises(ValueError, match="first-order"):
        MODELS["thesis"].casadi_discrete(h)


def test_continuous_casadi_ode_integrates_to_the_step_response():
    model = MODELS["thesis"]
    ode = model.casadi_ode()
    x = ca.MX.sym("x", model.n_states)
    u = ca.DM([0, 0, 1.0, 0, 0, 1.0])
    F = ca.integrator("F", "cvodes", {"x": x, "ode": ode(x, u)[0]}, 0.0, [0.5, 2.0, 8.0],
                      {"abstol": 1e-12, "reltol": 1e-12})
    xs = np.asarray(F(x0=0)["xf"])
    for k, t in enumerate((0.5, 2.0, 8.0)):
        y = np.asarray(ode(xs[:, k], u)[1]).ravel()
        np.testing.assert_allclose(y[2], model.channels[2].step_response(np.array([t]))[0], atol=1e-8)
        np.testing.assert_allclose(y[5], model.channels[5].step_response(np.array([t]))[0], atol=1e-8)


def test_otolith_sensitivity_band_like_figure_6_6(capsys):
    """Gain above its DC value from 0.1 to 10 Hz, peaking inside the band, falling off above it."""
    otolith = MODELS["thesis"].channels[3]
    dc = abs(otolith.frequency_response(0.0))
    band = 2 * np.pi * np.logspace(-1, 1, 200)
    gain = np.abs(otolith.frequency_response(band))
    assert dc == pytest.approx(1.0)
    assert np.all(gain > dc)
    w = np.logspace(-3, 4, 2000)
    g = np.abs(otolith.frequency_response(w))
    assert band[0] <= w[np.argmax(g)] <= band[-1]
    assert g[w > 1e3].max() < 0.5 * dc
    assert capsys.readouterr() == ("", "")


def test_canal_normalisation_and_washout():
    """Thesis canal: velocity gain 1 on its plateau, a constant rotation is no longer felt after ~30 s."""
    canal = MODELS["thesis"].channels[2]
    assert abs(canal.frequency_response(1.0)) == pytest.approx(1.0, abs=0.06)
    assert abs(canal.frequency_response(0.0)) == 0.0
    dt = 0.01
    S = np.zeros((6000, 6))
    S[:, 5] = 9.81
    S[100:, 2] = 0.5  # a 0.5 rad/s yaw starting at 1 s
    perceived = MODELS["thesis"].perceive(S, dt)
    np.testing.assert_allclose(perceived[:100], S[:100], atol=1e-12)  # level and at rest: felt as it is
    assert perceived[100:200, 2].max() > 0.4
    assert abs(perceived[-1, 2]) < 0.01 * 0.5
    np.testing.assert_allclose(perceived[:, 5], 9.81, rtol=1e-12)


def test_unnormalised_young_meiry_keeps_published_gain():
    otolith = telban_cardullo_model(normalised=False).channels[4]
    assert abs(otolith.frequency_response(0.0)) == pytest.approx(0.4)


def test_thresholds_helper():
    diff = np.array([[0.01, 0.1, 0.0, 0.1, 0.2, 0.3], [0.06, 0.0, 0.05, -0.16, -0.18, 0.27]])
    mask = perception.below_threshold(diff)
    np.testing.assert_array_equal(mask, [[True, False, True, True, False, False],
                                         [False, True, False, True, False, True]])


def test_errors():
    with pytest.raises(ValueError, match="unknown perception model 'vestibulum'"):
        get_model("vestibulum")
    with pytest.raises(ValueError, match="pole time constant -0.5"):
        Channel("otolith x", 1.0, 0, (1.0,), (-0.5, 0.016))
    with pytest.raises(ValueError, match="zero time constant 0.0"):
        Channel("otolith x", 1.0, 0, (0.0,), (0.5, 0.016))
    with pytest.raises(ValueError, match="alpha"):
        thesis_model(alpha=0.0)
    with pytest.raises(ValueError, match="dt"):
        MODELS["thesis"].discretize(-0.01)
    with pytest.raises(ValueError, match="expected \\(N, 6\\)"):
        MODELS["thesis"].perceive(np.zeros((10, 3)), 0.01)
