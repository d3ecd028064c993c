# noiselab: `make` builds bin/noiselab and build/libnoiselab.a; `make test`
# runs the tests; `make figures` reproduces the paper figures.  Every target
# first installs the missing Debian packages of deps.txt.

VERSION   := 0.1.0
CC        ?= gcc
OPT       ?= -O2 -g
CFLAGS    += -std=c11 -D_GNU_SOURCE -Wall -Wextra -fopenmp $(OPT) -MMD -MP \
             -I/usr/include/OpenEXR -DNL_VERSION='"$(VERSION)"'
LDLIBS    := -lOpenEXRCore -lfftw3_omp -lfftw3 -lgsl -lgslcblas -lpng -ljansson -lmatheval -lm
BUILD     := build

LIB_SRC   := $(wildcard core/*.c synth/*.c analysis/*.c render/*.c)
CLI_SRC   := $(wildcard cli/*.c)
TEST_SRC  := $(wildcard tests/*.c)
EXP_SRC   := $(wildcard experiments/*.c)
EXP_BIN   := $(EXP_SRC:%.c=$(BUILD)/%)
LIB_OBJ   := $(LIB_SRC:%.c=$(BUILD)/%.o)
CLI_OBJ   := $(CLI_SRC:%.c=$(BUILD)/%.o)
TEST_OBJ  := $(TEST_SRC:%.c=$(BUILD)/%.o)
LIB       := $(BUILD)/libnoiselab.a
BINDIR    ?= bin
BIN       := $(BINDIR)/noiselab
DEPS_OK   := $(BUILD)/.deps-ok

.PHONY: all deps test figures experiments bench asan fuzz clean
.SECONDARY:
all: $(BIN) $(LIB)

# One list of packages, in deps.txt; the stamp is redone when it changes.
$(DEPS_OK): deps.txt tools/deps.sh
	@sh tools/deps.sh
	@mkdir -p $(BUILD) && touch $@
deps: $(DEPS_OK)

$(BUILD)/%.o: %.c | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	$(AR) rcs $@ $^

$(BIN): $(CLI_OBJ) $(LIB)
	@mkdir -p $(BINDIR)
	$(CC) $(CFLAGS) -o $@ $(CLI_OBJ) $(LIB) $(LDLIBS)

$(BUILD)/tests/run: $(TEST_OBJ) $(LIB)
	$(CC) $(CFLAGS) -o $@ $(TEST_OBJ) $(LIB) $(LDLIBS) -lcriterion

$(BUILD)/experiments/%: $(BUILD)/experiments/%.o $(LIB)
	$(CC) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# Unit, error-path, CLI and statistical tests (Criterion). Each test is a
# fresh process, so measured FFTW plans would be paid for again and again:
# tests plan with FFTW_ESTIMATE, except the one comparing the two planners.
test: $(BIN) $(BUILD)/tests/run $(EXP_BIN)
	NOISELAB_FFTW=estimate NOISELAB=$(abspath $(BIN)) $(BUILD)/tests/run --jobs 2
	NOISELAB=$(abspath $(BIN)) NOISELAB_EXPERIMENTS=$(abspath $(BUILD)/experiments) \
	    sh experiments/quick.sh $(BUILD)/quick-figures

# Every experiment writes its data, picture and verdict into paper-figures/.
# Exemplar images from Debian packages' data (python3-skimage, gimp-data; not committed).
EXEMPLARS := $(BUILD)/exemplars/fibers.pat
$(EXEMPLARS): tools/exemplars.sh | $(DEPS_OK)
	@sh tools/exemplars.sh $(BUILD)/exemplars

figures: $(BIN) $(EXP_BIN) $(EXEMPLARS)
	@sh experiments/run-all.sh paper-figures

experiments: figures

# The whole test suite under AddressSanitizer, UndefinedBehaviorSanitizer and
# LeakSanitizer, in a build of its own.  The CLI's error exits leave their
# memory to exit() by design, so leaks are checked in the library tests and
# not in the CLI processes they start (tests/util.c).
asan: $(DEPS_OK)
	LSAN_OPTIONS=suppressions=$(abspath tests/lsan.supp) $(MAKE) BUILD=build/asan BINDIR=build/asan/bin \
	    OPT="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" test

# libFuzzer on the parsers (clang), FUZZ_SECONDS each (default 30), from the
# committed seed corpora; crashes are left as crash-* files and fail the run.
FUZZ_SECONDS ?= 30
# Targets 1-3 read one input with a library parser (tests/fuzz/fuzz_parse.c),
# 4-6 run the command line in-process (tests/fuzz/fuzz_cli.c).
FUZZ_TARGETS := model dist field cli krige cloud
FUZZ_CLI_SRC := $(filter-out cli/main.c,$(CLI_SRC))
fuzz: $(DEPS_OK)
	@mkdir -p $(BUILD)/fuzz
	@n=1; for t in $(FUZZ_TARGETS); do \
	    if [ $$n -le 3 ]; then src="tests/fuzz/fuzz_parse.c"; else src="tests/fuzz/fuzz_cli.c $(FUZZ_CLI_SRC)"; fi; \
	    clang -O1 -g -fsanitize=fuzzer,address,undefined -DFUZZ_TARGET=$$n -D_GNU_SOURCE -I/usr/include/OpenEXR \
	        -DNL_VERSION='"$(VERSION)"' $$src $(LIB_SRC) -o $(BUILD)/fuzz/$$t $(LDLIBS) -lgomp -lm || exit 1; \
	    mkdir -p $(BUILD)/fuzz/corpus-$$t $(BUILD)/fuzz/work-$$t && cp tests/fuzz/corpus/$$t/* $(BUILD)/fuzz/corpus-$$t/; \
	    (cd $(BUILD)/fuzz/work-$$t && ASAN_OPTIONS=detect_leaks=0 ../$$t -max_total_time=$(FUZZ_SECONDS) -max_len=4096 \
	        -timeout=20 -artifact_prefix=../$$t- ../corpus-$$t) || exit 1; \
	    n=$$((n + 1)); \
	done

# Speed against this machine's floor, measured in the same run (TSV).
bench: $(BIN)
	@mkdir -p $(BUILD)/bench
	$(BIN) bench | tee $(BUILD)/bench/bench.tsv
	gnuplot -e "in='$(BUILD)/bench/bench.tsv'; out='$(BUILD)/bench/bench.png'" tools/bench-plot.gp
	sh tools/bench-r.sh $(BIN) $(BUILD)/bench/r | tee $(BUILD)/bench/bench-r.tsv
	@echo "bench: $(BUILD)/bench/bench.tsv, bench.png and (with R installed) bench-r.tsv"

clean:
	rm -rf $(BUILD) bin tests/work

-include $(LIB_OBJ:.o=.d) $(CLI_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(EXP_SRC:%.c=$(BUILD)/%.d)
