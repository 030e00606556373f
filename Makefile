# Silva — top-level commands. See README.md.
BUILD      ?= build
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
SILVA      := $(BUILD)/silva
# Each target that configures $(BUILD) says whether it builds the tests and the benchmarks, so the
# CLI alone configures (and builds) without GTest or Google Benchmark installed.
CONFIGURE   = cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

.PHONY: deps deps-test configure build cli run test bench sanitize tidy fuzz test-slurm clean

## make deps: the packages building and running the CLI needs; make deps-test: those and the test tools
deps:
	@bash scripts/install-deps.sh

deps-test:
	@bash scripts/install-deps.sh --test

configure: deps-test
	@$(CONFIGURE) -DSILVA_BUILD_TESTS=ON -DSILVA_BUILD_BENCH=ON $(CMAKE_ARGS) >/dev/null

## make build: every target (the CLI, the asset library, the tests and the benchmarks)
build: configure
	@cmake --build $(BUILD) -j $(JOBS)

## make cli: only the silva CLI (its post-build step generates the asset library); no test or benchmark,
## and none of the packages only they need
cli: deps
	@$(CONFIGURE) -DSILVA_BUILD_TESTS=OFF -DSILVA_BUILD_BENCH=OFF $(CMAKE_ARGS) >/dev/null
	@cmake --build $(BUILD) --target silva -j $(JOBS)

## make run: build the Release CLI only and generate the demo dataset of configs/demo.toml into ./out/
run: cli
	$(SILVA) generate --config configs/demo.toml --overwrite
	@echo "The demo dataset is in out/1234567890/ (rgb/, semantic/, depth/, ... per sequence; see README.md)."
	@echo "The full thesis default is '$(SILVA) generate': 790 captures at 1920x1080, several GB."

## make test: build and run every test
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

## make bench: the end-to-end benchmark harness, ~20 min on 2 cores (writes bench/results/<date>-<cpu>-bench.json,
## a markdown report and charts; see bench/README.md). BENCH_ARGS=--quick for the ~3-minute subset.
bench:
	@bash scripts/install-deps.sh --bench
	@$(CONFIGURE) -DSILVA_BUILD_TESTS=OFF -DSILVA_BUILD_BENCH=ON $(CMAKE_ARGS) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)
	$(SILVA) bench $(BENCH_ARGS)

## make sanitize: ASan + UBSan build (optimised, so the rendering tests stay quick) running every test
sanitize: deps-test
	@cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Release -DSILVA_SANITIZE=ON -DSILVA_BUILD_TESTS=ON -DSILVA_BUILD_BENCH=OFF >/dev/null
	@cmake --build build-sanitize -j $(JOBS)
	cd build-sanitize && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS)

## make tidy: clang-tidy (checks in .clang-tidy) over the library and app sources; configures
## its own folder (no compile needed, only compile_commands.json)
tidy:
	@bash scripts/install-deps.sh --tidy
	@cmake -S . -B build-tidy -DCMAKE_BUILD_TYPE=Release -DSILVA_BUILD_TESTS=OFF -DSILVA_BUILD_BENCH=OFF >/dev/null
	bash scripts/tidy.sh build-tidy $(JOBS)

## make fuzz: the libFuzzer harnesses of every input reader (clang-14, ASan + UBSan, docs/fuzzing.md),
## each run FUZZ_SECONDS (default 600) from its seed corpus; a crash leaves its input in build-fuzz/crashes/
FUZZ_SECONDS ?= 600
fuzz:
	@bash scripts/install-deps.sh --fuzz
	@CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" -DSILVA_FUZZ=ON \
		-DSILVA_BUILD_TESTS=OFF -DSILVA_BUILD_BENCH=OFF >/dev/null
	@cmake --build build-fuzz --target fuzz_harnesses -j $(JOBS)
	bash scripts/fuzz.sh build-fuzz $(FUZZ_SECONDS)

## make test-slurm: a throw-away single-node Slurm cluster here (root or sudo); checks that a
## 2-shard job array + silva merge equals a single-process run byte for byte
test-slurm: cli
	SILVA=$(SILVA) bash scripts/test-slurm.sh

clean:
	rm -rf $(BUILD) build-sanitize build-tidy build-fuzz
