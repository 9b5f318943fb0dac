"""The steps the Makefile runs: ``python -m tools.build COMMAND PATH... [--reads DIR]``.

- ``execute NOTEBOOK OUT [--reads DIR]``: one notebook, cached (:mod:`~tools.build.execute`);
- ``publish FIGURES EXECUTED...``: what the chapters wrote into ``figures/``, where its bytes differ;
- ``assemble REPORT COMMIT FIGURES FINDINGS CHAPTER...``: ``build/report.ipynb`` (:mod:`~tools.build.assemble`);
- ``html REPORT OUT`` and ``pdf REPORT OUT``: the exports (:mod:`~tools.build.html`, :mod:`~tools.build.pdf`).

Exit status 0; 1 with ``BUILD FAILED`` and the reason; 128 + N when stopped by signal N (from Make,
or from the kernel when Make was killed), raised as :class:`KeyboardInterrupt` so that every
``finally`` runs: nbclient stops its kernel, ``subprocess.run`` kills xelatex or pandoc, temporary
directories go. A step first removes what it replaces: a failure leaves no report that looks current."""

from __future__ import annotations

import argparse
import signal
import sys
import time
from pathlib import Path

from . import BuildError, atomic_write, say

__all__ = ["main"]


def _stop(signum, frame):
    raise KeyboardInterrupt(signum)


def _run(cmd: str, paths: list[Path], reads: list[Path]) -> None:
    from .execute import execute, publish

    if cmd == "execute":
        execute(paths[0], paths[1], tuple(reads))
    elif cmd == "publish":
        publish(paths[0], paths[1:])
    else:
        import nbformat

        from . import assemble, html, pdf

        out = paths[0] if cmd == "assemble" else paths[1]
        for p in [out.with_suffix(x) for x in (".ipynb", ".html", ".pdf")] if cmd == "assemble" else [out]:
            p.unlink(missing_ok=True)
        t0 = time.perf_counter()
        if cmd == "assemble":
            atomic_write(out, nbformat.writes(assemble.report_notebook(paths[1], paths[2], paths[3], paths[4:])))
        else:
            (html.export_html if cmd == "html" else pdf.export_pdf)(nbformat.read(paths[0], as_version=4), out)
        say(cmd, f"{out.name} ({out.stat().st_size / 1e6:.2f} MB)", t0)


def main(argv: list[str] | None = None) -> int:
    raw = argparse.RawDescriptionHelpFormatter
    ap = argparse.ArgumentParser(prog="python -m tools.build", description=__doc__, formatter_class=raw)
    ap.add_argument("command", choices=("execute", "publish", "assemble", "html", "pdf"))
    ap.add_argument("paths", type=Path, nargs="+")
    ap.add_argument("--reads", type=Path, action="append", default=[], help="a folder or file it reads (its key)")
    a = ap.parse_args(argv)
    sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]  # jsonschema's IRI grammar: 1 s, unused
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        if sig != signal.SIGHUP or signal.getsignal(sig) != signal.SIG_IGN:  # nohup stays nohup
            signal.signal(sig, _stop)
    try:
        _run(a.command, a.paths, a.reads)
        return 0
    except BuildError as e:
        print(f"\nBUILD FAILED\n{e}", file=sys.stderr, flush=True)
        return 1
    except KeyboardInterrupt as e:
        signum = e.args[0] if e.args and isinstance(e.args[0], int) else signal.SIGINT
        print(f"\n[build] {a.command} stopped by signal {signum}", file=sys.stderr, flush=True)
        return 128 + signum


if __name__ == "__main__":
    sys.exit(main())
