"""Robot files: wmr.load / wmr.dump, the examples, and one-line errors for every malformed case."""

from pathlib import Path

import numpy as np
import pytest

import wmr
from wmr.io import RobotFileError, dump, load, loads, wheel_keys

from conftest import WRITTEN

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

CENTRED = """name = "two"

[[wheel]]
type = "centred"
position = [0.3, 0.0]
radius = 0.05

[[wheel]]
type = "centred"
position = [-0.3, 0.0]
radius = 0.05
"""


def _same_matrices(a, b):
    beta = np.random.default_rng(3).uniform(-np.pi, np.pi, (20, a.w))
    assert a.w == b.w and a.qdot_names == b.qdot_names and [u.kind for u in a.wheels] == [u.kind for u in b.wheels]
    assert np.allclose(a.F(beta), b.F(beta), rtol=WRITTEN, atol=WRITTEN)
    assert np.allclose(a.J1(L=0.7), b.J1(L=0.7), rtol=WRITTEN, atol=WRITTEN)
    assert np.allclose(a.J2(beta), b.J2(beta), rtol=WRITTEN, atol=WRITTEN)


def _mixed():
    return wmr.Robot(
        [
            wmr.OffsetWheel((1.0, 0.2), r=0.2, d=0.1),
            wmr.CentredWheel((-0.5, 0.9), r=0.3),
            wmr.DualWheel((-0.4, -1.0), r=0.25, b=0.15),
            wmr.CentredWheel((0.6, -0.7), r=1e-3),
        ],
        name='mixed "quoted" \\ name\twith tab',
    )


# ------------------------------------------------------------------------------------ reading
def test_load_reads_the_schema(tmp_path):
    path = tmp_path / "two.toml"
    path.write_text(CENTRED)
    bot = load(path)
    assert bot.name == "two" and bot.w == 2 and [u.kind for u in bot.wheels] == ["centred", "centred"]
    assert bot.mount_points.tolist() == [[0.3, 0.0], [-0.3, 0.0]] and bot.wheels[0].r == 0.05
    path.write_text(CENTRED.replace('name = "two"\n', ""))
    assert load(str(path)).name == "two"  # the file's stem


def test_integers_are_numbers():
    bot = loads('[[wheel]]\ntype = "offset"\nposition = [1, 0]\nradius = 1\noffset = 0\n')
    assert bot.wheels[0].position == (1.0, 0.0) and bot.wheels[0].d == 0.0  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "robot",
    [
        wmr.paper_robot("centred", L=0.3, r=0.05),
        wmr.paper_robot("offset", L=2.0, r=0.3, d=0.1),
        wmr.paper_robot("dual", L=1.0, r=0.2, b=0.4),
        wmr.paper_robot("centred", exact=True),
        _mixed(),
    ],
    ids=["centred", "offset", "dual", "exact", "mixed"],
)
def test_round_trip(robot, tmp_path):
    path = tmp_path / "bot.toml"
    text = dump(robot, path)
    assert path.read_text() == text
    back = load(path)
    assert back.name == robot.name
    _same_matrices(robot.numeric(), back)
    assert dump(back) == text  # a fixed point


def test_round_trip_fixed_and_swedish(tmp_path):
    bot = wmr.Robot(
        [
            wmr.FixedWheel((0.0, 0.2), 0.08, np.pi / 2),
            wmr.FixedWheel((0.0, -0.2), 0.08, 0.3),
            wmr.SwedishWheel((0.4, 0.1), 0.05, 1.1, np.pi / 4),
            wmr.CentredWheel((-0.3, 0.0), r=0.04),
        ]
    )
    dump(bot, tmp_path / "b.toml")
    back = load(tmp_path / "b.toml")
    _same_matrices(bot, back)
    assert np.isclose(back.wheels[2].roller, np.pi / 4) and np.isclose(back.wheels[1].angle, 0.3)  # type: ignore[attr-defined]


def test_dump_rejects_what_is_not_a_robot():
    with pytest.raises(TypeError, match="robot"):
        dump("robot")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="path"):
        dump(wmr.paper_robot(), path=3)  # type: ignore[arg-type]


# ------------------------------------------------------------------------------ malformed files
BASE = """name = "bot"
[[wheel]]
type = "centred"
position = [0.3, 0.0]
radius = 0.05

[[wheel]]
type = "offset"
position = [-0.3, 0.1]
radius = 0.05
offset = 0.02
"""

MALFORMED = {
    # case: (text, line, key, words in the reason)
    "unknown type": (BASE.replace('"offset"', '"ofset"'), 8, "wheel[2].type", ["must be one of", "'offset'"]),
    "type not a string": (BASE.replace('"offset"', "3"), 8, "wheel[2].type", ["must be one of", "got 3"]),
    "missing type": (BASE.replace('type = "offset"\n', ""), 7, "wheel[2].type", ["missing"]),
    "missing radius": (BASE.replace("radius = 0.05\n\n", "\n"), 2, "wheel[1].radius", ["missing", "radius"]),
    "non-numeric position": (BASE.replace("[-0.3, 0.1]", '["a", 0.1]'), 9, "wheel[2].position", ["two numbers"]),
    "position of three": (BASE.replace("[-0.3, 0.1]", "[1, 2, 3]"), 9, "wheel[2].position", ["two numbers"]),
    "position a number": (BASE.replace("[-0.3, 0.1]", "0.3"), 9, "wheel[2].position", ["two numbers"]),
    "infinite position": (BASE.replace("[-0.3, 0.1]", "[inf, 0.1]"), 9, "wheel[2].position", ["finite"]),
    "radius a string": (BASE.replace("radius = 0.05\n\n", 'radius = "5 cm"\n\n'), 5, "wheel[1].radius", ["number"]),
    "radius a boolean": (
        BASE.replace("radius = 0.05\n\n", "radius = true\n\n"),
        5,
        "wheel[1].radius",
        ["number", "true"],
    ),
    "zero radius": (BASE.replace("radius = 0.05\n\n", "radius = 0\n\n"), 5, "wheel[1].radius", ["positive"]),
    "negative offset": (BASE.replace("offset = 0.02", "offset = -0.02"), 11, "wheel[2].offset", ["negative"]),
    "missing offset": (BASE.replace("offset = 0.02\n", ""), 7, "wheel[2].offset", ["missing"]),
    "duplicate mount point": (
        BASE.replace("[-0.3, 0.1]", "[0.3, 0]"),
        9,
        "wheel[2].position",
        ["same mount point", "wheel[1]"],
    ),
    "zero wheels": ('name = "nothing"\n', 1, "wheel", ["no wheels"]),
    "empty file": ("", 1, "wheel", ["no wheels"]),
    "unknown wheel key": (
        BASE.replace("offset = 0.02", "offset = 0.02\nradious = 3"),
        12,
        "wheel[2].radious",
        ["unknown key", "'radius'"],
    ),
    "unknown top-level key": (BASE.replace('name = "bot"', 'name = "bot"\nmass = 3'), 2, "mass", ["unknown key"]),
    "name not a string": (BASE.replace('name = "bot"', "name = 3"), 1, "name", ["string"]),
    "wheel not tables": ("wheel = 3\n", 1, "wheel", ["[[wheel]]"]),
    "wheel not a table": ("wheel = [1]\n", 1, "wheel[1]", ["table"]),
    "TOML syntax error": (BASE.replace('"offset"', "offset"), 8, "wheel[2].type", ["TOML syntax error", "column 8"]),
    "TOML duplicate key": (
        BASE.replace("radius = 0.05\n\n", "radius = 0.05\nradius = 0.06\n\n"),
        6,
        "wheel[1].radius",
        ["TOML syntax error", "given twice"],
    ),
    "TOML duplicate top-level key": (
        BASE.replace('name = "bot"', 'name = "bot"\nname = "b"'),
        2,
        "name",
        ["given twice"],
    ),
    "TOML unterminated": (BASE + "x = [1,\n", 12, "wheel[2].x", ["TOML syntax error", "end of the file"]),
    "roller on a centred wheel": (
        BASE.replace("radius = 0.05\n\n", "radius = 0.05\nroller_deg = 45\n\n"),
        6,
        "wheel[1].roller_deg",
        ["not a key of a centred wheel"],
    ),
    "offset on a dual wheel": (
        BASE.replace('"offset"', '"dual"').replace("offset = 0.02", "half_separation = 0.1\noffset = 0.1"),
        12,
        "wheel[2].offset",
        ["not a key of a dual wheel", "half_separation"],
    ),
    "zero half separation": (
        BASE.replace('"offset"', '"dual"').replace("offset = 0.02", "half_separation = 0"),
        11,
        "wheel[2].half_separation",
        ["positive"],
    ),
    "angle on an offset wheel": (
        BASE.replace("offset = 0.02", "offset = 0.02\nangle_deg = 3"),
        12,
        "wheel[2].angle_deg",
        ["not a key of an offset wheel"],
    ),
}


@pytest.mark.parametrize("case", MALFORMED, ids=list(MALFORMED))
def test_malformed_file_gives_one_line(case, tmp_path):
    text, line, key, words = MALFORMED[case]
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(RobotFileError) as info:
        load(path)
    msg = str(info.value)
    assert "\n" not in msg
    assert msg.startswith(f"{path}:{line}: {key}: "), msg
    for w in words:
        assert w in msg, (w, msg)
    assert isinstance(info.value, ValueError) and (info.value.line, info.value.key) == (line, key)


def test_missing_key_names_each_key_of_each_type():
    assert {"offset", "centred", "dual", "fixed", "swedish"} <= set(wheel_keys())
    for kind, keys in wheel_keys().items():
        for key in keys[1:]:
            lines = [f'type = "{kind}"'] + [f"{k} = " + ("[0.0, 0.0]" if k == "position" else "0.1") for k in keys[1:]]
            lines = [s for s in lines if not s.startswith(key + " ")]
            with pytest.raises(RobotFileError, match=rf"^f\.toml:1: wheel\[1\]\.{key}: missing"):
                loads("[[wheel]]\n" + "\n".join(lines) + "\n", "f.toml")


def test_not_utf8(tmp_path):
    path = tmp_path / "latin.toml"
    path.write_bytes(b'name = "caf\xe9"\n')
    with pytest.raises(RobotFileError, match=r":1: file: not UTF-8"):
        load(path)


def test_bad_arguments_are_type_errors(tmp_path):
    with pytest.raises(TypeError, match="path"):
        load(3)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="text"):
        loads(b"x")  # type: ignore[arg-type]
    with pytest.raises(FileNotFoundError):
        load(tmp_path / "nowhere.toml")


# ------------------------------------------------------------------------------------ examples
PAPER = {"paper_centred.toml": "centred", "paper_offset.toml": "offset", "paper_dual.toml": "dual"}


@pytest.mark.parametrize("name, kind", PAPER.items())
def test_paper_examples_are_paper_robot(name, kind):
    bot = load(EXAMPLES / name)
    _same_matrices(bot, wmr.paper_robot(kind))
    assert bot.name == f"paper-{kind}"


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_every_example_loads_and_round_trips(name, tmp_path):
    bot = load(EXAMPLES / name)
    _same_matrices(bot, loads(dump(bot)))


# ------------------------------------------------------------------------------ Campion classes
CLASSES = {
    "paper_offset.toml": "(3,0)",
    "omni3.toml": "(3,0)",
    "mecanum4.toml": "(3,0)",
    "differential.toml": "(2,0)",
    "steered_castors.toml": "(2,1)",
    "tricycle.toml": "(1,1)",
    "swerve4.toml": "(1,2)",
    "paper_centred.toml": "(1,2)",
    "paper_dual.toml": "(1,2)",
}


def test_the_examples_cover_the_five_classes():
    assert set(CLASSES) == {p.name for p in EXAMPLES.glob("*.toml")}
    assert set(CLASSES.values()) == {"(3,0)", "(2,0)", "(2,1)", "(1,1)", "(1,2)"}  # all five of Campion's


@pytest.mark.parametrize("name, label", CLASSES.items())
def test_example_class(name, label):
    c = wmr.campion_class(load(EXAMPLES / name))
    assert c.label == label and f"({c.delta_m},{c.delta_s})" == label


def test_toml_strings_and_the_text_of_a_value_in_messages():
    from wmr.io.wheel_tables import toml_string, toml_text

    assert toml_string('a "b"\n') == '"a \\"b\\"\\n"'
    assert toml_text([1, "a", True, 2.5, 3, 4]) == '[1, "a", true, 2.5, ...]'


def test_layouts_are_recognised_without_passive_castors():
    from wmr.io.layouts import differential
    from wmr.io.recognise import free_passive, recognise, rectangle_of

    assert free_passive(wmr.OffsetWheel((0, 0), r=0.03, d=0.03, driven={"steer": False, "drive": False}))
    assert not free_passive(wmr.OffsetWheel((0, 0), r=0.03, d=0.03))  # motors: part of the layout
    assert recognise(differential(0.4, 0.05), ["mecanum", "differential"]).numbers == {"track": 0.4}
    order, length, width, centre = rectangle_of([[-0.3, 0.2], [0.3, 0.2], [0.3, -0.2], [-0.3, -0.2]])
    assert (order, round(length, 12), round(width, 12), centre.tolist()) == ((1, 2, 0, 3), 0.6, 0.4, [0.0, 0.0])


def test_an_optional_package_is_imported_when_a_bridge_needs_it():
    from wmr.io.extras import require

    pytest.importorskip("yaml")
    assert require("ros", "reading ROS 2 parameters").__name__ == "yaml"


def test_a_kind_takes_the_keys_of_its_nearest_base_with_an_entry():
    from wmr.io.wheel_tables import file_keys

    assert [k.name for k in file_keys(wmr.SwedishWheel)] == ["position", "radius", "angle_deg", "roller_deg"]
    assert [k.name for k in file_keys(wmr.FixedWheel)] == ["position", "radius", "angle_deg"]  # UnsteeredUnit's
