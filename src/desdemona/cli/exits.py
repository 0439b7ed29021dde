"""How the ``desdemona`` command ends: its exit codes, and the error it reports as bad input."""

EXIT_USAGE = 2
EXIT_UNSAFE = 3  # no trajectory within every limit was found: nothing is written
EXIT_NOT_CONVERGED = 4  # a result within every limit is written, but the solver did not converge
EXIT_CODES = """exit codes:
  0    done: the result is written
  1    an unexpected error (a bug: please report it with the command); for `machine`: a setpoint broke
       a limit, or none came
  2    bad input (profile, CSV, parameters, options, --out), --out being written by another run, or a
       problem too large for this machine's memory; nothing is run and nothing is written
  3    no trajectory within every limit was found; nothing is written (batch: for some job)
  4    a result within every limit is written, but the solver stopped before converging (for example
       at its iteration cap): its status is in the printed line and summary.json ("converged": false)
       (batch: for some job, and no job ended with 3)
  130  interrupted by Ctrl-C (SIGINT), 143 by SIGTERM: stopped within a second or two, workers too;
       no partial result is written (batch: the jobs done by then are kept and listed in batch.csv)"""
SEE_EXIT_CODES = "Exit codes: 0 done, 2 bad input, 3 no safe trajectory, 4 not converged, 130 interrupted; " \
                 "see 'desdemona --help'."


class UserError(Exception):
    """Bad input from the user: reported as one line on stderr with exit code 2."""
