# granmix — convenience front end. `make validate` and `make test` work on a fresh Debian machine:
# both install what is missing (scripts/install-deps.sh) and build first.
BUILD ?= build
JOBS ?= $(shell nproc)
OUT ?= out

.PHONY: deps build test validate figures bench clean

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

clean:
	rm -rf $(BUILD) $(OUT)
