r"""The claims of Sections 5-7 on the direction of travel: three centred wheels are not omnidirectional
(``omnidirectional``), and with mobility 1 a jump in the direction of travel needs re-steering
(``discontinuous-heading``); offset wheels need none.
"""

from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.analysis.mobility import rank_F
from wmr.analysis.steering import steering_angles
from wmr.model.tolerance import TOL

from ...text import bound
from ...verify import SEED
from .. import Derivation, claim
from .motions import corner, curved_translation
from .robots import robots

__all__ = ["omnidirectional", "discontinuous_heading"]


def omnidirectional(n=2000, seed=SEED):
    r"""Claim ``omnidirectional``: three centred wheels are not omnidirectional; they must stop only to turn a sharp
    corner exactly.

    Parameters
    ----------
    n : int
        Random and coordinated steering configurations.
    seed : int

    Returns
    -------
    Derivation
        ``dims`` (admissible twist dimensions, centred and offset), ``corner`` (:func:`corner`),
        ``curve`` (:func:`curved_translation`), finding ``omnidirectional``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    B = np.concatenate([rng.uniform(-np.pi, np.pi, (n, 3)), steering_angles(cen, rng.normal(size=(n, 3)))])
    dims = sorted(set((3 - (rank_F(cen, B) - 3)).tolist()))
    dims_off = sorted(set((3 - (rank_F(off, B) - 6)).tolist()))
    c = corner()
    curve = curved_translation()
    holds = dims == [3]
    proven = (
        dims == [0, 1]
        and dims_off == [3]
        and c["centred"]["slip"] < TOL
        and c["centred"]["moved"] == 0.0
        and not c["centred"]["admissible_at_once"]
        and abs(c["centred"]["at_once"] - c["v"]) < TOL
        and c["dual"]["slip"] < TOL
        and c["dual"]["moved"] < TOL
        and curve["psi"] < TOL
        and curve["slip"] < 1e-6
        and curve["miss"] < 1e-9
        and abs(curve["turned"] - curve["omega"] * curve["t_end"]) < 0.05
    )
    # the word's other meaning: any direction of travel, reached by re-steering (at rest or while moving)
    other_meaning = (
        c["centred"]["slip"] < TOL and c["centred"]["moved"] == 0.0 and curve["slip"] < 1e-6 and curve["miss"] < 1e-9
    )
    scope = (
        "terminology: false in the sense the paper gives the word in Section 4.2 (every twist executable at once), "
        "true in the looser sense of travelling in any direction after re-steering, which the same computation shows "
        "(the corner re-steered at rest and the curvilinear translation, both without slip)"
        if not holds and other_meaning
        else ""
    )
    return Derivation(
        dims=dims,
        dims_offset=dims_off,
        corner=c,
        curve=curve,
        n=2 * n,
        findings=[
            claim(
                "omnidirectional",
                holds,
                rf"the admissible twists of three centred wheels form a space of dimension at most 1 at all {2 * n} "
                r"configurations (3 for offset wheels); a 90-degree corner followed exactly needs the wheels re-steered with "
                r"the platform at rest (commanding the new twist at once slips at the full speed), while a curvilinear "
                rf"translation whose direction turns by ${np.degrees(curve['turned']):.0f}^\circ$ is followed without "
                rf"stopping: the twist executed differs from the one commanded by ${bound(curve['miss'], latex=True)}$, slip "
                rf"${bound(curve['slip'], latex=True)}$ (`wmr.simulate`)",
                max(curve["slip"], curve["miss"]),
                refuted=f"the admissible twists have dimension {' or '.join(map(str, dims))} (never 3): a twist in another "
                "direction than the current one cannot be executed without re-steering",
                corrected=r"A WMR with three centred (or dual) wheels has mobility $\nu = 1$ ($0$ at uncoordinated steering "
                r"angles): it is not omnidirectional. It can travel in any direction, and change direction while "
                r"moving when the wheels are re-steered together (they stay parallel, as in the curvilinear "
                r"translation of Fig. 8b); it must stop only to follow a sharp corner exactly, re-steering with the "
                r"platform at rest (type $(1, 2)$ in the classification of Campion et al.)",
                corrected_holds=proven,
                severity="wrong",
                overturn=(
                    r"the looser meaning of *omnidirectional*, travelling in any direction after re-steering: under it the"
                    r" claim holds (the terminology scope)"
                ),
                why="omnidirectional means every twist executable at once, the paper's own use in Section 4.2; decoupled "
                "steering only lets the wheels turn, one direction of motion at a time",
                convention="omnidirectional = every platform twist executable at once from any configuration (Section 4.2)",
                scope=scope,
            )
        ],
    )


def discontinuous_heading(n=2000, seed=SEED):
    r"""Claim ``discontinuous-heading``: with mobility 1 a jump in the direction of travel needs re-steering; offset
    wheels need none.

    Parameters
    ----------
    n : int
        Random twist jumps.
    seed : int

    Returns
    -------
    Derivation
        ``rows`` (executable fraction and largest residual per case), ``gain`` (largest joint-rate gain of the
        offset robot), ``bound`` (its bound), ``corner`` (:func:`corner`), finding ``discontinuous-heading``.
    """
    cen, _, off = robots()
    rng = np.random.default_rng(seed)
    t_minus, t_plus = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    lam = rng.choice([-1, 1], n) * rng.uniform(0.2, 3.0, n)
    b_minus = steering_angles(cen, t_minus)
    jump = inverse(cen, b_minus, t_plus)
    scaled = inverse(cen, b_minus, lam[:, None] * t_minus)
    be_off = rng.uniform(-np.pi, np.pi, (n, 3))
    sol_off = inverse(off, be_off, t_plus)
    gain = np.linalg.norm(sol_off.value, axis=-1) / np.linalg.norm(t_plus, axis=-1)
    bound_ = np.linalg.svd(off.J1(), compute_uv=False)[0] / np.linalg.svd(off.J2(be_off), compute_uv=False)[..., -1]
    c = corner()
    rows: list[dict] = [
        {
            "case": r"centred: $\mathbf t^-$ to a random $\mathbf t^+$",
            "executable": float(jump.admissible.mean()),
            "largest residual": float(np.abs(jump.residual).max()),
        },
        {
            "case": r"centred: $\mathbf t^-$ to $\lambda\mathbf t^-$ (incl. "
            r"reversal)",
            "executable": float(scaled.admissible.mean()),
            "largest residual": float(np.abs(scaled.residual).max()),
        },
        {
            "case": r"offset ($d = r$): any $\boldsymbol\beta$, random "
            r"$\mathbf t^+$",
            "executable": float(sol_off.admissible.mean()),
            "largest residual": float(np.abs(sol_off.residual).max()),
        },
    ]
    res = rows[2]["largest residual"]
    holds = (
        not jump.admissible.any()
        and bool(scaled.admissible.all())
        and bool(sol_off.admissible.all())
        and res < TOL
        and bool(np.all(gain <= bound_ * (1 + 1e-12)))
        and c["offset"]["slip"] < TOL
        and bool(np.allclose(c["offset"]["final"], [0.0, c["v"], c["v"]], atol=0.01 * c["v"]))
    )
    # the mobilities tested (dimension of the admissible twists); the claim is about every mobility below 3
    tested = sorted(set((3 - (rank_F(cen, b_minus) - 3)).tolist()) | set((3 - (rank_F(off, be_off) - 6)).tolist()))
    untested = [m for m in (1, 2) if m not in tested]
    scope = (
        f"special case: the claim is about every mobility below 3; tested at mobility "
        f"{' and '.join(map(str, tested))} (three centred wheels at coordinated angles; offset wheels for the converse), "
        f"not at mobility {' or '.join(map(str, untested))}"
        if holds and untested
        else ""
    )
    return Derivation(
        rows=rows,
        tested=tested,
        gain=float(gain.max()),
        bound=float(bound_.max()),
        corner=c,
        findings=[
            claim(
                "discontinuous-heading",
                holds,
                rf"of {n} random jumps of the twist, none is executable by the centred robot without re-steering, all jumps "
                r"$\mathbf t \to \lambda\mathbf t$ are; the offset robot executes all of them at once, with joint rates "
                r"bounded by "
                r"$\sigma_{\max}(\mathbf J_1)/\sigma_{\min}(\mathbf J_2)\,\|\mathbf t\|$, and turns a 90-degree corner without "
                r"stopping and without slip (`wmr.simulate`)",
                res,
                convention=r"heading = the direction of the platform twist; a jump $\mathbf t \to \lambda\mathbf t$ (same "
                r"instantaneous centre, a reversal for $\lambda < 0$) needs no delay; offset wheels ($d > 0$) "
                r"realise any twist at once",
                scope=scope,
            )
        ],
    )
