"""Tooth contact analysis (gearrep.tca): cylindrical, bevel, Novikov-Wildhaber and hob-cut pairs,
and the start strategies."""
