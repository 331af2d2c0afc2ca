# The ray tracing lab kit.  `make help` lists the targets.
# Needs only a C11 compiler, make and a POSIX shell.

# ---- settings ---------------------------------------------------------------
CC        ?= cc
OPT       ?= -O2
STD        = -std=c11
WARN       = -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes
FPFLAGS    = -ffp-contract=off          # never contract a*b+c; never -ffast-math
CFLAGS     = $(STD) $(OPT) $(FPFLAGS) $(WARN)
SANFLAGS   = $(STD) -O1 -g $(FPFLAGS) $(WARN) -fsanitize=address,undefined \
             -fno-omit-frame-pointer -fno-sanitize-recover=all
# gcc's UBSan runtime linked statically spares LeakSanitizer reading through
# its shared copy at every exit; clang has no such option, so the recipe asks.
SAN_LINK   = $(SANFLAGS) $$($(CC) -static-libubsan -E -x c /dev/null >/dev/null 2>&1 && echo -static-libubsan)
THREADS    = -pthread
RENDER_LTO = -flto                      # the renderer inlines across the stage files; empty to disable
LDLIBS     = -lm
SYSTEM    := $(shell uname -s)
# On Linux gcc-ar where it is on PATH: GNU ar alone loads every linker
# plugin beside it (all of LLVM where clang's is one).
KIT_AR    ?= $(if $(filter Linux,$(SYSTEM)),$(firstword $(wildcard $(addsuffix /gcc-ar,$(subst :, ,$(PATH)))) ar),ar)

# A copy with Windows line ends (CRLF: Git for Windows, where no .gitattributes
# says LF) cannot run its scripts: say so, and how to mend it, before anything
# else fails ($(empty) keeps the commands' indent).
empty :=
ifneq ($(shell grep -l "$$(printf '\r')" tests/run.sh 2>/dev/null),)
$(info this copy of the kit has Windows line ends (CRLF), which the shell cannot run:)
$(info Git for Windows wrote them when it checked the files out.  To mend the copy,)
$(info commit your work (git commit -am "my work"), then, in this folder:)
$(info $(empty)    git config core.autocrlf false)
$(info $(empty)    git rm -rq --cached . && git reset -q --hard)
$(info or clone the repository again from a WSL (Linux) terminal.)
$(error the kit's files have Windows line ends)
endif

# V=1 echoes every command; by default a stage file is named as it compiles.
Q          = $(if $(filter 1,$(V)),,@)
SAY_CC     = $(if $(Q),@echo "  CC      $<")
# What the targets act on (these and the other paths may be absolute).
SUBMISSION ?= labs
SCENE      ?= labs/scenes/default.scene
# Two builds, plain and sanitized: OUT_ROOT=dir puts them in dir/build and
# dir/asan (the portability suite builds with a second compiler there).
OUT_ROOT  ?= out
BUILD      = $(OUT_ROOT)/build
ASAN       = $(OUT_ROOT)/asan
STAGES     = part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color \
             part4_plane_intersect part5_triangle_intersect
# What the student kit does not have.
HAVE_SOLUTIONS := $(wildcard solutions/part1_image_plane.c)
HAVE_ORACLE := $(wildcard tests/oracle/oracle.h)
# The reference (the skeletons in the student kit) and its objects in build $(1).
REF_DIR    = $(if $(HAVE_SOLUTIONS),solutions,labs)
ref_obj    = $(STAGES:%=$(1)/sub/$(REF_DIR)/%.o)
# Each library is its folder's C files but the programs (and harnesses).
KIT_SRC    = $(filter-out %_main.c,$(wildcard labs/kit/*.c))
KIT_HDR    = $(wildcard labs/*.h labs/kit/*.h)
ORACLE_SRC = $(filter-out %_main.c,$(wildcard tests/oracle/*.c))
TOOLS_SRC  = $(filter-out %_main.c,$(wildcard tests/tools/*.c))
GRADER_LIB_SRC = $(filter-out %_main.c tests/grader/harness%,$(wildcard tests/grader/*.c))
GRADER_HDR = $(wildcard tests/grader/*.h) $(KIT_HDR)

.PHONY: all help render compare grade grade-all gradescope prairielearn student-kit bench \
        handouts test test-build unit-tests clean grader public-tests fuzz sanitize-grader selftests \
        submission-dir sort-submissions print-cflags
.DELETE_ON_ERROR:
.SECONDARY:                             # keep the objects a chain of rules makes (the renderer's lto/)
.SECONDEXPANSION:
# A target's folder is made once, as an order-only prerequisite (| $$(@D)/.).
%/.:
	@mkdir -p $@
# An archive's members are the prerequisites its own line names.
$(OUT_ROOT)/%.a:
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^

all: $(BUILD)/kit/libkit.a $(BUILD)/bin/compare $(BUILD)/sub/labs/render \
     $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render) grader
# The student kit (no solutions/) lists only what runs there.
help:
	@echo "make render  [SUBMISSION=dir] [SCENE=file] [SIZE=WxH] [OUT=file]"
	@echo "make compare [SUBMISSION=dir] [SCENE=file]"
	@echo "make grade   [SUBMISSION=dir] [PART=1|2|3a|3b|4|5] [FAILURES=all] [RESULTS=file]"
	@echo "             [FORMAT=gradescope|prairielearn] [CLASSROOM=file]"
ifneq ($(HAVE_SOLUTIONS),)
	@echo "make grade-all SUBMISSIONS=dir [OUT=dir] [JOBS=n] [PREVIOUS=dir]"
	@echo "make sort-submissions FROM=download.zip|dir TO=newdir [MAX_MB=n] [MAX_RATIO=n]"
	@echo "make gradescope | prairielearn | student-kit | bench | fuzz | sanitize-grader | handouts | selftests | test | clean"
else
	@echo "make test | clean"
endif
	@echo "V=1 after any of them echoes the build's compiler commands"

# ---- renderer and compare, per submission ----------------------------------
# A submission builds in out/build/sub/<name>: labs, solutions, or another
# folder's absolute path with / as _, with labs/ for the stage files it lacks;
# a student kit's repository (stage files in its labs/) is drawn from there.
sub_name   = $(if $(filter labs solutions,$(1)),$(1),$(subst /,_,$(abspath $(1))))
stage_src  = $(firstword $(wildcard $(2)/$(1).c) labs/$(1).c)
stage_dir  = $(if $(wildcard $(STAGES:%=$(1)/%.c)),$(1),$(if $(wildcard $(STAGES:%=$(1)/labs/%.c)),$(1)/labs,$(1)))
SUB_DIR   := $(call stage_dir,$(SUBMISSION))
SUB_NAME  := $(call sub_name,$(SUB_DIR))
SUB_BUILD  = $(BUILD)/sub/$(SUB_NAME)
# The renderer's objects (lto/) are built for link-time optimisation.  A stage
# file the grader would not build is refused (bin/stagecheck); if one does not
# compile, bin/lookalike says why; bin/linkcheck explains a failed link.
STAGE_CC = $(BUILD)/bin/stagecheck $< && \
           { $(CC) $(CFLAGS) $(RENDER_LTO) -Ilabs -c $< -o $@ || { $(BUILD)/bin/lookalike $<; exit 1; }; }
STAGE_TOOLS = $(BUILD)/bin/stagecheck $(BUILD)/bin/lookalike
$(BUILD)/sub/labs/lto/%.o: labs/%.c $(KIT_HDR) | $$(@D)/. $(STAGE_TOOLS)
	$(SAY_CC)
	$(Q)$(STAGE_CC)
$(BUILD)/sub/solutions/lto/%.o: solutions/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) -Ilabs -c $< -o $@
ifeq ($(filter labs solutions,$(SUB_NAME)),)
$(SUB_BUILD)/lto/%.o: $$(call stage_src,$$*,$(SUB_DIR)) $(KIT_HDR) | $$(@D)/. $(STAGE_TOOLS)
	$(SAY_CC)
	$(Q)$(STAGE_CC)
endif
$(BUILD)/kit/lto/%.o: labs/kit/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) $(THREADS) -c $< -o $@
render_src = $(if $(filter labs solutions,$(1)),$(STAGES:%=$(1)/%.c),\
                 $(foreach s,$(STAGES),$(call stage_src,$(s),$(SUB_DIR))))
$(BUILD)/sub/%/render: $(addprefix $(BUILD)/kit/lto/,render_main.o render.o image.o closest.o bvh.o) \
                       $$(addprefix $(BUILD)/sub/$$*/lto/,$$(addsuffix .o,$$(STAGES))) $(BUILD)/kit/libkit.a \
                       | $(BUILD)/bin/linkcheck
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) $(THREADS) $^ -o $@ $(LDLIBS) 2>$@.log || \
	    { cat $@.log >&2; $(BUILD)/bin/linkcheck $@.log $(call render_src,$*); rm -f $@.log; exit 1; }; \
	    cat $@.log >&2; rm -f $@.log
SCENE_NAME = $(basename $(notdir $(SCENE)))
# A SUBMISSION that is no folder is refused, not drawn as the skeletons.
submission-dir:
	@test -d "$(SUBMISSION)" || { echo "make: SUBMISSION=$(SUBMISSION) is not a directory"; exit 2; }
	@test -n "$(wildcard $(STAGES:%=$(SUB_DIR)/%.c))" || \
	    echo "note: $(SUBMISSION) holds no stage file (nor does its labs folder): the skeletons are drawn"
# A note where a header in labs/ is not the shipped one (tests/grader/shipped).
render: submission-dir $(SUB_BUILD)/render
	$(SUB_BUILD)/render "$(SCENE)" $(if $(SIZE),--size $(SIZE)) -o "$(if $(OUT),$(OUT),out/$(SCENE_NAME).png)"
	@for h in $(notdir $(wildcard tests/grader/shipped/*.h)); do cmp -s labs/$$h tests/grader/shipped/$$h || \
	    echo "note: labs/$$h is not the one the kit came with. make render used yours; your instructor grades your part*.c files with the kit's own (tests/grader/shipped/$$h), where what they use from your change will be missing: keep it in your part*.c files."; done
# In the kit's own repository the reference image is rendered with
# solutions/; in the student kit it is the stored render under labs/reference.
# Either way with its pixels on an edge (labs/kit/edges.h), where a colour
# that rounding decides is equal.
REF_IMAGE = $(if $(HAVE_SOLUTIONS),out/compare/$(SCENE_NAME)-reference.png,labs/reference/$(SCENE_NAME).png)
REF_EDGES = $(REF_IMAGE:.png=.edges)
compare: submission-dir $(SUB_BUILD)/render $(BUILD)/bin/compare $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render)
	@mkdir -p out/compare
	$(SUB_BUILD)/render "$(SCENE)" -o out/compare/$(SCENE_NAME)-submission.png
	$(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render "$(SCENE)" --quiet -o $(REF_IMAGE) --edges $(REF_EDGES))
	$(BUILD)/bin/compare out/compare/$(SCENE_NAME)-submission.png $(REF_IMAGE) \
	    --edges $(REF_EDGES) -o out/compare/$(SCENE_NAME).png

# ---- the plain build's programs: each links what its own line names --------
PROGRAMS   = compare pack gentests lookalike linkcheck stagecheck bench
$(PROGRAMS:%=$(BUILD)/bin/%): | $(BUILD)/bin/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/compare: $(BUILD)/kit/compare_main.o $(BUILD)/kit/libkit.a
$(BUILD)/bin/pack: $(BUILD)/tools/pack_main.o $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a
# The oracle's program: the public tests' values (commit them).
$(BUILD)/bin/gentests: $(BUILD)/oracle/gentests_main.o $(BUILD)/oracle/liboracle.a \
                       $(BUILD)/grader/libgrader.a $(BUILD)/kit/libkit.a
public-tests: $(BUILD)/bin/gentests
	$(BUILD)/bin/gentests tests/public
$(BUILD)/bin/lookalike: $(BUILD)/grader/lookalike_main.o $(BUILD)/grader/lookalike.o \
                        $(BUILD)/tools/utf8.o $(BUILD)/kit/libkit.a
$(BUILD)/bin/linkcheck: $(BUILD)/grader/linkcheck_main.o $(BUILD)/grader/linkmsg.o $(BUILD)/kit/libkit.a
$(BUILD)/bin/stagecheck: $(BUILD)/grader/stagecheck_main.o $(BUILD)/grader/include_scan.o \
                         $(BUILD)/grader/own_headers.o $(BUILD)/grader/lookalike.o \
                         $(BUILD)/tools/utf8.o $(BUILD)/kit/libkit.a

# ---- the autograder (tests/grader) ------------------------------------------
# A part's program links its harness (harness_partP.o, P one of PARTS, built
# with HARNESS_PART=PART_P) with the student's file; harness_render.o draws
# the report page's scene.
PARTS      = 1 2 3a 3b 4 5
stage_of   = $(filter part$(1)_%,$(STAGES))
part_macro = -DHARNESS_PART=PART_$(subst a,A,$(subst b,B,$(1)))
HARNESS    = $(PARTS:%=$(BUILD)/grader/harness_part%.o) $(BUILD)/grader/harness_render.o
GRADER_REF = $(if $(HAVE_SOLUTIONS),$(STAGES:%=$(BUILD)/grader/ref_%.o))
GRADE_DEFS = $(if $(and $(HAVE_ORACLE),$(wildcard tests/hidden/hidden.c)),-DGRADER_ORACLE)
$(PARTS:%=$(BUILD)/grader/harness_part%.o): $(BUILD)/grader/harness_part%.o: tests/grader/harness.c \
        tests/grader/hexfloat.h tests/grader/harness_init.h $(KIT_HDR) | $(BUILD)/grader/.
	$(Q)$(CC) $(CFLAGS) -Ilabs $(call part_macro,$*) -c $< -o $@
$(BUILD)/grader/ref_%.o: $(BUILD)/sub/solutions/%.o
	$(Q)cp $< $@
# On Linux runner_partP (harness_load_partP.o) loads the student's file as a
# shared object, with the reference of the other parts (3a's: no 3b).
RUNNERS    = $(if $(filter Linux,$(SYSTEM)),$(PARTS:%=$(BUILD)/grader/runner_part%))
runner_refs = $(if $(HAVE_SOLUTIONS),$(filter-out $(BUILD)/grader/ref_$(call stage_of,$(1)).o \
              $(if $(filter 3a,$(1)),$(BUILD)/grader/ref_part3b_ray_color.o),$(GRADER_REF)))
$(PARTS:%=$(BUILD)/grader/harness_load_part%.o): $(BUILD)/grader/harness_load_part%.o: tests/grader/harness.c \
        tests/grader/harness_load.h tests/grader/harness_init.h tests/grader/hexfloat.h $(KIT_HDR) | $(BUILD)/grader/.
	$(Q)$(CC) $(CFLAGS) -Ilabs $(call part_macro,$*) -DHARNESS_LOAD $(if $(HAVE_SOLUTIONS),-DHARNESS_REFS) -c $< -o $@
$(RUNNERS): $(BUILD)/grader/runner_part%: $(BUILD)/grader/harness_load_part%.o \
        $(BUILD)/grader/harness_load.o $$(call runner_refs,$$*)
	$(Q)$(CC) $(CFLAGS) -rdynamic $^ -o $@ $(LDLIBS) -ldl
# bin/sortsubs sorts a class's download from an LMS for grade-all.
grader: $(BUILD)/bin/grade $(HARNESS) $(GRADER_REF) $(RUNNERS) $(BUILD)/bin/sortsubs

# The report page's reference picture; the student kit's is in labs/reference.
REPORT_REF = $(if $(HAVE_SOLUTIONS),$(BUILD)/report/default.png)
$(BUILD)/report/default.png: $(BUILD)/sub/solutions/render labs/scenes/default.scene | $$(@D)/.
	$(Q)$(BUILD)/sub/solutions/render labs/scenes/default.scene --quiet -o $@
all: $(REPORT_REF)
grade: grader $(REPORT_REF)
	@$(BUILD)/bin/grade --submission "$(SUBMISSION)" $(if $(PART),--part $(PART)) \
	    $(if $(RESULTS),--results "$(RESULTS)") $(if $(FORMAT),--format "$(FORMAT)") \
	    $(if $(CLASSROOM),--classroom "$(CLASSROOM)") $(if $(filter all,$(FAILURES)),--all-failures) \
	    --report out/report
grade-all: grader $(REPORT_REF)
	@test -n "$(SUBMISSIONS)" || { echo "usage: make grade-all SUBMISSIONS=dir [OUT=dir] [JOBS=n] [PREVIOUS=dir]"; exit 2; }
	@$(BUILD)/bin/grade --all "$(SUBMISSIONS)" --out "$(if $(OUT),$(OUT),out/grades)" $(if $(JOBS),--jobs $(JOBS)) \
	    $(if $(PREVIOUS),--previous "$(PREVIOUS)")
sort-submissions: $(BUILD)/bin/sortsubs
	@test -n "$(FROM)" && test -n "$(TO)" || { echo "usage: make sort-submissions FROM=download.zip|dir TO=newdir [MAX_MB=n] [MAX_RATIO=n]"; exit 2; }
	@$(BUILD)/bin/sortsubs $(if $(MAX_MB),--max-mb "$(MAX_MB)") $(if $(MAX_RATIO),--max-ratio "$(MAX_RATIO)") "$(FROM)" "$(TO)"

# ---- releases: the Gradescope bundle and the student kit ------------------
# autograder.zip: setup.sh and run_autograder at its root, beside the kit.
gradescope: $(BUILD)/bin/pack
	rm -rf out/gradescope/bundle && mkdir -p out/gradescope/bundle
	cp -R Makefile labs solutions tests out/gradescope/bundle/
	cp tests/gradescope/setup.sh tests/gradescope/run_autograder out/gradescope/bundle/
	$(BUILD)/bin/pack zip out/gradescope/autograder.zip out/gradescope/bundle
	@echo "wrote out/gradescope/autograder.zip"
prairielearn:
	sh tests/prairielearn/question.sh out/prairielearn/raytracer-lab
# The student kit: no solutions/, hidden tests, oracle or other instructor's
# test material, nor the hidden seed, nor the instructor's pages (the
# instructor guide, the grader's README); the scenes' reference renders.
KIT_DIR    = out/student-kit
student-kit: $(BUILD)/sub/solutions/render
	rm -rf $(KIT_DIR) && mkdir -p $(KIT_DIR)/tests/unit $(KIT_DIR)/labs/reference
	cp -R Makefile .gitattributes .gitignore labs handouts $(KIT_DIR)/
	mv $(KIT_DIR)/handouts/student-readme.md $(KIT_DIR)/README.md
	rm -f $(KIT_DIR)/handouts/instructor-guide.md
	mkdir -p $(KIT_DIR)/.github/workflows
	sh tests/classroom/workflow.sh >$(KIT_DIR)/.github/workflows/classroom.yml
	cp -R tests/grader tests/public tests/tools tests/run.sh $(KIT_DIR)/tests/
	rm -f $(KIT_DIR)/tests/grader/README.md
	sed 's/^[ 	]*seed[ 	].*/# seed: the hidden cases'"'"' seed is the instructor'"'"'s (the student kit has no hidden tests)/' \
	    tests/weights.conf >$(KIT_DIR)/tests/weights.conf
	mkdir -p $(KIT_DIR)/tests/grader/shipped && cp labs/raytracer.h labs/vec3.h $(KIT_DIR)/tests/grader/shipped/
	cp tests/unit/check.h tests/unit/test_vec3.c tests/unit/test_png.c tests/unit/test_scene.c \
	   $(KIT_DIR)/tests/unit/
	for s in $(wildcard labs/scenes/*.scene); do \
	    n=$(KIT_DIR)/labs/reference/$$(basename $$s .scene); \
	    $(BUILD)/sub/solutions/render $$s --quiet -o $$n.png --edges $$n.edges || exit 1; \
	done
	tar -czf out/student-kit.tar.gz.tmp -C out student-kit && mv out/student-kit.tar.gz.tmp out/student-kit.tar.gz
	@echo "wrote $(KIT_DIR)/ and out/student-kit.tar.gz"
# The handouts' figures (handouts/figures/make-figures.sh; commit the PNGs).
handouts: $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render $(BUILD)/bin/compare grader)
	@if [ -n "$(HAVE_SOLUTIONS)" ]; then MAKE="$(MAKE)" sh handouts/figures/make-figures.sh; \
	 else echo "the figures are in handouts/figures (drawing them again needs solutions/)"; fi
# The compile flags, for a suite that builds a program of its own (hierarchy.sh).
print-cflags:
	@echo $(CFLAGS)

# ---- bench: speed against accuracy (tests/bench) ----------------------------
# out/bench/: results.csv, report.md, plot.svg and more (instructor's kit).
BENCH_SRC  = $(wildcard tests/bench/*.c)
BENCH_OBJ  = $(BENCH_SRC:tests/bench/%.c=$(BUILD)/bench/%.o) $(STAGES:%=$(BUILD)/bench/solutions/%.o)
HAVE_BENCH := $(and $(HAVE_SOLUTIONS),$(wildcard tests/oracle/hard.h),$(BENCH_SRC))
# 64-byte aligned functions and loops (where the compiler takes the flags): the
# linker's placement must not move the ratios (bench-reordered checks that).
BENCH_ALIGN = $(shell $(CC) -falign-functions=64 -falign-loops=64 -Werror -x c -c /dev/null -o /dev/null 2>/dev/null && echo -falign-functions=64 -falign-loops=64)
$(BUILD)/bench/%.o: tests/bench/%.c $(wildcard tests/bench/*.h) $(wildcard tests/oracle/*.h) $(KIT_HDR) Makefile | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(BENCH_ALIGN) -Ilabs -c $< -o $@
$(BUILD)/bench/solutions/%.o: solutions/%.c $(KIT_HDR) Makefile | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(BENCH_ALIGN) -Ilabs -c $< -o $@
# The fast path's sqrt is vectorised only if it need not set errno (no result changes).
$(BUILD)/bench/fastpath.o $(BUILD)/bench/measure.o: CFLAGS += -fno-math-errno
$(BUILD)/bin/bench: $(BENCH_OBJ) $(BUILD)/oracle/liboracle.a $(BUILD)/kit/libkit.a
all: $(if $(HAVE_BENCH),$(BUILD)/bin/bench)
reverse = $(if $(1),$(call reverse,$(wordlist 2,$(words $(1)),$(1))) $(firstword $(1)))
$(BUILD)/bin/bench-reordered: $(BENCH_OBJ) $(BUILD)/oracle/liboracle.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(call reverse,$(filter %.o,$^)) $(filter %.a,$^) -o $@ $(LDLIBS)
bench: $(BUILD)/bin/bench $(BUILD)/bin/bench-reordered $(BUILD)/sub/solutions/render
	@mkdir -p out/bench
	$(BUILD)/bin/bench-reordered --ratio-only >out/bench/placement.txt.new && mv out/bench/placement.txt.new out/bench/placement.txt
	$(BUILD)/bin/bench --out out/bench --placement out/bench/placement.txt

# ---- fuzzing the readers of untrusted input (tests/fuzz) --------------------
# `make fuzz [FUZZ="scene png ..."] [FUZZ_SECONDS=n]` builds each target
# with clang's libFuzzer and the sanitizers, then runs it (tests/fuzz/run.sh).
FUZZ_CC    ?= clang
FUZZ_FLAGS  = $(STD) -g -O1 $(FPFLAGS) $(WARN) -fsanitize=fuzzer,address,undefined \
              -fno-sanitize-recover=all
FUZZ_SRC    = $(filter-out labs/kit/render.c labs/kit/closest.c,$(KIT_SRC)) $(wildcard tests/grader/fig_*.c) \
              $(addprefix tests/grader/,cases.c check.c config.c markup.c figures.c) \
              $(addprefix tests/tools/,base64.c utf8.c)
FUZZ_OBJ    = $(FUZZ_SRC:%.c=$(OUT_ROOT)/fuzz/obj/%.o)
$(OUT_ROOT)/fuzz/obj/%.o: %.c $(GRADER_HDR) $(wildcard tests/tools/*.h) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -Ilabs -c $< -o $@
$(OUT_ROOT)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz.h tests/fuzz/fuzz_public.h $(FUZZ_OBJ) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -Ilabs $< $(FUZZ_OBJ) -o $@ $(LDLIBS)
fuzz:
	@if [ -f tests/fuzz/run.sh ]; then FUZZ_OUT=$(OUT_ROOT)/fuzz FUZZ_CC=$(FUZZ_CC) sh tests/fuzz/run.sh $(FUZZ); \
	 else echo "make fuzz: only the instructor's kit has the fuzz targets (tests/fuzz)"; exit 2; fi

# ---- the rules of both builds -----------------------------------------------
# $(1) is a build's folder, $(2) and $(3) name the variables of its flags
# for compiling and for linking; $$ is a $ left for the rule.
define BUILD_RULES
$(1)/kit/%.o: labs/kit/%.c $(KIT_HDR) | $(1)/kit/.
	$$(Q)$$(CC) $$($(2)) $$(THREADS) -c $$< -o $$@
$(1)/sub/$(REF_DIR)/%.o: $(REF_DIR)/%.c $(KIT_HDR) | $(1)/sub/$(REF_DIR)/.
	$$(Q)$$(CC) $$($(2)) -Ilabs -c $$< -o $$@
$(1)/oracle/%.o: tests/oracle/%.c $(wildcard tests/oracle/*.h) $(KIT_HDR) | $(1)/oracle/.
	$$(Q)$$(CC) $$($(2)) -Ilabs -c $$< -o $$@
$(1)/tools/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) $(KIT_HDR) | $(1)/tools/.
	$$(Q)$$(CC) $$($(2)) -Ilabs -c $$< -o $$@
$(1)/grader/%.o: tests/grader/%.c $(GRADER_HDR) | $(1)/grader/.
	$$(Q)$$(CC) $$($(2)) -Ilabs -c $$< -o $$@
$(1)/grader/hidden.o: tests/hidden/hidden.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $(1)/grader/.
	$$(Q)$$(CC) $$($(2)) -Ilabs -c $$< -o $$@
$(1)/grader/grade_main.o: tests/grader/grade_main.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $(1)/grader/.
	$$(Q)$$(CC) $$($(2)) $$(GRADE_DEFS) -DGRADER_BUILD='"$$(BUILD)"' -Ilabs -c $$< -o $$@
$(1)/kit/libkit.a: $(KIT_SRC:labs/kit/%.c=$(1)/kit/%.o)
$(1)/oracle/liboracle.a: $(ORACLE_SRC:tests/oracle/%.c=$(1)/oracle/%.o)
$(1)/tools/libtools.a: $(TOOLS_SRC:tests/tools/%.c=$(1)/tools/%.o)
$(1)/grader/libgrader.a: $(GRADER_LIB_SRC:tests/grader/%.c=$(1)/grader/%.o)
$(1)/bin/grade $(1)/bin/sortsubs: | $(1)/bin/.
	$$(Q)$$(CC) $$($(3)) $$^ -o $$@ $$(LDLIBS)
# Either build's grade runs the plain build's harnesses and runners.
$(1)/bin/grade: $(1)/grader/grade_main.o $(if $(GRADE_DEFS),$(1)/grader/hidden.o $(1)/oracle/liboracle.a) \
                $(1)/grader/libgrader.a $(1)/tools/libtools.a $(1)/kit/libkit.a | $(HARNESS) $(GRADER_REF) $(RUNNERS)
$(1)/bin/sortsubs: $(1)/grader/sortsubs_main.o $(1)/grader/libgrader.a $(1)/tools/libtools.a $(1)/kit/libkit.a
$(UNIT_LINKED:%=$(1)/tests/%): $(1)/tests/%: tests/unit/%.c tests/unit/check.h $(call ref_obj,$(1)) \
                                              $(call unit_libs,$(1)) | $(1)/tests/.
	$$(Q)$$(CC) $$($(3)) $$(THREADS) -Ilabs $$(filter-out %.h,$$^) -o $$@ $$(LDLIBS)
$(1)/tests/test_hexfloat: tests/grader/hexfloat.h tests/grader/decimal.h
$(1)/tests/test_render $(1)/tests/test_bvh: tests/unit/render_check.h
# test_bvh's own sphere_intersect and triangle_intersect call the reference's
# (compiled under other names) or deliberately wrong ones.
$(1)/tests/obj/renamed_%.o: $(REF_DIR)/%.c $(KIT_HDR) | $(1)/tests/obj/.
	$$(Q)$$(CC) $$($(2)) $$(BVH_RENAME) -Ilabs -c $$< -o $$@
$(1)/tests/test_bvh: tests/unit/test_bvh.c tests/unit/check.h $(BVH_OWN:%=$(1)/tests/obj/renamed_%.o) \
                     $(filter-out $(BVH_OWN:%=$(1)/sub/$(REF_DIR)/%.o),$(call ref_obj,$(1))) \
                     $(call unit_libs,$(1)) | $(1)/tests/.
	$$(Q)$$(CC) $$($(3)) $$(THREADS) -Ilabs $$(filter-out %.h,$$^) -o $$@ $$(LDLIBS)
# A grader part's unit test links that part alone: the build's objects it needs.
$(GRADER_UNITS:%=$(1)/tests/test_%): $(1)/tests/test_%: tests/unit/test_%.c tests/unit/check.h \
                                     $(1)/grader/%.o $(GRADER_HDR) $(1)/kit/libkit.a | $(1)/tests/.
	$$(Q)$$(CC) $$($(3)) -Ilabs $$(filter %.c %.o,$$^) $(1)/kit/libkit.a -o $$@ $$(LDLIBS)
$(1)/tests/test_check: $(1)/grader/cases.o
$(1)/tests/test_terminal $(1)/tests/test_lookalike: $(1)/tools/utf8.o
$(1)/tests/test_own_headers: $(1)/grader/include_scan.o
# init_sh, plain in both builds: a sanitized one would not fit a test's memory.
$(1)/tests/test_sandbox: $(1)/grader/jail.o | $(1)/tests/init_sh
$(1)/tests/init_sh: tests/unit/init_sh.c tests/grader/harness_init.h | $(1)/tests/.
	$$(Q)$$(CC) $$(CFLAGS) $$< -o $$@
# The hidden tests' and the figures' unit tests (instructor's kit only).
$(1)/tests/test_hidden $(1)/tests/test_figures: $(1)/tests/%: tests/unit/%.c tests/unit/check.h \
        $(1)/grader/hidden.o $(1)/oracle/liboracle.a $(1)/grader/libgrader.a $(1)/tools/libtools.a \
        $(1)/kit/libkit.a | $(1)/tests/.
	$$(Q)$$(CC) $$($(3)) $$(SEEDS) -Ilabs $$(filter-out %.h,$$^) -o $$@ $$(LDLIBS)
$(1)/tests/test_hidden: $(call ref_obj,$(1))
endef

UNIT_NAMES = $(basename $(notdir $(wildcard tests/unit/test_*.c)))
unit_libs  = $(if $(HAVE_ORACLE),$(1)/oracle/liboracle.a) $(1)/tools/libtools.a $(1)/kit/libkit.a
GRADER_UNITS = sandbox include_scan cases check linkmsg lookalike own_headers lmsname terminal csv
UNIT_LINKED = $(filter-out $(GRADER_UNITS:%=test_%) test_hidden test_figures test_bvh,$(UNIT_NAMES))
BVH_RENAME = -Dsphere_intersect=reference_sphere_intersect -Dtriangle_intersect=reference_triangle_intersect
BVH_OWN    = part3a_sphere_intersect part5_triangle_intersect
$(eval $(call BUILD_RULES,$(BUILD),CFLAGS,CFLAGS))
$(eval $(call BUILD_RULES,$(ASAN),SANFLAGS,SAN_LINK))
unit-tests: $(UNIT_NAMES:%=$(BUILD)/tests/%)
# Sanitized, they draw fewer seeds: what they check there is the code.
$(ASAN)/tests/test_hidden: SEEDS = -DSEEDS=30 -DSEEDS_FLAT=100
$(ASAN)/tests/test_figures: SEEDS = -DSEEDS=1
# The renderer with the reference stages, sanitized (tests/suites/render_cli.sh).
$(ASAN)/bin/render-solutions: $(ASAN)/kit/render_main.o $(call ref_obj,$(ASAN)) $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $(THREADS) $^ -o $@ $(LDLIBS)

# ---- the grader itself under the sanitizers (`make sanitize-grader`) --------
# The suites that grade, with the sanitized grade and sortsubs (GRADE=, SORTSUBS=).
SANITIZE_SUITES = grader.sh report.sh class_page.sh limits.sh signals.sh jail.sh sort_submissions.sh
HAVE_SUITES := $(wildcard tests/suites/grader.sh)
sanitize-grader: $(if $(HAVE_SUITES),all $(BUILD)/bin/pack $(ASAN)/bin/grade $(ASAN)/bin/sortsubs)
	@test -n "$(HAVE_SUITES)" || { echo "make sanitize-grader: only the instructor's kit has the grader's suites (tests/suites)"; exit 2; }
	@echo "grading with $(ASAN)/bin/grade, sorting with $(ASAN)/bin/sortsubs (address, undefined-behaviour and leak sanitizers)"
	@GRADE=$(ASAN)/bin/grade SORTSUBS=$(ASAN)/bin/sortsubs sh tests/run.sh $(SANITIZE_SUITES)
# The grader's self-test submissions written out, a folder each, in
# out/selftest (tests/selftest/README.md); each suite writes its own.
selftests:
	@test -f tests/selftest/mistakes || { echo "make selftests: only the instructor's kit has the self-tests (tests/selftest)"; exit 2; }
	sh tests/lib/selftests.sh out/selftest
# What the tests need built (`make -j2 test-build` builds it on two cores).
test-build: all unit-tests $(BUILD)/bin/pack $(UNIT_NAMES:%=$(ASAN)/tests/%) $(if $(HAVE_SOLUTIONS),$(ASAN)/bin/render-solutions)
test: test-build
	@sh tests/run.sh
clean:
	rm -rf out
