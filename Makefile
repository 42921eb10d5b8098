# One entry point per job; every install step the project needs lives here.
PY      ?= python3.11
VENV    := .venv
BIN     := $(VENV)/bin
STAMP   := $(VENV)/.installed
EXTRAS  ?= test,remote,render,batch,sim,studio
#: The revision `make bench` measures the speed figures against (before the start-up, asset and
#: edit speed work); override with SPEED_BASELINE=<rev>.
SPEED_BASELINE ?= 9091e14

.PHONY: install install-render install-clip install-batch install-sim install-studio tools chromium demo test bench clean

$(BIN)/python:
	@command -v $(PY) >/dev/null 2>&1 || { echo "scenewright needs Python 3.11 ($(PY) not found); set PY=/path/to/python3.11"; exit 1; }
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip

$(STAMP): $(BIN)/python pyproject.toml
	$(BIN)/pip install -q -e ".[$(EXTRAS)]"
	@touch $(STAMP)

install: $(STAMP)

# Optional extras named by MissingExtra messages (render, batch, sim and studio are already part of the default EXTRAS).
install-render install-clip install-batch install-sim install-studio: install-%: $(STAMP)
	$(BIN)/pip install -q -e ".[$*]"

# Node tools the tests use (the Khronos glTF validator), pinned by tools/package-lock.json.
TOOLS_STAMP := tools/node_modules/.installed
$(TOOLS_STAMP): tools/package.json tools/package-lock.json
	@command -v npm >/dev/null 2>&1 || { echo "the glTF validator needs Node.js >= 18 with npm (https://nodejs.org)"; exit 1; }
	cd tools && npm ci --no-audit --no-fund --loglevel=error
	@touch $(TOOLS_STAMP)

# The studio's browser tests drive Debian's chromium (headless, software GL); apt installs it when missing.
chromium:
	@command -v chromium >/dev/null 2>&1 || { command -v apt-get >/dev/null 2>&1 && apt-get update && apt-get install -y chromium; } \
		|| echo "chromium is not installed and apt-get is unavailable: the studio browser tests will be skipped"

tools: $(TOOLS_STAMP) chromium

# The demo needs only the render extra (Blender for the previews); a full install serves it too.
DEMO_STAMP := $(VENV)/.demo-installed
$(DEMO_STAMP): $(BIN)/python pyproject.toml
	@test -f $(STAMP) || $(BIN)/pip install -q -e ".[render]"
	@touch $(DEMO_STAMP)

demo: $(DEMO_STAMP)
	$(BIN)/scenewright generate --example --out demo-scene --preview default
	@echo "Open demo-scene/scene.glb in Blender (File > Import > glTF 2.0), Godot 4 or Unreal 5."

test: install tools
	$(BIN)/python -m pytest -n 2 -q

bench: install chromium
	@mkdir -p bench-results
	$(BIN)/scenewright bench layout --sizes 15,50,100 --seeds 20 --json | tee bench-results/layout.json
	$(BIN)/scenewright bench layout --hard --seeds 10 --json | tee bench-results/layout-hard.json
	$(BIN)/scenewright bench pipeline --json | tee bench-results/pipeline.json
	$(BIN)/scenewright bench analysis --objects 15 --latency 1 --concurrency 4 --json | tee bench-results/analysis.json
	$(BIN)/scenewright bench eval --out bench-results/eval | tee bench-results/eval.json
	$(BIN)/scenewright bench assets --assets 16 --servers 4 --delay 2 --fault transient --json | tee bench-results/assets.json
	$(BIN)/scenewright bench assets --assets 16 --servers 4 --delay 2 --fault reject --json | tee bench-results/assets-reject.json
	$(BIN)/scenewright bench assets --assets 16 --servers 4 --delay 2 --fault permanent --json | tee bench-results/assets-permanent.json
	$(BIN)/scenewright bench edits --json | tee bench-results/edits.json
	$(BIN)/scenewright bench parse --json | tee bench-results/parse.json
	$(BIN)/scenewright bench constructions --json > bench-results/constructions.json
	for b in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40 41 42 43 44 45 46 47 48 49 50 51 52 53 54 55; do $(BIN)/scenewright bench pipeline --prompts benchmarks/prompts-fresh-$$b --json > bench-results/fresh-$$b.json; done
	$(BIN)/scenewright bench batch --json | tee bench-results/batch.json
	$(BIN)/scenewright bench studio --json | tee bench-results/studio.json
	$(BIN)/scenewright bench physics --json | tee bench-results/physics.json
	$(BIN)/python benchmarks/procedural.py | tee bench-results/procedural.json
	$(BIN)/python benchmarks/speed.py --baseline $(SPEED_BASELINE) --render | tee bench-results/speed.json

clean:
	rm -rf $(VENV) demo-scene bench-results
