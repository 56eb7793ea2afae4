"""``python -m gearrep``: the ``gearrep`` command (:mod:`gearrep.cli`)."""

from gearrep.cli import main

raise SystemExit(main())
