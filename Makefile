# pendsym — each target bootstraps the virtual environment it needs.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: lock derive test test-quick report bench bench-derive bench-derive-original audit tex-tools clean

$(STAMP): pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --disable-pip-version-check -c constraints.txt -e ".[test]"
	touch $(STAMP)

# rewrite constraints.txt from a fresh environment of pyproject.toml's pins
lock:
	rm -rf build/lockvenv && $(PYTHON) -m venv build/lockvenv
	build/lockvenv/bin/pip install --quiet --disable-pip-version-check -e ".[test]"
	{ echo "# The whole environment pendsym was tested with (direct and indirect dependencies), exact."; \
	  echo "# make installs with -c constraints.txt; refresh: make lock."; \
	  build/lockvenv/bin/pip freeze --exclude-editable --disable-pip-version-check; } > constraints.txt

derive: $(STAMP)
	PYTHONHASHSEED=0 $(BIN)/pendsym derive --out generated

# over the cores, a test file per worker (so that a module's fixtures are built once), under the
# hash seed of make derive: the slow tests read the Results and evidence a derive computed (same
# content keys) and compute only what is missing; the 15 slowest tests are listed.  The files go to the
# workers in the order tests/conftest.py gives them, the costliest first (--no-loadscope-reorder: xdist would
# otherwise hand out the files with the most tests first, and leave a long file with few tests to the end)
PYTEST_XDIST := -n auto --dist loadfile --no-loadscope-reorder
test: $(STAMP)
	PYTHONHASHSEED=0 $(BIN)/pytest -q $(PYTEST_XDIST) --durations=15

# the quick tier (under 3 min on a cold cache): a test over ~2 s CPU goes to the slow tier, with a cheaper
# sibling here; the 10 slowest tests are listed
test-quick: $(STAMP)
	PYTHONHASHSEED=0 $(BIN)/pytest -q $(PYTEST_XDIST) -m "not slow" --durations=10

tex-tools:
	@command -v latexmk >/dev/null 2>&1 && kpsewhich pgfplots.sty adjustbox.sty enumitem.sty xltabular.sty needspace.sty >/dev/null 2>&1 || \
	  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
	    texlive-latex-recommended texlive-latex-extra texlive-pictures latexmk lmodern >/dev/null; }

report: $(STAMP) tex-tools
	mkdir -p build/report
	cd generated/tex && for f in *.tex; do \
	  log=../../build/report/$${f%.tex}.log; \
	  max_print_line=10000 latexmk -pdf -interaction=nonstopmode -halt-on-error -silent -outdir=../../build/report $$f \
	    || { ../../$(BIN)/python -m pendsym.emit.texlog $$log; exit 1; }; \
	  ../../$(BIN)/python -m pendsym.emit.texlog $$log || exit 1; done
	@ls -1 build/report/*.pdf

bench: $(STAMP) bench-derive
	$(BIN)/python -m pendsym.bench --out generated/bench
	$(BIN)/python -m pendsym.solve.bench --out generated/bench
	$(BIN)/python -m pendsym.bench_blade --out generated/bench
	$(BIN)/python -m pendsym.scenes.bench --out generated/bench

# every generated kernel, as emitted (C and Python), on >= 20,000 points with an adversarial search
# (docs/kernel-accuracy.md); fails (exit 1, last line "audit: FAILED: …") when a kernel is over the bound.
# Over the cores (PENDSYM_WORKERS); ~230-310 s of CPU for 81 kernels in session 11.  Needs the cache of make derive.
audit: $(STAMP)
	$(BIN)/python -m pendsym.audit --generated generated --out generated/audit

# cold, no-op and one-section-changed derive, on a copy of the tree with a cache of its own
bench-derive: $(STAMP)
	$(BIN)/python -m pendsym.bench_derive --out generated/bench

bench-derive-original: $(STAMP)
	$(BIN)/python -m pendsym.bench_derive --original-only --out generated/bench

clean:
	rm -rf build $(VENV) .cache/pendsym
