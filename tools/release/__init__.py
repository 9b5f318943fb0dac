"""``make release``: the sdist and the wheel build, hold what they should, and the wheel installed into a fresh venv
outside the repository passes the library's tests.  :mod:`tools.release.check` is the entry point."""
