"""``python -m gearrep``: the ``gearrep`` command (:mod:`gearrep.cli`)."""

from gearrep.cli import main

__all__: list[str] = []

if __name__ == "__main__":
    raise SystemExit(main())
