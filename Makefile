# wmr — executable edition of Leow, Low & Loh (2002).
#
#   make test      set up .venv + TeX, build the report, the student edition and the lessons' grades
#                  through nbgrader (each cached), run pytest
#                  (two workers; tests/, and tests/edition/ unless it passed on exactly this tree:
#                  tools/testcache.py, FRESH=1 runs it), ruff (check, format --check) and mypy, make release
#                  and make docs (each cached), and fail if the build modified files that git tracks
#   make report    build/report.html (self-contained, offline math) + build/report.pdf
#   make docs      build/docs/html: the API reference and the user guide
#   make release   the sdist and the wheel, the wheel tested in a fresh venv outside the repository
#
# This Makefile is the build: it knows every file, what it is made from, and runs two steps at a
# time (-j2). Each step is one call of tools/build (python -m tools.build COMMAND), the glue around
# nbclient (execute a notebook), pandoc and nbconvert (HTML, LaTeX) and xelatex (PDF). A notebook is
# executed again only when its key changes: the content hashes of the notebook, wmr/ and edition/,
# and of the derived objects of each earlier chapter it reads (build/out/<chapter>/<chapter>.derived.json;
# that chapter runs first). The recipe compares them and leaves the executed copy untouched when they
# match, so that Make sees nothing new. A second build of one tree waits for the first (flock on build/.lock).
# Signals: Make passes SIGTERM to its children and nbclient stops its kernel; when make itself is
# killed outright, the operating system sends its steps SIGTERM (setpriv --pdeathsig).
#
# Everything Python comes from environment.lock (pinned + sha256-hashed); the TeX toolchain for
# the PDF comes from Debian packages (installed here when possible).

SHELL        := /bin/bash
.SHELLFLAGS  := -eu -o pipefail -c
.DEFAULT_GOAL := help

PYTHON ?= python3
VENV   := .venv
VPY    := $(CURDIR)/$(VENV)/bin/python
STAMP  := $(VENV)/.environment.lock.sha256

# the tree to build (the tests build small trees of their own) and its build directory
WMR_ROOT ?= $(CURDIR)
export WMR_ROOT
WMR_BUILD ?= $(WMR_ROOT)/build
B        := $(WMR_BUILD)
NB       := $(WMR_ROOT)/notebooks
FINDINGS := $(NB)/findings.ipynb
CHAPTERS := $(filter-out $(FINDINGS),$(sort $(wildcard $(NB)/*.ipynb)))
LESSONS  := $(sort $(wildcard $(NB)/[0-9][0-9]_*.ipynb))
EXECUTED := $(CHAPTERS:$(NB)/%=$(B)/notebooks/%)
# chapters beyond the paper: lessons (executed, student edition, assignments), not chapters of the paper's report
BEYOND   := $(wildcard $(NB)/10_robot_classes.ipynb)
REPORTED := $(filter-out $(BEYOND:$(NB)/%=$(B)/notebooks/%),$(EXECUTED))
STUDENT  := $(LESSONS:$(NB)/%=$(B)/student/%)
STUDENT_RUN := $(LESSONS:$(NB)/%=$(B)/student-run/notebooks/%)
GRADES   := $(patsubst $(NB)/%.ipynb,$(B)/assignments/grades/%.json,$(LESSONS))
FIGURES  := $(wildcard $(WMR_ROOT)/figures/*)
TOOL     := $(wildcard $(CURDIR)/tools/build/*.py)
TEMPLATES := $(wildcard $(CURDIR)/tools/build/templates/*/*)
LINTED   := $(wildcard $(addprefix $(WMR_ROOT)/,wmr edition tools tests))
# make test also checks the release and the docs of this repository (not of another tree, WMR_ROOT=...)
RELEASED := $(if $(filter $(CURDIR),$(WMR_ROOT)),yes)
# what make test builds before pytest runs (the tests find it cached)
TEST_BUILD = $(B)/report.html $(B)/report.pdf $(STUDENT_RUN) $(GRADES) $(if $(RELEASED),$(B)/course/check.json)

PDEATH := $(shell command -v setpriv >/dev/null 2>&1 && echo setpriv --pdeathsig TERM --)
BUILD  := $(PDEATH) $(VPY) -m tools.build
SUB    := $(PDEATH) $(MAKE) --no-print-directory -s -j2 -O
# hold build/.lock for the rest of the recipe (a second build of this tree says so and waits)
LOCK   = mkdir -p $(B); exec 9>$(B)/.lock; ! command -v flock >/dev/null || flock -n 9 || \
  { echo "[lock] another build of $(WMR_ROOT) is running: waiting for it"; flock 9; };
# git status with a hash of each changed file: make test compares the state before and after
GIT_STATE = git -C $(WMR_ROOT) status --porcelain=v1 --untracked-files=all 2>/dev/null | while IFS= read -r l; do \
  echo "$$l $$(sha256sum < "$(WMR_ROOT)/$${l:3}" 2>/dev/null | cut -c1-16)"; done

# Debian packages for the PDF (xelatex + what nbconvert's LaTeX template \usepackage's),
# pandoc (nbconvert's markdown -> LaTeX) and poppler-utils (pdftotext/pdfinfo in the tests).
TEX_DEBS := texlive-xetex texlive-fonts-recommended texlive-plain-generic \
            texlive-latex-extra lmodern fonts-lmodern pandoc poppler-utils
TEX_CMDS := xelatex pandoc pdftotext pdfinfo

.PHONY: help venv tex browser test report figures notebooks publish student assignments grades course bench clean lock docs release FORCE

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

# ------------------------------------------------------------------------------------- the build
notebooks: venv ## execute the chapters into build/notebooks (only changed ones), publish figures/ and the ledger
	@$(LOCK) exec $(SUB) $(B)/notebooks/findings.ipynb

report: venv tex ## build/report.html + build/report.pdf (cached: about a second when nothing changed)
	@$(LOCK) exec $(SUB) $(B)/report.html $(B)/report.pdf

student: venv ## build/student/*.ipynb: the chapters without worked solutions (RUN=1: also run them, cached)
	@$(LOCK) exec $(SUB) $(STUDENT) $(if $(RUN),$(STUDENT_RUN))

assignments: venv ## build/assignments: nbgrader source notebooks from the exercise cells (tools/assignments.py)
	@$(VPY) -m tools.assignments $(B)/assignments $(LESSONS)

grades: venv ## build/assignments/grades: each lesson through nbgrader, solved and blank (cached, like a chapter)
	@$(LOCK) exec $(SUB) $(GRADES)

figures: venv ## regenerate figures/ outside the notebooks (python -m edition.figures figures/)
	@cd $(WMR_ROOT) && $(VPY) -m edition.figures figures

# a chapter, executed in a fresh kernel with WMR_OUT=build/out/<chapter> (see tools/build/execute.py)
$(B)/notebooks/%.ipynb: $(NB)/%.ipynb FORCE
	@$(BUILD) execute $< $@ $(foreach c,$(call DERIVED_FROM,$<),--reads $(B)/out/$c/$c.derived.json)

# a chapter that builds on what an earlier one derived (its calls derived("<chapter>"), edition.derivations) reads
# the file <chapter>.derived.json that chapter wrote: it runs after it, and its key holds that file (not notebooks/)
DERIVED_FROM = $(sort $(shell sed -n 's/.*derived(\\"\([0-9A-Za-z_]*\)\\").*/\1/p' $1 2>/dev/null))
$(foreach n,$(CHAPTERS),$(eval $(B)/notebooks/$(notdir $n): \
  $(foreach c,$(call DERIVED_FROM,$n),$(B)/notebooks/$c.ipynb)))
$(foreach n,$(LESSONS),$(eval $(B)/student-run/notebooks/$(notdir $n): \
  $(foreach c,$(call DERIVED_FROM,$n),$(B)/student-run/notebooks/$c.ipynb)))

# what the chapters wrote -> figures/ (a file only when its bytes differ); their rows -> figures/ledger.csv
publish: $(EXECUTED)
	@$(BUILD) publish $(WMR_ROOT)/figures $(EXECUTED)
	@if [ -d $(WMR_ROOT)/edition/ledger ]; then cd $(WMR_ROOT) && $(VPY) -m edition.ledger $(B)/out figures/ledger.csv; fi

# Part I: the findings chapter reads figures/ (its key includes their hashes)
$(B)/notebooks/findings.ipynb: $(FINDINGS) publish FORCE
	@$(BUILD) execute $< $@ --reads $(WMR_ROOT)/figures --reads $(NB)

# the commit and its date (the build date: two builds of one commit are byte-identical);
# rewritten only when they change
$(B)/commit: FORCE
	@mkdir -p $(@D); \
	c="$$(git -C $(WMR_ROOT) log -1 --format='%H %ct' 2>/dev/null || echo unknown 0)"; \
	d="$$(git -C $(WMR_ROOT) status --porcelain --untracked-files=no -- wmr edition notebooks tools pyproject.toml 2>/dev/null | head -c1 || true)"; \
	[ -z "$${SOURCE_DATE_EPOCH:-}" ] || c="$${c% *} $$SOURCE_DATE_EPOCH"; \
	c="$$c$${d:+ +}"; [ "$$c" = "$$(cat $@ 2>/dev/null)" ] || echo "$$c" > $@

$(B)/report.ipynb: $(B)/notebooks/findings.ipynb $(REPORTED) $(B)/commit $(FIGURES) $(TOOL)
	@$(BUILD) assemble $@ $(B)/commit $(WMR_ROOT)/figures $(B)/notebooks/findings.ipynb $(REPORTED)

$(B)/report.html: $(B)/report.ipynb $(TEMPLATES) $(CURDIR)/tools/mathjax.py
	@$(BUILD) html $< $@

$(B)/report.pdf: $(B)/report.ipynb $(TEMPLATES)
	@$(BUILD) pdf $< $@

# the student edition: nbconvert drops the cells tagged "solution" and "rubric" (one call for every chapter);
# RUN=1 executes it like the chapters, to show that every exercise still runs without its solution
$(STUDENT) &: $(LESSONS)
	@$(VPY) -m jupyter nbconvert --log-level=WARN --to notebook --ClearOutputPreprocessor.enabled=True \
	  --TagRemovePreprocessor.enabled=True --TagRemovePreprocessor.remove_cell_tags='["solution", "rubric"]' \
	  --output-dir $(B)/student $(LESSONS)

$(B)/student-run/notebooks/%.ipynb: $(B)/student/%.ipynb FORCE
	@$(BUILD) execute $< $@ $(foreach c,$(call DERIVED_FROM,$(NB)/$*.ipynb),--reads $(B)/student-run/out/$c/$c.derived.json)

# the nbgrader round trip of a lesson (tools/grades.py): generate, autograde the solved and the blank notebook;
# cached like a chapter (its key: the chapter, notebooks/, wmr/, edition/, tools/{grades,assignments}.py, the lock)
$(B)/assignments/grades/%.json: $(NB)/%.ipynb FORCE
	@$(PDEATH) $(VPY) -m tools.grades $< $@

# ------------------------------------------------------------------------------------- the tests
test: venv tex browser ## build (cached), pytest -n 2 (tests/; tests/edition/ unless it passed on this exact tree: FRESH=1 runs it), ruff, mypy, release, docs; fail if the build modified tracked files
	@mkdir -p $(B); $(GIT_STATE) > $(B)/git-before
	@$(LOCK) exec $(SUB) $(TEST_BUILD)
	@rc=0; cd $(WMR_ROOT); key=$$($(VPY) -m tools.testcache key $(PYTEST_ARGS)); only=; \
	if [ -n "$$key" ] && [ -z "$(FRESH)" ] && $(VPY) -m tools.testcache check "$$key"; then only=--ignore=tests/edition; fi; \
	$(PDEATH) $(VPY) -m pytest -n 2 --dist worksteal $$only $(PYTEST_ARGS) || rc=$$?; \
	if [ $$rc = 5 ] && [ -n "$$only" ]; then rc=0; fi; tests=$$rc; \
	if [ -n "$(LINTED)" ]; then \
	  echo "[lint] ruff check, ruff format --check, mypy: $(notdir $(LINTED))"; \
	  $(VPY) -m ruff check --quiet $(LINTED) || rc=1; \
	  $(VPY) -m ruff format --check --quiet $(LINTED) || rc=1; \
	  $(VPY) -m mypy --no-error-summary $(LINTED) || rc=1; \
	fi; \
	if [ -n "$(RELEASED)" ]; then \
	  $(PDEATH) $(VPY) -m tools.release || rc=1; \
	  $(PDEATH) $(VPY) -m tools.docs || rc=1; \
	fi; \
	if ! $(GIT_STATE) | diff $(B)/git-before - > $(B)/git-changed; then \
	  echo "[git] FAILED: the build modified files that git tracks (or left new ones it does not ignore):"; \
	  sed -n 's/^[<>] ...//p' $(B)/git-changed | cut -d' ' -f1 | sort -u | sed 's/^/  /'; rc=1; \
	else echo "[git] the build left git status as it found it"; \
	  if [ $$tests = 0 ] && [ -z "$$only" ] && [ -n "$$key" ]; then $(VPY) -m tools.testcache stamp "$$key"; fi; fi; \
	exit $$rc

course: $(B)/course/check.json ## build/course: the student package (a wheel without solutions), every notebook run in a fresh venv (cached)

$(B)/course/check.json: FORCE
	@$(PDEATH) $(VPY) -m tools.course $(B)/course --check

release: venv ## sdist + wheel; the wheel in a fresh venv outside the repo runs the library tests, the CLI, the README (cached)
	@$(PDEATH) $(VPY) -m tools.release

docs: venv ## build/docs/html: API reference + user guide (Sphinx, numpydoc, MathJax from its release; warnings are errors)
	@$(PDEATH) $(VPY) -m tools.docs

bench: venv ## the one benchmark (python -m tools.bench): kernels and sweeps against floors and peers, fast paths against plain code, wmr analyze against the number of units, chapter 9's physics, nbgrader's autograding; figures in tools/BENCH.md
	@cd $(WMR_ROOT) && $(VPY) -m tools.bench

clean: ## remove build/ and caches (committed figures/ are kept)
	rm -rf build .pytest_cache .hypothesis .mypy_cache .ruff_cache
	find . -path ./.venv -prune -o -name __pycache__ -type d -print0 | xargs -0 rm -rf

lock: ## regenerate environment.lock from requirements.in (uv, universal, hashed)
	@[ -x $(VENV)/bin/uv ] || { [ -x $(VPY) ] || $(PYTHON) -m venv $(VENV); $(VPY) -m pip install --quiet uv; }
	$(VENV)/bin/uv pip compile --universal --generate-hashes --python-version 3.11 requirements.in -o environment.lock

FORCE:
