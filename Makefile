# certbox: proven, tight axis-aligned bounding boxes.  What a target makes
# goes to build/; only make install and make proof-report write elsewhere.
#   make          the static and shared libraries (build/libcertbox.a,
#                 build/libcertbox.so*), build/certbox.pc and the scene tool
#                 build/certbox: a C compiler is all it needs (no GMP/MPFR;
#                 glTF input when pkg-config finds jansson, docs/gltf.md)
#   make demo     build the demo (links the GMP/MPFR test oracle) and run it,
#                 then the scene tool on examples/robot.scene (installs
#                 missing packages)
#   make check    every test, proofs included (installs missing packages);
#                 ends by checking that the run left the git checkout as it
#                 found it (a clean clone stays clean)
#   make install  PREFIX=/usr/local DESTDIR=: the libraries, certbox.h and the
#                 headers it includes, certbox.pc, and the CMake package
#                 (LIBDIR/cmake/certbox: find_package(certbox), targets
#                 certbox::certbox and certbox::certbox_static)
#   make proof    re-prove what changed (WP cache kept in build/proof-cache);
#                 make proof-check proves everything from scratch (as make check);
#                 report in build/proof/report.md
#   make proof-report  copy that report to the committed proofs/report.md
#   make evidence the evidence pack for an assessor, in build/evidence/
#   make mutants  mutation check: deliberate faults must all be caught
#   make fuzz     libFuzzer harnesses with the exact oracle (60 s each; the
#                 glTF reader's only with jansson)

VERSION   := 0.1.0
SOVERSION := 0
PREFIX    ?= /usr/local
LIBDIR    ?= $(PREFIX)/lib
INCDIR    ?= $(PREFIX)/include
PCDIR     ?= $(LIBDIR)/pkgconfig
CMAKEDIR  ?= $(LIBDIR)/cmake/certbox

# Plain make builds `all`, whatever rule comes first below (the $(eval ...)
# rules for the *_f.o objects would otherwise be the default goal).
.DEFAULT_GOAL := all

CC       ?= cc
CXX      ?= c++
# The proof assumes every operation rounds once to nearest in binary64:
# ISO C mode (no FMA contraction), no -ffast-math, SSE2 on x86.
IEEEFLAGS := -ffp-contract=off -fno-fast-math
WARN      := -Wall -Wextra -Wpedantic -Werror
CFLAGS   ?= -O2
# the public headers, then the layers of src/ (scripts/incs.sh: the same list)
INC       := -Iinclude -Isrc/core -Isrc/algo -Isrc/f64
ALLCFLAGS := -std=c99 $(WARN) $(IEEEFLAGS) $(CFLAGS) $(INC)
# programs that use the library as a client would: the public header alone
PUBCFLAGS := -std=c99 $(WARN) $(IEEEFLAGS) $(CFLAGS) -Iinclude
SANFLAGS  := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
# the library, its oracles and its tests under ASan/UBSan
SANCFLAGS := -std=c99 $(WARN) $(IEEEFLAGS) $(SANFLAGS) $(INC)

B := build
# binary64 sources; the *_f.c files instantiate the same sources for binary32
# every source of src/ (binary64 in core/, algo/, f64/; the *_f.c stubs of
# f32/ instantiate the same sources for binary32), and every header the
# library and its proofs read: what is in the tree is built, nothing listed
LIBSRC  := $(sort $(wildcard src/*/cbx_*.c))
HEADERS := $(sort $(wildcard include/*.h src/*/*.h specs/*.h))
LIBOBJ  := $(LIBSRC:src/%.c=$(B)/obj/%.o)
PICOBJ  := $(LIBSRC:src/%.c=$(B)/pic/%.o)
SANOBJ  := $(LIBSRC:src/%.c=$(B)/san/obj/%.o)
# each *_f.c is a stub that #includes its binary64 source: rebuild it when
# that source changes
FAMSRC  := $(patsubst src/f32/%_f.c,%,$(filter %_f.c,$(LIBSRC)))
famof    = $(filter %/$(1).c,$(LIBSRC))
$(foreach f,$(FAMSRC),$(eval $(B)/obj/f32/$(f)_f.o $(B)/pic/f32/$(f)_f.o $(B)/san/obj/f32/$(f)_f.o: $(call famof,$(f))))
SONAME  := libcertbox.so.$(SOVERSION)

.PHONY: fuzz fuzz-check mutants install-check all demo check check-deps check-deps-test check-deps-proof test test-san proof proof-check install uninstall clean header-check
# What a user builds: only a C compiler needed.  The demo and the tests link
# the GMP/MPFR oracle: make demo, make test, make check build them.
all: $(B)/libcertbox.a $(B)/libcertbox.so $(B)/certbox.pc $(B)/certbox

$(B)/obj/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -c $< -o $@
$(B)/pic/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -fPIC -fvisibility=default -c $< -o $@

# the library once more under ASan/UBSan, linked by every sanitizer test
$(B)/san/obj/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(SANCFLAGS) -c $< -o $@

$(B)/libcertbox.a: $(LIBOBJ)
	rm -f $@ && ar rcs $@ $^
$(B)/san/libcertbox.a: $(SANOBJ)
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
# the oracles and helpers every test links (scripts/testutil.sh: the same list
# for the scripts that build tests outside make), compiled once per flavour
# into an archive that every test links (the 3,100 lines used to be
# compiled again for each of the 48 test programs: most of the build step)
TESTUTIL := $(shell sh scripts/testutil.sh)
TESTHDR  := $(sort $(wildcard tests/*.h))
TU       := $(B)/libtestutil.a
SANTU    := $(B)/san/libtestutil.a
# GMP and MPFR: static where their archives are there (scripts/exactlibs.sh
# says why; scripts/evidence.py links the same way)
EXACTLIBS := $(shell sh scripts/exactlibs.sh $(CC))
$(B)/tu/%.o: tests/%.c $(TESTHDR) $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -Itests -c $< -o $@
$(B)/san/tu/%.o: tests/%.c $(TESTHDR) $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(SANCFLAGS) -Itests -c $< -o $@
$(TU): $(TESTUTIL:tests/%.c=$(B)/tu/%.o)
	rm -f $@ && ar rcs $@ $^
$(SANTU): $(TESTUTIL:tests/%.c=$(B)/san/tu/%.o)
	rm -f $@ && ar rcs $@ $^
$(B)/demo: examples/demo.c $(TU) $(B)/libcertbox.a $(TESTHDR)
	$(CC) $(PUBCFLAGS) -Itests examples/demo.c $(TU) $(B)/libcertbox.a $(EXACTLIBS) -lm -o $@
# The scene tool (issue 6): tools/certbox/, built with the library's flags.  An
# optional dependency of the tool adds its flags to TOOL_CFLAGS and its
# libraries to TOOL_LIBS (before -lm); the library itself never links them.
SCENESRC   := tools/certbox/scene.c
TOOL_CFLAGS :=
TOOL_LIBS   :=
# glTF input (issue 18: tools/certbox/gltf.c, docs/gltf.md) parses JSON with
# jansson, the tool's optional dependency: found by pkg-config, the tool
# reads glTF (-DCBX_GLTF); not found, it is built without (a note here, and
# a clear error for a glTF file).  test_gltf needs it (deps.sh test).
GLTFSRC      := tools/certbox/gltf.c
GLTFDIR      := /usr/share/assimp/models/glTF2
HAVE_JANSSON := $(shell pkg-config --exists jansson 2>/dev/null && echo 1)
ifeq ($(HAVE_JANSSON),1)
TOOL_CFLAGS  += -DCBX_GLTF $(shell pkg-config --cflags jansson)
TOOL_LIBS    += $(shell pkg-config --libs jansson)
endif
# build/tool-config changes when jansson comes or goes: the tool is rebuilt
TOOL_STAMP   := $(B)/tool-config
$(shell mkdir -p $(B) && { [ "$$(cat $(TOOL_STAMP) 2>/dev/null)" = "gltf=$(HAVE_JANSSON)" ] || echo "gltf=$(HAVE_JANSSON)" > $(TOOL_STAMP); })
NEED_JANSSON = @[ "$(HAVE_JANSSON)" = 1 ] || { echo "$@: needs jansson (libjansson-dev): run sh scripts/deps.sh test as root, or apt-get install libjansson-dev" >&2; exit 1; }
$(B)/certbox: tools/certbox/main.c $(SCENESRC) $(GLTFSRC) tools/certbox/scene.h tools/certbox/gltf.h tools/certbox/readall.h $(B)/libcertbox.a $(TOOL_STAMP)
	@[ "$(HAVE_JANSSON)" = 1 ] || echo "$@: note: jansson (libjansson-dev) not found: the tool is built without glTF input" >&2
	$(CC) $(PUBCFLAGS) $(TOOL_CFLAGS) tools/certbox/main.c $(SCENESRC) $(GLTFSRC) $(B)/libcertbox.a $(TOOL_LIBS) -lm -o $@
# the exact oracle of test_gltf, shared with the fuzz harness (tests/fuzz/fuzz_gltf.c),
# and test_gltf's --animated checks (tests/gltf_anim.c: test_gltf only); both
# need the tool's headers and jansson, so they are not in $(TU)
GLTFORACLE   := tests/gltf_oracle.c tests/gltf_anim.c
$(B)/test_gltf: tests/test_gltf.c $(GLTFORACLE) $(TU) $(TESTHDR) $(GLTFSRC) tools/certbox/gltf.h tools/certbox/readall.h $(B)/libcertbox.a
	$(NEED_JANSSON)
	$(CC) $(PUBCFLAGS) $(TOOL_CFLAGS) -Itests -Itools/certbox $< $(GLTFORACLE) $(GLTFSRC) $(TU) $(B)/libcertbox.a $(TOOL_LIBS) $(EXACTLIBS) -lm -o $@
$(B)/san/test_gltf: tests/test_gltf.c $(GLTFORACLE) $(SANTU) $(TESTHDR) $(GLTFSRC) tools/certbox/gltf.h tools/certbox/readall.h $(B)/san/libcertbox.a $(HEADERS)
	$(NEED_JANSSON)
	@mkdir -p $(@D)
	$(CC) $(SANCFLAGS) $(TOOL_CFLAGS) -Itools/certbox -Itests $< $(GLTFORACLE) $(GLTFSRC) $(SANTU) $(B)/san/libcertbox.a $(TOOL_LIBS) $(EXACTLIBS) -lm -o $@
$(B)/test_scene: tests/test_scene.c $(SCENESRC) tools/certbox/scene.h tools/certbox/readall.h $(TU) $(B)/libcertbox.a $(TESTHDR)
	$(CC) $(PUBCFLAGS) -Itests -Itools/certbox $< $(SCENESRC) $(TU) $(B)/libcertbox.a $(EXACTLIBS) -lm -o $@
$(B)/san/test_scene: tests/test_scene.c $(SCENESRC) tools/certbox/scene.h tools/certbox/readall.h $(SANTU) $(B)/san/libcertbox.a $(HEADERS) $(TESTHDR)
	@mkdir -p $(@D)
	$(CC) $(SANCFLAGS) -Itools/certbox -Itests $< $(SCENESRC) $(SANTU) $(B)/san/libcertbox.a $(EXACTLIBS) -lm -o $@
$(B)/test_%: tests/test_%.c $(TU) $(B)/libcertbox.a $(TESTHDR)
	$(CC) $(ALLCFLAGS) -Itests $< $(TU) $(B)/libcertbox.a $(EXACTLIBS) -lm -o $@
# the tight mode with the fma-free two_prod (Dekker's product, src/core/cbx_eft.h)
$(B)/test_tight_nofma: tests/test_tight.c $(TU) $(LIBSRC) $(HEADERS) $(TESTHDR)
	$(CC) $(ALLCFLAGS) -DCBX_NO_FMA -Itests $< $(LIBSRC) $(TU) $(EXACTLIBS) -lm -o $@
$(B)/san/test_%: tests/test_%.c $(SANTU) $(B)/san/libcertbox.a $(HEADERS) $(TESTHDR)
	@mkdir -p $(@D)
	$(CC) $(SANCFLAGS) -Itests $< $(SANTU) $(B)/san/libcertbox.a $(EXACTLIBS) -lm -o $@

demo: check-deps-test
	$(MAKE) $(B)/demo $(B)/certbox
	./$(B)/demo
	@echo; echo "== the scene tool on examples/robot.scene (format: examples/scene-format.md)"
	./$(B)/certbox examples/robot.scene

TESTS := exact badinput cbox sphere special chain alias halfspace batch tight classes scene float ieee eft gltf imat plane project trs psphere pnear pball pwide pell
# Each suite with its arguments: one target per run (run-NAME, san-NAME), so
# that make -j2 (make check) spreads the runs over both cores; -Otarget
# keeps each run's output together.  One line per suite: its name, its
# arguments, and its arguments under the sanitizers (fewer random cases:
# ASan/UBSan are ~3x slower; 2026-12-01, to keep make check within CI's 30
# minutes: pwide, tight, project and batch halved or less under the
# sanitizers, 36 s of CPU to 19 s, still at least the evidence pack's sizes,
# whose runs take every branch of src/; tight_nofma, the fma-free product's
# run of test_tight, 50 thousand cases: 16 s of CPU to about 5 s).
define suite
A_$(1)  := $(2)
SA_$(1) := $(3)
endef
$(eval $(call suite,badinput,,))
$(eval $(call suite,special,,))
$(eval $(call suite,exact,1000000 1,200000 2))
$(eval $(call suite,cbox,300000 1,100000 2))
$(eval $(call suite,sphere,200000 1,30000 2))
$(eval $(call suite,alias,100000 1,20000 2))
$(eval $(call suite,halfspace,150 1,30 2))
$(eval $(call suite,imat,200000 50000 1,40000 10000 2))
$(eval $(call suite,chain,1000 20 1,1000 10 2))
$(eval $(call suite,batch,200 1,50 2))
$(eval $(call suite,tight,150 1,25 2))
$(eval $(call suite,tight_nofma,50 1,))
$(eval $(call suite,eft,1000 1,200 2))
$(eval $(call suite,classes,200000 1,50000 2))
$(eval $(call suite,float,200000 1,50000 2))
$(eval $(call suite,plane,200000 1,40000 2))
$(eval $(call suite,project,20000 1,2000 2))
$(eval $(call suite,trs,100000 1,10000 2))
$(eval $(call suite,psphere,20000 1,4000 2))
$(eval $(call suite,pnear,20000 1,3000 2))
$(eval $(call suite,pball,20000 1,3000 2))
$(eval $(call suite,pwide,20000 1,3000 2))
$(eval $(call suite,pell,20000 1,4000 2))
$(eval $(call suite,ieee,,))
$(eval $(call suite,scene,examples/*.scene,examples/*.scene))
$(eval $(call suite,gltf,$(GLTFDIR) tests/data/gltf $(B)/certbox,$(GLTFDIR) tests/data/gltf $(B)/certbox))
# the longest runs first, so that make -j2 ends on short ones (2026-12-01,
# CPU seconds at -O2: trs 31, classes 19, pwide 18, tight 17, project 16,
# sphere 11; the rest 7 or less)
LONGEST  := trs classes pwide tight project sphere
RUNS     := $(LONGEST) $(filter-out $(LONGEST),$(TESTS)) tight_nofma
RUNS_SAN := $(filter-out tight_nofma,$(RUNS))
.PHONY: $(RUNS:%=run-%) $(RUNS_SAN:%=san-%) run-tool
test: $(RUNS:%=run-%) run-tool
test-san: $(RUNS_SAN:%=san-%)
$(RUNS:%=run-%): run-%: $(B)/test_% $(B)/certbox
	./$(B)/test_$* $(A_$*)
$(RUNS_SAN:%=san-%): san-%: $(B)/san/test_% $(B)/certbox
	./$(B)/san/test_$* $(SA_$*)
# the scene tool on every example, and its refusal of a file that is not one
run-tool: $(B)/certbox
	for f in examples/*.scene; do ./$(B)/certbox $$f > /dev/null || exit 1; done
	! ./$(B)/certbox examples/scene-format.md > /dev/null 2>&1

# Cortex-M4F and Cortex-M7, freestanding (arm-none-eabi-gcc): no libc beyond
# sqrt, code size and worst-case stack per function (build/embedded/report.md).
.PHONY: embedded check-cross
embedded:
	@sh scripts/deps.sh embedded
	python3 scripts/embedded.py

# The exact test suites on 32-bit ARM under qemu-user, output compared line
# by line with this machine's (scripts/cross.sh); test_gltf with the armhf
# jansson (skipped with a message without it).
check-cross: $(TESTS:%=$(B)/test_%) $(B)/test_tight_nofma
	@sh scripts/deps.sh cross
	sh scripts/cross.sh

# The IEEE build check (cbx_ieee_check) and its teeth: bad flags and bad
# run-time modes must be caught, -ffast-math and x87 refused (scripts/ieee.sh).
.PHONY: ieee-check
ieee-check: all
	sh scripts/ieee.sh $(CC)

# The public header compiles as C99, C11 and C++; the binary32 name list is
# up to date and no macro of the precision tables leaks past certbox.h;
# include/ alone on the include path (what an install holds).
header-check:
	@mkdir -p $(B)
	python3 scripts/names.py --check
	printf '#include "certbox.h"\n#if defined(cbx_fp) || defined(CBX_INST) || defined(CBX_U) || defined(cbx_boxf) || defined(has_nan)\n#error leak\n#endif\nint main(void){cbx_box b; cbx_boxf f; (void)b; (void)f; return 0;}\n' > $(B)/hc.c
	$(CC) -std=c99 $(WARN) -Iinclude -c $(B)/hc.c -o $(B)/hc.o
	$(CC) -std=c11 $(WARN) -Iinclude -c $(B)/hc.c -o $(B)/hc.o
	cp $(B)/hc.c $(B)/hc.cc && $(CXX) -std=c++11 $(WARN) -Iinclude -c $(B)/hc.cc -o $(B)/hc.o

# ---- proofs --------------------------------------------------------------
# Both write build/proof (logs, report.md); no tracked file changes.
# proof-report refreshes the committed proofs/report.md from the last run,
# only if that run proved the checkout's current sources (proofs/inputs.sh).
.PHONY: proof-report
# make proof (development): WP's cache kept in $(B)/proof-cache, so only
# what changed is re-proved; make proof-check (make check, CI): every goal
# from scratch.
proof: check-deps-proof
	CBX_WP_KEEP_CACHE=$(CURDIR)/$(B)/proof-cache sh proofs/run.sh

proof-check: check-deps-proof
	sh proofs/run.sh --check

proof-report:
	@test -f $(B)/proof/report.md || { echo "proof-report: no $(B)/proof/report.md: run make proof first"; exit 1; }
	@sh proofs/inputs.sh --check || { echo "proof-report: $(B)/proof is not a run on these sources (proofs/inputs.sh): run make proof first"; exit 1; }
	@! grep -q 'from a kept WP cache' $(B)/proof/report.md || { echo "proof-report: that run read goals from the kept cache: run make proof-check (from scratch) first"; exit 1; }
	cp $(B)/proof/report.md proofs/report.md
	@tail -n 2 proofs/report.md

# The evidence pack ($(B)/evidence/: claims, proof, tests, coverage, coding
# standard, tools, hashes; scripts/evidence.py), and its reproducibility:
# evidence-check makes the pack twice and compares them.
.PHONY: evidence evidence-check
# Both reuse the logs of the last proof run only if it proved these very
# sources (proofs/inputs.sh); otherwise they run the proofs first (a fresh
# clone: about 18 minutes on 2 cores on 2026-11-30, more on slower
# machines: docs/measurements.md).
PROOF_CURRENT = @{ sh proofs/inputs.sh --check && ! grep -q 'from a kept WP cache' $(B)/proof/report.md; } || { echo "evidence: no from-scratch proof run of these sources in $(B)/proof: running the proofs first"; $(MAKE) proof-check; }
evidence: all
	@sh scripts/deps.sh evidence
	$(PROOF_CURRENT)
	python3 scripts/evidence.py $(B)/evidence
evidence-check: all $(TESTS:%=$(B)/test_%)
	@sh scripts/deps.sh evidence
	$(PROOF_CURRENT)
	python3 scripts/evidence.py $(B)/evidence > $(B)/evidence-1.log 2>&1 & p=$$!; \
	python3 scripts/evidence.py $(B)/evidence-2 > $(B)/evidence-2.log 2>&1; s2=$$?; \
	wait $$p; s1=$$?; cat $(B)/evidence-1.log; tail -3 $(B)/evidence-2.log; \
	[ $$s1 = 0 ] && [ $$s2 = 0 ]
	python3 scripts/evidence.py --compare $(B)/evidence $(B)/evidence-2

# Do the smoke tests catch inconsistent contracts at their step budget?
.PHONY: smoke-teeth
smoke-teeth: check-deps-proof
	sh scripts/smoke_teeth.sh

# Do the contracts reject weakened bodies (sound but loose)?
.PHONY: proof-teeth
proof-teeth: check-deps-proof
	sh scripts/proof_teeth.sh

check-deps-test:
	@sh scripts/deps.sh test
check-deps:
	@sh scripts/deps.sh all
check-deps-proof:
	@sh scripts/deps.sh proof

# Each step stops the run on failure; the last line counts the steps.
# Independent steps run two at a time (each is single-threaded; the proofs
# and the smoke teeth use both cores on their own).
# Each step's time is printed (check: NAME: N s).  The last step fails if
# the run changed the git checkout (scripts/clean_tree.sh): every generated
# file belongs in build/.
TIMED = sh scripts/timed.sh
.PHONY: clean-tree-check
check: check-deps
	@sh scripts/clean_tree.sh save $(B)/clean-tree.before
	$(TIMED) build $(MAKE) -j2 all $(B)/demo $(TESTS:%=$(B)/test_%) $(TESTS:%=$(B)/san/test_%) $(B)/bench
	$(TIMED) header-check $(MAKE) header-check
	$(TIMED) test+test-san+ieee-check+bench-smoke+install-check+embedded+branchfree $(MAKE) -j2 -Otarget test test-san ieee-check bench-smoke install-check embedded branchfree
	$(TIMED) fuzz-check+check-cross $(MAKE) -j2 fuzz-check check-cross
	$(TIMED) proof-check $(MAKE) proof-check
	$(TIMED) smoke-teeth+proof-teeth $(MAKE) -j2 smoke-teeth proof-teeth
	$(TIMED) evidence-check $(MAKE) evidence-check
	$(TIMED) clean-tree $(MAKE) clean-tree-check
	@echo "check: 16 phases passed (build, header-check, test, test-san, ieee-check, bench-smoke, install-check, embedded, branchfree, fuzz-check, check-cross, proof-check, smoke-teeth, proof-teeth, evidence-check, clean-tree), 0 failed"

# Is the checkout as make check found it?  (In a git work tree: git status
# shows nothing, or only the local changes that were there before the run.)
clean-tree-check:
	sh scripts/clean_tree.sh check $(B)/clean-tree.before

# make install into a scratch DESTDIR (PREFIX=/opt/certbox staged in
# build/stage), then build programs against it and run them:
#   pkg-config  examples/cmake-consumer/main.c (both families) with $(CC), and
#               the C++ example examples/cpp/example.cpp with $(CXX)
#               -std=c++11 and the warnings as errors
#   CMake       examples/cmake-consumer: find_package(certbox 0.1) from the
#               staged prefix (the package config is relocatable), main.c
#               against certbox::certbox and certbox::certbox_static, the
#               C++ example against certbox::certbox; then a version the
#               install does not satisfy (0.2) must be refused
STAGE := $(CURDIR)/$(B)/stage/opt/certbox
STAGE_PC = PKG_CONFIG_SYSROOT_DIR=$(CURDIR)/$(B)/stage PKG_CONFIG_LIBDIR=$(STAGE)/lib/pkgconfig
install-check: all check-deps-test
	rm -rf $(B)/stage $(B)/cmake-consumer
	$(MAKE) install DESTDIR=$(CURDIR)/$(B)/stage PREFIX=/opt/certbox
	test -L $(B)/stage/opt/certbox/lib/libcertbox.so.$(SOVERSION)
	$(STAGE_PC) sh -c '$(CC) -std=c99 $(WARN) examples/cmake-consumer/main.c $$(pkg-config --cflags --libs certbox) -o $(B)/ic'
	LD_LIBRARY_PATH=$(STAGE)/lib ./$(B)/ic
	$(STAGE_PC) sh -c '$(CXX) -std=c++11 $(WARN) examples/cpp/example.cpp $$(pkg-config --cflags --libs certbox) -o $(B)/icpp'
	LD_LIBRARY_PATH=$(STAGE)/lib ./$(B)/icpp
	CC='$(CC)' CXX='$(CXX)' cmake -S examples/cmake-consumer -B $(B)/cmake-consumer \
	  -DCMAKE_PREFIX_PATH=$(STAGE) > $(B)/cmake-consumer.log 2>&1 || { cat $(B)/cmake-consumer.log; exit 1; }
	grep -qx 'certbox_DIR:PATH=$(STAGE)/lib/cmake/certbox' $(B)/cmake-consumer/CMakeCache.txt
	MAKEFLAGS= cmake --build $(B)/cmake-consumer > $(B)/cmake-consumer-build.log 2>&1 || { cat $(B)/cmake-consumer-build.log; exit 1; }
	./$(B)/cmake-consumer/consumer && ./$(B)/cmake-consumer/consumer_static && ./$(B)/cmake-consumer/consumer_cpp
	readelf -d $(B)/cmake-consumer/consumer | grep -q 'NEEDED.*\[libcertbox\.so\.$(SOVERSION)\]'
	! readelf -d $(B)/cmake-consumer/consumer_static | grep -q 'NEEDED.*libcertbox'
	! cmake -S examples/cmake-consumer -B $(B)/cmake-consumer -DCERTBOX_WANT=0.2 > $(B)/cmake-consumer-0.2.log 2>&1
	grep -q 'version: 0.1.0' $(B)/cmake-consumer-0.2.log
	@echo "install-check: pkg-config (C, C++11) and CMake (shared, static, C++11) consumers of the staged install built and ran; find_package(certbox 0.2) refused"

# ---- install -------------------------------------------------------------
# certbox.h and what it includes (both families' API, the precision tables,
# and the ACSL logic that Frama-C users of the contracts need).
PUBHDR := $(wildcard include/*.h) \
          specs/cbx_logic.h specs/cbx_spec.h specs/cbx_ball.h specs/cbx_class.h specs/cbx_plane.h \
          specs/cbx_proj_logic.h specs/cbx_proj.h
# The CMake package (cmake/*.cmake.in): its paths relative to its own place
# (realpath -s: by name, not through this machine's symlinks), so that the
# install can be staged or moved; absolute if they have no relative form.
CMAKE_SUBST = lib=$$(realpath -m -s --relative-to='$(CMAKEDIR)' '$(LIBDIR)' 2>/dev/null) || lib='$(LIBDIR)'; \
	inc=$$(realpath -m -s --relative-to='$(LIBDIR)' '$(INCDIR)' 2>/dev/null) || inc='$(INCDIR)'; \
	ptr=$$($(CC) -dM -E -x c /dev/null | sed -n 's/^\#define __SIZEOF_POINTER__ //p'); \
	subst() { sed -e "s\#@LIBDIR_FROM_CMAKEDIR@\#$$lib\#g" -e "s\#@INCDIR_FROM_LIBDIR@\#$$inc\#g" \
	  -e "s\#@SIZEOF_VOID_P@\#$$ptr\#g" -e 's\#@VERSION@\#$(VERSION)\#g' -e 's\#@SOVERSION@\#$(SOVERSION)\#g' "$$@"; }
install: all
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCDIR) $(DESTDIR)$(PCDIR) $(DESTDIR)$(CMAKEDIR)
	install -m 644 $(B)/libcertbox.a $(DESTDIR)$(LIBDIR)/
	install -m 755 $(B)/libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/
	ln -sf libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf libcertbox.so.$(VERSION) $(DESTDIR)$(LIBDIR)/libcertbox.so
	install -m 644 $(PUBHDR) $(DESTDIR)$(INCDIR)/
	sed -e 's#@PREFIX@#$(PREFIX)#' -e 's#@LIBDIR@#$(LIBDIR)#' -e 's#@INCDIR@#$(INCDIR)#' \
	    -e 's#@VERSION@#$(VERSION)#' certbox.pc.in > $(DESTDIR)$(PCDIR)/certbox.pc
	$(CMAKE_SUBST); \
	subst cmake/certboxConfig.cmake.in > $(DESTDIR)$(CMAKEDIR)/certboxConfig.cmake && \
	subst cmake/certboxConfigVersion.cmake.in > $(DESTDIR)$(CMAKEDIR)/certboxConfigVersion.cmake

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/libcertbox.a $(DESTDIR)$(LIBDIR)/libcertbox.so* \
	      $(addprefix $(DESTDIR)$(INCDIR)/,$(notdir $(PUBHDR))) $(DESTDIR)$(PCDIR)/certbox.pc \
	      $(DESTDIR)$(CMAKEDIR)/certboxConfig.cmake $(DESTDIR)$(CMAKEDIR)/certboxConfigVersion.cmake
	rmdir $(DESTDIR)$(CMAKEDIR) 2>/dev/null || true

# libFuzzer harnesses with the exact GMP oracle (tests/fuzz/); needs clang.
fuzz: check-deps-test
	@sh scripts/deps.sh fuzz
	sh scripts/fuzz.sh 60
# make check's short run: 4 s per harness (10 s until 2026-11-29, 6 s
# until 2026-12-01, each time to keep make check within CI's 30 minutes;
# the seed corpora run whole first); make fuzz is the long run
fuzz-check: check-deps-test
	@sh scripts/deps.sh fuzz
	sh scripts/fuzz.sh 4

# Mutation check: deliberate faults in a scratch copy must all be caught.
mutants: check-deps-test
	bash scripts/mutants.sh

clean:
	rm -rf $(B)

# ---- benchmark (issue 5) ---------------------------------------------------
# make bench        the tables (build/bench-out/bench.md, bench.dat, bench.png)
# make bench-smoke  the same tables on tiny sizes and 3 rounds (a few seconds
#                   per build: 7 s of CPU for both, 25 s with 11 rounds; a
#                   step of make check: fails on a containment failure in a
#                   certbox row, a prepared or batch output not bit-identical
#                   to cbx_transform_box(f)'s, or a certbox output that differs
#                   between the two builds); no plot unless gnuplot is already
#                   installed
# Two builds of bench/bench.c, each against the library compiled with the
# same flags, run one after the other and merged by scripts/bench_table.py
# into one table, one column group per build:
#   build/bench         the library's flags (ALLCFLAGS: -std=c99 -ffp-contract=off
#                       -fno-fast-math -O2), build/libcertbox.a
#   build/bench-native  the same with -O3 -march=native (BENCHNATIVE), against
#                       build/native/libcertbox.a (objects in build/native/obj)
BENCHARGS      := -n 20000 -r 11 -calls 200000 -exact 20000 -gmp 2000 -cache 1000 -big 4000000
BENCHSMOKEARGS := -n 2000 -r 3 -calls 10000 -exact 2000 -gmp 200 -cache 500 -big 50000
BENCHNATIVE    := -O3 -march=native
NATIVECFLAGS   := -std=c99 $(WARN) $(IEEEFLAGS) $(BENCHNATIVE) $(INC)
NATIVEOBJ      := $(LIBSRC:src/%.c=$(B)/native/obj/%.o)
# the bench links the exact oracles only, not the tests' parts
BENCHORACLES   := $(shell sh scripts/testutil.sh --oracles)
BENCHSRC       := bench/bench.c bench/bench_ref.h $(BENCHORACLES) tests/exact_util.h tests/exact_internal.h
.PHONY: bench bench-smoke branchfree
$(foreach f,$(FAMSRC),$(eval $(B)/native/obj/f32/$(f)_f.o: $(call famof,$(f))))
$(B)/native/obj/%.o: src/%.c $(HEADERS)
	@mkdir -p $(@D)
	$(CC) $(NATIVECFLAGS) -c $< -o $@
$(B)/native/libcertbox.a: $(NATIVEOBJ)
	rm -f $@ && ar rcs $@ $^
$(B)/bench: $(BENCHSRC) $(B)/libcertbox.a
	$(CC) $(ALLCFLAGS) -Itests -DBENCH_CC='"$(CC)"' -DBENCH_FLAGS='"$(ALLCFLAGS)"' \
	  -DBENCH_LABEL='"$(strip $(CFLAGS))"' bench/bench.c $(BENCHORACLES) $(B)/libcertbox.a $(EXACTLIBS) -lm -o $@
$(B)/bench-native: $(BENCHSRC) $(B)/native/libcertbox.a
	$(CC) $(NATIVECFLAGS) -Itests -DBENCH_CC='"$(CC)"' -DBENCH_FLAGS='"$(NATIVECFLAGS)"' \
	  -DBENCH_LABEL='"$(BENCHNATIVE)"' bench/bench.c $(BENCHORACLES) $(B)/native/libcertbox.a $(EXACTLIBS) -lm -o $@

# BENCH_RUN(dir, args): both builds, one after the other, then the merged table
BENCH_RUN = ./$(B)/bench $(2) -o $(1)/O2 && ./$(B)/bench-native $(2) -o $(1)/native && \
	python3 scripts/bench_table.py $(1) $(1)/O2 $(1)/native

bench: check-deps-test
	@sh scripts/deps.sh bench || echo "bench: note: gnuplot could not be installed; the plot will be skipped"
	$(MAKE) $(B)/bench $(B)/bench-native $(B)/bench_scene $(B)/certbox
	$(call BENCH_RUN,$(B)/bench-out,$(BENCHARGS))
	@sh scripts/bench_plot.sh $(B)/bench-out
	./$(B)/bench_scene $(BENCHSCENEARGS) -o $(B)/bench-out

bench-smoke: check-deps-test
	$(MAKE) $(B)/bench $(B)/bench-native $(B)/bench_scene $(B)/certbox
	$(call BENCH_RUN,$(B)/bench-smoke,$(BENCHSMOKEARGS))
	@sh scripts/bench_plot.sh $(B)/bench-smoke
	./$(B)/bench_scene $(BENCHSCENESMOKE) -o $(B)/bench-smoke

# The scene tool on big generated scenes (issue 18; bench/bench_scene.c):
# time and peak memory of build/certbox, the scenes written to the output
# folder and removed after their run (build/bench-out/scene.md)
BENCHSCENEARGS  := -nodes 1000000 -leaves 1000000
BENCHSCENESMOKE := -nodes 20000 -leaves 20000
$(B)/bench_scene: bench/bench_scene.c
	@mkdir -p $(@D)
	$(CC) $(ALLCFLAGS) -DBENCH_FLAGS='"$(ALLCFLAGS)"' $< -lm -o $@

# The fast path is branch-free: cbx_fast_box (src/algo/cbx_fast.h), both formats,
# compiled with the library's flags at -O2 into two wrappers, disassembled;
# fails on any conditional branch or call in them (scripts/branchfree.sh).
branchfree:
	sh scripts/branchfree.sh "$(CC)" -std=c99 $(WARN) $(IEEEFLAGS) -O2 $(INC) -Ispecs
