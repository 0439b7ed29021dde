"""The cueing problem and its solvers (thesis chapters 3-5, 7): the formulation
(:mod:`.formulation`), its transcription into an NLP (:mod:`.transcription`, :mod:`.assembly`), the
real-time iteration's QP (:mod:`.realtime_iteration`), compiled functions and BLASFEO
(:mod:`.compiled`, :mod:`.blasfeo`), the memory and time a problem takes (:mod:`.sizing`), and the
off-line solvers, whole (:mod:`.offline`) and windowed (:mod:`.windows`)."""
