"""The project's one benchmark: ``make bench`` (``python -m tools.bench``), reported in ``tools/BENCH.md``.

Each part is a module with a ``main(argv)`` that prints its table and returns 0, or 1 when a goal is missed
or a result disagrees with its reference; ``python -m tools.bench`` runs the parts in this order and
``python -m tools.bench.PART [ARGS]`` runs one with its own options (``--help``).

==============  ==========================================================================================
part            what it times
==============  ==========================================================================================
``batched``     the batched kernels against targets, plain-NumPy floors and WPILib, and the sweeps
                (:mod:`~tools.bench.floors` builds the kernel rows, :mod:`~tools.bench.sweeps` the sweep rows)
``fastpaths``   each fast path of wmr against the plain implementation it replaces (kept at 3x or more)
``analyze``     ``wmr analyze`` against the number of wheel units, 4 to 1,000
``physics``     chapter 9's MuJoCo experiments over their boxes and its Drake runs
``autograde``   nbgrader's autograding of one full submission, per chapter
==============  ==========================================================================================

Run by hand, because they compare two versions or rebuild the report: :mod:`~tools.bench.design`
(``wmr design`` and ``wmr sweep`` of two commands), ``tools/bench/report.sh`` (the report build, cold and
warm) and ``tools/bench/tests.sh`` (a warm ``make test``).  Timings on a shared machine are only as quiet
as it was: every part prints the load average.
"""

#: the parts ``python -m tools.bench`` runs, in order
PARTS = ("batched", "fastpaths", "analyze", "physics", "autograde")
