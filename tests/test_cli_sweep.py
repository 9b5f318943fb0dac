"""``wmr sweep``: the table, the JSON, the progress bar, Dask and one-line errors."""

import json

import numpy as np
import pytest

import wmr
from wmr.analysis.sweep import Grid, Sample
from wmr.cli import main

from conftest import WRITTEN


@pytest.fixture
def robot_file(tmp_path, monkeypatch):
    """A robot file name that wmr.load resolves to the paper's centred robot (the loader is tested elsewhere)."""
    path = tmp_path / "centred.toml"
    path.write_text("# read by the stand-in loader\n")
    bot = wmr.paper_robot("centred", L=0.3, r=0.05)

    def load(p):
        if str(p) != str(path):
            raise OSError(f"{p}: no such file")
        return bot

    monkeypatch.setattr(wmr, "load", load, raising=False)
    return str(path), bot


def test_table_and_json_match_the_library(robot_file, capsys):
    path, bot = robot_file
    assert main(["sweep", path, "mobility", "--grid", "12", "--no-progress"]) == 0
    table = capsys.readouterr().out
    res = wmr.sweep(bot, "mobility", Grid((12, 12, 12)))
    assert table.strip() == res.summary()
    assert (
        main(
            [
                "sweep",
                path,
                "kappa_J",
                "--angles",
                "any",
                "--sample",
                "2e4",
                "--seed",
                "5",
                "--json",
                "--quantiles",
                "0.5,1",
            ]
        )
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    res = wmr.sweep(bot, "kappa_J", Sample(20000, seed=5), quantiles=[0.5, 1.0])
    assert out["count"] == 20000 and out["quantiles"]["0.5"] == pytest.approx(res.quantiles[0.5], rel=WRITTEN)
    assert out["max"] == ("inf" if np.isinf(res.max) else pytest.approx(res.max, rel=WRITTEN))
    assert np.allclose(out["worst_deg"], np.degrees(res.worst_angles))


def test_range_in_degrees(robot_file, capsys):
    path, bot = robot_file
    assert main(["sweep", path, "det_J", "--grid", "4,5,6", "--range", "0", "90", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    res = wmr.sweep(bot, "det_J", Grid((4, 5, 6), lo=0.0, hi=np.pi / 2))
    assert (
        out["count"] == 120
        and out["min"] == pytest.approx(res.min, abs=WRITTEN)  # det J: dimensionless, at the scale 1
        and np.allclose(out["argmin_deg"], np.degrees(res.argmin))
    )


def test_progress_bar_on_stderr(robot_file, capsys):
    path, _ = robot_file
    assert main(["sweep", path, "rank_F", "--sample", "300000", "--chunk", "65536", "--progress"]) == 0
    err = capsys.readouterr().err
    assert "100%" in err and err.count("[") >= 2 and err.endswith("\n")


def test_dask_local_cluster(robot_file, capsys):
    pytest.importorskip("dask.distributed")
    path, bot = robot_file
    assert main(["sweep", path, "rank_F", "--grid", "10", "--chunk", "100", "--dask", "local:2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["counts"] == {str(k): v for k, v in wmr.sweep(bot, "rank_F", Grid(10)).counts.items()}


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--sample", "0"], "--sample"),
        (["--sample", "many"], "--sample"),
        (["--grid", "3,3"], "steps"),
        (["--quantiles", "0.5,x"], "--quantiles"),
        (["--quantiles", "2"], "quantiles"),
        (["--range", "10", "10"], "hi"),
        (["--length", "-1"], "L"),
    ],
)
def test_bad_input_is_one_line(robot_file, capsys, argv, words):
    path, _ = robot_file
    assert main(["sweep", path, "kappa_J", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("wmr sweep: ") and words in err and err.count("\n") == 1


def test_missing_file(robot_file, capsys):
    assert main(["sweep", "nowhere.toml", "rank_F"]) == 2
    assert "nowhere.toml" in capsys.readouterr().err
