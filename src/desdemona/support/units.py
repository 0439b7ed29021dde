"""Physical constants shared by the machine and the desired paths (SI units)."""

#: Standard gravity as the thesis takes it [m/s^2]: the machine's default ``gravity`` and the 1 g of
#: the desired paths (:data:`desdemona.profiles.G`): a cabin at rest and level feels (0, 0, +GRAVITY) (thesis eq. A.19, B.5).
GRAVITY = 9.81
