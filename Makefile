# The two commands of the README (`make` alone is `make demo`):
#   make demo       install missing Debian packages, build (Release, build/), solve the default scenario
#   make test       same set-up, then every test with ctest but those labelled "slow"
#   make test-slow  the "slow" ones: solves run to an external program's time limit,
#                   which a shorter case of the same test covers
# The shared set-up (packages, configure, build) is scripts/setup.sh.
BUILD_DIR ?= build
JOBS ?= 2
DEMO_SCENARIO ?= data/scenarios/geo_week_anzel4.json
DEMO_OUT ?= out/demo

.PHONY: demo test test-slow

demo:
	bash scripts/setup.sh $(BUILD_DIR) $(JOBS)
	bash scripts/demo.sh $(BUILD_DIR) $(DEMO_SCENARIO) $(DEMO_OUT)

test:
	bash scripts/setup.sh $(BUILD_DIR) $(JOBS)
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) -LE slow

test-slow:
	bash scripts/setup.sh $(BUILD_DIR) $(JOBS)
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS) -L slow
