"""Sphinx extension: pages of the user guide made from sections of the repository's Markdown files,
with their examples executed while the docs build.

``.. markdown:: README.md`` with ``:section: Swerve practice`` inserts that ``##`` section of the
README (without its heading: the page has its own title), converted to reStructuredText by pandoc
(without ``:section:``, the whole file less its ``#`` title; with ``:code: yaml``, the file as code).
Its fenced code blocks are not converted but handled here:

* ``python``: shown, then run (one namespace per page, the working directory the repository's root,
  so ``examples/...`` resolves); what it prints is shown below it. A ``print(...)`` line whose
  comment states a value (``print("class:", c.label)   # (1,2)``) is a claim: some printed line must
  hold the comment's words, in order.
* ``console``: each ``$ wmr ...`` line is run (``wmr.cli.main`` in process) and its output must be
  the text the Markdown shows under it, line for line.
* ``toml``: shown; a robot file (one with ``[[wheel]]``) must load with :func:`wmr.load`.
* anything else: shown.

Every failed claim is a Sphinx warning, which ``-W`` turns into a failed build. The README stays
the one source of the text; the docs prove its examples.
"""

from __future__ import annotations

import contextlib
import difflib
import io
import re
import shlex
import shutil
import subprocess
import tempfile
import textwrap
from pathlib import Path
from typing import Any, ClassVar

from docutils.parsers.rst import directives
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

FENCE = re.compile(r"^```([\w+-]*)[^\n]*\n(.*?)^```[ \t]*$", re.MULTILINE | re.DOTALL)
CLAIM = re.compile(r"^\s*print\(.*\)\s*#\s*(?P<value>\S.*?)\s*$")
PLACEHOLDER = "WMRCODEBLOCK{:04d}"


def section(markdown: str, title: str) -> str:
    """The body of the ``##`` section called ``title`` (up to the next ``##`` or ``#`` heading).

    Examples
    --------
    >>> section("# T\\n## A\\nabc\\n## B\\ndef\\n", "A")
    'abc\\n'
    """
    lines = markdown.splitlines(keepends=True)
    start = None
    for i, line in enumerate(lines):
        if start is None and line.rstrip("\n") == f"## {title}":
            start = i + 1
        elif start is not None and re.match(r"#{1,2} ", line) and not _in_fence(lines[:i]):
            return "".join(lines[start:i])
    if start is None:
        raise KeyError(title)
    return "".join(lines[start:])


def _in_fence(lines: list[str]) -> bool:
    return sum(1 for ln in lines if ln.startswith("```")) % 2 == 1


def claims(code: str) -> list[str]:
    """The values that ``print(...)  # value`` lines of ``code`` state.

    Examples
    --------
    >>> claims('x = 1  # one\\nprint("x:", x)   # 1\\nprint(x)\\n')
    ['1']
    """
    return [m.group("value") for m in map(CLAIM.match, code.splitlines()) if m]


def unmet_claims(code: str, output: str) -> list[str]:
    """The claims of ``code`` that no printed line bears out: a line holds the claim's words, in order.

    Examples
    --------
    >>> unmet_claims('print(a, "|", b)  # 1 | 0\\nprint(c)  # (1,2)\\n', "mobility: 1 | generic: 0\\nclass: (1,2)\\n")
    []
    >>> unmet_claims('print(a, "|", b)  # 1 | 0\\n', "mobility: 0 | generic: 1\\n")
    ['1 | 0']
    """
    printed = [ln.split() for ln in output.splitlines()]
    return [c for c in claims(code) if not any(_in_order(c.split(), words) for words in printed)]


def _in_order(want: list[str], words: list[str]) -> bool:
    it = iter(words)
    return all(any(w == x for x in it) for w in want)


def console_runs(block: str) -> list[tuple[str, str]]:
    """(command, shown output) pairs of a console block: each ``$ `` line and the lines under it.

    Examples
    --------
    >>> console_runs("$ wmr a x\\nline 1\\nline 2\\n$ wmr b\\n")
    [('wmr a x', 'line 1\\nline 2\\n'), ('wmr b', '')]
    """
    runs: list[tuple[str, list[str]]] = []
    for line in block.splitlines():
        if line.startswith("$ "):
            runs.append((line[2:].strip(), []))
        elif runs:
            runs[-1][1].append(line)
    return [(cmd, "".join(ln + "\n" for ln in out)) for cmd, out in runs]


def _literal(text: str, language: str = "text") -> list[str]:
    body = textwrap.indent(text.rstrip("\n") or " ", "   ")
    return [f".. code-block:: {language}", "", *body.splitlines(), ""]


class MarkdownSection(SphinxDirective):
    """``.. markdown:: FILE`` (relative to the repository): the file, or with ``:section: TITLE`` one
    ``##`` section of it; with ``:code: LANGUAGE`` the file shown as code."""

    required_arguments = 1
    option_spec: ClassVar[dict[str, Any]] = {
        "section": directives.unchanged_required,
        "code": directives.unchanged_required,
    }

    def run(self) -> list[Any]:
        root = Path(self.config.wmr_repository)
        path = root / self.arguments[0]
        self.env.note_dependency(str(path))
        text = path.read_text(encoding="utf-8")
        if "code" in self.options:  # the whole file, as code
            self.state_machine.insert_input(_literal(text, self.options["code"]), str(path))
            return []
        title = self.options.get("section")
        if title:
            try:
                text = section(text, title)
            except KeyError:
                raise self.error(f"{self.arguments[0]} has no section '## {title}'") from None
        else:  # the page has its own title
            text = re.sub(r"\A# [^\n]*\n", "", text)
        where = f"{self.arguments[0]}" + (f", section '{title}'" if title else "")
        blocks: list[tuple[str, str]] = []

        def hold(m: re.Match[str]) -> str:
            blocks.append((m.group(1), m.group(2)))
            return "\n" + PLACEHOLDER.format(len(blocks) - 1) + "\n"

        rst = _pandoc(FENCE.sub(hold, text))
        if "wmr_markdown_namespace" not in self.env.temp_data:  # one namespace per page
            self.env.temp_data["wmr_markdown_namespace"] = {"__name__": "__docs__"}
        namespace: dict[str, Any] = self.env.temp_data["wmr_markdown_namespace"]
        out: list[str] = []
        for line in rst.splitlines():
            m = re.fullmatch(r"WMRCODEBLOCK(\d{4})", line.strip())
            if not m:
                out.append(line)
                continue
            lang, code = blocks[int(m.group(1))]
            out += self._block(lang, code, root, namespace, where)
        self.state_machine.insert_input(out, str(path))
        return []

    def _block(self, lang: str, code: str, root: Path, ns: dict[str, Any], where: str) -> list[str]:
        if lang == "python":
            buf = io.StringIO()
            try:
                with contextlib.chdir(root), contextlib.redirect_stdout(buf):
                    exec(compile(code, f"<{where}>", "exec"), ns)  # the README's own example
            except Exception as exc:  # reported: fails -W
                logger.warning(
                    f"{where}: the Python example raised {type(exc).__name__}: {exc}", location=self.get_location()
                )
            for value in unmet_claims(code, buf.getvalue()):
                logger.warning(
                    f"{where}: the example's comment says it prints {value!r}; it printed:\n{buf.getvalue()}",
                    location=self.get_location(),
                )
            shown = _literal(code, "python")
            if buf.getvalue():
                shown += ["Output:", "", *_literal(buf.getvalue())]
            return shown
        if lang == "console":
            for cmd, shown_out in console_runs(code):
                got = _run_wmr(cmd, root)
                if got is not None and got.rstrip() != shown_out.rstrip():
                    diff = "\n".join(
                        difflib.unified_diff(
                            shown_out.rstrip().splitlines(),
                            got.rstrip().splitlines(),
                            "as shown",
                            "as run",
                            lineterm="",
                        )
                    )
                    logger.warning(
                        f"{where}: `{cmd}` prints something else than shown:\n{diff}", location=self.get_location()
                    )
            return _literal(code, "console")
        if lang == "toml" and "[[wheel]]" in code:
            import wmr

            with tempfile.TemporaryDirectory() as tmp:
                robot = Path(tmp) / "robot.toml"
                robot.write_text(code, encoding="utf-8")
                try:
                    wmr.load(robot)
                except (ValueError, TypeError) as exc:
                    logger.warning(f"{where}: the robot file does not load: {exc}", location=self.get_location())
        return _literal(code, lang or "text")


def _run_wmr(cmd: str, root: Path) -> str | None:
    """The output of a ``wmr ...`` command line (run in process), or None for other commands."""
    argv = shlex.split(cmd)
    if not argv or argv[0] != "wmr":
        return None
    from wmr.cli import main

    buf = io.StringIO()
    with contextlib.chdir(root), contextlib.redirect_stdout(buf):
        try:
            code = main(argv[1:])
        except SystemExit as exc:  # --version, --help
            code = exc.code if isinstance(exc.code, int) else 1
    if code != 0:
        logger.warning(f"`{cmd}` exited with status {code}")
    return buf.getvalue()


def _pandoc(markdown: str) -> str:
    pandoc = shutil.which("pandoc")
    if pandoc is None:
        raise RuntimeError(
            "pandoc not found: the user guide converts the README's Markdown with pandoc "
            "(make tex installs it; Debian: apt-get install pandoc)"
        )
    proc = subprocess.run(
        [pandoc, "--from", "gfm", "--to", "rst", "--wrap", "preserve"],
        input=markdown,
        capture_output=True,
        text=True,
        check=True,
    )
    return proc.stdout


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_config_value("wmr_repository", "", "env")
    app.add_directive("markdown", MarkdownSection)
    return {"version": "1", "parallel_read_safe": False, "parallel_write_safe": True}
