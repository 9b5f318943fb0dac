r"""Where the report's PDF may not break a page: a displayed formula stays with what leads into it.

A rule of the edition's text, applied by the build (:mod:`tools.build.pdf`) to the LaTeX it converts.
"""

from __future__ import annotations

import itertools
import re

__all__ = ["keep_displays_with_lead_in"]

_STARTS_DISPLAY = re.compile(r"(?<=\S)[ \t]*\n(?:[ \t]*\n)+(?=(?:\{\\postdisplaypenalty=10000 )?\\wmrdisplay\{)")
_DISPLAY_LINE = re.compile(r"^\\wmrdisplay\{.*\}$", re.MULTILINE)
_LIST_END = re.compile(r"\\end\{(quote|quotation|itemize|enumerate|description)\}(?=\\par\\nopagebreak\n)")


def keep_displays_with_lead_in(tex: str) -> str:
    r"""No page break just before a displayed formula: it stays with what leads into it.

    A display that starts its own paragraph (a blank line before ``\wmrdisplay``) gets ``\par\nopagebreak``
    after the paragraph before it: the penalty forbids a break there, and the glue after it is no breakpoint
    because a penalty, not a box, precedes it.  When what precedes is itself a display, TeX could still break
    at that display's ``\postdisplaypenalty``; it is set to 10000 for that display alone.  So neither "As
    printed:" nor a formula ends a page whose next formula opens the following one.  A list (a quote of the
    paper, an itemize) ends with its own breakpoint, a penalty before the space below it; ``\wmrkeepwithnext``
    just before its ``\end`` makes that penalty forbid the break too.

    >>> keep_displays_with_lead_in("As printed:\n\n\\wmrdisplay{x}{6}")
    'As printed:\\par\\nopagebreak\n\n\\wmrdisplay{x}{6}'
    >>> print(keep_displays_with_lead_in("As printed:\n\n\\wmrdisplay{x}{6}\n\n\\wmrdisplay{y}{}"))
    As printed:\par\nopagebreak
    <BLANKLINE>
    {\postdisplaypenalty=10000 \wmrdisplay{x}{6}}\par\nopagebreak
    <BLANKLINE>
    \wmrdisplay{y}{}
    >>> keep_displays_with_lead_in("\\end{quote}\n\n\\wmrdisplay{x}{}")
    '\\wmrkeepwithnext\\end{quote}\\par\\nopagebreak\n\n\\wmrdisplay{x}{}'
    """
    lines = tex.split("\n")
    for k, line in enumerate(lines):
        if not _DISPLAY_LINE.match(line):
            continue
        rest = next((x for x in itertools.islice(lines, k + 1, None) if x.strip()), "")
        if rest.startswith("\\wmrdisplay{"):
            lines[k] = "{\\postdisplaypenalty=10000 " + line + "}"
    kept = _STARTS_DISPLAY.sub(lambda m: r"\par\nopagebreak" + "\n\n", "\n".join(lines))
    return _LIST_END.sub(lambda m: r"\wmrkeepwithnext" + m.group(0), kept)
