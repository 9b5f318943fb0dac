r"""Drawing the seven experiments (matplotlib): the numbers come from the outcomes, these functions only draw them.

Four figures of chapter 9, each of two panels: :func:`draw_drift` (experiments 1-2),
:func:`draw_contacts` (3-4), :func:`draw_friction_noise` (5-6), :func:`draw_resteer` (7).
"""

from __future__ import annotations

import numpy as np

from wmr.plot.style import PALETTE, ROLE, new_figure, panel_title, style

__all__ = ["SHOWN", "draw_contacts", "draw_drift", "draw_friction_noise", "draw_resteer"]

#: how chapter 9 shows its figures (:func:`wmr.plot.design.show_figure`): 100 dpi, a palette of 48 colours --
#: a quarter of the bytes of a full-colour 150-dpi PNG, so that the report stays within its size budget
SHOWN = {"dpi": 100, "colours": 48}

_SIM, _MODEL = PALETTE["vermillion"], PALETTE["blue"]


def _legend(ax):
    """The panel's legend below its axes, outside the data: a legend inside would cover some of it."""
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), fontsize=7, frameon=False)


def _grid(ax):
    ax.grid(True, lw=0.3, color=PALETTE["light"])


def draw_drift(dead, jam, fig=None):
    r"""(a) The dead zone: the path of C in MuJoCo, wmr's circle about :math:`C_f`, the contact points;
    (b) steering with the drives locked: the steering travel against time, generic and equal angles.

    Parameters
    ----------
    dead, jam : Outcome
        Of :func:`~edition.physics.drift.dead_zone_experiment` and :func:`~edition.physics.drift.jam_experiment`.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style():
        fig, (a, b) = new_figure(1, 2, width=8.0, height=3.4, fig=fig, drawing=False)
        D = dead.data
        s = 1000.0  # mm
        C, Cf, d = D["C"] * s, D["Cf"] * s, D["d"] * s
        th = np.linspace(0, 2 * np.pi, 200)
        a.plot(
            Cf[0] + d * np.cos(th),
            Cf[1] + d * np.sin(th),
            color=_MODEL,
            ls="--",
            lw=1.0,
            label="wmr: radius d about $C_f$",
        )
        a.plot(C[:, 0], C[:, 1], color=_SIM, lw=1.4, label="MuJoCo: path of C")
        a.plot(*Cf, marker="+", color=PALETTE["black"], ms=9)
        a.annotate("$C_f$", Cf, xytext=(4, 4), textcoords="offset points")
        a.plot(*C[0], "o", color=_SIM, ms=4)
        a.set_aspect("equal", adjustable="datalim")
        a.set_xlabel("X (mm)")
        a.set_ylabel("Y (mm)")
        _legend(a)
        panel_title(a, "a", "one full turn, drives locked")
        _grid(a)
        for name, colour in (("generic", _SIM), ("equal", _MODEL)):
            rec = jam.data[name]["rec"]
            travel = np.degrees(np.abs(rec.beta - rec.beta[0]).max(axis=1))
            b.plot(rec.t, travel, color=colour, label=f"{name} angles: steering turned")
            steer = [k for k, n in enumerate(rec.export.servo_names) if n.endswith("steer")]
            torque = np.abs(rec.torque[:, steer]).max(axis=1)
            b.plot(
                rec.t,
                360 * torque / torque.max() if name == "generic" else np.nan * rec.t,
                color=colour,
                ls=":",
                lw=1.0,
                label="generic angles: steering torque (full scale = limit)" if name == "generic" else None,
            )
        t = jam.data["generic"]["rec"].t
        b.plot(t, np.minimum(t, 4.0) / 4.0 * 360, color=PALETTE["grey"], ls="--", lw=0.8, label="commanded")
        b.set_xlabel("t (s)")
        b.set_ylabel("steering angle turned (deg)")
        b.set_ylim(-10, 380)
        _legend(b)
        panel_title(b, "b", "steering with the drives locked")
        _grid(b)
    return fig


def draw_contacts(steer, brake, fig=None):
    r"""(a) Slip of the wheels, coordinated and incompatible steering, beside wmr's least-squares slip;
    (b) the push that moves a parked robot, by direction, Fig. 12a against parked and braked.

    Parameters
    ----------
    steer, brake : Outcome
        Of :func:`~edition.physics.contact.steering_experiment` and :func:`~edition.physics.contact.brake_experiment`.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style():
        fig, (a, b) = new_figure(1, 2, width=8.0, height=3.4, fig=fig, drawing=False)
        for (name, v), colour in zip(((k, steer.data[k]) for k in ("coordinated", "incompatible")), (_MODEL, _SIM)):
            rec = v["rec"]
            slip = np.linalg.norm(rec.slip.reshape(len(rec.t), -1), axis=1)
            a.plot(rec.t, slip, color=colour, label=f"{name} (rank F = {v['rank']})")
            a.axhline(v["predicted_slip"], color=colour, ls="--", lw=0.8)
        a.annotate(
            "wmr's least-squares slip",
            (0.5, steer.data["incompatible"]["predicted_slip"]),
            xytext=(0, 3),
            textcoords="offset points",
            fontsize=7,
        )
        a.set_xlabel("t (s)")
        a.set_ylabel("slip of the wheels (m/s)")
        a.set_ylim(bottom=0)
        _legend(a)
        panel_title(a, "a", "slip: coordinated and incompatible")
        _grid(a)
        ang = brake.data["directions"]
        styles = {
            "fig12a": (_SIM, "Fig. 12a, drives free"),
            "parked": (_MODEL, "parked, drives free"),
            "braked": (PALETTE["green"], "parked, drives locked"),
        }
        for name, (colour, label) in styles.items():
            v = brake.data[name]
            b.semilogy(ang, v["measured"], "o-", color=colour, ms=3, lw=1.0, label=label)
            if v["predicted"] is not None:
                b.semilogy(ang, v["predicted"], ls="--", color=colour, lw=0.8)
        b.set_xticks(range(0, 361, 60))
        b.set_xlabel("direction of the push (deg)")
        b.set_ylabel("push that moves it / weight")
        _legend(b)
        panel_title(b, "b", "braking (dashed: limit analysis)")
        _grid(b)
    return fig


def draw_friction_noise(reorient, noise, fig=None):
    r"""(a) The torque to reorient a unit in place, torsional friction on and off, against the paper's prediction;
    (b) the spread of the forward-kinematics error against :math:`\kappa(\mathbf J)`, design by design.

    Parameters
    ----------
    reorient, noise : Outcome
        Of :func:`~edition.physics.friction.reorient_experiment` and :func:`~edition.physics.noise.noise_experiment`.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style():
        fig, (a, b) = new_figure(1, 2, width=8.0, height=3.4, fig=fig, drawing=False)
        T = reorient.data["torque"]
        x = np.arange(2)
        for k, (sw, colour) in enumerate((("on", _SIM), ("off", _MODEL))):
            a.bar(
                x + (k - 0.5) * 0.35,
                [T[("centred", sw)], T[("dual", sw)]],
                width=0.35,
                color=colour,
                label=f"MuJoCo, torsional friction {sw}",
            )
        pred = reorient.data["predicted"]
        a.plot(
            [-0.4, 0.4],
            [pred["centred"]] * 2,
            color=PALETTE["black"],
            ls="--",
            lw=1.0,
            label="paper: dry friction (centred), rolling only (dual)",
        )
        a.plot([0.6, 1.4], [pred["dual"]] * 2, color=PALETTE["black"], ls="--", lw=1.0)
        a.set_xticks(x, ["centred wheel", "dual wheel"])
        a.set_ylabel("torque to reorient (N m)")
        _legend(a)
        panel_title(a, "a", "reorienting in place")
        _grid(a)
        runs = noise.data["runs"]
        kap = np.array([v["kappa"] for v in runs.values()])
        s = np.array([v["spread"] for v in runs.values()])
        top = 1.1 * max(float(kap.max()), float(s.max()))
        b.plot([1, top], [1, top], color=PALETTE["grey"], ls="--", lw=0.8, label="spread = kappa")
        for (name, v), colour in zip(runs.items(), ROLE["path"]):
            b.plot(v["kappa"], v["spread"], "o", color=colour, ms=6, label=name)
        b.set_xlabel(r"$\kappa(\mathbf{J})$ along the run")
        b.set_ylabel("spread of the twist error")
        _legend(b)
        panel_title(b, "b", "encoder noise and isotropy")
        _grid(b)
    return fig


def draw_resteer(resteer, fig=None):
    r"""(a) Path of C through the change of direction, wmr (dashed) and MuJoCo (solid), for two strategies;
    (b) the final path error of every strategy, wmr against MuJoCo.

    Parameters
    ----------
    resteer : Outcome
        Of :func:`~edition.physics.resteer.resteer_experiment`.
    fig : matplotlib.figure.Figure, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style():
        fig, (a, b) = new_figure(1, 2, width=8.0, height=3.4, fig=fig, drawing=False)
        rows = resteer.data["rows"]
        ref = next(iter(rows.values()))["transient"].reference
        a.plot(ref[:, 1], ref[:, 2], color=PALETTE["black"], lw=0.8, ls=":", label="commanded")
        for (name, v), colour in zip(((k, rows[k]) for k in ("plain", "module")), (_SIM, _MODEL)):
            tr, m = v["transient"], v["run"]
            a.plot(tr.pose[:, 1], tr.pose[:, 2], color=colour, ls="--", lw=1.0, label=f"{name}: wmr")
            a.plot(m["pose"][:, 1], m["pose"][:, 2], color=colour, lw=1.4, label=f"{name}: MuJoCo")
        a.set_aspect("equal", adjustable="datalim")
        a.set_xlabel("X (m)")
        a.set_ylabel("Y (m)")
        _legend(a)
        panel_title(a, "a", "path of C")
        _grid(a)
        x = np.arange(len(rows))
        b.bar(x - 0.18, [v["wmr"][1] for v in rows.values()], width=0.36, color=_MODEL, label="wmr.swerve (kinematic)")
        b.bar(x + 0.18, [v["mujoco"][1] for v in rows.values()], width=0.36, color=_SIM, label="MuJoCo")
        b.set_xticks(x, list(rows), rotation=20)
        b.set_ylabel("final path error (m)")
        _legend(b)
        panel_title(b, "b", "path error by strategy")
        _grid(b)
    return fig
