# certbox: proven, tight axis-aligned bounding boxes.
#   make          build the static and shared libraries and the demo (build/)
#   make demo     run the demo (the main job)
#   make check    run every test, proofs included (installs missing packages)
#   make proof    re-run the Frama-C/WP proofs and rewrite proofs/report.md
#   make install  PREFIX=/usr/local DESTDIR=
#   make mutants  mutation check: deliberate faults must all be caught
#   make fuzz     libFuzzer harnesses with the exact oracle (60 s each)

VERSION   := 0.1.0
SOVERSION := 0
PREFIX    ?= /usr/local
LIBDIR    ?= $(PREFIX)/lib
INCDIR    ?= $(PREFIX)/include
PCDIR     ?= $(LIBDIR)/pkgconfig

CC       ?= cc
CXX      ?= c++
# The proof assumes every operation rounds once to nearest in binary64:
# ISO C mode (no FMA contraction), no -ffast-math, SSE2 on x86.
IEEEFLAGS := -ffp-contract=off -fno-fast-math
WARN      := -Wall -Wextra -Wpedantic -Werror
CFLAGS   ?= -O2
ALLCFLAGS := -std=c99 $(WARN) $(IEEEFLAGS) $(CFLAGS) -Isrc
SANFLAGS  := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

B := build
# binary64 sources; the *_f.c files instantiate the same sources for binary32
LIBSRC  := src/cbx_interval.c src/cbx_center.c src/cbx_convert.c src/cbx_sphere.c src/cbx_status.c src/cbx_batch.c src/cbx_tight.c src/cbx_class.c src/cbx_motion.c \
           src/cbx_interval_f.c src/cbx_center_f.c src/cbx_convert_f.c src/cbx_sphere_f.c src/cbx_batch_f.c \
           src/cbx_ieee.c src/cbx_ieee_f.c
HEADERS := src/certbox.h src/cbx_api.h src/cbx_build.h src/cbx_prec.h src/cbx_prec_begin.h src/cbx_prec_end.h src/cbx_names_f.h src/cbx_round.h src/cbx_domain.h src/cbx_endpoints.h src/cbx_vertex.h src/cbx_kernel.h src/cbx_fast.h src/cbx_eft.h src/cbx_ieee_cases.h src/cbx_onebox.h specs/cbx_tight.h specs/cbx_logic.h specs/cbx_spec.h specs/cbx_ball.h specs/cbx_class.h
LIBOBJ  := $(LIBSRC:src/%.c=$(B)/obj/%.o)
PICOBJ  := $(LIBSRC:src/%.c=$(B)/pic/%.o)
# each *_f.c is a stub that #includes its binary64 source: rebuild it when
# that source changes
FAMSRC  := $(patsubst src/%_f.c,%,$(filter %_f.c,$(LIBSRC)))
$(foreach f,$(FAMSRC),$(eval $(B)/obj/$(f)_f.o $(B)/pic/$(f)_f.o: src/$(f).c))
SONAME  := libcertbox.so.$(SOVERSION)

.PHONY: fuzz fuzz-check mutants install-check all demo check check-deps check-deps-test check-deps-proof test test-san proof proof-check install uninstall clean header-check
all: $(B)/libcertbox.a $(B)/libcertbox.so $(B)/demo $(B)/certbox $(B)/certbox.pc

$(B)/obj/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -c $< -o $@
$(B)/pic/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -fPIC -fvisibility=default -c $< -o $@

$(B)/libcertbox.a: $(LIBOBJ)
	rm -f $@ && ar rcs $@ $^
$(B)/libcertbox.so.$(VERSION): $(PICOBJ)
	$(CC) -shared -Wl,-soname,$(SONAME) -o $@ $^ -lm
$(B)/libcertbox.so: $(B)/libcertbox.so.$(VERSION)
	ln -sf libcertbox.so.$(VERSION) $(B)/$(SONAME)
	ln -sf libcertbox.so.$(VERSION) $@

$(B)/certbox.pc: certbox.pc.in Makefile
	@mkdir -p $(@D)
	sed -e 's#@PREFIX@#$(PREFIX)#' -e 's#@LIBDIR@#$(LIBDIR)#' -e 's#@INCDIR@#$(INCDIR)#' \
	    -e 's#@VERSION@#$(VERSION)#' $< > $@

# ---- tests ---------------------------------------------------------------
TESTUTIL := tests/exact_util.c
$(B)/demo: examples/demo.c $(TESTUTIL) $(B)/libcertbox.a tests/exact_util.h
	$(CC) $(ALLCFLAGS) -Itests examples/demo.c $(TESTUTIL) $(B)/libcertbox.a -lmpfr -lgmp -lm -o $@
# The scene tool (issue 6): src/scene/, built with the library's flags.
SCENESRC := src/scene/scene.c
$(B)/certbox: src/scene/main.c $(SCENESRC) src/scene/scene.h $(B)/libcertbox.a
	$(CC) $(ALLCFLAGS) src/scene/main.c $(SCENESRC) $(B)/libcertbox.a -lm -o $@
$(B)/test_scene: tests/test_scene.c $(SCENESRC) src/scene/scene.h $(TESTUTIL) $(B)/libcertbox.a tests/exact_util.h
	$(CC) $(ALLCFLAGS) -Itests -Isrc/scene $< $(SCENESRC) $(TESTUTIL) $(B)/libcertbox.a -lmpfr -lgmp -lm -o $@
$(B)/san/test_scene: tests/test_scene.c $(SCENESRC) src/scene/scene.h $(TESTUTIL) $(LIBSRC) $(HEADERS) tests/exact_util.h
	@mkdir -p $(@D)
	$(CC) -std=c99 $(WARN) $(IEEEFLAGS) $(SANFLAGS) -Isrc -Isrc/scene -Itests $< $(SCENESRC) $(TESTUTIL) $(LIBSRC) -lmpfr -lgmp -lm -o $@
$(B)/test_%: tests/test_%.c $(TESTUTIL) $(B)/libcertbox.a tests/exact_util.h
	$(CC) $(ALLCFLAGS) -Itests $< $(TESTUTIL) $(B)/libcertbox.a -lmpfr -lgmp -lm -o $@
# the tight mode with the fma-free two_prod (Dekker's product, src/cbx_eft.h)
$(B)/test_tight_nofma: tests/test_tight.c $(TESTUTIL) $(LIBSRC) $(HEADERS) tests/exact_util.h
	$(CC) $(ALLCFLAGS) -DCBX_NO_FMA -Itests $< $(TESTUTIL) $(LIBSRC) -lmpfr -lgmp -lm -o $@
$(B)/san/test_%: tests/test_%.c $(TESTUTIL) $(LIBSRC) $(HEADERS) tests/exact_util.h
	@mkdir -p $(@D)
	$(CC) -std=c99 $(WARN) $(IEEEFLAGS) $(SANFLAGS) -Isrc -Itests $< $(TESTUTIL) $(LIBSRC) -lmpfr -lgmp -lm -o $@

demo: check-deps-test
	$(MAKE) $(B)/demo $(B)/certbox
	./$(B)/demo
	@echo; echo "== the scene tool on examples/robot.scene (format: examples/scene-format.md)"
	./$(B)/certbox examples/robot.scene

TESTS := exact badinput cbox sphere special chain alias halfspace batch tight classes scene float ieee eft
test: $(TESTS:%=$(B)/test_%) $(B)/test_tight_nofma $(B)/certbox
	./$(B)/test_badinput
	./$(B)/test_special
	./$(B)/test_exact 1000000 1
	./$(B)/test_cbox 300000 1
	./$(B)/test_sphere 200000 1
	./$(B)/test_alias 100000 1
	./$(B)/test_halfspace 150 1
	./$(B)/test_chain 1000 20 1
	./$(B)/test_batch 200 1
	./$(B)/test_tight 150 1
	./$(B)/test_tight_nofma 150 1
	./$(B)/test_eft 1000 1
	./$(B)/test_classes 200000 1
	./$(B)/test_float 200000 1
	./$(B)/test_ieee
	./$(B)/test_scene examples/*.scene
	for f in examples/*.scene; do ./$(B)/certbox $$f > /dev/null || exit 1; done
	! ./$(B)/certbox examples/scene-format.md > /dev/null 2>&1

# Sanitizers: same tests, fewer random cases (ASan/UBSan are ~3x slower).
test-san: $(TESTS:%=$(B)/san/test_%)
	./$(B)/san/test_badinput
	./$(B)/san/test_exact 200000 2
	./$(B)/san/test_cbox 100000 2
	./$(B)/san/test_sphere 30000 2
	./$(B)/san/test_special
	./$(B)/san/test_alias 20000 2
	./$(B)/san/test_halfspace 30 2
	./$(B)/san/test_chain 1000 10 2
	./$(B)/san/test_batch 200 2
	./$(B)/san/test_tight 50 2
	./$(B)/san/test_eft 200 2
	./$(B)/san/test_classes 50000 2
	./$(B)/san/test_float 50000 2
	./$(B)/san/test_ieee
	./$(B)/san/test_scene examples/*.scene

# Cortex-M4F and Cortex-M7, freestanding (arm-none-eabi-gcc): no libc beyond
# sqrt, code size and worst-case stack per function (build/embedded/report.md).
.PHONY: embedded check-cross
embedded:
	@sh scripts/deps.sh embedded
	python3 scripts/embedded.py

# The exact test suites on 32-bit ARM under qemu-user, output compared line
# by line with this machine's (scripts/cross.sh).
check-cross: $(TESTS:%=$(B)/test_%) $(B)/test_tight_nofma
	@sh scripts/deps.sh cross
	sh scripts/cross.sh

# The IEEE build check (cbx_ieee_check) and its teeth: bad flags and bad
# run-time modes must be caught, -ffast-math and x87 refused (scripts/ieee.sh).
.PHONY: ieee-check
ieee-check: all
	sh scripts/ieee.sh $(CC)

# The public header compiles as C99, C11 and C++; the binary32 name list is
# up to date and no macro of the precision tables leaks past certbox.h.
header-check:
	@mkdir -p $(B)
	python3 scripts/names.py --check
	printf '#include "certbox.h"\n#if defined(cbx_fp) || defined(CBX_INST) || defined(CBX_U) || defined(cbx_boxf) || defined(has_nan)\n#error leak\n#endif\nint main(void){cbx_box b; cbx_boxf f; (void)b; (void)f; return 0;}\n' > $(B)/hc.c
	$(CC) -std=c99 $(WARN) -Isrc -c $(B)/hc.c -o $(B)/hc.o
	$(CC) -std=c11 $(WARN) -Isrc -c $(B)/hc.c -o $(B)/hc.o
	cp $(B)/hc.c $(B)/hc.cc && $(CXX) -std=c++11 $(WARN) -Isrc -c $(B)/hc.cc -o $(B)/hc.o

# ---- proofs --------------------------------------------------------------
proof: check-deps-proof
	sh proofs/run.sh

proof-check: check-deps-proof
	sh proofs/run.sh --check

# The evidence pack (evidence/: claims, proof, tests, coverage, coding
# standard, tools, hashes; scripts/evidence.py), and its reproducibility:
# evidence-check makes the pack twice and compares them.
.PHONY: evidence evidence-check
# Both reuse the logs of the last proof run only if it proved these very
# sources (proofs/inputs.sh); otherwise they run the proofs first (a fresh
# clone: about 20 minutes on 2 cores).
PROOF_CURRENT = @sh proofs/inputs.sh --check || { echo "evidence: no proof run of these sources in $(B)/proof: running the proofs first"; $(MAKE) proof; }
evidence: all
	@sh scripts/deps.sh evidence
	$(PROOF_CURRENT)
	python3 scripts/evidence.py evidence
evidence-check: all $(TESTS:%=$(B)/test_%)
	@sh scripts/deps.sh evidence
	$(PROOF_CURRENT)
	python3 scripts/evidence.py evidence > $(B)/evidence-1.log 2>&1 & p=$$!; \
	python3 scripts/evidence.py $(B)/evidence-2 > $(B)/evidence-2.log 2>&1; s2=$$?; \
	wait $$p; s1=$$?; cat $(B)/evidence-1.log; tail -3 $(B)/evidence-2.log; \
	[ $$s1 = 0 ] && [ $$s2 = 0 ]
	python3 scripts/evidence.py --compare evidence $(B)/evidence-2

# Do the smoke tests catch inconsistent contracts at their step budget?
.PHONY: smoke-teeth
smoke-teeth: check-deps-proof
	sh scripts/smoke_teeth.sh

check-deps-test:
	@sh scripts/deps.sh test
check-deps:
	@sh scripts/deps.sh all
check-deps-proof:
	@sh scripts/deps.sh proof

# Each step stops the run on failure; the last line counts the steps.
# Independent steps run two at a time (each is single-threaded; the proofs
# and the smoke teeth use both cores on their own).
# Each step's time is printed (check: NAME: N s).
TIMED = sh scripts/timed.sh
check: check-deps
	$(TIMED) build $(MAKE) -j2 all $(TESTS:%=$(B)/test_%) $(TESTS:%=$(B)/san/test_%) $(B)/bench
	$(TIMED) header-check $(MAKE) header-check
	$(TIMED) test+test-san $(MAKE) -j2 test test-san
	$(TIMED) ieee-check+bench-smoke+install-check+embedded+branchfree $(MAKE) -j2 ieee-check bench-smoke install-check embedded branchfree
	$(TIMED) fuzz-check+check-cross $(MAKE) -j2 fuzz-check check-cross
	$(TIMED) proof-check $(MAKE) proof-check
	$(TIMED) smoke-teeth $(MAKE) smoke-teeth
	$(TIMED) evidence-check $(MAKE) evidence-check
	@echo "check: 14 phases passed (build, header-check, test, test-san, ieee-check, bench-smoke, install-check, embedded, branchfree, fuzz-check, check-cross, proof-check, smoke-teeth, evidence-check), 0 failed"

# make install into a scratch DESTDIR, then build a program against it
# with pkg-config, static and shared.
install-check: all
	rm -rf $(B)/stage
	$(MAKE) install DESTDIR=$(CURDIR)/$(B)/stage PREFIX=/opt/certbox
	printf '#include <certbox.h>\n#include <stdio.h>\nint main(void){cbx_affine a={{{1,0,0,1},{0,1,0,2},{0,0,1,3}}};cbx_box b={{0,0,0},{1,1,1}},o;cbx_affinef af={{{1,0,0,1},{0,1,0,2},{0,0,1,3}}};cbx_boxf bf={{0,0,0},{1,1,1}},of;int s=cbx_transform_box(&a,&b,&o),t=cbx_transform_boxf(&af,&bf,&of);unsigned c=cbx_ieee_check();printf("%%s %%g %%g; %%s %%g %%g; ieee %%u\\n",cbx_status_name(s),o.lo[0],o.hi[0],cbx_status_name(t),(double)of.lo[0],(double)of.hi[0],c);return s||t||c;}\n' > $(B)/ic.c
	PKG_CONFIG_SYSROOT_DIR=$(CURDIR)/$(B)/stage PKG_CONFIG_LIBDIR=$(CURDIR)/$(B)/stage/opt/certbox/lib/pkgconfig \
	  sh -c '$(CC) -std=c99 $(WARN) $(B)/ic.c $$(pkg-config --cflags --libs certbox) -o $(B)/ic && LD_LIBRARY_PATH=$(CURDIR)/$(B)/stage/opt/certbox/lib ./$(B)/ic'
	test -L $(B)/stage/opt/certbox/lib/libcertbox.so.$(SOVERSION)

# ---- install -------------------------------------------------------------
# certbox.h and what it includes (both families' API, the precision tables,
# and the ACSL logic that Frama-C users of the contracts need).
PUBHDR := src/certbox.h src/cbx_api.h src/cbx_prec_begin.h src/cbx_prec_end.h src/cbx_names_f.h \
          specs/cbx_logic.h specs/cbx_spec.h specs/cbx_ball.h specs/cbx_class.h
install: all
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCDIR) $(DESTDIR)$(PCDIR)
	install -m 644 $(B)/libcertbox.a $(DESTDIR)$(LIBDIR)/
	install -m 755 $(B)/libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/
	ln -sf libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libcertbox.so
	install -m 644 $(PUBHDR) $(DESTDIR)$(INCDIR)/
	sed -e 's#@PREFIX@#$(PREFIX)#' -e 's#@LIBDIR@#$(LIBDIR)#' -e 's#@INCDIR@#$(INCDIR)#' \
	    -e 's#@VERSION@#$(VERSION)#' certbox.pc.in > $(DESTDIR)$(PCDIR)/certbox.pc

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/libcertbox.a $(DESTDIR)$(LIBDIR)/libcertbox.so* \
	      $(addprefix $(DESTDIR)$(INCDIR)/,$(notdir $(PUBHDR))) $(DESTDIR)$(PCDIR)/certbox.pc

# libFuzzer harnesses with the exact GMP oracle (tests/fuzz/); needs clang.
fuzz: check-deps-test
	@sh scripts/deps.sh fuzz
	sh scripts/fuzz.sh 60
fuzz-check: check-deps-test
	@sh scripts/deps.sh fuzz
	sh scripts/fuzz.sh 10

# Mutation check: deliberate faults in a scratch copy must all be caught.
mutants: check-deps-test
	bash scripts/mutants.sh

clean:
	rm -rf $(B)

# ---- benchmark (issue 5) ---------------------------------------------------
# make bench        the tables (build/bench-out/bench.md, bench.dat, bench.png)
# make bench-smoke  the same tables on tiny sizes (a few seconds per build; a
#                   step of make check: fails on a containment failure in a
#                   certbox row, a prepared or batch output not bit-identical
#                   to cbx_transform_box(f)'s, or a certbox output that differs
#                   between the two builds); no plot unless gnuplot is already
#                   installed
# Two builds of tests/bench.c, each against the library compiled with the
# same flags, run one after the other and merged by scripts/bench_table.py
# into one table, one column group per build:
#   build/bench         the library's flags (ALLCFLAGS: -std=c99 -ffp-contract=off
#                       -fno-fast-math -O2), build/libcertbox.a
#   build/bench-native  the same with -O3 -march=native (BENCHNATIVE), against
#                       build/native/libcertbox.a (objects in build/native/obj)
BENCHARGS      := -n 20000 -r 11 -calls 200000 -exact 20000 -gmp 2000 -cache 1000 -big 4000000
BENCHSMOKEARGS := -n 2000 -r 11 -calls 10000 -exact 2000 -gmp 200 -cache 500 -big 50000
BENCHNATIVE    := -O3 -march=native
NATIVECFLAGS   := -std=c99 $(WARN) $(IEEEFLAGS) $(BENCHNATIVE) -Isrc
NATIVEOBJ      := $(LIBSRC:src/%.c=$(B)/native/obj/%.o)
BENCHSRC       := tests/bench.c tests/bench_ref.h $(TESTUTIL) tests/exact_util.h
.PHONY: bench bench-smoke branchfree
$(foreach f,$(FAMSRC),$(eval $(B)/native/obj/$(f)_f.o: src/$(f).c))
$(B)/native/obj/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(NATIVECFLAGS) -c $< -o $@
$(B)/native/libcertbox.a: $(NATIVEOBJ)
	rm -f $@ && ar rcs $@ $^
$(B)/bench: $(BENCHSRC) $(B)/libcertbox.a
	$(CC) $(ALLCFLAGS) -Itests -DBENCH_CC='"$(CC)"' -DBENCH_FLAGS='"$(ALLCFLAGS)"' \
	  -DBENCH_LABEL='"$(strip $(CFLAGS))"' tests/bench.c $(TESTUTIL) $(B)/libcertbox.a -lmpfr -lgmp -lm -o $@
$(B)/bench-native: $(BENCHSRC) $(B)/native/libcertbox.a
	$(CC) $(NATIVECFLAGS) -Itests -DBENCH_CC='"$(CC)"' -DBENCH_FLAGS='"$(NATIVECFLAGS)"' \
	  -DBENCH_LABEL='"$(BENCHNATIVE)"' tests/bench.c $(TESTUTIL) $(B)/native/libcertbox.a -lmpfr -lgmp -lm -o $@

# BENCH_RUN(dir, args): both builds, one after the other, then the merged table
BENCH_RUN = ./$(B)/bench $(2) -o $(1)/O2 && ./$(B)/bench-native $(2) -o $(1)/native && \
	python3 scripts/bench_table.py $(1) $(1)/O2 $(1)/native

bench: check-deps-test
	@sh scripts/deps.sh bench || echo "bench: note: gnuplot could not be installed; the plot will be skipped"
	$(MAKE) $(B)/bench $(B)/bench-native
	$(call BENCH_RUN,$(B)/bench-out,$(BENCHARGS))
	@sh scripts/bench_plot.sh $(B)/bench-out

bench-smoke: check-deps-test
	$(MAKE) $(B)/bench $(B)/bench-native
	$(call BENCH_RUN,$(B)/bench-smoke,$(BENCHSMOKEARGS))
	@sh scripts/bench_plot.sh $(B)/bench-smoke

# The fast path is branch-free: cbx_fast_box (src/cbx_fast.h), both formats,
# compiled with the library's flags at -O2 into two wrappers, disassembled;
# fails on any conditional branch or call in them (scripts/branchfree.sh).
branchfree:
	sh scripts/branchfree.sh "$(CC)" -std=c99 $(WARN) $(IEEEFLAGS) -O2 -Isrc -Ispecs
