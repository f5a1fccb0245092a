# granmix — convenience front end. `make validate` and `make test` work on a fresh Debian machine:
# both install what is missing (scripts/install-deps.sh) and build first.
BUILD ?= build
JOBS ?= $(shell nproc)
OUT ?= out

.PHONY: deps build test validate figures bench mutants clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null
	@cmake --build $(BUILD) -j$(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

validate: build
	@$(BUILD)/granmix validate --fidelity quick --out $(OUT)

figures: build
	@$(BUILD)/granmix validate --fidelity paper --out $(OUT)/paper

bench: build
	@$(BUILD)/granmix bench --out $(OUT)

# The mutation harness (tests/mutants/, not run by CI): plants each bug of mutants.toml in a scratch
# copy of HEAD, rebuilds, runs validate --fidelity quick and ctest. MUTANTS=id1,id2 runs a subset.
mutants: deps
	@command -v python3 > /dev/null || { echo "make mutants: python3 (3.11+) is needed; scripts/install-deps.sh installs it"; exit 2; }
	JOBS=$(JOBS) nice -n 10 python3 tests/mutants/run_mutants.py

clean:
	rm -rf $(BUILD) $(OUT)
