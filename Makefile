# cagd-repro — every target drives CMake in build/ (Release).
BUILD   ?= build
JOBS    ?= 2
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build test reproduce bench sanitize clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

reproduce: build
	@JOBS=$(JOBS) bash scripts/reproduce.sh $(BUILD)

bench: build
	@cmake --build $(BUILD) -j$(JOBS) --target cagd_bench
	@mkdir -p results/timing
	@$(BUILD)/bench/cagd_bench --benchmark_out=results/timing/bench.json --benchmark_out_format=json
	@python3 scripts/bench-targets.py $(BUILD)

# ASan + UBSan tests of the compare modules and a minute of libFuzzer (clang; build-sanitize/).
sanitize: deps
	@JOBS=$(JOBS) bash scripts/sanitize.sh $(CURDIR)/build-sanitize

clean:
	@rm -rf $(BUILD)
