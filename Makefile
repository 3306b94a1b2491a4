# Thin wrapper over CMake + Ninja. The README's two commands:
#   make run    build Release and open the GUI on the bundled example
#               (with no display: write out/example.iv and out/example.png)
#   make test   build with AddressSanitizer + UBSan and run every test under xvfb-run (the
#               layer and format checks among them), run clang-tidy over the sources, then
#               build the io and manifest libFuzzer targets with clang and run each for FUZZ_SECONDS
BUILD_RELEASE ?= build/release
BUILD_ASAN    ?= build/asan
BUILD_TSAN    ?= build/tsan
CMAKE_FLAGS   ?=
FUZZ_SECONDS  ?= 60

.PHONY: all run test deps release asan tsan tsan-test fuzz bench clean

all: release

deps:
	@scripts/install-deps.sh

release: deps
	cmake -S . -B $(BUILD_RELEASE) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)
	cmake --build $(BUILD_RELEASE)

run: release
	$(BUILD_RELEASE)/app/caliper3d

asan: deps
	cmake -S . -B $(BUILD_ASAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCALIPER3D_SANITIZE=ON -DCALIPER3D_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(BUILD_ASAN)

test: asan
	scripts/run-tests.sh $(BUILD_ASAN)
	scripts/check-tidy.sh $(BUILD_ASAN)
	scripts/run-fuzzers.sh $(FUZZ_SECONDS)

# The fuzz half of `make test` alone.
fuzz: deps
	scripts/run-fuzzers.sh $(FUZZ_SECONDS)

tsan: deps
	cmake -S . -B $(BUILD_TSAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCALIPER3D_TSAN=ON -DCALIPER3D_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build $(BUILD_TSAN)

tsan-test: tsan
	TSAN_OPTIONS="suppressions=$(CURDIR)/tests/tsan.supp" scripts/run-tests.sh $(BUILD_TSAN)

bench: release
	@echo "benchmarks are in $(BUILD_RELEASE)/bench"

clean:
	rm -rf build out
