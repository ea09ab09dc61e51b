# Facet: build, test, demo and benchmark.
#
#   make          build ./facet (optimised)
#   make check    build the release and the ASan+UBSan builds, then run every
#                 test of both, side by side on every core (tests/run.py)
#   make check-fast  the edit-test loop: the release build's unit tests and
#                 the end-to-end suites of the layers the change touches
#   make check-mutants  a defect in each layer is caught (CI runs it)
#   make demo     run the main job on a bundled example (no TTY needed)
#   make bench    benchmarks, reported as ratios against a baseline
#   make deps     install the Debian packages Facet needs (as root) and
#                 web-ifc (npm ci in tests/ifc), the IFC test's reader
#   make install  facet, its manual page (man facet) and its bash completion
#                 into PREFIX (default /usr/local), under DESTDIR if given;
#                 make uninstall removes them
#
# Objects go to build/$(VARIANT)/; VARIANT=release (default) or san.

SHELL   := /bin/bash
CC      ?= gcc
CXX     ?= g++
VARIANT ?= release
BUILD   := build/$(VARIANT)
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
VERSION := 0.1.0

# make install: where, as the GNU conventions name them.
PREFIX  ?= /usr/local
BINDIR  ?= $(PREFIX)/bin
MANDIR  ?= $(PREFIX)/share/man
BASH_COMPLETION_DIR ?= $(PREFIX)/share/bash-completion/completions

# libopenblas0-pthread becomes the system BLAS under CHOLMOD (facet planarize):
# 10.3 s against 24.2 s wall with the reference BLAS on the roof's 100 x 100
# quads, the same result.
DEBIAN_PACKAGES := gcc g++ make pkg-config libncurses-dev libsqlite3-dev librsvg2-bin \
	libcmocka-dev sqlite3 tmux python3 python3-tinyobjloader \
	libtinyobjloader-dev libxml2-utils python3-deap clang libclang-rt-14-dev \
	slurm-wlm munge libxlsxwriter-dev python3-openpyxl python3-ezdxf \
	python3-matplotlib nodejs npm man-db groff-base libsuitesparse-dev python3-numpy \
	libopenblas0-pthread

WARN    := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
DEFS    := -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -DFACET_VERSION=\"$(VERSION)\"
ifeq ($(VARIANT),san)
OPT     := -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer \
	-fno-sanitize-recover=all
else ifeq ($(VARIANT),clang)
OPT     := -O2 -g
else ifeq ($(VARIANT),fuzz)
OPT     := -O1 -g -fsanitize=address,undefined,fuzzer-no-link \
	-fno-omit-frame-pointer -fno-sanitize-recover=all
else
OPT     := -O2 -g
endif
# No -DNDEBUG in any variant: assert() states Facet's invariants and stays
# live in the release build (core/base/error.c refuses to build without).
CFLAGS  := -std=c11 $(WARN) $(DEFS) $(OPT) -MMD -MP -I.
# CHOLMOD is not linked: core/planar/sparse_solver.c loads it with dlopen in
# the one process that planarizes (the others skip OpenBLAS's start-up).
LDLIBS  := -lsqlite3 $(shell pkg-config --libs xlsxwriter 2>/dev/null || echo -lxlsxwriter) $(shell pkg-config --libs ncursesw 2>/dev/null || echo -lncursesw) -lpthread -lm
LDFLAGS := $(filter -fsanitize=%,$(OPT))

CORE_SRC  := $(wildcard core/*/*.c)
STORE_SRC := $(wildcard store/*.c)
STUDY_SRC := $(wildcard study/*.c)
TUI_SRC   := $(wildcard tui/*.c)
CLI_SRC   := $(filter-out cli/main.c,$(wildcard cli/*.c))
LIB_SRC   := $(CORE_SRC) $(STORE_SRC) $(STUDY_SRC) $(TUI_SRC) $(CLI_SRC)
# ... and the one source written by the build: Facet's schema of each
# version as its migrations leave it (store_schemas, below).
LIB_OBJ   := $(LIB_SRC:%.c=$(BUILD)/%.o) $(BUILD)/store/schema_script.o

SUPPORT_SRC := $(wildcard tests/support/*.c)
SUPPORT_OBJ := $(SUPPORT_SRC:%.c=$(BUILD)/%.o)
UNIT_SRC  := $(wildcard tests/unit/test_*.c)
UNIT_BIN  := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
TOOL_SRC  := $(wildcard tests/tools/*.c)
TOOL_BIN  := $(TOOL_SRC:tests/tools/%.c=$(BUILD)/tools/%)
FUZZ_SRC  := $(wildcard tests/fuzz/fuzz_*.c)
FUZZ_NAMES := $(FUZZ_SRC:tests/fuzz/fuzz_%.c=%)
REPLAY_BIN := $(FUZZ_NAMES:%=$(BUILD)/fuzz/replay_%)
FUZZ_BIN  := $(FUZZ_NAMES:%=$(BUILD)/fuzz/fuzz_%)
FUZZ_SECONDS ?= 60
FUZZ_SEED ?= 1
BENCH_SRC := $(wildcard tests/bench/*.c)
BENCH_BIN := $(BENCH_SRC:tests/bench/%.c=$(BUILD)/bench/%)

.PHONY: all check check-fast check-mutants test test-build demo bench deps clean fuzz fuzz-run \
	install uninstall

# Objects built on the way (the tests' support) are kept, not removed.
.SECONDARY:

all: facet

# ./facet is always the release build; the sanitizer build lives in build/san,
# clang's in build/clang, the fuzz targets' in build/fuzz.
ifeq ($(VARIANT),release)
facet: $(BUILD)/facet
	cp $< $@
endif

$(BUILD)/facet: $(BUILD)/cli/main.o $(BUILD)/libfacet.a
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# The manual page and the bash completion, written by facet itself from the
# tables its --help prints (cli/man_page.h, cli/completion.h).
$(BUILD)/facet.1: $(BUILD)/facet
	$< help --man >$@.tmp && mv $@.tmp $@

$(BUILD)/facet.bash: $(BUILD)/facet
	$< help --completion bash >$@.tmp && mv $@.tmp $@

$(BUILD)/libfacet.a: $(LIB_OBJ)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c -o $@ $<

# store_schemas (store/store_internal.h): each version's entries of
# sqlite_schema (type, name, CREATE statement), which store_schema_check
# compares a file with, written by a program that runs the migrations of
# store/schema.c themselves (store/tool/schema_script.c). It links those
# objects alone, not libfacet.a, which holds what it writes; an edit of
# any of them (the migrations) writes the file again, and
# test_store_schema holds it to a replay of the migrations.
SCHEMA_TOOL_OBJ := $(BUILD)/store/schema.o $(BUILD)/core/base/text.o \
	$(BUILD)/core/base/error.o

$(BUILD)/store/tool/schema_script: store/tool/schema_script.c $(SCHEMA_TOOL_OBJ)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(SCHEMA_TOOL_OBJ) -lsqlite3

$(BUILD)/store/schema_script.c: $(BUILD)/store/tool/schema_script
	$< $@.tmp && mv $@.tmp $@

$(BUILD)/store/schema_script.o: $(BUILD)/store/schema_script.c
	$(CC) $(CFLAGS) -c -o $@ $<

$(BUILD)/tests/%: tests/unit/%.c $(SUPPORT_OBJ) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(SUPPORT_OBJ) $(BUILD)/libfacet.a -lcmocka $(LDLIBS)

# A fuzz target as a plain program that replays its corpus (make check),
# and linked with libFuzzer (make fuzz, VARIANT=fuzz, clang).
$(BUILD)/fuzz/replay_%: tests/fuzz/fuzz_%.c tests/fuzz/replay.c $(SUPPORT_OBJ) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< tests/fuzz/replay.c $(SUPPORT_OBJ) $(BUILD)/libfacet.a $(LDLIBS)

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(SUPPORT_OBJ) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fsanitize=fuzzer,address,undefined -o $@ $< $(SUPPORT_OBJ) $(BUILD)/libfacet.a $(LDLIBS)

$(BUILD)/tools/%: tests/tools/%.c $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(BUILD)/libfacet.a $(LDLIBS)

$(BUILD)/bench/%: tests/bench/%.c $(SUPPORT_OBJ) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(SUPPORT_OBJ) $(BUILD)/libfacet.a $(LDLIBS)

# bench_curvature's baseline: the estimator as it was at CURVATURE_BASE
# (before the osculating correction, the thin fits and the Newton steps;
# issue 27 measures against it), taken from git at bench time and built
# beside today's, its public names prefixed with base_.
CURVATURE_BASE ?= d218719:core/curvature.c
CURVATURE_BASE_RENAME := -Dcurvature_at_vertices=base_curvature_at_vertices \
	-Dcurvature_at_vertices_jobs=base_curvature_at_vertices_jobs \
	-Dcurvature_free=base_curvature_free

$(BUILD)/bench/curvature_base.c:
	@mkdir -p $(dir $@)
	git show $(CURVATURE_BASE) > $@.tmp || { rm -f $@.tmp; \
		echo "bench_curvature: $(CURVATURE_BASE) is not in this clone's history"; exit 1; }
	mv $@.tmp $@

$(BUILD)/bench/curvature_base.o: $(BUILD)/bench/curvature_base.c
	$(CC) $(CFLAGS) -iquote core/surface -iquote core/base $(CURVATURE_BASE_RENAME) -c -o $@ $<

$(BUILD)/bench/bench_curvature: tests/bench/bench_curvature.c $(BUILD)/bench/curvature_base.o $(SUPPORT_OBJ) $(BUILD)/libfacet.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< $(BUILD)/bench/curvature_base.o $(SUPPORT_OBJ) $(BUILD)/libfacet.a $(LDLIBS)

# Everything one variant's tests run.
# The benchmarks are built with the tests, so that an API change that
# breaks one fails make check, not only the next make bench.
test-build: $(BUILD)/facet $(UNIT_BIN) $(TOOL_BIN) $(REPLAY_BIN) $(BENCH_BIN)

# Build and run every test of one variant.
test: test-build
	tests/run.py --jobs $(JOBS) $(BUILD)

# Both builds' suites in one queue, so that both cores stay busy to the end;
# the fixtures are made once, by the release build, for both.
check: deps
	$(MAKE) -j$(JOBS) VARIANT=release facet test-build
	$(MAKE) -j$(JOBS) VARIANT=san test-build
	tests/run.py --jobs $(JOBS) build/release build/san

check-fast:
	$(MAKE) -j$(JOBS) VARIANT=release facet test-build
	tests/run.py --jobs $(JOBS) --changed build/release

# Each layer's tests can still fail: a defect written into each layer of a
# scratch copy is caught by the suites check-fast picks for it (CI).
check-mutants:
	$(MAKE) -j$(JOBS) VARIANT=release facet test-build
	tests/mutants.sh build/release

# Every fuzz target under libFuzzer with ASan and UBSan for FUZZ_SECONDS
# each (default 60), from a copy of its seed corpus, with the mutations of
# FUZZ_SEED (default 1, so a run is repeatable; FUZZ_SEED=0 picks one); a crash stops it, and
# its input (build/fuzz/crashes/) belongs in tests/fuzz/crashes/NAME/ as a
# regression test that make check replays.
fuzz: deps
	$(MAKE) -j$(JOBS) VARIANT=fuzz CC=clang fuzz-run

fuzz-run: $(FUZZ_BIN)
	@mkdir -p $(BUILD)/crashes
	@for name in $(FUZZ_NAMES); do \
		work=$(BUILD)/work/$$name; rm -rf $$work; mkdir -p $$work; \
		cp tests/fuzz/corpus/$$name/* $$work/ 2>/dev/null; \
		echo "== fuzz_$$name for $(FUZZ_SECONDS) s"; \
		$(BUILD)/fuzz/fuzz_$$name $$work -max_total_time=$(FUZZ_SECONDS) -seed=$(FUZZ_SEED) \
			-timeout=20 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
			-artifact_prefix=$(BUILD)/crashes/$$name- 2>&1 | \
			grep -E '^(#[0-9]+ *DONE|stat::number_of_executed_units|stat::peak_rss|==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written)'; \
		status=$${PIPESTATUS[0]}; \
		if [ $$status -ne 0 ]; then echo "fuzz_$$name FAILED (status $$status): see $(BUILD)/crashes"; exit 1; fi; \
	done

demo: deps facet
	examples/demo.sh ./facet

bench: deps facet
	$(MAKE) VARIANT=release $(BUILD)/libfacet.a $(BENCH_BIN)
	tests/bench/run.sh $(BUILD)

deps:
	@missing=$$(for p in $(DEBIAN_PACKAGES); do \
		dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'ok installed' || \
		{ [ $$p = npm ] && command -v npm >/dev/null; } || echo $$p; done); \
	if [ -z "$$missing" ]; then :; \
	elif [ "$$(id -u)" = 0 ]; then \
		echo "installing:" $$missing; \
		DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$missing >/dev/null || \
		{ apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q $$missing >/dev/null; }; \
	else \
		echo "Facet needs Debian packages; run as root:"; \
		echo "  apt-get install -y" $$missing; exit 1; \
	fi
	@# web-ifc, the IFC test's reader, as tests/ifc/package-lock.json pins it
	@# (npm's own node_modules). Without it Facet still builds and tests; the
	@# IFC test then says its checks were skipped.
	@if [ ! -r tests/ifc/node_modules/web-ifc/package.json ] || \
		[ tests/ifc/package-lock.json -nt tests/ifc/node_modules/.package-lock.json ]; then \
		echo "installing web-ifc into tests/ifc/node_modules (npm ci)"; \
		(cd tests/ifc && npm ci --no-audit --no-fund --loglevel=error >/dev/null) || \
		echo "make deps: npm ci in tests/ifc failed: export_ifc.sh will say its checks were skipped"; \
	fi

install: $(BUILD)/facet $(BUILD)/facet.1 $(BUILD)/facet.bash
	install -d "$(DESTDIR)$(BINDIR)" "$(DESTDIR)$(MANDIR)/man1" \
		"$(DESTDIR)$(BASH_COMPLETION_DIR)"
	install -m 755 $(BUILD)/facet "$(DESTDIR)$(BINDIR)/facet"
	install -m 644 $(BUILD)/facet.1 "$(DESTDIR)$(MANDIR)/man1/facet.1"
	install -m 644 $(BUILD)/facet.bash "$(DESTDIR)$(BASH_COMPLETION_DIR)/facet"

uninstall:
	rm -f "$(DESTDIR)$(BINDIR)/facet" "$(DESTDIR)$(MANDIR)/man1/facet.1" \
		"$(DESTDIR)$(BASH_COMPLETION_DIR)/facet"

clean:
	rm -rf build facet

-include $(shell find build -name '*.d' 2>/dev/null)
