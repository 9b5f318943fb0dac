"""MathJax from its official release, for the report and the docs: no CDN, no rebuild.

The official MathJax 3 release is the npm package ``mathjax``; the registry publishes the sha512
``integrity`` of each tarball. This module fetches ``mathjax@VERSION`` once with npm (``npm pack``,
the registry's own client), checks the tarball against :data:`INTEGRITY` (pinned here, as the
registry gave it), keeps it in ``build/mathjax/`` and extracts the bundle asked for::

    python -m tools.mathjax                  # prints the path of es5/tex-svg-full.js
    python -m tools.mathjax tex-chtml.js     # another bundle of es5/

In Python: ``tools.mathjax.bundle("tex-svg-full.js") -> Path``. ``tex-svg-full.js`` is the one to
inline or serve: every TeX extension is in it and its glyphs are SVG paths, so it needs no other file
(no fonts, no extensions loaded later).

Why not the PyPI package ``django-static-mathjax``: it is a rebuild; its 3.2.2.1 differs from the
official 3.2.2 in 13 of the 106 files of ``es5/`` (``tex-svg-full.js`` among them: different minified
code), so what it serves is not what MathJax released.
"""

from __future__ import annotations

import base64
import gzip
import hashlib
import io
import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

__all__ = [
    "CACHE",
    "INTEGRITY",
    "VERSION",
    "MathJaxError",
    "bundle",
    "check_integrity",
    "inline_html",
    "tarball",
    "PANDOC_TEX",
    "DOLLAR_TEX",
]

#: the release: https://www.npmjs.com/package/mathjax/v/3.2.2 (the release GitHub tags as 3.2.2)
VERSION = "3.2.2"
#: ``npm view mathjax@3.2.2 dist.integrity`` (the registry's answer, pinned here)
INTEGRITY = "sha512-Bt+SSVU8eBG27zChVewOicYs7Xsdt40qm4+UpHyX7k0/O9NliPc+x77k1/FEsPsjKPZGJvtRZM1vO+geW0OhGw=="
#: where the checked tarball and the extracted bundles are kept (build/ is not tracked)
CACHE = Path(__file__).resolve().parents[1] / "build" / "mathjax"


class MathJaxError(RuntimeError):
    """MathJax could not be fetched, or what was fetched is not the release."""


def check_integrity(data: bytes, integrity: str | None = None) -> None:
    """Raise :class:`MathJaxError` unless ``data`` has the Subresource-Integrity hash ``integrity``
    (default :data:`INTEGRITY`).

    Examples
    --------
    >>> sri = "sha512-" + base64.b64encode(hashlib.sha512(b"abc").digest()).decode()
    >>> check_integrity(b"abc", sri)
    >>> try:
    ...     check_integrity(b"abd", sri)
    ... except MathJaxError as exc:
    ...     print(str(exc)[:35])
    integrity mismatch: expected sha512
    """
    integrity = INTEGRITY if integrity is None else integrity
    algo, _, want = integrity.partition("-")
    if algo not in ("sha256", "sha384", "sha512") or not want:
        raise MathJaxError(f"integrity {integrity!r}: expected 'sha512-<base64>'")
    got = base64.b64encode(hashlib.new(algo, data).digest()).decode()
    if got != want:
        raise MathJaxError(f"integrity mismatch: expected {integrity}, got {algo}-{got[:8]}...")


def _npm_pack(dest: Path) -> Path:
    npm = shutil.which("npm")
    if npm is None:
        raise MathJaxError(
            "npm not found: MathJax is fetched from the npm registry with npm (Debian: apt-get install npm)"
        )
    with tempfile.TemporaryDirectory(dir=dest) as tmp:  # an empty cwd: no project .npmrc applies
        proc = subprocess.run(
            [npm, "pack", f"mathjax@{VERSION}", "--silent", "--pack-destination", tmp],
            cwd=tmp,
            capture_output=True,
            text=True,
            timeout=600,
            check=False,
        )
        files = sorted(Path(tmp).glob("*.tgz"))
        if proc.returncode != 0 or len(files) != 1:
            raise MathJaxError(
                f"npm pack mathjax@{VERSION} failed (exit {proc.returncode}): "
                f"{proc.stderr.strip() or proc.stdout.strip()}"
            )
        out = dest / f".mathjax-{VERSION}.tgz.{os.getpid()}"
        shutil.move(str(files[0]), out)
    return out


def tarball(cache: Path = CACHE) -> bytes:
    """The bytes of the release tarball, checked against :data:`INTEGRITY` (fetched once with npm)."""
    cache.mkdir(parents=True, exist_ok=True)
    path = cache / f"mathjax-{VERSION}.tgz"
    if path.exists():
        data = path.read_bytes()
        try:
            check_integrity(data)
            return data
        except MathJaxError:
            print(f"[mathjax] {path} is damaged: fetching it again", file=sys.stderr)
    tmp = _npm_pack(cache)
    try:
        data = tmp.read_bytes()
        check_integrity(data)  # before it is kept under its name
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)
    return data


def bundle(name: str = "tex-svg-full.js", cache: Path = CACHE) -> Path:
    """Path of ``es5/<name>`` of the release, extracted from the checked tarball.

    The extracted file is compared with the tarball's member on every call, so a file changed
    after extraction is replaced.
    """
    if "/" in name or "\\" in name or name.startswith("."):
        raise MathJaxError(f"bundle {name!r}: expected a file name of es5/, such as 'tex-svg-full.js'")
    with tarfile.open(fileobj=io.BytesIO(tarball(cache)), mode="r:gz") as tar:
        try:
            member = tar.extractfile(f"package/es5/{name}")
        except KeyError:
            member = None
        if member is None:
            known = sorted(
                m.name.removeprefix("package/es5/")
                for m in tar.getmembers()
                if m.name.startswith("package/es5/") and m.name.count("/") == 2
            )
            raise MathJaxError(f"bundle {name!r} is not in mathjax@{VERSION}/es5 (there are: {', '.join(known)})")
        data = member.read()
    out = cache / VERSION / "es5" / name
    if not out.exists() or out.read_bytes() != data:
        out.parent.mkdir(parents=True, exist_ok=True)
        tmp = out.with_name(f".{name}.{os.getpid()}")
        tmp.write_bytes(data)
        os.replace(tmp, out)
    return out


#: MathJax's TeX options for a page pandoc wrote (the report): inline math between \( and \), display between \[ and \]
PANDOC_TEX = {
    "inlineMath": [["\\(", "\\)"]],
    "displayMath": [["\\[", "\\]"]],
    "processEscapes": False,
    "packages": {"[-]": ["autoload", "require", "noundefined"]},
}
#: ... and for a page nbconvert wrote from Markdown cells (nbgrader's feedback): the notebook's own ``$`` delimiters
DOLLAR_TEX = {
    "inlineMath": [["$", "$"], ["\\(", "\\)"]],
    "displayMath": [["$$", "$$"], ["\\[", "\\]"]],
    "processEscapes": True,
    "packages": {"[-]": ["autoload", "require", "noundefined"]},
}
#: the loader; the page gets the class ``no-math`` when the browser cannot unpack the bundle (no DecompressionStream)
_LOADER = """\
<script>
window.MathJax = %(config)s;
</script>
<script id="wmr-mathjax-gz" type="application/octet-stream">%(gz)s</script>
<script>
(function () {
  var data = document.getElementById('wmr-mathjax-gz').textContent.trim();
  var bin = atob(data), bytes = new Uint8Array(bin.length);
  for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  if (typeof DecompressionStream === 'undefined') {
    document.documentElement.className += ' no-math';
    return;
  }
  var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  new Response(stream).text().then(function (js) {
    var s = document.createElement('script');
    s.textContent = js;
    document.head.appendChild(s);
  });
})();
</script>"""


def inline_html(tex: dict, cache: Path = CACHE) -> str:
    """MathJax 3 inside a page, nothing fetched: its configuration, ``tex-svg-full.js`` (every TeX extension, SVG
    glyphs: no font files) gzip-compressed (fixed mtime: the bytes never change) and base64-encoded, and the
    script that unpacks it with the browser's DecompressionStream (the report and nbgrader's feedback pages).

    Parameters
    ----------
    tex : dict
        MathJax's ``tex`` options (delimiters, escapes, packages).
    cache : pathlib.Path, optional

    Returns
    -------
    str
        HTML: three ``<script>`` elements, for the page's ``<head>``.

    Raises
    ------
    MathJaxError
        The release cannot be fetched or fails its integrity check.
    """
    js = bundle("tex-svg-full.js", cache).read_bytes()
    gz = base64.b64encode(gzip.compress(js, compresslevel=9, mtime=0)).decode()
    config = {"loader": {"load": []}, "tex": tex, "svg": {"fontCache": "global", "scale": 1, "minScale": 1}}
    config["options"] = {"enableMenu": False}
    return _LOADER % {"config": json.dumps(config, indent=1), "gz": gz}


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) > 1 or (args and args[0].startswith("-")):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        print(bundle(args[0]) if args else bundle())
    except MathJaxError as exc:
        print(f"[mathjax] {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
