"""The independent check of what the tool returns or commands (:mod:`.simulate`: a plant integrator
of the same model and every limit on a grid finer than the optimiser's) and the figures that judge a
result as the occupant feels it (:mod:`.metrics`)."""
