"""The tooth surfaces of gearrep.surfaces, one file per family."""
