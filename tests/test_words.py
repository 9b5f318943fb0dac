"""wmr.words: the sentences of the output, made from the analyses' records (the analyses' tests check the data).

The sentences here are those ``wmr analyze`` printed before the analyses returned records (issue 29)."""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.analysis.actuation import Motion, MotionKind
from wmr.analysis.advice import Advice, Suggestion, Verdict, advice
from wmr.analysis.limitations import Limitation, LimitationKind
from wmr.words import advice as advice_words
from wmr.words import limitations as words

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
ENG = EXAMPLES / "engineers"
UNCONTROLLED = (
    "the motors cannot move it {}: it moves that way with every motor stopped (its passive joints roll freely), so "
    "the motors can neither drive nor stop that motion (actuated mobility {} < delta_m = {})"
)


def test_where_a_twist_moves_the_robot():
    bot = wmr.paper_robot("centred")
    said = [words.describe_twist(bot, t) for t in ([0, 1, 1], [0, 0, -2], [0, 1, 0], [1, 0, 0], [1, 0, -1], [0, 0, 0])]
    assert said == [
        "diagonally (along 45 deg from x)",
        "sideways (along y)",
        "straight ahead (along x)",
        "on the spot (turning about C)",
        "in a turn about the point (1, 0) m",
        "nowhere (standing still)",
    ]


@pytest.mark.parametrize(
    "name, said",
    [
        ("engineers/skid_steer6", ["turning requires skidding: it can only drive straight ahead (along x)"]),
        (
            "engineers/diff_drive_castors",
            [
                "it cannot move sideways (along y): no motion may have a part of that (non-holonomic, like a differential drive)"
            ],
        ),
        ("engineers/mecanum_same_hand", [UNCONTROLLED.format("diagonally (along 45 deg from x)", 2, 3)]),
        (
            "steered_castors",
            [
                "at any one steering it cannot move in a turn about the point (-0.233, 0.326) m: that needs its steered "
                "wheel re-steered first",
                UNCONTROLLED.format("in a turn about the point (0.2, 0) m", 1, 2),
            ],
        ),
        (
            "engineers/car",
            [
                "it cannot move sideways or choose its centre of rotation freely: every motion turns about a point on "
                "the line of its fixed wheels' axles (or drives straight along their planes), and steering picks the "
                "point (car-like)"
            ],
        ),
        (
            "engineers/swerve_offcentre",
            [
                "at any one steering it has a single motion: to change the direction of motion it must re-steer its "
                "wheels first (it cannot change direction instantly)"
            ],
        ),
        ("engineers/kiwi", []),
    ],
)
def test_limitations_in_words(name, said):
    assert words.sentences(wmr.load(EXAMPLES / f"{name}.toml")) == said


def test_the_limitations_no_example_has():
    free = wmr.CentredWheel((0.3, 0.0), r=0.05, driven={"steer": False})
    bot = wmr.Robot([free, wmr.CentredWheel((-0.3, 0.0), r=0.05)])
    assert words.sentences(bot)[-1] == (
        "wheel 1: its steering joint is passive and nothing turns it (no motor, no offset to trail behind): its angle "
        "is not under control"
    )
    turn = Motion(MotionKind.TURN, (1.0, 0.0, 2.0), centre=(-2.0, 0.0))
    assert words.sentence(Limitation(LimitationKind.NO_STRAIGHT, (turn,))) == (
        "driving straight requires skidding: it can only move in a turn about the point (-2, 0) m"
    )
    assert words.sentence(Limitation(LimitationKind.NO_MOTION)) == (
        "it cannot move at all without skidding: its wheels' constraints admit no motion"
    )
    for kind in LimitationKind:  # every kind has its words
        assert words.sentence(Limitation(kind, (turn,), 0, 1, 2))


def test_advice_in_words():
    same, x, agv = (wmr.load(ENG / f"{n}.toml") for n in ("mecanum_same_hand", "mecanum_x", "agv_two_steer"))
    omni = (
        "J2: use omni wheels (rollers at 90 deg) on wheel 1, 2, 3, 4: a Swedish wheel's block r[[0, sin g], [-1, -cos "
        "g]] has singular values r sqrt(1 +- cos g): then kappa(J2) = 1 (now 2.414); not advised: class (3,0) (now "
        "(3,0)), actuated mobility 2 (now {}) -- "
    )
    assert [advice_words.sentence(a) for a in advice(same)[0]] == [
        "actuation: build wheel 2 of the other hand (rollers at -45 deg); wheel 3 of the other hand (rollers at -45 "
        "deg): then actuated mobility 3 (now 2), the motors' map to the twist has condition number 1.406, kappa(J2) = "
        "2.414",
        omni.format(2) + UNCONTROLLED.format("sideways (along y)", 2, 3),
    ]
    assert [advice_words.sentence(a) for a in advice(x)[0]] == [
        omni.format(3) + UNCONTROLLED.format("sideways (along y)", 2, 3)
    ]
    assert [advice_words.sentence(a) for a in advice(agv)[0]][1:] == [
        "J2: give every wheel the radius 0.1 (now 0.05, 0.1): then kappa(J2) = 2.5 (now 2.5): no gain by itself",
        "J2: both changes together: then kappa(J2) = 1 (now 2.5)",
    ]


def test_advice_on_J_L1_and_a_singular_J2_in_words():
    (car,) = advice(wmr.load(ENG / "car.toml"))[0]
    assert advice_words.sentence(car) == (
        "J_L1: move C to the centroid of the mount points, (1.35, 0) in this frame (subtract it from every position); "
        "then L = 1.557 gives kappa(J_L1) = 1 (now 2.191 at L = 2.06)"
    )
    (dual,) = advice(wmr.paper_robot("dual"))[0]
    assert advice_words.sentence(dual) == (
        "J2: singular at every configuration (dual units: wheel 1, 2, 3 drive their mount point through one direction "
        "only); no choice of lengths makes it isotropic"
    )
    equal = Advice("J2", Suggestion.EQUAL_VALUES, Verdict.ADVISED, {"kappa_J2": np.inf}, {}, singular_values=((2, 1),))
    assert advice_words.sentence(equal) == (
        "J2: kappa(J2) = inf: make the singular values of every unit's block equal (wheel 1: 2, 1)"
    )


def test_the_moved_words_warn_and_answer_as_their_replacements():
    """wmr.deprecated: the words that left the records warn, naming their replacement."""
    from wmr.analysis import actuation
    from wmr.analysis.unit_design import isotropic_change

    bot = wmr.paper_robot("offset", r=0.1, d=0.03)
    (tip,) = advice(bot)[0]
    with pytest.warns(DeprecationWarning, match=r"Advice.text is deprecated: use wmr.words.advice.sentence\(advice\)"):
        assert tip.text == advice_words.sentence(tip)  # type: ignore[attr-defined]
    change = isotropic_change(bot.wheels[0])
    with pytest.warns(DeprecationWarning, match=r"Change.words is deprecated: use wmr.words.advice.change\(change\)"):
        assert change.words == advice_words.change(change)  # type: ignore[union-attr, arg-type]
    with pytest.warns(
        DeprecationWarning, match="describe_twist is deprecated: use wmr.words.limitations.describe_twist"
    ):
        assert actuation.describe_twist(bot, [0, 1, 0]) == "straight ahead (along x)"  # type: ignore[attr-defined]
