# Entry points of elliptic-pendulum. Every target creates the virtual environment first,
# so on a fresh machine `make book` and `make test` are the only set-up commands.
#
#   make book         the site in book/_build/html: the book, its Japanese edition in ja/ and
#                     its reference in reference/ (myst-nb cache: unchanged cells are not
#                     re-run; each edition runs its cells in its language, both at once)
#   make book-ja      the Japanese edition alone, book/_build/html/ja
#   make site         the one folder to publish, book/_build/html: `make book`, the student
#                     edition in student/, the four PDFs in pdf/ (the student site's two in
#                     student/pdf/ as well), the notebook bundles in classroom/; its home
#                     page links every part (book/_ext/site_links.py)
#   make i18n-update  the catalogs book/locale/ja/LC_MESSAGES/*.po merged with the current
#                     English pages (a translator sees what changed)
#   make i18n-status  fails unless every current message is translated, none fuzzy, and each
#                     translation keeps its roles, references, glue keys and formulas
#   make book-strict  the same from clean, every notebook re-executed
#   make docs         API/reference site in docs/_build/html
#   make notebooks    the classroom notebooks that `make book` wrote, in notebooks/student and
#                     notebooks/instructor, each with the package's wheel, requirements.txt
#                     and a README, and the zips
#   make notebooks-ja the Japanese ones, in notebooks/ja/student and notebooks/ja/instructor
#   make book-student the student site (no solutions) in book/_build/html/student, likewise
#   make pdf          book/_build/pdf/book.pdf (solutions open) and book-student.pdf, and
#                     the Japanese edition's book-ja.pdf and book-student-ja.pdf
#   make nbgrader     the nbgrader course folder, book/_build/nbgrader: one assignment per
#                     chapter with exercises, from the site's instructor notebooks
#   make bench        speed and accuracy tables
#   make test         everything: unit, property and doctests, every command of the README
#                     run on a fresh copy of the repository (the builds, the notebooks, the
#                     PDFs, nbgrader, the site), the notebooks in a fresh venv, headless
#                     Chromium (see tests/)
#   make test-fast    the quick tier for the edit-test loop: unit, property and doctests,
#                     the build tools' own tests (no builds, no venv creation, no browser),
#                     pytest -m "not slow" -n 2
#   make lint         ruff (code, tests, tools, book and docs), mypy, the import contracts

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
AXE    := node_modules/axe-core/axe.min.js
SPHINX := $(PY) -m sphinx -n -W --keep-going

# The notebook kernels and sphinx-build must see the venv (the package is installed there,
# the kernel does not see conf.py's sys.path).
export PATH := $(CURDIR)/$(VENV)/bin:$(PATH)
# Opt in to Jupyter's platformdirs layout now, which also silences its migration warning.
export JUPYTER_PLATFORM_DIRS := 1

.PHONY: venv reference book book-en book-ja book-strict gettext i18n-update i18n-status book-student docs notebooks notebooks-ja nbgrader pdf site bench test test-fast lint clean

venv: $(STAMP)

# Reinstall only when the dependencies change; `-e` makes edits in src/ visible at once. The
# versions are those of constraints.txt, the ones the book was built and checked with.
$(STAMP): pyproject.toml constraints.txt
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c constraints.txt -e ".[test,book,dev]"
	touch $@

# A site is one folder: the book, and the reference site built into its reference/ folder
# first (the book links the library's names there, reading reference/objects.inv:
# book/conf.py). Every link is relative and stays inside the folder, so it can be copied to
# a web server or zipped as it is. The doctrees are kept out of it, in book/_build/doctrees.
BUILD    := book/_build
SITE     := $(BUILD)/html
STUDENT  := $(SITE)/student
DOCTREES := $(BUILD)/doctrees

# The Japanese edition (book/_ext/i18n.py) is the same pages with book/locale's catalogs, in
# the site's ja/ folder, linking the same reference one folder up. It runs its own cells, in
# Japanese (book/_ext/kernels.py), with its own execution cache.
JA := -D language=ja -D reference_site=../reference

# What a build of the book reads: its pages, extensions and catalogs, the reference's pages,
# the package and the build tools. Each build below is remade when one of them changes (and
# then Sphinx itself rebuilds only what changed); otherwise the next command reuses it.
# (Not what the builds write beside them: the compiled catalogs, *.mo, caches, egg-info.)
INPUTS := pyproject.toml $(shell find book docs src tools -type f -not -path '*/_build/*' \
            -not -path '*/__pycache__/*' -not -path '*.egg-info/*' -not -name '*.mo' \
            -not -path '*/.ipynb_checkpoints/*' 2>/dev/null)

# The two editions execute their pages at once, one core each, once the reference they link
# exists; make prints each edition's output whole (--output-sync), after it finished.
$(BUILD)/.reference: $(INPUTS) | $(STAMP)
	$(SPHINX) -d $(DOCTREES)/reference -b html docs $(SITE)/reference
	touch $@

$(BUILD)/.book-en: $(BUILD)/.reference
	$(SPHINX) -d $(DOCTREES)/book -b html book $(SITE)
	touch $@

$(BUILD)/.book-ja: $(BUILD)/.reference
	$(SPHINX) -d $(DOCTREES)/book-ja $(JA) -b html book $(SITE)/ja
	touch $@

reference: $(BUILD)/.reference

book-en: $(BUILD)/.book-en

book-ja: $(BUILD)/.book-ja

$(BUILD)/.book: $(BUILD)/.reference
	$(MAKE) --no-print-directory -j2 --output-sync=target $(BUILD)/.book-en $(BUILD)/.book-ja
	touch $@

book: $(BUILD)/.book

book-strict: $(STAMP)
	$(SPHINX) -E -d $(DOCTREES)/reference -b html docs $(SITE)/reference
	$(SPHINX) -E -d $(DOCTREES)/book -D nb_execution_mode=force -b html book $(SITE)
	$(SPHINX) -E -d $(DOCTREES)/book-ja -D nb_execution_mode=force $(JA) -b html book $(SITE)/ja
	touch $(BUILD)/.reference $(BUILD)/.book-en $(BUILD)/.book-ja $(BUILD)/.book

# The messages of the current English pages, book/_build/gettext/<page>.pot (on the English
# execution cache: figure captions exist only in executed pages), and cells.pot, the texts
# that the pages' code cells pass to the library (tools/i18n/library_texts.py).
gettext: $(BUILD)/.book-en
	$(SPHINX) -d $(DOCTREES)/gettext -D reference_site=../html/reference -b gettext \
	  book $(BUILD)/gettext
	$(PY) -m tools.i18n.library_texts book $(BUILD)/gettext/cells.pot

i18n-update: gettext
	$(PY) -m tools.i18n.update $(BUILD)/gettext book/locale ja

i18n-status: gettext
	$(PY) -m tools.i18n.status $(BUILD)/gettext book/locale ja

# The reference site alone.
docs: $(STAMP)
	$(SPHINX) -b html docs docs/_build/html

# The notebooks that the book's build wrote from its pages (book/_ext/classroom.py), with
# their bundles: nothing is exported or run again.
notebooks: $(BUILD)/.book-en
	rm -rf notebooks/student notebooks/instructor notebooks/*.zip
	mkdir -p notebooks
	cp -R $(SITE)/classroom/student $(SITE)/classroom/instructor $(SITE)/classroom/*.zip \
	  notebooks/

notebooks-ja: $(BUILD)/.book-ja
	rm -rf notebooks/ja
	mkdir -p notebooks/ja
	cp -R $(SITE)/ja/classroom/student $(SITE)/ja/classroom/instructor \
	  $(SITE)/ja/classroom/*.zip notebooks/ja/

# The student site: the book without solutions (book/_ext/classroom.py removes them from
# the pages and the notebooks), with its own reference and Japanese edition, inside the
# site's student/ folder so that the published folder holds it (and it can be served alone).
$(BUILD)/.student: $(INPUTS) | $(STAMP)
	$(SPHINX) -d $(DOCTREES)/student-reference -b html docs $(STUDENT)/reference
	$(SPHINX) -d $(DOCTREES)/student -D hide_solutions=1 -b html book $(STUDENT)
	$(SPHINX) -d $(DOCTREES)/student-ja -D hide_solutions=1 $(JA) -b html book $(STUDENT)/ja
	touch $@

book-student: $(BUILD)/.student

# The course folder for nbgrader (tools/classroom/nbgrader.py): nbgrader_config.py and
# source/<assignment>/, made from the instructor notebooks that `make book` wrote.
nbgrader: $(BUILD)/.book-en
	$(PY) -m tools.classroom.nbgrader $(SITE)/classroom/instructor $(BUILD)/nbgrader

# The whole book as one PDF each for instructors (solutions open) and students (none), in
# English and in Japanese: a single-page build of each, printed by headless Chromium once
# MathJax is done (tools/pdf). Each single page shares the doctrees of its HTML edition (the
# book's and the student site's), so no page is read or executed again, and resolves the
# library's names in that edition's reference; a PDF cannot link to files beside it, so
# those names print as text.
$(BUILD)/pdf/.made: $(BUILD)/.book $(BUILD)/.student
	$(PY) -m tools.pdf book $(BUILD)
	touch $@

pdf: $(BUILD)/pdf/.made

# One folder to publish: the site with the student edition and the PDFs inside it.
site: $(BUILD)/.book $(BUILD)/.student $(BUILD)/pdf/.made
	mkdir -p $(SITE)/pdf $(STUDENT)/pdf
	cp $(BUILD)/pdf/*.pdf $(SITE)/pdf/
	cp $(BUILD)/pdf/book-student.pdf $(BUILD)/pdf/book-student-ja.pdf $(STUDENT)/pdf/
	@echo "The site is $(SITE): copy the folder to any web server."

bench: $(STAMP)
	$(PY) benchmarks/bench_theta.py

# pytest runs it all, configured in pyproject.toml: tests/ (including the book build with
# every page executed, the docs build, the notebooks, nbgrader, the PDFs and the browser
# check) and the doctests of src/, book/*.md, docs/*.md and README.md. In two runs: the quick
# tier on both cores (pytest-xdist: its tests share nothing), then the build tier in one
# process, whose session builds the book once for all its tests.
test: $(STAMP) $(AXE)
	$(PY) -m pytest -m "not slow" -n 2
	$(PY) -m pytest -m slow

# axe-core for the browser test's accessibility check (tests/book/test_browser.py injects
# axe.min.js into every page): the version package-lock.json pins, installed with `npm ci`
# (checked against the lock's sha512; no install scripts) into node_modules/, kept out of git,
# whenever it is missing or older than the lock. Without npm the check is skipped on a
# developer's machine and fails under CI=true (.ci/run installs npm).
$(AXE): package.json package-lock.json
	@if command -v npm >/dev/null 2>&1; then \
	    npm ci --ignore-scripts --no-audit --no-fund && touch $@; \
	else \
	    echo "no npm: tests/book/test_browser.py will skip the accessibility check"; \
	fi

test-fast: $(STAMP)
	$(PY) -m pytest -m "not slow" -n 2

# The layers of the package are import-linter contracts in pyproject.toml.
lint: $(STAMP)
	$(PY) -m ruff check src tests tools book docs benchmarks
	$(PY) -m mypy
	$(VENV)/bin/lint-imports

clean:
	rm -rf book/_build docs/_build notebooks .pytest_cache
