"""The person in the cabin: the vestibular model and its perception thresholds (thesis chapter 6,
:mod:`.perception`)."""
