r"""The robots of Chapter 6: the same three mount points with centred, dual (b = 0.05) and offset (d = r) wheels."""

from __future__ import annotations

from wmr.model.robots import paper_robot

__all__ = ["ROBOT", "robots"]


#: lengths of this chapter's robots (metres)
ROBOT = dict(L=0.4, r=0.1, b=0.05)


def robots():
    """The chapter's three robots on the same mount points: centred, dual (b = 0.05) and offset (d = r) wheels.

    Returns
    -------
    tuple of wmr.Robot
    """
    L, r, b = ROBOT["L"], ROBOT["r"], ROBOT["b"]
    return paper_robot("centred", L=L, r=r), paper_robot("dual", L=L, r=r, b=b), paper_robot("offset", L=L, r=r, d=r)
