# Thin wrapper around CMake (in the style of Neovim's): `make demo` and `make test` are the
# two commands of the README's quick start. Each installs missing Debian packages first.
# `make demo` (and `make build`) installs only what the executable and its plugins need and builds
# only them (the CMake target gearkit_runtime), so that a fresh machine's first result waits for no
# test (issue 26); `make test` then adds the test-only packages and targets to the same build tree.
BUILD_DIR     ?= build
BUILD_TYPE    ?= Release
JOBS          ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS   ?=
DEMO_DIR      ?= gearkit-demo

.PHONY: all deps deps-test configure configure-test build build-all demo test test-sanitize bench install \
        clean fuzz

all: build

deps:
	@./scripts/setup-deps.sh

deps-test:
	@./scripts/setup-deps.sh --test

# A new build tree is configured with Ninja when it is there (the generator is looked up when the
# recipe runs: on a fresh machine the packages come in after make has read this file) and without
# the tests; an existing tree keeps its generator and its settings.
define configure_tree
	@if [ ! -f $(BUILD_DIR)/CMakeCache.txt ]; then \
	  cmake -S . -B $(BUILD_DIR) $$(command -v ninja >/dev/null 2>&1 && echo "-G Ninja") \
	    -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DGEARKIT_BUILD_TESTS=$(1) $(CMAKE_FLAGS); \
	elif [ "$(1)" = ON ] && ! grep -q '^GEARKIT_BUILD_TESTS:BOOL=ON$$' $(BUILD_DIR)/CMakeCache.txt; then \
	  cmake -S . -B $(BUILD_DIR) -DGEARKIT_BUILD_TESTS=ON $(CMAKE_FLAGS); \
	fi
endef

configure: deps
	$(call configure_tree,OFF)

configure-test: deps-test
	$(call configure_tree,ON)

# The executable, its plugins and modules, and every library: nothing of the tests.
build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target gearkit_runtime

# Everything, the tests included.
build-all: configure-test
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	$(BUILD_DIR)/bin/gearkit demo --output $(DEMO_DIR)

test: build-all
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

# The CI's second configuration: AddressSanitizer + UndefinedBehaviorSanitizer, warnings as errors.
# -O1 -g1 (line tables only) instead of RelWithDebInfo's -O2 -g: the sanitizer build took 55 of
# CI's 74 minutes on 2 cores, and full debug info of Eigen/yaml-cpp/gtest templates was most of it
# (measured per TU: 21-26 s at -O2 -g, 8-19 s at -O1 -g1); ASan reports keep file:line.
test-sanitize:
	$(MAKE) test BUILD_DIR=build-sanitize BUILD_TYPE=RelWithDebInfo \
	  CMAKE_FLAGS="-DGEARKIT_SANITIZE=ON -DGEARKIT_WERROR=ON -DCMAKE_CXX_FLAGS_RELWITHDEBINFO='-O1 -g1 -DNDEBUG'"

# Mutation fuzzing of the gearkit executable (tests/fuzz/fuzz.py): N cases from seed SEED, with
# the past crashers of tests/fuzz/corpus; failing cases are saved in FUZZ_SAVE (corpus format).
N         ?= 2000
SEED      ?= 1
FUZZ_SAVE ?= fuzz-failures
fuzz: build deps-test
	python3 tests/fuzz/fuzz.py --exe $(BUILD_DIR)/bin/gearkit --cases $(N) --seed $(SEED) --jobs $(JOBS) \
	  --save $(FUZZ_SAVE)

bench:
	@./scripts/setup-deps.sh --bench
	cmake -S . -B build-bench $$([ -f build-bench/CMakeCache.txt ] || ! command -v ninja >/dev/null || echo "-G Ninja") \
	  -DCMAKE_BUILD_TYPE=Release -DGEARKIT_BUILD_BENCH=ON -DGEARKIT_BUILD_TESTS=OFF
	cmake --build build-bench -j $(JOBS)

install: build
	cmake --install $(BUILD_DIR) $(if $(PREFIX),--prefix $(PREFIX))

clean:
	rm -rf $(BUILD_DIR) build-sanitize build-bench
