"""The `gearrep` command (gearrep.cli): design files, analyses, the family registry, sweeps."""
