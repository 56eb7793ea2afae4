"""Check records of seed 004: every claim of ``claims_004.csv`` judged by the predicates of
:mod:`.claims` (seed 004 prints no numbers for Figs 12-15, so there are no value records); a
reading-dependent claim is recorded with the verdict of the primary reading, beside the table of
its verdict for every flank pair and reading (``claim_readings``)."""

from __future__ import annotations

import pandas as pd

from ... import checks as _checks
from .assembly import PRIMARY
from .claims import CLAIMS, NOT_COMPUTED, claim_verdicts

__all__ = ["checks"]


_LEGEND = (
    "Pairs: A = pinion convex/gear concave, B = pinion concave/gear convex; readings: R1 = phi1 is the "
    "pinion angle (pinion root->top), R2 = gear angle (gear root->top). Status from the primary "
    f"reading {PRIMARY[0]}/{PRIMARY[1]}. S = pi a b (eq 27) unless 'clipped'. "
)


def _variants_text(v: pd.DataFrame) -> str:
    parts = []
    for _, r in v.sort_values(["primary"], ascending=False).iterrows():
        parts.append(
            f"{r['pair']}/{r['reading']}{' (primary)' if r['primary'] else ''}: "
            f"{'holds' if r['holds'] else 'fails'} {r['evidence']}"
        )
    return " || ".join(parts)


def checks(tables: dict, published) -> dict:
    """Check records of every claim of claims_004.csv (``checks``) and the verdict of each
    reading-dependent claim for each flank pair and reading (``claim_readings``)."""
    claims = published.claims[published.claims["seed"] == "004"].set_index("id", drop=False)
    ver = claim_verdicts(tables)
    recs = []
    for cid, v in ver.groupby("id", sort=False):
        prim = v[v["primary"]].iloc[0]
        agree = (
            "verdict is the same for every pair and reading. "
            if v["holds"].nunique() == 1
            else "VERDICT DEPENDS ON THE READING. "
        )
        recs.append(_checks.qualitative(claims.loc[cid], bool(prim["holds"]), _LEGEND + agree + _variants_text(v)))
    for cid, predicate in CLAIMS.items():
        if predicate is None:
            recs.append(_checks.not_computed(claims.loc[[cid]], NOT_COMPUTED[cid]).iloc[0].to_dict())
        else:
            recs.append(_checks.qualitative(claims.loc[cid], *predicate(tables)))
    done = set(ver["id"]) | set(CLAIMS)
    missing = sorted(set(claims.index) - done)
    if missing:
        raise RuntimeError(f"claims without a check record: {missing}")
    return {"checks": pd.DataFrame(recs, columns=_checks.CHECK_COLUMNS), "claim_readings": ver}
