# springscene: every target does its own set-up (a .venv with the package in editable mode).
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
WIKI   := configs/wiki.toml

.PHONY: setup render figures matter test test-fast lint bench baselines clean system-deps system-deps-chromium fidelity glow

# Which Python made the .venv, and which one $(PYTHON) is: a .venv made by another (a run
# with an older or newer Python, or one whose Python has gone) is removed and made afresh.
PYWHO := import sys; print(sys.base_prefix, *sys.version_info[:3])
WANT  := $(shell $(PYTHON) -c '$(PYWHO)' 2>/dev/null)
HAVE  := $(shell $(BIN)/python -c '$(PYWHO)' 2>/dev/null)
ifneq ($(WANT),$(HAVE))
.PHONY: $(STAMP)
endif

$(STAMP): pyproject.toml
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 10))' 2>/dev/null || { \
	  echo "springscene needs Python 3.10 or newer; $(PYTHON) is" \
	    "$$($(PYTHON) --version 2>&1 || echo missing) (choose one: make PYTHON=python3.12 ...)"; \
	  exit 1; }
	@if [ -e $(VENV) ] && [ "$(WANT)" != "$(HAVE)" ]; then \
	  echo "$(VENV) was made by another Python ($(or $(HAVE),a missing one)); making it" \
	    "afresh with $(PYTHON) ($(WANT))"; rm -rf $(VENV); fi
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

# OSMesa (Debian's libosmesa6) is the second off-screen backend; EGL is on the machine.
# bubblewrap (bwrap) keeps a sandboxed run's program in its room (--sandbox, batch, grade).
# Each installed when missing and apt-get can run (as root); otherwise its tests skip.
system-deps:
	@if ! ldconfig -p 2>/dev/null | grep -q 'libOSMesa.so'; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing libosmesa6"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libosmesa6 >/dev/null) \
	      || echo "could not install libosmesa6: OSMesa tests will skip"; \
	  else echo "libosmesa6 not installed: OSMesa tests will skip"; fi; \
	fi
	@if ! command -v bwrap >/dev/null; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing bubblewrap"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq bubblewrap >/dev/null) \
	      || echo "could not install bubblewrap: the sandbox tests will skip"; \
	  else echo "bubblewrap not installed: the sandbox tests will skip"; fi; \
	fi

# Headless Chromium (Debian's chromium and chromium-driver) opens the interactive page in
# its tests (tests/vpython/test_interactive_page.py) and draws real VPython (make fidelity):
# installed when missing and apt-get can run as root; otherwise those tests skip (CI, with
# SPRINGSCENE_REQUIRE_BACKENDS=1, fails instead).
system-deps-chromium:
	@if ! command -v chromium >/dev/null || [ ! -x /usr/bin/chromedriver ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing chromium and chromium-driver"; \
	    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
	      chromium chromium-driver >/dev/null) \
	      || echo "could not install chromium: the interactive page's browser tests will skip"; \
	  else echo "chromium and chromium-driver are missing: the interactive page's browser" \
	    "tests will skip"; fi; \
	fi

# GlowScript's library (VPython 7.6.5's glow.min.js, jQuery, jQuery UI and the MIT licence)
# for the interactive page, fetched once into the cache (pip download of the vpython wheel,
# checked by SHA-256), so the tests and later runs need no network; README "The interactive
# page"
glow: $(STAMP)
	@$(BIN)/python -m springscene.vpython.page.glow_library \
	  || echo "the interactive page's tests will skip (or fail with SPRINGSCENE_REQUIRE_BACKENDS)"

setup: $(STAMP) system-deps system-deps-chromium glow

render: setup
	@mkdir -p renders/wiki
	$(BIN)/springscene render $(WIKI) --out renders/wiki/oscillation.mp4
	$(BIN)/springscene still $(WIKI) --time 0 --out renders/wiki/still.png

figures: setup
	$(BIN)/springscene figures $(WIKI) --out renders/wiki/

# the ball-and-spring model of matter: videos of a chain of aluminium atoms carrying a
# sound pulse, a crystal at 300 K and a bar pulled; stills and measured figures
matter: setup
	@mkdir -p renders/matter
	$(BIN)/springscene render configs/chain-aluminum.toml --out renders/matter/chain-aluminum.mp4
	$(BIN)/springscene render configs/crystal.toml --out renders/matter/crystal.mp4
	$(BIN)/springscene render configs/bar.toml --out renders/matter/bar.mp4
	for c in chain chain-aluminum chain-lead crystal bar; do \
	  $(BIN)/springscene figures configs/$$c.toml --out renders/matter/$$c/ || exit 1; done
	$(BIN)/springscene still configs/chain.toml --time 1 --out renders/matter/chain/still.png
	$(BIN)/springscene still configs/chain-aluminum.toml --time 3e-12 --out renders/matter/chain-aluminum/still.png
	$(BIN)/springscene still configs/crystal.toml --time 1e-12 --out renders/matter/crystal/still.png
	$(BIN)/springscene still configs/bar.toml --time 8e-12 --out renders/matter/bar/still.png

test: setup
	$(BIN)/python -m pytest --durations=25

# the fast tier: every test not marked slow (tests/conftest.py's rules), every layer, under a
# minute; `make test` runs the slow ones too
test-fast: setup
	$(BIN)/python -m pytest -m "not slow" --durations=10

# the layers (docs/architecture.md): import-linter's contracts and ruff's import rules;
# tests/test_architecture.py runs the same in `make test`
lint: setup
	$(BIN)/lint-imports
	$(BIN)/ruff check springscene

bench: setup
	$(BIN)/python benchmarks/bench_render.py
	$(BIN)/python benchmarks/bench_physics.py
	$(BIN)/python benchmarks/bench_vpython.py
	$(BIN)/python benchmarks/bench_matter.py
	$(BIN)/python benchmarks/bench_matter_render.py
	$(BIN)/python benchmarks/bench_recording.py
	$(BIN)/python benchmarks/bench_raycast.py
	$(BIN)/python benchmarks/bench_batch.py

baselines: setup
	$(BIN)/python -m pytest tests/view tests/figures tests/vpython --regen-baselines

# springscene against real VPython (docs/fidelity.md): real VPython 7 draws in headless
# Chromium (Debian's chromium and chromium-driver, installed when missing and apt-get can run
# as root) from a separate venv; its pictures are kept in tests/baselines/fidelity/ and taken
# again only with FIDELITY_ARGS=--update-reference
FIDELITY_VENV := .fidelity-venv
FIDELITY_ARGS ?=
$(FIDELITY_VENV)/.installed:
	$(PYTHON) -m venv $(FIDELITY_VENV)
	$(FIDELITY_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(FIDELITY_VENV)/bin/python -m pip install --quiet vpython==7.6.5 selenium==4.51.0 \
	  numpy==2.4.6 pillow==13.0.0
	touch $@

fidelity: setup $(FIDELITY_VENV)/.installed
	$(BIN)/python benchmarks/fidelity/run.py --python $(FIDELITY_VENV)/bin/python $(FIDELITY_ARGS)

clean:
	rm -rf $(VENV) build *.egg-info renders/wiki/oscillation.mp4 renders/wiki/still.png
