"""The report's apparatus (issue 30, item 9), read from the built PDF: authors in the metadata and on the title
page, the licences, a BibTeX entry with year, version and the commit stamped at build time, the full environment,
ReScience cited, no page numbers or DOI for the paper that its extracted text does not state."""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata

import pytest
from test_report import BUILD, HAVE_TEX, TREE, make

from edition.findings import citation

HAVE_POPPLER = bool(shutil.which("pdftotext") and shutil.which("pdfinfo"))
pytestmark = pytest.mark.skipif(not (HAVE_TEX and HAVE_POPPLER), reason="xelatex, pandoc or poppler missing")


@pytest.fixture(scope="module")
def pdf():
    make(str(BUILD / "report.pdf"))
    text = subprocess.run(["pdftotext", str(BUILD / "report.pdf"), "-"], capture_output=True, text=True, check=True)
    info = subprocess.run(["pdfinfo", str(BUILD / "report.pdf")], capture_output=True, text=True, check=True)
    return {"text": re.sub(r"\s+", " ", unicodedata.normalize("NFKC", text.stdout)), "info": info.stdout}


def test_authors_are_the_pdf_author_and_on_the_title_page(pdf):
    authors = citation(TREE)["authors"]
    assert re.search(rf"^Author:\s+{re.escape(authors)}\s*$", pdf["info"], re.MULTILINE), pdf["info"]
    assert authors in pdf["text"][:3000]


def test_licences_are_stated(pdf):
    assert "code: MIT; text and figures: CC BY 4.0" in pdf["text"][:3000]
    assert "Creative Commons Attribution 4.0" in pdf["text"] and (TREE / "LICENSE-text-and-figures.md").exists()


def test_bibtex_has_year_version_and_the_commit_stamped_at_build_time(pdf):
    commit = (BUILD / "commit").read_text(encoding="utf-8").split()[0][:12]
    text = pdf["text"]
    assert "@COMMIT@" not in text and "@YEAR@" not in text
    entry = text[text.index("@software{") :][:900]
    assert re.search(r"year = \{\d{4}\}", entry) and re.search(r"version = \{\d+\.\d+\.\d+\}", entry), entry
    assert f"commit = {{{commit}" in entry or "commit = {unknown" in entry, entry
    assert ("url = {" in entry) == bool(citation(TREE)["url"])


def test_environment_and_rescience(pdf):
    env = pdf["text"][pdf["text"].index("The versions this report was computed with") :][:3000]
    for name in ("robotpy-wpimath", "pandoc", "TeX (xelatex)", "operating system", "numpy", "mujoco"):
        assert name in env, name
    assert "Rougier et al. (2017)" in pdf["text"] and "10.7717/peerj-cs.142" in pdf["text"]


def test_no_invented_pages_or_doi_for_the_paper(pdf):
    paper = (TREE.parent / "shared" / "paper").glob("*.md") if (TREE.parent / "shared").exists() else []
    extracted = " ".join(p.read_text(encoding="utf-8") for p in paper)
    ref = re.search(r"Advanced Robotics 16\(2\)[^.]*\.", pdf["text"])
    assert ref, "the paper's reference"
    if not re.search(r"\b16\(2\)\s*:?\s*\d+", extracted):
        assert not re.search(r"16\(2\)[,:]\s*\d", pdf["text"]), "pages the extracted text does not state"
