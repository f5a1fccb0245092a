# granmix — convenience front end. `make validate` and `make test` work on a fresh Debian machine:
# both install what is missing (scripts/install-deps.sh) and build first.
BUILD ?= build
JOBS ?= $(shell nproc)
OUT ?= out
# make validate judges the suite at a held-out seed, one no design decision used (docs/validation.md), with its
# confirmation of failures (docs/judging.md §2.1). SEED=1 gives the validation record's tables.
SEED ?= 150
SANITIZE_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 300
# Under the sanitizers: every label but dsmc and slow (the DSMC engine is covered by hard and
# property), plus the fuzz-corpus replay.
SANITIZE_LABELS ?= model|theory|compare|hard|property|fuzz
# The executables those labels run (granmix_tests_dsmc holds [dsmc] tests only: building it under the
# sanitizers cost minutes of CI for no test; ctest lists it as NOT_BUILT, without a label, so -L skips it).
SANITIZE_TARGETS ?= granmix granmix_tests_model granmix_tests_theory granmix_tests_compare granmix_tests_hard \
  granmix_tests_property granmix_tests_bench replay_scene replay_hcs_args replay_tsv_roundtrip replay_checkpoint

.PHONY: deps build test install validate figures bench sanitize fuzz mutants clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null
	@cmake --build $(BUILD) -j$(JOBS)

# ctest runs JOBS tests at once, each with OpenMP threads of its own: more threads than cores, where libgomp's default
# spinning at barriers burns the cores another test needs (v1 Fig. 8-θ4's theory beside two running DSMCs: 70 s, 30 s
# passive). OMP_WAIT_POLICY=passive: the 251 tests outside [slow] take 121 s on 2 cores (130 s spinning).
CTEST_ENV = OMP_WAIT_POLICY=passive

test: build
	cd $(BUILD) && $(CTEST_ENV) ctest --output-on-failure -j$(JOBS)
	@$(MAKE) --no-print-directory install

# The Python module (docs/python.md) where the system's python3 finds it; without the rights to write there, a note.
install: build
	@if [ -d $(BUILD)/python/granmix ]; then \
	  if cmake --install $(BUILD) > /dev/null 2>&1; then \
	    echo "install: the Python module granmix is installed (python3 -c 'import granmix'; docs/python.md)"; scripts/python-path.sh $(BUILD); \
	  else echo "install: the Python module is in $(BUILD)/python (PYTHONPATH=$(BUILD)/python); cmake --install $(BUILD) as root installs it"; fi; \
	else echo "install: no Python module was built (python3-dev, pybind11-dev: scripts/install-deps.sh)"; fi

validate: build
	@$(BUILD)/granmix validate --fidelity quick --seed $(SEED) --out $(OUT)

figures: build
	@$(BUILD)/granmix validate --fidelity paper --out $(OUT)/paper

bench: build
	@$(BUILD)/granmix bench --out $(OUT)

# Address and undefined-behaviour sanitizers (-O1, any finding aborts) in their own build folder; it is
# also the build without MPI (GRANMIX_MPI=OFF), so CI checks both builds. -g1: line tables only, enough for the
# sanitizers' file:line reports, and a faster build than -g.
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
	  -DGRANMIX_SANITIZE=address,undefined -DGRANMIX_MPI=OFF > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j$(JOBS) --target $(SANITIZE_TARGETS)
	cd $(SANITIZE_BUILD) && $(CTEST_ENV) ctest --output-on-failure -j$(JOBS) -L '$(SANITIZE_LABELS)'

# libFuzzer harnesses of tests/fuzz (clang), FUZZ_SECONDS each, one after the other.
fuzz: deps
	@scripts/install-deps.sh --fuzz
	@CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
	  -DGRANMIX_FUZZ=ON > /dev/null
	@cmake --build $(FUZZ_BUILD) -j$(JOBS) --target fuzz_scene fuzz_hcs_args fuzz_tsv_roundtrip fuzz_checkpoint
	@scripts/run-fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The mutation harness (tests/mutants/, not run by CI): plants each bug of mutants.toml in a scratch
# copy of HEAD, rebuilds, runs validate --fidelity quick and ctest. MUTANTS=id1,id2 runs a subset.
mutants: deps
	@command -v python3 > /dev/null || { echo "make mutants: python3 (3.11+) is needed; scripts/install-deps.sh installs it"; exit 2; }
	JOBS=$(JOBS) nice -n 10 python3 tests/mutants/run_mutants.py

clean:
	rm -rf $(BUILD) $(OUT) $(SANITIZE_BUILD) $(FUZZ_BUILD)
