"""The entries of the value and claim tables of seed 002 (:data:`.checks.VALUES`,
:data:`.claims.CLAIMS`): id -> :class:`Rule`, a :class:`PrintedInput` (a printed design input,
status ``input``) or a not-computed reason, and :func:`evaluate`, which turns one into
(value or holds, note) from the tables."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = [
    "Rule",
    "PrintedInput",
    "one",
    "evaluate",
    "INPUT_RADII",
    "NOT_COMPUTED_SEC3",
]


class Rule:
    """``fn(tables) -> (value or holds, note)`` evaluated only if the tables in ``needs`` exist; a
    value rule may return ``(value, note, rel_tol, basis)``: the tolerance is then widened to rel_tol
    times the published value for the stated physical ``basis`` (never narrowed below the printed
    precision; :func:`gearrep.checks.compare_value`, ``extra_tol``)."""

    __slots__ = ("needs", "fn")

    def __init__(self, needs: tuple[str, ...], fn: Callable[[dict], tuple]):
        self.needs, self.fn = tuple(needs), fn


class PrintedInput(str):
    """A printed value that is a design input of the report, not a result (status ``input``); the
    text says why and where the replication uses it as printed."""

    __slots__ = ()


INPUT_RADII = PrintedInput(
    "versions 1 and 2 radii are design inputs of the circular-arc rack-cutters (refs. 1-4 of the report), not "
    "results of a computation in the report; they are used here as inputs of Table 6.2.4 and 6.2.3"
)


def _sec3_reason(t) -> str:
    """Why the concave-pinion height is not computed, from the table of job concave_heights."""
    ch = t["concave_heights"].set_index("placement")
    a, d = ch.loc["Q_in_pinion_addendum"], ch.loc["Q_in_pinion_dedendum"]
    return (
        "the tooth height of the pinion concave-gear convex design (sec. 3.3) is not computed: the undercutting and "
        "pointing analysis of the heights job (h = h_a + h_d about the pitch line, tooth thickness at the pitch line) "
        "needs a gear rack profile that crosses the pitch line between its limits, and the sec. 3.2 parabolas do not "
        f"give one (job concave_heights, N2 = {int(a['N2'])}). With Q in the pinion addendum (our reading for the "
        f"contact ellipse) the gear rack's profile turns back {a['gear_tip_limit_x_Pn']:.3f}/P_n above the pitch line "
        "and never reaches it; with Q in the pinion dedendum, the placement inequality 3.2.1 implies (the pinion's "
        f"profile at Q turns convex at rho = {d['rho_switch_Pn']:.2f}/P_n, bound {d['rho_bound_eq_3_2_1_Pn']:.2f}/P_n; "
        f"{a['rho_switch_Pn']:.2f}/P_n with Q in the addendum), the generated gear reaches Litvin's limiting line "
        f"{-d['gear_root_limit_x_Pn']:.3f}/P_n below the pitch line, before the profile gets there. Fig. 3.2.1, not in "
        "the text, must show further profile segments (or another placement) that the report does not describe"
    )


NOT_COMPUTED_SEC3 = Rule(("concave_heights",), _sec3_reason)


def one(df, **sel):
    """The one row of ``df`` whose columns equal ``sel`` (compared as strings); KeyError otherwise."""
    m = np.ones(len(df), bool)
    for k, v in sel.items():
        m &= (df[k].astype(str) == str(v)).to_numpy()
    hit = np.flatnonzero(m)
    if len(hit) != 1:
        raise KeyError(f"no unique row for {sel} ({len(hit)} rows)")
    return df.iloc[int(hit[0])]


def evaluate(entry, tables: dict):
    """(value or holds, note) of a :class:`Rule`, or the not-computed reason (a string)."""
    if isinstance(entry, str):
        return entry
    missing = [n for n in entry.needs if n not in tables]
    if missing:
        return f"not computed in this run: tables {missing} are missing"
    return entry.fn(tables)
