"""tools/testcache.py: the key of a test run changes with every file git sees, and only with those."""

import os
import subprocess

import pytest

from tools import testcache


@pytest.fixture
def tree(tmp_path):
    def git(*args):
        subprocess.run(["git", "-C", str(tmp_path), *args], check=True, capture_output=True)

    git("init", "-q")
    (tmp_path / ".gitignore").write_text("build/\n", encoding="utf-8")
    (tmp_path / "a.py").write_text("x = 1\n", encoding="utf-8")
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_a.py").write_text("def test(): pass\n", encoding="utf-8")
    git("add", "-A")
    git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "one")
    return tmp_path


def test_the_key_follows_every_file_git_sees_and_nothing_else(tree):
    k = testcache.key([], tree)
    assert testcache.key([], tree) == k
    os.utime(tree / "a.py", (1, 1))  # a new mtime is not a change
    assert testcache.key([], tree) == k
    (tree / "build").mkdir()
    (tree / "build" / "out.txt").write_text("made by the build", encoding="utf-8")  # ignored by git
    assert testcache.key([], tree) == k
    assert testcache.key(["-k", "slow"], tree) != k  # other pytest arguments
    keys = {k}
    (tree / "a.py").write_text("x = 2\n", encoding="utf-8")  # an edit, not committed
    keys.add(testcache.key([], tree))
    (tree / "new.py").write_text("", encoding="utf-8")  # untracked, not ignored
    keys.add(testcache.key([], tree))
    (tree / "tests" / "test_a.py").unlink()  # a tracked file deleted
    keys.add(testcache.key([], tree))
    assert len(keys) == 4


def test_the_stamp_holds_one_key(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(testcache, "STAMP", tmp_path / "build" / "tests-edition.stamp")
    monkeypatch.setattr(testcache, "ROOT", tmp_path)
    assert testcache.main(["check", "abc"]) == 1  # no stamp
    assert testcache.main(["stamp", "abc"]) == 0
    assert testcache.main(["check", "abc"]) == 0
    assert "passed on exactly this tree" in capsys.readouterr().out
    assert testcache.main(["check", "abd"]) == 1
    testcache.STAMP.write_text("not json", encoding="utf-8")
    assert testcache.main(["check", "abc"]) == 1
    assert testcache.main(["check"]) == 2 and testcache.main(["frobnicate", "x"]) == 2


def test_outside_a_git_checkout_there_is_no_key(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(testcache, "ROOT", tmp_path)  # not a repository
    with pytest.raises(subprocess.CalledProcessError):
        testcache.key([], tmp_path)
    monkeypatch.setattr(testcache, "key", lambda args: testcache.subprocess.run(["false"], check=True))
    assert testcache.main(["key"]) == 0
    out, err = capsys.readouterr()
    assert out == "" and "not a git checkout" in err
