"""The build of the wmr edition: notebooks executed (cached, in parallel), the report assembled
and exported to one self-contained HTML file and one PDF.

Modules, one responsibility each:

- :mod:`~tools.build.paths` every path; :mod:`~tools.build.files` atomic writes, hashes, temporary
  directories; :mod:`~tools.build.stamps` what a step consumed and produced;
  :mod:`~tools.build.gitinfo` every git call; :mod:`~tools.build.procs` child processes, signals,
  the build lock; :mod:`~tools.build.log` messages and errors;
- :mod:`~tools.build.execute` (+ :mod:`~tools.build.worker`) notebooks and the ledger merge;
- :mod:`~tools.build.inputs` the data the report shows; :mod:`~tools.build.frontmatter`,
  :mod:`~tools.build.findings`, :mod:`~tools.build.closing`, :mod:`~tools.build.chapters` its parts;
  :mod:`~tools.build.assemble` the report notebook; :mod:`~tools.build.typeset` tables and figures;
- :mod:`~tools.build.markup` Markdown through pandoc; :mod:`~tools.build.html`,
  :mod:`~tools.build.pdf` the exports; :mod:`~tools.build.report` the report step;
- :mod:`~tools.build.guard` the clean-work-tree check of ``make test``; :mod:`~tools.build.cli`.

Only the standard library is imported up front (an up-to-date ``make report`` answers at once);
nbformat, nbclient and nbconvert are imported when a step needs them.
"""
from .execute import execute, publish
from .log import BuildError
from .paths import Tree
from .report import report

__all__ = ["Tree", "BuildError", "execute", "publish", "report"]
