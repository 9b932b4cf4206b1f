# Entry point of the toolkit. `make test` and `make run` work on a fresh Debian machine:
# they install what is missing (make deps), configure, build and run.
BUILD   ?= build
JOBS    ?= $(shell nproc)
PREFIX  ?= /usr/local
OUT     ?= out
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

DEB_PACKAGES := build-essential cmake libeigen3-dev libcgal-dev libgsl-dev libboost-dev \
  libgmp-dev libmpfr-dev catch2 libcli11-dev libfmt-dev gnuplot-nox \
  help2man python3 python3-numpy python3-scipy python3-ase python3-meshio python3-vtk9

.PHONY: all deps configure test test-asan bench tables jamming-figure percolation-figure run install clean

all: configure
	cmake --build $(BUILD) -j $(JOBS)

# Installs the Debian packages the project needs; a no-op when all are present.
deps:
	@missing=""; for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing$$missing"; \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

configure: $(BUILD)/CMakeCache.txt
$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

# Builds everything and runs every test (Catch2 unit tests, programs as a user runs them,
# interoperability with ASE, meshio and scipy); the last line is "N passed, N failed".
test: deps all
	@scripts/run_tests.sh $(BUILD)

# The same tests under AddressSanitizer and UBSan (slower; not part of CI).
test-asan: deps
	$(MAKE) test BUILD=build-asan CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMP_SANITIZE=ON"

# Performance figures for the README's benchmark table (written to $(OUT)/bench/).
bench: deps all
	@scripts/bench.sh $(BUILD) $(OUT)/bench

# Tables A.5 and A.6 of the thesis regenerated beside the printed values ($(OUT)/tables/).
tables: deps all
	@scripts/thesis_tables.sh $(BUILD) $(OUT)/tables | tee $(OUT)/tables/tables.md

# Figs S5.1/S5.2: phi_J and Z of 100 jammed packings per N against the thesis ($(OUT)/figures/).
jamming-figure: deps all
	@scripts/jamming_figure.sh $(BUILD) $(OUT)/figures

# Fig. 5.2C-D's trend on jammed spheres: shellpack jam -> percolate -> kcfit ($(OUT)/figures/).
percolation-figure: deps all
	@scripts/percolation_figure.sh $(BUILD) $(OUT)/figures

# The demo pipeline of DESIGN.md with every tool that exists so far.
run: deps all
	@scripts/demo.sh $(BUILD) $(OUT)/demo

# Programs into $(DESTDIR)$(PREFIX)/bin, man pages made from their --help into share/man/man1.
install: all
	DESTDIR=$(DESTDIR) cmake --install $(BUILD) --prefix $(PREFIX)
	mkdir -p $(DESTDIR)$(PREFIX)/share/man/man1
	for tool in $(BUILD)/bin/*; do \
	  help2man --no-info --no-discard-stderr --help-option=--help-all "$$tool" > $(DESTDIR)$(PREFIX)/share/man/man1/$$(basename $$tool).1; \
	done

clean:
	rm -rf $(BUILD) build-asan $(OUT)
