# noiselab: `make` builds bin/noiselab, build/libnoiselab.a and the shared
# library; `make test` runs the tests; `make figures` reproduces the paper
# figures; `make course` runs and renders the course's notebooks;
# `make install` installs.  Every target first installs the missing
# Debian packages of deps.txt.

# The version is written once, in core/version.h.
VERSION   := $(shell sed -n 's/^\#define NL_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$$/\2/p' core/version.h | paste -sd.)
MAJOR     := $(firstword $(subst ., ,$(VERSION)))
CC        ?= gcc
OPT       ?= -O2 -g
CFLAGS    += -std=c11 -D_GNU_SOURCE -Wall -Wextra -fopenmp $(OPT) -MMD -MP \
             -I/usr/include/OpenEXR
LDLIBS    = -lOpenEXRCore -lfftw3_omp -lfftw3 -lgsl -lopenblas -lpng -ljansson -lzip -lmuparser -lm $(GDAL_LIBS) $(VDB_LIBS)
# GDAL (GeoTIFF, COG, NetCDF: core/formats/gdal_io.c) when pkg-config finds
# it; NL_GDAL=0 builds without, the formats then listed as off.  Recursive
# (=): pkg-config runs once the packages are installed.
NL_GDAL   ?= $(shell pkg-config --exists gdal && echo 1 || echo 0)
GDAL_LIBS  = $(if $(filter 1,$(NL_GDAL)),$(shell pkg-config --libs gdal))
GDAL_OBJ   = $(patsubst %.c,$(BUILD)/%.o,core/formats/gdal_io.c core/formats/geotiff.c core/formats/netcdf.c)
BUILD     := build
# OpenVDB is optional (Debian's libopenvdb-dev ships no .pc: found by its
# header).  Without it core/formats/vdb_io.cc compiles empty and the format
# openvdb is registered off (core/formats/vdb.c).  Recursive (=): looked for
# when recipes run, after deps.txt's packages are installed; the stamp
# rebuilds both objects when the answer changes.
HAVE_OPENVDB = $(shell test -f /usr/include/openvdb/openvdb.h && echo 1)
VDB_LIBS   = $(if $(HAVE_OPENVDB),-lopenvdb -ltbb -lImath -lstdc++)
CXXFLAGS  += -std=c++17 -D_GNU_SOURCE -Wall -Wextra $(OPT) -MMD -MP -fPIC -fno-semantic-interposition

LIB_SRC   := $(wildcard core/*.c core/families/*.c core/formats/*.c synth/*.c analysis/*.c render/*.c)
# cli/h5_*.c are the command line's HDF5 and MPI parts: noiselab-mpi only.
CLI_SRC   := $(filter-out cli/h5_%.c,$(wildcard cli/*.c))
# The distributed module (mpi/): Open MPI, FFTW-MPI and parallel HDF5, in a
# library of its own so that libnoiselab and bin/noiselab do not load them
# (about 40 libraries, 10 ms at every start); bin/noiselab hands a run with
# an .h5 file or under an MPI launcher to bin/noiselab-mpi (cli/main.c).
# Recursive (=): pkg-config runs once the packages are installed.
MPI_CFLAGS = $(shell pkg-config --cflags hdf5-openmpi mpi)
MPI_LIBS   = $(shell pkg-config --libs hdf5-openmpi mpi) -lfftw3_mpi
MPI_SRC   := $(wildcard mpi/*.c)
MPI_OBJ   := $(MPI_SRC:%.c=$(BUILD)/%.o)
H5CLI_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard cli/h5_*.c))
MPITEST_SRC := $(wildcard tests/mpi/*.c)
MPITEST_BIN := $(MPITEST_SRC:%.c=$(BUILD)/%)
BENCH_SRC := $(wildcard bench/*.c)
TEST_SRC  := $(wildcard tests/*.c)
EXP_SRC   := $(wildcard experiments/*.c)
EXP_BIN   := $(EXP_SRC:%.c=$(BUILD)/%)
LIB_OBJ   := $(LIB_SRC:%.c=$(BUILD)/%.o) $(BUILD)/core/formats/vdb_io.o
CLI_OBJ   := $(CLI_SRC:%.c=$(BUILD)/%.o) $(BENCH_SRC:%.c=$(BUILD)/%.o)
TEST_OBJ  := $(TEST_SRC:%.c=$(BUILD)/%.o)
LIB       := $(BUILD)/libnoiselab.a
MPILIB    := $(BUILD)/libnoiselab_mpi.a
MPISOLIB  := $(BUILD)/libnoiselab_mpi.so.$(VERSION)
SONAME    := libnoiselab.so.$(MAJOR)
SOLIB     := $(BUILD)/libnoiselab.so.$(VERSION)
MAN       := $(BUILD)/noiselab.1
BINDIR    ?= bin
BIN       := $(BINDIR)/noiselab
MPIBIN    := $(BINDIR)/noiselab-mpi
DEPS_OK   := $(BUILD)/.deps-ok

# Where `make install` puts things (DESTDIR is prepended to each).
PREFIX    ?= /usr/local
INSTALL_BINDIR ?= $(PREFIX)/bin
LIBDIR    ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
MANDIR    ?= $(PREFIX)/share/man
DOCDIR    ?= $(PREFIX)/share/doc/noiselab
PCDIR     ?= $(LIBDIR)/pkgconfig
DATADIR   ?= $(PREFIX)/share
# The folders the build writes into what it makes (noiselab.pc, the
# planner's wisdom file), kept in a file rewritten only when they change, so
# that `make install PREFIX=/usr` after a plain `make` remakes what names them.
INSTALL_DIRS := PREFIX=$(PREFIX) LIBDIR=$(LIBDIR) INCLUDEDIR=$(INCLUDEDIR) PCDIR=$(PCDIR) DATADIR=$(DATADIR)
PC        := $(BUILD)/noiselab.pc
# Public headers: every module header but the *_internal.h ones.
PUB_HDR   := $(filter-out %_internal.h,$(wildcard core/*.h synth/*.h analysis/*.h render/*.h))
MPI_HDR   := $(filter-out %_internal.h,$(wildcard mpi/*.h))
# The Python package python/noiselab, for Debian's interpreter (`make python`
# checks that it imports in the tree); installed where it looks under PREFIX.
PYTHON    ?= /usr/bin/python3
PYDIR     ?= $(if $(filter /usr,$(PREFIX)),/usr/lib/python3/dist-packages,$(PREFIX)/lib/python$(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)/dist-packages)

.PHONY: all deps wisdom gdal-off-check test test-api figures experiments bench asan fuzz clean install uninstall FORCE
.SECONDARY:
all: $(BIN) $(MPIBIN) $(LIB) $(SOLIB) $(MPISOLIB) $(MAN) $(PC)

# One list of packages, in deps.txt; the stamp is redone when it changes.
$(DEPS_OK): deps.txt tools/deps.sh
	@sh tools/deps.sh
	@mkdir -p $(BUILD) && touch $@
deps: $(DEPS_OK)

$(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

# The one C++ translation unit (OpenVDB), behind a C interface.
$(BUILD)/%.o: %.cc | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) -c $< -o $@
VDB_OBJ := $(BUILD)/core/formats/vdb.o $(BUILD)/core/formats/vdb_io.o
$(VDB_OBJ): $(BUILD)/openvdb-found
$(VDB_OBJ): CFLAGS += $(if $(HAVE_OPENVDB),-DNL_HAVE_OPENVDB)
$(VDB_OBJ): CXXFLAGS += $(if $(HAVE_OPENVDB),-DNL_HAVE_OPENVDB)
$(BUILD)/openvdb-found: FORCE | $(DEPS_OK)
	@echo '$(HAVE_OPENVDB)' | cmp -s - $@ || echo '$(HAVE_OPENVDB)' > $@

# Library objects serve both the static and the shared library (and are
# rebuilt when the Makefile, and so maybe their flags, changes).
$(LIB_OBJ): CFLAGS += -fPIC -fno-semantic-interposition
$(LIB_OBJ): Makefile
# The Gaussian kernel gives the same bits on every SIMD path only without
# fused multiply-adds (core/rng_kernel_internal.h).
$(BUILD)/core/rng%.o: CFLAGS += -ffp-contract=off
# The same for the subdivision stencils' SIMD paths (synth/subdiv_simd_internal.h).
$(BUILD)/synth/subdiv_simd%.o: CFLAGS += -ffp-contract=off
# Where the planner finds the measured FFTW wisdom that install puts there.
$(BUILD)/core/fftw_plan.o: CFLAGS += -DNL_WISDOM_FILE='"$(DATADIR)/noiselab/fftw-wisdom"'
$(BUILD)/core/fftw_plan.o: $(BUILD)/install-dirs
# The GDAL objects are remade when NL_GDAL changes.
$(GDAL_OBJ): CFLAGS += $(if $(filter 1,$(NL_GDAL)),-DNL_HAVE_GDAL $(shell pkg-config --cflags gdal))
$(GDAL_OBJ): $(BUILD)/gdal-config
$(BUILD)/gdal-config: FORCE | $(DEPS_OK)
	@mkdir -p $(BUILD) && echo 'NL_GDAL=$(NL_GDAL)' | cmp -s - $@ || echo 'NL_GDAL=$(NL_GDAL)' > $@

# The descriptors compile without GDAL too (as "off"): a check of the
# sources alone, not a rebuild.
gdal-off-check:
	@for f in core/formats/gdal_io.c core/formats/geotiff.c core/formats/netcdf.c; do \
	    $(CC) -std=c11 -D_GNU_SOURCE -Wall -Wextra -Werror -UNL_HAVE_GDAL -fsyntax-only $$f || exit 1; done
	@echo "gdal-off-check: the GDAL formats compile without GDAL"

$(BUILD)/install-dirs: FORCE
	@mkdir -p $(BUILD) && echo '$(INSTALL_DIRS)' | cmp -s - $@ || echo '$(INSTALL_DIRS)' > $@

$(LIB): $(LIB_OBJ)
	rm -f $@ && $(AR) rcs $@ $^

$(MPI_OBJ) $(H5CLI_OBJ) $(MPITEST_SRC:%.c=$(BUILD)/%.o): CFLAGS += $(MPI_CFLAGS)
$(MPI_OBJ): CFLAGS += -fPIC -fno-semantic-interposition
$(MPI_OBJ): Makefile
$(MPILIB): $(MPI_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
# The distributed plans share two pieces of the one-process ones that
# libnoiselab.so does not export (synth/fft_internal.h,
# synth/circulant_internal.h): libnoiselab_mpi.so links its own hidden copy
# of these objects, which hold no state.
MPI_SHARED_OBJ := $(BUILD)/synth/fft.o $(BUILD)/synth/circulant.o
$(MPISOLIB): $(MPI_OBJ) $(MPI_SHARED_OBJ) $(SOLIB) $(BUILD)/libnoiselab_mpi.map
	$(CC) $(CFLAGS) -shared -Wl,-soname,libnoiselab_mpi.so.$(MAJOR) -Wl,--no-undefined \
	    -Wl,--version-script=$(BUILD)/libnoiselab_mpi.map -o $@ $(MPI_OBJ) $(MPI_SHARED_OBJ) \
	    -Wl,--no-as-needed -L$(BUILD) -l:$(notdir $(SOLIB)) $(MPI_LIBS) $(LDLIBS)
	ln -sf $(notdir $@) $(BUILD)/libnoiselab_mpi.so.$(MAJOR)
	ln -sf libnoiselab_mpi.so.$(MAJOR) $(BUILD)/libnoiselab_mpi.so

# Each shared library exports exactly the functions its installed headers
# declare (tools/exports.sh makes the linker version script from them).
$(BUILD)/libnoiselab.map: $(PUB_HDR) include/noiselab.h tools/exports.sh | $(DEPS_OK)
	sh tools/exports.sh -map $(PUB_HDR) include/noiselab.h > $@.tmp && mv $@.tmp $@
$(BUILD)/libnoiselab_mpi.map: $(MPI_HDR) include/noiselab_mpi.h tools/exports.sh | $(DEPS_OK)
	CPPFLAGS="$(MPI_CFLAGS)" sh tools/exports.sh -map $(MPI_HDR) include/noiselab_mpi.h > $@.tmp && mv $@.tmp $@

# The shared library records its dependencies (DT_NEEDED), so a program
# links it with -lnoiselab alone.
$(SOLIB): $(LIB_OBJ) $(BUILD)/libnoiselab.map
	$(CC) $(CFLAGS) -shared -Wl,-soname,$(SONAME) -Wl,--no-undefined -Wl,--version-script=$(BUILD)/libnoiselab.map \
	    -o $@ $(LIB_OBJ) -Wl,--no-as-needed $(LDLIBS)
	ln -sf $(notdir $@) $(BUILD)/$(SONAME)
	ln -sf $(SONAME) $(BUILD)/libnoiselab.so

# noiselab.pc for pkg-config, its prefix relative to its own folder.
$(PC): noiselab.pc.in tools/pcfile.sh $(BUILD)/install-dirs core/version.h Makefile
	sh tools/pcfile.sh noiselab.pc.in '$(PREFIX)' '$(LIBDIR)' '$(INCLUDEDIR)' '$(PCDIR)' $(VERSION) \
	    '-fopenmp $(LDLIBS)' > $@.tmp && mv $@.tmp $@

# noiselab(1), from the help texts of the command and its subcommands.
$(MAN): $(BIN) tools/manpage.sh
	sh tools/manpage.sh $(BIN) $(VERSION) > $@.tmp && mv $@.tmp $@

$(BIN): $(CLI_OBJ) $(LIB)
	@mkdir -p $(BINDIR)
	$(CC) $(CFLAGS) -o $@ $(CLI_OBJ) $(LIB) $(LDLIBS)

$(MPIBIN): $(filter-out $(BUILD)/cli/main.o,$(CLI_OBJ)) $(H5CLI_OBJ) $(MPILIB) $(LIB)
	@mkdir -p $(BINDIR)
	$(CC) $(CFLAGS) -o $@ $^ $(MPI_LIBS) $(LDLIBS)

# MPI test programs, run by tests/mpi/run.sh under mpirun -np 1..4.
$(BUILD)/tests/mpi/%: $(BUILD)/tests/mpi/%.o $(MPILIB) $(LIB)
	$(CC) $(CFLAGS) -o $@ $^ $(MPI_LIBS) $(LDLIBS)

.PHONY: python
python: $(SOLIB)
	PYTHONPATH=python $(PYTHON) -c 'import noiselab'

# The option tables' tests (tests/test_opt.c) link the command line's parser.
CLI_OPT_OBJ := $(patsubst %,$(BUILD)/cli/%.o,opt util inputs outputs progress field_out)
$(BUILD)/tests/run: $(TEST_OBJ) $(CLI_OPT_OBJ) $(LIB)
	$(CC) $(CFLAGS) -o $@ $(TEST_OBJ) $(CLI_OPT_OBJ) $(LIB) $(LDLIBS) -lcriterion

# The catalogue of hostile inputs checks field outputs with this.
$(BUILD)/tests/finite: $(BUILD)/tests/bad/finite.o $(LIB)
	$(CC) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

$(BUILD)/experiments/%: $(BUILD)/experiments/%.o $(LIB)
	$(CC) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# Unit, error-path, CLI and statistical tests (Criterion). Each test is a
# fresh process, so measured FFTW plans would be paid for again and again:
# tests plan with FFTW_ESTIMATE, except the one comparing the two planners.
# tests/doc/run.sh runs every command of README.md, docs/tour.md, docs/geostatistics.md,
# docs/meuse.md (which needs R with sp and gstat), docs/scale-out.md, docs/validating.md and docs/expressions.md;
# tests/mpi/run.sh the distributed tests under mpirun -np 1..4; python/tests the Python package (pytest);
# tests/course the course's tools, then `make course` runs and renders the course's notebooks.
# test-api checks the installed headers and the libraries' exports.
# Then tools/test-install.sh installs into a scratch DESTDIR and builds the
# examples and the README's example against it with pkg-config alone.
test: all test-api gdal-off-check $(BUILD)/tests/run $(BUILD)/tests/finite $(EXP_BIN) $(MPITEST_BIN)
	NOISELAB_FFTW=estimate NOISELAB=$(abspath $(BIN)) $(BUILD)/tests/run --jobs 2 --filter '!(*_slow)/*'
	LIMIT=$(if $(findstring sanitize,$(OPT)),60,5) NOISELAB_FFTW=estimate sh tests/check/run.sh $(BIN)
	MPI_NPS="2 3" NOISELAB_FFTW=estimate NOISELAB_SANITIZED=$(if $(findstring sanitize,$(OPT)),1,) sh tests/mpi/run.sh $(BINDIR) $(BUILD)/tests/mpi
	NOISELAB_FFTW=estimate sh tests/par.sh "SHARD=0/2 sh tests/bad/run.sh $(BIN) $(BUILD)/tests/finite" \
	    "SHARD=1/2 sh tests/bad/run.sh $(BIN) $(BUILD)/tests/finite"
	NOISELAB_FFTW=estimate sh tests/par.sh "SHARD=0/2 sh tests/doc/run.sh $(BINDIR)" "SHARD=1/2 sh tests/doc/run.sh $(BINDIR)"
	sh tests/plots/run.sh
	$(if $(findstring sanitize,$(OPT)),@echo "python: skipped (a sanitized library does not load into $(PYTHON))",NOISELAB=$(abspath $(BIN)) NOISELAB_LIB=$(abspath $(SOLIB)) $(PYTHON) -m pytest -q -p no:cacheprovider -m "not heavy" python/tests tests/course)
	$(if $(findstring sanitize,$(OPT)),@echo "course: skipped (a sanitized library does not load into $(PYTHON))",@$(MAKE) --no-print-directory course)
	NOISELAB=$(abspath $(BIN)) NOISELAB_EXPERIMENTS=$(abspath $(BUILD)/experiments) \
	    sh experiments/quick.sh $(BUILD)/quick-figures
	MAKE="$(MAKE)" CC="$(CC)" EXAMPLE_CFLAGS="$(OPT)" VERSION=$(VERSION) WISDOM_SIZES=64 sh tools/test-install.sh

# The course (docs/course/*.ipynb, docs/course/README.md): tests/course/clean.py
# checks the committed notebooks are stripped and shaped as lessons;
# tests/course/run.py executes them (two at a time, 60 s each at most) into
# build/course/; tests/course/render.py renders those to build/course/html/
# (offline pages and an index); tests/course/browser.py opens every page in
# headless Chromium (no console error, every figure loaded) and saves
# build/course/screenshots/.  make test runs it all (pytest tests/course
# tests the tools themselves).
COURSE_NB := $(sort $(wildcard docs/course/*.ipynb))
COURSE    := $(BUILD)/course
.PHONY: course
course: $(BIN) $(SOLIB)
ifeq ($(COURSE_NB),)
	@echo "course: docs/course has no notebooks yet: nothing to run"
else
	$(PYTHON) tests/course/clean.py
	rm -rf $(COURSE) && NOISELAB=$(abspath $(BIN)) NOISELAB_LIB=$(abspath $(SOLIB)) \
	    $(PYTHON) tests/course/run.py --out $(COURSE) $(COURSE_NB)
	$(PYTHON) tests/course/render.py $(COURSE)/html $(addprefix $(COURSE)/,$(notdir $(COURSE_NB)))
	$(PYTHON) tests/course/browser.py --shots $(COURSE)/screenshots --no-figure-ok index.html \
	    $(COURSE)/html/index.html $(patsubst %.ipynb,$(COURSE)/html/%.html,$(notdir $(COURSE_NB)))
endif

# The slowest Criterion tests (suites named *_slow: sweeps over every model
# kind and plan, comparisons with R that take seconds each), the Python
# tests marked heavy, and the distributed tests on 1 and 4 processes (make
# test runs them on 2 and 3), kept out of `make test`'s 10 minutes; CI
# (.ci/run) runs them after it.
test-slow: all $(BUILD)/tests/run $(MPITEST_BIN)
	NOISELAB_FFTW=estimate NOISELAB=$(abspath $(BIN)) $(BUILD)/tests/run --jobs 2 --filter '*_slow/*'
	MPI_NPS="1 4" NOISELAB_FFTW=estimate sh tests/mpi/run.sh $(BINDIR) $(BUILD)/tests/mpi
	NOISELAB=$(abspath $(BIN)) NOISELAB_LIB=$(abspath $(SOLIB)) $(PYTHON) -m pytest -q -p no:cacheprovider -m heavy python/tests
.PHONY: test-slow

# The installed API: every installed header compiles alone as C and as C++
# with C linkage; each shared library exports exactly what its installed
# headers declare; docs/api.md (one line per exported function, from the
# headers: `make apidoc` writes it) is current.
API_ENV = PUB_HDR="$(PUB_HDR)" MPI_HDR="$(MPI_HDR)" MPI_CFLAGS="$(MPI_CFLAGS)" CC="$(CC)" CXX="$(CXX)"
APIDOC = CPPFLAGS="$(MPI_CFLAGS)" $(PYTHON) tools/apidoc.py $(PUB_HDR) $(MPI_HDR)
test-api: $(SOLIB) $(MPISOLIB)
	$(API_ENV) sh tests/api/headers.sh
	$(API_ENV) sh tests/api/exports.sh $(SOLIB) $(MPISOLIB)
	$(APIDOC) | diff -u docs/api.md - || { echo "docs/api.md is not the headers' (make apidoc)"; exit 1; }
.PHONY: apidoc
apidoc: | $(DEPS_OK)
	$(APIDOC) > docs/api.md.tmp && mv docs/api.md.tmp docs/api.md

# Measured FFTW wisdom for 2D fields of WISDOM_SIZES^2 (and circulant
# embeddings of them), installed where the planner looks (core/fftw_plan.h),
# so that first runs at these sizes use measured plans without planning.
WISDOM_SIZES ?= 256 512 1024 2048 4096
WISDOM    := $(BUILD)/fftw-wisdom-$(subst $() ,-,$(strip $(WISDOM_SIZES)))
$(WISDOM): tools/wisdom.sh | $(BIN)
	sh tools/wisdom.sh $(BIN) $@ $(WISDOM_SIZES)
wisdom: $(WISDOM)

# DESTDIR, PREFIX, LIBDIR, INCLUDEDIR, MANDIR, DOCDIR, PCDIR as usual, and
# INSTALL_BINDIR (BINDIR is where the build puts the program).  Install copies
# what the build made under build/ and bin/ and writes nothing else in the tree.
# Headers go to INCLUDEDIR/noiselab/{core,synth,analysis,render}/ (the tree's
# layout, so their relative includes hold) and noiselab.h to INCLUDEDIR.
install: all $(WISDOM)
	install -d $(DESTDIR)$(INSTALL_BINDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PCDIR) $(DESTDIR)$(MANDIR)/man1 \
	    $(DESTDIR)$(DATADIR)/noiselab \
	    $(DESTDIR)$(DOCDIR)/examples $(addprefix $(DESTDIR)$(INCLUDEDIR)/noiselab/,core synth analysis render mpi)
	install -m 755 $(BIN) $(DESTDIR)$(INSTALL_BINDIR)/noiselab
	install -m 755 $(MPIBIN) $(DESTDIR)$(INSTALL_BINDIR)/noiselab-mpi
	install -m 644 $(MPILIB) $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.a
	install -m 755 $(MPISOLIB) $(DESTDIR)$(LIBDIR)/
	ln -sf $(notdir $(MPISOLIB)) $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.so.$(MAJOR)
	ln -sf libnoiselab_mpi.so.$(MAJOR) $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.so
	install -m 644 include/noiselab_mpi.h $(DESTDIR)$(INCLUDEDIR)/noiselab_mpi.h
	for h in $(MPI_HDR); do install -m 644 $$h $(DESTDIR)$(INCLUDEDIR)/noiselab/$$h || exit 1; done
	install -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libnoiselab.a
	install -m 755 $(SOLIB) $(DESTDIR)$(LIBDIR)/
	ln -sf $(notdir $(SOLIB)) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libnoiselab.so
	install -m 644 include/noiselab.h $(DESTDIR)$(INCLUDEDIR)/noiselab.h
	for h in $(PUB_HDR); do install -m 644 $$h $(DESTDIR)$(INCLUDEDIR)/noiselab/$$h || exit 1; done
	install -m 644 $(PC) $(DESTDIR)$(PCDIR)/noiselab.pc
	install -m 644 $(MAN) $(DESTDIR)$(MANDIR)/man1/noiselab.1
	install -m 644 examples/*.c $(DESTDIR)$(DOCDIR)/examples/
	install -m 644 $(WISDOM) $(DESTDIR)$(DATADIR)/noiselab/fftw-wisdom
	install -d $(DESTDIR)$(PYDIR)/noiselab && install -m 644 python/noiselab/*.py $(DESTDIR)$(PYDIR)/noiselab/
	@if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" = 0 ]; then ldconfig || true; fi

# Removes exactly what install put there, then the folders it left empty.
uninstall:
	rm -f $(DESTDIR)$(INSTALL_BINDIR)/noiselab-mpi $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.a \
	    $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.so $(DESTDIR)$(LIBDIR)/libnoiselab_mpi.so.$(MAJOR) \
	    $(DESTDIR)$(LIBDIR)/$(notdir $(MPISOLIB)) $(DESTDIR)$(INCLUDEDIR)/noiselab_mpi.h \
	    $(addprefix $(DESTDIR)$(INCLUDEDIR)/noiselab/,$(MPI_HDR))
	rm -f $(DESTDIR)$(INSTALL_BINDIR)/noiselab $(DESTDIR)$(LIBDIR)/libnoiselab.a $(DESTDIR)$(LIBDIR)/libnoiselab.so \
	    $(DESTDIR)$(LIBDIR)/$(SONAME) $(DESTDIR)$(LIBDIR)/$(notdir $(SOLIB)) $(DESTDIR)$(PCDIR)/noiselab.pc \
	    $(DESTDIR)$(MANDIR)/man1/noiselab.1 $(DESTDIR)$(INCLUDEDIR)/noiselab.h $(DESTDIR)$(DATADIR)/noiselab/fftw-wisdom \
	    $(addprefix $(DESTDIR)$(INCLUDEDIR)/noiselab/,$(PUB_HDR)) \
	    $(addprefix $(DESTDIR)$(DOCDIR)/examples/,$(notdir $(wildcard examples/*.c)))
	rm -rf $(DESTDIR)$(PYDIR)/noiselab/__pycache__ $(addprefix $(DESTDIR)$(PYDIR)/noiselab/,$(notdir $(wildcard python/noiselab/*.py)))
	rmdir $(DESTDIR)$(PYDIR)/noiselab 2>/dev/null || true
	rmdir $(addprefix $(DESTDIR)$(INCLUDEDIR)/noiselab/,core synth analysis render mpi) $(DESTDIR)$(INCLUDEDIR)/noiselab \
	    $(DESTDIR)$(DOCDIR)/examples $(DESTDIR)$(DOCDIR) $(DESTDIR)$(DATADIR)/noiselab 2>/dev/null || true

# Every experiment writes its data, picture and verdict into paper-figures/.
# Exemplar images from Debian packages' data (python3-skimage, gimp-data; not committed).
EXEMPLARS := $(BUILD)/exemplars/fibers.pat
$(EXEMPLARS): tools/exemplars.sh | $(DEPS_OK)
	@sh tools/exemplars.sh $(BUILD)/exemplars

figures: $(BIN) $(EXP_BIN) $(EXEMPLARS)
	@sh experiments/run-all.sh paper-figures

# make experiments: the figures with the long runs (fig-fit-coverage.sh's full size).
experiments: export NOISELAB_FULL := 1
experiments: figures

# The whole test suite under AddressSanitizer, UndefinedBehaviorSanitizer and
# LeakSanitizer, in a build of its own.  The CLI's error exits leave their
# memory to exit() by design, so leaks are checked in the library tests and
# not in the CLI processes they start (tests/util.c).
asan: $(DEPS_OK)
	LSAN_OPTIONS=suppressions=$(abspath tests/lsan.supp) $(MAKE) BUILD=build/asan BINDIR=build/asan/bin \
	    OPT="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" test

# libFuzzer on the parsers and the number paths (clang), FUZZ_SECONDS each
# (default 30), from the committed seed corpora; crashes are left as crash-*
# files and fail the run.  Targets 1-3 read one input with a library parser
# (tests/fuzz/fuzz_parse.c), 4-6 run the command line in-process
# (tests/fuzz/fuzz_cli.c), 7-8 decode the input into a synthesis on a tiny
# grid, run by the library (tests/fuzz/fuzz_num.c) and by the command line
# (tests/fuzz/fuzz_synthcli.c), 9 into a tiny field for the analysis
# (fuzz_num.c), 10 the point tables (tests/fuzz/fuzz_points.c), 11 the
# HDF5 reader of mpi/h5.c on a temporary file (fuzz_h5.c), 12 a small point
# set for the fitters (fuzz_fit.c).
# `make fuzz FUZZ_TARGETS="synthnum synthcli"` runs some of them.
FUZZ_SECONDS ?= 30
FUZZ_TARGETS ?= model dist field cli krige cloud synthnum synthcli fieldnum points h5 fit
FUZZ_CLI_SRC := $(filter-out cli/main.c,$(CLI_SRC)) $(BENCH_SRC)
fuzz: $(DEPS_OK)
	@mkdir -p $(BUILD)/fuzz
	@for t in $(FUZZ_TARGETS); do \
	    x= l= m=4096; case $$t in \
	    model) n=1 src=tests/fuzz/fuzz_parse.c ;; dist) n=2 src=tests/fuzz/fuzz_parse.c ;; \
	    field) n=3 src=tests/fuzz/fuzz_parse.c ;; cli) n=4 src="tests/fuzz/fuzz_cli.c $(FUZZ_CLI_SRC)" ;; \
	    krige) n=5 src="tests/fuzz/fuzz_cli.c $(FUZZ_CLI_SRC)" ;; cloud) n=6 src="tests/fuzz/fuzz_cli.c $(FUZZ_CLI_SRC)" ;; \
	    synthnum) n=7 src=tests/fuzz/fuzz_num.c ;; synthcli) n=8 src="tests/fuzz/fuzz_synthcli.c $(FUZZ_CLI_SRC)" ;; \
	    fieldnum) n=9 src=tests/fuzz/fuzz_num.c ;; points) n=10 src=tests/fuzz/fuzz_points.c ;; \
	    h5) n=11 src="tests/fuzz/fuzz_h5.c $(MPI_SRC)" x="$(MPI_CFLAGS)" l="$(MPI_LIBS)" m=16384 ;; \
	    fit) n=12 src=tests/fuzz/fuzz_fit.c ;; \
	    *) echo "fuzz: no target $$t"; exit 1 ;; \
	    esac; \
	    clang -O1 -g -fsanitize=fuzzer,address,undefined -DFUZZ_TARGET=$$n -D_GNU_SOURCE -I/usr/include/OpenEXR $$x \
	        $$src $(LIB_SRC) -o $(BUILD)/fuzz/$$t $(LDLIBS) $$l -lgomp -lm || exit 1; \
	    mkdir -p $(BUILD)/fuzz/corpus-$$t $(BUILD)/fuzz/work-$$t && cp tests/fuzz/corpus/$$t/* $(BUILD)/fuzz/corpus-$$t/; \
	    (cd $(BUILD)/fuzz/work-$$t && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1 ../$$t -max_total_time=$(FUZZ_SECONDS) -max_len=$$m \
	        -timeout=20 -artifact_prefix=../$$t- ../corpus-$$t) || exit 1; \
	done

# Speed against this machine's floor, measured in the same run (TSV).
# Steady state: measured FFTW plans (the installed wisdom, or measured
# here and kept in the cache); tools/bench-firstrun.sh times first runs.
bench: $(SOLIB)
bench: $(BIN) $(MPIBIN) $(WISDOM)
	@mkdir -p $(BUILD)/bench
	NOISELAB_FFTW=measure NOISELAB_WISDOM=$(abspath $(WISDOM)) $(BIN) bench | tee $(BUILD)/bench/bench.tsv
	gnuplot -e "in='$(BUILD)/bench/bench.tsv'; out='$(BUILD)/bench/bench.png'" tools/bench-plot.gp
	NOISELAB_WISDOM=$(abspath $(WISDOM)) sh tools/bench-r.sh $(BIN) $(BUILD)/bench/r | tee $(BUILD)/bench/bench-r.tsv
	NOISELAB_WISDOM=$(abspath $(WISDOM)) sh tools/bench-gstat.sh $(BIN) $(BUILD)/bench/gstat | tee $(BUILD)/bench/bench-gstat.tsv
	NOISELAB_WISDOM=$(abspath $(WISDOM)) sh tools/bench-condsim.sh $(BIN) $(BUILD)/bench/condsim | tee $(BUILD)/bench/bench-condsim.tsv
	sh tools/bench-firstrun.sh $(BIN) $(abspath $(WISDOM)) $(BUILD)/bench/first | tee $(BUILD)/bench/bench-firstrun.tsv
	NOISELAB_FFTW=measure NOISELAB_WISDOM=$(abspath $(WISDOM)) CC="$(CC)" PYTHON=$(PYTHON) sh tools/bench-python.sh $(BUILD) | tee $(BUILD)/bench/bench-python.tsv
	NOISELAB_WISDOM=$(abspath $(WISDOM)) sh tools/bench-mpi.sh $(BINDIR) $(BUILD)/bench/mpi | tee $(BUILD)/bench/bench-mpi.tsv
	@echo "bench: $(BUILD)/bench/bench.tsv, bench.png and (with R installed) bench-r.tsv"

clean:
	rm -rf $(BUILD) bin tests/work

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(MPI_OBJ:.o=.d) $(H5CLI_OBJ:.o=.d) $(MPITEST_SRC:%.c=$(BUILD)/%.d) $(TEST_OBJ:.o=.d) $(EXP_SRC:%.c=$(BUILD)/%.d)

# Every output of bin/ against a build of the revision COMPAT_BASE (stdout,
# stderr, exit status and files of tools/compat/commands.txt; the version
# string and timings normalised): "N passed, M failed", exit 1 on a difference.
COMPAT_BASE ?= HEAD
.PHONY: compat
compat: $(BIN) $(MPIBIN)
	sh tools/compat/base.sh $(COMPAT_BASE) $(BUILD)/compat-base
	sh tools/compat/run.sh $(BUILD)/compat-base/src/bin $(BINDIR)
