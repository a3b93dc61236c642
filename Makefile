# pendsym — each target bootstraps the virtual environment it needs.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: derive test test-quick report bench tex-tools clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --disable-pip-version-check -e .
	touch $(STAMP)

derive: $(STAMP)
	$(BIN)/pendsym derive --out generated

test: $(STAMP)
	$(BIN)/pytest -q

test-quick: $(STAMP)
	$(BIN)/pytest -q -m "not slow"

tex-tools:
	@command -v latexmk >/dev/null 2>&1 && kpsewhich pgfplots.sty >/dev/null 2>&1 && kpsewhich adjustbox.sty >/dev/null 2>&1 || \
	  { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
	    texlive-latex-recommended texlive-latex-extra texlive-pictures latexmk lmodern >/dev/null; }

report: $(STAMP) tex-tools
	mkdir -p build/report
	cd generated/tex && for f in *.tex; do \
	  latexmk -pdf -interaction=nonstopmode -halt-on-error -silent -outdir=../../build/report $$f || exit 1; done
	@ls -1 build/report/*.pdf

bench: $(STAMP)
	$(BIN)/python -m pendsym.bench --out generated/bench

clean:
	rm -rf build $(VENV)
