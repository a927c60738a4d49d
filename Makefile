# grit's front door. `make demo` and `make test` work on a fresh Debian machine.
BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
# make fuzz: each target searches for FUZZ_SECONDS; FUZZ_RUNS=N instead replays the corpus and runs N
# inputs from seed 1 (deterministic, as CI does).
FUZZ_SECONDS ?= 600
FUZZ_RUNS ?= 0
FUZZ_COVERAGE_BUILD ?= build-fuzz-coverage
JOBS ?= $(shell nproc)
CTEST_ARGS ?=
# PORTABLE=1: a binary without -march=native, for clusters whose nodes are older than the build machine
# (a native binary can stop there with SIGILL). The two differ in the last bits (FMA contraction), so a
# restart is bit-identical only with the build that wrote the checkpoint.
PORTABLE ?= 0
ifeq ($(PORTABLE),1)
NATIVE_FLAG = -DGRIT_NATIVE=OFF
else
NATIVE_FLAG = -DGRIT_NATIVE=ON
endif

PREFIX ?= /usr/local

.PHONY: all deps configure build test test-long test-sanitize fuzz fuzz-coverage demo bench bench-awj install clean

all: build

deps:
	bash scripts/install_deps.sh

configure: deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(NATIVE_FLAG)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j 1 $(CTEST_ARGS)

# The same, with the long forms of the validation tests that CI runs reduced (tests/support/case_fixture.hpp,
# long_tests(): the cantilever over a whole swing).
test-long: build
	GRIT_LONG_TESTS=1 ctest --test-dir $(BUILD) --output-on-failure -j 1 $(CTEST_ARGS)

# Unit tests, and the short whole-case tests (conservation, a checkpoint and restart of every case, the
# grains on a mesh wall and on a copper plate), under AddressSanitizer and UndefinedBehaviorSanitizer.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIT_SANITIZE=ON -DGRIT_BENCH=OFF -DGRIT_PYTHON=OFF \
	  -DGRIT_UNITY_BUILD=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target grit_unit_tests grit_case_tests grit_extension_tests
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS) -L unit
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j 1 -R '^(Conservation\.|CouplingConservation\.(FreeBlob|PeriodicBox)WithGrainsMomentum2D|PackedBed\.|Restart\.EveryCase|Determinism\.(GrainsOnAMeshWall|PeriodicChannel)|GrainImpact\.Momentum)'

# The readers under libFuzzer (fuzz/): the case reader (with --set lines) and the STL reader, built with
# clang, AddressSanitizer and UndefinedBehaviorSanitizer (docs/validation.md, "Reliability").
fuzz: deps
	cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
	  -DCMAKE_C_COMPILER=clang-14 -DGRIT_FUZZ=ON -DGRIT_OPENMP=OFF -DGRIT_TESTS=OFF -DGRIT_BENCH=OFF \
	  -DGRIT_PYTHON=OFF -DGRIT_UNITY_BUILD=ON -DGRIT_NATIVE=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target grit_fuzz_case_reader grit_fuzz_stl
	bash fuzz/run.sh $(FUZZ_BUILD) $(if $(filter-out 0,$(FUZZ_RUNS)),0 $(FUZZ_RUNS),$(FUZZ_SECONDS))

# The readers' line coverage by the seeds and the corpus the last `make fuzz` grew.
fuzz-coverage: deps
	cmake -S . -B $(FUZZ_COVERAGE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
	  -DCMAKE_C_COMPILER=clang-14 -DGRIT_FUZZ=ON -DGRIT_OPENMP=OFF -DGRIT_TESTS=OFF -DGRIT_BENCH=OFF \
	  -DGRIT_PYTHON=OFF -DGRIT_UNITY_BUILD=ON -DGRIT_NATIVE=OFF \
	  -DCMAKE_CXX_FLAGS="-fprofile-instr-generate -fcoverage-mapping" \
	  -DCMAKE_EXE_LINKER_FLAGS="-fprofile-instr-generate"
	cmake --build $(FUZZ_COVERAGE_BUILD) -j $(JOBS) --target grit_fuzz_case_reader grit_fuzz_stl
	bash fuzz/coverage.sh $(FUZZ_COVERAGE_BUILD) $(FUZZ_BUILD)

demo: build
	./$(BUILD)/grit run cases/demo.toml --out output/demo --overwrite
	./$(BUILD)/grit plot output/demo

# The fluid throughput (dam breaks) and the time to crater (the paper's AWJ on copper, projected to 30 ms).
bench: build
	./$(BUILD)/grit_bench --benchmark_counters_tabular=true
	./$(BUILD)/grit_bench_awj --benchmark_counters_tabular=true

bench-awj: build
	./$(BUILD)/grit_bench_awj --benchmark_counters_tabular=true

# The binary, scripts, cases and docs under $(PREFIX) (make install PREFIX=$$HOME/.local for a user install).
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD) $(FUZZ_COVERAGE_BUILD) output
