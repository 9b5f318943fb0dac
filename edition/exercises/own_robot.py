r"""The "your own robot" cells of the chapters: a Markdown summary of any robot."""

from __future__ import annotations

import numpy as np

from wmr.analysis.kinematics import inverse
from wmr.analysis.linalg import rank
from wmr.analysis.mobility import admissible_twists
from wmr.model.robot import Robot

__all__ = ["describe_robot"]


def describe_robot(robot, beta=None, twist=None):
    r"""A Markdown summary of any robot: its units, the sizes of its matrices, rank F and mobility, and a twist's
    feasibility.

    For the "your own robot" cells of the chapters.

    Parameters
    ----------
    robot : wmr.Robot
    beta : array (w,), optional
        Steering angles (default: zeros).
    twist : array (3,), optional
        A platform twist to test (default: none).

    Returns
    -------
    str
        Markdown.
    """
    if not isinstance(robot, Robot):
        raise TypeError(f"robot must be a wmr.Robot, got {type(robot).__name__}")
    beta = np.zeros(robot.w) if beta is None else np.asarray(beta, dtype=float)
    F = robot.F(beta)
    rk = int(rank(F))
    tw = admissible_twists(robot, beta)
    kinds = ", ".join(f"{u.kind} at $({u.position[0]:.3g}, {u.position[1]:.3g})$" for u in robot.wheels)
    lines = [
        f"**Your robot:** {robot.w} units ({kinds}).",
        rf"$\mathbf F$ is ${F.shape[0]}\times{F.shape[1]}$ with rank {rk}: nullity {F.shape[1] - rk}; "
        rf"the platform can follow a {tw.shape[1]}-dimensional set of twists at these steering angles.",
    ]
    if twist is not None:
        sol = inverse(robot, beta, np.asarray(twist, dtype=float))
        lines.append(
            (
                "The twist is executable without slip; joint rates "
                + ", ".join(f"${v:.3g}$" for v in np.ravel(sol.value))
                + "."
            )
            if bool(sol.admissible)
            else f"The twist needs slip (residual ${np.abs(sol.residual).max():.3g}$)."
        )
    return "\n\n".join(lines)
