# Entry point of the toolkit. `make test` and `make run` work on a fresh Debian machine:
# they install what is missing (make deps), configure, build and run.
BUILD   ?= build
JOBS    ?= $(shell nproc)
PREFIX  ?= /usr/local
OUT     ?= out
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

DEB_PACKAGES := build-essential cmake libeigen3-dev libcgal-dev libgsl-dev libboost-dev \
  libgmp-dev libmpfr-dev catch2 libcli11-dev libfmt-dev gnuplot-nox \
  help2man python3 python3-numpy python3-scipy python3-ase python3-meshio python3-vtk9 \
  python3-matplotlib parallel xvfb xauth slurmd slurmctld slurm-client munge \
  libopenmpi-dev openmpi-bin
# Only make bench needs these (Palabos 1.5 beside lbflow's kernel): tests and the demo never do.
BENCH_PACKAGES := libplb-dev

.PHONY: all deps configure test test-asan bench bench-compare tables jamming-figure percolation-figure jam2d-figures chamber-figures flow-figure shell-figures compress-figures run install clean clean-results

all: configure
	cmake --build $(BUILD) -j $(JOBS)

# Installs the Debian packages the project needs; a no-op when all are present.
deps:
	@scripts/ci/install_debian_packages.sh deps $(DEB_PACKAGES)

configure: $(BUILD)/CMakeCache.txt
$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

# Builds everything and runs every test (Catch2 unit tests, programs as a user runs them,
# interoperability with ASE, meshio and scipy); the last line is "tests: N passed, N failed, N
# skipped" (scripts/ci/run_tests.sh: an entry skipped by its exit status 77 is not a pass).
# EXAMPLES=small|full: the size at which the documentation's examples run (docs/conventions.md).
EXAMPLES ?= small
export EXAMPLES
test: deps all
	@scripts/ci/run_tests.sh $(BUILD)

# The same tests under AddressSanitizer and UBSan (slower; not part of CI).
test-asan: deps
	$(MAKE) test BUILD=build-asan CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMP_SANITIZE=ON"

# libFuzzer on every reader of lib/io (fuzz/): builds $(FUZZ_BUILD) with Debian's clang (ASan,
# UBSan; libclang-rt-14-dev holds libFuzzer for clang 14, installed here when missing, as
# make deps does) and runs each target for FUZZ_SECONDS from the seeds of fuzz/corpus/<reader>
# with fuzz/dict/<reader>.dict. New inputs go to $(FUZZ_BUILD)/corpus, crashes to
# $(FUZZ_BUILD)/artifacts (the run stops at the first).
FUZZ_SECONDS ?= 30
FUZZ_BUILD   ?= build-fuzz
FUZZ_READERS := off xyz csv vtk packing
FUZZ_PACKAGES := clang libclang-rt-14-dev
# Records the hashes of tests/tools/golden_outputs.sh again, in tests/data/golden (every case,
# or GOLDEN_CASES='kcfit lbflow'), for a change that means to change results: its commit says
# why. Never under CI (CI=true refuses, before anything is built); `make test` only reads them.
GOLDEN_CASES ?= $(shell bash tests/tools/golden_outputs.sh --list 2>/dev/null)
.PHONY: golden-record
golden-record:
	@if [ "$${CI:-}" = true ]; then echo "make golden-record: not under CI (CI=true): goldens are recorded by hand and committed" >&2; exit 2; fi
	$(MAKE) all
	@for c in $(GOLDEN_CASES); do \
	  CMP_BIN=$(BUILD)/bin bash tests/tools/golden_outputs.sh --record $$c tests/data/golden/$$c.txt || exit 1; \
	done
	@git diff --stat -- tests/data/golden

.PHONY: fuzz
fuzz:
	@scripts/ci/install_debian_packages.sh fuzz $(FUZZ_PACKAGES)
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMP_FUZZ=ON -DBUILD_TESTING=OFF $(FUZZ_CMAKE_FLAGS)
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_READERS))
	@mkdir -p $(FUZZ_BUILD)/artifacts
	@for r in $(FUZZ_READERS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$r; \
	  echo "make fuzz: $$r for $(FUZZ_SECONDS) s"; \
	  $(FUZZ_BUILD)/fuzz/fuzz_$$r -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    -dict=fuzz/dict/$$r.dict -artifact_prefix=$(FUZZ_BUILD)/artifacts/$$r- \
	    $(FUZZ_BUILD)/corpus/$$r fuzz/corpus/$$r 2>$(FUZZ_BUILD)/fuzz_$$r.log \
	    || { tail -40 $(FUZZ_BUILD)/fuzz_$$r.log; echo "make fuzz: $$r failed (log: $(FUZZ_BUILD)/fuzz_$$r.log)"; exit 1; }; \
	  grep -E '^stat::number_of_executed_units|^Done' $(FUZZ_BUILD)/fuzz_$$r.log | sed "s/^/  $$r: /"; \
	done

# Performance figures for the README's benchmark table (written to $(OUT)/bench/).
# Installs Palabos first and configures again, so that CMake finds it (bench_palabos).
bench: deps
	@scripts/ci/install_debian_packages.sh bench $(BENCH_PACKAGES)
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)
	cmake --build $(BUILD) -j $(JOBS) --target benchmarks
	@scripts/bench/run.sh $(BUILD) $(OUT)/bench

# The kernels (FIRE, labelling, lbflow's sweep, shell forces, jam2d) at commit BEFORE beside this
# checkout's, in alternation, best of ROUNDS: make bench-compare BEFORE=<rev>.
ROUNDS ?= 5
bench-compare: configure
	@scripts/bench/compare_commits.sh $(BEFORE) $(BUILD) $(ROUNDS)

# Tables A.5 and A.6 of the thesis regenerated beside the printed values ($(OUT)/tables/).
tables: deps all
	@mkdir -p $(OUT)/tables
	@scripts/tables/thesis.sh $(BUILD) $(OUT)/tables | tee $(OUT)/tables/tables.md

# Figs S5.1/S5.2: phi_J and Z of 100 jammed packings per N against the thesis ($(OUT)/figures/).
jamming-figure: deps all
	@scripts/figures/jamming.sh $(BUILD) $(OUT)/figures

# Figs B.4-B.10: every shellpack bench-mechanics case beside its analytic curve ($(OUT)/figures/).
shell-figures: deps all
	@scripts/figures/shell.sh $(BUILD) $(OUT)/figures

# Figs 4.3-4.6 at N = 32, 50: shellpack jam -> compress -> analyze -> kcfit (COMPRESS_N, COMPRESS_LEVEL; $(OUT)/figures/).
compress-figures: deps all
	@scripts/figures/compress.sh $(BUILD) $(OUT)/figures

# Fig. 5.2C-D's trend on jammed spheres: shellpack jam -> percolate -> kcfit ($(OUT)/figures/).
percolation-figure: deps all
	@scripts/figures/percolation.sh $(BUILD) $(OUT)/figures

# Chapter 3 at small boxes (jam2d): Figs 3.1h, 3.2a, 3.3, S3.2 and the targets' table ($(OUT)/figures/).
jam2d-figures: deps all
	@scripts/figures/jam2d.sh $(BUILD) $(OUT)/figures
# Chapter 2's chamber (jam2d chamber, avalanches): Figs 2.2b-e, S2.10, S2.11, S2.13, 2.4c and the
# table beside the thesis's numbers, about 20 minutes on 2 cores (TIME, SWEEP_TIME, CHECK_TIME; $(OUT)/figures/).
chamber-figures: deps all
	@scripts/figures/chamber.sh $(BUILD) $(OUT)/figures
# The Chapter 5 chain on inflated jammed spheres: shellpack jam -> percolate -> lbflow -> kcfit,
# kappa and tau_H against porosity with Eq. 5.8 and the tortuosity law, and the refinement M ($(OUT)/figures/).
flow-figure: deps all
	@scripts/figures/flow.sh $(BUILD) $(OUT)/figures

# The demo pipeline (scripts/demo/run.sh): every tool chained, then the study at toy size and its
# report; outputs in $(OUT)/demo/. Builds the programs only, not the tests.
# (demo_tools: rndmesh shellpack percolate lbflow kcfit jam2d, CMakeLists.txt)
run: deps configure
	cmake --build $(BUILD) -j $(JOBS) --target demo_tools
	@scripts/demo/run.sh $(BUILD) $(OUT)/demo

# The thesis's study (Chapters 4-5) as a resumable campaign of files (scripts/study/study.mk):
# STUDY=default|thesis|demo|tiny picks the sizes, and N, SEEDS, VERTICES, PHI, DELTA, FLOW_DELTA,
# REFINE, FLOW_N, FLOW_SEEDS override them; RUN prefixes every recipe (srun on Slurm). Writes
# STUDY_DIR (out/study, out/study-<STUDY>) and its report.html. -j runs tasks in parallel.
# (study_tools: rndmesh shellpack percolate lbflow kcfit, CMakeLists.txt)
STUDY_MAKE = $(MAKE) -f scripts/study/study.mk --no-print-directory BUILD=$(BUILD) OUT=$(OUT)
.PHONY: study study-report study-docs study-jobs study-status study-tools test-slurm
study-tools: deps configure
	cmake --build $(BUILD) -j $(JOBS) --target study_tools >&2
study: study-tools
	+@$(STUDY_MAKE) all
# The report from whatever has finished (tables, fits, figures; the rest says what is missing).
study-report: study-tools
	+@$(STUDY_MAKE) report
# The report, summary and figures copied into docs/study (docs/study-<STUDY>), for a commit.
study-docs:
	@$(STUDY_MAKE) docs
# How far a campaign is: per stage, the targets finished of all, their seconds and the time
# left (CSV; scripts/study/stage_status.sh); builds, runs and writes nothing.
study-status:
	@$(STUDY_MAKE) status
# One stage's commands (STAGE=jam|compress|analyze|percolate|flow), one a line, for GNU parallel
# or a Slurm job array; run the stages in that order, each after the one before has finished.
# (Standard output holds the commands only: the build above reports on standard error.)
study-jobs: study-tools
	@$(STUDY_MAKE) jobs
# The tiny campaign on a single-node Slurm started here (scripts/study/slurm_local.sh), every
# recipe an srun step; also part of make test (tests/tools/study_slurm.sh).
test-slurm: study-tools
	CMP_BIN=$(CURDIR)/$(BUILD)/bin CMP_SRC=$(CURDIR) bash tests/tools/study_slurm.sh campaign_as_job_steps

# Programs into $(DESTDIR)$(PREFIX)/bin, man pages made from their --help into share/man/man1.
install: all
	DESTDIR=$(DESTDIR) cmake --install $(BUILD) --prefix $(PREFIX)
	mkdir -p $(DESTDIR)$(PREFIX)/share/man/man1
	for tool in $(BUILD)/bin/*; do \
	  help2man --no-info --no-discard-stderr --help-option=--help-all "$$tool" > $(DESTDIR)$(PREFIX)/share/man/man1/$$(basename $$tool).1; \
	done

# Removes the builds; results in $(OUT)/ (demo, benchmarks, figures, tables) stay.
clean:
	rm -rf $(BUILD) build-asan

# Removes the results in $(OUT)/ as well: everything make run, bench, tables and the figures wrote.
clean-results:
	rm -rf $(OUT)
