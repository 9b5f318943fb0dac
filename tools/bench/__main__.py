"""``python -m tools.bench [PART ...]``: the parts of :data:`tools.bench.PARTS` (all by default), one after another."""

from __future__ import annotations

import importlib
import sys

from tools.bench import PARTS


def main(argv: list[str] | None = None) -> int:
    """Run the parts named in ``argv`` (default: all) with their default options.

    Parameters
    ----------
    argv : list of str, optional
        Names from :data:`tools.bench.PARTS`.

    Returns
    -------
    int
        0 when every part met its goals, else 1.
    """
    names = list(sys.argv[1:] if argv is None else argv) or list(PARTS)
    unknown = [n for n in names if n not in PARTS]
    if unknown:
        print(f"unknown part(s) {', '.join(unknown)}: choose from {', '.join(PARTS)}", file=sys.stderr)
        return 2
    failed = []
    for name in names:
        print(f"\n## {name} (python -m tools.bench.{name})\n", flush=True)
        if importlib.import_module(f"tools.bench.{name}").main([]):
            failed.append(name)
    print(f"\nparts that missed a goal or disagreed: {', '.join(failed) or 'none'}")
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
