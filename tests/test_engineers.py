"""Issue 24, points 1-4 and 8: twelve engineers' robots (examples/engineers/), actuation, limitations, checked
advice, drivable sweeps and plain-language output, against hand computations."""

import json
from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.analysis.actuation import MotionKind, actuated_mobility, driven_columns, free_twists, uncontrolled
from wmr.analysis.advice import Suggestion, Verdict, advice, motor_conditioning, profile
from wmr.analysis.limitations import LimitationKind, limitations
from wmr.analysis.unit_design import ChangeKind
from wmr.cli import main

ROOT = Path(__file__).resolve().parent.parent
ENG = ROOT / "examples" / "engineers"

#: Campion's class (by the wheel types: Campion, Bastin & d'Andrea-Novel 1996) and the actuated mobility by hand
TABLE = {
    "car": ("(1,1)", 1),
    "forklift": ("(1,1)", 1),
    "skid_steer6": ("(1,0)", 1),
    "diff_drive_castors": ("(2,0)", 2),
    "swerve_offcentre": ("(1,2)", 1),
    "x_drive": ("(3,0)", 3),
    "mecanum_x": ("(3,0)", 3),
    "mecanum_same_hand": ("(3,0)", 2),
    "kiwi": ("(3,0)", 3),
    "agv_two_steer": ("(1,2)", 1),
    "powered_castors3": ("(3,0)", 3),
    "rover6": ("(1,1)", 1),
}


def _load(name):
    return wmr.load(ENG / f"{name}.toml")


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out = capsys.readouterr()
    return code, out.out, out.err


def _headings(lim):
    """The lines of travel of a limitation's motions (all translations), degrees from x."""
    assert all(m.kind is MotionKind.TRANSLATION for m in lim.motions), lim
    return [round(m.heading, 6) + 0.0 for m in lim.motions]


def _twist_dim(F, cols):
    """dim of the twist part of N(F[:, cols]) from the SVD of the column-scaled dense matrix."""
    A = F[:, cols] / np.linalg.norm(F[:, cols], axis=0).clip(1e-300)
    _, s, Vt = np.linalg.svd(A)
    N = Vt[int((s > wmr.TOL * s[0]).sum()) :].T
    return int((np.linalg.svd(N[:3], compute_uv=False) > 1e-6).sum()) if N.shape[1] else 0


@pytest.mark.parametrize("name", sorted(TABLE))
def test_the_twelve_robots(name):
    """Class and actuated mobility as computed by hand; the actuated mobility also from the dense F."""
    bot = _load(name)
    c = wmr.campion_class(bot)
    label, da = TABLE[name]
    assert c.label == label
    assert int(actuated_mobility(bot, c.beta)) == da
    F = bot.F(np.asarray(c.beta))
    passive = list(np.flatnonzero(~driven_columns(bot)) + 3)
    assert _twist_dim(F, list(range(F.shape[1]))) - _twist_dim(F, [0, 1, 2, *passive]) == da
    assert profile(bot)["actuated_mobility"] == da


# ---------------------------------------------------------------------------------- 1. actuation
def test_mecanum_same_hand_motor_map_has_rank_2_by_hand():
    """Each Swedish wheel's motor rate is theta_i = -a_i^T v_i / (r sin g) (its one constraint); with one hand,
    the rows [a^T E d_i, a_x, a_y] have rank 2: the 45 deg diagonal needs every motor at zero."""
    bot = _load("mecanum_same_hand")
    rows = []
    for u in bot.wheels:
        a = u.roller_axis()
        Ed = np.array([-u.position[1], u.position[0]])
        rows.append([a @ Ed, a[0], a[1]])
    assert np.linalg.matrix_rank(np.array(rows)) == 2
    good = _load("mecanum_x")
    rows = [[u.roller_axis() @ np.array([-u.position[1], u.position[0]]), *u.roller_axis()] for u in good.wheels]
    assert np.linalg.matrix_rank(np.array(rows)) == 3
    U = free_twists(bot, np.zeros(4))
    assert U.shape[1] == 1 and abs(U[0, 0]) < 1e-12 and np.isclose(abs(U[1, 0]), abs(U[2, 0]))  # the diagonal


def test_inverse_refuses_a_motion_the_motors_do_not_command():
    bot = _load("mecanum_same_hand")
    sol = wmr.inverse(bot, np.zeros(4), [0.0, 1.0, 1.0])  # along the 45 deg diagonal
    motors = sol.value[driven_columns(bot)]
    assert sol.no_slip and not sol.actuated and not sol.admissible and np.allclose(motors, 0, atol=1e-12)
    part, ok = uncontrolled(bot, np.zeros(4), [0.0, 1.0, 1.0])
    assert not ok and np.allclose(part, [0.0, 1.0, 1.0])
    assert wmr.inverse(bot, np.zeros(4), [0.0, 1.0, -1.0]).admissible  # the other diagonal: driven
    assert wmr.inverse(_load("mecanum_x"), np.zeros(4), [0.0, 1.0, 1.0]).admissible


def test_parallel_omni_wheels_cannot_be_driven_sideways(capsys, tmp_path):
    text = (ENG / "mecanum_x.toml").read_text().replace("roller_deg = 45.0", "roller_deg = 90.0")
    path = tmp_path / "omni_parallel.toml"
    path.write_text(text.replace("roller_deg = -45.0", "roller_deg = 90.0"))
    code, out, _ = _run(capsys, "ik", path, "--vy", "1", "--json")
    data = json.loads(out)
    assert code == 0 and not data["admissible"] and data["no_slip"] and not data["actuated"]
    assert all(abs(v) < 1e-12 for k, v in data["rates"].items() if k.startswith("theta"))
    code, out, _ = _run(capsys, "analyze", path, "--json", "--grid", "100", "--twists", "100")
    data = json.loads(out)
    assert data["actuated_mobility"] == 2 and len(data["uncontrolled"]) == 1 == len(data["limitations"])
    (lim,) = limitations(wmr.load(path))
    assert (lim.kind, lim.actuated_mobility, lim.delta_m, _headings(lim)) == (
        LimitationKind.UNCONTROLLED,
        2,
        3,
        [90.0],
    )


def test_same_hand_mecanum_is_flagged_and_its_fix_is_checked(capsys):
    code, out, _ = _run(capsys, "analyze", ENG / "mecanum_same_hand.toml", "--json", "--grid", "100", "--twists", "100")
    data = json.loads(out)
    assert code == 0 and (data["class"], data["actuated_mobility"]) == ("(3,0)", 2)
    assert data["advised"] == [True, False] and len(data["advice"]) == 2
    bot = _load("mecanum_same_hand")
    (lim,) = limitations(bot)
    assert lim.kind is LimitationKind.UNCONTROLLED and _headings(lim) == [45.0]  # the diagonal
    fix, omni = advice(bot)[0]
    assert (fix.matrix, fix.suggestion, fix.verdict, fix.units) == (
        "actuation",
        Suggestion.REBUILD,
        Verdict.ADVISED,
        (1, 2),
    )
    assert [c.kind for c in fix.changes] == [ChangeKind.OTHER_HAND] * 2
    assert (fix.before["actuated_mobility"], fix.after["actuated_mobility"]) == (2, 3)
    # the fix is the X pattern of mecanum_x.toml; omni wheels are not advised (they lose the sideways motion)
    x = _load("mecanum_x")
    assert [float(u.roller) for u in x.wheels] == pytest.approx(np.radians([45, -45, -45, 45]))
    assert [float(c.unit.roller) for c in fix.changes] == pytest.approx(np.radians([-45, -45]))  # type: ignore[attr-defined]
    assert fix.motor_kappa == pytest.approx(motor_conditioning(x, np.zeros(4)))
    assert omni.changes[0].kind is ChangeKind.OMNI_ROLLERS and omni.verdict is Verdict.COSTS_MOTION
    assert omni.lost is not None and omni.lost.kind is LimitationKind.UNCONTROLLED and _headings(omni.lost) == [90.0]


def test_mecanum_x_omni_advice_is_not_advised():
    tips, _ = advice(_load("mecanum_x"))
    omni = [t for t in tips if t.suggestion is Suggestion.CHANGE_UNITS]
    assert len(omni) == 1 and not omni[0].advised and omni[0].changes[0].kind is ChangeKind.OMNI_ROLLERS
    assert omni[0].after["kappa_J2"] == pytest.approx(1.0) and omni[0].after["actuated_mobility"] == 2
    assert omni[0].before["kappa_J2"] == pytest.approx(1 + np.sqrt(2))  # sqrt((1 + cos g) / (1 - cos g))


def test_advice_that_gains_nothing_by_itself_says_so():
    """AGV: equal radii alone leave kappa(J2) = 2.5 (the castors' blocks stay unequal); with d = r as well, 1."""
    tips, _ = advice(_load("agv_two_steer"))
    radius, both = (
        [t for t in tips if t.suggestion is Suggestion.SAME_RADIUS],
        [t for t in tips if t.suggestion is Suggestion.BOTH],
    )
    assert len(radius) == 1 and radius[0].verdict is Verdict.NO_GAIN and not radius[0].advised
    assert radius[0].after["kappa_J2"] == pytest.approx(radius[0].before["kappa_J2"]) == pytest.approx(2.5)
    assert len(both) == 1 and both[0].advised and both[0].after["kappa_J2"] == pytest.approx(1.0)


def test_a_change_that_costs_a_motion_names_the_limitation_it_brings():
    """Omni rollers on the driven Swedish wheels of a robot on passive fixed wheels: the motors lose the drive
    straight ahead; the limitation named is that one, not the sideways one the robot had before."""
    fixed = [wmr.FixedWheel((0.0, y), r=0.1, angle=np.pi / 2, driven={"drive": False}) for y in (0.3, -0.3)]
    bot = wmr.Robot(fixed + [wmr.SwedishWheel((0.4, y), r=0.1, angle=0.0, roller=np.pi / 4) for y in (0.3, -0.3)])
    (had,) = limitations(bot)
    assert had.kind is LimitationKind.FORBIDDEN and _headings(had) == [90.0]
    omni = next(t for t in advice(bot)[0] if t.suggestion is Suggestion.CHANGE_UNITS)
    assert omni.verdict is Verdict.COSTS_MOTION and (
        omni.before["actuated_mobility"],
        omni.after["actuated_mobility"],
    ) == (2, 1)
    assert omni.lost is not None and omni.lost.kind is LimitationKind.UNCONTROLLED and _headings(omni.lost) == [0.0]


def test_castors_are_passive_by_default_in_files_and_rollers_are_passive():
    bot = _load("diff_drive_castors")
    assert driven_columns(bot).tolist() == [True, True, False, False, False, False]
    assert [j.driven for j in wmr.SwedishWheel((0, 0), r=0.1, angle=0.0, roller=np.pi / 4).joints] == [True, False]
    assert [j.driven for j in wmr.DualWheel((0, 0), r=0.1, b=0.05).joints] == [False, True, True]


# ------------------------------------------------------------------------------ 2. the skid steer
def test_skid_steer_states_its_limit():
    bot = _load("skid_steer6")
    c = wmr.campion_class(bot)
    # by hand: each fixed wheel forbids velocity along its axle y at its mount point: rows [x_i, 0, 1],
    # x_i in {0.45, 0, -0.45}, rank 2: only the translation along x is left (delta_m = 1, no turning)
    rows = np.array([[u.position[0], 0.0, 1.0] for u in bot.wheels])
    assert np.linalg.matrix_rank(rows) == 2 and (c.delta_m, c.delta_s, c.rank_C1f) == (1, 0, 2)
    assert c.name == "degenerate: the fixed wheels allow only a translation along one direction (no turning)"
    (lim,) = limitations(bot)
    assert lim.kind is LimitationKind.NO_TURNING and _headings(lim) == [0.0]
    assert int(actuated_mobility(bot, c.beta)) == 1


def test_limitations_of_the_others():
    (diff,) = limitations(_load("diff_drive_castors"))  # no motion has a part along the axles
    assert diff.kind is LimitationKind.FORBIDDEN and _headings(diff) == [90.0]
    assert [x.kind for x in limitations(_load("car"))] == [LimitationKind.CAR_LIKE]
    assert [x.kind for x in limitations(_load("swerve_offcentre"))] == [LimitationKind.ONE_MOTION]
    for name in ("x_drive", "mecanum_x", "kiwi", "powered_castors3"):
        assert limitations(_load(name)) == []


# ---------------------------------------------------------------------------- 3. checked advice
def test_car_advice_gives_the_L_of_the_moved_robot():
    car = _load("car")
    # by hand: mount points (0, +-0.775), (2.7, +-0.775); centroid (1.35, 0)
    assert wmr.characteristic_length(car) == pytest.approx(np.sqrt((2 * 0.775**2 + 2 * (2.7**2 + 0.775**2)) / 4))
    L_moved = np.hypot(1.35, 0.775)  # every |d_i| after the move
    moved = car.moved(origin=(1.35, 0.0))
    assert wmr.characteristic_length(moved) == pytest.approx(L_moved) and L_moved == pytest.approx(1.557, abs=5e-4)
    assert float(wmr.condition_number(moved.J1(L=L_moved))) == pytest.approx(1.0)
    # the old claim: kappa(J_L1) = 1 at L = 2.06 after the move is false; sqrt(w / (a / L^2)) by (34)
    L_old = wmr.characteristic_length(car)
    assert (
        float(wmr.condition_number(moved.J1(L=L_old)))
        == pytest.approx(L_old / L_moved)
        == pytest.approx(1.32, abs=5e-3)
    )
    tips, iso = advice(car)
    assert (
        not iso["J_L1"] and tips[0].matrix == "J_L1" and tips[0].advised and tips[0].point == pytest.approx((1.35, 0))
    )
    assert tips[0].before["L"] == pytest.approx(L_old) and tips[0].before["kappa_JL1"] == pytest.approx(2.191, abs=5e-4)
    assert tips[0].after["L"] == pytest.approx(L_moved) and tips[0].after["kappa_JL1"] == pytest.approx(1.0)


@pytest.mark.parametrize("name", ["forklift", "swerve_offcentre"])
def test_moving_C_is_checked_for_the_forklift_and_the_swerve(name):
    bot = _load(name)
    tips, _ = advice(bot)
    tip = next(t for t in tips if t.matrix == "J_L1")
    moved = bot.moved(origin=bot.mount_points.mean(axis=0))
    L = wmr.characteristic_length(moved)
    assert tip.after["L"] == pytest.approx(L) and L != pytest.approx(wmr.characteristic_length(bot))
    assert float(wmr.condition_number(moved.J1(L=L))) == pytest.approx(1.0) == tip.after["kappa_JL1"]
    assert tip.suggestion is Suggestion.MOVE_C and tip.point == pytest.approx(bot.mount_points.mean(axis=0))


# ------------------------------------------------------------------------------- 4. sweeps
def test_default_swerve_sweep_is_over_drivable_configurations(capsys):
    swerve = ROOT / "examples" / "swerve4.toml"
    code, out, _ = _run(capsys, "sweep", swerve, "mobility", "--sample", "2e5", "--json")
    data = json.loads(out)
    assert code == 0 and data["min"] >= 1 and data["worst_is"] == "min" and data["worst"] == data["min"]
    assert data["covers"].startswith("drivable configurations") and data["count"] == 200000
    code, out, _ = _run(capsys, "sweep", swerve, "mobility", "--angles", "any", "--sample", "2e4", "--json")
    data = json.loads(out)
    assert data["counts"] == {"0": 20000} and data["covers"].startswith("all steering angles")


def test_drivable_kappa_is_not_the_torus_kappa():
    """kappa(J) over what the swerve can drive is far worse than over random angles (which it never drives)."""
    from wmr.analysis.sweep import Drivable, Sample

    bot = wmr.load(ROOT / "examples" / "swerve4.toml")
    drive = wmr.sweep(bot, "kappa_J", Drivable(200000, seed=2), quantiles=(0.5, 0.95))
    torus = wmr.sweep(bot, "kappa_J", Sample(200000, seed=2), quantiles=(0.5, 0.95))
    assert drive.quantiles[0.5] > 1.3 * torus.quantiles[0.5] and drive.quantiles[0.95] > 3 * torus.quantiles[0.95]
    beta = Drivable(1000, seed=2).bind(bot).configurations(4, 0, 1000)
    assert (wmr.mobility(bot, beta) >= 1).all()
    assert (wmr.mobility(bot, Sample(1000, seed=2).configurations(4, 0, 1000)) == 0).all()


def test_car_drivable_configurations_turn():
    from wmr.analysis.sweep import Drivable

    car = _load("car")
    beta = Drivable(2000, seed=1).bind(car).configurations(4, 0, 2000)
    assert (wmr.mobility(car, beta) >= 1).all()
    front = np.degrees(beta[:, 2:]) % 180
    assert np.mean(np.abs(front - 90) > 1) > 0.9  # not only straight ahead
    # the front wheels are coordinated (Ackermann): their axles meet on the rear axle line x = 0
    d = car.mount_points
    t = np.tan(beta[:, 2:])
    y_meet = d[2:, 1] + (0 - d[2:, 0]) * t  # axle lines at x = 0
    ok = np.abs(np.cos(beta[:, 2])) > 1e-6
    assert np.allclose(y_meet[ok, 0], y_meet[ok, 1], rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("name", ["swerve_offcentre", "agv_two_steer"])
def test_fused_drivable_kappa_equals_the_general_kernels(name):
    from wmr.analysis.sweep import Drivable
    from wmr.analysis.sweep.motions import kappa_J_of_twists

    bot = _load(name)
    L = wmr.characteristic_length(bot)
    src = Drivable(5000, seed=4).bind(bot)
    tw, cur = src.twists(0, 5000)
    tw[0] = [1.0, -bot.mount_points[0, 1], bot.mount_points[0, 0]]  # wheel 1 at the centre: still
    fused = kappa_J_of_twists(bot, tw, L)
    if fused is None:  # castors: no fused kernel
        assert not all(u.rolls_in_plane for u in bot.wheels)
        return
    want = wmr.condition_number(bot.J(wmr.steering_angles(bot, tw, cur), L=L))
    fin = np.isfinite(want)

    def close(got, ref):  # both within the SVD's own accuracy, ~eps kappa, or 1e-12
        return np.all(np.abs(got / ref - 1) <= 1e-12 + 64 * np.finfo(float).eps * ref)

    assert np.array_equal(np.isfinite(fused), fin) and close(fused[fin], want[fin])
    res = wmr.sweep(bot, "kappa_J", Drivable(5000, seed=4), keep=True)
    assert close(res.values, wmr.condition_number(bot.J(src.configurations(4, 0, 5000), L=L)))


# ------------------------------------------------------------------------------ 8. plain language
def test_analyze_explains_itself(capsys):
    code, out, _ = _run(capsys, "analyze", ENG / "car.toml", "--grid", "200", "--twists", "50")
    assert code == 0
    assert "What the rows mean" in out and "rank-F" in out and "nullity" in out and "J_L1" in out
    singular = out[out.index("singular") :]
    assert "means: the wheels all point the same way" in singular and "steer first" in singular


@pytest.mark.parametrize(
    "term, words",
    [
        ("rank-F", "no-slip equations"),
        ("nullity", "free motions"),
        ("J_L1", "mount points"),
        ("J2", "wheel rates"),
        ("through-P", "stands still"),
        ("kappa(J_L1)", "C is the centroid"),
    ],
)
def test_explain(capsys, term, words):
    code, out, _ = _run(capsys, "explain", term)
    assert code == 0 and words in out.replace("\n", " ")


def test_explain_unknown_term(capsys):
    code, _, err = _run(capsys, "explain", "thru-P")
    assert code == 2 and "did you mean 'through-P'" in err


def test_motor_conditioning_of_a_kiwi_drive():
    """M^T M = diag(3, 3/2, 3/2) / r^2: kappa^2 = 2."""
    kiwi = wmr.Robot(
        [
            wmr.SwedishWheel((0.2 * np.cos(a), 0.2 * np.sin(a)), r=0.05, angle=a, roller=np.pi / 2)
            for a in np.radians([90, 210, 330])
        ]
    )
    assert round(motor_conditioning(kiwi, np.zeros(3)) ** 2, 9) == 2.0


def test_profile_of_the_papers_offset_robot():
    p = profile(wmr.paper_robot("offset", L=0.3, r=0.05, d=0.05))
    assert (p["class"], p["actuated_mobility"]) == ("(3,0)", 3)
    assert [round(p[k], 12) for k in ("L", "kappa_JL1", "kappa_J2")] == [0.3, 1.0, 1.0]


def test_driven_columns_of_a_castor_and_a_mecanum_wheel():
    castor = wmr.OffsetWheel((0.3, 0.0), r=0.05, d=0.03, driven={"steer": False, "drive": False})
    mec = wmr.SwedishWheel((-0.3, 0.0), r=0.05, angle=0.0, roller=np.pi / 4)
    assert driven_columns(wmr.Robot([castor, mec])).tolist() == [False, False, True, False]  # phi, theta; theta, sigma


def test_motion_reads_a_heading_and_a_centre():
    from wmr.analysis.actuation import motion

    bot = wmr.paper_robot("centred")
    assert motion(bot, [0.0, 1.0, 1.0]).heading == 45.0
    assert motion(bot, [1.0, 0.0, -1.0]).centre == (1.0, 0.0)


def test_steering_limitations_name_the_unsteered_unit():
    from wmr.analysis.limitations import steering_limitations

    free = wmr.CentredWheel((0.3, 0.0), r=0.05, driven={"steer": False})
    assert steering_limitations(wmr.Robot([free, wmr.CentredWheel((-0.3, 0.0), r=0.05)]))[0].unit == 0
