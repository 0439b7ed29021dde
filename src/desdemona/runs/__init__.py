"""Runs of the tool: a session's choices resolved once (:mod:`.session`) and batches of sessions on
local processes or Dask (:mod:`.batch`)."""
