"""The person in the cabin: the vestibular model and its perception thresholds (thesis chapter 6,
:mod:`.perception`), the Coriolis cross-coupling of a head movement in the turning cabin
(:mod:`.coriolis`) and the sickness dose of a session (:mod:`.sickness`)."""
