"""Physical constants shared by the machine and the desired paths (SI units), and the resolution of
the figures a person reads."""

#: Standard gravity as the thesis takes it [m/s^2]: the machine's default ``gravity`` and the 1 g of
#: the desired paths (:data:`desdemona.profiles.G`); a cabin at rest and level feels (0, 0, +GRAVITY)
#: (thesis eq. A.19, B.5).
GRAVITY = 9.81


#: A printed figure smaller than this in magnitude, in its printed unit (m/s^2, rad/s or deg/s, s,
#: deg, %, 1/s), is printed as 0: it is the arithmetic's round-off, not a motion. Every figure that
#: means something here is 1e-3 or more in these units (the smallest perception threshold, 0.5 deg/s,
#: is 9e-3 rad/s), and nothing is resolved below 1e-8 (IPOPT's tolerance); double precision leaves
#: 1e-16 of a value's size per operation, so a channel that should be 0 reads 1e-30..1e-15 (a false
#: rotation of 4.89e-22 deg/s, a lag of 1.5e-16 s). Only what is printed is rounded: summary.json keeps
#: every figure as computed.
ROUND_OFF = 1e-9


def shown(value):
    """``value`` as printed: 0 where its magnitude is below :data:`ROUND_OFF`; None stays None."""
    return value if value is None or not abs(value) < ROUND_OFF else 0.0
