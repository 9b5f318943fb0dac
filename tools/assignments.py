r"""``make assignments``: nbgrader source notebooks from the chapters' exercise cells.

``python -m tools.assignments OUT NOTEBOOK...`` writes an nbgrader course directory ``OUT`` (the
Makefile: ``build/assignments``): ``OUT/nbgrader_config.py`` and, for each chapter that has exercises,
``OUT/source/<chapter>/<chapter>.ipynb``.  A chapter's exercise is four tagged cells in this order
(see :mod:`edition.exercises.framework`):

==============  ===============================================================================
tag             becomes
==============  ===============================================================================
``exercise``    a locked Markdown cell (the statement)
``answer``      a solution cell: the template's lines, then ``### BEGIN SOLUTION`` + the worked
                solution's lines + ``### END SOLUTION``; nbgrader's generate step replaces the region by
                ``# YOUR CODE HERE`` (``ClearSolutions.code_stub`` in the config), so the released
                notebook holds the template and runs
``solution``    merged into the answer cell above
``check``       an autograded test cell worth the exercise's points (:func:`edition.exercises.framework.by_name`):
                the visible check ``check_4_1(beta_4_1)`` shows the verdict (a blank answer: "no answer
                yet") and never raises, so Run All on a released notebook runs to the end; the hidden test
                ``check_4_1(beta_4_1).require()`` (between ``### BEGIN HIDDEN TESTS`` and
                ``### END HIDDEN TESTS``, which nbgrader removes from the released notebook and puts back
                when it autogrades) computes the verdict again and fails unless it passed
==============  ===============================================================================

``written``     (Markdown, after a check) where the student answers a "why" question in words; with the
                ``rubric`` cell after it (the model answer and how to mark it) it becomes one manually graded
                answer cell worth :data:`WRITTEN_POINTS`: the instructor's copy holds the rubric, the released
                notebook ``YOUR ANSWER HERE`` (nbgrader's ``text_stub``)
``rubric``      merged into the written cell above (dropped from the student edition)

Every other cell is kept as it is.  The files are written only when their bytes change, with
deterministic cell ids, so a second run leaves them untouched.
"""

from __future__ import annotations

import ast
import json
import sys
from pathlib import Path

import nbformat

ROLE_TAGS = ("exercise", "answer", "solution", "check", "written", "rubric")
#: points of a question answered in words (graded by hand against the rubric)
WRITTEN_POINTS = 1.0
CONFIG = """\
# written by `make assignments` (tools/assignments.py)
import os
import sys

# nbgrader runs `alembic` (its database migrations) as a command: find it beside the Python running nbgrader,
# whether or not that environment is activated
os.environ["PATH"] = os.pathsep.join([os.path.dirname(sys.executable), os.environ.get("PATH", "")])
c = get_config()  # noqa: F821
c.CourseDirectory.root = os.path.dirname(os.path.abspath(__file__))
c.ClearSolutions.code_stub = {"python": "# YOUR CODE HERE"}
c.ClearSolutions.text_stub = "YOUR ANSWER HERE"
c.Execute.timeout = 300
# feedback pages typeset their math offline: templates/feedback/mathjax.html.j2, found before nbconvert's own,
# inlines MathJax into nbgrader's feedback template (the formgrader's own pages are left as they are)
if os.path.isdir(os.path.join(c.CourseDirectory.root, "templates", "feedback")):
    import nbgrader

    c.HTMLExporter.extra_template_basedirs = [
        os.path.join(c.CourseDirectory.root, "templates"),
        os.path.join(os.path.dirname(nbgrader.__file__), "server_extensions", "formgrader", "templates"),
    ]
"""
#: beside nbgrader's own template ``feedback`` (same name, same base), a ``mathjax.html.j2`` that answers the template's
#: ``mathjax()`` call with MathJax inlined (:func:`tools.mathjax.inline_html`) instead of a CDN's URL
FEEDBACK_CONF = '{"base_template": "classic", "mimetypes": {"text/html": true}}\n'
FEEDBACK_MATHJAX = """\
{#- written by `make assignments` (tools/assignments.py): MathJax 3 inlined, nothing fetched -#}
{%- macro mathjax(url=None) -%}
@MATHJAX@
{%- endmacro %}
"""


class AssignmentError(ValueError):
    """A chapter whose exercise cells do not follow the convention (the message names the chapter and the cell)."""


def _tags(cell):
    return set(cell.get("metadata", {}).get("tags", []))


def _role(cell, where):
    roles = _tags(cell) & set(ROLE_TAGS)
    if len(roles) > 1:
        raise AssignmentError(f"{where}: a cell tagged {sorted(roles)}; an exercise cell has one of {ROLE_TAGS}")
    role = roles.pop() if roles else None
    want = "markdown" if role in ("exercise", "written", "rubric") else "code"
    if role and cell.cell_type != want and not (role == "exercise" and cell.cell_type == "code"):
        raise AssignmentError(f"{where}: a {cell.cell_type} cell tagged {role!r}, expected a {want} cell")
    return role


def check_call(source, where):
    """The check's name in a check cell: the cell must be one call ``name(arguments)`` or ``module.name(arguments)``.

    Parameters
    ----------
    source : str
    where : str
        The chapter and cell, for the message.

    Returns
    -------
    str
    """
    try:
        tree = ast.parse(source)
    except SyntaxError as e:
        raise AssignmentError(f"{where}: the check cell is not Python ({e.msg})") from None
    body = tree.body
    value = body[0].value if len(body) == 1 and isinstance(body[0], ast.Expr) else None
    call = value if isinstance(value, ast.Call) else None
    func = call.func if call is not None else None
    if call is not None and not all(isinstance(a, ast.Name) for a in [*call.args, *(k.value for k in call.keywords)]):
        func = None  # its arguments are the answers' names
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):  # module.check_4_1(...)
        return func.attr
    raise AssignmentError(f"{where}: a check cell must be one call such as `check_4_1(beta_4_1)`, got {source!r}")


def _meta(kind, grade_id, points=None):
    m = {
        "grade": kind in ("test", "written"),
        "grade_id": grade_id,
        "locked": kind not in ("solution", "written"),
        "schema_version": 3,
        "solution": kind in ("solution", "written"),
        "task": False,
    }
    if points is not None:
        m["points"] = points
    return {"nbgrader": m}


def assignment(nb, name, points_of):
    """The nbgrader source notebook of a chapter, or None when it has no exercise.

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The chapter (not modified).
    name : str
        The chapter's name, for messages and grade ids.
    points_of : callable
        Check name -> points.

    Returns
    -------
    nbformat.NotebookNode or None
        None for a chapter without cells tagged ``answer`` or ``check``.
    """
    if not any(_tags(c) & {"answer", "check"} for c in nb.cells):
        return None  # no gradable exercise (only "Your own robot" cells, or none)
    out, pending, n, last_check, written = [], None, 0, None, None
    for i, cell in enumerate(nb.cells):
        where = f"{name}, cell {i}"
        role = _role(cell, where)
        if role is None:
            out.append(nbformat.from_dict(json.loads(json.dumps(cell))))
            continue
        if role == "exercise":
            md = (
                nbformat.v4.new_markdown_cell(cell.source)
                if cell.cell_type == "markdown"
                else nbformat.v4.new_code_cell(cell.source)
            )
            if cell.cell_type == "markdown":
                md.metadata.update(_meta("text", f"{name}-statement-{i}"))
            out.append(md)
        elif role == "written":
            if last_check is None:
                raise AssignmentError(f"{where}: a written answer before any check: it follows an exercise's check")
            written = (i, last_check)
        elif role == "rubric":
            if written is None:
                raise AssignmentError(f"{where}: a rubric without a written answer cell before it")
            manual = nbformat.v4.new_markdown_cell(cell.source)  # the instructor's copy: the model answer, the rubric
            manual.metadata.update(_meta("written", f"{name}-{written[1]}-written", WRITTEN_POINTS))
            out.append(manual)
            written = None
        elif role == "answer":
            if pending is not None:
                raise AssignmentError(f"{where}: an answer cell before the check of the answer in cell {pending[0]}")
            pending = (i, cell.source.rstrip(), [])
        elif role == "solution":
            if pending is None:
                raise AssignmentError(f"{where}: a solution cell without an answer cell before it")
            pending[2].append(cell.source.rstrip())
        else:  # check
            if pending is None:
                raise AssignmentError(f"{where}: a check cell without an answer cell before it")
            if not pending[2]:
                raise AssignmentError(f"{where}: the answer in cell {pending[0]} has no solution cell")
            check = check_call(cell.source, where)
            n += 1
            src = "\n".join([pending[1], "### BEGIN SOLUTION", *pending[2], "### END SOLUTION"])
            sol = nbformat.v4.new_code_cell(src)
            sol.metadata.update(_meta("solution", f"{name}-{check}-answer"))
            call = cell.source.strip()
            test = nbformat.v4.new_code_cell(
                f"{call}\n### BEGIN HIDDEN TESTS\n{call}.require();\n### END HIDDEN TESTS"  # ';': no output to grade
            )
            test.metadata.update(_meta("test", f"{name}-{check}", float(points_of(check))))
            out += [sol, test]
            pending, last_check = None, check
    if pending is not None:
        raise AssignmentError(f"{name}: the answer in cell {pending[0]} has no check cell after it")
    if written is not None:
        raise AssignmentError(f"{name}: the written answer in cell {written[0]} has no rubric cell after it")
    if not n:
        return None
    new = nbformat.v4.new_notebook(metadata=json.loads(json.dumps(nb.metadata)))
    for k, c in enumerate(out):
        c["id"] = f"{name[:40]}-{k}".replace("_", "-")
        if c.cell_type == "code":
            c.outputs, c.execution_count = [], None
    new.cells = out
    return new


def _write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
        return True
    return False


def main(argv=None):
    """``python -m tools.assignments [--no-feedback] OUT NOTEBOOK...``.

    Writes the source notebooks, ``OUT/nbgrader_config.py`` and (unless ``--no-feedback``: the build's own
    round trips, which make no feedback page) ``OUT/templates/feedback/``: the feedback pages' math, offline.

    Returns
    -------
    int
        The exit status.
    """
    args = list(sys.argv[1:] if argv is None else argv)
    feedback = "--no-feedback" not in args
    args = [a for a in args if a != "--no-feedback"]
    if len(args) < 2:
        print("usage: python -m tools.assignments [--no-feedback] OUT NOTEBOOK...", file=sys.stderr)
        return 2
    from edition.exercises.framework import by_name

    def points_of(check):
        try:
            return by_name(check).points
        except KeyError as e:
            raise AssignmentError(
                f"{e.args[0]}: a check cell must call a check made with "
                "edition.exercises.framework.exercise (its points come from there)"
            ) from None

    out = Path(args[0])
    written, skipped = [], []
    try:
        for p in map(Path, args[1:]):
            nb = assignment(nbformat.read(p, as_version=4), p.stem, points_of)
            if nb is None:
                skipped.append(p.stem)
                continue
            nbformat.validate(nb)
            target = out / "source" / p.stem / p.name
            if _write(target, nbformat.writes(nb) + "\n"):
                written.append(target)
    except AssignmentError as e:
        print(f"[assignments] {e}", file=sys.stderr)
        return 1
    _write(out / "nbgrader_config.py", CONFIG)
    if feedback:
        from tools import mathjax

        feedback_dir = out / "templates" / "feedback"
        _write(feedback_dir / "conf.json", FEEDBACK_CONF)
        _write(
            feedback_dir / "mathjax.html.j2",
            FEEDBACK_MATHJAX.replace("@MATHJAX@", mathjax.inline_html(mathjax.DOLLAR_TEX)),
        )
    print(
        f"[assignments] {len(written)} source notebooks written in {out / 'source'}"
        + (f"; without answer/check cells: {', '.join(skipped)}" if skipped else "")
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
