"""The FMU's material parameters from the numbers a datasheet gives.

- lame(E, nu): Lame's lambda and mu (Pa) from Young's modulus E (Pa) and Poisson's ratio nu.
  The FMU is plane strain: lambda and mu are the 3-D material's, no plane-stress correction.
- stiffness_damping(loss_factor, frequency): Rayleigh's beta (s) of C = beta A that gives
  the loss factor eta (= 2 x the damping ratio) at the frequency f (Hz): eta = beta omega,
  omega = 2 pi f. Stiffness damping grows with frequency: eta is exact at f only.

Which beta keeps steady sliding stable is a separate question: the damped stability map
(examples/results/damped_stability.md) gives the smallest beta per friction coefficient for
the paper's body; it scales with H / c_p (docs/contract.md, "Warnings and guards"), and the
FMU warns at initialization when beta is below it.
"""
from __future__ import annotations

import math


def lame(youngs_modulus: float, poisson_ratio: float) -> tuple[float, float]:
    """(lambda, mu) in Pa."""
    if not youngs_modulus > 0:
        raise ValueError(f"youngs_modulus must be > 0 (got {youngs_modulus!r})")
    if not -1 < poisson_ratio < 0.5:
        raise ValueError(f"poisson_ratio must be in (-1, 0.5) (got {poisson_ratio!r})")
    mu = youngs_modulus / (2 * (1 + poisson_ratio))
    lam = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
    return lam, mu


def stiffness_damping(loss_factor: float, frequency: float) -> float:
    """beta (s) with loss factor eta at frequency f (Hz)."""
    if not (loss_factor >= 0 and frequency > 0):
        raise ValueError(f"need loss_factor >= 0 and frequency > 0 (got {loss_factor!r}, "
                         f"{frequency!r})")
    return loss_factor / (2 * math.pi * frequency)


# Names a study may use instead of the FMU's own (contactbody.study): each pair becomes FMU
# parameters before the point runs; the table keeps the names as given.
DERIVED = {("youngs_modulus", "poisson_ratio"): ("lambda", "mu"),
           ("loss_factor", "loss_frequency"): ("damping_stiffness",)}


def to_fmu(point: dict) -> dict:
    """The point with any DERIVED pair replaced by the FMU parameters it defines."""
    out = dict(point)
    if "youngs_modulus" in out or "poisson_ratio" in out:
        if "lambda" in out or "mu" in out:
            raise ValueError("give youngs_modulus and poisson_ratio, or lambda and mu, not both")
        try:
            out["lambda"], out["mu"] = lame(out.pop("youngs_modulus"), out.pop("poisson_ratio"))
        except KeyError as e:
            raise ValueError(f"youngs_modulus and poisson_ratio go together: {e.args[0]} is "
                             "missing") from None
    if "loss_factor" in out or "loss_frequency" in out:
        if "damping_stiffness" in out:
            raise ValueError("give loss_factor and loss_frequency, or damping_stiffness, not both")
        try:
            out["damping_stiffness"] = stiffness_damping(out.pop("loss_factor"),
                                                         out.pop("loss_frequency"))
        except KeyError as e:
            raise ValueError(f"loss_factor and loss_frequency go together: {e.args[0]} is "
                             "missing") from None
    return out
