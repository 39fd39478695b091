# The two commands of the README:
#   make demo   install missing Debian packages, build (Release, build/), solve the default scenario
#   make test   same set-up, then run every test with ctest
# Internal helper targets (deps, build) are used by both.
BUILD_DIR ?= build
JOBS ?= 2
DEMO_SCENARIO ?= data/scenarios/geo_week_anzel4.json
DEMO_OUT ?= out/demo

.PHONY: demo test deps build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	bash scripts/demo.sh $(BUILD_DIR) $(DEMO_SCENARIO) $(DEMO_OUT)

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)
