"""The replication report (gearrep.report)."""
