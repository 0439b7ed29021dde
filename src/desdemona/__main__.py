"""``python -m desdemona``: the same as the ``desdemona`` command."""

import sys

from desdemona.cli import main

sys.exit(main())
