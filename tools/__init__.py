"""Tools of the project: the build (``python -m tools.build``, driven by the Makefile) and the benchmarks."""
