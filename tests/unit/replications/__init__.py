"""The code of the replication packages (gearrep.replications): their common face and the papers'
printed equations (the studies' results against the published values: tests/replication)."""
