"""Support that every layer may use and that knows nothing of motion cueing: CasADi helpers
(:mod:`.symbolic`), the memory allocator's tuning (:mod:`.allocator`), interrupts and word from long
work (:mod:`.guard`), files written whole or not at all (:mod:`.files`), and physical constants
(:mod:`.units`)."""
