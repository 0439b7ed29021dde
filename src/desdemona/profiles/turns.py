"""Whether a log's gyros and its accelerometer tell of the same turn: the rate unit, checked by physics.

Where a vehicle moves slowly its accelerometer reads gravity alone (|f| = 1 g), and as the vehicle
tilts, gravity's direction in the sensor's axes turns the other way: for the unit vector u = f / |f|
in body axes, du/dt = -omega x u (the rotation of a fixed vector seen from a turning frame). So the
gyros, integrated, must turn u as the accelerometer sees it turn, whatever the size of the turn. A
factor of 180 / pi = 57.3 between the two names the rate unit: rates logged in deg/s and declared
rad/s turn u 57.3 times as fast as the accelerometer does. A check on the rates' size alone (above
10 rad/s for a second, :func:`.csvfile.check_units`) cannot see it at 9 deg/s.

Only the turn about a horizontal axis moves gravity's direction; a turn about the vertical (a car's
yaw) leaves u where it is, and the component of omega along u is left out (omega x u). A steady
coordinated turn or a loop keeps f fixed in the body while it turns (the felt force is not gravity
there, and |f| is not 1 g); that is why the check reads only where |f| is within
:data:`ONE_G_BAND` of 1 g and the gyros, as declared, turn u at :data:`MIN_TURN_RATE` or faster,
a rate at which no vehicle keeps 1 g steadily along its floor while pitching or rolling, and which
a tilt of 1 deg/s reaches when its deg/s are taken for rad/s.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import ndimage

from desdemona.profiles.path import G

#: Where |f| is within this share of 1 g, the vehicle moves slowly: its accelerometer reads gravity.
ONE_G_BAND = 0.05
#: [rad/s] the gyros, as declared, turn gravity's direction at least this fast where the check reads.
MIN_TURN_RATE = 0.5
#: [s] the least time the check reads before it judges: a longer turn than a noise spike.
MIN_SECONDS = 0.5
#: [s] both signals are smoothed alike (a Gaussian of this standard deviation) before u is differentiated.
SMOOTHING = 0.1
#: The gyros turning u faster than the accelerometer sees it by more than the geometric mean of 1 and
#: 57.3 (7.6) are in deg/s: halfway, on a log scale, between the two units.
DEG_PER_RAD = 180.0 / math.pi
REFUSE_BELOW = 1.0 / math.sqrt(DEG_PER_RAD)


def turn_ratio(t, omega, f) -> tuple[float, float, float] | None:
    """How fast gravity's direction turns as the accelerometer sees it, against how fast the gyros
    turn it, where the log moves slowly (see the module): the least-squares factor k in
    du/dt = -k (omega x u), the time [s] it was read over and the gyros' peak rate of turning u
    there [rad/s]; None where the log never turns fast enough by the gyros' word to tell.

    t : (N,) uniform times [s]; omega : (N, 3) angular rates [rad/s, as declared]; f : (N, 3) specific
    force [m/s^2], in the same axes (any: k does not depend on them). k is 1 for rates in the declared
    unit and 1 / 57.3 for deg/s declared as rad/s."""
    t, omega, f = (np.asarray(x, dtype=float) for x in (t, omega, f))
    if len(t) < 3:
        return None
    step = float(np.median(np.diff(t)))
    sigma = SMOOTHING / step
    f = ndimage.gaussian_filter1d(f, sigma, axis=0, mode="nearest")
    omega = ndimage.gaussian_filter1d(omega, sigma, axis=0, mode="nearest")
    size = np.linalg.norm(f, axis=1)
    u = f / np.where(size > 0, size, 1.0)[:, None]
    seen = np.gradient(u, step, axis=0)  # du/dt as the accelerometer has it
    told = -np.cross(omega, u)  # du/dt as the gyros have it
    reading = (np.abs(size / G - 1.0) <= ONE_G_BAND) & (np.linalg.norm(told, axis=1) >= MIN_TURN_RATE)
    if np.count_nonzero(reading) * step < MIN_SECONDS:
        return None
    k = float(np.sum(seen[reading] * told[reading]) / np.sum(told[reading] ** 2))
    return k, float(np.count_nonzero(reading) * step), float(np.max(np.linalg.norm(told[reading], axis=1)))


def rate_unit_problem(t, omega, f, declared: str) -> str | None:
    """A sentence where the gyros turn gravity's direction 57.3 times (within a factor 7.6 either way)
    as fast as the accelerometer sees it turn: rates in deg/s declared as ``declared`` (rad/s); None
    where they agree, or the log cannot tell (:func:`turn_ratio`)."""
    found = turn_ratio(t, omega, f)
    if declared != "rad/s" or found is None or found[0] >= REFUSE_BELOW:
        return None
    k, seconds, peak = found
    return (f"the rates turn gravity's direction {1.0 / k if k > 0 else math.inf:.3g} times as fast as the "
            f"accelerometer sees it turn (over {seconds:.3g} s where the log reads 1 g, up to {peak:.3g} rad/s "
            f"by the rates): a factor of {DEG_PER_RAD:.1f} is the rates in deg/s; give --rate-unit deg/s")
