"""Shared helpers of the published-data tests: read a CSV as text, precision of a printed number."""

from __future__ import annotations

import pandas as pd
from conftest import PUBLISHED_DIR as PUB


def read_text_csv(name: str) -> pd.DataFrame:
    """One data/published file with every cell kept as the printed string."""
    return pd.read_csv(PUB / name, dtype=str, keep_default_na=False)


def printed_precision(printed: str) -> tuple[str, int]:
    """("sig", n) for E-notation, else ("decimals", digits after the point)."""
    mant, _, exp = printed.lower().partition("e")
    mant = mant.lstrip("+-")
    if exp:
        return "sig", len(mant.replace(".", "").lstrip("0"))
    return "decimals", len(mant.partition(".")[2])
