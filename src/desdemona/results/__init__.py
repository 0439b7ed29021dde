"""Results a person reads: the result folder (:mod:`.report`), its figures (:mod:`.figures`), the 3D
replay (:mod:`.view`), the comparison of results (:mod:`.compare`), and a design study's figures (:mod:`.studyfigures`)."""
