"""On-line control (thesis section 7.5): the model predictive controller (:mod:`.mpc`), the predictors
of the desired path ahead (:mod:`.predictors`), and the closed-loop on-line session (:mod:`.online`)."""
