#!/usr/bin/env python3
"""Build tool for the wmr reproduction.

    python tools/build.py execute   # execute changed notebooks (2 in parallel), merge the ledger
    python tools/build.py figures   # regenerate figures/ when wmr/*.py changed (--force: always)
    python tools/build.py report    # execute + figures if stale, then build/report.{html,pdf}

Caching is by content hash (sha256), never by timestamps:
  build/notebooks/NAME.stamp  notebook + every wmr/*.py  -> skip re-execution
  build/figures.stamp         every wmr/*.py             -> skip `python -m wmr.paper.figures`
  build/report.stamp          notebooks, wmr, tools, figures, git HEAD -> skip the whole report

Options (before the subcommand): --root DIR (a tree with notebooks/, wmr/, figures/;
default: this repository), --build DIR (default ROOT/build). The environment variables
WMR_ROOT / WMR_BUILD do the same. Only the standard library is imported at start-up so
that an up-to-date `report` returns in well under a second; nbformat/nbclient/nbconvert
are imported when needed.
"""
from __future__ import annotations

import argparse
import base64
import csv
import datetime as _dt
import hashlib
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

TOOLS = Path(__file__).resolve().parent
REPO = TOOLS.parent
TEMPLATES = TOOLS / "templates"
CELL_TIMEOUT = 600  # seconds per notebook cell
WORKERS = 2

PAPER = ("Y. P. Leow, K. H. Low and W. K. Loh, \u201cKinematic modeling, mobility analysis "
         "and design of wheeled mobile robots\u201d, Advanced Robotics 16(2), 2002.")
TITLE = "Kinematic modeling, mobility analysis and design of wheeled mobile robots"
SUBTITLE = "An executable reproduction of Leow, Low & Loh (Advanced Robotics, 2002)"

_print_lock = threading.Lock()


class BuildError(RuntimeError):
    """A build step failed; the message says which and why."""


def say(step: str, msg: str, t0: float | None = None) -> None:
    el = f" ({time.perf_counter() - t0:.1f} s)" if t0 is not None else ""
    with _print_lock:
        print(f"[{step}] {msg}{el}", flush=True)


# ----------------------------------------------------------------------------- paths
class Tree:
    def __init__(self, root: Path | str | None = None, build: Path | str | None = None,
                 notebooks: Path | str | None = None):
        self.root = Path(root or os.environ.get("WMR_ROOT") or REPO).resolve()
        self.build = Path(build or os.environ.get("WMR_BUILD") or self.root / "build").resolve()
        self.notebooks = Path(notebooks or self.root / "notebooks").resolve()
        self.wmr = self.root / "wmr"
        self.figures = self.root / "figures"
        self.nb_out = self.build / "notebooks"

    def notebook_files(self) -> list[Path]:
        return sorted(p for p in self.notebooks.glob("*.ipynb") if not p.name.startswith("."))

    def wmr_files(self) -> list[Path]:
        if not self.wmr.is_dir():
            return []
        return sorted(p for p in self.wmr.rglob("*.py") if "__pycache__" not in p.parts)

    def env(self) -> dict:
        """Environment for notebook kernels and `python -m wmr.*`: the running (venv) Python
        first on PATH, ROOT first on PYTHONPATH."""
        env = dict(os.environ)
        env["PATH"] = str(Path(sys.executable).parent) + os.pathsep + env.get("PATH", "")
        env["PYTHONPATH"] = str(self.root) + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
        env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"
        # notebooks and the figure script run side by side on few cores: one BLAS thread each
        # (no oversubscription; also makes floating-point reductions run in a fixed order)
        for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            env.setdefault(var, "1")
        env["PYTHONHASHSEED"] = "0"
        # the venv's own "python3" kernelspec before any user-level one that may name another Python
        env["JUPYTER_PREFER_ENV_PATH"] = "1"
        return env


def _hash_files(files, base: Path, h=None):
    h = h or hashlib.sha256()
    for p in files:
        try:
            rel = p.relative_to(base).as_posix()
        except ValueError:
            rel = p.as_posix()
        h.update(rel.encode() + b"\0")
        h.update(p.read_bytes())
        h.update(b"\0")
    return h


def wmr_hash(t: Tree) -> str:
    return _hash_files(t.wmr_files(), t.root).hexdigest()


def _read(p: Path) -> str | None:
    try:
        return p.read_text().strip()
    except OSError:
        return None


def _umask_mode() -> int:
    """The mode an ordinary new file gets (0o666 less the umask): mkstemp's 0o600 is too private."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def _write_atomic(path: Path, data: bytes | str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix="." + path.name, suffix=".tmp")
    with os.fdopen(fd, "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)
    os.chmod(tmp, _umask_mode())
    os.replace(tmp, path)


_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


def strip_ansi(s: str) -> str:
    return _ANSI.sub("", s)


# ----------------------------------------------------------------------------- execute
def _run_one(nb_path: str, out_path: str, cwd: str) -> int:
    """Child process: execute one notebook with nbclient, write it atomically."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    nb = nbformat.read(nb_path, as_version=4)
    client = NotebookClient(nb, timeout=CELL_TIMEOUT, kernel_name="python3",
                            resources={"metadata": {"path": cwd}})
    try:
        client.execute(cwd=cwd)
    except CellExecutionError as e:  # message = failing cell's source + traceback
        sys.stderr.write(strip_ansi(str(e)) + "\n")
        return 3
    out = Path(out_path)
    fd, tmp = tempfile.mkstemp(dir=out.parent, prefix="." + out.name, suffix=".tmp")
    os.close(fd)
    try:
        nbformat.write(nb, tmp)
        os.chmod(tmp, _umask_mode())
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return 0


def notebook_key(t: Tree, nb: Path, whash: str | None = None) -> str:
    h = hashlib.sha256(nb.read_bytes())
    h.update((whash if whash is not None else wmr_hash(t)).encode())
    h.update(sys.version.encode())
    return h.hexdigest()


def stale_notebooks(t: Tree) -> list[Path]:
    wh = wmr_hash(t)
    out = []
    for nb in t.notebook_files():
        res, stamp = t.nb_out / nb.name, t.nb_out / (nb.stem + ".stamp")
        if not (res.exists() and _read(stamp) == notebook_key(t, nb, wh)):
            out.append(nb)
    return out


def _execute_one(t: Tree, nb: Path, key: str) -> str | None:
    """Execute NB in a fresh process+kernel; return None on success, the error text otherwise."""
    out, stamp = t.nb_out / nb.name, t.nb_out / (nb.stem + ".stamp")
    stamp.unlink(missing_ok=True)           # nothing stale may look valid while we run
    out.unlink(missing_ok=True)
    t0 = time.perf_counter()
    p = subprocess.run([sys.executable, str(Path(__file__).resolve()), "_run1", str(nb), str(out), str(t.root)],
                       cwd=t.root, env=t.env(), capture_output=True, text=True)
    if p.returncode != 0 or not out.exists():
        out.unlink(missing_ok=True)
        for junk in t.nb_out.glob("." + nb.name + "*.tmp"):
            junk.unlink(missing_ok=True)
        say("execute", f"FAILED {nb.name}", t0)
        err = "\n".join(l for l in p.stderr.splitlines() if not l.startswith("[IPKernelApp] WARNING"))
        return strip_ansi(err.strip() or p.stdout.strip() or f"exit code {p.returncode}")
    _write_atomic(stamp, key + "\n")
    say("execute", f"{nb.name}", t0)
    return None


def execute(tree: Tree | None = None, workers: int = WORKERS, merge: bool = True,
            only: list[str] | None = None) -> list[str]:
    """Execute every stale notebook (parallel), then merge the ledger. Raises BuildError.
    `only`: restrict to these notebook file names. Returns the names of the notebooks executed."""
    t = tree or Tree()
    t0 = time.perf_counter()
    nbs = [nb for nb in t.notebook_files() if only is None or nb.name in only]
    if not nbs:
        say("execute", f"no notebooks in {t.notebooks}")
    t.nb_out.mkdir(parents=True, exist_ok=True)
    wh = wmr_hash(t)
    todo = [nb for nb in stale_notebooks(t) if nb in nbs]
    for nb in nbs:
        if nb not in todo:
            say("execute", f"{nb.name} up to date (cached)")
    failures: dict[str, str] = {}
    if todo:
        with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
            futs = {nb.name: pool.submit(_execute_one, t, nb, notebook_key(t, nb, wh)) for nb in todo}
            for name, f in futs.items():
                err = f.result()
                if err:
                    failures[name] = err
    if failures:
        msg = "\n\n".join(f"=== notebook {t.notebooks.name}/{n} failed ===\n{e}" for n, e in failures.items())
        raise BuildError(msg)
    say("execute", f"{len(todo)} executed, {len(nbs) - len(todo)} cached", t0)
    if merge:
        merge_ledger(t, force=bool(todo))
    return [nb.name for nb in todo]


def _module_present(t: Tree, mod: str) -> bool:
    return (t.wmr / (mod + ".py")).exists() or (t.wmr / mod / "__init__.py").exists()


def merge_ledger(t: Tree, force: bool = False) -> None:
    t0 = time.perf_counter()
    if not _module_present(t, "paper/ledger"):
        say("ledger", "skipped: wmr/ledger.py not found (python -m wmr.paper.ledger unavailable)")
        return
    frags = sorted((t.figures / "ledger").glob("*.csv"))
    key = _hash_files(frags, t.root, hashlib.sha256(wmr_hash(t).encode())).hexdigest()
    stamp = t.build / "ledger.stamp"
    if not force and (t.figures / "ledger.csv").exists() and _read(stamp) == key:
        say("ledger", "figures/ledger.csv up to date (cached)")
        return
    stamp.unlink(missing_ok=True)
    p = subprocess.run([sys.executable, "-m", "wmr.paper.ledger"], cwd=t.root, env=t.env(),
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise BuildError(f"python -m wmr.paper.ledger failed (exit {p.returncode}):\n{p.stdout}\n{p.stderr}")
    _write_atomic(stamp, key + "\n")
    last = (p.stdout.strip().splitlines() or [""])[-1]
    say("ledger", f"python -m wmr.paper.ledger: {last or 'figures/ledger.csv'} ({len(frags)} fragments)", t0)


def figures(tree: Tree | None = None, force: bool = False) -> bool:
    """Run `python -m wmr.paper.figures figures/` when wmr/*.py changed since the last run."""
    t = tree or Tree()
    t0 = time.perf_counter()
    if not _module_present(t, "paper/figures"):
        say("figures", "skipped: wmr/figures.py not found (python -m wmr.paper.figures unavailable)")
        return False
    key = wmr_hash(t)
    stamp = t.build / "figures.stamp"
    if not force and _read(stamp) == key and (t.figures / "captions.json").exists():
        say("figures", "figures/ up to date (cached)")
        return False
    stamp.unlink(missing_ok=True)
    env = t.env()
    env.setdefault("MPLBACKEND", "Agg")
    p = subprocess.run([sys.executable, "-m", "wmr.paper.figures", "figures/"], cwd=t.root, env=env,
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise BuildError(f"python -m wmr.paper.figures figures/ failed (exit {p.returncode}):\n{p.stdout}\n{p.stderr}")
    _write_atomic(stamp, key + "\n")
    say("figures", "python -m wmr.paper.figures figures/", t0)
    return True


# ----------------------------------------------------------------------------- report inputs
def report_key(t: Tree) -> str:
    files = list(t.notebook_files()) + t.wmr_files()
    files += sorted(p for p in TOOLS.rglob("*") if p.is_file() and "__pycache__" not in p.parts
                    and p.suffix not in {".md", ".pyc"})
    if t.figures.is_dir():
        files += sorted(p for p in t.figures.rglob("*") if p.is_file())
    h = _hash_files(files, t.root)
    h.update(git_commit(t).encode())
    h.update(sys.version.encode())
    return h.hexdigest()


def git_commit(t: Tree) -> str:
    """HEAD, marked '-dirty' only when the sources (wmr/, notebooks/, tools/) differ from it:
    figures/ is rewritten by the build itself and does not count."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], cwd=t.root,
                              capture_output=True, text=True, timeout=10).stdout.strip()
        if not head:
            return "unknown"
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--",
                                "wmr", "notebooks", "tools", "pyproject.toml"],
                               cwd=t.root, capture_output=True, text=True, timeout=10).stdout.strip()
        return head + ("-dirty" if dirty else "")
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def read_csv(path: Path) -> list[dict] | None:
    if not path.exists():
        return None
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def read_captions(t: Tree) -> dict:
    p = t.figures / "captions.json"
    if not p.exists():
        return {}
    caps = json.loads(p.read_text(encoding="utf-8"))

    def order(k):
        n = str(caps[k].get("number", ""))
        return (0, int(n), k) if n.isdigit() else (1, 0, k)
    return {k: caps[k] for k in sorted(caps, key=order)}


# ----------------------------------------------------------------------------- text helpers
_MATH = re.compile(r"(\$\$.+?\$\$|(?<!\\)\$.+?(?<!\\)\$)", re.S)
_TEX_ESC = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "#": r"\#", "_": r"\_",
            "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def _tex_esc(part: str) -> str:
    return "".join(_TEX_ESC.get(c, c) for c in part).replace("$", r"\$")


def latex_text(s: str) -> str:
    """Escape text for LaTeX, leaving $...$ math untouched; `code` becomes \\texttt."""
    parts = _MATH.split(s or "")
    out = []
    for i, part in enumerate(parts):
        if i % 2:
            out.append(part)
        else:
            segs = re.split(r"`([^`]+)`", part)
            out.append("".join(r"\texttt{" + _tex_esc(x) + "}" if j % 2 else _tex_esc(x) for j, x in enumerate(segs)))
    return "".join(out)


def html_text(s: str) -> str:
    """Escape text for HTML (math stays for MathJax); `code` becomes <code>."""
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", html.escape(s or ""))


_CMD = re.compile(r"\\[A-Za-z]+")
_MATHY = re.compile(r"\\[A-Za-z]+|[A-Za-z0-9)\]}]_|\^|\\[,;!]")
_JOIN = {"=", "+", "-", "<", ">", "\\times", "\\cdot", "\\le", "\\ge", "\\ne", "\\approx", "\\to", "|"}


def auto_math(s: str) -> str:
    """Ledger text fields (note, convention) may carry bare LaTeX such as
    '\\dot\\psi\\times\\mathbf d_i read as ...'. Wrap each run of TeX-looking words in $...$ so that
    it is typeset (MathJax / LaTeX) instead of breaking the PDF or showing raw. Text that
    already has $...$ is returned unchanged."""
    s = " ".join((s or "").split())
    if "$" in s or not _CMD.search(s):
        return s
    words = s.split(" ")
    out: list[str] = []
    run: list[str] = []

    def flush():
        if not run:
            return
        while run and run[-1] in _JOIN:      # a trailing operator belongs to the prose
            tail = run.pop()
            out_tail.append(tail)
        if run:
            last = run[-1]
            m = re.match(r"^(.*?)([;,.:]*)$", last)
            run[-1], punct = m.group(1), m.group(2)
            body = " ".join(run)
            while body.endswith(")") and body.count(")") > body.count("("):  # '(... of the P_i)'
                body, punct = body[:-1], ")" + punct
            out.append("$" + body + "$" + punct)
        out.extend(out_tail)
        run.clear()
        out_tail.clear()
    out_tail: list[str] = []
    for w in words:
        mathy = bool(_MATHY.search(w))
        needs_arg = bool(run) and re.search(r"\\[A-Za-z]+$", run[-1]) is not None
        if mathy or needs_arg or (run and w in _JOIN):
            # a word that ends a sentence clause closes the run after itself
            run.append(w)
            if mathy and re.search(r"[;,:]$", w):
                flush()
        else:
            flush()
            out.append(w)
    flush()
    return " ".join(out)


def md_cell_text(s) -> str:
    """A value for a markdown table cell: one line, pipes escaped."""
    s = "" if s is None else str(s)
    return " ".join(s.split()).replace("|", r"\|")


def strip_math(s: str) -> str:
    s = (s or "").strip()
    for d in ("$$", "$"):
        if s.startswith(d) and s.endswith(d) and len(s) > 2 * len(d):
            return s[len(d):-len(d)].strip()
    return s


def display_math(s: str) -> str:
    body = " ".join(strip_math(s).split())
    return f"$$\n{body}\n$$" if body else "*(none)*"


_TEXTARG = re.compile(r"\\(?:text|mathrm|textrm|operatorname|mbox|mathit)\s*\{[^{}]*\}")


def is_prose(s: str) -> bool:
    """A ledger 'printed'/'corrected' field is either a formula (bare LaTeX) or, for the paper's
    claims, a sentence that may hold some LaTeX. Three or more plain words (outside \\text{...}
    and not LaTeX commands) make it prose."""
    s = s or ""
    if "$" in s:
        return True
    bare = re.sub(r"\\(?:begin|end)\s*\{[^{}]*\}", " ", _TEXTARG.sub(" ", s))
    words = re.findall(r"(?<![\\A-Za-z])[A-Za-z]{3,}\b", bare)
    return len(words) >= 3


def formula_cells(s: str) -> list:
    """Cells showing one printed/corrected form: a formula is typeset in display style and scaled
    down to the text width in the PDF (adjustbox) or scrollable in the HTML; prose is quoted."""
    s = " ".join((s or "").split())
    if not s:
        return [_md("*(none)*")]
    if is_prose(s):
        return [_md("> " + auto_math(s))]
    body = strip_math(s)
    if len(body) > 140 and "\\begin{" not in body and "\\left" not in body:
        # long, breakable (no matrix, no \left...\right): inline display-style math in a paragraph
        # breaks at relations and operators instead of being scaled down to an unreadable size
        tex = "\\begin{quote}\\raggedright $\\displaystyle " + body + "$\\end{quote}"
    else:
        tex = "\\begin{center}\\adjustbox{max width=\\linewidth}{$\\displaystyle " + body + "$}\\end{center}"
    return _both(f'<div class="wmr-eq">$$ {html.escape(body)} $$</div>', tex)


def md_table(headers: list[str], rows: list[list], widths: list[int] | None = None) -> str:
    widths = widths or [3] * len(headers)
    lines = ["| " + " | ".join(md_cell_text(h) for h in headers) + " |",
             "|" + "|".join("-" * max(3, w) for w in widths) + "|"]
    lines += ["| " + " | ".join(md_cell_text(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


NOT_OK = ("typo", "wrong")


def fmt_residual(v) -> str:
    try:
        x = float(v)
    except (TypeError, ValueError):
        return "" if v is None else str(v)
    return "0" if x == 0 else f"{x:.1e}"


def chapter_no(nb) -> str:
    m = re.match(r"(\d+)", str(nb or ""))
    return m.group(1) if m else str(nb or "")


def _truthy(v) -> bool | None:
    s = str(v).strip().lower()
    if s in {"1", "true", "yes", "y", "listed", "found", "reported"}:
        return True
    if s in {"0", "false", "no", "n", "missing", "missed", "not listed", "absent", ""}:
        return False
    return None


def _paper_column(cols: list[str]) -> str | None:
    for c in cols:
        lc = c.lower()
        if "paper" in lc or "missed" in lc or "missing" in lc:
            return c
    return None


def singularity_summary(rows: list[dict]) -> tuple[int, list[str], str | None]:
    """(number of families, families the paper misses, the column used for 'in paper')."""
    if not rows:
        return 0, [], None
    cols = list(rows[0].keys())
    fam_col = next((c for c in cols if c.lower() in {"family", "id", "name"}), cols[0])
    fams = list(dict.fromkeys(r[fam_col] for r in rows))
    pcol = _paper_column(cols)
    missed: list[str] = []
    if pcol:
        inverse = "miss" in pcol.lower()  # a 'missed_by_paper' column is true when missed
        for r in rows:
            v = _truthy(r.get(pcol))
            if v is None:
                continue
            if (v if inverse else not v) and r[fam_col] not in missed:
                missed.append(r[fam_col])
    return len(fams), missed, pcol


# ----------------------------------------------------------------------------- report notebook
def _md(src: str, tags=()):
    import nbformat
    c = nbformat.v4.new_markdown_cell(src)
    if tags:
        c.metadata["tags"] = list(tags)
    return c


def _raw(src: str, mime: str):
    import nbformat
    c = nbformat.v4.new_raw_cell(src)
    c.metadata["raw_mimetype"] = mime
    return c


def _both(html_src: str, latex_src: str):
    return [_raw(html_src, "text/html"), _raw(latex_src, "text/latex")]


def _img_data_uri(p: Path) -> str:
    mime = {".svg": "image/svg+xml", ".png": "image/png"}[p.suffix]
    return f"data:{mime};base64," + base64.b64encode(p.read_bytes()).decode()


def build_report_notebook(t: Tree, date: str, commit: str):
    import nbformat

    nb = nbformat.v4.new_notebook()
    cells = nb.cells
    nb.metadata["title"] = TITLE
    nb.metadata["wmr"] = {"subtitle": SUBTITLE, "paper": PAPER, "commit": commit, "date": date}

    ledger = read_csv(t.figures / "ledger.csv")
    caps = read_captions(t)
    sing = read_csv(t.figures / "singularities.csv")
    chapters = [t.nb_out / nb_.name for nb_ in t.notebook_files()]

    # --- title (the LaTeX title page is in the wmr_latex template)
    cells.append(_raw(
        f'<header class="wmr-title"><h1 class="wmr-h1">{html.escape(TITLE)}</h1>'
        f'<p class="wmr-sub">{html.escape(SUBTITLE)}</p>'
        f'<p class="wmr-ref">Paper: {html.escape(PAPER)}</p>'
        f'<p class="wmr-build">Built {html.escape(date)} from commit <code>{html.escape(commit)}</code></p>'
        "</header>", "text/html"))

    # --- summary of findings
    s = ["# Summary of findings", ""]
    if ledger is None:
        s.append("*The ledger (`figures/ledger.csv`) is not available: `python -m wmr.paper.ledger` has not produced it.*")
    else:
        counts: dict[str, int] = {}
        for r in ledger:
            counts[r.get("verdict", "?")] = counts.get(r.get("verdict", "?"), 0) + 1
        s.append(f"The ledger checks **{len(ledger)}** printed claims of the paper against the symbolic "
                 "and numerical derivations in the chapters below.")
        s.append("")
        s.append(md_table(["Verdict", "Count"], [[k, v] for k, v in sorted(counts.items(), key=lambda kv: -kv[1])], [12, 6]))
        s.append("")
        bad = [r for r in ledger if r.get("verdict", "ok") != "ok"]
        if bad:
            s.append(f"Claims whose verdict is not *ok* ({len(bad)}):")
            s.append("")
            for r in bad:
                note = auto_math(r.get("note"))
                s.append(f"- **{r.get('id')}** (§{r.get('section')}, *{r.get('verdict')}*)" + (f": {note}" if note else ""))
        else:
            s.append("Every claim in the ledger has verdict *ok*.")
    s.append("")
    if sing is None:
        s.append("*The singularity list (`figures/singularities.csv`) is not available.*")
    else:
        n, missed, pcol = singularity_summary(sing)
        s.append(f"**Singularities.** {n} singular configuration famil{'y' if n == 1 else 'ies'} found "
                 f"({len(sing)} rows in `figures/singularities.csv`).")
        if pcol is None:
            s.append(" (The list has no column saying whether the paper reports each family.)")
        elif missed:
            s.append(f" The paper misses {len(missed)}: " + ", ".join(f"**{m}**" for m in missed) + ".")
        else:
            s.append(" The paper reports all of them.")
    cells.append(_md("\n".join(s)))

    # --- ledger table
    if ledger is not None:
        rows = [[r.get("id"), r.get("section"),
                 r.get("verdict") if r.get("verdict") == "ok" else f"**{r.get('verdict')}**",
                 r.get("symbolic_check"), fmt_residual(r.get("max_residual")), chapter_no(r.get("notebook")),
                 auto_math(r.get("note"))
                 + (f" *Convention:* {auto_math(r['convention'])}" if (r.get("convention") or "").strip() else "")]
                for r in ledger]
        cells.append(_md("# Ledger\n\nEvery equation and claim checked, in the paper's order "
                         "(*Ch.* is the chapter that checks it; *Symbolic* the outcome of the exact comparison; "
                         "*Residual* the largest numerical residual). Printed and corrected forms of the rows that "
                         "are not *ok* are in the errata; the full table, with the LaTeX of every row, is "
                         "`figures/ledger.csv`.\n\n" +
                         md_table(["ID", "§", "Verdict", "Symbolic", "Residual", "Ch.", "Note"],
                                  rows, [13, 7, 6, 7, 7, 3, 45])))

    # --- errata
    if ledger is not None:
        errs = [r for r in ledger if r.get("verdict") in NOT_OK]
        cells.append(_md("# Errata\n\n" + ("Rows of the ledger judged *typo* or *wrong*: the form printed in the "
                                             "paper, the corrected form, and why." if errs else
                                             "No printed equation was found to be a typo or wrong.")))
        for i, r in enumerate(errs, 1):
            cells.append(_md(f"## E{i}. {r.get('id')} (§{r.get('section')}, {r.get('verdict')})\n\nPrinted:"))
            cells.extend(formula_cells(r.get("printed")))
            cells.append(_md("Corrected:"))
            cells.extend(formula_cells(r.get("corrected")))
            e = []
            if (r.get("note") or "").strip():
                e += [auto_math(r["note"]), ""]
            if (r.get("convention") or "").strip():
                e += [f"*Convention:* {auto_math(r['convention'])}", ""]
            if e:
                cells.append(_md("\n".join(e)))

    # --- figures
    cells.append(_md("# Figures\n\n" + ("Regenerated by `python -m wmr.paper.figures figures/`."
                                        if caps else "*No figures: `figures/captions.json` is missing.*")))
    for key, c in caps.items():
        num, title, cap = str(c.get("number", "")), c.get("title", ""), c.get("caption", "")
        label = f"Figure {num}." if num.isdigit() else ""
        svg, png, pdf = (t.figures / f"{key}.{ext}" for ext in ("svg", "png", "pdf"))
        img = svg if svg.exists() else png
        fn = c.get("function", "")
        src_note = f" <span class=\"wmr-src\">({html.escape(fn)})</span>" if fn else ""
        h = (f'<figure class="wmr-fig" id="{html.escape(key)}">'
             + (f'<img src="{_img_data_uri(img)}" alt="{html.escape((label + " " + title).strip())}">' if img.exists()
                else f"<p><em>missing image figures/{html.escape(key)}.svg</em></p>")
             + f"<figcaption><b>{html_text((label + ' ' + title).strip())}.</b> {html_text(cap)}{src_note}</figcaption></figure>")
        gfx = pdf if pdf.exists() else png
        if gfx.exists():
            body = (r"\includegraphics[width=\linewidth,height=0.62\textheight,keepaspectratio]{"
                    + gfx.as_posix() + "}")
        else:
            body = r"\fbox{missing image figures/" + latex_text(key) + "}"
        fn_tex = r" {\footnotesize(\texttt{" + latex_text(fn) + "})}" if fn else ""
        latex = ("\\begin{figure}[H]\\centering\n" + body + "\n"
                 "\\captionsetup{format=plain,font=small,aboveskip=6pt}\n\\caption*{\\textbf{" + latex_text(label + " " + title) + ".} " + latex_text(cap) + fn_tex + "}\n"
                 "\\label{fig:" + key + "}\n\\end{figure}")
        cells.extend(_both(h, latex))

    # --- singularity list
    if sing is not None:
        allcols = list(sing[0].keys()) if sing else []
        # the columns a reader needs (the others stay in the CSV); any other layout: all columns
        prefer = {"family": 10, "configuration": 18, "geometric_meaning": 18, "det_J": 6, "rank_F": 8,
                  "listed_in_paper": 5, "note": 30}
        cols = [c for c in allcols if c in prefer]
        if len(cols) < 3:
            cols = allcols
        widths = [prefer.get(c, 10) for c in cols]
        heads = [c.replace("_", " ") for c in cols]
        rows = [[auto_math(r.get(c)) for c in cols] for r in sing]
        cells.append(_md("# Singularities\n\nThe singular configurations of the robot with three centred wheels, "
                         "computed (`figures/singularities.csv`, which also has " +
                         ", ".join(f"`{c}`" for c in allcols if c not in cols) + ").\n\n" +
                         (md_table(heads, rows, widths) if cols else "*(empty)*")))

    # --- chapters
    for i, ch in enumerate(chapters):
        if not ch.exists():
            cells.append(_md(f"# {ch.stem}\n\n*Not executed: `{ch.name}` is missing from {t.nb_out}.*"))
            continue
        src = nbformat.read(ch, as_version=4)
        if i == 0:
            for k in ("kernelspec", "language_info"):
                if k in src.metadata:
                    nb.metadata[k] = src.metadata[k]
        first = next((c for c in src.cells if c.cell_type == "markdown" and c.source.strip()), None)
        if not (first is not None and first.source.lstrip().startswith("# ")):
            cells.append(_md(f"# {ch.stem.replace('_', ' ')}"))
        for c in src.cells:
            tags = set(c.get("metadata", {}).get("tags", []))
            if tags & {"remove-cell", "remove_cell", "hide-cell"}:
                continue
            c = nbformat.from_dict(dict(c))
            if c.cell_type == "code":
                c.outputs = [o for o in c.outputs if not (o.get("output_type") == "stream" and o.get("name") == "stderr")]
                if tags & {"remove-input", "remove_input", "hide-input"}:
                    c.metadata.setdefault("jupyter", {})["source_hidden"] = True
            cells.append(c)
    for j, c in enumerate(cells):
        c["id"] = f"r{j:04d}"
    nb.nbformat, nb.nbformat_minor = 4, 5
    return nb


# ----------------------------------------------------------------------------- exporters
def mathjax_js() -> str:
    """MathJax 3 (tex-svg-full: every TeX extension, SVG glyphs, no fonts to fetch) from the
    pinned PyPI package django-static-mathjax (see environment.lock)."""
    try:
        import mathjax  # django-static-mathjax
        base = Path(mathjax.__file__).parent
    except ImportError:
        import importlib.util
        spec = importlib.util.find_spec("mathjax")
        if spec is None or not spec.submodule_search_locations:
            raise BuildError("MathJax bundle not found: `pip install -r environment.lock` (django-static-mathjax)")
        base = Path(list(spec.submodule_search_locations)[0])
    js = base / "static" / "mathjax" / "es5" / "tex-svg-full.js"
    if not js.exists():
        raise BuildError(f"MathJax bundle not found at {js}")
    return js.read_text(encoding="utf-8").replace("</script", "<\\/script")


def _html_exporter():
    """nbconvert's HTMLExporter without its two costly passes over our own, trusted content:
    bleach sanitising (clean_html) of every cell and a BeautifulSoup re-parse of the whole page
    (which only adds alt text and tabindex attributes). Same output otherwise."""
    from nbconvert import HTMLExporter
    from nbconvert.exporters.templateexporter import TemplateExporter
    from nbconvert.filters.highlight import Highlight2HTML
    from nbconvert.filters.widgetsdatatypefilter import WidgetsDataTypeFilter

    class ReportHTMLExporter(HTMLExporter):
        def from_notebook_node(self, nb, resources=None, **kw):
            langinfo = nb.metadata.get("language_info", {})
            lexer = langinfo.get("pygments_lexer", langinfo.get("name", None))
            self.register_filter("highlight_code", Highlight2HTML(pygments_lexer=lexer, parent=self))
            resources = self._init_resources(resources)
            self.register_filter("filter_data_type", WidgetsDataTypeFilter(
                notebook_metadata=self._nb_metadata, parent=self, resources=resources))
            return TemplateExporter.from_notebook_node(self, nb, resources, **kw)

    exp = ReportHTMLExporter(template_name="wmr_html", extra_template_basedirs=[str(TEMPLATES)],
                             exclude_input_prompt=True, exclude_output_prompt=True, embed_images=True)
    exp.register_filter("clean_html", lambda html, *a, **k: html)
    return exp


def export_html(nb, t: Tree, out: Path) -> None:
    exp = _html_exporter()
    body, _ = exp.from_notebook_node(nb, resources={"metadata": {"path": str(t.root), "name": "report"},
                                                    "wmr_mathjax_js": mathjax_js()})
    _write_atomic(out, add_toc(body))


def add_toc(page: str) -> str:
    """Insert a table of contents (links to every top-level heading) after the title block."""
    heads = re.findall(r'<h1 id="([^"]+)">(.*?)<a class="anchor-link"', page, flags=re.S)
    if not heads or "</header>" not in page:
        return page
    items = "".join(f'<li><a href="#{hid}">{text}</a></li>' for hid, text in heads)
    nav = f'<nav class="wmr-toc"><p class="wmr-toc-h">Contents</p><ul>{items}</ul></nav>'
    return page.replace("</header>", "</header>" + nav, 1)


def html_tables_to_latex(nb) -> int:
    """Give every HTML-only table output (pandas DataFrames) a text/latex twin, converted by
    pandoc in ONE call, so the PDF shows a real (long)table instead of wrapped plain text.
    The HTML report is unaffected (it prefers text/html). Returns the number converted."""
    from nbconvert.utils.pandoc import pandoc
    targets = []
    for c in nb.cells:
        if c.cell_type != "code":
            continue
        for o in c.get("outputs", []):
            d = o.get("data", {})
            h = d.get("text/html")
            if h and "text/latex" not in d and "<table" in (h if isinstance(h, str) else "".join(h)):
                targets.append(d)
    if not targets:
        return 0
    sep = "WMRTABLESEPARATOR"
    src = f"\n<p>{sep}</p>\n".join(
        re.sub(r"<style.*?</style>", "", d["text/html"] if isinstance(d["text/html"], str) else "".join(d["text/html"]), flags=re.S)
        for d in targets)
    tex = pandoc(src, "html", "latex")
    parts = [p.strip() for p in re.split(r"\n*" + sep + r"\n*", tex)]
    if len(parts) != len(targets):
        return 0  # could not split reliably: keep the plain-text fallback
    for d, p in zip(targets, parts):
        d["text/latex"] = p
    return len(targets)


# Pandoc reader for the PDF, matched to what Jupyter/MathJax show: no fancy_lists ("(61) is ..."
# is a paragraph), no raw_tex (a bare '\dot' in prose is text, as in the notebook, not a LaTeX
# command that breaks the build); LaTeX environments outside $...$ (MathJax typesets them) are
# wrapped in $$...$$ by wrap_environments() first; no ^superscript^/~subscript~ (notes say d_i^T/...^2).
MD_READER = "markdown+tex_math_double_backslash+tex_math_single_backslash-fancy_lists-raw_tex-superscript-subscript-citations"
_ENV = re.compile(r"\\begin\{([A-Za-z]+\*?)\}.*?\\end\{\1\}", re.S)


def wrap_environments(md: str) -> str:
    parts = _MATH.split(md)
    for i in range(0, len(parts), 2):
        parts[i] = _ENV.sub(lambda m: "$$" + m.group(0) + "$$", parts[i])
    return "".join(parts)


def _text(v) -> str:
    return v if isinstance(v, str) else "".join(v)


def markdown_to_latex_batch(nb) -> int:
    """Convert every markdown cell and every text/markdown output to LaTeX in ONE pandoc call
    (nbconvert's template calls pandoc twice per cell: hundreds of processes for the report).
    Cells get the result in their metadata (used by the wmr_latex template), outputs a
    text/latex twin (which the PDF prefers; the HTML still shows the markdown). Falls back to
    nbconvert's per-cell path if the batch cannot be split back reliably."""
    from nbconvert.filters import citation2latex, strip_files_prefix
    from nbconvert.utils.pandoc import pandoc
    items = []  # (setter, source)
    for c in nb.cells:
        if c.cell_type == "markdown" and c.source.strip():
            items.append((lambda tex, c=c: c.metadata.__setitem__("wmr_latex", tex), c.source))
        elif c.cell_type == "code":
            for o in c.get("outputs", []):
                d = o.get("data", {})
                if "text/markdown" in d and "text/latex" not in d:
                    items.append((lambda tex, d=d: d.__setitem__("text/latex", tex), _text(d["text/markdown"])))
    if not items:
        return 0
    sep = "WMRCELLSEPARATOR"
    src = f"\n\n{sep}\n\n".join(wrap_environments(strip_files_prefix(citation2latex(s))) + "\n" for _, s in items)
    tex = pandoc(src, MD_READER, "latex")
    parts = re.split(r"\n*^" + sep + r"$\n*", tex, flags=re.M)
    if len(parts) != len(items):
        return 0
    for (setter, _), part in zip(items, parts):
        setter(part.strip("\n"))
    return len(items)


def export_pdf(nb, t: Tree, out: Path) -> None:
    from nbconvert import PDFExporter
    html_tables_to_latex(nb)
    markdown_to_latex_batch(nb)
    # raw_mimetypes: PDFExporter would keep only 'application/pdf' raw cells (its output type)
    exp = PDFExporter(template_name="wmr_latex", extra_template_basedirs=[str(TEMPLATES)],
                      raw_mimetypes=["text/latex", "text/tex", ""],
                      exclude_input=True, exclude_input_prompt=True, exclude_output_prompt=True)
    if not shutil.which("xelatex"):
        raise BuildError("xelatex not found: run `make report` (it installs the TeX toolchain) "
                         "or apt-get install texlive-xetex texlive-fonts-recommended texlive-plain-generic "
                         "texlive-latex-extra lmodern pandoc")
    try:
        pdf, _ = exp.from_notebook_node(nb, resources={"metadata": {"path": str(t.root), "name": "report"}})
    except Exception as e:  # nbconvert's LatexFailed carries the xelatex log
        raise BuildError(f"PDF export failed: {strip_ansi(str(e))[-6000:]}") from e
    _write_atomic(out, pdf)


def export_tex(nb, t: Tree, out: Path) -> None:
    """Debug helper: the LaTeX source the PDF is made from."""
    from nbconvert import LatexExporter
    exp = LatexExporter(template_name="wmr_latex", extra_template_basedirs=[str(TEMPLATES)],
                        raw_mimetypes=["text/latex", "text/tex", ""], exclude_input=True, exclude_input_prompt=True, exclude_output_prompt=True)
    body, res = exp.from_notebook_node(nb, resources={"metadata": {"path": str(t.root), "name": "report"}})
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(body)
    for name, data in res.get("outputs", {}).items():
        (out.parent / name).write_bytes(data)


def report(tree: Tree | None = None, html_only: bool = False) -> tuple[Path, Path]:
    t = tree or Tree()
    t0 = time.perf_counter()
    out_html, out_pdf = t.build / "report.html", t.build / "report.pdf"
    stamp = t.build / "report.stamp"
    want = report_key(t)
    if _read(stamp) == want and out_html.exists() and (html_only or out_pdf.exists()):
        say("report", "up to date (inputs unchanged)", t0)
        print(f"report: {out_html} {out_pdf}")
        return out_html, out_pdf
    stamp.unlink(missing_ok=True)
    out_pdf.unlink(missing_ok=True)  # no stale PDF beside a new HTML

    # figures and notebooks are independent: run the figure script beside the notebook pool
    fig_err: list[BaseException] = []

    def _fig():
        try:
            figures(t)
        except BaseException as e:  # noqa: BLE001 - re-raised below
            fig_err.append(e)
    th = threading.Thread(target=_fig)
    th.start()
    try:
        execute(t)
    finally:
        th.join()
    if fig_err:
        raise fig_err[0]

    t1 = time.perf_counter()
    import nbformat
    nb = build_report_notebook(t, _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"), git_commit(t))
    _write_atomic(t.build / "report.ipynb", nbformat.writes(nb))
    say("report", f"assembled build/report.ipynb ({len(nb.cells)} cells)", t1)

    def _html():
        t2 = time.perf_counter()
        export_html(nb, t, out_html)
        say("report", f"HTML {out_html.stat().st_size / 1e6:.1f} MB", t2)

    def _pdf():  # own process: nbconvert's PDFExporter chdir()s the whole process
        t2 = time.perf_counter()
        p = subprocess.run([sys.executable, str(Path(__file__).resolve()), "_pdf",
                            str(t.build / "report.ipynb"), str(out_pdf), str(t.root)],
                           cwd=t.root, capture_output=True, text=True)
        if p.returncode != 0 or not out_pdf.exists():
            raise BuildError(f"PDF export failed:\n{p.stdout[-3000:]}\n{p.stderr[-6000:]}")
        say("report", f"PDF {out_pdf.stat().st_size / 1e6:.1f} MB", t2)
    jobs = [_html] if html_only else [_html, _pdf]
    with ThreadPoolExecutor(max_workers=2) as pool:
        for f in [pool.submit(j) for j in jobs]:
            f.result()
    if not html_only:
        _write_atomic(stamp, report_key(t) + "\n")
    say("report", "done", t0)
    print(f"report: {out_html} {out_pdf}")
    return out_html, out_pdf


# ----------------------------------------------------------------------------- CLI
def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == ["_run1"]:
        return _run_one(*argv[1:4])
    if argv[:1] == ["_pdf"]:  # child: build/report.ipynb -> PDF
        import nbformat
        try:
            export_pdf(nbformat.read(argv[1], as_version=4), Tree(argv[3]), Path(argv[2]))
        except BuildError as e:
            print(e, file=sys.stderr)
            return 1
        return 0
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", help="tree with notebooks/, wmr/, figures/ (default: this repository)")
    ap.add_argument("--build", help="build directory (default: ROOT/build)")
    ap.add_argument("--notebooks", help="notebooks directory (default: ROOT/notebooks)")
    sub = ap.add_subparsers(dest="cmd", required=True)
    sub.add_parser("execute", help="execute changed notebooks, merge the ledger")
    f = sub.add_parser("figures", help="regenerate figures/ if wmr/*.py changed")
    f.add_argument("--force", action="store_true")
    r = sub.add_parser("report", help="build/report.html and build/report.pdf")
    r.add_argument("--html-only", action="store_true")
    sub.add_parser("tex", help="write build/tex/report.tex (debugging the PDF)")
    a = ap.parse_args(argv)
    t = Tree(a.root, a.build, a.notebooks)
    try:
        if a.cmd == "execute":
            execute(t)
        elif a.cmd == "figures":
            figures(t, force=a.force)
        elif a.cmd == "report":
            report(t, html_only=a.html_only)
        elif a.cmd == "tex":
            import nbformat
            nb = nbformat.read(t.build / "report.ipynb", as_version=4)
            export_tex(nb, t, t.build / "tex" / "report.tex")
            print(t.build / "tex" / "report.tex")
    except BuildError as e:
        print(f"\nBUILD FAILED\n{e}", file=sys.stderr, flush=True)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
