"""The baselines a result is judged against: the classical loops simulator operators use today
(:mod:`.classical`, the `dfs` loop and the followers the loops share; :mod:`.washout`, the classical
washout), and the thesis' own numerical method (:mod:`.thesis`)."""
