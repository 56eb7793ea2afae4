"""Loaded tooth contact analysis (gearrep.ltca)."""
