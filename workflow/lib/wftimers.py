"""Snakemake's selection timers, cancelled when a run ends.

Snakemake 9 selects the jobs to start again one timespan (of ``--max-jobs-per-timespan``; the
default profile sets 60 s) after every selection, on a
``threading.Timer``. Those threads are not daemons: without this, the interpreter would wait for
the last of them before exiting. The Snakefile calls :func:`cancel_pending_timers` from its
``onsuccess`` and ``onerror`` hooks.
"""

from __future__ import annotations

import threading

__all__ = ["cancel_pending_timers"]


def cancel_pending_timers() -> int:
    """Cancel every ``threading.Timer`` of this process that has not fired; return how many
    timers were asked to stop (a timer that already fired is unaffected)."""
    timers = [t for t in threading.enumerate() if isinstance(t, threading.Timer)]
    for t in timers:
        t.cancel()
    return len(timers)
