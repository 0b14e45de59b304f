# cagd-repro — every target drives CMake in build/ (Release), turning on what it needs
# (CMake options CAGD_BUILD_TESTS, _EXPERIMENTS, _CLI, _BENCH, _PYTHON; see CMakeLists.txt).
BUILD   ?= build
JOBS    ?= 2
PREFIX  ?= /usr/local
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
# A new build tree uses Ninja when it is installed (install-deps.sh installs it): it compiles a
# target's files while the libraries it links are still being built, which keeps both cores busy.
# A tree configured before keeps the generator it has.
generator_for = $(if $(wildcard $(1)/CMakeCache.txt),,$(if $(shell command -v ninja 2>/dev/null),-G Ninja,))

# What each target needs built.
# Each turns off what its install-deps layer does not provide (tests and benchmarks default to ON
# in a top-level build).
ALL_ON        = -DCAGD_BUILD_TESTS=ON -DCAGD_BUILD_EXPERIMENTS=ON -DCAGD_BUILD_CLI=ON -DCAGD_BUILD_PYTHON=ON
REPRODUCE_ON  = -DCAGD_BUILD_EXPERIMENTS=ON -DCAGD_BUILD_CLI=ON -DCAGD_BUILD_TESTS=OFF -DCAGD_BUILD_BENCH=OFF
BENCH_ON      = -DCAGD_BUILD_BENCH=ON -DCAGD_BUILD_CLI=ON -DCAGD_BUILD_PYTHON=ON -DCAGD_BUILD_TESTS=OFF
PYTHON_ON     = -DCAGD_BUILD_PYTHON=ON -DCAGD_BUILD_TESTS=OFF -DCAGD_BUILD_BENCH=OFF
# make install: the library, its headers, CMake config and pkg-config file, the cagd command and
# the Python package, into $(PREFIX), from a build of its own (no tests, experiments, benchmarks).
INSTALL_FLAGS = -DCAGD_BUILD_TESTS=OFF -DCAGD_BUILD_EXPERIMENTS=OFF -DCAGD_BUILD_BENCH=OFF -DCAGD_BUILD_CLI=ON -DCAGD_BUILD_PYTHON=ON -DCAGD_BUILD_PEERS=OFF

# The harness, the sanitizers and the benchmarks keep their table cache (the pseudo-energy tables
# that the library keeps in the user's cache, core/user_cache.hpp) in the build tree, never in the
# user's ~/.cache/cagd, where ctest's own tests keep it (CMakeLists.txt sets it per test); the one
# build of the space table serves all four. ccache, which the builds inside these targets call,
# keeps its own cache where it would without them (CCACHE_DIR, else $XDG_CACHE_HOME/ccache, else
# ~/.cache/ccache), so that compiled objects are reused across clones.
TABLE_CACHE = CCACHE_DIR="$${CCACHE_DIR:-$${XDG_CACHE_HOME:-$$HOME/.cache}/ccache}" XDG_CACHE_HOME=$(abspath $(BUILD))/cache/user

.PHONY: all deps configure build test reproduce benchmark scorecard bench python install sanitize docs clean web web-serve test-web

all: build

# Each target asks scripts/install-deps.sh for its own layer only (library, python, reproduce,
# test, bench, docs); `make deps` installs every layer.
deps:
	@bash scripts/install-deps.sh

configure:
	@bash scripts/install-deps.sh test
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(ALL_ON) >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j$(JOBS)
	@if command -v emcc >/dev/null 2>&1 && command -v chromium >/dev/null 2>&1; then \
	  $(MAKE) --no-print-directory test-web; \
	else \
	  echo "make test: the browser tests of the viewer (make test-web) are SKIPPED: they need Emscripten and Chromium (scripts/install-deps.sh web)"; \
	fi

# The viewer (web/): the library compiled to WebAssembly with Emscripten into $(WEB_BUILD)/site,
# a static site. Emscripten's JavaScript optimiser needs Debian's acorn, which a Node.js from
# elsewhere (NodeSource) does not search for: NODE_PATH names Debian's folder.
WEB_BUILD ?= build-web
CLI_ONLY  = -DCAGD_BUILD_CLI=ON -DCAGD_BUILD_TESTS=OFF -DCAGD_BUILD_EXPERIMENTS=OFF -DCAGD_BUILD_BENCH=OFF
WEB_FLAGS = -DCAGD_BUILD_WEB=ON -DCAGD_BUILD_TESTS=OFF -DCAGD_BUILD_EXPERIMENTS=OFF -DCAGD_BUILD_CLI=OFF -DCAGD_BUILD_BENCH=OFF -DCAGD_BUILD_PYTHON=OFF -DCAGD_BUILD_PEERS=OFF
# npm ci in folder $(1) once per lockfile (the viewer's tests in web/, the JavaScript peers in peers/).
npm_ci = cd $(1) && (cmp -s package-lock.json node_modules/.cagd-lock 2>/dev/null || (npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.cagd-lock))
web:
	@bash scripts/install-deps.sh web
	@$(call npm_ci,peers)
	@emcmake cmake -S . -B $(WEB_BUILD) $(call generator_for,$(WEB_BUILD)) $(CMAKE_FLAGS) $(WEB_FLAGS) >/dev/null
	@NODE_PATH=/usr/share/nodejs cmake --build $(WEB_BUILD) -j$(JOBS)

# A local server for development: http://127.0.0.1:8080/ (any static host serves the site).
web-serve: web
	@node web/serve.mjs $(WEB_BUILD)/site 8080

# The browser tests: the native command makes the golden files, puppeteer-core (web/package-lock.json)
# drives Debian's Chromium. Output (golden files, exports, the screenshot, frame times) in
# $(WEB_BUILD)/test-output; the frame times also in results/timing/web_frames.csv.
test-web: web
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(if $(wildcard $(BUILD)/CMakeCache.txt),,$(CLI_ONLY)) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS) --target cagd_cli
	@$(call npm_ci,web)
	@mkdir -p results/timing
	@cd web && CAGD_SITE=$(abspath $(WEB_BUILD))/site CAGD_CLI=$(abspath $(BUILD))/cagd CAGD_PEERS=$(abspath peers) CAGD_WEB_OUT=$(abspath $(WEB_BUILD))/test-output \
	  CAGD_FRAME_TIMES=$(abspath results/timing/web_frames.csv) node --test --test-reporter=spec tests/

reproduce:
	@bash scripts/install-deps.sh reproduce
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(REPRODUCE_ON) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS)
	@$(TABLE_CACHE) JOBS=$(JOBS) bash scripts/reproduce.sh $(BUILD)

# What the benchmark and the scorecard run: the command and the peers' programs, with their packages.
define benchmark_build
@bash scripts/install-deps.sh reproduce
@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(REPRODUCE_ON) >/dev/null
@cmake --build $(BUILD) -j$(JOBS) --target cagd_cli cagd_peers
endef

# The interpolant benchmark alone (make reproduce runs it too, without the scorecard): results/benchmark/ and its figures;
# the peers it runs are those installed (scripts/install-deps.sh reproduce installs them all).
benchmark:
	$(benchmark_build)
	@echo "make benchmark: truths, classic data, random sets and peers into results/benchmark/ ..."
	@$(TABLE_CACHE) bash scripts/benchmark.sh $(BUILD) all
	@gnuplot -e "datadir='results/benchmark'" scripts/plot/benchmark_fig_convergence.gp
	@gnuplot -e "datadir='results/benchmark'" scripts/plot/benchmark_fig_scorecard.gp

# The scorecard alone (make benchmark runs it too; make reproduce does not: about half an hour on two
# cores): Levien's properties for every method and peer, results/benchmark/scorecard.* and its figure.
scorecard:
	$(benchmark_build)
	@echo "make scorecard: every method and peer on 10^4 random polygons into results/benchmark/ ..."
	@$(TABLE_CACHE) bash scripts/benchmark.sh $(BUILD) scorecard
	@gnuplot -e "datadir='results/benchmark'" scripts/plot/benchmark_fig_scorecard.gp

bench:
	@bash scripts/install-deps.sh bench
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(BENCH_ON) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS)
	@cmake --build $(BUILD) -j$(JOBS) --target cagd_bench
	@mkdir -p results/timing
	@$(TABLE_CACHE) $(BUILD)/bench/cagd_bench --benchmark_out=results/timing/bench.json --benchmark_out_format=json
	@$(TABLE_CACHE) /usr/bin/python3 scripts/bench-targets.py $(BUILD)  # the interpreter the module is built for, with Debian's scipy

# The Python module alone: then PYTHONPATH=$(BUILD)/python /usr/bin/python3 -c 'import cagd'
python:
	@bash scripts/install-deps.sh python
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(PYTHON_ON) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS) --target cagd_python

install:
	@bash scripts/install-deps.sh python
	@cmake -S . -B $(BUILD)-install $(call generator_for,$(BUILD)-install) $(CMAKE_FLAGS) $(INSTALL_FLAGS) -DCMAKE_INSTALL_PREFIX=$(PREFIX) >/dev/null
	@cmake --build $(BUILD)-install -j$(JOBS)
	@cmake --install $(BUILD)-install

# The Doxygen API reference of the public headers into $(BUILD)/docs/html, and the Sphinx reference
# of the Python module's docstrings into $(BUILD)/docs/python; each fails on any warning.
docs:
	@bash scripts/install-deps.sh docs python
	@bash scripts/docs.sh $(abspath $(BUILD))/docs
	@cmake -S . -B $(BUILD) $(call generator_for,$(BUILD)) $(CMAKE_FLAGS) $(PYTHON_ON) >/dev/null
	@cmake --build $(BUILD) -j$(JOBS) --target cagd_python
	@bash scripts/python-docs.sh $(BUILD)/python $(abspath $(BUILD))/docs/python

# ASan + UBSan tests of the compare modules and a minute of libFuzzer (clang; build-sanitize/).
sanitize:
	@bash scripts/install-deps.sh test
	@$(TABLE_CACHE) JOBS=$(JOBS) bash scripts/sanitize.sh $(CURDIR)/build-sanitize

clean:
	@rm -rf $(BUILD) $(BUILD)-install $(WEB_BUILD) web/node_modules
