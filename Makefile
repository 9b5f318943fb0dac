# wmr — executable edition of Leow, Low & Loh (2002).
#
#   make test      set up .venv + TeX, execute the notebooks (cached), run pytest, and fail if
#                  the build modified files that git tracks
#   make report    build/report.html (self-contained, offline math) + build/report.pdf
#   make docs      build/docs/html: the API reference and the user guide
#   make release   the sdist and the wheel, the wheel tested in a fresh venv outside the repository
#
# The build tool is the package tools/build (python -m tools.build --help). It takes a lock
# (build/.lock: a second build of this tree waits), writes every output atomically, records in
# stamps the hashes of what each step produced, and stops every child process on SIGINT/SIGTERM.
#
# Everything Python comes from environment.lock (pinned + sha256-hashed); the TeX
# toolchain for the PDF comes from Debian packages (installed here when possible).

SHELL        := /bin/bash
.SHELLFLAGS  := -eu -o pipefail -c
.DEFAULT_GOAL := help

PYTHON ?= python3
VENV   := .venv
VPY    := $(VENV)/bin/python
STAMP  := $(VENV)/.environment.lock.sha256
BUILD  := $(VPY) -m tools.build

# Debian packages for the PDF (xelatex + what nbconvert's LaTeX template \usepackage's),
# pandoc (nbconvert's markdown -> LaTeX) and poppler-utils (pdftotext/pdfinfo in the tests).
TEX_DEBS := texlive-xetex texlive-fonts-recommended texlive-plain-generic \
            texlive-latex-extra lmodern fonts-lmodern pandoc poppler-utils
TEX_CMDS := xelatex pandoc pdftotext pdfinfo

.PHONY: help venv tex browser test report figures notebooks student bench clean lock docs release

help: ## show this help
	@echo "wmr — reproducible edition of Leow, Low & Loh (2002)"
	@echo
	@grep -E '^[a-z]+:.*## ' $(MAKEFILE_LIST) | sed -E 's/^([a-z]+):.*## (.*)/  make \1\t\2/' | expand -t 18

venv: ## (internal) create/refresh .venv from environment.lock, editable install of wmr, the edition importable
	@want="$$({ sha256sum environment.lock pyproject.toml wmr/_version.py; echo "edition on sys.path (.pth) v1"; } | sha256sum | cut -d' ' -f1)"; \
	have="$$(cat $(STAMP) 2>/dev/null || true)"; \
	if [ -x $(VPY) ] && [ "$$want" = "$$have" ]; then exit 0; fi; \
	if command -v flock >/dev/null 2>&1; then exec 9>.venv.lock; \
	  flock -n 9 || { echo "[venv] another make is setting up $(VENV): waiting for it"; flock 9; }; \
	  have="$$(cat $(STAMP) 2>/dev/null || true)"; \
	  if [ -x $(VPY) ] && [ "$$want" = "$$have" ]; then exit 0; fi; \
	fi; \
	t0=$$(date +%s); \
	if [ -d $(VENV) ]; then echo "[venv] environment.lock or pyproject.toml changed: recreating $(VENV)"; rm -rf $(VENV); \
	else echo "[venv] creating $(VENV) from environment.lock"; fi; \
	$(PYTHON) -m venv $(VENV); \
	log=$(VENV)/pip-install.log; \
	{ $(VPY) -m pip install --disable-pip-version-check --require-hashes -r environment.lock && \
	  $(VPY) -m pip install --disable-pip-version-check --no-deps --no-build-isolation -e . ; } > $$log 2>&1 \
	  || { cat $$log; echo "[venv] pip install failed (log: $$log)"; exit 1; }; \
	$(VPY) -c 'import sysconfig; print(sysconfig.get_path("purelib"))' | \
	  { read site; echo "$(CURDIR)" > "$$site/wmr-edition.pth"; }; \
	echo "$$want" > $(STAMP); \
	echo "[venv] ready in $$(( $$(date +%s) - t0 )) s"

tex: ## (internal) make sure xelatex/pandoc/poppler are present (apt-get on Debian as root)
	@missing=""; \
	for c in $(TEX_CMDS); do command -v $$c >/dev/null 2>&1 || missing="$$missing $$c"; done; \
	if [ -z "$$missing" ] && kpsewhich fontspec.sty adjustbox.sty needspace.sty newunicodechar.sty \
	     fancyhdr.sty bookmark.sty booktabs.sty bm.sty etoolbox.sty truncate.sty titlesec.sty lmroman10-regular.otf >/dev/null 2>&1; then exit 0; fi; \
	if command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ]; then \
	  echo "[tex] installing:$(TEX_DEBS)"; t0=$$(date +%s); \
	  apt-get update -qq >/dev/null && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(TEX_DEBS) >/dev/null; \
	  echo "[tex] installed in $$(( $$(date +%s) - t0 )) s"; \
	else \
	  echo "TeX toolchain missing ($${missing:- LaTeX packages}); run: sudo apt-get update && sudo apt-get install -y --no-install-recommends $(TEX_DEBS)"; \
	  exit 1; \
	fi

notebooks: venv ## execute notebooks/*.ipynb into build/notebooks (only changed ones), merge the ledger
	@$(BUILD) execute

figures: venv ## regenerate figures/ outside the notebooks (python -m edition.figures figures/)
	@$(BUILD) figures

browser: ## (internal) make sure headless Chromium is present for the HTML test (apt-get on Debian as root)
	@if command -v chromium >/dev/null 2>&1 || command -v chromium-browser >/dev/null 2>&1; then exit 0; fi; \
	if command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ]; then \
	  echo "[browser] installing: chromium"; t0=$$(date +%s); \
	  apt-get update -qq >/dev/null && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium >/dev/null; \
	  echo "[browser] installed in $$(( $$(date +%s) - t0 )) s"; \
	else \
	  echo "[browser] chromium missing: the test that opens report.html in a browser will be skipped;" \
	       "install it with: sudo apt-get install -y --no-install-recommends chromium"; \
	fi

report: venv tex ## build/report.html + build/report.pdf (cached: < 1 s when nothing changed)
	@$(BUILD) report

test: venv tex browser ## execute notebooks, pytest (two partitions at once), fail if the build modified tracked files; then release, docs
	@$(BUILD) test
	@$(VPY) -m tools.release_check
	@$(VPY) -m tools.docs

release: venv ## sdist + wheel; the wheel in a fresh venv outside the repo runs the library tests, the CLI, the README (cached)
	@$(VPY) -m tools.release_check

docs: venv tex ## build/docs/html: API reference + user guide (Sphinx, numpydoc, MathJax from its release; warnings are errors)
	@$(VPY) -m tools.docs

student: venv ## build/student/*.ipynb: the chapters without worked solutions (RUN=1: also run them)
	@$(VPY) tools/student.py $(if $(RUN),--run,)

bench: venv ## time the batched kernels against floors and peers (tools/bench.py)
	@$(VPY) tools/bench.py

clean: ## remove build/ and caches (committed figures/ are kept)
	rm -rf build .pytest_cache .hypothesis
	find . -path ./.venv -prune -o -name __pycache__ -type d -print0 | xargs -0 rm -rf

lock: ## regenerate environment.lock from requirements.in (uv, universal, hashed)
	@[ -x $(VENV)/bin/uv ] || { [ -x $(VPY) ] || $(PYTHON) -m venv $(VENV); $(VPY) -m pip install --quiet uv; }
	$(VENV)/bin/uv pip compile --universal --generate-hashes --python-version 3.11 requirements.in -o environment.lock
