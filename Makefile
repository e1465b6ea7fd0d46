# flotsam: every target installs what it needs first (Debian 12, root or sudo).
#   make demo   build and run the paper's bridge case into out/
#   make test   build and run the whole test suite (CTest)
#   make bench  build and run the benchmarks (figures go to docs/performance.md)
#   make test-fuzz  fuzz the case, mesh, raster and vector readers for FUZZ_SECONDS each (libFuzzer)
#   make test-qgis  open a run's UGRID and GeoPackage results in QGIS itself (python3-qgis)

BUILD     ?= build
SAN_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= case mesh raster vector
JOBS      ?= $(shell nproc)
CI        ?=
SUDO      := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

PACKAGES := g++ cmake ninja-build ccache pkg-config python3 python3-vtk9 clang-format \
            libeigen3-dev libsuitesparse-dev libgmsh-dev libyaml-cpp-dev libcli11-dev \
            libfmt-dev libspdlog-dev libgtest-dev libgmock-dev libbenchmark-dev libcairo2-dev \
            libmuparser-dev libgdal-dev libopenblas0-openmp time python3-gdal python3-numpy \
            libopenmpi-dev openmpi-bin valgrind clang lld libclang-rt-14-dev libbox2d-dev \
            libxxhash-dev libnetcdf-dev netcdf-bin python3-netcdf4 python3-xarray libmetis-dev

# QGIS (its Python bindings and MDAL provider, ~620 MB) only for `make test-qgis`.
QGIS_PACKAGES := python3-qgis

CMAKE_FLAGS := -G Ninja -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
               $(if $(CI),-DFLOTSAM_WERROR=ON -DFLOTSAM_VALIDATE=ON,)

.PHONY: all deps qgis-deps bench-deps build test test-sanitize test-slow test-fuzz test-qgis demo bench format \
        format-check clean

all: build

# $(call install_missing,PACKAGES): apt-get installs those of PACKAGES that are not installed.
define install_missing
	@missing=$$(for p in $(1); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	    echo "installing:" $$missing; \
	    $(SUDO) apt-get update -qq && \
	    DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing >/dev/null; \
	fi
endef

deps:
	$(call install_missing,$(PACKAGES))

qgis-deps:
	$(call install_missing,$(QGIS_PACKAGES))

$(BUILD)/build.ninja: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) -LE 'slow|qgis' --output-on-failure -j $(JOBS)

# The results opened in QGIS (tests/scripts/results.cmake, label qgis) and the run they read.
test-qgis: build qgis-deps
	ctest --test-dir $(BUILD) -L 'qgis' --output-on-failure -j $(JOBS)

test-slow: build
	ctest --test-dir $(BUILD) -L slow --output-on-failure

test-sanitize: deps
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
	    -DFLOTSAM_SANITIZE=ON $(CMAKE_FLAGS)
	cmake --build $(SAN_BUILD) -j $(JOBS) --target unit_tests
	LSAN_OPTIONS=suppressions=$(CURDIR)/cmake/lsan.supp \
	    ctest --test-dir $(SAN_BUILD) -L unit --output-on-failure -j $(JOBS)

# Fuzzing (tests/fuzz): the case, mesh, raster and vector readers under libFuzzer and AddressSanitizer,
# FUZZ_SECONDS each, mutating the corpus in tests/fuzz/corpus; new inputs go to
# $(FUZZ_BUILD)/corpus, and an input that crashes is saved as $(FUZZ_BUILD)/crash-* (add it to
# the corpus once fixed).
test-fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-g1 -O1 -DNDEBUG" -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DFLOTSAM_FUZZ=ON
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(FUZZ_TARGETS:%=fuzz_%_reader)
	@for t in $(FUZZ_TARGETS); do mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	    echo "== fuzzing the $$t reader for $(FUZZ_SECONDS) s"; \
	    ASAN_OPTIONS=detect_leaks=0 $(FUZZ_BUILD)/tests/fuzz/fuzz_$${t}_reader \
	    $(FUZZ_BUILD)/corpus/$$t tests/fuzz/corpus/$$t -max_total_time=$(FUZZ_SECONDS) \
	    -timeout=20 -rss_limit_mb=4096 -artifact_prefix=$(FUZZ_BUILD)/ -print_final_stats=1 \
	    || exit 1; done

# The paper's bridge case, run and drawn into out/bridge_piers/. The demo replaces its own
# earlier results there (--overwrite); nothing else in out/ is touched.
demo: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS) --target flotsam  # only the program, not the tests
	$(BUILD)/flotsam mesh examples/bridge_piers.yaml -o out/bridge_piers.msh \
	    --vtu out/bridge_piers_mesh.vtu --overwrite
	$(BUILD)/flotsam run examples/bridge_piers.yaml --overwrite
	$(BUILD)/flotsam render out/bridge_piers

# Benchmarks: the Google Benchmark programs in bench/, the contacts against Box2D (about 3 minutes),
# the flow engines' timed harnesses (about 5 minutes, most of it the FEM's hour of the paper's
# channel), then timed runs of the examples, the two bridge cases also with the finite-volume
# engine (results under build/bench_runs/, replaced each time). Figures go to docs/performance.md.
# Debian's Gerris for the side-by-side of make bench (its expressions compile against its headers).
BENCH_PACKAGES := gerris libgfs-dev

bench-deps:
	$(call install_missing,$(BENCH_PACKAGES))

bench: build bench-deps
	cmake --build $(BUILD) -j $(JOBS) --target benchmarks
	@for b in $(BUILD)/bench/bench_*; do \
	    case $$b in */bench_flow_channel|*/bench_fv_dam_break|*/bench_contacts_vs_box2d) continue;; esac; \
	    echo "== $$b"; $$b --benchmark_min_time=0.5; done
	@echo "== contacts against Box2D (docs/performance.md): both solvers at 1k and 10k logs, the soft"
	@echo "   step at 50k; ratios flotsam / Box2D from the same run"
	$(BUILD)/bench/bench_contacts_vs_box2d 1000 10000
	$(BUILD)/bench/bench_contacts_vs_box2d 50000 --no-sequential
	@echo "== FEM engine (docs/performance.md): time per step (the case's segregated step with its"
	@echo "   mixing length; the coupled step without it), steady mode at Re = 20 and at the case's"
	@echo "   Re = 1000, 1 h at dt = 1 s with both steps"
	$(BUILD)/bench/bench_flow_channel scaling 14.5 40 1
	FLOTSAM_FLOW_SCHEME=coupled FLOTSAM_FLOW_TURBULENCE=none $(BUILD)/bench/bench_flow_channel scaling 14.5 40 1
	$(BUILD)/bench/bench_flow_channel scaling 3.7 10 1
	FLOTSAM_FLOW_SCHEME=coupled FLOTSAM_FLOW_TURBULENCE=none $(BUILD)/bench/bench_flow_channel scaling 3.7 10 1
	FLOTSAM_FLOW_TURBULENCE=none $(BUILD)/bench/bench_flow_channel steady 0 1.5
	$(BUILD)/bench/bench_flow_channel steady
	$(BUILD)/bench/bench_flow_channel unsteady 1 3600
	FLOTSAM_FLOW_SCHEME=coupled FLOTSAM_FLOW_TURBULENCE=none $(BUILD)/bench/bench_flow_channel unsteady 1 3600
	@echo "== finite-volume engine: triangle-steps per second at 50k, 500k and 2M triangles"
	OMP_WAIT_POLICY=PASSIVE $(BUILD)/bench/bench_fv_dam_break
	@mkdir -p $(BUILD)/bench_runs
	@for c in bridge_piers bridge_flood; do \
	    sed 's/^flow:/flow:\n  engine: fv/; s/^name: .*/name: '$$c'_fv/; /^  scheme: /d; /^  turbulence: /d' \
	    examples/$$c.yaml \
	    > $(BUILD)/bench_runs/$${c}_fv.yaml; done
	@echo "== the circular dam break on a Gmsh mesh (bench/circular_dam_break.yaml, 256,988 cells):"
	@echo "   meshing (flotsam info) and the flow on 1 and 2 threads: cell updates per flow second"
	/usr/bin/time -f "meshing: %e s" $(BUILD)/flotsam info bench/circular_dam_break.yaml | grep quality
	@for t in 1 2 1 2; do OMP_NUM_THREADS=$$t $(BUILD)/flotsam run bench/circular_dam_break.yaml \
	    -o $(BUILD)/bench_runs/circular --overwrite -q --fixed-threads | \
	    sed -n 's/.* \([0-9.e+]*\) cell updates.*/'"$$t"' thread(s): \1 cell updates/p; s/^wall time *flow \([0-9.]*\) s.*/   flow \1 s/p'; done
	@echo "== Gerris (Debian's gerris2D) on the same basin, 262,144 cells, 0.2 s, 1 core"
	cd $(BUILD)/bench_runs && gerris2D $(CURDIR)/bench/circular_dam_break.gfs | grep "Timing summary"
	@echo "== shared machines (docs/performance.md): bridge_piers beside a busy core, two runs at once"
	bench/shared_machine.sh $(BUILD) 3
	@echo "== ensemble examples/bridge_blocking.yaml on 1 job (12 members per length) and on 2 jobs"
	@echo "   (all 96): members per minute, the shared flow, set-up and output per member"
	@echo "   (docs/performance.md, Ensembles). Into new folders: the last results are moved"
	@echo "   aside and deleted after the runs (files made just after a mass deletion are slow here)"
	@for j in 1 2; do rm -rf $(BUILD)/bench_runs/bridge_blocking_$$j.old; \
	    [ ! -e $(BUILD)/bench_runs/bridge_blocking_$$j ] || mv $(BUILD)/bench_runs/bridge_blocking_$$j \
	    $(BUILD)/bench_runs/bridge_blocking_$$j.old; done
	@for j in 1 2; do m=$$([ $$j = 1 ] && echo 12 || echo 96); \
	    OMP_NUM_THREADS=1 /usr/bin/time -f "bridge_blocking ensemble, $$j job(s): %e s wall, %U s user" \
	    $(BUILD)/flotsam ensemble examples/bridge_blocking.yaml -o $(BUILD)/bench_runs/bridge_blocking_$$j \
	    --members $$m --jobs $$j -q --no-pictures \
	    | grep -E "^ensemble|^members|^flow|wall time"; done
	@rm -rf $(BUILD)/bench_runs/bridge_blocking_1.old $(BUILD)/bench_runs/bridge_blocking_2.old
	@echo "== the town's road bridge with and without its deck (examples/town_flood, first 20"
	@echo "   minutes, run twice each, alternated): the flow stage (docs/performance.md, Bridges)"
	@mkdir -p $(BUILD)/bench_runs/town
	@/usr/bin/python3 examples/town_flood/make_inputs.py --out $(BUILD)/bench_runs/town/data > /dev/null
	@cp examples/town_flood/town_flood.yaml $(BUILD)/bench_runs/town/town_deck.yaml
	@sed '/^    deck: /d' examples/town_flood/town_flood.yaml > $(BUILD)/bench_runs/town/town_no_deck.yaml
	@for c in town_no_deck town_deck town_no_deck town_deck; do echo "$$c:"; \
	    $(BUILD)/flotsam run $(BUILD)/bench_runs/town/$$c.yaml -o $(BUILD)/bench_runs/town/$$c \
	    --end 1200 --overwrite -q | grep -E "finite volumes|wall time"; done
	@echo "== local time stepping (docs/performance.md): examples/town_flood (30 minutes) and"
	@echo "   bridge_piers with engine: fv (600 s), flow.fv.time_levels 1 and auto (3), alternated twice"
	@sed 's/^  engine: fv/  engine: fv\n  fv: {time_levels: 1}/' examples/town_flood/town_flood.yaml \
	    > $(BUILD)/bench_runs/town/town_one_level.yaml
	@sed 's/^  engine: fv/  engine: fv\n  fv: {time_levels: 1}/' $(BUILD)/bench_runs/bridge_piers_fv.yaml \
	    > $(BUILD)/bench_runs/bridge_piers_fv_one_level.yaml
	@for r in 1 2; do for c in town/town_one_level:1800 town/town_deck:1800 \
	    bridge_piers_fv_one_level:600 bridge_piers_fv:600; do f=$${c%%:*}; echo "$$f:"; \
	    $(BUILD)/flotsam run $(BUILD)/bench_runs/$$f.yaml -o $(BUILD)/bench_runs/levels_$$(basename $$f) \
	    --end $${c##*:} --overwrite -q | grep -E "finite volumes|wall time"; done; done
	@for c in examples/bridge_piers.yaml examples/bridge_flood.yaml \
	          $(BUILD)/bench_runs/bridge_piers_fv.yaml $(BUILD)/bench_runs/bridge_flood_fv.yaml \
	          examples/dam_break_valley.yaml; do \
	    n=$$(basename $$c .yaml); echo "== flotsam run $$c"; \
	    /usr/bin/time -f "$$n: %e s wall, %U s user, %M KiB peak" \
	    $(BUILD)/flotsam run $$c -o $(BUILD)/bench_runs/$$n --overwrite -q \
	    | grep -E "simulated|finite volumes|wall time"; done

format: deps
	find src tests bench -name '*.[ch]pp' | xargs clang-format -i

format-check: deps
	find src tests bench -name '*.[ch]pp' | xargs clang-format --dry-run -Werror

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(FUZZ_BUILD)
