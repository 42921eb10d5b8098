# One entry point per job; every install step the project needs lives here.
PY      ?= python3.11
VENV    := .venv
BIN     := $(VENV)/bin
STAMP   := $(VENV)/.installed
EXTRAS  ?= test,remote

.PHONY: install install-render tools demo test bench clean

$(BIN)/python:
	@command -v $(PY) >/dev/null 2>&1 || { echo "scenewright needs Python 3.11 ($(PY) not found); set PY=/path/to/python3.11"; exit 1; }
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/pip install -q -e ".[$(EXTRAS)]"
	@touch $(STAMP)

install: $(STAMP)

demo: install
	$(BIN)/scenewright generate --example --out demo-scene

test: install
	$(BIN)/python -m pytest -n 2 -q

bench: install
	@mkdir -p bench-results
	$(BIN)/scenewright bench layout --sizes 15,50,100 --seeds 20 --json | tee bench-results/layout.json

clean:
	rm -rf $(VENV) demo-scene bench-results
