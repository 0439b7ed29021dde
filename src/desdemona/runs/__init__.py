"""Runs of the tool: a session's choices resolved once (:mod:`.session`), an off-line session solved as
they say (:mod:`.solve`), and batches of sessions on local processes or Dask (:mod:`.batch`)."""
