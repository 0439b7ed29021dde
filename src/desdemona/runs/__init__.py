"""Runs of the tool: a session's choices resolved once (:mod:`.session`), an off-line session solved as
they say (:mod:`.solve`), batches of sessions on local processes or Dask (:mod:`.batch`), and design studies over the
machine's parameters built on them (:mod:`.study`)."""
